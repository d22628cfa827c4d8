"""The graphs of sheet 2: the balancing moment M_у(φ) over a turn of the crank, its mean
marked, the cycle's positions numbered; and the useful resistance's graph P(S) over the
working stroke, the analysed position marked on it."""

from __future__ import annotations

import math

import numpy as np

from drawing.labels import LabelRequest
from drawing.scene import Arrow, Circle, Item, Polyline, Segment, Text
from drawing.styles import LineType
from drawing.views.common import View, finish, per_mm, start_anchored
from drawing.views.forces import UNDER
from plans.fmt import num
from plans.forces.loads import resistance
from plans.scales import choose_mu

__all__ = ["GRAPH_WORDS", "moment_diagram_view", "resistance_view"]

GRAPH_WORDS = {
    "ru": {
        "moment": "Диаграмма уравновешивающего момента M_у(φ)",
        "resistance": "График сил полезного сопротивления P(S)",
        "Nm": "Н·м", "N": "Н", "m": "м", "mm": "мм", "rad": "рад",
        "mean": "M_{{у,ср}} = {v} Н·м",
        "cycle": "Работа сил полезного сопротивления A_{{пс}} = {A} Дж за цикл, средняя мощность "
                 "P_{{ср}} = {P} Вт",
        "cycle_no_resistance": "Средняя мощность P_{{ср}} = M_{{у,ср}}·ω_{{{i}}} = {P} Вт",
        "at": "P = {P} Н при S = {s} м ({stroke})",
        "working": "рабочий ход", "idle": "холостой ход",
        "idle_P": "На холостом ходу P = {P} Н",
    },
    "en": {
        "moment": "Balancing moment M_у(φ)",
        "resistance": "Useful resistance P(S)",
        "Nm": "N·m", "N": "N", "m": "m", "mm": "mm", "rad": "rad",
        "mean": "M_{{у,mean}} = {v} N·m",
        "cycle": "Work of the useful resistance A = {A} J per cycle, mean power P_{{mean}} = {P} W",
        "cycle_no_resistance": "Mean power P_{{mean}} = M_{{у,mean}}·ω_{{{i}}} = {P} W",
        "at": "P = {P} N at S = {s} m ({stroke})",
        "working": "working stroke", "idle": "idle stroke",
        "idle_P": "On the idle stroke P = {P} N",
    },
}


def _nice(x: float) -> float:
    """The next value ≥ x of the series 1, 2, 2.5, 4, 5 × 10^k."""
    return choose_mu(x, 0.0, crank_mm=1.0) if x > 0 else 1.0


def _axes(width: float, lo: float, hi: float, name: str, unit: str, scale: str, across: str) -> list[Item]:
    """A graph's axes, its zero line ``hi`` mm down from the top (y down): the vertical
    axis with its arrow and its name, the horizontal one ``across``, and the scale."""
    h = hi - lo
    items: list[Item] = [
        Segment((0.0, hi), (width + 6.0, hi), LineType.THIN),
        Arrow((0.0, h + 2.0), (0.0, -6.0), LineType.THIN, 3.0, 1.0),
        Text((2.0, -6.0), f"{name}, {unit}", size=3.5, baseline="hanging", markup=True),
        Text((width + 7.0, hi), across, size=3.5, baseline="middle", markup=True),
    ]
    if scale:
        items.append(start_anchored(Text((width - 2.0, -6.0), scale, size=3.5, anchor="end",
                                         baseline="hanging", markup=True)))
    return items


