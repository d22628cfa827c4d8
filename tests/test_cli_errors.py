"""The command line on bad input and failures: exit status, one line per problem, no
traceback, and no file lost (never an input written, never a half-written output)."""

from __future__ import annotations

import argparse
import json
import os
import re
import stat
import subprocess
import sys
from pathlib import Path

import pytest
from support import expectations, run
from test_errors import PARALLEL_RPP

from plans.cli import common as cli
from plans.cli import main
from plans.cli.main import COMMANDS, build_parser

ROOT = Path(__file__).resolve().parent.parent
CORPUS = ROOT / "tests" / "corpus"
PRESS = ROOT / "samples" / "press.toml"




def assert_clean_failure(err: str, command: str = "solve") -> list[str]:
    lines = err.splitlines()
    assert lines, "no message"
    assert "Traceback" not in err and "internal error" not in err
    assert all(line.startswith(f"plans {command}: ") for line in lines), err
    return lines


# ---------------------------------------------------------------------------------------
# every malformed input: exit 2, its messages, nothing written
# ---------------------------------------------------------------------------------------


@pytest.mark.parametrize("path", sorted(CORPUS.glob("*.toml")), ids=lambda p: p.stem)
def test_corpus_through_the_cli(capsys, tmp_path, path):
    out = tmp_path / "out.txt"
    code, stdout, err = run(capsys, "solve", path, "-o", out)
    assert code == 2 and stdout == ""
    lines = assert_clean_failure(err)
    want = expectations(path)
    assert len(lines) == len(want), err
    for line, expected in zip(lines, want, strict=True):
        assert line.startswith(f"plans solve: {path}: ") and expected in line
    assert not out.exists() and list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("path", sorted((CORPUS / "cams").glob("*.toml")), ids=lambda p: p.stem)
def test_cam_corpus_through_the_cli(capsys, tmp_path, path):
    """Each broken cam file (or a cam whose profile cannot be made: an undercut, a flat face
    on a hollow, a roller at a velocity jump): its problems, one located line each, exit 2,
    neither the text nor the sheet nor the note written."""
    sheet, note = tmp_path / "cam.svg", tmp_path / "cam.md"
    code, stdout, err = run(capsys, "cam", path, "-o", sheet, "--note", note)
    assert code == 2 and stdout == ""
    lines = assert_clean_failure(err, "cam")
    want = expectations(path)
    assert len(lines) == len(want), err
    for line, expected in zip(lines, want, strict=True):
        assert line.startswith(f"plans cam: {path}: ") and expected in line
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize("path", sorted((CORPUS / "tables").glob("*.toml")), ids=lambda p: p.stem)
def test_table_corpus_through_the_cli(capsys, path):
    """Each broken table asked for the row it has (or 0): the problems of that row, or of
    the table as a whole, are the error, one line each."""
    import re

    row = re.search(r"^n = (\d+)$", path.read_text("utf-8"), re.M)
    code, stdout, err = run(capsys, "solve", "--variant", row.group(1) if row else "0", "--table", path)
    assert code == 2 and stdout == ""
    lines = assert_clean_failure(err)
    want = expectations(path)
    assert len(lines) == len(want), err
    for line, expected in zip(lines, want, strict=True):
        assert line.startswith(f"plans solve: {path}: ") and expected in line


LOCKED = """name = "Locked"
[frame]
A = [0, 0]
D = [-0.2, 0]
[driver]
angle_deg = 40
omega = 10
[links.1]
axis = ["A", "B"]
points = { B = 0.05 }
[links.2]
axis = ["B", "C"]
points = { C = 0.2 }
[links.3]
axis = ["D", "C"]
points = { C = 0.15, B = 0.1 }
"""

YOKE_GUIDES_PARALLEL = 'name = "Yoke"\n' + PARALLEL_RPP  # guides parallel at every angle


@pytest.mark.parametrize("command", ["solve", "cycle", "report"])
@pytest.mark.parametrize(("text", "expected"), [
    (LOCKED, "W = 3n − 2p5 − p4 = 3·3 − 2·5 − 0 = −1: the chain is over-constrained"),
    (YOKE_GUIDES_PARALLEL, "group 2–3 (RPP): the guide DE of link 3 is parallel to the guide "
                           "x-x it moves along (a sliding link's x-axis runs along its guide), "
                           "so the yoke's position is not fixed at any crank angle"),
], ids=["locked", "yoke"])
def test_a_chain_that_cannot_move_is_reported_with_its_file(capsys, tmp_path, command, text,
                                                            expected):
    """A file that reads well but whose chain is not a mechanism of one crank: one line
    naming the file, exit 2, nothing written."""
    path = tmp_path / "chain.toml"
    path.write_text(text, encoding="utf-8")
    out = tmp_path / "out"
    code, stdout, err = run(capsys, command, path, "-o", out)
    assert code == 2 and stdout == ""
    (line,) = assert_clean_failure(err, command)
    assert line.startswith(f"plans {command}: {path}: {expected}")
    assert not out.exists()


@pytest.mark.parametrize("command", ["report", "cycle", "sheet"])
@pytest.mark.parametrize("name", ["many_problems", "toml_truncated", "garbage_bytes",
                                  "unknown_point_in_axis"])
def test_other_commands_report_bad_files_the_same_way(capsys, tmp_path, command, name):
    assert command in build_parser().commands
    path = CORPUS / f"{name}.toml"
    code, _, err = run(capsys, command, path, "-o", tmp_path / "out")
    assert code == 2
    lines = assert_clean_failure(err, command)
    assert len(lines) == len(expectations(path))
    for line, expected in zip(lines, expectations(path), strict=True):
        assert line.startswith(f"plans {command}: {path}: ") and expected in line
    assert list(tmp_path.iterdir()) == []


# ---------------------------------------------------------------------------------------
# never into an input; an existing output replaced only by a complete one
# ---------------------------------------------------------------------------------------


@pytest.fixture
def press(tmp_path):
    path = tmp_path / "press.toml"
    path.write_bytes(PRESS.read_bytes())
    return path


def _forbid_computing(monkeypatch):
    import plans.kinematics.solver

    def boom(*a, **k):
        raise AssertionError("computed before refusing the output")

    monkeypatch.setattr(plans.kinematics, "Solver", boom)


