"""The ``plans`` command: argparse front end, one module per command family.

Exit status: 0 success, 1 a check found deviations, 2 bad input or an unsolvable scene,
3 internal error (rerun with --debug for the traceback).
"""

from __future__ import annotations

import argparse
import importlib
import importlib.util
import re
import sys
from pathlib import Path

from plans.errors import InputError, PlansError

EXIT_OK, EXIT_DEVIATIONS, EXIT_INPUT, EXIT_INTERNAL = 0, 1, 2, 3

#: command → (module, help); each module has ``configure(parser)`` and ``run(args) -> int``
COMMANDS = {
    "solve": ("plans.cli.solve", "positions and both plans for one crank position"),
    "report": ("plans.cli.report", "the explanatory-note text, step by step (Markdown)"),
    "cycle": ("plans.cli.cycle", "every point and link over N crank positions"),
    "sheet": ("plans.cli.sheet", "drawing sheet 1 as SVG (ESKD frame and title block)"),
    "check": ("plans.cli.check", "check a hand-drawn plan against the computed one"),
    "bench": ("plans.cli.bench", "speed and error against a high-precision reference"),
}

EPILOG = """exit status: 0 success, 1 a check found deviations, 2 bad input or an
unsolvable scene, 3 internal error (rerun with --debug for the traceback)"""


def add_source(p: argparse.ArgumentParser, *, allow_all: bool = False) -> None:
    """FILE | --variant N [--table FILE]: where the mechanism comes from."""
    p.add_argument("file", nargs="?", help="mechanism file (TOML)")
    p.add_argument("--variant", metavar="N" if not allow_all else "N|all",
                   help="a row of the variant table instead of a file")
    p.add_argument("--table", metavar="FILE", help="a course's variant table (default: the built-in Table 2)")
    from plans.model.fileformat import MAX_ABS

    p.add_argument("--angle", type=number(-MAX_ABS, MAX_ABS), metavar="DEG",
                   help="crank angle, in the convention of the file (default: the file's)")


def number(lo: float, hi: float, integer: bool = False):
    """An argparse type: a finite number from ``lo`` to ``hi`` (an integer if asked), else
    one line saying so."""
    import math

    def parse(text: str):
        try:
            value = int(text) if integer else float(text)
        except ValueError:
            value = None
        if value is None or not math.isfinite(value) or not lo <= value <= hi:
            kind = "a whole number" if integer else "a number"
            span = f"{int(lo)} to {int(hi)}" if integer else f"{lo:g} to {hi:g}"
            raise argparse.ArgumentTypeError(f"{_arg(text, 30)} is not {kind} from {span}")
        return value

    return parse


def mechanism_from(args, table=None):
    """The mechanism named by FILE or --variant, with --angle applied; ``table``: the
    variant table of ``--table`` already read (``sheet --variant all`` reads it once for
    all its rows, and says each row's problems with that row's sheet).

    Refuses, before anything is computed, an output (``-o``) that is one of the inputs, and
    remembers the inputs so that :func:`write_output` refuses them too.
    """
    import re

    from plans.model import load, variants

    if (args.file is None) == (args.variant is None):
        raise InputError("command line", "give a mechanism FILE or --variant N (one of them)")
    path = getattr(args, "table", None)
    if path is not None and args.variant is None:
        raise InputError("command line", "--table goes with --variant N: a mechanism FILE "
                                         "is read as it is")
    if path == "":
        raise InputError("command line", "--table was given an empty file name")
    claim_inputs(args, [p for p in (args.file, path) if p])
    angle = getattr(args, "angle", None)  # a finite number within ±MAX_ABS: argparse checked
    if args.variant is not None:
        text = str(args.variant).strip()
        if not re.fullmatch(r"[+-]?\d{1,9}", text):
            raise InputError("command line", f"--variant: {_arg(args.variant, 30)} is not a variant number (0, 1, 2…)")
        t = table or variants.read_table(path)
        mech = t.variant(int(text))
        if table is None:
            for line in t.others(int(text)):
                warn(args.command, line)
    else:
        mech = load(args.file)
    return mech if angle is None else mech.at_file_angle(angle)


