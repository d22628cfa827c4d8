"""Synthesis by the time-ratio coefficient K and by given positions: the links from the
requirements, every answer checked by the engine, written as a mechanism file.

>>> d = synthesise(read_pairs(["crank-rocker", "K=1.25", "psi_deg=32", "CD=0.29", "BC=0.26"]))
>>> [round(s.lengths["AD"], 6) for s in d.solutions]      # both assemblies
[0.261013, 0.46764]
>>> check(d).ok
True
"""

from __future__ import annotations

from dataclasses import replace

from plans.synthesis import positions, rocker, slider, slotted
from plans.synthesis.design import (
    Curve,
    Design,
    K_of,
    Mark,
    Problem,
    Solution,
    impossible,
    theta_of,
)
from plans.synthesis.mechfile import mechanism_dict, mechanism_toml
from plans.synthesis.problem import KINDS, read_file, read_pairs
from plans.synthesis.verify import TOLERANCE, Check, Row, check

__all__ = [
    "KINDS", "TOLERANCE", "Check", "Curve", "Design", "K_of", "Mark", "Problem", "Row",
    "Solution", "check", "mechanism_dict", "mechanism_toml", "read_file", "read_pairs",
    "synthesise", "theta_of",
]

_BY_KIND = {"crank-rocker": rocker.synthesise, "crank-slider": slider.synthesise,
            "slotted-link": slotted.synthesise, "function": positions.synthesise,
            "coupler": positions.synthesise}


def synthesise(problem: Problem) -> Design:
    """Every solution of ``problem``, the chosen one its ``solution`` or the first (the
    best by its criterion)."""
    design = _BY_KIND[problem.kind](problem)
    if problem.solution is not None:
        n = len(design.solutions)
        if problem.solution > n:
            raise impossible(problem, "solution", f"solution {problem.solution} asked for, but "
                             f"the requirements have {n} solution{'s' if n > 1 else ''}")
        design = replace(design, chosen=problem.solution - 1)
    return design