@pytest.mark.parametrize("how", ["same", "relative", "symlink", "hardlink"])
def test_output_onto_the_input_is_refused_before_computing(capsys, monkeypatch, tmp_path, press, how):
    _forbid_computing(monkeypatch)
    target = press
    if how == "relative":
        monkeypatch.chdir(tmp_path)
        target = Path("..") / tmp_path.name / "press.toml"
    elif how == "symlink":
        target = tmp_path / "link.toml"
        target.symlink_to(press)
    elif how == "hardlink":
        target = tmp_path / "hard.toml"
        os.link(press, target)
    before = press.read_bytes()
    code, out, err = run(capsys, "solve", press, "-o", target)
    assert code == 2 and out == ""
    (line,) = assert_clean_failure(err)
    assert "is the input file" in line and "never writes into its inputs" in line
    assert press.read_bytes() == before


def test_output_onto_the_variant_table_is_refused(capsys, monkeypatch, tmp_path):
    _forbid_computing(monkeypatch)
    table = tmp_path / "t.toml"
    table.write_text((ROOT / "plans" / "data" / "table2.toml").read_text("utf-8"), "utf-8")
    before = table.read_bytes()
    code, _, err = run(capsys, "solve", "--variant", "3", "--table", table, "-o", table)
    assert code == 2 and "is the input file" in err
    assert table.read_bytes() == before


def test_check_never_writes_over_the_variant_table_it_read(capsys, tmp_path):
    """A measurement file of a variant of a course's table: -o onto the table is refused,
    and the table is left as it was."""
    table = tmp_path / "t.toml"
    table.write_text((ROOT / "plans" / "data" / "table2.toml").read_text("utf-8"), "utf-8")
    meas = tmp_path / "m.toml"
    meas.write_text('variant = 3\ntable = "t.toml"\n[scales]\nmu_v = 0.01\n'
                    "[segments]\npb = 100\n", "utf-8")
    before = table.read_bytes()
    code, out, err = run(capsys, "check", meas, "-o", table)
    assert code == 2 and out == ""
    (line,) = assert_clean_failure(err, "check")
    assert "-o" in line and "is the input file" in line
    assert table.read_bytes() == before


def test_write_output_itself_refuses_the_inputs(tmp_path, press):
    with pytest.raises(cli.InputError, match="is the input file"):
        cli.write_output(str(press), "x", inputs=[str(press)])
    files = cli.RunFiles()  # a run's files: what it claims it never writes
    files.claim(argparse.Namespace(), [press])
    with pytest.raises(cli.InputError, match="is the input file"):
        files.write(str(press), "x")
    assert press.read_text("utf-8") != "x"


def test_a_failing_run_leaves_the_existing_output_alone(capsys, tmp_path):
    out = tmp_path / "out.txt"
    out.write_text("previous result\n")
    code, _, _ = run(capsys, "solve", CORPUS / "many_problems.toml", "-o", out)
    assert code == 2
    assert out.read_text() == "previous result\n"
    code, _, _ = run(capsys, "solve", ROOT / "samples" / "fourbar.toml", "--angle", "180", "-o", out)
    assert code == 2  # an unsolvable scene, after the file was read
    assert out.read_text() == "previous result\n"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out.txt"]


def test_success_replaces_the_output_whole_and_keeps_its_mode(capsys, tmp_path, press):
    out = tmp_path / "out.txt"
    out.write_text("x" * 100_000)
    out.chmod(0o640)
    code, stdout, _ = run(capsys, "solve", press, "-o", out)
    assert code == 0 and stdout == ""
    text = out.read_text("utf-8")
    assert text.startswith("Slotted-link press") and "x" * 10 not in text
    assert stat.S_IMODE(out.stat().st_mode) == 0o640
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out.txt", "press.toml"]


def test_a_new_output_gets_the_usual_mode_not_the_temporary_files(capsys, tmp_path, press):
    umask = os.umask(0o022)
    try:
        code, _, _ = run(capsys, "solve", press, "-o", tmp_path / "new.txt")
    finally:
        os.umask(umask)
    assert code == 0
    assert stat.S_IMODE((tmp_path / "new.txt").stat().st_mode) == 0o644


@pytest.mark.parametrize("fail_in", ["replace", "fsync"])
def test_a_write_that_fails_midway_loses_nothing(capsys, monkeypatch, tmp_path, press, fail_in):
    out = tmp_path / "out.txt"
    out.write_text("previous result\n")

    def disk_full(*a, **k):
        raise OSError(28, "No space left on device")

    monkeypatch.setattr(os, fail_in, disk_full)
    code, _, err = run(capsys, "solve", press, "-o", out)
    assert code == 2
    (line,) = assert_clean_failure(err)
    assert line == f"plans solve: {out}: cannot write: No space left on device"
    assert out.read_text() == "previous result\n"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out.txt", "press.toml"]


def test_an_interrupted_write_loses_nothing(capsys, monkeypatch, tmp_path, press):
    out = tmp_path / "out.txt"
    out.write_text("previous result\n")

    def interrupt(*a, **k):
        raise KeyboardInterrupt

    monkeypatch.setattr(os, "fsync", interrupt)
    code, _, err = run(capsys, "solve", press, "-o", out)
    assert code == 130 and err == "plans solve: interrupted\n"
    assert out.read_text() == "previous result\n"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["out.txt", "press.toml"]


@pytest.mark.parametrize(
    ("target", "message"),
    [
        ("{tmp}", "{tmp}: is a folder: give a file name"),
        ("{tmp}/missing/out.txt", "{tmp}/missing/out.txt: the folder '{tmp}/missing' does not exist"),
    ],
    ids=["folder", "missing-folder"],
)
def test_outputs_that_cannot_be_files(capsys, tmp_path, press, target, message):
    target = target.format(tmp=tmp_path)
    code, _, err = run(capsys, "solve", press, "-o", target)
    assert code == 2
    assert assert_clean_failure(err) == [f"plans solve: {message.format(tmp=tmp_path)}"]


@pytest.mark.skipif(os.name != "posix" or os.geteuid() == 0, reason="needs a non-root POSIX user")
def test_an_unwritable_folder_is_bad_input(capsys, tmp_path, press):
    folder = tmp_path / "ro"
    folder.mkdir()
    folder.chmod(0o500)
    try:
        code, _, err = run(capsys, "solve", press, "-o", folder / "out.txt")
    finally:
        folder.chmod(0o700)
    assert code == 2 and "cannot write in the folder" in err


