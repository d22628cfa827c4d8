"""Check a hand-drawn plan against the computed one, and name the mistake.

A student measures segments on the drawing (pa3, aa3, πa3, n1a3…) in millimetres at the
scale factors they chose, and perhaps writes down ω, ε and a few values. :func:`load`
reads such a measurement file, :func:`check` compares every item with the exact plans at
the student's scales and, where something is beyond tolerance, :func:`diagnose` redraws
the plans under each common mistake and keeps the one mistake that explains the
measurements. Everything here returns data (:class:`Deviation`, :class:`Finding`,
:class:`Diagnosis`); nothing about a student's error is an exception.

How a mistake is simulated: the plans are replayed point by point from their recorded
constructions (each :class:`~plans.plan.PlanPoint` knows its :class:`~plans.plan.Source`):
poles and the crank as given, a known component (a^n, a^k) recomputed from the student's
own velocity plan exactly as they would (a^n = V²/l towards the centre, a^k = 2·ω·V_rel
turned by 90° in the sense of ω), the intersection of the two recorded lines, and the
similarity ratio. A mistake changes one step (a term reversed, omitted or 10 times off, a
line turned by 90°, another ratio) and everything after it follows, as on paper. The
other assembly branch is a new solution with that group's sign flipped; a scale mistake
multiplies the lengths of one plan.

Reading of "ω with the wrong sense": the student reads ω of link k from their velocity
plan and takes its sense the wrong way; the magnitude stays, the reported sense of ωk is
reversed, and every Coriolis vector that turns a relative velocity in the sense of ωk is
turned the other way. ε is then read off the student's (so mistaken) acceleration plan,
as a^t / l with the sense of a^t, which is where a reversed ε comes from. Without a
reported sense of ωk this mistake draws the same plans as "Coriolis vector reversed";
both are then named.

The items of a force analysis (:mod:`plans.check.forces`) are compared with the exact force
analysis at the student's scales, and its mistakes replayed as the plans' are: the loads
changed and the same group walk, the lever not turned, a plan at another μF. A mistake of
the plans carries over to the forces drawn on them.

Reading of "ω1 with the wrong sense": the student lays off the crank's V_A the other way
round. Every velocity is proportional to ω1, so the whole velocity plan is reflected
through p (no length changes) and every ω read off it turns the other way; the
accelerations are those of ω1² and ε1, and the student keeps ε1 as given (0 for a
uniformly turning crank), so the acceleration plan and every ε are the exact ones. Only
the senses of the ω written down show this mistake.
"""

from __future__ import annotations

import math
from collections import Counter
from dataclasses import dataclass, field, replace

from plans.check import forces
from plans.check.items import (  # noqa: F401  (the public names of the check live here)
    MU_KEY,
    PLANS,
    SIGNED,
    Item,
    Tolerance,
    parse_tolerance,
)
from plans.check.measured import (  # noqa: F401
    SENSE_WORDS,
    Measurement,
    from_dict,
    load,
    recorded_segments,
)
from plans.check.rebuild import rebuild  # noqa: F401  (the overlay's, by this name)
from plans.check.replay import (  # noqa: F401
    Degenerate,
    Mistake,
    Replayer,
    State,
    at_angle,
    cons_point,
    expected,
    hypotheses,
    reading_pairs,
    scale_example,
    simulate,
)
from plans.check.words import WORDS
from plans.errors import PlansError
from plans.geometry import apart, golden_min
from plans.plan.solution import plan_name
from plans.scales import series


@dataclass(frozen=True, slots=True)
class Deviation:
    item: Item
    computed: float  # signed for ω, ε
    deviation: float  # measured − computed (magnitudes)
    percent: float  # of the computed magnitude; nan when it is 0
    limit: float  # the allowed |deviation|
    ok: bool
    sense_ok: bool | None = None  # ω, ε with a sense given


def compare(item: Item, computed: float, tol: Tolerance) -> Deviation:
    mag = abs(computed)
    dev = item.measured - mag
    limit = tol.limit(mag, item.per_mm)
    pct = dev / mag * 100.0 if mag > 0 else math.nan
    sense_ok = None
    if item.kind in SIGNED and item.sense and mag > limit:
        sense_ok = (item.sense > 0) == (computed > 0)
    ok = abs(dev) <= limit * (1 + 1e-9) + 1e-12 and sense_ok is not False
    return Deviation(item, float(computed), float(dev), float(pct), float(limit), ok, sense_ok)


