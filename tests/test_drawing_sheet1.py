"""Sheet 1 as a teacher reads it (issue 23): the vector equations under the plans as the
course writes them, the ω1 arrow, the lettered extreme positions and θ on the plan of
positions, each position's plans together, no plan too small to read, and sheets whose
views fill their field with the plan of positions the largest of them."""

from __future__ import annotations

import io
import math
from functools import cache

import numpy as np
import pytest
from test_sheet import ROOT, _blank_band

from drawing.scene import INDEX_SIZE, Segment, Text, flatten
from drawing.sheet.frame import Sheet
from drawing.sheet.layout import LayoutError, field, pack, pack_kept
from drawing.sheet1 import LEAST_PLAN, build_sheet
from drawing.svg import to_svg
from drawing.text import text_box
from drawing.views import plan_view, positions_view
from drawing.views.common import EQUATION, Equation
from drawing.views.plans import plan_equations
from drawing.views.positions import AngleMark, to_sheet
from plans.cycle.analysis import analyse_cycle
from plans.cycle.positions import drawn
from plans.kinematics.solver import Solver
from plans.model import load
from plans.model.variants import variant
from plans.plan.solution import solve_position


@cache
def _built(key, fmt="A1", lang="ru", plans=None):
    mech = load(ROOT / "samples" / f"{key}.toml") if isinstance(key, str) else variant(key)
    scene, sheet, info = build_sheet(mech, fmt, lang, 12, list(plans) if plans else None)
    return mech, scene, sheet, info


def _texts(items):
    return [it for it in flatten(items) if isinstance(it, Text)]


# -- item 4: the vector equations under the plans ------------------------------------------

def test_a_crank_sliders_equations_name_each_terms_direction_as_the_course_does():
    """The equations under the plans read «V_C = V_B + V_CB; V_C ∥ x-x» in 2.5 mm letters
    (1.75 mm indices, under GOST 2.304's 1.8 mm), without vector bars and without each
    term's direction under it. They are now the course's: each term's direction under
    it, ∥ x-x, ⊥ AB, ⊥ CB, a normal component from its point to the centre, a fixed point
    0."""
    mech = variant(0)
    sol = solve_position(mech)
    (vel,) = plan_equations(sol.velocity, mech.driver, "ru")
    assert vel == Equation(("V_C", "V_B", "V_{CB}"), ("∥ x-x", "⊥ AB", "⊥ CB"), ("=", "+"))
    (acc,) = plan_equations(sol.acceleration, mech.driver, "ru")
    assert acc.terms == ("a_C", "a_B", "a^n_{CB}", "a^τ_{CB}")
    assert acc.directions == ("∥ x-x", "∥ BA", "∥ CB", "⊥ CB")
    assert plan_equations(sol.acceleration, mech.driver, "en")[0].terms[-1] == "a^t_{CB}"


def test_a_slotted_links_equations_carry_the_coriolis_term_across_the_guide():
    """The press (seed 000): V_A3 = V_A + V_A3A = V_B + V_A3B with V_A ⊥ OA, V_A3A ∥ BC,
    V_B = 0, V_A3B ⊥ BA3; the Coriolis term across the guide its sliding term runs
    along; a point found before (C) is known by its plan's segment."""
    mech = load(ROOT / "samples" / "press.toml")
    sol = solve_position(mech)
    v1, v2 = plan_equations(sol.velocity, mech.driver, "ru")
    assert v1.directions == ("", "⊥ OA", "∥ BC", "0", "⊥ BA_{3}")
    assert v2.terms == ("V_D", "V_C", "V_{DC}") and v2.directions == ("∥ x-x", "pc", "⊥ DC")
    a1, _ = plan_equations(sol.acceleration, mech.driver, "ru")
    assert a1.terms[2:4] == ("a^k_{A3A}", "a^r_{A3A}")
    assert a1.directions[1:4] == ("∥ AO", "⊥ BC", "∥ BC")
    assert a1.directions[5] == "∥ A_{3}B"


