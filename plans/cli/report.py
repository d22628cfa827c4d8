"""``plans report``: the explanatory-note text of one crank position (Markdown)."""

from __future__ import annotations

from plans.cli.common import EXIT_OK, add_source, mechanism_from, solved_position, warn
from plans.cycle.analysis import analyse_cycle
from plans.forces.note import force_note
from plans.forces.summary import solve_forces
from plans.note.report import note


def configure(p) -> None:
    add_source(p)
    p.add_argument("--lang", choices=("ru", "en"), default="en",
                   help="language of the note (ru uses a decimal comma)")
    p.add_argument("-o", "--output", metavar="FILE", help="write to FILE instead of stdout")


def run(args) -> int:
    mech = mechanism_from(args)
    solver, sol = solved_position(args, mech)
    cycle = analyse_cycle(mech, solver=solver)
    text = note(sol, args.lang, cycle)
    if mech.loads is not None:  # the note goes on with the force analysis, section after section
        section = sum(line.startswith("## ") for line in text.splitlines()) + 1
        text = text.rstrip("\n") + "\n\n" + force_note(solve_forces(sol, solver, cycle), args.lang, section)
    args.run_files.write(args.output, text)
    for w in sol.warnings:
        warn("report", w)
    return EXIT_OK
