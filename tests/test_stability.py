"""Stiff and extreme linkages against the mpmath reference, the conditioning figure and
its warnings, and the branch staying continuous over the cycle.

The error bound: per angle, positions within C·κ·ε, velocities, ω, accelerations and ε
within C·κ²·ε, where ε is the machine epsilon and κ = 1/(the conditioning figure):
1/|sin| of the angle between the lines each group intersects, and for a slotted link
also (|OQ| + |OP|)/|QP| (the block near the rocker's pivot Q). Near a toggle the position
of the new point is itself known only to κ·ε (the circles meet at a shallow angle), so
the directions of the lines the velocity plan intersects carry κ·ε and the intersection
multiplies that by κ again: κ² is the conditioning of the velocities themselves, not a
weakness of the formulas. Accelerations could in principle reach κ³; measured, they stay
within about 11·κ²·ε (velocities 2.5·κ²·ε, positions 1.6·κ·ε) on the cases below.
"""

from __future__ import annotations

import math
import tomllib

import numpy as np
import pytest

from plans.cycle import analyse_cycle, summary
from plans.cycle.table import compute, conditioning
from plans.kinematics.solver import Solver
from plans.model import from_dict, load
from plans.model.scenes import SAMPLES, SCENES
from plans.tolerances import WARN_SINE
from plans.verify import reference

EPS = np.finfo(float).eps
C = 32.0  # the "small multiple"


# ---------------------------------------------------------------------------------------
# scene builders
# ---------------------------------------------------------------------------------------


def fourbar(a, b, c, d, *, omega=10.0, angle=60.0) -> str:
    return f"""
name = "four-bar a={a!r} b={b!r} c={c!r} d={d!r}"
output = "B"
[frame]
O = [0.0, 0.0]
D = [{d!r}, 0.0]
[driver]
link = 1
angle_deg = {angle!r}
omega = {omega!r}
[links.1]
axis = ["O", "A"]
points = {{ A = {a!r} }}
[links.2]
axis = ["A", "B"]
points = {{ B = {b!r}, E = [{b / 2!r}, {b / 5!r}] }}
[links.3]
axis = ["D", "B"]
points = {{ B = {c!r}, F = [{c / 2!r}, {-c / 7!r}] }}
[assembly]
B = "above OD"
"""


def crank_slider(R, L, e, *, omega=10.0, angle=30.0) -> str:
    return f"""
name = "crank-slider R={R!r} L={L!r} e={e!r}"
output = "B"
[frame]
O = [0.0, 0.0]
[driver]
link = 1
angle_deg = {angle!r}
omega = {omega!r}
[links.1]
axis = ["O", "A"]
points = {{ A = {R!r} }}
[links.2]
axis = ["A", "B"]
points = {{ B = {L!r}, S2 = [{L / 3!r}, {L / 50!r}] }}
[links.3]
points = {{ B = 0 }}
[[sliders]]
link = 3
guide = {{ link = 0, through = [0.0, {e!r}], angle_deg = 0 }}
[assembly]
B = "right of O"
"""


def slotted(R, L, *, omega=8.0, angle=20.0) -> str:
    return f"""
name = "slotted link R={R!r} |OB|={L!r}"
output = "C"
[frame]
O = [0.0, 0.0]
B = [0.0, {-L!r}]
[driver]
link = 1
angle_deg = {angle!r}
omega = {omega!r}
[links.1]
axis = ["O", "A"]
points = {{ A = {R!r} }}
[links.2]
points = {{ A = 0 }}
[links.3]
axis = ["B", "C"]
points = {{ C = 0.5, S3 = [0.25, 0.01] }}
[[sliders]]
link = 2
guide = {{ link = 3 }}
"""


