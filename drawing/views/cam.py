"""The views of the cam sheet: the follower's s, v, a diagrams, the phase portrait with the
pressure-angle limits and the cam's centre, the profile built by inversion with the
numbered rays of the follower's reversed positions, and the tables of the phases and of
the profile's coordinates. Each view is drawn in its own box of sheet millimetres
(:class:`drawing.views.common.View`), model y up turned to the sheet's y down."""

from __future__ import annotations

import itertools
import math

import numpy as np

from drawing.labels import LabelRequest
from drawing.scene import Arrow, Circle, Hatch, Item, Polyline, Segment, Text
from drawing.styles import LineType
from drawing.views.common import LETTER, View, finish, per_mm, shared_points, start_anchored
from drawing.views.tables import table_view
from plans.cams.table import positions, profile_table
from plans.fmt import num
from plans.scales import GOST_MU_L, choose_mu, gost_scale

__all__ = ["CAM_WORDS", "cam_diagrams_view", "construction_scale", "construction_view", "limit_view",
           "phases_view", "portrait_view", "profile_table_view", "scale_for"]

CAM_WORDS = {
    "ru": {
        "diagrams": "Диаграммы движения толкателя", "portrait": "Фазовый портрет s(ds/dφ)",
        "alpha": "Угол давления α(φ)", "rho": "Выпуклость профиля: r0 + s + s″",
        "construction": "Профиль кулачка (метод обращения движения)", "table": "Координаты профиля",
        "phases": "Фазы движения толкателя", "phase": "Фаза", "angle": "Угол", "law": "Закон",
        "impact": "Удар в начале", "no": "№", "rise": "удаление", "return": "возвращение",
        "outer dwell": "дальнее стояние", "inner dwell": "ближнее стояние",
        "rigid": "жёсткий", "soft": "мягкий", "none": "нет", "mm": "мм", "m": "м", "ms": "м/с",
        "ms2": "м/с²", "rad": "рад", "rads": "рад/с", "rads2": "рад/с²", "deg": "°",
        "limit": "[α]", "best": "O*", "base": "r_0", "pitch": "центровой профиль",
    },
    "en": {
        "diagrams": "Follower's motion diagrams", "portrait": "Phase portrait s(ds/dφ)",
        "alpha": "Pressure angle α(φ)", "rho": "Convexity of the profile: r0 + s + s″",
        "construction": "Cam profile (inversion)", "table": "Profile coordinates",
        "phases": "Phases of the follower's motion", "phase": "Phase", "angle": "Angle", "law": "Law",
        "impact": "Impact at start", "no": "No.", "rise": "rise", "return": "return",
        "outer dwell": "outer dwell", "inner dwell": "inner dwell",
        "rigid": "rigid", "soft": "soft", "none": "none", "mm": "mm", "m": "m", "ms": "m/s",
        "ms2": "m/s²", "rad": "rad", "rads": "rad/s", "rads2": "rad/s²", "deg": "°",
        "limit": "[α]", "best": "O*", "base": "r_0", "pitch": "pitch curve",
    },
}


def phase_label(d, i: int, lang: str) -> str:
    p = d.motion.phases[i]
    w = CAM_WORDS[lang]
    if p.kind != "dwell":
        return w[p.kind]
    return w["outer dwell" if p.level > d.motion.stroke / 2 else "inner dwell"]


#: a flat face drawn this much wider than the stretch of it the profile touches
FACE = 1.15


def scale_for(extent: float, size: float) -> float:
    """The GOST scale μl (m/mm) at which ``extent`` (m) fits in ``size`` mm, the largest
    drawing that does (enlargements included)."""
    for mu in GOST_MU_L:
        if extent / mu <= size:
            return mu
    return GOST_MU_L[-1]


