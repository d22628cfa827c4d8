"""``plans sheet``: drawing sheet 1 (plan of positions, velocity and acceleration
plans, kinematic diagrams, tables) as one SVG in real millimetres.

    plans sheet samples/press.toml --format A2 -o press.svg
    plans sheet --variant 3 --format A2 --lang en --plans 1,4 -o v3.svg --png v3.png
    plans sheet --variant all -o sheets/      # one sheet per variant

The views are placed automatically (:mod:`drawing.sheet.layout`), the plans at one
sheet millimetre per plan millimetre, so that a vector measured on the sheet is
the engine's segment length.
"""

from __future__ import annotations

import copy
import sys
from pathlib import Path
from typing import NamedTuple

from plans.cli.common import (
    EXIT_INPUT,
    EXIT_OK,
    add_source,
    angle_field,
    mechanism_from,
    number,
    picture_names,
    warn,
    write_output,
)
from plans.errors import AssemblyError, InputError, PlansError, SingularPlanError

FIELDS = {
    "name": "name", "designation": "designation", "student": "developer",
    "developer": "developer", "group": "group", "organisation": "organisation",
    "organization": "organisation", "university": "organisation", "checker": "checker",
    "sheet": "sheet", "sheets": "sheets", "date": "date", "material": "material",
    "literal": "literal", "approver": "approver", "scale": "scale",
}  # fmt: skip
#: the smallest letters of a title-block entry, mm: GOST 2.304's 1.8 (2.5 is the rule,
#: 1.8 the size it allows where room is short). An entry that does not fit its cell in
#: them, condensed to 80 %, is refused, not shrunk further
TITLE_FLOOR = 1.8


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
                   help="position numbers (from an extreme position) to draw the plans for, "
                        "drawn heavy on the plan of positions; default: the position given "
                        "in the file")
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
    """The title block's fields: the file's [title], then --title-block over them. Two
    names of one field given different values in one place ("university" and
    "organisation") are refused: neither is dropped without a word."""
    out = {"name": mech.name_in(lang), "scale": scale}
    for where, items in ((mech.source, list((mech.title or {}).items())),
                         ("--title-block", _pairs(pairs))):
        given: dict[str, tuple[str, str]] = {}
        for k, v in items:
            key = FIELDS.get(k.lower())
            if key is None:
                raise InputError(where, f"unknown title-block field {k!r}; known: "
                                        f"{', '.join(sorted(FIELDS))}")
            if key in given and given[key][1] != str(v):
                raise InputError(where, f"{given[key][0]}={given[key][1]!r} and {k}={v!r} "
                                        f"both fill the title block's {key}: give one")
            given[key] = (k, str(v))
        out.update({key: v for key, (_, v) in given.items()})
    return out


def _pairs(pairs) -> list[tuple[str, str]]:
    out = []
    for pair in pairs:
        if "=" not in pair:
            raise InputError("--title-block", f"{pair!r} is not KEY=VALUE")
        k, v = pair.split("=", 1)
        out.append((k.strip(), v))
    return out


def _title_block(mech, sheet, title, scale: str, lang: str):
    """The title block, each entry in letters of at least TITLE_FLOOR mm."""
    from drawing.sheet.frame import FIELD_NO, TitleBlock, title_block_entries

    fields = _title_fields(mech, title, scale, lang)
    tb = TitleBlock(**fields)
    named = {FIELDS.get(k.lower()): (k, "--title-block") for k, _ in _pairs(title)}
    for k in (mech.title or {}):
        named.setdefault(FIELDS.get(k.lower()), (k, mech.source))
    for text, cell, entries in title_block_entries(sheet, tb, lang):
        if text.size < TITLE_FLOOR - 1e-9 and (given := [e for e in entries if fields.get(e)]):
            where = named.get(given[-1], (given[-1], mech.source))[1]
            what = " and ".join(f"{named.get(e, (e,))[0]}={fields[e]!r}" for e in given)
            raise InputError(where, f"{what} {'does' if len(given) == 1 else 'do'} not fit "
                                    f"{'its' if len(given) == 1 else 'their'} {cell.w:.0f} × "
                                    f"{cell.h:.0f} mm cell of the title block (field "
                                    f"{FIELD_NO[given[0]]}) even in {TITLE_FLOOR} mm "
                                    "letters condensed to 80 %: shorten it")
    return tb


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
    if twice := sorted({k for k in nums if nums.count(k) > 1}):
        raise InputError("--plans", f"position {', '.join(map(str, twice))} given twice in "
                         f"{text!r}: each position's plans are drawn once")
    return nums


