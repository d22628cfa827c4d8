"""SVG output and export (drawing.svg, drawing.export)."""

import base64
import io
import re
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

from drawing.export import ExportUnavailableError, pdf_bytes, png_bytes
from drawing.scene import (
    Arrow,
    Blank,
    Circle,
    Group,
    Hatch,
    Layer,
    Polyline,
    Scene,
    Segment,
    Text,
)
from drawing.sheet.frame import Sheet, TitleBlock, frame_scene
from drawing.styles import LineType, Style
from drawing.svg import FONT_FILE, fmt, to_svg
from plans.cli.common import write_output

NS = {"svg": "http://www.w3.org/2000/svg"}
INK = "{http://www.inkscape.org/namespaces/inkscape}"
TB = TitleBlock(
    name="Кинематический анализ механизма",
    designation="ТММ.КП.12.01.00",
    scale="1:10",
    sheet=1,
    sheets=4,
    organisation="МГТУ им. Н.Э. Баумана",
    developer="Иванов И.И.",
)


def parse(svg: str) -> ET.Element:
    return ET.fromstring(svg.encode("utf-8"))


def sheet_svg(name="A1", tb=TB, **kw) -> str:
    sheet = Sheet(name)
    return to_svg(frame_scene(sheet, tb), sheet, embed_font=False, **kw)


def layer(root, name):
    (g,) = root.findall(f"svg:g[@id='layer-{name}']", NS)
    return g


def texts(root):
    return [t.text for t in root.iter("{http://www.w3.org/2000/svg}text")]


@pytest.mark.parametrize(
    ("name", "w", "h"),
    [
        ("A1", "841", "594"),
        ("A3", "420", "297"),
        ("A4", "210", "297"),
        ("A2", "594", "420"),
    ],
)
def test_root_is_measured_in_millimetres(name, w, h):
    root = parse(sheet_svg(name))
    assert root.get("width") == f"{w}mm" and root.get("height") == f"{h}mm"
    assert root.get("viewBox") == f"0 0 {w} {h}"


def test_layers_are_named_inkscape_layers():
    root = parse(sheet_svg())
    ids = [g.get("id") for g in root.findall("svg:g", NS)]
    assert ids == ["layer-frame", "layer-title-block"]
    g = layer(root, "title-block")
    assert g.get("class") == "title-block"
    assert g.get(f"{INK}groupmode") == "layer" and g.get(f"{INK}label") == "title-block"
    assert (
        g.get("font-family")
        == "osifont, 'GOST type B', ISOCPEUR, 'DejaVu Sans', sans-serif"
    )


@pytest.mark.parametrize("name", ["A1", "A3", "A4"])
def test_frame_rectangle_is_20_5_5_5(name):
    sheet = Sheet(name)
    root = parse(sheet_svg(name))
    trim, frame = layer(root, "frame").findall("svg:polygon", NS)
    w, h = fmt(sheet.width), fmt(sheet.height)
    right_bottom = f"{fmt(sheet.width - 5)},{fmt(sheet.height - 5)}"
    assert (
        frame.get("points")
        == f"20,5 {fmt(sheet.width - 5)},5 {right_bottom} 20,{fmt(sheet.height - 5)}"
    )
    assert frame.get("stroke-width") == "0.7"
    assert (
        trim.get("points") == f"0,0 {w},0 {w},{h} 0,{h}"
        and trim.get("stroke-width") == "0.35"
    )


def lines_of(root, name, width):
    out = set()
    for ln in layer(root, name).findall("svg:line", NS):
        if ln.get("stroke-width") == width:
            out.add(tuple(float(ln.get(k)) for k in ("x1", "y1", "x2", "y2")))
    return out


