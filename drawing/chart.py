"""Charts that are not drawing sheets, drawn with matplotlib: the bench's error against
run time (``plans bench --chart``) and a mechanism's quantities over the crank's turn
(``plans cycle --plot``).

matplotlib is imported inside the plotting functions, never when this module is imported:
a sheet, the overlay and the commands that draw no chart never load it. The figures are
drawn on their own canvas (no pyplot, no global backend: Agg for PNG) and written so that
the same data give the same bytes: no dates in SVG or PDF metadata, a fixed
``svg.hashsalt`` for the SVG's ids.

The rows of the bench are read duck-typed: anything with ``scene``, ``method``,
``positions``, ``seconds_per_position`` and ``max_rel_error`` (None where not measured).
"""

from __future__ import annotations

import io
import math
from collections.abc import Iterable, Sequence
from typing import Any, Protocol

__all__ = [
    "COLORS",
    "FLOOR",
    "FORMATS",
    "SHAPES",
    "BenchRow",
    "bench_chart",
    "bench_figure",
    "cycle_chart",
    "cycle_figure",
    "method_colors",
    "scene_shapes",
]

#: the file formats a chart is written in
FORMATS = ("png", "svg", "pdf")
#: errors below this (0 included) are drawn on it: a log axis has no 0
FLOOR = 1e-17
#: the relative error the engine is held to (drawn as a dashed line)
TARGET = 1e-13
#: one colour per method; finite differences take :data:`FD_COLORS` in turn
COLORS = {
    "vectorized": "#1f77b4",
    "reused": "#17becf",
    "recorded": "#7f7f7f",
    "plan": "#2ca02c",
    "pylinkage": "#9467bd",
}
FD_COLORS = ("#ff7f0e", "#d62728", "#8c564b", "#e377c2", "#bcbd22")
#: one marker per scene, (matplotlib marker, filled): the bench's default scenes each get
#: their own (a test holds it)
SHAPES = (("o", True), ("s", True), ("D", True), ("^", True), ("x", True), ("*", True),
          ("o", False), ("v", True), ("+", True), ("s", False))
_DPI = 100
_SALT = "vector-plans"


class BenchRow(Protocol):
    """What the bench's chart reads of a row."""

    scene: str
    method: str
    positions: int
    seconds_per_position: float
    max_rel_error: float | None


def method_colors(methods: Iterable[str]) -> dict[str, str]:
    """Each method's colour: its own, a finite-difference step's in turn, else grey.

    >>> method_colors(["plan", "fd h=1e-04", "fd h=1e-06", "other"])
    {'plan': '#2ca02c', 'fd h=1e-04': '#ff7f0e', 'fd h=1e-06': '#d62728', 'other': '#7f7f7f'}
    """
    out: dict[str, str] = {}
    fd = 0
    for m in dict.fromkeys(methods):
        if m in COLORS:
            out[m] = COLORS[m]
        elif m.startswith("fd"):
            out[m] = FD_COLORS[fd % len(FD_COLORS)]
            fd += 1
        else:
            out[m] = "#7f7f7f"
    return out


def scene_shapes(scenes: Iterable[str]) -> dict[str, tuple[str, bool]]:
    """Each scene's marker, in the order the scenes first come.

    >>> scene_shapes(["press", "fourbar", "press"])
    {'press': ('o', True), 'fourbar': ('s', True)}
    """
    return {s: SHAPES[i % len(SHAPES)] for i, s in enumerate(dict.fromkeys(scenes))}


def _marker(shape: tuple[str, bool], color: str) -> dict[str, Any]:
    marker, filled = shape
    if marker in "x+":  # lines only: no face to fill
        return {"marker": marker, "color": color, "markeredgewidth": 2.0}
    return {"marker": marker, "markerfacecolor": color if filled else "none",
            "markeredgecolor": color, "markeredgewidth": 0.8 if filled else 1.6,
            "alpha": 0.8 if filled else 1.0}


def bench_figure(rows: Sequence[BenchRow], title: str = ""):
    """The bench's chart as a matplotlib Figure: the maximum relative error against the
    wall time per crank position, log-log, one colour per method and one marker shape per
    scene; errors below :data:`FLOOR` (0 included) on the floor, rows without an error
    (None, inf, NaN) or without a time left out. ``title``: a line under the heading (the
    machine the bench ran on)."""
    from matplotlib.figure import Figure
    from matplotlib.lines import Line2D

    rows = [r for r in rows if r.seconds_per_position > 0]
    drawn = [r for r in rows if r.max_rel_error is not None and math.isfinite(r.max_rel_error)]
    colors = method_colors(r.method for r in rows)
    shapes = scene_shapes(r.scene for r in rows)
    fig = Figure(figsize=(8.6, 5.6), dpi=_DPI, layout="constrained")
    ax = fig.add_subplot()
    ax.set_xscale("log")
    ax.set_yscale("log")
    for r in drawn:
        ax.plot([r.seconds_per_position], [max(r.max_rel_error, FLOOR)], linestyle="none",
                markersize=7, **_marker(shapes[r.scene], colors[r.method]))
    ax.axhline(TARGET, color="#888", linestyle=(0, (6, 4)), linewidth=1.0)
    ax.annotate(f"target {TARGET:.0e}", (1.0, TARGET), xycoords=("axes fraction", "data"),
                xytext=(-4, 4), textcoords="offset points", ha="right", color="#666",
                fontsize=9)
    ax.set_ylim(bottom=FLOOR / 3)
    if not drawn:
        ax.set_xlim(1e-9, 1e-3)
        ax.set_ylim(FLOOR / 3, 1.0)
    ax.grid(True, which="major", color="#ddd", linewidth=0.8)
    ax.set_xlabel("wall time per position (s)")
    ax.set_ylabel("max relative error (normwise)")
    ax.set_title("Max relative error versus run time per crank position"
                 + (f"\n{title}" if title else ""), loc="left", fontsize=11)
    methods = [Line2D([], [], linestyle="none", marker="s", markersize=8, markerfacecolor=c,
                      markeredgecolor=c, label=m) for m, c in colors.items()]
    scenes = [Line2D([], [], linestyle="none", markersize=7, label=s, **_marker(shape, "#444"))
              for s, shape in shapes.items()]
    if methods:  # beside the axes, room made for them by the layout
        fig.legend(handles=methods, title="method", loc="outside right upper", frameon=False,
                   fontsize=9, alignment="left")
        fig.legend(handles=scenes, title="scene", loc="outside right lower", frameon=False,
                   fontsize=9, alignment="left")
    fig.supxlabel(f"errors ≤ {FLOOR:.0e} (0 included) drawn at {FLOOR:.0e}; "
                  "reference: mpmath, 30 digits", x=0.01, ha="left", fontsize=8, color="#777")
    return fig


