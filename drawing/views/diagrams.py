"""The kinematic diagrams: s(φ), v(φ), a(φ) of the output over one turn (ψ, ω, ε of an
output link that rocks or turns), the positions numbered on their ticks."""

from __future__ import annotations

import math

import numpy as np
import shapely
from shapely.geometry import box as shp_box

from drawing.labels import LabelRequest, place_labels
from drawing.obstacles import obstacles_of
from drawing.scene import Arrow, Item, Polyline, Segment, Text
from drawing.styles import LineType, Style
from drawing.text import text_box
from drawing.ticks import Ticks
from drawing.views.common import WORDS, View, bbox, captioned, per_mm, start_anchored
from plans.cycle import at_rest
from plans.fmt import num
from plans.kinematics.solver import Solver
from plans.scales import choose_mu

__all__ = [
    "NUMBERS_APART",
    "NUMBER_BESIDE",
    "NUMBER_CLEAR",
    "NUMBER_GAPS",
    "diagram_curves",
    "diagrams_view",
]

def diagrams_view(mech, cycle, lang: str = "ru", width: float = 180.0, height: float = 40.0,
                  solver=None, curves=None) -> View | None:
    """s(φ), v(φ), a(φ) of the output over one turn from the first position; ψ(φ), ω(φ),
    ε(φ) of an output link that rocks, or that turns all the way round (a rotating slotted
    link: ψ then grows by a full turn). ``curves``: :func:`diagram_curves`, worked out
    before (a sheet draws the diagrams at several sizes)."""
    if curves is None:
        curves = diagram_curves(mech, cycle, solver)
    if curves is None:
        return None
    s, v, a, flip = curves
    out = cycle.output
    return _draw_diagrams(mech, cycle, lang, width, height, out.kind == "linear", s, v, a, flip)


def diagram_curves(mech, cycle, solver=None):
    """The output's (s, v, a) (or ψ, ω, ε) at 361 crank angles over one turn from the
    first position, positive the way the working stroke goes (so that s or ψ rises from
    0 at the extreme position it starts from), and that way: 1.0 where it is the
    world's positive sense (ccw for an angle), -1.0 where it is the other; None where
    there are no diagrams to draw."""
    solver = solver or Solver(mech)
    out = cycle.output
    if out is None or not cycle.full_turn or not cycle.positions:
        return None
    if not cycle.stroke and out.kind != "angular":
        return None
    sense = 1.0 if mech.driver.omega >= 0 else -1.0
    phi0 = cycle.positions[0]
    phis = phi0 + sense * np.linspace(0.0, 2 * math.pi, 361)
    m = solver.solve(phis)
    if not m.placed.all():
        return None
    s = np.asarray(out.value(m, mech), dtype=float)
    if out.kind == "angular":
        s = np.unwrap(s)  # an angle in (−π, π]: continuous across ±π, and past a full turn
    s = s - s[0]
    flip = -1.0 if abs(s.min()) > abs(s.max()) else 1.0  # s from the starting extreme, ≥ 0
    s = flip * s
    v = flip * np.asarray(out.rate(m, mech, "velocity"), dtype=float)
    a = flip * np.asarray(out.rate(m, mech, "acceleration"), dtype=float)
    ok = solver.trusted(m)
    if not ok.all():  # a sample on or beside a change point, where the plans are singular:
        # the curve runs straight over it from the samples either side (1° away); a
        # slotted link's block on its pivot is one too, where the lines' sine stays 1
        k = np.arange(len(phis))
        v[~ok] = np.interp(k[~ok], k[ok], v[ok])
        a[~ok] = np.interp(k[~ok], k[ok], a[ok])
    return s, v, a, flip


