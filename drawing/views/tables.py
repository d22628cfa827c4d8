"""The tables of a sheet (the plans' segments, the links' ω and ε) and the note view."""

from __future__ import annotations

from collections.abc import Sequence

from drawing.scene import Item, Segment, Text, name_markup
from drawing.styles import LineType
from drawing.text import LINE_PITCH, SLANT, text_box, text_width, wrap_words
from drawing.views.common import WORDS, View, assembled, bbox, centred, notation, shifted
from plans.fmt import notation_in, num

__all__ = ["PART_GAP", "note_view", "omega_table_view", "segments_table_view", "table_view"]

def table_view(name: str, caption: str, header: list[str], rows: list[list[str]],
               widths: list[float], row_h: float = 7.0, parts: int = 1, sizing: bool = False,
               body: float | Sequence[float] = 2.5) -> View:
    """A table under its caption; ``parts`` > 1 sets its rows in that many tables side
    by side, each under the header (a tall table on a small sheet). ``sizing``: its lines
    only (every cell's text is fitted into its cell), for its size. The cells are
    markup (``R^τ_{34}``), the header's 3.5 mm, the others' ``body`` mm, or each
    column's (3.5 keeps indices at GOST 2.304's 1.8 mm or more)."""
    items: list[Item] = []
    total_w = sum(widths)
    per = -(-len(rows) // max(1, parts))  # rows of each part, the last one's fewer
    chunks = [rows[i:i + per] for i in range(0, len(rows), per)] or [[]]
    for k, chunk in enumerate(chunks):
        items += shifted(_grid(header, chunk, widths, row_h, sizing, body),
                         k * (total_w + PART_GAP), 0.0)
    span = len(chunks) * total_w + (len(chunks) - 1) * PART_GAP
    return assembled(name, (items, []), (0.0, 0.0, span, bbox(items)[3]), caption, "fit")


#: mm between the parts of a table set side by side
PART_GAP = 6.0


def _grid(header: list[str], rows: list[list[str]], widths: list[float], row_h: float,
          lines_only: bool = False, body: float | Sequence[float] = 2.5) -> list[Item]:
    """The lines and cells of one table, its top-left corner at (0, 0)."""
    items: list[Item] = []
    total_w = sum(widths)
    n = len(rows) + 1
    for i in range(n + 1):
        line = LineType.MAIN if i in (0, 1, n) else LineType.THIN
        items.append(Segment((0, i * row_h), (total_w, i * row_h), line))
    x = 0.0
    for wd in [0.0, *widths]:
        x += wd
        items.append(Segment((x, 0), (x, n * row_h), LineType.MAIN))
    sizes = [body] * len(widths) if isinstance(body, int | float) else list(body)
    for r, row in enumerate([] if lines_only else [header, *rows]):
        x = 0.0
        for cell, wd, size in zip(row, widths, sizes, strict=True):
            size = size if r else 3.5
            pos = (x + wd / 2, r * row_h + row_h / 2)
            t = centred(pos, cell, size, "middle")
            bw = text_box(t).bounds
            if bw[2] - bw[0] > wd - 1.5:
                t = centred(pos, cell, size, "middle", max(0.5, (wd - 1.5) / (bw[2] - bw[0])))
            items.append(t)
            x += wd
    return items


def segments_table_view(sols: list[tuple[str, object]], lang: str = "ru", parts: int = 1,
                        sizing: bool = False) -> View:
    """Segments of both plans (mm) and their values (SI) for the chosen positions, in
    ``parts`` tables side by side."""
    w = WORDS[lang]
    header = [w["segment"]]
    for tag, _ in sols:
        pre = f"{tag}: " if len(sols) > 1 else ""  # name the position only when there are several
        header += [f"{pre}{w['mm']}", f"{pre}{w['value']}"]
    keys: list[tuple[str, str, str, str]] = []  # kind, start, end, label
    seen = set()
    for _, sol in sols:
        for kind, plan in (("v", sol.velocity), ("a", sol.acceleration)):
            for v in plan.vectors:
                key = (kind, v.start, v.end)
                if key not in seen:
                    seen.add(key)
                    keys.append((kind, v.start, v.end, v.label))
    rows = []
    for kind, a, b, label in keys:
        row = [f"{name_markup(a)}{name_markup(b)}: {notation(notation_in(label, lang))}"]
        for _, sol in sols:
            plan = sol.velocity if kind == "v" else sol.acceleration
            if a in plan.points or a == plan.pole:
                mm = plan.mm(a, b) if b in plan.points else float("nan")
                unit = w["ms"] if kind == "v" else w["ms2"]
                row += [num(mm, 4, lang), f"{num(mm * plan.mu, 4, lang)} {unit}"]
            else:
                row += ["—", "—"]
        rows.append(row)
    widths = [SEGMENT_W] + [22.0, 28.0] * len(sols)
    # the segments' names and their vectors' in 3.5 mm letters (their indices 2.45 mm);
    # the numbers, which have none, in 2.5 mm
    return table_view("segments", w["segments"], header, rows, widths, row_h=6.0, parts=parts,
                      sizing=sizing, body=[3.5] + [2.5] * (2 * len(sols)))


#: mm: the width of the segments table's first column, "n₁a₃: a^τ_A3B" in 3.5 mm letters
SEGMENT_W = 46.0


def omega_table_view(sols: list[tuple[str, object]], lang: str = "ru") -> View:
    w = WORDS[lang]
    header = [w["link"]]
    for tag, _ in sols:
        pre = f"{tag}: " if len(sols) > 1 else ""
        header += [f"{pre}ω, {w['rads']}", f"{pre}ε, {w['rads2']}"]
    first = sols[0][1]
    rows = []
    for lid in sorted(first.omega):
        row = [f"{lid}"]
        for _, sol in sols:
            om, ep = sol.omega.get(lid, 0.0), sol.epsilon.get(lid, 0.0)
            row += [_signed(om, lang), _signed(ep, lang)]
        rows.append(row)
    widths = [16.0] + [34.0, 34.0] * len(sols)
    return table_view("angular", w["angular"], header, rows, widths, row_h=6.0)


def _signed(x: float, lang: str) -> str:
    w = WORDS[lang]
    if abs(x) < 1e-12:
        return "0"
    return f"{num(abs(x), 4, lang)} {w['ccw'] if x > 0 else w['cw']}"


def note_view(lines: list[str], width: float = 180.0) -> View:
    """Lines of text at 3.5 mm, each broken at spaces into lines ``width`` mm long at
    most."""
    items: list[Item] = []
    y = 0.0
    for line in lines:
        for part in wrap_words(line, width - 2.0, lambda s: (text_width(s, 3.5)
                                                              + SLANT * 3.5), cut=False):
            y += 3.5 * LINE_PITCH
            items.append(Text((0, y), part, size=3.5))
    bx0, by0, bx1, by1 = bbox(items)
    items = shifted(items, -bx0 + 1, -by0 + 1)
    return View("note", items, bx1 - bx0 + 2, by1 - by0 + 2)
