"""The ParaView series of a 3D run: the lattice as hexahedra, and its interface as a surface of its
own (lattice_interface.pvd), one quad per face of the base, with each block's slip speed and the
fields published over the interface, read back by VTK's own reader."""
import os
import re

import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonDataModel import VTK_HEXAHEDRON, VTK_QUAD
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader


def read(path):
    reader = vtkXMLUnstructuredGridReader()
    reader.SetFileName(path)
    reader.Update()
    return reader.GetOutput()


def listed(collection):
    with open(collection) as f:
        return re.findall(r'timestep="([^"]+)"[^>]*file="([^"]+)"', f.read())


def test_a_3d_runs_series_has_hexahedra_and_the_interface_as_its_own_surface(run_3d):
    bulk = run_3d.metadata["scene"]["bulk"]
    nx, ny, nz = bulk["nx"], bulk["ny"], bulk["nz"]
    lattice = listed(os.path.join(run_3d.directory, "lattice.pvd"))
    interface = listed(os.path.join(run_3d.directory, "lattice_interface.pvd"))
    assert [t for t, _ in interface] == [t for t, _ in lattice] and len(lattice) >= 2
    grid = read(os.path.join(run_3d.directory, lattice[-1][1]))
    assert grid.GetNumberOfCells() == (nx - 1) * (ny - 1) * (nz - 1)
    assert set(vtk_to_numpy(grid.GetCellTypesArray())) == {VTK_HEXAHEDRON}
    surface = read(os.path.join(run_3d.directory, interface[-1][1]))
    assert surface.GetNumberOfPoints() == nx * ny and surface.GetNumberOfCells() == (nx - 1) * (ny - 1)
    assert set(vtk_to_numpy(surface.GetCellTypesArray())) == {VTK_QUAD}
    points = vtk_to_numpy(surface.GetPoints().GetData())
    assert np.all(points[:, 2] == 0)  # the base, at its reference positions
    data = surface.GetPointData()
    velocity = vtk_to_numpy(data.GetArray("velocity"))
    np.testing.assert_allclose(vtk_to_numpy(data.GetArray("slip_speed")), np.hypot(velocity[:, 0], velocity[:, 1]))
    for field in ("normal_force", "friction_force", "slipping"):
        assert data.HasArray(field), field
    # The surface's blocks are the lattice's base: the same velocities, and the same snapshot's time.
    lattice_velocity = vtk_to_numpy(grid.GetPointData().GetArray("velocity"))
    np.testing.assert_array_equal(velocity, lattice_velocity[: nx * ny])
    assert surface.GetFieldData().GetArray("TIME").GetValue(0) == grid.GetFieldData().GetArray("TIME").GetValue(0)
