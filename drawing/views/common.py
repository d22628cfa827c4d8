"""What every view of a sheet shares: the :class:`View` box, captions, the lines under a
drawing, the letters' placing against the view's own lines, and the sheet's words.

A view is drawn with its top-left corner at (0, 0); :mod:`drawing.sheet.layout` moves
it to its place on the sheet with a :class:`~drawing.scene.Group` offset. Labels of a
view are placed with :func:`drawing.labels.place_labels` against the view's own lines
(``obstacles_of``) and kept inside the view's box, so no label of one view can meet
another view.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace

from shapely.geometry import box as shp_box

from drawing.labels import LabelRequest, place_labels
from drawing.obstacles import obstacles_of
from drawing.scene import (
    Blank,
    Circle,
    Group,
    Item,
    Polyline,
    Segment,
    Text,
    flatten,
    index_markup,
    parse_markup,
    translate,
)
from drawing.styles import LineType
from drawing.text import LINE_PITCH, SLANT, SPACING, runs_width, text_box, text_width

__all__ = [
    "BLANK_PAD",
    "CAPTION",
    "CAPTION_OVER",
    "CAPTION_STYLES",
    "EQUATION",
    "HEAD",
    "JOINT_R",
    "LETTER",
    "PAD",
    "SHARED",
    "SMALL_CAPTION",
    "WORDS",
    "Equation",
    "View",
    "assembled",
    "bbox",
    "caption_lines",
    "caption_texts",
    "captioned",
    "captioned_width",
    "centred",
    "equation_items",
    "finish",
    "notation",
    "per_mm",
    "retitled",
    "shared_points",
    "shifted",
    "start_anchored",
    "width_of",
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
#: mm: the letters of the vector equations under a plan, their terms and directions: GOST
#: 2.304's 3.5, whose indices (0.7 of it, 2.45 mm) keep above its 1.8 mm floor
EQUATION = 3.5


@dataclass(frozen=True)
class Equation:
    """A vector equation as the course writes it under its plan: each term with a bar
    over its letter, and under the term its direction, "⊥ BA_{3}", "∥ x-x", "∥ A_{3}B"
    (a normal component, from the point to the centre), "0" (a fixed point), or the
    plan's segment that draws a vector known before ("pc"); the signs between the terms.

    >>> eq = Equation(("V_{C}", "V_{B}", "V_{CB}"), ("∥ x-x", "⊥ AB", "⊥ CB"), ("=", "+"))
    >>> eq.text
    'V_{C} = V_{B} + V_{CB}'
    """

    terms: tuple[str, ...]  # markup: "a^n_{A3B}"
    directions: tuple[str, ...]  # markup, "" where none is written
    signs: tuple[str, ...]  # between the terms: "=" or "+"

    @property
    def text(self) -> str:
        """The terms and signs in one line of markup, without bars or directions."""
        out = [self.terms[0]]
        for sign, term in zip(self.signs, self.terms[1:], strict=True):
            out += [sign, term]
        return " ".join(out)


#: mm: the room each side of an equation's sign, and above the capitals to its bars
SIGN_GAP = 1.5
BAR_RISE = 0.7
#: the height of the drawing font's lowercase letters, in h: a bar over "a" stands over it
X_HEIGHT = 0.75


def _direction_items(text: str, x: float, y: float, size: float) -> tuple[list[Item], float]:
    """A direction written from ``x`` on the baseline ``y``: "⊥ …" and "∥ …" with the
    sign drawn as strokes (the drawing font has neither glyph), slanted as the letters
    are; the items and their width."""
    lean = SLANT * size / 2  # the letters lean about their middle line (drawing.svg)
    sign, rest = (text[0], text[1:].lstrip()) if text[:1] in "⊥∥" else ("", text)
    items: list[Item] = []
    w = 0.0
    if sign == "⊥":
        a = 0.6 * size
        items += [Segment((x + a / 2 - lean, y), (x + a / 2 + lean, y - size), LineType.THIN),
                  Segment((x - lean, y), (x + a - lean, y), LineType.THIN)]
        w = a + (SPACING + 0.3) * size
    elif sign == "∥":
        for dx in (0.15 * size, 0.45 * size):
            items.append(Segment((x + dx - lean, y), (x + dx + lean, y - size), LineType.THIN))
        w = (0.6 + SPACING + 0.3) * size
    if rest:
        t = Text((x + w, y), rest, size=size, markup=True)
        items.append(t)
        w += runs_width(t.runs(), size)
    return items, w


def _direction_width(text: str, size: float) -> float:
    return _direction_items(text, 0.0, 0.0, size)[1] if text else 0.0


def equation_items(eq: Equation, x: float, y: float, size: float = EQUATION) -> list[Item]:
    """``eq`` written from ``x``: its terms on the baseline ``y``, each with a bar over
    its letter and centred over its direction, which stands one line under it (the
    line's pitch, :data:`~drawing.text.LINE_PITCH`, below)."""
    items: list[Item] = []
    lean = SLANT * size / 2
    below = y + size * LINE_PITCH
    for k, (term, direction) in enumerate(zip(eq.terms, eq.directions, strict=True)):
        if k:
            sign = eq.signs[k - 1]
            items.append(Text((x + SIGN_GAP, y), sign, size=size))
            x += 2 * SIGN_GAP + text_width(sign, size)
        runs = parse_markup(term)
        tw, dw = runs_width(runs, size), _direction_width(direction, size)
        col = max(tw, dw)
        tx = x + (col - tw) / 2
        items.append(Text((tx, y), term, size=size, markup=True))
        letter = runs[0].text
        rise = (size if letter[:1].isupper() else X_HEIGHT * size) + BAR_RISE
        bar_y = y - rise
        shift = SLANT * rise - lean  # the lean at the bar's height
        items.append(Segment((tx + shift, bar_y), (tx + shift + text_width(letter, size), bar_y),
                             LineType.THIN))
        if direction:
            items += _direction_items(direction, x + (col - dw) / 2, below, size)[0]
        x += col
    return items

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
        "no_stroke": "нет хода выходного звена",
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
        "no_stroke": "no stroke of the output",
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


def start_anchored(t: Text) -> Text:
    """The same text written from its start: SVG renderers misplace indices
    (``tspan`` with ``dy``) of middle- or end-anchored text."""
    if t.anchor == "start" or not t.markup or all(r.level == 0 for r in t.runs()):
        return t
    x0 = text_box(t).bounds[0]
    return replace(t, pos=(x0, t.pos[1]), anchor="start")


def shifted(items: list[Item], dx: float, dy: float) -> list[Item]:
    """Moved by (dx, dy); a group keeps its class, its contents are moved."""
    return [
        replace(it, items=tuple(shifted(list(it.items), dx, dy))) if isinstance(it, Group)
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


def bbox(items: list[Item]) -> tuple[float, float, float, float]:
    xs, ys = zip(*_coords(items), strict=True)
    return min(xs), min(ys), max(xs), max(ys)


def shared_points(points) -> list[tuple[tuple[float, float], list[str]]]:
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


def per_mm(unit: str, lang: str) -> str:
    """A scale factor's unit: "(м/с)/мм", "рад/мм"."""
    mm = WORDS[lang]["mm"]
    return f"({unit})/{mm}" if "/" in unit else f"{unit}/{mm}"


def finish(
    name: str,
    drawing: list[Item],
    labels: list[LabelRequest],
    caption: str,
    under: list[str] = (),
    pad: float = PAD,
    over: list[Item] = (),
    sizing: bool = False,
    under_size: float = 2.5,
) -> View:
    """Frame ``drawing`` with room for its labels, letter it, caption on top,
    ``under`` (equations) below in ``under_size`` mm letters; shift everything to the box
    (0, 0)–(w, h). ``over``: thin lines that no break cuts (a dimension's own arc), drawn
    after the breaks. ``sizing``: no letters placed, the view as large as they could make
    it (they stay within ``pad`` of the drawing), for a sheet that tries many scales."""
    drawing = list(drawing)
    x0, y0, x1, y1 = bbox(drawing + list(over))
    region = shp_box(x0 - pad, y0 - pad, x1 + pad, y1 + pad)
    if sizing:
        return captioned(name, list(drawing) + list(over), region.bounds, caption, under, under_size)
    thin = (LineType.THIN, LineType.DASHED, LineType.DASH_DOUBLE_DOT_THIN)
    is_soft = [isinstance(it, Segment | Polyline) and it.line in thin for it in drawing]
    drawing += over
    is_soft += [False] * len(over)
    placed = place_labels(labels,
                          obstacles_of([it for it, s in zip(drawing, is_soft, strict=True) if not s]),
                          region=region, distances=(1.0, 2.0, 3.0, 4.5, 6.0, 8.0),
                          soft=obstacles_of([it for it, s in zip(drawing, is_soft, strict=True) if s])
                          ) if labels else []  # the diagrams: nothing to letter
    texts = [start_anchored(p.text) for p, r in zip(placed, labels, strict=True)
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
    return captioned(name, items, bbox(items), caption, under, under_size)


def _leader(point, end) -> Segment:
    """A thin leader line from near ``point`` (clear of its dot) to a label's box."""
    d = math.dist(point, end)
    k = min(0.8, d / 2) / d if d > 0 else 0.0
    start = (point[0] + (end[0] - point[0]) * k, point[1] + (end[1] - point[1]) * k)
    return Segment(start, end, LineType.THIN)


def captioned(name: str, items: list[Item], bounds, caption: str, under: list,
              under_size: float = 2.5) -> View:
    """The view of ``items`` (within ``bounds``) under ``caption``, ``under`` below in
    ``under_size`` mm letters (3.5 keeps their indices at GOST 2.304's 1.8 mm or more),
    each line 3 mm under the one above: a line of text, or an :class:`Equation` with
    its bars and, one line under it, its terms' directions."""
    x0, _y0, _x1, y1 = bounds
    lines: list[Item] = []
    y = y1 + 2.0
    for line in under:
        if isinstance(line, Equation):
            y += under_size + BAR_RISE + 4.5
            lines += equation_items(line, x0, y, under_size)
            y += under_size * LINE_PITCH
            continue
        y += under_size + 3.0
        lines.append(Text((x0, y), notation(line), size=under_size, markup=True,
                          baseline="alphabetic"))
    return assembled(name, (items, lines), bounds, caption, "fit")


def assembled(name: str, parts: tuple[list[Item], list[Item]], bounds, caption: str,
               style: str) -> View:
    """The view of ``parts`` (the drawing within ``bounds``, the lines under it) with
    ``caption`` over ``bounds`` set as ``style`` says (:data:`CAPTION_STYLES`), in its
    box."""
    x0, y0, x1, y1 = bounds
    drawing, under = parts
    items = [*drawing, *caption_texts(caption, x0, x1, y0, style), *under]
    bx0, by0, bx1, by1 = bbox(items)
    bx0, by0, bx1, by1 = min(bx0, x0), min(by0, y0), max(bx1, x1), max(by1, y1)
    size = items[len(drawing)].size
    items = shifted(items, -bx0 + 1, -by0 + 1)
    widest = max([0.0, *(x - x0 for x, _ in _coords(list(under)))])
    return View(name, items, bx1 - bx0 + 2, by1 - by0 + 2, (x1 - x0, y1 - y0),
                (width_of(centred((0, 0), caption, CAPTION)), widest), caption, size,
                (parts, bounds))


def retitled(view: View, style: str) -> View:
    """``view`` with its caption set as ``style`` says (:data:`CAPTION_STYLES`): the
    drawing, its letters and the lines under it as they were."""
    if not view.parts:
        return view
    return assembled(view.name, *view.parts, view.caption, style)


def caption_lines(caption: str, width: float, style: str = "fit") -> tuple[float, list[str]]:
    """(letter size, lines) of a caption over a drawing ``width`` mm wide, set as
    ``style`` says (:data:`CAPTION_STYLES`)."""
    if style == "small":
        return SMALL_CAPTION, [caption]
    if _caption_at(width_of(centred((0, 0), caption, CAPTION)), width) == CAPTION:
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
        return max(width_of(centred((0, 0), part, CAPTION)) for part in (caption[:i], caption[i + 1:]))

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
    """The width :func:`captioned` gives a view whose drawing is ``body`` mm wide, its
    caption ``caption`` mm at :data:`CAPTION` (set at :data:`SMALL_CAPTION` where that is
    much wider than the drawing) and the widest line under it ``under`` mm: the caption
    centred on the drawing, the lines from its left, 1 mm of margin each side."""
    caption *= _caption_at(caption, body) / CAPTION
    return max(body, (body + caption) / 2, under) - min(0.0, (body - caption) / 2) + 2.0


def width_of(t: Text) -> float:
    b = text_box(t).bounds
    return b[2] - b[0]
