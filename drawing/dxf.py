"""Scene → DXF bytes.  The only module that imports ezdxf (the ``dxf`` extra).

The DXF is the SVG's twin: it is written from the same display list
(:class:`~drawing.scene.Scene`) by the same walk over its primitives as
:mod:`drawing.svg`, so there is no second drawing code.  What a CAD program needs
beyond the picture is added here:

* **1:1 in millimetres**: ``$INSUNITS`` = mm, one drawing unit one sheet millimetre,
  the sheet's corner at (0, 0) and y up (the sheet's y runs down: y ↦ height − y).
* **GOST 2.303 line types as DXF line types** with their widths as line weights:
  solid main *s* = 0.7 mm, solid thin 0.35 mm, dashed, dash-dot and dash-double-dot
  thin, each pattern the one the SVG dashes with (:meth:`Style.dasharray`).  A chain
  line is stretched by its own line-type scale so that it starts and ends with a dash,
  as the SVG stretches its dashes; one shorter than a period is solid, as there.
* **One layer per view and per line kind**, named in the sheet's language so that a
  user can switch them: "velocity plan - main", "План скоростей - тонкая",
  "title block - text" (:func:`layer_name`).  Every entity is BYLAYER.
* **Texts** as TEXT, or as MTEXT where they carry indices (``V_{BA}``: AutoCAD's own
  subscript code ``\\S^BA;``, the stack at 70 % as GOST's indices are), in the text
  style ``GOST`` that names the GOST type B font (:data:`FONT_FILE`) and leaves the
  reader to substitute its own where it has none.  Every text is anchored where the
  SVG anchors it: the start, middle or end of its baseline, slanted 75° about it.
* **Arrow heads** as solid hatches; a white joint or the break under a dimension's
  value as a WIPEOUT, which covers what lies under it as the SVG's white fill does.

The file is DXF R2010 (AC1024, UTF-8), which AutoCAD 2010 and later, КОМПАС-3D,
LibreCAD and ezdxf read; its bytes depend only on the scene (no date, no random id),
so a sheet's DXF is reproducible as its SVG is.

>>> from drawing.scene import Layer, Scene, Segment
>>> data = to_dxf(Scene((Layer("frame", (Segment((20, 5), (836, 5)),)),)), Page(841, 594, "mm"))
>>> data[:10], b"AC1024" in data
(b'  0\\nSECTIO', True)
"""

from __future__ import annotations

import io
import math
import re
from collections.abc import Iterator
from types import ModuleType

from drawing.scene import (
    Arrow,
    Blank,
    Circle,
    Group,
    Hatch,
    Item,
    Layer,
    Page,
    Point,
    Polyline,
    Scene,
    Segment,
    Text,
    flatten,
)
from drawing.sheet.frame import Sheet
from drawing.styles import LineType, Style
from plans.errors import PlansError

__all__ = [
    "DXF_VERSION",
    "FONT_FAMILY",
    "FONT_FILE",
    "KINDS",
    "DxfUnavailableError",
    "layer_name",
    "require",
    "to_dxf",
    "view_layers",
]

DXF_VERSION = "R2010"
#: the text style's font, by file and by family name: OpenGost Type B, a free GOST 2.304
#: type B with the Cyrillic and Greek letters and the ∥ and ⊥ of the notation. LibreCAD
#: has it as its own and finds it by the style's name, which is therefore the font's;
#: КОМПАС-3D, which has no font of that name, sets the texts in its own default font
#: (GOST type A), AutoCAD in the font its FONTALT names
FONT_FILE = "OpenGostTypeB-Regular.ttf"
FONT_FAMILY = "OpenGost Type B TT"
#: the one text style: GOST type B slanted 75° (oblique 15°). A TEXT keeps its own slant
#: (an upright one, in a table, 0°); an MTEXT, which has no slant of its own that every
#: reader reads, takes the style's
TEXT_STYLE = "OpenGostTypeB-Regular"

_HINT = "DXF export needs ezdxf: pip install 'vector-plans[dxf]'"


class DxfUnavailableError(PlansError, ImportError):
    """ezdxf is missing: a setup problem the user can fix (exit 2 with the pip
    command), not an internal error."""


def require() -> None:
    """Fail before anything is computed or written when DXF export cannot work here."""
    _ezdxf()


def _ezdxf() -> ModuleType:
    try:
        import ezdxf
    except ImportError as exc:
        raise DxfUnavailableError(f"{_HINT} ({exc})") from exc
    return ezdxf


# ------------------------------------------------------------------- layers

