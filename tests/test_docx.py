"""The explanatory note as a document (drawing/document.py, formula.py, docx.py,
notepdf.py; ``plans report --docx --pdf --frame``): its formulas read as formulas, the
DOCX opened by python-docx (and by LibreOffice where it is installed), every number the
Markdown's, the PDF's pages and fonts, the frame and its title blocks."""

import io
import re
import shutil
import subprocess
import zipfile
from functools import cache

import pytest

docx = pytest.importorskip("docx")
fpdf = pytest.importorskip("fpdf")

from drawing import notepdf  # noqa: E402
from drawing.document import Formula, Heading, Paragraph, numbers, parse_note  # noqa: E402
from drawing.docx import to_docx  # noqa: E402
from drawing.formula import Frac, Radical, Script, Vector, parse, plain, show, split_lines  # noqa: E402
from drawing.sheet.forms import FORM2, FORM2A  # noqa: E402
from drawing.sheet.frame import TitleBlock  # noqa: E402
from plans.cli.report import markdown  # noqa: E402
from plans.model import load, variants  # noqa: E402
from tests.support import run  # noqa: E402

M = "{http://schemas.openxmlformats.org/officeDocument/2006/math}"
W = "{http://schemas.openxmlformats.org/wordprocessingml/2006/main}"
TB = TitleBlock(name="Кулисный механизм пресса", designation="ТММ.КП.00.01 ПЗ", developer="Иванов",
                organisation="МГТУ", group="ТМ-21")


class _Args:
    angle = None
    file = None
    variant = None

    def __init__(self, lang):
        self.lang = lang


@cache
def note(source: str, lang: str) -> str:
    """The note's Markdown, as ``plans report`` writes it."""
    mech = (variants.read_table(None).variant(int(source[1:])) if source.startswith("v")
            else load(f"samples/{source}.toml"))
    return markdown(_Args(lang), mech)[0]


NOTES = [("press", "ru"), ("press", "en"), ("fourbar", "en"), ("v3", "ru"), ("v4", "en")]


# ------------------------------------------------------------------------- formulas

def test_a_spaced_slash_divides_terms_a_tight_one_atoms():
    assert show(parse("pc = pa3·BC / BA3")) == "pc = frac(pa_{3} · BC, BA_{3})"
    assert show(parse("Δn1 = (190,85 − 190,99)/190,99·100 %")) == \
        'Δn_{1} = frac(190,85 − 190,99, 190,99) · 100 "%"'
    assert show(parse("u = (z2/z1)·(z4/z3)")) == "u = (frac(z_{2}, z_{1})) · (frac(z_{4}, z_{3}))"


def test_a_unit_stays_a_unit_and_words_stay_words():
    assert show(parse("μv = V_A / pa = 3 / 60 = 0,05 (м/с)/мм")).endswith('0,05 "(м/с)/мм"')
    assert show(parse("ε2 = 1.2757 / 0.15 = 8.504 rad/s², counter-clockwise")).endswith(
        '8.504 "rad/s²" , "counter-clockwise"')
    assert show(parse("m1 = 0.25 kg (given)")) == 'm_{1} = 0.25 "kg" ("given")'


def test_names_indices_and_powers():
    (a,) = parse("a^n_A3B")
    assert isinstance(a, Script) and plain(a.sub) == "A3B" and plain(a.sup) == "n"
    (mu,) = parse("μF")
    assert plain(mu.base) == "μ" and plain(mu.sub) == "F"
    assert show(parse("n1a3")) == "n_{1}a_{3}"
    assert show(parse("V_DC² / l_DC")) == "frac(V_{DC}², l_{DC})"
    assert show(parse("δ = 3,8e−14 %")) == 'δ = 3,8 · 10^{−14} "%"'
    assert isinstance(parse("√(u/1,2)")[0], Radical)


def test_a_vector_equation_has_its_arrows_and_a_guide_none():
    nodes = parse("V_D = V_C + V_DC; V_D ∥ x-x", vector=True)
    assert sum(isinstance(n, Script) and isinstance(n.base[0], Vector) for n in nodes) == 4
    assert show(nodes).endswith("∥ x-x")


