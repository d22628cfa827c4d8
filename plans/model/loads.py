"""The loads of a mechanism, as its file gives them: masses and moments of inertia, g,
forces at points with a rule for their direction, moments on links, the useful-resistance
graph P(S) of the output, and the drive's data (``[loads]`` and ``[drive]``).

What they amount to at a crank position (weights, inertia forces from the exact
acceleration plan, the resistance read off its graph) is worked out by
:mod:`plans.forces.loads`; this module is the data and its reading only.

>>> loads = read_loads({"links": {"3": {"mass": 10, "J_S": 0.4, "centre": "S3"}}},
...                    {3: {"B", "C", "S3"}}, Problems("press.toml"))
>>> loads.masses[3]
Mass(link=3, mass=10.0, J=0.4, centre='S3')
>>> loads.g
9.81
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

from plans.model.fileformat import (
    Problems,
    check_keys,
    close_match,
    key_text,
    name_list,
    quote,
    read_number,
    read_text,
)

#: standard gravity, m/s² (seed 000 uses 9.81; seed 001 writes 9.8 and says so)
G_STANDARD = 9.81
#: at most this many kg, N, N·m: anything larger is a typo, not a course project's machine
MAX_LOAD = 1e9
#: rows of a P(S) graph
MAX_GRAPH = 10_000
#: how a force's direction may be given in words
DIRECTIONS = ("along velocity", "against velocity", "along guide", "against guide")
#: how a moment's sense may be given in words (the link's own ω)
SENSES = ("along omega", "against omega")
#: how the inertia loads are taken: both (the default), or forces only (seed 001's workbook)
INERTIA = ("forces and moments", "forces")
#: how an inertia moment is drawn and written: as it is, as a couple of two forces at the
#: link's two joints ⊥ the link (seed 000), or by shifting the inertia force
COUPLES = ("moment", "pair", "shift")


@dataclass(frozen=True, slots=True)
class Mass:
    """The mass (kg) of link ``link`` at its centre of mass ``centre`` (a point of the
    link), and its central moment of inertia J_S (kg·m²)."""

    link: int
    mass: float
    J: float
    centre: str


@dataclass(frozen=True, slots=True)
class PointForce:
    """A force at a point: a fixed magnitude, or ``times`` the weight of link
    ``weight_of``; its direction by ``rule`` (one of :data:`DIRECTIONS`) or at a fixed
    angle (rad from +x, counter-clockwise)."""

    name: str
    point: str
    magnitude: float | None = None
    link: int | None = None  # the link it acts on (default: the first that carries the point)
    weight_of: int | None = None
    times: float = 1.0
    rule: str | None = None
    angle: float | None = None


@dataclass(frozen=True, slots=True)
class LinkMoment:
    """A moment on a link (N·m): counter-clockwise positive, or of ``magnitude`` along or
    against the link's ω (``rule``)."""

    name: str
    link: int
    moment: float
    rule: str | None = None


@dataclass(frozen=True, slots=True)
class Resistance:
    """The useful-resistance graph P(S) of the output: (s, P) points, s measured from the
    extreme position that starts the working stroke (m, or a fraction of the stroke H
    where ``relative``); P (N) against the output's motion on the working stroke, and
    ``idle`` (N) on the idle stroke. Between the points P is linear in s."""

    s: tuple[float, ...]
    P: tuple[float, ...]
    relative: bool = False
    idle: float = 0.0
    name: str = "P"

    @property
    def peak(self) -> float:
        return max(self.P)


@dataclass(frozen=True, slots=True)
class Loads:
    g: float = G_STANDARD
    masses: dict[int, Mass] = field(default_factory=dict)
    forces: tuple[PointForce, ...] = ()
    moments: tuple[LinkMoment, ...] = ()
    resistance: Resistance | None = None
    inertia: str = "forces and moments"
    couples: str = "moment"

    @property
    def inertia_moments(self) -> bool:
        return self.inertia == "forces and moments"


