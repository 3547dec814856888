"""frictionlab.reproduce.slip_phases (Li et al. 2020 Fig. 9) on slip histories built by hand, whose
phases and collapse are known, and on one short real run of its quick variant."""
import os
import subprocess

import numpy as np
import pytest
import yaml

from frictionlab.reproduce import slip_phases


US = 1e-6
EVENT_START = 1000 * US
FRONT_DELAY = 10 * US        # the front reaches block b at EVENT_START + b * FRONT_DELAY
DISLOCATED_AT = 200 * US     # after its onset, dislocated junctions outnumber sliding ones (phase III)
REPINNED_AT = 1200 * US      # and pinned ones outnumber dislocated ones again (phase IV)
BLOCKS = list(range(10))


def rise(x):
    """Slip of a block whose speed x e^-x peaks at x = 1 (time over its rise time), from 0 to 1."""
    return 1 - np.exp(-x) * (1 + x)


def block_rows(onset, amplitude, rise_time, overshoot=0.0, detached=True, dislocates=True):
    """A block's contact_area rows, one a microsecond: stuck, then its contacts let go at `onset`,
    its speed peaks rise_time later, dislocated junctions dominate from DISLOCATED_AT, pinned ones
    again from REPINNED_AT; `overshoot` adds a slip that comes back (Fig. 9c's inset)."""
    time = np.arange(6001) * US
    tau = np.round((time - onset) / US) * US
    after = tau >= 0
    x = np.where(after, tau / rise_time, 0.0)
    bump = overshoot * np.where(after, tau / (50 * US) * np.exp(1 - tau / (50 * US)), 0.0)
    slip = amplitude * (np.where(after, rise(x), 0.0) + bump)
    velocity = amplitude * np.where(after, x * np.exp(-x), 0.0) / rise_time
    pinned, sliding, dislocated = np.ones_like(time), np.zeros_like(time), np.zeros_like(time)
    if detached:
        pinned[after], sliding[after] = 0.02, 0.98
        if dislocates:
            phase_iii = tau >= DISLOCATED_AT
            sliding[phase_iii], dislocated[phase_iii] = 0.1, 0.88
            phase_iv = tau >= REPINNED_AT
            pinned[phase_iv], sliding[phase_iv], dislocated[phase_iv] = 0.9, 0.0, 0.1
    return {"time": time, "pinned_fraction": pinned, "sliding_fraction": sliding,
            "dislocated_fraction": dislocated, "slip": slip, "velocity": velocity}


def write_table(directory, name, columns):
    names = list(columns)
    np.savetxt(os.path.join(directory, name + ".csv"), np.column_stack([columns[n] for n in names]),
               delimiter=",", header=",".join(names), comments="", fmt="%.17g")


def built_run(directory, rise_times, amplitudes, **block):
    """A run directory with one global slip (event 0) over a 41-block interface and the given blocks'
    histories through it."""
    os.makedirs(directory, exist_ok=True)
    with open(os.path.join(directory, "run.yaml"), "w") as f:
        yaml.safe_dump({"status": "done", "loading_start": 0.0,
                        "scene": {"seed": 1, "bulk": {"type": "spring_lattice_2d", "nx": 41, "length": 0.1}}}, f)
    write_table(directory, "precursors", {"event": [0], "t_start": [EVENT_START], "t_end": [EVENT_START + 500 * US],
                                          "global": [1], "max_ruptured_x": [0.1]})
    for b, rise_time, amplitude in zip(BLOCKS, rise_times, amplitudes):
        write_table(directory, f"contact_area_block_{b}",
                    block_rows(EVENT_START + b * FRONT_DELAY, amplitude, rise_time, **block))
    return str(directory)


AMPLITUDES = [(1 + b / 4) * 1e-6 for b in BLOCKS]   # final slips 1 to 3.25 um: far from collapsed as they are


@pytest.fixture
def collapsing(tmp_path):
    """Ten blocks, one history scaled: Δ/Δ_tot collapses exactly."""
    return built_run(tmp_path / "collapsing", [5 * US] * 10, AMPLITUDES)


