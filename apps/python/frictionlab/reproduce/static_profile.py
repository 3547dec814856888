"""An independent static solve of the settled normal-force profile (Li et al. 2020, Fig. 5).

After the `settle` stage the slider rests on the base under its normal load, and the normal force
each interface block carries is the profile of Fig. 5. The simulator reaches it by damped dynamics;
this module derives it again from the scene's parameters alone, sharing nothing with the C++ code:
it assembles the lattice's linear stiffness, the base, the load and the junctions' tangential
restraint as share/docs/theory.md (§1-3, §5) and the plugins define them. Being a second derivation
is its purpose, so it repeats the plugins' defaults and formulas rather than asking them.

    python3 -m frictionlab.reproduce.static_profile RUN_DIR...

prints, for each run (observed by interface_history at the end of its settle stage), the largest
difference between the simulated and the solved profile, relative to the mean block force;
compare() gives it block by block.
"""
import argparse
import math
import os
from dataclasses import dataclass

import numpy as np
import pandas as pd
import scipy.sparse as sparse
import scipy.sparse.linalg as sparse_linalg
import yaml

# The plugins' defaults (their ParamSpecs): a scene as written leaves them out, run.yaml has them.
LATTICE_DEFAULTS = {"length": 0.1, "height": 0.02, "width": 0.005, "youngs_modulus": 3e9, "nx": 41, "nz": 9,
                    "reference_spacing": 2.5e-3}
BASE_DEFAULTS = {"stiffness_ratio": 0.5, "stiffness_per": "area", "node_set": "interface"}
LOAD_DEFAULTS = {"total_force": 400.0, "theta": 0.0, "formula": "normalised", "node_set": "top"}
JUNCTION_DEFAULTS = {"hardness": 300e6, "contact_radius": 10e-6, "youngs_modulus": 3e9, "poisson_ratio": 0.33,
                     "tangential_stiffness": 0.0, "mu_s": 0.7, "settle_overload": "slip_and_repin",
                     "node_set": "interface"}
# How close the simulated profile must come to the solve: every block within 1 % of the mean block
# force. Measured on the campaign scene: 5-6e-4 (theta = 0, +-0.5), from the dynamics of the 2 ms
# load ramp (it falls as 1/ramp_time) and the springs' geometric nonlinearity (about 2e-4).
AGREEMENT = 0.01
# P_b/p this close to an integer counts as it (the friction law's tolerance on junction counts).
COUNT_TOLERANCE = 1e-9
# Spacings equal to this relative tolerance are the same (the plugins' square-cell and reference rules).
SAME_SPACING = 1e-9


def with_defaults(section, defaults):
    """The section with the plugin's defaults filled in, its numbers as numbers: YAML 1.1 reads
    3e+09 (no dot) as a string, which the simulator reads as a number."""
    merged = {**defaults, **(section or {})}
    return {k: type(defaults[k])(v) if isinstance(defaults.get(k), (int, float)) else v for k, v in merged.items()}


@dataclass
class Lattice:
    """spring_lattice_2d's grid: node ix + nx iz at (ix, iz) l_s; row 0 is the interface."""
    nx: int
    nz: int
    spacing: float
    bond_stiffness: float  # K = 3BE/4 on straight bonds, K/2 on diagonals
    reference_spacing: float

    @classmethod
    def of(cls, bulk):
        if bulk.get("type") != "spring_lattice_2d":
            raise NotImplementedError(f"static solve: bulk '{bulk.get('type')}' is not modelled")
        b = with_defaults(bulk, LATTICE_DEFAULTS)
        spacing = b["length"] / (b["nx"] - 1)
        if abs(spacing - b["height"] / (b["nz"] - 1)) > SAME_SPACING * spacing:
            raise ValueError("static solve: the lattice cells must be square")
        return cls(b["nx"], b["nz"], spacing, 0.75 * b["width"] * b["youngs_modulus"], b["reference_spacing"])

    @property
    def nodes(self):
        return self.nx * self.nz

    def row(self, iz):
        return np.arange(self.nx) + self.nx * iz

    def stiffness(self):
        """The central springs linearised about the reference lattice, k e e^T per bond (e its unit
        vector), on the dofs (x of every node, then z of every node)."""
        n = self.nodes
        ix, iz = (a.ravel() for a in np.meshgrid(np.arange(self.nx), np.arange(self.nz), indexing="ij"))
        r = 1 / math.sqrt(2)
        rows, cols, values = [], [], []
        # Grid offset, unit vector, stiffness relative to K (Li2020 §2.1).
        for (dx, dz), e, relative in (((1, 0), (1, 0), 1.0), ((0, 1), (0, 1), 1.0),
                                      ((1, 1), (r, r), 0.5), ((-1, 1), (-r, r), 0.5)):
            inside = (ix + dx >= 0) & (ix + dx < self.nx) & (iz + dz < self.nz)
            i = (ix + self.nx * iz)[inside]
            j = i + dx + self.nx * dz
            g = relative * self.bond_stiffness * np.outer(e, e)
            ends = ((i, n + i), (j, n + j))  # (x, z) dofs of each bond's two nodes
            for a in range(2):
                for b in range(2):
                    for u in range(2):
                        for w in range(2):
                            rows.append(ends[a][u])
                            cols.append(ends[b][w])
                            values.append(np.full(i.size, (1.0 if a == b else -1.0) * g[u, w]))
        return sparse.csr_matrix((np.concatenate(values), (np.concatenate(rows), np.concatenate(cols))),
                                 shape=(2 * n, 2 * n))


