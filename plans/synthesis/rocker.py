"""Crank-rocker by the time-ratio coefficient K, the rocker's swing ψ and its length CD
(seed 004, example 8.5; the crusher 8-25).

The rocker's extreme positions DC₁ and DC₂ are the two where crank and coupler lie in
line: folded at C₁ (AC₁ = BC − AB), stretched at C₂ (AC₂ = BC + AB). The crank pivot A
sees the chord C₁C₂ = 2·CD·sin(ψ/2) under the angle θ between the crank's two positions,
so it lies on a circle through C₁ and C₂; the textbook finds it by drawing C₁P ⊥ C₁C₂ and
∠C₁C₂P = 90° − θ, C₂P being a diameter. With u = ∠AC₂C₁ + θ/2 (A's place on the arc),
the triangle AC₁C₂ gives by the sine rule

    AB = C₁C₂·cos u / (2·cos(θ/2)),    BC = C₁C₂·sin u / (2·sin(θ/2)),   θ/2 < u < 90°,

one arc on each side of the chord (A beyond it from D, or on D's side); u past 90° is the
same linkage mirrored. A member is a crank-rocker where AB is the shortest link of a
Grashof chain and C₁, C₂ lie on one side of the frame AD; such members exist for
θ < 90° + ψ/2 only. The frame AD, the coupler, the crank, or the frame's direction fixes
the member; without one the family is reported with its best member by γmin.

>>> fam = RockerFamily(1.25, math.radians(32), 0.29)
>>> m = fam.members(fam.pivot(np.array([1.0]), 1))
>>> round(float(m["AB"][0]), 6), round(float(m["BC"][0]), 6), bool(m["ok"][0])
(0.043855, 0.387351, True)
"""

from __future__ import annotations

import math

import numpy as np

from plans.fmt import num
from plans.geometry import cross, golden_min
from plans.synthesis.design import (
    Curve,
    Design,
    Mark,
    Problem,
    Solution,
    crank_marks,
    fourbar_figures,
    impossible,
    merged,
    right_angle_marks,
    theta_of,
)
from plans.synthesis.roots import SAMPLES, ranges, roots

#: members worked at once by :meth:`RockerFamily.gamma_min` (as the engine's sweep blocks)
BLOCK = 8192

#: the two arcs A may lie on: beyond the chord C₁C₂ from D, or on D's side
SIDES = (1, -1)
SIDE_WORDS = {1: "beyond C1C2 from D", -1: "on D's side of C1C2"}


def limit_theta(psi: float) -> float:
    """The largest θ (rad) of a crank-rocker swinging through ``psi``: 90° + ψ/2 (where
    γmin falls to 0; found over the family, held by the tests)."""
    return math.pi / 2 + psi / 2


