"""``plans forces``: the loads, each group's force plan and reactions, the balancing moment by
the groups, by Zhukovsky's lever and by virtual power, the cycle's mean power, and the drive."""

from __future__ import annotations

import cmath
import json
import math

from plans.cli.common import EXIT_OK, add_source, mechanism_from, solved_position, warn
from plans.fmt import columns, decimal, from_x, json_angle, num, unit
from plans.forces.summary import Forces, rpm_of, solve_forces
from plans.forces.words import words


def configure(p) -> None:
    add_source(p)
    p.add_argument("--json", action="store_true", help="machine-readable output (SI units)")
    p.add_argument(
        "--lang", choices=("ru", "en"), default="en", help="language of the text (ru: decimal comma)"
    )
    p.add_argument("-o", "--output", metavar="FILE", help="write to FILE instead of stdout")


def run(args) -> int:
    mech = mechanism_from(args)
    cycle, sol = solved_position(args, mech)
    solver = sol.solver
    F = solve_forces(sol, solver, cycle)
    if args.json:
        text = json.dumps(to_json(F), ensure_ascii=False, indent=2) + "\n"
    else:
        text = to_text(F, args.lang)
    args.run_files.write(args.output, text)
    for w in sol.warnings:
        warn("forces", w)
    return EXIT_OK


def _xy(z) -> list[float]:
    z = complex(z)
    return [float(z.real) + 0.0, float(z.imag) + 0.0]


def _deg(z) -> float:
    """The direction of a vector (degrees from +x, counter-clockwise, in [0, 360))."""
    return json_angle(math.degrees(cmath.phase(complex(z))) % 360.0)


def to_json(F: Forces) -> dict:
    fa = F.analysis
    sol = fa.solution
    mech = sol.mechanism
    d = mech.driver
    loads = [
        {
            "name": ld.name,
            "kind": ld.kind,
            "link": ld.link,
            "point": ld.point,
            "at": _xy(ld.at),
            "force": _xy(ld.force),
            "magnitude": abs(complex(ld.force)) + 0.0,
            "moment": float(ld.moment) + 0.0,
        }
        for ld in fa.loads
    ]
    groups = []
    for g in fa.groups:
        reactions = {}
        for r in g.reactions:
            item = {
                "by": r.by,
                "on": r.on,
                "pair": r.pair,
                "point": r.point,
                "at": None if r.at is None else _xy(r.at),
                "force": _xy(r.value),
                "magnitude": abs(r.value) + 0.0,
            }
            if r.tangential is not None:
                item |= {"tangential": _xy(r.tangential), "normal": _xy(r.normal)}
            reactions[r.name] = item
        plan = g.plan
        groups.append(
            {
                "links": list(g.group.links),
                "kind": g.group.kind.name,
                "mu_F": plan.mu,
                "reactions": reactions,
                "segments": {k: float(v) for k, v in plan.segments.items()},
                "sine": float(g.sine),
            }
        )
    lv = F.lever
    out = {
        "phi_deg": json_angle(from_x(sol.phi)),
        "angle_deg": json_angle(d.file_angle(sol.phi)),
        "g": mech.loads.g,
        "loads": loads,
        "groups": groups,
        "crank": {"link": d.link, "R01": _xy(fa.R01), "M_y": fa.M_y + 0.0, "F_y": fa.F_y + 0.0},
        "balancing": {
            "groups": fa.M_y + 0.0,
            "lever": lv.M_y + 0.0,
            "virtual_power": F.M_y_power + 0.0,
            "global": F.M_y_global + 0.0,
            "lever_discrepancy": F.discrepancy,
            "lever_measured_discrepancy": lv.discrepancy,
        },
        "lever": {
            "mu_v": lv.mu_v,
            "pb": lv.pb,
            "F_y": lv.F_y + 0.0,
            "F_y_measured": lv.measured + 0.0,
            "terms": [
                {
                    "name": t.name,
                    "point": t.point or None,
                    "image": _xy(t.image),
                    "arm": t.arm,
                    "moment": t.moment + 0.0,
                }
                for t in lv.terms
            ],
        },
        "power": fa.power + 0.0,
    }
    if F.turn is not None:
        out["cycle"] = {
            "mean_M_y": F.turn.mean_M_y(),
            "resistance_work": F.turn.resistance_work(),
            "mean_power": F.turn.mean_power(),
            "positions": [{"phi_deg": json_angle(from_x(p)), "M_y": m + 0.0} for p, m in F.positions],
        }
    if F.drive is not None:
        dr, gb = F.drive, F.drive.gearbox
        out["drive"] = {
            "basis": F.drive_note,
            "power": dr.power,
            "efficiency": dr.efficiency,
            "needed": dr.needed,
            "motor": {"type": dr.motor.type, "power_kw": dr.motor.power_kw, "rpm": dr.motor.rpm},
            "n1": dr.n1,
            "gearbox": gb._asdict(),
        }
    else:
        out["drive"] = None
    return out


