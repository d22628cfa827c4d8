"""``plans check A.toml B.toml …``: a class's files, one summary table, a row per file.

The files are built from the exact plans of variant 1, as tests/test_check.py builds
them: exact (all within tolerance), the velocity plan drawn 1.25 times too large (the
mistake named), pc and pe swapped (slips), every third segment 40 % long (no single
mistake), and a file with a negative μv (bad input).
"""

from __future__ import annotations

import json
import os
from pathlib import Path

import pytest
from support import run, variant_exact

from plans import fmt
from plans.check import verdict as ck
from plans.fmt import cut_start

MU = {"mu_l": 0.0025, "mu_v": 0.01, "mu_a": 0.2}
VELOCITY = ["pb", "ps1", "pc", "pe", "ps2", "ps3", "bc", "dc"]


@pytest.fixture
def klass(tmp_path):
    """Five students' files of variant 1, by what is in them."""
    _, segs, write = variant_exact(tmp_path, 1, MU)
    out = {}

    def save(name, s, title=None, text=None):
        body = text if text is not None else write(s).read_text(encoding="utf-8")
        if title:
            body = f'title = "{title}"\n' + body
        path = out[name] = tmp_path / f"{name}.toml"
        path.write_text(body, encoding="utf-8")

    save("exact", segs, "Ivanov I. I.")
    save("scale", {k: x * (1.25 if k in VELOCITY else 1) for k, x in segs.items()}, "Petrov P. P.")
    swapped = dict(segs)
    swapped["pc"], swapped["pe"] = segs["pe"], segs["pc"]
    save("swapped", swapped)
    save("messy", {k: x * (1.4 if i % 3 == 0 else 1) for i, (k, x) in enumerate(segs.items())})
    save("bad", None, "Sidorov S. S.",
         text=write(segs).read_text(encoding="utf-8").replace("mu_v = 0.01", "mu_v = -1"))
    (tmp_path / "v1.toml").unlink()
    return out


def rows(out: str) -> dict[str, str]:
    """The table's rows by the file's stem."""
    out_rows = {}
    for line in out.splitlines():
        first = line.split()[0] if line.strip() else ""
        if first.endswith(".toml"):
            out_rows[first.rsplit("/", 1)[-1].removesuffix(".toml")] = line
    return out_rows


def test_several_files_one_table_with_known_verdicts(klass, capsys):
    code, out, err = run(capsys, "check", *klass.values())
    assert code == 2 and err == (f"plans check: {klass['bad']}: line 5: scales.mu_v: must be "
                                 "positive, got -1\n")
    lines = out.splitlines()
    assert lines[0] == "Check of hand-drawn plans: 5 files"
    assert lines[1] == "Tolerance: the larger of 1 mm and 5 %"
    assert lines[3].split() == ["file", "title", "mechanism", "verdict", "diagnosis"]
    got = rows(out)
    assert list(got) == ["exact", "scale", "swapped", "messy", "bad"]
    assert got["exact"].endswith("Ivanov I. I.   variant 1, φ1 = 50°  all 18 items within tolerance")
    assert "Petrov P. P." in got["scale"] and "8 of 18 beyond tolerance" in got["scale"]
    assert got["scale"].endswith("the velocity plan is drawn 1.25 times too large for the stated "
                                 "μv: its segments fit μv = 0.008 (m/s)/mm")
    assert got["swapped"].endswith("2 of 18 beyond tolerance       slips: pc and pe swapped")
    assert got["messy"].endswith("beyond tolerance       no single mistake")
    assert got["bad"].endswith("not checked                    line 5: scales.mu_v: must be "
                               "positive, got -1")
    assert "Sidorov S. S." in got["bad"]  # whose file it is, though it cannot be checked
    assert lines[-1] == ("Overall: 5 files: 1 within tolerance, 3 beyond tolerance, 1 not "
                         "checked.")


def test_each_row_agrees_with_the_files_own_check(klass):
    """The table is read off the same check as ``plans check FILE``: the verdicts and the
    mistake named are the library's."""
    res = {k: ck.check(ck.load(p)) for k, p in klass.items() if k != "bad"}
    assert res["exact"].ok
    assert res["scale"].diagnosis.best.mistake.kind == "scale"
    assert res["swapped"].slips_only
    assert res["messy"].diagnosis.best is None and not res["messy"].slips_only


