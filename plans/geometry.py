"""Plane geometry on complex numbers: x + iy is a point or a vector of the plane.

Complex arithmetic is the natural algebra of the vector-plan method: multiplying by ``1j``
turns a vector by +90° (the velocity of a point turning about another is ``1j·ω·r``),
multiplying by a unit complex number turns a body, and numpy vectorizes all of it over
many crank angles at once. Every function here takes scalars or arrays alike.
"""

from __future__ import annotations

import numpy as np


def cross(a, b):
    """z-component of a × b (positive when b is counter-clockwise from a).

    >>> float(cross(1 + 0j, 1j))
    1.0
    """
    return (np.conj(a) * b).imag


def dot(a, b):
    """Scalar product of two plane vectors.

    >>> float(dot(3 + 4j, 1 + 0j))
    3.0
    """
    return (np.conj(a) * b).real


def unit(a):
    """a / |a|."""
    return a / np.abs(a)


def intersect(p1, d1, p2, d2):
    """Intersection of the lines p1 + t1·d1 and p2 + t2·d2.

    Returns ``(t1, t2, sine)`` where ``sine`` is the sine of the angle from d1 to d2: the
    conditioning figure of the construction (0 means parallel lines, a singular plan).
    The two parameters are what the plan method wants: with d1 = i·(C − B), t1 is ω of
    link BC itself.

    >>> t1, t2, s = intersect(0j, 1 + 0j, 2 + 1j, 1j)
    >>> float(t1), float(t2), float(s)
    (2.0, -1.0, 1.0)
    """
    den = cross(d1, d2)
    w = p2 - p1
    t1 = cross(w, d2) / den
    t2 = cross(w, d1) / den
    sine = den / (np.abs(d1) * np.abs(d2))
    return t1, t2, sine


def heron_height_sq(l1, l2, d):
    """Square of the height over side d of the triangle with sides l1, l2, d, times (2d)².

    Written as the product (l1+l2+d)(−l1+l2+d)(l1−l2+d)(l1+l2−d) so that it stays
    accurate at tangency (each factor is formed from exact data, not by cancelling
    two large squares). Negative means the triangle does not close.
    """
    return (l1 + l2 + d) * (-l1 + l2 + d) * (l1 - l2 + d) * (l1 + l2 - d)


def circle_circle(c1, r1, c2, r2, sign):
    """Intersection of circles (c1, r1) and (c2, r2) on the side ``sign`` (+1: left of c1→c2).

    Returns ``(point, disc)``; ``disc`` < 0 means no intersection (the point is then
    computed from a clipped discriminant and must not be used).
    """
    w = c2 - c1
    d = np.abs(w)
    disc = heron_height_sq(r1, r2, d)
    along = (r1 * r1 - r2 * r2 + d * d) / (2 * d)
    h = np.sqrt(np.maximum(disc, 0.0)) / (2 * d)
    return c1 + (along + 1j * sign * h) * (w / d), disc


def circle_line(c, r, p, u, sign):
    """Intersection of circle (c, r) with the line p + t·u (|u| = 1) on the side ``sign`` along u.

    Returns ``(point, disc)`` where disc = r² − h² (h the distance from c to the line),
    formed as (r − |h|)(r + |h|) for accuracy near tangency.
    """
    w = c - p
    foot = p + dot(w, u) * u
    h = np.abs(cross(u, w))
    disc = (r - h) * (r + h)
    return foot + sign * np.sqrt(np.maximum(disc, 0.0)) * u, disc


def angle_deg(z):
    """Direction of a plane vector in degrees, counter-clockwise from +x, in [0, 360)."""
    return np.degrees(np.angle(z)) % 360.0
