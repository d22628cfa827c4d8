"""Check a hand-drawn plan against the computed one, and name the mistake."""

from .verdict import (  # noqa: F401
    CheckResult,
    Deviation,
    Diagnosis,
    Finding,
    Lookalike,
    check,
    compare,
    diagnose,
    lookalikes,
    rebuild,
)

__all__ = ['CheckResult', 'Deviation', 'Diagnosis', 'Finding', 'Lookalike', 'check', 'compare', 'diagnose', 'lookalikes', 'rebuild']