@dataclass(frozen=True, slots=True)
class Drive:
    """The drive's data (seed 001 steps 8–9): the gearbox's efficiency η, the digit Ш of
    the tooth numbers z1 = z3 = 20 + Ш, and the motor catalogue."""

    efficiency: float = 0.9
    digit: int = 0
    catalogue: str = "4A"
    synchronous: int = 3000  # rpm: the motors' pole count (3000, 1500, 1000, 750)
    #: the power the motor is chosen for: at the analysed position (seed 001), or the
    #: cycle's mean (a machine with a flywheel)
    power: str = "position"


def _keyword(value: Any, where: str, allowed: tuple[str, ...], pr: Problems) -> str | None:
    if not isinstance(value, str) or value.strip().lower() not in allowed:
        words = ", ".join(f'"{a}"' for a in allowed)
        guess = close_match(value, allowed) if isinstance(value, str) else ""
        pr.add(where, f"{quote(value)} is not one of {words}" + (f" — {guess.strip()}" if guess else ""))
        return None
    return value.strip().lower()


def _link_key(key: Any, where: str, links: dict[int, set[str]], pr: Problems) -> int | None:
    if isinstance(key, str) and key.isdigit() and key == str(int(key)) and int(key) in links:
        return int(key)
    pr.add(where, f"{quote(key)} is not a moving link: the links are {name_list(map(str, links))}")
    return None


def _point(value: Any, where: str, known: set[str], pr: Problems, what: str) -> str | None:
    if not isinstance(value, str) or value not in known:
        guess = close_match(value, known) if isinstance(value, str) else ""
        pr.add(where, f"unknown point {quote(value)}: {guess}{what} {name_list(known)}")
        return None
    return value


def read_loads(
    raw: Any,
    points: dict[int, set[str]],
    pr: Problems,
    where: str = "loads",
    sliding: frozenset[int] | None = None,
) -> Loads:
    """The ``[loads]`` table of a mechanism file; ``points``: each moving link's point
    names; ``sliding``: the links that slide on a guide (a force "along guide" needs one).
    Every problem goes to ``pr``, located by its key path."""
    if not isinstance(raw, dict):
        pr.add(where, f"must be a table ([loads]), got {quote(raw)}")
        return Loads()
    check_keys(raw, {"g", "links", "forces", "moments", "resistance", "inertia", "couples"}, where, pr)
    g = read_number(
        raw.get("g"), f"{where}.g", pr, positive=True, default=G_STANDARD, unit="m/s²", high=1000.0
    )
    inertia = couples = None
    if "inertia" in raw:
        inertia = _keyword(raw["inertia"], f"{where}.inertia", INERTIA, pr)
    if "couples" in raw:
        couples = _keyword(raw["couples"], f"{where}.couples", COUPLES, pr)
    everywhere = set().union(*points.values()) if points else set()
    masses: dict[int, Mass] = {}
    raw_links = raw.get("links", {})
    if not isinstance(raw_links, dict):
        pr.add(
            f"{where}.links",
            f"must be a table of links, e.g. [loads.links.3] mass = 10, got {quote(raw_links)}",
        )
        raw_links = {}
    for key, body in raw_links.items():
        at = f"{where}.links.{key_text(key)}"
        lid = _link_key(key, at, points, pr)
        if not isinstance(body, dict):
            pr.add(
                at, f'must be a table such as {{ mass = 10, J_S = 0.4, centre = "S3" }}, got {quote(body)}'
            )
            continue
        check_keys(body, {"mass", "J_S", "centre"}, at, pr)
        m = read_number(body.get("mass"), f"{at}.mass", pr, unit="kg", high=MAX_LOAD, default=0.0)
        J = read_number(body.get("J_S"), f"{at}.J_S", pr, unit="kg·m²", high=MAX_LOAD, default=0.0)
        for name, v in (("mass", m), ("J_S", J)):
            if v is not None and v < 0:
                pr.add(
                    f"{at}.{name}",
                    f"negative {'mass' if name == 'mass' else 'moment of inertia'} {v:g}: "
                    f"it is at least 0 (write {-v:g})",
                )
        centre = None
        if lid is not None:
            default = f"S{lid}" if f"S{lid}" in points[lid] else None
            if "centre" in body:
                centre = _point(
                    body["centre"],
                    f"{at}.centre",
                    points[lid],
                    pr,
                    f"the centre of mass is a point of link {lid}:",
                )
            elif (m or J) and default is None:
                pr.add(
                    at,
                    f"centre missing: name the centre of mass, a point of link {lid} "
                    f'({name_list(points[lid])}), e.g. centre = "{next(iter(sorted(points[lid])), "S")}"',
                )
            else:
                centre = default
        if lid is not None and centre is not None and m is not None and J is not None and m >= 0 and J >= 0:
            masses[lid] = Mass(lid, m, J, centre)
    forces = tuple(_forces(raw.get("forces", []), f"{where}.forces", points, everywhere, pr))
    for i, f in enumerate(forces):
        if sliding is not None and f.rule in ("along guide", "against guide") and f.link not in sliding:
            pr.add(
                f"{where}.forces[{i}].direction",
                f'"{f.rule}": link {f.link} slides on no guide; '
                "give angle_deg, or a direction along or against the point's velocity",
            )
    moments = tuple(_moments(raw.get("moments", []), f"{where}.moments", points, pr))
    resistance = None
    if "resistance" in raw:
        resistance = read_resistance(raw["resistance"], f"{where}.resistance", pr)
    return Loads(
        g=g if g is not None else G_STANDARD,
        masses=masses,
        forces=forces,
        moments=moments,
        resistance=resistance,
        inertia=inertia or "forces and moments",
        couples=couples or "moment",
    )


