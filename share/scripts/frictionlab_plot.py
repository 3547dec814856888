#!/usr/bin/python3
"""Pictures of FrictionLab runs, in the style of Li et al. (2020) and of the experiments.

    frictionlab plot RUN_DIR [RUN_DIR ...] [-o OUT_DIR]

For each run directory, writes into RUN_DIR/plots/ (PNG and SVG) whichever figures its outputs allow:
  loading_curve   F_S against time with the precursors marked, their l/L below (Li2020 Fig. 6)
  four_phase_<i>  pinned fraction, state fractions, slip, velocity and forces of interface block i
                  around the first event that reaches it (Li2020 Fig. 9; Ben-David et al. 2010)
  spacetime       slip velocity and pinned fraction along the interface against time
  fronts          rupture-front position against time since nucleation, one curve per event, with
                  the lattice's shear and Rayleigh wave speeds c_S and c_R for reference
  energy          the energy balance: input, stored, kinetic, dissipated, residual
  lattice         the lattice around the first global slip (its VTU snapshot; the last snapshot in a
                  run without one), coloured by the nodes' x velocity, displacement magnified:
                  rendered by VTK offscreen (under a private Xvfb without an X display), so PNG only
and, over all the runs given (into -o, default the first run's plots/): precursor_lengths, l/L
against F_S/F_N (Li2020 Figs. 7, 8), and with several runs loading_curves, F_S/F_N overlaid.

Every time axis has one origin, when loading started: the start of the first stage in which a
driving loader (driving_spring, plate_springs) acts (every stage if it names none), or of the last
stage in a scene without one, from the stage durations the run's run.yaml records. Figures on an
event's own clock (four_phase: since detachment; fronts: since nucleation) say when the event came
after loading started. Every title names the scene: its title, F_N, theta, h, the friction law and
the seed, from run.yaml. A panel without data says so, and so does a figure of a run without the
event it draws.

    frictionlab plot SWEEP_DIR                 (a directory `frictionlab sweep` wrote)

draws into SWEEP_DIR/plots/ from its sweep.csv and events.csv: sweep_precursor_lengths (l/L against
F_S/F_N, coloured by case, seeds together: Li2020 Fig. 7), sweep_against_<key> for a numeric varied
key such as theta (precursor count, first-precursor and global-slip F_S/F_N, mean and seed spread:
Li2020 Fig. 8) and sweep_loading_curves (every case's F_S against time since loading, overlaid).

    frictionlab_plot.py --study STUDY_DIR      (run by `frictionlab study`)

draws work_precision (PNG and SVG) into STUDY_DIR from its study.csv: each error against wall time,
log-log, one curve per family of cases.
Each figure is a short function below: adapt them freely.
"""
import argparse
import contextlib
import csv
import ctypes
import ctypes.util
import glob
import os
import re
import select
import shutil
import signal
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ElementTree

import matplotlib

matplotlib.use("Agg")
matplotlib.rcParams["svg.fonttype"] = "none"  # the SVGs keep their text as text: searchable, editable
import matplotlib.font_manager  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import matplotlib.ticker  # noqa: E402
import numpy as np  # noqa: E402


def table(run, name):
    """A table of the run as a structured array (columns by name), or None if absent/empty.

    `name` is the CSV name (e.g. "precursors.csv"); the HDF5 table of the same stem (precursors.h5,
    written with `format: hdf5`) is read when the CSV is absent.
    """
    path = os.path.join(run, name)
    if os.path.exists(path):
        with open(path) as f:  # one header line, then the rows (provenance: NAME.csv.meta.yaml)
            lines = f.readlines()
        if len(lines) < 2:
            return None
        return np.atleast_1d(np.genfromtxt(lines, delimiter=",", names=True))
    h5 = os.path.splitext(path)[0] + ".h5"
    if not os.path.exists(h5):
        return None
    import h5py  # python3-h5py; only needed for HDF5 tables

    with h5py.File(h5, "r") as f:
        values = f["table"][:]
        columns = [c.decode() if isinstance(c, bytes) else str(c) for c in f["table"].attrs["columns"]]
    if values.shape[0] == 0:
        return None
    return np.rec.fromarrays(values.T, names=columns)


def scene_of(run):
    """The resolved scene the run recorded in run.yaml (a dict; empty if unreadable)."""
    try:
        import yaml
        with open(os.path.join(run, "run.yaml")) as f:
            return (yaml.safe_load(f) or {}).get("scene") or {}
    except Exception:  # noqa: BLE001 - a figure without its title is still a figure
        return {}


def component(scene, kind, type_name):
    for c in scene.get(kind) or []:
        if c.get("type") == type_name:
            return c
    return {}


def run_label(run, short=False):
    """'title: F_N = 400 N, θ = 0, h = 5 mm, three_state_junctions, seed 42' from run.yaml."""
    scene = scene_of(run)
    if not scene:
        return os.path.basename(os.path.abspath(run))
    facts = []
    normal, driving = component(scene, "loaders", "normal_load"), component(scene, "loaders", "driving_spring")
    if "total_force" in normal:
        facts.append(f"$F_N$ = {normal['total_force']:g} N")
    if "theta" in normal:
        facts.append(rf"$\theta$ = {normal['theta']:g}")
    if "height" in driving:
        facts.append(f"h = {driving['height'] * 1e3:g} mm")
    law = (scene.get("friction") or {}).get("type")
    if law:
        facts.append(law)
    facts.append(f"seed {scene.get('seed', 0)}")
    title = scene.get("title") or os.path.basename(os.path.abspath(run))
    return ", ".join(facts) if short else f"{title}\n" + ", ".join(facts)


def run_labels(runs):
    """Each run's short run_label, told apart where two collide: by the scene values that differ
    between them (key paths as --set writes them, at most three), else by the directory given."""
    labels = [run_label(run, short=True) for run in runs]
    values = [scene_values({k: v for k, v in scene_of(run).items() if k != "output"}) for run in runs]
    unique = list(labels)
    for i, label in enumerate(labels):
        alike = [j for j, other in enumerate(labels) if other == label]
        if len(alike) < 2:
            continue
        keys = sorted({k for j in alike for k in values[j]})
        differing = [k for k in keys if len({repr(values[j].get(k)) for j in alike}) > 1][:3]
        unique[i] += "".join(f", {k}={values[i].get(k)}" for k in differing)
    if len(set(unique)) < len(unique):  # the same scene twice: the directories tell them apart
        unique = [f"{label} ({run})" if unique.count(label) > 1 else label for label, run in zip(unique, runs)]
    return unique


