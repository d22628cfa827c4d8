"""Variant tables: a course's task table → mechanisms.

A table file (TOML) has ``[[variant]]`` rows with ``n``, the lengths ``AB`` (crank), ``BC``
(connecting rod or coupler), ``CD`` (rocker) and ``AD`` (frame) in metres, ``phi_deg`` and
``rpm``; ``kind`` = "crank-slider" or "four-bar" (default: even n → crank-slider, odd n →
four-bar, as in the built-in Table 2).

Conventions (the built-in table's): four-bar A = (0, 0), D = (−AD, 0), φ1 counter-clockwise
from +x, crank turning counter-clockwise, C above the line BD, E on BC produced beyond C
with CE = BC/2, centres of mass mid-link (S2 at the middle of BE); links 1 = AB, 2 = BE,
3 = CD. Crank-slider: A = (0, 0), slider C on the x axis on the +x side, zero offset,
S1, S2 mid-link, S3 = C; links 1 = AB, 2 = BC, 3 = slider.
"""

from __future__ import annotations

import tomllib
from importlib import resources
from pathlib import Path

from .errors import InputError
from .mechanism import Mechanism, from_dict

BUILTIN = "Table 2 (built in)"
COLUMNS = ("AB", "BC", "CD", "AD", "phi_deg", "rpm")


def load_table(path: str | Path | None = None) -> tuple[str, dict[int, dict]]:
    if path is None:
        text = resources.files("plans").joinpath("data/table2.toml").read_text("utf-8")
        source = BUILTIN
    else:
        source = str(path)
        try:
            text = Path(path).read_text("utf-8")
        except (OSError, UnicodeDecodeError) as exc:
            raise InputError(source, f"cannot read the table: {exc}") from None
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise InputError(source, f"TOML syntax error: {exc}") from None
    rows = data.get("variant")
    if not isinstance(rows, list) or not rows:
        raise InputError(source, "variant: missing; the table needs [[variant]] rows")
    table: dict[int, dict] = {}
    problems = []
    for i, row in enumerate(rows):
        where = f"variant[{i}]"
        if not isinstance(row, dict):
            problems.append(f"{where}: must be a table")
            continue
        n = row.get("n")
        if not isinstance(n, int) or isinstance(n, bool) or n < 0:
            problems.append(f"{where}.n: must be a whole number ≥ 0, got {n!r:.20}")
            continue
        if n in table:
            problems.append(f"{where}.n: variant {n} appears twice")
            continue
        kind = row.get("kind", "crank-slider" if n % 2 == 0 else "four-bar")
        if kind not in ("crank-slider", "four-bar"):
            problems.append(f'{where}.kind: must be "crank-slider" or "four-bar", got {kind!r:.30}')
            continue
        need = COLUMNS if kind == "four-bar" else ("AB", "BC", "phi_deg", "rpm")
        bad = False
        for col in need:
            v = row.get(col)
            if isinstance(v, bool) or not isinstance(v, int | float):
                problems.append(f"{where}.{col}: missing or not a number (variant {n})")
                bad = True
            elif col not in ("phi_deg",) and not (0 < v < 1e6):
                problems.append(f"{where}.{col}: must be positive, got {v} (variant {n})")
                bad = True
        if not bad:
            table[n] = dict(row, kind=kind)
    if problems:
        raise InputError(source, problems)
    return source, table


def variant_dict(row: dict) -> dict:
    """The mechanism file (as a parsed dict) of one table row."""
    ab, bc, phi, rpm = row["AB"], row["BC"], row["phi_deg"], row["rpm"]
    n = row["n"]
    driver = {"link": 1, "angle_deg": phi, "rpm": rpm, "sense": "ccw"}
    if row["kind"] == "four-bar":
        cd, ad = row["CD"], row["AD"]
        return {
            "name": f"Four-bar linkage, variant {n}",
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
            "title": {"designation": f"ПМ.01.{n:02d}"},
        }
    return {
        "name": f"Crank-slider mechanism, variant {n}",
        "frame": {"A": [0.0, 0.0]},
        "driver": driver,
        "links": {
            "1": {"name": "crank", "axis": ["A", "B"], "points": {"B": ab, "S1": ab / 2}},
            "2": {"name": "connecting rod", "axis": ["B", "C"], "points": {"C": bc, "S2": bc / 2}},
            "3": {"name": "slider", "points": {"C": 0.0, "S3": 0.0}},
        },
        "sliders": [{"link": 3, "point": "C",
                     "guide": {"link": 0, "through": [0.0, 0.0], "angle_deg": 0.0}}],
        "assembly": {"C": "right of A"},
        "trace": ["S2"],
        "output": "C",
        "title": {"designation": f"ПМ.01.{n:02d}"},
    }


def variant(n: int, table: str | Path | None = None) -> Mechanism:
    source, rows = load_table(table)
    if n not in rows:
        raise InputError(source, f"variant {n} is not in the table (it has {', '.join(map(str, sorted(rows)))})")
    return from_dict(variant_dict(rows[n]), f"{source}, variant {n}")


def variant_numbers(table: str | Path | None = None) -> list[int]:
    return sorted(load_table(table)[1])