@dataclass(frozen=True)
class Finding:
    """How well one mistake explains the measurements."""

    mistake: Mistake
    explained: tuple[str, ...]  # items beyond tolerance that the mistake brings within
    unexplained: tuple[str, ...]  # items beyond tolerance that stay beyond
    broken: tuple[str, ...]  # items within tolerance that the mistake would put beyond
    score: float  # Σ (deviation / limit)² over all items under the mistake
    state: State | None = field(default=None, compare=False, repr=False)


@dataclass(frozen=True)
class Lookalike:
    """A measurement beyond tolerance that is, within tolerance, something else: another
    segment from one of its ends (measured from the wrong point), the segment of another
    item (two measurements swapped), its own value in SI units written as a length, or a
    value written as its segment's length in mm."""

    item: str  # the item's name, "pc"
    kind: str  # "segment", "swapped", "value", or "length" (a value written as its mm)
    other: str  # "ac", the other item's name, the value's symbol "V_C", or a segment "pc"
    exact: float  # the other segment's length (mm) or the value (m/s, m/s²)


@dataclass(frozen=True)
class Diagnosis:
    best: Finding | None  # the mistake that explains the measurements, if one does
    alternatives: tuple[Finding, ...] = ()  # mistakes that explain them as well
    closest: Finding | None = None  # when none does: the one that came nearest
    tried: int = 0
    lookalikes: tuple[Lookalike, ...] = ()  # for the items no mistake explains


@dataclass(frozen=True)
class CheckResult:
    measurement: Measurement
    tolerance: Tolerance
    deviations: tuple[Deviation, ...]
    diagnosis: Diagnosis

    @property
    def ok(self) -> bool:
        return all(d.ok for d in self.deviations)

    @property
    def failed(self) -> tuple[Deviation, ...]:
        return tuple(d for d in self.deviations if not d.ok)

    @property
    def slips_only(self) -> bool:
        """No mistake of construction is named, and every item beyond tolerance matches
        something else (:class:`Lookalike`): the plans are right, the slips are in the
        items (two swapped, one measured from the wrong point, one written in m/s)."""
        failed = {d.item.name for d in self.failed}
        return (self.diagnosis.best is None and bool(failed)
                and failed <= {lk.item for lk in self.diagnosis.lookalikes})


def check(meas: Measurement, tol: Tolerance | None = None, *, diagnose_: bool = True) -> CheckResult:
    """Compare every measured item with the exact plans; diagnose what is beyond tolerance."""
    tol = tol or meas.tolerance or Tolerance()
    st = redraw(meas)
    devs = tuple(compare(it, expected(it, st, meas.mu), tol) for it in meas.items)
    diag = diagnose(meas, devs, tol, exact=st) if diagnose_ else Diagnosis(None)
    if diagnose_ and not all(d.ok for d in devs):
        diag = _closer_slips(meas, devs, st, tol, diag)
        left = set(diag.best.unexplained) if diag.best else {d.item.name for d in devs if not d.ok}
        # what the items left over match is read off the plans the student drew: those of
        # the mistake just named, where there is one
        drawn, drawn_devs = st, devs
        if diag.best is not None and diag.best.state is not None:
            drawn = diag.best.state
            drawn_devs = tuple(compare(it, expected(it, drawn, meas.mu), tol) for it in meas.items)
        diag = replace(diag, lookalikes=lookalikes(meas, drawn_devs, drawn, tol, left))
    return CheckResult(meas, tol, devs, diag)


def _closer_slips(meas: Measurement, devs: tuple[Deviation, ...], st: State, tol: Tolerance,
                  diag: Diagnosis) -> Diagnosis:
    """The mistake named, unless the items it explains are each, on the exact plans, a
    slip of their own (:func:`lookalikes`) that fits the measurement more closely than the
    mistake's plan does: then no mistake is named, the slips say what happened, and the
    mistake is the closest. The slip must be closer by a quarter of the tolerance
    (:data:`_MATCH`). On variant 9, ps2 = 62.3 mm measured from b (bs2 is 62.34 mm)
    had been "s2 found with the ratio meant for e" (|pe| = 65.05 mm, within tolerance):
    a mistake of one item, fitted loosely, had won over the match to 0.04 mm."""
    best = diag.best
    if best is None or best.state is None or best.unexplained:
        return diag
    found = {lk.item: lk for lk in lookalikes(meas, devs, st, tol, set(best.explained))}
    for d in devs:
        it = d.item
        if it.name not in best.explained:
            continue
        lk = found.get(it.name)
        # closer by a clear margin: where the two readings draw the same length (c from
        # the other end of a3c is a3c), the mistake stays
        miss = abs(it.measured - expected(it, best.state, meas.mu))
        if lk is None or miss - abs(it.measured - lk.exact) <= _MATCH * d.limit:
            return diag
    return Diagnosis(None, (), best, diag.tried)


