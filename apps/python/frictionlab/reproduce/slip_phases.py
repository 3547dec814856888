"""Li et al. 2020 Fig. 9: the four phases of an interface block's motion through a rupture, and the
collapse of the blocks' normalised slip histories.

The paper (§3.3) finds "four distinct phases": *detachment* (I), *fast slip* (II), *slow slip* (III)
and *rejuvenation* (IV); and for "the normalized displacements of 10 bottom blocks", Δ/Δ_tot, with
Δ the slip since "the instant when fast slip starts" and Δ_tot the slip "from the beginning of its
fast slip motion to the end of its slow slip motion", "an approximate collapse of the slip history"
(Fig. 9c; time is not rescaled). The paper shows its first rupture event, a precursor, over blocks
i = 1..10. Here the default event is the first global slip, over ten blocks spread along the
interface; statements() measures both.

The phase boundaries are those of the four_phase figure (frictionlab.plot.run_figures.
phase_boundaries), read from the run's contact_area_block_<i> tables: they need the junction-state
fractions, which interface_history lacks (it has the pinned fraction only). The events are
precursors.csv's.
"""
import functools
import math
import os

import numpy as np

from .. import ensembles
from .report import Statement
from ..plot._tables import run_directory, scene_of, table
from ..plot.run_figures import phase_boundaries

SCENE = "headline.yaml"  # below configs/
PHASES = (("I", "detachment"), ("II", "fast slip"), ("III", "slow slip"), ("IV", "rejuvenation"))
PAPER_BLOCKS = tuple(range(10))  # Fig. 9c: bottom blocks i = 1..10, 0-based
PAPER_BLOCK = 5                  # Fig. 9a, b, d: block i = 6
HEADLINE_BLOCKS = 41             # configs/headline.yaml: bulk.nx
CONTACT_AREA, VTK_SERIES = 2, 4  # positions in configs/headline.yaml's observers
# One row a microsecond while RK4 (0.2 us steps) resolves a rupture, one per 10 us while the
# headline's integrator creeps (2 us steps): a front crosses a block in ~3 us, a detachment takes ~10.
STEPS_PER_ROW = 5
# A block's window opens this long before its event (about the detector's rate window L/c_S): early
# enough that it is still stuck, late enough that little of its creep before the event counts.
LEAD = 1e-4
# A block's phases lie within this span after its event started, as the four_phase figure's window
# (4 ms after detachment): rejuvenation begins ~1.2 ms after it. Until the next event at the latest.
PHASES_SPAN = 4e-3
# A block's fast slip starts when it last slipped slower than this fraction of its peak speed.
FAST_SLIP_START = 0.1
# A block with fewer of its junctions pinned is detached (four_phase's and the detector's criterion).
# One that enters a rupture detached is still in an earlier rupture's phases (Fig. 9b starts all pinned).
DETACHED = 0.5
GRID_POINTS = 400
# Verdict margins (statements()).
COLLAPSED, APPROXIMATE = 0.05, 0.10    # RMS spread of Δ/Δ_tot, as a fraction of the final slip
NARROWED = 0.5                         # normalising must at least halve the unnormalised spread
TEN_TIMES, MUCH_SLOWER = 10.0, 3.0     # phase II's slip rate over phase III's
ALL, MOST = 1.0, 0.9                   # share of blocks that must show a feature
BACKSLIP = 0.01                        # a fall of Δ/Δ_tot that is not round-off


def spread_blocks(nx, count=10):
    """`count` blocks evenly spread along an interface of nx blocks, each the middle of an equal
    stretch: away from both edges, where the drive and the free end make a block's motion special."""
    return [int((k + 0.5) * nx / count) for k in range(count)]


def recorded_blocks(nx=HEADLINE_BLOCKS):
    """The blocks both settings of statements() read."""
    return sorted(set(PAPER_BLOCKS) | set(spread_blocks(nx)))