def test_a_long_numerator_stays_on_the_line_and_a_long_step_breaks():
    text = "F = (" + " + ".join(f"{k},5·{k}" for k in range(1, 12)) + ") / 60 = 7 N"
    nodes = parse(text)
    assert not any(isinstance(n, Frac) for n in nodes)
    lines = split_lines(nodes, 40)
    assert len(lines) > 2 and plain(tuple(n for line in lines for n in line)) == plain(nodes)
    assert all(len(plain(line)) <= 40 for line in lines)


def test_every_character_of_every_step_reaches_the_formula():
    for source, lang in NOTES:
        for code in re.findall(r"`([^`]*)`", note(source, lang)):
            flat = re.sub(r"[\s\[\]()|]", "", plain(parse(code)))
            src = re.sub(r"[\s\[\]()|/_^]", "", re.sub(r"e([−-]?\d)", r"·10\1", code))
            # in their order, but for a name's index and power, which OMML writes index first
            assert sorted(flat.replace("/", "")) == sorted(src), code


# ------------------------------------------------------------------------- the document

def test_sections_are_numbered_as_gost_numbers_them():
    doc = parse_note(note("press", "ru"), "ru")
    heads = [(b.number, b.pieces[0].text) for b in doc.blocks if isinstance(b, Heading)]
    assert heads[:5] == [("1", "Структурный анализ механизма"), ("2", "План положений механизма"),
                         ("3", "План скоростей механизма"), ("4", "План ускорений механизма"),
                         ("5", "Силовой анализ")]
    assert ("5.1", "Массы и силы тяжести звеньев") in heads
    assert doc.title.startswith("Кинематический анализ")
    kinds = {type(b).__name__ for b in doc.blocks}
    assert {"Heading", "Paragraph", "Formula"} <= kinds
    assert any(isinstance(b, Paragraph) and b.kind == "group" for b in doc.blocks)


def test_a_table_of_the_markdown_is_a_table():
    md = "# T\n\n## 1. Initial data\n\n| quantity | value |\n|---|---|\n| `l_OA` | 0,15 m |\n"
    doc = parse_note(md, "en")
    (table,) = [b for b in doc.blocks if type(b).__name__ == "Table"]
    assert len(table.rows) == 2 and table.rows[1][0][0].kind == "math"
    data = to_docx(doc)
    d = docx.Document(io.BytesIO(data))
    (t,) = d.tables
    assert [c.text for c in t.rows[0].cells] == ["quantity", "value"]


@cache
def docx_of(source: str, lang: str, frame: bool = False) -> bytes:
    return to_docx(parse_note(note(source, lang), lang), frame, TB)


def _docx_text(data: bytes) -> list[tuple[str, str]]:
    """(paragraph style, text) of each body paragraph, Word's and math's characters
    alike, a space between two runs."""
    d = docx.Document(io.BytesIO(data))
    out = []
    for p in d.paragraphs:
        texts = [el.text or "" for el in p._p.iter() if el.tag in (f"{W}t", f"{M}t")]
        out.append((p.style.name, " ".join(texts)))
    return out


@pytest.mark.parametrize(("source", "lang"), NOTES)
def test_every_number_in_the_docx_is_the_markdowns(source, lang):
    md = note(source, lang)
    body = re.sub(r"^#+ (\d+\. )?", "", md, flags=re.MULTILINE)  # the sections' own numbers
    paragraphs = _docx_text(docx_of(source, lang))
    text = []
    for style, t in paragraphs:
        if style.startswith("Heading"):
            t = t.split(" ", 1)[1]  # the section's number, which the document gives
        text.append(t)
    assert numbers(" ".join(text)) == numbers(body)


