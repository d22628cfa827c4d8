"""The hostile inputs of the largest size, as benchmarks/hostile.py builds them, in the
suite: a measurement file just under the 1 MB limit and a variant table of 10,000 rows with
bad rows among them. Their time is held by the benchmark (README, Time budget), not here;
here, that each is read and judged as its small self is: the same verdict, and one located
line per problem."""

from __future__ import annotations

import importlib.util
import re
import shutil
from pathlib import Path

from support import run

ROOT = Path(__file__).resolve().parent.parent
_spec = importlib.util.spec_from_file_location("hostile_bench", ROOT / "benchmarks" / "hostile.py")
hostile = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(hostile)


def test_a_measurement_file_of_1_mb_is_judged_as_the_small_one(capsys, tmp_path):
    argv = hostile.big_measurement(tmp_path)
    big = Path(argv[-1])
    assert hostile.LIMIT - 1000 < big.stat().st_size < hostile.LIMIT  # it is the largest size
    code, out, err = run(capsys, *argv)
    small = tmp_path / "small"
    small.mkdir()
    shutil.copy(ROOT / "samples" / "check_press.toml", small / "check_press.toml")
    shutil.copy(ROOT / "samples" / "press.toml", small / "press.toml")
    code0, out0, err0 = run(capsys, "check", small / "check_press.toml")
    assert (code, err) == (code0, err0) and code == 1  # the sample's deviations, found again
    def bare(text: str, folder: Path, name: str) -> str:  # the files' paths aside
        return text.replace(str(folder / name), "F").replace(str(folder / "press.toml"), "M")

    assert bare(out, tmp_path, big.name) == bare(out0, small, "check_press.toml")


def test_a_table_of_10000_rows_with_bad_rows_says_each_in_one_located_line(capsys, tmp_path):
    argv = hostile.table_rows(tmp_path, 10_000, bad=3)
    code, out, err = run(capsys, *argv)
    assert code == 0 and out.startswith("Four-bar linkage, variant 9999\n")  # the last row: a good one
    lines = err.strip().splitlines()
    assert len(lines) == 3, err
    for k, line in enumerate(lines):
        assert re.search(rf": line \d+: variant\[{k}\]\.AB: must be positive, got -0\.05$", line), line
    code, _, err = run(capsys, "solve", "--variant", "1", "--table", argv[-1])
    assert code == 2 and err.count("\n") == 1 and "variant[1].AB: must be positive" in err
