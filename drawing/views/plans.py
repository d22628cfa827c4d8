"""A vector plan: any polygon of vectors from a pole, with its points' recorded sources.

The velocity and acceleration plans of sheet 1 are drawn by :func:`vector_plan_view`, and
so is any other plan that keeps to this protocol (a force plan: the forces laid end to
end and closed by two lines of known direction):

* ``plan.pole``: the pole's name ("p", "π");
* ``plan.points``: name → point, each with ``value`` (a complex number, in the plan's
  unit, from the pole) and ``source``, whose ``kind`` is "intersection" for a point found
  where two lines cross: then ``source.lines`` holds those lines (each with ``through``,
  the name of a point of the plan, and ``direction``, a complex number) and
  ``source.equation`` the vector equation it solves (written under the plan); any other
  kind draws no construction;
* ``plan.vectors``: the vectors drawn, each from ``start`` to ``end`` (names of points or
  the pole); its ``component`` kind and ``label`` travel with it (the tables and the note
  read them, the drawing does not);
* ``plan.mu``: the scale (the plan's unit per mm): one sheet millimetre per plan mm.

Nothing else is read: the caption, the ids of the vectors (``prefix``) and the sides of
the links' images a similarity point was found on (``sides``, optional) are given, and so
may be the lines under the plan (a force plan's equation written as its sheet writes the
forces' names) and how each vector's ``label`` is written beside it (``named``: a force
plan names its forces, G₄, R₃₄, where its points' letters say little).
"""

from __future__ import annotations

import math
import re
from collections.abc import Callable, Sequence

from drawing.labels import LabelRequest
from drawing.scene import Arrow, Circle, Group, Item, Segment, shared_label
from drawing.styles import LineType
from drawing.views.common import (
    EQUATION,
    HEAD,
    LETTER,
    WORDS,
    Equation,
    View,
    finish,
    notation,
    per_mm,
    shared_points,
)
from plans.fmt import notation_in, num
from plans.plan.solution import image_sides, plan_name

__all__ = ["NAME_MM", "plan_equations", "plan_view", "vector_plan_view"]

def _plan_xy(value: complex, mu: float) -> tuple[float, float]:
    z = value / mu
    return (z.real, -z.imag)


def plan_view(sol, kind: str, tag: str, lang: str = "ru", label: str | None = None,
              sizing: bool = False) -> View:
    """The velocity (``kind="velocity"``) or acceleration plan of the solution ``sol``,
    captioned with its position (``label``, else ``tag``) and scale factor.

    ``tag`` distinguishes the position (``"3"``) in the ids of its vectors.
    """
    plan = sol.velocity if kind == "velocity" else sol.acceleration
    w = WORDS[lang]
    unit = per_mm(w["ms" if kind == "velocity" else "ms2"], lang)
    mu_name = "μ_v" if kind == "velocity" else "μ_a"
    caption = f"{w[kind]} ({label or tag}), {mu_name} = {num(plan.mu, 4, lang)} {unit}"
    return vector_plan_view(plan, f"{kind}-{tag}", caption, "v" if kind == "velocity" else "a",
                            tag, lang, sides=image_sides(plan), sizing=sizing,
                            under=plan_equations(plan, sol.mechanism.driver, lang),
                            under_size=EQUATION)


def plan_equations(plan, driver, lang: str = "ru") -> list[Equation]:
    """The vector equations of ``plan``'s intersections as the course writes them under
    the plan (:class:`~drawing.views.common.Equation`), each term's direction read off
    the recorded construction: a line's relation for the term it carries ("⊥ BA3",
    "∥ x-x"), the crank's for its pin (⊥ OA, its acceleration ∥ AO, from the pin to the
    pivot), "0" for a fixed point, "∥ CB" for a normal component (from the point to the
    centre), the Coriolis term across its sliding term's guide, the plan's segment for a
    point found before ("pc"); a term whose direction the construction does not fix
    (the point sought, found where the two lines cross) has none under it."""
    out = []
    for p in plan.points.values():
        src = p.source
        if src.kind != "intersection" or not src.equation:
            continue
        main = src.equation.split(";")[0]
        terms, signs = [], []
        for k, side in enumerate(main.split(" = ")):
            for j, term in enumerate(side.split(" + ")):
                if k or j:
                    signs.append("+" if j else "=")
                terms.append(term.strip())
        carried = {line.unknown: line.relation for line in src.lines}
        # the point sought has a direction only where a line carries it (∥ x-x)
        directions = [carried.get(terms[0], "")]
        directions += [_direction(term, plan, driver, carried) for term in terms[1:]]
        out.append(Equation(tuple(notation(notation_in(t, lang)) for t in terms),
                            tuple(_direction_markup(d) for d in directions), tuple(signs)))
    return out


def _direction(term: str, plan, driver, carried: dict[str, str]) -> str:
    """The direction written under ``term`` (see :func:`plan_equations`), plain."""
    if term in carried:
        return carried[term]
    kind, _, rest = term.partition("^")
    if rest:  # a component: a^n_CB, a^k_A3A
        comp, _, pair = rest.partition("_")
        if comp == "n":
            return f"∥ {pair}"
        if comp == "k":  # across the guide its relative (sliding) term runs along
            along = carried.get(f"{kind}^r_{pair}", "")
            return {"∥": "⊥", "⊥": "∥"}.get(along[:1], "") + along[1:] if along else ""
        return ""
    _, _, name = term.partition("_")
    point = plan_name(name)
    src = plan.points[point].source if point in plan.points else None
    if point == plan.pole or (src is not None and src.kind == "pole"):
        return "0"
    if src is not None and src.kind == "driver" and name == driver.tip:
        return (f"⊥ {driver.pivot}{driver.tip}" if plan.kind == "velocity"
                else f"∥ {driver.tip}{driver.pivot}")
    return f"{plan.pole}{point}" if src is not None else ""


