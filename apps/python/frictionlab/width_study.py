"""The width study (configs/3d/width_study.yaml, after Iwashita, Matsukawa & Otsuki, Sci. Rep. 13,
2023): the first global slip's F_S/F_N, the precursors before it and the first precursor's area
against the slider's width, each a mean over seeds with its bootstrap interval (frictionlab.ensembles),
and the slope of each against the width over the bounded cases.

    python3 -m frictionlab.width_study SOURCE... [--figure width_study.png] [--save seeds.csv]

A source is a sweep's output folder or a seeds file that --save wrote: each seed's values with its
stepper, scene hash, version and processor time. The docs' study is such a file
(share/docs/data/width_study_seeds.csv), so its table and figure are redrawn in seconds, and a case
run anew replaces its rows:

    python3 -m frictionlab.width_study share/docs/data/width_study_seeds.csv out/width_study_square \\
        --save share/docs/data/width_study_seeds.csv --figure share/docs/images/width_study.png

A case's width is its node count across times the spacing, n_y a: with every node carrying the same
load, mass and drive (the study's scaling), that is the width each node's column stands for. A
periodic case (one period of a slider unbounded across) has no width: it is the row `periodic`,
left out of the slopes."""
import argparse
import csv
import math
import os
import sys
from typing import Dict, List, NamedTuple

import numpy as np
import yaml

from . import ensembles


class Seed(NamedTuple):
    """One finished run of the study: what the table and the figure are made of, and what made it."""
    case: str
    width: float           # n_y a (m); inf across a periodic width
    seed: int
    global_ratio: float    # F_S/F_N at the first global slip
    precursors: float      # precursors before it
    first_ratio: float     # F_S/F_N at the first precursor
    first_area: float      # the first precursor's area (m^2); NaN without one before the global slip
    events_agree: bool     # its events agree with its loading curve
    integrator: str
    scene_hash: str
    version: str
    cpu_seconds: float


class Case(NamedTuple):
    name: str
    width: float           # n_y a (m); inf across a periodic width
    global_ratio: list     # F_S/F_N at the first global slip, one per seed
    precursors: list       # precursors before the first global slip, one per seed
    first_area: list       # the first precursor's area (m^2), one per seed; NaN without one
    disagreeing: int       # runs whose events disagree with their loading curve
    integrator: str        # the seeds' stepper ("mixed" if they differ)


# The columns of a study's seeds file (--save), in this order.
SEED_COLUMNS = {"case": "case", "width": "width_m", "seed": "seed", "global_ratio": "global_slip_force_ratio",
                "precursors": "precursor_count", "first_ratio": "first_precursor_force_ratio",
                "first_area": "first_precursor_area_m2", "events_agree": "events_agree",
                "integrator": "integrator", "scene_hash": "scene_hash", "version": "version",
                "cpu_seconds": "cpu_seconds"}


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


def _sweep_seeds(sweep: str) -> List[Seed]:
    """A sweep's finished runs, in the order of its sweep.csv."""
    with open(os.path.join(sweep, "sweep.csv"), encoding="utf-8", newline="") as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    seeds = []
    for row in rows:
        if row["status"] != "done":
            continue
        run = os.path.join(sweep, "cases", row["run"])
        with open(os.path.join(run, "run.yaml"), encoding="utf-8") as f:
            record = yaml.safe_load(f)
        scene = record["scene"]
        bulk = scene["bulk"]
        spacing = float(bulk["length"]) / (int(bulk["nx"]) - 1)
        width = math.inf if bulk.get("across") == "periodic" else int(bulk["ny"]) * spacing
        seeds.append(Seed(row["case"], width, int(row["seed"]), float(row["global_slip_force_ratio"]),
                          float(row["precursor_count"]), float(row.get("first_precursor_force_ratio", "nan")),
                          _first_precursor_area(run, bulk), row["events_agree"].lower() != "false",
                          str(scene.get("integrator", {}).get("type", "")), row.get("scene_hash", ""),
                          str(record.get("version", "")), float(row.get("cpu_seconds", "nan"))))
    return seeds


def _file_seeds(path: str) -> List[Seed]:
    """The seeds a previous --save wrote."""
    with open(path, encoding="utf-8", newline="") as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    kinds = Seed.__annotations__
    return [Seed(**{field: (row[column].lower() == "true" if kinds[field] is bool else kinds[field](row[column]))
                    for field, column in SEED_COLUMNS.items()}) for row in rows]


