"""``plans solve``: structure, scale factors, every segment and value for one crank position,
in English or Russian (``--lang``; the JSON is the same in both)."""

from __future__ import annotations

import json
import math

import numpy as np

from plans.cli.common import (
    EXIT_OK,
    add_source,
    cycle_json,
    mechanism_from,
    place_json,
    solved_position,
    warn,
)
from plans.cli.output import terminal
from plans.cycle import analyse_cycle, existence, shown_from, summary
from plans.cycle.table import conditioning
from plans.cycle.transmission import WORDS as WORDS_T
from plans.cycle.transmission import lines as transmission_lines
from plans.cycle.transmission import transmission
from plans.errors import SingularPlanError
from plans.fmt import angle, from_x, json_angle, num
from plans.kinematics.solver import Solver
from plans.kinematics.transmission import between, gammas
from plans.note.report import warnings

#: the report's words by language
WORDS = {
    "en": {
        "structure": "Structure", "class": "class", "kind": "kind", "crank": "Crank",
        "group_line": "group {a}–{b} ({kind}): kind {n} ({ru})",
        "link": "link", "rads": "rad/s", "rads2": "rad/s²", "scales": "Scales",
        "positions": "Plan of positions", "segment": "segment", "mm": "mm", "m": "m",
        "how": "how", "velocity": "Velocity plan", "acceleration": "Acceleration plan",
        "pole": "pole", "units": {"m/s": "m/s", "m/s²": "m/s²"},
        "angular": "Angular velocities and accelerations", "cycle": "Cycle",
        "lines": "lines", "through": "through", "and": "and", "warning": "warning",
        "ccw": "ccw", "cw": "cw",
        "components": {},
        "input": "Input", "slider": "slider on the guide", "along": "along",
        "time": "Motion in time", "law": "law", "laws": {
            "uniform": "uniform", "accelerated": "uniformly accelerated", "harmonic": "harmonic",
            "table": "a table"},
        "ms": "m/s", "ms2": "m/s²", "s": "s",
        "singular_at": "Position at {at}: the plans are singular here",
        "positions_head": "Positions (m)           x            y",
        "singular": "The velocity and acceleration plans are not built: {why}",
    },
    "ru": {
        "structure": "Строение", "class": "класс", "kind": "вид", "crank": "Кривошип",
        "group_line": "группа {a}–{b}: вид {n} ({ru})",
        "link": "звено", "rads": "рад/с", "rads2": "рад/с²", "scales": "Масштабы",
        "positions": "План положений", "segment": "отрезок", "mm": "мм", "m": "м",
        "how": "построение", "velocity": "План скоростей", "acceleration": "План ускорений",
        "pole": "полюс", "units": {"m/s": "м/с", "m/s²": "м/с²"},
        "angular": "Угловые скорости и ускорения", "cycle": "Цикл",
        "lines": "линии", "through": "через", "and": "и", "warning": "предупреждение",
        "ccw": "против ч.с.", "cw": "по ч.с.",
        "components": {"absolute": "абсолютная", "relative": "относительная",
                       "normal": "нормальная", "tangential": "касательная",
                       "coriolis": "кориолисова", "sliding": "скольжения"},
        "input": "Начальное звено", "slider": "ползун на направляющей", "along": "вдоль",
        "time": "Движение во времени", "law": "закон", "laws": {
            "uniform": "равномерный", "accelerated": "равноускоренный", "harmonic": "гармонический",
            "table": "таблица"},
        "ms": "м/с", "ms2": "м/с²", "s": "с",
        "singular_at": "Положение при {at}: планы здесь вырождены",
        "positions_head": "Положения (м)           x            y",
        "singular": "Планы скоростей и ускорений не строятся: {why}",
    },
}


def configure(p) -> None:
    add_source(p)
    p.add_argument("--json", action="store_true", help="machine-readable output (SI units)")
    p.add_argument("--lang", choices=tuple(WORDS), default="en",
                   help="language of the text (ru: decimal commas; the JSON is the same, its "
                        "warnings in the language)")
    p.add_argument("-o", "--output", metavar="FILE", help="write to FILE instead of stdout")


def run(args) -> int:
    mech = mechanism_from(args)
    lang = getattr(args, "lang", "en")
    try:
        cycle, sol = solved_position(args, mech)
    except SingularPlanError as exc:  # a change point or a dead point: the positions stand
        return _singular(args, mech, exc, lang)
    if args.json:
        text = json.dumps(to_json(sol, cycle, lang), ensure_ascii=False, indent=2) + "\n"
    else:
        text = to_text(sol, cycle, lang)
    args.run_files.write(args.output, text)
    for w in sol.warnings:
        warn("solve", w)
    return EXIT_OK