def angle_field(args, mech) -> tuple[str, float]:
    """Where the crank angle of ``mech`` came from, for a message about it, and its value
    as given: ``--angle``, the file's ``driver.angle_deg``, or a variant row's ``phi_deg``."""
    if getattr(args, "angle", None) is not None:
        return "--angle", args.angle
    if getattr(args, "variant", None) is not None:  # the row's column (its source names the row)
        return "phi_deg", mech.driver.angle_deg
    return "driver.angle_deg", mech.driver.angle_deg


def solved_position(args, mech):
    """(cycle, solution) of ``mech`` at its crank angle, as solve and report need them:
    the cycle first, which sizes the plan of positions and words the solution's angles;
    where it does not assemble there, the error names the field the angle came from
    (:func:`angle_field`) and the crank's range where it does
    (:func:`plans.cycle.outside_range`)."""
    from plans.cycle import analyse_cycle, outside_range
    from plans.errors import AssemblyError
    from plans.kinematics.solver import Solver
    from plans.plan.solution import solve_position

    try:
        solver = Solver(mech)
        cycle = analyse_cycle(mech, solver=solver)
        return cycle, solve_position(mech, solver=solver, cycle=cycle)
    except AssemblyError as exc:
        raise outside_range(mech, exc, *angle_field(args, mech)) from None


#: the input files of the running command (see claim_inputs): never written over
_INPUTS: list[str] = []


#: the output options of the commands: (option, attribute); ``-o`` alone is stdout when
#: absent, the others are then not written at all
OUTPUTS = (("-o", "output"), ("--svg", "svg"), ("--note", "note"), ("--png", "png"),
           ("--pdf", "pdf"), ("--chart", "chart"))


def claim_inputs(args, paths) -> None:
    """Remember files the command reads, so that :func:`write_output` never writes over
    them, and refuse at once (before anything is computed) an output given as one, or
    any output that could not be written (:func:`check_outputs`)."""
    _INPUTS.extend(p for p in map(str, paths) if p not in _INPUTS)  # a batch claims each row
    check_outputs(args)


def check_outputs(args) -> None:
    """Refuse, before anything is computed or written, an output that could not be
    written (a folder, a folder that does not exist, an input) and two outputs that
    are one file, or both stdout: a run writes all its outputs or none."""
    seen: list[tuple[str, str]] = []
    for opt, attr in OUTPUTS:
        if not hasattr(args, attr):
            continue
        out = getattr(args, attr)
        if out in (None, "") and attr != "output":  # not asked for ('' is bench's "no chart")
            continue
        target = "-" if out in (None, "-") or _is_stdout(str(out)) else str(out)
        for other_opt, other in seen:
            if (target == "-" and other == "-") or (target != "-" and other != "-"
                                                    and _same_file(target, other)
                                                    and not _device(target)):
                what = "stdout" if target == "-" else _arg(target)
                raise InputError("command line", f"{other_opt} and {opt} are both {what}: "
                                 "give each output its own file")
        seen.append((opt, target))
        if target != "-":
            _target(target, opt)



KINDS = {".svg": "an SVG", ".png": "a PNG", ".pdf": "a PDF"}
#: names of other picture formats, which no command writes
PICTURE_SUFFIXES = {*KINDS, ".jpg", ".jpeg", ".gif", ".bmp", ".tif", ".tiff", ".webp", ".eps",
                    ".ps", ".dxf"}


def picture_names(args, pictures: dict[str, tuple[str, str]]) -> None:
    """Refuse an output name of another picture format than its option writes (x.png
    given to an option that writes SVG would hold SVG text): one line, before anything
    is computed or written. ``pictures``: the command's option and attribute for each
    format it writes, by suffix ({".svg": ("-o", "output"), …}), which also name the
    option to use instead. A name of no picture format (``-o sheet1``), stdout ('-') and
    a device (/dev/null) are taken as they are."""
    for suffix, (opt, attr) in pictures.items():
        path = getattr(args, attr)
        if path in (None, "-"):
            continue
        p = Path(path)
        other = p.suffix.lower()
        if other == suffix or other not in PICTURE_SUFFIXES:
            continue
        if p.exists() and not p.is_file() and not p.is_dir():  # /dev/null, a pipe
            continue
        hint = f"; for {KINDS[other]} give {pictures[other][0]} {path}" if other in pictures else ""
        raise InputError("command line", f"{opt} {path}: the name must end in {suffix} ({opt} "
                         f"writes {suffix[1:].upper()}){hint}")


