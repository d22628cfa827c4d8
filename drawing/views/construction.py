"""The views of the synthesis sheet: the graphical construction at μl as the textbooks draw
it (every construction line thin, every point and angle lettered, the resulting mechanism
in main lines), the family's figure of merit over its free parameter, and the table of
results with the engine's check.

The construction is the synthesis's own record (:class:`plans.synthesis.Mark`); the
mechanism in main lines is the engine's position of the written file at its crank angle.
"""

from __future__ import annotations

import cmath
import math

import numpy as np

from drawing.labels import LabelRequest
from drawing.scene import Circle, Hatch, Item, Polyline, Segment, Text, name_markup
from drawing.styles import LineType
from drawing.text import text_width
from drawing.views.common import JOINT_R, LETTER, View, bbox, captioned, finish, shifted
from drawing.views.positions import link_segments
from plans.fmt import num
from plans.kinematics.solver import Solver
from plans.synthesis.words import WORDS as SYNTH_WORDS
from plans.synthesis.words import grashof_in

__all__ = ["WORDS", "construction_view", "extent", "family_view", "results_view"]

WORDS = {
    "ru": {"construction": "Построение", "family": "Семейство решений", "results": "Результаты синтеза",
           "quantity": "Величина", "value": "Значение", "drawing": "На чертеже, мм",
           "check": "Проверка анализом (plans cycle): {what}; расхождение {d}",
           "chosen": "выбрано", "m": "м", "mm": "мм", "given": "задано"},
    "en": {"construction": "Construction", "family": "The family of solutions", "results": "Results",
           "quantity": "Quantity", "value": "Value", "drawing": "On the drawing, mm",
           "check": "Checked by analysis (plans cycle): {what}; difference {d}",
           "chosen": "chosen", "m": "m", "mm": "mm", "given": "given"},
}

_COMPASS = ("e", "ne", "n", "nw", "w", "sw", "s", "se")


def _sheet(z: complex, mu_l: float) -> tuple[float, float]:
    return (z.real / mu_l, -z.imag / mu_l)


