"""The force analysis over the whole cycle: M_у(φ) and every reaction at many crank angles
at once, by the same loads (:mod:`plans.forces.loads`) and the same group walk
(:func:`plans.forces.analysis.walk`) as one position's force plans, on numpy arrays: no
Python loop over the angles.

Over a full turn of a uniformly turning crank it also gives the mean balancing moment, the
work of the useful resistance per cycle and the mean power the drive gives:

    M_у,mean = (1/2π)·∮ M_у dφ,   A_P = ∮ P·V_out dt = ∮ (P·V_out / ω1) dφ,   P_mean = M_у,mean·ω1
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from plans.forces.analysis import _name, walk
from plans.forces.loads import Load, Stroke, at_position
from plans.model.loads import Loads


@dataclass(frozen=True)
class ForceSweep:
    phi: np.ndarray  # rad from +x
    M_y: np.ndarray  # N·m, counter-clockwise positive
    R01: np.ndarray  # N: the frame's force on the driving link
    reactions: dict[str, np.ndarray]  # R_ij by name, N (complex)
    resistance_power: np.ndarray | None  # W: the useful resistance's power (negative: it takes work)
    omega1: float

    @property
    def full_turn(self) -> bool:
        return self.phi.size > 1

    def mean_M_y(self) -> float:
        """The mean of M_у over the angles swept (evenly spaced over a turn: the cycle's
        mean; the trapezoid rule on a periodic function is exact to its spacing)."""
        return float(np.mean(self.M_y))

    def resistance_work(self) -> float | None:
        """J per cycle: the work the useful resistance takes (positive), over a full turn
        of evenly spaced angles."""
        if self.resistance_power is None:
            return None
        return float(-np.mean(self.resistance_power) * 2 * math.pi / abs(self.omega1))

    def mean_power(self) -> float:
        """W: the drive's mean power, M_у,mean·ω1."""
        return self.mean_M_y() * self.omega1


def sweep(solver, loads: Loads, phi, stroke: Stroke | None = None) -> ForceSweep:
    """M_у and the reactions at the crank angles ``phi`` (rad from +x, an array)."""
    mech = solver.mech
    phi = np.asarray(phi, dtype=float)
    with np.errstate(all="ignore"):
        motion = solver.solve(phi)
        external = at_position(mech, loads, motion, phi, stroke)
        on: dict[int, list[Load]] = {lid: [] for lid in mech.links}
        for ld in external:
            on[ld.link].append(ld)
        steps, M_y, R01 = walk(mech, solver.structure.groups, motion, on)
    shape = phi.shape
    valid = np.broadcast_to(np.asarray(motion.valid, dtype=bool), shape)

    def kept(values, dtype):
        """The values where the mechanism closes, NaN where it does not: there they mean
        nothing (a maximum or a mean over the sweep must not take them)."""
        return np.where(valid, np.broadcast_to(values, shape), np.nan).astype(dtype)

    reactions = {}
    for st in steps:
        for back in st.backs:
            reactions[_name(back.link, back.other)] = kept(-back.force, complex)
    power = None
    for ld in external:
        if ld.kind == "resistance":
            power = kept((np.conj(motion.velocity[ld.point]) * ld.force).real, float)
    return ForceSweep(phi, kept(M_y, float), kept(R01, complex), reactions, power, mech.driver.omega)