def test_title_block_lines_land_at_the_kicad_coordinates_on_a1():
    root = parse(sheet_svg("A1"))
    thick, thin = (
        lines_of(root, "title-block", "0.7"),
        lines_of(root, "title-block", "0.35"),
    )
    bx, by = 841 - 5 - 185, 594 - 5  # block's left edge, bottom edge
    assert (bx, by - 55, bx + 185, by - 55) in thick  # top edge: 185 wide
    assert (bx, by, bx, by - 55) in thick  # left edge: 55 high
    assert (bx, by - 30, bx + 65, by - 30) in thick and (
        bx,
        by - 35,
        bx + 65,
        by - 35,
    ) in thick
    assert (bx + 135, by, bx + 135, by - 40) in thick
    assert (bx + 65, by - 40, bx + 185, by - 40) in thick and (
        bx + 65,
        by - 15,
        bx + 185,
        by - 15,
    ) in thick
    assert (bx + 7, by - 30, bx + 7, by - 55) in thick
    assert (bx + 155, by - 15, bx + 155, by - 20) in thick
    assert (bx, by - 5, bx + 65, by - 5) in thin and (
        bx,
        by - 50,
        bx + 65,
        by - 50,
    ) in thin
    assert (bx + 140, by - 20, bx + 140, by - 35) in thin
    assert len(thick) == 19 and len(thin) == 10  # 17 block lines + 2 of field 26


def test_field_texts_appear():
    found = texts(parse(sheet_svg("A3")))
    for s in (
        "ТММ.КП.12.01.00",
        "1:10",
        "Иванов И.И.",
        "МГТУ им.",
        "Н.Э. Баумана",
        "У",
        "4",
        "Разраб.",
        "Формат A3",
    ):
        assert s in found, s
    assert found.count("ТММ.КП.12.01.00") == 2  # field 2 and field 26
    assert (
        "Кинематический" in found and "анализ механизма" in found
    )  # field 1 on two lines at 5 mm


def test_text_has_gost_size_and_slant():
    scene = Scene(
        (
            Layer(
                "notes",
                (
                    Text((10, 20), "A", size=5),
                    Text((10, 40), "B", size=5, italic=False),
                ),
            ),
        )
    )
    root = parse(to_svg(scene, Sheet("A4"), embed_font=False))
    slanted, upright = layer(root, "notes").findall("svg:text", NS)
    assert slanted.get("font-size") == fmt(5 / 0.74)  # capitals 5 mm high in osifont
    # caps middle at y = 20 - 2.5, baseline 2.5 below it; shear -15° = 75° slant
    assert (
        slanted.get("transform") == "translate(10 17.5) skewX(-15)"
        and slanted.get("y") == "2.5"
    )
    assert (upright.get("x"), upright.get("y"), upright.get("transform")) == (
        "10",
        "40",
        None,
    )
    assert slanted.get("fill") == "black" and slanted.get("stroke") == "none"


def test_rotated_text_turns_about_its_position():
    scene = Scene(
        (
            Layer(
                "n",
                (
                    Text(
                        (50, 30),
                        "A",
                        size=5,
                        anchor="middle",
                        rotate_deg=180,
                        baseline="middle",
                    ),
                ),
            ),
        )
    )
    (t,) = layer(parse(to_svg(scene, Sheet("A4"), embed_font=False)), "n").findall(
        "svg:text", NS
    )
    assert t.get("transform") == "translate(50 30) rotate(180) skewX(-15)"
    assert t.get("text-anchor") == "middle"


def test_hostile_strings_come_out_as_text():
    evil = "</text><script>alert(1)</script>"
    tb = TitleBlock(
        name=evil, designation='x" onload="alert(2)', organisation="a & b < c"
    )
    svg = sheet_svg("A3", tb, title="<title>" + evil)
    assert "<script" not in svg and "&lt;script&gt;" in svg
    root = parse(svg)
    assert not list(root.iter("{http://www.w3.org/2000/svg}script"))
    assert not any("onload" in el.attrib for el in root.iter())
    found = texts(root)
    assert evil in found and 'x" onload="alert(2)' in found and "a & b < c" in found
    assert root.find("svg:title", NS).text == "<title>" + evil


def test_characters_xml_cannot_carry_are_replaced():
    scene = Scene((Layer("n", (Text((5, 5), "a\x00b\x1bc"),)),))
    (t,) = layer(parse(to_svg(scene, Sheet("A4"), embed_font=False)), "n").findall(
        "svg:text", NS
    )
    assert t.text == "a\ufffdb\ufffdc"


def test_fmt_rounds_to_a_hundredth_and_strips_zeros():
    values = (0, 1, 1.5, 1.25, 1.255, 2.999, -0.004, -3.1, 1e-9, 594.0)
    assert [fmt(v) for v in values] == [
        "0", "1", "1.5", "1.25", "1.25", "3", "0", "-3.1", "0", "594",
    ]  # fmt: skip
    with pytest.raises(ValueError, match="non-finite"):
        fmt(float("nan"))