def _sampled(d, per_phase: int = 240):
    """(φ, s, s′, s″) over the cycle phase by phase, each phase's closed interval, so that
    a jump at a joint is a vertical step of the curve."""
    out = []
    for i, p in enumerate(d.motion.phases):
        phi = np.linspace(p.start, p.end, per_phase if p.moves else 2)
        k = p.start + p.k * p.angle if p.moves else None
        if k is not None and p.law is not None and p.law.key == "parabolic":  # its joint, both sides
            phi = np.sort(np.concatenate([phi, [k]]))
        s, s1, s2, _ = d.motion.of_phase(i, phi, "right")
        if k is not None and p.law is not None and p.law.key == "parabolic":
            left = phi <= k
            sl, s1l, s2l, _ = d.motion.of_phase(i, phi[left], "left")
            s2 = s2.copy()
            j = int(np.searchsorted(phi, k))
            # the joint twice: its left value, then its right one
            phi = np.insert(phi, j, k)
            s = np.insert(s, j, sl[-1])
            s1 = np.insert(s1, j, s1l[-1])
            s2 = np.insert(s2, j, s2l[-1])
        out.append((phi, s, s1, s2))
    # the turn's start as the last phase leaves it, so that a jump there is drawn too
    last = len(d.motion.phases) - 1
    end = np.array([d.motion.phases[last].end])
    before = d.motion.of_phase(last, end, "left")
    out.insert(0, (np.array([0.0]), *(np.asarray(v) for v in before[:3])))
    return [np.concatenate([o[k] for o in out]) for k in range(4)]


def cam_diagrams_view(d, lang: str = "ru", width: float = 240.0, height: float = 45.0) -> View:
    """s(φ), v(φ), a(φ) of the follower over the cam's turn (ψ, ω, ε of an oscillating
    one), each with its scale, the phases' joints and the numbered positions marked."""
    w = CAM_WORDS[lang]
    osc = d.cam.follower.oscillating
    om = d.cam.omega
    phi, s, s1, s2 = _sampled(d)
    curves = ((s, "ψ" if osc else "s", w["rad"] if osc else w["m"]),
              (s1 * om, "ω" if osc else "v", w["rads"] if osc else w["ms"]),
              (s2 * om * om, "ε" if osc else "a", w["rads2"] if osc else w["ms2"]))
    items: list[Item] = []
    labels: list[LabelRequest] = []
    x = phi / (2 * math.pi) * width
    rays = positions(d)
    y = 0.0
    for data, name, unit in curves:
        lo, hi = float(min(data.min(), 0.0)), float(max(data.max(), 0.0))
        mu = choose_mu((hi - lo) / height, 0.0, crank_mm=1.0) if hi > lo else 1.0
        y0 = y + hi / mu
        h = (hi - lo) / mu
        items.append(Segment((0, y0), (width + 6, y0), LineType.THIN))
        items.append(Arrow((0, y + h + 2), (0, y - 6), LineType.THIN, 3.0, 1.0))
        ys = y0 - data / mu
        items.append(Polyline(list(zip(x.tolist(), ys.tolist(), strict=True)), LineType.MAIN))
        for p in d.motion.phases[1:]:  # the joints
            xj = p.start / (2 * math.pi) * width
            items.append(Segment((xj, y - 2), (xj, y + h + 2), LineType.THIN))
        for k, r in enumerate(rays):
            xr = r / (2 * math.pi) * width
            items.append(Segment((xr, y0 - 1), (xr, y0 + 1), LineType.THIN))
            if name in ("s", "ψ"):
                labels.append(LabelRequest((xr, y0), str(k), 2.5, "s", markup=False, optional=True))
        items.append(Text((2, y - 6), f"{name}, {unit}", size=3.5, baseline="hanging"))
        items.append(Text((width + 6, y0 - 1.5), "φ", size=3.5, anchor="end"))
        scale = f"μ_{name} = {num(mu, 3, lang)} {per_mm(unit, lang)}"
        items.append(start_anchored(Text((width - 2, y - 6), scale, size=2.5, anchor="end",
                                         baseline="hanging", markup=True)))
        y += h + 16.0
    # the phases named over the s diagram
    for i, p in enumerate(d.motion.phases):
        xa, xb = p.start / (2 * math.pi) * width, p.end / (2 * math.pi) * width
        text = f"{phase_label(d, i, lang)} {num(math.degrees(p.angle), 4, lang)}°"
        labels.append(LabelRequest(((xa + xb) / 2, -8.0), text, 2.5, "n", markup=False, optional=True))
    mu_phi = 360.0 / width
    caption = f"{w['diagrams']}, μ_φ = {num(mu_phi, 3, lang)} °/{w['mm']}"
    return finish("cam-diagrams", items, labels, caption)


def _xy(z, mu: float) -> tuple[float, float]:
    return (float(np.real(z)) / mu, -float(np.imag(z)) / mu)


def portrait_view(d, lang: str = "ru", size: float = 150.0) -> View:
    """The phase portrait of a translating follower: each position's point P = (−σ·s′, s)
    from B0 up the follower's axis, the tangents at the allowed pressure angles (the
    admissible region below them hatched), the chosen centre O and the best O*."""
    w = CAM_WORDS[lang]
    port, arr = d.portrait, d.arrangement
    sig = arr.sigma
    _, s, s1, _ = _sampled(d, 200)
    X, Y = -sig * s1, s
    centre = complex(-d.offset, -arr.s0)
    best = complex(*port.centre)
    xs = np.concatenate([X, [centre.real, best.real, 0.0]])
    ys = np.concatenate([Y, [centre.imag, best.imag]])
    extent = max(float(xs.max() - xs.min()), float(ys.max() - ys.min())) * 1.25
    mu = scale_for(extent, size)
    items: list[Item] = []
    labels: list[LabelRequest] = []
    top = float(ys.max()) + 0.1 * extent
    low = float(ys.min()) - 0.1 * extent
    left, right = float(xs.min()) - 0.15 * extent, float(xs.max()) + 0.15 * extent
    items.append(Segment(_xy(complex(0, low), mu), _xy(complex(0, top), mu), LineType.DASH_DOT_THIN))
    items.append(Polyline([_xy(complex(a, b), mu) for a, b in zip(X, Y, strict=True)], LineType.MAIN))
    c = d.curves(np.array(positions(d)))
    marks = [(_xy(complex(-sig * float(a), float(b)), mu), str(k))
             for k, (a, b) in enumerate(zip(c.s1, c.s, strict=True))]
    for xy, names in shared_points(marks):  # positions on one point share a label: "8,9"
        items.append(Circle(xy, 0.5, LineType.MAIN, fill="black"))
        labels.append(LabelRequest(xy, ",".join(names), 2.5, "e", markup=False, optional=True))
    # the tangents, from their points down past the centre; the region below them hatched
    for t in port.tangents:  # down to the bottom of the drawing, or to its side
        y_end = low
        x_end = (y_end - t.b) / t.m
        if not left <= x_end <= right:
            x_end = left if x_end < left else right
            y_end = t.b + t.m * x_end
        items.append(Segment(_xy(complex(t.x, t.y), mu), _xy(complex(x_end, y_end), mu), LineType.THIN))
    grid = np.linspace(left, right, 400)
    ceiling = port.ceiling(grid)
    inside = ceiling >= low
    pts = [_xy(complex(a, b), mu) for a, b in zip(grid[inside], ceiling[inside], strict=True)]
    if len(pts) >= 2:
        # the region's edge: a hatch under each straight stretch of it
        corners = [pts[0]]
        for a, b, c in zip(pts, pts[1:], pts[2:], strict=False):
            if abs((b[0] - a[0]) * (c[1] - b[1]) - (b[1] - a[1]) * (c[0] - b[0])) > 1e-6:
                corners.append(b)
        corners.append(pts[-1])
        for a, b in itertools.pairwise(corners):
            items.append(Hatch(a, b, side=1, spacing=2.5, length=2.0, base=None))
    for t in port.tangents:  # each tangent's angle, halfway between its point and the centre's level
        y_mid = (t.y + centre.imag) / 2
        mid = complex((y_mid - t.b) / t.m, y_mid)
        labels.append(LabelRequest(_xy(mid, mu), f"{num(t.limit_deg, 3, lang)}°", 2.5, "e", markup=False,
                                   optional=True))
    # O, O*, B0, r0 and e
    o = _xy(centre, mu)
    items.append(Circle(o, 0.8, LineType.MAIN, fill="black"))
    labels.append(LabelRequest(o, "O", LETTER, "sw"))
    b0 = _xy(0j, mu)
    labels.append(LabelRequest(b0, "B_0", LETTER, "ne"))
    items.append(Segment(o, b0, LineType.THIN))
    labels.append(LabelRequest(_xy(centre / 2, mu), w["base"], LETTER, "w"))
    if abs(best - centre) / mu > 1.5:
        items.append(Circle(_xy(best, mu), 0.8, LineType.MAIN))
        labels.append(LabelRequest(_xy(best, mu), "O*", LETTER, "se"))
    if abs(d.offset) / mu > 1.0:
        items.append(Segment(o, _xy(complex(0, centre.imag), mu), LineType.THIN))
        labels.append(LabelRequest(_xy(complex(centre.real / 2, centre.imag), mu), "e", LETTER, "s",
                                   markup=False))
    caption = f"{w['portrait']}, μ_l = {num(mu, 3, lang)} {w['m']}/{w['mm']}"
    under = [f"r_0 = {num(d.r0 * 1000, 4, lang)} {w['mm']}, e = {num(d.offset * 1000, 4, lang)} {w['mm']}; "
             f"O*: r_0 = {num(d.best[0] * 1000, 4, lang)} {w['mm']}, e = {num(d.best[1] * 1000, 4, lang)} "
             f"{w['mm']}" if d.best else f"r_0 = {num(d.r0 * 1000, 4, lang)} {w['mm']}"]
    return finish("portrait", items, labels, caption, under)