class RockerFamily:
    """The crank-rockers of one K, ψ and rocker CD: the crank pivot A on the arcs of the
    circle through C₁ and C₂ that see the chord under θ. D is the origin, C₁ and C₂ are
    symmetric about +y, C₁ on the left; every length in m."""

    def __init__(self, K: float, psi: float, c: float):
        self.K, self.psi, self.c = K, psi, c
        self.theta = theta_of(K)
        self.chord = 2 * c * math.sin(psi / 2)
        self.C1 = c * complex(math.cos(math.pi / 2 + psi / 2), math.sin(math.pi / 2 + psi / 2))
        self.C2 = c * complex(math.cos(math.pi / 2 - psi / 2), math.sin(math.pi / 2 - psi / 2))
        self.lo, self.hi = self.theta / 2, math.pi / 2

    def lengths(self, u):
        """(AB, BC) of the members at ``u``."""
        t = self.theta / 2
        return self.chord * np.cos(u) / (2 * math.cos(t)), self.chord * np.sin(u) / (2 * math.sin(t))

    def pivot(self, u, side: int):
        """A at ``u`` on the arc ``side``: C₁ + (BC − AB)·e^{±i(180° − θ/2 − u)}, the chord
        C₁C₂ running along +x."""
        a, b = self.lengths(u)
        return self.C1 + (b - a) * np.exp(1j * side * (math.pi - self.theta / 2 - u))

    def members(self, A) -> dict[str, np.ndarray]:
        """The linkage of each pivot A (an array): its links, γmin, the frame's angle
        ∠C₁DA, and ``ok`` where it is a crank-rocker whose extremes are C₁ (folded) and
        C₂ with the crank seeing them under θ."""
        A = np.asarray(A, dtype=complex)
        c = self.c
        r1, r2 = np.abs(A - self.C1), np.abs(A - self.C2)
        a, b, d = (r2 - r1) / 2, (r1 + r2) / 2, np.abs(A)
        with np.errstate(all="ignore"):
            seen = np.abs(np.angle((self.C2 - A) / (self.C1 - A)))
            s1, s2 = np.sign(cross(-A, self.C1 - A)), np.sign(cross(-A, self.C2 - A))
            frame = np.abs(np.angle(A / self.C1))
        gamma, crank_rocker = fourbar_figures(a, b, c, d)
        ok = ((a > 1e-12 * c) & crank_rocker
              & (s1 == s2) & (s1 != 0) & (np.abs(seen - self.theta) < 1e-9))
        return {"AB": a, "BC": b, "AD": d, "CD": np.full(a.shape, c), "gamma_min": gamma,
                "frame": frame, "ok": ok}

    def gamma_min(self, u, side: int):
        """(γmin, ok) of the members at ``u`` (any shape) on arc ``side``: the family's figure
        of merit over any number of members in one call. AB and BC come from u directly (what
        :meth:`members` measures back from A), A from cos u and sin u alone, and both
        transmission angles at the crank along the frame through one arccos:
        max |cos γ| = (|BC² + CD² − AD² − AB²| + 2·AB·AD) / (2·BC·CD). Worked in blocks of
        :data:`BLOCK` members, which stay in the processor's cache."""
        u = np.asarray(u, dtype=float)
        gamma = np.empty(u.shape)
        ok = np.empty(u.shape, dtype=bool)
        flat, g, k = u.reshape(-1), gamma.reshape(-1), ok.reshape(-1)
        for start in range(0, flat.size, BLOCK):
            part = slice(start, start + BLOCK)
            self._gamma_block(flat[part], side, g[part], k[part])
        return gamma, ok

    def _gamma_block(self, u, side: int, gamma, ok) -> None:
        t = self.theta / 2
        ct, st = math.cos(t), math.sin(t)
        c = self.c
        cu, su = np.cos(u), np.sin(u)
        a = (self.chord / (2 * ct)) * cu
        b = (self.chord / (2 * st)) * su
        r = b - a
        cx = cu * ct - su * st  # cos(u + θ/2)
        sx = su * ct + cu * st  # sin(u + θ/2)
        ax = self.C1.real - r * cx
        ay = self.C1.imag + side * r * sx
        d = np.sqrt(ax * ax + ay * ay)
        # C1 and C2 on one side of AD (D the origin): the cross products of one sign
        s1 = ax * self.C1.imag - ay * self.C1.real
        s2 = ax * self.C2.imag - ay * self.C2.real
        longest = np.maximum(np.maximum(b, c), d)
        shortest = np.minimum(np.minimum(b, c), d)
        margin = (b + c + d - 2 * longest) - a
        worst = (np.abs(b * b + c * c - d * d - a * a) + 2 * a * d) / (2 * c * b)
        np.arccos(np.minimum(worst, 1.0), out=gamma)
        np.logical_and((a < shortest) & (margin > 1e-12 * (a + longest)), s1 * s2 > 0, out=ok)

    def quantity(self, key: str, side: int):
        """``key`` of the members over u on arc ``side``, as (values, defined) for the
        root finder."""
        def f(u):
            m = self.members(self.pivot(u, side))
            return m[key], m["ok"]

        return f


#: the extra requirement that fixes a member: the file's key, the members' figure
FIXING = {"AB": "AB", "BC": "BC", "AD": "AD", "frame": "frame"}


def _pivots(fam: RockerFamily, key: str, value: float) -> list[tuple[complex, int, float]]:
    """(A, arc, u) of every member where ``key`` has ``value``: AB and BC in closed form,
    the frame by the circle through D (AD) or the ray from D (its direction), each arc's
    intersections mapped to u by the sine rule."""
    out = []
    t = fam.theta / 2
    if key in ("AB", "BC"):
        arg = 2 * value * (math.cos(t) if key == "AB" else math.sin(t)) / fam.chord
        if not -1 < arg < 1:
            return []
        u = math.acos(arg) if key == "AB" else math.asin(arg)
        if not fam.lo < u < fam.hi:
            return []
        return [(complex(fam.pivot(np.array([u]), s)[0]), s, u) for s in SIDES]
    for s in SIDES:
        for u in roots(_closed(fam, key, value, s), fam.lo, fam.hi):
            out.append((complex(fam.pivot(np.array([u]), s)[0]), s, u))
    return out


def _closed(fam: RockerFamily, key: str, value: float, side: int):
    g = fam.quantity(FIXING[key], side)

    def f(u):
        v, ok = g(u)
        return v - value, ok

    return f


