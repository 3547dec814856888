"""The width study (configs/3d/width_study.yaml, after Iwashita, Matsukawa & Otsuki, Sci. Rep. 13,
2023): the first global slip's F_S/F_N, the precursors before it and the first precursor's area
against the slider's width, each a mean over seeds with its bootstrap interval (frictionlab.ensembles),
and the slope of each against the width over the bounded cases.

    python3 -m frictionlab.width_study out/width_study [out/width_study_square] [--figure width_study.png]

A case's width is its node count across times the spacing, n_y a: with every node carrying the same
load, mass and drive (the study's scaling), that is the width each node's column stands for. A
periodic case (one period of a slider unbounded across) has no width: it is the row `periodic`,
left out of the slopes."""
import argparse
import math
import os
import sys
from typing import Dict, List, NamedTuple

import numpy as np
import yaml

from . import ensembles


class Case(NamedTuple):
    name: str
    width: float           # n_y a (m); inf across a periodic width
    global_ratio: list     # F_S/F_N at the first global slip, one per seed
    precursors: list       # precursors before the first global slip, one per seed
    first_area: list       # the first precursor's area (m^2), one per seed; NaN without one
    disagreeing: int       # runs whose events disagree with their loading curve


def _first_precursor_area(run: str, bulk: dict) -> float:
    """The area of the run's first event that is not global, if it starts before the first global
    slip: its ruptured blocks' share of the interface times the interface's n_x n_y cells of a^2."""
    path = os.path.join(run, "precursors.csv")
    if not os.path.exists(path):
        return math.nan
    events = np.genfromtxt(path, delimiter=",", names=True, ndmin=1)
    if events.size == 0 or events["global"][0] == 1:
        return math.nan
    spacing = float(bulk["length"]) / (int(bulk["nx"]) - 1)
    return float(events["area_fraction"][0]) * int(bulk["nx"]) * int(bulk["ny"]) * spacing ** 2


def cases(sweep: str) -> List[Case]:
    """The study's cases in the order of its sweep.csv, each with its seeds' values."""
    rows = np.genfromtxt(os.path.join(sweep, "sweep.csv"), delimiter=",", names=True, dtype=None,
                         encoding="utf-8", ndmin=1)
    found: Dict[str, dict] = {}
    for row in rows:
        if row["status"] != "done":
            continue
        run = os.path.join(sweep, "cases", row["run"])
        with open(os.path.join(run, "run.yaml"), encoding="utf-8") as f:
            bulk = yaml.safe_load(f)["scene"]["bulk"]
        spacing = float(bulk["length"]) / (int(bulk["nx"]) - 1)
        width = math.inf if bulk.get("across") == "periodic" else int(bulk["ny"]) * spacing
        case = found.setdefault(str(row["case"]), {"width": width, "g": [], "p": [], "a": [], "bad": 0})
        case["g"].append(float(row["global_slip_force_ratio"]))
        case["p"].append(float(row["precursor_count"]))
        case["a"].append(_first_precursor_area(run, bulk))
        case["bad"] += str(row["events_agree"]).lower() == "false"
    return [Case(name, c["width"], c["g"], c["p"], c["a"], c["bad"]) for name, c in found.items()]


def _effect(e: ensembles.Effect, digits: int, scale: float = 1) -> str:
    value = f"{e.estimate * scale:.{digits}f}"
    return value if e.interval else f"{value} [{e.low * scale:.{digits}f}, {e.high * scale:.{digits}f}]"


def table(study: List[Case]) -> str:
    """Markdown: each case's means with their intervals, then the slopes against the width."""
    lines = ["| case | width (mm) | seeds | F_S/F_N at the first global slip | precursors before it | "
             "first precursor's area (mm²) |", "| --- | --- | --- | --- | --- | --- |"]
    for c in study:
        width = "periodic" if math.isinf(c.width) else f"{c.width * 1e3:g}"
        seeds = f"{len(c.global_ratio)}" + (f" ({c.disagreeing} disagreeing)" if c.disagreeing else "")
        lines.append(f"| {c.name} | {width} | {seeds} | {_effect(ensembles.mean(c.global_ratio), 4)} | "
                     f"{_effect(ensembles.mean(c.precursors), 1)} | {_effect(ensembles.mean(c.first_area), 1, 1e6)} |")
    bounded = [c for c in study if not math.isinf(c.width)]
    if len(bounded) > 1:
        def slope(values):
            x = [c.width * 1e3 for c in bounded for _ in getattr(c, values)]
            return ensembles.slope(x, [v for c in bounded for v in getattr(c, values)])
        lines += ["", "Slopes against the width over the bounded cases (per mm): F_S/F_N "
                  f"{_effect(slope('global_ratio'), 5)}, precursors {_effect(slope('precursors'), 3)}, "
                  f"first precursor's area {_effect(slope('first_area'), 2, 1e6)} mm²."]
    return "\n".join(lines)


def figure(study: List[Case], path: str) -> None:
    """The three statistics against the width (bounded cases; the periodic case as a line)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    panels = (("global_ratio", "F_S/F_N at the first global slip", 1), ("precursors", "precursors before it", 1),
              ("first_area", "first precursor's area (mm²)", 1e6))
    fig, axes = plt.subplots(1, 3, figsize=(12, 3.6))
    for ax, (field, label, scale) in zip(axes, panels):
        for c in study:
            e = ensembles.mean(getattr(c, field))
            if math.isinf(c.width):
                ax.axhline(e.estimate * scale, color="0.5", ls="--", label="periodic (unbounded)")
                continue
            error = [[(e.estimate - e.low) * scale], [(e.high - e.estimate) * scale]] if not e.interval else None
            ax.errorbar([c.width * 1e3], [e.estimate * scale], yerr=error, fmt="o", color="C0", capsize=3)
        ax.set_xlabel("width n_y a (mm)")
        ax.set_ylabel(label)
        ax.set_xlim(left=0)
    axes[0].legend(loc="best", fontsize="small")
    fig.suptitle("The headline's 3D twin against its width (means over seeds, 95 % bootstrap intervals)")
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(prog="python3 -m frictionlab.width_study", description=__doc__.split("\n\n")[0])
    parser.add_argument("sweeps", nargs="+", help="the output folders of frictionlab sweep configs/3d/width_study.yaml "
                        "(and of width_study_square.yaml), their cases in this order")
    parser.add_argument("--figure", help="also draw the statistics against the width into this file")
    args = parser.parse_args(argv)
    study = [case for sweep in args.sweeps for case in cases(sweep)]
    if not study:
        print(f"{', '.join(args.sweeps)}: no finished case", file=sys.stderr)
        return 1
    print(table(study))
    if args.figure:
        figure(study, args.figure)
    return 0


if __name__ == "__main__":
    sys.exit(main())
