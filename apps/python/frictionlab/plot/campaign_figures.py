"""The figures of a campaign: a sweep's, from its sweep.csv, events.csv, run_statistics.csv and
sweep_statistics.csv (Li2020 Figs. 7, 8), and an accuracy study's, from its study.csv and, over
seeds, its ensemble.csv.
Each function draws onto the Axes it is given (a new figure of the command's size if None) and
returns them; plot_sweep and plot_study write them as `frictionlab plot SWEEP_DIR` and
`frictionlab study` do. Axes name the varied keys by symbol and unit, titles come from the
campaign file's `title`, an empty panel says why, and the seeds of a case are told apart."""
import os

import matplotlib.lines
import matplotlib.ticker
import numpy as np

from ._clock import from_loading, overlaid_time_label, time_origin
from ._figure import axes_of, no_data, save, seed_style
from ._labels import key_axis_label, key_display, key_value_label
from ._tables import campaign_meta, campaign_rows, number, sidecar_text, table

def varied_keys(sweep):
    """The scene's key paths a sweep varies (but the seed), as its sidecar records them: only the
    keys that take more than one value over its runs; one set to the same value in every case is
    a constant of the sweep (the sidecar's `constants`), not an axis."""
    return list(campaign_meta(sweep, "sweep.csv").get("varied") or [])


def numeric_keys(sweep, cases):
    """The varied keys whose every value is a number (such as theta): each has its sweep_against."""
    return [k for k in varied_keys(sweep) if all(np.isfinite(number(r[k])) for r in cases)]


def sweep_units(sweep):
    """{column: unit} of sweep.csv, as its sidecar records them (empty for a sweep without one)."""
    return campaign_meta(sweep, "sweep.csv").get("units") or {}


def sweep_title(sweep):
    """The sweep file's `title` (its sidecar's), else the sweep directory's name."""
    return campaign_meta(sweep, "sweep.csv").get("title") or os.path.basename(os.path.abspath(sweep))


def case_group(row, varied, units=None):
    """The case of a row of sweep.csv or events.csv (its seeds together), as a label of its values
    by symbol and unit ("$h$ = 5 mm, $F_N$ = 400 N"), or its name where no key varies."""
    units = units or {}
    return ", ".join(key_value_label(k, row[k], units.get(k, "")) for k in varied) or row["case"]


def seed_of_row(row):
    """The seed of a row of sweep.csv or events.csv (None in a sweep without seeds)."""
    return row.get("seed") or None


def seed_legend(ax, seeds, **legend):
    """A second legend of the seeds' markers, grey, below the cases' (only with two seeds or more)."""
    if len(seeds) < 2:
        return
    first = ax.get_legend()
    handles = [matplotlib.lines.Line2D([], [], color="0.4", ls="none", ms=4, marker=seed_style(seeds, s)["marker"],
                                       label=f"seed {s}") for s in sorted(set(seeds))]
    ax.legend(handles=handles, **legend)
    if first is not None:
        ax.add_artist(first)


def sweep_precursor_lengths(sweep, ax=None):
    """l/L against F_S/F_N of every rupture event of every case of the sweep directory `sweep`,
    coloured by case, a marker per seed (Li2020 Fig. 7)."""
    cases = campaign_rows(sweep, "sweep.csv")
    events = campaign_rows(sweep, "events.csv")
    varied, units = varied_keys(sweep), sweep_units(sweep)
    groups = list(dict.fromkeys(case_group(r, varied, units) for r in cases))
    seeds = list(dict.fromkeys(seed_of_row(r) for r in cases))
    ax = axes_of(ax, figsize=(7, 5))
    for k, g in enumerate(groups):
        for seed in seeds:
            pts = [(number(e["force_ratio"]), number(e["extent_over_length"])) for e in events
                   if case_group(e, varied, units) == g and seed_of_row(e) == seed]
            if pts:
                first = g not in ax.get_legend_handles_labels()[1]
                ax.plot([p[0] for p in pts], [p[1] for p in pts], ls="none", marker=seed_style(seeds, seed)["marker"],
                        color=f"C{k % 10}", label=g if first else None, ms=4, alpha=0.8)
    ax.set_xlabel("$F_S/F_N$ at the event's start")
    ax.set_ylabel("rupture length $l/L$")
    if ax.lines:
        ax.legend(fontsize=8, loc="upper left")
        seed_legend(ax, seeds, fontsize=7, loc="lower right")
    else:
        no_data(ax, "no rupture event in any case (events.csv has no row)")
    ax.set_title(f"{sweep_title(sweep)}: every rupture event of every case", fontsize=10)
    return ax


