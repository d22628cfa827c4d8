"""Sheet 2 (``plans sheet --sheet 2``): the force analysis on one GOST sheet, read off the SVG
as a teacher reads it: every view there, every force plan's vector at the millimetres its
table gives, the lever's arms too, letters that do not collide, no text too small."""

from __future__ import annotations

import dataclasses
import math
import re
import tomllib
import xml.etree.ElementTree as ET
from functools import cache
from pathlib import Path

import pytest

from drawing.obstacles import overlaps
from drawing.scene import INDEX_SIZE, Text, flatten
from drawing.sheet.layout import LayoutError
from drawing.sheet2 import NO_LOADS, build_sheet2, force_plans_at
from drawing.svg import to_svg
from drawing.views.arrows import rays
from drawing.views.forces import force_markup, polygon_equation
from drawing.views.lever import arm_numbers
from plans.fmt import num
from plans.model import from_dict, load
from plans.model.loads import Loads, Mass
from plans.model.scenes import SCENES
from plans.model.variants import variant

ROOT = Path(__file__).resolve().parent.parent
NS = "{http://www.w3.org/2000/svg}"
#: the press (the slotted link, RRP and RPR groups, a P(S) graph, couples as pairs), seed
#: 001's four-bar (its crank makes no full turn: no diagram), a crank-slider and a
#: four-bar variant (inertia forces only)
KEYS = ["press", "fourbar", 0, 1]


def _mech(key):
    return load(ROOT / "samples" / f"{key}.toml") if isinstance(key, str) else variant(key)


@cache
def _sheet(key, lang="ru", fmt="A1"):
    mech = _mech(key)
    scene, sheet, info = build_sheet2(mech, fmt, lang)
    svg = to_svg(scene, sheet, embed_font=False)
    return mech, scene, sheet, info, svg


def _views(root) -> dict[str, ET.Element]:
    return {g.get("class").split()[1]: g for g in root.iter(NS + "g")
            if g.get("class", "").startswith("view ")}


def _offset(el) -> tuple[float, float]:
    m = re.match(r"translate\(([-\d.]+) ([-\d.]+)\)", el.get("transform", ""))
    return (float(m[1]), float(m[2])) if m else (0.0, 0.0)


def _arrows(view) -> dict[str, tuple[tuple[float, float], tuple[float, float]]]:
    """class → (start, tip) of every arrow group in a view, in the view's own mm: the start
    where its shaft begins, or (a vector shorter than its head, drawn as a head only) the
    middle of the head's base."""
    out = {}
    for g in view.iter(NS + "g"):
        cls = g.get("class", "")
        poly = g.find(NS + "polygon")
        if poly is None or not cls.split() or cls.split()[0] not in ("vec", "load", "reaction", "balancing"):
            continue
        pts = [tuple(float(v) for v in p.split(",")) for p in poly.get("points").split()]
        line = g.find(NS + "line")
        if line is not None:
            start = (float(line.get("x1")), float(line.get("y1")))
        else:
            start = ((pts[1][0] + pts[2][0]) / 2, (pts[1][1] + pts[2][1]) / 2)
        out[cls] = (start, pts[0])
    return out


def _texts(el) -> list[str]:
    return ["".join(t.itertext()) for t in el.iter(NS + "text")]


def _expected_views(info) -> set[str]:
    forces = info["forces"]
    n = len(forces.analysis.groups)
    names = {"mechanism", "crank", "lever", "loads", "reactions", "lever-table"}
    names |= {f"group-{i}" for i in range(1, n + 1)} | {f"force-{i}" for i in range(1, n + 1)}
    names.add("moment" if forces.turn is not None else "note")
    if forces.analysis.solution.mechanism.loads.resistance is not None:
        names.add("resistance")
    return names


@pytest.mark.parametrize("lang", ["ru", "en"])
@pytest.mark.parametrize("key", KEYS)
def test_every_view_is_on_the_sheet_and_nothing_more(key, lang):
    """The mechanism, each group with its force plan, the driving link, the lever, the
    tables; the M_у(φ) diagram only where the crank turns fully (the workbook's four-bar's
    does not: a note says why), the graph P(S) only where the file gives one."""
    *_, info, svg = _sheet(key, lang)
    root = ET.fromstring(svg)
    assert root.get("width") == "841mm" and root.get("height") == "594mm"
    assert set(_views(root)) == _expected_views(info)
    assert ("resistance" in _views(root)) == (key == "press")
    assert ("moment" in _views(root)) == (key != "fourbar")
    assert not re.search(r"\bnan\b|\binf\b", svg.lower())