def test_in_russian_with_decimal_commas(klass, capsys):
    code, out, _ = run(capsys, "check", *klass.values(), "--lang", "ru")
    assert code == 2
    lines = out.splitlines()
    assert lines[0] == "Проверка планов, построенных вручную: 5 файлов"
    assert lines[1] == "Допуск: большее из 1 мм и 5 %"
    assert lines[3].split() == ["файл", "заголовок", "механизм", "вывод", "диагноз"]
    got = rows(out)
    assert got["exact"].endswith("вариант 1, φ1 = 50°  все 18 величин в допуске")
    assert got["scale"].endswith("план скоростей в 1,25 раза крупнее (при указанном μv): его "
                                 "отрезки соответствуют μv = 0,008 (м/с)/мм")
    assert "8 из 18 вне допуска" in got["scale"]
    assert got["swapped"].endswith("ошибки измерения или записи: pc и pe перепутаны")
    assert got["messy"].endswith("ни одна отдельная ошибка не объясняет")
    assert "не проверен " in got["bad"]
    assert lines[-1] == "Итог: 5 файлов: в допуске 1, вне допуска 3, не проверено 1."


@pytest.mark.parametrize("names, code", [
    (["exact", "exact"], 0),
    (["exact", "scale"], 1),
    (["swapped", "exact"], 1),
    (["exact", "bad"], 2),
    (["bad", "scale", "exact"], 2),
])
def test_the_exit_status_is_the_worst_of_the_files(klass, capsys, names, code):
    """0 all within tolerance, 1 one beyond, 2 one not checked (bad input), whichever
    order; a bad file stops none of the others. A file named twice is one row."""
    got, out, _ = run(capsys, "check", *(klass[n] for n in names))
    assert got == code
    rows = sum(line.split()[0].endswith(".toml") for line in out.splitlines() if line.strip())
    assert rows == len(set(names))


def test_a_file_with_several_problems_says_the_first_in_its_row_and_all_on_stderr(tmp_path, klass, capsys):
    bad = tmp_path / "two.toml"
    bad.write_text("variant = 1\n[scales]\nmu_v = -1\nmu_a = 0\n[segments]\npb = 5\n", encoding="utf-8")
    code, _, single = run(capsys, "check", bad)
    assert code == 2 and len(single.splitlines()) >= 2
    code, out, err = run(capsys, "check", klass["exact"], bad)
    assert code == 2 and err == single
    first = single.splitlines()[0].removeprefix(f"plans check: {bad}: ")
    more = len(single.splitlines()) - 1
    assert rows(out)["two"].endswith(f"  {first} (and {more} more: see stderr)")
    assert "not checked" in rows(out)["two"]


def test_a_missing_file_and_a_mechanism_file_are_rows_too(tmp_path, klass, capsys):
    from pathlib import Path

    press = Path(__file__).resolve().parents[1] / "samples" / "press.toml"
    code, out, err = run(capsys, "check", klass["exact"], tmp_path / "nobody.toml", press)
    assert code == 2
    got = rows(out)
    assert "not checked" in got["nobody"] and "not checked" in got["press"]
    assert "a mechanism file, not a measurement file" in got["press"]
    assert len(err.splitlines()) == 2


def test_json_is_a_list_of_the_single_files_objects(klass, capsys):
    """One object per file, in order, each the one ``plans check FILE --json`` prints
    (the shared solver changes nothing); a file not checked: its name, ok null and its
    error's lines."""
    names = ["exact", "scale", "bad", "swapped"]
    code, out, _ = run(capsys, "check", *(klass[n] for n in names), "--json", "--lang", "ru")
    assert code == 2
    got = json.loads(out)
    assert isinstance(got, list) and [o["file"] for o in got] == [str(klass[n]) for n in names]
    for n, obj in zip(names, got, strict=True):
        if n == "bad":
            continue
        c, one, _ = run(capsys, "check", klass[n], "--json", "--lang", "ru")
        assert obj == json.loads(one) and c == (0 if n == "exact" else 1)
    assert got[2] == {"file": str(klass["bad"]), "ok": None, "internal": False,
                      "error": [f"{klass['bad']}: line 5: scales.mu_v: must be positive, got -1"]}


def test_one_file_is_checked_as_ever(klass, capsys):
    """A single file prints its full report, not a table of one row."""
    code, out, _ = run(capsys, "check", klass["scale"])
    assert code == 1 and out.startswith(f"Check of a hand-drawn plan: {klass['scale']}\n")


