"""frictionlab.plot's campaign figures, of a sweep and an accuracy study written here: every point
drawn is a row of the campaign's tables, seeds together or summarised as the figures say."""
import os
import shutil

import matplotlib.pyplot as plt
import numpy as np
import pytest

import frictionlab.plot
from conftest import plot_command
from frictionlab.plot import _tables, campaign_figures

SWEEP = """# frictionlab sweep theta.yaml
case,loaders[1].theta,seed,status,reason,scene_hash,global_static_coefficient,events,precursor_count,\
first_precursor_force_ratio,steps,wall_seconds,cpu_seconds
theta--0.5_seed-1,-0.5,1,done,,a1,0.30,3,2,0.20,100,1.0,1.0
theta--0.5_seed-2,-0.5,2,done,,a2,0.34,2,1,0.22,100,1.0,1.0
theta-0.5_seed-1,0.5,1,done,,b1,0.40,1,0,nan,100,1.0,1.0
theta-0.5_seed-2,0.5,2,failed,diverged,b2,nan,0,0,nan,100,1.0,1.0
"""
EVENTS = """# frictionlab sweep theta.yaml
case,loaders[1].theta,seed,event,t_start,t_end,force_ratio,extent_over_length,kind
theta--0.5_seed-1,-0.5,1,0,0.001,0.002,0.20,0.3,precursor
theta--0.5_seed-1,-0.5,1,1,0.003,0.004,0.25,0.6,precursor
theta--0.5_seed-1,-0.5,1,2,0.005,0.006,0.30,1,global
theta--0.5_seed-2,-0.5,2,0,0.001,0.002,0.22,0.5,precursor
theta--0.5_seed-2,-0.5,2,1,0.003,0.004,0.34,1,global
theta-0.5_seed-1,0.5,1,0,0.001,0.002,0.40,1,global
"""
ERRORS = [column for column, _ in campaign_figures.STUDY_ERRORS]
STUDY_CASES = [  # case, family, seed, wall seconds, every error
    ("reference", "rk4", 1, 8.0, 0.0), ("reference", "rk4", 2, 9.0, 0.0),
    ("rk4_fine", "rk4", 1, 4.0, 1e-4), ("rk4_fine", "rk4", 2, 6.0, 3e-4),
    ("rk4_coarse", "rk4", 1, 1.0, 1e-2), ("rk4_coarse", "rk4", 2, 2.0, 2e-2),
    ("euler", "euler", 1, 0.5, 0.1), ("euler", "euler", 2, 0.5, float("nan")),
]


@pytest.fixture
def sweep(tmp_path, csv_run):
    """A sweep over theta, two seeds each, one case failed; one case has its run's tables."""
    (tmp_path / "sweep.csv").write_text(SWEEP)
    (tmp_path / "events.csv").write_text(EVENTS)
    shutil.copytree(csv_run.directory, tmp_path / "cases" / "theta--0.5_seed-1")
    yield str(tmp_path)
    plt.close("all")


@pytest.fixture
def study(tmp_path):
    """An accuracy study of two families over two seeds, one run of which failed (NaN errors)."""
    rows = [",".join(["case", "family", "seed", "wall_seconds", *ERRORS])]
    rows += [",".join([case, family, str(seed), str(wall)] + [str(error)] * len(ERRORS))
             for case, family, seed, wall, error in STUDY_CASES]
    (tmp_path / "study.csv").write_text("\n".join(rows) + "\n")
    (tmp_path / "study.csv.meta.yaml").write_text("framework: frictionlab\nseeds: [1, 2]\n")
    (tmp_path / "study.md").write_text("# a study for the tests\n\nWhat it compares.\n")
    yield str(tmp_path)
    plt.close("all")


def test_the_sweeps_rupture_lengths_are_every_event_coloured_by_case(sweep):
    fig, ax = plt.subplots()
    assert frictionlab.plot.sweep_precursor_lengths(sweep, ax=ax) is ax
    minus, plus = ax.lines  # the seeds of a case together
    assert (minus.get_label(), plus.get_label()) == ("theta=-0.5", "theta=0.5")
    assert list(minus.get_xdata()) == [0.20, 0.25, 0.30, 0.22, 0.34]
    assert list(minus.get_ydata()) == [0.3, 0.6, 1, 0.5, 1]
    assert list(plus.get_xdata()) == [0.40] and plus.get_color() != minus.get_color()


def drawn(ax, marker):
    """{x: [y, ...]} of the lines of `marker` on ax: "o" a dot a seed, "s" the mean."""
    return {float(line.get_xdata()[0]): [float(y) for y in line.get_ydata()] for line in ax.lines
            if line.get_marker() == marker}


def test_against_a_varied_key_each_seed_and_their_mean_of_the_finished_cases(sweep):
    assert campaign_figures.numeric_keys(_tables.campaign_rows(sweep, "sweep.csv")) == ["loaders[1].theta"]
    count, first, coefficient = frictionlab.plot.sweep_against(sweep, "loaders[1].theta", axes=plt.subplots(1, 3)[1])
    assert drawn(count, "o") == {-0.5: [2, 1], 0.5: [0]}
    assert drawn(count, "s") == {-0.5: [1.5], 0.5: [0]}
    assert drawn(coefficient, "o") == {-0.5: [0.30, 0.34], 0.5: [0.40]}  # the failed case left out
    assert drawn(first, "o") == {-0.5: [0.20, 0.22]}  # no precursor at theta = 0.5: NaN, not drawn
    assert coefficient.get_xlabel() == "loaders[1].theta"


def test_the_sweeps_loading_curves_are_its_cases_that_have_one(sweep, csv_run):
    ax = frictionlab.plot.sweep_loading_curves(sweep)
    (curve,) = ax.lines
    expected = frictionlab.plot.loading_curve(csv_run).lines[0]
    np.testing.assert_array_equal(curve.get_xdata(), expected.get_xdata())
    np.testing.assert_array_equal(curve.get_ydata(), expected.get_ydata())
    assert curve.get_label() == "theta=-0.5"


def test_work_precision_draws_each_families_largest_error_over_the_seeds_against_wall_time(study):
    axes = frictionlab.plot.work_precision(study, axes=plt.subplots(3, 3)[1])
    assert [ax.get_title() for ax in axes.flat] == [title for _, title in campaign_figures.STUDY_ERRORS]
    (rk4,) = axes[0, 0].lines  # euler's NaN, of its failed seed, is not drawn
    assert rk4.get_label() == "rk4"
    assert list(rk4.get_xdata()) == [1.5, 5.0]  # the median wall time, cheapest case first
    assert list(rk4.get_ydata()) == [2e-2, 3e-4]  # the largest error over the seeds
    assert axes[0, 0].get_xscale() == "log" and axes[0, 0].get_yscale() == "log"
    assert axes[-1, 1].get_xlabel() == "wall time (s)" and axes[1, 0].get_ylabel() == "relative error"


def test_the_study_command_titles_the_plot_with_the_study_over_its_seeds(study):
    plot_command("--study", study)
    assert sorted(f for f in os.listdir(study) if f.startswith("work_precision")) == \
        ["work_precision.png", "work_precision.svg"]
    with open(os.path.join(study, "work_precision.svg")) as f:
        svg = f.read()
    assert "a study for the tests: relative error against the reference, the largest over 2 seeds" in svg