# The panels of sweep_against: the event statistic (sweep_statistics.csv), its title, and why a
# panel without a value is empty.
SWEEP_PANELS = [
    ("precursor_count", "precursors before the first global slip", "no case reached a global slip"),
    ("first_precursor_force_ratio", "$F_S/F_N$ of the first precursor", "no case had a precursor"),
    ("global_slip_force_ratio", "$F_S/F_N$ at the first global slip", "no case reached a global slip"),
]


def sweep_against(sweep, key, axes=None):
    """The precursor count before the first global slip, the first precursor's F_S/F_N and F_S/F_N
    at the first global slip against the numeric varied `key` of the sweep (e.g.
    "loaders[1].theta"), on three Axes: each seed of a case a faint dot, their mean (square) with
    its 95 % interval (sweep_statistics.csv; no bar with fewer than two seeds), a series per value
    of the other varied keys (Li2020 Figs. 7, 8)."""
    cases = [r for r in campaign_rows(sweep, "sweep.csv") if r["status"] == "done"]
    statistics = (campaign_rows(sweep, "sweep_statistics.csv")
                  if os.path.exists(os.path.join(sweep, "sweep_statistics.csv")) else [])
    units = sweep_units(sweep)
    others = [k for k in varied_keys(sweep) if k != key]
    _, _, factor = key_display(key, units.get(key, ""))
    series = list(dict.fromkeys(tuple(r[k] for k in others) for r in cases))
    # Each run's statistics as the sweep computed them (run_statistics.csv), by run.
    per_run = {r["run"]: {s: number(r[s]) for s, _, _ in SWEEP_PANELS}
               for r in campaign_rows(sweep, "run_statistics.csv")}
    xs = sorted({x * factor for x in (number(r[key]) for r in cases) if np.isfinite(x)})
    axes = axes_of(axes, 1, 3, figsize=(13, 4))
    for ax, (statistic, title, why) in zip(axes, SWEEP_PANELS):
        for k, values in enumerate(series):
            colour = f"C{k % 10}"
            label = ", ".join(key_value_label(o, v, units.get(o, "")) for o, v in zip(others, values)) or None
            rows = [r for r in cases if tuple(r[o] for o in others) == values]
            for x in sorted({number(r[key]) for r in rows}):
                at = [r for r in rows if number(r[key]) == x]
                ys = [y for y in (per_run[r["run"]][statistic] for r in at) if np.isfinite(y)]
                if not ys:
                    continue
                ax.plot([x * factor] * len(ys), ys, "o", color=colour, alpha=0.3, ms=3)
                summary = next((s for s in statistics if s["statistic"] == statistic and number(s[key]) == x
                                and all(s.get(o) == v for o, v in zip(others, values))), None)
                mean = number(summary["mean"]) if summary else float(np.mean(ys))
                low, high = (number(summary["ci_low"]), number(summary["ci_high"])) if summary else (mean, mean)
                bar = [[mean - low], [high - mean]] if np.isfinite(low) and np.isfinite(high) else None
                ax.errorbar([x * factor], [mean], yerr=bar, fmt="s", color=colour, capsize=3, ms=5,
                            label=label if label not in ax.get_legend_handles_labels()[1] else None)
        ax.set_xlabel(key_axis_label(key, units.get(key, "")))
        ax.set_title(title, fontsize=10)
        if not ax.lines:
            no_data(ax, why)
            if xs:  # the other panels' x range, not matplotlib's 0 to 1
                pad = 0.05 * (xs[-1] - xs[0]) or 0.05 * abs(xs[0]) or 1.0
                ax.set_xlim(xs[0] - pad, xs[-1] + pad)
        elif len(series) > 1:
            ax.legend(fontsize=7)
    return axes


