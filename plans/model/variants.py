"""Variant tables: a course's task table → mechanisms.

A table file (TOML) has ``[[variant]]`` rows with ``n``, the lengths ``AB`` (crank), ``BC``
(connecting rod or coupler), ``CD`` (rocker) and ``AD`` (frame) in metres, ``phi_deg`` and
``rpm``; ``kind`` = "crank-slider" or "four-bar" (default: even n → crank-slider, odd n →
four-bar, as in the built-in Table 2). Columns another course's table may add: ``omega``
(rad/s) instead of ``rpm``, ``sense`` of the crank ("ccw", the default, or "cw"), and a
crank-slider's offset ``e`` (m: its guide runs at y = e, above A where e > 0; default 0).

Conventions (the built-in table's): four-bar A = (0, 0), D = (−AD, 0), φ1 counter-clockwise
from +x, crank turning counter-clockwise, C above the line BD, E on BC produced beyond C
with CE = BC/2, centres of mass mid-link (S2 at the middle of BE); links 1 = AB, 2 = BE,
3 = CD. Crank-slider: A = (0, 0), slider C on the x axis on the +x side, zero offset,
S1, S2 mid-link, S3 = C; links 1 = AB, 2 = BC, 3 = slider.

A table's ``designation`` is the pattern of its sheets' document designation, with the
variant number as ``{n}`` (Python's format: ``"ТММ.КП.{n:02d}"`` gives ТММ.КП.07 for
variant 7); the default is :data:`DESIGNATION`.
"""

from __future__ import annotations

import operator
from dataclasses import replace
from importlib import resources
from pathlib import Path
from string import Formatter
from typing import NamedTuple

from plans.errors import InputError
from plans.model.fileformat import (
    MAX_ABS,
    Problems,
    close_match,
    key_text,
    other_kind,
    parse_toml,
    quote,
    read_number,
    read_toml,
)
from plans.model.load import from_dict
from plans.model.mechanism import SENSES, Mechanism
from plans.model.parts import MIN_LINK, RPM_MIN, SPEED

BUILTIN = "Table 2 (built in)"
#: :data:`BUILTIN` in Russian, for the reports in Russian that name a variant's source
BUILTIN_RU = "таблица 2 (встроенная)"
COLUMNS = ("AB", "BC", "CD", "AD", "phi_deg", "rpm")
#: the columns a row may add (module docstring): none of the built-in table's
OPTIONAL = ("omega", "sense", "e")
KINDS = ("crank-slider", "four-bar")
MAX_ROWS = 10_000
#: top-level keys a table may have besides its rows
TABLE_KEYS = {"variant", "title", "name", "source", "note", "designation", "loads"}
#: the keys of a table's ``[loads]``: the rules every row takes for its force analysis
LOAD_RULES = {"mass_per_metre", "g", "resistance", "inertia", "efficiency"}
#: the designation of a variant's sheet where its table gives none
DESIGNATION = "ПМ.01.{n:02d}"
ROW_KEYS = {"n", "kind", *COLUMNS, *OPTIONAL}


def load_table(path: str | Path | None = None) -> tuple[str, dict[int, dict]]:
    """The rows of a variant table by their number ``n``; every problem is reported at
    once, each with its line."""
    t = read_table(path)
    t.problems.raise_if_any()
    t.located(None, every=True).raise_if_any()
    return t.source, t.rows


