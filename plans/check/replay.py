"""The plans as a student draws them, and the mistakes a student makes.

The plans are replayed point by point from their recorded constructions: poles and the
crank as given, a known component (a^n, a^k) recomputed from the student's own velocity
plan, the intersection of the two recorded lines, and the similarity ratio. A
:class:`Mistake` changes one step and everything after it follows, as on paper.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from plans.check import describe
from plans.check.items import FORCE_PLANS, MU_KEY, PLANS, Item
from plans.geometry import cross, intersect
from plans.kinematics.solver import Solver
from plans.model.structure import DyadKind
from plans.plan.solution import Plan, Solution, plan_name, solve_position
from plans.tolerances import NOISE


@dataclass(frozen=True)
class State:
    """Plans as drawn: point values (m/s, m/s²) by plan name, positions by mechanism name,
    ω and ε as read off the plans, and a length factor per plan (a scale mistake); the
    exact motion of the position drawn (``scalar``), and the force analysis drawn on these
    plans (``forces``: a :class:`plans.check.forces.ForceDrawn`, where forces are measured)."""

    positions: dict[str, complex]
    velocity: dict[str, complex]
    acceleration: dict[str, complex]
    omega: dict[int, float]
    epsilon: dict[int, float]
    factor: dict[str, float] = field(default_factory=lambda: dict.fromkeys(PLANS, 1.0))
    scalar: object = field(default=None, compare=False, repr=False)
    forces: object = field(default=None, compare=False, repr=False)

    def values(self, plan: str) -> dict[str, complex]:
        return self.velocity if plan == "velocity" else self.acceleration


def expected(item: Item, st: State, mu: dict[str, float]) -> float:
    """What the student should have measured (or computed) if they drew ``st``.
    ω and ε are signed (counter-clockwise positive); everything else is a length. An item
    of the force analysis is what the force analysis drawn on ``st`` gives."""
    if item.plan in FORCE_PLANS:
        return st.forces.expected(item)
    f = st.factor[item.plan]
    if item.kind == "omega":
        return st.omega.get(item.link, 0.0) * f
    if item.kind == "epsilon":
        return st.epsilon.get(item.link, 0.0) * f
    if item.plan == "positions":
        return abs(st.positions[item.end] - st.positions[item.start]) / mu["mu_l"] * f
    vals = st.values(item.plan)
    d = abs(vals[item.end] - vals[item.start])
    if d <= NOISE * max(map(abs, vals.values())):  # rounding of a 0, as the plan rounds it
        return 0.0  # (a parallelogram's coupler translates: ab is 1e-13 mm, not 4e16 % off)
    d *= f
    return d if item.kind == "value" else d / mu[MU_KEY[item.plan]]


class Degenerate(Exception):
    """A simulated mistake makes two lines parallel: no plan can be drawn that way."""


@dataclass(frozen=True)
class Mistake:
    """One common mistake, located: which term, line, point, group or plan.

    kind: coriolis-reversed, coriolis-omitted, coriolis-half, coriolis-double, term-scale,
    normal-reversed, normal-omitted, normal-length, normal-swapped, omega-sense, crank-sense,
    crank-tangential-omitted, crank-tangential-reversed (an accelerating crank's a^t),
    value-sense, crank-omega, crank-angle, line-swapped,
    branch, scale, scale-swapped, similarity-ratio, similarity-mirrored; and of the force
    analysis (:mod:`plans.check.forces`): weight-omitted, inertia-along, inertia-omitted,
    inertia-moment-omitted, inertia-moment-reversed, force-reversed, lever-unturned,
    force-scale, moment-sense.
    """

    kind: str
    plan: str = ""  # velocity, acceleration, both, positions
    target: str = ""  # a term label, a plan point, a group label
    factor: complex = 1.0
    link: int = 0
    group: int = -1
    route: int = -1
    info: tuple[tuple[str, str], ...] = ()  # words; a number given here is kept as its repr

    def __post_init__(self):
        # info is words: a number given there (a scale ratio, a fitted μ) is written as
        # the repr of a Python float, which simulate reads back, whatever type it came as
        if any(not isinstance(v, str) for _, v in self.info):
            object.__setattr__(self, "info", tuple(
                (k, v if isinstance(v, str) else repr(float(v))) for k, v in self.info))

    @property
    def family(self) -> str:
        return {"coriolis-reversed": "coriolis", "coriolis-omitted": "coriolis",
                "coriolis-half": "coriolis", "coriolis-double": "coriolis",
                "normal-reversed": "normal",
                "normal-omitted": "normal", "normal-length": "normal",
                "normal-swapped": "normal", "omega-sense": "omega",
                "crank-tangential-omitted": "tangential", "crank-tangential-reversed": "tangential",
                "crank-sense": "omega", "crank-omega": "omega", "crank-angle": "angle",
                "value-sense": "sense",
                "line-swapped": "line", "branch": "branch", "scale": "scale",
                "scale-swapped": "scale", "term-scale": "scale",
                "similarity-ratio": "similarity",
                "similarity-mirrored": "similarity",
                "weight-omitted": "weight", "inertia-along": "inertia", "inertia-omitted": "inertia",
                "inertia-moment-omitted": "inertia moment", "inertia-moment-reversed": "inertia moment",
                "force-reversed": "force", "lever-unturned": "lever",
                "force-scale": "scale", "moment-sense": "sense"}[self.kind]

    def get(self, key: str) -> str:
        return dict(self.info).get(key, "")

    def describe(self, lang: str = "en") -> str:
        """What the mistake is, in ``lang`` (:mod:`plans.check.describe`)."""
        return describe.describe(self, lang)

    def correction(self, lang: str = "en") -> str:
        """How to correct it, in the method's words, in ``lang``."""
        return describe.correction(self, lang)


def link_points(sol: Solution) -> dict[int, list[str]]:
    """The points of each link, with the coincident points (A3) that belong to it."""
    m = sol.scalar
    out: dict[int, list[str]] = {}
    for lid, link in sol.mechanism.links.items():
        pts = list(link.points)
        pts += [n for n, owner in m.point_link.items() if owner == lid and n in m.coincident]
        out[lid] = pts
    return out


def reading_pairs(sol: Solution, points: dict[int, list[str]] | None = None
                  ) -> dict[int, tuple[str, str]]:
    """The pair of points the student reads ω and ε of each link from: the ends of its
    relative velocity vector if the plan has one, else its two farthest points.
    ``points``: :func:`link_points` of ``sol``, if worked out already."""
    points = link_points(sol) if points is None else points
    pos = sol.positions
    mech_name = {plan_name(n): n for n in sol.positions}
    pairs: dict[int, tuple[str, str]] = {}
    for v in sol.velocity.vectors:
        if v.component != "relative":
            continue
        X, Y = mech_name.get(v.end), mech_name.get(v.start)
        for lid, pts in points.items():
            if X in pts and Y in pts and lid not in pairs and abs(pos[X] - pos[Y]) > 0:
                pairs[lid] = (X, Y)
    for lid, pts in points.items():
        if lid in pairs:
            continue
        best, far = None, 0.0
        for i, a in enumerate(pts):
            for b in pts[i + 1:]:
                d = abs(pos[a] - pos[b])
                if d > far * (1 + 1e-9):
                    best, far = (b, a), d
        if best and far > 1e-9 * max(1.0, max(abs(z) for z in pos.values())):
            pairs[lid] = best
    return pairs


class Replayer:
    """Replays the recorded constructions of one solution, with at most one mistake."""

    def __init__(self, sol: Solution):
        self.sol = sol
        m = sol.scalar
        self.pos = sol.positions
        self.mech_name = {plan_name(n): n for n in sol.positions}
        self.terms = {t.label: t for g in m.groups for r in g.acceleration.routes for t in r.terms}
        self.link_points = link_points(sol)
        self.pairs = reading_pairs(sol, self.link_points)

    def guide_link(self, t) -> int:
        m = self.sol.scalar
        for n in t.about:
            if n in m.coincident:
                return m.point_link[n]
        return m.point_link.get(t.about[1], 0)

    def exact(self) -> State:
        s = self.sol
        v = {n: p.value for n, p in s.velocity.points.items()} | {s.velocity.pole: 0j}
        a = {n: p.value for n, p in s.acceleration.points.items()} | {s.acceleration.pole: 0j}
        return State(dict(self.pos), v, a, dict(s.omega), dict(s.epsilon), scalar=s.scalar)

    def _omega(self, vel, flip: set[int]) -> dict[int, float]:
        out = {}
        for lid in self.sol.mechanism.links:
            pair = self.pairs.get(lid)
            if pair is None:
                w = self.sol.omega[lid]
            else:
                X, Y = pair
                r = self.pos[X] - self.pos[Y]
                dv = vel[plan_name(X)] - vel[plan_name(Y)]
                c = cross(r, dv)
                w = math.copysign(abs(dv) / abs(r), c) if abs(dv) > 0 else 0.0
            out[lid] = -w if lid in flip else w
        return out

    def _epsilon(self, acc) -> dict[int, float]:
        out = {}
        for lid in self.sol.mechanism.links:
            pair = self.pairs.get(lid)
            if pair is None:
                out[lid] = self.sol.epsilon[lid]
                continue
            X, Y = pair
            r = self.pos[X] - self.pos[Y]
            out[lid] = float(cross(r, acc[plan_name(X)] - acc[plan_name(Y)]) / abs(r) ** 2)
        return out

    def run(self, mk: Mistake | None = None) -> State:
        s = self.sol
        if mk is None:
            return self.exact()
        if mk.kind == "crank-sense":
            return self._crank_reversed()
        if mk.kind == "value-sense":  # the plans as they are, one ω or ε written reversed
            st = self.exact()
            values = st.omega if mk.get("value") == "omega" else st.epsilon
            values[mk.link] = -values[mk.link]
            return st
        flip = {mk.link} if mk.kind == "omega-sense" else set()
        vel = self._plan(s.velocity, mk, None, None)
        omega = self._omega(vel, flip)
        acc = self._plan(s.acceleration, mk, vel, omega)
        eps = self._epsilon(acc)
        return State(dict(self.pos), vel, acc, omega, eps, scalar=s.scalar)

    def _crank_reversed(self) -> State:
        """The plans of a student who lays off the crank's V_A in the sense opposite to
        ω1: a mechanism of one degree of freedom has every velocity proportional to ω1,
        so every velocity is negated (the velocity plan is point-reflected through p) and
        every ω read off it turns the other way. The accelerations are those of ω1² and
        ε1: a^n = V²/l does not change, a^k = 2·ω·V_rel neither (both factors change
        sign), and ε1 is taken as the mechanism gives it (0 for a crank turning
        uniformly, which is every crank a mechanism file describes; were it not 0, the
        student who keeps its given sense draws the same a^t_A). So the acceleration
        plan, and every ε read off it, is the exact one."""
        st = self.exact()
        vel = {n: -z for n, z in st.velocity.items()}
        omega = {lid: -w for lid, w in st.omega.items()}
        return State(st.positions, vel, st.acceleration, omega, st.epsilon, scalar=st.scalar)

    def _applies(self, mk: Mistake, kind: str) -> bool:
        return mk.plan in (kind, "both")

    def _plan(self, plan: Plan, mk: Mistake, vel, omega) -> dict[str, complex]:
        kind = plan.kind
        vals: dict[str, complex] = {plan.pole: 0j}
        groups = self.sol.scalar.groups
        for name, pt in plan.points.items():
            s = pt.source
            if s.kind == "pole":
                v = 0j
            elif s.kind == "driver":
                v = pt.value
                if mk.kind == "normal-reversed" and mk.get("driver") and kind == "acceleration":
                    v = -v
                elif mk.kind.startswith("crank-tangential") and kind == "acceleration" and s.base:
                    # a^t of an accelerating crank, laid off from n1: left out, or reversed
                    v = vals[s.base] if mk.factor == 0 else vals[s.base] - (v - vals[s.base])
            elif s.kind == "similarity":
                r = s.ratio
                if mk.kind.startswith("similarity") and mk.target == name and self._applies(mk, kind):
                    r = complex(mk.factor)
                v = vals[s.base] + r * (vals[s.other] - vals[s.base])
            elif s.kind == "component":
                t = self.terms[s.label]
                v = vals[s.base] + self._term(t, mk, vel, omega)
            elif s.kind == "intersection":
                (l0, l1) = s.lines
                d0, d1 = l0.direction, l1.direction
                if mk.kind in ("line-swapped", "normal-swapped") and mk.plan == kind and \
                        plan_name(groups[mk.group].velocity.point) == name:
                    if mk.route == 0:
                        d0 = d0 * 1j
                    else:
                        d1 = d1 * 1j
                with np.errstate(all="ignore"):
                    t0, _, sine = intersect(vals[l0.through], d0, vals[l1.through], d1)
                if not abs(sine) >= 1e-6:
                    raise Degenerate(name)
                v = vals[l0.through] + t0 * d0
            else:  # "rigid": moves with the first known point of its link
                X = self.mech_name.get(name, "")
                lid = self.sol.scalar.point_link.get(X)
                v = pt.value
                for other in self.link_points.get(lid, []):
                    on = plan_name(other)
                    if other != X and on in vals:
                        v = vals[on] + (pt.value - plan.value(on))
                        break
            vals[name] = complex(v)
        return vals

    def _term(self, t, mk: Mistake, vel, omega) -> complex:
        X, Y = t.about
        dv = vel[plan_name(X)] - vel[plan_name(Y)]
        if t.kind == "normal":
            r = self.pos[X] - self.pos[Y]
            val = -(abs(dv) ** 2 / abs(r) ** 2) * r
        else:
            val = 2j * omega[self.guide_link(t)] * dv
        if mk.target == t.label and mk.kind in ("coriolis-reversed", "coriolis-omitted",
                                                  "coriolis-half", "coriolis-double",
                                                  "normal-reversed",
                                                  "normal-omitted", "normal-length",
                                                  "normal-swapped", "term-scale"):
            val = val * mk.factor
        return complex(val)


def simulate(sol: Solution, mk: Mistake | None, mu: dict[str, float] | None = None) -> State:
    """The plans as a student who makes mistake ``mk`` draws them (None: the exact ones)."""
    if mk is None:
        return Replayer(sol).exact()
    if mk.kind == "crank-angle":  # the plans of another position, at the stated scales
        return at_angle(sol, float(mk.get("phi")), mu)
    if mk.kind == "branch":
        # the signs the solution was solved on at its angle (past a change point they are
        # not those read at the file's angle), one of them flipped, none flipping again
        n = len(sol.structure.groups)
        sigmas = [int(sol.solver.sigma(i, sol.phi)) for i in range(n)]
        sigmas[mk.group] = -sigmas[mk.group]
        mu = mu or sol.mu
        other = solve_position(sol.mechanism, sol.phi, solver=Solver(
            sol.mechanism, sol.structure, tuple(sigmas), ((),) * n), mu=mu)
        return Replayer(other).exact()
    if mk.kind in ("scale", "scale-swapped", "crank-omega"):
        # ω1 k times off: every velocity (and ω) k times, every acceleration (and ε) k²
        st = Replayer(sol).exact()
        factor = dict.fromkeys(PLANS, 1.0)
        for plan, f in mk.info:
            if plan in factor:  # ("fits", μ), ("example", OA): words only
                factor[plan] = float(f)
        return State(st.positions, st.velocity, st.acceleration, st.omega, st.epsilon, factor, st.scalar)
    return Replayer(sol).run(mk)


def at_angle(sol: Solution, phi: float, mu: dict[str, float] | None = None) -> State:
    """The exact plans at crank angle ``phi`` (rad), at the scales ``mu``: those of a
    student who drew the crank at that angle, not at the solution's."""
    return Replayer(solve_position(sol.mechanism, phi, solver=sol.solver,
                                    mu=mu or sol.mu)).exact()


def hypotheses(sol: Solution, plans: set[str] | None = None) -> list[Mistake]:
    """Every common mistake that can be made on these plans, in order of preference."""
    plans = set(PLANS) if plans is None else plans
    rep = Replayer(sol)
    m = sol.scalar
    out: list[Mistake] = []
    cor = [t for t in rep.terms.values() if t.kind == "coriolis"]
    nor = [t for t in rep.terms.values() if t.kind == "normal"]
    for t in cor:
        X, Y = t.about
        info = (("rel", f"V_{X}{Y}"), ("omega", f"ω{rep.guide_link(t)}"))
        out.append(Mistake("coriolis-reversed", "acceleration", t.label, -1, rep.guide_link(t), info=info))
        out.append(Mistake("coriolis-omitted", "acceleration", t.label, 0, rep.guide_link(t), info=info))
    for t in nor:
        X, Y = t.about
        info = (("X", X), ("Y", Y))
        out.append(Mistake("normal-reversed", "acceleration", t.label, -1, info=info))
        out.append(Mistake("normal-omitted", "acceleration", t.label, 0, info=info))
    drv = sol.mechanism.driver
    out.append(Mistake("normal-reversed", "acceleration", f"a^n_{drv.tip}{drv.pivot}", -1,
                       info=(("X", drv.tip), ("Y", drv.pivot), ("driver", str(drv.link)))))
    if not drv.linear and drv.epsilon:  # an accelerating crank's a^t, from n1
        info = (("X", drv.tip), ("Y", drv.pivot), ("driver", str(drv.link)))
        target = f"a^t_{drv.tip}{drv.pivot}"
        out.append(Mistake("crank-tangential-omitted", "acceleration", target, 0, info=info))
        out.append(Mistake("crank-tangential-reversed", "acceleration", target, -1, info=info))
    for t in cor:
        out.append(Mistake("omega-sense", "acceleration", f"ω{rep.guide_link(t)}",
                           link=rep.guide_link(t), info=(("coriolis", t.label),)))
    # one ω or ε written with the sense reversed, the plans right (before the crank, as the
    # ω of another link below: one value wrong is that value's slip, not the whole
    # velocity plan turned round). The ω of a link that turns no Coriolis vector is the
    # "omega-sense" mistake below already.
    guides = {rep.guide_link(t) for t in cor}
    for key, sym, plan, values in (("omega", "ω", "velocity", sol.omega),
                                   ("epsilon", "ε", "acceleration", sol.epsilon)):
        for lid in sorted(sol.mechanism.links):
            if key == "omega" and lid not in guides:
                continue
            if lid in rep.pairs and abs(values.get(lid, 0.0)) > 0:
                X, Y = rep.pairs[lid]
                out.append(Mistake("value-sense", plan, f"{sym}{lid}", link=lid,
                                   info=(("value", key), ("X", X), ("Y", Y))))
    for lid in sorted(sol.mechanism.links):
        if lid != drv.link and lid not in guides and abs(sol.omega[lid]) > 0:
            out.append(Mistake("omega-sense", "velocity", f"ω{lid}", link=lid))
    out.append(Mistake("crank-sense", "velocity", f"ω{drv.link}", link=drv.link,
                       info=(("X", drv.tip), ("Y", drv.pivot),
                             ("sense", "ccw" if drv.omega > 0 else "cw"))))
    for gi, g in enumerate(m.groups):
        for kind, cons in (("velocity", g.velocity), ("acceleration", g.acceleration)):
            pt = sol.velocity.points[plan_name(cons.point)] if kind == "velocity" else \
                sol.acceleration.points[plan_name(cons.point)]
            for ri, (r, ln) in enumerate(zip(cons.routes, pt.source.lines, strict=True)):
                wrong = r.relation.replace("∥", "\0").replace("⊥", "∥").replace("\0", "⊥")
                out.append(Mistake("line-swapped", kind, r.unknown, group=gi, route=ri,
                                   info=(("relation", r.relation), ("wrong", wrong),
                                         ("through", ln.through), ("point", plan_name(cons.point)))))
    # the normal and the tangential component swapped: a^n laid off ⊥ the link (to one
    # side or the other) and the line of a^t drawn ∥ it through its end
    for gi, g in enumerate(m.groups):
        for ri, r in enumerate(g.acceleration.routes):
            for t in r.terms:
                if t.kind == "normal" and r.unknown_kind == "tangential":
                    X, Y = t.about
                    for f in (1j, -1j):
                        out.append(Mistake("normal-swapped", "acceleration", t.label, f, group=gi,
                                           route=ri, info=(("X", X), ("Y", Y),
                                                           ("tangential", r.unknown))))
    for gi, g in enumerate(m.groups):
        if g.group.kind in (DyadKind.RRR, DyadKind.RRP, DyadKind.RPR):
            out.append(Mistake("branch", "both", g.group.label, group=gi,
                               info=(("point", cons_point(g)),)))
    for plan in ("velocity", "acceleration", "positions"):
        if plan in plans:
            for f in (10.0, 0.1):
                out.append(Mistake("scale", plan, plan, f, info=((plan, f),
                                                                 *scale_example(sol, plan))))
    mv, ma = sol.mu_v, sol.mu_a
    if mv != ma and {"velocity", "acceleration"} & plans:
        out.append(Mistake("scale-swapped", "both", "μv↔μa",
                           info=(("velocity", mv / ma), ("acceleration", ma / mv))))
        out.append(Mistake("scale-swapped", "velocity", "μa",
                           info=(("velocity", mv / ma),)))
        out.append(Mistake("scale-swapped", "acceleration", "μv",
                           info=(("acceleration", ma / mv),)))
    for t in cor:  # the 2 of 2·ω·V_rel left out, or taken twice
        for kind, f in (("coriolis-half", 0.5), ("coriolis-double", 2.0)):
            out.append(Mistake(kind, "acceleration", t.label, f, rep.guide_link(t),
                               info=(("rel", f"V_{t.about[0]}{t.about[1]}"),
                                     ("omega", f"ω{rep.guide_link(t)}"))))
    for t in cor + nor:
        for f in (10.0, 0.1):
            out.append(Mistake("term-scale", "acceleration", t.label, f))
    out += _similarity_mistakes(sol)
    out += _normal_length_mistakes(sol, nor)
    return out


def _normal_length_mistakes(sol: Solution, nor) -> list[Mistake]:
    """a^n of a link computed with another length of the mechanism: a^n_XY = ω²·l or V²/l
    with l the distance of two points of one link or of the frame, so the term is l'/l or
    l/l' times its own. The points are the joints and a link's end points (a coupler's
    E), not a point between two others of its link (a centre of mass mid-link: l_BS2 is
    no length a student takes for l_CD). Only ratios 10 % or more off 1 (less stays in
    the tolerance) and not near 10 or 0.1 (the term drawn 10 times off is its own
    mistake); a ratio two lengths share is tried once. The lengths of the term's own link
    come first, the one a student takes most often (l_BC, the rocker, for l_A3B), and the
    others that share the ratio are named with it: on the press, V²/l_BC and ω3²·l_OB
    for a^n_A3B are 0.766 and 0.765 of it, and the first had been named "l_OB" alone."""
    mech = sol.mechanism
    pos = sol.positions

    def inner(p: str, names: list[str]) -> bool:  # between two other points of the link
        return any(abs(abs(pos[a] - pos[p]) + abs(pos[p] - pos[b]) - abs(pos[a] - pos[b]))
                   <= 1e-9 * abs(pos[a] - pos[b])
                   for i, a in enumerate(names) for b in names[i + 1:] if p not in (a, b))

    lengths: dict[tuple[str, str], float] = {}
    for names in [list(mech.frame), *(list(link.points) for link in mech.links.values())]:
        names = [n for n in names if n in pos]
        keep = [n for n in names if len(mech.links_of(n)) > 1 or not inner(n, names)]
        for i, a in enumerate(keep):
            for b in keep[i + 1:]:
                if abs(pos[a] - pos[b]) > 1e-12:
                    lengths.setdefault((a, b), abs(pos[a] - pos[b]))
    m = sol.scalar

    def link_of(p: str) -> set[int]:  # a coincident point (A3) is its link's
        return {m.point_link[p]} if p in m.coincident else set(mech.links_of(p))

    out = []
    for t in nor:
        X, Y = t.about
        own = abs(pos[X] - pos[Y])
        mine = link_of(X) & link_of(Y)
        # (ratio, how, the pair named, the other pairs of that ratio, its length)
        found: list[tuple[float, str, str, list[str], float]] = []
        for (a, b), length in sorted(lengths.items(), key=lambda kv: not (
                link_of(kv[0][0]) & link_of(kv[0][1]) & mine)):
            if {a, b} == {X, Y}:
                continue
            for f, how in ((length / own, "omega"), (own / length, "speed")):
                if abs(f - 1) < 0.1 or any(abs(f / g - 1) < 0.05 for g in (10.0, 0.1)):
                    continue
                same = next((fd for fd in found if abs(f / fd[0] - 1) < 0.05), None)
                if same is None:
                    found.append((f, how, a + b, [], length))
                elif a + b != same[2] and a + b not in same[3]:
                    same[3].append(a + b)
        for f, how, wrong, also, length in found:
            out.append(Mistake("normal-length", "acceleration", t.label, f,
                               info=(("X", X), ("Y", Y), ("wrong", wrong), ("how", how),
                                     ("own", repr(own)), ("length", repr(length)),
                                     *((("also", " ".join(also)),) if also else ()))))
    return out


def scale_example(sol: Solution, plan: str) -> tuple[tuple[str, str], ...]:
    """For a scale mistake on the plan of positions, the segment its correction shows
    (the crank, OA): the words only."""
    drv = sol.mechanism.driver
    return (("example", f"{drv.pivot}{drv.tip}"),) if plan == "positions" else ()


def cons_point(g) -> str:
    return g.velocity.point


def _similarity_mistakes(sol: Solution) -> list[Mistake]:
    out = []
    vp = sol.velocity
    sims = {n: p.source for n, p in vp.points.items() if p.source.kind == "similarity"}
    for name, s in sims.items():
        r = s.ratio
        cands: list[tuple[str, complex, str]] = []
        if abs(r.imag) < 1e-12:
            if abs(r) > 1e-12 and abs(abs(r) - 1) > 1e-6:
                cands.append(("similarity-ratio", 1 / r, "inverse"))
            cands.append(("similarity-mirrored", -r, "side"))
            # the ratio laid off from the other end: other + r·(base − other)
            if abs((1 - r) - r) > 1e-9 and all(abs((1 - r) - c[1]) > 1e-9 for c in cands):
                cands.append(("similarity-ratio", 1 - r, "end"))
        else:
            cands.append(("similarity-mirrored", r.conjugate(), "mirror"))
            cands.append(("similarity-ratio", r / abs(r) ** 2, "inverse"))
        for other, s2 in sims.items():
            if other != name and s2.base == s.base and s2.other == s.other and abs(s2.ratio - r) > 1e-9:
                cands.append(("similarity-ratio", s2.ratio, "sibling:" + other))
        for kind, ratio, how in cands:
            for plan in ("both", "velocity", "acceleration"):
                out.append(Mistake(kind, plan, name, ratio,
                                   info=(("how", how), ("equation", s.equation),
                                         ("base", s.base), ("other", s.other))))
    return out
