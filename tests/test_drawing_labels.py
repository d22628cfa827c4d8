"""Text extents, fitting into cells (drawing.text) and label placement (drawing.labels)."""

import math

import pytest
import shapely
from hypothesis import given, settings
from hypothesis import strategies as st
from shapely.geometry import LineString, box

from drawing.labels import LabelRequest, place_labels
from drawing.obstacles import obstacles_of, overlaps
from drawing.scene import Arrow, Circle, Rect, Segment, Text
from drawing.styles import LineType, Style
from drawing.text import fit_text, text_box, text_width


def test_text_width_follows_the_fixed_rule():
    # И 0.6 + з 0.5 + м 0.65 (wide) + . 0.3, plus 3 letter spacings of 0.2
    assert text_width("Изм.", 2.5) == pytest.approx(
        2.5 * (0.6 + 0.5 + 0.65 + 0.3 + 0.6)
    )
    assert text_width("ДД", 10) == pytest.approx(14.0)  # Cyrillic capitals 0.6
    assert text_width("AB", 10) == pytest.approx(16.0)  # Latin capitals 0.7
    assert text_width("ab", 10) == pytest.approx(14.0)  # Latin lowercase 0.6
    assert text_width("дд", 10) == pytest.approx(12.0)  # Cyrillic lowercase 0.5
    assert text_width("a b", 10) == pytest.approx(10 * (0.6 + 0.3 + 0.6 + 0.4))
    assert text_width("Ш", 5) == pytest.approx(4.5)  # wide capital
    assert text_width("23", 10) == pytest.approx(14.0)  # digits 0.6
    assert text_width("1-", 10) == pytest.approx(9.5)  # narrow 1 (0.3), hyphen 0.45
    assert text_width("", 5) == 0.0


def test_text_box_honours_anchor_and_baseline():
    t = Text((100, 50), "ДД", size=10, italic=False)  # 14 wide, 10 above the baseline, 3 below
    assert text_box(t).bounds == pytest.approx((100, 40, 114, 53))
    assert text_box(
        Text((100, 50), "ДД", size=10, anchor="middle", italic=False)
    ).bounds == pytest.approx((93, 40, 107, 53))
    assert text_box(
        Text((100, 50), "ДД", size=10, anchor="end", italic=False)
    ).bounds == pytest.approx((86, 40, 100, 53))
    assert text_box(
        Text((100, 50), "ДД", size=10, baseline="middle", italic=False)
    ).bounds == pytest.approx((100, 45, 114, 58))
    assert text_box(
        Text((100, 50), "ДД", size=10, baseline="hanging", italic=False)
    ).bounds == pytest.approx((100, 50, 114, 63))


def test_text_box_honours_rotation():
    # 90° clockwise on the sheet: the text runs downwards from pos
    b = text_box(Text((0, 0), "ДД", size=10, rotate_deg=90, italic=False)).bounds
    assert b == pytest.approx((-3, 0, 10, 14))
    # 180°: upside down about pos
    b = text_box(Text((0, 0), "ДД", size=10, rotate_deg=180, italic=False)).bounds
    assert b == pytest.approx((-14, -3, 0, 10))


def test_a_slanted_texts_box_takes_in_the_lean_of_its_letters():
    """GOST type B leans 75°: the top of the last letter stands h·tan 15° right of its
    advance; a label placed by the upright box touched the line beside it."""
    upright = text_box(Text((100, 50), "ДД", size=10, italic=False)).bounds
    slanted = text_box(Text((100, 50), "ДД", size=10)).bounds
    assert slanted[:2] == upright[:2] and slanted[3] == upright[3]
    assert slanted[2] - upright[2] == pytest.approx(10 * math.tan(math.radians(15)))


def test_fit_text_takes_the_largest_size_that_fits():
    cell = Rect(0, 0, 70, 25)
    (line,) = fit_text("Механизм", cell, sizes=(7, 5, 3.5, 2.5))
    assert line.size == 7
    assert line.anchor == "middle" and line.pos[0] == pytest.approx(35)


