"""Offset crank-slider by the time-ratio coefficient K and the stroke H (seed 004, 8-27;
seed 002's four variants).

The slider's extremes C₁ (crank and rod folded, AC₁ = BC − AB) and C₂ (stretched,
AC₂ = BC + AB) are H apart on the guide, and the crank pivot A sees them under θ: it lies
on the circle through C₁, C₂ on the diameter C₂P (C₁P ⊥ the guide, ∠C₁C₂P = 90° − θ), at
the height e (the offset) over the guide. With u = ∠AC₂C₁ + θ/2, by the sine rule

    AB = H·cos u / (2·cos(θ/2)),   BC = H·sin u / (2·sin(θ/2)),   e = (BC − AB)·sin(u + θ/2),

for θ/2 < u < 90° − θ/2: at the one end the rod is as long as the crank (λ = AB/BC = 1),
at the other the rod stands across the guide at C₁ (AB + e = BC). Seed 002's relative
figures follow: λ = tan(θ/2)/tan u (its formula (7) turned round), ε = e/AB, the largest
pressure angle (on the return stroke, the crank across the guide on the far side)
δ_m = arcsin((AB + e)/BC), and the pressure angle where the working stroke begins, p·H
before its end. Each variant fixes u by one equation, solved in closed form (λ, AB, BC)
or over the whole interval by bracketing (e, ε, δ_m, δ_p): every root is a mechanism.

>>> fam = SliderFamily(1.5, 0.05)
>>> (u,) = roots(fam.equation("e", 0.02), fam.lo, fam.hi)
>>> m = fam.members(np.array([u]))
>>> round(float(m["AB"][0]), 6), round(float(m["BC"][0]), 6), round(math.degrees(m["delta_m"][0]), 4)
(0.021507, 0.046517, 63.1624)
"""

from __future__ import annotations

import math

import numpy as np

from plans.fmt import num
from plans.geometry import golden_min
from plans.synthesis.design import (
    Curve,
    Design,
    Mark,
    Problem,
    Solution,
    crank_marks,
    impossible,
    merged,
    right_angle_marks,
    theta_of,
)
from plans.synthesis.roots import SAMPLES, ranges, roots

#: the requirement that fixes u, by the file's key: (figure of the members, closed form)
FIXING = {"AB": "AB", "BC": "BC", "lambda": "lambda", "e": "e", "eps": "eps",
          "delta_m": "delta_m", "delta_p": "delta_p"}
#: seed 002's variant of each requirement
VARIANT = {"lambda": 1, "eps": 2, "delta_m": 3, "delta_p": 4}


class SliderFamily:
    """The offset crank-sliders of one K and stroke H: C₁ = −H/2, C₂ = +H/2 on the guide
    (the x-axis), A above it beyond C₁. ``p``: where the working stroke begins, as a
    fraction of H before its end (seed 002's S_p = p·S_max)."""

    def __init__(self, K: float, H: float, p: float = 0.0):
        self.K, self.H, self.p = K, H, p
        self.theta = theta_of(K)
        self.lo, self.hi = self.theta / 2, math.pi / 2 - self.theta / 2

    def lengths(self, u):
        t = self.theta / 2
        return self.H * np.cos(u) / (2 * math.cos(t)), self.H * np.sin(u) / (2 * math.sin(t))

    def pivot(self, u):
        a, b = self.lengths(u)
        return -self.H / 2 + (b - a) * np.exp(1j * (math.pi - self.theta / 2 - u))

    def members(self, u) -> dict[str, np.ndarray]:
        """Each member's links and figures (angles in rad)."""
        u = np.asarray(u, dtype=float)
        a, b = self.lengths(u)
        A = self.pivot(u)
        e = A.imag
        with np.errstate(all="ignore"):
            delta_m = np.arcsin(np.clip((a + e) / b, -1, 1))
            beta_n = np.arcsin(np.clip(e / (b - a), -1, 1))
            delta_w = np.maximum(beta_n, np.arcsin(np.clip(np.abs(a - e) / b, 0, 1)))
            delta_p = self._start(a, b, e)
        ok = (u > self.lo) & (u < self.hi) & (a + e < b * (1 - 1e-12)) & (e > 0)
        return {"AB": a, "BC": b, "e": e, "lambda": a / b, "eps": e / a, "delta_m": delta_m,
                "delta_w": delta_w, "delta_p": delta_p, "ok": ok}

    def _start(self, a, b, e):
        """The pressure angle where the working stroke begins: the slider p·H before the
        far extreme, the crank on the guide's side of the line from A to the slider (the
        slow stroke passes there)."""
        xf = np.sqrt((b + a) ** 2 - e * e)
        Cp = (xf - self.p * self.H) - 1j * e  # A at the origin, the guide at y = −e
        d0 = np.abs(Cp)
        x0 = (a * a - b * b + d0 * d0) / (2 * d0)
        h0 = np.sqrt(np.maximum(a * a - x0 * x0, 0.0))
        w = Cp / d0
        B = (x0 - 1j * h0) * w  # clockwise of A→C: the working stroke's side
        return np.arcsin(np.clip(np.abs(B.imag + e) / b, 0, 1))

    def equation(self, key: str, value: float):
        """``key`` of the members minus ``value``, and where they exist, for
        :func:`plans.synthesis.roots.roots`."""
        def f(u):
            m = self.members(u)
            return m[key] - value, m["ok"]

        return f

    def quantity(self, key: str):
        def f(u):
            m = self.members(u)
            return m[key], m["ok"]

        return f