def test_every_number_in_the_output_has_at_most_two_decimals():
    scene = Scene(
        (
            Layer(
                "n",
                (
                    Segment((1 / 3, 2 / 3), (10 / 7, 5.123456)),
                    Circle((1 / 7, 1 / 9), 1 / 3),
                ),
            ),
        )
    )
    svg = to_svg(scene, Sheet("A4"), embed_font=False)
    assert re.findall(r"\d+\.\d{3,}", svg) == []
    (ln,) = layer(parse(svg), "n").findall("svg:line", NS)
    assert [ln.get(k) for k in ("x1", "y1", "x2", "y2")] == [
        "0.33",
        "0.67",
        "1.43",
        "5.12",
    ]


def test_line_types_map_to_widths_and_dashes():
    items = (
        Segment((0, 0), (100, 0), LineType.MAIN),
        Segment((0, 10), (100, 10), LineType.THIN),
        Segment((0, 20), (100, 20), LineType.DASHED),
        Polyline(((0, 30), (50, 30), (50, 60)), LineType.DASH_DOUBLE_DOT_THIN),
    )
    g = layer(
        parse(to_svg(Scene((Layer("n", items),)), Sheet("A4"), embed_font=False)), "n"
    )
    main, thin, dashed = g.findall("svg:line", NS)
    (chain,) = g.findall("svg:polyline", NS)
    assert (main.get("stroke-width"), main.get("stroke-dasharray")) == ("0.7", None)
    assert (thin.get("stroke-width"), thin.get("stroke-dasharray")) == ("0.35", None)
    assert (
        dashed.get("stroke-dasharray") == "4,1.5"
        and dashed.get("stroke-linecap") == "butt"
    )
    assert chain.get("stroke-dasharray") == "15,1.5,0.5,1.2,0.5,1.5"


def test_dash_dot_axis_starts_and_ends_with_a_dash():
    for length in (40.0, 57.3, 100.0, 263.9):
        scene = Scene(
            (Layer("n", (Segment((0, 0), (length, 0), LineType.DASH_DOT_THIN),)),)
        )
        (ln,) = layer(parse(to_svg(scene, Sheet("A1"), embed_font=False)), "n").findall(
            "svg:line", NS
        )
        dashes = [float(v) for v in ln.get("stroke-dasharray").split(",")]
        period, dash = sum(dashes), dashes[0]
        n = round((length - dash) / period)
        assert n * period + dash == pytest.approx(length, abs=0.05)
    short = Scene((Layer("n", (Segment((0, 0), (10, 0), LineType.DASH_DOT_THIN),)),))
    (ln,) = layer(parse(to_svg(short, Sheet("A4"), embed_font=False)), "n").findall(
        "svg:line", NS
    )
    assert ln.get("stroke-dasharray") is None  # shorter than one dash: solid thin


def test_arrow_hatch_circle_and_group():
    items = (
        Arrow((0, 0), (20, 0)),
        Hatch((0, 50), (10, 50), spacing=2.5),
        Circle((30, 30), 1.5, LineType.MAIN, fill="white"),
        Group((Segment((0, 0), (1, 0)),), offset=(100, 200), name="pivot"),
    )
    g = layer(
        parse(to_svg(Scene((Layer("n", items),)), Sheet("A4"), embed_font=False)), "n"
    )
    shaft, base = g.findall("svg:line", NS)
    (head,) = g.findall("svg:polygon", NS)
    assert (shaft.get("x2"), head.get("points")) == ("16.5", "20,0 16.5,-0.5 16.5,0.5")
    assert head.get("fill") == "black" and head.get("stroke") == "none"
    (hatch,) = g.findall("svg:path", NS)
    # 3 mm strokes at 45°, 2.5 mm apart, each ending within the base's 10 mm
    assert (
        hatch.get("d") == "M2.31,50L0.19,52.12 M4.81,50L2.69,52.12 "
        "M7.31,50L5.19,52.12 M9.81,50L7.69,52.12"
    )
    assert hatch.get("stroke-width") == "0.35"
    assert (base.get("y1"), base.get("stroke-width")) == ("50", "0.7")
    assert g.find("svg:circle", NS).get("fill") == "white"
    grp = g.find("svg:g", NS)
    assert grp.get("transform") == "translate(100 200)" and grp.get("class") == "pivot"


