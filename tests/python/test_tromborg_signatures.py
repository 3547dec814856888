"""frictionlab.reproduce.tromborg_signatures on run directories built by hand with known answers (a
front that runs fast then slow, fronts meeting, slip exactly proportional to the front speed,
precursors growing with the load), and on one real run of the quick variant."""
import os
import subprocess

import numpy as np
import pandas as pd
import pytest
import yaml

from frictionlab.reproduce import tromborg_signatures as ts

SPACING = 0.0025
# The scene's slider (configs/tromborg2014/pnas2014.yaml): c_S = sqrt(3E/8 / rho) = 993.0 m/s.
BULK = {"type": "spring_lattice_2d", "length": 0.14, "height": 0.075, "width": 0.006, "mass": 0.0756,
        "youngs_modulus": "3e+09", "nx": 57, "nz": 31, "reference_spacing": 0.0025}
EVENT = {"finished": 1, "force_ratio": 0.2, "nucleation_x": 0.0, "extent_over_length": 1.0, "ruptured_blocks": 57,
         "global": 1}


def write_run(directory, events, fronts, history=None):
    """A run directory as the observers write it: run.yaml, precursors.csv, precursor_fronts.csv and,
    if given ({table: frame}), the interface history."""
    os.makedirs(directory, exist_ok=True)
    with open(os.path.join(directory, "run.yaml"), "w") as f:
        yaml.safe_dump({"status": "done", "loading_start": 0.0, "scene": {"bulk": BULK}}, f)
    pd.DataFrame([{**EVENT, **e} for e in events]).to_csv(os.path.join(directory, "precursors.csv"), index=False)
    pd.DataFrame(fronts, columns=["event", "block", "x", "distance", "time", "resolution"]).to_csv(
        os.path.join(directory, "precursor_fronts.csv"), index=False)
    for name, frame in (history or {}).items():
        frame.to_csv(os.path.join(directory, f"{name}.csv"), index=False)
    return str(directory)


def front_rows(event, arrivals, resolution=1e-9):
    """precursor_fronts.csv rows of one event from {block: arrival time}, nucleating at the earliest."""
    first = min(arrivals, key=arrivals.get)
    return [[event, b, b * SPACING, abs(b - first) * SPACING, t + resolution / 2, resolution]
            for b, t in sorted(arrivals.items())]


def constant_front(first_block, blocks, speed, start=0.01, direction=1):
    return {first_block + direction * k: start + k * SPACING / speed for k in range(blocks)}


def test_wave_speeds_of_the_lattice(tmp_path):
    run = write_run(tmp_path, [{"event": 0, "t_start": 0.0}], front_rows(0, {0: 0.0}))
    waves = ts.lattice_wave_speeds(run)
    density = 0.0756 / (57 * 31) / (SPACING ** 2 * 0.006)
    assert waves["density"] == pytest.approx(density)
    assert waves["c_S"] == pytest.approx(np.sqrt(3e9 * 3 / 8 / density))
    assert waves["c_S"] == pytest.approx(993.0, abs=0.5)
    assert waves["c_L"] / waves["c_S"] == pytest.approx(np.sqrt(3))
    assert waves["c_R"] / waves["c_S"] == pytest.approx(0.9194, abs=1e-4)  # a Poisson solid's Rayleigh speed


def test_a_front_that_runs_fast_then_ten_times_slower_is_found_with_its_speeds(tmp_path):
    fast = constant_front(0, 9, 500.0)
    slow = constant_front(8, 13, 5.0, start=fast[8])
    run = write_run(tmp_path, [{"event": 0, "t_start": 0.01, "global": 0}], front_rows(0, {**fast, **slow}))
    (front,) = ts.split_fronts(pd.read_csv(os.path.join(run, "precursor_fronts.csv")))
    assert list(front["block"]) == list(range(21)) and (front["direction"] == 1).all()
    transitions = ts.front_transitions(run)
    assert len(transitions) == 1
    found = transitions.iloc[0]
    assert found["fast_then_slow"]
    assert found["fast_speed"] == pytest.approx(500.0, rel=1e-6) and found["slow_speed"] == pytest.approx(5.0, rel=1e-6)
    assert found["drop"] == pytest.approx(100.0, rel=1e-6)
    assert found["transition_x"] == pytest.approx(8 * SPACING)  # the block whose window straddles the change
    statement = ts.transition_statement(transitions, ts.all_events(run))
    assert statement["verdict"] == "reproduced" and "precursors: 1 of the 1 that ran a front" in statement["measured"]
    (slow_speeds,) = ts.slow_front_speeds(run).to_dict("records")
    assert slow_speeds["median"] == pytest.approx(5.0) and slow_speeds["slow_blocks"] == 13
    assert slow_speeds["median_over_c_S"] == pytest.approx(5.0 / 993.0, rel=1e-3)


