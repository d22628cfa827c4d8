"""``plans bench``: run time per crank position and error against a high-precision reference.


For each bench scene and each number N of crank positions (12 … 10⁶) it measures the
methods of :mod:`plans.verify.bench` (``vectorized``, ``reused``, ``recorded``, ``plan``,
``fd h=…`` and the peer packages installed), each with its largest relative error
against ``plans.verify.reference``, and checks the rates against the targets.

The table goes to stdout (``--json``: a list of rows ``{"scene", "method", "positions",
"seconds_per_position", "max_rel_error"}``), the error-versus-time chart (log-log;
``drawing.chart.bench_chart``, PNG, SVG or PDF by the name's ending) to ``--chart FILE``
only when asked (it had written bench.svg into the current folder unasked).
The bench needs sympy and mpmath (the ``bench`` extra: without them it says so, exit 2);
the two samples are benched in a source checkout, where ``samples/`` is, and ``--help``
lists them only there.
"""

from __future__ import annotations

import importlib.util
import json
import math
import sys

from drawing import chart as charts
from plans.cli.common import EXIT_OK, number, say
from plans.cli.output import picture_format
from plans.errors import InputError
from plans.forces.bench import force_bench
from plans.synthesis.bench import family_bench
from plans.verify.bench import (
    BENCH_SCENES,
    FD_STEPS,
    METHODS,
    QUICK_FD_STEPS,
    QUICK_SIZES,
    SIZES,
    Bench,
    Row,
    load_scenes,
    machine,
)

#: the issue's rates (positions per second at N ≥ 10⁵): (label, scenes, goal). The
#: four-bar's goal is read on its joints, the work the peers' four-bar kernels do; the
#: four-bars with coupler points and mass centres are held to it too, and reported apart
TARGETS = (
    ("four-bar, joints only", ("fourbar_joints",), 5e6),
    ("four-bar with 3–4 more points", ("crank_rocker", "fourbar"), 5e6),
    ("press", ("press",), 2e6),
)
#: the force analysis's rate: the loaded press over the cycle (issue 21)
FORCE_TARGET = ("loaded press, forces", ("press",), 1e6)


#: what the bench imports to compute its reference, with the extra that installs it
NEEDS = ("sympy", "mpmath")
EXTRA_HINT = "the bench extra: in the source folder, pip install '.[bench]' (README, Setup)"


def configure(p) -> None:
    scenes = load_scenes()
    here = [n for n in BENCH_SCENES if n in scenes]
    absent = [n for n in BENCH_SCENES if n not in scenes]
    p.add_argument("--json", action="store_true", help="print the rows as JSON")
    p.add_argument(
        "--quick",
        action="store_true",
        help="sizes 12 and 100, one FD step, short timing: seconds, for tests",
    )
    p.add_argument(
        "--max-positions",
        type=number(1, 10_000_000, integer=True),
        default=SIZES[-1],
        metavar="N",
        help=f"largest N of crank positions (default {SIZES[-1]})",
    )
    p.add_argument(
        "--scene",
        action="append",
        metavar="NAME",
        help=f"only these scenes (repeatable; default: {', '.join(here)}, and the "
        "synthesis's crank-rocker family, which a --scene leaves out"
        + (f"; {', '.join(absent)}: samples of the source checkout, not installed)" if absent else ")"),
    )
    p.add_argument(
        "--methods",
        metavar="LIST",
        default=",".join(METHODS),
        help=f"comma-separated subset of {','.join(METHODS)} (reused and recorded "
        "are timed only with vectorized)",
    )
    p.add_argument(
        "--ref-angles",
        type=number(1, 100_000, integer=True),
        default=100,
        metavar="M",
        help="angles on which the reference is evaluated (default 100)",
    )
    p.add_argument(
        "--plan-max",
        type=number(1, 10_000_000, integer=True),
        default=1_000,
        metavar="N",
        help="largest N timed for the single-position plan (default 1000)",
    )
    p.add_argument(
        "--budget",
        type=number(0, 600),
        default=0.3,
        metavar="S",
        help="seconds spent repeating a short measurement, best run kept (default 0.3)",
    )
    p.add_argument(
        "--chart",
        metavar="FILE",
        help="also draw the error-versus-time chart, PNG, SVG or PDF by the name's ending "
        "(default: no chart)",
    )
    p.add_argument(
        "-o",
        "--output",
        metavar="FILE",
        help="write the table to FILE instead of stdout",
    )


