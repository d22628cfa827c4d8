"""What a student measured on their drawing: the measurement file, the tolerance, and the
names of the segments (pa3, aa3, πa3, n1a3…) matched to the plans' recorded segments.

:func:`load` and :func:`from_dict` read a measurement file into a :class:`Measurement` of
:class:`Item` s, each saying which plan and which segment or value it is; every problem in
the file is reported at once, with its location.
"""

from __future__ import annotations

import math
import os
import re
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from plans.errors import InputError, PlansError
from plans.model.fileformat import (
    DECIMAL,
    LOOKALIKES,
    Problems,
    check_keys,
    close_match,
    decimal,
    key_text,
    other_kind,
    quote,
    read_number,
    read_toml,
    type_in_latin,
)
from plans.model.mechanism import MU_UNIT, Mechanism
from plans.plan.solution import Plan, Solution, plan_name, solve_position

PLANS = ("positions", "velocity", "acceleration")
MU_KEY = {"positions": "mu_l", "velocity": "mu_v", "acceleration": "mu_a"}
#: the scale factor of each plan as the note writes it
MU_SYMBOL = {"positions": "μl", "velocity": "μv", "acceleration": "μa"}
#: the sense of an ω or ε as a student writes it after the magnitude, +1 ccw, −1 cw
SENSE_WORDS = {
    "ccw": 1, "cw": -1, "counterclockwise": 1, "counter-clockwise": 1, "anticlockwise": 1,
    "anti-clockwise": 1, "clockwise": -1,
    "против часовой стрелки": 1, "против часовой": 1, "против ч.с.": 1, "против ч. с.": 1,
    "против чс": 1, "против": 1,
    "по часовой стрелке": -1, "по часовой": -1, "по ч.с.": -1, "по ч. с.": -1, "по чс": -1,
    "по": -1,
}
#: the senses a hint names
SENSE_HINT = "ccw, cw, против часовой стрелки, по часовой стрелке, против ч.с., по ч.с."
#: the units a quoted value may carry, by kind (Item.kind, "value" by its plan)
VALUE_UNITS = {
    "velocity": ("m/s", ("m/s", "м/с")),
    "acceleration": ("m/s²", ("m/s²", "м/с²")),
    "omega": ("rad/s", ("rad/s", "рад/с", "1/s", "1/с", "s⁻¹", "с⁻¹")),
    "epsilon": ("rad/s²", ("rad/s²", "рад/с²", "1/s²", "1/с²", "s⁻²", "с⁻²")),
}
_WHAT = {"velocity": "a velocity", "acceleration": "an acceleration",
         "omega": "an angular velocity", "epsilon": "an angular acceleration"}


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
        from plans.fmt import num

        if lang == "ru":
            return f"большее из {num(self.mm, 3, lang)} мм и {num(self.percent, 3, lang)} %"
        return f"the larger of {num(self.mm, 3)} mm and {num(self.percent, 3)} %"


def parse_tolerance(text: str, base: Tolerance | None = None) -> Tolerance:
    """``"5%"``, ``"1.5mm"``, ``"3%,0.5mm"`` → :class:`Tolerance` (unnamed parts stay).

    >>> parse_tolerance("3%")
    Tolerance(percent=3.0, mm=1.0)
    >>> parse_tolerance("0.5 mm, 2 %")
    Tolerance(percent=2.0, mm=0.5)
    >>> parse_tolerance("5%,1mm,2mm")
    Traceback (most recent call last):
    ValueError: "5%,1mm,2mm" gives the mm part twice: give a percentage and a length at most once each, e.g. "5%,1mm"
    """
    base = base or Tolerance()
    pct, mm = base.percent, base.mm
    token = r"(\d+(?:[.,]\d+)?)\s*(%|mm|мм)?"
    text = str(text).strip()
    if not re.fullmatch(rf"{token}(?:\s*[,;]?\s*{token})*", text):
        raise ValueError(f'"{text[:40]}" is not a tolerance (e.g. "5%", "1mm" or "5%,1mm")')
    seen: set[str] = set()
    for number, unit in re.findall(token, text):
        x = float(number.replace(",", "."))
        if not math.isfinite(x) or x > 1000:
            raise ValueError(f'"{number}" is out of range')
        part = "mm" if unit in ("mm", "мм") else "%"
        if part in seen:  # "5%,1mm,2mm": which one was meant?
            raise ValueError(f'"{text[:40]}" gives the {part} part twice: give a percentage and '
                             'a length at most once each, e.g. "5%,1mm"')
        seen.add(part)
        if part == "mm":
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
    #: the files read: the measurement file, then the mechanism file or the variants' table
    inputs: tuple[str, ...] = ()
    #: the scale factors the file gives (the others in ``mu`` the tool chose)
    given: frozenset[str] = frozenset()


