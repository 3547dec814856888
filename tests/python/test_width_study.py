"""frictionlab.width_study on a constructed sweep: each case's width from its lattice (n_y a, or
periodic), its seeds' first global slip, precursor count and first precursor's area (its ruptured
share of the n_x n_y cells), the means with their intervals, and the slopes over the bounded cases."""
import math
import os
import re

import pytest

from frictionlab import ensembles, width_study

SPACING = 0.0025  # 41 nodes over 100 mm

HEADER = "case,seed,run,status,precursor_count,global_slip_force_ratio,events_agree\n"


def write_run(folder, run, ny, across, events):
    """A finished run: its resolved lattice in run.yaml and its events (global, area_fraction)."""
    path = os.path.join(folder, "cases", run)
    os.makedirs(path)
    with open(os.path.join(path, "run.yaml"), "w") as f:
        f.write(f"scene:\n  bulk:\n    type: spring_lattice_3d\n    length: 0.1\n    nx: 41\n    ny: {ny}\n"
                f"    across: {across}\n")
    with open(os.path.join(path, "precursors.csv"), "w") as f:
        f.write("event,global,area_fraction\n")
        f.writelines(f"{i},{g},{a}\n" for i, (g, a) in enumerate(events))


@pytest.fixture
def sweep(tmp_path):
    """Two bounded widths (2 and 5 nodes) and a periodic layer, five seeds each; one run of the
    narrow case disagrees with its loading curve, and one starts with a global slip."""
    rows = []
    for case, ny, across in (("periodic", 1, "periodic"), ("ny2", 2, "bounded"), ("ny5", 5, "bounded")):
        for seed in range(1, 6):
            run = f"{case}_seed-{seed}"
            ratio = 0.38 + 0.002 * ny + 0.001 * seed
            first = (1, 1.0) if (case, seed) == ("ny5", 5) else (0, 0.1 * seed / ny)
            write_run(str(tmp_path), run, ny, across, [first, (1, 1.0)])
            agree = "false" if (case, seed) == ("ny2", 1) else "true"
            rows.append(f"{case},{seed},{run},done,{ny + seed % 2},{ratio},{agree}\n")
    rows.append("ny5,6,ny5_seed-6,failed,nan,nan,nan\n")  # a failed run counts nowhere
    with open(tmp_path / "sweep.csv", "w") as f:
        f.write(HEADER + "".join(rows))
    return str(tmp_path)


def test_each_case_has_its_width_and_its_seeds_values(sweep):
    study = {c.name: c for c in width_study.cases(width_study.load([sweep]))}
    assert list(study) == ["periodic", "ny2", "ny5"]
    assert math.isinf(study["periodic"].width)
    assert study["ny2"].width == pytest.approx(2 * SPACING) and study["ny5"].width == pytest.approx(5 * SPACING)
    assert study["ny5"].global_ratio == pytest.approx([0.39 + 0.001 * s for s in range(1, 6)])
    assert study["ny2"].precursors == [3, 2, 3, 2, 3]
    # Area: the ruptured share of 41 x n_y cells of a^2; no precursor before a global slip: NaN.
    assert study["ny2"].first_area[1] == pytest.approx(0.1 * 2 / 2 * 41 * 2 * SPACING ** 2)
    assert math.isnan(study["ny5"].first_area[4])
    assert study["ny2"].disagreeing == 1 and study["ny5"].disagreeing == 0


def test_the_table_gives_means_with_intervals_and_the_slopes_over_the_bounded_widths(sweep):
    study = width_study.cases(width_study.load([sweep]))
    text = width_study.table(study)
    ny5 = next(c for c in study if c.name == "ny5")
    mean = ensembles.mean(ny5.global_ratio)
    assert f"| ny5 | 12.5 | 5 | {mean.estimate:.4f} [{mean.low:.4f}, {mean.high:.4f}] |" in text
    assert "| periodic | periodic | 5 |" in text and "| ny2 | 5 | 5 (1 disagreeing) |" in text
    # F_S/F_N rises by 0.002 a node, 0.8 per metre of width: 0.0008 per mm.
    assert "Slopes against the width over the bounded cases (per mm): F_S/F_N 0.00080" in text


