"""The views of sheet 1: plan of positions, velocity and acceleration plans,
kinematic diagrams and tables, each built in its own box of sheet millimetres.

A view is drawn with its top-left corner at (0, 0); :mod:`drawing.sheet.layout` moves
it to its place on the sheet with a :class:`~drawing.scene.Group` offset.  The
plans are drawn at exactly one sheet millimetre per plan millimetre (the
engine's μv, μa), and every plan vector is a group of class ``vec v-pa3`` /
``vec a-πa3`` so that its length can be measured on the SVG.

Labels of a view are placed with :func:`drawing.labels.place_labels` against
the view's own lines (``obstacles_of``) and kept inside the view's box, so no
label of one view can meet another view.
"""

from __future__ import annotations

import itertools
import math
from dataclasses import dataclass, field

import numpy as np
import shapely
from shapely.geometry import Polygon
from shapely.geometry import box as shp_box

from drawing.labels import LabelRequest, obstacles_of, place_labels
from drawing.scene import (
    Arrow,
    Blank,
    Circle,
    Group,
    Hatch,
    Item,
    Polyline,
    Segment,
    Text,
    flatten,
    index_markup,
    name_markup,
    shared_label,
    translate,
)
from drawing.styles import LineType, Style
from drawing.text import LINE_PITCH, SLANT, text_box, text_width, wrap_words
from plans.cycle.analysis import at_rest
from plans.cycle.positions import drawn
from plans.fmt import notation_in, num
from plans.plan.solution import image_sides

__all__ = [
    "View",
    "diagrams_view",
    "note_view",
    "omega_table_view",
    "plan_view",
    "positions_view",
    "segments_table_view",
]

PAD = 6.0  # room around a drawing inside its view box, for labels
CAPTION = 5.0  # caption size, mm
#: mm: a caption wider than its drawing by more than this is set at SMALL_CAPTION, so
#: that a small plan's view is not as wide as its long title ("План скоростей
#: (положение 2, φ1 = 210°), μv = 0,02 (м/с)/мм" is 190 mm at 5 mm), or on two lines
#: at CAPTION (:func:`retitled`: a sheet gives all its titles one size)
CAPTION_OVER = 20.0
SMALL_CAPTION = 3.5
#: how a view's caption is set (:func:`caption_lines`): "fit", at CAPTION, or at
#: SMALL_CAPTION where that is much wider than the drawing; "wrap", at CAPTION, on two
#: lines where one is much wider; "small", at SMALL_CAPTION
CAPTION_STYLES = ("fit", "wrap", "small")
LETTER = 3.5  # letters of points, mm
JOINT_R = 1.0
BLANK_PAD = 0.5  # the break in thin lines around a dimension's value, mm
#: mm: plan points closer than this share one label ("g₁,g₃"); two labels side by side
#: would read as one word ("g₁g₃")
SHARED = 2.0
HEAD = {"head_len": 3.5, "head_width": 1.0}

WORDS = {
    "ru": {
        "positions": "План положений",
        "velocity": "План скоростей",
        "acceleration": "План ускорений",
        "diagrams": "Кинематические диаграммы",
        "segments": "Отрезки планов",
        "angular": "Угловые скорости и ускорения",
        "segment": "Отрезок",
        "mm": "мм",
        "value": "Величина",
        "link": "Звено",
        "position": "положение",
        "m": "м",
        "stroke": "H",
        "swing": "ψ",
        "no_diagrams": "Диаграммы не строятся: ",
        "left_off": "Положения {k} не показаны: в них точки механизма удаляются более чем на {d} м",
        "rad": "рад",
        "deg": "°",
        "ms": "м/с",
        "ms2": "м/с²",
        "rads": "рад/с",
        "rads2": "рад/с²",
        "ccw": "против ч.с.",
        "cw": "по ч.с.",
    },
    "en": {
        "positions": "Plan of positions",
        "velocity": "Velocity plan",
        "acceleration": "Acceleration plan",
        "diagrams": "Kinematic diagrams",
        "segments": "Plan segments",
        "angular": "Angular velocities and accelerations",
        "segment": "Segment",
        "mm": "mm",
        "value": "Value",
        "link": "Link",
        "position": "position",
        "m": "m",
        "stroke": "H",
        "swing": "ψ",
        "no_diagrams": "No diagrams: ",
        "left_off": "Positions {k} not shown: points of the mechanism run farther than {d} m out",
        "rad": "rad",
        "deg": "°",
        "ms": "m/s",
        "ms2": "m/s²",
        "rads": "rad/s",
        "rads2": "rad/s²",
        "ccw": "ccw",
        "cw": "cw",
    },
}


@dataclass
class View:
    """Items in local sheet mm, box (0, 0)–(w, h)."""

    name: str
    items: list[Item] = field(default_factory=list)
    w: float = 0.0
    h: float = 0.0
    #: mm: the drawing with its letters, without the caption and the lines under it
    #: (what grows with the scale); and the width those texts need whatever the scale
    body: tuple[float, float] = (0.0, 0.0)
    texts: tuple[float, float] = (0.0, 0.0)  # the caption's width, the widest line under
    caption: str = ""
    #: mm: the caption's letters (0 where there is none)
    caption_size: float = 0.0
    #: what the view is made of, to set its caption anew (:func:`retitled`): (its
    #: drawing, the lines under it) and the box the caption stands over
    parts: tuple = field(default=(), repr=False)


def notation(s: str) -> str:
    """Engine notation as Text markup: ``V_A3A`` → ``V_{A3A}``, ``a^n_A3B`` → ``a^n_{A3B}``."""
    return index_markup(s).replace("∥", "||")


def centred(pos, text: str, size: float, baseline: str = "alphabetic", stretch: float = 1.0) -> Text:
    """A text centred on ``pos``, written start-anchored (indices keep their place)."""
    t = Text(pos, text, size=size, anchor="middle", baseline=baseline, markup=True, stretch=stretch)
    x0 = text_box(t).bounds[0]
    return Text((x0, pos[1]), text, size=size, anchor="start", baseline=baseline, markup=True,
                stretch=stretch)


def _start_anchored(t: Text) -> Text:
    """The same text written from its start: SVG renderers misplace indices
    (``tspan`` with ``dy``) of middle- or end-anchored text."""
    if t.anchor == "start" or not t.markup or all(r.level == 0 for r in t.runs()):
        return t
    from dataclasses import replace

    x0 = text_box(t).bounds[0]
    return replace(t, pos=(x0, t.pos[1]), anchor="start")


def _shift(items: list[Item], dx: float, dy: float) -> list[Item]:
    """Moved by (dx, dy); a group keeps its class, its contents are moved."""
    from dataclasses import replace

    return [
        replace(it, items=tuple(_shift(list(it.items), dx, dy))) if isinstance(it, Group)
        else translate(it, dx, dy)
        for it in items
    ]


def _coords(items: list[Item]) -> list[tuple[float, float]]:
    """The corners of everything drawn: line ends, polyline vertices, circles' and texts'
    boxes."""
    out: list[tuple[float, float]] = []
    for it in flatten(items):
        if isinstance(it, Text):
            b = text_box(it).bounds
            out += [(b[0], b[1]), (b[2], b[3]), (b[0], b[3]), (b[2], b[1])]
        elif isinstance(it, Circle):
            (x, y), r = it.center, it.r
            out += [(x - r, y - r), (x + r, y + r)]
        elif isinstance(it, Polyline):
            out += list(it.points)
        else:
            out += [it.p1, it.p2]
    return out


