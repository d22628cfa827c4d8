"""Inputs beyond a uniformly turning crank (issue 24), against references built apart from
the plans: the positions in closed form, differentiated in time by mpmath at 30 digits
(mpmath.diff), never by the plans' own construction.

* a four-bar whose crank accelerates (ε1 ≠ 0), and superposition as a cross-check;
* a tangent mechanism driven by its slider, and a rocker driven by a piston;
* seed 003's crank-rocker whose rocker support slides along the frame (two inputs):
  frozen, it is seed 001's four-bar; moving by l4(t), it is the closed form's;
* the transmission angle against closed forms.
"""

from __future__ import annotations

import json
import math
import tomllib

import mpmath as mp
import pytest

from plans.cycle import analyse_cycle
from plans.cycle.transmission import transmission
from plans.kinematics.solver import Solver
from plans.kinematics.transmission import gammas
from plans.model import from_dict, load
from plans.plan.solution import solve_position

mp.mp.dps = 30
TOL = 1e-12


def mech_of(text: str):
    return from_dict(tomllib.loads(text))


def close(got: complex, want, scale: float) -> bool:
    """``got`` (a complex number) within TOL of ``want`` (an mpmath pair or complex), in
    units of ``scale``."""
    w = complex(want) if not isinstance(want, tuple) else complex(float(want[0]), float(want[1]))
    return abs(complex(got) - w) <= TOL * scale


def circles(c1, r1, c2, r2, left: bool):
    """The meeting point of the circles (c1, r1), (c2, r2) (mpmath complex), on the left of
    c1 → c2 (or on its right)."""
    d = c2 - c1
    L = abs(d)
    a = (r1 * r1 - r2 * r2 + L * L) / (2 * L)
    h = mp.sqrt(r1 * r1 - a * a)
    u = d / L
    return c1 + a * u + (1 if left else -1) * h * 1j * u


def derivs(f, t0=0):
    """f(t0), f′(t0), f″(t0) of a complex-valued function of time, at 30 digits."""
    return f(mp.mpf(t0)), mp.diff(f, t0, 1), mp.diff(f, t0, 2)


def arg_rates(f, t0=0):
    """The angle of the vector f(t) and its first two derivatives."""
    return derivs(lambda t: mp.arg(f(t)), t0)


# ---------------------------------------------------------------------------------------
# ε1 ≠ 0
# ---------------------------------------------------------------------------------------

FOURBAR = """
name = "four-bar, accelerating crank"
[frame]
O = [0.0, 0.0]
D = [0.2, 0.0]
[driver]
link = 1
angle_deg = {phi}
omega = 10
sense = "cw"
{eps}
[links.1]
axis = ["O", "A"]
points = {{ A = 0.05 }}
[links.2]
axis = ["A", "B"]
points = {{ B = 0.2, E = [0.1, 0.06] }}
[links.3]
axis = ["D", "B"]
points = {{ B = 0.15 }}
[assembly]
B = "above OD"
"""


def _fourbar_ref(phi_deg: float, w: float, e: float):
    phi0 = mp.radians(phi_deg)
    pivot, D = mp.mpc(0, 0), mp.mpc(0.2, 0)

    def A(t):
        return pivot + mp.mpf("0.05") * mp.expjpi((phi0 + w * t + e * t * t / 2) / mp.pi)

    def B(t):
        return circles(A(t), mp.mpf("0.2"), D, mp.mpf("0.15"), left=True)

    def E(t):
        a, b = A(t), B(t)
        u = (b - a) / abs(b - a)
        return a + u * mp.mpc(0.1, 0.06)

    return {"A": derivs(A), "B": derivs(B), "E": derivs(E),
            2: arg_rates(lambda t: B(t) - A(t)), 3: arg_rates(lambda t: B(t) - D)}


