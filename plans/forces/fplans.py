"""A group's force plan as the textbook lays it: its known forces end to end from the pole
a, closed by two lines of known direction (or by one vector), each point with the step that
found it, every segment in mm at the plan's μF (a standard value) — a
:class:`plans.plan.Plan` of kind "force", which the sheet draws as it draws the velocity
and acceleration plans.
"""

from __future__ import annotations

from types import MappingProxyType

from plans.plan.solution import Plan as VectorPlan
from plans.plan.solution import PlanLine, PlanPoint, PlanVector, Source
from plans.scales import choose_mu

#: the force plan's longest vector is at most this long (mm) at the μF chosen
FORCE_PLAN_MM = 150.0
#: below this share of a plan's largest force, a force is rounding of 0 (as a plan's NOISE)
NOISE = 1e-13


_LETTERS = "abcdefghijklmnopqrstuvwxyz"


def _letters():
    """a, b, … z, then a1, b1 …: a force plan's points."""
    n = 0
    while True:
        yield _LETTERS[n % 26] + (str(n // 26) if n >= 26 else "")
        n += 1


def _laid(vectors, names):
    """Vectors laid end to end from the pole: (points, plan vectors, segment ends, end)."""
    pole = next(names)
    at, here = 0j, pole
    points = {pole: PlanPoint(pole, 0j, Source("pole"))}
    out, ends = [], {}
    for label, comp, value in vectors:
        nxt = next(names)
        at = at + value
        points[nxt] = PlanPoint(nxt, at, Source("component", base=here, label=label))
        out.append(PlanVector(here, nxt, comp, label))
        ends[label] = (here, nxt)
        here = nxt
    return pole, points, out, ends, here


def _finish(pole, points, vectors, ends, mu_F) -> VectorPlan:
    big = max(
        [abs(p.value) for p in points.values()]
        + [abs(points[b].value - points[a].value) for a, b in ends.values()]
        + [0.0]
    )
    mu = mu_F or choose_mu(big, big, FORCE_PLAN_MM, FORCE_PLAN_MM)
    tiny = NOISE * big
    segments = {}
    for label, (a, b) in ends.items():
        size = abs(points[b].value - points[a].value)
        segments[label] = size / mu if size > tiny else 0.0
    return VectorPlan(
        "force",
        pole,
        points,
        tuple(vectors),
        mu,
        "N",
        MappingProxyType(segments),
        MappingProxyType(dict(ends)),
        tiny,
    )


def closed_plan(known, last, first, sine, mu_F, wholes, inner, A) -> VectorPlan:
    """A polygon of ``known`` vectors closed by two lines: ``last`` (name, direction,
    relation, its value) through the end, ``first`` through the pole; the reactions
    ``wholes`` (their two components' sums) and the inner reaction ``inner`` drawn as the
    resultants they are."""
    names = _letters()
    pole, points, vectors, ends, end = _laid(known, names)
    meet = next(names)
    value = points[end].value + last[3]
    eq = " + ".join([v.label for v in vectors] + [last[0], first[0]]) + " = 0"
    lines = (PlanLine(end, last[1], last[2], last[0]), PlanLine(pole, first[1], first[2], first[0]))
    points[meet] = PlanPoint(
        meet, value, Source("intersection", equation=eq, lines=lines, sine=float(abs(sine)))
    )
    vectors += [PlanVector(end, meet, "closing", last[0]), PlanVector(meet, pole, "closing", first[0])]
    ends[last[0]] = (end, meet)
    ends[first[0]] = (meet, pole)
    _resultants(points, vectors, ends, wholes, inner, A, pole, meet)
    return _finish(pole, points, vectors, ends, mu_F)


def _resultants(points, vectors, ends, wholes, inner, A, pole, meet):
    """Each reaction found as two components, drawn whole (from the start of its first
    component to the end of its second), and the inner reaction closing link a's own
    polygon."""
    for r in wholes:
        if r.tangential is None:
            continue
        t0, t1 = ends[r.name + "^τ"]
        n0, n1 = ends[r.name + "^n"]
        a, b = (n0, t1) if n1 == t0 else (t0, n1)
        vectors.append(PlanVector(a, b, "reaction", r.name))
        ends[r.name] = (a, b)
    # link a's loads run from the end of its first reaction's component on
    a_labels = [ld.name for ld in A if ld.force != 0]
    if a_labels:
        start = ends[a_labels[-1]][1]
    else:
        start = ends[wholes[0].name + "^τ"][1] if wholes[0].tangential is not None else pole
    vectors.append(PlanVector(start, meet, "reaction", inner.name))
    ends[inner.name] = (start, meet)


def vector_plan(known, closing, mu_F, inner, A) -> VectorPlan:
    """A polygon of known vectors closed by one vector back to the pole (the slotted
    link's frame reaction), and the block's own polygon closed by ``inner``."""
    names = _letters()
    pole, points, vectors, ends, end = _laid(known, names)
    vectors.append(PlanVector(end, pole, "closing", closing[0]))
    ends[closing[0]] = (end, pole)
    a_labels = [ld.name for ld in A if ld.force != 0]
    start = ends[a_labels[-1]][1] if a_labels else ends[known[0][0]][1]
    vectors.append(PlanVector(start, pole, "reaction", inner.name))
    ends[inner.name] = (start, pole)
    return _finish(pole, points, vectors, ends, mu_F)


def yoke_plan(b_vectors, outer, inner_b, a_vectors, RP, sine, mu_F) -> VectorPlan:
    """RPP: link b's polygon F_b + N_kb + N_ab = 0 closed by lines ⊥ the outer and ⊥ the
    inner guide; then the block's: N_ba + F_a + R_Pa = 0 from the meeting point."""
    names = _letters()
    pole, points, vectors, ends, end = _laid(b_vectors, names)
    meet = next(names)
    value = points[end].value + outer[3]
    eq = " + ".join([v.label for v in vectors] + [outer[0], inner_b[0]]) + " = 0"
    lines = (PlanLine(end, outer[1], outer[2], outer[0]), PlanLine(pole, inner_b[1], inner_b[2], inner_b[0]))
    points[meet] = PlanPoint(
        meet, value, Source("intersection", equation=eq, lines=lines, sine=float(abs(sine)))
    )
    vectors += [PlanVector(end, meet, "closing", outer[0]), PlanVector(meet, pole, "closing", inner_b[0])]
    ends[outer[0]] = (end, meet)
    ends[inner_b[0]] = (meet, pole)
    here, at = pole, 0j
    for label, comp, v in a_vectors:  # the block's loads from the pole: N_ba = pole → meet reversed
        nxt = next(names)
        at = at + v
        points[nxt] = PlanPoint(nxt, at, Source("component", base=here, label=label))
        vectors.append(PlanVector(here, nxt, comp, label))
        ends[label] = (here, nxt)
        here = nxt
    vectors.append(PlanVector(here, meet, "closing", RP.name))
    ends[RP.name] = (here, meet)
    return _finish(pole, points, vectors, ends, mu_F)
