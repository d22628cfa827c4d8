"""The command line against hostile input and as a teacher uses it (issues 22 and 23):
each case one located line and exit 2, or a correct result; no traceback, no exit 3, no
NaN, no partial set of outputs, no temporary file left, no link written through, no
control character of a user's text on the terminal.
"""

from __future__ import annotations

import json
import os
import signal
import subprocess
import sys
import time
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
from support import run

from drawing import export
from plans.cli.check_report import json_text
from plans.cli.output import terminal

ROOT = Path(__file__).resolve().parent.parent
SAMPLES = ROOT / "samples"
CHECK = (SAMPLES / "check_press.toml").read_text("utf-8")


def one_line(err: str, command: str) -> str:
    """The one stderr line of a refused run: no traceback, no internal error."""
    lines = err.splitlines()
    assert len(lines) == 1, err
    assert lines[0].startswith(f"plans {command}: ") and "internal error" not in err, err
    assert "Traceback" not in err
    return lines[0]


@pytest.fixture
def meas(tmp_path):
    """A copy of the press's measurement file beside a copy of its mechanism file, to be
    made hostile: ``meas(old, new)`` writes it with ``old`` replaced by ``new``."""
    (tmp_path / "press.toml").write_text((SAMPLES / "press.toml").read_text("utf-8"), "utf-8")

    def write(old: str = "", new: str = "", name: str = "m.toml") -> Path:
        text = CHECK.replace(old, new) if old else CHECK
        path = tmp_path / name
        path.write_text(text, "utf-8")
        return path

    return write


# --- numbers a measurement file gives --------------------------------------------------


@pytest.mark.parametrize("mu", ["5e-324", "1e-160", "1e-200", "1e7"])
def test_a_scale_factor_out_of_range_is_located_as_a_mechanism_files(capsys, meas, mu):
    """μ of 1e-160 had overflowed the misfit (exit 3); 5e-324 had given Infinity in the
    JSON and every item "ok", exit 0."""
    path = meas("mu_v = 0.05", f"mu_v = {mu}")
    code, out, err = run(capsys, "check", path, "--json")
    assert code == 2 and out == ""
    line = one_line(err, "check")
    assert "line 36: scales.mu_v:" in line
    assert ("too small: at least 1e-09 (m/s)/mm" in line) or ("at most 1e+06" in line)


def test_a_force_scale_out_of_range_is_located(capsys, tmp_path):
    (tmp_path / "fourbar.toml").write_text((SAMPLES / "fourbar.toml").read_text("utf-8"), "utf-8")
    text = (SAMPLES / "check_forces.toml").read_text("utf-8")
    path = tmp_path / "f.toml"
    path.write_text(text.replace("[forces]\n", "[forces]\nmu_F = 1e-300\n"), "utf-8")
    code, _, err = run(capsys, "check", path)
    assert code == 2, err
    assert "mu_F: 1e-300 is too small: at least 1e-09 N/mm" in err and "internal error" not in err


def test_check_json_has_no_nan_infinity_or_negative_zero():
    text = json_text({"deviation": -0.0, "percent": float("nan"), "computed": [float("inf"), 2.0]})
    data = json.loads(text, parse_constant=lambda c: pytest.fail(f"{c} in the JSON"))
    assert data == {"deviation": 0.0, "percent": None, "computed": [None, 2.0]}
    assert "-0.0" not in text


# --- the user's text on the terminal and in the pictures ------------------------------


HOSTILE_TITLE = "\\u0001\\u001b[31mRED\\u202eevil\\nplans check: all within tolerance <b>x</b>"


