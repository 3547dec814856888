"""The rupture-front signatures of Trømborg et al. (PNAS 111, 8764, 2014; PRE 92, 012408, 2015)
measured on finished runs of configs/tromborg2014/pnas2014.yaml, each with a verdict.

    frictionlab run configs/tromborg2014/pnas2014.yaml -o DIR --set seed=S --set ... (run_overrides)
    PYTHONPATH=apps/python /usr/bin/python3 -m frictionlab.reproduce.tromborg_signatures DIR [DIR ...]

Every measure takes one run directory or several (an ensemble of seeds) and reads only the tables
the runs wrote: precursors.csv and precursor_fronts.csv (the `precursors` observer), the interface
velocity and slip of `interface_history`, and run.yaml (the resolved scene)."""
import argparse
import os
from typing import Dict, List, Sequence, Tuple, Union

import numpy as np
import pandas as pd
from scipy import optimize, stats

from .._run import Run

SCENE = "tromborg2014/pnas2014.yaml"  # below configs/

# A front is fast at or above a tenth of c_S: Rubinstein et al. (Nature 430, 1005, 2004) call fronts
# slow when they are more than ten times below c_R, and the PNAS slow fronts (1-100 m/s against
# c_S ~ 1000 m/s) lie below it, the fast ones (a good fraction of c_R) above it.
FAST_FRACTION_OF_CS = 0.1
# "Drops by an order of magnitude" (PNAS 2014): the fast segment's median speed over the slow one's.
ORDER_OF_MAGNITUDE = 10.0
# A segment must span this many blocks (5 mm), so that one noisy block makes no segment.
SEGMENT_BLOCKS = 2
# A precursor comes from the driven edge when it nucleates within this fraction of L of it.
DRIVEN_EDGE = 0.05
# A front must run this many blocks: room for a fast and a slow segment, and for a centred window.
MIN_FRONT_BLOCKS = 2 * SEGMENT_BLOCKS
# The local speed at a block is the least-squares slope of arrival time against distance over this
# many blocks centred on it (5 mm): arrivals are resolved to front_every = 1 us, so a front at c_S
# (2.5 us a block) is measured to about +-30 %, and a transition is placed to within a block.
WINDOW_BLOCKS = 3
# Trømborg et al. 2015 compare the slip speed right behind the front tip: measured over the time the
# front takes to run this many blocks on (at least two samples of the history).
LOOKAHEAD_BLOCKS = 2
# The PNAS slow fronts: ~1-100 m/s, a few % of c_S ~ 1000 m/s for PMMA.
SLOW_FRONT_RANGE = (1.0, 100.0)
# Proportionality: the free log-log slope within this of 1, with at least this correlation.
SLOPE_MARGIN, LOOSE_SLOPE_MARGIN, MIN_CORRELATION = 0.2, 0.4, 0.7

SOURCES = {
    "pnas": "Trømborg et al., PNAS 111, 8764 (2014)",
    "pre": "Trømborg et al., PRE 92, 012408 (2015)",
    "precursors": "Rubinstein et al., PRL 98, 226103 (2007); Trømborg et al., PRL 107, 074301 (2011)",
}


def run_overrides(quick: bool) -> List[str]:
    """The --set overrides every run needs: the observers at the cadence the measures need (arrivals
    at the precursors' front_every, 1 us; slip from the interface history every 10 us, in HDF5 on the
    full run: 170 MB a run instead of ~450 MB of CSV). The quick variant (CI: ~40 CPU-s a seed, 38 MB
    of CSV) drives 10x faster (4 mm/s) for 60 ms: its first precursor and global slip come at the
    full run's F_S/F_N (0.16 and 0.22), 0.03 and 0.05 s into loading instead of 0.32 and 0.47 s."""
    history = "{type: interface_history, every: 1.0e-5" + ("}" if quick else ", format: hdf5}")
    observers = f"observers=[{{type: loading_curve, every: 1.0e-5}}, {{type: precursors, every: 1.0e-5}}, {history}]"
    return [observers, "loaders[2].velocity=4.0e-3", "stages[1].duration=0.06"] if quick else [observers]


