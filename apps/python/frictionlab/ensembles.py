"""Effects measured over ensembles of seeds, with their uncertainty: the difference of two ensembles'
means and the slope of a statistic against a varied value, each with a seeded bootstrap 95 %
interval (share/docs/accuracy-standard.md), and how many seeds would resolve an effect not yet
resolved.

    from frictionlab import ensembles
    e = ensembles.difference(counts_at_0833, counts_at_0)   # Effect: estimate, low, high, se
    e.resolved, ensembles.seeds_to_resolve(e, 10)
"""
from typing import NamedTuple, Sequence

import numpy as np

RESAMPLES = 10000


class Effect(NamedTuple):
    estimate: float  # the effect on the ensembles as they are
    low: float       # 2.5 % bootstrap quantile
    high: float      # 97.5 % bootstrap quantile
    se: float        # bootstrap standard error

    @property
    def resolved(self) -> bool:
        """Whether the 95 % interval excludes zero."""
        return self.low > 0 or self.high < 0


def _finite(values) -> np.ndarray:
    a = np.asarray(values, dtype=float)
    return a[np.isfinite(a)]


def _effect(estimate: float, draws: np.ndarray) -> Effect:
    low, high = np.quantile(draws, [0.025, 0.975])
    return Effect(float(estimate), float(low), float(high), float(np.std(draws, ddof=1)))


def mean(a: Sequence[float], seed: int = 1, resamples: int = RESAMPLES) -> Effect:
    """mean(a), NaNs left out, with the percentile interval of `resamples` draws of the ensemble with
    replacement (seeded, as difference()). It needs two values or more."""
    a = _finite(a)
    if len(a) < 2:
        raise ValueError(f"an ensemble of {len(a)} value(s): two or more are needed")
    rng = np.random.default_rng(seed)
    return _effect(a.mean(), rng.choice(a, (resamples, len(a))).mean(axis=1))


def difference(a: Sequence[float], b: Sequence[float], seed: int = 1, resamples: int = RESAMPLES) -> Effect:
    """mean(a) - mean(b), NaNs left out, with the percentile interval of `resamples` draws of each
    ensemble with replacement (numpy's default generator, seeded: the same inputs give the same
    interval). Each ensemble needs two values or more."""
    a, b = _finite(a), _finite(b)
    if len(a) < 2 or len(b) < 2:
        raise ValueError(f"an ensemble of {min(len(a), len(b))} value(s): two or more are needed")
    rng = np.random.default_rng(seed)
    draws = (rng.choice(a, (resamples, len(a))).mean(axis=1) - rng.choice(b, (resamples, len(b))).mean(axis=1))
    return _effect(a.mean() - b.mean(), draws)


def slope(x: Sequence[float], y: Sequence[float], seed: int = 1, resamples: int = RESAMPLES) -> Effect:
    """The least-squares slope of y against x over all runs, with the interval of bootstrap draws
    that resample the runs within each x (the grid stays as designed). NaN values of y are left out."""
    x, y = np.asarray(x, dtype=float), np.asarray(y, dtype=float)
    keep = np.isfinite(x) & np.isfinite(y)
    x, y = x[keep], y[keep]
    groups = [np.flatnonzero(x == v) for v in np.unique(x)]
    if len(groups) < 2:
        raise ValueError("a slope needs two values of x or more")
    rng = np.random.default_rng(seed)
    draws = np.empty(resamples)
    for r in range(resamples):
        pick = np.concatenate([rng.choice(g, len(g)) for g in groups])
        draws[r] = np.polyfit(x[pick], y[pick], 1)[0]
    return _effect(np.polyfit(x, y, 1)[0], draws)


def seeds_to_resolve(effect: Effect, seeds: int) -> float:
    """Seeds per ensemble at which an effect of this size would be resolved (1.96 standard errors),
    the standard error falling as one over the square root of the seeds: `seeds` times
    (1.96 se / |estimate|)^2; infinite for a zero estimate."""
    if effect.estimate == 0:
        return float("inf")
    return float(seeds * (1.96 * effect.se / abs(effect.estimate)) ** 2)
