"""Change points: where a group's links lie in line and its two assemblies meet, the motion
goes on smoothly (plans.kinematics.branches.change_points, Solver.flips), checked against closed forms
(a parallelogram translates its coupler, an isosceles crank-slider's slider runs at 2R·cos φ,
a slotted link whose pivot is on the crank circle turns at half the crank's rate) and
against the smoothness of the velocities across the change point."""

import json
import math

import numpy as np
import pytest
from test_stability import crank_slider, fourbar, mech_of, slotted

from plans import Solver, analyse_cycle
from plans.cycle import summary
from plans.cycle.positions import drawn

A, B_, D = 0.05, 0.2, 0.2  # crank, coupler, frame: a parallelogram with c = a


def parallelogram(hint="above OD"):
    return mech_of(fourbar(A, B_, A, D).replace('B = "above OD"', f'B = "{hint}"'))


def isosceles(R=0.1):
    return mech_of(crank_slider(R, R, 0.0).replace('B = "right of O"', 'B = "right of A"'))


def away(changes, n=7201, gap=1e-4):
    """Angles over the turn, none within ``gap`` rad of a change point (rad from +x)."""
    phi = np.linspace(0.0, 2 * math.pi, n)
    keep = np.ones(n, dtype=bool)
    for c in changes:
        keep &= np.abs((phi - c + math.pi) % (2 * math.pi) - math.pi) > gap
    return phi[keep]


def angles(sv):
    return [math.degrees(sv.branch_at + f) for points in sv.changes for f in points]


def on_circle(got, want, tol=1e-9):
    """Angles (degrees) ``got`` are ``want`` in some order, each to ``tol`` round the turn."""
    left = list(want)
    for g in got:
        k = min(range(len(left)), key=lambda i: abs((g - left[i] + 180) % 360 - 180))
        if abs((g - left[k] + 180) % 360 - 180) > tol:
            return False
        left.pop(k)
    return not left


def test_a_parallelogram_stays_a_parallelogram_over_the_whole_turn():
    mech = parallelogram()
    sv = Solver(mech)
    assert on_circle(angles(sv), [0.0, 180.0])
    assert sv.flips == sv.changes  # two a turn: both flip the sign
    phi = away([0.0, math.pi])
    m = sv.solve(phi)
    assert m.valid.all()
    # the coupler translates: B − A = D − O, so the rocker turns with the crank
    assert np.max(np.abs(m.position["B"] - m.position["A"] - D)) < 1e-12
    w1 = mech.driver.omega
    assert np.max(np.abs(m.links[3].omega - w1)) < 1e-9 * w1
    assert np.max(np.abs(m.links[2].omega)) < 1e-9 * w1
    c = analyse_cycle(mech, solver=sv)
    assert c.full_turn and not c.extremes
    assert [math.degrees(x) % 360 for x in c.change_points] == pytest.approx([180.0, 0.0], abs=1e-9)
    text = "\n".join(summary(c, mech.driver))
    assert "change points at φ1 = 180°, 0°" in text and "smooth motion" in text
    # singular at the change points, said beside them: "(the plans there are singular)"
    # had ended the line, after the angle where a slotted link's two turns meet
    assert "change points at φ1 = 180°, 0°: the links of a group lie in line there and the " \
           "plans are singular;" in text
    assert "cannot make a full turn" not in text


def test_with_its_sign_kept_the_parallelogram_would_fold_and_stop():
    """What the flips mend: a solver told of no change points folds into the
    antiparallelogram past 180° and judges the crank unable to turn."""
    mech = parallelogram()
    sv = Solver(mech)
    kept = sv.with_flips(((),))
    phi = np.radians(np.array([200.0, 300.0]))
    assert np.max(np.abs(kept.solve(phi).position["B"] - kept.solve(phi).position["A"] - D)) > 0.05
    assert np.max(np.abs(sv.solve(phi).position["B"] - sv.solve(phi).position["A"] - D)) < 1e-12


@pytest.mark.parametrize("hint", ["above OD", "below OD"])
def test_velocities_are_smooth_across_each_change_point(hint):
    """The parallelogram and the antiparallelogram (the other hint) each keep their form:
    the plan velocities on either side of a change point agree to O(δ), where a fold
    would reverse them."""
    mech = parallelogram(hint)
    sv = Solver(mech)
    for c in (0.0, math.pi):
        for d in (1e-3, 1e-2):
            m = sv.solve(np.array([c - d, c + d]))
            assert m.valid.all()
            for name in ("B",):
                v = m.velocity[name]
                assert abs(v[1] - v[0]) < 20 * d * abs(v[0]), (hint, c, d)
    # the antiparallelogram stays crossed: its coupler never translates
    if hint == "below OD":
        m = sv.solve(away([0.0, math.pi], gap=0.1))
        assert np.min(np.abs(m.position["B"] - m.position["A"] - D)) > 1e-3


def test_plan_velocities_are_the_derivatives_of_positions_through_the_turn():
    mech = parallelogram("below OD")
    sv = Solver(mech)
    h = 1e-6
    phi = away([0.0, math.pi], n=361, gap=0.01)
    m, lo, hi = sv.solve(phi), sv.solve(phi - h), sv.solve(phi + h)
    w1 = mech.driver.omega
    for name in ("B", "E", "F"):
        fd = (hi.position[name] - lo.position[name]) / (2 * h) * w1
        assert np.max(np.abs(fd - m.velocity[name])) < 1e-6 * np.max(np.abs(m.velocity[name]))