def seeds(quick: bool) -> List[int]:
    return [1, 2] if quick else list(range(1, 11))


# ---------------------------------------------------------------------------------------------
# Reading runs

RunDirs = Union[str, os.PathLike, Sequence[Union[str, os.PathLike]]]


def _directories(run_dirs: RunDirs) -> List[str]:
    return [os.fspath(run_dirs)] if isinstance(run_dirs, (str, os.PathLike)) else [os.fspath(d) for d in run_dirs]


def lattice_wave_speeds(run_dir: str) -> Dict[str, float]:
    """c_S, c_L and c_R of the run's lattice (theory.md §1): C44 = 3E/8 and C11 = 9E/8 (plane stress,
    nu = 1/3: the nearest + diagonal lattice with diagonals K/2, a 3D Poisson ratio of 1/4), with the
    density of the reference-spacing lattice, m_ref/(l_ref^2 B), m_ref = M over its nodes (theory.md §1a)."""
    bulk = {k: float(v) for k, v in Run(run_dir).metadata["scene"]["bulk"].items() if k != "type"
            and _is_number(v)}  # float(): PyYAML reads 3e+09 (no dot) as a string
    length, height, width = bulk["length"], bulk["height"], bulk["width"]
    spacing = length / (bulk["nx"] - 1)
    reference = bulk.get("reference_spacing", spacing) or spacing
    nodes = (bulk["nx"] * bulk["nz"] if reference == spacing else
             (round(length / reference) + 1) * (round(height / reference) + 1))
    density = bulk["mass"] / nodes / (reference ** 2 * width)
    c_s = np.sqrt(3.0 * bulk["youngs_modulus"] / 8.0 / density)
    c_l = np.sqrt(3.0) * c_s
    return {"c_S": c_s, "c_L": c_l, "c_R": rayleigh_fraction(c_s / c_l) * c_s, "density": density,
            "spacing": spacing, "length": length}


def _is_number(value) -> bool:
    try:
        float(value)
        return True
    except (TypeError, ValueError):
        return False


def rayleigh_fraction(shear_over_longitudinal: float) -> float:
    """c_R/c_S, the root of (2 - x^2)^2 = 4 sqrt(1 - x^2) sqrt(1 - k^2 x^2), k = c_S/c_L (0.919 at k^2 = 1/3)."""
    k2 = shear_over_longitudinal ** 2
    return optimize.brentq(lambda x: (2 - x * x) ** 2 - 4 * np.sqrt(1 - x * x) * np.sqrt(1 - k2 * x * x), 0.5, 0.999999)


def events(run_dir: str) -> pd.DataFrame:
    """The finished events of precursors.csv in time order (an unfinished one has an incomplete front)."""
    table = Run(run_dir).frame("precursors")
    return table[table["finished"].astype(bool)].sort_values("t_start").reset_index(drop=True)


# ---------------------------------------------------------------------------------------------
# Signatures 1 and 2: the front speed along its path