def run_overrides(quick: bool) -> list:
    """The --set overrides of SCENE this analysis needs: contact_area tables of the paper's ten blocks
    and ten spread ones, a row a microsecond in ruptures (in steps: the headline's integrator, not
    RK4 throughout), as HDF5 (a third of CSV's size); the load stage ended after the first global
    slip (0.217-0.233 s after loading over 20 seeds; the next comes ~48 ms later); no VTU series.
    quick: ten times the drive, the first global slip ~24 ms after loading, for CI."""
    overrides = [f"observers[{CONTACT_AREA}].blocks=[{','.join(map(str, recorded_blocks()))}]",
                 f"observers[{CONTACT_AREA}].every=~",
                 f"observers[{CONTACT_AREA}].every_steps={STEPS_PER_ROW}",
                 f"observers[{CONTACT_AREA}].format=hdf5",
                 f"observers[{VTK_SERIES}]=~"]
    if quick:
        return overrides + ["loaders[2].velocity=1.0e-2", "stages[1].duration=0.03"]
    return overrides + ["stages[1].duration=0.26"]


# --- Events, and a block's history through one -------------------------------------------------------

@functools.lru_cache(maxsize=256)
def _cached_table(directory, name, versions):
    return table(directory, name)


def run_table(run_dir, name):
    """table(run_dir, name), read once while its file stays the same: every measure below reads
    the same block tables again."""
    directory = os.path.abspath(run_directory(run_dir))
    paths = [os.path.join(directory, name + ext) for ext in (".csv", ".h5")]
    versions = tuple((os.stat(p).st_mtime_ns, os.stat(p).st_size) for p in paths if os.path.exists(p))
    return _cached_table(directory, name, versions)


def events_of(run_dir):
    events = run_table(run_dir, "precursors")
    if events is None:
        raise LookupError(f"{run_directory(run_dir)}: no rupture events (no precursors table)")
    return events


def interface_blocks(run_dir):
    return int(scene_of(run_dir)["bulk"]["nx"])


def block_spacing(run_dir):
    return float(scene_of(run_dir)["bulk"]["length"]) / (interface_blocks(run_dir) - 1)


def first_global_slip(run_dir):
    """The event number of the run's first global slip; LookupError if it has none."""
    events = events_of(run_dir)
    found = np.flatnonzero(events["global"] > 0.5)
    if not found.size:
        raise LookupError(f"{run_directory(run_dir)}: no global slip")
    return int(events["event"][found[0]])


def first_event_reaching(run_dir, block):
    """The first event whose rupture reached `block`: the paper's Fig. 9 event for blocks 1..10 (its
    first rupture event reached them; the headline's first precursor is shorter)."""
    events = events_of(run_dir)
    found = np.flatnonzero(events["max_ruptured_x"] >= (block - 0.5) * block_spacing(run_dir))
    if not found.size:
        raise LookupError(f"{run_directory(run_dir)}: no event reached block {block}")
    return int(events["event"][found[0]])


def event_row(run_dir, event):
    events = events_of(run_dir)
    found = np.flatnonzero(events["event"] == event)
    if not found.size:
        raise LookupError(f"{run_directory(run_dir)}: no event {event}")
    return int(found[0])


def event_window(run_dir, event):
    """(start, end) of the time a block's phases through `event` lie in: from LEAD before it, not
    into the previous event, PHASES_SPAN long, not into the next event."""
    events, k = events_of(run_dir), event_row(run_dir, event)
    start, end = events["t_start"][k] - LEAD, events["t_start"][k] + PHASES_SPAN
    if k > 0:
        start = max(start, events["t_end"][k - 1])
    if k + 1 < len(events):
        end = min(end, events["t_start"][k + 1])
    return start, end


def block_history(run_dir, block, window):
    """Rows of the block's contact_area table within `window`."""
    rows = run_table(run_dir, f"contact_area_block_{block}")
    if rows is None:
        raise LookupError(f"{run_directory(run_dir)}: no contact_area_block_{block} table: run with "
                          f"run_overrides(), or add the block to the contact_area observer")
    return rows[(rows["time"] >= window[0]) & (rows["time"] < window[1])]


