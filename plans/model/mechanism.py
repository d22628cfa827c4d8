"""The declarative description of a mechanism, and its TOML file format.

A mechanism is the frame (link 0) with its fixed pivots, numbered moving links, each with
its named points in the link's own coordinates, the prismatic pairs (sliders and the
guides they move along), and the driver (the crank). Revolute pairs are implied: a point
named on two links (or on a link and the frame) is a hinge joining them.

A link's own coordinates: the origin at ``axis[0]`` and the x-axis towards ``axis[1]``; a
point is given by its distance along that axis, or ``[along, across]`` (across positive to
the left of the axis). A link without an axis slides on a guide: its origin is its point
on the guide and its x-axis runs along the guide. A link with an axis that slides on a
guide has its axis along the guide too (a Scotch yoke's).

Lengths are metres, angles degrees in the file and radians inside, time seconds.
"""

from __future__ import annotations

import itertools
import math
import re
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any

from plans import tolerances
from plans.errors import InputError
from plans.geometry import cross
from plans.model.fileformat import (
    MAX_ABS,
    MAX_TEXT,
    Problems,
    check_keys,
    close_match,
    key_text,
    name_list,
    one_line,
    other_kind,
    quote,
    read_number,
    read_text,
    read_toml,
)

#: names the plans reserve for their own construction points (n1, k, p, π)
RESERVED = re.compile(r"^(P|N\d*|K\d*)$")
#: the unit of each scale factor, as an error message asks for it
MU_UNIT = {"mu_l": "m/mm", "mu_v": "(m/s)/mm", "mu_a": "(m/s²)/mm"}
POINT_NAME = re.compile(r"^[A-Z][A-Za-z0-9_']{0,11}$")
MIN_LEN = 1e-9


@dataclass(frozen=True, slots=True)
class Guide:
    """A straight guide carried by a link: a line through ``point`` along ``direction``.

    Both are in the carrying link's own coordinates (world coordinates for the frame).
    """

    link: int
    point: complex
    direction: complex  # unit
    label: str
    named_by_tool: bool = False  # the file gave no label: x-x, DA, x3-x3 … by notation

    @property
    def along(self) -> str:
        """The guide's direction as a plan's line is described: "∥ x-x", "∥ DE", or
        "⊥ DE" for a slot across the axis of the link that carries it."""
        return self.label if self.label.startswith("⊥") else f"∥ {self.label}"


@dataclass(frozen=True, slots=True)
class Link:
    id: int
    name: str
    points: dict[str, complex]  # own coordinates of every point of the link
    axis: tuple[str, str] | None = None


@dataclass(frozen=True, slots=True)
class Slider:
    """A prismatic pair: ``link`` moves along ``guide``; ``point`` of it lies on the guide."""

    link: int
    guide: Guide
    point: str


@dataclass(frozen=True, slots=True)
class Driver:
    """The crank: link ``link`` turning about the fixed ``pivot``; ``tip`` is its pin."""

    link: int
    pivot: str
    tip: str
    length: float
    phi: float  # rad, counter-clockwise from +x
    omega: float  # rad/s, signed: positive counter-clockwise
    angle_deg: float  # as given in the file
    reference: str  # "+x", "+y", ...
    measured: str  # "ccw" or "cw"
    rpm: float | None = None

    @property
    def phi_sym(self) -> str:
        """"φ1": the crank's angle named by its link's number, as its ω is ("ω1", the
        course's numbering; "φ3" for a crank numbered 3, whose text then never calls
        another link's ω "ω1" beside it)."""
        return f"φ{self.link}"

    @property
    def omega_sym(self) -> str:
        """"ω1": the crank's angular velocity, named by its link's number."""
        return f"ω{self.link}"

    def phi_of(self, angle_deg: float) -> float:
        """The crank angle (rad, counter-clockwise from +x) of an angle given in the
        file's convention (degrees from ``reference``, ``measured`` ccw or cw)."""
        return phi_of(angle_deg, self.reference, self.measured)

    def file_angle(self, phi: float) -> float:
        """The inverse: the crank angle ``phi`` in the file's convention, in [0, 360)."""
        return (SENSES[self.measured] * (math.degrees(phi) - REFERENCES[self.reference])) % 360.0

    def at(self, phi: float, lang: str = "en", lo: float = 0.0) -> str:
        """"φ1 = 330°" for a message about crank angle ``phi``, in the file's convention as
        ``--angle`` takes it, which it names unless it is the usual one (from +x, ccw);
        ``lo``, the turn it is written in (:func:`plans.fmt.angle`: "−99.7°" beside a crank
        range through 0°).

        >>> d = Driver(1, "O", "A", 0.1, math.radians(-240), 1.0, 330.0, "+y", "cw")
        >>> d.at(math.radians(-240)), d.at(math.radians(-240.5), "ru")
        ('φ1 = 330° (from +y, cw)', 'φ1 = 330,5° (от +y, по часовой стрелке)')
        """
        from plans.fmt import angle

        return f"{self.phi_sym} = {angle(self.file_angle(phi), 6, lang, lo)}°{self.convention(lang)}"

    def both(self, phi: float, lang: str = "en", lo: float = 0.0) -> str:
        """"60° from +x (30° from +y, cw, as the file gives it)": the crank angle ``phi``
        from +x, and in the file's own convention where that is another one, to six
        digits (the angle as the user typed it: 270.01° had printed as 270°). ``lo``:
        the turn the file's angles are written in (:meth:`plans.kinematics.Solver.shown_from`,
        "−99.7°" beside a crank range through 0°); the angle from +x takes it too where it
        is the file's own.

        >>> d = Driver(1, "O", "A", 0.1, math.radians(60), 1.0, 30.0, "+y", "cw")
        >>> d.both(math.radians(60)), d.both(math.radians(60), "ru")
        ('60° from +x (30° from +y, cw, as the file gives it)', '60° от +x (30° от +y, по часовой стрелке, как задано в файле)')
        >>> replace(d, reference="+x", measured="ccw").both(math.radians(60))
        '60° from +x'
        """
        from plans.fmt import angle

        ru = lang == "ru"
        conv = self.convention(lang)[2:-1]  # "from +y, cw" without its brackets
        own = (f" ({angle(self.file_angle(phi), 6, lang, lo)}° {conv}, "
               f"{'как задано в файле' if ru else 'as the file gives it'})") if conv else ""
        at = angle(math.degrees(phi), 6, lang, 0.0 if conv else lo)
        return f"{at}° {'от' if ru else 'from'} +x{own}"

    def convention(self, lang: str = "en") -> str:
        """" (from +y, cw)" after an angle in the file's convention; nothing for the usual
        one (from +x, counter-clockwise)."""
        if (self.reference, self.measured) == ("+x", "ccw"):
            return ""
        from plans.fmt import SENSE

        sense = self.measured if lang == "en" else SENSE["ru"][int(SENSES[self.measured])]
        return f" ({'from' if lang == 'en' else 'от'} {self.reference}, {sense})"



