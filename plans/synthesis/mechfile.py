"""The synthesised mechanism as a mechanism file (TOML) that ``plans solve``, ``sheet``,
``cycle`` and ``forces`` take as they take a file written by hand: its links to the last
bit (they read back as the same floats), the requirements in a comment, the tables
[loads], [drive] and [title] of the synthesis file carried over as they are.

Points are named as the textbook names them: the crank pivot A, the crank pin B, the
coupler's (or rod's) far joint C, the rocker's pivot D (a slotted link: the rocker's pivot
C, its end D and the ram's joint E), and each link's centre of mass S1, S2, … mid-link,
which a [loads] table names (``centre = "S2"``).
"""

from __future__ import annotations

import cmath
import json
import math
from typing import Any

from plans.fmt import num
from plans.geometry import cross
from plans.synthesis.design import Design

#: the crank's speed where the requirements give none (rad/s)
OMEGA = 10.0

TITLES = {
    "crank-rocker": {"en": "Crank-rocker mechanism (synthesised by K)",
                     "ru": "Кривошипно-коромысловый механизм (синтез по K)"},
    "crank-slider": {"en": "Offset crank-slider mechanism (synthesised by K)",
                     "ru": "Дезаксиальный кривошипно-ползунный механизм (синтез по K)"},
    "slotted-link": {"en": "Shaper's slotted-link mechanism (synthesised by K)",
                     "ru": "Кулисный механизм поперечно-строгального станка (синтез по K)"},
    "function": {"en": "Four-bar linkage (synthesised by positions of crank and rocker)",
                 "ru": "Шарнирный четырёхзвенник (синтез по положениям кривошипа и коромысла)"},
    "coupler": {"en": "Four-bar linkage (synthesised by positions of the coupler)",
                "ru": "Шарнирный четырёхзвенник (синтез по положениям шатуна)"},
}


def _pt(z: complex) -> list[float]:
    return [z.real + 0.0, z.imag + 0.0]


def file_angle(design: Design) -> float:
    """The crank angle the written file gives (degrees from +x, counter-clockwise): the
    requirements' ``angle_deg``, else position 1's for the kinds by positions, else for the
    kinds by K the middle of the working (slower) stroke, to the whole degree, where the
    mechanism stands clear of its extreme positions."""
    p = design.problem
    if "angle_deg" in p.options:
        return float(p.options["angle_deg"])
    sol = design.solution
    if p.kind == "function":
        return math.degrees(p.given["phi"][0]) % 360.0
    if p.kind == "coupler":
        return math.degrees(cmath.phase(sol.points["B1"] - sol.points["A"])) % 360.0
    a, b = sol.extremes
    span = (b - a) % (2 * math.pi)
    mid = a + span / 2 if span > math.pi else b + (2 * math.pi - span) / 2
    return float(round(math.degrees(mid)) % 360)


def _fourbar_hint(A: complex, D: complex, a: float, b: float, c: float, phi: float,
                  above: bool | None, target: complex | None = None) -> str:
    """The hint that picks C's assembly at crank angle ``phi``: C on the side of AD the
    extremes are on (``above``), or nearest ``target`` (a given position's C); worded on
    BD as above/below or, where BD is steep, left/right."""
    B = A + a * complex(math.cos(phi), math.sin(phi))
    dist = abs(D - B)
    x = (b * b - c * c + dist * dist) / (2 * dist)
    h = math.sqrt(max(b * b - x * x, 0.0))
    w = (D - B) / dist
    cands = [B + (x + 1j * s * h) * w for s in (1, -1)]
    if target is not None:
        C = min(cands, key=lambda z: abs(z - target))
    else:
        side = [cross(D - A, z - A) for z in cands]
        C = cands[0] if (side[0] > 0) == bool(above) else cands[1]
    d = D - B
    s = cross(d, C - B)
    if abs(d.real) >= abs(d.imag):
        up = (s > 0) == (d.real > 0)
        return f"{'above' if up else 'below'} BD"
    left = (s > 0) == (d.imag > 0)
    return f"{'left of' if left else 'right of'} BD"


