"""Plans for one crank position: points, vectors and how each point was constructed.

``solve_position(mech, phi)`` returns a :class:`Solution`: the positions, the velocity
plan (pole p) and the acceleration plan (pole π), each point recording its construction
(the two lines intersected, or the similarity step), ω and ε of every link, and every
segment in millimetres at the scale factors μl, μv, μa. The drawing, the explanatory note
and the check of a student's plan all read this one object.
"""

from __future__ import annotations

import linecache
import sys
import zlib
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from functools import cached_property
from types import MappingProxyType
from typing import NamedTuple

import numpy as np

from plans import tolerances
from plans.kinematics.kernels import record
from plans.kinematics.records import flag_words, flagged, frozen
from plans.kinematics.solver import Motion, Solver, crank_angle
from plans.model.fileformat import Problems, check_keys, read_number
from plans.model.mechanism import MU_UNIT, Mechanism
from plans.model.structure import Structure
from plans.scales import choose_mu, choose_mu_l


def plan_name(point: str) -> str:
    """Mechanism point → plan point: A3 → a3, S3 → s3."""
    return point.lower()


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

    @property
    def in_line(self) -> bool:
        """A similarity point in line with its two bases (``ratio`` real): found on the
        line of their image by the ratio of lengths, not by a similar triangle."""
        return abs(self.ratio.imag) < tolerances.RATIO_IN_LINE


class PlanPoint(NamedTuple):
    name: str
    value: complex  # the vector from the pole: m/s or m/s²
    source: Source


class PlanVector(NamedTuple):
    start: str
    end: str
    component: str  # absolute, relative, normal, tangential, coriolis, sliding
    label: str  # V_A3A, a^n_A3B …


class Plan(NamedTuple):
    """One plan (velocity or acceleration) at one angle: immutable, built once per angle.

    A NamedTuple, built in a fifth of a frozen dataclass's time: a changed copy is
    ``plan._replace(mu=…)`` (not ``dataclasses.replace``), and it unpacks and compares
    as the tuple of its nine fields."""

    kind: str  # "velocity" or "acceleration"
    pole: str  # "p" or "π"
    points: dict[str, PlanPoint]
    vectors: tuple[PlanVector, ...]
    mu: float
    unit: str  # "m/s" or "m/s²"
    #: every drawn segment in mm: pole to each point found, and each component vector
    segments: Mapping[str, float] = MappingProxyType({})
    #: the same segments' ends: name → (from, to), plan point names or the pole
    ends: Mapping[str, tuple[str, str]] = MappingProxyType({})
    #: m/s or m/s²: a vector no longer than this is rounding of 0 (:data:`plans.tolerances.NOISE` of the
    #: plan's longest vector), at any μ
    tiny: float = 0.0

    def value(self, name: str) -> complex:
        """The vector from the pole to plan point ``name`` (m/s or m/s²): plan names are
        lower case, ``value("d")`` for the mechanism's point D (:func:`plan_name`)."""
        try:
            return 0j if name == self.pole else self.points[name].value
        except KeyError:  # value("D") was a bare KeyError: 'D'
            hint = (f"; the mechanism's point {name} is {plan_name(name)!r} on a plan"
                    if isinstance(name, str) and plan_name(name) in self.points else "")
            raise KeyError(f"{name!r} is not a point of the {self.kind} plan (its points: "
                           f"{', '.join([self.pole, *self.points])}){hint}") from None

    def mm(self, start: str, end: str) -> float:
        """Length of the segment start→end on the drawing, in mm; 0 up to ``tiny``, as in
        ``segments``."""
        size = abs(self.value(end) - self.value(start))
        return size / self.mu if size > self.tiny else 0.0


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
    #: the figures the warnings word (:func:`plans.kinematics.records.flagged`), for other languages
    flags: tuple = field(default=(), repr=False, compare=False)
    #: the recorded solution on Python numbers, that the plans were built from
    scalar: Motion | None = field(default=None, repr=False, compare=False)

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
                   mu: dict[str, float] | None = None) -> Solution:
    """Positions and both plans at crank angle ``phi`` (rad from +x; default: the file's).

    ``mu``: scale factors by their file names (``mu_l``, ``mu_v``, ``mu_a``), over the
    file's ``[scales]``; one not given (or None) is chosen. A value that is not a positive
    finite number is an :class:`InputError`, in the words of a file's ``[scales]``.
    """
    mu = _given_scales(mu)
    solver = solver or Solver(mech)
    phi = mech.driver.phi if phi is None else crank_angle(phi)
    motion = solver.solve_one(phi)
    flags = flagged(motion.groups, motion.position, mech.frame[mech.driver.pivot],
                    lambda: solver.at(phi), mech.source,
                    lambda i: solver.singular_figures(i, phi))
    warnings = [flag_words(f, solver.at(phi)) for f in flags]
    scales = mech.scales
    if mu or "mu_l" not in scales:
        scales = dict(scales, **(mu or {}))
        if "mu_l" not in scales:  # the cycle is solved only when μl is to be chosen
            scales["mu_l"] = choose_mu_l(cycle_extent(solver))
    vplan = _plan(solver, motion, "velocity", scales.get("mu_v"))
    aplan = _plan(solver, motion, "acceleration", scales.get("mu_a"))
    positions = dict(motion.position)
    lengths = _position_segments(solver, motion, positions)
    mu_l = scales["mu_l"]
    segments = {k: v / mu_l for k, v in lengths.items()}
    segments.update(vplan.segments)
    segments.update(aplan.segments)
    links = solver.cache.get("links") or solver.cache.setdefault("links", sorted(mech.links))
    omega, epsilon = _rates(motion.links, links, mech.driver.omega)
    return frozen(
        Solution,
        mechanism=mech, structure=solver.structure, phi=phi, solver=solver,
        positions=positions, velocity=vplan, acceleration=aplan,
        omega=omega, epsilon=epsilon,
        mu_l=mu_l, segments=segments, lengths=lengths,
        warnings=tuple(warnings), flags=flags, scalar=motion,
    )


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