def phi_of(angle_deg: float, reference: str, measured: str) -> float:
    """A crank angle in a file's convention (degrees from ``reference``, ``measured`` ccw
    or cw) as the engine's: radians counter-clockwise from +x."""
    return math.radians(REFERENCES[reference] + SENSES[measured] * angle_deg)


@dataclass(frozen=True)
class Mechanism:
    name: str
    frame: dict[str, complex]
    links: dict[int, Link]
    sliders: tuple[Slider, ...]
    driver: Driver
    assembly: dict[str, str] = field(default_factory=dict)
    scales: dict[str, float] = field(default_factory=dict)
    trace: tuple[str, ...] = ()
    output: str | None = None
    title: dict[str, str] = field(default_factory=dict)
    source: str = "<mechanism>"
    #: the name in other languages ("ru": …), from ``name = { en = "…", ru = "…" }``
    names: dict[str, str] = field(default_factory=dict)
    #: ``source`` in other languages, where it has words ("ru": "таблица 2 (встроенная),
    #: вариант 3" for a row of the built-in table); a file's path has none
    sources: dict[str, str] = field(default_factory=dict)
    #: the crank angle (rad from +x) the assembly hints are read at: the file's own, kept
    #: by :meth:`at_file_angle`; None: the driver's
    hints_at: float | None = None

    def name_in(self, lang: str) -> str:
        """The name for a note or sheet in ``lang``: the file's name in that language if
        it gives one, else its name."""
        return self.names.get(lang, self.name)

    def source_in(self, lang: str) -> str:
        """Where the mechanism comes from, for a report in ``lang``: "Table 2 (built in),
        variant 3" is «таблица 2 (встроенная), вариант 3»; a file's path as it is."""
        return self.sources.get(lang, self.source)

    # ---- derived, read-only views -------------------------------------------------
    def links_of(self, point: str) -> list[int]:
        """Links (0 = frame) that carry ``point``."""
        found = [0] if point in self.frame else []
        found += [lid for lid, link in sorted(self.links.items()) if point in link.points]
        return found

    def point_names(self) -> list[str]:
        names = list(self.frame)
        for link in self.links.values():
            names += [p for p in link.points if p not in names]
        return names

    def revolutes(self) -> list[tuple[str, int, int]]:
        """Revolute pairs (point, link, link); a point on k links is k − 1 pairs."""
        pairs = []
        for name in self.point_names():
            carriers = self.links_of(name)
            pairs += [(name, carriers[0], other) for other in carriers[1:]]
        return pairs

    def translating(self) -> frozenset[int]:
        """The links that never turn: the frame, and every link joined to one of them by
        a prismatic pair (a slider on a fixed guide, a block in a translating yoke). A
        guide on such a link carries no Coriolis term."""
        out = {0}
        grew = True
        while grew:
            grew = False
            for s in self.sliders:
                pair = {s.link, s.guide.link}
                if pair & out and not pair <= out:
                    out |= pair
                    grew = True
        return frozenset(out)

    def slider_of(self, link: int) -> Slider | None:
        for s in self.sliders:
            if s.link == link:
                return s
        return None

    def at_file_angle(self, angle_deg: float) -> Mechanism:
        """The same mechanism with the crank at ``angle_deg`` in the file's convention
        (as ``--angle`` and a measurement file's ``angle_deg`` give it), assembled as the
        file's hints ask at the file's own angle: the crank turned there, on the same
        branch, as the cycle and the sheet draw it."""
        d = self.driver
        return replace(self, driver=replace(d, phi=d.phi_of(angle_deg), angle_deg=angle_deg),
                       hints_at=d.phi if self.hints_at is None else self.hints_at)

    def with_phi(self, phi: float) -> Mechanism:
        """The same mechanism with the crank at ``phi`` (rad, from +x)."""
        return replace(self, driver=replace(self.driver, phi=phi))


# ---------------------------------------------------------------------------------------
# loading and validation
# ---------------------------------------------------------------------------------------
#
# Every problem is collected and located (``plans/model/fileformat.py``).

REFERENCES = {"+x": 0.0, "+y": 90.0, "-x": 180.0, "-y": 270.0}
SENSES = {"ccw": 1.0, "cw": -1.0}

MAX_LINKS = 200
MAX_FRAME = 200  # fixed points
MAX_LINK_POINTS = 200  # points on one link
MAX_POINTS = 1000  # points in all
MAX_ITEMS = 200  # sliders, trace, assembly hints, title fields
MIN_LINK = 1e-6  # m: the shortest link (a micrometre)
SPEED = (1e-6, MAX_ABS)  # rad/s, rpm
#: the slowest crank in rpm: the slowest in rad/s (1e-6 rpm had passed as 1e-7 rad/s)
RPM_MIN = SPEED[0] * 30.0 / math.pi
SCALE = (1e-9, MAX_ABS)  # μl m/mm, μv (m/s)/mm, μa (m/s²)/mm
SAME = tolerances.SAME  # m: two points of one link closer than this are the same place


