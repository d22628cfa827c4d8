"""The single-position plans: seed numbers, recorded constructions and invariants."""

import math

import numpy as np
import pytest

from plans.model import load
from plans.model.variants import variant
from plans.plan.solution import solve_position


@pytest.fixture(scope="module")
def press():
    return solve_position(load("samples/press.toml"))


@pytest.fixture(scope="module")
def fourbar():
    return solve_position(load("samples/fourbar.toml"))


def test_press_seed_numbers_within_drawing_precision(press):
    seg = press.segments
    # seed 000 at μv = 0.05, μa = 1: its measured segments, a few percent off
    assert seg["pa"] == pytest.approx(60, abs=1e-9)
    assert seg["pa3"] == pytest.approx(55, rel=0.03)
    assert seg["aa3"] == pytest.approx(23, rel=0.03)
    assert seg["BA3"] == pytest.approx(57, rel=0.03)
    assert seg["ak"] == pytest.approx(11.09, rel=0.03)
    assert seg["bn1"] == pytest.approx(13.26, rel=0.03)
    assert press.omega[3] == pytest.approx(4.82, rel=0.01)
    assert seg["OB"] == pytest.approx(44) and seg["BC"] == pytest.approx(75)


def test_press_exact_values_closed_form(press):
    # RPR with the rocker pivot fixed: V_A3 is V_A's component ⊥ BA, V_A3A the ∥ one
    A = 0.15 * complex(math.cos(math.radians(60)), math.sin(math.radians(60)))
    B = -0.44j
    u = (A - B) / abs(A - B)
    vA = 1j * 20 * A
    v_par = (vA * u.conjugate()).real
    v_perp = (vA * u.conjugate()).imag
    assert abs(press.velocity.value("a3")) == pytest.approx(abs(v_perp), rel=1e-12)
    assert press.segments["aa3"] * 0.05 == pytest.approx(abs(v_par), rel=1e-12)
    w3 = v_perp / abs(A - B)
    assert press.omega[3] == pytest.approx(w3, rel=1e-12)
    # a^k = 2 ω3 V_A3A and a^n = ω3² l_A3B
    assert press.segments["ak"] == pytest.approx(2 * abs(w3) * abs(v_par), rel=1e-12)
    assert press.segments["bn1"] == pytest.approx(w3**2 * abs(A - B), rel=1e-12)


def test_coriolis_direction_is_relative_velocity_turned_by_omega(press):
    v = press.velocity
    a = press.acceleration
    vrel = v.value("a3") - v.value("a")  # V_A3A
    cor = a.value("k") - a.value("a")  # a^k_A3A drawn from a
    w3 = press.omega[3]
    assert cor == pytest.approx(2j * w3 * vrel, rel=1e-12)


def test_constructions_are_recorded(press):
    a3 = press.velocity.points["a3"].source
    assert a3.kind == "intersection"
    assert [ln.through for ln in a3.lines] == ["a", "b"]
    assert [ln.relation for ln in a3.lines] == ["∥ BC", "⊥ BA3"]
    acc_a3 = press.acceleration.points["a3"].source
    assert [ln.through for ln in acc_a3.lines] == ["k", "n1"]
    c = press.velocity.points["c"].source
    assert c.kind == "similarity" and (c.base, c.other) == ("b", "a3")
    assert c.equation == "pc = pa3·BC/BA3"  # B is fixed: b lies at the pole p
    assert press.acceleration.points["c"].source.equation == "πc = πa3·BC/BA3"
    d = press.velocity.points["d"].source
    assert [ln.through for ln in d.lines] == ["c", "p"]


def test_each_intersection_lies_on_both_recorded_lines(press, fourbar):
    for sol in (press, fourbar):
        for plan in (sol.velocity, sol.acceleration):
            for pt in plan.points.values():
                for ln in pt.source.lines:
                    start = plan.value(ln.through)
                    off = pt.value - start
                    # the point is on the line: the offset is parallel to its direction
                    cross = (off.conjugate() * ln.direction).imag
                    assert abs(cross) <= 1e-12 * max(1.0, abs(pt.value))


