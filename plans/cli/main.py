"""The ``plans`` command: argparse front end and the command registry, one module per
command (``configure(parser)`` and ``run(args) -> int`` each).

Exit status (:class:`plans.cli.common.ExitStatus`): 0 success, 1 a check found deviations
(``plans check`` only), 2 bad input or an unsolvable scene, 3 internal error (rerun with
--debug for the traceback), 130 interrupted (Ctrl-C), 143 and 129 stopped by SIGTERM and
SIGHUP.

Each run gets its own :class:`~plans.cli.output.RunFiles` on ``args.run_files``: the files
the command reads are claimed there and never written over, and the files it writes are
committed together once it has made them all, or removed, the old ones left, where it
fails or is stopped.
"""

from __future__ import annotations

import argparse
import errno
import importlib
import importlib.util
import os
import re
import signal
import sys
import threading

from plans.cli.common import ExitStatus, error_lines, say, terminal
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

EPILOG = """exit status: 0 success, 1 a check found deviations (plans check only), 2 bad
input or an unsolvable scene, 3 internal error (rerun with --debug for the traceback)"""


def epilog(command: str) -> str:
    """The exit statuses ``command`` can end with: 1 only where it checks (plans check)."""
    if command == "check":
        return ("exit status: 0 every item within tolerance, 1 a check found deviations, 2 bad\n"
                "input or an unsolvable scene, 3 internal error (rerun with --debug for the\n"
                "traceback)")
    return ("exit status: 0 success, 2 bad input or an unsolvable scene, 3 internal error\n"
            "(rerun with --debug for the traceback)")


class Stopped(BaseException):
    """SIGTERM or SIGHUP during a run: raised where the run is, so that it unwinds as
    Ctrl-C does and its temporary files are removed (a BaseException: no ``except
    Exception`` of a command takes it for an error of its own)."""

    def __init__(self, signum: int) -> None:
        super().__init__(signum)
        self.signum = signum


#: the signals a run stops on as on Ctrl-C, its outputs left as they were
STOP_SIGNALS = tuple(getattr(signal, n) for n in ("SIGTERM", "SIGHUP") if hasattr(signal, n))


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
        print(f"{self.prog}: command line: {terminal(message)} (see {self.prog} --help)",
              file=sys.stderr)
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
        p = sub.add_parser(name, help=help_text, description=help_text, epilog=epilog(name),
                           formatter_class=argparse.RawDescriptionHelpFormatter)
        mod.configure(p)
        # also after the command (plans solve F --debug), as its message says; SUPPRESS:
        # absent there, it leaves the value given before the command alone
        p.add_argument("--debug", action="store_true", default=argparse.SUPPRESS,
                       help="show the traceback of an internal error")
        p.add_argument("--follow-links", action="store_true",
                       help="an output that is a symbolic link: write the file it names "
                            "(default: replace the link with the new file)")
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
    # this run's: each command claims the files it reads and stages those it writes
    args.run_files = RunFiles(follow_links=getattr(args, "follow_links", False))
    held = _stop_on_signals()
    try:
        return _run(args)
    except Stopped as exc:
        name = signal.Signals(exc.signum).name
        say(args.command, f"stopped by {name}: nothing written")
        return 128 + exc.signum
    except PlansError as exc:
        for line in error_lines(exc):
            say(args.command, line)
        return ExitStatus.INPUT
    except KeyboardInterrupt:
        say(args.command, "interrupted")
        return ExitStatus.INTERRUPTED
    except BrokenPipeError:
        return ExitStatus.OK
    except Exception as exc:  # an internal error: short message, traceback on --debug
        if isinstance(exc, OSError) and exc.errno in (errno.ENOSPC, errno.EIO, errno.EDQUOT,
                                                      errno.EROFS):
            # stdout on a full disk or a dead device: bad output, not a bug
            say(args.command, f"cannot write the output: {exc.strerror}")
            _drop_stdout()
            return ExitStatus.INPUT
        if args.debug:
            raise
        say(args.command, f"internal error: {type(exc).__name__}: {terminal(str(exc), 300)} "
                          "(rerun with --debug for the traceback)")
        return ExitStatus.INTERNAL
    finally:
        for signum, handler in held.items():
            signal.signal(signum, handler)


def _run(args) -> int:
    """The command, then its staged outputs committed together; where it fails or is
    stopped, none of them (:class:`~plans.cli.output.RunFiles`)."""
    try:
        code = args.run(args)
        args.run_files.commit()
        return code
    except BaseException:
        args.run_files.abort()
        raise


def _stop(signum, frame) -> None:
    raise Stopped(signum)


def _stop_on_signals() -> dict:
    """SIGTERM and SIGHUP unwind the run as Ctrl-C does (its temporary files removed);
    the handlers they had, to put back (none outside the main thread, where Python
    cannot set them)."""
    if threading.current_thread() is not threading.main_thread():
        return {}
    return {signum: signal.signal(signum, _stop) for signum in STOP_SIGNALS}


def _drop_stdout() -> None:
    """Point stdout at the null device: what it still holds would fail again as the
    interpreter exits, as "Exception ignored" with exit status 120."""
    try:
        null = os.open(os.devnull, os.O_WRONLY)
        os.dup2(null, sys.stdout.fileno())
        os.close(null)
    except (OSError, ValueError):  # no file descriptor to point (a test's captured stdout)
        pass
