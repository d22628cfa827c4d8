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
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import numpy as np

from .errors import InputError, PlansError
from .geometry import circle_circle, cross, intersect
from .kinematics import Solver
from .mechanism import Mechanism
from .plan import Plan, Solution, plan_name, solve_position
from .structure import DyadKind

PLANS = ("positions", "velocity", "acceleration")
MU_KEY = {"positions": "mu_l", "velocity": "mu_v", "acceleration": "mu_a"}
SENSE_WORDS = {"ccw": 1, "cw": -1, "против": 1, "по": -1}


# ---------------------------------------------------------------------------------------
# tolerance
# ---------------------------------------------------------------------------------------


@dataclass(frozen=True, slots=True)
class Tolerance:
    """A deviation is within tolerance when it is at most the larger of ``mm`` (on the
    drawing) and ``percent`` of the computed length."""

    percent: float = 5.0
    mm: float = 1.0

    def limit(self, computed: float, per_mm: float = 1.0) -> float:
        """The allowed deviation of an item whose 1 mm of drawing is ``per_mm`` units."""
        return max(self.mm * per_mm, self.percent / 100.0 * abs(computed))

    def describe(self, lang: str = "en") -> str:
        from .fmt import num

        if lang == "ru":
            return f"большее из {num(self.mm, 3, lang)} мм и {num(self.percent, 3, lang)} %"
        return f"the larger of {num(self.mm, 3)} mm and {num(self.percent, 3)} %"


def parse_tolerance(text: str, base: Tolerance | None = None) -> Tolerance:
    """``"5%"``, ``"1.5mm"``, ``"3%,0.5mm"`` → :class:`Tolerance` (unnamed parts stay).

    >>> parse_tolerance("3%")
    Tolerance(percent=3.0, mm=1.0)
    >>> parse_tolerance("0.5 mm, 2 %")
    Tolerance(percent=2.0, mm=0.5)
    """
    base = base or Tolerance()
    pct, mm = base.percent, base.mm
    token = r"(\d+(?:[.,]\d+)?)\s*(%|mm|мм)?"
    text = str(text).strip()
    if not re.fullmatch(rf"{token}(?:\s*[,;]?\s*{token})*", text):
        raise ValueError(f'"{text[:40]}" is not a tolerance (e.g. "5%", "1mm" or "5%,1mm")')
    for number, unit in re.findall(token, text):
        x = float(number.replace(",", "."))
        if not math.isfinite(x) or x > 1000:
            raise ValueError(f'"{number}" is out of range')
        if unit in ("mm", "мм"):
            mm = x
        else:
            pct = x
    return Tolerance(pct, mm)


# ---------------------------------------------------------------------------------------
# what the student measured
# ---------------------------------------------------------------------------------------


@dataclass(frozen=True, slots=True)
class Item:
    """One measured segment or one value the student wrote down.

    kind: "segment" (mm on a plan), "value" (m/s, m/s²), "omega", "epsilon" (rad/s,
    rad/s²). ``start``/``end``: plan point names (mechanism names on the plan of
    positions); ``per_mm``: how much of the item 1 mm of drawing is (for the tolerance).
    """

    key: str  # where in the file, e.g. "segments.pia3"
    name: str  # as shown, e.g. "πa3", "ω3", "V_A3"
    kind: str
    plan: str  # positions, velocity, acceleration
    measured: float
    start: str = ""
    end: str = ""
    link: int = 0
    sense: int = 0  # ω, ε: +1 ccw, −1 cw, 0 not given
    per_mm: float = 1.0

    @property
    def unit(self) -> str:
        return {"segment": "mm", "omega": "rad/s", "epsilon": "rad/s²"}.get(
            self.kind, "m/s" if self.plan == "velocity" else "m/s²")


@dataclass(frozen=True)
class Measurement:
    source: str
    mechanism: Mechanism
    solution: Solution  # the exact plans at the student's scale factors
    mu: dict[str, float]
    items: tuple[Item, ...]
    tolerance: Tolerance | None = None  # from the file
    title: str = ""
    angle_deg: float | None = None


TOP_KEYS = {"title", "mechanism", "variant", "table", "angle_deg", "tolerance", "scales",
            "segments", "values"}


def load(path: str | Path) -> Measurement:
    """Read and validate a measurement file; every problem is reported, located."""
    from .mechanism import read_toml

    data, text = read_toml(path, "a measurement file is a few KB")
    path = Path(path)
    return from_dict(data, str(path), path.parent, text=text)


def _raise(source: str, text: str | None, problems: list[str]):
    """Every problem at once, each "key: what" located to its line when the text is known."""
    from .mechanism import _Problems

    pr = _Problems(source, text)
    for p in problems:
        where, _, what = p.partition(": ")
        pr.add(where, what)
    raise InputError(source, pr.lines())


def _num(value: Any, where: str, problems: list[str], *, positive=False,
         nonneg=False) -> float | None:
    if isinstance(value, bool) or not isinstance(value, int | float):
        problems.append(f"{where}: must be a number, got {type(value).__name__} {value!r:.40}")
        return None
    x = float(value)
    if not math.isfinite(x) or abs(x) > 1e9:
        problems.append(f"{where}: {value!r:.40} is out of range")
        return None
    if positive and x <= 0:
        problems.append(f"{where}: must be positive, got {value}")
        return None
    if nonneg and x < 0:
        problems.append(f"{where}: a length on the drawing cannot be negative, got {value}")
        return None
    return x


