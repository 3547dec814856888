#!/usr/bin/python3
"""Pictures of FrictionLab runs, in the style of Li et al. (2020) and of the experiments.

    frictionlab plot RUN_DIR [RUN_DIR ...] [-o OUT_DIR]

For each run directory, writes into RUN_DIR/plots/ (PNG and SVG) whichever figures its outputs allow:
  loading_curve   F_S against time with the precursors marked, their l/L below (Li2020 Fig. 6)
  four_phase_<i>  pinned fraction, state fractions, slip, velocity and forces of interface block i
                  around the first event that reaches it (Li2020 Fig. 9; Ben-David et al. 2010)
  spacetime       slip velocity and pinned fraction along the interface against time
  fronts          rupture-front position against time since nucleation, one curve per event
  energy          the energy balance: input, stored, kinetic, dissipated, residual
and, over all the runs given, precursor_lengths: l/L against F_S/F_N (Li2020 Figs. 7, 8).

    frictionlab_plot.py --study STUDY_DIR      (run by `frictionlab study`)

draws work_precision (PNG and SVG) into STUDY_DIR from its study.csv: each error against wall time,
log-log, one curve per family of cases.
Each figure is a short function below: adapt them freely.
"""
import argparse
import csv
import glob
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
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


def save(fig, out_dir, name):
    os.makedirs(out_dir, exist_ok=True)
    for ext in ("png", "svg"):
        fig.savefig(os.path.join(out_dir, f"{name}.{ext}"), dpi=150, bbox_inches="tight")
    plt.close(fig)
    print(os.path.join(out_dir, name + ".png"))


def load_stage_start(curve):
    """Time at which the last stage (the loading) starts: the driving force is zero until then."""
    stages = curve["stage"]
    return curve["time"][np.argmax(stages == stages.max())]


def loading_curve(run, out_dir):
    curve, events = table(run, "loading_curve.csv"), table(run, "precursors.csv")
    if curve is None or "driving_force" not in curve.dtype.names:
        return
    t0 = load_stage_start(curve)
    loading = curve["time"] >= t0
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
    bottom.set_ylim(0, 1.05)
    bottom.set_ylabel("$l/L$")
    bottom.set_xlabel("time since loading started (s)")
    top.set_title(os.path.basename(os.path.abspath(run)))
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
                label=os.path.basename(os.path.abspath(run)))
        plotted = True
    if not plotted:
        plt.close(fig)
        return
    ax.set_xlabel("$F_S/F_N$ at nucleation")
    ax.set_ylabel("$l/L$")
    ax.set_ylim(0, 1.05)
    ax.legend(frameon=False, fontsize=8)
    save(fig, out_dir, "precursor_lengths")


def four_phase(run, out_dir):
    paths = glob.glob(os.path.join(run, "contact_area_block_*.csv")) + glob.glob(os.path.join(run, "contact_area_block_*.h5"))
    for stem in sorted({os.path.splitext(os.path.basename(p))[0] for p in paths}):
        block = stem[len("contact_area_block_"):]
        d = table(run, stem + ".csv")
        if d is None:
            continue
        loading = d["stage"] == d["stage"].max()
        detached = np.flatnonzero(loading & (d["pinned_fraction"] < 0.5))
        if detached.size == 0:
            continue
        t_det = d["time"][detached[0]]
        window = (d["time"] > t_det - 5e-4) & (d["time"] < t_det + 4e-3)
        t = (d["time"][window] - t_det) * 1e3
        fig, axes = plt.subplots(4, 1, sharex=True, figsize=(6, 8))
        axes[0].plot(t, d["normalised_pinned"][window], "k", label=r"$\tilde N_p$")
        for name, color in (("pinned", "tab:green"), ("sliding", "tab:red"), ("dislocated", "tab:blue")):
            axes[0].plot(t, d[name + "_fraction"][window], color=color, lw=1, label=name)
        axes[0].legend(frameon=False, fontsize=8, ncol=4)
        axes[0].set_ylabel("fraction")
        slip = d["slip"][window]
        axes[1].plot(t, (slip - slip[0]) * 1e6, "k")
        axes[1].set_ylabel(r"slip $\Delta$ ($\mu$m)")
        axes[2].plot(t, d["velocity"][window] * 1e3, "k")
        axes[2].set_ylabel("velocity (mm/s)")
        for name, label in (("friction_force", "$f_i$"), ("bond_force_left", "left bond"), ("bond_force_right", "right bond")):
            axes[3].plot(t, d[name][window], lw=1, label=label)
        axes[3].legend(frameon=False, fontsize=8)
        axes[3].set_ylabel("force (N)")
        axes[3].set_xlabel("time since detachment (ms)")
        axes[0].set_title(f"block {block}: the four phases of one rupture")
        save(fig, out_dir, f"four_phase_{block}")


