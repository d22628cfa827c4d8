"""The explanatory note: each step as formula, substitution, result."""

from .report import (
    UNITS,
    Step,
    T,
    change_points,
    no_full_turn,
    note,
    warnings,
)

__all__ = ["UNITS", "Step", "T", "change_points", "no_full_turn", "note", "warnings"]
