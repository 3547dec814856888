"""`frictionlab reproduce`: the quick reproduction of Li et al. 2020 gives a report with a row and a
verdict for every figure's statements, its figures, provenance and cost; an unknown paper lists the
papers; a reproduction killed with SIGKILL and started again goes on and gives the same statements."""
import json
import os
import signal
import subprocess
import time

import pytest

from frictionlab.reproduce import report


def reproduce(cli, source_dir, *args, **kwargs):
    return subprocess.Popen([cli, "reproduce", *args], cwd=source_dir, stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True, **kwargs)


@pytest.fixture(scope="module")
def quick(cli, source_dir, tmp_path_factory):
    """The quick reproduction, killed once early (kill -9) and started again with the same command."""
    out = str(tmp_path_factory.mktemp("reproduce") / "li2020")
    first = reproduce(cli, source_dir, "li2020", "-o", out, "-j", "2", "--quick", start_new_session=True)
    time.sleep(8)
    os.killpg(first.pid, signal.SIGKILL)  # the command, its sweep and the sweep's runs
    first.wait()
    again = reproduce(cli, source_dir, "li2020", "-o", out, "-j", "2", "--quick")
    output, _ = again.communicate()
    assert again.returncode == 0, output
    return out, output


def test_an_unknown_paper_lists_the_papers(cli, source_dir):
    result = reproduce(cli, source_dir, "li2021")
    output, _ = result.communicate()
    assert result.returncode == 2
    assert "unknown paper 'li2021'; the papers: li2020, tromborg2014" in output


def test_the_report_has_a_verdict_for_every_statement_of_figs_5_to_9(quick):
    out, _ = quick
    rows = json.load(open(os.path.join(out, "report.json")))
    statements = rows["statements"]
    figures = {s["figure"].split()[1].rstrip("abc,") for s in statements}  # Fig. 9a, b: 9
    assert figures == {"5", "6", "7", "8", "9"}
    assert all(s["verdict"] in report.VERDICTS and s["claim"] and s["measured"] for s in statements)
    assert rows["failed_runs"] == [] and rows["cpu_seconds"] > 0
    text = open(os.path.join(out, "report.md")).read()
    for heading in ("## Statements", "## Figures", "## Failed runs", "## Provenance"):
        assert heading in text
    assert "Made by `frictionlab reproduce li2020 -o" in text and "--quick" in text
    for step in ("fig5", "fig6", "fig7", "fig8", "fig9"):
        assert f"| {step} |" in text, f"no provenance row for {step}"
    figures = [line.split("](")[1].rstrip(")\n") for line in text.splitlines() if line.startswith("![")]
    assert figures and all(os.path.getsize(os.path.join(out, f)) > 0 for f in figures)


def test_killed_and_started_again_it_gives_the_statements_of_its_runs(quick, cli, source_dir):
    out, _ = quick
    before = json.load(open(os.path.join(out, "report.json")))["statements"]
    # Run a third time: every run is finished, nothing runs again, the statements are the same.
    start = time.monotonic()
    result = reproduce(cli, source_dir, "li2020", "-o", out, "-j", "2", "--quick")
    output, _ = result.communicate()
    assert result.returncode == 0, output
    assert json.load(open(os.path.join(out, "report.json")))["statements"] == before
    assert time.monotonic() - start < 60, "finished runs were run again"


def test_a_failed_run_is_named_in_the_report(tmp_path):
    import pandas as pd
    from frictionlab.reproduce.steps import Outcome, Step
    runs = pd.DataFrame({"case": ["base", "base"], "seed": [1, 2], "run": ["base_seed-1", "base_seed-2"],
                         "status": ["done", "failed"], "reason": ["", "block 3: velocity not finite at step 120"],
                         "scene_hash": ["5c76dfd99d10f6aa"] * 2, "cpu_seconds": [1.5, 0.5]})
    outcome = Outcome(Step("fig6", "the headline scene over 2 seeds"), str(tmp_path / "runs/fig6"), runs, 1)
    statements = [report.Statement("Fig. 6", "a claim", "a value", "differs", "by 2 %")]
    text = open(report.write(str(tmp_path), "A paper", "frictionlab reproduce x", statements, {"fig6": outcome},
                             [])).read()
    assert "- step fig6, run `base_seed-2`: failed: block 3: velocity not finite at step 120" in text
    assert "| fig6 | the headline scene over 2 seeds | 1 | 1 | 1–2 | 5c76dfd99d10f6aa |" in text
    assert "**differs** (by 2 %)" in text and "Total processor time of the runs: 2 s" in text
    assert json.load(open(tmp_path / "report.json"))["failed_runs"] == [
        {"step": "fig6", "run": "base_seed-2", "status": "failed"}]
    with pytest.raises(ValueError, match="verdict 'maybe'"):
        report.Statement("Fig. 6", "a claim", "a value", "maybe")


def test_figures_whose_runs_all_failed_are_said_not_measured(tmp_path):
    from frictionlab.reproduce import li2020
    from frictionlab.reproduce.steps import Outcome
    outcomes = {s.name: Outcome(s, str(tmp_path / "runs" / s.name), None, 1) for s in li2020.steps(quick=True)}
    statements, figures, _ = li2020.measure(outcomes, str(tmp_path))
    not_measured = {s.figure for s in statements if s.verdict == "not measured"}
    assert {"Fig. 6", "Figs. 7, 8"} <= not_measured and figures == []
    assert all(s.verdict in report.VERDICTS for s in statements)
