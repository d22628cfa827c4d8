"""Kinetostatics of one crank position by force plans, group by group (d'Alembert).

The groups are taken in the reverse of their attachment, the last attached first; each is
statically determinate and is solved by its kernel (:mod:`plans.forces.kernels`) as the
textbook solves it: moment equations first, then a force polygon closed by two lines of
known direction. What a group's links put on the links solved after it (their reactions,
reversed) joins those links' loads. Then the driving link gives the balancing moment M_у
(and the balancing force F_у = M_у / l_OA at its pin, ⊥ the crank) and the frame's force.

Each group's force plan is recorded as the velocity and acceleration plans are
(:class:`plans.plan.Plan`, ``kind`` "force"): its vectors laid end to end from the pole
a, each point with the step that found it, the two closing lines with their directions,
and every segment in mm at the plan's μF (N/mm, a standard value).

>>> from plans import load, solve_position
>>> from plans.model.loads import Loads, Mass
>>> sol = solve_position(load("samples/fourbar.toml"))
>>> loads = Loads(g=9.8, masses={2: Mass(2, 1.575, 0.0, "S2")})
>>> fa = analyse(sol, loads)
>>> [g.group.label for g in fa.groups], round(fa.M_y, 4)
(['group 2–3 (RRR)'], 0.6961)
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import NamedTuple

from plans.errors import SingularPlanError
from plans.forces import kernels as K
from plans.forces.fplans import NOISE, closed_plan, vector_plan, yoke_plan
from plans.forces.loads import Load, Stroke, at_position
from plans.geometry import cross
from plans.model import Mechanism
from plans.model.loads import Loads
from plans.model.structure import DyadKind, Group
from plans.plan.solution import Plan as VectorPlan
from plans.plan.solution import Solution


class Reaction(NamedTuple):
    """The force of link ``by`` on link ``on`` (R_by,on), N. Through the joint ``point``
    of a revolute pair; a prismatic pair's force is ⊥ its guide, through ``at`` (None
    where it is 0 and has no line). ``tangential``, ``normal``: the textbook's two
    components of a revolute's reaction where it was found so (else None)."""

    name: str
    by: int
    on: int
    pair: str  # "revolute" or "prismatic"
    point: str | None
    at: complex | None
    value: complex
    tangential: complex | None = None
    normal: complex | None = None


class Arm(NamedTuple):
    """A term of a moment equation: the load ``name`` of size ``size`` (N, or N·m for a
    couple) with its arm ``arm`` (m, 0 for a couple) about a point, and its moment
    (N·m, counter-clockwise positive)."""

    name: str
    size: float
    arm: float
    moment: float


class Equation(NamedTuple):
    """ΣM_about(link) = 0 as a note writes it: the known terms and the unknown."""

    link: int
    about: str
    terms: tuple[Arm, ...]
    unknown: str  # "R12^τ", "N", …
    arm: float  # m: what the terms' sum is divided by (the unknown's arm, signed by its direction)
    value: float  # the unknown's signed size along its own direction (N): Σ terms / arm


class GroupForces(NamedTuple):
    group: Group
    loads: dict  # link → tuple of Load on it (its own, and what later groups put on it)
    reactions: tuple[Reaction, ...]
    equations: tuple[Equation, ...]
    plan: VectorPlan
    sine: float  # between the plan's two closing lines (1 where a vector closes it)