def mechanism_dict(design: Design) -> dict[str, Any]:
    """The chosen solution of ``design`` as a mechanism file's data (as ``plans.from_dict``
    takes it)."""
    p, sol = design.problem, design.solution
    L = sol.lengths
    opts = p.options
    angle = file_angle(design)
    driver: dict[str, Any] = {"link": 1, "angle_deg": angle}
    if "rpm" in opts:
        driver["rpm"] = opts["rpm"]
    else:
        driver["omega"] = opts.get("omega", OMEGA)
    driver["sense"] = opts.get("sense", "ccw")
    out: dict[str, Any] = {"name": opts.get("name", TITLES[p.kind])}
    if p.kind in ("crank-rocker", "function", "coupler"):
        A, D = sol.points["A"], sol.points["D"]
        a, b, c = L["AB"], L["BC"], L["CD"]
        phi = math.radians(angle)
        if p.kind == "crank-rocker":
            hint = _fourbar_hint(A, D, a, b, c, phi, sol.points["C1"].imag > 0)
        else:
            target = sol.points["C1"] if abs(phi - _phase(sol.points["B1"] - A)) < 1e-12 else None
            if target is None:  # the file's own angle: C on position 1's assembly
                target = _carried(A, D, a, b, c, sol.points["B1"], sol.points["C1"], phi)
            hint = _fourbar_hint(A, D, a, b, c, phi, None, target)
        out.update({
            "output": "C",
            "trace": ["S2"],
            "frame": {"A": _pt(A), "D": _pt(D)},
            "driver": driver,
            "links": {
                "1": {"name": "crank", "axis": ["A", "B"], "points": {"B": a, "S1": a / 2}},
                "2": {"name": "coupler", "axis": ["B", "C"], "points": {"C": b, "S2": b / 2}},
                "3": {"name": "rocker", "axis": ["D", "C"], "points": {"C": c, "S3": c / 2}},
            },
            "assembly": {"C": hint},
        })
    elif p.kind == "crank-slider":
        a, b, e = L["AB"], L["BC"], L["e"]
        y = e if opts.get("sense") == "cw" else -e
        out.update({
            "output": "C",
            "trace": ["S2"],
            "frame": {"A": [0.0, 0.0]},
            "driver": driver,
            "links": {
                "1": {"name": "crank", "axis": ["A", "B"], "points": {"B": a, "S1": a / 2}},
                "2": {"name": "connecting rod", "axis": ["B", "C"], "points": {"C": b, "S2": b / 2}},
                "3": {"name": "slider", "points": {"C": 0.0, "S3": 0.0}},
            },
            "sliders": [{"link": 3, "point": "C",
                         "guide": {"link": 0, "through": [0.0, y], "angle_deg": 0.0}}],
            "assembly": {"C": "right of A"},
        })
    else:
        a, ac, cd, h, de = (L[k] for k in ("AB", "AC", "CD", "h", "DE"))
        out.update({
            "output": "E",
            "trace": ["S4"],
            "frame": {"A": [0.0, 0.0], "C": [0.0, -ac]},
            "driver": driver,
            "links": {
                "1": {"name": "crank", "axis": ["A", "B"], "points": {"B": a, "S1": a / 2}},
                "2": {"name": "slide block", "points": {"B": 0.0}},
                "3": {"name": "rocker", "axis": ["C", "D"], "points": {"D": cd, "S3": cd / 2}},
                "4": {"name": "connecting rod", "axis": ["D", "E"], "points": {"E": de, "S4": de / 2}},
                "5": {"name": "ram", "points": {"E": 0.0, "S5": 0.0}},
            },
            "sliders": [{"link": 2, "guide": {"link": 3}},
                        {"link": 5, "point": "E",
                         "guide": {"link": 0, "through": [0.0, h - ac], "angle_deg": 0.0}}],
            "assembly": {"E": "right of D"},
        })
    for key in ("title", "loads", "drive"):
        if key in opts:
            out[key] = opts[key]
    return out


def _phase(z: complex) -> float:
    return math.atan2(z.imag, z.real) % (2 * math.pi)


def _carried(A, D, a, b, c, B1, C1, phi) -> complex:
    """C at crank angle ``phi`` on position 1's assembly: the side of BD that C₁ is on."""
    side = cross(D - B1, C1 - B1)
    B = A + a * complex(math.cos(phi), math.sin(phi))
    dist = abs(D - B)
    x = (b * b - c * c + dist * dist) / (2 * dist)
    h = math.sqrt(max(b * b - x * x, 0.0))
    w = (D - B) / dist
    s = 1 if side > 0 else -1
    return B + (x + 1j * s * h) * w