def test_similarity_points_agree_with_direct_computation(press, fourbar):
    """Every plan point, built on Python numbers by the recipe (similarity steps among
    them), equals the point solved directly on the array path."""
    for sol in (press, fourbar):
        m = sol.motion
        for plan, store in ((sol.velocity, m.velocity), (sol.acceleration, m.acceleration)):
            assert any(p.source.kind == "similarity" for p in plan.points.values())
            for name, values in store.items():
                pt = plan.points[name.lower()]
                assert pt.value == pytest.approx(complex(values[0]), rel=1e-12, abs=1e-12)


def test_vector_lengths_in_mm_equal_values_over_mu(press):
    for key, mm in press.segments.items():
        if key.startswith("p") and key[1:] in press.velocity.points:
            assert mm * press.mu_v == pytest.approx(abs(press.velocity.value(key[1:])), rel=1e-12)


def test_fourbar_seed_001_numbers(fourbar):
    v, a = fourbar.velocity, fourbar.acceleration
    assert abs(v.value("c")) == pytest.approx(0.92, rel=0.03)
    assert abs(v.value("e")) == pytest.approx(1.22, rel=0.03)
    assert abs(a.value("c")) == pytest.approx(12, rel=0.03)
    assert abs(v.value("b")) == pytest.approx(math.pi * 149.2 / 30 * 0.0625, rel=1e-12)


def test_velocities_are_derivatives_of_positions():
    mech = load("samples/press.toml")
    h = 1e-6
    sols = [solve_position(mech, mech.driver.phi + k * h) for k in (-1, 0, 1)]
    w1 = mech.driver.omega
    for name in sols[1].positions:
        fd = (sols[2].positions[name] - sols[0].positions[name]) / (2 * h) * w1
        exact = complex(sols[1].motion.velocity[name][0])
        if name in sols[1].motion.coincident:
            continue  # a coincident point is a different material point at each instant
        assert fd == pytest.approx(exact, rel=1e-6, abs=1e-8)


@pytest.mark.parametrize("n", range(10))
def test_variant_plans_solve(n):
    sol = solve_position(variant(n))
    assert sol.segments["pb"] > 0
    assert all(np.isfinite(v) for v in sol.segments.values())


@pytest.mark.parametrize(("name", "velocity", "acceleration"), [
    ("scotch_yoke", "V_A3 = V_A + V_A3A; V_A3 ∥ x-x", "a_A3 = a_A + a^r_A3A; a_A3 ∥ x-x"),
    ("yoke_on_rocker", "V_A5 = V_A + V_A5A = V_A3 + V_A5A3",
     "a_A5 = a_A + a^k_A5A + a^r_A5A = a_A3 + a^k_A5A3 + a^r_A5A3"),
    ("tangent", "V_C = V_C1 + V_CC1; V_C ∥ y-y", "a_C = a_C1 + a^k_CC1 + a^r_CC1; a_C ∥ y-y"),
])
def test_sliding_groups_write_each_side_of_their_equations_as_on_paper(name, velocity,
                                                                         acceleration):
    """Along a fixed guide the point's own vector only has a direction, said apart
    ("; V_C ∥ y-y", not the circular "= V_C(∥ y-y)"); a side along a turning link's guide
    starts at the coincident point and carries the Coriolis term; a block in a yoke that
    only translates has none."""
    from plans.model.scenes import SCENES

    sol = solve_position(SCENES[name].mechanism())
    got = {p.source.equation for plan in (sol.velocity, sol.acceleration)
           for p in plan.points.values() if p.source.kind == "intersection"}
    assert {velocity, acceleration} <= got
    # and the Coriolis terms drawn for its point are exactly the ones the equation names
    point = acceleration.split(" ")[0][2:]
    ks = {p.source.label for p in sol.acceleration.points.values()
          if p.source.kind == "component" and p.source.label.startswith(f"a^k_{point}")}
    assert ks == {t for t in acceleration.replace("=", "+").split(" + ") if t.startswith("a^k")}


def _yoke_and_rocker() -> str:
    """The built-in Scotch yoke with a rocker FG whose block G slides in a second slot of
    the yoke."""
    from plans.model.scenes import SCENES

    text = SCENES["scotch_yoke"].toml
    assert "[frame]\nO = [0.0, 0.0]\n" in text
    return text.replace("[frame]\nO = [0.0, 0.0]\n", "[frame]\nO = [0.0, 0.0]\nF = [0.1, 0.25]\n") + """
[links.4]
axis = ["F", "G"]
points = { G = 0.2 }
[links.5]
points = { G = 0 }
[[sliders]]
link = 5
guide = { link = 3, angle_deg = 90, through = [0.15, 0.0] }
[assembly]
G = "below F"
"""


