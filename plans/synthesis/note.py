"""The explanatory note's synthesis section: every step as formula → substitution →
result with its unit, in Russian (a decimal comma) or English. Formatting only: the values
come from the :class:`~plans.synthesis.design.Design` and the engine's
:class:`~plans.synthesis.verify.Check`.
"""

from __future__ import annotations

import math

from plans.fmt import num
from plans.synthesis.design import Design
from plans.synthesis.words import WORDS, grashof_in


def _step(formula: str, substitution: str, result: str, unit: str = "") -> str:
    mid = f" = {substitution}" if substitution else ""
    unit = "" if not unit else unit if unit == "°" else f" {unit}"
    return f"- `{formula}{mid} = {result}{unit}`"


class _Fmt:
    def __init__(self, lang: str):
        self.lang = lang
        self.m = WORDS[lang]["m"]

    def n(self, x: float, d: int = 4) -> str:
        return num(x, d, self.lang)

    def deg(self, x: float, d: int = 4) -> str:
        return num(math.degrees(x), d, self.lang)


def given_line(design: Design, lang: str) -> str:
    """"K = 1.25; ψ = 32°; l_CD = 0.29 m; …": the requirements as the note states them."""
    f = _Fmt(lang)
    g = design.problem.given
    parts = []
    sym = {"K": "K", "psi": "ψ", "CD": "l_CD", "AB": "l_AB", "BC": "l_BC", "AD": "l_AD",
           "frame": "∠C1DA", "gamma_min": "[γmin]", "H": "H", "lambda": "λ", "e": "e",
           "eps": "ε", "delta_m": "δ_m", "delta_p": "δ_p", "p": "p", "delta_max": "[δ]",
           "AC": "l_AC", "DE": "l_DE", "alpha_max": "α_max"}
    for key, value in g.items():
        if key in ("phi", "psi") and isinstance(value, list):
            name = "φ" if key == "phi" else "ψ"
            parts.append(", ".join(f"{name}{i + 1} = {f.deg(v)}°" for i, v in enumerate(value)))
        elif key in ("B", "C", "A", "D"):
            pts = value if isinstance(value, list) else [value]
            parts.append(", ".join(f"{key}{i + 1 if len(pts) > 1 or key in 'BC' else ''} = "
                                   f"({f.n(z.real)}; {f.n(z.imag)}) {f.m}" for i, z in enumerate(pts)))
        elif key in ("psi", "frame", "gamma_min", "delta_m", "delta_p", "delta_max", "alpha_max"):
            parts.append(f"{sym[key]} = {f.deg(value)}°")
        elif key in ("K", "lambda", "eps", "p"):
            parts.append(f"{sym[key]} = {f.n(value)}")
        else:
            parts.append(f"{sym.get(key, key)} = {f.n(value)} {f.m}")
    return "; ".join(parts)


def note(design: Design, check, lang: str = "en") -> str:
    """The synthesis section of the explanatory note, in Markdown."""
    t = WORDS[lang]
    p = design.problem
    out = [f"## {t['title'][p.kind]}", "", f"{t['given']}: {given_line(design, lang)}.", ""]
    body = {"crank-rocker": _rocker, "crank-slider": _slider, "slotted-link": _slotted,
            "function": _function, "coupler": _coupler}[p.kind]
    out += body(design, lang)
    if check is not None:
        f = _Fmt(lang)
        out += ["", t["check"], ""]
        for r in check.rows:
            if r.unit == "°":
                want, got = f"{f.deg(r.synthesis, 10)}°", f"{f.deg(r.engine, 10)}°"
            elif r.name.startswith("C") and p.kind == "coupler":
                want, got = f"0 {f.m}", f"{f.n(r.engine, 2)} {f.m}"
            else:
                unit = f" {f.m}" if r.unit == "m" else ""
                want, got = f"{f.n(r.synthesis, 10)}{unit}", f"{f.n(r.engine, 10)}{unit}"
            out.append(f"- {t['check_row'].format(name=r.name, want=want, got=got)}")
        if check.grashof:
            out.append("- " + t["grashof_check"].format(g=grashof_in(check.grashof, lang)))
        out.append(f"- {t['worst'].format(d=num(check.worst, 2, lang), tol='1e-12')}")
    return "\n".join(out) + "\n"


