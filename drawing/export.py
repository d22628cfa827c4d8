"""A drawing's SVG text rendered to PNG or PDF bytes through cairosvg (optional).

Bytes only: the command line writes them with its one atomic writer, so a reader
never sees half a sheet and a failed export leaves the old file in place.

cairosvg is an optional dependency (the ``export`` extra: ``pip install '.[export]'`` in
the source folder, as the README's setup installs the tool), imported only when a PNG or
PDF is asked for.  It does not read the embedded ``@font-face``; it renders with the
project's own osifont all the same (see :func:`_render`), so a PNG looks as the SVG does
on any machine.

A PNG is drawn whole in memory, four bytes a pixel and as much again to encode it: one
of more than :data:`MAX_PIXELS` is refused in one line (A0 at 600 dpi, 558 million
pixels, had taken 2.25 GB), naming the largest dpi that fits (:func:`check_raster`).
A render is not cut short by Ctrl-C, SIGTERM or SIGHUP: the signal is held until
cairosvg returns (an interrupt inside its callbacks had printed a traceback), then
acted on.
"""

from __future__ import annotations

import atexit
import math
import os
import re
import shutil
import signal
import tempfile
import threading
from contextlib import contextmanager
from pathlib import Path
from types import ModuleType

from drawing.styles import FONT_FILE
from plans.errors import InputError, PlansError

__all__ = [
    "MAX_PIXELS",
    "PAPER",
    "ExportUnavailableError",
    "check_raster",
    "largest_dpi",
    "pdf_bytes",
    "png_bytes",
    "raster_size",
    "require",
    "signals_held",
]

_HINT = ("PNG and PDF export needs cairosvg, the export extra: in the source folder, "
         "pip install '.[export]' (README, Setup)")

#: the most pixels a PNG may have: 100 million, 400 MB of raster (A0 up to 254 dpi, A1
#: up to 359 dpi); cairosvg peaks at about twice that as it encodes
MAX_PIXELS = 100_000_000
#: millimetres per inch
MM = 25.4


class ExportUnavailableError(PlansError, ImportError):
    """cairosvg (or the cairo library under it) is missing: a setup problem the user can
    fix (exit 2 with the pip command), not an internal error."""


def require() -> None:
    """Fail before anything is written when PNG/PDF export cannot work here."""
    _cairosvg()


def _cairosvg() -> ModuleType:
    try:
        import cairosvg
    except (ImportError, OSError) as exc:  # OSError: the cairo C library is absent
        raise ExportUnavailableError(f"{_HINT} ({exc})") from exc
    return cairosvg


_FONTS_CONF = """<?xml version="1.0"?>
<!DOCTYPE fontconfig SYSTEM "fonts.dtd">
<fontconfig>
  <include ignore_missing="yes">/etc/fonts/fonts.conf</include>
  <include ignore_missing="yes">/usr/local/etc/fonts/fonts.conf</include>
  <include ignore_missing="yes">/opt/homebrew/etc/fonts/fonts.conf</include>
  <dir>{fonts}</dir>
  <selectfont>
    <acceptfont><glob>{fonts}/*</glob></acceptfont>
    <rejectfont><glob>*osifont*</glob></rejectfont>
  </selectfont>
</fontconfig>
"""

_fonts_ready = False


def _render(call, svg: str, **options) -> bytes:
    """``call`` (cairosvg's svg2png or svg2pdf) on ``svg``, drawn with the project's
    osifont as the SVG embeds it.

    cairosvg ignores the SVG's embedded @font-face and asks fontconfig for "osifont": the
    Debian package's copy prints Ё, ё, Э, э as black boxes («четыр█хзвенник»), and a
    machine without it falls back to another face. For the process's first render (when
    fontconfig reads its setup) FONTCONFIG_FILE points at a private file that adds
    ``drawing/fonts`` and accepts only its osifont, the system's fonts staying for
    everything else; the variable is put back at once, so child processes never see it.
    The file stays while the process runs (fontconfig may check it again when it looks
    for changes) and goes when it exits. A process that sets FONTCONFIG_FILE itself keeps
    its own.
    """
    global _fonts_ready
    if _fonts_ready or "FONTCONFIG_FILE" in os.environ:
        with signals_held():
            return call(bytestring=svg.encode("utf-8"), **options)
    folder = tempfile.mkdtemp(prefix="vector-plans-fonts-")  # private: mode 0700
    atexit.register(shutil.rmtree, folder, ignore_errors=True)
    conf = Path(folder) / "fonts.conf"
    conf.write_text(_FONTS_CONF.format(fonts=FONT_FILE.parent.resolve()), encoding="utf-8")
    os.environ["FONTCONFIG_FILE"] = str(conf)
    try:
        with signals_held():
            return call(bytestring=svg.encode("utf-8"), **options)
    finally:
        del os.environ["FONTCONFIG_FILE"]
        _fonts_ready = True


