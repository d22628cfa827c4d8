"""What the commands share: exit statuses, the options that name a mechanism, the position
they solve, and how they say warnings and errors.

The writers of outputs are in :mod:`plans.cli.output` (their names are importable from
here as well); the parser and the command registry in :mod:`plans.cli.main`.
"""

from __future__ import annotations

import argparse
import math
import re
import sys
from enum import IntEnum

from plans.cli.output import (
    RunFiles,
    arg_text,
    check_outputs,
    make_folder,
    picture_names,
    same_file,
    terminal,
    write_output,
)
from plans.cycle import analyse_cycle, outside_range
from plans.errors import AssemblyError, InputError, PlansError
from plans.fmt import from_x
from plans.kinematics.solver import Solver
from plans.model import load, variants
from plans.model.fileformat import MAX_ABS
from plans.plan.solution import solve_position

__all__ = [
    "EXIT_DEVIATIONS",
    "EXIT_INPUT",
    "EXIT_INTERNAL",
    "EXIT_OK",
    "ExitStatus",
    "RunFiles",
    "add_source",
    "angle_field",
    "arg_text",
    "check_outputs",
    "cycle_json",
    "error_lines",
    "make_folder",
    "mechanism_from",
    "number",
    "picture_names",
    "place_json",
    "same_file",
    "say",
    "solved_position",
    "terminal",
    "warn",
    "write_output",
]


class ExitStatus(IntEnum):
    """The exit status of ``plans``, as its ``--help`` states it."""

    OK = 0
    DEVIATIONS = 1  # a check found an item beyond tolerance
    INPUT = 2  # bad input, an output that cannot be written, an unsolvable scene
    INTERNAL = 3  # a bug: rerun with --debug for the traceback
    INTERRUPTED = 130  # Ctrl-C, as a shell reports SIGINT


EXIT_OK, EXIT_DEVIATIONS, EXIT_INPUT, EXIT_INTERNAL = (
    ExitStatus.OK, ExitStatus.DEVIATIONS, ExitStatus.INPUT, ExitStatus.INTERNAL)


def add_source(p: argparse.ArgumentParser, *, allow_all: bool = False) -> None:
    """FILE | --variant N [--table FILE]: where the mechanism comes from."""
    p.add_argument("file", nargs="?", help="mechanism file (TOML)")
    p.add_argument("--variant", metavar="N" if not allow_all else "N|all",
                   help="a row of the variant table instead of a file")
    p.add_argument("--table", metavar="FILE", help="a course's variant table (default: the built-in Table 2)")
    p.add_argument("--angle", type=number(-MAX_ABS, MAX_ABS), metavar="DEG",
                   help="crank angle, in the convention of the file (default: the file's)")


def number(lo: float, hi: float, integer: bool = False):
    """An argparse type: a finite number from ``lo`` to ``hi`` (an integer if asked), else
    one line saying so.

    >>> number(1, 10, integer=True)("7")
    7
    """

    def parse(text: str):
        try:
            value = int(text) if integer else float(text)
        except ValueError:
            value = None
        if value is None or not math.isfinite(value) or not lo <= value <= hi:
            kind = "a whole number" if integer else "a number"
            span = f"{int(lo)} to {int(hi)}" if integer else f"{lo:g} to {hi:g}"
            raise argparse.ArgumentTypeError(f"{arg_text(text, 30)} is not {kind} from {span}")
        return value

    return parse


def mechanism_from(args, table=None):
    """The mechanism named by FILE or --variant, with --angle applied; ``table``: the
    variant table of ``--table`` already read (``sheet --variant all`` reads it once for
    all its rows, and says each row's problems with that row's sheet).

    Claims the files it reads on the run's :class:`~plans.cli.output.RunFiles`
    (``args.run_files``): an output (``-o``) that is one of them is refused before
    anything is computed, and never written.
    """
    if (args.file is None) == (args.variant is None):
        raise InputError("command line", "give a mechanism FILE or --variant N (one of them)")
    path = getattr(args, "table", None)
    if path is not None and args.variant is None:
        raise InputError("command line", "--table goes with --variant N: a mechanism FILE "
                                         "is read as it is")
    if path == "":
        raise InputError("command line", "--table was given an empty file name")
    args.run_files.claim(args, [p for p in (args.file, path) if p])
    angle = getattr(args, "angle", None)  # a finite number within ±MAX_ABS: argparse checked
    if args.variant is not None:
        text = str(args.variant).strip()
        if not re.fullmatch(r"[+-]?\d{1,9}", text):
            raise InputError("command line", f"--variant: {arg_text(args.variant, 30)} is not a "
                                             "variant number (0, 1, 2…)")
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
    the cycle first, which sizes the plan of positions and words the solution's angles
    (the solver is the solution's); where it does not assemble there, the error names the
    field the angle came from (:func:`angle_field`) and the crank's range where it does
    (:func:`plans.cycle.outside_range`)."""
    try:
        solver = Solver(mech)
        cycle = analyse_cycle(mech, solver=solver)
        return cycle, solve_position(mech, solver=solver, cycle=cycle)
    except AssemblyError as exc:
        raise outside_range(mech, exc, *angle_field(args, mech)) from None


def cycle_json(c) -> dict:
    """The cycle's figures (:class:`plans.cycle.Cycle`) as ``plans cycle --json`` and
    ``plans solve --json`` give them, in SI units and degrees from +x."""
    if c.kind != "turn":  # over a slider's travel (m) or an interval in time (s)
        unit = "s" if c.kind == "time" else "m"
        return {
            "runs_over": c.kind, "unit": unit, "span": list(c.span), "periodic": c.periodic,
            "full_turn": False,
            "output": None if c.output is None else
            {"point": c.output.point, "kind": c.output.kind, "link": c.output.link,
             "unit": "m" if c.output.kind == "linear" else "rad"},
            "extremes": [float(x) for x in c.extremes], "stroke": c.stroke,
            "theta_deg": None if c.theta is None else math.degrees(c.theta), "K": c.K,
            "notes": list(c.notes)}
    return {
        "full_turn": c.full_turn,
        "output": None
        if c.output is None
        else {"point": c.output.point, "kind": c.output.kind, "link": c.output.link,
              "unit": "m" if c.output.kind == "linear" else "rad"},
        "extremes_phi_deg": [from_x(x) for x in c.extremes],
        "stroke": c.stroke,
        "theta_deg": None if c.theta is None else math.degrees(c.theta),
        "K": c.K,
        "grashof": c.grashof,
        # counter-clockwise from the first angle to the second: in the crank's order a
        # clockwise crank's range named the arc that does not assemble
        "crank_range_phi_deg": None if c.ccw_range is None else [from_x(x) for x in c.ccw_range],
        "notes": list(c.notes),
    }


def place_json(mech, x: float) -> dict:
    """A place of the mechanism's cycle (its solver's parameter ``x``) for the JSON: the
    crank angle from +x and in the file's convention; a slider input's travel s (m); an
    instant t (s) of a mechanism moved in time."""
    if mech.timing is not None:
        return {"t": float(x)}
    d = mech.driver
    if d.linear:
        return {"s": float(x)}
    return {"phi_deg": from_x(x), "angle_deg": d.file_angle(x)}


def error_lines(exc: PlansError) -> list[str]:
    """The lines that say ``exc``, as ``plans CMD: LINE`` prints each: an input error
    names its file itself; a position that cannot be solved (a group that does not close,
    a dead point) carries the mechanism it belongs to, which is put before each line. The
    file's name is written as :func:`terminal` writes it (a line break in it had forged a
    line of its own)."""
    source = str(getattr(exc, "source", "") or "")
    text = str(exc)
    if source and terminal(source) != source:
        text = text.replace(source, terminal(source))
    where = f"{terminal(source)}: " if source and not isinstance(exc, InputError) else ""
    return [f"{where}{line}" for line in text.splitlines() or [type(exc).__name__]]


def say(command: str, line: str) -> None:
    """One line on stderr, "plans CMD: line", through :func:`terminal`: no escape
    sequence, bidi control or line break of a user's text reaches the terminal, and no
    echoed argument runs on for pages."""
    print(f"plans {command}: {terminal(line)}", file=sys.stderr)


def warn(command: str, text: str, source: str = "") -> None:
    """One warning line on stderr: "plans CMD: warning: [SOURCE: ]text"."""
    say(command, f"warning: {source + ': ' if source else ''}{text}")