def test_the_docx_opens_with_python_docx_and_holds_formulas():
    data = docx_of("press", "ru")
    d = docx.Document(io.BytesIO(data))
    assert d.sections[0].page_width.mm == pytest.approx(210, abs=0.05)
    assert d.sections[0].left_margin.mm == pytest.approx(30, abs=0.05)
    heads = [p.text for p in d.paragraphs if p.style.name == "Heading 1"]
    assert heads[0] == "1 Структурный анализ механизма"
    xml = d.element.xml
    assert xml.count("<m:f>") > 50 and "<m:acc>" in xml and "<m:sSub>" in xml and "<m:rad>" in xml
    assert "`" not in "".join(p.text for p in d.paragraphs)  # no code spans left
    assert d.core_properties.title.startswith("Кинематический анализ")


def test_the_same_note_gives_the_same_bytes():
    note_ = parse_note(note("press", "en"), "en")
    assert to_docx(note_) == to_docx(note_)
    assert notepdf.to_pdf(note_) == notepdf.to_pdf(note_)


def test_the_frame_puts_form_2_on_the_first_page_and_2a_on_the_others():
    data = docx_of("press", "ru", frame=True)
    d = docx.Document(io.BytesIO(data))
    section = d.sections[0]
    assert section.different_first_page_header_footer
    (first,) = section.first_page_footer.tables
    (other,) = section.footer.tables
    assert (len(first.rows), len(first.columns)) == (len(FORM2.rows), len(FORM2.cols))
    assert (len(other.rows), len(other.columns)) == (len(FORM2A.rows), len(FORM2A.cols))
    first_text = {c.text for row in first.rows for c in row.cells}
    assert {"ТММ.КП.00.01 ПЗ", "Кулисный механизм пресса", "Иванов", "Разраб.", "Лит.", "Листов",
            "МГТУ, гр. ТМ-21", "У"} <= first_text
    assert "ТММ.КП.00.01 ПЗ" in {c.text for row in other.rows for c in row.cells}
    xml = section._sectPr.xml
    assert "pgBorders" in xml and 'w:offsetFrom="text"' in xml
    with zipfile.ZipFile(io.BytesIO(data)) as z:
        footers = "".join(z.read(n).decode() for n in z.namelist() if "footer" in n)
    assert "NUMPAGES" in footers and "PAGE" in footers
    assert section.left_margin.mm == pytest.approx(25, abs=0.05)  # 5 mm inside the frame


def test_form_lines_are_main_but_the_rows_of_changes_and_signers():
    lines = FORM2.lines()
    thin = [ln for ln in lines if ln[4]]
    assert all(y0 == y1 and x1 <= 65 for x0, y0, x1, y1, _ in thin if y0 == y1)
    assert (0.0, 5.0, 7.0, 5.0, True) in lines and (0.0, 10.0, 7.0, 10.0, False) in lines
    assert max(x1 for _, _, x1, _, _ in lines) == 185 and max(y1 for _, _, _, y1, _ in lines) == 40


# ------------------------------------------------------------------------------ the PDF

def test_the_pdf_embeds_its_fonts_and_draws_a_page_per_page():
    data = notepdf.to_pdf(parse_note(note("press", "ru"), "ru"), True, TB)
    assert data.startswith(b"%PDF")
    assert data.count(b"/FontFile2") >= 2  # STIX regular and italic, embedded
    pages = len(re.findall(rb"/Type /Page\b", data))
    assert 5 <= pages <= 20


@pytest.mark.skipif(not shutil.which("pdftoppm"), reason="pdftoppm (poppler-utils) not installed")
def test_the_pdfs_pages_render_with_the_frame_where_gost_puts_it(tmp_path):
    import numpy as np
    from PIL import Image

    path = tmp_path / "note.pdf"
    path.write_bytes(notepdf.to_pdf(parse_note(note("v3", "ru"), "ru"), True, TB))
    subprocess.run(["pdftoppm", "-r", "50", "-png", str(path), str(tmp_path / "p")], check=True, timeout=120)
    pngs = sorted(tmp_path.glob("p-*.png"))
    assert len(pngs) >= 3
    mm = 25.4 / 50
    for k, png in enumerate(pngs):
        with Image.open(png) as im:
            ink = np.asarray(im.convert("L")) < 128
        cols = ink.sum(axis=0)
        rows = ink.sum(axis=1)
        # the frame's left side 20 mm from the edge, its bottom 5 mm from the foot
        assert cols[round(20 / mm) - 1: round(20 / mm) + 2].max() > 0.8 * ink.shape[0] * 0.9
        foot = ink.shape[0] - round(5 / mm)
        assert rows[foot - 2: foot + 2].max() > 0.8 * (185 / mm)
        # text between the frame's sides, nothing in the margins outside it
        assert not ink[:, : round(19 / mm)].any()
        block = 40 if k == 0 else 15
        top = ink.shape[0] - round((5 + block) / mm)
        assert rows[top - 2: top + 2].max() > 0.8 * (185 / mm)  # the title block's top edge


