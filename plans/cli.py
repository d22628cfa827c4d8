"""The ``plans`` command: argparse front end, one module per command family.

Exit status: 0 success, 1 a check found deviations, 2 bad input or an unsolvable scene,
3 internal error (rerun with --debug for the traceback).
"""

from __future__ import annotations

import argparse
import importlib
import sys
from pathlib import Path

from .errors import InputError, PlansError

EXIT_OK, EXIT_DEVIATIONS, EXIT_INPUT, EXIT_INTERNAL = 0, 1, 2, 3

#: command → (module, help); each module has ``configure(parser)`` and ``run(args) -> int``
COMMANDS = {
    "solve": ("plans.cli_solve", "positions and both plans for one crank position"),
    "report": ("plans.cli_report", "the explanatory-note text, step by step (Markdown)"),
    "cycle": ("plans.cli_cycle", "every point and link over N crank positions"),
    "sheet": ("drawing.cli_sheet", "drawing sheet 1 as SVG (ESKD frame and title block)"),
    "check": ("plans.cli_check", "check a hand-drawn plan against the computed one"),
    "bench": ("plans.bench", "speed and error against a high-precision reference"),
}

EPILOG = """exit status: 0 success, 1 a check found deviations, 2 bad input or an
unsolvable scene, 3 internal error (rerun with --debug for the traceback)"""


def add_source(p: argparse.ArgumentParser, *, allow_all: bool = False) -> None:
    """FILE | --variant N [--table FILE]: where the mechanism comes from."""
    p.add_argument("file", nargs="?", help="mechanism file (TOML)")
    p.add_argument("--variant", metavar="N" if not allow_all else "N|all",
                   help="a row of the variant table instead of a file")
    p.add_argument("--table", metavar="FILE", help="a course's variant table (default: the built-in Table 2)")
    p.add_argument("--angle", type=float, metavar="DEG",
                   help="crank angle, in the convention of the file (default: the file's)")


def mechanism_from(args):
    """The mechanism named by FILE or --variant, with --angle applied."""
    from . import mechanism, variants

    if (args.file is None) == (args.variant is None):
        raise InputError("command line", "give a mechanism FILE or --variant N (one of them)")
    if args.variant is not None:
        try:
            n = int(args.variant)
        except ValueError:
            raise InputError("command line", f"--variant: {args.variant!r} is not a number") from None
        mech = variants.variant(n, args.table)
    else:
        mech = mechanism.load(args.file)
    if getattr(args, "angle", None) is not None:
        import math

        d = mech.driver
        ref = mechanism.REFERENCES[d.reference] + mechanism.SENSES[d.measured] * args.angle
        mech = mech.with_phi(math.radians(ref))
    return mech


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="plans",
        description="Exact vector plans (velocity and acceleration polygons) of planar linkages.",
        epilog=EPILOG,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    parser.add_argument("--debug", action="store_true", help="show the traceback of an internal error")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND")
    for name, (module, help_text) in COMMANDS.items():
        try:
            mod = importlib.import_module(module)
        except ModuleNotFoundError as exc:
            if exc.name == module:
                continue  # a command family not built yet
            raise
        p = sub.add_parser(name, help=help_text, description=help_text, epilog=EPILOG,
                           formatter_class=argparse.RawDescriptionHelpFormatter)
        mod.configure(p)
        p.set_defaults(run=mod.run)
    return parser


def main(argv: list[str] | None = None) -> int:
    parser = build_parser()
    args = parser.parse_args(argv)
    if not getattr(args, "run", None):
        parser.print_help()
        return EXIT_INPUT
    try:
        return args.run(args)
    except PlansError as exc:
        for line in str(exc).splitlines() or [type(exc).__name__]:
            print(f"plans {args.command}: {line}", file=sys.stderr)
        return EXIT_INPUT
    except KeyboardInterrupt:
        print(f"plans {args.command}: interrupted", file=sys.stderr)
        return 130
    except BrokenPipeError:
        return EXIT_OK
    except Exception as exc:  # an internal error: short message, traceback on --debug
        if args.debug:
            raise
        print(
            f"plans {args.command}: internal error: {type(exc).__name__}: {exc} "
            "(rerun with --debug for the traceback)",
            file=sys.stderr,
        )
        return EXIT_INTERNAL


def write_output(path: str | None, text: str | bytes) -> None:
    """Write to stdout ('-' or None) or atomically to a file: a temporary file in the
    target folder, renamed over the target only when complete."""
    import os
    import tempfile

    if path in (None, "-"):
        if isinstance(text, bytes):
            sys.stdout.buffer.write(text)
        else:
            sys.stdout.write(text)
        return
    target = Path(path)
    folder = target.parent if str(target.parent) else Path(".")
    if not folder.is_dir():
        raise InputError(str(path), f"the folder {folder} does not exist")
    data = text.encode("utf-8") if isinstance(text, str) else text
    fd, tmp = tempfile.mkstemp(prefix=f".{target.name}.", suffix=".tmp", dir=folder)
    try:
        with os.fdopen(fd, "wb") as fh:
            fh.write(data)
        os.replace(tmp, target)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise
