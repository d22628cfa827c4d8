"""Synthesis by K and by positions against references written apart from the production code
(closed forms and 40-digit solves in mpmath, the seed article's own equations), the seeds'
worked problems, and the engine's re-analysis of every answer.

Seed 004's answers are graphical (and its extracted text garbles digits): the tests pin the
exact values and the difference from the text's figures, which README states."""

from __future__ import annotations

import math
from dataclasses import replace

import mpmath as mp
import numpy as np
import pytest

from plans.errors import InputError
from plans.synthesis import check, read_pairs, synthesise
from plans.synthesis.positions import circumcentre
from plans.synthesis.rocker import RockerFamily, limit_theta
from plans.synthesis.roots import brent, extremes, golden_min, ranges, roots
from plans.synthesis.slider import SliderFamily

mp.mp.dps = 40
REL = 1e-12


def close(a, b, rel=REL):
    return abs(float(a) - float(b)) <= rel * max(abs(float(b)), 1e-300)


def design(*words):
    return synthesise(read_pairs(list(words)))


def every(d):
    """Each solution of ``d`` as the chosen one."""
    return [replace(d, chosen=i) for i in range(len(d.solutions))]


# --------------------------------------------------------------------------------------
# references, written apart from plans/synthesis
# --------------------------------------------------------------------------------------

def ref_rocker(K, psi_deg, c, a=None, b=None):
    """Seed 004's construction in mpmath: D at the origin, C1 and C2 on the rocker's circle,
    the crank pivot A where the circles about C1 (radius b − a) and C2 (b + a) meet, a or
    b from the cosine rule in the triangle AC1C2; every A found, with its frame and γmin."""
    K, c = mp.mpf(K), mp.mpf(c)
    th = mp.pi * (K - 1) / (K + 1)
    psi = mp.radians(psi_deg)
    C1 = c * mp.expj(mp.pi / 2 + psi / 2)
    C2 = c * mp.expj(mp.pi / 2 - psi / 2)
    L = abs(C2 - C1)
    if a is None:
        b = mp.mpf(b)
        a = mp.sqrt((L**2 - 2 * b**2 * (1 - mp.cos(th))) / (2 * (1 + mp.cos(th))))
    else:
        a = mp.mpf(a)
        b = mp.sqrt((L**2 - 2 * a**2 * (1 + mp.cos(th))) / (2 * (1 - mp.cos(th))))
    r1, r2 = b - a, b + a
    x = (r1**2 - r2**2 + L**2) / (2 * L)  # along C1→C2
    h = mp.sqrt(r1**2 - x**2)
    out = []
    for s in (1, -1):
        A = C1 + (x + 1j * s * h) * (C2 - C1) / L
        d = abs(A)
        g1 = mp.acos((b**2 + c**2 - (d - a) ** 2) / (2 * b * c))
        g2 = mp.acos((b**2 + c**2 - (d + a) ** 2) / (2 * b * c))
        gam = min(g1, mp.pi - g1, g2, mp.pi - g2)
        out.append({"AB": a, "BC": b, "AD": d, "gamma": gam})
    return out


def ref_slider_offset(K, H, e):
    """Seed 004's 8-27 in mpmath: the line at the offset e meets the circle through C1, C2
    that sees them under θ."""
    K, H, e = mp.mpf(K), mp.mpf(H), mp.mpf(e)
    th = mp.pi * (K - 1) / (K + 1)
    R = H / (2 * mp.sin(th))
    yc = R * mp.cos(th)
    A = mp.mpc(-mp.sqrt(R**2 - (e - yc) ** 2), e)
    r1, r2 = abs(A - (-H / 2)), abs(A - H / 2)
    a, b = (r2 - r1) / 2, (r1 + r2) / 2
    return a, b, mp.asin((a + e) / b)


def seed002_variant1(K, H, lam):
    """Seed 002's variant I as the article writes it: (4), (7), (8), (11)."""
    K, H, lam = mp.mpf(K), mp.mpf(H), mp.mpf(lam)
    th = mp.pi * (K - 1) / (K + 1)
    R = H * lam / (2 * mp.cos(th / 2) * mp.sqrt(lam**2 + mp.tan(th / 2) ** 2))
    eps = (1 - lam**2) * R * mp.sin(th) / (H * lam**2)
    return R, R / lam, eps * R


