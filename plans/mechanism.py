"""The declarative description of a mechanism, and its TOML file format.

A mechanism is the frame (link 0) with its fixed pivots, numbered moving links, each with
its named points in the link's own coordinates, the prismatic pairs (sliders and the
guides they move along), and the driver (the crank). Revolute pairs are implied: a point
named on two links (or on a link and the frame) is a hinge joining them.

A link's own coordinates: the origin at ``axis[0]`` and the x-axis towards ``axis[1]``; a
point is given by its distance along that axis, or ``[along, across]`` (across positive to
the left of the axis). A link without an axis slides on a guide: its origin is its point
on the guide and its x-axis runs along the guide.

Lengths are metres, angles degrees in the file and radians inside, time seconds.
"""

from __future__ import annotations

import math
import re
import tomllib
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from .errors import InputError

#: names the plans reserve for their own construction points (n1, k, p, π)
RESERVED = re.compile(r"^(P|N\d*|K\d*)$")
POINT_NAME = re.compile(r"^[A-Z][A-Za-z0-9_']{0,11}$")
MAX_ABS = 1e6  # metres, rad/s: anything larger is a typo, not a machine
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

    def slider_of(self, link: int) -> Slider | None:
        for s in self.sliders:
            if s.link == link:
                return s
        return None

    def with_phi(self, phi: float) -> Mechanism:
        """The same mechanism with the crank at ``phi`` (rad, from +x)."""
        from dataclasses import replace

        return replace(self, driver=replace(self.driver, phi=phi))


# ---------------------------------------------------------------------------------------
# loading and validation
# ---------------------------------------------------------------------------------------

REFERENCES = {"+x": 0.0, "+y": 90.0, "-x": 180.0, "-y": 270.0}
SENSES = {"ccw": 1.0, "cw": -1.0}


def load(path: str | Path) -> Mechanism:
    """Read and validate a mechanism file; every problem is reported, located."""
    path = Path(path)
    source = str(path)
    try:
        raw = path.read_bytes()
    except OSError as exc:
        raise InputError(source, f"cannot read the file: {exc.strerror}") from None
    if len(raw) > 1_000_000:
        raise InputError(source, "file is larger than 1 MB; a mechanism file is a few KB")
    try:
        data = tomllib.loads(raw.decode("utf-8"))
    except UnicodeDecodeError as exc:
        raise InputError(source, f"not UTF-8 text (byte {exc.start})") from None
    except tomllib.TOMLDecodeError as exc:
        raise InputError(source, f"TOML syntax error: {exc}") from None
    return from_dict(data, source)


class _Problems:
    def __init__(self, source: str):
        self.source = source
        self.items: list[str] = []

    def add(self, where: str, what: str) -> None:
        self.items.append(f"{where}: {what}")

    def raise_if_any(self) -> None:
        if self.items:
            raise InputError(self.source, self.items)


def _number(value: Any, where: str, problems: _Problems, *, positive=False, default=None):
    if value is None:
        if default is not None:
            return default
        problems.add(where, "missing (a number is needed)")
        return None
    if isinstance(value, bool) or not isinstance(value, int | float):
        problems.add(where, f"must be a number, got {type(value).__name__} {value!r:.40}")
        return None
    x = float(value)
    if not math.isfinite(x) or abs(x) > MAX_ABS:
        problems.add(where, f"{value!r:.40} is out of range (|x| ≤ {MAX_ABS:g})")
        return None
    if positive and x <= 0:
        problems.add(where, f"must be positive, got {value}")
        return None
    return x


def _pair(value: Any, where: str, problems: _Problems) -> complex | None:
    if not (isinstance(value, list) and len(value) == 2):
        problems.add(where, f"must be [x, y] in metres, got {value!r:.60}")
        return None
    x = _number(value[0], where + "[0]", problems)
    y = _number(value[1], where + "[1]", problems)
    return None if x is None or y is None else complex(x, y)


def _name(value: Any, where: str, problems: _Problems) -> str | None:
    if not isinstance(value, str) or not POINT_NAME.match(value):
        problems.add(
            where,
            f"{value!r:.40} is not a point name (a capital letter, then letters/digits)",
        )
        return None
    if RESERVED.match(value):
        problems.add(
            where, f'"{value}" is reserved for plan construction points (p, n1, k…)'
        )
        return None
    return value


def _check_keys(table: dict, allowed: set[str], where: str, problems: _Problems):
    for key in table:
        if key not in allowed:
            close = ", ".join(sorted(allowed))
            problems.add(f"{where}.{key}" if where else key, f"unknown key (known: {close})")