def image_sides(plan: Plan) -> list[tuple[complex, complex]]:
    """The links' images that the similarity points of ``plan`` are found on, as
    segments between two vectors of the plan (from its pole): the image bc run on to e
    for a point in line with its two bases (be = bc·BE/BC), else the two sides be, ce of
    the link's triangle. On the acceleration plan no vector joins b and c, so without
    them e and s2 would float: the sheet and the check's picture draw them thin. A side
    no longer than the plan's rounding (``tiny``) is left out."""
    out = []
    for p in plan.points.values():
        src = p.source
        if src.kind != "similarity":
            continue
        b0, b1, z = plan.value(src.base), plan.value(src.other), p.value
        if src.in_line:  # as the step's equation is worded
            lo, hi = min(0.0, src.ratio.real), max(1.0, src.ratio.real)
            sides = [(b0 + lo * (b1 - b0), b0 + hi * (b1 - b0))]
        else:
            sides = [(b0, z), (b1, z)]
        out += [(a, b) for a, b in sides if abs(b - a) > plan.tiny]
    return out


def cycle_extent(solver: Solver) -> float:
    """The larger side (m) of what the plan of positions draws with its twelve positions
    (:attr:`plans.cycle.positions.Drawn.extent`): the sheet sizes it the same way."""
    got = solver.cache.get("cycle extent")
    if got is None:  # once per solver: solve_position asks at every angle
        from plans.cycle.analysis import analyse_cycle
        from plans.cycle.positions import drawn

        got = solver.cache["cycle extent"] = drawn(solver, analyse_cycle(solver.mech,
                                                                         solver=solver)).extent
    return got


def _position_segments(solver: Solver, motion: Motion, pos: dict[str, complex]) -> dict[str, float]:
    """Lengths (m) on the plan of positions: between fixed points, from each link's first
    point to its others (constant, worked out once), and to the coincident points."""
    fixed, moving = solver.cache.get("position segments") or solver.cache.setdefault(
        "position segments", _segment_pairs(solver.mech, motion))
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


# ---------------------------------------------------------------------------------------
# building the plans: a recipe worked out once per solver, then filled in per angle
# ---------------------------------------------------------------------------------------

_POLE, _VALUE, _TERM, _CROSS, _SIMILAR, _FIGURE = range(6)
_POLE_SOURCE = Source("pole")


class _Recipe(NamedTuple):
    """The steps that build one plan, with every name, equation, label and vector of
    the construction, which depend on the mechanism only; the values are read from the
    solved motion when the recipe is followed.

    ``same``: pairs of points that coincided when the recipe was made, so that a point
    of their link was taken as it is rather than by similarity; where they no longer
    coincide, the recipe is worked out again.
    """

    kind: str
    pole: str
    tip: str  # the crank's pin, whose vector sets the plan's scale
    steps: tuple
    same: tuple[tuple[str, str], ...]
    ends: Mapping[str, tuple[str, str]]  # every drawn segment: name → (from, to)
    follow: Callable[..., Plan]  # the steps compiled (:func:`_compile`)