def limit_view(d, lang: str = "ru", width: float = 200.0, height: float = 45.0) -> View:
    """Where no phase portrait is drawn: the pressure angle over the cycle with its limits
    (an oscillating follower), or r0 + s + s″ of a flat face with its bound."""
    w = CAM_WORDS[lang]
    phi = np.linspace(0.0, 2 * math.pi, 721)
    c = d.curves(phi)
    lim = d.cam.limits
    if d.cam.follower.flat:  # the bound over the whole turn
        data = 1000.0 / c.kappa_profile
        name, unit = "ρ", w["mm"]
        lines = [(0.0, 2 * math.pi, lim.min_radius * 1000)]
        title = w["rho"] if not d.cam.follower.oscillating else "ρ(φ)"
    else:  # each phase's limit over it
        data = np.degrees(c.pressure)
        name, unit = "α", "°"
        lines = [(p.start, p.end, lim.rise_deg if p.kind == "rise" else lim.return_deg)
                 for p in d.motion.phases if p.moves]
        title = w["alpha"]
    hi = max(float(data.max()), *(v for _, _, v in lines)) * 1.1
    mu = choose_mu(hi / height, 0.0, crank_mm=1.0)
    x = phi / (2 * math.pi) * width
    y0 = hi / mu
    items: list[Item] = [Segment((0, y0), (width + 6, y0), LineType.THIN),
                         Arrow((0, y0 + 2), (0, -6), LineType.THIN, 3.0, 1.0),
                         Polyline(list(zip(x.tolist(), (y0 - data / mu).tolist(), strict=True)),
                                  LineType.MAIN)]
    labels = []
    for a, b, v in lines:
        xa, xb = a / (2 * math.pi) * width, b / (2 * math.pi) * width
        items.append(Segment((xa, y0 - v / mu), (xb, y0 - v / mu), LineType.DASHED))
        labels.append(LabelRequest(((xa + xb) / 2, y0 - v / mu), num(v, 3, lang), 2.5, "n", markup=False))
    for p in d.motion.phases[1:]:  # the joints, and the numbered positions
        xj = p.start / (2 * math.pi) * width
        items.append(Segment((xj, y0 + 2), (xj, y0 - hi / mu), LineType.THIN))
    for k, r in enumerate(positions(d)):
        xr = r / (2 * math.pi) * width
        items.append(Segment((xr, y0 - 1), (xr, y0 + 1), LineType.THIN))
        labels.append(LabelRequest((xr, y0), str(k), 2.5, "s", markup=False, optional=True))
    items.append(Text((2, -6), f"{name}, {unit}", size=3.5, baseline="hanging"))
    items.append(Text((width + 6, y0 - 1.5), "φ", size=3.5, anchor="end"))
    return finish("portrait", items, labels, f"{title}, μ_{name} = {num(mu, 3, lang)} {unit}/{w['mm']}")