def test_a_front_slower_throughout_or_faster_later_is_no_transition():
    x = np.arange(10) * SPACING
    assert not ts.fast_then_slow(np.full(10, 20.0), x, 99.3)["fast_then_slow"]
    accelerating = ts.fast_then_slow(np.r_[np.full(5, 10.0), np.full(5, 500.0)], x, 99.3)
    assert not accelerating["fast_then_slow"] and np.isnan(accelerating["drop"])
    assert accelerating["fast_speed"] == 500.0 and accelerating["slow_speed"] == 10.0
    # A single slow block is no slow segment.
    assert not ts.fast_then_slow(np.r_[np.full(9, 500.0), 5.0], x, 99.3)["fast_then_slow"]


def test_fronts_are_split_where_they_start_and_where_they_meet():
    # A rupture from block 10 runs at 50 m/s to the driven edge and at 200 m/s the other way, where a
    # second one from block 30, 80 us later, runs back at 100 m/s: they meet at block 25.
    first, second = constant_front(10, 21, 200.0), constant_front(30, 21, 100.0, start=0.01 + 8e-5, direction=-1)
    arrivals = {**constant_front(10, 11, 50.0, direction=-1), **{b: min(first[b], second[b]) for b in range(10, 31)}}
    fronts = ts.split_fronts(pd.DataFrame(front_rows(0, arrivals),
                                          columns=["event", "block", "x", "distance", "time", "resolution"]))
    # The nucleation block starts both of its fronts; block 25, where they met, belongs to neither.
    assert [list(f["block"]) for f in fronts] == [list(range(10, -1, -1)), list(range(10, 25)), list(range(30, 25, -1))]
    assert [f["direction"].iloc[0] for f in fronts] == [-1, 1, -1]
    assert list(fronts[1]["path"]) == pytest.approx(list(np.arange(15) * SPACING))
    for front, expected in zip(fronts, (50.0, 200.0, 100.0)):
        speed = ts.local_speeds(front["path"].to_numpy(), front["arrival"].to_numpy(), 1720.0)
        assert speed == pytest.approx(np.full(len(front), expected), rel=1e-6)


def test_blocks_breaking_at_once_are_no_front(tmp_path):
    at_once = {b: 0.02 + (b % 2) * 1e-9 for b in range(57)}
    run = write_run(tmp_path, [{"event": 0, "t_start": 0.02}], front_rows(0, at_once, resolution=1e-6))
    assert ts.front_profiles(run).empty
    statement = ts.transition_statement(ts.front_transitions(run), ts.all_events(run))
    assert "global slips: 0 of the 0 that ran a front (1 did not)" in statement["measured"]
    assert statement["verdict"] == "differs"


def proportional_slip_run(directory, rate_over_speed=4e-4, speeds=(2.0, 10.0, 50.0, 250.0, 1000.0)):
    """Five events 50 ms apart, each a front at a constant speed over blocks 0-9 behind which every
    block slips at exactly rate_over_speed times that speed for 40 ms; the history every 10 us."""
    time = np.arange(0.0, 0.26, 1e-5)
    velocity, slip = np.zeros((len(time), 10)), np.zeros((len(time), 10))
    events, fronts = [], []
    for e, speed in enumerate(speeds):
        arrivals = constant_front(0, 10, speed, start=0.01 + 0.05 * e)
        events.append({"event": e, "t_start": arrivals[0], "global": 0, "extent_over_length": 0.17,
                       "ruptured_blocks": 10})
        fronts += front_rows(e, arrivals)
        for b, t in arrivals.items():
            rate = rate_over_speed * speed
            velocity[:, b] += np.where((time >= t) & (time < t + 0.04), rate, 0.0)
            slip[:, b] += rate * np.clip(time - t, 0.0, 0.04)
    history = {name: pd.DataFrame(values, columns=[f"block_{b}" for b in range(10)]).assign(time=time)
               for name, values in (("interface_velocity", velocity), ("interface_slip", slip))}
    return write_run(directory, events, fronts, history)


def test_slip_exactly_proportional_to_the_front_speed_is_reproduced(tmp_path):
    run = proportional_slip_run(tmp_path)
    pairs = ts.slip_and_front_speeds(run)
    assert len(pairs) == 50
    assert pairs["mean_slip_rate"].to_numpy() == pytest.approx(4e-4 * pairs["speed"].to_numpy(), rel=1e-6)
    assert pairs["peak_slip_speed"].to_numpy() == pytest.approx(4e-4 * pairs["speed"].to_numpy(), rel=1e-6)
    fit = ts.proportionality(pairs["speed"], pairs["mean_slip_rate"])
    assert fit["slope"] == pytest.approx(1.0) and fit["r"] == pytest.approx(1.0)
    assert fit["prefactor"] == pytest.approx(4e-4) and fit["decades"] == pytest.approx(np.log10(500))
    statement = ts.statements(run)[2]
    assert statement["verdict"] == "reproduced" and "slope 1.00" in statement["measured"]


