"""The cam's geometry (plans.cams): the pressure angle against a direct geometric computation,
the roller and flat-face envelopes against an independent tangency check to 1e-12, the
curvature against differences, the smallest base circle of the phase portrait against
brute force, and seed 004's cam problems against their closed forms.

The independent route: the test writes the inversion itself in real coordinates (the
pitch point or the face line turned by −σφ, x and y as separate real formulas) from the
motion's s alone, and differentiates it by complex step (φ + i·1e-30: exact to rounding),
never through the module's closed-form derivatives, its complex-number geometry or its
formulas of the pressure angle and the envelopes."""

from __future__ import annotations

import math

import numpy as np
import pytest

from plans.cams import Arrangement, design, from_dict, profile_table
from plans.cams.design import ProfileError

STEP = 1e-30


def _phases(rise="cosine", ret="cycloidal", angles=(120, 30, 120, 90), ratio=(1.0, 1.0)):
    a1, d1, a2, d2 = angles
    out = [{"kind": "rise", "angle_deg": a1, "law": rise, "ratio": ratio[0]}]
    if d1:
        out.append({"kind": "dwell", "angle_deg": d1})
    out.append({"kind": "return", "angle_deg": a2, "law": ret, "ratio": ratio[1]})
    if d2:
        out.append({"kind": "dwell", "angle_deg": d2})
    return out


def _cam(follower: dict, cam: dict | None = None, phases=None, limits=None, disc=None):
    data = {"follower": follower, "cam": cam or {}}
    if disc is not None:
        data["disc"] = disc
    else:
        data["phases"] = phases or _phases()
    if limits:
        data["limits"] = limits
    return from_dict(data, "test.toml")


def _s(d, phi):
    """s(φ) by the design's motion (φ may be complex: the laws take complex steps)."""
    return d.motion.at(phi)[0]


def _pitch_xy(d, phi):
    """The pitch point in the cam's frame, real x and y, written here from s alone."""
    arr, f = d.arrangement, d.cam.follower
    sig = arr.sigma
    s = _s(d, phi)
    if not f.oscillating:
        bx, by = arr.e + 0.0 * s, arr.s0 + s
    else:
        tau, a, ell = arr.tau, f.centre, f.arm
        psi = arr.psi0 + s
        # A at (−τa, 0); B = A + l·τ·(cos τΨ, sin τΨ)
        bx = -tau * a + ell * tau * np.cos(tau * psi)
        by = ell * tau * np.sin(tau * psi)
    c, sn = np.cos(sig * phi), np.sin(sig * phi)  # turned by −σφ
    return bx * c + by * sn, -bx * sn + by * c


def _tangent(fn, phi):
    x, y = fn(phi + 1j * STEP)
    return np.imag(x) / STEP, np.imag(y) / STEP


def _motion_direction(d, phi):
    """The unit direction of the follower's point's motion, turned into the cam's frame."""
    arr, f = d.arrangement, d.cam.follower
    sig = arr.sigma
    if not f.oscillating:
        dx, dy = 0.0 * phi, 1.0 + 0.0 * phi
    else:
        tau = arr.tau
        psi = arr.psi0 + _s(d, phi)
        # ⊥ AB, the way Ψ grows: d/dΨ of τ·(cos τΨ, sin τΨ) = (−sin τΨ, cos τΨ)
        dx, dy = -np.sin(tau * psi), np.cos(tau * psi)
    c, sn = np.cos(sig * phi), np.sin(sig * phi)
    return dx * c + dy * sn, -dx * sn + dy * c


FOLLOWERS = [
    ({"kind": "knife-edge", "stroke": 0.03, "offset": 0.012}, {"base_radius": 0.05, "sense": "ccw"}),
    ({"kind": "roller", "stroke": 0.03, "offset": -0.008, "roller_radius": 0.006}, {"base_radius": 0.045,
                                                                                    "sense": "cw"}),
    ({"kind": "roller", "stroke": 0.03, "offset": 0.01, "roller_radius": 0.008}, {"sense": "ccw"}),
    ({"kind": "roller", "motion": "oscillating", "swing_deg": 22, "arm": 0.09, "centre_distance": 0.11,
      "roller_radius": 0.008}, {"base_radius": 0.045, "sense": "ccw"}),
    ({"kind": "knife-edge", "motion": "oscillating", "swing_deg": 18, "arm": 0.08, "centre_distance": 0.1,
      "rise": "with"}, {"base_radius": 0.04, "sense": "cw"}),
]


