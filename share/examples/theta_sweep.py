#!/usr/bin/python3
"""θ sweep: how the non-uniformity of the normal load changes the number of precursors.

Runs one scene for each θ (the `theta` of its `normal_load` loader: the trailing edge carries
(1 - θ) F_N/N_x, the leading edge (1 + θ) F_N/N_x), counts the precursors before the first global
slip of each run, and plots that count against θ (Li et al. 2020, Figs. 7 and 8; Maegawa et al. 2010).

    PYTHONPATH=build/python /usr/bin/python3 share/examples/theta_sweep.py \\
        configs/li2020/maegawa_uniform.yaml --theta -0.2 0 0.2 -o out/theta_sweep

Start from here: change the scene, the parameter swept (any `--set` key path) or the figure.
"""
import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import yaml  # noqa: E402

import frictionlab  # noqa: E402


def normal_load_index(scene):
    """The position of the `normal_load` loader in the scene's `loaders:` list."""
    loaders = yaml.safe_load(scene.resolved_yaml)["loaders"]
    return next(i for i, loader in enumerate(loaders) if loader["type"] == "normal_load")


def precursor_count(run):
    """Precursors before the first global slip; NaN in a run without one (the summary's
    `precursor_count` is null there: there is no "before")."""
    with open(os.path.join(run.directory, "precursors_summary.yaml")) as f:
        summary = yaml.safe_load(f)
    count = summary["precursor_count"]
    return float("nan") if count is None else count


def main(argv):
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("scene")
    parser.add_argument("--theta", type=float, nargs="+", default=[-0.3, -0.15, 0.0, 0.15, 0.3])
    parser.add_argument("--set", action="append", default=[], help="further key.path=value overrides")
    parser.add_argument("-o", "--output", default="out/theta_sweep")
    args = parser.parse_args(argv)

    index = normal_load_index(frictionlab.Scene.load(args.scene, set=args.set))
    counts = []
    for theta in args.theta:
        scene = frictionlab.Scene.load(args.scene, set=args.set + [f"loaders[{index}].theta={theta}"])
        run = scene.run(output=os.path.join(args.output, f"theta_{theta:+.3f}"), overwrite=True)
        counts.append(precursor_count(run))
        print(f"theta = {theta:+.3f}: {counts[-1]} precursors ({run.directory})")

    fig, ax = plt.subplots(figsize=(5, 3.5))
    ax.plot(args.theta, counts, "o-k")
    ax.set_xlabel(r"non-uniformity of the normal load $\theta$")
    ax.set_ylabel("precursors before global slip")
    fig.tight_layout()
    figure = os.path.join(args.output, "precursors_vs_theta.png")
    fig.savefig(figure, dpi=150)
    with open(os.path.join(args.output, "precursors_vs_theta.csv"), "w") as f:
        f.write("theta,precursors\n" + "".join(f"{t},{n}\n" for t, n in zip(args.theta, counts)))
    print(f"figure: {figure}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
