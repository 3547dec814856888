"""The interface of a 3D run seen from below: maps of its blocks' slip speed over x and y, at the
lattice snapshots leading up to the fastest one (a global slip, where the run has one), so that a
front shows as it crosses the interface in both directions. A 2D run's interface is a line: it has
no such figure. Read from the run's VTU series with VTK for Python (Debian's python3-vtk9)."""
import os
import xml.etree.ElementTree as ElementTree

import matplotlib.colors
import numpy as np

from ._clock import time_origin
from ._figure import NothingToDraw, axes_of
from ._labels import run_label
from ._tables import run_directory

# Slower than this, a block is shown as still (m/s): the colour scale is logarithmic.
STILL = 1e-6


def interface_series(run):
    """(times, x, y, speeds) of the interface blocks (the nodes whose friction force is published) in
    every snapshot of the run's lattice series: x, y their reference positions (m), speeds an array of
    |v| in the interface plane (m/s), a row per snapshot. NothingToDraw without a series, or for an
    interface that is a line."""
    pvd = os.path.join(run_directory(run), "lattice.pvd")
    if not os.path.exists(pvd):
        raise NothingToDraw(f"{run_directory(run)}: no lattice series")
    import vtk
    from vtk.util.numpy_support import vtk_to_numpy

    times, speeds, x, y = [], [], None, None
    for d in ElementTree.parse(pvd).getroot().iter("DataSet"):
        reader = vtk.vtkXMLUnstructuredGridReader()
        reader.SetFileName(os.path.join(os.path.dirname(pvd), d.get("file")))
        reader.Update()
        grid = reader.GetOutput()
        data = grid.GetPointData()
        if data.GetArray("friction_force") is None or data.GetArray("velocity") is None:
            raise NothingToDraw(f"{pvd}: no friction force or velocity in its snapshots")
        on = ~np.isnan(vtk_to_numpy(data.GetArray("friction_force")))
        if x is None:
            reference = vtk_to_numpy(grid.GetPoints().GetData())[on] - vtk_to_numpy(data.GetArray("displacement"))[on]
            x, y = reference[:, 0], reference[:, 1]
            if np.ptp(y) == 0:
                raise NothingToDraw(f"{pvd}: the interface is a line (a 2D run)")
        times.append(float(d.get("timestep")))
        speeds.append(np.hypot(*vtk_to_numpy(data.GetArray("velocity"))[on][:, :2].T))
    if not times:
        raise NothingToDraw(f"{pvd}: no snapshots")
    return np.array(times), x, y, np.array(speeds)


def interface_maps(run, ax=None, maps=6, until=None):
    """`maps` maps of the interface's slip speed, one above the other (a grid row by row on an interface
    wider than half its length), at the snapshots up to and
    including the one whose mean speed is the largest, or the last at or before `until` (s since
    loading started: a nucleation, say, from a global slip's t_start_since_loading); one logarithmic
    colour scale from STILL."""
    times, x, y, speeds = interface_series(run)
    t0, since = time_origin(run)
    if until is None:
        last = int(np.argmax(speeds.mean(axis=1)))
    else:
        last = int(np.searchsorted(times - t0, until, side="right")) - 1
        if last < 0:
            raise NothingToDraw(f"{run_directory(run)}: no snapshot by {until} s after {since}")
    shown = list(range(max(0, last - maps + 1), last + 1))
    xs, ys = np.unique(x), np.unique(y)
    # A narrow interface's maps stand one above the other; a wide one's fill a grid, row by row.
    aspect = np.ptp(ys) / np.ptp(xs)
    columns = 1 if aspect <= 0.5 else int(np.ceil(np.sqrt(len(shown))))
    rows = int(np.ceil(len(shown) / columns))
    side = 6.5 / columns  # inches of x a map takes, of which the colour bar leaves about 3/4 in a grid
    drawn = side if columns == 1 else 0.75 * side
    figure = {"figsize": (1.5 + side * columns, 1.0 + (0.45 + drawn * aspect) * rows), "squeeze": False}
    grid = np.ravel(axes_of(ax, rows, columns, sharex=True, sharey=True, **figure))
    if ax is None:
        for unused in grid[len(shown):]:
            unused.remove()
    axes = grid[:len(shown)]
    column, row = np.searchsorted(xs, x), np.searchsorted(ys, y)
    norm = matplotlib.colors.LogNorm(STILL, max(float(speeds[shown].max()), 10 * STILL))
    for k, ax_k in zip(shown, axes):
        speed = np.full((len(ys), len(xs)), np.nan)
        speed[row, column] = np.maximum(speeds[k], STILL)
        image = ax_k.pcolormesh(xs * 1e3, ys * 1e3, speed, norm=norm, cmap="magma", shading="nearest")
        ax_k.set_aspect("equal")
        after = f" after {since}" if columns == 1 else ""  # in a grid, the suptitle says it once
        ax_k.set_title(f"{(times[k] - t0) * 1e3:.3f} ms{after}", fontsize=8, loc="left")
    for n, ax_n in enumerate(axes):
        if n % columns == 0:
            ax_n.set_ylabel("y (mm)")
        if n + columns >= len(axes):  # nothing below it
            ax_n.set_xlabel("x (mm)")
            ax_n.xaxis.set_tick_params(labelbottom=True)
    axes[0].figure.colorbar(image, ax=list(axes), label="slip speed |v| (m/s)", shrink=0.9)
    up_to = "its fastest snapshot" if until is None else f"{until * 1e3:g} ms after {since}"
    times_are = "" if columns == 1 else f" (times after {since})"
    axes[0].figure.suptitle(f"{run_label(run)}\nthe interface from below, up to {up_to}{times_are}", fontsize=8)
    return axes
