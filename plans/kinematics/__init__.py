"""Group-by-group kinematics: one formula per dyad kind, recorded and bulk solves."""

from plans.tolerances import LIMIT_STEP, SINGULAR_SINE, WARN_SINE

from .dyads import DYADS, Dyad
from .setup import Setup
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
    "DYADS",
    "LIMIT_STEP",
    "SINGULAR_SINE",
    "WARN_SINE",
    "Construction",
    "Dyad",
    "GroupSolution",
    "LinkState",
    "Route",
    "Setup",
    "Solver",
    "Sweep",
    "Term",
    "coincident_name",
    "crank_angle",
]
