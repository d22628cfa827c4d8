"""The whole turn: extremes, stroke, θ and K, the positions drawn, and the words for angles."""

from plans.model.outputs import Output, find_output, no_output, output_of, outputs

from .analysis import (
    TWO_PI,
    Cycle,
    analyse_cycle,
    at_rest,
    grashof_class,
    outside_range,
    rate_signs,
    reachable,
    reachable_cycle,
    table_angle,
)
from .positions import (
    FAR,
    Drawn,
    drawn,
    positions_at,
    reach,
    trajectory_angles,
)
from .words import (
    WORDS,
    change_angles,
    change_points,
    file_range,
    no_full_turn,
    outside,
    shown_from,
    summary,
    worded,
)

__all__ = [
    "FAR",
    "TWO_PI",
    "WORDS",
    "Cycle",
    "Drawn",
    "Output",
    "analyse_cycle",
    "at_rest",
    "change_angles",
    "change_points",
    "drawn",
    "file_range",
    "find_output",
    "grashof_class",
    "no_full_turn",
    "no_output",
    "output_of",
    "outputs",
    "outside",
    "outside_range",
    "positions_at",
    "rate_signs",
    "reach",
    "reachable",
    "reachable_cycle",
    "shown_from",
    "summary",
    "table_angle",
    "trajectory_angles",
    "worded",
]
