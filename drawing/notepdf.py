"""The explanatory note as PDF: the only module that imports fpdf2 (the ``pdf`` extra).

The same :class:`~drawing.document.Document` the DOCX is made of, set by this module's
own line layout on A4 pages in the DOCX's measures (GOST 2.105 margins, 14 pt at one
and a half lines, paragraphs indented 12.5 mm, sections numbered): the formulas as
formulas (a fraction's bar, indices at 0.7 of the letters and below or above them,
a root's sign, a vector's arrow, brackets as tall as what they hold), a long step
broken before its "=" (or, inside a long bracket, before a "+"). The letters are
STIX, a Times-like face whose Cyrillic, Greek and mathematical signs are all in one
font, which matplotlib ships; fpdf2 embeds the letters used. On request every page
has the text document's frame and title block, form 2 on the first and 2a on the
others (:mod:`drawing.sheet.forms`), drawn with the sheet's line widths.

The file's bytes depend on the note alone: a fixed creation date.
"""

from __future__ import annotations

import datetime
import importlib.util
import re
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from types import ModuleType

from drawing.document import Document, Formula, Heading, Paragraph, Piece, Table
from drawing.formula import Fence, Frac, Node, Radical, Run, Script, Vector, split_lines
from drawing.sheet.forms import FORM2, FORM2A, Form, cell_text
from drawing.sheet.frame import TitleBlock
from drawing.styles import Style
from plans.errors import PlansError

__all__ = ["PdfUnavailableError", "font_files", "require", "to_pdf"]

_HINT = "the note's PDF needs fpdf2: pip install 'vector-plans[pdf]'"
SIZE_PT = 14.0
PT = 25.4 / 72  # mm in a point
LEADING = 1.5
INDENT = 12.5
MARGINS = {False: (30.0, 10.0, 15.0, 20.0), True: (25.0, 10.0, 15.0, 15.0)}
_BINARY = {"=", "≈", "≥", "≤", "→", "∥", "⊥", "<", ">", "∠"}
_TERMS = {"+", "−", "±"}


class PdfUnavailableError(PlansError, ImportError):
    """fpdf2 (or its fonts) is missing: a setup problem the user can fix (exit 2 with
    the pip command), not an internal error."""


def _fpdf() -> ModuleType:
    try:
        import fpdf
    except ImportError as exc:
        raise PdfUnavailableError(f"{_HINT} ({exc})") from exc
    return fpdf


def font_files() -> dict[str, Path]:
    """The STIX faces matplotlib ships (regular, italic, bold, bold italic)."""
    spec = importlib.util.find_spec("matplotlib")
    if spec is None or not spec.submodule_search_locations:
        raise PdfUnavailableError("the note's PDF needs matplotlib's fonts: pip install matplotlib")
    folder = Path(next(iter(spec.submodule_search_locations))) / "mpl-data" / "fonts" / "ttf"
    files = {"": "STIXGeneral.ttf", "I": "STIXGeneralItalic.ttf", "B": "STIXGeneralBol.ttf",
             "BI": "STIXGeneralBolIta.ttf"}
    out = {style: folder / name for style, name in files.items()}
    missing = [str(p) for p in out.values() if not p.is_file()]
    if missing:
        raise PdfUnavailableError(f"the note's PDF needs matplotlib's STIX fonts; missing {missing[0]}")
    return out


def require() -> None:
    """Fail before anything is computed or written when the note's PDF cannot be made."""
    _fpdf()
    font_files()


# ------------------------------------------------------------------------- boxes


@dataclass
class Box:
    """Something set on a line: its width, height above and depth below the baseline
    (mm), and how to draw it with its origin at (x, baseline)."""

    w: float
    asc: float
    desc: float
    draw: Callable[[float, float], None]


