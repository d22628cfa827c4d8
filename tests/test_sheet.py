"""Sheet 1 (``plans sheet``): sizes, letters, no overlapping texts, vector lengths."""

from __future__ import annotations

import math
import re
import subprocess
import sys
import xml.etree.ElementTree as ET
from functools import cache
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from drawing.obstacles import overlaps
from drawing.scene import Text
from drawing.sheet.layout import share_covered
from drawing.sheet1 import build_sheet
from drawing.styles import LineType
from drawing.svg import to_svg
from drawing.text import text_box
from drawing.views import JOINT_R
from plans.model import load
from plans.model.scenes import SCENES
from plans.model.variants import variant, variant_numbers

ROOT = Path(__file__).resolve().parent.parent
NS = "{http://www.w3.org/2000/svg}"
SAMPLES = ["press", "fourbar"]


def _mech(key):
    return load(ROOT / "samples" / f"{key}.toml") if isinstance(key, str) else variant(key)


@cache
def _sheet(key, fmt="A1", lang="ru", plans=None):
    mech = _mech(key)
    scene, sheet, info = build_sheet(mech, fmt, lang, 12, list(plans) if plans else None)
    return mech, scene, sheet, info, to_svg(scene, sheet, embed_font=False)


def _texts(svg):
    root = ET.fromstring(svg)
    return root, ["".join(el.itertext()) for el in root.iter(NS + "text")]


def _vectors(root):
    """class → (start, tip) of every plan vector group on the sheet."""
    out = {}

    def walk(el, dx, dy):
        tr = el.get("transform", "")
        if m := re.match(r"translate\(([-\d.]+) ([-\d.]+)\)", tr):
            dx, dy = dx + float(m[1]), dy + float(m[2])
        cls = el.get("class", "")
        if cls.startswith("vec "):
            line = el.find(NS + "line")
            poly = el.find(NS + "polygon")
            tip = [float(v) for v in poly.get("points").split()[0].split(",")]
            start = (float(line.get("x1")), float(line.get("y1"))) if line is not None else None
            out[cls.split()[1]] = (start, (tip[0], tip[1]))
            return
        for ch in el:
            walk(ch, dx, dy)

    walk(root, 0.0, 0.0)
    return out


KEYS = SAMPLES + list(variant_numbers())


@pytest.mark.parametrize("key", KEYS)
def test_sheet_size_letters_and_texts(key):
    _mech, scene, _sheet_obj, info, svg = _sheet(key)
    root, texts = _texts(svg)
    assert root.get("width") == "841mm" and root.get("height") == "594mm"
    letters = set()
    for t in texts:
        letters.update(x.strip() for x in t.split(","))
    for _, _, sol in info["solutions"]:
        for plan in (sol.velocity, sol.acceleration):
            missing = {n for n in plan.points if n not in letters} - {plan.pole}
            assert not missing, f"unlettered plan points {missing}"
            assert plan.pole in letters
    items = [it for it in scene.items() if isinstance(it, Text)]
    assert overlaps(items) == []


@pytest.mark.parametrize("key", KEYS)
def test_vectors_drawn_at_their_segment_lengths(key):
    _mech, _scene, _sheet_obj, info, svg = _sheet(key)
    root, _ = _texts(svg)
    vecs = _vectors(root)
    checked = 0
    for tag, _, sol in info["solutions"]:
        for letter, plan in (("v", sol.velocity), ("a", sol.acceleration)):
            for v in plan.vectors:
                mm = plan.mm(v.start, v.end)
                key_ = f"{letter}-{v.start}{v.end}-{tag}"
                if mm < 4.0:  # drawn as a head only, no shaft line to measure from
                    continue
                start, tip = vecs[key_]
                assert math.dist(start, tip) == pytest.approx(mm, abs=0.03)
                checked += 1
    assert checked >= 4


def test_diagrams_only_with_a_stroke():
    *_, svg = _sheet("fourbar")
    _, texts = _texts(svg)
    assert any("Диаграммы не строятся" in t for t in texts)
    assert not any("Кинематические диаграммы" in t for t in texts)
    *_, svg = _sheet("press")
    _, texts = _texts(svg)
    assert any("Кинематические диаграммы" in t for t in texts)


def test_two_positions_english_a1():
    from plans.fmt import angle

    mech, scene, _sheet_obj, info, svg = _sheet("press", "A1", "en", (1, 4))
    _, texts = _texts(svg)
    # a plan names its position and its crank angle, in the file's convention
    deg = [angle(mech.driver.file_angle(info["cycle"].positions[k])) for k in (1, 4)]
    assert any(t.startswith(f"Velocity plan (position 1, φ1 = {deg[0]}°)") for t in texts), texts
    assert any(t.startswith(f"Acceleration plan (position 4, φ1 = {deg[1]}°)") for t in texts)
    assert len(set(deg)) == 2
    assert overlaps([it for it in scene.items() if isinstance(it, Text)]) == []


def test_cli_stdout_and_batch(tmp_path):
    env = {"PYTHONPATH": str(ROOT)}
    r = subprocess.run([sys.executable, "-m", "plans", "sheet", "samples/press.toml", "-o", "-",
                        "--title-block", "student=Иванов", "group=ТМ-21"],
                       cwd=ROOT, capture_output=True, env=env, timeout=60)
    assert r.returncode == 0, r.stderr.decode()
    _, texts = _texts(r.stdout.decode())
    assert "Иванов" in texts and "1:10" in texts
    # the press file fixes its scales, small for A1: the command says so, and how to mend it
    assert r.stderr.decode() == (
        "plans sheet: note: samples/press.toml: the views take 22% of the A1 sheet's field "
        "at the scale factors the file fixes (μl, μv, μa); leave them out of [scales] for "
        "the sheet to choose them, or take a smaller --format\n")
    r = subprocess.run([sys.executable, "-m", "plans", "sheet", "--variant", "all", "-o", str(tmp_path)],
                       cwd=ROOT, capture_output=True, env=env, timeout=120)
    assert r.returncode == 0, r.stderr.decode()
    assert len(list(tmp_path.glob("*.svg"))) == len(variant_numbers())


def test_png_without_cairosvg_is_a_setup_error_and_writes_nothing(tmp_path, monkeypatch, capsys):
    import sys

    from plans.cli import main

    monkeypatch.setitem(sys.modules, "cairosvg", None)  # as if it were not installed
    svg, png = tmp_path / "s.svg", tmp_path / "s.png"
    code = main(["sheet", "samples/press.toml", "-o", str(svg), "--png", str(png)])
    err = capsys.readouterr().err
    assert code == 2
    # the source install the README's setup uses, not a PyPI package
    assert "pip install '.[export]'" in err and "internal error" not in err
    assert list(tmp_path.iterdir()) == []


def test_exported_files_get_the_usual_mode(tmp_path):
    import os

    from plans.cli.common import write_output

    umask = os.umask(0o022)
    os.umask(umask)
    out = tmp_path / "s.svg"
    write_output(str(out), b"<svg/>")  # the command line's writer: drawing writes no file
    assert out.read_text() == "<svg/>"
    assert out.stat().st_mode & 0o777 == 0o666 & ~umask
    assert [p.name for p in tmp_path.iterdir()] == ["s.svg"]  # no temporary file left


def test_sheet_scales_fill_the_sheet_where_the_file_leaves_them_free():
    _, _, _, info, _ = _sheet(3)  # the sheets the other tests build, on A1
    sol = info["solutions"][0][2]
    # the engine alone would pick 1:2.5 and μv = 0.02 for this variant; A1 has room for more
    assert sol.mu_l == 0.001 and sol.mu_v == 0.01
    press = _sheet("press")[3]["solutions"][0][2]
    assert (press.mu_l, press.mu_v, press.mu_a) == (0.01, 0.05, 1.0)  # fixed in the file


def test_only_a_sheet_left_empty_by_the_files_own_scales_gets_a_note():
    """The press at its fixed scales fills a fifth of A1 (noted) and half of A2 (not);
    sheets whose scales the tool chose are not noted, however they fill the field."""
    from drawing.sheet.layout import share_used
    from drawing.sheet1 import SPARSE, sparse_note

    mech, _, sheet, info, _ = _sheet("press")
    assert 0.15 < share_used(sheet, info["placed"]) < SPARSE
    assert "22% of the A1 sheet's field" in sparse_note(mech, sheet, info["placed"])
    mech, _, sheet, info, _ = _sheet("press", "A2")
    assert share_used(sheet, info["placed"]) > 0.45
    assert sparse_note(mech, sheet, info["placed"]) is None
    for key in ("fourbar", 3):
        mech, _, sheet, info, _ = _sheet(key)
        assert not mech.scales and sparse_note(mech, sheet, info["placed"]) is None


def test_russian_fourbar_sheet_explains_the_missing_diagrams_in_russian():
    _, scene, _, _, _ = _sheet("fourbar")  # Russian by default: the sheet built already
    texts = " ".join(t.text for t in scene.items() if hasattr(t, "text"))
    assert "начальное звено 1 не может сделать полный оборот (это коромысло" in texts
    assert "cannot" not in texts


@pytest.mark.parametrize("key", KEYS)
def test_no_text_sits_on_a_vector_arrow(key):
    from shapely.geometry import LineString

    from drawing.scene import Arrow, Group, flatten
    from drawing.text import text_box

    _mech, scene, _sheet_obj, _info, _svg = _sheet(key)
    views = [g for g in scene.layer("views").items if isinstance(g, Group)
             and ("velocity" in g.name or "acceleration" in g.name)]
    assert len(views) >= 2
    hits = []
    for view in views:
        items = flatten([view])
        arrows = [LineString([a.p1, a.p2]) for a in items if isinstance(a, Arrow)]
        for t in (t for t in items if isinstance(t, Text)):
            box = text_box(t)
            hits += [(view.name, t.text) for a in arrows if box.intersects(a)]
    assert hits == []


def test_a_rockers_swing_is_dimensioned_on_the_plan_of_positions():
    """A crank-rocker's plan of positions carries ψ between the two extreme positions of
    the rocker, with the value the cycle computes; a slider's carries H instead."""
    from plans.cycle import analyse_cycle

    rockers = [n for n in variant_numbers() if n % 2]  # odd variants are four-bars
    checked = 0
    for n in rockers:
        mech = variant(n)
        cycle = analyse_cycle(mech)
        if not (cycle.full_turn and cycle.output and cycle.output.kind == "angular"):
            continue
        *_, svg = _sheet(n)
        _, texts = _texts(svg)
        psi = [t for t in texts if t.startswith("ψ = ")]
        assert len(psi) == 1, texts
        value = float(psi[0].removeprefix("ψ = ").removesuffix("°").replace(",", "."))
        assert value == pytest.approx(math.degrees(cycle.stroke), abs=0.01)
        assert not any(t.startswith("H = ") for t in texts)
        checked += 1
    assert checked >= 3  # every crank-rocker of the table, none left out
    *_, svg = _sheet("press")
    _, texts = _texts(svg)
    assert any(t.startswith("H = ") for t in texts) and not any(t.startswith("ψ = ") for t in texts)