@pytest.mark.parametrize("phi", [0.0, 60.0, 137.0, 250.0, 333.0])
def test_an_accelerating_crank_agrees_with_the_differentiated_closed_form(phi):
    """ω1 = 10 rad/s and ε1 = 30 rad/s², both clockwise: every point's velocity and
    acceleration and every link's ω and ε as the closed form's time derivatives."""
    mech = mech_of(FOURBAR.format(phi=phi, eps='epsilon = 30\nepsilon_sense = "cw"'))
    assert mech.driver.epsilon == -30.0
    m = solve_position(mech).scalar
    ref = _fourbar_ref(phi, -10.0, -30.0)
    for p in ("A", "B", "E"):
        x, v, a = ref[p]
        assert close(m.position[p], x, 0.2), p
        assert close(m.velocity[p], v, 1.0), p
        assert close(m.acceleration[p], a, 10.0), p
    for i in (2, 3):
        _, w, e = ref[i]
        assert abs(m.links[i].omega - float(w)) <= TOL * 10, i
        assert abs(m.links[i].epsilon - float(e)) <= TOL * 100, i
    assert abs(m.links[1].epsilon + 30.0) <= TOL


def test_an_accelerating_crank_is_the_uniform_one_plus_its_velocities_times_eps_over_omega():
    """a(ε1) = a(0) + (ε1/ω1)·V for a mechanism with one input: superposition."""
    for phi in (20.0, 200.0):
        acc = solve_position(mech_of(FOURBAR.format(phi=phi, eps="epsilon = 30"))).scalar
        uni = solve_position(mech_of(FOURBAR.format(phi=phi, eps=""))).scalar
        k = -30.0 / -10.0  # ε in the sense of ω (cw): −30 rad/s² over −10 rad/s
        for p in ("A", "B", "E"):
            want = uni.acceleration[p] + k * uni.velocity[p]
            assert abs(acc.acceleration[p] - want) <= TOL * 10, p
        for i in (2, 3):
            assert abs(acc.links[i].epsilon - (uni.links[i].epsilon + k * uni.links[i].omega)) <= TOL * 100


def test_a_uniform_cranks_plan_has_no_tangential_component_and_an_accelerating_one_has():
    uni = solve_position(mech_of(FOURBAR.format(phi=60, eps="")))
    acc = solve_position(mech_of(FOURBAR.format(phi=60, eps="epsilon = 30")))
    assert abs(acc.scalar.acceleration["A"] - uni.scalar.acceleration["A"]) == pytest.approx(30 * 0.05)


# ---------------------------------------------------------------------------------------
# a slider as the input
# ---------------------------------------------------------------------------------------

TANGENT = """
name = "tangent mechanism driven by its slider"
[frame]
O = [0.0, 0.0]
[driver]
link = 3
position = 0.1
velocity = 0.5
acceleration = -2.0
[links.1]
axis = ["O", "A"]
points = { A = 0.1 }
[links.2]
points = { C = 0 }
[links.3]
points = { C = 0, M = [0.05, 0.02] }
[[sliders]]
link = 2
guide = { link = 1 }
[[sliders]]
link = 3
guide = { link = 0, through = [0.2, 0.0], angle_deg = 90 }
"""


def test_a_tangent_mechanism_driven_by_its_slider_with_a_deceleration():
    """y_C(t) = 0.1 + 0.5·t − t²: link 1 turns by φ = atan(y_C / 0.2)."""
    m = solve_position(mech_of(TANGENT)).scalar

    def y(t):
        return mp.mpf("0.1") + mp.mpf("0.5") * t - t * t

    def A(t):
        return mp.mpf("0.1") * mp.expjpi(mp.atan2(y(t), mp.mpf("0.2")) / mp.pi)

    for p, f in (("A", A), ("C", lambda t: mp.mpc(0.2, y(t)))):
        x, v, a = derivs(f)
        assert close(m.position[p], x, 0.2), p
        assert close(m.velocity[p], v, 1.0), p
        assert close(m.acceleration[p], a, 10.0), p
    _, w, e = arg_rates(A)
    assert abs(m.links[1].omega - float(w)) <= TOL * 10
    assert abs(m.links[1].epsilon - float(e)) <= TOL * 100