@dataclass
class Junctions:
    """three_state_junctions while friction events are off: a block carries floor(P_b/p) pinned
    junctions of stiffness k_s, each anchored where its block was when it formed."""
    load: float       # p = pi rbar^2 H_d, N
    stiffness: float  # k_s, N/m
    threshold: float  # mu_s p, N
    repins_overloaded: bool  # settle_overload: slip_and_repin

    @classmethod
    def of(cls, friction):
        if friction is None:
            return None
        if friction.get("type") != "three_state_junctions":
            raise NotImplementedError(f"static solve: friction '{friction.get('type')}' is not modelled")
        f = with_defaults(friction, JUNCTION_DEFAULTS)
        if f["node_set"] != "interface":
            raise NotImplementedError("static solve: junctions on another node set than the interface")
        load = math.pi * f["contact_radius"] ** 2 * f["hardness"]
        stiffness = f["tangential_stiffness"]
        if stiffness <= 0:  # Mindlin, no slip: 8 G* rbar, G = E/(2(1+nu)), G* = G/(2(2-nu))
            nu = f["poisson_ratio"]
            stiffness = 8 * f["youngs_modulus"] / (2 * (1 + nu)) / (2 * (2 - nu)) * f["contact_radius"]
        return cls(load, stiffness, f["mu_s"] * load, f["settle_overload"] == "slip_and_repin")


def base_stiffness(lattice, base):
    """K_b = stiffness_ratio K at the reference spacing, the same per unit area on another lattice."""
    k = base["stiffness_ratio"] * lattice.bond_stiffness
    reference = lattice.reference_spacing if base["stiffness_per"] == "area" else 0.0
    if reference <= 0 or abs(lattice.spacing - reference) <= SAME_SPACING * reference:
        return k
    return k * lattice.spacing / reference


def load_weights(load, count):
    """W_i of Li2020 Eq. 3 on the top row, normalised to sum to F_N (theory.md B.1) or as printed."""
    i = np.arange(1, count + 1, dtype=float)
    if load["formula"] == "paper_literal":
        shape = (2 * i - count) / count
    else:
        shape = (2 * i - count - 1) / (count - 1) if count > 1 else np.zeros(count)
    return load["total_force"] / count * (1 + load["theta"] * shape)


def settle_stage(scene):
    """The scene's first stage, in which the normal load is applied and no junction may break."""
    stage = (scene.get("stages") or [{}])[0]
    if stage.get("friction_events", True):
        raise ValueError("static solve: the first stage must have friction_events: false (junctions that "
                         "break are not modelled)")
    return stage


def settle_loaders(scene):
    """The base and the normal load, with defaults: the loaders acting in the settle stage, which
    must be just these two."""
    name = settle_stage(scene).get("name")
    active = {l["type"]: l for l in scene.get("loaders", []) if name in l.get("stages", [name])}
    if set(active) != {"rigid_base_contact", "normal_load"}:
        raise NotImplementedError(f"static solve: settling under {sorted(active)} is not modelled "
                                  "(rigid_base_contact and normal_load are)")
    base = with_defaults(active["rigid_base_contact"], BASE_DEFAULTS)
    load = with_defaults(active["normal_load"], LOAD_DEFAULTS)
    if base["node_set"] != "interface" or load["node_set"] != "top":
        raise NotImplementedError("static solve: the base under the interface row and the load on the top row only")
    return base, load