def test_a_blank_is_a_white_box_without_a_stroke_in_drawing_order():
    """The break under a dimension's value: a white rectangle, drawn between the line
    before it (hidden) and the line after it (shown)."""
    items = (Segment((0, 5), (20, 5), LineType.THIN), Blank((4.5, 3), (12.25, 7)),
             Segment((8, 0), (8, 10)))
    g = layer(parse(to_svg(Scene((Layer("n", items),)), Sheet("A4"), embed_font=False)), "n")
    assert [el.tag.split("}")[1] for el in g] == ["line", "rect", "line"]
    rect = g.find("svg:rect", NS)
    assert [rect.get(k) for k in ("x", "y", "width", "height", "fill", "stroke")] == [
        "4.5", "3", "7.75", "4", "white", "none"]


def test_font_is_embedded_as_base64():
    sheet = Sheet("A1")
    scene = frame_scene(sheet, TB)
    svg_with = to_svg(scene, sheet)
    svg_without = to_svg(scene, sheet, embed_font=False)
    style = parse(svg_with).find("svg:defs/svg:style", NS)
    (b64,) = re.findall(r"base64,([A-Za-z0-9+/=]+)", style.text)
    assert base64.b64decode(b64) == FONT_FILE.read_bytes()
    assert "font-family:'osifont'" in style.text
    assert parse(svg_without).find("svg:defs/svg:style", NS) is None
    extra = len(svg_with.encode()) - len(svg_without.encode())
    assert (
        4 * FONT_FILE.stat().st_size / 3
        < extra
        < 4 * FONT_FILE.stat().st_size / 3 + 400
    )


def test_style_changes_reach_the_output():
    scene = Scene((Layer("n", (Segment((0, 0), (1, 0)),)),))
    svg = to_svg(scene, Sheet("A4"), Style(s=1.0, color="#123456"), embed_font=False)
    g = layer(parse(svg), "n")
    assert (
        g.get("stroke") == "#123456"
        and g.find("svg:line", NS).get("stroke-width") == "1"
    )


def test_write_svg_is_atomic_and_leaves_no_temp_files(tmp_path):
    """drawing writes no file: the command line's one atomic writer does."""
    target = tmp_path / "sheet.svg"
    target.write_text("old")
    write_output(str(target), sheet_svg("A4").encode("utf-8"))
    assert target.read_text(encoding="utf-8").startswith("<?xml")
    assert [p.name for p in tmp_path.iterdir()] == ["sheet.svg"]


def test_png_and_pdf_export(tmp_path):
    svg = sheet_svg("A4")
    png = tmp_path / "s.png"
    try:
        write_output(str(png), png_bytes(svg, dpi=25.4))  # 1 px per mm
    except ExportUnavailableError as exc:  # cairosvg or libcairo absent here
        pytest.skip(str(exc))
    data = png.read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    assert (
        int.from_bytes(data[16:20], "big") == 210
        and int.from_bytes(data[20:24], "big") == 297
    )
    pdf = tmp_path / "s.pdf"
    write_output(str(pdf), pdf_bytes(svg))
    assert pdf.read_bytes()[:5] == b"%PDF-"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["s.pdf", "s.png"]


def test_export_without_cairosvg_says_what_to_install(tmp_path, monkeypatch):
    monkeypatch.setitem(sys.modules, "cairosvg", None)  # import now raises ImportError
    with pytest.raises(
        ExportUnavailableError, match=r"pip install '\.\[export\]'"
    ):
        write_output(str(tmp_path / "x.png"), png_bytes("<svg/>"))
    assert list(tmp_path.iterdir()) == []


def test_markup_writes_indices_as_shifted_tspans():
    t = Text((10, 20), "a^n_{BA} = 1", size=5, markup=True)
    root = parse(to_svg(Scene((Layer("n", (t,)),)), Sheet("A4"), embed_font=False))
    (el,) = layer(root, "n").findall("svg:text", NS)
    spans = el.findall("svg:tspan", NS)
    assert [s.text for s in spans] == ["a", "n", "BA", " = 1"]
    # superscript up 0.45 h, subscript down 0.3 h, then back to the line
    assert [s.get("dy") for s in spans] == [None, "-2.25", "3.75", "-1.5"]
    assert (
        spans[1].get("font-size") == fmt(5 * 0.7 / 0.74)
        and spans[0].get("font-size") is None
    )
    plain = Text((10, 20), "a_1", markup=False)
    root = parse(to_svg(Scene((Layer("n", (plain,)),)), Sheet("A4"), embed_font=False))
    assert layer(root, "n").find("svg:text", NS).text == "a_1"