PISTON_ROCKER = """
name = "rocker driven by a piston"
[frame]
O = [0.0, 0.0]
D = [0.25, 0.05]
[driver]
link = 1
position = 0.05
velocity = -0.4
acceleration = 1.5
[links.1]
points = { B = 0 }
[links.2]
axis = ["B", "C"]
points = { C = 0.2 }
[links.3]
axis = ["D", "C"]
points = { C = 0.15 }
[[sliders]]
link = 1
guide = { link = 0, through = "O", angle_deg = 0 }
[assembly]
C = "above BD"
"""


def test_a_rocker_driven_by_a_piston_agrees_with_the_closed_form():
    mech = mech_of(PISTON_ROCKER)
    m = solve_position(mech).scalar

    def B(t):
        return mp.mpc(mp.mpf("0.05") - mp.mpf("0.4") * t + mp.mpf("0.75") * t * t, 0)

    D = mp.mpc(0.25, 0.05)
    x0 = solve_position(mech).scalar.position["C"]
    left = float(mp.im(circles(B(0), mp.mpf("0.2"), D, mp.mpf("0.15"), True))) == pytest.approx(x0.imag)

    def C(t):
        return circles(B(t), mp.mpf("0.2"), D, mp.mpf("0.15"), left)

    x, v, a = derivs(C)
    assert close(m.position["C"], x, 0.2)
    assert close(m.velocity["C"], v, 1.0)
    assert close(m.acceleration["C"], a, 10.0)
    _, w, e = arg_rates(lambda t: C(t) - D)
    assert abs(m.links[3].omega - float(w)) <= TOL * 10
    assert abs(m.links[3].epsilon - float(e)) <= TOL * 100


# ---------------------------------------------------------------------------------------
# two inputs: seed 003
# ---------------------------------------------------------------------------------------

SAMPLE = "samples/moving_support.toml"


def _sample() -> str:
    with open(SAMPLE, encoding="utf-8") as f:
        return f.read()


def test_the_sample_reads_as_two_inputs_and_w_2():
    mech = load(SAMPLE)
    assert len(mech.drivers) == 2
    sol = solve_position(mech)
    assert sol.structure.W == 2 and sol.structure.drivers == (1, 4)


def test_a_frozen_support_is_seed_001s_four_bar():
    """l4′ = l4″ = 0: V_C, ω3, a_C as the one-input engine gives them for samples/fourbar.toml."""
    text = _sample()
    assert "amplitude = 0.01," in text
    frozen = mech_of(text.replace("amplitude = 0.01,", "amplitude = 0.0,"))
    one = solve_position(load("samples/fourbar.toml")).scalar
    two = solve_position(frozen).scalar
    w1 = one.links[1].omega
    assert two.links[1].omega == pytest.approx(w1, abs=0)
    for p in ("B", "C"):
        assert abs(two.position[p] - one.position[p]) <= 1e-15, p
        assert abs(two.velocity[p] - one.velocity[p]) <= TOL, p
        assert abs(two.acceleration[p] - one.acceleration[p]) <= TOL * 10, p
    assert abs(two.links[3].omega - one.links[3].omega) <= TOL
    assert abs(two.links[3].epsilon - one.links[3].epsilon) <= TOL * 10


