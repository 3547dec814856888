"""Shared fixtures: the build's command line, the tiny scene, one run of it in each format and one
stopped before its first rupture, a run of a tiny 3D slider, a real small sweep and ensemble study, and the plotting package's
command line.

ctest sets FRICTIONLAB_CLI (the frictionlab executable) and FRICTIONLAB_SOURCE_DIR, and puts
build/python first on PYTHONPATH."""
import os
import shutil
import subprocess
import sys

import pytest

import frictionlab

HERE = os.path.dirname(os.path.abspath(__file__))
SCENE = os.path.join(HERE, "scenes", "tiny_rupture.yaml")
# The table observers of the tiny scene, by position in its `observers:` list.
HDF5_OVERRIDES = [f"observers[{i}].format=hdf5" for i in (1, 2, 3)]


@pytest.fixture(scope="session")
def cli():
    path = os.environ.get("FRICTIONLAB_CLI") or shutil.which("frictionlab")
    assert path, "set FRICTIONLAB_CLI to the frictionlab executable"
    return path


@pytest.fixture(scope="session")
def source_dir():
    return os.environ.get("FRICTIONLAB_SOURCE_DIR", os.path.dirname(os.path.dirname(HERE)))


@pytest.fixture(scope="session")
def csv_run(tmp_path_factory):
    out = tmp_path_factory.mktemp("csv") / "out"
    return frictionlab.Scene.load(SCENE).run(output=str(out))


@pytest.fixture(scope="session")
def hdf5_run(tmp_path_factory):
    out = tmp_path_factory.mktemp("hdf5") / "out"
    return frictionlab.Scene.load(SCENE, set=HDF5_OVERRIDES).run(output=str(out))


@pytest.fixture(scope="session")
def quiet_run(tmp_path_factory):
    """The tiny scene loaded for half a millisecond: no rupture event yet."""
    out = tmp_path_factory.mktemp("quiet") / "out"
    return frictionlab.Scene.load(SCENE, set=["stages[1].duration=5.0e-4"]).run(output=str(out))


@pytest.fixture(scope="session")
def run_3d(tmp_path_factory):
    """The tiny 3D slider (scenes/tiny_slider_3d.yaml): Coulomb friction on a 21 x 3 interface."""
    out = tmp_path_factory.mktemp("slider_3d") / "out"
    return frictionlab.Scene.load(os.path.join(HERE, "scenes", "tiny_slider_3d.yaml")).run(output=str(out))


@pytest.fixture(scope="session")
def real_sweep(cli, source_dir, tmp_path_factory):
    """tests/campaign/sweep/tiny_sweep.yaml run here: two loading rates x seeds 1 and 2, drawn by
    `frictionlab plot DIR`."""
    out = tmp_path_factory.mktemp("sweep") / "out"
    sweep = os.path.join(source_dir, "tests", "campaign", "sweep", "tiny_sweep.yaml")
    for args in (["sweep", "-q", sweep, "-o", str(out)], ["plot", str(out)]):
        result = subprocess.run([cli, *args], capture_output=True, text=True)
        assert result.returncode == 0, result.stdout + result.stderr
    return str(out)


@pytest.fixture(scope="session")
def real_study(cli, source_dir, tmp_path_factory):
    """An ensemble study of tests/campaign/study/tiny_scene.yaml over two seeds run here: the reference
    (RK4 at 0.2 us), the same at half its step, and at twice it. `frictionlab study` draws its figures."""
    folder = tmp_path_factory.mktemp("study")
    scene = os.path.join(source_dir, "tests", "campaign", "study", "tiny_scene.yaml")
    (folder / "study.yaml").write_text(
        f"title: tiny ensemble figures\nscene: {scene}\n"
        "observe_every: 1.0e-5\nprofile_every: 1.0e-4\nseeds: 2\n"
        "reference:\n  set: [integrator.dt=2.0e-7]\nhalf_step:\n  set: [integrator.dt=1.0e-7]\n"
        "cases:\n  - name: rk4_coarse\n    set: [integrator.dt=4.0e-7]\n")
    result = subprocess.run([cli, "study", "-q", "-j", "2", str(folder / "study.yaml"), "-o", str(folder / "out")],
                            capture_output=True, text=True)
    assert result.returncode == 0, result.stdout + result.stderr
    return str(folder / "out")


def plot_command(*arguments, env=None):
    """python3 -m frictionlab.plot ARGUMENTS, which `frictionlab plot` runs; its result, checked."""
    result = subprocess.run([sys.executable, "-m", "frictionlab.plot", *arguments], capture_output=True, text=True,
                            env=env)
    assert result.returncode == 0, result.stderr
    return result


def run_cli(cli, *args, cwd=None):
    return subprocess.run([cli, *args], cwd=cwd, capture_output=True, text=True)
