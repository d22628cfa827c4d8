"""Formats, frame and the GOST 2.104 form 1 title block (drawing.sheet)."""

import pytest
import shapely
from shapely.geometry import LineString, box

from drawing.obstacles import overlaps
from drawing.scene import Segment, Text
from drawing.sheet.frame import (
    FORMATS,
    Sheet,
    TitleBlock,
    frame_scene,
    title_block_texts,
)
from drawing.styles import LineType
from drawing.text import text_box

FULL = TitleBlock(
    name="Структурный и кинематический анализ рычажного механизма",
    designation="ТММ.КП.12.01.00",
    material="Сталь 45 ГОСТ 1050-2013",
    literal="У",
    mass="12,5",
    scale="1:10",
    sheet=1,
    sheets=4,
    organisation="МГТУ им. Н.Э. Баумана, гр. РК3-51",
    developer="Иванов И.И.",
    checker="Петров П.П.",
    tech_control="Смирнова",
    norm_control="Сидоров",
    approver="Кузнецов",
    date="21.11.25",
)
LONG = TitleBlock(
    name="Очень длинное наименование изделия " * 4,
    designation="ТММ.КП.12.01.00.000.СБ.ВАРИАНТ-17.ЛИСТ-1.РЕДАКЦИЯ-3",
    material="Материал с очень длинным обозначением по стандарту",
    organisation="Университет имени Н.Э. Баумана, группа РК3-51",
    developer="Константинопольский-Щербацкий К.К.",
    mass="123456789",
    scale="1:2,5 (μl=0,0025)",
    sheets=999,
)


def block_coords(sheet, seg):
    """A title-block segment as (x0, y0, x1, y1) from the block's bottom-left, y up."""
    blk = sheet.title_block
    (ax, ay), (bx, by) = seg.p1, seg.p2
    return tuple(
        round(v, 6) for v in (ax - blk.x, blk.y1 - ay, bx - blk.x, blk.y1 - by)
    )


def block_segments(sheet, kind):
    items = frame_scene(sheet, FULL).items("title-block")
    segs = [it for it in items if isinstance(it, Segment) and it.line is kind]
    return {
        block_coords(sheet, s) for s in segs if sheet.title_block.x - 0.1 <= s.p1[0]
    }


@pytest.mark.parametrize(
    ("name", "size"),
    [
        ("A0", (1189, 841)),
        ("A1", (841, 594)),
        ("A2", (594, 420)),
        ("A3", (420, 297)),
        ("A4", (210, 297)),
    ],
)
def test_formats_are_landscape_except_a4(name, size):
    sheet = Sheet(name)
    assert (sheet.width, sheet.height) == size
    assert FORMATS[name] == size


def test_unknown_format_is_refused():
    with pytest.raises(ValueError, match="A5"):
        Sheet("A5")


@pytest.mark.parametrize("name", ["A1", "A3", "A4"])
def test_frame_is_20_5_5_5_from_the_edges_and_the_block_sits_in_its_corner(name):
    sheet = Sheet(name)
    f = sheet.frame
    assert (f.x, f.y, sheet.width - f.x1, sheet.height - f.y1) == (20, 5, 5, 5)
    b = sheet.title_block
    assert (b.w, b.h) == (185, 55)
    assert (b.x1, b.y1) == (f.x1, f.y1)
    assert (sheet.field26.x, sheet.field26.y, sheet.field26.w, sheet.field26.h) == (
        20,
        5,
        70,
        14,
    )
    frame_layer = frame_scene(sheet).layer("frame")
    trim, frame = frame_layer.items
    assert trim.line is LineType.THIN and trim.points == (
        (0, 0),
        (sheet.width, 0),
        (sheet.width, sheet.height),
        (0, sheet.height),
    )
    assert frame.line is LineType.MAIN and frame.closed
    assert frame.points == (
        (20, 5),
        (sheet.width - 5, 5),
        (sheet.width - 5, sheet.height - 5),
        (20, sheet.height - 5),
    )


def test_a4_title_block_spans_the_whole_frame_width():
    sheet = Sheet("A4")
    assert sheet.frame.w == 185 == sheet.title_block.w


def test_drawing_area_leaves_out_the_title_block_and_field_26():
    sheet = Sheet("A1")
    area = sheet.drawing_area()
    assert area.area == pytest.approx(816 * 584 - 185 * 55 - 70 * 14)
    assert area.contains(shapely.Point(400, 300))
    assert not area.contains(shapely.Point(700, 560))  # inside the title block
    assert not area.contains(shapely.Point(50, 10))  # inside field 26
    assert not area.contains(shapely.Point(10, 300))  # binding margin


def test_thick_lines_are_at_the_kicad_coordinates():
    thick = block_segments(Sheet("A1"), LineType.MAIN)
    expected = {
        (0, 30, 65, 30), (0, 35, 65, 35),  # around the header row of the left part
        (65, 40, 185, 40), (65, 15, 185, 15),  # under field 2, over fields 3 and 9
        (135, 0, 135, 40), (135, 35, 185, 35), (135, 20, 185, 20),
        (7, 30, 7, 55), (17, 0, 17, 55), (40, 0, 40, 55),
        (55, 0, 55, 55), (65, 0, 65, 55),
        (150, 20, 150, 40), (167, 20, 167, 40), (155, 15, 155, 20),
        (0, 55, 185, 55), (0, 0, 0, 55),  # top and left edges of the block
    }  # fmt: skip
    assert thick == expected


def test_thin_lines_are_the_rows_and_the_literal_cells():
    thin = block_segments(Sheet("A1"), LineType.THIN)
    rows = {(0, y, 65, y) for y in (5, 10, 15, 20, 25, 40, 45, 50)}
    assert thin == rows | {(140, 20, 140, 35), (145, 20, 145, 35)}