@pytest.mark.parametrize("lang", ["ru", "en"])
@pytest.mark.parametrize("key", KEYS)
def test_every_force_plan_vector_is_drawn_at_the_mm_its_table_gives(key, lang):
    """Each group's force plan: every vector of the plan drawn, its length on the sheet
    the segment in mm at the plan's μF (within 0.03 mm), and that segment is the one the
    loads' or the reactions' table prints."""
    *_, info, svg = _sheet(key, lang)
    root = ET.fromstring(svg)
    views = _views(root)
    tables = _texts(views["loads"]) + _texts(views["reactions"])

    for i, gf in enumerate(info["forces"].analysis.groups, 1):
        plan = gf.plan
        arrows = _arrows(views[f"force-{i}"])
        drawn = 0
        for v in plan.vectors:
            mm = plan.segments[v.label]  # as the tables report it
            if mm < 1e-6:
                continue
            start, tip = arrows[f"vec f-{v.start}{v.end}-{i}"]
            assert math.dist(start, tip) == pytest.approx(mm, abs=0.03), v.label
            drawn += 1
            assert num(mm, 4, lang) in tables, v.label
        assert drawn >= 3
        # the polygon's equation under it, in the sheet's notation (its indices are tspans)
        equation = re.sub(r"[_{}^]", "", polygon_equation(plan, lang))
        assert equation in _texts(views[f"force-{i}"])


@pytest.mark.parametrize("key", KEYS)
def test_the_levers_plan_and_arms_are_drawn_at_the_mm_its_table_gives(key):
    """Zhukovsky's lever: the turned plan's pb (the crank pin's image) and every arm h
    drawn from the pole at the millimetres of the lever's table."""
    *_, info, svg = _sheet(key)
    root = ET.fromstring(svg)
    views = _views(root)
    forces, mu_v = info["forces"], info["mu"]["mu_v"]
    lv = forces.lever
    k = lv.mu_v / mu_v
    assert k == pytest.approx(1.0)  # the forces drawn are solved at the sheet's μv
    mech = forces.analysis.solution.mechanism
    tip = mech.driver.tip.lower()
    plan = forces.analysis.solution.velocity
    arrows = _arrows(views["lever"])
    start, end = arrows[f"vec l-{plan.pole}{tip}"]
    assert math.dist(start, end) == pytest.approx(lv.pb, abs=0.03)
    table = _texts(views["lever-table"])
    assert num(lv.pb, 4, "ru") in table
    numbers = arm_numbers(forces, mu_v)
    assert numbers
    lines = {g.get("class")[4:]: g.find(NS + "line") for g in views["lever"].iter(NS + "g")
             if g.get("class", "").startswith("arm ")}
    assert set(lines) == set(numbers)
    for t in lv.terms:
        if t.name in numbers:
            ln = lines[t.name]
            length = math.dist((float(ln.get("x1")), float(ln.get("y1"))),
                               (float(ln.get("x2")), float(ln.get("y2"))))
            assert length == pytest.approx(t.arm, abs=0.03), t.name
            assert num(t.arm, 4, "ru") in table, t.name
    assert f"h{max(numbers.values())}" in table and "Fу" in table


@pytest.mark.parametrize("lang", ["ru", "en"])
@pytest.mark.parametrize("key", KEYS)
def test_no_two_texts_collide_and_none_is_too_small(key, lang):
    """Every text of the views clear of every other; letters 2.5 mm or more, and any text
    with an index 3.5 mm, so that its indices are GOST 2.304's 1.8 mm or more."""
    _, scene, *_ = _sheet(key, lang)
    texts = [it for it in scene.items("views") if isinstance(it, Text)]
    assert overlaps(texts) == []
    for t in texts:
        assert t.size >= 2.5 - 1e-9, t.text
        if any(r.level for r in t.runs()):
            assert t.size * INDEX_SIZE >= 1.8 - 1e-9, t.text


@pytest.mark.parametrize("key", KEYS)
def test_every_load_is_drawn_at_its_point_and_nothing_that_is_zero(key):
    """The mechanism's view: an arrow for every load with a force, at its point (its
    start or its tip on the point's ring), an arc for every inertia moment (or, where the
    file writes couples as pairs, its two forces); no arc where J or ε is zero (the
    variants take inertia forces only)."""
    mech, _, _, info, svg = _sheet(key)
    view = _views(ET.fromstring(svg))["mechanism"]
    classes = {g.get("class") for g in view.iter(NS + "g")}
    fa = info["forces"].analysis
    for ld in fa.loads:
        if ld.force != 0:
            assert f"load {ld.name}" in classes, ld.name
        if ld.moment:
            pairs = mech.loads.couples == "pair"
            assert (f"moment {ld.name}" in classes) != pairs
            assert any(c.startswith(f"load {ld.name}(") for c in classes) == pairs
    if not mech.loads.inertia_moments:
        assert not any(c.startswith("moment ") for c in classes)
        assert not any(ld.kind == "inertia moment" for ld in fa.loads)


