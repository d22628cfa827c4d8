"""Sheet 1 of the course project: the plan of positions, the velocity and acceleration
plans, the kinematic diagrams and the tables of one mechanism, on one GOST sheet.

:func:`build_sheet` solves what the sheet draws, chooses the scale factors the file
leaves free so that the views fill the sheet (:class:`drawing.sheet.fit.Fit`), places the
views (:mod:`drawing.sheet.layout`) with the plans at one sheet millimetre per plan
millimetre (a vector measured on the sheet is the engine's segment length), and frames
them with the title block; :func:`render` writes it as SVG. ``plans sheet``
(:mod:`plans.cli.sheet`) is the command around it: options, files and batches.
"""

from __future__ import annotations

from typing import NamedTuple

from drawing.scene import Layer, Rect, Scene, parse_markup
from drawing.sheet.balance import balance
from drawing.sheet.fit import SCALED, SIZES, Fit, readable
from drawing.sheet.frame import FIELD_NO, FORMATS, Sheet, TitleBlock, frame_scene, title_block_entries
from drawing.sheet.layout import (
    LayoutError,
    Placed,
    describe,
    field,
    kept_together,
    pack,
    pack_kept,
    pairs_of,
    place_views,
    room,
    share_used,
)
from drawing.svg import to_svg
from drawing.views import (
    WORDS,
    diagram_curves,
    diagrams_view,
    note_view,
    omega_table_view,
    plan_view,
    positions_view,
    retitled,
    segments_table_view,
)
from plans.cycle import analyse_cycle, shown_from
from plans.cycle.positions import drawn
from plans.errors import InputError, SingularPlanError
from plans.fmt import angle
from plans.kinematics.solver import Solver
from plans.note.report import no_full_turn
from plans.plan.solution import plan_name, solve_position
from plans.scales import CRANK_MM, GOST_MU_L, PLAN_MM, choose_mu, choose_mu_l, gost_scale, series

__all__ = [
    "DIAGRAMS",
    "FIELDS",
    "LEAST_PLAN",
    "POSITIONS",
    "SPARSE",
    "TITLE_FLOOR",
    "AnySize",
    "Sheet1",
    "build_sheet",
    "compose",
    "one_title_size",
    "parse_plans",
    "plain_titles",
    "plan_extent",
    "render",
    "sparse_note",
    "title_block",
    "title_fields",
    "title_pairs",
    "views_of_any_size",
]

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
#: mm: where the plans of several positions are drawn at one μ, the least width (the
#: larger side of the box round its points) of any of them: a single plan's least crank
#: vector (:data:`drawing.sheet.fit.SIZES`)
LEAST_PLAN = 40.0


def title_fields(mech, pairs, scale: str, lang: str = "ru", numbers: tuple[str, str] | None = None,
                 subtitle: str = "") -> dict[str, str]:
    """The title block's fields: the file's [title], then --title-block over them. Two
    names of one field given different values in one place ("university" and
    "organisation") are refused: neither is dropped without a word. ``numbers``: the
    sheet's number and the count of sheets (fields 7 and 8) where several are drawn,
    under what the file and the options give; ``subtitle``: what the sheet shows, after
    the name in field 1 ("… . Силовой анализ")."""
    out = {"name": mech.name_in(lang), "scale": scale}
    if numbers is not None:
        out["sheet"], out["sheets"] = numbers
    for where, items in ((mech.source, list((mech.title or {}).items())),
                         ("--title-block", title_pairs(pairs))):
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
    if subtitle:
        out["name"] = f"{out['name']}. {subtitle}" if out["name"] else subtitle
    return out


def title_pairs(pairs) -> list[tuple[str, str]]:
    """--title-block's KEY=VALUE pairs as (key, value)."""
    out = []
    for pair in pairs:
        if "=" not in pair:
            raise InputError("--title-block", f"{pair!r} is not KEY=VALUE")
        k, v = pair.split("=", 1)
        out.append((k.strip(), v))
    return out


def title_block(mech, sheet, title, scale: str, lang: str, numbers: tuple[str, str] | None = None,
                subtitle: str = ""):
    """The title block, each entry in letters of at least TITLE_FLOOR mm (``numbers``,
    ``subtitle``: :func:`title_fields`)."""
    fields = title_fields(mech, title, scale, lang, numbers, subtitle)
    tb = TitleBlock(**fields)
    named = {FIELDS.get(k.lower()): (k, "--title-block") for k, _ in title_pairs(title)}
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