# ------------------------------------------------------------------------ LibreOffice

SOFFICE = shutil.which("soffice") or shutil.which("libreoffice")


@pytest.mark.skipif(not SOFFICE, reason="LibreOffice (Debian's libreoffice-writer) not installed")
def test_libreoffice_opens_the_docx_and_converts_it_to_pdf(tmp_path):
    path = tmp_path / "note.docx"
    path.write_bytes(docx_of("press", "ru", frame=True))
    profile = tmp_path / "profile"
    subprocess.run([SOFFICE, f"-env:UserInstallation=file://{profile}", "--headless",
                    "--convert-to", "pdf", "--outdir", str(tmp_path), str(path)],
                   check=True, capture_output=True, timeout=300)
    pdf = (tmp_path / "note.pdf").read_bytes()
    assert pdf.startswith(b"%PDF") and len(re.findall(rb"/Type\s*/Page\b", pdf)) >= 5
    if shutil.which("pdftotext"):
        out = subprocess.run(["pdftotext", str(tmp_path / "note.pdf"), "-"], capture_output=True,
                             text=True, check=True).stdout
        assert "Структурный анализ механизма" in out and "ТММ.КП.00.01 ПЗ" in out
        assert "57,482" in out and "1637" in out  # numbers of the formulas, as formulas


# --------------------------------------------------------------------------- the command

def test_report_writes_the_docx_and_the_pdf(tmp_path, capsys):
    d, p = tmp_path / "n.docx", tmp_path / "n.pdf"
    code, out, err = run(capsys, "report", "samples/press.toml", "--lang", "ru", "--docx", d, "--pdf", p,
                         "--frame", "--title-block", "student=Петров", "group=ТМ-22")
    assert code == 0, err
    assert out == ""  # the Markdown only where -o asks for it
    doc = docx.Document(d)
    first = doc.sections[0].first_page_footer.tables[0]
    assert {"Петров", "ТММ.КП.00.01 ПЗ"} <= {c.text for row in first.rows for c in row.cells}
    assert p.read_bytes().startswith(b"%PDF")


def test_report_with_o_writes_the_markdown_as_well(tmp_path, capsys):
    md, d = tmp_path / "n.md", tmp_path / "n.docx"
    code, _, err = run(capsys, "report", "--variant", "3", "-o", md, "--docx", d)
    assert code == 0, err
    assert md.read_text(encoding="utf-8") == note("v3", "en") and d.is_file()


def test_report_refuses_a_document_of_another_name(tmp_path, capsys):
    code, _, err = run(capsys, "report", "samples/press.toml", "--docx", tmp_path / "n.pdf")
    assert code == 2 and "--docx" in err and "must end in .docx" in err
    code, _, err = run(capsys, "report", "samples/press.toml", "--pdf", "-")
    assert code == 2 and "not stdout" in err
    code, _, err = run(capsys, "report", "samples/press.toml", "--pdf", tmp_path / "a.pdf", "--docx",
                       tmp_path / "a.pdf")
    assert code == 2
    assert not list(tmp_path.iterdir())


def test_formula_blocks_carry_their_source():
    doc = parse_note(note("press", "en"), "en")
    steps = [b for b in doc.blocks if isinstance(b, Formula)]
    assert steps and all(b.source for b in steps)