def load(path: str | Path) -> Mechanism:
    """Read and validate a mechanism file; every problem is reported, located."""
    data, text = read_toml(path, "a mechanism file is a few KB")
    return from_dict(data, str(path), text=text)


def _unknown_point(name: str, known, why: str = "") -> str:
    guess = close_match(name, known, cutoff=0.5)
    why = f": {why}" if why else ""
    return f"unknown point {quote(name)}{why} — {guess}known points: {name_list(known)}"


def _pair(value: Any, where: str, problems: Problems) -> complex | None:
    if not (isinstance(value, list) and len(value) == 2):
        problems.add(where, f"must be [x, y] in metres, got {quote(value)}")
        return None
    x = read_number(value[0], where + "[0]", problems)
    y = read_number(value[1], where + "[1]", problems)
    return None if x is None or y is None else complex(x, y)


def _name(value: Any, where: str, problems: Problems, named: set[str]) -> str | None:
    """The point name ``value``, or None with the problem. A reserved name is still
    recorded in ``named``: it is said once, not again where the file uses it (trace,
    output, a hint) as an unknown point."""
    if not isinstance(value, str) or not POINT_NAME.match(value):
        problems.add(
            where,
            f"{quote(value)} is not a point name: a capital letter, then up to 11 "
            "letters, digits, _ or ' (e.g. C, S3, A')",
        )
        return None
    if RESERVED.match(value):
        named.add(value)
        problems.add(
            where, f'"{value}" is reserved for plan construction points (p, n1, k…): rename it'
        )
        return None
    return value


def _one_spelling(nm: str, where: str, spellings: dict[str, str], pr: Problems) -> bool:
    """False (with the problem) for a name that differs from another only in case: the
    plans write points in lower case (C → c), so EF and Ef would be one plan point."""
    other = spellings.setdefault(nm.lower(), nm)
    if other == nm:
        return True
    pr.add(where, f'"{nm}" and "{other}" differ only in case, and the plans write both as '
                  f'"{nm.lower()}": rename one')
    return False


def _ids(links) -> str:
    return ", ".join(str(i) for i in sorted(links)) or "none"


def _fmt(z: complex) -> str:
    return f"[{z.real:g}, {z.imag:g}]"


def _link_id(value: Any) -> int | None:
    return value if isinstance(value, int) and not isinstance(value, bool) else None


def _not_a_link(value: Any, what: str, known: str) -> str:
    """The message for a link number that is not one (and for "3", which is not 3)."""
    if isinstance(value, str) and value.strip().isdigit() and len(value) < 10:
        return f"{quote(value, 20)} is text: write the number without quotes, {value.strip()} ({known})"
    if isinstance(value, float) and value.is_integer() and abs(value) < 1e9:
        return f"{value!r} is written as a decimal: a link's number is written {int(value)} ({known})"
    return f"{quote(value, 20)} is not {what} ({known})"


