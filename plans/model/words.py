"""The model's words, one table per language: how a crank angle's convention is said.

A third language is one more table here, with the same keys.
"""

from __future__ import annotations

#: "60° from +x (30° from +y, cw, as the file gives it)": the reference's preposition, the
#: file's own convention said as such, and each sense of measuring ("measured" in the
#: file: "ccw" or "cw")
WORDS = {
    "en": {
        "from": "from",
        "as_given": "as the file gives it",
        "m": "m",
        "s": "s",
        "along": "along",
        "measured": {"ccw": "ccw", "cw": "cw"},
    },
    "ru": {
        "from": "от",
        "as_given": "как задано в файле",
        "m": "м",
        "s": "с",
        "along": "вдоль",
        "measured": {"ccw": "против часовой стрелки", "cw": "по часовой стрелке"},
    },
}
