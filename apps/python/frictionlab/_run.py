"""Reading a run's output directory: run.yaml, every observer's tables (CSV or HDF5), the VTU series."""
import csv
import glob
import os
import xml.etree.ElementTree as ElementTree
from typing import Dict, List, Optional, Tuple

import numpy as np
import yaml


class Table:
    """One output table: `columns` (names, in order) and `values` (a float64 array, one row per
    observation, one column per name), with the provenance the run recorded (`provenance`: version,
    scene hash, seed, plugins). Read from NAME.csv (+ NAME.csv.meta.yaml) or NAME.h5."""

    def __init__(self, name: str, path: str, columns: List[str], values: np.ndarray, provenance: dict):
        self.name, self.path, self.columns, self.values, self.provenance = name, path, columns, values, provenance

    def __getitem__(self, column: str) -> np.ndarray:
        """One column as a 1-D array, e.g. table["time"]."""
        return self.values[:, self.columns.index(column)]

    def __len__(self) -> int:
        return self.values.shape[0]

    def __repr__(self) -> str:
        return f"Table({self.name!r}, {len(self)} rows, columns={self.columns[:6]}{'...' if len(self.columns) > 6 else ''})"

    def to_records(self) -> np.ndarray:
        """A structured array, columns by name (as numpy.genfromtxt(names=True) gives)."""
        return np.rec.fromarrays(self.values.T, names=self.columns) if len(self) else np.rec.array(
            np.zeros(0, dtype=[(c, float) for c in self.columns]))

    def to_pandas(self):
        """A pandas DataFrame (python3-pandas)."""
        import pandas

        return pandas.DataFrame(self.values, columns=self.columns)


def read_table(path: str) -> Table:
    """A table from its file: NAME.csv (provenance from NAME.csv.meta.yaml if present) or NAME.h5."""
    name = os.path.splitext(os.path.basename(path))[0]
    if path.endswith(".h5"):
        import h5py

        with h5py.File(path, "r") as f:
            values = np.asarray(f["table"][:], dtype=float)
            columns = [c.decode() if isinstance(c, bytes) else str(c) for c in f["table"].attrs["columns"]]
            provenance = {k: (v.decode() if isinstance(v, bytes) else v.item() if hasattr(v, "item") else v)
                          for k, v in f.attrs.items()}
        return Table(name, path, columns, values.reshape(-1, len(columns)), provenance)
    with open(path, newline="") as f:
        lines = f.readlines()
    columns = next(csv.reader(lines[:1]), [])
    try:  # NumPy's C parser: five times faster than a cell at a time, and the same values
        values = np.loadtxt(lines[1:], delimiter=",", dtype=float, ndmin=2) if len(lines) > 1 else \
            np.zeros((0, len(columns)))
    except ValueError:  # a cell that is not a number (empty, text) reads as NaN
        values = np.array([[_number(c) for c in r] for r in csv.reader(lines[1:])], dtype=float)
    provenance = {}
    if os.path.exists(path + ".meta.yaml"):
        with open(path + ".meta.yaml") as f:
            provenance = yaml.safe_load(f) or {}
        provenance.pop("columns", None)
    return Table(name, path, columns, values, provenance)


def _number(cell: str) -> float:
    try:
        return float(cell)
    except ValueError:
        return float("nan")


class Run:
    """A run's output directory.

    metadata    run.yaml as a dict: version, status, scene hash, seed, plugins, steps, wall time,
                and the scene with every default written out (`metadata["scene"]`)
    tables      the names of every table (CSV or HDF5), e.g. ["interface_velocity", "loading_curve", ...]
    table(name) one table (Table: .columns, .values, ["column"], .to_pandas())
    arrays(name) / frame(name)  the same as a NumPy structured array / pandas DataFrame
    series      the VTU series (ParaView .pvd files): {name: [(time, file), ...]}
    """

    def __init__(self, directory: str):
        self.directory = os.fspath(directory)
        meta = os.path.join(self.directory, "run.yaml")
        if not os.path.exists(meta):
            raise FileNotFoundError(f"{self.directory} is not a run directory (no run.yaml)")
        with open(meta) as f:
            self.metadata: dict = yaml.safe_load(f)
        self._files: Dict[str, str] = {}
        for path in sorted(glob.glob(os.path.join(self.directory, "*.csv")) + glob.glob(os.path.join(self.directory, "*.h5"))):
            self._files.setdefault(os.path.splitext(os.path.basename(path))[0], path)

    def __repr__(self) -> str:
        return f"Run({self.directory!r}, status={self.status!r}, tables={self.tables})"

    @property
    def status(self) -> str:
        """"completed", "failed" or "running"."""
        return self.metadata.get("status", "")

    @property
    def tables(self) -> List[str]:
        return list(self._files)

    def table(self, name: str) -> Table:
        """The table NAME (file NAME.csv or NAME.h5), e.g. run.table("interface_velocity")."""
        if name not in self._files:
            raise KeyError(f"no table {name!r} in {self.directory} (tables: {', '.join(self._files)})")
        return read_table(self._files[name])

    def arrays(self, name: str) -> np.ndarray:
        """The table NAME as a NumPy structured array (columns by name)."""
        return self.table(name).to_records()

    def frame(self, name: str):
        """The table NAME as a pandas DataFrame."""
        return self.table(name).to_pandas()

    @property
    def series(self) -> Dict[str, List[Tuple[float, str]]]:
        """Every VTU series of the run (its .pvd files): name -> [(time, file path joined to the run directory), ...]."""
        out = {}
        for pvd in sorted(glob.glob(os.path.join(self.directory, "*.pvd"))):
            root = ElementTree.parse(pvd).getroot()
            out[os.path.splitext(os.path.basename(pvd))[0]] = [
                (float(d.get("timestep")), os.path.join(self.directory, d.get("file")))
                for d in root.iter("DataSet")]
        return out


def open_run(directory: str) -> Run:
    """The run in an output directory (a Run)."""
    return Run(directory)