def test_an_isosceles_crank_slider_runs_at_2R_cos_phi_with_a_stroke_of_4R():
    R = 0.1
    mech = isosceles(R)
    sv = Solver(mech)
    assert on_circle(angles(sv), [90.0, 270.0])
    phi = away([math.pi / 2, 3 * math.pi / 2])
    m = sv.solve(phi)
    assert np.max(np.abs(m.position["B"] - 2 * R * np.cos(phi))) < 1e-12
    w1 = mech.driver.omega
    assert np.max(np.abs(m.velocity["B"] + 2 * R * w1 * np.sin(phi))) < 1e-9
    c = analyse_cycle(mech, solver=sv)
    assert c.full_turn
    assert c.stroke == pytest.approx(4 * R, rel=1e-12)
    assert c.theta == 0.0 and c.K == 1.0
    assert on_circle([math.degrees(x) for x in c.extremes], [0.0, 180.0])


def test_positions_on_a_change_point_are_drawn():
    """The twelve positions of the parallelogram from 60° include 0° and 180°, where the
    groups close to rounding only: they stand on the plan of positions."""
    mech = parallelogram()
    sv = Solver(mech)
    c = analyse_cycle(mech, solver=sv)
    on = [k for k, x in enumerate(c.positions) if abs(math.sin(x)) < 1e-12]
    assert len(on) == 2
    shown = drawn(sv, c)
    assert all(p is not None for p in shown.cycle)
    for k in on:
        p = shown.cycle[k]
        assert abs(p["B"] - p["A"] - D) < 1e-7  # the tangency, to the root of rounding
    assert shown.trajectory.all()


def test_the_sweep_and_the_one_angle_path_follow_the_same_smooth_motion():
    mech = isosceles()
    sv = Solver(mech)
    phi = away([math.pi / 2, 3 * math.pi / 2], n=3601)
    m = sv.solve(phi)
    sw = sv.sweep(phi, block=500)
    for name in m.position:
        assert np.max(np.abs(sw.position[name] - m.position[name])) < 1e-15
        assert np.max(np.abs(sw.velocity[name] - m.velocity[name])) < 1e-12
    for x in (2.0, 4.0, 5.0):  # past one change point and past both
        one = sv.solve_one(x)
        assert abs(one.position["B"] - 2 * 0.1 * math.cos(x)) < 1e-15


def test_a_slotted_link_with_its_pivot_on_the_crank_circle_turns_at_half_the_crank_rate():
    """Its block passes the pivot once a turn (an odd change point): kept, the sign would
    turn the slotted link over by 180° there; its smooth motion turns at ω1/2 and repeats
    after two crank turns, the seam at the file's angle."""
    R = 0.1
    mech = mech_of(slotted(R, R))
    sv = Solver(mech)
    assert on_circle(angles(sv), [270.0])
    assert sv.flips == sv.changes
    start = sv.branch_at
    phi = start + away([3 * math.pi / 2 - start], n=3601, gap=1e-3)[:-1]
    m = sv.solve(phi)
    w1 = mech.driver.omega
    assert np.max(np.abs(m.links[3].omega - w1 / 2)) < 1e-9 * w1
    psi = np.unwrap(np.angle(m.links[3].rotor))
    assert np.max(np.abs(np.diff(psi))) < 0.01  # no turning over within the turn
    c = analyse_cycle(mech, solver=sv)
    assert c.full_turn
    text = "\n".join(summary(c, mech.driver))
    assert "repeats only after two turns" in text and "meet at φ1 = 20°" in text


def test_a_crank_slider_whose_rod_reaches_the_guide_once_a_turn_folds_back_there():
    """R + e = L: the rod stands across the guide at 270° once a turn. Kept, the sign
    makes a continuous motion that turns back there: an extreme position exactly at the
    change point, the slider at the foot x = 0, the stroke to the stretched-out position."""
    R, L, e = 0.1, 0.15, 0.05
    mech = mech_of(crank_slider(R, L, e))
    sv = Solver(mech)
    assert on_circle(angles(sv), [270.0])
    assert sv.flips == ((),)
    c = analyse_cycle(mech, solver=sv)
    assert c.full_turn
    assert any(on_circle([math.degrees(x)], [270.0]) for x in c.extremes)
    assert c.stroke == pytest.approx(math.sqrt((R + L) ** 2 - e**2), rel=1e-9)
    text = "\n".join(summary(c, mech.driver))
    assert "folds back there" in text


@pytest.mark.parametrize("scale", [1 - 1e-9, 1 + 1e-9])
def test_a_near_miss_is_no_change_point(scale):
    """A frame 1e-9 shorter (a Grashof double crank that clears the line by a hair) or
    longer (a non-Grashof linkage with a dead point) has no change point: its sign is
    kept, as a true dead point must be."""
    sv = Solver(mech_of(fourbar(A, B_, A, D * scale)))
    assert sv.changes == ((),) and sv.flips == ((),)


def test_well_shaped_mechanisms_have_no_change_points():
    from plans.model.scenes import SCENES

    for name, scene in SCENES.items():
        sv = Solver(scene.mechanism())
        assert all(not c for c in sv.changes), name