def lookalikes(meas: Measurement, devs: tuple[Deviation, ...], st: State, tol: Tolerance,
               names: set[str]) -> tuple[Lookalike, ...]:
    """What each of the items ``names`` (segments of the velocity and acceleration plans,
    beyond tolerance) matches instead, within tolerance: two items swapped; the item's
    value in m/s or m/s² written as a length (where μ is not 1); another segment from one
    of its ends, the nearest. Only the segments of :func:`_wrong_points` are tried, so that
    a chance length among all the plan's pairs is not offered as a cause."""
    out: list[Lookalike] = []
    for d in devs:  # a value in m/s written as its segment's length in mm
        it = d.item
        if it.name in names and it.kind == "value" and it.plan in MU_KEY and _far(d):
            mu = meas.mu[MU_KEY[it.plan]]
            if abs(mu - 1.0) > 1e-9 and _mixup(it.measured, abs(d.computed) / mu, tol):
                out.append(Lookalike(it.name, "length", f"{it.start}{it.end}", abs(d.computed) / mu))
    # only an item far off its own length, matched closely: a measurement a little beyond
    # tolerance is drawing scatter
    bad = [d for d in devs if d.item.name in names and d.item.kind == "segment"
           and d.item.plan in ("velocity", "acceleration") and _far(d)]
    swapped: set[str] = set()
    for i, d in enumerate(bad):
        for e in bad[i + 1:]:
            if e.item.plan == d.item.plan and _near(d.item.measured, abs(e.computed), tol) \
                    and _near(e.item.measured, abs(d.computed), tol):
                out += [Lookalike(d.item.name, "swapped", e.item.name, abs(e.computed)),
                        Lookalike(e.item.name, "swapped", d.item.name, abs(d.computed))]
                swapped |= {d.item.name, e.item.name}
    sol = meas.solution
    mech_name = {plan_name(n): n for n in sol.positions}  # a3 → A3
    # the joints: points of two links or more, a slider's coincident point (a, a3, c)
    held = Counter(n for link in sol.mechanism.links.values() for n in link.points)
    joints = {plan_name(n) for n, k in held.items() if k > 1} | set(map(plan_name, sol.scalar.coincident))
    for d in bad:
        it = d.item
        if it.name in swapped:
            continue
        mu = meas.mu[MU_KEY[it.plan]]
        value = abs(d.computed) * mu
        plan = sol.velocity if it.plan == "velocity" else sol.acceleration
        pole = plan.pole
        names_ = [mech_name.get(x) for x in (it.end, it.start) if x != pole]
        # a value for a segment between mechanism points (not a component's n or k), in
        # m/s: 1 mm of drawing is μ of it
        if abs(mu - 1.0) > 1e-9 and None not in names_ and _mixup(it.measured, value, tol, per_mm=mu):
            sym = "V" if it.plan == "velocity" else "a"
            out.append(Lookalike(it.name, "value", f"{sym}_{''.join(names_)}", value))
            continue
        vals = st.values(it.plan)
        # a fixed point's letter stands at the pole (o, b): it is the pole, not another end
        ends = [x for x in vals if x == pole or abs(vals[x] - vals[pole]) > 1e-12 * mu]
        best = None
        for a, b in _wrong_points(it, plan, ends, joints):
            length = abs(vals[b] - vals[a]) / mu * st.factor[it.plan]
            if _near(length, abs(d.computed), tol) or not _near(it.measured, length, tol, _MATCH):
                continue  # as long as the item itself, or no close match
            if best is None or abs(it.measured - length) < abs(it.measured - best[1]):
                best = (f"{a}{b}", length)
        if best is not None:
            out.append(Lookalike(it.name, "segment", *best))
    return tuple(out)


#: a look-alike matches within this share of the tolerance: a quarter, ±1.25 % or
#: ±0.25 mm (half of it, and πd 15 % off the student's plan with the Coriolis vector
#: reversed, 56.2 mm, was "the length of ad", 55.3 mm)
_MATCH = 0.25