def test_the_equations_are_3_5_mm_with_a_bar_over_each_term_and_its_direction_under_it():
    """Drawn under the plan: every term and sign in 3.5 mm letters, a thin bar over each
    term's letter, and under each term, centred on it, its direction (the ⊥ and ∥ drawn
    as strokes: the drawing font has neither glyph)."""
    mech = variant(0)
    sol = solve_position(mech)
    view = plan_view(sol, "velocity", "1", "ru")
    texts = _texts(view.items)
    terms = {t.text: t for t in texts if t.text in ("V_C", "V_B", "V_{CB}")}
    assert set(terms) == {"V_C", "V_B", "V_{CB}"}
    assert all(t.size == EQUATION for t in terms.values())
    assert {t.size for t in texts if t.text in ("=", "+")} == {EQUATION}
    segments = [it for it in flatten(view.items) if isinstance(it, Segment)]
    for t in terms.values():
        x0, top, x1, _ = text_box(t).bounds
        bars = [s for s in segments if abs(s.p1[1] - s.p2[1]) < 1e-9
                and top - 1.5 < s.p1[1] < t.pos[1] - EQUATION + 0.1 and x0 - 0.5 < s.p1[0] < x1]
        assert len(bars) == 1, t.text
        mid = (x0 + x1) / 2
        below = [d for d in texts if 0 < d.pos[1] - t.pos[1] < 2 * EQUATION
                 and d.text in ("x-x", "AB", "CB")]
        d0, _, d1, _ = text_box(min(below, key=lambda d: abs(sum(text_box(d).bounds[::2]) / 2 - mid))
                                ).bounds
        assert d0 - 6 < mid < d1 + 1  # under its term (the sign's strokes before it)


@pytest.mark.parametrize(("key", "fmt", "lang", "plans"),
                         [(3, "A3", "ru", None), (5, "A2", "en", (1, 4)), ("press", "A2", "ru", None)])
def test_no_text_on_a_sheet_is_under_2_5_mm_nor_an_index_under_1_8_mm(key, fmt, lang, plans):
    """GOST 2.304: letters of 2.5 mm at least, and an index (0.7 of its line) of 1.8 mm
    at least: the equations, the segments table's names and the diagrams' scale factors
    had 1.75 mm indices, an English title block's «Tech. check» was shrunk to 2.3 mm."""
    _, scene, _, _ = _built(key, fmt, lang, plans)
    _gost_letters(scene)


# -- item 3: the plan of positions -----------------------------------------------------------

def _positions(key, lang="ru", marks=()):
    mech = load(ROOT / "samples" / f"{key}.toml") if isinstance(key, str) else variant(key)
    solver = Solver(mech)
    cycle = analyse_cycle(mech, 12, solver=solver)
    sol = solve_position(mech, solver=solver, mu={"mu_l": 0.002 if key != "press" else 0.005})
    return mech, cycle, sol, positions_view(sol, cycle, lang, marks=marks)


@pytest.mark.parametrize("key", ["press", 3, 0])
def test_the_crank_has_one_omega_arc_arrow_in_its_sense(key):
    """No ω1 at the crank: the plan of positions now draws the course's arc arrow about
    the crank's pivot, lettered ω₁ (drawing.views.inputs), once: the sheet's own arc and
    the inputs' were both drawn where the two met."""
    mech, _, _, view = _positions(key)
    assert len([t for t in _texts(view.items) if t.text == f"ω_{{{mech.driver.link}}}"]) == 1


def test_the_extreme_positions_are_lettered_as_the_note_names_them():
    """The note writes H = D′D″·μl and ψ = ∠C′DC″; the sheet drew the extreme positions
    unlettered. Their moving joints are now lettered ′ (where the working stroke starts)
    and ″, each at its point."""
    _mech, cycle, sol, view = _positions("press")
    texts = {t.text for t in _texts(view.items)}
    assert {"C′", "C″", "D′", "D″"} <= texts
    _, _, _, view3 = _positions(3)
    assert {"C′", "C″"} <= {t.text for t in _texts(view3.items)}
    # D′ stands by D of the first extreme position: where the working stroke starts
    shown = drawn(sol.solver, cycle)
    first, second = (to_sheet(e["D"], sol.mu_l) for e in shown.extremes)
    assert math.dist(first, second) == pytest.approx(cycle.stroke / sol.mu_l)


def test_theta_is_marked_at_the_cranks_pivot_where_the_strokes_differ():
    """θ = 39,86° for the press, the angle between the crank's two extreme positions, one
    turned through 180°: marked with its arc and value at the crank's pivot; a centric
    crank-slider's θ = 0 is not marked."""
    _, cycle, _, view = _positions("press")
    assert round(math.degrees(cycle.theta), 2) == 39.86
    assert [t for t in _texts(view.items) if t.text == "θ = 39,86°"]
    _, _, _, plain = _positions(0)
    assert not [t for t in _texts(plain.items) if t.text.startswith("θ")]