def _direction_markup(direction: str) -> str:
    """A direction as markup, each point's number an index: "⊥ BA3" → "⊥ BA_{3}",
    "∥ x3-x3" → "∥ x_{3}-x_{3}", "πs3" → "πs_{3}"."""
    return re.sub(r"(?<=[^\W\d_])(\d+)", r"_{\1}", direction)


def vector_plan_view(plan, name: str, caption: str, prefix: str, tag: str, lang: str = "ru",
                     sides: Sequence[tuple[complex, complex]] = (), sizing: bool = False,
                     under: Sequence[str] | None = None, under_size: float = 2.5,
                     named: Callable[[str], str] | None = None) -> View:
    """The view ``name`` of ``plan`` (the protocol of this module) at one sheet mm per plan
    mm under ``caption``: the construction lines of its intersections thin, ``sides``
    (pairs of values: the links' images its similarity points were found on) thin, its
    vectors heavy, each a group of class ``vec PREFIX-STARTEND-TAG`` (``vec v-pa3-1``) so
    that its length can be measured on the SVG, the pole a dot, the points lettered (those
    that coincide share one label, the pole first), the equations of the intersections
    under it in ``lang`` (or the lines ``under``, in ``under_size`` mm letters).
    ``named``: each vector's label as markup (``"R34^τ"`` → ``"R^τ_{34}"``), written
    beside its vector (one of :data:`NAME_MM` or longer), off the vectors, on the side
    away from the plan's middle."""
    mu = plan.mu
    pts = {n: _plan_xy(p.value, mu) for n, p in plan.points.items()}
    pts.setdefault(plan.pole, (0.0, 0.0))
    items: list[Item] = []
    # construction lines of the intersections, thin, under the vectors
    for p in plan.points.values():
        if p.source.kind != "intersection":
            continue
        for line in p.source.lines:
            if line.through not in pts:
                continue
            tx, ty = pts[line.through]
            dx, dy = line.direction.real, -line.direction.imag
            px, py = pts[p.name]
            t = (px - tx) * dx + (py - ty) * dy
            a, b = min(0.0, t) - 6.0, max(0.0, t) + 6.0
            items.append(
                Segment((tx + a * dx, ty + a * dy), (tx + b * dx, ty + b * dy), LineType.THIN)
            )
    # the link's image each similarity point is found on, thin: bc on to e of a coupler
    # BCE, the sides be, ce of a triangle
    items += [Segment(_plan_xy(a, mu), _plan_xy(b, mu), LineType.THIN) for a, b in sides]
    # the vectors
    for v in plan.vectors:
        p1, p2 = pts[v.start], pts[v.end]
        if math.dist(p1, p2) < 1e-6:
            continue
        arrow = Arrow(p1, p2, LineType.MAIN, **HEAD)
        items.append(Group((arrow,), name=f"vec {prefix}-{v.start}{v.end}-{tag}"))
    # the points: pole dot, joints of the letters; coincident points share a label
    groups = shared_points(
        (pts[name], name) for name in [plan.pole, *[n for n in plan.points if n != plan.pole]])
    items.append(Circle(pts[plan.pole], 0.6, LineType.MAIN, fill="black"))
    # prefer the side away from the pole
    cx = sum(x for x, _ in pts.values()) / len(pts)
    cy = sum(y for _, y in pts.values()) / len(pts)
    reqs = []
    for xy, names in groups:
        ang = math.degrees(math.atan2(-(xy[1] - cy), xy[0] - cx)) % 360
        prefer = ("e", "ne", "n", "nw", "w", "sw", "s", "se")[int(((ang + 22.5) % 360) // 45)]
        reqs.append(LabelRequest(xy, shared_label(names, plan.pole), LETTER, prefer,
                                 blank=True, cross=False))
    if named is not None:
        reqs += _vector_names(plan, pts, named, (cx, cy))
    eqs: list[str] = []
    for p in plan.points.values():
        if p.source.kind == "intersection" and p.source.equation:
            eqs.append(notation_in(p.source.equation, lang))
    return finish(name, items, reqs, caption, eqs if under is None else list(under),
                  sizing=sizing, under_size=under_size)


#: where along a vector its name may stand, in order of preference: its middle first
NAME_AT = (0.5, 0.35, 0.65, 0.2, 0.8)
#: mm: a vector shorter than this is not named: its name would stand beside another
#: vector as much as beside it; its points' letters, in the order of the plan's equation,
#: say which it is
NAME_MM = 6.0


def _vector_names(plan, pts, named, centre) -> list[LabelRequest]:
    """A label for each vector of ``plan`` of :data:`NAME_MM` or longer: ``named(label)``
    beside it, anchored along it (:data:`NAME_AT`), on the side of it away from
    ``centre``."""
    out = []
    compass = ("e", "ne", "n", "nw", "w", "sw", "s", "se")
    for v in plan.vectors:
        (x1, y1), (x2, y2) = pts[v.start], pts[v.end]
        if math.dist((x1, y1), (x2, y2)) < NAME_MM:
            continue
        along = [(x1 + t * (x2 - x1), y1 + t * (y2 - y1)) for t in NAME_AT]
        mx, my = along[0]
        nx, ny = -(y2 - y1), x2 - x1  # across the vector, to the side away from the middle
        if nx * (mx - centre[0]) + ny * (my - centre[1]) < 0:
            nx, ny = -nx, -ny
        ang = math.degrees(math.atan2(-ny, nx)) % 360
        prefer = compass[int(((ang + 22.5) % 360) // 45)]
        out.append(LabelRequest(along[0], named(v.label), LETTER, prefer, also=tuple(along[1:]),
                                blank=True, cross=False))
    return out
