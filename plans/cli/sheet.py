"""``plans sheet``: drawing sheet 1 (plan of positions, velocity and acceleration
plans, kinematic diagrams, tables) and sheet 2 (the force analysis), each as one SVG in
real millimetres.

    plans sheet samples/press.toml --format A2 -o press.svg
    plans sheet --variant 3 --format A2 --lang en --plans 1,4 -o v3.svg --png v3.png
    plans sheet samples/press.toml --sheet 2 -o press-2.svg
    plans sheet samples/press.toml --sheet 1,2 -o press.svg   # press.svg and press-2.svg
    plans sheet --variant all -o sheets/      # one sheet per variant
    plans sheet samples/press.toml -o press.svg --dxf press.dxf   # and for a CAD program

The sheets are built by :mod:`drawing.sheet1` and :mod:`drawing.sheet2`; this module is
the command around them: its options, the files it writes (all rendered before the first
is written: both sheets, their pictures and the note, or none) and the batch of a whole
table of variants. Where both sheets are drawn, each file option names sheet 1's file
and sheet 2's goes beside it, its name's stem ending in "-2" (:func:`beside`).
"""

from __future__ import annotations

import copy
import difflib
import re
import sys
from pathlib import Path

from drawing import dxf, export
from drawing.sheet.frame import FORMATS
from drawing.sheet.layout import LayoutError
from drawing.sheet1 import FIELDS, POSITIONS, plain_titles, sparse_note
from drawing.sheet1 import render as render_sheet
from drawing.sheet2 import needs_loads
from drawing.sheet2 import render as render_sheet2
from plans.cli.common import (
    EXIT_INPUT,
    EXIT_OK,
    add_source,
    angle_field,
    arg_text,
    make_folder,
    mechanism_from,
    number,
    picture_names,
    same_file,
    say,
    warn,
)
from plans.cycle import outside_range
from plans.errors import AssemblyError, InputError, PlansError
from plans.forces.note import force_note
from plans.model.variants import DESIGNATION, read_table
from plans.note.report import note

#: the longest title-block entry any cell holds: the widest cell (field 1, 70 mm, three
#: lines) takes about 120 letters of 1.8 mm condensed; a longer one is refused at once
MAX_ENTRY = 200
#: field 4 (the literal) has three cells of one letter each
LITERAL_CELLS = 3
#: the built-in table's designation on an English sheet: «ПМ» is «прикладная механика»,
#: the workbook's subject, applied mechanics (a table's own designation is kept as given)
#: by language, where it is not the table's own
DESIGNATION_IN = {"en": "AM.01.{n:02d}"}


def configure(p) -> None:
    add_source(p, allow_all=True)
    p.add_argument("--sheet", default="1", metavar="1|2|1,2|all",
                   help="which sheet: 1 the kinematics (default), 2 the force analysis (needs "
                        "[loads]), 1,2 or all both: then -o, --png and --pdf name sheet 1's files "
                        "and sheet 2's go beside them, NAME-2.svg")
    p.add_argument("-o", "--output", metavar="OUT.svg",
                   help="SVG file, '-' for stdout, or a folder with --variant all (default: "
                        "stdout, unless it is a terminal)")
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
                        "(with --variant all: a folder, DIR/variant-N.md for each sheet)")
    p.add_argument("--png", metavar="FILE",
                   help="also write a PNG (needs cairosvg; with --variant all: a folder)")
    p.add_argument("--pdf", metavar="FILE",
                   help="also write a PDF (needs cairosvg; with --variant all: a folder)")
    p.add_argument("--dxf", metavar="FILE", nargs="?", const="",
                   help="also write the sheet as DXF for КОМПАС or AutoCAD (needs ezdxf); with "
                        "--variant all, --dxf alone writes each beside its SVG")
    p.add_argument("--dpi", type=number(10, 600), default=100.0,
                   help="PNG resolution, 10 to 600 (default 100); a PNG has at most "
                        f"{export.MAX_PIXELS // 1_000_000} million pixels (A1 up to "
                        f"{export.largest_dpi(*FORMATS['A1'])} dpi, A0 up to "
                        f"{export.largest_dpi(*FORMATS['A0'])})")


#: what --sheet takes
SHEETS = {"1": (1,), "2": (2,), "1,2": (1, 2), "2,1": (1, 2), "all": (1, 2)}


def sheets_of(text: str) -> tuple[int, ...]:
    """--sheet's sheets, in order: "1", "2", "1,2" or "all".

    >>> sheets_of("2"), sheets_of(" 1, 2 "), sheets_of("ALL")
    ((2,), (1, 2), (1, 2))
    """
    got = SHEETS.get(text.replace(" ", "").lower())
    if got is None:
        raise InputError("--sheet", f"{text!r}: give 1 (the kinematics), 2 (the force analysis), "
                         "1,2 or all (both)")
    return got