def from_dict(data: dict, source: str = "<measurements>", folder: Path | None = None, *,
              text: str | None = None) -> Measurement:
    """Build a :class:`Measurement` from parsed TOML (the mechanism is loaded and solved)."""
    from . import mechanism as mechmod
    from . import variants

    problems: list[str] = []
    for key in data:
        if key not in TOP_KEYS:
            problems.append(f"{key}: unknown key (known: {', '.join(sorted(TOP_KEYS))})")
    title = data.get("title", "")
    if not isinstance(title, str) or len(title) > 300:
        problems.append("title: must be a text of at most 300 characters")
        title = ""
    # the mechanism -------------------------------------------------------------------
    mech = None
    has_file, has_var = "mechanism" in data, "variant" in data
    if has_file == has_var:
        problems.append('mechanism: give the mechanism file (mechanism = "press.toml") '
                        "or a variant (variant = 3), one of them")
    elif has_file:
        mpath = data["mechanism"]
        if not isinstance(mpath, str) or not mpath:
            problems.append(f"mechanism: must be a file name, got {mpath!r:.40}")
        else:
            p = Path(mpath)
            if not p.is_absolute() and folder is not None:
                p = folder / p
            if not p.is_file():
                problems.append(f"mechanism: {mpath}: no such file (paths are relative to "
                                "the measurement file)")
            else:
                mech = p
    else:
        var = data["variant"]
        if isinstance(var, bool) or not isinstance(var, int):
            problems.append(f"variant: must be a whole number, got {var!r:.40}")
        else:
            mech = var
    table = data.get("table")
    if table is not None:
        if not isinstance(table, str):
            problems.append("table: must be a file name")
            table = None
        elif folder is not None and not Path(table).is_absolute():
            table = str(folder / table)
    angle = None
    if "angle_deg" in data:
        angle = _num(data["angle_deg"], "angle_deg", problems)
    tol = None
    if "tolerance" in data:
        try:
            tol = parse_tolerance(data["tolerance"])
        except ValueError as exc:
            problems.append(f"tolerance: {exc}")
    mu: dict[str, float] = {}
    scales = data.get("scales", {})
    if not isinstance(scales, dict):
        problems.append("scales: must be a table, e.g. [scales] mu_v = 0.05")
        scales = {}
    for key, value in scales.items():
        if key not in MU_KEY.values():
            problems.append(f"scales.{key}: unknown key (known: mu_l, mu_v, mu_a)")
            continue
        x = _num(value, f"scales.{key}", problems, positive=True)
        if x is not None:
            mu[key] = x
    raw_segments = data.get("segments", {})
    if not isinstance(raw_segments, dict):
        problems.append("segments: must be a table of lengths in mm, e.g. [segments] pa3 = 55")
        raw_segments = {}
    raw_values = data.get("values", {})
    if not isinstance(raw_values, dict):
        problems.append('values: must be a table, e.g. [values] omega3 = "4.82 ccw"')
        raw_values = {}
    segs: list[tuple[str, str | None, str, float]] = []  # key, scope, name, mm
    for key, value in raw_segments.items():
        if isinstance(value, dict):
            if key not in PLANS:
                problems.append(f"segments.{key}: a sub-table must be one of "
                                f"{', '.join(PLANS)}")
                continue
            for k2, v2 in value.items():
                x = _num(v2, f"segments.{key}.{k2}", problems, nonneg=True)
                if x is not None:
                    segs.append((f"segments.{key}.{k2}", key, k2, x))
            continue
        x = _num(value, f"segments.{key}", problems, nonneg=True)
        if x is not None:
            segs.append((f"segments.{key}", None, key, x))
    if not raw_segments and not raw_values:
        problems.append("segments: nothing to check: give the measured segments, e.g. "
                        "[segments] pa3 = 55")
    if mech is None:
        _raise(source, text, problems or ["mechanism: missing"])
    # solve at the student's scales (the names are checked against the plans even when
    # other keys have problems, so that every problem is reported at once) -------------
    try:
        if isinstance(mech, int):
            m = variants.variant(mech, table)
        else:
            m = mechmod.load(mech)
        if angle is not None:
            d = m.driver
            ref = mechmod.REFERENCES[d.reference] + mechmod.SENSES[d.measured] * angle
            m = m.with_phi(math.radians(ref))
        sol = solve_position(m, mu=dict(mu))
    except PlansError:
        if problems:  # these first; the mechanism's own problems once they are fixed
            _raise(source, text, problems)
        raise
    names = _Names(sol)
    items: list[Item] = []
    for key, scope, name, x in segs:
        item = names.segment(key, scope, name, x, problems)
        if item is not None:
            items.append(item)
    for key, value in raw_values.items():
        item = names.value(f"values.{key}", key, value, problems)
        if item is not None:
            items.append(item)
    need = {it.plan for it in items if it.kind in ("segment", "value")}
    need |= {"velocity" for it in items if it.kind == "omega"}
    need |= {"acceleration" for it in items if it.kind == "epsilon"}
    for plan in PLANS:
        if plan in need and MU_KEY[plan] not in mu:
            what = {"positions": "the plan of positions", "velocity": "the velocity plan",
                    "acceleration": "the acceleration plan"}[plan]
            problems.append(f"scales.{MU_KEY[plan]}: missing: the scale factor the student "
                            f"used for {what}")
    if problems:
        _raise(source, text, problems)
    return Measurement(source, m, sol, {k: sol_mu(sol, k) for k in MU_KEY.values()},
                       tuple(items), tol, title, angle)


def sol_mu(sol: Solution, key: str) -> float:
    return {"mu_l": sol.mu_l, "mu_v": sol.mu_v, "mu_a": sol.mu_a}[key]


def _splits(text: str, names) -> list[tuple[str, str]]:
    return [(text[:i], text[i:]) for i in range(1, len(text))
            if text[:i] in names and text[i:] in names and text[:i] != text[i:]]


