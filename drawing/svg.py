"""Scene → SVG text.  The only module that imports svgwrite.

The root ``<svg>`` measures the sheet in real millimetres (``width="841mm"``)
and its ``viewBox`` counts millimetres too, so one user unit is one mm.  Every
layer is an Inkscape layer ``<g id="layer-NAME" class="NAME">``.  Every number
goes through :func:`fmt` (0.01 mm, trailing zeros stripped), which keeps the
output stable enough to diff.  User strings reach the file only as element text
or attribute values, which svgwrite's ElementTree escapes.

>>> fmt(12.0), fmt(0.125), fmt(-0.001), fmt(3.14159)
('12', '0.12', '0', '3.14')
"""

from __future__ import annotations

import base64
import math
import re
from functools import cache
from pathlib import Path

import svgwrite
from svgwrite.base import BaseElement

from drawing.scene import (
    INDEX_SIZE,
    SUB_SHIFT,
    SUP_SHIFT,
    Arrow,
    Blank,
    Circle,
    Group,
    Hatch,
    Item,
    Page,
    Point,
    Polyline,
    Scene,
    Segment,
    Text,
)
from drawing.sheet.frame import Sheet
from drawing.styles import FONT_FILE, LineType, Style

__all__ = ["FONT_FILE", "fmt", "to_svg"]

INKSCAPE_NS = "http://www.inkscape.org/namespaces/inkscape"
_CHAINS = (LineType.DASH_DOT_THIN, LineType.DASH_DOUBLE_DOT_THIN)
# characters XML 1.0 cannot carry at all (they would make the file unreadable)
_XML_INVALID = re.compile("[\x00-\x08\x0b\x0c\x0e-\x1f\ufffe\uffff\ud800-\udfff]")


def fmt(x: float) -> str:
    """``x`` rounded to 0.01 with trailing zeros (and a negative zero) removed."""
    if not math.isfinite(x):
        raise ValueError(f"cannot write a non-finite coordinate {x!r} to SVG")
    s = f"{x:.2f}".rstrip("0").rstrip(".")
    return "0" if s in ("-0", "") else s


def _pts(points: tuple[Point, ...] | list[Point]) -> list[tuple[str, str]]:
    """Points pre-formatted: svgwrite writes a shape's points with ``%s``."""
    return [(fmt(x), fmt(y)) for x, y in points]


def _clean(text: str) -> str:
    """Text as SVG may hold it: XML's invalid characters as U+FFFD, and the bidi controls
    (U+202E, U+2066 …: a name could turn the drawn text around it) dropped."""
    return re.sub("[\u061c\u200e\u200f\u202a-\u202e\u2066-\u2069]", "", _XML_INVALID.sub("\ufffd", text))


@cache
def _font_css(path: Path) -> str:
    data = base64.b64encode(path.read_bytes()).decode("ascii")
    return (
        "@font-face{font-family:'osifont';font-style:normal;font-weight:normal;"
        f"src:url(data:font/ttf;base64,{data}) format('truetype');}}"
    )


def _chain_dashes(
    length: float, pattern: tuple[float, ...]
) -> tuple[float, ...] | None:
    """Stretch a dash-dot pattern so a line of ``length`` starts and ends with a dash.

    GOST 2.303 wants chain lines to begin and end with strokes; a line shorter
    than one dash is drawn solid (as a centre line of a small circle is).
    """
    dash, period = pattern[0], sum(pattern)
    if length < dash:
        return None
    n = round((length - dash) / period)
    if n == 0:
        return None
    k = length / (n * period + dash)
    return tuple(p * k for p in pattern)