def beside(path: str | None, n: int = 2) -> str | None:
    """The name of sheet ``n``'s file beside sheet 1's ``path``: its stem ending in "-n",
    in the same folder, with the same ending.

    >>> beside("out/press.svg"), beside("press.PNG"), beside("sheet"), beside(None)
    ('out/press-2.svg', 'press-2.PNG', 'sheet-2', None)
    """
    if path is None:
        return None
    p = Path(path)
    return str(p.with_name(f"{p.stem}-{n}{p.suffix}"))


def render(mech, args, numbers: tuple[str, str] | None = None) -> tuple[str, str | None, dict]:
    """(sheet 1's SVG, its explanatory note or None when --note is not asked for, what
    :func:`drawing.sheet1.render` tells of it); ``numbers``: the sheet's number and the
    count of sheets, where both are drawn."""
    plans = None if args.plans is None else position_numbers(args.plans)
    try:
        svg, info = render_sheet(mech, args.format, args.lang, args.positions, plans,
                                 [*args.title_block, *designation_in(mech, args)], numbers)
    except LayoutError as exc:  # named by its file (or its table's variant), not an option
        raise InputError(mech.source, str(exc)) from None
    except AssemblyError as exc:  # an angle where it does not assemble: which, and where it does
        raise outside_range(mech, exc, *angle_field(args, mech)) from None
    if (text := sparse_note(mech, info["sheet"], info["placed"])) is not None:
        say("sheet", f"note: {mech.source}: {text}")
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
    return svg, text, info


def position_numbers(text: str) -> list[int]:
    """--plans: the position numbers, at most 72 of them and each of a few digits
    (a 5,000-digit number had ended in an internal error).

    >>> position_numbers("1, 4")
    [1, 4]
    """
    parts = [t.strip() for t in text.split(",") if t.strip()]
    if not parts or len(parts) > POSITIONS[1] or not all(re.fullmatch(r"-?\d{1,6}", t) for t in parts):
        raise InputError("--plans", f"{arg_text(text, 60)} is not a list of position numbers like 1,4")
    return [int(t) for t in parts]


def title_entries(pairs) -> None:
    """Refuse, before anything is drawn, a --title-block entry of an unknown field (with
    the field meant, where it is plain), one no cell holds, and a literal longer than its
    three cells: each in one line."""
    for pair in pairs:
        key, eq, value = pair.partition("=")
        key = key.strip()
        if not eq:
            raise InputError("--title-block", f"{arg_text(pair, 60)} is not KEY=VALUE")
        if key.lower() not in FIELDS:
            near = difflib.get_close_matches(key.lower(), FIELDS, n=1, cutoff=0.6)
            hint = f' — did you mean "{near[0]}"?' if near else ""
            raise InputError("--title-block", f"unknown title-block field {arg_text(key, 40)}{hint}; "
                             f"known: {', '.join(sorted(FIELDS))}")
        if len(value) > MAX_ENTRY:
            raise InputError("--title-block", f"{key}= ({len(value)} characters) does not fit any "
                             f"cell of the title block, which holds at most {MAX_ENTRY}: shorten it")
        if FIELDS[key.lower()] == "literal" and len(value) > LITERAL_CELLS:
            raise InputError("--title-block", f"{key}={arg_text(value, 40)} does not fit field 4: "
                             f"the literal has {LITERAL_CELLS} cells of one letter each (e.g. У)")


def designation_in(mech, args) -> list[str]:
    """The built-in table's designation for an English sheet ("AM.01.03" for
    «ПМ.01.03»), where neither the command line nor another table gives one: a sheet in
    English carries no Cyrillic of the tool's own."""
    own = DESIGNATION_IN.get(args.lang)
    if own is None or getattr(args, "table", None) or args.variant is None:
        return []
    if any(FIELDS.get(p.partition("=")[0].strip().lower()) == "designation" for p in args.title_block):
        return []
    n = int(str(args.variant).strip())
    if (mech.title or {}).get("designation") != DESIGNATION.format(n=n):
        return []
    return [f"designation={own.format(n=n)}"]


def render2(mech, args, numbers: tuple[str, str], beside_: dict[str, float] | None) -> tuple[str, dict]:
    """(sheet 2's SVG, what :func:`drawing.sheet2.render` tells of it); ``beside_``: sheet
    1's μv and μa where it is drawn too."""
    try:
        svg, info = render_sheet2(mech, args.format, args.lang, args.positions,
                                  [*args.title_block, *designation_in(mech, args)], numbers, beside_)
    except LayoutError as exc:
        raise InputError(mech.source, str(exc)) from None
    except AssemblyError as exc:
        raise outside_range(mech, exc, *angle_field(args, mech)) from None
    if info["sparse"] is not None:
        say("sheet", f"note: {mech.source}: sheet 2: {info['sparse']}")
    return svg, info


