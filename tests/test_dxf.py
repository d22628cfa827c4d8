"""The sheet as DXF (drawing/dxf.py, ``plans sheet --dxf``): a clean audit, the same
lines and texts as the SVG sheet when ezdxf's drawing add-on renders it again, the layers
and texts a second reader sees, GOST line types and widths, and the command's files."""

import math
import os
import re
import shutil
import subprocess
import xml.etree.ElementTree as ET
from functools import cache

import pytest

ezdxf = pytest.importorskip("ezdxf")

from ezdxf.addons.drawing import Frontend, RenderContext  # noqa: E402
from ezdxf.addons.drawing.config import Configuration, LinePolicy  # noqa: E402
from ezdxf.addons.drawing.recorder import Recorder  # noqa: E402

from drawing import dxf  # noqa: E402
from drawing.scene import Arrow, Blank, Circle, Layer, Page, Scene, Segment, Text  # noqa: E402
from drawing.sheet1 import build_sheet  # noqa: E402
from drawing.styles import LineType, Style  # noqa: E402
from drawing.svg import to_svg  # noqa: E402
from plans.model import load, variants  # noqa: E402
from tests.support import run  # noqa: E402

SVG = "{http://www.w3.org/2000/svg}"
TOL = 0.1  # mm: the acceptance's bound for every line end and text anchor


@cache
def sheet(source: str, fmt: str = "A1", lang: str = "ru"):
    """(scene, sheet, SVG text, DXF bytes, the document read back) of a sample or a variant."""
    mech = (variants.read_table(None).variant(int(source[1:])) if source.startswith("v")
            else load(f"samples/{source}.toml"))
    scene, sh, _ = build_sheet(mech, fmt, lang)
    data = dxf.to_dxf(scene, sh, title=mech.name_in(lang), lang=lang)
    return scene, sh, to_svg(scene, sh), data, ezdxf.read(_stream(data))


def _stream(data: bytes):
    import io

    return io.StringIO(data.decode("utf-8"))


SHEETS = [("press", "A1", "ru"), ("fourbar", "A2", "en"), ("v3", "A2", "ru"), ("v4", "A1", "en")]


# ----------------------------------------------------------------------- the SVG's geometry

def _matrix(transform: str | None):
    """The 2×3 matrix (a, b, c, d, e, f) of an SVG transform list."""
    m = (1.0, 0.0, 0.0, 1.0, 0.0, 0.0)
    for op, args in re.findall(r"(\w+)\(([^)]*)\)", transform or ""):
        v = [float(x) for x in re.split(r"[ ,]+", args.strip())]
        if op == "translate":
            n = (1, 0, 0, 1, v[0], v[1] if len(v) > 1 else 0.0)
        elif op == "rotate":
            a = math.radians(v[0])
            n = (math.cos(a), math.sin(a), -math.sin(a), math.cos(a), 0, 0)
        elif op == "skewX":
            n = (1, 0, math.tan(math.radians(v[0])), 1, 0, 0)
        elif op == "scale":
            n = (v[0], 0, 0, v[1] if len(v) > 1 else v[0], 0, 0)
        else:
            raise AssertionError(op)
        m = _mul(m, n)
    return m


def _mul(m, n):
    a, b, c, d, e, f = m
    a2, b2, c2, d2, e2, f2 = n
    return (a * a2 + c * b2, b * a2 + d * b2, a * c2 + c * d2, b * c2 + d * d2,
            a * e2 + c * f2 + e, b * e2 + d * f2 + f)


def _apply(m, x, y):
    a, b, c, d, e, f = m
    return (a * x + c * y + e, b * x + d * y + f)


