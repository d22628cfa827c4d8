"""Four-bars through given positions: two or three.

**Crank and rocker angles** (kind "function"; Freudenstein): A at the origin, D at (AD, 0),
the crank's angle φ and the rocker's ψ from the frame line A→D, counter-clockwise. The loop
closes where

    K₁·cos ψ − K₂·cos φ + K₃ = cos(φ − ψ),
    K₁ = AD/AB,  K₂ = AD/CD,  K₃ = (AB² − BC² + CD² + AD²) / (2·AB·CD),

linear in K₁, K₂, K₃: three positions fix them; two leave one free, the rocker CD or the
crank AB if given, else the family over CD/AD with its best member by γmin.

**Coupler positions** (kind "coupler"; the circle-point construction of seed 004): the
coupler's joints B and C in each position given, the crank pivot A is the centre of the
circle through B₁, B₂, B₃ (where the perpendicular bisectors of B₁B₂ and B₂B₃ meet) and
D that of C₁, C₂, C₃. Two positions leave A and D each anywhere on one bisector: given,
or chosen by γmin over the two-parameter family.

Either way the linkage must move through every position on one assembly: the engine's
re-analysis solves it at each position's crank angle and finds the rocker there.

>>> d = synthesise(Problem("function", {"AD": 0.1, "phi": [math.radians(x) for x in (40, 60, 80)],
...                                      "psi": [math.radians(x) for x in (57.32488, 64.94348, 74.91511)]}))
>>> {k: round(v, 6) for k, v in d.solution.lengths.items()}
{'AB': 0.04, 'BC': 0.12, 'CD': 0.08, 'AD': 0.1}
"""

from __future__ import annotations

import itertools
import math

import numpy as np

from plans.fmt import num
from plans.geometry import cross, golden_min
from plans.synthesis.design import Curve, Design, Mark, Problem, Solution, fourbar_figures, impossible

#: the rocker CD over the frame AD that the two-position family spans: links of a size with
#: the frame (a rocker far shorter makes the crank shorter still, as γmin grows towards 90°)
RATIO = (0.2, 5.0)


def _branch(A, B, C, D):
    """The side of the line BD that C is on (the RRR group's assembly)."""
    return np.sign(cross(D - B, C - B))


# --------------------------------------------------------------------------------------
# crank and rocker angles: Freudenstein
# --------------------------------------------------------------------------------------

def _freudenstein(phi, psi):
    rows = np.array([[math.cos(q), -math.cos(p), 1.0] for p, q in zip(phi, psi, strict=True)])
    rhs = np.array([math.cos(p - q) for p, q in zip(phi, psi, strict=True)])
    return rows, rhs


def _links(d: float, K1, K2, K3):
    with np.errstate(all="ignore"):
        a, c = d / K1, d / K2
        b2 = a * a + c * c + d * d - 2 * a * c * K3
    return a, np.sqrt(np.where(b2 > 0, b2, np.nan)), c, b2


def _function(problem: Problem) -> Design:
    g = problem.given
    d, phi, psi = g["AD"], g["phi"], g["psi"]
    rows, rhs = _freudenstein(phi, psi)
    curves: tuple[Curve, ...] = ()
    if len(phi) == 3:
        if abs(np.linalg.det(rows)) < 1e-12:
            raise impossible(problem, "phi_deg", "the three positions give dependent Freudenstein "
                             "equations (two positions alike): they fix no four-bar")
        K1, K2, K3 = np.linalg.solve(rows, rhs)
        a, b, c, b2 = _links(d, K1, K2, K3)
        why = "only"
    else:
        if "CD" in g or "AB" in g:
            key = "CD" if "CD" in g else "AB"
            K = d / g[key]
            # the free one's column goes to the right-hand side
            col = 1 if key == "CD" else 0
            sign = -1.0 if key == "CD" else 1.0
            rest = [j for j in range(3) if j != col]
            x = np.linalg.solve(rows[:, rest], rhs - rows[:, col] * K)
            Ks = [0.0, 0.0, 0.0]
            Ks[col] = K
            Ks[rest[0]], Ks[rest[1]] = x
            del sign
            a, b, c, b2 = _links(d, *Ks)
            why = "only"
        else:
            t, gam, ok = _function_family(d, phi, psi, rows, rhs)
            curves = (Curve("CD/AD", "gamma_min", t, np.where(ok, gam, np.nan), "CD/AD", ""),)
            if not ok.any():
                raise impossible(problem, "psi_deg", f"no crank-rocker with CD from {RATIO[0]:g} to "
                                 f"{RATIO[1]:g} times AD moves through the two positions on one "
                                 "assembly; give CD or AB, or a third position")
            i = int(np.argmax(np.where(ok, gam, -np.inf)))

            def neg(x):
                gg, oo = _function_member(d, phi, psi, rows, rhs, np.array([x]))
                return -float(gg[0]) if oo[0] else math.inf

            best = golden_min(neg, float(t[max(i - 1, 0)]), float(t[min(i + 1, t.size - 1)]))
            if not math.isfinite(neg(best)):
                best = float(t[i])
            K2 = 1.0 / best
            x = np.linalg.solve(rows[:, [0, 2]], rhs - rows[:, 1] * K2)
            a, b, c, b2 = _links(d, x[0], K2, x[1])
            why = problem.criterion
    a, b, c, b2 = float(a), float(b), float(c), float(b2)
    if not (a > 0 and c > 0 and b2 > 0):
        if not a > 0 or not c > 0:
            what = f"AB = {num(a)} m" if not a > 0 else f"CD = {num(c)} m"
        else:
            what = f"BC² = {num(b2)} m²"
        raise impossible(problem, "psi_deg", f"the positions give {what}: no four-bar has them; "
                         "change a position")
    gam, ok = fourbar_figures(np.array(a), np.array(b), np.array(c), np.array(d))
    A, D = 0j, complex(d, 0)
    Bs = [a * complex(math.cos(p), math.sin(p)) for p in phi]
    Cs = [D + c * complex(math.cos(q), math.sin(q)) for q in psi]
    points = {"A": A, "D": D, **{f"B{i + 1}": z for i, z in enumerate(Bs)},
              **{f"C{i + 1}": z for i, z in enumerate(Cs)}}
    figures = {"gamma_min": float(gam), "crank_rocker": float(bool(ok))}
    marks = [Mark("point", (A,), "A"), Mark("point", (D,), "D"), Mark("line", (A, D))]
    for i, (B, C) in enumerate(zip(Bs, Cs, strict=True)):
        marks += [Mark("thin", (A, B)), Mark("thin", (B, C)), Mark("thin", (D, C)),
                  Mark("point", (B,), f"B{i + 1}"), Mark("point", (C,), f"C{i + 1}")]
    sol = Solution({"AB": a, "BC": b, "CD": c, "AD": d}, figures, points, tuple(marks), c / d)
    return Design(problem, (sol,), 0, why, curves)


