"""Runs from Python: equal to the command line's, every table in both formats, h5py attributes,
Ctrl-C and the examples."""
import os
import signal
import subprocess
import sys
import time

import h5py
import numpy as np
import pytest
import yaml

import frictionlab
from conftest import HDF5_OVERRIDES, SCENE, run_cli

WALL_CLOCK_KEYS = ("wall_seconds", "cpu_seconds")
# How the run was started differs between a command and a Python call by design.
INVOCATION_KEYS = ("command_line",)


def without_wall_clock(path):
    """A file's bytes; in run.yaml without the wall-clock figures."""
    data = open(path, "rb").read()
    if not path.endswith("run.yaml"):
        return data
    text = data.decode()
    data = yaml.safe_load(text)
    if "command_line" in data:
        data.pop("command_line")
        for k in WALL_CLOCK_KEYS:
            data.pop(k)
        return yaml.safe_dump(data)
    return "".join(line for line in text.splitlines(True) if not line.startswith(WALL_CLOCK_KEYS))


def files_under(directory):
    return sorted(os.path.relpath(os.path.join(d, f), directory) for d, _, fs in os.walk(directory) for f in fs)


@pytest.mark.parametrize("overrides", [[], HDF5_OVERRIDES], ids=["csv", "hdf5"])
def test_a_run_from_python_equals_the_command_lines_byte_for_byte(cli, tmp_path, monkeypatch, overrides):
    (tmp_path / "cli").mkdir()
    (tmp_path / "py").mkdir()
    sets = [a for o in overrides for a in ("--set", o)]
    result = run_cli(cli, "run", "-q", SCENE, "-o", "out", *sets, cwd=tmp_path / "cli")
    assert result.returncode == 0, result.stderr
    monkeypatch.chdir(tmp_path / "py")
    run = frictionlab.Scene.load(SCENE, set=overrides).run(output="out")
    assert run.status == "done"
    cli_out, py_out = tmp_path / "cli" / "out", tmp_path / "py" / "out"
    assert files_under(cli_out) == files_under(py_out)
    for name in files_under(cli_out):
        if name.endswith(".h5"):
            # HDF5 files hold no clock, but compare their contents: the library may order metadata.
            with h5py.File(cli_out / name) as a, h5py.File(py_out / name) as b:
                assert np.array_equal(a["table"][:], b["table"][:], equal_nan=True), name
                assert dict(a.attrs) == dict(b.attrs), name
            continue
        assert without_wall_clock(str(cli_out / name)) == without_wall_clock(str(py_out / name)), name


def test_every_table_reads_the_same_in_both_formats(csv_run, hdf5_run):
    assert csv_run.metadata["scene"]["observers"][3]["format"] == "csv"
    assert hdf5_run.metadata["scene"]["observers"][3]["format"] == "hdf5"
    assert set(csv_run.tables) == set(hdf5_run.tables)
    large = [n for n in csv_run.tables if n.startswith(("interface_", "contact_area", "contact_changes", "precursor"))]
    assert len(large) >= 10, csv_run.tables
    for name in csv_run.tables:
        a, b = csv_run.table(name), hdf5_run.table(name)
        assert b.path.endswith(".h5" if name in large else ".csv"), b.path
        assert a.columns == b.columns, name
        # No block lifts off in this scene: its contact changes are a header without rows.
        assert len(a) == len(b) > 0 or name in ("precursor_fronts", "contact_changes"), name
        # The CSV holds 10 significant digits, the HDF5 table the doubles themselves.
        np.testing.assert_allclose(a.values, b.values, rtol=1e-9, atol=0, equal_nan=True, err_msg=name)
        assert a.provenance["scene_hash"] == csv_run.metadata["scene_hash"]
        assert b.provenance["scene_hash"] == hdf5_run.metadata["scene_hash"]