class _Setter:
    """Boxes of formulas and words, on one FPDF document."""

    def __init__(self, pdf) -> None:
        self.pdf = pdf

    def font(self, style: str, size: float) -> None:
        self.pdf.set_font("STIX", style, size)

    def text(self, s: str, size: float, style: str = "") -> Box:
        self.font(style, size)
        w = self.pdf.get_string_width(s)
        em = size * PT

        def draw(x: float, y: float) -> None:
            self.font(style, size)
            self.pdf.text(x, y, s)

        return Box(w, 0.75 * em, 0.25 * em, draw)

    def row(self, boxes: list[Box], gaps: list[float] | None = None) -> Box:
        gaps = gaps or [0.0] * len(boxes)
        w = sum(b.w for b in boxes) + sum(gaps)
        asc = max((b.asc for b in boxes), default=0.0)
        desc = max((b.desc for b in boxes), default=0.0)

        def draw(x: float, y: float) -> None:
            for b, g in zip(boxes, gaps, strict=True):
                b.draw(x, y)
                x += b.w + g

        return Box(w, asc, desc, draw)

    def run(self, r: Run, size: float) -> Box:
        if r.kind == "var":  # Latin letters italic, the rest upright
            parts = re.findall(r"[A-Za-z]+|[^A-Za-z]+", r.text)
            return self.row([self.text(p, size, "I" if p[0].isascii() and p[0].isalpha() else "")
                             for p in parts])
        return self.text(r.text, size)

    def math(self, nodes: tuple[Node, ...], size: float, display: bool = True) -> Box:
        """``nodes`` set at ``size`` pt, operators spaced as mathematics spaces them."""
        em = size * PT
        boxes: list[Box] = []
        gaps: list[float] = []
        prev: Node | None = None
        for n in nodes:
            before = 0.0
            if isinstance(n, Run) and n.kind == "op":
                binary = n.text in _BINARY or (n.text in _TERMS and prev is not None and not (
                    isinstance(prev, Run) and prev.kind in ("op", "punct", "bracket")))
                before = 0.22 * em if binary else 0.08 * em if n.text == "·" else 0.0
                if n.text == "·":
                    before = 0.06 * em
            elif isinstance(n, Run) and n.kind == "text" and prev is not None and not (
                    isinstance(prev, Run) and prev.kind == "punct"):
                before = 0.25 * em
            if isinstance(prev, Run) and prev.kind == "text" and not (
                    isinstance(n, Run) and n.kind in ("punct", "op")):
                before = max(before, 0.25 * em)  # "на звено 1": a word and what follows it
            if gaps:
                gaps[-1] += before
            box = self.node(n, size, display)
            boxes.append(box)
            after = 0.0
            if isinstance(n, Run) and n.kind == "op":
                after = before
            elif isinstance(n, Run) and n.kind == "punct":
                after = 0.25 * em
            gaps.append(after)
            prev = n
        if gaps:
            gaps[-1] = 0.0
        return self.row(boxes, gaps)

    def node(self, n: Node, size: float, display: bool) -> Box:
        em = size * PT
        if isinstance(n, Run):
            return self.run(n, size)
        if isinstance(n, Script):
            return self.script(n, size, display)
        if isinstance(n, Frac):
            small = size if display else size * 0.85
            num, den = self.math(n.num, small, display), self.math(n.den, small, display)
            w = max(num.w, den.w) + 0.2 * em
            axis, gap = 0.27 * em, 0.14 * em
            asc = axis + gap + num.desc + num.asc
            desc = -axis + gap + den.asc + den.desc

            def draw(x: float, y: float) -> None:
                bar = y - axis
                num.draw(x + (w - num.w) / 2, bar - gap - num.desc)
                den.draw(x + (w - den.w) / 2, bar + gap + den.asc)
                self.pdf.set_line_width(0.05 * em)
                self.pdf.line(x + 0.05 * em, bar, x + w - 0.05 * em, bar)

            return Box(w + 0.1 * em, asc, max(desc, 0.25 * em), draw)
        if isinstance(n, Radical):
            body = self.math(n.body, size, display)
            lead = 0.55 * em

            def draw(x: float, y: float) -> None:
                top = y - body.asc - 0.12 * em
                bottom = y + body.desc
                self.pdf.set_line_width(0.05 * em)
                self.pdf.polyline([(x, y - 0.35 * em), (x + 0.15 * em, y - 0.45 * em),
                                   (x + 0.3 * em, bottom), (x + lead - 0.05 * em, top),
                                   (x + lead + body.w + 0.05 * em, top)])
                body.draw(x + lead, y)

            return Box(body.w + lead + 0.1 * em, body.asc + 0.2 * em, body.desc, draw)
        if isinstance(n, Vector):
            body = self.math(n.body, size, display)

            def draw(x: float, y: float) -> None:
                body.draw(x, y)
                top = y - body.asc - 0.1 * em
                x0, x1 = x + 0.1 * em, x + max(body.w, 0.5 * em) + 0.05 * em
                self.pdf.set_line_width(0.04 * em)
                self.pdf.line(x0, top, x1, top)
                self.pdf.polygon([(x1 + 0.05 * em, top), (x1 - 0.15 * em, top - 0.07 * em),
                                  (x1 - 0.15 * em, top + 0.07 * em)], style="F")

            return Box(body.w, body.asc + 0.2 * em, body.desc, draw)
        if isinstance(n, Fence):
            body = self.math(n.body, size, display)
            tall = body.asc + body.desc
            scale = max(1.0, tall / (1.0 * em))
            opening, closing = self.text(n.open, size * scale), self.text(n.close, size * scale)
            # a tall bracket's middle on the formula's axis
            shift = (scale - 1) * 0.22 * em

            def draw(x: float, y: float) -> None:
                opening.draw(x, y + shift)
                body.draw(x + opening.w, y)
                closing.draw(x + opening.w + body.w, y + shift)

            return Box(opening.w + body.w + closing.w, max(body.asc, opening.asc - shift),
                       max(body.desc, opening.desc + shift), draw)
        raise TypeError(type(n).__name__)

    def script(self, n: Script, size: float, display: bool) -> Box:
        em = size * PT
        base = self.math(n.base, size, display)
        small = size * 0.7
        sub = self.math(n.sub, small, display) if n.sub else None
        sup = self.math(n.sup, small, display) if n.sup else None
        down, up = 0.22 * em, 0.42 * em
        w = base.w + max(sub.w if sub else 0.0, sup.w if sup else 0.0) + 0.03 * em
        asc = max(base.asc, up + sup.asc if sup else 0.0)
        desc = max(base.desc, down + sub.desc if sub else 0.0)

        def draw(x: float, y: float) -> None:
            base.draw(x, y)
            if sub:
                sub.draw(x + base.w + 0.02 * em, y + down)
            if sup:
                sup.draw(x + base.w + 0.02 * em, y - up)

        return Box(w, asc, desc, draw)


