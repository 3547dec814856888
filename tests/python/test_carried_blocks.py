"""A generated block is carried over a change that moves no output (frictionlab.carried_blocks): its
text kept, its stamp this tree's with the commit it was made at and the cases checked; and refused,
changing nothing, when a case run again wrote anything else."""
import os

import pytest

from frictionlab import carried_blocks, doc_blocks


def sweep(folder, loading_curve="time,driving_force\n0,0\n1,2\n", wall=1.0):
    """A sweep of two cases, each with a table and a run record."""
    for case in ("base_seed-1", "base_seed-2"):
        os.makedirs(os.path.join(folder, "cases", case, "logs"))
        with open(os.path.join(folder, "cases", case, "loading_curve.csv"), "w") as f:
            f.write(loading_curve)
        with open(os.path.join(folder, "cases", case, "run.yaml"), "w") as f:
            f.write(f"scene_hash: 0713c9b9a5ed576d\nseed: 1\nsteps: 10\nwall_seconds: {wall}\n"
                    f"command_line: [{folder}]\n")
        with open(os.path.join(folder, "cases", case, "logs", "run.log"), "w") as f:
            f.write(f"took {wall} s\n")
    return folder


@pytest.fixture
def tree(tmp_path):
    """A source tree whose README holds a stamped block, then a change of code."""
    for folder in ("core/src", "plugins/law", "configs"):
        (tmp_path / folder).mkdir(parents=True)
    (tmp_path / "CMakeLists.txt").write_text("project(x)\n")
    (tmp_path / "plugins/law/law.cpp").write_text("double force(double x) { return 2 * x; }\n")
    (tmp_path / "README.md").write_text("<!-- li2020-claims -->\n- 2.81 per unit theta\n<!-- /li2020-claims -->\n")
    doc_blocks.replace_block(str(tmp_path / "README.md"), "li2020-claims", "- 2.81 per unit theta\n", ["a1", "b2"], "1-2")
    (tmp_path / "plugins/law/law.cpp").write_text("double force(double x) { return x + x; }\n")
    return tmp_path


def test_a_block_whose_runs_wrote_the_same_is_carried_with_what_was_checked(tree, tmp_path):
    readme = str(tree / "README.md")
    assert doc_blocks.stale(str(tree), [readme]), "the change of code stales it"
    old, new = sweep(str(tmp_path / "old")), sweep(str(tmp_path / "new"), wall=9.0)
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


def test_a_block_whose_runs_left_an_output_unwritten_is_refused(tree, tmp_path):
    readme = str(tree / "README.md")
    old, new = sweep(str(tmp_path / "old")), sweep(str(tmp_path / "new"))
    os.remove(os.path.join(new, "cases", "base_seed-2", "loading_curve.csv"))
    with pytest.raises(ValueError, match=r"base_seed-2: loading_curve.csv \(not written again\)"):
        carried_blocks.carry("li2020-claims", [readme], old, new)