def test_a_plan_asked_for_on_a_change_point_gives_the_positions_and_says_why(capsys, tmp_path):
    """solve had refused the whole position; the positions stand there, and only the
    plans are singular: it gives them and says why, exit 0 as the cycle's row there."""
    from support import run

    path = tmp_path / "parallelogram.toml"
    path.write_text(fourbar(A, B_, A, D), "utf-8")
    code, out, err = run(capsys, "solve", path, "--angle", "180")
    assert code == 0 and err == ""
    assert "at φ1 = 180° (a change point: the two assemblies of a group meet there)" in out
    assert "dead point" not in out
    assert len([line for line in out.splitlines() if "change point" in line]) == 1
    assert "The velocity and acceleration plans are not built: group 2–3 (RRR)" in out
    assert "  B              0.15            0" in out  # A at −0.05, B = A + 0.2: in line with D
    code, out, _ = run(capsys, "solve", path, "--angle", "180", "--json")
    got = json.loads(out)
    assert got["plans"] is None and "(a change point" in got["singular"]
    assert got["points"]["B"]["position"] == pytest.approx([0.15, 0.0], abs=1e-15)
    code, out, err = run(capsys, "solve", path, "--angle", "180", "--lang", "ru")
    assert code == 0 and err == ""  # the reason in the report's language, not in English
    assert ("Планы скоростей и ускорений не строятся: группа 2–3 (ВВВ) при φ1 = 180° (точка смены "
            "сборки: в ней сходятся две сборки группы): A, B и D на одной прямой (звенья 2 и 3 "
            "вытянуты или сложены): особое положение, план не имеет единственного решения") in out
    assert "мёртвая точка" not in out and not any("a" <= c <= "z" for c in out.split("не строятся")[1]
                                                  .replace("sin", ""))
    code, out, err = run(capsys, "cycle", path, "--positions", "4", "--json")
    rows = json.loads(out)["rows"]  # from 60°: 60, 150, 240, 330 miss them; 12 would not
    assert all(r["solved"] for r in rows)


def test_a_cycle_row_on_a_change_point_gives_its_positions_and_says_why(capsys, tmp_path):
    """From 60° in 12 positions a parallelogram passes 180° (position 4) and 0° (10): their
    positions stand (B − A = D − O), their plans are singular. That is no error: the rows
    give x and y and leave V, a, ω and ε out, with the reason, and the command exits 0."""
    import csv
    import io
    import json

    from support import run

    path = tmp_path / "parallelogram.toml"
    path.write_text(fourbar(A, B_, A, D), "utf-8")
    code, out, err = run(capsys, "cycle", path, "--positions", "12", "--json")
    assert code == 0, err
    assert err.strip() == ("plans cycle: warning: positions 4, 10 are on or beside a change "
                           "point: positions only, the plans there are singular")
    rows = json.loads(out)["rows"]
    for r in rows:
        k, phi = r["index"], math.radians(r["phi_deg"])
        assert r["placed"]
        (ax, ay), (bx, by) = r["points"]["A"]["position"], r["points"]["B"]["position"]
        assert (ax, ay) == pytest.approx((A * math.cos(phi), A * math.sin(phi)), abs=1e-15)
        assert (bx - ax, by - ay) == pytest.approx((D, 0.0), abs=1e-15)  # the coupler translates
        assert r["output"] == pytest.approx(math.atan2(by, bx - D) % (2 * math.pi), abs=1e-12) \
            or r["output"] == pytest.approx(math.atan2(by, bx - D) % (2 * math.pi) + 2 * math.pi)
        if k in (4, 10):
            assert not r["solved"] and r["errors"] == [] and r["warnings"] == []
            assert r["points"]["B"]["velocity"] is None and r["links"]["3"]["omega"] is None
            assert len(r["singular"]) == 1 and "(a change point" in r["singular"][0]
            assert r["conditioning"]["min_sine"] < 1e-12
        else:
            assert r["solved"] and r["singular"] == []
            assert r["links"]["3"]["omega"] == pytest.approx(10.0, abs=1e-9)
    code, out, _ = run(capsys, "cycle", path, "--positions", "12")
    assert code == 0
    lines = out.splitlines()

    def cells(title, k):
        table = lines[lines.index(title):]
        return dict(zip(table[1].replace("φ1 °", "φ1").split(), table[2 + k].split(), strict=True))

    x4 = cells("x of points (m)", 4)
    assert (x4["φ1"], x4["A"], x4["B"]) == ("180.00", "-0.05", "0.15")
    assert cells("|V| of points (m/s)", 4)["B"] == "—"
    assert cells("|V| of points (m/s)", 3)["B"] == "0.5"
    assert cells("x of points (m)", 1)["A"] == "0"  # R·cos(π/2) = 3.06e-18 m is rounding
    assert cells("y of points (m)", 4)["B"] == "0"
    assert "position 4: singular: group 2–3 (RRR) at φ1 = 180° (a change point" in out
    assert "position 10: singular: group 2–3 (RRR) at φ1 = 0° (a change point" in out
    assert "error" not in out
    code, out, _ = run(capsys, "cycle", path, "--positions", "12", "--csv")
    row = list(csv.DictReader(io.StringIO(out)))[4]
    assert float(row["B.x"]) == pytest.approx(0.15) and row["B.vx"] == "" and row["omega3"] == ""
    assert row["solved"] == "0" and row["errors"] == "" and "(a change point" in row["singular"]
    assert row["placed"] == "1"


def test_the_explanatory_note_names_the_change_points_in_either_language(capsys, tmp_path):
    from support import run

    path = tmp_path / "parallelogram.toml"
    path.write_text(fourbar(A, B_, A, D), "utf-8")
    code, out, _ = run(capsys, "report", path, "--lang", "ru")
    assert code == 0
    assert ("При φ1 = 180 и 0° (точки смены сборки) звенья группы лежат на одной прямой и обе "
            "её сборки совпадают") in out
    code, out, _ = run(capsys, "report", path)
    assert "At φ1 = 180 and 0°, change points, the links of a group lie on one line" in out


# --- found by review: each failed before its fix ------------------------------------------


def test_a_pin_landing_exactly_on_a_pivot_is_no_internal_error(capsys, tmp_path):
    """A kite (crank = frame) whose crank pin lands on the rocker's pivot at 0°, the first
    sample of its trajectories: the positions there are not finite, and were taken as
    standing (exit 3, 'cannot convert float NaN to integer')."""
    from support import run

    path = tmp_path / "kite.toml"
    path.write_text('trace = ["E"]\n' + fourbar(0.1, 0.2, 0.2, 0.1), "utf-8")
    code, out, err = run(capsys, "solve", path)
    assert code == 0, err
    assert "nan" not in out.lower()