def from_dict(data: dict, source: str = "<mechanism>") -> Mechanism:
    """Build a :class:`Mechanism` from parsed TOML, reporting every problem at once."""
    pr = _Problems(source)
    if not isinstance(data, dict):
        raise InputError(source, "the file must be a TOML table")
    _check_keys(
        data,
        {"name", "frame", "links", "sliders", "driver", "assembly", "scales", "trace",
         "output", "title"},
        "", pr,
    )
    name = data.get("name", Path(source).stem)
    if not isinstance(name, str) or len(name) > 200:
        pr.add("name", "must be a text of at most 200 characters")
        name = "mechanism"

    # frame -------------------------------------------------------------------------
    frame: dict[str, complex] = {}
    raw_frame = data.get("frame")
    if not isinstance(raw_frame, dict) or not raw_frame:
        pr.add("frame", "missing: the fixed pivots, e.g. O = [0.0, 0.0]")
        raw_frame = {}
    for key, value in raw_frame.items():
        nm = _name(key, f"frame.{key}", pr)
        xy = _pair(value, f"frame.{key}", pr)
        if nm and xy is not None:
            frame[nm] = xy

    # links -------------------------------------------------------------------------
    links: dict[int, Link] = {}
    raw_links = data.get("links")
    if not isinstance(raw_links, dict) or not raw_links:
        pr.add("links", "missing: the moving links, e.g. [links.1] axis = [\"O\", \"A\"]")
        raw_links = {}
    if len(raw_links) > 200:
        pr.add("links", f"{len(raw_links)} links: at most 200 are supported")
        raw_links = {}
    for key, body in raw_links.items():
        where = f"links.{key}"
        if not (isinstance(key, str) and key.isdigit() and 0 < int(key) < 1000):
            pr.add(where, "links are numbered 1, 2, 3… (0 is the frame)")
            continue
        lid = int(key)
        if not isinstance(body, dict):
            pr.add(where, "must be a table with axis and points")
            continue
        _check_keys(body, {"name", "axis", "points"}, where, pr)
        lname = body.get("name", f"link {lid}")
        if not isinstance(lname, str) or len(lname) > 200:
            pr.add(where + ".name", "must be a text of at most 200 characters")
            lname = f"link {lid}"
        points: dict[str, complex] = {}
        axis = body.get("axis")
        if axis is not None:
            if not (isinstance(axis, list) and len(axis) == 2):
                pr.add(where + ".axis", 'must be two point names, e.g. ["B", "C"]')
                axis = None
            else:
                a0 = _name(axis[0], where + ".axis[0]", pr)
                a1 = _name(axis[1], where + ".axis[1]", pr)
                axis = (a0, a1) if a0 and a1 else None
                if axis and a0 == a1:
                    pr.add(where + ".axis", f'both ends are "{a0}": an axis needs two points')
                    axis = None
                if axis:
                    points[a0] = 0j
        raw_points = body.get("points", {})
        if not isinstance(raw_points, dict):
            pr.add(where + ".points", "must be a table, e.g. { C = 0.75, S3 = 0.25 }")
            raw_points = {}
        if len(raw_points) > 1000:
            pr.add(where + ".points", "more than 1000 points on one link")
            raw_points = {}
        for pname, spec in raw_points.items():
            pw = f"{where}.points.{pname}"
            nm = _name(pname, pw, pr)
            if nm is None:
                continue
            if isinstance(spec, list):
                if len(spec) != 2:
                    pr.add(pw, "must be a distance along the axis or [along, across]")
                    continue
                x = _number(spec[0], pw + "[0]", pr)
                y = _number(spec[1], pw + "[1]", pr)
                if x is None or y is None:
                    continue
                local = complex(x, y)
            else:
                x = _number(spec, pw, pr)
                if x is None:
                    continue
                local = complex(x, 0.0)
            if axis and nm == axis[0] and local != 0:
                pr.add(pw, f'"{nm}" is the origin of the axis: its position is 0')
                continue
            points[nm] = local
        if axis:
            a1 = axis[1]
            if a1 not in points:
                pr.add(where + ".points", f'the axis end "{a1}" needs its distance, e.g. {a1} = 0.2')
            elif points[a1].imag != 0 or points[a1].real <= MIN_LEN:
                pr.add(
                    f"{where}.points.{a1}",
                    f'the axis end "{a1}" must lie on the axis at a positive distance, '
                    f"got {_fmt(points[a1])}",
                )
        if not points:
            pr.add(where, "has no points")
        links[lid] = Link(lid, lname, points, axis)

    # sliders -----------------------------------------------------------------------
    sliders: list[Slider] = []
    raw_sliders = data.get("sliders", [])
    if not isinstance(raw_sliders, list):
        pr.add("sliders", "must be an array of tables: [[sliders]]")
        raw_sliders = []
    for i, body in enumerate(raw_sliders):
        where = f"sliders[{i}]"
        if not isinstance(body, dict):
            pr.add(where, "must be a table with link and guide")
            continue
        _check_keys(body, {"link", "point", "guide"}, where, pr)
        lid = body.get("link")
        if not isinstance(lid, int) or isinstance(lid, bool) or lid not in links:
            pr.add(where + ".link", f"{lid!r:.20} is not a moving link (known: {_ids(links)})")
            continue
        link = links[lid]
        point = body.get("point")
        if point is None:
            point = next(iter(link.points), None)
        elif point not in link.points:
            pr.add(
                where + ".point",
                f'"{point}" is not a point of link {lid} (its points: {", ".join(link.points)})',
            )
            continue
        guide = _guide(body.get("guide"), where + ".guide", pr, links, frame, lid)
        if guide is None or point is None:
            continue
        if guide.link == lid:
            pr.add(where + ".guide.link", "a link cannot slide on its own guide")
            continue
        if link.axis is None and link.points.get(point, 0j) != 0j:
            pr.add(f"links.{lid}.points.{point}", "the sliding point of a link without an axis is its origin: 0")
            continue
        sliders.append(Slider(lid, guide, point))
    for lid, link in links.items():
        if link.axis is None:
            own = [s for s in sliders if s.link == lid]
            if not own:
                pr.add(
                    f"links.{lid}.axis",
                    'missing: a link that does not slide on a guide needs an axis, e.g. axis = ["B", "C"]',
                )

    # driver ------------------------------------------------------------------------
    driver = _driver(data.get("driver"), pr, links, frame)

    # assembly hints, scales, output, trace, title ---------------------------------
    assembly = data.get("assembly", {})
    if not isinstance(assembly, dict) or not all(
        isinstance(k, str) and isinstance(v, str) for k, v in assembly.items()
    ):
        pr.add("assembly", 'must be a table of hints, e.g. C = "above BD"')
        assembly = {}
    scales = {}
    raw_scales = data.get("scales", {})
    if not isinstance(raw_scales, dict):
        pr.add("scales", "must be a table: mu_l, mu_v, mu_a")
        raw_scales = {}
    _check_keys(raw_scales, {"mu_l", "mu_v", "mu_a"}, "scales", pr)
    for key in ("mu_l", "mu_v", "mu_a"):
        if key in raw_scales:
            val = _number(raw_scales[key], f"scales.{key}", pr, positive=True)
            if val is not None:
                scales[key] = val
    all_points = set(frame)
    for link in links.values():
        all_points |= set(link.points)
    trace = data.get("trace", [])
    if not isinstance(trace, list) or not all(isinstance(t, str) for t in trace):
        pr.add("trace", 'must be a list of point names, e.g. ["C", "S3"]')
        trace = []
    for t in trace:
        if t not in all_points:
            pr.add("trace", f'unknown point "{t}" (known: {", ".join(sorted(all_points))})')
    output = data.get("output")
    if output is not None and output not in all_points:
        pr.add("output", f'unknown point "{output}" (known: {", ".join(sorted(all_points))})')
    for k, hint in assembly.items():
        if k not in all_points:
            pr.add(f"assembly.{k}", f'unknown point "{k}" (known: {", ".join(sorted(all_points))})')
    title = data.get("title", {})
    if not isinstance(title, dict) or not all(isinstance(v, str | int) for v in title.values()):
        pr.add("title", "must be a table of texts for the title block")
        title = {}
    title = {str(k): str(v)[:500] for k, v in title.items()}

    pr.raise_if_any()
    assert driver is not None
    return Mechanism(
        name=name,
        frame=frame,
        links=links,
        sliders=tuple(sliders),
        driver=driver,
        assembly=dict(assembly),
        scales=scales,
        trace=tuple(trace),
        output=output,
        title=title,
        source=source,
    )


