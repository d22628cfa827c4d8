"""The synthesis sheet: the graphical construction as the textbooks draw it, at a GOST
scale factor μl that makes it large on the sheet, beside the family's figure of merit over
its free parameter and the table of results with the engine's check, in the GOST frame
with the title block (:mod:`drawing.sheet.frame`).

``plans synth --svg`` (:mod:`plans.cli.synth`) is the command around it.
"""

from __future__ import annotations

from drawing.scene import Layer, Scene
from drawing.sheet.frame import Sheet, frame_scene
from drawing.sheet.layout import LayoutError, Placed, place_views, spread
from drawing.sheet1 import FIELDS, title_block
from drawing.svg import to_svg
from drawing.views.construction import construction_view, extent, family_view, results_view
from plans.scales import GOST_MU_L, gost_scale, series

__all__ = ["FIELDS", "build", "choose_mu_l", "render"]

#: the share of the sheet's free field the construction may take, across and down, at
#: most: where the other views do not fit beside it, the next GOST μl is taken
SHARE = (0.72, 0.85)


def choose_mu_l(design, check, sheet: Sheet) -> float:
    """The smallest GOST μl (m/mm) at which the construction fits its share of the field
    (:data:`SHARE`), with room for its letters: the first :func:`build` tries."""
    x0, y0, x1, y1 = extent(design, check)
    f = sheet.frame
    room_w = (f.w - 10) * SHARE[0] - 20
    room_h = (f.h - 10) * SHARE[1] - 30
    need = max((x1 - x0) / room_w, (y1 - y0) / room_h)
    for mu in GOST_MU_L:
        if mu >= need:
            return mu
    return next(series(need, need * 10))


def build(design, check, fmt: str = "A3", lang: str = "ru", title=()) -> tuple[Scene, Sheet, float]:
    """(scene, sheet, μl): the views placed in the frame with the title block, the title
    block's scale that of the construction."""
    sheet = Sheet(fmt)
    first = choose_mu_l(design, check, sheet)
    tries = [mu for mu in GOST_MU_L if mu >= first] or [first]
    for k, mu_l in enumerate(tries):
        views = [construction_view(design, check, mu_l, lang)]
        if (fam := family_view(design, lang)) is not None:
            views.append(fam)
        views.append(results_view(design, check, mu_l, lang))
        try:
            placed: list[Placed] = spread(sheet, place_views(sheet, views))
            break
        except LayoutError:
            if k == len(tries) - 1:
                raise
    tb = title_block(check.mechanism, sheet, list(title), gost_scale(mu_l, lang), lang)
    scene = frame_scene(sheet, tb, lang=lang)
    scene = scene + Scene((Layer("views", tuple(p.group() for p in placed)),))
    return scene, sheet, mu_l


def render(design, check, fmt: str = "A3", lang: str = "ru", title=()) -> str:
    """The sheet's SVG."""
    scene, sheet, _ = build(design, check, fmt, lang, title)
    return to_svg(scene, sheet, title=check.mechanism.name_in(lang))
