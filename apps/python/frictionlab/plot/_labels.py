"""What the figures say about the runs they draw: every title names the scene (its title, F_N,
theta, h, the friction law and the seed, from run.yaml), curves of several runs are labelled apart,
and a figure without the event it draws says so."""
import os

from ._tables import has_table, run_directory, scene_of


def component(scene, kind, type_name):
    """The scene's first component of `kind` (e.g. "loaders") of type `type_name`; {} if none."""
    for c in scene.get(kind) or []:
        if c.get("type") == type_name:
            return c
    return {}


def run_label(run, short=False):
    """'title: F_N = 400 N, θ = 0, h = 5 mm, three_state_junctions, seed 42' from run.yaml."""
    scene = scene_of(run)
    name = os.path.basename(os.path.abspath(run_directory(run)))
    if not scene:
        return name
    facts = []
    normal, driving = component(scene, "loaders", "normal_load"), component(scene, "loaders", "driving_spring")
    if "total_force" in normal:
        facts.append(f"$F_N$ = {normal['total_force']:g} N")
    if "theta" in normal:
        facts.append(rf"$\theta$ = {normal['theta']:g}")
    if "height" in driving:
        facts.append(f"h = {driving['height'] * 1e3:g} mm")
    law = (scene.get("friction") or {}).get("type")
    if law:
        facts.append(law)
    facts.append(f"seed {scene.get('seed', 0)}")
    title = scene.get("title") or name
    return ", ".join(facts) if short else f"{title}\n" + ", ".join(facts)


# Symbols and display units of the keys figures name, by the key's last part: (symbol, unit, factor
# from the SI value to the unit shown). A key not listed shows its name and its declared unit.
KEY_SYMBOLS = {
    "theta": (r"$\theta$", "", 1.0),
    "total_force": ("$F_N$", "N", 1.0),
    "height": ("$h$", "mm", 1e3),
    "velocity": ("$V$", "m/s", 1.0),
    "dt": (r"$\Delta t$", "µs", 1e6),
    "mu_s": (r"$\mu_s$", "", 1.0),
    "mu_d": (r"$\mu_d$", "", 1.0),
    "seed": ("seed", "", 1.0),
}


def key_display(key, unit=""):
    """(symbol, unit shown, factor from the SI value) of a key path such as `loaders[2].height`;
    `unit` is the declared SI unit ("1" for a pure number), used for a key KEY_SYMBOLS lacks."""
    leaf = key.split(".")[-1]
    if leaf in KEY_SYMBOLS:
        return KEY_SYMBOLS[leaf]
    return leaf, "" if unit in ("", "1") else unit, 1.0


def key_axis_label(key, unit=""):
    """An axis label of a key: its symbol and unit, "$h$ [mm]", "$\\theta$"."""
    symbol, shown, _ = key_display(key, unit)
    return f"{symbol} [{shown}]" if shown else symbol


def key_value_label(key, value, unit=""):
    """A key's value as a legend shows it: "$h$ = 5 mm", "$\\theta$ = 0.5", "seed 2"."""
    symbol, shown, factor = key_display(key, unit)
    if symbol == "seed":
        return f"seed {value}"
    try:
        text = f"{float(value) * factor:g}"
    except (TypeError, ValueError):
        text = str(value)
    return f"{symbol} = {text}" + (f" {shown}" if shown else "")


def is_physics_key(key):
    """Whether a scene key path is physics, not where or what a run writes (output, observers,
    checkpoint) nor its title: the keys a legend may tell runs apart by."""
    return not (key == "title" or key.startswith(("output", "observers", "checkpoint")))


def run_labels(runs):
    """A legend label of each run of an overlay: the physics values that differ between the runs
    (key_value_label; the seed last), never where they write; the directory given where the
    scenes are the same."""
    values = [{k: v for k, v in scene_values(scene_of(run)).items() if is_physics_key(k)} for run in runs]
    keys = sorted({k for v in values for k in v}, key=lambda k: (k == "seed", k))
    differing = [k for k in keys if len({repr(v.get(k)) for v in values}) > 1]
    labels = [", ".join(key_value_label(k, v.get(k)) for k in differing) for v in values]
    if len(set(labels)) < len(labels):  # the same scene twice: the directories tell them apart
        labels = [(f"{label} ({run_directory(run)})" if label else run_directory(run))
                  if labels.count(label) > 1 else label for label, run in zip(labels, runs)]
    return labels


def seed_of(run):
    """The seed the run's scene records (0 if none)."""
    return scene_of(run).get("seed", 0)


def scene_values(node, path=""):
    """{key path: value} of a scene's mapping, key paths as --set writes them (loaders[2].velocity)."""
    if isinstance(node, dict):
        items = ((f"{path}.{k}" if path else str(k), v) for k, v in node.items())
    elif isinstance(node, list) and any(isinstance(v, (dict, list)) for v in node):
        items = ((f"{path}[{i}]", v) for i, v in enumerate(node))
    else:
        return {path: node}
    return {key: value for k, v in items for key, value in scene_values(v, k).items()}


def no_events_note(run):
    """What a figure of rupture events says when it has none to draw."""
    if has_table(run, "precursors"):
        return "no rupture event in this run (the precursors observer recorded none)"
    return "no rupture events recorded (no precursors observer)"
