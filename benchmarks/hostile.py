"""Hold the time budget of hostile input (README, "Time budget"): any input file up to the
1 MB limit is read and judged, accepted or refused with its located problems, in under
BUDGET seconds, and a batch of files in under BUDGET seconds a file.

    python benchmarks/hostile.py            # every case, a table, exit 1 if one is over
    python benchmarks/hostile.py --quick    # the smaller sizes only

Each case is a command run as a user runs it (``python -m plans …``, a fresh process),
timed by the wall clock and killed at KILL × its budget; it is a benchmark, not a unit
test: a machine's load moves the figures, so it is run by hand and its figures quoted.
The files are generated in a temporary folder: long dotted table headers with one
problem, a measurement file of the largest size, a variant table of 10,000 rows, and a
class of measurement files of which one is pathological.
"""

from __future__ import annotations

import argparse
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
BUDGET = 2.0  # seconds a file
KILL = 5.0  # a case is stopped at this many times its budget
LIMIT = 1_000_000  # bytes: the largest input file the tool reads


def _press() -> str:
    return (ROOT / "samples" / "press.toml").read_text("utf-8")


def dotted(folder: Path, levels: int) -> list[str]:
    """A mechanism file with one problem (a negative ω) and a table header of ``levels``
    dotted keys ([a.a.a…]): its one error line had taken 14–25 s at 10,000 levels."""
    text = _press().replace("\nomega = ", "\nomega = -20\n# omega = ", 1)
    text += "\n[" + ".".join(["a"] * levels) + "]\nx = 1\n"
    path = folder / f"dotted-{levels}.toml"
    path.write_text(text, "utf-8")
    return ["solve", str(path)]


def big_measurement(folder: Path) -> list[str]:
    """A measurement file just under the size limit: comments, then its segments."""
    (folder / "press.toml").write_text(_press(), "utf-8")
    body = (ROOT / "samples" / "check_press.toml").read_text("utf-8")
    pad = "# " + "x" * 97 + "\n"
    text = pad * ((LIMIT - len(body.encode()) - 200) // len(pad)) + body
    path = folder / "big.toml"
    path.write_text(text, "utf-8")
    return ["check", str(path)]


def table_rows(folder: Path, rows: int, bad: int = 0) -> list[str]:
    """A variant table of ``rows`` rows (the built-in one's first row repeated, ``bad`` of
    them with a negative length), solved at its last row: the table is read and judged
    whole (``sheet --variant all`` had located the whole text again for each bad row)."""
    text = (ROOT / "plans" / "data" / "table2.toml").read_text("utf-8")
    head, _, rest = text.partition("[[variant]]")
    first = "[[variant]]" + rest.split("[[variant]]")[0]
    out = [head]
    for n in range(rows):
        row = first.replace("n = 0\n", f"n = {n}\n", 1)
        if n < bad:
            row = row.replace("AB = ", "AB = -", 1)
        out.append(row)
    path = folder / f"table-{rows}-{bad}.toml"
    path.write_text("".join(out), "utf-8")
    return ["solve", "--variant", str(rows - 1), "--table", str(path)]


def batch(folder: Path, files: int, levels: int) -> list[str]:
    """A class of ``files`` measurement files, one of them with a dotted header."""
    (folder / "press.toml").write_text(_press(), "utf-8")
    body = (ROOT / "samples" / "check_press.toml").read_text("utf-8")
    names = []
    for k in range(files):
        path = folder / f"student{k:03d}.toml"
        text = body if k else body + "\n[" + ".".join(["a"] * levels) + "]\nx = 1\n"
        path.write_text(text.replace("mu_v = 0.05", "mu_v = -1") if not k else text, "utf-8")
        names.append(str(path))
    return ["check", *names]


def run(argv: list[str], budget: float) -> tuple[float, str]:
    """(seconds, what happened) of ``plans argv``."""
    t = time.monotonic()
    try:
        r = subprocess.run([sys.executable, "-m", "plans", *argv], cwd=ROOT, capture_output=True,
                           env={**os.environ, "PYTHONPATH": str(ROOT)}, timeout=KILL * budget)
    except subprocess.TimeoutExpired:
        return time.monotonic() - t, f"stopped at {KILL * budget:.0f} s"
    lines = r.stderr.decode("utf-8", "replace").count("\n")
    return time.monotonic() - t, f"exit {r.returncode}, {lines} stderr line{'s' * (lines != 1)}"


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--quick", action="store_true", help="the smaller sizes only")
    args = ap.parse_args()
    over = 0
    with tempfile.TemporaryDirectory(prefix="plans-hostile-") as tmp:
        folder = Path(tmp)
        cases = [("dotted header, 1,000 levels (4 KB)", dotted(folder, 1_000), BUDGET),
                 ("variant table, 10,000 rows, row 9,999", table_rows(folder, 10_000), BUDGET),
                 ("variant table, 1,000 bad rows", table_rows(folder, 1_001, 1_000), BUDGET),
                 ("measurement file of 1 MB", big_measurement(folder), BUDGET),
                 ("class of 30 files, one with 1,000 levels", batch(folder, 30, 1_000), 30 * BUDGET)]
        if not args.quick:
            cases += [("dotted header, 10,000 levels (21 KB)", dotted(folder, 10_000), BUDGET),
                      ("dotted header, 50,000 levels (100 KB)", dotted(folder, 50_000), BUDGET),
                      ("class of 30 files, one with 10,000 levels", batch(folder, 30, 10_000),
                       30 * BUDGET)]
        print(f"{'case':45s} {'budget':>8s} {'time':>8s}  result")
        for label, argv, budget in cases:
            seconds, what = run(argv, budget)
            ok = seconds <= budget and not what.startswith("stopped")
            over += not ok
            print(f"{label:45s} {budget:7.0f}s {seconds:7.2f}s  {what}{'' if ok else '  OVER BUDGET'}",
                  flush=True)
    print(f"{over} case{'s' * (over != 1)} over budget" if over else "every case within budget")
    return 1 if over else 0


if __name__ == "__main__":
    sys.exit(main())