def _closed(fam: SliderFamily, key: str, value: float) -> list[float]:
    t = fam.theta / 2
    if key == "lambda":  # seed 002's (7): tan u = tan(θ/2)/λ
        u = math.atan2(math.tan(t), value)
    elif key == "AB":
        arg = 2 * value * math.cos(t) / fam.H
        u = math.acos(arg) if -1 < arg < 1 else math.nan
    else:
        arg = 2 * value * math.sin(t) / fam.H
        u = math.asin(arg) if -1 < arg < 1 else math.nan
    return [u] if fam.lo < u < fam.hi else []


def synthesise(problem: Problem) -> Design:
    """The offset crank-sliders of ``problem`` (kind "crank-slider")."""
    g = problem.given
    K, H = g["K"], g["H"]
    fam = SliderFamily(K, H, g.get("p", 0.0))
    fixed = next((k for k in FIXING if k in g), None)
    limit = g.get("delta_max")
    curve = _curve(fam)
    if fixed is not None:
        value = g[fixed]
        us = _closed(fam, fixed, value) if fixed in ("lambda", "AB", "BC") else \
            roots(fam.equation(fixed, value), fam.lo, fam.hi)
        us = [u for u in us if bool(fam.members(np.array([u]))["ok"][0])]
        if not us:
            spans = merged(ranges(fam.quantity(fixed), fam.lo, fam.hi))
            raise impossible(problem, _key(fixed), _no_member(fam, fixed, value, spans))
        found = [_solution(fam, u, problem) for u in us]
        # the least largest pressure angle first; where that is the requirement itself, the
        # working stroke's largest
        found.sort(key=lambda s: (round(s.figures["delta_m"], 9), s.figures["delta_w"]))
        why = "given"
    else:
        found = [_solution(fam, _best(fam, problem, limit), problem)]
        why = problem.criterion
    if limit is not None:
        kept = [s for s in found if s.figures["delta_m"] <= limit * (1 + 1e-12)]
        if not kept:
            least = min(s.figures["delta_m"] for s in found)
            raise impossible(problem, "delta_max_deg",
                             f"no offset crank-slider of K = {num(K)}, H = {num(H)} m"
                             f"{_with(problem, fixed)} has its largest pressure angle δ ≤ "
                             f"{num(math.degrees(limit))}°: δ is at least "
                             f"{num(math.degrees(least))}°")
        found = kept
    return Design(problem, tuple(found), 0, "only" if len(found) == 1 and fixed else why, (curve,))


def _key(key: str) -> str:
    return f"{key}_deg" if key.startswith("delta") else key


def _show(key: str, x: float) -> str:
    if key.startswith("delta"):
        return f"{num(math.degrees(x))}°"
    return f"{num(x)} m" if key in ("AB", "BC", "e") else num(x)


def _with(problem: Problem, fixed: str | None) -> str:
    if fixed is None:
        return ""
    return f", {_key(fixed)} = {_show(fixed, problem.given[fixed])}"


NAMES = {"AB": "AB", "BC": "BC", "e": "the offset e", "lambda": "λ = AB/BC",
         "eps": "ε = e/AB", "delta_m": "the largest pressure angle δ_m (return stroke)",
         "delta_p": "the pressure angle δ_p where the working stroke begins"}


def _no_member(fam: SliderFamily, key: str, value: float, spans) -> str:
    head = (f"no offset crank-slider of K = {num(fam.K)} (θ = {num(math.degrees(fam.theta))}°), "
            f"H = {num(fam.H)} m has {NAMES[key]} = {_show(key, value)}")
    if key == "delta_p":
        head += f" at p = {num(fam.p)}"
    if not spans:
        return head
    return (f"{head}: {_key(key)} must lie " + " or ".join(
        f"from {_show(key, lo)} to {_show(key, hi)}" for lo, hi in spans) + " (ends excluded)")