def _theta(design: Design, f: _Fmt) -> str:
    K = design.problem.given["K"]
    th = design.solution.figures["theta"]
    return _step("θ = 180°·(K − 1)/(K + 1)", f"180°·({f.n(K)} − 1)/({f.n(K)} + 1)", f.deg(th), "°")


def _u_line(design: Design, f: _Fmt, eq: str) -> str:
    t = WORDS[f.lang]
    sol = design.solution
    u = f.deg(sol.param)
    if design.why in ("given", "only") and eq:
        return t["root"].format(u=u, i=design.chosen + 1, n=len(design.solutions), eq=eq)
    why = t["why"]["size" if design.why == "size" else
                   "best_slider" if design.problem.kind == "crank-slider" else "best"]
    return t["best"].format(u=u, why=why)


def _rocker(design: Design, lang: str) -> list[str]:
    t, f = WORDS[lang], _Fmt(lang)
    g, sol = design.problem.given, design.solution
    a, b, c, d = (sol.lengths[k] for k in ("AB", "BC", "CD", "AD"))
    th, psi = sol.figures["theta"], g["psi"]
    chord = 2 * c * math.sin(psi / 2)
    out = [t["theta"], "", _theta(design, f), "", t["chord"], "",
           _step("C1C2 = 2·l_CD·sin(ψ/2)", f"2·{f.n(c)}·sin {f.deg(psi / 2)}°", f.n(chord), f.m),
           "", t["circle"], ""]
    if "BC" in g:
        out += [t["cosines"], "", _step(
            "l_AB = √((C1C2² − 2·l_BC²·(1 − cos θ))/(2·(1 + cos θ)))",
            f"√(({f.n(chord)}² − 2·{f.n(b)}²·(1 − cos {f.deg(th)}°))/(2·(1 + cos {f.deg(th)}°)))",
            f.n(a), f.m)]
    elif "AB" in g:
        out += [t["cosines"], "", _step(
            "l_BC = √((C1C2² − 2·l_AB²·(1 + cos θ))/(2·(1 − cos θ)))",
            f"√(({f.n(chord)}² − 2·{f.n(a)}²·(1 + cos {f.deg(th)}°))/(2·(1 − cos {f.deg(th)}°)))",
            f.n(b), f.m)]
    else:
        eq = ""
        if "AD" in g:
            eq = f"l_AD(u) = {f.n(g['AD'])} {f.m}"
        elif "frame" in g:
            eq = f"∠C1DA(u) = {f.deg(g['frame'])}°"
        out += [t["place"], "", f"- {_u_line(design, f, eq)}",
                _step("l_AB = C1C2·cos u/(2·cos(θ/2))",
                      f"{f.n(chord)}·cos {f.deg(sol.param)}°/(2·cos {f.deg(th / 2)}°)", f.n(a), f.m),
                _step("l_BC = C1C2·sin u/(2·sin(θ/2))",
                      f"{f.n(chord)}·sin {f.deg(sol.param)}°/(2·sin {f.deg(th / 2)}°)", f.n(b), f.m)]
    pts = sol.points
    ac1, ac2 = b - a, b + a
    ang = abs(math.remainder(math.atan2((pts["D"] - pts["C1"]).imag, (pts["D"] - pts["C1"]).real)
                             - math.atan2((0 - pts["C1"]).imag, (0 - pts["C1"]).real), 2 * math.pi))
    out += ["", t["lengths"], "",
            _step("AC1 = l_BC − l_AB", f"{f.n(b)} − {f.n(a)}", f.n(ac1), f.m),
            _step("AC2 = l_BC + l_AB", f"{f.n(b)} + {f.n(a)}", f.n(ac2), f.m),
            "", t["frame_len"], "",
            _step("l_AD = √(AC1² + l_CD² − 2·AC1·l_CD·cos ∠AC1D)",
                  f"√({f.n(ac1)}² + {f.n(c)}² − 2·{f.n(ac1)}·{f.n(c)}·cos {f.deg(ang)}°)", f.n(d), f.m),
            "", t["gamma"], ""]
    g1 = math.acos((b * b + c * c - (d - a) ** 2) / (2 * b * c))
    g2 = math.acos((b * b + c * c - (d + a) ** 2) / (2 * b * c))
    out += [_step("γ1 = arccos((l_BC² + l_CD² − (l_AD − l_AB)²)/(2·l_BC·l_CD))",
                  f"arccos(({f.n(b)}² + {f.n(c)}² − ({f.n(d)} − {f.n(a)})²)/(2·{f.n(b)}·{f.n(c)}))",
                  f.deg(g1), "°"),
            _step("γ2 = arccos((l_BC² + l_CD² − (l_AD + l_AB)²)/(2·l_BC·l_CD))",
                  f"arccos(({f.n(b)}² + {f.n(c)}² − ({f.n(d)} + {f.n(a)})²)/(2·{f.n(b)}·{f.n(c)}))",
                  f.deg(g2), "°"),
            _step("γmin = min(γ1, 180° − γ1, γ2, 180° − γ2)", "", f.deg(sol.figures["gamma_min"]), "°")]
    out += _grashof_step(sol.lengths, f, t)
    return out


