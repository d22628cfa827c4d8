"""The student's plan drawn over the computed one (``plans check --svg``).

Two panels, the velocity plan and the acceleration plan, each at its own zoom (the
numbers on it are millimetres at the student's scale factors):

* black: the computed plan, every segment the plan names, points labelled;
* red dashed: the student's plan rebuilt from the measured lengths
  (:func:`plans.check.rebuild`), a red ring at each point placed;
* red text: the segments beyond tolerance, with the deviation in mm, at the segment or,
  where it is crowded, farther out on a dotted leader; a thin red line joins a computed
  point to where the student's drawing puts it when they differ;
* under each panel, every deviation beyond tolerance of that plan; below: the legend,
  the verdict and the diagnosis, in the language of the report, the method's notation
  with its indices (a^k_A3A as a with k above and A3A below, as the sheet writes it).

It is drawn as the sheets are: one :class:`~drawing.scene.Scene` (a layer per colour and
line, each with its own :class:`~drawing.styles.Style`) written by :mod:`drawing.svg` on a
page measured in px, its text in the project's osifont, laid out by the one fixed rule of
:mod:`drawing.text`, and its letters placed by :func:`drawing.labels.place_labels`. Every
text's box is kept (:class:`Overlay`), lines are wrapped to the drawing, no two texts
overlap and none sits on a point, and the picture's height is what its texts need.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass, field, replace

import shapely

from drawing.labels import LabelRequest, place_labels
from drawing.obstacles import obstacles_of
from drawing.scene import (
    Blank,
    Circle,
    Item,
    Layer,
    Page,
    Polyline,
    Run,
    Scene,
    Segment,
    Text,
    index_markup,
    parse_markup,
    shared_label,
)
from drawing.styles import LineType, Style
from drawing.svg import to_svg
from drawing.text import runs_width, text_box, wrap_words
from drawing.text import text_width as rule_width
from plans.check.describe import lookalike_lines
from plans.check.verdict import MU_KEY, CheckResult, rebuild, recorded_segments
from plans.fmt import listing, notation_in, num, signed
from plans.plan.solution import image_sides

__all__ = ["WORDS", "Overlay", "mark", "notation", "overlay", "overlay_svg", "text_width"]

PANEL = 340.0  # px of one plan's square
MARGIN = 24.0
#: font sizes (px, the em); the rule and the scene take the capitals' height
TITLE = 13.0
FONT = 11.0
SMALL = 9.5
INDENT = 12.0  # of a wrapped line's continuation
RED = "#c62828"
BLACK = "#222"
GREY = "#999"
#: red at 70 % on white: the thin line from a computed point to the student's
PALE_RED = "#d86868"
CAP = Style().cap_height  # capitals' height per em, of osifont

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
        "slips": "Diagnosis: the plans are right; the items beyond tolerance are slips in "
                 "measuring or writing down:",
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
        "slips": "Диагноз: планы построены верно; отклонения — ошибки измерения или записи "
                 "отдельных величин:",
        "diag": "Диагноз: {what}.",
        "fix": "Исправление: {fix}.",
        "title": "Проверка плана, построенного вручную: {src}",
        "nothing": "(на этом плане ничего не измерено)",
    },
}

#: the picture's layers, bottom first, each with its colour, widths and dashes
STYLES = {
    "paper": Style(),
    "panels": Style(thin=1.0, color="#ddd"),
    "computed": Style(s=1.1, thin=0.5, color=BLACK),  # the plan's segments, the images thin
    "student": Style(s=1.0, thin=1.2, dash=5.0, dash_gap=3.0, color=RED),  # rings: s
    "beyond": Style(thin=1.8, dash=5.0, dash_gap=3.0, color=RED),
    "moved": Style(thin=0.6, color=PALE_RED),
    "text": Style(color=BLACK),  # the title first
    "red-text": Style(color=RED),
    "grey-text": Style(color=GREY),
    "letters": Style(thin=0.6, color=BLACK),  # the points' letters and their leaders
    "moved-letters": Style(thin=0.6, color=RED),
    "deviations": Style(thin=0.6, dash=1.5, dash_gap=1.5, color=RED),  # leaders dotted
}
#: what a line may be drawn wider than the rule says (its stated ±10 %): lines are wrapped
#: and cut to the drawing at the rule's width times this, so that none runs out of it
SPARE = 1.1
#: px from a point to its letter's box, nearest first; beyond them, on a leader
NEAR = (4.0, 8.0, 13.0)
FAR = (20.0, 28.0, 38.0, 50.0, 64.0, 80.0, 100.0, 125.0, 150.0)
#: px a line's ink is widened by for the letters to keep clear of, and a point's round
CLEAR = 1.5
POINT_R = 3.5

Box = tuple[float, float, float, float]

#: what the picture writes for the characters osifont has no glyph for (the PNG would
#: print a box): the sheets write ∥ as "||" too
STAND_INS = {"∥": "||", "⊥": "_|_", "…": "...", "→": "->"}
_PLAIN = str.maketrans(STAND_INS)
_RICH = str.maketrans({c: s.replace("_", "\\_") for c, s in STAND_INS.items()})


def text_width(text: str, size: float) -> float:
    """The advance of ``text`` at font size ``size`` (px, the em) by the one fixed rule
    (:func:`drawing.text.text_width`), its capitals :data:`CAP` of the em high.

    >>> round(text_width("pd −4.2", 10), 2)
    35.52
    """
    return rule_width(text, size * CAP)


def notation(text: str) -> tuple[Run, ...]:
    """The method's notation as the sheet writes it: V_A3A, a^k_A3A, V²_DC, μv → runs with
    their indices (:func:`drawing.scene.parse_markup`).

    >>> [(r.text, r.level) for r in notation("a^k_A3A = 2·ω3·V_A3A; pa = V_A/μv")]
    [('a', 0), ('k', 1), ('A3A', -1), (' = 2·ω3·V', 0), ('A3A', -1), ('; pa = V', 0),
     ('A', -1), ('/μ', 0), ('v', -1)]
    """
    return parse_markup(_markup(text))


def _markup(text: str) -> str:
    s = index_markup(text.replace("\\", "\\\\")).translate(_RICH)
    return re.sub(r"μ([vla])(?![A-Za-z0-9])", r"μ_\1", s)


def _text(text: str, x: float, y: float, size: float, rich: bool = False) -> Text:
    """A line at font size ``size`` with its baseline's start at (x, y), upright."""
    return Text((x, y), _markup(text) if rich else text.translate(_PLAIN), size=size * CAP,
                italic=False, markup=rich)


