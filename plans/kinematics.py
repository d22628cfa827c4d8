"""Group-by-group solution of positions, velocity plans and acceleration plans.

Every formula works on numpy arrays of crank angles at once, and the same code serves the
single-position plan (an array of one angle, whose recorded constructions become the plan
points) and the whole cycle. For each group the velocity and the acceleration of its new
point come from the intersection of two lines, exactly as on paper:

    RRR  V_C  = V_P + V_CP (⊥ CP)          = V_Q + V_CQ (⊥ CQ)
    RRP  V_C  = V_P + V_CP (⊥ CP)          = V_Ck + V_CCk (∥ guide)
    RPR  V_P3 = V_P + V_P3P (∥ guide)      = V_Q + V_P3Q (⊥ QP)
    PRP  V_C  = V_Ck + V_CCk (∥ guide 1)   = V_Cm + V_CCm (∥ guide 2)
    RPP  V_P3 = V_P + V_P3P (∥ guide 1)    = V_Pk + V_P3Pk (∥ guide 2)

and for accelerations the same lines, shifted by the known normal components
a^n = −ω²·r (towards the centre) and the Coriolis components a^k = 2ω × V_rel (the
relative velocity turned by 90° in the sense of the guide's ω).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace
from typing import NamedTuple

import numpy as np

from . import kernels
from .errors import AssemblyError, InputError, PlansError, SingularPlanError
from .geometry import cross
from .mechanism import Guide, Mechanism
from .structure import DyadKind, Group, Structure, analyse

#: below this |sin| of the angle between the two lines a plan is singular
SINGULAR_SINE = 1e-10
#: below this |sin| (about 2°) a position is reported as near-singular
WARN_SINE = 0.035


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


def _state(origin, rotor, X, vX, aX, omega, eps) -> LinkState:
    """The state of a link from one of its points X with known velocity and acceleration."""
    r = origin - X
    return LinkState(
        origin, rotor, vX + 1j * omega * r, omega, aX + (1j * eps - omega**2) * r, eps
    )


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

    def failure(self, k: int, phi_deg: float, note: str = "") -> PlansError:
        """The error for angle index ``k`` where the group does not close.

        A group that misses (its links do not reach) is an :class:`AssemblyError` with the
        distance it misses by; one exactly at the limit (links in line, parallel guides,
        a pivot on the pin) is a dead point: a :class:`SingularPlanError`.
        """
        label = self.group.label
        if bool(self.singular[k]):
            return SingularPlanError(
                f"{label} at φ1 = {phi_deg:.6g}°: {self.why_singular}: a singular position "
                f"(dead point), the plan has no unique solution{note}"
            )
        return AssemblyError(
            f"{label} cannot be assembled at φ1 = {phi_deg:.6g}°: needs {self.admissible}, "
            f"misses by {float(self.gap[k]):.6g} m{note}",
            group=label, phi_deg=phi_deg,
        )


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
    def min_sine(self) -> np.ndarray:
        """Conditioning: the smallest |sin| between intersected lines over the groups."""
        out = np.ones_like(self.phi)
        for g in self.groups:
            out = np.minimum(out, np.abs(g.velocity.sine))
        return out


def coincident_name(point: str, link: int) -> str:
    return f"{point}{link}"


class Solver:
    """Solves one mechanism; branches fixed once at its given crank angle."""

    def __init__(self, mech: Mechanism, structure: Structure | None = None,
                 sigmas: tuple[int, ...] | None = None):
        self.mech = mech
        self.structure = structure or analyse(mech)
        self.sigmas = sigmas if sigmas is not None else choose_branches(mech, self.structure)
        #: what follows from the mechanism alone, worked out once: the groups' words,
        #: the plans' recipes, the extent of the cycle (``plans.plan``)
        self.cache: dict = {}
        self.steps = tuple((SOLVERS[g.kind], g, sigma)
                           for g, sigma in zip(self.structure.groups, self.sigmas, strict=True))

    # -------------------------------------------------------------------------------
    def solve(self, phi) -> Motion:
        """Every point and link at the crank angles ``phi`` (rad from +x, any shape).

        Where a group does not close, ``valid`` is False and the values there are
        meaningless (never shown): numpy's warnings for them are silenced here.
        """
        with np.errstate(all="ignore"):
            phi = np.atleast_1d(np.asarray(phi, dtype=float))
            zero = np.zeros_like(phi)
            return self._solve(kernels.ARRAY, phi, zero, np.exp(1j * phi))

    def sweep(self, phi, **options):
        """Every point and link at many angles, without the recorded constructions:
        the same kernels block by block (:func:`plans.sweep.sweep`), for bulk work."""
        from . import sweep

        return sweep.sweep(self, phi, **options)

    def solve_one(self, phi: float) -> Motion:
        """The same recorded solution at one crank angle, on Python numbers.

        Every value in the result is a Python ``complex`` or ``float`` instead of an array
        of one; it is about twenty times faster than :meth:`solve` on one angle. Where
        the mechanism does not close or a plan is singular it raises the error that
        :meth:`solve` would report for that angle.
        """
        phi = float(phi)
        try:
            return self._solve(kernels.SCALAR, phi, 0.0, complex(math.cos(phi), math.sin(phi)))
        except (_Fallback, ArithmeticError, ValueError):
            pass
        m = self.solve(np.array([phi]))
        deg = math.degrees(phi) % 360
        for g in m.groups:
            if not g.valid[0]:
                raise g.failure(0, deg)
        for g in m.groups:
            if abs(float(g.velocity.sine[0])) < SINGULAR_SINE:
                raise SingularPlanError(
                    f"{g.group.label} at φ1 = {deg:.6g}°: the lines of its plan are parallel: "
                    "a singular position (dead point), the plan has no unique solution",
                    sine=float(g.velocity.sine[0]))
        raise SingularPlanError(  # pragma: no cover - every fallback above is a failure
            f"at φ1 = {deg:.6g}°: the plan has no unique solution")

    def _solve(self, xp, phi, zero, rotor) -> Motion:
        mech = self.mech
        drv = mech.driver
        if xp.scalar:  # the frame's part is the same at every angle: copied, not rebuilt
            frame = self.cache.get("scalar frame")
            if frame is None:
                frame = self.cache["scalar frame"] = self._frame(0j, 0.0)
        else:
            frame = self._frame(zero * 0j, zero)
        frame_state, pos, vel, acc, owner = frame
        states: dict[int, LinkState] = {0: frame_state}
        pos, vel, acc, owner = dict(pos), dict(vel), dict(acc), dict(owner)
        zc = frame_state.v
        states[drv.link] = LinkState(zc + mech.frame[drv.pivot], rotor, zc, zero + drv.omega, zc, zero)
        self._fill(drv.link, states, pos, vel, acc, owner)
        solutions = []
        valid = True if xp.scalar else np.ones(phi.shape, dtype=bool)
        coincident: dict[str, str] = {}
        for solve_group, g, sigma in self.steps:
            sol, extra = solve_group(self, xp, g, sigma, states, pos, vel, acc)
            solutions.append(sol)
            if not xp.scalar:
                valid &= sol.valid
            for a in (g.a, g.b):
                self._fill(a, states, pos, vel, acc, owner)
            for name, (link, base) in extra.items():
                X = pos[base]
                st = states[link]
                r = X - st.origin
                pos[name] = X
                vel[name] = st.v + 1j * st.omega * r
                acc[name] = st.a + (1j * st.epsilon - st.omega * st.omega) * r
                owner[name] = link
                coincident[name] = base
        return Motion(phi, states, pos, vel, acc, owner, tuple(solutions), valid, coincident)

    def _frame(self, zc, zero):
        """The frame's state and its points: fixed, at rest."""
        pos = {name: zc + xy for name, xy in self.mech.frame.items()}
        rest = dict.fromkeys(pos, zc)
        return (LinkState(zc, zc + 1, zc, zero, zc, zero), pos, rest, rest,
                dict.fromkeys(pos, 0))

    def _solve_upto(self, count: int) -> Motion:
        """Solve only the first ``count`` groups at the given crank angle (branch choice)."""
        part = Solver(self.mech, replace(self.structure, groups=self.structure.groups[:count]),
                      self.sigmas[:count])
        return part.solve(np.array([self.mech.driver.phi]))

    def _fill(self, lid, states, pos, vel, acc, owner):
        """The points of link ``lid`` that no link solved before it has placed (a group's
        new hinge is placed again here, from the first of its two links)."""
        origin, rotor, v, w, a, e = states[lid]
        jw = kk = None
        for name, local in self.mech.links[lid].points.items():
            if name in owner:
                continue  # a hinge already known from the link solved before
            if jw is None:
                jw, kk = 1j * w, 1j * e - w * w
            r = rotor * local
            pos[name] = origin + r
            vel[name] = v + jw * r
            acc[name] = a + kk * r
            owner[name] = lid

    # helpers used by the group solvers ------------------------------------------------
    def guide_world(self, guide: Guide, states):
        st = states[guide.link]
        return st.pos(guide.point), st.rotor * guide.direction

    def local(self, lid: int, point: str) -> complex:
        return self.mech.links[lid].points[point]


