"""The scale factors of sheet 1: as large as the sheet holds, each on its own.

The scale factors the mechanism file leaves free are chosen for the sheet: μl for the
plan of positions, μv for the velocity plans, μa for the acceleration plans. Each
runs through its own standard series (:mod:`plans.scales`), from views 3 times the
engine's default size (a plan's longest vector 450 mm, the plan of positions 450 mm
across) down to half of it (75 mm), and no further (:func:`readable`): the series' next
step down may halve a view again, to a plan of positions whose letters crowd a 24 mm
crank circle and plans 24 mm long, on a sheet that looks full only because the views'
captions keep their width. Views that do not fit at half their default size do not fit:
the sheet is refused with the format that holds them, as one too small for them at any
scale is.

A factor does not wait for the others: a plan of positions that fits at μl = 0.001
keeps it where the acceleration plan needs a step down, instead of every view going
down a step together until the largest fits. The combinations are tried best first:
the one whose smallest view (as a multiple of its default size) is largest, then by the
next smallest, and so on, so that no view is shrunk for another to grow; then by the
area the views cover. The kinematic diagrams are one more factor (their width), sized
with the room the plans leave beyond their default 180 mm (up to it, they count as a
plan does), never larger than the largest plan. Each combination is packed as foreseen
(:func:`drawing.sheet.layout.pack`): a view's size at each candidate is that of the view
drawn without its letters, with the room they may take around the drawing (placing them
is what takes the time), at the factor's largest and smallest candidates, and between
them on the straight line, which is never under it. The first combination that packs is
drawn and packed for real; a combination whose views are none smaller than those of one
that did not pack is not tried.
"""

from __future__ import annotations

import itertools
from collections.abc import Sequence

from drawing.sheet.layout import LayoutError, pack, pack_units, pairs_of, place_views, why_not
from drawing.views.common import captioned_width

__all__ = ["SIZES", "Fit", "readable"]

#: the views' sizes tried, as multiples of the engine's default drawing sizes (a plan's
#: crank vector 80 mm and its longest vector 150 mm, the plan of positions 150 mm
#: across): the largest and the smallest. The plan of positions may be larger still,
#: up to the field's longer side
SIZES = (3.0, 0.5)


def readable(size: float) -> bool:
    """Whether a view ``size`` times the engine's default size is drawn large enough to
    read: at least the smallest of :data:`SIZES` (a plan's longest vector 75 mm or its
    crank vector 40 mm, the plan of positions 75 mm across)."""
    return size >= SIZES[1] - 1e-9


#: the factors whose views are lettered: drawn without their letters to be sized (the
#: tables without their cells' texts, which are fitted into the cells)
LETTERED = ("mu_l", "mu_v", "mu_a", "segments")
#: the scale factors, whose views' drawings grow as 1/μ
SCALED = ("mu_l", "mu_v", "mu_a")
#: the factors sized with the room the scale factors' views leave
SECONDARY = ("diagrams",)
#: how many combinations :class:`Fit` packs in every order of their views at most, and
#: the share of the field their views may cover at most to be (a larger share never
#: packs: the searches are kept for those that may)
SEARCHED = 24
DEEP = 0.72


