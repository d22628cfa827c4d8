"""The plan of positions: the mechanism at μl in the positions the plans are built for
(heavy), the cycle's others and the two extreme ones (thin), the trajectories, pivots,
sliders and guides, and the output's stroke H or swing ψ."""

from __future__ import annotations

import cmath
import itertools
import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np
import shapely
from shapely.geometry import Polygon

from drawing.labels import LabelRequest
from drawing.obstacles import obstacles_of
from drawing.scene import Arrow, Circle, Hatch, Item, Polyline, Segment, Text, name_markup, shared_label
from drawing.styles import LineType
from drawing.text import text_width
from drawing.views.common import JOINT_R, LETTER, WORDS, View, finish, shared_points
from drawing.views.inputs import gamma_marks, input_marks
from plans.cycle.positions import drawn
from plans.fmt import num

__all__ = [
    "SWING_AT",
    "SWING_R",
    "AngleMark",
    "centre_of_mass",
    "extreme_letters",
    "guide_dir",
    "guide_slots",
    "link_segments",
    "positions_view",
    "slider_block",
    "slot_segments",
    "support",
    "swing_arc",
    "swing_point",
    "theta_mark",
    "to_sheet",
]

def to_sheet(z: complex, mu_l: float) -> tuple[float, float]:
    return (z.real / mu_l, -z.imag / mu_l)


def centre_of_mass(mech, name: str) -> bool:
    """S1, S2 …: a centre of mass, marked on its link but not drawn as a bar of it;
    never a point where a pair is (a hinge, a slider's point) nor an axis end."""
    if not (name[0] == "S" and name[1:].isdigit() and len(mech.links_of(name)) == 1):
        return False
    return (all(s.point != name for s in mech.sliders)
            and all(name not in (link.axis or ()) for link in mech.links.values()))


def link_segments(mech, pos: dict[str, complex], mu_l: float, line: LineType) -> list[Item]:
    out: list[Item] = []
    slider_links = {s.link for s in mech.sliders}
    for lid, link in mech.links.items():
        names = [n for n in link.points if n in pos and not centre_of_mass(mech, n)]
        if lid in slider_links and len(names) <= 1:
            continue
        if link.axis and link.axis[0] in pos:
            root = link.axis[0]
        elif names:
            root = names[0]
        else:
            continue
        # the farthest point first, so a point on the axis does not make a stub
        for n in names:
            if n != root and abs(pos[n] - pos[root]) > 1e-12:
                out.append(Segment(to_sheet(pos[root], mu_l), to_sheet(pos[n], mu_l), line))
        # a rigid link of three points or more not in line is a plate: its outline closed
        # (the coupler ABE is a triangle, not the bars AB and AE)
        hull = _hull([pos[n] for n in names])
        if len(hull) >= 3:  # the sides the bars from the root do not draw
            out += [Segment(to_sheet(a, mu_l), to_sheet(b, mu_l), line)
                    for a, b in zip(hull, hull[1:] + hull[:1], strict=True)
                    if pos[root] not in (a, b)]
    return out


def _hull(points: list[complex]) -> list[complex]:
    """The corners of the convex hull of ``points``, counter-clockwise; fewer than three
    where they are in line (within 1e-9 of their spread: a coupler point on the link's
    axis, as computed, makes no plate, which shapely's exact hull would)."""
    pts = sorted(set(points), key=lambda z: (z.real, z.imag))
    if len(pts) < 3:
        return pts
    spread = max(abs(p - q) for p in pts for q in pts)

    def turn(o, a, b):  # twice the signed area of o, a, b, over the spread
        return ((a - o).conjugate() * (b - o)).imag / spread

    def half(seq):
        chain: list[complex] = []
        for p in seq:
            while len(chain) >= 2 and turn(chain[-2], chain[-1], p) <= 1e-9 * spread:
                chain.pop()
            chain.append(p)
        return chain

    lower, upper = half(pts), half(reversed(pts))
    hull = lower[:-1] + upper[:-1]
    return hull if len(hull) >= 3 else []


