"""Sheet 2 of the course project: the force analysis of one crank position on one GOST sheet.

It draws what :func:`plans.forces.summary.solve_forces` finds at the mechanism's position:
the mechanism at μl with every load on it, each Assur group drawn apart with its loads and
its unknown reactions beside its force plan, the driving link with R01 and M_у,
Zhukovsky's lever at μv, the M_у(φ) diagram over the cycle (where the crank turns fully),
the useful resistance's graph P(S) (where the file gives one), and the tables of the loads,
the reactions and the lever (:mod:`drawing.views.forces` and its neighbours).

The scale factors the file leaves free are chosen as sheet 1 chooses its own
(:class:`drawing.sheet.fit.Fit`): μl for the mechanism's views, μv for the lever, and one
step of the force plans' μF (each plan at its own standard μF, its longest vector 150 mm
as ``plans forces`` draws it, or 113 or 75 mm where the sheet needs the room); a vector
measured on the sheet is the segment its table gives.
"""

from __future__ import annotations

import dataclasses
import math

from drawing.scene import Layer, Scene
from drawing.sheet.fit import SIZES, Fit, readable
from drawing.sheet.frame import FORMATS, Sheet, frame_scene
from drawing.sheet.layout import LayoutError, field, place_views, room, spread
from drawing.sheet1 import one_title_size, sparse_note, title_block
from drawing.svg import to_svg
from drawing.views import note_view
from drawing.views.force_diagrams import moment_diagram_view, resistance_view
from drawing.views.force_tables import lever_table_view, loads_table_view, reactions_table_view
from drawing.views.forces import FORCE_WORDS, crank_view, force_plan_view, group_view, mechanism_view
from drawing.views.lever import lever_view
from plans.cycle import analyse_cycle, shown_from
from plans.errors import InputError, SingularPlanError
from plans.fmt import angle
from plans.forces.fplans import FORCE_PLAN_MM
from plans.forces.summary import Forces, solve_forces
from plans.kinematics.solver import Solver
from plans.note.report import no_full_turn
from plans.plan.solution import plan_name, solve_position
from plans.scales import CRANK_MM, GOST_MU_L, PLAN_MM, choose_mu, gost_scale, series

__all__ = ["FORCE_SIZES", "LARGEST", "LONGEST", "MECHANISM_MM", "MOMENT", "NO_LOADS", "Sheet2",
           "build_sheet2", "force_plans_at", "needs_loads", "render"]

#: the force plans' sizes tried: their longest vector as a share of FORCE_PLAN_MM (150 mm,
#: as ``plans forces`` draws them), largest first: they are what sheet 2 is for
FORCE_SIZES = (2.5, 2.0, 1.5, 1.25, 1.0, 0.75, 0.5)
#: the largest the mechanism's views and the lever are drawn, as a multiple of the
#: engine's default size (150 mm across): the force plans, not the mechanism drawn three
#: times over, should take the room a large sheet has
LARGEST = {"mu_l": 2.0, "mu_v": 3.0}
#: mm: the longest a flat mechanism (a crank-slider) is drawn
LONGEST = 500.0
#: mm: the size across of the mechanism's views that counts as their default when the
#: sheet weighs them against the other views (the engine's plan of positions is 150 mm:
#: sheet 2 draws the mechanism two or three times over, and no force plan should be
#: drawn smaller for it to be drawn at 1:1)
MECHANISM_MM = 100.0
#: mm: the M_у(φ) diagram's sizes tried, largest first: its width (one turn of the
#: crank) and its height; the factor's value is the size's index
MOMENT = ((360.0, 120.0), (360.0, 90.0), (240.0, 70.0), (180.0, 50.0), (120.0, 40.0))

NO_LOADS = ("loads: missing: sheet 2 draws the force analysis, which needs the links' masses and "
            'the forces on them, e.g. [loads.links.3] mass = 10, J_S = 0.4, centre = "S3" (README: Loads)')


def needs_loads(mech) -> None:
    """Refuse a mechanism without [loads] for sheet 2, in one line, before any work."""
    if mech.loads is None:
        raise InputError(mech.source, NO_LOADS)


