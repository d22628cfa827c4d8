"""The explanatory note's cam section, as a student writes it: each step the formula, the
numbers substituted, the result with its unit (a decimal comma in Russian). Formatting
only: every value comes from :class:`plans.cams.design.Design`.

>>> from plans.cams.camfile import from_dict
>>> from plans.cams.design import design
>>> cam = from_dict({"follower": {"kind": "knife-edge", "stroke": 0.016}, "cam": {"base_radius": 0.03},
...                  "phases": [{"kind": "rise", "angle_deg": 120, "law": "cosine"},
...                             {"kind": "dwell", "angle_deg": 60},
...                             {"kind": "return", "angle_deg": 120, "law": "cosine"},
...                             {"kind": "dwell", "angle_deg": 60}]}, "exam.toml")
>>> text = cam_note(design(cam), "en")
>>> "`v_max = C_v·h·ω/β = 1.571·0.016·1/2.094 = 0.012 m/s`" in text
True
"""

from __future__ import annotations

import math

import numpy as np

from plans.cams.table import positions
from plans.fmt import num, unit

__all__ = ["cam_note"]

T = {
    "en": {
        "title": "Cam mechanism: {name}",
        "motion": "Motion of the follower",
        "phase": "{Kind}, φ from {a}° to {b}° (β = {beta}° = {rad} rad), {law}:",
        "coef": "(C_v = max f′, C_a = max |f″| of the law over the phase, f = s/h, u = φ/β)",
        "disc": "The eccentric disc (R = {R} mm, OA = {c} mm) gives the follower the motion",
        "disc_r0": "r0 = R + r_r − OA",
        "impacts": "Impacts at the joints of the phases",
        "rigid": "rigid impact (the velocity jumps)", "soft": "soft impact (the acceleration jumps)",
        "none": "no impact",
        "base": "Base circle and offset",
        "limits": "Allowed pressure angles: [α] = {rise}° on rise, [α′] = {ret}° on return.",
        "portrait": "The phase portrait s(ds/dφ): each position's point P = (−σ·s′; s) (σ = {sigma}); the "
                    "cam's centre must lie below the tangents drawn at the allowed angle to the vertical, "
                    "y = b + m·x, m = ±cot[α]:",
        "tangent": "touches at φ = {phi}° ({kind}):",
        "nearest": "The admissible point nearest B0 gives the smallest base radius and the best offset:",
        "at_e": "At the offset e = {e} mm the centre lies on x = −e under the lowest tangent:",
        "osc": "The smallest r0 that keeps the pressure angles within the limits with this arm and pivot "
               "(found along r0 by bisection): r0,min = {r} mm.",
        "flat": "A flat face needs a convex profile, ρ = r0 + s + s″ ≥ ρ_min:",
        "flat_osc": "A flat face needs a convex profile, ρ ≥ ρ_min; the smallest such r0 (found along r0 by "
                    "bisection): r0,min = {r} mm.",
        "taken": "Taken: r0 = {r} mm ({how}).", "given": "given", "smallest": "the smallest",
        "pressure": "Pressure angle",
        "p_flat": "The flat face is square to the follower's motion: α = 0 in every position.",
        "p_at": "Largest on {kind}, at φ = {phi}°:",
        "profile": "The profile by inversion",
        "inv": "The cam held still, the follower turned about O by −σφ: its pitch point in the cam's frame",
        "inv_t": "R = (e + i·(s0 + s))·exp(−iσφ)",
        "inv_o": "R = (A + l·τ·exp(iτΨ))·exp(−iσφ), A = −τa, Ψ = Ψ0 + ψ",
        "inv_f": "The face line in the cam's frame X·n = p (n = exp(iθ)); its envelope P = p·n + (dp/dθ)·i·n",
        "roller": "The actual profile is the envelope of the roller circles: the pitch curve offset by r_r "
                  "towards the cam, P = R + r_r·n.",
        "undercut": "No undercut where the pitch curve's smallest convex radius exceeds the roller's:",
        "knife": "A knife-edge follower's profile is the pitch curve itself; its smallest convex radius",
        "face": "The face touches from {lo} to {hi} mm {along}: its length at least {w} mm.",
        "along_axis": "from the axis", "along_pivot": "from the pivot",
        "table": "Coordinates of the numbered positions (cam's frame, mm):",
        "head": "| No. | φ, ° | {s} | pitch x | pitch y | x | y | α, ° |",
        "rise": "rise", "return": "return", "dwell": "dwell", "outer": "outer dwell", "inner": "inner dwell",
        "ok": "no undercut", "ccw": "+1, counter-clockwise", "cw": "−1, clockwise", "tan": "tan",
    },
    "ru": {
        "title": "Кулачковый механизм: {name}",
        "motion": "Закон движения толкателя",
        "phase": "{Kind}, φ от {a}° до {b}° (β = {beta}° = {rad} рад), {law}:",
        "coef": "(C_v = max f′, C_a = max |f″| закона на фазе, f = s/h, u = φ/β)",
        "disc": "Эксцентриковый диск (R = {R} мм, OA = {c} мм) сообщает толкателю движение",
        "disc_r0": "r0 = R + r_р − OA",
        "impacts": "Удары на границах фаз",
        "rigid": "жёсткий удар (скачок скорости)", "soft": "мягкий удар (скачок ускорения)",
        "none": "удара нет",
        "base": "Радиус начальной шайбы и эксцентриситет",
        "limits": "Допускаемые углы давления: [α] = {rise}° на удалении, [α′] = {ret}° на возвращении.",
        "portrait": "Фазовый портрет s(ds/dφ): точка каждого положения P = (−σ·s′; s) (σ = {sigma}); центр "
                    "кулачка должен лежать ниже касательных, проведённых под допускаемым углом к вертикали, "
                    "y = b + m·x, m = ±ctg[α]:",
        "tangent": "касается при φ = {phi}° ({kind}):",
        "nearest": "Ближайшая к B0 допустимая точка даёт наименьший радиус и лучший эксцентриситет:",
        "at_e": "При эксцентриситете e = {e} мм центр лежит на прямой x = −e ниже нижней касательной:",
        "osc": "Наименьший r0, при котором углы давления не превышают допускаемых при данных коромысле и "
               "оси (найден делением пополам): r0,min = {r} мм.",
        "flat": "Тарельчатому толкателю нужен выпуклый профиль, ρ = r0 + s + s″ ≥ ρ_min:",
        "flat_osc": "Тарельчатому толкателю нужен выпуклый профиль, ρ ≥ ρ_min; наименьший такой r0 (найден "
                    "делением пополам): r0,min = {r} мм.",
        "taken": "Принимаем r0 = {r} мм ({how}).", "given": "задан", "smallest": "наименьший",
        "pressure": "Угол давления",
        "p_flat": "Тарелка перпендикулярна направлению движения толкателя: α = 0 во всех положениях.",
        "p_at": "Наибольший на фазе «{kind}», при φ = {phi}°:",
        "profile": "Профиль кулачка методом обращения движения",
        "inv": "Кулачок остановлен, толкатель повёрнут вокруг O на −σφ: центр ролика (острие) в системе "
               "кулачка",
        "inv_t": "R = (e + i·(s0 + s))·exp(−iσφ)",
        "inv_o": "R = (A + l·τ·exp(iτΨ))·exp(−iσφ), A = −τa, Ψ = Ψ0 + ψ",
        "inv_f": "Прямая тарелки в системе кулачка X·n = p (n = exp(iθ)); её огибающая P = p·n + (dp/dθ)·i·n",
        "roller": "Действительный профиль — огибающая окружностей ролика: центровой профиль, смещённый "
                  "на r_р к кулачку, P = R + r_р·n.",
        "undercut": "Подрезания нет, если наименьший радиус выпуклого участка центрового профиля больше "
                    "радиуса ролика:",
        "knife": "Профиль для острого толкателя совпадает с центровым; наименьший радиус выпуклого участка",
        "face": "Тарелка касается профиля от {lo} до {hi} мм {along}: её длина не менее {w} мм.",
        "along_axis": "от оси", "along_pivot": "от оси качания",
        "table": "Координаты пронумерованных положений (система кулачка, мм):",
        "head": "| № | φ, ° | {s} | центр. x | центр. y | x | y | α, ° |",
        "rise": "удаление", "return": "возвращение", "dwell": "стояние", "outer": "дальнее стояние",
        "inner": "ближнее стояние",
        "ok": "подрезания нет", "ccw": "+1, против часовой стрелки", "cw": "−1, по часовой стрелке",
        "tan": "tg",
    },
}


