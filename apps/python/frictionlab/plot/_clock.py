"""The one origin of every time axis: when loading started, from the stage durations run.yaml
records. A figure on an event's own clock (four_phase: since detachment; fronts: since nucleation)
says when the event came after it."""
import numpy as np

from ._tables import scene_of

DRIVING_LOADERS = ("driving_spring", "plate_springs")  # the loaders that pull the slider


def loading_stage(scene):
    """Index of the stage loading starts in: the first in which a driving loader acts (its `stages`,
    or every stage if it names none); the last stage in a scene without one. None without stages."""
    names = [stage.get("name") for stage in scene.get("stages") or []]
    if not names:
        return None
    acting = [names.index(name) for loader in scene.get("loaders") or [] if loader.get("type") in DRIVING_LOADERS
              for name in (loader.get("stages") or names) if name in names]
    return min(acting) if acting else len(names) - 1


def loading_start(run):
    """When loading started, in the run's simulated time: the stage durations before the loading
    stage (loading_stage) summed, as run.yaml records them; None if it records no stages."""
    scene = scene_of(run)
    stage = loading_stage(scene)
    if stage is None:
        return None
    try:  # PyYAML (YAML 1.1) reads 3e-3 as a string: float() takes it
        return float(sum(float(s["duration"]) for s in scene["stages"][:stage]))
    except (KeyError, TypeError, ValueError):
        return None


def time_origin(run):
    """(t0, what t0 is) for the run's time axes: when loading started, or, said so, the run's start
    where run.yaml does not tell when loading started."""
    t0 = loading_start(run)
    if t0 is None:
        return 0.0, "the run started (when loading started is unknown: run.yaml records no stages)"
    return t0, "loading started"


def from_loading(times, t0):
    """Which rows are at or after t0: a row's time is a sum of steps, so within round-off of a stage's
    start; half an observation interval's grace takes the row observed at the start."""
    grace = 0.5 * float(np.median(np.diff(times))) if len(times) > 1 else 0.0
    return times >= t0 - grace


def overlaid_time_label(unknown):
    """The time axis of curves of several runs, each from its own time_origin; `unknown`: some run
    does not tell when its loading started."""
    return "time since loading started (s" + ("; from the run's start where run.yaml records no stages"
                                              if unknown else "") + ")"
