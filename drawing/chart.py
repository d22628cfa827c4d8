"""The bench's chart: maximum relative error against run time per crank position, log-log,
one colour per method and one marker shape per scene (``plans bench --chart``).

Written as SVG text: a chart of a few hundred markers needs no plotting library.
"""

from __future__ import annotations

import math

_COLORS = {
    "vectorized": "#1f77b4",
    "reused": "#17becf",
    "recorded": "#7f7f7f",
    "plan": "#2ca02c",
    "pylinkage": "#9467bd",
}
_FD_COLORS = ("#ff7f0e", "#d62728", "#8c564b", "#e377c2", "#bcbd22")
#: one per scene: the bench's default scenes each get their own (a test holds it)
_SHAPES = ("circle", "square", "diamond", "triangle", "cross", "star", "ring", "down", "plus",
           "box")


def marker(shape: str, x: float, y: float, color: str, size: float = 5.0) -> str:
    """One marker of ``shape`` (:data:`_SHAPES`) centred at (x, y), as SVG."""
    s = size
    if shape == "circle":
        return f'<circle cx="{x:.1f}" cy="{y:.1f}" r="{s:.1f}" fill="{color}" fill-opacity="0.75"/>'
    if shape == "ring":
        return (
            f'<circle cx="{x:.1f}" cy="{y:.1f}" r="{s:.1f}" fill="none" stroke="{color}" '
            'stroke-width="2"/>'
        )
    if shape == "box":  # a square's outline
        return (
            f'<rect x="{x - s:.1f}" y="{y - s:.1f}" width="{2 * s:.1f}" height="{2 * s:.1f}" '
            f'fill="none" stroke="{color}" stroke-width="2"/>'
        )
    if shape == "plus":
        return (
            f'<path d="M{x - s * 1.2},{y}L{x + s * 1.2},{y}M{x},{y - s * 1.2}L{x},{y + s * 1.2}" '
            f'stroke="{color}" stroke-width="2.4"/>'
        )
    if shape == "square":
        return (
            f'<rect x="{x - s:.1f}" y="{y - s:.1f}" width="{2 * s:.1f}" height="{2 * s:.1f}" '
            f'fill="{color}" fill-opacity="0.75"/>'
        )
    if shape == "diamond":
        pts = f"{x},{y - s * 1.3} {x + s * 1.3},{y} {x},{y + s * 1.3} {x - s * 1.3},{y}"
    elif shape == "triangle":
        pts = f"{x},{y - s * 1.3} {x + s * 1.2},{y + s} {x - s * 1.2},{y + s}"
    elif shape == "down":
        pts = f"{x},{y + s * 1.3} {x + s * 1.2},{y - s} {x - s * 1.2},{y - s}"
    elif shape == "star":
        pts = " ".join(
            f"{x + (s * 1.4 if k % 2 == 0 else s * 0.6) * math.sin(k * math.pi / 5):.1f},"
            f"{y - (s * 1.4 if k % 2 == 0 else s * 0.6) * math.cos(k * math.pi / 5):.1f}"
            for k in range(10)
        )
    else:  # cross
        return (
            f'<path d="M{x - s},{y - s}L{x + s},{y + s}M{x - s},{y + s}L{x + s},{y - s}" '
            f'stroke="{color}" stroke-width="2.2"/>'
        )
    return f'<polygon points="{pts}" fill="{color}" fill-opacity="0.75"/>'