def test_tolerance_for_all_and_a_files_own(klass, capsys, tmp_path):
    code, out, _ = run(capsys, "check", klass["exact"], klass["messy"], "--tolerance", "80%")
    assert code == 0 and out.splitlines()[1] == "Tolerance: the larger of 1 mm and 80 %"
    own = tmp_path / "own.toml"
    own.write_text('tolerance = "50%"\n' + klass["messy"].read_text(encoding="utf-8"), encoding="utf-8")
    code, out, _ = run(capsys, "check", klass["exact"], own, klass["scale"])
    assert code == 1
    assert rows(out)["own"].endswith("all 18 items within tolerance (tolerance the larger of 1 mm and 50 %)")
    code, out, err = run(capsys, "check", klass["exact"], klass["scale"], "--tolerance", "-5%")
    assert code == 2 and out == "" and err.startswith("plans check: command line: --tolerance:")


def test_the_table_goes_to_a_file_with_o(klass, capsys, tmp_path):
    report = tmp_path / "week.txt"
    code, out, _ = run(capsys, "check", klass["exact"], klass["scale"], "-o", report)
    assert code == 1 and out == ""
    assert report.read_text(encoding="utf-8").startswith("Check of hand-drawn plans: 2 files\n")
    code, _, err = run(capsys, "check", klass["exact"], klass["scale"], "-o", klass["exact"])
    assert code == 2 and "is the input file" in err


def test_pictures_of_several_files_go_into_a_folder(klass, capsys, tmp_path):
    """--svg DIR/: DIR/STEM.svg for each file checked; a file not checked draws none and
    leaves an old picture of its name alone."""
    pics = tmp_path / "pics"
    pics.mkdir()
    old = pics / "bad.svg"
    old.write_text("last week's", encoding="utf-8")
    code, _, _ = run(capsys, "check", klass["exact"], klass["scale"], klass["bad"], "--svg", f"{pics}/")
    assert code == 2
    assert sorted(p.name for p in pics.iterdir()) == ["bad.svg", "exact.svg", "scale.svg"]
    assert old.read_text(encoding="utf-8") == "last week's"
    assert (pics / "scale.svg").read_text(encoding="utf-8").lstrip().startswith("<?xml")
    made = tmp_path / "new" / "svg"  # a folder not there yet is made, as sheet -o DIR/ does
    code, _, _ = run(capsys, "check", klass["exact"], klass["scale"], "--svg", made)
    assert code == 1 and sorted(os.listdir(made)) == ["exact.svg", "scale.svg"]
    assert not [p for p in made.iterdir() if p.name.startswith(".")]  # no temporary left


@pytest.mark.parametrize("opt, value, expect", [
    ("--svg", "{d}/week.svg", "--svg {d}/week.svg: looks like a file name: with several "
                              "measurement files give a folder, e.g. --svg pictures/"),
    ("--svg", "{f}", "--svg {f}: is not a folder: with several measurement files give a "
                     "folder, e.g. --svg pictures/"),
    ("--svg", "-", "--svg '-': with several measurement files give a folder, e.g. --svg pictures/"),
])
def test_a_picture_option_that_is_not_a_folder_is_refused_in_one_line(klass, capsys, tmp_path,
                                                                      opt, value, expect):
    value = value.format(d=tmp_path, f=klass["exact"])
    before = {p: p.read_bytes() for p in tmp_path.iterdir() if p.is_file()}
    code, out, err = run(capsys, "check", klass["exact"], klass["scale"], opt, value)
    assert code == 2 and out == ""
    assert err == f"plans check: command line: {expect.format(d=tmp_path, f=klass['exact'])}\n"
    assert {p: p.read_bytes() for p in tmp_path.iterdir() if p.is_file()} == before


def test_two_files_of_one_name_would_draw_one_picture(klass, capsys, tmp_path):
    other = tmp_path / "b"
    other.mkdir()
    twin = other / "exact.toml"
    twin.write_text(klass["exact"].read_text(encoding="utf-8"), encoding="utf-8")
    code, out, err = run(capsys, "check", klass["exact"], twin, "--svg", tmp_path / "pics")
    assert code == 2 and out == ""
    assert err == (f"plans check: command line: {klass['exact']} and {twin} would both be drawn "
                   "as exact.svg: check them in two runs\n")
    assert not (tmp_path / "pics").exists()
    code, out, _ = run(capsys, "check", klass["exact"], twin)  # without pictures: two rows
    # the path as the table writes it: cut at its start where it is long (a deep tmp folder)
    assert code == 0 and list(rows(out)) == ["exact"] and f"  {cut_start(str(twin), 80)}  " in out


