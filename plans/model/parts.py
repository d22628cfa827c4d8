"""Reading the parts of a mechanism file: one link, one guide, the driver, and the names
the tool gives the guides a file leaves unlabelled; with the file's limits.

Each reader adds every problem it finds to the file's :class:`~plans.model.fileformat.Problems`
and returns None (or a part marked bad) where it cannot go on, so that
:func:`plans.model.load.from_dict` reports every problem of a file at once.
"""

from __future__ import annotations

import itertools
import math
import re
from dataclasses import replace
from typing import Any

from plans import tolerances
from plans.geometry import cross
from plans.model.fileformat import (
    MAX_ABS,
    Problems,
    check_keys,
    close_match,
    key_text,
    name_list,
    quote,
    read_number,
)
from plans.model.mechanism import Guide, Link, Slider

#: the point names whose plan letters would be the plans' own (the pole p, n1, k): no
#: longer refused, they are written with a prime on the plans (p′, n1′, k′:
#: :func:`plans.plan.values.plan_name`)
RESERVED = re.compile(r"^(P|PI|Pi|N\d+|K\d*)$")
POINT_NAME = re.compile(r"^[A-Z][A-Za-z0-9_']{0,11}$")
MAX_LINK_POINTS = 200  # points on one link
MIN_LINK = 1e-6  # m: the shortest link (a micrometre)
SPEED = (1e-6, MAX_ABS)  # rad/s, rpm
#: the slowest crank in rpm: the slowest in rad/s (1e-6 rpm had passed as 1e-7 rad/s)
RPM_MIN = SPEED[0] * 30.0 / math.pi


def unknown_point(name: str, known, why: str = "") -> str:
    guess = close_match(name, known, cutoff=0.5)
    why = f": {why}" if why else ""
    return f"unknown point {quote(name)}{why} — {guess}known points: {name_list(known)}"


def read_pair(value: Any, where: str, problems: Problems) -> complex | None:
    if not (isinstance(value, list) and len(value) == 2):
        problems.add(where, f"must be [x, y] in metres, got {quote(value)}")
        return None
    x = read_number(value[0], where + "[0]", problems)
    y = read_number(value[1], where + "[1]", problems)
    return None if x is None or y is None else complex(x, y)


def read_name(value: Any, where: str, problems: Problems, named: set[str]) -> str | None:
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
    return value


def one_spelling(nm: str, where: str, spellings: dict[str, str], pr: Problems) -> bool:
    """False (with the problem) for a name that differs from another only in case: the
    plans write points in lower case (C → c), so EF and Ef would be one plan point."""
    other = spellings.setdefault(nm.lower(), nm)
    if other == nm:
        return True
    pr.add(where, f'"{nm}" and "{other}" differ only in case, and the plans write both as '
                  f'"{nm.lower()}": rename one')
    return False


def link_ids(links) -> str:
    return ", ".join(str(i) for i in sorted(links)) or "none"


def xy_text(z: complex) -> str:
    return f"[{z.real:g}, {z.imag:g}]"


def link_id(value: Any) -> int | None:
    return value if isinstance(value, int) and not isinstance(value, bool) else None


def not_a_link(value: Any, what: str, known: str) -> str:
    """The message for a link number that is not one (and for "3", which is not 3)."""
    if isinstance(value, str) and value.strip().isdigit() and len(value) < 10:
        return f"{quote(value, 20)} is text: write the number without quotes, {value.strip()} ({known})"
    if isinstance(value, float) and value.is_integer() and abs(value) < 1e9:
        return f"{value!r} is written as a decimal: a link's number is written {int(value)} ({known})"
    return f"{quote(value, 20)} is not {what} ({known})"