def _singular(args, mech, exc: SingularPlanError, lang: str) -> int:
    """The positions where the plans are singular (a change point, a dead point), and why
    the velocity and acceleration plans are not built there: the exit status as the
    cycle's row there would give (0 where the row is "singular", 2 where it is an error)."""
    solver = Solver(mech)
    cycle = analyse_cycle(mech, solver=solver)
    x = mech.param
    with np.errstate(all="ignore"):
        m = solver.solve(np.array([x]))
    (st,) = conditioning(mech, m, solver, shown_from(cycle, mech.driver))
    if not st.placed or st.errors:  # no change point: refused, as the cycle's row is an error
        raise exc
    pos = {p: complex(np.ravel(z)[0]) for p, z in m.position.items()}
    big = max((abs(z) for z in pos.values()), default=0.0)
    pos = {p: complex(*(0.0 if abs(c) <= 1e-12 * big else c for c in (z.real, z.imag)))
           for p, z in pos.items()}  # y of a pin at 180° is l·sin π = 6e-18 m: 0
    why = str(exc).split(": ", 1)[-1] if str(exc).startswith(mech.source) else str(exc)
    if args.json:
        text = json.dumps({"points": {p: {"position": _xy(z)} for p, z in pos.items()},
                           "structure": {"W": solver.structure.W},
                           **place_json(mech, x), "singular": why, "plans": None},
                          ensure_ascii=False, indent=2) + "\n"
    else:
        t = WORDS[lang]
        at = mech.at(x, lang, shown_from(cycle, mech.driver))
        if exc.words is not None:  # the reason in the report's language
            why = exc.words(solver.at(x, lang, shown_from(cycle, mech.driver)), lang)
        out = [mech.name, "", t["singular_at"].format(at=at), "", t["positions_head"]]
        out += [f"  {p:<6} {num(z.real + 0.0, 6, lang):>12} {num(z.imag + 0.0, 6, lang):>12}"
                for p, z in pos.items()]
        out += ["", t["singular"].format(why=why)]
        text = "\n".join(out) + "\n"
    args.run_files.write(args.output, text)
    return EXIT_OK


def _xy(z: complex) -> list[float]:
    return [float(z.real) + 0.0, float(z.imag) + 0.0]  # + 0.0: no −0.0


def to_json(sol, cycle=None, lang: str = "en", trans=None) -> dict:
    """The solution as JSON; with ``cycle`` (:func:`plans.cycle.analyse_cycle`), its
    figures too (stroke or swing, extreme positions, θ, K, Grashof), as the text gives,
    and the transmission over it (``trans``: :func:`plans.cycle.transmission.transmission`,
    worked out here where not given); the warnings in ``lang``."""
    if trans is None and cycle is not None:
        trans = transmission(sol.solver, cycle)
    m = sol.scalar
    points = {
        name: {
            "position": _xy(sol.positions[name]),
            "velocity": _xy(m.velocity[name]),
            "acceleration": _xy(m.acceleration[name]),
        }
        for name in sol.positions
    }
    st = sol.structure
    return {
        "points": points,
        "links": {str(i): {"omega": sol.omega[i] + 0.0, "epsilon": sol.epsilon[i] + 0.0}
                  for i in sorted(sol.omega)},
        "scales": sol.mu,
        "segments": {k: float(v) for k, v in sol.segments.items()},
        "plans": {
            plan.kind: {"pole": plan.pole, "mu": plan.mu, "unit": plan.unit,
                        "segments": {k: float(v) for k, v in plan.segments.items()}}
            for plan in (sol.velocity, sol.acceleration)
        },
        "structure": {
            "W": st.W,
            "n": st.n,
            "p5": st.p5,
            "p4": st.p4,
            "formula": st.formula(),
            "class": st.mechanism_class,
            "groups": [{"links": list(g.links), "kind": g.kind.name} for g in st.groups],
        },
        **_place(sol),
        "warnings": warnings(sol, lang),
    } | ({} if cycle is None else {"cycle": cycle_json(cycle)}) | _transmission_json(sol, trans) | (
        {} if (cond := None if cycle is None else existence.support_conditions(
            sol.mechanism, sol.solver, cycle)) is None else {"crank_conditions": existence.as_json(cond)})


