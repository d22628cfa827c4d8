"""Plans for one crank position: points, vectors and how each point was constructed.

``solve_position(mech, phi)`` returns a :class:`Solution`: the positions, the velocity
plan (pole p) and the acceleration plan (pole π), each point recording its construction
(the two lines intersected, or the similarity step), ω and ε of every link, and every
segment in millimetres at the scale factors μl, μv, μa. The drawing, the explanatory note
and the check of a student's plan all read this one object. The plans are built by
recipes, worked out once per solver (:mod:`plans.plan.recipe`); the plans' values are
:mod:`plans.plan.values`'.

One position's solve goes down only: the mechanism (model), its motion at the angle
(kinematics), its plans; the cycle is read where the caller gives it, never solved here.
"""

from __future__ import annotations

import math
import sys
from collections.abc import Mapping
from dataclasses import dataclass, field
from functools import cached_property

import numpy as np

from plans import tolerances
from plans.cycle.positions import drawn
from plans.cycle.words import shown_from, worded
from plans.errors import PositionError
from plans.kinematics.conditioning import flag_words, flagged
from plans.kinematics.records import frozen
from plans.kinematics.solver import Motion, Solver, crank_angle
from plans.model import MU_UNIT, Mechanism
from plans.model.fileformat import Problems, check_keys, read_number
from plans.model.structure import Structure
from plans.plan.recipe import kept, plan
from plans.plan.values import (
    Plan,
    PlanLine,
    PlanPoint,
    PlanVector,
    Source,
    image_sides,
    plan_name,
)
from plans.scales import choose_mu_l

__all__ = [
    "Plan", "PlanLine", "PlanPoint", "PlanVector", "Solution", "Source", "image_sides",
    "plan_name", "solve_position",
]


@dataclass(frozen=True)
class Solution:
    mechanism: Mechanism
    structure: Structure
    phi: float
    solver: Solver
    positions: dict[str, complex]
    velocity: Plan
    acceleration: Plan
    omega: dict[int, float]
    epsilon: dict[int, float]
    mu_l: float
    #: mm: the plan of positions' lengths and both plans' segments by name. A name drawn on
    #: both plans (aa3 of a block on a fixed guide) keeps the acceleration plan's length
    #: here; ``velocity.segments`` and ``acceleration.segments`` hold each plan's own.
    segments: dict[str, float]
    lengths: dict[str, float]  # m, position plan segments
    warnings: tuple[str, ...] = field(default_factory=tuple)
    #: the figures the warnings word (:func:`plans.kinematics.conditioning.flagged`), for other languages
    flags: tuple = field(default=(), repr=False, compare=False)
    #: the recorded solution on Python numbers, that the plans were built from
    scalar: Motion | None = field(default=None, repr=False, compare=False)
    #: where the turn its crank angles are written in begins (degrees, in the file's
    #: convention): 0 for [0°, 360°), or the turn of its cycle's range
    #: (:func:`plans.cycle.shown_from`: "−99.7°" beside a crank range through 0°)
    shown_from: float = 0.0

    @property
    def mu_v(self) -> float:
        return self.velocity.mu

    @property
    def mu_a(self) -> float:
        return self.acceleration.mu

    @property
    def mu(self) -> dict[str, float]:
        """The three scale factors by their file names: mu_l, mu_v, mu_a."""
        return {"mu_l": self.mu_l, "mu_v": self.velocity.mu, "mu_a": self.acceleration.mu}

    @cached_property
    def motion(self) -> Motion:
        """The same solution as arrays of one angle, for everything the plans do not name.

        Solved again on first use, by the array path: the plans come from the scalar
        path, and the two share every group formula.
        """
        with np.errstate(all="ignore"):
            return self.solver.solve(np.array([self.phi]))


def solve_position(mech: Mechanism, phi: float | None = None, solver: Solver | None = None,
                   mu: dict[str, float] | None = None, cycle=None) -> Solution:
    """Positions and both plans at crank angle ``phi`` (rad from +x; default: the file's).

    ``mu``: scale factors by their file names (``mu_l``, ``mu_v``, ``mu_a``), over the
    file's ``[scales]``; one not given (or None) is chosen. A value that is not a positive
    finite number is an :class:`InputError`, in the words of a file's ``[scales]``.

    ``cycle``: the mechanism's cycle (:func:`plans.cycle.analyse_cycle`), where the caller
    has it, as the commands do. A μl left free is then the one the plan of positions with
    the cycle's positions, the extreme ones and the trajectories fits at
    (:attr:`plans.cycle.Drawn.extent`: the sheet's rule), and the crank angles of the
    warnings and errors are written in the turn of the cycle's range (−99.7° beside a
    range through 0°, :func:`plans.cycle.shown_from`). Without it nothing of the cycle is
    solved: a μl left free is the one the given position alone fits at (the larger side
    of the box round its points), and the angles are written in [0°, 360°).
    """
    mu = _given_scales(mu)
    solver = solver or Solver(mech)
    phi = mech.param if phi is None else crank_angle(phi)
    lo = 0.0 if cycle is None else shown_from(cycle, mech.driver)
    try:
        motion = solver.solve_one(phi)
    except PositionError as err:
        if cycle is None:
            raise
        raise worded(err, solver, cycle) from None
    flags = flagged(motion.groups, motion.position, mech.driver.origin,
                    lambda: solver.at(phi, "en", lo), mech.source,
                    lambda i: solver.singular_figures(i, phi), phi)
    warnings = [flag_words(f, solver.at(phi, "en", lo)) for f in flags]
    scales = mech.scales
    if mu or "mu_l" not in scales:
        scales = dict(scales, **(mu or {}))
        if "mu_l" not in scales:  # the drawing is sized only when μl is to be chosen
            extent = _extent(motion.position) if cycle is None else drawn(solver, cycle).extent
            scales["mu_l"] = choose_mu_l(extent)
    keep = kept(solver)
    vplan = plan(solver, motion, "velocity", scales.get("mu_v"), keep.recipes["velocity"])
    aplan = plan(solver, motion, "acceleration", scales.get("mu_a"), keep.recipes["acceleration"])
    positions = dict(motion.position)
    if keep.segments is None:
        keep.segments = _segment_pairs(solver.mech, motion)
    lengths = _position_segments(keep.segments, positions)
    mu_l = scales["mu_l"]
    segments = {k: v / mu_l for k, v in lengths.items()}
    segments.update(vplan.segments)
    segments.update(aplan.segments)
    omega, epsilon = _rates(motion.links, keep.links, mech.driver.omega)
    return frozen(
        Solution,
        mechanism=mech, structure=solver.structure, phi=phi, solver=solver,
        positions=positions, velocity=vplan, acceleration=aplan,
        omega=omega, epsilon=epsilon,
        mu_l=mu_l, segments=segments, lengths=lengths,
        warnings=tuple(warnings), flags=flags, scalar=motion, shown_from=lo,
    )