def read_link(lid: int, lname: str, body: dict, where: str, pr: Problems, named: set[str],
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
            a0 = read_name(axis[0], where + ".axis[0]", pr, named)
            a1 = read_name(axis[1], where + ".axis[1]", pr, named)
            a0 = a0 if a0 and one_spelling(a0, where + ".axis[0]", spellings, pr) else None
            a1 = a1 if a1 and one_spelling(a1, where + ".axis[1]", spellings, pr) else None
            named |= {a for a in (a0, a1) if a}
            axis = (a0, a1) if a0 and a1 else None
            if axis and a0 == a1:
                pr.add(where + ".axis", f'zero-length link: both ends of the axis are "{a0}"; an axis runs '
                                        'between two points')
                axis = None
            if axis:
                points[a0] = 0j
    raw_points = body.get("points", {})
    if not isinstance(raw_points, dict):
        pr.add(where + ".points", "must be a table, e.g. points = { C = 0.75, S3 = [0.25, 0.02] }, got "
                                  f"{quote(raw_points)}")
        raw_points = {}
    if len(raw_points) > MAX_LINK_POINTS:
        pr.add(where + ".points", f"{len(raw_points)} points on one link: at most {MAX_LINK_POINTS}")
        return Link(lid, lname, points, axis), False
    failed: set[str] = set()
    for pname, spec in raw_points.items():
        pw = f"{where}.points.{key_text(pname)}"
        nm = read_name(pname, pw, pr, named)
        if nm is None or not one_spelling(nm, pw, spellings, pr):
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
                pr.add(pw, f'zero-length link: the axis end "{a1}" is at the origin "{a0}"; give the length '
                           f'{a0}{a1} in metres')
            elif end.imag != 0:
                pr.add(pw, f'the axis end "{a1}" must lie on the axis: give its distance, {a1} = '
                           f'{abs(end):g}, not {xy_text(end)}')
            elif end.real < 0:
                pr.add(pw, negative_end(lid, a0, a1, end.real, points))
            elif end.real < MIN_LINK:
                pr.add(pw, f"link length {end.real:g} m: zero or too short, a link is at least "
                           f"{MIN_LINK:g} m")
    if not points and not failed and len(pr.items) == before:
        pr.add(where, 'has no points: give axis = ["B", "C"] and points = { C = 0.3 }')
    return Link(lid, lname, points, axis), len(pr.items) == before


def negative_end(lid: int, a0: str, a1: str, end: float, points: dict[str, complex]) -> str:
    """The problem of an axis end given behind its origin. An axis runs from its origin to
    its end, so the end lies at a positive distance; writing it positive alone would leave
    the link's other points, measured along the reversed direction, on the other side of
    the pivot: their signs change with it, and the message says to what.

    >>> print(negative_end(3, "D", "C", -0.1, {"D": 0j, "C": -0.1, "S3": -0.05, "E": -0.2 + 0.01j}))
    negative length -0.1: an axis runs from its origin D to its end C, so C lies at +0.1
    along it and every other point of link 3 is measured along D→C: write C = 0.1 and the
    other points with both signs changed (S3 = 0.05, E = [0.2, -0.01]), or the link turns
    to the other side of D
    """
    others = [(n, z) for n, z in points.items() if n not in (a0, a1)]
    head = (f"negative length {end:g}: an axis runs from its origin {a0} to its end {a1}, so {a1} lies "
            f"at +{-end:g} along it and every other point of link {lid} is measured along {a0}→{a1}: "
            f"write {a1} = {-end:g}")
    if not others:
        return head
    said = ", ".join(f"{n} = {-z.real + 0.0:g}" if z.imag == 0 else
                     f"{n} = {xy_text(complex(-z.real + 0.0, -z.imag + 0.0))}"
                     for n, z in others[:4]) + (", …" if len(others) > 4 else "")
    return (f"{head} and the other points with both signs changed ({said}), or the link turns to "
            f"the other side of {a0}")


#: names of fixed guides, in the order an inclined one takes them
FIXED_NAMES = ("x-x", "y-y", "z-z", "u-u", "w-w")


def parallel(a: complex, b: complex) -> bool:
    return abs(cross(a, b)) <= tolerances.AXIAL


def free_name(candidates, taken: dict[str, complex], direction: complex) -> str:
    """The first of ``candidates`` not ``taken`` by a guide of another direction (parallel
    guides may share a name: a plan's line only says "∥ x-x"); it is then taken."""
    name = next(n for n in candidates if n not in taken or parallel(taken[n], direction))
    taken.setdefault(name, direction)
    return name


def name_fixed_guides(sliders: list[Slider]) -> list[Slider]:
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
        name = free_name((*FIXED_NAMES, g.label), taken, g.direction)
        out[i] = replace(out[i], guide=replace(g, label=name))
    return out


def name_slots(sliders: list[Slider]) -> list[Slider]:
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
        name = free_name((f"x{g.link}{m}-x{g.link}{m}" for m in marks),
                          taken.setdefault(g.link, {}), g.direction)
        out[i] = replace(out[i], guide=replace(g, label=name))
    return out


def read_guide(body, where, pr: Problems, links, frame, bad_links, slides: str | None = None
           ) -> Guide | None:
    """The guide of a [[sliders]] entry whose point ``slides`` runs along it.

    Without a ``label`` it is named by notation, never by a word, so that a Russian sheet
    says what an English one does: x-x or y-y on the frame (an inclined fixed guide
    too is the slider's axis x-x, see :func:`name_fixed_guides`); on a link, its axis
    (along it), "⊥ DE" (across it), else the line through a named point of the link and
    the sliding point ("DA"), or x3-x3 for link 3 when no named point lies on it.
    """
    if not isinstance(body, dict):
        got = "missing" if body is None else f"must be a table, got {quote(body)}"
        pr.add(where, f"{got}: e.g. guide = {{ link = 0, through = [0, 0.35], angle_deg = 0 }} or {{ link = "
                      "3 }")
        return None
    check_keys(body, {"link", "through", "angle_deg", "direction", "offset", "label"}, where, pr)
    raw = body.get("link", 0)
    gl = link_id(raw)
    if gl is None or (gl != 0 and gl not in links):
        if gl not in bad_links:
            pr.add(where + ".link", not_a_link(raw, "a link", f"0 = frame; moving: {link_ids(links)}"))
        return None
    if gl in bad_links:
        return None
    if "direction" in body:
        if "angle_deg" in body:
            pr.add(where, "give angle_deg or direction, not both")
            return None
        d = read_pair(body["direction"], where + ".direction", pr)
        if d is None:
            return None
        if abs(d) < tolerances.SAME:
            pr.add(where + ".direction", f"guide direction of zero length {xy_text(d)}: give a vector along "
                                         "the guide, e.g. [1, 0]")
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
                pr.add(where + ".through", f"{quote(through)} is not a fixed point (fixed points: "
                                           f"{name_list(frame)}); or give [x, y]")
                return None
            point = frame[through]
        elif through is None:
            pr.add(where + ".through", "missing: a point of the guide, [x, y] or a fixed point name")
            return None
        else:
            point = read_pair(through, where + ".through", pr)
            if point is None:
                return None
        default_label = "y-y" if abs(direction.real) < tolerances.AXIAL else "x-x"
    else:
        link = links[gl]
        if link.axis is None:
            pr.add(where + ".link", f"link {gl} has no axis to carry a guide: give it an axis, or let the "
                                    "guide be on another link")
            return None
        if isinstance(through, str):
            if through not in link.points:
                pr.add(where + ".through", f"{quote(through)} is not a point of link {gl} (its points: "
                                           f"{name_list(link.points)})")
                return None
            point = link.points[through]
        elif through is None:
            point = 0j
        else:
            point = read_pair(through, where + ".through", pr)
            if point is None:
                return None
    point = point + offset * 1j * direction
    if gl != 0:
        # the link's own x-axis runs along its axis: a guide along it or across it is
        # named by it, any other by a named point on it and the point sliding along it
        axis = "".join(link.axis)
        on = [n for n, q in link.points.items()
              if n != slides and abs(((q - point) * direction.conjugate()).imag) < tolerances.SAME]
        default_label = (axis if abs(direction.imag) < tolerances.AXIAL else f"⊥ {axis}"
                         if abs(direction.real) < tolerances.AXIAL
                         else f"{on[0]}{slides}" if on and slides else f"x{gl}-x{gl}")
    if label is not None and (not isinstance(label, str) or len(label) > 20):
        pr.add(where + ".label", 'must be a short text (at most 20 characters), e.g. "x-x", got '
                                 f'{quote(label)}')
        label = None
    return Guide(gl, point, direction, label or default_label, named_by_tool=not label)

