"""``plans project``: a course project's files in one folder, all made before the first
is written, each written atomically, and a summary of them."""

import io
import json

import pytest

pytest.importorskip("ezdxf")
pytest.importorskip("docx")
pytest.importorskip("fpdf")
pytest.importorskip("cairosvg")

import docx
import ezdxf

from plans.cli import project
from tests.support import run


@pytest.fixture(scope="module")
def variant3(tmp_path_factory):
    """(folder, exit status, stdout, stderr) of ``plans project --variant 3``."""
    import contextlib

    from plans.cli import main

    folder = tmp_path_factory.mktemp("p") / "v3"
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        code = main(["project", "--variant", "3", "-o", str(folder), "--title-block", "student=Иванов"])
    return folder, code, out.getvalue(), err.getvalue()


def test_a_project_holds_the_sheet_the_note_and_the_results(variant3):
    folder, code, _, err = variant3
    assert code == 0, err
    assert sorted(p.name for p in folder.iterdir()) == sorted(name for name, _ in project.FILES)
    assert (folder / "sheet-1.svg").read_text(encoding="utf-8").startswith("<?xml")
    assert (folder / "sheet-1.pdf").read_bytes().startswith(b"%PDF")
    assert not ezdxf.readfile(folder / "sheet-1.dxf").audit().has_errors
    assert (folder / "note.pdf").read_bytes().startswith(b"%PDF")
    d = docx.Document(folder / "note.docx")
    first = d.sections[0].first_page_footer.tables[0]
    assert "Иванов" in {c.text for row in first.rows for c in row.cells}
    results = json.loads((folder / "results.json").read_text(encoding="utf-8"))
    forces = json.loads((folder / "forces.json").read_text(encoding="utf-8"))
    assert {"points", "segments", "cycle"} <= set(results) and "balancing" in forces


def test_the_note_is_the_sheets_and_goes_on_with_the_forces(variant3):
    folder = variant3[0]
    md = (folder / "note.md").read_text(encoding="utf-8")
    assert md.startswith("# Кинематический анализ") and "## 6. Силовой анализ" in md
    results = json.loads((folder / "results.json").read_text(encoding="utf-8"))
    # the note's scale factors are the sheet's, and the JSON's
    mu_v = results["scales"]["mu_v"]
    assert f"= {str(mu_v).replace('.', ',')} (м/с)/мм" in md


def test_the_summary_lists_every_file(variant3):
    folder, _, out, _ = variant3
    lines = out.splitlines()
    assert lines[0].startswith("plans project: Шарнирный четырёхзвенник, вариант 3: 8 files")
    for name, what in project.FILES:
        assert any(str(folder / name) in line and what in line for line in lines[1:]), name


def test_a_file_or_a_missing_parent_is_refused_before_anything_is_computed(tmp_path, capsys):
    f = tmp_path / "x.md"
    f.write_text("", encoding="utf-8")
    code, _, err = run(capsys, "project", "--variant", "3", "-o", f)
    assert code == 2 and "is a file" in err
    code, _, err = run(capsys, "project", "--variant", "3", "-o", tmp_path / "no" / "p")
    assert code == 2 and "does not exist" in err
    assert [p.name for p in tmp_path.iterdir()] == ["x.md"]


def test_a_missing_export_is_said_with_its_pip_command(tmp_path, capsys, monkeypatch):
    import sys

    monkeypatch.setitem(sys.modules, "fpdf", None)  # as if fpdf2 were not installed
    code, _, err = run(capsys, "project", "--variant", "3", "-o", tmp_path / "p")
    assert code == 2 and "pip install 'vector-plans[pdf]'" in err
    assert not (tmp_path / "p").exists()


def test_a_file_without_loads_has_no_forces_json(tmp_path, capsys):
    src = tmp_path / "m.toml"
    with open("samples/fourbar.toml", encoding="utf-8") as fh:
        text = fh.read()
    cut = text.find("[loads]")
    src.write_text(text[:cut] if cut >= 0 else text, encoding="utf-8")
    code, out, err = run(capsys, "project", src, "-o", tmp_path / "p", "--format", "A2", "--lang", "en",
                         "--no-frame")
    assert code == 0, err
    names = {p.name for p in (tmp_path / "p").iterdir()}
    assert "forces.json" not in names and "note.docx" in names
    assert "7 files" in out
    d = docx.Document(tmp_path / "p" / "note.docx")
    assert not d.sections[0].footer.tables
