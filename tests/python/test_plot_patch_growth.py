"""frictionlab.plot's growth of a 3D run's rupture patches: each event's area and extents along and
across against the time since it started, from its blocks' first ruptures; a 2D run's events are
lines and have none."""
import matplotlib.pyplot as plt
import numpy as np
import pytest

from frictionlab.plot import NothingToDraw, patch_growth
from frictionlab.plot.patch_figures import patch_growth_series


def test_each_events_area_and_extents_grow_to_what_its_row_says(run_3d):
    series = patch_growth_series(run_3d)
    events = run_3d.table("precursors")
    assert sorted(series) == sorted(int(e) for e in events["event"])
    for k, event in enumerate(events["event"]):
        delays, area, along, across = series[int(event)]
        assert np.all(np.diff(delays) > 0) and np.all(np.diff(area) >= 0)
        assert np.all(np.diff(along) >= 0) and np.all(np.diff(across) >= 0)
        # Its last state is the event's: the blocks of its extent (and its nucleation block).
        assert area[-1] == pytest.approx(events["area_fraction"][k], abs=1e-12)
        assert along[-1] == pytest.approx(events["max_ruptured_x"][k] - events["min_ruptured_x"][k], abs=1e-12)
        assert across[-1] == pytest.approx(events["max_ruptured_y"][k] - events["min_ruptured_y"][k], abs=1e-12)
    top, bottom = patch_growth(run_3d)
    assert len(top.lines) >= min(4, len(series)) and bottom.get_ylabel() == "extent (mm)"
    plt.close(top.figure)


def test_a_2d_run_has_no_patches(csv_run):
    with pytest.raises(NothingToDraw):
        patch_growth(csv_run)