def transmission(gmin_deg: float, gmax_deg: float, b=0.3, c=0.2) -> str:
    """A crank-rocker whose transmission angle (coupler to rocker) sweeps [γmin, γmax]:
    BD runs over [d − a, d + a] and cos γ = (b² + c² − BD²)/(2bc)."""
    g1, g2 = math.radians(gmin_deg), math.radians(gmax_deg)
    bd1 = math.sqrt(b * b + c * c - 2 * b * c * math.cos(g1))
    bd2 = math.sqrt(b * b + c * c - 2 * b * c * math.cos(g2))
    return fourbar((bd2 - bd1) / 2, b, c, (bd1 + bd2) / 2)


def mech_of(text: str):
    return from_dict(tomllib.loads(text), "<stiff scene>")


def press(omega: float):
    text = (SAMPLES / "press.toml").read_text("utf-8")
    assert "omega = 20 " in text
    return from_dict(
        tomllib.loads(text.replace("omega = 20 ", f"omega = {omega!r} ")), "<press>"
    )


# ---------------------------------------------------------------------------------------
# the check
# ---------------------------------------------------------------------------------------


def worst_angles(mech, solver, extra=(), n=24, fine=7200):
    """n angles over the crank range plus the worst-conditioned angle of a fine grid and
    its neighbours (and any ``extra``)."""
    cyc = analyse_cycle(mech, n_positions=n, solver=solver)
    if cyc.full_turn:
        grid = mech.driver.phi + np.linspace(0, 2 * np.pi, fine, endpoint=False)
    else:  # inside the limits, where the plans are singular
        lo, hi = cyc.crank_range
        grid = np.linspace(lo, hi, fine + 2)[1:-1]
    with np.errstate(all="ignore"):
        m = solver.solve(grid)
    figs = figure(mech, m)
    k = int(np.nanargmin(figs))
    near = grid[[max(k - 1, 0), k, min(k + 1, fine - 1)]]
    return np.concatenate(
        [np.array(cyc.positions), near, np.asarray(extra, dtype=float)]
    )


def figure(mech, motion) -> np.ndarray:
    """The smallest conditioning figure per angle (the one ``plans cycle`` reports)."""
    sts = conditioning(mech, motion)
    return np.array([min(s.figures.values()) if s.figures else 1.0 for s in sts])


def check(mech, phi, *, c=C):
    solver = Solver(mech)
    with np.errstate(all="ignore"):
        motion = solver.solve(phi)
    assert motion.valid.all()
    ref = reference.reference(mech, phi, motion=motion)
    err = reference.errors(motion, ref)
    kappa = 1.0 / figure(mech, motion)
    bound = c * kappa * EPS
    assert (err["position"] <= bound).all(), float(
        np.max(err["position"] / (kappa * EPS))
    )
    for q in ("velocity", "omega", "acceleration", "epsilon"):
        bound = c * kappa**2 * EPS
        assert (err[q] <= bound).all(), (q, float(np.max(err[q] / (kappa**2 * EPS))))
    return motion, err, kappa


def warnings_at(mech, phi):
    sv = Solver(mech)
    with np.errstate(all="ignore"):
        motion = sv.solve(phi)
    return [w for s in conditioning(mech, motion, sv) for w in s.warnings]


# ---------------------------------------------------------------------------------------
# the cases
# ---------------------------------------------------------------------------------------


def test_transmission_angle_within_half_a_degree_of_0_and_180():
    mech = mech_of(transmission(0.3, 179.7))
    solver = Solver(mech)
    cyc = analyse_cycle(mech, solver=solver)
    assert cyc.full_turn and cyc.grashof.startswith("crank-rocker")
    fine = np.linspace(0, 2 * np.pi, 36000, endpoint=False)
    m = solver.solve(fine)
    C_, A_, D_ = m.position["B"], m.position["A"], m.position["D"]
    cosg = ((A_ - C_) * np.conj(D_ - C_)).real / (np.abs(A_ - C_) * np.abs(D_ - C_))
    gamma = np.degrees(np.arccos(np.clip(cosg, -1, 1)))
    assert gamma.min() < 0.5 and gamma.max() > 179.5
    phi = np.concatenate(
        [worst_angles(mech, solver), fine[[np.argmin(gamma), np.argmax(gamma)]]]
    )
    _, _, kappa = check(mech, phi)
    assert kappa.max() > 1 / math.sin(math.radians(0.5))
    ws = warnings_at(mech, phi)
    assert any("near-singular" in w and "⊥ BA" in w for w in ws)
    # both ends of the sweep are flagged, each with its own figure
    assert len({w.split("(sin = ")[1] for w in ws}) >= 2


