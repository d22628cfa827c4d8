"""Exact vector plans (velocity and acceleration polygons) of planar linkages.

>>> from plans import load, solve_position
>>> sol = solve_position(load("samples/press.toml"))
>>> round(sol.segments["pa3"], 2), round(sol.omega[3], 3)
(55.43, 4.822)
"""

from .cycle import Cycle, analyse_cycle, grashof_class
from .errors import AssemblyError, InputError, PlansError, SingularPlanError, StructureError
from .kinematics import Motion, Solver
from .mechanism import Mechanism, from_dict, load
from .plan import Plan, PlanPoint, PlanVector, Solution, Source, solve_position
from .structure import DyadKind, Structure, analyse
from .variants import variant

__all__ = [
    "AssemblyError", "Cycle", "DyadKind", "InputError", "Mechanism", "Motion", "Plan",
    "PlanPoint", "PlanVector", "PlansError", "SingularPlanError", "Solution", "Solver",
    "Source", "Structure", "StructureError", "analyse", "analyse_cycle", "from_dict",
    "grashof_class", "load", "solve_position", "variant",
]