def force_plans_at(forces: Forces, size: float) -> Forces:
    """``forces`` with each group's force plan at the standard μF that makes its longest
    vector at most ``size`` × 150 mm (1.0: the μF ``plans forces`` gives it), its segments
    in mm at that μF."""
    groups = []
    for gf in forces.analysis.groups:
        plan = gf.plan
        ends = plan.ends.values()
        big = max([abs(p.value) for p in plan.points.values()]
                  + [abs(plan.points[b].value - plan.points[a].value) for a, b in ends] + [0.0])
        mu = choose_mu(big, big, FORCE_PLAN_MM * size, FORCE_PLAN_MM * size)
        segments = {label: (abs(plan.points[b].value - plan.points[a].value) / mu
                            if abs(plan.points[b].value - plan.points[a].value) > plan.tiny else 0.0)
                    for label, (a, b) in plan.ends.items()}
        groups.append(gf._replace(plan=plan._replace(mu=mu, segments=segments)))
    fa = dataclasses.replace(forces.analysis, groups=tuple(groups))
    return dataclasses.replace(forces, analysis=fa)


def _box(sol) -> tuple[float, float]:
    """The sides (m) of the box round the mechanism in its position, the larger first."""
    xs = [z.real for z in sol.positions.values()]
    ys = [z.imag for z in sol.positions.values()]
    w, h = max(xs) - min(xs), max(ys) - min(ys)
    return max(w, h, 1e-9), max(min(w, h), 1e-9)


def _not_too_large(box: tuple[float, float], mu_l: float) -> bool:
    """Whether the mechanism's views at ``mu_l`` are no larger than sheet 2 wants them: no
    more than :data:`LARGEST` times the default size across, as large in area as a square
    of that size, and a flat one (a crank-slider) up to :data:`LONGEST` long."""
    side = PLAN_MM * LARGEST["mu_l"]
    long, short = box[0] / mu_l, box[1] / mu_l
    return long <= side or (long <= LONGEST and long * short <= side * side)