@dataclass(frozen=True)
class ForceAnalysis:
    """The force analysis of one crank position."""

    solution: Solution
    loads: tuple[Load, ...]  # the external loads, as :func:`plans.forces.loads.at_position`
    groups: tuple[GroupForces, ...]  # in the order solved: the last attached first
    crank_loads: tuple[Load, ...]  # on the driving link: its own and the groups' forces
    R01: complex  # the frame's force on the driving link at its pivot
    M_y: float  # the balancing moment on the driving link, counter-clockwise positive
    stroke: Stroke | None

    @property
    def mechanism(self) -> Mechanism:
        return self.solution.mechanism

    @property
    def F_y(self) -> float:
        """The balancing force at the crank pin ⊥ the crank (N): M_у / l_OA, positive
        where it turns the crank counter-clockwise."""
        return self.M_y / self.crank_length

    @property
    def crank_length(self) -> float:
        d = self.mechanism.driver
        return abs(self.solution.positions[d.tip] - self.solution.positions[d.pivot])

    @property
    def reactions(self) -> dict[str, Reaction]:
        out = {}
        for g in self.groups:
            for r in g.reactions:
                out[r.name] = r
        d = self.mechanism.driver
        out[_name(0, d.link)] = Reaction(
            _name(0, d.link), 0, d.link, "revolute", d.pivot, self.solution.positions[d.pivot], self.R01
        )
        return out

    @property
    def power(self) -> float:
        """The power the drive gives the crank, M_у·ω1 (W)."""
        return self.M_y * self.mechanism.driver.omega


def _name(by: int, on: int) -> str:
    return f"R{by}{on}" if by < 10 and on < 10 else f"R{by},{on}"


def _partner(mech: Mechanism, point: str, link: int, known: set[int]) -> int:
    """The known link that ``link`` is hinged to at ``point``."""
    for p, x, y in mech.revolutes():
        if p == point and link in (x, y):
            other = y if x == link else x
            if other in known:
                return other
    raise ValueError(f"link {link} is not hinged to a known link at {point}")  # pragma: no cover


def analyse(
    sol: Solution, loads: Loads, stroke: Stroke | None = None, mu_F: float | None = None
) -> ForceAnalysis:
    """The force analysis at the position of ``sol`` under ``loads``; ``stroke``: the
    working stroke (:func:`plans.forces.loads.stroke_of`), which a P(S) graph needs;
    ``mu_F``: one scale factor for every force plan (None: each its own standard value)."""
    mech, m = sol.mechanism, sol.scalar
    # a load that is exactly nothing here (the inertia force of a centre on the pivot) is left out
    external = [ld for ld in at_position(mech, loads, m, sol.phi, stroke) if ld.force != 0 or ld.moment != 0]
    return analyse_loads(sol, external, stroke, mu_F)


def analyse_loads(
    sol: Solution, external, stroke: Stroke | None = None, mu_F: float | None = None, motion=None
) -> ForceAnalysis:
    """The force analysis at the position of ``sol`` under the external loads ``external``
    (:class:`plans.forces.loads.Load` s, as :func:`plans.forces.loads.at_position` gives
    them, or changed: the check replays a student's mistake so), the groups solved at
    ``motion`` (default the solution's own; the check passes the motion a student's plans
    give)."""
    mech = sol.mechanism
    m = sol.scalar if motion is None else motion
    on: dict[int, list[Load]] = {lid: [] for lid in mech.links}
    for ld in external:
        on[ld.link].append(ld)
    steps, M_y, R01 = walk(mech, sol.structure.groups, m, on)
    groups = tuple(_recorded(mech, st, mu_F, sol) for st in steps)
    return ForceAnalysis(
        sol, tuple(external), groups, tuple(on[mech.driver.link]), complex(R01), float(M_y), stroke
    )


def _terms(loads):
    return [ld.term for ld in loads]


class Step(NamedTuple):
    """One group's equilibrium as :func:`walk` finds it: the kernel's record, the points
    and directions it used, and the forces the group puts back on the links before it."""

    group: Group
    result: object  # a record of :mod:`plans.forces.kernels`
    geometry: dict  # "P", "C", "Q", "u", "u1", "u2", "us", "B0" as the kind uses them
    partners: dict  # joint → the known link the group is hinged to there
    loads: dict  # link → its loads (its own and those later groups put on it)
    backs: tuple[K.Back, ...]


