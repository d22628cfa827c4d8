"""Where a command's outputs go: checked before anything is computed, and written atomically.

A run writes all its outputs or none, and never over a file it reads. The files it reads
are claimed on its :class:`RunFiles`, which ``plans.cli.main`` makes for each run and hands
down on the parsed arguments (``args.run_files``); :func:`check_outputs` refuses, before
anything is computed, an output that is one of them or that could not be written, and
:meth:`RunFiles.write` (through :func:`write_output`) refuses them again when it writes.
"""

from __future__ import annotations

import os
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

    def __init__(self) -> None:
        self._inputs: list[str] = []

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
        """:func:`write_output`, refusing the files claimed."""
        write_output(path, text, self._inputs)


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


def same_file(a, b) -> bool:
    """``a`` and ``b`` name one file (through links too), or would once written."""
    try:
        if os.path.exists(a) and os.path.exists(b):
            return os.path.samefile(a, b)
        return Path(a).resolve() == Path(b).resolve()
    except (OSError, ValueError, RuntimeError):
        return False


def write_output(path: str | None, text, inputs=()) -> None:
    """Write to stdout ('-' or None) or atomically to a file: a temporary file in the
    target folder, renamed over the target only when complete, so an existing output is
    replaced only by a complete new one. Refuses ``inputs`` (the run's files it reads:
    :meth:`RunFiles.write` passes them), a folder, and a folder that does not exist; a
    file that cannot be written is bad input (exit 2), not an internal error.

    ``text``: a str, bytes, or an iterable of str chunks, written as they come (a table
    of 10⁵ rows never stands in memory as one string)."""
    chunks = [text] if isinstance(text, (str, bytes)) else text
    if path in (None, "-") or _is_stdout(path):  # /dev/stdout too: never replaced by a file
        for chunk in chunks:
            if isinstance(chunk, bytes):
                sys.stdout.buffer.write(chunk)
            else:
                sys.stdout.write(chunk)
        sys.stdout.flush()  # now, inside main's handler, not at the interpreter's exit
        return
    where, target, st, folder = _target(path, inputs)

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
        raise InputError(where, f"cannot write in the folder {arg_text(folder)}: {exc.strerror}") from None
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


def _target(path: str, inputs=(), opt: str | None = None):
    """(name for messages, Path, its stat or None, its folder) of an output file that can
    be written; InputError where it cannot (one of ``inputs``, a folder, no such folder).
    ``opt``: the option that named it, for the message about an input."""
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
    if st is not None and stat.S_ISREG(st.st_mode) and os.path.islink(path):
        target = Path(os.path.realpath(path))  # written through the link, never replacing it
    folder = target.parent if str(target.parent) else Path(".")
    if st is None or stat.S_ISREG(st.st_mode):
        if not folder.is_dir():
            raise InputError(where, f"the folder {arg_text(folder)} does not exist")
    return where, target, st, folder
