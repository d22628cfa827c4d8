"""Structural analysis: Chebyshev's mobility and the split into the driver and Assur groups.

W = 3n − 2p5 − p4, with n moving links, p5 one-DOF pairs (revolute R and prismatic P) and
p4 two-DOF pairs (none in the file format). A 1-DOF linkage = the driver (crank with the
frame) + class-II groups (dyads), each attached to links already known; one of W = 2 has
two initial links (two drivers, each with the frame: a crank, or a slider on a fixed guide). The five kinds
(вид), in Artobolevsky's numbering: 1 RRR, 2 RRP, 3 RPR, 4 PRP, 5 RPP.
"""

from __future__ import annotations

import itertools
from dataclasses import dataclass
from enum import Enum

from plans import tolerances
from plans.errors import StructureError
from plans.model.mechanism import Mechanism, Slider

#: the pairs' letters in each language's textbooks: R, P in English; В (вращательная),
#: П (поступательная) in Russian
PAIR_LETTERS = {"en": {"R": "R", "P": "P"}, "ru": {"R": "В", "P": "П"}}
#: a group named in a sentence, by language
GROUP_LABEL = {"en": "group {a}–{b} ({kind})", "ru": "группа {a}–{b} ({kind})"}


class DyadKind(Enum):
    RRR = 1
    RRP = 2
    RPR = 3
    PRP = 4
    RPP = 5

    @property
    def ru(self) -> str:
        return self.letters("ru")

    def letters(self, lang: str = "en") -> str:
        """The kind as ``lang``'s textbooks letter it.

        >>> DyadKind.RPR.letters("ru"), DyadKind.RPR.letters("en")
        ('ВПВ', 'RPR')
        """
        table = PAIR_LETTERS.get(lang, PAIR_LETTERS["en"])
        return "".join(table[c] for c in self.name)


@dataclass(frozen=True, slots=True)
class Edge:
    """A pair between two links: a revolute at ``point`` or a prismatic ``slider``."""

    a: int
    b: int
    point: str | None = None  # revolute
    slider: Slider | None = None  # prismatic

    @property
    def kind(self) -> str:
        return "R" if self.slider is None else "P"

    def other(self, link: int) -> int:
        return self.b if link == self.a else self.a


@dataclass(frozen=True, slots=True)
class Group:
    """One class-II group with its roles resolved for the construction.

    RRR: link ``a`` hinged to a known link at P, to link ``b`` at C; ``b`` hinged at Q.
    RRP: ``a`` hinged at P and at C to the slider ``b``, which moves along ``s1``.
    RPR: block ``a`` hinged at P slides along the guide ``s1`` of link ``b`` hinged at Q.
    PRP: ``a`` moves along ``s1``, ``b`` along ``s2``; they are hinged together at C.
    RPP: block ``a`` hinged at P slides along ``s1`` carried by ``b``; ``b`` moves along ``s2``.
    """

    kind: DyadKind
    a: int
    b: int
    P: str | None = None
    C: str | None = None
    Q: str | None = None
    s1: Slider | None = None
    s2: Slider | None = None

    @property
    def links(self) -> tuple[int, int]:
        return tuple(sorted((self.a, self.b)))

    @property
    def label(self) -> str:
        return self.label_in("en")

    def label_in(self, lang: str = "en") -> str:
        """"group 2–3 (RRR)", "группа 2–3 (ВВВ)": the group by its links and its kind."""
        a, b = self.links
        return GROUP_LABEL.get(lang, GROUP_LABEL["en"]).format(a=a, b=b, kind=self.kind.letters(lang))

    def labels(self) -> dict[str, str]:
        """:meth:`label_in` in every language the engine speaks."""
        return {lang: self.label_in(lang) for lang in GROUP_LABEL}


@dataclass(frozen=True, slots=True)
class Structure:
    n: int
    p5: int
    p4: int
    W: int
    driver: int
    groups: tuple[Group, ...]
    #: every input link, the first (``driver``) first: one per degree of freedom
    drivers: tuple[int, ...] = ()

    @property
    def mechanism_class(self) -> int:
        return 2 if self.groups else 1

    def formula(self) -> str:
        """Structural formula, e.g. ``I(0,1) → II3(2,3) → II2(4,5)``; with two inputs
        ``I(0,1) → I(0,4) → II1(2,3)``."""
        parts = [f"I(0,{d})" for d in (self.drivers or (self.driver,))]
        parts += [f"II{g.kind.value}({g.links[0]},{g.links[1]})" for g in self.groups]
        return " → ".join(parts)

    def chebyshev(self) -> str:
        """Chebyshev's formula with its numbers, as the note and the errors write it."""
        return chebyshev(self.n, self.p5, self.p4)


def chebyshev(n: int, p5: int, p4: int = 0) -> str:
    W = 3 * n - 2 * p5 - p4
    return f"W = 3n − 2p5 − p4 = 3·{n} − 2·{p5} − {p4} = {W}".replace("= -", "= −")


def edges(mech: Mechanism) -> list[Edge]:
    out = [Edge(a, b, point=p) for p, a, b in mech.revolutes()]
    out += [Edge(s.link, s.guide.link, slider=s) for s in mech.sliders]
    return out


def analyse(mech: Mechanism) -> Structure:
    """Mobility and Assur decomposition; raises :class:`StructureError` with the reason,
    naming the mechanism's file."""
    try:
        return _analyse(mech)
    except StructureError as err:
        err.source = err.source or mech.source
        raise


