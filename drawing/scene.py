"""Drawing primitives in sheet millimetres, grouped into named layers.

All coordinates are **sheet millimetres with the origin at the top-left corner
of the sheet and y pointing down** (the SVG convention).  A view converts its
model (metres, y up) into these coordinates once, in its own transform; from
here on nothing is scaled, only translated, so line widths and font sizes stay
true to GOST.

Every value is a frozen dataclass.  Points are stored as ``(x, y)`` tuples of
floats; anything with two items (a list, a numpy row) is accepted and converted.

>>> seg = Segment((10, 20), [30, 20])
>>> seg.p2
(30.0, 20.0)
>>> scene = Scene((Layer("plan", (seg,)),)) + Scene((Layer("plan", (seg,)),))
>>> [(layer.name, len(layer.items)) for layer in scene.layers]
[('plan', 2)]
"""

from __future__ import annotations

import math
import re
from collections.abc import Iterable, Iterator, Sequence
from dataclasses import dataclass, replace
from typing import Any, Literal, TypeAlias

from drawing.styles import LineType, Style

__all__ = [
    "Arrow",
    "Blank",
    "Circle",
    "Group",
    "Hatch",
    "Item",
    "Layer",
    "Page",
    "Point",
    "Polyline",
    "Rect",
    "Run",
    "Scene",
    "Segment",
    "Text",
    "flatten",
    "parse_markup",
    "translate",
]

Point: TypeAlias = tuple[float, float]

_ANCHORS = ("start", "middle", "end")
_BASELINES = ("alphabetic", "middle", "hanging")
_LAYER_NAME = re.compile(r"[A-Za-z][A-Za-z0-9_-]*\Z")


def _pt(p: Sequence[float]) -> Point:
    x, y = p  # exactly two items, or a clear ValueError
    return (float(x), float(y))


def _set(obj: object, name: str, value: Any) -> None:
    object.__setattr__(obj, name, value)  # normalising a frozen dataclass field


@dataclass(frozen=True, slots=True)
class Rect:
    """An axis-parallel rectangle: top-left corner ``(x, y)``, width, height."""

    x: float
    y: float
    w: float
    h: float

    @property
    def x1(self) -> float:
        return self.x + self.w

    @property
    def y1(self) -> float:
        return self.y + self.h

    @property
    def center(self) -> Point:
        return (self.x + self.w / 2, self.y + self.h / 2)

    @property
    def bounds(self) -> tuple[float, float, float, float]:
        """``(xmin, ymin, xmax, ymax)``, the order of ``shapely.box``."""
        return (self.x, self.y, self.x1, self.y1)

    def corners(self) -> tuple[Point, Point, Point, Point]:
        """Corners clockwise on the sheet, from the top-left one."""
        return (
            (self.x, self.y),
            (self.x1, self.y),
            (self.x1, self.y1),
            (self.x, self.y1),
        )


@dataclass(frozen=True, slots=True)
class Segment:
    """A straight line from ``p1`` to ``p2``."""

    p1: Point
    p2: Point
    line: LineType = LineType.MAIN

    def __post_init__(self) -> None:
        _set(self, "p1", _pt(self.p1))
        _set(self, "p2", _pt(self.p2))


@dataclass(frozen=True, slots=True)
class Polyline:
    """A chain of straight lines; ``closed`` joins the last point to the first."""

    points: tuple[Point, ...]
    line: LineType = LineType.MAIN
    closed: bool = False

    def __post_init__(self) -> None:
        pts = tuple(_pt(p) for p in self.points)
        if len(pts) < 2:
            raise ValueError(f"a polyline needs at least 2 points, got {len(pts)}")
        _set(self, "points", pts)


@dataclass(frozen=True, slots=True)
class Circle:
    """A circle; ``fill`` is a colour (``"white"`` hides what lies under a joint)."""

    center: Point
    r: float
    line: LineType = LineType.MAIN
    fill: str | None = None

    def __post_init__(self) -> None:
        _set(self, "center", _pt(self.center))
        if not self.r > 0:
            raise ValueError(f"circle radius must be positive, got {self.r}")


