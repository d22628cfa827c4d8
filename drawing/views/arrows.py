"""Arrows for forces and moments drawn on a mechanism or a lever, not to scale: one length
for every force, an arc for a moment, and at a point where several act, the way each runs
chosen so that none hides another or lies on a bar (:func:`rays`)."""

from __future__ import annotations

import cmath
import itertools
import math

from drawing.scene import Arrow, Item, Polyline
from drawing.styles import LineType
from drawing.views.common import HEAD

__all__ = ["ARC_R", "ARC_SPAN", "ARROW", "BESIDE", "CROWDED", "arc_arrow", "beside", "clear", "compass",
           "force_arrow", "rays"]

#: mm: a force's arrow on a link: its line and sense, not to scale
ARROW = 14.0
#: mm: the radius of a moment's arc arrow, and how far round it runs (degrees)
ARC_R = 6.0
ARC_SPAN = 270.0
#: rad: an arrow closer than this in angle to a bar or an arrow at its point is moved
#: :data:`BESIDE` mm aside, parallel to its line, so that it is seen
CROWDED = math.radians(5.0)
BESIDE = 2.5


def rays(bars: list[complex], guides: list[complex], directions: list[complex]) -> list[complex]:
    """The ways the arrows of ``directions`` (unit, sheet) at one point run from it: each
    ``d`` (it leaves the point) or ``-d`` (it arrives at it), chosen together so that no
    arrow comes close in angle to a bar there, to another arrow (two alike are set side by
    side, :data:`BESIDE`) or, less, to the ``guides`` (a thin line a force may lie on), and
    then so that as many as may leave the point.

    >>> [(r.real, r.imag) for r in rays([1 + 0j], [], [1 + 0j, 1j])]  # one arrives: not on the bar
    [(-1.0, 0.0), (0.0, 1.0)]
    >>> [r.real for r in rays([-1 + 0j], [], [1 + 0j, 1 + 0j])]  # two alike both leave, off the bar
    [1.0, 1.0]
    """
    n = len(directions)
    if n > 10:  # 1024 ways at most; beyond, each the clearer way from those before it
        head = rays(bars, guides, directions[:10])
        return head + [d if clear(bars + head, d) >= clear(bars + head, -d) else -d
                       for d in directions[10:]]

    def near(a: complex, b: complex) -> float:  # how close two rays are, 0 beyond 40°
        return max(0.0, 40.0 - math.degrees(abs(cmath.phase(a / b)))) ** 2

    best, chosen = None, list(directions)
    for signs in itertools.product((1, -1), repeat=n):
        out = [s * d for s, d in zip(signs, directions, strict=True)]
        cost = (sum(near(r, b) for r in out for b in bars)
                + 0.5 * sum(near(a, b) for i, a in enumerate(out) for b in out[i + 1:])
                + 0.25 * sum(near(r, g) for r in out for g in guides))
        score = (round(cost, 6), -sum(signs))
        if best is None or score < best:
            best, chosen = score, out
    return chosen


def clear(used: list[complex], r: complex) -> float:
    """The smallest angle (rad) between the ray ``r`` and the rays ``used``."""
    return min((abs(cmath.phase(r / u)) for u in used), default=math.pi)


def beside(seen: list[complex], r: complex) -> float:
    """How far aside (mm) an arrow on the ray ``r`` is drawn, parallel to its line: on a
    bar or on an arrow drawn there before (``seen``), :data:`BESIDE` for each it would
    hide itself behind."""
    return BESIDE * sum(clear([q], r) < CROWDED for q in seen)


def force_arrow(p, u: complex, r: complex, aside: float, gap: float) -> tuple[Arrow, tuple[float, float]]:
    """The arrow (:data:`ARROW` long) of a force of direction ``u`` (unit, sheet) at the
    point ``p``, on the ray ``r`` (``u``: it leaves the point; ``-u``: it arrives), ``gap``
    mm off the point and ``aside`` mm to the ray's left; and its far end, where its name
    goes."""
    side = complex(-r.imag, r.real) * aside
    near = (p[0] + gap * r.real + side.real, p[1] + gap * r.imag + side.imag)
    far = (p[0] + (gap + ARROW) * r.real + side.real, p[1] + (gap + ARROW) * r.imag + side.imag)
    ends = (near, far) if abs(r - u) < 1e-9 else (far, near)
    return Arrow(*ends, LineType.MAIN, **HEAD), far


def compass(d: complex) -> str:
    """The compass direction (on the sheet, y down) nearest to ``d``: where a label at the
    end of an arrow running that way goes.

    >>> compass(1 + 0j), compass(-1j)
    ('e', 'n')
    """
    ang = math.degrees(math.atan2(-d.imag, d.real)) % 360
    return ("e", "ne", "n", "nw", "w", "sw", "s", "se")[int(((ang + 22.5) % 360) // 45)]


def arc_arrow(p, moment: float, bars: list[complex]):
    """An arc arrow of radius :data:`ARC_R` round ``p`` (sheet) in the sense of ``moment``
    (counter-clockwise positive, as on the sheet too), its gap on the first of the ``bars``
    there (unit directions, sheet); with where its label goes and which way."""
    sense = 1.0 if moment > 0 else -1.0
    gap = cmath.phase(complex(bars[0].real, -bars[0].imag)) if bars else math.pi / 2  # world angle
    start = gap + sense * math.radians((360.0 - ARC_SPAN) / 2)
    head = 3.5 / ARC_R  # the head's chord, in radians of the arc

    def at(t):  # world angle → sheet point
        return (p[0] + ARC_R * math.cos(t), p[1] - ARC_R * math.sin(t))

    span = math.radians(ARC_SPAN)
    pts = [at(start + sense * span * k / 40) for k in range(41)]
    end = start + sense * span
    body = [q for k, q in enumerate(pts) if span * k / 40 <= span - head + 1e-9]  # up to the head
    items: list[Item] = [Polyline(body, LineType.MAIN),
                         Arrow(at(end - sense * head), at(end), LineType.MAIN, **HEAD)]
    mid = start + sense * span / 2
    anchor = at(mid)
    out = complex(math.cos(mid), -math.sin(mid))
    return items, anchor, compass(out)