TOP_KEYS = {"title", "mechanism", "variant", "table", "angle_deg", "tolerance", "scales",
            "segments", "values"}


def load(path: str | Path, solvers: Solvers | None = None) -> Measurement:
    """Read and validate a measurement file; every problem is reported, located.
    ``solvers``: those of the mechanisms already met (:class:`Solvers`), shared by the
    files of one mechanism at one crank angle."""
    data, text = read_toml(path, "a measurement file is a few KB")
    path = Path(path)
    return from_dict(data, str(path), path.parent, text=text, solvers=solvers)


class Solvers:
    """One :class:`~plans.kinematics.Solver` and its cycle per mechanism, for a batch of
    measurement files: the files of a class, most of one variant at one angle, solve it
    once. A solver compiles its plans' recipes, and the cycle sizes the plan of positions
    and words the angles a report writes; of 30 files of one mechanism that is most of
    the time that is not diagnosis. Mechanisms are told apart by equality (one file read
    twice is one mechanism; another angle, another path to it or another table is
    another)."""

    def __init__(self) -> None:
        self.known: list[tuple[Mechanism, Any, Any]] = []  # a Mechanism holds dicts: no hash

    def __call__(self, mech: Mechanism):
        """(solver, cycle) of ``mech``: its cycle first, which raises where ``mech`` does
        not assemble at its angle."""
        from plans.cycle import analyse_cycle
        from plans.kinematics.solver import Solver

        for m, solver, cycle in self.known:
            if m == mech:
                return solver, cycle
        solver = Solver(mech)
        cycle = analyse_cycle(mech, solver=solver)
        self.known.append((mech, solver, cycle))
        return solver, cycle


def _num(value: Any, where: str, problems: Problems, *, positive=False, nonneg=False,
         unit: str = "mm", what: str = "a length on the drawing") -> float | None:
    """A number of the file (``fileformat.read_number``: in quotes too, with a decimal point
    or comma); ``what`` (a length on the drawing, a magnitude) is not negative."""
    x = read_number(value, where, problems, positive=positive, unit=unit)
    if x is not None and nonneg and x < 0:
        problems.add(where, f"{what} cannot be negative, got {x:g}")
        return None
    return x