def test_a_guide_on_a_link_that_only_translates_has_no_coriolis_term():
    """The rocker's block G slides in a slot of the Scotch yoke, which never turns: its
    equation and its acceleration plan have no Coriolis term, in the recorded solve and
    in the sweep alike, and the plan still matches the exact solution."""
    import tomllib

    import numpy as np

    from plans.kinematics.solver import Solver
    from plans.model import from_dict

    mech = from_dict(tomllib.loads(_yoke_and_rocker()), "yoke_rocker")
    assert mech.translating() == {0, 2, 3, 5}  # the yoke and the blocks in its slots
    sol = solve_position(mech)
    g = sol.acceleration.points["g"].source
    assert g.equation == "a_G = a_F + a^n_GF + a^t_GF = a_G3 + a^r_GG3"
    assert not [p for p in sol.acceleration.points.values()
                if p.source.kind == "component" and p.source.label.startswith("a^k")]
    phi = np.radians(np.arange(0.0, 360.0, 7.5))
    sv = Solver(mech)
    m, sw = sv.solve(phi), sv.sweep(phi)
    ok = np.asarray(m.valid)
    for name in ("G", "A3"):
        np.testing.assert_allclose(sw.acceleration[name][ok], m.acceleration[name][ok], rtol=1e-13)
    # against finite differences of the velocity plan's V_G (centred, h = 1e-6 rad)
    h = 1e-6
    v = [complex(Solver(mech).solve(np.array([mech.driver.phi + d])).velocity["G"][0])
         for d in (-h, h)]
    dv_dt = (v[1] - v[0]) / (2 * h) * mech.driver.omega
    assert abs(sol.acceleration.value("g") - dv_dt) < 1e-6 * abs(dv_dt) + 1e-9


@pytest.mark.parametrize(("name", "point", "unknowns"), [
    ("scotch_yoke", "a3", ["a^r_A3A", "a_A3"]),
    ("tangent", "c", ["a^r_CC1", "a_C"]),
    ("crank_slider_offset", "b", ["a^t_BA", "a_B"]),
])
def test_the_unknown_along_a_fixed_guide_is_the_points_own_acceleration(name, point, unknowns):
    """Along a fixed guide the unknown is the point's own a_C (as the equation writes
    it), not a relative a^r_C."""
    from plans.model.scenes import SCENES

    sol = solve_position(SCENES[name].mechanism())
    assert [ln.unknown for ln in sol.acceleration.points[point].source.lines] == unknowns


@pytest.mark.parametrize("deg", [200.0, 230.0])
def test_a_segment_that_is_zero_reads_zero_not_rounding(deg):
    """The inclined yoke (guide at 20°, slot at 80°) at φ1 = 200°: the crank pin's
    acceleration −ω²·OA points along the guide, so its share along the slot, a^r_A3A, is
    0. It was printed as 4.4e-16 m/s² (two equal vectors subtracted); every reader of the
    plan now gets 0. At 230° the same segment is the exact decomposition."""
    from plans.model.scenes import SCENES
    from plans.note.report import note

    mech = SCENES["yoke_inclined"].mechanism()
    sol = solve_position(mech, math.radians(deg))
    acc = sol.acceleration
    w, r = abs(mech.driver.omega), mech.driver.length
    a_pin = -w * w * r * complex(math.cos(math.radians(deg)), math.sin(math.radians(deg)))
    u, s = complex(math.cos(math.radians(20)), math.sin(math.radians(20))), complex(
        math.cos(math.radians(80)), math.sin(math.radians(80)))
    beta = (u.conjugate() * a_pin).imag / (u.conjugate() * s).imag  # a_A = α·u + β·s
    want = abs(beta) / acc.mu
    for got in (acc.segments["aa3"], acc.mm("a", "a3"), sol.segments["aa3"]):
        assert got == (0.0 if deg == 200.0 else pytest.approx(want, rel=1e-12))
    text = note(sol, "ru")
    assert "e-1" not in text
    if deg == 200.0:
        assert "a^r_A3A = aa3·μa = 0·0,2 = 0 м/с²" in text


