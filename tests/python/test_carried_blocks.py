"""A generated block is carried over a change that moves no output (frictionlab.carried_blocks): its
text kept, its stamp this tree's with the commit it was made at and the cases checked; and refused,
changing nothing, when a case run again wrote anything else."""
import os
import re
import subprocess

import pytest

from frictionlab import carried_blocks, doc_blocks


def sweep(folder, loading_curve="time,driving_force\n0,0\n1,2\n", wall=1.0, scene_hash="0713c9b9a5ed576d",
          load="{type: normal_load, total_force: 400}", threads=1, cases=("base_seed-1", "base_seed-2")):
    """A sweep of two cases (or `cases`), each with a table, its record of the scene hash, and a run record."""
    for case in cases:
        os.makedirs(os.path.join(folder, "cases", case, "logs"))
        with open(os.path.join(folder, "cases", case, "loading_curve.csv"), "w") as f:
            f.write(loading_curve)
        with open(os.path.join(folder, "cases", case, "loading_curve.csv.meta.yaml"), "w") as f:
            f.write(f"scene_hash: {scene_hash}\ncolumns: [time, driving_force]\n")
        with open(os.path.join(folder, "cases", case, "run.yaml"), "w") as f:
            f.write(f"scene_hash: {scene_hash}\nseed: 1\nsteps: 10\nwall_seconds: {wall}\nthreads: {threads}\n"
                    f"command_line: [{folder}]\nscene:\n  output: {folder}\n  loaders:\n    - {load}\n")
        with open(os.path.join(folder, "cases", case, "logs", "run.log"), "w") as f:
            f.write(f"took {wall} s\n")
    return folder


def source_tree(root):
    """The core, one law plugin (type `law`) and the li2020 campaign scene that names it."""
    for folder in ("core/src", "plugins/law", "configs/li2020"):
        (root / folder).mkdir(parents=True)
    (root / "CMakeLists.txt").write_text("project(x)\n")
    (root / "plugins/law/law.hpp").write_text('struct Law { static constexpr std::string_view type = "law"; };\n')
    (root / "plugins/law/law.cpp").write_text("double force(double x) { return 2 * x; }\n")
    (root / "configs/li2020/campaign_scene.yaml").write_text("friction: {type: law}\n")


@pytest.fixture
def tree(tmp_path):
    """A source tree whose README holds a stamped block, then a change of code."""
    source_tree(tmp_path)
    (tmp_path / "README.md").write_text("<!-- li2020-claims -->\n- 2.81 per unit theta\n<!-- /li2020-claims -->\n")
    doc_blocks.replace_block(str(tmp_path / "README.md"), "li2020-claims", "- 2.81 per unit theta\n", ["a1", "b2"], "1-2")
    (tmp_path / "plugins/law/law.cpp").write_text("double force(double x) { return x + x; }\n")
    return tmp_path


def test_a_block_whose_runs_wrote_the_same_is_carried_with_what_was_checked(tree, tmp_path):
    readme = str(tree / "README.md")
    assert doc_blocks.stale(str(tree), [readme]), "the change of code stales it"
    # Run again on more threads, which changes no result (the suite holds them to the same bits).
    old, new = sweep(str(tmp_path / "old")), sweep(str(tmp_path / "new"), wall=9.0, threads=2)
    stamp = carried_blocks.carry("li2020-claims", [readme], old, new)
    assert doc_blocks.stale(str(tree), [readme]) == []
    assert f"fingerprint={doc_blocks.fingerprint(str(tree), 'li2020-claims')}" in stamp
    assert "scenes=2:" in stamp and "seeds=1-2" in stamp and "carried_from=unknown checked=2/2" in stamp
    assert "- 2.81 per unit theta\n<!-- /li2020-claims -->" in open(readme).read()


def test_a_block_whose_runs_wrote_anything_else_is_refused_and_left_as_it_was(tree, tmp_path):
    readme = str(tree / "README.md")
    before = open(readme).read()
    old, new = sweep(str(tmp_path / "old")), sweep(str(tmp_path / "new"), loading_curve="time,driving_force\n0,0\n1,3\n")
    with pytest.raises(ValueError, match="base_seed-1: loading_curve.csv"):
        carried_blocks.carry("li2020-claims", [readme], old, new)
    assert open(readme).read() == before
    assert carried_blocks.main(["li2020-claims", readme, "--old", old, "--new", new]) == 1


def test_runs_whose_scene_gained_a_parameter_at_its_default_carry_the_block_if_the_rest_is_the_same(tree, tmp_path):
    # A new parameter is resolved into every scene and changes its hash, in the records and the tables.
    readme = str(tree / "README.md")
    old = sweep(str(tmp_path / "old"))
    new = sweep(str(tmp_path / "new"), scene_hash="9f0e8c2b5a4d3e21",
                load="{type: normal_load, total_force: 400, theta_across: 0.0}")
    assert carried_blocks.renamed_scene(os.path.join(old, "cases", "base_seed-1"),
                                        os.path.join(new, "cases", "base_seed-1")) == ("0713c9b9a5ed576d",
                                                                                       "9f0e8c2b5a4d3e21")
    assert "checked=2/2" in carried_blocks.carry("li2020-claims", [readme], old, new)