def test_a_folder_refusing_the_file_is_bad_input_even_as_root(capsys, tmp_path, press, monkeypatch):
    """The same path as above where the permission cannot be taken away (CI runs as root):
    the system refuses to create the file, as it does in a read-only folder."""
    import tempfile

    def refuse(*a, **k):
        raise PermissionError(13, "Permission denied")

    monkeypatch.setattr(tempfile, "mkstemp", refuse)
    target = tmp_path / "out.txt"
    code, out, err = run(capsys, "solve", press, "-o", target)
    assert code == 2 and out == ""
    (line,) = assert_clean_failure(err)
    assert "cannot write in the folder" in line and "Permission denied" in line
    assert not target.exists()


@pytest.mark.skipif(not Path("/dev/null").exists(), reason="no /dev/null")
def test_output_to_a_device_is_written_not_replaced(capsys, press):
    code, _, _ = run(capsys, "solve", press, "-o", "/dev/null")
    assert code == 0
    assert stat.S_ISCHR(os.stat("/dev/null").st_mode)


# ---------------------------------------------------------------------------------------
# hostile command-line values
# ---------------------------------------------------------------------------------------


@pytest.mark.parametrize("angle", ["inf", "-inf", "nan", "1e300"])
def test_absurd_angles(capsys, press, angle):
    code, _, err = run(capsys, "solve", press, f"--angle={angle}")
    assert code == 2
    (line,) = assert_clean_failure(err)
    assert f"argument --angle: '{angle}' is not a number from -1e+06 to 1e+06" in line


@pytest.mark.parametrize("value", ["x", "1.5", "9" * 5000, "1\n2", ""])
def test_bad_variant_numbers(capsys, value):
    code, _, err = run(capsys, "solve", "--variant", value)
    assert code == 2
    (line,) = assert_clean_failure(err)
    assert "is not a variant number" in line and len(line) < 200


def test_an_unknown_variant_lists_the_table(capsys):
    code, _, err = run(capsys, "solve", "--variant", "99")
    assert code == 2
    assert err == (
        "plans solve: Table 2 (built in): variant 99 is not in the table "
        "(it has 0, 1, 2, 3, 4, 5, 6, 7, 8, 9)\n"
    )


def test_neither_or_both_sources(capsys, press):
    for argv in (["solve"], ["solve", press, "--variant", "1"]):
        code, _, err = run(capsys, *argv)
        assert code == 2
        assert err == "plans solve: command line: give a mechanism FILE or --variant N (one of them)\n"


# ---------------------------------------------------------------------------------------
# internal errors and the documented exit status
# ---------------------------------------------------------------------------------------


def _break_solve(monkeypatch):
    import plans.cli.solve

    def broken(args):
        raise ZeroDivisionError("float division by zero")

    monkeypatch.setattr(plans.cli.solve, "run", broken)


def test_an_internal_error_is_one_line_and_exit_3(capsys, monkeypatch, press):
    _break_solve(monkeypatch)
    code, out, err = run(capsys, "solve", press)
    assert code == 3 and out == ""
    assert err == (
        "plans solve: internal error: ZeroDivisionError: float division by zero "
        "(rerun with --debug for the traceback)\n"
    )


def test_debug_shows_the_traceback(monkeypatch, press):
    _break_solve(monkeypatch)
    with pytest.raises(ZeroDivisionError):
        main(["--debug", "solve", str(press)])


@pytest.mark.parametrize("argv", [["--help"], ["solve", "--help"]])
def test_help_documents_the_exit_status(capsys, argv):
    """Each command's --help lists the statuses it can end with: exit 1 is the check's
    alone (every command's epilog had listed it)."""
    assert main(argv) == 0  # main returns argparse's code, it does not exit
    text = " ".join(capsys.readouterr().out.split())
    if argv == ["--help"]:
        assert ("exit status: 0 success, 1 a check found deviations (plans check only), 2 bad "
                "input or an unsolvable scene, 3 internal error (rerun with --debug for the "
                "traceback)") in text
    else:
        assert ("exit status: 0 success, 2 bad input or an unsolvable scene, 3 internal error "
                "(rerun with --debug for the traceback)") in text
        assert "1 a check" not in text


@pytest.mark.parametrize("command", [c for c in COMMANDS if c != "check"])
def test_only_the_check_lists_exit_1(capsys, command):
    assert main([command, "--help"]) == 0
    assert "1 a check found deviations" not in capsys.readouterr().out
    assert main(["check", "--help"]) == 0
    text = " ".join(capsys.readouterr().out.split())
    assert "1 a check found deviations" in text


def test_help_and_a_misspelt_command_still_name_every_command(capsys):
    """A run configures only the command it names; the others are still listed."""
    assert main(["--help"]) == 0
    out = capsys.readouterr().out
    for name, (_, help_text) in COMMANDS.items():
        assert re.search(rf"^ +{name} +{re.escape(help_text)}$", out, re.M), name
    assert main(["sovle", "x.toml"]) == 2
    err = capsys.readouterr().err
    assert err == ("plans: command line: argument COMMAND: invalid choice: 'sovle' (choose from "
                   + ", ".join(f"'{n}'" for n in COMMANDS) + ") (see plans --help)\n")


@pytest.mark.parametrize("module", ["plans.cli_not_built", "family_not_built.cli"])
def test_a_command_whose_module_is_not_there_is_left_out(capsys, tmp_path, monkeypatch, module):
    """A command family not built yet, a module or its whole package, is left out of the
    list; the other commands run as ever, whichever of them the run names."""
    monkeypatch.setitem(COMMANDS, "later", (module, "a command still to come"))
    target = tmp_path / "s.json"
    assert main(["solve", str(PRESS), "--json", "-o", str(target)]) == 0
    assert main(["--help"]) == 0
    assert "later" not in capsys.readouterr().out
    assert main(["later"]) == 2
    assert "invalid choice: 'later'" in capsys.readouterr().err
    assert "later" not in build_parser().commands


def test_the_readme_documents_the_exit_status():
    readme = (ROOT / "README.md").read_text("utf-8")
    for code in ("| 0 |", "| 1 |", "| 2 |", "| 3 |"):
        assert code in readme
    assert "--debug" in readme


# ---------------------------------------------------------------------------------------
# as a user runs it: a separate process, nothing but the message on stderr
# ---------------------------------------------------------------------------------------