@pytest.mark.parametrize("time", [0.0, 0.013, 0.31])
def test_a_moving_support_agrees_with_seed_003s_closed_form_at_30_digits(time):
    """l4(t) = 0.135 + 0.01·sin(ω1·t), φ1 = 40° + ω1·t: B, C by seed 003's closed-form
    positions (the triangle B, C, D on S = |BD|), differentiated by mpmath."""
    mech = load(SAMPLE) if time == 0.0 else mech_of(_moving_time(time))
    m = solve_position(mech).scalar
    w1 = mp.mpf(mech.drivers[0].law.rate)
    om = mp.mpf(mech.drivers[1].law.omega)  # 2π/period: ω1 to rounding
    assert abs(om - w1) <= 1e-14 * w1
    phi0 = mp.radians(40)
    l1, l2, l3 = mp.mpf("0.0625"), mp.mpf("0.21"), mp.mpf("0.1025")

    def l4(t):
        return mp.mpf("0.135") + mp.mpf("0.01") * mp.sin(om * t)

    def B(t):
        return l1 * mp.expjpi((phi0 + w1 * t) / mp.pi)

    def D(t):
        return mp.mpc(-l4(t), 0)

    def C(t):
        # seed 003: S = |BD|, the angle at D between DB and DC from the cosine rule; C
        # above BD
        b, d = B(t), D(t)
        s = abs(b - d)
        psi = mp.acos((s * s + l3 * l3 - l2 * l2) / (2 * l3 * s))
        return d + l3 * (b - d) / s * mp.expjpi(psi / mp.pi)

    t0 = mp.mpf(time)
    for p, f in (("B", B), ("C", C), ("D", D)):
        x, v, a = f(t0), mp.diff(f, t0, 1), mp.diff(f, t0, 2)
        assert close(m.position[p], x, 0.2), p
        assert close(m.velocity[p], v, 1.0), p
        assert close(m.acceleration[p], a, 100.0), p
    for i, f in ((2, lambda t: C(t) - B(t)), (3, lambda t: C(t) - D(t))):
        def ang(t, f=f):
            return mp.arg(f(t))
        assert abs(m.links[i].omega - float(mp.diff(ang, t0, 1))) <= TOL * 10, i
        assert abs(m.links[i].epsilon - float(mp.diff(ang, t0, 2))) <= TOL * 1000, i


def _moving_time(time: float) -> str:
    return _sample().replace("time = 0.0", f"time = {time!r}")


# ---------------------------------------------------------------------------------------
# the transmission angle
# ---------------------------------------------------------------------------------------

CRANK_ROCKER = FOURBAR.format(phi=60, eps="")


def test_a_crank_rockers_gamma_at_a_position_and_its_least_at_the_crank_in_line_with_the_frame():
    a, b, c, d = 0.05, 0.2, 0.15, 0.2
    mech = mech_of(CRANK_ROCKER)
    for phi in (0.0, 1.0, 2.5, 4.0):
        m = solve_position(mech, phi).scalar
        bd2 = a * a + d * d - 2 * a * d * math.cos(phi)
        g = math.acos((b * b + c * c - bd2) / (2 * b * c))
        want = min(g, math.pi - g)
        assert abs(gammas(m)["group 2–3 (RRR)"] - want) <= 1e-12, phi
    solver = Solver(mech)
    tr = transmission(solver, analyse_cycle(mech, solver=solver))
    (g,) = tr.groups
    # γmin at φ1 = 0 (crank along OD): cos γ = (b² + c² − (d − a)²)/(2bc)
    want = math.acos((b * b + c * c - (d - a) ** 2) / (2 * b * c))
    assert abs(g.gamma_min - want) <= 1e-12
    assert abs(math.remainder(g.at, 2 * math.pi)) <= 1e-6
    assert g.dead == () and g.change == ()


OFFSET = """
name = "offset crank-slider"
[frame]
O = [0.0, 0.0]
[driver]
link = 1
angle_deg = 30
omega = 15
sense = "cw"
[links.1]
axis = ["O", "A"]
points = { A = 0.1 }
[links.2]
axis = ["A", "B"]
points = { B = 0.4 }
[links.3]
points = { B = 0 }
[[sliders]]
link = 3
guide = { link = 0, through = [0.0, 0.05], angle_deg = 0 }
[assembly]
B = "right of O"
"""


