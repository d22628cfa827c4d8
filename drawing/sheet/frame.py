"""The sheet: GOST 2.301 format, the frame, and the GOST 2.104 form 1 title block.

Sheet coordinates are millimetres from the top-left corner of the sheet, y down.
The frame runs 20 mm from the left edge (binding margin) and 5 mm from the
others; the 185 × 55 title block sits in the bottom-right corner of the frame.

The title-block geometry is KiCad's GOST worksheet
(``common/page_layout/title_block_shapes_gost.cpp``).  The tables below give it
as in the project notes: **x from the block's left edge, y up from its bottom
edge**, mm; :func:`_block_to_sheet` turns that into sheet coordinates.

>>> sheet = Sheet("A1")
>>> sheet.width, sheet.height
(841.0, 594.0)
>>> sheet.frame
Rect(x=20.0, y=5.0, w=816.0, h=584.0)
>>> sheet.title_block
Rect(x=651.0, y=534.0, w=185.0, h=55.0)
>>> round(sheet.drawing_area().area)  # 816·584 − 185·55 − 70·14
465389
"""

from __future__ import annotations

from dataclasses import dataclass, fields, replace
from typing import Literal

from shapely.geometry import Polygon, box

from drawing.scene import Layer, Polyline, Rect, Scene, Segment, Text
from drawing.styles import LineType, Style
from drawing.text import fit_text

__all__ = [
    "FORMATS",
    "GROUP",
    "LABELS",
    "LITERAL",
    "THICK_LINES",
    "THIN_LINES",
    "Sheet",
    "TitleBlock",
    "field9",
    "frame_scene",
    "title_block_texts",
]

#: Sheet sizes as drawn, (width, height) mm: landscape, except A4 portrait
#: (its title block runs along the short side, GOST 2.104).
FORMATS: dict[str, tuple[float, float]] = {
    "A0": (1189.0, 841.0),
    "A1": (841.0, 594.0),
    "A2": (594.0, 420.0),
    "A3": (420.0, 297.0),
    "A4": (210.0, 297.0),
}
MARGIN_LEFT, MARGIN_TOP, MARGIN_RIGHT, MARGIN_BOTTOM = 20.0, 5.0, 5.0, 5.0
BLOCK_W, BLOCK_H = 185.0, 55.0
FIELD26_W, FIELD26_H = 70.0, 14.0

Seg = tuple[float, float, float, float]  # x0, y0, x1, y1 in block coordinates

#: Main (thick) lines of form 1.  The block's right and bottom edges are the frame.
THICK_LINES: tuple[Seg, ...] = (
    (0, 55, 185, 55), (0, 0, 0, 55),  # top and left edges
    (65, 40, 185, 40), (0, 35, 65, 35), (135, 35, 185, 35),
    (0, 30, 65, 30), (135, 20, 185, 20), (65, 15, 185, 15),
    (7, 30, 7, 55), (17, 0, 17, 55), (40, 0, 40, 55), (55, 0, 55, 55), (65, 0, 65, 55),
    (135, 0, 135, 40), (150, 20, 150, 40), (155, 15, 155, 20), (167, 20, 167, 40),
)  # fmt: skip
#: Thin lines of form 1: the change-record and signature rows, the literal cells.
THIN_LINES: tuple[Seg, ...] = (
    (0, 50, 65, 50), (0, 45, 65, 45), (0, 40, 65, 40),
    (0, 25, 65, 25), (0, 20, 65, 20), (0, 15, 65, 15), (0, 10, 65, 10), (0, 5, 65, 5),
    (140, 20, 140, 35), (145, 20, 145, 35),
)  # fmt: skip

