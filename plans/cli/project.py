"""``plans project``: everything a course project hands in for one mechanism, in one
folder: drawing sheet 1 as SVG, PDF and DXF, the explanatory note as Markdown, DOCX and
PDF (in the text document's frame), and the results as JSON.

    plans project --variant 3 -o project/
    plans project samples/press.toml --format A1 -o press/ --title-block student=Иванов group=ТМ-21

The note is the sheet's: its plans at the sheet's scale factors, then the force
analysis where the file has loads, so that every segment it gives is one the sheet
draws; ``results.json`` is ``plans solve --json`` of the same position at the same
scales (and ``forces.json`` ``plans forces --json``). Everything is computed and
rendered before the first file is written; each file is written atomically; a summary
lists what was written.
"""

from __future__ import annotations

import json
import sys
from pathlib import Path

from drawing import docx as docx_writer
from drawing import dxf, export, notepdf
from drawing.document import parse_note
from drawing.sheet.layout import LayoutError
from drawing.sheet1 import FIELDS, POSITIONS, parse_plans, plain_titles, sparse_note
from drawing.sheet1 import render as render_sheet
from plans.cli import forces as forces_cli
from plans.cli import solve as solve_cli
from plans.cli.common import EXIT_OK, add_source, angle_field, mechanism_from, number, warn
from plans.cli.output import arg_text
from plans.cli.report import title_block
from plans.cycle import outside_range
from plans.errors import AssemblyError, InputError
from plans.forces.note import force_note
from plans.forces.summary import solve_forces
from plans.note.report import note

#: what a project holds, in the order it is listed: (file, what it is)
FILES = (
    ("sheet-1.svg", "drawing sheet 1, SVG"),
    ("sheet-1.pdf", "drawing sheet 1, PDF"),
    ("sheet-1.dxf", "drawing sheet 1, DXF for КОМПАС-3D and AutoCAD"),
    ("note.md", "explanatory note, Markdown"),
    ("note.docx", "explanatory note, DOCX"),
    ("note.pdf", "explanatory note, PDF"),
    ("results.json", "positions, velocities, accelerations, plans' segments (plans solve --json)"),
    ("forces.json", "loads, reactions, balancing moment, drive (plans forces --json)"),
)


def configure(p) -> None:
    add_source(p)
    p.add_argument("-o", "--output-dir", dest="folder", metavar="DIR", required=True,
                   help="the project's folder (made where it does not exist)")
    p.add_argument("--format", default="A1", choices=["A0", "A1", "A2", "A3", "A4"],
                   help="the sheet's format (default A1)")
    p.add_argument("--lang", default="ru", choices=["ru", "en"],
                   help="language of the sheet and the note (default ru)")
    p.add_argument("--positions", type=number(*POSITIONS, integer=True), default=12, metavar="N",
                   help="crank positions on the plan of positions (default 12)")
    p.add_argument("--plans", metavar="1,4",
                   help="position numbers to draw the plans for (default: the file's position)")
    p.add_argument("--title-block", nargs="*", default=[], metavar="KEY=VALUE",
                   help="title-block fields of the sheet and the note: " + ", ".join(sorted(FIELDS)))
    p.add_argument("--no-frame", action="store_true",
                   help="the note's DOCX and PDF without the text document's frame")


def _progress(step: int, total: int, what: str) -> None:
    """One line of progress on a terminal (rewritten in place), nothing elsewhere."""
    if sys.stderr.isatty():
        print(f"\rplans project: {step}/{total} {what:<40}", end="", file=sys.stderr, flush=True)


def _folder(path: str) -> Path:
    out = Path(path)
    if out.exists() and not out.is_dir():
        raise InputError("-o", f"{arg_text(path)[1:-1]} is a file: give the project's folder")
    if not out.exists() and not out.parent.is_dir():
        raise InputError("-o", f"the folder {arg_text(str(out.parent))} does not exist")
    return out


def build(mech, args) -> list[tuple[str, str | bytes]]:
    """Every file of the project, as (name, content), in the order of :data:`FILES`."""
    steps = 7 + (mech.loads is not None)
    plans = None
    if args.plans is not None:
        plans = parse_plans(args.plans, 10**6)  # the numbers' form; the sheet checks their range
    _progress(1, steps, "drawing sheet 1")
    try:
        svg, info = render_sheet(mech, args.format, args.lang, args.positions, plans, args.title_block)
    except LayoutError as exc:
        raise InputError(mech.source, str(exc)) from None
    except AssemblyError as exc:
        raise outside_range(mech, exc, *angle_field(args, mech)) from None
    if (text := sparse_note(mech, info["sheet"], info["placed"])) is not None:
        print(f"plans project: note: {mech.source}: {text}", file=sys.stderr)
    given, cycle, sols = info["given"], info["cycle"], info["solutions"]
    for _, _, sol in sols:
        for w in sol.warnings:
            warn("project", w, mech.source)
    files: list[tuple[str, str | bytes]] = [("sheet-1.svg", svg)]
    _progress(2, steps, "sheet 1 as PDF")
    files.append(("sheet-1.pdf", export.pdf_bytes(svg)))
    _progress(3, steps, "sheet 1 as DXF")
    files.append(("sheet-1.dxf", dxf.to_dxf(info["scene"], info["sheet"], title=mech.name_in(args.lang),
                                            lang=args.lang)))
    _progress(4, steps, "the explanatory note")
    text = note(given, args.lang, cycle, plain_titles(sols) if sols[0][0] != "g" else ())
    F = None
    if mech.loads is not None:  # the note goes on with the force analysis
        F = solve_forces(given, given.solver, cycle)
        section = sum(line.startswith("## ") for line in text.splitlines()) + 1
        text = text.rstrip("\n") + "\n\n" + force_note(F, args.lang, section)
    files.append(("note.md", text))
    doc = parse_note(text, args.lang)
    tb = title_block(mech, args.title_block, args.lang)
    _progress(5, steps, "the note as DOCX")
    files.append(("note.docx", docx_writer.to_docx(doc, not args.no_frame, tb)))
    _progress(6, steps, "the note as PDF")
    files.append(("note.pdf", notepdf.to_pdf(doc, not args.no_frame, tb)))
    _progress(7, steps, "the results as JSON")
    files.append(("results.json", json.dumps(solve_cli.to_json(given, cycle), ensure_ascii=False,
                                             indent=2) + "\n"))
    if F is not None:
        _progress(8, steps, "the forces as JSON")
        files.append(("forces.json", json.dumps(forces_cli.to_json(F), ensure_ascii=False, indent=2) + "\n"))
    if sys.stderr.isatty():
        print(file=sys.stderr)
    return files


def _size(n: int) -> str:
    return f"{n} B" if n < 1024 else f"{n / 1024:.0f} kB" if n < 1024**2 else f"{n / 1024**2:.1f} MB"


def run(args) -> int:
    folder = _folder(args.folder)
    for require in (export.require, dxf.require, docx_writer.require, notepdf.require):
        require()  # every format, before anything is computed
    mech = mechanism_from(args)
    files = build(mech, args)  # every file made before the first is written
    folder.mkdir(exist_ok=True)
    words = dict(FILES)
    width = max(len(str(folder / name)) for name, _ in files)
    lines = []
    for name, data in files:
        path = folder / name
        args.run_files.write(str(path), data)
        size = len(data.encode("utf-8") if isinstance(data, str) else data)
        lines.append(f"  {path!s:<{width}}  {_size(size):>7}  {words[name]}")
    print(f"plans project: {mech.name_in(args.lang)}: {len(files)} files in {folder}/")
    print("\n".join(lines))
    return EXIT_OK