def _function_member(d, phi, psi, rows, rhs, t):
    """γmin and validity of the two-position family at CD/AD = ``t`` (an array)."""
    K2 = 1.0 / t
    m = rows[:, [0, 2]]
    inv = np.linalg.inv(m)
    rest = rhs[:, None] - rows[:, 1][:, None] * K2[None, :]
    K1, K3 = inv @ rest
    a, b, c, b2 = _links(d, K1, K2, K3)
    gam, ok = fourbar_figures(a, b, c, np.full(t.shape, d))
    ok = ok & (b2 > 0) & (c > 0)
    sides = []
    for p, q in zip(phi, psi, strict=True):
        B = a * np.exp(1j * p)
        C = d + c * np.exp(1j * q)
        sides.append(_branch(0j, B, C, d + 0j))
    ok = ok & (sides[0] == sides[1]) & (sides[0] != 0)
    return gam, ok


def _function_family(d, phi, psi, rows, rhs):
    t = np.geomspace(*RATIO, 2001)
    gam, ok = _function_member(d, phi, psi, rows, rhs, t)
    return t, gam, ok


# --------------------------------------------------------------------------------------
# coupler positions: the circle-point construction
# --------------------------------------------------------------------------------------

def circumcentre(p: complex, q: complex, r: complex) -> complex | None:
    """The centre of the circle through three points; None where they are in line.

    >>> circumcentre(0j, 2 + 0j, 2j)
    (1+1j)
    """
    den = 2 * cross(q - p, r - p)
    if abs(den) <= 1e-14 * max(abs(q - p), abs(r - p)) ** 2:
        return None
    u, v = q - p, r - p
    return p - 1j * (abs(u) ** 2 * v - abs(v) ** 2 * u) / den


def _coupler(problem: Problem) -> Design:
    g = problem.given
    Bs, Cs = g["B"], g["C"]
    lengths = [abs(c - b) for b, c in zip(Bs, Cs, strict=True)]
    for i, L in enumerate(lengths[1:], 2):
        if abs(L - lengths[0]) > 1e-9 * lengths[0]:
            raise impossible(problem, "C", f"the coupler BC is {num(lengths[0])} m long in position 1 "
                             f"and {num(L)} m in position {i}: a rigid coupler keeps its length")
    curves: tuple[Curve, ...] = ()
    why = "only"
    if len(Bs) == 3:
        A = circumcentre(*Bs)
        D = circumcentre(*Cs)
        for name, got in (("B", A), ("C", D)):
            if got is None:
                raise impossible(problem, name, f"{name}1, {name}2, {name}3 lie on one line: no "
                                 "circle passes through them, so no fixed pivot turns "
                                 f"{name} through them")
    else:
        A, D, curves, why = _coupler_pair(problem, Bs, Cs)
        mid, normal = (Bs[0] + Bs[1]) / 2, 1j * (Bs[1] - Bs[0]) / abs(Bs[1] - Bs[0])
        param = ((A - mid) * normal.conjugate()).real
    a, b = abs(Bs[0] - A), lengths[0]
    c, d = abs(Cs[0] - D), abs(D - A)
    gam, ok = fourbar_figures(np.array(a), np.array(b), np.array(c), np.array(d))
    points = {"A": A, "D": D, **{f"B{i + 1}": z for i, z in enumerate(Bs)},
              **{f"C{i + 1}": z for i, z in enumerate(Cs)}}
    marks = [Mark("point", (A,), "A"), Mark("point", (D,), "D")]
    for i, (B, C) in enumerate(zip(Bs, Cs, strict=True)):
        marks += [Mark("thin", (B, C)), Mark("point", (B,), f"B{i + 1}"),
                  Mark("point", (C,), f"C{i + 1}")]
    for pts, centre in ((Bs, A), (Cs, D)):
        for p, q in itertools.pairwise(pts):
            mid = (p + q) / 2
            marks.append(Mark("line", (mid, centre)))
            marks.append(Mark("line", (p, q)))
        marks.append(Mark("arc", (centre, *_ccw(centre, pts[0], pts[-1]))))
    figures = {"gamma_min": float(gam), "crank_rocker": float(bool(ok))}
    sol = Solution({"AB": a, "BC": b, "CD": c, "AD": d}, figures, points, tuple(marks),
                   param if len(Bs) == 2 else None)
    return Design(problem, (sol,), 0, why, curves)


