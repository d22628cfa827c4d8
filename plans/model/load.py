"""Reading and validating a mechanism file (TOML): every problem is collected and located
(:mod:`plans.model.fileformat`), then the :class:`~plans.model.mechanism.Mechanism`.

The parts (a link, a guide, the driver) are read by :mod:`plans.model.parts`; here the file
as a whole: its sections in turn, then what follows from them together (every link
attached by two pairs, no joint with two names, the hints, the output).
"""

from __future__ import annotations

import difflib
from pathlib import Path

from plans import tolerances
from plans.errors import InputError
from plans.model.drivers import read_drivers
from plans.model.fileformat import (
    MAX_ABS,
    MAX_TEXT,
    Problems,
    check_keys,
    key_text,
    name_list,
    one_line,
    other_kind,
    quote,
    read_number,
    read_text,
    read_toml,
)
from plans.model.hints import parse_hint
from plans.model.loads import read_drive, read_loads
from plans.model.mechanism import MU_UNIT, Link, Mechanism, Slider
from plans.model.outputs import no_output
from plans.model.parts import (
    link_id,
    link_ids,
    name_fixed_guides,
    name_slots,
    not_a_link,
    one_spelling,
    read_guide,
    read_link,
    read_name,
    read_pair,
    unknown_point,
    xy_text,
)

MAX_LINKS = 200
MAX_FRAME = 200  # fixed points
MAX_POINTS = 1000  # points in all
MAX_ITEMS = 200  # sliders, trace, assembly hints, title fields
SCALE = (1e-9, MAX_ABS)  # μl m/mm, μv (m/s)/mm, μa (m/s²)/mm
#: m: two fixed points closer than this are one place
MIN_LEN = 1e-9
#: the languages a name may be given in
LANGS = ("en", "ru")


def load(path: str | Path) -> Mechanism:
    """Read and validate a mechanism file; every problem is reported, located."""
    data, text = read_toml(path, "a mechanism file is a few KB")
    return from_dict(data, str(path), text=text)


#: the top-level keys of a mechanism file
TOP_KEYS = {"name", "frame", "links", "sliders", "driver", "drivers", "motion", "assembly", "scales",
            "trace", "output", "title", "loads", "drive"}
#: the keys of [driver]: found in [drive], the crank was meant
DRIVER_KEYS = {"link", "angle_deg", "omega", "rpm", "sense", "from", "measured"}


