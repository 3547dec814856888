"""The reproduction report: one row per statement of the paper (what it says, what we measured with
its interval, a verdict), the figures beside it, the provenance of every run, and what it cost."""
import dataclasses
import json
import os
from typing import Dict, List

import pandas as pd

from .. import doc_blocks
from .steps import Outcome

VERDICTS = ("reproduced", "reproduced within a stated margin", "differs", "not measured")


@dataclasses.dataclass
class Statement:
    figure: str     # "Fig. 8", or a signature's name
    claim: str      # the paper's statement, in our words
    measured: str   # what we measured, with its interval
    verdict: str    # one of VERDICTS
    margin: str = ""  # the margin a "within" verdict allows, or by how much it differs

    def __post_init__(self):
        if self.verdict not in VERDICTS:
            raise ValueError(f"verdict {self.verdict!r} is none of {VERDICTS}")


def cell(text: str) -> str:
    return str(text).replace("|", "\\|").replace("\n", " ")


def statements_table(statements: List[Statement]) -> str:
    lines = ["| figure | the paper's statement | measured | verdict |", "| --- | --- | --- | --- |"]
    for s in statements:
        verdict = f"**{s.verdict}**" + (f" ({s.margin})" if s.margin else "")
        lines.append(f"| {cell(s.figure)} | {cell(s.claim)} | {cell(s.measured)} | {cell(verdict)} |")
    return "\n".join(lines) + "\n"


def provenance_table(outcomes: Dict[str, Outcome]) -> str:
    lines = ["| step | what it runs | runs done | failed | seeds | scene hashes | frictionlab | CPU s |",
             "| --- | --- | --- | --- | --- | --- | --- | --- |"]
    for name, o in outcomes.items():
        runs = o.runs if o.runs is not None else pd.DataFrame(columns=["status", "seed", "scene_hash"])
        done = int((runs["status"] == "done").sum())
        seeds = sorted(int(s) for s in runs["seed"].dropna().unique())
        seeds_text = f"{seeds[0]}–{seeds[-1]}" if len(seeds) > 1 else ", ".join(map(str, seeds))
        hashes = ", ".join(sorted(str(h) for h in runs["scene_hash"].dropna().unique()))
        lines.append(f"| {name} | {cell(o.step.what)} | {done} | {len(o.failed)} | {seeds_text} | {hashes} | "
                     f"{version_of(o)} | {o.cpu_seconds:.0f} |")
    return "\n".join(lines) + "\n"


def version_of(o: Outcome) -> str:
    """The framework version its runs record (run.yaml), or '?' before any finished."""
    for d in o.run_directories():
        path = os.path.join(d, "run.yaml")
        if os.path.exists(path):
            with open(path) as f:
                for line in f:
                    if line.startswith("version:"):
                        return line.split(":", 1)[1].strip()
    return "?"


def failures(outcomes: Dict[str, Outcome]) -> str:
    """Every run that failed, by name and reason: a reproduction never hides one."""
    lines = []
    for name, o in outcomes.items():
        for _, r in o.failed.iterrows():
            lines.append(f"- step {name}, run `{r['run']}`: {r['status']}: {r.get('reason', '')}")
        if o.runs is None:
            lines.append(f"- step {name}: its sweep wrote no table (exit code {o.exit_code})")
    return "\n".join(lines) + ("\n" if lines else "")


def write_block(root: str, document: str, name: str, statements: List[Statement],
                outcomes: Dict[str, Outcome]) -> str:
    """The statements' table as the generated block `name` of `document` (below `root`), stamped
    with the runs' scene hashes and seeds; returns the document's path."""
    runs = [o.runs[["scene_hash", "seed"]] for o in outcomes.values() if o.runs is not None]
    table = pd.concat(runs) if runs else pd.DataFrame(columns=["scene_hash", "seed"])
    path = os.path.join(root, document)
    doc_blocks.replace_block(path, name, statements_table(statements), table["scene_hash"].dropna().astype(str),
                             doc_blocks.seed_range(table["seed"].dropna()))
    return path


def write(out: str, title: str, command: str, statements: List[Statement], outcomes: Dict[str, Outcome],
          figures: List[str], notes: str = "") -> str:
    """report.md (and report.json, the rows for programs) in `out`; returns the Markdown's path."""
    cpu = sum(o.cpu_seconds for o in outcomes.values())
    counts = {v: sum(s.verdict == v for s in statements) for v in VERDICTS}
    summary = ", ".join(f"{n} {v}" for v, n in counts.items() if n)
    failed = failures(outcomes)
    text = [f"# {title}\n",
            f"Made by `{command}`. Every number below was measured on the runs listed under *Provenance*; "
            f"{len(statements)} statements: {summary}.\n",
            "## Statements\n", statements_table(statements)]
    if notes:
        text += ["## Notes\n", notes.rstrip() + "\n"]
    text += ["## Figures\n"] + [f"![{os.path.splitext(os.path.basename(f))[0]}]({f})\n" for f in figures]
    text += ["## Failed runs\n", failed or "None.\n",
             "## Provenance\n",
             f"Total processor time of the runs: {cpu:.0f} s ({cpu / 3600:.2f} h). Each run's directory holds "
             "its run.yaml (version, scene hash, seed, plugins and their file hashes, command line).\n",
             provenance_table(outcomes)]
    path = os.path.join(out, "report.md")
    with open(path, "w") as f:
        f.write("\n".join(text))
    with open(os.path.join(out, "report.json"), "w") as f:
        json.dump({"title": title, "command": command, "cpu_seconds": cpu,
                   "statements": [dataclasses.asdict(s) for s in statements],
                   "failed_runs": [{"step": n, "run": r["run"], "status": r["status"]}
                                   for n, o in outcomes.items() for _, r in o.failed.iterrows()]}, f, indent=1)
    return path
