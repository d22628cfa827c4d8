"""The whole force analysis of a mechanism at its crank position, as the command, the note
and sheet 2 use it: the loads and each group's force plan (:mod:`plans.forces.analysis`),
M_у by Zhukovsky's lever and by virtual power beside the groups' (and the global linear
solve's, the independent check), M_у over the cycle with its mean, the resistance's work
and the mean power (:mod:`plans.forces.sweep`), and the drive (:mod:`plans.forces.drive`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from plans.errors import InputError, PlansError
from plans.forces.analysis import ForceAnalysis, analyse
from plans.forces.drive import DriveResult, drive, read_catalogue
from plans.forces.lever import Lever, lever
from plans.forces.loads import Stroke, stroke_of
from plans.forces.reference import global_solve, virtual_power
from plans.forces.sweep import ForceSweep, sweep
from plans.model.loads import Drive

#: angles over a turn at which M_у is swept for its mean and its diagram
SAMPLES = 720


@dataclass(frozen=True)
class Forces:
    analysis: ForceAnalysis
    lever: Lever
    M_y_power: float  # N·m, by virtual power
    M_y_global: float  # N·m, by the global linear solve
    #: M_у at the cycle's positions (the sheet's numbered positions), in their order
    positions: tuple[tuple[float, float], ...]
    turn: ForceSweep | None  # over a whole turn, evenly: the diagram, the mean, the work
    drive: DriveResult | None
    drive_note: str  # why the drive is sized as it is (or why there is none)

    @property
    def discrepancy(self) -> float:
        """|M_у by the lever − M_у by the groups| / |M_у|: rounding, the lever being exact."""
        M = self.analysis.M_y
        return abs(self.lever.M_y - M) / abs(M) if M else abs(self.lever.M_y)


def rpm_of(mech) -> float:
    d = mech.driver
    return d.rpm if d.rpm is not None else abs(d.omega) * 30 / math.pi


def solve_forces(sol, solver, cycle, mu_F: float | None = None, catalogue=None) -> Forces:
    """Everything sheet 2 and the note's force section show, at the position of ``sol``;
    ``cycle``: :func:`plans.cycle.analyse_cycle` of its mechanism."""
    mech = sol.mechanism
    loads = mech.loads
    if loads is None:
        raise InputError(
            mech.source,
            "loads: missing: the force analysis needs the links' masses and the "
            'forces on them, e.g. [loads.links.3] mass = 10, J_S = 0.4, centre = "S3" '
            "(README: Loads)",
        )
    why = unbalanced(mech)
    if why is not None:
        raise InputError(mech.source, why)
    stroke: Stroke | None = stroke_of(mech, cycle, solver)
    fa = analyse(sol, loads, stroke, mu_F)
    lv = lever(sol, list(fa.loads))
    vp = virtual_power(sol.scalar, fa.loads, mech.driver.omega)
    ref = global_solve(mech, sol.scalar, fa.loads)
    turn = positions = None
    if cycle.full_turn:
        phi = cycle.positions[0] + np.linspace(0.0, 2 * math.pi, SAMPLES, endpoint=False) * np.sign(
            mech.driver.omega
        )
        try:
            turn = sweep(solver, loads, phi, stroke)
            at = sweep(solver, loads, np.asarray(cycle.positions), stroke)
            positions = tuple((float(p), float(m)) for p, m in zip(at.phi, at.M_y, strict=True))
        except PlansError:
            turn = None
        if turn is not None and not np.all(np.isfinite(turn.M_y)):
            turn = None  # a dead point on the way: no mean, no diagram
    dr, why = _drive(fa, turn, mech.drive or Drive(), catalogue, mech)
    return Forces(fa, lv, vp, ref.M_y, positions or (), turn, dr, why)


def _drive(fa: ForceAnalysis, turn: ForceSweep | None, spec: Drive, catalogue, mech):
    """The motor and gearbox for the power at this position (seed 001's rule), or, where
    the crank takes none here, for the cycle's mean power."""
    n1 = rpm_of(mech)
    power, why = fa.power, "position"
    if spec.power == "mean" and turn is not None:
        power, why = turn.mean_power(), "mean"
    if not power > 0:
        if turn is None or not turn.mean_power() > 0:
            return None, "none"
        power, why = turn.mean_power(), "mean"
    catalogue = catalogue if catalogue is not None else read_catalogue()
    try:
        return drive(
            power, n1, spec.efficiency, spec.digit, spec.synchronous, catalogue, source=mech.source
        ), why
    except InputError as exc:
        return None, str(exc).split(": ", 1)[-1]


def unbalanced(mech) -> str | None:
    """Why the force analysis does not balance ``mech`` (its field first), or None where it
    does: it balances one crank by its moment M_у, at a crank angle and over the crank's
    turn; two inputs, a slider input and a crank moved by a law in time are not worked out."""
    if len(mech.drivers) > 1:
        inputs = " and ".join(f"link {d.link}" for d in mech.drivers)
        return (f"drivers: the force analysis balances one crank by its moment M_у: this mechanism has "
                f"two inputs ({inputs}), and each would need a balancing load of its own")
    if mech.driver.linear:
        return (f"driver: the force analysis balances a crank by its moment M_у: link {mech.driver.link} "
                "is a slider driven along its guide, whose balancing force is not worked out here")
    if mech.timing is not None:  # its positions are instants, not crank angles
        return ("driver.law: the force analysis works at a crank angle and over the crank's turn: a "
                "crank moved by a law in time is not balanced here; give its omega (and epsilon) at the "
                "position instead")
    return None