def _interior(d, n=1500):
    """Cam angles inside the phases, off their joints and the laws' inner joints."""
    phi = np.linspace(0.0, 2 * math.pi, n, endpoint=False) + 0.0013
    joints = [p.start for p in d.motion.phases] + [p.start + p.k * p.angle for p in d.motion.phases]
    apart = np.abs(np.mod(phi[:, None] - np.array(joints)[None, :] + 1, 2 * math.pi) - 1)
    return phi[np.all(apart > 1e-6, axis=1)]


@pytest.mark.parametrize(("follower", "cam"), FOLLOWERS,
                         ids=lambda x: x.get("kind", "") + x.get("motion", ""))
def test_pressure_angle_against_the_geometry(follower, cam):
    """α between the normal of the pitch curve (its tangent by complex step, in the cam's
    frame) and the follower's direction of motion there: sin α = |t·d| / |t|."""
    d = design(_cam(follower, cam))
    phi = _interior(d)
    tx, ty = _tangent(lambda p: _pitch_xy(d, p), phi)
    dx, dy = _motion_direction(d, phi)
    direct = np.arcsin(np.clip(np.abs(tx * dx + ty * dy) / np.hypot(tx, ty), 0, 1))
    got = d.curves(phi).pressure
    assert np.max(np.abs(got - direct)) < 1e-12


def test_the_offset_formula_is_r_squared_minus_e_squared():
    """s0 = √(r0² − e²): at the start of the rise of a translating knife-edge follower on its
    base circle, tan α = |e|/s0 exactly (√(r0² + e²) would be the wrong one)."""
    d = design(_cam({"kind": "knife-edge", "stroke": 0.02, "offset": 0.015},
                    {"base_radius": 0.025, "sense": "ccw"}, _phases("cycloidal", "cycloidal")))
    alpha = float(d.curves(np.array([0.0])).pressure[0])
    assert math.tan(alpha) == pytest.approx(0.015 / math.sqrt(0.025**2 - 0.015**2), rel=1e-14)
    assert d.arrangement.s0 == pytest.approx(0.02, rel=1e-14)


ENVELOPES = [
    ({"kind": "roller", "stroke": 0.03, "offset": 0.01, "roller_radius": 0.008}, {"base_radius": 0.05}),
    ({"kind": "roller", "stroke": 0.025, "offset": -0.012, "roller_radius": 0.01},
     {"base_radius": 0.045, "sense": "cw"}),
    ({"kind": "roller", "motion": "oscillating", "swing_deg": 22, "arm": 0.09, "centre_distance": 0.11,
      "roller_radius": 0.008}, {"base_radius": 0.045}),
]


@pytest.mark.parametrize(("follower", "cam"), ENVELOPES, ids=["offset", "left-cw", "oscillating"])
def test_roller_envelope_is_tangent_to_every_roller_circle(follower, cam):
    """Each profile point lies on its roller circle (|P − R| = r_r) and the circle family's
    envelope condition holds there: (P − R)·dR/dφ = 0, dR/dφ by complex step of the
    pitch curve written here: to 1e-12."""
    d = design(_cam(follower, cam))
    phi = _interior(d)
    c = d.curves(phi)
    x, y = _pitch_xy(d, phi)
    tx, ty = _tangent(lambda p: _pitch_xy(d, p), phi)
    rr = d.cam.follower.roller
    px, py = c.profile.real - x, c.profile.imag - y
    assert np.max(np.abs(np.hypot(px, py) - rr)) < 1e-12 * rr
    assert np.max(np.abs(px * tx + py * ty) / (rr * np.hypot(tx, ty))) < 1e-12
    # on the cam's side: towards the centre where the pitch curve is convex
    assert (np.abs(c.profile) < np.hypot(x, y) + rr * 1e-9).mean() > 0.5


