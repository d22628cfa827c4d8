"""Files written by people, read for people: TOML with every problem located.

Every problem in a file is collected (not raised at the first one) as a key path and a
message in :class:`Problems`; when the file's text is known each path is located to its
line. The messages say what is wrong and what would be right, on one line each, and never
echo more than a few dozen characters of what the file holds, so that a hostile file
cannot flood the terminal. The mechanism file, the table of variants and the measurement
file of a hand-drawn plan are all read with these.
"""

from __future__ import annotations

import ast
import difflib
import json
import math
import re
import tomllib
from pathlib import Path
from typing import Any

from plans.errors import InputError
from plans.model.locate import BARE, first_duplicate, key_text, line_of, locate, one_line, quote

MAX_ABS = 1e6  # metres, rad/s: anything larger is a typo, not a machine
MAX_FILE = 1_000_000  # bytes: a mechanism file is a few KB
MAX_TEXT = 200  # names and hints, characters
MAX_PROBLEMS = 50  # reported; the rest are counted


def read_toml(path: str | Path, typical: str = "") -> tuple[dict, str]:
    """The parsed TOML and the text of a file, or an :class:`InputError` saying why not.

    Reads at most :data:`MAX_FILE` bytes (a 10 GB file or ``/dev/zero`` is refused, not
    read); refuses binary data, text that is not UTF-8, and TOML syntax errors, each with
    its line.
    """
    source = str(path)
    try:
        with open(path, "rb") as fh:
            raw = fh.read(MAX_FILE + 1)
    except IsADirectoryError:
        raise InputError(source, "is a folder, not a file") from None
    except OSError as exc:
        raise InputError(source, f"cannot read the file: {exc.strerror or exc}") from None
    if len(raw) > MAX_FILE:
        raise InputError(
            source,
            f"the file is larger than {MAX_FILE // 1_000_000} MB" + (f"; {typical}" if typical else "")
        )
    nul = raw.find(b"\x00")
    if nul >= 0:
        line = raw.count(b"\n", 0, nul) + 1
        raise InputError(source, f"line {line}: binary data (a NUL byte): not a TOML text file")
    try:
        text = raw.decode("utf-8")
    except UnicodeDecodeError as exc:
        line = raw.count(b"\n", 0, exc.start) + 1
        raise InputError(
            source,
            f"line {line}: not UTF-8 text (byte 0x{raw[exc.start]:02x}); save the file as UTF-8",
        ) from None
    return parse_toml(text, source), text


def parse_toml(text: str, source: str) -> dict:
    """``tomllib.loads`` with its errors turned into one located line each."""
    text = text.removeprefix("\ufeff")
    try:
        return tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise InputError(source, _toml_problem(str(exc), text)) from None
    except RecursionError:
        deep = re.search(r"[\[{](?:\s*[\[{]){50}", text)
        at = f"line {text.count(chr(10), 0, deep.start()) + 1}: " if deep else ""
        raise InputError(source, f"{at}TOML nested too deeply: these files need three levels at "
                                 "most") from None
    except (ValueError, OverflowError, MemoryError) as exc:  # e.g. an integer of 5000 digits
        long = re.search(r"\d{4000,}", text)
        at = f"line {text.count(chr(10), 0, long.start()) + 1}: " if long else ""
        what = "a number of thousands of digits" if "digits" in str(exc) else type(exc).__name__
        raise InputError(source, f"{at}TOML value out of range: {what}") from None


_TOML_AT = re.compile(r"^(?P<msg>.*?)\s*\((?:at line (?P<line>\d+), column (?P<col>\d+)|at end of "
                      r"document)\)$", re.S)
_TOML_HINTS = (
    ("Invalid value", "a value is a number, \"text\" in double quotes, [a, list] or { a = table }"),
    ("Cannot overwrite a value", "a name given twice: each key once"),
    ("Cannot declare", "a table given twice: merge the two sections"),
    ("Duplicate inline table key", "a name given twice: each key once"),
    ("Expected '=' after a key", "write key = value"),
    ("Unclosed array", "a [ is not closed by ]"),
    ("Unclosed inline table", "a { is not closed by } on the same line"),
    ("Unterminated string", "a \" is not closed on the same line"),
    ("Illegal character", "texts are on one line, in double quotes"),
    ("Expected newline or end of document", "one key = value per line; numbers as 0.15, 1e-3"),
    ("Invalid statement", "a line is key = value, [table], [[array]] or # comment"),
    ("Expected ']'", "a table header is [name] on its own line"),
)