def mp_all_roots(f, lo, hi, n=4000):
    """Every root of ``f`` on (lo, hi): a 40-digit scan and mpmath's bisection (anderson)
    of each change of sign."""
    xs = [lo + (hi - lo) * mp.mpf(i) / n for i in range(1, n)]
    vs = [f(x) for x in xs]
    out = []
    for x0, x1, v0, v1 in zip(xs, xs[1:], vs, vs[1:], strict=False):
        if v0 == 0:
            out.append(x0)
        elif v0 * v1 < 0:
            out.append(mp.findroot(f, (x0, x1), solver="anderson"))
    return out


# --------------------------------------------------------------------------------------
# the root finder
# --------------------------------------------------------------------------------------

def test_every_root_is_found_a_double_one_too():
    def f(x):
        return (x - 0.2) * (x - 0.7) ** 2 * (x - 0.9), np.ones_like(x, bool)

    got = roots(f, 0.0, 1.0)
    assert len(got) == 3
    assert got[0] == pytest.approx(0.2, abs=1e-14) and got[2] == pytest.approx(0.9, abs=1e-14)
    assert got[1] == pytest.approx(0.7, abs=1e-7)  # a double root: as precise as its square allows


def test_roots_only_where_the_function_is_defined():
    def f(x):
        return np.sin(10 * x), x < 0.5  # roots at k·π/10: 0.314 inside, 0.628 beyond

    assert roots(f, 0.1, 1.0) == [pytest.approx(math.pi / 10, abs=1e-15)]


def test_brent_golden_and_ranges():
    assert brent(lambda x: x**3 - 2, 0.0, 2.0, -2.0, 6.0) == pytest.approx(2 ** (1 / 3), rel=1e-15)
    assert golden_min(lambda x: (x - 0.25) ** 2 + 1, 0, 1) == pytest.approx(0.25, abs=1e-7)
    lo, _, hi, _ = extremes(lambda x: (np.sin(x), np.ones_like(x, bool)), 0, math.pi)
    assert lo == pytest.approx(0.0, abs=1e-12) and hi == pytest.approx(1.0, rel=1e-14)
    spans = ranges(lambda x: (x * x, (x < 0.3) | (x > 0.6)), 0.0, 1.0)
    assert spans[0] == (pytest.approx(0.0), pytest.approx(0.09, rel=1e-9))
    assert spans[1] == (pytest.approx(0.36, rel=1e-9), pytest.approx(1.0))


# --------------------------------------------------------------------------------------
# seed 004's worked problems
# --------------------------------------------------------------------------------------

def test_seed004_example_8_5_crank_rocker_with_its_coupler():
    """CD = 290 mm, ψ = 32°, K = 1.25, BC = 260 mm: θ = 20°, AB = 67 mm and AD ≈ 250 mm on the
    text's drawing; exactly AB = 66.981 mm and, of the two assemblies, AD = 261.013 mm
    (A on D's side of the chord: the text's, 4.4 % over its 250) or 467.64 mm."""
    d = design("crank-rocker", "K=1.25", "psi_deg=32", "CD=0.29", "BC=0.26")
    assert math.degrees(d.solution.figures["theta"]) == pytest.approx(20.0, rel=1e-15)
    ref = ref_rocker(1.25, 32, 0.29, b=0.26)
    assert len(d.solutions) == 2
    got = sorted(d.solutions, key=lambda s: s.lengths["AD"])
    want = sorted(ref, key=lambda r: r["AD"])
    for s, r in zip(got, want, strict=True):
        for k in ("AB", "BC", "AD"):
            assert close(s.lengths[k], r[k])
        assert close(s.figures["gamma_min"], r["gamma"])
    assert got[0].lengths["AB"] * 1000 == pytest.approx(66.981, abs=5e-4)
    assert got[0].lengths["AD"] * 1000 == pytest.approx(261.013, abs=5e-4)
    assert got[0].lengths["AD"] / 0.250 - 1 == pytest.approx(0.0441, abs=5e-4)
    for one in every(d):
        assert check(one).ok