def _place(sol) -> dict:
    """Where the solution is: the crank angle from +x and in the file's convention, as
    before; a slider input's travel, each input's coordinate and rates, the instant of a
    timed mechanism, where the mechanism has them."""
    mech = sol.mechanism
    d = mech.driver
    if mech.timing is None and not d.linear and d.epsilon == 0:
        return {"phi_deg": json_angle(from_x(sol.phi)),
                "angle_deg": json_angle(d.file_angle(sol.phi))}
    out = {} if mech.timing is None else {"t": sol.phi}
    inputs = []
    for dd, (q, dq, ddq) in zip(mech.drivers, mech.inputs_at(sol.phi), strict=True):
        if dd.linear:
            inputs.append({"link": dd.link, "kind": "slider", "point": dd.tip, "guide": dd.guide.label,
                           "s": float(q) + 0.0, "velocity": float(dq) + 0.0,
                           "acceleration": float(ddq) + 0.0})
        else:
            inputs.append({"link": dd.link, "kind": "crank", "phi_deg": json_angle(from_x(float(q))),
                           "angle_deg": json_angle(dd.file_angle(float(q))),
                           "omega": float(dq) + 0.0, "epsilon": float(ddq) + 0.0})
    first = inputs[0]
    if first["kind"] == "crank":
        out |= {"phi_deg": first["phi_deg"], "angle_deg": first["angle_deg"]}
    return out | {"inputs": inputs}


def _transmission_json(sol, trans) -> dict:
    """γ and α of every group at the position, and over the cycle its γmin, where, and
    the dead points (degrees; places as :func:`plans.cli.common.place_json` gives them)."""
    mech = sol.mechanism
    here = gammas(sol.scalar)
    over = {g.group.label: g for g in trans.groups} if trans is not None else {}
    groups = {}
    for grp in sol.structure.groups:
        g = here[grp.label]
        item = {"gamma_deg": math.degrees(g), "pressure_deg": 90.0 - math.degrees(g),
                "between": between(grp)}
        ga = over.get(grp.label)
        if ga is not None:
            item |= {"gamma_min_deg": None if not math.isfinite(ga.gamma_min) else math.degrees(ga.gamma_min),
                     "pressure_max_deg": None if not math.isfinite(ga.gamma_min) else
                     math.degrees(ga.pressure_max),
                     "at": None if not math.isfinite(ga.at) or ga.constant else place_json(mech, ga.at),
                     "constant": ga.constant,
                     "dead_points": [place_json(mech, x) for x in ga.dead],
                     "change_points": [place_json(mech, x) for x in ga.change]}
        groups[grp.label] = item
    out = {"groups": groups}
    if trans is not None:
        out["reversed_dead_points"] = [place_json(mech, x) for x in trans.reversed]
    return {"transmission": out}


def _sense(w: float, t=WORDS["en"]) -> str:
    """' ccw' or ' cw' after a value; nothing after a zero, which has no sense."""
    return f" {t['ccw']}" if w > 0 else f" {t['cw']}" if w < 0 else ""