def from_dict(data: dict, source: str = "<mechanism>", *, text: str | None = None) -> Mechanism:
    """Build a :class:`Mechanism` from parsed TOML, reporting every problem at once.

    ``text``: the file's text, to locate each problem to its line.
    """
    pr = Problems(source, text)
    if not isinstance(data, dict):
        raise InputError(source, "the file must be a TOML table")
    if why := other_kind(data, source, "mechanism"):
        raise InputError(source, why)
    check_keys(
        data,
        {"name", "frame", "links", "sliders", "driver", "assembly", "scales", "trace",
         "output", "title"},
        "", pr,
    )
    name, names = _title_names(data.get("name"), pr, Path(source).stem[:MAX_TEXT] or "mechanism")

    # frame -------------------------------------------------------------------------
    frame: dict[str, complex] = {}
    named: set[str] = set()  # every point name the file uses, valid coordinates or not
    spellings: dict[str, str] = {}  # plan name (lower case) → the point name that has it
    frame_names: set[str] = set()
    raw_frame = data.get("frame")
    if not isinstance(raw_frame, dict) or not raw_frame:
        what = "missing" if raw_frame is None else f"must be a table of fixed points, got {quote(raw_frame)}"
        pr.add("frame", f"{what}: the fixed pivots, e.g. [frame] O = [0.0, 0.0]")
        raw_frame = {}
    if len(raw_frame) > MAX_FRAME:
        pr.add("frame", f"{len(raw_frame)} fixed points: at most {MAX_FRAME}")
        raw_frame = {}
    for key, value in raw_frame.items():
        where = f"frame.{key_text(key)}"
        nm = _name(key, where, pr, named)
        if nm and _one_spelling(nm, where, spellings, pr):
            named.add(nm)
            frame_names.add(nm)
        xy = _pair(value, where, pr)
        if nm and xy is not None:
            frame[nm] = xy
    _coincident(frame, set(frame), "frame", "fixed points", pr)

    # links -------------------------------------------------------------------------
    links: dict[int, Link] = {}
    bad_links: set[int] = set()  # links with a problem of their own: no follow-up messages
    raw_links = data.get("links")
    if not isinstance(raw_links, dict) or not raw_links:
        what = "missing" if raw_links is None else f"must be a table of numbered links, got {quote(raw_links)}"
        pr.add("links", f'{what}: the moving links, e.g. [links.1] axis = ["O", "A"]')
        raw_links = {}
    if len(raw_links) > MAX_LINKS:
        pr.add("links", f"{len(raw_links)} links: at most {MAX_LINKS} are supported")
        raw_links = {}
    total_points = 0
    for key, body in raw_links.items():
        where = f"links.{key_text(key)}"
        if not (isinstance(key, str) and 0 < len(key) <= 3 and key.isascii() and key.isdigit()
                and key == str(int(key)) and int(key) > 0):
            if key == "0":
                pr.add(where, "link 0 is the frame: give fixed points in [frame]")
            else:
                pr.add(where, "links are numbered 1, 2, 3… up to 999, without leading zeros (0 is the frame)")
            continue
        lid = int(key)
        if not isinstance(body, dict):
            pr.add(where, f'must be a table with axis and points, e.g. [links.{lid}] axis = ["B", "C"], got {quote(body)}')
            bad_links.add(lid)
            continue
        check_keys(body, {"name", "axis", "points"}, where, pr)
        lname = read_text(body.get("name"), where + ".name", pr, f"link {lid}")
        link, ok = _link(lid, lname, body, where, pr, named, spellings)
        total_points += len(link.points)
        if not ok:
            bad_links.add(lid)
        links[lid] = link
    if total_points > MAX_POINTS:
        pr.add("links", f"{total_points} points in all: at most {MAX_POINTS}")

    # sliders -----------------------------------------------------------------------
    sliders: list[Slider] = []
    raw_sliders = data.get("sliders", [])
    if not isinstance(raw_sliders, list):
        pr.add("sliders", f"must be an array of tables, [[sliders]] link = … guide = {{…}}, got {quote(raw_sliders)}")
        raw_sliders = []
    if len(raw_sliders) > MAX_ITEMS:
        pr.add("sliders", f"{len(raw_sliders)} sliders: at most {MAX_ITEMS}")
        raw_sliders = []
    sliding: dict[int, int] = {}  # link → index of its [[sliders]] entry
    pairs: list[tuple[int, int | None]] = []  # (link, guide's link) of every entry, valid or not
    for i, body in enumerate(raw_sliders):
        where = f"sliders[{i}]"
        if not isinstance(body, dict):
            pr.add(where, f"must be a table with link and guide, got {quote(body)}")
            continue
        check_keys(body, {"link", "point", "guide"}, where, pr)
        raw_lid = body.get("link")
        lid = _link_id(raw_lid)
        if lid is None or lid not in links:
            if lid not in bad_links:
                if raw_lid is None:
                    pr.add(where + ".link", f"missing: the number of the sliding link (moving links: {_ids(links)})")
                else:
                    pr.add(where + ".link", _not_a_link(raw_lid, "a moving link", f"moving links: {_ids(links)}"))
            continue
        if lid in sliding:
            pr.add(
                where + ".link",
                f"link {lid} already slides on a guide (sliders[{sliding[lid]}]): a link slides "
                "on one guide; the link that carries a guide is named in guide.link",
            )
            continue
        sliding[lid] = i
        raw_guide = body.get("guide")
        pairs.append((lid, _link_id(raw_guide.get("link", 0)) if isinstance(raw_guide, dict) else None))
        link = links[lid]
        point = body.get("point")
        if point is None:
            point = next(iter(link.points), None)
        elif not isinstance(point, str) or point not in link.points:
            if lid not in bad_links:
                pr.add(
                    where + ".point",
                    f"{quote(point)} is not a point of link {lid} (its points: {name_list(link.points)})",
                )
            continue
        guide = _guide(body.get("guide"), where + ".guide", pr, links, frame, bad_links, point)
        if guide is None or point is None:
            continue
        if guide.link == lid:
            pr.add(where + ".guide.link", f"link {lid} cannot slide on its own guide: name the link that carries the guide (0 = frame)")
            continue
        if link.axis is None and link.points.get(point, 0j) != 0j:
            pr.add(f"links.{lid}.points.{point}", "the sliding point of a link without an axis is its origin: 0")
            continue
        sliders.append(Slider(lid, guide, point))
    sliders = _name_slots(_name_fixed_guides(sliders))
    # what follows is derived from the links and sliders as a whole: only when they are
    # valid, so that one typo does not come back as a second, misleading message
    whole = not any(w.split(".")[0].split("[")[0] in ("frame", "links", "sliders") for w, _ in pr.items)
    for lid, link in links.items():
        if whole and link.axis is None and lid not in sliding:
            pr.add(
                f"links.{lid}",
                'has no axis and does not slide on a guide: give axis = ["B", "C"], or a '
                f"[[sliders]] entry with link = {lid}",
            )

    # driver ------------------------------------------------------------------------
    driver = _driver(data.get("driver"), pr, links, frame, bad_links, frame_names if raw_frame else None)

    # joints: every link attached by two pairs, no joint with two names ---------------
    raw_driver = data.get("driver")
    drv = _link_id(raw_driver.get("link", 1)) if isinstance(raw_driver, dict) else None
    before = len(pr.items)
    if whole:
        _connections(frame, links, pairs, drv, bad_links, pr)
    # a fixed point that nothing uses: a pivot whose link names it otherwise (said above,
    # when that link is left with one pair), or a stray one that would only widen the
    # plan of positions; a guide's through or a hint may name it
    unused = set(frame) if whole and len(pr.items) == before else set()
    for link in links.values():
        unused -= set(link.points)
    for body in raw_sliders:
        guide = body.get("guide") if isinstance(body, dict) else None
        if isinstance(guide, dict) and isinstance(guide.get("through"), str):
            unused.discard(guide["through"])

    # assembly hints, scales, output, trace, title ---------------------------------
    all_points = set(frame)
    for link in links.values():
        all_points |= set(link.points)
    all_points |= named
    assembly = data.get("assembly", {})
    if not isinstance(assembly, dict):
        pr.add("assembly", f'must be a table of hints, e.g. [assembly] C = "above BD", got {quote(assembly)}')
        assembly = {}
    if len(assembly) > MAX_ITEMS:
        pr.add("assembly", f"{len(assembly)} hints: at most {MAX_ITEMS}")
        assembly = {}
    hints: dict[str, str] = {}
    for k, hint in assembly.items():
        where = f"assembly.{key_text(k)}"
        if k not in all_points:
            pr.add(where, _unknown_point(k, all_points))
            continue
        on = [lid for lid, link in links.items() if k in link.points]
        fixed = "a fixed point" if k in frame else "on the crank only" if drv is not None and on == [drv] else ""
        if fixed:
            pr.add(where, f"{k} is {fixed}: it has one position; a hint names the new point of a "
                   "group that closes two ways (the end of a coupler, a slider)")
            continue
        if not isinstance(hint, str) or len(hint) > MAX_TEXT:
            pr.add(where, f'must be a hint such as "above BD" or "right of C", got {quote(hint)}')
            continue
        problem, refs = _hint_problem(k, hint, sorted(all_points, key=len, reverse=True))
        if problem:
            pr.add(where, f"{quote(hint)}: {problem}")
            continue
        hints[k] = hint
        unused -= set(refs)
    # a fixed point named as the output is refused as such below (no stroke), with the
    # outputs the mechanism has, rather than as a stray point to remove
    if isinstance(data.get("output"), str):
        unused.discard(data["output"])
    for nm in sorted(unused):
        pr.add(f"frame.{nm}", f'"{nm}" is on no link: a fixed pivot is a joint, named on the '
               "link hinged there as well; name it on its link, or remove it")
    scales = {}
    raw_scales = data.get("scales", {})
    if not isinstance(raw_scales, dict):
        pr.add("scales", f"must be a table: [scales] mu_l = 0.01, mu_v = …, mu_a = …, got {quote(raw_scales)}")
        raw_scales = {}
    check_keys(raw_scales, {"mu_l", "mu_v", "mu_a"}, "scales", pr)
    for key in ("mu_l", "mu_v", "mu_a"):
        if key in raw_scales:
            val = read_number(raw_scales[key], f"scales.{key}", pr, positive=True, unit=MU_UNIT[key],
                          low=SCALE[0], high=SCALE[1])
            if val is not None:
                scales[key] = val
    trace = data.get("trace", [])
    if not isinstance(trace, list) or len(trace) > MAX_ITEMS:
        pr.add("trace", f'must be a list of at most {MAX_ITEMS} point names, e.g. ["C", "S3"], got {quote(trace)}')
        trace = []
    for i, t in enumerate(trace):
        if not isinstance(t, str):
            pr.add(f"trace[{i}]", f'must be a point name, e.g. "C", got {quote(t)}')
        elif t not in all_points:
            pr.add(f"trace[{i}]", _unknown_point(t, all_points))
    trace = [t for t in trace if isinstance(t, str) and t in all_points]
    output = data.get("output")
    if output is not None:
        if not isinstance(output, str):
            pr.add("output", f'must be a point name, e.g. "C", got {quote(output)}')
            output = None
        elif output not in all_points:
            pr.add("output", _unknown_point(output, all_points))
    title = data.get("title", {})
    if not isinstance(title, dict) or len(title) > MAX_ITEMS:
        pr.add("title", f"must be a table of texts for the title block, got {quote(title)}")
        title = {}
    for k, v in title.items():
        if isinstance(v, bool) or not isinstance(v, str | int):
            pr.add(f"title.{key_text(k)}", f"must be a text, got {quote(v)}")
    title = {str(k)[:MAX_TEXT]: str(v)[:500] for k, v in title.items()
             if isinstance(v, str | int) and not isinstance(v, bool)}

    pr.raise_if_any()
    assert driver is not None
    mech = Mechanism(
        name=name,
        frame=frame,
        links=links,
        sliders=tuple(sliders),
        driver=driver,
        assembly=hints,
        scales=scales,
        trace=tuple(trace),
        output=output,
        title=title,
        source=source,
        names=names,
    )
    if output is not None:  # a point with no stroke was silently replaced by another
        from plans.cycle.analysis import no_output

        if (why := no_output(mech, output)) is not None:
            pr.add("output", why)
            pr.raise_if_any()
    return mech


