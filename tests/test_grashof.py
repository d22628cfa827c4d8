"""The four-bar's Grashof class, read from what its links join, not from their numbers."""

import json
import re

import numpy as np
import pytest
from support import run

from plans.cycle import analyse_cycle, grashof_class
from plans.model import from_dict


def fourbar(coupler_id: int, rocker_id: int, crank: float, coupler: float, rocker: float,
            frame: float, angle: float = 50.0) -> str:
    """A four-bar A–B–C–D with its coupler BC and rocker DC numbered as asked."""
    return f"""
name = "four-bar"
output = "C"
[frame]
A = [0.0, 0.0]
D = [{frame!r}, 0.0]
[driver]
link = 1
angle_deg = {angle!r}
omega = 12
[links.1]
axis = ["A", "B"]
points = {{ B = {crank!r} }}
[links.{coupler_id}]
axis = ["B", "C"]
points = {{ C = {coupler!r} }}
[links.{rocker_id}]
axis = ["D", "C"]
points = {{ C = {rocker!r} }}
[assembly]
C = "above BD"
"""


CASES = [
    # crank 0.08, coupler 0.28, rocker 0.18, frame 0.30 (the engineer's crank-rocker)
    ((0.08, 0.28, 0.18, 0.3, 50.0), "crank-rocker (Grashof: 0.38 ≤ 0.46)"),
    ((0.12, 0.15, 0.1, 0.2, 90.0), "double rocker (non-Grashof: 0.3 > 0.27)"),
    ((0.1, 0.2, 0.1, 0.2, 60.0),
     "change-point linkage (Grashof equality: 0.3 ≤ 0.3): its links come in line at change points"),
    # the rocker shortest, the coupler long: which link is which decides the class
    ((0.3, 0.35, 0.15, 0.4, 60.0),
     "rocker-crank (Grashof, the shortest link is the rocker, which turns fully: 0.55 ≤ 0.65)"),
    ((0.3, 0.15, 0.35, 0.4, 60.0),
     "double rocker (Grashof, the shortest link is the coupler: 0.55 ≤ 0.65)"),
]


@pytest.mark.parametrize(("lengths", "want"), CASES)
def test_the_class_does_not_depend_on_which_link_is_numbered_first(lengths, want):
    """With the rocker numbered 2 and the coupler 3 the group's first joint is the rocker's
    pivot D, and the class had been left out (None)."""
    *sizes, angle = lengths
    got = [analyse_cycle(from_dict(__import__("tomllib").loads(fourbar(c, r, *sizes, angle)),
                                   "<f>")).grashof for c, r in ((2, 3), (3, 2))]
    assert got == [want, want]


def test_solve_and_cycle_give_the_class_of_a_four_bar_numbered_either_way(capsys, tmp_path):
    for c, r in ((2, 3), (3, 2)):
        path = tmp_path / f"fb{c}{r}.toml"
        path.write_text(fourbar(c, r, 0.08, 0.28, 0.18, 0.3).replace(
            "D = [0.3, 0.0]", "D = [0.3, 0.05]"), "utf-8")
        code, out, err = run(capsys, "solve", path)
        assert code == 0, err
        assert "  four-bar: crank-rocker (Grashof: 0.384138 ≤ 0.46)\n" in out
        code, out, err = run(capsys, "cycle", path, "--json", "--positions", "2")
        assert code == 0, err
        assert json.loads(out)["cycle"]["grashof"] == "crank-rocker (Grashof: 0.384138 ≤ 0.46)"


@pytest.mark.parametrize(("lengths", "message"), [
    ((-0.03, 0.1, 0.08, 0.09), "the crank a must be a positive length (m), got -0.03"),
    ((0.03, 0.0, 0.08, 0.09), "the coupler b must be a positive length (m), got 0.0"),
    ((0.03, 0.1, float("nan"), 0.09), "the rocker c must be a positive length (m), got nan"),
    ((0.03, 0.1, 0.08, "0.09"), "the frame d must be a positive length (m), got '0.09'"),
])
def test_grashof_class_refuses_what_is_not_a_length(lengths, message):
    """grashof_class(-0.03, 0.1, 0.08, 0.09) said "crank-rocker (Grashof: 0.07 ≤ 0.17)"."""
    with pytest.raises(ValueError, match=re.escape(f"grashof_class: {message}")):
        grashof_class(*lengths)
    assert grashof_class(np.float32(0.03), 1, 0.08, np.float64(0.09)).startswith("double rocker")
