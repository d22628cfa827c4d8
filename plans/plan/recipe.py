"""The recipes that build a plan: the construction walked once, compiled, then followed at
each crank angle.

A student draws a plan step by step: the pole, the crank's pin, each group's two routes
and their intersection, every other point of a link by similarity. Those steps, with
every name, equation, label and vector of the construction, depend on the mechanism only;
:func:`work_out` walks them once and :func:`compile_steps` writes them as one Python
function, which :func:`follow` runs on each solved motion. The recipes are held here, by
the plan layer, for each solver (:func:`kept`), as long as the solver lives.
"""

from __future__ import annotations

import linecache
import weakref
import zlib
from collections.abc import Callable, Mapping
from types import MappingProxyType
from typing import NamedTuple

from plans import tolerances
from plans.kinematics.kernels import record
from plans.kinematics.solver import Motion, Solver
from plans.model import Mechanism
from plans.plan.values import Plan, PlanLine, PlanPoint, PlanVector, Source, plan_name
from plans.scales import choose_mu

#: the kinds of a recipe's step (the first item of each), as :func:`compile_steps` writes them;
#: DRIVER_N and DRIVER_T: a crank's acceleration as its normal and tangential components
#: (where it has an ε)
POLE, VALUE, TERM, CROSS, SIMILAR, FIGURE, DRIVER_N, DRIVER_T = range(8)
__POLE_SOURCE = Source("pole")


class Recipe(NamedTuple):
    """The steps that build one plan, with every name, equation, label and vector of
    the construction, which depend on the mechanism only; the values are read from the
    solved motion when the recipe is followed.

    ``same``: pairs of points that coincided when the recipe was made, so that a point
    of their link was taken as it is rather than by similarity; where they no longer
    coincide, the recipe is worked out again. ``near``: the distance (m) within which two
    points are one place, the mechanism's size times :data:`plans.tolerances.SAME_PLACE`
    (a Scotch yoke's A3 and D 1.7e-311 m apart at φ1 = 1e-308° had been a similarity
    base, and its ratio infinite).
    """

    kind: str
    pole: str
    tip: str  # the crank's pin, whose vector sets the plan's scale
    steps: tuple
    same: tuple[tuple[str, str], ...]
    near: float
    ends: Mapping[str, tuple[str, str]]  # every drawn segment: name → (from, to)
    follow: Callable[..., Plan]  # the steps compiled (:func:`compile_steps`)


class Kept:
    """What the plan layer keeps of one solver's mechanism, worked out at its first plans:
    the recipes of each kind of plan, the last one used first (:func:`plan`); the plan of
    positions' segments, (fixed lengths, moving pairs), and the links in order
    (:mod:`plans.plan.solution`)."""

    __slots__ = ("links", "recipes", "segments")

    def __init__(self, links: list[int]):
        self.recipes: dict[str, list[Recipe]] = {"velocity": [], "acceleration": []}
        self.segments: tuple | None = None
        self.links = links


#: per solver (by its id), a weak reference to it and what the plan layer keeps of it:
#: held here as long as the solver lives (the reference's callback lets go of it). A
#: plain dict read by a number, not a WeakKeyDictionary, whose look-up is Python code:
#: this is read at every plan.
_KEPT: dict[int, tuple[weakref.ref, Kept]] = {}


def kept(solver: Solver) -> Kept:
    """What the plan layer keeps for ``solver`` (:class:`Kept`); made at its first plans."""
    got = _KEPT.get(id(solver))
    if got is not None and got[0]() is solver:
        return got[1]
    key = id(solver)
    keep = Kept(sorted(solver.mech.links))
    _KEPT[key] = (weakref.ref(solver, lambda _, key=key: _KEPT.pop(key, None)), keep)
    return keep


def recipes(solver: Solver, kind: str) -> list[Recipe]:
    """The recipes of ``solver``'s ``kind`` plan ("velocity" or "acceleration") worked out
    so far, the last one used first: the very list :func:`plan` follows and keeps."""
    return kept(solver).recipes[kind]