class InterfaceResponse:
    """The lattice on the base under its full load, condensed onto the interface blocks' x: for a
    tangential restraint D (N/m per block), the rates of their x and of their normal forces P_b per
    unit load fraction. The rest of the dofs (K_RR) is regular: the base holds z and rotation."""

    def __init__(self, lattice, base_k, top_load):
        n = lattice.nodes
        interface = lattice.row(0)
        on_base = np.zeros(2 * n)
        on_base[n + interface] = base_k
        k = (lattice.stiffness() + sparse.diags(on_base)).tocsr()
        force = np.zeros(2 * n)
        force[n + lattice.row(lattice.nz - 1)] = -top_load
        rest = np.setdiff1d(np.arange(2 * n), interface)
        k_ri = k[rest][:, interface].toarray()
        # K_RR^-1 [f_R, K_RI]: the rest's displacement under the load and per unit interface x.
        solved = sparse_linalg.spsolve(k[rest][:, rest].tocsc(), np.column_stack([force[rest], k_ri]))
        self.schur = k[interface][:, interface].toarray() - k_ri.T @ solved[:, 1:]
        self.condensed_load = -k_ri.T @ solved[:, 0]
        interface_z = np.searchsorted(rest, n + interface)
        # P_b = -K_b z, z = (load part) - (coupling) x.
        self.normal_load = -base_k * solved[interface_z, 0]
        self.normal_coupling = base_k * solved[interface_z, 1:]

    def rates(self, restraint):
        """d x/d lambda and d P_b/d lambda of the interface blocks under the restraint."""
        matrix = self.schur + np.diag(restraint)
        if restraint.any():
            x = np.linalg.solve(matrix, self.condensed_load)
        else:  # free along x: any solution will do, a rigid translation loads nothing
            x = np.linalg.lstsq(matrix, self.condensed_load, rcond=None)[0]
        return x, self.normal_load + self.normal_coupling @ x


def settled_normal_forces(scene):
    """Normal force on the base of each interface block (N, ordered by x) at rest after settling.

    Modelled: the lattice's central springs (K, K/2) linearised about the reference configuration;
    the base as springs K_b on the interface z (every block in contact); the top row loaded by W_i
    (normal_load's Eq. 3); and the tangential restraint of three_state_junctions while friction
    events are off. There a block carries floor(P_b/p) pinned junctions (B.7: the count follows P_b,
    none breaks), each a spring k_s anchored where the block was when it formed. The restraint thus
    remembers the path, and it shapes the profile: on the campaign scene a frictionless interface
    would be off by 19-24 % of the mean block force, one whose final junctions were all anchored at
    the reference position by 6-7 %.
    So the solve follows the quasi-static loading path, lambda = 0..1 of the (proportionally ramped)
    load. Between count changes the problem is linear: with the current counts it takes the rates of
    x and P_b, advances to the lambda at which a block's P_b/p reaches the next integer, adds that
    junction (it then stiffens the increments only, being anchored there) and repeats - the fixed
    point of counts and forces, taken exactly, one junction at a time.

    Assumed: the damped dynamics of the ramp stay close to this path (a uniform lag does not matter,
    as a junction still forms where the state reaches its P_b; the residual falls as 1/ramp_time, a
    few 1e-4 of the mean at the campaigns' 2 ms), and geometric nonlinearity (strains ~1e-3) is left
    out. Refused (NotImplementedError), as not modelled: a block leaving the base, a P_b falling by a
    whole p (a random junction would go), and a junction above mu_s p under slip_and_repin.
    """
    lattice = Lattice.of(scene["bulk"])
    base, load = settle_loaders(scene)
    response = InterfaceResponse(lattice, base_stiffness(lattice, base), load_weights(load, lattice.nx))
    junctions = Junctions.of(scene.get("friction"))
    if junctions is None:
        normal = response.rates(np.zeros(lattice.nx))[1]
    else:
        normal = follow_loading_path(response, junctions, lattice.nx)
    if np.any(normal <= 0):
        raise NotImplementedError("static solve: a block leaves the base (not modelled)")
    return normal


