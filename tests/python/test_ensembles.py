"""frictionlab.ensembles against values worked out by hand, and share/scripts/li2020-claims and
share/scripts/lattice-convergence on campaign tables built by hand."""
import os
import subprocess
import sys

import numpy as np
import pytest

from frictionlab import ensembles

SOURCE = os.environ.get("FRICTIONLAB_SOURCE_DIR", os.path.join(os.path.dirname(__file__), "..", ".."))


def test_difference_is_the_difference_of_the_means_with_a_reproducible_bootstrap_interval():
    a, b = [1.0, 2.0, 3.0, np.nan], [0.5, 1.5]
    e = ensembles.difference(a, b, seed=7)
    assert e.estimate == pytest.approx(2.0 - 1.0)
    assert e == ensembles.difference(a, b, seed=7)
    assert e.low <= e.estimate <= e.high
    # Every draw is a mean of the values: the interval lies within the extreme differences.
    assert e.low >= 1.0 - 1.5 and e.high <= 3.0 - 0.5
    with pytest.raises(ValueError):
        ensembles.difference([1.0, np.nan], b)


def test_mean_has_the_plug_in_standard_error_and_an_interval_within_the_values():
    a = np.random.default_rng(5).normal(1.0, 0.5, 400)
    m = ensembles.mean(np.append(a, np.nan))
    assert m.estimate == pytest.approx(a.mean())
    assert m.se == pytest.approx(a.std() / np.sqrt(len(a)), rel=0.03)
    assert a.min() <= m.low <= m.estimate <= m.high <= a.max()
    assert m == ensembles.mean(a)
    with pytest.raises(ValueError):
        ensembles.mean([1.0, np.nan])


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
    x = np.repeat([-1.0, 0.0, 1.0], 4)
    exact = ensembles.slope(x, 2 * x + 1)
    assert exact.estimate == pytest.approx(2) and exact.low == pytest.approx(2) and exact.high == pytest.approx(2)
    noisy = ensembles.slope(x, 2 * x + np.tile([-0.1, 0.1, 0.0, 0.0], 3), seed=5)
    assert noisy.estimate == pytest.approx(2) and noisy.low < 2 < noisy.high and noisy.resolved


def test_seeds_to_resolve_scales_with_the_square_of_the_standard_error_over_the_effect():
    e = ensembles.Effect(estimate=0.01, low=-0.01, high=0.03, se=0.01)
    assert ensembles.seeds_to_resolve(e, 10) == pytest.approx(10 * 1.96 ** 2)
    assert ensembles.seeds_to_resolve(e._replace(estimate=0.0), 10) == float("inf")


def write(path, text):
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w") as f:
        f.write(text)


STATISTICS = ("precursor_count,first_precursor_time,first_precursor_force_ratio,precursor_1_length,"
              "precursor_2_length,precursor_3_length,global_slip_force_ratio,global_slip_time,stick_slip_period,"
              "mean_drop")


def test_the_claims_script_reads_the_campaigns_tables(tmp_path):
    # Fig. 8: two precursors more per unit theta, the first one 0.1 s earlier at theta > 0, the
    # global slip 0.01 higher there.
    rows = []
    for theta in (-0.5, 0.0, 0.5):
        for seed, noise in enumerate((-0.1, 0.1, 0.0), start=1):
            rows.append(f"t,{theta},{seed},{4 + 4 * theta + noise},{1.0 - 0.1 * (theta > 0) + noise / 10},0.2,"
                        f"0.1,0.2,nan,{0.4 + 0.01 * (theta > 0) + noise / 100},2,nan,nan")
    write(tmp_path / "fig8/run_statistics.csv", f"case,loaders[1].theta,seed,{STATISTICS}\n" + "\n".join(rows) + "\n")
    # Fig. 7: at 5 mm, l/L = F_S/F_N at 400 N and l/L = F_S/F_N + 0.05 at 1200 N; at 2.5 mm, the
    # first precursor 0.05 earlier in F_S/F_N, one precursor more and longer.
    events, runs = [], []
    for force, height, shift, count in ((400, 0.005, 0.0, 3), (1200, 0.005, 0.05, 3), (400, 0.0025, -0.05, 4)):
        for seed in (1, 2, 3, 4):
            # The lattice (for the edge block's l/L) is in each run's run.yaml.
            case = f"fn{force}-h{height}_seed-{seed},{force},{height}"
            write(tmp_path / "fig7/cases" / case.split(",")[0] / "run.yaml", "scene:\n  bulk: {nx: 41}\n")
            ratios = [0.2 + shift + 0.05 * k for k in range(count)]
            for k, f in enumerate(ratios):
                events.append(f"{case},{seed},{k},{k},{f},{f - shift if height == 0.005 else f + 0.2},precursor")
            # A slip of the edge block alone (l/L = 0.5 / 40) is no front: left out of the curves.
            events.append(f"{case},{seed},{count},{count - 0.5},0.32,0.0125,precursor")
            events.append(f"{case},{seed},{count + 1},{count},0.4,1,global")
            runs.append(f"{case},{seed},{count},1,{ratios[0]},0.1,0.2,0.3,0.4,1,nan,nan")
    keys = "case,loaders[1].total_force,loaders[2].height,seed"
    write(tmp_path / "fig7/events.csv", f"{keys},event,t_start,force_ratio,extent_over_length,kind\n"
          + "\n".join(events) + "\n")
    write(tmp_path / "fig7/run_statistics.csv", f"{keys},{STATISTICS}\n" + "\n".join(runs) + "\n")
    write(tmp_path / "doc.md", "before\n<!-- li2020-claims -->\nold\n<!-- /li2020-claims -->\nafter\n")
    build = os.path.dirname(os.path.dirname(ensembles.__file__))  # build/python
    out = subprocess.run([sys.executable, os.path.join(SOURCE, "share/scripts/li2020-claims"), "fig7", "fig8",
                          "--write", "doc.md"], cwd=tmp_path, capture_output=True, text=True,
                         env={**os.environ, "PYTHONPATH": build})
    assert out.returncode == 0, out.stderr
    text = out.stdout
    assert "10 seeds" not in text and "3 seeds a point (Fig. 8) and 4 a configuration (Fig. 7)" in text
    assert "slope +4.00" in text and "θ = 0.5 against -0.5: +4.0" in text
    assert "at θ = 0.5, -100" in text
    assert "the largest shift is at θ = 0.5, +0.010" in text
    assert "matched F_S/F_N is 0.050;" in text and "seeds it is 0.000 to 0.000" in text
    assert "F_S/F_N -0.050 [-0.050, -0.050]" in text and "+1.0 [+1.0, +1.0]" in text
    assert "longest one's l/L +0.20" in text  # 0.3 + 0.2 against 0.3
    assert (tmp_path / "doc.md").read_text() == f"before\n<!-- li2020-claims -->\n{text}<!-- /li2020-claims -->\nafter\n"