def slider_block(center: tuple[float, float], direction: complex, line: LineType,
           w: float = 8.0, h: float = 5.0) -> Polyline:
    """A slider / slide block: a small rectangle along ``direction`` (model)."""
    ux, uy = direction.real, -direction.imag
    n = math.hypot(ux, uy) or 1.0
    ux, uy = ux / n, uy / n
    vx, vy = -uy, ux
    cx, cy = center
    corners = [
        (cx + sx * ux * w / 2 + sy * vx * h / 2, cy + sx * uy * w / 2 + sy * vy * h / 2)
        for sx, sy in ((-1, -1), (1, -1), (1, 1), (-1, 1))
    ]
    return Polyline(corners, line, closed=True)


def guide_dir(mech, slider, pos) -> complex:
    """The guide's direction in the world: its own direction turned with its link."""
    g = slider.guide
    if g.link == 0:
        return g.direction
    pose = _pose(mech, g.link, pos)
    return g.direction if pose is None else pose[1] * g.direction


def _pose(mech, lid: int, pos) -> tuple[complex, complex] | None:
    """(origin, rotor) of a link with an axis, from its axis points' positions."""
    link = mech.links[lid]
    if not (link.axis and all(a in pos for a in link.axis)):
        return None
    d = pos[link.axis[1]] - pos[link.axis[0]]
    return (pos[link.axis[0]], d / abs(d)) if abs(d) > 1e-12 else None


def _reach(t: list[float]) -> tuple[float, float]:
    """A guide's drawn stretch: the block's travel along it, and a tenth more each way."""
    pad = 0.1 * (max(t) - min(t) + 0.05)
    return min(t) - pad, max(t) + pad


def guide_slots(mech, drawn) -> list[tuple[object, float, float, tuple[float, float] | None]]:
    """The guides carried by moving links (a slot in a rocker or a yoke), each with its
    stretch in its own coordinates along the guide: from the guide's point on its link to
    every place of the block in the positions ``drawn``, kept within twice the link's own
    size, so that a position near a dead point does not stretch it at every position
    (that one is reached by :func:`slot_segments`). A guide along the link's axis lies
    on the link's bar: the bar's stretch is given, and only the part beyond it is drawn."""
    out = []
    for s in mech.sliders:
        g = s.guide
        if g.link == 0:
            continue
        own = mech.links[g.link].points.values()
        size = max((abs(p - q) for p in own for q in own), default=0.0) or 0.1
        t = [0.0]
        for pos in drawn:
            pose = _pose(mech, g.link, pos)
            if pose is not None:
                local = (pos[s.point] - pose[0]) * pose[1].conjugate()
                t.append(((local - g.point) * g.direction.conjugate()).real)
        a, b = _reach(t)
        a, b = max(a, -2 * size), min(b, 2 * size)
        bar = None
        if abs(g.direction.imag) < 1e-12 and abs(g.point.imag) < 1e-12:  # along the axis
            proj = [((p - g.point) * g.direction.conjugate()).real for p in own]
            bar = (min(proj), max(proj))
        out.append((s, a, b, bar))
    return out


def slot_segments(mech, slots, pos, mu_l: float, line: LineType) -> list[Item]:
    out: list[Item] = []
    for s, a, b, bar in slots:
        g = s.guide
        pose = _pose(mech, g.link, pos)
        if pose is None:
            continue
        o, r = pose
        t = (((pos[s.point] - o) * r.conjugate() - g.point) * g.direction.conjugate()).real
        pad = 0.1 * (b - a)
        a, b = min(a, t - pad), max(b, t + pad)  # the block is always on its guide
        if bar is not None:  # only where the block runs past the link's own bar
            lo, hi = bar
            if lo - 1e-9 <= t <= hi + 1e-9:
                continue
            a, b = (hi, t + pad) if t > hi else (t - pad, lo)
        ends = (o + r * (g.point + x * g.direction) for x in (a, b))
        out.append(Segment(*(to_sheet(z, mu_l) for z in ends), line))
    return out