def _wide(text: str, size: float, rich: bool) -> float:
    """The advance of ``text`` at font size ``size``, indices at their size if ``rich``."""
    return runs_width(notation(text) if rich else (Run(text.translate(_PLAIN)),), size * CAP)


def _wrap(text: str, size: float, width: float, rich: bool, indent: float = INDENT) -> list[str]:
    """``text`` broken at spaces into lines no wider than ``width`` (the continuations
    ``indent`` narrower); a word wider than a line is cut."""
    return wrap_words(text, width, lambda s: SPARE * _wide(s, size, rich), indent)


def _fit_left(text: str, size: float, width: float) -> str:
    """``text`` cut at its start with "..." until it fits ``width`` (a long path)."""
    if SPARE * text_width(text, size) <= width:
        return text
    k = 1
    while k < len(text) and SPARE * text_width("..." + text[k:], size) > width:
        k += 1
    return "..." + text[k:]


@dataclass
class Overlay:
    """The drawing and where its texts are: ``texts`` holds (text, box, role) for every
    text drawn, the box (x0, y0, x1, y1) in px as laid out; role: title, caption, point,
    deviation, list, legend or footer. ``layers``: what each layer of :data:`STYLES`
    draws."""

    width: float
    height: float
    layers: dict[str, list[Item]] = field(default_factory=lambda: {k: [] for k in STYLES},
                                          repr=False)
    texts: list[tuple[str, Box, str]] = field(default_factory=list)
    #: the layer of each of ``texts``
    text_layers: list[str] = field(default_factory=list, repr=False)

    def text(self, layer: str, text: str, x: float, y: float, size: float, role: str, *,
             rich: bool = False) -> Box:
        """A line of text with its baseline's start at (x, y) in ``layer`` (its colour);
        ``rich``: in the method's notation, indices as the sheet writes them."""
        t = _text(text, x, y, size, rich)
        self.layers[layer].append(t)
        box = tuple(float(b) for b in text_box(t).bounds)
        self.texts.append(("".join(r.text for r in t.runs()), box, role))
        self.text_layers.append(layer)
        return box

    def drawing_order(self) -> None:
        """``texts`` in the order the SVG draws them: layer by layer, as
        :data:`STYLES` lists them, each in the order it was laid out."""
        order = list(STYLES)
        pairs = sorted(zip(self.text_layers, self.texts, strict=True),
                       key=lambda lt: order.index(lt[0]))
        self.text_layers = [layer for layer, _ in pairs]
        self.texts = [t for _, t in pairs]

    def scene(self) -> Scene:
        """The drawing as one scene, a layer per entry of :data:`STYLES`, on white."""
        self.layers["paper"] = [Blank((0.0, 0.0), (self.width, self.height))]
        return Scene(tuple(Layer(name, tuple(items), STYLES[name])
                           for name, items in self.layers.items() if items))

    def tostring(self) -> str:
        """The SVG document, written by :func:`drawing.svg.to_svg` (osifont embedded)."""
        return to_svg(self.scene(), Page(float(self.width), float(self.height)),
                      style=STYLES["text"])


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
    doc = Overlay(width, 0.0)
    # the title (and the file's own), cut or wrapped to the drawing
    y = MARGIN
    title = w["title"].format(src="")
    src = _fit_left(meas.source, TITLE, inner - SPARE * text_width(title, TITLE))
    doc.text("text", title + src, MARGIN, y, TITLE, "title")
    for line in (_wrap(meas.title, SMALL, inner, rich=False) if meas.title else []):
        y += SMALL * 1.5
        doc.text("text", line, MARGIN, y, SMALL, "title")
    # the panels' captions, each wrapped to its panel
    caps = {kind: _wrap(w[kind].format(mu=num(meas.mu[MU_KEY[kind]], 4, lang)), FONT, PANEL,
                        rich=True) for kind in ("velocity", "acceleration")}
    y += 10.0
    for i, kind in enumerate(("velocity", "acceleration")):
        x0 = MARGIN + i * (PANEL + MARGIN)
        for j, line in enumerate(caps[kind]):
            doc.text("text", line, x0 + (INDENT if j else 0.0), y + FONT + FONT * 1.5 * j, FONT,
                     "caption", rich=True)
    top = y + FONT + FONT * 1.5 * (max(len(c) for c in caps.values()) - 1) + 8.0
    failed = {id(d.item) for d in result.failed}
    lists = {kind: _deviation_list(result, kind, lang) for kind in ("velocity", "acceleration")}
    for i, kind in enumerate(("velocity", "acceleration")):
        x0 = MARGIN + i * (PANEL + MARGIN)
        plan = sol.velocity if kind == "velocity" else sol.acceleration
        mu = meas.mu[MU_KEY[kind]]
        doc.layers["panels"].append(Polyline([(x0, top), (x0 + PANEL, top),
                                              (x0 + PANEL, top + PANEL), (x0, top + PANEL)],
                                             LineType.THIN, closed=True))
        items = [(d, d.item) for d in result.deviations
                 if d.item.kind == "segment" and d.item.plan == kind]
        _panel(doc, (x0, top), plan, mu, student.get(kind, {}), items, failed, lang, w)
        for j, line in enumerate(lists[kind]):
            doc.text("red-text", line, x0 + (INDENT if j else 0.0), top + PANEL + 16 + 14 * j,
                     SMALL, "list")
    below = max(len(v) for v in lists.values())
    y = top + PANEL + 14 * below + 32
    first = next((d for d in result.failed if d.item.kind == "segment"), None)
    sample = mark(first.item.name, first.deviation, lang) if first else mark("ab", -4.2, lang)
    y = _legend(doc, MARGIN, y, inner, w, sample) + 24
    for lines, layer in _footer(result, lang, inner):
        for j, line in enumerate(lines):
            doc.text(layer, line, MARGIN + (INDENT if j else 0.0), y, FONT, "footer", rich=True)
            y += FONT * 1.65
    doc.height = math.ceil(y - FONT * 1.65 + FONT * 0.5 + MARGIN)
    doc.drawing_order()
    return doc


