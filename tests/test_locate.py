"""Where a problem is in a file, found in time linear in the file's size and once per file
(issue 22): a long dotted header, a variant table's many rows, a device given as a file."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest
from support import run

from plans.errors import InputError
from plans.model import fileformat, locate, variants

ROOT = Path(__file__).resolve().parent.parent
PRESS = (ROOT / "samples" / "press.toml").read_text("utf-8")
TABLE = (ROOT / "plans" / "data" / "table2.toml").read_text("utf-8")


def test_a_key_under_a_deep_header_is_located_in_linear_time():
    """Each prefix of a 50,000-level header had been joined into a string of its own
    (380 s); the keys now form a tree, each key costing its own length. The locator is
    asked directly here: the file itself is refused before TOML reads it (below)."""
    depth = 50_000
    text = "x = 1\n[" + ".".join(["a"] * depth) + "]\nb = 2\nc = { d = 3 }\n"
    index = locate.FileIndex(text)
    deep = ".".join(["a"] * depth)
    assert index.line("x") == 1
    assert index.line(deep + ".b") == 3 and index.line(deep + ".c.d") == 4
    assert index.line(deep + ".nowhere") == 2  # the nearest enclosing key
    assert index.line("a") == 2  # the header's first part, where nothing else names it


def test_a_dotted_header_of_fifty_thousand_levels_is_one_located_line():
    """A 100 KB file with one problem and a 50,000-level header: the header is one located
    line, said before TOML reads it (tomllib reads a dotted key in time that grows with
    the square of its parts), as a user runs it."""
    text = PRESS.replace("\nomega = ", "\nomega = -20\n# omega = ", 1)
    text += "\n[" + ".".join(["a"] * 50_000) + "]\nx = 1\n"
    with pytest.raises(InputError) as info:
        fileformat.parse_toml(text, "m.toml")
    assert info.value.problems == [f"line {PRESS.count(chr(10)) + 3}: TOML key of 50000 dotted parts: "
                                   "these files need three levels at most (links.3.points)"]


def test_the_hostile_header_runs_as_a_user_runs_it(tmp_path):
    text = PRESS + "\n[" + ".".join(["a"] * 50_000) + "]\nx = 1\n"
    path = tmp_path / "m.toml"
    path.write_text(text, "utf-8")
    r = subprocess.run([sys.executable, "-m", "plans", "solve", str(path)], cwd=ROOT, capture_output=True,
                       text=True, timeout=120)
    assert r.returncode == 2 and r.stdout == ""
    assert r.stderr.count("\n") == 1 and "TOML key of 50000 dotted parts" in r.stderr


@pytest.mark.parametrize("text", [
    'name = "' + ".".join(["a"] * 600) + '"\n',             # a value, in a string
    "x = [" + ", ".join(["1.5"] * 2000) + "]\n",              # many numbers on one line
    "[" + ".".join(["a"] * 255) + "]\nx = 1\n",                # at the limit
])
def test_many_dots_that_are_no_long_key_are_read(text):
    assert fileformat.parse_toml(text, "m.toml")


def _table(rows: int, bad: int) -> str:
    head, _, rest = TABLE.partition("[[variant]]")
    first = "[[variant]]" + rest.split("[[variant]]")[0]
    out = [head]
    for n in range(rows):
        row = first.replace("n = 0\n", f"n = {n}\n", 1)
        out.append(row.replace("AB = ", "AB = -", 1) if n < bad else row)
    return "".join(out)


@pytest.fixture
def documents(monkeypatch):
    """How many times a file's text is read for its lines."""
    count = []
    read = locate._Locator.document

    def counted(self):
        count.append(1)
        return read(self)

    monkeypatch.setattr(locate._Locator, "document", counted)
    return count


def test_a_table_is_located_once_however_many_rows_fail(tmp_path, documents):
    """sheet --variant all had located the whole table again for each failing row (1,000
    bad rows: 55 s; 10,000: 1.5 h). Every row's problems now share the table's lines."""
    path = tmp_path / "t.toml"
    path.write_text(_table(12, 8), "utf-8")
    table = variants.read_table(path)
    said = []
    for n in table.numbers:
        try:
            table.variant(n)
        except InputError as exc:
            said += exc.problems
    said += table.others(None)
    assert len(said) == 8 and all(line.startswith("line ") for line in said)
    assert len(documents) == 1


def test_a_good_table_is_not_located_at_all(tmp_path, capsys, documents):
    """solve --variant N --table T had located the whole table with no problem in it
    (3.7 s of 5.8 s on a good 10⁴-row table): it is read for its lines only where a
    problem is said."""
    path = tmp_path / "t.toml"
    path.write_text(_table(40, 0), "utf-8")
    code, out, err = run(capsys, "solve", "--variant", "39", "--table", path)
    assert code == 0 and err == "" and "variant 39" in out
    assert documents == []


def test_a_device_is_not_a_file(capsys):
    """/dev/zero was "larger than 1 MB" (read to the limit first): it is a device."""
    code, out, err = run(capsys, "solve", "/dev/zero")
    assert code == 2 and out == ""
    assert err == "plans solve: /dev/zero: is a device, not a file\n"
    code, _, err = run(capsys, "check", "/dev/zero")
    assert code == 2 and "/dev/zero: is a device, not a file" in err