def render_all(mech, args, sheets: tuple[int, ...]) -> list[tuple[str | None, str | bytes]]:
    """Every file of the run as (path, data): the sheets asked for, the note, PNGs and
    PDFs, all rendered before the first is written, so that a failed export leaves every
    existing output as it was. Sheet 2's files go :func:`beside` sheet 1's where both are
    drawn."""
    both = len(sheets) == 2
    files: list[tuple[str | None, str | bytes]] = []
    text = None
    besides = None
    if 1 in sheets:
        svg, text, info = render(mech, args, ("1", "2") if both else None)
        files += _pictures(svg, args.output, args.png, args.pdf, args)
        if getattr(args, "dxf", None):  # from the scene the SVG was written from
            files.append((args.dxf, dxf.to_dxf(info["scene"], info["sheet"], title=mech.name_in(args.lang),
                                               lang=args.lang)))
        given = info["given"]
        besides = {"mu_v": given.velocity.mu, "mu_a": given.acceleration.mu}
    if 2 in sheets:
        svg2, info2 = render2(mech, args, ("2", "2"), besides)
        if 1 not in sheets or args.plans is not None:  # a plan near a dead point is said so once
            for w in info2["solution"].warnings:
                warn("sheet", w, mech.source)
        names = (beside(args.output), beside(args.png), beside(args.pdf)) if both else (
            args.output, args.png, args.pdf)
        files += _pictures(svg2, *names, args)
        if getattr(args, "dxf", None):
            drawn = dxf.to_dxf(info2["scene"], info2["sheet"], title=mech.name_in(args.lang), lang=args.lang)
            files.append((beside(args.dxf) if both else args.dxf, drawn))
        if getattr(args, "note", None):
            forces = info2["forces"]
            if text is None:  # the note of the position sheet 2 draws, then its forces
                text = note(info2["solution"], args.lang, info2["cycle"])
            section = sum(line.startswith("## ") for line in text.splitlines()) + 1
            text = text.rstrip("\n") + "\n\n" + force_note(forces, args.lang, section)
    if text is not None:
        files.append((args.note, text))
    return files


def _pictures(svg: str, output, png, pdf, args) -> list[tuple[str | None, str | bytes]]:
    """A sheet's SVG at ``output``, and its PNG and PDF where asked for."""
    out: list[tuple[str | None, str | bytes]] = [(output, svg)]
    if png:
        out.append((png, export.png_bytes(svg, dpi=args.dpi)))
    if pdf:
        out.append((pdf, export.pdf_bytes(svg)))
    return out


def _write(files: list[tuple[str | None, str | bytes]], args) -> None:
    for path, data in files:
        args.run_files.write(path, data)


def _check_second(args, sheets: tuple[int, ...]) -> None:
    """Refuse, before anything is computed, what sheet 2's files beside sheet 1's could
    not be: stdout (two sheets are two files), a file of the run's own, or one another's."""
    if len(sheets) < 2:
        return
    if args.output in (None, "-"):
        raise InputError("-o", "two sheets are two files: give -o NAME.svg (sheet 2 is written "
                         "beside it as NAME-2.svg)")
    second = copy.copy(args)
    second.output, second.png, second.pdf, second.note = (beside(args.output), beside(args.png),
                                                          beside(args.pdf), None)
    second.dxf = beside(getattr(args, "dxf", None) or None)
    args.run_files.check(second)
    firsts = [getattr(args, a) for a in ("output", "png", "pdf", "note", "dxf") if getattr(args, a, None)]
    for path in (second.output, second.png, second.pdf, second.dxf):
        if path and any(same_file(path, other) for other in firsts):
            raise InputError("command line", f"{path} is both sheet 2's file (beside sheet 1's) and "
                             "another output: give them other names")


#: the option (and its attribute) that writes each picture format
PICTURES = {".svg": ("-o", "output"), ".png": ("--png", "png"), ".pdf": ("--pdf", "pdf"),
            ".dxf": ("--dxf", "dxf")}