# ---------------------------------------------------------------------------------------
# the five kinds: the kernels' numbers, recorded as the two routes of each construction
# ---------------------------------------------------------------------------------------


class _Fallback(Exception):
    """The one-angle scalar path met a group that does not close or a division by zero:
    the array path then finds and words the failure."""


def _closure(xp, valid, gap, scale):
    """(valid, gap, singular) of a group; the scalar path leaves as soon as it misses."""
    if xp.scalar:
        if not valid:
            raise _Fallback
        return True, 0.0, False
    gap = gap()
    return valid, gap, ~valid & (gap <= 1e-9 * scale)


def _pose_from_two(P, pl, C, cl):
    """Origin and rotor of a link from two world points and their own coordinates."""
    r = (C - P) / (cl - pl)
    r = r / abs(r)
    return P - r * pl, r


def _guide(guide: Guide, states):
    """A world point of the guide, its direction, and the motion of its link there."""
    st = states[guide.link]
    G = st.pos(guide.point)
    u = st.rotor * guide.direction
    if guide.link == 0:
        return G, u, 0j, 0j, None, None
    return G, u, st.vel(G), st.acc(G), st.omega, st.epsilon


def _words(sv: Solver, g: Group, compose, *args) -> dict[str, str]:
    """The names, equations and conditions of a group's constructions, composed once per
    solver: they depend on the mechanism only (``compose(g, *args)``)."""
    key = ("words", id(g))  # the groups live as long as the solver's structure
    got = sv.cache.get(key)
    if got is None:
        got = sv.cache[key] = compose(g, *args)
    return got


