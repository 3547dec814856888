"""frictionlab.plot's lattice rendering: the snapshot around the first global slip, said so in the
title; colour bar labels kept short; drawn with matplotlib onto the Axes it is given, or rendered
by VTK offscreen under a private Xvfb where there is no display, several plots at once."""
import os
import shutil
import subprocess
import sys

import matplotlib.pyplot as plt
import numpy as np
import pytest

import frictionlab.plot
from conftest import plot_command
from frictionlab.plot import _tables, lattice_rendering

SETTLE = 0.003  # the tiny scene's first stage; its driving spring acts in the second
# As on a batch node: no X server, so the lattice is rendered under a private Xvfb.
NO_DISPLAY = {k: v for k, v in os.environ.items() if k != "DISPLAY"}


def test_the_lattice_colour_bar_reads_in_a_unit_that_keeps_its_labels_short():
    assert lattice_rendering.velocity_unit(2.0) == ("m/s", 1.0)
    assert lattice_rendering.velocity_unit(0.5) == ("mm/s", 1e-3)
    assert lattice_rendering.velocity_unit(1.2e-4) == ("µm/s", 1e-6)
    for largest in (1.2e-4, 3e-2, 0.9, 7.0):
        unit, size = lattice_rendering.velocity_unit(largest)
        ticks, number = lattice_rendering.round_ticks(-0.1 * largest / size, largest / size)
        assert max(len(number % t) for t in ticks) <= 5, (largest, [number % t for t in ticks])


def test_the_lattice_says_which_snapshot_it_shows(csv_run, quiet_run):
    events = _tables.table(csv_run.directory, "precursors")
    t_global = events["t_start"][events["global"] > 0.5][0]
    snapshot = lattice_rendering.lattice_snapshot(csv_run.directory)
    assert snapshot[2] == t_global and t_global <= snapshot[1] < t_global + 0.003  # every 3 ms
    title = lattice_rendering.lattice_title(csv_run.directory, snapshot, 0.0, 200)
    assert "the first snapshot after the first global slip started" in title
    # Without a global slip, the last snapshot, and said so: not one around a rupture.
    snapshot = lattice_rendering.lattice_snapshot(quiet_run.directory)
    assert snapshot[2] is None
    title = lattice_rendering.lattice_title(quiet_run.directory, snapshot, 0.0, 200)
    assert "the last snapshot (no global slip in this run before it)" in title
    assert f"lattice at {(0.0035 - SETTLE) * 1e3:.3f} ms after loading started" in title


def test_the_lattice_is_drawn_onto_the_axes_it_is_given_a_cell_a_polygon(csv_run):
    fig, ax = plt.subplots()
    assert frictionlab.plot.lattice(csv_run, ax=ax, magnify=0) is ax
    (cells,) = ax.collections
    scene = csv_run.metadata["scene"]["bulk"]
    assert len(cells.get_paths()) == (scene["nx"] - 1) * (scene["nz"] - 1)
    # Not magnified, the cells are the lattice at rest, in mm.
    corners = np.concatenate([path.vertices for path in cells.get_paths()])
    assert corners[:, 0].min() == pytest.approx(0)
    assert corners[:, 0].max() == pytest.approx(float(scene["length"]) * 1e3)
    assert corners[:, 1].max() - corners[:, 1].min() == pytest.approx(float(scene["height"]) * 1e3)
    assert len(fig.axes) == 2 and fig.axes[1].get_ylabel().startswith("x velocity vₓ (")  # its colour bar
    assert "lattice at" in ax.get_title()
    plt.close(fig)


def test_a_3d_lattice_is_drawn_from_the_side_its_front_face(run_3d):
    # Seen from above, its width would stand where the axes say z.
    fig, ax = plt.subplots()
    frictionlab.plot.lattice(run_3d, ax=ax, magnify=0)
    (cells,) = ax.collections
    bulk = run_3d.metadata["scene"]["bulk"]
    assert len(cells.get_paths()) == (bulk["nx"] - 1) * (bulk["nz"] - 1)  # the faces of its front cubes
    corners = np.concatenate([path.vertices for path in cells.get_paths()])
    assert corners[:, 0].max() - corners[:, 0].min() == pytest.approx(float(bulk["length"]) * 1e3)
    assert corners[:, 1].max() - corners[:, 1].min() == pytest.approx(float(bulk["height"]) * 1e3)
    assert "front face" in ax.get_title()
    plt.close(fig)


def test_the_command_reads_hdf5_runs_and_renders_the_lattice_with_vtk_without_a_display(hdf5_run):
    from PIL import Image  # python3-pil, which python3-matplotlib depends on

    out = os.path.join(hdf5_run.directory, "plots")
    result = plot_command(hdf5_run.directory, env=NO_DISPLAY)
    assert "matplotlib instead" not in result.stderr, result.stderr
    for figure in ("loading_curve", "spacetime", "fronts", "four_phase_3"):
        assert os.path.exists(os.path.join(out, figure + ".png")), (figure, os.listdir(out))
    with Image.open(os.path.join(out, "lattice.png")) as image:
        assert image.format == "PNG"
        assert image.text["Software"].startswith("VTK ") and image.text["Software"].endswith("offscreen render")
        assert 1200 <= image.width <= 1600 and 200 <= image.height <= 1200, image.size
        colours = image.convert("RGB").getcolors(maxcolors=1 << 24)
    assert len(colours) > 1000, len(colours)  # the colour map, the text's anti-aliasing: not a blank render


def test_plots_started_together_each_render_the_lattice_under_their_own_xvfb(hdf5_run, tmp_path):
    # An X server resets when its last client leaves and refuses connections meanwhile; VTK connects
    # twice in a row (SupportsOpenGL, then the render), so without -noreset about half of these failed.
    from PIL import Image

    runs = [shutil.copytree(hdf5_run.directory, tmp_path / f"run{k}") for k in range(4)]
    plots = [subprocess.Popen([sys.executable, "-m", "frictionlab.plot", run], stdout=subprocess.DEVNULL,
                              stderr=subprocess.PIPE, text=True, env=NO_DISPLAY) for run in runs]
    for run, plot in zip(runs, plots):
        stderr = plot.communicate(timeout=300)[1]
        assert plot.returncode == 0, stderr
        assert "matplotlib instead" not in stderr, stderr
        with Image.open(run / "plots" / "lattice.png") as image:
            assert image.text["Software"].endswith("offscreen render")