class _Writer:
    """Turns primitives into svgwrite elements under one style."""

    def __init__(self, dwg: svgwrite.Drawing, style: Style) -> None:
        self.dwg, self.style = dwg, style

    def stroke(
        self, el: BaseElement, line: LineType, dashes: tuple[float, ...] | None = None
    ) -> BaseElement:
        el["stroke-width"] = fmt(self.style.width(line))
        dashes = dashes if dashes is not None else self.style.dasharray(line)
        if dashes:
            el["stroke-dasharray"] = ",".join(fmt(d) for d in dashes)
            el["stroke-linecap"] = (
                "butt"  # round caps would lengthen every dash and dot
            )
        return el

    def line(self, p1: Point, p2: Point, line: LineType) -> BaseElement:
        el = self.dwg.line()
        el.attribs.update(x1=fmt(p1[0]), y1=fmt(p1[1]), x2=fmt(p2[0]), y2=fmt(p2[1]))
        dashes = None
        if line in _CHAINS:
            # () = solid: the line is too short for one dash-dot period
            dashes = _chain_dashes(math.dist(p1, p2), self.style.dasharray(line)) or ()
        return self.stroke(el, line, dashes)

    def item(self, it: Item) -> list[BaseElement]:
        dwg, st = self.dwg, self.style
        if isinstance(it, Segment):
            return [self.line(it.p1, it.p2, it.line)]
        if isinstance(it, Polyline):
            el = (dwg.polygon if it.closed else dwg.polyline)(_pts(it.points))
            return [self.stroke(el, it.line)]
        if isinstance(it, Circle):
            el = dwg.circle()
            el.attribs.update(cx=fmt(it.center[0]), cy=fmt(it.center[1]), r=fmt(it.r))
            if it.fill:
                el["fill"] = it.fill
            return [self.stroke(el, it.line)]
        if isinstance(it, Arrow):
            out = []
            if (shaft := it.shaft()) is not None:
                out.append(self.line(*shaft, it.line))
            if (head := it.head()) is not None:
                el = dwg.polygon(_pts(list(head)))
                el.attribs.update(fill=st.color, stroke="none")
                out.append(el)
            return out
        if isinstance(it, Hatch):
            out = []
            if strokes := it.strokes():
                d = " ".join(
                    f"M{fmt(a[0])},{fmt(a[1])}L{fmt(b[0])},{fmt(b[1])}"
                    for a, b in strokes
                )
                el = dwg.path(d=d)
                out.append(self.stroke(el, it.line))
            if it.base is not None:
                out.append(self.line(it.p1, it.p2, it.base))
            return out
        if isinstance(it, Text):
            return [self.text(it)]
        if isinstance(it, Blank):
            el = dwg.rect()
            el.attribs.update(x=fmt(it.p1[0]), y=fmt(it.p1[1]), width=fmt(it.p2[0] - it.p1[0]),
                              height=fmt(it.p2[1] - it.p1[1]), fill="white", stroke="none")
            return [el]
        if isinstance(it, Group):
            g = dwg.g()
            if it.name:
                g["class"] = it.name
            if it.offset != (0.0, 0.0):
                g["transform"] = f"translate({fmt(it.offset[0])} {fmt(it.offset[1])})"
            for sub in it.items:
                for el in self.item(sub):
                    g.add(el)
            return [g]
        raise TypeError(f"not a drawing item: {type(it).__name__}")

    def fill_runs(self, el: BaseElement, t: Text) -> None:
        """Plain text, or one ``<tspan>`` per run shifted by ``dy`` for indices."""
        runs = t.runs()
        if all(r.level == 0 for r in runs):
            el.text = _clean("".join(r.text for r in runs))
            return
        el.text = ""
        small = fmt(t.size * INDEX_SIZE / self.style.cap_height)
        shift = {0: 0.0, -1: SUB_SHIFT * t.size, 1: -SUP_SHIFT * t.size}
        now = 0.0
        for r in runs:
            span = self.dwg.tspan(_clean(r.text))
            if r.level:
                span["font-size"] = small
            if (dy := shift[r.level] - now) != 0:
                span["dy"] = fmt(dy)
            now = shift[r.level]
            el.add(span)

    def text(self, t: Text) -> BaseElement:
        """A ``<text>``; the slant is a shear about the capitals' middle line.

        Shearing about the middle (not the baseline) keeps slanted text centred
        where the upright estimate of :mod:`drawing.labels` puts it.  A plain
        upright text is written with ``x``/``y`` only.
        """
        el = self.dwg.text("")
        h = t.size
        self.fill_runs(el, t)
        el["font-size"] = fmt(h / self.style.cap_height)
        if t.anchor != "start":
            el["text-anchor"] = t.anchor
        el.attribs.update(fill=self.style.color, stroke="none")
        x, y = t.pos
        # origin of the glyph transform: the caps' middle line if slanted, else pos
        lift, baseline = (
            (t.baseline_shift - h / 2, h / 2) if t.italic else (0.0, t.baseline_shift)
        )
        if not (t.italic or t.rotate_deg or t.stretch != 1):
            el.attribs.update(x=fmt(x), y=fmt(y + baseline))
            return el
        if t.rotate_deg:
            ops = [f"translate({fmt(x)} {fmt(y)})", f"rotate({fmt(t.rotate_deg)})"]
            if fmt(lift) != "0":
                ops.append(f"translate(0 {fmt(lift)})")
        else:
            ops = [f"translate({fmt(x)} {fmt(y + lift)})"]
        if t.italic:
            ops.append(f"skewX({fmt(self.style.skew_deg)})")
        if t.stretch != 1:
            ops.append(f"scale({fmt(t.stretch)} 1)")
        el["transform"] = " ".join(ops)
        el["y"] = fmt(baseline)
        return el


def to_svg(
    scene: Scene,
    sheet: Sheet | Page,
    style: Style | None = None,
    title: str | None = None,
    embed_font: bool = True,
) -> str:
    """The SVG document of ``scene`` drawn on ``sheet`` (in mm), or on a :class:`Page`
    in its own unit (a picture measured in px). A layer with a style of its own is drawn
    in it, the others in ``style``.

    Args:
        title: the document's ``<title>`` (shown by viewers; escaped).
        embed_font: embed osifont as a base64 ``@font-face`` (≈155 kB) so the
            sheet looks the same where the font is not installed.
    """
    style = style or Style()
    w, h = fmt(sheet.width), fmt(sheet.height)
    unit = sheet.unit if isinstance(sheet, Page) else "mm"
    dwg = svgwrite.Drawing(size=(f"{w}{unit}", f"{h}{unit}"), profile="full", debug=False)
    dwg["viewBox"] = f"0 0 {w} {h}"
    dwg["xmlns:inkscape"] = INKSCAPE_NS
    if title is not None:
        dwg.set_desc(title=_clean(title))
    if embed_font:
        dwg.defs.add(dwg.style(_font_css(FONT_FILE)))
    for layer in scene.layers:
        own = layer.style or style
        writer = _Writer(dwg, own)
        g = dwg.g(id=f"layer-{layer.name}")
        g.attribs.update(
            {
                "class": layer.name,
                "inkscape:groupmode": "layer",
                "inkscape:label": layer.name,
                "fill": "none",
                "stroke": own.color,
                "stroke-linecap": "round",
                "stroke-linejoin": "round",
                "font-family": own.font_css,
            }
        )
        for item in layer.items:
            for el in writer.item(item):
                g.add(el)
        dwg.add(g)
    return '<?xml version="1.0" encoding="utf-8"?>\n' + dwg.tostring() + "\n"