def walk(mech: Mechanism, groups, motion, on: dict[int, list[Load]]):
    """The groups' equilibrium, the last attached first, at the position(s) of ``motion``
    (Python numbers or arrays alike: the sweep over the cycle walks the same way), each
    group's forces on the links before it added to their loads in ``on``. Returns the
    steps in the order solved and the driving link's (M_у, R_01)."""
    known_before = []
    known = {0, mech.driver.link}
    for g in groups:
        known_before.append(set(known))
        known |= {g.a, g.b}
    steps = []
    for gi in reversed(range(len(groups))):
        step = _step(mech, motion, groups[gi], on, known_before[gi])
        steps.append(step)
        for b in step.backs:
            if b.link:
                on[b.link].append(Load(b.name, "reaction", b.link, None, b.at, b.force, b.moment))
    d = mech.driver
    terms = [ld.term for ld in on[d.link]]
    pivot = motion.position[d.pivot]
    M_y, R01 = K.crank(pivot, K.resultant(terms), K.moment(terms, pivot))
    return steps, M_y, R01


def _direction(motion, guide):
    return motion.links[guide.link].rotor * guide.direction if guide.link else guide.direction


def _step(mech, m, g: Group, on, known) -> Step:
    pos = m.position
    A, B = tuple(on[g.a]), tuple(on[g.b])
    ta, tb = _terms(A), _terms(B)
    Fa, Fb = K.resultant(ta), K.resultant(tb)
    kind = g.kind
    if kind == DyadKind.RRR:
        P, C, Q = pos[g.P], pos[g.C], pos[g.Q]
        kP, kQ = _partner(mech, g.P, g.a, known), _partner(mech, g.Q, g.b, known)
        r = K.rrr(P, C, Q, Fa, K.moment(ta, C), Fb, K.moment(tb, C))
        backs = (
            K.Back(kP, _name(g.a, kP), g.a, P, -r.R_P, 0.0),
            K.Back(kQ, _name(g.b, kQ), g.b, Q, -r.R_Q, 0.0),
        )
        return Step(g, r, {"P": P, "C": C, "Q": Q}, {g.P: kP, g.Q: kQ}, {g.a: A, g.b: B}, backs)
    if kind == DyadKind.RRP:
        P, C = pos[g.P], pos[g.C]
        kP, k = _partner(mech, g.P, g.a, known), g.s1.guide.link
        u = _direction(m, g.s1.guide)
        r = K.rrp(P, C, u, Fa, K.moment(ta, C), Fb, K.moment(tb, C))
        backs = (
            K.Back(kP, _name(g.a, kP), g.a, P, -r.R_P, 0.0),
            K.Back(k, _name(g.b, k), g.b, C, -r.N, r.m_b),
        )
        return Step(g, r, {"P": P, "C": C, "u": u}, {g.P: kP}, {g.a: A, g.b: B}, backs)
    if kind == DyadKind.RPR:
        P, Q = pos[g.P], pos[g.Q]
        kP, kQ = _partner(mech, g.P, g.a, known), _partner(mech, g.Q, g.b, known)
        u = m.links[g.b].rotor * g.s1.guide.direction
        r = K.rpr(P, Q, u, Fa, K.moment(ta, P), Fb, K.moment(tb, Q))
        backs = (
            K.Back(kP, _name(g.a, kP), g.a, P, -r.R_P, 0.0),
            K.Back(kQ, _name(g.b, kQ), g.b, Q, -r.R_Q, 0.0),
        )
        return Step(g, r, {"P": P, "Q": Q, "u": u}, {g.P: kP, g.Q: kQ}, {g.a: A, g.b: B}, backs)
    if kind == DyadKind.PRP:
        C = pos[g.C]
        g1, g2 = g.s1.guide, g.s2.guide
        u1, u2 = _direction(m, g1), _direction(m, g2)
        r = K.prp(C, u1, u2, Fa, K.moment(ta, C), Fb, K.moment(tb, C))
        backs = (
            K.Back(g1.link, _name(g.a, g1.link), g.a, C, -r.N1, r.m_a),
            K.Back(g2.link, _name(g.b, g2.link), g.b, C, -r.N2, r.m_b),
        )
        return Step(g, r, {"C": C, "u1": u1, "u2": u2}, {}, {g.a: A, g.b: B}, backs)
    # RPP: the block a hinged at P slides in link b, which slides on the guide of link k
    P = pos[g.P]
    kP = _partner(mech, g.P, g.a, known)
    gin, gout = g.s1.guide, g.s2.guide
    k = gout.link
    us = m.links[g.b].rotor * gin.direction
    u = _direction(m, gout)
    B0 = m.links[k].pos(gout.point) if k else gout.point
    r = K.rpp(P, B0, us, u, Fa, K.moment(ta, P), Fb, K.moment(tb, B0))
    backs = (
        K.Back(kP, _name(g.a, kP), g.a, P, -r.R_P, 0.0),
        K.Back(k, _name(g.b, k), g.b, B0, -r.N_kb, -r.couple),
    )
    return Step(g, r, {"P": P, "us": us, "u": u, "B0": B0}, {g.P: kP}, {g.a: A, g.b: B}, backs)


