"""The student's plan drawn over the computed one (``plans check --svg``).

Two panels, the velocity plan and the acceleration plan, each at its own zoom (the
numbers on it are millimetres at the student's scale factors):

* black: the computed plan, every segment the plan names, points labelled;
* red dashed: the student's plan rebuilt from the measured lengths
  (:func:`plans.check.rebuild`), a red ring at each point placed;
* red text: the segments beyond tolerance, with the deviation in mm, at the segment or,
  where it is crowded, farther out on a thin leader; a thin red line joins a computed
  point to where the student's drawing puts it when they differ;
* under each panel, every deviation beyond tolerance of that plan; below: the legend,
  the verdict and the diagnosis, in the language of the report, the method's notation
  with its indices (a^k_A3A as a with k above and A3A below, as the sheet writes it).

A small standalone SVG written with xml.etree (which escapes every text): the sheet
renderer (drawing.svg) draws GOST sheets in one colour, and this picture needs two.

Text is laid out by a fixed rule, not by the fonts of the machine: the advance of each
character in DejaVu Sans (what "sans-serif" is on Linux, and wider than Arial or
Helvetica), rounded up. Every text's box is kept (:class:`Overlay`), lines are wrapped
to the drawing, labels are placed greedily so that no two texts overlap and none sits on
a point, and the picture's height is what its texts need.
"""

from __future__ import annotations

import math
import re
import xml.etree.ElementTree as ET
from dataclasses import dataclass, field

import numpy as np

from drawing.scene import (
    INDEX_SIZE,
    SUB_SHIFT,
    SUP_SHIFT,
    Run,
    index_markup,
    parse_markup,
    shared_label,
)
from drawing.text import wrap_words
from plans.check.verdict import MU_KEY, CheckResult, rebuild, recorded_segments
from plans.fmt import listing, notation_in
from plans.plan.solution import image_sides

PANEL = 340.0  # user units (px) of one plan's square
MARGIN = 24.0
TITLE = 13.0
FONT = 11.0
SMALL = 9.5
INDENT = 12.0  # of a wrapped line's continuation
RED = "#c62828"
BLACK = "#222"
GREY = "#999"

WORDS = {
    "en": {
        "velocity": "Velocity plan (pole p), μ_v = {mu} (m/s)/mm",
        "acceleration": "Acceleration plan (pole π), μ_a = {mu} (m/s²)/mm",
        "legend_c": "computed plan",
        "legend_s": "student's plan, rebuilt from the measured lengths",
        "legend_d": "beyond tolerance: deviation in mm",
        "list": "beyond tolerance, mm:",
        "ok": "All measured segments within tolerance ({tol}).",
        "bad": "Beyond tolerance ({tol}): {names}.",
        "none": "Diagnosis: no single mistake explains this.",
        "slips": "Diagnosis: the plans are right; the items beyond tolerance are slips in measuring or writing down:",
        "diag": "Diagnosis: {what}.",
        "fix": "Correction: {fix}.",
        "title": "Check of a hand-drawn plan: {src}",
        "nothing": "(nothing measured on this plan)",
    },
    "ru": {
        "velocity": "План скоростей (полюс p), μ_v = {mu} (м/с)/мм",
        "acceleration": "План ускорений (полюс π), μ_a = {mu} (м/с²)/мм",
        "legend_c": "расчётный план",
        "legend_s": "план студента, восстановленный по измеренным отрезкам",
        "legend_d": "вне допуска: отклонение, мм",
        "list": "вне допуска, мм:",
        "ok": "Все измеренные отрезки в допуске ({tol}).",
        "bad": "Вне допуска ({tol}): {names}.",
        "none": "Диагноз: ни одна отдельная ошибка этого не объясняет.",
        "slips": "Диагноз: планы построены верно; отклонения — ошибки измерения или записи отдельных величин:",
        "diag": "Диагноз: {what}.",
        "fix": "Исправление: {fix}.",
        "title": "Проверка плана, построенного вручную: {src}",
        "nothing": "(на этом плане ничего не измерено)",
    },
}


