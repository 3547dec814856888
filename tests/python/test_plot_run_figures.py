"""frictionlab.plot's run figures as a researcher reads them: each draws the run's data onto the Axes
it is given; one time origin, when loading started, and the events on their own clocks placed on
it; titles and labels from the scene; a figure without the event it draws says so. The command's
files are read for their text, which the SVGs keep."""
import os
import shutil

import matplotlib.pyplot as plt
import numpy as np
import pytest
import yaml

import frictionlab.plot
from conftest import plot_command
from frictionlab.plot import _clock, _labels, _tables

SETTLE = 0.003  # the tiny scene's first stage; its driving spring acts in the second


@pytest.fixture
def figure():
    """A figure for a test to draw on, closed afterwards."""
    fig = plt.figure()
    yield fig
    plt.close(fig)


def svg_text(directory, figure):
    with open(os.path.join(directory, figure + ".svg")) as f:
        return f.read()


def test_the_loading_curve_is_the_driving_force_from_when_loading_started(csv_run, figure):
    ax = figure.add_subplot()
    assert frictionlab.plot.loading_curve(csv_run, ax=ax) is ax
    curve = _tables.table(csv_run, "loading_curve")
    loading = _clock.from_loading(curve["time"], SETTLE)
    force, precursors, global_slips = ax.lines
    np.testing.assert_array_equal(force.get_xdata(), curve["time"][loading] - SETTLE)
    np.testing.assert_array_equal(force.get_ydata(), curve["driving_force"][loading])
    events = _tables.table(csv_run, "precursors")
    assert len(global_slips.get_xdata()) == np.count_nonzero(events["global"] > 0.5) >= 1
    assert len(precursors.get_xdata()) + len(global_slips.get_xdata()) == len(events)
    assert ax.get_xlabel() == "time since loading started (s)"
    assert ax.get_title().startswith("tiny rupture for the Python tests\n")
    assert figure.axes == [ax]


def test_the_event_lengths_stand_at_each_events_start(csv_run, figure):
    ax = frictionlab.plot.event_lengths(csv_run.directory, ax=figure.add_subplot())
    events = _tables.table(csv_run, "precursors")
    segments = ax.collections[0].get_segments()
    assert [s[0][0] for s in segments] == pytest.approx(events["t_start"] - SETTLE)
    assert [s[1][1] for s in segments] == pytest.approx(events["extent_over_length"])
    assert ax.get_ylim() == (0, 1.05)


def test_without_axes_a_figure_draws_a_figure_of_its_own_and_without_its_table_nothing(csv_run, tmp_path):
    ax = frictionlab.plot.fronts(csv_run)
    assert ax.figure.get_size_inches().tolist() == [7, 4.5]
    plt.close(ax.figure)
    run = shutil.copytree(csv_run.directory, tmp_path / "run")
    os.remove(run / "precursors.csv")
    figures = plt.get_fignums()
    with pytest.raises(frictionlab.plot.NothingToDraw):
        frictionlab.plot.fronts(run)
    with pytest.raises(frictionlab.plot.NothingToDraw):
        frictionlab.plot.energy(run)  # the tiny scene has no energy observer
    assert plt.get_fignums() == figures


def test_the_four_phases_are_on_the_clock_of_the_blocks_detachment(csv_run, figure):
    axes = figure.subplots(4, 1, sharex=True)
    assert list(frictionlab.plot.four_phase(csv_run, 3, axes=axes)) == list(axes)
    assert [line.get_label() for line in axes[0].lines] == [r"$\tilde N_p$", "pinned", "sliding", "dislocated"]
    block = _tables.table(csv_run, "contact_area_block_3")
    detached = block["time"][(block["time"] >= SETTLE) & (block["pinned_fraction"] < 0.5)][0]
    t = axes[1].lines[0].get_xdata()  # ms since detachment
    assert t.min() > -0.5 and t.max() < 4 and 0 in t
    assert axes[1].lines[0].get_ydata()[0] == 0, "the slip counts from the window's start"
    assert axes[0].texts[0].get_text() == "I"  # the phases the data reach, named above
    assert f"detachment at {(detached - SETTLE) * 1e3:.2f} ms after loading started" in axes[3].get_xlabel()


def test_the_spacetime_images_are_blocks_against_time(csv_run, figure):
    axes = frictionlab.plot.spacetime(csv_run, axes=figure.subplots(2, 1, sharex=True))
    velocity = _tables.table(csv_run, "interface_velocity")
    blocks = [n for n in velocity.dtype.names if n.startswith("block_")]
    image = axes[0].images[0]
    assert image.get_array().shape == (len(blocks), len(velocity))
    np.testing.assert_allclose(image.get_array()[5], np.log10(np.abs(velocity["block_5"]) + 1e-9))
    assert image.get_extent()[:2] == [velocity["time"][0] - SETTLE, velocity["time"][-1] - SETTLE]
    pinned = axes[1].images[0].get_array()
    assert pinned.min() >= 0 and pinned.max() <= 1
    assert len(figure.axes) == 4  # with a colour bar each