def _face(d, phi):
    """The flat face's line in the cam's frame, written here: its unit normal (nx, ny) and
    its distance p from O, for the contact X·n = p."""
    arr, f = d.arrangement, d.cam.follower
    sig = arr.sigma
    s = _s(d, phi)
    if not f.oscillating:
        theta, p = math.pi / 2 - sig * phi, arr.r0 + s
    else:
        psi = arr.psi0 + s
        theta, p = math.pi / 2 + arr.tau * psi - sig * phi, f.centre * np.sin(psi)
    return np.cos(theta), np.sin(theta), p


@pytest.mark.parametrize(("follower", "cam"), [
    ({"kind": "flat-faced", "stroke": 0.02}, {"base_radius": 0.06}),
    ({"kind": "flat-faced", "stroke": 0.02, "offset": 0.01}, {"base_radius": 0.05, "sense": "cw"}),
    ({"kind": "flat-faced", "motion": "oscillating", "swing_deg": 15, "arm": 0.1, "centre_distance": 0.12},
     {"base_radius": 0.05}),
], ids=["centred", "offset-cw", "oscillating"])
def test_flat_face_envelope_is_tangent_to_every_face_line(follower, cam):
    """Each profile point lies on its face line (X·n = p) and the line family's envelope
    condition holds: X·dn/dφ = dp/dφ, both by complex step here: to 1e-12."""
    d = design(_cam(follower, cam, _phases("3-4-5", "cycloidal", (140, 40, 120, 60))))
    phi = _interior(d)
    c = d.curves(phi)
    nx, ny, p = _face(d, phi)
    X, Y = c.profile.real, c.profile.imag
    scale = float(np.max(np.abs(p)))
    assert np.max(np.abs(X * nx + Y * ny - p)) < 1e-12 * scale
    nxs, nys, ps = _face(d, phi + 1j * STEP)
    dnx, dny, dp = np.imag(nxs) / STEP, np.imag(nys) / STEP, np.imag(ps) / STEP
    assert np.max(np.abs(X * dnx + Y * dny - dp)) < 1e-12 * scale


def test_curvature_against_differences():
    """The pitch curve's radius of curvature against second differences of the pitch curve
    written here (complex step of each coordinate, then a central difference), and the
    roller profile's against the same of its points."""
    d = design(_cam(*ENVELOPES[0]))
    phi = _interior(d, 400)
    h = 1e-5
    t0 = _tangent(lambda p: _pitch_xy(d, p), phi)
    tp = _tangent(lambda p: _pitch_xy(d, p), phi + h)
    tm = _tangent(lambda p: _pitch_xy(d, p), phi - h)
    ax, ay = (tp[0] - tm[0]) / (2 * h), (tp[1] - tm[1]) / (2 * h)
    kappa = -d.arrangement.sigma * (t0[0] * ay - t0[1] * ax) / np.hypot(*t0) ** 3
    c = d.curves(phi)
    assert np.max(np.abs(c.kappa - kappa)) < 1e-6 * np.max(np.abs(kappa))
    # the roller profile's radius is ρ − r_r
    P = lambda p: d.curves(p).profile  # noqa: E731
    d1 = (P(phi + h) - P(phi - h)) / (2 * h)
    d2 = (P(phi + h) - 2 * P(phi) + P(phi - h)) / h**2
    k_prof = -d.arrangement.sigma * (np.conj(d1) * d2).imag / np.abs(d1) ** 3
    scale = float(np.max(np.abs(1 / kappa)))
    assert np.max(np.abs(1 / k_prof - (1 / kappa - d.cam.follower.roller))) < 1e-4 * scale


def _brute_r0(d, e, lims, grid=None):
    """The smallest r0 at the offset e by brute force: the largest α over a dense grid of
    each phase, at a dense ladder of r0, the first that keeps within both limits."""
    m = d.motion
    phi = np.linspace(0, 2 * math.pi, 200001)
    idx = m.index(phi)
    s, s1 = m.at(phi)[:2]
    sig = d.cam.sense

    def within(r0):
        s0 = math.sqrt(r0 * r0 - e * e)
        alpha = np.degrees(np.arctan2(np.abs(s1 - sig * e), s0 + s))
        for i, p in enumerate(m.phases):
            if p.moves and alpha[idx == i].max() > (lims[0] if p.kind == "rise" else lims[1]):
                return False
        return True
    lo, hi = abs(e) + 1e-9, 1.0
    for _ in range(60):
        mid = (lo + hi) / 2
        lo, hi = (lo, mid) if within(mid) else (mid, hi)
    return hi