@pytest.mark.parametrize("scene", ["slotted_offset", "slot_rrp_moving", "crank_rocker"])
def test_the_value_of_the_swing_breaks_the_thin_lines_under_it(scene):
    """GOST 2.307: no line crosses a dimension's value. ψ stands in a white break drawn
    over every thin line (other positions, slots, the arc) and under every heavy one, so
    the given position is never hidden; it touches no heavy line and no other label."""
    from shapely.geometry import box

    from drawing.obstacles import obstacles_of
    from drawing.scene import Blank, Polyline, Segment, flatten
    from drawing.styles import LineType
    from drawing.text import text_box
    from plans.model.scenes import SCENES

    scene_, *_ = build_sheet(SCENES[scene].mechanism(), "A1", "ru", 12, None)
    view = next(g for g in scene_.layer("views").items if g.name == "view positions")
    items = flatten([view])
    psi = [t for t in items if isinstance(t, Text) and t.text.startswith("ψ = ")]
    assert len(psi) == 1
    label = text_box(psi[0])
    (blank,) = [(i, b) for i, b in enumerate(items)
                if isinstance(b, Blank) and box(*b.p1, *b.p2).contains(label)]
    at, blank = blank
    thin = (LineType.THIN, LineType.DASHED, LineType.DASH_DOUBLE_DOT_THIN)
    crossing = 0
    for i, it in enumerate(items):
        if isinstance(it, Text | Blank):
            continue
        soft = isinstance(it, Segment | Polyline) and it.line in thin
        hit = any(g.intersects(label) for g in obstacles_of([it], clearance=0.0))
        if soft and i > at:  # the dimension's own arc, drawn over the break: clear of it
            assert not hit, it
        elif soft:
            crossing += hit  # broken by the blank
        else:
            assert i > at and not hit, it  # drawn over the blank, and clear of the value
    # the dimension's own arc is drawn over the break, not cut by it
    assert any(isinstance(it, Polyline) and it.line == LineType.THIN for it in items[at + 1:])
    others = [text_box(t) for t in items if isinstance(t, Text) and t is not psi[0]]
    assert not any(label.intersects(o) for o in others)
    if scene == "slotted_offset":
        assert crossing >= 2  # in a fan of slot lines: the break is what keeps it readable


def test_swing_arc_runs_from_one_extreme_arm_to_the_other():
    import cmath

    from drawing.scene import Arrow, Polyline
    from drawing.views.positions import SWING_R, swing_arc

    pivot, a, b = 0.1 + 0.2j, 0.1 + 0.2j + 0.3 * cmath.exp(0.4j), 0.1 + 0.2j + 0.25 * cmath.exp(1.9j)
    mu = 0.002
    items = swing_arc(pivot, a, b, mu)
    arc = next(it for it in items if isinstance(it, Polyline))
    to_world = lambda p: complex(p[0] * mu, -p[1] * mu)  # noqa: E731  (the sheet flips y)
    start, end = to_world(arc.points[0]), to_world(arc.points[-1])
    assert abs(start - pivot) == pytest.approx(SWING_R * 0.25)
    assert cmath.phase(start - pivot) == pytest.approx(0.4)
    assert cmath.phase(end - pivot) == pytest.approx(1.9)
    for p in arc.points:  # on the circle all the way
        assert abs(to_world(p) - pivot) == pytest.approx(SWING_R * 0.25)
    heads = [it for it in items if isinstance(it, Arrow)]
    assert len(heads) == 2 and {heads[0].p2, heads[1].p2} == {arc.points[0], arc.points[-1]}


def test_trajectories_span_the_positions_drawn_when_the_crank_cannot_turn():
    """Seed 001's four-bar assembles over −128.8°…128.8°, across the file's angle: the
    trajectories must cover every position drawn, not stop at the file's angle."""
    import numpy as np

    from plans.cycle import analyse_cycle
    from plans.cycle.positions import trajectory_angles
    from plans.kinematics.solver import Solver

    mech = _mech("fourbar")
    solver = Solver(mech)
    cycle = analyse_cycle(mech, solver=solver)
    assert not cycle.full_turn
    phis = trajectory_angles(cycle)
    assert math.degrees(abs(phis[-1] - phis[0])) == pytest.approx(2 * 128.8, abs=0.2)
    # every position's points lie on the trajectories drawn, within a sample's spacing
    along = solver.solve(phis)
    at = solver.solve(np.array(cycle.positions))
    step = abs(phis[1] - phis[0])
    for name in (*mech.trace, mech.driver.tip):
        path = np.asarray(along.position[name])
        speed = np.abs(np.diff(path)).max() / step
        for z in np.asarray(at.position[name]):
            assert np.abs(path - z).min() <= speed * step


def test_batch_takes_the_variants_of_the_table_given(tmp_path):
    """--variant all with --table draws that table's rows, not the built-in table's."""
    from plans.cli import main

    table = tmp_path / "t.toml"
    table.write_text("[[variant]]\nn = 6\nAB = 0.05\nBC = 0.15\nphi_deg = 15\nrpm = 100\n",
                     encoding="utf-8")
    out = tmp_path / "sheets"
    assert main(["sheet", "--variant", "all", "--table", str(table), "-o", str(out)]) == 0
    assert [p.name for p in out.iterdir()] == ["variant-6.svg"]


def test_the_angle_asked_for_is_the_angle_the_titles_give(tmp_path):
    """sheet --angle 20 draws the plans at 20° in the file's convention, and says so."""
    from plans.cli import main

    out = tmp_path / "a.svg"
    assert main(["sheet", "samples/fourbar.toml", "--angle", "20", "-o", str(out)]) == 0
    _, texts = _texts(out.read_text(encoding="utf-8"))
    titles = [t for t in texts if t.startswith(("План скоростей", "План ускорений"))]
    assert len(titles) == 2 and all("(φ1 = 20°)" in t for t in titles), titles
    mech = _mech("fourbar").at_file_angle(20)
    assert mech.driver.angle_deg == 20
    assert mech.driver.file_angle(mech.driver.phi) == pytest.approx(20)


def test_a_scotch_yokes_slot_is_drawn_across_its_axis_and_its_block_slides_along_it():
    """The yoke's slot (a guide at 90° to its axis DE) is drawn on the yoke through the
    block, the block stands along it, and the yoke's centre of mass S3 (off its axis) is
    a dot, not a bar."""
    import numpy as np

    from drawing.views import positions as V
    from plans.cycle import analyse_cycle
    from plans.kinematics.solver import Solver
    from plans.model.scenes import SCENES
    from plans.plan.solution import solve_position

    mech = SCENES["scotch_yoke"].mechanism()
    solver = Solver(mech)
    sol = solve_position(mech, solver=solver)
    pos, mu_l = sol.positions, sol.mu_l
    slot = next(s for s in mech.sliders if s.guide.link == 3)
    de = pos["E"] - pos["D"]
    across = V.guide_dir(mech, slot, pos)
    assert abs((across * np.conj(de / abs(de))) - 1j) < 1e-12  # ⊥ DE, turned +90°
    cycle = analyse_cycle(mech, 12, solver=solver)
    m = solver.solve(np.array(cycle.positions))
    drawn = [{n: complex(v[k]) for n, v in m.position.items()} for k in range(len(cycle.positions))]
    slots = V.guide_slots(mech, drawn)
    (seg,) = V.slot_segments(mech, slots, pos, mu_l, LineType.MAIN)
    (ax, ay), (bx, by), (px, py) = seg.p1, seg.p2, V.to_sheet(pos["A"], mu_l)
    assert abs(ax - bx) < 1e-9 and abs(ax - px) < 1e-9  # vertical, through the block's pin
    assert min(ay, by) < py < max(ay, by)
    # it spans the block's whole travel in the slot (the crank's ±0.1 m) and a little more
    assert abs(ay - by) * mu_l == pytest.approx(0.2 + 2 * 0.1 * (0.2 + 0.05), rel=1e-6)
    ends = {p for s in V.link_segments(mech, pos, mu_l, LineType.MAIN) for p in (s.p1, s.p2)}
    assert V.to_sheet(pos["S3"], mu_l) not in ends and V.to_sheet(pos["E"], mu_l) in ends


def test_a_view_no_sheet_can_hold_is_blamed_on_the_mechanism_not_the_format(capsys, tmp_path):
    """The press drawn at μl = 0.0005 m/mm (2:1) fixed in its file: no format holds its
    plan of positions, and the message says so, naming the file and its [scales]
    instead of suggesting a larger --format."""
    from support import run

    text = (ROOT / "samples" / "press.toml").read_text(encoding="utf-8")
    assert "mu_l = 0.01\n" in text
    path = tmp_path / "press.toml"
    path.write_text(text.replace("mu_l = 0.01\n", "mu_l = 0.0005\n"), encoding="utf-8")
    out = tmp_path / "t.svg"
    code, _, err = run(capsys, "sheet", path, "-o", out, "--format", "A0")
    assert code == 2 and not out.exists()
    assert err.startswith(f"plans sheet: {path}: the plan of positions (")  # not its id
    assert "is larger than any sheet, A0 included, at the μl the file fixes" in err
    assert "--format" not in err


def test_positions_where_a_slider_runs_off_to_infinity_are_left_off_and_said_so():
    """The tangent mechanism's crank range ends where its slider runs off to infinity
    (C at 114 m at φ1 = ±89.9°): those positions are not drawn, the view says which, and
    the sheet's μl is chosen for the rest (not 1 m/mm for a speck)."""
    from plans.model.scenes import SCENES

    mech = SCENES["tangent"].mechanism()
    _, _sheet_obj, info = build_sheet(mech, "A2", "en")
    (view,) = [p.view for p in info["placed"] if p.view.name == "positions"]
    texts = [it.text for it in view.items if isinstance(it, Text)]
    (note,) = [t for t in texts if t.startswith("Positions ")]
    assert note.startswith("Positions 0, 11 not shown: points of the mechanism run farther than")
    sol = info["solutions"][0][2]
    assert sol.mu_l <= 0.01 and view.h < 400


@pytest.mark.parametrize(("name", "low", "high"), [("press", 0.95, 1.01), ("crank_rocker", 0.95, 1.01),
                                                   ("prp_two_moving", 0.0, 0.5)])
def test_the_plan_of_positions_is_sized_by_what_it_draws(name, low, high):
    """μl of a sheet and of solve comes from the positions drawn (the cycle's, the
    extreme ones, the given one, the trajectories): the same as the whole turn's extent
    for an ordinary linkage, but a cross-slide's point that runs far out between the
    positions drawn does not shrink the drawing. solve and the sheet use one rule."""
    import numpy as np

    from plans.cycle import analyse_cycle
    from plans.cycle.positions import drawn
    from plans.kinematics.solver import Solver
    from plans.model.scenes import SCENES
    from plans.plan.solution import solve_position
    from plans.scales import choose_mu_l

    mech = SCENES[name].mechanism()
    solver = Solver(mech)
    cycle = analyse_cycle(mech, 12, solver=solver)
    extent = drawn(solver, cycle).extent
    m = solver.solve(mech.driver.phi + np.linspace(0, 2 * np.pi, 720))
    z = np.concatenate([np.asarray(v)[m.valid] for v in m.position.values()])
    whole = max(np.ptp(z.real), np.ptp(z.imag))
    assert low * whole <= extent <= high * whole
    assert np.isfinite(extent) and extent > 0
    # solve sizes the plan of positions of the cycle it is given as the sheet does
    assert drawn(Solver(mech), analyse_cycle(mech)).extent == extent
    assert (solve_position(mech, cycle=analyse_cycle(mech)).mu_l
            == mech.scales.get("mu_l", choose_mu_l(extent)))