def build_sheet(mech, fmt: str = "A1", lang: str = "ru", n_positions: int = 12,
                plans: list[int] | None = None, title: list[str] = ()):
    """(scene, sheet, info) for ``mech``; info holds the solutions drawn."""
    from drawing.sheet.frame import Sheet
    from plans.cycle.analysis import analyse_cycle
    from plans.kinematics.solver import Solver
    from plans.plan.solution import solve_position
    from plans.scales import choose_mu_l

    if not POSITIONS[0] <= n_positions <= POSITIONS[1]:  # called from Python, not argparse
        raise InputError("--positions", f"give {POSITIONS[0]} to {POSITIONS[1]} positions, "
                         f"got {n_positions}")
    sheet = Sheet(fmt)
    _title_block(mech, sheet, title, "", lang)  # refused before the views are fitted
    solver = Solver(mech)
    cycle = analyse_cycle(mech, n_positions, solver=solver)
    chosen = _parse_plans(None if plans is None else ",".join(map(str, plans)), len(cycle.positions))
    fixed = _views_of_any_size(mech, solver, cycle, lang)
    # the plans drawn, for their μv and μa. μl is given only so that solve_position does
    # not size a plan of positions of its own
    mu0 = {"mu_l": mech.scales.get("mu_l") or choose_mu_l(fixed.shown.extent)}
    try:
        given = solve_position(mech, solver=solver, mu=mu0, cycle=cycle)
    except SingularPlanError as exc:  # its structure, μl and title block's scale are read off it
        why = ("the sheet draws the given position" if chosen is None else
               "the sheet solves the given position for its scale even with --plans")
        raise SingularPlanError(f"{exc} ({why}: choose another with --angle)",
                                sine=exc.sine, source=exc.source) from None
    sheet_ = _Sheet1(mech, sheet, solver, cycle, chosen, lang, fixed, given, mu0)
    mu, placed = sheet_.fill()  # every μ: the file's and those chosen
    return _compose(mech, sheet, cycle, mu, lang, title, placed, sheet_.titled(mu))


class _AnySize(NamedTuple):
    """What the sheet draws whatever the scale factors, worked out once, not per size."""

    shown: object  # the positions the plan of positions draws (plans.cycle.positions.Drawn)
    curves: object  # the kinematic diagrams' curves (views.diagram_curves), or None …
    notes: list  # … and the note that says why


def _views_of_any_size(mech, solver, cycle, lang) -> _AnySize:
    from drawing.views import views as V
    from plans.cycle.positions import drawn

    shown = drawn(solver, cycle)
    curves = V.diagram_curves(mech, cycle, solver)
    if curves is not None:
        return _AnySize(shown, curves, [])
    from plans.note.report import no_full_turn

    why = (no_full_turn(cycle, lang, mech.driver) if not cycle.full_turn else
           "no stroke of the output" if lang == "en" else "нет хода выходного звена")
    return _AnySize(shown, None, [V.WORDS[lang]["no_diagrams"] + why[0].lower() + why[1:]])


#: mm: the kinematic diagrams' widths tried (one turn of the crank), with the height of
#: each of the three; 180 mm is 15 mm per position of twelve, 360 mm 1° per mm, 120 mm
#: what an A3 sheet beside the plans has room for
DIAGRAMS = {360.0: 60.0, 240.0: 50.0, 180.0: 40.0, 120.0: 28.0}


