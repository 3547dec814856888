"""Scene.load / Scene.from_yaml: the command line's validation, every error with its location."""
import os

import pytest

import frictionlab
from conftest import SCENE


def test_load_reads_the_scene_as_the_command_line_does(cli):
    scene = frictionlab.Scene.load(SCENE)
    assert scene.seed == 3
    assert scene.title == "tiny rupture for the Python tests"
    assert scene.output == "tiny_rupture_out"
    assert len(scene.hash) >= 16
    # The resolved scene has every default written out, e.g. the friction law's mu_s.
    assert "mu_s" in scene.resolved_yaml


def test_from_yaml_reports_every_error_with_file_line_and_column():
    text = open(SCENE).read().replace("nz: 5", "nz: -5").replace("type: rk4", "type: rk5")
    with pytest.raises(frictionlab.SceneError) as caught:
        frictionlab.Scene.from_yaml(text, name="broken.yaml")
    diagnostics = caught.value.diagnostics
    assert len(diagnostics) == 2, str(caught.value)
    lines = text.splitlines()
    by_key = {d.key_path: d for d in diagnostics}
    nz = by_key["bulk.nz"]
    assert nz.file == "broken.yaml"
    assert lines[nz.line - 1][nz.column - 1:].startswith("-5")
    integrator = by_key["integrator.type"]
    assert lines[integrator.line - 1][integrator.column - 1:].startswith("rk5")
    assert "rk4" in integrator.message  # the available types are listed
    # str() is what `frictionlab check` prints.
    assert f"broken.yaml:{nz.line}:{nz.column}: error: bulk.nz:" in str(caught.value)


def test_a_bad_override_points_at_the_command_line_and_matches_check(cli):
    with pytest.raises(frictionlab.SceneError) as caught:
        frictionlab.Scene.load(SCENE, set=["integrator.dt=-1"])
    (d,) = caught.value.diagnostics
    assert d.key_path == "integrator.dt" and d.line == 1 and d.column > 0
    check = __import__("conftest").run_cli(cli, "check", SCENE, "--set", "integrator.dt=-1")
    assert check.returncode == 2
    assert str(d) in check.stderr


def test_a_missing_file_is_a_scene_error():
    with pytest.raises(frictionlab.SceneError) as caught:
        frictionlab.Scene.load("no/such/scene.yaml")
    assert caught.value.diagnostics[0].file == "no/such/scene.yaml"


def test_types_and_doc_are_what_list_and_doc_print(cli):
    # `list`: a line per type (KIND/TYPE and its library), then what it is, indented.
    lines = __import__("conftest").run_cli(cli, "list").stdout.splitlines()
    listed = {line.split()[0]: what.strip() for line, what in zip(lines, lines[1:]) if not line[:1].isspace()}
    types = frictionlab.types()
    assert {f"{t['kind']}/{t['type']}": t["summary"] for t in types} == listed
    normal_load = frictionlab.doc("loader", "normal_load")
    theta = next(p for p in normal_load["params"] if p["key"] == "theta")
    assert theta["unit"] == "1" and theta["default"] == 0
    history = frictionlab.doc("observer", "interface_history")
    fmt = next(p for p in history["params"] if p["key"] == "format")
    assert fmt["choices"] == ["csv", "hdf5"]
    with pytest.raises(frictionlab.InputError, match="available"):
        frictionlab.doc("loader", "no_such_loader")


def test_help_is_useful():
    assert "SceneError" in frictionlab.Scene.__doc__
    assert "Ctrl-C" in frictionlab.Scene.run.__doc__
    stub = os.path.join(os.path.dirname(frictionlab.__file__), "__init__.pyi")
    assert "def open_run" in open(stub).read()