def phase_entries(rows):
    """When the block enters phases I-IV (None where it does not), by phase_boundaries; all None if
    the rupture never detached it (its pinned fraction never fell below half, as four_phase asks)."""
    if not rows.size or not np.any(rows["pinned_fraction"] < DETACHED):
        return [None] * 4
    return phase_boundaries(rows["time"], rows)


def entered_stuck(rows):
    """Whether the block entered the window stuck, as the paper's blocks did, not still detached."""
    return bool(rows.size) and bool(rows["pinned_fraction"][0] >= DETACHED)


def slip_at(rows, t):
    return float(np.interp(t, rows["time"], rows["slip"]))


def fast_slip_onset(rows):
    """"The instant when fast slip starts" (Δ's origin in Fig. 9c): the last row before the block's
    peak speed at which it slipped slower than FAST_SLIP_START of it. Kinematic, so a block whose
    contacts partly let go before the event (by creep ahead of an arrested precursor) is aligned by
    its slip, as the paper aligns it, not by its junctions."""
    speed = np.abs(rows["velocity"])
    peak = int(np.argmax(speed))
    slow = np.flatnonzero(speed[:peak] < FAST_SLIP_START * speed[peak])
    return float(rows["time"][slow[-1] if slow.size else 0])


# --- 1. The four phases of one block -----------------------------------------------------------------

def phases(run_dir, event=None, block=PAPER_BLOCK):
    """The four phases of interface block `block` (0-based) through `event` (precursors.csv's
    number; default the first global slip): when it enters each (s, and since the event started),
    how long each lasts, the slip in it, its mean slip rate and peak speed. `in_order`: all four
    present, each lasting, in order; `brief_detachment`: phase I shorter than phase II, as the
    contacts' breaking that precedes the fast slip; `stuck_before`: the block entered the event
    stuck, as the paper's did, not still detached by an earlier rupture.
    Phase IV lasts to the end of the window (event_window)."""
    event = first_global_slip(run_dir) if event is None else int(event)
    rows = block_history(run_dir, block, event_window(run_dir, event))
    entries = phase_entries(rows)
    ends = entries[1:] + [float(rows["time"][-1]) if rows.size else None]
    t_event = float(events_of(run_dir)["t_start"][event_row(run_dir, event)])
    record = {"event": event, "block": block, "reached": entries[0] is not None, "stuck_before": entered_stuck(rows),
              "phases": []}
    for (label, name), start, stop in zip(PHASES, entries, ends):
        phase = {"phase": label, "name": name, "enters": start,
                 "enters_since_event": None if start is None else start - t_event}
        if start is not None and stop is not None and stop > start:
            inside = (rows["time"] >= start) & (rows["time"] <= stop)
            slip = slip_at(rows, stop) - slip_at(rows, start)
            phase.update(duration=stop - start, slip=slip, mean_rate=slip / (stop - start),
                         peak_speed=float(np.max(np.abs(rows["velocity"][inside]))))
        record["phases"].append(phase)
    record["in_order"] = all("duration" in p for p in record["phases"])
    fast, slow = record["phases"][1:3]
    record["brief_detachment"] = record["in_order"] and record["phases"][0]["duration"] < fast["duration"]
    record["fast_over_slow"] = math.nan
    if "mean_rate" in fast and "mean_rate" in slow:
        record["fast_over_slow"] = abs(fast["mean_rate"]) / abs(slow["mean_rate"]) if slow["mean_rate"] else math.inf
    return record


# --- 2. The collapse of the normalised slip histories ------------------------------------------------

