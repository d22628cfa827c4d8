"""The two searches the cam's figures need: the extreme of a smooth function over an
interval (a pressure angle's maximum, a radius of curvature's minimum), and the edge of a
condition over a parameter (the smallest base radius that meets a limit).

Both sample densely in one numpy call, then refine: the extreme by zooming into the bracket
of the best sample, sampled again in one call each round (its value is then exact to
rounding, its place to about 1e-13 of the interval), the edge by bisection to rounding.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

__all__ = ["edge", "extreme"]

SAMPLES = 2049


def extreme(fn: Callable[[np.ndarray], np.ndarray], lo: float, hi: float, largest: bool = True,
            samples: int = SAMPLES, refine: bool = True) -> tuple[float, float]:
    """(value, x) of the largest (or smallest) value of ``fn`` over [lo, hi]; ``fn``
    takes an array of x. ``refine=False``: the best of the samples only (a scan's rough
    look).

    >>> v, x = extreme(lambda x: np.sin(x), 0.0, 3.0)
    >>> round(v, 15), round(x, 6)
    (1.0, 1.570796)
    """
    sign = 1.0 if largest else -1.0
    xs = np.linspace(lo, hi, samples)
    ys = sign * np.asarray(fn(xs), dtype=float)
    ys = np.where(np.isnan(ys), -np.inf, ys)
    i = int(np.argmax(ys))
    a, b = xs[max(i - 1, 0)], xs[min(i + 1, samples - 1)]
    best_x, best_y = float(xs[i]), float(ys[i])
    if not refine:
        return sign * best_y, best_x
    # zoom: the bracket of the best sample, sampled again, each round 16 times narrower
    for _ in range(40):
        if b - a <= 1e-13 * max(1.0, abs(hi - lo)):
            break
        xs = np.linspace(a, b, ZOOM)
        ys = sign * np.asarray(fn(xs), dtype=float)
        ys = np.where(np.isnan(ys), -np.inf, ys)
        i = int(np.argmax(ys))
        if ys[i] >= best_y:
            best_x, best_y = float(xs[i]), float(ys[i])
        a, b = xs[max(i - 1, 0)], xs[min(i + 1, ZOOM - 1)]
    return sign * best_y, best_x


#: samples of each zooming round of :func:`extreme`
ZOOM = 33


def edge(ok: Callable[[float], bool], lo: float, hi: float, samples: int = 200,
         rough: Callable[[float], bool] | None = None) -> float | None:
    """The smallest x in [lo, hi] where ``ok(x)`` holds, to rounding: the first of
    ``samples`` equal steps where it holds (looked for with ``rough``, a cheaper test, where
    given), then bisection between it and the step before; None where it holds at none.

    >>> round(edge(lambda x: x * x >= 2.0, 0.0, 4.0), 12)
    1.414213562373
    """
    xs = np.linspace(lo, hi, samples)
    scan = rough or ok
    k = next((k for k, x in enumerate(xs) if scan(float(x))), None)
    while k is not None and rough is not None and not ok(float(xs[k])):
        k = k + 1 if k + 1 < samples else None
    if k is None:
        return None
    if k == 0:
        return float(xs[0])
    a, b = float(xs[k - 1]), float(xs[k])  # a fails, b holds
    for _ in range(200):
        m = (a + b) / 2.0
        if m in (a, b):
            break
        if ok(m):
            b = m
        else:
            a = m
    return b