class Fit:
    """The views of one sheet at the scale factors that fill it (see the module).

    ``draw(key, value, sizing=False)`` draws the views the factor ``key`` sizes at
    ``value`` (``sizing``: without their letters, as large as those could make them);
    ``fixed`` are the views no free factor sizes; ``factors`` gives
    each free factor's candidates, largest views first, with the size of its views at
    each (as a multiple of the engine's default size); ``order``, the views' names in
    the order they are packed (the plan of positions first: top left where it fits);
    ``lettered``, the factors beyond :data:`LETTERED` whose views are sized drawn without
    their letters.
    """

    def __init__(self, sheet, factors: list[tuple[str, list[float], list[float]]], draw,
                 fixed: list, order: list[str], plain: set[str] = frozenset(),
                 lettered: tuple[str, ...] = (), leader: tuple[str, str, tuple[str, ...]] | None = None,
                 together: Sequence[tuple[str, str]] = (), search: bool = False):
        self.sheet, self.factors, self.draw, self.fixed = sheet, factors, draw, fixed
        #: (its factor, the view that is to be the largest, the prefixes of the views'
        #: names it is to be larger than): combinations where it is come first, and of
        #: those the ones where it is largest (sheet 1's plan of positions, the view a
        #: teacher reads first, larger than any plan)
        self.leader = leader
        #: the views packed as one box, each pair (a position's two plans): a combination
        #: whose views do not pack so is not taken
        self.together = list(together)
        #: whether the first combinations are packed in every order of their views
        #: (:func:`~drawing.sheet.layout.pack`'s ``search``), up to SEARCHED of them
        self.search = search
        self._searched = 0
        self._bodies: dict[str, list[list[tuple[float, float]]]] = {}
        self._sized: dict[tuple[str, float], list[tuple[float, float]]] = {}
        self.plain = plain  # the factors that only change a view's shape: the first that packs
        #: the factors whose views are sized drawn without their letters: LETTERED, and
        #: the sheet's own (sheet 2's force plans)
        self.lettered = LETTERED + tuple(lettered)
        self.order = order  # the views' names in the order they are packed
        self._drawn: dict[tuple[str, float], list] = {}
        self._names: dict[str, list[str]] = {}

    def views(self, key: str, value: float) -> list:
        """The views ``key`` sizes, drawn at ``value`` (each drawn once)."""
        got = self._drawn.get((key, value))
        if got is None:
            got = self._drawn[(key, value)] = self.draw(key, value)
        return got

    def foreseen(self, key: str, values: list[float]) -> list[list[tuple[float, float]]]:
        """For each candidate, the (w, h) of each view the factor sizes: as large as its
        letters could make it, drawn without them (placing letters is what takes time).
        A scale factor's views are drawn so at its largest and smallest candidates only:
        in between, each side of a drawing is a largest of terms linear in 1/μ (lines
        that scale, marks that do not), so the straight line between the two is never
        under it; the caption and the equations do not scale."""
        def drawn(value):
            got = self.draw(key, value, sizing=True) if key in self.lettered else self.views(key, value)
            self._names[key] = [v.name for v in got]
            return got

        if key not in SCALED or len(values) <= 2:
            views = [drawn(value) for value in values]
            self._bodies[key] = [[v.body for v in vs] for vs in views]
            return [[(v.w, v.h) for v in vs] for vs in views]
        big, small = drawn(values[0]), drawn(values[-1])
        k0, k1 = 1 / values[0], 1 / values[-1]
        out, bodies = [], []
        for value in values:
            t = (1 / value - k1) / (k0 - k1)  # 1 at the largest views, 0 at the smallest
            sizes, inner = [], []
            for a, b in zip(big, small, strict=True):
                bw, bh = (q + t * (p - q) for p, q in zip(a.body, b.body, strict=True))
                sizes.append((captioned_width(bw, *a.texts),
                              bh + max(a.h - a.body[1], b.h - b.body[1])))
                inner.append((bw, bh))
            out.append(sizes)
            bodies.append(inner)
        self._bodies[key] = bodies
        return out

    def best(self) -> dict[str, float]:
        """The free factors' values; :class:`LayoutError` (why, from the smallest
        views) when even those do not fit."""
        sizes = [self.foreseen(k, vals) for k, vals, _ in self.factors]
        rest = [(v.w, v.h) for v in self.fixed]
        field = self.sheet.drawing_area().area
        combos = []
        keys = [k for k, _, _ in self.factors]
        ranked = [f for f, k in enumerate(keys) if k not in self.plain]
        for idx in itertools.product(*(range(len(v)) for _, v, _ in self.factors)):
            sized = [self.factors[f][2][idx[f]] for f in ranked]
            if "diagrams" in keys:  # no larger than the largest plan, nor than the default
                d = keys.index("diagrams")
                plans = [size for f, size in zip(ranked, sized, strict=True) if f != d]
                if self.factors[d][2][idx[d]] > max([1.0, *plans]) + 1e-9:
                    continue
            # the smallest view's size first, then the next: no view is given up for
            # another. The diagrams count up to their default size (180 mm): beyond it,
            # they take the room the plans leave
            rank = tuple(-s for s in sorted(
                round(min(x, 1.0) if keys[f] in SECONDARY else x, 6)
                for f, x in zip(ranked, sized, strict=True)))
            rank += tuple(idx[f] for f in ranked if keys[f] in SECONDARY)
            shape = tuple(i for f, i in enumerate(idx) if f not in ranked)
            boxes = self._ordered(idx, sizes, rest)
            area = sum(w * h for w, h in boxes)
            # the leader (sheet 1's plan of positions) the largest view first, the views
            # then as large as above, and of those the leader largest; where it cannot
            # be the largest, it is as large as it can be, the others as near its size
            lead = ((-self.factors[keys.index(self.leader[0])][2][idx[keys.index(self.leader[0])]],)
                    if self.leader is not None and self.leader[0] in keys else ())
            excess = self._excess(idx)  # 1 or less where the leader is the largest
            order = ((True, lead, round(excess, 6), rank) if excess > 1 + 1e-9
                     else (False, (), 0.0, rank + lead))
            combos.append(((*order, shape), -area, idx, boxes))
        combos.sort(key=lambda c: c[:2])
        failed: list[tuple[int, ...]] = []
        ranks = [f in ranked for f in range(len(keys))]
        for key, area, idx, boxes in combos:
            if -area > field:  # more than the field holds, however packed
                continue
            if any(all(i <= j if r else i == j for i, j, r in zip(idx, f, ranks, strict=True))
                   for f in failed):
                continue  # no view smaller than in one of its shape that did not pack
            # every order of the views is searched for the first combinations that may
            # pack, a few of them (:data:`SEARCHED`): those where a small sheet's plan of
            # positions is largest may fit only one way of hundreds
            deep = self.search and self._searched < SEARCHED and -area <= DEEP * field
            self._searched += deep
            if self._pack(boxes, deep) is None and (
                    not self._interpolated(idx)
                    or self._pack(self._ordered(idx, self._drawn_sizes(idx, sizes), rest), deep)
                    is None):  # foreseen between two drawings: drawn, for a close call
                failed.append(idx)
                continue
            mu = self._values(idx)
            try:
                self._place(self._all(mu))
            except LayoutError:  # foreseen too small: drawn, it does not pack
                failed.append(idx)
                continue
            if not key[0] and self._drawn_excess(self._all(mu)) > 1 + 1e-9:
                continue  # foreseen the largest, drawn it is not
            return mu
        mu = self._values(tuple(len(v) - 1 for _, v, _ in self.factors))
        self._place(self._all(mu))  # the smallest views: why they do not fit
        return mu  # they do, foreseen larger than they are

    def _pack(self, boxes: list[tuple[float, float]], search: bool = False):
        """:func:`~drawing.sheet.layout.pack` of boxes in packing order, each pair of
        ``together`` as one box (:func:`~drawing.sheet.layout.pack_units`)."""
        if not self.together:
            return pack(self.sheet, boxes, search=search)
        return pack_units(self.sheet, boxes, pairs_of(self._order_names, self.together), search)

    def _place(self, views: list) -> None:
        """:class:`LayoutError` where ``views`` (drawn) do not pack, pairs together."""
        if self.together:
            sizes = [(v.w, v.h) for v in views]
            pairs = pairs_of([v.name for v in views], self.together)
            if pack_units(self.sheet, sizes, pairs, self.search) is None:
                raise LayoutError(*why_not(self.sheet, views))
            return
        place_views(self.sheet, views, search=self.search)

    def _drawn_excess(self, views: list) -> float:
        """:meth:`_excess` of the views drawn."""
        if self.leader is None:
            return 1.0
        _, name, led = self.leader
        bodies = {v.name: v.body for v in views}
        if name not in bodies or not bodies[name][0] * bodies[name][1]:
            return 1.0
        most = max([0.0, *(w * h for n, (w, h) in bodies.items() if n.startswith(led))])
        return most / (bodies[name][0] * bodies[name][1])

    def _excess(self, idx) -> float:
        """How many times the largest drawing (by area) the leader leads is the leader's,
        at the combination ``idx`` (the views of the free factors and the fixed ones):
        1 or less where the leader is the largest."""
        if self.leader is None:
            return 1.0
        _, name, led = self.leader
        bodies: dict[str, tuple[float, float]] = {}
        for (key, _, _), i in zip(self.factors, idx, strict=True):
            if key in self._bodies:
                bodies.update(zip(self._names[key], self._bodies[key][i], strict=True))
        bodies.update((v.name, v.body) for v in self.fixed)
        if name not in bodies:
            return 1.0
        area = bodies[name][0] * bodies[name][1]
        most = max([0.0, *(w * h for n, (w, h) in bodies.items() if n.startswith(led))])
        return most / area if area > 0 else 1.0

    def _interpolated(self, idx) -> bool:
        """Whether a combination's sizes were foreseen between two drawings."""
        return any(key in SCALED and 0 < i < len(values) - 1
                   for (key, values, _), i in zip(self.factors, idx, strict=True))

    def _drawn_sizes(self, idx, sizes):
        """``sizes`` with the combination's own views drawn (without their letters)."""
        out = [list(per) for per in sizes]
        for f, ((key, values, _), i) in enumerate(zip(self.factors, idx, strict=True)):
            if key in SCALED and 0 < i < len(values) - 1:
                got = self._sized.get((key, values[i]))
                if got is None:  # each drawn once: many combinations share it
                    got = self._sized[(key, values[i])] = [
                        (v.w, v.h) for v in self.draw(key, values[i], sizing=True)]
                out[f][i] = got
        return out

    def _ordered(self, idx, sizes, rest) -> list[tuple[float, float]]:
        """The foreseen boxes of a combination, in packing order (their names in
        ``_order_names``)."""
        named = [(name, box) for f, ((key, _, _), i) in enumerate(zip(self.factors, idx, strict=True))
                 for name, box in zip(self._names[key], sizes[f][i], strict=True)]
        named += [(v.name, box) for v, box in zip(self.fixed, rest, strict=True)]
        named.sort(key=lambda nb: self.order.index(nb[0]))
        self._order_names = [name for name, _ in named]
        return [box for _, box in named]

    def _values(self, idx) -> dict[str, float]:
        return {k: vals[i] for (k, vals, _), i in zip(self.factors, idx, strict=True)}

    def arranged(self, views: list) -> list:
        """``views`` in the order they are packed."""
        return sorted(views, key=lambda v: self.order.index(v.name))

    def _all(self, mu: dict[str, float]) -> list:
        return self.arranged([v for k, value in mu.items() for v in self.views(k, value)]
                             + list(self.fixed))