def _draw_diagrams(mech, cycle, lang, width, height, linear, s, v, a, flip=1.0) -> View:
    w = WORDS[lang]
    units = (w["m"], w["ms"], w["ms2"]) if linear else (w["rad"], w["rads"], w["rads2"])
    names = ("s", "v", "a") if linear else ("ψ", "ω", "ε")
    # the axes name their quantity as the tables and the note do: ω3 of the rocker 3,
    # s_D of the slider's point D (a sheet may have ω of several links)
    out = cycle.output
    index = (out.point if linear else str(out.link)) if out is not None else ""
    items: list[Item] = []
    numbers: list[tuple[float, float, str]] = []  # each numbered position's tick and number
    every = _numbered_every(len(cycle.positions), width)
    y = 0.0
    # rounding of a 0 is drawn as 0, not blown up to the height of the diagram (a
    # parallelogram's ε3 of 1e-13 rad/s² at μ = 5e-10)
    s, v, a = (np.where(np.abs(x) < at_rest(mech, linear, k), 0.0, x) for k, x in enumerate((s, v, a)))
    for data, name, unit in zip((s, v, a), names, units, strict=True):
        lo, hi = float(min(data.min(), 0)), float(max(data.max(), 0))
        span = hi - lo or 1.0
        mu = _nice(span / height)
        y_zero = y + hi / mu
        h = (hi - lo) / mu
        xs = np.linspace(0, width, len(data))
        ys = y_zero - data / mu
        items.append(Segment((0, y_zero), (width + 6, y_zero), LineType.THIN))
        items.append(Arrow((0, y + h + 2), (0, y - 6), LineType.THIN, 3.0, 1.0))
        items.append(Polyline(list(zip(xs.tolist(), ys.tolist(), strict=True)), LineType.MAIN))
        for k in range(len(cycle.positions) + 1):
            x = width * k / len(cycle.positions)
            items.append(Segment((x, y_zero - 1), (x, y_zero + 1), LineType.THIN))
            if k % every == 0:
                numbers.append((x, y_zero, str(k % len(cycle.positions))))
        axis = _axis_name(name + (f"_{{{index}}}" if index else ""), unit,
                          None if linear else flip, lang)
        items.append(Text((2, y - 6), axis, size=3.5, baseline="hanging", markup=True))
        items.append(Text((width + 6, y_zero - 1.5), "φ", size=3.5, anchor="end"))
        scale = f"μ_{{{name}}} = {num(mu, 3, lang)} {per_mm(unit, lang)}"
        items.append(start_anchored(Text((width - 2, y - 6), scale, size=3.5, anchor="end",
                                         baseline="hanging", markup=True)))
        y += h + 16.0
    placed, bounds = _numbers(items, numbers)
    mu_phi = 2 * math.pi / width
    caption = f"{w['diagrams']}, μ_φ = {num(mu_phi, 3, lang)} {w['rad']}/{w['mm']}"
    return captioned("diagrams", items + placed, bounds, caption, [])


def _numbered_every(count: int, width: float) -> int:
    """Every how many positions a diagram's tick is numbered: every second, as on
    paper, or every fourth, sixth … where the numbers would stand closer than their own
    width and a gap. With 72 positions on a 120 mm diagram the ticks are 1.7 mm apart, and
    every second one's two digits (3.4 mm) ran into the next number and onto the curves."""
    widest = text_box(Text((0.0, 0.0), str(count - 1), size=2.5, italic=True)).bounds
    need = widest[2] - widest[0] + NUMBERS_APART
    every = 2
    while every * width / count < need:
        every += 2
    return every


#: mm: the least gap between two numbers of positions next to each other on the φ axis
NUMBERS_APART = 1.5
#: mm: how far a position's number stands from the φ axis (its box), nearest first
NUMBER_GAPS = (1.5, 3.0, 4.5)
#: mm: between a tick and the box of a number set beside it, not under or over it
NUMBER_BESIDE = 0.6
#: mm: what a number keeps clear of a diagram's curve beyond the line's half width,
#: of the axes and ticks, and of the other texts
NUMBER_CLEAR = (0.4, 0.1, 0.5)