def _fmt(z: complex) -> str:
    return f"[{z.real:g}, {z.imag:g}]"


def _ids(links) -> str:
    return ", ".join(str(i) for i in sorted(links)) or "none"


def _guide(body, where, pr: _Problems, links, frame, slider_link) -> Guide | None:
    if not isinstance(body, dict):
        pr.add(where, 'missing: e.g. { link = 0, through = [0, 0.35], angle_deg = 0 } or { link = 3 }')
        return None
    _check_keys(body, {"link", "through", "angle_deg", "offset", "label"}, where, pr)
    gl = body.get("link", 0)
    if not isinstance(gl, int) or isinstance(gl, bool) or (gl != 0 and gl not in links):
        pr.add(where + ".link", f"{gl!r:.20} is not a link (0 = frame; moving: {_ids(links)})")
        return None
    angle = _number(body.get("angle_deg", 0.0), where + ".angle_deg", pr)
    offset = _number(body.get("offset", 0.0), where + ".offset", pr)
    if angle is None or offset is None:
        return None
    direction = complex(math.cos(math.radians(angle)), math.sin(math.radians(angle)))
    through = body.get("through")
    label = body.get("label")
    if gl == 0:
        if isinstance(through, str):
            if through not in frame:
                pr.add(where + ".through", f'"{through}" is not a fixed point (known: {", ".join(frame)})')
                return None
            point = frame[through]
        elif through is None:
            pr.add(where + ".through", "missing: a point [x, y] or a fixed point name")
            return None
        else:
            point = _pair(through, where + ".through", pr)
            if point is None:
                return None
        default_label = "x-x" if abs(direction.imag) < 1e-12 else "y-y" if abs(direction.real) < 1e-12 else "guide"
    else:
        link = links[gl]
        if link.axis is None:
            pr.add(where + ".link", f"link {gl} has no axis to carry a guide")
            return None
        if isinstance(through, str):
            if through not in link.points:
                pr.add(where + ".through", f'"{through}" is not a point of link {gl}')
                return None
            point = link.points[through]
        elif through is None:
            point = 0j
        else:
            point = _pair(through, where + ".through", pr)
            if point is None:
                return None
        default_label = "".join(link.axis)
    point = point + offset * 1j * direction
    if label is not None and not isinstance(label, str):
        pr.add(where + ".label", "must be a text")
        label = None
    return Guide(gl, point, direction, label or default_label)