def test_seed004_crusher_8_25():
    """K = 1.2, CD = 300 mm, ψ = 35°, AB = 80 mm: the text reads BC ≈ 310 mm and γmin = 45°
    off its drawing; exactly BC = 303.678 mm (the text 2.1 % over) and γmin = 44.64° with
    AD = 309.29 mm (the other assembly: AD = 499.03 mm, γmin = 32.86°)."""
    d = design("crank-rocker", "K=1.2", "psi_deg=35", "CD=0.3", "AB=0.08")
    assert math.degrees(d.solution.figures["theta"]) == pytest.approx(16.3636364, rel=1e-8)
    ref = sorted(ref_rocker(1.2, 35, 0.3, a=0.08), key=lambda r: -r["gamma"])
    for s, r in zip(d.solutions, ref, strict=True):
        for k in ("AB", "BC", "AD"):
            assert close(s.lengths[k], r[k])
        assert close(s.figures["gamma_min"], r["gamma"])
    best = d.solution
    assert best.lengths["BC"] * 1000 == pytest.approx(303.678, abs=5e-4)
    assert math.degrees(best.figures["gamma_min"]) == pytest.approx(44.640, abs=5e-4)
    assert 0.310 / best.lengths["BC"] - 1 == pytest.approx(0.0208, abs=5e-4)
    assert check(d).ok


def test_seed004_shaper():
    """K = 2, H = 300 mm, AB = 75 mm: ψ = θ = 60°, AC = 150, CD = 300 and the ram's guide
    h = 279.9 mm over C, as the text gives them."""
    d = design("slotted-link", "K=2", "H=0.3", "AB=0.075")
    L = d.solution.lengths
    half = mp.pi / 6
    assert close(L["AC"], mp.mpf("0.075") / mp.sin(half))
    assert close(L["CD"], mp.mpf("0.3") / (2 * mp.sin(half)))
    assert close(L["h"], L["CD"] * (1 + mp.cos(half)) / 2)
    assert round(L["AC"] * 1000, 6) == 150.0 and round(L["CD"] * 1000, 6) == 300.0
    assert L["h"] * 1000 == pytest.approx(279.9, abs=0.01)
    got = check(d)
    assert got.ok and {r.name for r in got.rows} >= {"K", "θ", "H", "αmax", "ψ"}


def test_seed004_offset_crank_slider_8_27():
    """K = 1.5, H = 50 mm, e = 20 mm: θ = 36°; exactly AB = 21.507 mm, BC = 46.517 mm and
    the largest pressure angle 63.16° (the text as extracted reads AB = 17 mm and 62.7°)."""
    d = design("crank-slider", "K=1.5", "H=0.05", "e=0.02")
    a, b, delta = ref_slider_offset(1.5, 0.05, 0.02)
    s = d.solution
    assert math.degrees(s.figures["theta"]) == pytest.approx(36.0, rel=1e-14)
    assert close(s.lengths["AB"], a) and close(s.lengths["BC"], b)
    assert close(s.figures["delta_m"], delta)
    assert math.degrees(s.figures["delta_m"]) == pytest.approx(63.162, abs=5e-4)
    assert check(d).ok


# --------------------------------------------------------------------------------------
# seed 002's four variants, each on a worked example of our own
# --------------------------------------------------------------------------------------

K, H = "1.1", "0.2"  # a press's quick return: θ = 8.571°


def test_seed002_variant_1_rod_ratio():
    d = design("crank-slider", f"K={K}", f"H={H}", "lambda=0.3")
    R, L, E = seed002_variant1(K, H, "0.3")
    s = d.solution
    assert close(s.lengths["AB"], R) and close(s.lengths["BC"], L) and close(s.lengths["e"], E)
    got = check(d)
    assert got.ok and {r.name for r in got.rows} >= {"K", "θ", "H"}


