"""Li, Zhao, Xiong & Liu (2020), "2D numerical model for studying frictional sliding", Acta Mech.
Sin. 36: what Figs. 5-9 show, as runs and as statements with verdicts (the statements as the
physics notes' section C lists them)."""
import os
import subprocess
from typing import Dict, List, Tuple

import numpy as np
import pandas as pd
import yaml

from .. import ensembles, li2020_claims
from . import report, slip_phases, static_profile
from .report import Statement
from .steps import Outcome, Step, cli

TITLE = "Li, Zhao, Xiong & Liu (2020), Acta Mech. Sin. 36: the reproduction"
SEEDS, QUICK_SEEDS = 10, 2
QUICK_RATE = 10  # the quick variant drives this many times faster, over a tenth of the time
THETA = "loaders[1].theta"
LINEAR_LOADING_MARGIN = 0.01  # physics notes C.3: F_S grows at K_S V within 1 %


def faster(overrides: List[str], velocity: float, duration: float) -> List[str]:
    return overrides + [f"loaders[2].velocity={velocity * QUICK_RATE:g}",
                        f"stages[1].duration={duration / QUICK_RATE:g}"]


def steps(quick: bool) -> List[Step]:
    seeds = QUICK_SEEDS if quick else SEEDS
    campaign = "li2020/campaign_scene.yaml"
    out = [Step("fig5", "the settled interface at θ = -0.5, 0, 0.5 (settling only)", scene=campaign,
                grid={THETA: [-0.5, 0.0, 0.5]}, common=static_profile.run_overrides())]
    headline = [] if not quick else faster([], 1e-3, 0.4)
    out.append(Step("fig6", f"the headline scene over {seeds} seeds", scene="headline.yaml", seeds=seeds,
                    common=headline))
    if quick:
        fig7_cases = {f"fn{f / 1000:g}kn-h{h * 1e3:g}mm": faster([f"loaders[1].total_force={f:g}",
                                                                   f"loaders[2].height={h:g}"], v, 3.0)
                      for f, v, h in ((400, 1e-4, 0.005), (1200, 3e-4, 0.005), (2000, 5e-4, 0.005),
                                      (400, 1e-4, 0.0025))}
        out.append(Step("fig7", "Fig. 7's four configurations, ten times the rate", scene=campaign,
                        seeds=seeds, cases=fig7_cases))
        out.append(Step("fig8", "Fig. 8's five θ, ten times the rate", scene=campaign, seeds=seeds,
                        grid={THETA: [-0.833, -0.4165, 0.0, 0.4165, 0.833]},
                        cases={"fast": faster([], 1e-4, 3.0)}))
    else:
        out.append(Step("fig7", "configs/li2020/fig7_precursor_scaling.yaml", sweep="li2020/fig7_precursor_scaling.yaml"))
        out.append(Step("fig8", "configs/li2020/fig8_nonuniform_loading.yaml",
                        sweep="li2020/fig8_nonuniform_loading.yaml"))
    out.append(Step("fig9", f"the headline scene's interface through its first global slip, {seeds} seeds",
                    scene=slip_phases.SCENE, seeds=seeds, common=slip_phases.run_overrides(quick)))
    return out


SYMMETRY = 1e-6  # physics notes C.2: the at-rest profiles are mirror images to 1e-6 of the mean


def settled(run: str):
    """(θ, the scene, the settled normal and friction forces per interface block) of a Fig. 5 run."""
    scene = yaml.safe_load(open(os.path.join(run, "run.yaml")))["scene"]
    return (float(scene["loaders"][1]["theta"]), scene, static_profile.simulated_profile(run, scene),
            static_profile.simulated_profile(run, scene, "friction_force"))