def _bbox(items: list[Item]) -> tuple[float, float, float, float]:
    xs, ys = zip(*_coords(items), strict=True)
    return min(xs), min(ys), max(xs), max(ys)


def _shared(points) -> list[tuple[tuple[float, float], list[str]]]:
    """(sheet point, name) pairs grouped into one label each where closer than
    :data:`SHARED` to the group's first point ("c,n₂"), in order."""
    groups: list[tuple[tuple[float, float], list[str]]] = []
    for xy, name in points:
        same = next((g for g in groups if math.dist(g[0], xy) < SHARED), None)
        if same is None:
            groups.append((xy, [name]))
        else:
            same[1].append(name)
    return groups


def _per_mm(unit: str, lang: str) -> str:
    """A scale factor's unit: "(м/с)/мм", "рад/мм"."""
    mm = WORDS[lang]["mm"]
    return f"({unit})/{mm}" if "/" in unit else f"{unit}/{mm}"


def _finish(
    name: str,
    drawing: list[Item],
    labels: list[LabelRequest],
    caption: str,
    under: list[str] = (),
    pad: float = PAD,
    over: list[Item] = (),
    sizing: bool = False,
) -> View:
    """Frame ``drawing`` with room for its labels, letter it, caption on top,
    ``under`` (equations) below; shift everything to the box (0, 0)–(w, h). ``over``:
    thin lines that no break cuts (a dimension's own arc), drawn after the breaks.
    ``sizing``: no letters placed, the view as large as they could make it (they stay
    within ``pad`` of the drawing), for a sheet that tries many scales."""
    drawing = list(drawing)
    x0, y0, x1, y1 = _bbox(drawing + list(over))
    region = shp_box(x0 - pad, y0 - pad, x1 + pad, y1 + pad)
    if sizing:
        return _captioned(name, list(drawing) + list(over), region.bounds, caption, under)
    thin = (LineType.THIN, LineType.DASHED, LineType.DASH_DOUBLE_DOT_THIN)
    is_soft = [isinstance(it, Segment | Polyline) and it.line in thin for it in drawing]
    drawing += over
    is_soft += [False] * len(over)
    placed = place_labels(labels,
                          obstacles_of([it for it, s in zip(drawing, is_soft, strict=True) if not s]),
                          region=region, distances=(1.0, 2.0, 3.0, 4.5, 6.0, 8.0),
                          soft=obstacles_of([it for it, s in zip(drawing, is_soft, strict=True) if s])
                          ) if labels else []  # the diagrams: nothing to letter
    texts = [_start_anchored(p.text) for p, r in zip(placed, labels, strict=True)
             if p.clear or p.leader or not r.optional]  # numbers of positions: dropped
    leaders = [_leader(*p.leader) for p in placed if p.leader]
    drawing += leaders
    is_soft += [True] * len(leaders)
    blanks = [Blank((x0 - BLANK_PAD, y0 - BLANK_PAD), (x1 + BLANK_PAD, y1 + BLANK_PAD))
              for p, r in zip(placed, labels, strict=True) if r.blank
              for x0, y0, x1, y1 in [p.box.bounds]]
    if blanks:  # thin lines, the breaks in them, then the lines a break must not hide
        drawing = ([it for it, s in zip(drawing, is_soft, strict=True) if s] + blanks
                   + [it for it, s in zip(drawing, is_soft, strict=True) if not s])
    items = list(drawing) + texts
    return _captioned(name, items, _bbox(items), caption, under)


def _leader(point, end) -> Segment:
    """A thin leader line from near ``point`` (clear of its dot) to a label's box."""
    d = math.dist(point, end)
    k = min(0.8, d / 2) / d if d > 0 else 0.0
    start = (point[0] + (end[0] - point[0]) * k, point[1] + (end[1] - point[1]) * k)
    return Segment(start, end, LineType.THIN)


def _captioned(name: str, items: list[Item], bounds, caption: str, under: list[str]) -> View:
    """The view of ``items`` (within ``bounds``) under ``caption``, ``under`` below."""
    x0, _y0, _x1, y1 = bounds
    lines = []
    y = y1 + 2.0
    for line in under:
        y += 3.5 + 2.0
        lines.append(Text((x0, y), notation(line), size=2.5, markup=True, baseline="alphabetic"))
    return _assembled(name, (items, lines), bounds, caption, "fit")


def _assembled(name: str, parts: tuple[list[Item], list[Text]], bounds, caption: str,
               style: str) -> View:
    """The view of ``parts`` (the drawing within ``bounds``, the lines under it) with
    ``caption`` over ``bounds`` set as ``style`` says (:data:`CAPTION_STYLES`), in its
    box."""
    x0, y0, x1, y1 = bounds
    drawing, under = parts
    items = [*drawing, *caption_texts(caption, x0, x1, y0, style), *under]
    bx0, by0, bx1, by1 = _bbox(items)
    bx0, by0, bx1, by1 = min(bx0, x0), min(by0, y0), max(bx1, x1), max(by1, y1)
    size = items[len(drawing)].size
    items = _shift(items, -bx0 + 1, -by0 + 1)
    widest = max([0.0, *(text_box(t).bounds[2] - x0 for t in under)])
    return View(name, items, bx1 - bx0 + 2, by1 - by0 + 2, (x1 - x0, y1 - y0),
                (_width(centred((0, 0), caption, CAPTION)), widest), caption, size,
                (parts, bounds))


def retitled(view: View, style: str) -> View:
    """``view`` with its caption set as ``style`` says (:data:`CAPTION_STYLES`): the
    drawing, its letters and the lines under it as they were."""
    if not view.parts:
        return view
    return _assembled(view.name, *view.parts, view.caption, style)


def caption_lines(caption: str, width: float, style: str = "fit") -> tuple[float, list[str]]:
    """(letter size, lines) of a caption over a drawing ``width`` mm wide, set as
    ``style`` says (:data:`CAPTION_STYLES`)."""
    if style == "small":
        return SMALL_CAPTION, [caption]
    if _caption_at(_width(centred((0, 0), caption, CAPTION)), width) == CAPTION:
        return CAPTION, [caption]
    return (CAPTION, _broken(caption)) if style == "wrap" else (SMALL_CAPTION, [caption])


def _broken(caption: str) -> list[str]:
    """``caption`` on two lines: broken after a comma outside brackets, before the scale
    factor ("План ускорений (φ1 = 60°)," / "μa = 0,1 (м/с²)/мм"), else at the space
    outside brackets that makes its longer line shortest; one line where it has
    neither."""
    depth, commas, spaces = 0, [], []
    for i, c in enumerate(caption):
        depth += (c in "([{") - (c in ")]}")
        if c == " " and depth == 0:
            (commas if caption[i - 1] == "," else spaces).append(i)

    def longer(i):
        return max(_width(centred((0, 0), part, CAPTION)) for part in (caption[:i], caption[i + 1:]))

    cuts = commas[-1:] or spaces
    if not cuts:
        return [caption]
    i = min(cuts, key=longer)
    return [caption[:i], caption[i + 1:]]