def _plan(solver: Solver, motion: Motion, kind: str, mu) -> Plan:
    """The plan by one of the solver's recipes, the last one used first. A recipe does not
    hold where a similarity base's two points have met (caught by its division by zero)
    or where two points that coincided when it was made no longer do; where none holds,
    one is worked out here and kept too. A mechanism whose points meet at some angles
    only (a Scotch yoke) so keeps two recipes, instead of compiling one anew at each
    change."""
    key = ("plan recipes", kind)
    recipes = solver.cache.get(key) or solver.cache.setdefault(key, [])
    pos = motion.position
    for i, recipe in enumerate(recipes):
        if recipe.same and any(abs(pos[b] - pos[a]) > 0 for a, b in recipe.same):
            continue
        try:
            plan = _follow(recipe, motion, mu)
        except ZeroDivisionError:
            continue
        if i:
            recipes.insert(0, recipes.pop(i))
        return plan
    recipe = _work_out(solver.mech, motion, kind)
    recipes.insert(0, recipe)
    return _follow(recipe, motion, mu)


def _work_out(mech: Mechanism, m: Motion, kind: str) -> _Recipe:
    """Walk the construction as a student draws it: the poles, the crank's pin, then each
    group's two routes and their intersection, and every other point of a link by
    similarity as soon as two of its points are on the plan."""
    acc = kind == "acceleration"
    pole = "π" if acc else "p"
    sym = "a" if acc else "V"
    steps: list[tuple] = []
    same: list[tuple[str, str]] = []
    known: set[str] = set()
    counters = {"n": 0, "k": 0}
    single_k = sum(1 for g in m.groups for r in g.acceleration.routes for t in r.terms
                   if t.kind == "coriolis") == 1
    link_points = {lid: list(link.points) for lid, link in mech.links.items()}
    for n in m.coincident:
        link_points[m.point_link[n]].append(n)
    pos = m.position

    def absolute(name):
        return PlanVector(pole, plan_name(name), "absolute", f"{sym}_{name}")

    def similar(lid, only=None):
        pts = link_points[lid]
        base = [p for p in pts if p in known]
        for name in pts:
            if name in known or (only and name != only):
                continue
            nx = plan_name(name)
            own = mech.links[lid].points
            if len(base) >= 2 and abs(pos[base[1]] - pos[base[0]]) > 0:
                b0, b1 = base[0], base[1]
                n0, n1 = plan_name(b0), plan_name(b1)
                # a fixed point lies at the pole, and is written by the pole's letter
                w0, w1 = (pole if b in mech.frame else nb for b, nb in ((b0, n0), (b1, n1)))
                eqs = (f"{w0}{nx} = {w0}{w1}·{b0}{name}/{b0}{b1}",
                       f"△{w0}{w1}{nx} ∼ △{b0}{b1}{name}")
                if name in own and b0 in own and b1 in own:
                    # three points of the rigid figure: the ratio is the figure's own
                    ratio = (own[name] - own[b0]) / (own[b1] - own[b0])
                    src = Source("similarity", eqs[abs(ratio.imag) >= tolerances.RATIO_IN_LINE], (), n0, n1, ratio)
                    steps.append((_FIGURE, nx, n0, n1, ratio, src, absolute(name)))
                else:  # a coincident point: where it is on the link changes with φ
                    steps.append((_SIMILAR, nx, name, b0, b1, n0, n1, eqs, absolute(name)))
            else:
                if len(base) >= 2:
                    same.append((base[0], base[1]))
                moves = base[0] if base else "its guide"
                src = Source("rigid", equation=f"{sym}_{name}: link {lid} moves with {moves}")
                steps.append((_VALUE, nx, name, src, absolute(name)))
            known.add(name)
            base.append(name)

    for name in mech.frame:
        steps.append((_POLE, plan_name(name), PlanPoint(plan_name(name), 0j, _POLE_SOURCE)))
        known.add(name)
    drv = mech.driver
    if acc:
        eq = f"a_{drv.tip} = a^n_{drv.tip}{drv.pivot} = {drv.omega_sym}²·l_{drv.pivot}{drv.tip}"
        rel = f"∥ {drv.tip}{drv.pivot}, from {drv.tip} to {drv.pivot}"
    else:
        eq = f"V_{drv.tip} = {drv.omega_sym}·l_{drv.pivot}{drv.tip}"
        rel = f"⊥ {drv.pivot}{drv.tip}, in the sense of {drv.omega_sym}"
    steps.append((_VALUE, plan_name(drv.tip), drv.tip, Source("driver", equation=eq, label=rel),
                  absolute(drv.tip)))
    known.add(drv.tip)
    similar(drv.link)
    for gi, g in enumerate(m.groups):
        cons = g.acceleration if acc else g.velocity
        for r in cons.routes:
            if r.base is not None and r.base not in known:
                # a coincident point of a moving guide, e.g. C4 under the slider C
                similar(m.point_link[r.base], only=r.base)
        lines = []
        for ri, r in enumerate(cons.routes):
            start = plan_name(r.base) if r.base is not None else pole
            for ti, t in enumerate(r.terms):
                tag = "n" if t.kind == "normal" else "k"
                counters[tag] += 1
                tname = "k" if tag == "k" and single_k else f"{tag}{counters[tag]}"
                src = Source("component", equation=_term_formula(t), base=start, label=t.label)
                steps.append((_TERM, tname, start, gi, ri, ti, src,
                              PlanVector(start, tname, t.kind, t.label)))
                start = tname
            lines.append((start, ri, r.relation, r.unknown))
        new = cons.point
        pn = plan_name(new)
        line_vectors = tuple(
            PlanVector(through, pn, r.unknown_kind, r.unknown)
            for (through, _, _, _), r in zip(lines, cons.routes, strict=True)
            if through != pole or r.unknown_kind != "sliding"
        )
        steps.append((_CROSS, pn, new, gi, tuple(lines), cons.equation, absolute(new),
                      line_vectors))
        known.add(new)
        for lid in (g.group.a, g.group.b):
            similar(lid)
    ends = _segments_of(steps, pole)
    return _Recipe(kind, pole, drv.tip, tuple(steps), tuple(same), ends,
                   _compile(kind, pole, drv.tip, steps, ends))


