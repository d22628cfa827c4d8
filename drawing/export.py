"""A drawing's SVG text rendered to PNG or PDF bytes through cairosvg (optional).

Bytes only: the command line writes them with its one atomic writer, so a reader
never sees half a sheet and a failed export leaves the old file in place.

cairosvg is an optional dependency (``pip install 'vector-plans[export]'``),
imported only when a PNG or PDF is asked for.  It does not read the embedded
``@font-face``; it renders with the project's own osifont all the same (see
:func:`_render`), so a PNG looks as the SVG does on any machine.
"""

from __future__ import annotations

import atexit
import os
import shutil
import tempfile
from pathlib import Path
from types import ModuleType

from drawing.styles import FONT_FILE
from plans.errors import PlansError

__all__ = [
    "PAPER",
    "ExportUnavailableError",
    "pdf_bytes",
    "png_bytes",
    "require",
]

_HINT = "PNG and PDF export needs cairosvg: pip install 'vector-plans[export]'"


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
        return call(bytestring=svg.encode("utf-8"), **options)
    folder = tempfile.mkdtemp(prefix="vector-plans-fonts-")  # private: mode 0700
    atexit.register(shutil.rmtree, folder, ignore_errors=True)
    conf = Path(folder) / "fonts.conf"
    conf.write_text(_FONTS_CONF.format(fonts=FONT_FILE.parent.resolve()), encoding="utf-8")
    os.environ["FONTCONFIG_FILE"] = str(conf)
    try:
        return call(bytestring=svg.encode("utf-8"), **options)
    finally:
        del os.environ["FONTCONFIG_FILE"]
        _fonts_ready = True


#: a PNG's background: a sheet is paper, and black lines on a transparent PNG are black
#: on black in a viewer with a dark background
PAPER = "white"


def png_bytes(svg: str, dpi: float = 150, scale: float = 1.0) -> bytes:
    """The SVG rendered to a PNG at ``dpi`` (an A1 sheet at 150 dpi is 4967 × 3508 px),
    on white paper, not transparent; ``scale`` enlarges a drawing sized in px, which
    ``dpi`` leaves as it is."""
    return _render(_cairosvg().svg2png, svg, dpi=dpi, scale=scale, background_color=PAPER)


def pdf_bytes(svg: str) -> bytes:
    """The SVG rendered to a one-page PDF of the sheet's real size."""
    return _render(_cairosvg().svg2pdf, svg)
