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


def run_labels(runs):
    """Each run's short run_label, told apart where two collide: by the scene values that differ
    between them (key paths as --set writes them, at most three), else by the directory given."""
    labels = [run_label(run, short=True) for run in runs]
    values = [scene_values({k: v for k, v in scene_of(run).items() if k != "output"}) for run in runs]
    unique = list(labels)
    for i, label in enumerate(labels):
        alike = [j for j, other in enumerate(labels) if other == label]
        if len(alike) < 2:
            continue
        keys = sorted({k for j in alike for k in values[j]})
        differing = [k for k in keys if len({repr(values[j].get(k)) for j in alike}) > 1][:3]
        unique[i] += "".join(f", {k}={values[i].get(k)}" for k in differing)
    if len(set(unique)) < len(unique):  # the same scene twice: the directories tell them apart
        unique = [f"{label} ({run_directory(run)})" if unique.count(label) > 1 else label
                  for label, run in zip(unique, runs)]
    return unique


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