def split_fronts(front: pd.DataFrame) -> List[pd.DataFrame]:
    """One event's arrivals (rows of precursor_fronts.csv) split into its fronts, each in the order
    it ran: a front runs from a block where the rupture arrived before its neighbours (a nucleation,
    shared by the two fronts it starts) until the block before one where it arrived after them (where
    two fronts met: that block's arrival is either's). A block's arrival is the middle of the interval
    it lies in (time - resolution/2); neighbours arriving within their resolution of each other tie,
    and a tie does not turn a front. Each front gets its `direction` (+1 towards the leading edge) and
    `path`, the distance it ran to each block."""
    table = front.sort_values("x").assign(arrival=lambda t: t["time"] - t["resolution"] / 2)
    arrival, resolution = table["arrival"].to_numpy(), table["resolution"].to_numpy()
    step = np.diff(arrival)
    signs = pd.Series(np.where(np.abs(step) <= np.maximum(resolution[1:], resolution[:-1]), np.nan, np.sign(step)))
    signs = signs.ffill().bfill().fillna(1.0).to_numpy()  # ties join the front they lie in
    turns = np.flatnonzero(np.diff(signs)) + 1  # blocks where the direction turns
    bounds = np.concatenate(([0], turns, [len(table) - 1]))
    fronts = []
    for k, (first, last) in enumerate(zip(bounds[:-1], bounds[1:])):
        direction = int(signs[first]) if len(signs) else 1
        meeting_first = k > 0 and direction < 0    # the turn before is a meeting point
        meeting_last = k < len(turns) and direction > 0
        piece = table.iloc[first + meeting_first:last + 1 - meeting_last].iloc[::direction]
        if len(piece):
            fronts.append(piece.assign(direction=direction, path=np.abs(piece["x"] - piece["x"].iloc[0])))
    return fronts


def local_speeds(path: np.ndarray, arrival: np.ndarray, fastest: float,
                 window_blocks: int = WINDOW_BLOCKS) -> np.ndarray:
    """The local speed of one front at each of its blocks: the inverse least-squares slope of arrival
    against path over `window_blocks` blocks centred on it (fewer at the front's ends); faster than
    `fastest` (c_L: no wave of the lattice is faster), or a slope <= 0, is no resolved front: inf."""
    half = window_blocks // 2
    speed = np.full(len(path), np.inf)
    for k in range(len(path)):
        window = slice(max(0, k - half), min(len(path), k + half + 1))
        if np.ptp(path[window]) > 0:
            slope = np.polyfit(path[window], arrival[window], 1)[0]
            if slope * fastest > 1:
                speed[k] = 1.0 / slope
    return speed


def front_profiles(run_dirs: RunDirs) -> pd.DataFrame:
    """Every finished event's fronts (split_fronts) of MIN_FRONT_BLOCKS blocks or more that ran at a
    resolved speed (a finite median), with the local speed at each block (local_speeds), its run,
    event, front number, whether it is a global slip, its F_S/F_N and the run's c_S. Shorter pieces lie
    between patches that broke on their own, too short for a centred window; a piece whose blocks
    broke within the resolution of each other (faster than c_L) is the interface slipping at once."""
    frames = []
    for run_dir in _directories(run_dirs):
        waves = lattice_wave_speeds(run_dir)
        arrivals = Run(run_dir).frame("precursor_fronts")
        for _, event in events(run_dir).iterrows():
            for number, front in enumerate(split_fronts(arrivals[arrivals["event"] == event["event"]])):
                if len(front) < MIN_FRONT_BLOCKS:
                    continue
                speed = local_speeds(front["path"].to_numpy(), front["arrival"].to_numpy(), waves["c_L"])
                if np.median(speed) < np.inf:
                    frames.append(front.assign(front=number, speed=speed, run=run_dir,
                                               global_slip=bool(event["global"]), force_ratio=event["force_ratio"],
                                               c_S=waves["c_S"]))
    return pd.concat(frames, ignore_index=True) if frames else pd.DataFrame()


def all_events(run_dirs: RunDirs) -> pd.DataFrame:
    """Every run's finished events (events), with the run they belong to."""
    frames = [events(run_dir).assign(run=run_dir) for run_dir in _directories(run_dirs)]
    return pd.concat(frames, ignore_index=True) if frames else pd.DataFrame(columns=["run", "event", "global"])


def _segments(mask: np.ndarray, min_blocks: int) -> List[Tuple[int, int]]:
    """The runs [start, stop) of consecutive True in `mask`, at least min_blocks long."""
    edges = np.flatnonzero(np.diff(np.concatenate(([0], mask.astype(int), [0]))))
    return [(a, b) for a, b in zip(edges[::2], edges[1::2]) if b - a >= min_blocks]


