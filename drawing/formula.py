"""The note's formulas as formulas: its plain notation read into a tree that a document
writer sets as mathematics (a fraction, an index, a root, a vector's arrow).

The explanatory note (:mod:`plans.note.report`) writes every step in one line of plain
notation, ``ω3 = V_A3B / l_A3B = 2,7716 / 0,57482 = 4,822 рад/с``: an index after ``_``
(or after a letter, as digits: ``ω3``, ``pa3``), a superscript after ``^``, a fraction
as " / " between two terms, or "/" between two atoms (``P/η``), ``√(…)``, a result's
unit after its number. :func:`parse` reads such a line into :data:`Node` values; the DOCX
writer turns them into Office Math, the PDF writer into boxes. Nothing here is
computed: every character of the line reaches the tree, in its order (the test of
the documents compares their numbers with the Markdown's).

>>> show(parse("ω3 = V_A3B / l_A3B = 2,7716 / 0,57482 = 4,822 рад/с"))
'ω_{3} = frac(V_{A3B}, l_{A3B}) = frac(2,7716, 0,57482) = 4,822 "рад/с"'
>>> show(parse("V_A = V_B + V_AB", vector=True))
'vec(V)_{A} = vec(V)_{B} + vec(V)_{AB}'
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from typing import TypeAlias

__all__ = [
    "LONG",
    "Fence",
    "Frac",
    "Node",
    "Radical",
    "Run",
    "Script",
    "Vector",
    "parse",
    "plain",
    "prose",
    "show",
    "split_lines",
]


@dataclass(frozen=True, slots=True)
class Run:
    """Characters set alike: ``kind`` "var" (a letter of the notation: Latin italic,
    Greek and Cyrillic upright), "num", "op" (an operator, spaced), "punct" (a comma,
    a colon: space after only), "text" (words and units, upright, as written), "roman"
    (a class's numeral, upright), "bracket" (a bracket of a formula broken over lines)."""

    text: str
    kind: str = "var"


@dataclass(frozen=True, slots=True)
class Script:
    """``base`` with an index ``sub`` and/or a superscript ``sup``."""

    base: tuple[Node, ...]
    sub: tuple[Node, ...] = ()
    sup: tuple[Node, ...] = ()


@dataclass(frozen=True, slots=True)
class Frac:
    num: tuple[Node, ...]
    den: tuple[Node, ...]


@dataclass(frozen=True, slots=True)
class Radical:
    body: tuple[Node, ...]


@dataclass(frozen=True, slots=True)
class Vector:
    """An arrow over ``body``: a vector of a vector equation."""

    body: tuple[Node, ...]


@dataclass(frozen=True, slots=True)
class Fence:
    """``body`` between ``open`` and ``close`` (brackets, bars)."""

    open: str
    body: tuple[Node, ...]
    close: str


Node: TypeAlias = Run | Script | Frac | Radical | Vector | Fence

#: a numerator longer than this many characters is left on the line ("(…) / 60"): a
#: fraction that wide runs off the page, and neither Word nor the PDF breaks inside one
LONG = 48

_GREEK = "Α-Ωα-ωϑϕ"
_CYR = "А-Яа-яЁё"
_LETTER = f"A-Za-z{_GREEK}"
#: units a number may carry, by their first word (Russian and English)
_UNITS = {"м", "мм", "с", "рад", "Н", "Вт", "кВт", "кг", "об", "г", "м²", "m", "mm", "s", "rad",
          "N", "W", "kW", "kg", "rpm", "g", "%", "°"}
#: short English words that are words, not a segment's two letters
_WORDS = {"at", "on", "of", "in", "by", "to", "is", "or", "an", "as", "if", "no"}
_OPS = "=+−·≈≥≤∥⊥±→×<>∠Σ√%"

_TOKEN = re.compile(
    rf"""
    (?P<space>\s+)
  | (?P<motor>\d[A-Z{_CYR}0-9]*[{_CYR}][A-Z{_CYR}0-9]*)       # 4А80В2У3: a name
  | (?P<num>\d+(?:[.,]\d+)?(?:e[−-]?\d+)?[°′″²³]*)
  | (?P<guide>[a-z]\d*-[a-z]\d*(?![\w]))                      # the guide x-x, x3-x3
  | (?P<word>[a-z]+(?:-[a-z]+)+)                              # counter-clockwise
  | (?P<ident>[{_LETTER}][{_LETTER}0-9′″]*(?:[_^](?:\{{[^}}]*\}}|[^\s_^=+·/(),;:\[\]|−²³]+))*)
  | (?P<cyr>[{_CYR}]+(?:-[{_CYR}]+)*)
  | (?P<pow>[²³]+)
  | (?P<open>[(\[])
  | (?P<close>[)\]])
  | (?P<bar>\|)
  | (?P<slash>/)
  | (?P<punct>[,;:])
  | (?P<op>[{_OPS}-])
  | (?P<other>.)
    """,
    re.VERBOSE,
)


@dataclass(slots=True)
class _Tok:
    kind: str
    text: str
    space_before: bool = False
    space_after: bool = False


def _lex(s: str) -> list[_Tok]:
    out: list[_Tok] = []
    pending_space = False
    for m in _TOKEN.finditer(s):
        kind, text = m.lastgroup or "other", m.group()
        if kind == "space":
            pending_space = True
            if out:
                out[-1].space_after = True
            continue
        out.append(_Tok(kind, text, pending_space))
        pending_space = False
    return out


def _ident(text: str, vector: bool = False) -> tuple[Node, ...]:
    """A name of the notation: letters with digits as their index (``ω3``, ``pa3``,
    ``n1a3``), ``μ`` with its plan's letter (``μv``), and indices after ``_`` and
    superscripts after ``^`` (``a^n_A3B``, ``R34^τ``)."""
    m = re.match(r"[^_^]*", text)
    head, rest = m.group(), text[m.end():]
    sub: list[str] = []
    sup: list[str] = []
    for mark, arg in re.findall(r"([_^])(\{[^}]*\}|[^_^]+)", rest):
        (sub if mark == "_" else sup).append(arg.strip("{}"))
    parts = re.findall(rf"([{_LETTER}′″]+)(\d*)", head)
    nodes: list[Node] = []
    if head.startswith("μ") and len(head) > 1 and not any(d for _, d in parts):
        parts = [("μ", ""), ("", "")]
        sub.insert(0, head[1:])
    for i, (letters, digits) in enumerate(parts):
        if not letters and not digits:
            continue
        last = i == len([p for p in parts if p[0] or p[1]]) - 1
        base: tuple[Node, ...] = (Run(letters, "var"),)
        if vector and i == 0:
            base = (Vector(base),)
        s = (Run(digits, "var"),) if digits else ()
        if last and (sub or sup):
            s = s + tuple(Run(x, "var") for x in sub) if s and sub else (
                s or tuple(Run(x, "var") for x in sub))
            up = tuple(Run(x, "var") for x in sup)
            nodes.append(Script(base, s, up))
        elif s:
            nodes.append(Script(base, s))
        else:
            nodes.extend(base)
    return tuple(nodes)


def _number(text: str) -> tuple[Node, ...]:
    """A number, its exponent set as a power of ten (3,8e−14 is 3,8·10⁻¹⁴)."""
    m = re.fullmatch(r"(.+?)e([−-]?\d+)(.*)", text)
    if not m:
        return (Run(text, "num"),)
    mant, exp, tail = m.groups()
    out: list[Node] = [Run(mant, "num"), Run("·", "op"),
                       Script((Run("10", "num"),), (), (Run(exp.replace("-", "−"), "num"),))]
    if tail:
        out.append(Run(tail, "num"))
    return tuple(out)


def _unit_after(toks: list[_Tok], i: int) -> int:
    """The end of a unit that starts at token ``i`` after a number (``м/с``, ``(м/с)/мм``,
    ``rad/s²``, ``Н·м``), or ``i`` where none does."""
    j = i
    depth = 0
    seen = False
    while j < len(toks):
        t = toks[j]
        if j > i and t.space_before:  # a unit is one word: "м/с", "(м/с²)/мм", "Н·м"
            break
        word = t.text
        if t.kind in ("ident", "cyr") and (word in _UNITS or (seen and word.isalpha())):
            seen = True
        elif t.kind == "pow" and seen:
            pass
        elif t.kind == "open" and t.text == "(" and not t.space_after:
            depth += 1
        elif t.kind == "close" and t.text == ")" and depth:
            depth -= 1
        elif t.kind in ("slash",) or t.text == "·":
            pass
        elif t.kind == "op" and t.text == "%":
            seen = True
        else:
            break
        j += 1
    while j > i and (toks[j - 1].kind in ("slash", "open") or toks[j - 1].text == "·"):
        j -= 1
    return j if seen and depth == 0 else i


def _atoms(toks: list[_Tok], vector: bool) -> list[tuple[str, tuple[Node, ...], _Tok]]:
    """The tokens as (kind, nodes, token) with brackets nested (kind "fence")."""
    out: list[tuple[str, tuple[Node, ...], _Tok]] = []
    i = 0
    after_number = False
    while i < len(toks):
        t = toks[i]
        if after_number and t.kind in ("ident", "cyr", "op", "open"):
            j = _unit_after(toks, i)
            if j > i:
                text = ""
                for k in range(i, j):
                    text += (" " if k > i and toks[k].space_before else "") + toks[k].text
                out.append(("text", (Run(text, "text"),), toks[j - 1]))
                i = j
                after_number = False
                continue
        after_number = False
        if t.kind == "num":
            out.append(("atom", _number(t.text), t))
            after_number = True
        elif t.kind == "ident":
            word = t.text
            if (word in _WORDS or re.fullmatch(r"[a-z]{3,}|[A-Z][a-z]{2,}(?:-[a-z]+)*|[a-z]+(?:-[a-z]+)+",
                                               word)) and not re.search(r"[_^]", word):
                out.append(("text", (Run(word, "text"),), t))
            elif (roman := re.fullmatch(r"(I{1,3}|IV|VI{0,3})(\d?)", word)) and i + 1 < len(toks) \
                    and toks[i + 1].kind == "open":  # a structural formula's class: II3(2,3)
                numeral = (Run(roman.group(1), "roman"),)
                out.append(("atom", (Script(numeral, (Run(roman.group(2), "num"),)),) if roman.group(2)
                            else numeral, t))
            else:
                out.append(("atom", _ident(word, vector), t))
        elif t.kind == "guide":
            out.append(("atom", (Run(t.text, "var"),), t))
        elif t.kind == "word":
            out.append(("text", (Run(t.text, "text"),), t))
        elif t.kind == "pow":  # V_DC²: the power of the name before it
            out.append(("atom", (Run(t.text, "var"),), t))
        elif t.kind in ("cyr", "motor"):
            kind = "atom" if re.fullmatch(f"[{_CYR}]", t.text) and t.text.isupper() else "text"
            out.append((kind, (Run(t.text, "var" if kind == "atom" else "text"),), t))
        elif t.kind == "op" and t.text == "√":
            out.append(("sqrt", (), t))
        elif t.kind in ("open", "close", "bar", "slash"):
            out.append((t.kind, (), t))
        elif t.kind == "punct":
            out.append(("punct", (Run(t.text, "punct"),), t))
        elif t.kind == "op":
            out.append(("op", (Run("−" if t.text == "-" else t.text, "op"),), t))
        else:
            out.append(("text", (Run(t.text, "text"),), t))
        i += 1
    return out


def _nest(atoms, i=0, close=None):
    """Brackets and bars into ("fence", nodes): returns (items, next index)."""
    items: list = []
    while i < len(atoms):
        kind, nodes, t = atoms[i]
        if kind == "close" and close is not None and t.text == close:
            return items, i + 1
        if kind == "bar" and close == "|":
            return items, i + 1
        if kind in ("open", "bar"):
            want = {"(": ")", "[": "]", "|": "|"}[t.text]
            inner, j = _nest(atoms, i + 1, want)
            if j <= len(atoms) and (j > i + 1 or want == "|"):
                items.append(("fence", (Fence(t.text, _resolve(inner), want),), t))
                i = j
                continue
        items.append((kind, nodes, t))
        i += 1
    if close is not None:  # unbalanced: the bracket is a character
        return items, len(atoms) + 1
    return items, i


_SEPARATORS = {"=", "≈", "≥", "≤", "+", "−", "→", "±", "<", ">"}


def _resolve(items) -> tuple[Node, ...]:
    """Fractions and roots of one bracket level, as nodes."""
    items = list(items)
    # roots: √ and the bracket after it
    k = 0
    while k < len(items):
        if items[k][0] == "sqrt" and k + 1 < len(items) and items[k + 1][0] == "fence":
            fence = items[k + 1][1][0]
            items[k:k + 2] = [("atom", (Radical(fence.body),), items[k][2])]
        elif items[k][0] == "sqrt":
            items[k] = ("op", (Run("√", "op"),), items[k][2])
        k += 1
    # fractions, left to right
    k = 0
    while k < len(items):
        kind, _, t = items[k]
        if kind != "slash":
            k += 1
            continue
        spaced = t.space_before and t.space_after
        if spaced:
            lo = k
            while lo > 0 and not _separates(items[lo - 1]):
                lo -= 1
            hi = k + 1
            while hi < len(items) and not _separates(items[hi]):
                hi += 1
        else:
            lo, hi = k - 1, k + 2
        num, den = items[lo:k], items[k + 1:hi]
        ok = (num and den and lo >= 0 and hi <= len(items)
              and all(x[0] in ("atom", "fence", "op") for x in num + den)
              and not all(x[0] == "op" for x in num) and not all(x[0] == "op" for x in den))
        if ok and len(plain(_flat(num))) > LONG:
            ok = False
        if not ok:
            items[k] = ("op", (Run("/", "slash" if not spaced else "op"),), t)
            k += 1
            continue
        frac = Frac(_unfence(_flat(num)), _unfence(_flat(den)))
        items[lo:hi] = [("atom", (frac,), t)]
        k = lo + 1
    return _flat(items)


def _separates(item) -> bool:
    kind, nodes, _ = item
    if kind == "punct":
        return True
    return kind == "op" and isinstance(nodes[0], Run) and nodes[0].text in _SEPARATORS


def _flat(items) -> tuple[Node, ...]:
    return tuple(n for _, nodes, _ in items for n in nodes)


def _unfence(nodes: tuple[Node, ...]) -> tuple[Node, ...]:
    """A numerator or denominator in round brackets loses them: the bar groups it."""
    if len(nodes) == 1 and isinstance(nodes[0], Fence) and nodes[0].open == "(":
        return nodes[0].body
    return nodes


def parse(text: str, vector: bool = False) -> tuple[Node, ...]:
    """``text`` in the note's notation as nodes; ``vector``: its names are vectors (a
    vector equation), an arrow over each.

    >>> show(parse("u34 = √(u/1,2) = 3,85"))
    'u_{34} = sqrt(frac(u, 1,2)) = 3,85'
    >>> show(parse("δ = 1,3e−14 %"))
    'δ = 1,3 · 10^{−14} "%"'
    >>> show(parse("K = (180° + θ) / (180° − θ) = 1,569"))
    'K = frac(180° + θ, 180° − θ) = 1,569'
    """
    items, _ = _nest(_atoms(_lex(text), vector))
    return _resolve(items)


def prose(text: str) -> list[tuple[str, str | tuple[Node, ...]]]:
    """A sentence of the note in pieces: ("text", words) and ("math", nodes) for the
    notation it names in passing (``V_A3A``, ``ω1``, ``S3``, ``μF``, ``φ_рх``, ``ψ``).

    >>> [v if k == "text" else show(v) for k, v in prose("Через точку a3 и V_A3A при ω1:")]
    ['Через точку ', 'a_{3}', ' и ', 'V_{A3A}', ' при ', 'ω_{1}', ':']
    """
    pattern = re.compile(
        rf"(?<![\w{_CYR}])(?:[{_LETTER}]+\d*(?:[_^][^\s,;:()]+)+|[{_LETTER}]{{1,3}}\d+[A-Za-z0-9]*"
        rf"|μ[lvaF]|[{_GREEK}]\d*)(?![\w{_CYR}])")
    out: list[tuple[str, str | tuple[Node, ...]]] = []
    pos = 0
    for m in pattern.finditer(text):
        if m.start() > pos:
            out.append(("text", text[pos:m.start()]))
        out.append(("math", parse(m.group())))
        pos = m.end()
    if pos < len(text):
        out.append(("text", text[pos:]))
    return out


def plain(nodes: tuple[Node, ...]) -> str:
    """The characters of ``nodes`` in their order (a fraction's numerator, then its
    denominator), without the marks that set them."""
    out = []
    for n in nodes:
        if isinstance(n, Run):
            out.append(n.text)
        elif isinstance(n, Script):
            out.append(plain(n.base) + plain(n.sub) + plain(n.sup))
        elif isinstance(n, Frac):
            out.append(plain(n.num) + " " + plain(n.den))
        elif isinstance(n, Radical):
            out.append("√" + plain(n.body))
        elif isinstance(n, Vector):
            out.append(plain(n.body))
        elif isinstance(n, Fence):
            out.append(n.open + plain(n.body) + n.close)
    return "".join(out)


def show(nodes: tuple[Node, ...]) -> str:
    """``nodes`` written out for a reader (and a doctest): frac(a, b), sqrt(x),
    vec(V), x_{i}, x^{n}, "text"."""
    out = []
    for n in nodes:
        if isinstance(n, Run):
            piece = f'"{n.text}"' if n.kind == "text" else n.text
            if n.kind in ("op",) or (n.kind == "text"):
                out.append(f" {piece} ")
            elif n.kind == "punct":
                out.append(f"{piece} ")
            else:
                out.append(piece)
        elif isinstance(n, Script):
            s = show(n.base)
            if n.sub:
                s += "_{" + show(n.sub) + "}"
            if n.sup:
                s += "^{" + show(n.sup) + "}"
            out.append(s)
        elif isinstance(n, Frac):
            out.append(f"frac({show(n.num)}, {show(n.den)})")
        elif isinstance(n, Radical):
            out.append(f"sqrt({show(n.body)})")
        elif isinstance(n, Vector):
            out.append(f"vec({show(n.body)})")
        elif isinstance(n, Fence):
            out.append(f"{n.open}{show(n.body)}{n.close}")
    return re.sub(r"\s+", " ", "".join(out)).strip()


_BREAKS = ("=", "≈", "≥", "≤")
_TERMS = ("+", "−", "±")


def _width(nodes: tuple[Node, ...]) -> int:
    return len(plain(nodes))


def _open_up(nodes: tuple[Node, ...]) -> tuple[Node, ...]:
    """A long bracket's contents laid on the line, so that it can break at its terms:
    ``(a + b + c)`` as "(", a, +, b, +, c, ")"."""
    out: list[Node] = []
    for n in nodes:
        if isinstance(n, Fence) and _width(n.body) > LONG:
            out += [Run(n.open, "bracket"), *n.body, Run(n.close, "bracket")]
        else:
            out.append(n)
    return tuple(out)


def split_lines(nodes: tuple[Node, ...], limit: int = 60) -> list[tuple[Node, ...]]:
    """A formula too long for a line, broken where a reader breaks it: before an "="
    (the next line starts with it), and inside a long bracket before a "+" or "−";
    each line at most ``limit`` characters where a break allows.

    >>> [show(line) for line in split_lines(parse("x = a + b = 10"), 6)]
    ['x = a + b', '= 10']
    """
    if _width(nodes) <= limit:
        return [nodes]

    def pieces(ns: tuple[Node, ...], ops: tuple[str, ...]) -> list[tuple[Node, ...]]:
        out: list[list[Node]] = [[]]
        for n in ns:
            if isinstance(n, Run) and n.kind == "op" and n.text in ops and out[-1]:
                out.append([])
            out[-1].append(n)
        return [tuple(p) for p in out]

    parts = pieces(nodes, _BREAKS)
    fine: list[tuple[Node, ...]] = []
    for part in parts:
        if _width(part) <= limit:
            fine.append(part)
        else:
            fine += pieces(_open_up(part), _TERMS)
    lines: list[tuple[Node, ...]] = []
    for part in fine:
        if lines and _width(lines[-1]) + _width(part) <= limit:
            lines[-1] = lines[-1] + part
        else:
            lines.append(part)
    return lines
