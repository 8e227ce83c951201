"""Observed order of convergence from the first metric of records at several resolutions."""
import math
from dataclasses import dataclass

import numpy as np

from .records import LEVELS, group_by


def fit_order(dx, err):
    """Least-squares slope p of log(err) = log(C) + p*log(dx); returns (p, C)."""
    lx, ly = np.log(np.asarray(dx, float)), np.log(np.asarray(err, float))
    if len(lx) < 2 or np.ptp(lx) == 0:
        raise ValueError("need errors at two or more distinct dx to fit an order")
    A = np.column_stack([lx, np.ones_like(lx)])
    (p, logc), *_ = np.linalg.lstsq(A, ly, rcond=None)
    return float(p), float(math.exp(logc))


def local_orders(dx, err):
    """Orders log(e_i/e_{i+1}) / log(dx_i/dx_{i+1}) between successive resolutions."""
    return [math.log(err[i] / err[i + 1]) / math.log(dx[i] / dx[i + 1])
            for i in range(len(dx) - 1)]


@dataclass
class Study:
    """A convergence study: one case, variant and metric at several dx (coarse to fine)."""
    case: str
    variant: str
    metric: str
    dx: list
    error: list
    records: list
    expected_order: float = None

    @property
    def observed_order(self):
        return fit_order(self.dx, self.error)[0]

    @property
    def constant(self):
        return fit_order(self.dx, self.error)[1]

    @property
    def local_orders(self):
        return local_orders(self.dx, self.error)


def _usable(r):
    v = r.first["value"]
    return r.stable and v is not None and math.isfinite(v) and v > 0


def studies(records, min_points=2):
    """Studies with >= min_points distinct dx per (case, variant, first-metric name).

    Unstable runs and non-positive/missing errors are left out. At a repeated dx the
    record of the highest level (convergence > full > quick) is used.
    """
    out = []
    groups = group_by([r for r in records if _usable(r)],
                      lambda r: (r.case, r.variant, r.first["name"]))
    for (case, variant, metric), recs in groups.items():
        by_dx = {}
        for r in sorted(recs, key=lambda r: (LEVELS.index(r.level), r.path)):
            by_dx[r.dx] = r
        if len(by_dx) < min_points:
            continue
        chosen = [by_dx[d] for d in sorted(by_dx, reverse=True)]
        expected = next((r.expected_order for r in recs if r.expected_order is not None), None)
        out.append(Study(case, variant, metric, [r.dx for r in chosen],
                         [r.first["value"] for r in chosen], chosen, expected))
    return out