def test_csv_tables_read_in_one_line_by_numpy_and_pandas(csv_run):
    import pandas

    path = os.path.join(csv_run.directory, "interface_velocity.csv")
    data = np.genfromtxt(path, delimiter=",", names=True)
    frame = pandas.read_csv(path)
    table = csv_run.table("interface_velocity")
    assert list(data.dtype.names) == table.columns == list(frame.columns)
    np.testing.assert_array_equal(frame["block_3"].to_numpy(), table["block_3"])
    meta = yaml.safe_load(open(path + ".meta.yaml"))
    assert meta["columns"] == table.columns
    assert meta["seed"] == 3 and meta["scene_hash"] == csv_run.metadata["scene_hash"]
    # The same provenance record as run.yaml's, under the same names.
    for key in ("framework", "version", "scene_file", "scene_hash", "seed", "plugins"):
        assert meta[key] == csv_run.metadata[key], key
    assert {p.split()[0] for p in meta["plugins"].split(", ")} == {p["name"] for p in csv_run.metadata["plugin_files"]}


def test_frames_give_integers_and_flags_their_types_and_take_an_index(csv_run, hdf5_run):
    import pandas

    for run in (csv_run, hdf5_run):
        events = run.frame("precursors")
        assert len(events) >= 1
        for column in ("event", "nucleation_block", "ruptured_blocks", "out_of_contact"):
            assert events[column].dtype == np.int64, column
        assert events["finished"].dtype == bool and events["global"].dtype == bool
        assert events["t_start"].dtype == np.float64
        assert run.arrays("precursors")["event"].dtype == np.int64
        curve = run.frame("loading_curve", index="time")
        assert curve.index.name == "time" and "time" not in curve.columns
        assert curve.index[-1] == pytest.approx(0.012)
        assert curve["step"].dtype == np.int64 and curve["stage"].dtype == np.int64
        with pytest.raises(KeyError, match="columns"):
            run.frame("loading_curve", index="no_such_column")
    # The integers as pandas.read_csv reads them from the file itself; its other columns are float64
    # whatever their values (pandas reads a column of whole numbers, such as a constant load, as int64).
    path = os.path.join(csv_run.directory, "loading_curve.csv")
    frame, read = csv_run.frame("loading_curve"), pandas.read_csv(path)
    assert (frame["step"].dtype, frame["stage"].dtype) == (read["step"].dtype, read["stage"].dtype)
    assert (frame.dtypes.drop(["step", "stage"]) == np.float64).all()
    pandas.testing.assert_frame_equal(frame, read, check_dtype=False)


def test_hdf5_tables_are_chunked_compressed_and_carry_their_provenance(hdf5_run, csv_run):
    path = os.path.join(hdf5_run.directory, "interface_velocity.h5")
    with h5py.File(path, "r") as f:
        table = f["table"]
        assert table.dtype == np.float64
        assert table.chunks is not None and table.compression == "gzip" and table.shuffle
        assert table.maxshape == (None, table.shape[1])
        assert list(table.attrs["columns"])[:3] == ["time", "time_since_loading", "block_0"]
        assert f.attrs["framework"] == "frictionlab"
        assert f.attrs["scene_hash"] == hdf5_run.metadata["scene_hash"]
        assert f.attrs["seed"] == 3
        assert f.attrs["version"] == frictionlab.version()
        assert "observer_interface_history" in f.attrs["plugins"]
        # time column: every 2e-5 s from 0 to 0.012 s
        np.testing.assert_allclose(table[:, 0], np.arange(601) * 2e-5, atol=1e-12)
    # Compressed: smaller than the CSV of the same numbers.
    assert os.path.getsize(path) < os.path.getsize(os.path.join(csv_run.directory, "interface_velocity.csv"))


def test_open_run_gives_metadata_frames_and_the_vtu_series(csv_run):
    run = frictionlab.open_run(csv_run.directory)
    assert run.metadata["status"] == "done" and run.metadata["seed"] == 3
    frame = run.frame("precursors")
    assert list(frame.columns[:3]) == ["event", "finished", "t_start"] and len(frame) >= 1
    records = run.arrays("loading_curve")
    assert records["time"][-1] == pytest.approx(0.012)
    ((name, files),) = run.series.items()
    assert name == "lattice"
    assert [t for t, _ in files] == pytest.approx([0, 0.003, 0.006, 0.009, 0.012])
    assert all(os.path.exists(f) for _, f in files)
    with pytest.raises(KeyError, match="tables"):
        run.table("no_such_table")