def test_runs_overlaid_on_one_axes_are_labelled_apart(csv_run, hdf5_run, figure):
    left, right = figure.subplots(1, 2)
    frictionlab.plot.precursor_lengths([csv_run, hdf5_run], ax=left)
    assert len(left.lines) == 2
    for line, run in zip(left.lines, (csv_run, hdf5_run)):
        events = _tables.table(run, "precursors")
        np.testing.assert_array_equal(line.get_xdata(), events["force_ratio"])
        np.testing.assert_array_equal(line.get_ydata(), events["extent_over_length"])
    frictionlab.plot.loading_curves([csv_run, hdf5_run], ax=right)
    csv_label, hdf5_label = [text.get_text() for text in right.get_legend().get_texts()]
    # The same physics written in two formats: told apart by directory, not by an output key.
    assert (csv_label, hdf5_label) == (csv_run.directory, hdf5_run.directory)
    assert right.get_title() == "tiny rupture for the Python tests: the loading curves of 2 runs"


@pytest.fixture(scope="session")
def csv_plots(csv_run, tmp_path_factory):
    """The figures of the tiny run, as the command writes them (its multi-run figure elsewhere)."""
    plot_command(csv_run.directory, "-o", str(tmp_path_factory.mktemp("all")))
    return os.path.join(csv_run.directory, "plots")


def test_the_command_writes_every_figure_the_run_allows(csv_plots):
    figures = ("loading_curve", "four_phase_3", "spacetime", "fronts")  # no energy observer
    assert sorted(os.listdir(csv_plots)) == sorted([f"{f}.{ext}" for f in figures for ext in ("png", "svg")]
                                                   + ["lattice.png"])


def test_the_event_figures_place_their_event_on_the_loading_clock(csv_run, csv_plots):
    four_phase = svg_text(csv_plots, "four_phase_3")
    block = _tables.table(csv_run.directory, "contact_area_block_3")
    detached = block["time"][(block["time"] >= SETTLE) & (block["pinned_fraction"] < 0.5)][0]
    assert f"time since detachment (ms); detachment at {(detached - SETTLE) * 1e3:.2f} ms after loading started" \
        in four_phase
    fronts = svg_text(csv_plots, "fronts")
    assert "nucleation, ms after loading started" in fronts
    assert fronts.count("m/s (lattice)") == 2  # c_S and c_R
    events = _tables.table(csv_run.directory, "precursors")
    first = (events["t_start"][0] - SETTLE) * 1e3
    assert f"at {first:.2f} ms" in fronts


def test_figures_of_a_run_without_rupture_events_say_so(quiet_run):
    assert _tables.table(quiet_run.directory, "precursors") is None
    plot_command(quiet_run.directory)
    plots = os.path.join(quiet_run.directory, "plots")
    assert "no rupture event reached this block in this run" in svg_text(plots, "four_phase_3")
    fronts = svg_text(plots, "fronts")
    assert "no rupture event in this run (the precursors observer recorded none)" in fronts
    assert fronts.count("m/s (lattice)") == 2, "the wave speeds are the lattice's, events or not"
    assert "the precursors observer recorded none" in svg_text(plots, "loading_curve")


def test_without_a_precursors_observer_the_loading_curve_says_that_instead(csv_run, tmp_path):
    run = shutil.copytree(csv_run.directory, tmp_path / "run")
    os.remove(run / "precursors.csv")
    assert _labels.no_events_note(str(run)) == "no rupture events recorded (no precursors observer)"
    assert _labels.no_events_note(csv_run.directory).endswith("(the precursors observer recorded none)")


def test_a_figure_of_one_event_names_the_scene_it_comes_from(csv_plots):
    assert "tiny rupture for the Python tests" in svg_text(csv_plots, "four_phase_3")  # the scene's title


def test_overlaid_loading_curves_are_titled_and_labelled_by_the_physics_that_differs(csv_run, tmp_path):
    runs = [shutil.copytree(csv_run.directory, tmp_path / name) for name in ("a", "b", "c")]
    record = yaml.safe_load(open(runs[1] / "run.yaml"))
    record["scene"]["loaders"][2]["velocity"] = 0.03
    record["scene"]["output"] = "elsewhere"  # where a run writes tells nothing of its physics
    record["scene"]["checkpoint"] = {"every": 1.0e-3}
    with open(runs[1] / "run.yaml", "w") as f:
        yaml.safe_dump(record, f)
    a, b, c = _labels.run_labels([str(r) for r in runs])
    assert b == "$V$ = 0.03 m/s"  # the symbol and unit; not the output nor the checkpoint
    assert a == f"$V$ = 0.02 m/s ({runs[0]})"  # a and c alike: by directory
    assert c == f"$V$ = 0.02 m/s ({runs[2]})"
    plot_command(str(runs[0]), str(runs[1]), "-o", str(tmp_path / "both"))
    both = svg_text(tmp_path / "both", "loading_curves")
    assert "tiny rupture for the Python tests: the loading curves of 2 runs" in both
    assert "= 0.03 m/s" in both and "checkpoint" not in both and "output" not in both


def test_overlays_tell_seeds_apart_by_line_style_and_marker(csv_run, tmp_path):
    runs = [shutil.copytree(csv_run.directory, tmp_path / name) for name in ("one", "two")]
    record = yaml.safe_load(open(runs[1] / "run.yaml"))
    record["scene"]["seed"] = 7
    with open(runs[1] / "run.yaml", "w") as f:
        yaml.safe_dump(record, f)
    assert _labels.run_labels([str(r) for r in runs])[1] == "seed 7"
    first, second = frictionlab.plot.loading_curves([str(r) for r in runs]).lines
    assert first.get_linestyle() != second.get_linestyle()
    first, second = frictionlab.plot.precursor_lengths([str(r) for r in runs]).lines
    assert first.get_marker() != second.get_marker()