def test_a_rocking_crank_flips_at_its_change_point_within_its_range():
    """Crank 0.2, coupler and rocker 0.1, frame 0.2: the crank rocks over −60°…60° with a
    change point at 0°. The flips were counted round through the angles where it does not
    close, so the positions between 0° and the file's 50° were on the other assembly."""
    mech = mech_of(fourbar(0.2, 0.1, 0.1, 0.2, angle=50.0).replace("above OD", "above AD"))
    sv = Solver(mech)
    c = analyse_cycle(mech, 12, solver=sv)
    assert not c.full_turn and sv.seam is not None
    lo, hi = c.crank_range
    assert math.degrees(lo) == pytest.approx(-60, abs=1e-9)
    assert math.degrees(hi) == pytest.approx(60, abs=1e-9)
    m = sv.solve(np.array(c.positions))
    x = m.position["B"].real
    assert np.allclose(x, x[::-1], atol=1e-12)  # symmetric about 0°, as the linkage is
    phi = np.linspace(lo + 1e-3, hi - 1e-3, 4001)
    phi = phi[np.abs(phi) > 1e-4]
    from test_stability import jumps

    assert jumps(sv.solve(phi), mech.driver.omega) < 1.05  # no step beyond its velocity


def test_an_output_at_rest_has_no_turning_points():
    """The isosceles crank-slider on its other assembly keeps its slider on the crank's
    pivot: velocities of 1e-17 that change sign had made some 1200 'turning points',
    each drawn as an extreme position."""
    mech = mech_of(crank_slider(0.1, 0.1, 0.0).replace('B = "right of O"', 'B = "left of A"'))
    c = analyse_cycle(mech)
    assert c.full_turn and c.extremes == () and c.stroke is None
    assert "the output B does not move" in c.notes


def test_an_extreme_on_a_grid_sample_is_found_exactly():
    """Crank and coupler 0.1, rocker and frame 0.2: the rocker stops at 300° exactly, a
    sample of the grid from 60°, where the two paths' rounding differs in sign."""
    c = analyse_cycle(mech_of(fourbar(0.1, 0.1, 0.2, 0.2)))
    assert on_circle([math.degrees(x) for x in c.extremes], [300.0, 60.0])
    assert math.degrees(c.theta) == pytest.approx(60.0, abs=1e-9)
    assert c.K == pytest.approx(2.0, abs=1e-12)


def test_the_diagrams_draw_rounding_as_zero_and_run_over_change_points():
    from drawing.scene import Polyline, Text
    from drawing.views import diagrams_view

    mech = parallelogram()
    sv = Solver(mech)
    view = diagrams_view(mech, analyse_cycle(mech, solver=sv), "en", solver=sv)
    texts = [it.text for it in view.items if isinstance(it, Text)]
    assert "μ_{ε} = 0.025 (rad/s²)/mm" in texts  # ε3 = 0: no scale of 5e-10 for its noise
    curves = [it for it in view.items if isinstance(it, Polyline)]
    omega = np.array(curves[1].points)[:, 1]
    assert np.ptp(omega) < 1e-9  # ω3 = ω1 all round, the change points included


def test_check_names_the_other_assembly_past_a_change_point(tmp_path):
    """At 200°, past the change point at 180°, the sign the plan is solved on is not the
    one read at 60°: the 'other assembly' hypothesis had been the exact solution again."""
    from test_check import ck, named, write_meas

    from plans import solve_position

    path = tmp_path / "parallelogram.toml"
    path.write_text(fourbar(A, B_, A, D), "utf-8")
    mech = mech_of(fourbar(A, B_, A, D))
    turned = mech.at_file_angle(200.0)
    sv = Solver(mech)
    mu = {"mu_l": 0.002, "mu_v": 0.01, "mu_a": 0.1}
    other = solve_position(turned, solver=Solver(
        turned, sigmas=(-int(sv.sigma(0, turned.driver.phi)),), flips=((),)), mu=mu)
    segs = {k: v for k, v in other.segments.items() if k[0].islower() or k[0] == "π"}
    meas = write_meas(tmp_path / "m.toml", path, segs, mu, extra="angle_deg = 200")
    got = named(ck.check(ck.load(meas)))
    assert (got.kind, got.target) == ("branch", "group 2–3 (RRR)")


def test_a_limit_is_found_on_the_side_where_the_mechanism_closes():
    """A crank-slider with L = R − e reaches the guide's normal at 0° and 180°: the range
    read 'from −2.6e−11° to 180°'."""
    from plans.note.report import no_full_turn

    mech = mech_of(crank_slider(0.1, 0.05, 0.05).replace('B = "right of O"', 'B = "right of A"'))
    sv = Solver(mech)
    c = analyse_cycle(mech, solver=sv)
    assert sv.solve(np.array(c.crank_range)).placed.all()
    assert abs(c.crank_range[0]) < 1e-13 and abs(c.crank_range[1] - math.pi) < 1e-13
    assert "from 0° to 180°, a swing of 180°" in no_full_turn(c, "en", mech.driver)


