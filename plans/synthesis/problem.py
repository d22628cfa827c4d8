"""The requirements of a synthesis, from a file (TOML) or the command line's KEY=VALUE
words, with every problem located and said on one line.

Units as in a mechanism file: metres, degrees (keys ending ``_deg``), rad/s or rpm. A
number may be written with a decimal comma in quotes (``CD = "0,29"``).

>>> p = read_pairs(["crank-rocker", "K=1.25", "psi_deg=32", "CD=0.29", "BC=0,26"])
>>> p.kind, round(p.given["psi"], 6), p.given["BC"]
('crank-rocker', 0.558505, 0.26)
"""

from __future__ import annotations

import math
import tomllib
from dataclasses import replace
from pathlib import Path
from typing import Any

from plans.errors import InputError
from plans.model.fileformat import (
    Problems,
    check_keys,
    close_match,
    quote,
    read_number,
    read_toml,
)
from plans.synthesis.design import Problem

#: the kinds and the words of each: required keys, keys of which at most one fixes the
#: member (``one``), other keys it takes
KINDS: dict[str, dict[str, tuple[str, ...]]] = {
    "crank-rocker": {"required": ("K", "psi_deg", "CD"), "one": ("AB", "BC", "AD", "frame_deg"),
                     "optional": ("gamma_min_deg",)},
    "crank-slider": {"required": ("K", "H"),
                     "one": ("AB", "BC", "lambda", "e", "eps", "delta_m_deg", "delta_p_deg"),
                     "optional": ("p", "delta_max_deg")},
    "slotted-link": {"required": ("K", "H"), "one": ("AB", "AC"), "optional": ("DE", "alpha_max_deg")},
    "function": {"required": ("AD", "phi_deg", "psi_deg"), "one": ("AB", "CD"), "optional": ()},
    "coupler": {"required": ("B", "C"), "one": (), "optional": ("A", "D")},
}
ALIASES = {"shaper": "slotted-link"}
#: keys every kind takes: the written mechanism file's own, and how to choose
COMMON = ("kind", "name", "omega", "rpm", "sense", "angle_deg", "criterion", "solution",
          "loads", "drive", "title")
CRITERIA = ("best", "size")
#: open ranges of the angles (degrees), by key
ANGLES = {"psi_deg": (0.0, 180.0), "frame_deg": (0.0, 180.0), "gamma_min_deg": (0.0, 90.0),
          "delta_m_deg": (0.0, 90.0), "delta_p_deg": (0.0, 90.0), "delta_max_deg": (0.0, 90.0),
          "alpha_max_deg": (0.0, 90.0)}
LENGTHS = ("CD", "AB", "BC", "AD", "AC", "DE", "H", "e")
#: the limit a criterion "size" keeps to, by kind
LIMITS = {"crank-rocker": "gamma_min_deg", "crank-slider": "delta_max_deg"}


def kind_of(text: Any, where: str, pr: Problems) -> str | None:
    """The kind named by ``text`` (an alias taken), else None and a problem."""
    if not isinstance(text, str):
        pr.add(where, f"must be one of {', '.join(KINDS)}, got {quote(text)}")
        return None
    k = text.strip().lower()
    k = ALIASES.get(k, k)
    if k not in KINDS:
        guess = close_match(k, [*KINDS, *ALIASES])
        pr.add(where, f"unknown kind {quote(text)} — {guess}known: {', '.join(KINDS)} (shaper is "
                      "slotted-link)")
        return None
    return k


def read_file(path: str | Path, pairs: list[str] = ()) -> Problem:
    """The synthesis file at ``path``, with command-line ``pairs`` (KEY=VALUE) over it."""
    data, text = read_toml(path, "a synthesis file is a few lines")
    source = str(path)
    if {"frame", "links", "driver"} & data.keys():
        raise InputError(source, "a mechanism file, not a synthesis file: plans solve, sheet and "
                                 "forces read it; a synthesis file names its kind = \"crank-rocker\" …")
    extra = _pairs(pairs, Problems("command line"))
    pr = Problems(source, text)
    merged_data = {**data, **extra}
    if "kind" not in merged_data:
        pr.add("kind", f"missing: what to synthesise, one of {', '.join(KINDS)}")
        pr.raise_if_any()
    return replace(_read(merged_data, source, pr, _lines(text, data, extra)), file_text=text)