def recorded_segments(plan: Plan) -> dict[str, tuple[str, str]]:
    """The segments a plan names (as ``plans solve`` prints them) → (start, end)."""
    out = {}
    for name, pt in plan.points.items():
        if pt.source.kind not in ("pole", "component"):
            out[plan.pole + name] = (plan.pole, name)
    for v in plan.vectors:
        if v.component != "absolute":
            out[v.start + v.end] = (v.start, v.end)
    return out


class _Names:
    """Resolves the names a student writes to plan segments and values."""

    def __init__(self, sol: Solution):
        self.sol = sol
        self.plans = {"velocity": sol.velocity, "acceleration": sol.acceleration}
        self.recorded = {k: recorded_segments(p) for k, p in self.plans.items()}
        self.recorded["positions"] = {k: (k, "") for k in sol.lengths}
        self.pos_names = set(sol.positions)
        self.rep = _Replayer(sol)

    def known(self) -> str:
        names = list(self.sol.lengths) + [
            k for p in ("velocity", "acceleration") for k in self.recorded[p]]
        return ", ".join(names)

    def segment(self, key, scope, name, mm, problems) -> Item | None:
        spellings = [name]
        if name.startswith("pi"):
            spellings.append("π" + name[2:])
        if name.endswith("pi"):
            spellings.append(name[:-2] + "π")
        cands: dict[tuple[str, str, str], str] = {}
        for sp in spellings:
            if scope in (None, "positions"):
                for x, y in _splits(sp, self.pos_names):
                    cands.setdefault(("positions", x, y), sp)
            for kind, plan in self.plans.items():
                if scope in (None, kind):
                    for x, y in _splits(sp, set(plan.points) | {plan.pole}):
                        cands.setdefault((kind, x, y), sp)
        if len({c[0] for c in cands}) > 1:
            rec = {c: sp for c, sp in cands.items() if sp in self.recorded[c[0]]}
            if len({c[0] for c in rec}) == 1:
                cands = rec
        if not cands:
            problems.append(f"{key}: unknown segment \"{name}\"; known: {self.known()} "
                            "(or any two points of one plan; write π as pi)")
            return None
        if len(cands) > 1:
            where = sorted({c[0] for c in cands})
            if len(where) > 1:
                problems.append(f"{key}: \"{name}\" names a segment on the {' and the '.join(where)} "
                                f"plans: put it under [segments.{where[-1]}] or "
                                f"[segments.{where[0]}]")
            else:
                problems.append(f"{key}: \"{name}\" can be read as "
                                + " or ".join(f"{x}–{y}" for _, x, y in cands))
            return None
        (plan, x, y), sp = next(iter(cands.items()))
        return Item(key, sp, "segment", plan, mm, x, y)

    def value(self, key, name, value, problems) -> Item | None:
        sol = self.sol
        m = re.fullmatch(r"(omega|ω|w|epsilon|ε|eps)_?(\d+)", name)
        if m:
            link = int(m.group(2))
            kind = "omega" if m.group(1) in ("omega", "ω", "w") else "epsilon"
            if link not in sol.mechanism.links:
                problems.append(f"{key}: there is no link {link} (links: "
                                f"{', '.join(map(str, sorted(sol.mechanism.links)))})")
                return None
            mag, sense = _magnitude_sense(value, key, problems, allow_sense=True)
            if mag is None:
                return None
            plan = "velocity" if kind == "omega" else "acceleration"
            pair = self.rep.pairs.get(link)
            per_mm = 0.0
            if pair:
                per_mm = sol_mu(sol, MU_KEY[plan]) / abs(sol.positions[pair[0]] - sol.positions[pair[1]])
            sym = "ω" if kind == "omega" else "ε"
            return Item(key, f"{sym}{link}", kind, plan, mag, link=link, sense=sense, per_mm=per_mm)
        hit = self._physical(name)
        if hit is None:
            labels = ["ω<link>", "ε<link>", "V_<point>", "a_<point>", "V_<point><point>"]
            labels += [v.label for v in sol.acceleration.vectors if v.component != "absolute"]
            problems.append(f"{key}: unknown value \"{name}\"; known: {', '.join(dict.fromkeys(labels))}")
            return None
        plan, x, y, label = hit
        mag, _ = _magnitude_sense(value, key, problems, allow_sense=False)
        if mag is None:
            return None
        return Item(key, label, "value", plan, mag, x, y,
                    per_mm=sol_mu(sol, MU_KEY[plan]))

    def _physical(self, name: str):
        m = re.fullmatch(r"(V|v|a)(?:\^?([nktr]))?_(\w+)", name)
        if not m:
            return None
        sym, comp, rest = m.groups()
        plan = self.sol.velocity if sym in "Vv" else self.sol.acceleration
        if comp:
            if sym != "a":
                return None
            label = f"a^{comp}_{rest}"
            for v in plan.vectors:
                if v.label == label:
                    return plan.kind, v.start, v.end, label
            return None
        names = set(self.sol.positions)
        head = "V" if sym in "Vv" else "a"
        if rest in names:
            return plan.kind, plan.pole, plan_name(rest), f"{head}_{rest}"
        sp = _splits(rest, names)
        if len(sp) == 1:
            x, y = sp[0]
            return plan.kind, plan_name(y), plan_name(x), f"{head}_{rest}"
        return None


