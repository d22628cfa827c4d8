"""``plans sheet``: drawing sheet 1 (plan of positions, velocity and acceleration
plans, kinematic diagrams, tables) as one SVG in real millimetres.

    plans sheet samples/press.toml --format A2 -o press.svg
    plans sheet --variant 3 --format A2 --lang en --plans 1,4 -o v3.svg --png v3.png
    plans sheet --variant all -o sheets/      # one sheet per variant
    plans sheet samples/press.toml -o press.svg --dxf press.dxf   # and for a CAD program

The sheet is built by :mod:`drawing.sheet1`; this module is the command around it: its
options, the files it writes (all rendered before the first is written) and the batch of
a whole table of variants.
"""

from __future__ import annotations

import copy
import sys
from pathlib import Path

from drawing import dxf, export
from drawing.sheet.layout import LayoutError
from drawing.sheet1 import FIELDS, POSITIONS, plain_titles, sparse_note
from drawing.sheet1 import render as render_sheet
from plans.cli.common import (
    EXIT_INPUT,
    EXIT_OK,
    add_source,
    angle_field,
    mechanism_from,
    number,
    picture_names,
    warn,
)
from plans.cycle.analysis import outside_range
from plans.errors import AssemblyError, InputError, PlansError
from plans.model.variants import read_table
from plans.note.report import note


def configure(p) -> None:
    add_source(p, allow_all=True)
    p.add_argument("-o", "--output", metavar="OUT.svg",
                   help="SVG file, '-' for stdout, or a folder with --variant all (default: stdout)")
    p.add_argument("--format", default="A1", choices=["A0", "A1", "A2", "A3", "A4"],
                   help="sheet format (default A1)")
    p.add_argument("--lang", default="ru", choices=["ru", "en"], help="language of the sheet (default ru)")
    p.add_argument("--positions", type=number(*POSITIONS, integer=True), default=12, metavar="N",
                   help="crank positions on the plan of positions (default 12)")
    p.add_argument("--plans", metavar="1,4",
                   help="position numbers (from an extreme position) to draw the plans for, "
                        "drawn heavy on the plan of positions; default: the position given "
                        "in the file")
    p.add_argument("--title-block", nargs="*", default=[], metavar="KEY=VALUE",
                   help="title-block fields: " + ", ".join(sorted(FIELDS)))
    p.add_argument("--note", metavar="NOTE.md",
                   help="also write the explanatory note (Markdown) of the positions the sheet "
                        "draws plans for, at the sheet's scale factors and in its language "
                        "(with --variant all: a note beside each sheet)")
    p.add_argument("--png", metavar="FILE", help="also write a PNG (needs cairosvg)")
    p.add_argument("--pdf", metavar="FILE", help="also write a PDF (needs cairosvg)")
    p.add_argument("--dxf", metavar="FILE", nargs="?", const="",
                   help="also write the sheet as DXF for КОМПАС or AutoCAD (needs ezdxf); with "
                        "--variant all, --dxf alone writes each beside its SVG")
    p.add_argument("--dpi", type=number(10, 600), default=100.0,
                   help="PNG resolution, 10 to 600 (default 100)")


def render(mech, args) -> tuple[str, str | None, bytes | None]:
    """(the sheet's SVG, its explanatory note or None when --note is not asked for, its
    DXF or None when --dxf is not asked for)."""
    plans = None
    if args.plans is not None:
        plans = [int(t) for t in args.plans.split(",") if t.strip()] if all(
            t.strip().lstrip("-").isdigit() for t in args.plans.split(",") if t.strip()) else None
        if plans is None:
            raise InputError("--plans", f"{args.plans!r} is not a list of position numbers like 1,4")
    try:
        svg, info = render_sheet(mech, args.format, args.lang, args.positions, plans,
                                 args.title_block)
    except LayoutError as exc:  # named by its file (or its table's variant), not an option
        raise InputError(mech.source, str(exc)) from None
    except AssemblyError as exc:  # an angle where it does not assemble: which, and where it does
        raise outside_range(mech, exc, *angle_field(args, mech)) from None
    if (text := sparse_note(mech, info["sheet"], info["placed"])) is not None:
        print(f"plans sheet: note: {mech.source}: {text}", file=sys.stderr)
    for _, _, sol in info["solutions"]:  # a plan drawn near a dead point is said so
        for w in sol.warnings:
            warn("sheet", w, mech.source)
    text = None
    if getattr(args, "note", None):
        sols = info["solutions"]
        # the plans' titles as plain text ("φ_1" is φ1); none for the given position
        # alone ("g"), whose plans are the note's own sections
        titles = plain_titles(sols)
        # the structure and μl from the given position; with --plans the plan of
        # positions draws theirs heavy, and the note says so and gives their segments
        text = note(info["given"], args.lang, info["cycle"], titles if sols[0][0] != "g" else ())
    drawn = None
    if getattr(args, "dxf", None) is not None:  # from the scene the SVG was written from
        drawn = dxf.to_dxf(info["scene"], info["sheet"], title=mech.name_in(args.lang),
                           lang=args.lang)
    return svg, text, drawn


