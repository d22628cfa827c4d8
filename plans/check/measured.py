"""What a student measured on their drawing: the measurement file, the tolerance, and the
names of the segments (pa3, aa3, πa3, n1a3…) matched to the plans' recorded segments.

:func:`load` and :func:`from_dict` read a measurement file into a :class:`Measurement` of
:class:`Item` s, each saying which plan and which segment or value it is; every problem in
the file is reported at once, with its location. The force analysis's items (``[forces]``
and the forces of ``[values]``) are read by :mod:`plans.check.force_items`.
"""

from __future__ import annotations

import os
import re
import stat
from dataclasses import dataclass, replace
from pathlib import Path
from typing import Any

from plans.check.force_items import ForceNames, read_forces
from plans.check.forces import ForceContext
from plans.check.items import MU_KEY, PLANS, Item, Tolerance, parse_tolerance
from plans.check.reading import (  # noqa: F401  (SENSE_WORDS: the check's public words)
    SENSE_WORDS,
    magnitude_sense,
    normal_unit,
    number,
    scale,
)
from plans.check.replay import reading_pairs
from plans.cycle import analyse_cycle, outside, reachable_cycle
from plans.errors import AssemblyError, InputError, PlansError
from plans.kinematics.solver import Solver
from plans.model import MU_UNIT, Mechanism, variants
from plans.model import load as load_mechanism
from plans.model.fileformat import (
    LOOKALIKES,
    Problems,
    check_keys,
    close_match,
    key_text,
    other_kind,
    quote,
    read_toml,
    type_in_latin,
)
from plans.plan.solution import Plan, Solution, plan_name, solve_position

# ---------------------------------------------------------------------------------------
# what the student measured
# ---------------------------------------------------------------------------------------


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
    #: the exact force analysis and the student's μF, where the file measures forces
    forces: ForceContext | None = None


TOP_KEYS = {"title", "mechanism", "variant", "table", "angle_deg", "tolerance", "scales",
            "segments", "values", "forces"}


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
        for m, solver, cycle in self.known:
            if m == mech:
                return solver, cycle
        solver = Solver(mech)
        cycle = analyse_cycle(mech, solver=solver)
        self.known.append((mech, solver, cycle))
        return solver, cycle


def from_dict(data: dict, source: str = "<measurements>", folder: Path | None = None, *,
              text: str | None = None, solvers: Solvers | None = None) -> Measurement:
    """Build a :class:`Measurement` from parsed TOML (the mechanism is loaded and solved,
    with the solver ``solvers`` has for it, if given)."""
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
        angle = number(data["angle_deg"], "angle_deg", problems, unit="°")
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
    if "mu_F" in scales:  # the force plans' μF is the [forces] table's
        problems.add("scales.mu_F", "goes in [forces]: [forces] mu_F = 20 (N/mm)")
    check_keys({k: v for k, v in scales.items() if k != "mu_F"}, set(MU_KEY.values()), "scales", problems)
    for key, value in scales.items():
        if key not in MU_KEY.values():
            continue
        x = scale(value, f"scales.{key}", problems, MU_UNIT[key])
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
    raw_forces = data.get("forces")
    if raw_forces is not None and not isinstance(raw_forces, dict):
        problems.add("forces", "must be a table, e.g. [forces] mu_F = 20, \"R12^τ\" = 28.4")
        raw_forces = {}
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
                x = number(v2, where, problems, nonneg=True)
                if x is not None:
                    segs.append((f"segments.{key}.{k2}", where, key, k2, x))
            continue
        where = f"segments.{key_text(key)}"
        x = number(value, where, problems, nonneg=True)
        if x is not None:
            segs.append((f"segments.{key}", where, None, key, x))
    if not raw_segments and not raw_values and not raw_forces:
        problems.add("segments", "nothing to check: give the measured segments, e.g. "
                        '[segments] pa3 = 55, or a force analysis\'s ([forces] "R12^τ" = 28.4)')
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
    # the force analysis, where the file measures forces
    ctx = fnames = None
    if raw_forces is not None or (m.loads is not None and not all(map(names.kinematic, raw_values))):
        ctx = _force_context(sol, problems)
        fnames = ForceNames(ctx) if ctx is not None else None
    force_items: list[Item] = []
    mu_F: dict[str, float] = {}
    if fnames is not None and raw_forces:
        force_items, mu_F, given = read_forces(raw_forces, fnames, problems)
        ctx = replace(ctx, mu_F=mu_F, mu_F_given=given)
    for key, value in raw_values.items():
        where = f"values.{key_text(key)}"
        if fnames is not None and not names.kinematic(key):
            item = fnames.value(f"values.{key}", where, key, value, problems, mu_F)
            if item is not False:
                force_items += [item] if item is not None else []
                continue
        item = names.value(f"values.{key}", where, key, value, problems, fnames)
        if item is not None:
            items.append(item)
    seen: dict[tuple, Item] = {}
    for it in force_items:  # one force or arm twice, in two spellings
        was = seen.setdefault((it.plan, it.kind, it.name), it)
        if was is not it:
            problems.add(it.key, f"measures what {was.key} does: give each once")
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
    need |= {"velocity" for it in force_items if it.plan == "lever"}  # the velocity plan turned
    for plan in PLANS:
        if plan in need and MU_KEY[plan] not in scales:  # given but bad: said above
            what = {"positions": "the plan of positions", "velocity": "the velocity plan",
                    "acceleration": "the acceleration plan"}[plan]
            problems.add(f"scales.{MU_KEY[plan]}", f"missing: the scale factor the student "
                            f"used for {what}")
    if not items and not force_items and not problems:  # [forces] mu_F = 20 and nothing measured
        problems.add("forces", 'nothing to check: give the segments of the force plans, e.g. [forces] '
                     '"R12^τ" = 28.4, the lever\'s arms (h.G1 = 19) or the forces in [values]')
    problems.raise_if_any()
    read = [source] + [str(p) for p in (mech if not isinstance(mech, int) else table,) if p]
    return Measurement(source, m, sol, sol.mu, tuple(items + force_items), tol, title, angle,
                       tuple(read), frozenset(mu), ctx if force_items else None)


