"""Placing the views of a sheet: rectangles packed into the drawing area.

Each view is a box (0, 0)–(w, h) of local sheet mm (:class:`drawing.views.View`).
The free field is the frame less the title block and field 26, less ``MARGIN``;
views keep ``GAP`` mm from each other.  :func:`pack` puts boxes in, one after the
other, each at the topmost (or leftmost) spot where it meets nothing placed before
it: the spots tried are the corners the field and the boxes already placed make.
Several orders are tried (the order given, largest first, tallest first, widest
first), so that a set of views that fits one way is not refused for the order it
came in.  Nothing is scaled: what sizes the views is :mod:`plans.cli.sheet`.

Views may be packed in pairs kept together (a position's velocity and acceleration
plans, where the sheet draws several positions): the second right beside or right
under the first, and each pair before the next in reading order. Where no order packs
them so, they are packed as if they were not paired.
"""

from __future__ import annotations

import itertools
import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
from shapely.geometry import box

from drawing.scene import Group, Rect
from drawing.sheet.frame import Sheet

__all__ = ["LayoutError", "Placed", "describe", "field", "in_order", "kept_together",
           "pack", "pack_kept", "pack_units", "pair_box", "pairs_of", "place_views", "reads_before", "room",
           "share_covered", "share_used", "spread", "unit_sizes", "why_not"]

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
    free spot (``rows``) or the leftmost then topmost one; None if one has none. (Boxes
    kept in pairs are put by :func:`_put` itself, each prefix once: :func:`_pack_pairs`.)"""
    state: _State | None = ((None,) * len(sizes), ())
    for i in order:
        state = _put(inner, blocked, sizes, rows, {}, state, i)
        if state is None:
            return None
    return list(state[0])  # type: ignore[arg-type]


#: what :func:`_put` has placed: each box's spot (None until placed), and the boxes
#: placed, widened by GAP
_State = tuple[tuple[tuple[float, float] | None, ...], tuple[Box, ...]]


def _put(inner: Box, blocked: list[Box], sizes: Sequence[tuple[float, float]], rows: bool,
         partner: dict[int, int], state: _State, i: int) -> _State | None:
    """``state`` with box ``i`` (and its partner) put in, as :func:`_first_fit` puts each
    box; None where it has no spot. A box with a ``partner`` is put at the first spot
    where its partner fits right beside it or right under it (:func:`_beside`), and its
    partner there."""
    spots, wide = state
    if spots[i] is not None:  # put beside its partner already
        return state
    x0, y0, x1, y1 = inner
    w, h = sizes[i]
    if w > x1 - x0 + 1e-9 or h > y1 - y0 + 1e-9:
        return None

    def free(x, y, w, h, edges):
        return (x0 - 1e-9 <= x and x + w <= x1 + 1e-9 and y0 - 1e-9 <= y
                and y + h <= y1 + 1e-9
                and not any(x < e[2] - 1e-9 and e[0] < x + w - 1e-9 and y < e[3] - 1e-9
                            and e[1] < y + h - 1e-9 for e in edges))

    edges = [*blocked, *wide]
    j = partner.get(i)
    # the corners a box of each size makes: the box itself, or it and its partner
    # side by side or one under the other
    shapes = [(w, h)] if j is None else [
        (w, h), (w + GAP + sizes[j][0], max(h, sizes[j][1])),
        (max(w, sizes[j][0]), h + GAP + sizes[j][1])]
    xs = sorted(x for x in {c for sw, _ in shapes for c in (
                    x0, x1 - sw, *(b[2] for b in edges), *(b[0] - sw for b in edges))}
                if x0 - 1e-9 <= x and x + w <= x1 + 1e-9)
    ys = sorted(y for y in {c for _, sh in shapes for c in (
                    y0, y1 - sh, *(b[3] for b in edges), *(b[1] - sh for b in edges))}
                if y0 - 1e-9 <= y and y + h <= y1 + 1e-9)
    best = other = None
    # every candidate at once, in the order of the scan (rows: y, then x), as free() has
    # it (xs and ys are inside the field already): the search for a position's plans
    # together places a box thousands of times
    xa, ya = np.asarray(xs), np.asarray(ys)
    X, Y = (xa[None, :], ya[:, None]) if rows else (xa[:, None], ya[None, :])
    ok = np.ones((len(ys), len(xs)) if rows else (len(xs), len(ys)), dtype=bool)
    if edges:
        E = np.asarray(edges)
        Xe, Ye = X[..., None], Y[..., None]
        ok &= ~((Xe < E[:, 2] - 1e-9) & (E[:, 0] < Xe + w - 1e-9) & (Ye < E[:, 3] - 1e-9)
                & (E[:, 1] < Ye + h - 1e-9)).any(axis=-1)
    for k in np.flatnonzero(ok):
        a, b = divmod(int(k), ok.shape[1])
        x, y = (xs[b], ys[a]) if rows else (xs[a], ys[b])
        if j is not None:
            wj, hj = sizes[j]
            here = [*edges, (x - GAP, y - GAP, x + w + GAP, y + h + GAP)]
            other = next((s for s in _beside((x, y, w, h), (wj, hj))
                          if free(*s, wj, hj, here)), None)
            if other is None:
                continue
        best = (x, y)
        break
    if best is None:
        return None
    new_spots, new_wide = list(spots), list(wide)
    for k, (x, y) in [(i, best)] + ([] if j is None else [(j, other)]):
        new_spots[k] = (x, y)
        wk, hk = sizes[k]
        new_wide.append((x - GAP, y - GAP, x + wk + GAP, y + hk + GAP))
    return tuple(new_spots), tuple(new_wide)


def _beside(lead: Box, size: tuple[float, float]) -> list[tuple[float, float]]:
    """The spots, best first, for a box of ``size`` right beside the box ``lead`` (x, y,
    w, h), ``GAP`` from it: to its right, their tops or their bottoms level; under it,
    their left or their right sides level."""
    x, y, w, h = lead
    wj, hj = size
    return [(x + w + GAP, y), (x + w + GAP, y + h - hj), (x, y + h + GAP),
            (x + w - wj, y + h + GAP)]


def pack(sheet: Sheet, sizes: Sequence[tuple[float, float]],
         pairs: Sequence[tuple[int, int]] = (),
         apart: bool = True, search: bool = False) -> list[tuple[float, float]] | None:
    """Top-left corners for boxes of ``sizes`` (w, h mm) on ``sheet``, none meeting
    another (``GAP`` apart) nor the title block and field 26; None if no order tried
    fits them all. The order given is tried first, so that the plan of positions, put
    first, is at the top left where it fits there.

    ``pairs`` (i, j): boxes to keep together, j right beside or right under i, each
    pair before the next in reading order (:func:`reads_before`): a position's velocity
    and acceleration plans. Where no order tried packs them so, the boxes are packed
    as if no pairs were given (``apart``), else None: a pair kept together never costs
    a view its size.

    ``search``: where none of those orders packs the boxes, every order of them with
    the first box first is tried, up to :data:`SEARCH` placements of a box (a small
    sheet's views, which fit one way of the 240 and not in the ten tried first)."""
    inner, blocked = field(sheet)
    if pairs:
        spots = _pack_pairs(inner, blocked, sizes, pairs)
        if spots is not None or not apart:
            return spots
    for order, rows in _orders([[i] for i in range(len(sizes))], sizes):
        spots = _first_fit(inner, blocked, sizes, order, rows)
        if spots is not None:
            return spots
    return _search(inner, blocked, sizes) if search else None


#: how many placements of a box :func:`pack`'s ``search`` makes at most (a sheet of six
#: views: 650 for every order of the five after the first, by rows and by columns)
SEARCH = 800


def _search(inner: Box, blocked: list[Box], sizes: Sequence[tuple[float, float]]
            ) -> list[tuple[float, float]] | None:
    """Spots for the boxes from the first order that packs them of those with the first
    box first, by rows then by columns, each prefix of an order placed once; None where
    none does within :data:`SEARCH` placements."""
    n = len(sizes)
    budget = SEARCH
    for rows in (True, False):
        placed: dict[tuple[int, ...], _State | None] = {}
        for rest in itertools.permutations(range(1, n)):
            order = (0, *rest)
            state: _State | None = ((None,) * n, ())
            for k, i in enumerate(order):
                key = order[:k + 1]
                if key not in placed:
                    if budget <= 0:
                        return None
                    budget -= 1
                    placed[key] = _put(inner, blocked, sizes, rows, {}, state, i)
                state = placed[key]
                if state is None:
                    break
            if state is not None:
                return list(state[0])  # type: ignore[arg-type]
    return None


def _orders(units: list[list[int]], sizes: Sequence[tuple[float, float]]):
    """The orders :func:`pack` tries, each once, with ``rows`` (see :func:`_first_fit`):
    the ``units`` (boxes put one right after the other) as given, the first then the
    largest, the largest, the tallest and the widest first, flattened to the boxes."""
    def area(u):
        return sum(sizes[i][0] * sizes[i][1] for i in u)

    def height(u):
        return max(sizes[i][1] for i in u)

    def width(u):
        return max(sizes[i][0] for i in u)

    given = list(range(len(units)))
    by_area = sorted(given, key=lambda k: -area(units[k]))
    tall = sorted(given, key=lambda k: (-height(units[k]), -width(units[k])))
    wide = sorted(given, key=lambda k: (-width(units[k]), -height(units[k])))
    first = [0, *(k for k in by_area if k)]  # the first view top left, then the largest
    tried = set()
    for order, rows in ((given, True), (given, False), (first, True), (first, False),
                        (by_area, True), (by_area, False), (tall, False), (wide, True),
                        (tall, True), (wide, False)):
        flat = tuple(i for k in order for i in units[k])
        if (flat, rows) in tried:
            continue
        tried.add((flat, rows))
        yield flat, rows


#: how many orders of the units (a view, or a pair kept together) :func:`pack` tries at
#: most for the pairs, beyond those it tries without them: every order of seven units
#: that keeps two pairs in theirs, by rows and by columns (a sheet has six: the plan of
#: positions, two pairs, the diagrams and two tables)
TRIES = 5040


def in_order(n: int, rank: Sequence[int]):
    """The permutations of ``range(n)`` in which the items ``rank`` come in that order,
    in the order ``itertools.permutations`` gives them: built so, not filtered out of
    all n! (362 880 for a sheet of five positions' plans, of which 3 024 are wanted).

    >>> list(in_order(3, [2, 0]))
    [(1, 2, 0), (2, 0, 1), (2, 1, 0)]
    """
    nth = {u: i for i, u in enumerate(rank)}
    used = [False] * n
    prefix: list[int] = []

    def grow(due: int):
        if len(prefix) == n:
            yield tuple(prefix)
            return
        for u in range(n):
            if used[u] or nth.get(u, due) != due:
                continue
            used[u] = True
            prefix.append(u)
            yield from grow(due + (u in nth))
            prefix.pop()
            used[u] = False

    yield from grow(0)


def _pack_pairs(inner: Box, blocked: list[Box], sizes: Sequence[tuple[float, float]],
                pairs: Sequence[tuple[int, int]], tries: int = TRIES
                ) -> list[tuple[float, float]] | None:
    """:func:`pack` with each of ``pairs`` together and in order; None where no order
    tried packs them so. The orders tried without pairs first, then every order of the
    units with the pairs in theirs, up to ``tries`` (a sheet's views are few)."""
    first = {i: (i, j) for i, j in pairs}
    seconds = {j for _, j in pairs}
    units = [list(first[i]) if i in first else [i] for i in range(len(sizes))
             if i not in seconds]
    rank = [units.index(list(pair)) for pair in pairs]
    partner = dict(pairs)

    def every():
        for perm in in_order(len(units), rank):
            for rows in (True, False):
                yield tuple(i for k in perm for i in units[k]), rows

    # the placements of every prefix of the orders tried: the orders share long prefixes
    # (all but their last few units, in the order permutations come), so each order
    # places only what its prefix did not (a sheet of five positions' plans: 24–29 s
    # where no order keeps its pairs, placing every order from its first box)
    placed: dict[tuple[bool, tuple[int, ...]], _State | None] = {}
    tried = set()
    for order, rows in itertools.chain(_orders(units, sizes), itertools.islice(every(), tries)):
        if (order, rows) in tried:
            continue
        tried.add((order, rows))
        state: _State | None = ((None,) * len(sizes), ())
        for k, i in enumerate(order):
            key = (rows, order[:k + 1])
            if key not in placed:
                placed[key] = _put(inner, blocked, sizes, rows, partner, state, i)
            state = placed[key]
            if state is None:
                break
        if state is None:
            continue
        spots = list(state[0])
        if _in_reading_order([(*spot, *size) for spot, size in zip(spots, sizes, strict=True)],
                             pairs):
            return spots
    return None


def kept_together(placed: list[Placed], together: Sequence[tuple[str, str]]) -> bool:
    """Whether the views named in ``together`` are placed as :func:`pack` keeps pairs:
    each second right beside or right under its first, each pair before the next."""
    pairs = pairs_of([p.view.name for p in placed], together)
    rects = [(p.rect.x, p.rect.y, p.rect.w, p.rect.h) for p in placed]
    for i, j in pairs:
        if not any(math.dist(spot, rects[j][:2]) < 1e-6
                   for spot in _beside(rects[i], rects[j][2:])):
            return False
    return bool(pairs) and _in_reading_order(rects, pairs)


def _in_reading_order(rects: Sequence[tuple[float, float, float, float]],
                      pairs: Sequence[tuple[int, int]]) -> bool:
    """Whether each of ``pairs`` (indices into ``rects``, x, y, w, h), taken as the one
    box around its two, is read before the next (:func:`reads_before`): what
    :func:`_pack_pairs` asks of an order and :func:`kept_together` of a placement."""
    boxes = [_union(rects[i], rects[j]) for i, j in pairs]
    return all(reads_before(a, b) for a, b in itertools.pairwise(boxes))


def _union(*rects: tuple[float, float, float, float]) -> Box:
    """The bounding box (x0, y0, x1, y1) of rectangles (x, y, w, h)."""
    return (min(r[0] for r in rects), min(r[1] for r in rects),
            max(r[0] + r[2] for r in rects), max(r[1] + r[3] for r in rects))


def reads_before(a: Box, b: Box) -> bool:
    """Whether the box ``a`` (x0, y0, x1, y1) is read before ``b``: wholly above it or
    wholly left of it, and ``b`` neither wholly above nor wholly left of ``a`` (a box
    above and to the right of the other is read first by rows, last by columns)."""
    def ahead(p, q):
        return p[3] <= q[1] + 1e-9 or p[2] <= q[0] + 1e-9

    return ahead(a, b) and not ahead(b, a)


def place_views(sheet: Sheet, views, together: Sequence[tuple[str, str]] = (),
                keep: bool = False, search: bool = False) -> list[Placed]:
    """Positions for ``views`` (see :func:`pack`), the views named in each of
    ``together`` kept together where they fit so, or (``keep``) always: where no order
    of :func:`pack`'s search keeps each pair together in reading order, each pair is
    packed as one box (:func:`pack_units`). :class:`LayoutError` if they do not all fit
    (``keep``: together). ``search``: as :func:`pack`'s."""
    sizes = [(v.w, v.h) for v in views]
    pairs = pairs_of([v.name for v in views], together)
    if keep and pairs:
        spots = pack_kept(sheet, sizes, pairs, search)
    else:
        spots = pack(sheet, sizes, pairs, search=search)
    if spots is None:
        raise LayoutError(*why_not(sheet, views))
    return [Placed(v, Rect(x, y, v.w, v.h)) for v, (x, y) in zip(views, spots, strict=True)]


def pair_box(a: tuple[float, float], b: tuple[float, float]) -> tuple[bool, tuple[float, float]]:
    """How two boxes kept together stand, and the box round them: (True, …) for ``b``
    right of ``a``, their tops level, where that box is the smaller; (False, …) for ``b``
    under ``a``, their left sides level.

    >>> pair_box((100.0, 40.0), (80.0, 50.0))
    (True, (186.0, 50.0))
    >>> pair_box((200.0, 20.0), (100.0, 100.0))
    (False, (200.0, 126.0))
    """
    beside = (a[0] + GAP + b[0], max(a[1], b[1]))
    under = (max(a[0], b[0]), a[1] + GAP + b[1])
    return (True, beside) if beside[0] * beside[1] <= under[0] * under[1] else (False, under)


def unit_sizes(sizes: Sequence[tuple[float, float]], pairs: Sequence[tuple[int, int]]
               ) -> tuple[list[tuple[float, float]], list[list[int]]]:
    """The boxes packed when each of ``pairs`` is one box (:func:`pair_box`), in the order
    of their first boxes, and the boxes each unit holds."""
    partner = dict(pairs)
    seconds = set(partner.values())
    out, units = [], []
    for i, size in enumerate(sizes):
        if i in seconds:
            continue
        if i in partner:
            out.append(pair_box(size, sizes[partner[i]])[1])
            units.append([i, partner[i]])
        else:
            out.append(size)
            units.append([i])
    return out, units


#: how many orders :func:`pack_kept` tries for the pairs in reading order at most
KEPT_TRIES = 720


def pack_kept(sheet: Sheet, sizes: Sequence[tuple[float, float]],
              pairs: Sequence[tuple[int, int]], search: bool = False
              ) -> list[tuple[float, float]] | None:
    """Spots for boxes of ``sizes`` with each of ``pairs`` together, always: each pair
    as one box (:func:`pack_units`), taken where the pairs come so in reading order;
    else the first order of :func:`pack`'s search for pairs (up to :data:`KEPT_TRIES`)
    that puts them in reading order, or that packing after all. None where the pairs
    do not fit together."""
    spots = pack_units(sheet, sizes, pairs, search)
    if spots is None:
        return None
    if _in_reading_order([(*spot, *size) for spot, size in zip(spots, sizes, strict=True)], pairs):
        return spots
    inner, blocked = field(sheet)
    return _pack_pairs(inner, blocked, sizes, pairs, KEPT_TRIES) or spots


def pack_units(sheet: Sheet, sizes: Sequence[tuple[float, float]],
               pairs: Sequence[tuple[int, int]], search: bool = False
               ) -> list[tuple[float, float]] | None:
    """:func:`pack` with each of ``pairs`` as one box, the second box right of the first
    or under it as :func:`pair_box` stands them: a pair is never parted, though the
    pairs may not come in reading order; None where they do not all fit so."""
    boxes, units = unit_sizes(sizes, pairs)
    spots = pack(sheet, boxes, search=search)
    if spots is None:
        return None
    out: list[tuple[float, float]] = [(0.0, 0.0)] * len(sizes)
    for (x, y), unit in zip(spots, units, strict=True):
        out[unit[0]] = (x, y)
        if len(unit) == 2:
            i, j = unit
            beside, _ = pair_box(sizes[i], sizes[j])
            out[j] = (x + sizes[i][0] + GAP, y) if beside else (x, y + sizes[i][1] + GAP)
    return out


def pairs_of(names: Sequence[str], together: Sequence[tuple[str, str]]) -> list[tuple[int, int]]:
    """The pairs of ``together`` (view names) as indices into ``names``, those of a view
    not among them left out."""
    return [(names.index(a), names.index(b)) for a, b in together if a in names and b in names]


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


def why_not(sheet: Sheet, views) -> tuple[str, str]:
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