def _base_name(point: str, guide: Guide) -> str | None:
    return None if guide.link == 0 else coincident_name(point, guide.link)


def _rrr(sv: Solver, xp, g: Group, sigma, states, pos, vel, acc):
    P, C, Q = g.P, g.C, g.Q
    pl, cl = sv.local(g.a, P), sv.local(g.a, C)
    ql, cl3 = sv.local(g.b, Q), sv.local(g.b, C)
    l2, l3 = abs(cl - pl), abs(cl3 - ql)
    Pw, Qw = pos[P], pos[Q]
    Cw, vC, aC, w2, e2, w3, e3, (d1, d2, t1, t2, s1, s2, nP, nQ, sine, disc, d) = kernels.rrr(
        xp, sigma, l2, l3, Pw, vel[P], acc[P], Qw, vel[Q], acc[Q])
    valid, gap, singular = _closure(
        xp, disc > 0, lambda: np.maximum(np.maximum(d - (l2 + l3), abs(l2 - l3) - d), 0.0), l2 + l3)
    w = _words(sv, g, _rrr_words, l2, l3)
    vroute = (
        Route(P, vel[P], (), d1, w["⊥P"], w["VP"], "relative", t1),
        Route(Q, vel[Q], (), d2, w["⊥Q"], w["VQ"], "relative", t2),
    )
    aroute = (
        Route(P, acc[P], (Term("normal", nP, w["nP"], (C, P)),), d1,
              w["⊥P"], w["tP"], "tangential", s1),
        Route(Q, acc[Q], (Term("normal", nQ, w["nQ"], (C, Q)),), d2,
              w["⊥Q"], w["tQ"], "tangential", s2),
    )
    oa, ra = _pose_from_two(Pw, pl, Cw, cl)
    ob, rb = _pose_from_two(Qw, ql, Cw, cl3)
    states[g.a] = _state(oa, ra, Cw, vC, aC, w2, e2)
    states[g.b] = _state(ob, rb, Cw, vC, aC, w3, e3)
    pos[C] = Cw
    sol = GroupSolution(
        g, Construction(C, vC, vroute, sine, w["veq"]), Construction(C, aC, aroute, sine, w["aeq"]),
        valid, gap, w["admissible"], singular, w["singular"],
    )
    return sol, {}


