"""The student's plan drawn over the computed one (``plans check --svg``).

Two panels, the velocity plan and the acceleration plan, each at its own zoom (the
numbers on it are millimetres at the student's scale factors):

* black: the computed plan, every segment the plan names, points labelled;
* red dashed: the student's plan rebuilt from the measured lengths
  (:func:`plans.check.rebuild`), a red ring at each point placed;
* red text: the segments beyond tolerance, with the deviation in mm; a thin red line
  joins a computed point to where the student's drawing puts it when they differ;
* below: the legend, the verdict and the diagnosis.

A small standalone SVG written with xml.etree (which escapes every text): the sheet
renderer (drawing.svg) draws GOST sheets in one colour, and this picture needs two.
Labels are placed greedily so that no two overlap and none sits on a point.
"""

from __future__ import annotations

import math
import xml.etree.ElementTree as ET

from plans.check import MU_KEY, CheckResult, rebuild, recorded_segments

PANEL = 340.0  # user units (px) of one plan's square
MARGIN = 24.0
FONT = 11.0
SMALL = 9.5
RED = "#c62828"
BLACK = "#222"
GREY = "#999"

WORDS = {
    "en": {
        "velocity": "Velocity plan (pole p), μv = {mu} (m/s)/mm",
        "acceleration": "Acceleration plan (pole π), μa = {mu} (m/s²)/mm",
        "legend_c": "computed plan",
        "legend_s": "student's plan, rebuilt from the measured lengths",
        "legend_d": "beyond tolerance: deviation in mm",
        "ok": "All measured segments within tolerance ({tol}).",
        "bad": "Beyond tolerance ({tol}): {names}.",
        "none": "Diagnosis: no single mistake explains this.",
        "diag": "Diagnosis: {what}.",
        "fix": "Correction: {fix}.",
        "title": "plans check: {src}",
        "nothing": "(nothing measured on this plan)",
    },
    "ru": {
        "velocity": "План скоростей (полюс p), μv = {mu} (м/с)/мм",
        "acceleration": "План ускорений (полюс π), μa = {mu} (м/с²)/мм",
        "legend_c": "расчётный план",
        "legend_s": "план студента, восстановленный по измеренным отрезкам",
        "legend_d": "вне допуска: отклонение, мм",
        "ok": "Все измеренные отрезки в допуске ({tol}).",
        "bad": "Вне допуска ({tol}): {names}.",
        "none": "Диагноз: ни одна отдельная ошибка этого не объясняет.",
        "diag": "Диагноз: {what}.",
        "fix": "Исправление: {fix}.",
        "title": "plans check: {src}",
        "nothing": "(на этом плане ничего не измерено)",
    },
}


def _f(x) -> str:
    return f"{x:.2f}".rstrip("0").rstrip(".") if isinstance(x, float) else str(x)


class _El:
    """An SVG element with the few calls this picture needs (attribute names with
    underscores become hyphens: font_size → font-size)."""

    def __init__(self, tag: str, text: str | None = None, **attrs):
        self.el = ET.Element(tag, {k.replace("_", "-"): _f(v) for k, v in attrs.items()})
        if text is not None:
            self.el.text = text

    def add(self, child: _El) -> _El:
        self.el.append(child.el)
        return child


class _Doc(_El):
    def __init__(self, width: float, height: float):
        super().__init__("svg", xmlns="http://www.w3.org/2000/svg", width=f"{width:.0f}px",
                         height=f"{height:.0f}px", viewBox=f"0 0 {width:.0f} {height:.0f}")

    @staticmethod
    def rect(insert, size, **kw) -> _El:
        return _El("rect", x=float(insert[0]), y=float(insert[1]), width=float(size[0]),
                   height=float(size[1]), **kw)

    @staticmethod
    def text(text: str, insert, **kw) -> _El:
        return _El("text", text, x=float(insert[0]), y=float(insert[1]), **kw)

    @staticmethod
    def line(p, q, **kw) -> _El:
        return _El("line", x1=float(p[0]), y1=float(p[1]), x2=float(q[0]), y2=float(q[1]), **kw)

    @staticmethod
    def circle(c, r, **kw) -> _El:
        return _El("circle", cx=float(c[0]), cy=float(c[1]), r=float(r), **kw)

    @staticmethod
    def g(**kw) -> _El:
        return _El("g", **kw)

    def tostring(self) -> str:
        return '<?xml version="1.0" encoding="utf-8"?>\n' + ET.tostring(self.el, encoding="unicode")