def _step(formula: str, substitution: str, result: str, unit: str = "") -> str:
    mid = f" = {substitution}" if substitution else ""
    unit = "" if not unit else unit if unit == "°" else f" {unit}"
    return f"- `{formula}{mid} = {result}{unit}`"


def cam_note(d, lang: str = "en", section: int = 1) -> str:
    """The note's cam section in Markdown, its parts numbered from ``section``."""
    t = T[lang]
    cam, f, m = d.cam, d.cam.follower, d.motion
    vu, au = ("rad/s", "rad/s²") if f.oscillating else ("m/s", "m/s²")
    u = {"m": unit("m", lang), "mm": unit("mm", lang), "v": unit(vu, lang), "a": unit(au, lang)}

    def n(x, digits=4):  # a true minus; rounding's noise of a zero is a zero
        x = float(x)
        return num(0.0 if abs(x) < 1e-12 else x, digits, lang).replace("-", "−")

    def mm(x):
        return n(float(x) * 1000)

    def pm(x):  # in parentheses where negative, as a term of a formula
        text = mm(x)
        return f"({text})" if text.startswith("−") else text

    def deg(x):
        v = math.degrees(float(x)) % 360.0
        return n(0.0 if v > 360 - 5e-10 else v, 5)

    h = m.stroke
    h_text = n(h, 4)
    out = [f"## {section}. " + t["title"].format(name=cam.name_in(lang)), ""]
    k = 1
    # the motion -----------------------------------------------------------------------
    out += [f"### {section}.{k}. {t['motion']}", ""]
    if cam.disc is not None:
        out += [t["disc"].format(R=mm(cam.disc.radius), c=mm(cam.disc.eccentricity)) + ":", "",
                f"- `{m.law.formula}`", ""]
    for i, p in enumerate(m.phases):
        if not p.moves:
            continue
        v, a = d.speeds[i]
        law = p.law.name(lang)
        out.append(t["phase"].format(Kind=t[p.kind].capitalize(), a=deg(p.start), b=n(math.degrees(p.end), 5),
                                     beta=n(math.degrees(p.angle), 5), rad=n(p.angle), law=law))
        out.append("")
        if cam.disc is None:
            out.append(f"- `{p.law.formula}`" + (f" (u = φ/β, k = {n(p.k)})" if p.ratio != 1 else ""))
            cv, ca = v.value * p.angle / h, a.value * p.angle**2 / h
            out.append(_step("v_max = C_v·h·ω/β", f"{n(cv)}·{h_text}·{n(cam.omega)}/{n(p.angle)}",
                             n(v.value * cam.omega), u["v"]))
            out.append(_step("a_max = C_a·h·ω²/β²", f"{n(ca)}·{h_text}·{n(cam.omega)}²/{n(p.angle)}²",
                             n(a.value * cam.omega**2), u["a"]))
        else:
            out.append(_step("v_max = ω·max|ds/dφ|", f"{n(cam.omega)}·{n(v.value)}", n(v.value * cam.omega),
                             u["v"]))
            out.append(_step("a_max = ω²·max|d²s/dφ²|", f"{n(cam.omega)}²·{n(a.value)}",
                             n(a.value * cam.omega**2), u["a"]))
        out.append("")
    if cam.disc is None:
        out += [t["coef"], ""]
    # impacts --------------------------------------------------------------------------
    k += 1
    out += [f"### {section}.{k}. {t['impacts']}", ""]
    def phase(i):
        p = m.phases[i]
        return t[p.kind] if p.moves else t["outer" if p.level > h / 2 else "inner"]

    for imp in d.impacts:
        b, a = imp.where
        # a jump under the classing's threshold is rounding: written as none
        dv = imp.dv * cam.omega if imp.kind == "rigid" else 0.0
        da = imp.da * cam.omega**2 if imp.kind != "none" else 0.0
        out.append(f"- φ = {deg(imp.phi)}° ({phase(b)} → {phase(a)}): "
                   f"`Δv = {n(dv)} {u['v']}`, `Δa = {n(da)} {u['a']}`: {t[imp.kind]}")
    out.append("")
    # the base circle ------------------------------------------------------------------
    k += 1
    out += [f"### {section}.{k}. {t['base']}", ""]
    lim = cam.limits
    arr = d.arrangement
    if cam.disc is not None:
        disc = cam.disc
        out.append(_step(t["disc_r0"], f"{mm(disc.radius)} + {mm(f.roller)} − {mm(disc.eccentricity)}",
                         mm(d.r0), u["mm"]))
    elif d.portrait is not None:
        out += [t["limits"].format(rise=n(lim.rise_deg), ret=n(lim.return_deg)), "",
                t["portrait"].format(sigma=t["ccw" if cam.sense > 0 else "cw"]), ""]
        for tg in d.portrait.tangents:
            sign = "+" if tg.m > 0 else "−"
            out.append(f"- {t['tangent'].format(phi=deg(tg.phi), kind=t[m.phases[tg.phase].kind])} "
                       f"`b = s {sign} σ·s′·cot {n(tg.limit_deg)}° = {mm(tg.y)} {sign} "
                       f"{pm(-tg.x)}·{n(abs(tg.m))} = {mm(tg.b)} {u['mm']}`")
        x, y = d.portrait.centre
        out += ["", t["nearest"], "",
                _step("r0,min = √(x_O² + y_O²)", f"√({pm(x)}² + {pm(y)}²)", mm(d.best[0]), u["mm"]),
                _step("e = −x_O", "", mm(d.best[1]), u["mm"]), "",
                t["at_e"].format(e=mm(d.offset)), "",
                _step("r0 = √(e² + s0²)", f"√({mm(d.offset)}² + {mm(d.portrait.at_offset(d.offset)[1])}²)",
                      mm(d.smallest), u["mm"])]
    elif f.flat and not f.oscillating:
        out.append(t["flat"])
        if d.smallest is not None:  # min(s + s″) = ρ_min − r0,min
            out += ["", _step("r0,min = ρ_min − min(s + s″)",
                              f"{mm(lim.min_radius)} − {pm(lim.min_radius - d.smallest)}", mm(d.smallest),
                              u["mm"])]
    elif f.flat:
        out.append(t["flat_osc"].format(r=mm(d.smallest)) if d.smallest is not None else "")
    else:
        out += [t["limits"].format(rise=n(lim.rise_deg), ret=n(lim.return_deg)), "",
                t["osc"].format(r=mm(d.smallest))]
    if cam.disc is None:
        how = t["given" if cam.base_radius is not None else "smallest"]
        out += ["", t["taken"].format(r=mm(d.r0), how=how)]
    out.append("")
    # the pressure angle ---------------------------------------------------------------
    k += 1
    out += [f"### {section}.{k}. {t['pressure']}", ""]
    if f.flat:
        out += [t["p_flat"], ""]
    else:
        for kind in ("rise", "return"):
            e = d.pressure[kind]
            c = d.of_phase(e.phase, np.array([e.phi]), "right")
            s, s1 = float(c.s[0]), float(c.s1[0])
            out += [t["p_at"].format(kind=t[kind], phi=deg(e.phi)), ""]
            if f.oscillating:
                st = arr.sigma * arr.tau
                psi = n(math.degrees(arr.psi0 + s))
                minus, plus = ("−", "+") if st > 0 else ("+", "−")
                out.append(_step(f"{t['tan']} α = |l·(ψ′ − στ) + στ·a·cos Ψ| / (a·sin Ψ)",
                                 f"|{mm(arr.l)}·({n(s1)} {minus} 1) {plus} {mm(arr.a)}·cos {psi}°| / "
                                 f"({mm(arr.a)}·sin {psi}°)", n(math.tan(e.value))))
            else:
                se = arr.sigma * arr.e
                out.append(_step(f"{t['tan']} α = |s′ − σe| / (s0 + s)",
                                 f"|{mm(s1)} − {pm(se)}| / ({mm(arr.s0)} + {mm(s)})", n(math.tan(e.value))))
            out.append(_step("α", "", n(math.degrees(e.value)), "°"))
            out.append("")
    # the profile ----------------------------------------------------------------------
    k += 1
    out += [f"### {section}.{k}. {t['profile']}", ""]
    if f.flat:
        out += [t["inv_f"] + ":", "", "- `ρ = p + d²p/dθ²`", ""]
        r = d.radius["profile"]
        c = d.of_phase(r.phase, np.array([r.phi]), "right")
        if not f.oscillating:
            out.append(_step("ρ_min = r0 + s + s″", f"{mm(d.r0)} + {mm(c.s[0])} + {pm(c.s2[0])}",
                             mm(r.value), u["mm"]))
        else:
            out.append(_step("ρ_min", "", mm(r.value), u["mm"]))
        lo, hi = d.face
        along = t["along_pivot" if f.oscillating else "along_axis"]
        out += ["", t["face"].format(lo=mm(lo), hi=mm(hi), along=along, w=mm(hi - lo)), ""]
    else:
        out += [t["inv"] + ":", "", f"- `{t['inv_o' if f.oscillating else 'inv_t']}`", ""]
        r = d.radius["pitch"]
        if f.kind == "roller":
            out += [t["roller"], "", t["undercut"], ""]
            if r is not None:
                out.append(_step("ρ_min − r_r", f"{mm(r.value)} − {mm(f.roller)}", mm(r.value - f.roller),
                                 u["mm"]) + f" > 0: {t['ok']}")
        elif r is not None:
            out += [t["knife"] + ":", "", _step("ρ_min", "", mm(r.value), u["mm"])]
        out.append("")
    out += [t["table"], "", t["head"].format(s="ψ, °" if f.oscillating else "s"),
            "|" + "---|" * 8]
    phis = np.array(positions(d))
    c = d.curves(phis)
    for j, phi in enumerate(phis):
        s = n(math.degrees(c.s[j])) if f.oscillating else mm(c.s[j])
        out.append(f"| {j} | {deg(phi)} | {s} | {mm(c.pitch[j].real)} | {mm(c.pitch[j].imag)} | "
                   f"{mm(c.profile[j].real)} | {mm(c.profile[j].imag)} | {n(math.degrees(c.pressure[j]))} |")
    return "\n".join(out) + "\n"
