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


def _interface_snapshots(run, arrays, optional=()):
    """(times, x, y, {name: values}) of the interface blocks (the nodes whose friction force is
    published) in every snapshot of the run's lattice series: x, y their reference positions (m), each
    of `arrays` and `optional` (point arrays of the series) a row per snapshot, an optional one NaN
    where a snapshot lacks it. NothingToDraw without a series, for snapshots without `arrays`, or for
    an interface that is a line."""
    pvd = os.path.join(run_directory(run), "lattice.pvd")
    if not os.path.exists(pvd):
        raise NothingToDraw(f"{run_directory(run)}: no lattice series")
    import vtk
    from vtk.util.numpy_support import vtk_to_numpy

    times, values, x, y = [], {name: [] for name in tuple(arrays) + tuple(optional)}, None, None
    for d in ElementTree.parse(pvd).getroot().iter("DataSet"):
        reader = vtk.vtkXMLUnstructuredGridReader()
        reader.SetFileName(os.path.join(os.path.dirname(pvd), d.get("file")))
        reader.Update()
        grid = reader.GetOutput()
        data = grid.GetPointData()
        missing = [name for name in ("friction_force",) + tuple(arrays) if data.GetArray(name) is None]
        if missing:
            raise NothingToDraw(f"{pvd}: no {' or '.join(missing)} in its snapshots")
        on = ~np.isnan(vtk_to_numpy(data.GetArray("friction_force")))
        if x is None:
            reference = vtk_to_numpy(grid.GetPoints().GetData())[on] - vtk_to_numpy(data.GetArray("displacement"))[on]
            x, y = reference[:, 0], reference[:, 1]
            if np.ptp(y) == 0:
                raise NothingToDraw(f"{pvd}: the interface is a line (a 2D run)")
        times.append(float(d.get("timestep")))
        for name in arrays:
            values[name].append(vtk_to_numpy(data.GetArray(name))[on])
        for name in optional:
            array = data.GetArray(name)
            values[name].append(vtk_to_numpy(array)[on] if array is not None else np.full(on.sum(), np.nan))
    if not times:
        raise NothingToDraw(f"{pvd}: no snapshots")
    return np.array(times), x, y, {name: np.array(rows) for name, rows in values.items()}


def interface_series(run):
    """(times, x, y, speeds) of the interface blocks in every snapshot of the run's lattice series:
    x, y their reference positions (m), speeds an array of |v| in the interface plane (m/s), a row per
    snapshot. NothingToDraw without a series, or for an interface that is a line."""
    times, x, y, values = _interface_snapshots(run, ("velocity",))
    return times, x, y, np.hypot(values["velocity"][:, :, 0], values["velocity"][:, :, 1])


def slipping_patch(run):
    """The blocks in the slipping state (the friction law's `slipping` quantity) in every snapshot of
    the run's lattice series, as a structured array with a row per snapshot: time (s, of the run),
    blocks (how many), along and across (the span of their reference positions in x and y, m, 0 for
    one block, NaN for none), speed (their mean slip speed, m/s) and slip (the largest slip of any
    block, m; NaN for a law that publishes none). A slow patch creeping below the precursors
    observer's quiet_speed is no event for it, and shows here (theory.md 5a)."""
    times, x, y, values = _interface_snapshots(run, ("slipping", "velocity"), optional=("slip",))
    rows = []
    for t, slipping, velocity, slip in zip(times, values["slipping"], values["velocity"], values["slip"]):
        on = slipping > 0.5
        some = bool(on.any())
        speed = np.hypot(velocity[on, 0], velocity[on, 1]).mean() if some else np.nan
        rows.append((t, int(on.sum()), np.ptp(x[on]) if some else np.nan, np.ptp(y[on]) if some else np.nan,
                     speed, np.abs(slip).max()))
    return np.array(rows, dtype=[("time", float), ("blocks", int), ("along", float), ("across", float),
                                 ("speed", float), ("slip", float)])


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