def run(args) -> int:
    missing = [m for m in NEEDS if importlib.util.find_spec(m) is None]
    if missing:  # before anything is timed: a setup problem, not an internal error
        raise InputError("command line", f"the bench needs {' and '.join(missing)}, {EXTRA_HINT}")
    methods = {m.strip() for m in args.methods.split(",") if m.strip()}
    unknown = methods - set(METHODS)
    if unknown or not methods:
        raise InputError(
            "command line", f"--methods: unknown {', '.join(sorted(unknown))}" if unknown
            else f"--methods: give at least one of {','.join(METHODS)}"
        )
    args.run_files.check(args)  # a bad --chart is found now, not after minutes of timing
    chart_format = picture_format(args, "chart", "--chart") if args.chart else None
    scenes = load_scenes()
    names = args.scene or [n for n in BENCH_SCENES if n in scenes]
    skipped = [n for n in BENCH_SCENES if n not in scenes]
    unknown = [n for n in names if n not in scenes]
    if unknown:
        samples = [n for n in unknown if n in BENCH_SCENES]
        why = (f"; {', '.join(samples)}: samples of the source checkout (samples/), not installed: "
               "run the bench from the source folder" if samples else "")
        raise InputError(
            "command line",
            f"--scene: unknown {', '.join(unknown)} "
            f"(known: {', '.join(sorted(scenes))}){why}",
        )
    sizes = [
        n for n in (QUICK_SIZES if args.quick else SIZES) if n <= args.max_positions
    ]
    if not sizes:
        sizes = [args.max_positions]
    notes: list[str] = []
    log = (
        (lambda msg: print(msg, file=sys.stderr))
        if not args.json
        else (lambda msg: None)
    )
    bench = Bench(
        budget=0.02 if args.quick else args.budget,
        ref_angles=min(args.ref_angles, 12) if args.quick else args.ref_angles,
        plan_max=min(args.plan_max, 100) if args.quick else args.plan_max,
        fd_steps=QUICK_FD_STEPS if args.quick else FD_STEPS,
        methods=methods,
        notes=notes,
        log=log,
    )
    if skipped and not args.scene:
        notes.append(f"{', '.join(skipped)}: the samples are benched in a source checkout")
    rows: list[Row] = []
    for name in names if methods - {"synthesis"} else ():
        rows += bench.scene(name, scenes[name], sizes)
        mech = scenes[name].mechanism()
        if "forces" in methods and mech.loads is not None and scenes[name].full_turn:
            for n in sizes:
                if n >= 100:  # the loaded sweep over the cycle, and its error against one linear solve
                    log(f"bench {name}: forces, N = {n}")
                    got = force_bench(mech, name, n, repeats=1 if args.quick else 3,
                                      checks=4 if args.quick else 24)
                    rows.append(Row(name, "forces", n, got.seconds_per_position, float(got.max_rel_error)))
    if "synthesis" in methods and not args.scene:  # γmin over a crank-rocker family, one call
        n = 10_000 if args.quick else 1_000_000
        log(f"bench synthesis: γmin over {n} members of a crank-rocker family")
        got = family_bench(n, repeats=1 if args.quick else 3, checks=4 if args.quick else 24)
        rows.append(Row("crank-rocker family", "synthesis", n, got.seconds / n, got.max_rel_error))
    if args.json:
        text = json.dumps([r.as_json() for r in rows], indent=1) + "\n"
        for n in notes:
            say("bench", f"note: {n}")
    else:
        text = to_text(rows, notes)
    chart = None
    if chart_format is not None:  # built before the table is written: both or neither
        chart = charts.bench_chart(rows, machine(), chart_format)
    args.run_files.write(args.output, text)
    if chart is not None:
        args.run_files.write(args.chart, chart)
        if not args.json:
            print(f"plans bench: chart written to {args.chart}", file=sys.stderr)
    return EXIT_OK