def test_ctrl_c_stops_a_run_from_python_cleanly(tmp_path):
    """SIGINT to a Python process running a long scene: KeyboardInterrupt, closed outputs."""
    out = tmp_path / "out"
    script = (f"import frictionlab\n"
              f"frictionlab.Scene.load({SCENE!r}, set=['stages[1].duration=100'] + {HDF5_OVERRIDES!r})"
              f".run(output={str(out)!r})\n")
    child = subprocess.Popen([sys.executable, "-c", script], stderr=subprocess.PIPE, text=True)
    deadline = time.monotonic() + 120
    # Wait until the run is past its first chunk of history rows (0.02 s simulated).
    while time.monotonic() < deadline and child.poll() is None:
        if (out / "run.yaml").exists() and (out / "loading_curve.csv").exists() and \
                sum(1 for _ in open(out / "loading_curve.csv")) > 2500:
            break
        time.sleep(0.2)
    assert child.poll() is None, child.stderr.read()
    child.send_signal(signal.SIGINT)
    _, stderr = child.communicate(timeout=60)
    assert child.returncode != 0
    assert "KeyboardInterrupt" in stderr, stderr
    meta = yaml.safe_load(open(out / "run.yaml"))
    assert meta["status"] == "interrupted", meta
    assert 0.02 < meta["simulated_time"] < 100
    # The HDF5 tables were closed: every row up to the stop is there.
    with h5py.File(out / "interface_velocity.h5", "r") as f:
        rows = f["table"].shape[0]
    assert rows == pytest.approx(meta["simulated_time"] / 2e-5, abs=2)


def test_a_run_stopped_by_ctrl_c_resumes_from_python_to_the_same_outputs(tmp_path):
    """SIGINT writes a checkpoint; Scene.run(resume=True) goes on from it, and the tables come out as
    an uninterrupted run writes them."""
    overrides = ["stages[1].duration=0.04", "checkpoint={every: 0.001, wall_every: 0}"]
    whole = frictionlab.Scene.load(SCENE, set=overrides).run(output=str(tmp_path / "whole"))
    out = tmp_path / "out"
    script = (f"import frictionlab\n"
              f"frictionlab.Scene.load({SCENE!r}, set={overrides!r}).run(output={str(out)!r})\n")
    child = subprocess.Popen([sys.executable, "-c", script], stderr=subprocess.PIPE, text=True)
    deadline = time.monotonic() + 120
    while time.monotonic() < deadline and child.poll() is None and not (out / "checkpoint.bin").exists():
        time.sleep(0.05)
    assert child.poll() is None, child.stderr.read()
    child.send_signal(signal.SIGINT)
    child.communicate(timeout=60)
    assert yaml.safe_load(open(out / "run.yaml"))["status"] == "interrupted"
    resumed = frictionlab.Scene.load(SCENE, set=overrides).run(output=str(out), resume=True)
    assert yaml.safe_load(open(out / "run.yaml"))["status"] == "done"
    for name in ("loading_curve.csv", "precursors.csv", "interface_velocity.csv"):
        assert open(os.path.join(resumed.directory, name)).read() == \
            open(os.path.join(whole.directory, name)).read(), name


def test_the_theta_sweep_example(tmp_path, source_dir):
    script = os.path.join(source_dir, "share", "examples", "theta_sweep.py")
    result = subprocess.run([sys.executable, script, SCENE, "--theta", "-0.5", "0.5", "--set",
                             "stages[1].duration=0.004", "-o", str(tmp_path)], capture_output=True, text=True)
    assert result.returncode == 0, result.stderr
    assert (tmp_path / "precursors_vs_theta.png").exists()
    rows = (tmp_path / "precursors_vs_theta.csv").read_text().splitlines()
    assert rows[0] == "theta,precursors" and [r.split(",")[0] for r in rows[1:]] == ["-0.5", "0.5"]
    for theta in ("-0.500", "+0.500"):
        meta = yaml.safe_load(open(tmp_path / f"theta_{theta}" / "run.yaml"))
        assert meta["scene"]["loaders"][1]["theta"] == float(theta)


def test_the_rupture_look_example(hdf5_run, csv_run, source_dir, tmp_path):
    script = os.path.join(source_dir, "share", "examples", "rupture_look.py")
    for run in (csv_run, hdf5_run):
        figure = tmp_path / (os.path.basename(os.path.dirname(run.directory)) + ".png")
        result = subprocess.run([sys.executable, script, run.directory, "-o", str(figure)], capture_output=True,
                                text=True)
        assert result.returncode == 0, result.stderr
        assert figure.exists()
