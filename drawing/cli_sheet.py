"""``plans sheet``: drawing sheet 1 (plan of positions, velocity and acceleration
plans, kinematic diagrams, tables) as one SVG in real millimetres.

    plans sheet samples/press.toml --format A2 -o press.svg
    plans sheet --variant 3 --format A2 --lang en --plans 1,4 -o v3.svg --png v3.png
    plans sheet --variant all -o sheets/      # one sheet per variant

The views are placed automatically (:mod:`drawing.layout`), the plans at one
sheet millimetre per plan millimetre, so that a vector measured on the sheet is
the engine's segment length.
"""

from __future__ import annotations

import copy
import sys
from pathlib import Path
from typing import NamedTuple

from plans.cli import (
    EXIT_INPUT,
    EXIT_OK,
    add_source,
    mechanism_from,
    number,
    warn,
    write_output,
)
from plans.errors import InputError, PlansError, SingularPlanError

FIELDS = {
    "name": "name", "designation": "designation", "student": "developer",
    "developer": "developer", "group": "organisation", "organisation": "organisation",
    "organization": "organisation", "university": "organisation", "checker": "checker",
    "sheet": "sheet", "sheets": "sheets", "date": "date", "material": "material",
    "literal": "literal", "approver": "approver", "scale": "scale",
}  # fmt: skip


#: how many positions of the cycle a sheet may draw
POSITIONS = (3, 72)

def configure(p) -> None:
    add_source(p, allow_all=True)
    p.add_argument("-o", "--output", metavar="OUT.svg",
                   help="SVG file, '-' for stdout, or a folder with --variant all (default: stdout)")
    p.add_argument("--format", default="A1", choices=["A0", "A1", "A2", "A3", "A4"],
                   help="sheet format (default A1)")
    p.add_argument("--lang", default="ru", choices=["ru", "en"], help="language of the sheet (default ru)")
    p.add_argument("--positions", type=number(*POSITIONS, integer=True), default=12, metavar="N",
                   help="crank positions on the plan of positions (default 12)")
    p.add_argument("--plans", metavar="1,4",
                   help="position numbers (from an extreme position) to draw the plans for; "
                        "default: the position given in the file")
    p.add_argument("--title-block", nargs="*", default=[], metavar="KEY=VALUE",
                   help="title-block fields: " + ", ".join(sorted(FIELDS)))
    p.add_argument("--note", metavar="NOTE.md",
                   help="also write the explanatory note (Markdown) of the positions the sheet "
                        "draws plans for, at the sheet's scale factors and in its language "
                        "(with --variant all: a note beside each sheet)")
    p.add_argument("--png", metavar="FILE", help="also write a PNG (needs cairosvg)")
    p.add_argument("--pdf", metavar="FILE", help="also write a PDF (needs cairosvg)")
    p.add_argument("--dpi", type=number(10, 600), default=100.0,
                   help="PNG resolution, 10 to 600 (default 100)")


def _title_fields(mech, pairs, scale: str, lang: str = "ru") -> dict[str, str]:
    out = {"name": mech.name_in(lang), "scale": scale}
    items = list((mech.title or {}).items())
    for pair in pairs:
        if "=" not in pair:
            raise InputError("--title-block", f"{pair!r} is not KEY=VALUE")
        k, v = pair.split("=", 1)
        items.append((k.strip(), v))
    for k, v in items:
        key = FIELDS.get(k.lower())
        if key is None:
            raise InputError("--title-block", f"unknown field {k!r}; known: {', '.join(sorted(FIELDS))}")
        out[key] = str(v)
    return out


def _parse_plans(text: str | None, n: int) -> list[int] | None:
    if text is None:
        return None
    try:
        nums = [int(t) for t in text.split(",") if t.strip()]
    except ValueError:
        raise InputError("--plans", f"{text!r} is not a list of position numbers like 1,4") from None
    bad = [k for k in nums if not 0 <= k < n]
    if bad or not nums:
        raise InputError("--plans", f"position numbers run from 0 to {n - 1}, got {text!r}")
    return nums