def plans(*argv, cwd=None):
    env = dict(os.environ, PYTHONPATH=str(ROOT), PYTHONWARNINGS="default")
    return subprocess.run(
        [sys.executable, "-m", "plans", *map(str, argv)],
        capture_output=True, text=True, env=env, cwd=cwd, timeout=120,
    )


def test_subprocess_many_problems_exit_2_without_traceback():
    path = CORPUS / "many_problems.toml"
    proc = plans("solve", path)
    assert proc.returncode == 2 and proc.stdout == ""
    lines = proc.stderr.splitlines()
    assert len(lines) == len(expectations(path)) and "Traceback" not in proc.stderr
    assert all(line.startswith(f"plans solve: {path}: line ") for line in lines)


def test_subprocess_garbage_and_hostile_files(tmp_path):
    for name, data in (
        ("zeros.toml", b"\x00" * 5000),
        ("random.toml", bytes(range(256)) * 40),
        ("deep.toml", b"x = " + b"[" * 200_000 + b"]" * 200_000),
        ("digits.toml", b"x = " + b"7" * 100_000),
    ):
        path = tmp_path / name
        path.write_bytes(data)
        proc = plans("solve", path, "-o", tmp_path / "out.txt")
        assert proc.returncode == 2, proc.stderr
        assert "Traceback" not in proc.stderr and len(proc.stderr.splitlines()) == 1
    assert not (tmp_path / "out.txt").exists()


def test_subprocess_output_onto_input_and_success(tmp_path, press):
    before = press.read_bytes()
    proc = plans("solve", "press.toml", "-o", "./press.toml", cwd=tmp_path)
    assert proc.returncode == 2 and "never writes into its inputs" in proc.stderr
    assert press.read_bytes() == before
    proc = plans("solve", "press.toml", "-o", "plans.txt", cwd=tmp_path)
    assert proc.returncode == 0 and proc.stderr == ""
    assert (tmp_path / "plans.txt").read_text("utf-8").startswith("Slotted-link press")


def test_subprocess_internal_error_exit_3_without_traceback(press):
    script = (
        "import sys, plans.cli.solve as s, plans.cli as c\n"
        "def run(args): raise KeyError('boom')\n"
        "s.run = run\n"
        f"sys.exit(c.main(['solve', {str(press)!r}]))\n"
    )
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    proc = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, env=env,
                          timeout=120)
    assert proc.returncode == 3
    assert proc.stderr == ("plans solve: internal error: KeyError: 'boom' (rerun with --debug for "
                           "the traceback)\n")


# ---------------------------------------------------------------------------------------
# several outputs: all checked before any is written
# ---------------------------------------------------------------------------------------


@pytest.mark.parametrize("extra", [
    ["--png", "{d}/nodir/o.png"],                      # the PNG's folder is missing
    ["--png", "{d}/o.png", "--dpi", "-1"],            # a resolution cairo cannot render
    ["--png", "{d}/o.png", "--pdf", "{d}/nodir/o.pdf"],  # the last of three outputs is bad
    ["--png", "{d}/o.svg"],                            # the PNG would replace the SVG
    ["--note", "{d}/nodir/o.md"],                      # the note's folder is missing
    ["--note", "{d}/o.svg"],                           # the note would replace the SVG
])
def test_a_sheet_whose_png_or_pdf_would_fail_writes_nothing(capsys, tmp_path, extra):
    """The SVG used to be written first and then the PNG or PDF failed: the old SVG was
    lost. Every output is now checked before anything is computed or written."""
    svg, png = tmp_path / "o.svg", tmp_path / "o.png"
    svg.write_text("KEEP")
    png.write_bytes(b"KEEP")
    code, _, err = run(capsys, "sheet", PRESS, "-o", svg, *(a.format(d=tmp_path) for a in extra))
    assert code == 2 and len(err.splitlines()) == 1 and "Traceback" not in err, err
    assert err.startswith("plans sheet: ")
    assert svg.read_text() == "KEEP" and png.read_bytes() == b"KEEP"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["o.png", "o.svg"]


@pytest.mark.parametrize(("argv", "message"), [
    (["check", "{m}", "--svg", "-"], "-o and --svg are both stdout"),
    (["check", "{m}", "-o", "{d}/k.txt", "--svg", "{d}/k.txt"], "-o and --svg are both"),
    (["bench", "--quick", "-o", "{d}/t.txt", "--chart", "{d}/t.txt"], "-o and --chart are both"),
    (["bench", "--quick", "-o", "{d}/t.txt", "--chart", "{d}/nodir/c.svg"], "does not exist"),
])
def test_outputs_that_would_collide_or_fail_are_refused_first(capsys, tmp_path, argv, message):
    meas = ROOT / "samples" / "check_press.toml"
    code, _, err = run(capsys, *(a.format(m=meas, d=tmp_path) for a in argv))
    assert code == 2 and len(err.splitlines()) == 1 and message in err, err
    assert list(tmp_path.iterdir()) == []  # bench stopped before minutes of timing


@pytest.mark.parametrize(("argv", "message"), [
    (["solve", "{p}", "--angle", "abc"],
     "plans solve: command line: argument --angle: 'abc' is not a number from -1e+06 to 1e+06"),
    (["sheet", "{p}", "--format", "a2"],
     "plans sheet: command line: argument --format: invalid choice: 'a2'"),
    (["sheet", "{p}", "--dpi", "nan"],
     "plans sheet: command line: argument --dpi: 'nan' is not a number from 10 to 600"),
    (["sheet", "{p}", "--plans", "1,4,1"],
     "plans sheet: --plans: position 1 given twice in '1,4,1': each position's plans are drawn once"),
    (["bench", "--budget", "inf"],
     "plans bench: command line: argument --budget: 'inf' is not a number from 0 to 600"),
    (["bench", "--plan-max", "0"], "argument --plan-max: '0' is not a whole number from 1 to 10000000"),
    (["bench", "--methods", ","], "plans bench: command line: --methods: give at least one of"),
    (["solve", "{p}", "{p}"], "plans solve: command line: unrecognized arguments"),
])
def test_command_line_mistakes_are_one_line_and_exit_2(capsys, argv, message):
    code, _, err = run(capsys, *(a.format(p=PRESS) for a in argv))
    assert code == 2 and len(err.splitlines()) == 1 and message in err, err
    assert "usage:" not in err and "Traceback" not in err