def collapse(run_dir, blocks=None, event=None, rescale_time=False, stuck_only=True):
    """How well the blocks' slip histories through `event` (default the first global slip) collapse
    once normalised as the paper does: Δ/Δ_tot against time since the block's fast slip started
    (fast_slip_onset), Δ_tot its slip up to the end of phase III. The measure, `normalised`, is the
    RMS over a time grid of the standard deviation across blocks (`peak`: its largest value); as
    the reference that gives it meaning, `unnormalised` is the same for Δ over the blocks' mean
    Δ_tot (both fractions of a final slip), `ratio` the first over the second. The grid runs to
    the blocks' median onset-to-end-of-III span (one odd block does not cut it short);
    rescale_time divides each block's time by its own span (grid 0..1). blocks: default ten spread
    along the interface; stuck_only leaves out (`left_out`) those that entered the event still in
    the phases of an earlier rupture, whose phase III ends with that rupture's, not this one's.
    LookupError if the event did not detach a block or its slow slip did not end in its window."""
    event = first_global_slip(run_dir) if event is None else int(event)
    blocks = spread_blocks(interface_blocks(run_dir)) if blocks is None else list(blocks)
    window = event_window(run_dir, event)
    used, left_out, onsets, spans, totals, histories = [], [], [], [], [], []
    for block in blocks:
        rows = block_history(run_dir, block, window)
        if stuck_only and not entered_stuck(rows):
            left_out.append(block)
            continue
        end = phase_entries(rows)[3]
        if end is None:
            raise LookupError(f"{run_directory(run_dir)}: in event {event}, block {block} was not detached or its "
                              f"slow slip did not end")
        onset = fast_slip_onset(rows[rows["time"] < end])
        slip0 = slip_at(rows, onset)
        used.append(block)
        onsets.append(onset)
        spans.append(end - onset)
        totals.append(slip_at(rows, end) - slip0)
        histories.append((rows["time"] - onset, rows["slip"] - slip0))
    if len(used) < 2:
        raise LookupError(f"{run_directory(run_dir)}: fewer than two blocks entered event {event} stuck")
    spans, totals = np.array(spans), np.array(totals)
    grid = np.linspace(0.0, 1.0 if rescale_time else float(np.median(spans)), GRID_POINTS)
    slips = np.array([np.interp(grid * (span if rescale_time else 1.0), tau, slip)
                      for (tau, slip), span in zip(histories, spans)])
    curves = {"normalised": slips / totals[:, None], "unnormalised": slips / totals.mean()}
    spread = {name: np.std(c, axis=0) for name, c in curves.items()}
    rms = {name: float(np.sqrt(np.mean(s ** 2))) for name, s in spread.items()}
    return {"event": event, "blocks": used, "left_out": left_out, "rescale_time": rescale_time, **rms,
            "peak": float(spread["normalised"].max()),
            "ratio": rms["normalised"] / rms["unnormalised"] if rms["unnormalised"] else math.nan,
            "onsets": onsets, "spans": spans.tolist(), "final_slips": totals.tolist(), "time": grid,
            "normalised_curves": curves["normalised"], "unnormalised_curves": curves["unnormalised"]}


def backslip(run_dir, blocks=None, event=None):
    """Fig. 9c's inset: between phases II and III "the normalized displacement decreases first and
    then increases". Per block, the largest fall of Δ/Δ_tot below its running maximum up to the end
    of phase III (0 if it never falls)."""
    curves = collapse(run_dir, blocks, event, rescale_time=True)["normalised_curves"]
    return (np.maximum.accumulate(curves, axis=1) - curves).max(axis=1)


# --- 3. Statements -----------------------------------------------------------------------------------

SETTINGS = {  # name: (what it measures, run -> (event, blocks))
    "global": ("the first global slip, ten blocks spread along the interface",
               lambda run: (first_global_slip(run), spread_blocks(interface_blocks(run)))),
    "paper": ("as the paper: the first event to reach blocks 1-10, those blocks",
              lambda run: (first_event_reaching(run, PAPER_BLOCKS[-1]), list(PAPER_BLOCKS))),
}


def measure_run(run, setting):
    """One run in one setting: its event, each block's phases, the collapse and the back-slips (None
    where a block lacks a phase boundary); {"missing": why} if the run has no such event."""
    try:
        event, blocks = SETTINGS[setting][1](run)
    except LookupError as missing:
        return {"run": run, "missing": str(missing)}
    measured = {"run": run, "event": event, "phases": [phases(run, event, b) for b in blocks]}
    try:
        measured["collapse"] = collapse(run, blocks, event)
        measured["backslip"] = backslip(run, blocks, event)
    except LookupError:
        measured["collapse"] = measured["backslip"] = None
    return measured


