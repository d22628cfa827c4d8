"""``plans solve``: structure, scale factors, every segment and value for one crank position."""

from __future__ import annotations

import json

from plans.cli.common import add_source, mechanism_from, solved_position, warn, write_output
from plans.fmt import from_x, json_angle, num


def configure(p) -> None:
    add_source(p)
    p.add_argument("--json", action="store_true", help="machine-readable output (SI units)")
    p.add_argument("-o", "--output", metavar="FILE", help="write to FILE instead of stdout")


def run(args) -> int:
    mech = mechanism_from(args)
    cycle, sol = solved_position(args, mech)
    if args.json:
        text = json.dumps(to_json(sol, cycle), ensure_ascii=False, indent=2) + "\n"
    else:
        text = to_text(sol, cycle)
    write_output(args.output, text)
    for w in sol.warnings:
        warn("solve", w)
    return 0


def _xy(z: complex) -> list[float]:
    return [float(z.real) + 0.0, float(z.imag) + 0.0]  # + 0.0: no −0.0


def to_json(sol, cycle=None) -> dict:
    """The solution as JSON; with ``cycle`` (:func:`plans.cycle.analyse_cycle`), its
    figures too (stroke or swing, extreme positions, θ, K, Grashof), as the text gives."""
    from plans.cli.cycle import cycle_json

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
        "warnings": list(sol.warnings),
    } | ({} if cycle is None else {"cycle": cycle_json(cycle)})


def _sense(w: float) -> str:
    """' ccw' or ' cw' after a value; nothing after a zero, which has no sense."""
    return " ccw" if w > 0 else " cw" if w < 0 else ""


def to_text(sol, cycle=None) -> str:
    mech, st = sol.mechanism, sol.structure
    out = [f"{mech.name}", ""]
    out.append(f"Structure: {st.chebyshev()}; {st.formula()}; class {'I' * st.mechanism_class}")
    for g in st.groups:
        out.append(f"  {g.label}: kind {g.kind.value} ({g.kind.ru})")
    d = mech.driver
    # the file's own convention too, the one --angle and the cycle's lines below use
    out.append(
        f"Crank: link {d.link}, l_{d.pivot}{d.tip} = {num(d.length)} m, "
        f"{d.phi_sym} = {d.both(sol.phi, lo=sol.shown_from)}, "
        f"{d.omega_sym} = {num(abs(d.omega))} rad/s{_sense(d.omega)}"
    )
    out.append(
        f"Scales: μl = {num(sol.mu_l)} m/mm, μv = {num(sol.mu_v)} (m/s)/mm, μa = {num(sol.mu_a)} (m/s²)/mm"
    )
    out.append("")
    out.append("Plan of positions")
    out.append(f"  {'segment':10s} {'mm':>9s} {'m':>11s}")
    for k, v in sol.lengths.items():
        out.append(f"  {k:10s} {num(v / sol.mu_l):>9s} {num(v):>11s}")
    for plan, unit in ((sol.velocity, "m/s"), (sol.acceleration, "m/s²")):
        out.append("")
        out.append(f"{plan.kind.capitalize()} plan (pole {plan.pole}, μ = {num(plan.mu)} ({unit})/mm)")
        out.append(f"  {'segment':10s} {'mm':>9s} {unit:>11s}  {'how'}")
        vectors = {(v.start, v.end): v for v in plan.vectors if v.component != "absolute"}
        for key, (start, end) in plan.ends.items():
            mm = plan.segments[key]
            pt = plan.points[end]
            how = (_how(pt) if start == plan.pole and pt.source.kind != "component" else
                   f"{vectors[start, end].label} ({vectors[start, end].component})")
            out.append(f"  {key:10s} {num(mm):>9s} {num(mm * plan.mu):>11s}  {how}")
    out.append("")
    out.append("Angular velocities and accelerations")
    for i in sorted(sol.omega):
        w, e = sol.omega[i], sol.epsilon[i]
        out.append(
            f"  link {i} ({mech.links[i].name}): ω{i} = {num(abs(w))} rad/s{_sense(w)}, "
            f"ε{i} = {num(abs(e))} rad/s²{_sense(e)}"
        )
    if cycle is not None:
        out.append("")
        from plans.cycle import summary

        out.append("Cycle")
        out += [f"  {line}" for line in summary(cycle, d)]
    for w in sol.warnings:
        out.append(f"warning: {w}")
    return "\n".join(out) + "\n"


def _how(pt) -> str:
    s = pt.source
    if s.kind == "intersection":
        lines = " and ".join(f"{ln.relation} through {ln.through}" for ln in s.lines)
        return f"{s.equation}; lines {lines}"
    return s.equation