def test_fit_text_wraps_to_two_lines_before_shrinking():
    # one line would need 2.5 mm (74 mm wide); two lines fit at 5 mm (76.5 mm)
    cell = Rect(0, 0, 80, 25)
    text = "Кинематический анализ рычажного механизма"
    lines = fit_text(text, cell, sizes=(7, 5, 3.5, 2.5), max_lines=2)
    assert len(lines) == 2
    assert " ".join(t.text for t in lines) == text
    assert lines[0].size == lines[1].size == 5
    assert lines[1].pos[1] - lines[0].pos[1] == pytest.approx(
        1.7 * 5
    )  # GOST type B line pitch
    for t in lines:
        assert box(*cell.bounds).contains(text_box(t))


def test_fit_text_shrinks_below_the_smallest_size_rather_than_overflow():
    cell = Rect(10, 10, 10, 5)
    (t,) = fit_text("21.11.2025", cell, sizes=(2.5,))
    assert t.size < 2.5
    assert box(*cell.bounds).contains(text_box(t))


def test_fit_text_start_alignment_keeps_the_inset():
    (t,) = fit_text(
        "Разраб.", Rect(0, 0, 17, 5), sizes=(2.5,), align="start", inset=0.7
    )
    assert t.pos == pytest.approx((0.7, 2.5 + 1.25))  # capitals centred on the row
    assert fit_text("", Rect(0, 0, 17, 5)) == ()


def test_label_avoids_a_line_through_the_preferred_place():
    anchor = (50.0, 50.0)
    # a thick line leaving the point to the north-east, right where "ne" would go
    line = Segment(anchor, (80, 20), LineType.MAIN)
    obstacles = obstacles_of([line])
    free = place_labels([LabelRequest(anchor, "b", 3.5, prefer="e")], obstacles)
    blocked = place_labels([LabelRequest(anchor, "b", 3.5, prefer="ne")], obstacles)
    assert free[0].clear and blocked[0].clear
    assert not blocked[0].box.intersects(obstacles[0])
    # "ne" was taken by the line; the label went next door, still 1 mm from the point
    ne_box = text_box(
        Text((50 + math.sqrt(0.5), 50 - math.sqrt(0.5) - 1.05), "b", size=3.5)
    )
    assert ne_box.intersects(obstacles[0])
    assert blocked[0].box.distance(shapely.Point(anchor)) == pytest.approx(
        1.0, abs=0.01
    )
    assert blocked[0].box.centroid.x > 50  # clockwise neighbour "e" first


def test_a_label_with_further_anchors_goes_to_the_first_free_one():
    """A dimension's value may stand anywhere along its arc: when every spot around the
    first anchor is blocked, it goes next to the first further anchor that is free, and
    not next to a later one."""
    first, second, third = (20.0, 20.0), (60.0, 20.0), (100.0, 20.0)
    walls = [box(first[0] - 15, first[1] - 15, first[0] + 15, first[1] + 15)]  # all round
    req = LabelRequest(first, "ψ = 39,04°", 3.5, "n", markup=False, also=(second, third))
    (got,) = place_labels([req], walls)
    assert got.clear and not got.box.intersects(walls[0])
    assert got.box.distance(shapely.Point(second)) == pytest.approx(1.0, abs=0.01)
    assert got.box.centroid.y < second[1]  # "n" of it, as preferred
    (alone,) = place_labels([LabelRequest(first, "ψ = 39,04°", 3.5, "n", markup=False)], walls)
    assert not alone.clear  # the same label with one anchor had nowhere to go


def test_labels_avoid_each_other_and_the_taken_boxes():
    anchor = (20.0, 20.0)
    taken = [text_box(Text((21, 18.95), "XX", size=3.5))]  # sits where "ne" would go
    reqs = [
        LabelRequest(anchor, name, 3.5, prefer="ne") for name in ("a", "b", "c", "d")
    ]
    placed = place_labels(reqs, obstacles=[], taken=taken, distances=(1.0, 2.0, 3.0, 4.5))
    assert all(p.clear for p in placed)
    assert overlaps([p.text for p in placed]) == []
    assert not any(p.box.intersects(taken[0]) for p in placed)


