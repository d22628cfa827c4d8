"""``plans report``: the explanatory-note text of one crank position (Markdown)."""

from __future__ import annotations

from .cli import add_source, angle_field, mechanism_from, warn, write_output


def configure(p) -> None:
    add_source(p)
    p.add_argument("--lang", choices=("ru", "en"), default="en", help="language of the note (ru uses a decimal comma)")
    p.add_argument("-o", "--output", metavar="FILE", help="write to FILE instead of stdout")


def run(args) -> int:
    from .cycle import analyse_cycle, outside_range
    from .errors import AssemblyError
    from .kinematics import Solver
    from .plan import solve_position
    from .report import note

    mech = mechanism_from(args)
    try:
        solver = Solver(mech)
        sol = solve_position(mech, solver=solver)
    except AssemblyError as exc:  # an angle where it does not assemble: which, and where it does
        raise outside_range(mech, exc, *angle_field(args, mech)) from None
    write_output(args.output, note(sol, args.lang, analyse_cycle(mech, solver=solver)))
    for w in sol.warnings:
        warn("report", w)
    return 0
