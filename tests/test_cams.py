"""The cam's motion laws and impacts (plans.cams.laws, plans.cams.motion): every law's s, s′,
s″, s‴ against independent finite differences and against the textbooks' own formulas over
the whole phase, its boundary values, the asymmetric laws' joint, and the impacts classed
as the notes class them."""

from __future__ import annotations

import math

import numpy as np
import pytest

from plans.cams import LAWS, Motion, Phase, impacts, law_named, unit
from plans.cams.laws import MT_PEAK

RATIOS = (1.0, 0.5, 2.0, 0.2)


def _joints(key: str, k: float) -> list[float]:
    """Where a law's pieces meet on u ∈ [0, 1] (its formulas change there)."""
    out = [k]
    if key == "modified trapezoid":
        out += [k / 4, 3 * k / 4, 1 - (1 - k) / 4, 1 - 3 * (1 - k) / 4]
    return out


def _away(u: np.ndarray, joints, gap: float) -> np.ndarray:
    return u[np.all(np.abs(u[:, None] - np.array(joints)[None, :]) > gap, axis=1)]


@pytest.mark.parametrize("ratio", RATIOS)
@pytest.mark.parametrize("key", sorted(LAWS))
def test_every_law_against_central_differences(key, ratio):
    """s′, s″, s‴ against central differences of s, s′, s″ (h = 1e-5 of the phase, away from
    the joints of the law's pieces): agreement to the differences' own error, h²·f⁗/6."""
    k = ratio / (1 + ratio)
    h = 1e-5
    u = _away(np.linspace(0.001, 0.999, 997), _joints(key, k), 10 * h)
    f = unit(key, u, k)
    up, down = unit(key, u + h, k), unit(key, u - h, k)
    for order in range(3):
        fd = (up[order] - down[order]) / (2 * h)
        scale = max(1.0, float(np.max(np.abs(f[order + 1]))))
        assert np.max(np.abs(fd - f[order + 1])) < 1e-6 * scale * (1 + order * 10), (key, ratio, order)


#: the laws over the whole rise as the textbooks write them (Artobolevsky; 孙桓 §9; Norton
#: ch. 8), each its own formula, not the half-phase construction of plans.cams.laws
def _textbook(key: str, u):
    pi = math.pi
    if key == "constant velocity":
        return u, np.ones_like(u), np.zeros_like(u), np.zeros_like(u)
    if key == "parabolic":
        first = u <= 0.5
        return (np.where(first, 2 * u**2, 1 - 2 * (1 - u) ** 2), np.where(first, 4 * u, 4 * (1 - u)),
                np.where(first, 4.0, -4.0), np.zeros_like(u))
    if key == "cosine":
        return ((1 - np.cos(pi * u)) / 2, pi / 2 * np.sin(pi * u), pi**2 / 2 * np.cos(pi * u),
                -(pi**3) / 2 * np.sin(pi * u))
    if key == "cycloidal":
        return (u - np.sin(2 * pi * u) / (2 * pi), 1 - np.cos(2 * pi * u), 2 * pi * np.sin(2 * pi * u),
                4 * pi**2 * np.cos(2 * pi * u))
    if key == "3-4-5":
        return (10 * u**3 - 15 * u**4 + 6 * u**5, 30 * u**2 - 60 * u**3 + 30 * u**4,
                60 * u - 180 * u**2 + 120 * u**3, 60 - 360 * u + 360 * u**2)
    if key == "4-5-6-7":
        return (35 * u**4 - 84 * u**5 + 70 * u**6 - 20 * u**7,
                140 * u**3 - 420 * u**4 + 420 * u**5 - 140 * u**6,
                420 * u**2 - 1680 * u**3 + 2100 * u**4 - 840 * u**5,
                840 * u - 5040 * u**2 + 8400 * u**3 - 4200 * u**4)
    raise KeyError(key)


@pytest.mark.parametrize("key", sorted(set(LAWS) - {"modified trapezoid"}))
def test_symmetric_laws_are_the_textbooks_formulas(key):
    u = np.linspace(0.0, 1.0, 1001)
    u = u[np.abs(u - 0.5) > 1e-12]  # the parabolic law's joint: its acceleration jumps there
    for got, want in zip(unit(key, u), _textbook(key, u), strict=True):
        assert np.max(np.abs(got - want)) < 1e-12 * max(1.0, float(np.max(np.abs(want))))