def mean_interval(values, digits=3):
    """(Effect, 'mean [low, high]') over the runs: frictionlab.ensembles' 95 % bootstrap interval,
    or why there is none."""
    e = ensembles.mean(values)
    text = f"{e.estimate:.{digits}f}"
    return e, f"{text} ({e.interval})" if e.interval else f"{text} [{e.low:.{digits}f}, {e.high:.{digits}f}]"


def upper(e):
    """The effect's upper 95 % bound, or its estimate where it has no interval."""
    return e.estimate if e.interval else e.high


def share_verdict(share):
    return "reproduced" if share >= ALL else "reproduced within a stated margin" if share >= MOST else "differs"


def statement(figure, what, claim, measured, verdict, margin=""):
    return Statement(figure, f"{claim} ({what})", measured, verdict, margin)


def statements(run_dirs):
    """Fig. 9's statements measured over the runs given (seeds of SCENE with run_overrides), on the
    first global slip and in the paper's setting: report Statements."""
    run_dirs = [os.fspath(r) for r in run_dirs]
    out = []
    for setting, (what, _) in SETTINGS.items():
        measured = [measure_run(run, setting) for run in run_dirs]
        runs = [m for m in measured if "missing" not in m]
        lacking = f"; {len(measured) - len(runs)} of {len(measured)} runs lack the event" if len(runs) < len(measured) \
            else ""
        if not runs:
            out.append(statement("Fig. 9", what, "the event exists", "no run has it" + lacking, "differs",
                                 "the runs lack the event: none of Fig. 9 can be measured"))
            continue
        out += [phase_order_statement(runs, what, lacking), detachment_statement(runs, what),
                rate_statement(runs, what), collapse_statement(runs, what), backslip_statement(runs, what)]
    return out


def blocks_of(runs):
    return [r for run in runs for r in run["phases"]]


def median_duration_us(records, k):
    return np.nanmedian([r["phases"][k].get("duration", math.nan) for r in records]) * 1e6


def phase_order_statement(runs, what, lacking):
    records = blocks_of(runs)
    worst = min(np.mean([r["in_order"] for r in run["phases"]]) for run in runs)
    verdict = share_verdict(worst)
    unsettled = sum(not r["stuck_before"] for r in records)
    unsettled = f"; {unsettled} entered it still in an earlier rupture's phases" if unsettled else ""
    return statement("Fig. 9a, b", what, "a block passes four phases in order: detachment (I), fast slip (II), slow "
                     "slip (III), rejuvenation (IV)",
                     f"all four, in order, in {sum(r['in_order'] for r in records)} of {len(records)} blocks over "
                     f"{len(runs)} runs (worst run: {worst:.0%}); median durations I "
                     f"{median_duration_us(records, 0):.0f} us, II {median_duration_us(records, 1):.0f} us, III "
                     f"{median_duration_us(records, 2):.0f} us{unsettled}{lacking}",
                     verdict, "" if verdict == "reproduced" else f"in at least {MOST:.0%} of each run's blocks")


def detachment_statement(runs, what):
    """The paper's phase I is the contacts' breaking before the fast slip, not part of it."""
    records = blocks_of(runs)
    share = np.mean([r["brief_detachment"] for r in records])
    verdict = share_verdict(share)
    slip_in_i = np.median([r["phases"][0]["slip"] / (r["phases"][0]["slip"] + r["phases"][1]["slip"])
                           for r in records if r["in_order"]] or [math.nan])
    return statement("Fig. 9a, b", what, "detachment (I), all contacts pinned then breaking, precedes the fast slip "
                     "(II), which carries the high slip velocity",
                     f"phase I (to the block's peak speed) shorter than phase II in {share:.0%} of the blocks; median "
                     f"I {median_duration_us(records, 0):.0f} us against II {median_duration_us(records, 1):.0f} us; "
                     f"median share of phases I+II's slip in phase I: {slip_in_i:.0%}",
                     verdict, "" if verdict == "reproduced" else f"in at least {MOST:.0%} of the blocks")


