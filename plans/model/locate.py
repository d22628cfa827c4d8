"""Where a key is in a file, and how a message quotes what the file holds.

A :class:`FileIndex` reads a TOML text that parses, once and only when a problem is said,
and notes the line of every key path ("links.3.points.C", "sliders[1].guide",
"frame.O[0]"), so that each problem of :class:`plans.model.fileformat.Problems` is said
with its line, in time linear in the text; :func:`first_duplicate` finds the key a file
gives twice. :func:`quote` and :func:`key_text` put a value or a key
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


class _Node:
    """One key of the file: the line it first appears on, the keys under it (an array's
    elements as "[n]"), and for an array of tables the number of its current element."""

    __slots__ = ("defined", "kids", "line", "n")

    def __init__(self):
        self.line: int | None = None
        self.kids: dict[str, _Node] = {}
        self.n: int | None = None  # an array of tables: its current element
        self.defined: int | None = None  # the line where a value is given to this key

    def child(self, part: str) -> _Node:
        node = self.kids.get(part)
        if node is None:
            node = self.kids[part] = _Node()
        return node

    def mark(self, line: int) -> None:
        if self.line is None:
            self.line = line


def split_path(where: str) -> list[str]:
    """A key path as messages write it ("links.3.points.C", "sliders[1].guide",
    'title."a.b"') as its keys, an element of an array as "[n]"; one pass.

    >>> split_path('sliders[1].guide.through[0]'), split_path('x."a.b".y')
    (['sliders', '[1]', 'guide', 'through', '[0]'], ['x', '"a.b"', 'y'])
    """
    parts: list[str] = []
    i, n = 0, len(where)
    while i < n:
        c = where[i]
        if c == ".":
            i += 1
            continue
        if c == "[":
            j = where.find("]", i)
            j = n if j < 0 else j + 1
        elif c == '"':
            j = i + 1
            while j < n and where[j] != '"':
                j += 2 if where[j] == "\\" else 1
            j = min(j + 1, n)
        else:
            j = i
            while j < n and where[j] not in ".[":
                j += 1
        parts.append(where[i:j])
        i = j
    return parts


class FileIndex:
    """The lines of a file's keys, read once, on first use, in time linear in the text's
    size: the key paths form a tree, each key a node under the table that holds it, so
    that a key under a header of 10,000 dotted levels costs its own length, not the
    header's (each prefix had been joined into a string of its own: a 10,000-level
    header with one problem took 14–25 s to locate, 50,000 levels 380 s)."""

    def __init__(self, text: str | None):
        self.text = text
        self._read: _Locator | None = None

    def _locator(self) -> _Locator:
        if self._read is None:
            self._read = _Locator(self.text or "")
            try:
                self._read.document()
            except Exception:  # best effort: what was read before stays located
                pass
        return self._read

    def line(self, where: str) -> int | None:
        """The line of ``where`` or of the nearest enclosing key that is in the file."""
        if not where or not self.text:
            return None
        node, found = self._locator().root, None
        for part in split_path(where):
            node = node.kids.get(part)
            if node is None:
                break
            if node.line is not None:
                found = node.line
        return found

    def duplicate(self) -> tuple[str, int, int] | None:
        """The first key given twice: (key path, first line, second line)."""
        return self._locator().duplicate


def _join(path: list[str]) -> str:
    return "".join(p if p.startswith("[") or not i else "." + p for i, p in enumerate(path))


def line_of(where: str, index: FileIndex) -> int | None:
    """The line of ``where`` or of the nearest enclosing key that is in the file."""
    return index.line(where)


def locate(text: str) -> FileIndex:
    """The lines of the keys of a TOML text that parses, read on first use
    (:meth:`FileIndex.line`: "links.3.points.C", "sliders[1].guide", "frame.O[0]" → its
    line). Best effort: never raises; an unlocated problem keeps its key path."""
    return FileIndex(text)


def first_duplicate(text: str) -> tuple[str, int, int] | None:
    """The first key given twice in ``text``: (key path, first line, second line)."""
    return FileIndex(text).duplicate()


class _Locator:
    """A small reader of valid TOML that notes the line where each key is defined, as a
    tree of :class:`_Node` (linear in the text: nothing is joined or copied per key)."""

    def __init__(self, text: str):
        self.s = text
        self.i = 0
        self.line = 1
        self.root = _Node()
        self.duplicate: tuple[str, int, int] | None = None

    def _note(self, node: _Node, parts: list[str], line: int, *, value: bool = False,
              table: list[str] | None = None) -> _Node:
        """The node of ``parts`` under ``node``, each new key noted at ``line``; a value
        given twice is the file's first duplicate (its path joined once, for the message)."""
        for part in parts:
            node = node.child(part)
            node.mark(line)
        if value:
            if node.defined is not None and self.duplicate is None:
                self.duplicate = (_join([*(table or []), *parts]), node.defined, line)
            if node.defined is None:
                node.defined = line
        return node

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

    def _header(self, parts: list[str], line: int, array: bool) -> tuple[_Node, list[str]]:
        """The node of a table header and its path (kept for a duplicate's message), with
        the current element of every array of tables on the way, walked once; an array of
        tables is noted where it first appears, each element where it begins."""
        node, path = self.root, []
        last = len(parts) - 1
        for k, part in enumerate(parts):
            node = node.child(part)
            node.mark(line)  # [a.b.c] locates a problem of "a" too, where nothing else does
            path.append(part)
            if array and k == last:
                node.n = 0 if node.n is None else node.n + 1
            if node.n is not None:
                path.append(f"[{node.n}]")
                node = node.child(path[-1])
        node.mark(line)
        return node, path

    def document(self) -> None:
        table, path = self.root, []
        while True:
            self._skip(newlines=True)
            if self.i >= len(self.s):
                return
            line = self.line
            if self.s.startswith("[[", self.i):
                self._advance(2)
                parts = self._key()
                self._expect("]]")
                table, path = self._header(parts, line, array=True)
            elif self._peek() == "[":
                self._advance()
                parts = self._key()
                self._expect("]")
                table, path = self._header(parts, line, array=False)
            else:
                parts = self._key()
                self._expect("=")
                node = self._note(table, parts, line, value=True, table=path)
                self._value(node)

    def _value(self, node: _Node) -> None:
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
                item = node.child(f"[{n}]")
                item.mark(self.line)
                self._value(item)
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
                self._value(self._note(node, parts, line, value=True))
                self._skip()
                if self._peek() == ",":
                    self._advance()
        else:
            m = _SCALAR.match(self.s, self.i)
            if not m.group().strip():
                raise ValueError(f"no value at line {self.line}")
            self._advance(len(m.group()))


_SCALAR = re.compile(r"[^,\]}\n#]*")
