"""The ``plans`` command: argparse front end and the command registry, one module per
command (``configure(parser)`` and ``run(args) -> int`` each).

Exit status (:class:`plans.cli.common.ExitStatus`): 0 success, 1 a check found deviations,
2 bad input or an unsolvable scene, 3 internal error (rerun with --debug for the
traceback).

Each run gets its own :class:`~plans.cli.output.RunFiles` on ``args.run_files``: the files
the command reads are claimed there and never written over.
"""

from __future__ import annotations

import argparse
import errno
import importlib
import importlib.util
import os
import re
import sys

from plans.cli.common import ExitStatus, error_lines
from plans.cli.output import RunFiles
from plans.errors import PlansError

#: command → (module, help); each module has ``configure(parser)`` and ``run(args) -> int``.
#: A run imports the module of its own command only (by name, here)
COMMANDS = {
    "solve": ("plans.cli.solve", "positions and both plans for one crank position"),
    "report": ("plans.cli.report", "the explanatory-note text, step by step (Markdown)"),
    "cycle": ("plans.cli.cycle", "every point and link over N crank positions"),
    "sheet": ("plans.cli.sheet", "drawing sheets as SVG: 1 the kinematics, 2 the force analysis"),
    "forces": ("plans.cli.forces", "force analysis: loads, force plans, Zhukovsky's lever, the drive"),
    "cam": ("plans.cli.cam", "a cam: motion laws, base circle, profile, the cam sheet"),
    "check": ("plans.cli.check", "check a hand-drawn plan against the computed one"),
    "bench": ("plans.cli.bench", "speed and error against a high-precision reference"),
    "synth": ("plans.cli.synth", "a mechanism from requirements: by K or by given positions"),
    "project": ("plans.cli.project", "a course project's files: the sheet, the note, the results"),
}

EPILOG = """exit status: 0 success, 1 a check found deviations, 2 bad input or an
unsolvable scene, 3 internal error (rerun with --debug for the traceback)"""


class _Parser(argparse.ArgumentParser):
    """argparse with the tool's own error format: one line, ``plans COMMAND: command line:
    …``, exit 2, no usage block (``--help`` still prints it).

    ``dash_values``: options whose value may begin with "-" (``--tolerance -5%``).
    argparse reads "-5%" as an option of its own and says "expected one argument"; such
    value that begins as a negative number does ("-5%", "-1mm") is handed to its option
    as ``--tolerance=-5%`` is, so that the command judges it; anything else after the
    option, ``--json`` or its abbreviation ``--js``, is an option, and the tolerance
    still lacks a value."""

    dash_values: tuple[str, ...] = ()

    def parse_known_args(self, args=None, namespace=None):
        args = list(sys.argv[1:] if args is None else args)
        out: list[str] = []
        i = 0
        while i < len(args):
            arg = args[i]
            if arg == "--":
                out += args[i:]
                break
            nxt = args[i + 1] if i + 1 < len(args) else None
            if self._takes_dash_value(arg) and nxt is not None \
                    and re.match(r"[-−][\d.,]", nxt):  # a negative number, never an option
                out.append(f"{arg}={nxt}")
                i += 2
                continue
            out.append(arg)
            i += 1
        return super().parse_known_args(out, namespace)

    def _takes_dash_value(self, arg: str) -> bool:
        """``arg`` is one of :attr:`dash_values`, or an abbreviation that argparse reads
        as one (``--tol``)."""
        if arg in self.dash_values:
            return True
        named = [o for o in self._option_string_actions if arg.startswith("--") and o.startswith(arg)]
        return len(named) == 1 and named[0] in self.dash_values

    def error(self, message: str):  # type: ignore[override]
        print(f"{self.prog}: command line: {message} (see {self.prog} --help)", file=sys.stderr)
        sys.exit(ExitStatus.INPUT)