def build_sheet(mech, fmt: str = "A1", lang: str = "ru", n_positions: int = 12,
                plans: list[int] | None = None, title: list[str] = ()):
    """(scene, sheet, info) for ``mech``; info holds the solutions drawn."""
    from drawing.layout import LayoutError
    from drawing.sheet import Sheet
    from plans.cycle import analyse_cycle
    from plans.kinematics import Solver
    from plans.plan import solve_position
    from plans.scales import choose_mu_l

    if not POSITIONS[0] <= n_positions <= POSITIONS[1]:  # called from Python, not argparse
        raise InputError("--positions", f"give {POSITIONS[0]} to {POSITIONS[1]} positions, "
                         f"got {n_positions}")
    sheet = Sheet(fmt)
    solver = Solver(mech)
    cycle = analyse_cycle(mech, n_positions, solver=solver)
    chosen = _parse_plans(None if plans is None else ",".join(map(str, plans)), len(cycle.positions))
    fixed = _views_of_any_size(mech, solver, cycle, lang)
    extent = fixed.shown.extent
    # the plans, for their μv and μa: sheet_scales reads nothing else. μl is given only so
    # that solve_position does not size a plan of positions of its own
    try:
        first = solve_position(mech, solver=solver,
                               mu={"mu_l": mech.scales.get("mu_l") or choose_mu_l(extent)})
    except SingularPlanError as exc:  # the given position is drawn whatever --plans asks
        raise SingularPlanError(f"{exc} (the sheet draws the given position: choose another "
                                "with --angle)", sine=exc.sine, source=exc.source) from None
    # the largest views that fit: scales the file leaves free are chosen for the sheet
    error, tried = None, []
    for size in SIZES:
        mu = sheet_scales(mech, first, extent, size)
        if mu in tried:  # the file fixes the scales this size would change: same sheet
            continue
        tried.append(mu)
        try:
            return _compose(mech, sheet, solver, cycle, chosen, mu, lang, title, fixed)
        except LayoutError as exc:
            error = exc
            if not exc.option:  # the file's own μl: no size of the sheet's changes it
                break
    raise error


class _AnySize(NamedTuple):
    """What the sheet draws whatever the scale factors, worked out once, not per size."""

    shown: object  # the positions the plan of positions draws (plans.positions.Drawn)
    diagrams: list  # the kinematic diagrams, or none …
    notes: list  # … and the note that says why


def _views_of_any_size(mech, solver, cycle, lang) -> _AnySize:
    from drawing import views as V
    from plans.positions import drawn

    shown = drawn(solver, cycle)
    diag = V.diagrams_view(mech, cycle, lang, solver=solver)
    if diag is not None:
        return _AnySize(shown, [diag], [])
    from plans.report import no_full_turn

    why = (no_full_turn(cycle, lang, mech.driver) if not cycle.full_turn else
           "no stroke of the output" if lang == "en" else "нет хода выходного звена")
    return _AnySize(shown, [], [V.WORDS[lang]["no_diagrams"] + why[0].lower() + why[1:]])


#: view sizes tried, as multiples of the engine's default drawing sizes (largest first)
SIZES = (3.0, 2.5, 2.0, 1.6, 1.25, 1.0, 0.8, 0.6, 0.5)


def sheet_scales(mech, sol, extent: float, size: float) -> dict[str, float]:
    """μl, μv, μa from the standard series for views ``size`` times the default size;
    the factors the mechanism file fixes are kept."""
    from plans.plan import plan_mu, plan_name
    from plans.scales import choose_mu_l

    mu = {}
    if "mu_l" not in mech.scales:
        mu["mu_l"] = choose_mu_l(extent, max_mm=150 * size)
    for key, plan in (("mu_v", sol.velocity), ("mu_a", sol.acceleration)):
        if key not in mech.scales:
            mu[key] = plan_mu(plan.points, plan.value(plan_name(mech.driver.tip)), size)
    return mu