class Sheet2:
    """The views of sheet 2 and the scale factors they are drawn at."""

    def __init__(self, mech, sheet, lang: str, forces: Forces, cycle, scales: dict[str, float]):
        self.mech, self.sheet, self.lang, self.forces, self.cycle = mech, sheet, lang, forces, cycle
        self.scales = scales  # the scale factors fixed: the file's, and sheet 1's μv drawn beside it
        self.sol = forces.analysis.solution
        lo = shown_from(cycle, mech.driver)
        self.label = f"φ_{mech.driver.link} = {angle(mech.driver.angle_deg, 6, lang, lo)}°"

    def factors(self) -> list[tuple[str, list[float], list[float]]]:
        out = []
        box = _box(self.sol)
        extent = box[0]
        if "mu_l" not in self.scales:
            values = [m for m in GOST_MU_L if readable(extent / m / PLAN_MM) and _not_too_large(box, m)]
            values = values or [min(GOST_MU_L, key=lambda m: abs(extent / m - PLAN_MM))]
            # sized against MECHANISM_MM: the mechanism is drawn two or three times, and
            # a step of the GOST series may halve it; the force plans come first
            out.append(("mu_l", values, [extent / m / MECHANISM_MM for m in values]))
        if "mu_v" not in self.scales:
            plan = self.sol.velocity
            tip = abs(plan.value(plan_name(self.mech.driver.tip)))
            largest = max(abs(q.value) for q in plan.points.values())
            hi, lo = (choose_mu(tip, largest, crank_mm=CRANK_MM * k, max_mm=PLAN_MM * k) for k in SIZES)
            sized = [(m, max(tip / m / CRANK_MM, largest / m / PLAN_MM))
                     for m in sorted(set(series(hi, lo)) | {hi, lo})]
            sized = [(m, k) for m, k in sized if readable(k) and k <= LARGEST["mu_v"]] or sized[-1:]
            out.append(("mu_v", [m for m, _ in sized], [k for _, k in sized]))
        out.append(("mu_F", list(FORCE_SIZES), list(FORCE_SIZES)))
        if self.forces.turn is not None:
            # as a multiple of the default 180 × 50 mm, by its area
            out.append(("diagrams", list(range(len(MOMENT))),
                        [math.sqrt(w * h / (180.0 * 50.0)) for w, h in MOMENT]))
        return out

    def draw(self, key: str, value: float, sizing: bool = False) -> list:
        """The views the factor ``key`` sizes, drawn at ``value``."""
        fa, lang = self.forces.analysis, self.lang
        if key == "mu_l":
            return [mechanism_view(fa, value, lang, self.label, sizing=sizing),
                    *(group_view(fa, gf, value, lang, str(i), sizing=sizing)
                      for i, gf in enumerate(fa.groups, 1)),
                    crank_view(fa, value, lang, sizing=sizing)]
        if key == "mu_v":
            return [lever_view(self.forces, value, lang, sizing=sizing)]
        if key == "mu_F":
            return [force_plan_view(gf, lang, str(i), sizing=sizing)
                    for i, gf in enumerate(force_plans_at(self.forces, value).analysis.groups, 1)]
        return [moment_diagram_view(self.forces, self.cycle, lang, *MOMENT[int(value)], sizing=sizing)]

    def tables(self, mu: dict[str, float]) -> list:
        """The tables at the scale factors ``mu`` (their sizes do not depend on them)."""
        forces = force_plans_at(self.forces, mu["mu_F"])
        return [loads_table_view(forces, self.lang), reactions_table_view(forces, self.lang),
                lever_table_view(forces, mu["mu_v"], self.lang)]

    def others(self, mu: dict[str, float]) -> list:
        """The views no free factor sizes: those at the scales the file fixes, the graph
        P(S), the tables and the note where there is no diagram."""
        out = []
        for key in ("mu_l", "mu_v"):
            if key in self.scales:
                out += self.draw(key, self.scales[key])
        graph = resistance_view(self.forces, self.lang)
        if graph is not None:
            out.append(graph)
        out += self.tables(mu)
        if self.forces.turn is None:
            why = no_full_turn(self.cycle, self.lang, self.mech.driver)
            words = FORCE_WORDS[self.lang]["no_moment_diagram"]
            (x0, _, x1, _), _ = field(self.sheet)
            out.append(note_view([words + why[0].lower() + why[1:]], width=min(180.0, x1 - x0)))
        return out

    def order(self) -> list[str]:
        groups = range(1, len(self.forces.analysis.groups) + 1)
        return (["mechanism"] + [f"{kind}-{i}" for i in groups for kind in ("group", "force")]
                + ["crank", "lever", "moment", "resistance", "loads", "reactions", "lever-table", "note"])

    def together(self) -> list[tuple[str, str]]:
        """Each group drawn apart with its force plan beside it, in the order solved."""
        return [(f"group-{i}", f"force-{i}") for i in range(1, len(self.forces.analysis.groups) + 1)]

    def fill(self):
        """(every factor's value, the views placed, the forces as drawn)."""
        factors = self.factors()
        provisional = {k: v[-1] for k, v, _ in factors}
        mu_v = self.scales.get("mu_v", provisional.get("mu_v"))
        fit = Fit(self.sheet, factors, self.draw,
                  self.others({"mu_F": provisional["mu_F"], "mu_v": mu_v}), self.order(),
                  plain=set(), lettered=("mu_F",))
        chosen = fit.best()
        full = {"mu_l": self.scales.get("mu_l"), "mu_v": self.scales.get("mu_v"), **chosen}
        views = [v for k, value in chosen.items() for v in fit.views(k, value)]
        tables = {v.name: v for v in self.tables(full)}
        views += [tables.get(v.name, v) for v in fit.fixed]
        together = self.together()
        placed = one_title_size(self.sheet, place_views(self.sheet, fit.arranged(views), together),
                                together)
        if not any(k in self.scales for k in ("mu_l", "mu_v")):
            placed = spread(self.sheet, placed)
        return full, placed, force_plans_at(self.forces, full["mu_F"])


