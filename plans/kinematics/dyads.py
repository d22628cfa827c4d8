"""The five dyad kinds, one table: per kind its kernel, its setup, its recorded step and its
bulk step, and what they say.

Everything that differs from one kind of class-II group to another is here, one section
per kind; the rest of the kinematics reads :data:`DYADS` instead of listing the kinds
again. For each kind:

* ``kernel`` (:mod:`plans.kinematics.kernels`): the formulas, shared by both paths;
* ``setup(mech, translating, g)``: what the group's solution needs of the mechanism only,
  worked out once per solver (:class:`plans.kinematics.setup.Setup`): its points' own
  coordinates, link lengths and guide offsets, and the names, equations and conditions
  of its constructions;
* ``recorded(xp, g, w, sigma, states, pos, vel, acc, translating)``: the kernel run and
  its numbers recorded as the two routes of each construction
  (:class:`plans.kinematics.groups.Recorded`); it returns the group's solution and the
  points it found on another link (coincident points);
* ``bulk(b, g, w, sigma)``: the kernel run on a block of angles keeping the results only
  (:class:`plans.kinematics.sweep.Block`); it returns the coincident points;
* ``assemblies``: whether the group closes two ways, so that a sign (a hint) chooses;
* ``coincident``: the keys of the setup that name the coincident points it adds.

A coincident point is (name, the link it belongs to, the point it is under, its
velocity, its acceleration).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import NamedTuple

import numpy as np

from plans.kinematics import kernels
from plans.kinematics.groups import (
    CLOSED,
    closure,
    guide_motion,
    never_misses,
    one_closes,
    pose_from_two,
    solution,
)
from plans.kinematics.kernels import ARRAY, record
from plans.kinematics.records import Route, Term, coincident_name, state_from
from plans.model import Guide, Mechanism
from plans.model.structure import DyadKind, Group


class Dyad(NamedTuple):
    """One dyad kind's row of :data:`DYADS`."""

    kind: DyadKind
    kernel: Callable
    setup: Callable[[Mechanism, frozenset[int], Group], dict]
    recorded: Callable
    bulk: Callable
    assemblies: bool
    coincident: tuple[str, ...]


# ---------------------------------------------------------------------------------------
# the words of the equations
# ---------------------------------------------------------------------------------------


def equation(lhs: str, *sides) -> str:
    """A vector equation as written on paper: "V_C = V_B + V_CB = V_D + V_CD". A side is
    a sum, or a (sum, direction) pair from :func:`_slide`; a fixed guide's side is no sum,
    only a direction, said apart: "V_D = V_C + V_DC; V_D ∥ x-x".

    >>> equation("V_D", "V_C + V_DC", (None, "V_D ∥ x-x"))
    'V_D = V_C + V_DC; V_D ∥ x-x'
    """
    sums, dirs = [], []
    for side in sides:
        total, direction = side if isinstance(side, tuple) else (side, None)
        sums += [total] if total else []
        dirs += [direction] if direction else []
    return "; ".join(([f"{lhs} = {' = '.join(sums)}"] if sums else []) + dirs)


def _coriolis(translating: frozenset[int], link: int, term: str) -> str:
    """" + a^k_…" where the guide's ``link`` turns; nothing on one that translates."""
    return "" if link in translating else f" + {term}"


def _base_name(point: str, guide: Guide) -> str | None:
    return None if guide.link == 0 else coincident_name(point, guide.link)


def _slide(translating: frozenset[int], sym: str, C: str, base: str | None, guide: Guide) -> tuple:
    """One side of an equation for C sliding along ``guide``, as (sum, direction): from
    the coincident point ``base`` of the guide's link, with the Coriolis term where that
    link turns ("V_C4 + V_CC4", "a_C4 + a^k_CC4 + a^r_CC4"), or along a fixed guide only
    a direction ("V_C ∥ x-x")."""
    if base is None:
        return None, f"{sym}_{C} {guide.along}"
    if sym == "V":
        return f"V_{base} + V_{C}{base}", None
    return f"a_{base}{_coriolis(translating, guide.link, f'a^k_{C}{base}')} + a^r_{C}{base}", None