def _magnitude_sense(value, key, problems, *, allow_sense):
    sense = 0
    if isinstance(value, str) and allow_sense:
        parts = value.replace(",", ".").split()
        try:
            mag = float(parts[0]) if parts else None
        except ValueError:
            mag = None
        word = parts[1].lower() if len(parts) > 1 else ""
        if mag is None or len(parts) > 3 or (word and word not in SENSE_WORDS):
            problems.append(f'{key}: write a magnitude and a sense, e.g. "4.82 ccw" or "4.82 cw", '
                            f"got {value!r:.40}")
            return None, 0
        sense = SENSE_WORDS.get(word, 0)
        value = mag
    x = _num(value, key, problems, nonneg=True)
    if x is None:
        return None, 0
    return x, sense


# ---------------------------------------------------------------------------------------
# the plans as a student draws them
# ---------------------------------------------------------------------------------------


@dataclass(frozen=True)
class State:
    """Plans as drawn: point values (m/s, m/s²) by plan name, positions by mechanism name,
    ω and ε as read off the plans, and a length factor per plan (a scale mistake)."""

    positions: dict[str, complex]
    velocity: dict[str, complex]
    acceleration: dict[str, complex]
    omega: dict[int, float]
    epsilon: dict[int, float]
    factor: dict[str, float] = field(default_factory=lambda: dict.fromkeys(PLANS, 1.0))

    def values(self, plan: str) -> dict[str, complex]:
        return self.velocity if plan == "velocity" else self.acceleration


def expected(item: Item, st: State, mu: dict[str, float]) -> float:
    """What the student should have measured (or computed) if they drew ``st``.
    ω and ε are signed (counter-clockwise positive); everything else is a length."""
    f = st.factor[item.plan]
    if item.kind == "omega":
        return st.omega.get(item.link, 0.0) * f
    if item.kind == "epsilon":
        return st.epsilon.get(item.link, 0.0) * f
    if item.plan == "positions":
        return abs(st.positions[item.end] - st.positions[item.start]) / mu["mu_l"] * f
    vals = st.values(item.plan)
    d = abs(vals[item.end] - vals[item.start]) * f
    return d if item.kind == "value" else d / mu[MU_KEY[item.plan]]


class _Degenerate(Exception):
    """A simulated mistake makes two lines parallel: no plan can be drawn that way."""


@dataclass(frozen=True)
class Mistake:
    """One common mistake, located: which term, line, point, group or plan.

    kind: coriolis-reversed, coriolis-omitted, coriolis-half, term-scale,
    normal-reversed, normal-omitted, omega-sense, line-swapped, branch, scale,
    scale-swapped, similarity-ratio, similarity-mirrored.
    """

    kind: str
    plan: str = ""  # velocity, acceleration, both, positions
    target: str = ""  # a term label, a plan point, a group label
    factor: complex = 1.0
    link: int = 0
    group: int = -1
    route: int = -1
    info: tuple[tuple[str, str], ...] = ()

    @property
    def family(self) -> str:
        return {"coriolis-reversed": "coriolis", "coriolis-omitted": "coriolis",
                "coriolis-half": "coriolis", "normal-reversed": "normal",
                "normal-omitted": "normal", "omega-sense": "omega",
                "line-swapped": "line", "branch": "branch", "scale": "scale",
                "scale-swapped": "scale", "term-scale": "scale",
                "similarity-ratio": "similarity",
                "similarity-mirrored": "similarity"}[self.kind]

    def get(self, key: str) -> str:
        return dict(self.info).get(key, "")

    def describe(self, lang: str = "en") -> str:
        return _text(self, lang)[0]

    def correction(self, lang: str = "en") -> str:
        return _text(self, lang)[1]