def _deviation_list(result: CheckResult, kind: str, lang: str) -> list[str]:
    """"beyond tolerance, mm: πa3 +18.6, …" wrapped to the panel's width: every deviation
    beyond tolerance of the plan, those labelled on it too."""
    parts = [mark(d.item.name, d.deviation, lang) for d in result.failed
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
    text says it), each wrapped to ``width``, with the layer (colour) it is drawn in."""

    w = WORDS[lang]
    tol = result.tolerance.describe(lang)
    if result.ok:
        texts = [(w["ok"].format(tol=tol), "text")]
    else:
        texts = [(w["bad"].format(tol=tol, names=", ".join(notation_in(d.item.name, lang)
                                                             for d in result.failed)),
                  "red-text")]
        diag = result.diagnosis
        if result.slips_only:
            texts.append((w["slips"], "text"))
        elif diag.best is None:
            texts.append((w["none"], "text"))
        else:
            texts.append((w["diag"].format(what=diag.best.mistake.describe(lang)), "text"))
            texts.append((w["fix"].format(fix=diag.best.mistake.correction(lang)), "text"))
        texts += [(line.strip(), "text") for line in lookalike_lines(result, lang)]
    return [(_wrap(t, FONT, width, rich=True), layer) for t, layer in texts]


def mark(name: str, deviation: float, lang: str) -> str:
    """A segment's deviation as the sheet marks it: "πa3 +18,6" (mm)."""
    return f"{notation_in(name, lang)} {signed(deviation, lang, 1)}"