def test_seed002_variant_2_offset_ratio():
    """ε given: seed 002's (1) solved for λ (a 40-digit scan): one root, θ rising with λ."""
    d = design("crank-slider", f"K={K}", f"H={H}", "eps=0.5")
    th = mp.pi * (mp.mpf(K) - 1) / (mp.mpf(K) + 1)
    eps = mp.mpf("0.5")

    def eq1(lam):
        return mp.asin(eps * lam / (1 - lam)) - mp.asin(eps * lam / (1 + lam)) - th

    lams = mp_all_roots(eq1, mp.mpf(0), 1 / (1 + eps))
    assert len(lams) == len(d.solutions) == 1
    R, L, E = seed002_variant1(K, H, lams[0])
    s = d.solution
    assert close(s.lengths["AB"], R) and close(s.lengths["BC"], L) and close(s.lengths["e"], E)
    assert close(s.lengths["e"] / s.lengths["AB"], eps)
    assert check(d).ok


def seed002_variant3(K, H, delta_m):
    """Seed 002's variant III from the article's own chain, (12)–(20): its equation (17) in
    δ_n, with sin δ_m where the extracted text has cos δ_m (its (15) likewise has sin δ_n,
    the extraction cos δ_n: derived again from its system (14), the sine is right), every
    root by a 40-digit scan; then S1, E, R, L."""
    th = mp.pi * (mp.mpf(K) - 1) / (mp.mpf(K) + 1)
    dm = mp.radians(delta_m)
    H = mp.mpf(H)

    def eq17(dn):
        return mp.sin(dn + th) / mp.sin(dn) - 1 - 2 / (1 - mp.sin(dm)) * (mp.sin(dm) - mp.sin(dn + th))

    out = []
    for dn in mp_all_roots(eq17, mp.mpf("1e-9"), mp.pi / 2 - th - mp.mpf("1e-9")):
        dv = dn + th
        S1 = H * mp.tan(dn) / (mp.tan(dv) - mp.tan(dn))
        E = S1 * mp.tan(dv)
        R = S1 * (mp.sin(dm) / mp.cos(dv) - mp.tan(dv)) / (1 - mp.sin(dm))
        L = S1 / mp.cos(dv) + R
        if R > 0 and L > R + E:
            out.append((R, L, E))
    return out


def test_seed002_variant_3_largest_pressure_angle_both_roots():
    d = design("crank-slider", f"K={K}", f"H={H}", "delta_m_deg=35")
    want = sorted(seed002_variant3(K, H, 35), key=lambda r: float(r[0]))
    got = sorted(d.solutions, key=lambda s: s.lengths["AB"])
    assert len(want) == len(got) == 2
    for s, (R, L, E) in zip(got, want, strict=True):
        assert close(s.lengths["AB"], R) and close(s.lengths["BC"], L) and close(s.lengths["e"], E)
        assert close(s.figures["delta_m"], math.radians(35))
    for one in every(d):
        assert check(one).ok


def test_seed002_variant_3_as_extracted_does_not_close():
    """The article's (17) as the extracted text has it (cos δ_m) gives δ_n whose mechanism,
    built by its (16), (18)–(20), keeps δ_m but not θ nor the stroke (H = 1 here): the
    text's slip, not the method."""
    th = mp.pi * mp.mpf("0.1") / mp.mpf("2.1")
    dm = mp.radians(35)

    def eq17_text(dn):
        return mp.sin(dn + th) / mp.sin(dn) - 1 - 2 / (1 - mp.cos(dm)) * (mp.sin(dm) - mp.sin(dn + th))

    for dn in mp_all_roots(eq17_text, mp.mpf("1e-9"), mp.pi / 2 - th - mp.mpf("1e-9"), 1000):
        dv = dn + th
        S1 = mp.tan(dn) / (mp.tan(dv) - mp.tan(dn))
        E = S1 * mp.tan(dv)
        R = S1 * (mp.sin(dm) / mp.cos(dv) - mp.tan(dv)) / (1 - mp.sin(dm))
        L = S1 / mp.cos(dv) + R
        assert abs(mp.asin((R + E) / L) - dm) < mp.mpf("1e-30")
        theta = mp.asin(E / (L - R)) - mp.asin(E / (L + R))
        stroke = mp.sqrt((L + R) ** 2 - E**2) - mp.sqrt((L - R) ** 2 - E**2)
        assert abs(theta - th) > mp.radians(1) and abs(stroke - 1) > mp.mpf("0.5")


