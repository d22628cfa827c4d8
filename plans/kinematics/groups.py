"""The five group solvers that record: each runs its kernel (``plans/kinematics/kernels.py``) and
records the numbers as the two routes of its velocity and acceleration constructions,
with the names, equations and conditions of the group (composed once per solver).

Each works on numpy arrays of angles or on Python numbers of one angle (``xp``); on one
angle a group that does not close raises :class:`ScalarFallback`, and the array path
words the error.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from plans import tolerances
from plans.kinematics import kernels
from plans.kinematics.kernels import record
from plans.kinematics.records import (
    Construction,
    GroupSolution,
    Route,
    Term,
    coincident_name,
    state_from,
)
from plans.model.mechanism import Guide
from plans.model.structure import DyadKind, Group

if TYPE_CHECKING:
    from plans.kinematics.solver import Solver



class ScalarFallback(Exception):
    """The one-angle scalar path met a group that does not close or a division by zero:
    the array path then finds and words the failure."""


#: (valid, gap, singular, margin) of a group that closes at the one angle solved
_CLOSED = (True, 0.0, False, None)


def _one_closes(xp, closes) -> bool:
    """True on the one-angle path where the group closes; there it leaves as soon as it
    misses (:class:`ScalarFallback`), and the array path words why. False for arrays,
    whose closure :func:`_closure` or :func:`_never_misses` records angle by angle.

    A group so writes ``_CLOSED if _one_closes(xp, r.closes) else _closure(…)``: the
    arguments of the array's closure are not even evaluated for one angle, and no
    function is made to defer them (a lambda would make the group's locals cells, slower
    to read at every use)."""
    if not xp.scalar:
        return False
    if not closes:
        raise ScalarFallback
    return True


def _closure(closes, margin, scale):
    """(valid, gap, singular, margin) of a group over arrays of angles. ``margin``: how
    far inside its limit the group is, in metres, negative where it misses; ``scale``:
    the group's size, which the recorded margin is a fraction of."""
    gap = np.maximum(-margin, 0.0)
    return closes, gap, ~closes & (gap <= tolerances.DEAD_GAP * scale), margin * (1.0 / scale)


def _never_misses(closes, shape):
    """(valid, gap, singular, margin) over arrays of angles of a group that cannot miss,
    only fail at a dead point (parallel guides): its gap is 0 and where it does not close
    it is singular; its margin is infinite, and minus infinity where its point is
    nowhere."""
    closes = np.broadcast_to(closes, shape)
    return closes, np.zeros(shape), ~closes, np.where(closes, np.inf, -np.inf)


def _solution(g: Group, w: dict, point: str, v, a, vroute, aroute, sine, closure):
    """A group's recorded solution: the velocity and acceleration constructions of its
    new ``point``, where the group closes, and the words of its conditions (``w``)."""
    valid, gap, singular, margin = closure
    return record(GroupSolution, (
        g, record(Construction, (point, v, vroute, sine, w["veq"])),
        record(Construction, (point, a, aroute, sine, w["aeq"])),
        valid, gap, w["admissible"], singular, w["singular"], margin,
    ))


def _pose_from_two(P, pl, C, cl):
    """Origin and rotor of a link from two world points and their own coordinates."""
    r = (C - P) / (cl - pl)
    r = r / abs(r)
    return P - r * pl, r


def _guide(sv: Solver, guide: Guide, states):
    """A world point of the guide, its direction, the motion of its link there, and the
    link's ω, ε: None where the link never turns (no Coriolis term, as for the frame)."""
    st = states[guide.link]
    G = st.pos(guide.point)
    u = st.rotor * guide.direction
    if guide.link == 0:
        return G, u, 0j, 0j, None, None
    if guide.link in sv.translating:
        return G, u, st.v, st.a, None, None
    return G, u, st.vel(G), st.acc(G), st.omega, st.epsilon


def setup(sv: Solver, g: Group) -> dict:
    """What a group's solution needs that depends on the mechanism only, worked out once
    per solver: its points' own coordinates, link lengths and guide offsets (shared with
    :mod:`plans.kinematics.sweep`), and the names, equations and conditions of its constructions."""
    key = ("group", id(g))  # the groups live as long as the solver's structure
    got = sv.cache.get(key)
    if got is None:
        got = sv.cache[key] = _SETUPS[g.kind](sv, g)
    return got