def test_messages_give_the_crank_angle_as_the_file_measures_it(capsys, tmp_path):
    """Seed 001's four-bar measured from +y clockwise: --angle 270 is φ = 180° from +x,
    where BD is too long. The message said "φ1 = -90°" (from +x, unlabelled); it now
    gives the angle the user typed, and the convention it is in."""
    text = (ROOT / "samples" / "fourbar.toml").read_text("utf-8")
    text = text.replace("angle_deg = 40\n", 'angle_deg = 50\nfrom = "+y"\nmeasured = "cw"\n')
    path = tmp_path / "fourbar_y.toml"
    path.write_text(text, "utf-8")
    code, _, err = run(capsys, "solve", path, "--angle", "270")
    assert code == 2
    (line,) = assert_clean_failure(err)
    assert "cannot be assembled at φ1 = 270° (from +y, cw): needs BD within" in line, line
    code, out, err = run(capsys, "cycle", path, "--positions", "12")
    assert "φ1 = -" not in out + err


def test_near_a_dead_point_every_command_warns_in_its_language(capsys, tmp_path):
    """Seed 001's four-bar at 128.8046°, 0.03° short of where BD is too long: the plan's
    lines ⊥ CB and ⊥ CD meet at 0.03°. The sheet drew it silently; the Russian note and
    check gave the warning in English with a decimal point."""
    fourbar = ROOT / "samples" / "fourbar.toml"
    code, out, err = run(capsys, "report", fourbar, "--angle", "128.8046", "--lang", "ru")
    assert code == 0 and err.startswith("plans report: warning: group 2–3 (RRR) at φ1 = 128.805°")
    (line,) = [ln for ln in out.splitlines() if ln.startswith("> Предупреждение")]
    assert line.startswith("> Предупреждение: группа 2–3 (RRR) при φ1 = 128,805°: положение, "
                           "близкое к особому: прямые ⊥ CB и ⊥ CD пересекаются под углом 0,0")
    assert "." not in line and "near" not in line
    code, _, err = run(capsys, "sheet", fourbar, "--angle", "128.8046", "-o", tmp_path / "n.svg")
    assert code == 0 and len(err.splitlines()) == 1
    assert err.startswith(f"plans sheet: warning: {fourbar}: group 2–3 (RRR) at φ1 = 128.805°: "
                          "near-singular, the lines ⊥ CB and ⊥ CD meet at 0.0")


def test_a_check_near_a_dead_point_warns_on_stderr_and_in_its_json(capsys, tmp_path):
    """The check of a plan drawn 0.03° short of seed 001's dead point wrote its warning
    among the text report's lines only: with --json, or among several files, the
    near-singular position was checked without a word of it anywhere."""
    meas = tmp_path / "near.toml"
    meas.write_text(f'mechanism = {str(ROOT / "samples" / "fourbar.toml")!r}\n'
                    "angle_deg = 128.8046\n[scales]\nmu_v = 0.01\n[segments]\npb = 94\n",
                    "utf-8")
    head = "group 2–3 (RRR) at φ1 = 128.805°: near-singular, the lines ⊥ CB and ⊥ CD meet at 0.0"
    code, out, err = run(capsys, "check", meas, "--json")
    assert code == 0 and err.startswith(f"plans check: warning: {head}")
    assert [w[:len(head)] for w in json.loads(out)["warnings"]] == [head]
    code, out, err = run(capsys, "check", meas, "--json", "--lang", "ru")
    (w,) = json.loads(out)["warnings"]
    assert w.startswith("группа 2–3 (RRR) при φ1 = 128,805°: положение, близкое к особому")
    code, out, err = run(capsys, "check", meas, PRESS.parent / "check_press.toml")
    assert code == 1 and f"plans check: warning: {meas}: {head}" in err

@pytest.mark.parametrize("point", ["O", "A", "B", "C"])
def test_an_output_with_no_stroke_is_refused_not_replaced(capsys, tmp_path, point):
    """The press's output set to the fixed pivot O or the crank pin A has no stroke: solve,
    report, cycle and the sheet silently used D instead. The rocker's end C is a fine
    output (its swing); its fixed pivot B is not, and the message had offered one."""
    text = PRESS.read_text("utf-8").replace('output = "D"', f'output = "{point}"')
    path = tmp_path / "p.toml"
    path.write_text(text, "utf-8")
    code, out, err = run(capsys, "solve", path)
    if point == "C":  # C is a point of the rocker 3, hinged to the frame at B: its swing
        assert code == 0 and "swing of link 3" in out
        return
    (line,) = assert_clean_failure(err)
    assert code == 2 and f'output: "{point}" has no stroke or swing' in line
    assert line.endswith('(a link other than the crank hinged to the frame): here "D", "C" or "S3"')


def test_batch_output_that_looks_like_a_file_is_refused(capsys, tmp_path):
    code, _, err = run(capsys, "sheet", "--variant", "all", "-o", tmp_path / "b.svg")
    assert code == 2 and not (tmp_path / "b.svg").exists()
    assert err == (f"plans sheet: -o: {tmp_path / 'b.svg'} looks like a file name: with --variant "
                   "all give a folder, e.g. -o sheets/\n")


def test_a_date_in_place_of_a_number_is_quoted_as_the_file_wrote_it(capsys, tmp_path):
    path = tmp_path / "d.toml"
    path.write_text(PRESS.read_text("utf-8").replace("angle_deg = 30 ", "angle_deg = 1979-05-27 "), "utf-8")
    code, _, err = run(capsys, "solve", path)
    (line,) = assert_clean_failure(err)
    assert code == 2 and "the date or time 1979-05-27" in line and "datetime" not in line


@pytest.mark.skipif(not Path("/dev/full").exists(), reason="needs /dev/full (Linux)")
@pytest.mark.parametrize("buffered", [True, False])
def test_stdout_on_a_full_disk_is_bad_output_not_a_crash(buffered):
    """Buffered, as a user's stdout is: the text waited in the buffer until the
    interpreter's exit, which printed "Exception ignored" and exited 120. This
    machine's PYTHONUNBUFFERED=1 had hidden it."""
    env = {k: v for k, v in os.environ.items() if k != "PYTHONUNBUFFERED"}
    env.update({"PYTHONPATH": str(ROOT)} if buffered else {"PYTHONPATH": str(ROOT),
                                                           "PYTHONUNBUFFERED": "1"})
    with open("/dev/full", "w") as full:
        r = subprocess.run([sys.executable, "-m", "plans", "solve", str(PRESS)], cwd=ROOT,
                           env=env, stdout=full, stderr=subprocess.PIPE, text=True)
    assert r.returncode == 2
    assert r.stderr == "plans solve: cannot write the output: No space left on device\n"