def test_an_offset_crank_sliders_largest_pressure_angle_is_at_the_crank_across_the_guide():
    """sin α = (r + e)/l with the crank ⊥ the guide on the side away from the offset;
    γ = 90° − α, between the rod and the guide's normal."""
    r, rod, e = 0.1, 0.4, 0.05
    mech = mech_of(OFFSET)
    for phi in (0.3, 2.0, 4.0):
        m = solve_position(mech, phi).scalar
        alpha = math.asin(abs(r * math.sin(phi) - e) / rod)
        assert abs(gammas(m)["group 2–3 (RRP)"] - (math.pi / 2 - alpha)) <= 1e-12
    solver = Solver(mech)
    (g,) = transmission(solver, analyse_cycle(mech, solver=solver)).groups
    assert abs(g.pressure_max - math.asin((r + e) / rod)) <= 1e-12
    assert abs(math.remainder(g.at + math.pi / 2, 2 * math.pi)) <= 1e-6


def test_a_double_rockers_limits_are_its_dead_points():
    """seed 001's four-bar (not Grashof): at the limits of its crank range the coupler and
    the rocker lie in line, γ = 0."""
    mech = load("samples/fourbar.toml")
    solver = Solver(mech)
    cyc = analyse_cycle(mech, solver=solver)
    (g,) = transmission(solver, cyc).groups
    assert g.gamma_min == 0.0
    assert sorted(g.dead) == pytest.approx(sorted(cyc.crank_range), abs=1e-12)


def test_gamma_is_in_solve_and_cycle(capsys):
    from support import run

    code, out, _ = run(capsys, "solve", "samples/fourbar.toml")
    assert code == 0 and "pressure angle α = 90° − γ" in out
    code, out, _ = run(capsys, "cycle", "samples/fourbar.toml", "--csv")
    assert code == 0 and "gamma_deg group 2–3 (RRR)" in out.splitlines()[0]


def _grashof_support() -> str:
    """The sample with seed 003's conditions holding: l1 = 0.05, l2 = 0.2, l3 = 0.15, the
    support 0.2 ± 0.01 m from A, the cycle over the laws' whole period."""
    text = _sample()
    for old, new in (("points = { B = 0.0625 }", "points = { B = 0.05 }"),
                     ("points = { C = 0.21 }", "points = { C = 0.2 }"),
                     ("points = { C = 0.1025 }", "points = { C = 0.15 }"),
                     ("through = [-0.135, 0.0]", "through = [-0.2, 0.0]"),
                     ("span = [0.216, 0.51]\n", "")):
        assert text.count(old) == 1, old
        text = text.replace(old, new)
    return text


def test_seed_003s_crank_existence_conditions_over_the_supports_range(capsys, tmp_path):
    from support import run

    from plans.cycle.existence import support_conditions

    mech = load(SAMPLE)
    solver = Solver(mech)
    c = support_conditions(mech, solver, analyse_cycle(mech, solver=solver))
    # seed 001's lengths: l1 + l2 < l3 + l4 needs l4 > 0.17 m, and l4 is 0.135 ± 0.01 m
    assert (c.l1, c.l2, c.l3) == (0.0625, 0.21, 0.1025)
    assert c.l4 == pytest.approx((0.125, 0.145), abs=1e-8)
    assert c.lower == pytest.approx(0.17) and c.upper == pytest.approx(0.25)
    assert not c.first and c.second and c.never
    path = tmp_path / "grashof.toml"
    path.write_text(_grashof_support(), "utf-8")
    mech = load(path)
    solver = Solver(mech)
    c = support_conditions(mech, solver, analyse_cycle(mech, solver=solver))
    assert c.l4 == pytest.approx((0.19, 0.21), abs=1e-8) and c.hold
    code, out, err = run(capsys, "cycle", path)
    assert code == 0, err
    assert "both hold over the support's whole range: link 1 turns fully" in out
    code, out, _ = run(capsys, "solve", SAMPLE, "--json")
    assert code == 0 and json.loads(out)["crank_conditions"]["hold"] is False
    assert support_conditions(load("samples/fourbar.toml"), Solver(load("samples/fourbar.toml")),
                              None) is None