@pytest.fixture
def not_collapsing(tmp_path):
    """The same slips, each block rising at its own pace (5 to 50 us): no normalisation of slip can
    collapse them."""
    return built_run(tmp_path / "not_collapsing", [5 * US * (b + 1) for b in BLOCKS], AMPLITUDES)


def test_the_four_phases_are_entered_when_the_junctions_and_the_speed_say(collapsing):
    block = 3
    onset = EVENT_START + block * FRONT_DELAY
    record = slip_phases.phases(collapsing, event=0, block=block)
    entries = [p["enters"] for p in record["phases"]]
    assert entries == pytest.approx([onset, onset + 5 * US, onset + DISLOCATED_AT, onset + REPINNED_AT], abs=1e-12)
    assert [p["enters_since_event"] for p in record["phases"]][0] == pytest.approx(block * FRONT_DELAY, abs=1e-12)
    assert record["reached"] and record["in_order"] and record["brief_detachment"]
    fast = record["phases"][1]
    expected = AMPLITUDES[block] * (rise(DISLOCATED_AT / (5 * US)) - rise(1.0))
    assert fast["slip"] == pytest.approx(expected, rel=1e-9)
    assert fast["mean_rate"] == pytest.approx(expected / (DISLOCATED_AT - 5 * US), rel=1e-9)
    assert fast["peak_speed"] == pytest.approx(AMPLITUDES[block] * np.exp(-1) / (5 * US), rel=1e-9)
    assert record["fast_over_slow"] > 1e6  # phase III: the rise has long ended
    # The default event is the first global slip.
    assert slip_phases.phases(collapsing, block=block)["phases"] == record["phases"]


def test_a_block_the_rupture_did_not_detach_or_that_never_dislocates_lacks_phases(tmp_path):
    stuck = built_run(tmp_path / "stuck", [5 * US] * 10, AMPLITUDES, detached=False)
    record = slip_phases.phases(stuck, block=0)
    assert not record["reached"] and not record["in_order"]
    assert all(p["enters"] is None and "duration" not in p for p in record["phases"])
    with pytest.raises(LookupError, match="not detached"):
        slip_phases.collapse(stuck, blocks=BLOCKS)
    sliding = built_run(tmp_path / "sliding", [5 * US] * 10, AMPLITUDES, dislocates=False)
    record = slip_phases.phases(sliding, block=0)
    assert record["reached"] and not record["in_order"]
    assert record["phases"][2]["enters"] is None and np.isnan(record["fast_over_slow"])


def test_a_block_still_detached_by_an_earlier_rupture_is_left_out_of_the_collapse(collapsing):
    rows = block_rows(EVENT_START, AMPLITUDES[0], 5 * US)
    rows["pinned_fraction"][rows["time"] < EVENT_START] = 0.4
    rows["dislocated_fraction"][rows["time"] < EVENT_START] = 0.6
    write_table(collapsing, "contact_area_block_0", rows)
    assert not slip_phases.phases(collapsing, block=0)["stuck_before"]
    assert slip_phases.phases(collapsing, block=1)["stuck_before"]
    c = slip_phases.collapse(collapsing, blocks=BLOCKS)
    assert c["left_out"] == [0] and c["blocks"] == BLOCKS[1:] and c["normalised"] < 1e-9
    assert slip_phases.collapse(collapsing, blocks=BLOCKS, stuck_only=False)["blocks"] == BLOCKS