def test_runs_whose_scene_changed_a_value_do_not_carry_the_block(tree, tmp_path):
    readme = str(tree / "README.md")
    old = sweep(str(tmp_path / "old"))
    new = sweep(str(tmp_path / "new"), scene_hash="9f0e8c2b5a4d3e21",
                load="{type: normal_load, total_force: 500, theta_across: 0.0}")
    with pytest.raises(ValueError, match="base_seed-1: loading_curve.csv.meta.yaml"):
        carried_blocks.carry("li2020-claims", [readme], old, new)
    # Nor does a hash that changed in the tables alone.
    other = sweep(str(tmp_path / "other"), scene_hash="9f0e8c2b5a4d3e21")
    with pytest.raises(ValueError, match="base_seed-1: run.yaml"):
        carried_blocks.carry("li2020-claims", [readme], old, other)


def test_a_block_whose_runs_left_an_output_unwritten_is_refused(tree, tmp_path):
    readme = str(tree / "README.md")
    old, new = sweep(str(tmp_path / "old")), sweep(str(tmp_path / "new"))
    os.remove(os.path.join(new, "cases", "base_seed-2", "loading_curve.csv"))
    with pytest.raises(ValueError, match=r"base_seed-2: loading_curve.csv \(not written again\)"):
        carried_blocks.carry("li2020-claims", [readme], old, new)


def git(tree, *args):
    return subprocess.run(["git", "-C", str(tree), "-c", "user.name=t", "-c", "user.email=t@t", *args],
                          check=True, capture_output=True, text=True).stdout.strip()


@pytest.fixture
def repository(tmp_path):
    """A repository whose block was stamped by an older fingerprint rule (one that counted every
    plugin, the other law too), committed; then a plugin the block cannot load was added and the rule
    became today's."""
    source_tree(tmp_path)
    for folder in ("plugins/other_law", "apps/python/frictionlab"):
        (tmp_path / folder).mkdir(parents=True)
    (tmp_path / "plugins/other_law/other_law.hpp").write_text('static constexpr std::string_view type = "other";\n')
    rule = open(doc_blocks.__file__).read()
    older_rule = rule.replace('PHYSICS = ("core/src", "core/include", "apps/campaign")',
                              'PHYSICS = ("core/src", "core/include", "apps/campaign", "plugins")')
    assert older_rule != rule
    (tmp_path / "apps/python/frictionlab/doc_blocks.py").write_text(older_rule)
    (tmp_path / "README.md").write_text("<!-- li2020-claims fingerprint=x -->\n- 2.81\n<!-- /li2020-claims -->\n")
    git(tmp_path, "init", "-q")
    git(tmp_path, "add", ".")
    git(tmp_path, "commit", "-qm", "made")
    import importlib.util
    spec = importlib.util.spec_from_file_location("rule_then", tmp_path / "apps/python/frictionlab/doc_blocks.py")
    rule_then = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(rule_then)
    readme = tmp_path / "README.md"
    made = git(tmp_path, "rev-parse", "--short", "HEAD")
    stamp = f"fingerprint={rule_then.fingerprint(str(tmp_path), 'li2020-claims')} commit={made} seeds=1-10"
    readme.write_text(readme.read_text().replace("fingerprint=x", stamp))
    (tmp_path / "plugins/bulk_3d").mkdir()
    (tmp_path / "plugins/bulk_3d/bulk_3d.hpp").write_text('static constexpr std::string_view type = "bulk_3d";\n')
    (tmp_path / "apps/python/frictionlab/doc_blocks.py").write_text(rule)
    git(tmp_path, "add", ".")
    git(tmp_path, "commit", "-qm", "a 3D bulk, and the rule counts the plugins a block names")
    return tmp_path, made


def test_a_block_whose_sources_did_not_change_is_carried_without_runs(repository):
    tree, made = repository
    readme = str(tree / "README.md")
    assert doc_blocks.stale(str(tree), [readme]), "the new rule gives another fingerprint"
    stamp = carried_blocks.carry_same_sources("li2020-claims", [readme])
    assert doc_blocks.stale(str(tree), [readme]) == []
    assert f"seeds=1-10 carried_from={made} checked=sources" in stamp
    assert "- 2.81\n<!-- /li2020-claims -->" in open(readme).read()


def test_a_block_whose_sources_changed_is_not_carried_without_runs(repository):
    tree, made = repository
    readme = str(tree / "README.md")
    (tree / "plugins/law/law.cpp").write_text("double force(double x) { return 3 * x; }\n")
    before = open(readme).read()
    with pytest.raises(ValueError, match=f"changed since {made}.*\n  plugins/law/law.cpp"):
        carried_blocks.carry_same_sources("li2020-claims", [readme])
    assert open(readme).read() == before
    assert carried_blocks.main(["li2020-claims", readme, "--same-sources"]) == 1


def test_a_block_that_was_not_current_where_it_was_stamped_is_not_carried(repository):
    tree, made = repository
    readme = tree / "README.md"
    readme.write_text(readme.read_text().replace("fingerprint=", "fingerprint=0"))
    with pytest.raises(ValueError, match=f"was not current at {made}"):
        carried_blocks.carry_same_sources("li2020-claims", [str(readme)])


def test_checked_counts_the_runs_the_block_was_made_from_not_those_run_again(tree, tmp_path):
    # The stamp says the block came from 2 runs (scenes=2:); checking one of them says 1/2, even when
    # the first runs are at hand only for that one.
    readme = str(tree / "README.md")
    old, new = sweep(str(tmp_path / "old"), cases=("base_seed-1",)), sweep(str(tmp_path / "new"), cases=("base_seed-1",))
    assert "checked=1/2" in carried_blocks.carry("li2020-claims", [readme], old, new)
    # A stamp without scenes= (a block made from a test's runs) takes the count it is given.
    text = open(readme).read()
    open(readme, "w").write(re.sub(r" scenes=\S+", "", text))
    assert "checked=1/45" in carried_blocks.carry("li2020-claims", [readme], old, new, runs=45)
