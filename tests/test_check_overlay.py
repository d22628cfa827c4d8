"""``plans check --svg``: the overlay's texts stay in the drawing, never overlap, and
every deviation beyond tolerance is labelled on its plan.

The reviewer's files (tests/overlay_cases) had the diagnosis run past the right edge and
cut ("…the acceleration plan is drawn 20", «…крупнее (при»), the velocity plan's list
of deviations run into the acceleration plan's, labels on the plan without their value
(πc, πa3) or missing (dn2, n1c, n2c), and the Russian SVG an English title with a raw
"a^k_A3A". The layout's own boxes (:class:`drawing.overlay.Overlay`) are checked
with shapely, and they are checked against what the project's osifont (which the SVG
embeds and the PNG is drawn with) draws.
"""

from __future__ import annotations

import dataclasses
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
import shapely
from support import run

from drawing.overlay import Overlay, mark, overlay
from plans.check import verdict as ck

HERE = Path(__file__).resolve().parent
CASES = HERE / "overlay_cases"
FILES = [CASES / "p_muswap.toml", CASES / "f_lineB_par.toml", CASES / "m_cor_pd15.toml",
         HERE.parent / "samples" / "check_press.toml"]
SVG = "{http://www.w3.org/2000/svg}"


@pytest.fixture(scope="module")
def results():
    return {path.stem: ck.check(ck.load(path)) for path in FILES}


def _layouts(results):
    return {(name, lang): overlay(res, lang) for name, res in results.items()
            for lang in ("en", "ru")}


@pytest.fixture(scope="module")
def layouts(results) -> dict[tuple[str, str], Overlay]:
    return _layouts(results)


@pytest.mark.parametrize("lang", ["en", "ru"])
@pytest.mark.parametrize("name", [p.stem for p in FILES])
def test_no_text_leaves_the_drawing_or_overlaps_another(layouts, name, lang):
    ov = layouts[name, lang]
    frame = shapely.box(0, 0, ov.width, ov.height)
    boxes = [shapely.box(*b) for _, b, _ in ov.texts]
    for (text, b, role), poly in zip(ov.texts, boxes, strict=True):
        assert frame.contains(poly), f"{role} {text!r} leaves the drawing: {b}"
    tree = shapely.STRtree(boxes)
    left, right = tree.query(boxes, predicate="intersects")
    for i, j in zip(left, right, strict=True):
        if i < j and boxes[i].intersection(boxes[j]).area > 0.01:
            raise AssertionError(f"{ov.texts[i][:1]} ({ov.texts[i][2]}) overlaps "
                                 f"{ov.texts[j][:1]} ({ov.texts[j][2]})")


@pytest.mark.parametrize("name", [p.stem for p in FILES])
def test_every_deviation_beyond_tolerance_is_labelled_on_its_plan(results, layouts, name):
    res = results[name]
    for lang in ("en", "ru"):
        ov = layouts[name, lang]
        labels = [t for t, _, role in ov.texts if role == "deviation"]
        listed = " ".join(t for t, _, role in ov.texts if role == "list")
        marks = [mark(d.item.name, d.deviation, lang) for d in res.failed
                 if d.item.kind == "segment"]
        assert sorted(labels) == sorted(marks), lang  # each with its value, none bare
        for m in marks:  # and each in the list under its panel, whole on one line
            assert m in listed, (lang, m)