def _num(x: float, lang: str, digits: int = 4) -> str:
    from plans.fmt import num

    return num(x, digits, lang)


def text_width(text: str, size: float) -> float:
    """A generous estimate of the advance of ``text`` in a sans-serif font."""
    w = 0.0
    for c in text:
        if c in "il.,:;|'!":
            w += 0.3
        elif c in " −-()":
            w += 0.4
        elif c in "жмшщыюфЖМШЩЫЮФ":
            w += 0.9
        elif c.isupper() or c in "mwMWπ":
            w += 0.75
        elif "а" <= c.lower() <= "я" or c == "ё":
            w += 0.64
        else:
            w += 0.58
    return w * size


class _Labels:
    """Greedy label placement: the first candidate position that overlaps no label,
    no point marker and stays in the panel; else the one overlapping least."""

    def __init__(self, box: tuple[float, float, float, float]):
        self.box = box
        self.taken: list[tuple[float, float, float, float]] = []

    def block(self, x: float, y: float, r: float = 3.0) -> None:
        self.taken.append((x - r, y - r, x + r, y + r))

    def block_line(self, p: tuple[float, float], q: tuple[float, float], step: float = 6.0) -> None:
        n = max(int(math.hypot(q[0] - p[0], q[1] - p[1]) / step), 1)
        for i in range(n + 1):
            t = i / n
            self.block(p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1]), 1.2)

    @staticmethod
    def _overlap(a, b) -> float:
        w = min(a[2], b[2]) - max(a[0], b[0])
        h = min(a[3], b[3]) - max(a[1], b[1])
        return w * h if w > 0 and h > 0 else 0.0

    def place(self, x: float, y: float, text: str, size: float, prefer: float = 0.0,
              must: bool = True, bold: bool = False):
        """Top-left corner of the label's box near (x, y) and the ring distance used;
        ``prefer``: angle (rad) of the first direction tried. A label that can be left
        out (``must`` false) is placed only where it overlaps nothing, else None."""
        w, h = text_width(text, size) * (1.2 if bold else 1.05) + 3, size * 1.15 + 2
        best, best_cost = None, math.inf
        rings = (4.0, 8.0, 13.0, 20.0, 28.0, 38.0, 50.0) if must else (4.0, 8.0, 13.0)
        for ring in rings:
            for k in range(16):
                ang = prefer + k * math.pi / 8
                cx, cy = x + (ring + w / 2) * math.cos(ang), y - (ring + h / 2) * math.sin(ang)
                b = (cx - w / 2, cy - h / 2, cx + w / 2, cy + h / 2)
                x0, y0, x1, y1 = self.box
                out = max(x0 - b[0], 0) + max(b[2] - x1, 0) + max(y0 - b[1], 0) + max(b[3] - y1, 0)
                cost = sum(self._overlap(b, t) for t in self.taken) + 100 * out
                if cost < best_cost:
                    best, best_cost = b, cost
                if cost == 0:
                    self.taken.append(b)
                    return b[0] + 1.5, b[1] + 1, ring
        if not must:
            return None
        self.taken.append(best)
        return best[0] + 1.5, best[1] + 1, rings[-1]


def overlay_svg(result: CheckResult, lang: str = "en") -> str:
    """The SVG document (text) of the overlay for one check."""
    w = WORDS[lang]
    meas = result.measurement
    sol = meas.solution
    student = rebuild(result)
    width = 2 * PANEL + 3 * MARGIN
    foot = _footer(result, lang)
    lists = {kind: _deviation_list(result, kind, lang) for kind in ("velocity", "acceleration")}
    below = max(len(v) for v in lists.values())
    height = MARGIN * 2 + 22 + PANEL + 14 * below + 56 + 16 * (len(foot) + 1)
    dwg = _Doc(width, height)
    dwg.add(dwg.rect((0, 0), (width, height), fill="white"))
    dwg.add(dwg.text(w["title"].format(src=meas.source), insert=(MARGIN, MARGIN),
                     font_size=FONT + 2, font_family="sans-serif", fill=BLACK))
    top = MARGIN + 22
    failed = {id(d.item) for d in result.failed}
    for i, kind in enumerate(("velocity", "acceleration")):
        x0 = MARGIN + i * (PANEL + MARGIN)
        plan = sol.velocity if kind == "velocity" else sol.acceleration
        mu = meas.mu[MU_KEY[kind]]
        dwg.add(dwg.text(w[kind].format(mu=_num(mu, lang)), insert=(x0, top + 4),
                         font_size=FONT, font_family="sans-serif", fill=BLACK))
        dwg.add(dwg.rect((x0, top + 12), (PANEL, PANEL), fill="none", stroke="#ddd"))
        items = [(d, d.item) for d in result.deviations
                 if d.item.kind == "segment" and d.item.plan == kind]
        _panel(dwg, (x0, top + 12), plan, mu, student.get(kind, {}), items, failed, lang, w)
        for j, line in enumerate(lists[kind]):
            dwg.add(dwg.text(line, insert=(x0, top + 12 + PANEL + 16 + 14 * j), font_size=SMALL,
                             font_family="sans-serif", fill=RED))
    y = top + 12 + PANEL + 14 * below + 32
    first = next((d for d in result.failed if d.item.kind == "segment"), None)
    mark = _mark(first.item.name, first.deviation, lang) if first else _mark("ab", -4.2, lang)
    y = _legend(dwg, MARGIN, y, w, mark) + 22
    for line, color in foot:
        dwg.add(dwg.text(line, insert=(MARGIN, y), font_size=FONT, font_family="sans-serif",
                         fill=color))
        y += 16
    return dwg.tostring()