def _curve(fam: SliderFamily) -> Curve:
    u = np.linspace(fam.lo, fam.hi, 721)[1:-1]
    m = fam.members(u)
    return Curve("offset crank-slider", "delta_max", u, np.where(m["ok"], m["delta_m"], np.nan))


def _best(fam: SliderFamily, problem: Problem, limit) -> float:
    """u of the member with the least largest pressure angle, or with the criterion
    "size" the shortest crank and rod (AB + BC) among those within the limit."""
    u = np.linspace(fam.lo, fam.hi, SAMPLES)[1:-1]
    m = fam.members(u)
    if problem.criterion == "size":
        good = m["ok"] & (m["delta_m"] <= limit)
        if not good.any():
            least = float(np.nanmin(np.where(m["ok"], m["delta_m"], np.nan)))
            raise impossible(problem, "delta_max_deg",
                             f"no offset crank-slider of K = {num(fam.K)}, H = {num(fam.H)} m "
                             f"has its largest pressure angle δ ≤ {num(math.degrees(limit))}°: "
                             f"δ is at least {num(math.degrees(least))}°")
        size = np.where(good, m["AB"] + m["BC"], np.inf)
        cands = [float(u[int(np.argmin(size))])]
        cands += roots(fam.equation("delta_m", limit), fam.lo, fam.hi)

        def sz(x):
            mm = fam.members(np.array([x]))
            if not (mm["ok"][0] and mm["delta_m"][0] <= limit * (1 + 1e-12)):
                return math.inf
            return float(mm["AB"][0] + mm["BC"][0])

        return min(cands, key=sz)
    i = int(np.argmin(np.where(m["ok"], m["delta_m"], np.inf)))
    g = fam.quantity("delta_m")

    def f(x):
        v, ok = g(np.array([x]))
        return float(v[0]) if ok[0] else math.inf

    return golden_min(f, float(u[max(i - 1, 0)]), float(u[min(i + 1, u.size - 1)]))


def _solution(fam: SliderFamily, u: float, problem: Problem) -> Solution:
    """The member at ``u`` as the written file places it: A at the origin, the slider's
    guide at y = −e (y = +e for a crank turning clockwise, so that the slower, working
    stroke always pushes the slider away from the crank), the slider to the right."""
    m = fam.members(np.array([u]))
    a, b, e = (float(m[k][0]) for k in ("AB", "BC", "e"))
    A = complex(fam.pivot(np.array([u]))[0])
    cw = problem.options.get("sense") == "cw"

    def at(z):
        w = z - A
        return w.conjugate() if cw else w

    C1, C2 = at(-fam.H / 2 + 0j), at(fam.H / 2 + 0j)
    folded = math.atan2(-C1.imag, -C1.real)
    stretched = math.atan2(C2.imag, C2.real)
    figures = {"theta": fam.theta, "K": fam.K, "H": fam.H, "delta_m": float(m["delta_m"][0]),
               "delta_w": float(m["delta_w"][0]), "lambda": a / b, "eps": e / a, "u": u}
    if fam.p:
        figures["delta_p"] = float(m["delta_p"][0])
    points = {"A": 0j, "C1": C1, "C2": C2}
    return Solution({"AB": a, "BC": b, "e": e}, figures, points, _marks(fam, at, a, b, e, A),
                    u, 0, (folded, stretched))


def _marks(fam: SliderFamily, at, a: float, b: float, e: float, A0: complex) -> tuple[Mark, ...]:
    """Seed 004's construction (8-27): the guide and the extremes C₁, C₂ = H apart,
    C₁P ⊥ the guide and ∠C₁C₂P = 90° − θ, the circle on C₂P, the line at the offset e
    that meets it at A, AC₁ = BC − AB, AC₂ = BC + AB and AE = AC₁ on AC₂."""
    th, H = fam.theta, fam.H
    C1, C2 = at(-H / 2 + 0j), at(H / 2 + 0j)
    A = 0j
    centre = at(complex(0, H / (2 * math.tan(th))))
    P = at(complex(-H / 2, H / math.tan(th))) if th < math.pi / 2 - 1e-6 else None
    F = at(complex(A0.real, 0.0))  # the foot of the offset
    across = at(complex(-A0.real, A0.imag))  # the offset line's other point on the circle
    return (
        Mark("guide", (C1, C2), "x-x"),
        Mark("point", (C1,), "C1"), Mark("point", (C2,), "C2"),
        Mark("length", (C1, C2), "H", H),
        Mark("circle", (centre, C1)), Mark("point", (centre,), "O"),
        *right_angle_marks(C1, C2, P, th),
        Mark("line", (A, F)), Mark("length", (A, F), "e", e), Mark("line", (A, across)),
        *crank_marks(A, C1, C2, a, b, th),
    )
