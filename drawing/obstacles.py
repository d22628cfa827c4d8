"""What a label keeps clear of: the drawn items as shapes widened by their line's half
width and a clearance, the area of a box outside its region, and which texts overlap.

>>> overlaps([Text((0, 0), "AB"), Text((3, 0), "CD"), Text((50, 0), "EF")])
[(0, 1)]
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence

import shapely
from shapely.geometry import LineString, Polygon
from shapely.geometry.base import BaseGeometry

from drawing.scene import Arrow, Blank, Circle, Hatch, Item, Polyline, Segment, Text, flatten
from drawing.styles import Style
from drawing.text import text_box

__all__ = ["area_outside", "is_box", "obstacles_of", "overlaps"]


def is_box(g: BaseGeometry) -> bool:
    """An axis-parallel rectangle: its area is its bounds'."""
    x0, y0, x1, y1 = g.bounds
    return abs(g.area - (x1 - x0) * (y1 - y0)) <= 1e-9 * max(g.area, 1.0)


def area_outside(box: Polygon, region: BaseGeometry, region_box: bool) -> float:
    """The area of ``box`` outside ``region``: by bounds where both are axis-parallel
    rectangles (a label and a view's frame, some thousand times a sheet)."""
    if not (region_box and is_box(box)):
        return box.difference(region).area
    a0, b0, a1, b1 = box.bounds
    r0, s0, r1, s1 = region.bounds
    inside = max(0.0, min(a1, r1) - max(a0, r0)) * max(0.0, min(b1, s1) - max(b0, s0))
    return (a1 - a0) * (b1 - b0) - inside


def obstacles_of(
    items: Iterable[Item], style: Style | None = None, clearance: float = 0.3
) -> list[BaseGeometry]:
    """Geometry of drawn items, widened by half the line width + ``clearance`` mm.

    Lines become buffered strokes, an arrow its shaft and head, a circle its
    ring (its disc if filled), a text its box.
    """
    style = style or Style()
    out: list[BaseGeometry] = []
    for it in flatten(items):
        if isinstance(it, Text):
            out.append(text_box(it))
            continue
        if isinstance(it, Blank):  # white: nothing to keep clear of
            continue
        if isinstance(it, Hatch):
            lines = [LineString(s) for s in it.strokes()]
            half = style.width(it.line) / 2 + clearance
            out += [ln.buffer(half) for ln in lines]
            if it.base is not None:
                out.append(
                    LineString([it.p1, it.p2]).buffer(
                        style.width(it.base) / 2 + clearance
                    )
                )
            continue
        half = style.width(it.line) / 2 + clearance
        if isinstance(it, Segment):
            out.append(LineString([it.p1, it.p2]).buffer(half))
        elif isinstance(it, Polyline):
            pts = [*it.points, it.points[0]] if it.closed else list(it.points)
            out.append(LineString(pts).buffer(half))
        elif isinstance(it, Arrow):
            if (shaft := it.shaft()) is not None:
                out.append(LineString(shaft).buffer(half))
            if (head := it.head()) is not None:
                out.append(Polygon(head).buffer(clearance))
        elif isinstance(it, Circle):
            disc = shapely.Point(it.center).buffer(it.r)
            out.append(disc.buffer(half) if it.fill else disc.exterior.buffer(half))
    return out


def overlaps(texts: Sequence[Text], tolerance: float = 1e-6) -> list[tuple[int, int]]:
    """Pairs ``(i, j)``, i < j, of texts whose boxes share over ``tolerance`` mm².

    >>> overlaps([Text((0, 0), "AB"), Text((3, 0), "CD"), Text((50, 0), "EF")])
    [(0, 1)]
    """
    boxes = [text_box(t) for t in texts]
    if not boxes:
        return []
    tree = shapely.STRtree(boxes)
    left, right = tree.query(boxes, predicate="intersects")
    pairs = sorted(
        {(int(i), int(j)) for i, j in zip(left, right, strict=True) if i < j}
    )
    return [
        (i, j) for i, j in pairs if boxes[i].intersection(boxes[j]).area > tolerance
    ]
