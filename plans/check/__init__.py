"""Check a hand-drawn plan against the computed one, and name the mistake.

Inside, from the bottom: ``words`` (the check's words, a table per language), ``items``
(plans, scale factors, tolerance, a measured item), ``describe`` (a mistake and a
look-alike in words), ``replay`` (the plans as a student draws them, and the mistakes),
``measured`` (reading a measurement file), ``verdict`` (comparing and diagnosing).
"""

from .describe import lookalike_lines
from .items import Item, Tolerance, parse_tolerance
from .measured import Measurement, load
from .replay import Mistake
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
    "Item",
    "Lookalike",
    "Measurement",
    "Mistake",
    "Tolerance",
    "check",
    "compare",
    "diagnose",
    "load",
    "lookalike_lines",
    "lookalikes",
    "parse_tolerance",
    "rebuild",
]