def test_a_position_stands_only_where_every_group_closes_or_misses_by_rounding():
    """placed had been valid OR any group missing by rounding: a group that misses by
    centimetres beside one in line to rounding counted as standing."""
    from dataclasses import replace

    mech = parallelogram()
    m = Solver(mech).solve(np.radians([60.0, 180.0, 200.0]))
    (g,) = m.groups
    assert list(m.placed) == [True, True, True]
    for margin, valid, want in ((-1e-15, False, True), (-0.01, False, False), (0.2, True, True)):
        fake = g._replace(valid=np.full(3, valid), margin=np.full(3, margin))
        two = replace(m, groups=(fake, g._replace(valid=np.full(3, False),
                                                  margin=np.full(3, -1e-15))),
                      valid=np.full(3, False))
        assert list(two.placed) == [want] * 3, (margin, valid)


def test_a_block_on_the_pivot_at_a_change_point_is_not_called_a_dead_point(capsys, tmp_path):
    from support import run

    path = tmp_path / "slotted.toml"
    path.write_text(slotted(0.1, 0.1), "utf-8")
    code, out, err = run(capsys, "solve", path, "--angle", "270")
    assert code == 0 and "at φ1 = 270° (a change point" in out
    assert "is on the rocker's pivot" in out and "dead point" not in out + err


def test_rounding_of_a_zero_stays_zero_at_any_scale_factor():
    """A parallelogram's coupler translates: its relative velocity ab is rounding. Plan.tiny
    is in m/s, so a plan redrawn at a scale factor 10⁴ times finer still has ab = 0 mm (in
    mm, kept from the first μ, it gave 1e-9 mm)."""
    from plans import solve_position

    plan = solve_position(parallelogram(), math.radians(200.0)).velocity
    assert plan.mm("a", "b") == 0.0
    fine = plan._replace(mu=plan.mu / 1e4)
    assert fine.mm("a", "b") == 0.0 and fine.mm("p", "b") == pytest.approx(plan.mm("p", "b") * 1e4)


def test_the_cycle_table_rounds_epsilon_as_solve_does(capsys, tmp_path):
    """The isosceles crank-slider's rod turns at −ω1 throughout: its ε2 is rounding at
    every position, the largest of its own column; solve printed 0 and cycle 1e-13."""
    from support import run

    path = tmp_path / "iso.toml"
    path.write_text(crank_slider(0.1, 0.1, 0.0).replace('B = "right of O"', 'B = "right of A"'),
                    "utf-8")
    _, out, _ = run(capsys, "cycle", path, "--positions", "8")
    table = out.split("ω (rad/s) and ε (rad/s²) of links")[1].split("\n\n")[0]
    rows = [r.split() for r in table.splitlines()[2:] if r.strip()]
    assert rows and all(r[6] in ("0", "—") for r in rows), table  # ε2


def test_check_keeps_small_true_values_and_zeroes_only_rounding():
    """A crank at 1e-4 rad/s gives ε3 of 5e-10 rad/s²: a real value, which an absolute
    1e-9 floor had made 0 (and the student's right answer BEYOND). Only what is rounding
    relative to the plan, as the plan's own segments are, is 0."""
    from plans import solve_position
    from plans.check import verdict as ck
    from plans.check.measured import Item, Tolerance
    from plans.check.replay import expected, simulate

    item = Item("values.eps3", "ε3", "epsilon", "acceleration", 5.17e-10, link=3)
    d = ck.compare(item, 5.17e-10, Tolerance(5.0, 1.0))
    assert d.computed == 5.17e-10 and d.ok and d.percent == 0.0
    sol = solve_position(parallelogram(), math.radians(200.0))
    st = simulate(sol, None)
    ab = Item("segments.ab", "ab", "segment", "velocity", 0.0, "a", "b")
    pb = Item("segments.pb", "pb", "segment", "velocity", 0.0, "p", "b")
    assert expected(ab, st, sol.mu) == 0.0  # the coupler translates: rounding is 0
    assert expected(pb, st, sol.mu) == pytest.approx(sol.segments["pb"])


@pytest.mark.parametrize("given", [0.0, 180.0])
@pytest.mark.parametrize(("sense", "hint", "kind"), [
    ("ccw", "above OD", "parallelogram"), ("ccw", "below OD", "anti"),
    ("cw", "above OD", "anti"), ("cw", "below OD", "parallelogram"),
])
def test_hints_given_on_a_change_point_are_read_just_past_it(given, sense, hint, kind):
    """At 0° and 180° a parallelogram's two assemblies meet, so "above OD" names neither:
    the hint had been read on rounding, or failed as a dead point. It is read just past
    the angle the way the crank turns: counter-clockwise from 0° the parallelogram has B
    above OD, clockwise below. At 180° the sides are the other way round."""
    mech = mech_of(fourbar(A, B_, A, D, angle=given).replace(
        'B = "above OD"', f'B = "{hint}"').replace("omega = 10.0", f'omega = 10.0\nsense = "{sense}"'))
    assert (mech.driver.omega > 0) == (sense == "ccw")
    sv = Solver(mech)
    if given == 180.0:
        kind = {"parallelogram": "anti", "anti": "parallelogram"}[kind]
    assert on_circle(angles(sv), [0.0, 180.0])
    m = sv.solve(away([0.0, math.pi], n=721))
    assert m.valid.all()
    coupler = m.position["B"] - m.position["A"]
    if kind == "parallelogram":
        assert np.abs(coupler - D).max() < 1e-12  # B − A = D − O all round
    else:  # the other assembly: away from the change points never a parallelogram
        assert np.abs(coupler - D).max() > 0.05
        assert (np.abs(coupler - D) > 1e-5).all()