def svg_geometry(svg: str):
    """(line ends, circles (x, y, r), text anchors (x, y, text)) of an SVG sheet, in mm."""
    ends: list[tuple[float, float]] = []
    circles, anchors = [], []

    def walk(el, m):
        m = _mul(m, _matrix(el.get("transform"))) if el.tag != SVG + "text" else m
        tag = el.tag.replace(SVG, "")
        if tag == "line":
            ends.extend(_apply(m, float(el.get(f"x{i}")), float(el.get(f"y{i}"))) for i in (1, 2))
        elif tag in ("polyline", "polygon"):
            nums = [float(v) for v in re.split(r"[ ,]+", el.get("points").strip())]
            ends.extend(_apply(m, x, y) for x, y in zip(nums[::2], nums[1::2], strict=True))
        elif tag == "path":
            nums = [float(v) for v in re.findall(r"-?[\d.]+", el.get("d"))]
            ends.extend(_apply(m, x, y) for x, y in zip(nums[::2], nums[1::2], strict=True))
        elif tag == "rect":
            x, y, w, h = (float(el.get(k)) for k in ("x", "y", "width", "height"))
            ends.extend(_apply(m, px, py) for px, py in ((x, y), (x + w, y), (x + w, y + h), (x, y + h)))
        elif tag == "circle":
            cx, cy = _apply(m, float(el.get("cx")), float(el.get("cy")))
            circles.append((cx, cy, float(el.get("r"))))
        elif tag == "text":
            t = _mul(m, _matrix(el.get("transform")))
            x, y = _apply(t, float(el.get("x", 0)), float(el.get("y", 0)))
            anchors.append((x, y, "".join(el.itertext())))
            return
        for child in el:
            walk(child, m)

    root = ET.fromstring(svg.encode("utf-8"))
    for child in root:
        walk(child, (1.0, 0.0, 0.0, 1.0, 0.0, 0.0))
    return ends, circles, anchors


# --------------------------------------------------------------------- the DXF rendered again

def rendered(doc, height: float):
    """What ezdxf's drawing add-on draws of ``doc``, by entity type: {type: [(handle, points)]},
    the points in sheet millimetres (y down), lines solid (their ends, not their dashes)."""
    rec = Recorder()
    Frontend(RenderContext(doc), rec, config=Configuration(line_policy=LinePolicy.SOLID)).draw_layout(
        doc.modelspace())
    out: dict[str, list] = {}
    for record, props in rec.player().recordings():
        kind = doc.entitydb[props.handle].dxftype()
        pts = []
        if hasattr(record, "points"):
            pts = [(v.x, v.y) for v in record.points.vertices()]
        elif hasattr(record, "lines"):
            pts = [(v.x, v.y) for v in record.lines.vertices()]
        elif hasattr(record, "path"):
            pts = [(v.x, v.y) for v in record.path.control_vertices()]
        elif hasattr(record, "paths"):
            pts = [(v.x, v.y) for p in record.paths for v in p.control_vertices()]
        out.setdefault(kind, []).append((props.handle, [(x, height - y) for x, y in pts]))
    return out