def test_control_characters_of_a_title_and_a_name_reach_no_terminal_and_no_svg(capsys, meas, tmp_path):
    a = meas('title = "Worked', f'title = "{HOSTILE_TITLE} Worked')
    b = meas('title = "Worked', f'title = "{HOSTILE_TITLE} Worked', name="b\x01\x1b[2J\nplans check: x.toml")
    code, out, err = run(capsys, "check", a)
    assert code == 1 and "\x1b" not in out and "\x01" not in out and "\u202e" not in out
    assert not any(line.startswith("plans check: all") for line in out.splitlines())
    pics = tmp_path / "pics"
    code, out, err = run(capsys, "check", a, b, "--svg", f"{pics}/", "--png", f"{pics}/")
    assert code == 1, err
    for text in (out, err):
        assert "\x1b" not in text and "\x01" not in text and "\u202e" not in text
    assert not any(line.startswith("plans check: x.toml") for line in out.splitlines() + err.splitlines())
    svgs = sorted(pics.glob("*.svg"))
    assert len(svgs) == 2 and len(list(pics.glob("*.png"))) == 2
    for svg in svgs:
        ET.parse(svg)  # the one writer cleans what XML cannot carry


def test_terminal_is_the_one_path_for_a_users_text():
    assert terminal("a\x1b[2J\nb\u202ec\x85") == "a\\x1b[2J\\nb\\u202ec\\x85"
    assert len(terminal("x" * 120_000)) == 1000


def test_a_long_argument_is_echoed_cut(capsys):
    code, _, err = run(capsys, "sheet", "--variant", "3", "--plans", "1" * 5000, "-o", os.devnull)
    line = one_line(err, "sheet")
    assert code == 2 and "is not a list of position numbers" in line and len(line) < 200
    code, _, err = run(capsys, "solve", "--variant", "3", "--nope", "x" * 120_000)
    assert code == 2 and len(err) < 1200 and "Traceback" not in err


# --- tracebacks that were ----------------------------------------------------------------


def test_a_batch_folder_that_cannot_be_made_is_one_line(capsys, tmp_path):
    (tmp_path / "afile").write_text("x")
    code, _, err = run(capsys, "sheet", "--variant", "all", "-o", f"{tmp_path}/afile/sub/")
    assert code == 2
    assert "cannot make the folder: Not a directory" in one_line(err, "sheet")


def test_a_file_name_too_long_and_a_device_named_in_a_measurement_file(capsys, meas):
    path = meas('mechanism = "press.toml"', f'mechanism = "{"a" * 300}.toml"')
    code, _, err = run(capsys, "check", path)
    assert code == 2 and "cannot read the file: File name too long" in one_line(err, "check")
    path = meas('mechanism = "press.toml"', 'mechanism = "/dev/zero"')
    code, _, err = run(capsys, "check", path)
    line = one_line(err, "check")
    assert code == 2 and "is a device or a pipe, not a file" in line and "no such file" not in line


def test_an_interrupt_waits_until_the_render_returns():
    """A signal that arrives while cairosvg renders is acted on after it: inside its C
    callbacks a KeyboardInterrupt had printed a traceback and ended with exit 1."""
    done = []
    # Python's own Ctrl-C handler, as the command runs with it (a test runner's worker
    # process may have SIGINT ignored)
    before = signal.signal(signal.SIGINT, signal.default_int_handler)
    try:
        with pytest.raises(KeyboardInterrupt):
            with export.signals_held():
                os.kill(os.getpid(), signal.SIGINT)
                time.sleep(0.05)
                done.append(True)  # not interrupted halfway
    finally:
        signal.signal(signal.SIGINT, before)
    assert done == [True]


# --- every output or none -----------------------------------------------------------------