class _Replayer:
    """Replays the recorded constructions of one solution, with at most one mistake."""

    def __init__(self, sol: Solution):
        self.sol = sol
        m = sol.motion
        self.pos = sol.positions
        self.mech_name = {plan_name(n): n for n in sol.positions}
        self.terms = {t.label: t for g in m.groups for r in g.acceleration.routes for t in r.terms}
        self.link_points: dict[int, list[str]] = {}
        for lid, link in sol.mechanism.links.items():
            pts = list(link.points)
            pts += [n for n, owner in m.point_link.items() if owner == lid and n in m.coincident]
            self.link_points[lid] = pts
        # the pair of points the student reads ω and ε of a link from: the ends of its
        # relative velocity vector if the plan has one, else its two farthest points
        self.pairs: dict[int, tuple[str, str]] = {}
        for v in sol.velocity.vectors:
            if v.component != "relative":
                continue
            X, Y = self.mech_name.get(v.end), self.mech_name.get(v.start)
            for lid, pts in self.link_points.items():
                if X in pts and Y in pts and lid not in self.pairs and abs(self.pos[X] - self.pos[Y]) > 0:
                    self.pairs[lid] = (X, Y)
        for lid, pts in self.link_points.items():
            if lid in self.pairs:
                continue
            best, far = None, 0.0
            for i, a in enumerate(pts):
                for b in pts[i + 1:]:
                    d = abs(self.pos[a] - self.pos[b])
                    if d > far * (1 + 1e-9):
                        best, far = (b, a), d
            if best and far > 1e-9 * max(1.0, max(abs(z) for z in self.pos.values())):
                self.pairs[lid] = best

    def guide_link(self, t) -> int:
        m = self.sol.motion
        for n in t.about:
            if n in m.coincident:
                return m.point_link[n]
        return m.point_link.get(t.about[1], 0)

    def exact(self) -> State:
        s = self.sol
        v = {n: p.value for n, p in s.velocity.points.items()} | {s.velocity.pole: 0j}
        a = {n: p.value for n, p in s.acceleration.points.items()} | {s.acceleration.pole: 0j}
        return State(dict(self.pos), v, a, dict(s.omega), dict(s.epsilon))

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
        flip = {mk.link} if mk.kind == "omega-sense" else set()
        vel = self._plan(s.velocity, mk, None, None)
        omega = self._omega(vel, flip)
        acc = self._plan(s.acceleration, mk, vel, omega)
        eps = self._epsilon(acc)
        return State(dict(self.pos), vel, acc, omega, eps)

    def _applies(self, mk: Mistake, kind: str) -> bool:
        return mk.plan in (kind, "both")

    def _plan(self, plan: Plan, mk: Mistake, vel, omega) -> dict[str, complex]:
        kind = plan.kind
        vals: dict[str, complex] = {plan.pole: 0j}
        groups = self.sol.motion.groups
        for name, pt in plan.points.items():
            s = pt.source
            if s.kind == "pole":
                v = 0j
            elif s.kind == "driver":
                v = pt.value
                if mk.kind == "normal-reversed" and mk.get("driver") and kind == "acceleration":
                    v = -v
            elif s.kind == "similarity":
                r = s.ratio
                if mk.kind.startswith("similarity") and mk.target == name and self._applies(mk, kind):
                    r = self._ratio(mk, s.ratio)
                v = vals[s.base] + r * (vals[s.other] - vals[s.base])
            elif s.kind == "component":
                t = self.terms[s.label]
                v = vals[s.base] + self._term(t, mk, vel, omega)
            elif s.kind == "intersection":
                (l0, l1) = s.lines
                d0, d1 = l0.direction, l1.direction
                if mk.kind == "line-swapped" and mk.plan == kind and \
                        plan_name(groups[mk.group].velocity.point) == name:
                    if mk.route == 0:
                        d0 = d0 * 1j
                    else:
                        d1 = d1 * 1j
                with np.errstate(all="ignore"):
                    t0, _, sine = intersect(vals[l0.through], d0, vals[l1.through], d1)
                if not abs(sine) >= 1e-6:
                    raise _Degenerate(name)
                v = vals[l0.through] + t0 * d0
            else:  # "rigid": moves with the first known point of its link
                X = self.mech_name.get(name, "")
                lid = self.sol.motion.point_link.get(X)
                v = pt.value
                for other in self.link_points.get(lid, []):
                    on = plan_name(other)
                    if other != X and on in vals:
                        v = vals[on] + (pt.value - plan.value(on))
                        break
            vals[name] = complex(v)
        return vals

    @staticmethod
    def _ratio(mk: Mistake, r: complex) -> complex:
        return complex(mk.factor)

    def _term(self, t, mk: Mistake, vel, omega) -> complex:
        X, Y = t.about
        dv = vel[plan_name(X)] - vel[plan_name(Y)]
        if t.kind == "normal":
            r = self.pos[X] - self.pos[Y]
            val = -(abs(dv) ** 2 / abs(r) ** 2) * r
        else:
            val = 2j * omega[self.guide_link(t)] * dv
        if mk.target == t.label and mk.kind in ("coriolis-reversed", "coriolis-omitted",
                                                  "coriolis-half", "normal-reversed",
                                                  "normal-omitted", "term-scale"):
            val = val * mk.factor
        return complex(val)


def simulate(sol: Solution, mk: Mistake | None, mu: dict[str, float] | None = None) -> State:
    """The plans as a student who makes mistake ``mk`` draws them (None: the exact ones)."""
    if mk is None:
        return _Replayer(sol).exact()
    if mk.kind == "branch":
        sigmas = list(Solver(sol.mechanism, sol.structure).sigmas)
        sigmas[mk.group] = -sigmas[mk.group]
        mu = mu or {"mu_l": sol.mu_l, "mu_v": sol.mu_v, "mu_a": sol.mu_a}
        other = solve_position(sol.mechanism, sol.phi,
                               solver=Solver(sol.mechanism, sol.structure, tuple(sigmas)), mu=mu)
        return _Replayer(other).exact()
    if mk.kind in ("scale", "scale-swapped"):
        st = _Replayer(sol).exact()
        factor = dict.fromkeys(PLANS, 1.0)
        for plan, f in mk.info:
            factor[plan] = float(f)
        return State(st.positions, st.velocity, st.acceleration, st.omega, st.epsilon, factor)
    return _Replayer(sol).run(mk)


def hypotheses(sol: Solution, plans: set[str] | None = None) -> list[Mistake]:
    """Every common mistake that can be made on these plans, in order of preference."""
    plans = set(PLANS) if plans is None else plans
    rep = _Replayer(sol)
    m = sol.motion
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
                       info=(("X", drv.tip), ("Y", drv.pivot), ("driver", "1"))))
    for t in cor:
        out.append(Mistake("omega-sense", "acceleration", f"ω{rep.guide_link(t)}",
                           link=rep.guide_link(t), info=(("coriolis", t.label),)))
    guides = {rep.guide_link(t) for t in cor}
    for lid in sorted(sol.mechanism.links):
        if lid != drv.link and lid not in guides and abs(sol.omega[lid]) > 0:
            out.append(Mistake("omega-sense", "velocity", f"ω{lid}", link=lid))
    for gi, g in enumerate(m.groups):
        for kind, cons in (("velocity", g.velocity), ("acceleration", g.acceleration)):
            pt = sol.velocity.points[plan_name(cons.point)] if kind == "velocity" else \
                sol.acceleration.points[plan_name(cons.point)]
            for ri, (r, ln) in enumerate(zip(cons.routes, pt.source.lines, strict=True)):
                wrong = r.relation.replace("∥", "\0").replace("⊥", "∥").replace("\0", "⊥")
                out.append(Mistake("line-swapped", kind, r.unknown, group=gi, route=ri,
                                   info=(("relation", r.relation), ("wrong", wrong),
                                         ("through", ln.through), ("point", plan_name(cons.point)))))
    for gi, g in enumerate(m.groups):
        if g.group.kind in (DyadKind.RRR, DyadKind.RRP, DyadKind.RPR):
            out.append(Mistake("branch", "both", g.group.label, group=gi,
                               info=(("point", cons_point(g)),)))
    for plan in ("velocity", "acceleration", "positions"):
        if plan in plans:
            for f in (10.0, 0.1):
                out.append(Mistake("scale", plan, plan, f, info=((plan, repr(f)),)))
    mv, ma = sol.mu_v, sol.mu_a
    if mv != ma and {"velocity", "acceleration"} & plans:
        out.append(Mistake("scale-swapped", "both", "μv↔μa",
                           info=(("velocity", repr(mv / ma)), ("acceleration", repr(ma / mv)))))
        out.append(Mistake("scale-swapped", "velocity", "μa",
                           info=(("velocity", repr(mv / ma)),)))
        out.append(Mistake("scale-swapped", "acceleration", "μv",
                           info=(("acceleration", repr(ma / mv)),)))
    for t in cor:
        out.append(Mistake("coriolis-half", "acceleration", t.label, 0.5, rep.guide_link(t),
                           info=(("rel", f"V_{t.about[0]}{t.about[1]}"),
                                 ("omega", f"ω{rep.guide_link(t)}"))))
    for t in cor + nor:
        for f in (10.0, 0.1):
            out.append(Mistake("term-scale", "acceleration", t.label, f))
    out += _similarity_mistakes(sol)
    return out


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