def test_the_press_shows_its_useful_resistance_where_the_analysis_reads_it():
    """The graph P(S) marks the analysed position: P = 1100 N at S = 0.1492 m."""
    *_, svg = _sheet("press")
    texts = _texts(_views(ET.fromstring(svg))["resistance"])
    assert "P = 1100 Н при S = 0,1492 м (рабочий ход)" in texts


def test_the_title_block_names_the_sheet_and_numbers_it_2_of_2():
    _, scene, *_ = _sheet("press")
    words = {t.text for t in scene.items("title-block") if isinstance(t, Text)}
    assert any("Силовой" in w for w in words) and any("анализ" in w for w in words)
    assert {"Лист", "Листов", "2"} <= words
    _, scene, *_ = _sheet(1, "en")
    words = " ".join(t.text for t in scene.items("title-block") if isinstance(t, Text))
    assert "Force analysis" in words


def test_force_names_are_written_as_the_course_writes_them():
    assert [force_markup(n) for n in ("G4", "Φ3", "R34^τ", "R05", "M_Φ3", "M_Φ3(B)", "F_пс")] == [
        "G_4", "Φ_3", "R^τ_{34}", "R_{05}", "M_{Φ3}", "P_{Φ3}", "F_{пс}"]
    assert force_markup("R34^τ", "en") == "R^t_{34}"


def test_arrows_at_one_point_keep_off_its_bars_and_each_other():
    """A force along a bar arrives at the point from outside; two alike both leave it
    (they are then drawn side by side), rather than one lie on the bar."""
    assert rays([1 + 0j], [], [1 + 0j]) == [-1 + 0j]
    got = rays([-1 + 0j], [], [1 + 0j, 1 + 0j])
    assert [r.real for r in got] == [1.0, 1.0]


def test_the_force_plans_sizes_keep_their_vectors_and_their_standard_mu_F():
    """The sheet draws each force plan at the standard μF for its size; at size 1 that is
    the μF ``plans forces`` gives; its segments follow μF, its vectors do not change."""
    *_, info, _ = _sheet("press", "ru", "A2")
    forces = info["forces"]
    at_one = force_plans_at(forces, 1.0)
    assert [g.plan.mu for g in at_one.analysis.groups] == [10.0, 20.0]
    for a, b in zip(at_one.analysis.groups, forces.analysis.groups, strict=True):
        assert a.plan.points == b.plan.points
        for label, mm in a.plan.segments.items():
            assert mm * a.plan.mu == pytest.approx(b.plan.segments[label] * b.plan.mu)


def _with_loads(name: str):
    """A built-in scene with a mass and a moment of inertia on every link (centred on its
    last point): every dyad kind gets a force plan."""
    mech = from_dict(tomllib.loads(SCENES[name].toml), name)
    masses = {lid: Mass(lid, 1.0 + lid, 0.01 * lid, list(link.points)[-1])
              for lid, link in mech.links.items()}
    return dataclasses.replace(mech, loads=Loads(g=9.81, masses=masses))


@pytest.mark.parametrize(("name", "kinds"), [
    ("prp_two_moving", ["PRP", "RPR"]), ("yoke_on_rocker", ["RPP", "RPR"]), ("scotch_yoke", ["RPP"]),
    ("slot_rrp_moving", ["RRP", "RPR"])])
def test_every_dyad_kind_gets_its_group_and_force_plan(name, kinds):
    mech = _with_loads(name)
    scene, sheet, info = build_sheet2(mech, "A1", "en")
    svg = to_svg(scene, sheet, embed_font=False)
    assert [g.group.kind.name for g in info["forces"].analysis.groups] == kinds
    views = _views(ET.fromstring(svg))
    for i, gf in enumerate(info["forces"].analysis.groups, 1):
        arrows = _arrows(views[f"force-{i}"])
        for v in gf.plan.vectors:
            mm = gf.plan.mm(v.start, v.end)
            if mm > 1e-6:
                start, tip = arrows[f"vec f-{v.start}{v.end}-{i}"]
                assert math.dist(start, tip) == pytest.approx(mm, abs=0.03)
        assert f"group-{i}" in views
    assert overlaps([it for it in flatten(scene.items("views")) if isinstance(it, Text)]) == []
    assert "nan" not in svg.lower()