def _ccw(centre: complex, p: complex, q: complex) -> tuple[complex, complex]:
    """``p`` and ``q`` ordered so that the shorter arc between them runs
    counter-clockwise from the first."""
    return (p, q) if cross(p - centre, q - centre) >= 0 else (q, p)


def _coupler_pair(problem: Problem, Bs, Cs):
    """A and D for two positions: each given (on its bisector), or the best pair over the
    two bisectors by γmin among crank-rockers on one assembly in both positions."""
    g = problem.given
    ends = []
    for key, (p, q) in (("A", Bs), ("D", Cs)):
        mid, normal = (p + q) / 2, 1j * (q - p) / abs(q - p)
        if key in g:
            z = g[key]
            if abs(abs(z - p) - abs(z - q)) > 1e-9 * max(abs(z - p), abs(q - p)):
                name = "B" if key == "A" else "C"
                raise impossible(problem, key, f"{key} is {num(abs(z - p))} m from {name}1 and "
                                 f"{num(abs(z - q))} m from {name}2: a fixed pivot lies on the "
                                 f"perpendicular bisector of {name}1{name}2")
            ends.append((mid, normal, np.array([((z - mid) * normal.conjugate()).real])))
        else:
            span = 3.0 * max(abs(q - p), abs(Cs[0] - Bs[0]))
            ends.append((mid, normal, np.linspace(-span, span, 241)))
    (ma, na, ta), (md, nd, td) = ends
    TA, TD = np.meshgrid(ta, td, indexing="ij")
    A = ma + TA * na
    D = md + TD * nd
    gam, ok = _pair_members(A, D, Bs, Cs)
    if not ok.any():
        raise impossible(problem, "A" if "A" not in g else "D",
                         "no crank-rocker with its fixed pivots on the two perpendicular "
                         "bisectors (within three coupler lengths) moves through both "
                         "positions on one assembly; give A and D")
    i, j = np.unravel_index(int(np.argmax(np.where(ok, gam, -np.inf))), gam.shape)
    best = (float(TA[i, j]), float(TD[i, j]))
    steps = (ta[1] - ta[0] if ta.size > 1 else 0.0, td[1] - td[0] if td.size > 1 else 0.0)
    for _ in range(3):  # narrowed round the best, one parameter then the other
        for k in (0, 1):
            if not steps[k]:
                continue

            def neg(x, k=k, best=best):
                t = list(best)
                t[k] = x
                gg, oo = _pair_members(np.array([ma + t[0] * na]), np.array([md + t[1] * nd]), Bs, Cs)
                return -float(gg[0]) if oo[0] else math.inf

            x = golden_min(neg, best[k] - steps[k], best[k] + steps[k])
            if neg(x) <= neg(best[k]):
                best = (x, best[1]) if k == 0 else (best[0], x)
    best_per_a = np.max(np.where(ok, gam, -np.inf), axis=1)
    curves = (Curve("A on the bisector of B1B2", "gamma_min", ta,
                    np.where(np.isfinite(best_per_a), best_per_a, np.nan), "t_A", "m"),)
    why = "given" if len(ta) == len(td) == 1 else problem.criterion
    return ma + best[0] * na, md + best[1] * nd, curves, why


def _pair_members(A, D, Bs, Cs):
    a = np.abs(Bs[0] - A)
    b = abs(Cs[0] - Bs[0])
    c = np.abs(Cs[0] - D)
    d = np.abs(D - A)
    gam, ok = fourbar_figures(a, np.full(a.shape, b), c, d)
    s1 = _branch(A, Bs[0], Cs[0], D)
    s2 = _branch(A, Bs[1], Cs[1], D)
    return gam, ok & (s1 == s2) & (s1 != 0)


def synthesise(problem: Problem) -> Design:
    """The four-bar of ``problem`` (kind "function" or "coupler")."""
    return _function(problem) if problem.kind == "function" else _coupler(problem)
