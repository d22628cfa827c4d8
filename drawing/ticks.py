"""The rule of the positions' numbers on a kinematic diagram's φ axis: an option of
:func:`drawing.labels.place_labels` (its ``ticks``), where a number's rule differs from a
letter's.

A number stays by its tick: under it where that is clear, else over it (on the other
side of the axis from the curve), else beside the tick under the axis, then over it, then
a little farther off (``distances``); the origin's 0 right of the vertical axis, never
across it. It meets no line and no text, keeps :attr:`Ticks.apart` from the numbers
before it and keeps off the curves; where every spot crosses a curve, it crosses the
least of them. It never leaves ``region``: a number must not widen its view (the sheets
are packed first-fit, and a view 0.75 mm wider moves the others).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
import shapely
from shapely.geometry import Polygon
from shapely.geometry.base import BaseGeometry

from drawing.scene import Text, translate
from drawing.text import text_box

__all__ = ["Ticks", "on_ticks"]


@dataclass(frozen=True, slots=True)
class Ticks:
    """What numbers on ticks keep clear of, beyond the obstacles a label meets.

    Args:
        lines: the middle lines of the axes and the ticks, step by step (LineStrings).
        line_reach: how near a line's middle a number may not come (mm).
        curve_reach: the same for a curve (``soft``, to :func:`on_ticks`).
        apart: mm between a number and the numbers placed before it.
        beside: mm between a tick and the box of a number set beside it.
    """

    lines: Sequence[BaseGeometry]
    line_reach: float
    curve_reach: float
    apart: float
    beside: float


def _grown(boxes, d: float) -> np.ndarray:
    """Axis-parallel boxes (rows of x0, y0, x1, y1) widened by ``d``."""
    b = np.asarray(boxes).reshape(-1, 4)
    return shapely.box(b[:, 0] - d, b[:, 1] - d, b[:, 2] + d, b[:, 3] + d)


def on_ticks(requests, obstacles: Sequence[BaseGeometry], curves: Sequence[BaseGeometry],
             region: BaseGeometry, distances: Sequence[float], ticks: Ticks
             ) -> list[tuple[Text, Polygon, bool]]:
    """(text, box, clear) of each number of ``requests``, each anchored at its tick where
    it meets the φ axis (x, y of the axis), in turn. ``obstacles``: shapes a number may
    not meet (already widened); ``curves``: the curves' middle lines, step by step."""
    tree = shapely.STRtree(list(obstacles))
    on_lines = shapely.STRtree(list(ticks.lines))
    on_curves = shapely.STRtree(list(curves))
    ink = None  # the curves' ink as one shape, where a number has no clear spot
    out: list[tuple[Text, Polygon, bool]] = []
    taken = []  # the boxes of the numbers placed
    for req in requests:
        x, y_zero = req.anchor
        first = Text((x, y_zero + distances[0]), req.text, size=req.size, anchor="middle",
                     baseline="hanging", italic=req.italic, markup=req.markup)
        x0, y0, x1, y1 = text_box(first).bounds
        w, h = x1 - x0, y1 - y0
        # (side, beside): under or over the tick, then beside it under the axis, then
        # over it; the origin's 0 right of the vertical axis, never across it
        spots = (((1, 0), (-1, 0), (1, 1), (1, -1), (-1, 1), (-1, -1)) if x > 0
                 else ((1, 1), (-1, 1)))
        moves = np.array([(
            {0: x0, 1: x + ticks.beside, -1: x - ticks.beside - w}[beside] - x0,
            (y_zero + gap if side > 0 else y_zero - gap - h) - y0)
            for gap in distances for side, beside in spots])
        tried = np.array([x0, y0, x1, y1]) + np.tile(moves, 2)
        boxes = _grown(tried, 0.0)
        outside = ~shapely.covers(region, boxes)  # none leaves the view's box
        hit = np.zeros(len(boxes), dtype=bool)
        hit[tree.query(boxes, predicate="intersects")[0]] = True
        hit[on_lines.query(boxes, predicate="dwithin", distance=ticks.line_reach)[0]] = True
        if taken:
            others = _grown(taken, ticks.apart)
            hit |= shapely.intersects(boxes[:, None], others[None, :]).any(axis=1)
        crossed = np.zeros(len(boxes))
        crossed[on_curves.query(boxes, predicate="dwithin", distance=ticks.curve_reach)[0]] = 1.0
        if (crossed[~hit & ~outside] > 0).all():  # nowhere clear: the least of the curves
            if ink is None:  # once a view, not once a number
                ink = shapely.union_all(list(curves)).buffer(ticks.curve_reach)
            crossed[crossed > 0] = shapely.area(shapely.intersection(boxes[crossed > 0], ink))
        # the first that meets nothing; where none, the one that meets no line and no text
        # and crosses the least of the curves; in the view's box always (the nearest
        # under the tick is)
        k = int(np.lexsort((np.arange(len(boxes)), crossed, hit, outside))[0])
        out.append((translate(first, *moves[k]), boxes[k],
                    not (outside[k] or hit[k] or crossed[k])))
        taken.append(tried[k])
    return out