def load(sources: List[str]) -> List[Seed]:
    """The seeds of sweeps' output folders and of seeds files, in order; a case found again in a
    later source is replaced by it where it first stood (a study's data, with one case run anew)."""
    found: Dict[str, List[Seed]] = {}
    for source in sources:
        by_case: Dict[str, List[Seed]] = {}
        for s in _file_seeds(source) if os.path.isfile(source) else _sweep_seeds(source):
            by_case.setdefault(s.case, []).append(s)
        found.update(by_case)
    return [s for seeds in found.values() for s in seeds]


def save(seeds: List[Seed], path: str) -> None:
    """The seeds as CSV, one row a run, which load reads back."""
    with open(path, "w", encoding="utf-8", newline="") as f:
        out = csv.writer(f, lineterminator="\n")
        out.writerow(SEED_COLUMNS.values())
        for s in seeds:
            out.writerow([repr(v) if isinstance(v, float) else str(v).lower() if isinstance(v, bool) else v
                          for v in s])


def cases(seeds: List[Seed]) -> List[Case]:
    """The study's cases in the order their seeds come, each with its seeds' values."""
    found: Dict[str, List[Seed]] = {}
    for s in seeds:
        found.setdefault(s.case, []).append(s)
    return [Case(name, runs[0].width, [r.global_ratio for r in runs], [r.precursors for r in runs],
                 [r.first_area for r in runs], sum(not r.events_agree for r in runs),
                 runs[0].integrator if len({r.integrator for r in runs}) == 1 else "mixed")
            for name, runs in found.items()]


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
    """The three statistics against the width on a logarithmic axis (bounded cases, each seed as a
    dot and the mean with its interval, marked by the stepper; the periodic case as a line)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    panels = (("global_ratio", "F_S/F_N at the first global slip", 1), ("precursors", "precursors before it", 1),
              ("first_area", "first precursor's area (mm²)", 1e6))
    steppers = {"quasi_static_hybrid": ("o", "C0", "hybrid"), "rk4": ("s", "C1", "RK4")}
    bounded = [c for c in study if not math.isinf(c.width)]
    fig, axes = plt.subplots(1, 3, figsize=(12, 3.8))
    for ax, (field, label, scale) in zip(axes, panels):
        for c in study:
            values = np.asarray(getattr(c, field), dtype=float) * scale
            e = ensembles.mean(getattr(c, field))
            if math.isinf(c.width):
                ax.axhline(e.estimate * scale, color="0.5", ls="--", label="periodic (unbounded)")
                continue
            marker, color, stepper = steppers.get(c.integrator, ("D", "C2", c.integrator))
            ax.plot([c.width * 1e3] * len(values), values, ".", color="0.6", ms=4)
            error = [[(e.estimate - e.low) * scale], [(e.high - e.estimate) * scale]] if not e.interval else None
            ax.errorbar([c.width * 1e3], [e.estimate * scale], yerr=error, fmt=marker, color=color, capsize=3,
                        label=stepper)
        ax.set_xscale("log")
        ax.set_xticks([c.width * 1e3 for c in bounded])
        ax.set_xticklabels([f"{c.width * 1e3:g}" for c in bounded], fontsize="small")
        ax.minorticks_off()
        ax.set_xlabel("width n_y a (mm)")
        ax.set_ylabel(label)
    handles, labels = axes[0].get_legend_handles_labels()
    unique = dict(zip(labels, handles))
    axes[0].legend(unique.values(), unique.keys(), loc="best", fontsize="small")
    fig.suptitle("The headline's 3D twin against its width (seeds, their means and 95 % bootstrap intervals)")
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(prog="python3 -m frictionlab.width_study", description=__doc__.split("\n\n")[0])
    parser.add_argument("sources", nargs="+", help="the output folders of frictionlab sweep configs/3d/width_study*.yaml "
                        "or seeds files (--save), their cases in this order; a case found again in a later source "
                        "is replaced by it")
    parser.add_argument("--figure", help="also draw the statistics against the width into this file")
    parser.add_argument("--save", help="also write every seed's values, with what made them, into this CSV file "
                        "(share/docs/data/width_study_seeds.csv holds the docs' study)")
    args = parser.parse_args(argv)
    try:
        seeds = load(args.sources)
    except OSError as e:
        print(f"{e.filename}: {e.strerror} (a sweep writes sweep.csv when it ends)", file=sys.stderr)
        return 1
    study = cases(seeds)
    if not study:
        print(f"{', '.join(args.sources)}: no finished case", file=sys.stderr)
        return 1
    if args.save:
        save(seeds, args.save)
    print(table(study))
    if args.figure:
        figure(study, args.figure)
    return 0


if __name__ == "__main__":
    sys.exit(main())