def _near(points, targets, tol=TOL):
    """The points of ``points`` farther than ``tol`` from every point of ``targets``."""
    grid: dict[tuple[int, int], list] = {}
    for x, y in targets:
        grid.setdefault((int(x // tol), int(y // tol)), []).append((x, y))
    far = []
    for x, y in points:
        i, j = int(x // tol), int(y // tol)
        cands = [q for di in (-1, 0, 1) for dj in (-1, 0, 1) for q in grid.get((i + di, j + dj), ())]
        if not any(math.dist((x, y), q) <= tol for q in cands):
            far.append((round(x, 3), round(y, 3)))
    return far


@pytest.mark.parametrize(("source", "fmt", "lang"), SHEETS)
def test_every_dxf_passes_the_audit(source, fmt, lang):
    doc = sheet(source, fmt, lang)[4]
    auditor = doc.audit()
    assert not auditor.has_errors, [str(e.message) for e in auditor.errors]
    assert not auditor.has_fixes, [str(f.message) for f in auditor.fixes]


@pytest.mark.parametrize(("source", "fmt", "lang"), SHEETS)
def test_rendered_again_its_lines_end_where_the_svg_sheets_do(source, fmt, lang):
    """Every line end of the SVG sheet (lines, polylines, hatch strokes, arrow heads, the
    breaks under dimension values) is a line end of the DXF as ezdxf's drawing add-on
    renders it, within 0.1 mm, and every rendered line end is one of the SVG's."""
    _, sh, svg, _, doc = sheet(source, fmt, lang)
    ends, circles, _ = svg_geometry(svg)
    drawn = rendered(doc, sh.height)
    lines = [p for kind in ("LINE", "LWPOLYLINE", "HATCH") for _, pts in drawn.get(kind, ()) for p in pts]
    boxes = [p for _, pts in drawn.get("WIPEOUT", ()) if len(pts) <= 5 for p in pts]
    assert len(ends) > 300
    assert _near(ends, lines + boxes) == []
    assert _near(lines + boxes, ends) == []
    # circles: the rendered outline's centre and radius
    got = []
    for _, pts in drawn.get("CIRCLE", ()):
        xs, ys = [p[0] for p in pts], [p[1] for p in pts]
        got.append(((min(xs) + max(xs)) / 2, (min(ys) + max(ys)) / 2, (max(xs) - min(xs)) / 2))
    assert len(got) == len(circles) > 0
    for c in circles:
        assert min(math.dist(c, g) for g in got) <= TOL, c


def _dxf_texts(doc, height):
    """(x, y, plain text, handle) of every TEXT and MTEXT, at its anchor, in sheet mm."""
    out = []
    for e in doc.modelspace().query("TEXT MTEXT"):
        if e.dxftype() == "TEXT":
            _, p, _ = e.get_placement()
        else:
            p = e.dxf.insert
        # an MTEXT's index reads back as its stack, "S^3": the characters are S and 3
        text = e.plain_text() if e.dxftype() == "TEXT" else e.plain_text().replace("^", "")
        out.append((p.x, height - p.y, text, e.dxf.handle))
    return out


@pytest.mark.parametrize(("source", "fmt", "lang"), SHEETS)
def test_every_text_is_anchored_where_the_svg_anchors_it(source, fmt, lang):
    """The same texts, each at the SVG's anchor (the start, middle or end of its baseline,
    slanted letters included) within 0.1 mm, and ezdxf's rendering of each drawn around
    its anchor."""
    _, sh, svg, _, doc = sheet(source, fmt, lang)
    _, _, anchors = svg_geometry(svg)
    texts = _dxf_texts(doc, sh.height)
    assert len(texts) == len(anchors) > 50
    for x, y, s in anchors:
        best = min(texts, key=lambda t: math.dist((x, y), t[:2]))
        assert math.dist((x, y), best[:2]) <= TOL, (s, x, y, best)
        assert best[2] == s
    glyphs: dict[str, list] = {}
    for kind in ("TEXT", "MTEXT"):
        for handle, pts in rendered(doc, sh.height).get(kind, ()):
            glyphs.setdefault(handle, []).extend(pts)
    sizes = {e.dxf.handle: e.dxf.height if e.dxftype() == "TEXT" else e.dxf.char_height
             for e in doc.modelspace().query("TEXT MTEXT")}
    for x, y, s, handle in texts:
        if not s.strip():
            continue
        pts = glyphs[handle]
        h = sizes[handle]
        xs, ys = [p[0] for p in pts], [p[1] for p in pts]
        assert min(xs) - h <= x <= max(xs) + h and min(ys) - h <= y <= max(ys) + h, (s, x, y)


def test_cyrillic_greek_and_indices_are_kept():
    doc = sheet("press")[4]
    plain = {e.plain_text() for e in doc.modelspace().query("TEXT MTEXT")}
    assert "План положений, μ^l = 0,01 м/мм" in plain  # its index read back as a stack
    raw = {e.text for e in doc.modelspace().query("MTEXT")}
    # an index is AutoCAD's subscript (a stack with nothing over it), its caret written
    # "^ " as a DXF string writes one
    assert any("V\\S^ A3A;" in t for t in raw)
    assert "μ\\S^ v; = 0,05 (м/с)/мм" in raw


def test_one_layer_per_view_and_line_kind_named_in_the_sheets_language():
    ru = {layer.dxf.name for layer in sheet("press")[4].layers}
    assert {"Рамка - основная", "Рамка - тонкая", "Основная надпись - текст",
            "План положений - штрихпунктирная", "План скоростей - основная",
            "План ускорений - текст", "Кинематические диаграммы - тонкая"} <= ru
    en = {layer.dxf.name for layer in sheet("fourbar", "A2", "en")[4].layers}
    assert {"frame - main", "title block - thin", "plan of positions - dashed",
            "velocity plan - main", "acceleration plan - text"} <= en
    doc = sheet("press")[4]
    for e in doc.modelspace():  # nothing on layer 0, every property by layer
        assert e.dxf.layer not in ("0", "Defpoints")
        assert e.dxf.get("color", 256) == 256
        assert e.dxf.get("lineweight", -1) == -1


def test_gost_line_types_and_widths():
    doc = sheet("press")[4]
    layers = {layer.dxf.name: layer for layer in doc.layers}
    assert layers["План положений - основная"].dxf.lineweight == 70
    assert layers["План положений - тонкая"].dxf.lineweight == 35
    assert layers["План положений - штриховая"].dxf.linetype == "GOST_DASHED"
    assert layers["План положений - штрихпунктирная"].dxf.linetype == "GOST_DASH_DOT"
    assert layers["План положений - штрихпунктирная с двумя точками"].dxf.linetype == "GOST_DASH_DOT_DOT"
    dashed = doc.linetypes.get("GOST_DASHED")
    assert [round(t.value, 3) for t in dashed.pattern_tags.tags if t.code == 49] == [4.0, -1.5]
    chain = doc.linetypes.get("GOST_DASH_DOT")
    assert [round(t.value, 3) for t in chain.pattern_tags.tags if t.code == 49] == [15.0, -1.5, 0.5, -1.5]
    header = doc.header
    assert header["$INSUNITS"] == 4 and header["$MEASUREMENT"] == 1 and header["$LWDISPLAY"] == 1
    assert tuple(header["$LIMMAX"]) == (841.0, 594.0)


def test_a_chain_line_starts_and_ends_with_a_dash_and_a_short_one_is_solid():
    style = Style()
    scene = Scene((Layer("positions", (Segment((0, 10), (50, 10), LineType.DASH_DOT_THIN),
                                       Segment((0, 20), (10, 20), LineType.DASH_DOT_THIN))),))
    doc = ezdxf.read(_stream(dxf.to_dxf(scene, Page(100, 50, "mm"), style)))
    long, short = doc.modelspace().query("LINE")
    period, dash = sum(style.dasharray(LineType.DASH_DOT_THIN)), style.chain_dash
    k = long.dxf.ltscale
    n = (50 - dash * k) / (period * k)
    assert n == pytest.approx(round(n)) and round(n) >= 1  # whole periods, then a dash
    assert short.dxf.linetype == "Continuous"


def test_texts_anchor_align_rotate_slant_and_stretch():
    style = Style()
    items = (Text((10, 10), "start", size=5), Text((50, 10), "middle", anchor="middle", italic=False),
             Text((90, 10), "end", anchor="end", baseline="middle", stretch=0.8),
             Text((30, 40), "turned", rotate_deg=180, baseline="hanging"))
    doc = ezdxf.read(_stream(dxf.to_dxf(Scene((Layer("t", items),)), Page(100, 50, "mm"), style)))
    texts = {e.dxf.text: e for e in doc.modelspace().query("TEXT")}
    s = style.slant_tan
    a = texts["start"].get_placement()
    assert a[0].name == "LEFT" and (a[1].x, a[1].y) == pytest.approx((10 - s * 2.5, 40))
    assert texts["start"].dxf.oblique == pytest.approx(15)
    b = texts["middle"].get_placement()
    assert b[0].name == "CENTER" and (b[1].x, b[1].y) == pytest.approx((50, 40))
    assert texts["middle"].dxf.oblique == 0
    c = texts["end"].get_placement()
    assert c[0].name == "RIGHT" and (c[1].x, c[1].y) == pytest.approx((90 - s * 1.75, 40 - 1.75))
    assert texts["end"].dxf.width == pytest.approx(0.8)
    d = texts["turned"]
    assert d.dxf.rotation == pytest.approx(180)
    assert (d.get_placement()[1].x, d.get_placement()[1].y) == pytest.approx((30 + s * 1.75, 50 - 40 + 3.5))


def test_arrow_heads_are_solid_hatches_and_blanks_and_white_joints_wipeouts():
    scene = Scene((Layer("velocity-g", (Arrow((0, 0), (20, 0)), Blank((5, 5), (10, 8)),
                                        Circle((30, 30), 2, fill="white"))),))
    doc = ezdxf.read(_stream(dxf.to_dxf(scene, Page(100, 50, "mm"))))
    msp = doc.modelspace()
    (hatch,) = msp.query("HATCH")
    assert hatch.dxf.solid_fill == 1 and hatch.dxf.layer == "velocity plan - main"
    wipeouts = msp.query("WIPEOUT")
    assert len(wipeouts) == 2
    kinds = [e.dxftype() for e in msp]
    assert kinds.index("WIPEOUT", 2) < kinds.index("CIRCLE")  # the joint's white under its ring


def test_hostile_strings_are_text_not_codes():
    items = (Text((10, 10), "a%%c{\\P}^J"), Text((10, 20), "x_{a^b;c}", markup=True))
    doc = ezdxf.read(_stream(dxf.to_dxf(Scene((Layer("t", items),)), Page(100, 50, "mm"))))
    (text,) = doc.modelspace().query("TEXT")
    (mtext,) = doc.modelspace().query("MTEXT")
    assert text.dxf.text == "a%%%%%%c{\\P}^ J"
    assert mtext.text == "x\\S^ a\\^ b\\;c;"


def test_the_same_scene_gives_the_same_bytes():
    scene, sh, _, data, _ = sheet("press")
    assert dxf.to_dxf(scene, sh, title="Кулисный механизм пресса для брикетирования", lang="ru") == data


def test_a_layer_with_a_style_of_its_own_keeps_its_colour():
    red = Style(color="#d02020", s=1.0)
    scene = Scene((Layer("student", (Segment((0, 0), (10, 10)),), style=red),
                   Layer("computed", (Segment((0, 0), (10, 0)),))))
    doc = ezdxf.read(_stream(dxf.to_dxf(scene, Page(100, 50, "mm"))))
    layers = {layer.dxf.name: layer for layer in doc.layers}
    assert layers["student - main"].rgb == (208, 32, 32)
    assert layers["student - main"].dxf.lineweight == 100
    assert layers["computed - main"].dxf.color == 7


# ---------------------------------------------------------------- a second reader

def _layers_and_texts(doc):
    return ({e.dxf.layer for e in doc.modelspace()},
            sorted(e.plain_text() for e in doc.modelspace().query("TEXT MTEXT")))


def test_read_by_ezdxfs_recover_reader_without_loss_of_layers_or_texts(tmp_path):
    """The DXF read as a damaged file would be (ezdxf's recover module, a second reader
    of its own): the same layers and texts as the scene's."""
    from ezdxf import recover

    scene, _, _, data, doc = sheet("press")
    path = tmp_path / "press.dxf"
    path.write_bytes(data)
    again, auditor = recover.readfile(path)
    assert not auditor.has_errors
    assert _layers_and_texts(again) == _layers_and_texts(doc)
    texts = [t for t in scene.items() if isinstance(t, Text)]
    assert len(_layers_and_texts(again)[1]) == len(texts)
    assert {dxf.layer_name(v, k, "ru") for v, _, items in dxf.view_layers(scene)
            for k in dxf._kinds(items)} == _layers_and_texts(again)[0]


LIBRECAD = shutil.which("librecad")


DPI = 30


def _librecad_ink(tmp_path, doc, keep: set[str]):
    """The dark pixels of LibreCAD's drawing of the A1 ``doc`` with every layer but
    ``keep`` frozen, as (row, column) arrays: dxf2pdf prints it at 1:2 on an A3 page, so
    that a pixel is 2·25.4/DPI sheet millimetres from the sheet's top-left corner."""
    import numpy as np
    from PIL import Image

    for layer in doc.layers:
        if layer.dxf.name in keep:
            layer.thaw()
        else:
            layer.freeze()
    path = tmp_path / "sheet.dxf"
    doc.saveas(path)
    env = dict(os.environ, QT_QPA_PLATFORM="offscreen", XDG_RUNTIME_DIR=str(tmp_path))
    subprocess.run([LIBRECAD, "dxf2pdf", "-s", "0.5", str(path)], cwd=tmp_path, env=env,
                   check=True, capture_output=True, timeout=120)
    subprocess.run(["pdftoppm", "-r", str(DPI), "-png", "-singlefile", str(tmp_path / "sheet.pdf"),
                    str(tmp_path / "sheet")], check=True, timeout=120)
    with Image.open(tmp_path / "sheet.png") as im:
        rows, cols = np.nonzero(np.asarray(im.convert("L")) < 128)
    mm = 2 * 25.4 / DPI
    return rows * mm, cols * mm


@pytest.mark.skipif(not (LIBRECAD and shutil.which("pdftoppm")),
                    reason="LibreCAD (Debian's librecad) and pdftoppm (poppler-utils) not installed")
def test_librecad_reads_its_layers_and_texts(tmp_path):
    """A second reader: LibreCAD's dxf2pdf draws the frame's layer alone as the frame, the
    title block's texts alone inside the title block (and its fields 26, 31 and 32), and
    nothing of a frozen layer."""
    _, sh, _, data, _ = sheet("press")
    doc = ezdxf.read(_stream(data))
    names = {layer.dxf.name for layer in doc.layers}
    assert "Рамка - основная" in names and "Основная надпись - текст" in names
    y, x = _librecad_ink(tmp_path, doc, set())
    assert len(x) == 0
    y, x = _librecad_ink(tmp_path, doc, {"Рамка - основная"})
    f = sh.frame
    assert len(x) > 0
    assert abs(x.min() - f.x) < 2 and abs(x.max() - f.x1) < 2
    assert abs(y.min() - f.y) < 2 and abs(y.max() - f.y1) < 2
    y, x = _librecad_ink(tmp_path, doc, {"Основная надпись - текст"})
    b, f26 = sh.title_block, sh.field26
    inside = ((x >= b.x - 2) & (y >= b.y - 2)) | ((x <= f26.x1 + 2) & (y <= f26.y1 + 2))  # a pixel is 1.7 mm
    assert len(x) > 100 and inside.all(), (x[~inside][:5], y[~inside][:5])
    assert ((x >= b.x + 65) & (y <= b.y + 15)).any()  # the designation, field 2


# --------------------------------------------------------------------------- the command

def test_sheet_writes_the_dxf_beside_the_svg(tmp_path, capsys):
    svg, out = tmp_path / "press.svg", tmp_path / "press.dxf"
    code, _, err = run(capsys, "sheet", "samples/press.toml", "-o", svg, "--dxf", out)
    assert code == 0, err
    doc = ezdxf.readfile(out)
    assert not doc.audit().has_errors
    assert out.read_bytes() == dxf.to_dxf(*sheet("press")[:2], title="Кулисный механизм пресса для "
                                          "брикетирования", lang="ru")


def test_sheet_refuses_a_dxf_without_a_name_or_of_another_kind(tmp_path, capsys):
    code, _, err = run(capsys, "sheet", "samples/press.toml", "-o", tmp_path / "a.svg", "--dxf")
    assert code == 2 and "--dxf: give the DXF's file name" in err
    code, _, err = run(capsys, "sheet", "samples/press.toml", "-o", tmp_path / "a.dxf")
    assert code == 2 and "for a DXF give --dxf" in err
    code, _, err = run(capsys, "sheet", "samples/press.toml", "-o", tmp_path / "a.svg", "--dxf",
                       tmp_path / "a.svg")
    assert code == 2 and "must end in .dxf" in err
    assert not list(tmp_path.iterdir())  # nothing written


def test_batch_writes_each_dxf_beside_its_svg(tmp_path, capsys):
    table = tmp_path / "t.toml"
    table.write_text("[[variant]]\nn = 6\nAB = 0.05\nBC = 0.15\nphi_deg = 15\nrpm = 100\n"
                     "[[variant]]\nn = 8\nAB = 0.06\nBC = 0.2\nphi_deg = 30\nrpm = 120\n",
                     encoding="utf-8")
    out = tmp_path / "s"
    code, _, err = run(capsys, "sheet", "--variant", "all", "--table", table, "-o", f"{out}/",
                       "--dxf", "--format", "A2")
    assert code == 0, err
    assert sorted(p.name for p in out.iterdir()) == ["variant-6.dxf", "variant-6.svg",
                                                     "variant-8.dxf", "variant-8.svg"]
    assert not ezdxf.readfile(out / "variant-8.dxf").audit().has_errors


def test_the_bytes_do_not_change_from_run_to_run(tmp_path):
    """Two processes with different string hashes write the same DXF (ezdxf orders the
    classes section by a set of the entity types used, unless told)."""
    import sys
    from pathlib import Path

    root = Path(__file__).resolve().parent.parent
    code = ("import sys\nfrom drawing.dxf import to_dxf\n"
            "from drawing.scene import Arrow, Blank, Circle, Layer, Page, Polyline, Scene, Text\n"
            "items = (Arrow((0, 0), (20, 0)), Blank((5, 5), (10, 8)), Circle((30, 30), 2, fill='white'),\n"
            "         Polyline(((0, 0), (5, 5), (9, 1))), Text((1, 1), 'x_{a}', markup=True),\n"
            "         Text((2, 2), 'y'))\n"
            "sys.stdout.buffer.write(to_dxf(Scene((Layer('v', items),)), Page(100, 50, 'mm')))\n")
    outs = [subprocess.run([sys.executable, "-c", code], capture_output=True, check=True, cwd=root,
                           env={**os.environ, "PYTHONHASHSEED": seed}).stdout for seed in ("1", "2", "3")]
    assert outs[0] == outs[1] == outs[2] and b"WIPEOUT" in outs[0]
