"""The smallest base circle: by the phase portrait for a translating follower, as the
classroom method draws it, and by the limit itself for the others.

**The phase portrait** (s against ds/dφ). Lay the follower's axis upright with B0, its
lowest pitch point, at the origin; mark each position's displacement s up the axis and lay
ds/dφ off across it, on the side the follower's velocity points to when turned by 90° the
way the cam turns: the point P(φ) = (−σ·s′, s). With the cam's centre O at (−e, −s0), the
pressure angle tan α = |s′ − σe|/(s0 + s) is at most [α] exactly where O lies inside the
cone hanging from P(φ) with its half-angle [α] about the vertical:

    y_O ≤ s − |x_O + σs′|·cot[α].

Over a phase the cones' edges are two families of parallel lines (slopes ±cot[α]); each
family's lowest line is the tangent to the portrait at [α] to the vertical,

    y = b± ± x·cot[α],   b± = min over the phase of (s ± σs′·cot[α]),

so the admissible region is below at most two lines per phase (rise at [α], return at
[α′]). The nearest point of it to B0 gives the smallest r0 = |O B0| and the best offset;
at a given e, O is on the line x = −e under the lowest of them.

>>> from plans.cams.laws import LAWS
>>> from plans.cams.motion import Motion, Phase
>>> b = math.radians(120)
>>> m = Motion([Phase("rise", 0, b, LAWS["cosine"]), Phase("dwell", b, math.radians(60), level=0.016),
...             Phase("return", math.radians(180), b, LAWS["cosine"]),
...             Phase("dwell", math.radians(300), math.radians(60))], 0.016)
>>> p = portrait(m, 1, 30.0, 70.0)
>>> round(p.at_offset(0.0)[0] * 1000, 4), round(p.r0 * 1000, 4), round(p.e * 1000, 4)
(14.2711, 8.2394, 4.1197)
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

from plans.cams.search import extreme

__all__ = ["Portrait", "Tangent", "pieces", "portrait"]


class Tangent(NamedTuple):
    """A tangent to the portrait at the pressure-angle limit: y = b + m·x, touching it at
    the cam angle ``phi`` of phase ``phase`` in the point (x, y)."""

    phase: int
    m: float
    b: float
    phi: float
    x: float
    y: float
    limit_deg: float


class Portrait(NamedTuple):
    """The admissible region of the cam's centre: below every tangent. ``r0`` and ``e``:
    the smallest base radius and the offset it takes (its centre at ``centre`` =
    (x_O, y_O) = (−e, −s0) from B0)."""

    tangents: tuple[Tangent, ...]
    r0: float
    e: float
    centre: tuple[float, float]

    def ceiling(self, x):
        """The admissible region's upper edge over ``x``: min over the tangents."""
        x = np.asarray(x, dtype=float)
        return np.min([t.b + t.m * x for t in self.tangents], axis=0)

    def at_offset(self, e: float) -> tuple[float, float]:
        """(r0, s0): the smallest base radius with the axis at the offset ``e``, and its
        s0 (the centre is then at (−e, −s0) from B0)."""
        y = float(self.ceiling(-e))
        s0 = max(-y, 0.0)
        return math.hypot(e, s0), s0

    def admissible(self, x: float, y: float, tol: float = 1e-12) -> bool:
        scale = max(1.0, abs(x), abs(y))
        return all(y <= t.b + t.m * x + tol * scale for t in self.tangents)


def pieces(motion, i: int) -> list[tuple[float, float, str]]:
    """The phase ``i`` in the pieces its formulas are smooth over: (from, to, side) with
    the law's inner joint between its acceleration and deceleration parts (``side``:
    which of the two a joint belongs to, for :meth:`~plans.cams.motion.Motion.of_phase`)."""
    p = motion.phases[i]
    law = getattr(p, "law", None)
    if not p.moves or law is None or law.key in ("constant velocity", "eccentric disc"):
        return [(p.start, p.end, "right")]
    joint = p.start + p.k * p.angle
    return [(p.start, joint, "left"), (joint, p.end, "right")]


def portrait(motion, sigma: int, rise_deg: float, return_deg: float) -> Portrait:
    """The phase portrait's tangents at the limits (rise ``rise_deg``, return
    ``return_deg``) and the nearest admissible centre of the cam."""
    tangents = []
    for i, p in enumerate(motion.phases):
        if not p.moves:
            continue
        limit = rise_deg if p.kind == "rise" else return_deg
        cot = 1.0 / math.tan(math.radians(limit))
        for m in (cot, -cot):
            best = None
            for lo, hi, side in pieces(motion, i):
                def height(phi, i=i, side=side, m=m):
                    s, s1 = motion.of_phase(i, phi, side)[:2]
                    return s + m * sigma * s1  # b = Y − m·X, X = −σs′
                b, phi = extreme(height, lo, hi, largest=False)
                if best is None or b < best[0]:
                    best = (b, phi, side)
            b, phi, side = best
            s, s1 = (float(v) for v in motion.of_phase(i, np.array(phi), side)[:2])
            tangents.append(Tangent(i, m, b, phi, -sigma * s1, s, limit))
    tangents = tuple(tangents)
    x, y = _nearest(tangents)
    return Portrait(tangents, math.hypot(x, y), -x, (x, y))


def _nearest(tangents) -> tuple[float, float]:
    """The point of {y ≤ b + m·x for every tangent} nearest the origin: the foot of the
    origin's perpendicular on one line, or a corner where two meet."""
    cand = []
    for t in tangents:
        d = 1.0 + t.m * t.m
        cand.append((-t.m * t.b / d, t.b / d))
    for i, t in enumerate(tangents):
        for u in tangents[i + 1:]:
            if abs(t.m - u.m) > 1e-15:
                x = (u.b - t.b) / (t.m - u.m)
                cand.append((x, t.b + t.m * x))
    best = None
    for x, y in cand:
        scale = max(1.0, abs(x), abs(y))
        if y < 0 and all(y <= t.b + t.m * x + 1e-12 * scale for t in tangents):
            r = math.hypot(x, y)
            if best is None or r < best[0]:
                best = (r, x, y)
    if best is None:  # (cannot happen: the rise's first point bounds the region below 0)
        raise ArithmeticError("the phase portrait leaves no admissible centre below B0")
    return best[1], best[2]