def _grashof_step(L: dict, f: _Fmt, t: dict) -> list[str]:
    names = ("AB", "BC", "CD", "AD")
    longest = max(names, key=lambda k: L[k])
    others = [k for k in names if k not in ("AB", longest)]
    lhs, rhs = L["AB"] + L[longest], L[others[0]] + L[others[1]]
    ok = lhs < rhs and L["AB"] == min(L[k] for k in names)
    sign = "<" if lhs < rhs else "≥"
    return ["", t["grashof"], "",
            f"- `l_AB + l_{longest} = {f.n(L['AB'])} + {f.n(L[longest])} = {f.n(lhs)} {sign} "
            f"l_{others[0]} + l_{others[1]} = {f.n(L[others[0]])} + {f.n(L[others[1]])} = "
            f"{f.n(rhs)}`: {t['crank_rocker'] if ok else t['not_crank_rocker']}"]


def _slider(design: Design, lang: str) -> list[str]:
    t, f = WORDS[lang], _Fmt(lang)
    g, sol = design.problem.given, design.solution
    a, b, e = (sol.lengths[k] for k in ("AB", "BC", "e"))
    H, th = g["H"], sol.figures["theta"]
    out = [t["theta"], "", _theta(design, f), "", t["circle_slider"], ""]
    if "lambda" in g:  # seed 002's variant I: its (7), (8), (11)
        lam = g["lambda"]
        out += [_step("l_AB = H·λ/(2·cos(θ/2)·√(λ² + tg²(θ/2)))",
                      f"{f.n(H)}·{f.n(lam)}/(2·cos {f.deg(th / 2)}°·√({f.n(lam)}² + tg² {f.deg(th / 2)}°))",
                      f.n(a), f.m),
                _step("l_BC = l_AB/λ", f"{f.n(a)}/{f.n(lam)}", f.n(b), f.m),
                _step("e = (l_BC² − l_AB²)·sin θ/H",
                      f"({f.n(b)}² − {f.n(a)}²)·sin {f.deg(th)}°/{f.n(H)}", f.n(e), f.m)]
    else:
        eq = ""
        for key, text in (("e", f"e(u) = {f.n(g.get('e', 0))} {f.m}"),
                          ("eps", f"ε(u) = {f.n(g.get('eps', 0))}"),
                          ("delta_m", f"δ_m(u) = {f.deg(g.get('delta_m', 0))}°"),
                          ("delta_p", f"δ_p(u) = {f.deg(g.get('delta_p', 0))}°"),
                          ("AB", f"l_AB(u) = {f.n(g.get('AB', 0))} {f.m}"),
                          ("BC", f"l_BC(u) = {f.n(g.get('BC', 0))} {f.m}")):
            if key in g:
                eq = text
        out += [t["place"], "", f"- {_u_line(design, f, eq)}",
                _step("l_AB = H·cos u/(2·cos(θ/2))",
                      f"{f.n(H)}·cos {f.deg(sol.param)}°/(2·cos {f.deg(th / 2)}°)", f.n(a), f.m),
                _step("l_BC = H·sin u/(2·sin(θ/2))",
                      f"{f.n(H)}·sin {f.deg(sol.param)}°/(2·sin {f.deg(th / 2)}°)", f.n(b), f.m),
                _step("e = (l_BC − l_AB)·sin(u + θ/2)",
                      f"({f.n(b)} − {f.n(a)})·sin {f.deg(sol.param + th / 2)}°", f.n(e), f.m)]
    out += ["", _step("λ = l_AB/l_BC", f"{f.n(a)}/{f.n(b)}", f.n(a / b)),
            _step("ε = e/l_AB", f"{f.n(e)}/{f.n(a)}", f.n(e / a)),
            _step("θ = arcsin(e/(l_BC − l_AB)) − arcsin(e/(l_BC + l_AB))",
                  f"arcsin({f.n(e)}/{f.n(b - a)}) − arcsin({f.n(e)}/{f.n(b + a)})", f.deg(th), "°"),
            _step("H = √((l_BC + l_AB)² − e²) − √((l_BC − l_AB)² − e²)",
                  f"√({f.n(b + a)}² − {f.n(e)}²) − √({f.n(b - a)}² − {f.n(e)}²)", f.n(H), f.m),
            "", t["pressure"], "",
            _step("δ_max = arcsin((l_AB + e)/l_BC)", f"arcsin(({f.n(a)} + {f.n(e)})/{f.n(b)})",
                  f.deg(sol.figures["delta_m"]), "°")]
    if "delta_p" in sol.figures:
        out += ["", t["pressure_p"], "",
                _step(f"δ_p (p = {f.n(g['p'])})", "", f.deg(sol.figures["delta_p"]), "°")]
    return out


