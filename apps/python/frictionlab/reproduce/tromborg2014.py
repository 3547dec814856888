"""Trømborg, Sveinsson, Scheibert, Thøgersen, Amundsen & Malthe-Sørenssen (2014), "Slow slip and the
transition from fast to slow fronts in the rupture of frictional interfaces", PNAS 111, 8764, with
Trømborg et al. (2015), PRE 92, 012408: their signatures measured on an ensemble of our runs."""
from typing import Dict, List, Tuple

from . import report, tromborg_signatures
from .report import Statement
from .steps import Outcome, Step

TITLE = "Trømborg et al. (2014), PNAS 111, 8764: the signatures, reproduced"


# The signature each of tromborg_signatures.statements()'s rows judges, in its order.
SIGNATURES = ("PNAS 2014: fronts", "PNAS 2014: slow fronts", "PRE 2015: slip speed", "precursors")


def steps(quick: bool) -> List[Step]:
    seeds = tromborg_signatures.seeds(quick)
    return [Step("pnas2014", f"configs/{tromborg_signatures.SCENE} over {len(seeds)} seeds",
                 scene=tromborg_signatures.SCENE, seeds=len(seeds), common=tromborg_signatures.run_overrides(quick))]


def measure(outcomes: Dict[str, Outcome], out: str) -> Tuple[List[Statement], List[str], str]:
    runs = outcomes["pnas2014"].run_directories()
    rows = [Statement(name, row["statement"], row["measured"], row["verdict"], row["margin"])
            for name, row in zip(SIGNATURES, tromborg_signatures.statements(runs))]
    return rows, [], ""


def write_docs(outcomes: Dict[str, Outcome], statements: List[Statement], root: str) -> List[str]:
    return [report.write_block(root, "share/docs/reproduction.md", "tromborg2014-reproduction", statements,
                               outcomes)]
