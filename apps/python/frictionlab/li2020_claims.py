"""The claims of Li et al. 2020 about Figs. 7 and 8, each as an effect measured over the seeds of
the shipped campaigns with its 95 % bootstrap interval (frictionlab.ensembles), as Markdown.

    build/bin/frictionlab sweep configs/li2020/fig7_precursor_scaling.yaml -o out/fig7 -j 2
    build/bin/frictionlab sweep configs/li2020/fig8_nonuniform_loading.yaml -o out/fig8 -j 2
    PYTHONPATH=build/python /usr/bin/python3 -m frictionlab.li2020_claims out/fig7 out/fig8 [--write README.md]

With --write, the list replaces what stands between the <!-- li2020-claims --> markers of each
file named, and the tables of each case's means those between <!-- fig8-means --> and <!-- fig7-means
--> where a file has them."""
import argparse
import os
import sys
from typing import NamedTuple

import numpy as np
import pandas as pd
import yaml

from . import doc_blocks, ensembles
from .reproduce.report import Statement

THETA = "loaders[1].theta"
FORCE, HEIGHT = "loaders[1].total_force", "loaders[2].height"


EDGE_BLOCK = "edge_block_extent"
COLLAPSE_MARGIN = 0.1  # |Δ l/L| between configurations at matched F_S/F_N (physics notes C.4's suggested test)


class Claim(NamedTuple):
    line: str             # the Markdown line of the docs' generated block
    statement: Statement  # the row of a reproduction report


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


def verdict_of(e, wanted_sign):
    """reproduced when the effect is resolved with the sign the paper states; else differs, and why."""
    if e.resolved and (e.estimate > 0) == (wanted_sign > 0):
        return "reproduced", ""
    if e.resolved:
        return "differs", "resolved, with the opposite sign"
    return "differs", "not resolved" if not e.interval else e.interval


def fig8_claims(directory):
    """Fig. 8's statements (physics notes C.5), each a Markdown line and a report Statement."""
    runs = pd.read_csv(os.path.join(directory, "run_statistics.csv"))
    thetas = sorted(runs[THETA].unique())
    at = {t: runs[runs[THETA] == t] for t in thetas}
    seeds = runs["seed"].nunique()
    claims = []
    slope = ensembles.slope(runs[THETA], runs["precursor_count"])
    extremes = ensembles.difference(at[thetas[-1]]["precursor_count"], at[thetas[0]]["precursor_count"])
    measured = (f"slope {interval(slope, 2)} precursors per unit θ; θ = {thetas[-1]:g} against {thetas[0]:g}: "
                f"{interval(extremes, 1)}{unresolved(slope, seeds)}")
    claims.append(Claim(f"- **The precursor count rises with θ** (Fig. 8): {measured}.",
                        Statement("Fig. 8", "The number of precursors before the first global slip rises with θ "
                                  "(less load at the driven edge)", measured, *verdict_of(slope, +1))))
    later, verdicts = [], []
    for t in (t for t in thetas if t > 0):
        time = ensembles.difference(at[t]["first_precursor_time_since_loading"],
                                    at[0]["first_precursor_time_since_loading"])
        ratio = ensembles.difference(at[t]["first_precursor_force_ratio"], at[0]["first_precursor_force_ratio"])
        later.append(f"at θ = {t:g}, {interval(time, 0, 1e3)} ms and F_S/F_N {interval(ratio)}"
                     f"{unresolved(time, seeds)}")
        verdict, why = verdict_of(ratio, -1)
        verdicts.append((verdict, f"θ = {t:g}: F_S/F_N {why}" if why else ""))
    measured = "its start against θ = 0 " + "; ".join(later)
    differs = [why for v, why in verdicts if v != "reproduced"]
    claims.append(Claim("- **The first precursor comes earlier for θ > 0**: " + measured + ".",
                        Statement("Fig. 8", "The lower the driven edge's normal load (θ > 0), the lower the F_S at "
                                  "which the first precursors nucleate", measured,
                                  "differs" if differs else "reproduced", "; ".join(differs))))
    shifts = {t: ensembles.difference(at[t]["global_slip_force_ratio"], at[0]["global_slip_force_ratio"])
              for t in thetas if t != 0}
    worst = max(shifts, key=lambda t: abs(shifts[t].estimate))
    base = at[0]["global_slip_force_ratio"].mean()
    relative = shifts[worst].estimate / base
    measured = (f"{base:.3f} at θ = 0; the largest shift is at θ = {worst:g}, {interval(shifts[worst])} "
                f"({relative:+.0%}){unresolved(shifts[worst], seeds)}")
    claims.append(Claim(f"- **The global F_S/F_N barely depends on θ**: {measured}.",
                        Statement("Fig. 8", "The F_S/F_N of the global slip is nearly independent of θ", measured,
                                  *(("differs", f"{relative:+.0%} at θ = {worst:g}, resolved")
                                    if shifts[worst].resolved else ("reproduced", "")))))
    return claims, seeds


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
    """Fig. 7's statements (physics notes C.4), each a Markdown line and a report Statement."""
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
    measured = (f"the largest |Δ l/L| between the configurations' mean curves at matched F_S/F_N is {between:.3f}; "
                f"between the mean curves of two halves of one configuration's seeds it is {min(halves):.3f} to "
                f"{max(halves):.3f}")
    claims = [Claim(f"- **Fig. 7's curves collapse across F_N** ({loads} kN, h = {h5[0][1] * 1e3:g} mm): {measured}.",
                    Statement("Fig. 7", f"l/L against F_S/F_N collapses onto one curve across F_N ({loads} kN, "
                              f"h = {h5[0][1] * 1e3:g} mm)", measured,
                              *(("reproduced within a stated margin", f"|Δ l/L| ≤ {COLLAPSE_MARGIN:g}")
                                if between <= COLLAPSE_MARGIN else
                                ("differs", f"{between:.2f} apart, beyond the {COLLAPSE_MARGIN:g} allowed"))))]
    low = runs[runs[FORCE] == min(runs[FORCE])]
    heights = sorted(low[HEIGHT].unique())
    lower, higher = low[low[HEIGHT] == heights[0]], low[low[HEIGHT] == heights[-1]]

    def longest(height):
        return [max(c[1], default=np.nan) for c in curves[(min(runs[FORCE]), height)].values()]

    start = ensembles.difference(lower["first_precursor_force_ratio"], higher["first_precursor_force_ratio"])
    count = ensembles.difference(lower["precursor_count"], higher["precursor_count"])
    length = ensembles.difference(longest(heights[0]), longest(heights[-1]))
    measured = (f"the first starts at F_S/F_N {interval(start)}{unresolved(start, seeds)}; precursors before the "
                f"global slip {interval(count, 1)}{unresolved(count, seeds)}; the longest one's l/L "
                f"{interval(length, 2)}{unresolved(length, seeds)}")
    verdicts = [verdict_of(start, -1), verdict_of(count, +1), verdict_of(length, +1)]
    wrong = [f"{what}: {why}" for what, (v, why) in zip(("start", "count", "length"), verdicts) if v != "reproduced"]
    claims.append(Claim(f"- **Driving lower (h = {heights[0] * 1e3:g} mm against {heights[-1] * 1e3:g} mm, "
                        f"{min(runs[FORCE]) / 1000:g} kN) gives earlier and longer precursors**: {measured}.",
                        Statement("Fig. 7", f"Driving lower (h = {heights[0] * 1e3:g} mm against "
                                  f"{heights[-1] * 1e3:g} mm) gives earlier, more and longer precursors", measured,
                                  "differs" if wrong else "reproduced", "; ".join(wrong))))
    return claims, seeds