def test_a_real_small_segment_is_not_taken_for_rounding():
    """1e-4° from the press's extreme position V_A3B is 5e-6 m/s and a^n_A3B = V²/l is
    6.6e-11 m/s²: tiny but real, not two equal vectors subtracted. The plan keeps it, so
    the note's a^n and its segment bn1 agree."""
    from plans.model import load

    mech = load("samples/press.toml").at_file_angle(250.06763)
    sol = solve_position(mech)
    v = abs(sol.velocity.value("a3") - sol.velocity.value("b"))
    l_ab = abs(sol.positions["A3"] - sol.positions["B"])
    assert 0 < v < 1e-5
    assert sol.acceleration.segments["bn1"] == pytest.approx(v * v / l_ab / sol.acceleration.mu, rel=1e-6)


def test_a_rocker_at_rest_has_no_velocity_left_on_its_plan():
    """Variant 3 at its cycle's position 0, an extreme position: the rocker is at rest,
    and pc, dc had read 1.599e-12 mm on the sheet's table (1.2e-14 of the plan's longest
    vector, just above the 1e-14 rounding was taken to reach)."""
    from plans.cycle import analyse_cycle
    from plans.kinematics.solver import Solver
    from plans.model.variants import variant

    mech = variant(3)
    solver = Solver(mech)
    phi = analyse_cycle(mech, solver=solver).positions[0]
    sol = solve_position(mech, phi, solver=solver)
    assert sol.velocity.segments["pc"] == 0.0 and sol.omega[3] == 0.0
    assert sol.velocity.segments["pb"] > 50  # the crank pin is not at rest


def test_rounding_of_epsilon_is_judged_against_the_cranks_omega_squared():
    """A parallelogram turns its rocker at the crank's constant ω and translates its
    coupler: every ε is 0, and the coupler's ω too. The solved values are rounding
    (ε up to 2e-13 rad/s², ω2 2e-15 rad/s), which the plan takes as 0 against the
    largest ω and against ω1² for ε: with no ε larger than rounding, ε had no other
    scale to be judged against."""
    from test_change_points import parallelogram

    mech = parallelogram()
    w1 = mech.driver.omega
    for deg in (40, 100, 220, 300):
        sol = solve_position(mech, math.radians(deg))
        raw = sol.scalar.links
        assert any(raw[i].epsilon != 0.0 for i in (2, 3)) and raw[2].omega != 0.0
        assert sol.epsilon == {1: 0.0, 2: 0.0, 3: 0.0}
        assert sol.omega[2] == 0.0
        assert sol.omega[1] == w1 and sol.omega[3] == pytest.approx(w1, rel=1e-14)


@pytest.mark.parametrize("scene", ["crank_rocker", "slotted_general", "scotch_yoke", "fourbar"])
def test_every_similarity_point_lies_on_a_side_of_its_links_image(scene):
    """``image_sides``: each point found by similarity lies on a side drawn, the bases'
    line run on to it where it is in line with them (variant 1's b–c–e), else the two
    sides of the link's triangle (the crank-rocker's e and f): both ends of the
    triangle's sides are a base and the point itself. A link that translates (the Scotch
    yoke's) is one point on the plan, and has no image to draw."""
    from plans.model.scenes import SCENES
    from plans.plan.solution import image_sides

    sol = solve_position(SCENES[scene].mechanism())
    for plan in (sol.velocity, sol.acceleration):
        sides = image_sides(plan)
        similar = [p for p in plan.points.values() if p.source.kind == "similarity"]
        assert similar
        for p in similar:
            src = p.source
            b0, b1, z = plan.value(src.base), plan.value(src.other), p.value
            if abs(b1 - b0) <= plan.tiny:  # a link that translates: one point, no image
                assert abs(z - b0) <= plan.tiny
                assert all(abs(z - x) > plan.tiny for side in sides for x in side)
                continue
            if abs(src.ratio.imag) >= 1e-12:  # a triangle: its two sides, as they are
                assert (b0, z) in sides and (b1, z) in sides
                continue

            def on(x, a, b):
                t = (x - a) / (b - a)
                return abs(t.imag) <= 1e-12 and -1e-12 <= t.real <= 1 + 1e-12

            # a side through the point and both its bases
            assert any(all(on(x, a, b) for x in (z, b0, b1)) for a, b in sides), p.name