def test_the_figure_is_drawn(sweep, tmp_path):
    path = str(tmp_path / "width.png")
    width_study.figure(width_study.cases(width_study.load([sweep])), path)
    assert os.path.getsize(path) > 10000


def test_a_second_sweep_adds_its_cases_after_the_first(sweep, tmp_path, capsys):
    """The square interface is a sweep of its own (configs/3d/width_study_square.yaml): its cases
    join the table and the slopes after the first sweep's."""
    square = tmp_path / "square"
    write_run(str(square), "ny41_seed-1", 41, "bounded", [(0, 0.2), (1, 1.0)])
    with open(square / "sweep.csv", "w") as f:
        f.write(HEADER + "ny41,1,ny41_seed-1,done,2,0.41,true\n")
    assert width_study.main([sweep, str(square)]) == 0
    rows = [line.split(" |")[0] for line in capsys.readouterr().out.splitlines() if line.startswith("| ny")]
    assert rows == ["| ny2", "| ny5", "| ny41"]
    # One seed: its value without an interval.
    assert "| ny41 | 102.5 | 1 | 0.4100 |" in width_study.table(width_study.cases(width_study.load([str(square)])))


def test_a_saved_study_reads_back_and_a_case_run_anew_replaces_its_rows(sweep, tmp_path):
    """The docs' study is a seeds file (--save): it reads back to the same table, and a later source
    with a case of the same name replaces that case's rows where they stood."""
    saved = str(tmp_path / "seeds.csv")
    assert width_study.main([sweep, "--save", saved]) == 0
    # repr: NaN, the area without a precursor before the global slip, is not equal to itself.
    assert list(map(repr, width_study.load([saved]))) == list(map(repr, width_study.load([sweep])))
    again = tmp_path / "again"
    write_run(str(again), "ny2_seed-7", 2, "bounded", [(0, 0.3), (1, 1.0)])
    with open(again / "sweep.csv", "w") as f:
        f.write(HEADER + "ny2,7,ny2_seed-7,done,4,0.45,true\n")
    study = width_study.cases(width_study.load([saved, str(again)]))
    assert [c.name for c in study] == ["periodic", "ny2", "ny5"]
    assert study[1].global_ratio == [0.45] and study[1].precursors == [4] and study[1].disagreeing == 0


def _rows(text):
    """The case rows of the text's first Markdown table, by case, each cell without the notes in
    parentheses that the docs add ("(a corner patch)") or the table writes ("(1 disagreeing)")."""
    rows = {}
    table = text[text.index("| case |"):].split("\n\n")[0]
    for line in table.splitlines():
        if line.startswith("| ") and not line.startswith(("| case", "| ---")):
            cells = [re.sub(r"\s*\([^)]*\)", "", cell).strip() for cell in line.strip(" |").split(" | ")]
            rows[cells[0]] = cells[1:]
    return rows


def test_the_docs_table_is_what_the_docs_seeds_file_gives(source_dir):
    """theory.md 3a quotes the study from share/docs/data/width_study_seeds.csv: each of its rows and
    the slopes are what the file gives, so the table cannot drift from the data that makes it."""
    seeds = width_study.load([os.path.join(source_dir, "share/docs/data/width_study_seeds.csv")])
    expected = width_study.table(width_study.cases(seeds))
    with open(os.path.join(source_dir, "share/docs/theory.md"), encoding="utf-8") as f:
        docs = f.read()
    assert _rows(docs[docs.index("**The width study**"):]) == _rows(expected)
    slopes = expected.splitlines()[-1].split(": ", 1)[1]
    assert slopes in " ".join(docs.split())


def test_a_sweep_not_yet_ended_is_named_without_a_traceback(tmp_path, capsys):
    """A sweep writes sweep.csv when it ends: before that its folder is refused in one line."""
    assert width_study.main([str(tmp_path)]) == 1
    assert "sweep.csv: No such file or directory (a sweep writes sweep.csv when it ends)" in capsys.readouterr().err
