"""The crank-existence conditions of a crank-rocker whose rocker support slides along the
frame (two inputs: the crank, and the slider that carries the rocker's pivot).

With the crank l1 = |AB|, the coupler l2 = |BC|, the rocker l3 = |DC| and the distance
l4 = |AD| between the crank's pivot and the rocker's moving support, the crank turns fully
while

    l1 + l2 < l3 + l4   and   l4 + l1 < l3 + l2,

that is while l4 stays between l1 + l2 − l3 and l3 + l2 − l1 (Manzhosov & Petrova, the
crank-rocker with a moving rocker support). l4 changes with the support's travel: the
conditions are checked over the whole range it takes over the cycle.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from plans.fmt import num
from plans.model.structure import DyadKind


@dataclass(frozen=True)
class SupportConditions:
    """The conditions over the support's range (m)."""

    crank: int
    l1: float
    l2: float
    l3: float
    #: the least and the greatest l4 over the cycle
    l4: tuple[float, float]

    @property
    def lower(self) -> float:
        """l1 + l2 < l3 + l4 holds for l4 above this."""
        return self.l1 + self.l2 - self.l3

    @property
    def upper(self) -> float:
        """l4 + l1 < l3 + l2 holds for l4 below this."""
        return self.l3 + self.l2 - self.l1

    @property
    def first(self) -> bool:
        return self.l4[0] > self.lower

    @property
    def second(self) -> bool:
        return self.l4[1] < self.upper

    @property
    def hold(self) -> bool:
        return self.first and self.second

    @property
    def never(self) -> bool:
        """They fail at every support position of the range."""
        return self.l4[1] <= self.lower or self.l4[0] >= self.upper or self.lower >= self.upper


def support_conditions(mech, solver, cycle, samples: int = 3600) -> SupportConditions | None:
    """The conditions of ``mech`` over ``cycle`` where it is a crank-rocker whose rocker
    support slides (a rotary and a linear input, an RRR group between the crank's pin and
    a point of the slider); None for any other mechanism."""
    if len(mech.drivers) != 2 or cycle is None or cycle.span is None:
        return None
    crank = next((d for d in mech.drivers if not d.linear), None)
    slider = next((d for d in mech.drivers if d.linear), None)
    if crank is None or slider is None:
        return None
    for g in solver.structure.groups:
        if g.kind is not DyadKind.RRR:
            continue
        ends = {g.P: g.a, g.Q: g.b}
        if crank.tip not in ends or len(ends) != 2:
            continue
        other = g.Q if g.P == crank.tip else g.P
        if other not in mech.links[slider.link].points:
            continue
        coupler, rocker = mech.links[ends[crank.tip]], mech.links[ends[other]]
        l2 = abs(coupler.points[g.C] - coupler.points[crank.tip])
        l3 = abs(rocker.points[g.C] - rocker.points[other])
        lo, hi = cycle.span
        period = slider.law.period if slider.law is not None else None
        if period:  # the support's whole range: a period of its law
            hi = max(hi, lo + period)
        with np.errstate(all="ignore"):
            m = solver.solve(np.linspace(lo, hi, samples))
        l4 = np.abs(np.asarray(m.position[other]) - crank.origin)
        return SupportConditions(crank.link, crank.length, float(l2), float(l3),
                                 (float(l4.min()), float(l4.max())))
    return None


WORDS = {
    "en": {
        "head": "crank-existence conditions of the moving support: l1 + l2 < l3 + l4 (l4 > {lower} m) "
                "and l4 + l1 < l3 + l2 (l4 < {upper} m); over the support's travel l4 = {a} … {b} m",
        "hold": "both hold over the support's whole range: link {crank} turns fully",
        "fail": "not over the support's whole range ({which}): link {crank} cannot turn fully "
                "at every support position",
        "never": "at no support position ({which}): link {crank} is no crank, it cannot turn fully",
        "first": "l1 + l2 < l3 + l4 fails", "second": "l4 + l1 < l3 + l2 fails", "and": ", ",
    },
    "ru": {
        "head": "условия существования кривошипа при подвижной опоре: l1 + l2 < l3 + l4 "
                "(l4 > {lower} м) и l4 + l1 < l3 + l2 (l4 < {upper} м); при перемещении опоры "
                "l4 = {a} … {b} м",
        "hold": "оба выполняются во всём диапазоне перемещения опоры: звено {crank} — кривошип",
        "fail": "выполняются не во всём диапазоне перемещения опоры ({which}): звено {crank} "
                "не может сделать полный оборот при всех положениях опоры",
        "never": "не выполняются ни при одном положении опоры ({which}): звено {crank} не может "
                 "сделать полный оборот",
        "first": "l1 + l2 < l3 + l4 нарушено", "second": "l4 + l1 < l3 + l2 нарушено", "and": ", ",
    },
}


def lines(c: SupportConditions | None, lang: str = "en") -> list[str]:
    """The conditions in words (none where there are none)."""
    if c is None:
        return []
    w = WORDS[lang]

    def n(x: float) -> str:
        return num(x, 4, lang)

    out = [w["head"].format(lower=n(c.lower), upper=n(c.upper), a=n(c.l4[0]), b=n(c.l4[1]))]
    which = w["and"].join(w[k] for k, ok in (("first", c.first), ("second", c.second)) if not ok)
    out.append(w["hold"].format(crank=c.crank) if c.hold else
               w["never" if c.never else "fail"].format(which=which, crank=c.crank))
    return out


def as_json(c: SupportConditions | None) -> dict | None:
    """The conditions for the JSON (m)."""
    if c is None:
        return None
    return {"l1": c.l1, "l2": c.l2, "l3": c.l3, "l4_least": c.l4[0], "l4_greatest": c.l4[1],
            "l4_above": c.lower, "l4_below": c.upper, "first_holds": c.first,
            "second_holds": c.second, "hold": c.hold}
