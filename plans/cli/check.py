"""``plans check MEAS.toml``: a hand-drawn plan against the computed one, and the mistake.

Exit status: 0 every item within tolerance, 1 something is not, 2 bad input. Several
files (``plans check students/*.toml``) are checked by :mod:`plans.cli.check_batch`,
one summary table.
"""

from __future__ import annotations

import json

from drawing import export
from drawing.overlay import overlay_svg
from plans.check import verdict as ck
from plans.check.words import WORDS as CHECK_WORDS
from plans.cli.check_batch import run as run_batch
from plans.cli.check_report import PNG_SCALE, command_tolerance, to_json, to_text
from plans.cli.common import EXIT_DEVIATIONS, EXIT_OK, picture_names, warn
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
                        "(default: the larger of 1 mm and 5 %%)")
    p.dash_values = ("--tolerance",)  # "--tolerance -5%" is a wrong tolerance, said as one
    p.add_argument("--json", action="store_true",
                   help="machine-readable output (several files: a list, one object per file)")
    p.add_argument("--svg", metavar="OUT.svg|DIR",
                   help="also draw the student's plan over the computed one (several files: "
                        "a folder, DIR/STEM.svg for each file checked)")
    p.add_argument("--png", metavar="OUT.png|DIR",
                   help="the same drawing as a PNG (needs cairosvg: pip install "
                        "'vector-plans[export]'; several files: a folder, as --svg)")
    # the languages both word tables speak, the check's and the report's
    p.add_argument("--lang", choices=[lang for lang in WORDS if lang in CHECK_WORDS], default="en",
                   help="language of the report (ru: decimal commas)")
    p.add_argument("-o", "--output", metavar="FILE",
                   help="write the report (several files: the table) to FILE instead of stdout")


def run(args) -> int:
    if len(args.file) > 1:
        return run_batch(args, args.file)
    args.file = args.file[0]
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
        text = json.dumps(to_json(result, args.lang), ensure_ascii=False, indent=2) + "\n"
    else:
        text = to_text(result, args.lang)
    for path, data in [(args.output, text), *files]:
        args.run_files.write(path, data)
    for w in result.measurement.solution.warnings:  # as solve and report: on stderr too
        warn("check", w)
    return EXIT_OK if result.ok else EXIT_DEVIATIONS
