"""Line types (GOST 2.303) and the one drawing ``Style`` (widths, dashes, fonts).

Every length here is in sheet millimetres.  A view never picks a stroke width or
a dash pattern itself: it names a :class:`LineType`, and the renderer asks the
:class:`Style` what that means.  Vary a style with :func:`dataclasses.replace`:

>>> from dataclasses import replace
>>> style = Style()
>>> style.width(LineType.MAIN), style.width(LineType.THIN)
(0.7, 0.35)
>>> replace(style, s=1.0, thin=0.5).width(LineType.DASHED)
0.5
>>> LineType.CONSTRUCTION is LineType.THIN
True
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from enum import Enum
from pathlib import Path

__all__ = ["FONT_FILE", "FONT_SIZES", "LineType", "Style"]

#: the project's own copy of osifont (GOST type B), which the SVG embeds and the PNG
#: and PDF export draws with
FONT_FILE = Path(__file__).with_name("fonts") / "osifont.ttf"

#: Standard font sizes of GOST 2.304 (capital height h, mm) used on a sheet.
#: 1.8 is allowed for type B only and "not recommended"; 14 and up are for posters.
FONT_SIZES: tuple[float, ...] = (2.5, 3.5, 5.0, 7.0, 10.0)


class LineType(Enum):
    """GOST 2.303-68 lines used on a kinematics sheet.

    * ``MAIN``: solid thick main line *s*: frame, title block, links in the
      chosen position, vectors of the plans.
    * ``THIN``: solid thin line: other positions, dimension and leader lines,
      hatching, diagram axes and grids.  ``CONSTRUCTION`` is the same line (an
      alias), named for the construction lines of a plan.
    * ``DASHED``: hidden lines; the coupler-point trajectory.
    * ``DASH_DOT_THIN``: axes and centre lines, the slider guide axis x-x.
    * ``DASH_DOUBLE_DOT_THIN``: parts in extreme positions.
    """

    MAIN = "main"
    THIN = "thin"
    CONSTRUCTION = "thin"  # alias of THIN: same value, so `is` holds
    DASHED = "dashed"
    DASH_DOT_THIN = "dash-dot-thin"
    DASH_DOUBLE_DOT_THIN = "dash-double-dot-thin"


@dataclass(frozen=True, slots=True)
class Style:
    """Line widths, dash patterns and fonts of one sheet (millimetres).

    Dash patterns are SVG ``stroke-dasharray`` values, dash first.  Dots are
    short dashes of ``dot`` mm so that they survive butt line caps.  The gaps
    follow GOST 2.303: dashed 2…8 / 1…2, dash-dot 5…30 / 3…5 (the gap holds the
    dot), dash-double-dot 5…30 / 4…6.

    ``cap_height`` is the height of the capitals as a fraction of the em, the
    ratio that turns a GOST size *h* (capital height) into an SVG
    ``font-size``: osifont has 1515/2048 = 0.74; DejaVu Sans 0.73.
    """

    s: float = 0.7
    thin: float = 0.35
    dash: float = 4.0
    dash_gap: float = 1.5
    chain_dash: float = 15.0
    chain_gap: float = 1.5
    dot: float = 0.5
    font_family: tuple[str, ...] = (
        "osifont",
        "GOST type B",
        "ISOCPEUR",
        "DejaVu Sans",
        "sans-serif",
    )
    slant_deg: float = 75.0
    cap_height: float = 0.74
    font_sizes: tuple[float, ...] = FONT_SIZES
    color: str = "black"

    def width(self, line: LineType) -> float:
        """Stroke width of ``line``: *s* for the main line, ``thin`` otherwise."""
        return self.s if line is LineType.MAIN else self.thin

    def dasharray(self, line: LineType) -> tuple[float, ...] | None:
        """Dash pattern of ``line`` (dash, gap, dot, gap, …) or ``None`` if solid.

        >>> Style().dasharray(LineType.DASH_DOT_THIN)
        (15.0, 1.5, 0.5, 1.5)
        >>> Style().dasharray(LineType.MAIN) is None
        True
        """
        if line is LineType.DASHED:
            return (self.dash, self.dash_gap)
        if line is LineType.DASH_DOT_THIN:
            return (self.chain_dash, self.chain_gap, self.dot, self.chain_gap)
        if line is LineType.DASH_DOUBLE_DOT_THIN:
            g = self.chain_gap
            return (self.chain_dash, g, self.dot, g * 0.8, self.dot, g)
        return None

    @property
    def font_css(self) -> str:
        """The family list as one CSS value, names with spaces quoted.

        >>> Style().font_css
        "osifont, 'GOST type B', ISOCPEUR, 'DejaVu Sans', sans-serif"
        """
        return ", ".join(f"'{f}'" if " " in f else f for f in self.font_family)

    @property
    def skew_deg(self) -> float:
        """The SVG ``skewX`` angle that slants upright glyphs to ``slant_deg``.

        75° from the baseline is 15° from the vertical; SVG's y axis points
        down, so the tops lean right with a negative angle.

        >>> Style().skew_deg
        -15.0
        """
        return -(90.0 - self.slant_deg)

    @property
    def slant_tan(self) -> float:
        """Horizontal lean of a glyph per unit of height (tan 15° ≈ 0.268)."""
        return math.tan(math.radians(90.0 - self.slant_deg))