def _arg(value, limit: int = 200) -> str:
    """A command-line value for a message: one line, cut short."""
    text = "".join(c if c.isprintable() else "?" for c in str(value)[: limit + 1])
    return repr(text if len(text) <= limit else text[: limit - 1] + "…")


def _same_file(a, b) -> bool:
    import os

    try:
        if os.path.exists(a) and os.path.exists(b):
            return os.path.samefile(a, b)
        return Path(a).resolve() == Path(b).resolve()
    except (OSError, ValueError, RuntimeError):
        return False


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
        sys.exit(EXIT_INPUT)


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
    parser = build_parser(only=_command_in(argv))
    try:  # argparse ends --help and its own errors with SystemExit: main returns the code
        args, extra = parser.parse_known_args(argv)
        if extra:  # blamed on the command, which lists what it takes in its --help
            command = parser.commands.get(getattr(args, "command", None) or "", parser)
            command.error(f"unrecognized arguments: {' '.join(extra)}")
    except SystemExit as exc:
        return exc.code if isinstance(exc.code, int) else EXIT_INPUT
    if not getattr(args, "run", None):
        parser.print_help()
        return EXIT_INPUT
    _INPUTS.clear()  # each command claims the files it reads
    try:
        return args.run(args)
    except PlansError as exc:
        for line in error_lines(exc):
            print(f"plans {args.command}: {line}", file=sys.stderr)
        return EXIT_INPUT
    except KeyboardInterrupt:
        print(f"plans {args.command}: interrupted", file=sys.stderr)
        return 130
    except BrokenPipeError:
        return EXIT_OK
    except OSError as exc:  # stdout on a full disk or a dead device: bad output, not a bug
        import errno

        if exc.errno not in (errno.ENOSPC, errno.EIO, errno.EDQUOT, errno.EROFS):
            raise
        print(f"plans {args.command}: cannot write the output: {exc.strerror}", file=sys.stderr)
        _drop_stdout()
        return EXIT_INPUT
    except Exception as exc:  # an internal error: short message, traceback on --debug
        if args.debug:
            raise
        print(
            f"plans {args.command}: internal error: {type(exc).__name__}: {exc} "
            "(rerun with --debug for the traceback)",
            file=sys.stderr,
        )
        return EXIT_INTERNAL


def error_lines(exc: PlansError) -> list[str]:
    """The lines that say ``exc``, as ``plans CMD: LINE`` prints each: an input error
    names its file itself; a position that cannot be solved (a group that does not close,
    a dead point) carries the mechanism it belongs to, which is put before each line."""
    source = getattr(exc, "source", "")
    where = f"{source}: " if source and not isinstance(exc, InputError) else ""
    return [f"{where}{line}" for line in str(exc).splitlines() or [type(exc).__name__]]


def _drop_stdout() -> None:
    """Point stdout at the null device: what it still holds would fail again as the
    interpreter exits, as "Exception ignored" with exit status 120."""
    import os

    try:
        null = os.open(os.devnull, os.O_WRONLY)
        os.dup2(null, sys.stdout.fileno())
        os.close(null)
    except (OSError, ValueError):  # no file descriptor to point (a test's captured stdout)
        pass


def warn(command: str, text: str, source: str = "") -> None:
    """One warning line on stderr: "plans CMD: warning: [SOURCE: ]text"."""
    print(f"plans {command}: warning: {source + ': ' if source else ''}{text}", file=sys.stderr)