def _link(lid: int, lname: str, body: dict, where: str, pr: Problems, named: set[str],
          spellings: dict[str, str]):
    """One link's points in its own coordinates; ``ok`` False when it has a problem."""
    before = len(pr.items)
    points: dict[str, complex] = {}
    axis = body.get("axis")
    if axis is not None:
        if not (isinstance(axis, list) and len(axis) == 2):
            pr.add(where + ".axis", f'must be two point names, e.g. ["B", "C"], got {quote(axis)}')
            axis = None
        else:
            a0 = _name(axis[0], where + ".axis[0]", pr, named)
            a1 = _name(axis[1], where + ".axis[1]", pr, named)
            a0 = a0 if a0 and _one_spelling(a0, where + ".axis[0]", spellings, pr) else None
            a1 = a1 if a1 and _one_spelling(a1, where + ".axis[1]", spellings, pr) else None
            named |= {a for a in (a0, a1) if a}
            axis = (a0, a1) if a0 and a1 else None
            if axis and a0 == a1:
                pr.add(where + ".axis", f'zero-length link: both ends of the axis are "{a0}"; an axis runs between two points')
                axis = None
            if axis:
                points[a0] = 0j
    raw_points = body.get("points", {})
    if not isinstance(raw_points, dict):
        pr.add(where + ".points", f"must be a table, e.g. points = {{ C = 0.75, S3 = [0.25, 0.02] }}, got {quote(raw_points)}")
        raw_points = {}
    if len(raw_points) > MAX_LINK_POINTS:
        pr.add(where + ".points", f"{len(raw_points)} points on one link: at most {MAX_LINK_POINTS}")
        return Link(lid, lname, points, axis), False
    failed: set[str] = set()
    for pname, spec in raw_points.items():
        pw = f"{where}.points.{key_text(pname)}"
        nm = _name(pname, pw, pr, named)
        if nm is None or not _one_spelling(nm, pw, spellings, pr):
            continue
        named.add(nm)
        if isinstance(spec, list):
            if len(spec) != 2:
                pr.add(pw, f"must be a distance along the axis or [along, across], got {quote(spec)}")
                failed.add(nm)
                continue
            x = read_number(spec[0], pw + "[0]", pr)
            y = read_number(spec[1], pw + "[1]", pr)
            if x is None or y is None:
                failed.add(nm)
                continue
            local = complex(x, y)
        else:
            if isinstance(spec, dict):
                pr.add(pw, "must be a distance along the axis or [along, across], got a table")
                failed.add(nm)
                continue
            x = read_number(spec, pw, pr)
            if x is None:
                failed.add(nm)
                continue
            local = complex(x, 0.0)
        if axis and nm == axis[0] and local != 0:
            pr.add(pw, f'"{nm}" is the origin of the axis: its position is 0 (or leave it out)')
            failed.add(nm)
            continue
        points[nm] = local
    if axis:
        a0, a1 = axis
        if a1 in failed or ("points" not in body and set(body) - {"name", "axis"}):
            pass  # a bad value or a misspelt "points": said already
        elif a1 not in points:
            pr.add(
                where + ".points",
                f'the axis end "{a1}" is not among the points of link {lid} '
                f"(its points: {name_list(set(raw_points) - {a0}) if raw_points else 'none'}): "
                f"give its distance from {a0}, e.g. {a1} = 0.2",
            )
        else:
            end = points[a1]
            pw = f"{where}.points.{a1}"
            if end == 0:
                pr.add(pw, f'zero-length link: the axis end "{a1}" is at the origin "{a0}"; give the length {a0}{a1} in metres')
            elif end.imag != 0:
                pr.add(pw, f'the axis end "{a1}" must lie on the axis: give its distance, {a1} = {abs(end):g}, not {_fmt(end)}')
            elif end.real < 0:
                pr.add(pw, f"negative length {end.real:g}: the length {a0}{a1} is positive (write {a1} = {-end.real:g})")
            elif end.real < MIN_LINK:
                pr.add(pw, f"link length {end.real:g} m: zero or too short, a link is at least {MIN_LINK:g} m")
    if not points and not failed and len(pr.items) == before:
        pr.add(where, 'has no points: give axis = ["B", "C"] and points = { C = 0.3 }')
    return Link(lid, lname, points, axis), len(pr.items) == before