def _wrong_points(it: Item, plan, ends: list[str], joints: set[str]) -> list[tuple[str, str]]:
    """The segments a student measures instead of ``it`` when one of its ends is taken at
    the wrong point, start first: the plan's vectors that share an end with ``it``, and
    for a vector from the pole the segment to its end from a joint of the mechanism (pc
    measured from a is ac, the relative velocity V_CA). Not the distance from a
    construction point (k, n1) or a link's own point (a centre of mass s4) to any other
    point, nor a side of a similarity figure, nor another vector from the pole in place of
    one: a plan has many of these, of like lengths, and one of them lies near a wrong
    length by chance ("n1a3 = 17.11 mm is the length of n1s4"). One segment of the exact
    plans of four mechanisms scaled by a random factor (0.3–0.8 or 1.25–3) drew a look-alike
    1 time in 8 from any two points of the plan within half the tolerance; from these,
    within a quarter of it (:data:`_MATCH`), about 1 in 75, while a wrong point measured to
    ±0.2 mm is named 29 times in 30 (to ±0.4 mm, 5 in 7)."""
    pole = plan.pole
    drawn = _drawn(plan)

    def at(x: str) -> str:  # a fixed point's letter is the pole
        return x if x in ends else pole

    from_pole = at(it.start) == pole
    out = []
    for x in ends:
        if x in (it.start, it.end) or at(it.end) == x:
            continue
        if frozenset((x, at(it.end))) in drawn or (from_pole and x in joints):
            out.append((x, it.end))
    if not from_pole:
        for x in ends:
            if x not in (it.start, it.end) and at(it.start) != x and frozenset((at(it.start), x)) in drawn:
                out.append((it.start, x))
    return out


def _drawn(plan) -> set[frozenset[str]]:
    """The vectors a student draws on ``plan``, as pairs of point names (a fixed point's
    letter standing for the pole)."""
    pole = plan.pole
    at_pole = {n for n, p in plan.points.items() if p.source.kind == "pole"}

    def name(n: str) -> str:
        return pole if n in at_pole else n

    return {frozenset((name(v.start), name(v.end))) for v in plan.vectors}


def _near(measured: float, exact: float, tol: Tolerance, share: float = 1.0,
          per_mm: float = 1.0) -> bool:
    """Within ``share`` of the tolerance, as :func:`compare` judges an item whose 1 mm of
    drawing is ``per_mm`` of it."""
    return abs(measured - exact) <= share * tol.limit(exact, per_mm) * (1 + 1e-9) + 1e-12


def _mixup(measured: float, exact: float, tol: Tolerance, per_mm: float = 1.0) -> bool:
    """``measured`` is ``exact`` in the other unit (a value in m/s written as its segment's
    mm, or a segment written as its value): within tolerance of it, and ``exact`` stands
    clear of zero, at least twice the tolerance. Near zero the tolerance's fixed part
    matches any small number: at a dead point V_C = 0.1 m/s is no more "the length of pc"
    (0 mm, ±1 mm) than it is V_C (0 m/s)."""
    return exact >= 2.0 * tol.limit(exact, per_mm) and _near(measured, exact, tol, per_mm=per_mm)


def _far(d: Deviation) -> bool:
    """Off by more than one and a half times its tolerance: a wrong measurement, not
    scatter. (Three times, while any two points of a plan were a look-alike; a segment
    measured from the wrong point of a plan drawn with a mistake can be nearer its own
    length than that: πc from a on a plan with the Coriolis vector reversed is 43.6 mm
    where πc is 47.7. Drawing scatter of 4 % and 0.5 mm made no look-alike in 800 plans
    of four mechanisms, nor in 320 with a mistake.)"""
    return abs(d.deviation) > 1.5 * d.limit


