"""frictionlab.ensembles against values worked out by hand, and python3 -m frictionlab.li2020_claims
and -m frictionlab.lattice_convergence on campaign tables built by hand."""
import os
import re
import subprocess
import sys

import numpy as np
import pandas as pd
import pytest

from frictionlab import ensembles


def test_difference_is_the_difference_of_the_means_with_a_reproducible_bootstrap_interval():
    a, b = [1.0, 2.0, 3.0, 2.5, 1.5, np.nan], [0.5, 1.5, 1.0, 0.8, 1.2]
    e = ensembles.difference(a, b, seed=7)
    assert e.estimate == pytest.approx(2.0 - 1.0) and e.interval == ""
    assert e == ensembles.difference(a, b, seed=7)
    assert e.low <= e.estimate <= e.high
    # Every draw is a mean of the values: the interval lies within the extreme differences.
    assert e.low >= 1.0 - 1.5 and e.high <= 3.0 - 0.5


def test_fewer_than_five_seeds_give_an_estimate_and_no_interval_saying_why():
    assert ensembles.minimum_values() == 5
    e = ensembles.difference([1.0, 2.0, 3.0, 4.0, np.nan], [0.5, 1.5, 1.0, 0.8, 1.2])
    assert e.estimate == pytest.approx(2.5 - 1.0)
    assert np.isnan(e.low) and np.isnan(e.high) and np.isnan(e.se) and e.interval == "too few seeds"
    assert not e.resolved
    m = ensembles.mean([2.0, np.nan])
    assert m.estimate == 2.0 and m.interval == "too few seeds"
    assert np.isnan(ensembles.mean([]).estimate)
    assert np.isnan(ensembles.seeds_to_resolve(e, 4))


def test_an_interval_of_counts_stays_within_the_counts_seen():
    # Student's t would reach below zero here (mean 1.2, sd 2.2 over five seeds).
    m = ensembles.mean([0, 0, 0, 1, 5])
    assert m.estimate == pytest.approx(1.2)
    assert 0 <= m.low <= m.estimate <= m.high <= 5


def test_mean_has_the_plug_in_standard_error_and_an_interval_within_the_values():
    a = np.random.default_rng(5).normal(1.0, 0.5, 400)
    m = ensembles.mean(np.append(a, np.nan))
    assert m.estimate == pytest.approx(a.mean())
    assert m.se == pytest.approx(a.std() / np.sqrt(len(a)), rel=0.03)
    assert a.min() <= m.low <= m.estimate <= m.high <= a.max()
    assert m == ensembles.mean(a)


def test_the_bootstrap_standard_error_is_the_plug_in_standard_error_of_the_difference():
    rng = np.random.default_rng(3)
    a, b = rng.normal(0, 1, 400), rng.normal(0, 2, 300)
    e = ensembles.difference(a, b)
    plug_in = np.sqrt(a.var() / len(a) + b.var() / len(b))  # what resampling with replacement gives
    assert e.se == pytest.approx(plug_in, rel=0.03)
    assert e.high - e.low == pytest.approx(2 * 1.96 * plug_in, rel=0.05)


def test_a_known_difference_is_resolved_and_equal_distributions_are_not():
    rng = np.random.default_rng(11)
    base = rng.normal(0.40, 0.02, 10)
    assert ensembles.difference(base + 0.05, base).resolved  # five standard deviations apart
    same = ensembles.difference(rng.normal(0.40, 0.02, 10), base)
    assert not same.resolved, same


