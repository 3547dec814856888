"""The claims of Li et al. 2020 about Figs. 7 and 8, each as an effect measured over the seeds of
the shipped campaigns with its 95 % bootstrap interval (frictionlab.ensembles), as Markdown.

    build/bin/frictionlab sweep configs/li2020/fig7_precursor_scaling.yaml -o out/fig7 -j 2
    build/bin/frictionlab sweep configs/li2020/fig8_nonuniform_loading.yaml -o out/fig8 -j 2
    PYTHONPATH=build/python /usr/bin/python3 -m frictionlab.li2020_claims out/fig7 out/fig8 [--write README.md]

With --write, the list replaces what stands between the <!-- li2020-claims --> markers of each
file named."""
import argparse
import os
import sys

import numpy as np
import pandas as pd
import yaml

from . import doc_blocks, ensembles

THETA = "loaders[1].theta"
FORCE, HEIGHT = "loaders[1].total_force", "loaders[2].height"


EDGE_BLOCK = "edge_block_extent"


def with_edge_block(directory, table):
    """`table` (rows of runs, each with its directory below cases/ in `run`) with the l/L of an
    event of the driven edge's block alone: half a spacing over the length, from the lattice each
    run's run.yaml records."""
    def extent(run):
        with open(os.path.join(directory, "cases", run, "run.yaml")) as f:
            return 0.5 / (int(yaml.safe_load(f)["scene"]["bulk"]["nx"]) - 1)
    return table.assign(**{EDGE_BLOCK: table["run"].map({r: extent(r) for r in table["run"].unique()})})


def interval(e, digits=3, scale=1.0):
    """The effect with its interval, or with why it has none (too few seeds)."""
    if e.interval:
        return f"{e.estimate * scale:+.{digits}f} ({e.interval})"
    return f"{e.estimate * scale:+.{digits}f} [{e.low * scale:+.{digits}f}, {e.high * scale:+.{digits}f}]"


def unresolved(e, seeds):
    if e.resolved or e.interval:
        return ""
    return f" (not resolved at {seeds} seeds; about {ensembles.seeds_to_resolve(e, seeds):.0f} would resolve it)"


def fig8_claims(directory):
    runs = pd.read_csv(os.path.join(directory, "run_statistics.csv"))
    thetas = sorted(runs[THETA].unique())
    at = {t: runs[runs[THETA] == t] for t in thetas}
    seeds = runs["seed"].nunique()
    lines = []
    slope = ensembles.slope(runs[THETA], runs["precursor_count"])
    extremes = ensembles.difference(at[thetas[-1]]["precursor_count"], at[thetas[0]]["precursor_count"])
    lines.append(f"- **The precursor count rises with θ** (Fig. 8): slope {interval(slope, 2)} precursors per "
                 f"unit θ; θ = {thetas[-1]:g} against {thetas[0]:g}: {interval(extremes, 1)}"
                 f"{unresolved(slope, seeds)}.")
    later = []
    for t in (t for t in thetas if t > 0):
        time = ensembles.difference(at[t]["first_precursor_time_since_loading"],
                                    at[0]["first_precursor_time_since_loading"])
        ratio = ensembles.difference(at[t]["first_precursor_force_ratio"], at[0]["first_precursor_force_ratio"])
        later.append(f"at θ = {t:g}, {interval(time, 0, 1e3)} ms and F_S/F_N {interval(ratio)}"
                     f"{unresolved(time, seeds)}")
    lines.append("- **The first precursor comes earlier for θ > 0**: its start against θ = 0 " + "; ".join(later)
                 + ".")
    shifts = {t: ensembles.difference(at[t]["global_slip_force_ratio"], at[0]["global_slip_force_ratio"])
              for t in thetas if t != 0}
    worst = max(shifts, key=lambda t: abs(shifts[t].estimate))
    base = at[0]["global_slip_force_ratio"].mean()
    lines.append(f"- **The global F_S/F_N barely depends on θ**: {base:.3f} at θ = 0; the largest shift is at "
                 f"θ = {worst:g}, {interval(shifts[worst])} ({shifts[worst].estimate / base:+.0%})"
                 f"{unresolved(shifts[worst], seeds)}.")
    return lines, seeds


def precursor_curves(directory):
    """Each run's precursors before its first global slip as l/L against F_S/F_N, by configuration
    (F_N, h): {(F_N, h): {seed: (F, l/L) sorted by F}}. Slips of the driven edge's block alone are
    left out: they are no front, and their l/L would pull a curve to zero between two precursors."""
    events = with_edge_block(directory, pd.read_csv(os.path.join(directory, "events.csv")))
    curves = {}
    for (force, height, seed), run in events.groupby([FORCE, HEIGHT, "seed"]):
        run = run.sort_values("t_start")
        globals_ = run.index[run["kind"] == "global"]
        if len(globals_):
            run = run.loc[: globals_[0]].iloc[:-1]
        run = run[run["extent_over_length"] > 1.01 * run[EDGE_BLOCK]].sort_values("force_ratio")
        curves.setdefault((force, height), {})[seed] = (run["force_ratio"].to_numpy(),
                                                        run["extent_over_length"].to_numpy())
    return curves


