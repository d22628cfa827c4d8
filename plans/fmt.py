"""Numbers as people write them: significant digits, units, a decimal comma in Russian.

What differs by language is in tables, one entry per language (a language without one
writes as English does): the decimal mark, the separator of items that hold numbers, the
notation of the method, the senses of a turn.
"""

from __future__ import annotations

import math
import re
import unicodedata

#: the decimal mark, by language
DECIMAL_MARK = {"en": ".", "ru": ","}
#: what separates items that hold numbers: in Russian, whose decimal mark is a comma, a
#: comma between them would read as one more decimal mark
ITEM_SEPARATOR = {"en": ", ", "ru": "; "}
#: units as each language writes them (SI symbols; Russian in Cyrillic, as GOST 8.417 has it)
UNITS = {
    "en": {"m": "m", "mm": "mm", "s": "s", "N": "N", "N·m": "N·m", "N·mm": "N·mm", "W": "W", "J": "J",
           "m/s": "m/s", "m/s²": "m/s²", "rad": "rad", "rad/s": "rad/s", "rad/s²": "rad/s²", "rpm": "rpm",
           "kg": "kg", "kg·m²": "kg·m²"},
    "ru": {"m": "м", "mm": "мм", "s": "с", "N": "Н", "N·m": "Н·м", "N·mm": "Н·мм", "W": "Вт", "J": "Дж",
           "m/s": "м/с", "m/s²": "м/с²", "rad": "рад", "rad/s": "рад/с", "rad/s²": "рад/с²", "rpm": "об/мин",
           "kg": "кг", "kg·m²": "кг·м²"},
}


def unit(symbol: str, lang: str = "en") -> str:
    """The SI unit ``symbol`` (as English writes it) in ``lang``.

    >>> unit("N·m", "ru"), unit("m/s²", "en")
    ('Н·м', 'm/s²')
    """
    return UNITS.get(lang, UNITS["en"])[symbol]


#: the method's notation as each language's textbooks write it: the engine's tangential
#: a^t_CB is a^τ_CB in Russian
NOTATION = {"en": {}, "ru": {"a^t_": "a^τ_"}}


def decimal(text: str, lang: str) -> str:
    """``text``, a number written with a decimal point, with ``lang``'s decimal mark.

    >>> decimal("-0.25", "ru"), decimal("2.5", "en")
    ('-0,25', '2.5')
    """
    mark = DECIMAL_MARK.get(lang, ".")
    return text if mark == "." else text.replace(".", mark)


def num(x: float, digits: int = 4, lang: str = "en") -> str:
    """A number with ``digits`` significant digits, no exponent for everyday magnitudes.

    >>> num(2.771580654, 3), num(0.05), num(11.07238, 4, "ru"), num(-1e-7), num(2.5e-9, 4, "ru")
    ('2.77', '0.05', '11,07', '-1e-07', '2,5e-09')
    """
    if x == 0 or not math.isfinite(x):
        s = "0" if x == 0 else "—"
    else:
        mag = math.floor(math.log10(abs(x)))
        if -4 <= mag < 7:
            decimals = max(digits - 1 - mag, 0)
            s = f"{x:.{decimals}f}"
            if "." in s:
                s = s.rstrip("0").rstrip(".")
        else:  # trailing zeros dropped as above: 1e-07, not 1.000e-07
            mant, exp = f"{x:.{digits - 1}e}".split("e")
            s = (mant.rstrip("0").rstrip(".") if "." in mant else mant) + "e" + exp
    if s in ("-0",):
        s = "0"
    return decimal(s, lang)


#: the senses of a turn in words, by sign (+1 counter-clockwise)
SENSE = {
    "en": {1: "counter-clockwise", -1: "clockwise"},
    "ru": {1: "против часовой стрелки", -1: "по часовой стрелке"},
}


def listing(parts, lang: str = "en") -> str:
    """Items that hold numbers, in one line: in Russian, whose decimal mark is a comma,
    separated by "; " (a comma between them would read as one more decimal mark), else
    by ", ".

    >>> listing(["n1a3 +22.1", "πa3 +18.6"]), listing(["n1a3 +22,1", "πa3 +18,6"], "ru")
    ('n1a3 +22.1, πa3 +18.6', 'n1a3 +22,1; πa3 +18,6')
    """
    return ITEM_SEPARATOR.get(lang, ", ").join(parts)