def test_a_cycle_from_a_change_point_starts_with_a_singular_row(capsys, tmp_path):
    from support import run

    path = tmp_path / "parallelogram.toml"
    path.write_text(fourbar(A, B_, A, D, angle=0.0), "utf-8")
    code, out, err = run(capsys, "cycle", path, "--positions", "4")
    assert code == 0, err
    assert "position 0: singular: group 2–3 (RRR) at φ1 = 0° (a change point" in out
    assert "position 2: singular: group 2–3 (RRR) at φ1 = 180° (a change point" in out
    code, out, err = run(capsys, "solve", path)
    assert code == 0 and err == ""
    assert out.strip().splitlines()[-1] == (
        "The velocity and acceleration plans are not built: group 2–3 (RRR) at φ1 = 0° (a change "
        "point: the two assemblies of a group meet there): A, B and D are in line (links 2 and 3 "
        "stretched out or folded): a singular position, the plan has no unique solution")
    code, out, err = run(capsys, "sheet", path, "--plans", "1", "-o", tmp_path / "s.svg")
    assert code == 2 and not (tmp_path / "s.svg").exists()
    assert err.strip().endswith("(the sheet solves the given position for its scale even with "
                                "--plans: choose another with --angle)")
    code, out, err = run(capsys, "sheet", path, "-o", tmp_path / "s.svg")
    assert code == 2 and not (tmp_path / "s.svg").exists()
    assert err.strip().endswith("(the sheet draws the given position: choose another with --angle)")
    code, out, err = run(capsys, "sheet", path, "--angle", "30", "-o", tmp_path / "s.svg")
    assert code == 0, err


def test_a_crank_given_at_a_limit_of_its_range_rocks_between_its_two_limits():
    """b + c = |BD| at 90°: the crank rocks between −90° and 90°, its limits, and the given
    angle is one of them. The hint is read just inside the range, and the cycle spans it;
    before, the cycle failed there as a dead point. "Above AD" and "below AD" give the
    two assemblies, each on one side of AD all through."""
    a, d = 0.05, 0.2
    b = 0.15
    c = math.hypot(a, d) - b
    sides = []
    for hint in ("above AD", "below AD"):
        mech = mech_of(fourbar(a, b, c, d, angle=90.0).replace('"above OD"', f'"{hint}"'))
        sv = Solver(mech)
        cyc = analyse_cycle(mech, n_positions=6, solver=sv)
        assert not cyc.full_turn
        assert sorted(math.degrees(x) for x in cyc.extremes) == pytest.approx([-90.0, 90.0],
                                                                             abs=1e-9)
        m = sv.solve(cyc.positions)
        assert m.valid.all()
        A_, B = m.position["A"], m.position["B"]
        assert np.abs(np.abs(B - A_) - b).max() < 1e-12
        assert np.abs(np.abs(B - D) - c).max() < 1e-12
        side = np.sign(((D - A_).conjugate() * (B - A_)).imag)  # + : B left of A→D
        assert len(set(side.tolist())) == 1
        sides.append(side[0])
    assert sides == [1.0, -1.0]
    from plans.errors import InputError

    with pytest.raises(InputError) as exc:  # B is above OD on both, either side of the limit
        Solver(mech_of(fourbar(a, b, c, d, angle=90.0)))
    assert "'above OD' fits both assemblies of group 2–3 (RRR) at φ1 = 89.9943°" in str(exc.value)
    assert str(exc.value).endswith(
        "(read 0.0001 rad past φ1 = 90°, where the two assemblies of group 2–3 (RRR) meet)")


def tilted_parallelogram(angle=60.0):
    """The parallelogram with its frame OD turned 30° up: its change points, 30° and 210°,
    are where rounding leaves the lines' sine at 3e-8 rather than under 1e-10."""
    d = D * np.exp(1j * math.radians(30.0))
    return fourbar(A, B_, A, D, angle=angle).replace(
        f"D = [{D!r}, 0.0]", f"D = [{float(d.real)!r}, {float(d.imag)!r}]").replace(
        'B = "above OD"', 'B = "left of OD"')


def test_no_solved_row_beside_a_change_point_carries_lost_digits(capsys, tmp_path):
    """At 30° the tilted parallelogram's lines met at sin = 3e-8, above the 1e-10 of a
    singular plan: the cycle printed |a_B| = 2.3e8 m/s² (truly 5) as a warning, while
    solve refused the angle. Beside a change point the acceleration plan loses 7·κ³·ε,
    so there a sine under CHANGE_SINE is singular as well: every row still solved is
    right to 1e-5 (ω3 = ω1 = 10, ε = 0, |a_B| = ω1²·a = 5), every other gives positions."""
    import json

    from support import run

    path = tmp_path / "tilted.toml"
    path.write_text(tilted_parallelogram(), "utf-8")
    code, out, err = run(capsys, "cycle", path, "--positions", "12", "--json")
    assert code == 0, err
    rows = json.loads(out)["rows"]
    assert [r["index"] for r in rows if not r["solved"]] == [5, 11]  # 210° and 30°
    assert all(r["placed"] and r["errors"] == [] for r in rows)
    code, out, err = run(capsys, "cycle", path, "--positions", "7200", "--json")
    assert code == 0, err
    rows = json.loads(out)["rows"]
    solved = [r for r in rows if r["solved"]]
    assert 7190 <= len(solved) < 7200  # a sample or two each side of each change point
    for r in solved:
        assert abs(r["links"]["3"]["omega"] - 10.0) < 1e-5
        assert abs(r["links"]["3"]["epsilon"]) < 1e-5 * 100 and abs(r["links"]["2"]["epsilon"]) < 1e-3
        assert abs(math.hypot(*r["points"]["B"]["acceleration"]) - 5.0) < 5e-5
    for r in rows:
        if not r["solved"]:
            assert r["conditioning"]["min_sine"] < 1e-3 and r["singular"]
    for cmd in (("solve", path, "--angle", "30"), ("sheet", path, "--plans", "11", "-o",
                                                   tmp_path / "t.svg")):
        code, out, err = run(capsys, *cmd)
        said = err if cmd[0] == "sheet" else out  # solve gives the positions, exit 0
        assert code == (2 if cmd[0] == "sheet" else 0), err
        assert "group 2–3 (RRR) at φ1 = 30° (a change point" in said, err
        assert "dead point" not in said and ": a singular position, the plan" in said
        assert len([line for line in said.strip().splitlines() if "change point" in line]) == 1