class Table(NamedTuple):
    """A table read once, row by row: a problem of one numbered row is that row's own, so
    that a typo in variant 3 does not stop variant 5 (nor the sheets of the others)."""

    source: str
    text: str
    path: str | None  # the file, None for the built-in table
    problems: Problems  # of the table as a whole: no row can be read while there are any
    rows: dict[int, dict]  # the rows that can be read, by their number
    rows_problems: dict[int, list]  # the problems (key, message) of a numbered row, by number
    loose: list  # the problems of rows without a number: no variant's own, so none stops
    designation: str = DESIGNATION  # the pattern of a variant's designation, ``{n}`` its number
    rules: dict | None = None  # the table's [loads] rules, read (:func:`_rules`)

    @property
    def numbers(self) -> list[int]:
        """Every numbered row, those with problems too: each fails on its own. An
        InputError where the table cannot be used at all."""
        self.problems.raise_if_any()
        if not self.rows and not self.rows_problems:  # not one numbered row
            self.located(None).raise_if_any()
        return sorted(self.rows.keys() | self.rows_problems.keys())

    def located(self, n: int | None, every: bool = False) -> Problems:
        """The problems of the rows without a number and of row ``n`` (``every``: of every
        row but ``n``), in one list, so that they are located and capped once."""
        out = Problems(self.source, self.text)
        out.items = list(self.loose) + [it for m, items in sorted(self.rows_problems.items())
                                        if (m != n if every else m == n) for it in items]
        return out

    def variant(self, n: int) -> Mechanism:
        """Row ``n`` as a mechanism; the problems of that row, or of the table as a whole,
        are an InputError, those of other rows are not (:meth:`others`)."""
        try:  # variant("3") was "variant 3 is not in the table (it has 0, 1, 2, 3 …)"
            n = int(n) if isinstance(n, float) and n.is_integer() else operator.index(n)
        except TypeError:
            raise InputError(self.source, f"variant {n!r}: a variant is the whole number "
                                          "of a row, e.g. 3") from None
        self.numbers  # noqa: B018 - raises where the table cannot be used at all
        if n in self.rows_problems:
            own = Problems(self.source, self.text)
            own.items = list(self.rows_problems[n])
            own.raise_if_any()
        if n not in self.rows:
            raise InputError(self.source, [*self.located(n, every=True).lines(),
                                           f"variant {n} is not in the table ({self.has()})"])
        mech = from_dict(variant_dict(self.rows[n], self.designation, self.rules),
                         f"{self.source}, variant {n}")
        table_ru = BUILTIN_RU if self.path is None else self.source
        return replace(mech, sources={"ru": f"{table_ru}, вариант {n}"})

    def has(self) -> str:
        """The numbered rows in words, for a message: "it has 0, 1, 2" (or "0…99, 100
        rows" for a long table)."""
        have = self.numbers
        listed = ", ".join(map(str, have)) if len(have) <= 30 else f"{have[0]}…{have[-1]}, {len(have)} rows"
        return f"it has {listed}"

    def others(self, n: int | None) -> list[str]:
        """The problems of the rows other than ``n`` (None: of the rows without a number
        only), located, for warnings."""
        found = self.located(n, every=True) if n is not None else self.located(None)
        return [f"{self.source}: {line}" for line in found.lines()]