def test_solve_sizes_the_tangent_mechanism_as_the_sheet_does(capsys):
    """The tangent mechanism's slider runs off towards infinity near φ1 = ±90°: solve
    and report chose μl = 0.04 m/mm from every angle of the turn, a crank of 2.5 mm. They
    now leave those positions off as the sheet does."""
    from plans.model.scenes import SCENES
    from plans.plan.solution import solve_position

    sol = solve_position(SCENES["tangent"].mechanism())
    crank_mm = sol.mechanism.driver.length / sol.mu_l
    assert sol.mu_l <= 0.01 and crank_mm >= 10


def _drawn_at(name_or_mech, angles=None):
    """(mech, positions at the cycle's angles and at the given one) of a built-in scene."""
    import numpy as np

    from plans.cycle import analyse_cycle
    from plans.kinematics.solver import Solver
    from plans.model.scenes import SCENES

    mech = SCENES[name_or_mech].mechanism() if isinstance(name_or_mech, str) else name_or_mech
    solver = Solver(mech)
    phis = np.array(angles if angles is not None else
                    [*analyse_cycle(mech, 12, solver=solver).positions, mech.driver.phi])
    m = solver.solve(phis)
    ok = np.asarray(m.valid)
    return mech, [{n: complex(v[k]) for n, v in m.position.items()} for k in range(len(phis)) if ok[k]]


def test_a_block_past_the_end_of_its_links_bar_is_joined_to_it():
    """The tangent mechanism's block C slides on the crank's line beyond A: the guide is
    drawn from the bar's end A out past C, at every position; where the block is on the
    bar (the press's A3 on BC) nothing is added."""
    from drawing.views import positions as V

    mech, drawn = _drawn_at("tangent")
    slots = V.guide_slots(mech, drawn)
    for pos in drawn:
        (seg,) = V.slot_segments(mech, slots, pos, 1e-3, LineType.MAIN)
        a, c, o = (complex(*V.to_sheet(pos[n], 1e-3)) for n in ("A", "C", "O"))
        p1, p2 = complex(*seg.p1), complex(*seg.p2)
        assert abs(p1 - a) < 1e-6  # from the bar's end …
        assert abs(p2 - o) > abs(c - o) and abs(((p2 - o) / (c - o)).imag) < 1e-9  # … past C
    mech, drawn = _drawn_at("press")
    slots = V.guide_slots(mech, drawn)
    assert all(V.slot_segments(mech, slots, pos, 1e-3, LineType.MAIN) == [] for pos in drawn)


def test_a_point_named_like_a_centre_of_mass_but_carrying_a_pair_stays_on_the_bar():
    """S4 where the yoke slides on its guide is a pair, not a centre of mass: the yoke's
    bar S4–E is drawn; S3 off the axis is only a dot."""
    import tomllib

    from drawing.views import positions as V
    from plans.model import from_dict
    from plans.model.scenes import SCENES

    text = SCENES["scotch_yoke"].toml.replace('"D"', '"S4"')
    mech = from_dict(tomllib.loads(text), "yoke_S4")
    assert not V.centre_of_mass(mech, "S4") and V.centre_of_mass(mech, "S3")
    _, (pos, *_) = _drawn_at(mech, [mech.driver.phi])
    ends = {p for s in V.link_segments(mech, pos, 1e-3, LineType.MAIN) for p in (s.p1, s.p2)}
    assert {V.to_sheet(pos["S4"], 1e-3), V.to_sheet(pos["E"], 1e-3)} <= ends
    assert V.to_sheet(pos["S3"], 1e-3) not in ends


def test_a_plan_no_sheet_can_hold_points_to_the_plans_option():
    from drawing.sheet.frame import Sheet
    from drawing.sheet.layout import LayoutError, place_views
    from drawing.views import View

    for name, option in (("positions", ""), ("acceleration-1", "--plans")):
        with pytest.raises(LayoutError) as info:
            place_views(Sheet("A3"), [View(name, [], 900.0, 3200.0)])
        assert info.value.option == option and "larger than any sheet" in str(info.value)
    with pytest.raises(LayoutError) as info:
        place_views(Sheet("A4"), [View("positions", [], 400.0, 250.0)])
    assert info.value.option == "--format"


@pytest.mark.parametrize("n", ["2", "73", "500"])
def test_positions_outside_3_to_72_are_refused_before_any_work(capsys, tmp_path, n):
    from support import run

    out = tmp_path / "s.svg"
    code, _, err = run(capsys, "sheet", "samples/fourbar.toml", "--positions", n, "-o", out)
    assert code == 2 and not out.exists()
    assert err == (f"plans sheet: command line: argument --positions: '{n}' is not a whole number "
                   "from 3 to 72 (see plans sheet --help)\n")


def test_a_russian_sheet_names_and_measures_in_russian():
    """Variant 5 in Russian: the title block names it in Russian, the segments table's
    value column is «Величина» (was the Latin "SI"), a diagram's scale is per mm of
    drawing with its unit in brackets, «(рад/с)/мм» (was «рад/с/мм»)."""
    *_, svg = _sheet(5)
    _, texts = _texts(svg)
    assert "Шарнирный четырёхзвенник, вариант 5" in " ".join(texts)
    assert "Величина" in texts and "SI" not in texts
    assert any(t.startswith("μω = ") and t.endswith(" (рад/с)/мм") for t in texts), texts
    assert not any("/с/мм" in t for t in texts)


def test_a_gost_scale_has_a_decimal_comma_on_a_russian_sheet():

    # a sheet whose μl the sheet chooses as 1:2.5 (the yoke on A1 was, before each scale
    # factor was chosen on its own: it is now 1:2; the general slotted link on A2 was,
    # before the plan of positions was made the largest view: it is now 1:2 there)
    scene, sheet, info = build_sheet(variant(1), "A3", "ru")
    _, texts = _texts(to_svg(scene, sheet, embed_font=False))
    assert info["solutions"][0][2].mu_l == 0.0025
    assert "1:2,5" in texts and "1:2.5" not in texts


def _mu_lines(text: str) -> list[str]:
    """The scale factors a note (its 'μl = l_AB / AB = … = 0,001 м/мм' steps) or a
    sheet (its captions' 'μl = 0,001 м/мм') states, as 'μl = 0,001' strings."""
    steps = re.findall(r"^- `(μ[lva]) = (?:.* = )?([\d,]+) ", text, re.M)
    captions = re.findall(r"(μ[lva]) = ([\d,]+) ", text) if not steps else []
    return sorted({f"{k} = {v}" for k, v in steps + captions})


def test_the_sheets_note_states_the_sheets_scales_for_each_plan(capsys, tmp_path):
    """plans sheet --note writes the explanatory note of the positions the sheet draws
    plans for, at the sheet's own scale factors: the note and the sheet a student hands in
    cannot disagree. plans report alone chooses μ for a 150 mm drawing and may differ."""
    from plans.cli import main

    svg, md = tmp_path / "v3.svg", tmp_path / "v3.md"
    assert main(["sheet", "--variant", "3", "-o", str(svg), "--note", str(md), "--plans", "1,4"]) == 0
    note, (_, texts) = md.read_text("utf-8"), _texts(svg.read_text("utf-8"))
    heads = [ln for ln in note.splitlines() if ln.startswith("## ")]
    assert [h.split(" (")[0] for h in heads[3:]] == [
        "## 4. План скоростей механизма", "## 5. План ускорений механизма",
        "## 6. План скоростей механизма", "## 7. План ускорений механизма"]
    assert heads[3].endswith("(положение 1, φ1 = 296,2°)")
    assert heads[5].startswith("## 6. План скоростей механизма (положение 4,")
    sheet_mu = _mu_lines(" ".join(t for t in texts if t.startswith("План ")))
    assert len(sheet_mu) == 3 and _mu_lines(note) == sheet_mu
    # the given position, in English: the same rule
    svg, md = tmp_path / "f.svg", tmp_path / "f.md"
    assert main(["sheet", str(ROOT / "samples" / "fourbar.toml"), "--lang", "en", "-o", str(svg),
                 "--note", str(md)]) == 0
    _, texts = _texts(svg.read_text("utf-8"))
    sheet_mu = _mu_lines(" ".join(t for t in texts if "plan" in t.lower()).replace(".", ","))
    assert _mu_lines(md.read_text("utf-8").replace(".", ",")) == sheet_mu
    main(["report", str(ROOT / "samples" / "fourbar.toml")])
    alone = capsys.readouterr().out
    assert _mu_lines(alone.replace(".", ",")) != sheet_mu  # the sheet draws larger than 150 mm


@pytest.mark.parametrize("key", KEYS)
def test_position_numbers_keep_clear_of_the_letters(key):
    """'11' beside 'O' read as '110', and 'B10', 'A7': a position's number now keeps
    labels.GAP from every letter on the plan of positions."""
    _, scene, *_ = _sheet(key)
    _numbers_keep_clear_of_letters(scene)


def _numbers_keep_clear_of_letters(scene):
    """The positions' numbers on the plan of positions keep labels.GAP from its letters."""
    from drawing.labels import GAP
    from drawing.scene import flatten
    from drawing.text import text_box

    view = next(g for g in scene.layer("views").items if g.name == "view positions")
    texts = [t for t in flatten([view]) if isinstance(t, Text)]
    numbers = [text_box(t) for t in texts if re.fullmatch(r"\d+", t.text)]
    letters = [text_box(t) for t in texts if re.fullmatch(r"[A-Z][A-Za-z0-9_{}]*", t.text)]
    assert len(numbers) >= 6 and len(letters) >= 3
    assert min(n.distance(b) for n in numbers for b in letters) >= GAP - 1e-9


def test_the_stroke_stands_beside_its_extension_lines_when_it_has_no_room_between():
    """H = 0,2 м was wider than the 20 mm between its extension lines on an A3 sheet,
    which crossed its letters; it now stands on a shelf beyond the right one."""
    from shapely.geometry import LineString

    from drawing.scene import Segment, flatten
    from drawing.styles import LineType
    from drawing.text import text_box
    from plans.model.scenes import SCENES

    scene, *_ = build_sheet(SCENES["crank_slider_central"].mechanism(), "A3", "ru")
    view = next(g for g in scene.layer("views").items if g.name == "view positions")
    items = flatten([view])
    (h,) = [text_box(t) for t in items if isinstance(t, Text) and t.text.startswith("H = ")]
    thin = [LineString([s.p1, s.p2]) for s in items
            if isinstance(s, Segment) and s.line == LineType.THIN and s.p1[0] == s.p2[0]]
    assert thin and not any(h.intersects(ln) for ln in thin)


