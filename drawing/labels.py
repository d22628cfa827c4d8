"""Label placement: each label near its point where it meets nothing drawn.

Text extents come from :mod:`drawing.text` (the one fixed rule); :func:`place_labels`
puts a view's letters, a dimension's value and a position's number where they keep
clear of the lines, of each other and of the view's edge, on a leader where a point has
no room beside it.

>>> req = LabelRequest((0, 0), "A", prefer="e")
>>> (p,) = place_labels([req])
>>> p.clear, p.text.anchor
(True, 'start')
"""

from __future__ import annotations

import functools
import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
import shapely
import shapely.ops
from shapely.geometry import LineString, Polygon
from shapely.geometry.base import BaseGeometry

from drawing.obstacles import area_outside, is_box
from drawing.scene import Point, Text
from drawing.text import text_box
from drawing.ticks import Ticks, on_ticks

__all__ = [
    "ALONG",
    "FAR",
    "GAP",
    "LEADER",
    "LEADER_END",
    "RETRIES",
    "TURN",
    "LabelRequest",
    "Placement",
    "place_labels",
]

_COMPASS = ("n", "ne", "e", "se", "s", "sw", "w", "nw")


@dataclass(frozen=True, slots=True)
class LabelRequest:
    """A label wanted next to ``anchor`` (the point being lettered).

    ``prefer`` is a compass direction on the sheet (``"n"`` is up):
    n, ne, e, se, s, sw, w, nw.  ``markup``: ``"s_3"`` has a subscript 3
    (see :class:`drawing.scene.Text`).  ``optional``: a label that may be left out (a
    position's number) rather than drawn over something; it then takes no room.
    ``also``: further anchors the label may stand at, tried after ``anchor`` at each
    distance (the value of a dimension may go anywhere along its arc).  ``blank``: a
    dimension's value, under which thin lines are broken (GOST 2.307), see
    :class:`drawing.scene.Blank`. ``cross``: the label may cross thin lines close to its
    point rather than stand clear further off (a letter among the other positions' lines
    on a plan of positions); a plan's letter (``cross=False``) keeps off its construction
    lines wherever it has room within the distances tried.
    """

    anchor: Point
    text: str
    size: float = 3.5
    prefer: str = "ne"
    markup: bool = True
    optional: bool = False
    also: tuple[Point, ...] = ()
    blank: bool = False
    cross: bool = True
    #: slanted (GOST type B), as a sheet letters; upright in a picture's plain text
    italic: bool = True

    def __post_init__(self) -> None:
        if self.prefer not in _COMPASS:
            raise ValueError(f"prefer must be one of {_COMPASS}, got {self.prefer!r}")


@dataclass(frozen=True, slots=True)
class Placement:
    """Where a label went; ``clear`` is False when every candidate collided
    and the least-overlapping one was taken (or, with ``leader``, when it stands clear
    but across a line from its point)."""

    text: Text
    box: Polygon
    clear: bool
    #: (point, box's nearest point): a thin leader line to draw between them, where the
    #: label could stand clear only beyond another line
    leader: tuple[Point, Point] | None = None


_UNIT = {
    "n": (0, -1), "ne": (1, -1), "e": (1, 0), "se": (1, 1),
    "s": (0, 1), "sw": (-1, 1), "w": (-1, 0), "nw": (-1, -1),
}  # fmt: skip


def _candidate(req: LabelRequest, direction: str, gap: float, anchor: Point) -> Text:
    """The label with its box ``gap`` mm from ``anchor`` towards ``direction``.

    Sideways (e, w) the capitals are centred on the anchor's height; up or
    down, the box's near edge is ``gap`` away; diagonally its near corner is.
    """
    ux, uy = _UNIT[direction]
    d = gap if ux == 0 or uy == 0 else gap * math.sqrt(0.5)
    kind = "start" if ux > 0 else "end" if ux < 0 else "middle"
    ax, ay = anchor
    probe = Text((ax, ay), req.text, req.size, anchor=kind, markup=req.markup,
                 italic=req.italic)
    _, top, _, bottom = text_box(probe).bounds  # relative to a baseline at ay
    if uy < 0:
        y = ay - d - (bottom - ay)
    elif uy > 0:
        y = ay + d + (ay - top)
    else:
        y = ay + req.size / 2
    return Text((ax + ux * d, y), req.text, req.size, anchor=kind,  # type: ignore[arg-type]
                markup=req.markup, italic=req.italic)