# ---------------------------------------------------------------------------------------
# the comparison and the diagnosis
# ---------------------------------------------------------------------------------------


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
    if item.kind in ("omega", "epsilon") and item.sense and mag > limit:
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
class Diagnosis:
    best: Finding | None  # the mistake that explains the measurements, if one does
    alternatives: tuple[Finding, ...] = ()  # mistakes that explain them as well
    closest: Finding | None = None  # when none does: the one that came nearest
    tried: int = 0


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


def check(meas: Measurement, tol: Tolerance | None = None, *, diagnose_: bool = True) -> CheckResult:
    """Compare every measured item with the exact plans; diagnose what is beyond tolerance."""
    tol = tol or meas.tolerance or Tolerance()
    st = _Replayer(meas.solution).exact()
    devs = tuple(compare(it, expected(it, st, meas.mu), tol) for it in meas.items)
    diag = diagnose(meas, devs, tol) if diagnose_ else Diagnosis(None)
    return CheckResult(meas, tol, devs, diag)


def diagnose(meas: Measurement, devs: tuple[Deviation, ...], tol: Tolerance) -> Diagnosis:
    """Redraw the plans under each common mistake; keep the one that explains the
    deviations (all of them, or all but one in four) without spoiling what was right."""
    bad = [i for i, d in enumerate(devs) if not d.ok]
    if not bad:
        return Diagnosis(None)
    items = meas.items
    plans = {it.plan for it in items}
    findings: list[Finding] = []
    tried = 0
    for mk in hypotheses(meas.solution, plans):
        try:
            st = simulate(meas.solution, mk, meas.mu)
            sim = [compare(it, expected(it, st, meas.mu), tol) for it in items]
        except (_Degenerate, PlansError, ZeroDivisionError, KeyError):
            continue
        tried += 1
        explained = tuple(items[i].name for i in bad if sim[i].ok)
        if not explained:
            continue
        unexplained = tuple(items[i].name for i in bad if not sim[i].ok)
        broken = tuple(items[i].name for i, d in enumerate(devs) if d.ok and not sim[i].ok)
        score = sum((d.deviation / d.limit) ** 2 if d.limit > 0 else 0.0 for d in sim)
        score += sum(4.0 for d in sim if d.sense_ok is False)
        findings.append(Finding(mk, explained, unexplained, broken, float(score), st))
    allowed = (len(bad) - 1) // 4
    accepted = [f for f in findings if not f.broken and len(f.unexplained) <= allowed]
    accepted.sort(key=lambda f: (len(f.unexplained), f.score))
    if accepted:
        best = accepted[0]
        alts = tuple(
            f for f in accepted[1:]
            if len(f.unexplained) == len(best.unexplained) and f.score <= best.score * 1.25 + 0.25
        )[:3]
        return Diagnosis(best, alts, None, tried)
    near = [f for f in findings if not f.broken]
    near.sort(key=lambda f: (-len(f.explained), f.score))
    return Diagnosis(None, (), near[0] if near else None, tried)


# ---------------------------------------------------------------------------------------
# the student's plan rebuilt from the measured lengths (for the overlay)
# ---------------------------------------------------------------------------------------


def rebuild(result: CheckResult) -> dict[str, dict[str, complex]]:
    """Points of each plan (mm at the student's scale, pole at 0) placed from the measured
    segments: a point measured from two placed points by the intersection of two circles
    (the one nearer the reference), from one placed point along the reference direction.
    The reference is the plan of the diagnosed mistake if there is one, else the exact
    plan. Points that no measurement reaches are left out."""
    meas = result.measurement
    diag = result.diagnosis
    st = diag.best.state if diag.best and diag.best.state is not None else _Replayer(meas.solution).exact()
    out: dict[str, dict[str, complex]] = {}
    for kind in ("velocity", "acceleration"):
        plan = meas.solution.velocity if kind == "velocity" else meas.solution.acceleration
        mu = meas.mu[MU_KEY[kind]] / st.factor[kind]
        ref = {n: z / mu for n, z in st.values(kind).items()}
        segs = [(it.start, it.end, it.measured) for it in meas.items
                if it.kind == "segment" and it.plan == kind]
        placed = {plan.pole: 0j}
        for n, p in plan.points.items():
            if p.source.kind == "pole":
                placed[n] = 0j
        order = list(plan.points)
        changed = True
        while changed:
            changed = False
            for n in order:
                if n in placed:
                    continue
                anchors = []
                for a, b, L in segs:
                    if a == n and b in placed:
                        anchors.append((b, L))
                    elif b == n and a in placed:
                        anchors.append((a, L))
                if not anchors:
                    continue
                z = _place(n, anchors, placed, ref)
                if z is not None:
                    placed[n] = z
                    changed = True
        out[kind] = {n: z for n, z in placed.items()
                     if any(n in (a, b) for a, b, _ in segs) or n == plan.pole}
    return out