def _equation(lhs: str, *sides) -> str:
    """A vector equation as written on paper: "V_C = V_B + V_CB = V_D + V_CD". A side is
    a sum, or a (sum, direction) pair from :func:`_slide`; a fixed guide's side is no sum,
    only a direction, said apart: "V_D = V_C + V_DC; V_D ∥ x-x".

    >>> _equation("V_D", "V_C + V_DC", (None, "V_D ∥ x-x"))
    'V_D = V_C + V_DC; V_D ∥ x-x'
    """
    sums, dirs = [], []
    for side in sides:
        total, direction = side if isinstance(side, tuple) else (side, None)
        sums += [total] if total else []
        dirs += [direction] if direction else []
    return "; ".join(([f"{lhs} = {' = '.join(sums)}"] if sums else []) + dirs)


def _coriolis(sv: Solver, link: int, term: str) -> str:
    """" + a^k_…" where the guide's ``link`` turns; nothing on one that translates."""
    return "" if link in sv.translating else f" + {term}"


def _base_name(point: str, guide: Guide) -> str | None:
    return None if guide.link == 0 else coincident_name(point, guide.link)


def _slide(sv: Solver, sym: str, C: str, base: str | None, guide: Guide) -> tuple:
    """One side of an equation for C sliding along ``guide``, as (sum, direction): from
    the coincident point ``base`` of the guide's link, with the Coriolis term where that
    link turns ("V_C4 + V_CC4", "a_C4 + a^k_CC4 + a^r_CC4"), or along a fixed guide only
    a direction ("V_C ∥ x-x")."""
    if base is None:
        return None, f"{sym}_{C} {guide.along}"
    if sym == "V":
        return f"V_{base} + V_{C}{base}", None
    return f"a_{base}{_coriolis(sv, guide.link, f'a^k_{C}{base}')} + a^r_{C}{base}", None


# ---------------------------------------------------------------------------------------
# RRR


def _rrr_setup(sv: Solver, g: Group) -> dict:
    P, C, Q = g.P, g.C, g.Q
    pl, cl = sv.local(g.a, P), sv.local(g.a, C)
    ql, cl3 = sv.local(g.b, Q), sv.local(g.b, C)
    l2, l3 = abs(cl - pl), abs(cl3 - ql)
    return {
        "pl": pl, "cl": cl, "ql": ql, "cl3": cl3, "l2": l2, "l3": l3,
        "⊥P": f"⊥ {C}{P}", "⊥Q": f"⊥ {C}{Q}", "VP": f"V_{C}{P}", "VQ": f"V_{C}{Q}",
        "nP": f"a^n_{C}{P}", "nQ": f"a^n_{C}{Q}", "tP": f"a^t_{C}{P}", "tQ": f"a^t_{C}{Q}",
        "veq": f"V_{C} = V_{P} + V_{C}{P} = V_{Q} + V_{C}{Q}",
        "aeq": f"a_{C} = a_{P} + a^n_{C}{P} + a^t_{C}{P} = a_{Q} + a^n_{C}{Q} + a^t_{C}{Q}",
        "admissible": f"{P}{Q} within [{abs(l2 - l3):.6g}, {l2 + l3:.6g}] m",
        "singular": f"{P}, {C} and {Q} are in line (links {g.a} and {g.b} stretched out or folded)",
    }


