"""Placing the views of a sheet: rectangles packed into the drawing area.

Each view is a box (0, 0)–(w, h) of local sheet mm (:class:`drawing.views.View`).
The free field is the frame less the title block and field 26, less ``MARGIN``;
views keep ``GAP`` mm from each other.  :func:`pack` puts boxes in, one after the
other, each at the topmost (or leftmost) spot where it meets nothing placed before
it: the spots tried are the corners the field and the boxes already placed make.
Several orders are tried (the order given, largest first, tallest first, widest
first), so that a set of views that fits one way is not refused for the order it
came in.  Nothing is scaled: what sizes the views is :mod:`drawing.cli_sheet`.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

from shapely.geometry import box

from drawing.scene import Group, Rect
from drawing.sheet import Sheet

__all__ = ["LayoutError", "Placed", "describe", "pack", "place_views", "share_covered",
           "share_used", "spread"]

GAP = 6.0
MARGIN = 4.0


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


Box = tuple[float, float, float, float]  # x0, y0, x1, y1


def field(sheet: Sheet) -> tuple[Box, list[Box]]:
    """The rectangle the views stay in, and the boxes they keep out of (the title block
    and field 26, widened by ``MARGIN``)."""
    f = sheet.frame
    inner = (f.x + MARGIN, f.y + MARGIN, f.x1 - MARGIN, f.y1 - MARGIN)
    out = [(r.x - MARGIN, r.y - MARGIN, r.x1 + MARGIN, r.y1 + MARGIN)
           for r in (sheet.title_block, sheet.field26)]
    return inner, out


def _first_fit(inner: Box, blocked: list[Box], sizes: Sequence[tuple[float, float]],
               order: Sequence[int], rows: bool) -> list[tuple[float, float]] | None:
    """Spots for the boxes ``sizes`` put in ``order``, each at the topmost then leftmost
    free spot (``rows``) or the leftmost then topmost one; None if one has none."""
    x0, y0, x1, y1 = inner
    hard = list(blocked)  # obstacles, exact
    wide: list[Box] = []  # boxes placed, widened by GAP
    spots: list[tuple[float, float] | None] = [None] * len(sizes)
    for i in order:
        w, h = sizes[i]
        if w > x1 - x0 + 1e-9 or h > y1 - y0 + 1e-9:
            return None
        edges = [*hard, *wide]
        xs = sorted(x for x in {x0, x1 - w, *(b[2] for b in edges), *(b[0] - w for b in edges)}
                    if x0 - 1e-9 <= x and x + w <= x1 + 1e-9)
        ys = sorted(y for y in {y0, y1 - h, *(b[3] for b in edges), *(b[1] - h for b in edges)}
                    if y0 - 1e-9 <= y and y + h <= y1 + 1e-9)
        best = None
        for a in (ys if rows else xs):
            for b in (xs if rows else ys):
                x, y = (b, a) if rows else (a, b)
                if not any(x < e[2] - 1e-9 and e[0] < x + w - 1e-9 and y < e[3] - 1e-9
                           and e[1] < y + h - 1e-9 for e in edges):
                    best = (x, y)
                    break
            if best is not None:
                break
        if best is None:
            return None
        x, y = best
        spots[i] = (x, y)
        wide.append((x - GAP, y - GAP, x + w + GAP, y + h + GAP))
    return spots  # type: ignore[return-value]


def pack(sheet: Sheet, sizes: Sequence[tuple[float, float]]) -> list[tuple[float, float]] | None:
    """Top-left corners for boxes of ``sizes`` (w, h mm) on ``sheet``, none meeting
    another (``GAP`` apart) nor the title block and field 26; None if no order tried
    fits them all. The order given is tried first, so that the plan of positions, put
    first, is at the top left where it fits there."""
    inner, blocked = field(sheet)
    n = len(sizes)
    given = list(range(n))
    area = sorted(given, key=lambda i: -sizes[i][0] * sizes[i][1])
    tall = sorted(given, key=lambda i: (-sizes[i][1], -sizes[i][0]))
    wide = sorted(given, key=lambda i: (-sizes[i][0], -sizes[i][1]))
    first = [0, *(i for i in area if i)]  # the first view top left, then the largest
    tried = set()
    for order, rows in ((given, True), (given, False), (first, True), (first, False),
                        (area, True), (area, False), (tall, False), (wide, True),
                        (tall, True), (wide, False)):
        if (tuple(order), rows) in tried:
            continue
        tried.add((tuple(order), rows))
        spots = _first_fit(inner, blocked, sizes, order, rows)
        if spots is not None:
            return spots
    return None


def place_views(sheet: Sheet, views) -> list[Placed]:
    """Positions for ``views`` (see :func:`pack`); :class:`LayoutError` if they do not
    all fit."""
    spots = pack(sheet, [(v.w, v.h) for v in views])
    if spots is None:
        raise LayoutError(*_why_not(sheet, views))
    return [Placed(v, Rect(x, y, v.w, v.h)) for v, (x, y) in zip(views, spots, strict=True)]


def spread(sheet: Sheet, placed: list[Placed]) -> list[Placed]:
    """The views moved apart to use the whole field: each one's distance from the field's
    top edge stretched by one factor, as large as keeps every view inside the field and
    clear of the title block, then the same across from the left edge. Views apart stay
    apart (their gaps only grow), and none changes its size; a sheet whose views, at
    their largest, still leave room is not left with its lower half blank."""
    (x0, y0, x1, y1), (tb, _) = field(sheet)
    rects = [p.rect for p in placed]

    def most(starts, sizes, lo, hi, block, across):
        """The largest stretch of the ``starts`` away from ``lo`` keeping each box within
        ``hi``, or short of ``block`` (the title block's near edge) where its ``across``
        span meets the block's."""
        k = math.inf
        for a, size, (c0, c1) in zip(starts, sizes, across, strict=True):
            if a - lo <= 1e-9:
                continue
            limit = block[0] if c0 < block[2] and c1 > block[1] else hi
            k = min(k, (limit - size - lo) / (a - lo))
        return max(1.0, k) if k < math.inf else 1.0

    ky = most([r.y for r in rects], [r.h for r in rects], y0, y1, (tb[1], tb[0], tb[2]),
              [(r.x, r.x1) for r in rects])
    rects = [Rect(r.x, y0 + (r.y - y0) * ky, r.w, r.h) for r in rects]
    kx = most([r.x for r in rects], [r.w for r in rects], x0, x1, (tb[0], tb[1], tb[3]),
              [(r.y, r.y1) for r in rects])
    rects = [Rect(x0 + (r.x - x0) * kx, r.y, r.w, r.h) for r in rects]
    return [Placed(p.view, r) for p, r in zip(placed, rects, strict=True)]


def share_used(sheet: Sheet, placed: list[Placed]) -> float:
    """The share of the sheet's free field that the views' bounding box covers: about 0.7
    on a well-filled sheet, under 0.3 where fixed small scales leave most of it empty."""
    if not placed:
        return 0.0
    xs0, ys0, xs1, ys1 = zip(*(p.rect.bounds for p in placed), strict=True)
    used = box(min(xs0), min(ys0), max(xs1), max(ys1))
    area = sheet.drawing_area()
    return used.intersection(area).area / area.area


def share_covered(sheet: Sheet, placed: list[Placed]) -> float:
    """The share of the sheet's free field that the views' own boxes cover (they do not
    overlap): what the drawings, tables and their captions take of the sheet."""
    return sum(p.rect.w * p.rect.h for p in placed) / sheet.drawing_area().area


def describe(view) -> str:
    """A view as the user knows it: "the velocity plan of position 2"."""
    kind, _, tag = view.name.partition("-")
    of = "" if tag in ("", "g") else f" of position {tag}"
    words = {"positions": "the plan of positions", "velocity": "the velocity plan",
             "acceleration": "the acceleration plan", "diagrams": "the kinematic diagrams",
             "segments": "the table of plan segments", "angular": "the table of ω and ε",
             "note": "the note"}
    return words.get(kind, f"the view {view.name!r}") + of


def _why_not(sheet: Sheet, views) -> tuple[str, str]:
    """Why the views found no place, and the option to change (see
    :class:`LayoutError`)."""
    x0, y0, x1, y1 = Sheet("A0").drawing_area().bounds
    for v in views:
        size = f"{describe(v)} ({v.w:.0f} × {v.h:.0f} mm)"
        if min(v.w, v.h) > min(x1 - x0, y1 - y0) or max(v.w, v.h) > max(x1 - x0, y1 - y0):
            if v.name == "positions":  # the sheet's own μl always fits: the file fixed it
                return (f"{size} is larger than any sheet, A0 included, at the μl the file "
                        "fixes: give a larger mu_l in [scales], or leave it out for the sheet "
                        "to choose"), ""
            return (f"{size} is larger than any sheet, A0 included, at the scale factors the "
                    "file fixes: give larger mu_v and mu_a in [scales] (or leave them out for "
                    "the sheet to choose), or choose other --plans"), "--plans"
    need = ", ".join(f"{describe(v)} {v.w:.0f} × {v.h:.0f} mm" for v in views)
    return (f"the views do not fit together on {room(sheet)} ({need}): take a larger "
            "--format"), "--format"


def room(sheet: Sheet) -> str:
    """The sheet's room in words: "A4, whose frame is 185 × 287 mm with the 185 × 55 mm
    title block in it"."""
    f, tb = sheet.frame, sheet.title_block
    return (f"{sheet.name}, whose frame is {f.w:.0f} × {f.h:.0f} mm with the {tb.w:.0f} × "
            f"{tb.h:.0f} mm title block in it")
