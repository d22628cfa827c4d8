"""``plans report``: the explanatory-note text of one crank position (Markdown)."""

from __future__ import annotations

from plans.cli.common import add_source, mechanism_from, solved_position, warn, write_output


def configure(p) -> None:
    add_source(p)
    p.add_argument("--lang", choices=("ru", "en"), default="en", help="language of the note (ru uses a decimal comma)")
    p.add_argument("-o", "--output", metavar="FILE", help="write to FILE instead of stdout")


def run(args) -> int:
    from plans.note.report import note

    mech = mechanism_from(args)
    cycle, sol = solved_position(args, mech)
    write_output(args.output, note(sol, args.lang, cycle))
    for w in sol.warnings:
        warn("report", w)
    return 0
