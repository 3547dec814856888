"""Shared fixtures: the build's command line, the tiny scene, one run of it in each format and one
stopped before its first rupture, and the plotting package's command line.

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


def plot_command(*arguments, env=None):
    """python3 -m frictionlab.plot ARGUMENTS, which `frictionlab plot` runs; its result, checked."""
    result = subprocess.run([sys.executable, "-m", "frictionlab.plot", *arguments], capture_output=True, text=True,
                            env=env)
    assert result.returncode == 0, result.stderr
    return result


def run_cli(cli, *args, cwd=None):
    return subprocess.run([cli, *args], cwd=cwd, capture_output=True, text=True)
