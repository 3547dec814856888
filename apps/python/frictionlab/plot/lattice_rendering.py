"""The lattice around the first global slip: its VTU snapshot warped by the displacement less its
mean, magnified, coloured by the nodes' x velocity. Rendered by VTK offscreen into a PNG (a render
is a raster) under an X display (_x_display), or drawn with matplotlib onto an Axes where VTK cannot
render; plot_lattice writes it as `frictionlab plot` does. VTK for Python: Debian's python3-vtk9."""
import os
import sys
import xml.etree.ElementTree as ElementTree

import matplotlib.font_manager
import matplotlib.pyplot as plt
import matplotlib.ticker
import numpy as np

from ._clock import time_origin
from ._figure import NothingToDraw, axes_of, write
from ._labels import run_label
from ._tables import has_table, run_directory, table
from ._x_display import RenderUnavailable, x_display


def lattice_snapshot(run):
    """(path, time, global slip's start) of the first VTU snapshot at or after the first global slip
    started, or (path, time, None) of the last one in a run without a global slip (or whose series
    ends before it); None without a lattice series."""
    directory = run_directory(run)
    pvd = os.path.join(directory, "lattice.pvd")
    if not os.path.exists(pvd):
        return None
    snapshots = [(float(d.get("timestep")), d.get("file")) for d in ElementTree.parse(pvd).getroot().iter("DataSet")]
    if not snapshots:
        return None
    events = table(run, "precursors")
    if events is not None and (events["global"] > 0.5).any():
        t_global = events["t_start"][events["global"] > 0.5][0]
        later = [s for s in snapshots if s[0] >= t_global]
        if later:
            return os.path.join(directory, later[0][1]), later[0][0], t_global
    return os.path.join(directory, snapshots[-1][1]), snapshots[-1][0], None


def lattice_title(run, snapshot, mean_slip, magnify):
    """What the lattice figure shows: the run, which snapshot and when, and how it is deformed."""
    t0, since = time_origin(run)
    _, t, t_global = snapshot
    if t_global is not None:
        which = f"the first snapshot after the first global slip started ({(t_global - t0) * 1e3:.3f} ms)"
    elif has_table(run, "precursors"):
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


def lattice_grid(run, magnify=200.0):
    """(grid, title, colour bar label) of the lattice figure: the VTU snapshot lattice_snapshot picks
    (points at their reference positions) with its arrays 'deformation' (the displacement less its
    mean) and 'x_velocity' (in velocity_unit). NothingToDraw without a lattice series with cells,
    displacement and velocity; ImportError without VTK."""
    snapshot = lattice_snapshot(run)
    if snapshot is None:
        raise NothingToDraw(f"{run_directory(run)}: no lattice series")
    import vtk
    from vtk.util.numpy_support import numpy_to_vtk, vtk_to_numpy

    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(snapshot[0])
    reader.Update()
    snapshot_grid = reader.GetOutput()
    grid = side_view(snapshot_grid)
    face = "; the 3D lattice's front face (least y), seen from the side" if grid is not snapshot_grid else ""
    data = grid.GetPointData()
    if grid.GetNumberOfCells() == 0 or data.GetArray("displacement") is None or data.GetArray("velocity") is None:
        raise NothingToDraw(f"{snapshot[0]}: no cells, displacement or velocity")
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
    return grid, lattice_title(run, snapshot, mean[0], magnify) + face, f"x velocity vₓ ({unit})"


def side_view(grid):
    """The lattice as the figure's plane holds it, (x, z) as a 2D run writes it: a 2D run's grid as it
    is; a 3D run's front face (its nodes at the least y and the cells among them: its bonds, or the
    faces of its cubes), with its points and
    displacements turned from (x, y, z) into (x, z, 0). Seen from above, a 3D lattice would show its
    width where the axes say z."""
    import vtk
    from vtk.util.numpy_support import numpy_to_vtk, vtk_to_numpy

    points = vtk_to_numpy(grid.GetPoints().GetData())
    if grid.GetNumberOfPoints() == 0 or np.ptp(points[:, 2]) == 0:
        return grid
    front = numpy_to_vtk((points[:, 1] <= points[:, 1].min()).astype(float), deep=True)
    front.SetName("front_face")
    grid.GetPointData().AddArray(front)
    threshold = vtk.vtkThreshold()  # a cell stays when all its points are on the face
    if any(grid.GetCell(c).GetCellDimension() == 3 for c in range(min(grid.GetNumberOfCells(), 1))):
        surface = vtk.vtkDataSetSurfaceFilter()  # volumes: their boundary faces, the front face's among them
        surface.SetInputData(grid)
        threshold.SetInputConnection(surface.GetOutputPort())
    else:
        threshold.SetInputData(grid)
    threshold.SetInputArrayToProcess(0, 0, 0, vtk.vtkDataObject.FIELD_ASSOCIATION_POINTS, "front_face")
    threshold.SetLowerThreshold(0.5)
    threshold.SetUpperThreshold(1.5)
    threshold.Update()
    face = threshold.GetOutput()

    def turned(xyz):
        return numpy_to_vtk(np.column_stack([xyz[:, 0], xyz[:, 2], np.zeros(len(xyz))]), deep=True)

    plane = vtk.vtkPoints()
    plane.SetData(turned(vtk_to_numpy(face.GetPoints().GetData())))
    face.SetPoints(plane)
    data = face.GetPointData()
    for name in ("displacement", "velocity"):
        if data.GetArray(name) is not None:
            array = turned(vtk_to_numpy(data.GetArray(name)))
            array.SetName(name)
            data.AddArray(array)  # replaces the array of that name
    return face