def _plus(a, b):
    """a + b, skipping the zero of a fixed point (a Python 0j) instead of adding it."""
    return b if isinstance(a, complex) and a == 0 else a + b


def rigid(vX, aX, r, w, e):
    """Velocity and acceleration of the point X + r of a link moving with X at ω, ε."""
    return _plus(vX, r * (1j * w)), _plus(aX, r * (1j * e - w * w))


# ---------------------------------------------------------------------------------------
# RRR: C on link a (|PC| = l2) and link b (|QC| = l3)


def _rrr_setup(mech: Mechanism, translating: frozenset[int], g: Group) -> dict:
    P, C, Q = g.P, g.C, g.Q
    pl, cl = mech.links[g.a].points[P], mech.links[g.a].points[C]
    ql, cl3 = mech.links[g.b].points[Q], mech.links[g.b].points[C]
    l2, l3 = abs(cl - pl), abs(cl3 - ql)
    return {
        "pl": pl, "cl": cl, "ql": ql, "cl3": cl3, "l2": l2, "l3": l3,
        "⊥P": f"⊥ {C}{P}", "⊥Q": f"⊥ {C}{Q}", "VP": f"V_{C}{P}", "VQ": f"V_{C}{Q}",
        "nP": f"a^n_{C}{P}", "nQ": f"a^n_{C}{Q}", "tP": f"a^t_{C}{P}", "tQ": f"a^t_{C}{Q}",
        "veq": f"V_{C} = V_{P} + V_{C}{P} = V_{Q} + V_{C}{Q}",
        "aeq": f"a_{C} = a_{P} + a^n_{C}{P} + a^t_{C}{P} = a_{Q} + a^n_{C}{Q} + a^t_{C}{Q}",
        "admissible": f"{P}{Q} within [{abs(l2 - l3):.6g}, {l2 + l3:.6g}] m",
        "singular": {"en": f"{P}, {C} and {Q} are in line (links {g.a} and {g.b} stretched out or folded)",
                     "ru": f"{P}, {C} и {Q} на одной прямой (звенья {g.a} и {g.b} вытянуты или сложены)"},
    }


def _rrr(xp, g: Group, w: dict, sigma, states, pos, vel, acc, translating):
    P, C, Q = g.P, g.C, g.Q
    l2, l3 = w["l2"], w["l3"]
    Pw, Qw = pos[P], pos[Q]
    r = kernels.rrr(xp, sigma, l2, l3, Pw, vel[P], acc[P], Qw, vel[Q], acc[Q])
    closed = CLOSED if one_closes(xp, r.closes) else closure(
        r.closes, np.minimum((l2 + l3) - r.d, r.d - abs(l2 - l3)), l2 + l3)
    vroute = (
        record(Route, (P, vel[P], (), r.d1, w["⊥P"], w["VP"], "relative", r.t1)),
        record(Route, (Q, vel[Q], (), r.d2, w["⊥Q"], w["VQ"], "relative", r.t2)),
    )
    aroute = (
        record(Route, (P, acc[P], (record(Term, ("normal", r.nP, w["nP"], (C, P))),), r.d1,
              w["⊥P"], w["tP"], "tangential", r.s1)),
        record(Route, (Q, acc[Q], (record(Term, ("normal", r.nQ, w["nQ"], (C, Q))),), r.d2,
              w["⊥Q"], w["tQ"], "tangential", r.s2)),
    )
    oa, ra = pose_from_two(Pw, w["pl"], r.C, w["cl"])
    ob, rb = pose_from_two(Qw, w["ql"], r.C, w["cl3"])
    states[g.a] = state_from(oa, ra, r.C, r.vC, r.aC, r.w2, r.e2)
    states[g.b] = state_from(ob, rb, r.C, r.vC, r.aC, r.w3, r.e3)
    pos[C] = r.C
    return solution(g, w, C, r.vC, r.aC, vroute, aroute, r.sine, closed), ()