def from_dict(data: dict, source: str = "<measurements>", folder: Path | None = None, *,
              text: str | None = None, solvers: Solvers | None = None) -> Measurement:
    """Build a :class:`Measurement` from parsed TOML (the mechanism is loaded and solved,
    with the solver ``solvers`` has for it, if given)."""
    from plans.model import load as load_mechanism

    problems = Problems(source, text)
    if why := other_kind(data, source, "measurement"):
        raise InputError(source, why)
    check_keys(data, TOP_KEYS, "", problems)
    title = data.get("title", "")
    if not isinstance(title, str) or len(title) > 300:
        problems.add("title", "must be a text of at most 300 characters")
        title = ""
    # the mechanism -------------------------------------------------------------------
    mech = None
    has_file, has_var = "mechanism" in data, "variant" in data
    if has_file == has_var:
        problems.add('mechanism', 'give the mechanism file (mechanism = "press.toml") '
                        "or a variant (variant = 3), one of them")
    elif has_file:
        mech = _input_file(data["mechanism"], "mechanism", folder, problems)
    else:
        var = data["variant"]
        if isinstance(var, bool) or not isinstance(var, int):
            problems.add("variant", f"must be a whole number, got {quote(var, 20)}")
        else:
            mech = var
    table = None  # the table of variants: None for the built-in one
    if "table" in data:
        if has_file and not has_var:
            problems.add("table", "goes with variant = N (a row of that table of variants); "
                            "with a mechanism file leave it out")
        else:
            table = _input_file(data["table"], "table", folder, problems)
            if table is None and isinstance(mech, int):
                mech = None  # not the built-in table instead
    angle = None
    if "angle_deg" in data:
        angle = _num(data["angle_deg"], "angle_deg", problems, unit="°")
    tol = None
    if "tolerance" in data:
        try:
            tol = parse_tolerance(data["tolerance"])
        except ValueError as exc:
            problems.add("tolerance", f"{exc}")
    mu: dict[str, float] = {}
    scales = data.get("scales", {})
    if not isinstance(scales, dict):
        problems.add("scales", "must be a table, e.g. [scales] mu_v = 0.05")
        scales = {}
    check_keys(scales, set(MU_KEY.values()), "scales", problems)
    for key, value in scales.items():
        if key not in MU_KEY.values():
            continue
        x = _num(value, f"scales.{key}", problems, positive=True, unit=MU_UNIT[key])
        if x is not None:
            mu[key] = x
    raw_segments = data.get("segments", {})
    if not isinstance(raw_segments, dict):
        problems.add("segments", "must be a table of lengths in mm, e.g. [segments] pa3 = 55")
        raw_segments = {}
    raw_values = data.get("values", {})
    if not isinstance(raw_values, dict):
        problems.add('values', 'must be a table, e.g. [values] omega3 = "4.82 ccw"')
        raw_values = {}
    # (key as the report shows it, key path as the file spells it, plan or None, name, mm)
    segs: list[tuple[str, str, str | None, str, float]] = []
    for key, value in raw_segments.items():
        if isinstance(value, dict):
            if key not in PLANS:
                problems.add(f"segments.{key_text(key)}", f"a sub-table must be one of "
                                f"{', '.join(PLANS)}")
                continue
            for k2, v2 in value.items():
                where = f"segments.{key}.{key_text(k2)}"
                x = _num(v2, where, problems, nonneg=True)
                if x is not None:
                    segs.append((f"segments.{key}.{k2}", where, key, k2, x))
            continue
        where = f"segments.{key_text(key)}"
        x = _num(value, where, problems, nonneg=True)
        if x is not None:
            segs.append((f"segments.{key}", where, None, key, x))
    if not raw_segments and not raw_values:
        problems.add("segments", "nothing to check: give the measured segments, e.g. "
                        "[segments] pa3 = 55")
    if isinstance(mech, int):
        rows = _table_of(mech, table, problems)
        if rows is None:
            mech = None
    if mech is None:
        if not problems:
            problems.add("mechanism", "missing")
        problems.raise_if_any()
    # solve at the student's scales (the names are checked against the plans even when
    # other keys have problems, so that every problem is reported at once) -------------
    try:
        if isinstance(mech, int):
            m = rows.variant(mech)
        else:
            m = load_mechanism(mech)
        if angle is not None:
            m = m.at_file_angle(angle)
        solver, cycle = (solvers or Solvers())(m)
        sol = solve_position(m, mu=dict(mu), solver=solver, cycle=cycle)
    except PlansError as exc:
        problems.raise_if_any()  # these first; the mechanism's own problems once they are fixed
        if angle is not None and not isinstance(exc, InputError):  # the file's own angle
            from plans.cycle.analysis import outside, reachable_cycle
            from plans.errors import AssemblyError

            got = reachable_cycle(m) if isinstance(exc, AssemblyError) else None
            head = f"{angle:g}°" if got is None else outside("", angle, got[2], m.driver)
            problems.add("angle_deg", f"{head}: {exc}")
            problems.raise_if_any()
        raise
    names = _Names(sol)
    items: list[Item] = []
    for key, where, scope, name, x in segs:
        item = names.segment(key, where, scope, name, x, problems)
        if item is not None:
            items.append(item)
    for key, value in raw_values.items():
        item = names.value(f"values.{key}", f"values.{key_text(key)}", key, value, problems)
        if item is not None:
            items.append(item)
    first: dict[tuple, Item] = {}
    for it in items:  # one thing measured twice with two values ([segments] and [segments.velocity])
        same = (it.kind, it.plan, *sorted((it.start, it.end)), it.link)
        was = first.setdefault(same, it)
        if was is not it and (was.measured, was.sense) != (it.measured, it.sense):
            problems.add(it.key, f"measures what {was.key} does, as {it.measured:g} against "
                         f"{was.measured:g}: give each once")
    need = {it.plan for it in items if it.kind in ("segment", "value")}
    need |= {"velocity" for it in items if it.kind == "omega"}
    need |= {"acceleration" for it in items if it.kind == "epsilon"}
    for plan in PLANS:
        if plan in need and MU_KEY[plan] not in scales:  # given but bad: said above
            what = {"positions": "the plan of positions", "velocity": "the velocity plan",
                    "acceleration": "the acceleration plan"}[plan]
            problems.add(f"scales.{MU_KEY[plan]}", f"missing: the scale factor the student "
                            f"used for {what}")
    problems.raise_if_any()
    read = [source] + [str(p) for p in (mech if not isinstance(mech, int) else table,) if p]
    return Measurement(source, m, sol, sol.mu,
                       tuple(items), tol, title, angle, tuple(read), frozenset(mu))