def test_the_modified_trapezoid_is_nortons():
    """Norton's coefficients: peak acceleration 4.8881, peak velocity 2.0000, jerk
    61.4258 at the start; the acceleration constant from u = 1/8 to 3/8; f(½) = ½."""
    assert MT_PEAK == pytest.approx(4.888124, abs=1e-6)
    u = np.array([0.0, 0.125, 0.25, 0.375, 0.5, 0.625, 0.875, 1.0])
    f, f1, f2, f3 = unit("modified trapezoid", u)
    assert f[[0, 4, 7]] == pytest.approx([0.0, 0.5, 1.0], abs=1e-15)
    assert f1[4] == pytest.approx(2.0, abs=1e-14) and f1.max() == pytest.approx(2.0, abs=1e-14)
    assert f2[1:4] == pytest.approx([MT_PEAK] * 3, abs=1e-13)
    assert f2[5:7] == pytest.approx([-MT_PEAK] * 2, abs=1e-13)
    assert f3[0] == pytest.approx(4 * math.pi * MT_PEAK, abs=1e-12)
    assert f3[0] == pytest.approx(61.426, abs=1e-3)
    # Norton's table: f(1/8) = 0.38898448·(1/8 − 1/(4π)·sin(π/2)) = 0.0176718
    assert f[1] == pytest.approx(0.38898448 * (0.125 - 1 / (4 * math.pi)), abs=1e-8)


#: each law's values at the ends of a rise: f′ (0 but constant velocity's), whether f″ is
#: 0 there (the laws without a soft impact), whether f‴ is 0 (4-5-6-7's, and those whose
#: f″ is flat there: constant velocity, parabolic, cosine)
ENDS = {
    "constant velocity": (1.0, True, True),
    "parabolic": (0.0, False, True),
    "cosine": (0.0, False, True),
    "cycloidal": (0.0, True, False),
    "3-4-5": (0.0, True, False),
    "4-5-6-7": (0.0, True, True),
    "modified trapezoid": (0.0, True, False),
}


@pytest.mark.parametrize("ratio", RATIOS)
@pytest.mark.parametrize("key", sorted(LAWS))
def test_boundary_values(key, ratio):
    k = ratio / (1 + ratio)
    f, f1, f2, f3 = unit(key, np.array([0.0, 1.0]), k)
    v, a0, j0 = ENDS[key]
    assert f == pytest.approx([0.0, 1.0], abs=1e-15)
    assert f1 == pytest.approx([v, v], abs=1e-14)
    assert (np.abs(f2) < 1e-12).all() == a0
    assert (np.abs(f3) < 1e-9).all() == j0
    # the joint of the acceleration and deceleration parts: s and s′ continuous, and s″ too
    # but for the parabolic law's jump from +2/k to −2/(1 − k)
    left = unit(key, np.array(k), k, "left")
    right = unit(key, np.array(k), k, "right")
    assert float(left[0]) == pytest.approx(float(right[0]), abs=1e-15)
    assert float(left[1]) == pytest.approx(float(right[1]), abs=1e-14)
    if key == "parabolic":
        assert (float(left[2]), float(right[2])) == pytest.approx((2 / k, -2 / (1 - k)), rel=1e-14)
    else:
        assert float(left[2]) == pytest.approx(float(right[2]), abs=1e-12)


def test_an_asymmetric_law_spends_its_ratio_accelerating():
    """With ratio 1:3 the velocity peaks at a quarter of the phase, and the peak of s″ over
    the acceleration part is three times that over the deceleration part (cosine)."""
    k = 0.25
    u = np.linspace(0, 1, 100001)
    _f, f1, f2, _ = unit("cosine", u, k)
    assert u[np.argmax(f1)] == pytest.approx(k, abs=1e-5)
    assert f2.max() / -f2.min() == pytest.approx(3.0, rel=1e-9)


@pytest.mark.parametrize(("name", "key"), [("uniform", "constant velocity"), ("Simple Harmonic", "cosine"),
                                           ("sine", "cycloidal"), ("345", "3-4-5"),
                                           ("modified trapezoidal", "modified trapezoid")])
def test_laws_are_found_by_their_other_names(name, key):
    assert law_named(name).key == key