def plan(solver: Solver, motion: Motion, kind: str, mu,
         kinds: list[Recipe] | None = None) -> Plan:
    """The plan of ``kind`` of the solved ``motion`` at scale ``mu`` (None: chosen), by one
    of the solver's recipes (``kinds``: :func:`recipes`, where the caller has them), the
    last one used first. A recipe does not hold where a
    similarity base's two points have met (caught by its division by zero) or where two
    points that coincided when it was made no longer do; where none holds, one is worked
    out here and kept too. A mechanism whose points meet at some angles only (a Scotch
    yoke) so keeps two recipes, instead of compiling one anew at each change."""
    kinds = recipes(solver, kind) if kinds is None else kinds
    pos = motion.position
    for i, recipe in enumerate(kinds):
        if recipe.same and any(abs(pos[b] - pos[a]) > recipe.near for a, b in recipe.same):
            continue
        try:
            got = follow(recipe, motion, mu)
        except ZeroDivisionError:
            continue
        if i:
            kinds.insert(0, kinds.pop(i))
        return got
    recipe = work_out(solver.mech, motion, kind)
    kinds.insert(0, recipe)
    return follow(recipe, motion, mu)


def work_out(mech: Mechanism, m: Motion, kind: str) -> Recipe:
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
    # two points within ``near`` of each other are one place: no base for a figure; the
    # mechanism's size is how far its points lie from one of them, whatever drives it
    first = next(iter(pos.values()))
    near = tolerances.SAME_PLACE * max(abs(z - first) for z in pos.values())

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
            # the figure's base: the first point found, and the next one apart from it
            b1 = next((b for b in base[1:] if abs(pos[b] - pos[base[0]]) > near), None)
            if b1 is not None:
                b0 = base[0]
                n0, n1 = plan_name(b0), plan_name(b1)
                # a fixed point lies at the pole, and is written by the pole's letter
                w0, w1 = (pole if b in mech.frame else nb for b, nb in ((b0, n0), (b1, n1)))
                eqs = (f"{w0}{nx} = {w0}{w1}·{b0}{name}/{b0}{b1}",
                       f"△{w0}{w1}{nx} ∼ △{b0}{b1}{name}")
                if name in own and b0 in own and b1 in own:
                    # three points of the rigid figure: the ratio is the figure's own
                    ratio = (own[name] - own[b0]) / (own[b1] - own[b0])
                    off_line = abs(ratio.imag) >= tolerances.RATIO_IN_LINE
                    src = Source("similarity", eqs[off_line], (), n0, n1, ratio)
                    steps.append((FIGURE, nx, n0, n1, ratio, src, absolute(name)))
                else:  # a coincident point: where it is on the link changes with φ
                    steps.append((SIMILAR, nx, name, b0, b1, n0, n1, eqs, absolute(name)))
            else:
                same.extend((base[0], b) for b in base[1:] if (base[0], b) not in same)
                moves = base[0] if base else "its guide"
                src = Source("rigid", equation=f"{sym}_{name}: link {lid} moves with {moves}")
                steps.append((VALUE, nx, name, src, absolute(name)))
            known.add(name)
            base.append(name)

    for name in mech.frame:
        steps.append((POLE, plan_name(name), PlanPoint(plan_name(name), 0j, __POLE_SOURCE)))
        known.add(name)
    drv = mech.driver
    for d in mech.drivers:
        steps += driver_steps(d, acc, pole, counters, absolute(d.tip))
        known.add(d.tip)
        similar(d.link)
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
                src = Source("component", equation=term_formula(t), base=start, label=t.label)
                steps.append((TERM, tname, start, gi, ri, ti, src,
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
        steps.append((CROSS, pn, new, gi, tuple(lines), cons.equation, absolute(new),
                      line_vectors))
        known.add(new)
        for lid in (g.group.a, g.group.b):
            similar(lid)
    ends = segments_of(steps, pole)
    return Recipe(kind, pole, drv.tip, tuple(steps), tuple(same), near, ends,
                   compile_steps(kind, pole, drv.tip, steps, ends, near))


def accelerating(d) -> bool:
    """Whether the crank ``d`` may have an angular acceleration: an ε of its own, or a
    law in time that is not uniform. Its acceleration plan then lays off the crank pin's
    normal and tangential components, as the method does for any point turning about a
    centre; a crank turning uniformly has the normal one only, a^n_AO = a_A."""
    return not d.linear and (d.epsilon != 0 or (d.law is not None and d.law.kind != "uniform"))


def driver_steps(d, acc: bool, pole: str, counters: dict, vec: PlanVector) -> list[tuple]:
    """The steps of an input's pin: its velocity V_A = ω1·l_OA (⊥ OA); its acceleration
    a_A = a^n_AO (∥ AO, towards O), with a^t_AO = ε1·l_OA (⊥ OA) laid from the normal one's
    end where the crank accelerates; a slider's velocity and acceleration along its
    guide, as given."""
    tip, pn = d.tip, plan_name(d.tip)
    if d.linear:
        sym = "a" if acc else "V"
        src = Source("driver", equation=f"{sym}_{tip}: the input's, given", label=f"∥ {d.guide.label}")
        return [(VALUE, pn, tip, src, vec)]
    o, w, e = d.pivot, d.omega_sym, f"ε{d.link}"
    if not acc:
        eq = f"V_{tip} = {w}·l_{o}{tip}"
        rel = f"⊥ {o}{tip}, in the sense of {w}"
        return [(VALUE, pn, tip, Source("driver", equation=eq, label=rel), vec)]
    if not accelerating(d):
        eq = f"a_{tip} = a^n_{tip}{o} = {w}²·l_{o}{tip}"
        rel = f"∥ {tip}{o}, from {tip} to {o}"
        return [(VALUE, pn, tip, Source("driver", equation=eq, label=rel), vec)]
    counters["n"] += 1
    nn = f"n{counters['n']}"
    normal, tangential = f"a^n_{tip}{o}", f"a^t_{tip}{o}"
    nsrc = Source("driver", equation=f"{normal} = {w}²·l_{o}{tip}, directed from {tip} to {o}",
                  label=normal)
    tsrc = Source("driver", equation=f"a_{tip} = {normal} + {tangential}; {tangential} = {e}·l_{o}{tip}",
                  base=nn, label=f"⊥ {o}{tip}, in the sense of {e}")
    return [(DRIVER_N, nn, tip, o, d.link, nsrc, PlanVector(pole, nn, "normal", normal)),
            (DRIVER_T, pn, tip, nn, tsrc, vec, PlanVector(nn, pn, "tangential", tangential))]


def segments_of(steps, pole: str) -> Mapping[str, tuple[str, str]]:
    """The plan's drawn segments, name → (from, to): pole to every point found (not the
    poles, not the ends of known components), then every component vector; the absolute
    vectors are the pole-to-point segments already. Read-only: every plan of the recipe
    shares it."""
    out = {pole + st[1]: (pole, st[1]) for st in steps
           if st[0] in (VALUE, SIMILAR, FIGURE, CROSS, DRIVER_T)}
    for st in steps:
        for v in ((st[7],) if st[0] == TERM else st[7] if st[0] == CROSS else (st[6],)
                  if st[0] in (DRIVER_N, DRIVER_T) else ()):
            out.setdefault(v.start + v.end, (v.start, v.end))
    return MappingProxyType(out)


def follow(recipe: Recipe, m: Motion, mu) -> Plan:
    """The plan at the motion's angle, by the recipe's steps (compiled once: see
    :func:`compile_steps`)."""
    if recipe.kind == "acceleration":
        return recipe.follow(m.acceleration, [g.acceleration for g in m.groups], m.position, mu,
                             m.links)
    return recipe.follow(m.velocity, [g.velocity for g in m.groups], m.position, mu)


def compile_steps(kind: str, pole: str, tip: str, steps, ends, near: float = 0.0):
    """The recipe's steps as one Python function ``follow(store, cons, pos, mu, links) -> Plan``
    (``links``: the motion's link states, which a crank's normal component reads its ω from).

    Following the steps one by one (unpacking each, dispatching on its kind, looking
    every earlier vector up by name) took two thirds of a plan's time; written out once
    as straight-line code over local variables, the same arithmetic and the same records
    take a third of it. The names, equations, labels and vectors of the steps enter the
    code as constants (``K0``, ``K1`` …), never as source text. Each step's lines:

    * a pole: its constant record, vector 0;
    * the crank's pin or a point of a translating link: the vector solved (``store``);
    * a point of a rigid figure: by its fixed complex ratio to two points found;
    * a coincident point: by the ratio of where it is on its link at this angle (its base's
      two points within ``near`` of each other are no base: the recipe does not hold,
      as where they meet);
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
        if op == POLE:
            var[pn] = "0j"
            points.append((pn, "0j", k(step[2])))
            continue
        if op == VALUE:
            _, _, name, src, vec = step
            body.append(f"{v} = store[{name!r}]")
            rec = f"record(PlanPoint, ({pn!r}, {v}, {k(src)}))"
        elif op == FIGURE:
            _, _, n0, n1, ratio, src, vec = step
            body.append(f"{v} = {var[n0]} + {k(ratio)} * ({var[n1]} - {var[n0]})")
            rec = f"record(PlanPoint, ({pn!r}, {v}, {k(src)}))"
        elif op == SIMILAR:
            _, _, name, b0, b1, n0, n1, eqs, vec = step
            body.append(f"d{i} = pos[{b1!r}] - pos[{b0!r}]")
            body.append(f"if abs(d{i}) <= {near!r}: raise ZeroDivisionError")
            body.append(f"q{i} = (pos[{name!r}] - pos[{b0!r}]) / d{i}")
            body.append(f"{v} = {var[n0]} + q{i} * ({var[n1]} - {var[n0]})")
            rec = (f"record(PlanPoint, ({pn!r}, {v}, record(Source, ('similarity', "
                   f"{k(eqs)}[abs(q{i}.imag) >= {tolerances.RATIO_IN_LINE!r}], (), {n0!r}, {n1!r}, q{i}, "
                   "1.0, ''))))")
        elif op == DRIVER_N:  # the crank pin's normal component, towards its pivot
            _, _, tip, centre, link, src, vec = step
            body.append(f"{v} = (pos[{centre!r}] - pos[{tip!r}]) * (links[{link!r}].omega ** 2)")
            var[pn] = v
            points.append((pn, v, f"record(PlanPoint, ({pn!r}, {v}, {k(src)}))"))
            vectors.append(k(vec))
            continue
        elif op == DRIVER_T:  # the pin itself, its tangential component from the normal's end
            _, _, name, _base, src, vec, tvec = step
            body.append(f"{v} = store[{name!r}]")
            var[pn] = v
            points.append((pn, v, f"record(PlanPoint, ({pn!r}, {v}, {k(src)}))"))
            absolute(v, vec)
            vectors.append(k(tvec))
            continue
        elif op == TERM:
            _, _, start, gi, ri, ti, src, vec = step
            term = f"cons[{gi}].routes[{ri}].terms[{ti}].value"
            body.append(f"{v} = {term}" if start == pole else f"{v} = {var[start]} + {term}")
            var[pn] = v
            points.append((pn, v, f"record(PlanPoint, ({pn!r}, {v}, {k(src)}))"))
            vectors.append(k(vec))
            continue
        else:  # CROSS
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
        else f"{key!r}: (m_ if (m_ := abs({var[b]}) / mu) > tiny_mm else 0.0)"
        for key, (a, b) in ends.items())
    unit = "m/s²" if kind == "acceleration" else "m/s"
    source = "\n".join([
        "def follow(store, cons, pos, mu, links=None):",
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


def term_formula(t) -> str:
    x, y = t.about
    if t.kind == "normal":
        return f"{t.label} = V_{x}{y}²/l_{x}{y}, directed from {x} to {y}"
    return f"{t.label} = 2·ω·V_{x}{y}, V_{x}{y} turned by 90° in the sense of ω"