def test_png_export_draws_yo_and_e_with_the_projects_font(tmp_path):
    """cairosvg asks fontconfig for "osifont"; Debian's copy has Ё, ё, Э, э as black
    boxes («Шарнирный четыр█хзвенник» in a title block). The export now draws with the
    project's patched copy. Run in a fresh process: fontconfig reads its setup once."""
    import json
    import os
    import subprocess

    pytest.importorskip("cairosvg")
    code = (
        "import io, json, sys\n"
        "from PIL import Image\n"
        "from drawing import export\n"
        "def dark(ch):\n"
        "    svg = ('<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"60mm\" height=\"60mm\" '\n"
        "           'viewBox=\"0 0 60 60\"><rect width=\"60\" height=\"60\" fill=\"white\"/>'\n"
        "           '<text x=\"5\" y=\"45\" font-family=\"osifont\" font-size=\"40\">' + ch\n"
        "           + '</text></svg>')\n"
        "    im = Image.open(io.BytesIO(export.png_bytes(svg, dpi=72))).convert('L')\n"
        "    return sum(1 for v in im.getdata() if v < 128)\n"
        "import os\n"
        "print(json.dumps({c: dark(c) for c in 'еёЭэС'} | {'env': os.environ.get('FONTCONFIG_FILE')}))\n"
    )
    env = {k: v for k, v in os.environ.items() if k != "FONTCONFIG_FILE"}
    env["PYTHONPATH"] = str(Path(__file__).resolve().parent.parent)
    env["TMPDIR"] = str(tmp_path)
    r = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True)
    if r.returncode and "PIL" in r.stderr:
        pytest.skip("needs Pillow to read the PNG")
    assert r.returncode == 0, r.stderr
    dark = json.loads(r.stdout)
    # a black box fills its cell: three times the ink of the letter it stands for
    assert dark["ё"] < 1.5 * dark["е"] and dark["э"] < 1.5 * dark["е"] and dark["Э"] < 1.5 * dark["С"]
    assert dark["env"] is None  # set for the first render only: child processes never see it
    assert list(tmp_path.iterdir()) == []  # the private font setup is gone with the process


@pytest.mark.parametrize(("argv", "must"), [
    (["sheet", "samples/fourbar.toml"], "−128,8°"),  # a crank range through 0°
    (["sheet", "samples/press.toml", "--lang", "en"], ""),
    (["check", "samples/check_press.toml", "--svg", "{out}", "-o", "/dev/null"], "−"),
])
def test_every_character_of_a_sheet_is_in_the_projects_font(tmp_path, capsys, argv, must):
    """osifont has no minus sign: «от −128,8°» and a check's "−4,2" printed with a box in
    the PNG and PDF. The font now maps it (and the primes of x3′-x3′) to GOST's glyphs."""
    from support import run

    ttlib = pytest.importorskip("fontTools.ttLib")
    from drawing.svg import FONT_FILE

    cmap = ttlib.TTFont(FONT_FILE).getBestCmap()
    out = tmp_path / "s.svg"
    args = [a.format(out=out) for a in argv]
    if "{out}" not in " ".join(argv):
        args += ["-o", str(out)]
    code, _, err = run(capsys, *args)
    assert code in (0, 1), err
    root = ET.parse(out).getroot()
    text = "".join("".join(el.itertext()) for el in root.iter("{http://www.w3.org/2000/svg}text"))
    assert must in text
    missing = sorted({c for c in text if not c.isspace() and ord(c) not in cmap})
    assert missing == []


def test_a_png_is_drawn_on_white_paper(tmp_path):
    """The PNG was black ink on a transparent background: black on black in a viewer with
    a dark background. Every pixel of it is now opaque, white where nothing is drawn."""
    pytest.importorskip("PIL")
    from PIL import Image

    try:
        png = io.BytesIO(png_bytes(sheet_svg("A4"), dpi=25.4))
    except ExportUnavailableError as exc:
        pytest.skip(str(exc))
    im = Image.open(png).convert("RGBA")
    alpha = im.getchannel("A")
    assert alpha.getextrema() == (255, 255)
    assert im.getpixel((100, 100))[:3] == (255, 255, 255)  # the drawing field, blank