def _toml_problem(message: str, text: str) -> str:
    m = _TOML_AT.match(message)
    msg = m.group("msg") if m else message
    if m and m.group("line"):
        where = f"line {m.group('line')}, column {m.group('col')}"
        line = int(m.group("line"))
    else:
        line = max(text.count("\n") + (0 if text.endswith("\n") else 1), 1)
        where = f"line {line} (end of file)"
    if msg.startswith("Cannot overwrite a value"):
        dup = first_duplicate("\n".join(text.split("\n")[:line]))
        if dup:
            key, first, again = dup
            return (
                f"line {again}: TOML syntax error: {key} is given twice (first at line {first}): "
                "each name once"
            )
    twice = re.match(r"Cannot declare \((.*)\) twice", msg)
    if twice:
        try:
            name = ".".join(key_text(p) for p in ast.literal_eval(f"({twice.group(1)})"))
            return f"{where}: TOML syntax error: the table [{name}] is given twice: merge the two sections"
        except (ValueError, SyntaxError, TypeError, RecursionError, MemoryError):
            pass
    hint = next((h for prefix, h in _TOML_HINTS if msg.startswith(prefix)), "")
    lines = text.split("\n")
    key = ""
    if m and m.group("line") and 0 < line <= len(lines):
        here = lines[line - 1]
        # the name where the parser stopped (points = { В = 0.06 } stops at the В), or the
        # line's own key
        at = re.match(r"[^\s=,{}\[\]\"']*", here[max(int(m.group("col")) - 1, 0):]).group()
        key = at if any(c in LOOKALIKES for c in at) else here.split("=", 1)[0]
    if type_in_latin(key):  # "АВ = 0.06" typed on a Russian keyboard: a bare key is Latin only
        hint = f"the name has {type_in_latin(key)}"
    elif m and m.group("line") and not here.lstrip().startswith("[") and "=" in here:
        hint = _bare_key_hint(key) or _comma_hint(here) or hint
    msg = one_line(msg[:1].lower() + msg[1:], 120)
    return f"{where}: TOML syntax error: {msg}" + (f" ({hint})" if hint else "")


#: a bare number with a decimal comma after a key's =: AB = 0,05 (TOML stops at the comma)
_BARE_COMMA = re.compile(r"=\s*([-+]?\d+),(\d+)\s*(?:#.*)?$")


def _comma_hint(line: str) -> str:
    """What to write for a number with a decimal comma (AB = 0,05), else "".

    >>> _comma_hint("AB = 0,05  # mm")
    'a decimal comma is written in quotes: "0,05", or 0.05'
    >>> _comma_hint("A = [0,05]")
    ''
    """
    m = _BARE_COMMA.search(line)
    if not m:
        return ""
    whole, frac = m.groups()
    return f'a decimal comma is written in quotes: "{whole},{frac}", or {whole}.{frac}'


#: Greek letters of the method's names, as a bare key writes them
_GREEK = {"π": "pi", "ω": "omega", "ε": "epsilon"}


def _bare_key_hint(key: str) -> str:
    """What to write for a bare key with letters TOML does not take bare (πk = 5), else "".

    >>> _bare_key_hint("πk ")
    'write π as pi (pik) or quote the key ("πk")'
    >>> _bare_key_hint("β2")
    'a key with letters other than A–Z, a–z is quoted: "β2"'
    """
    key = key.strip()
    parts = key.split(".")
    if not key or any(c in key for c in "\"'#") or all(BARE.fullmatch(p) for p in parts):
        return ""
    quoted = ".".join(p if BARE.fullmatch(p) else json.dumps(p, ensure_ascii=False)
                      for p in parts)
    latin = "".join(_GREEK.get(c, c) for c in key)
    if latin != key and all(BARE.fullmatch(p) for p in latin.split(".")):
        said = ", ".join(f"{g} as {a}" for g, a in _GREEK.items() if g in key)
        return f"write {said} ({latin}) or quote the key ({quoted})"
    return f"a key with letters other than A–Z, a–z is quoted: {quoted}"