def _err(x: float | None) -> str:
    if x is None:
        return "—"
    if not math.isfinite(x):
        return "inf" if x == math.inf else "—"
    return f"{x:.2e}"


def _time(sec: float) -> str:
    if sec >= 1e-3:
        return f"{sec * 1e3:.3g} ms"
    if sec >= 1e-6:
        return f"{sec * 1e6:.3g} µs"
    return f"{sec * 1e9:.3g} ns"


def to_text(rows: list[Row], notes: list[str]) -> str:
    out = [f"plans bench — {machine()}; one process, numpy on one core", ""]
    head = ("scene", "method", "N", "time/position", "positions/s", "max rel error")
    body = [
        (
            r.scene,
            r.method,
            str(r.positions),
            _time(r.seconds_per_position),
            f"{1 / r.seconds_per_position:.3g}" if r.seconds_per_position > 0 else "—",
            _err(r.max_rel_error),
        )
        for r in rows
    ]
    widths = [
        max(len(h), *(len(b[i]) for b in body)) if body else len(h)
        for i, h in enumerate(head)
    ]
    fmt = lambda cells: "  ".join(  # noqa: E731
        c.ljust(w) if i < 2 else c.rjust(w)
        for i, (c, w) in enumerate(zip(cells, widths, strict=True))
    )
    out.append(fmt(head))
    last = None
    for r, b in zip(rows, body, strict=True):
        if last is not None and r.scene != last:
            out.append("")
        last = r.scene
        out.append(fmt(b))
    out += ["", *targets(rows)]
    if notes:
        out.append("")
        out += [f"note: {n}" for n in notes]
    return "\n".join(out) + "\n"


def targets(rows: list[Row]) -> list[str]:
    """The issue's targets, checked against what was measured."""
    out = ["targets"]

    for label, scenes, goal in TARGETS:
        for method, how in (("vectorized", "new arrays"), ("reused", "reused arrays")):
            got = {}
            for r in rows:
                if r.method == method and r.scene in scenes and r.positions >= 100_000:
                    rate = 1 / r.seconds_per_position
                    got[r.positions] = max(got.get(r.positions, 0.0), rate)
            head = f"  {label} ≥ {goal:.0e} positions/s, N ≥ 1e5, {how}:"
            if not got:
                if method == "vectorized":
                    out.append(f"{head} not measured")
                continue
            figures = ", ".join(f"{v:.3g} at N = {n:.0e}" for n, v in sorted(got.items()))
            worst = min(got.values())
            verdict = ("met" if worst >= goal
                       else "met at some N only" if max(got.values()) >= goal else "NOT met")
            out.append(f"{head} {figures} — {verdict}")
    label, scenes, goal = FORCE_TARGET
    got = {r.positions: 1 / r.seconds_per_position for r in rows
           if r.method == "forces" and r.scene in scenes and r.positions >= 100_000
           and r.seconds_per_position > 0}
    if got:
        figures = ", ".join(f"{v:.3g} at N = {n:.0e}" for n, v in sorted(got.items()))
        verdict = "met" if min(got.values()) >= goal else "NOT met"
        out.append(f"  {label} ≥ {goal:.0e} positions/s, N ≥ 1e5: {figures} — {verdict}")
    for r in rows:
        if r.method == "synthesis":
            whole = _time(r.seconds_per_position * r.positions)
            out.append(f"  γmin over a crank-rocker family in one call: {r.positions:.0e} members in "
                       f"{whole} "
                       f"({1 / r.seconds_per_position:.3g} members/s), against the engine "
                       f"{_err(r.max_rel_error)}")
    plan = [
        r.seconds_per_position
        for r in rows
        if r.method == "plan" and r.scene == "press"
    ]
    if plan:
        best = min(plan)
        out.append(
            f"  plan of the press ≤ 100 µs: {_time(best)} — {'met' if best <= 1e-4 else 'NOT met'}"
        )
    errs = [
        r.max_rel_error
        for r in rows
        if r.method == "vectorized" and r.max_rel_error is not None
    ]
    if errs:
        worst = max(errs)
        out.append(
            f"  vectorized max rel error ≤ 1e-13 (well-conditioned scenes): {_err(worst)} — "
            f"{'met' if worst <= 1e-13 else 'NOT met'}"
        )
    return out
