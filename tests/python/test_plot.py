"""The plotting package's figures as a researcher reads them: one time origin, when loading
started, and the events on their own clocks placed on it; titles and labels from the scene; a
figure without the event it draws says so. The package is imported for its rules and run for its
figures, whose SVGs keep their text."""
import os
import shutil

import pytest
import yaml

from conftest import plot_command
from frictionlab.plot import _clock, _labels, _tables, lattice_rendering

SETTLE = 0.003  # the tiny scene's first stage; its driving spring acts in the second


def svg_text(directory, figure):
    with open(os.path.join(directory, figure + ".svg")) as f:
        return f.read()


def test_loading_starts_when_the_loading_stage_does_not_a_sample_later(csv_run):
    assert _clock.loading_start(csv_run.directory) == SETTLE
    curve = _tables.table(csv_run.directory, "loading_curve")
    loading = _clock.from_loading(curve["time"], SETTLE)
    # The row observed at the stage's start is still labelled with the settling stage: the first row
    # labelled with the loading stage is one observation late.
    assert curve["time"][loading][0] == pytest.approx(SETTLE, abs=1e-12)
    assert curve["stage"][loading][0] == 0
    assert curve["time"][curve["stage"] == 1][0] == pytest.approx(SETTLE + 1e-5, abs=1e-12)


def test_loading_starts_in_the_first_stage_a_driving_loader_acts_in(tmp_path):
    stages = [{"name": n, "duration": 0.5} for n in ("settle", "load", "hold")]
    driven = {"stages": stages, "loaders": [{"type": "normal_load"}, {"type": "driving_spring", "stages": ["load"]}]}
    assert _clock.loading_stage(driven) == 1
    assert _clock.loading_stage({"stages": stages, "loaders": [{"type": "plate_springs", "stages": ["hold"]}]}) == 2
    assert _clock.loading_stage({"stages": stages, "loaders": [{"type": "driving_spring"}]}) == 0
    assert _clock.loading_stage({"stages": stages, "loaders": [{"type": "normal_load"}]}) == 2  # none: the last
    assert _clock.loading_stage({"loaders": [{"type": "driving_spring"}]}) is None
    # A run directory whose run.yaml records no stages: the axes count from the run's start, saying so.
    (tmp_path / "run.yaml").write_text("framework: frictionlab\n")
    t0, since = _clock.time_origin(str(tmp_path))
    assert t0 == 0 and since.startswith("the run started") and "unknown" in since


@pytest.fixture(scope="session")
def csv_plots(csv_run, tmp_path_factory):
    """The figures of the tiny run (its multi-run figure elsewhere)."""
    plot_command(csv_run.directory, "-o", str(tmp_path_factory.mktemp("all")))
    return os.path.join(csv_run.directory, "plots")


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


def test_overlaid_loading_curves_are_titled_and_labelled_apart(csv_run, tmp_path):
    runs = [shutil.copytree(csv_run.directory, tmp_path / name) for name in ("a", "b", "c")]
    record = yaml.safe_load(open(runs[1] / "run.yaml"))
    record["scene"]["loaders"][2]["velocity"] = 0.03  # not among the label's facts
    with open(runs[1] / "run.yaml", "w") as f:
        yaml.safe_dump(record, f)
    a, b, c = _labels.run_labels([str(r) for r in runs])
    assert len({a, b, c}) == 3
    assert b.endswith("loaders[2].velocity=0.03")
    assert "loaders[2].velocity=0.02" in a and a.endswith(f"({runs[0]})")  # a and c alike: by directory
    assert c.endswith(f"({runs[2]})")
    plot_command(str(runs[0]), str(runs[1]), "-o", str(tmp_path / "both"))
    both = svg_text(tmp_path / "both", "loading_curves")
    assert "tiny rupture for the Python tests: the loading curves of 2 runs" in both
    assert "loaders[2].velocity=0.03" in both


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
