"""Plans for one crank position: points, vectors and how each point was constructed.

``solve_position(mech, phi)`` returns a :class:`Solution`: the positions, the velocity
plan (pole p) and the acceleration plan (pole π), each point recording its construction
(the two lines intersected, or the similarity step), ω and ε of every link, and every
segment in millimetres at the scale factors μl, μv, μa. The drawing, the explanatory note
and the check of a student's plan all read this one object.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from functools import cached_property
from typing import NamedTuple

import numpy as np

from .errors import SingularPlanError
from .kinematics import SINGULAR_SINE, WARN_SINE, Motion, Solver
from .mechanism import Mechanism
from .scales import choose_mu, choose_mu_l
from .structure import Structure


def plan_name(point: str) -> str:
    """Mechanism point → plan point: A3 → a3, S3 → s3."""
    try:
        return _PLAN_NAMES[point]
    except KeyError:
        return _PLAN_NAMES.setdefault(point, point.lower())


_PLAN_NAMES: dict[str, str] = {}


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


class PlanPoint(NamedTuple):
    name: str
    value: complex  # the vector from the pole: m/s or m/s²
    source: Source


class PlanVector(NamedTuple):
    start: str
    end: str
    component: str  # absolute, relative, normal, tangential, coriolis, sliding
    label: str  # V_A3A, a^n_A3B …


@dataclass(frozen=True)
class Plan:
    kind: str  # "velocity" or "acceleration"
    pole: str  # "p" or "π"
    points: dict[str, PlanPoint]
    vectors: tuple[PlanVector, ...]
    mu: float
    unit: str  # "m/s" or "m/s²"

    def value(self, name: str) -> complex:
        return 0j if name == self.pole else self.points[name].value

    def mm(self, start: str, end: str) -> float:
        """Length of the segment start→end on the drawing, in mm."""
        return abs(self.value(end) - self.value(start)) / self.mu


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
    segments: dict[str, float]  # mm
    lengths: dict[str, float]  # m, position plan segments
    warnings: tuple[str, ...] = field(default_factory=tuple)
    #: the recorded solution on Python numbers, that the plans were built from
    scalar: Motion | None = field(default=None, repr=False, compare=False)

    @property
    def mu_v(self) -> float:
        return self.velocity.mu

    @property
    def mu_a(self) -> float:
        return self.acceleration.mu

    @cached_property
    def motion(self) -> Motion:
        """The same solution as arrays of one angle, for everything the plans do not name.

        Solved again on first use, by the array path: the plans come from the scalar
        path, and the two share every group formula.
        """
        with np.errstate(all="ignore"):
            return self.solver.solve(np.array([self.phi]))


def solve_position(mech: Mechanism, phi: float | None = None, solver: Solver | None = None,
                   mu: dict[str, float] | None = None) -> Solution:
    """Positions and both plans at crank angle ``phi`` (rad from +x; default: the file's)."""
    solver = solver or Solver(mech)
    phi = mech.driver.phi if phi is None else float(phi)
    motion = solver.solve_one(phi)
    deg = math.degrees(phi) % 360
    warnings = []
    for g in motion.groups:
        s = g.velocity.sine
        ang = math.degrees(math.asin(min(abs(s), 1.0)))
        r0, r1 = g.velocity.routes
        if abs(s) < SINGULAR_SINE:
            raise SingularPlanError(
                f"{g.group.label} at φ1 = {deg:.6g}°: the lines {r0.relation} and "
                f"{r1.relation} are parallel (angle {ang:.3g}°): a singular position "
                "(dead point), the plan has no unique solution",
                sine=s,
            )
        if abs(s) < WARN_SINE:
            warnings.append(
                f"{g.group.label} at φ1 = {deg:.6g}°: near-singular, the lines "
                f"{r0.relation} and {r1.relation} meet at {ang:.3g}° (sin = {abs(s):.3g})"
            )
    scales = dict(mech.scales)
    if mu:
        scales.update(mu)
    if "mu_l" not in scales:
        scales["mu_l"] = choose_mu_l(cycle_extent(solver))
    builder = _Builder(mech, solver.structure, motion)
    vplan = builder.velocity(scales.get("mu_v"))
    aplan = builder.acceleration(scales.get("mu_a"))
    positions = dict(motion.position)
    lengths = _position_segments(mech, motion, positions)
    mu_l = scales["mu_l"]
    segments = {k: v / mu_l for k, v in lengths.items()}
    for plan in (vplan, aplan):
        segments.update(_plan_segments(plan))
    links = sorted(mech.links)
    return Solution(
        mechanism=mech, structure=solver.structure, phi=phi, solver=solver,
        positions=positions, velocity=vplan, acceleration=aplan,
        omega={i: float(motion.links[i].omega) for i in links},
        epsilon={i: float(motion.links[i].epsilon) for i in links},
        mu_l=mu_l, segments=segments, lengths=lengths,
        warnings=tuple(warnings), scalar=motion,
    )


def cycle_extent(solver: Solver, n: int = 72) -> float:
    """The larger side (m) of the box that holds every point over the crank's travel."""
    phi = solver.mech.driver.phi + np.linspace(0, 2 * np.pi, n, endpoint=False)
    with np.errstate(all="ignore"):
        m = solver.solve(phi)
    pts = np.concatenate([v[m.valid] for v in m.position.values()])
    if pts.size == 0:
        return 1.0
    return float(max(np.ptp(pts.real), np.ptp(pts.imag), 1e-9))


def _position_segments(mech: Mechanism, motion: Motion, pos: dict[str, complex]) -> dict[str, float]:
    out: dict[str, float] = {}
    names = list(mech.frame)
    for i, a in enumerate(names):
        for b in names[i + 1 :]:
            out[a + b] = abs(pos[b] - pos[a])
    for link in mech.links.values():
        pts = list(link.points)
        origin = link.axis[0] if link.axis else pts[0]
        for p in pts:
            if p != origin:
                out[origin + p] = abs(link.points[p] - link.points[origin])
    for name, base in motion.coincident.items():
        lid = motion.point_link[name]
        link = mech.links[lid]
        origin = link.axis[0] if link.axis else next(iter(link.points))
        if origin != base:
            out[origin + name] = abs(pos[name] - pos[origin])
    return out


def _plan_segments(plan: Plan) -> dict[str, float]:
    out = {}
    for name, pt in plan.points.items():
        if pt.source.kind not in ("pole", "component"):
            out[plan.pole + name] = plan.mm(plan.pole, name)
    for v in plan.vectors:
        if v.component == "absolute":
            continue
        out[v.start + v.end] = plan.mm(v.start, v.end)
    return out


class _Builder:
    """Turns the recorded constructions of a one-angle scalar Motion into the two plans."""

    def __init__(self, mech: Mechanism, structure: Structure, motion: Motion):
        self.mech = mech
        self.structure = structure
        self.m = motion
        self.pos = motion.position
        n_cor = sum(
            1 for g in motion.groups for r in g.acceleration.routes for t in r.terms
            if t.kind == "coriolis"
        )
        self.single_k = n_cor == 1
        self.link_points = {lid: list(link.points) for lid, link in mech.links.items()}
        for n in motion.coincident:
            self.link_points[motion.point_link[n]].append(n)

    def _link_points(self, lid: int) -> list[str]:
        return self.link_points[lid]

    def velocity(self, mu):
        return self._plan("velocity", mu)

    def acceleration(self, mu):
        return self._plan("acceleration", mu)

    def _plan(self, kind: str, mu) -> Plan:
        acc = kind == "acceleration"
        pole = "π" if acc else "p"
        store = self.m.acceleration if acc else self.m.velocity
        sym = "a" if acc else "V"
        points: dict[str, PlanPoint] = {}
        vectors: list[PlanVector] = []
        known: set[str] = set()
        counters = {"n": 0, "k": 0}

        def add(name: str, value: complex, source: Source, absolute=True):
            pn = plan_name(name)
            points[pn] = PlanPoint(pn, value, source)
            known.add(name)
            if absolute and abs(value) > 0:
                vectors.append(PlanVector(pole, pn, "absolute", f"{sym}_{name}"))

        for name in self.mech.frame:
            add(name, 0j, Source("pole"), absolute=False)
        drv = self.mech.driver
        tip_val = store[drv.tip]
        if acc:
            eq = f"a_{drv.tip} = a^n_{drv.tip}{drv.pivot} = ω1²·l_{drv.pivot}{drv.tip}"
            rel = f"∥ {drv.tip}{drv.pivot}, from {drv.tip} to {drv.pivot}"
        else:
            eq = f"V_{drv.tip} = ω1·l_{drv.pivot}{drv.tip}"
            rel = f"⊥ {drv.pivot}{drv.tip}, in the sense of ω1"
        add(drv.tip, tip_val, Source("driver", equation=eq, label=rel))
        self._similar(drv.link, points, store, add, known, sym)
        for g in self.m.groups:
            cons = g.acceleration if acc else g.velocity
            for r in cons.routes:
                if r.base is not None and r.base not in known:
                    # a coincident point of a moving guide, e.g. C4 under the slider C
                    link = self.m.point_link[r.base]
                    self._similar(link, points, store, add, known, sym, only=r.base)
            lines = []
            for r in cons.routes:
                start = plan_name(r.base) if r.base is not None else pole
                for t in r.terms:
                    tag = "n" if t.kind == "normal" else "k"
                    counters[tag] += 1
                    tname = f"{tag}{counters[tag]}"
                    if tag == "k" and self.single_k:
                        tname = "k"
                    val = (points[start].value if start != pole else 0j) + t.value
                    points[tname] = PlanPoint(
                        tname, val,
                        Source("component", equation=_term_formula(t), base=start, label=t.label),
                    )
                    vectors.append(PlanVector(start, tname, t.kind, t.label))
                    start = tname
                lines.append(PlanLine(start, r.direction, r.relation, r.unknown))
            new = cons.point
            val = store[new]
            add(new, val, Source("intersection", equation=cons.equation, lines=tuple(lines),
                                 sine=float(cons.sine)))
            for ln, r in zip(lines, cons.routes, strict=True):
                if ln.through != pole or r.unknown_kind != "sliding":
                    vectors.append(PlanVector(ln.through, plan_name(new), r.unknown_kind, r.unknown))
            for lid in (g.group.a, g.group.b):
                self._similar(lid, points, store, add, known, sym)
        return Plan(kind, pole, points, tuple(vectors), mu or self._mu(points, tip_val),
                    "m/s²" if acc else "m/s")

    @staticmethod
    def _mu(points, tip_val) -> float:
        largest = max(abs(p.value) for p in points.values())
        return choose_mu(abs(tip_val), largest)

    def _similar(self, lid, points, store, add, known, sym, only=None):
        """Points of link ``lid`` not yet on the plan, by the similarity theorem."""
        pts = self._link_points(lid)
        base = [p for p in pts if p in known]
        for name in pts:
            if name in known or (only and name != only):
                continue
            if len(base) >= 2 and abs(self.pos[base[1]] - self.pos[base[0]]) > 0:
                b0, b1 = base[0], base[1]
                ratio = (self.pos[name] - self.pos[b0]) / (self.pos[b1] - self.pos[b0])
                v0 = points[plan_name(b0)].value
                v1 = points[plan_name(b1)].value
                value = v0 + ratio * (v1 - v0)
                n0, n1, nx = plan_name(b0), plan_name(b1), plan_name(name)
                if abs(ratio.imag) < 1e-12:
                    eq = f"{n0}{nx} = {n0}{n1}·{b0}{name}/{b0}{b1}"
                else:
                    eq = f"△{n0}{n1}{nx} ∼ △{b0}{b1}{name}"
                add(name, value, Source("similarity", equation=eq, base=n0, other=n1, ratio=ratio))
            else:
                value = store[name]
                add(name, value, Source("rigid", equation=f"{sym}_{name}: link {lid} moves with {base[0] if base else 'its guide'}"))
            base.append(name)


def _term_formula(t) -> str:
    x, y = t.about
    if t.kind == "normal":
        return f"{t.label} = V_{x}{y}²/l_{x}{y}, directed from {x} to {y}"
    return f"{t.label} = 2·ω·V_{x}{y}, V_{x}{y} turned by 90° in the sense of ω"