@dataclass(frozen=True, slots=True)
class Arrow:
    """A vector from ``p1`` to ``p2`` with a filled head at ``p2``.

    The head follows the GOST 2.307 figure: ``head_len`` about 5 *s* and
    ``head_width`` (the full width of the base) about a quarter to a third of
    the length.  Use one size for every vector of a sheet.

    >>> a = Arrow((0, 0), (10, 0))
    >>> a.head()
    ((10.0, 0.0), (6.5, -0.5), (6.5, 0.5))
    >>> a.shaft()
    ((0.0, 0.0), (6.5, 0.0))
    """

    p1: Point
    p2: Point
    line: LineType = LineType.MAIN
    head_len: float = 3.5
    head_width: float = 1.0

    def __post_init__(self) -> None:
        _set(self, "p1", _pt(self.p1))
        _set(self, "p2", _pt(self.p2))

    @property
    def length(self) -> float:
        return math.dist(self.p1, self.p2)

    def head(self) -> tuple[Point, Point, Point] | None:
        """Tip and the two base corners of the head, or ``None`` for a zero vector.

        A vector shorter than ``head_len`` is drawn as a head only, shortened to
        the vector's length, so that its tip still lands on ``p2``.
        """
        n = self.length
        if n < 1e-9:
            return None
        ux, uy = (self.p2[0] - self.p1[0]) / n, (self.p2[1] - self.p1[1]) / n
        hl = min(self.head_len, n)
        hw = self.head_width / 2 * hl / self.head_len
        bx, by = self.p2[0] - ux * hl, self.p2[1] - uy * hl
        return (self.p2, (bx + uy * hw, by - ux * hw), (bx - uy * hw, by + ux * hw))

    def shaft(self) -> tuple[Point, Point] | None:
        """The line part, from ``p1`` to the base of the head (``None`` if none)."""
        n = self.length
        if n <= self.head_len:
            return None
        k = (n - self.head_len) / n
        end = (
            self.p1[0] + (self.p2[0] - self.p1[0]) * k,
            self.p1[1] + (self.p2[1] - self.p1[1]) * k,
        )
        return (self.p1, end)


@dataclass(frozen=True, slots=True)
class Text:
    """One line of text.

    Args:
        pos: the reference point.
        size: GOST 2.304 size *h* = height of the capitals, mm.
        anchor: where ``pos`` lies along the line: ``"start"``, ``"middle"``
            or ``"end"`` of the text.
        rotate_deg: rotation about ``pos``, degrees **clockwise on the sheet**
            (SVG ``rotate``, since y points down); 180 turns the text upside
            down, as in field 26 of the title block.
        italic: slanted 75° (GOST type B slanted), drawn as a shear.
        baseline: where ``pos`` lies across the line: ``"alphabetic"`` (on the
            baseline), ``"middle"`` (half the capital height above it) or
            ``"hanging"`` (at the top of the capitals).
        stretch: horizontal scale of the letters (0.8 = condensed to 80 %),
            the way a tight table cell is filled without a smaller size.
        markup: read ``_`` and ``^`` as sub- and superscript marks, for the
            method's notation: ``"V_{BA}"``, ``"a^n_{BA}"``, ``"s_3"``,
            ``"μ_v"``; one character, or a group in braces; ``\\`` escapes.
            Indices are 0.7 h, written in turn after their base (not stacked).
    """

    pos: Point
    text: str
    size: float = 3.5
    anchor: Literal["start", "middle", "end"] = "start"
    rotate_deg: float = 0.0
    italic: bool = True
    baseline: Literal["alphabetic", "middle", "hanging"] = "alphabetic"
    stretch: float = 1.0
    markup: bool = False

    def __post_init__(self) -> None:
        _set(self, "pos", _pt(self.pos))
        if not self.stretch > 0:
            raise ValueError(f"text stretch must be positive, got {self.stretch}")
        if not isinstance(self.text, str):
            raise TypeError(f"text must be a str, got {type(self.text).__name__}")
        if not self.size > 0:
            raise ValueError(f"text size must be positive, got {self.size}")
        if self.anchor not in _ANCHORS:
            raise ValueError(f"anchor must be one of {_ANCHORS}, got {self.anchor!r}")
        if self.baseline not in _BASELINES:
            raise ValueError(
                f"baseline must be one of {_BASELINES}, got {self.baseline!r}"
            )

    @property
    def baseline_shift(self) -> float:
        """Distance from ``pos`` down to the baseline, in the text's own frame.

        >>> Text((0, 0), "A", size=5, baseline="middle").baseline_shift
        2.5
        """
        return {"alphabetic": 0.0, "middle": self.size / 2, "hanging": self.size}[
            self.baseline
        ]

    def runs(self) -> tuple[Run, ...]:
        """The text as runs of one level; plain text is one run.

        >>> [(r.text, r.level) for r in Text((0, 0), "a^n_{BA}", markup=True).runs()]
        [('a', 0), ('n', 1), ('BA', -1)]
        """
        return parse_markup(self.text) if self.markup else (Run(self.text, 0),)


