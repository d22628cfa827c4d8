"""Placing the views of a sheet: first fit on a 5 mm grid inside the drawing area.

Each view is a box (0, 0)–(w, h) of local sheet mm (:class:`drawing.views.View`).
A view is put at the first grid position, top to bottom and left to right,
where its box, widened by ``GAP``, stays inside the free field of the sheet
(frame less the title block and field 26, less ``MARGIN``) and meets no box
placed before it.  Nothing is scaled.
"""

from __future__ import annotations

from dataclasses import dataclass

from shapely.geometry import box
from shapely.prepared import prep

from drawing.scene import Group, Rect
from drawing.sheet import Sheet

__all__ = ["LayoutError", "Placed", "place_views", "share_used"]

GAP = 6.0
MARGIN = 4.0
STEP = 5.0


class LayoutError(ValueError):
    """A view does not fit on the sheet. ``option``: what to change, "--format" for a
    full sheet, "--plans" for a plan no sheet holds, "" where the mechanism itself is
    the cause (its plan of positions larger than any sheet)."""

    def __init__(self, message: str, option: str = "--format"):
        super().__init__(message)
        self.option = option


@dataclass(frozen=True)
class Placed:
    view: object
    rect: Rect

    def group(self) -> Group:
        return Group(tuple(self.view.items), (self.rect.x, self.rect.y), name=f"view {self.view.name}")


def place_views(sheet: Sheet, views) -> list[Placed]:
    """Positions for ``views`` in their order, each at the first free spot scanning the
    sheet row by row; :class:`LayoutError` if one does not fit.

    The boxes placed are kept widened by ``GAP``, so that a candidate is tested against
    them by plain arithmetic (touching counts as meeting); only a spot clear of them is
    tested against the free field with shapely."""
    area = sheet.drawing_area().buffer(-MARGIN)
    free = prep(area)
    x0, y0, x1, y1 = area.bounds
    placed: list[Placed] = []
    wide: list[tuple[float, float, float, float]] = []
    for v in views:
        spot = None
        xs = [x0 + STEP * i for i in range(int((x1 - x0 - v.w) / STEP) + 1)]
        ys = [y0 + STEP * j for j in range(int((y1 - y0 - v.h) / STEP) + 1)]
        for x, y in ((x, y) for y in ys for x in xs):
            if any(x <= bx1 and bx0 <= x + v.w and y <= by1 and by0 <= y + v.h
                   for bx0, by0, bx1, by1 in wide):
                continue
            if free.contains(box(x, y, x + v.w, y + v.h)):
                spot = (x, y)
                break
        if spot is None:
            raise LayoutError(*_why_not(sheet, v))
        r = Rect(spot[0], spot[1], v.w, v.h)
        placed.append(Placed(v, r))
        bx0, by0, bx1, by1 = r.bounds
        wide.append((bx0 - GAP, by0 - GAP, bx1 + GAP, by1 + GAP))
    return placed


def share_used(sheet: Sheet, placed: list[Placed]) -> float:
    """The share of the sheet's free field that the views' bounding box covers: about 0.7
    on a well-filled sheet, under 0.3 where fixed small scales leave most of it empty."""
    if not placed:
        return 0.0
    xs0, ys0, xs1, ys1 = zip(*(p.rect.bounds for p in placed), strict=True)
    used = box(min(xs0), min(ys0), max(xs1), max(ys1))
    area = sheet.drawing_area()
    return used.intersection(area).area / area.area


def _why_not(sheet: Sheet, v) -> tuple[str, str]:
    """Why a view found no place, and the option to change (see :class:`LayoutError`)."""
    size = f"the view {v.name!r} ({v.w:.0f} × {v.h:.0f} mm)"
    x0, y0, x1, y1 = Sheet("A0").drawing_area().bounds
    if min(v.w, v.h) > min(x1 - x0, y1 - y0) or max(v.w, v.h) > max(x1 - x0, y1 - y0):
        if v.name == "positions":  # the sheet's own μl always fits: the file fixed it
            return (f"{size} is larger than any sheet, A0 included, at the μl the file "
                    "fixes: give a larger mu_l in [scales], or leave it out for the sheet "
                    "to choose"), ""
        return (f"{size} is larger than any sheet, A0 included: the plans' scale factors "
                "are chosen at the given position, and this position needs far larger ones; "
                "choose other --plans or give mu_v and mu_a in [scales]"), "--plans"
    return (f"{size} does not fit on {sheet.name} beside the others; try a larger --format "
            "or fewer --plans"), "--format"