def test_crank_slider_lambda_099_is_well_conditioned():
    mech = mech_of(crank_slider(0.099, 0.1, 0.0))
    solver = Solver(mech)
    phi = worst_angles(mech, solver)
    _, err, kappa = check(mech, phi)
    # the rod's steepest angle is arcsin λ: |sin| of the plan lines = √(1 − λ²) ≈ 0.141
    assert 1 / kappa.max() == pytest.approx(math.sqrt(1 - 0.99**2), rel=1e-3)
    assert max(err["velocity"]) < 4 * 8 * EPS
    assert warnings_at(mech, phi) == []


@pytest.mark.parametrize(
    ("R", "L", "e"),
    [(0.099, 0.1, 0.00095), (0.1, 0.2, 0.0999)],
    ids=["lambda_099_offset", "large_offset"],
)
def test_crank_slider_with_offset_near_the_dead_point(R, L, e):
    mech = mech_of(crank_slider(R, L, e))
    solver = Solver(mech)
    phi = worst_angles(mech, solver)
    _, _, kappa = check(mech, phi)
    # the rod's steepest angle: sin β = (R + e)/L
    assert 1 / kappa.max() == pytest.approx(math.sqrt(1 - ((R + e) / L) ** 2), rel=1e-2)
    ws = warnings_at(mech, phi)
    assert ws and all("group 2–3 (RRP)" in w for w in ws)
    table = compute(mech, 720)
    assert any(s.warnings for s in table.status) and all(s.ok for s in table.status)


def test_slotted_link_with_its_pivot_almost_on_the_crank_circle():
    R = 0.1
    mech = mech_of(slotted(R, R * (1 + 1e-4)))
    solver = Solver(mech)
    # the block passes 1e-5 m from the pivot B when the crank points down (φ = −90°)
    down = -np.pi / 2 + np.array([-1e-3, -1e-4, -1e-5, 0.0, 1e-5, 1e-4, 1e-3])
    phi = worst_angles(mech, solver, extra=down)
    motion, _, kappa = check(mech, phi)
    assert kappa.max() > 1e4
    ws = warnings_at(mech, phi)
    assert any("close to the rocker's pivot B" in w for w in ws)
    # the lines themselves stay perpendicular: the figure that warns is the pivot one
    assert motion.min_sine.min() > 0.99


def test_one_position_with_the_block_on_the_pivot_is_refused_and_near_it_warned():
    """The rocker's pivot exactly on the crank circle: at φ1 = 270° the block is on the
    pivot. ``plans cycle`` said so, but one position (solve, report, sheet) printed
    ε3 = 5.4e17 rad/s² with exit 0: the lines of its plans stay perpendicular, so only the
    pivot figure sees it. Now that position is an error and the ones near it warn, in
    the note's language too."""
    from plans.errors import SingularPlanError
    from plans.note.report import warnings as note_warnings
    from plans.plan.solution import solve_position

    R = 0.1
    mech = mech_of(slotted(R, R))
    with pytest.raises(SingularPlanError, match="the block A is on the rocker's pivot B"):
        solve_position(mech, math.radians(-90))
    sol = solve_position(mech, math.radians(-90.1))
    (w,) = sol.warnings
    assert "the block A passes close to the rocker's pivot B" in w and "= 0.000873" in w
    (ru,) = note_warnings(sol, "ru")
    assert "камень A проходит близко к оси кулисы B" in ru and "= 0,000873" in ru
    assert not solve_position(mech, math.radians(-60)).warnings
    # the cycle's table words it the same way
    assert any(w in x for x in warnings_at(mech, np.radians([-90.1])))


