"""The figures of a campaign: a sweep's, from its sweep.csv and events.csv (Li2020 Figs. 7, 8), and an
accuracy study's work-precision plot, from its study.csv. Each function draws onto the Axes it is
given (a new figure of the command's size if None) and returns them; plot_sweep and plot_study write
them as `frictionlab plot SWEEP_DIR` and `frictionlab study` do."""
import os
import re

import matplotlib.ticker
import numpy as np

from ._clock import from_loading, overlaid_time_label, time_origin
from ._figure import axes_of, no_data, save
from ._tables import campaign_rows, number, sidecar_text, table

# The columns of sweep.csv that are not a varied key of the scene.
SWEEP_RESULTS = {"case", "status", "reason", "scene_hash", "global_static_coefficient", "events", "precursor_count",
                 "first_precursor_force_ratio", "steps", "wall_seconds", "cpu_seconds"}


def varied_keys(cases):
    """The scene's key paths a sweep varies but the seed, from the rows of its sweep.csv."""
    return [k for k in (cases[0].keys() if cases else []) if k not in SWEEP_RESULTS and k != "seed"]


def numeric_keys(cases):
    """The varied keys whose every value is a number (such as theta): each has its sweep_against."""
    return [k for k in varied_keys(cases) if all(np.isfinite(number(r[k])) for r in cases)]


def case_group(row, varied):
    """The case of a row of sweep.csv or events.csv apart from its seed, as a label."""
    return ", ".join(f"{k.split('.')[-1]}={row[k]}" for k in varied) or re.sub(r"_seed-[0-9]+$", "", row["case"])


def sweep_precursor_lengths(sweep, ax=None):
    """l/L against F_S/F_N of every rupture event of every case of the sweep directory `sweep`,
    coloured by case, seeds together (Li2020 Fig. 7)."""
    cases = campaign_rows(sweep, "sweep.csv")
    events = campaign_rows(sweep, "events.csv")
    varied = varied_keys(cases)
    groups = list(dict.fromkeys(case_group(r, varied) for r in cases))
    ax = axes_of(ax, figsize=(7, 5))
    for k, g in enumerate(groups):
        pts = [(number(e["force_ratio"]), number(e["extent_over_length"])) for e in events if case_group(e, varied) == g]
        if pts:
            ax.plot([p[0] for p in pts], [p[1] for p in pts], "o", color=f"C{k % 10}", label=g, ms=4, alpha=0.8)
    ax.set_xlabel("$F_S/F_N$ at the event's start")
    ax.set_ylabel("rupture length $l/L$")
    if ax.lines:
        ax.legend(fontsize=8)
    else:
        no_data(ax, "no rupture event in any case")
    ax.set_title("every rupture event of every case (Li2020 Fig. 7)")
    return ax


def sweep_against(sweep, key, axes=None):
    """The precursor count, the first precursor's F_S/F_N and F_S/F_N at global slip against the
    numeric varied `key` of the sweep (e.g. "loaders[1].theta"), on three Axes: every seed (dots),
    their mean (square) and spread (Li2020 Fig. 8)."""
    cases = campaign_rows(sweep, "sweep.csv")
    xs = sorted({number(r[key]) for r in cases})
    axes = axes_of(axes, 1, 3, figsize=(13, 4))
    for ax, (column, label) in zip(axes, [("precursor_count", "precursors before global slip"),
                                          ("first_precursor_force_ratio", "$F_S/F_N$ of the first precursor"),
                                          ("global_static_coefficient", "$F_S/F_N$ at global slip")]):
        for x in xs:
            ys = [number(r[column]) for r in cases if number(r[key]) == x and r["status"] == "done"]
            ys = [y for y in ys if np.isfinite(y)]
            if ys:
                ax.plot([x] * len(ys), ys, "o", color="0.6", ms=3)
                ax.errorbar([x], [np.mean(ys)], yerr=[[np.mean(ys) - min(ys)], [max(ys) - np.mean(ys)]],
                            fmt="s", color="tab:blue", capsize=3)
        ax.set_xlabel(key)
        ax.set_title(label, fontsize=10)
    return axes


def sweep_loading_curves(sweep, ax=None):
    """Every case's F_S against time since its loading started, overlaid, coloured by case."""
    cases = campaign_rows(sweep, "sweep.csv")
    varied = varied_keys(cases)
    groups = list(dict.fromkeys(case_group(r, varied) for r in cases))
    ax = axes_of(ax, figsize=(7, 5))
    unknown = False  # a case whose loading start is unknown is drawn from its own start
    for r in cases:
        case = os.path.join(sweep, "cases", r["case"])
        curve = table(case, "loading_curve")
        if curve is None or "driving_force" not in curve.dtype.names:
            continue
        t0, since = time_origin(case)
        unknown = unknown or since != "loading started"
        loading = from_loading(curve["time"], t0)
        group = case_group(r, varied)
        ax.plot(curve["time"][loading] - t0, curve["driving_force"][loading], lw=0.8,
                color=f"C{groups.index(group) % 10}",
                label=group if group not in ax.get_legend_handles_labels()[1] else None)
    ax.set_xlabel(overlaid_time_label(unknown))
    ax.set_ylabel("driving force $F_S$ (N)")
    if ax.lines:
        ax.legend(fontsize=8)
    else:
        no_data(ax, "no case has a loading_curve table")
    return ax


def plot_sweep(sweep):
    """sweep_precursor_lengths, sweep_against_<key> for each numeric varied key and
    sweep_loading_curves, into the sweep directory's plots/ as PNG and SVG."""
    out = os.path.join(sweep, "plots")
    save(sweep_precursor_lengths(sweep).figure, out, "sweep_precursor_lengths")
    for key in numeric_keys(campaign_rows(sweep, "sweep.csv")):
        fig = sweep_against(sweep, key)[0].figure
        fig.suptitle("mean (square), seeds (dots) and their spread (Li2020 Fig. 8)")
        fig.tight_layout()
        save(fig, out, "sweep_against_" + key.split(".")[-1])
    save(sweep_loading_curves(sweep).figure, out, "sweep_loading_curves")


# The errors study.csv holds, in the order work_precision draws them, with their panel titles.
STUDY_ERRORS = [
    ("err_settled_normal_force", "settled normal force profile"),
    ("err_settled_friction_force", "settled friction force profile"),
    ("err_first_precursor_time", "time of the first precursor"),
    ("err_first_precursor_force", "$F_S$ of the first precursor"),
    ("err_global_static_coefficient", "global $F_S/F_N$"),
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