def test_any_angle_mark_is_drawn_on_the_plan_of_positions():
    """The hook for γmin (issue 24): an AngleMark given to the plan of positions is drawn
    as an arc between its rays with its label."""
    _mech, _, sol, _ = _positions(3)
    c, b, d = (sol.positions[n] for n in ("C", "B", "D"))
    *_, view = _positions(3, marks=[AngleMark(c, b, d, "γ_min = 41°")])
    assert [t for t in _texts(view.items) if t.text == "γ_min = 41°"]


# -- item 6 and the layout --------------------------------------------------------------------

def test_a_positions_plans_are_never_parted():
    """With several positions a pair that did not pack together was packed apart; now
    each pair is kept together, in reading order where an order of the views puts it so,
    else as one box; where the pairs do not fit together the sheet is refused."""
    sheet = Sheet("A2")
    sizes = [(400.0, 190.0), (150.0, 380.0)]
    assert pack(sheet, sizes) is not None
    assert pack_kept(sheet, sizes, [(0, 1)]) is None
    sizes = [(300.0, 150.0), (200.0, 150.0), (150.0, 100.0)]
    spots = pack_kept(sheet, sizes, [(0, 1)])
    (x0, y0), (x1, y1) = spots[0], spots[1]
    assert (x1, y1) in ((x0 + 300.0 + 6.0, y0), (x0, y0 + 150.0 + 6.0))


def test_a_plan_too_small_to_read_beside_another_position_is_refused():
    """Variant 1's plans of positions 2 and 8 at one μa: position 2's is 34 mm across
    where position 8's fits A2, its letters crowded. Each position's plan is now at least
    LEAST_PLAN across: A2 is refused, naming A1."""
    with pytest.raises(LayoutError) as exc:
        build_sheet(variant(1), "A2", "ru", 12, [2, 8])
    assert "each position's plans 40 mm across at least" in str(exc.value)
    assert str(exc.value).endswith("A1 holds it: use --format A1 or draw fewer positions' plans "
                                   "(--plans)")
    *_, info = _built(1, "A1", "ru", (2, 8))
    for _, _, sol in info["solutions"]:
        for plan in (sol.velocity, sol.acceleration):
            zs = [0j, *(p.value for p in plan.points.values())]
            across = max(np.ptp([z.real for z in zs]), np.ptp([z.imag for z in zs])) / plan.mu
            assert across >= LEAST_PLAN - 1e-9


def test_a_small_sheets_views_that_fit_one_order_of_hundreds_are_found():
    """Variant 9's views on A3 at μl = 0.004 fit in one order of the 240 with the plan
    of positions first, and in none of the ten pack tried: the sheet took 1:5. pack's
    search tries every order."""
    sheet = Sheet("A3")
    sizes = [(116.0, 96.0), (106.0, 128.0), (154.0, 95.0), (130.0, 115.0), (98.0, 124.0),
             (101.0, 34.0)]
    assert pack(sheet, sizes) is None
    spots = pack(sheet, sizes, search=True)
    assert spots is not None
    boxes = [(x, y, x + w, y + h) for (x, y), (w, h) in zip(spots, sizes, strict=True)]
    (x0, y0, x1, y1), _ = field(sheet)
    assert all(x0 - 1e-9 <= a and y0 - 1e-9 <= b and c <= x1 + 1e-9 and d <= y1 + 1e-9
               for a, b, c, d in boxes)


#: (variant, language, --plans) of the acceptance sheets on each format: every variant
#: on A1, A2 and A3, in both languages, with and without --plans (one position's plans
#: on A3, which two positions' do not fit: test_sheet's refusal names A2)
ACCEPT = [(v, "ru" if v % 2 else "en", None if v % 4 < 2 else (1, 4)) for v in range(10)]


def _gost_letters(scene) -> None:
    """No text under GOST 2.304's 2.5 mm, no index under its 1.8 mm."""
    for t in _texts(scene.items()):
        assert t.size >= 2.5 - 1e-9, t
        if t.markup and any(r.level for r in t.runs()):
            assert t.size * INDEX_SIZE >= 1.8 - 1e-9, t


def _largest(placed) -> bool:
    bodies = {p.view.name: p.view.body[0] * p.view.body[1] for p in placed}
    return all(bodies["positions"] >= a - 1e-9 for n, a in bodies.items()
               if n.startswith(("velocity-", "acceleration-")))