# ---------------------------------------------------------------------------------------
# text extents
# ---------------------------------------------------------------------------------------


def _advances(groups: dict[float, str]) -> dict[str, float]:
    return {c: w for w, chars in groups.items() for c in chars}


#: advance in em of DejaVu Sans Book, rounded up to 0.05 em
_ADVANCE = _advances({
    0.25: "′", 0.30: "'IJijl", 0.35: " \u00a0,./:;\\|ι·", 0.40: "()-[]ft″", 0.45: "!r²³¹",
    0.50: '"*_`∥°–', 0.55: "?cszεζгзсэ⁻", 0.60: "FLkvxyγκλνξυχвтухчь",
    0.65: "$0123456789EPSTYabdeghnopqu{}βδηθμοπρστΣабеёийклоряГЕЁЗРТУ«»",
    0.70: "ABCKRVXZαφψΔднпцАБВСХЧЬЭЯ∆", 0.75: "NUъИЙК", 0.80: "&DGHOQΦΩмыДЛНОПЦ",
    0.85: "#+<=>^w~ωюЪ−≡×±≈≤≥→←", 0.90: "MфМФЫ⊥∠", 0.95: "жшщ", 1.00: "%@Wm…—",
    1.10: "ЖШЩЮ",
})
#: the same for DejaVu Sans Bold
_ADVANCE_BOLD = _advances({
    0.30: "′", 0.35: " \u00a0'ijl", 0.40: ",./:;IJ\\|ι·", 0.45: "-f″²³¹", 0.50: "!()[]_`rt∥°–",
    0.55: '"*г⁻', 0.60: "?cszεζξзстэ", 0.65: "LxλτχвхьяГ«»",
    0.70: "$0123456789EFTaekovyαγδθνουΣабеёкнопучЕЁТ∆",
    0.75: "CPSYZbdghnpqu{}βηκμρийлрцЗРСЭ", 0.80: "ABKRVXπσφψΔъАБВУХЬЯ",
    0.85: "#+<=>DGHNU^~дмИЙКЛНПЧ−≡×±≈≤≥→←", 0.90: "&OQωΦΩДО∠", 0.95: "wыЦЪ⊥",
    1.00: "@MжфюМФ…—", 1.05: "%mЫ", 1.10: "ш", 1.15: "Wщ", 1.20: "Ю", 1.25: "ЖШ", 1.35: "Щ",
})


def text_width(text: str, size: float, bold: bool = False) -> float:
    """The advance of ``text`` at font size ``size`` (px): DejaVu Sans's, rounded up per
    character; a character it does not list counts as 1 em (1.4 bold).

    >>> text_width("pd −4.2", 10)
    41.5
    """
    table, other = (_ADVANCE_BOLD, 1.4) if bold else (_ADVANCE, 1.0)
    return size * sum(table.get(c, other) for c in text)


def notation(text: str) -> tuple[Run, ...]:
    """The method's notation as the sheet writes it: V_A3A, a^k_A3A, V²_DC, μv → runs with
    their indices (:func:`drawing.scene.parse_markup`).

    >>> [(r.text, r.level) for r in notation("a^k_A3A = 2·ω3·V_A3A; pa = V_A/μv")]
    [('a', 0), ('k', 1), ('A3A', -1), (' = 2·ω3·V', 0), ('A3A', -1), ('; pa = V', 0), ('A', -1), ('/μ', 0), ('v', -1)]
    """
    s = index_markup(text.replace("\\", "\\\\"))
    s = re.sub(r"μ([vla])(?![A-Za-z0-9])", r"μ_\1", s)
    return parse_markup(s)


def runs_width(runs, size: float, bold: bool = False) -> float:
    return sum(text_width(r.text, size * (INDEX_SIZE if r.level else 1.0), bold) for r in runs)


def _extent(runs, size: float) -> tuple[float, float]:
    """How far a line of ``runs`` reaches above and below its baseline."""
    levels = {r.level for r in runs}
    up = max(0.95, SUP_SHIFT + 0.95 * INDEX_SIZE) if 1 in levels else 0.95
    down = max(0.25, SUB_SHIFT + 0.25 * INDEX_SIZE) if -1 in levels else 0.25
    return up * size, down * size