@pytest.mark.parametrize(
    "text",
    [
        fourbar(1e-4, 1.0, 1.0, 1.0),
        crank_slider(1e-4, 1.0, 0.0),
        fourbar(1.0, 1e4, 1e4 - 0.5, 1e4),
    ],
    ids=["fourbar_crank_1e-4", "slider_lambda_1e-4", "fourbar_links_1e4"],
)
def test_link_length_ratios_of_ten_thousand(text):
    mech = mech_of(text)
    solver = Solver(mech)
    assert analyse_cycle(mech, solver=solver).full_turn
    phi = worst_angles(mech, solver, fine=720)
    _, err, _ = check(mech, phi)
    assert max(max(v) for v in err.values()) < 1e-13


def test_crank_speed_of_ten_thousand():
    slow, fast = press(20.0), press(1e4)
    phi = SCENES["press"].angles(20)
    check(fast, phi)
    ms, mf = Solver(slow).solve(phi), Solver(fast).solve(phi)
    k = 1e4 / 20.0
    for name in ms.velocity:
        np.testing.assert_allclose(
            mf.velocity[name], k * ms.velocity[name], rtol=1e-14, atol=1e-9
        )
        np.testing.assert_allclose(
            mf.acceleration[name], k * k * ms.acceleration[name], rtol=1e-14, atol=1e-6
        )
    err = reference.max_rel_error(mf, reference.reference(fast, phi, motion=mf))
    assert err["max"] < 1e-14


def test_linkage_that_cannot_make_a_full_turn():
    mech = load(SAMPLES / "fourbar.toml")
    solver = Solver(mech)
    cyc = analyse_cycle(mech, n_positions=12, solver=solver)
    assert not cyc.full_turn
    # it folds where |BD| = |BC − CD|: the crank at 180° ± γ about AD, by the cosine rule
    a = mech.driver.length
    bc = abs(mech.links[2].points["C"] - mech.links[2].points["B"])
    cd = abs(mech.links[3].points["C"] - mech.links[3].points["D"])
    ad = abs(mech.frame["D"] - mech.frame["A"])
    gamma = math.degrees(math.acos((a * a + ad * ad - (bc - cd) ** 2) / (2 * a * ad)))
    lo, hi = (math.degrees(x) % 360 for x in cyc.crank_range)
    assert lo == pytest.approx(180 + gamma, abs=1e-9) and hi == pytest.approx(180 - gamma, abs=1e-9)
    assert summary(cyc)[1] == (f"The input link 1 cannot make a full turn (it rocks, it is not a "
                               f"crank): the mechanism assembles only for φ1 from −{hi:.1f}° to "
                               f"{hi:.1f}°, a swing of {360 - 2 * gamma:.1f}°.")
    phi = worst_angles(mech, solver)
    _, _, kappa = check(mech, phi)
    assert kappa.max() > 1 / WARN_SINE
    assert not warnings_at(mech, np.array(cyc.positions))  # the middles of 12 parts
    ws = warnings_at(mech, [*np.array(cyc.crank_range), 0.0001, -0.0001])  # near the limits
    assert len(ws) == 2 and all("group 2–3 (RRR)" in w for w in ws)
    # outside the range it does not assemble, and says by how much
    with np.errstate(all="ignore"):
        out = solver.solve(np.radians([180.0]))
    assert not out.valid[0] and out.groups[0].gap[0] > 0


# ---------------------------------------------------------------------------------------
# the branch never jumps
# ---------------------------------------------------------------------------------------


