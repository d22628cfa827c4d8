"""Where a key is in a file, and how a message quotes what the file holds.

:func:`locate` reads a TOML text that parses and notes the line of every key path
("links.3.points.C", "sliders[1].guide", "frame.O[0]"), so that each problem of
:class:`plans.model.fileformat.Problems` is said with its line; :func:`first_duplicate`
finds the key a file gives twice. :func:`quote` and :func:`key_text` put a value or a key
of the file into a message, on one line and cut short, so that a hostile file cannot
flood the terminal.
"""

from __future__ import annotations

import datetime
import json
import re
from typing import Any


def one_line(text: str, limit: int = 200) -> str:
    """``text`` on one line, at most ``limit`` characters."""
    cut = len(text) > limit
    text = "".join(c if c.isprintable() else repr(c)[1:-1] for c in text[:limit])
    return text[: limit - 1] + "…" if cut or len(text) > limit else text


def quote(value: Any, limit: int = 40) -> str:
    """A value of the file, quoted and cut short, for a message."""
    if isinstance(value, str):
        return '"' + one_line(value, limit).replace('"', '\\"') + '"'
    if isinstance(value, dict):
        return "a table"
    if isinstance(value, list):
        return f"a list of {len(value)}"
    if isinstance(value, int) and not isinstance(value, bool) and abs(value) > 10**15:
        digits = len(str(abs(value))) if abs(value) < 10**4000 else "thousands of"
        return f"{'-' if value < 0 else ''}an integer of {digits} digits"
    if isinstance(value, bool):
        return "true" if value else "false"  # as the file spells it
    if isinstance(value, datetime.date | datetime.time):
        return f"the date or time {value.isoformat()}"  # 1979-05-27, not datetime.date(…)
    return one_line(repr(value), limit)


_SIMPLE_KEY = re.compile(r"^[A-Za-z0-9_'-]{1,40}$")


def key_text(key: Any) -> str:
    """A key of the file as it appears in a key path."""
    if isinstance(key, str) and _SIMPLE_KEY.match(key):
        return key
    return quote(key, 30)


#: a bare TOML key's characters
BARE = re.compile(r"[A-Za-z0-9_-]+")


def _join(path: list[str]) -> str:
    out = ""
    for part in path:
        out += part if part.startswith("[") or not out else "." + part
    return out


def line_of(where: str, index: dict[str, int]) -> int | None:
    """The line of ``where`` or of the nearest enclosing key that is in the file."""
    while where:
        if where in index:
            return index[where]
        cut = max(where.rfind("."), where.rfind("["))
        if cut <= 0:
            return None
        where = where[:cut]
    return None


def locate(text: str) -> dict[str, int]:
    """Key path ("links.3.points.C", "sliders[1].guide", "frame.O[0]") → line, for a TOML
    text that parses. Best effort: never raises; an unlocated problem keeps its key path."""
    loc = _Locator(text)
    try:
        loc.document()
    except Exception:
        pass
    return loc.index


def first_duplicate(text: str) -> tuple[str, int, int] | None:
    """The first key given twice in ``text``: (key path, first line, second line)."""
    loc = _Locator(text)
    try:
        loc.document()
    except Exception:
        pass
    return loc.duplicate


