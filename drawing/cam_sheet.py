"""The cam sheet of the course project: the follower's s, v, a diagrams, the phase portrait
with the pressure-angle limits and the chosen centre, the profile built by inversion with
its numbered rays, the tables of the phases and of the profile's coordinates, in the GOST
frame with its title block (as sheets 1 and 2).

The views are drawn as large as the format holds: each is sized for the sheet, then all
are stepped down together until they pack (:func:`drawing.sheet.layout.place_views`);
the title block's scale is the profile's.
"""

from __future__ import annotations

from drawing.scene import Layer, Rect, Scene
from drawing.sheet.frame import Sheet, frame_scene
from drawing.sheet.layout import GAP, MARGIN, LayoutError, Placed, field, place_views, room, spread
from drawing.sheet1 import title_block
from drawing.svg import to_svg
from drawing.views import retitled
from drawing.views.cam import (
    cam_diagrams_view,
    construction_scale,
    construction_view,
    limit_view,
    phases_view,
    portrait_view,
    profile_table_view,
)
from plans.scales import gost_scale

__all__ = ["SIZES", "STEPS", "build", "columns", "render", "views"]

#: mm: the views' sizes on each format (the profile's circle, the portrait, the diagrams'
#: width and each diagram's height), tried largest first
SIZES = {
    "A1": (420.0, 200.0, 330.0, 55.0),
    "A2": (230.0, 140.0, 220.0, 40.0),
    "A3": (165.0, 100.0, 160.0, 28.0),
}
#: the factors the sizes are stepped down by until the views pack
STEPS = (1.0, 0.85, 0.7, 0.55)


def views(d, fmt: str, lang: str, k: float = 1.0) -> list:
    """The sheet's views other than the construction, at ``k`` times the format's sizes:
    the phase portrait (or the limit's diagram), the motion diagrams, the profile's table,
    the phases' table; each title 5 mm, a long one on two lines."""
    _, port, width, height = (x * k for x in SIZES[fmt])
    out = []
    if d.portrait is not None and not d.cam.follower.flat:
        out.append(portrait_view(d, lang, port))
    else:
        out.append(limit_view(d, lang, width * 0.75, height))
    out.append(cam_diagrams_view(d, lang, width, height))
    out.append(profile_table_view(d, lang))
    out.append(phases_view(d, lang))
    return [retitled(v, "wrap") for v in out]


def columns(sheet: Sheet, vs: list) -> list[Placed] | None:
    """The sheet as it is drawn by hand: the construction with the two tables under it
    on the left, the portrait over the diagrams on the right, each column's views spread
    down its height (the right one's above the title block); None where they do not fit
    so."""
    construction, portrait, diagrams, table, phases = vs
    (x0, y0, x1, y1), _ = field(sheet)
    top_of_block = sheet.title_block.y - MARGIN
    tables_w = table.w + GAP + phases.w
    left_w = max(construction.w, tables_w)
    right_w = max(portrait.w, diagrams.w)
    if left_w + GAP + right_w > x1 - x0:
        return None
    left_h = construction.h + GAP + max(table.h, phases.h)
    right_h = portrait.h + GAP + diagrams.h
    if left_h > y1 - y0 or right_h > top_of_block - y0:
        return None
    # the columns apart by what the width leaves, each centred in its share
    free = (x1 - x0) - left_w - right_w
    lx = x0 + free / 4
    rx = x1 - right_w - free / 4
    out = [Placed(construction, Rect(lx + (left_w - construction.w) / 2, y0, construction.w, construction.h))]
    ty = y0 + construction.h + max(GAP, (y1 - y0 - left_h) / 2)
    tx = lx + (left_w - tables_w) / 2
    out.append(Placed(table, Rect(tx, ty, table.w, table.h)))
    out.append(Placed(phases, Rect(tx + table.w + GAP, ty, phases.w, phases.h)))
    py = y0
    dy = py + portrait.h + max(GAP, (top_of_block - y0 - right_h) / 2)
    out.append(Placed(portrait, Rect(rx + (right_w - portrait.w) / 2, py, portrait.w, portrait.h)))
    out.append(Placed(diagrams, Rect(rx + (right_w - diagrams.w) / 2, dy, diagrams.w, diagrams.h)))
    return out


def build(d, fmt: str = "A1", lang: str = "ru", title=()):
    """(scene, sheet, the construction's μl) of the cam sheet of the design ``d``: the
    construction as large as the sheet holds, then the other views as large as they fit
    beside it, in :func:`columns` where they fit so, else packed
    (:func:`drawing.sheet.layout.place_views`)."""
    sheet = Sheet(fmt)
    constructions = {}  # by μl: one view for the sizes that come to the same scale
    for k in STEPS:
        mu = construction_scale(d, SIZES[fmt][0] * k)
        if mu not in constructions:
            constructions[mu] = retitled(construction_view(d, lang, SIZES[fmt][0] * k), "wrap")
    others: dict[float, list] = {}

    def other(k: float) -> list:  # drawn when first tried
        if k not in others:
            others[k] = views(d, fmt, lang, k)
        return others[k]

    tries = ((arrange, mu, cons, k) for arrange in (columns, _packed)
             for mu, cons in constructions.items() for k in STEPS)
    placed, mu = None, None
    for arrange, scale, cons, k in tries:
        placed, mu = arrange(sheet, [cons, *other(k)]), scale
        if placed is not None:
            break
    if placed is None:
        bigger = {"A3": "A2", "A2": "A1"}.get(fmt)
        smallest = [list(constructions.values())[-1], *other(STEPS[-1])]
        need = ", ".join(f"{v.name} {v.w:.0f} × {v.h:.0f} mm" for v in smallest)
        raise LayoutError(f"the cam sheet does not fit on {room(sheet)} (its views at their smallest: {need})"
                          + (f": use --format {bigger}" if bigger else ""))
    tb = title_block(d.cam, sheet, title, gost_scale(mu, lang), lang)
    scene = frame_scene(sheet, tb, lang=lang) + Scene((Layer("views", tuple(p.group() for p in placed)),))
    return scene, sheet, mu


def _packed(sheet: Sheet, vs: list) -> list[Placed] | None:
    try:
        return spread(sheet, place_views(sheet, vs))
    except LayoutError:
        return None


def render(d, fmt: str = "A1", lang: str = "ru", title=()) -> str:
    """The cam sheet of the design ``d`` as SVG."""
    scene, sheet, _ = build(d, fmt, lang, title)
    return to_svg(scene, sheet, title=d.cam.name_in(lang))