def support(xy: tuple[float, float]) -> list[Item]:
    """A fixed pivot: a small triangle standing on a hatched base."""
    x, y = xy
    return [
        Polyline([(x, y), (x - 3, y + 5), (x + 3, y + 5)], LineType.MAIN, closed=True),
        Hatch((x - 5, y + 5), (x + 5, y + 5), side=1, spacing=1.6, length=2.0),
    ]


def positions_view(sol, cycle, lang: str = "ru", sizing: bool = False,
                   heavy: list[int] | None = None, marks: Sequence[AngleMark] = ()) -> View:
    """Plan of positions at μl: the positions the plans are built for heavy, the cycle's
    other positions and the two extreme ones thin, trajectories, pivots, sliders, stroke
    H; the positions drawn are the engine's (:func:`plans.cycle.positions.drawn`, worked out
    once per solver). ``heavy``: the numbers of the cycle's positions the sheet draws
    plans for (``--plans``), drawn heavy and numbered, the points lettered on the first;
    the given position (``sol``'s), which has no plans then, is not drawn. None: the
    given position heavy, the plans being its own.

    The inputs (the crank's ω1 as an arc arrow in its sense) and γ where it falls lowest
    are drawn as :mod:`drawing.views.inputs` draws them; the extreme positions'
    moving joints are lettered ′ and ″ as the note names them (H = D′D″·μl, ψ = ∠C′DC″),
    ′ the one the working stroke starts from; θ and any other angle of ``marks``
    (:class:`AngleMark`) are marked with their arcs."""
    mech, mu_l = sol.mechanism, sol.mu_l
    shown = drawn(sol.solver, cycle)
    main = _heavy_positions(sol, shown, heavy)
    motion_all = shown.motion_all
    items: list[Item] = []
    over: list[Item] = []  # drawn over the breaks under labels
    labels: list[LabelRequest] = []

    # trajectories, where they stay near the mechanism
    valid = shown.trajectory
    for name in shown.traced:
        z = np.asarray(motion_all.position[name])
        run: list[tuple[float, float]] = []
        for ok, zz in zip(valid, z, strict=True):
            if ok:
                run.append(to_sheet(complex(zz), mu_l))
            elif len(run) > 1:
                items.append(Polyline(run, LineType.DASHED if name != mech.driver.tip else LineType.THIN))
                run = []
            else:
                run = []
        if len(run) > 1:
            closed = bool(valid.all()) and cycle.full_turn
            items.append(Polyline(run, LineType.DASHED if name != mech.driver.tip else LineType.THIN,
                                  closed=closed))
    # the positions drawn: the cycle's, numbered, the extreme ones, and the given one
    cycle_pos, extremes = shown.cycle, shown.extremes
    drawn_at = [p for p in (*cycle_pos, *extremes, *main) if p is not None]
    # fixed guides: the axis dash-dot over the slider's reach in the positions drawn
    for s in mech.sliders:
        if s.guide.link != 0:
            continue
        d = s.guide.direction
        a, b = _reach([((p[s.point] - s.guide.point) * d.conjugate()).real for p in drawn_at])
        items.append(Segment(to_sheet(s.guide.point + a * d, mu_l), to_sheet(s.guide.point + b * d, mu_l),
                             LineType.DASH_DOT_THIN))
    tip = mech.driver.tip
    slots = guide_slots(mech, drawn_at)
    for k, pos in enumerate(cycle_pos):
        if pos is None:
            continue
        if not any(pos is p for p in main):  # a heavy one is drawn below, numbered here
            items += link_segments(mech, pos, mu_l, LineType.THIN)
            items += slot_segments(mech, slots, pos, mu_l, LineType.THIN)
        labels.append(LabelRequest(to_sheet(pos[tip], mu_l), str(k), 2.5, "ne", markup=False,
                                   optional=True))
    for pos in extremes:
        if pos is None:
            continue
        items += link_segments(mech, pos, mu_l, LineType.DASH_DOUBLE_DOT_THIN)
        items += slot_segments(mech, slots, pos, mu_l, LineType.DASH_DOUBLE_DOT_THIN)
    # the heavy positions; centres of mass as small dots on their links; every heavy
    # line before the joints, whose white rings would cut another position's links
    for pos in main:
        items += link_segments(mech, pos, mu_l, LineType.MAIN)
        items += slot_segments(mech, slots, pos, mu_l, LineType.MAIN)
    for pos in main:
        for n in pos:
            if n in mech.point_names() and centre_of_mass(mech, n):
                items.append(Circle(to_sheet(pos[n], mu_l), 0.6, LineType.MAIN, fill="black"))
        for s in mech.sliders:
            if s.point in pos:
                items.append(slider_block(to_sheet(pos[s.point], mu_l), guide_dir(mech, s, pos),
                                    LineType.MAIN))
    pos = main[0]  # the one lettered
    for name in mech.frame:
        items += support(to_sheet(pos[name], mu_l))
    # the joints (points of two links or more) are the mechanism's: found once, ringed
    # in each heavy position
    joints = sorted({n for link in mech.links.values() for n in link.points
                     if len(mech.links_of(n)) > 1})
    for at in main:
        items += [Circle(to_sheet(at[n], mu_l), JOINT_R, LineType.MAIN, fill="white")
                  for n in joints if n in at]
    shared = shared_points((to_sheet(pos[n], mu_l), n) for n in mech.point_names() if n in pos)
    for xy, names in reversed(shared):
        # close to its point even among the other positions' lines, which break for it
        labels.insert(0, LabelRequest(xy, shared_label(names), LETTER, "nw",
                                      blank=True))
    # the inputs drawn as such, γ marked where it falls lowest (drawing/views/inputs.py)
    inputs, marked = input_marks(sol, pos, to_sheet, lang)
    gamma_items, gamma_labels = gamma_marks(sol, cycle, pos, to_sheet, lang)
    items += inputs + gamma_items
    labels += marked + gamma_labels
    # stroke H of a linear output
    out = cycle.output
    w = WORDS[lang]
    ends = len(extremes) == 2 and all(e is not None for e in extremes)
    if out is not None and cycle.stroke and out.kind == "linear" and ends:
        p1, p2 = (to_sheet(e[out.point], mu_l) for e in extremes)
        items += _stroke_dimension(items, p1, p2, mech.slider_of(out.link).guide.direction,
                                   f"H = {num(cycle.stroke, 4, lang)} {w['m']}")
    # swing ψ of a rocker: an arc between its two extreme positions, about its pivot
    if out is not None and cycle.stroke and out.kind == "angular" and ends:
        arm = out.arm(mech)
        if arm is not None:
            pivot, tip = arm
            a, b = extremes[0][tip], extremes[1][tip]
            over += swing_arc(pos[pivot], a, b, mu_l)  # its value's break must not cut it
            along = [to_sheet(swing_point(pos[pivot], a, b, t), mu_l) for t in SWING_AT]
            deg = math.degrees(cycle.stroke)
            labels.append(LabelRequest(along[0], f"{w['swing']} = {num(deg, 4, lang)}°",
                                       3.5, "n", markup=False, also=tuple(along[1:]),
                                       blank=True))
    # the extreme positions lettered; θ and the other marks
    if cycle.full_turn and cycle.stroke and ends:
        labels += [LabelRequest(to_sheet(e[n], mu_l), name_markup(n) + prime, LETTER, "ne", blank=True)
                   for e, prime in zip(extremes, ("′", "″"), strict=True)
                   for n in extreme_letters(mech, e)]
    theta = theta_mark(cycle, extremes, mech.driver, lang)
    for mark in ([theta] if theta is not None else []) + list(marks):
        lines, arc, req = _angle_items(mark, mu_l)
        items += lines
        over += arc
        labels.append(req)
    caption = f"{w['positions']}, μ_l = {num(mu_l, 4, lang)} {w['m']}/{w['mm']}"
    under = [w["left_off"].format(k=", ".join(map(str, shown.left_off)),
                                  d=num(shown.limit, 2, lang))] if shown.left_off else []
    return finish("positions", items, labels, caption, under, pad=8.0, over=over,
                   sizing=sizing)


