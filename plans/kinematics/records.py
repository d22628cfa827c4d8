"""The records of a solution: link states, the two routes of each construction with their
known terms, each group's solution, and the motion of the whole mechanism.

Values of one angle (Python numbers) or of many (numpy arrays) alike: the solver records
whichever it solved. Everything here is immutable.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import NamedTuple

import numpy as np

from plans import tolerances
from plans.errors import AssemblyError, PlansError, SingularPlanError
from plans.kinematics.kernels import record
from plans.model.structure import DyadKind, Group

def plan_error(sine: float) -> float | None:
    """How far off, at most and relative to the largest of them, a plan's velocities and
    accelerations may be where its lines' sine is ``sine`` (:data:`plans.tolerances.LOSS`);
    None where it is below what a report prints (:data:`plans.tolerances.PRINTED`).

    >>> plan_error(0.03), f"{plan_error(3.3e-7):.1e}", plan_error(1e-9) > 1
    (None, '2.2e-02', True)
    """
    err = tolerances.LOSS * float(np.finfo(float).eps) / (sine * sine)
    return err if err > tolerances.PRINTED else None



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
    why_singular: str  # what makes it singular, for messages
    #: how far inside its limit the group is, as a fraction of its size: 0 where its links
    #: lie in line (a dead point, or a change point where its two assemblies meet), < 0
    #: where it does not close (arrays only: None on the one-angle path)
    margin: np.ndarray | None

    def failure(self, k: int, at: str, note: str = "", source: str = "") -> PlansError:
        """The error for angle index ``k`` where the group does not close; ``at`` names the
        crank angle ("φ1 = 330°", :meth:`plans.model.mechanism.Driver.at`).

        A group that misses (its links do not reach) is an :class:`AssemblyError` with the
        distance it misses by; one exactly at the limit (links in line, parallel guides,
        a pivot on the pin) is a dead point: a :class:`SingularPlanError`.
        """
        label = self.group.label
        if bool(self.singular[k]):
            return SingularPlanError(
                f"{label} at {at}: {self.why_singular}: {_singular(at)}, the plan has no "
                f"unique solution{note}", source=source,
            )
        return AssemblyError(
            f"{label} cannot be assembled at {at}: needs {self.admissible}, "
            f"misses by {float(self.gap[k]):.6g} m{note}",
            group=label, source=source,
        )

    def sine_at(self, k: int | None = None) -> float:
        """|sin| of the angle between the two lines of the plans (k: the angle's index in
        an array solution; None for a solution on Python numbers), as :func:`sine_figure`."""
        s = self.velocity.sine
        return float(sine_figure(s if k is None else s[k]))

    def parallel(self, k: int | None, at: str, source: str = "",
                 below: float | None = None) -> SingularPlanError | None:
        """The error where the two lines of the plans are parallel (|sin| below
        :data:`plans.tolerances.SINGULAR_SINE`): a dead point, no unique plan. None elsewhere. ``below``:
        :data:`plans.tolerances.CHANGE_SINE` beside a change point."""
        below = tolerances.SINGULAR_SINE if below is None else below
        s = self.sine_at(k)
        if s >= below:
            return None
        r0, r1 = self.velocity.routes
        if s >= tolerances.SINGULAR_SINE:
            return SingularPlanError(
                f"{self.group.label} at {at}: the lines {r0.relation} and {r1.relation} "
                f"meet at {_degrees(s):.3g}° (sin = {s:.3g}), under {below:g} beside a "
                f"change point, where the accelerations lose their digits as 1/sin³: "
                f"{_singular(at)}, the plan is not built", sine=s, source=source)
        return SingularPlanError(
            f"{self.group.label} at {at}: the lines {r0.relation} and "
            f"{r1.relation} are parallel (angle {_degrees(s):.3g}°, sin = {s:.3g}): "
            f"{_singular(at)}, the plan has no unique solution", sine=s, source=source)

    def near_parallel(self, k: int | None, at: str, lang: str = "en",
                      below: float | None = None) -> str | None:
        """The warning where the two lines meet at under about 2° (|sin| below
        :data:`plans.tolerances.WARN_SINE`), when they are not parallel (``below``, as for
        :meth:`parallel`). None elsewhere."""
        below = tolerances.SINGULAR_SINE if below is None else below
        s = self.sine_at(k)
        if not below <= s < tolerances.WARN_SINE:
            return None
        r0, r1 = self.velocity.routes
        err = plan_error(s)  # said where the four digits printed are not all right
        if lang == "ru":
            from plans.fmt import num

            lost = ("" if err is None else
                    "; скорости и ускорения могут быть неверны целиком" if err >= 1 else
                    f"; скорости и ускорения могут быть неточны до {num(100 * err, 2, 'ru')} % "
                    "(от наибольшей)")
            return (f"группа {self.group.label.removeprefix('group ')} при {at}: положение, "
                    f"близкое к особому: прямые {r0.relation} и {r1.relation} пересекаются "
                    f"под углом {num(_degrees(s), 3, 'ru')}° (sin = {num(s, 3, 'ru')}){lost}")
        lost = ("" if err is None else
                "; its velocities and accelerations may be wrong altogether" if err >= 1 else
                f"; its velocities and accelerations may be off by up to {100 * err:.2g} % "
                "(of the largest)")
        return (f"{self.group.label} at {at}: near-singular, the lines "
                f"{r0.relation} and {r1.relation} meet at {_degrees(s):.3g}° (sin = {s:.3g}){lost}")


def pivot_figure(g: GroupSolution, position: dict, crank_pivot: complex):
    """For a slotted link (RPR): how far the block P is from the rocker's pivot Q, relative
    to the loop, |QP| / (|OQ| + |OP|) with O the crank's pivot (arrays or Python numbers,
    as ``position`` holds them); None for the other kinds. Near 0 the rocker's
    ω = V / |QP| loses its digits, though the two lines of the plans stay perpendicular."""
    if g.group.kind != DyadKind.RPR:
        return None
    return pivot_ratio(position[g.group.P], position[g.group.Q], crank_pivot)


#: what the pivot figure's key adds to its group's label ("group 2–3 (RPR) pivot"), in a
#: sweep's :attr:`plans.kinematics.sweep.Sweep.pivot` and a cycle row's figures alike
PIVOT = " pivot"


def pivot_key(label: str) -> str:
    """The key of group ``label``'s pivot figure."""
    return label + PIVOT