def synthesise(problem: Problem) -> Design:
    """The crank-rockers of ``problem`` (kind "crank-rocker"): every member that meets
    its requirements, best first by its criterion, or the family's best members."""
    g = problem.given
    K, psi, c = g["K"], g["psi"], g["CD"]
    fam = RockerFamily(K, psi, c)
    if fam.theta >= limit_theta(psi):
        kmax = (math.pi + limit_theta(psi)) / (math.pi - limit_theta(psi))
        raise impossible(problem, "K", f"K = {num(K)} gives θ = {num(math.degrees(fam.theta))}°, "
                         f"and a crank-rocker swinging through ψ = {num(math.degrees(psi))}° "
                         f"needs θ < 90° + ψ/2 = {num(90 + math.degrees(psi) / 2)}°: "
                         f"K from 1 to {num(kmax)}")
    curves = tuple(_curve(fam, s) for s in SIDES)
    fixed = next((k for k in FIXING if k in g), None)
    limit = g.get("gamma_min")
    found: list[Solution] = []
    if fixed is not None:
        value = g[fixed]
        for A, s, u in _pivots(fam, fixed, value):
            m = fam.members(np.array([A]))
            if bool(m["ok"][0]):
                found.append(_solution(fam, A, s, u, problem))
        if not found:
            spans = merged([r for s in SIDES
                            for r in ranges(fam.quantity(FIXING[fixed], s), fam.lo, fam.hi)])
            raise impossible(problem, "frame_deg" if fixed == "frame" else fixed,
                             _no_member(fam, fixed, value, spans))
        found.sort(key=lambda sol: -sol.figures["gamma_min"])
        why = "given"
    else:
        for s, curve in zip(SIDES, curves, strict=True):
            u = _best(fam, s, curve, problem, limit)
            if u is not None:
                found.append(_solution(fam, complex(fam.pivot(np.array([u]), s)[0]), s, u, problem))
        if problem.criterion == "size":
            found.sort(key=lambda sol: _size(sol))
        else:
            found.sort(key=lambda sol: -sol.figures["gamma_min"])
        why = problem.criterion
    if limit is not None:
        kept = [sol for sol in found if sol.figures["gamma_min"] >= limit * (1 - 1e-12)]
        if not kept:
            most = max((s.figures["gamma_min"] for s in found),
                       default=max(float(np.nanmax(cv.y)) for cv in curves))
            raise impossible(problem, "gamma_min_deg",
                             f"no crank-rocker of K = {num(K)}, ψ = {num(math.degrees(psi))}°, "
                             f"CD = {num(c)} m{_with(problem, fixed)} has γmin ≥ "
                             f"{num(math.degrees(limit))}°: its γmin is at most "
                             f"{num(math.degrees(most))}°")
        found = kept
    return Design(problem, tuple(found), 0, "only" if len(found) == 1 and fixed else why, curves)


def _with(problem: Problem, fixed: str | None) -> str:
    if fixed is None:
        return ""
    v = problem.given[fixed]
    return f", {'∠C1DA' if fixed == 'frame' else fixed} = " + (
        f"{num(math.degrees(v))}°" if fixed == "frame" else f"{num(v)} m")


def _no_member(fam: RockerFamily, key: str, value: float, spans) -> str:
    deg = key == "frame"

    def show(x):
        return f"{num(math.degrees(x))}°" if deg else f"{num(x)} m"

    what = "∠C1DA, the frame's angle from the folded extreme position DC1," if deg else key
    head = (f"no crank-rocker of K = {num(fam.K)} (θ = {num(math.degrees(fam.theta))}°), "
            f"ψ = {num(math.degrees(fam.psi))}°, CD = {num(fam.c)} m has {what} = {show(value)}")
    if not spans:
        return head
    parts = [f"from {show(lo)} to {show(hi)}" for lo, hi in spans]
    return f"{head}: {'frame_deg' if deg else key} must lie " + " or ".join(parts) + " (ends excluded)"


def _curve(fam: RockerFamily, side: int) -> Curve:
    u = np.linspace(fam.lo, fam.hi, 721)[1:-1]
    m = fam.members(fam.pivot(u, side))
    return Curve(SIDE_WORDS[side], "gamma_min", u, np.where(m["ok"], m["gamma_min"], np.nan))


def _size(sol: Solution) -> float:
    """The overall size a criterion compares: the sum of the four links."""
    L = sol.lengths
    return L["AB"] + L["BC"] + L["CD"] + L["AD"]


