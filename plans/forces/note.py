"""The explanatory note's force section, as seeds 000 and 001 write it: masses and weights,
inertia forces and moments, the useful resistance, each group's equilibrium equations with
their arms, its force plan's scale and the reactions read off it, the driving link and the
balancing moment, Zhukovsky's lever with its arms, the power, the motor and the gearbox.
Every step: formula → substitution → result with its unit, numbers in the language's own
way (a decimal comma in Russian). Formatting only: every value comes from
:class:`plans.forces.summary.Forces`.
"""

from __future__ import annotations

import cmath
import math

from plans.fmt import decimal, md_code, md_text, num, unit
from plans.forces.lever import joints
from plans.forces.summary import Forces, rpm_of
from plans.plan.values import plan_name

T = {
    "en": {
        "title": "Force analysis",
        "masses": "Masses and weights of the links",
        "weight": "Weight of link {i} (through its centre of mass {S}, downwards):",
        "given_m": "m{i} = {m} kg (given)",
        "inertia": "Inertia loads of the links (from the acceleration plan)",
        "phi_force": "Inertia force of link {i}, through {S}, against a_{S}:",
        "a_read": "a_{S} = π{s}·μa = {mm}·{mu} = {a} m/s²",
        "phi_moment": "Inertia moment of link {i}, against ε{i} ({sense}):",
        "pair": "Replaced by a couple of two forces ⊥ {a}{b} at {a} and {b}:",
        "shift": "Taken with the inertia force: its line shifted from {S} by h, on the side that "
                 "turns it about {S} as M_Φ{i} does:",
        "zero_phi": "The centre of mass of link {i} is on its fixed pivot {S}: its inertia force is zero.",
        "no_moments": "As the task asks, only the inertia forces are taken (no inertia moments).",
        "resistance": "Useful resistance",
        "graph": "From the graph P(S) at s = {s} m from the start of the working stroke (H = {H} m, "
                 "{stroke}):",
        "times": "{name} = {k}·G{j} = {k}·{G} = {F} N, at {p}, {rule}",
        "fixed_force": "{name} = {F} N at {p}, {rule}",
        "against velocity": "against V_{p}",
        "along velocity": "along V_{p}",
        "along guide": "along the guide",
        "against guide": "against the guide",
        "angle": "at {a}° from +x",
        "working": "working stroke",
        "idle": "idle stroke",
        "groups": "Kinetostatics of the groups (the last attached first)",
        "group": "Group of links {a} and {b} ({kind})",
        "moments_of": "Moments about {X} of link {i} (arms measured on the drawing, in m):",
        "unknown": "{R} = {expr} = {v} N",
        "plan_scale": "Force plan at μF = {mu} N/mm; the vectors of the known forces:",
        "vec": "[{n}] = {n}/μF = {F}/{mu} = {mm} mm",
        "closes": "The polygon {eq} closes with lines {l0} and {l1}; read off the plan:",
        "closes1": "The polygon closes with the vector {R}; read off the plan:",
        "read": "{R} = [{R}]·μF = {mm}·{mu} = {F} N",
        "inner": "The inner reaction from the polygon of link {a}: {R} = [{R}]·μF = {mm}·{mu} = {F} N",
        "rpr": "The whole group about {Q}: the guide's force on the block ⊥ the guide, from ΣM_{Q} = 0:",
        "crank": "Driving link {i}",
        "My": "Balancing moment from ΣM_{O}(link {i}) = 0:",
        "Fy": "Balancing force at {t} ⊥ {O}{t}:",
        "R01": "Reaction of the frame: R0{i} = −(ΣF on link {i}) = {F} N",
        "lever": "Zhukovsky's lever",
        "lever_intro": "The velocity plan turned by 90°, every load applied at the image of its point; "
        "the moments about the pole p (arms h in mm of the plan, pb = {pb} mm):",
        "lever_eq": "F_у = (Σ ±F·h) / pb = ({expr}) / {pb} = {F} N",
        "discrepancy": "Discrepancy from the force plans: δ = |F_у(lever) − F_у(plans)| / F_у(plans) = {d} %",
        "power": "Power and drive",
        "P": "P = F_у·V_{t} = {F}·{V} = {P} W",
        "P_mean": "The cycle's mean power (the crank takes no power at this position): P = M_у,mean·ω{i} = "
                  "{P} W",
        "need": "P_motor ≥ P/η = {P}/{eta} = {need} W: motor {type}, {kw} kW, n = {rpm} rpm",
        "u": "u = n_motor/n1 = {rpm}/{n1} = {u}",
        "stages2": "u > 6.3: a two-stage gearbox, u12 = 1.2·u34: u34 = √(u/1.2) = √({u}/1.2) = {u34}, "
        "u12 = 1.2·{u34} = {u12}",
        "stages1": "u ≤ 6.3: a one-stage gearbox",
        "teeth2": "z1 = z3 = 20 + Ш = {z1}; z2 = u12·z1 = {u12}·{z1} = {z2r} ≈ {z2}; "
        "z4 = u34·z3 = {u34}·{z1} = {z4r} ≈ {z4}",
        "teeth1": "z1 = 20 + Ш = {z1}; z2 = u·z1 = {u}·{z1} = {z2r} ≈ {z2}",
        "actual2": "u = (z2/z1)·(z4/z3) = {u12a}·{u34a} = {ua}; n1 = {rpm}/{ua} = {n1a} rpm; "
        "Δn1 = ({n1a} − {n1})/{n1}·100 % = {dev} %",
        "actual1": "u = z2/z1 = {ua}; n1 = {rpm}/{ua} = {n1a} rpm; Δn1 = ({n1a} − {n1})/{n1}·100 % = {dev} %",
        "nodrive": "No drive is chosen: {why}.",
        "ccw": "counter-clockwise",
        "cw": "clockwise",
    },
    "ru": {
        "title": "Силовой анализ",
        "masses": "Массы и силы тяжести звеньев",
        "weight": "Сила тяжести звена {i} (через центр масс {S}, вниз):",
        "given_m": "m{i} = {m} кг (задано)",
        "inertia": "Силы и моменты сил инерции звеньев (по плану ускорений)",
        "phi_force": "Главный вектор сил инерции звена {i}, через {S}, противоположно a_{S}:",
        "a_read": "a_{S} = π{s}·μa = {mm}·{mu} = {a} м/с²",
        "phi_moment": "Главный момент сил инерции звена {i}, противоположно ε{i} ({sense}):",
        "pair": "Заменяем парой сил, приложенных в точках {a} и {b} ⊥ {a}{b}:",
        "shift": "Учитываем вместе с силой инерции: её линию действия смещаем от {S} на h в ту "
                 "сторону, чтобы её момент относительно {S} совпадал с M_Φ{i}:",
        "zero_phi": "Центр масс звена {i} совпадает с неподвижной точкой {S}: главный вектор сил инерции "
                    "равен нулю.",
        "no_moments": "По условию учитываются только силы инерции (без моментов сил инерции).",
        "resistance": "Сила полезного сопротивления",
        "graph": "По графику P(S) при s = {s} м от начала рабочего хода (H = {H} м, {stroke}):",
        "times": "{name} = {k}·G{j} = {k}·{G} = {F} Н, в точке {p}, {rule}",
        "fixed_force": "{name} = {F} Н в точке {p}, {rule}",
        "against velocity": "против V_{p}",
        "along velocity": "по V_{p}",
        "along guide": "вдоль направляющей",
        "against guide": "против направляющей",
        "angle": "под углом {a}° к +x",
        "working": "рабочий ход",
        "idle": "холостой ход",
        "groups": "Кинетостатика групп Ассура (начиная с последней присоединённой)",
        "group": "Группа звеньев {a} и {b} ({kind})",
        "moments_of": "Моменты относительно точки {X} для звена {i} (плечи — по чертежу, в м):",
        "unknown": "{R} = {expr} = {v} Н",
        "plan_scale": "План сил в масштабе μF = {mu} Н/мм; векторы известных сил:",
        "vec": "[{n}] = {n}/μF = {F}/{mu} = {mm} мм",
        "closes": "Многоугольник {eq} замыкается прямыми {l0} и {l1}; из плана сил:",
        "closes1": "Многоугольник замыкается вектором {R}; из плана сил:",
        "read": "{R} = [{R}]·μF = {mm}·{mu} = {F} Н",
        "inner": "Внутренняя реакция — из многоугольника сил звена {a}: {R} = [{R}]·μF = {mm}·{mu} = {F} Н",
        "rpr": "Вся группа относительно точки {Q}: сила направляющей на камень ⊥ направляющей, из ΣM_{Q} = "
               "0:",
        "crank": "Ведущее звено {i}",
        "My": "Уравновешивающий момент из ΣM_{O}(звено {i}) = 0:",
        "Fy": "Уравновешивающая сила в точке {t} ⊥ {O}{t}:",
        "R01": "Реакция стойки: R0{i} = −(ΣF на звено {i}) = {F} Н",
        "lever": "Рычаг Н. Е. Жуковского",
        "lever_intro": "План скоростей, повёрнутый на 90°; силы приложены в одноимённых точках; моменты "
        "относительно полюса p (плечи h в мм плана, pb = {pb} мм):",
        "lever_eq": "F_у = (Σ ±F·h) / pb = ({expr}) / {pb} = {F} Н",
        "discrepancy": "Расхождение с планами сил: δ = |F_у(рычаг) − F_у(планы)| / F_у(планы) = {d} %",
        "power": "Мощность и привод",
        "P": "P = F_у·V_{t} = {F}·{V} = {P} Вт",
        "P_mean": "Средняя мощность за цикл (в этом положении кривошип мощности не потребляет): "
        "P = M_у,ср·ω{i} = {P} Вт",
        "need": "P_дв ≥ P/η = {P}/{eta} = {need} Вт: электродвигатель {type}, {kw} кВт, n = {rpm} об/мин",
        "u": "u = n_дв/n1 = {rpm}/{n1} = {u}",
        "stages2": "u > 6,3: двухступенчатый редуктор, u12 = 1,2·u34: u34 = √(u/1,2) = √({u}/1,2) = {u34}, "
        "u12 = 1,2·{u34} = {u12}",
        "stages1": "u ≤ 6,3: одноступенчатый редуктор",
        "teeth2": "z1 = z3 = 20 + Ш = {z1}; z2 = u12·z1 = {u12}·{z1} = {z2r} ≈ {z2}; "
        "z4 = u34·z3 = {u34}·{z1} = {z4r} ≈ {z4}",
        "teeth1": "z1 = 20 + Ш = {z1}; z2 = u·z1 = {u}·{z1} = {z2r} ≈ {z2}",
        "actual2": "u = (z2/z1)·(z4/z3) = {u12a}·{u34a} = {ua}; n1 = {rpm}/{ua} = {n1a} об/мин; "
        "Δn1 = ({n1a} − {n1})/{n1}·100 % = {dev} %",
        "actual1": "u = z2/z1 = {ua}; n1 = {rpm}/{ua} = {n1a} об/мин; Δn1 = ({n1a} − {n1})/{n1}·100 % = "
                   "{dev} %",
        "nodrive": "Привод не подобран: {why}.",
        "ccw": "против часовой стрелки",
        "cw": "по часовой стрелке",
    },
}