def caption_texts(caption: str, x0: float, x1: float, y0: float, style: str = "fit") -> list[Text]:
    """The caption's lines (:func:`caption_lines`) centred over ``x0``–``x1``, the last
    1.5 mm above ``y0``, each :data:`~drawing.labels.LINE_PITCH` under the one before."""
    size, lines = caption_lines(caption, x1 - x0, style)
    out = []
    for k, line in enumerate(lines):
        cap = centred(((x0 + x1) / 2, y0), line, size)
        below = (len(lines) - 1 - k) * size * LINE_PITCH  # the lines under this one
        out.append(translate(cap, 0.0, y0 - 1.5 - below - text_box(cap).bounds[3]))
    return out


def _caption_at(wide: float, width: float) -> float:
    """The caption's size, ``wide`` mm at :data:`CAPTION`, over a drawing ``width`` wide."""
    return CAPTION if wide <= width + CAPTION_OVER else SMALL_CAPTION


def captioned_width(body: float, caption: float, under: float) -> float:
    """The width :func:`_captioned` gives a view whose drawing is ``body`` mm wide, its
    caption ``caption`` mm at :data:`CAPTION` (set at :data:`SMALL_CAPTION` where that is
    much wider than the drawing) and the widest line under it ``under`` mm: the caption
    centred on the drawing, the lines from its left, 1 mm of margin each side."""
    caption *= _caption_at(caption, body) / CAPTION
    return max(body, (body + caption) / 2, under) - min(0.0, (body - caption) / 2) + 2.0


def _width(t: Text) -> float:
    b = text_box(t).bounds
    return b[2] - b[0]


# ----------------------------------------------------------------- plans


def _plan_xy(value: complex, mu: float) -> tuple[float, float]:
    z = value / mu
    return (z.real, -z.imag)


