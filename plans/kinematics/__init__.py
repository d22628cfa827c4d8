"""Group-by-group kinematics: one formula per dyad kind, recorded and bulk solves."""

from .solver import (  # noqa: F401
    Construction,
    GroupSolution,
    LIMIT_STEP,
    LinkState,
    Route,
    SINGULAR_SINE,
    Solver,
    Term,
    WARN_SINE,
    coincident_name,
    crank_angle,
)
from .sweep import (  # noqa: F401
    BLOCK,
    Sweep,
)

__all__ = ['BLOCK', 'Construction', 'GroupSolution', 'LIMIT_STEP', 'LinkState', 'Route', 'SINGULAR_SINE', 'Solver', 'Sweep', 'Term', 'WARN_SINE', 'coincident_name', 'crank_angle']