# --------------------------------------------------------------------------------------
# TOML
# --------------------------------------------------------------------------------------

def _value(v: Any) -> str:
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):
        return repr(v + 0.0)
    if isinstance(v, str):
        return json.dumps(v, ensure_ascii=False)
    if isinstance(v, list):
        return "[" + ", ".join(_value(x) for x in v) + "]"
    if isinstance(v, dict):
        return "{ " + ", ".join(f"{_key(k)} = {_value(x)}" for k, x in v.items()) + " }"
    raise TypeError(f"cannot write {type(v).__name__} to TOML")


def _key(k: Any) -> str:
    k = str(k)
    return k if k.replace("_", "").replace("-", "").isalnum() and k.isascii() else json.dumps(k)


def _table(path: str, body: dict, out: list[str]) -> None:
    """A table as [path] with its plain values, then its sub-tables and arrays of
    tables, as a hand-written file has them."""
    plain = {k: v for k, v in body.items() if not _nested(v)}
    if plain or not body:
        out.append(f"[{path}]")
        out += [f"{_key(k)} = {_value(v)}" for k, v in plain.items()]
    for k, v in body.items():
        if isinstance(v, dict) and _nested(v):
            _table(f"{path}.{_key(k)}", v, out)
        elif isinstance(v, list) and v and all(isinstance(x, dict) for x in v):
            for item in v:
                out.append(f"[[{path}.{_key(k)}]]")
                out += [f"{_key(kk)} = {_value(vv)}" for kk, vv in item.items()]


def _nested(v: Any) -> bool:
    return (isinstance(v, dict)) or (isinstance(v, list) and bool(v) and all(isinstance(x, dict) for x in v))


def mechanism_toml(design: Design, check=None) -> str:
    """The mechanism file's text: a comment with the requirements, the solution and the
    engine's re-analysis (``check``, :class:`plans.synthesis.verify.Check`), then the
    file."""
    data = mechanism_dict(design)
    p, sol = design.problem, design.solution
    kind = TITLES[p.kind]["en"].split(" (")[0]
    lines = [f"# {kind}: synthesised by `plans synth {p.kind}`."]
    lines.append("# Requirements: " + ("; ".join(p.text) if p.text else "none") + ".")
    n = len(design.solutions)
    if n > 1:
        lines.append(f"# Solution {design.chosen + 1} of {n} ({why_words(design)}); "
                     "`solution = N` takes another.")
    lines.append("# Links: " + ", ".join(f"{k} = {num(v * 1000, 5)} mm"
                                          for k, v in sol.lengths.items()) + ".")
    if check is not None:
        lines.append("# Checked by the engine's analysis of this file (as plans cycle does): "
                     + "; ".join(f"{r.name} = {r.shown}" for r in check.rows) + f" (each within "
                     f"{check.worst:.1e} of the synthesis).")
    if "loads" not in data:
        lines.append('# For plans forces add [loads] (README: Loads), e.g. [loads.links.2] mass = 1.3, '
                     'centre = "S2", and a useful resistance.')
    lines.append("")
    order = ("name", "output", "trace")
    for k in order:
        if k in data:
            lines.append(f"{k} = {_value(data[k])}")
    lines.append("")
    lines.append("[frame]")
    lines += [f"{k} = {_value(v)}" for k, v in data["frame"].items()]
    lines.append("")
    lines.append("[driver]")
    lines += [f"{k} = {_value(v)}" for k, v in data["driver"].items()]
    for lid, link in data["links"].items():
        lines.append("")
        lines.append(f"[links.{lid}]")
        lines += [f"{k} = {_value(v)}" for k, v in link.items()]
    for s in data.get("sliders", ()):
        lines.append("")
        lines.append("[[sliders]]")
        lines += [f"{k} = {_value(v)}" for k, v in s.items()]
    lines.append("")
    lines.append("[assembly]")
    lines += [f"{k} = {_value(v)}" for k, v in data["assembly"].items()]
    for key in ("title", "loads", "drive"):
        if key in data:
            lines.append("")
            _table(key, data[key], lines)
    return "\n".join(lines) + "\n"


def why_words(design: Design) -> str:
    """Why the chosen solution was chosen, in words."""
    p = design.problem
    if p.solution is not None:
        return "asked for"
    if design.why == "size":
        return "the smallest within the limit"
    if p.kind == "crank-slider":
        return "the least largest pressure angle"
    return "the largest γmin"