def columns(rows, head, right=()) -> list[str]:
    """``head`` and ``rows`` (lists of cells) as lines of aligned columns, each indented
    by two spaces and two apart, cells left-aligned except the columns ``right``.

    >>> columns([["ab", "1.5"], ["c", "12"]], ("x", "y"), right=(1,))
    ['  x     y', '  ab  1.5', '  c    12']
    """
    lines = [list(head), *rows]
    widths = [max(width(r[i]) for r in lines) for i in range(len(head))]

    def pad(i, c):
        fill = " " * (widths[i] - width(c))
        return fill + c if i in right else c + fill

    return ["  " + "  ".join(pad(i, c) for i, c in enumerate(r)).rstrip() for r in lines]


def width(text: str) -> int:
    """The columns ``text`` takes in a terminal: two for a wide (CJK) character, none for
    a combining mark, one for the others, so that a student's title in Chinese does not
    push the rest of its row out of line.

    >>> width("ab"), width("曲柄"), width("и\u0306")
    (2, 4, 1)
    """
    return sum(0 if unicodedata.combining(ch) else
               2 if unicodedata.east_asian_width(ch) in "WF" else 1 for ch in text)


def cut(text: str, limit: int) -> str:
    """``text`` in at most ``limit`` columns of a terminal (:func:`width`), cut with an
    ellipsis where it is wider: forty Chinese characters are eighty columns, not forty.

    >>> cut("abcdef", 4), cut("张伟机械原理", 7), cut("张伟", 4)
    ('abc…', '张伟机…', '张伟')
    """
    if width(text) <= limit:
        return text
    while text and width(text) + 1 > limit:
        text = text[:-1]
    return text + "…"


def cut_start(text: str, limit: int) -> str:
    """``text`` in at most ``limit`` columns, cut at its start where it is wider: a file's
    path keeps its name, the part a reader looks for.

    >>> cut_start("/a/long/path/to/ivanov.toml", 13)
    '…/ivanov.toml'
    """
    if width(text) <= limit:
        return text
    while text and width(text) + 1 > limit:
        text = text[1:]
    return "…" + text


def notation_in(text: str, lang: str) -> str:
    """The method's notation as ``lang``'s textbooks write it: the engine's ``a^t_CB``
    (tangential, as English and Chinese texts write it) is ``a^τ_CB`` in Russian.

    >>> notation_in("a_C = a_B + a^n_CB + a^t_CB", "ru")
    'a_C = a_B + a^n_CB + a^τ_CB'
    """
    for engine, written in NOTATION.get(lang, {}).items():
        text = text.replace(engine, written)
    return text


def ru_plural(n: int, one: str, few: str, many: str) -> str:
    """The Russian noun form that agrees with the whole number ``n``: 1, 21 … take
    ``one``, 2–4, 22–24 … ``few``, the rest (5–20, 11–14, 25 …) ``many``.

    >>> [ru_plural(n, "величина", "величины", "величин") for n in (1, 2, 5, 11, 12, 21, 22)]
    ['величина', 'величины', 'величин', 'величин', 'величин', 'величина', 'величины']
    """
    if n % 10 == 1 and n % 100 != 11:
        return one
    if n % 10 in (2, 3, 4) and n % 100 not in (12, 13, 14):
        return few
    return many


def from_x(phi: float) -> float:
    """A crank angle (rad) in degrees counter-clockwise from +x, in [0, 360)."""
    return math.degrees(phi) % 360.0


def json_angle(deg: float) -> float:
    """A crank angle of one position, in degrees in [0, 360), for JSON: to 1e-9°, far
    finer than any angle typed, so that the noise of degrees → radians → degrees does not
    show (30° from +y, clockwise, is 60.0 from +x, not 59.99999999999999); a rounding's
    worth from a full turn is 0.

    >>> json_angle(59.99999999999999), json_angle(-1e-13), json_angle(30.000000000000004)
    (60.0, 0.0, 30.0)
    """
    x = round(deg % 360.0, 9)
    return 0.0 if x >= 360.0 else x + 0.0  # + 0.0: no −0.0