def test_outputs_through_links_and_devices(capsys, tmp_path):
    """A symbolic link is written through when asked (--follow-links: it stays a link and
    its file is new; as root, -o /dev/stdout replaced the /dev/stdout link with a file);
    /dev/null may take several outputs; an empty file name is refused plainly."""
    real, link = tmp_path / "real.txt", tmp_path / "link.txt"
    real.write_text("old")
    link.symlink_to(real)
    code, _, _ = run(capsys, "solve", "--variant", "3", "-o", link, "--follow-links")
    assert code == 0 and link.is_symlink() and real.read_text().startswith("Four-bar linkage, variant 3")
    code, _, err = run(capsys, "sheet", "--variant", "3", "-o", "/dev/null", "--png", "/dev/null",
                       "--note", "/dev/null")
    assert code == 0, err
    code, _, err = run(capsys, "solve", "--variant", "3", "-o", "")
    assert code == 2 and err == "plans solve: command line: an output option was given an empty file name\n"


@pytest.mark.parametrize("argv", [["-o", "/dev/stdout", "--png", "/dev/stdout"],
                                  ["--png", "/dev/stdout"]])
def test_two_outputs_into_one_pipe_are_refused(tmp_path, argv):
    """/dev/stdout is standard output whatever it is called: an SVG and a PNG mixed in
    one pipe were written with exit 0."""
    r = subprocess.run([sys.executable, "-m", "plans", "sheet", "--variant", "3", *argv],
                       cwd=ROOT, env={**os.environ, "PYTHONPATH": str(ROOT)},
                       capture_output=True)
    assert r.returncode == 2 and r.stdout == b""
    assert b"are both stdout" in r.stderr


def test_output_to_dev_stdout_appends_to_what_stdout_is(tmp_path):
    """-o /dev/stdout with stdout appended to a file: the file was replaced by a new
    one through the link, and what it held was lost."""
    log = tmp_path / "log"
    log.write_text("BEFORE\n")
    with open(log, "a") as out:
        r = subprocess.run([sys.executable, "-m", "plans", "solve", "--variant", "1", "-o",
                            "/dev/stdout"], cwd=ROOT, env={**os.environ, "PYTHONPATH": str(ROOT)},
                           stdout=out, stderr=subprocess.PIPE, text=True)
    assert r.returncode == 0, r.stderr
    text = log.read_text()
    assert text.startswith("BEFORE\nFour-bar linkage, variant 1\n")


@pytest.mark.parametrize(("argv", "debug"), [
    (["--debug", "solve", "F"], True),
    (["solve", "F", "--debug"], True),  # where the internal error's message asks for it
    (["solve", "F"], False),
])
def test_debug_is_taken_before_or_after_the_command(argv, debug):
    args = build_parser().parse_args(argv)
    assert args.debug is debug


@pytest.mark.parametrize("debug", ["--debug", "--deb", "--d"])
def test_a_run_configures_its_command_after_debug_however_abbreviated(capsys, tmp_path, debug):
    """argparse takes "--deb" for "--debug" before the command as after it: the command
    that follows is the one configured, its options and its file read as ever."""
    target = tmp_path / "s.json"
    assert main([debug, "solve", str(PRESS), "--json", "-o", str(target)]) == 0
    assert json.loads(target.read_text("utf-8"))["points"]
    assert main([debug, "cycle", "-h"]) == 0
    assert "--positions N" in capsys.readouterr().out


def test_output_written_in_pieces_is_all_or_nothing(tmp_path):
    """A table written as it is made (cycle --json): a failure half way leaves the old
    file as it was, and no temporary file behind."""
    out = tmp_path / "t.json"
    out.write_text("KEEP")

    def pieces():
        yield "{"
        raise RuntimeError("half way")

    with pytest.raises(RuntimeError):
        cli.write_output(str(out), pieces())
    assert out.read_text() == "KEEP" and [p.name for p in tmp_path.iterdir()] == ["t.json"]
    cli.write_output(str(out), iter(["a", "b", "c"]))
    assert out.read_text() == "abc"


def test_a_table_goes_with_a_variant_only(capsys, tmp_path):
    """--table beside a FILE had been ignored without a word, even a table that does not
    exist; an empty --table read "plans solve: : cannot read the file"."""
    code, out, err = run(capsys, "solve", PRESS, "--table", tmp_path / "none.toml")
    assert code == 2 and out == ""
    assert err == ("plans solve: command line: --table goes with --variant N: a mechanism "
                   "FILE is read as it is\n")
    code, _, err = run(capsys, "solve", "--variant", "3", "--table", "")
    assert code == 2 and err == "plans solve: command line: --table was given an empty file name\n"


def test_all_variants_of_a_table_that_cannot_be_read_make_no_folder(capsys, tmp_path):
    code, _, err = run(capsys, "sheet", "--variant", "all", "--table", tmp_path / "none.toml",
                       "-o", f"{tmp_path}/sheets/")
    assert code == 2 and len(err.splitlines()) == 1
    assert not (tmp_path / "sheets").exists()


def test_a_bad_row_of_a_table_stops_only_its_own_variant(capsys, tmp_path):
    """A typo in variant 3 of a class's table had stopped every variant of it, and
    sheet --variant all made no sheet at all."""
    table = tmp_path / "t.toml"
    table.write_text("[[variant]]\nn = 1\nAB = 0.06\nBC = 0.16\nCD = 0.12\nAD = 0.11\n"
                     "phi_deg = 50\nrpm = 115\n\n"
                     "[[variant]]\nn = 3\nAB = 0.06\nBC = 0.16\nCD = 0.12\nAd = 0.11\n"
                     "phi_deg = 50\nrpm = 115\n", "utf-8")
    code, out, err = run(capsys, "solve", "--variant", "1", "--table", table)
    assert code == 0 and "Four-bar linkage, variant 1" in out
    assert err.splitlines() == [
        f"plans solve: warning: {table}: line 10: variant[1].AD: missing: four-bar variant 3 "
        "needs AB, BC, CD, AD, phi_deg, rpm",
        f"plans solve: warning: {table}: line 15: variant[1].Ad: unknown column (variant 3) — "
        'did you mean "AD"? known: AB, AD, BC, CD, e, kind, n, omega, phi_deg, rpm, sense']
    code, out, err = run(capsys, "solve", "--variant", "3", "--table", table)
    assert code == 2 and out == "" and len(err.splitlines()) == 2 and "variant 3" in err
    code, _, err = run(capsys, "sheet", "--variant", "all", "--table", table, "-o", f"{tmp_path}/s/")
    assert code == 2
    assert sorted(p.name for p in (tmp_path / "s").iterdir()) == ["variant-1.svg"]
    assert err.splitlines()[-1] == "plans sheet: 1 of 2 sheets failed"
    assert "warning" not in err


