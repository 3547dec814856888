"""What every figure shares: where a figure function draws (the Axes it is given, else a new
figure's), what a panel without data shows, and how the command writes a figure to files."""
import os

import matplotlib
import matplotlib.pyplot as plt
import numpy as np


class NothingToDraw(LookupError):
    """The run lacks what a figure draws (its table, or the column): the figure function draws
    nothing, and the command writes no file for that figure."""


def axes_of(ax, *grid, **figure):
    """`ax` (an Axes, or several) if given, else those of a new figure: plt.subplots(*grid, **figure)."""
    return plt.subplots(*grid, **figure)[1] if ax is None else ax


def no_data(ax, what):
    """A panel with nothing to draw says so instead of staying empty."""
    ax.text(0.5, 0.5, what, transform=ax.transAxes, ha="center", va="center", color="0.4", fontsize=9)


# What tells the seeds of overlaid runs apart, the colour telling their cases apart.
SEED_MARKERS = "os^vDP*Xh<>p"
SEED_LINESTYLES = ["-", "--", ":", "-.", (0, (5, 1, 1, 1, 1, 1)), (0, (1, 3)), (0, (8, 2)), (0, (3, 1, 1, 1))]


def seed_style(seeds, seed):
    """{marker, linestyle} of `seed` among `seeds` (all the seeds drawn, in order)."""
    k = sorted(set(seeds)).index(seed)
    return {"marker": SEED_MARKERS[k % len(SEED_MARKERS)], "linestyle": SEED_LINESTYLES[k % len(SEED_LINESTYLES)]}


def save(fig, out_dir, name):
    """out_dir/NAME.png and NAME.svg of the figure, which is then closed; the SVG keeps its text as
    text (searchable, editable)."""
    os.makedirs(out_dir, exist_ok=True)
    with matplotlib.rc_context({"svg.fonttype": "none"}):
        for ext in ("png", "svg"):
            fig.savefig(os.path.join(out_dir, f"{name}.{ext}"), dpi=150, bbox_inches="tight")
    plt.close(fig)
    print(os.path.join(out_dir, name + ".png"))


def write(out_dir, name, figure, *args):
    """figure(*args) drawn on a figure of its own and saved as out_dir/NAME; no file if the run lacks
    what it draws (NothingToDraw)."""
    try:
        drawn = figure(*args)
    except NothingToDraw:
        return
    save(np.ravel(drawn)[0].figure, out_dir, name)