def _place(n, anchors, placed, ref):
    uniq = {}
    for a, L in anchors:
        uniq.setdefault(placed[a], (a, L))
    anchors = list(uniq.values())
    if len(anchors) >= 2:
        best = None
        for i, (a, La) in enumerate(anchors):
            for b, Lb in anchors[i + 1:]:
                ua, ub = ref[n] - ref[a], ref[n] - ref[b]
                s = abs(cross(ua, ub)) / max(abs(ua) * abs(ub), 1e-300)
                if best is None or s > best[0]:
                    best = (s, a, La, b, Lb)
        s, a, La, b, Lb = best
        if s > 0.05:
            guess = placed[a] + (ref[n] - ref[a])
            d = abs(placed[b] - placed[a])
            if d > 1e-9:
                cands = []
                for sign in (1, -1):
                    z, disc = circle_circle(placed[a], La, placed[b], Lb, sign)
                    if disc < 0:  # the circles miss: the nearest point between them
                        u = (placed[b] - placed[a]) / d
                        z = placed[a] + u * (La + (d - La - Lb) / 2 if d > La + Lb else
                                             (La if La > Lb else d - Lb))
                    cands.append(complex(z))
                return min(cands, key=lambda z: abs(z - guess))
    a, L = anchors[0]
    u = ref[n] - ref[a]
    if abs(u) < 1e-12:
        return None
    return placed[a] + L * u / abs(u)


# ---------------------------------------------------------------------------------------
# words
# ---------------------------------------------------------------------------------------

PLAN_WORDS = {
    "en": {"velocity": "velocity plan", "acceleration": "acceleration plan",
           "positions": "plan of positions", "both": "both plans"},
    "ru": {"velocity": "план скоростей", "acceleration": "план ускорений",
           "positions": "план положений", "both": "оба плана"},
}


def _fnum(x: float, lang: str) -> str:
    from .fmt import num

    return num(float(x), 3, lang)