def fast_then_slow(speed: np.ndarray, x: np.ndarray, fast_speed: float,
                   min_blocks: int = SEGMENT_BLOCKS) -> Dict[str, float]:
    """Along one front (speeds in the order it ran): its first fast segment (>= fast_speed over
    min_blocks blocks) followed by a slow one (below it over min_blocks), their median speeds, the drop
    (fast over slow) and where the slow segment starts. Without such a pair the medians are over all
    the front's fast and all its slow blocks (NaN where there are none) and the drop is NaN."""
    fast = speed >= fast_speed
    for a, b in _segments(fast, min_blocks):
        slow = [s for s in _segments(~fast, min_blocks) if s[0] >= b]
        if slow:
            fast_median, slow_median = np.median(speed[a:b]), np.median(speed[slow[0][0]:slow[0][1]])
            return {"fast_then_slow": True, "fast_speed": fast_median, "slow_speed": slow_median,
                    "drop": fast_median / slow_median, "transition_x": x[slow[0][0]]}
    medians = [np.median(speed[m]) if m.any() else np.nan for m in (fast, ~fast)]
    return {"fast_then_slow": False, "fast_speed": medians[0], "slow_speed": medians[1], "drop": np.nan,
            "transition_x": np.nan}


def front_transitions(run_dirs: RunDirs, profiles: pd.DataFrame = None) -> pd.DataFrame:
    """Signature 1, one row per front (run, event, front): fast_then_slow with the threshold
    FAST_FRACTION_OF_CS c_S, the front's direction and its blocks."""
    profiles = front_profiles(run_dirs) if profiles is None else profiles
    rows = []
    if profiles.empty:
        return pd.DataFrame(rows)
    for (run, event, number), front in profiles.groupby(["run", "event", "front"]):
        found = fast_then_slow(front["speed"].to_numpy(), front["x"].to_numpy(),
                               FAST_FRACTION_OF_CS * front["c_S"].iloc[0])
        rows.append({"run": run, "event": event, "front": number, "direction": front["direction"].iloc[0],
                     "global_slip": front["global_slip"].iloc[0], "force_ratio": front["force_ratio"].iloc[0],
                     "blocks": len(front), **found})
    return pd.DataFrame(rows)


def slow_front_speeds(run_dirs: RunDirs, profiles: pd.DataFrame = None) -> pd.DataFrame:
    """Signature 2, one row per event with a front: the speeds of its slow blocks (below
    FAST_FRACTION_OF_CS c_S, every front): median, 10th and 90th percentiles in m/s, the median over
    c_S, and their count."""
    profiles = front_profiles(run_dirs) if profiles is None else profiles
    rows = []
    if profiles.empty:
        return pd.DataFrame(rows)
    for (run, event), fronts in profiles.groupby(["run", "event"]):
        c_s = fronts["c_S"].iloc[0]
        slow = fronts.loc[fronts["speed"] < FAST_FRACTION_OF_CS * c_s, "speed"].to_numpy()
        p10, median, p90 = np.percentile(slow, [10, 50, 90]) if len(slow) else (np.nan,) * 3
        rows.append({"run": run, "event": event, "global_slip": fronts["global_slip"].iloc[0],
                     "slow_blocks": len(slow), "median": median, "p10": p10, "p90": p90, "c_S": c_s,
                     "median_over_c_S": median / c_s})
    return pd.DataFrame(rows)


# ---------------------------------------------------------------------------------------------
# Signature 3: slip speed against front speed