def _sense(v: float, w: dict) -> str:
    return w["ccw"] if v > 0 else w["cw"] if v < 0 else ""


def to_text(F: Forces, lang: str = "en") -> str:
    w = words(lang)
    fa = F.analysis
    sol = fa.solution
    mech = sol.mechanism
    d = mech.driver
    loads = mech.loads

    def n(x, digits=4):
        return num(float(x), digits, lang)

    out = [w["title"].format(name=mech.name_in(lang)), ""]
    out.append(
        w["position"].format(
            phi=f"{d.phi_sym} = {d.both(sol.phi, lang, sol.shown_from)}",
            omega_sym=d.omega_sym,
            omega=n(abs(d.omega)),
            sense=_sense(d.omega, w),
        )
        # an accelerating crank: its ε1 changes the inertia loads, said beside ω1
        + (f"; ε{d.link} = {n(abs(d.epsilon))} {w['rads2']} {_sense(d.epsilon, w)}" if d.epsilon else "")
    )
    out.append("")
    out.append(w["loads"].format(g=n(loads.g)))
    rows = []
    for ld in fa.loads:
        if ld.point is None:
            value, direction = (
                f"{n(abs(ld.moment))} {unit('N·m', lang)}",
                _sense(ld.moment, w),
            )
        else:
            value, direction = f"{n(abs(ld.force))} {unit('N', lang)}", f"{n(_deg(ld.force))}°"
        rows.append([ld.name, w[ld.kind], str(ld.link), ld.point or "—", value, direction])
    out += _columns(rows, w["load_head"])
    if loads.resistance is not None and fa.stroke is not None:
        P = (
            next(ld for ld in fa.loads if ld.kind == "resistance")
            if any(ld.kind == "resistance" for ld in fa.loads)
            else None
        )
        st = fa.stroke
        s = ((sol.positions[st.point] - st.origin) * st.direction.conjugate()).real
        s = abs(s - st.start)
        out.append(
            w["stroke"].format(
                P=P.name if P else loads.resistance.name,
                s=n(s),
                H=n(st.H),
                stroke=w["working" if st.working(sol.phi) else "idle"],
            )
        )
    for g in fa.groups:
        out.append("")
        out.append(
            w["group"].format(
                label=g.group.label_in(lang),
                mu=n(g.plan.mu),
            )
        )
        rows = []
        for r in g.reactions:
            mm = g.plan.segments.get(r.name)
            where = r.point if r.point else (_at(r.at, lang) if r.at is not None else w["contact_none"])
            rows.append(
                [r.name, n(abs(r.value)), n(mm) if mm is not None else "", f"{n(_deg(r.value))}°", where]
            )
            if r.tangential is not None:
                for comp, value in (("^τ", r.tangential), ("^n", r.normal)):
                    mm = g.plan.segments.get(r.name + comp)
                    rows.append(
                        [
                            f"  {r.name}{comp}",
                            n(abs(value)),
                            n(mm) if mm is not None else "",
                            f"{n(_deg(value))}°" if value else "",
                            "",
                        ]
                    )
        out += _columns(rows, w["reaction_head"], right=(1, 2))
    out.append("")
    out.append(w["crank"].format(link=d.link))
    out.append(
        w["R01"].format(name=f"R0{d.link}", value=n(abs(fa.R01)), angle=n(_deg(fa.R01)), pivot=d.pivot)
    )
    out.append(
        w["My"].format(
            value=n(abs(fa.M_y)), sense=_sense(fa.M_y, w), pivot=d.pivot, tip=d.tip, F=n(abs(fa.F_y))
        )
    )
    out.append("")
    out.append(w["balance"])
    out.append(w["by_groups"].format(value=n(fa.M_y, 6)))
    out.append(
        w["by_lever"].format(
            value=n(F.lever.M_y, 6), d=n(100 * F.discrepancy, 2), m=n(100 * F.lever.discrepancy, 2)
        )
    )
    out.append(w["by_power"].format(value=n(F.M_y_power, 6)))
    out.append(w["by_global"].format(value=n(F.M_y_global, 6)))
    out.append("")
    if F.turn is None:
        out.append(w["no_cycle"])
    elif F.turn.resistance_work() is None:
        out.append(w["cycle_no_resistance"].format(mean=n(F.turn.mean_M_y()), power=n(F.turn.mean_power())))
    else:
        out.append(
            w["cycle"].format(
                mean=n(F.turn.mean_M_y()), work=n(F.turn.resistance_work()), power=n(F.turn.mean_power())
            )
        )
    out.append("")
    out.append(w["drive"])
    out += _drive_lines(F, lang)
    return "\n".join(out) + "\n"