def test_label_stays_inside_the_region_and_reports_failure():
    region = box(0, 0, 100, 100)
    (p,) = place_labels(
        [LabelRequest((99.5, 0.5), "long label", 3.5, prefer="ne")], region=region
    )
    assert p.clear and region.contains(p.box)
    # a point boxed in on every side: the least bad candidate comes back, flagged
    wall = (
        shapely.Point(50, 50).buffer(30).difference(shapely.Point(50, 50).buffer(0.5))
    )
    (q,) = place_labels([LabelRequest((50, 50), "c", 3.5)], obstacles=[wall])
    assert not q.clear


def test_obstacles_of_widens_lines_by_half_the_width_and_clearance():
    style = Style()
    seg, arrow, ring, disc = obstacles_of(
        [
            Segment((0, 0), (10, 0)),
            Arrow((0, 10), (3, 10)),
            Circle((0, 30), 5),
            Circle((0, 50), 1, fill="white"),
        ],
        style,
    )
    assert seg.bounds == pytest.approx((-0.65, -0.65, 10.65, 0.65), abs=0.01)
    assert arrow.contains(shapely.Point(2.9, 10))  # short arrow: a head only
    assert not ring.contains(shapely.Point(0, 30)) and ring.contains(
        shapely.Point(5, 30)
    )
    assert disc.contains(shapely.Point(0, 50))


def test_overlaps_ignores_boxes_that_only_touch():
    a = Text((0, 0), "ДД", size=10, italic=False)  # x 0…14
    b = Text((14, 0), "ББ", size=10, italic=False)  # x 14…28: shares an edge
    c = Text((27, 0), "ГГ", size=10, italic=False)  # overlaps b
    assert overlaps([a, b, c]) == [(1, 2)]


@settings(max_examples=40, deadline=None)
@given(
    st.lists(
        st.tuples(
            st.floats(10, 90),
            st.floats(10, 90),
            st.sampled_from(["a", "b2", "s3", "n_BA"]),
        ),
        min_size=1,
        max_size=8,
    )
)
def test_labels_placed_clear_never_overlap(points):
    lines = [
        LineString([(0, 0), (100, 100)]).buffer(0.65),
        LineString([(0, 100), (100, 0)]).buffer(0.65),
    ]
    placed = place_labels(
        [LabelRequest((x, y), s) for x, y, s in points], obstacles=lines
    )
    clear = [p for p in placed if p.clear]
    assert overlaps([p.text for p in clear]) == []
    for p in clear:
        assert not any(p.box.intersects(g) for g in lines)


def test_markup_indices_are_smaller_and_widen_the_box():
    plain = text_box(Text((0, 0), "V", size=10, italic=False)).bounds
    indexed = text_box(Text((0, 0), "V_{BA}", size=10, markup=True, italic=False)).bounds
    # V at 10 mm (0.7 h), then "BA" at 7 mm after a spacing of its own size
    assert indexed[2] == pytest.approx(10 * 0.7 + 7 * 0.2 + 7 * (0.7 + 0.2 + 0.7))
    assert indexed[3] == pytest.approx(10 * (0.3 + 0.3 * 0.7))  # subscript hangs lower
    assert plain[1] == indexed[1] == -10
    sup = text_box(Text((0, 0), "a^n", size=10, markup=True, italic=False)).bounds
    assert sup[1] == pytest.approx(-10 * (0.45 + 0.7))  # superscript reaches higher


def test_placed_label_with_index_keeps_its_gap():
    (p,) = place_labels([LabelRequest((50, 50), "s_3", 5, prefer="n")])
    assert p.text.markup and p.box.bounds[3] == pytest.approx(49.0)  # 1 mm above
    (q,) = place_labels([LabelRequest((50, 50), "a^n", 5, prefer="s")])
    assert q.box.bounds[1] == pytest.approx(51.0)  # 1 mm below, superscript included


