"""The lattice size as a resolution: what a sweep over lattice sizes (one case per lattice, several
seeds each) gives at each, with 95 % bootstrap intervals (frictionlab.ensembles), as a Markdown table
and a figure.

    build/bin/frictionlab sweep configs/li2020/lattice_convergence.yaml -o out/convergence -j 2
    PYTHONPATH=build/python /usr/bin/python3 -m frictionlab.lattice_convergence out/convergence [--figure F.png]
        [--write share/docs/lattice-resolution.md]

The quantities: the settled normal-force profile (Fig. 5; from interface_history's row at the start
of loading), the first precursor's F_S/F_N and l/L, the precursor count before the first global
slip, the global slip's F_S/F_N, and the front speeds (the first precursor's mean front speed and
the first global slip's crossing speed). Each lattice is compared with the finest; the profiles by
their root-mean-square difference to the finest's mean profile. With --by case the runs are
grouped by their case instead (a sweep that varies something else on one lattice,
configs/li2020/junction_noise.yaml), each compared with the last case. With --write, the table
replaces what stands between the <!-- BLOCK --> markers (--block, default lattice-convergence)."""
import argparse
import os
import sys

import numpy as np
import pandas as pd
import yaml

from . import doc_blocks, ensembles

# (column of the per-run table, label, format)
QUANTITIES = [
    ("first_precursor_force_ratio", "first precursor, F_S/F_N", ".3f"),
    ("first_precursor_extent", "first precursor, l/L", ".3f"),
    ("precursor_count", "precursors before the first global slip", ".2f"),
    ("global_slip_force_ratio", "first global slip, F_S/F_N", ".3f"),
    ("first_precursor_front_speed", "first precursor, mean front speed [m/s]", ".3g"),
    ("global_crossing_speed", "first global slip, crossing speed [m/s]", ".3g"),
    ("profile_gap", "settled normal-force profile, RMS difference to the finest's mean [σ̄]", ".3f"),
]


def read_run(directory, run):
    """One run's lattice, events and settled profile (`run`: its directory below cases/)."""
    folder = os.path.join(directory, "cases", run)
    with open(os.path.join(folder, "run.yaml")) as f:
        record = yaml.safe_load(f)
    bulk = record["scene"]["bulk"]
    events = pd.read_csv(os.path.join(folder, "precursors.csv"))
    forces = pd.read_csv(os.path.join(folder, "interface_normal_force.csv"))
    settled = forces.iloc[int(np.argmin(np.abs(forces["time_since_loading"].to_numpy())))]
    blocks = settled[[c for c in forces.columns if c.startswith("block_")]].to_numpy(dtype=float)
    return bulk, events, blocks


def pressure_profile(blocks, length):
    """The settled normal force per unit length over its mean (σ/σ̄), the two edge blocks carrying
    half a spacing each, against x/L."""
    n = len(blocks)
    spacing = length / (n - 1)
    widths = np.full(n, spacing)
    widths[[0, -1]] = spacing / 2
    pressure = blocks / widths
    return np.linspace(0, 1, n), pressure / (blocks.sum() / length)


def first_of(events, global_slip):
    rows = events[events["global"] == int(global_slip)]
    return rows.iloc[0] if len(rows) else None


def per_run(directory, by="lattice"):
    """One row per run: its group (lattice, or case), seed and quantities, and the profiles by
    group; the groups in the order they are compared, the last the reference."""
    statistics = pd.read_csv(os.path.join(directory, "run_statistics.csv"))
    status = pd.read_csv(os.path.join(directory, "sweep.csv"), usecols=["run", "status"])
    done = set(status[status["status"] == "done"]["run"])  # an interrupted sweep lists the rest too
    statistics = statistics[statistics["run"].isin(done)]
    rows, profiles = [], {}
    for order, s in statistics.iterrows():
        bulk, events, blocks = read_run(directory, s["run"])
        precursor, slip = first_of(events, False), first_of(events, True)
        if slip is not None and precursor is not None and precursor["t_start"] > slip["t_start"]:
            precursor = None  # the first precursor counts only before the first global slip
        x, profile = pressure_profile(blocks, float(bulk["length"]))
        lattice = f"{bulk['nx']} × {bulk['nz']}"
        group = lattice if by == "lattice" else s["case"]
        profiles.setdefault(group, {})[s["seed"]] = (x, profile)
        rows.append({
            "lattice": group, "nx": int(bulk["nx"]) if by == "lattice" else order, "seed": s["seed"],
            "first_precursor_force_ratio": s["first_precursor_force_ratio"],
            "first_precursor_extent": s["precursor_1_length"],
            "precursor_count": s["precursor_count"],
            "global_slip_force_ratio": s["global_slip_force_ratio"],
            "first_precursor_front_speed": precursor["front_speed"] if precursor is not None else np.nan,
            "global_crossing_speed": slip["crossing_speed"] if slip is not None else np.nan,
        })
    runs = pd.DataFrame(rows)
    if by == "lattice":
        runs = runs.sort_values(["nx", "seed"])
    else:  # the sweep's order of cases
        first = runs.groupby("lattice", sort=False)["nx"].transform("min")
        runs = runs.assign(order=first).sort_values(["order", "seed"]).drop(columns="order")
    finest = runs["lattice"].iloc[-1]
    fine_x, fine_mean = mean_profile(profiles[finest])
    def gap(run):  # root mean square over x/L: the edges' stress concentration narrows as l_s falls
        x, p = profiles[run["lattice"]][run["seed"]]
        return np.sqrt(np.mean((np.interp(fine_x, x, p) - fine_mean) ** 2))
    runs["profile_gap"] = runs.apply(gap, axis=1)
    return runs, profiles