#: the keys only one kind of input file has: a mechanism's [frame], [links], [driver]; a
#: measurement file's mechanism = … and [segments]; a variant table's [[variant]] rows
_MECHANISM_KEYS = {"frame", "links", "driver"}
_MEASUREMENT_KEYS = {"mechanism", "segments"}
#: each kind as the line that refuses it names it, and how it is used
_KINDS = {
    "mechanism": ("a mechanism file", "solve it with plans solve {src} (or report, cycle, sheet)"),
    "measurement": ("a measurement file (mechanism = …, [segments])",
                    "check it with plans check {src}"),
    "table": ("a variant table ([[variant]] rows)",
              'give it as --table {src} --variant N, or name it in a measurement file '
              '(table = "…", variant = N)'),
}


def file_kind(data: dict) -> str | None:
    """What a parsed input file is by the keys only its kind has: "mechanism",
    "measurement" or "table"; None where it has none of them or keys of two kinds (its
    reader then says which keys it does not know).

    >>> file_kind({"frame": {}, "links": {}}), file_kind({"variant": 3, "segments": {}})
    ('mechanism', 'measurement')
    >>> file_kind({"variant": [{"n": 1}]}), file_kind({"title": "x"})
    ('table', None)
    """
    mechanism, measurement = _MECHANISM_KEYS & data.keys(), _MEASUREMENT_KEYS & data.keys()
    if mechanism and not measurement:
        return "mechanism"
    if measurement and not mechanism:
        return "measurement"
    if not mechanism and isinstance(data.get("variant"), list):
        return "table"
    return None


def other_kind(data: dict, source: str, reads: str) -> str | None:
    """The one line for a file of another kind than the reader's own (``reads``), naming
    what it is and how it is used; None where it is not one."""
    kind = file_kind(data)
    if kind is None or kind == reads:
        return None
    what, how = _KINDS[kind]
    return f"{what}, not {_KINDS[reads][0].split(' (')[0]}: {how.format(src=source)}"


def name_list(names, limit: int = 20) -> str:
    names = sorted(names)
    if not names:
        return "none"
    if len(names) > limit:
        return ", ".join(names[:limit]) + f"… ({len(names)} in all)"
    return ", ".join(names)


class Problems:
    """Problems found in one file: (key path, message), located when it is raised."""

    def __init__(self, source: str, text: str | None = None):
        self.source = source
        self.text = text
        self.items: list[tuple[str, str]] = []

    def add(self, where: str, what: str) -> None:
        self.items.append((where, what))

    def __bool__(self) -> bool:
        return bool(self.items)

    def lines(self) -> list[str]:
        index = locate(self.text) if self.text else {}
        located = []
        for n, (where, what) in enumerate(self.items):
            line = line_of(where, index)
            text = f"{where}: {what}" if where else what
            if line:
                text = f"line {line}: {text}"
            located.append((line or 0, n, one_line(text, 400)))
        out: list[str] = []
        seen: set[str] = set()
        for _, _, text in sorted(located):
            if text not in seen:
                seen.add(text)
                out.append(text)
        if len(out) > MAX_PROBLEMS:
            more = len(out) - MAX_PROBLEMS
            out = [*out[:MAX_PROBLEMS], f"… and {more} more problems"]
        return out

    def raise_if_any(self) -> None:
        if self.items:
            raise InputError(self.source, self.lines())


#: how a field's own unit may be written after its number in quotes ("0,15 м", "40°"):
#: only then is the number without it suggested, since "12 см" in a field of metres is 0.12
UNIT_SPELLINGS = {
    "m": ("m", "м"),
    "mm": ("mm", "мм"),
    "°": ("°", "deg", "град"),
    "rpm": ("rpm", "об/мин"),
    "rad/s": ("rad/s", "рад/с"),
}

#: a number as a person writes one in quotes: a decimal point or comma, a sign (− too),
#: an exponent
DECIMAL = r"[-+−]?(?:\d+(?:[.,]\d*)?|[.,]\d+)(?:[eE][-+]?\d+)?"


def decimal(text: str) -> float:
    """The value of a :data:`DECIMAL` ("−4,82" is -4.82)."""
    return float(text.strip().replace("−", "-").replace(",", "."))