def follow_loading_path(response, junctions, blocks):
    """P_b at full load, the junction counts following it on the way (see settled_normal_forces)."""
    p = junctions.load
    counts, x, normal = np.zeros(blocks), np.zeros(blocks), np.zeros(blocks)
    anchors = [[] for _ in range(blocks)]
    done = 0.0
    while done < 1.0:
        x_rate, normal_rate = response.rates(junctions.stiffness * counts)
        with np.errstate(divide="ignore", invalid="ignore"):
            to_next = np.where(normal_rate > 0, ((counts + 1 - COUNT_TOLERANCE) * p - normal) / normal_rate, np.inf)
            to_removal = np.where(normal_rate < 0, ((counts - 1 + COUNT_TOLERANCE) * p - normal) / normal_rate,
                                  np.inf)
        step = max(0.0, to_next.min())
        if to_removal.min() < min(step, 1.0 - done):
            raise NotImplementedError("static solve: a block's normal force falls by a junction's load on the way "
                                      "(its random removal is not modelled)")
        if step >= 1.0 - done:
            step, done = 1.0 - done, 1.0  # not done += step, which could leave a sliver of path
        else:
            done += step
        x += x_rate * step
        normal += normal_rate * step
        formed = np.floor(normal / p + COUNT_TOLERANCE)
        reached = to_next <= step
        formed[reached] = np.maximum(formed, counts + 1)[reached]  # the block the step went to, whatever the rounding
        for block in np.flatnonzero(formed > counts):
            anchors[block] += [x[block]] * int(formed[block] - counts[block])
        counts = np.maximum(counts, formed)
    check_no_overload(junctions, x, anchors)
    return normal


def check_no_overload(junctions, x, anchors):
    """slip_and_repin re-pins a junction stretched past mu_s p while settling (B.18a): not modelled."""
    largest = max((junctions.stiffness * abs(x[b] - a) for b, block in enumerate(anchors) for a in block), default=0.0)
    if junctions.repins_overloaded and largest > junctions.threshold:
        raise NotImplementedError(f"static solve: a junction carries {largest / junctions.threshold:.4f} mu_s p, "
                                  "which settle_overload would re-pin (not modelled)")


def run_overrides():
    """The --set overrides that run a scene shaped like configs/li2020/campaign_scene.yaml (settle,
    then load) for its settling only, observed by interface_history at the settle stage's end
    (its 10 ms are a whole number of observation intervals)."""
    return ["stages[1].duration=1.0e-6", "observers=[{type: interface_history, every: 1.0e-3}]"]


def simulated_profile(run_dir, scene, quantity="normal_force"):
    """interface_history's `quantity` (interface_QUANTITY.csv) per block at the end of the settle stage."""
    table = pd.read_csv(os.path.join(run_dir, f"interface_{quantity}.csv"))
    end = float(settle_stage(scene)["duration"])
    at_end = np.flatnonzero(np.abs(table["time"].to_numpy() - end) <= 1e-9 * max(1.0, end))
    if at_end.size == 0:
        raise ValueError(f"{run_dir}: interface_history has no row at the end of the settle stage (t = {end:g} s); "
                         "observe it at an interval that divides the stage's duration")
    row = table.iloc[at_end[-1]]
    return row[[c for c in table.columns if c.startswith("block_")]].to_numpy(dtype=float)


def compare(run_dir):
    """Per interface block: the simulated settled normal force, the solved one from the run's
    resolved scene (run.yaml), and their difference relative to the mean block force."""
    with open(os.path.join(run_dir, "run.yaml")) as f:
        scene = yaml.safe_load(f)["scene"]
    simulated = simulated_profile(run_dir, scene)
    solved = settled_normal_forces(scene)
    return pd.DataFrame({"simulated": simulated, "solved": solved,
                         "relative_difference": (simulated - solved) / solved.mean()},
                        index=pd.RangeIndex(len(solved), name="block"))


def largest_difference(comparison):
    """The largest |simulated - solved| over the blocks of compare(), relative to the mean block force."""
    return float(comparison["relative_difference"].abs().max())


def main(argv=None):
    parser = argparse.ArgumentParser(prog="python3 -m frictionlab.reproduce.static_profile",
                                     description=__doc__.splitlines()[0])
    parser.add_argument("runs", nargs="+", metavar="RUN_DIR", help="a run observed by interface_history")
    for run_dir in parser.parse_args(argv).runs:
        print(f"{run_dir}: largest difference {largest_difference(compare(run_dir)):.3e} of the mean block force")


if __name__ == "__main__":
    main()
