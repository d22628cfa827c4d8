"""The kinematic diagrams' numbers of positions: clear of the axes, the curves and the
other texts, each by its tick, and the view no larger for where they stand."""

from __future__ import annotations

from functools import cache

import pytest

from drawing.obstacles import obstacles_of
from drawing.scene import Arrow, Polyline, Segment, Text, flatten
from drawing.sheet1 import DIAGRAMS, build_sheet
from drawing.text import text_box
from drawing.views import NUMBER_GAPS, WORDS, diagrams_view
from plans.cycle import analyse_cycle
from plans.model.scenes import SCENES
from plans.model.variants import variant

#: the curves of these cross the φ axis at or beside a tick (v and a of a crank-slider
#: at its middle position, ε of a rotating slotted link just under the axis from the
#: origin on), where a number under its tick stood on the curve
MECHANISMS = ("variant 2", "variant 4", "press", "slotted_rotating", "crank_slider_central")


def _mech(name: str):
    """A built-in variant ("variant 2") or scene ("press") by name."""
    return variant(int(name.split()[1])) if name.startswith("variant") else SCENES[name].mechanism()


@cache
def _view(name: str, width: float, lang: str = "ru"):
    mech = _mech(name)
    return diagrams_view(mech, analyse_cycle(mech), lang, width, DIAGRAMS[width])


def _parts(view):
    """(the numbers of positions, each with its tick (x, y of the φ axis)), the other
    texts, the vertical axes, the curves) of a diagrams view."""
    items = flatten(view.items)
    ticks = [s for s in items if isinstance(s, Segment) and s.p1[0] == s.p2[0]
             and abs(abs(s.p2[1] - s.p1[1]) - 2.0) < 1e-9]
    numbers, texts = [], []
    for t in (it for it in items if isinstance(it, Text)):
        if t.size == 2.5 and t.text.isdigit():
            (x0, y0, x1, y1) = text_box(t).bounds
            tick = min(ticks, key=lambda s: abs(s.p1[0] - (x0 + x1) / 2)
                       + abs((s.p1[1] + s.p2[1]) / 2 - (y0 + y1) / 2))
            numbers.append((t, (tick.p1[0], (tick.p1[1] + tick.p2[1]) / 2)))
        else:
            texts.append(t)
    axes = [a for a in items if isinstance(a, Arrow)]
    curves = [c for c in items if isinstance(c, Polyline)]
    return numbers, texts, axes, curves


@pytest.mark.parametrize("name", MECHANISMS)
def test_the_origins_zero_stands_beside_the_vertical_axis_not_across_it(name):
    """The 0 at each diagram's origin was centred on the vertical axis, the axis drawn
    through it. It now stands right of the axis, at the origin."""
    for width in (180.0, 120.0):
        numbers, _, axes, _ = _parts(_view(name, width))
        lines = obstacles_of(axes, clearance=0.0)
        assert len(axes) == 3
        for t, _ in numbers:
            assert not any(text_box(t).intersects(g) for g in lines), (t.text, width)
        origins = [(t, tick) for t, tick in numbers if tick[0] == axes[0].p1[0]]
        assert [t.text for t, _ in origins] == ["0"] * 3
        for t, (x, y) in origins:
            x0, y0, _x1, y1 = text_box(t).bounds
            assert x < x0 < x + 1.0 and (y0 > y or y1 < y), (width, text_box(t).bounds)


@pytest.mark.parametrize("width", [240.0, 120.0])
@pytest.mark.parametrize("name", MECHANISMS)
def test_no_number_of_a_position_crosses_a_curve(name, width):
    """A number stood under its tick whatever ran there: where a curve ran under the φ
    axis (v or a of a slider after its middle position) it went through the number. Each
    now stands clear of the curves and of every other text, over or beside its tick
    where the curve takes the room under it."""
    numbers, texts, _, curves = _parts(_view(name, width, "en"))
    strokes = obstacles_of(curves, clearance=0.0)
    boxes = [text_box(t) for t, _ in numbers]
    for (t, (x, y)), box in zip(numbers, boxes, strict=True):
        assert not any(box.intersects(g) for g in strokes), (t.text, x)
        assert not any(box.intersects(text_box(o)) for o in texts), t.text
        assert not any(box.intersects(b) for b in boxes if b is not box), t.text
        # by its own tick: across it or within a millimetre of it, close to the axis
        x0, y0, x1, y1 = box.bounds
        assert x0 - 1.0 <= x <= x1 + 1.0, (t.text, x, box.bounds)
        assert min(abs(y0 - y), abs(y1 - y)) <= NUMBER_GAPS[-1] + 1e-9, (t.text, box.bounds)


@pytest.mark.parametrize("name", MECHANISMS[:3])
def test_the_view_keeps_the_box_it_has_with_every_number_under_its_tick(name):
    """The numbers move within the box the drawing has with each of them under its tick,
    so that the view is the size it was: a view 0.75 mm narrower (the origin's 0 no
    longer reaching left of the axis) repacked variant 5's English A2 sheet with its
    diagrams a step smaller."""
    view = _view(name, 180.0)
    numbers, _, _, _ = _parts(view)
    under = [Text((x, y + NUMBER_GAPS[0]), t.text, size=2.5, anchor="middle",
                  baseline="hanging") for t, (x, y) in numbers]
    rest = [it for it in flatten(view.items) if not isinstance(it, Text)
            or not (it.text.isdigit() or it.text.startswith(WORDS["ru"]["diagrams"]))]
    xs, ys = [], []
    for it in rest + under:
        if isinstance(it, Text):
            x0, y0, x1, y1 = text_box(it).bounds
            xs += [x0, x1]
            ys += [y0, y1]
        elif isinstance(it, Polyline):
            xs += [p[0] for p in it.points]
            ys += [p[1] for p in it.points]
        else:
            xs += [it.p1[0], it.p2[0]]
            ys += [it.p1[1], it.p2[1]]
    assert view.body == pytest.approx((max(xs) - min(xs), max(ys) - min(ys)), abs=1e-9)
    _, _, info = build_sheet(variant(5), "A2", "en")
    (placed,) = [p for p in info["placed"] if p.view.name == "diagrams"]
    assert placed.rect.w > 240.0  # the 240 mm diagrams


@pytest.mark.parametrize("width", [120.0, 180.0])
@pytest.mark.parametrize("name", ["variant 2", "press"])
def test_dense_positions_number_fewer_ticks_and_none_collides(name, width):
    """72 positions on a 120 mm diagram put ticks 1.7 mm apart: every second tick's two
    digits ran into the next number and onto the curves. Ticks are numbered every
    fourth, sixth … position there, as far apart as a number is wide and a gap."""
    mech = _mech(name)
    view = diagrams_view(mech, analyse_cycle(mech, 72), "ru", width, DIAGRAMS[width])
    numbers, _, _, curves = _parts(view)
    strokes = obstacles_of(curves, clearance=0.0)
    boxes = [text_box(t) for t, _ in numbers]
    for (t, _), box in zip(numbers, boxes, strict=True):
        assert not any(box.intersects(g) for g in strokes), (t.text, width)
        assert not any(box.intersects(b) for b in boxes if b is not box), (t.text, width)
    shown = sorted({int(t.text) for t, _ in numbers})
    step = shown[1] - shown[0]
    assert shown == list(range(0, 72, step))  # evenly, from position 0
    assert step == (4 if width == 120.0 else 2)  # as close as the numbers allow