def fig5(o: Outcome, figures: str) -> Tuple[List[Statement], List[str]]:
    runs = {}
    for d in o.run_directories():
        theta, scene, normal, friction = settled(d)
        runs[theta] = (d, normal, friction, static_profile.compare(d))
    if not runs:
        return [], []
    worst = {t: static_profile.largest_difference(r[3]) for t, r in runs.items()}
    text = "; ".join(f"θ = {t:+g}: {100 * w:.2f} %" for t, w in sorted(worst.items()))
    within = max(worst.values()) <= static_profile.AGREEMENT
    rows = [Statement("Fig. 5", "At rest under the load, each interface block carries the normal force of the "
                      "slider's static equilibrium (against an independent static solve, θ = 0, ±0.5)",
                      f"largest difference from the solve, of the mean block force: {text}",
                      "reproduced within a stated margin" if within else "differs",
                      f"{100 * static_profile.AGREEMENT:g} % of the mean block force")]
    if 0.0 in runs:
        _, normal, friction, _ = runs[0.0]
        mean = normal.mean()
        asymmetry = np.abs(normal - normal[::-1]).max() / mean
        spread = (normal.max() - normal.min()) / mean
        weak = asymmetry <= SYMMETRY and spread < 0.5
        rows.append(Statement("Fig. 5", "At θ = 0 the normal profile is symmetric and weakly non-uniform",
                              f"|P_i − P_mirror| ≤ {asymmetry:.1e} P̄; (max − min)/P̄ = {spread:.3f}, heaviest at the "
                              f"edges ({normal[0] / mean:.3f} P̄)", "reproduced" if weak else "differs",
                              "" if weak else "not symmetric to 1e-6, or not weakly non-uniform"))
        half = len(friction) // 2
        scale = np.abs(friction).max()
        antisymmetry = np.abs(friction + friction[::-1]).max() / scale
        inward = bool(np.all(friction[:half] > 0))
        ok = antisymmetry <= SYMMETRY and inward
        rows.append(Statement("Fig. 5", "At θ = 0 the friction profile is antisymmetric and resists the Poisson "
                              "expansion (inward on each half), largest at the edges",
                              f"|f_i + f_mirror| ≤ {antisymmetry:.1e} max|f|; trailing half all inward: {inward}; "
                              f"largest at block {int(np.abs(friction).argmax())} of {len(friction)}",
                              "reproduced" if ok else "differs", "" if ok else "not antisymmetric, or not inward"))
    return rows, [fig5_figure(runs, os.path.join(figures, "fig5_settled_interface.png"))]


def fig5_figure(runs, path: str) -> str:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (normal_ax, friction_ax) = plt.subplots(1, 2, figsize=(10, 3.8))
    for theta, (_, normal, friction, comparison) in sorted(runs.items()):
        blocks = np.arange(len(normal))
        line, = normal_ax.plot(blocks, normal, "o", ms=3, label=f"θ = {theta:+g}, run")
        normal_ax.plot(blocks, comparison["solved"], "-", color=line.get_color(), lw=1, label=f"θ = {theta:+g}, solve")
        friction_ax.plot(blocks, friction, "o-", ms=3, lw=1, color=line.get_color(), label=f"θ = {theta:+g}")
    normal_ax.set(xlabel="interface block", ylabel="normal force [N]", title="settled normal force (Fig. 5)")
    friction_ax.set(xlabel="interface block", ylabel="friction force [N]", title="settled friction force")
    normal_ax.legend(fontsize=7)
    friction_ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path


def loading_rate(run: str) -> float:
    """F_S's rate over the first half of the loading before its first event, against K_S V."""
    curve = pd.read_csv(os.path.join(run, "loading_curve.csv"))
    events = pd.read_csv(os.path.join(run, "precursors.csv"))
    scene = yaml.safe_load(open(os.path.join(run, "run.yaml")))["scene"]
    spring = scene["loaders"][2]
    first = events["t_start_since_loading"].min() if len(events) else curve["time_since_loading"].max()
    rising = curve[(curve["time_since_loading"] > 0.05 * first) & (curve["time_since_loading"] < 0.5 * first)]
    slope = np.polyfit(rising["time_since_loading"], rising["driving_force"], 1)[0]
    return slope / (float(spring["stiffness"]) * float(spring["velocity"]))  # YAML reads 8e+05 as text


def fig6(o: Outcome, figures: str) -> Tuple[List[Statement], List[str], str]:
    runs = o.run_directories()
    stats = pd.read_csv(os.path.join(o.directory, "run_statistics.csv"))
    rates = [loading_rate(r) for r in runs]
    rate = ensembles.mean(rates)
    within = abs(rate.estimate - 1) <= LINEAR_LOADING_MARGIN
    rows = [Statement("Fig. 6", "Before any slip, F_S grows linearly at K_S V", f"F_S's rate / (K_S V) "
                      f"{fmt(rate, 4)} over {len(rates)} seeds",
                      "reproduced within a stated margin" if within else "differs",
                      f"{100 * LINEAR_LOADING_MARGIN:g} %" if within else
                      f"{100 * (rate.estimate - 1):+.0f} %, beyond the {100 * LINEAR_LOADING_MARGIN:g} % allowed: the "
                      "slider's own compliance at the driving point is in series with the spring")]
    count = ensembles.mean(stats["precursor_count"])
    rows.append(Statement("Fig. 6", "Several precursors (partial slips) come before the first global slip",
                          f"{fmt(count, 2)} precursors a run; fewest {stats['precursor_count'].min():g}",
                          "reproduced" if stats["precursor_count"].min() >= 1 else "differs",
                          "" if stats["precursor_count"].min() >= 1 else "a run without precursors"))
    globals_per_run = [int((pd.read_csv(os.path.join(r, "precursors.csv"))["global"] == 1).sum()) for r in runs]
    rows.append(Statement("Fig. 6", "After it, the interface stick-slips: global slips recur as a sawtooth",
                          f"global slips a run: {min(globals_per_run)} to {max(globals_per_run)}; period "
                          f"{fmt(ensembles.mean(stats['stick_slip_period'] * 1e3), 1)} ms",
                          "reproduced" if min(globals_per_run) >= 2 else "differs",
                          "" if min(globals_per_run) >= 2 else "a run with fewer than two global slips"))
    notes = ("Fig. 6's ensemble (the headline scene, each value a mean over the seeds with its 95 % bootstrap "
             "interval): precursors before the first global slip "
             f"{fmt(count, 2)}; the first precursor at F_S/F_N {fmt(ensembles.mean(stats['first_precursor_force_ratio']), 3)}; "
             f"the first global slip at F_S/F_N {fmt(ensembles.mean(stats['global_slip_force_ratio']), 3)}, "
             f"{fmt(ensembles.mean(stats['global_slip_time_since_loading'] * 1e3), 1)} ms after loading began. "
             "The paper's own values (its Fig. 6) were not recovered in numbers (physics notes C.3): the "
             "comparison with the experiment stays qualitative.\n")
    return rows, plot(o, figures, "fig6"), notes