def _coincident(points: dict[str, complex], joints: set[str], where: str, what: str,
                pr: Problems, tol: float = MIN_LEN) -> None:
    """Two joints at one place: a zero-length link between them, or one joint with two names."""
    names = [n for n in points if n in joints]
    if len(names) > 60:  # keep it linear-ish for big files; cells of the tolerance
        cells: dict[tuple[int, int], str] = {}
        for n in names:
            z = points[n]
            key = (round(z.real / tol), round(z.imag / tol))
            if key in cells:
                pr.add(f"{where}.{n}" if where == "frame" else where,
                       f'{what} "{cells[key]}" and "{n}" are at the same place {_fmt(z)}: one joint has one name')
            cells.setdefault(key, n)
        return
    for i, a in enumerate(names):
        for b in names[i + 1:]:
            if abs(points[a] - points[b]) < tol:
                pr.add(
                    f"{where}.{b}" if where == "frame" else where,
                    f'{what} "{a}" and "{b}" are at the same place {_fmt(points[b])}: a '
                    "zero-length link between them; if they are one joint, give it one name",
                )


def _connections(frame, links, pairs, drv, bad_links, pr: Problems) -> None:
    """Links attached by fewer than two pairs (a typo in a point name, usually), and two
    joints of one link at the same place."""
    carriers: dict[str, list[int]] = {name: [0] for name in frame}
    for lid, link in sorted(links.items()):
        for name in link.points:
            carriers.setdefault(name, []).append(lid)
    slides: dict[int, list[str]] = {lid: [] for lid in links}
    for lid, gl in pairs:
        slides[lid].append("its slider")
        if gl in slides:
            slides[gl].append(f"the guide of link {lid}")
    for lid, link in sorted(links.items()):
        if lid in bad_links:
            continue
        joints = {n for n in link.points if len(carriers[n]) > 1}
        _coincident(link.points, joints, f"links.{lid}.points", f"joints of link {lid}", pr, SAME)
        if lid == drv:
            continue
        pairs = [f'"{n}"' for n in sorted(joints)] + slides[lid]
        if len(pairs) >= 2:
            continue
        free = [n for n in link.points if len(carriers[n]) == 1]
        others = {n for n, c in carriers.items() if c != [lid]}
        what = (f"link {lid} is not connected to anything" if not pairs
                else f"link {lid} is attached by one pair only ({pairs[0]})")
        need = "a link of a mechanism is attached by at least two pairs (joints named on two links, or a slider)"
        if link.axis and link.axis[0] in free:
            why = f"it is on no other link and not in [frame], so {what}"
            pr.add(f"links.{lid}.axis[0]", _unknown_point(link.axis[0], others, why))
        elif free and others:
            import difflib  # only for a misspelt joint

            guesses = []
            for n in free:
                close = difflib.get_close_matches(n, list(others), n=1, cutoff=0.5)
                if close:
                    guesses.append(f'"{n}" → "{close[0]}"?')
            hint = f"; a misspelt joint? {', '.join(guesses)}" if guesses else ""
            pr.add(f"links.{lid}", f"{what}: {need}{hint}")
        else:
            pr.add(f"links.{lid}", f"{what}: {need}")


