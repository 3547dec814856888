#!/usr/bin/python3
"""A look at one rupture: slip velocity along the interface against time, around an event.

Reads a finished run's interface history (interface_velocity.csv or .h5) and its events
(precursors.csv or .h5), and draws log10 |v| of every interface block against time around the
chosen event, with its nucleation marked: the space-time map in which rupture fronts show as
slanted edges (Rubinstein et al. 2004; Ben-David et al. 2010).

    PYTHONPATH=build/python /usr/bin/python3 share/examples/rupture_look.py out/headline --event 0

Start from here: another quantity (run.table("interface_slip"), "interface_pinned_fraction"),
another window, a front-speed fit.
"""
import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

import frictionlab  # noqa: E402


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("run", help="a run directory with interface_history and precursors outputs")
    parser.add_argument("--event", type=int, default=-1, help="event index (default: the first global slip, "
                                                                "else the last event)")
    parser.add_argument("--before", type=float, default=5e-4, help="window before nucleation (s)")
    parser.add_argument("--after", type=float, default=3e-3, help="window after nucleation (s)")
    parser.add_argument("-o", "--output", help="figure file (default: RUN/plots/rupture_look.png)")
    args = parser.parse_args(argv)

    run = frictionlab.open_run(args.run)
    events = run.table("precursors")
    if len(events) == 0:
        print(f"{args.run}: no rupture event to look at", file=sys.stderr)
        return 1
    if args.event >= 0:
        row = list(events["event"]).index(args.event)
    else:
        global_rows = np.flatnonzero(events["global"] > 0.5)
        row = global_rows[0] if global_rows.size else len(events) - 1
    t0, x0 = events["t_start"][row], events["nucleation_x"][row]

    velocity = run.table("interface_velocity")
    t = velocity["time"]
    blocks = [c for c in velocity.columns if c.startswith("block_")]
    window = (t >= t0 - args.before) & (t <= t0 + args.after)
    v = velocity.values[window][:, [velocity.columns.index(b) for b in blocks]]

    fig, ax = plt.subplots(figsize=(7, 3.5))
    image = ax.imshow(np.log10(np.abs(v) + 1e-9).T, aspect="auto", origin="lower", cmap="magma",
                      interpolation="nearest",
                      extent=[(t[window][0] - t0) * 1e3, (t[window][-1] - t0) * 1e3, -0.5, len(blocks) - 0.5])
    fig.colorbar(image, ax=ax, label=r"log$_{10}$ |slip velocity| (m/s)")
    nucleation = events["nucleation_block"][row]
    ax.plot([0], [nucleation], "c*", ms=12, label=f"nucleation (x = {x0 * 1e3:.1f} mm)")
    ax.set_xlabel("time since nucleation (ms)")
    ax.set_ylabel("interface block (trailing edge = 0)")
    ax.set_title(f"event {int(events['event'][row])}, l/L = {events['extent_over_length'][row]:.2f}")
    ax.legend(frameon=False, fontsize=8, loc="upper right")
    fig.tight_layout()
    figure = args.output or os.path.join(run.directory, "plots", "rupture_look.png")
    os.makedirs(os.path.dirname(os.path.abspath(figure)), exist_ok=True)
    fig.savefig(figure, dpi=150)
    print(f"figure: {figure}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