def _rrr_words(g: Group, l2: float, l3: float) -> dict[str, str]:
    """The names, equations and conditions of an RRR group's constructions (its text
    depends on the mechanism only, so it is composed once)."""
    P, C, Q = g.P, g.C, g.Q
    return {
        "⊥P": f"⊥ {C}{P}", "⊥Q": f"⊥ {C}{Q}", "VP": f"V_{C}{P}", "VQ": f"V_{C}{Q}",
        "nP": f"a^n_{C}{P}", "nQ": f"a^n_{C}{Q}", "tP": f"a^t_{C}{P}", "tQ": f"a^t_{C}{Q}",
        "veq": f"V_{C} = V_{P} + V_{C}{P} = V_{Q} + V_{C}{Q}",
        "aeq": f"a_{C} = a_{P} + a^n_{C}{P} + a^t_{C}{P} = a_{Q} + a^n_{C}{Q} + a^t_{C}{Q}",
        "admissible": f"{P}{Q} within [{abs(l2 - l3):.6g}, {l2 + l3:.6g}] m",
        "singular": f"{P}, {C} and {Q} are in line (links {g.a} and {g.b} stretched out or folded)",
    }


def _rrp(sv: Solver, xp, g: Group, sigma, states, pos, vel, acc):
    P, C, s = g.P, g.C, g.s1
    pl, cl = sv.local(g.a, P), sv.local(g.a, C)
    l2 = abs(cl - pl)
    Pw = pos[P]
    G0, u, vG, aG, wk, ek = _guide(s.guide, states)
    Cw, vC, aC, w2, e2, (d1, t1, t2, s1, s2, nP, vCk, aCk, cor, sine, disc, h) = kernels.rrp(
        xp, sigma, l2, Pw, vel[P], acc[P], G0, u, vG, aG, wk, ek)
    valid, gap, singular = _closure(xp, disc > 0, lambda: np.maximum(h - l2, 0.0), l2)
    k = s.guide.link
    base = _base_name(C, s.guide)
    w = _words(sv, g, _rrp_words, l2)
    vroute = (
        Route(P, vel[P], (), d1, w["⊥P"], w["VP"], "relative", t1),
        Route(base, vCk, (), u, w["∥"], w["Vs"], "sliding", t2),
    )
    terms2 = (Term("coriolis", cor, w["k"], (C, base)),) if base else ()
    aroute = (
        Route(P, acc[P], (Term("normal", nP, w["nP"], (C, P)),), d1,
              w["⊥P"], w["tP"], "tangential", s1),
        Route(base, aCk, terms2, u, w["∥"], w["as"], "sliding", s2),
    )
    oa, ra = _pose_from_two(Pw, pl, Cw, cl)
    states[g.a] = _state(oa, ra, Cw, vC, aC, w2, e2)
    kb = states[k]
    ob = Cw - u * sv.local(g.b, C)
    states[g.b] = _state(ob, u, Cw, vC, aC, kb.omega, kb.epsilon)
    pos[C] = Cw
    sol = GroupSolution(
        g, Construction(C, vC, vroute, sine, w["veq"]), Construction(C, aC, aroute, sine, w["aeq"]),
        valid, gap, w["admissible"], singular, w["singular"],
    )
    extra = {base: (k, C)} if base else {}
    return sol, extra