def _rrr(sv: Solver, xp, g: Group, sigma, states, pos, vel, acc):
    P, C, Q = g.P, g.C, g.Q
    w = setup(sv, g)
    l2, l3 = w["l2"], w["l3"]
    Pw, Qw = pos[P], pos[Q]
    r = kernels.rrr(xp, sigma, l2, l3, Pw, vel[P], acc[P], Qw, vel[Q], acc[Q])
    closure = _CLOSED if _one_closes(xp, r.closes) else _closure(
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
    oa, ra = _pose_from_two(Pw, w["pl"], r.C, w["cl"])
    ob, rb = _pose_from_two(Qw, w["ql"], r.C, w["cl3"])
    states[g.a] = state_from(oa, ra, r.C, r.vC, r.aC, r.w2, r.e2)
    states[g.b] = state_from(ob, rb, r.C, r.vC, r.aC, r.w3, r.e3)
    pos[C] = r.C
    return _solution(g, w, C, r.vC, r.aC, vroute, aroute, r.sine, closure), {}


# ---------------------------------------------------------------------------------------
# RRP


def _rrp_setup(sv: Solver, g: Group) -> dict:
    P, C, gl, along = g.P, g.C, g.s1.guide.label, g.s1.guide.along
    pl, cl = sv.local(g.a, P), sv.local(g.a, C)
    l2 = abs(cl - pl)
    base = _base_name(C, g.s1.guide)
    second, asecond = _slide(sv, "V", C, base, g.s1.guide), _slide(sv, "a", C, base, g.s1.guide)
    return {
        "pl": pl, "cl": cl, "l2": l2, "cb": sv.local(g.b, C), "base": base,
        "⊥P": f"⊥ {C}{P}", "VP": f"V_{C}{P}", "∥": along,
        "Vs": f"V_{C}{base}" if base else f"V_{C}", "k": f"a^k_{C}{base}",
        "nP": f"a^n_{C}{P}", "tP": f"a^t_{C}{P}",
        "as": f"a^r_{C}{base}" if base else f"a_{C}",
        "veq": _equation(f"V_{C}", f"V_{P} + V_{C}{P}", second),
        "aeq": _equation(f"a_{C}", f"a_{P} + a^n_{C}{P} + a^t_{C}{P}", asecond),
        "admissible": f"distance from {P} to the guide {gl} ≤ {l2:.6g} m",
        "singular": f"{P}{C} is perpendicular to the guide {gl}",
    }


def _rrp(sv: Solver, xp, g: Group, sigma, states, pos, vel, acc):
    P, C, s = g.P, g.C, g.s1
    w = setup(sv, g)
    l2, base, k = w["l2"], w["base"], s.guide.link
    Pw = pos[P]
    G0, u, vG, aG, wk, ek = _guide(sv, s.guide, states)
    r = kernels.rrp(xp, sigma, l2, Pw, vel[P], acc[P], G0, u, vG, aG, wk, ek)
    closure = _CLOSED if _one_closes(xp, r.closes) else _closure(r.closes, l2 - r.h, l2)
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
    oa, ra = _pose_from_two(Pw, w["pl"], r.C, w["cl"])
    states[g.a] = state_from(oa, ra, r.C, r.vC, r.aC, r.w2, r.e2)
    kb = states[k]
    states[g.b] = state_from(r.C - u * w["cb"], u, r.C, r.vC, r.aC, kb.omega, kb.epsilon)
    pos[C] = r.C
    extra = {base: (k, C, r.vCk, r.aCk)} if base else {}
    return _solution(g, w, C, r.vC, r.aC, vroute, aroute, r.sine, closure), extra


# ---------------------------------------------------------------------------------------
# RPR


def _rpr_setup(sv: Solver, g: Group) -> dict:
    P, Q, G, s = g.P, g.Q, g.b, g.s1  # block g.a hinged at P slides on the guide of G
    gd = s.guide.direction
    q = sv.local(G, Q)
    e = (gd.conjugate() * (s.guide.point - q)).imag  # offset of the guide from the pivot Q
    name = coincident_name(P, G)
    return {
        "q": q, "e": e, "gd": gd, "pa": sv.local(g.a, P), "name": name,
        "∥": s.guide.along, "VP": f"V_{name}{P}", "⊥Q": f"⊥ {Q}{name}", "VQ": f"V_{name}{Q}",
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


def _rpr(sv: Solver, xp, g: Group, sigma, states, pos, vel, acc):
    P, Q, G = g.P, g.Q, g.b
    w = setup(sv, g)
    e, name = w["e"], w["name"]
    Pw, Qw = pos[P], pos[Q]
    r = kernels.rpr(xp, sigma, e, w["gd"], Pw, vel[P], acc[P], Qw, vel[Q], acc[Q])
    closure = _CLOSED if _one_closes(xp, r.closes) else _closure(
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
    return (_solution(g, w, name, r.vP3, r.aP3, vroute, aroute, r.sine, closure),
            {name: (G, P, r.vP3, r.aP3)})


# ---------------------------------------------------------------------------------------
# PRP


def _prp_setup(sv: Solver, g: Group) -> dict:
    C, sa, sb = g.C, g.s1, g.s2
    b1, b2 = _base_name(C, sa.guide), _base_name(C, sb.guide)
    l1, l2 = sa.guide.label, sb.guide.label
    return {
        "ca": sv.local(g.a, C), "cb": sv.local(g.b, C), "b1": b1, "b2": b2,
        "∥1": sa.guide.along, "∥2": sb.guide.along, "V1": f"V_{C}{b1 or ''}", "V2": f"V_{C}{b2 or ''}",
        "k1": f"a^k_{C}{b1}", "k2": f"a^k_{C}{b2}",
        "r1": f"a^r_{C}{b1}" if b1 else f"a_{C}", "r2": f"a^r_{C}{b2}" if b2 else f"a_{C}",
        "veq": _equation(f"V_{C}", _slide(sv, "V", C, b1, sa.guide), _slide(sv, "V", C, b2, sb.guide)),
        "aeq": _equation(f"a_{C}", _slide(sv, "a", C, b1, sa.guide), _slide(sv, "a", C, b2, sb.guide)),
        "admissible": "the two guides not parallel",
        "singular": f"the guides {l1} and {l2} are parallel: the hinge {C} is not fixed",
    }


def _prp(sv: Solver, xp, g: Group, sigma, states, pos, vel, acc):
    C, sa, sb = g.C, g.s1, g.s2
    w = setup(sv, g)
    b1, b2 = w["b1"], w["b2"]
    G1, u1, vG1, aG1, w1, e1 = _guide(sv, sa.guide, states)
    G2, u2, vG2, aG2, w2, e2 = _guide(sv, sb.guide, states)
    r = kernels.prp(xp, G1, u1, vG1, aG1, w1, e1, G2, u2, vG2, aG2, w2, e2)
    closure = _CLOSED if _one_closes(xp, r.closes) else _never_misses(r.closes, np.shape(r.C))
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
    extra = {b: (s.guide.link, C, v, a)
             for b, s, v, a in ((b1, sa, r.v1, r.a1), (b2, sb, r.v2, r.a2)) if b}
    return _solution(g, w, C, r.vC, r.aC, vroute, aroute, r.sine, closure), extra


# ---------------------------------------------------------------------------------------
# RPP


def _rpp_setup(sv: Solver, g: Group) -> dict:
    P, B, s_in, s_out = g.P, g.b, g.s1, g.s2  # block g.a at P slides along s_in carried by B
    name = coincident_name(P, B)
    bk = _base_name(P, s_out.guide)
    li, lo = s_in.guide.label, s_out.guide.label
    return {
        "locD": sv.local(B, s_out.point), "g0": s_in.guide.point, "gd": s_in.guide.direction,
        "pa": sv.local(g.a, P), "name": name, "bk": bk,
        "∥in": s_in.guide.along, "∥out": s_out.guide.along, "VP": f"V_{name}{P}", "Vk": f"V_{name}{bk or ''}",
        "kP": f"a^k_{name}{P}", "kk": f"a^k_{name}{bk}",
        "rP": f"a^r_{name}{P}", "rk": f"a^r_{name}{bk}" if bk else f"a_{name}",
        # the block slides in the yoke, which turns only if its own guide does
        "veq": _equation(f"V_{name}", f"V_{P} + V_{name}{P}", _slide(sv, "V", name, bk, s_out.guide)),
        "aeq": _equation(f"a_{name}",
                         f"a_{P}{_coriolis(sv, s_out.guide.link, f'a^k_{name}{P}')} + a^r_{name}{P}",
                         _slide(sv, "a", name, bk, s_out.guide)),
        "admissible": "the two guides not parallel",
        "singular": f"the guide {li} of link {B} is parallel to the guide {lo}: the yoke's "
                    "position is not fixed",
    }


def _rpp(sv: Solver, xp, g: Group, sigma, states, pos, vel, acc):
    P, B, s_out = g.P, g.b, g.s2
    w = setup(sv, g)
    name, bk = w["name"], w["bk"]
    Gk, uk, vG, aG, wk, ek = _guide(sv, s_out.guide, states)
    Pw = pos[P]
    r = kernels.rpp(xp, Pw, vel[P], acc[P], Gk, uk, vG, aG, wk, ek, w["locD"], w["g0"], w["gd"])
    closure = _CLOSED if _one_closes(xp, r.closes) else _never_misses(r.closes, np.shape(Pw))
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
    extra = {name: (B, P, r.vP3, r.aP3)}
    if bk:
        extra[bk] = (s_out.guide.link, P, r.vk, r.ak)
    return _solution(g, w, name, r.vP3, r.aP3, vroute, aroute, r.sine, closure), extra


SOLVERS = {
    DyadKind.RRR: _rrr,
    DyadKind.RRP: _rrp,
    DyadKind.RPR: _rpr,
    DyadKind.PRP: _prp,
    DyadKind.RPP: _rpp,
}
_SETUPS = {
    DyadKind.RRR: _rrr_setup,
    DyadKind.RRP: _rrp_setup,
    DyadKind.RPR: _rpr_setup,
    DyadKind.PRP: _prp_setup,
    DyadKind.RPP: _rpp_setup,
}