def _cycle(rise: str, ret: str, dwell=(60.0, 60.0), rise_deg=120.0, ret_deg=120.0, h=0.016, ratio=1.0):
    b1, b2 = math.radians(rise_deg), math.radians(ret_deg)
    d1, d2 = (math.radians(x) for x in dwell)
    phases = [Phase("rise", 0.0, b1, LAWS[rise], ratio)]
    at = b1
    if d1:
        phases.append(Phase("dwell", at, d1, level=h))
        at += d1
    phases.append(Phase("return", at, b2, LAWS[ret]))
    at += b2
    if d2:
        phases.append(Phase("dwell", at, 2 * math.pi - at))
    return Motion(phases, h)


@pytest.mark.parametrize(("law", "kind"), [("constant velocity", "rigid"), ("parabolic", "soft"),
                                           ("cosine", "soft"), ("cycloidal", "none"), ("3-4-5", "none"),
                                           ("4-5-6-7", "none"), ("modified trapezoid", "none")])
def test_the_exams_impacts(law, kind):
    """Seed 004's exam: the centred knife-edge follower, h = 16 mm over δ0 = 120°, after a
    dwell: constant velocity gives rigid impacts, constant acceleration and cosine soft ones
    (the notes: 有刚性冲击, 有柔性冲击, 亦有柔性冲击), the sine law none; so do the
    polynomials and the modified trapezoid."""
    m = _cycle(law, law)
    got = impacts(m)
    at_rise = [i for i in got if i.where[0] != i.where[1] and 0 in i.where]
    assert {i.kind for i in at_rise} == {kind}
    inner = [i for i in got if i.where[0] == i.where[1]]
    assert [i.kind for i in inner] == (["soft", "soft"] if law == "parabolic" else [])
    if kind == "rigid":  # the velocity jumps by h·ω/β (per unit ω): 16 mm / (2π/3)
        assert abs(at_rise[0].dv) == pytest.approx(0.016 / math.radians(120), rel=1e-14)
    if kind == "soft" and law == "cosine":  # by π²h/(2β²)
        want = math.pi**2 * 0.016 / (2 * math.radians(120) ** 2)
        assert abs(at_rise[0].da) == pytest.approx(want, rel=1e-14)


def test_a_rise_straight_into_a_return_of_the_same_cosine_has_no_impact_at_the_top():
    """The impacts come from the jumps, not from the laws' names: two cosine phases of one
    angle meet with equal accelerations, −π²h/(2β²) on each side."""
    m = _cycle("cosine", "cosine", dwell=(0.0, 120.0))
    top = next(i for i in impacts(m) if i.where == (0, 1))
    assert top.kind == "none"


def test_the_motion_over_the_cycle():
    """s is continuous over the whole turn, at every joint; a return runs the law backwards;
    at() equals each phase's own formulas inside it."""
    m = _cycle("cosine", "3-4-5", ratio=0.5)
    for phi, before, after in m.joints():
        end = m.phases[before].end
        assert m.limits(before, end, "left")[0] == pytest.approx(m.limits(after, phi, "right")[0], abs=1e-15)
    phi = np.linspace(0, 2 * math.pi, 7201)[:-1]
    s, s1, _s2, _s3 = m.at(phi)
    assert s.min() >= -1e-16 and s.max() <= 0.016 + 1e-16
    ret = m.phases[2]
    inside = (phi > ret.start) & (phi < ret.end)
    f = unit("3-4-5", (phi[inside] - ret.start) / ret.angle)[0]
    assert s[inside] == pytest.approx(0.016 * (1 - f), abs=1e-17)
    # s′ by differences over the whole turn (away from the joints)
    h = 1e-6
    joints = [p.start for p in m.phases] + [m.phases[0].start + m.phases[0].k * m.phases[0].angle]
    far = np.all(np.abs(phi[:, None] - np.array(joints)[None, :]) > 1e-4, axis=1)
    fd = (m.at(phi[far] + h)[0] - m.at(phi[far] - h)[0]) / (2 * h)
    assert np.max(np.abs(fd - s1[far])) < 1e-9


def test_complex_steps_go_through_the_laws():
    """Every law takes complex cam angles (its pieces chosen by the real part), so that the
    tests can differentiate the geometry by complex step to rounding."""
    m = _cycle("modified trapezoid", "4-5-6-7", ratio=2.0)
    phi = np.linspace(0.01, 6.27, 500)
    step = 1e-30
    s1 = np.imag(m.at(phi + 1j * step)[0]) / step
    assert np.max(np.abs(s1 - m.at(phi)[1])) < 1e-15