def _rrp_words(g: Group, l2: float) -> dict[str, str]:
    P, C, gl = g.P, g.C, g.s1.guide.label
    base = _base_name(C, g.s1.guide)
    second = f"V_{base} + V_{C}{base}" if base else f"V_{C}(∥ {gl})"
    asecond = f"a_{base} + a^k_{C}{base} + a^r_{C}{base}" if base else f"a_{C}(∥ {gl})"
    return {
        "⊥P": f"⊥ {C}{P}", "VP": f"V_{C}{P}", "∥": f"∥ {gl}",
        "Vs": f"V_{C}{base}" if base else f"V_{C}", "k": f"a^k_{C}{base}",
        "nP": f"a^n_{C}{P}", "tP": f"a^t_{C}{P}",
        "as": f"a^r_{C}{base}" if base else f"a_{C}",
        "veq": f"V_{C} = V_{P} + V_{C}{P} = {second}",
        "aeq": f"a_{C} = a_{P} + a^n_{C}{P} + a^t_{C}{P} = {asecond}",
        "admissible": f"distance from {P} to the guide {gl} ≤ {l2:.6g} m",
        "singular": f"{P}{C} is perpendicular to the guide {gl}",
    }


def _rpr(sv: Solver, xp, g: Group, sigma, states, pos, vel, acc):
    P, Q, s = g.P, g.Q, g.s1  # block g.a hinged at P slides on the guide of link g.b
    G = g.b
    q = sv.local(G, Q)
    gd = s.guide.direction
    e = (gd.conjugate() * (s.guide.point - q)).imag  # offset of the guide from the pivot Q
    Pw, Qw = pos[P], pos[Q]
    rG, u, vP3, aP3, w3, e3, (d2, t1, t2, s1, s2, cor, nQ, sine, disc, dist) = kernels.rpr(
        xp, sigma, e, gd, Pw, vel[P], acc[P], Qw, vel[Q], acc[Q])
    valid, gap, singular = _closure(
        xp, disc > 0 and dist > 0 if xp.scalar else (disc > 0) & (dist > 0),
        lambda: np.maximum(abs(e) - dist, 0.0), max(abs(e), 1.0) if e else 1.0)
    name = coincident_name(P, G)
    w = _words(sv, g, _rpr_words, e)
    vroute = (
        Route(P, vel[P], (), u, w["∥"], w["VP"], "sliding", t1),
        Route(Q, vel[Q], (), d2, w["⊥Q"], w["VQ"], "relative", t2),
    )
    aroute = (
        Route(P, acc[P], (Term("coriolis", cor, w["k"], (name, P)),), u,
              w["∥"], w["rP"], "sliding", s1),
        Route(Q, acc[Q], (Term("normal", nQ, w["nQ"], (name, Q)),), d2,
              w["⊥Q"], w["tQ"], "tangential", s2),
    )
    states[G] = _state(Qw - rG * q, rG, Pw, vP3, aP3, w3, e3)
    oK = Pw - u * sv.local(g.a, P)
    states[g.a] = _state(oK, u, Pw, vel[P], acc[P], w3, e3)
    sol = GroupSolution(
        g, Construction(name, vP3, vroute, sine, w["veq"]),
        Construction(name, aP3, aroute, sine, w["aeq"]),
        valid, gap, w["admissible"], singular, w["singular"],
    )
    return sol, {name: (G, P)}