def _directions(prefer: str) -> list[str]:
    """``prefer`` first, then its neighbours by turn, clockwise first."""
    i = _COMPASS.index(prefer)
    order = [0, 1, -1, 2, -2, 3, -3, 4]
    return [_COMPASS[(i + k) % 8] for k in order]


#: mm: the shortest leader line worth drawing to a label across a line from its point
LEADER = 3.0

#: mm a label keeps clear of the labels of other points placed before it, so that "11"
#: and "O" do not read as "11O", nor "g₁" and "g₃" as "g₁g₃"
GAP = 1.0


def place_labels(
    requests: Sequence[LabelRequest],
    obstacles: Sequence[BaseGeometry] = (),
    taken: Sequence[BaseGeometry] = (),
    region: BaseGeometry | None = None,
    distances: Sequence[float] = (1.0, 2.0, 3.0),
    soft: Sequence[BaseGeometry] = (),
    near: float = 3.0,
    max_soft: int = 2,
    leader_from: float | None = None,
    ticks: Ticks | None = None,
) -> list[Placement]:
    """Put each label near its anchor where it hits nothing.

    Candidates are tried nearest first (``distances``, mm between the anchor
    and the box); at each distance the preferred direction first, then its
    neighbours by turn.  The first candidate whose box stays inside ``region``
    (if given) and meets no obstacle, no box in ``taken`` and no label placed
    before it wins.  ``soft`` obstacles (thin lines: other positions, trajectories)
    are avoided too, but a letter within ``near`` mm of its point that crosses only
    soft lines (at most ``max_soft`` of them, any number for a ``blank`` one, the fewest)
    beats a clear one further away: a letter far from its point is read as another
    point's.  A label with ``cross=False`` stands on its point's side of every drawn
    line: the shortest way from its point to its box crosses no obstacle but those at
    the point itself (a letter beyond a vector reads as that vector's point); where it
    has no such spot, it takes the nearest clear one beyond a line with a ``leader``
    line to its point (GOST 2.316), one that ends :data:`LEADER_END` mm clear of every
    line and crosses lines rather than runs along them (else the finer search of
    :func:`_wider`; a leader ending on a line only where all else covers one). A label
    keeps :data:`GAP` mm from the labels of other points (an ``optional`` one from every
    label: a position's number beside the letter of its own point read as one word,
    "¹B"). If none is free, the candidate with the least overlap area is taken and reported with
    ``clear=False`` (an ``optional`` one is then meant to be left out, and later labels
    may take its place).

    Args:
        obstacles: drawn geometry to avoid, already widened; see
            :func:`obstacles_of`.
        taken: boxes of labels placed earlier (e.g. by another view).
        leader_from: a picture's rule (the check's overlay): each label takes the first
            spot, nearest first, that meets nothing (no line, no label within
            :data:`GAP`, nothing out of ``region``), whatever side of a line it is on;
            one farther than ``leader_from`` from its point hangs on a leader that keeps
            :data:`GAP` from the labels. Where none is clear, the nearest least covered
            spot (``clear=False``). None: the sheets' rule above.
        ticks: the rule of the positions' numbers on a diagram's φ axis
            (:mod:`drawing.ticks`): each request is a number anchored where its tick
            meets the axis, ``soft`` are the curves' middle lines, ``region`` the view's
            box it must not widen. None: the labels' rule.

    Labels are placed in turn, so an early one may take the only room a later one had:
    where a ``cross=False`` label is left with no clear spot, the labels are placed again
    with those left so first, and the placing kept where fewer labels cover a line.
    """
    if ticks is not None:
        return [Placement(text, box, clear) for text, box, clear in
                on_ticks(requests, [*obstacles, *taken], soft, region, distances, ticks)]
    hard = [g for g in (*obstacles, *taken) if not g.is_empty]
    tree = shapely.STRtree(hard) if hard else None
    args = (hard, tree, region, distances, soft, near, max_soft, leader_from)
    order = list(range(len(requests)))
    out = _in_order(requests, *args)
    score = _score(requests, out, hard, tree, region)
    front: list[int] = []  # the labels placed first, those left with no clear spot
    for _ in range(RETRIES):
        stuck = [i for i in order if not requests[i].cross and not (out[i].clear or out[i].leader)]
        if not stuck or set(stuck) <= set(front):
            break
        front += [i for i in stuck if i not in front]
        order = front + [i for i in range(len(requests)) if i not in front]
        again = _in_order([requests[i] for i in order], *args)
        placed = [again[order.index(i)] for i in range(len(requests))]
        if (better := _score(requests, placed, hard, tree, region)) < score:
            out, score = placed, better
    return out