def _compose(mech, sheet, solver, cycle, chosen, mu, lang, title, fixed):

    from drawing import views as V
    from drawing.layout import place_views
    from drawing.scene import Layer, Scene
    from drawing.sheet import TitleBlock, frame_scene
    from plans.fmt import angle, num
    from plans.plan import solve_position
    from plans.scales import gost_scale

    given = solve_position(mech, solver=solver, mu=mu)
    sols: list[tuple[str, str, object]] = []
    if chosen is None:
        deg = mech.driver.angle_deg
        sols.append(("g", f"φ_1 = {num(deg, 6, lang)}°", given))
    else:
        for k in chosen:
            deg = mech.driver.file_angle(cycle.positions[k])
            label = f"{V.WORDS[lang]['position']} {k}, φ_1 = {angle(deg, 4, lang)}°"
            sols.append((str(k), label, solve_position(mech, cycle.positions[k], solver=solver, mu=mu)))
    views = [V.positions_view(given, cycle, lang)]
    for tag, label, sol in sols:
        views.append(V.plan_view(sol, "velocity", tag, lang, label))
        views.append(V.plan_view(sol, "acceleration", tag, lang, label))
    views += fixed.diagrams
    tabsols = [(tag if tag != "g" else "φ", sol) for tag, _, sol in sols]  # columns by number
    views.append(V.segments_table_view(tabsols, lang))
    views.append(V.omega_table_view(tabsols, lang))
    if fixed.notes:
        views.append(V.note_view(fixed.notes))
    placed = place_views(sheet, views)
    tb = TitleBlock(**_title_fields(mech, title, gost_scale(given.mu_l, lang), lang))
    scene = frame_scene(sheet, tb, lang=lang)
    scene = scene + Scene((Layer("views", tuple(p.group() for p in placed)),))
    return scene, sheet, {"solutions": sols, "given": given, "cycle": cycle, "placed": placed}


def render(mech, args) -> tuple[str, str | None]:
    """(the sheet's SVG, its explanatory note or None when --note is not asked for)."""
    from drawing.svg import to_svg

    plans = None
    if args.plans is not None:
        plans = [int(t) for t in args.plans.split(",") if t.strip()] if all(
            t.strip().lstrip("-").isdigit() for t in args.plans.split(",") if t.strip()) else None
        if plans is None:
            raise InputError("--plans", f"{args.plans!r} is not a list of position numbers like 1,4")
    from drawing.layout import LayoutError

    try:
        scene, sheet, info = build_sheet(mech, args.format, args.lang, args.positions, plans,
                                         args.title_block)
    except LayoutError as exc:
        raise InputError(exc.option or mech.source, str(exc)) from None
    if (note := sparse_note(mech, sheet, info["placed"])) is not None:
        print(f"plans sheet: note: {mech.source}: {note}", file=sys.stderr)
    for _, _, sol in info["solutions"]:  # a plan drawn near a dead point is said so
        for w in sol.warnings:
            warn("sheet", w, mech.source)
    text = None
    if getattr(args, "note", None):
        from drawing.scene import parse_markup
        from plans.report import note

        sols = info["solutions"]
        # the plans' titles as plain text ("φ_1" is φ1); none for the given position
        # alone ("g"), whose plans are the note's own sections
        titles = [("".join(r.text for r in parse_markup(label)), sol) for _, label, sol in sols]
        # the structure and the plan of positions of the given position, drawn heavy
        text = note(info["given"], args.lang, info["cycle"], titles if sols[0][0] != "g" else ())
    return to_svg(scene, sheet, title=mech.name_in(args.lang)), text


#: below this share of the sheet's field, views drawn at scales the file fixes are noted
SPARSE = 0.3