def _analyse(mech: Mechanism) -> Structure:
    all_edges = edges(mech)
    n = len(mech.links)
    p5 = len(all_edges)
    W = 3 * n - 2 * p5
    inputs = len(mech.drivers)
    if W != inputs:
        if inputs == 1:
            what = ("over-constrained (a structure or a locked chain)" if W < 1 else
                    "under-constrained: more inputs than one crank")
            need = "a mechanism with one crank needs W = 1"
        else:
            what = ("over-constrained for its two inputs" if W < inputs else
                    f"under-constrained: it needs {W} inputs")
            need = f"a mechanism with {inputs} inputs needs W = {inputs}"
        raise StructureError(f"{chebyshev(n, p5)}: the chain is {what}; {need}")
    for d in mech.drivers:
        frame_edges = [e for e in all_edges if {e.a, e.b} == {0, d.link}]
        if d.linear:
            if len(frame_edges) != 1 or frame_edges[0].slider is None:
                raise StructureError(
                    f"the input slider (link {d.link}) must be joined to the frame by its guide "
                    f"{d.guide.label} only")
        elif len(frame_edges) != 1 or frame_edges[0].point != d.pivot:
            raise StructureError(
                f"the crank (link {d.link}) must be hinged to the frame at {d.pivot} only"
            )
    drv = mech.driver.link
    known = {0, *(d.link for d in mech.drivers)}
    unknown = set(mech.links) - known
    groups: list[Group] = []
    while unknown:
        found = None
        for x, y in itertools.combinations(sorted(unknown), 2):
            between = [e for e in all_edges if {e.a, e.b} == {x, y}]
            ext_x = [e for e in all_edges if x in (e.a, e.b) and e.other(x) in known]
            ext_y = [e for e in all_edges if y in (e.a, e.b) and e.other(y) in known]
            if len(between) == 1 and len(ext_x) == 1 and len(ext_y) == 1:
                found = _classify(x, y, ext_x[0], between[0], ext_y[0])
                break
        if found is None:
            left = ", ".join(str(i) for i in sorted(unknown))
            raise StructureError(
                f"links {left} do not form class-II groups attached to the known links "
                f"{', '.join(str(i) for i in sorted(known))}: the chain needs a group of "
                "a higher class, or a pair is missing or extra"
            )
        groups.append(found)
        known |= {found.a, found.b}
        unknown -= {found.a, found.b}
    return Structure(n=n, p5=p5, p4=0, W=W, driver=drv, groups=tuple(groups),
                     drivers=tuple(d.link for d in mech.drivers))


def _classify(x: int, y: int, ex: Edge, inner: Edge, ey: Edge) -> Group:
    code = ex.kind + inner.kind + ey.kind
    # orient the group so that its code is one of the five canonical kinds
    if code in ("PRR", "PPR"):
        x, y, ex, ey = y, x, ey, ex
        code = code[::-1]
    label = f"group {min(x, y)}–{max(x, y)} ({code})"
    if code == "RRR":
        return Group(DyadKind.RRR, x, y, P=ex.point, C=inner.point, Q=ey.point)
    if code == "RRP":
        _must_slide(ey.slider, y, label)
        if ey.slider.point != inner.point:
            raise StructureError(
                f"{label}: slider link {y} must be on its guide at the hinge {inner.point}"
            )
        return Group(DyadKind.RRP, x, y, P=ex.point, C=inner.point, s1=ey.slider)
    if code == "RPR":
        s = inner.slider
        block, guide_link = s.link, s.guide.link
        P = ex.point if block == x else ey.point
        Q = ey.point if block == x else ex.point
        if s.point != P:
            raise StructureError(
                f"{label}: the block (link {block}) must slide with its hinge {P} on the guide"
            )
        return Group(DyadKind.RPR, block, guide_link, P=P, Q=Q, s1=s)
    if code == "PRP":
        _must_slide(ex.slider, x, label)
        _must_slide(ey.slider, y, label)
        for s in (ex.slider, ey.slider):
            if s.point != inner.point:
                raise StructureError(
                    f"{label}: link {s.link} must be on its guide at the hinge {inner.point}"
                )
        return Group(DyadKind.PRP, x, y, C=inner.point, s1=ex.slider, s2=ey.slider)
    if code == "RPP":
        s_in = inner.slider
        _must_slide(ey.slider, y, label)
        if s_in.link != x or s_in.point != ex.point:
            raise StructureError(
                f"{label}: the block (link {x}) hinged at {ex.point} must slide along the "
                f"guide carried by link {y}"
            )
        # the inner guide in the yoke's coordinates, whose x runs along the yoke's own guide:
        # along x, the two stay parallel at every angle (the threshold of a singular plan)
        if abs(s_in.guide.direction.imag) <= tolerances.SINGULAR_SINE:
            raise StructureError(
                f"{label}: the guide {s_in.guide.label} of link {y} is parallel to the guide "
                f"{ey.slider.guide.label} it moves along (a sliding link's x-axis runs along "
                "its guide), so the yoke's position is not fixed at any crank angle: turn "
                f"one of them, e.g. angle_deg = 90 for a slot across link {y}"
            )
        return Group(DyadKind.RPP, x, y, P=ex.point, s1=s_in, s2=ey.slider)
    raise StructureError(f"{label}: a group of three prismatic pairs has no fixed position")


def _must_slide(slider: Slider | None, link: int, label: str) -> None:
    if slider is None or slider.link != link:
        raise StructureError(
            f"{label}: link {link} must slide on a guide carried by a known link "
            "(a guide carried by the group itself over a known block is not supported)"
        )
