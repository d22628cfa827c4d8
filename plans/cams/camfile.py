"""The cam file (TOML): the phases and their laws (or an eccentric disc), the follower, the
cam's rotation and the limits; read with every problem located to its line.

Units: metres, seconds, degrees, as in a mechanism file. ::

    name = { en = "Disc cam with a roller follower", ru = "Кулачковый механизм" }
    [cam]
    sense = "ccw"              # the cam's rotation, the follower above it: "ccw" (default) or "cw"
    omega = 10                 # rad/s; or rpm = 95.5
    base_radius = 0.030        # r0, m: leave it out for the smallest the limits allow
    [follower]
    kind = "roller"            # "knife-edge", "roller" or "flat-faced"
    motion = "translating"     # or "oscillating"
    stroke = 0.016             # h, m; an oscillating follower: swing_deg = 20
    offset = 0.010             # e, m, + right of the cam centre; "best": chosen with r0
    roller_radius = 0.005      # r_r, m
    [limits]
    pressure_rise_deg = 30     # [α] on rise; pressure_return_deg = 70 on return
    [[phases]]
    kind = "rise"              # "rise", "dwell", "return"
    angle_deg = 120
    law = "cosine"             # see plans.cams.laws.LAWS; ratio = 1 (asymmetric: ≠ 1)

>>> cam = from_dict({"follower": {"kind": "knife-edge", "stroke": 0.016},
...                  "cam": {"omega": 1, "base_radius": 0.03},
...                  "phases": [{"kind": "rise", "angle_deg": 120, "law": "cosine"},
...                             {"kind": "dwell", "angle_deg": 60},
...                             {"kind": "return", "angle_deg": 120, "law": "cosine"},
...                             {"kind": "dwell", "angle_deg": 60}]}, "exam.toml")
>>> cam.follower.kind, round(math.degrees(cam.phases[2].start), 9), cam.phases[1].level, cam.limits.rise_deg
('knife-edge', 180.0, 0.016, 30.0)
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from plans.cams.laws import LAWS, law_named
from plans.cams.motion import TURN, Phase
from plans.model.fileformat import (
    MAX_TEXT,
    Problems,
    check_keys,
    close_match,
    file_kind,
    quote,
    read_number,
    read_text,
    read_toml,
)

__all__ = ["FOLLOWERS", "MOTIONS", "Cam", "Disc", "Follower", "Limits", "from_dict", "load"]

FOLLOWERS = ("knife-edge", "roller", "flat-faced")
MOTIONS = ("translating", "oscillating")
LANGS = ("en", "ru")
TOP_KEYS = {"name", "cam", "follower", "limits", "phases", "disc", "title"}
#: the senses of rotation as they may be spelt, and the word the file reads them as
SENSES = {"clockwise": "cw", "counter-clockwise": "ccw", "counterclockwise": "ccw",
          "anticlockwise": "ccw", "anti-clockwise": "ccw"}
MAX_PHASES = 50


@dataclass(frozen=True, slots=True)
class Follower:
    """The follower: ``kind`` (knife-edge, roller, flat-faced), ``motion`` (translating or
    oscillating), its stroke h (m) or swing (rad), the translating one's ``offset`` e (m,
    + right; None: the best, chosen with r0), the roller's radius, the oscillating one's
    ``arm`` l = AB and ``centre`` a = OA (m), and ``with_cam``: its arm turns on rise the
    way the cam turns."""

    kind: str
    motion: str = "translating"
    stroke: float = 0.0
    offset: float | None = 0.0
    roller: float = 0.0
    arm: float = 0.0
    centre: float = 0.0
    with_cam: bool = False

    @property
    def oscillating(self) -> bool:
        return self.motion == "oscillating"

    @property
    def flat(self) -> bool:
        return self.kind == "flat-faced"


@dataclass(frozen=True, slots=True)
class Limits:
    """The allowed pressure angles on rise and return (degrees) and the smallest radius of
    curvature of the profile (m; 0: any, short of a cusp)."""

    rise_deg: float = 30.0
    return_deg: float = 70.0
    min_radius: float = 0.0


@dataclass(frozen=True, slots=True)
class Disc:
    """An eccentric disc: its radius R and the distance OA of its centre from the shaft."""

    radius: float
    eccentricity: float


@dataclass(frozen=True)
class Cam:
    """A cam file, read: the cam turns ``sense`` (+1 counter-clockwise) at ``omega``
    (rad/s); ``base_radius`` r0 (m, None: the smallest the limits allow); the follower;
    the ``phases`` (or the ``disc``); the limits; the profile's table every ``step``
    (rad)."""

    name: str
    source: str
    sense: int
    omega: float
    base_radius: float | None
    follower: Follower
    phases: tuple[Phase, ...] = ()
    disc: Disc | None = None
    limits: Limits = Limits()
    step: float = math.radians(1.0)
    names: dict[str, str] = field(default_factory=dict)
    title: dict[str, str] = field(default_factory=dict)
    rpm: float | None = None

    def name_in(self, lang: str) -> str:
        return self.names.get(lang, self.name)


def load(path: str | Path) -> Cam:
    """Read and check a cam file; every problem is reported, located."""
    data, text = read_toml(path, "a cam file is a few KB")
    return from_dict(data, str(path), text=text)


#: the files of the other commands, by their kind: what they are and the command that reads them
_OTHERS = {
    "mechanism": "a mechanism file, not a cam file: solve it with plans solve {src}",
    "measurement": "a measurement file (mechanism = …, [segments]), not a cam file: check it with "
                   "plans check {src}",
    "table": "a variant table ([[variant]] rows), not a cam file: give it as --table {src} --variant N",
}


def from_dict(data: dict, source: str, text: str | None = None) -> Cam:
    """A :class:`Cam` from a parsed file, or :class:`~plans.errors.InputError` with one
    located line per problem."""
    pr = Problems(source, text)
    kind = file_kind(data) if not (TOP_KEYS & data.keys()) - {"name", "title"} else None
    if kind is not None:
        pr.add("", _OTHERS[kind].format(src=source))
        pr.raise_if_any()
    check_keys(data, TOP_KEYS, "", pr)
    name, names = _names(data.get("name"), pr, Path(source).stem[:MAX_TEXT] or "cam")
    cam_t = _table(data, "cam", pr)
    fol_t = _table(data, "follower", pr, required=True)
    lim_t = _table(data, "limits", pr)
    disc_t = _table(data, "disc", pr) if "disc" in data else None

    # the cam ------------------------------------------------------------------------
    check_keys(cam_t, {"sense", "omega", "rpm", "base_radius", "step_deg"}, "cam", pr)
    sense = cam_t.get("sense", "ccw")
    sense = SENSES.get(sense.strip().lower(), sense) if isinstance(sense, str) else sense
    sense = _choice(sense, "cam.sense", ("ccw", "cw"), pr, "ccw")
    omega, rpm = _speed(cam_t, pr)
    base = cam_t.get("base_radius")
    base = None if base is None else read_number(base, "cam.base_radius", pr, positive=True, low=1e-6)
    step = read_number(cam_t.get("step_deg"), "cam.step_deg", pr, positive=True, default=1.0, unit="°",
                       high=90.0)
    if step is not None and 360.0 / step > 100_000:
        pr.add("cam.step_deg", f"{step:g}° gives more than 100 000 points a turn: at least 0.0036°")
        step = None

    # the follower -------------------------------------------------------------------
    follower = _follower(fol_t, disc_t is not None, pr)

    # the limits ---------------------------------------------------------------------
    check_keys(lim_t, {"pressure_rise_deg", "pressure_return_deg", "min_radius"}, "limits", pr)
    rise_default = 45.0 if follower is not None and follower.oscillating else 30.0
    a_rise = _angle_limit(lim_t.get("pressure_rise_deg"), "limits.pressure_rise_deg", rise_default, pr)
    a_ret = _angle_limit(lim_t.get("pressure_return_deg"), "limits.pressure_return_deg", 70.0, pr)
    rho = read_number(lim_t.get("min_radius"), "limits.min_radius", pr, default=0.0)
    if rho is not None and rho < 0:
        pr.add("limits.min_radius", f"must not be negative, got {rho:g}")
        rho = None

    # the phases or the disc ---------------------------------------------------------
    phases: tuple[Phase, ...] = ()
    disc = None
    if disc_t is not None:
        if "phases" in data:
            pr.add("disc", "a cam is given by its [[phases]] or as a [disc], not both")
        disc = _disc(disc_t, follower, base, pr)
    else:
        phases = _phases(data.get("phases"), follower, pr)

    title = data.get("title", {})
    if not isinstance(title, dict) or len(title) > 50:
        pr.add("title", f"must be a table of texts for the title block, got {quote(title)}")
        title = {}
    title = {str(k): read_text(v, f"title.{k}", pr, "") for k, v in title.items()}
    pr.raise_if_any()
    cam = Cam(name, source, 1 if sense == "ccw" else -1, omega, base, follower, phases, disc,
              Limits(a_rise, a_ret, rho), math.radians(step), names, title, rpm)
    _geometry(cam, pr)
    pr.raise_if_any()
    return cam


def _names(value, pr: Problems, default: str) -> tuple[str, dict[str, str]]:
    """``name = "…"`` or ``name = { en = "…", ru = "…" }``."""
    if not isinstance(value, dict):
        return read_text(value, "name", pr, default), {}
    check_keys(value, set(LANGS), "name", pr)
    names = {lang: read_text(value[lang], f"name.{lang}", pr, default) for lang in LANGS if lang in value}
    if not names and not any(k not in LANGS for k in value):
        pr.add("name", 'an empty table: give a text, or { en = "…", ru = "…" }')
    return names.get("en") or next(iter(names.values()), default), names


def _table(data: dict, key: str, pr: Problems, required: bool = False) -> dict:
    value = data.get(key)
    if value is None:
        if required:
            pr.add(key, f"missing: the [{key}] table is needed")
        return {}
    if not isinstance(value, dict):
        pr.add(key, f"must be a table ([{key}]), got {quote(value)}")
        return {}
    return value


def _choice(value: Any, where: str, choices, pr: Problems, default: str) -> str:
    if isinstance(value, str) and value.strip().lower() in choices:
        return value.strip().lower()
    guess = close_match(value, choices) if isinstance(value, str) else ""
    pr.add(where, f"{quote(value)} is not one of {', '.join(choices)}"
           + (f" — {guess.strip()}" if guess else ""))
    return default


def _speed(table: dict, pr: Problems) -> tuple[float, float | None]:
    for key in ("omega", "rpm"):
        value = table.get(key)
        if isinstance(value, int | float) and not isinstance(value, bool) and value < 0:
            pr.add(f"cam.{key}", f"must be positive, got {value:g} (the sense of rotation is sense = "
                                 '"cw" or "ccw")')
            return 1.0, None
    if "omega" in table and "rpm" in table:
        pr.add("cam.rpm", "give omega (rad/s) or rpm, not both")
        return 1.0, None
    if "rpm" in table:
        rpm = read_number(table["rpm"], "cam.rpm", pr, positive=True, unit="rpm", high=1e6)
        return (1.0, None) if rpm is None else (rpm * math.pi / 30.0, rpm)
    omega = read_number(table.get("omega"), "cam.omega", pr, positive=True, default=1.0, unit="rad/s",
                        high=1e5)
    return (omega or 1.0), None


def _angle_limit(value, where: str, default: float, pr: Problems) -> float:
    x = read_number(value, where, pr, default=default, unit="°")
    if x is None:
        return default
    if not 0.0 < x < 90.0:
        pr.add(where, f"{x:g}° is not a pressure angle: give one between 0° and 90°")
        return default
    return x


_FOLLOWER_KEYS = {"kind", "motion", "stroke", "swing_deg", "offset", "roller_radius", "arm",
                  "centre_distance", "rise"}


def _follower(t: dict, disc: bool, pr: Problems) -> Follower | None:
    check_keys(t, _FOLLOWER_KEYS, "follower", pr)
    if "kind" not in t:
        if t:  # (no [follower] at all is said once, as a missing table)
            pr.add("follower.kind", f"missing: {', '.join(FOLLOWERS)}")
        return None
    kind = _choice(t["kind"], "follower.kind", FOLLOWERS, pr, "knife-edge")
    motion = _choice(t.get("motion", "translating"), "follower.motion", MOTIONS, pr, "translating")
    oscillating = motion == "oscillating"
    roller = 0.0
    if kind == "roller":
        roller = read_number(t.get("roller_radius"), "follower.roller_radius", pr, positive=True,
                             low=1e-6) or 0.0
    elif "roller_radius" in t:
        pr.add("follower.roller_radius", f"a {kind} follower has no roller: leave it out, or make it kind = "
                                         '"roller"')
    stroke = 0.0
    if disc:
        for key in ("stroke", "swing_deg"):
            if key in t:
                pr.add(f"follower.{key}", "the disc's eccentricity makes the stroke: leave it out")
    elif oscillating:
        if "stroke" in t:
            pr.add("follower.stroke", "an oscillating follower swings: give swing_deg, its angle")
        sw = read_number(t.get("swing_deg"), "follower.swing_deg", pr, positive=True, unit="°", high=179.0)
        stroke = math.radians(sw) if sw else 0.0
    else:
        if "swing_deg" in t:
            pr.add("follower.swing_deg", "a translating follower has a stroke (m), not a swing: give stroke")
        stroke = read_number(t.get("stroke"), "follower.stroke", pr, positive=True, low=1e-6) or 0.0
    offset: float | None = 0.0
    arm = centre = 0.0
    with_cam = False
    if oscillating:
        for key in ("offset",):
            if key in t:
                pr.add(f"follower.{key}", "an oscillating follower has no offset: its pivot is at "
                                          "centre_distance from the cam's")
        arm = read_number(t.get("arm"), "follower.arm", pr, positive=True, low=1e-6) or 0.0
        centre = read_number(t.get("centre_distance"), "follower.centre_distance", pr, positive=True,
                             low=1e-6) or 0.0
        with_cam = _choice(t.get("rise", "against"), "follower.rise", ("against", "with"), pr,
                           "against") == "with"
    else:
        for key in ("arm", "centre_distance", "rise"):
            if key in t:
                pr.add(f"follower.{key}", "only an oscillating follower has it (motion = \"oscillating\")")
        value = t.get("offset", 0.0)
        if isinstance(value, str) and value.strip().lower() == "best":
            offset = None
            if disc:
                pr.add("follower.offset", 'a disc is given as it is: give its follower\'s offset, not "best"')
        else:
            offset = read_number(value, "follower.offset", pr)
            offset = 0.0 if offset is None else offset
    return Follower(kind, motion, stroke, offset, roller, arm, centre, with_cam)


def _disc(t: dict, follower: Follower | None, base, pr: Problems) -> Disc | None:
    check_keys(t, {"radius", "eccentricity"}, "disc", pr)
    r = read_number(t.get("radius"), "disc.radius", pr, positive=True, low=1e-6)
    c = read_number(t.get("eccentricity"), "disc.eccentricity", pr, positive=True, low=1e-9)
    if base is not None:
        pr.add("cam.base_radius", "a disc's base circle follows from the disc: leave base_radius out")
    if follower is not None and follower.oscillating:
        pr.add("follower.motion", "a disc cam drives a translating follower here: an oscillating "
                                  "follower needs [[phases]]")
    if r is None or c is None:
        return None
    if c >= r:
        pr.add("disc.eccentricity", f"{c:g} m is not less than the radius {r:g} m: the shaft would lie "
                                    "outside the disc")
        return None
    return Disc(r, c)


_PHASE_KEYS = {"kind", "angle_deg", "law", "ratio"}


def _phases(items, follower: Follower | None, pr: Problems) -> tuple[Phase, ...]:
    if items is None:
        pr.add("phases", "missing: the [[phases]] of the cycle (rise, dwell, return, dwell), or a [disc]")
        return ()
    if not isinstance(items, list) or not all(isinstance(p, dict) for p in items):
        pr.add("phases", f"must be [[phases]] tables, got {quote(items)}")
        return ()
    if len(items) > MAX_PHASES:
        pr.add("phases", f"{len(items)} phases: at most {MAX_PHASES}")
        return ()
    out: list[Phase] = []
    start = 0.0
    total = 0.0
    ok = True
    stroke = follower.stroke if follower is not None else 0.0
    for n, body in enumerate(items):
        where = f"phases[{n}]"
        check_keys(body, _PHASE_KEYS, where, pr)
        kind = _choice(body.get("kind"), f"{where}.kind", ("rise", "dwell", "return"), pr, "dwell") \
            if "kind" in body else None
        if kind is None:
            pr.add(f"{where}.kind", "missing: rise, dwell or return")
            ok = False
        angle = read_number(body.get("angle_deg"), f"{where}.angle_deg", pr, positive=True, unit="°",
                            high=360.0)
        if angle is None:
            ok = False
            angle = 0.0
        total += angle
        law = None
        ratio = 1.0
        if kind in ("rise", "return"):
            name = body.get("law")
            if name is None:
                pr.add(f"{where}.law", f"missing: the law of the {kind} — {', '.join(LAWS)}")
                ok = False
            else:
                law = law_named(name) if isinstance(name, str) else None
                if law is None:
                    guess = close_match(name, LAWS, cutoff=0.5) if isinstance(name, str) else ""
                    pr.add(f"{where}.law", f"unknown law {quote(name)} — {guess}known: {', '.join(LAWS)}")
                    ok = False
            if "ratio" in body:
                ratio = read_number(body["ratio"], f"{where}.ratio", pr, positive=True, unit="", high=100.0)
                if ratio is not None and not 0.01 <= ratio <= 100:
                    pr.add(f"{where}.ratio", f"{ratio:g} is out of range: from 0.01 to 100")
                    ratio = None
                if ratio is None:
                    ok, ratio = False, 1.0
                elif law is not None and law.key == "constant velocity" and ratio != 1.0:
                    pr.add(f"{where}.ratio", "the constant-velocity law has no acceleration part to "
                                             "share out: leave ratio out")
        elif kind == "dwell":
            for key in ("law", "ratio"):
                if key in body:
                    pr.add(f"{where}.{key}", "a dwell holds the follower still: it has no law")
        out.append(Phase(kind or "dwell", math.radians(start), math.radians(angle), law, ratio))
        start += angle
    if not ok or not out:
        if not out:
            pr.add("phases", "no phases: give the rise, dwells and return")
        return ()
    if abs(total - 360.0) > 1e-9:
        pr.add("phases", f"the phases' angles add up to {total:.10g}°, not 360°")
        return ()
    moving = [p.kind for p in out if p.kind != "dwell"]
    if "rise" not in moving or "return" not in moving:
        pr.add("phases", "the cycle needs a rise and a return")
        return ()
    if any(a == b for a, b in zip(moving, moving[1:] + moving[:1], strict=True)):
        n = next(i for i, (a, b) in enumerate(zip(moving, moving[1:] + moving[:1], strict=True)) if a == b)
        pr.add("phases", f"two {moving[n]}s follow each other (with only dwells between): a rise and a "
                         "return take turns")
        return ()
    # the levels: a dwell after a rise is the outer one (s = h), after a return the inner one
    level = 0.0 if moving[0] == "rise" else stroke
    phases = []
    for p in out:
        phases.append(Phase(p.kind, p.start, p.angle, p.law, p.ratio, level if p.kind == "dwell" else 0.0))
        level = stroke if p.kind == "rise" else 0.0 if p.kind == "return" else level
    # the end of the last phase is the start of the first: a whole turn
    last = phases[-1]
    phases[-1] = Phase(last.kind, last.start, TURN - last.start, last.law, last.ratio, last.level)
    return tuple(phases)


def _geometry(cam: Cam, pr: Problems) -> None:
    """Problems of the geometry as a whole: a base circle the offset does not fit in, an
    arm that cannot reach it, a disc the follower's axis misses."""
    f = cam.follower
    r0 = cam.base_radius
    if cam.disc is not None:
        rp = cam.disc.radius + f.roller
        if f.flat:
            return
        if abs(f.offset) + cam.disc.eccentricity >= rp:
            c = cam.disc.eccentricity
            pr.add("follower.offset", f"the follower's axis at {f.offset:g} m misses the disc's pitch circle "
                                      f"(radius {rp:g} m about a centre {c:g} m from the shaft) in some "
                                      f"positions: |e| must be under {rp - c:g} m")
        return
    if r0 is None:
        if f.flat and cam.limits.min_radius <= 0:
            pr.add("cam.base_radius", "missing: a flat-faced follower's base radius is set by the profile's "
                                      "curvature; give base_radius, or limits.min_radius (the smallest "
                                      "radius of curvature allowed) to choose the smallest")
        return
    if not f.oscillating:
        if f.offset is not None and not f.flat and abs(f.offset) >= r0:
            pr.add("cam.base_radius", f"{r0:g} m is not more than the offset |e| = {abs(f.offset):g} m: the "
                                      "follower's axis must cut the base circle")
        return
    a, ell = f.centre, f.arm
    if not abs(a - ell) < r0 < a + ell and not f.flat:
        pr.add("cam.base_radius", f"{r0:g} m: an arm of {ell:g} m pivoted {a:g} m from the cam's centre "
                                  f"reaches the base circle only for r0 between {abs(a - ell):g} and "
                                  f"{a + ell:g} m")
    elif f.flat and not r0 < a:
        pr.add("cam.base_radius", f"{r0:g} m: the face through the pivot {a:g} m away touches a base circle "
                                  "smaller than that")
    else:
        psi0 = (math.asin(r0 / a) if f.flat
                else math.acos((a * a + ell * ell - r0 * r0) / (2.0 * a * ell)))
        if psi0 + f.stroke >= math.pi:
            pr.add("follower.swing_deg", f"{math.degrees(f.stroke):g}° from the arm's start at "
                                         f"{math.degrees(psi0):.4g}° to the line OA passes 180°")