def _slotted(design: Design, lang: str) -> list[str]:
    t, f = WORDS[lang], _Fmt(lang)
    g, sol = design.problem.given, design.solution
    L, F = sol.lengths, sol.figures
    half = F["theta"] / 2
    out = [t["shaper_swing"], "",
           _step("ψ = θ = 180°·(K − 1)/(K + 1)", f"180°·({f.n(g['K'])} − 1)/({f.n(g['K'])} + 1)",
                 f.deg(F["theta"]), "°")]
    if "AB" in g:
        out.append(_step("l_AC = l_AB/sin(ψ/2)", f"{f.n(L['AB'])}/sin {f.deg(half)}°", f.n(L["AC"]), f.m))
    else:
        out.append(_step("l_AB = l_AC·sin(ψ/2)", f"{f.n(L['AC'])}·sin {f.deg(half)}°", f.n(L["AB"]), f.m))
    out += [_step("l_CD = H/(2·sin(ψ/2))", f"{f.n(g['H'])}/(2·sin {f.deg(half)}°)", f.n(L["CD"]), f.m),
            "", t["shaper_guide"], "",
            _step("f = l_CD·(1 − cos(ψ/2))", f"{f.n(L['CD'])}·(1 − cos {f.deg(half)}°)",
                  f.n(F["sagitta"]), f.m),
            _step("h = l_CD·(1 + cos(ψ/2))/2", f"{f.n(L['CD'])}·(1 + cos {f.deg(half)}°)/2",
                  f.n(L["h"]), f.m)]
    if "DE" in g:
        out.append(_step("α_max = arcsin(f/(2·l_DE))", f"arcsin({f.n(F['sagitta'])}/(2·{f.n(L['DE'])}))",
                         f.deg(F["alpha_max"]), "°"))
    else:
        if "alpha_max" not in g:
            out += ["", t["alpha_default"].format(a=f.deg(F["alpha_max"])), ""]
        out.append(_step("l_DE = f/(2·sin α_max)", f"{f.n(F['sagitta'])}/(2·sin {f.deg(F['alpha_max'])}°)",
                         f.n(L["DE"]), f.m))
    return out