TABLE_COLUMNS = (("precursor_count", "precursors before the global slip", 1),
                 ("first_precursor_force_ratio", "first precursor F_S/F_N", 3),
                 ("first_precursor_time_since_loading", "first precursor time [s]", 3),
                 ("global_slip_force_ratio", "global F_S/F_N", 3))


def means_table(directory, label):
    """Each case's means with their intervals (sweep_statistics.csv), and how many runs disagree
    with their own check, as a Markdown table; `label(case row)` names a case."""
    stats = pd.read_csv(os.path.join(directory, "sweep_statistics.csv"), keep_default_na=False,
                        na_values=["nan", ""])
    lines = ["| case | " + " | ".join(title for _, title, _ in TABLE_COLUMNS) + " | runs disagreeing |",
             "| --- " * (len(TABLE_COLUMNS) + 2) + "|"]
    for case, rows in stats.groupby("case", sort=False):
        by = rows.set_index("statistic")
        cells = []
        for statistic, _, digits in TABLE_COLUMNS:
            r = by.loc[statistic]
            cells.append(f"{r['mean']:.{digits}f} ({r['interval']})" if isinstance(r["interval"], str) and r["interval"]
                         else f"{r['mean']:.{digits}f} [{r['ci_low']:.{digits}f}, {r['ci_high']:.{digits}f}]")
        disagreeing = int(rows["disagreeing"].max())
        lines.append(f"| {label(rows.iloc[0])} | " + " | ".join(cells) + f" | {disagreeing} of {int(by.loc['precursor_count', 'n'])} |")
    return "\n".join(lines) + "\n"


def fig8_table(directory):
    return means_table(directory, lambda r: f"θ = {r[THETA]:g}")


def fig7_table(directory):
    return means_table(directory, lambda r: f"{r[FORCE] / 1000:g} kN, h = {r[HEIGHT] * 1e3:g} mm")


def write_blocks(doc, blocks, hashes, seeds):
    """Replaces each block the document has (name: what makes its text); it need not have them all."""
    with open(doc) as f:
        present = f.read()
    for name, make in blocks.items():
        if f"<!-- /{name} -->" in present:
            doc_blocks.replace_block(doc, name, make(), hashes, seeds)


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
            "effect with its 95 % bootstrap interval:\n\n" + "\n".join(c.line for c in fig8 + fig7) + "\n")
    print(text, end="")
    hashes, seeds = doc_blocks.runs_of(args.fig7, args.fig8)
    blocks = {"li2020-claims": lambda: text, "fig8-means": lambda: fig8_table(args.fig8),
              "fig7-means": lambda: fig7_table(args.fig7)}
    for doc in args.write:
        try:
            write_blocks(doc, blocks, hashes, seeds)
        except ValueError as e:
            sys.exit(str(e))


if __name__ == "__main__":
    main()