def _heavy_positions(sol, shown, heavy: list[int] | None) -> list[dict[str, complex]]:
    """The positions drawn heavy: the cycle's positions numbered ``heavy`` (one drawn
    once, in the order given), the given position where there are none (None: no
    ``--plans``), or where every one of them is left off the drawing (a point runs far
    out: :func:`plans.cycle.positions.drawn`), so that the points have a position to be
    lettered on."""
    if heavy is None:
        return [sol.positions]
    main: list[dict[str, complex]] = []
    for k in heavy:
        pos = shown.cycle[k]
        if pos is not None and not any(pos is p for p in main):
            main.append(pos)
    return main or [sol.positions]


def _stroke_dimension(items, p1, p2, direction: complex, value: str) -> list[Item]:
    """The stroke H between the output's extreme positions ``p1``, ``p2`` (sheet mm), a
    dimension parallel to its guide (``direction``, in the world) and clear of the drawing
    ``items``: extension lines, a dimension line with two arrows, the value above it,
    or on a shelf beyond its end where it has no room between the extension lines.

    It stands on the side of the guide where its extension lines are shortest, below a
    horizontal guide unless above is shorter: what it must clear is only what lies across
    its own span along the guide, so a guide above the whole mechanism (a press's) has
    its stroke just above it, not under the mechanism with lines crossing all of it."""
    ux, uy = direction.real, -direction.imag  # the sheet's y points down
    if ux < -1e-12 or (abs(ux) <= 1e-12 and uy > 0):
        ux, uy = -ux, -uy  # read from left to right, or from the bottom up
    nx, ny = -uy, ux  # below a horizontal guide; the value stands on the −n side of its line
    width = text_width(value, 3.5)
    lo, hi = sorted((p[0] - p1[0]) * ux + (p[1] - p1[1]) * uy for p in (p1, p2))
    on_shelf = width + 2.0 > hi - lo
    hi += 2.0 + (width + 3.0 if on_shelf else 0.0)  # the shelf runs on beyond the far end
    lo -= 2.0
    strip = Polygon([(p1[0] + ux * a + nx * b, p1[1] + uy * a + ny * b)
                     for a, b in ((lo, -1e4), (hi, -1e4), (hi, 1e4), (lo, 1e4))])
    across = shapely.get_coordinates([g.intersection(strip) for g in obstacles_of(items, clearance=0.0)])
    across = (across - p1) @ np.array([nx, ny])
    reach = {side: float(np.max(side * across, initial=0.0)) + 8.0 for side in (1.0, -1.0)}
    side = -1.0 if reach[-1.0] < reach[1.0] - 1.0 else 1.0  # above only where shorter
    ox, oy = side * nx, side * ny  # from the guide to the dimension line

    def at(p, t):  # the point t beyond the dimension line on the extension line from p
        k = reach[side] - ((p[0] - p1[0]) * ox + (p[1] - p1[1]) * oy)
        return (p[0] + ox * (k + t), p[1] + oy * (k + t))

    d1, d2 = at(p1, 0.0), at(p2, 0.0)
    mid = ((d1[0] + d2[0]) / 2, (d1[1] + d2[1]) / 2)
    out: list[Item] = [Segment(p1, at(p1, 2.0), LineType.THIN), Segment(p2, at(p2, 2.0), LineType.THIN),
                       Arrow(mid, d1, LineType.THIN, 3.0, 1.0), Arrow(mid, d2, LineType.THIN, 3.0, 1.0)]
    turn = math.degrees(math.atan2(uy, ux))  # clockwise on the sheet, as Text takes it
    if not on_shelf:
        out.append(Text((mid[0] - nx, mid[1] - ny), value, size=3.5, anchor="middle", rotate_deg=turn))
    else:  # no room between the extension lines: on a shelf beyond the far one (GOST 2.307)
        end = d2 if (d2[0] - d1[0]) * ux + (d2[1] - d1[1]) * uy > 0 else d1
        out.append(Segment(end, (end[0] + ux * (width + 3.0), end[1] + uy * (width + 3.0)), LineType.THIN))
        out.append(Text((end[0] + ux * 1.5 - nx, end[1] + uy * 1.5 - ny), value, size=3.5,
                        rotate_deg=turn))
    return out