def mean_profile(by_seed):
    """x/L and the mean over the seeds of one lattice's profiles."""
    profiles = list(by_seed.values())
    return profiles[0][0], np.mean([p for _, p in profiles], axis=0)


def interval(e, fmt):
    """The estimate with its interval, or with why it has none (too few seeds)."""
    if not np.isfinite(e.estimate):
        return "–"
    if e.interval:
        return f"{e.estimate:{fmt}} ({e.interval})"
    return f"{e.estimate:{fmt}} [{e.low:{fmt}}, {e.high:{fmt}}]"


def table(runs):
    lattices = list(dict.fromkeys(runs["lattice"]))
    finest = lattices[-1]
    seeds = ", ".join(f"{runs[runs['lattice'] == l]['seed'].nunique()}" for l in lattices)
    head = ["quantity"] + lattices + [f"{l} − {finest}" for l in lattices[:-1]]
    lines = [f"Seeds per column: {seeds}. Mean over the seeds with its 95 % bootstrap interval; the last "
             f"columns give each column's difference to {finest} (**bold**: resolved, the interval "
             f"excludes zero).", "", "| " + " | ".join(head) + " |", "|" + " --- |" * len(head)]
    for column, label, fmt in QUANTITIES:
        at = {l: runs[runs["lattice"] == l][column].to_numpy(dtype=float) for l in lattices}
        cells = [label.replace("the finest's", f"{finest}'s")]
        for l in lattices:
            cells.append(interval(ensembles.mean(at[l]), fmt))
        for l in lattices[:-1]:
            d = ensembles.difference(at[l], at[finest])
            text = interval(d, "+" + fmt)
            cells.append(f"**{text}**" if d.resolved and column != "profile_gap" else text)
        lines.append("| " + " | ".join(cells) + " |")
    return "\n".join(lines) + "\n"


def figure(runs, profiles, path, title):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    lattices = list(dict.fromkeys(runs["lattice"]))
    panels = [q for q in QUANTITIES if q[0] != "profile_gap"]
    fig, axes = plt.subplots(2, 4, figsize=(15, 6.5), constrained_layout=True)
    ax = axes[0, 0]
    for lattice in lattices:
        x, mean = mean_profile(profiles[lattice])
        ax.plot(x, mean, marker="o" if len(x) < 60 else None, ms=3, label=lattice)
    ax.set(xlabel="x/L", ylabel="σ_N/σ̄_N", title="settled normal force (Fig. 5)")
    ax.legend(fontsize=8)
    for ax, (column, label, _) in zip(axes.flat[1:], panels):
        for k, lattice in enumerate(lattices):
            values = runs[runs["lattice"] == lattice][column].to_numpy(dtype=float)
            finite = values[np.isfinite(values)]
            ax.plot(np.full(len(finite), k) + np.linspace(-0.15, 0.15, len(finite)), finite, ".", color="0.6")
            m = ensembles.mean(finite)
            if np.isfinite(m.estimate):  # with its interval where the seeds give one
                bar = [[m.estimate - m.low], [m.high - m.estimate]] if not m.interval else None
                ax.errorbar(k, m.estimate, yerr=bar, fmt="o", color="C0", capsize=4)
        ax.set_xticks(range(len(lattices)), lattices)
        ax.set_title(label, fontsize=9)
    ax = axes.flat[-1]  # the speed follows the stress the slip starts at, on every lattice alike
    for k, lattice in enumerate(lattices):
        at = runs[runs["lattice"] == lattice]
        ax.plot(at["global_slip_force_ratio"], at["global_crossing_speed"], "o", ms=4, color=f"C{k}", label=lattice)
    ax.set(xlabel="first global slip, F_S/F_N", ylabel="its crossing speed [m/s]",
           title="each run: speed against F_S/F_N")
    ax.legend(fontsize=8)
    fig.suptitle(f"{title} (mean and 95 % interval; grey: each seed)")
    fig.savefig(path, dpi=110)


def main(argv=None):
    parser = argparse.ArgumentParser(prog="python3 -m frictionlab.lattice_convergence",
                                     description=__doc__.splitlines()[0])
    parser.add_argument("directory", help="output directory of the sweep over lattice sizes")
    parser.add_argument("--figure", help="where to write the figure (PNG)")
    parser.add_argument("--write", nargs="*", default=[], help="files whose <!-- BLOCK --> block to replace")
    parser.add_argument("--block", default="lattice-convergence", help="name of the block --write replaces")
    parser.add_argument("--by", choices=["lattice", "case"], default="lattice",
                        help="group the runs by lattice (compared with the finest) or by case (with the last)")
    args = parser.parse_args(argv)
    runs, profiles = per_run(args.directory, args.by)
    text = table(runs)
    print(text, end="")
    if args.figure:
        groups = runs["lattice"].nunique()
        title = (f"The same slider at {groups} lattice resolutions" if args.by == "lattice"
                 else f"{groups} cases of one sweep")
        figure(runs, profiles, args.figure, title)
    hashes, seeds = doc_blocks.runs_of(args.directory)
    for doc in args.write:
        try:
            doc_blocks.replace_block(doc, args.block, text, hashes, seeds)
        except ValueError as e:
            sys.exit(str(e))


if __name__ == "__main__":
    main()