def _rpr_words(g: Group, e: float) -> dict[str, str]:
    P, Q, G, gl = g.P, g.Q, g.b, g.s1.guide.label
    name = coincident_name(P, G)
    return {
        "∥": f"∥ {gl}", "VP": f"V_{name}{P}", "⊥Q": f"⊥ {Q}{name}", "VQ": f"V_{name}{Q}",
        "k": f"a^k_{name}{P}", "rP": f"a^r_{name}{P}", "nQ": f"a^n_{name}{Q}",
        "tQ": f"a^t_{name}{Q}",
        "veq": f"V_{name} = V_{P} + V_{name}{P} = V_{Q} + V_{name}{Q}",
        "aeq": f"a_{name} = a_{P} + a^k_{name}{P} + a^r_{name}{P} = "
               f"a_{Q} + a^n_{name}{Q} + a^t_{name}{Q}",
        "admissible": f"distance {Q}{P} > {abs(e):.6g} m (the guide's offset)" if e else f"{Q} ≠ {P}",
        "singular": (
            f"the guide of link {G} is tangent to the pin {P} at its offset {abs(e):.6g} m from {Q}"
            if e else f"the pivot {Q} is on the block's pin {P}: the guide's direction is undetermined"),
    }


def _prp(sv: Solver, xp, g: Group, sigma, states, pos, vel, acc):
    C, sa, sb = g.C, g.s1, g.s2
    G1, u1, vG1, aG1, w1, e1 = _guide(sa.guide, states)
    G2, u2, vG2, aG2, w2, e2 = _guide(sb.guide, states)
    Cw, vC, aC, (v1, v2, a1, a2, c1, c2, t1, t2, s1, s2, sine) = kernels.prp(
        xp, G1, u1, vG1, aG1, w1, e1, G2, u2, vG2, aG2, w2, e2)
    good = abs(sine) > SINGULAR_SINE
    if xp.scalar:
        _closure(xp, good, None, 1.0)
    b1, b2 = _base_name(C, sa.guide), _base_name(C, sb.guide)
    vroute = (
        Route(b1, v1, (), u1, f"∥ {sa.guide.label}", f"V_{C}{b1 or ''}", "sliding", t1),
        Route(b2, v2, (), u2, f"∥ {sb.guide.label}", f"V_{C}{b2 or ''}", "sliding", t2),
    )
    terms1 = (Term("coriolis", c1, f"a^k_{C}{b1}", (C, b1)),) if b1 else ()
    terms2 = (Term("coriolis", c2, f"a^k_{C}{b2}", (C, b2)),) if b2 else ()
    aroute = (
        Route(b1, a1, terms1, u1, f"∥ {sa.guide.label}", f"a^r_{C}{b1 or ''}", "sliding", s1),
        Route(b2, a2, terms2, u2, f"∥ {sb.guide.label}", f"a^r_{C}{b2 or ''}", "sliding", s2),
    )
    for lid, u, s in ((g.a, u1, sa), (g.b, u2, sb)):
        k = states[s.guide.link]
        states[lid] = _state(Cw - u * sv.local(lid, C), u, Cw, vC, aC, k.omega, k.epsilon)
    pos[C] = Cw
    sol = GroupSolution(
        g,
        Construction(C, vC, vroute, sine, f"V_{C} = V_{b1 or '0'} + V_{C}{b1 or ''} = V_{b2 or '0'} + V_{C}{b2 or ''}"),
        Construction(C, aC, aroute, sine, f"a_{C} = a_{b1 or '0'} + a^k + a^r = a_{b2 or '0'} + a^k + a^r"),
        *((True, 0.0) if xp.scalar else (good, np.zeros(np.shape(Cw)))),
        "the two guides not parallel", False if xp.scalar else ~good,
        f"the guides {sa.guide.label} and {sb.guide.label} are parallel: the hinge {C} is not fixed",
    )
    extra = {b: (s.guide.link, C) for b, s in ((b1, sa), (b2, sb)) if b}
    return sol, extra