def _write(rendered: tuple[str, str | None, bytes | None], args) -> None:
    """The SVG, and the note, PNG, PDF and DXF asked for: all rendered before the first
    is written, so that a failed export leaves every existing output as it was."""
    svg, text, drawn = rendered
    files: list[tuple[str | None, str | bytes]] = [(args.output, svg)]
    if text is not None:
        files.append((args.note, text))
    if drawn is not None:
        files.append((args.dxf, drawn))
    if args.png or args.pdf:
        if args.png:
            files.append((args.png, export.png_bytes(svg, dpi=args.dpi)))
        if args.pdf:
            files.append((args.pdf, export.pdf_bytes(svg)))
    for path, data in files:
        args.run_files.write(path, data)


#: the option (and its attribute) that writes each picture format
PICTURES = {".svg": ("-o", "output"), ".png": ("--png", "png"), ".pdf": ("--pdf", "pdf"),
            ".dxf": ("--dxf", "dxf")}


def run(args) -> int:
    if str(args.variant).strip().lower() == "all" and args.file is None:
        return _batch(args)
    if args.dxf == "":
        raise InputError("--dxf", "give the DXF's file name: --dxf FILE (--dxf alone is for "
                         "--variant all, which writes each DXF beside its SVG)")
    picture_names(args, PICTURES)  # x.png given to -o would hold SVG text
    mech = mechanism_from(args)
    if args.png or args.pdf:
        export.require()  # before anything is computed
    if args.dxf:
        dxf.require()
    _write(render(mech, args), args)
    return EXIT_OK


def _batch(args) -> int:
    if not args.output or args.output == "-":
        raise InputError("-o", "with --variant all give a folder: -o DIR/")
    out = Path(args.output)
    if out.exists() and not out.is_dir():
        raise InputError("-o", f"{args.output} is not a folder")
    if not out.exists() and out.suffix and not args.output.endswith(("/", "\\")):
        raise InputError("-o", f"{args.output} looks like a file name: with --variant all give a "
                         "folder, e.g. -o sheets/")
    if args.dxf is not None:
        dxf.require()  # before a folder is made or a row is drawn
    table = read_table(args.table)  # once, for every row
    numbers = table.numbers  # a table that cannot be used: no folder made
    for line in table.others(None):  # rows with no number: no sheet
        warn("sheet", line)
    out.mkdir(parents=True, exist_ok=True)
    tty = sys.stderr.isatty()
    failed: list[tuple[int, str]] = []
    for i, n in enumerate(numbers, 1):
        if tty:
            print(f"\rsheet {i}/{len(numbers)}: variant {n} ", end="", file=sys.stderr, flush=True)
        a = copy.copy(args)
        a.variant = str(n)
        a.output = str(out / f"variant-{n}.svg")
        a.png = str(out / f"variant-{n}.png") if args.png else None
        a.pdf = str(out / f"variant-{n}.pdf") if args.pdf else None
        a.note = str(out / f"variant-{n}.md") if args.note else None
        a.dxf = str(out / f"variant-{n}.dxf") if args.dxf is not None else None
        try:
            mech = mechanism_from(a, table)
            _write(render(mech, a), a)
        except (PlansError, ValueError, ArithmeticError) as exc:
            source = getattr(exc, "source", "")  # an input error names its source itself
            msg = str(exc) if isinstance(exc, InputError) or not source else f"{source}: {exc}"
            if f"variant {n}:" not in msg.split("\n")[0]:  # named by an option (--plans)
                msg = "\n".join(f"variant {n}: {line}" for line in msg.split("\n"))
            failed.append((n, msg))
    if tty:
        print(file=sys.stderr)
    for _, msg in failed:
        for line in msg.splitlines():
            print(f"plans sheet: {line}", file=sys.stderr)
    if failed:
        print(f"plans sheet: {len(failed)} of {len(numbers)} sheets failed", file=sys.stderr)
        return EXIT_INPUT
    return EXIT_OK


if __name__ == "__main__":  # pragma: no cover
    from plans.cli.common import main

    sys.exit(main(["sheet", *sys.argv[1:]]))
