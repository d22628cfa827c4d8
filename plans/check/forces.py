"""The force analysis as a student draws it, and the mistakes a student makes in it.

The items of a force analysis (segments of each group's force plan in mm at μF, forces and
moments in N and N·m, the arms of Zhukovsky's lever in mm of the velocity plan at μv, and
the balancing force F_у or moment M_у) are compared with the exact force analysis
(:mod:`plans.forces`) at the student's scales. A mistake is replayed as the kinematic ones
are, by doing the work again with one step changed and everything after it following:

- a load mistake changes the loads (an inertia force laid along the acceleration, one
  left out, an inertia moment left out or of the wrong sense, a weight left out, a force
  or the useful resistance turned round), then the same group walk and the same lever;
- on the lever, the forces applied to the velocity plan as it is, not turned by 90°. Turning
  the forces by 90° with the plan is the same figure turned as a whole: every moment about
  the pole is the same, so it is one mistake. (Turning the plan by −90° instead of +90°
  changes nothing: every moment, F_у's included, changes sign.) F_у is then Σ ±F_i·h_i / pb
  with the arms of that figure;
- a force plan drawn at another μF than the one written down: its segments, and the
  reactions read off it, are that many times the exact ones;
- a kinematic mistake carries over: the loads are those of the student's own plans (a_S, ε
  and V as they drew them), the lever is their velocity plan turned.

F_у is taken as found by the lever (seed 001), M_у from the driving link's equilibrium
(seed 000); without a lever mistake the two agree.
"""

from __future__ import annotations

import dataclasses
import math
from collections.abc import Mapping
from dataclasses import dataclass, field
from types import MappingProxyType

from plans.check.replay import Mistake
from plans.forces.analysis import ForceAnalysis, analyse_loads
from plans.forces.lever import couple_pair, joints
from plans.forces.loads import Load, Stroke, at_position, stroke_of
from plans.geometry import cross
from plans.model.loads import Loads
from plans.plan.solution import Solution, plan_name
from plans.scales import series

#: the force analysis's mistakes (Mistake.kind); the rest are the plans' own
KINDS = ("weight-omitted", "inertia-along", "inertia-omitted", "inertia-moment-omitted",
         "inertia-moment-reversed", "force-reversed", "lever-unturned", "force-scale", "moment-sense")
#: the load each load mistake changes (plans.forces.loads.Load.kind)
LOAD_KIND = {"weight-omitted": "weight", "inertia-along": "inertia", "inertia-omitted": "inertia",
             "inertia-moment-omitted": "inertia moment", "inertia-moment-reversed": "inertia moment"}
#: the kinematic mistakes whose plans are the exact ones of another position (its own motion)
ELSEWHERE = ("branch", "crank-angle")
#: the names of the balancing force and moment, as ``plans forces`` prints them
F_Y, M_Y = "F_у", "M_у"


def group_key(gf) -> str:
    """A group's force plan by its links, "4–5", as its label says them."""
    a, b = gf.group.links
    return f"{a}–{b}"


def reaction_name(by: int, on: int) -> str:
    return f"R{by}{on}" if by < 10 and on < 10 else f"R{by},{on}"


@dataclass(frozen=True)
class ForceDrawn:
    """A force analysis as drawn: each segment of the force plans (N, by its label), every
    force (N, complex) and moment (N·m, signed) by name, the lever's arms and pb (mm), F_у
    (N) and M_у (N·m), and the μF of each plan and the factor a plan is drawn off it."""

    segments: Mapping[str, float]
    values: Mapping[str, complex | float]
    arms: Mapping[str, float]
    pb: float
    F_y: float
    M_y: float
    mu: Mapping[str, float]  # group key → the student's μF
    factor: Mapping[str, float] = field(default_factory=dict)  # group key → drawn so many times
    read_off: Mapping[str, str] = field(default_factory=dict)  # value → the group it is read off

    def expected(self, item) -> float:
        """What the student should have measured (or computed) on this analysis: a length
        in mm, a force's magnitude, a moment and F_у signed (counter-clockwise positive)."""
        if item.kind == "segment":
            if item.plan == "lever":
                return self.pb if not item.start else self.arms.get(item.start, 0.0)
            f = self.factor.get(item.group, 1.0)
            return self.segments.get(item.name, 0.0) / self.mu[item.group] * f
        if item.kind == "balancing":
            return self.F_y
        v = self.values.get(item.name, 0.0)
        f = self.factor.get(self.read_off.get(item.name, ""), 1.0)
        return float(v) * f if item.kind == "moment" else abs(v) * f