def _deviation_list(result: CheckResult, kind: str, lang: str) -> list[str]:
    """"beyond tolerance: πa3 +18.6 mm, …" wrapped to the panel's width."""
    parts = []
    for d in result.failed:
        it = d.item
        if it.kind == "segment" and it.plan == kind:
            parts.append(_mark(it.name, d.deviation, lang))
    if not parts:
        return []
    head = "вне допуска, мм: " if lang == "ru" else "beyond tolerance, mm: "
    lines, cur = [], head
    for i, part in enumerate(parts):
        piece = part + ("," if i < len(parts) - 1 else "")
        if text_width(cur + " " + piece, SMALL) > PANEL and cur.strip():
            lines.append(cur)
            cur = "  " + piece
        else:
            cur = (cur + " " + piece) if cur != head else cur + piece
    lines.append(cur)
    return lines


def _footer(result: CheckResult, lang: str) -> list[tuple[str, str]]:
    w = WORDS[lang]
    tol = result.tolerance.describe(lang)
    out = []
    if result.ok:
        out.append((w["ok"].format(tol=tol), BLACK))
        return out
    out.append((w["bad"].format(tol=tol, names=", ".join(d.item.name for d in result.failed)), RED))
    diag = result.diagnosis
    if diag.best is None:
        out.append((w["none"], BLACK))
    else:
        out.append((w["diag"].format(what=diag.best.mistake.describe(lang)), BLACK))
        for line in _wrap(w["fix"].format(fix=diag.best.mistake.correction(lang)), 110):
            out.append((line, BLACK))
    return out


def _wrap(text: str, width: int) -> list[str]:
    lines, cur = [], ""
    for word in text.split():
        if cur and len(cur) + 1 + len(word) > width:
            lines.append(cur)
            cur = "  " + word
        else:
            cur = f"{cur} {word}" if cur else word
    if cur:
        lines.append(cur)
    return lines


def _mark(name: str, deviation: float, lang: str) -> str:
    """A segment's deviation as the sheet marks it: "πa3 +18,6" (mm)."""
    from plans.fmt import signed

    return f"{name} {signed(deviation, lang, 1)}"


def _legend(dwg, x, y, w, mark: str) -> float:
    """The legend from (x, y), wrapped to the picture's width; returns the y after it.
    ``mark`` is the deviation shown as its sample: the first one beyond tolerance, so the
    legend names a segment of this sheet."""
    g = dwg.g(font_family="sans-serif")
    right = x + 2 * PANEL + MARGIN
    entries = [("computed", w["legend_c"]), ("student", w["legend_s"]), ("deviation", w["legend_d"])]
    at = x
    for kind, label in entries:
        sample = 24.0 if kind != "deviation" else 1.2 * text_width(mark, SMALL)
        need = sample + 6 + text_width(label, SMALL)
        if at > x and at + need > right:
            at, y = x, y + 16
        if kind == "computed":
            g.add(dwg.line((at, y - 3), (at + 24, y - 3), stroke=BLACK, stroke_width=1.2))
        elif kind == "student":
            g.add(dwg.line((at, y - 3), (at + 24, y - 3), stroke=RED, stroke_width=1.4,
                           stroke_dasharray="5,3"))
            g.add(dwg.circle((at + 12, y - 3), 2.6, fill="none", stroke=RED, stroke_width=1))
        else:
            g.add(dwg.text(mark, insert=(at, y), fill=RED, font_size=SMALL, font_weight="bold"))
        g.add(dwg.text(label, insert=(at + sample + 6, y), fill=BLACK if kind == "computed" else RED,
                       font_size=SMALL))
        at += need + 16
    dwg.add(g)
    return y


