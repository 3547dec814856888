"""frictionlab.plot's campaign figures, of a sweep and an accuracy study written here and of a real
small sweep and ensemble study run here: every point drawn is a row of the campaign's tables, seeds
told apart or summarised as the figures say, axes named by symbol and unit, titles from the
campaign file."""
import os
import shutil
import subprocess

import matplotlib.pyplot as plt
import numpy as np
import pytest

import frictionlab.plot
from conftest import plot_command
from frictionlab.plot import _tables, campaign_figures

SWEEP = """case,loaders[1].theta,seed,run,status,reason,scene_hash,event_count,precursor_count,\
first_precursor_force_ratio,global_slip_force_ratio,steps,wall_seconds,cpu_seconds
theta--0.5,-0.5,1,theta--0.5_seed-1,done,,a1,3,2,0.20,0.30,100,1.0,1.0
theta--0.5,-0.5,2,theta--0.5_seed-2,done,,a2,2,1,0.22,0.34,100,1.0,1.0
theta-0.5,0.5,1,theta-0.5_seed-1,done,,b1,1,0,nan,0.40,100,1.0,1.0
theta-0.5,0.5,2,theta-0.5_seed-2,failed,diverged,b2,nan,nan,nan,nan,100,1.0,1.0
"""
SIDECAR = """framework: frictionlab
sweep_file: theta.yaml
title: precursors against theta
seeds: [1, 2]
units:
  case: ""
  loaders[1].theta: "1"
  seed: "1"
  run: ""
varied: ["loaders[1].theta"]
constants:
  stages[1].duration: "0.03"
"""
EVENTS = """case,loaders[1].theta,seed,run,event,t_start,t_end,force_ratio,extent_over_length,kind
theta--0.5,-0.5,1,theta--0.5_seed-1,0,0.001,0.002,0.20,0.3,precursor
theta--0.5,-0.5,1,theta--0.5_seed-1,1,0.003,0.004,0.25,0.6,precursor
theta--0.5,-0.5,1,theta--0.5_seed-1,2,0.005,0.006,0.30,1,global
theta--0.5,-0.5,2,theta--0.5_seed-2,0,0.001,0.002,0.22,0.5,precursor
theta--0.5,-0.5,2,theta--0.5_seed-2,1,0.003,0.004,0.34,1,global
theta-0.5,0.5,1,theta-0.5_seed-1,0,0.001,0.002,0.40,1,global
"""
# Each run's statistics as the sweep computes them (the ones the figures draw).
RUN_STATISTICS = """case,loaders[1].theta,seed,run,precursor_count,first_precursor_force_ratio,global_slip_force_ratio
theta--0.5,-0.5,1,theta--0.5_seed-1,2,0.20,0.30
theta--0.5,-0.5,2,theta--0.5_seed-2,1,0.22,0.34
theta-0.5,0.5,1,theta-0.5_seed-1,0,nan,0.40
theta-0.5,0.5,2,theta-0.5_seed-2,nan,nan,nan
"""
# As the sweep writes it: the mean over the seeds that reach the event, with its 95 % interval
# (made up here: two seeds are too few for one, as the last rows say).
STATISTICS = """case,loaders[1].theta,statistic,unit,n,missing,mean,sd,ci_low,ci_high,interval
theta--0.5,-0.5,precursor_count,1,2,0,1.5,0.7071067812,1,2,
theta--0.5,-0.5,first_precursor_force_ratio,1,2,0,0.21,0.01414213562,0.20,0.22,
theta--0.5,-0.5,global_slip_force_ratio,1,2,0,0.32,0.02828427125,0.30,0.34,
theta-0.5,0.5,precursor_count,1,1,0,0,nan,nan,nan,too few seeds
theta-0.5,0.5,first_precursor_force_ratio,1,0,1,nan,nan,nan,nan,too few seeds
theta-0.5,0.5,global_slip_force_ratio,1,1,0,0.4,nan,nan,nan,too few seeds
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
    (tmp_path / "sweep.csv.meta.yaml").write_text(SIDECAR)
    (tmp_path / "events.csv").write_text(EVENTS)
    (tmp_path / "run_statistics.csv").write_text(RUN_STATISTICS)
    (tmp_path / "sweep_statistics.csv").write_text(STATISTICS)
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


def test_the_sweeps_rupture_lengths_are_every_event_coloured_by_case_a_marker_per_seed(sweep):
    fig, ax = plt.subplots()
    assert frictionlab.plot.sweep_precursor_lengths(sweep, ax=ax) is ax
    minus_1, minus_2, plus_1 = ax.lines  # a case's colour, a seed's marker
    assert minus_1.get_label() == r"$\theta$ = -0.5" and plus_1.get_label() == r"$\theta$ = 0.5"
    assert list(minus_1.get_xdata()) == [0.20, 0.25, 0.30] and list(minus_2.get_xdata()) == [0.22, 0.34]
    assert list(minus_1.get_ydata()) == [0.3, 0.6, 1] and list(minus_2.get_ydata()) == [0.5, 1]
    assert minus_1.get_color() == minus_2.get_color() != plus_1.get_color()
    assert minus_1.get_marker() == plus_1.get_marker() != minus_2.get_marker()
    assert ax.get_title().startswith("precursors against theta")  # the sweep file's title
    assert [t.get_text() for t in ax.get_legend().get_texts()] == ["seed 1", "seed 2"]


def drawn(ax, marker):
    """{x: [y, ...]} of the lines of `marker` on ax: "o" a dot a seed, "s" the mean."""
    return {float(line.get_xdata()[0]): [float(y) for y in line.get_ydata()] for line in ax.lines
            if line.get_marker() == marker}


def error_bars(ax):
    """[(low, high), ...] of the error bars on ax."""
    return [tuple(float(y) for y in segment[:, 1]) for c in ax.collections for segment in c.get_segments()]


def test_against_a_varied_key_each_seed_faint_and_the_mean_with_its_interval(sweep):
    assert campaign_figures.numeric_keys(sweep, _tables.campaign_rows(sweep, "sweep.csv")) == ["loaders[1].theta"]
    count, first, coefficient = frictionlab.plot.sweep_against(sweep, "loaders[1].theta", axes=plt.subplots(1, 3)[1])
    assert drawn(count, "o") == {-0.5: [2, 1], 0.5: [0]}
    assert all(line.get_alpha() < 0.5 for line in count.lines if line.get_marker() == "o")  # faint
    assert drawn(count, "s") == {-0.5: [1.5], 0.5: [0]}
    assert error_bars(coefficient) == [pytest.approx((0.30, 0.34))]  # none where the table gives none
    assert drawn(coefficient, "o") == {-0.5: [0.30, 0.34], 0.5: [0.40]}  # the failed case left out
    assert drawn(first, "o") == {-0.5: [0.20, 0.22]}  # no precursor at theta = 0.5: NaN, not drawn
    assert coefficient.get_xlabel() == r"$\theta$"  # the symbol, not the key path


def test_only_keys_that_vary_are_axes(sweep):
    # The sidecar's constants (a duration every case sets alike) are no axis, and the table has no
    # column for them.
    assert campaign_figures.varied_keys(sweep) == ["loaders[1].theta"]
    sidecar = os.path.join(sweep, "sweep.csv.meta.yaml")
    with open(sidecar) as f:
        text = f.read()
    with open(sidecar, "w") as f:
        f.write(text.replace("varied: [\"loaders[1].theta\"]", "varied: []"))
    assert campaign_figures.varied_keys(sweep) == []
    frictionlab.plot.plot_sweep(sweep)
    assert not [f for f in os.listdir(os.path.join(sweep, "plots")) if f.startswith("sweep_against")]
    labels = [line.get_label() for line in frictionlab.plot.sweep_precursor_lengths(sweep).lines]
    assert labels[0] == "theta--0.5"  # the case by its name where no key varies


def test_an_empty_panel_says_why(sweep):
    with open(os.path.join(sweep, "run_statistics.csv")) as f:
        lines = f.readlines()
    with open(os.path.join(sweep, "run_statistics.csv"), "w") as f:  # no precursors: only global slips
        f.writelines(line.replace(",0.20,", ",nan,").replace(",0.22,", ",nan,") for line in lines)
    _, first, _ = frictionlab.plot.sweep_against(sweep, "loaders[1].theta", axes=plt.subplots(1, 3)[1])
    assert not first.lines and [t.get_text() for t in first.texts] == ["no case had a precursor"]
    low, high = first.get_xlim()  # the sweep's values of theta, as on the other panels
    assert -0.6 < low < -0.5 and 0.5 < high < 0.6


def test_the_sweeps_loading_curves_are_its_cases_that_have_one(sweep, csv_run):
    ax = frictionlab.plot.sweep_loading_curves(sweep)
    (curve,) = ax.lines
    expected = frictionlab.plot.loading_curve(csv_run).lines[0]
    np.testing.assert_array_equal(curve.get_xdata(), expected.get_xdata())
    np.testing.assert_array_equal(curve.get_ydata(), expected.get_ydata())
    assert curve.get_label() == r"$\theta$ = -0.5, seed 1"


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


def test_a_real_sweeps_figures_are_its_means_with_intervals_by_symbol_and_unit(real_sweep):
    for name in ("sweep_precursor_lengths", "sweep_against_velocity", "sweep_loading_curves"):
        assert os.path.exists(os.path.join(real_sweep, "plots", name + ".svg")), name
    with open(os.path.join(real_sweep, "plots", "sweep_against_velocity.svg")) as f:
        svg = f.read()
    assert "tiny sweep: the mean over 2 seeds" in svg and "loaders[2].velocity" not in svg
    count, first, coefficient = frictionlab.plot.sweep_against(real_sweep, "loaders[2].velocity",
                                                               axes=plt.subplots(1, 3)[1])
    assert coefficient.get_xlabel() == "$V$ [m/s]"
    statistics = [r for r in _tables.campaign_rows(real_sweep, "sweep_statistics.csv")
                  if r["statistic"] == "global_slip_force_ratio"]
    assert drawn(coefficient, "s") == {float(r["loaders[2].velocity"]): [float(r["mean"])] for r in statistics}
    # Two seeds are too few for an interval: the table says so, and no bar is drawn.
    assert all(r["interval"] == "too few seeds" and r["ci_low"] == "nan" for r in statistics)
    assert error_bars(coefficient) == []
    assert all(len(ys) == 2 for ys in drawn(coefficient, "o").values())  # each seed a dot
    assert [t.get_text() for t in first.texts] == ["no case had a precursor"]  # the tiny sweep has none
    plt.close("all")


def test_a_real_ensemble_studys_work_precision_is_each_cases_error_with_its_interval(real_study):
    for name in ("work_precision", "ensemble_work_precision", "single_seed_divergence"):
        assert os.path.exists(os.path.join(real_study, name + ".svg")), name
    axes = frictionlab.plot.ensemble_work_precision(real_study, axes=plt.subplots(2, 5)[1])
    rows = [r for r in _tables.campaign_rows(real_study, "ensemble.csv")
            if r["statistic"] == "global_slip_force_ratio" and r["verdict"] != "reference"]
    (panel,) = [ax for ax in axes if ax.get_title() == "global slip force ratio"]
    assert sorted(r["case"] for r in rows) == ["half_step", "rk4_coarse"]
    assert drawn(panel, "o") == {float(r["cpu_seconds"]): [float(r["difference"])] for r in rows}
    # Two seeds a side are too few for an interval of the difference: none drawn, as the table says.
    assert all(r["difference_interval"] == "too few seeds" for r in rows)
    assert error_bars(panel) == []
    assert axes[-1].get_xlabel() == "CPU time per run [s]"
    plt.close("all")


def test_a_real_ensemble_studys_single_seeds_part_under_step_halving_by_event_rank(real_study):
    times, ratios = frictionlab.plot.single_seed_divergence(real_study, axes=plt.subplots(1, 2)[1])
    seed_1, seed_2 = times.lines  # one curve per seed, told apart by marker
    assert (seed_1.get_label(), seed_2.get_label()) == ("seed 1", "seed 2")
    assert seed_1.get_marker() != seed_2.get_marker()
    reference = frictionlab.plot.table(os.path.join(real_study, "cases", "reference", "seed_2"), "precursors")
    half = frictionlab.plot.table(os.path.join(real_study, "cases", "half_step", "seed_2"), "precursors")
    n = min(len(reference), len(half))
    assert list(seed_2.get_xdata()) == list(range(1, n + 1))
    np.testing.assert_allclose(ratios.lines[1].get_ydata(),
                               np.abs(np.sort(reference, order="t_start")["force_ratio"][:n]
                                      - np.sort(half, order="t_start")["force_ratio"][:n]))
    plt.close("all")