def slip_speeds_behind_front(front: pd.DataFrame, time: np.ndarray, velocity: Dict[int, np.ndarray],
                             slip: Dict[int, np.ndarray], spacing: float,
                             lookahead_blocks: int = LOOKAHEAD_BLOCKS) -> Tuple[np.ndarray, np.ndarray]:
    """For each block of one front (in the order it ran), its slip speed right behind the tip: from
    the first sample after its arrival until the front has run lookahead_blocks on (their arrival;
    past the front's end, at its local speed), at least two samples of the history. Both the peak of vx and
    the mean slip rate (slip gained over the window's time): behind a slow front the slider rings at
    +-5-10 mm/s, more than the slow slip itself, and the mean averages that out where the peak cannot."""
    arrival, speed = front["arrival"].to_numpy(), front["speed"].to_numpy()
    peak, mean = np.full(len(front), np.nan), np.full(len(front), np.nan)
    for k, block in enumerate(front["block"].astype(int)):
        ahead = arrival[k + lookahead_blocks] - arrival[k] if k + lookahead_blocks < len(arrival) else \
            lookahead_blocks * spacing / speed[k]
        start = np.searchsorted(time, arrival[k])
        stop = min(len(time), max(start + 2, np.searchsorted(time, arrival[k] + max(ahead, 0.0), side="right")))
        if stop - start >= 2:
            peak[k] = np.max(velocity[block][start:stop])
            mean[k] = (slip[block][stop - 1] - slip[block][start]) / (time[stop - 1] - time[start])
    return peak, mean


def slip_and_front_speeds(run_dirs: RunDirs, profiles: pd.DataFrame = None) -> pd.DataFrame:
    """Signature 3, one row per block of every front: the local front speed, and the peak slip speed
    and mean slip rate right behind it (slip_speeds_behind_front), from the interface history."""
    frames = []
    profiles = front_profiles(run_dirs) if profiles is None else profiles
    for run_dir in _directories(run_dirs):
        fronts = profiles[profiles["run"] == run_dir] if len(profiles) else profiles
        if fronts.empty:
            continue
        run = Run(run_dir)
        velocity, slip = run.table("interface_velocity"), run.table("interface_slip")
        blocks = fronts["block"].astype(int).unique()
        by_block = [{b: table[f"block_{b}"] for b in blocks} for table in (velocity, slip)]
        spacing = lattice_wave_speeds(run_dir)["spacing"]
        for _, front in fronts.groupby(["event", "front"]):
            peak, mean = slip_speeds_behind_front(front, velocity["time"], *by_block, spacing)
            frames.append(front.assign(peak_slip_speed=peak, mean_slip_rate=mean))
    return pd.concat(frames, ignore_index=True) if frames else pd.DataFrame()


def proportionality(front_speed: np.ndarray, slip_speed: np.ndarray) -> Dict[str, float]:
    """v_slip = a v_front? The free slope of log v_slip against log v_front with its Pearson r, and the
    prefactor a of the fit through the origin in log space (slope 1: the geometric mean of v_slip/v_front),
    over the pairs with both speeds finite and positive; `decades`: the span of front speeds."""
    front_speed, slip_speed = np.asarray(front_speed, float), np.asarray(slip_speed, float)
    usable = np.isfinite(front_speed) & np.isfinite(slip_speed) & (front_speed > 0) & (slip_speed > 0)
    x, y = np.log10(front_speed[usable]), np.log10(slip_speed[usable])
    if len(x) < 3 or np.ptp(x) == 0:
        return {"pairs": int(len(x)), "slope": np.nan, "r": np.nan, "prefactor": np.nan, "decades": np.nan}
    return {"pairs": int(len(x)), "slope": np.polyfit(x, y, 1)[0],
            "r": stats.pearsonr(x, y)[0] if np.ptp(y) > 0 else np.nan,
            "prefactor": 10 ** np.mean(y - x), "decades": np.ptp(x)}


# ---------------------------------------------------------------------------------------------
# Signature 4: the precursors' arrest lengths