def diagnose(meas: Measurement, devs: tuple[Deviation, ...], tol: Tolerance,
             exact: State | None = None) -> Diagnosis:
    """Redraw the plans under each common mistake; keep the one that explains the
    deviations (all of them, or all but one in four) without spoiling what was right.
    ``exact``: the exact plans, where the caller has them already."""
    bad = [i for i, d in enumerate(devs) if not d.ok]
    if not bad:
        return Diagnosis(None)
    items = meas.items
    plans = {it.plan for it in items} & set(PLANS)  # the plans measured (not the forces)
    findings: list[Finding] = []
    tried = 0

    def judge(mistakes) -> None:
        nonlocal tried
        for mk in mistakes:
            got = _redrawn(meas, lambda mk=mk: redraw(meas, mk), tol)
            if got is None:
                continue
            st, sim = got
            tried += 1
            explained = tuple(items[i].name for i in bad if sim[i].ok)
            if not explained:
                continue
            unexplained = tuple(items[i].name for i in bad if not sim[i].ok)
            broken = tuple(items[i].name for i, d in enumerate(devs) if d.ok and not sim[i].ok)
            findings.append(Finding(mk, explained, unexplained, broken, _misfit(sim), st))

    if plans:
        judge([*hypotheses(meas.solution, plans), *_fitted_scales(meas, devs)])
    if meas.forces is not None:
        judge([*forces.hypotheses(meas.forces, items), *forces.fitted_scales(meas.forces, devs)])
    # the plans of another crank angle, only where no mistake above explains everything
    # without spoiling a thing, nor do slips of the items on the exact plans (two swapped,
    # one from the wrong point: an ordinary file, checked as fast as before): its search
    # solves some two hundred positions
    if plans and not any(not f.broken and not f.unexplained for f in findings):
        if exact is None:
            exact = Replayer(meas.solution).exact()
        failed = {items[i].name for i in bad}
        if not failed <= {lk.item for lk in lookalikes(meas, devs, exact, tol, failed)}:
            judge(fitted_angle(meas, devs, tol))
    allowed = (len(bad) - 1) // 4
    # mistakes that draw the same plans score the same but for the last digits: scores are
    # compared to 9 digits, and the sorts being stable, the hypotheses' order of
    # preference chooses among equals, not the rounding
    accepted = sorted((f for f in findings if not f.broken and len(f.unexplained) <= allowed),
                      key=lambda f: (len(f.unexplained), _score(f)))
    if accepted:
        best = accepted[0]
        alts = tuple(
            f for f in accepted[1:]
            if len(f.unexplained) == len(best.unexplained)
            and f.score <= best.score * 1.25 + 0.25
        )[:3]
        return Diagnosis(best, alts, None, tried)
    near = sorted((f for f in findings if not f.broken),
                  key=lambda f: (-len(f.explained), _score(f)))
    return Diagnosis(None, (), near[0] if near else None, tried)


def redraw(meas: Measurement, mk: Mistake | None = None, st: State | None = None) -> State:
    """The plans a student who makes the mistake ``mk`` draws (None: the exact ones; ``st``:
    drawn already, another crank angle's), and where the file measures forces, the force
    analysis on them (:mod:`plans.check.forces`): a mistake of the plans carries over."""
    if st is None:
        st = simulate(meas.solution, None if mk is not None and mk.kind in forces.KINDS else mk, meas.mu)
    if meas.forces is not None:
        st = replace(st, forces=meas.forces.drawn(st, mk))
    return st


def _redrawn(meas: Measurement, drawn, tol: Tolerance) -> tuple[State, list[Deviation]] | None:
    """The plans ``drawn()`` gives (a mistake's, another crank angle's) and the items
    compared on them; None where those plans cannot be drawn."""
    try:
        st = drawn()
        return st, [compare(it, expected(it, st, meas.mu), tol) for it in meas.items]
    except (Degenerate, PlansError, ZeroDivisionError, KeyError):
        return None


def _misfit(sim: list[Deviation]) -> float:
    """How far plans are from the measured items: the squares of each deviation in its
    tolerance, and 4 for each sense written the other way."""
    score = sum((d.deviation / d.limit) ** 2 if d.limit > 0 else 0.0 for d in sim)
    return float(score + sum(4.0 for d in sim if d.sense_ok is False))


def _score(f: Finding) -> float:
    """A finding's score to 9 digits, for ranking: equal plans tie."""
    return float(f"{f.score:.9g}")


