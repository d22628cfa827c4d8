"""The explanatory note: each step as formula, substitution, result."""

from plans.cycle.words import change_points, no_full_turn

from .report import Step, note, warnings
from .words import UNITS, T

__all__ = ["UNITS", "Step", "T", "change_points", "no_full_turn", "note", "warnings"]