def test_an_accelerating_crank_changes_the_inertia_loads_and_m_y_stays_balanced():
    """ε1 = 30 rad/s² on seed 001's four-bar: the crank's inertia force is −m1·a_S1 with
    a_S1's tangential part ε1·l_AS1, and M_у by the groups, by virtual power and by the
    global solve agree as they do for a uniform crank."""
    from plans.forces.summary import solve_forces

    def forces(text):
        mech = mech_of(text)
        solver = Solver(mech)
        cyc = analyse_cycle(mech, solver=solver)
        return solve_forces(solve_position(mech, solver=solver, cycle=cyc), solver, cyc)

    with open("samples/fourbar.toml", encoding="utf-8") as f:
        text = f.read()
    uni = forces(text)
    acc = forces(text.replace('sense = "ccw"\n', 'sense = "ccw"\nepsilon = 30\n', 1))
    m1 = 0.3125
    a = acc.analysis.solution.scalar.acceleration["S1"]
    w1 = acc.analysis.solution.mechanism.driver.omega
    s1 = acc.analysis.solution.scalar.position["S1"]
    assert abs(a - (-w1 * w1 + 30j) * s1) <= 1e-12 * abs(a)  # a_S1 = (−ω1² + iε1)·AS1
    (phi1,) = [ld for ld in acc.analysis.loads if ld.kind == "inertia" and ld.link == 1]
    assert abs(phi1.force + m1 * a) <= 1e-12 * abs(m1 * a)
    for f in (uni, acc):
        M = f.analysis.M_y
        assert abs(f.M_y_power - M) <= 1e-9 * abs(M) and abs(f.M_y_global - M) <= 1e-9 * abs(M)
    assert abs(acc.analysis.M_y - uni.analysis.M_y) > 1e-3


def test_the_force_analysis_refuses_two_inputs_in_one_line(capsys, tmp_path):
    from support import run

    with open("samples/fourbar.toml", encoding="utf-8") as f:
        loads = f.read().partition("[loads]")[2]
    path = tmp_path / "two.toml"
    path.write_text(_sample() + "\n[loads]" + loads.replace('"S1"', '"B"').replace('"S2"', '"C"')
                    .replace('"S3"', '"C"').replace('point = "E"', 'point = "C"'), "utf-8")
    code, out, err = run(capsys, "forces", path)
    assert code == 2 and out == "" and len(err.strip().splitlines()) == 1
    assert "two inputs (link 1 and link 4), and each would need a balancing load" in err


def test_the_check_knows_an_accelerating_cranks_tangential_acceleration(capsys, tmp_path):
    """A hand-drawn acceleration plan of a crank with ε1: drawn right, it is within
    tolerance; drawn with a_A = a^n_AO only, the diagnosis names the missing a^t_AO."""
    from support import run

    (tmp_path / "eps.toml").write_text(FOURBAR.format(phi=60, eps="epsilon = 30"), "utf-8")
    head = 'mechanism = "eps.toml"\n[scales]\nmu_l = 0.002\nmu_v = 0.01\nmu_a = 0.1\n'
    right = tmp_path / "right.toml"
    right.write_text(head + '[segments.acceleration]\n"πa" = 52.2\n"πn1" = 50\nn1a = 15\n'
                     '"πb" = 45.9\n[values]\n"a^t_AO" = 1.5\n', "utf-8")
    code, out, err = run(capsys, "check", right)
    assert code == 0, err + out
    assert "Overall: all 5 items within tolerance." in out
    left_out = tmp_path / "left_out.toml"
    left_out.write_text(head + '[segments.acceleration]\n"πa" = 50\n"πb" = 54\n"πe" = 60.4\n', "utf-8")
    code, out, _ = run(capsys, "check", left_out)
    assert code == 1
    assert "Diagnosis: the crank's tangential acceleration a^t_AO is missing." in out