def scene_values(node, path=""):
    """{key path: value} of a scene's mapping, key paths as --set writes them (loaders[2].velocity)."""
    if isinstance(node, dict):
        items = ((f"{path}.{k}" if path else str(k), v) for k, v in node.items())
    elif isinstance(node, list) and any(isinstance(v, (dict, list)) for v in node):
        items = ((f"{path}[{i}]", v) for i, v in enumerate(node))
    else:
        return {path: node}
    return {key: value for k, v in items for key, value in scene_values(v, k).items()}


def no_data(ax, what):
    """A panel with nothing to draw says so instead of staying empty."""
    ax.text(0.5, 0.5, what, transform=ax.transAxes, ha="center", va="center", color="0.4", fontsize=9)


def has_table(run, name):
    """Whether the run wrote the table `name` (CSV or HDF5), rows or not: an observer ran."""
    return any(os.path.exists(os.path.join(run, os.path.splitext(name)[0] + ext)) for ext in (".csv", ".h5"))


DRIVING_LOADERS = ("driving_spring", "plate_springs")  # the loaders that pull the slider


def loading_stage(scene):
    """Index of the stage loading starts in: the first in which a driving loader acts (its `stages`,
    or every stage if it names none); the last stage in a scene without one. None without stages."""
    names = [stage.get("name") for stage in scene.get("stages") or []]
    if not names:
        return None
    acting = [names.index(name) for loader in scene.get("loaders") or [] if loader.get("type") in DRIVING_LOADERS
              for name in (loader.get("stages") or names) if name in names]
    return min(acting) if acting else len(names) - 1


def loading_start(run):
    """When loading started, in the run's simulated time: the stage durations before the loading
    stage (loading_stage) summed, as run.yaml records them; None if it records no stages."""
    scene = scene_of(run)
    stage = loading_stage(scene)
    if stage is None:
        return None
    try:  # PyYAML (YAML 1.1) reads 3e-3 as a string: float() takes it
        return float(sum(float(s["duration"]) for s in scene["stages"][:stage]))
    except (KeyError, TypeError, ValueError):
        return None


def time_origin(run):
    """(t0, what t0 is) for the run's time axes: when loading started, or, said so, the run's start
    where run.yaml does not tell when loading started."""
    t0 = loading_start(run)
    if t0 is None:
        return 0.0, "the run started (when loading started is unknown: run.yaml records no stages)"
    return t0, "loading started"


def from_loading(times, t0):
    """Which rows are at or after t0: a row's time is a sum of steps, so within round-off of a stage's
    start; half an observation interval's grace takes the row observed at the start."""
    grace = 0.5 * float(np.median(np.diff(times))) if len(times) > 1 else 0.0
    return times >= t0 - grace


def overlaid_time_label(unknown):
    """The time axis of curves of several runs, each from its own time_origin; `unknown`: some run
    does not tell when its loading started."""
    return "time since loading started (s" + ("; from the run's start where run.yaml records no stages"
                                              if unknown else "") + ")"


def no_events_note(run):
    """What a figure of rupture events says when it has none to draw."""
    if has_table(run, "precursors.csv"):
        return "no rupture event in this run (the precursors observer recorded none)"
    return "no rupture events recorded (no precursors observer)"


def save(fig, out_dir, name):
    os.makedirs(out_dir, exist_ok=True)
    for ext in ("png", "svg"):
        fig.savefig(os.path.join(out_dir, f"{name}.{ext}"), dpi=150, bbox_inches="tight")
    plt.close(fig)
    print(os.path.join(out_dir, name + ".png"))


def loading_curve(run, out_dir):
    curve, events = table(run, "loading_curve.csv"), table(run, "precursors.csv")
    if curve is None or "driving_force" not in curve.dtype.names:
        return
    t0, since = time_origin(run)
    loading = from_loading(curve["time"], t0)
    fig, (top, bottom) = plt.subplots(2, 1, sharex=True, figsize=(7, 5), gridspec_kw={"height_ratios": [3, 1]})
    top.plot(curve["time"][loading] - t0, curve["driving_force"][loading], color="tab:red", lw=1)
    top.set_ylabel("driving force $F_S$ (N)")
    if events is not None:
        events = np.atleast_1d(events)
        t = events["t_start"] - t0
        glob_ = events["global"] > 0.5
        top.plot(t[~glob_], events["driving_force"][~glob_], "v", color="tab:blue", ms=5, label="precursor")
        top.plot(t[glob_], events["driving_force"][glob_], "o", mfc="none", color="k", ms=6, label="global slip")
        top.legend(loc="lower right", frameon=False)
        bottom.vlines(t, 0, events["extent_over_length"], color="tab:blue")
        bottom.plot(t, events["extent_over_length"], ".", color="tab:blue")
    else:
        no_data(bottom, no_events_note(run))
    bottom.set_ylim(0, 1.05)
    bottom.set_ylabel("$l/L$")
    bottom.set_xlabel(f"time since {since} (s)")
    top.set_title(run_label(run), fontsize=9)
    save(fig, out_dir, "loading_curve")


def precursor_lengths(runs, out_dir):
    fig, ax = plt.subplots(figsize=(5, 4))
    plotted = False
    for run in runs:
        events = table(run, "precursors.csv")
        if events is None:
            continue
        events = np.atleast_1d(events)
        ax.plot(events["force_ratio"], events["extent_over_length"], "o-", ms=4, lw=0.8,
                label=run_label(run, short=len(runs) > 1))
        plotted = True
    if plotted:
        ax.legend(frameon=False, fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1))
    else:
        no_data(ax, "no rupture events in " + ("these runs" if len(runs) > 1 else "this run"))
    ax.set_xlabel("$F_S/F_N$ at nucleation")
    ax.set_ylabel("$l/L$")
    ax.set_ylim(0, 1.05)
    if len(runs) == 1:
        ax.set_title(run_label(runs[0]), fontsize=8)
    save(fig, out_dir, "precursor_lengths")