def _segments_of(steps, pole: str) -> Mapping[str, tuple[str, str]]:
    """The plan's drawn segments, name → (from, to): pole to every point found (not the
    poles, not the ends of known components), then every component vector; the absolute
    vectors are the pole-to-point segments already. Read-only: every plan of the recipe
    shares it."""
    out = {pole + st[1]: (pole, st[1]) for st in steps
           if st[0] in (_VALUE, _SIMILAR, _FIGURE, _CROSS)}
    for st in steps:
        for v in (st[7],) if st[0] == _TERM else st[7] if st[0] == _CROSS else ():
            out.setdefault(v.start + v.end, (v.start, v.end))
    return MappingProxyType(out)


def _follow(recipe: _Recipe, m: Motion, mu) -> Plan:
    """The plan at the motion's angle, by the recipe's steps (compiled once: see
    :func:`_compile`)."""
    if recipe.kind == "acceleration":
        return recipe.follow(m.acceleration, [g.acceleration for g in m.groups], m.position, mu)
    return recipe.follow(m.velocity, [g.velocity for g in m.groups], m.position, mu)


def _compile(kind: str, pole: str, tip: str, steps, ends):
    """The recipe's steps as one Python function ``follow(store, cons, pos, mu) -> Plan``.

    Following the steps one by one (unpacking each, dispatching on its kind, looking
    every earlier vector up by name) took two thirds of a plan's time; written out once
    as straight-line code over local variables, the same arithmetic and the same records
    take a third of it. The names, equations, labels and vectors of the steps enter the
    code as constants (``K0``, ``K1`` …), never as source text. Each step's lines:

    * a pole: its constant record, vector 0;
    * the crank's pin or a point of a translating link: the vector solved (``store``);
    * a point of a rigid figure: by its fixed complex ratio to two points found;
    * a coincident point: by the ratio of where it is on its link at this angle;
    * a known component: from the group's route term (``cons``), laid from its start;
    * an intersection: the vector solved, with the two lines' directions at this angle.
    """
    consts: list = []

    def k(value) -> str:
        consts.append(value)
        return f"K{len(consts) - 1}"

    var = {pole: "0j"}
    body: list[str] = []
    points: list[tuple[str, str, str]] = []  # name, vector, record
    vectors: list[str] = []  # expressions of the vector list, in order

    def absolute(v: str, vec) -> None:
        vectors.append(f"*(({k(vec)},) if abs({v}) > 0 else ())")

    for i, step in enumerate(steps):
        op, pn = step[0], step[1]
        v = f"v{i}"
        if op == _POLE:
            var[pn] = "0j"
            points.append((pn, "0j", k(step[2])))
            continue
        if op == _VALUE:
            _, _, name, src, vec = step
            body.append(f"{v} = store[{name!r}]")
            rec = f"record(PlanPoint, ({pn!r}, {v}, {k(src)}))"
        elif op == _FIGURE:
            _, _, n0, n1, ratio, src, vec = step
            body.append(f"{v} = {var[n0]} + {k(ratio)} * ({var[n1]} - {var[n0]})")
            rec = f"record(PlanPoint, ({pn!r}, {v}, {k(src)}))"
        elif op == _SIMILAR:
            _, _, name, b0, b1, n0, n1, eqs, vec = step
            body.append(f"q{i} = (pos[{name!r}] - pos[{b0!r}]) / (pos[{b1!r}] - pos[{b0!r}])")
            body.append(f"{v} = {var[n0]} + q{i} * ({var[n1]} - {var[n0]})")
            rec = (f"record(PlanPoint, ({pn!r}, {v}, record(Source, ('similarity', "
                   f"{k(eqs)}[abs(q{i}.imag) >= {tolerances.RATIO_IN_LINE!r}], (), {n0!r}, {n1!r}, q{i}, 1.0, ''))))")
        elif op == _TERM:
            _, _, start, gi, ri, ti, src, vec = step
            term = f"cons[{gi}].routes[{ri}].terms[{ti}].value"
            body.append(f"{v} = {term}" if start == pole else f"{v} = {var[start]} + {term}")
            var[pn] = v
            points.append((pn, v, f"record(PlanPoint, ({pn!r}, {v}, {k(src)}))"))
            vectors.append(k(vec))
            continue
        else:  # _CROSS
            _, _, name, gi, lines, equation, vec, line_vectors = step
            body.append(f"{v} = store[{name!r}]")
            body.append(f"c{i} = cons[{gi}]")
            plan_lines = ", ".join(
                f"record(PlanLine, ({through!r}, c{i}.routes[{ri}].direction, {rel!r}, "
                f"{unknown!r}))" for through, ri, rel, unknown in lines)
            rec = (f"record(PlanPoint, ({pn!r}, {v}, record(Source, ('intersection', "
                   f"{k(equation)}, ({plan_lines},), '', '', 0j, float(c{i}.sine), ''))))")
            var[pn] = v
            points.append((pn, v, rec))
            absolute(v, vec)
            vectors.extend(k(lv) for lv in line_vectors)
            continue
        var[pn] = v
        points.append((pn, v, rec))
        absolute(v, vec)
    values = ", ".join({pn: v for pn, v, _ in points}.values())  # as the plan keeps them
    # each length 0 up to ``tiny`` (see plans.tolerances.NOISE), in the one dict display
    segments = ", ".join(
        f"{key!r}: (m_ if (m_ := abs({var[b]} - {var[a]}) / mu) > tiny_mm else 0.0)" if var[a] != "0j"
        else f"{key!r}: (m_ if (m_ := abs({var[b]}) / mu) > tiny_mm else 0.0)" for key, (a, b) in ends.items())
    unit = "m/s²" if kind == "acceleration" else "m/s"
    source = "\n".join([
        "def follow(store, cons, pos, mu):",
        *(f"    {line}" for line in body),
        f"    big = max(map(abs, ({values}, 0j)))",
        "    if not mu:",
        f"        mu = choose_mu(abs(store[{tip!r}]), big)",
        "    tiny = NOISE * big",
        "    tiny_mm = tiny / mu",
        "    return record(Plan, (",
        f"        {kind!r}, {pole!r},",
        "        {" + ", ".join(f"{pn!r}: {rec}" for pn, _, rec in points) + "},",
        f"        ({''.join(v + ', ' for v in vectors)}),",
        f"        mu, {unit!r},",
        "        {" + segments + "},",
        f"        {k(ends)}, tiny))",
    ])
    scope = {"record": record, "Plan": Plan, "PlanPoint": PlanPoint, "Source": Source,
             "PlanLine": PlanLine, "choose_mu": choose_mu, "NOISE": tolerances.NOISE}
    scope.update((f"K{j}", c) for j, c in enumerate(consts))
    # named by its text, so that a traceback through it shows the generated line, and one
    # mechanism solved again and again keeps one entry in linecache
    filename = f"<plan recipe {kind} {zlib.crc32(source.encode()):08x}{len(source):08x}>"
    exec(compile(source, filename, "exec"), scope)
    linecache.cache[filename] = (len(source), None, source.splitlines(True), filename)
    follow = scope["follow"]
    follow.source = source
    return follow


def _term_formula(t) -> str:
    x, y = t.about
    if t.kind == "normal":
        return f"{t.label} = V_{x}{y}²/l_{x}{y}, directed from {x} to {y}"
    return f"{t.label} = 2·ω·V_{x}{y}, V_{x}{y} turned by 90° in the sense of ω"
