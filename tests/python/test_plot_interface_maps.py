"""frictionlab.plot's maps of a 3D run's interface: one map of the blocks' slip speed over x and y per
lattice snapshot, up to the fastest one, on one logarithmic scale; a 2D run's interface is a line
and has none."""
import os

import matplotlib.pyplot as plt
import numpy as np
import pytest

from conftest import plot_command
from frictionlab.plot import NothingToDraw, interface_maps
from frictionlab.plot._clock import time_origin
from frictionlab.plot.interface_figures import STILL, interface_series


def test_each_map_is_the_interface_over_x_and_y_up_to_the_fastest_snapshot(run_3d):
    times, x, y, speeds = interface_series(run_3d)
    bulk = run_3d.metadata["scene"]["bulk"]
    assert len(x) == bulk["nx"] * bulk["ny"] and speeds.shape == (len(times), len(x))
    assert np.unique(y).size == bulk["ny"] and np.ptp(y) == pytest.approx(float(bulk["width"]))
    fastest = int(np.argmax(speeds.mean(axis=1)))
    axes = interface_maps(run_3d)
    assert len(axes) == min(6, fastest + 1)
    for ax in axes:
        (mesh,) = ax.collections
        assert mesh.get_array().size == bulk["ny"] * bulk["nx"]  # a cell per block
    # The last map is the fastest snapshot, its speeds as the series gives them (at least STILL).
    np.testing.assert_allclose(np.sort(axes[-1].collections[0].get_array().ravel()),
                               np.sort(np.maximum(speeds[fastest], STILL)))
    assert axes[-1].get_xlabel() == "x (mm)" and "ms after loading started" in axes[-1].get_title(loc="left")
    plt.close(axes[0].figure)


def test_until_a_time_the_maps_end_at_the_last_snapshot_by_then(run_3d):
    times, _, _, speeds = interface_series(run_3d)
    t0, _ = time_origin(run_3d)  # the series' times are on the run's clock
    until = times[2] - t0 + 1e-9  # just after the third snapshot, in time since loading
    axes = interface_maps(run_3d, maps=2, until=until)
    assert len(axes) == 2
    np.testing.assert_allclose(np.sort(axes[-1].collections[0].get_array().ravel()),
                               np.sort(np.maximum(speeds[2], STILL)))
    assert f"up to {until * 1e3:g} ms after loading started" in axes[0].figure._suptitle.get_text()
    plt.close(axes[0].figure)
    with pytest.raises(NothingToDraw, match="no snapshot by"):
        interface_maps(run_3d, until=-1.0)


def test_a_2d_run_has_no_interface_maps(csv_run):
    with pytest.raises(NothingToDraw, match="a line"):
        interface_maps(csv_run)


def test_the_command_draws_them_for_a_3d_run(run_3d):
    plot_command(run_3d.directory)
    out = os.path.join(run_3d.directory, "plots")
    for ext in ("png", "svg"):
        assert os.path.exists(os.path.join(out, "interface." + ext)), os.listdir(out)
    assert os.path.exists(os.path.join(out, "loading_curve.png"))


def test_a_wide_interfaces_maps_fill_a_grid_row_by_row(run_3d, monkeypatch):
    # The tiny slider's snapshots, redrawn on an interface as wide as it is long: 21 x 21 blocks.
    times, _, _, speeds = interface_series(run_3d)
    grid = np.arange(21) * 0.005
    x, y = (a.ravel() for a in np.meshgrid(grid, grid))
    wide = np.tile(speeds[:, :1], (1, x.size)) * (1 + x / 0.1)  # faster towards the leading edge
    monkeypatch.setattr("frictionlab.plot.interface_figures.interface_series", lambda run: (times, x, y, wide))
    axes = interface_maps(run_3d, maps=5)
    assert len(axes) == 5 and len(axes[0].figure.axes) == 5 + 1  # the maps and the colour bar, no empty panel
    corners = [ax.get_position() for ax in axes]  # 3 columns, 2 rows: the first row full
    assert corners[0].y0 == pytest.approx(corners[2].y0) and corners[3].y0 < corners[0].y0
    assert corners[3].x0 == pytest.approx(corners[0].x0) and corners[1].x0 > corners[0].x0
    assert [ax.get_ylabel() for ax in axes] == ["y (mm)", "", "", "y (mm)", ""]
    assert [ax.get_xlabel() for ax in axes] == ["", "", "x (mm)", "x (mm)", "x (mm)"]  # nothing below them
    width, height = axes[0].figure.get_size_inches()
    assert height < 2 * width  # where one column of five square maps would be five times as tall
    plt.close(axes[0].figure)


def test_the_slipping_patch_is_the_blocks_each_snapshot_shows_slipping(run_3d):
    import xml.etree.ElementTree as ElementTree
    from vtkmodules.util.numpy_support import vtk_to_numpy
    from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader

    from frictionlab.plot.interface_figures import slipping_patch

    patch = slipping_patch(run_3d)
    times, x, y, _ = interface_series(run_3d)
    np.testing.assert_array_equal(patch["time"], times)
    busiest = int(np.argmax(patch["blocks"]))
    assert patch["blocks"][busiest] > 1, "the tiny slider slips somewhere"
    # That snapshot read here with VTK: its interface nodes (those with a friction force) that slip.
    pvd = os.path.join(run_3d.directory, "lattice.pvd")
    files = [d.get("file") for d in ElementTree.parse(pvd).getroot().iter("DataSet")]
    reader = vtkXMLUnstructuredGridReader()
    reader.SetFileName(os.path.join(run_3d.directory, files[busiest]))
    reader.Update()
    data = reader.GetOutput().GetPointData()
    on = ~np.isnan(vtk_to_numpy(data.GetArray("friction_force")))
    slipping = vtk_to_numpy(data.GetArray("slipping"))[on] > 0.5
    velocity = vtk_to_numpy(data.GetArray("velocity"))[on]
    row = patch[busiest]
    assert row["blocks"] == slipping.sum()
    assert row["along"] == pytest.approx(np.ptp(x[slipping])) and row["across"] == pytest.approx(np.ptp(y[slipping]))
    assert row["speed"] == pytest.approx(np.hypot(velocity[slipping, 0], velocity[slipping, 1]).mean())
    assert np.isnan(row["slip"]) and data.GetArray("slip") is None  # Coulomb publishes no slip
    still = patch["blocks"] == 0
    assert np.isnan(patch["along"][still]).all() and np.isnan(patch["speed"][still]).all()


def test_a_2d_run_has_no_slipping_patch(csv_run):
    from frictionlab.plot.interface_figures import slipping_patch

    with pytest.raises(NothingToDraw):
        slipping_patch(csv_run)
