"""The records of a solution: link states, the two routes of each construction with their
known terms, each group's solution, and the motion of the whole mechanism.

Values of one angle (Python numbers) or of many (numpy arrays) alike: the solver records
whichever it solved. Everything here is immutable.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import NamedTuple

import numpy as np

from plans import tolerances
from plans.errors import PositionError, SingularPlanError
from plans.kinematics import conditioning
from plans.kinematics.kernels import record
from plans.model.structure import Group


class LinkState(NamedTuple):
    """Pose and motion of a link: its origin point and orientation (unit complex),
    the velocity and acceleration of the origin, ω and ε (counter-clockwise positive)."""

    origin: np.ndarray
    rotor: np.ndarray
    v: np.ndarray
    omega: np.ndarray
    a: np.ndarray
    epsilon: np.ndarray

    def pos(self, local):
        return self.origin + self.rotor * local

    def vel(self, X):
        return self.v + 1j * self.omega * (X - self.origin)

    def acc(self, X):
        return self.a + (1j * self.epsilon - self.omega**2) * (X - self.origin)


def state_from(origin, rotor, X, vX, aX, omega, eps) -> LinkState:
    """The state of a link from one of its points X with known velocity and acceleration."""
    r = origin - X
    return record(LinkState, (
        origin, rotor, vX + 1j * omega * r, omega, aX + (1j * eps - omega * omega) * r, eps
    ))


class Term(NamedTuple):
    """A known vector of an equation, drawn head to tail before the unknown line."""

    kind: str  # "normal" or "coriolis"
    value: np.ndarray
    label: str  # "a^n_A3B", "a^k_A3A"
    about: tuple[str, str]  # normal: (point, centre); Coriolis: (point, the point it slides on)


class Route(NamedTuple):
    """One of the two vector equations of a group: known base, known terms, one line."""

    base: str | None  # mechanism point whose plan point starts the route; None = the pole
    base_value: np.ndarray
    terms: tuple[Term, ...]
    direction: np.ndarray  # unit vector of the unknown term
    relation: str  # "⊥ CB", "∥ BC", "∥ x-x"
    unknown: str  # "V_A3B", "a^t_A3B", "a^r_A3A"
    unknown_kind: str  # "relative", "tangential", "sliding"
    param: np.ndarray  # signed magnitude of the unknown term along ``direction``

    @property
    def line_point(self):
        out = self.base_value
        for t in self.terms:
            out = out + t.value
        return out


class Construction(NamedTuple):
    """How the new point of a group was found: the intersection of two routes."""

    point: str  # mechanism name of the point found (C, A3…)
    value: np.ndarray
    routes: tuple[Route, Route]
    sine: np.ndarray
    equation: str


class GroupSolution(NamedTuple):
    group: Group
    velocity: Construction
    acceleration: Construction
    valid: np.ndarray  # bool: the group closes at this angle
    gap: np.ndarray  # how far it is from closing (m); > 0 where it does not close
    admissible: str  # the condition, for messages
    singular: np.ndarray  # bool: where it does not close, is it a dead point (no miss)?
    why_singular: dict[str, str]  # what makes it singular, for messages, by language
    #: how far inside its limit the group is, as a fraction of its size: 0 where its links
    #: lie in line (a dead point, or a change point where its two assemblies meet), < 0
    #: where it does not close (arrays only: None on the one-angle path)
    margin: np.ndarray | None

    def failure(self, k: int, at: str, note: str = "", source: str = "",
                phi: float | None = None) -> PositionError:
        """The error for angle index ``k`` where the group does not close
        (:func:`plans.kinematics.conditioning.failure`)."""
        return conditioning.failure(self, k, at, note, source, phi)

    def sine_at(self, k: int | None = None) -> float:
        """|sin| of the angle between the two lines of the plans
        (:func:`plans.kinematics.conditioning.sine_at`)."""
        return conditioning.sine_at(self, k)

    def parallel(self, k: int | None, at: str, source: str = "", below: float | None = None,
                 phi: float | None = None) -> SingularPlanError | None:
        """The error where the two lines of the plans are parallel
        (:func:`plans.kinematics.conditioning.parallel`); None elsewhere."""
        return conditioning.parallel(self, k, at, source, below, phi)

    def near_parallel(self, k: int | None, at: str, lang: str = "en",
                      below: float | None = None) -> str | None:
        """The warning where the two lines meet at under about 2°
        (:func:`plans.kinematics.conditioning.near_parallel`); None elsewhere."""
        return conditioning.near_parallel(self, k, at, lang, below)


def frozen(cls, **fields):
    """An instance of the frozen dataclass ``cls`` from every one of its fields, put in its
    dict in one step: the class's own ``__init__`` sets them one by one through
    ``object.__setattr__``, three times as long, and the one-angle path makes a
    :class:`Motion` and a ``Solution`` at every angle (``tests/test_paths.py`` holds the
    two ways equal)."""
    obj = object.__new__(cls)
    obj.__dict__.update(fields)
    return obj


@dataclass(frozen=True)
class Motion:
    """Positions, velocities and accelerations of every point and link over angles ``phi``."""

    phi: np.ndarray
    links: dict[int, LinkState]
    position: dict[str, np.ndarray]
    velocity: dict[str, np.ndarray]
    acceleration: dict[str, np.ndarray]
    point_link: dict[str, int]  # the link a (coincident) point belongs to
    groups: tuple[GroupSolution, ...]
    valid: np.ndarray
    coincident: dict[str, str] = field(default_factory=dict)  # "A3" -> "A"

    @property
    def placed(self) -> np.ndarray:
        """Where every point stands: each group closes, or misses by rounding only, its
        links in line (at a change point the positions stand, the plans are singular)."""
        out = np.asarray(self.valid, dtype=bool)
        if self.groups:  # valid, unless a group misses by more than rounding
            out = np.ones_like(out)
        for g in self.groups:
            out = out & (g.valid if g.margin is None else g.valid | (g.margin >= -tolerances.IN_LINE))
        for z in self.position.values():  # a pin exactly on a pivot: the group has no place
            out = out & np.isfinite(z)
        return out

    @property
    def min_sine(self) -> np.ndarray:
        """Conditioning: the smallest |sin| between intersected lines over the groups."""
        out = np.ones_like(self.phi)
        for g in self.groups:
            out = np.minimum(out, conditioning.sine_figure(g.velocity.sine))
        return out


def coincident_name(point: str, link: int) -> str:
    return f"{point}{link}"