@pytest.mark.parametrize(("rise", "ret", "sense", "lims"), [
    ("cosine", "cycloidal", "ccw", (30, 70)),
    ("3-4-5", "parabolic", "cw", (35, 60)),
    ("modified trapezoid", "4-5-6-7", "ccw", (25, 75)),
    ("constant velocity", "cosine", "ccw", (30, 70)),
])
def test_smallest_r0_of_the_phase_portrait_against_brute_force(rise, ret, sense, lims):
    limits = {"pressure_rise_deg": lims[0], "pressure_return_deg": lims[1]}
    cam = _cam({"kind": "roller", "stroke": 0.03, "offset": "best", "roller_radius": 0.001},
               {"sense": sense}, _phases(rise, ret), limits)
    try:
        d = design(cam)
    except ProfileError:  # constant velocity: its corner undercuts even a small roller
        cam = _cam({"kind": "knife-edge", "stroke": 0.03, "offset": "best"}, {"sense": sense},
                   _phases(rise, ret), limits)
        d = design(cam)
    r0, e = d.best
    assert d.r0 == pytest.approx(r0, rel=1e-12) and d.offset == pytest.approx(e, rel=1e-12)
    # brute force at the portrait's offset, and at others: never smaller
    assert _brute_r0(d, e, lims) == pytest.approx(r0, rel=1e-6)
    for other in (e - 0.004, e + 0.004, 0.0):
        brute = _brute_r0(d, other, lims)
        assert brute >= r0 * (1 - 1e-9)
        assert d.portrait.at_offset(other)[0] == pytest.approx(brute, rel=1e-6)


def test_an_oscillating_followers_smallest_r0_against_brute_force():
    cam = _cam({"kind": "roller", "motion": "oscillating", "swing_deg": 20, "arm": 0.08,
                "centre_distance": 0.1, "roller_radius": 0.005}, {},
               _phases("3-4-5", "cycloidal", (150, 30, 120, 60)),
               {"pressure_rise_deg": 40, "pressure_return_deg": 60})
    d = design(cam)
    phi = np.linspace(0, 2 * math.pi, 100001)
    m = d.motion
    idx = m.index(phi)
    values = m.at(phi)

    def worst(r0):
        arr = Arrangement(cam.follower, cam.sense, r0)
        alpha = np.degrees(arr.pressure(*values[:2]))
        return max(alpha[idx == i].max() - (40 if p.kind == "rise" else 60)
                   for i, p in enumerate(m.phases) if p.moves)
    assert worst(d.r0) == pytest.approx(0.0, abs=1e-6)
    assert worst(d.r0 * (1 - 1e-4)) > 0
    assert worst(d.r0 * (1 + 1e-4)) <= 1e-9


# ---------------------------------------------------------------------------------------
# seed 004's problems
# ---------------------------------------------------------------------------------------


def test_seed_eccentric_disc_offset_knife_edge():
    """R = 30, OA = 10, the follower's axis 10 mm to the left of O (the figure's offset, which
    the notes call the wrong side for a cam turning counter-clockwise): r0 = R − OA = 20 mm;
    in the position where AD ⊥ CD the cam has turned φ = 60°, α = arcsin(20/30) = 41.81° and
    s = √(30² − 20²) − √(20² − 10²) = 5.04 mm."""
    disc = {"radius": 0.030, "eccentricity": 0.010}
    d = design(_cam({"kind": "knife-edge", "offset": -0.010}, {"sense": "ccw"}, disc=disc))
    assert d.r0 == pytest.approx(0.020, rel=1e-14)
    c = d.curves(np.radians([60.0]))
    assert math.degrees(float(c.pressure[0])) == pytest.approx(math.degrees(math.asin(2 / 3)), abs=1e-10)
    s = math.sqrt(0.03**2 - 0.02**2) - math.sqrt(0.02**2 - 0.01**2)
    assert float(c.s[0]) == pytest.approx(s, abs=1e-15)
    assert float(c.s[0]) * 1000 == pytest.approx(5.04, abs=0.005)
    # the position asked is where α is largest on the rise; the axis on the right lowers it
    assert d.pressure["rise"].value == pytest.approx(math.asin(2 / 3), abs=1e-12)
    right = design(_cam({"kind": "knife-edge", "offset": 0.010}, {"sense": "ccw"}, disc=disc))
    assert right.pressure["rise"].value < d.pressure["rise"].value


