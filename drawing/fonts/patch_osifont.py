"""Draw the four Cyrillic letters that osifont 0.1.20220224 leaves as black boxes.

Debian's ``fonts-osifont`` (0.1.20220224-1) maps Ё, ё, Э and э to placeholder
rectangles, so "Н.Э. Баумана" would print a black block.  This script, run once
by hand, writes ``osifont.ttf`` beside it from the Debian file with those glyphs
built from the font's own strokes:

* Ё, ё: Е, е with the combining diaeresis (U+0308), placed as the font's Ë, ä;
* Э, э: С, с mirrored, with the hyphen's stroke as the middle bar;

and maps the minus sign (U+2212) to the hyphen's glyph, the primes (U+2032, U+2033) to
the straight quotes'.  Nothing else changes.  Needs fontTools (``pip install fonttools``), which is not
a dependency of the project: the patched font is committed.

    python drawing/fonts/patch_osifont.py /usr/share/fonts/truetype/osifont/osifont.ttf
"""

from __future__ import annotations

import sys
from pathlib import Path


def main(source: str) -> None:
    from fontTools.pens.recordingPen import RecordingPen
    from fontTools.pens.reverseContourPen import ReverseContourPen
    from fontTools.pens.transformPen import TransformPen
    from fontTools.pens.ttGlyphPen import TTGlyphPen
    from fontTools.ttLib import TTFont
    from fontTools.ttLib.tables._g_l_y_f import GlyphComponent

    font = TTFont(source)
    glyf, hmtx, gs = font["glyf"], font["hmtx"], font.getGlyphSet()

    def dieresis(target: str, base: str, dx: int, dy: int) -> None:
        g = glyf[target]
        g.numberOfContours = -1
        g.components = []
        for name, x, y in (("uni0308", dx, dy), (base, 0, 0)):
            c = GlyphComponent()
            c.glyphName, c.x, c.y, c.flags = name, x, y, 0
            g.components.append(c)
        hmtx[target] = hmtx[base]

    def mirrored_with_bar(target: str, base: str, bar: tuple[int, int, int]) -> None:
        """``base`` mirrored in its own box, plus the hyphen from x0 to x1 at y."""
        x0, x1, y = bar
        bounds = glyf[base]
        bounds.recalcBounds(glyf)
        pen = TTGlyphPen(gs)
        mirror = TransformPen(
            ReverseContourPen(pen), (-1, 0, 0, 1, bounds.xMin + bounds.xMax, 0)
        )
        gs[base].draw(mirror)  # reversed, so both contours wind the same way
        hyphen = RecordingPen()
        gs["hyphen"].draw(hyphen)  # round-capped bar, x 100…852, y 527…671

        def move(pt: tuple[int, int]) -> tuple[int, int]:
            px, py = pt
            return (px + (x0 - 100 if px < 476 else x1 - 852), py + y - 599)

        for op, args in hyphen.value:
            getattr(pen, op)(*(move(a) for a in args))
        glyf[target] = pen.glyph()
        hmtx[target] = hmtx[base]

    dieresis("uni0401", "uni0415", 134, 195)  # Ё = Е + ¨ (as Ë)
    dieresis("uni0451", "uni0435", 53, -275)  # ё = е + ¨ (as ä)
    mirrored_with_bar("uni042D", "uni0421", (330, 790, 757))  # Э = mirrored С + bar
    mirrored_with_bar("uni044D", "uni0441", (250, 600, 531))  # э = mirrored с + bar
    # characters the font has no glyph for, drawn with the glyph GOST type B draws them
    # with: the minus sign as the hyphen (a deviation "−4,2", a range "от −128,8°"), the
    # primes of x3′-x3′ as the straight quotes
    for table in font["cmap"].tables:
        if table.isUnicode():
            table.cmap.update({0x2212: "hyphen", 0x2032: "quotesingle", 0x2033: "quotedbl"})
    for rec in font["name"].names:
        if rec.nameID == 5:
            rec.string = (
                rec.toUnicode().strip()
                + "; vector-plans: U+0401 U+0451 U+042D U+044D drawn, U+2212 U+2032 U+2033 mapped"
            )
    font.save(Path(__file__).with_name("osifont.ttf"))


if __name__ == "__main__":
    main(
        sys.argv[1]
        if len(sys.argv) > 1
        else "/usr/share/fonts/truetype/osifont/osifont.ttf"
    )