def _input_file(value: Any, key: str, folder: Path | None, problems: Problems) -> Path | None:
    """The file that ``key`` (mechanism, table) names, relative to the measurement file;
    None, and a problem of that key, where it cannot be read."""
    if not isinstance(value, str) or not value:
        problems.add(key, f"must be a file name, got {quote(value)}")
        return None
    p = Path(value)
    if not p.is_absolute() and folder is not None:
        # students/../press.toml is press.toml, as a batch's table and a message name it
        p = Path(os.path.normpath(folder / p))
    name = quote(value, 80)[1:-1]
    if p.is_dir():
        problems.add(key, f"{name}: is a folder, not a file")
        return None
    if not p.is_file():
        problems.add(key, f"{name}: no such file (paths are relative to the measurement file)")
        return None
    try:
        with open(p, "rb"):
            pass
    except OSError as exc:
        problems.add(key, f"{name}: cannot read the file: {exc.strerror or exc}")
        return None
    return p


def _table_of(n: int, table: Path | None, problems: Problems):
    """The table of variants (:class:`plans.model.variants.Table`) that has row ``n``; None, and
    a problem of the key ``variant``, where it has no such row. A table that cannot be
    used at all is its own file's problem (raised after the measurement file's own)."""
    from plans.model import variants

    try:
        rows = variants.read_table(table)
        have = rows.numbers
    except InputError:
        problems.raise_if_any()
        raise
    if n in have:
        return rows
    problems.add("variant", f"{n} is not in {rows.source} ({rows.has()})")
    return None


def _splits(text: str, names) -> list[tuple[str, str]]:
    return [(text[:i], text[i:]) for i in range(1, len(text))
            if text[:i] in names and text[i:] in names and text[:i] != text[i:]]


def recorded_segments(plan: Plan) -> dict[str, tuple[str, str]]:
    """The segments a plan names (as ``plans solve`` prints them) → (start, end)."""
    return dict(plan.ends)