def _driver(body, pr: _Problems, links, frame) -> Driver | None:
    where = "driver"
    if not isinstance(body, dict):
        pr.add(where, "missing: [driver] with link, angle_deg and omega or rpm")
        return None
    _check_keys(
        body, {"link", "angle_deg", "from", "measured", "omega", "rpm", "sense"}, where, pr
    )
    lid = body.get("link", 1)
    if not isinstance(lid, int) or isinstance(lid, bool) or lid not in links:
        pr.add(where + ".link", f"{lid!r:.20} is not a moving link (known: {_ids(links)})")
        return None
    link = links[lid]
    if link.axis is None:
        pr.add(f"links.{lid}.axis", 'the crank needs an axis from its pivot to its pin, e.g. ["O", "A"]')
        return None
    pivot, tip = link.axis
    if pivot not in frame:
        pr.add(
            f"links.{lid}.axis[0]",
            f'the crank turns about "{pivot}", which is not a fixed point in [frame] '
            f'(fixed: {", ".join(frame) or "none"}): the driver must be attached to the frame',
        )
    angle = _number(body.get("angle_deg"), where + ".angle_deg", pr)
    ref = body.get("from", "+x")
    if ref not in REFERENCES:
        pr.add(where + ".from", f'{ref!r:.20} is not a reference (one of "+x", "+y", "-x", "-y")')
        ref = "+x"
    measured = body.get("measured", "ccw")
    if measured not in SENSES:
        pr.add(where + ".measured", f'{measured!r:.20} must be "ccw" or "cw"')
        measured = "ccw"
    sense = body.get("sense", "ccw")
    if sense not in SENSES:
        pr.add(where + ".sense", f'{sense!r:.20} must be "ccw" or "cw"')
        sense = "ccw"
    rpm = None
    if "omega" in body and "rpm" in body:
        pr.add(where, "give omega (rad/s) or rpm, not both")
        return None
    if "rpm" in body:
        rpm = _number(body["rpm"], where + ".rpm", pr, positive=True)
        omega = None if rpm is None else math.pi * rpm / 30.0
    elif "omega" in body:
        omega = _number(body["omega"], where + ".omega", pr, positive=True)
    else:
        pr.add(where + ".omega", "missing: the crank speed, omega in rad/s or rpm")
        omega = None
    if angle is None or omega is None:
        return None
    phi = math.radians(REFERENCES[ref] + SENSES[measured] * angle)
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
