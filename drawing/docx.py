"""The explanatory note as DOCX: the only module that imports python-docx (the ``docx``
extra).

A :class:`~drawing.document.Document` becomes an editable Word document: A4 pages with
the margins of GOST 2.105 (30 mm left, 10 right, 15 top, 20 bottom; within the frame,
text 5 mm from its sides and 10 mm from its top and from the title block), Times New
Roman 14 pt at one and a half lines, paragraphs indented 12.5 mm; the sections numbered
"1", "5.1" as GOST 2.105 numbers them (Word's own heading styles, so that its
navigation and table of contents see them); every formula as Office Math (fractions,
indices, roots, a vector's arrow), which Word and LibreOffice edit as formulas; the
tables as tables. On request (``frame``) each page has the text document's frame: the
page's border 20 mm from the left edge and 5 mm from the others, and the title block
as a table in the footer, form 2 on the first page and 2a on the others
(:mod:`drawing.sheet.forms`), its page numbers Word's fields.

The file's bytes depend on the note alone: its parts are zipped with one fixed date.
"""

from __future__ import annotations

import datetime
import io
import re
import zipfile
from types import ModuleType
from xml.sax.saxutils import escape, quoteattr

from drawing.document import Document, Formula, Heading, Paragraph, Piece, Table
from drawing.formula import Fence, Frac, Node, Radical, Run, Script, Vector, split_lines
from drawing.sheet.forms import FORM2, FORM2A, Form, cell_text
from drawing.sheet.frame import TitleBlock
from plans.errors import PlansError

__all__ = ["FONT", "MARGINS", "DocxUnavailableError", "omml", "require", "to_docx"]

_HINT = "DOCX export needs python-docx: pip install 'vector-plans[docx]'"
#: the document's language tag (w:lang) by the note's language
LANGUAGE_TAGS = {"ru": "ru-RU", "en": "en-GB"}
FONT = "Times New Roman"
SIZE_PT = 14
#: page margins, mm (left, right, top, bottom): GOST 2.105 without a frame, and with one
#: (the frame 20/5/5/5 mm from the edges, text 5 mm from its sides and 10 mm from its
#: top and from the title block's 15 mm of form 2a)
MARGINS = {False: (30.0, 10.0, 15.0, 20.0), True: (25.0, 10.0, 15.0, 30.0)}
_INDENT_MM = 12.5
#: characters of a formula on one line of the page at 14 pt
LINE_CHARS = 64
_M = "http://schemas.openxmlformats.org/officeDocument/2006/math"
_W = "http://schemas.openxmlformats.org/wordprocessingml/2006/main"
_NS = f'xmlns:m="{_M}" xmlns:w="{_W}"'
_LATIN = re.compile(r"[A-Za-z]+|[^A-Za-z]+")


class DocxUnavailableError(PlansError, ImportError):
    """python-docx is missing: a setup problem the user can fix (exit 2 with the pip
    command), not an internal error."""


def require() -> None:
    """Fail before anything is computed or written when DOCX export cannot work here."""
    _docx()


def _docx() -> ModuleType:
    try:
        import docx
    except ImportError as exc:
        raise DocxUnavailableError(f"{_HINT} ({exc})") from exc
    return docx


# ----------------------------------------------------------------------- Office Math


def _mrun(text: str, style: str) -> str:
    """One math run: ``style`` "i" (italic), "p" (upright) or "text" (the document's
    own letters, for words and units)."""
    if not text:
        return ""
    size = f'<w:sz w:val="{SIZE_PT * 2}"/><w:szCs w:val="{SIZE_PT * 2}"/>'
    if style == "text":
        props = (f'<m:rPr><m:nor/></m:rPr><w:rPr><w:rFonts w:ascii="{FONT}" w:hAnsi="{FONT}" '
                 f'w:cs="{FONT}"/>{size}</w:rPr>')
    else:
        props = f'<m:rPr><m:sty m:val="{style}"/></m:rPr><w:rPr>{size}</w:rPr>'
    space = ' xml:space="preserve"' if text != text.strip() else ""
    return f"<m:r>{props}<m:t{space}>{escape(text)}</m:t></m:r>"


