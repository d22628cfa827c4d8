"""The synthesis's benchmark: γmin over a whole crank-rocker family (seed 004's example 8.5:
K = 1.25, ψ = 32°, CD = 290 mm) in one vectorized call, and its largest error against the
engine's γmin of members spread over the family, each written as a mechanism file and
analysed (:func:`plans.synthesis.verify.check`). ``plans bench`` prints it; timings are
figures, never assertions.
"""

from __future__ import annotations

import math
import time
from typing import NamedTuple

import numpy as np

from plans.synthesis.design import Design, Problem
from plans.synthesis.rocker import RockerFamily, _solution
from plans.synthesis.verify import check

#: the least γmin of the members checked against the engine (rad)
USEFUL = math.radians(5.0)

#: the family benched: seed 004's example 8.5 without its coupler
FAMILY = {"K": 1.25, "psi": math.radians(32.0), "CD": 0.29}


class FamilyRow(NamedTuple):
    members: int
    seconds: float  # the best of the runs, for the whole call
    max_rel_error: float  # over the members checked, γmin against the engine's
    best_gamma: float  # rad, the family's largest γmin among the members timed

    @property
    def per_second(self) -> float:
        return self.members / self.seconds if self.seconds > 0 else math.inf


def family_bench(members: int = 1_000_000, repeats: int = 3, checks: int = 24) -> FamilyRow:
    """Time γmin of ``members`` crank-rockers (A spread over the arc beyond the chord) in
    one call, the best of ``repeats``; check ``checks`` of them against the engine."""
    fam = RockerFamily(FAMILY["K"], FAMILY["psi"], FAMILY["CD"])
    u = np.linspace(fam.lo, fam.hi, members + 2)[1:-1]
    best = math.inf
    gamma = ok = None
    for _ in range(repeats):
        t0 = time.perf_counter()
        gamma, ok = fam.gamma_min(u, 1)
        best = min(best, time.perf_counter() - t0)
    # members of some use (γmin ≥ 5°): where γ → 0 the linkage nears a dead point, and any
    # γ found from a cosine loses digits as 1/γ², the engine's as this one's
    useful = np.flatnonzero(ok & (gamma >= USEFUL))
    worst = 0.0
    problem = Problem("crank-rocker", dict(FAMILY), "bench")
    for k in useful[np.linspace(0, useful.size - 1, checks).astype(int)] if useful.size else ():
        A = complex(fam.pivot(u[k:k + 1], 1)[0])
        design = Design(problem, (_solution(fam, A, 1, float(u[k]), problem),), 0, "given")
        row = next(r for r in check(design).rows if r.name == "γmin")
        worst = max(worst, abs(float(gamma[k]) - row.engine) / row.engine)
    top = float(np.max(np.where(ok, gamma, -np.inf)))
    return FamilyRow(members, best, worst, top)