def _force_context(sol: Solution, problems: Problems) -> ForceContext | None:
    """The exact force analysis of the measurement's position; None, and a problem of
    [forces], where there is none: the mechanism gives no loads, or its force plans cannot
    be drawn here."""
    mech = sol.mechanism
    if mech.loads is None:
        problems.add("forces", f"the mechanism ({mech.source}) gives no loads: the force analysis "
                     'needs its [loads], e.g. [loads.links.3] mass = 10, J_S = 0.4, centre = "S3" '
                     "(README: Loads)")
        return None
    try:
        cycle = analyse_cycle(mech, solver=sol.solver) if mech.loads.resistance is not None else None
        return ForceContext.build(sol, cycle)
    except PlansError as exc:
        problems.add("forces", f"no force analysis at this position: {str(exc).split(': ', 1)[-1]}")
        return None


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
    try:  # a name too long, a folder in the path that is a file: said, never a traceback
        st = p.stat()
    except FileNotFoundError:
        problems.add(key, f"{name}: no such file (paths are relative to the measurement file)")
        return None
    except OSError as exc:
        problems.add(key, f"{name}: cannot read the file: {exc.strerror or exc}")
        return None
    if stat.S_ISDIR(st.st_mode):
        problems.add(key, f"{name}: is a folder, not a file")
        return None
    if not stat.S_ISREG(st.st_mode):  # /dev/zero, a pipe: there, but no file of the tool's
        problems.add(key, f"{name}: is a device or a pipe, not a file: name the {key} file")
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
        self.sol = sol
        self.plans = {"velocity": sol.velocity, "acceleration": sol.acceleration}
        self.recorded = {k: recorded_segments(p) for k, p in self.plans.items()}
        self.recorded["positions"] = {k: (k, "") for k in sol.lengths}
        self.pos_names = set(sol.positions)
        self.pairs = reading_pairs(sol)

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
        # a point whose letter is the plans' own is primed on them (p′, k′): ' types it
        spellings = [name] if "'" not in name else [name.replace("'", "′"), name]
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

    def kinematic(self, name: str) -> bool:
        """Whether [values] ``name`` is an ω, an ε or a value of the plans (V_A3, a^k_A3A)."""
        return bool(re.fullmatch(r"(omega|ω|w|epsilon|ε|eps|alpha|α)_?(\d+)", name)) or \
            self._physical(name) is not None

    def value(self, key, where, name, value, problems, forces=None) -> Item | None:
        """The item of [values] ``name``; ``forces``: the force analysis's names
        (:class:`plans.check.force_items.ForceNames`) an unknown name is offered too."""
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
            mag, sense = magnitude_sense(value, where, problems, allow_sense=True, kind=kind)
            if mag is None:
                return None
            plan = "velocity" if kind == "omega" else "acceleration"
            pair = self.pairs.get(link)
            per_mm = 0.0
            if pair:
                per_mm = sol.mu[MU_KEY[plan]] / abs(sol.positions[pair[0]] - sol.positions[pair[1]])
            sym = "ω" if kind == "omega" else "ε"
            return Item(key, f"{sym}{link}", kind, plan, mag, link=link, sense=sense, per_mm=per_mm)
        hit = self._physical(name)
        if hit is None:
            labels = ["ω<link>", "ε<link>", "V_<point>", "a_<point>", "V_<point><point>"]
            labels += [v.label for v in sol.acceleration.vectors if v.component != "absolute"]
            more = f"; forces and moments: {forces.known_values()}" if forces is not None else ""
            problems.add(where, f"unknown value \"{name}\"; known: {', '.join(dict.fromkeys(labels))}{more}")
            return None
        plan, x, y, label = hit
        mag, _ = magnitude_sense(value, where, problems, allow_sense=False, kind=plan)
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