def construction_view(d, lang: str = "ru", size: float = 250.0) -> View:
    """The profile by inversion at a GOST scale: the base circle, the offset circle (or the
    circle of the pivot's reversed positions), the numbered rays of the follower's reversed
    positions, the pitch curve thin, the roller circles or face lines at the rays, the
    actual profile in main lines, and the follower where it stands at φ = 0."""
    w = CAM_WORDS[lang]
    f, arr = d.cam.follower, d.arrangement
    fine = profile_table(d, math.radians(0.5))
    rays = positions(d)
    rc = d.curves(np.array(rays))
    reach = _reach(d, fine)
    mu = construction_scale(d, size)
    items: list[Item] = []
    labels: list[LabelRequest] = []
    big = reach * 1.12
    # the centre lines and the cam's shaft
    items.append(Segment(_xy(complex(-big, 0), mu), _xy(complex(big, 0), mu), LineType.DASH_DOT_THIN))
    items.append(Segment(_xy(complex(0, -big), mu), _xy(complex(0, big), mu), LineType.DASH_DOT_THIN))
    o = _xy(0j, mu)
    items.append(Circle(o, arr.r0 / mu, LineType.THIN))
    if not f.oscillating and abs(d.offset) / mu > 0.5 and not f.flat:
        items.append(Circle(o, abs(d.offset) / mu, LineType.THIN))
    if f.oscillating:
        items.append(Circle(o, f.centre / mu, LineType.THIN))
    # the rays: the follower's axis (or arm, or face) in each reversed position
    turn = np.exp(-1j * arr.sigma * np.array(rays))
    for k, tn in enumerate(turn):
        if f.oscillating:
            A = arr.A * tn
            tip = rc.pitch[k] if not f.flat else rc.profile[k]
            items.append(Segment(_xy(A, mu), _xy(tip, mu), LineType.THIN))
            items.append(Circle(_xy(A, mu), 0.5, LineType.THIN))
            out = A * (1 + 0.06 * f.arm / abs(A))
            labels.append(LabelRequest(_xy(out, mu), str(k), 2.5, "n", markup=False, optional=True))
            continue
        # from the base circle (B_k on it, where s is measured from) out past the pitch point
        start = (arr.e + 1j * arr.s0) * tn if not f.flat else arr.r0 * 1j * tn
        along = 1j * tn
        end = rc.pitch[k] + along * 0.08 * reach
        items.append(Segment(_xy(start, mu), _xy(end, mu), LineType.THIN))
        labels.append(LabelRequest(_xy(end, mu), str(k), 2.5, "n", markup=False, optional=True))
    # the roller circles, or the face lines, at the rays
    for k in range(len(rays)):
        if f.kind == "roller":
            items.append(Circle(_xy(rc.pitch[k], mu), f.roller / mu, LineType.THIN))
        elif f.flat and not f.oscillating:  # the face across the axis, as wide as it must be
            a, b = (rc.pitch[k] + turn[k] * x * FACE for x in d.face)
            items.append(Segment(_xy(a, mu), _xy(b, mu), LineType.THIN))
    # the pitch curve thin, the profile in main lines
    if f.kind != "knife-edge" and not (f.flat and f.oscillating):
        items.append(Polyline([_xy(z, mu) for z in fine.pitch], LineType.THIN, closed=True))
    items.append(Polyline([_xy(z, mu) for z in fine.profile], LineType.MAIN, closed=True))
    # the follower at φ = 0, heavy
    items += _follower(d, mu, rc.pitch[0], rc.profile[0], reach)
    items.append(Circle(o, 1.2, LineType.MAIN, fill="white"))
    labels.append(LabelRequest(o, "O", LETTER, "sw"))
    # the cam's rotation ω near its shaft, and the inversion's −ω out by the rays' numbers
    r_in = arr.r0 * 0.5  # clear of the offset circle
    if not f.oscillating and abs(r_in - abs(d.offset)) < 0.12 * arr.r0:
        r_in = arr.r0 * (0.3 if abs(d.offset) > 0.4 * arr.r0 else 0.7)
    r_in /= mu
    items += _rotation(r_in, arr.sigma, o, 200.0)
    at = math.radians(250.0)
    labels.append(LabelRequest((o[0] + r_in * math.cos(at), o[1] - r_in * math.sin(at)), "ω", LETTER, "s",
                               markup=False))
    r_out = reach * 1.16 / mu
    items += _rotation(r_out, -arr.sigma, o, 215.0, 30.0)
    at = math.radians(230.0)
    labels.append(LabelRequest((o[0] + r_out * math.cos(at), o[1] - r_out * math.sin(at)), "−ω", LETTER, "sw",
                               markup=False))
    b0 = _xy(rc.pitch[0], mu)
    labels.append(LabelRequest(b0, "B_0", LETTER, "ne" if not f.oscillating else "nw"))
    caption = f"{w['construction']}, μ_l = {num(mu, 3, lang)} {w['m']}/{w['mm']} ({gost_scale(mu, lang)})"
    mm = w["mm"]
    under = [f"r_0 = {num(d.r0 * 1000, 4, lang)} {mm}"
             + (f", e = {num(d.offset * 1000, 4, lang)} {mm}" if not f.oscillating and d.offset else "")
             + (f", r_r = {num(f.roller * 1000, 4, lang)} {mm}" if f.kind == "roller" else "")
             + (f", l = {num(f.arm * 1000, 4, lang)} {mm}, a = {num(f.centre * 1000, 4, lang)} {mm}"
                if f.oscillating else "")]
    return finish("construction", items, labels, caption, under)