def test_names_typed_with_cyrillic_letters_say_so(capsys, tmp_path):
    """"АВ" and "роints" typed on a Russian keyboard: a TOML syntax error, or an unknown
    column, with nothing to say that the letters were the matter."""
    mech = tmp_path / "m.toml"
    mech.write_text('[frame]\nO = [0, 0]\n[driver]\nlink = 1\nangle_deg = 30\nomega = 10\n'
                    '[links.1]\naxis = ["O", "A"]\nроints = { A = 0.1 }\n', "utf-8")
    code, _, err = run(capsys, "solve", mech)
    assert code == 2 and err == (f"plans solve: {mech}: line 9, column 1: TOML syntax error: invalid "
                                 "statement (the name has the Cyrillic letters р, о: type them in Latin)\n")
    inline = tmp_path / "i.toml"  # a point name in an inline table, where most of them are
    inline.write_text(mech.read_text("utf-8").replace("роints = { A", "points = { А"), "utf-8")
    code, _, err = run(capsys, "solve", inline)
    assert code == 2 and err.endswith("(the name has the Cyrillic letter А: type it in Latin)\n")
    table = tmp_path / "t.toml"
    table.write_text('[[variant]]\nn = 3\n"АВ" = 0.06\nBC = 0.16\nCD = 0.12\nAD = 0.11\n'
                     "phi_deg = 50\nrpm = 115\n", "utf-8")
    code, _, err = run(capsys, "solve", "--variant", "3", "--table", table)
    assert code == 2
    assert 'unknown column (variant 3) — did you mean "AB" (typed with the Cyrillic letters А, В)?' in err


def test_a_mechanism_file_given_as_a_table_is_named_so(capsys):
    """It had got nine lines: unknown keys frame, driver, links…, and no rows."""
    code, out, err = run(capsys, "solve", "--variant", "1", "--table", PRESS)
    assert code == 2 and out == ""
    assert err == (f"plans solve: {PRESS}: a mechanism file, not a variant table: solve it with "
                   f"plans solve {PRESS} (or report, cycle, sheet)\n")


@pytest.mark.parametrize(("command", "path", "says"), [
    ("check", PRESS, "a mechanism file, not a measurement file: solve it with plans solve"),
    ("check", ROOT / "plans" / "data" / "table2.toml",
     "a variant table ([[variant]] rows), not a measurement file: give it as --table"),
    ("solve", ROOT / "samples" / "fourbar.toml", None),
    ("solve", ROOT / "samples" / "check_press.toml",
     "a measurement file (mechanism = …, [segments]), not a mechanism file: check it with plans check"),
    ("sheet", ROOT / "plans" / "data" / "table2.toml",
     "a variant table ([[variant]] rows), not a mechanism file: give it as --table"),
])
def test_a_file_of_another_kind_is_named_so(capsys, tmp_path, command, path, says):
    """A mechanism file given to check, a measurement file or a table given to solve had
    got six to ten lines, one per key each did not know. (A file of the reader's own kind
    is read: ``says`` None.)"""
    code, out, err = run(capsys, command, path, *(["-o", tmp_path / "s.svg"] if command == "sheet" else []))
    if says is None:
        assert code == 0 and err == "", err
        return
    assert code == 2 and out == "" and list(tmp_path.iterdir()) == []
    assert err.startswith(f"plans {command}: {path}: {says}") and err.count("\n") == 1, err


def test_a_row_without_a_number_stops_no_variant(capsys, tmp_path):
    """n = "four" in one row had stopped every variant of the table."""
    table = tmp_path / "t.toml"
    table.write_text('[[variant]]\nn = 1\nAB = 0.06\nBC = 0.16\nCD = 0.12\nAD = 0.11\n'
                     'phi_deg = 50\nrpm = 115\n\n[[variant]]\nn = "four"\nAB = 0.06\n', "utf-8")
    code, out, err = run(capsys, "solve", "--variant", "1", "--table", table)
    assert code == 0 and "variant 1" in out
    assert err == (f"plans solve: warning: {table}: line 11: variant[1].n: the variant number "
                   'must be a whole number 0…999999, got "four"\n')


def test_a_table_is_read_once_and_its_other_rows_problems_are_capped(capsys, tmp_path, monkeypatch):
    """The table had been read again for the other rows' warnings (a pipe gave nothing the
    second time) and for every sheet of --variant all, and each row's problems were
    located apart: 300 broken rows took 11 s and printed 299 lines."""
    import plans.model.variants as variants

    rows = [f"[[variant]]\nn = {n}\nAB = 0.06\nBC = 0.16\nCD = 0.12\n{'Ad' if n else 'AD'} = 0.11\n"
            "phi_deg = 50\nrpm = 115\n" for n in range(300)]
    table = tmp_path / "t.toml"
    table.write_text("\n".join(rows), "utf-8")
    reads = []
    real = variants.read_toml
    monkeypatch.setattr(variants, "read_toml", lambda *a, **k: reads.append(a) or real(*a, **k))
    code, _, err = run(capsys, "solve", "--variant", "0", "--table", table)
    assert code == 0 and len(reads) == 1
    lines = err.splitlines()
    assert len(lines) == 51 and lines[-1] == f"plans solve: warning: {table}: … and 399 more problems"
    two = tmp_path / "two.toml"
    two.write_text("\n".join(rows[:2]).replace("Ad =", "AD ="), "utf-8")
    reads.clear()
    code, _, _ = run(capsys, "sheet", "--variant", "all", "--table", two, "-o", f"{tmp_path}/s/")
    assert code == 0 and len(reads) == 1


