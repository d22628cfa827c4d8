"""The explanatory note: each step as formula, substitution, result."""

from .report import (  # noqa: F401
    Step,
    T,
    UNITS,
    change_points,
    no_full_turn,
    note,
    warnings,
)

__all__ = ['Step', 'T', 'UNITS', 'change_points', 'no_full_turn', 'note', 'warnings']
