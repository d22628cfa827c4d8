"""Plane geometry on complex numbers: x + iy is a point or a vector of the plane.

Complex arithmetic is the natural algebra of the vector-plan method: multiplying by ``1j``
turns a vector by +90° (the velocity of a point turning about another is ``1j·ω·r``),
multiplying by a unit complex number turns a body, and numpy vectorizes all of it over
many crank angles at once. Every function here takes scalars or arrays alike.
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np


def apart(a, b):
    """How far angle ``a`` is from angle ``b`` round the circle (rad, in [0, π]); for
    arrays and Python numbers alike.

    >>> round(float(apart(0.1, 2 * np.pi - 0.1)), 12)
    0.2
    """
    return abs((a - b + np.pi) % (2 * np.pi) - np.pi)


def cross(a, b):
    """z-component of a × b (positive when b is counter-clockwise from a); for arrays and
    Python numbers alike.

    >>> cross(1 + 0j, 1j)
    1.0
    """
    return (a.conjugate() * b).imag


def meet(w, d1, d2, inv):
    """Parameters (t1, t2) where p1 + t1·d1 = p2 + t2·d2, given w = p2 − p1 and
    inv = 1 / cross(d1, d2): a group's velocity and acceleration plans intersect lines of
    the same two directions, so they share ``inv``."""
    cw = w.conjugate()
    return (cw * d2).imag * inv, (cw * d1).imag * inv


def intersect(p1, d1, p2, d2):
    """Intersection of the lines p1 + t1·d1 and p2 + t2·d2.

    Returns ``(t1, t2, sine)`` where ``sine`` is the sine of the angle from d1 to d2: the
    conditioning figure of the construction (0 means parallel lines, a singular plan).
    The two parameters are what the plan method wants: with d1 = i·(C − B), t1 is ω of
    link BC itself. Parallel lines give infinite or undefined parameters (with numpy's
    warning), never an exception.

    >>> t1, t2, s = intersect(0j, 1 + 0j, 2 + 1j, 1j)
    >>> float(t1), float(t2), float(s)
    (2.0, -1.0, 1.0)
    """
    den = cross(d1, d2)
    inv = np.divide(1.0, den)  # parallel lines: infinite parameters, as numpy gives them
    t1, t2 = meet(p2 - p1, d1, d2, inv)
    return t1, t2, den / (abs(d1) * abs(d2))


def heron(l1, l2, d):
    """(2d·h)² for the triangle of sides l1, l2, d (h its height over d).

    Written as the product of four factors, each formed from exact data rather than by
    cancelling two large squares, so that it stays accurate at tangency. Negative: the
    triangle does not close.
    """
    return (d + (l1 + l2)) * (d + (l2 - l1)) * (d - (l2 - l1)) * ((l1 + l2) - d)


def circle_circle(c1, r1, c2, r2, sign):
    """Intersection of circles (c1, r1) and (c2, r2) on the side ``sign`` (+1: left of c1→c2).

    Returns ``(point, disc)``; ``disc`` < 0 means no intersection (the point is then
    computed from a clipped discriminant and must not be used).
    """
    w = c2 - c1
    d = np.abs(w)
    disc = heron(r1, r2, d)
    along = (r1 * r1 - r2 * r2 + d * d) / (2 * d)
    h = np.sqrt(np.maximum(disc, 0.0)) / (2 * d)
    return c1 + (along + 1j * sign * h) * (w / d), disc


def golden_min(g: Callable[[float], float], a: float, b: float, width: float = 0.0,
               iterations: int = 90) -> float:
    """Where ``g`` is least on [a, b] (one minimum there): golden-section search, until the
    interval is ``width`` wide (or at rounding of its ends); its middle. A NaN counts as
    larger than anything. The one search of the project: a synthesis's best member, a
    cycle's least transmission angle, the check's crank angle a plan was drawn at.

    >>> round(golden_min(lambda x: (x - 0.3) ** 2, 0.0, 1.0), 7)
    0.3
    >>> abs(golden_min(lambda x: (x - 0.3) ** 2, 0.0, 1.0, width=1e-3) - 0.3) < 1e-3
    True
    """
    k = (math.sqrt(5) - 1) / 2
    x1, x2 = b - k * (b - a), a + k * (b - a)
    f1, f2 = g(x1), g(x2)
    for _ in range(iterations):
        if abs(b - a) <= max(width, 1e-15 * max(abs(a), abs(b), 1e-300)):
            break
        if not (f1 <= f2 or math.isnan(f2)):
            a, x1, f1 = x1, x2, f2
            x2 = a + k * (b - a)
            f2 = g(x2)
        else:
            b, x2, f2 = x2, x1, f1
            x1 = b - k * (b - a)
            f1 = g(x1)
    return 0.5 * (a + b)