def test_the_boxes_hold_what_osifont_draws(layouts):
    """Each text's box is as wide as osifont (the font the SVG embeds) draws the text to
    the end of its ink, indices at their size, within the one text rule's stated ±10 %
    (drawing.text); the
    SVG holds the texts the layout placed, in its order. (The overlay was drawn in
    "sans-serif" with its own width table of DejaVu Sans; it now takes the sheets' font
    and rule.)"""
    ImageFont = pytest.importorskip("PIL.ImageFont")
    from drawing.styles import FONT_FILE, Style

    font = ImageFont.truetype(str(FONT_FILE), 100)
    for (name, lang), ov in layouts.items():
        root = ET.fromstring(ov.tostring())
        els = list(root.iter(f"{SVG}text"))
        assert len(els) == len(ov.texts), (name, lang)
        for el, (text, box, role) in zip(els, ov.texts, strict=True):
            assert "".join(el.itertext()) == text
            size = float(el.get("font-size"))
            runs = [(el.text, size)] if el.text else []
            runs += [(sp.text, float(sp.get("font-size") or size)) for sp in el.iter(f"{SVG}tspan")]
            # where the ink ends: the advances of the runs before the last, the last one's ink
            drawn = (sum(font.getlength(t) * z / 100 for t, z in runs[:-1])
                     + font.getbbox(runs[-1][0])[2] * runs[-1][1] / 100)
            assert float(el.get("x")) == pytest.approx(box[0], abs=0.01)
            assert el.get("text-anchor") is None  # written from its start, as laid out
            # the rule's ±10 % on words; on a label of a letter or two ("a", "n1": osifont
            # sets its digits in cells of one width) half a letter
            wide, h = box[2] - box[0], size * Style().cap_height
            assert drawn <= max(1.1 * wide, wide + 0.5 * h), (name, lang, role, text)


def test_the_overlay_speaks_the_reports_language_and_notation(tmp_path, capsys, monkeypatch):
    """--lang ru: the title was English ("plans check: …") and the diagnosis showed the
    raw a^k_A3A; both follow the language now, the components written as on the plans:
    a with k above and A3A below, μ with its v. The file is named as the command was given
    it: relative here, so that the title is whole wherever the checkout lies (a long
    absolute path is shortened with "..." at its start)."""
    monkeypatch.chdir(CASES)
    for lang, title, words in (("en", "Check of a hand-drawn plan: ", "Coriolis"),
                               ("ru", "Проверка плана, построенного вручную: ", "Кориолиса")):
        out = tmp_path / f"{lang}.svg"
        code, _, err = run(capsys, "check", "m_cor_pd15.toml", "--lang", lang, "--svg", out)
        assert code == 1, err
        root = ET.parse(out).getroot()
        texts = ["".join(el.itertext()) for el in root.iter(f"{SVG}text")]
        assert texts[0] == title + "m_cor_pd15.toml"
        diagnosis = next(el for el in root.iter(f"{SVG}text") if words in "".join(el.itertext()))
        assert "^" not in "".join(texts) and "a^k" not in "".join(texts)
        spans = [(sp.text, float(sp.get("font-size") or diagnosis.get("font-size")))
                 for sp in diagnosis.iter(f"{SVG}tspan")]
        assert ("k", pytest.approx(11 * 0.7)) in spans and ("A3A", pytest.approx(11 * 0.7)) in spans
        caption = next(el for el in root.iter(f"{SVG}text") if "(m/s)/mm" in "".join(el.itertext())
                       or "(м/с)/мм" in "".join(el.itertext()))
        # the first index of the caption (its spans with a size of their own) is μ's v
        assert [sp.text for sp in caption.iter(f"{SVG}tspan") if sp.get("font-size")][:1] == ["v"]


def test_the_rendered_drawing_has_no_ink_at_its_edges(tmp_path):
    """The picture as the command renders it (drawing.export, with the project's osifont,
    in a fresh process: fontconfig reads its setup once): nothing drawn in the margin at
    the right or at the bottom, where the cut diagnosis was."""
    import subprocess
    import sys

    pytest.importorskip("cairosvg")
    Image = pytest.importorskip("PIL.Image")
    code = ("import sys\nfrom pathlib import Path\nfrom drawing import export\n"
            "from drawing.overlay import overlay\nfrom plans.check import verdict as ck\n"
            "res = ck.check(ck.load(sys.argv[1]))\n"
            "for lang in ('en', 'ru'):\n"
            "    ov = overlay(res, lang)\n"
            "    Path(sys.argv[2], lang + '.png').write_bytes(export.png_bytes(ov.tostring()))\n"
            "    print(lang, ov.width, ov.height)\n")
    r = subprocess.run([sys.executable, "-c", code, str(CASES / "p_muswap.toml"), str(tmp_path)],
                       capture_output=True, text=True, cwd=HERE.parent)
    assert r.returncode == 0, r.stderr
    for line in r.stdout.split("\n")[:2]:
        lang, width, height = line.split()
        im = Image.open(tmp_path / f"{lang}.png").convert("L")
        w, h = im.size
        assert (w, h) == (round(float(width)), round(float(height)))
        right = im.crop((w - 16, 0, w, h)).getextrema()
        bottom = im.crop((0, h - 12, w, h)).getextrema()
        assert right[0] > 200 and bottom[0] > 200, (lang, right, bottom)