def _rpp(sv: Solver, xp, g: Group, sigma, states, pos, vel, acc):
    P, s_in, s_out = g.P, g.s1, g.s2  # block g.a at P slides along s_in carried by g.b
    B = g.b
    Gk, uk, vG, aG, wk, ek = _guide(s_out.guide, states)
    locD = sv.local(B, s_out.point)
    gd = s_in.guide.direction
    if abs(gd.imag) <= SINGULAR_SINE:
        if xp.scalar:
            raise _Fallback
        gd = 1j  # placeholder direction: every angle is reported as not closing
    Pw = pos[P]
    oB, us, vP3, aP3, (vk, ak, c1, c2, t1, t2, s1, s2, sine) = kernels.rpp(
        xp, Pw, vel[P], acc[P], Gk, uk, vG, aG, wk, ek, locD, s_in.guide.point, gd)
    good = abs(s_in.guide.direction.imag) > SINGULAR_SINE
    name = coincident_name(P, B)
    bk = _base_name(P, s_out.guide)
    vroute = (
        Route(P, vel[P], (), us, f"∥ {s_in.guide.label}", f"V_{name}{P}", "sliding", t1),
        Route(bk, vk, (), uk, f"∥ {s_out.guide.label}", f"V_{name}{bk or ''}", "sliding", t2),
    )
    terms1 = (Term("coriolis", c1, f"a^k_{name}{P}", (name, P)),) if c1 is not None else ()
    terms2 = (Term("coriolis", c2, f"a^k_{name}{bk}", (name, bk)),) if bk else ()
    aroute = (
        Route(P, acc[P], terms1, us, f"∥ {s_in.guide.label}", f"a^r_{name}{P}", "sliding", s1),
        Route(bk, ak, terms2, uk, f"∥ {s_out.guide.label}", f"a^r_{name}{bk or ''}", "sliding", s2),
    )
    kst = states[s_out.guide.link]
    states[B] = _state(oB, uk, Pw, vP3, aP3, kst.omega, kst.epsilon)
    states[g.a] = _state(Pw - us * sv.local(g.a, P), us, Pw, vel[P], acc[P], kst.omega, kst.epsilon)
    shape = np.shape(Pw)
    sol = GroupSolution(
        g,
        Construction(name, vP3, vroute, sine, f"V_{name} = V_{P} + V_{name}{P} = V_{bk or '0'} + V_{name}{bk or ''}"),
        Construction(name, aP3, aroute, sine, f"a_{name} = a_{P} + a^k + a^r = a_{bk or '0'} + a^k + a^r"),
        *((True, 0.0) if xp.scalar else (np.full(shape, good), np.zeros(shape))),
        "the two guides not parallel", False if xp.scalar else np.full(shape, not good),
        f"the guide {s_in.guide.label} of link {B} is parallel to the guide "
        f"{s_out.guide.label}: the yoke's position is not fixed",
    )
    extra = {name: (B, P)}
    if bk:
        extra[bk] = (s_out.guide.link, P)
    return sol, extra

SOLVERS = {
    DyadKind.RRR: _rrr,
    DyadKind.RRP: _rrp,
    DyadKind.RPR: _rpr,
    DyadKind.PRP: _prp,
    DyadKind.RPP: _rpp,
}

# ---------------------------------------------------------------------------------------
# assembly branches from human-readable hints
# ---------------------------------------------------------------------------------------

RELATIONS = ("above", "below", "left of", "right of")


def parse_hint(hint: str, names: list[str]) -> tuple[str, list[str]]:
    """``"above BD"`` → ("above", ["B", "D"]); ``"right of C"`` → ("right of", ["C"])."""
    text = " ".join(hint.strip().split())
    for rel in RELATIONS:
        if text.startswith(rel + " "):
            rest = text[len(rel) + 1 :].replace("line ", "").replace("-", "").replace(" ", "")
            refs: list[str] = []
            while rest:
                match = max((n for n in names if rest.startswith(n)), key=len, default=None)
                if match is None:
                    raise ValueError(f'"{rest}" is not a point name')
                refs.append(match)
                rest = rest[len(match) :]
            if len(refs) not in (1, 2):
                raise ValueError("name one point or a line through two points")
            return rel, refs
    raise ValueError('a hint reads "above BD", "below BD", "left of C" or "right of C"')