#: the line kinds a layer holds, in the order their layers are listed: (key, the
#: GOST 2.303 line type, or None for texts)
KINDS: tuple[tuple[str, LineType | None], ...] = (
    ("main", LineType.MAIN),
    ("thin", LineType.THIN),
    ("dashed", LineType.DASHED),
    ("dash-dot", LineType.DASH_DOT_THIN),
    ("dash-dot-dot", LineType.DASH_DOUBLE_DOT_THIN),
    ("text", None),
)
_KIND_OF = {line: key for key, line in KINDS if line is not None}

_KIND_WORDS = {
    "en": {"main": "main", "thin": "thin", "dashed": "dashed", "dash-dot": "dash-dot",
           "dash-dot-dot": "dash-dot-dot", "text": "text"},
    "ru": {"main": "основная", "thin": "тонкая", "dashed": "штриховая",
           "dash-dot": "штрихпунктирная", "dash-dot-dot": "штрихпунктирная с двумя точками",
           "text": "текст"},
}
#: the views' names on a sheet (the first word of a view's name: "velocity-3" is the
#: velocity plan of position 3, "velocity-g" that of the position the file gives)
_VIEW_WORDS = {
    "en": {"frame": "frame", "title-block": "title block", "positions": "plan of positions",
           "velocity": "velocity plan", "acceleration": "acceleration plan",
           "force": "force plan", "forces": "force plans", "lever": "Zhukovsky's lever",
           "diagrams": "kinematic diagrams", "segments": "table of segments",
           "angular": "table of angular velocities", "note": "note", "views": "views"},
    "ru": {"frame": "Рамка", "title-block": "Основная надпись", "positions": "План положений",
           "velocity": "План скоростей", "acceleration": "План ускорений",
           "force": "План сил", "forces": "Планы сил", "lever": "Рычаг Жуковского",
           "diagrams": "Кинематические диаграммы", "segments": "Таблица отрезков",
           "angular": "Таблица угловых скоростей", "note": "Примечание", "views": "Виды"},
}
#: characters a DXF layer name cannot hold
_BAD_NAME = re.compile(r'[<>/\\":;?*|=`,\x00-\x1f]')


def layer_name(view: str, kind: str, lang: str = "en") -> str:
    """The DXF layer of the line kind ``kind`` (a key of :data:`KINDS`) of the view
    ``view`` (a scene layer's name, or a placed view's), in ``lang``.

    >>> layer_name("velocity-g", "main"), layer_name("velocity-3", "thin", "ru")
    ('velocity plan - main', 'План скоростей 3 - тонкая')
    >>> layer_name("title-block", "text", "ru"), layer_name("my-view", "dashed")
    ('Основная надпись - текст', 'my-view - dashed')
    """
    words = _VIEW_WORDS.get(lang, _VIEW_WORDS["en"])
    head, _, tag = view.partition("-")
    if view in words:
        name = words[view]
    elif head in words:
        name = words[head] if tag in ("", "g") else f"{words[head]} {tag}"
    else:
        name = view
    kinds = _KIND_WORDS.get(lang, _KIND_WORDS["en"])
    return _BAD_NAME.sub("_", f"{name} - {kinds[kind]}")


def view_layers(scene: Scene) -> Iterator[tuple[str, Layer, tuple[Item, ...]]]:
    """(view name, its scene layer, its primitives with every offset applied) of each
    view of ``scene``: a placed view (a group named "view NAME", as
    :meth:`drawing.sheet.layout.Placed.group` names it) is a view of its own, anything
    else belongs to its scene layer's view."""
    for layer in scene.layers:
        loose: list[Item] = []
        for item in layer.items:
            if isinstance(item, Group) and item.name and item.name.startswith("view "):
                if loose:
                    yield layer.name, layer, flatten(loose)
                    loose = []
                yield item.name[5:], layer, flatten((item,))
            else:
                loose.append(item)
        if loose:
            yield layer.name, layer, flatten(loose)


# ------------------------------------------------------------------ writer

#: DXF line weights (1/100 mm) a reader accepts
_WEIGHTS = (0, 5, 9, 13, 15, 18, 20, 25, 30, 35, 40, 50, 53, 60, 70, 80, 90, 100, 106, 120,
            140, 158, 200, 211)
_LINETYPES = {LineType.DASHED: "GOST_DASHED", LineType.DASH_DOT_THIN: "GOST_DASH_DOT",
              LineType.DASH_DOUBLE_DOT_THIN: "GOST_DASH_DOT_DOT"}
