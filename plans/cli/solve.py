"""``plans solve``: structure, scale factors, every segment and value for one crank position,
in English or Russian (``--lang``; the JSON is the same in both)."""

from __future__ import annotations

import json
import math

from plans.cli.common import EXIT_OK, add_source, cycle_json, mechanism_from, solved_position, warn
from plans.cli.output import terminal
from plans.cycle import summary
from plans.fmt import angle, from_x, json_angle, num
from plans.note.report import change_points, no_full_turn, warnings

#: the report's words by language
WORDS = {
    "en": {
        "structure": "Structure", "class": "class", "kind": "kind", "crank": "Crank",
        "link": "link", "rads": "rad/s", "rads2": "rad/s²", "scales": "Scales",
        "positions": "Plan of positions", "segment": "segment", "mm": "mm", "m": "m",
        "how": "how", "velocity": "Velocity plan", "acceleration": "Acceleration plan",
        "pole": "pole", "units": {"m/s": "m/s", "m/s²": "m/s²"},
        "angular": "Angular velocities and accelerations", "cycle": "Cycle",
        "lines": "lines", "through": "through", "and": "and", "warning": "warning",
        "ccw": "ccw", "cw": "cw",
        "components": {},
    },
    "ru": {
        "structure": "Строение", "class": "класс", "kind": "вид", "crank": "Кривошип",
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
    cycle, sol = solved_position(args, mech)
    lang = getattr(args, "lang", "en")
    if args.json:
        text = json.dumps(to_json(sol, cycle, lang), ensure_ascii=False, indent=2) + "\n"
    else:
        text = to_text(sol, cycle, lang)
    args.run_files.write(args.output, text)
    for w in sol.warnings:
        warn("solve", w)
    return EXIT_OK


def _xy(z: complex) -> list[float]:
    return [float(z.real) + 0.0, float(z.imag) + 0.0]  # + 0.0: no −0.0


def to_json(sol, cycle=None, lang: str = "en") -> dict:
    """The solution as JSON; with ``cycle`` (:func:`plans.cycle.analyse_cycle`), its
    figures too (stroke or swing, extreme positions, θ, K, Grashof), as the text gives;
    the warnings in ``lang``."""
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
        "phi_deg": json_angle(from_x(sol.phi)),
        "angle_deg": json_angle(sol.mechanism.driver.file_angle(sol.phi)),
        "warnings": warnings(sol, lang),
    } | ({} if cycle is None else {"cycle": cycle_json(cycle)})


def _sense(w: float, t=WORDS["en"]) -> str:
    """' ccw' or ' cw' after a value; nothing after a zero, which has no sense."""
    return f" {t['ccw']}" if w > 0 else f" {t['cw']}" if w < 0 else ""


def to_text(sol, cycle=None, lang: str = "en") -> str:
    t = WORDS[lang]
    mech, st = sol.mechanism, sol.structure

    def n(x) -> str:
        return num(x, 4, lang)

    out = [f"{terminal(mech.name_in(lang))}", ""]
    out.append(f"{t['structure']}: {st.chebyshev()}; {st.formula()}; {t['class']} {'I' * st.mechanism_class}")
    for g in st.groups:
        label = g.label if lang == "en" else f"группа {g.links[0]}–{g.links[1]} ({g.kind.name})"
        out.append(f"  {label}: {t['kind']} {g.kind.value} ({g.kind.ru})")
    d = mech.driver
    # the file's own convention too, the one --angle and the cycle's lines below use
    out.append(
        f"{t['crank']}: {t['link']} {d.link}, l_{d.pivot}{d.tip} = {n(d.length)} {t['m']}, "
        f"{d.phi_sym} = {d.both(sol.phi, lang, lo=sol.shown_from)}, "
        f"{d.omega_sym} = {n(abs(d.omega))} {t['rads']}{_sense(d.omega, t)}"
    )
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
    if cycle is not None:
        out.append("")
        out.append(t["cycle"])
        out += [f"  {line}" for line in (summary(cycle, d) if lang == "en" else _cycle_ru(cycle, d))]
    for w in warnings(sol, lang):
        out.append(f"{t['warning']}: {w}")
    return "\n".join(out) + "\n"


def _cycle_ru(c, d) -> list[str]:
    """The cycle's lines in Russian, as :func:`plans.cycle.analysis.summary` gives them in
    English: the crank's range, the change points, the stroke or swing, the extreme
    positions, θ and K."""
    lines = []
    if c.grashof:
        lines.append(f"четырёхзвенник: {c.grashof}")
    if not c.full_turn:
        lines.append(no_full_turn(c, "ru", d))
    if c.change_points:
        lines.append(change_points(c, "ru", d))
    if c.stroke is not None and c.output is not None:
        if c.output.kind == "linear":
            lines.append(f"ход точки {c.output.point}: H = {num(c.stroke, 4, 'ru')} м")
        else:
            lines.append(f"размах звена {c.output.link}: ψ = {num(math.degrees(c.stroke), 4, 'ru')}°")
        lines.append(
            f"крайние положения при {d.phi_sym} = "
            + ", ".join(f"{angle(d.file_angle(x), 4, 'ru')}°" for x in c.extremes) + d.convention("ru")
            + f"; θ = {num(math.degrees(c.theta), 4, 'ru')}°, K = {num(c.K, 4, 'ru')}")
    return lines


def _how(pt, t=WORDS["en"]) -> str:
    s = pt.source
    if s.kind == "intersection":
        lines = f" {t['and']} ".join(f"{ln.relation} {t['through']} {ln.through}" for ln in s.lines)
        return f"{s.equation}; {t['lines']} {lines}"
    return s.equation
