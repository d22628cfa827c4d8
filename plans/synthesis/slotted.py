"""The shaper's slotted link (кулисный механизм, 导杆机构) by K and the ram's stroke H
(seed 004, the shaper of problem 10).

The crank AB drives a slide block along the slotted rocker CD; at the rocker's extreme
positions the crank stands across it, so the rocker swings through ψ = θ and

    sin(ψ/2) = AB / AC,    CD = H / (2·sin(ψ/2)),

the ram's stroke being the chord D₁D₂ of the rocker's end (a rod DE to the ram, whose
guide is level with the chord's ends' height at both extremes, keeps the stroke). The
ram's guide at the middle of the arc's sagitta, at the height

    h = CD·(1 + cos(ψ/2)) / 2

over C, makes the largest offset of D from the guide, CD·(1 − cos(ψ/2))/2, the least it
can be; the rod DE then meets the guide at most at α_max with sin α_max = that offset /
DE. The crank (or the centres' distance AC) is given; DE is given or follows from the
pressure angle allowed (10° unless given, seed 004's shaping-machine problem).

>>> d = synthesise(Problem("slotted-link", {"K": 2.0, "H": 0.3, "AB": 0.075}))
>>> {k: round(v, 6) for k, v in d.solution.lengths.items()}
{'AB': 0.075, 'AC': 0.15, 'CD': 0.3, 'h': 0.279904, 'DE': 0.115729}
"""

from __future__ import annotations

import math

from plans.fmt import num
from plans.synthesis.design import Design, Mark, Problem, Solution, impossible, theta_of

#: the rod's pressure angle on the ram where neither DE nor alpha_max_deg is given
ALPHA_DEFAULT = math.radians(10.0)


def synthesise(problem: Problem) -> Design:
    """The slotted-link shaper of ``problem`` (kind "slotted-link")."""
    g = problem.given
    K, H = g["K"], g["H"]
    theta = theta_of(K)
    half = theta / 2
    if "AB" in g:
        a = g["AB"]
        ac = a / math.sin(half)
    else:
        ac = g["AC"]
        a = ac * math.sin(half)
    cd = H / (2 * math.sin(half))
    if a + ac >= cd:
        most = cd * math.sin(half) / (1 + math.sin(half))
        key = "AB" if "AB" in g else "AC"
        value = most if key == "AB" else most / math.sin(half)
        raise impossible(problem, key, f"the slide block would run off the rocker's end D: "
                         f"AB + AC = {num(a + ac)} m is not less than CD = {num(cd)} m "
                         f"(K = {num(K)}, H = {num(H)} m): {key} must be less than {num(value)} m")
    sag = cd * (1 - math.cos(half))
    h = cd * (1 + math.cos(half)) / 2
    offset = sag / 2
    if "DE" in g:
        de = g["DE"]
        if de <= offset * (1 + 1e-9):
            raise impossible(problem, "DE", f"the rod DE = {num(de)} m cannot reach the ram's guide "
                             f"from D at its farthest, {num(offset)} m off it: DE must be longer "
                             f"than {num(offset)} m")
        alpha = math.asin(offset / de)
    else:
        alpha = g.get("alpha_max", ALPHA_DEFAULT)
        de = offset / math.sin(alpha)
    lengths = {"AB": a, "AC": ac, "CD": cd, "h": h, "DE": de}
    figures = {"theta": theta, "K": K, "H": H, "psi": theta, "alpha_max": alpha,
               "sagitta": sag}
    C = -1j * ac  # the rocker's pivot under the crank's
    t1 = complex(-math.sin(half), math.cos(half))
    t2 = complex(math.sin(half), math.cos(half))
    B1, B2 = C + ac * math.cos(half) * t1, C + ac * math.cos(half) * t2
    D1, D2 = C + cd * t1, C + cd * t2
    guide_y = C.imag + h
    E1 = complex(D1.real + math.sqrt(de * de - (guide_y - D1.imag) ** 2), guide_y)
    E2 = complex(D2.real + math.sqrt(de * de - (guide_y - D2.imag) ** 2), guide_y)
    folded = math.atan2(B1.imag, B1.real)
    other = math.atan2(B2.imag, B2.real)
    points = {"A": 0j, "C": C, "B1": B1, "B2": B2, "D1": D1, "D2": D2, "E1": E1, "E2": E2}
    sol = Solution(lengths, figures, points, _marks(points, a, cd, h, half, sag), None, 0,
                   (folded, other))
    return Design(problem, (sol,), 0, "only")


def _marks(p: dict[str, complex], a: float, cd: float, h: float, half: float,
           sag: float) -> tuple[Mark, ...]:
    """The crank circle, the rocker's extreme positions touching it (the crank across
    the rocker there), ψ at C, the arc of D with its chord D₁D₂ = H and its sagitta, the
    ram's guide through the sagitta's middle, and the ram's extremes E₁, E₂."""
    A, C = p["A"], p["C"]
    top = C + 1j * cd
    mid_chord = C + 1j * cd * math.cos(half)
    guide = C + 1j * h
    span = abs(p["E2"] - p["D1"]) + cd * 0.2
    return (
        Mark("circle", (A, A + a)),
        Mark("point", (A,), "A"), Mark("point", (C,), "C"),
        Mark("thin", (C, p["D1"])), Mark("thin", (C, p["D2"])),
        Mark("line", (A, p["B1"])), Mark("line", (A, p["B2"])),
        Mark("point", (p["B1"],), "B1"), Mark("point", (p["B2"],), "B2"),
        Mark("angle", (C, p["D2"], p["D1"]), "ψ = θ", 2 * half),
        Mark("arc", (C, p["D2"], p["D1"])),
        Mark("point", (p["D1"],), "D1"), Mark("point", (p["D2"],), "D2"),
        Mark("line", (p["D1"], p["D2"])),
        Mark("line", (mid_chord, top)), Mark("length", (mid_chord, top), "f", sag),
        Mark("guide", (complex(p["D1"].real - 0.1 * cd, guide.imag),
                       complex(p["D1"].real + span, guide.imag)), "x-x"),
        Mark("length", (C, guide), "h", h),
        Mark("thin", (p["D1"], p["E1"])), Mark("thin", (p["D2"], p["E2"])),
        Mark("point", (p["E1"],), "E1"), Mark("point", (p["E2"],), "E2"),
        Mark("length", (p["E1"], p["E2"]), "H", abs(p["E2"] - p["E1"])),
    )