def loading_curves(runs, out_dir):
    """F_S/F_N against time since loading started, every run overlaid, each labelled apart."""
    fig, ax = plt.subplots(figsize=(7, 4))
    unknown = False  # a run whose loading start is unknown is drawn from its own start
    for run, label in zip(runs, run_labels(runs)):
        curve = table(run, "loading_curve.csv")
        if curve is None or "driving_force_over_normal_load" not in curve.dtype.names:
            continue
        t0, since = time_origin(run)
        known = since == "loading started"
        unknown = unknown or not known
        loading = from_loading(curve["time"], t0)
        ax.plot(curve["time"][loading] - t0, curve["driving_force_over_normal_load"][loading], lw=1,
                label=label + ("" if known else " (from the run's start)"))
    if ax.lines:
        ax.legend(frameon=False, fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1))
    else:
        no_data(ax, "no loading curve with F_S/F_N in these runs")
    ax.set_xlabel(overlaid_time_label(unknown))
    ax.set_ylabel("$F_S/F_N$")
    titles = {scene_of(run).get("title") or "" for run in runs}
    scene = f"{titles.pop()}: " if len(titles) == 1 and "" not in titles else ""
    ax.set_title(f"{scene}the loading curves of {len(runs)} runs", fontsize=9)
    save(fig, out_dir, "loading_curves")


def phase_boundaries(t, d):
    """Start of phase I and the ends of phases I-III of one rupture of an interface block (Li2020
    Fig. 9), times as t:
    I detachment: from when a tenth of the pinned junctions let go, until the block is fastest;
    II fast slip: sliding junctions dominate, until dislocated ones outnumber them;
    III slow slip: dislocated junctions dominate while the block creeps, until pinned ones again
    outnumber the dislocated; IV rejuvenation: junctions re-pin, the block is stuck.
    None for a boundary the data do not reach."""
    peak = int(np.argmax(np.abs(d["velocity"])))
    letting_go = np.flatnonzero(d["pinned_fraction"][: peak + 1] < 0.9 * d["pinned_fraction"][0])
    after = np.arange(len(t)) > peak
    dislocated = np.flatnonzero(after & (d["dislocated_fraction"] > d["sliding_fraction"]))
    ends = [t[letting_go[0]] if letting_go.size else t[0], t[peak], None, None]
    if dislocated.size:
        ends[2] = t[dislocated[0]]
        repinned = np.flatnonzero((np.arange(len(t)) > dislocated[0]) & (d["pinned_fraction"] > d["dislocated_fraction"]))
        if repinned.size:
            ends[3] = t[repinned[0]]
    return ends


def four_phase(run, out_dir):
    paths = glob.glob(os.path.join(run, "contact_area_block_*.csv")) + glob.glob(os.path.join(run, "contact_area_block_*.h5"))
    t0, since = time_origin(run)
    for stem in sorted({os.path.splitext(os.path.basename(p))[0] for p in paths}):
        block = stem[len("contact_area_block_"):]
        d = table(run, stem + ".csv")
        if d is None:
            continue
        title = (f"interface block {int(block) + 1} of the paper (index {block}): the four phases of one rupture\n"
                 + run_label(run))
        detached = np.flatnonzero(from_loading(d["time"], t0) & (d["pinned_fraction"] < 0.5))
        if detached.size == 0:
            fig, ax = plt.subplots(figsize=(7.5, 3))
            no_data(ax, "no rupture event reached this block in this run:\n"
                        "its pinned fraction never fell below 0.5 after loading started")
            ax.set_xticks([])
            ax.set_yticks([])
            ax.set_title(title, fontsize=9)
            save(fig, out_dir, f"four_phase_{block}")
            continue
        t_det = d["time"][detached[0]]
        window = (d["time"] > t_det - 5e-4) & (d["time"] < t_det + 4e-3)
        w = d[window]
        t = (w["time"] - t_det) * 1e3
        fig, axes = plt.subplots(4, 1, sharex=True, figsize=(7.5, 8.5))
        axes[0].plot(t, w["normalised_pinned"], "k", label=r"$\tilde N_p$")
        for name, color in (("pinned", "tab:green"), ("sliding", "tab:red"), ("dislocated", "tab:blue")):
            axes[0].plot(t, w[name + "_fraction"], color=color, lw=1, label=name)
        axes[0].set_ylabel("fraction")
        slip = w["slip"]
        axes[1].plot(t, (slip - slip[0]) * 1e6, "k")
        axes[1].set_ylabel(r"slip $\Delta$ ($\mu$m)")
        # Log axis: the slow slip of phase III (um/s) is invisible next to the fast slip (m/s).
        speed = np.abs(w["velocity"])
        axes[2].semilogy(t, np.maximum(speed, 1e-7), "k")
        axes[2].set_ylim(1e-7, None)
        axes[2].set_ylabel("|velocity| (m/s, log)")
        for name, label in (("friction_force", "$f_i$"), ("bond_force_left", "left bond"), ("bond_force_right", "right bond")):
            axes[3].plot(t, w[name], lw=1, label=label)
        axes[3].set_ylabel("force (N)")
        axes[3].set_xlabel(f"time since detachment (ms); detachment at {(t_det - t0) * 1e3:.2f} ms after {since}")
        for ax in (axes[0], axes[3]):  # beside the axes, never over the curves
            ax.legend(frameon=False, fontsize=8, loc="upper left", bbox_to_anchor=(1.01, 1))
        bounds = phase_boundaries(t, w)
        starts = bounds
        stops = bounds[1:] + [t[-1]]
        for k, (a, b) in enumerate(zip(starts, stops)):
            if a is None or b is None:
                continue
            for ax in axes:
                if k % 2 == 0:
                    ax.axvspan(a, b, color="0.93", zorder=0)
            axes[0].text(0.5 * (a + b), 1.02, ["I", "II", "III", "IV"][k], transform=axes[0].get_xaxis_transform(),
                         ha="center", va="bottom", fontsize=10, fontweight="bold")
        axes[0].set_title(title, fontsize=9, pad=16)
        save(fig, out_dir, f"four_phase_{block}")


