"""The force analysis's benchmark: positions per second of the cycle's sweep of a loaded
mechanism (:func:`plans.forces.sweep.sweep`), and its largest error against the global
linear solve (:func:`plans.forces.reference.global_solve`) at angles spread over the turn.
``plans bench`` prints it; timings are figures, never assertions.
"""

from __future__ import annotations

import math
import time
from typing import NamedTuple

import numpy as np

from plans.cycle import analyse_cycle
from plans.forces.analysis import analyse
from plans.forces.loads import stroke_of
from plans.forces.reference import global_solve
from plans.forces.sweep import sweep
from plans.kinematics.solver import Solver
from plans.plan.solution import solve_position


class ForceRow(NamedTuple):
    scene: str
    positions: int
    seconds_per_position: float
    max_rel_error: float  # over the checked angles: |M_у − M_у,global| and every reaction, over the largest

    @property
    def per_second(self) -> float:
        return 1.0 / self.seconds_per_position if self.seconds_per_position > 0 else math.inf


def force_bench(mech, name: str, positions: int = 100_000, repeats: int = 3, checks: int = 24) -> ForceRow:
    """Time the sweep of ``mech`` (which carries its loads) over ``positions`` angles, the
    best of ``repeats`` runs, and check ``checks`` angles against the global solve."""
    sv = Solver(mech)
    cycle = analyse_cycle(mech, solver=sv)
    stroke = stroke_of(mech, cycle, sv)
    phi = np.linspace(0.0, 2 * math.pi, positions, endpoint=False) + 1e-3
    best = math.inf
    out = None
    for _ in range(repeats):
        t0 = time.perf_counter()
        out = sweep(sv, mech.loads, phi, stroke)
        best = min(best, time.perf_counter() - t0)
    worst = 0.0
    for k in np.linspace(0, positions - 1, checks).astype(int):
        sol = solve_position(mech, float(phi[k]), solver=sv, mu={"mu_l": 1.0})
        fa = analyse(sol, mech.loads, stroke)
        ref = global_solve(mech, sol.scalar, fa.loads)
        big = max([abs(r.value) for r in fa.reactions.values()] + [abs(fa.M_y)] + [1e-300])
        worst = max(worst, abs(out.M_y[k] - ref.M_y) / big)
        for (_pt, i, j), f in ref.revolutes.items():
            got = out.reactions.get(f"R{i}{j}")
            if got is not None:
                worst = max(worst, abs(got[k] - f) / big)
            elif (back := out.reactions.get(f"R{j}{i}")) is not None:
                worst = max(worst, abs(back[k] + f) / big)
    return ForceRow(name, positions, best / positions, worst)
