"""The positions a plan of positions draws: the one rule that ``solve``, ``report`` and the
sheet choose μl by.

A plan of positions shows the given position, the cycle's numbered positions, the two
extreme ones and the trajectories of the traced points. Where a slider runs off towards
a dead point at infinity (the tangent mechanism at the ends of its crank range) a
position is left off: one of its points lies farther than :data:`FAR` times the given
position's own size from it (:func:`reach`). μl is chosen from the box round what is
left (:attr:`Drawn.extent`), so a note and a sheet size the same drawing.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from functools import cached_property

import numpy as np

from plans.cycle.words import worded
from plans.errors import PositionError
from plans.kinematics.solver import Motion, Solver

#: how far a point of a drawn position may lie from the given position, in multiples of
#: the given position's size
FAR = 8.0


def reach(given: dict[str, complex]) -> tuple[complex, float]:
    """(centre, limit): the given position's centre, and how far from it a point of a
    position drawn may lie (:data:`FAR` times the given position's size)."""
    pts = np.array(list(given.values()))
    centre = complex(pts.mean())
    return centre, FAR * max(float(np.abs(pts - centre).max()), 1e-6)


def trajectory_angles(cycle, n: int = 361) -> np.ndarray:
    """The crank angles the trajectories are drawn over: the whole turn, or the range the
    cycle's positions span when the crank cannot make a full turn."""
    lo, hi = (0.0, 2 * math.pi) if cycle.full_turn else cycle.crank_range
    return np.linspace(lo, hi, n)


def positions_at(solver: Solver, phis) -> list[dict[str, complex] | None]:
    """Every point's position at each angle; None where the mechanism does not close (a
    change point, where it closes to rounding, stands: :attr:`Motion.placed`)."""
    with np.errstate(all="ignore"):
        m = solver.solve(np.asarray(phis, dtype=float))
    ok = m.placed
    return [{n: complex(np.asarray(a)[i]) for n, a in m.position.items()} if ok[i] else None
            for i in range(len(phis))]


@dataclass(frozen=True)
class Drawn:
    """What the plan of positions draws, whatever its scale: the given position, the
    cycle's positions and the extreme ones (None where the mechanism does not close there,
    or where a point runs beyond :func:`reach`: those cycle positions are ``left_off``),
    the trajectories' motion and which of its samples are drawn."""

    given: dict[str, complex]
    cycle: list[dict[str, complex] | None]
    extremes: list[dict[str, complex] | None]
    left_off: tuple[int, ...]
    limit: float
    motion_all: Motion  # at trajectory_angles(cycle)
    trajectory: np.ndarray  # bool per sample of motion_all
    traced: tuple[str, ...]  # the points whose trajectories are drawn

    @property
    def positions(self) -> list[dict[str, complex]]:
        return [p for p in (*self.cycle, *self.extremes, self.given) if p is not None]

    @cached_property
    def extent(self) -> float:
        """The larger side (m) of the box round it all: μl is chosen from this, so a
        point that runs far out between the positions drawn (a cross-slide near its dead
        point) does not shrink the drawing, nor do the positions left off."""
        pts = [np.array(list(p.values())) for p in self.positions]
        pts += [np.asarray(self.motion_all.position[n])[self.trajectory] for n in self.traced]
        z = np.concatenate(pts)
        return float(max(np.ptp(z.real), np.ptp(z.imag), 1e-9))


def drawn(solver: Solver, cycle) -> Drawn:
    """The positions the plan of positions draws (:class:`Drawn`) for ``cycle`` (from
    :func:`plans.cycle.analyse_cycle`, by ``solver``); a value: whoever draws it more than
    once keeps it."""
    mech = solver.mech
    given = positions_at(solver, [mech.param])[0]
    if given is None:  # the given position does not close: say why, as solve would
        try:
            solver.solve_one(mech.param)
        except PositionError as err:
            raise worded(err, solver, cycle) from None
    centre, limit = reach(given)

    def far(z) -> np.ndarray:
        return np.abs(np.asarray(z) - centre) > limit

    def near(positions):
        return [p if p is not None and not far(list(p.values())).any() else None
                for p in positions]

    everywhere = positions_at(solver, cycle.positions)
    kept = near(everywhere)
    left_off = tuple(k for k, (p, q) in enumerate(zip(everywhere, kept, strict=True))
                     if p is not None and q is None)
    motion_all = solver.solve(trajectory_angles(cycle))
    traced = tuple(n for n in (*mech.trace, mech.driver.tip) if n in motion_all.position)
    trajectory = motion_all.placed
    for n in traced:
        trajectory &= ~far(motion_all.position[n])
    return Drawn(given, kept, near(positions_at(solver, cycle.extremes)), left_off, limit,
                 motion_all, trajectory, traced)
