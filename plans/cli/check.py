"""``plans check MEAS.toml``: a hand-drawn plan against the computed one, and the mistake.

Exit status: 0 every item within tolerance, 1 something is not, 2 bad input. Several
files (``plans check students/*.toml``) are checked by :mod:`plans.cli.check_batch`,
one summary table.
"""

from __future__ import annotations

from pathlib import Path

from drawing import export
from drawing.overlay import overlay_svg
from plans.check import verdict as ck
from plans.check.words import WORDS as CHECK_WORDS
from plans.cli.check_batch import run as run_batch
from plans.cli.check_report import PNG_SCALE, command_tolerance, json_text, to_json, to_text
from plans.cli.common import (
    EXIT_DEVIATIONS,
    EXIT_OK,
    arg_text,
    make_folder,
    picture_names,
    same_file,
    warn,
)
from plans.cli.words import WORDS


def configure(p) -> None:
    p.add_argument("file", metavar="MEAS.toml", nargs="+",
                   help="the measurement file: mechanism, crank position, the student's scale "
                        "factors and the segments measured on the drawing (mm). Several "
                        "files: one summary table, a row per file (file, title, mechanism, "
                        "verdict, diagnosis); a file that cannot be checked is a row of "
                        "its own. Exit status the worst of theirs: 3 an internal error, "
                        "else 2 bad input, else 1 beyond tolerance, else 0")
    p.add_argument("--tolerance", metavar="TOL",
                   help='allowed deviation, e.g. "5%%", "1mm" or "5%%,1mm" '
                        "(default: the larger of 1 mm and 5 %%); a number needs its unit")
    p.dash_values = ("--tolerance",)  # "--tolerance -5%" is a wrong tolerance, said as one
    p.add_argument("--json", action="store_true",
                   help="machine-readable output (several files: a list, one object per file)")
    p.add_argument("--svg", metavar="OUT.svg|DIR",
                   help="also draw the student's plan over the computed one (a folder, "
                        "existing or written DIR/, takes DIR/STEM.svg for each file checked; "
                        "several files: a folder)")
    p.add_argument("--png", metavar="OUT.png|DIR",
                   help="the same drawing as a PNG (needs cairosvg, the export extra: "
                        "pip install '.[export]' in the source folder; a folder as --svg)")
    # the languages both word tables speak, the check's and the report's
    p.add_argument("--lang", choices=[lang for lang in WORDS if lang in CHECK_WORDS], default="en",
                   help="language of the report (ru: decimal commas)")
    p.add_argument("-o", "--output", metavar="FILE",
                   help="write the report (several files: the table) to FILE instead of stdout")


def run(args) -> int:
    command_tolerance(args)  # "--tolerance 5" is refused before any file is read
    if len(args.file) > 1:  # a table, a row per file, each file once
        return run_batch(args, once_each(args.file))
    args.file = args.file[0]
    for attr, suffix in (("svg", ".svg"), ("png", ".png")):  # a teacher's glob of one file
        folder = getattr(args, attr)
        if folder not in (None, "", "-") and (Path(folder).is_dir() or folder.endswith(("/", "\\"))):
            setattr(args, attr, str(Path(folder) / f"{Path(args.file).stem}{suffix}"))
            make_folder(Path(folder), f"--{attr}", folder)
    args.run_files.claim(args, [args.file])
    picture_names(args, {".svg": ("--svg", "svg"), ".png": ("--png", "png")})
    if args.png:
        export.require()  # before anything is computed
    meas = ck.load(args.file)
    args.run_files.claim(args, meas.inputs[1:])
    result = ck.check(meas, command_tolerance(args))  # None: the file's own, or the default
    files = []  # all built before any is written
    if args.svg or args.png:
        svg = overlay_svg(result, lang=args.lang)
        if args.svg:
            files.append((args.svg, svg))
        if args.png:
            files.append((args.png, export.png_bytes(svg, scale=PNG_SCALE)))
    if args.json:
        text = json_text(to_json(result, args.lang))
    else:
        text = to_text(result, args.lang)
    for path, data in [*files, (args.output, text)]:
        args.run_files.write(path, data)
    for w in result.measurement.solution.warnings:  # as solve and report: on stderr too
        warn("check", w)
    return EXIT_OK if result.ok else EXIT_DEVIATIONS


def once_each(files: list[str]) -> list[str]:
    """The measurement files in the order given, each once: a file named twice (by two
    globs, or by two names of one file) is checked and counted once, and said so."""
    out: list[str] = []
    for path in files:
        first = next((p for p in out if p == path or same_file(p, path)), None)
        if first is None:
            out.append(path)
            continue
        also = "" if first == path else f" (as {arg_text(first)})"
        warn("check", f"{arg_text(path)} is given twice{also}: checked and counted once")
    return out
