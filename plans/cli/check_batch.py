"""``plans check A.toml B.toml …``: a class's measurement files, one summary table.

One row per file: the file (and its title, e.g. the student's name), the mechanism and
crank angle, the verdict and the diagnosis in a few words. A file that cannot be checked
does not stop the others: its row says its first problem, and stderr says every problem
as ``plans check FILE`` would.

Exit status: the worst of the files': 3 an internal error in one, else 2 bad input in
one, else 1 something beyond tolerance in one, else 0.

``--svg DIR`` and ``--png DIR`` draw each checked file's picture into the folder DIR, as
DIR/STEM.svg (STEM: the measurement file's name without .toml): each written atomically,
after all of that file's pictures are rendered; a file that cannot be checked writes none
and leaves an old one alone. ``-o FILE`` writes the table (or the JSON list) to FILE.
"""

from __future__ import annotations

import copy
import sys
from dataclasses import dataclass, field
from pathlib import Path

from drawing import export
from drawing.overlay import overlay_svg
from plans.check import verdict as ck
from plans.check.describe import plan_unit
from plans.check.measured import Solvers, from_dict
from plans.cli.check_report import PNG_SCALE, all_items, command_tolerance, json_text
from plans.cli.check_report import to_json as file_json
from plans.cli.common import (
    EXIT_DEVIATIONS,
    EXIT_INPUT,
    EXIT_INTERNAL,
    EXIT_OK,
    arg_text,
    error_lines,
    make_folder,
    same_file,
    say,
    terminal,
    warn,
)
from plans.cli.words import WORDS
from plans.errors import InputError, PlansError
from plans.fmt import angle, columns, cut, cut_start, listing, notation_in
from plans.model.fileformat import read_toml
from plans.model.variants import BUILTIN, BUILTIN_RU

#: a title wider than this (columns of a terminal) is cut in the table (the file's title
#: may hold 300 characters)
TITLE_WIDTH = 40

@dataclass
class Row:
    """One measurement file of the batch: its check, or the lines that say why there is
    none (as ``plans check FILE`` prints them after "plans check: ")."""

    path: str
    result: object = None  # plans.check.CheckResult
    error: list[str] = field(default_factory=list)
    status: int = EXIT_OK
    title: str = ""  # of a file not checked, if it can be read: whose file it is

    def title_text(self) -> str:
        return self.result.measurement.title if self.result is not None else self.title


def _read(path: str):
    """(the file's TOML as a dict, its text, the problem of reading it): read once for
    everything the batch does with it (its names, its check, its title)."""
    try:
        data, text = read_toml(path, "a measurement file is a few KB")
    except PlansError as exc:
        return {}, None, exc
    return (data if isinstance(data, dict) else {}), text, None


def _named(data: dict, path: str) -> list[Path]:
    """The files a measurement file names (its mechanism file, its table of variants),
    relative to its folder as :func:`plans.check.measured.load` reads them: inputs of the
    run even where the file cannot be checked, so that ``-o`` never goes over one."""
    names = [Path(v) for v in (data.get("mechanism"), data.get("table"))
             if isinstance(v, str) and v]
    return [p if p.is_absolute() else Path(path).parent / p for p in names]


def status(rows: list[Row]) -> int:
    """The batch's exit status: the worst of its files' (3, then 2, then 1, then 0)."""
    order = (EXIT_INTERNAL, EXIT_INPUT, EXIT_DEVIATIONS)
    return next((code for code in order if any(r.status == code for r in rows)), EXIT_OK)


def run(args, files: list[str]) -> int:
    report = copy.copy(args)  # the report's own output, checked as one run checks it
    report.svg = report.png = None
    # every file the run reads, refused as -o before anything is checked or drawn (a
    # file that cannot be checked has its mechanism file named all the same); each file
    # is read here once, and what it holds checked from what was read
    read = {path: _read(path) for path in files}
    report.run_files.claim(report, [*files, *(p for f in files for p in _named(read[f][0], f))])
    folders = _picture_folders(args, files)
    if args.png:
        export.require()  # before anything is computed

    tol = command_tolerance(args)
    _make_folders(args, folders)

    solvers = Solvers()  # a mechanism at one angle is solved once for all its files
    tty = sys.stderr.isatty()
    rows = []
    for i, path in enumerate(files, 1):
        if tty:
            print(f"\rcheck {i}/{len(files)}: {terminal(path, 60)} ", end="", file=sys.stderr,
                  flush=True)
        rows.append(_one(args, report, path, tol, folders, solvers, read.pop(path)))
    if tty:
        print("\r\033[K", end="", file=sys.stderr, flush=True)
    for r in rows:
        for line in r.error:
            say("check", line)
        for w in r.result.measurement.solution.warnings if r.result is not None else ():
            warn("check", w, r.path)  # near-singular: said as for one file, naming it
    if args.json:
        text = json_text(to_json(rows, args.lang))
    else:
        text = to_text(rows, args.lang, tol)
    args.run_files.write(args.output, text)
    return status(rows)