@pytest.mark.parametrize(("key", "lang", "plans"), ACCEPT)
def test_an_a1_sheet_leaves_no_band_over_60_mm_blank(key, lang, plans):
    """Variant 4 on A1 left a 165 mm band blank across the sheet, ink in a quarter of
    its field. Measured on the PNG (1 px a mm): no band across the field, the title block
    and field 26 taken as ink, is blank for more than 60 mm; the plan of positions is the
    largest view, and every view keeps clear of the others."""
    from PIL import Image

    from drawing.export import png_bytes

    _, scene, sheet, info = _built(key, "A1", lang, plans)
    png = png_bytes(to_svg(scene, sheet), dpi=25.4)
    ink = np.asarray(Image.open(io.BytesIO(png)).convert("L")) < 160
    f = sheet.frame
    inside = ink[round(f.y + 2):round(f.y1 - 2), round(f.x + 2):round(f.x1 - 2)]
    rows = inside.any(axis=1)
    blank, most = 0, 0
    for r in rows:
        blank = 0 if r else blank + 1
        most = max(most, blank)
    assert most <= 60
    assert _largest(info["placed"])
    _gost_letters(scene)
    (_x0, y0, _x1, y1), blocked = field(sheet)
    spans = [(p.rect.y, p.rect.y1) for p in info["placed"]] + [(b[1], b[3]) for b in blocked]
    assert _blank_band(y0, y1, spans) <= 60 + 1e-6


@pytest.mark.parametrize("fmt", ["A2", "A3"])
@pytest.mark.parametrize(("key", "lang", "plans"), ACCEPT)
def test_the_plan_of_positions_is_the_largest_view_where_the_scales_are_free(fmt, key, lang, plans):
    """Variant 3 on A3: the acceleration plan, πb = 207 mm, filled the middle of the
    sheet while the plan of positions was 1:4. Where the file leaves the scales free,
    the plan of positions, the view a teacher reads first, is now the largest (by the
    area of its drawing); on A3 a position's plans (one position's: two do not fit).
    Not on every sheet: variant 1's on A3 with --plans 1 keeps 1:4 beside a velocity
    plan 6% larger, its acceleration plan crowded at the scale that would let the plan
    of positions lead; no letter is under 2.5 mm, no index under 1.8 mm."""
    if fmt == "A3" and plans:
        plans = plans[:1]
    mech, scene, _, info = _built(key, fmt, lang, plans)
    assert not mech.scales
    assert _largest(info["placed"])
    _gost_letters(scene)


@pytest.mark.parametrize(("name", "argv"), [
    ("press", ["samples/press.toml", "--format", "A2"]),
    ("fourbar", ["samples/fourbar.toml"]),
])
def test_the_committed_sheet_samples_are_what_the_readmes_commands_write(name, argv, tmp_path):
    """samples/press.svg and samples/fourbar.svg are regenerated byte for byte by README's
    commands (the sheet changed under them: they showed the sheet as it was)."""
    import os

    from plans.cli import main

    readme = (ROOT / "README.md").read_text(encoding="utf-8")
    assert f"plans sheet {' '.join(argv)} -o samples/{name}.svg --png samples/{name}.png" in " ".join(
        readme.split())
    here = os.getcwd()
    try:
        os.chdir(ROOT)  # the command as README gives it, its file named as there
        assert main(["sheet", *argv, "-o", str(tmp_path / f"{name}.svg")]) == 0
    finally:
        os.chdir(here)
    assert (tmp_path / f"{name}.svg").read_bytes() == (ROOT / "samples" / f"{name}.svg").read_bytes()


def test_views_at_a_files_own_scales_are_spread_where_they_fill_enough_of_the_field():
    """The press fixes its scales; on A2 its views take half of the field, and packed to
    the top they left the lower 106 mm of the sheet blank. Views at a file's scales that
    fill SPARSE of the field or more are set evenly over it as the sheet's own are; on A1,
    where they take a fifth, they stay together and the note says so."""
    from drawing.sheet.layout import share_used
    from drawing.sheet1 import SPARSE, sparse_note

    mech, _, sheet, info = _built("press", "A2")
    assert mech.scales and share_used(sheet, info["placed"]) >= SPARSE
    (_x0, y0, _x1, y1), blocked = field(sheet)
    spans = [(p.rect.y, p.rect.y1) for p in info["placed"]] + [(b[1], b[3]) for b in blocked]
    assert _blank_band(y0, y1, spans) <= 60
    mech, _, sheet, info = _built("press", "A1")
    assert sparse_note(mech, sheet, info["placed"]) is not None
    assert min(p.rect.y for p in info["placed"]) < field(sheet)[0][1] + 1.0  # packed to the top