def test_a_mechanism_without_loads_is_refused_in_one_line():
    mech = from_dict(tomllib.loads(SCENES["crank_rocker"].toml), "crank_rocker.toml")
    from plans.errors import InputError

    with pytest.raises(InputError) as err:
        build_sheet2(mech)
    assert str(err.value).count("\n") == 0 and NO_LOADS in str(err.value)


def test_a4_is_refused_naming_the_format_that_holds_sheet_2():
    with pytest.raises(LayoutError) as err:
        build_sheet2(_mech("fourbar"), "A4", "en")
    assert "use --format A2" in str(err.value) and err.value.option == "--format"


# ---- the command line ----------------------------------------------------------------

def _run(capsys, *argv):
    from plans.cli import main

    code = main(list(argv))
    out, err = capsys.readouterr()
    return code, out, err


def test_both_sheets_in_one_run_put_sheet_2_beside_sheet_1(capsys, tmp_path):
    """--sheet 1,2: -o, --png and --note name sheet 1's files, sheet 2's go beside them
    (NAME-2.svg); sheet 1 is sheet 1 of 2; the note goes on with the force section."""
    out = tmp_path / "out"
    out.mkdir()
    code, _, err = _run(capsys, "sheet", str(ROOT / "samples" / "press.toml"), "--sheet", "1,2",
                        "--format", "A2", "-o", str(out / "press.svg"), "--png", str(out / "press.png"),
                        "--dpi", "20", "--note", str(out / "press.md"))
    assert code == 0, err
    assert sorted(p.name for p in out.iterdir()) == ["press-2.png", "press-2.svg", "press.md", "press.png",
                                                    "press.svg"]
    one = ET.fromstring((out / "press.svg").read_text(encoding="utf-8"))
    two = ET.fromstring((out / "press-2.svg").read_text(encoding="utf-8"))
    assert "positions" in _views(one) and "force-1" in _views(two)

    def numbers(root):  # fields 7 and 8: the texts after «Лист» (the field's, not the header's)
        texts = [t for t in _texts(root) if t.strip()]
        at = len(texts) - 1 - texts[::-1].index("Лист")
        return texts[at + 1], texts[texts.index("Листов") + 1]

    assert numbers(one) == ("1", "2") and numbers(two) == ("2", "2")
    note = (out / "press.md").read_text(encoding="utf-8")
    assert "## 5. Силовой анализ" in note and "## 4. План ускорений" in note


def test_sheet_2_alone_is_written_where_o_says_and_its_note_is_the_whole_analysis(capsys, tmp_path):
    code, _, err = _run(capsys, "sheet", "--variant", "1", "--sheet", "2", "--lang", "en",
                        "-o", str(tmp_path / "v1.svg"), "--note", str(tmp_path / "v1.md"))
    assert code == 0, err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["v1.md", "v1.svg"]
    note = (tmp_path / "v1.md").read_text(encoding="utf-8")
    assert "Force analysis" in note and "Zhukovsky" in note


@pytest.mark.parametrize("argv", [["--sheet", "1,2"], ["--sheet", "all", "-o", "-"]])
def test_two_sheets_are_not_written_to_stdout(capsys, argv):
    code, out, err = _run(capsys, "sheet", str(ROOT / "samples" / "press.toml"), *argv)
    assert code == 2 and out == ""
    assert err.count("\n") == 1 and "two sheets are two files" in err


def test_sheet_2s_name_is_checked_before_anything_is_drawn(capsys, tmp_path):
    """Sheet 2's file beside sheet 1's is refused (a folder there) before anything is
    computed: neither sheet is written."""
    (tmp_path / "s-2.svg").mkdir()
    code, _, err = _run(capsys, "sheet", str(ROOT / "samples" / "press.toml"), "--sheet", "1,2",
                        "-o", str(tmp_path / "s.svg"))
    assert code == 2 and "is a folder" in err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["s-2.svg"]


@pytest.mark.parametrize("sheets", ["2", "1,2"])
def test_a_file_without_loads_gets_one_line_and_no_sheet(capsys, tmp_path, sheets):
    src = tmp_path / "crank_rocker.toml"
    src.write_text(SCENES["crank_rocker"].toml, encoding="utf-8")
    code, _, err = _run(capsys, "sheet", str(src), "--sheet", sheets, "-o", str(tmp_path / "s.svg"))
    assert code == 2
    assert err.count("\n") == 1 and "loads: missing" in err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["crank_rocker.toml"]