def to_text(sol, cycle=None, lang: str = "en", trans=None) -> str:
    if trans is None and cycle is not None:
        trans = transmission(sol.solver, cycle)
    t = WORDS[lang]
    mech, st = sol.mechanism, sol.structure

    def n(x) -> str:
        return num(x, 4, lang)

    out = [f"{terminal(mech.name_in(lang))}", ""]
    out.append(f"{t['structure']}: {st.chebyshev()}; {st.formula()}; {t['class']} {'I' * st.mechanism_class}")
    for g in st.groups:
        out.append("  " + t["group_line"].format(a=g.links[0], b=g.links[1], kind=g.kind.name,
                                                 n=g.kind.value, ru=g.kind.ru))
    d = mech.driver
    out += _inputs(sol, t, lang)
    u = t["units"]
    out.append(
        f"{t['scales']}: μl = {n(sol.mu_l)} {t['m']}/{t['mm']}, μv = {n(sol.mu_v)} ({u['m/s']})/{t['mm']}, "
        f"μa = {n(sol.mu_a)} ({u['m/s²']})/{t['mm']}"
    )
    out.append("")
    out.append(t["positions"])
    out.append(f"  {t['segment']:10s} {t['mm']:>9s} {t['m']:>11s}")
    for k, v in sol.lengths.items():
        out.append(f"  {k:10s} {n(v / sol.mu_l):>9s} {n(v):>11s}")
    for plan, unit in ((sol.velocity, u["m/s"]), (sol.acceleration, u["m/s²"])):
        out.append("")
        out.append(f"{t[plan.kind]} ({t['pole']} {plan.pole}, μ = {n(plan.mu)} ({unit})/{t['mm']})")
        out.append(f"  {t['segment']:10s} {t['mm']:>9s} {unit:>11s}  {t['how']}")
        vectors = {(v.start, v.end): v for v in plan.vectors if v.component != "absolute"}
        for key, (start, end) in plan.ends.items():
            mm = plan.segments[key]
            pt = plan.points[end]
            if start == plan.pole and pt.source.kind != "component":
                how = _how(pt, t)
            else:
                v = vectors[start, end]
                how = f"{v.label} ({t['components'].get(v.component, v.component)})"
            out.append(f"  {key:10s} {n(mm):>9s} {n(mm * plan.mu):>11s}  {how}")
    out.append("")
    out.append(t["angular"])
    for i in sorted(sol.omega):
        w, e = sol.omega[i], sol.epsilon[i]
        out.append(
            f"  {t['link']} {i} ({terminal(mech.links[i].name)}): ω{i} = {n(abs(w))} {t['rads']}"
            f"{_sense(w, t)}, ε{i} = {n(abs(e))} {t['rads2']}{_sense(e, t)}"
        )
    out.append("")
    out.append(WORDS_T[lang]["head"])
    out += [f"  {line}" for line in transmission_lines(
        trans, mech, st.groups, gammas(sol.scalar), lang, sol.shown_from,
        cycle.output.point if cycle is not None and cycle.output is not None else "")]
    if cycle is not None:
        out.append("")
        out.append(t["cycle"])
        out += [f"  {line}" for line in summary(cycle, d, lang)]
        out += [f"  {line}" for line in existence.lines(
            existence.support_conditions(mech, sol.solver, cycle), lang)]
    for w in warnings(sol, lang):
        out.append(f"{t['warning']}: {w}")
    return "\n".join(out) + "\n"


def _inputs(sol, t, lang: str) -> list[str]:
    """The input's line (a line per input): a crank's length, angle (in the file's own
    convention too, the one --angle and the cycle's lines use), ω and ε where it has one;
    a slider's guide, travel, velocity and acceleration; and the instant of a mechanism
    moved in time."""
    mech = sol.mechanism

    def n(x) -> str:
        return num(x, 4, lang)

    out = []
    rates = mech.inputs_at(sol.phi)
    if mech.timing is not None:
        laws = "; ".join(f"{t['link']} {d.link}: {t['laws'][d.law.kind]}" for d in mech.drivers)
        out.append(f"{t['time']}: t = {n(sol.phi)} {t['s']} ({t['law']}: {laws})")
    for d, (q, dq, ddq) in zip(mech.drivers, rates, strict=True):
        q, dq, ddq = float(q), float(dq), float(ddq)
        if d.linear:  # sin π of a harmonic law is 1.2e-16: a travel or a rate that is rounding
            big = max(abs(q), abs(dq), abs(ddq))
            q, dq, ddq = (0.0 if abs(x) <= 1e-12 * big else x for x in (q, dq, ddq))
        if d.linear:
            out.append(f"{t['input']}: {t['link']} {d.link}, {t['slider']} {d.guide.label}, "
                       f"{d.phi_sym} = {n(q)} {t['m']} {t['along']} {d.guide.label}, "
                       f"{d.omega_sym} = {n(dq)} {t['ms']}, {d.epsilon_sym} = {n(ddq)} {t['ms2']}")
            continue
        where = (d.both(q, lang, lo=sol.shown_from) if mech.timing is None else
                 f"{angle(d.file_angle(q), 6, lang)}°{d.convention(lang)}")
        line = (f"{t['crank']}: {t['link']} {d.link}, l_{d.pivot}{d.tip} = {n(d.length)} {t['m']}, "
                f"{d.phi_sym} = {where}, {d.omega_sym} = {n(abs(dq))} {t['rads']}{_sense(dq, t)}")
        if ddq != 0 or (mech.timing is None and d.epsilon != 0):
            line += f", ε{d.link} = {n(abs(ddq))} {t['rads2']}{_sense(ddq, t)}"
        out.append(line)
    return out


def _how(pt, t=WORDS["en"]) -> str:
    s = pt.source
    if s.kind == "intersection":
        lines = f" {t['and']} ".join(f"{ln.relation} {t['through']} {ln.through}" for ln in s.lines)
        return f"{s.equation}; {t['lines']} {lines}"
    return s.equation