def _legend(doc: Overlay, x: float, y: float, width: float, w, sample: str) -> float:
    """The legend from (x, y), wrapped to ``width``; returns the y of its last line.
    ``sample`` is the deviation shown as its sample: the first one beyond tolerance, so
    the legend names a segment of this sheet."""
    right = x + width
    entries = [("computed", w["legend_c"]), ("student", w["legend_s"]), ("deviation", w["legend_d"])]
    at = x
    for kind, label in entries:
        drawn = 24.0 if kind != "deviation" else SPARE * text_width(sample, SMALL)
        need = drawn + 6 + SPARE * text_width(label, SMALL)
        if at > x and at + need > right:
            at, y = x, y + 16
        if kind == "computed":
            doc.layers["computed"].append(Segment((at, y - 3), (at + 24, y - 3), LineType.MAIN))
        elif kind == "student":
            doc.layers["student"] += [Segment((at, y - 3), (at + 24, y - 3), LineType.DASHED),
                                      Circle((at + 12, y - 3), 2.6, LineType.MAIN)]
        else:
            doc.text("red-text", sample, at, y, SMALL, "legend")
        doc.text("text" if kind == "computed" else "red-text", label, at + drawn + 6, y, SMALL,
                 "legend")
        at += need + 16
    return y


def _compass(angle: float) -> str:
    """The compass direction on the sheet nearest ``angle`` (rad, y up, from east)."""
    k = round(math.degrees(angle) / 45.0) % 8
    return ("e", "ne", "n", "nw", "w", "sw", "s", "se")[k]


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

    drawn: dict[str, list[Item]] = {k: [] for k in ("computed", "student", "beyond", "moved")}
    # the computed plan, with the links' images its similarity points are found on, thin
    for a, b in segs.values():
        drawn["computed"].append(Segment(sc(comp[a]), sc(comp[b]), LineType.MAIN))
    drawn["computed"] += [Segment(sc(a / mu), sc(b / mu), LineType.THIN)
                          for a, b in image_sides(plan)]
    names: dict[complex, list[str]] = {}
    for n, z in comp.items():
        names.setdefault(z, []).append(n)
    spots = [sc(z) for z in names]
    # the student's plan
    for _, it in items:
        if it.start in student and it.end in student:
            layer = "beyond" if id(it) in failed else "student"
            drawn[layer].append(Segment(sc(student[it.start]), sc(student[it.end]),
                                        LineType.DASHED))
    moved = []
    for n, z in student.items():
        s = sc(z)
        drawn["student"].append(Circle(s, 2.8, LineType.MAIN))
        spots.append(s)
        c = sc(comp[n]) if n in comp else s
        if math.hypot(s[0] - c[0], s[1] - c[1]) > 6:
            drawn["moved"].append(Segment(c, s, LineType.THIN))
            moved.append((n, s))
    for layer, its in drawn.items():
        doc.layers[layer] += its
    # what the letters keep clear of: every line as drawn, every point's round
    obstacles = [g for layer, its in drawn.items()
                 for g in obstacles_of(its, STYLES[layer], clearance=CLEAR)]
    obstacles += [shapely.Point(p).buffer(POINT_R) for p in spots]
    taken = []
    if not items:  # said before the labels are placed, so that none sits on it
        taken.append(shapely.box(*doc.text("grey-text", w["nothing"], ox + 8, oy + PANEL - 8,
                                           SMALL, "caption")))

    def outward(x, y) -> str:
        return _compass(math.atan2(-(y - (oy + PANEL / 2)), x - (ox + PANEL / 2)))

    # point labels: the computed points, then the student's where they differ; then the
    # deviations beyond tolerance, at the student's segment, else at the computed one
    # (a student's plan drawn tiny leaves no room at its own); one that finds no room at
    # all is in the list under the panel all the same
    reqs: list[LabelRequest] = []
    kinds: list[tuple[str, str]] = []  # (layer, role) of each request
    for z, ns in names.items():
        x, y = sc(z)
        text = shared_label(ns, plan.pole, markup=False)  # "p,o,b", as on the sheet
        if len(ns) > 3:  # no room for them all: the first stands for them
            text = text.split(",")[0] + "..."
        reqs.append(LabelRequest((x, y), text, FONT * CAP, outward(x, y), markup=False,
                                 italic=False))
        kinds.append(("letters", "point"))
    for n, (x, y) in moved:
        reqs.append(LabelRequest((x, y), n + "′", FONT * CAP, outward(x, y), markup=False,
                                 italic=False))
        kinds.append(("moved-letters", "point"))
    for d, it in items:
        if id(it) not in failed:
            continue
        anchors: list[tuple[float, float]] = []
        prefer = None
        for src in (student, comp):
            if it.start not in src or it.end not in src:
                continue
            p, q = sc(src[it.start]), sc(src[it.end])
            if prefer is None:  # perpendicular to the segment
                prefer = _compass(math.atan2(-(q[0] - p[0]), -(q[1] - p[1])))
            anchors += [(p[0] + t * (q[0] - p[0]), p[1] + t * (q[1] - p[1]))
                        for t in (0.5, 0.3, 0.7)]
        if not anchors:
            continue
        reqs.append(LabelRequest(anchors[0], mark(it.name, d.deviation, lang).translate(_PLAIN),
                                 SMALL * CAP,
                                 prefer, markup=False, optional=True, also=tuple(anchors[1:]),
                                 italic=False))
        kinds.append(("deviations", "deviation"))
    region = shapely.box(ox + 2, oy + 2, ox + PANEL - 2, oy + PANEL - 2)
    placed = place_labels(reqs, obstacles, taken, region, distances=NEAR + FAR,
                          leader_from=NEAR[-1])
    for req, p, (layer, role) in zip(reqs, placed, kinds, strict=True):
        if req.optional and not (p.clear or p.leader):
            continue  # no room: the list under the panel names it
        if p.leader is not None:  # from the point to the label's box
            doc.layers[layer].append(Segment(*p.leader, LineType.DASHED if role == "deviation"
                                             else LineType.THIN))
        box = tuple(float(b) for b in p.box.bounds)
        text = replace(p.text, pos=(box[0], p.text.pos[1]), anchor="start")  # x: its start
        doc.layers[layer].append(text)
        doc.texts.append((text.text, box, role))
        doc.text_layers.append(layer)

