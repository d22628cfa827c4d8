"""Where a command's outputs go: checked before anything is computed, and committed together.

A run writes all its outputs or none, and never over a file it reads. The files it reads
are claimed on its :class:`RunFiles`, which ``plans.cli.main`` makes for each run and hands
down on the parsed arguments (``args.run_files``); :func:`check_outputs` refuses, before
anything is computed, an output that is one of them or that could not be written, and
:meth:`RunFiles.write` refuses them again when it writes.

:meth:`RunFiles.write` stages a file: its data goes to a hidden temporary file beside the
target, and ``plans.cli.main`` renames every staged file over its target only once the
command has made them all (:meth:`RunFiles.commit`); a run that fails, is interrupted
(Ctrl-C) or is told to stop (SIGTERM, SIGHUP) removes them (:meth:`RunFiles.abort`) and
leaves every old output as it was. A symbolic link given as an output is replaced by the
new file, never written through (its target is someone else's file), unless the run is
told to (``--follow-links``).
"""

from __future__ import annotations

import os
import re
import stat
import sys
import tempfile
from pathlib import Path

from plans.errors import InputError

#: the output options of the commands: (option, attribute); ``-o`` alone is stdout when
#: absent, the others are then not written at all
OUTPUTS = (("-o", "output"), ("--svg", "svg"), ("--note", "note"), ("--png", "png"),
           ("--pdf", "pdf"), ("--dxf", "dxf"), ("--docx", "docx"), ("--chart", "chart"),
           ("--plot", "plot"))

KINDS = {".svg": "an SVG", ".png": "a PNG", ".pdf": "a PDF", ".dxf": "a DXF"}
#: names of other picture formats, which no command writes
PICTURE_SUFFIXES = {*KINDS, ".jpg", ".jpeg", ".gif", ".bmp", ".tif", ".tiff", ".webp", ".eps",
                    ".ps", ".dxf"}


class RunFiles:
    """The files of one run of a command: those it reads (claimed as it reads them,
    never written over) and the writer of those it writes.

    >>> files = RunFiles()
    >>> files.inputs
    ()
    """

    def __init__(self, follow_links: bool = False) -> None:
        self._inputs: list[str] = []
        self.follow_links = follow_links  # write into a linked file instead of replacing the link
        self._staged: list[tuple[str, Path]] = []  # (temporary, target), renamed by commit()
        self._stdout: list = []  # what goes to stdout, printed by commit() after the files

    @property
    def inputs(self) -> tuple[str, ...]:
        return tuple(self._inputs)

    def claim(self, args, paths) -> None:
        """Remember files the command reads, so that :meth:`write` never writes over them,
        and refuse at once (before anything is computed) an output given as one, or any
        output that could not be written (:func:`check_outputs`)."""
        self._inputs.extend(p for p in map(str, paths) if p not in self._inputs)  # a batch claims each row
        self.check(args)

    def check(self, args) -> None:
        """:func:`check_outputs` of ``args`` against the files claimed so far."""
        check_outputs(args, self._inputs)

    def write(self, path: str | None, text) -> None:
        """Stage an output (:func:`write_output`'s rules, refusing the files claimed): a
        file is written to a temporary beside it and renamed over it by :meth:`commit`,
        with the run's other outputs, and stdout is written then too, last; a device
        (/dev/null) is written at once."""
        if path in (None, "-") or _is_stdout(str(path)):
            self._stdout.append(text)
            return
        staged = _write(path, text, self._inputs, follow_links=self.follow_links, stage=True)
        if staged is not None:
            self._staged.append(staged)

    @property
    def staged(self) -> tuple[str, ...]:
        """The targets written so far, not yet committed."""
        return tuple(str(target) for _, target in self._staged)

    def commit(self) -> None:
        """Rename every staged output over its target, all made before the first goes.
        A rename that fails (a folder made read-only meanwhile) removes the temporaries
        left and is bad input; the outputs already renamed stay new."""
        staged, self._staged = self._staged, []
        printed, self._stdout = self._stdout, []
        for k, (tmp, target) in enumerate(staged):
            try:
                os.replace(tmp, target)
            except OSError as exc:
                for other, _ in staged[k:]:
                    Path(other).unlink(missing_ok=True)
                raise InputError(arg_text(target)[1:-1], f"cannot write: {exc.strerror or exc}") from None
        for text in printed:
            _write(None, text, (), follow_links=False, stage=False)

    def abort(self) -> None:
        """Remove every staged temporary: the run's old outputs stay as they were."""
        staged, self._staged = self._staged, []
        self._stdout = []
        for tmp, _ in staged:
            try:
                Path(tmp).unlink(missing_ok=True)
            except OSError:  # a folder gone meanwhile: nothing left to remove
                pass


