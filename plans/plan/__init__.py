"""One crank position: the plans with every construction recorded."""

from .recipe import Recipe, recipes
from .solution import Solution, solve_position
from .values import (
    Plan,
    PlanLine,
    PlanPoint,
    PlanVector,
    Source,
    image_sides,
    plan_name,
)

__all__ = [
    "Plan",
    "PlanLine",
    "PlanPoint",
    "PlanVector",
    "Recipe",
    "Solution",
    "Source",
    "image_sides",
    "plan_name",
    "recipes",
    "solve_position",
]