def start_pressure(R, L, E, H, p):
    """The rod's pressure angle p·H before the end of the slower stroke, worked in the
    crank angle: the slider's place x(φ) = R·cos φ + √(L² − (R·sin φ + E)²) (guide at −E)
    solved by mpmath for φ between 270° and the stretched extreme, where the slower stroke
    passes (the crank on the guide's side)."""
    xf = mp.sqrt((L + R) ** 2 - E**2)
    target = xf - p * H

    def x(phi):
        return R * mp.cos(phi) + mp.sqrt(L**2 - (R * mp.sin(phi) + E) ** 2) - target

    phi_far = 2 * mp.pi - mp.asin(E / (L + R))
    phi_near = mp.pi - mp.asin(E / (L - R))
    phi = mp.findroot(x, (phi_near, phi_far), solver="anderson")
    return mp.asin(abs(R * mp.sin(phi) + E) / L)


def test_seed002_variant_4_pressure_angle_where_the_working_stroke_begins_every_root():
    """δ_p = 5° at p = 0.2: over the whole family (variant I's closed form in λ, the start's
    angle worked apart), every λ where it holds: two, both found."""
    d = design("crank-slider", f"K={K}", f"H={H}", "delta_p_deg=5", "p=0.2")
    th = mp.pi * (mp.mpf(K) - 1) / (mp.mpf(K) + 1)
    Hm, p = mp.mpf(H), mp.mpf("0.2")

    def f(lam):
        R, L, E = seed002_variant1(K, H, lam)
        return start_pressure(R, L, E, Hm, p) - mp.radians(5)

    lams = mp_all_roots(f, mp.tan(th / 2) ** 2, mp.mpf(1), 600)
    assert len(lams) == len(d.solutions) == 2
    got = sorted(d.solutions, key=lambda s: s.lengths["AB"] / s.lengths["BC"])
    for s, lam in zip(got, sorted(lams), strict=True):
        R, L, E = seed002_variant1(K, H, lam)
        assert close(s.lengths["AB"], R, 1e-11) and close(s.lengths["BC"], L, 1e-11)
        assert close(s.lengths["e"], E, 1e-11)
    for one in every(d):
        got = check(one)
        assert got.ok and "δp" in {r.name for r in got.rows}


# --------------------------------------------------------------------------------------
# families, limits, impossible requirements
# --------------------------------------------------------------------------------------

@pytest.mark.parametrize("psi", [10.0, 32.0, 90.0, 150.0])
def test_a_crank_rocker_exists_below_theta_90_plus_half_psi_only(psi):
    psi = math.radians(psi)
    top = limit_theta(psi)

    def any_member(theta):
        K = (math.pi + theta) / (math.pi - theta)
        fam = RockerFamily(K, psi, 1.0)
        u = np.linspace(fam.lo, fam.hi, 200001)[1:-1]
        return any(fam.members(fam.pivot(u, s))["ok"].any() for s in (1, -1))

    assert any_member(top - math.radians(0.05))
    assert not any_member(top + math.radians(0.05))


def test_the_family_best_is_the_largest_gamma_min_over_a_million_members():
    d = design("crank-rocker", "K=1.25", "psi_deg=32", "CD=0.29")
    fam = RockerFamily(1.25, math.radians(32), 0.29)
    u = np.linspace(fam.lo, fam.hi, 1_000_000)[1:-1]
    best = 0.0
    for s in (1, -1):
        m = fam.members(fam.pivot(u, s))
        best = max(best, float(np.max(np.where(m["ok"], m["gamma_min"], -1))))
    assert d.solution.figures["gamma_min"] >= best * (1 - 1e-12)
    assert d.solution.figures["gamma_min"] == pytest.approx(best, rel=1e-9)
    assert check(d).ok