def _function(design: Design, lang: str) -> list[str]:
    t, f = WORDS[lang], _Fmt(lang)
    g, sol = design.problem.given, design.solution
    L = sol.lengths
    out = [t["freudenstein"], ""]
    for i, (ph, ps) in enumerate(zip(g["phi"], g["psi"], strict=True)):
        out.append(f"- `K1·cos {f.deg(ps)}° − K2·cos {f.deg(ph)}° + K3 = cos({f.deg(ph)}° − {f.deg(ps)}°)` "
                   f"({t['positions_given'].format(i=i + 1, what=f'φ{i + 1}, ψ{i + 1}')})")
    if len(g["phi"]) == 2:
        if "CD" in g or "AB" in g:
            key = "CD" if "CD" in g else "AB"
            what = f"l_{key} = {f.n(L[key])} {f.m}"
        else:
            what = f"l_CD/l_AD = {f.n(L['CD'] / L['AD'])}, γmin = {f.deg(sol.figures['gamma_min'])}°"
        out += ["", t["family2"].format(what=what)]
    K1, K2 = L["AD"] / L["AB"], L["AD"] / L["CD"]
    K3 = (L["AB"] ** 2 - L["BC"] ** 2 + L["CD"] ** 2 + L["AD"] ** 2) / (2 * L["AB"] * L["CD"])
    out += ["", f"- `K1 = {f.n(K1, 6)}; K2 = {f.n(K2, 6)}; K3 = {f.n(K3, 6)}`",
            _step("l_AB = l_AD/K1", f"{f.n(L['AD'])}/{f.n(K1, 6)}", f.n(L["AB"]), f.m),
            _step("l_CD = l_AD/K2", f"{f.n(L['AD'])}/{f.n(K2, 6)}", f.n(L["CD"]), f.m),
            _step("l_BC = √(l_AB² + l_CD² + l_AD² − 2·l_AB·l_CD·K3)",
                  f"√({f.n(L['AB'])}² + {f.n(L['CD'])}² + {f.n(L['AD'])}² − 2·{f.n(L['AB'])}·"
                  f"{f.n(L['CD'])}·{f.n(K3, 6)})", f.n(L["BC"]), f.m)]
    out += _grashof_step(L, f, t)
    return out


def _coupler(design: Design, lang: str) -> list[str]:
    t, f = WORDS[lang], _Fmt(lang)
    g, sol = design.problem.given, design.solution
    P, L = sol.points, sol.lengths
    out = [t["centres"] if len(g["B"]) == 3 else t["centres2"].format(
        what=f"γmin = {f.deg(sol.figures['gamma_min'])}°"), ""]
    for name in ("A", "D"):
        z = P[name]
        out.append(f"- `{name} = ({f.n(z.real)}; {f.n(z.imag)}) {f.m}`")
    out += ["", t["lengths"], "",
            _step("l_AB = |AB1|", "", f.n(L["AB"]), f.m), _step("l_BC = |B1C1|", "", f.n(L["BC"]), f.m),
            _step("l_CD = |DC1|", "", f.n(L["CD"]), f.m), _step("l_AD = |AD|", "", f.n(L["AD"]), f.m)]
    out += _grashof_step(L, f, t)
    return out