#: the swing arc's radius, as a share of the rocker's arm
SWING_R = 0.55
#: where along the arc ψ's value may stand, in order of preference: its middle first
SWING_AT = (0.5, 0.35, 0.65, 0.2, 0.8)


def swing_point(pivot: complex, a: complex, b: complex, t: float) -> complex:
    """The point at share ``t`` along the arc from the arm's direction at ``a`` to ``b``
    (the shorter way round), at :data:`SWING_R` of the arm."""
    ra, rb = a - pivot, b - pivot
    turn = math.atan2((ra.conjugate() * rb).imag, (ra.conjugate() * rb).real)
    r = SWING_R * min(abs(ra), abs(rb))
    return pivot + r * (ra / abs(ra)) * complex(math.cos(t * turn), math.sin(t * turn))


def swing_arc(pivot: complex, a: complex, b: complex, mu_l: float) -> list[Item]:
    """The dimension arc of ψ with an arrowhead at each end."""
    pts = [to_sheet(swing_point(pivot, a, b, k / 48), mu_l) for k in range(49)]
    length = sum(math.dist(p, q) for p, q in itertools.pairwise(pts))  # mm on the sheet
    out: list[Item] = [Polyline(pts, LineType.THIN)]
    if length > 8.0:  # room for the two 3 mm heads
        t = 3.0 / length
        for end, inner in ((pts[0], t), (pts[-1], 1 - t)):
            out.append(Arrow(to_sheet(swing_point(pivot, a, b, inner), mu_l), end,
                             LineType.THIN, 3.0, 1.0))
    return out