class _Locator:
    """A small reader of valid TOML that notes the line where each key is defined."""

    def __init__(self, text: str):
        self.s = text
        self.i = 0
        self.line = 1
        self.index: dict[str, int] = {}
        self.defined: dict[str, int] = {}
        self.duplicate: tuple[str, int, int] | None = None
        self.aot: dict[str, int] = {}  # array of tables → index of its current element

    def _note(self, path: list[str], line: int, *, value: bool = False) -> None:
        key = _join(path)
        self.index.setdefault(key, line)
        if value:
            if key in self.defined and self.duplicate is None:
                self.duplicate = (key, self.defined[key], line)
            self.defined.setdefault(key, line)

    def _peek(self) -> str:
        return self.s[self.i] if self.i < len(self.s) else ""

    def _advance(self, n: int = 1) -> None:
        self.line += self.s.count("\n", self.i, self.i + n)
        self.i += n

    def _skip(self, newlines: bool = False) -> None:
        s = self.s
        while self.i < len(s):
            c = s[self.i]
            if c in " \t\r" or (newlines and c == "\n"):
                self._advance()
            elif c == "#":
                end = s.find("\n", self.i)
                self.i = len(s) if end < 0 else end
            else:
                return

    def _expect(self, token: str) -> None:
        self._skip()
        if not self.s.startswith(token, self.i):
            raise ValueError(f"expected {token!r} at line {self.line}")
        self._advance(len(token))

    def _key(self) -> list[str]:
        parts = []
        while True:
            self._skip()
            if self._peek() in "\"'":
                parts.append(key_text(self._string()))
            else:
                m = BARE.match(self.s, self.i)
                if not m:
                    raise ValueError(f"no key at line {self.line}")
                parts.append(key_text(m.group()))
                self._advance(len(m.group()))
            self._skip()
            if self._peek() != ".":
                return parts
            self._advance()

    def _string(self) -> str:
        s, q = self.s, self.s[self.i]
        if s.startswith(q * 3, self.i):
            end = self.i + 3
            while True:
                end = s.find(q * 3, end)
                if end < 0:
                    raise ValueError("unterminated string")
                if q == '"' and s[end - 1] == "\\":
                    end += 1
                    continue
                break
            while s.startswith(q, end + 3):
                end += 1
            raw = s[self.i + 3 : end]
            self._advance(end + 3 - self.i)
            return raw
        j = self.i + 1
        while s[j] != q:
            j += 2 if (q == '"' and s[j] == "\\") else 1
        raw = s[self.i + 1 : j]
        self._advance(j + 1 - self.i)
        if q == '"' and "\\" in raw:
            try:
                raw = json.loads(f'"{raw}"')
            except ValueError:
                pass
        return raw

    def _resolve(self, parts: list[str]) -> list[str]:
        """Header key → path, with the current element of every array of tables in it."""
        out: list[str] = []
        for part in parts:
            out.append(part)
            n = self.aot.get(_join(out))
            if n is not None:
                out[-1] = f"{part}[{n}]"
        return out

    def document(self) -> None:
        table: list[str] = []
        while True:
            self._skip(newlines=True)
            if self.i >= len(self.s):
                return
            line = self.line
            if self.s.startswith("[[", self.i):
                self._advance(2)
                parts = self._key()
                self._expect("]]")
                base = [*self._resolve(parts[:-1]), parts[-1]]
                key = _join(base)
                n = self.aot.get(key, -1) + 1
                self.aot[key] = n
                self.index.setdefault(key, line)
                table = [*base[:-1], f"{parts[-1]}[{n}]"]
                self._note(table, line)
            elif self._peek() == "[":
                self._advance()
                parts = self._key()
                self._expect("]")
                table = self._resolve(parts)
                self._note(table, line)
            else:
                parts = self._key()
                self._expect("=")
                self._note(table + parts, line, value=True)
                self._value(table + parts)

    def _value(self, path: list[str]) -> None:
        self._skip()
        c = self._peek()
        if c in "\"'":
            self._string()
        elif c == "[":
            self._advance()
            n = 0
            while True:
                self._skip(newlines=True)
                if self._peek() == "]":
                    self._advance()
                    return
                self._note([*path, f"[{n}]"], self.line)
                self._value([*path, f"[{n}]"])
                n += 1
                self._skip(newlines=True)
                if self._peek() == ",":
                    self._advance()
        elif c == "{":
            self._advance()
            while True:
                self._skip()
                if self._peek() == "}":
                    self._advance()
                    return
                line = self.line
                parts = self._key()
                self._expect("=")
                self._note(path + parts, line, value=True)
                self._value(path + parts)
                self._skip()
                if self._peek() == ",":
                    self._advance()
        else:
            m = re.compile(r"[^,\]}\n#]*").match(self.s, self.i)
            if not m.group().strip():
                raise ValueError(f"no value at line {self.line}")
            self._advance(len(m.group()))
