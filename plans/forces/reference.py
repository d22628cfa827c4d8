"""An independent reference for the force analysis: every moving link's three
Newton–Euler (d'Alembert) equations at once, one linear solve.

Unknowns: the two components of the force at each revolute pair (of its second link on
its first, as :meth:`plans.model.mechanism.Mechanism.revolutes` lists the pair), the
magnitude ν of each prismatic pair's force ⊥ its guide (of the guide's link on the
sliding link) with the couple it carries (which places its line), and the balancing
moment M_у on the driving link. A mechanism with W = 1 has exactly 3n of them for its 3n
equations. Nothing here follows the groups or their order: it checks the group-by-group
force plans, and the virtual-power route checks M_у on its own.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from plans.geometry import cross
from plans.model import Mechanism


class GlobalSolution(NamedTuple):
    #: (point, first link, second link) → the force of the first link on the second (N)
    revolutes: dict
    #: sliding link → (the guide link's force on it ⊥ the guide (N), the couple (N·m) that
    #: comes with it about the slider's own point on the guide)
    prismatic: dict
    M_y: float
    #: the largest residual of the linear solve over the largest load (rounding)
    residual: float


def global_solve(mech: Mechanism, motion, loads) -> GlobalSolution:
    """Solve all links at once at the position of ``motion`` (on Python numbers) under
    ``loads`` (:class:`plans.forces.loads.Load` records)."""
    moving = sorted(mech.links)
    row = {lid: 3 * i for i, lid in enumerate(moving)}
    n = 3 * len(moving)
    A = np.zeros((n, n))
    b = np.zeros(n)
    pos = motion.position
    cols = []

    def put(lid, col, fx, fy, m):
        if lid == 0:
            return
        r = row[lid]
        A[r, col] += fx
        A[r + 1, col] += fy
        A[r + 2, col] += m

    pairs = mech.revolutes()
    for point, i, j in pairs:
        X = complex(pos[point])
        for comp, unit in ((0, 1 + 0j), (1, 1j)):
            col = len(cols)
            cols.append(("R", point, i, j, comp))
            # the force of i on j is +unit on j, −unit on i, both through X
            put(j, col, unit.real, unit.imag, cross(X, unit))
            put(i, col, -unit.real, -unit.imag, -cross(X, unit))
    for s in mech.sliders:
        k = s.guide.link
        u = complex(motion.links[k].rotor * s.guide.direction) if k else s.guide.direction
        w = 1j * u
        X = complex(pos[s.point])
        col = len(cols)
        cols.append(("N", s.link))
        put(s.link, col, w.real, w.imag, cross(X, w))
        put(k, col, -w.real, -w.imag, -cross(X, w))
        col = len(cols)
        cols.append(("M", s.link))
        put(s.link, col, 0.0, 0.0, 1.0)
        put(k, col, 0.0, 0.0, -1.0)
    col = len(cols)
    cols.append(("My",))
    put(mech.driver.link, col, 0.0, 0.0, 1.0)
    if len(cols) != n:
        raise ValueError(f"{len(cols)} unknowns for {n} equations: not a mechanism with W = 1")
    big = 0.0
    for ld in loads:
        if ld.link == 0:
            continue
        r = row[ld.link]
        f = complex(ld.force)
        b[r] -= f.real
        b[r + 1] -= f.imag
        b[r + 2] -= cross(complex(ld.at), f) + float(ld.moment)
        big = max(big, abs(f), abs(float(ld.moment)))
    x = np.linalg.solve(A, b)
    residual = float(np.max(np.abs(A @ x - b))) / max(big, 1e-300)
    revolutes: dict = {}
    prismatic: dict = {}
    for c, value in zip(cols, x, strict=True):
        if c[0] == "R":
            key = c[1:4]
            revolutes[key] = revolutes.get(key, 0j) + (value if c[4] == 0 else 1j * value)
    for s in mech.sliders:
        k = s.guide.link
        u = complex(motion.links[k].rotor * s.guide.direction) if k else s.guide.direction
        nu = x[cols.index(("N", s.link))]
        prismatic[s.link] = (complex(nu * 1j * u), float(x[cols.index(("M", s.link))]))
    return GlobalSolution(revolutes, prismatic, float(x[-1]), residual)


def virtual_power(motion, loads, omega1: float) -> float:
    """M_у from the principle of virtual power: M_у·ω1 + Σ F·V + Σ M·ω = 0, the loads'
    points' velocities and the links' ω as ``motion`` gives them."""
    total = 0.0
    for ld in loads:
        f = ld.force
        if ld.point is not None:
            total += (np.conj(motion.velocity[ld.point]) * f).real
        if ld.moment:
            total += ld.moment * motion.links[ld.link].omega
    return -total / omega1
