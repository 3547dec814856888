"""Rupture events of a 3D run: on its 2D interface each event is a connected region in x, y and time,
and precursors.csv gives, after the columns a 2D run has, where it nucleated across, its extent
across and its share of the interface's area; precursor_fronts.csv each block's y."""
import numpy as np
import pytest
import yaml


def test_a_3d_runs_events_are_measured_across_its_width_and_checked(run_3d):
    events = run_3d.table("precursors")
    across = ["nucleation_y", "min_ruptured_y", "max_ruptured_y", "extent_across", "area_fraction"]
    assert events.columns[-len(across):] == across
    width = float(run_3d.metadata["scene"]["bulk"]["width"])
    assert len(events) >= 2
    # The slider is driven uniformly across its width: each global slip covers the whole interface.
    for k in np.flatnonzero(events["global"] == 1):
        assert events["area_fraction"][k] == 1.0 and events["extent_across"][k] == pytest.approx(width)
        assert events["min_ruptured_y"][k] == 0 and events["max_ruptured_y"][k] == pytest.approx(width)
    assert np.all((events["nucleation_y"] >= 0) & (events["nucleation_y"] <= width))
    fronts = run_3d.table("precursor_fronts")
    assert fronts.columns[-1] == "y" and np.unique(fronts["y"]).size == run_3d.metadata["scene"]["bulk"]["ny"]
    # Every drop of the loading curve is matched by exactly one global slip (this fast-driven slider's
    # slips start more than 5 % below their peaks, which the check reports: theory.md §5a).
    with open(f"{run_3d.directory}/precursors_summary.yaml") as f:
        check = yaml.safe_load(f)["event_check"]
    globals_ = sorted(int(k) for k in np.flatnonzero(events["global"] == 1))
    assert sorted(d["global_slip_event"] for d in check["falls"] if d["drop"]) == globals_