def test_the_lattice_convergence_script_compares_each_lattice_with_the_finest(tmp_path):
    # Two lattices, three seeds each: the coarse one slips globally 0.02 higher in F_S/F_N and its
    # global front crosses at 500 m/s against 1000; both settle to a uniform normal force.
    runs = []
    for nx, nz, shift, speed in ((5, 2, 0.02, 500.0), (9, 3, 0.0, 1000.0)):
        for seed, noise in ((1, -0.001), (2, 0.001), (3, 0.0)):
            case = f"lattice-{nx}x{nz}_seed-{seed}"
            folder = tmp_path / "conv/cases" / case
            write(folder / "run.yaml", f"scene:\n  bulk: {{nx: {nx}, nz: {nz}, length: 0.1}}\n")
            write(folder / "precursors.csv", "event,t_start,global,front_speed,crossing_speed\n"
                  f"0,0.10,0,200,nan\n1,0.20,1,{speed},{speed + noise * 1000}\n")
            blocks = ",".join(f"block_{i}" for i in range(nx))
            write(folder / "interface_normal_force.csv", f"time,time_since_loading,{blocks}\n"
                  f"0,-0.01,{','.join(['0'] * nx)}\n0.01,0,{','.join(['2.5'] * nx)}\n")
            runs.append(f"{case},{seed},1,0.1,0.2,0.3,nan,nan,{0.38 + shift + noise},0.2,nan,nan")
    # A case an interruption left unrun has a row of empty statistics and no folder: it is left out.
    runs.append("lattice-9x3_seed-4,4" + "," * STATISTICS.count(",") + ",")
    write(tmp_path / "conv/run_statistics.csv", f"case,seed,{STATISTICS}\n" + "\n".join(runs) + "\n")
    cases = [r.split(",")[0] for r in runs]
    write(tmp_path / "conv/sweep.csv", "case,status\n" + "".join(
        f"{c},{'not run' if c.endswith('seed-4') else 'done'}\n" for c in cases))
    write(tmp_path / "doc.md", "<!-- lattice-convergence -->\nold\n<!-- /lattice-convergence -->\n")
    build = os.path.dirname(os.path.dirname(ensembles.__file__))  # build/python
    out = subprocess.run([sys.executable, os.path.join(SOURCE, "share/scripts/lattice-convergence"), "conv",
                          "--figure", "f.png", "--write", "doc.md"], cwd=tmp_path, capture_output=True, text=True,
                         env={**os.environ, "PYTHONPATH": build, "MPLBACKEND": "Agg"})
    assert out.returncode == 0, out.stderr
    lines = {line.split(" | ")[0].lstrip("| "): line for line in out.stdout.splitlines() if line.startswith("| ")}
    assert lines["quantity"] == "| quantity | 5 × 2 | 9 × 3 | 5 × 2 − 9 × 3 |"
    assert "**+0.020 [" in lines["first global slip, F_S/F_N"]          # resolved: the seeds agree to 0.001
    assert "**-500 [" in lines["first global slip, crossing speed [m/s]"]  # coarse minus finest
    assert "| 0.380 [0.379, 0.381] |" in lines["first global slip, F_S/F_N"]
    assert lines["first precursor, F_S/F_N"].endswith("| +0.000 [+0.000, +0.000] |")  # not resolved: no bold
    assert (tmp_path / "f.png").stat().st_size > 0
    assert (tmp_path / "doc.md").read_text() == f"<!-- lattice-convergence -->\n{out.stdout}<!-- /lattice-convergence -->\n"
    # Grouped by case (a sweep over something else on one lattice), each compared with the last case.
    by_case = subprocess.run([sys.executable, os.path.join(SOURCE, "share/scripts/lattice-convergence"), "conv",
                              "--by", "case"], cwd=tmp_path, capture_output=True, text=True,
                             env={**os.environ, "PYTHONPATH": build, "MPLBACKEND": "Agg"})
    assert by_case.returncode == 0, by_case.stderr
    assert "| quantity | lattice-5x2 | lattice-9x3 | lattice-5x2 − lattice-9x3 |" in by_case.stdout
    assert "**+0.020 [" in by_case.stdout