def _para(out: list[str], text: str) -> None:
    """A paragraph: a blank line before it, as before each list."""
    if out and out[-1]:
        out.append("")
    out.append(text)


def _deg(z) -> float:
    return math.degrees(cmath.phase(complex(z))) % 360.0


def _shown(text: str) -> float:
    """A number as a step printed it (a decimal comma, a true minus), as a reader takes it."""
    try:
        return float(text.replace(",", ".").replace("−", "-"))
    except ValueError:
        return math.nan


def force_note(F: Forces, lang: str = "en", section: int = 1, numbers: dict | None = None) -> str:
    """The force section of the note, numbered from ``section`` (Markdown). ``numbers``:
    what the kinematic sections printed (:func:`plans.note.report.note`'s), by (φ, μa):
    the accelerations, ε and V of this position are carried on as they were printed, and
    each number this section prints and carries on (a weight, an inertia force or moment,
    M_у, F_у) is carried as printed, with five digits, its result computed from the
    numbers shown (a teacher redoing a line gets its result)."""
    t = T.get(lang, T["en"])
    fa = F.analysis
    sol = fa.solution
    kin = (numbers or {}).get((sol.phi, sol.acceleration.mu), {})
    shown: dict[str, str] = {}  # this section's numbers carried on, by name
    mech = sol.mechanism
    loads = mech.loads
    d = mech.driver
    m = sol.scalar
    N = unit("N", lang)

    def n(x, digits=4):
        return num(float(x), digits, lang).replace("-", "−")

    def c(x):  # a value carried into a substitution: one digit more than a result
        return n(x, 5)

    def item(text):
        if out and out[-1] and not out[-1].startswith("- "):
            out.append("")  # a paragraph, then its list
        out.append(f"- `{md_code(text)}`")  # a load's name is the file's: no markup

    def para(text):
        if out and out[-1]:
            out.append("")
        out.append(text)

    out = [f"## {section}. {t['title']}", ""]

    def heading(text):
        out.extend(["", f"### {text}", ""])

    heading(t["masses"])
    by_name = {ld.name: ld for ld in fa.loads}
    for lid in sorted(loads.masses):
        ms = loads.masses[lid]
        if not ms.mass:
            continue
        item(t["given_m"].format(i=lid, m=n(ms.mass)))
        para(t["weight"].format(i=lid, S=ms.centre))
        shown[f"G{lid}"] = c(_shown(c(ms.mass)) * _shown(c(loads.g)))
        item(f"G{lid} = m{lid}·g = {c(ms.mass)}·{c(loads.g)} = {shown[f'G{lid}']} {N}")
    heading(t["inertia"])
    mu_a = sol.acceleration.mu
    for lid in sorted(loads.masses):
        ms = loads.masses[lid]
        S = ms.centre
        if ms.mass:
            ld = by_name.get(f"Φ{lid}")
            if ld is None:
                para(t["zero_phi"].format(i=lid, S=S))
                continue
            a = abs(m.acceleration[S])
            para(t["phi_force"].format(i=lid, S=S))
            s = plan_name(S)
            mm = kin.get(f"acceleration:π{s}") or c(a / mu_a)  # as the acceleration plan's section gave it
            a_s = kin.get(f"a_{S}") or c(_shown(mm) * _shown(c(mu_a)))
            item(t["a_read"].format(S=S, s=s, mm=mm, mu=c(mu_a), a=a_s))
            shown[f"Φ{lid}"] = c(_shown(c(ms.mass)) * _shown(a_s))
            item(f"Φ{lid} = m{lid}·a_{S} = {c(ms.mass)}·{a_s} = {shown[f'Φ{lid}']} {N}")
        ld = by_name.get(f"M_Φ{lid}")
        if ld is not None:
            eps = sol.epsilon[lid]
            para(t["phi_moment"].format(i=lid, sense=t["ccw" if ld.moment > 0 else "cw"]))
            Nm = unit("N·m", lang)
            es = kin.get(f"ε{lid}") or c(abs(eps))
            ms_ = shown[f"M_Φ{lid}"] = c(_shown(c(ms.J)) * _shown(es))
            item(f"M_Φ{lid} = J_S{lid}·ε{lid} = {c(ms.J)}·{es} = {ms_} {Nm}")
            ends = joints(mech, lid)
            phi_force = by_name.get(f"Φ{lid}")
            if loads.couples == "shift" and phi_force is not None and abs(phi_force.force) > 0:
                para(t["shift"].format(S=S, i=lid))
                size = abs(phi_force.force)
                fs = shown.get(f"Φ{lid}") or c(size)
                item(f"h = M_Φ{lid} / Φ{lid} = {ms_} / {fs} = "
                     f"{n(_shown(ms_) / _shown(fs))} {unit('m', lang)}")
            elif loads.couples == "pair" and ends is not None:
                a, b = ends
                length = abs(m.position[b] - m.position[a])
                para(t["pair"].format(a=a, b=b))
                ps = shown[f"P_Φ{lid}"] = c(_shown(ms_) / _shown(c(length)))
                item(f"P_Φ{lid} = M_Φ{lid} / l_{a}{b} = {ms_} / {c(length)} = {ps} {N}")
    if not loads.inertia_moments:
        para(t["no_moments"])
    forces = [ld for ld in fa.loads if ld.kind in ("force", "resistance")]
    if forces:
        heading(t["resistance"])
        for ld in forces:
            _resistance(out, t, ld, fa, loads, lang, item, n, N, shown)
    heading(t["groups"])
    for g in fa.groups:
        _group(out, t, g, lang, item, n, N, sol, shown)
    heading(t["crank"].format(i=d.link))
    pivot = m.position[d.pivot]
    para(t["My"].format(O=d.pivot, i=d.link))
    parts = []
    for ld in fa.crank_loads:
        mo = float((complex(ld.at - pivot).conjugate() * ld.force).imag + ld.moment)
        if mo:
            size = abs(complex(ld.force))
            what = f"{c(size)}·{c(abs(mo) / size)}" if size else c(abs(mo))
            parts.append(("− " if mo > 0 else "+ ") + what)
    expr = " ".join(parts).removeprefix("+ ") or "0"
    Nm = unit("N·m", lang)
    My = c(fa.M_y)
    item(f"M_у = −ΣM_{d.pivot}(F) = {expr} = {My} {Nm}")
    para(t["Fy"].format(t=d.tip, O=d.pivot))
    shown["F_у"] = c(_shown(My) / _shown(c(fa.crank_length)))
    item(f"F_у = M_у / l_{d.pivot}{d.tip} = {My} / {c(fa.crank_length)} = {shown['F_у']} {N}")
    item(t["R01"].format(i=d.link, F=n(abs(fa.R01))))
    heading(t["lever"])
    lv = F.lever
    pbs = kin.get(f"velocity:p{d.tip.lower()}") or c(lv.pb)  # as the velocity plan's section drew it
    para(t["lever_intro"].format(pb=pbs))
    parts = []
    for term in lv.terms:
        if term.force and round(term.arm, 3):
            fs = shown.get(term.name) or c(abs(term.force))  # a load as its own line printed it
            parts.append(("+ " if term.moment > 0 else "− ") + f"{fs}·{c(term.arm)}")
        elif term.moment and not term.force:
            parts.append(("+ " if term.moment > 0 else "− ") + c(abs(term.moment)))
    sense = 1.0 if d.omega > 0 else -1.0
    expr = " ".join(parts).removeprefix("+ ")
    shown["F_у"] = c(lv.F_y)  # the power below takes the lever's, as printed last
    item(t["lever_eq"].format(expr=expr if sense > 0 else f"−({expr})", pb=pbs, F=shown["F_у"]))
    item(t["discrepancy"].format(d=n(100 * F.discrepancy, 2)))
    heading(t["power"])
    _drive(out, t, F, lang, item, n, shown.get("F_у"), kin.get(f"V_{d.tip}"))
    return "\n".join(out).replace("\n\n\n", "\n\n") + "\n"