def spacetime(run, out_dir):
    velocity, pinned = table(run, "interface_velocity.csv"), table(run, "interface_pinned_fraction.csv")
    if velocity is None:
        return
    panels = [(velocity, "log$_{10}$ |slip velocity| (m/s)", lambda v: np.log10(np.abs(v) + 1e-9), "magma")]
    if pinned is not None:
        panels.append((pinned, "pinned fraction", lambda v: v, "viridis"))
    t0, since = time_origin(run)  # one time origin with the loading curve
    fig, axes = plt.subplots(len(panels), 1, sharex=True, figsize=(7, 3 * len(panels)), squeeze=False)
    for ax, (data, label, transform, cmap) in zip(axes[:, 0], panels):
        blocks = [n for n in data.dtype.names if n.startswith("block_")]
        values = np.column_stack([data[b] for b in blocks])
        image = ax.imshow(transform(values).T, aspect="auto", origin="lower", cmap=cmap, interpolation="nearest",
                          extent=[data["time"][0] - t0, data["time"][-1] - t0, -0.5, len(blocks) - 0.5])
        fig.colorbar(image, ax=ax, label=label)
        ax.set_ylabel("interface block (trailing edge = 0)")
    axes[0, 0].set_title(run_label(run), fontsize=9)
    axes[-1, 0].set_xlabel(f"time since {since} (s; negative: settling)")
    save(fig, out_dir, "spacetime")


def wave_speeds(scene):
    """Long-wave shear and Rayleigh speeds of a spring_lattice_2d (theory.md §1: C44 = 3E/8,
    C11 = 3 C44; the lattice's density puts M/N on every node), or None for another bulk."""
    bulk = scene.get("bulk") or {}
    if bulk.get("type") != "spring_lattice_2d":
        return None
    try:  # PyYAML (YAML 1.1) reads 3e+09 as a string: float() takes it
        length, width, mass, modulus = (float(bulk[k]) for k in ("length", "width", "mass", "youngs_modulus"))
        spacing = length / (int(bulk["nx"]) - 1)
        density = mass / (int(bulk["nx"]) * int(bulk["nz"]) * spacing ** 2 * width)
        c_s = np.sqrt(0.375 * modulus / density)
    except (KeyError, TypeError, ValueError, ZeroDivisionError):
        return None
    # Rayleigh: (2 - x^2)^2 = 4 sqrt(1 - x^2) sqrt(1 - x^2 c_S^2/c_L^2), x = c_R/c_S, c_L^2 = 3 c_S^2.
    lo, hi = 0.5, 0.999
    for _ in range(60):
        x = 0.5 * (lo + hi)
        f = (2 - x * x) ** 2 - 4 * np.sqrt(1 - x * x) * np.sqrt(1 - x * x / 3)
        lo, hi = (lo, x) if f > 0 else (x, hi)  # R < 0 below the root, > 0 above
    return c_s, c_s * 0.5 * (lo + hi)


def fronts(run, out_dir):
    """Rupture-front position against time for every event (Rubinstein et al. 2004 style), with the
    lattice's wave speeds for reference, events or not."""
    if not has_table(run, "precursors.csv"):
        return  # no precursors observer: no events to draw, nor their absence
    f, events = table(run, "precursor_fronts.csv"), table(run, "precursors.csv")
    t0, since = time_origin(run)
    fig, ax = plt.subplots(figsize=(7, 4.5))
    cmap = plt.get_cmap("viridis")
    ids = np.unique(f["event"]) if f is not None and events is not None else np.array([])
    for k, event in enumerate(ids):
        rows = f[f["event"] == event]
        rows = rows[np.lexsort((rows["distance"], rows["delay"]))]  # in time order, nearest first at ties
        is_global = events["global"][events["event"] == event].max() > 0.5
        nucleation = (events["t_start"][events["event"] == event].min() - t0) * 1e3
        # Points only: two fronts of one event (from both sides) joined by a line would zig-zag.
        ax.plot(rows["delay"] * 1e3, rows["x"] * 1e3, "." if is_global else "o", ms=4 if is_global else 3,
                color=cmap(k / max(len(ids) - 1, 1)),
                label=f"event {int(event)}" + (" (global)" if is_global else "") + f" at {nucleation:.2f} ms")
    if not ids.size:
        no_data(ax, no_events_note(run))
    speeds, global_ids = wave_speeds(scene_of(run)), np.array([])
    if events is not None:
        global_ids = events["event"][events["global"] > 0.5]
    if speeds and f is not None and global_ids.size:
        # Through the first global slip's arrival at its farthest block: a crossing at c_S or c_R
        # would run parallel to these.
        rows = f[f["event"] == global_ids[0]]
        last = rows[np.argmax(rows["delay"])]
        x0, t_far, x_far = float(np.min(rows["x"])), float(last["delay"]), float(last["x"])
        if x_far < x0 + 1e-12:  # a front running towards the trailing edge
            x0 = float(np.max(rows["x"]))
    elif speeds:
        # No global slip: a front from the trailing edge (where the driving spring nucleates them)
        # to the leading edge at each speed.
        x0, x_far = 0.0, float(scene_of(run)["bulk"]["length"])
        t_far = x_far / speeds[1]
    if speeds:
        for c, name, style in ((speeds[0], "$c_S$", "--"), (speeds[1], "$c_R$", ":")):
            t_start = t_far - abs(x_far - x0) / c
            ax.plot([t_start * 1e3, t_far * 1e3], [x0 * 1e3, x_far * 1e3], style, color="0.2", lw=1.2,
                    label=f"{name} = {c:.0f} m/s (lattice)")
    ax.set_xlabel(f"time since each event's nucleation (ms); legend: nucleation, ms after {since}")
    ax.set_ylabel("front position x (mm)")
    ax.set_title(run_label(run), fontsize=9)
    if ax.lines:
        ax.legend(frameon=False, fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1))
    save(fig, out_dir, "fronts")


def energy(run, out_dir):
    e = table(run, "energy.csv")
    if e is None:
        return
    t0, since = time_origin(run)
    t = e["time"] - t0
    fig, (top, bottom) = plt.subplots(2, 1, sharex=True, figsize=(7, 6), gridspec_kw={"height_ratios": [3, 1]})
    top.set_title(run_label(run), fontsize=9)
    for name in ("input", "stored_energy", "kinetic_energy", "dissipated_damping", "dissipated_friction"):
        if name in e.dtype.names:
            top.plot(t, e[name], label=name.replace("_", " "))
    top.set_ylabel("energy (J)")
    top.legend(frameon=False, fontsize=8)
    bottom.plot(t, e["residual"], "k", lw=1)
    bottom.set_ylabel("balance residual (J)")
    bottom.set_xlabel(f"time since {since} (s; negative: settling)")
    save(fig, out_dir, "energy")