def write_output(path: str | None, text) -> None:
    """Write to stdout ('-' or None) or atomically to a file: a temporary file in the
    target folder, renamed over the target only when complete, so an existing output is
    replaced only by a complete new one. Refuses the command's input files, a folder,
    and a folder that does not exist; a file that cannot be written is bad input (exit 2),
    not an internal error.

    ``text``: a str, bytes, or an iterable of str chunks, written as they come (a table
    of 10⁵ rows never stands in memory as one string)."""
    import os
    import stat
    import tempfile

    chunks = [text] if isinstance(text, (str, bytes)) else text
    if path in (None, "-") or _is_stdout(path):  # /dev/stdout too: never replaced by a file
        for chunk in chunks:
            if isinstance(chunk, bytes):
                sys.stdout.buffer.write(chunk)
            else:
                sys.stdout.write(chunk)
        sys.stdout.flush()  # now, inside main's handler, not at the interpreter's exit
        return
    where, target, st, folder = _target(path)

    def fill(fh) -> None:
        for chunk in chunks:
            fh.write(chunk.encode("utf-8") if isinstance(chunk, str) else chunk)

    if st is not None and not stat.S_ISREG(st.st_mode):  # /dev/null, a pipe: no rename
        try:
            with open(target, "wb") as fh:
                fill(fh)
        except OSError as exc:
            raise InputError(where, f"cannot write: {exc.strerror}") from None
        return
    if st is not None:
        mode = stat.S_IMODE(st.st_mode)
    else:
        umask = os.umask(0o022)
        os.umask(umask)
        mode = 0o666 & ~umask
    try:
        fd, tmp = tempfile.mkstemp(prefix=f".{target.name}.", suffix=".tmp", dir=folder)
    except OSError as exc:
        raise InputError(where, f"cannot write in the folder {_arg(folder)}: {exc.strerror}") from None
    try:
        with os.fdopen(fd, "wb") as fh:
            fill(fh)
            fh.flush()
            os.fsync(fh.fileno())
        os.chmod(tmp, mode)
        os.replace(tmp, target)
    except BaseException as exc:
        Path(tmp).unlink(missing_ok=True)
        if isinstance(exc, OSError):
            raise InputError(where, f"cannot write: {exc.strerror or exc}") from None
        raise


def _device(path: str) -> bool:
    """The null device, which any number of outputs may share."""
    import os

    try:
        return os.path.samefile(path, os.devnull)
    except OSError:
        return False


def _is_stdout(path: str) -> bool:
    """/dev/stdout, /dev/fd/1 or anything else that is this process's standard output."""
    import os

    try:
        a, b = os.stat(path), os.fstat(sys.stdout.fileno())
    except (OSError, ValueError, AttributeError):
        return False
    return (a.st_dev, a.st_ino) == (b.st_dev, b.st_ino) and not _device(path)


def _target(path: str, opt: str | None = None):
    """(name for messages, Path, its stat or None, its folder) of an output file that can
    be written; InputError where it cannot (an input, a folder, no such folder). ``opt``:
    the option that named it, for the message about an input."""
    import os
    import stat

    if not str(path):
        raise InputError("command line", "an output option was given an empty file name")
    where = _arg(path)[1:-1]
    for inp in _INPUTS:
        if _same_file(path, inp):
            if opt is None:
                raise InputError(where, f"is the input file {_arg(inp)}: the tool never "
                                 "writes into its inputs")
            raise InputError("command line", f"{opt} {_arg(path)} is the input file "
                             f"{_arg(inp)}: the tool never writes into its inputs; choose "
                             "another output name")
    target = Path(path)
    try:
        st = target.stat()  # through a symbolic link, of what it names
    except FileNotFoundError:
        st = None
    except OSError as exc:
        raise InputError(where, f"cannot write: {exc.strerror}") from None
    if st is not None and stat.S_ISDIR(st.st_mode):
        raise InputError(where, "is a folder: give a file name")
    if st is not None and stat.S_ISREG(st.st_mode) and os.path.islink(path):
        target = Path(os.path.realpath(path))  # written through the link, never replacing it
    folder = target.parent if str(target.parent) else Path(".")
    if st is None or stat.S_ISREG(st.st_mode):
        if not folder.is_dir():
            raise InputError(where, f"the folder {_arg(folder)} does not exist")
    return where, target, st, folder