def sweep_loading_curves(sweep, ax=None):
    """Every case's F_S against time since its loading started, overlaid, coloured by case, a line
    style per seed."""
    cases = campaign_rows(sweep, "sweep.csv")
    varied, units = varied_keys(sweep), sweep_units(sweep)
    groups = list(dict.fromkeys(case_group(r, varied, units) for r in cases))
    seeds = list(dict.fromkeys(seed_of_row(r) for r in cases))
    ax = axes_of(ax, figsize=(7, 5))
    unknown = False  # a case whose loading start is unknown is drawn from its own start
    for r in cases:
        case = os.path.join(sweep, "cases", r["run"])
        curve = table(case, "loading_curve")
        if curve is None or "driving_force" not in curve.dtype.names:
            continue
        t0, since = time_origin(case)
        unknown = unknown or since != "loading started"
        loading = from_loading(curve["time"], t0)
        group = case_group(r, varied, units)
        seed = seed_of_row(r)
        label = group + (f", seed {seed}" if len(seeds) > 1 else "")
        ax.plot(curve["time"][loading] - t0, curve["driving_force"][loading], lw=0.8,
                color=f"C{groups.index(group) % 10}", linestyle=seed_style(seeds, seed)["linestyle"], label=label)
    ax.set_xlabel(overlaid_time_label(unknown))
    ax.set_ylabel("driving force $F_S$ [N]")
    if ax.lines:
        ax.legend(fontsize=8)
    else:
        no_data(ax, "no case has a loading_curve table:\nthe sweep's scene has no loading_curve observer")
    ax.set_title(f"{sweep_title(sweep)}: the loading curves of its cases", fontsize=10)
    return ax


def plot_sweep(sweep):
    """sweep_precursor_lengths, sweep_against_<key> for each numeric varied key and
    sweep_loading_curves, into the sweep directory's plots/ as PNG and SVG."""
    out = os.path.join(sweep, "plots")
    save(sweep_precursor_lengths(sweep).figure, out, "sweep_precursor_lengths")
    cases = campaign_rows(sweep, "sweep.csv")
    seeds = len({seed_of_row(r) for r in cases})
    for key in numeric_keys(sweep, cases):
        fig = sweep_against(sweep, key)[0].figure
        over = f"the mean over {seeds} seeds (square) with its 95 % interval, each seed (faint dot)" if seeds > 1 \
            else "each case (square)"
        fig.suptitle(f"{sweep_title(sweep)}: {over}")
        fig.tight_layout()
        save(fig, out, "sweep_against_" + key.split(".")[-1])
    save(sweep_loading_curves(sweep).figure, out, "sweep_loading_curves")


# The errors study.csv holds, in the order work_precision draws them, with their panel titles.
STUDY_ERRORS = [
    ("err_settled_normal_force", "settled normal force profile"),
    ("err_settled_friction_force", "settled friction force profile"),
    ("err_first_precursor_time_since_loading", "time of the first precursor"),
    ("err_first_precursor_force", "$F_S$ of the first precursor"),
    ("err_global_slip_force_ratio", "global $F_S/F_N$"),
    ("err_event_slip", "slip profile of the first event"),
    ("err_event_time", "start times of the events to the 2nd global slip"),
    ("err_event_force", "$F_S$ of the events to the 2nd global slip"),
    ("err_event_length", "$l/L$ of the events (absolute difference)"),
]


def over_seeds(cases):
    """One row per case of a study run over seeds: each error's largest over the seeds (NaN, a
    failed run's, wins), the median wall time."""
    merged = {}
    for r in cases:
        merged.setdefault(r["case"], []).append(r)
    out = []
    for runs in merged.values():
        row = dict(runs[0])
        row["wall_seconds"] = str(float(np.median([float(r["wall_seconds"]) for r in runs])))
        for column, _ in STUDY_ERRORS:
            row[column] = str(max(float(r[column]) for r in runs) if all(np.isfinite(float(r[column])) for r in runs)
                              else float("nan"))
        out.append(row)
    return out


def study_cases(study):
    """(the cases of the study directory `study` but its reference, as rows of study.csv, one per
    case (over_seeds) when it ran over several seeds; how many seeds)."""
    rows = campaign_rows(study, "study.csv")
    cases = [r for r in rows if r["case"] != "reference"]
    seeds = {r.get("seed") for r in rows} if "seeds:" in sidecar_text(study, "study.csv") else {None}
    return (over_seeds(cases) if len(seeds) > 1 else cases), len(seeds)


