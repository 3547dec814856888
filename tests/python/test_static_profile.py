"""The settled normal-force profile (Li2020 Fig. 5) against frictionlab.reproduce.static_profile,
an independent static solve: the campaign scene's settle stage run here at theta = 0 and +-0.5,
every block within static_profile.AGREEMENT (1 %) of the mean block force, the totals F_N; and the
solve alone in a limit with a closed form."""
import os

import numpy as np
import pytest
import yaml

from conftest import run_cli
from frictionlab.reproduce import static_profile

THETAS = (0.0, 0.5, -0.5)
# theta of the campaign scene's normal_load (its loaders: base, normal load, driving spring).
THETA_KEY = "loaders[1].theta"


def campaign_scene_path(source_dir):
    return os.path.join(source_dir, "configs", "li2020", "campaign_scene.yaml")


@pytest.fixture(scope="module")
def settled_runs(cli, source_dir, tmp_path_factory):
    """The campaign scene's settle stage (then 1 us of loading) at each theta, observed at its end."""
    folder = tmp_path_factory.mktemp("static_profile")
    runs = {}
    for theta in THETAS:
        out = str(folder / f"theta_{theta:+g}")
        sets = [a for o in static_profile.run_overrides() + [f"{THETA_KEY}={theta}"] for a in ("--set", o)]
        result = run_cli(cli, "run", "-q", campaign_scene_path(source_dir), "-o", out, *sets)
        assert result.returncode == 0, result.stdout + result.stderr
        runs[theta] = out
    return runs


@pytest.mark.parametrize("theta", THETAS)
def test_the_settled_profile_is_the_independent_static_solves(settled_runs, theta):
    comparison = static_profile.compare(settled_runs[theta])
    assert len(comparison) == 41
    assert static_profile.largest_difference(comparison) < static_profile.AGREEMENT, comparison.to_string()
    # Nothing but the base holds the slider up: both carry the whole load.
    assert comparison["simulated"].sum() == pytest.approx(400.0, rel=1e-6)
    assert comparison["solved"].sum() == pytest.approx(400.0, rel=1e-9)


def test_the_command_prints_the_largest_difference_of_each_run(settled_runs, capsys):
    static_profile.main([settled_runs[0.0]])
    assert capsys.readouterr().out.startswith(f"{settled_runs[0.0]}: largest difference ")


@pytest.mark.parametrize("stiffness_ratio", [1e-3, 1e-5])
def test_a_slider_stiff_against_its_base_carries_the_load_as_applied(source_dir, stiffness_ratio):
    """A rigid slider on springs (a Winkler foundation) compresses them linearly in x, so P_b is the
    linear profile with the load's total and moment; the normalised Eq. 3 is one, so P_b -> W_i as
    K_b/K -> 0, junctions or not (they act along x and on the interface plane), within O(K_b/K)."""
    with open(campaign_scene_path(source_dir)) as f:
        scene = yaml.safe_load(f)
    scene["loaders"][0]["stiffness_ratio"] = stiffness_ratio
    scene["loaders"][1]["theta"] = 0.5
    normal = static_profile.settled_normal_forces(scene)
    applied = static_profile.load_weights(static_profile.with_defaults(scene["loaders"][1],
                                                                       static_profile.LOAD_DEFAULTS), 41)
    assert np.abs(normal - applied).max() < 10 * stiffness_ratio * applied.mean()