def read_pairs(words: list[str]) -> Problem:
    """The requirements on the command line: KIND then KEY=VALUE words."""
    pr = Problems("command line")
    if not words or "=" in words[0]:
        raise InputError("command line", "give the kind first (" + ", ".join(KINDS) +
                         ") or a synthesis file, then KEY=VALUE requirements")
    data = {"kind": words[0], **_pairs(words[1:], pr)}
    pr.raise_if_any()
    return _read(data, "command line", pr, list(words[1:]))


def _pairs(words, pr: Problems) -> dict[str, Any]:
    """KEY=VALUE words as a dict: each value read as TOML (numbers, lists, quoted text),
    else as the text it is (a decimal comma, a kind's name)."""
    out: dict[str, Any] = {}
    for w in words:
        if "=" not in w:
            pr.add("", f"{quote(w)} is not KEY=VALUE (e.g. K=1.25)")
            continue
        key, value = (s.strip() for s in w.split("=", 1))
        if not key:
            pr.add("", f"{quote(w)} has no key before its =")
            continue
        if key in out:
            pr.add(key, "given twice on the command line")
            continue
        try:
            out[key] = tomllib.loads(f"v = {value}")["v"]
        except (tomllib.TOMLDecodeError, ValueError, RecursionError):
            out[key] = value
    return out


def _lines(text: str, data: dict, extra: dict) -> list[str]:
    """The requirements as written, one "KEY = VALUE" each, for the mechanism file's
    comment: the file's top-level lines, then the command line's."""
    out = []
    for line in text.splitlines():
        s = line.split("#", 1)[0].strip()
        if not s:
            continue
        if s.startswith("["):
            break
        key = s.split("=", 1)[0].strip().strip('"')
        if "=" in s and key not in extra and key != "kind":
            out.append(s)
    out += [f"{k} = {v!r}" if isinstance(v, str) else f"{k} = {v}" for k, v in extra.items()]
    return out


def _read(data: dict, source: str, pr: Problems, text: list[str]) -> Problem:
    kind = kind_of(data.get("kind"), "kind", pr)
    if kind is None:
        pr.raise_if_any()
    spec = KINDS[kind]
    allowed = set(COMMON) | set(spec["required"]) | set(spec["one"]) | set(spec["optional"])
    check_keys(data, allowed, "", pr)
    given: dict[str, Any] = {}
    for key in spec["required"]:
        if key not in data:
            pr.add(key, f"missing: a {kind} needs {', '.join(spec['required'])}")
    fixing = [k for k in spec["one"] if k in data]
    if len(fixing) > 1 and kind != "slotted-link":
        pr.add(fixing[1], f"{' and '.join(fixing)} each fix the member: give one of them")
    if kind == "slotted-link":
        if len(fixing) != 1:
            pr.add("AB" if not fixing else fixing[1],
                   "give one of AB (the crank) and AC (the distance of the centres)")
        if "DE" in data and "alpha_max_deg" in data:
            pr.add("alpha_max_deg", "DE and alpha_max_deg each fix the rod DE: give one of them")
    for key in (*spec["required"], *spec["one"], *spec["optional"]):
        if key in data:
            value = _value(kind, key, data[key], pr)
            if value is not None:
                given[key.removesuffix("_deg") if key in ANGLES or key == "phi_deg" else key] = value
    _cross_checks(kind, data, given, pr)
    options = _options(data, pr)
    criterion = data.get("criterion", "best")
    if criterion not in CRITERIA:
        pr.add("criterion", f"must be one of {', '.join(CRITERIA)}, got {quote(criterion)}")
        criterion = "best"
    elif criterion == "size" and (kind not in LIMITS or LIMITS[kind] not in data):
        need = LIMITS.get(kind)
        pr.add("criterion", f'"size" takes the smallest member within a limit: give {need} too'
               if need else f'"size" chooses among a family: a {kind} has none to choose from')
    solution = data.get("solution")
    if solution is not None and (isinstance(solution, bool) or not isinstance(solution, int)
                                 or solution < 1):
        pr.add("solution", f"must be the number of a solution listed (1, 2 …), got {quote(solution)}")
        solution = None
    pr.raise_if_any()
    keys = {*spec["required"], *spec["one"], *spec["optional"], "criterion", "solution"}
    text = [line for line in text if line.split("=", 1)[0].strip().strip('"') in keys]
    return Problem(kind, given, source, options, criterion, solution, tuple(text))