def hint_holds(rel: str, X: complex, refs: list[complex]) -> bool:
    if len(refs) == 1:
        Q = refs[0]
        return {"above": X.imag > Q.imag, "below": X.imag < Q.imag,
                "left of": X.real < Q.real, "right of": X.real > Q.real}[rel]
    Q, R = refs
    d = R - Q
    if rel in ("above", "below"):
        if d.real < 0:
            d = -d
        side = cross(d, X - Q) > 0
        return side if rel == "above" else not side
    if d.imag < 0:
        d = -d
    side = cross(d, X - Q) > 0
    return side if rel == "left of" else not side


def choose_branches(mech: Mechanism, structure: Structure) -> tuple[int, ...]:
    """Turn the file's hints into a sign per group, evaluated at the given crank angle.

    The sign (which side of the line of centres, which way along the guide) is then kept
    over the whole cycle, so the branch stays continuous.
    """
    names = mech.point_names()
    hints = {}
    for key, text in mech.assembly.items():
        try:
            hints[key] = parse_hint(text, names)
        except ValueError as exc:
            raise InputError(mech.source, f"assembly.{key}: {exc}") from None
    used = set()
    sigmas: list[int] = []
    for i, g in enumerate(structure.groups):
        if g.kind in (DyadKind.PRP, DyadKind.RPP):
            sigmas.append(1)
            continue
        group_points = set(mech.links[g.a].points) | set(mech.links[g.b].points)
        mine = {k: h for k, h in hints.items() if k in group_points}
        ok = []
        positions = {}
        for sigma in (1, -1):
            trial = Solver(mech, structure, tuple(sigmas) + (sigma,) + (1,) * (len(structure.groups) - i - 1))
            motion = trial._solve_upto(i + 1)
            positions[sigma] = motion
            if not motion.valid[0]:
                continue
            if all(
                hint_holds(rel, complex(motion.position[k][0]),
                           [complex(motion.position[r][0]) for r in refs if r in motion.position])
                for k, (rel, refs) in mine.items()
            ):
                ok.append(sigma)
        used |= set(mine)
        if len(ok) == 1:
            sigmas.append(ok[0])
            continue
        if g.kind == DyadKind.RPR and not mine:
            sigmas.append(1)  # the guide's axis points from its pivot towards the block
            continue
        phi = np.degrees(mech.driver.phi)
        if not positions[1].valid[0]:
            earlier = sorted(used - set(mine))
            note = ""
            if earlier:
                asked = ", ".join(f"{k} = {mech.assembly[k]!r}" for k in earlier)
                note = f" (the groups before it are assembled as the hints {asked} ask: is one of them wrong?)"
            raise positions[1].groups[i].failure(0, phi, note)
        new = g.C or coincident_name(g.P, g.b)
        key = g.C or next(iter(mech.links[g.b].points))
        if not mine:
            cands = []
            for sigma in (1, -1):
                X = complex(positions[sigma].position[key][0])
                cands.append(f"({X.real:.4g}, {X.imag:.4g})")
            raise InputError(
                mech.source,
                f"assembly: {g.label} closes two ways at φ1 = {phi:.6g}°, with {key} at "
                f"{cands[0]} or {cands[1]}: add a hint such as [assembly] {key} = "
                f'"above {g.P or ""}{g.Q or ""}"',
            )
        raise InputError(
            mech.source,
            f"assembly: the hints {', '.join(f'{k} = {mech.assembly[k]!r}' for k in mine)} "
            f"{'fit neither' if not ok else 'fit both'} assembly of {g.label} "
            f"at φ1 = {phi:.6g}° (new point {new})",
        )
    unused = set(hints) - used
    if unused:
        k = sorted(unused)[0]
        raise InputError(mech.source, f"assembly.{k}: {k} is not a point of a group with two assemblies")
    return tuple(sigmas)

