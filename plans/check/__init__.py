"""Check a hand-drawn plan against the computed one, and name the mistake.

Inside, from the bottom: ``words`` (the check's words, a table per language), ``items``
(plans, scale factors, tolerance, a measured item), ``reading`` (numbers with their units
and senses as a student writes them), ``describe`` (a mistake and a look-alike in words),
``replay`` (the plans as a student draws them, and the mistakes), ``forces`` (the force
analysis as a student draws it on those plans, and its mistakes), ``force_items`` (the
force analysis's items of a file, by the names a student types), ``measured`` (reading a
measurement file), ``rebuild`` (the student's plans from the measured lengths, for the
overlay), ``verdict`` (comparing and diagnosing).
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