class RenderUnavailable(Exception):
    """VTK cannot render here; the message says why and what to install."""


def display_answers(name):
    """True if the X display `name` accepts a connection and offers GLX, as VTK's X render window
    needs: asked through Xlib first, since VTK aborts the whole process on a display it cannot open."""
    try:
        xlib = ctypes.CDLL(ctypes.util.find_library("X11") or "libX11.so.6")
    except OSError:
        return False
    xlib.XOpenDisplay.restype = ctypes.c_void_p
    xlib.XOpenDisplay.argtypes = [ctypes.c_char_p]
    xlib.XQueryExtension.argtypes = [ctypes.c_void_p, ctypes.c_char_p] + [ctypes.POINTER(ctypes.c_int)] * 3
    xlib.XCloseDisplay.argtypes = [ctypes.c_void_p]
    display = xlib.XOpenDisplay(name.encode())
    if not display:
        return False
    codes = [ctypes.c_int() for _ in range(3)]
    glx = xlib.XQueryExtension(display, b"GLX", *(ctypes.byref(c) for c in codes))
    xlib.XCloseDisplay(display)
    return bool(glx)


def stop_with_parent():
    """In a child before it starts: SIGTERM for it when this process ends, even killed (Linux's
    PR_SET_PDEATHSIG), so that no Xvfb outlives a plot stopped by a batch system."""
    ctypes.CDLL(None, use_errno=True).prctl(1, signal.SIGTERM)


@contextlib.contextmanager
def x_display():
    """An X display for the block: $DISPLAY if it answers, else a private Xvfb (Debian's VTK renders
    only through an X server, which batch nodes and CI lack), always stopped afterwards."""
    if os.environ.get("DISPLAY") and display_answers(os.environ["DISPLAY"]):
        yield
        return
    if not shutil.which("Xvfb"):
        raise RenderUnavailable("no X display, and no Xvfb to start one (Debian: xvfb)")
    # -displayfd: Xvfb takes a free display number itself (no collision with another run) and writes
    # it to the pipe once it accepts clients. -noreset: by default an X server resets when its last
    # client disconnects, and refuses connections meanwhile; VTK's SupportsOpenGL() connects and
    # disconnects just before the render connects again, which then failed at random (and VTK aborts).
    ready, number_fd = os.pipe()
    with tempfile.TemporaryFile() as log:
        server = subprocess.Popen(["Xvfb", "-displayfd", str(number_fd), "-screen", "0", "1600x1200x24",
                                   "-nolisten", "tcp", "-noreset"], pass_fds=(number_fd,), stdout=log, stderr=log,
                                  preexec_fn=stop_with_parent)
        os.close(number_fd)
        saved = os.environ.get("DISPLAY")
        try:
            with os.fdopen(ready) as f:  # Xvfb closes it, unwritten, if it fails
                number = f.readline().strip() if select.select([f], [], [], 30)[0] else ""
            if not number:
                log.seek(0)
                last = (log.read().decode(errors="replace").strip().splitlines() or ["no message"])[-1]
                raise RenderUnavailable(f"Xvfb did not start ({last})")
            os.environ["DISPLAY"] = ":" + number
            yield
        finally:
            if saved is None:
                os.environ.pop("DISPLAY", None)
            else:
                os.environ["DISPLAY"] = saved
            server.terminate()
            server.wait()


def lattice_snapshot(run):
    """(path, time, global slip's start) of the first VTU snapshot at or after the first global slip
    started, or (path, time, None) of the last one in a run without a global slip (or whose series
    ends before it); None without a lattice series."""
    pvd = os.path.join(run, "lattice.pvd")
    if not os.path.exists(pvd):
        return None
    snapshots = [(float(d.get("timestep")), d.get("file")) for d in ElementTree.parse(pvd).getroot().iter("DataSet")]
    if not snapshots:
        return None
    events = table(run, "precursors.csv")
    if events is not None and (events["global"] > 0.5).any():
        t_global = events["t_start"][events["global"] > 0.5][0]
        later = [s for s in snapshots if s[0] >= t_global]
        if later:
            return os.path.join(run, later[0][1]), later[0][0], t_global
    return os.path.join(run, snapshots[-1][1]), snapshots[-1][0], None


def lattice_title(run, snapshot, mean_slip, magnify):
    """What the lattice figure shows: the run, which snapshot and when, and how it is deformed."""
    t0, since = time_origin(run)
    _, t, t_global = snapshot
    if t_global is not None:
        which = f"the first snapshot after the first global slip started ({(t_global - t0) * 1e3:.3f} ms)"
    elif has_table(run, "precursors.csv"):
        which = "the last snapshot (no global slip in this run before it)"
    else:
        which = "the last snapshot (no precursors observer to find a global slip)"
    return (f"{run_label(run)}\nlattice at {(t - t0) * 1e3:.3f} ms after {since}: {which}\n"
            f"deformation (displacement less its mean {mean_slip * 1e6:.1f} µm in x) ×{magnify:g}")


def velocity_unit(largest):
    """(name, m/s in one) of the unit in which the `largest` |velocity| reads at least 1, so that the
    colour bar's labels stay short (120 µm/s, not 0.00012 m/s)."""
    for name, size in (("m/s", 1.0), ("mm/s", 1e-3), ("µm/s", 1e-6)):
        if largest >= size:
            return name, size
    return "nm/s", 1e-9