def test_near_label_may_cross_a_thin_line_rather_than_drift_away():
    from shapely.geometry import Point

    from drawing.labels import LabelRequest, place_labels

    anchor = (50.0, 50.0)
    ring = Point(anchor).buffer(4.0).exterior.buffer(0.2)  # one thin line round the point
    req = [LabelRequest(anchor, "A", 3.5, "ne")]
    distances = (1.0, 2.0, 3.0, 4.5, 6.0, 8.0)
    as_hard = place_labels(req, [ring], distances=distances)[0]
    as_soft = place_labels(req, [], distances=distances, soft=[ring])[0]
    assert as_soft.clear and as_soft.box.distance(Point(anchor)) <= 1.0 + 1e-9
    assert as_hard.box.distance(Point(anchor)) > 4.0  # had to go round the line
    # a bundle of thin lines (more than two) is not crossed: the letter goes further out
    radii = [1.5 + 0.5 * k for k in range(12)]  # 1.5 … 7 mm: every near spot crosses ≥ 3
    bundle = [Point(anchor).buffer(r).exterior.buffer(0.1) for r in radii]
    far = place_labels(req, [], distances=distances, soft=bundle)[0]
    assert far.clear and far.box.distance(Point(anchor)) > 7.0


def test_a_label_among_more_thin_lines_than_allowed_everywhere_still_gets_a_place():
    """Thirty thin rings round the anchor: every spot crosses more than ``max_soft`` of
    them and none hits a hard line. The label is placed where it crosses fewest, marked
    not clear (a sheet with 72 positions crashed here)."""
    from shapely.geometry import Point

    rings = [Point(50, 50).buffer(r).exterior.buffer(0.05) for r in [0.5 + 0.4 * k for k in range(30)]]
    (p,) = place_labels([LabelRequest((50, 50), "A", 3.5)], obstacles=[], soft=rings)
    assert not p.clear
    assert sum(1 for g in rings if g.intersects(p.box)) > 2


@settings(max_examples=60, deadline=None)
@given(st.tuples(*[st.floats(-50, 50, allow_subnormal=False)] * 2, st.floats(0.1, 30), st.floats(0.1, 30)),
       st.tuples(*[st.floats(-50, 50, allow_subnormal=False)] * 2, st.floats(0.1, 60), st.floats(0.1, 60)))
def test_the_area_outside_a_region_by_bounds_is_shapelys(b, r):
    """The label placer measures how far a box sticks out of its view by bounds (both are
    axis-parallel rectangles); it must be what shapely's difference gives. Not at subnormal
    coordinates (a region's corner at y = 2.2e-313), where GEOS's own difference goes wrong
    (0.875 for the 1.25 that the bounds give) and no sheet ever draws."""
    from drawing.obstacles import area_outside

    lab = box(b[0], b[1], b[0] + b[2], b[1] + b[3])
    reg = box(r[0], r[1], r[0] + r[2], r[1] + r[3])
    assert area_outside(lab, reg, True) == pytest.approx(lab.difference(reg).area, abs=1e-9)


def _star(anchor, rays, length=20.0, ring=None):
    """Vectors from ``anchor`` at each angle of ``rays`` (degrees, y down), widened as a
    plan's are, and a circle of radius ``ring`` round it."""
    ax, ay = anchor
    lines = [LineString([anchor, (ax + length * math.cos(math.radians(t)),
                                  ay + length * math.sin(math.radians(t)))]).buffer(0.65)
             for t in rays]
    if ring is not None:
        lines.append(shapely.Point(anchor).buffer(ring).exterior.buffer(0.65))
    return lines


def test_a_plan_letter_in_a_star_of_vectors_takes_a_turn_between_them():
    """Vectors leave the point along every compass direction: each spot of the compass
    lies on one. The letter goes between two of them, on its point's side of both, near
    it and with no leader, rather than over a vector."""
    from shapely.geometry import Point

    anchor = (50.0, 50.0)
    star = _star(anchor, range(0, 360, 45))
    (p,) = place_labels([LabelRequest(anchor, "s_3", 3.5, "ne", blank=True, cross=False)],
                        star, distances=(1.0, 2.0, 3.0, 4.5, 6.0, 8.0))
    assert p.clear and p.leader is None
    assert not any(g.intersects(p.box) for g in star)
    assert p.box.distance(Point(anchor)) <= 8.0