def _resistance(out, t, ld, fa, loads, lang, item, n, N, shown: dict[str, str]):
    sol = fa.solution
    p = ld.point
    if ld.kind == "resistance" and fa.stroke is not None:
        st = fa.stroke
        s = abs(((sol.positions[st.point] - st.origin) * st.direction.conjugate()).real - st.start)
        _para(
            out, t["graph"].format(s=n(s), H=n(st.H), stroke=t["working" if st.working(sol.phi) else "idle"])
        )
        shown[ld.name] = n(abs(ld.force), 5)  # carried on into the lever and the group's plan
        item(f"{ld.name} = {shown[ld.name]} {N}")
        return
    f = next((x for x in loads.forces if x.name == ld.name), None)
    if f is None:
        return
    rule = t[f.rule].format(p=p) if f.rule else t["angle"].format(a=n(math.degrees(f.angle)))
    if f.weight_of is not None:
        G = shown.get(f"G{f.weight_of}") or n(loads.masses[f.weight_of].mass * loads.g, 5)
        shown[ld.name] = n(_shown(n(f.times, 5)) * _shown(G), 5)
        item(t["times"].format(name=ld.name, k=n(f.times, 5), j=f.weight_of, G=G, F=shown[ld.name], p=p,
                               rule=rule))
    else:
        shown[ld.name] = n(abs(ld.force), 5)
        item(t["fixed_force"].format(name=ld.name, F=shown[ld.name], p=p, rule=rule))