@dataclass(frozen=True)
class ForceContext:
    """The exact force analysis of a measurement's position at the student's scales, and
    what replays it: the solution, the loads as the file gives them, the working stroke
    (for a P(S) graph), the student's μF by group (given or not) and the lever's μv."""

    solution: Solution
    loads: Loads
    stroke: Stroke | None
    analysis: ForceAnalysis
    mu_F: Mapping[str, float] = field(default_factory=dict)
    #: μF as the file writes it: one number for every plan, or a table by group
    mu_F_given: float | Mapping[str, float] | None = None
    #: the exact lever: each force's arm (mm), pb (mm), F_у (N)
    lever: tuple = ({}, 0.0, 0.0)
    #: the forces read off each group's force plan (:func:`read_off`)
    read_off: Mapping[str, str] = field(default_factory=dict)

    @classmethod
    def build(cls, sol: Solution, cycle=None) -> ForceContext:
        """The exact analysis of ``sol`` (a :class:`plans.errors.PlansError` where it has
        no force plan here); ``cycle`` (:func:`plans.cycle.analyse_cycle`): only a P(S)
        graph needs it, for the working stroke."""
        mech = sol.mechanism
        loads = mech.loads
        stroke = stroke_of(mech, cycle, sol.solver) if cycle is not None else None
        fa = analyse_loads(sol, external(mech, loads, sol.scalar, sol.phi, stroke), stroke)
        arms, pb, F_y = lever_of(sol, sol.scalar, list(fa.loads))
        return cls(sol, loads, stroke, fa, lever=(MappingProxyType(arms), pb, F_y),
                   read_off=MappingProxyType(read_off(fa)))

    @property
    def keys(self) -> tuple[str, ...]:
        """The groups' keys in the order their force plans are drawn."""
        return tuple(group_key(gf) for gf in self.analysis.groups)

    @property
    def tip(self) -> str:
        return self.solution.mechanism.driver.tip

    @property
    def pb_name(self) -> str:
        """The lever's segment from the pole to the crank pin's image, "pb"."""
        return "p" + plan_name(self.tip)

    def drawn(self, st=None, mk: Mistake | None = None) -> ForceDrawn:
        """The force analysis of a student who drew the plans ``st`` (a
        :class:`plans.check.replay.State`; None: the exact ones) and made the mistake ``mk``
        (a kinematic one is in ``st`` already)."""
        sol = self.solution
        mech = sol.mechanism
        force_mk = mk if mk is not None and mk.kind in KINDS else None
        kinematic = mk is not None and force_mk is None
        if not kinematic:
            motion = sol.scalar
            analysis = self.analysis
            computed = list(analysis.loads)
        else:
            base = st.scalar if st.scalar is not None else sol.scalar
            motion = base if mk.kind in ELSEWHERE else drawn_motion(st, base)
            computed = external(mech, self.loads, motion, float(motion.phi), self.stroke)
            analysis = None
        used = computed if force_mk is None else _changed(computed, force_mk)
        if analysis is None or used is not computed:
            analysis = analyse_loads(sol, used, self.stroke, motion=motion)
        turn = 1.0 if force_mk is not None and force_mk.kind == "lever-unturned" else 1j
        if mk is None or (force_mk is not None and turn == 1j and used is computed):
            arms, pb, F_y = self.lever
        else:
            arms, pb, F_y = lever_of(sol, motion, used, turn)
        factor = {}
        if force_mk is not None and force_mk.kind == "force-scale":
            f = float(force_mk.factor.real)
            factor = {k: f for k in self.keys if force_mk.target in ("all", k)}
        values = _values(analysis, computed, used)
        if force_mk is not None and force_mk.kind == "moment-sense":  # one sense written the other way
            if force_mk.target == F_Y:
                F_y = -F_y
            else:
                values[force_mk.target] = -values[force_mk.target]
        return ForceDrawn(
            MappingProxyType(_segments(analysis)), MappingProxyType(values),
            MappingProxyType({**self.lever[0], **arms}), pb, F_y, analysis.M_y,
            MappingProxyType(dict(self.mu_F)), MappingProxyType(factor), self.read_off)


def external(mech, loads: Loads, motion, phi, stroke) -> list[Load]:
    """The file's loads at ``motion``, as :func:`plans.forces.analysis.analyse` takes them:
    a load that is exactly nothing here left out."""
    return [ld for ld in at_position(mech, loads, motion, phi, stroke) if ld.force != 0 or ld.moment != 0]


