"""The five group solvers that record: each runs its kernel (``plans/kernels.py``) and
records the numbers as the two routes of its velocity and acceleration constructions,
with the names, equations and conditions of the group (composed once per solver).

Each works on numpy arrays of angles or on Python numbers of one angle (``xp``); on one
angle a group that does not close raises :class:`ScalarFallback`, and the array path
words the error.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from . import kernels
from .mechanism import Guide
from .records import (
    SINGULAR_SINE,
    Construction,
    GroupSolution,
    Route,
    Term,
    coincident_name,
    state_from,
)
from .structure import DyadKind, Group

if TYPE_CHECKING:
    from .kinematics import Solver


class ScalarFallback(Exception):
    """The one-angle scalar path met a group that does not close or a division by zero:
    the array path then finds and words the failure."""


def _closure(xp, valid, gap, scale):
    """(valid, gap, singular) of a group; the scalar path leaves as soon as it misses."""
    if xp.scalar:
        if not valid:
            raise ScalarFallback
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
    states[g.a] = state_from(oa, ra, Cw, vC, aC, w2, e2)
    states[g.b] = state_from(ob, rb, Cw, vC, aC, w3, e3)
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
    states[g.a] = state_from(oa, ra, Cw, vC, aC, w2, e2)
    kb = states[k]
    ob = Cw - u * sv.local(g.b, C)
    states[g.b] = state_from(ob, u, Cw, vC, aC, kb.omega, kb.epsilon)
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
    states[G] = state_from(Qw - rG * q, rG, Pw, vP3, aP3, w3, e3)
    oK = Pw - u * sv.local(g.a, P)
    states[g.a] = state_from(oK, u, Pw, vel[P], acc[P], w3, e3)
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
        states[lid] = state_from(Cw - u * sv.local(lid, C), u, Cw, vC, aC, k.omega, k.epsilon)
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
            raise ScalarFallback
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
    states[B] = state_from(oB, uk, Pw, vP3, aP3, kst.omega, kst.epsilon)
    states[g.a] = state_from(Pw - us * sv.local(g.a, P), us, Pw, vel[P], acc[P], kst.omega, kst.epsilon)
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