# ---------------------------------------------------------------------- the pages


class _Writer:
    def __init__(self, fpdf: ModuleType, note: Document, frame: bool, tb: TitleBlock | None,
                 pages: int = 0) -> None:
        self.note, self.frame, self.pages = note, frame, pages
        self.tb = tb or TitleBlock(name=note.title)
        pdf = fpdf.FPDF(orientation="P", unit="mm", format="A4")
        pdf.set_creation_date(datetime.datetime(2000, 1, 1, tzinfo=datetime.UTC))
        pdf.set_title(note.title)
        pdf.set_lang(note.lang if note.lang in ("en", "ru") else "en")
        if self.tb.developer:
            pdf.set_author(self.tb.developer)
        pdf.set_auto_page_break(False)
        for style, path in font_files().items():
            pdf.add_font("STIX", style, str(path))
        self.pdf = pdf
        self.setter = _Setter(pdf)
        self.left, self.right, self.top, self.bottom = MARGINS[frame]
        self.width = 210.0 - self.left - self.right
        self.em = SIZE_PT * PT
        self.y = 0.0
        self.new_page()

    # pages
    def limit(self) -> float:
        """The lowest baseline on this page: 10 mm above the title block in a frame."""
        if self.frame:
            form = FORM2 if self.pdf.page_no() == 1 else FORM2A
            return 297.0 - 5.0 - sum(form.rows) - 10.0
        return 297.0 - self.bottom

    def new_page(self) -> None:
        self.pdf.add_page()
        self.y = self.top
        if self.frame:
            self.draw_frame()

    def room(self, h: float) -> None:
        if self.y + h > self.limit():
            self.new_page()

    def draw_frame(self) -> None:
        pdf, style = self.pdf, Style()
        pdf.set_draw_color(0)
        pdf.set_line_width(style.s)
        pdf.rect(20.0, 5.0, 185.0, 287.0)
        form = FORM2 if pdf.page_no() == 1 else FORM2A
        x0, y0 = 20.0, 292.0 - sum(form.rows)
        for a, b, c, d, thin in form.lines():
            pdf.set_line_width(style.thin if thin else style.s)
            pdf.line(x0 + a, y0 + b, x0 + c, y0 + d)
        self.form_texts(form, x0, y0)

    def form_texts(self, form: Form, x0: float, y0: float) -> None:
        pdf = self.pdf
        for c in form.cells:
            text = cell_text(c.text, self.tb, self.note.lang, page=str(pdf.page_no()),
                             pages=str(self.pages or ""))
            if not text:
                continue
            x, y = x0 + form.x(c.col), y0 + form.y(c.row)
            w, h = form.x(c.col + c.cols) - form.x(c.col), form.y(c.row + c.rows) - form.y(c.row)
            size = c.size / 0.66 / PT  # a cap height of c.size mm
            pdf.set_font("STIX", "I", size)
            lines = [text]
            while pdf.get_string_width(max(lines, key=len)) > w - 1.0 and size > 5:
                if len(lines) == 1 and " " in text and c.rows * 5 >= 10:
                    words = text.split()
                    half = len(words) // 2 or 1
                    lines = [" ".join(words[:half]), " ".join(words[half:])]
                else:
                    size *= 0.9
                pdf.set_font("STIX", "I", size)
            step = size * PT * 1.15
            first = y + h / 2 - step * (len(lines) - 1) / 2 + c.size / 2
            for k, line in enumerate(lines):
                lw = pdf.get_string_width(line)
                tx = x + 1.0 if c.align == "start" else x + (w - lw) / 2
                pdf.text(tx, first + k * step, line)

    # lines of boxes
    def line(self, boxes: list[Box], gaps: list[float], x: float, extra: float = 0.0) -> None:
        asc = max((b.asc for b in boxes), default=0.75 * self.em)
        desc = max((b.desc for b in boxes), default=0.25 * self.em)
        lead = max(LEADING * self.em, asc + desc + 0.4 * self.em)
        self.room(lead)
        base = self.y + (lead - (asc + desc)) / 2 + asc
        for b, g in zip(boxes, gaps, strict=True):
            b.draw(x, base)
            x += b.w + g + (extra if g > 0 else 0.0)
        self.y += lead

    def words(self, pieces: tuple[Piece, ...], style: str = "") -> list[tuple[Box, bool]]:
        """(box, a space may follow it) of each word and formula."""
        out: list[tuple[Box, bool]] = []
        for p in pieces:
            if p.kind == "math":
                out.append((self.setter.math(p.nodes, SIZE_PT, display=False), False))
                continue
            st = ("B" if p.bold or "B" in style else "") + ("I" if "I" in style else "")
            if p.text[:1].isspace() and out:  # a space before it follows what came before
                out[-1] = (out[-1][0], True)
            for k, m in enumerate(re.finditer(r"(\S+)(\s*)", p.text)):
                box = self.setter.text(m.group(1), SIZE_PT, st)
                if k == 0 and out and not out[-1][1] and not p.text[:1].isspace():
                    box = self.setter.row([out.pop()[0], box])  # "φ_хх:" is one word
                out.append((box, bool(m.group(2))))
        return out

    def paragraph(self, pieces: tuple[Piece, ...], indent: float = INDENT, left: float = 0.0,
                  justify: bool = True, style: str = "", centre: bool = False) -> None:
        items = self.words(pieces, style)
        space = self.setter.text(" ", SIZE_PT).w
        lines: list[list[tuple[Box, bool]]] = [[]]
        width = self.width - left - indent
        used = 0.0
        for box, sp in items:
            need = box.w + (space if lines[-1] and lines[-1][-1][1] else 0.0)
            if lines[-1] and used + need > width:
                lines.append([])
                width, used = self.width - left, 0.0
                need = box.w
            lines[-1].append((box, sp))
            used += need
        for k, ln in enumerate(lines):
            if not ln:
                continue
            boxes = [b for b, _ in ln]
            gaps = [space if sp else 0.0 for _, sp in ln]
            gaps[-1] = 0.0
            x = self.left + left + (indent if k == 0 else 0.0)
            room = self.width - (x - self.left) - sum(b.w for b in boxes) - sum(gaps)
            spaces = sum(1 for g in gaps if g > 0)
            extra = room / spaces if justify and k < len(lines) - 1 and spaces else 0.0
            if centre:
                x += room / 2
            self.line(boxes, gaps, x, extra)

    def formula(self, f: Formula) -> None:
        left = INDENT * f.level
        limit = 64 - 8 * f.level
        while True:
            lines = split_lines(f.nodes, limit)
            boxes = [self.setter.math(line, SIZE_PT) for line in lines]
            if all(b.w <= self.width - left - INDENT for b in boxes) or limit < 20:
                break
            limit -= 6
        for k, box in enumerate(boxes):
            if len(boxes) == 1:
                x = self.left + left + (self.width - left - box.w) / 2
            else:
                x = self.left + INDENT + left + (INDENT if k else 0.0)
            self.line([box], [0.0], x)

    def heading(self, h: Heading) -> None:
        self.room(4 * LEADING * self.em)  # a heading is not left alone at a page's foot
        self.y += 4.0
        number = Piece("text", f"{h.number} ", bold=True)
        items = (number, *(Piece(p.kind, p.text, p.nodes, True) for p in h.pieces))
        self.paragraph(items, justify=False, style="B")
        self.y += 2.0

    def table(self, t: Table) -> None:
        cols = max(len(r) for r in t.rows)
        w = self.width / cols
        for i, row in enumerate(t.rows):
            boxes = [self.setter.row([b for b, _ in self.words(cell, "B" if i == 0 else "")])
                     for cell in row]
            h = max(b.asc + b.desc for b in boxes) + 2.0
            self.room(h)
            self.pdf.set_line_width(0.2)
            for j, b in enumerate(boxes):
                x = self.left + j * w
                self.pdf.rect(x, self.y, w, h)
                b.draw(x + 1.0, self.y + 1.0 + b.asc)
            self.y += h

    def body(self) -> None:
        self.paragraph((Piece("text", self.note.title, bold=True),), indent=0.0, justify=False,
                       style="B", centre=True)
        self.y += 4.0
        for b in self.note.blocks:
            if isinstance(b, Heading):
                self.heading(b)
            elif isinstance(b, Formula):
                self.formula(b)
            elif isinstance(b, Table):
                self.table(b)
            elif isinstance(b, Paragraph):
                if b.kind in ("item", "aside"):
                    lead = (Piece("text", "– "),) if b.kind == "item" else ()
                    self.paragraph((*lead, *b.pieces), indent=0.0, left=INDENT * (1 + b.level),
                                   justify=False)
                else:
                    self.paragraph(b.pieces, justify=b.kind == "body",
                                   style="B" if b.kind == "group" else "I" if b.kind == "note" else "")


def to_pdf(note: Document, frame: bool = False, title_block: TitleBlock | None = None) -> bytes:
    """The note as the bytes of a PDF file; ``frame``: with the text document's frame
    and title block (form 2, then 2a), filled from ``title_block``."""
    fpdf = _fpdf()
    pages = 0
    if frame:  # form 2 counts the pages: set the note once to count them
        first = _Writer(fpdf, note, frame, title_block)
        first.body()
        pages = first.pdf.page_no()
        _close(first.pdf)
    w = _Writer(fpdf, note, frame, title_block, pages)
    w.body()
    try:
        return bytes(w.pdf.output())
    finally:
        _close(w.pdf)


def _close(pdf) -> None:
    """The font files fpdf2 keeps open (fontTools reads them lazily), closed."""
    for font in pdf.fonts.values():
        ttfont = getattr(font, "ttfont", None)
        if ttfont is not None:
            ttfont.close()