def test_the_note_lays_off_an_accelerating_cranks_two_components_and_gives_gamma(capsys, tmp_path):
    from support import run

    path = tmp_path / "eps.toml"
    path.write_text(FOURBAR.format(phi=60, eps="epsilon = 30"), "utf-8")
    code, out, err = run(capsys, "report", path)
    assert code == 0, err
    assert "- `a^n_AO = ω1²·l_OA = 10²·0.05 = 5 m/s²`" in out
    assert "- `a^τ_AO = ε1·l_OA = 30·0.05 = 1.5 m/s²`" in out
    assert "- `a_A = √((a^n_AO)² + (a^τ_AO)²) = √(5² + 1.5²) = 5.22015 m/s²`" in out  # six digits, as V_A
    assert "(ω1 = const)" not in out
    assert "Transmission angles γ and pressure angles α = 90° − γ of the groups:" in out
    path = tmp_path / "piston.toml"
    path.write_text(PISTON_ROCKER, "utf-8")
    code, out, err = run(capsys, "report", path)
    assert code == 0, err
    assert ("Velocity of point B of the input slider 1, along its guide x-x, given:\n\n"
            "- `V_B = 0.4 m/s`") in out
    assert "- `a_B = 1.5 m/s²`" in out and "l_B / B" not in out


SLOTTED = """
name = "oscillating slotted link, seed 004"
[frame]
A = [0.0, 0.0]
C = [0.0, -0.06]
[driver]
link = 1
angle_deg = 30
omega = 10
[links.1]
axis = ["A", "B"]
points = {{ B = 0.04 }}
[links.2]
points = {{ B = 0 }}
[links.3]
axis = ["C", "D"]
points = {{ D = 0.1 }}
[[sliders]]
link = 2
guide = {{ link = 3{offset} }}
"""


@pytest.mark.parametrize("e", [0.0, 0.01])
def test_seed_004s_slotted_link_gamma_is_constant_without_offset_and_varies_with_it(e):
    """Seed 004 (problem 6): l_AB = 40 mm drives, the slot offset e = 10 mm from the
    pivot C, l_AC = 60 mm > l_AB + e; with e = 0 γ = 90° at every position (the slot runs
    through C: the block pushes along the slot point's motion), with e > 0 it varies:
    sin α = e/|CB|, least at |CB| = l_AC − l_AB, γmin = 90° − asin(0.01/0.02) = 60°."""
    mech = mech_of(SLOTTED.format(offset=f", offset = {e}" if e else ""))
    solver = Solver(mech)
    (g,) = transmission(solver, analyse_cycle(mech, solver=solver)).groups
    for phi in (0.0, 1.0, 2.0, 4.5):
        m = solve_position(mech, phi).scalar
        cb = abs(m.position["B"] - m.position["C"])
        want = math.pi / 2 - math.asin(e / cb)
        assert abs(gammas(m)["group 2–3 (RPR)"] - want) <= 1e-12
    if e == 0:
        assert g.constant and abs(g.gamma_min - math.pi / 2) <= 1e-12
    else:
        assert not g.constant and abs(g.gamma_min - math.radians(60.0)) <= 1e-12
        assert abs(math.remainder(g.at - (-math.pi / 2), 2 * math.pi)) <= 1e-6  # B towards C