class _Sheet1:
    """The views of one sheet and the scale factors they are drawn at
    (:class:`drawing.sheet.fit.Fit` chooses those the file leaves free)."""

    def __init__(self, mech, sheet, solver, cycle, chosen, lang, fixed, given, mu0):
        self.mech, self.sheet, self.solver, self.cycle = mech, sheet, solver, cycle
        self.chosen, self.lang, self.fixed, self.given = chosen, lang, fixed, given
        self.mu0 = mu0
        self._sols: dict[tuple, list] = {}
        if chosen is None:  # the given position at mu0, solved already
            self._sols[tuple(sorted(mu0.items()))] = [given]

    def solutions(self, mu: dict[str, float]) -> list:
        """The solutions the sheet draws plans for, at ``mu``."""
        from plans.plan.solution import solve_position

        key = tuple(sorted(mu.items()))
        got = self._sols.get(key)
        if got is None:
            if self.chosen is None:
                got = [solve_position(self.mech, solver=self.solver, mu=mu, cycle=self.cycle)]
            else:
                got = [solve_position(self.mech, self.cycle.positions[k], solver=self.solver, mu=mu,
                                      cycle=self.cycle)
                       for k in self.chosen]
            self._sols[key] = got
        return got

    def titled(self, mu: dict[str, float]) -> list[tuple[str, str, object]]:
        """(tag, caption label, solution) of each position the sheet draws plans for."""
        from drawing.views import views as V
        from plans.cycle.analysis import shown_from
        from plans.fmt import angle

        sols = self.solutions(mu)
        lo = shown_from(self.cycle, self.mech.driver)  # as the range is written, if through 0°
        if self.chosen is None:
            return [("g", f"φ_{self.mech.driver.link} = "
                          f"{angle(self.mech.driver.angle_deg, 6, self.lang, lo)}°", sols[0])]
        out = []
        for k, sol in zip(self.chosen, sols, strict=True):
            deg = self.mech.driver.file_angle(self.cycle.positions[k])
            out.append((str(k), f"{V.WORDS[self.lang]['position']} {k}, φ_{self.mech.driver.link} = "
                                f"{angle(deg, 4, self.lang, lo)}°", sol))
        return out

    def factors(self) -> list[tuple[str, list[float], list[float]]]:
        """The free scale factors, their candidates (largest views first) and the size
        of the views at each, as a multiple of the engine's default size (a plan of
        positions 150 mm across, a plan's crank vector 80 mm or its longest 150 mm)."""
        from drawing.sheet.fit import SIZES, readable
        from plans.plan.solution import plan_name
        from plans.scales import (
            CRANK_MM,
            GOST_MU_L,
            PLAN_MM,
            choose_mu,
            choose_mu_l,
            series,
        )

        out = []
        extent = self.fixed.shown.extent
        if "mu_l" not in self.mech.scales:
            from drawing.sheet.layout import field

            (x0, y0, x1, y1), _ = field(self.sheet)  # up to the field's longer side
            hi = choose_mu_l(extent, max_mm=max(x1 - x0, y1 - y0, PLAN_MM * SIZES[0]))
            values = [m for m in GOST_MU_L if hi <= m and readable(extent / m / PLAN_MM)]
            values = values or [hi]
            out.append(("mu_l", values, [extent / m / PLAN_MM for m in values]))
        sols = self.solutions(self.mu0)
        for key, kind in (("mu_v", "velocity"), ("mu_a", "acceleration")):
            if key in self.mech.scales:
                continue
            plans = [getattr(sol, kind) for sol in sols]  # every position drawn, not one
            tip = max(abs(p.value(plan_name(self.mech.driver.tip))) for p in plans)
            largest = max(abs(q.value) for p in plans for q in p.points.values())
            hi, lo = (choose_mu(tip, largest, crank_mm=CRANK_MM * k, max_mm=PLAN_MM * k)
                      for k in SIZES)
            sized = [(m, max(tip / m / CRANK_MM, largest / m / PLAN_MM))
                     for m in sorted(set(series(hi, lo)) | {hi, lo})]
            sized = [(m, k) for m, k in sized if readable(k)] or sized[:1]
            out.append((key, [m for m, _ in sized], [k for _, k in sized]))
        if self.fixed.curves is not None:
            widths = sorted(DIAGRAMS, reverse=True)
            out.append(("diagrams", widths, [w / 180 for w in widths]))
        out.append(("segments", [1, 2], [1.0, 1.0]))  # one table, or its rows in two halves
        return out

    def draw(self, key: str, value: float, mu: dict[str, float] | None = None,
             sizing: bool = False) -> list:
        """The views the factor ``key`` sizes, drawn at ``value`` (``sizing``: without
        their letters, as large as those could make them)."""
        from drawing.views import views as V

        if key == "diagrams":
            return [V.diagrams_view(self.mech, self.cycle, self.lang, value, DIAGRAMS[value],
                                    curves=self.fixed.curves)]
        if key == "segments":
            return [V.segments_table_view(self._tabsols(mu or self.mu0), self.lang, value,
                                          sizing=sizing)]
        mu = dict(mu or self.mu0, **{key: value})
        if key == "mu_l":
            from plans.plan.solution import solve_position

            # the positions of the plans heavy (--plans), else the given one
            return [V.positions_view(solve_position(self.mech, solver=self.solver, mu=mu,
                                                    cycle=self.cycle),
                                     self.cycle, self.lang, sizing=sizing, heavy=self.chosen)]
        kind = "velocity" if key == "mu_v" else "acceleration"
        return [V.plan_view(sol, kind, tag, self.lang, label, sizing=sizing)
                for tag, label, sol in self.titled(mu)]

    def others(self, mu: dict[str, float]) -> list:
        """The views no free factor sizes: those of the factors the file fixes (at its
        values), the diagrams, the tables (at ``mu``) and the note."""
        from drawing.sheet.fit import SCALED
        from drawing.views import views as V

        out = []
        for key in SCALED:
            if key in self.mech.scales:
                out += self.draw(key, self.mech.scales[key], mu)
        out.append(V.omega_table_view(self._tabsols(mu), self.lang))
        if self.fixed.notes:
            from drawing.sheet.layout import field

            (x0, _, x1, _), _ = field(self.sheet)  # wrapped to the field, 180 mm at most
            out.append(V.note_view(self.fixed.notes, width=min(180.0, x1 - x0)))
        return out

    def _tabsols(self, mu: dict[str, float]) -> list[tuple[str, object]]:
        """The tables' columns: each position by its number ("φ" for the given one)."""
        return [(tag if tag != "g" else "φ", sol) for tag, _, sol in self.titled(mu)]

    def order(self) -> list[str]:
        tags = ["g"] if self.chosen is None else [str(k) for k in self.chosen]
        return (["positions"] + [f"{kind}-{t}" for t in tags for kind in ("velocity", "acceleration")]
                + ["diagrams", "segments", "angular", "note"])

    def together(self) -> list[tuple[str, str]]:
        """The views kept together, in reading order, where they fit so: each position's
        velocity plan with its acceleration plan, when the sheet draws several (the
        student compares a position's two plans, the teacher reads them position by
        position). One position's plans are placed as they always were."""
        if self.chosen is None or len(self.chosen) < 2:
            return []
        return [(f"velocity-{k}", f"acceleration-{k}") for k in self.chosen]

    def fill(self, suggest: bool = True):
        """(μ of every factor, the views placed). Where even the smallest views do not
        fit, :class:`LayoutError` says what they need, and (``suggest``) which larger
        format holds them."""
        from drawing.sheet.fit import SCALED, Fit
        from drawing.sheet.layout import LayoutError, place_views, spread

        factors = self.factors()
        mu_free = {k: v[-1] for k, v, _ in factors if k in SCALED}
        # the views no free factor sizes are the same at any of their values: drawn once
        fit = Fit(self.sheet, factors, self.draw, self.others(dict(self.mu0, **mu_free)),
                  self.order(), plain={"segments"})
        try:
            chosen = fit.best()
        except LayoutError as exc:
            if exc.option != "--format" or not suggest:
                raise
            raise LayoutError(self._no_room(fit), "--format") from None
        full = dict(self.mu0, **{k: v for k, v in self.mech.scales.items() if k in SCALED},
                    **{k: v for k, v in chosen.items() if k in SCALED})
        views = [v for k, value in chosen.items()
                 for v in (self.draw(k, value, full) if k == "segments" else fit.views(k, value))]
        # the scale factors chosen, each position's two plans are kept together where
        # the views fit so (they are not packed so while choosing: never a scale lost)
        together = self.together()
        placed = one_title_size(self.sheet, place_views(
            self.sheet, fit.arranged(views + list(fit.fixed)), together), together)
        if not any(k in self.mech.scales for k in SCALED):
            # at their largest and still leaving room: spread over the field. Views at
            # the scales a file fixes stay together, the share they take said in a note
            placed = spread(self.sheet, placed)
        return full, placed


    def _no_room(self, fit) -> str:
        """Why sheet 1 does not fit this format: what its views need at their smallest,
        and the smallest format that holds them."""
        from drawing.sheet.fit import SIZES
        from drawing.sheet.frame import FORMATS, Sheet
        from drawing.sheet.layout import LayoutError, describe, room
        from plans.scales import CRANK_MM, PLAN_MM

        smallest = {k: v[0] if k in fit.plain else v[-1] for k, v, _ in fit.factors}
        views = fit.arranged([v for k, value in smallest.items() for v in fit.views(k, value)]
                             + list(fit.fixed))
        need = ", ".join(f"{describe(v)} {v.w:.0f} × {v.h:.0f} mm" for v in views)
        names = list(FORMATS)
        holds = None
        for name in reversed(names[:names.index(self.sheet.name)]):  # the next larger first
            other = _Sheet1(self.mech, Sheet(name), self.solver, self.cycle, self.chosen,
                            self.lang, self.fixed, self.given, self.mu0)
            try:
                other.fill(suggest=False)
            except LayoutError:  # that format does not hold it either
                continue
            holds = name
            break
        fewer = (" or draw fewer positions' plans (--plans)"
                 if self.chosen is not None and len(self.chosen) > 1 else "")
        where = (f"{holds} holds it: use --format {holds}{fewer}" if holds
                 else f"no format holds it{fewer}")
        least = (f"half their default size: the longest vector of a plan {PLAN_MM * SIZES[1]:.0f} "
                 f"mm or its crank vector {CRANK_MM * SIZES[1]:.0f} mm, the plan of positions "
                 f"{PLAN_MM * SIZES[1]:.0f} mm across")
        return (f"sheet 1 does not fit on {room(self.sheet)}: at their smallest readable scales "
                f"({least}) its views need {need}; {where}")