def _one(args, report, path: str, tol, folders: dict[str, Path], solvers=None, read=None) -> Row:
    """Check one file of the batch, and draw its pictures; a problem of its own (bad
    input, an unsolvable position, a picture that cannot be written) is its row's, not the
    batch's. A problem of the command line stops the batch."""
    data, text, problem = read if read is not None else _read(path)
    try:
        if problem is not None:
            raise problem
        meas = from_dict(data, str(Path(path)), Path(path).parent, text=text, solvers=solvers)
        report.run_files.claim(report, meas.inputs[1:])  # -o is never a mechanism file read
        result = ck.check(meas, tol)  # None: the file's own, or the default
        _draw(result, args, path, folders)
        return Row(path, result, status=EXIT_OK if result.ok else EXIT_DEVIATIONS)
    except PlansError as exc:
        if isinstance(exc, InputError) and exc.source == "command line":
            raise
        return Row(path, error=error_lines(exc), status=EXIT_INPUT, title=_title(data))
    except (KeyboardInterrupt, MemoryError):
        raise
    except Exception as exc:  # one file's internal error: said, and the others checked
        if args.debug:
            raise
        return Row(path, error=[f"{path}: internal error: {type(exc).__name__}: {exc} "
                                "(rerun with --debug for the traceback)"],
                   status=EXIT_INTERNAL, title=_title(data))


def _title(data: dict) -> str:
    """The title of a file that cannot be checked, where it reads as TOML at all: the
    teacher sees whose file it is."""
    title = data.get("title")
    return title if isinstance(title, str) else ""


def _picture_folders(args, files: list[str]) -> dict[str, Path]:
    """The folders --svg and --png name, by suffix; refused in one line, before anything
    is computed, where one is not a folder, or where two files would draw one picture."""
    out: dict[str, Path] = {}
    for suffix, opt, value in ((".svg", "--svg", args.svg), (".png", "--png", args.png)):
        if value is None:
            continue
        d = Path(value)
        hint = f"with several measurement files give a folder, e.g. {opt} pictures/"
        if value in ("", "-"):
            raise InputError("command line", f"{opt} {value!r}: {hint}")
        if d.exists() and not d.is_dir():
            raise InputError("command line", f"{opt} {value}: is not a folder: {hint}")
        if not d.exists() and d.suffix and not value.endswith(("/", "\\")):
            raise InputError("command line", f"{opt} {value}: looks like a file name: {hint}")
        out[suffix] = d
    if out:
        seen: dict[str, str] = {}
        for path in files:
            stem = Path(path).stem.casefold()
            if stem in seen and seen[stem] != path:
                name = Path(path).stem
                raise InputError("command line", f"{seen[stem]} and {path} would both be "
                                 f"drawn as {name}{'/'.join(out)}: check them in two runs")
            seen[stem] = path

        report = args.output
        for path in files if report not in (None, "-") else ():
            for suffix, d in out.items():
                picture = d / f"{Path(path).stem}{suffix}"
                if same_file(report, picture):  # the table would replace the picture
                    opt = "--svg" if suffix == ".svg" else "--png"
                    raise InputError("command line", f"-o and {opt} are both {arg_text(picture)}: "
                                     "give each output its own file")
    return out


def _make_folders(args, folders: dict[str, Path]) -> None:
    """Make the picture folders missing, once the run is not refused otherwise; one that
    cannot be made (under a file, on a read-only disk) is a problem of the command line,
    said in one line before anything is checked, not each file's internal error."""
    for suffix, folder in folders.items():
        if suffix == ".svg":
            make_folder(folder, "--svg", args.svg)
        else:
            make_folder(folder, "--png", args.png)


def _draw(result, args, path: str, folders: dict[str, Path]) -> None:
    """The file's pictures in their folders, all rendered before the first is written."""
    if not folders:
        return

    stem = Path(path).stem
    one = copy.copy(args)
    one.output = None  # stdout: checked already, as the report's
    one.svg = str(folders[".svg"] / f"{stem}.svg") if ".svg" in folders else None
    one.png = str(folders[".png"] / f"{stem}.png") if ".png" in folders else None
    one.run_files.check(one)  # not an input, not a folder
    svg = overlay_svg(result, lang=args.lang)
    files = []
    if one.svg:
        files.append((one.svg, svg))
    if one.png:
        files.append((one.png, export.png_bytes(svg, scale=PNG_SCALE)))
    for out, data in files:
        args.run_files.write(out, data)


# ---------------------------------------------------------------------------------------


def mechanism_cell(meas, lang: str) -> str:
    """"variant 3, φ1 = 30°" or "samples/press.toml, φ1 = 30°": where the mechanism
    comes from (a row of the built-in table by its number alone) and the crank angle, as
    the file gives it."""
    mech = meas.mechanism
    source = mech.source_in(lang)
    for prefix in (BUILTIN, BUILTIN_RU):
        if source.startswith(prefix + ", "):
            source = source[len(prefix) + 2:]
    sol = meas.solution
    deg = mech.driver.file_angle(sol.phi)
    return f"{source}, {mech.driver.phi_sym} = {angle(deg, 4, lang, sol.shown_from)}°"