def test_criterion_size_within_a_limit():
    d = design("crank-rocker", "K=1.25", "psi_deg=32", "CD=0.29", "criterion=size",
               "gamma_min_deg=40")
    s = d.solution
    assert s.figures["gamma_min"] >= math.radians(40) * (1 - 1e-12)
    best = design("crank-rocker", "K=1.25", "psi_deg=32", "CD=0.29").solution
    size = sum(s.lengths.values())
    assert size < sum(best.lengths.values())
    assert check(d).ok


@pytest.mark.parametrize(("words", "key", "says"), [
    (["K=4", "psi_deg=32", "CD=0.29"], "K", "needs θ < 90° + ψ/2 = 106°: K from 1 to 3.865"),
    (["K=1.25", "psi_deg=32", "CD=0.29", "BC=2"], "BC", "BC must lie from"),
    (["K=1.25", "psi_deg=32", "CD=0.29", "AB=0.2"], "AB", "AB must lie from"),
    (["K=1.25", "psi_deg=32", "CD=0.29", "gamma_min_deg=50"], "gamma_min_deg",
     "its γmin is at most 44.02°"),
], ids=["K", "BC", "AB", "gamma"])
def test_an_impossible_crank_rocker_is_one_line_with_the_admissible_range(words, key, says):
    with pytest.raises(InputError) as err:
        design("crank-rocker", *words)
    (line,) = str(err.value).splitlines()
    assert line.startswith(f"command line: {key}: ") and says in line


@pytest.mark.parametrize(("words", "key", "says"), [
    (["delta_m_deg=20"], "delta_m_deg", "delta_m_deg must lie from 31.15° to 90°"),
    (["e=2"], "e", "e must lie from 0 m to 1.327 m (ends excluded)"),
    (["lambda=0.001"], "lambda", "λ = AB/BC"),
], ids=["delta_m", "e", "lambda"])
def test_an_impossible_crank_slider_is_one_line_with_the_admissible_range(words, key, says):
    with pytest.raises(InputError) as err:
        design("crank-slider", f"K={K}", f"H={H}", *words)
    (line,) = str(err.value).splitlines()
    assert line.startswith(f"command line: {key}: ") and says in line


def test_the_slider_family_spans_lambda_from_tan2_half_theta_to_1():
    fam = SliderFamily(1.5, 0.05)
    u = np.linspace(fam.lo, fam.hi, 10001)[1:-1]
    lam = fam.members(u)["lambda"]
    assert lam.min() == pytest.approx(math.tan(fam.theta / 2) ** 2, rel=1e-3)
    assert lam.max() == pytest.approx(1.0, rel=1e-3)
    e = fam.members(u)["e"]
    assert e.max() == pytest.approx(0.05 / math.tan(fam.theta), rel=1e-3)  # e < H·cot θ


def test_a_shaper_whose_block_would_leave_the_rocker_is_refused():
    with pytest.raises(InputError, match=r"AB must be less than 0\.1 m"):
        design("slotted-link", "K=2", "H=0.3", "AB=0.12")


# --------------------------------------------------------------------------------------
# positions
# --------------------------------------------------------------------------------------

def fourbar_at(a, b, c, d, phi, above=True):
    B = a * complex(math.cos(phi), math.sin(phi))
    D = complex(d, 0)
    dist = abs(D - B)
    x = (b * b - c * c + dist * dist) / (2 * dist)
    h = math.sqrt(b * b - x * x)
    return B, B + (x + 1j * (h if above else -h)) * (D - B) / dist


def test_freudenstein_three_positions_give_back_the_linkage():
    a, b, c, d = 0.05, 0.17, 0.11, 0.15
    phis = (30.0, 75.0, 120.0)
    psis = [math.degrees(math.atan2((C - d).imag, (C - d).real))
            for C in (fourbar_at(a, b, c, d, math.radians(p))[1] for p in phis)]
    got = design("function", "AD=0.15", f"phi_deg={list(phis)}", f"psi_deg={psis}")
    L = got.solution.lengths
    for k, v in (("AB", a), ("BC", b), ("CD", c)):
        assert L[k] == pytest.approx(v, rel=1e-11)
    assert check(got).ok