def one_title_size(sheet, placed: list, together=()) -> list:
    """The views ``placed`` with their titles in one size. A view's title much wider than
    its drawing is set smaller (:data:`drawing.views.SMALL_CAPTION`), so that a narrow
    plan's view is not as wide as its title; the other views' titles were then larger
    on the same sheet. Where they all pack with every title at full size, the long ones
    on two lines, they are so; else every title is set at the smaller size, each view in
    its place (its box only shrinks). The scale factors are those chosen either way: a
    title never costs a plan a step of its scale. Nor does it part the views kept
    ``together`` (:func:`drawing.sheet.layout.place_views`): where those are placed together
    and the full-size titles do not pack so, the titles are set smaller."""
    from drawing.scene import Rect
    from drawing.sheet.layout import Placed, kept_together, pack, pairs_of
    from drawing.views.views import retitled

    if len({p.view.caption_size for p in placed if p.view.caption_size}) <= 1:
        return placed
    views = [retitled(p.view, "wrap") for p in placed]
    spots = pack(sheet, [(v.w, v.h) for v in views], pairs_of([v.name for v in views], together),
                 apart=not kept_together(placed, together))
    if spots is None:
        views = [retitled(p.view, "small") for p in placed]
        spots = [(p.rect.x, p.rect.y) for p in placed]
    return [Placed(v, Rect(x, y, v.w, v.h)) for v, (x, y) in zip(views, spots, strict=True)]


