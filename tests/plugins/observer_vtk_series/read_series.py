"""Reads a vtk_series output with VTK's Python reader and checks it against expected.json.

    python3 read_series.py <series directory>

The directory holds lattice.pvd, its .vtu files and expected.json (written by test_vtk_series.cpp,
the single source of what was set). Plain VTK has no .pvd reader (vtkPVDReader is ParaView's), so
the collection is parsed as XML, which also proves it is complete. Exit code 0 when everything
matches; otherwise every mismatch is printed and the exit code is 1.
"""
import json
import math
import sys
import xml.etree.ElementTree as ElementTree
from pathlib import Path

import vtk

problems = []


def check(condition, message):
    if not condition:
        problems.append(message)
    return condition


def same(actual, expected):
    if math.isnan(expected):
        return math.isnan(actual)
    return math.isclose(actual, expected, rel_tol=1e-12, abs_tol=1e-15)


def check_values(what, actual, expected):
    if not check(len(actual) == len(expected), f"{what}: {len(actual)} values, expected {len(expected)}"):
        return
    bad = [i for i, (a, e) in enumerate(zip(actual, expected)) if not same(a, e)]
    check(not bad, f"{what}: values differ at {bad[:5]}, e.g. {[actual[i] for i in bad[:3]]} "
                   f"instead of {[expected[i] for i in bad[:3]]}")


def values_of(array):
    n, c = array.GetNumberOfTuples(), array.GetNumberOfComponents()
    return [array.GetComponent(t, k) for t in range(n) for k in range(c)]


def strings_of(field_data, name):
    array = field_data.GetAbstractArray(name)
    if not check(array is not None and array.IsA("vtkStringArray"), f"field data string array {name!r} missing"):
        return None
    return [array.GetValue(i) for i in range(array.GetNumberOfValues())]


def check_snapshot(path, snapshot, expected):
    reader = vtk.vtkXMLUnstructuredGridReader()
    reader.SetFileName(str(path))
    reader.Update()
    grid = reader.GetOutput()
    name = path.name
    check(grid.GetNumberOfPoints() == expected["points"], f"{name}: {grid.GetNumberOfPoints()} points")
    check(grid.GetNumberOfCells() == expected["cells"], f"{name}: {grid.GetNumberOfCells()} cells")
    types = {grid.GetCellType(c) for c in range(grid.GetNumberOfCells())}
    check(types == {expected["cell_type"]}, f"{name}: cell types {types}, expected {{{expected['cell_type']}}}")
    check_values(f"{name} points", values_of(grid.GetPoints().GetData()), snapshot["points"])

    point_data = grid.GetPointData()
    present = {point_data.GetArrayName(i) for i in range(point_data.GetNumberOfArrays())}
    check(present == set(snapshot["arrays"]), f"{name}: point arrays {sorted(present)}, "
                                              f"expected {sorted(snapshot['arrays'])}")
    for array_name, a in snapshot["arrays"].items():
        array = point_data.GetArray(array_name)
        if not check(array is not None, f"{name}: point array {array_name!r} missing"):
            continue
        check(array.GetNumberOfComponents() == a["components"],
              f"{name}: {array_name} has {array.GetNumberOfComponents()} components, expected {a['components']}")
        check_values(f"{name} {array_name}", values_of(array), a["values"])

    field_data = grid.GetFieldData()
    for number_name, value in snapshot["numbers"].items():
        array = field_data.GetArray(number_name)
        if check(array is not None, f"{name}: field data {number_name!r} missing"):
            check(same(array.GetComponent(0, 0), value), f"{name}: {number_name} = {array.GetComponent(0, 0)}, "
                                                         f"expected {value}")
    for string_name, value in expected["strings"].items():
        check(strings_of(field_data, string_name) == value, f"{name}: {string_name} differs from {value}")


def main(directory):
    expected = json.loads((directory / "expected.json").read_text())
    collection = ElementTree.parse(directory / expected["collection"]).getroot()
    check(collection.get("type") == "Collection", "the .pvd is not a VTK collection")
    datasets = collection.findall("./Collection/DataSet")
    snapshots = expected["snapshots"]
    check(len(datasets) == len(snapshots), f"the .pvd lists {len(datasets)} files, expected {len(snapshots)}")
    for dataset, snapshot in zip(datasets, snapshots):
        check(dataset.get("file") == snapshot["file"], f"the .pvd lists {dataset.get('file')}")
        check(float(dataset.get("timestep")) == snapshot["time"],
              f"{snapshot['file']}: .pvd time {dataset.get('timestep')}, simulated {snapshot['time']}")
        path = directory / dataset.get("file")
        if check(path.is_file(), f"{path} listed but missing"):
            check_snapshot(path, snapshot, expected)
    leftovers = sorted(str(p) for p in directory.rglob("*.tmp"))
    check(not leftovers, f"temporary files left behind: {leftovers}")
    for p in problems:
        print("read_series.py:", p, file=sys.stderr)
    print(f"read_series.py: {len(datasets)} snapshots read, {len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main(Path(sys.argv[1])))