def _wrap(text: str, size: float, width: float, rich: bool, bold: bool = False,
          indent: float = INDENT) -> list[str]:
    """``text`` broken at spaces into lines no wider than ``width`` (the continuations
    ``indent`` narrower); a word wider than a line is cut."""
    def wide(s: str) -> float:
        return runs_width(notation(s) if rich else (Run(s),), size, bold)

    return wrap_words(text, width, wide, indent)


def _fit_left(text: str, size: float, width: float) -> str:
    """``text`` cut at its start with "…" until it fits ``width`` (a long path)."""
    if text_width(text, size) <= width:
        return text
    k = 1
    while k < len(text) and text_width("…" + text[k:], size) > width:
        k += 1
    return "…" + text[k:]


# ---------------------------------------------------------------------------------------
# the document
# ---------------------------------------------------------------------------------------


def _f(x) -> str:
    if isinstance(x, float | np.floating):
        return f"{float(x):.2f}".rstrip("0").rstrip(".")
    return str(x)


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


def _line(p, q, **kw) -> _El:
    return _El("line", x1=float(p[0]), y1=float(p[1]), x2=float(q[0]), y2=float(q[1]), **kw)


def _circle(c, r, **kw) -> _El:
    return _El("circle", cx=float(c[0]), cy=float(c[1]), r=float(r), **kw)


Box = tuple[float, float, float, float]


@dataclass
class Overlay:
    """The drawing and where its texts are: ``texts`` holds (text, box, role) for every
    text drawn, the box (x0, y0, x1, y1) in px as laid out; role: title, caption, point,
    deviation, list, legend or footer."""

    width: float
    height: float
    body: _El = field(repr=False)
    texts: list[tuple[str, Box, str]] = field(default_factory=list)

    def text(self, parent: _El, text: str, x: float, y: float, size: float, fill: str,
             role: str, *, bold: bool = False, rich: bool = False) -> Box:
        """A line of text with its baseline's start at (x, y); ``rich``: in the method's
        notation, indices as tspans (shifted by dy, as the sheet writes them)."""
        runs = notation(text) if rich else (Run(text),)
        attrs = {"x": float(x), "y": float(y), "font_size": size, "fill": fill}
        if bold:
            attrs["font_weight"] = "bold"
        el = parent.add(_El("text", **attrs))
        if all(r.level == 0 for r in runs):
            el.el.text = "".join(r.text for r in runs)
        else:
            shift = {0: 0.0, -1: SUB_SHIFT * size, 1: -SUP_SHIFT * size}
            now = 0.0
            if runs[0].level == 0:  # the text's start as the element's own text
                el.el.text = runs[0].text
                runs_after = runs[1:]
            else:
                runs_after = runs
            for r in runs_after:
                span = {"font_size": size * INDEX_SIZE} if r.level else {}
                if (dy := shift[r.level] - now) != 0:
                    span["dy"] = float(dy)
                el.add(_El("tspan", r.text, **span))
                now = shift[r.level]
        up, down = _extent(runs, size)
        box = (x, y - up, x + runs_width(runs, size, bold), y + down)
        self.texts.append(("".join(r.text for r in runs), box, role))
        return box

    def tostring(self) -> str:
        root = _El("svg", xmlns="http://www.w3.org/2000/svg", width=f"{self.width:.0f}px",
                   height=f"{self.height:.0f}px",
                   viewBox=f"0 0 {self.width:.0f} {self.height:.0f}",
                   font_family="sans-serif")
        root.add(_El("rect", x=0, y=0, width=f"{self.width:.0f}", height=f"{self.height:.0f}",
                     fill="white"))
        root.el.extend(list(self.body.el))
        return '<?xml version="1.0" encoding="utf-8"?>\n' + ET.tostring(root.el, encoding="unicode")


def _num(x: float, lang: str, digits: int = 4) -> str:
    from plans.fmt import num

    return num(x, digits, lang)