def _panel(dwg, origin, plan, mu, student, items, failed, lang, w):
    ox, oy = origin
    comp = {n: p.value / mu for n, p in plan.points.items()} | {plan.pole: 0j}
    segs = recorded_segments(plan)
    pts = list(comp.values()) + list(student.values())
    xs = [z.real for z in pts]
    ys = [z.imag for z in pts]
    span = max(max(xs) - min(xs), max(ys) - min(ys), 1e-9)
    pad = 40.0
    zoom = (PANEL - 2 * pad) / span
    cx, cy = (max(xs) + min(xs)) / 2, (max(ys) + min(ys)) / 2

    def sc(z: complex) -> tuple[float, float]:
        return (ox + PANEL / 2 + zoom * (z.real - cx), oy + PANEL / 2 - zoom * (z.imag - cy))

    labels = _Labels((ox + 2, oy + 2, ox + PANEL - 2, oy + PANEL - 2))
    g = dwg.g(font_family="sans-serif")
    # the computed plan
    for a, b in segs.values():
        p, q = sc(comp[a]), sc(comp[b])
        g.add(dwg.line(p, q, stroke=BLACK, stroke_width=1.1))
        labels.block_line(p, q)
    names = {}
    for n, z in comp.items():
        names.setdefault(z, []).append(n)
    for z in names:
        labels.block(*sc(z), 3.5)
    # the student's plan
    for _, it in items:
        if it.start in student and it.end in student:
            p, q = sc(student[it.start]), sc(student[it.end])
            bad = id(it) in failed
            g.add(dwg.line(p, q, stroke=RED, stroke_width=1.8 if bad else 1.2,
                           stroke_dasharray="5,3", fill="none"))
            labels.block_line(p, q)
    moved = []
    for n, z in student.items():
        s = sc(z)
        g.add(dwg.circle(s, 2.8, fill="none", stroke=RED, stroke_width=1))
        labels.block(*s, 3.5)
        c = sc(comp[n]) if n in comp else s
        if math.hypot(s[0] - c[0], s[1] - c[1]) > 6:
            g.add(dwg.line(c, s, stroke=RED, stroke_width=0.6, stroke_opacity=0.7))
            labels.block_line(c, s)
            moved.append((n, s))
    # point labels: the computed points, then the student's where they differ
    def label(x, y, text, color):
        ang = math.atan2(-(y - (oy + PANEL / 2)), x - (ox + PANEL / 2))
        bx, by, ring = labels.place(x, y, text, FONT, prefer=ang)
        if ring > 10:  # a leader from the point to a label placed farther out
            w_ = text_width(text, FONT)
            tx = min(max(x, bx), bx + w_)
            ty = min(max(y, by), by + FONT * 1.15)
            g.add(dwg.line((x, y), (tx, ty), stroke=color, stroke_width=0.5, stroke_opacity=0.6))
        g.add(dwg.text(text, insert=(bx, by + FONT * 0.95), font_size=FONT, fill=color))

    for z, ns in names.items():
        label(*sc(z), "≡".join(ns) if len(ns) <= 3 else ns[0] + "…", BLACK)
    for n, (x, y) in moved:
        label(x, y, n + "′", RED)
    # the deviations beyond tolerance, at the middle of the student's (or computed) segment
    for d, it in items:
        if id(it) not in failed:
            continue
        src = student if it.start in student and it.end in student else comp
        if it.start not in src or it.end not in src:
            continue
        p, q = sc(src[it.start]), sc(src[it.end])
        mx, my = (p[0] + q[0]) / 2, (p[1] + q[1]) / 2
        text = _mark(it.name, d.deviation, lang)
        normal = math.atan2(-(q[0] - p[0]), -(q[1] - p[1]))  # perpendicular to the segment
        spot = labels.place(mx, my, text, SMALL, prefer=normal, must=False, bold=True)
        if spot is None:
            spot = labels.place(mx, my, it.name, SMALL, prefer=normal, must=False, bold=True)
            text = it.name
        if spot is not None:  # else only in the list under the panel
            g.add(dwg.text(text, insert=(spot[0], spot[1] + SMALL * 0.95), font_size=SMALL,
                           fill=RED, font_weight="bold"))
    if not items:
        g.add(dwg.text(w["nothing"], insert=(ox + 8, oy + PANEL - 8), font_size=SMALL, fill=GREY))
    dwg.add(g)