def _compose(mech, sheet, cycle, mu, lang, title, placed, sols):
    from drawing.scene import Layer, Scene
    from drawing.sheet.frame import frame_scene
    from plans.plan.solution import solve_position
    from plans.scales import gost_scale

    given = solve_position(mech, solver=sols[0][2].solver, mu=mu, cycle=cycle)
    tb = _title_block(mech, sheet, title, gost_scale(given.mu_l, lang), lang)
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
    from drawing.sheet.layout import LayoutError

    try:
        scene, sheet, info = build_sheet(mech, args.format, args.lang, args.positions, plans,
                                         args.title_block)
    except LayoutError as exc:  # named by its file (or its table's variant), not an option
        raise InputError(mech.source, str(exc)) from None
    except AssemblyError as exc:  # an angle where it does not assemble: which, and where it does
        from plans.cycle.analysis import outside_range

        raise outside_range(mech, exc, *angle_field(args, mech)) from None
    if (note := sparse_note(mech, sheet, info["placed"])) is not None:
        print(f"plans sheet: note: {mech.source}: {note}", file=sys.stderr)
    for _, _, sol in info["solutions"]:  # a plan drawn near a dead point is said so
        for w in sol.warnings:
            warn("sheet", w, mech.source)
    text = None
    if getattr(args, "note", None):
        from drawing.scene import parse_markup
        from plans.note.report import note

        sols = info["solutions"]
        # the plans' titles as plain text ("φ_1" is φ1); none for the given position
        # alone ("g"), whose plans are the note's own sections
        titles = [("".join(r.text for r in parse_markup(label)), sol) for _, label, sol in sols]
        # the structure and μl from the given position; with --plans the plan of
        # positions draws theirs heavy, and the note says so and gives their segments
        text = note(info["given"], args.lang, info["cycle"], titles if sols[0][0] != "g" else ())
    return to_svg(scene, sheet, title=mech.name_in(args.lang)), text


