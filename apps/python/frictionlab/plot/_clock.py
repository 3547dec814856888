"""The one origin of every time axis: when loading started, as run.yaml records it (the tables
give the same origin in `time_since_loading`). A figure on an event's own clock (four_phase: since
detachment; fronts: since nucleation) says when the event came after it."""
import numpy as np

from ._tables import run_record


def loading_start(run):
    """When loading started, in the run's simulated time, as run.yaml records it (`loading_start`:
    the start of the first stage a driving loader acts in; the tables' `time_since_loading` counts
    from it); None if it does not."""
    try:
        return float(run_record(run)["loading_start"])
    except (KeyError, TypeError, ValueError):
        return None


def time_origin(run):
    """(t0, what t0 is) for the run's time axes: when loading started, or, said so, the run's start
    where run.yaml does not tell (a run of an older version)."""
    t0 = loading_start(run)
    if t0 is None:
        return 0.0, "the run started (when loading started is unknown: run.yaml does not record it)"
    return t0, "loading started"


def from_loading(times, t0):
    """Which rows are at or after t0: a row's time is a sum of steps, so within round-off of a stage's
    start; half an observation interval's grace takes the row observed at the start."""
    grace = 0.5 * float(np.median(np.diff(times))) if len(times) > 1 else 0.0
    return times >= t0 - grace


def overlaid_time_label(unknown):
    """The time axis of curves of several runs, each from its own time_origin; `unknown`: some run
    does not tell when its loading started."""
    return "time since loading started (s" + ("; from the run's start where run.yaml does not record it"
                                              if unknown else "") + ")"
