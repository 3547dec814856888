"""The static response of a 3D block on the rigid base under a uniform load (issue: the lattice's
exact results): the run's rest state, reached by the hybrid stepper's static solves, against an
independent solve of the same linear structure assembled here from the lattice's documented
constants (theory.md 1b, 2): springs k = 2Ea/5 along the 6 nearest and 12 face-diagonal bonds (small
strain: k n n^T each), the base K_b = K/2 = k on each interface node along z, the Coulomb springs
k_t along x and y, and F_N/(n_x n_y) down on each node of the top face."""
import itertools
import os

import numpy as np
import pytest
import scipy.sparse
import scipy.sparse.linalg
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridReader

import frictionlab

HERE = os.path.dirname(os.path.abspath(__file__))
SCENE = os.path.join(HERE, "scenes", "block_on_base_3d.yaml")


def independent_solve(nx, ny, nz, a, youngs_modulus, tangential, total_force):
    """Displacements (n, 3) of the nodes ix + nx (iy + ny iz) at rest."""
    k = 2 * youngs_modulus * a / 5
    n = nx * ny * nz
    index = lambda ix, iy, iz: ix + nx * (iy + ny * iz)
    rows, cols, values = [], [], []

    def add(i, j, block):
        for r, c in itertools.product(range(3), range(3)):
            rows.append(3 * i + r), cols.append(3 * j + c), values.append(block[r, c])

    directions = [d for d in itertools.product((-1, 0, 1), repeat=3) if 0 < sum(map(abs, d)) <= 2 and d > (0, 0, 0)]
    assert len(directions) == 9  # 3 straight and 6 face-diagonal, each bond once
    for ix, iy, iz in itertools.product(range(nx), range(ny), range(nz)):
        for d in directions:
            jx, jy, jz = ix + d[0], iy + d[1], iz + d[2]
            if not (0 <= jx < nx and 0 <= jy < ny and 0 <= jz < nz):
                continue
            u = np.array(d, float) / np.linalg.norm(d)
            block = k * np.outer(u, u)
            i, j = index(ix, iy, iz), index(jx, jy, jz)
            add(i, i, block), add(j, j, block), add(i, j, -block), add(j, i, -block)
    f = np.zeros(3 * n)
    for ix, iy in itertools.product(range(nx), range(ny)):
        base = index(ix, iy, 0)
        add(base, base, np.diag([tangential, tangential, k]))  # Coulomb springs, base contact K/2 = k
        f[3 * index(ix, iy, nz - 1) + 2] -= total_force / (nx * ny)
    stiffness = scipy.sparse.csc_matrix((values, (rows, cols)), shape=(3 * n, 3 * n))
    return scipy.sparse.linalg.spsolve(stiffness, f).reshape(n, 3)


@pytest.fixture(scope="module")
def rest(tmp_path_factory):
    run = frictionlab.Scene.load(SCENE).run(output=str(tmp_path_factory.mktemp("block") / "out"))
    snapshots = sorted(os.listdir(os.path.join(run.directory, "lattice")))
    reader = vtkXMLUnstructuredGridReader()
    reader.SetFileName(os.path.join(run.directory, "lattice", snapshots[-1]))
    reader.Update()
    return run, vtk_to_numpy(reader.GetOutput().GetPointData().GetArray("displacement"))


def test_the_block_comes_to_rest_where_an_independent_static_solve_puts_it(rest):
    run, displacement = rest
    bulk, friction = run.metadata["scene"]["bulk"], run.metadata["scene"]["friction"]
    a = float(bulk["length"]) / (bulk["nx"] - 1)
    # float(): YAML 1.1 readers take 3e+09 (no point) for a string.
    expected = independent_solve(bulk["nx"], bulk["ny"], bulk["nz"], a, float(bulk["youngs_modulus"]),
                                 float(friction["tangential_stiffness"]),
                                 float(run.metadata["scene"]["loaders"][1]["total_force"]))
    scale = np.abs(expected).max()
    assert scale > 1e-7, "the load compresses the block measurably"
    # The static solves stop at corrections below 1e-13 m, 1e-8 of this scale (measured: 2e-13 of it).
    np.testing.assert_allclose(displacement, expected, rtol=0, atol=1e-8 * scale)


def test_its_rest_state_has_the_symmetries_and_the_poisson_bulge_of_a_pressed_block(rest):
    run, u = rest
    bulk = run.metadata["scene"]["bulk"]
    nx, ny, nz = bulk["nx"], bulk["ny"], bulk["nz"]
    grid = u.reshape(nz, ny, nx, 3)
    # Mirror symmetric in x and y; pressed down; the top face bulges out sideways more than the
    # base, which the Coulomb springs hold.
    np.testing.assert_allclose(grid[:, :, ::-1, 0], -grid[..., 0], atol=1e-12)
    np.testing.assert_allclose(grid[:, ::-1, :, 1], -grid[..., 1], atol=1e-12)
    assert np.all(grid[..., 2] < 0)
    assert grid[-1, 0, -1, 0] > grid[0, 0, -1, 0] > 0