def sparse_note(mech, sheet, placed) -> str | None:
    """Why a sheet is mostly empty, where the file's own scale factors made it so; None
    where the sheet chose its scales or the views fill it."""
    from drawing.layout import share_used

    fixed = [k for k in ("mu_l", "mu_v", "mu_a") if k in mech.scales]
    share = share_used(sheet, placed)
    if not fixed or share >= SPARSE:
        return None
    names = ", ".join("μ" + k[-1] for k in fixed)
    return (f"the views take {share:.0%} of the {sheet.name} sheet's field at the scale "
            f"factors the file fixes ({names}); leave them out of [scales] for the sheet to "
            "choose them, or take a smaller --format")


def _write(rendered: tuple[str, str | None], args) -> None:
    """The SVG, and the note, PNG and PDF asked for: all rendered before the first is
    written, so that a failed export leaves every existing output as it was."""
    svg, text = rendered
    files: list[tuple[str | None, str | bytes]] = [(args.output, svg)]
    if text is not None:
        files.append((args.note, text))
    if args.png or args.pdf:
        from drawing import export

        if args.png:
            files.append((args.png, export.png_bytes(svg, dpi=args.dpi)))
        if args.pdf:
            files.append((args.pdf, export.pdf_bytes(svg)))
    for path, data in files:
        write_output(path, data)


def run(args) -> int:
    if str(args.variant).strip().lower() == "all" and args.file is None:
        return _batch(args)
    mech = mechanism_from(args)
    if args.png or args.pdf:
        from drawing import export

        export.require()  # before anything is computed
    _write(render(mech, args), args)
    return EXIT_OK


def _batch(args) -> int:
    from plans.variants import read_table

    if not args.output or args.output == "-":
        raise InputError("-o", "with --variant all give a folder: -o DIR/")
    out = Path(args.output)
    if out.exists() and not out.is_dir():
        raise InputError("-o", f"{args.output} is not a folder")
    if not out.exists() and out.suffix and not args.output.endswith(("/", "\\")):
        raise InputError("-o", f"{args.output} looks like a file name: with --variant all give a "
                         "folder, e.g. -o sheets/")
    table = read_table(args.table)  # once, for every row
    numbers = table.numbers  # a table that cannot be used: no folder made
    for line in table.others(None):  # rows with no number: no sheet
        warn("sheet", line)
    out.mkdir(parents=True, exist_ok=True)
    tty = sys.stderr.isatty()
    failed: list[tuple[int, str]] = []
    for i, n in enumerate(numbers, 1):
        if tty:
            print(f"\rsheet {i}/{len(numbers)}: variant {n} ", end="", file=sys.stderr, flush=True)
        a = copy.copy(args)
        a.variant = str(n)
        a.output = str(out / f"variant-{n}.svg")
        a.png = str(out / f"variant-{n}.png") if args.png else None
        a.pdf = str(out / f"variant-{n}.pdf") if args.pdf else None
        a.note = str(out / f"variant-{n}.md") if args.note else None
        try:
            mech = mechanism_from(a, table)
            _write(render(mech, a), a)
        except (PlansError, ValueError, ArithmeticError) as exc:
            source = getattr(exc, "source", "")  # an input error names its source itself
            failed.append((n, str(exc) if isinstance(exc, InputError) or not source
                           else f"{source}: {exc}"))
    if tty:
        print(file=sys.stderr)
    for _, msg in failed:
        for line in msg.splitlines():
            print(f"plans sheet: {line}", file=sys.stderr)
    if failed:
        print(f"plans sheet: {len(failed)} of {len(numbers)} sheets failed", file=sys.stderr)
        return EXIT_INPUT
    return EXIT_OK


if __name__ == "__main__":  # pragma: no cover
    from plans.cli import main

    sys.exit(main(["sheet", *sys.argv[1:]]))