def precursor_extents(run_dirs: RunDirs) -> pd.DataFrame:
    """Signature 4, one row per precursor that a global slip followed: its run, loading cycle (the
    number of global slips before it), F_S/F_N at its start, its extent l/L, its blocks, and whether it
    `arrested`: it ran a front (SEGMENT_BLOCKS blocks or more) from the driven edge (nucleated within
    DRIVEN_EDGE of L), so that l/L, measured from that edge, is how far it ran (an event of the leading
    edge has l/L = 1 however small it is)."""
    columns = ["run", "cycle", "event", "force_ratio", "extent_over_length", "blocks", "arrested"]
    rows = []
    for run_dir in _directories(run_dirs):
        table, length = events(run_dir), lattice_wave_speeds(run_dir)["length"]
        is_global = table["global"].astype(int).to_numpy()
        cycle = np.cumsum(is_global) - is_global
        for (_, event), k in zip(table.iterrows(), cycle):
            if not event["global"] and k < is_global.sum():
                blocks = int(event["ruptured_blocks"])
                arrested = blocks >= SEGMENT_BLOCKS and event["nucleation_x"] <= DRIVEN_EDGE * length
                rows.append([run_dir, int(k), event["event"], event["force_ratio"], event["extent_over_length"],
                             blocks, arrested])
    return pd.DataFrame(rows, columns=columns)


def extent_growth(extents: pd.DataFrame) -> Dict[str, float]:
    """How l/L grows with F_S/F_N over the precursors that `arrested` (precursor_extents): the fraction
    of successive precursors of a cycle that reach farther than the one before, and pooled over every
    cycle, the least-squares slope, the `rise` it makes over their range of F_S/F_N and Spearman's
    rank correlation."""
    arrested = extents[extents["arrested"].astype(bool)]
    force, extent = arrested["force_ratio"], arrested["extent_over_length"]
    steps = [np.diff(c.sort_values("force_ratio")["extent_over_length"].to_numpy())
             for _, c in arrested.groupby(["run", "cycle"])]
    steps = np.concatenate(steps) if steps else np.zeros(0)
    varied = len(arrested) >= 2 and np.ptp(force) > 0
    slope = np.polyfit(force, extent, 1)[0] if varied else np.nan
    rise = slope * np.ptp(force) if varied else np.nan
    ranked = varied and len(arrested) >= 3 and np.ptp(extent) > 0
    return {"precursors": len(arrested), "others": len(extents) - len(arrested), "slope": slope, "rise": rise,
            "spearman": stats.spearmanr(force, extent)[0] if ranked else np.nan,
            "successive_growing": float(np.mean(steps > 0)) if len(steps) else np.nan,
            "successive_pairs": len(steps)}


# ---------------------------------------------------------------------------------------------
# Verdicts

REPRODUCED, WITHIN_MARGIN, DIFFERS = "reproduced", "reproduced within a stated margin", "differs"


def graded(reproduced: bool, within_margin: bool) -> str:
    """The verdict of a statement from its two tests, the stricter first."""
    return REPRODUCED if reproduced else WITHIN_MARGIN if within_margin else DIFFERS


def _range(values, digits: str = ".3g") -> str:
    values = np.asarray(values, float)
    values = values[np.isfinite(values)]
    if not len(values):
        return "none"
    low, high = np.min(values), np.max(values)
    return f"{low:{digits}}" if f"{low:{digits}}" == f"{high:{digits}}" else f"{low:{digits}}-{high:{digits}}"