def test_solvers_are_shared_by_the_files_of_one_mechanism(klass):
    """Thirty files of one variant at one angle solve it once: one solver, whose cycle
    (for the angles the table writes) is analysed once."""
    from plans.check.measured import Solvers

    solvers = Solvers()
    meas = [ck.load(klass[n], solvers) for n in ("exact", "scale", "swapped", "messy")]
    assert len(solvers.known) == 1
    assert len({id(m.solution.solver) for m in meas}) == 1
    alone = ck.load(klass["scale"])
    assert ck.check(alone).diagnosis == ck.check(meas[1]).diagnosis


def test_svg_and_png_of_several_files_may_share_a_folder(klass, capsys, tmp_path):
    pytest.importorskip("cairosvg")
    pics = tmp_path / "pics"
    code, _, err = run(capsys, "check", klass["exact"], klass["swapped"], "--svg", pics, "--png", pics)
    assert code == 1 and err == ""
    assert sorted(os.listdir(pics)) == ["exact.png", "exact.svg", "swapped.png", "swapped.svg"]
    assert (pics / "swapped.png").read_bytes().startswith(b"\x89PNG")


def test_an_internal_error_in_one_file_is_its_row_and_exit_3(klass, capsys, monkeypatch):
    real = ck.check

    def check(meas, tol=None, **kw):
        if meas.source.endswith("scale.toml"):
            raise RuntimeError("boom")
        return real(meas, tol, **kw)

    monkeypatch.setattr(ck, "check", check)
    code, out, err = run(capsys, "check", klass["exact"], klass["scale"], klass["bad"])
    assert code == 3
    assert rows(out)["scale"].endswith("internal error                 RuntimeError: boom (rerun "
                                       "with --debug for the traceback)")
    assert "Petrov P. P." in rows(out)["scale"]
    assert rows(out)["exact"].endswith("all 18 items within tolerance")
    assert (f"plans check: {klass['scale']}: internal error: RuntimeError: boom (rerun with "
            "--debug for the traceback)") in err.splitlines()
    assert out.splitlines()[-1].endswith("1 not checked, 1 with an internal error.")
    with pytest.raises(RuntimeError):
        run(capsys, "check", klass["exact"], klass["scale"], "--debug")


def test_a_picture_folder_that_cannot_be_made_is_refused_in_one_line(klass, capsys, tmp_path):
    """--svg under a file (or where no folder can be made) is a problem of the command
    line, exit 2 in one line before anything is checked, as a picture folder that is a
    file is: it was each file's "internal error" (exit 3), its check lost."""
    where = f"{klass['exact']}/pics/"
    code, out, err = run(capsys, "check", klass["exact"], klass["scale"], "--svg", where)
    assert code == 2 and out == ""
    assert err.startswith(f"plans check: command line: --svg {where}: cannot make the folder")
    assert len(err.splitlines()) == 1
    code, out, err = run(capsys, "check", klass["exact"], klass["scale"], "--svg", tmp_path / "p",
                         "--tolerance", "-5%")
    assert code == 2 and not (tmp_path / "p").exists()  # nothing made for a run refused



def test_the_table_never_goes_over_a_mechanism_file_a_row_names(klass, capsys, tmp_path):
    """-o naming the mechanism file of a measurement file is refused before anything is
    checked, as for a single file, even where that file cannot be checked (its mechanism
    does not close at its angle): the table was written over the mechanism file."""
    from pathlib import Path

    press = tmp_path / "press.toml"
    press.write_bytes((Path(__file__).resolve().parents[1] / "samples" / "press.toml").read_bytes())
    before = press.read_bytes()
    nobody = tmp_path / "nobody.toml"
    nobody.write_text('mechanism = "press.toml"\nangle_deg = "x"\n[scales]\nmu_v = 0.05\n'
                      "[segments]\npa3 = 55\n", encoding="utf-8")
    pics = tmp_path / "pics"
    for files in ([nobody, klass["exact"]], [klass["exact"], nobody]):
        code, out, err = run(capsys, "check", *files, "-o", press, "--svg", pics)
        assert code == 2 and out == "" and press.read_bytes() == before
        assert err == (f"plans check: command line: -o '{press}' is the input file '{press}': "
                       "the tool never writes into its inputs; choose another output name\n")
        assert not pics.exists()  # no picture of a file checked before the refusal


def test_the_table_is_not_written_over_a_picture_of_the_batch(klass, capsys, tmp_path):
    """-o pics/exact.svg with --svg pics/: the table replaced exact's picture (exit 1);
    one file refuses -o and --svg of one name, and so does the batch, in one line."""
    pics = tmp_path / "pics"
    pics.mkdir()
    code, out, err = run(capsys, "check", klass["exact"], klass["scale"], "--svg", pics,
                         "-o", pics / "exact.svg")
    assert code == 2 and out == "" and os.listdir(pics) == []
    assert err == (f"plans check: command line: -o and --svg are both '{pics / 'exact.svg'}': "
                   "give each output its own file\n")


