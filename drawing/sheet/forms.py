"""The title blocks of a text document (GOST 2.104): form 2 on its first page (185 × 40)
and form 2a on the others (185 × 15), as grids of cells that the DOCX writer makes
tables of and the PDF writer draws.

A form is columns and rows in millimetres, and cells that span them; every cell's
edges are main lines but for the thin ones GOST draws thin: the lines between the rows
of changes and between the signers' rows, and the literal's cells. Texts are the
form's own words (by language) and the entries of a :class:`~drawing.sheet.frame.TitleBlock`,
named by its fields; "page" and "pages" are the page's number and the count, which a
writer fills.

>>> sum(FORM2.cols), sum(FORM2.rows), sum(FORM2A.cols), sum(FORM2A.rows)
(185.0, 40.0, 185.0, 15.0)
>>> [c.text for c in FORM2.cells if c.row == 2][:3]
['header0', 'header1', 'header2']
"""

from __future__ import annotations

from dataclasses import dataclass

from drawing.sheet.frame import LABELS, LITERAL, TitleBlock, field9

__all__ = ["FORM2", "FORM2A", "Cell", "Form", "cell_text"]


@dataclass(frozen=True, slots=True)
class Cell:
    """A cell from row ``row`` and column ``col``, ``rows`` × ``cols`` of them. ``text``: a
    word of the form ("lit", "header2", "signer0"), a TitleBlock field ("designation",
    "developer"), or "page"/"pages"; ``size``: its letters' height in mm; ``align``
    "start" or "middle"."""

    row: int
    col: int
    rows: int = 1
    cols: int = 1
    text: str = ""
    size: float = 2.5
    align: str = "middle"


@dataclass(frozen=True, slots=True)
class Form:
    cols: tuple[float, ...]
    rows: tuple[float, ...]
    cells: tuple[Cell, ...]
    #: (row boundary, first column, last column + 1) drawn thin; vertical: (column
    #: boundary, first row, last row + 1)
    thin_h: tuple[tuple[int, int, int], ...] = ()
    thin_v: tuple[tuple[int, int, int], ...] = ()

    def x(self, col: int) -> float:
        return sum(self.cols[:col])

    def y(self, row: int) -> float:
        return sum(self.rows[:row])

    def lines(self) -> list[tuple[float, float, float, float, bool]]:
        """Every cell edge once, as (x0, y0, x1, y1, thin) in mm from the form's top-left
        corner: the rows' and columns' boundaries that some cell has as its edge."""
        h: dict[tuple[int, int], bool] = {}  # (boundary row, column) → thin
        v: dict[tuple[int, int], bool] = {}  # (boundary column, row) → thin
        for c in self.cells:
            for col in range(c.col, c.col + c.cols):
                for r in (c.row, c.row + c.rows):
                    h[(r, col)] = any(r == b and a <= col < e for b, a, e in self.thin_h)
            for row in range(c.row, c.row + c.rows):
                for k in (c.col, c.col + c.cols):
                    v[(k, row)] = any(k == b and a <= row < e for b, a, e in self.thin_v)
        out = [(self.x(col), self.y(r), self.x(col + 1), self.y(r), thin) for (r, col), thin in h.items()]
        out += [(self.x(k), self.y(row), self.x(k), self.y(row + 1), thin) for (k, row), thin in v.items()]
        return sorted(out)


_LEFT = (7.0, 10.0, 23.0, 15.0, 10.0)  # Изм., Лист, № докум., Подп., Дата: 65 mm


def _left(first_row: int, signers: int) -> list[Cell]:
    """The left part: two rows of changes, the header, then the signers' rows."""
    cells = [Cell(r, c) for r in range(first_row, first_row + 2) for c in range(5)]
    cells += [Cell(first_row + 2, c, text=f"header{c}") for c in range(5)]
    for i in range(signers):
        r = first_row + 3 + i
        cells += [Cell(r, 0, cols=2, text=f"signer{i}", align="start"),
                  Cell(r, 2, text=f"surname{i}", align="start"), Cell(r, 3), Cell(r, 4)]
    return cells


#: form 2: the first page of a text document
FORM2 = Form(
    cols=(*_LEFT, 70.0, 5.0, 5.0, 5.0, 15.0, 20.0),
    rows=(5.0,) * 8,
    cells=(
        *_left(0, 5),
        Cell(0, 5, rows=3, cols=6, text="designation", size=7.0),
        Cell(3, 5, rows=5, text="name", size=3.5),
        Cell(3, 6, cols=3, text="lit"), Cell(3, 9, text="sheet"), Cell(3, 10, text="sheets"),
        Cell(4, 6, text="literal0"), Cell(4, 7, text="literal1"), Cell(4, 8, text="literal2"),
        Cell(4, 9, text="page"), Cell(4, 10, text="pages"),
        Cell(5, 6, rows=3, cols=5, text="organisation", size=3.5),
    ),
    thin_h=((1, 0, 5), (4, 0, 5), (5, 0, 5), (6, 0, 5), (7, 0, 5)),
    thin_v=((7, 4, 5), (8, 4, 5)),
)

#: form 2a: the following pages
FORM2A = Form(
    cols=(*_LEFT, 110.0, 10.0),
    rows=(5.0, 2.0, 3.0, 5.0),
    cells=(
        *(Cell(0, c) for c in range(5)),
        *(Cell(1, c, rows=2) for c in range(5)),
        *(Cell(3, c, text=f"header{c}") for c in range(5)),
        Cell(0, 5, rows=4, text="designation", size=7.0),
        Cell(0, 6, rows=2, text="sheet"),
        Cell(2, 6, rows=2, text="page", size=3.5),
    ),
    thin_h=((1, 0, 5),),
)

#: the signers of a text document's form 2, by the TitleBlock's fields
_SIGNERS = ("developer", "checker", "", "norm_control", "approver")
_SIGNER_WORDS = {"ru": ("Разраб.", "Пров.", "", "Н. контр.", "Утв."),
                 "en": ("Drawn", "Checked", "", "Norm. check", "Approved")}


def cell_text(key: str, tb: TitleBlock, lang: str = "ru", page: str = "", pages: str = "") -> str:
    """What the cell ``key`` of a form says in ``lang``, its entries from ``tb``.

    >>> tb = TitleBlock(name="Курсовой проект", developer="Иванов")
    >>> cell_text("signer0", tb), cell_text("surname0", tb), cell_text("literal0", tb)
    ('Разраб.', 'Иванов', 'У')
    >>> cell_text("header2", tb, "en"), cell_text("page", tb, page="3")
    ('Doc. No.', '3')
    """
    words = LABELS[lang]
    if key.startswith("header"):
        return str(words["header"][int(key[6:])])
    if key.startswith("signer"):
        return _SIGNER_WORDS[lang][int(key[6:])]
    if key.startswith("surname"):
        field = _SIGNERS[int(key[7:])]
        return getattr(tb, field) if field else ""
    if key.startswith("literal"):
        literal = LITERAL[lang] if tb.literal is None else tb.literal
        k = int(key[7:])
        return literal[k] if k < len(literal) else ""
    if key in ("lit", "sheet", "sheets"):
        return str(words[key])
    if key == "organisation":
        return field9(tb.organisation, tb.group, lang)
    if key == "page":
        return page
    if key == "pages":
        return pages
    return str(getattr(tb, key, "")) if key else ""