def build_sheet2(mech, fmt: str = "A1", lang: str = "ru", n_positions: int = 12,
                 title: list[str] = (), numbers: tuple[str, str] = ("2", "2"),
                 beside: dict[str, float] | None = None):
    """(scene, sheet, info) of sheet 2 of ``mech``: info holds the forces drawn (their
    plans at the sheet's μF, their solution at its μl and μv), the views placed and the
    scale factors. ``beside``: sheet 1's μv and μa where it is drawn too: the lever is
    its velocity plan turned, and the note reads the inertia loads' accelerations off its
    acceleration plan."""
    needs_loads(mech)
    sheet = Sheet(fmt)
    subtitle = FORCE_WORDS[lang]["title"]
    title_block(mech, sheet, title, "", lang, numbers, subtitle)  # refused before the views are fitted
    scales = {k: v for k, v in mech.scales.items() if k in ("mu_l", "mu_v", "mu_a")}
    scales.update(beside or {})
    solver = Solver(mech)
    cycle = analyse_cycle(mech, n_positions, solver=solver)
    try:
        given = {k: scales[k] for k in ("mu_v", "mu_a") if k in scales}
        sol = solve_position(mech, solver=solver, mu={"mu_l": scales.get("mu_l", 0.001), **given},
                             cycle=cycle)
        forces = solve_forces(sol, solver, cycle)
    except SingularPlanError as exc:
        raise SingularPlanError(f"{exc} (sheet 2 draws the force analysis of the given position: "
                                "choose another with --angle)", sine=exc.sine, source=exc.source) from None
    try:
        full, placed, forces = Sheet2(mech, sheet, lang, forces, cycle, scales).fill()
    except LayoutError as exc:
        if exc.option != "--format":
            raise
        raise LayoutError(_no_room(mech, sheet, lang, forces, cycle, scales), "--format") from None
    # the solution at the sheet's μl and μv: the note's numbers are those drawn
    mu_a = {"mu_a": scales["mu_a"]} if "mu_a" in scales else {}
    final = solve_position(mech, solver=solver, mu={"mu_l": full["mu_l"], "mu_v": full["mu_v"], **mu_a},
                           cycle=cycle)
    tb = title_block(mech, sheet, title, gost_scale(full["mu_l"], lang), lang, numbers, subtitle)
    scene = frame_scene(sheet, tb, lang=lang)
    scene = scene + Scene((Layer("views", tuple(p.group() for p in placed)),))
    drawn = force_plans_at(solve_forces(final, solver, cycle), full["mu_F"])
    return scene, sheet, {"forces": drawn, "placed": placed, "cycle": cycle, "mu": full,
                          "solution": final}


def _no_room(mech, sheet, lang, forces, cycle, scales) -> str:
    """Why sheet 2 does not fit this format, and the smallest format that holds it."""
    names = list(FORMATS)
    holds = None
    for name in reversed(names[:names.index(sheet.name)]):  # the next larger first
        try:
            Sheet2(mech, Sheet(name), lang, forces, cycle, scales).fill()
        except LayoutError:
            continue
        holds = name
        break
    where = f"{holds} holds it: use --format {holds}" if holds else "no format holds it"
    fixed = [f"μ{k[-1]} = {v:g}" for k, v in scales.items() if k in ("mu_l", "mu_v")]
    given = f", {' and '.join(fixed)} as fixed" if fixed else ""
    return (f"sheet 2 does not fit on {room(sheet)}: its views need more room even at their "
            f"smallest (the force plans' longest vectors {FORCE_PLAN_MM * FORCE_SIZES[-1]:.0f} mm, "
            f"the mechanism {PLAN_MM * SIZES[1]:.0f} mm across{given}); {where}")


def render(mech, fmt: str = "A1", lang: str = "ru", n_positions: int = 12, title: list[str] = (),
           numbers: tuple[str, str] = ("2", "2"), beside: dict[str, float] | None = None
           ) -> tuple[str, dict]:
    """(the SVG of sheet 2 of ``mech``, what :func:`build_sheet2` tells of it, with the
    ``sheet`` it is drawn on, the ``scene`` drawn (which the DXF is written from) and a note
    where the file's scales leave it mostly empty)."""
    scene, sheet, info = build_sheet2(mech, fmt, lang, n_positions, title, numbers, beside)
    info = dict(info, sheet=sheet, scene=scene, sparse=sparse_note(mech, sheet, info["placed"]))
    return to_svg(scene, sheet, title=f"{mech.name_in(lang)}: {FORCE_WORDS[lang]['title']}"), info