_LINETYPE_WORDS = {LineType.DASHED: "GOST 2.303 dashed",
                   LineType.DASH_DOT_THIN: "GOST 2.303 dash-dot thin",
                   LineType.DASH_DOUBLE_DOT_THIN: "GOST 2.303 dash-double-dot thin"}
_CHAINS = (LineType.DASH_DOT_THIN, LineType.DASH_DOUBLE_DOT_THIN)
#: colours a scene names, as AutoCAD colour indices (7: black on paper, white on a
#: dark screen, as a drawing's lines are)
_ACI = {"black": 7, "red": 1, "yellow": 2, "green": 3, "cyan": 4, "blue": 5, "magenta": 6,
        "white": 7, "gray": 8, "grey": 8}
_CONTROL = re.compile("[\x00-\x1f\x7f\ufffe\uffff\ud800-\udfff]")
_ANCHOR = {"start": "LEFT", "middle": "CENTER", "end": "RIGHT"}
_MTEXT_ANCHOR = {"start": 7, "middle": 8, "end": 9}  # BOTTOM_LEFT, _CENTER, _RIGHT


def _weight(mm: float) -> int:
    """The DXF line weight nearest ``mm``: 0.7 → 70, 0.35 → 35."""
    return min(_WEIGHTS, key=lambda w: abs(w - mm * 100))


def _color(name: str) -> tuple[int, tuple[int, int, int] | None]:
    """The colour a style names as a DXF colour index, and as a true colour where it
    is one ("#rrggbb"); a name it does not know is black (7).

    >>> _color("black"), _color("#2060c0")
    ((7, None), (7, (32, 96, 192)))
    """
    name = name.strip().lower()
    if re.fullmatch(r"#[0-9a-f]{3}", name):  # "#ddd" is "#dddddd"
        name = "#" + "".join(c * 2 for c in name[1:])
    m = re.fullmatch(r"#([0-9a-f]{2})([0-9a-f]{2})([0-9a-f]{2})", name)
    if m:
        return 7, (int(m.group(1), 16), int(m.group(2), 16), int(m.group(3), 16))
    return _ACI.get(name, 7), None


def _chain_scale(length: float, pattern: tuple[float, ...]) -> float | None:
    """The line-type scale that stretches a chain line of ``length`` to start and end
    with a dash (as :func:`drawing.svg._chain_dashes` stretches its dashes), or None
    where it is drawn solid (shorter than one dash, or than a period and a dash)."""
    dash, period = pattern[0], sum(pattern)
    if length < dash:
        return None
    n = round((length - dash) / period)
    if n == 0:
        return None
    return length / (n * period + dash)


def _caret(s: str) -> str:
    """A DXF string's carets: "^X" is a control character in a DXF file, "^ " a caret."""
    return s.replace("^", "^ ")


def _text(s: str) -> str:
    """A text as a TEXT entity holds it: no control characters, and AutoCAD's "%%"
    codes (%%c is ⌀, %%d °) and carets written so that they read as the characters.

    >>> _text("a^2 %% b")
    'a^ 2 %%%%%% b'
    """
    return _caret(_CONTROL.sub("\ufffd", s).replace("%%", "%%%%%%"))


def _mtext(s: str) -> str:
    """A piece of an MTEXT's content: its format codes' characters escaped."""
    s = _CONTROL.sub("\ufffd", s)
    return s.replace("\\", "\\\\").replace("{", "\\{").replace("}", "\\}")


def _stacked(s: str) -> str:
    """A piece of an MTEXT stack (after ``\\S``): its separators escaped too."""
    return re.sub(r"([\^/#;])", r"\\\1", _mtext(s))


