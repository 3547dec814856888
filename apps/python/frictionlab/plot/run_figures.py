"""The figures of one run, and of several overlaid. Each function draws onto the Axes it is given (a
new figure of the command's size if None) and returns them; plot_run and plot_runs write every
figure the runs' outputs allow, as `frictionlab plot RUN_DIR ...` does."""
import glob
import os

import matplotlib.pyplot as plt
import numpy as np

from ._clock import from_loading, overlaid_time_label, time_origin
from ._figure import NothingToDraw, axes_of, no_data, seed_style, write
from ._labels import no_events_note, run_label, run_labels, seed_of
from ._tables import has_table, run_directory, scene_of, table
from .interface_figures import interface_maps
from .patch_figures import patch_growth
from .lattice_rendering import plot_lattice


def loading_curve(run, ax=None):
    """F_S against time since loading started, the precursors (triangles) and global slips (circles)
    marked, titled with the scene (Li2020 Fig. 6). NothingToDraw without a loading curve of F_S."""
    curve, events = table(run, "loading_curve"), table(run, "precursors")
    if curve is None or "driving_force" not in curve.dtype.names:
        raise NothingToDraw(f"{run_directory(run)}: no loading_curve table with driving_force")
    t0, since = time_origin(run)
    loading = from_loading(curve["time"], t0)
    ax = axes_of(ax, figsize=(7, 4))
    ax.plot(curve["time"][loading] - t0, curve["driving_force"][loading], color="tab:red", lw=1)
    ax.set_ylabel("driving force $F_S$ (N)")
    if events is not None:
        t = events["t_start"] - t0
        glob_ = events["global"] > 0.5
        ax.plot(t[~glob_], events["driving_force"][~glob_], "v", color="tab:blue", ms=5, label="precursor")
        ax.plot(t[glob_], events["driving_force"][glob_], "o", mfc="none", color="k", ms=6, label="global slip")
        ax.legend(loc="lower right", frameon=False)
    ax.set_xlabel(f"time since {since} (s)")
    ax.set_title(run_label(run), fontsize=9)
    return ax


def event_lengths(run, ax=None):
    """The rupture length l/L of every event at its start, on loading_curve's clock (Li2020 Fig. 6,
    below the loading curve); a run without events says so."""
    events = table(run, "precursors")
    t0, since = time_origin(run)
    ax = axes_of(ax, figsize=(7, 1.5))
    if events is not None:
        t = events["t_start"] - t0
        ax.vlines(t, 0, events["extent_over_length"], color="tab:blue")
        ax.plot(t, events["extent_over_length"], ".", color="tab:blue")
    else:
        no_data(ax, no_events_note(run))
    ax.set_ylim(0, 1.05)
    ax.set_ylabel("$l/L$")
    ax.set_xlabel(f"time since {since} (s)")
    return ax


def loading_curve_with_events(run):
    """The command's loading_curve figure: loading_curve above event_lengths, on one time axis."""
    fig, (top, bottom) = plt.subplots(2, 1, sharex=True, figsize=(7, 5), gridspec_kw={"height_ratios": [3, 1]})
    try:
        loading_curve(run, ax=top)
    except NothingToDraw:
        plt.close(fig)
        raise
    event_lengths(run, ax=bottom)
    top.label_outer()  # the time axis is labelled once, below
    return top, bottom


def precursor_lengths(runs, ax=None):
    """l/L of every rupture event against F_S/F_N at its nucleation, a curve per run (Li2020 Figs. 7,
    8); `runs`: a list of runs."""
    ax = axes_of(ax, figsize=(5, 4))
    plotted = False
    seeds = [seed_of(run) for run in runs]
    labels = run_labels(runs) if len(runs) > 1 else [run_label(runs[0], short=True)]
    for run, seed, label in zip(runs, seeds, labels):
        events = table(run, "precursors")
        if events is None:
            continue
        ax.plot(events["force_ratio"], events["extent_over_length"], ms=4, lw=0.8, label=label,
                **seed_style(seeds, seed))  # the seeds told apart by marker and line
        plotted = True
    if plotted:
        ax.legend(frameon=False, fontsize=7, loc="upper left", bbox_to_anchor=(1.01, 1))
    else:
        no_data(ax, no_events_note(runs[0]) if len(runs) == 1 else "no rupture events in these runs")
    ax.set_xlabel("$F_S/F_N$ at nucleation")
    ax.set_ylabel("$l/L$")
    ax.set_ylim(0, 1.05)
    if len(runs) == 1:
        ax.set_title(run_label(runs[0]), fontsize=8)
    return ax