@pytest.mark.parametrize("angle", ["359.9999999", "1e-7", "180.0000001"])
def test_a_row_within_rounding_of_a_change_point_is_no_dead_point(capsys, tmp_path, angle):
    """1e-7° from a change point the links lie in line to rounding: those rows were errors
    (exit 2) called dead points, under a summary that names the change points."""
    from support import run

    path = tmp_path / "parallelogram.toml"
    path.write_text(fourbar(A, B_, A, D), "utf-8")
    code, out, err = run(capsys, "cycle", path, "--positions", "12", "--angle", angle)
    assert code == 0, err
    assert "dead point" not in out + err and "error" not in out
    assert out.count("singular: group 2–3 (RRR) at φ1 = ") == 2
    assert "(beside the change point at φ1 = 0°" in out + err or (angle == "1e-7" and \
        "(beside the change point at φ1 = 0°" in out)


def test_a_slotted_link_given_on_its_change_point_turns_on_from_there(capsys, tmp_path):
    """The slotted link whose pivot is on the crank circle, given at 270° where the block
    is on the pivot: its smooth motion takes two turns, and its two turns meet at the
    given angle. Read 1e-4 rad on, the hints had moved that seam there too: row 0 was on
    the other turn, and the rocker jumped 165° between rows 0 and 1."""
    import json

    from support import run

    path = tmp_path / "slotted.toml"
    path.write_text(slotted(0.1, 0.1, angle=270.0), "utf-8")
    code, out, err = run(capsys, "cycle", path, "--positions", "12", "--json")
    assert code == 0, err
    rows = json.loads(out)["rows"]
    assert rows[0]["singular"] and rows[0]["placed"]
    psi = [math.degrees(r["output"]) for r in rows]
    assert np.diff(psi) == pytest.approx([15.0] * 11, abs=1e-9)  # ω3 = ω1 / 2 all round
    C = [complex(*rows[k]["points"]["C"]["position"]) for k in (0, 1)]
    assert abs(C[1] - C[0]) < 0.14  # 15° of a 0.5 m rocker is 0.13 m, not a jump
    sv = Solver(mech_of(slotted(0.1, 0.1, angle=270.0)))
    after, before = (complex(sv.solve_one(math.radians(a)).position["C"]) for a in (270.001, 269.999))
    assert after.real == pytest.approx(0.5, abs=1e-6) and before.real == pytest.approx(-0.5, abs=1e-6)


def test_a_hint_met_only_by_rounding_picks_no_assembly():
    """The kite a = b given at 180°: read just past it, one assembly has B on OD (to
    2.8e-13 m), where the crank and coupler fold onto the frame and the rocker stays. "Above
    OD" had picked it by the sign of rounding: 'the output B does not move'. It names the
    other, which swings the rocker 120° with K = 2."""
    from plans.model import hint_holds

    c = analyse_cycle(mech_of(fourbar(0.1, 0.1, 0.2, 0.2, angle=180.0)))
    assert c.K == pytest.approx(2.0, abs=1e-9)
    assert "the output B does not move" not in c.notes
    assert not hint_holds("above", complex(-1e-17, 2.8e-13), [0j, 0.2 + 0j])
    assert not hint_holds("below", complex(-1e-17, -2.8e-13), [0j, 0.2 + 0j])
    assert hint_holds("above", complex(0.1, 1e-6), [0j, 0.2 + 0j])
    assert not hint_holds("right of", complex(1e-18, 0.3), [0j])
    assert hint_holds("right of", complex(1e-9, 0.3), [0j])


def test_the_cycle_table_prints_a_stroke_position_that_is_rounding_as_0(capsys, tmp_path):
    """The isosceles crank-slider from 30°: s_B = 2R·cos φ is 0 at 90° and 270°, which the
    table printed as −2.505e-15 and 2.518e-15 m."""
    from support import run

    path = tmp_path / "isosceles.toml"
    path.write_text(crank_slider(0.1, 0.1, 0.0, angle=30.0).replace(
        'B = "right of O"', 'B = "right of A"'), "utf-8")
    code, out, err = run(capsys, "cycle", path, "--positions", "12")
    assert code == 0, err
    lines = out.splitlines()
    table = lines[lines.index("Conditioning (sine of the angle between the intersected lines)") + 2:][:12]
    s = [row.split()[2] for row in table]
    assert s == ["-0.2", "-0.1732", "-0.1", "0", "0.1", "0.1732", "0.2", "0.1732", "0.1", "0",
                 "-0.1", "-0.1732"]


def test_the_diagrams_run_over_a_block_passing_the_rockers_pivot():
    """The slotted link whose pivot is on the crank circle turns at ω1/2 with ε = 0 all
    round. Its block passes the pivot at 270°, where the lines' sine stays 1: the diagrams
    had trusted that sample (they read only the sine) and drew ε up to 4e16 rad/s², at
    μ_ε = 4e15. They skip what Solver.trusted refuses, as solve and cycle do."""
    from drawing.scene import Polyline, Text
    from drawing.views import diagrams_view

    mech = mech_of(slotted(0.1, 0.1, angle=300.0))
    sv = Solver(mech)
    view = diagrams_view(mech, analyse_cycle(mech, solver=sv), "en", solver=sv)
    texts = [it.text for it in view.items if isinstance(it, Text)]
    assert "μ_{ε} = 0.025 (rad/s²)/mm" in texts
    curves = [np.array(it.points)[:, 1] for it in view.items if isinstance(it, Polyline)]
    assert np.ptp(curves[1]) < 1e-9 and np.ptp(curves[2]) < 1e-9  # ω3 = 4, ε3 = 0
    phi = np.radians([270.0, 270.1, 271.0, 300.0])
    m = sv.solve(phi)
    assert sv.trusted(m).tolist() == [False, True, True, True]  # pivot figure 8.7e-4 at 270.1°
    pm = Solver(parallelogram())
    near = np.radians([0.0, 0.01, 0.1, 90.0])  # sine 0, 1.7e-4, 1.7e-3, 1
    assert pm.trusted(pm.solve(near)).tolist() == [False, False, True, True]