def _runs(run: Run) -> str:
    if run.kind == "text":
        return _mrun(run.text, "text")
    if run.kind == "punct":
        return _mrun(run.text + " ", "p")
    if run.kind == "bracket":  # of a bracket broken over lines: a character, not a fence
        return _mrun(run.text, "text")
    if run.kind == "roman":
        return _mrun(run.text, "p")
    if run.kind == "var":  # Latin letters italic; Greek, Cyrillic, digits upright
        return "".join(_mrun(part, "i" if part[0].isascii() and part[0].isalpha() else "p")
                       for part in _LATIN.findall(run.text))
    return _mrun(run.text, "p")


def omml(nodes: tuple[Node, ...]) -> str:
    """``nodes`` as the inside of an ``<m:oMath>`` element.

    >>> from drawing.formula import parse
    >>> import re
    >>> re.findall(r"<m:(\\w+)>", omml(parse("P/η")))
    ['f', 'num', 'r', 'rPr', 't', 'den', 'r', 'rPr', 't']
    """
    out: list[str] = []
    for i, n in enumerate(nodes):
        if isinstance(n, Run):
            text = n
            if n.kind == "text":  # a unit or a word keeps its spaces
                after = i + 1 < len(nodes) and not (isinstance(nodes[i + 1], Run)
                                                    and nodes[i + 1].kind in ("punct", "op"))
                text = Run((" " if i > 0 else "") + n.text + (" " if after else ""), "text")
            out.append(_runs(text))
        elif isinstance(n, Script):
            base = f"<m:e>{omml(n.base)}</m:e>"
            if n.sub and n.sup:
                out.append(f"<m:sSubSup>{base}<m:sub>{omml(n.sub)}</m:sub>"
                           f"<m:sup>{omml(n.sup)}</m:sup></m:sSubSup>")
            elif n.sub:
                out.append(f"<m:sSub>{base}<m:sub>{omml(n.sub)}</m:sub></m:sSub>")
            else:
                out.append(f"<m:sSup>{base}<m:sup>{omml(n.sup)}</m:sup></m:sSup>")
        elif isinstance(n, Frac):
            out.append(f"<m:f><m:num>{omml(n.num)}</m:num><m:den>{omml(n.den)}</m:den></m:f>")
        elif isinstance(n, Radical):
            out.append('<m:rad><m:radPr><m:degHide m:val="1"/></m:radPr><m:deg/>'
                       f"<m:e>{omml(n.body)}</m:e></m:rad>")
        elif isinstance(n, Vector):
            out.append('<m:acc><m:accPr><m:chr m:val="\u20d7"/></m:accPr>'
                       f"<m:e>{omml(n.body)}</m:e></m:acc>")
        elif isinstance(n, Fence):
            # round brackets are the default, and LibreOffice reads them only so
            chars = "" if n.open == "(" else (f"<m:begChr m:val={quoteattr(n.open)}/>"
                                              f"<m:endChr m:val={quoteattr(n.close)}/>")
            out.append(f"<m:d><m:dPr>{chars}</m:dPr><m:e>{omml(n.body)}</m:e></m:d>")
    return "".join(out)


# ---------------------------------------------------------------------- the document