def _rrr_bulk(b, g: Group, w: dict, sigma):
    P, C, Q = g.P, g.C, g.Q
    Pw, Qw = b.pos[P], b.pos[Q]
    r = kernels.rrr(ARRAY, sigma, w["l2"], w["l3"], Pw, b.vel[P], b.acc[P],
                    Qw, b.vel[Q], b.acc[Q])
    b.pos[C], b.vel[C], b.acc[C] = r.C, r.vC, r.aC
    b.links[g.a] = (r.C, r.vC, r.aC, (r.C - Pw) * (1 / (w["cl"] - w["pl"])), r.w2, r.e2, w["cl"])
    b.links[g.b] = (r.C, r.vC, r.aC, (r.C - Qw) * (1 / (w["cl3"] - w["ql"])), r.w3, r.e3,
                    w["cl3"])
    b.close(g.label, r.sine, r.closes)
    return ()


# ---------------------------------------------------------------------------------------
# RRP: C on link a (|PC| = l2) and on the guide the slider b moves along


def _rrp_setup(mech: Mechanism, translating: frozenset[int], g: Group) -> dict:
    P, C, gl, along = g.P, g.C, g.s1.guide.label, g.s1.guide.along
    pl, cl = mech.links[g.a].points[P], mech.links[g.a].points[C]
    l2 = abs(cl - pl)
    base = _base_name(C, g.s1.guide)
    second = _slide(translating, "V", C, base, g.s1.guide)
    asecond = _slide(translating, "a", C, base, g.s1.guide)
    return {
        "pl": pl, "cl": cl, "l2": l2, "cb": mech.links[g.b].points[C], "base": base,
        "⊥P": f"⊥ {C}{P}", "VP": f"V_{C}{P}", "∥": along,
        "Vs": f"V_{C}{base}" if base else f"V_{C}", "k": f"a^k_{C}{base}",
        "nP": f"a^n_{C}{P}", "tP": f"a^t_{C}{P}",
        "as": f"a^r_{C}{base}" if base else f"a_{C}",
        "veq": equation(f"V_{C}", f"V_{P} + V_{C}{P}", second),
        "aeq": equation(f"a_{C}", f"a_{P} + a^n_{C}{P} + a^t_{C}{P}", asecond),
        "admissible": f"distance from {P} to the guide {gl} ≤ {l2:.6g} m",
        "singular": {"en": f"{P}{C} is perpendicular to the guide {gl}",
                     "ru": f"{P}{C} перпендикулярна направляющей {gl}"},
    }


def _rrp(xp, g: Group, w: dict, sigma, states, pos, vel, acc, translating):
    P, C, s = g.P, g.C, g.s1
    l2, base, k = w["l2"], w["base"], s.guide.link
    Pw = pos[P]
    G0, u, vG, aG, wk, ek = guide_motion(s.guide, states, translating)
    r = kernels.rrp(xp, sigma, l2, Pw, vel[P], acc[P], G0, u, vG, aG, wk, ek)
    closed = CLOSED if one_closes(xp, r.closes) else closure(r.closes, l2 - r.h, l2)
    vroute = (
        record(Route, (P, vel[P], (), r.d1, w["⊥P"], w["VP"], "relative", r.t1)),
        record(Route, (base, r.vCk, (), u, w["∥"], w["Vs"], "sliding", r.t2)),
    )
    terms2 = (record(Term, ("coriolis", r.cor, w["k"], (C, base))),) if r.cor is not None else ()
    aroute = (
        record(Route, (P, acc[P], (record(Term, ("normal", r.nP, w["nP"], (C, P))),), r.d1,
              w["⊥P"], w["tP"], "tangential", r.s1)),
        record(Route, (base, r.aCk, terms2, u, w["∥"], w["as"], "sliding", r.s2)),
    )
    oa, ra = pose_from_two(Pw, w["pl"], r.C, w["cl"])
    states[g.a] = state_from(oa, ra, r.C, r.vC, r.aC, r.w2, r.e2)
    kb = states[k]
    states[g.b] = state_from(r.C - u * w["cb"], u, r.C, r.vC, r.aC, kb.omega, kb.epsilon)
    pos[C] = r.C
    found = ((base, k, C, r.vCk, r.aCk),) if base else ()
    return solution(g, w, C, r.vC, r.aC, vroute, aroute, r.sine, closed), found