def test_a_decimal_comma_in_quotes_is_read(capsys, tmp_path):
    """A Russian keyboard writes "0,05": the message said only "must be a number", then
    "write 0.05 without quotes, with a decimal point" while the same file's omega3 = "4,82"
    and tolerance = "0,5mm" were read. One rule now: a measurement file reads a decimal
    comma in quotes wherever a number goes (a bare TOML number cannot hold one); with a
    unit after it, it is told what to write."""
    meas = tmp_path / "m.toml"
    meas.write_text(f'mechanism = "{PRESS}"\n[scales]\nmu_v = "0,05"\n[segments]\npa3 = 55\n', "utf-8")
    code, out, err = run(capsys, "check", meas)
    assert code == 0 and err == "" and "μv = 0.05 (m/s)/mm" in out
    meas.write_text(f'mechanism = "{PRESS}"\n[scales]\nmu_v = 0.05\n[segments]\npa3 = "55,4 мм"\n', "utf-8")
    code, _, err = run(capsys, "check", meas)
    assert code == 2 and err == (f'plans check: {meas}: line 5: segments.pa3: must be a number, '
                                 'got "55,4 мм": write "55,4" or 55.4, without the unit\n')


def test_a_number_in_quotes_is_read_in_every_file(capsys, tmp_path):
    """The same rule in a mechanism file and a variant table as in a measurement file:
    "0,15" (a Russian keyboard) and "0.15" are numbers. Before, a mechanism file and a
    table refused both, with "write 0.15 without quotes", while a measurement file read
    "30,0" and refused "30"."""
    text = PRESS.read_text("utf-8")
    quoted = (text.replace("angle_deg = 30", 'angle_deg = "30,0"')
              .replace("B = [0.0, -0.44]", 'B = ["0", "−0,44"]'))
    assert quoted != text and '"30,0"' in quoted and '"−0,44"' in quoted
    mech = tmp_path / "press.toml"
    mech.write_text(quoted, "utf-8")
    code, out, err = run(capsys, "solve", mech, "--json")
    assert code == 0 and err == "", err
    code, ref, _ = run(capsys, "solve", PRESS, "--json")
    assert out == ref

    row = {"n": 0, "AB": 0.05, "BC": 0.15, "phi_deg": 15, "rpm": 100}
    bare = tmp_path / "bare.toml"
    bare.write_text("[[variant]]\n" + "".join(f"{k} = {v}\n" for k, v in row.items()), "utf-8")
    commas = tmp_path / "commas.toml"
    commas.write_text('[[variant]]\nn = 0\nAB = "0,05"\nBC = "0.15"\nphi_deg = "15"\n'
                      'rpm = "100,0"\n', "utf-8")
    outs = []
    for table in (bare, commas):
        code, out, err = run(capsys, "solve", "--variant", "0", "--table", table, "--json")
        assert code == 0 and err == "", err
        outs.append(out)
    assert outs[0] == outs[1]
    assert abs(complex(*json.loads(outs[0])["points"]["B"]["position"])) == pytest.approx(0.05, rel=1e-14)


FOURBAR_E = """
name = "four-bar"
{output}
[frame]
A = [0.0, 0.0]
D = [0.30, 0.05]
[driver]
link = 1
angle_deg = 50
omega = 12
[links.1]
axis = ["A", "B"]
points = {{ B = 0.08 }}
[links.2]
axis = ["B", "C"]
points = {{ C = 0.28, E = [0.12, 0.05] }}
[links.3]
axis = ["D", "C"]
points = {{ C = 0.18 }}
[assembly]
C = "above AD"
"""


@pytest.mark.parametrize(("point", "why"), [
    ("E", "it is a point of link 2, which neither slides on a fixed guide nor turns about a "
          "fixed pivot"),
    ("D", "it is a fixed point"),
])
def test_a_coupler_point_or_a_fixed_pivot_as_output_names_the_rockers_joint(
        capsys, tmp_path, point, why):
    """A coupler's point E was refused with 'e.g. "D"', the rocker's fixed pivot; and D
    itself passed as the output. The message names the outputs there are: C."""
    path = tmp_path / "fb.toml"
    path.write_text(FOURBAR_E.format(output=f'output = "{point}"'), "utf-8")
    code, out, err = run(capsys, "solve", path)
    (line,) = assert_clean_failure(err)
    assert code == 2 and out == ""
    assert line == (f'plans solve: {path}: line 3: output: "{point}" has no stroke or swing: '
                    f"{why}; the output is the point of a slider on a fixed guide or a moving "
                    "point of a rocker (a link other than the crank hinged to the frame): "
                    'here "C"')


def test_without_an_output_the_rockers_moving_joint_names_its_columns(capsys, tmp_path):
    """With no output given, the cycle's columns were ψ_D and 'output D (rad)', after the
    rocker's fixed pivot: they are the rocker's moving joint C's, as with output = "C"."""
    path = tmp_path / "fb.toml"
    path.write_text(FOURBAR_E.format(output=""), "utf-8")
    code, out, err = run(capsys, "cycle", path, "--positions", "4")
    assert code == 0, err
    assert "ψ_C: degrees of link 3 from +x, measured ccw" in out and "ψ_D" not in out
    code, out, _ = run(capsys, "cycle", path, "--csv", "--positions", "4")
    head = out.splitlines()[0].split(",")
    assert "output C (rad)" in head and "output D (rad)" not in head
    code, out, _ = run(capsys, "cycle", path, "--json", "--positions", "4")
    assert json.loads(out)["cycle"]["output"] == {"point": "C", "kind": "angular", "link": 3,
                                                  "unit": "rad"}


def test_a_measurement_file_that_names_a_table_as_its_mechanism_is_told_how(capsys, tmp_path):
    """A measurement file's mechanism = "table2.toml" was told to give the table as
    --table on the command line, which a measurement file cannot do: the line now names
    both ways, the file's own (table = …, variant = N) too."""
    meas = tmp_path / "m.toml"
    table = ROOT / "plans" / "data" / "table2.toml"
    meas.write_text(f'mechanism = "{table.as_posix()}"\n[scales]\nmu_v = 0.01\n[segments]\npb = 70\n',
                    "utf-8")
    code, out, err = run(capsys, "check", meas)
    assert code == 2 and out == "" and err.count("\n") == 1, err
    assert 'a variant table ([[variant]] rows), not a mechanism file: give it as --table ' in err
    assert err.rstrip().endswith('or name it in a measurement file (table = "…", variant = N)')