# ---------------------------------------------------------------------------------------
# labels on a panel
# ---------------------------------------------------------------------------------------

_NEAR = (4.0, 8.0, 13.0)  # ring distances (px) of a label next to its point
_FAR = (20.0, 28.0, 38.0, 50.0, 64.0, 80.0, 100.0, 125.0, 150.0)  # on a leader


class _Labels:
    """Greedy label placement in a panel: the first candidate around a point that stays
    in the panel and overlaps no text and no mark (a point, a line); farther out than
    :data:`_NEAR` a label hangs on a leader that crosses no text."""

    def __init__(self, box: Box, texts: list[Box]):
        self.box = box
        self.texts = texts  # boxes of texts: no label may overlap one
        self.marks: list[Box] = []  # points and lines: labels keep off them

    def block(self, x: float, y: float, r: float = 3.0) -> None:
        self.marks.append((x - r, y - r, x + r, y + r))

    def block_line(self, p, q, step: float = 6.0) -> None:
        n = max(int(math.hypot(q[0] - p[0], q[1] - p[1]) / step), 1)
        for i in range(n + 1):
            t = i / n
            self.block(p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1]), 1.2)

    @staticmethod
    def _overlap(cands: np.ndarray, taken: list[Box]) -> np.ndarray:
        """Area of overlap of each candidate box with all of ``taken``."""
        if not taken:
            return np.zeros(len(cands))
        t = np.asarray(taken)
        w = np.minimum(cands[:, None, 2], t[None, :, 2]) - np.maximum(cands[:, None, 0], t[None, :, 0])
        h = np.minimum(cands[:, None, 3], t[None, :, 3]) - np.maximum(cands[:, None, 1], t[None, :, 1])
        return (np.clip(w, 0, None) * np.clip(h, 0, None)).sum(axis=1)

    def _leader_hits(self, x: float, y: float, b: Box) -> bool:
        """Does the leader from (x, y) to box ``b`` cross a text?"""
        tx, ty = min(max(x, b[0]), b[2]), min(max(y, b[1]), b[3])
        n = max(int(math.hypot(tx - x, ty - y) / 2.0), 1)
        s = np.linspace(0.0, 1.0, n + 1)
        pts = np.stack([x + s * (tx - x), y + s * (ty - y)], axis=1)
        if not self.texts:
            return False
        t = np.asarray(self.texts)
        inside = ((pts[:, None, 0] > t[None, :, 0]) & (pts[:, None, 0] < t[None, :, 2])
                  & (pts[:, None, 1] > t[None, :, 1]) & (pts[:, None, 1] < t[None, :, 3]))
        return bool(inside.any())

    def place(self, x: float, y: float, w: float, h: float, prefer: float = 0.0,
              must: bool = True, rings=_NEAR + _FAR) -> tuple[Box, bool] | None:
        """The box (w × h) of a label for the point (x, y), and whether it needs a leader.
        ``prefer``: the angle (rad, y up) tried first. A label that must be placed takes
        the least crowded spot where nothing is free; one that need not, None."""
        x0, y0, x1, y1 = self.box
        best, best_cost = None, math.inf
        for ring in rings:
            n = 16 if ring < 30 else 32
            steps = [0, *[s for k in range(1, n // 2 + 1) for s in (k, -k)][:n - 1]]
            ang = prefer + np.array(steps) * (2 * math.pi / n)
            cx = x + (ring + w / 2) * np.cos(ang)
            cy = y - (ring + h / 2) * np.sin(ang)
            cands = np.stack([cx - w / 2, cy - h / 2, cx + w / 2, cy + h / 2], axis=1)
            out = (np.clip(x0 - cands[:, 0], 0, None) + np.clip(cands[:, 2] - x1, 0, None)
                   + np.clip(y0 - cands[:, 1], 0, None) + np.clip(cands[:, 3] - y1, 0, None))
            on_text = self._overlap(cands, self.texts)
            on_mark = self._overlap(cands, self.marks)
            leader = ring > _NEAR[-1]
            for i in np.argsort((out > 0) * 1e9 + on_text * 1e3 + on_mark, kind="stable"):
                b = tuple(float(v) for v in cands[i])
                free = out[i] == 0 and on_text[i] == 0 and on_mark[i] == 0
                if free and not (leader and self._leader_hits(x, y, b)):
                    return self._take(x, y, b, leader)
                cost = 1e6 * out[i] + 1e3 * on_text[i] + on_mark[i]
                if cost < best_cost:
                    best, best_cost = (b, leader), cost
                if not free:
                    break  # sorted: the rest of this ring is no better
        if not must or best is None:
            return None
        return self._take(x, y, *best)

    def _take(self, x: float, y: float, b: Box, leader: bool) -> tuple[Box, bool]:
        self.texts.append(b)
        if leader:
            tx, ty = min(max(x, b[0]), b[2]), min(max(y, b[1]), b[3])
            self.block_line((x, y), (tx, ty), step=4.0)
        return b, leader


# ---------------------------------------------------------------------------------------
# the picture
# ---------------------------------------------------------------------------------------


def overlay_svg(result: CheckResult, lang: str = "en") -> str:
    """The SVG document (text) of the overlay for one check."""
    return overlay(result, lang).tostring()


def overlay(result: CheckResult, lang: str = "en") -> Overlay:
    """The overlay for one check, its texts' boxes kept (:class:`Overlay`)."""
    w = WORDS[lang]
    meas = result.measurement
    sol = meas.solution
    student = rebuild(result)
    width = 2 * PANEL + 3 * MARGIN
    inner = width - 2 * MARGIN  # the width of a line of text
    doc = Overlay(width, 0.0, _El("g"))
    body = doc.body
    # the title (and the file's own), cut or wrapped to the drawing
    y = MARGIN
    title = w["title"].format(src="")
    src = _fit_left(meas.source, TITLE, inner - text_width(title, TITLE))
    doc.text(body, title + src, MARGIN, y, TITLE, BLACK, "title")
    for line in (_wrap(meas.title, SMALL, inner, rich=False) if meas.title else []):
        y += SMALL * 1.5
        doc.text(body, line, MARGIN, y, SMALL, BLACK, "title")
    # the panels' captions, each wrapped to its panel
    caps = {kind: _wrap(w[kind].format(mu=_num(meas.mu[MU_KEY[kind]], lang)), FONT, PANEL,
                        rich=True) for kind in ("velocity", "acceleration")}
    y += 10.0
    for i, kind in enumerate(("velocity", "acceleration")):
        x0 = MARGIN + i * (PANEL + MARGIN)
        for j, line in enumerate(caps[kind]):
            doc.text(body, line, x0 + (INDENT if j else 0.0), y + FONT + FONT * 1.5 * j, FONT,
                     BLACK, "caption", rich=True)
    top = y + FONT + FONT * 1.5 * (max(len(c) for c in caps.values()) - 1) + 8.0
    failed = {id(d.item) for d in result.failed}
    lists = {kind: _deviation_list(result, kind, lang) for kind in ("velocity", "acceleration")}
    for i, kind in enumerate(("velocity", "acceleration")):
        x0 = MARGIN + i * (PANEL + MARGIN)
        plan = sol.velocity if kind == "velocity" else sol.acceleration
        mu = meas.mu[MU_KEY[kind]]
        body.add(_El("rect", x=x0, y=top, width=PANEL, height=PANEL, fill="none", stroke="#ddd"))
        items = [(d, d.item) for d in result.deviations
                 if d.item.kind == "segment" and d.item.plan == kind]
        _panel(doc, (x0, top), plan, mu, student.get(kind, {}), items, failed, lang, w)
        for j, line in enumerate(lists[kind]):
            doc.text(body, line, x0 + (INDENT if j else 0.0), top + PANEL + 16 + 14 * j, SMALL,
                     RED, "list")
    below = max(len(v) for v in lists.values())
    y = top + PANEL + 14 * below + 32
    first = next((d for d in result.failed if d.item.kind == "segment"), None)
    mark = _mark(first.item.name, first.deviation, lang) if first else _mark("ab", -4.2, lang)
    y = _legend(doc, MARGIN, y, inner, w, mark) + 24
    for lines, color in _footer(result, lang, inner):
        for j, line in enumerate(lines):
            doc.text(body, line, MARGIN + (INDENT if j else 0.0), y, FONT, color, "footer",
                     rich=True)
            y += FONT * 1.65
    doc.height = math.ceil(y - FONT * 1.65 + FONT * 0.5 + MARGIN)
    return doc


def _deviation_list(result: CheckResult, kind: str, lang: str) -> list[str]:
    """"beyond tolerance, mm: πa3 +18.6, …" wrapped to the panel's width: every deviation
    beyond tolerance of the plan, those labelled on it too."""
    parts = [_mark(d.item.name, d.deviation, lang) for d in result.failed
             if d.item.kind == "segment" and d.item.plan == kind]
    if not parts:
        return []
    # broken between the marks, never inside one ("ka3 / +799.3")
    glued = [p.replace(" ", "\u00a0") for p in parts]
    text = WORDS[lang]["list"] + " " + listing(glued, lang)
    return [line.replace("\u00a0", " ") for line in _wrap(text, SMALL, PANEL, rich=False)]


def _footer(result: CheckResult, lang: str, width: float) -> list[tuple[list[str], str]]:
    """The verdict, the diagnosis and the correction, then what each item beyond
    tolerance that no mistake explains looks like ("are πc and πa3 swapped?", as the
    text says it), each wrapped to ``width``."""
    from plans.cli.check import lookalike_lines

    w = WORDS[lang]
    tol = result.tolerance.describe(lang)
    if result.ok:
        texts = [(w["ok"].format(tol=tol), BLACK)]
    else:
        texts = [(w["bad"].format(tol=tol, names=", ".join(notation_in(d.item.name, lang)
                                                             for d in result.failed)),
                  RED)]
        diag = result.diagnosis
        if result.slips_only:
            texts.append((w["slips"], BLACK))
        elif diag.best is None:
            texts.append((w["none"], BLACK))
        else:
            texts.append((w["diag"].format(what=diag.best.mistake.describe(lang)), BLACK))
            texts.append((w["fix"].format(fix=diag.best.mistake.correction(lang)), BLACK))
        texts += [(line.strip(), BLACK) for line in lookalike_lines(result, lang)]
    return [(_wrap(t, FONT, width, rich=True), color) for t, color in texts]


def _mark(name: str, deviation: float, lang: str) -> str:
    """A segment's deviation as the sheet marks it: "πa3 +18,6" (mm)."""
    from plans.fmt import signed

    return f"{notation_in(name, lang)} {signed(deviation, lang, 1)}"


def _legend(doc: Overlay, x: float, y: float, width: float, w, mark: str) -> float:
    """The legend from (x, y), wrapped to ``width``; returns the y of its last line.
    ``mark`` is the deviation shown as its sample: the first one beyond tolerance, so the
    legend names a segment of this sheet."""
    g = doc.body.add(_El("g"))
    right = x + width
    entries = [("computed", w["legend_c"]), ("student", w["legend_s"]), ("deviation", w["legend_d"])]
    at = x
    for kind, label in entries:
        sample = 24.0 if kind != "deviation" else text_width(mark, SMALL, bold=True)
        need = sample + 6 + text_width(label, SMALL)
        if at > x and at + need > right:
            at, y = x, y + 16
        if kind == "computed":
            g.add(_line((at, y - 3), (at + 24, y - 3), stroke=BLACK, stroke_width=1.2))
        elif kind == "student":
            g.add(_line((at, y - 3), (at + 24, y - 3), stroke=RED, stroke_width=1.4,
                        stroke_dasharray="5,3"))
            g.add(_circle((at + 12, y - 3), 2.6, fill="none", stroke=RED, stroke_width=1))
        else:
            doc.text(g, mark, at, y, SMALL, RED, "legend", bold=True)
        doc.text(g, label, at + sample + 6, y, SMALL, BLACK if kind == "computed" else RED,
                 "legend")
        at += need + 16
    return y


def _panel(doc: Overlay, origin, plan, mu, student, items, failed, lang, w):
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

    labels = _Labels((ox + 2, oy + 2, ox + PANEL - 2, oy + PANEL - 2), [])
    g = doc.body.add(_El("g"))
    # the computed plan, with the links' images its similarity points are found on, thin
    for a, b in segs.values():
        p, q = sc(comp[a]), sc(comp[b])
        g.add(_line(p, q, stroke=BLACK, stroke_width=1.1))
        labels.block_line(p, q)
    for a, b in image_sides(plan):
        p, q = sc(a / mu), sc(b / mu)
        g.add(_line(p, q, stroke=BLACK, stroke_width=0.5))
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
            g.add(_line(p, q, stroke=RED, stroke_width=1.8 if bad else 1.2,
                        stroke_dasharray="5,3", fill="none"))
            labels.block_line(p, q)
    moved = []
    for n, z in student.items():
        s = sc(z)
        g.add(_circle(s, 2.8, fill="none", stroke=RED, stroke_width=1))
        labels.block(*s, 3.5)
        c = sc(comp[n]) if n in comp else s
        if math.hypot(s[0] - c[0], s[1] - c[1]) > 6:
            g.add(_line(c, s, stroke=RED, stroke_width=0.6, stroke_opacity=0.7))
            labels.block_line(c, s)
            moved.append((n, s))

    def label(anchors, text, size, color, role, must, bold=False, dotted=False) -> bool:
        """``text`` at the first of ``anchors`` ((x, y, preferred angle)) with room next
        to it, else on a leader from the first with room farther out."""
        up, down = _extent((Run(text),), size)
        wide = text_width(text, size, bold)
        for rings in (_NEAR, _FAR):
            for x, y, prefer in anchors:
                spot = labels.place(x, y, wide + 2.0, up + down + 2.0, prefer=prefer,
                                    must=must and rings is _FAR, rings=rings)
                if spot is not None:
                    break
            if spot is not None:
                break
        if spot is None:
            return False
        b, leader = spot
        if leader:  # from the point to the label's box
            tx, ty = min(max(x, b[0]), b[2]), min(max(y, b[1]), b[3])
            g.add(_line((x, y), (tx, ty), stroke=color, stroke_width=0.6, stroke_opacity=0.8,
                        **({"stroke_dasharray": "1.5,1.5"} if dotted else {})))
        doc.text(g, text, b[0] + 1.0, b[1] + 1.0 + up, size, color, role, bold=bold)
        return True

    if not items:  # said before the labels are placed, so that none sits on it
        labels.texts.append(doc.text(g, w["nothing"], ox + 8, oy + PANEL - 8, SMALL, GREY,
                                     "caption"))

    def outward(x, y) -> float:
        return math.atan2(-(y - (oy + PANEL / 2)), x - (ox + PANEL / 2))

    # point labels: the computed points, then the student's where they differ
    for z, ns in names.items():
        x, y = sc(z)
        text = shared_label(ns, plan.pole, markup=False)  # "p,o,b", as on the sheet
        if len(ns) > 3:  # no room for them all: the first stands for them
            text = text.split(",")[0] + "…"
        label([(x, y, outward(x, y))], text, FONT, BLACK, "point", True)
    for n, (x, y) in moved:
        label([(x, y, outward(x, y))], n + "′", FONT, RED, "point", True)
    # the deviations beyond tolerance, at the student's segment, else at the computed one
    # (a student's plan drawn tiny leaves no room at its own); one that finds no room at
    # all is in the list under the panel all the same
    for d, it in items:
        if id(it) not in failed:
            continue
        anchors = []
        for src in (student, comp):
            if it.start not in src or it.end not in src:
                continue
            p, q = sc(src[it.start]), sc(src[it.end])
            normal = math.atan2(-(q[0] - p[0]), -(q[1] - p[1]))  # perpendicular to it
            anchors += [(p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1]), normal)
                        for t in (0.5, 0.3, 0.7)]
        label(anchors, _mark(it.name, d.deviation, lang), SMALL, RED, "deviation", False,
              bold=True, dotted=True)