def lattice(run, out_dir, magnify=200.0):
    """The lattice around the first global slip (lattice_snapshot): its VTU snapshot (points at
    their reference positions) warped by the displacement less its mean, magnified, coloured by the
    nodes' x velocity. Rendered by VTK offscreen, PNG only (a render is a raster); drawn with
    matplotlib where VTK cannot render."""
    snapshot = lattice_snapshot(run)
    if snapshot is None:
        return
    try:
        import vtk
        from vtk.util.numpy_support import numpy_to_vtk, vtk_to_numpy
    except ImportError:
        print("frictionlab plot: no VTK for Python (Debian: python3-vtk9); lattice figure skipped", file=sys.stderr)
        return
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(snapshot[0])
    reader.Update()
    grid = reader.GetOutput()
    data = grid.GetPointData()
    if grid.GetNumberOfCells() == 0 or data.GetArray("displacement") is None or data.GetArray("velocity") is None:
        return
    displacement = vtk_to_numpy(data.GetArray("displacement"))
    # The slider's rigid slip would hide its deformation: magnify the displacement less its mean.
    mean = displacement.mean(axis=0)
    deformation = numpy_to_vtk(displacement - mean, deep=True)
    deformation.SetName("deformation")
    data.AddArray(deformation)
    # Every node's x velocity (the slip velocity only on the interface row), in a unit that keeps the
    # colour bar's labels short.
    vx = vtk_to_numpy(data.GetArray("velocity"))[:, 0]
    unit, size = velocity_unit(float(np.abs(vx).max()))
    shown = numpy_to_vtk(vx / size, deep=True)
    shown.SetName("x_velocity")
    data.AddArray(shown)
    title = lattice_title(run, snapshot, mean[0], magnify)
    colour = f"x velocity vₓ ({unit})"
    try:
        with x_display():
            render_lattice(grid, title, colour, magnify, out_dir)
    except RenderUnavailable as why:
        print(f"frictionlab plot: VTK cannot render the lattice: {why}; drawn with matplotlib instead", file=sys.stderr)
        draw_lattice(grid, title, colour, magnify, out_dir)


def round_ticks(lo, hi):
    """matplotlib's round tick values between lo and hi, and a printf format showing them alike."""
    slack = 1e-9 * (hi - lo)
    ticks = [t for t in matplotlib.ticker.MaxNLocator(nbins=5).tick_values(lo, hi) if lo - slack <= t <= hi + slack]
    step = ticks[1] - ticks[0] if len(ticks) > 1 else abs(lo) or 1.0
    decimals = max(0, -int(np.floor(np.log10(step))))
    if abs(step * 10 ** decimals - round(step * 10 ** decimals)) > 1e-6:  # a step of 2.5 or 0.25
        decimals += 1
    return ticks, f"%.{decimals}f"


def vtk_text(string, position, size, world=False, **settings):
    """A VTK text actor in the other figures' font at `position` (display pixels, or world
    coordinates); `settings` name vtkTextProperty setters, e.g. Justification=1."""
    import vtk

    actor = vtk.vtkTextActor()
    actor.SetInput(string)
    prop = actor.GetTextProperty()
    prop.SetFontFamily(vtk.VTK_FONT_FILE)
    prop.SetFontFile(matplotlib.font_manager.findfont("DejaVu Sans"))
    prop.SetFontSize(size)
    prop.SetColor(0, 0, 0)
    for key, value in settings.items():
        getattr(prop, "Set" + key)(value)
    if world:
        actor.GetPositionCoordinate().SetCoordinateSystemToWorld()
    actor.GetPositionCoordinate().SetValue(*position)
    return actor


def lattice_axes(reference, frame, px, size):
    """x and z axes in mm as actors in the lattice's plane, `px` metres a pixel: a little off the
    `frame` (x0, x1, z0, z1) round the lattice, spanning round values of its reference extent (the
    deformation is magnified, the size is not). Lines and texts, not vtkAxisActor2D, which places
    every label by the widest one, off its tick."""
    import vtk

    points, segments, actors = vtk.vtkPoints(), vtk.vtkCellArray(), []
    for name, (lo, hi), base in (("x", reference[0:2], frame[2] - 14 * px), ("z", reference[2:4], frame[0] - 14 * px)):
        ticks, number = round_ticks(lo * 1e3, hi * 1e3)
        labels = [number % t for t in ticks]
        ticks = [t / 1e3 for t in ticks]

        def at(along, across):  # a point of the plane by its place along and across the axis
            return (along, across, 0) if name == "x" else (across, along, 0)

        ends = [(at(ticks[0], base), at(ticks[-1], base))] + [(at(t, base), at(t, base - 10 * px)) for t in ticks]
        for a, b in ends:
            segments.InsertNextCell(2, [points.InsertNextPoint(a), points.InsertNextPoint(b)])
        # Labels centred below the x ticks, and left of the z ticks, ending there.
        placement = dict(Justification=1, VerticalJustification=2) if name == "x" else \
            dict(Justification=2, VerticalJustification=1)
        for t, label in zip(ticks, labels):
            actors.append(vtk_text(label, at(t, base - 15 * px), size, world=True, **placement))
        # The axis title clears the labels: below them for x, left of the widest for z (turned).
        clearance = 2.4 * size if name == "x" else 16 + 0.62 * size * max(map(len, labels)) + 0.8 * size
        actors.append(vtk_text(f"{name} (mm)", at(0.5 * (ticks[0] + ticks[-1]), base - clearance * px), size,
                               world=True, Justification=1, VerticalJustification=1,
                               Orientation=0 if name == "x" else 90))
    lines = vtk.vtkPolyData()
    lines.SetPoints(points)
    lines.SetLines(segments)
    mapper = vtk.vtkPolyDataMapper()
    mapper.SetInputData(lines)
    actors.append(vtk.vtkActor())
    actors[-1].SetMapper(mapper)
    actors[-1].GetProperty().SetColor(0, 0, 0)
    actors[-1].GetProperty().SetLineWidth(2)
    return actors


