"""What a synthesis gives back: its solutions, each with its links and its construction as
recorded data, the family a free parameter spans, and the chosen member.

The time-ratio coefficient and the angle between the extreme positions (seed 004; seed
002's K_v):

    K = (180° + θ) / (180° − θ),    θ = 180°·(K − 1) / (K + 1)

>>> round(math.degrees(theta_of(1.25)), 12), round(K_of(math.radians(36)), 12)
(20.0, 1.5)
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from plans.errors import InputError
from plans.model.fileformat import Problems


def theta_of(K: float) -> float:
    """θ (rad) of the time-ratio coefficient K."""
    return math.pi * (K - 1.0) / (K + 1.0)


def K_of(theta: float) -> float:
    """K of the angle θ (rad) between the extreme positions."""
    return (math.pi + theta) / (math.pi - theta)


@dataclass(frozen=True, slots=True)
class Mark:
    """One element of the construction as the textbook draws it, in the written file's
    coordinates (m, x right, y up), for the sheet to draw and letter.

    ``kind``: "point" (one point, lettered ``label``), "line" (a thin construction line
    through ``points``), "circle" (centre, a point on it), "arc" (centre, start, end:
    counter-clockwise), "angle" (vertex, one side's point, the other's: the angle
    ``value`` lettered ``label``), "length" (a segment ``label`` = ``value`` at μl),
    "guide" (a slider's fixed guide through two points), "link" (a link of the
    mechanism in main lines), "pivot" (a fixed pivot), "block" (a slider or slide block
    at the first point along the direction to the second), "thin" (a link in an extreme
    position, thin)."""

    kind: str
    points: tuple[complex, ...]
    label: str = ""
    value: float | None = None


@dataclass(frozen=True)
class Solution:
    """One mechanism that meets the requirements.

    ``lengths``: the links in m ("AB", "BC", "CD", "AD", "e", "AC", "DE", "h": the ram
    guide's height over the rocker's pivot); ``figures``: what the engine's re-analysis
    must give back and the criterion's figures ("theta" rad, "K", "H" m or "psi" rad,
    "gamma_min" rad, "delta_max" rad, …); ``points``: the joints and fixed pivots in the
    written file's coordinates; ``marks``: the construction; ``param``: its value of the
    family's free parameter (rad), where it belongs to one; ``branch``: which of the
    family's branches (an index into :attr:`Design.curves`)."""

    lengths: dict[str, float]
    figures: dict[str, float]
    points: dict[str, complex]
    marks: tuple[Mark, ...] = ()
    param: float | None = None
    branch: int = 0
    #: the crank angles (rad from +x) of the extreme positions, the folded one (crank and
    #: coupler overlapping) first, in the written file's coordinates
    extremes: tuple[float, ...] = ()


@dataclass(frozen=True)
class Curve:
    """A family's figure of merit sampled over its free parameter, for the note, the JSON
    and the sheet: ``x`` the parameter (the angle u = ∠AC₂C₁ + θ/2 in rad, a ratio, or a
    distance), ``y`` the figure (rad), NaN where no mechanism exists; ``label`` names the
    branch."""

    label: str
    figure: str  # "gamma_min" or "delta_max"
    x: np.ndarray
    y: np.ndarray
    #: the free parameter's symbol and unit ("°": ``x`` in rad shown in degrees; "m"; "")
    parameter: str = "u"
    unit: str = "°"

    def shown(self, x):
        """The parameter as the report and the sheet write it (degrees for an angle)."""
        return np.degrees(x) if self.unit == "°" else np.asarray(x, dtype=float)


@dataclass(frozen=True)
class Problem:
    """The requirements as read (:mod:`plans.synthesis.problem`), in SI units (m, rad).

    ``given``: the kind's own requirements by their file keys ("K", "CD", "psi" in rad
    for ``psi_deg`` …); ``options``: what the written mechanism file carries as given
    (name, driver, loads, drive, title); ``source``: the file or "command line"; ``text``:
    the requirements as the user wrote them, for the written file's comment."""

    kind: str
    given: dict[str, Any]
    source: str = "command line"
    options: dict[str, Any] = field(default_factory=dict)
    criterion: str = "best"
    solution: int | None = None
    text: tuple[str, ...] = ()
    #: the synthesis file's text, to locate a problem to its line (None: the command line)
    file_text: str | None = None