class _Writer:
    """Puts a scene's primitives into a DXF document's modelspace."""

    def __init__(self, doc, style: Style, height: float, lang: str) -> None:
        self.doc, self.style, self.height, self.lang = doc, style, height, lang
        self.msp = doc.modelspace()
        self.layer = ""  # the view whose entities are being written
        self.made: set[str] = set()

    # coordinates: the sheet's y runs down, the DXF's up
    def xy(self, p: Point) -> tuple[float, float]:
        return (p[0], self.height - p[1])

    def on(self, kind: str, own: Style) -> dict:
        """The attributes of an entity on this view's layer of ``kind`` (made on first use)."""
        name = layer_name(self.layer, kind, self.lang)
        if name not in self.made:
            line = dict(KINDS)[kind]
            color, rgb = _color(own.color)
            layer = self.doc.layers.add(
                name, color=color, linetype=_LINETYPES.get(line, "Continuous") if line else "Continuous",
                lineweight=_weight(own.width(line or LineType.THIN)))
            if rgb is not None:
                layer.rgb = rgb
            self.made.add(name)
        return {"layer": name}

    def line(self, p1: Point, p2: Point, line: LineType, own: Style) -> None:
        attribs = self.on(_KIND_OF[line], own)
        if line in _CHAINS:
            k = _chain_scale(math.dist(p1, p2), own.dasharray(line) or ())
            if k is None:
                attribs["linetype"] = "Continuous"  # too short for one period: solid, as the SVG
            elif abs(k - 1) > 1e-9:
                attribs["ltscale"] = k
        self.msp.add_line(self.xy(p1), self.xy(p2), dxfattribs=attribs)

    def wipeout(self, points, kind: str, own: Style) -> None:
        wipeout = self.msp.add_wipeout([self.xy(p) for p in points])
        wipeout.dxf.layer = self.on(kind, own)["layer"]  # after its area, which resets it

    def item(self, it: Item, own: Style) -> None:
        if isinstance(it, Segment):
            self.line(it.p1, it.p2, it.line, own)
        elif isinstance(it, Polyline):
            attribs = self.on(_KIND_OF[it.line], own)
            pl = self.msp.add_lwpolyline([self.xy(p) for p in it.points], close=it.closed,
                                         dxfattribs=attribs)
            if it.line in _LINETYPES:  # one pattern along the whole chain, as the SVG dashes it
                pl.dxf.flags |= 128
        elif isinstance(it, Circle):
            if it.fill:  # a white joint hides what lies under it
                cx, cy = it.center
                n = 48
                self.wipeout([(cx + it.r * math.cos(2 * math.pi * i / n),
                               cy + it.r * math.sin(2 * math.pi * i / n)) for i in range(n)],
                             _KIND_OF[it.line], own)
            self.msp.add_circle(self.xy(it.center), it.r, dxfattribs=self.on(_KIND_OF[it.line], own))
        elif isinstance(it, Arrow):
            if (shaft := it.shaft()) is not None:
                self.line(*shaft, it.line, own)
            if (head := it.head()) is not None:
                hatch = self.msp.add_hatch(color=256, dxfattribs=self.on(_KIND_OF[it.line], own))
                hatch.paths.add_polyline_path([self.xy(p) for p in head], is_closed=True)
        elif isinstance(it, Hatch):
            for a, b in it.strokes():
                self.line(a, b, it.line, own)
            if it.base is not None:
                self.line(it.p1, it.p2, it.base, own)
        elif isinstance(it, Blank):
            (x0, y0), (x1, y1) = it.p1, it.p2
            self.wipeout([(x0, y0), (x1, y0), (x1, y1), (x0, y1)], "text", own)  # under a value
        elif isinstance(it, Text):
            self.text(it, own)
        elif isinstance(it, Group):  # flattened before: only a scene built by hand has one here
            for sub in flatten((it,)):
                self.item(sub, own)
        else:
            raise TypeError(f"not a drawing item: {type(it).__name__}")

    def text(self, t: Text, own: Style) -> None:
        """A TEXT (or an MTEXT with indices) anchored where the SVG anchors ``t``: the
        start, middle or end of its baseline, moved back by the slant of its middle line
        (the SVG slants its letters about their middle, a DXF about the baseline)."""
        h = t.size
        dx = -own.slant_tan * h / 2 if t.italic else 0.0
        dy = t.baseline_shift
        a = math.radians(t.rotate_deg)
        ax = t.pos[0] + dx * math.cos(a) - dy * math.sin(a)
        ay = t.pos[1] + dx * math.sin(a) + dy * math.cos(a)
        anchor = self.xy((ax, ay))
        rotation = -t.rotate_deg % 360.0
        oblique = 90.0 - own.slant_deg if t.italic else 0.0
        attribs = self.on("text", own)
        runs = t.runs()
        if all(r.level == 0 for r in runs):
            from ezdxf.enums import TextEntityAlignment

            entity = self.msp.add_text(_text("".join(r.text for r in runs)), height=h,
                                       rotation=rotation, dxfattribs={
                                           **attribs, "style": TEXT_STYLE, "oblique": oblique,
                                           "width": t.stretch})
            entity.set_placement(anchor, align=TextEntityAlignment[_ANCHOR[t.anchor]])
            return
        codes = f"\\W{t.stretch:g};" if t.stretch != 1 else ""
        # AutoCAD's sub- and superscript: a stack with nothing under or over it
        body = "".join(_mtext(r.text) if r.level == 0 else
                       f"\\S^{_stacked(r.text)};" if r.level < 0 else f"\\S{_stacked(r.text)}^;"
                       for r in runs)
        self.msp.add_mtext(_caret(codes + body), dxfattribs={
            **attribs, "style": TEXT_STYLE, "char_height": h, "insert": anchor,
            "rotation": rotation, "attachment_point": _MTEXT_ANCHOR[t.anchor]})


