"""Published numbers cannot go stale in silence (frictionlab.doc_blocks): every generated block of the
README and share/docs was made from the code and scenes of this tree; and the stamp and the
fingerprint behave as documented on a tree made here."""
import glob
import hashlib
import os

import pytest

from frictionlab import doc_blocks


def documents(source_dir):
    return [os.path.join(source_dir, "README.md")] + sorted(glob.glob(os.path.join(source_dir, "share/docs/*.md")))


def test_every_generated_block_was_made_from_this_tree(source_dir):
    found = [b for d in documents(source_dir) for b in doc_blocks.blocks_in(d)]
    assert {b.name for b in found} >= {"li2020-claims", "crossing-speeds", "event-matrix", "li2020-reproduction"}
    problems = doc_blocks.stale(source_dir, documents(source_dir))
    assert not problems, "\n".join(problems)


@pytest.fixture
def tree(tmp_path):
    """A source tree with two plugins, scenes that name one of them and a document with two generated
    blocks."""
    for folder in ("core/src", "plugins/law", "plugins/other_law", "configs/li2020"):
        (tmp_path / folder).mkdir(parents=True)
    (tmp_path / "CMakeLists.txt").write_text("project(x)\n")
    for plugin in ("law", "other_law"):
        (tmp_path / f"plugins/{plugin}/{plugin}.hpp").write_text(
            f'struct Law {{ static constexpr std::string_view type = "{plugin}"; }};\n')
    (tmp_path / "plugins/law/law.cpp").write_text("// the law\ndouble force(double x) { return 2 * x; }\n")
    (tmp_path / "plugins/other_law/other_law.cpp").write_text("double force(double x) { return x; }\n")
    (tmp_path / "configs/headline.yaml").write_text("# a scene\nseed: 1\nfriction: {type: law}\n")
    (tmp_path / "configs/li2020/campaign_scene.yaml").write_text("friction: {type: law}\n")
    (tmp_path / "README.md").write_text("Speeds: <!-- crossing-speeds -->1 m/s<!-- /crossing-speeds -->.\n\n"
                                        "<!-- li2020-claims -->\nold\n<!-- /li2020-claims -->\n")
    return tmp_path


def test_a_block_is_stamped_with_what_made_it_and_a_line_stays_a_line(tree):
    readme = str(tree / "README.md")
    doc_blocks.replace_block(readme, "crossing-speeds", "578 ± 32 m/s", ["5c76dfd99d10f6aa"], "1")
    doc_blocks.replace_block(readme, "li2020-claims", "- new\n", ["a1", "b2", "a1"], doc_blocks.seed_range(range(1, 11)))
    text = open(readme).read()
    fingerprint = doc_blocks.fingerprint(str(tree), "crossing-speeds")
    assert (f"Speeds: <!-- crossing-speeds fingerprint={fingerprint} commit=unknown scene=5c76dfd99d10f6aa "
            f"seeds=1 -->578 ± 32 m/s<!-- /crossing-speeds -->.") in text
    digest = hashlib.sha256(b"a1,b2").hexdigest()[:12]
    assert f"scenes=2:{digest} seeds=1-10 -->\n- new\n<!-- /li2020-claims -->" in text
    assert doc_blocks.stale(str(tree), [readme]) == []
    # Regenerated again, the block is replaced, not nested.
    doc_blocks.replace_block(readme, "li2020-claims", "- newer\n")
    assert open(readme).read().count("li2020-claims") == 2 and "- new\n" not in open(readme).read()


def test_a_change_of_code_or_scene_makes_a_block_stale_and_rewording_does_not(tree):
    readme = str(tree / "README.md")
    doc_blocks.replace_block(readme, "crossing-speeds", "578 ± 32 m/s")
    doc_blocks.replace_block(readme, "li2020-claims", "- new\n")
    law = tree / "plugins/law/law.cpp"
    law.write_text("// the law, as Li et al. write it\ndouble force(double x) {\n    return 2 * x;\n}\n")
    assert doc_blocks.stale(str(tree), [readme]) == [], "a comment and layout changed, nothing else"
    law.write_text("double force(double x) { return 3 * x; }\n")
    problems = doc_blocks.stale(str(tree), [readme])
    assert len(problems) == 2 and "README.md: <!-- crossing-speeds --> was made from other code" in problems[0]
    assert "share/scripts/update-readme-figures --headline-only" in problems[0]
    doc_blocks.replace_block(readme, "crossing-speeds", "579 m/s")
    doc_blocks.replace_block(readme, "li2020-claims", "- newer\n")
    (tree / "configs/headline.yaml").write_text("# a scene\nseed: 2\nfriction: {type: law}\n")
    assert len(doc_blocks.stale(str(tree), [readme])) == 1, "its scene changed"


def test_a_block_depends_on_the_plugins_its_scenes_name_and_on_no_other(tree):
    readme = str(tree / "README.md")
    doc_blocks.replace_block(readme, "crossing-speeds", "578 ± 32 m/s")
    assert doc_blocks.plugin_folders(str(tree), ["configs/headline.yaml"]) == ["plugins/law"]
    (tree / "plugins/other_law/other_law.cpp").write_text("double force(double x) { return 4 * x; }\n")
    (tree / "plugins/new_bulk").mkdir()
    (tree / "plugins/new_bulk/new_bulk.hpp").write_text('static constexpr std::string_view type = "new_bulk";\n')
    assert all("crossing-speeds" not in p for p in doc_blocks.stale(str(tree), [readme])), \
        "another law changed and a new plugin came: neither can run in the headline"
    (tree / "configs/headline.yaml").write_text("# a scene\nseed: 1\nfriction: {type: other_law}\n")
    assert any("crossing-speeds" in p for p in doc_blocks.stale(str(tree), [readme])), "now it loads the other law"


def test_an_unstamped_or_unknown_block_is_named(tree):
    readme = tree / "README.md"
    readme.write_text(readme.read_text() + "<!-- made-up -->\nx\n<!-- /made-up -->\n")
    problems = doc_blocks.stale(str(tree), [str(readme)])
    assert any("made-up --> is not a registered generated block" in p for p in problems)
    assert any("crossing-speeds --> was made from other code" in p and "fingerprint None" in p for p in problems)
    with pytest.raises(ValueError, match="not a registered generated block"):
        doc_blocks.replace_block(str(readme), "made-up", "y\n")
