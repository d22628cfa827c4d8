"""The explanatory note as a document: its Markdown read into headings, paragraphs,
formulas and tables, which the DOCX and PDF writers set (:mod:`drawing.docx`,
:mod:`drawing.notepdf`).

The note (:func:`plans.note.report.note`, with :func:`plans.forces.note.force_note`
after it) is Markdown of a few forms only: a title (``#``), numbered sections
(``## 1. …``), unnumbered subsections (``###``), paragraphs, items (``- …``), a step of
the calculation as an item that is one code span (``- `formula = substitution =
result```), its continuation lines indented under it, a group's name in bold, a
warning as a quote, and tables (``| … |``). Here each becomes a block: a step is a
display :class:`Formula` (a vector equation's names get their arrows), a subsection
takes its section's number (5.1, 5.2, as GOST 2.105 numbers them), and the notation
in a sentence (``V_A3A``, ``ω1``) is set as mathematics too. Every character of the
Markdown reaches a block, so the documents say what the Markdown says.

>>> doc = parse_note("# Note: press\\n\\n## 1. Plans\\n\\n### Loads\\n\\nVelocity:\\n\\n- `V_A = 3 m/s`\\n")
>>> [type(b).__name__ for b in doc.blocks], doc.blocks[1].number, doc.title
(['Heading', 'Heading', 'Paragraph', 'Formula'], '1.1', 'Note: press')
"""

from __future__ import annotations

import re
from dataclasses import dataclass, field
from typing import TypeAlias

from drawing.formula import Node, Run, parse, prose

__all__ = [
    "Block",
    "Document",
    "Formula",
    "Heading",
    "Paragraph",
    "Piece",
    "Table",
    "numbers",
    "parse_note",
    "pieces",
]


@dataclass(frozen=True, slots=True)
class Piece:
    """A piece of a sentence: ``kind`` "text" (``bold`` or not) or "math" (``nodes``)."""

    kind: str
    text: str = ""
    nodes: tuple[Node, ...] = ()
    bold: bool = False


@dataclass(frozen=True, slots=True)
class Heading:
    """A section (``level`` 1, numbered "3") or a subsection (``level`` 2, "5.1")."""

    level: int
    number: str
    pieces: tuple[Piece, ...]


@dataclass(frozen=True, slots=True)
class Paragraph:
    """``kind``: "body" (a paragraph), "item" (an item of a list), "aside" (a line under
    an item), "group" (a group's name, in bold), "note" (a warning)."""

    pieces: tuple[Piece, ...]
    kind: str = "body"
    level: int = 0


@dataclass(frozen=True, slots=True)
class Formula:
    """A step of the calculation, on a line of its own; ``level`` 1 under an item."""

    nodes: tuple[Node, ...]
    level: int = 0
    source: str = ""


@dataclass(frozen=True, slots=True)
class Table:
    """Rows of cells, each cell pieces; the first row is the header."""

    rows: tuple[tuple[tuple[Piece, ...], ...], ...]


Block: TypeAlias = Heading | Paragraph | Formula | Table


@dataclass(frozen=True, slots=True)
class Document:
    """The note: its ``title`` (plain text) and blocks, in ``lang``."""

    title: str
    blocks: tuple[Block, ...]
    lang: str = "en"
    sections: tuple[str, ...] = field(default=())


#: the sentences after which a step is a vector equation (its names get arrows)
_VECTOR_LEAD = re.compile(r"(Векторные уравнения|Vector equations)")
#: a sentence that names the force polygon, whose sum is a vector sum
_POLYGON = re.compile(r"(Многоугольник|polygon)", re.IGNORECASE)