def test_a_russian_list_of_numbers_is_separated_by_semicolons(tmp_path, capsys):
    """«вне допуска, мм: n1a3 +22,1, πa3 +18,6, …» had commas both as decimal marks and
    between the items; in Russian the items take «; », in English ", " as before. The
    report's line of scale factors is one such list too."""
    meas = tmp_path / "cor.toml"
    meas.write_text(f'mechanism = "{HERE.parent / "samples" / "press.toml"}"\nangle_deg = 30\n'
                    "[scales]\nmu_l = 0.01\nmu_v = 0.05\nmu_a = 1.0\n[segments]\n"
                    "ak = 11\nbn1 = 13.4\nn1a3 = 34\npia3 = 36.5\npic = 47.5\npid = 49\n", "utf-8")
    res = ck.check(ck.load(meas))
    for lang, text in (("ru", "вне допуска, мм: n1a3 +22,1; πa3 +18,6; πc +24,2; πd +28,2"),
                       ("en", "beyond tolerance, mm: n1a3 +22.1, πa3 +18.6, πc +24.2, πd +28.2")):
        listed = " ".join(t for t, _, role in overlay(res, lang).texts if role == "list")
        assert listed == text
    _, out, _ = run(capsys, "check", meas, "--lang", "ru")
    assert ("Масштабные коэффициенты студента: μl = 0,01 м/мм; μv = 0,05 (м/с)/мм; "
            "μa = 1 (м/с²)/мм\n") in out
    _, out, _ = run(capsys, "check", meas)
    assert "Student's scale factors: μl = 0.01 m/mm, μv = 0.05 (m/s)/mm, μa = 1 (m/s²)/mm\n" in out


@pytest.mark.parametrize(("name", "shared"), [("check_press", {"p,o,b", "π,o,b"})])
def test_coincident_points_are_lettered_as_on_the_sheet(results, name, shared):
    """The picture had lettered the points at the pole «o≡b≡π»; the sheet writes them
    «π,o,b», the pole first, and the picture now takes the sheet's rule
    (drawing.scene.shared_label): the same labels on both."""
    from drawing.scene import Text, flatten
    from drawing.views import plan_view

    res = results[name]
    sol = res.measurement.solution
    sheet = {it.text for kind in ("velocity", "acceleration")
             for it in flatten(plan_view(sol, kind, "1").items) if isinstance(it, Text)}
    assert shared <= sheet
    for lang in ("en", "ru"):
        points = [t for t, _, role in overlay(res, lang).texts if role == "point"]
        assert shared <= set(points) and not any("≡" in t for t in points), points
        assert {t for t in points if "," in t} == shared


def test_the_overlay_loads_no_command_line_and_no_chart_library():
    """The check's picture is drawn as the sheets are (one text rule, one placer, one SVG
    writer: so it loads shapely and svgwrite, which it had kept clear of), but importing
    it loads nothing of the command line and neither matplotlib nor cairosvg (only a PNG
    asks for that)."""
    import subprocess
    import sys

    code = ("import sys\nimport drawing.overlay\n"
            "print(sorted({m for m in sys.modules if m.split('.')[0] in ('matplotlib', 'cairosvg')"
            " or m.startswith('plans.cli')}))\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True,
                         cwd=HERE.parent, env={"PYTHONPATH": str(HERE.parent), "PATH": ""})
    assert out.stdout.strip() == "[]"