@pytest.mark.parametrize("sense", ["ccw", "cw"])
def test_seed_eccentric_disc_centred_roller(sense):
    """R = 40, OA = 25, r_r = 10, centred: rise and return 180° each, h = 2·OA = 50 mm,
    r0 = R − OA + r_r = 25 mm; the largest pressure angle, with OA ⊥ the axis,
    α = arcsin(OA/(R + r_r)) = 30°."""
    d = design(_cam({"kind": "roller", "roller_radius": 0.010}, {"sense": sense},
                    disc={"radius": 0.040, "eccentricity": 0.025}))
    assert d.r0 == pytest.approx(0.025, rel=1e-14)
    assert d.motion.stroke == pytest.approx(0.050, rel=1e-14)
    assert [math.degrees(p.angle) for p in d.motion.phases] == pytest.approx([180.0, 180.0], abs=1e-12)
    for kind in ("rise", "return"):
        assert d.pressure[kind].value == pytest.approx(math.radians(30.0), abs=1e-12)
        assert math.degrees(d.pressure[kind].phi) % 180 == pytest.approx(90.0, abs=1e-5)  # a flat top: to √ε
    # the actual profile is the disc itself
    t = profile_table(d, math.radians(5))
    A = 0.025 * np.exp(1j * (-math.pi / 2))  # the disc's centre in the cam's frame (φ = 0: below O)
    assert np.max(np.abs(np.abs(t.profile - A) - 0.040)) < 1e-15


def test_seed_eccentric_disc_offset_roller():
    """R = 30, OA = 10, e = 15, r_r = 5: r0 = R − OA + r_r = 25 mm, h = √(45² − 15²) −
    √(25² − 15²) = 22.43 mm; the normal runs through the disc's centre, so
    sin α = |e − x_A|/(R + r_r): largest arcsin(25/35) where A is farthest from the axis,
    smallest arcsin(5/35) where nearest."""
    d = design(_cam({"kind": "roller", "roller_radius": 0.005, "offset": 0.015}, {"sense": "ccw"},
                    disc={"radius": 0.030, "eccentricity": 0.010}))
    assert d.r0 == pytest.approx(0.025, rel=1e-14)
    assert d.motion.stroke == pytest.approx(math.sqrt(0.045**2 - 0.015**2) - 0.02, rel=1e-14)
    assert d.motion.stroke * 1000 == pytest.approx(22.43, abs=0.005)
    phi = np.linspace(0, 2 * math.pi, 20001)
    xa = 0.010 * np.cos(d.motion.theta0 + phi)  # the disc's centre, turning ccw
    direct = np.arcsin(np.abs(0.015 - xa) / 0.035)
    assert np.max(np.abs(d.curves(phi).pressure - direct)) < 1e-12
    both = max(d.pressure["rise"].value, d.pressure["return"].value)
    assert both == pytest.approx(math.asin(25 / 35), abs=1e-12)
    assert float(d.curves(phi).pressure.min()) == pytest.approx(math.asin(5 / 35), abs=1e-7)