def extreme_letters(mech, pos: dict[str, complex]) -> list[str]:
    """The points lettered in an extreme position: the moving joints (a point of two
    links or more) and the output's point, but the crank's pin, which is lettered on the
    heavy position and numbered on every one, and a point where it is (a slide block's
    A3 on its pin A)."""
    tip = pos.get(mech.driver.tip)
    names = sorted({n for link in mech.links.values() for n in link.points
                    if len(mech.links_of(n)) > 1 and n in pos and n not in mech.frame})
    return [n for n in names if tip is None or abs(pos[n] - tip) > 1e-9 * (1 + abs(tip))]


@dataclass(frozen=True)
class AngleMark:
    """An angle marked on the plan of positions (world coordinates, m): an arc about
    ``vertex`` from its ray towards ``a`` to its ray towards ``b``, the shorter way, at
    ``share`` of the shorter ray (within :data:`ARC_MM` on the sheet); the rays drawn
    thin to :data:`RAY_PAST` beyond the arc, and ``label`` beside it. θ is one
    (:func:`theta_mark`). The plan of positions takes any others
    (``positions_view(marks=…)``), an angle a task asks for beyond θ, ψ and γ (those
    three the view marks itself)."""

    vertex: complex
    a: complex
    b: complex
    label: str
    share: float = 0.4