def _hint_problem(key: str, hint: str, names: list[str]) -> tuple[str | None, list[str]]:
    """Why an [assembly] hint for ``key`` cannot be read or cannot decide anything, or
    None; and the points it names (none where it cannot be read)."""
    from plans.kinematics.branches import parse_hint

    try:
        _, refs = parse_hint(hint, names)
    except ValueError as exc:
        known = f" — known points: {name_list(names)}" if "not a point name" in str(exc) else ""
        return one_line(str(exc), 120) + known, []
    if key in refs:
        return (f"the hint places {key} relative to {key} itself: name other points, "
                f'e.g. "above BD"'), refs
    if len(refs) == 2 and refs[0] == refs[1]:
        return f"a line needs two different points, not {refs[0]} twice", refs
    return None, refs


#: names of fixed guides, in the order an inclined one takes them
FIXED_NAMES = ("x-x", "y-y", "z-z", "u-u", "w-w")


def _parallel(a: complex, b: complex) -> bool:
    return abs(cross(a, b)) <= tolerances.AXIAL


def _free_name(candidates, taken: dict[str, complex], direction: complex) -> str:
    """The first of ``candidates`` not ``taken`` by a guide of another direction (parallel
    guides may share a name: a plan's line only says "∥ x-x"); it is then taken."""
    name = next(n for n in candidates if n not in taken or _parallel(taken[n], direction))
    taken.setdefault(name, direction)
    return name


def _name_fixed_guides(sliders: list[Slider]) -> list[Slider]:
    """An unlabelled inclined fixed guide is x-x, the slider's axis, unless a fixed guide
    of another direction is already called so: then the first free of
    :data:`FIXED_NAMES`."""
    def inclined(d: complex) -> bool:
        return abs(d.real) > tolerances.AXIAL and abs(d.imag) > tolerances.AXIAL

    renamed = [i for i, s in enumerate(sliders)
               if s.guide.named_by_tool and s.guide.link == 0 and inclined(s.guide.direction)]
    taken = {s.guide.label: s.guide.direction for i, s in enumerate(sliders)
             if s.guide.link == 0 and i not in renamed}
    out = list(sliders)
    for i in renamed:
        g = out[i].guide
        name = _free_name((*FIXED_NAMES, g.label), taken, g.direction)
        out[i] = replace(out[i], guide=replace(g, label=name))
    return out


#: the languages a name may be given in
LANGS = ("en", "ru")


def _name_slots(sliders: list[Slider]) -> list[Slider]:
    """Two slots of one link in different directions would both be x3-x3: the second is
    x3′-x3′, the third x3′′-x3′′, whatever names the file gave the others."""
    out = list(sliders)
    taken: dict[int, dict[str, complex]] = {}  # link → name → direction, the file's first
    for s in out:
        if not s.guide.named_by_tool and s.guide.link:
            taken.setdefault(s.guide.link, {})[s.guide.label] = s.guide.direction
    for i, s in enumerate(out):
        g = s.guide
        if not g.named_by_tool or g.link == 0 or g.label != f"x{g.link}-x{g.link}":
            continue
        marks = ("′" * k for k in itertools.count())
        name = _free_name((f"x{g.link}{m}-x{g.link}{m}" for m in marks),
                          taken.setdefault(g.link, {}), g.direction)
        out[i] = replace(out[i], guide=replace(g, label=name))
    return out


def _title_names(value, pr: Problems, default: str) -> tuple[str, dict[str, str]]:
    """``name = "…"`` or ``name = { en = "…", ru = "…" }``: (the name, names by language).
    The plain name is the English one, else the first given."""
    if not isinstance(value, dict):
        return read_text(value, "name", pr, default), {}
    check_keys(value, set(LANGS), "name", pr)
    names = {lang: read_text(value[lang], f"name.{lang}", pr, default)
             for lang in LANGS if lang in value}
    if not names and not any(k not in LANGS for k in value):
        pr.add("name", 'an empty table: give a text, or { en = "…", ru = "…" }')
    return names.get("en") or next(iter(names.values()), default), names


def _guide(body, where, pr: Problems, links, frame, bad_links, slides: str | None = None
           ) -> Guide | None:
    """The guide of a [[sliders]] entry whose point ``slides`` runs along it.

    Without a ``label`` it is named by notation, never by a word, so that a Russian sheet
    says what an English one does: x-x or y-y on the frame (an inclined fixed guide
    too is the slider's axis x-x, see :func:`_name_fixed_guides`); on a link, its axis
    (along it), "⊥ DE" (across it), else the line through a named point of the link and
    the sliding point ("DA"), or x3-x3 for link 3 when no named point lies on it.
    """
    if not isinstance(body, dict):
        got = "missing" if body is None else f"must be a table, got {quote(body)}"
        pr.add(where, f"{got}: e.g. guide = {{ link = 0, through = [0, 0.35], angle_deg = 0 }} or {{ link = 3 }}")
        return None
    check_keys(body, {"link", "through", "angle_deg", "direction", "offset", "label"}, where, pr)
    raw = body.get("link", 0)
    gl = _link_id(raw)
    if gl is None or (gl != 0 and gl not in links):
        if gl not in bad_links:
            pr.add(where + ".link", _not_a_link(raw, "a link", f"0 = frame; moving: {_ids(links)}"))
        return None
    if gl in bad_links:
        return None
    if "direction" in body:
        if "angle_deg" in body:
            pr.add(where, "give angle_deg or direction, not both")
            return None
        d = _pair(body["direction"], where + ".direction", pr)
        if d is None:
            return None
        if abs(d) < SAME:
            pr.add(where + ".direction", f"guide direction of zero length {_fmt(d)}: give a vector along the guide, e.g. [1, 0]")
            return None
        direction = d / abs(d)
    else:
        angle = read_number(body.get("angle_deg", 0.0), where + ".angle_deg", pr, unit="°")
        if angle is None:
            return None
        direction = complex(math.cos(math.radians(angle)), math.sin(math.radians(angle)))
    offset = read_number(body.get("offset", 0.0), where + ".offset", pr)
    if offset is None:
        return None
    through = body.get("through")
    label = body.get("label")
    if gl == 0:
        if isinstance(through, str):
            if through not in frame:
                pr.add(where + ".through", f"{quote(through)} is not a fixed point (fixed points: {name_list(frame)}); or give [x, y]")
                return None
            point = frame[through]
        elif through is None:
            pr.add(where + ".through", "missing: a point of the guide, [x, y] or a fixed point name")
            return None
        else:
            point = _pair(through, where + ".through", pr)
            if point is None:
                return None
        default_label = "y-y" if abs(direction.real) < tolerances.AXIAL else "x-x"
    else:
        link = links[gl]
        if link.axis is None:
            pr.add(where + ".link", f"link {gl} has no axis to carry a guide: give it an axis, or let the guide be on another link")
            return None
        if isinstance(through, str):
            if through not in link.points:
                pr.add(where + ".through", f"{quote(through)} is not a point of link {gl} (its points: {name_list(link.points)})")
                return None
            point = link.points[through]
        elif through is None:
            point = 0j
        else:
            point = _pair(through, where + ".through", pr)
            if point is None:
                return None
    point = point + offset * 1j * direction
    if gl != 0:
        # the link's own x-axis runs along its axis: a guide along it or across it is
        # named by it, any other by a named point on it and the point sliding along it
        axis = "".join(link.axis)
        on = [n for n, q in link.points.items()
              if n != slides and abs(((q - point) * direction.conjugate()).imag) < SAME]
        default_label = (axis if abs(direction.imag) < tolerances.AXIAL else f"⊥ {axis}"
                         if abs(direction.real) < tolerances.AXIAL
                         else f"{on[0]}{slides}" if on and slides else f"x{gl}-x{gl}")
    if label is not None and (not isinstance(label, str) or len(label) > 20):
        pr.add(where + ".label", f'must be a short text (at most 20 characters), e.g. "x-x", got {quote(label)}')
        label = None
    return Guide(gl, point, direction, label or default_label, named_by_tool=not label)