def parse_plans(text: str | None, n: int) -> list[int] | None:
    """--plans's position numbers ("1,4"), each once and among the ``n`` of the cycle."""
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
                plans: list[int] | None = None, title: list[str] = (),
                numbers: tuple[str, str] | None = None):
    """(scene, sheet, info) for ``mech``; info holds the solutions drawn. ``numbers``:
    the sheet's number and the count of sheets, where both sheets are drawn ("1", "2")."""
    if not POSITIONS[0] <= n_positions <= POSITIONS[1]:  # called from Python, not argparse
        raise InputError("--positions", f"give {POSITIONS[0]} to {POSITIONS[1]} positions, "
                         f"got {n_positions}")
    sheet = Sheet(fmt)
    title_block(mech, sheet, title, "", lang, numbers)  # refused before the views are fitted
    solver = Solver(mech)
    cycle = analyse_cycle(mech, n_positions, solver=solver)
    chosen = parse_plans(None if plans is None else ",".join(map(str, plans)), len(cycle.positions))
    fixed = views_of_any_size(mech, solver, cycle, lang)
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
    sheet_ = Sheet1(mech, sheet, solver, cycle, chosen, lang, fixed, given, mu0)
    mu, placed = sheet_.fill()  # every μ: the file's and those chosen
    return compose(mech, sheet, cycle, mu, lang, title, placed, sheet_.titled(mu), numbers)


class AnySize(NamedTuple):
    """What the sheet draws whatever the scale factors, worked out once, not per size."""

    shown: object  # the positions the plan of positions draws (plans.cycle.positions.Drawn)
    curves: object  # the kinematic diagrams' curves (views.diagram_curves), or None …
    notes: list  # … and the note that says why


def views_of_any_size(mech, solver, cycle, lang) -> AnySize:
    """The positions drawn and the diagrams' curves (or the note why there are none)."""
    shown = drawn(solver, cycle)
    curves = diagram_curves(mech, cycle, solver)
    if curves is not None:
        return AnySize(shown, curves, [])
    why = (no_full_turn(cycle, lang, mech.driver) if not cycle.full_turn else
           WORDS[lang]["no_stroke"])
    return AnySize(shown, None, [WORDS[lang]["no_diagrams"] + why[0].lower() + why[1:]])


#: mm: the kinematic diagrams' widths tried (one turn of the crank), with the height of
#: each of the three; 180 mm is 15 mm per position of twelve, 360 mm 1° per mm, 120 mm
#: what an A3 sheet beside the plans has room for
DIAGRAMS = {360.0: 60.0, 240.0: 50.0, 180.0: 40.0, 120.0: 28.0}