def _fitted_scales(meas: Measurement, devs: tuple[Deviation, ...]) -> list[Mistake]:
    """A plan drawn at a scale factor other than the one written down, by any factor: the
    ratio of its measured segments to the exact ones, where two or more segments of it are
    measured and the ratio is 15 % or more off 1 (10 and 0.1 are among the common mistakes).
    Whether it explains them, and spoils none that was right, is judged as for any other
    mistake."""
    out = []
    ratios: dict[str, float] = {}
    for plan in PLANS:
        pairs = [(d.item.measured, abs(d.computed)) for d in devs
                 if d.item.kind == "segment" and d.item.plan == plan and d.computed]
        if len(pairs) < 2:
            continue  # one segment could be anything
        # the ratio of the sums: the long segments, measured to the same ±mm, weigh most
        r = ratios[plan] = sum(m for m, _ in pairs) / sum(c for _, c in pairs)
        # a μ mistake is a step of the standard series or more (0.04 for 0.05: 20 %), not
        # the few per cent that drawing scatter leaves on two or three segments
        if r > 0 and abs(r - 1) >= 0.15 and not any(abs(r / f - 1) < 0.05 for f in (10.0, 0.1)):
            stated = meas.mu[MU_KEY[plan]]
            fits = stated / r
            # a round factor that close is the one drawn at: the segments' own scatter
            # made the ratio 0.0999 where the student drew at 0.1
            near = min(series(fits / 1.2, fits * 1.2), key=lambda m: abs(m / fits - 1), default=fits)
            if abs(near / fits - 1) < 0.015:
                fits, r = near, stated / near
            out.append(Mistake("scale", plan, plan, r, info=((plan, r), ("fits", fits),
                                                             *scale_example(meas.solution, plan))))
    # ω1 computed wrongly (n1/30 without π, 2π·n1 without /60): the velocity plan r times
    # the exact one and the acceleration plan r² times, both at the μ written down
    r = ratios.get("velocity", 1.0)
    if "acceleration" in ratios and r > 0 and abs(r - 1) >= 0.15:
        drv = meas.solution.mechanism.driver
        out.append(Mistake("crank-omega", "both", drv.omega_sym, r, drv.link, info=(
            ("velocity", r), ("acceleration", r * r), ("omega", abs(drv.omega) * r),
            ("given", abs(drv.omega)), ("rpm", drv.rpm or ""), ("X", drv.tip), ("Y", drv.pivot))))
    return out


#: the plans of another crank angle, as the forces drawn on them take it
_ANGLE = Mistake("crank-angle")
#: the grid the crank angle of :func:`fitted_angle` is searched on, and how near the
#: given angle a fit is drawing scatter, not another position (rad)
_ANGLE_STEP = math.radians(2.0)
_ANGLE_APART = math.radians(2.5)


def fitted_angle(meas: Measurement, devs: tuple[Deviation, ...], tol: Tolerance) -> list[Mistake]:
    """The plans of another crank position: the crank drawn at a wrong angle on the plan
    of positions (measured from the other axis, the other way round, or another numbered
    position's), and both plans built for it, right. The angle whose exact plans fit the
    measured items best, on a 2° grid and then to 0.01°, more than 2.5° from the given
    one; within 0.25° of a whole number of degrees from it, that whole number (a student
    turns the crank by 15°, not 14.93°). Where two items or more are beyond tolerance
    only: some two hundred positions solved, 40–140 ms. Whether it explains them is judged
    as for any other mistake (:func:`diagnose` searches only where none of the others
    explains every item)."""
    if sum(not d.ok for d in devs) < 2:
        return []
    sol = meas.solution
    mu = meas.mu

    def misfit(phi: float) -> float:
        got = _redrawn(meas, lambda: redraw(meas, _ANGLE, at_angle(sol, phi, mu)), tol)
        return math.inf if got is None else _misfit(got[1])

    given = sol.phi
    grid = [given + k * _ANGLE_STEP for k in range(1, round(2 * math.pi / _ANGLE_STEP))]
    scored = [(misfit(phi), phi) for phi in grid if apart(phi, given) > _ANGLE_APART]
    best, phi = min(scored, default=(math.inf, given))
    if not math.isfinite(best):
        return []
    phi = golden_min(misfit, phi - _ANGLE_STEP, phi + _ANGLE_STEP, width=math.radians(0.01))
    turn = math.degrees((phi - given + math.pi) % (2 * math.pi) - math.pi)
    if abs(turn - round(turn)) < 0.25:
        phi = given + math.radians(round(turn))
    if apart(phi, given) <= _ANGLE_APART:
        return []
    at = sol.solver.at
    # the two angles in the words of every language the check speaks (at_en, given_ru…)
    words = [(f"{key}_{lang}", at(x, lang)) for lang in WORDS
             for key, x in (("at", phi), ("given", given))]
    return [Mistake("crank-angle", "both", sol.mechanism.driver.phi_sym,
                    info=(("phi", phi), *words))]