def _toward(dx: float, dy: float) -> str:
    """The compass direction (on the sheet, y down) nearest to (dx, dy)."""
    a = math.degrees(math.atan2(-dy, dx)) % 360.0
    return _COMPASS[int((a + 22.5) // 45) % 8]


def _letters(label: str) -> str:
    """A point's label as markup: C1 → C₁ (``C_{1}``); other text as it is."""
    return name_markup(label) if label[:1].isalpha() and label[1:].isdigit() else label


def positions_of(check) -> dict[str, complex]:
    """The engine's positions of the written mechanism at its own crank angle."""
    mech = check.mechanism
    return Solver(mech).solve_one(mech.param).position


def extent(design, check) -> tuple[float, float, float, float]:
    """(xmin, ymin, xmax, ymax) in m of everything the construction view draws."""
    pts: list[complex] = []
    for m in design.solution.marks:
        if m.kind == "circle":
            c, r = m.points[0], abs(m.points[1] - m.points[0])
            pts += [c + r, c - r, c + 1j * r, c - 1j * r]
        elif m.kind == "angle":  # its sides are drawn by other marks
            pts.append(m.points[0])
        else:
            pts += list(m.points)
    pts += list(positions_of(check).values())
    xs, ys = [z.real for z in pts], [z.imag for z in pts]
    return min(xs), min(ys), max(xs), max(ys)


def _arc(centre: complex, r: float, a0: float, a1: float, mu_l: float, n: int = 90) -> Polyline:
    """The arc of radius ``r`` (m) about ``centre`` from angle a0 counter-clockwise to a1."""
    span = (a1 - a0) % (2 * math.pi)
    ts = a0 + span * np.linspace(0.0, 1.0, max(n, 8))
    return Polyline([_sheet(centre + r * cmath.exp(1j * t), mu_l) for t in ts], LineType.THIN)


def _support(xy: tuple[float, float]) -> list[Item]:
    x, y = xy
    return [Polyline([(x, y), (x - 3, y + 5), (x + 3, y + 5)], LineType.MAIN, closed=True),
            Hatch((x - 5, y + 5), (x + 5, y + 5), side=1, spacing=1.6, length=2.0)]


def _block(xy: tuple[float, float], direction: complex, w: float = 8.0, h: float = 5.0) -> Polyline:
    ux, uy = direction.real / abs(direction), -direction.imag / abs(direction)
    vx, vy = -uy, ux
    cx, cy = xy
    return Polyline([(cx + sx * ux * w / 2 + sy * vx * h / 2, cy + sx * uy * w / 2 + sy * vy * h / 2)
                     for sx, sy in ((-1, -1), (1, -1), (1, 1), (-1, 1))], LineType.MAIN, closed=True)


def construction_view(design, check, mu_l: float, lang: str = "ru", sizing: bool = False) -> View:
    """The construction at ``mu_l`` (m/mm) and the mechanism in main lines."""
    items: list[Item] = []
    over: list[Item] = []
    labels: list[LabelRequest] = []
    lettered: set[str] = set()
    sol = design.solution
    points = [m for m in sol.marks if m.kind == "point"]
    for m in sol.marks:
        p = m.points
        if m.kind == "line":
            items.append(Segment(_sheet(p[0], mu_l), _sheet(p[1], mu_l), LineType.THIN))
        elif m.kind == "thin":
            items.append(Segment(_sheet(p[0], mu_l), _sheet(p[1], mu_l), LineType.DASH_DOUBLE_DOT_THIN))
        elif m.kind == "guide":
            d = (p[1] - p[0]) / abs(p[1] - p[0])
            pad = 0.15 * abs(p[1] - p[0])
            items.append(Segment(_sheet(p[0] - pad * d, mu_l), _sheet(p[1] + pad * d, mu_l),
                                 LineType.DASH_DOT_THIN))
        elif m.kind == "circle":
            r = abs(p[1] - p[0]) / mu_l
            items.append(Circle(_sheet(p[0], mu_l), r, LineType.THIN))
        elif m.kind == "arc":  # the shorter way round from one end to the other
            c = p[0]
            a0, a1 = cmath.phase(p[1] - c), cmath.phase(p[2] - c)
            if (a1 - a0) % (2 * math.pi) > math.pi:
                a0, a1 = a1, a0
            items.append(_arc(c, abs(p[1] - c), a0, a1, mu_l))
        elif m.kind == "angle":
            over_items, req = _angle(m, mu_l)
            over += over_items
            labels.append(req)
        elif m.kind == "length" and len(m.label) == 1:  # H, e, h, f: lettered at its middle
            mid = _sheet((p[0] + p[1]) / 2, mu_l)
            dx, dy = (p[1] - p[0]).real, -(p[1] - p[0]).imag
            labels.append(LabelRequest(mid, m.label, LETTER, _toward(-dy, dx)))
    # the mechanism in main lines at the written file's crank angle (the engine's)
    mech = check.mechanism
    pos = positions_of(check)
    items += link_segments(mech, pos, mu_l, LineType.MAIN)
    for s in mech.sliders:
        direction = s.guide.direction
        if s.guide.link != 0:  # a block on a rocker: along the rocker
            link = mech.links[s.guide.link]
            direction = pos[link.axis[1]] - pos[link.axis[0]]
        point = s.point if s.point in pos else next(iter(mech.links[s.link].points))
        items.append(_block(_sheet(pos[point], mu_l), direction))
    for name in mech.frame:
        items += _support(_sheet(pos[name], mu_l))
    joints = sorted({n for link in mech.links.values() for n in link.points
                     if len(mech.links_of(n)) > 1 or n in mech.frame})
    for n in joints:
        items.append(Circle(_sheet(pos[n], mu_l), JOINT_R, LineType.MAIN, fill="white"))
    for m in points:
        items.append(Circle(_sheet(m.points[0], mu_l), 0.5, LineType.THIN, fill="black"))
        labels.insert(0, LabelRequest(_sheet(m.points[0], mu_l), _letters(m.label), LETTER, "nw"))
        lettered.add(m.label)
    for n in joints:
        if n not in lettered:
            labels.insert(0, LabelRequest(_sheet(pos[n], mu_l), _letters(n), LETTER, "ne"))
    w = WORDS[lang]
    caption = f"{w['construction']}, μ_l = {num(mu_l, 4, lang)} {w['m']}/{w['mm']}"
    return finish("construction", items, labels, caption, [], pad=8.0, over=over, sizing=sizing)


def _angle(m, mu_l: float) -> tuple[list[Item], LabelRequest]:
    """An angle's arc at its vertex between its two sides (the smaller angle), and the
    request for its letter just outside the arc's middle."""
    v, p, q = m.points
    a0, a1 = cmath.phase(p - v), cmath.phase(q - v)
    if (a1 - a0) % (2 * math.pi) > math.pi:
        a0, a1 = a1, a0
    shortest = min(abs(p - v), abs(q - v)) / mu_l
    r_mm = max(5.0, min(14.0, 0.3 * shortest))
    r = r_mm * mu_l
    arc = _arc(v, r, a0, a1, mu_l, 40)
    mid = a0 + ((a1 - a0) % (2 * math.pi)) / 2
    at = v + r * cmath.exp(1j * mid)
    x, y = _sheet(at, mu_l)
    dx, dy = math.cos(mid), -math.sin(mid)
    return [arc], LabelRequest((x, y), m.label, 3.5, _toward(dx, dy), markup=False)


def family_view(design, lang: str = "ru") -> View | None:
    """The family's γmin (or largest pressure angle) over u, each branch a line, the chosen
    member marked; None where the requirements fix the member."""
    if design.why not in ("best", "size") or not design.curves:
        return None
    curves = [c for c in design.curves if np.isfinite(c.y).any()]
    if not curves:
        return None
    xs = np.concatenate([c.shown(c.x) for c in curves])
    ys = np.concatenate([np.degrees(c.y) for c in curves])
    ok = np.isfinite(ys)
    x0, x1 = float(xs[ok].min()), float(xs[ok].max())
    y1 = float(np.nanmax(ys)) * 1.1
    W, H = 120.0, 70.0

    def at(x, y):
        return (W * (x - x0) / (x1 - x0), H - H * y / y1)

    items: list[Item] = [Segment((0, H), (W, H), LineType.THIN), Segment((0, 0), (0, H), LineType.THIN)]
    for k, c in enumerate(curves):
        cx = c.shown(c.x)
        cy = np.degrees(c.y)
        run: list[tuple[float, float]] = []
        for x, y in zip(cx, cy, strict=True):
            if math.isfinite(y):
                run.append(at(x, y))
            elif len(run) > 1:
                items.append(Polyline(run, LineType.MAIN if k == 0 else LineType.DASHED))
                run = []
            else:
                run = []
        if len(run) > 1:
            items.append(Polyline(run, LineType.MAIN if k == 0 else LineType.DASHED))
    sol = design.solution
    fig = sol.figures["gamma_min" if curves[0].figure == "gamma_min" else "delta_m"]
    xp = float(curves[0].shown(sol.param)) if sol.param is not None else x0
    px, py = at(xp, math.degrees(fig))
    items += [Circle((px, py), 1.2, LineType.MAIN, fill="black"),
              Segment((px, py), (px, H), LineType.THIN)]
    texts: list[Item] = []
    for x in _ticks(x0, x1):
        tx, _ = at(x, 0)
        items.append(Segment((tx, H), (tx, H + 1.5), LineType.THIN))
        texts.append(Text((tx, H + 5.5), num(float(x), 3, lang), 2.5, anchor="middle"))
    for y in _ticks(0.0, y1 / 1.1):
        _, ty = at(x0, y)
        items.append(Segment((-1.5, ty), (0, ty), LineType.THIN))
        texts.append(Text((-2.5, ty + 1.25), num(float(y), 3, lang), 2.5, anchor="end"))
    sym = "γ_{min}, °" if curves[0].figure == "gamma_min" else "δ_{max}, °"
    texts.append(Text((2, -3), sym, 3.5, markup=True))
    unit = {"°": ", °", "m": f", {WORDS[lang]['m']}"}.get(curves[0].unit, "")
    name = {"t_A": "t_{A}", "CD/AD": "l_{CD}/l_{AD}"}.get(curves[0].parameter, curves[0].parameter)
    texts.append(Text((W, H + 11), name + unit, 3.5, anchor="end", markup=True))
    texts.append(Text((px + 2, py - 2), f"{num(math.degrees(fig), 4, lang)}°", 2.5))
    for k, c in enumerate(curves):
        y = H + 17 + 5 * k
        items.append(Segment((0, y - 1), (10, y - 1), LineType.MAIN if k == 0 else LineType.DASHED))
        texts.append(Text((12, y), SYNTH_WORDS[lang]["curves"].get(c.label, c.label), 2.5,
                          italic=False))
    return _framed("family", items + texts, WORDS[lang]["family"])


def _ticks(lo: float, hi: float, most: int = 6) -> list[float]:
    """Round values from ``lo`` to ``hi``, at most ``most``, steps of 1, 2, 2.5 or 5 × 10ⁿ.

    >>> _ticks(10.1, 83.9)
    [20.0, 40.0, 60.0, 80.0]
    """
    span = hi - lo
    if span <= 0:
        return [lo]
    k = math.floor(math.log10(span / most))
    for m in (1.0, 2.0, 2.5, 5.0, 10.0):
        step = m * 10.0**k
        if span / step <= most:
            break
    first = math.ceil(lo / step - 1e-9) * step
    return [round(first + i * step, 10) for i in range(int((hi - first) / step + 1e-9) + 1)]


def _framed(name: str, items: list[Item], caption: str) -> View:
    return captioned(name, items, bbox(items), caption, [])


def results_view(design, check, mu_l: float, lang: str = "ru") -> View:
    """The table of results: every link and figure, the lengths also in mm at μl, and the
    engine's check in a line under it."""
    w = WORDS[lang]
    sol = design.solution

    def n(x, d=5):
        return num(x, d, lang)

    rows: list[tuple[str, str, str]] = []
    for key, value in sol.lengths.items():
        name = {"e": "e", "h": "h"}.get(key, f"l_{{{key}}}")
        rows.append((name, f"{n(value)} {w['m']}", n(value / mu_l, 4)))
    for m in sol.marks:
        if m.kind == "length" and m.label[:2] in ("AC", "EC"):
            name = m.label.split(" = ")[0]
            rows.append((_letters_eq(name), f"{n(m.value)} {w['m']}", n(m.value / mu_l, 4)))
    f = sol.figures
    for key, sym in (("theta", "θ"), ("psi", "ψ"), ("gamma_min", "γ_{min}"), ("delta_m", "δ_{max}"),
                     ("delta_p", "δ_{p}"), ("alpha_max", "α_{max}")):
        if key in f:
            rows.append((sym, f"{num(math.degrees(f[key]), 5, lang)}°", ""))
    if "K" in f:
        rows.append(("K", n(f["K"]), ""))
    head = (w["quantity"], w["value"], w["drawing"])
    size = 3.5
    pitch = 7.0
    widths = [max(text_width(_plain(r[i]), size) for r in (*rows, head)) + 6 for i in range(3)]
    xs = [0.0, widths[0], widths[0] + widths[1]]
    total = sum(widths)
    items: list[Item] = []
    y = 0.0
    for k, row in enumerate((head, *rows)):
        items.append(Segment((0, y), (total, y), LineType.MAIN if k <= 1 else LineType.THIN))
        for i, cell in enumerate(row):
            items.append(Text((xs[i] + 2, y + pitch - 2), cell, size, markup=(k > 0 and i == 0)))
        y += pitch
    items.append(Segment((0, y), (total, y), LineType.MAIN))
    for x in (*xs, total):
        items.append(Segment((x, 0), (x, y), LineType.MAIN if x in (0, total) else LineType.THIN))
    what = ", ".join(r.name for r in check.rows)
    line = w["check"].format(what=what, d=num(check.worst, 2, lang))
    items.append(Text((0, y + 6), line, 2.5, italic=False))
    if check.grashof:
        items.append(Text((0, y + 11), grashof_in(check.grashof, lang), 2.5, italic=False))
    items = shifted(items, 0, 0)
    return _framed("results", items, w["results"])


def _letters_eq(name: str) -> str:
    """"AC1" → "AC_{1}"."""
    return name[:-1] + "_{" + name[-1] + "}" if name[-1:].isdigit() else name


def _plain(s: str) -> str:
    return s.replace("_{", "").replace("}", "")