def fmt(e: ensembles.Effect, digits: int) -> str:
    if e.interval:
        return f"{e.estimate:.{digits}f} ({e.interval})"
    return f"{e.estimate:.{digits}f} [{e.low:.{digits}f}, {e.high:.{digits}f}]"


def plot(o: Outcome, figures: str, prefix: str) -> List[str]:
    """The sweep's own figures (`frictionlab plot`), copied beside the report as PREFIX_NAME.png."""
    plots = os.path.join(o.directory, "plots")
    if subprocess.run([cli(), "plot", o.directory], stdout=subprocess.DEVNULL).returncode != 0:
        return []
    out = []
    for name in sorted(os.listdir(plots)):
        if name.endswith(".png"):
            target = os.path.join(figures, f"{prefix}_{name}")
            with open(os.path.join(plots, name), "rb") as src, open(target, "wb") as dst:
                dst.write(src.read())
            out.append(target)
    return out


def figs7_8(outcomes: Dict[str, Outcome], figures: str) -> Tuple[List[Statement], List[str], str]:
    fig7, seeds7 = li2020_claims.fig7_claims(outcomes["fig7"].directory)
    fig8, seeds8 = li2020_claims.fig8_claims(outcomes["fig8"].directory)
    paths = plot(outcomes["fig7"], figures, "fig7") + plot(outcomes["fig8"], figures, "fig8")
    return [c.statement for c in fig7 + fig8], paths, (
        f"\nFigs. 7 and 8: {seeds7} seeds a configuration, {seeds8} a θ; the effects as "
        "`python3 -m frictionlab.li2020_claims` states them for the README.\n")


def fig9(o: Outcome, figures: str) -> Tuple[List[Statement], List[str], str]:
    runs = o.run_directories()
    paths = []
    if runs:
        paths.append(os.path.join(figures, "fig9_phases_and_collapse.png"))
        slip_phases.figure(runs[0], paths[0])
    return slip_phases.statements(runs), paths, ""


def measure(outcomes: Dict[str, Outcome], out: str) -> Tuple[List[Statement], List[str], str]:
    """Every statement of Figs. 5-9, the figures (paths) and notes, from the steps' runs. A figure
    whose runs cannot be measured (its runs failed) gets a row saying so, and the others go on."""
    figures = os.path.join(out, "figures")
    os.makedirs(figures, exist_ok=True)
    parts = (("Fig. 5", lambda: fig5(outcomes["fig5"], figures) + ("",)),
             ("Fig. 6", lambda: fig6(outcomes["fig6"], figures)),
             ("Figs. 7, 8", lambda: figs7_8(outcomes, figures)),
             ("Fig. 9", lambda: fig9(outcomes["fig9"], figures)))
    statements, paths, notes = [], [], ""
    for name, part in parts:
        try:
            s, p, n = part()
        except Exception as error:  # noqa: BLE001 - a report names what it could not measure
            s, p, n = [Statement(name, "(every statement of the figure)", f"could not be measured: {error!r}",
                                 "not measured", "see Failed runs")], [], ""
        statements += s
        paths += p
        notes += n
    return statements, [os.path.relpath(p, out) for p in paths], notes


def write_docs(outcomes: Dict[str, Outcome], statements: List[Statement], root: str) -> List[str]:
    """The verdicts into reproduction.md, the Figs. 7-8 claims into the README and campaigns.md."""
    written = [report.write_block(root, "share/docs/reproduction.md", "li2020-reproduction", statements, outcomes)]
    fig7, fig8 = outcomes["fig7"].directory, outcomes["fig8"].directory
    for doc in ("README.md", "share/docs/campaigns.md"):
        li2020_claims.main([fig7, fig8, "--write", os.path.join(root, doc)])
        written.append(os.path.join(root, doc))
    return written