def test_the_notes_plan_of_positions_is_the_heavy_one(tmp_path):
    """The note's section 2 describes the position the sheet draws heavy. With --plans 1,4
    that is positions 1 and 4 (BA3 = 48,91 mm at 1), no longer the file's own position
    (BA3 = 57,48 mm), which the sheet then leaves out; and the note says which are heavy."""
    from plans.cli import main

    md = tmp_path / "p.md"
    assert main(["sheet", str(ROOT / "samples" / "press.toml"), "--plans", "1,4", "-o",
                 str(tmp_path / "p.svg"), "--note", str(md)]) == 0
    section2 = md.read_text("utf-8").split("## 3.")[1].split("## 4.")[0]
    assert "57,48" not in section2 and "заданном" not in section2
    assert ("Положения, для которых ниже построены планы (положение 1, φ1 = 79,93°; положение 4, "
            "φ1 = 349,9°), выделены основными линиями, остальные положения — тонкими.") in section2
    first = section2.split("в положении, для которого ниже построены планы (положение 1, "
                           "φ1 = 79,93°):")[1]
    assert "- `BA3 = l_BA3 / μl = 0,48906 / 0,01 = 48,906 мм`" in first.split("(положение 4,")[0]
    # in English, one position: the same, in the singular
    assert main(["sheet", str(ROOT / "samples" / "press.toml"), "--plans", "4", "--lang", "en",
                 "-o", str(tmp_path / "p.svg"), "--note", str(md)]) == 0
    section2 = md.read_text("utf-8").split("## 3.")[1].split("## 4.")[0]
    assert ("The position of the plans below (position 4, φ1 = 349.9°) is drawn in heavy lines, "
            "the other positions in thin lines.") in section2
    assert "- `BA3 = l_BA3 / μl = 0.58827 / 0.01 = 58.827 mm`" in section2
    assert "given" not in section2 and "57.48" not in section2
    # without --plans the given position is the heavy one, its plans the note's own
    assert main(["sheet", str(ROOT / "samples" / "press.toml"), "-o", str(tmp_path / "p.svg"),
                 "--note", str(md)]) == 0
    section2 = md.read_text("utf-8").split("## 3.")[1].split("## 4.")[0]
    assert "- `BA3 = l_BA3 / μl = 0,57482 / 0,01 = 57,482 мм`" in section2
    assert "основными" not in section2


def test_the_notes_plan_of_positions_gives_the_segments_of_each_position_drawn(tmp_path):
    """With --plans 1,4 section 2 gave BA3 only at the file's own angle (57,48 mm), and
    the plans of positions 1 and 4 then divided by their own BA3 (48,906 and 58,827 mm)
    that the note never gave. Section 2 now says which position its segments are of (the
    first position of the plans, drawn heavy with the others) and gives those that change
    at each of the others."""
    from plans.cli import main

    md = tmp_path / "p.md"
    assert main(["sheet", str(ROOT / "samples" / "press.toml"), "--plans", "1,4", "-o",
                 str(tmp_path / "p.svg"), "--note", str(md)]) == 0
    text = md.read_text("utf-8")
    section2 = text.split("## 3.")[1].split("## 4.")[0]
    at = section2.split("Длины отрезков, изображающих звенья на чертеже, ")[1].split(
        "построены планы (положение ")[1:]
    assert [a.split(",")[0] for a in at] == ["1", "4"]
    assert "- `BA3 = l_BA3 / μl = 0,48906 / 0,01 = 48,906 мм`" in at[0]
    assert "- `BA3 = l_BA3 / μl = 0,58827 / 0,01 = 58,827 мм`" in at[1]
    assert at[1].startswith("4, φ1 = 349,9°):")  # changes from position 1's
    assert "BC / BA3 = 27,839·75 / 48,906 = " in text.split("## 4.")[1].split("## 5.")[0]
    assert "BC / BA3 = 59,485·75 / 58,827 = " in text.split("## 6.")[1].split("## 7.")[0]


@pytest.mark.parametrize("scene", ["yoke_inclined", "crank_slider_offset"])
def test_the_stroke_is_dimensioned_along_its_guide_at_its_true_length(scene):
    """The inclined yoke's guide is at 20°: H was drawn horizontally, the horizontal
    projection (0.217 m) labelled 0,2309 м. The dimension line now runs along the guide,
    its arrows' tips as far apart as the stroke at μl."""
    import shapely

    from drawing.scene import Arrow, flatten
    from drawing.text import text_box
    from plans.cycle import analyse_cycle
    from plans.model.scenes import SCENES

    mech = SCENES[scene].mechanism()
    scene_, _, info = build_sheet(mech, "A1", "ru")
    mu_l = info["solutions"][0][2].mu_l
    view = next(g for g in scene_.layer("views").items if g.name == "view positions")
    items = flatten([view])
    (h,) = [t for t in items if isinstance(t, Text) and t.text.startswith("H = ")]
    heads = [a for a in items if isinstance(a, Arrow) and a.line.name == "THIN"]
    tips = [a.p2 for a in heads if sum(b.p1 == a.p1 for b in heads) == 2 and
            text_box(h).distance(shapely.Point(a.p1)) < 3.0]
    assert len(tips) == 2
    stroke = analyse_cycle(mech).stroke
    assert math.dist(*tips) * mu_l == pytest.approx(stroke, rel=1e-9)
    d = mech.slider_of(analyse_cycle(mech).output.link).guide.direction
    along = ((tips[1][0] - tips[0][0]) * d.real - (tips[1][1] - tips[0][1]) * d.imag) / math.dist(*tips)
    assert abs(along) == pytest.approx(1.0, abs=1e-9)  # parallel to the guide
    assert d.real > 0 and h.rotate_deg == pytest.approx(-math.degrees(math.atan2(d.imag, d.real)))


def test_points_at_one_place_on_the_plan_of_positions_share_a_label():
    """The slider's centre of mass S3 is at C: two labels read 'S₃ C'."""
    from drawing.scene import flatten

    _, scene, *_ = _sheet(0)
    view = next(g for g in scene.layer("views").items if g.name == "view positions")
    texts = [t.text for t in flatten([view]) if isinstance(t, Text)]
    assert "C,S_{3}" in texts and "C" not in texts and "S_{3}" not in texts


def test_an_output_link_that_turns_all_the_way_gets_its_diagrams():
    """The rotating slotted link has no stroke, and its sheet said «Диаграммы не строятся:
    нет хода выходного звена». ψ(φ), ω(φ), ε(φ) are drawn; ψ grows by one full turn."""
    from drawing.scene import Polyline, Segment
    from drawing.views import diagrams_view
    from plans.cycle import analyse_cycle
    from plans.model.scenes import SCENES

    mech = SCENES["slotted_rotating"].mechanism()
    cycle = analyse_cycle(mech)
    assert cycle.output.kind == "angular" and not cycle.stroke
    view = diagrams_view(mech, cycle, "ru")
    assert view is not None
    texts = [t.text for t in view.items if isinstance(t, Text)]
    k = cycle.output.link  # the axes name the output link's ψ and ω: a sheet may show several
    assert {t.split(" (+")[0] for t in texts} >= {f"ψ_{{{k}}}, рад", f"ω_{{{k}}}, рад/с"}
    (mu_text,) = [t for t in texts if t.startswith("μ_{ψ} = ")]
    mu = float(mu_text.split("= ")[1].split()[0].replace(",", "."))
    axis = next(it for it in view.items if isinstance(it, Segment))
    curve = next(it for it in view.items if isinstance(it, Polyline))
    rise = (curve.points[0][1] - curve.points[-1][1]) * mu  # the sheet's y points down
    assert abs(rise) == pytest.approx(2 * math.pi, rel=1e-6)
    assert curve.points[0][1] == pytest.approx(axis.p1[1])  # ψ starts at 0


#: the share of an A1 sheet's free field that the views' own boxes cover where the sheet
#: chooses every scale factor. Sheet 1 is six views of shapes fixed by the mechanism (the
#: plan of positions, two plans, the diagrams, two tables), each with its caption; packed
#: they leave gaps, and a plan of positions grows only in GOST steps (1:1 to 2:1 doubles
#: it), so a full sheet covers 45–75 %. With every view going down a size step together
#: until the largest fitted, the variants covered 27–52 %, all in a band at the top of the
#: sheet (variant 5: 27 %, the lower 62 % blank): 40 % is under every full sheet and over
#: every half-empty one.
FILLED = 0.4


def _boxes_clear(sheet, placed):
    """Each view's box inside the free field, and clear of every other view's."""
    from shapely.geometry import box

    from drawing.sheet.layout import GAP

    boxes = [box(*p.rect.bounds) for p in placed]
    area = sheet.drawing_area()
    assert all(area.contains(b) for b in boxes)
    for i, a in enumerate(boxes):
        for b in boxes[i + 1:]:
            assert a.distance(b) >= GAP - 1e-6


def _side_by_side(a, b, others) -> bool:
    """Whether the box ``b`` (x0, y0, x1, y1) follows ``a`` side by side: their spans down
    the sheet overlap and ``b`` is right of ``a``, or their spans across it overlap and
    ``b`` is under ``a``; and none of ``others`` meets the strip between them."""
    from shapely.geometry import box

    for d in (1, 0):  # beside: the y spans overlap; under: the x spans overlap
        lo, hi = max(a[d], b[d]), min(a[d + 2], b[d + 2])
        if lo >= hi:
            continue
        gap = (a[3 - d], b[1 - d])  # a's right (lower) edge, b's left (upper) one
        strip = box(gap[0], lo, gap[1], hi) if d == 1 else box(lo, gap[0], hi, gap[1])
        return gap[0] <= gap[1] and not any(
            strip.intersection(box(*o)).area > 1e-6 for o in others)
    return False


def _read_before(a, b) -> bool:
    """Whether the box ``a`` comes before ``b`` read left to right or top to bottom: wholly
    above it or wholly left of it, and ``b`` neither wholly above nor left of ``a``."""
    def ahead(p, q):
        return p[3] <= q[1] + 1e-6 or p[2] <= q[0] + 1e-6

    return ahead(a, b) and not ahead(b, a)


#: the scale factors (μl, μv, μa) and the kinematic diagrams' width (mm) chosen for these
#: sheets before each position's plans were kept together, measured with
#: ``plans sheet --variant N --format F --plans P`` as the sheet now chooses its scales:
#: each position's two plans stand together always (packed as one box where no order
#: of the views puts them so in reading order), and the plan of positions is the
#: largest view; the scales may not grow smaller than these. Variant 1's plans of
#: positions 2 and 8 are 34 mm across at the scale that fits A2 (LEAST_PLAN): on A1
PAIRED = [
    (7, "A2", (2, 8), (0.004, 0.05, 1.0), 130),
    (3, "A2", (1, 4), (0.0025, 0.01, 0.25), 190),
    (3, "A1", (1, 4), (0.001, 0.01, 0.1), 250),
    (2, "A1", (1, 4), (0.001, 0.005, 0.1), 370),
    (1, "A2", (1, 4), (0.002, 0.01, 0.1), 190),
    (6, "A1", (2, 8), (0.002, 0.02, 0.25), 370),
    (9, "A2", (1, 4), (0.002, 0.01, 0.25), 190),
    (1, "A1", (2, 8), (0.002, 0.01, 0.25), 190),
    (7, "A1", (1, 4), (0.002, 0.01, 0.25), 250),
]


@pytest.mark.parametrize(("key", "fmt", "plans", "mu", "diagrams"), PAIRED,
                         ids=[f"{k}-{f}-{p[0]},{p[1]}" for k, f, p, *_ in PAIRED])