class _Writer:
    def __init__(self, docx: ModuleType, note: Document, frame: bool, tb: TitleBlock | None) -> None:
        from docx.shared import Mm, Pt

        self.docx, self.note, self.frame = docx, note, frame
        self.tb = tb or TitleBlock(name=note.title)
        self.Mm, self.Pt = Mm, Pt
        self.doc = docx.Document()
        self._setup()

    def _setup(self) -> None:
        from docx.enum.text import WD_LINE_SPACING
        from docx.oxml.ns import qn

        Mm, Pt = self.Mm, self.Pt
        section = self.doc.sections[0]
        section.page_width, section.page_height = Mm(210), Mm(297)
        left, right, top, bottom = MARGINS[self.frame]
        section.left_margin, section.right_margin = Mm(left), Mm(right)
        section.top_margin, section.bottom_margin = Mm(top), Mm(bottom)
        section.header_distance, section.footer_distance = Mm(5), Mm(5)
        lang = LANGUAGE_TAGS.get(self.note.lang, "en-GB")
        for name in ("Normal", "Heading 1", "Heading 2"):
            st = self.doc.styles[name]
            st.font.name = FONT
            st.font.color.rgb = None
            rpr = st.element.get_or_add_rPr()
            fonts = rpr.find(qn("w:rFonts"))
            if fonts is None:
                fonts = rpr.makeelement(qn("w:rFonts"), {})
                rpr.append(fonts)
            for attr in ("w:ascii", "w:hAnsi", "w:cs", "w:eastAsia"):
                fonts.set(qn(attr), FONT)
            for attr in ("w:asciiTheme", "w:hAnsiTheme", "w:cstheme", "w:eastAsiaTheme"):
                fonts.attrib.pop(qn(attr), None)
            lang_el = rpr.find(qn("w:lang"))
            if lang_el is None:
                lang_el = rpr.makeelement(qn("w:lang"), {})
                rpr.append(lang_el)
            lang_el.set(qn("w:val"), lang)
            pf = st.paragraph_format
            pf.line_spacing_rule = WD_LINE_SPACING.ONE_POINT_FIVE
            pf.space_before, pf.space_after = Pt(0), Pt(0)
        normal = self.doc.styles["Normal"]
        normal.font.size = Pt(SIZE_PT)
        normal.paragraph_format.first_line_indent = Mm(_INDENT_MM)
        for name, size in (("Heading 1", SIZE_PT + 2), ("Heading 2", SIZE_PT)):
            st = self.doc.styles[name]
            st.font.size, st.font.bold, st.font.italic = Pt(size), True, False
            st.paragraph_format.space_before = Pt(12)
            st.paragraph_format.space_after = Pt(6)
            st.paragraph_format.keep_with_next = True
        self.doc.styles["Heading 1"].paragraph_format.first_line_indent = Mm(_INDENT_MM)
        self.doc.styles["Heading 2"].paragraph_format.first_line_indent = Mm(_INDENT_MM)
        core = self.doc.core_properties
        core.title, core.language = self.note.title, lang
        core.author = self.tb.developer or ""
        core.subject = self.tb.designation or ""
        fixed = datetime.datetime(2000, 1, 1)
        core.created = core.modified = fixed
        core.last_modified_by, core.revision = "", 1

    # pieces of a sentence
    def _pieces(self, p, pieces: tuple[Piece, ...], bold: bool = False, italic: bool = False) -> None:
        from docx.oxml import parse_xml

        for piece in pieces:
            if piece.kind == "math":
                p._p.append(parse_xml(f"<m:oMath {_NS}>{omml(piece.nodes)}</m:oMath>"))
            else:
                run = p.add_run(piece.text)
                run.bold = bold or piece.bold or None
                run.italic = italic or None

    def _display(self, nodes: tuple[Node, ...], level: int, broken: bool = False) -> None:
        """A formula on a line of its own: centred, or (a line of one broken over several)
        from the paragraph's indent, its continuations further in."""
        from docx.enum.text import WD_ALIGN_PARAGRAPH
        from docx.oxml import parse_xml

        p = self.doc.add_paragraph()
        p.paragraph_format.first_line_indent = self.Mm(0)
        p.alignment = WD_ALIGN_PARAGRAPH.LEFT if broken else WD_ALIGN_PARAGRAPH.CENTER
        if level or broken:
            p.paragraph_format.left_indent = self.Mm(_INDENT_MM * (1 + level))
        jc = "left" if broken else "centerGroup"
        # a continuation starts with its "=" or "+": something before it, for a reader
        # that wants an operator's left side (LibreOffice)
        starts = bool(nodes) and isinstance(nodes[0], Run) and nodes[0].kind == "op"
        lead = _mrun("\u200b", "text") if starts else ""
        p._p.append(parse_xml(f'<m:oMathPara {_NS}><m:oMathParaPr><m:jc m:val="{jc}"/>'
                              f"</m:oMathParaPr><m:oMath>{lead}{omml(nodes)}</m:oMath></m:oMathPara>"))

    def _table(self, t: Table) -> None:
        cols = max(len(r) for r in t.rows)
        table = self.doc.add_table(rows=len(t.rows), cols=cols)
        table.style = self.doc.styles["Table Grid"]
        for i, row in enumerate(t.rows):
            for j, cell in enumerate(row):
                p = table.cell(i, j).paragraphs[0]
                p.paragraph_format.first_line_indent = self.Mm(0)
                self._pieces(p, cell, bold=i == 0)

    def body(self) -> None:
        from docx.enum.text import WD_ALIGN_PARAGRAPH

        title = self.doc.add_paragraph()
        title.alignment = WD_ALIGN_PARAGRAPH.CENTER
        title.paragraph_format.first_line_indent = self.Mm(0)
        title.paragraph_format.space_after = self.Pt(12)
        run = title.add_run(self.note.title)
        run.bold, run.font.size = True, self.Pt(SIZE_PT + 2)
        for b in self.note.blocks:
            if isinstance(b, Heading):
                p = self.doc.add_paragraph(style="Heading 1" if b.level == 1 else "Heading 2")
                p.add_run(f"{b.number} ")
                self._pieces(p, b.pieces)
            elif isinstance(b, Formula):
                lines = split_lines(b.nodes, LINE_CHARS - 8 * b.level)
                for k, line in enumerate(lines):  # a long one broken before its "=" or "+"
                    self._display(line, b.level + (k > 0), len(lines) > 1)
            elif isinstance(b, Table):
                self._table(b)
            elif isinstance(b, Paragraph):
                p = self.doc.add_paragraph()
                pf = p.paragraph_format
                if b.kind == "body":
                    p.alignment = WD_ALIGN_PARAGRAPH.JUSTIFY
                if b.kind in ("item", "aside"):
                    pf.left_indent = self.Mm(_INDENT_MM * (1 + b.level))
                    pf.first_line_indent = self.Mm(0)
                    if b.kind == "item":  # GOST 2.105 lists: a dash before each item
                        p.add_run("– ")
                self._pieces(p, b.pieces, bold=b.kind == "group", italic=b.kind == "note")

    # the frame: the page's border and the title block in the footer
    def frame_parts(self) -> None:
        from docx.oxml import parse_xml
        from docx.oxml.ns import nsdecls

        section = self.doc.sections[0]
        section.different_first_page_header_footer = True
        self._form(section.first_page_footer, FORM2, first=True)
        self._form(section.footer, FORM2A, first=False)
        # the border: 20 mm from the left edge, 5 from the others (from the text: its
        # margins less these), round the footer's title block
        left, right, top, _ = MARGINS[True]
        pt = 72 / 25.4
        space = {"left": (left - 20) * pt, "right": (right - 5) * pt, "top": (top - 5) * pt,
                 "bottom": 0}
        edges = "".join(f'<w:{k} w:val="single" w:sz="16" w:space="{round(v)}" w:color="000000"/>'
                        for k, v in space.items())
        section._sectPr.append(parse_xml(f'<w:pgBorders {nsdecls("w")} w:offsetFrom="text">{edges}'
                                         "</w:pgBorders>"))

    def _form(self, footer, form: Form, first: bool) -> None:
        from docx.enum.table import WD_TABLE_ALIGNMENT
        from docx.enum.text import WD_ALIGN_PARAGRAPH
        from docx.oxml import parse_xml
        from docx.oxml.ns import nsdecls

        footer.is_linked_to_previous = False
        Mm, Pt = self.Mm, self.Pt
        table = footer.add_table(rows=len(form.rows), cols=len(form.cols), width=Mm(sum(form.cols)))
        table.alignment = WD_TABLE_ALIGNMENT.LEFT
        table.autofit = False
        tbl = table._tbl
        tbl_pr = tbl.tblPr
        # its left edge on the frame's, 20 mm from the page's, left of the text's margin
        indent = round((20.0 - MARGINS[True][0]) * 56.6929)
        tbl_pr.append(parse_xml(f'<w:tblInd {nsdecls("w")} w:w="{indent}" w:type="dxa"/>'))
        tbl_pr.append(parse_xml(f'<w:tblLayout {nsdecls("w")} w:type="fixed"/>'))
        tbl_pr.append(parse_xml(f'<w:tblCellMar {nsdecls("w")}><w:left w:w="28" w:type="dxa"/>'
                                '<w:right w:w="28" w:type="dxa"/></w:tblCellMar>'))
        for j, w in enumerate(form.cols):
            tbl.tblGrid.gridCol_lst[j].w = Mm(w)  # the grid is what a reader lays out by
            for cell in table.columns[j].cells:
                cell.width = Mm(w)
        for i, h in enumerate(form.rows):
            tr_pr = table.rows[i]._tr.get_or_add_trPr()
            tr_pr.append(parse_xml(f'<w:trHeight {nsdecls("w")} w:val="{round(h * 56.6929)}" '
                                   'w:hRule="exact"/>'))
        thin = {(round(x0, 3), round(y0, 3), round(x1, 3), round(y1, 3)): t
                for x0, y0, x1, y1, t in form.lines()}
        for c in form.cells:
            cell = table.cell(c.row, c.col)
            if c.rows > 1 or c.cols > 1:
                cell = cell.merge(table.cell(c.row + c.rows - 1, c.col + c.cols - 1))
            x0, x1, y0, y1 = form.x(c.col), form.x(c.col + c.cols), form.y(c.row), form.y(c.row + c.rows)
            xa, yb = form.x(c.col + 1), form.y(c.row + 1)  # a merged cell's edge: its first piece's

            def key(a, b, c_, d):
                return (round(a, 3), round(b, 3), round(c_, 3), round(d, 3))

            borders = {"top": thin.get(key(x0, y0, xa, y0)), "bottom": thin.get(key(x0, y1, xa, y1)),
                       "left": thin.get(key(x0, y0, x0, yb)), "right": thin.get(key(x1, y0, x1, yb))}
            xml = "".join(f'<w:{k} w:val="single" w:sz="{4 if t else 12}" w:space="0" w:color="000000"/>'
                          for k, t in borders.items())
            tc_pr = cell._tc.get_or_add_tcPr()
            tc_pr.append(parse_xml(f'<w:tcBorders {nsdecls("w")}>{xml}</w:tcBorders>'))
            tc_pr.append(parse_xml(f'<w:vAlign {nsdecls("w")} w:val="center"/>'))
            p = cell.paragraphs[0]
            pf = p.paragraph_format
            pf.first_line_indent, pf.space_before, pf.space_after = Mm(0), Pt(0), Pt(0)
            pf.line_spacing = 1.0
            p.alignment = WD_ALIGN_PARAGRAPH.CENTER if c.align == "middle" else WD_ALIGN_PARAGRAPH.LEFT
            size = Pt(max(6.0, c.size / 0.7 * 72 / 25.4))  # a cap height of c.size mm
            if c.text in ("page", "pages"):
                self._field(p, "PAGE" if c.text == "page" else "NUMPAGES", size)
                continue
            text = cell_text(c.text, self.tb, self.note.lang)
            if text:
                run = p.add_run(text)
                run.font.size, run.italic = size, True
        # nothing after the table in the footer: its empty paragraph at 1 pt
        for p in footer.paragraphs:
            p.paragraph_format.first_line_indent = Mm(0)
            for r in p.runs:
                r.text = ""
            p.paragraph_format.line_spacing = Pt(1)
            rpr = p._p.get_or_add_pPr()
            rpr.append(parse_xml(f'<w:rPr {nsdecls("w")}><w:sz w:val="2"/></w:rPr>'))
        body = footer._element
        body.remove(tbl)
        body.insert(0, tbl)


    def _field(self, p, code: str, size) -> None:
        from docx.oxml import parse_xml
        from docx.oxml.ns import nsdecls

        sz = round(size.pt * 2)
        rpr = f'<w:rPr><w:i/><w:sz w:val="{sz}"/></w:rPr>'
        p._p.append(parse_xml(f'<w:fldSimple {nsdecls("w")} w:instr=" {code} ">'
                              f'<w:r>{rpr}<w:t>1</w:t></w:r></w:fldSimple>'))


def to_docx(note: Document, frame: bool = False, title_block: TitleBlock | None = None) -> bytes:
    """The note as the bytes of a DOCX file; ``frame``: with the text document's frame
    and title block (form 2, then 2a), filled from ``title_block``."""
    docx = _docx()
    w = _Writer(docx, note, frame, title_block)
    w.body()
    if frame:
        w.frame_parts()
    raw = io.BytesIO()
    w.doc.save(raw)
    return _fixed_zip(raw.getvalue())


def _fixed_zip(data: bytes) -> bytes:
    """The same parts, in the same order, each dated 1980-01-01: bytes that depend on
    the content alone."""
    out = io.BytesIO()
    with zipfile.ZipFile(io.BytesIO(data)) as src, zipfile.ZipFile(out, "w", zipfile.ZIP_DEFLATED) as dst:
        for info in src.infolist():
            fixed = zipfile.ZipInfo(info.filename, date_time=(1980, 1, 1, 0, 0, 0))
            fixed.compress_type = zipfile.ZIP_DEFLATED
            fixed.external_attr = 0o644 << 16
            dst.writestr(fixed, src.read(info.filename))
    return out.getvalue()