def render_lattice(grid, title, colour, magnify, out_dir):
    """lattice.png rendered by VTK offscreen: the lattice warped by its 'deformation' array, coloured
    by its 'x_velocity' array, axes, a colour bar titled `colour`; the PNG says so in its Software
    text."""
    import vtk

    warp = vtk.vtkWarpVector()
    warp.SetInputData(grid)
    warp.SetInputArrayToProcess(0, 0, 0, vtk.vtkDataObject.FIELD_ASSOCIATION_POINTS, "deformation")
    warp.SetScaleFactor(magnify)
    warp.Update()
    # The x velocity rather than the shear/normal ratio: the ratio lives on the interface row only,
    # while a slip sets the whole slider above it moving, so the velocity shows in every cell which
    # part has slipped and which is still stuck.
    lut = vtk.vtkLookupTable()
    lut.SetNumberOfTableValues(256)
    for k, rgba in enumerate(plt.get_cmap("magma")(np.linspace(0, 1, 256))):  # as the spacetime figure
        lut.SetTableValue(k, *rgba)
    lut.SetRange(grid.GetPointData().GetArray("x_velocity").GetRange())
    mapper = vtk.vtkDataSetMapper()
    mapper.SetInputConnection(warp.GetOutputPort())
    mapper.SetScalarModeToUsePointFieldData()
    mapper.SelectColorArray("x_velocity")
    mapper.SetLookupTable(lut)
    mapper.UseLookupTableScalarRangeOn()
    mapper.InterpolateScalarsBeforeMappingOn()
    cells = vtk.vtkActor()
    cells.SetMapper(mapper)
    cells.GetProperty().LightingOff()  # colours exactly as on the colour bar
    cells.GetProperty().EdgeVisibilityOn()
    cells.GetProperty().SetEdgeColor(0.5, 0.5, 0.5)

    # Pixels: the lattice as large as fits a 1600 x 1200 window (the Xvfb screen) beside the z axis
    # (left), the colour bar (right), the title (top) and the x axis (bottom); the window at least
    # 1400 wide, for the title.
    size = 28  # of the labels' font
    left, right, bottom = 130, 270, 125
    top = 55 + round(1.3 * size * (title.count("\n") + 1))
    # The frame holds the deformed lattice and the axes, which span its reference extent.
    reference, deformed = grid.GetBounds(), warp.GetOutput().GetBounds()
    x0, x1, z0, z1 = ((min if k % 2 == 0 else max)(reference[k], deformed[k]) for k in range(4))
    scale = min((1600 - left - right) / (x1 - x0), (1200 - top - bottom) / (z1 - z0))  # pixels a metre
    pad = max(0, 1400 - left - right - scale * (x1 - x0)) / 2
    left, right = left + pad, right + pad
    width, height = round(left + right + scale * (x1 - x0)), round(top + bottom + scale * (z1 - z0))

    renderer = vtk.vtkRenderer()
    renderer.SetBackground(1, 1, 1)
    renderer.AddActor(cells)
    for actor in lattice_axes(reference, (x0, x1, z0, z1), 1 / scale, size):
        renderer.AddActor(actor)
    camera = renderer.GetActiveCamera()
    camera.ParallelProjectionOn()
    camera.SetParallelScale(height / (2 * scale))
    centre = (0.5 * (x0 + x1) - (left + 0.5 * scale * (x1 - x0) - 0.5 * width) / scale,
              0.5 * (z0 + z1) - (bottom + 0.5 * scale * (z1 - z0) - 0.5 * height) / scale)
    camera.SetFocalPoint(*centre, 0)
    camera.SetPosition(*centre, 1)
    camera.SetViewUp(0, 1, 0)
    renderer.ResetCameraClippingRange()

    bar = vtk.vtkScalarBarActor()
    bar.SetLookupTable(lut)
    ticks, number = round_ticks(*lut.GetRange())
    marks = vtk.vtkDoubleArray()
    for t in ticks:
        marks.InsertNextValue(t)
    bar.UseCustomLabelsOn()
    bar.SetCustomLabels(marks)
    bar.SetLabelFormat(number)
    bar.UnconstrainedFontSizeOn()
    bar.SetLabelTextProperty(vtk_text("", (0, 0), size).GetTextProperty())
    bar.SetPosition((width - right + 40) / width, bottom / height)
    bar.SetPosition2(160 / width, (height - top - bottom) / height)
    renderer.AddActor(bar)
    renderer.AddActor(vtk_text(colour, (width - right + 240, bottom + (height - top - bottom) / 2),
                               size, Orientation=90, Justification=1, VerticalJustification=1))
    # VTK draws no mathtext: run_label's $F_N$ and $\theta$ as plain text.
    renderer.AddActor(vtk_text(title.replace("\\theta", "θ").replace("$", ""), (width / 2, height - 25), size - 2,
                               Justification=1, VerticalJustification=2, LineSpacing=1.15))

    window = vtk.vtkRenderWindow()
    window.SetOffScreenRendering(1)
    if not window.SupportsOpenGL():
        raise RenderUnavailable("the X display offers no OpenGL 3.2 for VTK to render with")
    window.SetSize(width, height)
    window.SetMultiSamples(8)
    window.AddRenderer(renderer)
    try:
        window.Render()
        image = vtk.vtkWindowToImageFilter()
        image.SetInput(window)
        image.ReadFrontBufferOff()
        os.makedirs(out_dir, exist_ok=True)
        png = vtk.vtkPNGWriter()
        png.SetInputConnection(image.GetOutputPort())
        png.SetFileName(os.path.join(out_dir, "lattice.png"))
        png.AddText("Software", f"VTK {vtk.vtkVersion.GetVTKVersion()} offscreen render")
        png.Write()
    finally:
        window.Finalize()  # closes the X connection while its server, perhaps our Xvfb, still runs
    print(os.path.join(out_dir, "lattice.png"))


def draw_lattice(grid, title, colour, magnify, out_dir):
    """lattice.png and .svg drawn with matplotlib, for where VTK cannot render."""
    from matplotlib.collections import PolyCollection
    from vtk.util.numpy_support import vtk_to_numpy

    data = grid.GetPointData()
    deformed = (vtk_to_numpy(grid.GetPoints().GetData()) + magnify * vtk_to_numpy(data.GetArray("deformation")))[:, :2]
    velocity = vtk_to_numpy(data.GetArray("x_velocity"))
    cells = [[grid.GetCell(c).GetPointId(k) for k in range(grid.GetCell(c).GetNumberOfPoints())]
             for c in range(grid.GetNumberOfCells())]
    fig, ax = plt.subplots(figsize=(9, 3.2))
    polygons = PolyCollection([deformed[c] * 1e3 for c in cells], array=np.array([velocity[c].mean() for c in cells]),
                              cmap="magma", edgecolors="0.5", linewidths=0.2)
    ax.add_collection(polygons)
    ax.autoscale_view()
    ax.set_aspect("equal")
    fig.colorbar(polygons, ax=ax, label=colour, shrink=0.8)
    ax.set_xlabel("x (mm)")
    ax.set_ylabel("z (mm)")
    ax.set_title(title, fontsize=8)
    save(fig, out_dir, "lattice")


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


def sidecar_text(directory, table):
    path = os.path.join(directory, table + ".meta.yaml")
    return open(path).read() if os.path.exists(path) else ""


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