def test_each_positions_plans_are_side_by_side_in_position_order(key, fmt, plans, mu,
                                                                  diagrams):
    """With --plans 2,8 variant 7's A2 sheet put position 8's acceleration plan top left,
    its velocity plan in the middle and position 2's plans at the bottom, the diagrams
    between them: the views were packed by area. Each position's velocity and
    acceleration plans now sit side by side (the acceleration plan right of or under the
    velocity plan, nothing between), the first position's pair read first, at the scales
    chosen before."""
    _, _, sheet, info, _ = _sheet(key, fmt, "ru", plans)
    placed = info["placed"]
    rects = {p.view.name: p.rect.bounds for p in placed}
    pairs = []
    for k in plans:
        mine = (f"velocity-{k}", f"acceleration-{k}")
        others = [r for name, r in rects.items() if name not in mine]
        a, b = (rects[n] for n in mine)
        assert _side_by_side(a, b, others), f"position {k}'s plans are apart: {rects}"
        pairs.append((min(a[0], b[0]), min(a[1], b[1]), max(a[2], b[2]), max(a[3], b[3])))
    assert _read_before(*pairs), f"position {plans[1]}'s plans come first: {rects}"
    sol = info["solutions"][0][2]
    assert info["given"].mu_l <= mu[0] and sol.velocity.mu <= mu[1]
    assert sol.acceleration.mu <= mu[2]
    (width,) = [p.rect.w for p in placed if p.view.name == "diagrams"]
    assert width >= diagrams - 1
    _boxes_clear(sheet, placed)


def test_a_pair_that_does_not_fit_together_is_packed_as_without_pairs():
    """A pair kept together never costs a view its place: a tall narrow partner cannot
    go right beside (it would meet the title block) or under a wide box, but both fit
    apart; pack then packs them as it did without pairs."""
    from drawing.sheet.frame import Sheet
    from drawing.sheet.layout import pack

    sheet = Sheet("A2")
    sizes = [(400.0, 190.0), (150.0, 380.0)]
    assert pack(sheet, sizes) is not None
    assert pack(sheet, sizes, [(0, 1)]) == pack(sheet, sizes)


@given(st.integers(1, 7).flatmap(lambda n: st.tuples(
    st.just(n), st.lists(st.integers(0, n - 1), unique=True, max_size=n))))
@settings(max_examples=60, deadline=None)
def test_the_orders_of_the_pairs_search_are_those_it_filtered_from_all(case):
    """The pairs' search tries the permutations of a sheet's units in which the pairs come
    in their order. It had made all n! and kept those (3 024 of 362 880 for five
    positions' plans, about 3 s of a 7 s build); they are now built so, and must be the
    very same orders in the very same sequence, or a sheet would change."""
    from itertools import permutations

    from drawing.sheet.layout import in_order

    n, rank = case
    want = [p for p in permutations(range(n))
            if [p.index(k) for k in rank] == sorted(p.index(k) for k in rank)]
    assert list(in_order(n, rank)) == want


def test_pairs_are_packed_together_in_their_order():
    """The boxes of variant 7's A2 sheet with --plans 2,8 (the plan of positions, the
    two positions' plans, the diagrams, two tables): without pairs position 8's
    acceleration plan is packed above its velocity plan and both before position 2's
    plans; with them each velocity plan has its acceleration plan right of it or under
    it, position 2's first."""
    from drawing.sheet.frame import Sheet
    from drawing.sheet.layout import pack

    sheet = Sheet("A2")
    sizes = [(155.0, 137.0), (143.0, 98.0), (144.0, 59.0), (146.0, 171.0), (269.0, 116.0),
             (190.0, 145.0), (142.0, 124.0), (154.0, 34.0)]

    def boxes(spots):
        return [(x, y, x + w, y + h) for (x, y), (w, h) in zip(spots, sizes, strict=True)]

    apart = boxes(pack(sheet, sizes))
    assert not _side_by_side(apart[3], apart[4], apart[:3] + apart[5:])
    assert apart[4][3] <= apart[3][1] and apart[4][3] <= min(apart[1][1], apart[2][1])
    got = boxes(pack(sheet, sizes, [(1, 2), (3, 4)]))
    assert _side_by_side(got[1], got[2], [got[0], *got[3:]])
    assert _side_by_side(got[3], got[4], got[:3] + got[5:])
    first = (min(got[1][0], got[2][0]), min(got[1][1], got[2][1]),
             max(got[1][2], got[2][2]), max(got[1][3], got[2][3]))
    second = (min(got[3][0], got[4][0]), min(got[3][1], got[4][1]),
              max(got[3][2], got[4][2]), max(got[3][3], got[4][3]))
    assert _read_before(first, second)


@pytest.mark.parametrize(("key", "fmt", "lang", "plans", "size", "broken", "mu_a"), [
    (3, "A2", "ru", None, 5.0, [["План ускорений (φ_1 = 60°),", "μ_a = 0,1 (м/с²)/мм"]], 0.1),
    (5, "A1", "en", (1, 4), 5.0, [["Acceleration plan (position 1, φ_1 = 314.7°),",
                                   "μ_a = 0.2 (m/s²)/mm"],
                                  ["Acceleration plan (position 4, φ_1 = 44.66°),",
                                   "μ_a = 0.2 (m/s²)/mm"]], 0.2),
    # the acceleration plan at μa = 0.1, 207 mm long, filled the middle of A3 and left no
    # room for titles on two lines (every title was 3.5 mm); the plan of positions the
    # largest view, the plans are drawn at μa = 0.2 and the long titles break
    (3, "A3", "ru", None, 5.0, [["План скоростей (φ_1 = 60°),", "μ_v = 0,02 (м/с)/мм"],
                                ["План ускорений (φ_1 = 60°),", "μ_a = 0,2 (м/с²)/мм"],
                                ["Кинематические диаграммы,", "μ_φ = 0,0524 рад/мм"]], 0.2),
])
def test_every_title_on_a_sheet_is_one_size(key, fmt, lang, plans, size, broken, mu_a):
    """A caption much wider than its drawing was set at 3.5 mm instead of 5: variant 3's
    acceleration plan (a narrow one) was titled smaller than its velocity plan on the same
    sheet. A sheet's titles now have one size: 5 mm, a long one broken before its scale
    factor, where the views so titled still fit at the scales chosen; else 3.5 mm. The
    second line stands under the first, over everything else of its view."""
    from drawing.views import WORDS
    from drawing.views.common import bbox

    _, scene, sheet, info, _ = _sheet(key, fmt, lang, plans)
    w = WORDS[lang]
    titles = (w["positions"], w["velocity"], w["acceleration"], w["diagrams"], w["segments"],
              w["angular"])
    two = []
    for p in info["placed"]:
        texts = [t for t in p.view.items if isinstance(t, Text)]
        (i,) = [k for k, t in enumerate(texts) if t.text.startswith(titles)]
        lines = texts[i:i + 2] if texts[i].text.endswith(",") else texts[i:i + 1]
        assert [t.size for t in lines] == [size] * len(lines), (p.view.name, lines)
        if len(lines) == 2:
            two.append([t.text for t in lines])
            upper, lower = (text_box(t).bounds for t in lines)
            assert 0.5 < lower[1] - upper[3] < 3  # the next line, its own pitch apart
        # the title over everything else of its view: the drawing, its letters
        rest = bbox([it for it in p.view.items if not any(it is t for t in lines)])
        assert text_box(lines[-1]).bounds[3] < rest[1]
    assert two == broken
    assert {sol.acceleration.mu for _, _, sol in info["solutions"]} == {mu_a}
    assert overlaps([it for it in scene.items() if isinstance(it, Text)]) == []
    _boxes_clear(sheet, info["placed"])


@pytest.mark.parametrize("key", ["fourbar", *variant_numbers()])
def test_the_views_fill_a_sheet_whose_scales_are_free(key):
    """The views of a sheet whose scale factors the file leaves free take the sheet: each
    factor is chosen on its own (a plan of positions that fits at 1:1 keeps it where the
    acceleration plan needs a step down), and the views are packed in whatever order
    fits, not only the order they are drawn in."""
    mech, _, sheet, info, _ = _sheet(key)
    assert not mech.scales
    placed = info["placed"]
    covered = share_covered(sheet, placed)
    assert covered >= FILLED, f"the views cover {covered:.0%} of the field"
    _boxes_clear(sheet, placed)


@pytest.mark.parametrize("name", ["slotted_rotating", "yoke_on_rocker"])
def test_plans_of_two_positions_are_drawn_large_on_a2(name):
    """With --plans 2,7 on A2 the sheet shrank every view together: the yoke's plans had a
    30 mm crank vector, its plan of positions a 15 mm crank. The plans' factors are now
    chosen for every position drawn and packed beside each other."""
    from plans.model.scenes import SCENES

    mech = SCENES[name].mechanism()
    _, sheet, info = build_sheet(mech, "A2", "ru", 12, [2, 7])
    tip = mech.driver.tip
    for _, _, sol in info["solutions"]:
        assert sol.velocity.mm("p", tip.lower()) >= 50  # pa of 50–150 mm, as taught
        assert sol.acceleration.mm("π", tip.lower()) >= 50
    assert abs(mech.links[mech.driver.link].points[tip]) / info["given"].mu_l >= 25
    placed = info["placed"]
    assert sum(p.rect.w * p.rect.h for p in placed) / sheet.drawing_area().area >= 0.5
    _boxes_clear(sheet, placed)


@pytest.mark.parametrize("key", [3, 8])
def test_a3_holds_sheet_1_its_diagrams_and_tables_sized_to_the_field(key):
    """On A3 six of the ten variants were refused: the diagrams were 190 mm wide whatever
    the sheet, the segments table one 92 × 124 mm block. The diagrams now narrow to the
    field (down to 120 mm) and a tall table may set its rows side by side."""
    _, scene, sheet, info, _ = _sheet(key, "A3")
    _boxes_clear(sheet, info["placed"])
    assert overlaps([it for it in scene.items() if isinstance(it, Text)]) == []


def test_a_long_note_is_wrapped_to_the_sheet(tmp_path):
    """The four-bar's one-line note (why there are no diagrams) was 430 mm long and never
    wrapped: the A3 sheet was refused for it."""
    _, _scene, sheet, info, _ = _sheet("fourbar", "A3")
    (note,) = [p for p in info["placed"] if p.view.name == "note"]
    assert note.rect.w <= 182 and len([t for t in note.view.items if isinstance(t, Text)]) > 1
    _boxes_clear(sheet, info["placed"])


def test_a4_says_in_one_line_what_sheet_1_needs_and_which_format_holds_it(capsys, tmp_path):
    """A4 (a 177 mm wide field over a full-width title block) cannot hold sheet 1: the
    error named the internal view 'diagrams', blamed --plans no one gave and named no
    format. It now says what the views need and that A3 holds them, in one line."""
    from support import run

    out = tmp_path / "s.svg"
    code, _, err = run(capsys, "sheet", "--variant", "6", "--format", "A4", "-o", out)
    assert code == 2 and not out.exists() and len(err.splitlines()) == 1
    assert err.startswith("plans sheet: Table 2 (built in), variant 6: sheet 1 does not fit "
                          "on A4, whose frame is 185 × 287 mm with the 185 × 55 mm title block in it: ")
    for words in ("the plan of positions", "the velocity plan", "the acceleration plan",
                  "the kinematic diagrams", "the table of plan segments"):
        assert words in err
    assert err.endswith("; A3 holds it: use --format A3\n")
    assert "'" not in err and "--plans" not in err