def is_pivot(key: str) -> bool:
    """Whether a figure's key is a pivot figure's (else it is a group's lines' sine)."""
    return key.endswith(PIVOT)


def pivot_ratio(P, Q, O):
    """|QP| / (|OQ| + |OP|) of a block P, a rocker's pivot Q and the crank's pivot O
    (arrays or Python numbers); 0 where all three coincide."""
    loop = abs(Q - O) + abs(P - O)
    if isinstance(loop, float):  # the one-angle path, on Python numbers
        return abs(P - Q) / loop if loop > 0 else 0.0
    with np.errstate(all="ignore"):
        return np.where(loop > 0, np.abs(P - Q) / np.where(loop > 0, loop, 1.0), 0.0)


def on_pivot(g: GroupSolution, q: float, at: str, source: str = "",
             below: float | None = None) -> SingularPlanError | None:
    """The error where the block is on the rocker's pivot (``q`` from :func:`pivot_figure`
    below :data:`plans.tolerances.SINGULAR_SINE`, or ``below`` beside a change point): the rocker's
    direction, ω and ε are undefined. None elsewhere."""
    below = tolerances.SINGULAR_SINE if below is None else below
    if not q < below:
        return None
    P, Q = g.group.P, g.group.Q
    where = "is on" if q < tolerances.SINGULAR_SINE else f"is all but on (under {below:g}, beside a change point)"
    return SingularPlanError(
        f"{g.group.label} at {at}: the block {P} {where} the rocker's pivot {Q} (|{Q}{P}| "
        f"ratio {q:.3g}): the rocker's ω is undefined, {_singular(at)}",
        sine=q, source=source)