def test_the_links_images_are_drawn_thin_on_both_panels(tmp_path):
    """The sheet draws the line each similarity point is found on (b–c–e of the
    four-bar's coupler BCE); the check's picture drew only the plan's vectors, and on
    its acceleration panel e and s2 floated beside them. One thin line is drawn per
    side of ``plans.plan.image_sides``, on each panel."""
    from plans.plan.solution import image_sides

    path = tmp_path / "m.toml"
    path.write_text(f'mechanism = "{(HERE.parent / "samples" / "fourbar.toml").as_posix()}"\n'
                    "[scales]\nmu_v = 0.02\nmu_a = 0.2\n[segments]\npb = 48.8\npc = 45.9\n"
                    '"πb" = 76.3\n"πc" = 59.9\n', encoding="utf-8")
    res = ck.check(ck.load(path))
    sol = res.measurement.solution
    root = ET.fromstring(overlay(res, "en").tostring().split("\n", 1)[1])
    # a line takes its colour from its layer (drawing.svg writes one style a layer)
    thin = [e for g in root.iter(SVG + "g") if g.get("stroke") == "#222"
            for e in g.findall(SVG + "line") if e.get("stroke-width") == "0.5"]
    want = sum(len(image_sides(p)) for p in (sol.velocity, sol.acceleration))
    assert want >= 2 and len(thin) == want


def test_a_long_path_in_the_title_is_shortened_at_its_start(results):
    """The title names the file; a path too long for the drawing loses its start, not its
    file name ("Check of a hand-drawn plan: .../deep/m_cor_pd15.toml"; osifont has no
    "…")."""
    res = results["m_cor_pd15"]
    meas = res.measurement
    long = "/" + "/".join(["a-folder-with-a-long-name"] * 12) + "/m_cor_pd15.toml"
    res = dataclasses.replace(res, measurement=dataclasses.replace(meas, source=long))
    ov = overlay(res, "en")
    (title,) = [t for t, _, role in ov.texts if role == "title"][:1]
    head = "Check of a hand-drawn plan: "
    assert title.startswith(head + "...") and long.endswith(title[len(head) + 3:])
    assert title.endswith("/m_cor_pd15.toml")


def test_control_characters_in_a_title_or_a_path_leave_the_svg_readable(results):
    """A control character (U+0001…U+001F but tab and newline) in a measurement's title or
    file name made the overlay an SVG no parser reads: it had its own writer. It is now
    written by drawing.svg, the sheets' writer, which replaces what XML cannot carry."""
    res = results["m_cor_pd15"]
    meas = dataclasses.replace(res.measurement, title="Group\x01 7\x1b[31m",
                               source="m\x02_cor\x1f.toml")
    svg = overlay(dataclasses.replace(res, measurement=meas), "en").tostring()
    root = ET.fromstring(svg)  # well-formed
    texts = ["".join(el.itertext()) for el in root.iter(f"{SVG}text")]
    assert texts[0].endswith("m\ufffd_cor\ufffd.toml")
    assert "Group\ufffd 7\ufffd[31m" in texts


@pytest.mark.parametrize("lang", ["en", "ru"])
def test_every_character_of_the_picture_is_in_the_projects_font(results, lang):
    """The diagnosis of a line drawn parallel instead of perpendicular says "∥ CB" and
    "⊥ CB": osifont has neither, and the PNG printed boxes. The picture writes what the
    font can draw ("||", "_|_"), as the sheets write ∥."""
    ttlib = pytest.importorskip("fontTools.ttLib")
    from drawing.styles import FONT_FILE

    cmap = ttlib.TTFont(FONT_FILE).getBestCmap()
    root = ET.fromstring(overlay(results["f_lineB_par"], lang).tostring())
    text = "".join("".join(el.itertext()) for el in root.iter(f"{SVG}text"))
    assert "||" in text and "_|_" in text
    assert sorted({c for c in text if not c.isspace() and ord(c) not in cmap}) == []