def test_slip_independent_of_the_front_speed_differs():
    speeds = np.geomspace(1, 1000, 30)
    fit = ts.proportionality(speeds, np.full(30, 0.01))
    assert fit["slope"] == pytest.approx(0.0, abs=1e-12)
    assert ts.proportionality_statement(fit, fit)["verdict"] == "differs"
    square_root = ts.proportionality(speeds, 1e-3 * np.sqrt(speeds))
    assert square_root["slope"] == pytest.approx(0.5) and ts.proportionality_statement(square_root, fit)["verdict"] == \
        "differs"


def test_precursors_growing_with_the_load_over_two_cycles(tmp_path):
    rows = [(0.15, 0.10, 0.0, 4), (0.155, 0.01, 0.0, 1), (0.17, 0.20, 0.0, 9), (0.175, 1.0, 0.14, 2),
            (0.19, 0.35, 0.0025, 15), (0.22, 1.0, 0.03, 57),                      # cycle 0, then its global slip
            (0.16, 0.12, 0.0, 5), (0.18, 0.30, 0.0, 13), (0.21, 1.0, 0.05, 57),   # cycle 1
            (0.17, 0.25, 0.0, 10)]                                                # no global slip followed
    events = [{"event": k, "t_start": 0.01 * k, "force_ratio": f, "extent_over_length": ell, "nucleation_x": x,
               "ruptured_blocks": n, "global": int(n == 57)} for k, (f, ell, x, n) in enumerate(rows)]
    run = write_run(tmp_path, events, front_rows(0, {0: 0.0}))
    extents = ts.precursor_extents(run)
    assert list(extents["cycle"]) == [0, 0, 0, 0, 0, 1, 1]
    assert list(extents["arrested"]) == [True, False, True, False, True, True, True]  # one block; the leading edge
    growth = ts.extent_growth(extents)
    assert growth["precursors"] == 5 and growth["others"] == 2
    assert growth["spearman"] == pytest.approx(1.0)
    assert growth["successive_pairs"] == 3 and growth["successive_growing"] == 1.0
    x, y = [0.15, 0.16, 0.17, 0.18, 0.19], [0.10, 0.12, 0.20, 0.30, 0.35]
    assert growth["slope"] == pytest.approx(np.polyfit(x, y, 1)[0])
    assert growth["rise"] == pytest.approx(growth["slope"] * 0.04)
    assert ts.growth_statement(extents)["verdict"] == "reproduced"
    # Precursors as far as the one before (one a seed, as two quick runs give) do not grow.
    same = extents.assign(extent_over_length=0.205, force_ratio=0.1629 + 1e-5 * np.arange(len(extents)))
    assert ts.extent_growth(same)["successive_growing"] == 0 and ts.growth_statement(same)["verdict"] == "differs"
    # A later cycle whose precursors shrink: two of three pairs grow.
    shrinking = extents.assign(extent_over_length=np.where(extents["cycle"] == 1, [0, 0, 0, 0, 0, 0.3, 0.12],
                                                           extents["extent_over_length"]))
    assert ts.extent_growth(shrinking)["successive_growing"] == pytest.approx(2 / 3)
    assert ts.growth_statement(shrinking)["verdict"] == "reproduced within a stated margin"


def test_the_overrides_and_seeds_of_both_variants():
    assert ts.seeds(False) == list(range(1, 11)) and ts.seeds(True) == [1, 2]
    full, quick = ts.run_overrides(False), ts.run_overrides(True)
    assert all("interface_history" in o and "precursors" in o for o in (full[0], quick[0]))
    assert "format: hdf5" in full[0] and "loaders[2].velocity=4.0e-3" in quick
    assert any(o.startswith("stages[1].duration=") for o in quick)


def test_a_real_run_of_the_quick_variant_gives_the_four_statements(cli, source_dir, tmp_path):
    """Seed 1 of the quick variant (~40 CPU-s): its first precursor and global slip."""
    out = tmp_path / "quick"
    arguments = [cli, "run", "-q", os.path.join(source_dir, "configs", ts.SCENE), "-o", str(out), "--set", "seed=1"]
    for override in ts.run_overrides(True):
        arguments += ["--set", override]
    result = subprocess.run(arguments, capture_output=True, text=True)
    assert result.returncode == 0, result.stdout + result.stderr
    with open(out / "run.yaml") as f:
        resolved = yaml.safe_load(f)["resolved_choices"]["observers[1].rate_window"]
    # The precursors observer's rate_window is L/c_S: the code's c_S and ours agree.
    assert 0.14 / float(resolved["value"]) == pytest.approx(ts.lattice_wave_speeds(str(out))["c_S"], rel=2e-3)
    found = ts.statements(str(out))
    assert len(found) == 4
    for statement in found:
        assert set(statement) == {"statement", "measured", "verdict", "margin"}
        assert statement["verdict"] in ("reproduced", "reproduced within a stated margin", "differs")
        assert all(statement[k] for k in ("statement", "measured", "margin"))
    assert "PNAS 111, 8764" in found[0]["statement"] and "PRE 92, 012408" in found[2]["statement"]
    assert ts.all_events(str(out))["global"].astype(bool).any(), "the quick variant should reach a global slip"
