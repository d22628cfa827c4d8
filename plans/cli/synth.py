"""``plans synth``: a mechanism from requirements: by the time-ratio coefficient K (a
crank-rocker, an offset crank-slider, a shaper's slotted link) or by two or three given
positions (a four-bar), every answer checked by the engine and written as a mechanism file.

    plans synth crank-rocker K=1.25 psi_deg=32 CD=0.29 BC=0.26 -o rocker.toml
    plans synth crank-slider K=1.5 H=0.05 e=0.02 --svg sheet.svg --png sheet.png
    plans synth samples/synth_rocker.toml --lang ru --note note.md

The report goes to stdout (``--json``: as data); ``-o`` writes the mechanism file (``-o -``
prints it instead of the report), ``--svg``/``--png``/``--pdf`` the construction sheet,
``--note`` the explanatory note's synthesis section. Every output is checked before
anything is computed and written only once all are made.
"""

from __future__ import annotations

import json
import sys
from dataclasses import replace
from pathlib import Path

from drawing import export
from drawing.sheet.layout import LayoutError
from drawing.synth_sheet import FIELDS
from drawing.synth_sheet import render as render_sheet
from plans.cli.common import EXIT_OK, number, picture_names
from plans.errors import InputError
from plans.synthesis import check, mechanism_toml, read_file, read_pairs, synthesise
from plans.synthesis.note import note
from plans.synthesis.problem import KINDS
from plans.synthesis.report import as_json, text

PICTURES = {".svg": ("--svg", "svg"), ".png": ("--png", "png"), ".pdf": ("--pdf", "pdf")}


def configure(p) -> None:
    p.add_argument("what", nargs="*", metavar="KIND|FILE [KEY=VALUE ...]",
                   help="the kind (" + ", ".join(KINDS) + ") and its requirements as KEY=VALUE "
                        "(metres, degrees for keys ending _deg), or a synthesis file (TOML) "
                        "with KEY=VALUE over it")
    p.add_argument("-o", "--output", metavar="MECH.toml",
                   help="write the mechanism file ('-': print it instead of the report)")
    p.add_argument("--json", action="store_true", help="print the report as JSON")
    p.add_argument("--lang", default="en", choices=["en", "ru"],
                   help="language of the report, the note and the sheet (default en)")
    p.add_argument("--solution", type=number(1, 1000, integer=True), metavar="N",
                   help="take solution N of those listed (default: the best by the criterion)")
    p.add_argument("--svg", metavar="SHEET.svg", help="the construction sheet (SVG)")
    p.add_argument("--png", metavar="SHEET.png", help="the construction sheet as PNG (needs cairosvg)")
    p.add_argument("--pdf", metavar="SHEET.pdf", help="the construction sheet as PDF (needs cairosvg)")
    p.add_argument("--dpi", type=number(10, 600), default=100.0,
                   help="PNG resolution, 10 to 600 (default 100)")
    p.add_argument("--format", default="A3", choices=["A1", "A2", "A3"],
                   help="the construction sheet's format (default A3)")
    p.add_argument("--title-block", nargs="*", default=[], metavar="KEY=VALUE",
                   help="title-block fields: " + ", ".join(sorted(FIELDS)))
    p.add_argument("--note", metavar="NOTE.md",
                   help="also write the explanatory note's synthesis section (Markdown)")


def _problem(args):
    words = list(args.what)
    if not words:
        raise InputError("command line", "give the kind (" + ", ".join(KINDS) + ") and its "
                         "requirements, e.g. plans synth crank-rocker K=1.25 psi_deg=32 CD=0.29, "
                         "or a synthesis file")
    first = words[0]
    if "=" not in first and (first.lower().endswith(".toml") or Path(first).is_file()):
        args.run_files.claim(args, [first])
        problem = read_file(first, words[1:])
    else:
        args.run_files.check(args)
        problem = read_pairs(words)
    if args.solution is not None:
        problem = replace(problem, solution=args.solution)
    return problem


def run(args) -> int:
    if args.output == "-" and args.json:
        raise InputError("command line", "-o - prints the mechanism file to stdout, where --json "
                         "would print the report: give -o a file name")
    picture_names(args, PICTURES)
    problem = _problem(args)
    if args.png or args.pdf:
        export.require()  # before anything is computed
    design = synthesise(problem)
    got = check(design)
    if not got.ok:  # the engine does not give the answer back: a bug, never bad input
        raise RuntimeError(f"the engine's re-analysis differs from the synthesis by {got.worst:.1e}: "
                           + "; ".join(f"{r.name} {r.synthesis!r} vs {r.engine!r}" for r in got.rows))
    mech_text = mechanism_toml(design, got)
    written = args.output if args.output not in (None, "-") else None
    files: list[tuple[str | None, str | bytes]] = []
    if args.output:
        files.append((args.output, mech_text))
    if args.svg or args.png or args.pdf:
        try:
            svg = render_sheet(design, got, args.format, args.lang, args.title_block)
        except LayoutError as exc:
            raise InputError("--format", str(exc)) from None
        if args.svg:
            files.append((args.svg, svg))
        if args.png:
            files.append((args.png, export.png_bytes(svg, dpi=args.dpi)))
        if args.pdf:
            files.append((args.pdf, export.pdf_bytes(svg)))
    if args.note:
        files.append((args.note, note(design, got, args.lang)))
    if args.output != "-":
        report = (json.dumps(as_json(design, got, written), ensure_ascii=False, indent=1) + "\n"
                  if args.json else text(design, got, args.lang, written))
    for path, data in files:
        args.run_files.write(path, data)
    if args.output != "-":
        sys.stdout.write(report)
    return EXIT_OK
