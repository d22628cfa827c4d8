"""Group-by-group kinematics: one formula per dyad kind, recorded and bulk solves."""

from plans.tolerances import LIMIT_STEP, SINGULAR_SINE, WARN_SINE

from .solver import (
    Construction,
    GroupSolution,
    LinkState,
    Route,
    Solver,
    Term,
    coincident_name,
    crank_angle,
)
from .sweep import (
    BLOCK,
    Sweep,
)

__all__ = [
    "BLOCK",
    "LIMIT_STEP",
    "SINGULAR_SINE",
    "WARN_SINE",
    "Construction",
    "GroupSolution",
    "LinkState",
    "Route",
    "Solver",
    "Sweep",
    "Term",
    "coincident_name",
    "crank_angle",
]