@pytest.mark.parametrize(("argv", "words"), [
    (["--sheet", "3"], "--sheet: '3'"),
    (["--sheet", "2", "--plans", "1,4"], "--plans: chooses the positions of sheet 1's plans"),
])
def test_a_wrong_sheet_or_plans_for_sheet_2_is_refused(capsys, tmp_path, argv, words):
    code, _, err = _run(capsys, "sheet", str(ROOT / "samples" / "press.toml"), *argv,
                        "-o", str(tmp_path / "s.svg"))
    assert code == 2 and words in err and err.count("\n") == 1
    assert not (tmp_path / "s.svg").exists()


def test_a_batch_writes_sheet_2_beside_each_sheet_1(capsys, tmp_path):
    """--variant all --sheet all: variant-N.svg and variant-N-2.svg; --sheet 2 alone:
    variant-N-2.svg, as it would be beside sheet 1."""
    table = tmp_path / "t.toml"
    rules = (ROOT / "plans" / "data" / "table2.toml").read_text(encoding="utf-8")
    loads = rules[rules.index("[loads]"):rules.index("[[variant]]")]
    table.write_text(loads + "[[variant]]\nn = 6\nAB = 0.05\nBC = 0.15\nphi_deg = 15\nrpm = 100\n",
                     encoding="utf-8")
    both, second = tmp_path / "both", tmp_path / "second"
    code, _, err = _run(capsys, "sheet", "--variant", "all", "--table", str(table), "--sheet", "all",
                        "-o", str(both))
    assert code == 0, err
    assert sorted(p.name for p in both.iterdir()) == ["variant-6-2.svg", "variant-6.svg"]
    code, _, err = _run(capsys, "sheet", "--variant", "all", "--table", str(table), "--sheet", "2",
                        "-o", str(second))
    assert code == 0, err
    assert [p.name for p in second.iterdir()] == ["variant-6-2.svg"]


    def mu_v(path, title):  # the μv of the caption that starts with ``title`` (on one line or two)
        texts = " ".join(_texts(ET.fromstring(path.read_text(encoding="utf-8"))))
        return re.search(title + r"[^μ]*μv = ([\d,]+)", texts)[1]

    # beside sheet 1, sheet 2's lever is sheet 1's velocity plan turned, at its μv
    assert mu_v(both / "variant-6-2.svg", "Рычаг") == mu_v(both / "variant-6.svg", "План скоростей")


def test_the_committed_sample_is_what_the_readmes_command_writes(tmp_path):
    """samples/press-2.svg is regenerated byte for byte by README's command."""
    import os

    from plans.cli import main

    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    assert ("plans sheet samples/press.toml --sheet 2 --format A2 -o samples/press-2.svg --png\n"
            "samples/press-2.png") in readme
    here = os.getcwd()
    try:
        os.chdir(ROOT)  # the command as README gives it, its file named as there
        assert main(["sheet", "samples/press.toml", "--sheet", "2", "--format", "A2",
                     "-o", str(tmp_path / "press-2.svg")]) == 0
    finally:
        os.chdir(here)
    assert (tmp_path / "press-2.svg").read_bytes() == (ROOT / "samples" / "press-2.svg").read_bytes()


def _tallest_band(svg: str, fmt: str, px_per_mm: float = 4.0) -> float:
    """mm: the tallest strip across the whole field inside the frame with no ink."""
    import io

    import numpy as np
    from PIL import Image

    from drawing import export
    from drawing.sheet.frame import Sheet

    ink = np.asarray(Image.open(io.BytesIO(export.png_bytes(svg, dpi=25.4 * px_per_mm))).convert("L")) < 128
    f = Sheet(fmt).frame
    rows = ink[int((f.y + 1.5) * px_per_mm):int((f.y1 - 1.5) * px_per_mm),
               int((f.x + 1.5) * px_per_mm):int((f.x1 - 1.5) * px_per_mm)].any(axis=1)
    best = run = 0
    for r in rows:
        run = 0 if r else run + 1
        best = max(best, run)
    return best / px_per_mm


@pytest.mark.parametrize(("key", "fmt"), [("press", "A2"), ("press", "A1"), ("fourbar", "A1"), (1, "A1"),
                                          (3, "A1"), (0, "A2"), (4, "A2")])
def test_the_views_fill_the_sheet_without_a_wide_blank_band(key, fmt):
    """No strip across the field taller than 60 mm is left without ink (measured on the
    PNG), on A1 for the samples and the four-bars, on A2 for the crank-slider, whose flat
    views leave about 70 mm of A1 blank (README)."""
    pytest.importorskip("cairosvg")
    *_, svg = _sheet(key, "ru", fmt)
    assert _tallest_band(svg, fmt) <= 60.0