def _value(kind: str, key: str, raw: Any, pr: Problems):
    if key in ("phi_deg", "psi_deg") and kind == "function":
        return _angles(key, raw, pr)
    if key in ("B", "C", "A", "D") and kind == "coupler":
        return _points(key, raw, pr, many=key in ("B", "C"))
    if key == "K":
        K = read_number(raw, key, pr, unit="")
        if K is None:
            return None
        if K <= 1:
            pr.add(key, f"K = {K:g} has no quick return ({'θ = 0' if K == 1 else 'θ < 0'}): "
                        "synthesis by K needs K > 1 (K = (180° + θ)/(180° − θ))")
            return None
        if K > 1e6:
            pr.add(key, f"{K:g} is out of range: K is the ratio of the two strokes' times (a typo?)")
            return None
        return K
    if key in ANGLES:
        x = read_number(raw, key, pr, unit="°", high=360.0)
        lo, hi = ANGLES[key]
        if x is None:
            return None
        if not lo < x < hi:
            pr.add(key, f"{x:g}° is out of range: it must lie between {lo:g}° and {hi:g}°")
            return None
        return math.radians(x)
    if key in LENGTHS:
        x = read_number(raw, key, pr, unit="m")
        if x is None:
            return None
        if x <= 0:
            pr.add(key, f"{'negative' if x < 0 else 'zero'} length {x:g} m: a length must be positive")
            return None
        return x
    if key in ("lambda", "eps", "p"):
        x = read_number(raw, key, pr, unit="")
        if x is None:
            return None
        bad = {"lambda": not 0 < x < 1, "eps": not x > 0, "p": not 0 < x <= 1}[key]
        if bad:
            why = {"lambda": "λ = AB/BC lies between 0 and 1 (a crank shorter than its rod)",
                   "eps": "ε = e/AB must be positive",
                   "p": "p, the share of the stroke H before its end where the working stroke "
                        "begins, lies in (0, 1]"}[key]
            pr.add(key, f"{x:g} is out of range: {why}")
            return None
        return x
    return None


def _angles(key: str, raw: Any, pr: Problems) -> list[float] | None:
    if not isinstance(raw, list) or not 2 <= len(raw) <= 3:
        pr.add(key, f"must be a list of two or three angles in degrees, e.g. [30, 60, 90], got "
                    f"{quote(raw)}")
        return None
    out = []
    for i, v in enumerate(raw):
        x = read_number(v, f"{key}[{i}]", pr, unit="°", high=3600.0)
        if x is None:
            return None
        out.append(math.radians(x))
    return out


def _points(key: str, raw: Any, pr: Problems, many: bool):
    if not many:
        return _point(raw, key, pr)
    if not isinstance(raw, list) or not 2 <= len(raw) <= 3:
        pr.add(key, f"must be a list of two or three points [x, y] in m, e.g. [[0, 0.1], "
                    f"[0.05, 0.12]], got {quote(raw)}")
        return None
    pts = [_point(v, f"{key}[{i}]", pr) for i, v in enumerate(raw)]
    return None if any(p is None for p in pts) else pts