def test_two_positions_on_a3_are_refused_rather_than_drawn_unreadably_small(capsys, tmp_path):
    """Variant 6 with --plans 2,8 on A3 was drawn, exit 0 and no word, at μl = 0.01 and
    μv = 0.1: a crank circle 24 mm across with its letters on the links, plans 24 mm long,
    a third of the field empty (the plans' captions, not their drawings, set their width).
    The sheet's scales go down to half the default sizes, no further: the sheet is refused
    as A4 is, naming A2, where every view is at least that large."""
    from support import run

    from plans.plan.solution import plan_name

    out, png = tmp_path / "s.svg", tmp_path / "s.png"
    code, _, err = run(capsys, "sheet", "--variant", "6", "--format", "A3", "--plans", "2,8",
                       "-o", out, "--png", png)
    assert code == 2 and not out.exists() and not png.exists() and len(err.splitlines()) == 1
    assert "sheet 1 does not fit on A3" in err and "the longest vector of a plan 75 mm" in err
    assert err.endswith("; A2 holds it: use --format A2 or draw fewer positions' plans "
                        "(--plans)\n")
    mech = variant(6)
    _, _, info = build_sheet(mech, "A2", "ru", 12, [2, 8])
    given = info["given"]
    assert given.mu_l == 0.0025  # 0.01 on the A3 sheet (0.002 with the pairs packed apart)
    across = max(p.rect.w for p in info["placed"] if p.view.name == "positions")
    assert across > 150
    tip = plan_name(mech.driver.tip)
    for _, _, sol in info["solutions"]:
        for plan, mu in ((sol.velocity, 0.02), (sol.acceleration, 0.4)):  # 0.1 and 2 on A3
            assert plan.mu == mu
            longest = max(abs(q.value) for q in plan.points.values()) / mu
            assert longest >= 75 or abs(plan.value(tip)) / mu >= 40


def test_every_failed_sheet_of_a_batch_names_its_variant(capsys, tmp_path):
    """sheet --variant all --format A4 printed ten errors without saying whose."""
    from support import run

    table = tmp_path / "t.toml"
    table.write_text("[[variant]]\nn = 1\nAB = 0.06\nBC = 0.16\nCD = 0.12\nAD = 0.11\n"
                     "phi_deg = 50\nrpm = 115\n", "utf-8")
    code, _, err = run(capsys, "sheet", "--variant", "all", "--table", table, "--format",
                       "A4", "-o", f"{tmp_path}/s/")
    assert code == 2
    first, last = err.splitlines()
    assert first.startswith("plans sheet: ") and "variant 1: sheet 1 does not fit on A4" in first
    assert last == "plans sheet: 1 of 1 sheets failed"


def test_the_group_is_written_with_the_organisation_in_field_9():
    """group, university and organisation all filled field 9, the last given winning: the
    group vanished. Field 9 now reads "МГТУ, гр. ТМ-21", as course projects fill it."""
    scene, sheet, _ = build_sheet(_mech(3), "A1", "ru", 12, None,
                                  ["student=Иванов", "group=ТМ-21", "university=МГТУ"])
    _, texts = _texts(to_svg(scene, sheet, embed_font=False))
    assert "МГТУ, гр. ТМ-21" in texts and "Иванов" in texts
    scene, sheet, _ = build_sheet(_mech(3), "A1", "en", 12, None, ["group=TM-21"])
    assert "group TM-21" in _texts(to_svg(scene, sheet, embed_font=False))[1]


@pytest.mark.parametrize(("pairs", "words"), [
    (["university=МГТУ", "organisation=МИФИ"],
     "--title-block: university='МГТУ' and organisation='МИФИ' both fill the title block's "
     "organisation: give one"),
    (["student=Константинопольский-Преображенский"],
     "--title-block: student='Константинопольский-Преображенский' does not fit its 23 × 5 mm "
     "cell of the title block (field 11) even in 1.8 mm letters condensed to 80 %: shorten it"),
])
def test_a_title_block_entry_is_never_dropped_nor_shrunk_below_1_8_mm(capsys, tmp_path,
                                                                      monkeypatch, pairs, words):
    """Two names of field 9 with different values: the first was dropped without a word. A
    surname too long for its cell was shrunk to 1.45 mm at 80 % width, under GOST 2.304's
    1.8 mm: it is now refused, in one line, and nothing is written; before the views are
    fitted (1.5 s of a sheet, paid for every variant of --variant all)."""
    from support import run

    from drawing import sheet1

    def no_fit(self, suggest=True):
        raise AssertionError("the views were fitted before the title block was checked")

    monkeypatch.setattr(sheet1.Sheet1, "fill", no_fit)
    out = tmp_path / "s.svg"
    code, _, err = run(capsys, "sheet", "--variant", "3", "-o", out, "--title-block", *pairs)
    assert code == 2 and not out.exists()
    assert err == f"plans sheet: {words}\n"


def test_a_long_surname_that_fits_in_1_8_mm_letters_is_kept():
    scene, _sheet_obj, _ = build_sheet(_mech(3), "A1", "ru", 12, None, ["student=Преображенский П.П."])
    texts = [it for it in scene.items("title-block") if isinstance(it, Text)]
    (t,) = [it for it in texts if it.text == "Преображенский П.П."]
    assert 1.8 <= t.size < 2.5
    assert all(it.size >= 1.8 for it in texts)


def test_a_link_of_three_points_not_in_line_is_drawn_as_a_triangle():
    """The coupler AB with its point E was drawn as the bars AB and AE, the rocker DB with
    its point F as DB and DF: the closing sides BE and BF were missing. A point on the
    link's axis still makes no triangle."""
    from drawing.views import positions as V

    mech, (*_, pos) = _drawn_at("crank_rocker")

    def sides(mech, pos):
        out = set()
        for s in V.link_segments(mech, pos, 1e-3, LineType.MAIN):
            out.add(frozenset(n for n in pos if V.to_sheet(pos[n], 1e-3) in (s.p1, s.p2)))
        return out

    got = sides(mech, pos)
    for link in ({"A", "B", "E"}, {"D", "B", "F"}):
        a, b, c = sorted(link)
        assert {frozenset((a, b)), frozenset((b, c)), frozenset((a, c))} <= got, (link, got)
    mech = _mech("fourbar")  # its E lies on the coupler's axis BC, beyond C: one bar B–E
    _, (*_, pos) = _drawn_at(mech)
    assert frozenset(("C", "E")) not in sides(mech, pos)


SIX = """
name = "Six-link press"
output = "F"
[frame]
O = [0.0, 0.0]
D = [0.32, 0.05]
[driver]
link = 1
angle_deg = 17
from = "+y"
measured = "cw"
rpm = 95
sense = "ccw"
[links.1]
axis = ["O", "A"]
points = { A = 0.08 }
[links.2]
axis = ["A", "B"]
points = { B = 0.28, S2 = 0.14 }
[links.3]
axis = ["D", "B"]
points = { B = 0.2, E = [0.1, -0.05], S3 = 0.1 }
[links.4]
axis = ["E", "F"]
points = { F = 0.3, S4 = 0.15 }
[links.5]
points = { F = 0 }
[[sliders]]
link = 5
guide = { link = 0, through = [0.2, -0.2], angle_deg = 75 }
[assembly]
B = "above OD"
F = "below E"
"""


def _plan_letters(monkeypatch, build) -> list[tuple]:
    """(requests, obstacles, soft lines, placements) of each call of ``place_labels`` that
    places a plan's letters, while ``build()`` draws a sheet."""
    from drawing.views import common as V  # where each view's letters are placed

    calls = []
    real = V.place_labels

    def spy(requests, obstacles=(), *args, **kw):
        got = real(requests, obstacles, *args, **kw)
        calls.append((requests, obstacles, kw.get("soft", ()), got))
        return got

    monkeypatch.setattr(V, "place_labels", spy)
    build()
    return [c for c in calls if c[0] and not any(r.cross for r in c[0])]


@pytest.mark.parametrize("key", [5, "six"])
def test_a_plans_letter_stays_on_its_points_side_and_off_construction_lines(key, tmp_path,
                                                                            monkeypatch):
    """Variant 5's s₃ stood beyond the vector pe, reading as a point of pe; the six-link
    press's f stood on the construction line ⊥FE, which broke under it and left a stray
    dash. A plan's letter now takes a spot clear of the construction lines wherever it
    has one, and one from which the way to its point crosses no vector; where none is
    clear, a leader line joins it to its point."""
    from shapely.geometry import Point

    from drawing import labels as L

    if key == "six":
        path = tmp_path / "six.toml"
        path.write_text(SIX, "utf-8")
        mech = load(path)
    else:
        mech = _mech(key)
    # the plans at the sheet's own scale factors
    plans = _plan_letters(monkeypatch, lambda: build_sheet(mech, "A1", "ru"))
    assert len(plans) >= 2
    names = set()
    for requests, hard, soft, placed in plans:
        for req, p in zip(requests, placed, strict=True):
            names.add(req.text)
            a = Point(req.anchor)
            sight = L.LineString([req.anchor, L.shapely.ops.nearest_points(a, p.box)[1].coords[0]])
            across = [g for g in hard if sight.intersects(g) and g.distance(a) > 1e-9]
            if p.leader is None:  # on its point's side, off the construction lines
                assert p.clear and not across, req.text
                assert not any(p.box.intersects(g) for g in soft), req.text
            else:  # clear of every line, joined to its point
                assert not any(p.box.intersects(g) for g in hard), req.text
                assert p.leader[0] == req.anchor
    assert ("s_{3}" if key == 5 else "f") in names


# variant 1's plans of positions 1 and 5 beside position 9's are under 40 mm across at
# any scale that fits a format (sheet1.LEAST_PLAN): that sheet is refused; positions 1 and
# 5 alone are drawn on A1
@pytest.mark.parametrize("key, fmt, plans", [(1, "A2", (2, 6, 10)), (1, "A1", (1, 5)),
                                             ("slot_rrp_moving", "A2", None)])
def test_a_plans_letter_in_a_narrow_fan_hangs_on_a_leader_rather_than_touch_a_vector(
        key, fmt, plans, monkeypatch):
    """In a narrow fan of vectors no spot of the compass round a point was clear, on
    either side of them: variant 1's s₂ (acceleration plan of position 6) covered a
    vector by 0.9 mm², and of position 1 by 13 mm², the moving-slot scene's s₄ by 2 mm²,
    with no leader. And a leader of variant 1 ran through the letter placed before it
    (s₃, position 1). Every plan letter now stands clear of every vector, or hangs on a
    leader clear of them whose line comes within GAP of no other letter."""
    from shapely.geometry import LineString

    from drawing.labels import GAP

    mech = SCENES[key].mechanism() if isinstance(key, str) else _mech(key)
    plans_ = _plan_letters(
        monkeypatch, lambda: build_sheet(mech, fmt, "ru", 12, list(plans) if plans else None))
    assert plans_
    leaders, bad = 0, []
    for requests, hard, _, placed in plans_:
        for i, (req, p) in enumerate(zip(requests, placed, strict=True)):
            covered = sum(p.box.intersection(g).area for g in hard)  # mm² of vectors
            if covered > 1e-6 or not (p.clear or p.leader):
                bad.append((req.text, round(covered, 2), p.leader))
            if p.leader:
                leaders += 1
                line = LineString(p.leader)
                assert p.leader[0] == req.anchor and p.box.distance(line) < 1e-9
                if any(line.distance(q.box) < GAP - 1e-9 for j, q in enumerate(placed) if j != i):
                    bad.append((req.text, "leader at a letter"))
    assert not bad
    assert leaders