#: how many times the labels are placed again, those left with no clear spot first
RETRIES = 2


def _score(requests: Sequence[LabelRequest], placed: list[Placement], hard: list,
           tree, region: BaseGeometry | None) -> tuple[int, int, int, float]:
    """How bad a placing is: the labels out of ``region`` (they would make the view
    larger than it was sized for), those covering a line, those with no clear spot (and
    no leader), the mm² of lines they cover and out of the region."""
    region_box = region is not None and is_box(region)
    out = [0.0 if region is None or p.clear or p.leader else area_outside(p.box, region, region_box)
           for p in placed]
    area = [0.0 if tree is None or p.clear or p.leader else
            sum(p.box.intersection(hard[i]).area for i in tree.query(p.box, predicate="intersects"))
            for p in placed]
    return (sum(o > 1e-9 for o in out), sum(a > 1e-6 for a in area),
            sum(not (p.clear or p.leader) for r, p in zip(requests, placed, strict=True)
                if not r.optional), sum(area) + sum(out))


def _in_order(
    requests: Sequence[LabelRequest],
    hard: list[BaseGeometry],
    hard_tree,
    region: BaseGeometry | None,
    distances: Sequence[float],
    soft: Sequence[BaseGeometry],
    near: float,
    max_soft: int,
    leader_from: float | None = None,
) -> list[Placement]:
    """:func:`place_labels`, each label in turn in the order given, against the
    obstacles and labels taken before (``hard``, non-empty, and their STRtree)."""
    soft = [g for g in soft if not g.is_empty]
    soft_tree = shapely.STRtree(soft) if soft else None
    close = [d for d in distances if d <= near] or list(distances[:1])
    rings = [close, [d for d in distances if d not in close]] if soft else [list(distances)]
    placed: list[Polygon] = []
    placed_at: list[Point] = []  # the anchor of each box placed
    region_box = region is not None and is_box(region)
    out: list[Placement] = []
    leaders: list[BaseGeometry] = []  # the leader lines drawn so far, widened: no letter on one
    lines = ((hard, hard_tree), (soft, soft_tree))

    def meets(req: LabelRequest, box: Polygon, boxes, others) -> tuple[list, float, float]:
        """What ``box`` meets: the obstacles, leaders and labels placed before it that
        it hits (or comes within GAP of), the mm² of those labels it covers, and its
        area outside ``region``."""
        hits = [] if hard_tree is None else [
            hard[i] for i in hard_tree.query(box, predicate="intersects")]
        hits += [g for g in leaders if g.intersects(box)]
        on_labels = 0.0  # mm² of the labels placed before that it covers
        if placed:  # a label keeps GAP from the labels of other points, a
            # position's number from its own point's letter too ("¹B")
            near_box = shapely.box(
                *(a + d for a, d in zip(box.bounds, (-GAP, -GAP, GAP, GAP), strict=True)))
            mask = shapely.intersects(near_box, boxes)
            if not req.optional:
                mask &= shapely.intersects(box, boxes) | others
            near_labels = [p for p, m in zip(placed, mask, strict=True) if m]
            on_labels = sum(box.intersection(p).area for p in near_labels)
            hits += near_labels
        outside = 0.0 if region is None else area_outside(box, region, region_box)
        return hits, on_labels, outside

    def blocked(req: LabelRequest, cands: np.ndarray, boxes, others) -> np.ndarray:
        """Which of the boxes ``cands`` (axis-parallel) :func:`meets` something or stand
        out of ``region``: the same rule, for many boxes at once."""
        out = np.zeros(len(cands), dtype=bool)
        if hard_tree is not None:
            out[hard_tree.query(cands, predicate="intersects")[0]] = True
        if leaders:
            out |= shapely.intersects(cands[:, None], np.asarray(leaders)[None, :]).any(axis=1)
        x0, y0, x1, y1 = shapely.bounds(cands).T
        if placed:
            mask = shapely.intersects(shapely.box(x0 - GAP, y0 - GAP, x1 + GAP, y1 + GAP)[:, None],
                                      boxes[None, :])
            if not req.optional:
                mask &= shapely.intersects(cands[:, None], boxes[None, :]) | others[None, :]
            out |= mask.any(axis=1)
        if region is not None:
            if region_box:
                r0, s0, r1, s1 = region.bounds
                out |= (x0 < r0 - 1e-9) | (y0 < s0 - 1e-9) | (x1 > r1 + 1e-9) | (y1 > s1 + 1e-9)
            else:
                out |= np.array([area_outside(b, region, False) > 1e-9 for b in cands], dtype=bool)
        return out

    def picture(req: LabelRequest, spots, boxes, others) -> Placement:
        """The first spot of ``spots`` at the nearest of ``distances`` that meets nothing
        (:func:`blocked`), with a leader beyond ``leader_from`` that keeps GAP from the
        labels; else the least covered spot at the nearest distance."""
        for gap in distances:
            texts = [_candidate(req, direction, gap, anchor) for anchor, direction in spots]
            cands = np.asarray([text_box(t) for t in texts], dtype=object)
            for i in np.flatnonzero(~blocked(req, cands, boxes, others)):
                anchor, box = spots[i][0], cands[i]
                if gap <= leader_from:
                    return Placement(texts[i], box, clear=True)
                if _leader_near(anchor, box, placed):
                    continue  # its leader would run through a letter
                line = _leader(anchor, box)
                leaders.append(line.buffer(GAP))
                return Placement(texts[i], box, clear=True, leader=(anchor, line.coords[1]))
        best = None  # none clear: in the region, off the labels, on the least of the lines
        for gap in distances:
            for anchor, direction in spots:
                text = _candidate(req, direction, gap, anchor)
                box = text_box(text)
                hits, on_labels, outside = meets(req, box, boxes, others)
                cost = (outside > 1e-9, on_labels > 1e-6,
                        sum(box.intersection(g).area for g in hits) + outside)
                if best is None or cost < best[0]:
                    best = (cost, text, box)
        assert best is not None  # distances and directions are never empty
        return Placement(best[1], best[2], clear=False)

    for req in requests:
        chosen: tuple[Text, Polygon] | None = None
        fallback: tuple[tuple[bool, float], Text, Polygon] | None = None
        across: tuple[tuple, Text, Polygon, Point] | None = None  # clear, but beyond a line
        on_line: tuple[tuple, Text, Polygon, Point] | None = None  # so, its leader ending on one
        spots = [(anchor, direction) for anchor in (req.anchor, *req.also)
                 for direction in _directions(req.prefer)]
        boxes = np.asarray(placed, dtype=object)  # the labels before this one, once
        others = np.asarray([a != req.anchor for a in placed_at], dtype=bool)
        if leader_from is not None:  # a picture's rule: the first clear spot, nearest first
            got = picture(req, spots, boxes, others)
            if got.clear or not req.optional:  # an optional label left out takes no room
                placed.append(got.box)
                placed_at.append(req.anchor)
            out.append(got)
            continue
        for ring in rings:
            # clear of everything wins; else the spot crossing the fewest thin lines
            relaxed: tuple[int, Text, Polygon] | None = None
            for gap in ring:
                for anchor, direction in spots:
                    text = _candidate(req, direction, gap, anchor)
                    box = text_box(text)
                    hits, on_labels, outside = meets(req, box, boxes, others)
                    if not (hits or req.cross or hard_tree is None or outside > 1e-9):
                        if _beyond(anchor, box, hard, hard_tree):  # on its point's far side
                            if _leader_near(anchor, box, placed):
                                continue  # its leader would run through a letter
                            # for a leader that reads as one: oblique, a few mm long
                            n_soft = 0 if soft_tree is None else len(
                                soft_tree.query(box, predicate="intersects"))
                            key = (n_soft, gap < LEADER, len(direction) == 1)
                            if (not _open_end(anchor, box, hard_tree, soft_tree)
                                    or _runs_along(anchor, box, lines)):
                                # ending on a line it reads as a tick on it, running
                                # along one as that line: the last resort of leaders
                                if on_line is None or key < on_line[0]:
                                    on_line = (key, text, box, anchor)
                            elif across is None or key < across[0]:
                                across = (key, text, box, anchor)
                            continue
                    if hits or outside > 1e-9:
                        # a letter over another letter is read as neither: the last resort
                        # covers lines rather than labels wherever it can
                        cost = (on_labels > 1e-6, sum(box.intersection(g).area for g in hits)
                                + outside + 1e-6 * len(hits))
                        if fallback is None or cost < fallback[0]:
                            fallback = (cost, text, box)
                        continue
                    n_soft = 0 if soft_tree is None else len(soft_tree.query(box, predicate="intersects"))
                    # the last resort too, when every spot crosses more thin lines than allowed
                    if fallback is None or (False, 1e-9 * n_soft) < fallback[0]:
                        fallback = ((False, 1e-9 * n_soft), text, box)
                    if n_soft == 0:
                        chosen = (text, box)
                        break
                    # a letter on a break in the thin lines may cross any number of them
                    if req.cross and (n_soft <= max_soft or req.blank) and (
                            relaxed is None or n_soft < relaxed[0]):
                        relaxed = (n_soft, text, box)
                if chosen:
                    break
            if chosen is None and relaxed is not None:
                chosen = relaxed[1:]
            if chosen:
                break
        leader = None
        if chosen is None and across is None and not req.cross and hard_tree is not None:
            # a narrow fan of vectors: no spot of the compass is clear on either side of
            # them. Finer turns, and farther out on a leader
            wider = _wider(req, distances, hard, hard_tree, soft, soft_tree, placed,
                           functools.partial(blocked, req, boxes=boxes, others=others))
            if wider is not None:
                n_soft, far, text, box, anchor = wider
                # clear of every line; or of the vectors at least, where the last resort
                # covers one or a letter
                if n_soft == 0 or fallback is None or _covers(
                        fallback[2], *meets(req, fallback[2], boxes, others)[::2]):
                    if far:
                        across = ((), text, box, anchor)
                    elif n_soft == 0:  # on its point's side, near it: as a spot of the compass
                        chosen = (text, box)
                    else:  # the last resort, on thin lines only
                        fallback = ((False, 0.0), text, box)
        if chosen is None and across is None and on_line is not None and (
                fallback is None or fallback[0][0] or fallback[0][1] > 1e-6):
            across = on_line  # rather than a letter over a vector, or over a letter
        if chosen is None and across is not None:  # clear, with a leader to its point
            _, text, box, anchor = across
            chosen = (text, box)
            line = _leader(anchor, box)
            leader = (anchor, line.coords[1])
            leaders.append(line.buffer(GAP))
        if chosen is not None:
            text, box = chosen
            clear = leader is None
        else:
            assert fallback is not None  # distances and directions are never empty
            _, text, box = fallback
            clear = False
        if clear or leader or not req.optional:  # an optional label left out takes no room
            placed.append(box)
            placed_at.append(req.anchor)
        out.append(Placement(text, box, clear=clear, leader=leader))
    return out