@dataclass(frozen=True)
class Design:
    """The synthesis: every admissible solution (ordered), the one chosen and why, and
    the families sampled."""

    problem: Problem
    solutions: tuple[Solution, ...]
    chosen: int
    why: str  # "only", "given", "best", "size", "limit"
    curves: tuple[Curve, ...] = ()

    @property
    def solution(self) -> Solution:
        return self.solutions[self.chosen]


def crank_marks(A: complex, C1: complex, C2: complex, a: float, b: float, th: float) -> list[Mark]:
    """The crank's part of a construction by K, the same for a rocker's and a slider's
    extremes C₁, C₂: the lines AC₁, AC₂ and θ between them, AE = AC₁ laid on AC₂, the
    lengths AC₁ = BC − AB, AC₂ = BC + AB and EC₂ = 2·AB at μl, and the pivot A."""
    E = (b - a) * (C2 - A) / abs(C2 - A)
    return [
        Mark("line", (A, C1)), Mark("line", (A, C2)),
        Mark("angle", (A, C1, C2), "θ", th),
        Mark("arc", (A, C1, E)), Mark("point", (E,), "E"),
        Mark("length", (A, C1), "AC1 = BC − AB", b - a),
        Mark("length", (A, C2), "AC2 = BC + AB", b + a),
        Mark("length", (E, C2), "EC2 = 2·AB", 2 * a),
        Mark("point", (A,), "A"),
    ]


def right_angle_marks(C1: complex, C2: complex, P: complex | None, th: float) -> list[Mark]:
    """C₁P ⊥ C₁C₂ and ∠C₁C₂P = 90° − θ, whose circle on C₂P sees C₁C₂ under θ; none where
    θ is 90° and P is at infinity."""
    if P is None:
        return []
    return [Mark("line", (C1, P)), Mark("line", (C2, P)), Mark("point", (P,), "P"),
            Mark("angle", (C2, C1, P), "90° − θ", math.pi / 2 - th)]


def impossible(problem: Problem, key: str, message: str) -> InputError:
    """The one line of a requirement that no mechanism meets: the key (located to its line
    in a synthesis file), the condition it violates and the admissible range."""
    pr = Problems(problem.source, problem.file_text)
    pr.add(key, message)
    return InputError(problem.source, pr.lines())


def merged(spans: list[tuple[float, float]], close: float = 1e-9) -> list[tuple[float, float]]:
    """Overlapping spans (lo, hi) joined, ascending; an end within rounding of 0 is 0.

    >>> merged([(3.0, 4.0), (1e-17, 1.0), (0.5, 2.0)])
    [(0.0, 2.0), (3.0, 4.0)]
    """
    out: list[tuple[float, float]] = []
    big = max((max(abs(lo), abs(hi)) for lo, hi in spans), default=0.0)
    spans = [(0.0 if abs(lo) < 1e-9 * big else lo, 0.0 if abs(hi) < 1e-9 * big else hi)
             for lo, hi in spans]  # an end the family reaches in the limit, as 0
    for lo, hi in sorted(spans):
        if out and lo <= out[-1][1] + close * max(abs(hi), 1.0):
            out[-1] = (out[-1][0], max(out[-1][1], hi))
        else:
            out.append((lo, hi))
    return out


def acute(cos_value):
    """The acute angle whose cosine has the magnitude of ``cos_value`` (the transmission
    angle γ taken as the acute angle between coupler and rocker, seed 004)."""
    return np.arccos(np.clip(np.abs(cos_value), 0.0, 1.0))


def fourbar_figures(a, b, c, d):
    """γmin of crank a, coupler b, rocker c, frame d (arrays), and where the chain is a
    crank-rocker (a the shortest link, Grashof's sum strictly less)."""
    with np.errstate(all="ignore"):
        longest = np.maximum(np.maximum(b, c), d)
        shortest = np.minimum(np.minimum(b, c), d)
        margin = (b + c + d - longest) - (a + longest)
        cos1 = (b * b + c * c - (d - a) ** 2) / (2 * b * c)
        cos2 = (b * b + c * c - (d + a) ** 2) / (2 * b * c)
        gamma = np.minimum(acute(cos1), acute(cos2))
    ok = (a > 0) & (a < shortest) & (margin > 1e-12 * (a + longest))
    return gamma, ok