def _text(mk: Mistake, lang: str) -> tuple[str, str]:
    """(what the mistake is, the correction in the method's words)."""
    ru = lang == "ru"
    g = mk.get
    k = mk.kind
    if k == "coriolis-reversed":
        if ru:
            return (f"вектор ускорения Кориолиса {mk.target} направлен в обратную сторону",
                    f"поверните вектор относительной скорости {g('rel')} на 90° в сторону "
                    f"переносной угловой скорости {g('omega')}")
        return (f"the Coriolis vector {mk.target} points the wrong way",
                f"turn the relative velocity {g('rel')} by 90° in the sense of {g('omega')}")
    if k == "coriolis-omitted":
        if ru:
            return (f"ускорение Кориолиса {mk.target} не учтено",
                    f"отложите {mk.target} = 2·{g('omega')}·{g('rel')} (вектор {g('rel')}, "
                    f"повёрнутый на 90° в сторону {g('omega')}) перед линией относительного ускорения")
        return (f"the Coriolis acceleration {mk.target} is missing",
                f"lay off {mk.target} = 2·{g('omega')}·{g('rel')} ({g('rel')} turned by 90° in "
                f"the sense of {g('omega')}) before drawing the line of the sliding acceleration")
    if k == "coriolis-half":
        if ru:
            return (f"ускорение Кориолиса {mk.target} вдвое меньше",
                    f"{mk.target} = 2·{g('omega')}·{g('rel')}: не забудьте множитель 2")
        return (f"the Coriolis acceleration {mk.target} is half as long as it should be",
                f"{mk.target} = 2·{g('omega')}·{g('rel')}: the factor 2 is missing")
    if k == "normal-reversed":
        X, Y = g("X"), g("Y")
        if g("driver"):
            if ru:
                return (f"ускорение {mk.target} кривошипа направлено от {Y} к {X}",
                        f"a_{X} = ω1²·l_{Y}{X} направлено от {X} к центру {Y}: "
                        f"π{X.lower()} ∥ {Y}{X}, от {X} к {Y}")
            return (f"the crank's acceleration {mk.target} points from {Y} to {X}",
                    f"a_{X} = ω1²·l_{Y}{X} is directed from {X} towards the centre {Y}: "
                    f"draw π{X.lower()} ∥ {Y}{X}, from {X} to {Y}")
        if ru:
            return (f"нормальное ускорение {mk.target} направлено в обратную сторону",
                    f"{mk.target} = V²_{X}{Y}/l_{X}{Y} направлено от точки {X} к центру {Y} (∥ {X}{Y})")
        return (f"the normal acceleration {mk.target} points the wrong way",
                f"{mk.target} = V_{X}{Y}²/l_{X}{Y} is directed from {X} towards the centre {Y} (∥ {X}{Y})")
    if k == "normal-omitted":
        X, Y = g("X"), g("Y")
        if ru:
            return (f"нормальное ускорение {mk.target} не учтено",
                    f"отложите {mk.target} = V²_{X}{Y}/l_{X}{Y} (∥ {X}{Y}, от {X} к {Y}) и проведите "
                    f"линию касательного ускорения ⊥ {X}{Y} через его конец")
        return (f"the normal acceleration {mk.target} is missing",
                f"lay off {mk.target} = V_{X}{Y}²/l_{X}{Y} (∥ {X}{Y}, from {X} to {Y}) and draw the "
                f"line of the tangential acceleration ⊥ {X}{Y} through its end")
    if k == "omega-sense":
        if ru:
            extra = (f"; вектор Кориолиса {g('coriolis')} тогда поворачивается не в ту сторону"
                     if g("coriolis") else "")
            return (f"угловая скорость {mk.target} взята с обратным направлением",
                    f"направление {mk.target} определяется направлением относительной скорости "
                    f"на плане скоростей{extra}")
        extra = (f"; with it the Coriolis vector {g('coriolis')} turns the wrong way"
                 if g("coriolis") else "")
        return (f"{mk.target} taken with the wrong sense",
                f"the sense of {mk.target} is that of the relative velocity on the velocity plan"
                f"{extra}")
    if k == "line-swapped":
        plan = PLAN_WORDS[lang][mk.plan]
        if ru:
            return (f"на плане ({plan}) линия {mk.target} проведена {g('wrong')} вместо {g('relation')}",
                    f"через точку {g('through')} проведите линию {g('relation')} "
                    f"(линия вектора {mk.target}), а не {g('wrong')}")
        return (f"on the {plan} the line of {mk.target} is drawn {g('wrong')} instead of {g('relation')}",
                f"through {g('through')} draw the line {g('relation')} (the line of {mk.target}), "
                f"not {g('wrong')}")
    if k == "branch":
        if ru:
            return (f"{mk.target.replace('group', 'группа')} собрана в другом положении (другая сборка)",
                    f"постройте план положений с заданной сборкой группы: точка {g('point')} "
                    "на другой стороне; затем перестройте планы")
        return (f"{mk.target} is assembled the other way (the other branch)",
                f"draw the plan of positions with the given assembly of the group ({g('point')} "
                "on the other side), then redraw the plans")
    if k in ("scale", "scale-swapped"):
        facs = dict(mk.info)
        parts = []
        for plan, f in facs.items():
            f = float(f)
            mu = {"velocity": "μv", "acceleration": "μa", "positions": "μl"}[plan]
            if ru:
                parts.append(f"{PLAN_WORDS[lang][plan]} в {_fnum(f, lang)} раза крупнее "
                             f"(при указанном {mu})" if f > 1 else
                             f"{PLAN_WORDS[lang][plan]} в {_fnum(1 / f, lang)} раза мельче "
                             f"(при указанном {mu})")
            else:
                parts.append(f"the {PLAN_WORDS[lang][plan]} is drawn {_fnum(f, lang)} times too large "
                             f"for the stated {mu}" if f > 1 else
                             f"the {PLAN_WORDS[lang][plan]} is drawn {_fnum(1 / f, lang)} times too "
                             f"small for the stated {mu}")
        what = "; ".join(parts)
        if k == "scale-swapped":
            what = ("μv и μa перепутаны: " if ru else "μv and μa swapped: ") + what
        if ru:
            return (what, "длина отрезка = величина / масштабный коэффициент: pa = V_A/μv, "
                          "πa = a_A/μa, в мм; проверьте степень 10 и какой μ к какому плану")
        return (what, "a segment is the value divided by its own scale factor: pa = V_A/μv, "
                      "πa = a_A/μa, in mm; check the power of 10 and which μ belongs to which plan")
    if k == "term-scale":
        f = float(mk.factor.real)
        if ru:
            return (f"{mk.target} отложено в {_fnum(max(f, 1 / f), lang)} раза "
                    + ("длиннее" if f > 1 else "короче"),
                    f"вычислите {mk.target} в единицах СИ (длины в м: l = отрезок·μl) и разделите на μa")
        return (f"{mk.target} is drawn {_fnum(max(f, 1 / f), lang)} times too "
                + ("long" if f > 1 else "short"),
                f"compute {mk.target} in SI units (lengths in m: l = segment·μl), then divide by μa")
    if k.startswith("similarity"):
        how = g("how")
        eq = g("equation")
        plan = PLAN_WORDS[lang][mk.plan]
        if how.startswith("sibling:"):
            other = how.split(":", 1)[1]
            if ru:
                return (f"точка {mk.target} ({plan}) найдена по отношению для точки {other}",
                        f"по теореме подобия: {eq}")
            return (f"{mk.target} on the {plan} found with the ratio meant for {other}",
                    f"by similarity: {eq}")
        if how == "inverse":
            if ru:
                return (f"точка {mk.target} ({plan}) найдена по обратному отношению отрезков",
                        f"по теореме подобия: {eq} (отрезок плана / отрезок звена одинаковы для всех точек звена)")
            return (f"{mk.target} on the {plan} found with the ratio of the wrong segments (inverted)",
                    f"by similarity: {eq} (plan segment / link segment is the same for every point of the link)")
        if how == "side":
            if ru:
                return (f"точка {mk.target} ({plan}) отложена по другую сторону от {g('base')}",
                        f"по теореме подобия: {eq}, в ту же сторону, что и на звене")
            return (f"{mk.target} on the {plan} laid off on the wrong side of {g('base')}",
                    f"by similarity: {eq}, in the same direction as on the link")
        if ru:
            return (f"фигура для точки {mk.target} ({plan}) построена зеркально",
                    f"по теореме подобия: {eq}; обход букв на плане тот же, что на звене, "
                    "фигура не зеркальная")
        return (f"the figure for {mk.target} on the {plan} is mirrored",
                f"by similarity: {eq}, with the letters in the same order round the figure as "
                "on the link, not mirrored")
    return (k, "")