#: Size of indices relative to the line, and the shift of their baselines in h
#: (down for subscripts, up for superscripts).
INDEX_SIZE = 0.7
SUB_SHIFT = 0.3
SUP_SHIFT = 0.45


@dataclass(frozen=True, slots=True)
class Run:
    """A piece of text at one level: 0 on the line, -1 subscript, +1 superscript."""

    text: str
    level: int = 0


def index_markup(s: str) -> str:
    """The engine's notation as markup: an index of two characters or more is braced,
    ``V_A3A`` → ``V_{A3A}``, ``a^n_A3B`` → ``a^n_{A3B}`` (one character needs none)."""
    return re.sub(r"_([A-Za-z0-9]{2,})", r"_{\1}", s)


def name_markup(name: str) -> str:
    """A point's name as markup, its index after the letters: ``a3`` → ``a_{3}``, ``S4``
    → ``S_{4}``, ``n1`` → ``n_{1}``."""
    i = len(name)
    while i > 0 and name[i - 1].isdigit():
        i -= 1
    if 0 < i < len(name):
        return f"{name[:i]}_{{{name[i:]}}}"
    return name


def shared_label(names: Sequence[str], pole: str | None = None, markup: bool = True) -> str:
    """The one label of points that coincide on a plan, as the sheets letter them: the
    pole first, then the others in their order, separated by commas: "p,o,b", "c,n₂".
    ``markup``: each index as markup (``n_{2}``), else the names as written (``n2``).

    >>> shared_label(["o", "b", "p"], "p"), shared_label(["c", "n2"])
    ('p,o,b', 'c,n_{2}')
    >>> shared_label(["a", "d", "π"], "π", markup=False), shared_label(["a3"], "π", markup=False)
    ('π,a,d', 'a3')
    """
    order = sorted(names, key=lambda n: n != pole)  # stable: the others keep their order
    return ",".join(name_markup(n) if markup else n for n in order)


def parse_markup(s: str) -> tuple[Run, ...]:
    """Split ``"x_{ab}^c"``-style text into runs (see :class:`Text` ``markup``).

    >>> [(r.text, r.level) for r in parse_markup(r"V_{BA} = 2\\_x")]
    [('V', 0), ('BA', -1), (' = 2_x', 0)]
    """
    runs: list[Run] = []
    buf: list[str] = []
    i = 0

    def flush(level: int = 0) -> None:
        if buf:
            runs.append(Run("".join(buf), level))
            buf.clear()

    while i < len(s):
        ch = s[i]
        if ch == "\\" and i + 1 < len(s):
            buf.append(s[i + 1])
            i += 2
        elif ch in "_^" and i + 1 < len(s):
            flush()
            level = -1 if ch == "_" else 1
            if s[i + 1] == "{" and (end := s.find("}", i + 2)) != -1:
                buf.append(s[i + 2 : end])
                i = end + 1
            else:
                buf.append(s[i + 1])
                i += 2
            flush(level)
        else:
            buf.append(ch)
            i += 1
    flush()
    return tuple(r for r in runs if r.text)