#: the signals held while cairosvg renders
_HELD = tuple(getattr(signal, n) for n in ("SIGINT", "SIGTERM", "SIGHUP") if hasattr(signal, n))


@contextmanager
def signals_held():
    """Ctrl-C, SIGTERM and SIGHUP wait until the block is done, then act as they would
    have: a KeyboardInterrupt raised inside cairo's C callbacks is printed as a
    traceback and the render goes on or fails in its own way (4 of 8 interrupted runs
    ended in a traceback and exit 1). Outside the main thread, where Python sets no
    handlers, the block runs as it is."""
    if threading.current_thread() is not threading.main_thread():
        yield
        return
    got: list[int] = []
    before = {s: signal.signal(s, lambda signum, frame: got.append(signum)) for s in _HELD}
    try:
        yield
    finally:
        for s, handler in before.items():
            signal.signal(s, handler)
        if got:
            signal.raise_signal(got[0])  # now, to the handler it was meant for


def raster_size(width_mm: float, height_mm: float, dpi: float) -> tuple[int, int]:
    """The pixels of a PNG of a drawing ``width_mm`` × ``height_mm`` at ``dpi``.

    >>> raster_size(1189, 841, 600)
    (28087, 19867)
    """
    return math.ceil(width_mm * dpi / MM), math.ceil(height_mm * dpi / MM)


def largest_dpi(width_mm: float, height_mm: float) -> int:
    """The largest whole dpi at which a drawing of that size stays within MAX_PIXELS.

    >>> largest_dpi(1189, 841), largest_dpi(841, 594), largest_dpi(297, 210)
    (254, 359, 1017)
    """
    dpi = int(MM * math.sqrt(MAX_PIXELS / (width_mm * height_mm)))
    while dpi > 1 and math.prod(raster_size(width_mm, height_mm, dpi)) > MAX_PIXELS:
        dpi -= 1
    return dpi


def check_raster(width_mm: float, height_mm: float, dpi: float, what: str = "the drawing",
                 where: str = "--dpi") -> None:
    """Refuse, in one line and before anything is drawn, a PNG of more than MAX_PIXELS."""
    w, h = raster_size(width_mm, height_mm, dpi)
    if w * h > MAX_PIXELS:
        raise InputError(where, f"{dpi:g} dpi makes {what} a {w} × {h} px PNG ({w * h / 1e6:.0f} "
                                f"million pixels), over the {MAX_PIXELS // 1_000_000} million a PNG "
                                f"may have: give --dpi {largest_dpi(width_mm, height_mm)} or less")


_SIZE = re.compile(r'<svg\b[^>]*?\swidth="([\d.]+)(mm|px)?"[^>]*?\sheight="([\d.]+)(mm|px)?"')


def _pixels(svg: str, dpi: float, scale: float) -> tuple[int, int] | None:
    """The PNG's size in pixels as cairosvg renders ``svg`` (mm at ``dpi``, px as they
    are, both times ``scale``), read off the root element; None where it is not given."""
    m = _SIZE.search(svg[:4000])
    if m is None:
        return None
    per = {"mm": dpi / MM, "px": 1.0, None: 1.0}
    return (math.ceil(float(m.group(1)) * per[m.group(2)] * scale),
            math.ceil(float(m.group(3)) * per[m.group(4)] * scale))


#: a PNG's background: a sheet is paper, and black lines on a transparent PNG are black
#: on black in a viewer with a dark background
PAPER = "white"


def png_bytes(svg: str, dpi: float = 150, scale: float = 1.0) -> bytes:
    """The SVG rendered to a PNG at ``dpi`` (an A1 sheet at 150 dpi is 4967 × 3508 px),
    on white paper, not transparent; ``scale`` enlarges a drawing sized in px, which
    ``dpi`` leaves as it is. One of more than :data:`MAX_PIXELS` is refused."""
    size = _pixels(svg, dpi, scale)
    if size is not None and size[0] * size[1] > MAX_PIXELS:
        w, h = size
        raise InputError("--dpi", f"a {w} × {h} px PNG ({w * h / 1e6:.0f} million pixels) is over "
                                  f"the {MAX_PIXELS // 1_000_000} million a PNG may have: give a "
                                  "lower --dpi")
    return _render(_cairosvg().svg2png, svg, dpi=dpi, scale=scale, background_color=PAPER)


def pdf_bytes(svg: str) -> bytes:
    """The SVG rendered to a one-page PDF of the sheet's real size."""
    return _render(_cairosvg().svg2pdf, svg)