def _group(out, t, g, lang, item, n, N, sol, shown: dict[str, str]):
    grp = g.group
    kind = grp.kind.letters(lang)
    out.extend(["", f"**{t['group'].format(a=grp.links[0], b=grp.links[1], kind=kind)}**"])
    for eq in g.equations:
        _para(
            out,
            t["moments_of"].format(X=eq.about, i=eq.link)
            if eq.unknown != "N"
            else t["rpr"].format(Q=eq.about),
        )
        total = sum(term.moment for term in eq.terms)
        parts = []
        got = 0.0  # the sum as the numbers shown give it
        for term in eq.terms:
            if not term.moment:
                continue
            sign = "+ " if term.moment > 0 else "− "
            part = f"{n(term.size, 5)}·{n(term.arm, 5)}" if term.arm else n(abs(term.moment), 5)
            parts.append(sign + part)
            got += math.copysign(math.prod(_shown(x) for x in part.split("·")), term.moment)
        known = " ".join(parts).removeprefix("+ ") or "0"
        expr = f"({known}) / {n(eq.arm, 5)}"
        name = eq.unknown if eq.unknown != "N" else next(r.name for r in g.reactions if r.pair == "prismatic")
        value = math.copysign(abs(got / _shown(n(eq.arm, 5))), eq.value) if eq.value else 0.0
        shown[name] = n(abs(value), 5)  # carried on into the group's plan
        item(t["unknown"].format(R=name, expr=expr, v=n(value, 5)))
        del total
    plan = g.plan
    _para(out, t["plan_scale"].format(mu=n(plan.mu)))
    closing = [v for v in plan.vectors if v.component == "closing"]
    known = [v for v in plan.vectors if v.component not in ("closing", "reaction")]
    sizes = {ld.name: abs(complex(ld.force)) for link_loads in g.loads.values() for ld in link_loads}
    for v in known:
        # a load's size as its own line gave it, not as the difference of two plan points
        F = sizes.get(v.label, abs(plan.points[v.end].value - plan.points[v.start].value))
        Fs = shown.get(v.label) or n(F, 5)  # as its own line printed it
        item(t["vec"].format(n=v.label, F=Fs, mu=n(plan.mu), mm=n(_shown(Fs) / _shown(n(plan.mu)))))
    if len(closing) == 2:
        lines = [pt for pt in plan.points.values() if pt.source.kind == "intersection"]
        src = lines[0].source if lines else None
        l0, l1 = (md_text(src.lines[0].relation), md_text(src.lines[1].relation)) if src else ("", "")
        _para(out, t["closes"].format(eq=f"`{md_code(src.equation)}`" if src else "", l0=l0, l1=l1))
    else:
        _para(out, t["closes1"].format(R=closing[0].label))
    for r in g.reactions:
        mm = plan.segments.get(r.name)
        if mm is None:
            continue
        item(t["read"].format(R=r.name, mm=n(mm, 5), mu=n(plan.mu), F=n(mm * plan.mu)))