@pytest.mark.parametrize("kind", ["roller", "flat-faced"])
def test_seed_eccentric_disc_follower_speed_is_omega_times_oa(kind):
    """R = 80, OA = 50, ω = 10 rad/s, the axis ⊥ OA bisecting it (e = 25; a flat face): with OA
    ⊥ the axis the instant centre is at A's foot and v = ω·OA = 500 mm/s; the roller (r_r =
    20) has r0 = 50 mm and h = √(150² − 25²) − √(50² − 25²) = 104.6 mm, the flat face r0 =
    R − OA = 30 mm."""
    fol = {"kind": kind, "offset": 0.025} | ({"roller_radius": 0.020} if kind == "roller" else {})
    d = design(_cam(fol, {"sense": "ccw", "omega": 10}, disc={"radius": 0.080, "eccentricity": 0.050}))
    # A at (50, 0): the cam turned from A's start by the angle to the +x axis
    phi = (0.0 - d.motion.theta0) % (2 * math.pi)
    v = float(d.curves(np.array([phi])).s1[0]) * 10
    assert v == pytest.approx(0.5, rel=1e-12)
    if kind == "roller":
        assert d.r0 == pytest.approx(0.050, rel=1e-14)
        assert d.motion.stroke * 1000 == pytest.approx(104.6, abs=0.05)
    else:
        assert d.r0 == pytest.approx(0.030, rel=1e-14) and d.motion.stroke == pytest.approx(0.1, rel=1e-14)


def test_seed_exam_centred_knife_edge_cosine():
    """The exam: h = 16 mm over δ0 = 120°, r0 = 30 mm, the cam counter-clockwise, the cosine
    law: s = 8·(1 − cos(1.5φ)) mm, the profile point at φ turned back by φ, r = 30 + s."""
    d = design(_cam({"kind": "knife-edge", "stroke": 0.016}, {"base_radius": 0.030, "sense": "ccw"},
                    _phases("cosine", "cosine", (120, 60, 120, 60))))
    phi = np.radians(np.arange(0, 121, 15.0))
    c = d.curves(phi)
    assert c.s * 1000 == pytest.approx(8 * (1 - np.cos(1.5 * phi)), abs=1e-12)
    want = (0.030 + c.s) * np.exp(1j * (math.pi / 2 - phi))
    assert np.max(np.abs(c.profile - want)) < 1e-15
    assert [i.kind for i in d.impacts] == ["soft", "soft", "soft", "soft"]


# ---------------------------------------------------------------------------------------
# refusals
# ---------------------------------------------------------------------------------------


def test_undercut_is_refused_with_where_and_by_how_much():
    cam = _cam({"kind": "roller", "stroke": 0.04, "roller_radius": 0.02}, {"base_radius": 0.025},
               _phases("cycloidal", "cycloidal", (60, 120, 60, 120)))
    with pytest.raises(ProfileError) as err:
        design(cam)
    text = str(err.value)
    assert text.startswith("undercut: at φ = ") and "the pitch curve's radius of curvature is" in text
    assert "under the roller's r_r = 20 mm by" in text and "a base radius of at least" in text
    r = float(text.split("a base radius of at least ")[1].split(" mm")[0]) / 1000
    ok = _cam({"kind": "roller", "stroke": 0.04, "roller_radius": 0.02}, {"base_radius": r * 1.001},
              _phases("cycloidal", "cycloidal", (60, 120, 60, 120)))
    assert design(ok).radius["pitch"].value > 0.02


def test_a_roller_cannot_follow_a_velocity_jump():
    cam = _cam({"kind": "roller", "stroke": 0.02, "roller_radius": 0.005}, {"base_radius": 0.05},
               _phases("constant velocity", "cosine"))
    with pytest.raises(ProfileError, match=r"turns a corner at φ = 120°.*a roller cannot follow it"):
        design(cam)
    # a knife-edge can: its profile has the corner, its hollow one at the rise's start
    knife = design(_cam({"kind": "knife-edge", "stroke": 0.02}, {"base_radius": 0.05},
                        _phases("constant velocity", "cosine")))
    assert [(round(math.degrees(c.phi)), c.convex) for c in knife.corners] == [(0, False), (120, True)]


def test_a_flat_face_needs_a_convex_profile():
    cam = _cam({"kind": "flat-faced", "stroke": 0.03}, {"base_radius": 0.02},
               _phases("cycloidal", "cycloidal", (60, 120, 60, 120)))
    with pytest.raises(ProfileError, match=r"not convex enough for a flat face at φ = .*r0 \+ s \+ s″"):
        design(cam)