@pytest.mark.parametrize("lang", ["ru", "en"])
def test_every_value_read_off_a_plan_stands_under_its_heading(lang):
    """A crank's own similarity point (S1 of variant 4) had its V_S1 = ps1·μv line right
    under the similarity step, without the heading "Скорости точек по плану:" that every
    group's points get: the note read as if the value were a second similarity step."""
    import re

    from plans.model.variants import variant
    from plans.note.report import T, note

    for n in (3, 4):
        text = note(solve_position(variant(n)), lang)
        lines = [ln for ln in text.splitlines() if ln.strip()]
        value = re.compile(r"- `(V|a)_\w+ = [pπ]\w+·μ[va] = ")
        read_off = re.compile(r"- `(V|a)\S* = \w+·μ[va] = ")  # values, then unknowns
        found = headed = 0
        for i, ln in enumerate(lines):
            if not value.match(ln):
                continue
            found += 1
            j = i - 1
            while read_off.match(lines[j]):
                j -= 1
            want = T[lang]["avalues" if ln.startswith("- `a") else "values"]
            # the plan's heading, or that of a translating link's equal values
            assert lines[j] == want or (lines[j].endswith(":") and " = " in lines[j]
                                        and not lines[j].startswith("- ")), (n, ln, lines[j])
            headed += lines[j] == want
        assert found >= 6 and headed >= 4


def test_a_plan_point_asked_by_the_mechanisms_name_is_told_its_plan_name(press):
    """``velocity.value("D")`` was a bare KeyError: 'D'; a plan names D as d."""
    assert press.velocity.value("d") == press.scalar.velocity["D"]
    with pytest.raises(KeyError, match=r"'D' is not a point of the velocity plan .*"
                                       r"the mechanism's point D is 'd' on a plan"):
        press.velocity.value("D")
    with pytest.raises(KeyError, match=r"'Q' is not a point of the acceleration plan \(its "
                                       r"points: π, o, b, a, "):
        press.acceleration.mm("π", "Q")


@pytest.mark.parametrize(("phi", "error", "message"), [
    (np.array([0.5]), TypeError, r"one number of radians \(for many angles at once: "
                                 r"Solver\.sweep or Solver\.solve\), not array\(\[0\.5\]\)"),
    (np.array([0.5, 0.6]), TypeError, r"one number of radians \(for many angles"),
    (1 + 1j, TypeError, r"one number of radians, not \(1\+1j\)"),
    ("half", ValueError, r"one number of radians, not 'half'"),
    (float("nan"), ValueError, r"a finite number of radians, not nan"),
])
def test_one_position_refuses_what_is_not_one_angle_in_its_own_words(phi, error, message):
    """An array of angles given to solve_position or solve_one was numpy's "only
    0-dimensional arrays can be converted to Python scalars", a complex angle float()'s
    words: each now says what is wanted, and where many angles go."""
    from plans.kinematics.solver import Solver

    mech = load("samples/press.toml")
    for solve in (lambda: solve_position(mech, phi), lambda: Solver(mech).solve_one(phi)):
        with pytest.raises(error, match=f"^the crank angle must be {message}"):
            solve()
    assert solve_position(mech, np.float64(mech.driver.phi)).segments["pa3"] == \
        pytest.approx(55.43, abs=0.005)


def test_a_file_name_given_for_a_mechanism_is_told_to_be_loaded():
    """Solver("press.toml") and solve_position("press.toml") were AttributeError: 'str'
    object has no attribute 'revolutes', from deep in the structure analysis."""
    from plans.cycle import analyse_cycle
    from plans.kinematics.solver import Solver

    for call in (Solver, solve_position, analyse_cycle):
        with pytest.raises(TypeError, match=r"^a mechanism \(plans\.load, plans\.from_dict\) is "
                                            r"needed, not 'samples/press\.toml': read the file "
                                            r"first, with load\('samples/press\.toml'\)$"):
            call("samples/press.toml")
    with pytest.raises(TypeError, match=r"is needed, not None$"):
        Solver(None)