def check_outputs(args, inputs=()) -> None:
    """Refuse, before anything is computed or written, an output that could not be
    written (a folder, a folder that does not exist, one of ``inputs``) and two outputs
    that are one file, or both stdout: a run writes all its outputs or none."""
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
                                                    and same_file(target, other)
                                                    and not _device(target)):
                what = "stdout" if target == "-" else arg_text(target)
                raise InputError("command line", f"{other_opt} and {opt} are both {what}: "
                                 "give each output its own file")
        seen.append((opt, target))
        if target != "-":
            _target(target, inputs, opt)


def make_folder(folder, opt: str, given: str | None = None) -> None:
    """Make the folder an output option names (and the folders above it), or say in one
    line why it cannot be made (a file in its path, a read-only folder, a name too long).
    ``given``: the option's value as typed, for the message."""
    try:
        Path(folder).mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise InputError("command line", f"{opt} {given or folder}: cannot make the folder: "
                         f"{exc.strerror or exc}") from None


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


def picture_format(args, attr: str, opt: str, formats=(".png", ".svg", ".pdf")) -> str:
    """The format a picture option (``attr``, given as ``opt``) writes, by its file name's
    ending: "png", "svg" or "pdf"; refused in one line, before anything is computed,
    where the name ends otherwise. A device (/dev/null, a pipe) is written SVG.

    >>> import argparse
    >>> picture_format(argparse.Namespace(plot="cycle.PDF"), "plot", "--plot")
    'pdf'
    """
    path = str(getattr(args, attr))
    p = Path(path)
    suffix = p.suffix.lower()
    if suffix in formats:
        return suffix[1:]
    if p.exists() and not p.is_file() and not p.is_dir():  # /dev/null, a pipe
        return "svg"
    names = ", ".join(formats[:-1]) + f" or {formats[-1]}"
    kinds = ", ".join(f[1:].upper() for f in formats[:-1]) + f" or {formats[-1][1:].upper()}"
    raise InputError("command line", f"{opt} {arg_text(path)[1:-1]}: the name must end in {names} "
                     f"({opt} writes {kinds}, as the name ends)")


def arg_text(value, limit: int = 200) -> str:
    """A command-line value for a message: one line, cut short, in quotes.

    >>> arg_text("a\\nb"), arg_text("x" * 10, 5)
    ("'a?b'", "'xxxx…'")
    """
    text = "".join(c if c.isprintable() else "?" for c in str(value)[: limit + 1])
    return repr(text if len(text) <= limit else text[: limit - 1] + "…")


#: what never reaches a terminal as it is: control characters (escape sequences, a
#: carriage return that overwrites a line, a backspace), and the bidi controls that
#: reorder what a line shows (U+202E turns "txt.exe" round)
_UNSAFE = re.compile("[\x00-\x08\x0b-\x1f\x7f-\x9f\u061c\u200e\u200f\u2028\u2029"
                     "\u202a-\u202e\u2066-\u2069\ufeff]")
#: the longest line said on stderr: an argument of 120 KB is echoed cut, not whole
LINE_LIMIT = 1000


def terminal(text: str, limit: int = LINE_LIMIT) -> str:
    r"""``text`` as the one path for a user's text (a file's title, a file name, an
    argument) to the terminal: one line (a line break inside it is written ``\n``, so
    that no file name forges a line of its own), every control and bidi character
    escaped, and cut at ``limit`` characters with "…".

    >>> print(terminal("a\x1b[31mred\nplans check: ok\u202e"))
    a\x1b[31mred\nplans check: ok\u202e
    >>> len(terminal("x" * 5000, 100))
    100
    """
    text = str(text)
    cut = len(text) > limit
    text = _UNSAFE.sub(lambda m: repr(m.group())[1:-1], text[:limit]).replace("\n", "\\n")
    return text[: limit - 1] + "…" if cut or len(text) > limit else text


def same_file(a, b) -> bool:
    """``a`` and ``b`` name one file (through links too), or would once written."""
    try:
        if os.path.exists(a) and os.path.exists(b):
            return os.path.samefile(a, b)
        return Path(a).resolve() == Path(b).resolve()
    except (OSError, ValueError, RuntimeError):
        return False