def moment_diagram_view(forces, cycle, lang: str = "ru", width: float = 180.0, height: float = 60.0,
                        sizing: bool = False) -> View | None:
    """M_у(φ) over a turn from the cycle's position 0, the way the crank turns, at μ_M and
    μ_φ: the curve heavy, the mean dashed and named, the positions numbered on their
    ticks, the analysed position a dot; None where the crank makes no full turn."""
    turn = forces.turn
    if turn is None:
        return None
    w = GRAPH_WORDS[lang]
    sol = forces.analysis.solution
    mech = sol.mechanism
    M = np.append(turn.M_y, turn.M_y[0])  # round the turn back to where it started
    lo, hi = float(min(M.min(), 0.0)), float(max(M.max(), 0.0))
    mu = _nice((hi - lo) / height or 1.0)
    top = hi / mu  # the φ axis, mm under the top
    xs = np.linspace(0.0, width, len(M))
    items: list[Item] = _axes(width, lo / mu, top, "M_у", w["Nm"],
                              f"μ_M = {num(mu, 3, lang)} {per_mm(w['Nm'], lang)}", "φ")
    items.append(Polyline(list(zip(xs.tolist(), (top - M / mu).tolist(), strict=True)), LineType.MAIN))
    mean = turn.mean_M_y()
    y_mean = top - mean / mu
    items.append(Segment((0.0, y_mean), (width, y_mean), LineType.DASHED))
    labels = [LabelRequest((width, y_mean), w["mean"].format(v=num(mean, 4, lang)), 3.5, "ne",
                           also=((width * 0.75, y_mean), (width * 0.5, y_mean), (width * 0.25, y_mean)))]
    n = len(cycle.positions)
    for k in range(n + 1):
        x = width * k / n
        items.append(Segment((x, top - 1.0), (x, top + 1.0), LineType.THIN))
        if k < n:
            labels.append(LabelRequest((x, top), str(k), 3.5, "s", markup=False))
    # the analysed position: where on the turn the sheet's force plans are
    sense = 1.0 if mech.driver.omega >= 0 else -1.0
    t = ((sol.phi - turn.phi[0]) * sense) % (2 * math.pi) / (2 * math.pi)
    items.append(Circle((width * t, top - forces.analysis.M_y / mu), 0.8, LineType.MAIN, fill="black"))
    power = turn.mean_power()
    work = turn.resistance_work()
    under = [w["cycle"].format(A=num(work, 4, lang), P=num(power, 4, lang)) if work is not None
             else w["cycle_no_resistance"].format(i=mech.driver.link, P=num(power, 4, lang))]
    caption = f"{w['moment']}, μ_φ = {num(2 * math.pi / width, 3, lang)} {w['rad']}/{w['mm']}"
    return finish("moment", items, labels, caption, under, pad=4.0, sizing=sizing, under_size=UNDER)


def resistance_view(forces, lang: str = "ru", width: float = 120.0, height: float = 50.0,
                    sizing: bool = False) -> View | None:
    """The useful resistance P(S) over the working stroke as the file gives it, at μ_P and
    μ_S, with the analysed position's S and P marked; None where the file gives no graph."""
    fa = forces.analysis
    mech = fa.solution.mechanism
    graph = mech.loads.resistance
    stroke = fa.stroke
    if graph is None or stroke is None:
        return None
    w = GRAPH_WORDS[lang]
    H = stroke.H
    xs = np.asarray(graph.s, dtype=float) * (H if graph.relative else 1.0)
    Ps = np.asarray(graph.P, dtype=float)
    s = [0.0, *[x for x in xs if 0.0 < x < H]]
    pts = [(x, float(np.interp(x, xs, Ps, right=0.0))) for x in s]
    if xs[-1] < H * (1 - 1e-9):  # beyond its last point the graph is 0: a step down there
        pts += [(float(xs[-1]), float(Ps[-1])), (float(xs[-1]), 0.0), (H, 0.0)]
    else:
        pts.append((H, float(np.interp(H, xs, Ps))))
    mu_s = _nice(H / width)
    mu_P = _nice(max(Ps.max(), 1e-9) / height)
    top = max(Ps.max(), 0.0) / mu_P
    span = H / mu_s
    items: list[Item] = _axes(span, 0.0, top, "P", w["N"], "", f"S, {w['m']}")
    items.append(Polyline([(x / mu_s, top - P / mu_P) for x, P in pts], LineType.MAIN))
    items.append(Segment((span, top - 1.0), (span, top + 1.0), LineType.THIN))
    labels = [LabelRequest((span, top), "H", 3.5, "s", markup=False),
              LabelRequest((0.0, top), "0", 3.5, "sw", markup=False)]
    P, _, s_at = resistance(mech.loads, stroke, fa.solution.phi, fa.solution.scalar.position)
    working = bool(stroke.working(fa.solution.phi))
    under = [f"μ_P = {num(mu_P, 3, lang)} {per_mm(w['N'], lang)}, μ_S = {num(mu_s, 3, lang)} "
             f"{per_mm(w['m'], lang)}"]
    if working:  # the position on the graph: S and P, projected to the axes
        x, y = s_at / mu_s, top - P / mu_P
        items += [Segment((x, top), (x, y), LineType.DASHED), Segment((0.0, y), (x, y), LineType.DASHED),
                  Circle((x, y), 0.8, LineType.MAIN, fill="black")]
    under.append(w["at"].format(P=num(P, 4, lang), s=num(s_at, 4, lang),
                                stroke=w["working" if working else "idle"]))
    if graph.idle:
        under.append(w["idle_P"].format(P=num(graph.idle, 4, lang)))
    return finish("resistance", items, labels, w["resistance"], under, pad=4.0, sizing=sizing,
                  under_size=UNDER)