def _drive(out, t, F, lang, item, n, Fy: str | None = None, V_tip: str | None = None):
    fa = F.analysis
    mech = fa.mechanism
    d = mech.driver
    if F.drive is None:
        _para(out, t["nodrive"].format(why=F.drive_note))
        return

    def r2(x):
        return decimal(f"{x:.2f}", lang)

    dr, gb = F.drive, F.drive.gearbox
    V = abs(fa.solution.scalar.velocity[d.tip])
    if F.drive_note == "position":
        Fs, Vs = Fy or n(abs(fa.F_y), 5), V_tip or n(V, 6)  # as printed above (V_A: six digits)
        item(t["P"].format(t=d.tip, F=Fs, V=Vs, P=n(_shown(Fs) * _shown(Vs))))
    else:
        item(t["P_mean"].format(i=d.link, P=n(dr.power)))
    item(
        t["need"].format(
            P=n(dr.power, 5),
            eta=n(dr.efficiency),
            need=n(dr.needed),
            type=dr.motor.type,
            kw=n(dr.motor.power_kw),
            rpm=n(dr.motor.rpm),
        )
    )
    item(t["u"].format(rpm=n(dr.motor.rpm), n1=n(rpm_of(mech), 5), u=r2(gb.u)))
    dev = ("+" if gb.deviation > 0 else "−" if gb.deviation < 0 else "") + num(abs(gb.deviation), 2, lang)
    if gb.stages == 2:
        item(t["stages2"].format(u=r2(gb.u), u34=r2(gb.u34), u12=r2(gb.u12)))
        item(
            t["teeth2"].format(
                z1=gb.z1,
                u12=r2(gb.u12),
                u34=r2(gb.u34),
                z2r=r2(gb.u12 * gb.z1),
                z2=gb.z2,
                z4r=r2(gb.u34 * gb.z1),
                z4=gb.z4,
            )
        )
        item(
            t["actual2"].format(
                u12a=r2(gb.z2 / gb.z1),
                u34a=r2(gb.z4 / gb.z3),
                ua=r2(gb.u_actual),
                rpm=n(dr.motor.rpm),
                n1a=r2(gb.n1_actual),
                n1=n(dr.n1, 5),
                dev=dev,
            )
        )
    else:
        item(t["stages1"])
        item(t["teeth1"].format(z1=gb.z1, u=r2(gb.u), z2r=r2(gb.u * gb.z1), z2=gb.z2))
        item(
            t["actual1"].format(
                ua=r2(gb.u_actual), rpm=n(dr.motor.rpm), n1a=r2(gb.n1_actual), n1=n(dr.n1, 5), dev=dev
            )
        )