def test_a_plan_letter_walled_in_by_vectors_hangs_on_a_leader_clear_of_them():
    """A star of vectors and a circle round the point 6 mm out leave no clear spot
    within 8 mm: the letter covered a vector (the least overlap) with nothing to join it
    to its point. It now stands clear beyond the circle, on a leader from its point
    that crosses the circle rather than runs along a vector, and ends in the open."""
    from shapely.geometry import Point

    from drawing.labels import GAP, LEADER_END

    anchor = (50.0, 50.0)
    walls = _star(anchor, range(0, 360, 30), ring=6.0)
    first = LabelRequest((50.0, 30.0), "b", 3.5, "n", blank=True, cross=False)
    req = LabelRequest(anchor, "s_3", 3.5, "ne", blank=True, cross=False)
    other, p = place_labels([first, req], walls, distances=(1.0, 2.0, 3.0, 4.5, 6.0, 8.0))
    assert p.leader is not None and p.leader[0] == anchor
    assert not any(g.intersects(p.box) for g in walls)
    leader = LineString(p.leader)
    assert leader.distance(other.box) >= GAP  # no text on it, nor a break under one
    assert p.box.distance(Point(p.leader[1])) < 1e-9
    assert all(g.distance(Point(p.leader[1])) >= LEADER_END for g in walls)
    assert Point(anchor).distance(p.box) > 6.0  # beyond the circle


def test_a_later_letter_keeps_off_an_earlier_leader():
    """A leader is drawn: the letters placed after it keep :data:`GAP` from it, as they
    keep from each other, so that none stands on it nor breaks it."""
    from drawing.labels import GAP

    anchor = (50.0, 50.0)
    walls = _star(anchor, range(0, 360, 30), ring=6.0)
    reqs = [LabelRequest(anchor, "s_3", 3.5, "ne", blank=True, cross=False)]
    (first,) = place_labels(reqs, walls, distances=(1.0, 2.0, 3.0, 4.5, 6.0, 8.0))
    leader = LineString(first.leader)
    # a second point just beside the leader's middle, its letter preferring the leader
    mx, my = leader.interpolate(0.5, normalized=True).coords[0]
    (ux, uy) = (first.leader[1][0] - anchor[0], first.leader[1][1] - anchor[1])
    n = math.hypot(ux, uy)
    beside = (mx - 2.0 * uy / n, my + 2.0 * ux / n)
    second = LabelRequest(beside, "k", 3.5, "s", blank=True, cross=False)
    _, q = place_labels([*reqs, second], walls, distances=(1.0, 2.0, 3.0, 4.5, 6.0, 8.0))
    assert q.box.distance(leader) >= GAP - 1e-9


def test_a_letter_left_with_no_room_is_placed_first_on_a_second_try():
    """b's point sits in a fan of vectors open only towards a, whose letter prefers that
    side and, placed first, took the one spot b had: b's letter covered a vector. The
    letters are placed again with b's first, and a's goes round its point."""
    a, b = (46.0, 50.0), (56.0, 50.0)
    fan = _star(b, [t for t in range(0, 360, 15) if abs(t - 180) > 40], length=30.0)
    reqs = [LabelRequest(a, "a", 3.5, "e", blank=True, cross=False),
            LabelRequest(b, "b", 3.5, "w", blank=True, cross=False)]
    placed = place_labels(reqs, fan, region=box(38, 42, 70, 58),
                          distances=(1.0, 2.0, 3.0, 4.5, 6.0, 8.0))
    assert all(p.clear for p in placed)
    assert not any(g.intersects(p.box) for p in placed for g in fan)
    assert [p.text.text for p in placed] == ["a", "b"]  # in the order asked for