def read_number(value: Any, where: str, problems: Problems, *, positive=False, default=None,
            unit: str = "m", low: float | None = None, high: float = MAX_ABS):
    """A finite number within range, else ``None`` and a problem.

    ``low``: the smallest admissible magnitude (lengths are checked where they are known,
    between two points: a coordinate of 1e-300 is just 0).
    """
    if value is None:
        if default is not None:
            return default
        problems.add(where, "missing (a number is needed)")
        return None
    if isinstance(value, str) and re.fullmatch(rf"\s*{DECIMAL}\s*", value):
        value = decimal(value)  # "0,15" from a Russian keyboard, or "0.15": a number all the same
    if isinstance(value, bool) or not isinstance(value, int | float):
        hint = ""
        m = re.fullmatch(rf"\s*({DECIMAL})\s*(\S.*?)\s*", value[:60]) if isinstance(value, str) else None
        if m and m.group(2) in UNIT_SPELLINGS.get(unit, ()):  # the field's own unit
            number = m.group(1)
            hint = (f': write "{number}" or {number.replace(",", ".")}, without the unit'
                    if "," in number else f": write {number} without the unit")
        elif m and re.fullmatch(r"[^\d\s,.]+(/[^\d\s,.]+)?", m.group(2)):  # another unit
            hint = f": write the number in {unit}, without the unit"
        problems.add(where, f"must be a number, got {quote(value)}{hint}")
        return None
    if isinstance(value, int) and abs(value) > high:  # also 10**400, which float() refuses
        problems.add(where, f"{quote(value)} is out of range: at most {high:g} {unit}")
        return None
    x = float(value)
    if math.isnan(x):
        problems.add(where, f"nan is not a number: give a value in {unit}")
        return None
    if not math.isfinite(x):
        problems.add(where, f"{quote(value)} is out of range: at most {high:g} {unit}")
        return None
    if abs(x) > high:
        problems.add(where, f"{x:g} is out of range: at most {high:g} {unit} (a typo?)")
        return None
    if positive and x <= 0:
        hint = ' (the sense of rotation is sense = "cw" or "ccw")' if where.startswith("driver") else ""
        problems.add(where, f"must be positive, got {x:g}{hint}")
        return None
    if low is not None and abs(x) < low:
        problems.add(where, f"{x:g} is too small: at least {low:g} {unit}")
        return None
    return x


def read_text(value: Any, where: str, problems: Problems, default: str) -> str:
    if value is None:
        return default
    if not isinstance(value, str) or len(value) > MAX_TEXT:
        got = f"{len(value)} characters" if isinstance(value, str) else quote(value)
        problems.add(where, f"must be a text of at most {MAX_TEXT} characters, got {got}")
        return default
    return value


def check_keys(table: dict, allowed: set[str], where: str, problems: Problems):
    unknown = [key for key in table if key not in allowed]
    for n, key in enumerate(unknown):
        path = f"{where}.{key_text(key)}" if where else key_text(key)
        guess = close_match(key, allowed) if n < MAX_PROBLEMS else ""
        problems.add(path, f"unknown key — {guess}known: {', '.join(sorted(allowed))}")


#: Cyrillic letters that look like Latin ones: "АВ" typed on a Russian keyboard
LOOKALIKES = dict(zip("аеорсхукАВЕКМНОРСТХ", "aeopcxykABEKMHOPCTX", strict=True))


def cyrillic_letters(text: str) -> str:
    """"the Cyrillic letters р, а" (or "letter р") for the look-alikes in ``text``; "" where
    it has none. The messages of every file kind say it with these words.

    >>> cyrillic_letters("рa"), cyrillic_letters("pa")
    ('the Cyrillic letter р', '')
    """
    found = [c for c in dict.fromkeys(text) if c in LOOKALIKES]
    return f"the Cyrillic letter{'s' if len(found) > 1 else ''} {', '.join(found)}" if found else ""


def type_in_latin(text: str) -> str:
    """"the Cyrillic letters р, а: type them in Latin", or "" where ``text`` has none.

    >>> type_in_latin("ро")
    'the Cyrillic letters р, о: type them in Latin'
    """
    letters = cyrillic_letters(text)
    return f"{letters}: type {'them' if ',' in letters else 'it'} in Latin" if letters else ""


def close_match(key: Any, allowed, cutoff: float = 0.6) -> str:
    """'did you mean "AD"? ' for a key close to one of ``allowed``, else ''; a key typed
    with Cyrillic look-alike letters says so.

    >>> close_match("АВ", ["AB", "BC"])
    'did you mean "AB" (typed with the Cyrillic letters А, В)? '
    """
    key = str(key)[:40]
    latin = "".join(LOOKALIKES.get(c, c) for c in key)
    if latin != key and latin in allowed:
        return f'did you mean "{latin}" (typed with {cyrillic_letters(key)})? '
    same = sorted(a for a in allowed if a.lower() == key.lower())
    close = same or difflib.get_close_matches(key, sorted(allowed), n=1, cutoff=cutoff)
    return f'did you mean "{close[0]}"? ' if close else ""
