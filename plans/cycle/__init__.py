"""The whole turn: extremes, stroke, θ and K, the positions drawn, and the words for angles."""

from .analysis import (  # noqa: F401
    Cycle,
    Output,
    SHOWN_FROM,
    TWO_PI,
    analyse_cycle,
    at_rest,
    change_angles,
    file_range,
    find_output,
    grashof_class,
    no_output,
    output_of,
    outputs,
    outside,
    outside_range,
    reachable,
    reachable_cycle,
    shown_from,
    summary,
    table_angle,
)
from .positions import (  # noqa: F401
    Drawn,
    FAR,
    drawn,
    positions_at,
    reach,
    trajectory_angles,
)

__all__ = ['Cycle', 'Drawn', 'FAR', 'Output', 'SHOWN_FROM', 'TWO_PI', 'analyse_cycle', 'at_rest', 'change_angles', 'drawn', 'file_range', 'find_output', 'grashof_class', 'no_output', 'output_of', 'outputs', 'outside', 'outside_range', 'positions_at', 'reach', 'reachable', 'reachable_cycle', 'shown_from', 'summary', 'table_angle', 'trajectory_angles']
