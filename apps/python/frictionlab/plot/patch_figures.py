"""How each rupture event of a 3D run grows on its 2D interface: from precursor_fronts.csv (each
block's first rupture), the event's area and its extents along x and across y against the time since
it started. A patch that nucleates away from the edges grows in both directions until it spans the
width, then runs along the length (Gvirtzman et al., Nature 637, 369, 2025): the figure marks when
each event's extent across reaches the width. A 2D run's events are lines: it has no such figure."""
import numpy as np

from ._figure import NothingToDraw, axes_of
from ._labels import run_label
from ._tables import has_table, run_directory, scene_of, table


def patch_growth_series(run):
    """{event: (delays, area_fraction, along, across)}: at each first-rupture delay (s) of the event's
    blocks, the share of the interface's area its ruptured blocks' cells cover and the span of their
    positions along x and across y (m), each block counting from its first rupture on. NothingToDraw
    without events, or for a 2D run."""
    if not has_table(run, "precursors"):
        raise NothingToDraw(f"{run_directory(run)}: no precursors observer")
    fronts = table(run, "precursor_fronts")
    if fronts is None or "y" not in fronts.dtype.names:
        raise NothingToDraw(f"{run_directory(run)}: its events are on a line (a 2D run)")
    bulk = scene_of(run)["bulk"]
    length, width = float(bulk["length"]), float(bulk["width"])
    spacing = length / (int(bulk["nx"]) - 1)
    cells = ((np.minimum(length, fronts["x"] + spacing / 2) - np.maximum(0, fronts["x"] - spacing / 2)) *
             (np.minimum(width, fronts["y"] + spacing / 2) - np.maximum(0, fronts["y"] - spacing / 2)))
    series = {}
    for event in np.unique(fronts["event"]):
        rows = fronts["event"] == event
        delays, x, y, area = fronts["delay"][rows], fronts["x"][rows], fronts["y"][rows], cells[rows]
        order = np.argsort(delays, kind="stable")
        delays, x, y, area = delays[order], x[order], y[order], area[order]
        steps = np.unique(delays)
        last = np.searchsorted(delays, steps, side="right")  # blocks ruptured by each delay
        series[int(event)] = (steps, np.cumsum(area)[last - 1] / (length * width),
                              np.array([np.ptp(x[:k]) for k in last]), np.array([np.ptp(y[:k]) for k in last]))
    if not series:
        raise NothingToDraw(f"{run_directory(run)}: no rupture events")
    return series


def patch_growth(run, ax=None, events=4):
    """The area (top) and the extents along and across (bottom) of the run's `events` largest events
    against the time since each started; a dot where an event's extent across first reaches the
    interface's width."""
    series = patch_growth_series(run)
    width = float(scene_of(run)["bulk"]["width"])
    spacing = float(scene_of(run)["bulk"]["length"]) / (int(scene_of(run)["bulk"]["nx"]) - 1)
    largest = sorted(series, key=lambda e: series[e][1][-1], reverse=True)[:events]
    top, bottom = axes_of(ax, 2, 1, sharex=True, figsize=(7, 6))
    for k, event in enumerate(sorted(largest)):
        delays, area, along, across = series[event]
        colour = f"C{k}"
        t = delays * 1e6
        top.step(t, area, where="post", color=colour, label=f"event {event}")
        bottom.step(t, along * 1e3, where="post", color=colour, label=f"event {event}: along x")
        bottom.step(t, across * 1e3, where="post", color=colour, ls="--", label=f"event {event}: across y")
        spans = np.flatnonzero(across >= width - spacing / 2)
        if spans.size:
            top.plot(t[spans[0]], area[spans[0]], "o", color=colour, ms=5)
    top.set_ylabel("area, fraction of the interface")
    top.legend(frameon=False, fontsize=8)
    top.set_title(f"{run_label(run)}\nrupture patches (dot: the patch spans the width)", fontsize=8)
    bottom.set_ylabel("extent (mm)")
    bottom.set_xlabel("time since the event started (µs)")
    bottom.legend(frameon=False, fontsize=7, ncol=2)
    return top, bottom