def _rows(raw: Any, where: str, pr: Problems, example: str) -> list[tuple[str, dict]]:
    if isinstance(raw, dict):
        raw = [raw]
    if not isinstance(raw, list):
        pr.add(where, f"must be a list of tables ({example}), got {quote(raw)}")
        return []
    if len(raw) > 1000:
        pr.add(where, f"{len(raw)} entries: at most 1000")
        return []
    out = []
    for i, body in enumerate(raw):
        at = f"{where}[{i}]"
        if not isinstance(body, dict):
            pr.add(at, f"must be a table ({example}), got {quote(body)}")
            continue
        out.append((at, body))
    return out


def _forces(raw, where, points, everywhere, pr):
    for i, (at, body) in enumerate(_rows(raw, where, pr, '[[loads.forces]] point = "E", magnitude = 100')):
        check_keys(
            body,
            {"name", "point", "link", "magnitude", "weight_of", "times", "direction", "angle_deg"},
            at,
            pr,
        )
        name = read_text(body.get("name"), f"{at}.name", pr, f"F{i + 1}")
        point = _point(body.get("point"), f"{at}.point", everywhere, pr, "the points of the moving links are")
        magnitude = weight_of = link = None
        times = 1.0
        carriers = sorted(lid for lid, names in points.items() if point in names)
        if "link" in body:
            raw_link = body["link"]
            link = _link_key(
                str(raw_link) if isinstance(raw_link, int) and not isinstance(raw_link, bool) else raw_link,
                f"{at}.link",
                points,
                pr,
            )
            if link is not None and point is not None and link not in carriers:
                pr.add(
                    f"{at}.link",
                    f"link {link} does not carry the point {point}: {name_list(map(str, carriers))} do",
                )
                link = None
        if "magnitude" in body and "weight_of" in body:
            pr.add(at, "give magnitude (N) or weight_of with times, not both")
        elif "weight_of" in body:
            weight_of = _link_key(
                str(body["weight_of"]) if isinstance(body["weight_of"], int) else body["weight_of"],
                f"{at}.weight_of",
                points,
                pr,
            )
            times = read_number(
                body.get("times"), f"{at}.times", pr, positive=True, default=1.0, unit="", high=MAX_LOAD
            )
        else:
            magnitude = read_number(body.get("magnitude"), f"{at}.magnitude", pr, unit="N", high=MAX_LOAD)
            if magnitude is not None and magnitude < 0:
                pr.add(
                    f"{at}.magnitude",
                    f"negative magnitude {magnitude:g}: give its size and turn it "
                    "with direction or angle_deg",
                )
                magnitude = None
        rule = angle = None
        if ("direction" in body) == ("angle_deg" in body):
            words = ", ".join(f'"{d}"' for d in DIRECTIONS)
            pr.add(at, f"give direction ({words}) or angle_deg (from +x, counter-clockwise), one of them")
        elif "direction" in body:
            rule = _keyword(body["direction"], f"{at}.direction", DIRECTIONS, pr)
        else:
            deg = read_number(body["angle_deg"], f"{at}.angle_deg", pr, unit="°", high=1e4)
            angle = None if deg is None else math.radians(deg)
        if (
            point is not None
            and (magnitude is not None or weight_of is not None)
            and times is not None
            and (rule is not None or angle is not None)
        ):
            yield PointForce(
                name,
                point,
                magnitude,
                link if link is not None else carriers[0],
                weight_of,
                times,
                rule,
                angle,
            )