def plan_view(sol, kind: str, tag: str, lang: str = "ru", label: str | None = None,
              sizing: bool = False) -> View:
    """The velocity (``kind="velocity"``) or acceleration plan of ``sol``.

    ``tag`` distinguishes the position (``"3"``) in the ids of its vectors.
    """
    plan = sol.velocity if kind == "velocity" else sol.acceleration
    mu = plan.mu
    pts = {n: _plan_xy(p.value, mu) for n, p in plan.points.items()}
    pts.setdefault(plan.pole, (0.0, 0.0))
    items: list[Item] = []
    letter = "v" if kind == "velocity" else "a"
    # construction lines of the intersections, thin, under the vectors
    for p in plan.points.values():
        if p.source.kind != "intersection":
            continue
        for line in p.source.lines:
            if line.through not in pts:
                continue
            tx, ty = pts[line.through]
            dx, dy = line.direction.real, -line.direction.imag
            px, py = pts[p.name]
            t = (px - tx) * dx + (py - ty) * dy
            a, b = min(0.0, t) - 6.0, max(0.0, t) + 6.0
            items.append(
                Segment((tx + a * dx, ty + a * dy), (tx + b * dx, ty + b * dy), LineType.THIN)
            )
    # the link's image each similarity point is found on, thin: bc on to e of a coupler
    # BCE, the sides be, ce of a triangle
    items += [Segment(_plan_xy(a, mu), _plan_xy(b, mu), LineType.THIN)
              for a, b in image_sides(plan)]
    # the vectors
    for v in plan.vectors:
        p1, p2 = pts[v.start], pts[v.end]
        if math.dist(p1, p2) < 1e-6:
            continue
        arrow = Arrow(p1, p2, LineType.MAIN, **HEAD)
        items.append(Group((arrow,), name=f"vec {letter}-{v.start}{v.end}-{tag}"))
    # the points: pole dot, joints of the letters; coincident points share a label
    groups = _shared(
        (pts[name], name) for name in [plan.pole, *[n for n in plan.points if n != plan.pole]])
    items.append(Circle(pts[plan.pole], 0.6, LineType.MAIN, fill="black"))
    # prefer the side away from the pole
    cx = sum(x for x, _ in pts.values()) / len(pts)
    cy = sum(y for _, y in pts.values()) / len(pts)
    reqs = []
    for xy, names in groups:
        ang = math.degrees(math.atan2(-(xy[1] - cy), xy[0] - cx)) % 360
        prefer = ("e", "ne", "n", "nw", "w", "sw", "s", "se")[int(((ang + 22.5) % 360) // 45)]
        reqs.append(LabelRequest(xy, shared_label(names, plan.pole), LETTER, prefer,
                                 blank=True, cross=False))
    title = WORDS[lang][kind]
    unit = _per_mm(WORDS[lang]["ms" if kind == "velocity" else "ms2"], lang)
    mu_name = "μ_v" if kind == "velocity" else "μ_a"
    caption = f"{title} ({label or tag}), {mu_name} = {num(mu, 4, lang)} {unit}"
    eqs: list[str] = []
    for p in plan.points.values():
        if p.source.kind == "intersection" and p.source.equation:
            eqs.append(notation_in(p.source.equation, lang))
    return _finish(f"{kind}-{tag}", items, reqs, caption, eqs, sizing=sizing)


# ----------------------------------------------------------------- positions


def _sheet(z: complex, mu_l: float) -> tuple[float, float]:
    return (z.real / mu_l, -z.imag / mu_l)


def _centre_of_mass(mech, name: str) -> bool:
    """S1, S2 …: a centre of mass, marked on its link but not drawn as a bar of it;
    never a point where a pair is (a hinge, a slider's point) nor an axis end."""
    if not (name[0] == "S" and name[1:].isdigit() and len(mech.links_of(name)) == 1):
        return False
    return (all(s.point != name for s in mech.sliders)
            and all(name not in (link.axis or ()) for link in mech.links.values()))


def _link_segments(mech, pos: dict[str, complex], mu_l: float, line: LineType) -> list[Item]:
    out: list[Item] = []
    slider_links = {s.link for s in mech.sliders}
    for lid, link in mech.links.items():
        names = [n for n in link.points if n in pos and not _centre_of_mass(mech, n)]
        if lid in slider_links and len(names) <= 1:
            continue
        if link.axis and link.axis[0] in pos:
            root = link.axis[0]
        elif names:
            root = names[0]
        else:
            continue
        # the farthest point first, so a point on the axis does not make a stub
        for n in names:
            if n != root and abs(pos[n] - pos[root]) > 1e-12:
                out.append(Segment(_sheet(pos[root], mu_l), _sheet(pos[n], mu_l), line))
        # a rigid link of three points or more not in line is a plate: its outline closed
        # (the coupler ABE is a triangle, not the bars AB and AE)
        hull = _hull([pos[n] for n in names])
        if len(hull) >= 3:  # the sides the bars from the root do not draw
            out += [Segment(_sheet(a, mu_l), _sheet(b, mu_l), line)
                    for a, b in zip(hull, hull[1:] + hull[:1], strict=True)
                    if pos[root] not in (a, b)]
    return out


def _hull(points: list[complex]) -> list[complex]:
    """The corners of the convex hull of ``points``, counter-clockwise; fewer than three
    where they are in line (within 1e-9 of their spread: a coupler point on the link's
    axis, as computed, makes no plate, which shapely's exact hull would)."""
    pts = sorted(set(points), key=lambda z: (z.real, z.imag))
    if len(pts) < 3:
        return pts
    spread = max(abs(p - q) for p in pts for q in pts)

    def turn(o, a, b):  # twice the signed area of o, a, b, over the spread
        return ((a - o).conjugate() * (b - o)).imag / spread

    def half(seq):
        chain: list[complex] = []
        for p in seq:
            while len(chain) >= 2 and turn(chain[-2], chain[-1], p) <= 1e-9 * spread:
                chain.pop()
            chain.append(p)
        return chain

    lower, upper = half(pts), half(reversed(pts))
    hull = lower[:-1] + upper[:-1]
    return hull if len(hull) >= 3 else []


def _block(center: tuple[float, float], direction: complex, line: LineType,
           w: float = 8.0, h: float = 5.0) -> Polyline:
    """A slider / slide block: a small rectangle along ``direction`` (model)."""
    ux, uy = direction.real, -direction.imag
    n = math.hypot(ux, uy) or 1.0
    ux, uy = ux / n, uy / n
    vx, vy = -uy, ux
    cx, cy = center
    corners = [
        (cx + sx * ux * w / 2 + sy * vx * h / 2, cy + sx * uy * w / 2 + sy * vy * h / 2)
        for sx, sy in ((-1, -1), (1, -1), (1, 1), (-1, 1))
    ]
    return Polyline(corners, line, closed=True)


def _guide_dir(mech, slider, pos) -> complex:
    """The guide's direction in the world: its own direction turned with its link."""
    g = slider.guide
    if g.link == 0:
        return g.direction
    pose = _pose(mech, g.link, pos)
    return g.direction if pose is None else pose[1] * g.direction


def _pose(mech, lid: int, pos) -> tuple[complex, complex] | None:
    """(origin, rotor) of a link with an axis, from its axis points' positions."""
    link = mech.links[lid]
    if not (link.axis and all(a in pos for a in link.axis)):
        return None
    d = pos[link.axis[1]] - pos[link.axis[0]]
    return (pos[link.axis[0]], d / abs(d)) if abs(d) > 1e-12 else None


def _reach(t: list[float]) -> tuple[float, float]:
    """A guide's drawn stretch: the block's travel along it, and a tenth more each way."""
    pad = 0.1 * (max(t) - min(t) + 0.05)
    return min(t) - pad, max(t) + pad


def _slots(mech, drawn) -> list[tuple[object, float, float, tuple[float, float] | None]]:
    """The guides carried by moving links (a slot in a rocker or a yoke), each with its
    stretch in its own coordinates along the guide: from the guide's point on its link to
    every place of the block in the positions ``drawn``, kept within twice the link's own
    size, so that a position near a dead point does not stretch it at every position
    (that one is reached by :func:`_slot_segments`). A guide along the link's axis lies
    on the link's bar: the bar's stretch is given, and only the part beyond it is drawn."""
    out = []
    for s in mech.sliders:
        g = s.guide
        if g.link == 0:
            continue
        own = mech.links[g.link].points.values()
        size = max((abs(p - q) for p in own for q in own), default=0.0) or 0.1
        t = [0.0]
        for pos in drawn:
            pose = _pose(mech, g.link, pos)
            if pose is not None:
                local = (pos[s.point] - pose[0]) * pose[1].conjugate()
                t.append(((local - g.point) * g.direction.conjugate()).real)
        a, b = _reach(t)
        a, b = max(a, -2 * size), min(b, 2 * size)
        bar = None
        if abs(g.direction.imag) < 1e-12 and abs(g.point.imag) < 1e-12:  # along the axis
            proj = [((p - g.point) * g.direction.conjugate()).real for p in own]
            bar = (min(proj), max(proj))
        out.append((s, a, b, bar))
    return out


def _slot_segments(mech, slots, pos, mu_l: float, line: LineType) -> list[Item]:
    out: list[Item] = []
    for s, a, b, bar in slots:
        g = s.guide
        pose = _pose(mech, g.link, pos)
        if pose is None:
            continue
        o, r = pose
        t = (((pos[s.point] - o) * r.conjugate() - g.point) * g.direction.conjugate()).real
        pad = 0.1 * (b - a)
        a, b = min(a, t - pad), max(b, t + pad)  # the block is always on its guide
        if bar is not None:  # only where the block runs past the link's own bar
            lo, hi = bar
            if lo - 1e-9 <= t <= hi + 1e-9:
                continue
            a, b = (hi, t + pad) if t > hi else (t - pad, lo)
        ends = (o + r * (g.point + x * g.direction) for x in (a, b))
        out.append(Segment(*(_sheet(z, mu_l) for z in ends), line))
    return out


def _support(xy: tuple[float, float]) -> list[Item]:
    """A fixed pivot: a small triangle standing on a hatched base."""
    x, y = xy
    return [
        Polyline([(x, y), (x - 3, y + 5), (x + 3, y + 5)], LineType.MAIN, closed=True),
        Hatch((x - 5, y + 5), (x + 5, y + 5), side=1, spacing=1.6, length=2.0),
    ]


def positions_view(sol, cycle, lang: str = "ru", sizing: bool = False,
                   heavy: list[int] | None = None) -> View:
    """Plan of positions at μl: the positions the plans are built for heavy, the cycle's
    other positions and the two extreme ones thin, trajectories, pivots, sliders, stroke
    H; the positions drawn are the engine's (:func:`plans.cycle.positions.drawn`, worked out
    once per solver). ``heavy``: the numbers of the cycle's positions the sheet draws
    plans for (``--plans``), drawn heavy and numbered, the points lettered on the first;
    the given position (``sol``'s), which has no plans then, is not drawn. None: the
    given position heavy, the plans being its own."""
    mech, mu_l = sol.mechanism, sol.mu_l
    shown = drawn(sol.solver, cycle)
    main = _heavy_positions(sol, shown, heavy)
    motion_all = shown.motion_all
    items: list[Item] = []
    over: list[Item] = []  # drawn over the breaks under labels
    labels: list[LabelRequest] = []

    # trajectories, where they stay near the mechanism
    valid = shown.trajectory
    for name in shown.traced:
        z = np.asarray(motion_all.position[name])
        run: list[tuple[float, float]] = []
        for ok, zz in zip(valid, z, strict=True):
            if ok:
                run.append(_sheet(complex(zz), mu_l))
            elif len(run) > 1:
                items.append(Polyline(run, LineType.DASHED if name != mech.driver.tip else LineType.THIN))
                run = []
            else:
                run = []
        if len(run) > 1:
            closed = bool(valid.all()) and cycle.full_turn
            items.append(Polyline(run, LineType.DASHED if name != mech.driver.tip else LineType.THIN,
                                  closed=closed))
    # the positions drawn: the cycle's, numbered, the extreme ones, and the given one
    cycle_pos, extremes = shown.cycle, shown.extremes
    drawn_at = [p for p in (*cycle_pos, *extremes, *main) if p is not None]
    # fixed guides: the axis dash-dot over the slider's reach in the positions drawn
    for s in mech.sliders:
        if s.guide.link != 0:
            continue
        d = s.guide.direction
        a, b = _reach([((p[s.point] - s.guide.point) * d.conjugate()).real for p in drawn_at])
        items.append(Segment(_sheet(s.guide.point + a * d, mu_l), _sheet(s.guide.point + b * d, mu_l),
                             LineType.DASH_DOT_THIN))
    tip = mech.driver.tip
    slots = _slots(mech, drawn_at)
    for k, pos in enumerate(cycle_pos):
        if pos is None:
            continue
        if not any(pos is p for p in main):  # a heavy one is drawn below, numbered here
            items += _link_segments(mech, pos, mu_l, LineType.THIN)
            items += _slot_segments(mech, slots, pos, mu_l, LineType.THIN)
        labels.append(LabelRequest(_sheet(pos[tip], mu_l), str(k), 2.5, "ne", markup=False,
                                   optional=True))
    for pos in extremes:
        if pos is None:
            continue
        items += _link_segments(mech, pos, mu_l, LineType.DASH_DOUBLE_DOT_THIN)
        items += _slot_segments(mech, slots, pos, mu_l, LineType.DASH_DOUBLE_DOT_THIN)
    # the heavy positions; centres of mass as small dots on their links; every heavy
    # line before the joints, whose white rings would cut another position's links
    for pos in main:
        items += _link_segments(mech, pos, mu_l, LineType.MAIN)
        items += _slot_segments(mech, slots, pos, mu_l, LineType.MAIN)
    for pos in main:
        for n in pos:
            if n in mech.point_names() and _centre_of_mass(mech, n):
                items.append(Circle(_sheet(pos[n], mu_l), 0.6, LineType.MAIN, fill="black"))
        for s in mech.sliders:
            if s.point in pos:
                items.append(_block(_sheet(pos[s.point], mu_l), _guide_dir(mech, s, pos),
                                    LineType.MAIN))
    pos = main[0]  # the one lettered
    for name in mech.frame:
        items += _support(_sheet(pos[name], mu_l))
    # the joints (points of two links or more) are the mechanism's: found once, ringed
    # in each heavy position
    joints = sorted({n for link in mech.links.values() for n in link.points
                     if len(mech.links_of(n)) > 1})
    for at in main:
        items += [Circle(_sheet(at[n], mu_l), JOINT_R, LineType.MAIN, fill="white")
                  for n in joints if n in at]
    shared = _shared((_sheet(pos[n], mu_l), n) for n in mech.point_names() if n in pos)
    for xy, names in reversed(shared):
        # close to its point even among the other positions' lines, which break for it
        labels.insert(0, LabelRequest(xy, shared_label(names), LETTER, "nw",
                                      blank=True))
    # stroke H of a linear output
    out = cycle.output
    w = WORDS[lang]
    ends = len(extremes) == 2 and all(e is not None for e in extremes)
    if out is not None and cycle.stroke and out.kind == "linear" and ends:
        p1, p2 = (_sheet(e[out.point], mu_l) for e in extremes)
        items += _stroke_dimension(items, p1, p2, mech.slider_of(out.link).guide.direction,
                                   f"H = {num(cycle.stroke, 4, lang)} {w['m']}")
    # swing ψ of a rocker: an arc between its two extreme positions, about its pivot
    if out is not None and cycle.stroke and out.kind == "angular" and ends:
        arm = out.arm(mech)
        if arm is not None:
            pivot, tip = arm
            a, b = extremes[0][tip], extremes[1][tip]
            over += _swing_arc(pos[pivot], a, b, mu_l)  # its value's break must not cut it
            along = [_sheet(_swing_point(pos[pivot], a, b, t), mu_l) for t in _SWING_AT]
            deg = math.degrees(cycle.stroke)
            labels.append(LabelRequest(along[0], f"{w['swing']} = {num(deg, 4, lang)}°",
                                       3.5, "n", markup=False, also=tuple(along[1:]),
                                       blank=True))
    caption = f"{w['positions']}, μ_l = {num(mu_l, 4, lang)} {w['m']}/{w['mm']}"
    under = [w["left_off"].format(k=", ".join(map(str, shown.left_off)),
                                  d=num(shown.limit, 2, lang))] if shown.left_off else []
    return _finish("positions", items, labels, caption, under, pad=8.0, over=over,
                   sizing=sizing)


def _heavy_positions(sol, shown, heavy: list[int] | None) -> list[dict[str, complex]]:
    """The positions drawn heavy: the cycle's positions numbered ``heavy`` (one drawn
    once, in the order given), the given position where there are none (None: no
    ``--plans``), or where every one of them is left off the drawing (a point runs far
    out: :func:`plans.cycle.positions.drawn`), so that the points have a position to be
    lettered on."""
    if heavy is None:
        return [sol.positions]
    main: list[dict[str, complex]] = []
    for k in heavy:
        pos = shown.cycle[k]
        if pos is not None and not any(pos is p for p in main):
            main.append(pos)
    return main or [sol.positions]


def _stroke_dimension(items, p1, p2, direction: complex, value: str) -> list[Item]:
    """The stroke H between the output's extreme positions ``p1``, ``p2`` (sheet mm), a
    dimension parallel to its guide (``direction``, in the world) and clear of the drawing
    ``items``: extension lines, a dimension line with two arrows, the value above it,
    or on a shelf beyond its end where it has no room between the extension lines.

    It stands on the side of the guide where its extension lines are shortest, below a
    horizontal guide unless above is shorter: what it must clear is only what lies across
    its own span along the guide, so a guide above the whole mechanism (a press's) has
    its stroke just above it, not under the mechanism with lines crossing all of it."""
    ux, uy = direction.real, -direction.imag  # the sheet's y points down
    if ux < -1e-12 or (abs(ux) <= 1e-12 and uy > 0):
        ux, uy = -ux, -uy  # read from left to right, or from the bottom up
    nx, ny = -uy, ux  # below a horizontal guide; the value stands on the −n side of its line
    width = text_width(value, 3.5)
    lo, hi = sorted((p[0] - p1[0]) * ux + (p[1] - p1[1]) * uy for p in (p1, p2))
    on_shelf = width + 2.0 > hi - lo
    hi += 2.0 + (width + 3.0 if on_shelf else 0.0)  # the shelf runs on beyond the far end
    lo -= 2.0
    strip = Polygon([(p1[0] + ux * a + nx * b, p1[1] + uy * a + ny * b)
                     for a, b in ((lo, -1e4), (hi, -1e4), (hi, 1e4), (lo, 1e4))])
    across = shapely.get_coordinates([g.intersection(strip) for g in obstacles_of(items, clearance=0.0)])
    across = (across - p1) @ np.array([nx, ny])
    reach = {side: float(np.max(side * across, initial=0.0)) + 8.0 for side in (1.0, -1.0)}
    side = -1.0 if reach[-1.0] < reach[1.0] - 1.0 else 1.0  # above only where shorter
    ox, oy = side * nx, side * ny  # from the guide to the dimension line

    def at(p, t):  # the point t beyond the dimension line on the extension line from p
        k = reach[side] - ((p[0] - p1[0]) * ox + (p[1] - p1[1]) * oy)
        return (p[0] + ox * (k + t), p[1] + oy * (k + t))

    d1, d2 = at(p1, 0.0), at(p2, 0.0)
    mid = ((d1[0] + d2[0]) / 2, (d1[1] + d2[1]) / 2)
    out: list[Item] = [Segment(p1, at(p1, 2.0), LineType.THIN), Segment(p2, at(p2, 2.0), LineType.THIN),
                       Arrow(mid, d1, LineType.THIN, 3.0, 1.0), Arrow(mid, d2, LineType.THIN, 3.0, 1.0)]
    turn = math.degrees(math.atan2(uy, ux))  # clockwise on the sheet, as Text takes it
    if not on_shelf:
        out.append(Text((mid[0] - nx, mid[1] - ny), value, size=3.5, anchor="middle", rotate_deg=turn))
    else:  # no room between the extension lines: on a shelf beyond the far one (GOST 2.307)
        end = d2 if (d2[0] - d1[0]) * ux + (d2[1] - d1[1]) * uy > 0 else d1
        out.append(Segment(end, (end[0] + ux * (width + 3.0), end[1] + uy * (width + 3.0)), LineType.THIN))
        out.append(Text((end[0] + ux * 1.5 - nx, end[1] + uy * 1.5 - ny), value, size=3.5,
                        rotate_deg=turn))
    return out


#: the swing arc's radius, as a share of the rocker's arm
_SWING_R = 0.55
#: where along the arc ψ's value may stand, in order of preference: its middle first
_SWING_AT = (0.5, 0.35, 0.65, 0.2, 0.8)


def _swing_point(pivot: complex, a: complex, b: complex, t: float) -> complex:
    """The point at share ``t`` along the arc from the arm's direction at ``a`` to ``b``
    (the shorter way round), at :data:`_SWING_R` of the arm."""
    ra, rb = a - pivot, b - pivot
    turn = math.atan2((ra.conjugate() * rb).imag, (ra.conjugate() * rb).real)
    r = _SWING_R * min(abs(ra), abs(rb))
    return pivot + r * (ra / abs(ra)) * complex(math.cos(t * turn), math.sin(t * turn))


def _swing_arc(pivot: complex, a: complex, b: complex, mu_l: float) -> list[Item]:
    """The dimension arc of ψ with an arrowhead at each end."""
    pts = [_sheet(_swing_point(pivot, a, b, k / 48), mu_l) for k in range(49)]
    length = sum(math.dist(p, q) for p, q in itertools.pairwise(pts))  # mm on the sheet
    out: list[Item] = [Polyline(pts, LineType.THIN)]
    if length > 8.0:  # room for the two 3 mm heads
        t = 3.0 / length
        for end, inner in ((pts[0], t), (pts[-1], 1 - t)):
            out.append(Arrow(_sheet(_swing_point(pivot, a, b, inner), mu_l), end,
                             LineType.THIN, 3.0, 1.0))
    return out


# ----------------------------------------------------------------- diagrams


def diagrams_view(mech, cycle, lang: str = "ru", width: float = 180.0, height: float = 40.0,
                  solver=None, curves=None) -> View | None:
    """s(φ), v(φ), a(φ) of the output over one turn from the first position; ψ(φ), ω(φ),
    ε(φ) of an output link that rocks, or that turns all the way round (a rotating slotted
    link: ψ then grows by a full turn). ``curves``: :func:`diagram_curves`, worked out
    before (a sheet draws the diagrams at several sizes)."""
    if curves is None:
        curves = diagram_curves(mech, cycle, solver)
    if curves is None:
        return None
    s, v, a, flip = curves
    out = cycle.output
    return _draw_diagrams(mech, cycle, lang, width, height, out.kind == "linear", s, v, a, flip)


def diagram_curves(mech, cycle, solver=None):
    """The output's (s, v, a) (or ψ, ω, ε) at 361 crank angles over one turn from the
    first position, positive the way the working stroke goes (so that s or ψ rises from
    0 at the extreme position it starts from), and that way: 1.0 where it is the
    world's positive sense (ccw for an angle), -1.0 where it is the other; None where
    there are no diagrams to draw."""
    from plans.kinematics.solver import Solver

    solver = solver or Solver(mech)
    out = cycle.output
    if out is None or not cycle.full_turn or not cycle.positions:
        return None
    if not cycle.stroke and out.kind != "angular":
        return None
    sense = 1.0 if mech.driver.omega >= 0 else -1.0
    phi0 = cycle.positions[0]
    phis = phi0 + sense * np.linspace(0.0, 2 * math.pi, 361)
    m = solver.solve(phis)
    if not m.placed.all():
        return None
    s = np.asarray(out.value(m, mech), dtype=float)
    if out.kind == "angular":
        s = np.unwrap(s)  # an angle in (−π, π]: continuous across ±π, and past a full turn
    s = s - s[0]
    flip = -1.0 if abs(s.min()) > abs(s.max()) else 1.0  # s from the starting extreme, ≥ 0
    s = flip * s
    v = flip * np.asarray(out.rate(m, mech, "velocity"), dtype=float)
    a = flip * np.asarray(out.rate(m, mech, "acceleration"), dtype=float)
    ok = solver.trusted(m)
    if not ok.all():  # a sample on or beside a change point, where the plans are singular:
        # the curve runs straight over it from the samples either side (1° away); a
        # slotted link's block on its pivot is one too, where the lines' sine stays 1
        k = np.arange(len(phis))
        v[~ok] = np.interp(k[~ok], k[ok], v[ok])
        a[~ok] = np.interp(k[~ok], k[ok], a[ok])
    return s, v, a, flip


def _draw_diagrams(mech, cycle, lang, width, height, linear, s, v, a, flip=1.0) -> View:
    w = WORDS[lang]
    units = (w["m"], w["ms"], w["ms2"]) if linear else (w["rad"], w["rads"], w["rads2"])
    names = ("s", "v", "a") if linear else ("ψ", "ω", "ε")
    # the axes name their quantity as the tables and the note do: ω3 of the rocker 3,
    # s_D of the slider's point D (a sheet may have ω of several links)
    out = cycle.output
    index = (out.point if linear else str(out.link)) if out is not None else ""
    items: list[Item] = []
    numbers: list[tuple[float, float, str]] = []  # each numbered position's tick and number
    every = _numbered_every(len(cycle.positions), width)
    y = 0.0
    # rounding of a 0 is drawn as 0, not blown up to the height of the diagram (a
    # parallelogram's ε3 of 1e-13 rad/s² at μ = 5e-10)
    s, v, a = (np.where(np.abs(x) < at_rest(mech, linear, k), 0.0, x) for k, x in enumerate((s, v, a)))
    for data, name, unit in zip((s, v, a), names, units, strict=True):
        lo, hi = float(min(data.min(), 0)), float(max(data.max(), 0))
        span = hi - lo or 1.0
        mu = _nice(span / height)
        y_zero = y + hi / mu
        h = (hi - lo) / mu
        xs = np.linspace(0, width, len(data))
        ys = y_zero - data / mu
        items.append(Segment((0, y_zero), (width + 6, y_zero), LineType.THIN))
        items.append(Arrow((0, y + h + 2), (0, y - 6), LineType.THIN, 3.0, 1.0))
        items.append(Polyline(list(zip(xs.tolist(), ys.tolist(), strict=True)), LineType.MAIN))
        for k in range(len(cycle.positions) + 1):
            x = width * k / len(cycle.positions)
            items.append(Segment((x, y_zero - 1), (x, y_zero + 1), LineType.THIN))
            if k % every == 0:
                numbers.append((x, y_zero, str(k % len(cycle.positions))))
        axis = _axis_name(name + (f"_{{{index}}}" if index else ""), unit,
                          None if linear else flip, lang)
        items.append(Text((2, y - 6), axis, size=3.5, baseline="hanging", markup=True))
        items.append(Text((width + 6, y_zero - 1.5), "φ", size=3.5, anchor="end"))
        items.append(_start_anchored(Text((width - 2, y - 6), f"μ_{{{name}}} = {num(mu, 3, lang)} {_per_mm(unit, lang)}",
                          size=2.5, anchor="end", baseline="hanging", markup=True)))
        y += h + 16.0
    placed, bounds = _numbers(items, numbers)
    mu_phi = 2 * math.pi / width
    caption = f"{w['diagrams']}, μ_φ = {num(mu_phi, 3, lang)} {w['rad']}/{w['mm']}"
    return _captioned("diagrams", items + placed, bounds, caption, [])


def _numbered_every(count: int, width: float) -> int:
    """Every how many positions a diagram's tick is numbered: every second, as on
    paper, or every fourth, sixth … where the numbers would stand closer than their own
    width and a gap. With 72 positions on a 120 mm diagram the ticks are 1.7 mm apart, and
    every second one's two digits (3.4 mm) ran into the next number and onto the curves."""
    widest = text_box(Text((0.0, 0.0), str(count - 1), size=2.5, italic=True)).bounds
    need = widest[2] - widest[0] + NUMBERS_APART
    every = 2
    while every * width / count < need:
        every += 2
    return every


#: mm: the least gap between two numbers of positions next to each other on the φ axis
NUMBERS_APART = 1.5
#: mm: how far a position's number stands from the φ axis (its box), nearest first
NUMBER_GAPS = (1.5, 3.0, 4.5)
#: mm: between a tick and the box of a number set beside it, not under or over it
NUMBER_BESIDE = 0.6
#: mm: what a number keeps clear of a diagram's curve beyond the line's half width,
#: of the axes and ticks, and of the other texts
NUMBER_CLEAR = (0.4, 0.1, 0.5)


def _numbers(items: list[Item], numbers: list[tuple[float, float, str]]
             ) -> tuple[list[Text], tuple[float, float, float, float]]:
    """The positions' numbers ((x, y_zero, text) of each tick) on the diagrams ``items``,
    and the box of the view's drawing.

    A number stood under its tick whatever was there, so a curve running below the φ
    axis went through it, and the origin's 0 was written across the vertical axis. Each
    now stands where it meets no curve, no line and no text: under its tick where that
    is clear, else over it (on the other side of the axis from the curve), else beside
    the tick, under the axis, then over it, then a little farther off; the origin's 0
    right of the vertical axis. The view keeps its box, that of the drawing with every
    number under its tick, and each number stays in it: the sheets are packed first-fit,
    and a view 0.75 mm narrower moved them too (variant 5's English sheet on A2 lost a
    step of its diagrams)."""
    under = [Text((x, y_zero + NUMBER_GAPS[0]), text, size=2.5, anchor="middle",
                  baseline="hanging", italic=True) for x, y_zero, text in numbers]
    texts = np.array([text_box(t).bounds for t in items if isinstance(t, Text)]).reshape(-1, 4)
    spans = np.array([text_box(t).bounds for t in under]).reshape(-1, 4)
    every = np.vstack([texts, spans, _bbox([it for it in items if not isinstance(it, Text)])])
    bounds = tuple(float(b) for b in (*every[:, :2].min(axis=0), *every[:, 2:].max(axis=0)))
    frame = shp_box(*np.add(bounds, (-1e-6, -1e-6, 1e-6, 1e-6)))
    style = Style()

    def steps(lines):  # the middle lines of ``lines`` (segments, polylines), step by step
        return shapely.linestrings(np.concatenate([
            np.stack([np.asarray(p)[:-1], np.asarray(p)[1:]], axis=1)
            for p in (it.points if isinstance(it, Polyline) else (it.p1, it.p2) for it in lines)]))

    def reach(lines, clear):  # how near the middle of one of ``lines`` a number may not come
        return max(style.width(it.line) for it in lines) / 2 + clear

    def grown(boxes, d):  # axis-parallel boxes (x0, y0, x1, y1) widened by d
        b = np.asarray(boxes).reshape(-1, 4)
        return shapely.box(b[:, 0] - d, b[:, 1] - d, b[:, 2] + d, b[:, 3] + d)

    curves = [it for it in items if isinstance(it, Polyline)]
    segments = [it for it in items if isinstance(it, Segment)]  # the φ axes, the ticks
    curve_steps = steps(curves)
    on_curves, curve_reach = shapely.STRtree(curve_steps), reach(curves, NUMBER_CLEAR[0])
    ink = None  # the curves' ink as one shape, where a number has no clear spot
    on_lines, line_reach = shapely.STRtree(steps(segments)), reach(segments, NUMBER_CLEAR[1])
    tree = shapely.STRtree([  # the vertical axes with their heads, the other texts
        *obstacles_of([it for it in items if isinstance(it, Arrow)], clearance=NUMBER_CLEAR[1]),
        *grown(texts, NUMBER_CLEAR[2])])
    out: list[Text] = []
    taken = []  # the boxes of the numbers placed
    for (x, y_zero, _), first, (x0, y0, x1, y1) in zip(numbers, under, spans, strict=True):
        w, h = x1 - x0, y1 - y0
        # (side, beside): under or over the tick, then beside it under the axis, then
        # over it; the origin's 0 right of the vertical axis, never across it
        spots = (((1, 0), (-1, 0), (1, 1), (1, -1), (-1, 1), (-1, -1)) if x > 0
                 else ((1, 1), (-1, 1)))
        moves = np.array([(
            {0: x0, 1: x + NUMBER_BESIDE, -1: x - NUMBER_BESIDE - w}[beside] - x0,
            (y_zero + gap if side > 0 else y_zero - gap - h) - y0)
            for gap in NUMBER_GAPS for side, beside in spots])
        tried = np.array([x0, y0, x1, y1]) + np.tile(moves, 2)
        boxes = grown(tried, 0.0)
        outside = ~shapely.covers(frame, boxes)  # none leaves the view's box
        hit = np.zeros(len(boxes), dtype=bool)
        hit[tree.query(boxes, predicate="intersects")[0]] = True
        hit[on_lines.query(boxes, predicate="dwithin", distance=line_reach)[0]] = True
        if taken:
            others = grown(taken, NUMBER_CLEAR[2])
            hit |= shapely.intersects(boxes[:, None], others[None, :]).any(axis=1)
        crossed = np.zeros(len(boxes))
        crossed[on_curves.query(boxes, predicate="dwithin", distance=curve_reach)[0]] = 1.0
        if (crossed[~hit & ~outside] > 0).all():  # nowhere clear: the least of the curves
            if ink is None:  # once a view, not once a number
                ink = shapely.union_all(curve_steps).buffer(curve_reach)
            crossed[crossed > 0] = shapely.area(shapely.intersection(boxes[crossed > 0], ink))
        # the first that meets nothing; where none, the one that meets no line and no text
        # and crosses the least of the curves; in the view's box always (the nearest
        # under the tick is)
        k = int(np.lexsort((np.arange(len(boxes)), crossed, hit, outside))[0])
        out.append(translate(first, *moves[k]))
        taken.append(tried[k])
    return out, bounds


def _axis_name(name: str, unit: str, flip: float | None, lang: str) -> str:
    """A diagram's axis: "s, м"; an angle's with its positive sense after it, one space
    apart, "ε, рад/с² (+ против ч.с.)": the tables give ω and ε by their senses, and the
    working stroke of a rocker may turn either way. One text, so that the space is the
    font's own (set apart by an estimate of the name's width, the sense stood two
    spaces after "рад/с²" and one after "рад")."""
    if flip is None:
        return f"{name}, {unit}"
    w = WORDS[lang]
    return f"{name}, {unit} (+ {w['ccw'] if flip > 0 else w['cw']})"


def _nice(x: float) -> float:
    """The next value ≥ x of the series 1, 2, 2.5, 4, 5 × 10^k (the plans' series)."""
    from plans.scales import choose_mu

    return choose_mu(x, 0.0, crank_mm=1.0) if x > 0 else 1.0


# ----------------------------------------------------------------- tables


def _table(name: str, caption: str, header: list[str], rows: list[list[str]],
           widths: list[float], row_h: float = 7.0, parts: int = 1, sizing: bool = False) -> View:
    """A table under its caption; ``parts`` > 1 sets its rows in that many tables side
    by side, each under the header (a tall table on a small sheet). ``sizing``: its lines
    only (every cell's text is fitted into its cell), for its size."""
    items: list[Item] = []
    total_w = sum(widths)
    per = -(-len(rows) // max(1, parts))  # rows of each part, the last one's fewer
    chunks = [rows[i:i + per] for i in range(0, len(rows), per)] or [[]]
    for k, chunk in enumerate(chunks):
        items += _shift(_grid(header, chunk, widths, row_h, sizing), k * (total_w + PART_GAP), 0.0)
    span = len(chunks) * total_w + (len(chunks) - 1) * PART_GAP
    return _assembled(name, (items, []), (0.0, 0.0, span, _bbox(items)[3]), caption, "fit")


#: mm between the parts of a table set side by side
PART_GAP = 6.0


def _grid(header: list[str], rows: list[list[str]], widths: list[float], row_h: float,
          lines_only: bool = False) -> list[Item]:
    """The lines and cells of one table, its top-left corner at (0, 0)."""
    items: list[Item] = []
    total_w = sum(widths)
    n = len(rows) + 1
    for i in range(n + 1):
        items.append(Segment((0, i * row_h), (total_w, i * row_h), LineType.MAIN if i in (0, 1, n) else LineType.THIN))
    x = 0.0
    for wd in [0.0, *widths]:
        x += wd
        items.append(Segment((x, 0), (x, n * row_h), LineType.MAIN))
    for r, row in enumerate([] if lines_only else [header, *rows]):
        x = 0.0
        for cell, wd in zip(row, widths, strict=True):
            size = 2.5 if r else 3.5
            pos = (x + wd / 2, r * row_h + row_h / 2)
            t = centred(pos, cell, size, "middle")
            bw = text_box(t).bounds
            if bw[2] - bw[0] > wd - 1.5:
                t = centred(pos, cell, size, "middle", max(0.5, (wd - 1.5) / (bw[2] - bw[0])))
            items.append(t)
            x += wd
    return items


def segments_table_view(sols: list[tuple[str, object]], lang: str = "ru", parts: int = 1,
                        sizing: bool = False) -> View:
    """Segments of both plans (mm) and their values (SI) for the chosen positions, in
    ``parts`` tables side by side."""
    w = WORDS[lang]
    header = [w["segment"]]
    for tag, _ in sols:
        pre = f"{tag}: " if len(sols) > 1 else ""  # name the position only when there are several
        header += [f"{pre}{w['mm']}", f"{pre}{w['value']}"]
    keys: list[tuple[str, str, str, str]] = []  # kind, start, end, label
    seen = set()
    for _, sol in sols:
        for kind, plan in (("v", sol.velocity), ("a", sol.acceleration)):
            for v in plan.vectors:
                key = (kind, v.start, v.end)
                if key not in seen:
                    seen.add(key)
                    keys.append((kind, v.start, v.end, v.label))
    rows = []
    for kind, a, b, label in keys:
        row = [f"{name_markup(a)}{name_markup(b)}: {notation(notation_in(label, lang))}"]
        for _, sol in sols:
            plan = sol.velocity if kind == "v" else sol.acceleration
            if a in plan.points or a == plan.pole:
                mm = plan.mm(a, b) if b in plan.points else float("nan")
                row += [num(mm, 4, lang), f"{num(mm * plan.mu, 4, lang)} {plan.unit if lang == 'en' else (w['ms'] if kind == 'v' else w['ms2'])}"]
            else:
                row += ["—", "—"]
        rows.append(row)
    widths = [40.0] + [22.0, 28.0] * len(sols)
    return _table("segments", w["segments"], header, rows, widths, row_h=6.0, parts=parts,
                  sizing=sizing)


def omega_table_view(sols: list[tuple[str, object]], lang: str = "ru") -> View:
    w = WORDS[lang]
    header = [w["link"]]
    for tag, _ in sols:
        pre = f"{tag}: " if len(sols) > 1 else ""
        header += [f"{pre}ω, {w['rads']}", f"{pre}ε, {w['rads2']}"]
    first = sols[0][1]
    rows = []
    for lid in sorted(first.omega):
        row = [f"{lid}"]
        for _, sol in sols:
            om, ep = sol.omega.get(lid, 0.0), sol.epsilon.get(lid, 0.0)
            row += [_signed(om, lang), _signed(ep, lang)]
        rows.append(row)
    widths = [16.0] + [34.0, 34.0] * len(sols)
    return _table("angular", w["angular"], header, rows, widths, row_h=6.0)


def _signed(x: float, lang: str) -> str:
    w = WORDS[lang]
    if abs(x) < 1e-12:
        return "0"
    return f"{num(abs(x), 4, lang)} {w['ccw'] if x > 0 else w['cw']}"


def note_view(lines: list[str], width: float = 180.0) -> View:
    """Lines of text at 3.5 mm, each broken at spaces into lines ``width`` mm long at
    most."""
    items: list[Item] = []
    y = 0.0
    for line in lines:
        for part in wrap_words(line, width - 2.0, lambda s: (text_width(s, 3.5)
                                                              + SLANT * 3.5), cut=False):
            y += 3.5 * LINE_PITCH
            items.append(Text((0, y), part, size=3.5))
    bx0, by0, bx1, by1 = _bbox(items)
    items = _shift(items, -bx0 + 1, -by0 + 1)
    return View("note", items, bx1 - bx0 + 2, by1 - by0 + 2)