def test_the_slope_of_exact_data_and_its_interval_over_seeds_within_each_value():
    x = np.repeat([-1.0, 0.0, 1.0], 5)
    exact = ensembles.slope(x, 2 * x + 1)
    assert exact.estimate == pytest.approx(2) and exact.low == pytest.approx(2) and exact.high == pytest.approx(2)
    noisy = ensembles.slope(x, 2 * x + np.tile([-0.1, 0.1, 0.0, 0.05, -0.05], 3), seed=5)
    assert noisy.estimate == pytest.approx(2) and noisy.low < 2 < noisy.high and noisy.resolved
    few = ensembles.slope(np.repeat([0.0, 1.0], 4), np.repeat([0.0, 1.0], 4))
    assert few.estimate == pytest.approx(1) and few.interval == "too few seeds"
    with pytest.raises(ValueError):
        ensembles.slope([1.0, 1.0], [2.0, 3.0])


def test_the_module_and_a_sweeps_table_give_the_same_interval(cli, source_dir, tmp_path):
    # One interval method: sweep_statistics.csv's bounds are ensembles.mean of run_statistics.csv's
    # values, to the last digit written.
    sweep = tmp_path / "five.yaml"
    sweep.write_text(f"scene: {source_dir}/tests/campaign/sweep/tiny_scene.yaml\n"
                     "seeds: [1, 2, 3, 4, 5]\n")
    done = subprocess.run([cli, "sweep", "-q", str(sweep), "-o", str(tmp_path / "out"), "-j", "2"],
                          capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    runs = pd.read_csv(tmp_path / "out/run_statistics.csv")
    table = pd.read_csv(tmp_path / "out/sweep_statistics.csv", keep_default_na=False)
    compared = 0
    for _, row in table.iterrows():
        m = ensembles.mean(runs[row["statistic"]])
        if row["interval"]:
            assert row["interval"] == m.interval == "too few seeds" and int(row["n"]) < 5
            continue
        compared += 1
        for column, value in (("mean", m.estimate), ("ci_low", m.low), ("ci_high", m.high)):
            assert float(row[column]) == pytest.approx(value, rel=1e-9, abs=1e-15), (row["statistic"], column)
    assert compared >= 1


def test_seeds_to_resolve_scales_with_the_square_of_the_standard_error_over_the_effect():
    e = ensembles.Effect(estimate=0.01, low=-0.01, high=0.03, se=0.01)
    assert ensembles.seeds_to_resolve(e, 10) == pytest.approx(10 * 1.96 ** 2)
    assert ensembles.seeds_to_resolve(e._replace(estimate=0.0), 10) == float("inf")


def write(path, text):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        f.write(text)


def analysis(module, *arguments, cwd):
    """python3 -m frictionlab.MODULE ARGUMENTS in `cwd`, finding the package as this test does (ctest
    puts build/python on PYTHONPATH)."""
    return subprocess.run([sys.executable, "-m", f"frictionlab.{module}", *arguments], cwd=cwd, capture_output=True,
                          text=True)


def in_a_tree(folder):
    """Makes `folder` a source tree, as the documents a script writes its blocks into live in one."""
    for sub in ("core", "plugins"):
        (folder / sub).mkdir(exist_ok=True)
    write(folder / "CMakeLists.txt", "project(x)\n")


STATISTICS = ("precursor_count,first_precursor_time_since_loading,first_precursor_force_ratio,precursor_1_length,"
              "precursor_2_length,precursor_3_length,global_slip_force_ratio,global_slip_time_since_loading,"
              "stick_slip_period,mean_drop")
NOISE = (-0.1, 0.1, 0.0, -0.05, 0.05)  # five seeds, the fewest an interval is given for; mean zero


def test_the_claims_script_reads_the_campaigns_tables(tmp_path):
    # Fig. 8: two precursors more per unit theta, the first one 0.1 s earlier at theta > 0, the
    # global slip 0.01 higher there.
    rows = []
    for theta in (-0.5, 0.0, 0.5):
        for seed, noise in enumerate(NOISE, start=1):
            rows.append(f"t{theta},{theta},{seed},t{theta}_seed-{seed},{4 + 4 * theta + noise},"
                        f"{1.0 - 0.1 * (theta > 0) + noise / 10},0.2,0.1,0.2,nan,"
                        f"{0.4 + 0.01 * (theta > 0) + noise / 100},2,nan,nan")
    write(tmp_path / "fig8/run_statistics.csv", f"case,loaders[1].theta,seed,run,{STATISTICS}\n" + "\n".join(rows)
          + "\n")
    # Fig. 7: at 5 mm, l/L = F_S/F_N at 400 N and l/L = F_S/F_N + 0.05 at 1200 N; at 2.5 mm, the
    # first precursor 0.05 earlier in F_S/F_N, one precursor more and longer.
    events, runs = [], []
    for force, height, shift, count in ((400, 0.005, 0.0, 3), (1200, 0.005, 0.05, 3), (400, 0.0025, -0.05, 4)):
        for seed in range(1, len(NOISE) + 1):
            # The lattice (for the edge block's l/L) is in each run's run.yaml.
            case, run = f"fn{force}-h{height}", f"fn{force}-h{height}_seed-{seed}"
            cells = f"{case},{force},{height},{seed},{run}"
            write(tmp_path / "fig7/cases" / run / "run.yaml", "scene:\n  bulk: {nx: 41}\n")
            ratios = [0.2 + shift + 0.05 * k for k in range(count)]
            for k, f in enumerate(ratios):
                events.append(f"{cells},{k},{k},{f},{f - shift if height == 0.005 else f + 0.2},precursor")
            # A slip of the edge block alone (l/L = 0.5 / 40) is no front: left out of the curves.
            events.append(f"{cells},{count},{count - 0.5},0.32,0.0125,precursor")
            events.append(f"{cells},{count + 1},{count},0.4,1,global")
            runs.append(f"{cells},{count},1,{ratios[0]},0.1,0.2,0.3,0.4,1,nan,nan")
    keys = "case,loaders[1].total_force,loaders[2].height,seed,run"
    write(tmp_path / "fig7/events.csv", f"{keys},event,t_start,force_ratio,extent_over_length,kind\n"
          + "\n".join(events) + "\n")
    write(tmp_path / "fig7/run_statistics.csv", f"{keys},{STATISTICS}\n" + "\n".join(runs) + "\n")
    in_a_tree(tmp_path)
    write(tmp_path / "doc.md", "before\n<!-- li2020-claims -->\nold\n<!-- /li2020-claims -->\nafter\n")
    out = analysis("li2020_claims", "fig7", "fig8", "--write", "doc.md", cwd=tmp_path)
    assert out.returncode == 0, out.stderr
    text = out.stdout
    assert "10 seeds" not in text and "5 seeds a point (Fig. 8) and 5 a configuration (Fig. 7)" in text
    assert "slope +4.00 [" in text and "θ = 0.5 against -0.5: +4.0 [" in text
    assert "at θ = 0.5, -100 [" in text
    assert "the largest shift is at θ = 0.5, +0.010 [" in text
    assert "matched F_S/F_N is 0.050;" in text and "seeds it is 0.000 to 0.000" in text
    assert "F_S/F_N -0.050 [-0.050, -0.050]" in text and "+1.0 [+1.0, +1.0]" in text
    assert "longest one's l/L +0.20" in text  # 0.3 + 0.2 against 0.3
    assert re.fullmatch(f"before\n<!-- li2020-claims fingerprint=[0-9a-f]{{12}} commit=unknown -->\n{re.escape(text)}"
                        "<!-- /li2020-claims -->\nafter\n", (tmp_path / "doc.md").read_text())
    # Four seeds a point are too few for an interval: the claims say so instead of giving one.
    write(tmp_path / "fig8/run_statistics.csv", f"case,loaders[1].theta,seed,run,{STATISTICS}\n"
          + "\n".join(r for r in rows if "_seed-5," not in r) + "\n")
    few = analysis("li2020_claims", "fig7", "fig8", cwd=tmp_path)
    assert few.returncode == 0, few.stderr
    assert "slope +4.00 (too few seeds)" in few.stdout and "4 seeds a point (Fig. 8)" in few.stdout


def test_the_lattice_convergence_script_compares_each_lattice_with_the_finest(tmp_path):
    # Two lattices, five seeds each: the coarse one slips globally 0.02 higher in F_S/F_N and its
    # global front crosses at 500 m/s against 1000; both settle to a uniform normal force.
    runs = []
    for nx, nz, shift, speed in ((5, 2, 0.02, 500.0), (9, 3, 0.0, 1000.0)):
        for seed, noise in enumerate((n / 100 for n in NOISE), start=1):
            case, run = f"lattice-{nx}x{nz}", f"lattice-{nx}x{nz}_seed-{seed}"
            folder = tmp_path / "conv/cases" / run
            write(folder / "run.yaml", f"scene:\n  bulk: {{nx: {nx}, nz: {nz}, length: 0.1}}\n")
            write(folder / "precursors.csv", "event,t_start,global,front_speed,crossing_speed\n"
                  f"0,0.10,0,200,nan\n1,0.20,1,{speed},{speed + noise * 1000}\n")
            blocks = ",".join(f"block_{i}" for i in range(nx))
            write(folder / "interface_normal_force.csv", f"time,time_since_loading,{blocks}\n"
                  f"0,-0.01,{','.join(['0'] * nx)}\n0.01,0,{','.join(['2.5'] * nx)}\n")
            runs.append(f"{case},{seed},{run},1,0.1,0.2,0.3,nan,nan,{0.38 + shift + noise},0.2,nan,nan")
    # A case an interruption left unrun has a row of empty statistics and no folder: it is left out.
    runs.append("lattice-9x3,6,lattice-9x3_seed-6" + "," * STATISTICS.count(",") + ",")
    write(tmp_path / "conv/run_statistics.csv", f"case,seed,run,{STATISTICS}\n" + "\n".join(runs) + "\n")
    names = [r.split(",")[2] for r in runs]
    write(tmp_path / "conv/sweep.csv", "case,seed,run,status\n" + "".join(
        f"x,0,{n},{'not run' if n.endswith('seed-6') else 'done'}\n" for n in names))
    in_a_tree(tmp_path)
    write(tmp_path / "doc.md", "<!-- lattice-convergence -->\nold\n<!-- /lattice-convergence -->\n")
    out = analysis("lattice_convergence", "conv", "--figure", "f.png", "--write", "doc.md", cwd=tmp_path)
    assert out.returncode == 0, out.stderr
    lines = {line.split(" | ")[0].lstrip("| "): line for line in out.stdout.splitlines() if line.startswith("| ")}
    assert lines["quantity"] == "| quantity | 5 × 2 | 9 × 3 | 5 × 2 − 9 × 3 |"
    assert "**+0.020 [" in lines["first global slip, F_S/F_N"]          # resolved: the seeds agree to 0.001
    assert "**-500 [" in lines["first global slip, crossing speed [m/s]"]  # coarse minus finest
    assert "| 0.380 [0.379, 0.381] |" in lines["first global slip, F_S/F_N"]
    assert lines["first precursor, F_S/F_N"].endswith("| +0.000 [+0.000, +0.000] |")  # not resolved: no bold
    assert (tmp_path / "f.png").stat().st_size > 0
    assert re.fullmatch(f"<!-- lattice-convergence fingerprint=[0-9a-f]{{12}} commit=unknown seeds=0 -->\n"
                        f"{re.escape(out.stdout)}<!-- /lattice-convergence -->\n", (tmp_path / "doc.md").read_text())
    # Grouped by case (a sweep over something else on one lattice), each compared with the last case.
    by_case = analysis("lattice_convergence", "conv", "--by", "case", cwd=tmp_path)
    assert by_case.returncode == 0, by_case.stderr
    assert "| quantity | lattice-5x2 | lattice-9x3 | lattice-5x2 − lattice-9x3 |" in by_case.stdout
    assert "**+0.020 [" in by_case.stdout
