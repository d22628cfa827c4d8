"""``plans report``: the explanatory-note text of one crank position (Markdown)."""

from __future__ import annotations

from plans.cli.common import EXIT_OK, add_source, mechanism_from, solved_position, warn
from plans.cycle.analysis import analyse_cycle
from plans.note.report import note


def configure(p) -> None:
    add_source(p)
    p.add_argument("--lang", choices=("ru", "en"), default="en",
                   help="language of the note (ru uses a decimal comma)")
    p.add_argument("-o", "--output", metavar="FILE", help="write to FILE instead of stdout")


def run(args) -> int:
    mech = mechanism_from(args)
    solver, sol = solved_position(args, mech)
    args.run_files.write(args.output, note(sol, args.lang, analyse_cycle(mech, solver=solver)))
    for w in sol.warnings:
        warn("report", w)
    return EXIT_OK