def spacetime(run, out_dir):
    velocity, pinned = table(run, "interface_velocity.csv"), table(run, "interface_pinned_fraction.csv")
    if velocity is None:
        return
    panels = [(velocity, "log$_{10}$ |slip velocity| (m/s)", lambda v: np.log10(np.abs(v) + 1e-9), "magma")]
    if pinned is not None:
        panels.append((pinned, "pinned fraction", lambda v: v, "viridis"))
    fig, axes = plt.subplots(len(panels), 1, sharex=True, figsize=(7, 3 * len(panels)), squeeze=False)
    for ax, (data, label, transform, cmap) in zip(axes[:, 0], panels):
        blocks = [n for n in data.dtype.names if n.startswith("block_")]
        values = np.column_stack([data[b] for b in blocks])
        image = ax.imshow(transform(values).T, aspect="auto", origin="lower", cmap=cmap, interpolation="nearest",
                          extent=[data["time"][0], data["time"][-1], -0.5, len(blocks) - 0.5])
        fig.colorbar(image, ax=ax, label=label)
        ax.set_ylabel("interface block (trailing edge = 0)")
    axes[-1, 0].set_xlabel("time (s)")
    save(fig, out_dir, "spacetime")


def fronts(run, out_dir):
    """Rupture-front position against time for every event (Rubinstein et al. 2004 style)."""
    f, events = table(run, "precursor_fronts.csv"), table(run, "precursors.csv")
    if f is None or events is None:
        return
    fig, ax = plt.subplots(figsize=(6, 4))
    cmap = plt.get_cmap("viridis")
    ids = np.unique(f["event"])
    for k, event in enumerate(ids):
        rows = f["event"] == event
        order = np.argsort(f["delay"][rows])
        is_global = events["global"][events["event"] == event].max() > 0.5
        ax.plot(f["delay"][rows][order] * 1e3, f["x"][rows][order] * 1e3, ".-" if is_global else "o-", ms=3,
                lw=0.8, color=cmap(k / max(len(ids) - 1, 1)), label=f"event {int(event)}" + (" (global)" if is_global else ""))
    ax.set_xlabel("time since nucleation (ms)")
    ax.set_ylabel("front position x (mm)")
    ax.legend(frameon=False, fontsize=7)
    save(fig, out_dir, "fronts")


def energy(run, out_dir):
    e = table(run, "energy.csv")
    if e is None:
        return
    t = e["time"]
    fig, (top, bottom) = plt.subplots(2, 1, sharex=True, figsize=(7, 6), gridspec_kw={"height_ratios": [3, 1]})
    for name in ("input", "stored_energy", "kinetic_energy", "dissipated_damping", "dissipated_friction"):
        if name in e.dtype.names:
            top.plot(t, e[name], label=name.replace("_", " "))
    top.set_ylabel("energy (J)")
    top.legend(frameon=False, fontsize=8)
    bottom.plot(t, e["residual"], "k", lw=1)
    bottom.set_ylabel("balance residual (J)")
    bottom.set_xlabel("time (s)")
    save(fig, out_dir, "energy")


STUDY_ERRORS = [
    ("err_settled_normal_force", "settled normal force profile"),
    ("err_settled_friction_force", "settled friction force profile"),
    ("err_first_precursor_time", "time of the first precursor"),
    ("err_first_precursor_force", "$F_S$ of the first precursor"),
    ("err_global_static_coefficient", "global $F_S/F_N$"),
    ("err_event_slip", "slip profile of the first event"),
]


def work_precision(study_dir):
    """Each relative error against wall time, one curve per family, cheapest case first."""
    with open(os.path.join(study_dir, "study.csv"), newline="") as f:
        rows = list(csv.DictReader(f))
    cases = [r for r in rows if r["case"] != "reference"]
    families = list(dict.fromkeys(r["family"] for r in cases))
    fig, axes = plt.subplots(2, 3, figsize=(13, 7.5))
    for ax, (column, title) in zip(axes.flat, STUDY_ERRORS):
        for k, family in enumerate(families):
            points = sorted((float(r["wall_seconds"]), float(r[column]), r["case"]) for r in cases if r["family"] == family)
            points = [p for p in points if np.isfinite(p[1]) and p[1] > 0]  # a log axis has no 0 or NaN
            if points:
                ax.plot([p[0] for p in points], [p[1] for p in points], "o-", color=f"C{k}", label=family, ms=4)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_title(title, fontsize=10)
        ax.grid(True, which="major", alpha=0.3)
    for ax in axes[1]:
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
    fig.suptitle(f"{title}: relative error against the reference (0 and NaN not drawn)")
    fig.tight_layout(rect=(0, 0.05, 1, 0.97))
    save(fig, study_dir, "work_precision")


def main(argv):
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
        for figure in (loading_curve, four_phase, spacetime, fronts, energy):
            figure(run, out)
    precursor_lengths(args.runs, args.output or os.path.join(args.runs[0], "plots"))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