def _best(fam: RockerFamily, side: int, curve: Curve, problem: Problem, limit) -> float | None:
    """u of the best member on arc ``side``: the largest γmin, or with the criterion
    "size" the smallest sum of links among those of γmin ≥ the limit; None where the
    arc holds no crank-rocker (or none within the limit)."""
    u = np.linspace(fam.lo, fam.hi, SAMPLES)[1:-1]
    m = fam.members(fam.pivot(u, side))
    ok = m["ok"]
    if not ok.any():
        return None
    g = fam.quantity("gamma_min", side)
    if problem.criterion == "size":
        size = m["AB"] + m["BC"] + m["AD"]
        good = ok & (m["gamma_min"] >= limit)
        if not good.any():
            return None
        i = int(np.argmin(np.where(good, size, np.inf)))
        edges = roots(lambda x: (g(x)[0] - limit, g(x)[1]), fam.lo, fam.hi)
        cands = [float(u[i]), *edges]

        def sz(x):
            mm = fam.members(fam.pivot(np.array([x]), side))
            if not (mm["ok"][0] and mm["gamma_min"][0] >= limit * (1 - 1e-12)):
                return math.inf
            return float(mm["AB"][0] + mm["BC"][0] + mm["AD"][0])

        lo, hi = float(u[max(i - 1, 0)]), float(u[min(i + 1, u.size - 1)])
        cands.append(golden_min(sz, lo, hi))
        best = min(cands, key=sz)
        return best if math.isfinite(sz(best)) else None
    i = int(np.argmax(np.where(ok, m["gamma_min"], -np.inf)))

    def neg(x):
        v, o = g(np.array([x]))
        return -float(v[0]) if o[0] else math.inf

    return golden_min(neg, float(u[max(i - 1, 0)]), float(u[min(i + 1, u.size - 1)]))


def _solution(fam: RockerFamily, A: complex, side: int, u: float, problem: Problem) -> Solution:
    """The member of pivot A, placed as the written file has it: A at the origin, D on +x,
    C above AD; with its construction."""
    m = fam.members(np.array([A]))
    a, b, d = float(m["AB"][0]), float(m["BC"][0]), float(m["AD"][0])
    rot = (0 - A).conjugate() / abs(A)  # D − A along +x

    def place(z):
        return (z - A) * rot

    flip = place(fam.C1).imag < 0
    def at(z):
        w = place(z)
        return w.conjugate() if flip else w

    C1, C2, D = at(fam.C1), at(fam.C2), at(0j)
    folded = math.atan2(-C1.imag, -C1.real)  # the crank points away from C1
    stretched = math.atan2(C2.imag, C2.real)
    figures = {"theta": fam.theta, "K": fam.K, "psi": fam.psi,
               "gamma_min": float(m["gamma_min"][0]), "frame": float(m["frame"][0]), "u": u}
    points = {"A": 0j, "D": D, "C1": C1, "C2": C2}
    return Solution({"AB": a, "BC": b, "CD": fam.c, "AD": d}, figures, points,
                    _marks(fam, at, a, b, side), u, SIDES.index(side), (folded, stretched))


def _marks(fam: RockerFamily, at, a: float, b: float, side: int) -> tuple[Mark, ...]:
    """The construction of seed 004's example 8.5: the rocker's extreme positions and ψ,
    the chord C₁C₂, C₁P ⊥ C₁C₂ and ∠C₁C₂P = 90° − θ, the circle on the diameter C₂P, A on
    it seeing C₁C₂ under θ, AC₁ = BC − AB and AC₂ = BC + AB at μl, and AE = AC₁ on AC₂ so
    that EC₂ = 2·AB."""
    th = fam.theta
    C1, C2, D = at(fam.C1), at(fam.C2), at(0j)
    A = 0j
    P = at(fam.C1 + side * 1j * fam.chord / math.tan(th)) if th < math.pi / 2 - 1e-6 else None
    centre = at(fam.C1 + fam.chord / 2 + side * 1j * fam.chord / (2 * math.tan(th)))
    return (
        Mark("point", (D,), "D"), Mark("point", (C1,), "C1"), Mark("point", (C2,), "C2"),
        Mark("thin", (D, C1)), Mark("thin", (D, C2)),
        Mark("angle", (D, C1, C2), "ψ", fam.psi),
        Mark("line", (C1, C2)),
        *right_angle_marks(C1, C2, P, th),
        Mark("circle", (centre, C1), "", None),
        Mark("point", (centre,), "O"),
        *crank_marks(A, C1, C2, a, b, th),
    )