def drawn_motion(st, motion):
    """The motion a student's plans ``st`` give: the velocities and accelerations of the
    points, ω and ε as read off them, each plan's values taken at the scale written down
    (a plan drawn k times too large is read k times too large); the positions as they are."""
    fv, fa = st.factor.get("velocity", 1.0), st.factor.get("acceleration", 1.0)
    vel = {X: fv * st.velocity.get(plan_name(X), v) for X, v in motion.velocity.items()}
    acc = {X: fa * st.acceleration.get(plan_name(X), a) for X, a in motion.acceleration.items()}
    links = {lid: ls._replace(omega=fv * st.omega.get(lid, ls.omega),
                              epsilon=fa * st.epsilon.get(lid, ls.epsilon))
             for lid, ls in motion.links.items()}
    return dataclasses.replace(motion, velocity=vel, acceleration=acc, links=links)


def _changed(loads: list[Load], mk: Mistake) -> list[Load]:
    """The loads with the mistake ``mk`` made: its load (or every load of its kind)
    reversed or left out."""
    if mk.kind in ("lever-unturned", "force-scale"):
        return loads
    every = mk.target == "all"
    out = []
    for ld in loads:
        if not ((every and ld.kind == LOAD_KIND[mk.kind]) or (not every and ld.name == mk.target)):
            out.append(ld)
        elif mk.kind in ("inertia-along", "force-reversed"):
            out.append(ld._replace(force=-ld.force))
        elif mk.kind == "inertia-moment-reversed":
            out.append(ld._replace(moment=-ld.moment))
        # the rest: left out
    return out


def _segments(fa: ForceAnalysis) -> dict[str, float]:
    """Every segment of the groups' force plans, in N, by its label."""
    return {label: mm * gf.plan.mu for gf in fa.groups for label, mm in gf.plan.segments.items()}


def _values(fa: ForceAnalysis, computed: list[Load], used: list[Load]) -> dict[str, complex | float]:
    """Every force (N) and moment (N·m) by name: the loads as the student computed them
    (one left out of the plans is still computed; one reversed is written reversed), the
    reactions and their components, what the groups put on the links before them, M_у."""
    out: dict[str, complex | float] = {}
    for ld in [*computed, *used]:
        out[ld.name] = float(ld.moment) if ld.force == 0 else complex(ld.force)
    for gf in fa.groups:
        for lid in (gf.group.a, gf.group.b):
            for ld in gf.loads[lid]:
                if ld.kind == "reaction":
                    out[ld.name] = complex(ld.force)
    for ld in fa.crank_loads:
        if ld.kind == "reaction":
            out[ld.name] = complex(ld.force)
    for r in fa.reactions.values():
        out[r.name] = complex(r.value)
        if r.tangential is not None:
            out[r.name + "^τ"] = complex(r.tangential)
            out[r.name + "^n"] = complex(r.normal)
    out[M_Y] = float(fa.M_y)
    return out


def read_off(fa: ForceAnalysis) -> dict[str, str]:
    """The forces a student reads off a group's force plan, by the group's key: every
    segment of it that is not laid off as known (the lines that close it, a reaction drawn
    whole, the inner one), not the loads nor what the moment equations gave (R12^τ, the
    slotted link's R12). A force the other way round is read off where it is (R45 as R54,
    and R43, laid off as known in the next plan, as R34)."""
    out: dict[str, str] = {}
    for gf in fa.groups:
        key = group_key(gf)
        points = gf.plan.points
        for label, (_, b) in gf.plan.ends.items():
            src = points[b].source
            if not (src.kind == "component" and src.label == label):
                out.setdefault(label, key)
    for gf in fa.groups:
        for r in gf.reactions:
            if r.name in out:
                out.setdefault(reaction_name(r.on, r.by), out[r.name])
    return out


def lever_of(sol: Solution, motion, loads: list[Load], turn: complex = 1j):
    """Zhukovsky's lever as :func:`plans.forces.lever.lever` draws it, on the velocity plan
    of ``motion`` at the solution's μv, turned by ``turn`` (1j: +90°, as the method says;
    1: not turned): (each force's arm by name, mm; pb, mm; F_у, N)."""
    mech = sol.mechanism
    mu = sol.velocity.mu
    d = mech.driver
    arms: dict[str, float] = {}
    total = 0.0

    def put(name, point, force):
        nonlocal total
        image = turn * motion.velocity[point] / mu
        mo = cross(image, force)
        arms[name] = abs(mo) / abs(force) if force else 0.0
        total += mo

    for ld in loads:
        if ld.point is not None and ld.force != 0:
            put(ld.name, ld.point, ld.force)
        if ld.moment:
            ends = joints(mech, ld.link)
            if ends is None:  # a block's couple: its power, as the lever takes it
                total += -ld.moment * motion.links[ld.link].omega / mu
                continue
            for point, _, force in couple_pair(ld.link, ld.moment, motion.position, *ends):
                put(f"{ld.name}({point})", point, force)
    pb = abs(motion.velocity[d.tip]) / mu
    sense = 1.0 if d.omega > 0 else -1.0
    F_y = total / (pb * sense) if pb else math.nan
    return arms, pb, float(F_y)