def work_precision(study, axes=None):
    """Each relative error of STUDY_ERRORS against wall time, log-log, one curve per family of cases,
    cheapest case first, on a 3 x 3 grid of Axes; over several seeds, each error's largest."""
    cases, _ = study_cases(study)
    families = list(dict.fromkeys(r["family"] for r in cases))
    axes = np.reshape(axes_of(axes, 3, 3, figsize=(13, 10.5)), (3, 3))
    for ax, (column, title) in zip(axes.flat, STUDY_ERRORS):
        for k, family in enumerate(families):
            points = sorted((float(r["wall_seconds"]), float(r[column]), r["case"]) for r in cases if r["family"] == family)
            points = [p for p in points if np.isfinite(p[1]) and p[1] > 0]  # a log axis has no 0 or NaN
            if points:
                ax.plot([p[0] for p in points], [p[1] for p in points], "o-", color=f"C{k}", label=family, ms=4)
        ax.set_xscale("log")
        ax.set_yscale("log")
        # Ticks at 1, 2, 5 of each decade, as plain numbers: cases often span less than a decade.
        ax.xaxis.set_major_locator(matplotlib.ticker.LogLocator(subs=(1.0, 2.0, 5.0)))
        ax.xaxis.set_major_formatter(matplotlib.ticker.FuncFormatter(lambda value, _: f"{value:g}"))
        ax.xaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())
        ax.set_title(title, fontsize=10)
        ax.grid(True, which="major", alpha=0.3)
    for ax in axes[-1]:
        ax.set_xlabel("wall time (s)")
    for ax in axes[:, 0]:
        ax.set_ylabel("relative error")
    return axes


def plot_study(study):
    """work_precision into the study directory as PNG and SVG, one legend of the families below,
    titled with the study's title (the first line of its study.md)."""
    axes = work_precision(study)
    fig = axes.flat[0].figure
    handles, labels = axes.flat[0].get_legend_handles_labels()
    for ax in axes.flat[1:]:
        for h, lab in zip(*ax.get_legend_handles_labels()):
            if lab not in labels:
                handles.append(h)
                labels.append(lab)
    fig.legend(handles, labels, loc="lower center", ncol=max(1, len(labels)), frameon=False)
    with open(os.path.join(study, "study.md")) as f:  # its first line is "# <the study's title>"
        title = f.readline().lstrip("# ").strip()
    seeds = study_cases(study)[1]
    over = f", the largest over {seeds} seeds" if seeds > 1 else ""
    fig.suptitle(f"{title}: relative error against the reference{over} (0 and NaN not drawn)")
    fig.tight_layout(rect=(0, 0.05, 1, 0.97))
    save(fig, study, "work_precision")
    if os.path.exists(os.path.join(study, "ensemble.csv")):
        fig = ensemble_work_precision(study)[0].figure
        fig.suptitle(f"{title}: each case's mean less the reference's over {len(study_seeds(study))} seeds, "
                     "with its 95 % bootstrap interval")
        fig.tight_layout(rect=(0, 0, 1, 0.96))
        save(fig, study, "ensemble_work_precision")
        fig = single_seed_divergence(study)[0].figure
        fig.suptitle(f"{title}: what one seed predicts, RK4 at dt against dt/2 (the half_step case)")
        fig.tight_layout(rect=(0, 0, 1, 0.94))
        save(fig, study, "single_seed_divergence")


def study_seeds(study):
    """The seeds of a study's first ensemble (its sidecar's `seeds`)."""
    return list(campaign_meta(study, "ensemble.csv").get("seeds") or campaign_meta(study, "study.csv").get("seeds")
                or [])