def loading_curves(runs, ax=None):
    """F_S/F_N against time since loading started, every run of the list `runs` overlaid, each
    labelled apart (run_labels)."""
    ax = axes_of(ax, figsize=(7, 4))
    unknown = False  # a run whose loading start is unknown is drawn from its own start
    seeds = [seed_of(run) for run in runs]
    for run, seed, label in zip(runs, seeds, run_labels(runs)):
        curve = table(run, "loading_curve")
        if curve is None or "driving_force_over_normal_load" not in curve.dtype.names:
            continue
        t0, since = time_origin(run)
        known = since == "loading started"
        unknown = unknown or not known
        loading = from_loading(curve["time"], t0)
        ax.plot(curve["time"][loading] - t0, curve["driving_force_over_normal_load"][loading], lw=1,
                linestyle=seed_style(seeds, seed)["linestyle"],  # the seeds told apart
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
    return ax


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


def contact_blocks(run):
    """The interface blocks whose junctions the run recorded (its contact_area_block_<i> tables), as
    the tables name them."""
    directory = run_directory(run)
    paths = glob.glob(os.path.join(directory, "contact_area_block_*.csv")) + \
        glob.glob(os.path.join(directory, "contact_area_block_*.h5"))
    return sorted({os.path.splitext(os.path.basename(p))[0][len("contact_area_block_"):] for p in paths})


def four_phase(run, block, axes=None):
    """Pinned fraction, state fractions, slip, |velocity| and forces of interface block `block`
    around the first event that detaches it after loading started, on four Axes sharing their time
    axis, the phases I-IV shaded (Li2020 Fig. 9; Ben-David et al. 2010). Where no event reached the
    block, the (first) Axes says so; a new figure then has one. NothingToDraw without the block's
    contact_area_block table."""
    d = table(run, f"contact_area_block_{block}")
    if d is None:
        raise NothingToDraw(f"{run_directory(run)}: no contact_area_block_{block} table")
    t0, since = time_origin(run)
    title = (f"interface block {int(block) + 1} of the paper (index {block}): the four phases of one rupture\n"
             + run_label(run))
    detached = np.flatnonzero(from_loading(d["time"], t0) & (d["pinned_fraction"] < 0.5))
    if detached.size == 0:
        axes = np.ravel(axes_of(axes, figsize=(7.5, 3)))
        no_data(axes[0], "no rupture event reached this block in this run:\n"
                         "its pinned fraction never fell below 0.5 after loading started")
        axes[0].set_xticks([])
        axes[0].set_yticks([])
        axes[0].set_title(title, fontsize=9)
        return axes
    t_det = d["time"][detached[0]]
    window = (d["time"] > t_det - 5e-4) & (d["time"] < t_det + 4e-3)
    w = d[window]
    t = (w["time"] - t_det) * 1e3
    axes = axes_of(axes, 4, 1, sharex=True, figsize=(7.5, 8.5))
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
    return axes


def spacetime(run, axes=None):
    """The slip velocity (log) and, where the run recorded it, the pinned fraction along the
    interface against time since loading started: an image on each Axes (a new figure has one or
    two). NothingToDraw without the interface_velocity table."""
    velocity, pinned = table(run, "interface_velocity"), table(run, "interface_pinned_fraction")
    if velocity is None:
        raise NothingToDraw(f"{run_directory(run)}: no interface_velocity table")
    panels = [(velocity, "log$_{10}$ |slip velocity| (m/s)", lambda v: np.log10(np.abs(v) + 1e-9), "magma")]
    if pinned is not None:
        panels.append((pinned, "pinned fraction", lambda v: v, "viridis"))
    t0, since = time_origin(run)  # one time origin with the loading curve
    axes = np.ravel(axes_of(axes, len(panels), 1, sharex=True, figsize=(7, 3 * len(panels)), squeeze=False))
    for ax, (data, label, transform, cmap) in zip(axes, panels):
        blocks = [n for n in data.dtype.names if n.startswith("block_")]
        values = np.column_stack([data[b] for b in blocks])
        image = ax.imshow(transform(values).T, aspect="auto", origin="lower", cmap=cmap, interpolation="nearest",
                          extent=[data["time"][0] - t0, data["time"][-1] - t0, -0.5, len(blocks) - 0.5])
        ax.figure.colorbar(image, ax=ax, label=label)
        ax.set_ylabel("interface block (trailing edge = 0)")
    axes[0].set_title(run_label(run), fontsize=9)
    axes[-1].set_xlabel(f"time since {since} (s; negative: settling)")
    return axes


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


def fronts(run, ax=None):
    """Rupture-front position against time since nucleation for every event (Rubinstein et al. 2004
    style), with the lattice's shear and Rayleigh wave speeds for reference, events or not.
    NothingToDraw without a precursors observer."""
    if not has_table(run, "precursors"):
        raise NothingToDraw(f"{run_directory(run)}: no precursors observer")
    f, events = table(run, "precursor_fronts"), table(run, "precursors")
    t0, since = time_origin(run)
    ax = axes_of(ax, figsize=(7, 4.5))
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
    return ax


def energy(run, axes=None):
    """The energy balance against time since loading started: input, stored, kinetic and dissipated
    energy on the first Axes, the balance's residual on the second. NothingToDraw without the energy
    table."""
    e = table(run, "energy")
    if e is None:
        raise NothingToDraw(f"{run_directory(run)}: no energy table")
    t0, since = time_origin(run)
    t = e["time"] - t0
    top, bottom = axes_of(axes, 2, 1, sharex=True, figsize=(7, 6), gridspec_kw={"height_ratios": [3, 1]})
    top.set_title(run_label(run), fontsize=9)
    for name in ("input", "stored_energy", "kinetic_energy", "dissipated_damping", "dissipated_friction"):
        if name in e.dtype.names:
            top.plot(t, e[name], label=name.replace("_", " "))
    top.set_ylabel("energy (J)")
    top.legend(frameon=False, fontsize=8)
    bottom.plot(t, e["residual"], "k", lw=1)
    bottom.set_ylabel("balance residual (J)")
    bottom.set_xlabel(f"time since {since} (s; negative: settling)")
    return top, bottom


def plot_run(run, out_dir=None):
    """Every figure the run's outputs allow, into out_dir (default: the run's plots/), as PNG and SVG
    named loading_curve, four_phase_<block>, spacetime, fronts, energy, interface (a 3D run's maps of
    its interface), patches (a 3D run's events' growth on its interface) and lattice (PNG only)."""
    out_dir = out_dir or os.path.join(run_directory(run), "plots")
    write(out_dir, "loading_curve", loading_curve_with_events, run)
    for block in contact_blocks(run):
        write(out_dir, f"four_phase_{block}", four_phase, run, block)
    write(out_dir, "spacetime", spacetime, run)
    write(out_dir, "fronts", fronts, run)
    write(out_dir, "energy", energy, run)
    write(out_dir, "interface", interface_maps, run)
    write(out_dir, "patches", patch_growth, run)
    plot_lattice(run, out_dir)


def plot_runs(runs, output=None):
    """plot_run for every run of the list `runs`, then precursor_lengths over all of them and, with
    several, loading_curves, into `output` (default: the first run's plots/)."""
    for run in runs:
        plot_run(run)
    out = output or os.path.join(run_directory(runs[0]), "plots")
    write(out, "precursor_lengths", precursor_lengths, runs)
    if len(runs) > 1:
        write(out, "loading_curves", loading_curves, runs)