def _point(raw: Any, where: str, pr: Problems) -> complex | None:
    if not isinstance(raw, list) or len(raw) != 2:
        pr.add(where, f"must be a point [x, y] in m, got {quote(raw)}")
        return None
    x = read_number(raw[0], where, pr)
    y = read_number(raw[1], where, pr)
    return None if x is None or y is None else complex(x, y)


def _cross_checks(kind: str, data: dict, given: dict, pr: Problems) -> None:
    if kind == "crank-slider":
        if ("delta_p_deg" in data) != ("p" in data):
            pr.add("p" if "delta_p_deg" in data else "delta_p_deg",
                   "delta_p_deg (the pressure angle where the working stroke begins) goes with p "
                   "(where it begins: p·H before the stroke's end)")
    if kind == "function":
        phi, psi = given.get("phi"), given.get("psi")
        if phi is not None and psi is not None and len(phi) != len(psi):
            pr.add("psi_deg", f"{len(psi)} rocker angles for {len(phi)} crank angles: give one "
                              "rocker angle per crank angle")
        if phi is not None:
            _distinct("phi_deg", phi, pr)
        if phi is not None and len(phi) == 3 and ("AB" in data or "CD" in data):
            pr.add("AB" if "AB" in data else "CD", "three positions fix every link: AB and CD "
                   "go with two positions only")
    if kind == "coupler":
        B, C = given.get("B"), given.get("C")
        if B is not None and C is not None and len(B) != len(C):
            pr.add("C", f"{len(C)} positions of C for {len(B)} of B: give both joints in every "
                        "position")
        if B is not None and len(B) == 3 and ("A" in data or "D" in data):
            pr.add("A" if "A" in data else "D", "three positions fix the pivots: A and D go "
                   "with two positions only")
        for name in ("B", "C"):
            pts = given.get(name)
            if pts is not None:
                for i in range(len(pts)):
                    for j in range(i):
                        if abs(pts[i] - pts[j]) < 1e-9:
                            pr.add(name, f"{name}{j + 1} and {name}{i + 1} are one point: each "
                                         "position must move the joint")


def _distinct(key: str, angles: list[float], pr: Problems) -> None:
    for i in range(len(angles)):
        for j in range(i):
            if abs(math.remainder(angles[i] - angles[j], 2 * math.pi)) < 1e-9:
                pr.add(key, f"positions {j + 1} and {i + 1} have one crank angle: each position "
                            "needs its own")


def _options(data: dict, pr: Problems) -> dict[str, Any]:
    """What the written mechanism file takes as given: its name, the crank's speed,
    sense and angle, and the tables [loads], [drive], [title] as they are."""
    out: dict[str, Any] = {}
    if "name" in data:
        name = data["name"]
        if isinstance(name, str) or (isinstance(name, dict) and all(
                isinstance(v, str) for v in name.values())):
            out["name"] = name
        else:
            pr.add("name", f"must be a text or {{ en = \"…\", ru = \"…\" }}, got {quote(name)}")
    if "omega" in data and "rpm" in data:
        pr.add("rpm", "omega and rpm both give the crank's speed: give one")
    for key, unit in (("omega", "rad/s"), ("rpm", "rpm")):
        if key in data:
            x = read_number(data[key], key, pr, unit=unit, positive=True)
            if x is not None:
                out[key] = x
    if "sense" in data:
        if data["sense"] in ("ccw", "cw"):
            out["sense"] = data["sense"]
        else:
            pr.add("sense", f'must be "ccw" or "cw", got {quote(data["sense"])}')
    if "angle_deg" in data:
        x = read_number(data["angle_deg"], "angle_deg", pr, unit="°", high=3600.0)
        if x is not None:
            out["angle_deg"] = x
    for key in ("loads", "drive", "title"):
        if key in data:
            if isinstance(data[key], dict):
                out[key] = data[key]
            else:
                pr.add(key, f"must be a table ([{key}]), got {quote(data[key])}")
    return out