def _moments(raw, where, points, pr):
    for i, (at, body) in enumerate(_rows(raw, where, pr, "[[loads.moments]] link = 3, moment = 12.5")):
        check_keys(body, {"name", "link", "moment", "magnitude", "direction"}, at, pr)
        name = read_text(body.get("name"), f"{at}.name", pr, f"M{i + 1}")
        link = body.get("link")
        lid = _link_key(
            str(link) if isinstance(link, int) and not isinstance(link, bool) else link,
            f"{at}.link",
            points,
            pr,
        )
        if ("moment" in body) == ("magnitude" in body):
            pr.add(
                at, "give moment (N·m, counter-clockwise positive) or magnitude with direction, one of them"
            )
            continue
        if "moment" in body:
            value = read_number(body["moment"], f"{at}.moment", pr, unit="N·m", high=MAX_LOAD)
            rule = None
            if "direction" in body:
                pr.add(
                    f"{at}.direction", "goes with magnitude: a signed moment is counter-clockwise positive"
                )
        else:
            value = read_number(body["magnitude"], f"{at}.magnitude", pr, unit="N·m", high=MAX_LOAD)
            if value is not None and value < 0:
                pr.add(
                    f"{at}.magnitude",
                    f"negative magnitude {value:g}: give its size and its sense with direction",
                )
                value = None
            rule = _keyword(body.get("direction"), f"{at}.direction", SENSES, pr)
        if lid is not None and value is not None and ("moment" in body or rule is not None):
            yield LinkMoment(name, lid, value, rule)