def _drive_lines(F: Forces, lang: str) -> list[str]:
    w = words(lang)
    mech = F.analysis.mechanism
    d = mech.driver

    def n(x, digits=4):
        return num(float(x), digits, lang)

    def r2(x):  # a ratio as the workbook writes it: two decimals
        return decimal(f"{x:.2f}", lang)

    if F.drive is None:
        return [w["no_drive"].format(why=F.drive_note)]
    dr, gb = F.drive, F.drive.gearbox
    key = {
        "position": "power_position",
        "mean": "power_mean_asked" if (mech.drive and mech.drive.power == "mean") else "power_mean",
    }[F.drive_note]
    out = [w[key].format(omega_sym=d.omega_sym, P=n(dr.power))]
    out.append(
        w["motor"].format(
            P=n(dr.power),
            eta=n(dr.efficiency),
            need=n(dr.needed),
            type=dr.motor.type,
            kw=n(dr.motor.power_kw),
            rpm=n(dr.motor.rpm),
        )
    )
    out.append(
        w["ratio"].format(
            rpm=n(dr.motor.rpm),
            n1=n(rpm_of(mech)),
            u=r2(gb.u),
            stages=w["one_stage" if gb.stages == 1 else "two_stages"],
        )
    )
    if gb.stages == 2:
        out.append(w["split"].format(u34=r2(gb.u34), u12=r2(gb.u12)))
        out.append(w["teeth2"].format(z1=gb.z1, z2=gb.z2, z4=gb.z4))
    else:
        out.append(w["teeth1"].format(z1=gb.z1, z2=gb.z2))
    dev = num(abs(gb.deviation), 2, lang)
    dev = ("+" if gb.deviation > 0 else "−" if gb.deviation < 0 else "") + dev
    out.append(
        w["actual"].format(
            u=r2(gb.u_actual), rpm=n(dr.motor.rpm), n1=r2(gb.n1_actual), dev=dev, n1_given=n(dr.n1, 5)
        )
    )
    return out


def _at(z, lang) -> str:
    z = complex(z)
    return f"({num(z.real, 4, lang)}; {num(z.imag, 4, lang)}) {unit('m', lang)}"


def _columns(rows, head, right=()) -> list[str]:
    return columns(rows, head, right)
