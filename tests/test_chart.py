"""Charts drawn with matplotlib (drawing.chart): the bench's and the cycle's."""

from __future__ import annotations

import math
import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path
from types import SimpleNamespace

import pytest

from drawing import chart

ROOT = Path(__file__).resolve().parent.parent
ANGLES = [float(a) for a in range(0, 361, 5)]
PANELS = [
    ("s_D, m", [("", [0.1 * math.sin(math.radians(a)) for a in ANGLES])]),
    ("ω, rad/s", [("ω2", [math.cos(math.radians(a)) for a in ANGLES]),
                  ("ω3", [None if a == 180 else math.sin(math.radians(2 * a)) for a in ANGLES])]),
]


def _rows():
    return [SimpleNamespace(scene=s, method=m, positions=12, seconds_per_position=t, max_rel_error=e)
            for s, m, t, e in (("press", "vectorized", 1e-6, 2e-16), ("press", "plan", 7e-5, 0.0),
                               ("fourbar", "fd h=1e-04", 3e-6, 8e-8),
                               ("fourbar", "recorded", 2e-6, None))]


@pytest.mark.parametrize("fmt", chart.FORMATS)
def test_charts_are_the_same_bytes_for_the_same_data(fmt):
    """No date, no random id: a chart written twice is one file (svg.hashsalt, metadata
    without dates), so a committed chart changes only where its data do."""
    one = chart.bench_chart(_rows(), "machine", fmt)
    assert one == chart.bench_chart(_rows(), "machine", fmt)
    cyc = chart.cycle_chart(ANGLES, PANELS, title="t", x_label="φ1, °", fmt=fmt)
    assert cyc == chart.cycle_chart(ANGLES, PANELS, title="t", x_label="φ1, °", fmt=fmt)
    magic = {"png": b"\x89PNG", "svg": b"<?xml", "pdf": b"%PDF"}[fmt]
    assert one.startswith(magic) and cyc.startswith(magic)
    if fmt == "svg":
        ET.fromstring(cyc)
        assert b"<dc:date>" not in one and b"<dc:date>" not in cyc


def test_a_cycle_chart_draws_each_panel_under_the_one_before_over_the_angle():
    fig = chart.cycle_figure(ANGLES, PANELS, title="Press", x_label="φ1, °")
    axes = fig.axes
    assert [ax.get_ylabel() for ax in axes] == ["s_D, m", "ω, rad/s"]
    assert axes[0].get_position().y0 > axes[1].get_position().y0  # one under another
    assert axes[-1].get_xlabel() == "φ1, °" and axes[0].get_xlim() == (0.0, 360.0)
    lines = [ln for ln in axes[1].get_lines() if len(ln.get_xdata()) == len(ANGLES)]
    assert [ln.get_label() for ln in lines] == ["ω2", "ω3"]
    assert math.isnan(lines[1].get_ydata()[ANGLES.index(180.0)])  # a gap, not a 0
    assert axes[0].get_legend() is None and axes[1].get_legend() is not None
    assert fig.get_suptitle() == "Press"


def test_a_chart_refuses_an_unknown_format_and_values_that_do_not_match_the_angles():
    with pytest.raises(ValueError, match="png, svg, pdf"):
        chart.bench_chart(_rows(), "", "jpg")
    with pytest.raises(ValueError, match="3 values for 73 angles"):
        chart.cycle_chart(ANGLES, [("s", [("", [0.0, 1.0, 2.0])])], fmt="png")


def test_the_bench_chart_puts_errors_below_the_floor_on_it_and_leaves_out_the_unmeasured():
    fig = chart.bench_figure(_rows(), "machine")
    points = [(ln.get_xdata()[0], ln.get_ydata()[0]) for ln in fig.axes[0].get_lines()
              if len(ln.get_xdata()) == 1]
    assert (7e-5, chart.FLOOR) in points and (1e-6, 2e-16) in points
    assert len(points) == 3  # the row without an error is not drawn
    (methods,) = [lg for lg in fig.legends if lg.get_title().get_text() == "method"]
    assert [t.get_text() for t in methods.get_texts()] == ["vectorized", "plan", "fd h=1e-04",
                                                           "recorded"]


def test_matplotlib_is_loaded_only_to_draw_a_chart():
    """Importing the charts, or drawing a sheet, loads no matplotlib; a chart does."""
    code = ("import sys\nimport drawing.chart, drawing.sheet1, drawing.overlay\n"
            "before = 'matplotlib' in sys.modules\n"
            "drawing.chart.cycle_chart([0, 1], [('y', [('', [0, 1])])], fmt='svg')\n"
            "print(before, 'matplotlib' in sys.modules)\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True,
                         cwd=ROOT)
    assert out.stdout.split() == ["False", "True"]
