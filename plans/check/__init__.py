"""Check a hand-drawn plan against the computed one, and name the mistake."""

from .verdict import (
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

__all__ = [
    "CheckResult",
    "Deviation",
    "Diagnosis",
    "Finding",
    "Lookalike",
    "check",
    "compare",
    "diagnose",
    "lookalikes",
    "rebuild",
]