class Sheet1:
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
        sols = self.solutions(mu)
        lo = shown_from(self.cycle, self.mech.driver)  # as the range is written, if through 0°
        if self.chosen is None:
            return [("g", f"φ_{self.mech.driver.link} = "
                          f"{angle(self.mech.driver.angle_deg, 6, self.lang, lo)}°", sols[0])]
        out = []
        for k, sol in zip(self.chosen, sols, strict=True):
            deg = self.mech.driver.file_angle(self.cycle.positions[k])
            out.append((str(k), f"{WORDS[self.lang]['position']} {k}, φ_{self.mech.driver.link} = "
                                f"{angle(deg, 4, self.lang, lo)}°", sol))
        return out

    def factors(self) -> list[tuple[str, list[float], list[float]]]:
        """The free scale factors, their candidates (largest views first) and the size
        of the views at each, as a multiple of the engine's default size (a plan of
        positions 150 mm across, a plan's crank vector 80 mm or its longest 150 mm)."""
        out = []
        extent = self.fixed.shown.extent
        if "mu_l" not in self.mech.scales:
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
            # each position's plan is read on its own: where several are drawn at one μ,
            # the least of them no narrower than LEAST_PLAN, lest its letters crowd
            # (variant 1's plans of positions 2 and 6, 33 mm across beside a 185 mm one)
            least = min(plan_extent(p) for p in plans)
            hi, lo = (choose_mu(tip, largest, crank_mm=CRANK_MM * k, max_mm=PLAN_MM * k)
                      for k in SIZES)
            candidates = set(series(hi, lo)) | {hi, lo}
            if len(plans) > 1 and least / hi < LEAST_PLAN:
                # the least plan readable only where the largest is drawn larger than
                # the default's three times: the larger views too, up to the field's
                # longer side (beyond it no sheet of this format holds them)
                (x0, y0, x1, y1), _ = field(self.sheet)
                candidates |= set(series(largest / max(x1 - x0, y1 - y0), hi))
            sized = [(m, max(tip / m / CRANK_MM, largest / m / PLAN_MM)) for m in sorted(candidates)]
            sized = ([(m, k) for m, k in sized if readable(k)
                      and (len(plans) == 1 or least / m >= LEAST_PLAN - 1e-9)] or sized[:1])
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
        if key == "diagrams":
            return [diagrams_view(self.mech, self.cycle, self.lang, value, DIAGRAMS[value],
                                  curves=self.fixed.curves)]
        if key == "segments":
            return [segments_table_view(self._tabsols(mu or self.mu0), self.lang, value,
                                        sizing=sizing)]
        mu = dict(mu or self.mu0, **{key: value})
        if key == "mu_l":
            # the positions of the plans heavy (--plans), else the given one
            return [positions_view(solve_position(self.mech, solver=self.solver, mu=mu, cycle=self.cycle),
                                   self.cycle, self.lang, sizing=sizing, heavy=self.chosen)]
        kind = "velocity" if key == "mu_v" else "acceleration"
        return [plan_view(sol, kind, tag, self.lang, label, sizing=sizing)
                for tag, label, sol in self.titled(mu)]

    def others(self, mu: dict[str, float]) -> list:
        """The views no free factor sizes: those of the factors the file fixes (at its
        values), the diagrams, the tables (at ``mu``) and the note."""
        out = []
        for key in SCALED:
            if key in self.mech.scales:
                out += self.draw(key, self.mech.scales[key], mu)
        out.append(omega_table_view(self._tabsols(mu), self.lang))
        if self.fixed.notes:
            (x0, _, x1, _), _ = field(self.sheet)  # wrapped to the field, 180 mm at most
            out.append(note_view(self.fixed.notes, width=min(180.0, x1 - x0)))
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
        factors = self.factors()
        mu_free = {k: v[-1] for k, v, _ in factors if k in SCALED}
        # the views no free factor sizes are the same at any of their values: drawn once.
        # The plan of positions, the view a teacher reads first, is the largest where
        # its scale is free; each position's two plans stand together
        together = self.together()
        leader = (None if "mu_l" in self.mech.scales
                  else ("mu_l", "positions", ("velocity-", "acceleration-")))
        fit = Fit(self.sheet, factors, self.draw, self.others(dict(self.mu0, **mu_free)),
                  self.order(), plain={"segments"}, leader=leader, together=together, search=True)
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
        # each position's two plans together, the first position's read first where an
        # order of the views puts them so
        placed = one_title_size(self.sheet, place_views(
            self.sheet, fit.arranged(views + list(fit.fixed)), together, keep=True, search=True),
            together, keep=True)
        if not any(k in self.mech.scales for k in SCALED) or share_used(self.sheet, placed) >= SPARSE:
            # at their largest and still leaving room: spread evenly over the field, and so
            # at the scales a file fixes where they fill enough of it (the press on A2: half
            # of it, the lower 106 mm blank). Views the file's scales leave sparse stay
            # together, the share they take said in a note
            placed = balance(self.sheet, placed, together)
        return full, placed

    def _no_room(self, fit) -> str:
        """Why sheet 1 does not fit this format: what its views need at their smallest,
        and the smallest format that holds them."""
        smallest = {k: v[0] if k in fit.plain else v[-1] for k, v, _ in fit.factors}
        views = fit.arranged([v for k, value in smallest.items() for v in fit.views(k, value)]
                             + list(fit.fixed))
        need = ", ".join(f"{describe(v)} {v.w:.0f} × {v.h:.0f} mm" for v in views)
        names = list(FORMATS)
        holds = None
        for name in reversed(names[:names.index(self.sheet.name)]):  # the next larger first
            other = Sheet1(self.mech, Sheet(name), self.solver, self.cycle, self.chosen,
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
                 f"{PLAN_MM * SIZES[1]:.0f} mm across"
                 + (f", each position's plans {LEAST_PLAN:.0f} mm across at least, beside one "
                    "another" if self.chosen is not None and len(self.chosen) > 1 else "") + ")")
        return (f"sheet 1 does not fit on {room(self.sheet)}: at their smallest readable scales "
                f"({least} its views need {need}; {where}")