#: Fixed wording of the block.  Labels too wide for their cell at 2.5 mm
#: ("Tech. check" needs 18 mm of a 17 mm cell) are condensed by fit_text, down to
#: LABEL_STRETCH: never set below GOST 2.304's 2.5 mm.
LABEL_STRETCH = 0.7
LABELS: dict[str, dict[str, tuple[str, ...] | str]] = {
    "ru": {
        "signers": ("Разраб.", "Пров.", "Т.контр.", "", "Н.контр.", "Утв."),
        "header": ("Изм.", "Лист", "№ докум.", "Подп.", "Дата"),
        "lit": "Лит.", "mass": "Масса", "scale": "Масштаб",
        "sheet": "Лист", "sheets": "Листов", "copied": "Копировал", "format": "Формат",
    },
    "en": {
        "signers": ("Drawn", "Checked", "Tech. check", "", "Norm. check", "Approved"),
        "header": ("Rev.", "Sheet", "Doc. No.", "Sign.", "Date"),
        "lit": "Lit.", "mass": "Mass", "scale": "Scale",
        "sheet": "Sheet", "sheets": "Sheets", "copied": "Copied", "format": "Format",
    },
}  # fmt: skip


@dataclass(frozen=True, slots=True)
class Sheet:
    """A sheet of one GOST 2.301 format (``"A0"`` … ``"A4"``)."""

    name: str = "A1"

    def __post_init__(self) -> None:
        if self.name not in FORMATS:
            raise ValueError(
                f"unknown sheet format {self.name!r}; known: {', '.join(FORMATS)}"
            )

    @property
    def width(self) -> float:
        return FORMATS[self.name][0]

    @property
    def height(self) -> float:
        return FORMATS[self.name][1]

    @property
    def frame(self) -> Rect:
        """The inner frame (thick line), 20 mm from the left and 5 mm elsewhere."""
        return Rect(
            MARGIN_LEFT,
            MARGIN_TOP,
            self.width - MARGIN_LEFT - MARGIN_RIGHT,
            self.height - MARGIN_TOP - MARGIN_BOTTOM,
        )

    @property
    def title_block(self) -> Rect:
        """The 185 × 55 title block, flush with the frame's bottom-right corner."""
        f = self.frame
        return Rect(f.x1 - BLOCK_W, f.y1 - BLOCK_H, BLOCK_W, BLOCK_H)

    @property
    def field26(self) -> Rect:
        """The 70 × 14 box in the frame's top-left corner (designation, upside down)."""
        return Rect(self.frame.x, self.frame.y, FIELD26_W, FIELD26_H)

    def drawing_area(self) -> Polygon:
        """The free field: inside the frame, less the title block and field 26.

        Boundaries run along the middle of the frame lines; a layout keeps its
        own clearance (``area.buffer(-5)``, say).
        """
        free = box(*self.frame.bounds).difference(box(*self.title_block.bounds))
        return free.difference(box(*self.field26.bounds))


@dataclass(frozen=True, slots=True)
class TitleBlock:
    """What is written in the title block; empty fields stay blank.

    Numbered as in GOST 2.104: ``name`` (1), ``designation`` (2, repeated
    upside down in field 26), ``material`` (3), ``literal`` (4; None: the sheet's
    language's, :data:`LITERAL`), ``mass`` (5), ``scale`` (6, e.g. "1:10"), ``sheet``
    (7: left blank on a one-sheet document), ``sheets`` (8), ``organisation``
    (9: the university), ``group`` (the student's group, written in field 9 after
    the organisation, "МГТУ, гр. ТМ-21", as course projects fill it), the signers'
    surnames (11) and the date of the developer's signature (13).  Numbers may be
    given as ``int``.
    """

    name: str = ""
    designation: str = ""
    material: str = ""
    literal: str | None = None
    mass: str = ""
    scale: str = ""
    sheet: str = ""
    sheets: str = "1"
    organisation: str = ""
    group: str = ""
    developer: str = ""
    checker: str = ""
    tech_control: str = ""
    norm_control: str = ""
    approver: str = ""
    date: str = ""

    def __post_init__(self) -> None:
        for f in fields(self):
            value = getattr(self, f.name)
            if isinstance(value, int | float):
                object.__setattr__(self, f.name, str(value))
            elif not isinstance(value, str) and not (f.name == "literal" and value is None):
                raise TypeError(
                    f"TitleBlock.{f.name} must be a str, got {type(value).__name__}"
                )


#: the word before a group's name in field 9
GROUP = {"ru": "гр.", "en": "group"}
#: field 4's literal of a student's drawing by the sheet's language: GOST 2.103's «У»
#: (учебный) is a Russian letter with no English counterpart, so an English sheet
#: leaves the cells blank unless a literal is given
LITERAL = {"ru": "У", "en": ""}