def _rrp_bulk(b, g: Group, w: dict, sigma):
    P, C, s = g.P, g.C, g.s1
    Pw = b.pos[P]
    G, u, vG, aG, wk, ek = b.guide(s.guide)
    r = kernels.rrp(ARRAY, sigma, w["l2"], Pw, b.vel[P], b.acc[P], G, u, vG, aG, wk, ek)
    b.pos[C], b.vel[C], b.acc[C] = r.C, r.vC, r.aC
    k = b.links[s.guide.link]
    b.links[g.a] = (r.C, r.vC, r.aC, (r.C - Pw) * (1 / (w["cl"] - w["pl"])), r.w2, r.e2, w["cl"])
    b.links[g.b] = (r.C, r.vC, r.aC, u, k[4], k[5], w["cb"])
    b.close(g.label, r.sine, r.closes)
    return ((w["base"], s.guide.link, C, r.vCk, r.aCk),) if s.guide.link else ()


# ---------------------------------------------------------------------------------------
# RPR: the block a hinged at P slides along the guide of link b, hinged at Q


def _rpr_setup(mech: Mechanism, translating: frozenset[int], g: Group) -> dict:
    P, Q, G, s = g.P, g.Q, g.b, g.s1
    gd = s.guide.direction
    q = mech.links[G].points[Q]
    e = (gd.conjugate() * (s.guide.point - q)).imag  # offset of the guide from the pivot Q
    name = coincident_name(P, G)
    return {
        "q": q, "e": e, "gd": gd, "pa": mech.links[g.a].points[P], "name": name,
        "∥": s.guide.along, "VP": f"V_{name}{P}", "⊥Q": f"⊥ {Q}{name}", "VQ": f"V_{name}{Q}",
        "k": f"a^k_{name}{P}", "rP": f"a^r_{name}{P}", "nQ": f"a^n_{name}{Q}",
        "tQ": f"a^t_{name}{Q}",
        "veq": f"V_{name} = V_{P} + V_{name}{P} = V_{Q} + V_{name}{Q}",
        "aeq": f"a_{name} = a_{P} + a^k_{name}{P} + a^r_{name}{P} = "
               f"a_{Q} + a^n_{name}{Q} + a^t_{name}{Q}",
        "admissible": f"distance {Q}{P} > {abs(e):.6g} m (the guide's offset)" if e else f"{Q} ≠ {P}",
        "singular": {
            "en": f"the guide of link {G} is tangent to the pin {P} at its offset {abs(e):.6g} m from {Q}"
            if e else f"the pivot {Q} is on the block's pin {P}: the guide's direction is undetermined",
            "ru": f"направляющая звена {G} касается пальца {P} на своём смещении {abs(e):.6g} м от {Q}"
            if e else f"ось {Q} на пальце камня {P}: направление направляющей не определено"},
    }