def render_lattice(run, path, magnify=200.0):
    """The lattice rendered by VTK offscreen into the PNG `path`, under $DISPLAY or a private Xvfb;
    RenderUnavailable where VTK cannot render (the message says why)."""
    grid, title, colour = lattice_grid(run, magnify)
    with x_display():
        render_grid(grid, title, colour, magnify, path)


def lattice(run, ax=None, magnify=200.0):
    """The lattice drawn with matplotlib onto `ax` (a new figure if None), with its colour bar: what
    plot_lattice draws where VTK cannot render. NothingToDraw without a lattice series."""
    from matplotlib.collections import PolyCollection
    from vtk.util.numpy_support import vtk_to_numpy

    grid, title, colour = lattice_grid(run, magnify)
    data = grid.GetPointData()
    deformed = (vtk_to_numpy(grid.GetPoints().GetData()) + magnify * vtk_to_numpy(data.GetArray("deformation")))[:, :2]
    velocity = vtk_to_numpy(data.GetArray("x_velocity"))
    cells = [[grid.GetCell(c).GetPointId(k) for k in range(grid.GetCell(c).GetNumberOfPoints())]
             for c in range(grid.GetNumberOfCells())]
    ax = axes_of(ax, figsize=(9, 3.2))
    polygons = PolyCollection([deformed[c] * 1e3 for c in cells], array=np.array([velocity[c].mean() for c in cells]),
                              cmap="magma", edgecolors="0.5", linewidths=0.2)
    ax.add_collection(polygons)
    ax.autoscale_view()
    ax.set_aspect("equal")
    ax.figure.colorbar(polygons, ax=ax, label=colour, shrink=0.8)
    ax.set_xlabel("x (mm)")
    ax.set_ylabel("z (mm)")
    ax.set_title(title, fontsize=8)
    return ax


def plot_lattice(run, out_dir, magnify=200.0):
    """out_dir/lattice.png rendered by VTK (render_lattice), or lattice.png and .svg drawn with
    matplotlib where VTK cannot render, saying so; nothing without a lattice series or VTK."""
    if lattice_snapshot(run) is None:
        return
    try:
        import vtk  # noqa: F401
    except ImportError:
        print("frictionlab plot: no VTK for Python (Debian: python3-vtk9); lattice figure skipped", file=sys.stderr)
        return
    path = os.path.join(out_dir, "lattice.png")
    try:
        render_lattice(run, path, magnify)
    except NothingToDraw:
        return
    except RenderUnavailable as why:
        print(f"frictionlab plot: VTK cannot render the lattice: {why}; drawn with matplotlib instead", file=sys.stderr)
        write(out_dir, "lattice", lattice, run, None, magnify)
        return
    print(path)


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


def render_grid(grid, title, colour, magnify, path):
    """The PNG `path` rendered by VTK offscreen, under an X display (lattice_grid's grid): the lattice
    warped by its 'deformation' array, coloured by its 'x_velocity' array, axes, a colour bar titled
    `colour`; the PNG says so in its Software text."""
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
        os.makedirs(os.path.dirname(path) or ".", exist_ok=True)
        png = vtk.vtkPNGWriter()
        png.SetInputConnection(image.GetOutputPort())
        png.SetFileName(path)
        png.AddText("Software", f"VTK {vtk.vtkVersion.GetVTKVersion()} offscreen render")
        png.Write()
    finally:
        window.Finalize()  # closes the X connection while its server, perhaps our Xvfb, still runs