def jumps(motion, omega1: float) -> float:
    """The largest step between adjacent angles over what the velocities allow:
    |X(φ_k+1) − X(φ_k)| / (Δφ·max(|V_k|, |V_k+1|)/|ω1|), over the points; a branch
    jump is a step of a link's length, hundreds of times the allowance."""
    phi = motion.phi
    dphi = np.abs(np.diff(phi))
    worst = 0.0
    size = max(float(np.max(np.abs(x))) for x in motion.position.values())
    for name, x in motion.position.items():
        if name in motion.coincident:
            continue  # it sits on its base point, whose own velocity bounds its steps
        v = np.abs(motion.velocity[name]) / abs(omega1)
        allow = dphi * np.maximum(v[1:], v[:-1]) + 1e-12 * size
        worst = max(worst, float(np.max(np.abs(np.diff(x)) / allow)))
    return worst


CONTINUITY = {
    **dict.fromkeys(SCENES),
    "transmission": transmission(0.3, 179.7),
    "slider_large_offset": crank_slider(0.1, 0.2, 0.0999),
}


@pytest.mark.parametrize("name", list(CONTINUITY))
def test_positions_are_continuous_over_a_fine_grid(name):
    if CONTINUITY[name] is None:
        scene = SCENES[name]
        mech = scene.mechanism()
        lo, hi = math.radians(scene.lo_deg), math.radians(scene.hi_deg)
        if not scene.full_turn:
            lo, hi = lo + 0.01 * (hi - lo), hi - 0.01 * (hi - lo)
        full = scene.full_turn
    else:
        mech = mech_of(CONTINUITY[name])
        lo, hi, full = 0.0, 2 * np.pi, True
    n = 20_000
    phi = np.linspace(
        lo, hi, n + 1
    )  # closes the turn: the last angle is the first again
    motion = Solver(mech).solve(phi)
    assert motion.valid.all()
    assert jumps(motion, mech.driver.omega) < 1.05
    if full:
        for name_, x in motion.position.items():
            assert abs(x[-1] - x[0]) < 1e-12, name_


def test_the_continuity_check_catches_a_flipped_branch():
    mech = SCENES["crank_rocker"].mechanism()
    phi = np.linspace(0, 2 * np.pi, 2001)
    keep = Solver(mech).solve(phi)
    flip = Solver(mech, sigmas=(-1,)).solve(phi)
    from dataclasses import replace

    half = phi < np.pi
    mixed = replace(
        keep,
        position={
            k: np.where(half, keep.position[k], flip.position[k]) for k in keep.position
        },
        velocity={
            k: np.where(half, keep.velocity[k], flip.velocity[k]) for k in keep.velocity
        },
    )
    assert jumps(keep, mech.driver.omega) < 1.05
    assert jumps(mixed, mech.driver.omega) > 100


def test_a_warning_says_how_far_off_the_plans_may_be_where_digits_are_lost(tmp_path):
    """At a crank's limit position (a non-Grashof four-bar, 1e-13 rad inside its range)
    the lines meet at sin = 3.3e-7 and the plans' values are off by 1.5e-3 of the largest
    against the 40-digit reference: the four digits printed are not all right, and the
    warning had said only the sine. It now bounds the error, and the bound holds; where
    the digits printed are right (sin = 1.1e-5), it says nothing more."""
    from support import NON_GRASHOF

    from plans.plan.solution import solve_position

    path = tmp_path / "ng.toml"
    path.write_text(NON_GRASHOF.format(angle=60), encoding="utf-8")
    mech = load(path)
    sv = Solver(mech)
    hi = analyse_cycle(mech, solver=sv).crank_range[1]
    for inside, said in ((1e-13, True), (1e-9, False)):
        phi = hi - inside
        sol = solve_position(mech, phi, sv)
        (warning,) = sol.warnings
        m = sv.solve(np.array([phi]))
        err = reference.errors(m, reference.reference(mech, np.array([phi]), motion=m, dps=40))
        worst = max(float(err[k][0]) for k in ("velocity", "acceleration", "omega", "epsilon"))
        if said:
            bound = float(warning.split("may be off by up to ")[1].split(" %")[0]) / 100
            assert worst <= bound < 100 * worst, (worst, warning)
        else:
            assert "may be off" not in warning and worst < 5e-5, (worst, warning)