#: below this share of the sheet's field, views drawn at scales the file fixes are noted
SPARSE = 0.3


def sparse_note(mech, sheet, placed) -> str | None:
    """Why a sheet is mostly empty, where the file's own scale factors made it so; None
    where the sheet chose its scales or the views fill it."""
    from drawing.sheet.layout import share_used

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


#: the option (and its attribute) that writes each picture format
PICTURES = {".svg": ("-o", "output"), ".png": ("--png", "png"), ".pdf": ("--pdf", "pdf")}


def run(args) -> int:
    if str(args.variant).strip().lower() == "all" and args.file is None:
        return _batch(args)
    picture_names(args, PICTURES)  # x.png given to -o would hold SVG text
    mech = mechanism_from(args)
    if args.png or args.pdf:
        from drawing import export

        export.require()  # before anything is computed
    _write(render(mech, args), args)
    return EXIT_OK


def _batch(args) -> int:
    from plans.model.variants import read_table

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
            msg = str(exc) if isinstance(exc, InputError) or not source else f"{source}: {exc}"
            if f"variant {n}:" not in msg.split("\n")[0]:  # named by an option (--plans)
                msg = "\n".join(f"variant {n}: {line}" for line in msg.split("\n"))
            failed.append((n, msg))
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
    from plans.cli.common import main

    sys.exit(main(["sheet", *sys.argv[1:]]))