def transition_statement(transitions: pd.DataFrame, every_event: pd.DataFrame) -> Dict[str, str]:
    """Statement 1 from front_transitions and all_events."""
    runs = every_event["run"].nunique()
    drops = transitions.groupby(["run", "event"])["drop"].max() if len(transitions) else pd.Series(dtype=float)
    shown = transitions[transitions["drop"] >= ORDER_OF_MAGNITUDE] if len(transitions) else transitions
    counts = []
    for name, kind in (("global slips", True), ("precursors", False)):
        of_kind = every_event[every_event["global"].astype(bool) == kind].set_index(["run", "event"]).index
        with_front = drops[drops.index.isin(of_kind)] if len(drops) else drops
        counts.append(f"{name}: {int((with_front >= ORDER_OF_MAGNITUDE).sum())} of the {len(with_front)} that ran a "
                      f"front ({len(of_kind) - len(with_front)} did not)")
    runs_showing = shown["run"].nunique() if len(shown) else 0
    measured = (f"events with a front of {MIN_FRONT_BLOCKS}+ blocks that runs fast (>= {FAST_FRACTION_OF_CS:g} c_S "
                f"over {SEGMENT_BLOCKS}+ blocks) then {ORDER_OF_MAGNITUDE:g}x slower: " + "; ".join(counts)
                + f"; in {runs_showing} of {runs} runs")
    if len(shown):
        measured += (f"; fast {_range(shown['fast_speed'])} m/s, then slow {_range(shown['slow_speed'])} m/s (drops "
                     f"{_range(shown['drop'], '.0f')}x) from x = {_range(shown['transition_x'] * 1e3, '.1f')} mm")
    verdict = graded(runs and runs_showing >= runs / 2,
                     len(shown) or (len(drops) and (drops >= 3).any()))
    return {"statement": "A fast front arrests and the rupture runs on as a slow front: the front speed drops by an "
                         f"order of magnitude at a point of its path, within one event ({SOURCES['pnas']})",
            "measured": measured, "verdict": verdict,
            "margin": f"reproduced: in at least half the runs an event runs fast then {ORDER_OF_MAGNITUDE:g}x slower; "
                      "within the margin: in fewer runs, or a drop of 3x or more"}


def slow_speed_statement(slow: pd.DataFrame) -> Dict[str, str]:
    """Statement 2 from slow_front_speeds."""
    lo, hi = SLOW_FRONT_RANGE
    slow = slow[slow["slow_blocks"] > 0] if len(slow) else pd.DataFrame(columns=["global_slip", "median", "c_S"])
    medians = slow["median"].to_numpy(float)
    c_s = float(slow["c_S"].iloc[0]) if len(slow) else np.nan
    parts = []
    is_global = slow["global_slip"].astype(bool)
    for name, m in (("global slips", slow.loc[is_global, "median"]), ("precursors", slow.loc[~is_global, "median"])):
        parts.append(f"{name} {_range(m)} m/s ({_range(100 * m / c_s, '.2g')} % of c_S)")
    inside = (medians >= lo) & (medians <= hi)
    measured = (f"median speed of the slow blocks (< {FAST_FRACTION_OF_CS:g} c_S) per event: " + ", ".join(parts)
                + f"; c_S = {c_s:.0f} m/s; {int(inside.sum())} of {len(medians)} events within {lo:g}-{hi:g} m/s")
    verdict = graded(len(medians) and inside.all(),
                     len(medians) and ((medians >= lo / 3) & (medians <= hi * 3)).all())
    return {"statement": f"Slow fronts run at a few % of the shear-wave speed: ~{lo:g}-{hi:g} m/s against c_S ~ "
                         f"1000 m/s for PMMA ({SOURCES['pnas']})",
            "measured": measured, "verdict": verdict,
            "margin": f"reproduced: every event's median slow speed within {lo:g}-{hi:g} m/s; within the margin: "
                      "within a factor 3 of that range"}