def mean_curve(runs, grid):
    """The seeds' mean l/L at each F_S/F_N of `grid`, each seed interpolated between its precursors
    (NaN outside them); NaN where fewer than half of the seeds have a value."""
    values = np.array([np.interp(grid, f, l, left=np.nan, right=np.nan) if len(f) > 1 else np.full(len(grid), np.nan)
                       for f, l in runs])
    enough = np.sum(np.isfinite(values), axis=0) >= max(2, len(runs) / 2)
    mean = np.full(len(grid), np.nan)
    mean[enough] = np.nanmean(values[:, enough], axis=0)
    return mean


def largest_gap(a, b):
    gap = np.abs(a - b)
    return float(np.nanmax(gap)) if np.any(np.isfinite(gap)) else float("nan")


def fig7_claims(directory):
    runs = pd.read_csv(os.path.join(directory, "run_statistics.csv"))
    seeds = runs["seed"].nunique()
    curves = precursor_curves(directory)
    grid = np.linspace(0, 0.6, 601)
    h5 = sorted(k for k in curves if k[1] == max(k[1] for k in curves))
    means = {k: mean_curve(list(curves[k].values()), grid) for k in h5}
    between = max(largest_gap(means[a], means[b]) for i, a in enumerate(h5) for b in h5[i + 1:])
    halves = []
    for k in h5:
        ordered = [curves[k][s] for s in sorted(curves[k])]
        half = len(ordered) // 2
        halves.append(largest_gap(mean_curve(ordered[:half], grid), mean_curve(ordered[half:], grid)))
    loads = ", ".join(f"{k[0] / 1000:g}" for k in h5)
    lines = [f"- **Fig. 7's curves collapse across F_N** ({loads} kN, h = {h5[0][1] * 1e3:g} mm): the largest "
             f"|Δ l/L| between the configurations' mean curves at matched F_S/F_N is {between:.3f}; between the "
             f"mean curves of two halves of one configuration's seeds it is {min(halves):.3f} to {max(halves):.3f}."]
    low = runs[runs[FORCE] == min(runs[FORCE])]
    heights = sorted(low[HEIGHT].unique())
    lower, higher = low[low[HEIGHT] == heights[0]], low[low[HEIGHT] == heights[-1]]

    def longest(height):
        return [max(c[1], default=np.nan) for c in curves[(min(runs[FORCE]), height)].values()]

    start = ensembles.difference(lower["first_precursor_force_ratio"], higher["first_precursor_force_ratio"])
    count = ensembles.difference(lower["precursor_count"], higher["precursor_count"])
    length = ensembles.difference(longest(heights[0]), longest(heights[-1]))
    lines.append(f"- **Driving lower (h = {heights[0] * 1e3:g} mm against {heights[-1] * 1e3:g} mm, "
                 f"{min(runs[FORCE]) / 1000:g} kN) gives earlier and longer precursors**: the first starts at "
                 f"F_S/F_N {interval(start)}{unresolved(start, seeds)}; precursors before the global slip "
                 f"{interval(count, 1)}{unresolved(count, seeds)}; the longest one's l/L "
                 f"{interval(length, 2)}{unresolved(length, seeds)}.")
    return lines, seeds


def main(argv=None):
    parser = argparse.ArgumentParser(prog="python3 -m frictionlab.li2020_claims",
                                     description=__doc__.splitlines()[0])
    parser.add_argument("fig7", help="output directory of the Fig. 7 sweep")
    parser.add_argument("fig8", help="output directory of the Fig. 8 sweep")
    parser.add_argument("--write", nargs="*", default=[], help="files whose <!-- li2020-claims --> block to replace")
    args = parser.parse_args(argv)
    fig8, seeds8 = fig8_claims(args.fig8)
    fig7, seeds7 = fig7_claims(args.fig7)
    text = (f"Measured over {seeds8} seeds a point (Fig. 8) and {seeds7} a configuration (Fig. 7); each "
            "effect with its 95 % bootstrap interval:\n\n" + "\n".join(fig8 + fig7) + "\n")
    print(text, end="")
    for doc in args.write:
        try:
            doc_blocks.replace_block(doc, "li2020-claims", text)
        except ValueError as e:
            sys.exit(str(e))


if __name__ == "__main__":
    main()