def near_pivot(g: GroupSolution, q: float, at: str, lang: str = "en",
               below: float | None = None) -> str | None:
    """The warning where the block passes close to the rocker's pivot (``q`` under
    :data:`plans.tolerances.WARN_SINE`, not on it: ``below`` as for :func:`on_pivot`). None elsewhere."""
    below = tolerances.SINGULAR_SINE if below is None else below
    if not below <= q < tolerances.WARN_SINE:
        return None
    P, Q = g.group.P, g.group.Q
    if lang == "ru":
        from plans.fmt import num

        return (f"группа {g.group.label.removeprefix('group ')} при {at}: камень {P} проходит "
                f"близко к оси кулисы {Q} (|{Q}{P}| / (|O{Q}| + |O{P}|) = {num(q, 3, 'ru')}): "
                "ω и ε кулисы теряют точность")
    return (f"{g.group.label} at {at}: the block {P} passes close to the rocker's pivot {Q} "
            f"(|{Q}{P}| / (|O{Q}| + |O{P}|) = {q:.3g}): the rocker's ω and ε lose digits")


def flagged(groups, position: dict, crank_pivot: complex, at, source: str = "",
            below=None) -> tuple:
    """The conditioning figures of one position (groups and positions on Python numbers)
    that call for a word: (group, "lines" or "pivot", figure) for each under
    :data:`plans.tolerances.WARN_SINE`, the sine between a group's two lines or a slotted link's pivot
    figure. One that is singular raises its error. ``at()`` names the crank angle, asked
    only then; ``below(i)``, the singular figures (lines, pivot) of the i-th group
    (:meth:`plans.kinematics.Solver.singular_figures`). The words, in either language, are
    :func:`flag_words`."""
    out = []
    for i, g in enumerate(groups):
        lines = abs(g.velocity.sine)
        q = pivot_figure(g, position, crank_pivot)
        if tolerances.WARN_SINE <= lines < math.inf and (q is None or q >= tolerances.WARN_SINE):
            continue
        under, under_q = (tolerances.SINGULAR_SINE, tolerances.SINGULAR_SINE) if below is None else below(i)
        if not tolerances.WARN_SINE <= lines < math.inf:  # NaN, inf: parallel() refuses them
            if (err := g.parallel(None, at(), source, under)) is not None:
                raise err
            out.append((g, "lines", g.sine_at(None)))
        if q is not None and q < tolerances.WARN_SINE:
            if (err := on_pivot(g, q, at(), source, under_q)) is not None:
                raise err
            out.append((g, "pivot", q))
    return tuple(out)


def flag_words(flag: tuple, at: str, lang: str = "en") -> str:
    """The warning for one of :func:`flagged`'s figures."""
    g, kind, figure = flag
    return g.near_parallel(None, at, lang) if kind == "lines" else near_pivot(g, figure, at, lang)


def _singular(at: str) -> str:
    """'a singular position (dead point)', but not where ``at`` already calls the angle a
    change point (:meth:`plans.kinematics.Solver.at`), through which the motion goes on."""
    return "a singular position" if "change point" in at else "a singular position (dead point)"


def _degrees(sine: float) -> float:
    return math.degrees(math.asin(min(sine, 1.0)))


def sine_figure(sine):
    """The conditioning figure of a group's lines from the kernel's signed ``sine`` (a
    number or an array): |sin| within [0, 1], the cross product of two unit vectors as
    rounded reaching 1.0000000000000002, which the kernel divides by as it is; 0 where it
    is not a number (parallel lines). The sweep clips its own in its blocks
    (:meth:`plans.kinematics.sweep._Block._close`), where it is NaN only where nothing closes."""
    s = np.abs(sine)
    return np.where(np.isfinite(s), np.minimum(s, 1.0), 0.0)


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
            out = np.minimum(out, sine_figure(g.velocity.sine))
        return out


def coincident_name(point: str, link: int) -> str:
    return f"{point}{link}"