def _recorded(mech, step: Step, mu_F, sol) -> GroupForces:
    """A step of the walk at one position, recorded: its reactions by name, its moment
    equations with their arms, and its force plan."""
    g, r, geo, kp = step.group, step.result, step.geometry, step.partners
    A, B = step.loads[g.a], step.loads[g.b]
    kind = g.kind
    if kind == DyadKind.RRR:
        P, C, Q = geo["P"], geo["C"], geo["Q"]
        kP, kQ = kp[g.P], kp[g.Q]
        _singular(r.sine, g, sol, f"the lines ∥ {g.P}{g.C} and ∥ {g.Q}{g.C}")
        RP = Reaction(_name(kP, g.a), kP, g.a, "revolute", g.P, P, r.R_P, 1j * r.tau_a * r.e_a, r.n_a * r.e_a)
        RQ = Reaction(_name(kQ, g.b), kQ, g.b, "revolute", g.Q, Q, r.R_Q, 1j * r.tau_b * r.e_b, r.n_b * r.e_b)
        RC = Reaction(_name(g.b, g.a), g.b, g.a, "revolute", g.C, C, r.R_C)
        RCb = Reaction(_name(g.a, g.b), g.a, g.b, "revolute", g.C, C, -r.R_C)
        eqs = (
            _equation(A, g.a, g.C, C, RP.name + "^τ", P, 1j * r.e_a, r.tau_a),
            _equation(B, g.b, g.C, C, RQ.name + "^τ", Q, 1j * r.e_b, r.tau_b),
        )
        plan = closed_plan(
            [
                (RP.name + "^τ", "tangential", 1j * r.tau_a * r.e_a),
                *_vectors(A),
                *_vectors(B),
                (RQ.name + "^τ", "tangential", 1j * r.tau_b * r.e_b),
            ],
            (RQ.name + "^n", r.e_b, f"∥ {g.Q}{g.C}", r.n_b * r.e_b),
            (RP.name + "^n", r.e_a, f"∥ {g.P}{g.C}", r.n_a * r.e_a),
            r.sine,
            mu_F,
            [RP, RQ],
            RC,
            A,
        )
        return GroupForces(g, {g.a: A, g.b: B}, (RP, RQ, RC, RCb), eqs, plan, abs(r.sine))
    if kind == DyadKind.RRP:
        P, C, u = geo["P"], geo["C"], geo["u"]
        kP, guide = kp[g.P], g.s1.guide
        k = guide.link
        _singular(r.sine, g, sol, f"the lines ∥ {g.P}{g.C} and ⊥ the guide {guide.label}")
        RP = Reaction(_name(kP, g.a), kP, g.a, "revolute", g.P, P, r.R_P, 1j * r.tau_a * r.e_a, r.n_a * r.e_a)
        RN = Reaction(_name(k, g.b), k, g.b, "prismatic", None, _contact(C, u, r.m_b, r.nu), r.N)
        RC = Reaction(_name(g.b, g.a), g.b, g.a, "revolute", g.C, C, r.R_C)
        RCb = Reaction(_name(g.a, g.b), g.a, g.b, "revolute", g.C, C, -r.R_C)
        eqs = (_equation(A, g.a, g.C, C, RP.name + "^τ", P, 1j * r.e_a, r.tau_a),)
        plan = closed_plan(
            [(RP.name + "^τ", "tangential", 1j * r.tau_a * r.e_a), *_vectors(A), *_vectors(B)],
            (RN.name, r.w, f"⊥ {guide.label}", r.N),
            (RP.name + "^n", r.e_a, f"∥ {g.P}{g.C}", r.n_a * r.e_a),
            r.sine,
            mu_F,
            [RP, RN],
            RC,
            A,
        )
        return GroupForces(g, {g.a: A, g.b: B}, (RP, RN, RC, RCb), eqs, plan, abs(r.sine))
    if kind == DyadKind.RPR:
        P, Q, u = geo["P"], geo["Q"], geo["u"]
        kP, kQ = kp[g.P], kp[g.Q]
        _singular(r.sine, g, sol, f"the guide of link {g.b} and the line {g.Q}{g.P}")
        RP = Reaction(_name(kP, g.a), kP, g.a, "revolute", g.P, P, r.R_P)
        RQ = Reaction(_name(kQ, g.b), kQ, g.b, "revolute", g.Q, Q, r.R_Q)
        at = _contact(P, u, r.m_a, r.nu)
        RN = Reaction(_name(g.b, g.a), g.b, g.a, "prismatic", None, at, r.N)
        RNb = Reaction(_name(g.a, g.b), g.a, g.b, "prismatic", None, at, -r.N)
        eqs = (_group_equation(A, B, g, Q, P, r.w, r.nu),)
        plan = vector_plan(
            [(RP.name, "reaction", r.R_P), *_vectors(A), *_vectors(B)], (RQ.name, r.R_Q), mu_F, RN, A
        )
        return GroupForces(g, {g.a: A, g.b: B}, (RP, RN, RNb, RQ), eqs, plan, 1.0)
    if kind == DyadKind.PRP:
        C, u1, u2 = geo["C"], geo["u1"], geo["u2"]
        g1, g2 = g.s1.guide, g.s2.guide
        _singular(r.sine, g, sol, f"the lines ⊥ {g1.label} and ⊥ {g2.label}")
        R1 = Reaction(
            _name(g1.link, g.a), g1.link, g.a, "prismatic", None, _contact(C, u1, r.m_a, r.nu1), r.N1
        )
        R2 = Reaction(
            _name(g2.link, g.b), g2.link, g.b, "prismatic", None, _contact(C, u2, r.m_b, r.nu2), r.N2
        )
        RC = Reaction(_name(g.b, g.a), g.b, g.a, "revolute", g.C, C, r.R_C)
        RCb = Reaction(_name(g.a, g.b), g.a, g.b, "revolute", g.C, C, -r.R_C)
        plan = closed_plan(
            [*_vectors(A), *_vectors(B)],
            (R2.name, r.w2, f"⊥ {g2.label}", r.N2),
            (R1.name, r.w1, f"⊥ {g1.label}", r.N1),
            r.sine,
            mu_F,
            [R1, R2],
            RC,
            A,
        )
        return GroupForces(g, {g.a: A, g.b: B}, (R1, R2, RC, RCb), (), plan, abs(r.sine))
    P, us, u, B0 = geo["P"], geo["us"], geo["u"], geo["B0"]
    kP, gin, gout = kp[g.P], g.s1.guide, g.s2.guide
    k = gout.link
    _singular(r.sine, g, sol, f"the lines ⊥ {gin.label} and ⊥ {gout.label}")
    RP = Reaction(_name(kP, g.a), kP, g.a, "revolute", g.P, P, r.R_P)
    RN1 = Reaction(_name(g.b, g.a), g.b, g.a, "prismatic", None, _contact(P, us, r.m_a, r.nu1), r.N_ba)
    RN1b = Reaction(_name(g.a, g.b), g.a, g.b, "prismatic", None, RN1.at, -r.N_ba)
    RN2 = Reaction(_name(k, g.b), k, g.b, "prismatic", None, _contact(B0, u, -r.couple, r.nu2), r.N_kb)
    plan = yoke_plan(
        _vectors(B),
        (RN2.name, r.w, f"⊥ {gout.label}", r.N_kb),
        (RN1b.name, r.ws, f"⊥ {gin.label}", -r.N_ba),
        _vectors(A),
        RP,
        r.sine,
        mu_F,
    )
    return GroupForces(g, {g.a: A, g.b: B}, (RP, RN1, RN1b, RN2), (), plan, abs(r.sine))


