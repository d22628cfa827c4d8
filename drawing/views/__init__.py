"""The views of a sheet, each built in its own box of sheet millimetres: the plan of
positions (:mod:`.positions`), the vector plans (:mod:`.plans`), the kinematic diagrams
(:mod:`.diagrams`), the tables and the note (:mod:`.tables`), on what they share
(:mod:`.common`); sheet 2's, the force analysis: the mechanism, the groups and the force
plans (:mod:`.forces`, their arrows :mod:`.arrows`), Zhukovsky's lever (:mod:`.lever`),
M_у(φ) and P(S) (:mod:`.force_diagrams`) and their tables (:mod:`.force_tables`)."""

from .common import (
    BLANK_PAD,
    CAPTION,
    CAPTION_OVER,
    CAPTION_STYLES,
    HEAD,
    JOINT_R,
    LETTER,
    PAD,
    SHARED,
    SMALL_CAPTION,
    WORDS,
    View,
    caption_lines,
    caption_texts,
    captioned_width,
    centred,
    notation,
    retitled,
)
from .diagrams import (
    NUMBER_BESIDE,
    NUMBER_CLEAR,
    NUMBER_GAPS,
    NUMBERS_APART,
    diagram_curves,
    diagrams_view,
)
from .plans import plan_view, vector_plan_view
from .positions import positions_view
from .tables import PART_GAP, note_view, omega_table_view, segments_table_view

__all__ = [
    "BLANK_PAD",
    "CAPTION",
    "CAPTION_OVER",
    "CAPTION_STYLES",
    "HEAD",
    "JOINT_R",
    "LETTER",
    "NUMBERS_APART",
    "NUMBER_BESIDE",
    "NUMBER_CLEAR",
    "NUMBER_GAPS",
    "PAD",
    "PART_GAP",
    "SHARED",
    "SMALL_CAPTION",
    "WORDS",
    "View",
    "caption_lines",
    "caption_texts",
    "captioned_width",
    "centred",
    "diagram_curves",
    "diagrams_view",
    "notation",
    "note_view",
    "omega_table_view",
    "plan_view",
    "positions_view",
    "retitled",
    "segments_table_view",
    "vector_plan_view",
]
