"""Effects measured over ensembles of seeds, with their uncertainty: one ensemble's mean, the
difference of two ensembles' means and the slope of a statistic against a varied value, each with
its seeded percentile bootstrap 95 % interval (share/docs/accuracy-standard.md), and how many seeds
would resolve an effect not yet resolved.

The intervals are the campaign tables' own (sweep_statistics.csv, a study's ensemble.csv), computed
by the same C++ (frictionlab._core): 10,000 keyed resamples, the same values and seed give the same
interval here and there. Below five finite values an ensemble gives no interval: `low` and `high`
are NaN and `interval` says why ("too few seeds").

    from frictionlab import ensembles
    e = ensembles.difference(counts_at_0833, counts_at_0)   # Effect: estimate, low, high, se, interval
    e.resolved, ensembles.seeds_to_resolve(e, 10)
"""
import importlib
import math
from typing import NamedTuple, Sequence

import numpy as np

RESAMPLES = 10000


class Effect(NamedTuple):
    estimate: float     # the effect on the ensembles as they are
    low: float          # 2.5 % bootstrap quantile; NaN without an interval
    high: float         # 97.5 % bootstrap quantile; NaN without an interval
    se: float           # bootstrap standard error; NaN without an interval
    interval: str = ""  # "" where the interval is given, else why not ("too few seeds")

    @property
    def resolved(self) -> bool:
        """Whether the 95 % interval excludes zero (never without an interval)."""
        return self.low > 0 or self.high < 0


def _core():
    return importlib.import_module("frictionlab._core")


def _values(values) -> list:
    return np.asarray(values, dtype=float).ravel().tolist()


def minimum_values() -> int:
    """The fewest finite values an ensemble needs for an interval (5)."""
    return int(_core().interval_minimum_values)


def mean(a: Sequence[float], seed: int = 1, resamples: int = RESAMPLES) -> Effect:
    """mean(a), NaNs left out, with the percentile interval of `resamples` keyed draws of the
    ensemble with replacement: sweep_statistics.csv's `ci_low`, `ci_high` for the same values."""
    return Effect(*_core().bootstrap_mean(_values(a), seed, resamples))


def difference(a: Sequence[float], b: Sequence[float], seed: int = 1, resamples: int = RESAMPLES) -> Effect:
    """mean(a) - mean(b), NaNs left out, with the percentile interval of `resamples` keyed draws of
    each ensemble with replacement (the same inputs give the same interval)."""
    return Effect(*_core().bootstrap_difference(_values(a), _values(b), seed, resamples))


def slope(x: Sequence[float], y: Sequence[float], seed: int = 1, resamples: int = RESAMPLES) -> Effect:
    """The least-squares slope of y against x over all runs, with the interval of bootstrap draws
    that resample the runs within each x (the grid stays as designed); an interval needs five
    values at each x. NaN values are left out; fewer than two values of x raise ValueError."""
    return Effect(*_core().bootstrap_slope(_values(x), _values(y), seed, resamples))


def seeds_to_resolve(effect: Effect, seeds: int) -> float:
    """Seeds per ensemble at which an effect of this size would be resolved (1.96 standard errors),
    the standard error falling as one over the square root of the seeds: `seeds` times
    (1.96 se / |estimate|)^2; infinite for a zero estimate, NaN without a standard error."""
    if effect.estimate == 0:
        return float("inf")
    if math.isnan(effect.se):
        return float("nan")
    return float(seeds * (1.96 * effect.se / abs(effect.estimate)) ** 2)
