"""Every CSV table the project writes reads at the common tools' defaults: pandas.read_csv and
numpy.genfromtxt(names=True) see one header line and its rows (provenance is in the sidecar,
NAME.csv.meta.yaml), and pandas gives the columns the sidecar declares integer as int64 and those it
declares flags as 0/1; the Python module gives the same columns as int64 and bool.

The tables are those of a real run (every observer of the tiny scene), a real sweep over seeds and a
real ensemble study."""
import glob
import os

import numpy as np
import pandas as pd
import pytest
import yaml

import frictionlab


def csv_files(directory):
    return sorted(glob.glob(os.path.join(directory, "**", "*.csv"), recursive=True))


def sidecar(path):
    with open(path + ".meta.yaml") as f:
        return yaml.safe_load(f)


def header(path):
    with open(path) as f:
        return f.readline().rstrip("\n").split(",")


def check_table(path):
    columns = header(path)
    frame = pd.read_csv(path)
    assert list(frame.columns) == columns, path
    with open(path) as f:
        assert len(frame) == sum(1 for _ in f) - 1, f"{path}: a row pandas did not see as one"
    numeric = np.genfromtxt(path, delimiter=",", names=True)
    assert len(numeric.dtype.names) == len(columns), path
    assert numeric.size == len(frame) or (len(frame) == 0 and numeric.size in (0, 1)), path
    meta = sidecar(path)
    assert meta["framework"] == "frictionlab" and "version" in meta, path
    # Every column's unit, as text ("1" for a pure number, "" only for a column of text).
    assert list(meta["units"]) == columns, path
    assert all(isinstance(unit, str) for unit in meta["units"].values()), path
    if frame.empty:  # pandas types no column of an empty table
        return frame
    for column in meta.get("integer_columns", []):
        if not frame[column].isna().any():
            assert frame[column].dtype == np.int64, f"{path}: {column} is {frame[column].dtype}"
    for column in meta.get("flag_columns", []):
        assert set(frame[column].dropna().unique()) <= {0, 1}, f"{path}: {column}"
    return frame


def test_every_table_of_a_run_reads_as_one_header_and_its_rows_typed_as_declared(csv_run):
    paths = csv_files(csv_run.directory)
    assert {"loading_curve", "precursors", "precursor_fronts", "contact_changes"} <= \
        {os.path.basename(p)[:-4] for p in paths}
    for path in paths:
        frame = check_table(path)
        assert frame.empty or all(np.issubdtype(t, np.number) for t in frame.dtypes), f"{path}: not all numbers"


def test_the_python_module_types_integer_and_flag_columns_as_pandas_does(csv_run):
    events = csv_run.frame("precursors")
    read = pd.read_csv(os.path.join(csv_run.directory, "precursors.csv"))
    assert len(events) > 0, "the tiny scene has rupture events"
    for column in ("event", "nucleation_block", "ruptured_blocks"):
        assert events[column].dtype == np.int64 and read[column].dtype == np.int64, column
        np.testing.assert_array_equal(events[column], read[column])
    for column in ("finished", "global"):
        assert events[column].dtype == bool, column
        np.testing.assert_array_equal(events[column], read[column].astype(bool))
    curve = csv_run.frame("loading_curve", index="time")
    assert curve.index.name == "time" and curve.index.is_monotonic_increasing


def test_every_column_of_a_run_has_its_unit_in_the_module_as_in_the_sidecar(csv_run, hdf5_run):
    table = csv_run.table("precursors")
    assert table.units["t_start"] == table.units["t_start_since_loading"] == "s"
    assert table.units["driving_force"] == "N" and table.units["front_speed"] == "m/s"
    assert table.units["global"] == "1" and table.units["nucleation_x"] == "m"
    assert csv_run.table("loading_curve").units["driving_force_over_normal_load"] == "1"
    for run in (csv_run, hdf5_run):
        for name in run.tables:
            t = run.table(name)
            assert set(t.units) == set(t.columns) and all(t.units.values()), (run.directory, name)
    # HDF5 keeps them as the dataset's attribute, aligned with its columns.
    assert hdf5_run.table("precursors").units == csv_run.table("precursors").units


@pytest.mark.parametrize("campaign", ["real_sweep", "real_study"])
def test_every_table_of_a_campaign_reads_as_one_header_and_its_rows(campaign, request):
    directory = request.getfixturevalue(campaign)
    own = [p for p in csv_files(directory) if os.sep + "cases" + os.sep not in p]
    names = {os.path.basename(p) for p in own}
    assert names >= ({"sweep.csv", "events.csv", "run_statistics.csv", "sweep_statistics.csv"} if campaign == "real_sweep"
                     else {"study.csv", "ensemble.csv"}), names
    for path in own:
        frame = check_table(path)
        assert len(frame) > 0, path
        meta = sidecar(path)  # what wrote it, and each column's unit
        assert "title" in meta and meta["columns"] == list(frame.columns), path
        assert set(meta["units"]) == set(frame.columns), path
    for path in csv_files(os.path.join(directory, "cases")):  # each case's run tables
        check_table(path)


def test_a_run_opened_from_disk_gives_the_same_typed_frame(csv_run):
    again = frictionlab.open_run(csv_run.directory).frame("precursors")
    pd.testing.assert_frame_equal(again, csv_run.frame("precursors"))