def rate_statement(runs, what):
    """Ben-David et al. 2010, whom the paper follows: slow slip about ten times slower than fast."""
    medians = [float(np.nanmedian([r["fast_over_slow"] for r in run["phases"]])) for run in runs]
    e, text = mean_interval(np.log10(medians), 2)
    slow_share = np.nanmedian([r["phases"][2]["slip"] / sum(p["slip"] for p in r["phases"][:3])
                               for r in blocks_of(runs) if r["in_order"]] or [math.nan])
    ratio = 10 ** e.estimate
    verdict = "reproduced" if ratio >= TEN_TIMES else "reproduced within a stated margin" if ratio >= MUCH_SLOWER \
        else "differs"
    return statement("Fig. 9a", what, "phase III slips at a velocity much slower than phase II (the experiments: "
                     "about ten times slower)",
                     f"mean slip rate of phase II over phase III's, median over the blocks: geometric mean "
                     f"{ratio:.3g} over {len(runs)} runs (log10: {text}); median share of phases I-III's slip "
                     f"in phase III: {slow_share:.0%}",
                     verdict, "" if verdict == "reproduced" else
                     f"'much slower' taken as at least {MUCH_SLOWER:g} times; the experiments' ten not reached")


def collapse_statement(runs, what):
    measured = [run["collapse"] for run in runs if run["collapse"] is not None]
    if not measured:
        return statement("Fig. 9c", what, "the normalised slip histories of ten blocks collapse",
                         "no run has every block's phases I-III", "differs", "nothing to normalise")
    e, text = mean_interval([c["normalised"] for c in measured])
    r, ratio_text = mean_interval([c["ratio"] for c in measured], 2)
    reference = np.mean([c["unnormalised"] for c in measured])
    peak = np.mean([c["peak"] for c in measured])
    left_out = sum(len(c["left_out"]) for c in measured)
    left_out = f"; {left_out} blocks left out, still in an earlier rupture's phases" if left_out else ""
    if upper(e) <= COLLAPSED and upper(r) <= NARROWED:
        verdict, margin = "reproduced", ""
    elif upper(e) <= APPROXIMATE:
        verdict = "reproduced within a stated margin"
        margin = (f"'approximate' taken as an RMS spread within {APPROXIMATE:g} of the final slip; collapsed would be "
                  f"within {COLLAPSED:g}, normalising at least halving the unnormalised spread")
        if upper(e) <= COLLAPSED:
            margin = (f"the curves lie within {COLLAPSED:g} of the final slip, but normalising does not surely halve "
                      f"their spread (the ratio's upper bound is above {NARROWED:g}): where the blocks' final slips "
                      f"barely differ, a collapse cannot show that their motion is independent of Δ_tot")
    else:
        verdict, margin = "differs", f"an approximate collapse would be an RMS spread within {APPROXIMATE:g}"
    return statement("Fig. 9c", what, "the normalised slip histories Δ/Δ_tot of ten blocks, against time since "
                     "their fast slip started, collapse approximately onto one curve",
                     f"RMS over time of the spread (standard deviation across blocks) of Δ/Δ_tot: {text} (at its "
                     f"largest {peak:.2f}); of Δ/mean Δ_tot: {reference:.3f}; ratio {ratio_text}; over "
                     f"{len(measured)} runs{'' if len(measured) == len(runs) else f' of {len(runs)}'}{left_out}",
                     verdict, margin)


def backslip_statement(runs, what):
    falls = np.concatenate([run["backslip"] for run in runs if run["backslip"] is not None] or [np.zeros(0)])
    share = float(np.mean(falls > BACKSLIP)) if falls.size else 0.0
    verdict = share_verdict(share)
    return statement("Fig. 9c inset", what, "between phases II and III the normalised slip first decreases, then "
                     "increases",
                     f"Δ/Δ_tot falls below its running maximum by more than {BACKSLIP:g} in {share:.0%} of the "
                     f"blocks; median fall {np.median(falls) if falls.size else math.nan:.3f}",
                     verdict, "" if verdict == "reproduced" else f"in at least {MOST:.0%} of the blocks")


