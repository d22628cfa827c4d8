"""Zhukovsky's lever (рычаг Жуковского) on sheet 2: the velocity plan turned by 90° at μv,
every load at the image of its point, the arm h of each from the pole, and the balancing
force F_у at the image of the crank pin.

    Σ M_p(F_i) + M_p(F_у) = 0:  F_у = Σ ±F_i·h_i / pb

The turned plan's vectors are drawn at their length (``vec l-pb``), so is each arm (a
group of class ``arm NAME``): both can be measured on the sheet against the lever's table.
"""

from __future__ import annotations

import math

from drawing.labels import LabelRequest
from drawing.scene import Arrow, Circle, Group, Item, Segment, shared_label
from drawing.styles import LineType
from drawing.views.arrows import ARROW, beside, compass, force_arrow, rays
from drawing.views.common import HEAD, LETTER, View, finish, per_mm, shared_points
from drawing.views.forces import UNDER, force_markup
from plans.fmt import decimal, num
from plans.plan.solution import plan_name

__all__ = ["LEVER_WORDS", "arm_numbers", "lever_view", "turned"]

LEVER_WORDS = {
    "ru": {"lever": "Рычаг Жуковского", "ms": "м/с", "N": "Н", "Nm": "Н·м",
           "equation": "F_у = ΣF_i·h_i / p{tip} = {sum} Н·мм / {pb} мм = {F} Н",
           "moment": "M_у = F_у·l_{{{crank}}} = {M} Н·м (расхождение с планами сил {d} %)"},
    "en": {"lever": "Zhukovsky's lever", "ms": "m/s", "N": "N", "Nm": "N·m",
           "equation": "F_у = ΣF_i·h_i / p{tip} = {sum} N·mm / {pb} mm = {F} N",
           "moment": "M_у = F_у·l_{{{crank}}} = {M} N·m ({d} % from the force plans' M_у)"},
}


def turned(value: complex, mu_v: float) -> tuple[float, float]:
    """A velocity's image on the lever, in sheet mm from the pole: turned by +90° at
    ``mu_v`` (y down on the sheet)."""
    z = 1j * value / mu_v
    return (z.real, -z.imag)


def lever_view(forces, mu_v: float, lang: str = "ru", sizing: bool = False) -> View:
    """The lever of ``forces`` (:class:`plans.forces.summary.Forces`) drawn at ``mu_v``: the
    velocity plan turned by 90° (its vectors heavy), each load an arrow (:data:`ARROW`, its
    direction, not its size) at the image of its point with its arm h from the pole thin,
    F_у at the image of the crank pin; the lever's equation under it."""
    fa, lv = forces.analysis, forces.lever
    sol = fa.solution
    mech = sol.mechanism
    d = mech.driver
    w = LEVER_WORDS[lang]
    plan = sol.velocity
    k = lv.mu_v / mu_v  # the engine's lever is at its own μv: its mm scale with 1/μv
    pts = {n: turned(p.value, mu_v) for n, p in plan.points.items()}
    pts[plan.pole] = (0.0, 0.0)
    items: list[Item] = []
    for v in plan.vectors:
        p1, p2 = pts[v.start], pts[v.end]
        if math.dist(p1, p2) < 1e-6:
            continue
        items.append(Group((Arrow(p1, p2, LineType.MAIN, **HEAD),), name=f"vec l-{v.start}{v.end}"))
    items.append(Circle(pts[plan.pole], 0.6, LineType.MAIN, fill="black"))
    labels = [LabelRequest(xy, shared_label(names, plan.pole), LETTER, "nw", blank=True, cross=False)
              for xy, names in shared_points((pts[n], n) for n in [plan.pole, *plan.points])]
    # the forces at their images, each way from its point clear of the plan's vectors
    # there; none at the pole (a force at a fixed point: no arm, no moment)
    terms = [t for t in lv.terms if t.force != 0 and abs(t.image * k) > 0.5]
    tip = mech.driver.tip
    F_y = complex(0.0)
    crank = sol.positions[d.tip] - sol.positions[d.pivot]
    if lv.F_y:
        F_y = lv.F_y * 1j * crank / abs(crank)  # ⊥ the crank, positive counter-clockwise
    at = [(t.image * k, t.force, t.name) for t in terms]
    arms = arm_numbers(forces, mu_v)
    if F_y:
        at.append((1j * sol.scalar.velocity[tip] / mu_v, F_y, "F_у"))
    spots: list[tuple[complex, list[int]]] = []
    for i, (z, _, _) in enumerate(at):
        near = next((idx for where, idx in spots if abs(where - z) < 1.5), None)
        if near is None:
            spots.append((z, [i]))
        else:
            near.append(i)
    for z, idx in spots:
        xy = (z.real, -z.imag)
        bars = _vectors_at(plan, pts, xy)
        dirs = [complex(at[i][1].real, -at[i][1].imag) / abs(at[i][1]) for i in idx]
        seen = list(bars)
        for i, r, u in zip(idx, rays(bars, [], dirs), dirs, strict=True):
            image, force, name = at[i]
            arrow, far = force_arrow((image.real, -image.imag), u, r, beside(seen, r), 0.8)
            seen.append(r)
            items.append(Group((arrow,), name=f"{'balancing' if name == 'F_у' else 'load'} {name}"))
            labels.append(LabelRequest(far, force_markup(name, lang), LETTER, compass(r)))
            if name == "F_у":
                continue  # its arm is pb, the plan's own vector
            items += _arm(image, force, name, arms.get(name), labels)
    pb = abs(1j * sol.scalar.velocity[tip] / mu_v)
    total = lv.F_y * lv.pb * (1.0 if d.omega > 0 else -1.0) * k  # Σ ±F_i·h_i, N·mm at mu_v
    under = [w["equation"].format(tip=plan_name(tip), sum=num(abs(total), 5, lang),
                                  pb=num(pb, 4, lang), F=num(abs(lv.F_y), 4, lang)),
             w["moment"].format(crank=f"{d.pivot}{d.tip}", M=num(abs(lv.M_y), 4, lang),
                                d=_percent(forces.discrepancy, lang))]
    caption = f"{w['lever']}, μ_v = {num(mu_v, 4, lang)} {per_mm(w['ms'], lang)}"
    return finish("lever", items, labels, caption, under, sizing=sizing, under_size=UNDER)