def write_output(path: str | None, text, inputs=(), follow_links: bool = False) -> None:
    """Write to stdout ('-' or None) or atomically to a file: a temporary file in the
    target folder, renamed over the target only when complete, so an existing output is
    replaced only by a complete new one. Refuses ``inputs`` (the run's files it reads:
    :meth:`RunFiles.write` passes them), a folder, and a folder that does not exist; a
    file that cannot be written is bad input (exit 2), not an internal error. A symbolic
    link is replaced by the file, unless ``follow_links``: then the file it names is.

    ``text``: a str, bytes, or an iterable of str chunks, written as they come (a table
    of 10⁵ rows never stands in memory as one string)."""
    _write(path, text, inputs, follow_links=follow_links, stage=False)


def _write(path, text, inputs, *, follow_links: bool, stage: bool):
    """:func:`write_output`; with ``stage``, the temporary is not renamed but returned
    as (temporary, target) for :meth:`RunFiles.commit` (None where nothing is left to
    rename: stdout, a device)."""
    chunks = [text] if isinstance(text, (str, bytes)) else text
    if path in (None, "-") or _is_stdout(path):  # /dev/stdout too: never replaced by a file
        for chunk in chunks:
            if isinstance(chunk, bytes):
                sys.stdout.buffer.write(chunk)
            else:
                sys.stdout.write(chunk)
        sys.stdout.flush()  # now, inside main's handler, not at the interpreter's exit
        return None
    where, target, st, folder = _target(path, inputs, follow_links=follow_links)

    def fill(fh) -> None:
        for chunk in chunks:
            fh.write(chunk.encode("utf-8") if isinstance(chunk, str) else chunk)

    if st is not None and not stat.S_ISREG(st.st_mode):  # /dev/null, a pipe: no rename
        try:
            with open(target, "wb") as fh:
                fill(fh)
        except OSError as exc:
            raise InputError(where, f"cannot write: {exc.strerror}") from None
        return None
    if st is not None:
        mode = stat.S_IMODE(st.st_mode)
    else:
        umask = os.umask(0o022)
        os.umask(umask)
        mode = 0o666 & ~umask
    try:
        fd, tmp = tempfile.mkstemp(prefix=f".{target.name}.", suffix=".tmp", dir=folder)
    except OSError as exc:
        raise InputError(where, f"cannot write in the folder {arg_text(folder)}: {exc.strerror}") from None
    try:
        with os.fdopen(fd, "wb") as fh:
            fill(fh)
            fh.flush()
            os.fsync(fh.fileno())
        os.chmod(tmp, mode)
        if stage:
            return tmp, target
        os.replace(tmp, target)
    except BaseException as exc:
        Path(tmp).unlink(missing_ok=True)
        if isinstance(exc, OSError):
            raise InputError(where, f"cannot write: {exc.strerror or exc}") from None
        raise
    return None


def _device(path: str) -> bool:
    """The null device, which any number of outputs may share."""
    try:
        return os.path.samefile(path, os.devnull)
    except OSError:
        return False


def _is_stdout(path: str) -> bool:
    """/dev/stdout, /dev/fd/1 or anything else that is this process's standard output."""
    try:
        a, b = os.stat(path), os.fstat(sys.stdout.fileno())
    except (OSError, ValueError, AttributeError):
        return False
    return (a.st_dev, a.st_ino) == (b.st_dev, b.st_ino) and not _device(path)


def _target(path: str, inputs=(), opt: str | None = None, follow_links: bool = False):
    """(name for messages, Path, its stat or None, its folder) of an output file that can
    be written; InputError where it cannot (one of ``inputs``, a folder, no such folder).
    ``opt``: the option that named it, for the message about an input. A symbolic link to
    a file is the target itself (the new file replaces the link), or with
    ``follow_links`` the file it names."""
    if not str(path):
        raise InputError("command line", "an output option was given an empty file name")
    where = arg_text(path)[1:-1]
    for inp in inputs:
        if same_file(path, inp):
            if opt is None:
                raise InputError(where, f"is the input file {arg_text(inp)}: the tool never "
                                 "writes into its inputs")
            raise InputError("command line", f"{opt} {arg_text(path)} is the input file "
                             f"{arg_text(inp)}: the tool never writes into its inputs; choose "
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
    if follow_links and st is not None and stat.S_ISREG(st.st_mode) and os.path.islink(path):
        target = Path(os.path.realpath(path))  # written through the link, as asked
    folder = target.parent if str(target.parent) else Path(".")
    if st is None or stat.S_ISREG(st.st_mode):
        if not folder.is_dir():
            raise InputError(where, f"the folder {arg_text(folder)} does not exist")
    return where, target, st, folder