@pytest.mark.parametrize("key, fmt, plans", [(1, "A2", (2, 6, 10)), (1, "A1", (1, 5))])
def test_a_plans_leader_ends_in_the_open_not_on_a_vector(key, fmt, plans, monkeypatch):
    """A letter standing clear but across a vector from its point hung on a leader that
    ended on the next vector, 0.2–0.5 mm from it: variant 1's s₃ on the plans of
    positions 6 and 10, n₂ of position 6. The leader read as a tick on that vector, the
    letter beyond as its point's. Every leader now ends LEADER_END mm clear of every
    line, and crosses the lines on its way rather than runs along one."""
    from shapely.geometry import LineString, Point

    from drawing.labels import ALONG, LEADER_END

    mech = _mech(key)
    leaders, bad = 0, []
    for requests, hard, soft, placed in _plan_letters(
            monkeypatch, lambda: build_sheet(mech, fmt, "ru", 12, list(plans))):
        lines = [g for g in (*hard, *soft) if not g.is_empty]
        for req, p in zip(requests, placed, strict=True):
            if p.leader is None:
                continue
            leaders += 1
            end = min(g.distance(Point(p.leader[1])) for g in lines)
            tail = LineString(p.leader).difference(Point(req.anchor).buffer(LEADER_END))
            along = max(tail.intersection(g).length for g in lines)
            if end < LEADER_END - 1e-9 or along > ALONG:
                bad.append((req.text, round(end, 2), round(along, 2)))
    assert leaders
    assert not bad


#: the scenes' crank-rocker given from +y, measured and turning clockwise
CR4 = SCENES["crank_rocker"].toml.replace(
    "angle_deg = 60\nomega = 10",
    'angle_deg = 137\nfrom = "+y"\nmeasured = "cw"\nomega = 12.5\nsense = "cw"')


@pytest.mark.parametrize("name", ["crank_rocker", "cr4"])
def test_the_angular_diagrams_say_which_sense_is_positive(name, tmp_path):
    """ψ, ω and ε of a rocker are drawn positive the way its working stroke turns, so
    that ψ rises from 0 at the extreme position it starts from; for a crank-rocker
    driven clockwise that was clockwise while the ω and ε table read counter-clockwise
    positive, and the diagram did not say so. Each axis now names its positive sense,
    and ω read off the diagram with it has the sign of ω in the table."""
    import numpy as np

    from drawing.views import WORDS, diagram_curves, diagrams_view
    from plans.cycle import analyse_cycle
    from plans.kinematics.solver import Solver
    from plans.model.scenes import SCENES
    from plans.plan.solution import solve_position

    if name == "cr4":
        path = tmp_path / "cr4.toml"
        assert 'sense = "cw"' in CR4  # the scene's driver was replaced
        path.write_text(CR4, "utf-8")
        mech = load(path)
    else:
        mech = SCENES[name].mechanism()
    solver = Solver(mech)
    cycle = analyse_cycle(mech, 12, solver=solver)
    s, v, _, flip = diagram_curves(mech, cycle, solver)
    assert s.min() >= -1e-9  # ψ from the extreme position it starts from
    words = WORDS["ru"]
    sense = words["ccw"] if flip > 0 else words["cw"]
    texts = [t for t in diagrams_view(mech, cycle, "ru", solver=solver).items
             if isinstance(t, Text)]
    link = cycle.output.link
    for axis in (f"ψ_{{{link}}}, рад", f"ω_{{{link}}}, рад/с", f"ε_{{{link}}}, рад/с²"):
        # each axis's name, its sense after it
        (name,) = [t for t in texts if t.text.startswith(axis + " ")]
        assert name.text == f"{axis} (+ {sense})"
    for k, phi in enumerate(cycle.positions):
        omega = solve_position(mech, phi, solver=solver).omega[link]
        if abs(omega) > 1e-6:
            assert np.sign(v[30 * k]) * flip == np.sign(omega), k
    if name == "cr4":
        assert sense == "по ч.с."  # the working stroke turns the rocker clockwise


@pytest.mark.parametrize("lang", ["ru", "en"])
def test_the_three_angular_axes_set_their_sense_one_space_after_the_unit(lang):
    """The ε axis read «ε, рад/с²  (+ против ч.с.)», two spaces where ψ and ω had one: the
    sense was a text of its own, set after an estimate of the name's width, which "²"
    overstated. Each axis is now one text, built by one formula."""
    from drawing.views import WORDS

    _, texts = _texts(_sheet(3, "A2", lang)[4])
    w = WORDS[lang]
    axes = [t for t in texts if t.startswith(("ψ", "ω", "ε")) and "(+" in t]
    assert axes == [f"{n}3, {w[u]} (+ {w['ccw']})"
                    for n, u in (("ψ", "rad"), ("ω", "rads"), ("ε", "rads2"))]  # a rocker: ccw
    assert not [t for t in texts if "  " in t]


def test_a_sheet_is_written_in_the_format_its_name_says(tmp_path, capsys):
    """-o x.png wrote the sheet's SVG text into a .png file, silently. A name that does not
    end in its option's format is refused, one line, before anything is written."""
    from support import run

    for opt, name, want in (("-o", "x.png", "; for a PNG give --png {p}"),
                            ("--png", "x.svg", "; for an SVG give -o {p}"),
                            ("--pdf", "x.png", "; for a PNG give --png {p}"),
                            ("-o", "x.jpg", "")):
        path = tmp_path / name
        path.write_bytes(b"kept")
        extra = [] if opt == "-o" else ["-o", str(tmp_path / "s.svg")]
        code, out, err = run(capsys, "sheet", "samples/press.toml", "--format", "A2", opt, path,
                             *extra)
        suffix = {"-o": ".svg", "--png": ".png", "--pdf": ".pdf"}[opt]
        assert code == 2 and out == "" and path.read_bytes() == b"kept"
        assert not (tmp_path / "s.svg").exists()
        assert err == (f"plans sheet: command line: {opt} {path}: the name must end in {suffix} "
                       f"({opt} writes {suffix[1:].upper()}){want.format(p=path)}\n")
    for name in ("o.SVG", "sheet1"):  # a name of no picture format is written as asked
        code, _, err = run(capsys, "sheet", "samples/press.toml", "--format", "A2", "-o",
                           tmp_path / name)
        assert code == 0 and (tmp_path / name).read_text("utf-8").startswith("<?xml")


@pytest.mark.parametrize("key", [5, "fourbar", 4])
def test_views_at_free_scales_are_spread_evenly_over_the_field(key):
    """At their largest the views of a sheet with free scales still leave room; packed to
    the top left they left the lower half blank. Stretched from the field's top and left
    edges until one view met its bottom and one its right edge (layout.spread), a column
    of two views kept all its room in one band between them: variant 4 on A1 had a band
    165 mm tall blank across the sheet. sheet.balance sets each view (a pair of plans
    kept together as one) in the middle of the room above and below it, then beside it,
    until the gaps settle: a column's gaps are equal from the field's top edge to its
    bottom or the title block, none resized and none overlapping, and no band across the
    field is blank for more than 60 mm."""
    from drawing.sheet.layout import field

    mech, _, sheet, info, _ = _sheet(key)
    assert not mech.scales
    placed = info["placed"]
    (_x0, y0, _x1, y1), blocked = field(sheet)  # the title block and field 26
    rects = [p.rect for p in placed]
    assert min(r.y for r in rects) > y0 + 1.0  # not packed to the top edge
    assert _blank_band(y0, y1, [(r.y, r.y1) for r in rects] + [(b[1], b[3]) for b in blocked]) <= BAND
    _boxes_clear(sheet, placed)


#: mm: the tallest band across an A1 sheet's field that no view may leave blank
BAND = 60.0


def _blank_band(y0: float, y1: float, spans: list[tuple[float, float]]) -> float:
    """The tallest stretch of [y0, y1] that none of ``spans`` (top, bottom) covers."""
    edge, most = y0, 0.0
    for top, bottom in sorted(spans):
        most = max(most, top - edge)
        edge = max(edge, bottom)
    return max(most, y1 - edge)


def test_a_tall_segments_table_is_set_in_two_halves_where_the_sheet_needs_it():
    """The two moving guides' segments table is 180 mm tall, more than an A3 sheet has
    beside the plans: there its rows are set in two halves side by side, each with its
    head, every row once; on A1 it is one table."""
    from drawing.scene import Text
    from plans.model.scenes import SCENES

    def texts(items):
        for it in items:
            if isinstance(it, Text):
                yield it.text
            elif hasattr(it, "items"):
                yield from texts(it.items)

    mech = SCENES["prp_two_moving"].mechanism()
    got = {}
    for fmt in ("A3", "A1"):
        _, _, info = build_sheet(mech, fmt, "ru", 12, None)
        (table,) = [p for p in info["placed"] if p.view.name == "segments"]
        got[fmt] = list(texts(table.view.items))
    assert got["A3"].count("Отрезок") == 2 and got["A1"].count("Отрезок") == 1
    rows = {fmt: sorted(t for t in texts if ": " in t) for fmt, texts in got.items()}  # "pa: V_A"
    assert len(rows["A1"]) == len(set(rows["A1"])) == 24 and rows["A3"] == rows["A1"]  # each once



@pytest.mark.parametrize("kind", ["velocity", "acceleration"])
def test_points_found_by_similarity_lie_on_the_links_image_drawn(kind):
    """Variant 1's coupler BCE: e and s2 are found by similarity, be = bc·BE/BC, but on the
    acceleration plan no vector joins b and c, and on both plans nothing reached e: e and
    s2 floated beside the vectors. A thin line now runs from b through c on to e."""
    from shapely.geometry import LineString, Point

    from drawing.scene import Circle, Segment, flatten
    from drawing.styles import LineType
    from drawing.views import plan_view
    from plans.plan.solution import solve_position

    sol = solve_position(variant(1))
    plan = getattr(sol, kind)
    items = flatten(plan_view(sol, kind, "1").items)
    (pole,) = [c.center for c in items if isinstance(c, Circle) and c.fill == "black"]
    thin = [LineString([s.p1, s.p2]) for s in items
            if isinstance(s, Segment) and s.line == LineType.THIN]
    on = [Point(pole[0] + plan.points[n].value.real / plan.mu,
                pole[1] - plan.points[n].value.imag / plan.mu) for n in ("b", "c", "e", "s2")]
    assert any(all(line.distance(p) < 1e-6 for p in on) for line in thin)