@pytest.mark.parametrize("sig", [signal.SIGTERM, signal.SIGHUP])
def test_a_stopped_cycle_leaves_no_temporary_file(tmp_path, sig):
    out = tmp_path / "c.json"
    p = subprocess.Popen([sys.executable, "-m", "plans", "cycle", "--variant", "3", "--positions",
                          "100000", "--json", "-o", str(out)], cwd=ROOT,
                         env={**os.environ, "PYTHONPATH": str(ROOT)},
                         stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    deadline = time.monotonic() + 120
    while time.monotonic() < deadline and p.poll() is None:
        if any(f.name.endswith(".tmp") for f in tmp_path.iterdir()):
            break  # writing: its temporary is there
        time.sleep(0.02)
    p.send_signal(sig)
    _, err = p.communicate(timeout=60)
    assert p.returncode == 128 + sig, err
    assert list(tmp_path.iterdir()) == [], "a temporary file or a partial output is left"
    assert "stopped by" in err and "Traceback" not in err


def test_a_failed_output_leaves_every_old_output(capsys, tmp_path, monkeypatch):
    """A full disk as the PNG is written: the SVG written before it had replaced the old
    one, and the old PNG stood beside it."""
    import errno

    from plans.cli import sheet

    svg, png = tmp_path / "s.svg", tmp_path / "s.png"
    svg.write_text("OLD SVG")
    png.write_bytes(b"OLD PNG")

    def full(svg_text, dpi=150, scale=1.0):
        def chunks():
            yield b"\x89PNG"
            raise OSError(errno.ENOSPC, "No space left on device")
        return chunks()

    monkeypatch.setattr(sheet.export, "png_bytes", full)
    code, _, err = run(capsys, "sheet", "--variant", "3", "-o", svg, "--png", png)
    assert code == 2 and "No space left on device" in err
    assert svg.read_text() == "OLD SVG" and png.read_bytes() == b"OLD PNG"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["s.png", "s.svg"]


def test_links_are_replaced_not_written_through(capsys, tmp_path, meas):
    real, link = tmp_path / "theirs.txt", tmp_path / "out.txt"
    real.write_text("someone else's")
    link.symlink_to(real)
    code, _, _ = run(capsys, "solve", "--variant", "3", "-o", link)
    assert code == 0 and not link.is_symlink() and link.read_text().startswith("Four-bar")
    assert real.read_text() == "someone else's"
    pics = tmp_path / "pics"
    pics.mkdir()
    planted = pics / "m.svg"
    planted.symlink_to(real)
    path = meas()
    code, _, err = run(capsys, "check", path, meas(name="n.toml"), "--svg", pics)
    assert code in (0, 1), err
    assert not planted.is_symlink() and real.read_text() == "someone else's"


# --- bounds --------------------------------------------------------------------------------


def test_a_raster_over_the_budget_is_refused_before_anything_is_drawn(capsys, tmp_path):
    png = tmp_path / "a0.png"
    t = time.monotonic()
    code, _, err = run(capsys, "sheet", "--variant", "3", "--format", "A0", "--dpi", "600",
                       "--png", png, "-o", tmp_path / "a0.svg")
    line = one_line(err, "sheet")
    assert code == 2 and "558 million pixels" in line and "--dpi 254 or less" in line
    assert list(tmp_path.iterdir()) == [] and time.monotonic() - t < 5
    assert export.largest_dpi(*export.raster_size(1189, 841, 25.4)) == 254


def test_title_block_entries_are_judged_in_one_line(capsys):
    code, _, err = run(capsys, "sheet", "--variant", "3", "--title-block", "student=" + "Ы" * 2449,
                       "-o", os.devnull)
    assert code == 2 and "does not fit" in one_line(err, "sheet")
    code, _, err = run(capsys, "sheet", "--variant", "3", "--title-block", "literal=ABCD", "-o", os.devnull)
    assert code == 2 and "does not fit field 4" in one_line(err, "sheet")
    code, _, err = run(capsys, "sheet", "--variant", "3", "--title-block", "studnet=Ivanov", "-o", os.devnull)
    assert code == 2 and 'did you mean "student"?' in one_line(err, "sheet")


# --- issue 23, 8–10: the command line as a teacher uses it -------------------------------


def test_check_svg_folder_with_one_file_as_with_several(capsys, meas, tmp_path):
    path = meas()
    code, out, err = run(capsys, "check", path, "--svg", f"{tmp_path}/over/")
    assert code in (0, 1), err
    assert (tmp_path / "over" / "m.svg").is_file() and out.startswith("Check of a hand-drawn plan")
    (tmp_path / "old").mkdir()
    code, _, err = run(capsys, "check", path, "--svg", tmp_path / "old")
    assert code in (0, 1) and (tmp_path / "old" / "m.svg").is_file()


def test_a_file_given_twice_is_checked_and_counted_once(capsys, meas):
    path = meas()
    code, out, err = run(capsys, "check", path, path, str(path.parent / "." / path.name))
    assert code in (0, 1)
    assert "is given twice" in err and "checked and counted once" in err
    assert "1 file:" in out or "1 file" in out.splitlines()[0]


def test_a_bare_tolerance_is_refused_with_what_to_write(capsys, meas):
    code, out, err = run(capsys, "check", meas(), "--tolerance", "5")
    line = one_line(err, "check")
    assert code == 2 and out == "" and 'has no unit: write "5%"' in line and '"5mm"' in line


def test_the_bench_needs_its_extra_and_writes_no_chart_unasked(capsys, tmp_path, monkeypatch):
    import importlib.util

    real = importlib.util.find_spec
    monkeypatch.setattr(importlib.util, "find_spec",
                        lambda name, *a: None if name == "sympy" else real(name, *a))
    code, _, err = run(capsys, "bench", "--quick")
    line = one_line(err, "bench")
    assert code == 2 and "pip install '.[bench]'" in line
    monkeypatch.undo()
    monkeypatch.chdir(tmp_path)
    code, _, err = run(capsys, "bench", "--quick", "--scene", "tangent", "--methods", "vectorized")
    assert code == 0, err
    assert list(tmp_path.iterdir()) == []  # no bench.svg unasked


def test_the_bench_lists_only_the_scenes_it_has(capsys, monkeypatch, tmp_path):
    """Installed, the samples are not there: --help had listed press as a default and
    --scene press then said "unknown"."""
    from plans.model import scenes

    monkeypatch.setattr(scenes, "SAMPLES", tmp_path)  # as an installed package has it
    code, out, _ = run(capsys, "bench", "--help")
    assert code == 0
    text = " ".join(out.split())
    assert "default: press" not in text and "source checkout" in text
    code, _, err = run(capsys, "bench", "--quick", "--scene", "press")
    assert code == 2 and "samples of the source checkout" in one_line(err, "bench")


def test_no_svg_on_a_terminal(capsys, monkeypatch):
    monkeypatch.setattr(sys.stdout, "isatty", lambda: True)
    code, out, err = run(capsys, "sheet", "--variant", "3")
    assert code == 2 and out == "" and "-o FILE.svg" in one_line(err, "sheet")


def test_variant_all_takes_picture_options_as_folders(capsys, tmp_path):
    table = tmp_path / "t.toml"
    table.write_text((ROOT / "plans" / "data" / "table2.toml").read_text("utf-8"), "utf-8")
    code, _, err = run(capsys, "sheet", "--variant", "all", "-o", f"{tmp_path}/s/",
                       "--note", tmp_path / "x.md")
    assert code == 2 and "looks like a file name" in one_line(err, "sheet")
    assert not (tmp_path / "s").exists()


def test_solve_speaks_russian(capsys):
    code, out, _ = run(capsys, "solve", SAMPLES / "press.toml", "--lang", "ru")
    assert code == 0
    assert out.splitlines()[0] == "Кулисный механизм пресса для брикетирования"
    assert "План скоростей (полюс p, μ = 0,05 (м/с)/мм)" in out
    assert "ход точки D: H = 0,5114 м" in out
    code, en, _ = run(capsys, "solve", SAMPLES / "press.toml")
    assert "Velocity plan (pole p, μ = 0.05 (m/s)/mm)" in en


def test_an_english_sheet_carries_no_cyrillic_designation(capsys, tmp_path):
    en, ru = tmp_path / "en.svg", tmp_path / "ru.svg"
    assert run(capsys, "sheet", "--variant", "3", "--lang", "en", "-o", en)[0] == 0
    assert run(capsys, "sheet", "--variant", "3", "-o", ru)[0] == 0
    assert "AM.01.03" in en.read_text("utf-8") and "ПМ.01.03" not in en.read_text("utf-8")
    assert "ПМ.01.03" in ru.read_text("utf-8")