def _rpr(xp, g: Group, w: dict, sigma, states, pos, vel, acc, translating):
    P, Q, G = g.P, g.Q, g.b
    e, name = w["e"], w["name"]
    Pw, Qw = pos[P], pos[Q]
    r = kernels.rpr(xp, sigma, e, w["gd"], Pw, vel[P], acc[P], Qw, vel[Q], acc[Q])
    closed = CLOSED if one_closes(xp, r.closes) else closure(
        r.closes, r.dist - abs(e), max(abs(e), 1.0))
    vroute = (
        record(Route, (P, vel[P], (), r.u, w["∥"], w["VP"], "sliding", r.t1)),
        record(Route, (Q, vel[Q], (), r.d2, w["⊥Q"], w["VQ"], "relative", r.t2)),
    )
    aroute = (
        record(Route, (P, acc[P], (record(Term, ("coriolis", r.cor, w["k"], (name, P))),), r.u,
              w["∥"], w["rP"], "sliding", r.s1)),
        record(Route, (Q, acc[Q], (record(Term, ("normal", r.nQ, w["nQ"], (name, Q))),), r.d2,
              w["⊥Q"], w["tQ"], "tangential", r.s2)),
    )
    states[G] = state_from(Qw - r.rot * w["q"], r.rot, Pw, r.vP3, r.aP3, r.w3, r.e3)
    states[g.a] = state_from(Pw - r.u * w["pa"], r.u, Pw, vel[P], acc[P], r.w3, r.e3)
    return (solution(g, w, name, r.vP3, r.aP3, vroute, aroute, r.sine, closed),
            ((name, G, P, r.vP3, r.aP3),))


def _rpr_bulk(b, g: Group, w: dict, sigma):
    P, Q = g.P, g.Q
    Pw, Qw = b.pos[P], b.pos[Q]
    vP, aP = b.vel[P], b.acc[P]
    r = kernels.rpr(ARRAY, sigma, w["e"], w["gd"], Pw, vP, aP, Qw, b.vel[Q], b.acc[Q])
    b.links[g.b] = (Qw, b.vel[Q], b.acc[Q], r.rot, r.w3, r.e3, w["q"])
    b.links[g.a] = (Pw, vP, aP, r.u, r.w3, r.e3, w["pa"])
    b.close(g.label, r.sine, r.closes)
    return ((w["name"], g.b, P, r.vP3, r.aP3),)


# ---------------------------------------------------------------------------------------
# PRP: C slides on the guide of link a's carrier and on that of link b's


def _prp_setup(mech: Mechanism, translating: frozenset[int], g: Group) -> dict:
    C, sa, sb = g.C, g.s1, g.s2
    b1, b2 = _base_name(C, sa.guide), _base_name(C, sb.guide)
    l1, l2 = sa.guide.label, sb.guide.label
    return {
        "ca": mech.links[g.a].points[C], "cb": mech.links[g.b].points[C], "b1": b1, "b2": b2,
        "∥1": sa.guide.along, "∥2": sb.guide.along, "V1": f"V_{C}{b1 or ''}",
        "V2": f"V_{C}{b2 or ''}", "k1": f"a^k_{C}{b1}", "k2": f"a^k_{C}{b2}",
        "r1": f"a^r_{C}{b1}" if b1 else f"a_{C}", "r2": f"a^r_{C}{b2}" if b2 else f"a_{C}",
        "veq": equation(f"V_{C}", _slide(translating, "V", C, b1, sa.guide),
                        _slide(translating, "V", C, b2, sb.guide)),
        "aeq": equation(f"a_{C}", _slide(translating, "a", C, b1, sa.guide),
                        _slide(translating, "a", C, b2, sb.guide)),
        "admissible": "the two guides not parallel",
        "singular": {"en": f"the guides {l1} and {l2} are parallel: the hinge {C} is not fixed",
                     "ru": f"направляющие {l1} и {l2} параллельны: шарнир {C} не определён"},
    }