def _extent(position: dict[str, complex]) -> float:
    """The larger side (m) of the box round one position's points, as
    :attr:`plans.cycle.Drawn.extent` measures the plan of positions."""
    x0 = y0 = math.inf
    x1 = y1 = -math.inf
    for z in position.values():  # one pass of comparisons: this runs at every angle
        x, y = z.real, z.imag
        if x < x0:
            x0 = x
        if x > x1:
            x1 = x
        if y < y0:
            y0 = y
        if y > y1:
            y1 = y
    return max(x1 - x0, y1 - y0, 1e-9)


def _given_scales(mu) -> dict[str, float] | None:
    """The scale factors passed to :func:`solve_position`, read as ``[scales]`` is: a
    negative μ made every segment 0, a μ of 0 was taken for one not given, and a μ in
    quotes failed deep in a plan's recipe."""
    if not mu:
        return mu
    pr = Problems("solve_position")
    if not isinstance(mu, Mapping):
        pr.add("mu", f"must be a dict such as {{'mu_v': 0.05}}, got {mu!r}")
        pr.raise_if_any()
    check_keys(mu, set(MU_UNIT), "mu", pr)
    out = {}
    for key, unit in MU_UNIT.items():
        if mu.get(key) is not None:
            # no bounds of a typed file's: a sheet near a dead point asks for μa = 5e8
            val = read_number(mu[key], f"mu.{key}", pr, positive=True, unit=unit,
                              high=sys.float_info.max)
            if val is not None:
                out[key] = val
    pr.raise_if_any()
    return out


def _rates(states, links, crank_omega: float) -> tuple[dict[int, float], dict[int, float]]:
    """ω and ε of every link, each 0 where it is rounding: within :data:`NOISE` of the
    largest of its kind (ε of ω1² at least, the crank's ω being the largest there is or
    near it), as a plan's segments are. A rocker at rest at an extreme position has ω
    3.9e-14 rad/s, not a sense of turning. Plain loops, and one pass reading both: this
    runs at every angle of a plan."""
    omega, epsilon = {}, {}
    big_w, big_e = 0.0, crank_omega * crank_omega
    for i in links:
        st = states[i]
        w = omega[i] = st.omega
        e = epsilon[i] = st.epsilon
        if abs(w) > big_w:
            big_w = abs(w)
        if abs(e) > big_e:
            big_e = abs(e)
    tiny = tolerances.NOISE
    return _rounded_off(omega, tiny * big_w), _rounded_off(epsilon, tiny * big_e)


def _rounded_off(values: dict[int, float], tiny: float) -> dict[int, float]:
    """``values`` with 0 for each one within ``tiny`` of 0."""
    for v in values.values():
        if v != 0.0 and abs(v) <= tiny:
            return {i: (v if abs(v) > tiny else 0.0) for i, v in values.items()}
    return values  # nearly always: as it is



def _position_segments(pairs, pos: dict[str, complex]) -> dict[str, float]:
    """Lengths (m) on the plan of positions: between fixed points, from each link's first
    point to its others (constant, worked out once: ``pairs``, :func:`_segment_pairs`), and
    to the coincident points."""
    fixed, moving = pairs
    out = dict(fixed)
    for key, a, b in moving:
        out[key] = abs(pos[b] - pos[a])
    return out


def _segment_pairs(mech: Mechanism, motion: Motion):
    fixed: dict[str, float] = {}
    names = list(mech.frame)
    for i, a in enumerate(names):
        for b in names[i + 1 :]:
            fixed[a + b] = abs(mech.frame[b] - mech.frame[a])
    for link in mech.links.values():
        pts = list(link.points)
        origin = link.axis[0] if link.axis else pts[0]
        for p in pts:
            if p != origin:
                fixed[origin + p] = abs(link.points[p] - link.points[origin])
    moving = []
    for name, base in motion.coincident.items():
        link = mech.links[motion.point_link[name]]
        origin = link.axis[0] if link.axis else next(iter(link.points))
        if origin != base:
            moving.append((origin + name, origin, name))
    return fixed, tuple(moving)