class _Names:
    """Resolves the names a student writes to plan segments and values."""

    def __init__(self, sol: Solution):
        from plans.check.replay import _Replayer  # it reads measurements' names in turn

        self.sol = sol
        self.plans = {"velocity": sol.velocity, "acceleration": sol.acceleration}
        self.recorded = {k: recorded_segments(p) for k, p in self.plans.items()}
        self.recorded["positions"] = {k: (k, "") for k in sol.lengths}
        self.pos_names = set(sol.positions)
        self.rep = _Replayer(sol)

    def names(self) -> list[str]:
        """Every segment a file may name: the plan of positions', then the plans'."""
        return list(self.sol.lengths) + [
            k for p in ("velocity", "acceleration") for k in self.recorded[p]]

    def known(self) -> str:
        return ", ".join(self.names())

    def suggest(self, name: str) -> str:
        """'did you mean "pa3"? ' for a near miss (Pa3, pA3, PIa3, pa33), π as the file
        can write it bare (pia3); Cyrillic look-alikes are said by the caller."""
        names = self.names()
        allowed = set(names) | {n.replace("π", "pi") for n in names}
        latin = "".join(LOOKALIKES.get(c, c) for c in name)
        hit = close_match(latin, allowed)
        if "π" in hit and "π" not in name:
            hit = hit.replace("π", "pi")
        return hit

    def segment(self, key, where, scope, name, mm, problems) -> Item | None:
        """The item ``key`` (located in the file by ``where``) measuring segment ``name``."""
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
            problems.add(where, f"unknown segment \"{name}\"{_cyrillic(name)}; "
                            f"{self.suggest(name)}known: {self.known()} "
                            "(or any two points of one plan; write π as pi)")
            return None
        if len(cands) > 1:
            plans = sorted({c[0] for c in cands})
            if len(plans) > 1:
                problems.add(where, f"\"{name}\" names a segment on the {' and the '.join(plans)} "
                                f"plans: put it under [segments.{plans[-1]}] or "
                                f"[segments.{plans[0]}]")
            else:
                problems.add(where, f"\"{name}\" can be read as "
                                + " or ".join(f"{x}–{y}" for _, x, y in cands))
            return None
        (plan, x, y), sp = next(iter(cands.items()))
        return Item(key, sp, "segment", plan, mm, x, y)

    def value(self, key, where, name, value, problems) -> Item | None:
        sol = self.sol
        # α3 (alpha3) is ε3 as Western texts write the angular acceleration
        m = re.fullmatch(r"(omega|ω|w|epsilon|ε|eps|alpha|α)_?(\d+)", name)
        if m:
            link = int(m.group(2))
            kind = "omega" if m.group(1) in ("omega", "ω", "w") else "epsilon"
            if link not in sol.mechanism.links:
                problems.add(where, f"there is no link {link} (links: "
                                f"{', '.join(map(str, sorted(sol.mechanism.links)))})")
                return None
            mag, sense = _magnitude_sense(value, where, problems, allow_sense=True, kind=kind)
            if mag is None:
                return None
            plan = "velocity" if kind == "omega" else "acceleration"
            pair = self.rep.pairs.get(link)
            per_mm = 0.0
            if pair:
                per_mm = sol.mu[MU_KEY[plan]] / abs(sol.positions[pair[0]] - sol.positions[pair[1]])
            sym = "ω" if kind == "omega" else "ε"
            return Item(key, f"{sym}{link}", kind, plan, mag, link=link, sense=sense, per_mm=per_mm)
        hit = self._physical(name)
        if hit is None:
            labels = ["ω<link>", "ε<link>", "V_<point>", "a_<point>", "V_<point><point>"]
            labels += [v.label for v in sol.acceleration.vectors if v.component != "absolute"]
            problems.add(where, f"unknown value \"{name}\"; known: {', '.join(dict.fromkeys(labels))}")
            return None
        plan, x, y, label = hit
        mag, _ = _magnitude_sense(value, where, problems, allow_sense=False, kind=plan)
        if mag is None:
            return None
        return Item(key, label, "value", plan, mag, x, y,
                    per_mm=sol.mu[MU_KEY[plan]])

    def _physical(self, name: str):
        # a^τ as the Russian sheet and note write it; Norton's capital A (A_B, A^n_BA) is
        # a, and his Coriolis A^c the plan's a^k
        m = re.fullmatch(r"(V|v|a|A)(?:\^?([nktrτc]))?_(\w+)", name)
        if not m:
            return None
        sym, comp, rest = m.groups()
        comp = {"τ": "t", "c": "k"}.get(comp, comp)
        plan = self.sol.velocity if sym in "Vv" else self.sol.acceleration
        if comp:
            if sym not in "aA":
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


def _cyrillic(name: str) -> str:
    """', with the Cyrillic letters р, а: type them in Latin' where ``name`` has some."""
    return f", with {type_in_latin(name)}" if type_in_latin(name) else ""