def _prp(xp, g: Group, w: dict, sigma, states, pos, vel, acc, translating):
    C, sa, sb = g.C, g.s1, g.s2
    b1, b2 = w["b1"], w["b2"]
    G1, u1, vG1, aG1, w1, e1 = guide_motion(sa.guide, states, translating)
    G2, u2, vG2, aG2, w2, e2 = guide_motion(sb.guide, states, translating)
    r = kernels.prp(xp, G1, u1, vG1, aG1, w1, e1, G2, u2, vG2, aG2, w2, e2)
    closed = CLOSED if one_closes(xp, r.closes) else never_misses(r.closes, np.shape(r.C))
    vroute = (
        record(Route, (b1, r.v1, (), u1, w["∥1"], w["V1"], "sliding", r.t1)),
        record(Route, (b2, r.v2, (), u2, w["∥2"], w["V2"], "sliding", r.t2)),
    )
    terms1 = (record(Term, ("coriolis", r.c1, w["k1"], (C, b1))),) if r.c1 is not None else ()
    terms2 = (record(Term, ("coriolis", r.c2, w["k2"], (C, b2))),) if r.c2 is not None else ()
    aroute = (
        record(Route, (b1, r.a1, terms1, u1, w["∥1"], w["r1"], "sliding", r.s1)),
        record(Route, (b2, r.a2, terms2, u2, w["∥2"], w["r2"], "sliding", r.s2)),
    )
    for lid, u, s, own in ((g.a, u1, sa, w["ca"]), (g.b, u2, sb, w["cb"])):
        k = states[s.guide.link]
        states[lid] = state_from(r.C - u * own, u, r.C, r.vC, r.aC, k.omega, k.epsilon)
    pos[C] = r.C
    found = tuple((b, s.guide.link, C, v, a)
                  for b, s, v, a in ((b1, sa, r.v1, r.a1), (b2, sb, r.v2, r.a2)) if b)
    return solution(g, w, C, r.vC, r.aC, vroute, aroute, r.sine, closed), found


def _prp_bulk(b, g: Group, w: dict, sigma):
    C, sa, sb = g.C, g.s1, g.s2
    G1, u1, vG1, aG1, w1, e1 = b.guide(sa.guide)
    G2, u2, vG2, aG2, w2, e2 = b.guide(sb.guide)
    r = kernels.prp(ARRAY, G1, u1, vG1, aG1, w1, e1, G2, u2, vG2, aG2, w2, e2)
    b.pos[C], b.vel[C], b.acc[C] = r.C, r.vC, r.aC
    for lid, u, s, own in ((g.a, u1, sa, w["ca"]), (g.b, u2, sb, w["cb"])):
        k = b.links[s.guide.link]
        b.links[lid] = (r.C, r.vC, r.aC, u, k[4], k[5], own)
    b.close(g.label, r.sine, r.closes)
    return tuple((base, s.guide.link, C, v, a)
                 for s, base, v, a in ((sa, w["b1"], r.v1, r.a1), (sb, w["b2"], r.v2, r.a2))
                 if base)


# ---------------------------------------------------------------------------------------
# RPP: the block a at P slides along the guide of the yoke b, which slides along another


def _rpp_setup(mech: Mechanism, translating: frozenset[int], g: Group) -> dict:
    P, B, s_in, s_out = g.P, g.b, g.s1, g.s2
    name = coincident_name(P, B)
    bk = _base_name(P, s_out.guide)
    li, lo = s_in.guide.label, s_out.guide.label
    return {
        "locD": mech.links[B].points[s_out.point], "g0": s_in.guide.point,
        "gd": s_in.guide.direction, "pa": mech.links[g.a].points[P], "name": name, "bk": bk,
        "∥in": s_in.guide.along, "∥out": s_out.guide.along, "VP": f"V_{name}{P}",
        "Vk": f"V_{name}{bk or ''}", "kP": f"a^k_{name}{P}", "kk": f"a^k_{name}{bk}",
        "rP": f"a^r_{name}{P}", "rk": f"a^r_{name}{bk}" if bk else f"a_{name}",
        # the block slides in the yoke, which turns only if its own guide does
        "veq": equation(f"V_{name}", f"V_{P} + V_{name}{P}",
                        _slide(translating, "V", name, bk, s_out.guide)),
        "aeq": equation(f"a_{name}",
                        f"a_{P}{_coriolis(translating, s_out.guide.link, f'a^k_{name}{P}')}"
                        f" + a^r_{name}{P}", _slide(translating, "a", name, bk, s_out.guide)),
        "admissible": "the two guides not parallel",
        "singular": {"en": f"the guide {li} of link {B} is parallel to the guide {lo}: the yoke's "
                           "position is not fixed",
                     "ru": f"направляющая {li} звена {B} параллельна направляющей {lo}: положение "
                           "кулисы не определено"},
    }