def run(args) -> int:
    sheets = sheets_of(args.sheet)
    title_entries(args.title_block)
    if args.plans is not None:
        position_numbers(args.plans)  # once, not for each variant of --variant all
    if args.png:
        export.check_raster(*FORMATS[args.format], args.dpi, f"the {args.format} sheet")
    if str(args.variant).strip().lower() == "all" and args.file is None:
        return _batch(args, sheets)
    if args.output is None and sys.stdout.isatty():
        raise InputError("command line", "the sheet is an SVG of some 250 KB, not for a terminal: "
                         "give -o FILE.svg (or -o - to print it all the same)")
    if args.dxf == "":
        raise InputError("--dxf", "give the DXF's file name: --dxf FILE (--dxf alone is for "
                         "--variant all, which writes each DXF beside its SVG)")
    picture_names(args, PICTURES)  # x.png given to -o would hold SVG text
    _plans_need_sheet_1(args, sheets)
    mech = mechanism_from(args)
    _check_second(args, sheets)
    if 2 in sheets:
        needs_loads(mech)  # one line, before sheet 1 is drawn
    if args.png or args.pdf:
        export.require()  # before anything is computed
    if args.dxf:
        dxf.require()
    _write(render_all(mech, args, sheets), args)
    return EXIT_OK


def _plans_need_sheet_1(args, sheets: tuple[int, ...]) -> None:
    """--plans chooses sheet 1's plans: with sheet 2 alone it would be dropped unsaid."""
    if args.plans is not None and 1 not in sheets:
        raise InputError("--plans", "chooses the positions of sheet 1's plans; sheet 2 draws the "
                         "force analysis of the file's position (choose it with --angle): give "
                         "--sheet 1,2, or leave --plans out")


def _folder(args, opt: str, attr: str) -> Path | None:
    """The folder an output option names with --variant all (each sheet's file goes in it
    under the variant's name); refused in one line where it is a file or looks like a
    file's name (it had been ignored without a word)."""
    value = getattr(args, attr)
    if value is None:
        return None
    hint = f"with --variant all give a folder, e.g. {opt} {'sheets' if opt == '-o' else attr}/"
    if value in ("", "-"):
        raise InputError(opt, f"{arg_text(value)}: {hint}")
    d = Path(value)
    if d.exists() and not d.is_dir():
        raise InputError(opt, f"{value} is not a folder: {hint}")
    if not d.exists() and d.suffix and not value.endswith(("/", "\\")):
        raise InputError(opt, f"{value} looks like a file name: {hint}")
    return d


def _batch(args, sheets: tuple[int, ...] = (1,)) -> int:
    _plans_need_sheet_1(args, sheets)
    if not args.output or args.output == "-":
        raise InputError("-o", "with --variant all give a folder: -o DIR/")
    out = _folder(args, "-o", "output")
    folders = {attr: _folder(args, opt, attr) or out
               for opt, attr in (("--png", "png"), ("--pdf", "pdf"), ("--note", "note"))}
    if args.dxf is not None:
        dxf.require()  # before a folder is made or a row is drawn
    table = read_table(args.table)  # once, for every row
    numbers = table.numbers  # a table that cannot be used: no folder made
    for line in table.others(None):  # rows with no number: no sheet
        warn("sheet", line)
    if args.png or args.pdf:
        export.require()  # before any folder is made
    make_folder(out, "-o", args.output)
    for opt, attr in (("--png", "png"), ("--pdf", "pdf"), ("--note", "note")):
        if getattr(args, attr):
            make_folder(folders[attr], opt, getattr(args, attr))
    tty = sys.stderr.isatty()
    failed: list[tuple[int, str]] = []
    for i, n in enumerate(numbers, 1):
        if tty:
            print(f"\rsheet {i}/{len(numbers)}: variant {n} ", end="", file=sys.stderr, flush=True)
        a = copy.copy(args)
        a.variant = str(n)
        # sheet 1 variant-N.svg, sheet 2 beside it variant-N-2.svg, whichever are drawn
        stem = f"variant-{n}" if 1 in sheets else f"variant-{n}-2"
        a.output = str(out / f"{stem}.svg")
        a.png = str(folders["png"] / f"{stem}.png") if args.png else None
        a.pdf = str(folders["pdf"] / f"{stem}.pdf") if args.pdf else None
        a.note = str(folders["note"] / f"variant-{n}.md") if args.note else None
        a.dxf = str(out / f"{stem}.dxf") if args.dxf is not None else None
        try:
            mech = mechanism_from(a, table)
            if 2 in sheets:
                needs_loads(mech)
            _write(render_all(mech, a, sheets), a)
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
            say("sheet", line)
    if failed:
        say("sheet", f"{len(failed)} of {len(numbers)} sheets failed")
        return EXIT_INPUT
    return EXIT_OK


if __name__ == "__main__":  # pragma: no cover
    from plans.cli.common import main

    sys.exit(main(["sheet", *sys.argv[1:]]))