def field9(organisation: str, group: str, lang: str = "ru") -> str:
    """Field 9: the organisation, then the group ("МГТУ, гр. ТМ-21"); a group given with
    its own word ("группа РК3-51", "gr. 5") is written as it is.

    >>> field9("МГТУ", "ТМ-21"), field9("", "группа 5"), field9("MIT", "5", "en")
    ('МГТУ, гр. ТМ-21', 'группа 5', 'MIT, group 5')
    """
    group = group.strip()
    if group and not group.lower().startswith(("гр", "gr")):
        group = f"{GROUP[lang]} {group}"
    return ", ".join(part for part in (organisation.strip(), group) if part)


def _block_to_sheet(block: Rect, x0: float, y0: float, x1: float, y1: float) -> Rect:
    """A block-coordinate box (x right, y up from the bottom) as a sheet ``Rect``."""
    return Rect(block.x + x0, block.y1 - y1, x1 - x0, y1 - y0)


def _sizes(style: Style, largest: float) -> tuple[float, ...]:
    return tuple(s for s in style.font_sizes if s <= largest) or (
        min(style.font_sizes),
    )


#: the GOST 2.104 field of each TitleBlock entry (the group is written in field 9)
FIELD_NO = {"name": 1, "designation": 2, "material": 3, "literal": 4, "mass": 5, "scale": 6,
            "sheet": 7, "sheets": 8, "organisation": 9, "group": 9, "developer": 11,
            "checker": 11, "tech_control": 11, "norm_control": 11, "approver": 11, "date": 13}


def title_block_texts(
    sheet: Sheet,
    title_block: TitleBlock,
    lang: Literal["ru", "en"] = "ru",
    style: Style | None = None,
) -> tuple[tuple[Text, Rect], ...]:
    """Every text of the title block (and of fields 26, 31, 32) with its cell.

    The cell is what the text must stay inside; tests and views can check it.
    """
    return tuple((t, cell) for t, cell, _ in title_block_entries(sheet, title_block, lang, style))