def svg_chart(rows: list, subtitle: str = "") -> str:
    """Error versus run time per position, log-log, one colour per method, one marker
    shape per scene; errors below 1e-17 (0 included) are drawn on the floor."""
    from xml.sax.saxutils import escape

    rows = [r for r in rows if r.seconds_per_position > 0]
    W, H = 860, 560
    L, R, T, B = 80, 250, 50, 60
    floor = 1e-17
    xs = [r.seconds_per_position for r in rows] or [1e-9, 1e-3]
    ys = [
        max(r.max_rel_error, floor)
        for r in rows
        if r.max_rel_error is not None and math.isfinite(r.max_rel_error)
    ] or [floor, 1]
    x0, x1 = math.floor(math.log10(min(xs))), math.ceil(math.log10(max(xs)))
    y0, y1 = math.floor(math.log10(min(ys))), math.ceil(math.log10(max(max(ys), 1e-12)))
    x1 = max(x1, x0 + 1)
    y1 = max(y1, y0 + 1)

    def px(x):
        return L + (math.log10(x) - x0) / (x1 - x0) * (W - L - R)

    def py(y):
        return T + (y1 - math.log10(max(y, floor))) / (y1 - y0) * (H - T - B)

    methods = list(dict.fromkeys(r.method for r in rows))
    colors = {}
    fd = 0
    for m in methods:
        if m in _COLORS:
            colors[m] = _COLORS[m]
        else:
            colors[m] = (
                _FD_COLORS[fd % len(_FD_COLORS)] if m.startswith("fd") else "#7f7f7f"
            )
            fd += m.startswith("fd")
    scenes = list(dict.fromkeys(r.scene for r in rows))
    shapes = {s: _SHAPES[i % len(_SHAPES)] for i, s in enumerate(scenes)}

    out = [
        f'<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{H}" '
        f'viewBox="0 0 {W} {H}" font-family="DejaVu Sans, Arial, sans-serif" font-size="12">',
        f'<rect width="{W}" height="{H}" fill="white"/>',
        f'<text x="{L}" y="22" font-size="15" font-weight="bold">Max relative error versus '
        "run time per crank position</text>",
        f'<text x="{L}" y="40" fill="#555">{escape(subtitle)}</text>',
    ]
    for e in range(x0, x1 + 1):
        x = px(10.0**e)
        out.append(
            f'<line x1="{x:.1f}" y1="{T}" x2="{x:.1f}" y2="{H - B}" stroke="#ddd"/>'
        )
        out.append(
            f'<text x="{x:.1f}" y="{H - B + 18}" text-anchor="middle">1e{e}</text>'
        )
    for e in range(y0, y1 + 1):
        y = py(10.0**e)
        out.append(
            f'<line x1="{L}" y1="{y:.1f}" x2="{W - R}" y2="{y:.1f}" stroke="#ddd"/>'
        )
        out.append(f'<text x="{L - 6}" y="{y + 4:.1f}" text-anchor="end">1e{e}</text>')
    if y0 <= -13 <= y1:
        y = py(1e-13)
        out.append(
            f'<line x1="{L}" y1="{y:.1f}" x2="{W - R}" y2="{y:.1f}" stroke="#888" '
            'stroke-dasharray="6 4"/>'
        )
        out.append(
            f'<text x="{W - R - 4}" y="{y - 4:.1f}" text-anchor="end" fill="#666">'
            "target 1e-13</text>"
        )
    out.append(
        f'<rect x="{L}" y="{T}" width="{W - L - R}" height="{H - T - B}" fill="none" stroke="#333"/>'
    )
    out.append(
        f'<text x="{(L + W - R) / 2:.1f}" y="{H - 18}" text-anchor="middle">'
        "wall time per position (s)</text>"
    )
    out.append(
        f'<text transform="translate(20 {(T + H - B) / 2:.1f}) rotate(-90)" '
        'text-anchor="middle">max relative error (normwise)</text>'
    )
    for r in rows:
        if r.max_rel_error is None or not math.isfinite(r.max_rel_error):
            continue
        out.append(
            marker(
                shapes[r.scene],
                px(r.seconds_per_position),
                py(r.max_rel_error),
                colors[r.method],
            )
        )
    lx, ly = W - R + 18, T + 6
    out.append(f'<text x="{lx}" y="{ly}" font-weight="bold">method</text>')
    for i, m in enumerate(methods):
        y = ly + 18 * (i + 1)
        out.append(
            f'<rect x="{lx}" y="{y - 9}" width="12" height="12" fill="{colors[m]}"/>'
        )
        out.append(f'<text x="{lx + 18}" y="{y + 1}">{escape(m)}</text>')
    ly += 18 * (len(methods) + 2)
    out.append(f'<text x="{lx}" y="{ly}" font-weight="bold">scene</text>')
    for i, s in enumerate(scenes):
        y = ly + 18 * (i + 1)
        out.append(marker(shapes[s], lx + 6, y - 3, "#444", 4.5))
        out.append(f'<text x="{lx + 18}" y="{y + 1}">{escape(s)}</text>')
    out.append(
        f'<text x="{L}" y="{H - 4}" fill="#777" font-size="10">errors ≤ 1e-17 '
        "(0 included) drawn at 1e-17; reference: mpmath, 30 digits</text>"
    )
    out.append("</svg>")
    return "\n".join(out) + "\n"


def bench_chart(rows: list, title: str, fmt: str) -> bytes:
    """The bench's chart as ``fmt`` bytes (``plans bench --chart``); rows are read
    duck-typed (scene, method, positions, seconds_per_position, max_rel_error).

    This SVG-only stand-in keeps ``plans bench --chart`` working until the matplotlib
    chart of the same signature takes its place."""
    if fmt != "svg":
        raise ValueError(f"the bench's chart is written as SVG only, not {fmt!r}")
    return svg_chart(rows, title).encode("utf-8")
