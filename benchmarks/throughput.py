"""Throughput of the vectorized solver (positions, velocities, accelerations of every
point with the recorded constructions) against N, and what solving in cache-sized blocks
would give if the Motion were not kept whole — the evidence behind leaving
``plans/kinematics/solver.py`` as it is (see the bench's notes).

    python benchmarks/throughput.py [--scene press --scene crank_rocker] [--block 8192]

At N ≳ 1e5 every one of the ~100 arrays a Motion keeps (points × p/v/a, link states,
each group's routes and terms) is a fresh 16 MB allocation: the solver is bound by
memory traffic, not arithmetic. Blocks of ~8k angles run from cache about 3× faster,
but gluing the blocks' Motions back together costs as much as it saves.
"""

from __future__ import annotations

import argparse
import dataclasses
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
sys.path[:0] = [str(ROOT), str(ROOT / "tests")]

from plans.kinematics.solver import Solver  # noqa: E402
from plans.model.scenes import SCENES  # noqa: E402


def best(fn, runs=3):
    out = []
    for _ in range(runs):
        t0 = time.perf_counter()
        fn()
        out.append(time.perf_counter() - t0)
    return min(out)


def concat(parts):
    f = parts[0]
    if isinstance(f, np.ndarray):
        return np.concatenate(parts) if f.ndim else f
    if dataclasses.is_dataclass(f) and not isinstance(f, type):
        return dataclasses.replace(
            f,
            **{
                x.name: concat([getattr(p, x.name) for p in parts])
                for x in dataclasses.fields(f)
            },
        )
    if isinstance(f, dict):
        return {k: concat([p[k] for p in parts]) for k in f}
    if isinstance(f, tuple):
        return tuple(concat(list(x)) for x in zip(*parts, strict=True))
    return f


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--scene", action="append")
    ap.add_argument("--block", type=int, default=8192)
    args = ap.parse_args()
    np.seterr(all="ignore")
    for name in args.scene or ["crank_rocker", "press"]:
        solver = Solver(SCENES[name].mechanism())
        for n in (1_000, 10_000, 100_000, 1_000_000):
            phi = np.linspace(0, 2 * np.pi, n, endpoint=False)
            whole = best(lambda phi=phi, solver=solver: solver.solve(phi))
            line = f"{name:14s} N={n:8d} whole {n / whole / 1e6:5.2f} M/s"
            if n > args.block:
                b = args.block
                blocks = best(
                    lambda phi=phi, solver=solver, b=b, n=n: [
                        solver.solve(phi[i : i + b]) for i in range(0, n, b)
                    ]
                )
                glued = best(
                    lambda phi=phi, solver=solver, b=b, n=n: concat(
                        [solver.solve(phi[i : i + b]) for i in range(0, n, b)]
                    ),
                    runs=2,
                )
                line += (
                    f" | blocks of {b}: {n / blocks / 1e6:5.2f} M/s discarded, "
                    f"{n / glued / 1e6:5.2f} M/s glued into one Motion"
                )
            print(line, flush=True)


if __name__ == "__main__":
    main()