def from_dict(data: dict, source: str = "<mechanism>", *, text: str | None = None) -> Mechanism:
    """Build a :class:`Mechanism` from parsed TOML, reporting every problem at once.

    ``text``: the file's text, to locate each problem to its line.
    """
    pr = Problems(source, text)
    if not isinstance(data, dict):
        raise InputError(source, "the file must be a TOML table")
    if why := other_kind(data, source, "mechanism"):
        raise InputError(source, why)
    check_keys(data, TOP_KEYS, "", pr)
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
        nm = read_name(key, where, pr, named)
        if nm and one_spelling(nm, where, spellings, pr):
            named.add(nm)
            frame_names.add(nm)
        xy = read_pair(value, where, pr)
        if nm and xy is not None:
            frame[nm] = xy
    _coincident(frame, set(frame), "frame", "fixed points", pr)

    # links -------------------------------------------------------------------------
    links: dict[int, Link] = {}
    bad_links: set[int] = set()  # links with a problem of their own: no follow-up messages
    raw_links = data.get("links")
    if not isinstance(raw_links, dict) or not raw_links:
        what = ("missing" if raw_links is None else
                f"must be a table of numbered links, got {quote(raw_links)}")
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
            pr.add(where, f'must be a table with axis and points, e.g. [links.{lid}] axis = ["B", "C"], got '
                          f'{quote(body)}')
            bad_links.add(lid)
            continue
        check_keys(body, {"name", "axis", "points"}, where, pr)
        lname = read_text(body.get("name"), where + ".name", pr, f"link {lid}")
        link, ok = read_link(lid, lname, body, where, pr, named, spellings)
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
        pr.add("sliders", "must be an array of tables, [[sliders]] link = … guide = {…}, got "
                          f"{quote(raw_sliders)}")
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
        lid = link_id(raw_lid)
        if lid is None or lid not in links:
            if lid not in bad_links:
                if raw_lid is None:
                    pr.add(where + ".link", "missing: the number of the sliding link (moving links: "
                                            f"{link_ids(links)})")
                else:
                    pr.add(where + ".link", not_a_link(raw_lid, "a moving link", "moving links: "
                                                                                 f"{link_ids(links)}"))
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
        pairs.append((lid, link_id(raw_guide.get("link", 0)) if isinstance(raw_guide, dict) else None))
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
        guide = read_guide(body.get("guide"), where + ".guide", pr, links, frame, bad_links, point)
        if guide is None or point is None:
            continue
        if guide.link == lid:
            pr.add(where + ".guide.link", f"link {lid} cannot slide on its own guide: name the link that "
                                          "carries the guide (0 = frame)")
            continue
        if link.axis is None and link.points.get(point, 0j) != 0j:
            pr.add(f"links.{lid}.points.{point}", "the sliding point of a link without an axis is its "
                                                  "origin: 0")
            continue
        sliders.append(Slider(lid, guide, point))
    sliders = name_slots(name_fixed_guides(sliders))
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

    # drivers -----------------------------------------------------------------------
    drivers, timing = read_drivers(data, pr, links, frame, bad_links, frame_names if raw_frame else None,
                                   sliders, frozenset(sliding))

    # joints: every link attached by two pairs, no joint with two names ---------------
    raw_drivers = data.get("drivers") if "drivers" in data else [data.get("driver")]
    drv = {link_id(d.get("link", 1)) for d in raw_drivers if isinstance(d, dict)} if isinstance(
        raw_drivers, list) else set()
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
            pr.add(where, unknown_point(k, all_points))
            continue
        on = [lid for lid, link in links.items() if k in link.points]
        fixed = ("a fixed point" if k in frame else
                 "on the crank only" if len(on) == 1 and on[0] in drv else "")
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
        pr.add("scales", "must be a table: [scales] mu_l = 0.01, mu_v = …, mu_a = …, got "
                         f"{quote(raw_scales)}")
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
        pr.add("trace", f'must be a list of at most {MAX_ITEMS} point names, e.g. ["C", "S3"], got '
                        f'{quote(trace)}')
        trace = []
    for i, t in enumerate(trace):
        if not isinstance(t, str):
            pr.add(f"trace[{i}]", f'must be a point name, e.g. "C", got {quote(t)}')
        elif t not in all_points:
            pr.add(f"trace[{i}]", unknown_point(t, all_points))
    trace = [t for t in trace if isinstance(t, str) and t in all_points]
    output = data.get("output")
    if output is not None:
        if not isinstance(output, str):
            pr.add("output", f'must be a point name, e.g. "C", got {quote(output)}')
            output = None
        elif output not in all_points:
            pr.add("output", unknown_point(output, all_points))
    title = data.get("title", {})
    if not isinstance(title, dict) or len(title) > MAX_ITEMS:
        pr.add("title", f"must be a table of texts for the title block, got {quote(title)}")
        title = {}
    for k, v in title.items():
        if isinstance(v, bool) or not isinstance(v, str | int):
            pr.add(f"title.{key_text(k)}", f"must be a text, got {quote(v)}")
    title = {str(k)[:MAX_TEXT]: str(v)[:500] for k, v in title.items()
             if isinstance(v, str | int) and not isinstance(v, bool)}
    loads = drive = None
    if "loads" in data:
        loads = read_loads(data["loads"], {lid: set(link.points) for lid, link in links.items()}, pr,
                           sliding=frozenset(s.link for s in sliders))
    raw_drive = data.get("drive")
    if isinstance(raw_drive, dict) and "driver" not in data and raw_drive.keys() & DRIVER_KEYS:
        # [drive] for [driver]: the crank's keys in the gearbox's table
        pr.add("drive", f'unknown key — did you mean "driver"? known: {", ".join(sorted(TOP_KEYS))}')
    elif "drive" in data:
        drive = read_drive(raw_drive, pr)

    pr.raise_if_any()
    assert drivers
    mech = Mechanism(
        name=name,
        frame=frame,
        links=links,
        sliders=tuple(sliders),
        driver=drivers[0],
        more_drivers=drivers[1:],
        timing=timing,
        assembly=hints,
        scales=scales,
        trace=tuple(trace),
        output=output,
        title=title,
        source=source,
        names=names,
        loads=loads,
        drive=drive,
    )
    if output is not None:  # a point with no stroke was silently replaced by another
        if (why := no_output(mech, output)) is not None:
            pr.add("output", why)
            pr.raise_if_any()
    return mech


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
                       f'{what} "{cells[key]}" and "{n}" are at the same place {xy_text(z)}: one joint has '
                       'one name')
            cells.setdefault(key, n)
        return
    for i, a in enumerate(names):
        for b in names[i + 1:]:
            if abs(points[a] - points[b]) < tol:
                pr.add(
                    f"{where}.{b}" if where == "frame" else where,
                    f'{what} "{a}" and "{b}" are at the same place {xy_text(points[b])}: a '
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
        _coincident(link.points, joints, f"links.{lid}.points", f"joints of link {lid}", pr, tolerances.SAME)
        if lid in drv:
            continue
        pairs = [f'"{n}"' for n in sorted(joints)] + slides[lid]
        if len(pairs) >= 2:
            continue
        free = [n for n in link.points if len(carriers[n]) == 1]
        others = {n for n, c in carriers.items() if c != [lid]}
        what = (f"link {lid} is not connected to anything" if not pairs
                else f"link {lid} is attached by one pair only ({pairs[0]})")
        need = ("a link of a mechanism is attached by at least two pairs (joints named on two links, "
                "or a slider)")
        if link.axis and link.axis[0] in free:
            why = f"it is on no other link and not in [frame], so {what}"
            pr.add(f"links.{lid}.axis[0]", unknown_point(link.axis[0], others, why))
        elif free and others:
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


