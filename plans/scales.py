"""Scale factors μl, μv, μa: real value per millimetre of drawing, from the standard series.

Teachers pick "round" factors k·10^n with k ∈ {1, 2, 2.5, 4, 5} so that values are easy to
compute by hand; μl must also be a GOST 2.302 drawing scale (1:10 is μl = 0.01 m/mm).

>>> choose_mu(3.0, 3.6)        # V_A = 3 m/s: pa = 75 mm
0.04
>>> choose_mu(0.8, 1.0) == next(series(0.01, 0.2))   # exactly 0.01 m/s per mm
True
>>> gost_scale(0.01)
'1:10'
"""

from __future__ import annotations

import math

from plans.fmt import decimal

MANTISSAS = (1.0, 2.0, 2.5, 4.0, 5.0)
#: GOST 2.302 scales as μl in m/mm (reduction, natural size, enlargement)
GOST_MU_L = (
    0.0001, 0.0002, 0.00025, 0.0004, 0.0005, 0.001, 0.002, 0.0025, 0.004, 0.005, 0.01,
    0.015, 0.02, 0.025, 0.04, 0.05, 0.075, 0.1, 0.2, 0.4, 0.5, 0.8, 1.0,
)


def series(lo: float, hi: float):
    """The standard values k·10^n in [lo, hi], ascending."""
    n = math.floor(math.log10(lo)) - 1
    while True:
        for k in MANTISSAS:
            v = float(f"{k * 10.0**n:.12g}")
            if v > hi:
                return
            if v >= lo:
                yield v
        n += 1


#: mm: the default size of a drawing: a plan's crank vector (CRANK_MM), its longest vector
#: and a plan of positions across (PLAN_MM); a sheet may draw them larger or smaller
CRANK_MM = 80.0
PLAN_MM = 150.0


def choose_mu(value: float, largest: float, crank_mm: float = CRANK_MM,
              max_mm: float = PLAN_MM) -> float:
    """The smallest standard μ that keeps the driver's vector ≤ ``crank_mm`` and every
    vector of the plan ≤ ``max_mm``."""
    need = max(abs(value) / crank_mm, abs(largest) / max_mm, 1e-300)
    # series(need, …)'s first value, formatting only the candidate that fits. The scan
    # starts in need's own decade: were log10's rounding to put it one decade low, the scan
    # would only take one decade longer; it cannot put it one decade high.
    n = math.floor(math.log10(need))
    while True:
        decade = 10.0**n
        for k in MANTISSAS:
            raw = k * decade
            if raw >= need * (1 - 1e-9):
                v = float(f"{raw:.12g}")
                if v >= need:
                    return v
        n += 1


def choose_mu_l(extent: float, max_mm: float = PLAN_MM) -> float:
    """The smallest GOST μl at which the mechanism's extent (m) fits in ``max_mm``."""
    for mu in GOST_MU_L:
        if extent / mu <= max_mm:
            return mu
    return next(series(extent / max_mm, extent))


def gost_scale(mu_l: float, lang: str = "en") -> str:
    """'1:10' for μl = 0.01 m/mm, '2:1' for 0.0005 m/mm (1 mm of drawing = μl metres);
    '1:2,5' in Russian.

    >>> gost_scale(0.0025), gost_scale(0.0025, "ru"), gost_scale(0.0004)
    ('1:2.5', '1:2,5', '2.5:1')
    """
    ratio = mu_l / 0.001
    text = f"1:{ratio:.10g}" if ratio >= 1 else f"{1 / ratio:.10g}:1"
    return decimal(text, lang)
