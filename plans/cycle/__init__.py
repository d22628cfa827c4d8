"""The whole turn: extremes, stroke, θ and K, the positions drawn, and the words for angles."""

from plans.model.outputs import Output, find_output, no_output, output_of, outputs

from .analysis import (
    SHOWN_FROM,
    TWO_PI,
    Cycle,
    analyse_cycle,
    at_rest,
    change_angles,
    file_range,
    grashof_class,
    outside,
    outside_range,
    reachable,
    reachable_cycle,
    shown_from,
    summary,
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

__all__ = [
    "FAR",
    "SHOWN_FROM",
    "TWO_PI",
    "Cycle",
    "Drawn",
    "Output",
    "analyse_cycle",
    "at_rest",
    "change_angles",
    "drawn",
    "file_range",
    "find_output",
    "grashof_class",
    "no_output",
    "output_of",
    "outputs",
    "outside",
    "outside_range",
    "positions_at",
    "reach",
    "reachable",
    "reachable_cycle",
    "shown_from",
    "summary",
    "table_angle",
    "trajectory_angles",
]
