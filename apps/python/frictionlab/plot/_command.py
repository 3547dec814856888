"""`frictionlab plot`'s command line (python3 -m frictionlab.plot; the package's docstring)."""
import argparse
import os
import sys

from .campaign_figures import plot_study, plot_sweep
from .run_figures import plot_runs

# The campaigns drawn from their directory: the option, the table the directory has, the drawing.
CAMPAIGNS = {"--sweep": ("sweep.csv", plot_sweep), "--study": ("study.csv", plot_study)}


def main(argv):
    """Draws what the command line `argv` asks for (the package's docstring); returns the exit
    status."""
    if argv[:1] and argv[0] in CAMPAIGNS:
        name, draw = CAMPAIGNS[argv[0]]
        if len(argv) != 2 or not os.path.exists(os.path.join(argv[1], name)):
            print(f"frictionlab.plot {argv[0]} {argv[0][2:].upper()}_DIR: expected a directory with {name}",
                  file=sys.stderr)
            return 2
        draw(argv[1])
        return 0
    parser = argparse.ArgumentParser(prog="frictionlab plot", description="Pictures of FrictionLab runs, in the style "
                                     "of Li et al. (2020) and of the experiments.")
    parser.add_argument("runs", nargs="+", help="run output directories")
    parser.add_argument("-o", "--output", help="where the figure over all runs goes (default: first run's plots/)")
    args = parser.parse_args(argv)
    for run in args.runs:
        if not os.path.exists(os.path.join(run, "run.yaml")):
            print(f"frictionlab plot: {run} is not a run directory (no run.yaml)", file=sys.stderr)
            return 2
    plot_runs(args.runs, args.output)
    return 0