@dataclass(frozen=True, slots=True)
class Blank:
    """A white box from ``p1`` (top-left) to ``p2`` (bottom-right): the break in the thin
    lines under a dimension's value (GOST 2.307: no line of the drawing crosses a
    dimension's value). Drawn after the lines it breaks, before the ones it must not."""

    p1: Point
    p2: Point

    def __post_init__(self) -> None:
        _set(self, "p1", _pt(self.p1))
        _set(self, "p2", _pt(self.p2))


@dataclass(frozen=True, slots=True)
class Hatch:
    """Hatching of a fixed support: short parallel thin strokes along a base.

    The strokes start on the base ``p1``–``p2`` and lean back at ``angle_deg``
    to it, on the side ``side`` = +1 (right of ``p1``→``p2`` as seen on the
    sheet: below a base drawn left to right) or -1 (the other side).  ``base``
    is the line type of the base itself (the support or guide surface), or
    ``None`` to draw the strokes only.

    >>> h = Hatch((0, 0), (10, 0), spacing=2.5, length=2 ** 0.5)
    >>> len(h.strokes())
    4
    >>> [(round(x, 2), round(y, 2)) for x, y in h.strokes()[0]]
    [(1.75, 0.0), (0.75, 1.0)]
    """

    p1: Point
    p2: Point
    side: int = 1
    spacing: float = 2.0
    length: float = 3.0
    angle_deg: float = 45.0
    line: LineType = LineType.THIN
    base: LineType | None = LineType.MAIN

    def __post_init__(self) -> None:
        _set(self, "p1", _pt(self.p1))
        _set(self, "p2", _pt(self.p2))
        if self.side not in (1, -1):
            raise ValueError(f"side must be +1 or -1, got {self.side}")
        if not (self.spacing > 0 and self.length > 0):
            raise ValueError("hatch spacing and length must be positive")

    def strokes(self) -> tuple[tuple[Point, Point], ...]:
        """The strokes, evenly spaced, each ending inside the base's extent."""
        n = math.dist(self.p1, self.p2)
        if n < 1e-9:
            return ()
        ux, uy = (self.p2[0] - self.p1[0]) / n, (self.p2[1] - self.p1[1]) / n
        nx, ny = (
            -uy * self.side,
            ux * self.side,
        )  # +90° on a y-down sheet = right-hand side
        a = math.radians(self.angle_deg)
        dx = self.length * (nx * math.sin(a) - ux * math.cos(a))
        dy = self.length * (ny * math.sin(a) - uy * math.cos(a))
        back = max(
            0.0, self.length * math.cos(a)
        )  # leaning back: keep the first one inside
        count = int((n - back) / self.spacing + 1e-9) + 1 if n > back else 1
        first = back + ((n - back) - (count - 1) * self.spacing) / 2 if n > back else n
        out = []
        for i in range(count):
            t = first + i * self.spacing
            q = (self.p1[0] + ux * t, self.p1[1] + uy * t)
            out.append((q, (q[0] + dx, q[1] + dy)))
        return tuple(out)


@dataclass(frozen=True, slots=True)
class Group:
    """Items drawn together, shifted by ``offset`` (mm); rendered as one ``<g>``.

    Only a translation is offered, not a general transform: a scale would
    scale stroke widths and fonts away from GOST, and the model-to-sheet
    scaling belongs to the view that computes the coordinates.
    """

    items: tuple[Item, ...]
    offset: Point = (0.0, 0.0)
    name: str | None = None

    def __post_init__(self) -> None:
        _set(self, "items", tuple(self.items))
        _set(self, "offset", _pt(self.offset))


Item: TypeAlias = Segment | Polyline | Circle | Arrow | Text | Hatch | Blank | Group


