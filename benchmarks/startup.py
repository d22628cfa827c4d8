"""Start-up cost of the commands that only compute: end-to-end wall time of
``plans solve samples/press.toml --json`` (target ≤ 0.3 s), of a bare numpy import for
comparison, and which heavy packages each command loads (none should).

    python benchmarks/startup.py [--runs 7]
"""

from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
HEAVY = (
    "matplotlib",
    "shapely",
    "svgwrite",
    "sympy",
    "mpmath",
    "cairosvg",
    "pylinkage",
)


def wall(argv: list[str], runs: int) -> tuple[float, float]:
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    times = []
    for _ in range(runs):
        t0 = time.perf_counter()
        subprocess.run(argv, cwd=ROOT, env=env, check=True, capture_output=True)
        times.append(time.perf_counter() - t0)
    return min(times), statistics.median(times)


def heavy_loaded(command: list[str]) -> list[str]:
    code = (
        "import sys, io, contextlib\n"
        "from plans.cli import main\n"
        "with contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(io.StringIO()):\n"
        f"    main({command!r})\n"
        f"print(sorted({{m.split('.')[0] for m in sys.modules}} & set({HEAVY!r})))\n"
    )
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    out = subprocess.run(
        [sys.executable, "-c", code],
        cwd=ROOT,
        env=env,
        check=True,
        capture_output=True,
        text=True,
    )
    return eval(out.stdout.strip())  # a printed list of names


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--runs", type=int, default=7)
    args = ap.parse_args()
    py = sys.executable
    rows = [
        ("python -c pass", [py, "-c", "pass"]),
        ("import numpy", [py, "-c", "import numpy"]),
        ("import plans", [py, "-c", "import plans"]),
        (
            "plans solve press --json",
            [py, "-m", "plans", "solve", "samples/press.toml", "--json"],
        ),
        (
            "plans cycle press --json",
            [py, "-m", "plans", "cycle", "samples/press.toml", "--json"],
        ),
    ]
    print(
        f"load average {os.getloadavg()[0]:.1f}, {args.runs} runs each (best / median)"
    )
    for label, argv in rows:
        best, med = wall(argv, args.runs)
        print(f"  {label:28s} {best * 1e3:7.0f} ms / {med * 1e3:7.0f} ms")
    for cmd in (
        ["solve", "samples/press.toml", "--json"],
        ["cycle", "samples/press.toml", "--json"],
        ["report", "samples/press.toml"],
    ):
        print(
            f"  heavy packages loaded by plans {' '.join(cmd)}: {heavy_loaded(cmd) or 'none'}"
        )


if __name__ == "__main__":
    main()
