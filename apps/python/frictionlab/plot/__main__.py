"""python3 -m frictionlab.plot: what `frictionlab plot` and `frictionlab study` run (the package's
docstring). Figures go to files only: matplotlib's Agg backend, no window."""
import sys

import matplotlib

from ._command import main

matplotlib.use("Agg")
sys.exit(main(sys.argv[1:]))
