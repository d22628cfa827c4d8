"""``plans report``: the explanatory-note text of one crank position (Markdown), and the
note as a document: ``--docx`` (editable, its formulas as Office Math) and ``--pdf``,
on request in the text document's frame with its title block (``--frame``).

    plans report samples/press.toml --lang ru -o note.md
    plans report --variant 3 --lang ru --docx note.docx --pdf note.pdf --frame \\
        --title-block student=Иванов group=ТМ-21
"""

from __future__ import annotations

from pathlib import Path

from drawing import docx as docx_writer
from drawing import notepdf
from drawing.document import parse_note
from drawing.sheet.frame import TitleBlock
from drawing.sheet1 import FIELDS, title_fields
from plans.cli.common import EXIT_OK, add_source, mechanism_from, solved_position, warn
from plans.errors import InputError
from plans.forces.note import force_note
from plans.forces.summary import solve_forces, unbalanced
from plans.note.report import note


def configure(p) -> None:
    add_source(p)
    p.add_argument("--lang", choices=("ru", "en"), default="en",
                   help="language of the note (ru uses a decimal comma)")
    p.add_argument("-o", "--output", metavar="FILE",
                   help="write the Markdown to FILE instead of stdout (with --docx or --pdf, "
                        "the Markdown is written only where -o asks for it)")
    p.add_argument("--docx", metavar="FILE", help="also write the note as DOCX (needs python-docx)")
    p.add_argument("--pdf", metavar="FILE", help="also write the note as PDF (needs fpdf2)")
    p.add_argument("--frame", action="store_true",
                   help="the DOCX and PDF in the text document's frame, title block form 2 on "
                        "the first page and 2a on the others (GOST 2.104)")
    p.add_argument("--title-block", nargs="*", default=[], metavar="KEY=VALUE",
                   help="the frame's title block: " + ", ".join(sorted(FIELDS)))


def markdown(args, mech) -> tuple[str, list[str]]:
    """(the note's Markdown, the warnings of its position)."""
    cycle, sol = solved_position(args, mech)
    solver = sol.solver
    numbers: dict = {}  # what the plans printed, for the force section to carry on as printed
    text = note(sol, args.lang, cycle, numbers=numbers)
    warnings = list(sol.warnings)
    why = unbalanced(mech) if mech.loads is not None else None
    if why is not None:  # the note stops at the kinematics, and says why on stderr
        warnings.append(f"the note stops at the kinematics: {why}")
    elif mech.loads is not None:  # the note goes on with the force analysis, section after section
        section = sum(line.startswith("## ") for line in text.splitlines()) + 1
        text = text.rstrip("\n") + "\n\n" + force_note(solve_forces(sol, solver, cycle), args.lang, section,
                                                         numbers)
    return text, warnings


#: an explanatory note's document code after its designation, by language (GOST 2.102's
#: ПЗ; an English designation carries none)
NOTE_CODE = {"ru": "ПЗ"}


def title_block(mech, pairs, lang: str) -> TitleBlock:
    """The text document's title block: the file's [title] and --title-block, its
    designation the document's (GOST 2.102 gives an explanatory note the code ПЗ)."""
    fields = title_fields(mech, pairs, "", lang)
    fields.pop("scale", None)  # a text document has no scale
    designation, code = fields.get("designation", ""), NOTE_CODE.get(lang, "")
    if designation and code and not designation.rstrip().endswith(code):
        fields["designation"] = f"{designation} {code}"
    return TitleBlock(**fields)


def documents(text: str, args, mech) -> list[tuple[str, bytes]]:
    """The DOCX and PDF asked for, as (path, bytes)."""
    out: list[tuple[str, bytes]] = []
    if not (args.docx or args.pdf):
        return out
    doc = parse_note(text, args.lang)
    tb = title_block(mech, args.title_block, args.lang)
    if args.docx:
        out.append((args.docx, docx_writer.to_docx(doc, args.frame, tb)))
    if args.pdf:
        out.append((args.pdf, notepdf.to_pdf(doc, args.frame, tb)))
    return out


def check_names(args) -> None:
    """--docx and --pdf name files of their kind; refused before anything is computed."""
    for opt, attr, suffix in (("--docx", "docx", ".docx"), ("--pdf", "pdf", ".pdf")):
        path = getattr(args, attr)
        if path and path != "-" and Path(path).suffix.lower() != suffix and not (
                Path(path).exists() and not Path(path).is_file()):
            raise InputError("command line", f"{opt} {path}: the name must end in {suffix} ({opt} "
                                             f"writes {suffix[1:].upper()})")
        if path == "-":
            raise InputError("command line", f"{opt} writes a file, not stdout: give its name")


def run(args) -> int:
    check_names(args)
    mech = mechanism_from(args)
    if args.docx:
        docx_writer.require()  # before anything is computed
    if args.pdf:
        notepdf.require()
    text, warnings = markdown(args, mech)
    files = documents(text, args, mech)  # every output made before the first is written
    if args.output is not None or not files:
        args.run_files.write(args.output, text)
    for path, data in files:
        args.run_files.write(path, data)
    for w in warnings:
        warn("report", w)
    return EXIT_OK