def _singular(sine, g: Group, sol: Solution, lines: str) -> None:
    if not abs(sine) > 1e-10:
        raise SingularPlanError(
            f"{g.label}: {lines} are parallel: the force plan has no unique solution "
            "at this position (a dead point)",
            sine=abs(sine),
            source=sol.mechanism.source,
        )


def _contact(X, u, m, nu):
    """Where a slide's normal force ν·(i·u) acts on the line X + s·u: s·ν = −m; None where
    ν is rounding of 0 (no force, no line)."""
    if abs(nu) <= NOISE * max(abs(m), 1.0):
        return None
    return X + (-m / nu) * u


def _vectors(loads) -> list[tuple[str, str, complex]]:
    """The forces of ``loads`` as vectors of a force plan (couples have none)."""
    return [
        (ld.name, "load" if ld.kind != "reaction" else "reaction", complex(ld.force))
        for ld in loads
        if ld.force != 0
    ]


def _arm(name, X, at, force, couple) -> Arm:
    size = abs(force)
    mo = cross(at - X, force) + couple
    if size == 0:
        return Arm(name, abs(couple), 0.0, couple)
    return Arm(name, size, abs(cross(at - X, force)) / size, mo)


def _equation(loads, link, about, X, unknown, at, direction, value) -> Equation:
    """ΣM_X(link) = 0: each load's arm and moment, and the unknown's (``value`` along
    ``direction`` through ``at``)."""
    terms = tuple(_arm(ld.name, X, ld.at, ld.force, ld.moment) for ld in loads)
    arm = abs(cross(at - X, direction))
    return Equation(link, about, terms, unknown, arm, value)