def test_an_exactly_collapsing_family_measures_zero_against_its_unnormalised_spread(collapsing):
    c = slip_phases.collapse(collapsing, blocks=BLOCKS)
    assert c["event"] == 0 and c["blocks"] == BLOCKS
    assert c["onsets"] == pytest.approx([EVENT_START + b * FRONT_DELAY for b in BLOCKS], abs=1e-12)
    assert c["final_slips"] == pytest.approx([a * rise(REPINNED_AT / (5 * US)) for a in AMPLITUDES], rel=1e-9)
    assert c["normalised"] < 1e-9 and c["peak"] < 1e-9
    # Left in slip, the curves spread as their final slips do (0.72 um about a mean of 2.1 um).
    assert c["unnormalised"] == pytest.approx(np.std(AMPLITUDES) / np.mean(AMPLITUDES), rel=0.05)
    assert c["ratio"] < 1e-8
    assert c["time"][-1] == pytest.approx(REPINNED_AT, abs=1e-12)
    assert slip_phases.collapse(collapsing, blocks=BLOCKS, rescale_time=True)["normalised"] < 1e-9


def test_a_family_rising_at_different_paces_does_not_collapse(collapsing, not_collapsing):
    c = slip_phases.collapse(not_collapsing, blocks=BLOCKS)
    assert c["normalised"] > 0.05 and c["peak"] > 0.2
    assert c["normalised"] > 1e6 * slip_phases.collapse(collapsing, blocks=BLOCKS)["normalised"]


def test_the_back_slip_of_fig_9c_inset_is_the_fall_below_the_running_maximum(tmp_path, collapsing):
    assert np.all(slip_phases.backslip(collapsing, blocks=BLOCKS) < 1e-12)
    overshooting = built_run(tmp_path / "overshooting", [5 * US] * 10, AMPLITUDES, overshoot=0.2)
    falls = slip_phases.backslip(overshooting, blocks=BLOCKS)
    assert falls == pytest.approx(np.full(10, 0.2), abs=0.01)


def test_the_spread_blocks_are_the_middles_of_ten_equal_stretches():
    assert slip_phases.spread_blocks(41) == [2, 6, 10, 14, 18, 22, 26, 30, 34, 38]
    assert slip_phases.recorded_blocks() == sorted(set(range(11)) | {14, 18, 22, 26, 30, 34, 38})


@pytest.fixture(scope="module")
def quick_run(cli, source_dir, tmp_path_factory):
    """The headline with the quick overrides: ten times the drive, loaded 30 ms (~15 s)."""
    out = tmp_path_factory.mktemp("slip_phases") / "quick"
    sets = [a for o in slip_phases.run_overrides(quick=True) for a in ("--set", o)]
    result = subprocess.run([cli, "run", "-q", os.path.join(source_dir, "configs", slip_phases.SCENE), "-o", str(out), *sets],
                            capture_output=True, text=True)
    assert result.returncode == 0, result.stdout + result.stderr
    return str(out)


def test_a_real_run_shows_the_four_phases_in_every_block_and_statements_in_form(quick_run, tmp_path):
    event = slip_phases.first_global_slip(quick_run)
    for block in slip_phases.spread_blocks(41):
        record = slip_phases.phases(quick_run, block=block)
        assert record["event"] == event and record["in_order"], record
    paper_event = slip_phases.first_event_reaching(quick_run, 9)
    assert paper_event < event
    assert all(slip_phases.phases(quick_run, paper_event, b)["in_order"] for b in slip_phases.PAPER_BLOCKS)
    said = slip_phases.statements([quick_run])
    assert len(said) == 10
    for s in said:
        assert s.figure.startswith("Fig. 9") and s.claim and s.measured
        assert s.verdict in ("reproduced", "reproduced within a stated margin", "differs")
        assert bool(s.margin) == (s.verdict != "reproduced")
    in_order = [s for s in said if "four phases in order" in s.claim]
    assert len(in_order) == 2 and all(s.verdict == "reproduced" for s in in_order)
    path = slip_phases.figure(quick_run, str(tmp_path / "fig9.png"))
    assert os.path.getsize(path) > 10000


def test_the_overrides_are_accepted_by_the_scene_check(cli, source_dir):
    for quick in (False, True):
        sets = [a for o in slip_phases.run_overrides(quick) for a in ("--set", o)]
        result = subprocess.run([cli, "check", os.path.join(source_dir, "configs", slip_phases.SCENE), *sets],
                                capture_output=True, text=True)
        assert result.returncode == 0, result.stdout + result.stderr