@dataclass(frozen=True, slots=True)
class Layer:
    """A named layer; the name becomes the SVG id ``layer-NAME`` and class ``NAME``.

    ``style``: the layer's own :class:`~drawing.styles.Style` (its colour, widths and
    dashes), where it is not the drawing's: a picture in two colours draws each in its
    layers; a sheet's layers have none.
    """

    name: str
    items: tuple[Item, ...] = ()
    style: Style | None = None

    def __post_init__(self) -> None:
        if not _LAYER_NAME.match(self.name):
            raise ValueError(
                f"layer name must match [A-Za-z][A-Za-z0-9_-]*, got {self.name!r}"
            )
        _set(self, "items", tuple(self.items))


@dataclass(frozen=True, slots=True)
class Page:
    """A drawing's page that is not a GOST sheet: ``width`` × ``height`` in ``unit`` ("px"
    for a picture on screen, "mm"), the origin at its top-left corner.

    >>> Page(748, 1000).unit
    'px'
    """

    width: float
    height: float
    unit: str = "px"


@dataclass(frozen=True, slots=True)
class Scene:
    """Layers in drawing order (the first is drawn first, i.e. lowest)."""

    layers: tuple[Layer, ...] = ()

    def __post_init__(self) -> None:
        _set(self, "layers", tuple(self.layers))

    @staticmethod
    def concat(*scenes: Scene) -> Scene:
        """One scene from several; layers of the same name are joined in order.

        A layer keeps the place of its first appearance, so the frame built
        first stays under everything added later.
        """
        names: list[str] = []
        items: dict[str, list[Item]] = {}
        for scene in scenes:
            for layer in scene.layers:
                if layer.name not in items:
                    names.append(layer.name)
                    items[layer.name] = []
                items[layer.name].extend(layer.items)
        styles = {}
        for scene in scenes:
            for layer in scene.layers:
                styles.setdefault(layer.name, layer.style)
        return Scene(tuple(Layer(n, tuple(items[n]), styles[n]) for n in names))

    def __add__(self, other: Scene) -> Scene:
        return Scene.concat(self, other)

    def layer(self, name: str) -> Layer:
        """The layer called ``name`` (``KeyError`` if absent)."""
        for layer in self.layers:
            if layer.name == name:
                return layer
        raise KeyError(name)

    def items(self, layer: str | None = None) -> tuple[Item, ...]:
        """All primitives (of layer ``layer`` if given); groups flattened."""
        layers = self.layers if layer is None else (self.layer(layer),)
        return flatten(item for lay in layers for item in lay.items)


def translate(item: Item, dx: float, dy: float) -> Item:
    """``item`` moved by ``(dx, dy)`` mm.

    >>> translate(Segment((0, 0), (1, 1)), 5, 0).p1
    (5.0, 0.0)
    """

    def mv(p: Point) -> Point:
        return (p[0] + dx, p[1] + dy)

    if isinstance(item, Segment | Arrow | Hatch | Blank):
        return replace(item, p1=mv(item.p1), p2=mv(item.p2))
    if isinstance(item, Polyline):
        return replace(item, points=tuple(mv(p) for p in item.points))
    if isinstance(item, Circle):
        return replace(item, center=mv(item.center))
    if isinstance(item, Text):
        return replace(item, pos=mv(item.pos))
    if isinstance(item, Group):
        return replace(item, offset=mv(item.offset))
    raise TypeError(f"not a drawing item: {type(item).__name__}")


def flatten(items: Iterable[Item]) -> tuple[Item, ...]:
    """The primitives of ``items`` with every group's offset applied."""

    def walk(its: Iterable[Item], dx: float, dy: float) -> Iterator[Item]:
        for it in its:
            if isinstance(it, Group):
                yield from walk(it.items, dx + it.offset[0], dy + it.offset[1])
            else:
                yield translate(it, dx, dy) if (dx or dy) else it

    return tuple(walk(items, 0.0, 0.0))