def work_precision(study_dir):
    """Each relative error against wall time, one curve per family, cheapest case first."""
    with open(os.path.join(study_dir, "study.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    cases = [r for r in rows if r["case"] != "reference"]
    seeds = {r.get("seed") for r in rows} if "seeds:" in sidecar_text(study_dir, "study.csv") else {None}
    if len(seeds) > 1:
        cases = over_seeds(cases)
    families = list(dict.fromkeys(r["family"] for r in cases))
    fig, axes = plt.subplots(3, 3, figsize=(13, 10.5))
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
    handles, labels = axes.flat[0].get_legend_handles_labels()
    for ax in axes.flat[1:]:
        for h, lab in zip(*ax.get_legend_handles_labels()):
            if lab not in labels:
                handles.append(h)
                labels.append(lab)
    fig.legend(handles, labels, loc="lower center", ncol=max(1, len(labels)), frameon=False)
    with open(os.path.join(study_dir, "study.md")) as f:  # its first line is "# <the study's title>"
        title = f.readline().lstrip("# ").strip()
    over = f", the largest over {len(seeds)} seeds" if len(seeds) > 1 else ""
    fig.suptitle(f"{title}: relative error against the reference{over} (0 and NaN not drawn)")
    fig.tight_layout(rect=(0, 0.05, 1, 0.97))
    save(fig, study_dir, "work_precision")


def sweep_rows(sweep_dir, name):
    with open(os.path.join(sweep_dir, name), newline="") as f:
        return list(csv.DictReader(line for line in f if not line.startswith("#")))


def number(text):
    try:
        return float(text)
    except (TypeError, ValueError):
        return float("nan")


def sweep_figures(sweep_dir):
    """The campaign's figures from sweep.csv and events.csv (module docstring)."""
    cases = sweep_rows(sweep_dir, "sweep.csv")
    events = sweep_rows(sweep_dir, "events.csv")
    fixed = {"case", "status", "reason", "scene_hash", "global_static_coefficient", "events", "precursor_count",
             "first_precursor_force_ratio", "steps", "wall_seconds", "cpu_seconds"}
    varied = [k for k in (cases[0].keys() if cases else []) if k not in fixed and k != "seed"]
    def group(row):  # the case apart from its seed
        return ", ".join(f"{k.split('.')[-1]}={row[k]}" for k in varied) or re.sub(r"_seed-[0-9]+$", "", row["case"])
    out = os.path.join(sweep_dir, "plots")

    groups = list(dict.fromkeys(group(r) for r in cases))
    fig, ax = plt.subplots(figsize=(7, 5))
    for k, g in enumerate(groups):
        pts = [(number(e["force_ratio"]), number(e["extent_over_length"])) for e in events if group(e) == g]
        if pts:
            ax.plot([p[0] for p in pts], [p[1] for p in pts], "o", color=f"C{k % 10}", label=g, ms=4, alpha=0.8)
    ax.set_xlabel("$F_S/F_N$ at the event's start")
    ax.set_ylabel("rupture length $l/L$")
    if ax.lines:
        ax.legend(fontsize=8)
    else:
        no_data(ax, "no rupture event in any case")
    ax.set_title("every rupture event of every case (Li2020 Fig. 7)")
    save(fig, out, "sweep_precursor_lengths")
    plt.close(fig)

    numeric = [k for k in varied if all(np.isfinite(number(r[k])) for r in cases)]
    for key in numeric:
        xs = sorted({number(r[key]) for r in cases})
        fig, axes = plt.subplots(1, 3, figsize=(13, 4))
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
        fig.suptitle("mean (square), seeds (dots) and their spread (Li2020 Fig. 8)")
        fig.tight_layout()
        save(fig, out, "sweep_against_" + key.split(".")[-1])
        plt.close(fig)

    fig, ax = plt.subplots(figsize=(7, 5))
    unknown = False  # a case whose loading start is unknown is drawn from its own start
    for k, r in enumerate(cases):
        case = os.path.join(sweep_dir, "cases", r["case"])
        curve = table(case, "loading_curve.csv")
        if curve is None or "driving_force" not in curve.dtype.names:
            continue
        t0, since = time_origin(case)
        unknown = unknown or since != "loading started"
        loading = from_loading(curve["time"], t0)
        ax.plot(curve["time"][loading] - t0, curve["driving_force"][loading], lw=0.8,
                color=f"C{groups.index(group(r)) % 10}", label=group(r) if group(r) not in
                ax.get_legend_handles_labels()[1] else None)
    ax.set_xlabel(overlaid_time_label(unknown))
    ax.set_ylabel("driving force $F_S$ (N)")
    if ax.lines:
        ax.legend(fontsize=8)
    else:
        no_data(ax, "no case has a loading_curve table")
    save(fig, out, "sweep_loading_curves")
    plt.close(fig)


def main(argv):
    if argv[:1] == ["--sweep"]:
        if len(argv) != 2 or not os.path.exists(os.path.join(argv[1], "sweep.csv")):
            print("frictionlab_plot.py --sweep SWEEP_DIR: expected a directory with sweep.csv", file=sys.stderr)
            return 2
        sweep_figures(argv[1])
        return 0
    if argv[:1] == ["--study"]:
        if len(argv) != 2 or not os.path.exists(os.path.join(argv[1], "study.csv")):
            print("frictionlab_plot.py --study STUDY_DIR: expected a directory with study.csv", file=sys.stderr)
            return 2
        work_precision(argv[1])
        return 0
    parser = argparse.ArgumentParser(prog="frictionlab plot", description=__doc__.split("\n\n")[0])
    parser.add_argument("runs", nargs="+", help="run output directories")
    parser.add_argument("-o", "--output", help="where the figure over all runs goes (default: first run's plots/)")
    args = parser.parse_args(argv)
    for run in args.runs:
        if not os.path.exists(os.path.join(run, "run.yaml")):
            print(f"frictionlab plot: {run} is not a run directory (no run.yaml)", file=sys.stderr)
            return 2
    for run in args.runs:
        out = os.path.join(run, "plots")
        for figure in (loading_curve, four_phase, spacetime, fronts, energy, lattice):
            figure(run, out)
    out = args.output or os.path.join(args.runs[0], "plots")
    os.makedirs(out, exist_ok=True)
    precursor_lengths(args.runs, out)
    if len(args.runs) > 1:
        loading_curves(args.runs, out)
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
