"""Exact vector plans (velocity and acceleration polygons) of planar linkages.

>>> from plans import load, solve_position
>>> sol = solve_position(load("samples/press.toml"))
>>> round(sol.segments["pa3"], 2), round(sol.omega[3], 3)
(55.43, 4.822)

Over many crank angles at once, without the recorded constructions (``Solver.sweep``):

>>> import numpy as np
>>> sw = Solver(load("samples/press.toml")).sweep(np.radians(np.arange(0, 360, 0.5)))
>>> H = np.ptp(sw.position["D"].real)  # the slider's stroke
>>> round(float(H), 4), round(float(np.max(np.abs(sw.velocity["D"]))), 3)  # m, m/s
(0.5114, 7.764)
"""

from plans.cycle import Cycle, analyse_cycle, grashof_class
from plans.errors import (
    AssemblyError,
    InputError,
    PlansError,
    SingularPlanError,
    StructureError,
)
from plans.kinematics.solver import Motion, Solver
from plans.kinematics.sweep import Sweep
from plans.model import Mechanism
from plans.model.load import from_dict, load
from plans.model.structure import DyadKind, Structure, analyse
from plans.model.variants import variant
from plans.plan.solution import Plan, PlanPoint, PlanVector, Solution, Source, solve_position

__all__ = [
    "AssemblyError", "Cycle", "DyadKind", "InputError", "Mechanism", "Motion", "Plan",
    "PlanPoint", "PlanVector", "PlansError", "SingularPlanError", "Solution", "Solver",
    "Source", "Structure", "StructureError", "Sweep", "analyse", "analyse_cycle", "from_dict",
    "grashof_class", "load", "solve_position", "variant",
]