def _group_equation(A, B, g, Q, P, w, nu) -> Equation:
    """The slotted link's group about Q: the guide's force on the block N = ν·w (⊥ the
    guide, through the block) from ΣM_Q = 0: ν·(QP × w) = ΣM_Q(link b) + ΣM_P(block)."""
    terms = tuple(_arm(ld.name, Q, ld.at, ld.force, ld.moment) for ld in B)
    terms += tuple(_arm(ld.name, P, ld.at, ld.force, ld.moment) for ld in A)
    return Equation(g.b, g.Q, terms, "N", cross(P - Q, w), nu)


def residual(fa: ForceAnalysis) -> float:
    """The largest |Σ F| or |Σ M| left on any moving link by the reactions found, over the
    largest load (N, N·m): rounding only, where every link is in equilibrium."""
    worst = 0.0
    for gf in fa.groups:
        for lid in (gf.group.a, gf.group.b):
            terms = [ld.term for ld in gf.loads[lid]]
            for r in gf.reactions:
                if r.on == lid and r.at is not None:
                    terms.append((r.at, r.value, 0.0))
            worst = max(worst, abs(K.resultant(terms)), abs(K.moment(terms, 0j)))
    pivot = fa.solution.positions[fa.mechanism.driver.pivot]
    terms = [ld.term for ld in fa.crank_loads] + [(pivot, fa.R01, fa.M_y)]
    worst = max(worst, abs(K.resultant(terms)), abs(K.moment(terms, 0j)))
    big = max([abs(ld.force) for ld in fa.loads] + [abs(ld.moment) for ld in fa.loads] + [1e-300])
    return worst / big
