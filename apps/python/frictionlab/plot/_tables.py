"""What the figures read: a run's tables as structured arrays (through frictionlab.read_table, CSV or
HDF5), the scene its run.yaml records, and a campaign's tables (sweep.csv, events.csv, study.csv)."""
import csv
import os

from .._run import Run, read_table


def run_directory(run):
    """The directory of `run`: a run directory (a str or os.PathLike) or a frictionlab.Run."""
    return run.directory if isinstance(run, Run) else os.fspath(run)


def table(run, name):
    """The run's table `name` (e.g. "precursors": precursors.csv, else precursors.h5) as a structured
    array, columns by name; None if the run wrote no such table or it has no rows."""
    for ext in (".csv", ".h5"):
        path = os.path.join(run_directory(run), name + ext)
        if os.path.exists(path):
            rows = read_table(path)
            return rows.to_records() if len(rows) else None
    return None


def has_table(run, name):
    """Whether the run wrote the table `name` (CSV or HDF5), rows or not: its observer ran."""
    return any(os.path.exists(os.path.join(run_directory(run), name + ext)) for ext in (".csv", ".h5"))


def run_record(run):
    """The run's run.yaml (a dict; empty if unreadable)."""
    try:
        import yaml
        with open(os.path.join(run_directory(run), "run.yaml")) as f:
            return yaml.safe_load(f) or {}
    except Exception:  # noqa: BLE001 - a figure without its title is still a figure
        return {}


def scene_of(run):
    """The resolved scene the run recorded in run.yaml (a dict; empty if unreadable)."""
    return run_record(run).get("scene") or {}


def campaign_rows(directory, name):
    """The rows of a campaign's table (sweep.csv, events.csv, study.csv) as dicts of strings; the
    comment lines of tables written before the provenance moved to the sidecar are left out."""
    with open(os.path.join(directory, name), newline="") as f:
        return list(csv.DictReader(line for line in f if not line.startswith("#")))


def sidecar_text(directory, name):
    """The provenance a campaign recorded beside its table `name` (NAME.meta.yaml), as text; empty
    if there is none."""
    path = os.path.join(directory, name + ".meta.yaml")
    return open(path).read() if os.path.exists(path) else ""


def campaign_meta(directory, name):
    """The provenance a campaign recorded beside its table `name` (NAME.meta.yaml) as a dict:
    title, seeds, units, ...; empty if there is none."""
    try:
        import yaml
        return yaml.safe_load(sidecar_text(directory, name)) or {}
    except Exception:  # noqa: BLE001 - a figure without its units is still a figure
        return {}


def number(text):
    """A campaign table's cell as a number; NaN for an empty or text cell."""
    try:
        return float(text)
    except (TypeError, ValueError):
        return float("nan")