def test_field_26_box_is_drawn_thick_in_the_top_left_corner():
    sheet = Sheet("A3")
    segs = [
        it
        for it in frame_scene(sheet).items("title-block")
        if isinstance(it, Segment) and it.p1[0] < 100
    ]
    assert {(s.p1, s.p2) for s in segs} == {((90, 5), (90, 19)), ((20, 19), (90, 19))}
    assert all(s.line is LineType.MAIN for s in segs)


def test_fields_are_written_in_their_cells():
    sheet = Sheet("A1")
    blk = sheet.title_block
    placed = {
        t.text: (t, cell)
        for t, cell in title_block_texts(sheet, FULL)
        if t.rotate_deg == 0
    }
    designation, cell = placed["ТММ.КП.12.01.00"]
    assert (cell.x - blk.x, blk.y1 - cell.y1, cell.w, cell.h) == (
        65,
        40,
        120,
        15,
    )  # x, bottom, w, h
    assert designation.size == 7
    # field 1: three lines at 3.5 mm beat one line at 2.5 mm in the 70 × 25 cell
    name_lines = [
        t for t, c in title_block_texts(sheet, FULL) if c.w == 70 and c.h == 25
    ]
    assert [t.text for t in name_lines] == [
        "Структурный и",
        "кинематический анализ",
        "рычажного механизма",
    ]
    assert {t.size for t in name_lines} == {3.5}
    # literal, scale, sheet numbers, signers, header
    assert placed["У"][1].x - blk.x == 135 and placed["У"][1].w == 5
    assert placed["1:10"][1].x - blk.x == 167
    assert placed["4"][1].x - blk.x == 170 and placed["1"][1].x - blk.x == 146
    assert placed["Иванов И.И."][1].x - blk.x == 17
    assert blk.y1 - placed["Иванов И.И."][1].y1 == 25  # the "Разраб." row
    ru_labels = "Разраб. Пров. Т.контр. Н.контр. Утв. Изм. Лист Подп. Дата Лит. Масса"
    for label in (
        *ru_labels.split(),
        "№ докум.",
        "Масштаб",
        "Листов",
        "Копировал",
        "Формат A1",
    ):
        assert label in placed, label
    copied, cell = placed["Копировал"]
    assert copied.pos[0] == blk.x + 75 and cell.y == sheet.height - 5


def test_field_26_repeats_the_designation_upside_down():
    sheet = Sheet("A1")
    texts = [
        t for t, cell in title_block_texts(sheet, FULL) if t.text == FULL.designation
    ]
    assert len(texts) == 2
    f26 = next(t for t in texts if t.rotate_deg == 180)
    assert box(*sheet.field26.bounds).contains(text_box(f26))


def test_english_labels():
    texts = {t.text for t, _ in title_block_texts(Sheet("A3"), FULL, lang="en")}
    signers = ("Drawn", "Checked", "Tech. check", "Norm. check", "Approved")
    header = ("Rev.", "Sheet", "Doc. No.", "Sign.", "Date")
    right = ("Lit.", "Mass", "Scale", "Sheets", "Copied", "Format A3")
    for label in (*signers, *header, *right):
        assert label in texts, label
    assert "Разраб." not in texts
    with pytest.raises(ValueError, match="lang"):
        frame_scene(Sheet("A3"), FULL, lang="de")


@pytest.mark.parametrize("lang", ["ru", "en"])
@pytest.mark.parametrize(
    "tb", [FULL, LONG, TitleBlock()], ids=["full", "long", "empty"]
)
def test_no_title_block_text_overlaps_another_or_leaves_its_cell(lang, tb):
    sheet = Sheet("A1")
    placed = title_block_texts(sheet, tb, lang=lang)
    assert overlaps([t for t, _ in placed]) == []
    for t, cell in placed:
        assert box(*cell.bounds).contains(text_box(t)), (t.text, cell)


@pytest.mark.parametrize("tb", [FULL, LONG], ids=["full", "long"])
def test_no_title_block_text_crosses_a_line(tb):
    sheet = Sheet("A2")
    scene = frame_scene(sheet, tb)
    lines = [
        LineString([s.p1, s.p2])
        for s in scene.items("title-block")
        if isinstance(s, Segment)
    ]
    for t in scene.items("title-block"):
        if isinstance(t, Text):
            inner = text_box(t).buffer(-0.05)
            assert not any(inner.intersects(ln) for ln in lines), t.text


def test_long_strings_shrink_and_wrap():
    placed = title_block_texts(Sheet("A1"), LONG)
    org = [t for t, c in placed if c.w == 50 and c.h == 15]
    assert [t.text for t in org] == ["Университет имени Н.Э.", "Баумана, группа РК3-51"]
    assert all(t.size == 2.5 for t in org)
    (dev,) = [t for t, _ in placed if t.text == LONG.developer]
    assert dev.size < 2.5


def test_title_block_numbers_may_be_ints_and_other_types_are_refused():
    assert TitleBlock(sheet=2, sheets=3).sheets == "3"
    with pytest.raises(TypeError, match="name"):
        TitleBlock(name=None)


def test_an_empty_english_title_block_has_no_russian_literal():
    """frame_scene's own title block wrote GOST's «У» in the literal cells in English
    too; an English one leaves them blank, a Russian one keeps «У»."""
    def literal(lang):
        return [t.text for t in frame_scene(Sheet("A3"), lang=lang).items("title-block")
                if isinstance(t, Text) and t.text == "У"]
    assert literal("en") == [] and literal("ru") == ["У"]