def _kinds(items: tuple[Item, ...]) -> set[str]:
    """The line kinds (keys of :data:`KINDS`) that ``items`` draw with."""
    out: set[str] = set()
    for it in items:
        if isinstance(it, Text | Blank):
            out.add("text")
        elif isinstance(it, Hatch):
            out.add(_KIND_OF[it.line])
            if it.base is not None:
                out.add(_KIND_OF[it.base])
        elif isinstance(it, Group):
            out |= _kinds(flatten((it,)))
        else:
            out.add(_KIND_OF[it.line])
    return out


def _setup(doc, sheet: Sheet | Page, style: Style) -> None:
    """Units, limits, the view of the whole sheet, the line types and the text style."""
    w, h = sheet.width, sheet.height
    mm = isinstance(sheet, Sheet) or sheet.unit == "mm"
    header = doc.header
    header["$INSUNITS"] = 4 if mm else 0  # millimetres (a picture in px: unitless)
    header["$MEASUREMENT"] = 1  # metric
    header["$LUNITS"] = 2  # decimal
    header["$LUPREC"] = 2
    msp = doc.modelspace()  # the header's limits and extents are written from its own
    msp.dxf.limmin, msp.dxf.limmax = (0.0, 0.0), (w, h)
    msp.dxf.extmin, msp.dxf.extmax = (0.0, 0.0, 0.0), (w, h, 0.0)
    header["$LTSCALE"] = 1.0
    header["$CELTSCALE"] = 1.0
    header["$LWDISPLAY"] = 1  # show the line weights: main and thin lines differ
    header["$TEXTSTYLE"] = TEXT_STYLE
    header["$TEXTSIZE"] = 3.5
    doc.set_modelspace_vport(height=h * 1.05, center=(w / 2, h / 2))
    for line, name in _LINETYPES.items():
        pattern = style.dasharray(line) or ()
        # DXF: the total length, then dashes positive and gaps negative
        doc.linetypes.add(name, pattern=[sum(pattern), *(d if i % 2 == 0 else -d
                                                         for i, d in enumerate(pattern))],
                          description=_LINETYPE_WORDS[line])
    st = doc.styles.add(TEXT_STYLE, font=FONT_FILE)
    st.dxf.oblique = 90.0 - style.slant_deg
    st.set_extended_font_data(FONT_FAMILY)
    doc.set_wipeout_variables(frame=0)  # a wipeout's outline is not drawn


def to_dxf(
    scene: Scene,
    sheet: Sheet | Page,
    style: Style | None = None,
    title: str | None = None,
    lang: str = "en",
) -> bytes:
    """The DXF document of ``scene`` drawn on ``sheet`` (in mm), as bytes (UTF-8).

    A layer with a style of its own is drawn in its colour and widths, the others in
    ``style``.  ``title`` is kept as the drawing's custom property "Title";
    ``lang`` is the language of the layers' names (ru, en).
    """
    ezdxf = _ezdxf()
    style = style or Style()
    fixed = ezdxf.options.write_fixed_meta_data_for_testing
    ezdxf.options.write_fixed_meta_data_for_testing = True  # no date, no random id
    try:
        doc = ezdxf.new(DXF_VERSION, setup=False, units=4)
        _setup(doc, sheet, style)
        if title:  # a drawing property, as AutoCAD's DWGPROPS shows it
            doc.header.custom_vars.append("Title", _CONTROL.sub(" ", title))
        writer = _Writer(doc, style, sheet.height, lang)
        for view, layer, items in view_layers(scene):
            writer.layer = view
            own = layer.style or style
            used = _kinds(items)
            for kind, _ in KINDS:  # a view's layers listed in one order: main, thin, …, text
                if kind in used:
                    writer.on(kind, own)
            for item in items:
                writer.item(item, own)
        # the classes of the entity types used, in one order: ezdxf adds them from a set,
        # whose order changes from run to run
        for name in sorted(doc.entitydb.dxf_types_in_use()):
            doc.classes.add_class(name)
        out = io.StringIO()
        doc.write(out)
    finally:
        ezdxf.options.write_fixed_meta_data_for_testing = fixed
    return out.getvalue().encode("utf-8")