def _vectors_at(plan, pts, xy) -> list[complex]:
    """The directions (unit, sheet) of the turned plan's vectors at the image ``xy``: those
    that leave or reach it, and both ways along one that runs through it (the image s₁ on
    pb): an arrow along them would be hidden."""
    out = []
    p = complex(*xy)
    for v in plan.vectors:
        a, b = complex(*pts[v.start]), complex(*pts[v.end])
        if abs(b - a) < 1e-6:
            continue
        u = (b - a) / abs(b - a)
        t = ((p - a) * u.conjugate()).real  # along the vector, from its start
        if abs(p - a) < 1.5:
            out.append(u)
        elif abs(p - b) < 1.5:
            out.append(-u)
        elif 0 < t < abs(b - a) and abs(((p - a) * u.conjugate()).imag) < 0.5:
            out += [u, -u]
    return out


def _percent(share: float, lang: str) -> str:
    """A discrepancy in per cent to two decimals, "0" at rounding level (exact arms).

    >>> _percent(3.8e-16, "ru"), _percent(0.0123, "ru")
    ('0', '1,23')
    """
    pct = 100 * share
    return "0" if pct < 0.005 else decimal(f"{pct:.2f}", lang)


def arm_numbers(forces, mu_v: float) -> dict[str, int]:
    """The number of each arm drawn on the lever (h1, h2 … in the order of the loads): the
    forces on it whose line misses the pole by half a millimetre or more at ``mu_v``."""
    lv = forces.lever
    k = lv.mu_v / mu_v
    out: dict[str, int] = {}
    for t in lv.terms:
        if t.force != 0 and abs(t.image * k) > 0.5 and t.arm * k >= 0.5:
            out[t.name] = len(out) + 1
    return out


def _arm(image: complex, force: complex, name: str, number: int | None, labels: list) -> list[Item]:
    """The arm of ``force`` at ``image`` (mm from the pole, world axes): a thin line from the
    pole square to the force's line (class ``arm NAME``, its length the arm), lettered
    h with its ``number``, and the force's line carried on thin to it where it ends short
    of it; none for a force through the pole."""
    u = force / abs(force)
    foot = image - u * (image * u.conjugate()).real  # the pole's projection on the line
    if number is None:
        return []
    out: list[Item] = [Group((Segment((0.0, 0.0), (foot.real, -foot.imag), LineType.THIN),),
                             name=f"arm {name}")]
    along = ((foot - image) * u.conjugate()).real  # where the foot is along the line, from the image
    if along < -0.8 or along > 0.8 + ARROW:  # beyond the arrow: the line carried on to it
        out.append(Segment((image.real, -image.imag), (foot.real, -foot.imag), LineType.THIN))
    labels.append(LabelRequest((foot.real / 2, -foot.imag / 2), f"h_{{{number}}}", LETTER, "ne", blank=True,
                               also=tuple((foot.real * t, -foot.imag * t) for t in (0.3, 0.7, 0.85))))
    return out
