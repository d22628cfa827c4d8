"""Views spread evenly over a sheet's field (:func:`balance`): sheet 1's views at free
scales, which at their largest still leave room, each set in the middle of the room
around it rather than packed to the field's top left."""

from __future__ import annotations

import math
from collections.abc import Sequence

from drawing.scene import Rect
from drawing.sheet.frame import Sheet
from drawing.sheet.layout import GAP, Placed, field, pairs_of, unit_sizes

__all__ = ["balance"]


def balance(sheet: Sheet, placed: list[Placed], together: Sequence[tuple[str, str]] = (),
            rounds: int = 60) -> list[Placed]:
    """The views moved to spread evenly over the field: down the sheet, each view (a pair
    kept ``together`` moves as one box) to the middle of the room between the views or
    edges above and below it that share some of its width, until the gaps settle equal;
    then across, each to the middle of the room beside it. A column of views stands with
    equal gaps from the field's top edge to its bottom (or the title block), so no band
    across the sheet is left blank while one column has room; views keep their order
    along each line, do not meet, and none changes its size."""
    (x0, y0, x1, y1), blocked = field(sheet)
    names = [p.view.name for p in placed]
    _, units = unit_sizes([(p.rect.w, p.rect.h) for p in placed], pairs_of(names, together))
    rects = [p.rect for p in placed]

    def bounds(i):  # x0, y0, x1, y1 of a view
        r = rects[i]
        return (r.x, r.y, r.x1, r.y1)

    def settle(axis: int) -> None:
        lo_edge, hi_edge = (y0, y1) if axis else (x0, x1)
        for _ in range(rounds):
            moved = 0.0
            for k, unit in enumerate(units):
                # the shifts along the axis that keep each view of the unit clear of the
                # views of the others across from it, GAP apart, of the title block and
                # inside the field: the unit goes to the middle of them
                least, most = -math.inf, math.inf
                others = [(bounds(i), GAP) for j, u in enumerate(units) if j != k for i in u]
                others += [(o, 0.0) for o in blocked]
                for i in unit:
                    b = bounds(i)
                    least, most = max(least, lo_edge - b[axis]), min(most, hi_edge - b[axis + 2])
                    for o, gap in others:
                        # across from it: nearer than ``gap`` across the axis (two views
                        # GAP apart one way may come near the other way)
                        if (o[1 - axis] >= b[3 - axis] + gap - 1e-9
                                or o[3 - axis] <= b[1 - axis] - gap + 1e-9):
                            continue
                        if o[axis + 2] <= b[axis] + 1e-9:
                            least = max(least, o[axis + 2] + gap - b[axis])
                        elif o[axis] >= b[axis + 2] - 1e-9:
                            most = min(most, o[axis] - gap - b[axis + 2])
                shift = (least + most) / 2
                if least > most + 1e-9 or abs(shift) < 1e-6:
                    continue
                for i in unit:
                    r = rects[i]
                    rects[i] = Rect(r.x + (0.0 if axis else shift), r.y + (shift if axis else 0.0), r.w, r.h)
                moved = max(moved, abs(shift))
            if moved < 0.05:
                return

    settle(1)
    settle(0)
    return [Placed(p.view, r) for p, r in zip(placed, rects, strict=True)]