def title_block_entries(
    sheet: Sheet,
    title_block: TitleBlock,
    lang: Literal["ru", "en"] = "ru",
    style: Style | None = None,
) -> tuple[tuple[Text, Rect, tuple[str, ...]], ...]:
    """As :func:`title_block_texts`, each text with the TitleBlock entries it writes
    (none for the form's own words; field 9 writes the organisation and the group)."""
    style = style or Style()
    words = LABELS[lang]
    blk = sheet.title_block
    out: list[tuple[Text, Rect, tuple[str, ...]]] = []
    # keep clear of the cell's own lines: half a main line plus 0.1 mm
    room = {"pad": style.s / 2 + 0.1, "inset": 1.0, "slant": style.slant_tan}

    def put(
        value: str,
        x0: float,
        y0: float,
        x1: float,
        y1: float,
        largest: float = 2.5,
        lines: int = 1,
        align: Literal["start", "middle"] = "middle",
        entries: tuple[str, ...] = (),
    ) -> None:
        cell = _block_to_sheet(blk, x0, y0, x1, y1)
        for t in fit_text(
            value,
            cell,
            sizes=_sizes(style, largest),
            max_lines=lines,
            align=align,
            # the form's own words in 2.5 mm letters, condensed as far as they need
            # ("Tech. check" to 74 %); an entry is condensed to 80 % at most
            min_stretch=0.8 if entries else LABEL_STRETCH,
            **room,
        ):
            out.append((t, cell, entries))

    # left part: header row, then the six signature rows
    for label, (x0, x1) in zip(
        words["header"], ((0, 7), (7, 17), (17, 40), (40, 55), (55, 65)), strict=True
    ):
        put(label, x0, 30, x1, 35)
    tb = title_block
    signers = ("developer", "checker", "tech_control", "", "norm_control", "approver")
    for i, (label, key) in enumerate(zip(words["signers"], signers, strict=True)):
        top = 30 - 5 * i
        put(label, 0, top - 5, 17, top, align="start")
        put(getattr(tb, key) if key else "", 17, top - 5, 40, top, align="start",
            entries=(key,) if key else ())
    put(tb.date, 55, 25, 65, 30, entries=("date",))

    # right part
    put(tb.designation, 65, 40, 185, 55, largest=7, entries=("designation",))
    put(tb.name, 65, 15, 135, 40, largest=7, lines=3, entries=("name",))
    put(tb.material, 65, 0, 135, 15, largest=5, entries=("material",))
    put(field9(tb.organisation, tb.group, lang), 135, 0, 185, 15, largest=5, lines=2,
        entries=("organisation", "group"))
    put(words["lit"], 135, 35, 150, 40)
    put(words["mass"], 150, 35, 167, 40)
    put(words["scale"], 167, 35, 185, 40)
    literal = LITERAL[lang] if tb.literal is None else tb.literal  # «У» on a Russian sheet
    for k, ch in enumerate(literal[:3]):
        put(ch, 135 + 5 * k, 20, 140 + 5 * k, 35, largest=3.5, entries=("literal",))
    put(tb.mass, 150, 20, 167, 35, largest=5, entries=("mass",))
    put(tb.scale, 167, 20, 185, 35, largest=5, entries=("scale",))
    put(words["sheet"], 135, 15, 146, 20, align="start")
    put(tb.sheet, 146, 15, 155, 20, entries=("sheet",))
    put(words["sheets"], 155, 15, 170, 20, align="start")
    put(tb.sheets, 170, 15, 185, 20, entries=("sheets",))

    # field 26: the designation upside down in the top-left corner of the frame
    f26 = sheet.field26
    for t in fit_text(tb.designation, f26, sizes=_sizes(style, 5), **room):
        cx, cy = f26.center
        out.append(
            (
                replace(
                    t, pos=(2 * cx - t.pos[0], 2 * cy - t.pos[1]), rotate_deg=180.0
                ),
                f26,
                ("designation",),
            )
        )

    # fields 31 and 32 in the bottom margin, under the block
    y = sheet.height - MARGIN_BOTTOM / 2
    for text, x0, x1 in (
        (words["copied"], 75, 135),
        (f"{words['format']} {sheet.name}", 145, 185),
    ):
        cell = Rect(blk.x + x0, blk.y1, x1 - x0, MARGIN_BOTTOM)
        out.append((Text((cell.x, y), text, size=2.5, baseline="middle"), cell, ()))
    return tuple(out)


def frame_scene(
    sheet: Sheet,
    title_block: TitleBlock | None = None,
    style: Style | None = None,
    lang: Literal["ru", "en"] = "ru",
    trim: bool = True,
) -> Scene:
    """Layers ``"frame"`` (trim edge, thin; frame, thick) and ``"title-block"``.

    ``trim=False`` leaves out the thin outer edge of the format, which GOST
    2.301 allows when the sheet is printed on paper of exactly that size.
    """
    if lang not in LABELS:
        raise ValueError(f"lang must be one of {sorted(LABELS)}, got {lang!r}")
    title_block = title_block or TitleBlock()
    frame_items: list = []
    if trim:
        frame_items.append(
            Polyline(
                Rect(0, 0, sheet.width, sheet.height).corners(),
                LineType.THIN,
                closed=True,
            )
        )
    frame_items.append(Polyline(sheet.frame.corners(), LineType.MAIN, closed=True))

    blk = sheet.title_block
    lines: list = []
    for table, kind in ((THICK_LINES, LineType.MAIN), (THIN_LINES, LineType.THIN)):
        for x0, y0, x1, y1 in table:
            lines.append(
                Segment((blk.x + x0, blk.y1 - y0), (blk.x + x1, blk.y1 - y1), kind)
            )
    f26 = sheet.field26
    lines += [
        Segment((f26.x1, f26.y), (f26.x1, f26.y1)),
        Segment((f26.x, f26.y1), (f26.x1, f26.y1)),
    ]
    texts = [t for t, _ in title_block_texts(sheet, title_block, lang, style)]
    return Scene(
        (Layer("frame", tuple(frame_items)), Layer("title-block", (*lines, *texts)))
    )