def ensemble_work_precision(study, axes=None):
    """For each event statistic of ensemble.csv, each case's ensemble error (its mean less the
    reference's, over the study's seeds) with its 95 % bootstrap interval against its CPU time per
    run, a colour per family; the dashed lines are ± the tolerance of the accuracy standard
    (max(2 se, the step-halving spread)); a panel says why it is empty. Axes: 2 x 5."""
    rows = [r for r in campaign_rows(study, "ensemble.csv") if r["ensemble"] == "1" and r["verdict"] != "reference"]
    statistics = list(dict.fromkeys(r["statistic"] for r in campaign_rows(study, "ensemble.csv")))
    families = list(dict.fromkeys(r["family"] for r in rows))
    axes = np.reshape(axes_of(axes, 2, 5, figsize=(18, 7)), (-1,))
    for ax, statistic in zip(axes, statistics):
        of = [r for r in rows if r["statistic"] == statistic]
        unit = of[0]["unit"] if of else ""
        for r in of:
            d, low, high = number(r["difference"]), number(r["difference_ci_low"]), number(r["difference_ci_high"])
            if not np.isfinite(d):
                continue
            bar = [[d - low], [high - d]] if np.isfinite(low) and np.isfinite(high) else None
            colour = f"C{families.index(r['family']) % 10}"
            marker = "x" if r["verdict"] == "fail" else "o"
            ax.errorbar([number(r["cpu_seconds"])], [d], yerr=bar, fmt=marker, color=colour, capsize=3, ms=5,
                        label=r["family"] if r["family"] not in ax.get_legend_handles_labels()[1] else None)
            ax.annotate(r["case"], (number(r["cpu_seconds"]), d), fontsize=6, xytext=(3, 3),
                        textcoords="offset points")
            tolerance = number(r["tolerance"])
            if np.isfinite(tolerance):
                ax.plot([number(r["cpu_seconds"])] * 2, [-tolerance, tolerance], "_", color=colour, ms=8, alpha=0.6)
        ax.set_title(statistic.replace("_", " "), fontsize=9)
        ax.set_ylabel(f"case − reference [{unit}]" if unit not in ("", "1") else "case − reference")
        if not ax.lines:
            no_data(ax, "no seed of the reference or of a case\nreached this event" if of else "only the reference")
        else:
            ax.axhline(0, color="0.6", lw=0.6)
            ax.set_xscale("log")
            ax.xaxis.set_major_formatter(matplotlib.ticker.FuncFormatter(lambda value, _: f"{value:g}"))
    for ax in axes[len(statistics):]:
        ax.set_visible(False)
    for ax in axes[-5:]:
        ax.set_xlabel("CPU time per run [s]")
    handles = {lab: h for ax in axes for h, lab in zip(*ax.get_legend_handles_labels())}
    if handles:
        axes[0].legend(handles.values(), handles.keys(), fontsize=7)
    return axes


def seed_runs(study, case):
    """{seed: run directory} of a study's case over its seeds (cases/<case>/seed_<n>)."""
    folder = os.path.join(study, "cases", case)
    runs = {}
    for name in sorted(os.listdir(folder)) if os.path.isdir(folder) else []:
        if name.startswith("seed_") and name[5:].isdigit():
            runs[int(name[5:])] = os.path.join(folder, name)
    return runs


def event_divergence(coarse, fine):
    """(ranks, |Δ t_start|, |Δ F_S/F_N|) of two runs' rupture events taken in order of their start,
    as far as both have events; None if either has no precursors table."""
    a, b = table(coarse, "precursors"), table(fine, "precursors")
    if a is None or b is None:
        return None
    a, b = np.sort(a, order="t_start"), np.sort(b, order="t_start")
    n = min(len(a), len(b))
    return (np.arange(1, n + 1), np.abs(a["t_start"][:n] - b["t_start"][:n]),
            np.abs(a["force_ratio"][:n] - b["force_ratio"][:n]))


def single_seed_divergence(study, axes=None):
    """Per seed of the study's first ensemble, how far RK4 at dt (the reference) and at dt/2 (the
    `half_step` case) of that one seed part: the difference of the k-th rupture event's start time
    and of its F_S/F_N against its rank k, a marker and line style per seed, on two Axes. A single
    seed predicts an event only as far as this stays small."""
    axes = axes_of(axes, 1, 2, figsize=(12, 4.5))
    reference, half = seed_runs(study, "reference"), seed_runs(study, "half_step")
    seeds = [s for s in (study_seeds(study) or sorted(reference)) if s in reference and s in half]
    for seed in seeds:
        drawn = event_divergence(reference[seed], half[seed])
        if drawn is None:
            continue
        ranks, times, ratios = drawn
        style = seed_style(seeds, seed)
        for ax, values in zip(axes, (times * 1e3, ratios)):
            ax.plot(ranks, values, color=f"C{seeds.index(seed) % 10}", alpha=0.8, ms=4, lw=0.8, label=f"seed {seed}",
                    **style)
    titles = ["start time of the k-th rupture event", "$F_S/F_N$ at the k-th event's start"]
    for ax, title, unit in zip(axes, titles, ("|Δt| [ms]", "|Δ($F_S/F_N$)|")):
        ax.set_title(title, fontsize=10)
        ax.set_xlabel("event rank k (by start time)")
        ax.set_ylabel(f"RK4 dt vs dt/2: {unit}")
        ax.xaxis.set_major_locator(matplotlib.ticker.MaxNLocator(integer=True))
        if ax.lines:
            ax.legend(fontsize=7)
        elif not half:
            no_data(ax, "the study has no half_step case (RK4 at half the reference's step)")
        else:
            no_data(ax, "no seed has rupture events in both the reference and the half_step case")
    return axes