def proportionality_statement(mean_rate: Dict[str, float], peak: Dict[str, float]) -> Dict[str, str]:
    """Statement 3 from proportionality of the mean slip rate (the verdict) and of the peak slip speed."""
    def fitted(fit):
        return (f"log-log slope {fit['slope']:.2f}, Pearson r (logs) {fit['r']:.2f}, v_slip/v_front = "
                f"{fit['prefactor']:.3g}")
    measured = (f"{mean_rate['pairs']} blocks over {mean_rate['decades']:.2g} decades of front speed; mean slip rate "
                f"behind the tip: {fitted(mean_rate)}; its peak (slip plus the slider's ringing): {fitted(peak)} "
                "(v_slip/v_front: the geometric mean, slope 1 through the origin in log space)")
    off = abs(mean_rate["slope"] - 1)
    verdict = graded(mean_rate["r"] >= MIN_CORRELATION and off <= SLOPE_MARGIN and mean_rate["decades"] >= 1,
                     mean_rate["r"] >= MIN_CORRELATION and off <= LOOSE_SLOPE_MARGIN)
    return {"statement": "The slip speed is proportional to the front speed over the whole range of front "
                         f"speeds ({SOURCES['pre']})",
            "measured": measured, "verdict": verdict,
            "margin": f"on the mean slip rate; reproduced: slope 1 +- {SLOPE_MARGIN:g} with r >= {MIN_CORRELATION:g} "
                      f"over a decade or more; within the margin: slope 1 +- {LOOSE_SLOPE_MARGIN:g} with r >= "
                      f"{MIN_CORRELATION:g}"}


def growth_statement(extents: pd.DataFrame) -> Dict[str, str]:
    """Statement 4 from precursor_extents. The verdict is on successive precursors within a loading
    cycle (Rubinstein et al. 2007: under a rising load each reaches farther): pooled over cycles, a
    cycle after a global slip starts from its own stress state, not from rest."""
    growth = extent_growth(extents)
    arrested = extents[extents["arrested"].astype(bool)]
    measured = (f"{growth['precursors']} precursors from the driven edge before global slips (besides "
                f"{growth['others']} events of one block or from elsewhere): l/L "
                f"{_range(arrested['extent_over_length'])} at F_S/F_N {_range(arrested['force_ratio'])}; "
                f"{growth['successive_pairs']} successive pairs within a loading cycle")
    if growth["successive_pairs"]:
        measured += f", {growth['successive_growing']:.0%} reaching farther"
    if growth["precursors"] >= 2:
        measured += (f"; pooled: slope d(l/L)/d(F_S/F_N) {growth['slope']:.3g} (a rise of {growth['rise']:.2g} in "
                     f"l/L over their F_S/F_N), Spearman {growth['spearman']:.2f}")
    measured += " (no published numbers for this scene: the claim is qualitative)"
    verdict = graded(growth["successive_pairs"] >= 3 and growth["successive_growing"] >= 0.75,
                     growth["successive_pairs"] >= 1 and growth["successive_growing"] > 0.5)
    return {"statement": "Precursors from the driven edge arrest after a length l/L that grows with the shear load "
                         f"F_S/F_N ({SOURCES['precursors']}; precursors in {SOURCES['pnas']})",
            "measured": measured, "verdict": verdict,
            "margin": f"reproduced: 3+ successive pairs of precursors (fronts of {SEGMENT_BLOCKS}+ blocks from the "
                      "driven edge) within loading cycles, at least 75 % of them reaching farther; within the margin: "
                      "1+ pair, more than half reaching farther"}


def statements(run_dirs: RunDirs) -> List[Dict[str, str]]:
    """The four statements with what the runs measure, pooled over every run given."""
    profiles = front_profiles(run_dirs)
    pairs = slip_and_front_speeds(run_dirs, profiles)
    fits = [proportionality(*(pairs[c] if len(pairs) else [] for c in ("speed", slip)))
            for slip in ("mean_slip_rate", "peak_slip_speed")]
    return [transition_statement(front_transitions(run_dirs, profiles), all_events(run_dirs)),
            slow_speed_statement(slow_front_speeds(run_dirs, profiles)),
            proportionality_statement(*fits), growth_statement(precursor_extents(run_dirs))]


def main(argv=None):
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("run_dirs", nargs="+", help="finished runs of configs/" + SCENE)
    for s in statements(parser.parse_args(argv).run_dirs):
        print(f"- {s['statement']}\n  measured: {s['measured']}\n  verdict: {s['verdict']} ({s['margin']})")


if __name__ == "__main__":
    main()