def verdict_cell(row: Row, lang: str, tol=None) -> str:
    w = WORDS[lang]["batch"]
    if row.status == EXIT_INTERNAL:
        return w["internal"]
    if row.result is None:
        return w["bad"]
    res = row.result
    n = len(res.deviations)
    text = (w["all_ok"].format(all=all_items(n, lang)) if res.ok else
            w["some"].format(k=len(res.failed), n=n))
    if tol is not None and res.tolerance != tol:
        text += f" ({w['own_tol'].format(tol=res.tolerance.describe(lang))})"
    return text


def diagnosis_cell(row: Row, lang: str) -> str:
    """The diagnosis in a few words: the mistake named (and what it leaves unexplained),
    the slips, or "no single mistake"; for a file not checked, its first problem."""
    w = WORDS[lang]["batch"]
    if row.result is None:
        first = row.error[0] if row.error else ""
        if first.startswith(f"{row.path}: "):  # the file is in the first column
            first = first[len(row.path) + 2:]
        if row.status == EXIT_INTERNAL:  # and the verdict says "internal error"
            first = first.removeprefix("internal error: ")
        more = len(row.error) - 1
        return first + (f" {w['more'].format(k=more)}" if more else "")
    res = row.result
    if res.ok:
        return ""
    diag = res.diagnosis
    slips = _slips(res, lang)
    if res.slips_only:
        return f"{w['slips']} {slips}"
    if diag.best is None:
        return w["none"] + (f"; {w['slips']} {slips}" if slips else "")
    said = [f.mistake.describe(lang) for f in (diag.best, *diag.alternatives)]
    # a mistake said in two clauses ("ω3 written with the wrong sense; the plans are
    # right") takes the next one after a semicolon too, or "or" would join it to its
    # second clause: "the plans are right or ω1 (V_A) drawn with the wrong sense"
    text = f"; {w['or']} ".join(said) if any("; " in d for d in said) else f" {w['or']} ".join(said)
    if diag.best.unexplained:
        text += f"; {w['not']} {', '.join(diag.best.unexplained)}"
    return text


def _slips(res, lang: str) -> str:
    """The look-alikes in a few words each: "pc and pe swapped", "pd measured as ad"."""
    w = WORDS[lang]["batch"]
    out: list[str] = []
    said: set[frozenset[str]] = set()
    plan = {d.item.name: d.item.plan for d in res.deviations}
    for lk in res.diagnosis.lookalikes:
        if lk.kind == "swapped":
            pair = frozenset((lk.item, lk.other))
            if pair in said:
                continue
            said.add(pair)
        out.append(w[lk.kind].format(a=lk.item, b=lk.other, unit=plan_unit(plan.get(lk.item), lang)))
    return listing(out, lang)


def to_text(rows: list[Row], lang: str = "en", tol=None) -> str:
    """The summary table: one row per file, then the count of each verdict."""
    w = WORDS[lang]["batch"]
    out = [w["head"].format(n=w["files"](len(rows)))]
    checked = [r.result for r in rows if r.result is not None]
    common = tol
    if common is None and checked:  # the tolerance most files were checked at
        kinds = [r.tolerance for r in checked]
        common = max(kinds, key=kinds.count)
    if common is not None:
        out.append(f"{w['tol']}: {common.describe(lang)}")
    titled = any(r.title_text() for r in rows)
    table = []
    for r in rows:
        res = r.result
        cells = [cut_start(terminal(r.path), 80)]  # a long path keeps the file's name
        if titled:
            # cut to the columns it takes (a Chinese character two), not to its characters
            cells.append(cut(terminal(" ".join(r.title_text().split()), TITLE_WIDTH), TITLE_WIDTH))
        cells.append(mechanism_cell(res.measurement, lang) if res is not None else "")
        cells += [verdict_cell(r, lang, common), diagnosis_cell(r, lang)]
        table.append(cells)
    head = list(w["cols"]) if titled else [c for i, c in enumerate(w["cols"]) if i != 1]
    out += ["", *columns(table, head), ""]
    counts = [(w["n_ok"], sum(r.status == EXIT_OK for r in rows)),
              (w["n_some"], sum(r.status == EXIT_DEVIATIONS for r in rows)),
              (w["n_bad"], sum(r.status == EXIT_INPUT for r in rows)),
              (w["n_internal"], sum(r.status == EXIT_INTERNAL for r in rows))]
    parts = [text.format(k=k) for text, k in counts if k]
    out.append(w["total"].format(files=w["files"](len(rows)), parts=", ".join(parts)))
    return notation_in("\n".join(out) + "\n", lang)  # a^τ_A3B in Russian, as the words


def to_json(rows: list[Row], lang: str = "en") -> list[dict]:
    """A list, one object per file in the order given: the single file's JSON
    (:func:`plans.cli.check_report.to_json`, which names its file), or for a file that could not
    be checked its file, ``"ok": null`` and the lines of its error."""
    out = []
    for r in rows:
        if r.result is not None:
            out.append(file_json(r.result, lang))
        else:
            out.append({"file": r.path, "ok": None, "error": list(r.error),
                        "internal": r.status == EXIT_INTERNAL})
    return out