def read_resistance(raw: Any, where: str, pr: Problems) -> Resistance | None:
    """The P(S) graph: ``s`` (m) or ``fraction`` (of the stroke H), ``P`` (N), ``idle``."""
    example = "s = [0.0, 0.3, 0.5], P = [0, 2500, 2500]"
    if not isinstance(raw, dict):
        pr.add(where, f"must be a table ({example}), got {quote(raw)}")
        return None
    check_keys(raw, {"s", "fraction", "P", "idle", "name"}, where, pr)
    name = read_text(raw.get("name"), f"{where}.name", pr, "P")
    if ("s" in raw) == ("fraction" in raw):
        pr.add(
            where,
            "give s (m from the start of the working stroke) or fraction (of the stroke H), one of them",
        )
        return None
    key = "s" if "s" in raw else "fraction"
    xs = _numbers(raw.get(key), f"{where}.{key}", pr, "m" if key == "s" else "")
    ps = _numbers(raw.get("P"), f"{where}.P", pr, "N")
    idle = read_number(raw.get("idle"), f"{where}.idle", pr, default=0.0, unit="N", high=MAX_LOAD)
    if xs is None or ps is None or idle is None:
        return None
    ok = True
    if len(xs) != len(ps):
        pr.add(where, f"{key} has {len(xs)} values and P {len(ps)}: give one P for each {key}")
        ok = False
    if len(xs) < 2:
        pr.add(f"{where}.{key}", "at least two points make a graph")
        ok = False
    for i in range(1, len(xs)):
        if not xs[i] > xs[i - 1]:
            pr.add(f"{where}.{key}", f"must increase: {key}[{i}] = {xs[i]:g} after {xs[i - 1]:g}")
            ok = False
            break
    if xs and xs[0] < 0:
        pr.add(
            f"{where}.{key}",
            f"starts at {xs[0]:g}: s is measured from the start of the working stroke, from 0",
        )
        ok = False
    if key == "fraction" and xs and xs[-1] > 1:
        pr.add(f"{where}.fraction", f"ends at {xs[-1]:g}: a fraction of the stroke is at most 1")
        ok = False
    for i, p in enumerate(ps):
        if p < 0:
            pr.add(
                f"{where}.P",
                f"P[{i}] = {p:g} is negative: the resistance is its size, it always acts against the motion",
            )
            ok = False
            break
    if idle < 0:
        pr.add(f"{where}.idle", f"{idle:g} is negative: its size, acting against the motion")
        ok = False
    return Resistance(tuple(xs), tuple(ps), key == "fraction", idle, name) if ok else None


def _numbers(raw: Any, where: str, pr: Problems, unit: str) -> list[float] | None:
    if not isinstance(raw, list):
        pr.add(where, f"must be a list of numbers, got {quote(raw)}")
        return None
    if len(raw) > MAX_GRAPH:
        pr.add(where, f"{len(raw)} values: at most {MAX_GRAPH}")
        return None
    out = []
    for i, v in enumerate(raw):
        x = read_number(v, f"{where}[{i}]", pr, unit=unit, high=MAX_LOAD)
        if x is None:
            return None
        out.append(x)
    return out


def read_drive(raw: Any, pr: Problems, where: str = "drive") -> Drive:
    """The ``[drive]`` table: efficiency η (0 < η ≤ 1), digit Ш (0…9), catalogue."""
    if not isinstance(raw, dict):
        pr.add(where, f"must be a table ([drive] efficiency = 0.9), got {quote(raw)}")
        return Drive()
    check_keys(raw, {"efficiency", "digit", "catalogue", "synchronous", "power"}, where, pr)
    power = _keyword(raw["power"], f"{where}.power", ("position", "mean"), pr) if "power" in raw else None
    eta = read_number(
        raw.get("efficiency"), f"{where}.efficiency", pr, positive=True, default=0.9, unit="", high=1.0
    )
    digit = raw.get("digit", 0)
    if isinstance(digit, bool) or not isinstance(digit, int) or not 0 <= digit <= 9:
        pr.add(
            f"{where}.digit",
            f"must be one digit 0…9 (Ш, the last digit of the student's code), got {quote(digit)}",
        )
        digit = 0
    catalogue = read_text(raw.get("catalogue"), f"{where}.catalogue", pr, "4A")
    sync = raw.get("synchronous", 3000)
    if sync not in (3000, 1500, 1000, 750) or isinstance(sync, bool):
        pr.add(
            f"{where}.synchronous",
            f"must be the motors' synchronous speed in rpm: 3000, 1500, 1000 or 750, got {quote(sync)}",
        )
        sync = 3000
    return Drive(eta if eta is not None else 0.9, digit, catalogue, int(sync), power or "position")