#: degrees between the turns tried around a point where no spot of the compass is clear
TURN = 5.0
#: mm between a point and its label on a leader, beyond the distances of the compass
#: spots: where a narrow fan of vectors leaves no room near the point
FAR = (10.0, 12.0, 14.0, 17.0, 20.0, 24.0)
#: mm the end of such a leader keeps from the lines, beyond their widening
LEADER_END = 1.0
#: mm of such a leader, past the first :data:`LEADER_END` from its point, that may run
#: within one line's widening: a crossing at 25° or more, not a run along the line
ALONG = 3.0


def _turn_centres(turns: np.ndarray, gap: float, hw: float, hh: float) -> np.ndarray:
    """The centres (relative to the point, rows of x, y) of boxes ``2 hw`` × ``2 hh``
    ``gap`` mm from the point, each on the ray ``turns`` degrees clockwise from east on
    the sheet (y down) from it: past a side of the box, or past its corner."""
    ux, uy = np.cos(np.radians(turns)), np.sin(np.radians(turns))
    a, b = np.abs(ux), np.abs(uy)
    with np.errstate(divide="ignore", invalid="ignore"):
        side_x = (gap + hw) / a  # the point beside the box's left or right side
        side_y = (gap + hh) / b  # above or below it
        c = a * hw + b * hh
        corner = c + np.sqrt(np.maximum(c * c - (hw * hw + hh * hh - gap * gap), 0.0))
        t = np.where(side_x * b <= hh + 1e-9, side_x,
                     np.where(side_y * a <= hw + 1e-9, side_y, corner))
    return np.stack([t * ux, t * uy], axis=1)