def _numbers(items: list[Item], numbers: list[tuple[float, float, str]]
             ) -> tuple[list[Text], tuple[float, float, float, float]]:
    """The positions' numbers ((x, y_zero, text) of each tick) on the diagrams ``items``,
    and the box of the view's drawing.

    A number stood under its tick whatever was there, so a curve running below the φ
    axis went through it, and the origin's 0 was written across the vertical axis. Each
    is now placed by :func:`drawing.labels.place_labels` with the numbers' rule
    (:mod:`drawing.ticks`): by its tick, where it meets no curve, no line and no text.
    The view keeps its box, that of the drawing with every number under its tick, and
    each number stays in it: the sheets are packed first-fit, and a view 0.75 mm narrower
    moved them too (variant 5's English sheet on A2 lost a step of its diagrams)."""
    requests = [LabelRequest((x, y_zero), text, 2.5, "s", markup=False)
                for x, y_zero, text in numbers]
    under = [Text((x, y_zero + NUMBER_GAPS[0]), text, size=2.5, anchor="middle",
                  baseline="hanging", italic=True) for x, y_zero, text in numbers]
    texts = np.array([text_box(t).bounds for t in items if isinstance(t, Text)]).reshape(-1, 4)
    spans = np.array([text_box(t).bounds for t in under]).reshape(-1, 4)
    every = np.vstack([texts, spans, bbox([it for it in items if not isinstance(it, Text)])])
    bounds = tuple(float(b) for b in (*every[:, :2].min(axis=0), *every[:, 2:].max(axis=0)))
    frame = shp_box(*np.add(bounds, (-1e-6, -1e-6, 1e-6, 1e-6)))
    style = Style()

    def steps(lines):  # the middle lines of ``lines`` (segments, polylines), step by step
        return shapely.linestrings(np.concatenate([
            np.stack([np.asarray(p)[:-1], np.asarray(p)[1:]], axis=1)
            for p in (it.points if isinstance(it, Polyline) else (it.p1, it.p2) for it in lines)]))

    def reach(lines, clear):  # how near the middle of one of ``lines`` a number may not come
        return max(style.width(it.line) for it in lines) / 2 + clear

    curves = [it for it in items if isinstance(it, Polyline)]
    segments = [it for it in items if isinstance(it, Segment)]  # the φ axes, the ticks
    obstacles = [  # the vertical axes with their heads, the other texts
        *obstacles_of([it for it in items if isinstance(it, Arrow)], clearance=NUMBER_CLEAR[1]),
        *shapely.box(texts[:, 0] - NUMBER_CLEAR[2], texts[:, 1] - NUMBER_CLEAR[2],
                     texts[:, 2] + NUMBER_CLEAR[2], texts[:, 3] + NUMBER_CLEAR[2])]
    ticks = Ticks(steps(segments), reach(segments, NUMBER_CLEAR[1]),
                  reach(curves, NUMBER_CLEAR[0]), NUMBER_CLEAR[2], NUMBER_BESIDE)
    placed = place_labels(requests, obstacles, region=frame, distances=NUMBER_GAPS,
                          soft=steps(curves), ticks=ticks)
    return [p.text for p in placed], bounds


def _axis_name(name: str, unit: str, flip: float | None, lang: str) -> str:
    """A diagram's axis: "s, м"; an angle's with its positive sense after it, one space
    apart, "ε, рад/с² (+ против ч.с.)": the tables give ω and ε by their senses, and the
    working stroke of a rocker may turn either way. One text, so that the space is the
    font's own (set apart by an estimate of the name's width, the sense stood two
    spaces after "рад/с²" and one after "рад")."""
    if flip is None:
        return f"{name}, {unit}"
    w = WORDS[lang]
    return f"{name}, {unit} (+ {w['ccw'] if flip > 0 else w['cw']})"


def _nice(x: float) -> float:
    """The next value ≥ x of the series 1, 2, 2.5, 4, 5 × 10^k (the plans' series)."""
    return choose_mu(x, 0.0, crank_mm=1.0) if x > 0 else 1.0
