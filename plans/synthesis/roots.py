"""Every root of a function of one parameter, found by bracketing, never by one Newton start.

A synthesis that leaves one equation in one unknown (the rod ratio λ of seed 002's second
variant, the largest pressure angle of its third) may have no root, one, or several, and
each is a mechanism. The function is evaluated vectorized on a dense grid of the
parameter's whole admissible interval; every change of sign between two neighbouring
samples where the function is defined is then narrowed by Brent's method to the last
bit, and a sample where the function touches zero without changing sign (a double root)
is narrowed by golden-section search on its magnitude.

>>> import numpy as np
>>> [round(r, 12) for r in roots(lambda x: (np.cos(3 * x), np.ones_like(x, bool)), 0, 3)]
[0.523598775598, 1.570796326795, 2.617993877991]
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np

from plans.geometry import golden_min

#: samples of the parameter's interval
SAMPLES = 4097

#: a touching zero is a root where the function's magnitude there is below this, relative
#: to its largest magnitude on the grid
TOUCH = 1e-12

Vectorized = Callable[[np.ndarray], tuple[np.ndarray, np.ndarray]]


def _scalar(f: Vectorized) -> Callable[[float], float]:
    def g(x: float) -> float:
        value, ok = f(np.array([x], dtype=float))
        return float(value[0]) if bool(ok[0]) else math.nan

    return g


def brent(g: Callable[[float], float], a: float, b: float, fa: float, fb: float,
          xtol: float = 1e-15) -> float:
    """The root of ``g`` in [a, b], where ``fa`` = g(a) and ``fb`` = g(b) differ in sign:
    Brent's method (inverse quadratic interpolation, secant and bisection), to ``xtol``
    relative and a few ulps absolute.

    >>> round(brent(lambda x: x * x - 2, 1.0, 2.0, -1.0, 2.0), 15)
    1.414213562373095
    """
    if fa == 0:
        return a
    if fb == 0:
        return b
    c, fc = a, fa
    d = e = b - a
    for _ in range(200):
        if (fb > 0) == (fc > 0):
            c, fc = a, fa
            d = e = b - a
        if abs(fc) < abs(fb):
            a, b, c = b, c, b
            fa, fb, fc = fb, fc, fb
        tol = 2 * np.finfo(float).eps * abs(b) + 0.5 * xtol * max(abs(b), 1e-300)
        m = 0.5 * (c - b)
        if abs(m) <= tol or fb == 0:
            return b
        if abs(e) >= tol and abs(fa) > abs(fb):
            s = fb / fa
            if a == c:  # secant
                p, q = 2 * m * s, 1 - s
            else:  # inverse quadratic interpolation
                q, r = fa / fc, fb / fc
                p = s * (2 * m * q * (q - r) - (b - a) * (r - 1))
                q = (q - 1) * (r - 1) * (s - 1)
            if p > 0:
                q = -q
            p = abs(p)
            if 2 * p < min(3 * m * q - abs(tol * q), abs(e * q)):
                e, d = d, p / q
            else:
                d = e = m
        else:
            d = e = m
        a, fa = b, fb
        b = b + (d if abs(d) > tol else math.copysign(tol, m))
        fb = g(b)
        if math.isnan(fb):  # stepped out of where g is defined: bisect back
            b, fb = a, fa
            d = e = m
    return b


def roots(f: Vectorized, lo: float, hi: float, samples: int = SAMPLES) -> list[float]:
    """Every root of ``f`` in [``lo``, ``hi``], ascending.

    ``f(x)`` takes an array and returns (values, defined): the function and where it is
    defined (a mechanism that exists). A root is a change of sign between neighbouring
    samples that are both defined, narrowed by :func:`brent`, or a sample where the
    magnitude has a local minimum below :data:`TOUCH` of the largest (a double root),
    narrowed by :func:`golden_min`. Two roots closer than the grid's step are one, unless
    the function changes sign between them on the grid."""
    x = np.linspace(lo, hi, samples)
    with np.errstate(all="ignore"):
        v, ok = f(x)
    v = np.where(ok, v, np.nan)
    g = _scalar(f)
    out: list[float] = []
    for i in np.flatnonzero(ok[:-1] & ok[1:] & (np.sign(v[:-1]) * np.sign(v[1:]) <= 0)):
        if v[i] == 0:
            r = float(x[i])
        elif v[i + 1] == 0:
            r = float(x[i + 1])
        else:
            r = brent(g, float(x[i]), float(x[i + 1]), float(v[i]), float(v[i + 1]))
        if not out or r != out[-1]:
            out.append(r)
    scale = np.nanmax(np.abs(v)) if np.isfinite(v).any() else 0.0
    mag = np.abs(v)
    for i in range(1, samples - 1):  # touching zeros: |f| least without a change of sign
        if not (ok[i - 1] and ok[i] and ok[i + 1]):
            continue
        if not (mag[i] <= mag[i - 1] and mag[i] <= mag[i + 1]):
            continue
        if np.sign(v[i - 1]) != np.sign(v[i + 1]) or v[i] == 0:
            continue  # a change of sign: found above
        r = golden_min(lambda t: abs(g(t)), float(x[i - 1]), float(x[i + 1]))
        if abs(g(r)) <= TOUCH * max(scale, 1e-300):
            out.append(r)
    return sorted(out)


def ranges(f: Vectorized, lo: float, hi: float, samples: int = SAMPLES
           ) -> list[tuple[float, float]]:
    """The values ``f`` takes where it is defined on [lo, hi]: (least, largest) over each
    run of the grid where it is defined, the run's ends narrowed by bisection on where it
    is defined and its extremes by :func:`extremes` (the admissible range of a
    requirement, said where it has no root)."""
    x = np.linspace(lo, hi, samples)
    with np.errstate(all="ignore"):
        _, ok = f(x)
    g = _scalar(f)
    out = []
    for first, last in _runs(ok):
        a, b = float(x[first]), float(x[last])
        if first > 0:
            a = _edge(g, float(x[first - 1]), a)
        if last < samples - 1:
            b = _edge(g, float(x[last + 1]), b)
        got = extremes(f, a, b, max(33, (last - first + 1) * 2 + 1))
        if got is not None:
            out.append((got[0], got[2]))
    return out


def _runs(ok: np.ndarray) -> list[tuple[int, int]]:
    idx = np.flatnonzero(ok)
    if idx.size == 0:
        return []
    cut = np.flatnonzero(np.diff(idx) > 1)
    return list(zip(np.r_[idx[0], idx[cut + 1]].tolist(), np.r_[idx[cut], idx[-1]].tolist(),
                    strict=True))


def _edge(g: Callable[[float], float], outside: float, inside: float) -> float:
    """The last point, from ``inside`` towards ``outside``, where ``g`` is defined."""
    for _ in range(80):
        mid = 0.5 * (outside + inside)
        if mid in (outside, inside):
            break
        if math.isnan(g(mid)):
            outside = mid
        else:
            inside = mid
    return inside


def extremes(f: Vectorized, lo: float, hi: float, samples: int = SAMPLES
             ) -> tuple[float, float, float, float] | None:
    """(least value, where, largest value, where) of ``f`` over [lo, hi] where it is
    defined, each narrowed by golden-section search round the best sample (the admissible
    range of a requirement, said when it has no root); None where it is defined nowhere."""
    x = np.linspace(lo, hi, samples)
    with np.errstate(all="ignore"):
        v, ok = f(x)
    if not ok.any():
        return None
    g = _scalar(f)
    out = []
    for sign in (1.0, -1.0):
        w = np.where(ok, sign * v, np.inf)
        i = int(np.argmin(w))
        a, b = float(x[max(i - 1, 0)]), float(x[min(i + 1, samples - 1)])

        def h(t, s=sign):
            y = g(t)
            return math.inf if math.isnan(y) else s * y

        t = golden_min(h, a, b)
        best = (float(v[i]), float(x[i]))
        if math.isfinite(h(t)) and h(t) <= sign * best[0]:
            best = (g(t), t)
        out.extend(best)
    return out[0], out[1], out[2], out[3]