def pieces(text: str, vector_sum: bool = False) -> tuple[Piece, ...]:
    """A Markdown line's pieces: code spans as formulas, ``**bold**``, and the notation
    named in the words (:func:`drawing.formula.prose`).

    >>> [(p.kind, p.bold, p.text) for p in pieces("Lines ∥ BC at `a3`, **bold**")]
    [('text', False, 'Lines ∥ BC at '), ('math', False, 'a3'), ('text', False, ', '), ('text', True, 'bold')]
    """
    out: list[Piece] = []
    for m in re.finditer(r"`([^`]*)`|\*\*(.+?)\*\*|([^`*]+|\*)", text):
        code, bold, words = m.groups()
        if code is not None:
            vector = vector_sum and bool(re.search(r"\+.*= 0$", code))
            out.append(Piece("math", nodes=parse(code, vector=vector), text=code))
        elif bold is not None:
            out.append(Piece("text", bold, bold=True))
        else:
            for kind, value in prose(words):
                if kind == "text":
                    out.append(Piece("text", value))
                else:
                    out.append(Piece("math", nodes=value))
    return tuple(out)


def _row(line: str) -> tuple[str, ...]:
    return tuple(c.strip() for c in line.strip().strip("|").split("|"))


def parse_note(markdown: str, lang: str = "en") -> Document:
    """The note's Markdown as a :class:`Document`."""
    title = ""
    blocks: list[Block] = []
    section = 0
    sub = 0
    lines = markdown.splitlines()
    i = 0
    para: list[str] = []
    last_text = ""

    def flush() -> None:
        nonlocal last_text
        if para:
            text = " ".join(s.strip() for s in para)
            blocks.append(Paragraph(pieces(text, bool(_POLYGON.search(text)))))
            last_text = text
            para.clear()

    while i < len(lines):
        line = lines[i]
        stripped = line.strip()
        if not stripped:
            flush()
            i += 1
            continue
        if line.startswith("# "):
            flush()
            title = line[2:].strip()
        elif line.startswith("## "):
            flush()
            text = line[3:].strip()
            m = re.match(r"(\d+)\.?\s+(.*)", text)
            section = int(m.group(1)) if m else section + 1
            sub = 0
            blocks.append(Heading(1, str(section), pieces(m.group(2) if m else text)))
        elif line.startswith("### "):
            flush()
            sub += 1
            blocks.append(Heading(2, f"{section}.{sub}", pieces(line[4:].strip())))
        elif stripped.startswith("|"):
            flush()
            rows = []
            while i < len(lines) and lines[i].strip().startswith("|"):
                cells = _row(lines[i])
                if not all(re.fullmatch(r":?-{3,}:?", c) for c in cells):
                    rows.append(tuple(pieces(c) for c in cells))
                i += 1
            blocks.append(Table(tuple(rows)))
            continue
        elif re.fullmatch(r"\*\*.+\*\*", stripped):
            flush()
            blocks.append(Paragraph(pieces(stripped), "group"))
        elif stripped.startswith(">"):
            flush()
            blocks.append(Paragraph(pieces(stripped.lstrip("> ").strip()), "note"))
        elif line.startswith(("- ", "* ")) or (line.startswith("  ") and blocks and not para):
            flush()
            level = 1 if line.startswith("  ") else 0
            body = stripped[2:] if not level else stripped
            m = re.fullmatch(r"`([^`]*)`:?", body)
            if m:  # a step: a formula of its own
                vector = level == 0 and bool(_VECTOR_LEAD.search(last_text)) and (
                    not blocks or isinstance(blocks[-1], Paragraph))
                nodes = parse(m.group(1), vector=vector)
                if body.endswith(":"):  # a figure's equation, its sides below it
                    nodes = (*nodes, Run(":", "punct"))
                blocks.append(Formula(nodes, level, m.group(1)))
            else:
                blocks.append(Paragraph(pieces(body), "aside" if level else "item", level))
        else:
            para.append(line)
        i += 1
    flush()
    return Document(title, tuple(blocks), lang)


_NUMBER = re.compile(r"\d+(?:[.,]\d+)?")


def numbers(text: str) -> list[str]:
    """The numbers of a text in their order, an exponent written as a power of ten
    (``3,8e−14`` is 3,8, 10 and 14, as the documents set it).

    >>> numbers("F = 1,5·2 = 3,8e−14 Н")
    ['1,5', '2', '3,8', '10', '14']
    """
    text = re.sub(r"(\d)e([−-]?)(\d)", r"\1·10 \2\3", text)
    return _NUMBER.findall(text)