def titled(tmp_path, capsys, a: str, b: str) -> dict[str, str]:
    """The rows of two exact files of variant 1 titled ``a`` and ``b``, each checked to
    have its mechanism's column start where the other's does (in a terminal's columns)."""
    _, segs, write = variant_exact(tmp_path, 1, MU)
    body = write(segs).read_text(encoding="utf-8")
    files = []
    for name, title in (("a", a), ("b", b)):
        files.append(tmp_path / f"{name}.toml")
        files[-1].write_text(f'title = "{title}"\n' + body, encoding="utf-8")
    code, out, _ = run(capsys, "check", *map(str, files))
    assert code == 0
    got = rows(out)
    starts = {k: fmt.width(line[: line.index("variant 1")]) for k, line in got.items()}
    assert starts["a"] == starts["b"], out
    return got


def test_a_title_in_chinese_keeps_its_row_in_line(tmp_path, capsys):
    """A Chinese character takes two columns of a terminal: counted as one, a student
    named 张伟 pushed the rest of the row one column out per character."""
    titled(tmp_path, capsys, "Ivanov I. I.", "张伟，机械原理课程设计")


def test_an_alternative_is_not_joined_to_a_mistakes_second_clause(tmp_path, capsys):
    """Right plans, ω3 written clockwise: "ω3 written with the wrong sense; the plans are
    right", or the crank's V_A laid off the wrong way round (every ω reversed). The row
    had read "…; the plans are right or ω1 (V_A) drawn with the wrong sense", as if the
    plans being right were one of the two explanations."""
    body = ('mechanism = "{}"\n[scales]\nmu_l = 0.01\nmu_v = 0.05\nmu_a = 1.0\n[segments]\n'
            'pa3 = 55.4\naa3 = 23\npc = 72.3\n[values]\nomega3 = "4,82 по ч.с."\n')
    sample = os.path.join(os.path.dirname(__file__), "..", "samples", "press.toml")
    for name in ("a", "b"):
        (tmp_path / f"{name}.toml").write_text(body.format(sample.replace("\\", "/")), encoding="utf-8")
    for lang, words in (("en", "ω3 written with the wrong sense; the plans are right; or ω1 (V_A) drawn "
                                "with the wrong sense"),
                        ("ru", "угловая скорость ω3 записана с обратным направлением; планы построены "
                                "верно; или ω1 (V_A) взята с обратным направлением")):
        code, out, _ = run(capsys, "check", tmp_path / "a.toml", tmp_path / "b.toml", "--lang", lang)
        assert code == 1
        assert words in rows(out)["a"], rows(out)["a"]


def test_a_mechanism_file_up_a_folder_is_named_without_its_dots(tmp_path, capsys):
    """A student's file in students/ naming ../press.toml had its row read
    "students/../press.toml, φ1 = 30°"."""
    press = os.path.join(os.path.dirname(__file__), "..", "samples", "press.toml")
    (tmp_path / "press.toml").write_bytes(Path(press).read_bytes())
    (tmp_path / "students").mkdir()
    files = []
    for name in ("a", "b"):
        files.append(tmp_path / "students" / f"{name}.toml")
        files[-1].write_text('mechanism = "../press.toml"\n[scales]\nmu_l = 0.01\nmu_v = 0.05\n'
                             'mu_a = 1.0\n[segments]\npa3 = 55.4\n', encoding="utf-8")
    code, out, _ = run(capsys, "check", *map(str, files))
    assert code == 0
    row = rows(out)["a"]
    assert f"{tmp_path / 'press.toml'}, φ1 = 30°" in row and "/../" not in row, row


def test_a_long_chinese_title_is_cut_to_the_columns_of_the_title_column(tmp_path, capsys):
    """A title is cut at TITLE_WIDTH (40): counted in characters, thirty Chinese ones
    passed whole and took sixty columns of the table, half as wide again as the column
    any other title is cut to."""
    from plans.cli.check_batch import TITLE_WIDTH

    got = titled(tmp_path, capsys, "x" * 60, "机械原理课程设计" * 4)
    cell = got["b"].split("  ")[2]  # the file, then the title
    assert cell.startswith("机械原理") and cell.endswith("…")
    assert TITLE_WIDTH - 1 <= fmt.width(cell) <= TITLE_WIDTH, cell