def test_positions_whose_segments_are_those_above_are_named_in_one_sentence(tmp_path):
    """A crank-slider's segments do not change with the position: with --plans 1,4 the
    note said twice over «В положении, для которого ниже построены планы (…), длины
    отрезков те же», once per position; it now says it once, of both. (The segments are
    given at the first position of the plans, drawn heavy with the others: with --plans
    1,4,7 the sentence names 4 and 7.)"""
    from plans.cli import main

    md = tmp_path / "v2.md"
    assert main(["sheet", "--variant", "2", "-o", str(tmp_path / "v2.svg"), "--note", str(md),
                 "--plans", "1,4,7"]) == 0
    section2 = md.read_text("utf-8").split("## 3.")[1].split("## 4.")[0]
    assert "длины отрезков те же" in section2
    assert [ln for ln in section2.splitlines() if "те же" in ln] == [
        "В положениях, для которых ниже построены планы (положение 4, φ1 = 300°; "
        "положение 7, φ1 = 30°), длины отрезков те же."]


def _positions_drawn(key, plans=None, fmt="A1", lang="ru"):
    """(mech, info, heavy line ends, joints, blocks' centres, (text, its box's centre)) of
    a sheet's plan of positions, every point in the world's sheet mm (views._sheet at the
    sheet's μl): the view's own offset is read off the first fixed pivot's support."""
    from drawing.scene import Circle, Polyline, Segment, flatten
    from drawing.styles import LineType
    from drawing.views import positions as V

    mech, _, _, info, _ = _sheet(key, fmt, lang, plans)
    view = next(p.view for p in info["placed"] if p.view.name == "positions")
    items = flatten(view.items)
    mu_l = info["given"].mu_l
    apex = next(it.points[0] for it in items if isinstance(it, Polyline) and it.closed
                and len(it.points) == 3 and it.line is LineType.MAIN)
    pivot = V.to_sheet(next(iter(mech.frame.values())), mu_l)
    dx, dy = apex[0] - pivot[0], apex[1] - pivot[1]

    def back(p):
        return (p[0] - dx, p[1] - dy)

    ends = [back(p) for it in items if isinstance(it, Segment) and it.line is LineType.MAIN
            for p in (it.p1, it.p2)]
    joints = [back(it.center) for it in items if isinstance(it, Circle) and it.r == JOINT_R]
    blocks = [back((sum(x for x, _ in it.points) / 4, sum(y for _, y in it.points) / 4))
              for it in items if isinstance(it, Polyline) and it.closed and len(it.points) == 4
              and it.line is LineType.MAIN]
    texts = [(it.text, back(((b[0] + b[2]) / 2, (b[1] + b[3]) / 2)))
             for it in items if isinstance(it, Text) for b in [text_box(it).bounds]]
    return mech, info, ends, joints, blocks, texts


def _at(xy, pos, mu_l, names=None, tol=1e-6) -> bool:
    """``xy`` (sheet mm) is a point of the position ``pos``."""
    from drawing.views import positions as V

    return any(math.dist(xy, V.to_sheet(pos[n], mu_l)) < tol for n in (names or pos))


@pytest.mark.parametrize("key", [3, 2])
def test_the_positions_of_the_plans_are_drawn_heavy_not_the_given_one(key):
    """With --plans 1,4 the plan of positions drew the file's own position in main lines
    and positions 1 and 4 thin like the others; the ТММ convention draws heavy the
    positions the plans are built for. Now every heavy line, joint and slider block is at
    position 1 or 4 (each of them has its own), none at the given position, whose points
    the letters no longer stand by; the numbers 1 and 4 stay."""
    mech, info, ends, joints, blocks, texts = _positions_drawn(key, (1, 4))
    mu_l = info["given"].mu_l
    at = {sol_tag: sol.positions for sol_tag, _, sol in info["solutions"]}
    assert set(at) == {"1", "4"}
    given = info["given"].positions
    tip = mech.driver.tip
    moving = [n for n in given if n not in mech.frame and abs(given[n] - at["1"][n]) > 1e-3
              and abs(given[n] - at["4"][n]) > 1e-3]
    assert tip in moving  # the given position is apart from both
    assert ends and all(_at(e, at["1"], mu_l) or _at(e, at["4"], mu_l) for e in ends)
    for k in ("1", "4"):
        assert any(_at(e, at[k], mu_l, [tip]) for e in ends)
        assert any(_at(j, at[k], mu_l, [tip]) for j in joints)
    assert not any(_at(p, given, mu_l, moving, tol=0.5) for p in ends + joints + blocks)
    assert all(_at(j, at["1"], mu_l) or _at(j, at["4"], mu_l) for j in joints)
    if mech.sliders:  # a crank-slider: a block at each heavy position, at its slider
        (s,) = mech.sliders
        assert len(blocks) == 2
        assert all(any(_at(b, at[k], mu_l, [s.point]) for b in blocks) for k in ("1", "4"))
    # the points are lettered once, on position 1: the tip's letter by its tip there
    from drawing.views import positions as V

    (centre,) = (c for t, c in texts if t == tip)
    assert math.dist(centre, V.to_sheet(at["1"][tip], mu_l)) < 10.0
    assert math.dist(centre, V.to_sheet(given[tip], mu_l)) > 10.0
    assert {"1", "4"} <= {t for t, _ in texts if re.fullmatch(r"\d+", t)}


@pytest.mark.parametrize("key", [3, 2, "press"])
def test_without_plans_the_given_position_is_the_heavy_one(key):
    """The plans are the given position's own: its links, joints and blocks are the heavy
    ones, and no cycle position's apart from it."""
    mech, info, ends, joints, blocks, _ = _positions_drawn(key)
    mu_l = info["given"].mu_l
    given = info["given"].positions
    assert ends and all(_at(e, given, mu_l) for e in ends)
    assert joints and all(_at(j, given, mu_l) for j in joints)
    assert len(blocks) == len(mech.sliders)
    assert all(_at(b, given, mu_l, [s.point for s in mech.sliders]) for b in blocks)


@pytest.mark.parametrize("key,fmt,lang", [(3, "A2", "en"), (2, "A2", "ru"), (2, "A1", "en")])
def test_the_heavy_positions_letters_and_numbers_do_not_overlap(key, fmt, lang):
    """Two heavy positions, numbered and lettered: no text meets another, and the numbers
    keep labels.GAP from the letters (the tip's own too, which read '¹B')."""
    _mech, scene, *_ = _sheet(key, fmt, lang, (1, 4))
    assert overlaps([it for it in scene.items() if isinstance(it, Text)]) == []
    _numbers_keep_clear_of_letters(scene)


def test_the_stroke_stands_beside_its_guide_not_across_the_mechanism():
    """The press's guide runs above the whole mechanism; H stood below all of it, its
    extension lines some 100 mm long across every link and position. It now stands on
    the side of the guide where its extension lines are shortest, here just above it;
    a crank-slider's below its own span, not below the whole crank circle."""
    from drawing.scene import Segment, flatten
    from drawing.styles import LineType

    def stroke(key, fmt):
        _, scene, *_ = _sheet(key, fmt)
        view = next(g for g in scene.layer("views").items if g.name == "view positions")
        items = flatten([view])
        (h,) = [t for t in items if isinstance(t, Text) and t.text.startswith("H = ")]
        # the extension lines: thin, across the guide, the one pair ending past the value's line
        ext = [s for s in items if isinstance(s, Segment) and s.line == LineType.THIN
               and abs(s.p1[0] - s.p2[0]) < 1e-9 and abs(s.p2[1] - h.pos[1]) < 6]
        return h, ext

    _h, ext = stroke("press", "A2")
    assert len(ext) == 2
    assert all(s.p2[1] < s.p1[1] for s in ext)  # from the guide upwards
    assert max(math.dist(s.p1, s.p2) for s in ext) < 15
    _h, ext = stroke(6, "A1")  # crank-slider: the crank circle (R 120 mm) is beside its span
    assert len(ext) == 2 and max(math.dist(s.p1, s.p2) for s in ext) < 100


@pytest.mark.parametrize("lang, tangential", [("ru", "τ"), ("en", "t")])
def test_the_sheets_equations_write_the_tangential_component_as_its_language_does(lang, tangential):
    """On a Russian sheet the acceleration plan's equation and the segments' table read
    a^τ_CB, as Russian textbooks write it; on an English one a^t_CB."""
    from drawing.scene import flatten
    from drawing.views import plan_view
    from plans.plan.solution import solve_position

    sol = solve_position(variant(1))
    items = [it for it in flatten(plan_view(sol, "acceleration", "1", lang).items)
             if isinstance(it, Text)]
    texts = [it.text for it in items]
    # an equation's terms and signs are texts of their own on one baseline, left to right
    rows: dict[float, list] = {}
    for it in items:
        rows.setdefault(round(it.pos[1], 3), []).append(it)
    texts += [" ".join(t.text for t in sorted(row, key=lambda t: t.pos[0]))
              for row in rows.values() if len(row) > 1]
    eq = [t for t in texts if t.startswith("a_C = ")]
    assert eq and all(f"a^{tangential}_" in t for t in eq), texts
    assert not any(f"a^{'t' if tangential == 'τ' else 'τ'}_" in t for t in texts)


def test_the_diagrams_axes_name_the_output_point_or_link():
    """The axes read «s, м», «ω, рад/с»: whose? The note and the tables say ω3 and V_D,
    and a sheet has ω of several links. They now read s_D, v_D, a_D of the slider's
    point, ψ3, ω3, ε3 of the rocker."""
    from drawing.views import diagrams_view
    from plans.cycle import analyse_cycle

    for mech, names in ((load("samples/press.toml"), ("s_{D}, м", "v_{D}, м/с", "a_{D}, м/с²")),
                        (variant(3), ("ψ_{3}, рад", "ω_{3}, рад/с", "ε_{3}, рад/с²"))):
        texts = [t.text.split(" (+")[0] for t in diagrams_view(mech, analyse_cycle(mech), "ru").items
                 if isinstance(t, Text)]
        assert [t for t in texts if t in names] == list(names), texts


@pytest.mark.parametrize(("key", "fmt"), [("fourbar", "A1"), (3, "A2")])
def test_an_english_sheet_has_no_cyrillic_letter(key, fmt):
    """The title block's literal cells wrote GOST's «У» (a student's drawing) on English
    sheets too: a Russian letter a Western reader takes for a y. An English sheet writes
    no Cyrillic of its own (the designation is the file's or the table's, as given); a
    Russian one keeps its «У»."""
    mech, _, _, _, svg = _sheet(key, fmt, "en")
    _, texts = _texts(svg)
    given = str((mech.title or {}).get("designation"))
    assert not [t for t in texts if re.search("[\u0400-\u04ff]", t) and t != given], texts
    _, ru = _texts(_sheet(key, fmt, "ru")[4])
    assert "У" in ru


def test_a_letter_with_no_clear_spot_covers_a_line_rather_than_another_letter():
    """Variant 1's acceleration plan of position 6 has no clear spot for s₂: its last
    resort, the spot that covered least, was on n₂'s letter (by 0.3 mm², less than any
    vector it could touch), and «n₂» and «s₂» ran into one another. A letter over a letter
    reads as neither: the last resort covers lines rather than letters."""
    _, scene, *_ = _sheet(1, "A2", "ru", (2, 6, 10))
    assert overlaps([it for it in scene.items() if isinstance(it, Text)]) == []