def test_the_sheet_draws_the_inputs_as_such_and_marks_gamma(tmp_path):
    """The plan of positions: a crank's ω (and ε where it accelerates) as arcs about its
    pivot, a slider input's V beside its guide, and γ of the group whose γ falls lowest
    marked at its joint with that γmin."""
    from drawing.views.inputs import gamma_marks, input_marks
    from drawing.views.positions import to_sheet

    mech = mech_of(FOURBAR.format(phi=60, eps="epsilon = 30"))
    solver = Solver(mech)
    cyc = analyse_cycle(mech, solver=solver)
    sol = solve_position(mech, solver=solver, cycle=cyc)
    items, labels = input_marks(sol, sol.positions, to_sheet, "en")
    assert len(items) == 4  # two arcs, each a polyline and its arrowhead
    assert [lb.text for lb in labels] == ["ω_{1}", "ε_{1}"]
    _, labels = gamma_marks(sol, cyc, sol.positions, to_sheet, "en")
    a, b, c, d = 0.05, 0.2, 0.15, 0.2
    want = math.degrees(math.acos((b * b + c * c - (d - a) ** 2) / (2 * b * c)))
    here = math.degrees(gammas(sol.scalar)["group 2–3 (RRR)"])
    assert [lb.text for lb in labels] == [f"γ = {here:.4g}°", f"γ_{{min}} = {want:.4g}°"]
    piston = mech_of(PISTON_ROCKER)
    sol = solve_position(piston)
    _, labels = input_marks(sol, sol.positions, to_sheet, "en")
    assert [lb.text for lb in labels] == ["V_{B}"]


LAW_CRANK = """
name = "crank-slider, the crank speeding up by a law in time"
[frame]
O = [0.0, 0.0]
[driver]
link = 1
angle_deg = 30
omega = 10
epsilon = 5
law = { kind = "accelerated" }
[motion]
time = 0.2
span = [0.0, 0.5]
[links.1]
axis = ["O", "A"]
points = { A = 0.1 }
[links.2]
axis = ["A", "B"]
points = { B = 0.4, S2 = 0.2 }
[links.3]
points = { B = 0.0 }
[[sliders]]
link = 3
point = "B"
guide = { through = "O", angle_deg = 0 }
[assembly]
B = "right of A"
[loads.links.2]
mass = 2
centre = "S2"
[loads.links.3]
mass = 3
centre = "B"
"""


def test_a_law_in_time_is_an_instant_in_the_note_and_refused_by_the_force_analysis(capsys, tmp_path):
    """The position of laws in time is an instant: the note's plan sections and forces said
    "φ1 = 11.4592°" (the instant 0.2 s read as radians); the note now gives t and where the crank is
    then (30° + 10·0.2 rad + 5·0.2²/2 rad = 150.321°), and the force analysis, which works
    over a crank's turn, refuses the law in one line; the note with loads stops at the
    kinematics with a warning, as it does for two inputs."""
    from support import run

    path = tmp_path / "law.toml"
    path.write_text(LAW_CRANK, "utf-8")
    want = 30 + math.degrees(10 * 0.2 + 0.5 * 5 * 0.2**2)
    code, out, err = run(capsys, "report", path)
    assert code == 0 and "## 6." not in out  # the note stops at the kinematics, and says why
    assert err.strip().endswith("the note stops at the kinematics: driver.law: the force analysis works "
                                "at a crank angle and over the crank's turn: a crank moved by a law in "
                                "time is not balanced here; give its omega (and epsilon) at the position "
                                "instead")
    assert f"Position of the mechanism: t = 0.2 s (φ1 = {want:.6g}° from +x)." in out
    assert "- `t = 0.2 s` (φ1 = 150.321° from +x)." in out and f"{want:.6g}" == "150.321"
    # the law itself, in rad and s: 30° = 0.523599 rad, ε/2 = 2.5 rad/s²
    assert "- `φ1(t) = 0.523599 + 10·t + 2.5·t² rad`, the law of input 1 in time;" in out
    code, out, err = run(capsys, "report", SAMPLE, "--lang", "ru")
    assert code == 0, err  # seed 003's l4(t): the support's travel s4 = 0.01·sin(ω1·t + 180°)
    assert "- `s4(t) = 0,01·sin(15,6242·t + 180°) м`, закон движения начального звена 4 во времени;" in out
    code, out, err = run(capsys, "forces", path)
    assert code == 2 and out == "" and len(err.strip().splitlines()) == 1
    assert "driver.law: the force analysis works at a crank angle" in err
