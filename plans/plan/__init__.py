"""One crank position: the plans with every construction recorded."""

from .solution import (
    Plan,
    PlanLine,
    PlanPoint,
    PlanVector,
    Solution,
    Source,
    cycle_extent,
    image_sides,
    plan_name,
    solve_position,
)

__all__ = [
    "Plan",
    "PlanLine",
    "PlanPoint",
    "PlanVector",
    "Solution",
    "Source",
    "cycle_extent",
    "image_sides",
    "plan_name",
    "solve_position",
]