def read_table(path: str | Path | None = None) -> Table:
    """The table at ``path`` (None: the built-in Table 2), read once."""
    if path is None:
        text = resources.files("plans").joinpath("data/table2.toml").read_text("utf-8")
        source = BUILTIN
        data = parse_toml(text, source)
    else:
        source = str(path)
        data, text = read_toml(path, "a variant table is a few KB")
    pr = Problems(source, text)
    loose = Problems(source, text)
    table: dict[int, dict] = {}
    bad: dict[int, Problems] = {}

    def done() -> Table:
        return Table(source, text, None if path is None else str(path), pr, table,
                     {n: p.items for n, p in bad.items() if p}, loose.items,
                     pattern if isinstance(pattern, str) else DESIGNATION, rules)
    pattern = data.get("designation", DESIGNATION)
    rules = None
    if why := other_kind(data, source, "table"):
        pr.add("", why)
        return done()
    if "loads" in data:
        rules = _rules(data["loads"], pr)
    for key in data:
        if key not in TABLE_KEYS:
            pr.add(key_text(key), "unknown key — a table has [[variant]] rows (and title, name, "
                                  "source, note, designation, loads)")
        elif key not in ("variant", "loads") and not isinstance(data[key], str):
            pr.add(key, f"must be text in double quotes, got {quote(data[key])}")
        elif key == "designation" and (why := _bad_pattern(data[key])):
            pr.add(key, f"{why}, got {quote(data[key])}")
            pattern = None
    rows = data.get("variant")
    if not isinstance(rows, list) or not rows:
        got = "" if rows is None else f" (got {quote(rows)})"
        pr.add("variant", "missing: the table needs [[variant]] rows with n, AB, BC, CD, AD, phi_deg, "
                          f"rpm{got}")
        return done()
    if len(rows) > MAX_ROWS:
        pr.add("variant", f"{len(rows)} rows: at most {MAX_ROWS}")
        return done()
    first: dict[int, int] = {}
    for i, row in enumerate(rows):
        where = f"variant[{i}]"
        if not isinstance(row, dict):
            loose.add(where, f"must be a table ([[variant]] n = …, AB = …), got {quote(row)}")
            continue
        n = row.get("n")
        if isinstance(n, bool) or not isinstance(n, int) or not 0 <= n < 10**6:
            got = "missing" if n is None else f"got {quote(n, 20)}"
            loose.add(where + ".n", f"the variant number must be a whole number 0…999999, {got}")
            continue
        rp = bad.setdefault(n, Problems(source, text))
        for key in row:
            if key not in ROW_KEYS:
                rp.add(f"{where}.{key_text(key)}", f"unknown column (variant {n}) — "
                                                   f"{close_match(key, ROW_KEYS)}known: "
                                                   f"{', '.join(sorted(ROW_KEYS))}")
        if n in first:
            rp.add(where + ".n",
                   f"variant {n} appears twice (first as variant[{first[n]}]): each number once")
            table.pop(n, None)
            continue
        first[n] = i
        kind = row.get("kind", "crank-slider" if n % 2 == 0 else "four-bar")
        if kind not in KINDS:
            rp.add(where + ".kind", f'must be "crank-slider" or "four-bar", got {quote(kind, 30)} (variant '
                                    f'{n})')
            continue
        need = COLUMNS if kind == "four-bar" else ("AB", "BC", "phi_deg", "rpm")
        if "kind" not in row and kind == "four-bar" and not {"CD", "AD"} & row.keys():
            # a crank-slider row of another course's table, its kind left to Table 2's rule:
            # "CD missing, AD missing" would not say why it was read as a four-bar
            rp.add(where + ".kind", f"missing: variant {n} has no CD, AD and no kind, and an odd "
                                    'n is a four-bar (as in Table 2): write kind = "crank-slider"'
                                    " (or give CD and AD)")
            need = ("AB", "BC", "phi_deg", "rpm")  # its numbers are checked all the same
        values = {}
        if "omega" in row:  # the crank's speed in rad/s instead of rpm
            need = tuple(c for c in need if c != "rpm")
            if "rpm" in row:
                rp.add(where + ".omega", f"give omega (rad/s) or rpm, not both (variant {n})")
            else:
                values["omega"] = read_number(row["omega"], where + ".omega", rp, positive=True,
                                              unit="rad/s", low=SPEED[0], high=SPEED[1])
        if "sense" in row and not (isinstance(row["sense"], str) and row["sense"] in SENSES):
            rp.add(where + ".sense", f'must be "ccw" (counter-clockwise) or "cw" (clockwise), '
                                     f"got {quote(row['sense'], 20)} (variant {n})")
        if "e" in row:
            if kind != "crank-slider":
                rp.add(where + ".e", f"an offset is a crank-slider's; variant {n} is a {kind}")
            else:
                values["e"] = read_number(row["e"], where + ".e", rp, unit="m", high=MAX_ABS)
        for col in need:
            cw = f"{where}.{col}"
            if col not in row:
                rp.add(cw, f"missing: {kind} variant {n} needs {', '.join(need)}")
            elif col == "phi_deg":
                values[col] = read_number(row[col], cw, rp, unit="°")
            elif col == "rpm":
                # as a mechanism file's rpm, else the row passed here and failed as
                # "driver.rpm", a key the table has not, with no line
                values[col] = read_number(row[col], cw, rp, positive=True, unit="rpm",
                                          low=RPM_MIN, high=SPEED[1])
            else:
                values[col] = read_number(row[col], cw, rp, positive=True, low=MIN_LINK, high=MAX_ABS)
        if not rp:
            table[n] = dict(row, kind=kind, **values)
    return done()


def _rules(raw, pr: Problems) -> dict | None:
    """A table's ``[loads]``: the rules of seed 001's task 1 that make each row's loads
    (:func:`variant_dict`): ``mass_per_metre`` (kg per metre of link), ``g``,
    ``resistance`` (the useful resistance as so many times a weight), ``inertia``
    ("forces" or "forces and moments") and the gearbox's ``efficiency``."""
    if not isinstance(raw, dict):
        pr.add("loads", f"must be a table ([loads] mass_per_metre = 5, …), got {quote(raw)}")
        return None
    out: dict = {}
    for key in raw:
        if key not in LOAD_RULES:
            pr.add(f"loads.{key_text(key)}", f"unknown key — {close_match(key, LOAD_RULES)}known: "
                   f"{', '.join(sorted(LOAD_RULES))}")
    for key, unit, hi in (("mass_per_metre", "kg/m", 1e6), ("g", "m/s²", 1000.0), ("resistance", "", 1e6),
                          ("efficiency", "", 1.0)):
        if key in raw:
            v = read_number(raw[key], f"loads.{key}", pr, positive=True, unit=unit, high=hi)
            if v is not None:
                out[key] = v
    if "inertia" in raw:
        if raw["inertia"] in ("forces", "forces and moments"):
            out["inertia"] = raw["inertia"]
        else:
            pr.add("loads.inertia", f'must be "forces" or "forces and moments", got {quote(raw["inertia"])}')
    return out


