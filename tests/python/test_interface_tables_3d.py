"""The interface tables of a 3D run read back against its lattice series (VTK's own reader): where
each column's block is (interface_blocks), the across components of slip and velocity, the real
contact area of every block (contact_area's map) and the table of a block off the first row."""
import os
import re

import numpy as np
import pytest
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader

import frictionlab

HERE = os.path.dirname(os.path.abspath(__file__))


@pytest.fixture(scope="module")
def run(tmp_path_factory):
    out = tmp_path_factory.mktemp("junctions_3d") / "out"
    return frictionlab.Scene.load(os.path.join(HERE, "scenes", "tiny_junctions_3d.yaml")).run(output=str(out))


@pytest.fixture(scope="module")
def hdf5_run(tmp_path_factory):
    out = tmp_path_factory.mktemp("junctions_3d_hdf5") / "out"
    tables = [f"observers[{i}].format=hdf5" for i in (1, 2)]
    return frictionlab.Scene.load(os.path.join(HERE, "scenes", "tiny_junctions_3d.yaml"), set=tables).run(
        output=str(out))


def snapshots(run):
    """(time, point arrays by name, reference positions) of every lattice snapshot."""
    with open(os.path.join(run.directory, "lattice.pvd")) as f:
        listed = re.findall(r'timestep="([^"]+)"[^>]*file="([^"]+)"', f.read())
    for time, file in listed:
        reader = vtkXMLUnstructuredGridReader()
        reader.SetFileName(os.path.join(run.directory, file))
        reader.Update()
        grid = reader.GetOutput()
        data = grid.GetPointData()
        arrays = {data.GetArrayName(i): vtk_to_numpy(data.GetArray(i)) for i in range(data.GetNumberOfArrays())}
        yield float(time), arrays, vtk_to_numpy(grid.GetPoints().GetData()) - arrays["displacement"]


def row_at(table, time):
    rows = np.flatnonzero(table["time"] == time)
    assert len(rows) == 1, f"{table.name}: one row at t = {time}"
    return table.values[rows[0]]


def test_each_column_is_a_block_whose_place_on_the_grid_is_written(run):
    bulk = run.metadata["scene"]["bulk"]
    blocks = run.table("interface_blocks")
    assert blocks.typed_column("block").tolist() == list(range(bulk["nx"] * bulk["ny"]))
    places = set(zip(blocks["x0"], blocks["y0"]))
    assert len(places) == len(blocks), "one block per place"
    assert len(set(blocks["x0"])) == bulk["nx"] and len(set(blocks["y0"])) == bulk["ny"]
    _, _, reference = next(snapshots(run))
    nodes = blocks.typed_column("node")
    np.testing.assert_allclose(reference[nodes, 0], blocks["x0"], atol=1e-15)
    np.testing.assert_allclose(reference[nodes, 1], blocks["y0"], atol=1e-15)
    assert np.all(reference[nodes, 2] == 0), "the interface is the base"


def test_slip_and_velocity_along_and_across_are_the_series_displacements_and_velocities(run):
    nodes = run.table("interface_blocks").typed_column("node")
    tables = {name: run.table(name) for name in ("interface_slip", "interface_slip_y", "interface_velocity",
                                                 "interface_velocity_y")}
    moved = 0
    for time, arrays, _ in snapshots(run):
        for name, (array, axis) in {"interface_slip": ("displacement", 0), "interface_slip_y": ("displacement", 1),
                                    "interface_velocity": ("velocity", 0),
                                    "interface_velocity_y": ("velocity", 1)}.items():
            written = row_at(tables[name], time)[-len(nodes):]  # after time and time_since_loading
            np.testing.assert_allclose(written, arrays[array][nodes, axis], rtol=1e-9, atol=1e-18, err_msg=name)
        moved += np.count_nonzero(arrays["displacement"][nodes, 1])
    assert moved > 0, "the Poisson bulge moves the blocks across"


def test_the_contact_map_is_every_blocks_junctions_times_one_junctions_area_and_sums_to_the_whole(run):
    nodes = run.table("interface_blocks").typed_column("node")
    contact_map, whole = run.table("contact_area_map"), run.table("contact_area")
    assert contact_map.columns[2:] == [f"block_{k}" for k in range(len(nodes))]
    assert {contact_map.units[c] for c in contact_map.columns[2:]} == {"m^2"}
    touching = 0
    for time, arrays, _ in snapshots(run):
        area = row_at(contact_map, time)[2:]
        junctions = sum(arrays[f"junctions_{phase}"][nodes] for phase in ("pinned", "sliding", "dislocated"))
        on = junctions > 0
        touching += np.count_nonzero(on)
        assert np.all(area[~on] == 0)
        if on.any():
            one = area[on] / junctions[on]
            np.testing.assert_allclose(one, one[0], rtol=1e-9, err_msg="one junction's area, pi rbar^2")
        np.testing.assert_allclose(area.sum(), row_at(whole, time)[whole.columns.index("contact_area")], rtol=1e-9)
    assert touching > 0, "the slider touches its base"


def test_a_block_off_the_first_row_has_its_own_table_and_no_bond_force(run):
    """Block 22 is the second of the second row: its own counts, slip and velocity, and NaN for the
    bond forces, which a 3D body's K (the 2D lattice's, a straight bond and its diagonals) cannot give."""
    block, nodes = run.table("contact_area_block_22"), run.table("interface_blocks").typed_column("node")
    assert np.all(np.isnan(block["bond_force_left"])) and np.all(np.isnan(block["bond_force_right"]))
    for time, arrays, _ in snapshots(run):
        row = row_at(block, time)
        at = {c: row[block.columns.index(c)] for c in ("slip", "velocity", "junctions")}
        np.testing.assert_allclose(at["slip"], arrays["displacement"][nodes[22], 0], rtol=1e-9, atol=1e-18)
        np.testing.assert_allclose(at["velocity"], arrays["velocity"][nodes[22], 0], rtol=1e-9, atol=1e-18)
        junctions = sum(arrays[f"junctions_{phase}"][nodes[22]] for phase in ("pinned", "sliding", "dislocated"))
        assert at["junctions"] == junctions


@pytest.mark.parametrize("name", ["interface_slip_y", "contact_area_map"])
def test_a_table_of_blocks_is_a_map_over_x_and_y_in_csv_and_hdf5(run, hdf5_run, name):
    bulk = run.metadata["scene"]["bulk"]
    blocks = run.table("interface_blocks")
    maps = run.interface_map(name)
    assert maps.values.shape == (len(run.table(name)), bulk["ny"], bulk["nx"])
    np.testing.assert_allclose(maps.x, np.linspace(0, bulk["length"], bulk["nx"]), atol=1e-15)
    np.testing.assert_allclose(maps.y, np.linspace(0, bulk["width"], bulk["ny"]), atol=1e-15)
    table = run.table(name)
    for k in (0, 22, len(blocks) - 1):  # a corner, the second row, the far corner
        iy, ix = np.searchsorted(maps.y, blocks["y0"][k]), np.searchsorted(maps.x, blocks["x0"][k])
        np.testing.assert_array_equal(maps.values[:, iy, ix], table[f"block_{k}"])
    stored = hdf5_run.interface_map(name)
    assert hdf5_run.table(name).path.endswith(".h5")
    np.testing.assert_allclose(stored.values, maps.values, rtol=1e-9, atol=1e-18, err_msg="the same run in HDF5")


def test_a_2d_run_has_no_interface_map(csv_run):
    with pytest.raises(KeyError, match="not a grid"):
        csv_run.interface_map("interface_slip")