# ---------------------------------------------------------------------------------------
# the mistakes
# ---------------------------------------------------------------------------------------


def hypotheses(ctx: ForceContext, items) -> list[Mistake]:
    """Every common mistake of the force analysis that the measured ``items`` could show,
    in order of preference: a moment (or F_у) written with the wrong sense, the analysis
    right; of one load before those of every load of a kind; the loads before the lever,
    the lever before a scale."""
    loads = ctx.analysis.loads
    out: list[Mistake] = []
    for it in items:
        if it.kind in ("moment", "balancing") and it.sense:
            out.append(Mistake("moment-sense", "force", it.name, info=(("what", _moment_what(it.name)),)))
    by_kind = {k: [ld for ld in loads if ld.kind == k] for k in set(LOAD_KIND.values())}
    order = ("inertia-along", "inertia-moment-reversed", "inertia-moment-omitted", "weight-omitted",
             "inertia-omitted")
    for kind in order:
        for ld in by_kind[LOAD_KIND[kind]]:
            out.append(Mistake(kind, "force", ld.name, link=ld.link, info=_where(ctx, ld)))
    for ld in loads:
        if ld.kind in ("resistance", "force"):
            out.append(Mistake("force-reversed", "force", ld.name, link=ld.link,
                               info=(("what", ld.kind), *_rule(ctx, ld))))
    for kind in order:
        if len(by_kind[LOAD_KIND[kind]]) > 1:
            out.append(Mistake(kind, "force", "all", info=(("all", "1"),)))
    if any(it.plan == "lever" or it.kind == "balancing" for it in items):
        out.append(Mistake("lever-unturned", "force", "lever", info=(("pb", ctx.pb_name),)))
    keys = [k for k in ctx.keys if any(it.group == k for it in items if it.kind == "segment")]
    for k in keys + (["all"] if len(keys) > 1 else []):
        for f in (10.0, 0.1):
            out.append(Mistake("force-scale", "force", k, f, info=(("factor", f),)))
    return out


def fitted_scales(ctx: ForceContext, devs) -> list[Mistake]:
    """A force plan drawn at a μF other than the one written down, by any factor: the
    ratio of its measured segments to the exact ones, as :func:`plans.check.verdict`
    fits μv and μa (two segments or more, 15 % or more off 1, not near 10 or 0.1); every
    plan at once where a file gives one μF for them all and measures on two or more."""
    segs = [(d.item.group, d.item.measured, abs(d.computed)) for d in devs
            if d.item.plan == "force" and d.item.kind == "segment" and d.computed]
    groups = list(dict.fromkeys(g for g, _, _ in segs))
    sets = [(g, [s for s in segs if s[0] == g]) for g in groups]
    if len(groups) > 1 and not isinstance(ctx.mu_F_given, Mapping):
        sets.append(("all", segs))
    out = []
    for key, pairs in sets:
        if len(pairs) < 2:
            continue
        r = sum(m for _, m, _ in pairs) / sum(c for _, _, c in pairs)
        if r > 0 and abs(r - 1) >= 0.15 and not any(abs(r / f - 1) < 0.05 for f in (10.0, 0.1)):
            stated = ctx.mu_F[groups[0] if key == "all" else key]
            fits = stated / r
            near = min(series(fits / 1.2, fits * 1.2), key=lambda m: abs(m / fits - 1), default=fits)
            if abs(near / fits - 1) < 0.015:
                fits, r = near, stated / near
            out.append(Mistake("force-scale", "force", key, r, info=(("factor", r), ("fits", fits))))
    return out


def _moment_what(name: str) -> str:
    """Which moment a sense mistake is of, for its words: M_у, F_у, an inertia moment, another."""
    return {M_Y: "balancing", F_Y: "force"}.get(name, "inertia" if name.startswith("M_Φ") else "moment")


def _where(ctx: ForceContext, ld: Load) -> tuple[tuple[str, str], ...]:
    """The words of a load's mistake: its centre of mass and link."""
    centre = ctx.loads.masses[ld.link].centre if ld.link in ctx.loads.masses else (ld.point or "")
    crank = (("crank", "1"),) if ld.link == ctx.solution.mechanism.driver.link else ()
    return (("centre", centre), ("image", plan_name(centre)), *crank)


def _rule(ctx: ForceContext, ld: Load) -> tuple[tuple[str, str], ...]:
    """A file's force's direction rule, for the words ("against velocity")."""
    for f in ctx.loads.forces:
        if f.name == ld.name:
            return (("rule", f.rule or ""), ("point", f.point))
    return (("point", ld.point or ""),)