def _reach(d, fine) -> float:
    """m: how far from the cam's centre the construction reaches (its pitch curve and
    profile, or the oscillating follower's pivot)."""
    reach = float(max(np.abs(fine.pitch).max(), np.abs(fine.profile).max()))
    f = d.cam.follower
    return max(reach, f.centre + 0.1 * f.arm) if f.oscillating else reach


def construction_scale(d, size: float) -> float:
    """The GOST μl of the construction drawn about ``size`` mm across."""
    return scale_for(2.3 * _reach(d, profile_table(d, math.radians(2.0))), size)


def _rotation(r: float, sigma: int, o, start: float, span: float = 100.0) -> list[Item]:
    """A circular arrow of radius ``r`` (mm) about ``o``, over ``span`` degrees from
    ``start`` (counter-clockwise on the drawing), pointing the way ``sigma`` turns."""
    a0, a1 = math.radians(start), math.radians(start + span)
    if sigma < 0:
        a0, a1 = a1, a0
    pts = [(o[0] + r * math.cos(a), o[1] - r * math.sin(a)) for a in np.linspace(a0, a1, 24)]
    return [Polyline(pts[:-1], LineType.THIN), Arrow(pts[-3], pts[-1], LineType.THIN, 3.0, 1.0)]


def _follower(d, mu: float, pitch0: complex, contact0: complex, reach: float) -> list[Item]:
    """The follower at φ = 0 (the cam's frame is the fixed one there), heavy."""
    f, arr = d.cam.follower, d.arrangement
    out: list[Item] = []
    if f.oscillating:
        A = arr.A
        tip = pitch0 if not f.flat else contact0
        out.append(Segment(_xy(A, mu), _xy(tip + (tip - A) * 0.1 if f.flat else tip, mu), LineType.MAIN))
        ax, ay = _xy(A, mu)
        out += [Polyline([(ax, ay), (ax - 3, ay + 5), (ax + 3, ay + 5)], LineType.MAIN, closed=True),
                Hatch((ax - 5, ay + 5), (ax + 5, ay + 5), side=1, spacing=1.6, length=2.0)]
        out.append(Circle((ax, ay), 1.0, LineType.MAIN, fill="white"))
        if f.kind == "roller":
            out.append(Circle(_xy(pitch0, mu), f.roller / mu, LineType.MAIN, fill="white"))
        return out
    top = pitch0 + 1j * (d.motion.stroke + 0.12 * reach)
    base = pitch0 if f.kind != "roller" else pitch0 + 1j * f.roller
    out.append(Segment(_xy(base, mu), _xy(top, mu), LineType.MAIN))
    # the guide: two short strokes either side of the rod, hatched outside
    g = pitch0 + 1j * (d.motion.stroke + 0.04 * reach)
    gx, gy = _xy(g, mu)
    for side in (-1, 1):
        x = gx + side * 2.5
        out.append(Segment((x, gy - 6), (x, gy + 6), LineType.MAIN))
        out.append(Hatch((x, gy + 6), (x, gy - 6), side=side, spacing=1.6, length=2.0, base=None))
    if f.kind == "roller":
        out.append(Circle(_xy(pitch0, mu), f.roller / mu, LineType.MAIN, fill="white"))
        out.append(Circle(_xy(pitch0, mu), 0.6, LineType.MAIN, fill="black"))
    elif f.flat:  # the face, a little wider than where it touches
        a, b = (pitch0 + x * FACE for x in d.face)
        out.append(Segment(_xy(a, mu), _xy(b, mu), LineType.MAIN))
    else:  # the knife's edge
        px, py = _xy(pitch0, mu)
        out.append(Polyline([(px - 2.0, py - 5.0), (px, py), (px + 2.0, py - 5.0)], LineType.MAIN))
    return out