#: mm: the radius of an angle's arc on the sheet, at least and at most; its rays run
#: RAY_PAST beyond it
ARC_MM = (10.0, 30.0)
RAY_PAST = 4.0
#: below this, θ (deg) is not marked: K = 1, the strokes take equal crank turns
THETA_LEAST = 0.5


def theta_mark(cycle, extremes, driver, lang: str = "ru") -> AngleMark | None:
    """θ, the angle between the crank's positions at the two extremes, one turned
    through 180° (the working stroke takes 180° + θ of the crank's turn): at the crank's
    pivot, between the ray to the pin at ′ and the ray away from it at ″ (a crank-rocker's
    connecting rod lies along both). None where the crank does not turn all the way, θ
    is under :data:`THETA_LEAST` or an extreme position is not drawn."""
    if (not cycle.full_turn or cycle.theta is None or math.degrees(cycle.theta) < THETA_LEAST
            or len(extremes) != 2 or any(e is None for e in extremes)):
        return None
    first, second = extremes
    o = first[driver.pivot]
    u1, u2 = first[driver.tip] - o, -(second[driver.tip] - o)
    return AngleMark(o, o + driver.length * u1 / abs(u1), o + driver.length * u2 / abs(u2),
                     f"θ = {num(math.degrees(cycle.theta), 4, lang)}°", share=0.6)


def _arc_points(vertex: complex, start: complex, turn: float, r: float, n: int = 48) -> list[complex]:
    """``n`` + 1 points of the arc of radius ``r`` about ``vertex`` from the direction of
    ``start`` through the angle ``turn`` (rad, counter-clockwise in the world)."""
    u = start / abs(start)
    return [vertex + r * u * cmath.exp(1j * turn * k / n) for k in range(n + 1)]


def _angle_items(mark: AngleMark, mu_l: float) -> tuple[list[Item], list[Item], LabelRequest]:
    """(the rays, the arc with its arrowheads, the request for its label) of ``mark``."""
    v = mark.vertex
    ra, rb = mark.a - v, mark.b - v
    turn = cmath.phase(rb / ra)  # the shorter way round
    r_mm = min(max(mark.share * min(abs(ra), abs(rb)) / mu_l, ARC_MM[0]), ARC_MM[1])
    r = r_mm * mu_l
    rays = [Segment(to_sheet(v, mu_l), to_sheet(v + (r_mm + RAY_PAST) * mu_l * d / abs(d), mu_l),
                    LineType.THIN) for d in (ra, rb)]
    pts = [to_sheet(z, mu_l) for z in _arc_points(v, ra, turn, r)]
    length = sum(math.dist(p, q) for p, q in itertools.pairwise(pts))
    arc: list[Item] = [Polyline(pts, LineType.THIN)]
    if length > 8.0:  # room for the two 3 mm heads
        t = 3.0 / length
        for end, inner in ((pts[0], t), (pts[-1], 1 - t)):
            at = to_sheet(_arc_points(v, ra, turn * inner, r, 1)[-1], mu_l)
            arc.append(Arrow(at, end, LineType.THIN, 3.0, 1.0))
    along = [to_sheet(_arc_points(v, ra, turn * t, r, 1)[-1], mu_l) for t in SWING_AT]
    out = to_sheet(_arc_points(v, ra, turn / 2, r + 1.0, 1)[-1], mu_l)  # outward from v
    prefer = _compass(out[0] - along[0][0], out[1] - along[0][1])
    return rays, arc, LabelRequest(along[0], mark.label, 3.5, prefer, markup=False,
                                   also=tuple(along[1:]), blank=True)


def _compass(dx: float, dy: float) -> str:
    """The compass direction on the sheet (y down) nearest to (dx, dy)."""
    a = math.degrees(math.atan2(-dy, dx)) % 360.0
    return ("e", "ne", "n", "nw", "w", "sw", "s", "se")[int((a + 22.5) // 45) % 8]
