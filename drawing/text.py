"""Text by one fixed rule: extents, widths of marked-up runs, fitting into cells, wrapping.

Text widths come from a **fixed rule, not from the fonts installed on the
machine**, so that a layout (and its tests) is the same everywhere.  The rule
is GOST 2.304 type B, with *h* the capital height:

* capitals and digits 0.6 h wide, lowercase 0.5 h, punctuation and spaces 0.3 h;
* Latin and Greek letters 0.1 h wider, the widest letters (Ж, Ш, Щ, Ы, Ю, №, M,
  W; ж, ш, щ, ы, ю, м, и, й, m, w, ω) 0.9 h and 0.65 h, I, i, l, 1 0.3 h,
  dashes 0.45 h: the classes as osifont draws them;
* 0.2 h of letter spacing between characters;
* height h above the baseline, descent 0.3 h below it.

Against osifont's real advances the rule is within about ±10 % on words.

>>> text_width("Изм.", 2.5)
6.625
>>> text_box(Text((0, 0), "AB", size=10)).bounds
(0.0, -10.0, 18.68, 3.0)
"""

from __future__ import annotations

import itertools
import math
import unicodedata
from collections.abc import Callable, Sequence
from typing import Literal

from shapely.geometry import Polygon

from drawing.scene import INDEX_SIZE, SUB_SHIFT, SUP_SHIFT, Rect, Run, Text

__all__ = [
    "DESCENT",
    "LINE_PITCH",
    "SLANT",
    "SPACING",
    "char_width",
    "fit_text",
    "runs_width",
    "text_box",
    "text_width",
    "wrap_words",
]

SPACING = 0.2  # letter spacing, in h
DESCENT = 0.3  # below the baseline, in h
LINE_PITCH = 1.7  # baseline to baseline, in h (GOST 2.304 type B minimum)
SLANT = math.tan(math.radians(15))  # lean of 75° letters per unit of height
_WIDE = {  # letters much wider than their class in osifont: width in h
    **dict.fromkeys("ЖШЩЫЮ№MW", 0.9),
    **dict.fromkeys("жшщыюмийmwω", 0.65),
}
_NARROW = {**dict.fromkeys("Iil1|", 0.3), **dict.fromkeys("-–—", 0.45)}


def char_width(c: str) -> float:
    """Width of one character in units of h, without the letter spacing.

    The GOST type B classes, with Latin and Greek letters one step wider
    than Cyrillic ones because osifont draws them so (measured: Latin
    lowercase 0.58 h, Cyrillic 0.46 h, before spacing).

    >>> [char_width(c) for c in "ДдAa."]
    [0.6, 0.5, 0.7, 0.6, 0.3]
    """
    if c in _WIDE:
        return _WIDE[c]
    if c in _NARROW:
        return _NARROW[c]
    if c.isspace() or unicodedata.category(c).startswith("P"):
        return 0.3
    wider = 0.1 if unicodedata.name(c, "").startswith(("LATIN", "GREEK")) else 0.0
    if c.islower():
        return 0.5 + wider
    if c.isalpha():
        return 0.6 + wider
    return 0.6  # digits and symbols


def text_width(text: str, size: float) -> float:
    """Estimated advance of ``text`` at capital height ``size`` (mm)."""
    if not text:
        return 0.0
    return size * (sum(char_width(c) for c in text) + SPACING * (len(text) - 1))


def runs_width(runs: Sequence[Run], size: float) -> float:
    """Advance of marked-up runs: indices at 0.7 h, in turn after their base."""
    total, count = 0.0, 0
    for r in runs:
        h = size if r.level == 0 else size * INDEX_SIZE
        total += text_width(r.text, h) + (SPACING * h if count else 0.0)
        count += 1
    return total


def text_box(t: Text) -> Polygon:
    """The box of ``t`` on the sheet: advance × (h + descent).

    Anchor, baseline, rotation, horizontal stretch and the lean of slanted letters at
    the top of the box are honoured.
    """
    runs = t.runs()
    w = runs_width(runs, t.size) * t.stretch
    x0 = {"start": 0.0, "middle": -w / 2, "end": -w}[t.anchor]
    base, h = t.baseline_shift, t.size
    levels = {r.level for r in runs}
    up = SUP_SHIFT + INDEX_SIZE if 1 in levels else 1.0
    down = SUB_SHIFT + DESCENT * INDEX_SIZE if -1 in levels else DESCENT
    top, bottom = base - h * max(1.0, up), base + h * max(DESCENT, down)
    a = math.radians(t.rotate_deg)
    ca, sa = math.cos(a), math.sin(a)
    px, py = t.pos
    lean = SLANT * (base - top) if t.italic else 0.0
    local = ((x0, top), (x0 + w + lean, top), (x0 + w + lean, bottom), (x0, bottom))
    return Polygon([(px + x * ca - y * sa, py + x * sa + y * ca) for x, y in local])


# ---------------------------------------------------------------- fitting into cells


def _wrap(text: str, size: float, lines: int) -> tuple[str, ...] | None:
    """``text`` broken at spaces into ``lines`` lines of the least widest width."""
    words = text.split()
    if len(words) < lines:
        return None
    best: tuple[str, ...] | None = None
    best_w = math.inf
    for cuts in itertools.combinations(range(1, len(words)), lines - 1):
        bounds = (0, *cuts, len(words))
        parts = tuple(" ".join(words[a:b]) for a, b in itertools.pairwise(bounds))
        w = max(text_width(p, size) for p in parts)
        if w < best_w:
            best, best_w = parts, w
    return best