def test_freudenstein_two_positions_with_the_rocker_given():
    a, b, c, d = 0.05, 0.17, 0.11, 0.15
    phis = (30.0, 120.0)
    psis = [math.degrees(math.atan2((C - d).imag, (C - d).real))
            for C in (fourbar_at(a, b, c, d, math.radians(p))[1] for p in phis)]
    got = design("function", "AD=0.15", f"phi_deg={list(phis)}", f"psi_deg={psis}", "CD=0.11")
    assert got.solution.lengths["AB"] == pytest.approx(a, rel=1e-11)
    assert got.solution.lengths["BC"] == pytest.approx(b, rel=1e-11)
    free = design("function", "AD=0.15", f"phi_deg={list(phis)}", f"psi_deg={psis}")
    assert check(free).ok and free.solution.figures["gamma_min"] > 0


def test_a_position_on_the_other_assembly_is_a_branch_defect():
    a, b, c, d = 0.05, 0.17, 0.11, 0.15
    phis = (30.0, 75.0, 120.0)
    Cs = [fourbar_at(a, b, c, d, math.radians(p), above=(p != 120.0))[1] for p in phis]
    psis = [math.degrees(math.atan2((C - d).imag, (C - d).real)) for C in Cs]
    got = design("function", "AD=0.15", f"phi_deg={list(phis)}", f"psi_deg={psis}")
    with pytest.raises(InputError, match="position 3 only in its other assembly"):
        check(got)


def test_coupler_positions_give_back_the_fixed_pivots():
    A, D = complex(0.01, -0.02), complex(0.16, 0.01)
    a, b, c = 0.05, 0.17, 0.11
    pts = []
    for phi in (40.0, 80.0, 130.0):
        B = A + a * complex(math.cos(math.radians(phi)), math.sin(math.radians(phi)))
        dist = abs(D - B)
        x = (b * b - c * c + dist * dist) / (2 * dist)
        C = B + (x + 1j * math.sqrt(b * b - x * x)) * (D - B) / dist
        pts.append((B, C))
    Bs = [[z.real, z.imag] for z, _ in pts]
    Cs = [[z.real, z.imag] for _, z in pts]
    got = design("coupler", f"B={Bs}", f"C={Cs}")
    assert abs(got.solution.points["A"] - A) < 1e-14 and abs(got.solution.points["D"] - D) < 1e-14
    assert check(got).ok
    two = design("coupler", f"B={Bs[:2]}", f"C={Cs[:2]}")
    s = two.solution
    for name, (p, q) in (("A", (pts[0][0], pts[1][0])), ("D", (pts[0][1], pts[1][1]))):
        assert abs(s.points[name] - p) == pytest.approx(abs(s.points[name] - q), rel=1e-12)
    assert check(two).ok
    given = design("coupler", f"B={Bs[:2]}", f"C={Cs[:2]}", f"A={[A.real, A.imag]}",
                   f"D={[D.real, D.imag]}")
    assert given.solution.lengths["AB"] == pytest.approx(a, rel=1e-12)


def test_circumcentre():
    assert circumcentre(0j, 2 + 0j, 2j) == 1 + 1j
    assert circumcentre(0j, 1 + 0j, 2 + 0j) is None


@pytest.mark.parametrize("sense", ["ccw", "cw"])
def test_the_working_stroke_pushes_the_slider_away_from_the_crank(sense):
    """The guide goes on the side that makes the slower stroke the one away from the crank,
    whichever way it turns: the engine's position 0 starts it, and the slider's travel grows."""
    from plans.kinematics.solver import Solver

    d = design("crank-slider", "K=1.3", "H=0.1", "AB=0.04", f'sense="{sense}"')
    got = check(d)
    sv = Solver(got.mechanism)
    start, end = (float(got.cycle.output.value(sv.solve_one(x), got.mechanism))
                  for x in got.cycle.extremes)
    assert end - start == pytest.approx(0.1, rel=1e-12)
