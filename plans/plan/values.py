"""The plans of one crank position as values: points, vectors and how each point was
constructed.

A :class:`Plan` (velocity or acceleration) is a pole and its points, each a vector from the
pole with its :class:`Source` (the two lines intersected, a similarity step, a known
component), and the vectors drawn between them, at a scale factor μ. Plans are built by
their recipes (:mod:`plans.plan.recipe`) and held by a :class:`plans.plan.Solution`.
"""

from __future__ import annotations

import re
from collections.abc import Mapping
from types import MappingProxyType
from typing import NamedTuple

from plans import tolerances

#: the plans' own letters: the velocity pole p (π is written pi where a file cannot have
#: Greek), the Coriolis points k, k1, k2 …, the normal components' ends n1, n2 …
OWN_LETTERS = re.compile(r"^(p|pi|k\d*|n\d+)$")


def plan_name(point: str) -> str:
    """Mechanism point → plan point: A3 → a3, S3 → s3. A point whose lower-case letters
    are the plans' own (:data:`OWN_LETTERS`: the pole p, a Coriolis point k, a normal
    component's end n1) is written with a prime, which no point name has: P → p′, K → k′,
    N1 → n1′; so a textbook's points P, Q, R, S, K, N, K1 all keep their letters, and a
    plan's letters stay unambiguous by construction.

    >>> plan_name("A3"), plan_name("P"), plan_name("K1"), plan_name("N")
    ('a3', 'p′', 'k1′', 'n')
    """
    low = point.lower()
    return low + "′" if OWN_LETTERS.match(low) else low


class PlanLine(NamedTuple):
    """A line of known direction through a plan point: "through n1, ⊥ A3B"."""

    through: str
    direction: complex
    relation: str
    unknown: str  # the term the line carries, e.g. "a^t_A3B"


class Source(NamedTuple):
    """How a plan point was obtained.

    kind: "pole" (a fixed point), "driver", "intersection" (of ``lines``), "component"
    (a known vector laid from ``base``), "similarity" (from ``base`` and ``other`` with the
    complex ratio of the link figure), "rigid" (a translating or single-point link).
    """

    kind: str
    equation: str = ""
    lines: tuple[PlanLine, ...] = ()
    base: str = ""
    other: str = ""
    ratio: complex = 0j
    sine: float = 1.0
    label: str = ""  # the physical term, e.g. "a^k_A3A"

    @property
    def in_line(self) -> bool:
        """A similarity point in line with its two bases (``ratio`` real): found on the
        line of their image by the ratio of lengths, not by a similar triangle."""
        return abs(self.ratio.imag) < tolerances.RATIO_IN_LINE


class PlanPoint(NamedTuple):
    name: str
    value: complex  # the vector from the pole: m/s or m/s²
    source: Source


class PlanVector(NamedTuple):
    start: str
    end: str
    component: str  # absolute, relative, normal, tangential, coriolis, sliding
    label: str  # V_A3A, a^n_A3B …


class Plan(NamedTuple):
    """One plan (velocity or acceleration) at one angle: immutable, built once per angle.

    A NamedTuple, built in a fifth of a frozen dataclass's time: a changed copy is
    ``plan._replace(mu=…)`` (not ``dataclasses.replace``), and it unpacks and compares
    as the tuple of its nine fields."""

    kind: str  # "velocity" or "acceleration"
    pole: str  # "p" or "π"
    points: dict[str, PlanPoint]
    vectors: tuple[PlanVector, ...]
    mu: float
    unit: str  # "m/s" or "m/s²"
    #: every drawn segment in mm: pole to each point found, and each component vector
    segments: Mapping[str, float] = MappingProxyType({})
    #: the same segments' ends: name → (from, to), plan point names or the pole
    ends: Mapping[str, tuple[str, str]] = MappingProxyType({})
    #: m/s or m/s²: a vector no longer than this is rounding of 0 (:data:`plans.tolerances.NOISE` of the
    #: plan's longest vector), at any μ
    tiny: float = 0.0

    def value(self, name: str) -> complex:
        """The vector from the pole to plan point ``name`` (m/s or m/s²): plan names are
        lower case, ``value("d")`` for the mechanism's point D (:func:`plan_name`)."""
        try:
            return 0j if name == self.pole else self.points[name].value
        except KeyError:  # value("D") was a bare KeyError: 'D'
            hint = (f"; the mechanism's point {name} is {plan_name(name)!r} on a plan"
                    if isinstance(name, str) and plan_name(name) in self.points else "")
            raise KeyError(f"{name!r} is not a point of the {self.kind} plan (its points: "
                           f"{', '.join([self.pole, *self.points])}){hint}") from None

    def mm(self, start: str, end: str) -> float:
        """Length of the segment start→end on the drawing, in mm; 0 up to ``tiny``, as in
        ``segments``."""
        size = abs(self.value(end) - self.value(start))
        return size / self.mu if size > self.tiny else 0.0


def image_sides(plan: Plan) -> list[tuple[complex, complex]]:
    """The links' images that the similarity points of ``plan`` are found on, as
    segments between two vectors of the plan (from its pole): the image bc run on to e
    for a point in line with its two bases (be = bc·BE/BC), else the two sides be, ce of
    the link's triangle. On the acceleration plan no vector joins b and c, so without
    them e and s2 would float: the sheet and the check's picture draw them thin. A side
    no longer than the plan's rounding (``tiny``) is left out."""
    out = []
    for p in plan.points.values():
        src = p.source
        if src.kind != "similarity":
            continue
        b0, b1, z = plan.value(src.base), plan.value(src.other), p.value
        if src.in_line:  # as the step's equation is worded
            lo, hi = min(0.0, src.ratio.real), max(1.0, src.ratio.real)
            sides = [(b0 + lo * (b1 - b0), b0 + hi * (b1 - b0))]
        else:
            sides = [(b0, z), (b1, z)]
        out += [(a, b) for a, b in sides if abs(b - a) > plan.tiny]
    return out
