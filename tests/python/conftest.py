"""Shared fixtures: the build's command line, the tiny scene, and one run of it in each format.

ctest sets FRICTIONLAB_CLI (the frictionlab executable) and FRICTIONLAB_SOURCE_DIR, and puts
build/python first on PYTHONPATH."""
import os
import shutil
import subprocess

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


def run_cli(cli, *args, cwd=None):
    return subprocess.run([cli, *args], cwd=cwd, capture_output=True, text=True)
