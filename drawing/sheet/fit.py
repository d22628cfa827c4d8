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

from drawing.sheet.layout import LayoutError, pack, place_views
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
                 lettered: tuple[str, ...] = ()):
        self.sheet, self.factors, self.draw, self.fixed = sheet, factors, draw, fixed
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
            return [[(v.w, v.h) for v in drawn(value)] for value in values]
        big, small = drawn(values[0]), drawn(values[-1])
        k0, k1 = 1 / values[0], 1 / values[-1]
        out = []
        for value in values:
            t = (1 / value - k1) / (k0 - k1)  # 1 at the largest views, 0 at the smallest
            sizes = []
            for a, b in zip(big, small, strict=True):
                bw, bh = (q + t * (p - q) for p, q in zip(a.body, b.body, strict=True))
                sizes.append((captioned_width(bw, *a.texts),
                              bh + max(a.h - a.body[1], b.h - b.body[1])))
            out.append(sizes)
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
            combos.append(((rank, shape), -area, idx, boxes))
        combos.sort(key=lambda c: c[:2])
        failed: list[tuple[int, ...]] = []
        ranks = [f in ranked for f in range(len(keys))]
        for _, area, idx, boxes in combos:
            if -area > field:  # more than the field holds, however packed
                continue
            if any(all(i <= j if r else i == j for i, j, r in zip(idx, f, ranks, strict=True))
                   for f in failed):
                continue  # no view smaller than in one of its shape that did not pack
            if pack(self.sheet, boxes) is None and (
                    not self._interpolated(idx)
                    or pack(self.sheet, self._ordered(idx, self._drawn_sizes(idx, sizes), rest))
                    is None):  # foreseen between two drawings: drawn, for a close call
                failed.append(idx)
                continue
            mu = self._values(idx)
            try:
                place_views(self.sheet, self._all(mu))
            except LayoutError:  # foreseen too small: drawn, it does not pack
                failed.append(idx)
                continue
            return mu
        mu = self._values(tuple(len(v) - 1 for _, v, _ in self.factors))
        place_views(self.sheet, self._all(mu))  # the smallest views: why they do not fit
        return mu  # they do, foreseen larger than they are

    def _interpolated(self, idx) -> bool:
        """Whether a combination's sizes were foreseen between two drawings."""
        return any(key in SCALED and 0 < i < len(values) - 1
                   for (key, values, _), i in zip(self.factors, idx, strict=True))

    def _drawn_sizes(self, idx, sizes):
        """``sizes`` with the combination's own views drawn (without their letters)."""
        out = [list(per) for per in sizes]
        for f, ((key, values, _), i) in enumerate(zip(self.factors, idx, strict=True)):
            if key in SCALED and 0 < i < len(values) - 1:
                out[f][i] = [(v.w, v.h) for v in self.draw(key, values[i], sizing=True)]
        return out

    def _ordered(self, idx, sizes, rest) -> list[tuple[float, float]]:
        """The foreseen boxes of a combination, in packing order."""
        named = [(name, box) for f, ((key, _, _), i) in enumerate(zip(self.factors, idx, strict=True))
                 for name, box in zip(self._names[key], sizes[f][i], strict=True)]
        named += [(v.name, box) for v, box in zip(self.fixed, rest, strict=True)]
        return [box for _, box in sorted(named, key=lambda nb: self.order.index(nb[0]))]

    def _values(self, idx) -> dict[str, float]:
        return {k: vals[i] for (k, vals, _), i in zip(self.factors, idx, strict=True)}

    def arranged(self, views: list) -> list:
        """``views`` in the order they are packed."""
        return sorted(views, key=lambda v: self.order.index(v.name))

    def _all(self, mu: dict[str, float]) -> list:
        return self.arranged([v for k, value in mu.items() for v in self.views(k, value)]
                             + list(self.fixed))
