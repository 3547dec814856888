"""What frictionlab.plot reads: a run's tables as structured arrays of columns by name (float64,
the declared integers int64 and flags bool), the same from CSV and HDF5 (to the CSV's digits); when loading started, from the stages run.yaml records; a campaign's tables
as rows."""
import os

import numpy as np
import pytest

from frictionlab.plot import _clock, _tables

SETTLE = 0.003  # the tiny scene's first stage; its driving spring acts in the second


def test_a_table_reads_as_typed_columns_by_name_the_same_from_csv_and_hdf5(csv_run, hdf5_run):
    events = _tables.table(csv_run.directory, "precursors")
    with open(os.path.join(csv_run.directory, "precursors.csv")) as f:
        header, first = f.readline().strip().split(","), f.readline().strip().split(",")
    assert list(events.dtype.names) == header
    typed = {"event": np.int64, "nucleation_block": np.int64, "ruptured_blocks": np.int64, "out_of_contact": np.int64,
             "finished": bool, "global": bool}
    assert all(events.dtype[c] == typed.get(c, np.float64) for c in header)
    assert [events[c][0] for c in header] == [float(v) for v in first]
    from_hdf5 = _tables.table(hdf5_run, "precursors")  # a frictionlab.Run does as well as its directory
    assert os.path.exists(os.path.join(hdf5_run.directory, "precursors.h5"))
    assert from_hdf5.dtype == events.dtype
    for c in header:  # the CSV's ten significant digits, the HDF5's every bit
        np.testing.assert_allclose(from_hdf5[c], events[c], rtol=1e-9)


def test_a_table_without_rows_or_without_a_file_is_none(csv_run, tmp_path):
    with open(os.path.join(csv_run.directory, "precursors.csv")) as f:
        (tmp_path / "precursors.csv").write_text(f.readline())
    (tmp_path / "empty.csv").write_text("")
    assert _tables.table(tmp_path, "precursors") is None
    assert _tables.has_table(tmp_path, "precursors"), "its observer ran, and recorded nothing"
    assert _tables.table(tmp_path, "empty") is None
    assert _tables.table(tmp_path, "energy") is None and not _tables.has_table(tmp_path, "energy")


def test_loading_starts_when_the_loading_stage_does_not_a_sample_later(csv_run):
    assert _clock.loading_start(csv_run.directory) == SETTLE
    curve = _tables.table(csv_run.directory, "loading_curve")
    loading = _clock.from_loading(curve["time"], SETTLE)
    # The row observed at the stage's start is still labelled with the settling stage: the first row
    # labelled with the loading stage is one observation late.
    assert curve["time"][loading][0] == pytest.approx(SETTLE, abs=1e-12)
    assert curve["stage"][loading][0] == 0
    assert curve["time"][curve["stage"] == 1][0] == pytest.approx(SETTLE + 1e-5, abs=1e-12)


def test_the_time_origin_is_the_loading_start_run_yaml_records(csv_run, tmp_path):
    assert _clock.time_origin(csv_run.directory) == (SETTLE, "loading started")
    curve = _tables.table(csv_run.directory, "loading_curve")
    np.testing.assert_allclose(curve["time_since_loading"], curve["time"] - SETTLE, rtol=0, atol=1e-10)
    # A run directory whose run.yaml does not record it: the axes count from the run's start, saying so.
    (tmp_path / "run.yaml").write_text("framework: frictionlab\n")
    t0, since = _clock.time_origin(str(tmp_path))
    assert t0 == 0 and since.startswith("the run started") and "unknown" in since


def test_a_campaign_table_reads_as_rows_of_text_without_its_comment_lines(tmp_path):
    (tmp_path / "sweep.csv").write_text("# frictionlab sweep s.yaml\ncase,theta,status\na_seed-1,0.5,done\n"
                                        "b_seed-1,,failed\n")
    rows = _tables.campaign_rows(tmp_path, "sweep.csv")
    assert rows == [{"case": "a_seed-1", "theta": "0.5", "status": "done"},
                    {"case": "b_seed-1", "theta": "", "status": "failed"}]
    assert _tables.number(rows[0]["theta"]) == 0.5 and np.isnan(_tables.number(rows[1]["theta"]))
    assert _tables.sidecar_text(tmp_path, "sweep.csv") == ""
    (tmp_path / "sweep.csv.meta.yaml").write_text("seeds: [1, 2]\n")
    assert _tables.sidecar_text(tmp_path, "sweep.csv") == "seeds: [1, 2]\n"