def test_a_block_exactly_on_the_pivot_at_the_given_angle_is_a_singular_row(capsys, tmp_path):
    """The pivot B on the crank circle at (R, 0), the file given at 0°: the block is
    exactly on the pivot, and 0/0 left the rocker nowhere. Row 0 was an error (exit 2,
    every value blank, the crank pin's too), where given at 90° the same 0° row was
    singular with its positions; and the CSV's header, made from row 0, had no pivot
    column, so every later column of rows 1–7 stood one to the right (ψ read as O.x)."""
    import csv
    import io
    import json

    from support import run

    text = (slotted(0.1, 0.1, angle=0.0).replace("B = [0.0, -0.1]", "B = [0.1, 0.0]")
            .replace("C = 0.5, S3 = [0.25, 0.01]", "C = 0.35"))
    path = tmp_path / "slotted.toml"
    path.write_text(text, "utf-8")
    code, out, err = run(capsys, "cycle", path, "--positions", "8", "--json")
    assert code == 0, err
    rows = json.loads(out)["rows"]
    assert rows[0]["singular"] and rows[0]["placed"] and not rows[0]["errors"]
    assert all(r["solved"] for r in rows[1:])
    psi = [math.degrees(r["output"]) for r in rows]
    assert psi[0] == pytest.approx(90.0, abs=1e-6)  # where the turn from 0° goes on
    assert np.diff(psi) == pytest.approx([22.5] * 7, abs=1e-6)  # ω3 = ω1 / 2 all round
    C0 = complex(*rows[0]["points"]["C"]["position"])
    assert abs(C0 - complex(0.1, 0.35)) < 1e-8
    assert rows[0]["points"]["A"]["position"] == [0.1, 0.0]  # exact, not moved on
    code, out, err = run(capsys, "cycle", path, "--positions", "8", "--csv")
    assert code == 0, err
    table = list(csv.reader(io.StringIO(out)))
    head = table[0]
    assert {len(r) for r in table} == {len(head)}
    assert "group 2–3 (RPR) pivot" in head
    got = [float(r[head.index("output C (rad)")]) for r in table[1:]]
    assert got == pytest.approx([r["output"] for r in rows], abs=1e-12)
    assert float(table[2][head.index("O.x")]) == 0.0


@pytest.mark.parametrize(("angle", "sense", "hint", "parallel"), [
    (359.9999, "ccw", "below OD", True), (0.0001, "cw", "above OD", True),
    (359.9999, "ccw", "above OD", False), (0.0001, "cw", "below OD", False),
])
def test_a_hint_that_parts_the_assemblies_at_the_given_angle_is_read_there(
        angle, sense, hint, parallel):
    """A parallelogram given 1.7e-6 rad short of its change point at 0°: its coupler end B
    is 1.7e-7 m below OD, the other assembly's 3.5e-7 m above, and the hint parts them.
    Its margin is within rounding of 0, so the hint was read 1e-4 rad on, past the change
    point, where "below OD" names the other assembly: the file's parallelogram became an
    antiparallelogram at the very angle it was given for."""
    text = (fourbar(A, B_, A, D, angle=angle).replace('"above OD"', f'"{hint}"')
            .replace("omega = 10.0", f'omega = 10.0\nsense = "{sense}"'))
    mech = mech_of(text)
    m = Solver(mech).solve(mech.driver.phi + np.radians(np.arange(0.0, 360.0, 15.0)))
    B, Ap = m.position["B"], m.position["A"]
    assert (B[0].imag < 0) == (hint == "below OD")  # the hint holds at the given angle
    if parallel:  # to 1.6·κ·ε, κ = 1/sin ≈ 6e5 at the given angle
        assert np.abs(B - Ap - D).max() < 1e-9
    else:
        assert np.abs(B - Ap - D).max() > 0.05


def test_a_sweep_says_where_its_plans_can_be_trusted_as_a_motion_does():
    """``Sweep.valid`` is True beside a change point, where the accelerations lose their
    digits (ε off by 4e-3 at 0.001° from the isosceles crank-slider's): ``Solver.trusted``
    takes a sweep as it takes a motion, its pivot figure included."""
    R = 0.1
    phi = np.radians(np.linspace(0.0, 360.0, 36001))
    for mech in (isosceles(R), mech_of(slotted(R, R)), parallelogram()):
        sv = Solver(mech)
        sw = sv.sweep(phi)
        assert (sv.trusted(sw) == sv.trusted(sv.solve(phi))).all()
        assert 0 < (sw.valid & ~sv.trusted(sw)).sum() < 60  # beside the change points only
    sv = Solver(isosceles(R))
    sw = sv.sweep(phi)
    ok = sv.trusted(sw)
    w = sv.mech.driver.omega
    exact = -2 * R * w * w * np.cos(phi)  # x_B = 2R cos φ
    err = np.abs(sw.acceleration["B"].real - exact) / (2 * R * w * w)
    assert err[ok].max() < 1e-5