def _rpp(xp, g: Group, w: dict, sigma, states, pos, vel, acc, translating):
    P, B, s_out = g.P, g.b, g.s2
    name, bk = w["name"], w["bk"]
    Gk, uk, vG, aG, wk, ek = guide_motion(s_out.guide, states, translating)
    Pw = pos[P]
    r = kernels.rpp(xp, Pw, vel[P], acc[P], Gk, uk, vG, aG, wk, ek, w["locD"], w["g0"], w["gd"])
    closed = CLOSED if one_closes(xp, r.closes) else never_misses(r.closes, np.shape(Pw))
    vroute = (
        record(Route, (P, vel[P], (), r.us, w["∥in"], w["VP"], "sliding", r.t1)),
        record(Route, (bk, r.vk, (), uk, w["∥out"], w["Vk"], "sliding", r.t2)),
    )
    terms1 = (record(Term, ("coriolis", r.c1, w["kP"], (name, P))),) if r.c1 is not None else ()
    terms2 = (record(Term, ("coriolis", r.c2, w["kk"], (name, bk))),) if r.c2 is not None else ()
    aroute = (
        record(Route, (P, acc[P], terms1, r.us, w["∥in"], w["rP"], "sliding", r.s1)),
        record(Route, (bk, r.ak, terms2, uk, w["∥out"], w["rk"], "sliding", r.s2)),
    )
    kst = states[s_out.guide.link]
    states[B] = state_from(r.oB, uk, Pw, r.vP3, r.aP3, kst.omega, kst.epsilon)
    states[g.a] = state_from(Pw - r.us * w["pa"], r.us, Pw, vel[P], acc[P], kst.omega, kst.epsilon)
    found = ((name, B, P, r.vP3, r.aP3),)
    if bk:
        found += ((bk, s_out.guide.link, P, r.vk, r.ak),)
    return solution(g, w, name, r.vP3, r.aP3, vroute, aroute, r.sine, closed), found


def _rpp_bulk(b, g: Group, w: dict, sigma):
    P, s_out = g.P, g.s2
    Gk, uk, vG, aG, wk, ek = b.guide(s_out.guide)
    Pw, vP, aP = b.pos[P], b.vel[P], b.acc[P]
    r = kernels.rpp(ARRAY, Pw, vP, aP, Gk, uk, vG, aG, wk, ek, w["locD"], w["g0"], w["gd"])
    k = b.links[s_out.guide.link]
    vB, aB = rigid(r.vP3, r.aP3, r.oB - Pw, k[4], k[5])  # the yoke at its origin
    b.links[g.b] = (r.oB, vB, aB, uk, k[4], k[5], 0j)
    b.links[g.a] = (Pw, vP, aP, r.us, k[4], k[5], w["pa"])
    b.close(g.label, r.sine, r.closes)
    found = ((w["name"], g.b, P, r.vP3, r.aP3),)
    if w["bk"]:
        found += ((w["bk"], s_out.guide.link, P, r.vk, r.ak),)
    return found


# ---------------------------------------------------------------------------------------

#: the five kinds, in Artobolevsky's numbering
DYADS = {
    DyadKind.RRR: Dyad(DyadKind.RRR, kernels.rrr, _rrr_setup, _rrr, _rrr_bulk, True, ()),
    DyadKind.RRP: Dyad(DyadKind.RRP, kernels.rrp, _rrp_setup, _rrp, _rrp_bulk, True, ("base",)),
    DyadKind.RPR: Dyad(DyadKind.RPR, kernels.rpr, _rpr_setup, _rpr, _rpr_bulk, True, ("name",)),
    DyadKind.PRP: Dyad(DyadKind.PRP, kernels.prp, _prp_setup, _prp, _prp_bulk, False,
                       ("b1", "b2")),
    DyadKind.RPP: Dyad(DyadKind.RPP, kernels.rpp, _rpp_setup, _rpp, _rpp_bulk, False,
                       ("name", "bk")),
}