def _need(lines: Sequence[str], size: float) -> tuple[float, float]:
    """Advance of the widest line, and the height a block needs with its
    capitals centred in a cell (room for the descent above and below)."""
    width = max(text_width(s, size) for s in lines)
    block = size * (1 + LINE_PITCH * (len(lines) - 1))
    return width, block + 2 * DESCENT * size


def fit_text(
    text: str,
    cell: Rect,
    *,
    sizes: Sequence[float] = (3.5, 2.5),
    max_lines: int = 1,
    align: Literal["start", "middle"] = "middle",
    pad: float = 0.3,
    inset: float = 0.7,
    slant: float = SLANT,
    min_stretch: float = 0.8,
) -> tuple[Text, ...]:
    """Lines of ``text`` set inside ``cell``, as large as they fit.

    1. Sizes are tried largest first; at each size one line, then two and
       more up to ``max_lines``, broken at spaces into lines of even width.
    2. If nothing fits, the smallest size is condensed horizontally, down to
       ``min_stretch`` (KiCad's GOST sheet writes "Изм." at 80 % width).
    3. If that is not enough either, it is shrunk below the smallest size, so
       that text never leaves its cell.

    The capitals of the block are centred vertically; horizontally the lines
    are centred, or start ``inset`` mm from the left edge.  ``pad`` mm stays
    free on every side (make it half the cell's line width plus a little), and
    the lean of slanted letters (``slant`` × h, tan 15°) is counted in.

    >>> [(t.text, t.size) for t in fit_text("Масштаб", Rect(0, 0, 18, 5), sizes=(2.5,))]
    [('Масштаб', 2.5)]
    >>> [t.text for t in fit_text("Кинематический анализ", Rect(0, 0, 60, 20),
    ...                              sizes=(5.0,), max_lines=2)]
    ['Кинематический', 'анализ']
    >>> cell = Rect(0, 0, 7, 5)
    >>> [(t.size, t.stretch) for t in fit_text("Изм.", cell, sizes=(2.5,), pad=0.45)]
    [(2.5, 0.81)]
    """
    if not text:
        return ()
    sizes = sorted(sizes, reverse=True)
    avail_w = cell.w - 2 * pad - (inset - pad if align == "start" else 0.0)
    avail_h = cell.h - 2 * pad

    def layouts(size: float) -> list[tuple[str, ...]]:
        out = [(text,)]
        for n in range(2, max_lines + 1):
            if wrapped := _wrap(text, size, n):
                out.append(wrapped)
        return out

    def stretch_needed(lines: tuple[str, ...], size: float) -> float:
        """Horizontal scale making the block fit (>1: room to spare; 0: too tall)."""
        w, h = _need(lines, size)
        if h > avail_h + 1e-9:
            return 0.0
        return (avail_w - slant * size) / w if w > 0 else math.inf

    chosen: tuple[float, float, tuple[str, ...]] | None = None
    for size in sizes:
        for lines in layouts(size):
            if stretch_needed(lines, size) >= 1 - 1e-9:
                chosen = (size, 1.0, lines)
                break
        if chosen:
            break
    if chosen is None:
        size = sizes[-1]
        lines = max(layouts(size), key=lambda ls: stretch_needed(ls, size))
        k = stretch_needed(lines, size)
        if k >= min_stretch:
            chosen = (size, math.floor(k * 100) / 100, lines)
        else:  # shrink at the narrowest stretch until both width and height fit
            w, h = _need(lines, size)
            scale = min(avail_w / (w * min_stretch + slant * size), avail_h / h)
            chosen = (math.floor(size * scale * 100) / 100, min_stretch, lines)

    size, stretch, lines = chosen
    pitch = LINE_PITCH * size
    cx, cy = cell.center
    first = cy + size / 2 - pitch * (len(lines) - 1) / 2  # baseline of line 1
    x = cx if align == "middle" else cell.x + inset
    return tuple(
        Text((x, first + i * pitch), line, size=size, anchor=align, stretch=stretch)
        for i, line in enumerate(lines)
    )


def wrap_words(text: str, width: float, measure: Callable[[str], float], indent: float = 0.0,
               cut: bool = True) -> list[str]:
    """``text`` broken at its spaces (not at no-break spaces) into lines ``measure``
    (str → mm) no wider than ``width``, the continuations ``indent`` narrower. A word
    wider than a line is cut (``cut``), or stands alone on its line."""
    lines: list[str] = []
    cur = ""
    for word in text.split(" "):
        room = width - (indent if lines else 0.0)
        trial = f"{cur} {word}" if cur else word
        if measure(trial) <= room:
            cur = trial
            continue
        if cur:
            lines.append(cur)
            room = width - indent
        cur = word
        while cut and measure(cur) > room and len(cur) > 1:
            k = len(cur)
            while k > 1 and measure(cur[:k]) > room:
                k -= 1
            lines.append(cur[:k])
            cur = cur[k:]
            room = width - indent
    if cur or not lines:
        lines.append(cur)
    return lines