def profile_table_view(d, lang: str = "ru") -> View:
    """The coordinates of the numbered positions: φ, s (ψ), the profile's x and y in the
    cam's frame, its radius of curvature and the pressure angle."""
    w = CAM_WORDS[lang]
    mm = w["mm"]
    rays = positions(d)
    c = d.curves(np.array(rays))
    osc = d.cam.follower.oscillating
    header = [w["no"], "φ, °", "ψ, °" if osc else f"s, {mm}", f"x, {mm}", f"y, {mm}", f"ρ, {mm}", "α, °"]
    rows = []
    for k, r in enumerate(rays):
        kp = c.kappa_profile[k]
        rho = "∞" if abs(kp) < 1e-12 else num(1000 / kp, 4, lang)
        s = num(math.degrees(c.s[k]), 4, lang) if osc else num(c.s[k] * 1000, 4, lang)
        rows.append([str(k), num(math.degrees(r), 4, lang), s, num(_clean(c.profile[k].real) * 1000, 4, lang),
                     num(_clean(c.profile[k].imag) * 1000, 4, lang), rho,
                     num(math.degrees(c.pressure[k]), 3, lang)])
    return table_view("profile-table", w["table"], header, rows, [10.0, 16.0, 18.0, 20.0, 20.0, 20.0, 14.0],
                      row_h=6.0)


def _clean(x: float) -> float:
    return 0.0 if abs(x) < 1e-12 else float(x)


def phases_view(d, lang: str = "ru") -> View:
    """The phases: their cam angles, laws and the impact each starts with."""
    w = CAM_WORDS[lang]
    impacts = {i.where[1]: i.kind for i in d.impacts if i.where[0] != i.where[1]}
    rows = []
    for i, p in enumerate(d.motion.phases):
        law = p.law.name(lang) if p.moves else "—"
        if p.moves and p.ratio != 1.0:
            law += f" ({num(p.ratio, 3, lang)}:1)"
        rows.append([phase_label(d, i, lang), f"{num(math.degrees(p.start), 4, lang)}–"
                     f"{num(math.degrees(p.end), 4, lang)}°", law, w[impacts.get(i, 'none')]])
    return table_view("phases", w["phases"], [w["phase"], "φ", w["law"], w["impact"]], rows,
                      [30.0, 26.0, 78.0, 32.0], row_h=6.0)