def build_parser(only: str | None = None) -> argparse.ArgumentParser:
    """The command line's parser: every command's, or with ``only`` just that command's
    options (the others listed by name and help, for ``--help`` and a misspelt command).

    A run needs one command's options: building all six imported their modules and made
    argparse lay out some seventy options, a tenth of what ``plans solve`` takes."""
    parser = _Parser(
        prog="plans",
        description="Exact vector plans (velocity and acceleration polygons) of planar linkages.",
        epilog=EPILOG,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    parser.add_argument("--debug", action="store_true", help="show the traceback of an internal error")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND")
    parser.commands = {}  # name → its parser, for the errors only it can word
    for name, (module, help_text) in COMMANDS.items():
        if only is not None and name != only:
            if _built(module):
                sub.add_parser(name, help=help_text)
            continue
        try:
            mod = importlib.import_module(module)
        except ModuleNotFoundError as exc:
            if _missing(exc, module):
                continue  # a command family not built yet
            raise
        p = sub.add_parser(name, help=help_text, description=help_text, epilog=EPILOG,
                           formatter_class=argparse.RawDescriptionHelpFormatter)
        mod.configure(p)
        # also after the command (plans solve F --debug), as its message says; SUPPRESS:
        # absent there, it leaves the value given before the command alone
        p.add_argument("--debug", action="store_true", default=argparse.SUPPRESS,
                       help="show the traceback of an internal error")
        p.set_defaults(run=mod.run)
        parser.commands[name] = p
    return parser


def _missing(exc: ModuleNotFoundError, module: str) -> bool:
    """``exc`` says that ``module`` itself, or the package it belongs to, is not there
    (not a module that it imports)."""
    return exc.name is not None and (module + ".").startswith(exc.name + ".")


def _built(module: str) -> bool:
    """``module`` is there to import (found, not imported: a package of it may be)."""
    try:
        return importlib.util.find_spec(module) is not None
    except ModuleNotFoundError as exc:  # its package is not there either
        if _missing(exc, module):
            return False
        raise


def _command_in(argv: list[str] | None) -> str:
    """The command named on the command line (after a leading ``--debug``, or "--deb",
    which argparse reads as it), or ""."""
    for arg in sys.argv[1:] if argv is None else argv:
        if not (len(arg) > 2 and "--debug".startswith(arg)):
            return arg if arg in COMMANDS else ""
    return ""


def main(argv: list[str] | None = None) -> int:
    """Run ``plans`` with ``argv`` (default: the process's arguments); the exit status."""
    parser = build_parser(only=_command_in(argv))
    try:  # argparse ends --help and its own errors with SystemExit: main returns the code
        args, extra = parser.parse_known_args(argv)
        if extra:  # blamed on the command, which lists what it takes in its --help
            command = parser.commands.get(getattr(args, "command", None) or "", parser)
            command.error(f"unrecognized arguments: {' '.join(extra)}")
    except SystemExit as exc:
        return exc.code if isinstance(exc.code, int) else ExitStatus.INPUT
    if not getattr(args, "run", None):
        parser.print_help()
        return ExitStatus.INPUT
    args.run_files = RunFiles()  # this run's: each command claims the files it reads
    try:
        return args.run(args)
    except PlansError as exc:
        for line in error_lines(exc):
            print(f"plans {args.command}: {line}", file=sys.stderr)
        return ExitStatus.INPUT
    except KeyboardInterrupt:
        print(f"plans {args.command}: interrupted", file=sys.stderr)
        return ExitStatus.INTERRUPTED
    except BrokenPipeError:
        return ExitStatus.OK
    except OSError as exc:  # stdout on a full disk or a dead device: bad output, not a bug
        if exc.errno not in (errno.ENOSPC, errno.EIO, errno.EDQUOT, errno.EROFS):
            raise
        print(f"plans {args.command}: cannot write the output: {exc.strerror}", file=sys.stderr)
        _drop_stdout()
        return ExitStatus.INPUT
    except Exception as exc:  # an internal error: short message, traceback on --debug
        if args.debug:
            raise
        print(
            f"plans {args.command}: internal error: {type(exc).__name__}: {exc} "
            "(rerun with --debug for the traceback)",
            file=sys.stderr,
        )
        return ExitStatus.INTERNAL


def _drop_stdout() -> None:
    """Point stdout at the null device: what it still holds would fail again as the
    interpreter exits, as "Exception ignored" with exit status 120."""
    try:
        null = os.open(os.devnull, os.O_WRONLY)
        os.dup2(null, sys.stdout.fileno())
        os.close(null)
    except (OSError, ValueError):  # no file descriptor to point (a test's captured stdout)
        pass