def _at(req: LabelRequest, centre: tuple[float, float]) -> Text:
    """The label with its box centred on ``centre``."""
    x0, y0, x1, y1 = text_box(Text((0.0, 0.0), req.text, req.size, markup=req.markup,
                                   italic=req.italic)).bounds
    return Text((centre[0] - (x0 + x1) / 2, centre[1] - (y0 + y1) / 2), req.text, req.size,
                italic=req.italic, markup=req.markup)


def _leader(anchor: Point, box: Polygon) -> LineString:
    """The shortest way from ``anchor`` to ``box``: the line of its leader, or the sight
    from a point to its letter."""
    return LineString([anchor, shapely.ops.nearest_points(shapely.Point(anchor), box)[1]])


def _open_end(anchor: Point, box: Polygon, hard_tree, soft_tree) -> bool:
    """Does the leader from ``anchor`` end at ``box`` in the open, :data:`LEADER_END` mm
    clear of every line? One that ends on a vector reads as a tick on it, the letter
    beyond as that vector's."""
    near = shapely.Point(_leader(anchor, box).coords[1]).buffer(LEADER_END)
    return not any(len(tree.query(near, predicate="intersects"))
                   for tree in (hard_tree, soft_tree) if tree is not None)


def _covers(box: Polygon, hits: list, outside: float) -> bool:
    """Does ``box`` cover some of what it meets, or stand out of its region?"""
    return outside > 1e-9 or any(box.intersection(g).area > 1e-6 for g in hits)