def one_title_size(sheet, placed: list, together=(), keep: bool = False) -> list:
    """The views ``placed`` with their titles in one size. A view's title much wider than
    its drawing is set smaller (:data:`drawing.views.SMALL_CAPTION`), so that a narrow
    plan's view is not as wide as its title; the other views' titles were then larger
    on the same sheet. Where they all pack with every title at full size, the long ones
    on two lines, they are so; else every title is set at the smaller size, each view in
    its place (its box only shrinks). The scale factors are those chosen either way: a
    title never costs a plan a step of its scale. Nor does it part the views kept
    ``together`` (:func:`drawing.sheet.layout.place_views`): where those are placed together
    and the full-size titles do not pack so, the titles are set smaller."""
    if len({p.view.caption_size for p in placed if p.view.caption_size}) <= 1:
        return placed
    views = [retitled(p.view, "wrap") for p in placed]
    sizes, pairs = [(v.w, v.h) for v in views], pairs_of([v.name for v in views], together)
    if keep and pairs:  # ``keep``: the pairs together, if need be not in reading order
        spots = pack_kept(sheet, sizes, pairs)
    else:
        spots = pack(sheet, sizes, pairs, apart=not kept_together(placed, together))
    if spots is None:
        views = [retitled(p.view, "small") for p in placed]
        spots = [(p.rect.x, p.rect.y) for p in placed]
    return [Placed(v, Rect(x, y, v.w, v.h)) for v, (x, y) in zip(views, spots, strict=True)]


def compose(mech, sheet, cycle, mu, lang, title, placed, sols, numbers=None):
    """(scene, sheet, info): the views ``placed`` in the frame with the title block, its
    scale that of the given position at ``mu`` (``numbers``: :func:`title_fields`)."""
    given = solve_position(mech, solver=sols[0][2].solver, mu=mu, cycle=cycle)
    tb = title_block(mech, sheet, title, gost_scale(given.mu_l, lang), lang, numbers)
    scene = frame_scene(sheet, tb, lang=lang)
    scene = scene + Scene((Layer("views", tuple(p.group() for p in placed)),))
    return scene, sheet, {"solutions": sols, "given": given, "cycle": cycle, "placed": placed}


#: below this share of the sheet's field, views drawn at scales the file fixes are noted
SPARSE = 0.3


def sparse_note(mech, sheet, placed) -> str | None:
    """Why a sheet is mostly empty, where the file's own scale factors made it so; None
    where the sheet chose its scales or the views fill it."""
    fixed = [k for k in ("mu_l", "mu_v", "mu_a") if k in mech.scales]
    share = share_used(sheet, placed)
    if not fixed or share >= SPARSE:
        return None
    names = ", ".join("μ" + k[-1] for k in fixed)
    return (f"the views take {share:.0%} of the {sheet.name} sheet's field at the scale "
            f"factors the file fixes ({names}); leave them out of [scales] for the sheet to "
            "choose them, or take a smaller --format")


def render(mech, fmt: str = "A1", lang: str = "ru", n_positions: int = 12,
           plans: list[int] | None = None, title: list[str] = (),
           numbers: tuple[str, str] | None = None) -> tuple[str, dict]:
    """(the SVG of sheet 1 of ``mech``, what :func:`build_sheet` tells of it, with the
    ``sheet`` it is drawn on and the ``scene`` drawn, which the DXF is written from)."""
    scene, sheet, info = build_sheet(mech, fmt, lang, n_positions, plans, title, numbers)
    return to_svg(scene, sheet, title=mech.name_in(lang)), dict(info, sheet=sheet, scene=scene)


def plain_titles(solutions) -> list[tuple[str, object]]:
    """(title as plain text, solution) of each position a sheet draws plans for: its
    caption's label without markup ("φ_1" is φ1), for the explanatory note."""
    return [("".join(r.text for r in parse_markup(label)), sol) for _, label, sol in solutions]


def plan_extent(plan) -> float:
    """The larger side of the box round a plan's points and pole, in its unit (m/s or
    m/s²): the width of its drawing at μ = 1."""
    zs = [0j, *(p.value for p in plan.points.values())]
    xs, ys = [z.real for z in zs], [z.imag for z in zs]
    return max(max(xs) - min(xs), max(ys) - min(ys))