def angle(deg: float, digits: int = 4, lang: str = "en", lo: float = 0.0) -> str:
    """A crank angle in degrees, in [0, 360) as written: one that rounds to 360 is 0.
    ``lo``: the turn [lo, lo + 360) to write it in instead, with a true minus sign, as
    a crank's range through 0° is written (:func:`plans.cycle.shown_from`).

    >>> angle(359.99), angle(-30.0), angle(40.0, 4, "ru"), angle(12.345, 3), angle(1.1e-13, 6)
    ('0', '330', '40', '12.3', '0')
    >>> angle(260.3, 4, "en", -180.0), angle(-0.25, 4, "ru", -180.0), angle(359.9999999999, 4, "en", -180.0)
    ('−99.7', '−0,25', '0')
    """
    if lo:
        x = in_turn(deg, lo)
        if abs(x) < 1e-9:  # a rounding's worth from 0
            return "0"
        s = num(x, digits, lang)
        return "0" if s == "-0" else s.replace("-", "−")
    x = deg % 360.0
    if x < 1e-9 or 360.0 - x < 1e-9:  # a rounding's worth from a full turn: 0
        return "0"
    s = num(x, digits, lang)
    return "0" if s == "360" else s



def in_turn(deg: float, lo: float) -> float:
    """``deg`` moved by whole turns into [lo, lo + 360), for ``lo`` below 0: an angle on
    the turn's edge (to 1e-6°), as far from one end of a range centred in it as from the
    other, keeps its usual reading, 270 rather than −90.

    >>> in_turn(260.3, -180.0), in_turn(270.0, -90.0 - 1e-12), in_turn(-99.8, -150.0)
    (-99.69999999999999, 270.0, -99.8)
    """
    x = lo + (deg - lo) % 360.0
    return x + 360.0 if x < 0.0 and x - lo < 1e-6 else x


def signed(x: float, lang: str = "en", decimals: int | None = None) -> str:
    """A deviation with its sign, a true minus sign: ``decimals`` places, else ``num``'s
    three figures; no sign on a zero, "—" for no number.

    >>> signed(0.4321, "en", 2), signed(-4.23, "ru", 1), signed(0.0, "en", 1)
    ('+0.43', '−4,2', '0.0')
    """
    if not math.isfinite(x):
        return "—"
    s = f"{abs(x):.{decimals}f}" if decimals is not None else num(abs(x), 3)
    if float(s) != 0:
        s = ("+" if x > 0 else "−") + s
    return decimal(s, lang)


#: Markdown's and HTML's own characters, escaped in user text the note writes (a name
#: "<script>" or "**x**" had become markup; a name with a line break, forged lines)
_MD_SPECIAL = re.compile(r"([\\`*_\[\]<>|&~#])")


def plain(text: str) -> str:
    """User text without its control and format characters: a line break or tab is a
    space, and bidi controls (U+202E …), zero-width and other format characters are
    dropped, so that a name can neither forge a line nor turn the text around it.

    >>> plain("Press\\nfor\\u202ebriquettes\\u200b")
    'Press forbriquettes'
    """
    out = []
    for ch in text:
        cat = unicodedata.category(ch)
        if cat == "Cc":
            out.append(" ")
        elif cat != "Cf":
            out.append(ch)
    return "".join(out)


def md_text(text: str) -> str:
    """User text (a mechanism's name, a guide's label) for the Markdown note's prose: its
    control characters gone (:func:`plain`) and Markdown's and HTML's characters escaped.

    >>> md_text("<b>Press</b> *1*")
    '\\\\<b\\\\>Press\\\\</b\\\\> \\\\*1\\\\*'
    """
    return _MD_SPECIAL.sub(r"\\\1", plain(text))


def md_code(text: str) -> str:
    """Text for inside one of the note's code spans (a step): its control characters
    gone and a backtick (which would close the span) written ˋ; nothing else is markup
    there.

    >>> md_code("F`1")
    'Fˋ1'
    """
    return plain(text).replace("`", "ˋ")