def bench_chart(rows: Sequence[BenchRow], title: str, fmt: str) -> bytes:
    """:func:`bench_figure` as the bytes of a ``fmt`` file (:data:`FORMATS`)."""
    return _save(bench_figure(rows, title), fmt)


#: the colours of the series of one panel, in turn
SERIES = ("#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b", "#e377c2",
          "#17becf", "#bcbd22", "#7f7f7f")


def cycle_figure(angle_deg: Sequence[float],
                 panels: Sequence[tuple[str, Sequence[tuple[str, Sequence[float]]]]], *,
                 title: str = "", x_label: str = "φ1, °"):
    """Quantities over the crank's turn as a matplotlib Figure: one panel per entry of
    ``panels`` ((y label, [(series label, values), …])), one under another over the
    shared axis of ``angle_deg``; a panel with several series, or a named one, has a
    legend. Values that are None or not finite (a position that does not assemble) leave
    a gap in their line."""
    from matplotlib.figure import Figure
    from matplotlib.ticker import MultipleLocator

    if not panels:
        raise ValueError("a cycle chart needs at least one panel")
    x = [float(a) for a in angle_deg]
    fig = Figure(figsize=(8.6, 1.2 + 2.1 * len(panels)), dpi=_DPI, layout="constrained")
    axes = fig.subplots(len(panels), 1, sharex=True, squeeze=False)[:, 0]
    for ax, (y_label, series) in zip(axes, panels, strict=True):
        for k, (label, values) in enumerate(series):
            y = [math.nan if v is None or not math.isfinite(v) else float(v) for v in values]
            if len(y) != len(x):
                raise ValueError(f"{label or y_label}: {len(y)} values for {len(x)} angles")
            ax.plot(x, y, color=SERIES[k % len(SERIES)], linewidth=1.4, label=label or None)
        ax.axhline(0.0, color="#999", linewidth=0.6)
        ax.set_ylabel(y_label)
        ax.grid(True, color="#e4e4e4", linewidth=0.7)
        if len(series) > 1 or any(label for label, _ in series):
            ax.legend(loc="upper left", bbox_to_anchor=(1.01, 1.0), frameon=False, fontsize=9)
    if x:
        lo, hi = min(x), max(x)
        axes[-1].set_xlim(lo, hi if hi > lo else lo + 1.0)
        if hi - lo >= 90:
            axes[-1].xaxis.set_major_locator(MultipleLocator(30 if hi - lo <= 400 else 90))
    axes[-1].set_xlabel(x_label)
    if title:
        fig.suptitle(title, x=0.01, ha="left", fontsize=11)
    return fig


def cycle_chart(angle_deg: Sequence[float],
                panels: Sequence[tuple[str, Sequence[tuple[str, Sequence[float]]]]], *,
                title: str = "", x_label: str = "φ1, °", fmt: str = "png") -> bytes:
    """:func:`cycle_figure` as the bytes of a ``fmt`` file (:data:`FORMATS`)."""
    return _save(cycle_figure(angle_deg, panels, title=title, x_label=x_label), fmt)


def _save(fig, fmt: str) -> bytes:
    """The figure's file in ``fmt``, the same bytes for the same figure: no dates, the
    SVG's ids from a fixed salt, the PNG drawn by Agg."""
    from matplotlib import rc_context

    if fmt not in FORMATS:
        raise ValueError(f"a chart is written as {', '.join(FORMATS)}, not {fmt!r}")
    metadata = {"png": {"Software": None}, "svg": {"Date": None, "Creator": None},
                "pdf": {"CreationDate": None, "ModDate": None, "Creator": None,
                        "Producer": None}}[fmt]
    out = io.BytesIO()
    with rc_context({"svg.hashsalt": _SALT, "svg.fonttype": "path", "pdf.fonttype": 42}):
        fig.savefig(out, format=fmt, dpi=_DPI * 1.5 if fmt == "png" else _DPI,
                    metadata=metadata, facecolor="white")
    return out.getvalue()
