"""Reading a run's output directory: run.yaml, every observer's tables (CSV or HDF5), the VTU series."""
import csv
import glob
import os
import xml.etree.ElementTree as ElementTree
from typing import Dict, List, NamedTuple, Optional, Sequence, Tuple

import numpy as np
import yaml


class Table:
    """One output table: `columns` (names, in order) and `values` (a float64 array, one row per
    observation, one column per name), with the provenance the run recorded (`provenance`: version,
    scene hash, seed, plugins). Read from NAME.csv (+ NAME.csv.meta.yaml) or NAME.h5.

    `units` gives each column's unit as the observer declared it ({"time": "s", "driving_force": "N",
    ...}; "1" for a pure number). `integer_columns` and `flag_columns` name the columns the observer
    declared integers (counts, indices, step and stage numbers) and flags (0 or 1): to_records() and
    to_pandas() give them as int64 and bool, where every value is one (a column with a missing value
    stays float64, as pandas.read_csv reads it)."""

    def __init__(self, name: str, path: str, columns: List[str], values: np.ndarray, provenance: dict,
                 integer_columns: Sequence[str] = (), flag_columns: Sequence[str] = (),
                 units: Optional[Dict[str, str]] = None):
        self.name, self.path, self.columns, self.values, self.provenance = name, path, columns, values, provenance
        self.integer_columns, self.flag_columns = list(integer_columns), list(flag_columns)
        self.units: Dict[str, str] = dict(units or {})

    def __getitem__(self, column: str) -> np.ndarray:
        """One column as a 1-D array, e.g. table["time"]."""
        return self.values[:, self.columns.index(column)]

    def __len__(self) -> int:
        return self.values.shape[0]

    def __repr__(self) -> str:
        return f"Table({self.name!r}, {len(self)} rows, columns={self.columns[:6]}{'...' if len(self.columns) > 6 else ''})"

    def typed_column(self, column: str) -> np.ndarray:
        """One column in its declared type: int64 or bool where every value is one, else float64."""
        values = self[column]
        if column not in self.integer_columns and column not in self.flag_columns:
            return values
        if not np.all(np.isfinite(values)) or np.any(values != np.round(values)):
            return values
        if column in self.flag_columns and np.all((values == 0) | (values == 1)):
            return values.astype(bool)
        return values.astype(np.int64)

    def to_records(self) -> np.ndarray:
        """A structured array, columns by name (as numpy.genfromtxt(names=True) gives), integers and
        flags typed."""
        if not len(self):
            return np.rec.array(np.zeros(0, dtype=[(c, self._empty_type(c)) for c in self.columns]))
        return np.rec.fromarrays([self.typed_column(c) for c in self.columns], names=self.columns)

    def to_pandas(self, index: Optional[str] = None):
        """A pandas DataFrame (python3-pandas), integers and flags typed; `index` names the column to
        index it by (e.g. "time")."""
        import pandas

        if index is not None and index not in self.columns:
            raise KeyError(f"no column {index!r} in {self.name} (columns: {', '.join(self.columns)})")
        frame = pandas.DataFrame({c: (self.typed_column(c) if len(self) else np.zeros(0, self._empty_type(c)))
                                  for c in self.columns}, columns=self.columns)
        return frame.set_index(index) if index is not None else frame

    def _empty_type(self, column: str) -> type:
        return bool if column in self.flag_columns else np.int64 if column in self.integer_columns else float


def read_table(path: str) -> Table:
    """A table from its file: NAME.csv (provenance from NAME.csv.meta.yaml if present) or NAME.h5."""
    name = os.path.splitext(os.path.basename(path))[0]
    if path.endswith(".h5"):
        import h5py

        with h5py.File(path, "r") as f:
            values = np.asarray(f["table"][:], dtype=float)
            attributes = f["table"].attrs
            names = {key: [c.decode() if isinstance(c, bytes) else str(c) for c in attributes.get(key, [])]
                     for key in ("columns", "integer_columns", "flag_columns", "units")}
            provenance = {k: (v.decode() if isinstance(v, bytes) else v.item() if hasattr(v, "item") else v)
                          for k, v in f.attrs.items()}
        columns = names["columns"]
        return Table(name, path, columns, values.reshape(-1, len(columns)), provenance, names["integer_columns"],
                     names["flag_columns"], dict(zip(columns, names["units"])))
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
    return Table(name, path, columns, values, provenance, provenance.pop("integer_columns", []),
                 provenance.pop("flag_columns", []), provenance.pop("units", None))


def _number(cell: str) -> float:
    try:
        return float(cell)
    except ValueError:
        return float("nan")


class InterfaceMap(NamedTuple):
    """An interface table of a 3D run as maps (Run.interface_map): values[row, iy, ix] at time[row]
    for the block at (x[ix], y[iy])."""
    time: np.ndarray
    x: np.ndarray
    y: np.ndarray
    values: np.ndarray


class Run:
    """A run's output directory.

    metadata    run.yaml as a dict: version, status, scene hash, seed, plugins, steps, wall time,
                and the scene with every default written out (`metadata["scene"]`)
    tables      the names of every table (CSV or HDF5), e.g. ["interface_velocity", "loading_curve", ...]
    table(name) one table (Table: .columns, .values, ["column"], .to_pandas())
    arrays(name) / frame(name, index=None)  the same as a NumPy structured array / pandas DataFrame,
                with integer columns as int64 and flags as bool; frame(name, index="time") is indexed by time
    series      the VTU series (ParaView .pvd files): {name: [(time, file), ...]}
    interface_map(name)  a table with a column per interface block of a 3D run as maps over x and y
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
        """"done", "failed", "interrupted" or "running": run.yaml's `status`, the word a sweep's
        sweep.csv uses for its runs too."""
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
        """The table NAME as a NumPy structured array (columns by name, integers and flags typed)."""
        return self.table(name).to_records()

    def frame(self, name: str, index: Optional[str] = None):
        """The table NAME as a pandas DataFrame (integers as int64, flags as bool), indexed by the
        column `index` if given, e.g. run.frame("loading_curve", index="time")."""
        return self.table(name).to_pandas(index)

    def interface_map(self, name: str) -> "InterfaceMap":
        """The table NAME of a 3D run, whose columns block_<k> are the interface's blocks
        (interface_history's tables, contact_area's map), as maps: InterfaceMap(time, x, y, values)
        with x and y the blocks' places (m, increasing) and values[row, iy, ix] the block at (x[ix],
        y[iy]), placed by the run's interface_blocks table."""
        if "interface_blocks" not in self._files:
            raise KeyError(f"{self.directory} has no interface_blocks table: its interface is not a grid "
                           "(a 2D run), or it has no interface_history observer")
        blocks, table = self.table("interface_blocks"), self.table(name)
        x, y = np.unique(blocks["x0"]), np.unique(blocks["y0"])
        values = np.full((len(table), len(y), len(x)), np.nan)
        for block, x0, y0 in zip(blocks.typed_column("block"), blocks["x0"], blocks["y0"]):
            values[:, np.searchsorted(y, y0), np.searchsorted(x, x0)] = table[f"block_{block}"]
        return InterfaceMap(table["time"], x, y, values)

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