def _leader_near(anchor: Point, box: Polygon, placed: list[Polygon]) -> bool:
    """Does the leader from ``anchor`` to ``box`` come within :data:`GAP` of a label
    placed before (run through it, or be broken by the blank under it)?"""
    line = _leader(anchor, box)
    return any(line.distance(p) < GAP for p in placed)


def _runs_along(anchor: Point, box: Polygon, lines: Sequence[tuple[list, object]]) -> bool:
    """Does the leader from ``anchor`` to ``box`` run along a line (more than
    :data:`ALONG` mm within its widening) rather than cross it? ``lines``: (geometry,
    its STRtree) pairs."""
    line = _leader(anchor, box).difference(shapely.Point(anchor).buffer(LEADER_END))
    return any(line.intersection(geoms[i]).length > ALONG
               for geoms, tree in lines if tree is not None
               for i in tree.query(line, predicate="intersects"))


def _wider(req: LabelRequest, distances: Sequence[float], hard: list, hard_tree, soft: list,
           soft_tree, placed: list[Polygon], blocked) -> tuple[int, bool, Text, Polygon, Point] | None:
    """A spot for a plan's letter that no spot of the compass has room for: clear of the
    vectors and the labels (not ``blocked``), at turns of :data:`TURN` degrees. On the point's
    side of every vector within ``distances`` (nearest first), it needs no leader; else
    the nearest spot out to :data:`FAR` whose leader keeps :data:`GAP` from the labels,
    crosses the lines rather than runs along them, ends in the open and is at least
    :data:`LEADER` long where it can be. Off the construction lines wherever one is, else
    on the fewest. (n thin lines crossed, whether it needs a leader, text, box, anchor),
    or None where every spot meets something."""
    lines = ((hard, hard_tree), (soft, soft_tree))
    x0, y0, x1, y1 = text_box(Text((0.0, 0.0), req.text, req.size, markup=req.markup,
                                   italic=req.italic)).bounds
    hw, hh = (x1 - x0) / 2, (y1 - y0) / 2
    start = math.degrees(math.atan2(_UNIT[req.prefer][1], _UNIT[req.prefer][0]))
    half = round(180 / TURN)  # the preferred direction first, then by turn either way
    turns = start + TURN * np.array([k * sign for k in range(half + 1)
                                     for sign in ((1,) if k in (0, half) else (1, -1))])
    best: tuple[tuple, tuple[int, bool, Text, Polygon, Point]] | None = None
    for anchor in (req.anchor, *req.also):
        for gap in (*distances, *[d for d in FAR if d > max(distances)]):
            xy = _turn_centres(turns, gap, hw, hh) + np.asarray(anchor)
            boxes = shapely.box(xy[:, 0] - hw, xy[:, 1] - hh, xy[:, 0] + hw, xy[:, 1] + hh)
            for i in np.flatnonzero(~blocked(boxes)):
                text = _at(req, tuple(xy[i]))
                box = text_box(text)
                n_soft = 0 if soft_tree is None else len(
                    soft_tree.query(box, predicate="intersects"))
                far = gap > max(distances) or bool(_beyond(anchor, box, hard, hard_tree))
                if far and (_leader_near(anchor, box, placed)
                            or not _open_end(anchor, box, hard_tree, soft_tree)
                            or _runs_along(anchor, box, lines)):
                    continue
                key = (n_soft, far, far and gap < LEADER, gap, int(i))
                if best is None or key < best[0]:
                    best = (key, (n_soft, far, text, box, anchor))
            if best is not None and (best[0][:2] == (0, False) or (
                    gap >= max(distances) and best[0][:3] == (0, True, False))):
                return best[1]  # off every line, and none nearer or with no leader
    return None if best is None else best[1]


def _beyond(anchor: Point, box: Polygon, hard: list, tree) -> list:
    """The obstacles between ``anchor`` and ``box``: those the shortest segment from the
    point to the box meets, but for those at the point itself (its own vectors)."""
    a = shapely.Point(anchor)
    sight = _leader(anchor, box)
    if sight.length < 1e-9:
        return []
    return [hard[i] for i in tree.query(sight, predicate="intersects")
            if hard[i].distance(a) > 1e-9]