def _driver(body, pr: Problems, links, frame, bad_links, frame_names) -> Driver | None:
    """The crank; ``frame_names``: the names in [frame] (None: no [frame] at all)."""
    where = "driver"
    if not isinstance(body, dict):
        got = "missing" if body is None else f"must be a table, got {quote(body)}"
        pr.add(where, f"{got}: [driver] with link, angle_deg, and omega (rad/s) or rpm")
        return None
    check_keys(
        body, {"link", "angle_deg", "from", "measured", "omega", "rpm", "sense"}, where, pr
    )
    raw = body.get("link", 1)
    lid = _link_id(raw)
    if lid is None or lid not in links:
        if lid not in bad_links and (links or lid is None):
            pr.add(where + ".link", _not_a_link(raw, "a moving link", f"moving links: {_ids(links)}"))
        return None
    link = links[lid]
    if link.axis is None:
        if lid not in bad_links:
            pr.add(f"links.{lid}.axis", f'missing: the crank (link {lid}) needs an axis from its fixed pivot to its pin, e.g. ["O", "A"]')
        return None
    pivot, tip = link.axis
    if frame_names is None or (pivot in frame_names and pivot not in frame):
        pass  # [frame] missing, or the pivot's coordinates are wrong: said already
    elif pivot not in frame:
        swapped = f' (the axis runs from the fixed pivot to the pin: ["{tip}", "{pivot}"]?)' if tip in frame else ""
        pr.add(
            f"links.{lid}.axis[0]",
            f'the crank turns about "{pivot}", which is not a fixed point in [frame] '
            f"(fixed points: {name_list(frame)}): the driver must be attached to the frame{swapped}",
        )
    else:
        also = sorted(n for n in link.points if n in frame and n != pivot)
        if also:
            pr.add(
                f"links.{lid}.points.{also[0]}",
                f'the crank is hinged to the frame at "{pivot}" and at "{also[0]}": it could '
                "not turn; a crank has one fixed pivot",
            )
    angle = read_number(body.get("angle_deg"), where + ".angle_deg", pr, unit="°")
    ref = body.get("from", "+x")
    if not isinstance(ref, str) or ref not in REFERENCES:
        pr.add(where + ".from", f'{quote(ref, 20)} is not a reference: one of "+x", "+y", "-x", "-y"')
        ref = "+x"
    measured = body.get("measured", "ccw")
    if not isinstance(measured, str) or measured not in SENSES:
        pr.add(where + ".measured", f'{quote(measured, 20)}: must be "ccw" (counter-clockwise) or "cw" (clockwise)')
        measured = "ccw"
    sense = body.get("sense", "ccw")
    if not isinstance(sense, str) or sense not in SENSES:
        pr.add(where + ".sense", f'{quote(sense, 20)}: must be "ccw" (counter-clockwise) or "cw" (clockwise)')
        sense = "ccw"
    rpm = None
    if "omega" in body and "rpm" in body:
        pr.add(where, "give omega (rad/s) or rpm, not both")
        return None
    if "rpm" in body:
        rpm = read_number(body["rpm"], where + ".rpm", pr, positive=True, unit="rpm",
                          low=RPM_MIN, high=SPEED[1])
        omega = None if rpm is None else math.pi * rpm / 30.0
    elif "omega" in body:
        omega = read_number(body["omega"], where + ".omega", pr, positive=True, unit="rad/s",
                        low=SPEED[0], high=SPEED[1])
    else:
        pr.add(where + ".omega", "missing: the crank speed, omega in rad/s or rpm")
        omega = None
    if angle is None or omega is None or tip not in link.points:
        return None
    phi = phi_of(angle, ref, measured)
    return Driver(
        link=lid,
        pivot=pivot,
        tip=tip,
        length=link.points[tip].real,
        phi=phi,
        omega=SENSES[sense] * omega,
        angle_deg=angle,
        reference=ref,
        measured=measured,
        rpm=rpm,
    )