def _row_loads(row: dict, rules: dict) -> tuple[dict, dict]:
    """The ``[loads]`` and ``[drive]`` of one row by the table's rules (seed 001, steps 4–9):
    each link's mass at so many kg per metre of its length at its middle (the four-bar's
    coupler BE counts BC + CE, CE = BC/2), a crank-slider's slider as heavy as its rod,
    the useful resistance so many times the slider's weight on the slider (crank-slider)
    or the coupler's at E (four-bar), against the point's velocity; Ш is the variant's
    last digit."""
    q = rules.get("mass_per_metre", 5.0)
    ab, bc = row["AB"], row["BC"]
    loads: dict = {"g": rules.get("g", 9.81), "inertia": rules.get("inertia", "forces and moments")}
    if row["kind"] == "four-bar":
        masses = {"1": q * ab, "2": q * 1.5 * bc, "3": q * row["CD"]}
        heavy, point = 2, "E"
    else:
        masses = {"1": q * ab, "2": q * bc, "3": q * bc}
        heavy, point = 3, "C"
    loads["links"] = {k: {"mass": m, "centre": f"S{k}"} for k, m in masses.items()}
    if "resistance" in rules:
        loads["forces"] = [{"name": "F_пс", "point": point, "link": heavy, "weight_of": heavy,
                            "times": rules["resistance"], "direction": "against velocity"}]
    drive = {"efficiency": rules.get("efficiency", 0.9), "digit": row["n"] % 10}
    return loads, drive


def _bad_pattern(pattern: str) -> str | None:
    """What is wrong with a table's designation pattern, None if nothing: it must name the
    variant ``{n}`` (else every sheet would carry one designation) and nothing else."""
    try:
        fields = [f for _, f, _, _ in Formatter().parse(pattern) if f is not None]
        pattern.format(n=7)
    except (ValueError, KeyError, IndexError, AttributeError, TypeError):
        fields = None
    if fields is None or any(f != "n" for f in fields):
        return ('must hold the variant number as {n} and no other field in braces, '
                'as "ТММ.КП.{n:02d}"')
    if not fields:
        return 'must hold the variant number as {n} (as "ТММ.КП.{n:02d}"): each sheet its own'
    return None


def variant_dict(row: dict, designation: str = DESIGNATION, rules: dict | None = None) -> dict:
    """The mechanism file (as a parsed dict) of one table row; ``designation``, its
    table's pattern (``{n}`` the variant); ``rules``: its ``[loads]`` (:func:`_rules`)."""
    out = _variant_dict(row, designation)
    if rules is not None:
        out["loads"], out["drive"] = _row_loads(row, rules)
    return out


def _variant_dict(row: dict, designation: str) -> dict:
    ab, bc, phi = row["AB"], row["BC"], row["phi_deg"]
    n = row["n"]
    title = {"designation": designation.format(n=n)}
    speed = {"omega": row["omega"]} if "omega" in row else {"rpm": row["rpm"]}
    driver = {"link": 1, "angle_deg": phi, **speed, "sense": row.get("sense", "ccw")}
    if row["kind"] == "four-bar":
        cd, ad = row["CD"], row["AD"]
        return {
            "name": {"en": f"Four-bar linkage, variant {n}",
                     "ru": f"Шарнирный четырёхзвенник, вариант {n}"},
            "frame": {"A": [0.0, 0.0], "D": [-ad, 0.0]},
            "driver": driver,
            "links": {
                "1": {"name": "crank", "axis": ["A", "B"], "points": {"B": ab, "S1": ab / 2}},
                "2": {"name": "coupler", "axis": ["B", "C"],
                      "points": {"C": bc, "E": 1.5 * bc, "S2": 0.75 * bc}},
                "3": {"name": "rocker", "axis": ["D", "C"], "points": {"C": cd, "S3": cd / 2}},
            },
            "assembly": {"C": "above BD"},
            "trace": ["E"],
            "output": "C",
            "title": title,
        }
    return {
        "name": {"en": f"Crank-slider mechanism, variant {n}",
                 "ru": f"Кривошипно-ползунный механизм, вариант {n}"},
        "frame": {"A": [0.0, 0.0]},
        "driver": driver,
        "links": {
            "1": {"name": "crank", "axis": ["A", "B"], "points": {"B": ab, "S1": ab / 2}},
            "2": {"name": "connecting rod", "axis": ["B", "C"], "points": {"C": bc, "S2": bc / 2}},
            "3": {"name": "slider", "points": {"C": 0.0, "S3": 0.0}},
        },
        "sliders": [{"link": 3, "point": "C",
                     "guide": {"link": 0, "through": [0.0, row.get("e", 0.0)], "angle_deg": 0.0}}],
        "assembly": {"C": "right of A"},
        "trace": ["S2"],
        "output": "C",
        "title": title,
    }


def variant(n: int, table: str | Path | None = None) -> Mechanism:
    """Row ``n`` of the table at ``table`` (None: the built-in one)."""
    return read_table(table).variant(n)


def variant_numbers(table: str | Path | None = None) -> list[int]:
    """Every numbered row of the table, those with problems too."""
    return read_table(table).numbers