# --- 4. The figure -----------------------------------------------------------------------------------

def figure(run_dir, path, block=PAPER_BLOCK):
    """Fig. 9 of the run, for the first global slip (top) and in the paper's setting (bottom): block
    `block`'s junction states and slip with phases I-IV shaded (Fig. 9a, b), and the ten blocks'
    normalised slip histories over their unnormalised ones (Fig. 9c); written to `path` by Agg
    (a bare Figure: pyplot's state and backend are left alone)."""
    from matplotlib.figure import Figure

    fig = Figure(figsize=(13, 8))
    axes = fig.subplots(2, 2, gridspec_kw={"width_ratios": [1, 1.2]})
    for row, (what, choose) in zip(axes, SETTINGS.values()):
        try:
            event, blocks = choose(run_dir)
            draw_phases(row[0], run_dir, event, block)
            draw_collapse(row[1], run_dir, event, blocks, what)
        except LookupError as missing:
            for ax in row:
                ax.text(0.5, 0.5, str(missing), transform=ax.transAxes, ha="center", va="center", fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=150)
    return path


def draw_phases(ax, run_dir, event, block):
    record = phases(run_dir, event, block)
    rows = block_history(run_dir, block, event_window(run_dir, event))
    onset = record["phases"][0]["enters"]
    if onset is None:
        raise LookupError(f"event {event} did not detach block {block}")
    t = (rows["time"] - onset) * 1e3
    for name, color in (("pinned", "tab:green"), ("sliding", "tab:red"), ("dislocated", "tab:blue")):
        ax.plot(t, rows[name + "_fraction"], color=color, lw=1, label=name)
    ax.set_ylabel("junction fraction")
    ax.set_xlabel(f"time since block {block + 1}'s contacts began to let go (ms)")
    slip = ax.twinx()
    slip.plot(t, (rows["slip"] - slip_at(rows, onset)) * 1e6, "k", lw=1.5)
    slip.set_ylabel(r"slip $\Delta$ ($\mu$m, black)")
    shown = min(t[-1], 3.0)
    for k, p in enumerate(record["phases"]):
        if "duration" not in p:
            continue
        a, b = (p["enters"] - onset) * 1e3, min((p["enters"] + p["duration"] - onset) * 1e3, shown)
        if k % 2 == 0:
            ax.axvspan(a, b, color="0.92", zorder=0)
        ax.text((a + b) / 2, 1.01, p["phase"], transform=ax.get_xaxis_transform(), ha="center", va="bottom",
                fontsize=9, fontweight="bold")
    ax.set_xlim(-0.1, shown)
    ax.legend(loc="center right", fontsize=7, frameon=False)
    ax.set_title(f"event {event}, block {block + 1} (index {block}): phases I-IV", fontsize=9, pad=14)


def draw_collapse(ax, run_dir, event, blocks, what):
    c = collapse(run_dir, blocks, event)
    t = c["time"] * 1e3
    for block, normalised, unnormalised in zip(c["blocks"], c["normalised_curves"], c["unnormalised_curves"]):
        ax.plot(t, unnormalised, color="0.78", lw=0.8)
        ax.plot(t, normalised, lw=1, label=f"{block + 1}")
    ax.set_xlabel("time since the block's fast slip started (ms)")
    ax.set_ylabel(r"$\Delta/\Delta_{tot}$ (grey: $\Delta/\langle\Delta_{tot}\rangle$)")
    ax.legend(title="block", fontsize=7, ncol=2, frameon=False, loc="lower right")
    left_out = f"; left out, still detached: {', '.join(str(b + 1) for b in c['left_out'])}" if c["left_out"] else ""
    ax.set_title(f"{what}\nRMS spread {c['normalised']:.3f} normalised, {c['unnormalised']:.3f} unnormalised"
                 f"{left_out}", fontsize=9)