def normal_unit(text: str) -> str:
    """A unit as a student types it, in one spelling: lower case, no spaces, powers as
    superscripts ("m/s^2", "m/s2", "м/с²" → "m/s²", "м/с²"; "s^-1", "с-1" → "s⁻¹", "с⁻¹").

    >>> [normal_unit(u) for u in ("M/S^2", "м/с2", "rad / s", "c^-1", "1/s**2")]
    ['m/s²', 'м/с²', 'rad/s', 'с⁻¹', '1/s²']
    """
    u = "".join(text.lower().split()).replace("**", "^")
    u = re.sub(r"(?<=[sсc])\^?-1$", "⁻¹", u)
    u = re.sub(r"(?<=[sсc])\^?-2$", "⁻²", u)
    u = re.sub(r"(?<=[sсc])\^?2$", "²", u)
    if re.search(r"[а-я]", u):  # "м/c" typed with a Latin c
        u = u.replace("c", "с")
    elif u in ("c⁻¹", "c⁻²"):
        u = "с" + u[1:]
    return u


def _split_sense(rest: str) -> tuple[str, int]:
    """The words after a magnitude as (unit, sense): the sense (SENSE_WORDS) before or
    after the unit, or alone."""
    r = " ".join(rest.lower().split())
    for phrase in sorted(SENSE_WORDS, key=len, reverse=True):
        if r == phrase:
            return "", SENSE_WORDS[phrase]
        if r.endswith(" " + phrase):
            return r[: -len(phrase) - 1], SENSE_WORDS[phrase]
        if r.startswith(phrase + " "):
            return r[len(phrase) + 1:], SENSE_WORDS[phrase]
    return r, 0


def _magnitude_sense(value, key, problems, *, allow_sense, kind="velocity"):
    """The magnitude and sense (+1 ccw, −1 cw, 0 not given) of a value of [values]: a
    number, or in quotes a number (decimal point or comma) with its unit and, for ω and
    ε (``allow_sense``), a sense: "4,82 рад/с против часовой стрелки"."""
    sense = 0
    main, units = VALUE_UNITS[kind]
    if isinstance(value, str):
        if allow_sense:
            example = (f'e.g. "4.82 ccw" or "4,82 {units[1]} против часовой стрелки" '
                       f"(senses: {SENSE_HINT})")
            bad = f"write a magnitude and a sense, {example}, got {quote(value)}"
        else:
            example = f'e.g. 2.77, "2,77" or "2.77 {main}"'
            bad = f"must be a number, got {quote(value)}: write {_WHAT[kind]} in {main}, {example}"
        m = re.fullmatch(rf"\s*({DECIMAL})\s*(.*?)\s*", value, re.S)
        if m is None:
            problems.add(key, bad)
            return None, 0
        unit, sense = _split_sense(m.group(2))
        if sense and not allow_sense:
            problems.add(key, f"{bad} (a sense is given for ω and ε only)")
            return None, 0
        if unit and normal_unit(unit) not in {normal_unit(u) for u in units}:
            other = next((k for k, (_, us) in VALUE_UNITS.items()
                          if normal_unit(unit) in {normal_unit(u) for u in us}), None)
            if other is not None:
                problems.add(key, f"{quote(value)} is in {unit}, the unit of {_WHAT[other]}: "
                                  f"{_WHAT[kind]} is in {' or '.join(units[:2])}")
            elif allow_sense:
                problems.add(key, f"{bad}: {quote(unit, 20)} is neither a sense nor a unit of "
                                  f"{_WHAT[kind]} ({', '.join(units)})")
            else:
                problems.add(key, f"must be a number, got {quote(value)}: {quote(unit, 20)} is not "
                                  f"a unit of {_WHAT[kind]}; write it in {' or '.join(units)}, "
                                  f"{example}")
            return None, 0
        mag = decimal(m.group(1))
        value = mag
        if allow_sense and mag < 0 and not sense:
            sense, value = -1, -mag  # "-4.82": clockwise, as a number would be
    elif allow_sense and isinstance(value, int | float) and not isinstance(value, bool) and value < 0:
        sense, value = -1, -value  # ω3 = -4.82: clockwise, as the engine signs it
    x = _num(value, key, problems, nonneg=True, unit=main,
             what="a magnitude with a sense word" if allow_sense else "a magnitude")
    if x is None:
        return None, 0
    return x, sense
