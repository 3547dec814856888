"""Pictures of FrictionLab runs, in the style of Li et al. (2020) and of the experiments.

Every figure is a function that draws onto the matplotlib Axes it is given and returns them, as
seaborn's and xarray's do; with none it draws a new figure of the size `frictionlab plot` writes:

    import matplotlib.pyplot as plt
    import frictionlab.plot
    fig, (left, right) = plt.subplots(1, 2, figsize=(12, 4))
    frictionlab.plot.loading_curve("out/headline", ax=left)
    frictionlab.plot.precursor_lengths(["out/headline", "out/other"], ax=right)

A run is its output directory (a str or os.PathLike) or a frictionlab.Run; a figure of several
panels takes `axes`, as many as it draws. A figure whose table the run lacks draws nothing and
raises NothingToDraw. The figures by family: run_figures (one run, or several overlaid),
campaign_figures (a sweep, an accuracy study), lattice_rendering (the lattice, by VTK into a PNG or
by matplotlib onto an Axes); the tables they read: table(run, name).

    frictionlab plot RUN_DIR [RUN_DIR ...] [-o OUT_DIR]      (python3 -m frictionlab.plot ...)

For each run directory, writes into RUN_DIR/plots/ (PNG and SVG) whichever figures its outputs allow
(plot_run):
  loading_curve   F_S against time with the precursors marked, their l/L below (Li2020 Fig. 6)
  four_phase_<i>  pinned fraction, state fractions, slip, velocity and forces of interface block i
                  around the first event that reaches it (Li2020 Fig. 9; Ben-David et al. 2010)
  spacetime       slip velocity and pinned fraction along the interface against time
  fronts          rupture-front position against time since nucleation, one curve per event, with
                  the lattice's shear and Rayleigh wave speeds c_S and c_R for reference
  energy          the energy balance: input, stored, kinetic, dissipated, residual
  interface       a 3D run's interface seen from below: its blocks' slip speed over x and y at the
                  six lattice snapshots up to the fastest (a global slip), so a front shows as it
                  crosses the interface in both directions
  lattice         the lattice around the first global slip (its VTU snapshot; the last snapshot in a
                  run without one; a 3D run's front face, from the side), coloured by the nodes'
                  x velocity, displacement magnified:
                  rendered by VTK offscreen (under a private Xvfb without an X display), so PNG only
and, over all the runs given (into -o, default the first run's plots/: plot_runs): precursor_lengths,
l/L against F_S/F_N (Li2020 Figs. 7, 8), and with several runs loading_curves, F_S/F_N overlaid.

Every time axis has one origin, when loading started: the start of the first stage in which a
driving loader (driving_spring, plate_springs) acts (every stage if it names none), or of the last
stage in a scene without one, from the stage durations the run's run.yaml records. Figures on an
event's own clock (four_phase: since detachment; fronts: since nucleation) say when the event came
after loading started. Every title names the scene: its title, F_N, theta, h, the friction law and
the seed, from run.yaml. A panel without data says so, and so does a figure of a run without the
event it draws.

    frictionlab plot SWEEP_DIR                 (python3 -m frictionlab.plot --sweep SWEEP_DIR)

draws into SWEEP_DIR/plots/ from its sweep.csv, events.csv and sweep_statistics.csv (plot_sweep):
sweep_precursor_lengths (l/L against F_S/F_N, coloured by case, a marker per seed: Li2020 Fig. 7),
sweep_against_<key> for a numeric varied key such as theta (precursor count, first-precursor and
global-slip F_S/F_N: each seed a faint dot, the mean over the seeds with its 95 % interval; a series
per value of the other varied keys: Li2020 Fig. 8) and sweep_loading_curves (every case's F_S
against time since loading, overlaid, a line style per seed). Axes name the varied keys by symbol
and unit (θ, F_N [N], h [mm], V [m/s]); titles are the sweep file's `title`.

    python3 -m frictionlab.plot --study STUDY_DIR      (run by `frictionlab study`)

draws work_precision (PNG and SVG) into STUDY_DIR from its study.csv (plot_study): each error against
wall time, log-log, one curve per family of cases; over seeds (ensemble.csv) also
ensemble_work_precision (each case's mean less the reference's, with its 95 % bootstrap interval
and the accuracy standard's tolerance, against CPU time per run, a panel per event statistic) and
single_seed_divergence (per seed, how far RK4 at dt and at dt/2, the `half_step` case, part on the
k-th rupture event's start time and F_S/F_N, against k).

Overlays tell runs apart by the physics values that differ between them (never where they write:
output, observers, checkpoint), and their seeds by marker or line style.
"""
from ._clock import time_origin
from ._command import main
from ._figure import NothingToDraw
from ._labels import run_label
from ._tables import table
from .campaign_figures import (ensemble_work_precision, plot_study, plot_sweep, single_seed_divergence, sweep_against,
                               sweep_loading_curves, sweep_precursor_lengths, work_precision)
from .interface_figures import interface_maps
from .patch_figures import patch_growth
from .lattice_rendering import lattice, plot_lattice, render_lattice
from .run_figures import (energy, event_lengths, four_phase, fronts, loading_curve, loading_curves, plot_run,
                          plot_runs, precursor_lengths, spacetime)

__all__ = ["loading_curve", "event_lengths", "precursor_lengths", "loading_curves", "four_phase", "spacetime",
           "fronts", "energy", "interface_maps", "patch_growth", "lattice", "render_lattice", "sweep_precursor_lengths", "sweep_against",
           "sweep_loading_curves", "work_precision", "ensemble_work_precision", "single_seed_divergence", "plot_run",
           "plot_runs", "plot_lattice", "plot_sweep", "plot_study", "main", "table", "time_origin", "run_label",
           "NothingToDraw"]
