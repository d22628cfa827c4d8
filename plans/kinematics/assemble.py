"""The one group loop: the crank, then each group in its order of attachment, as on paper.

Both paths run it: the recorded solve (:class:`plans.kinematics.groups.Recorded`, for
:meth:`plans.kinematics.Solver.solve` and ``solve_one``) and the bulk sweep
(:class:`plans.kinematics.sweep.Block`). Each path supplies its state and its per-kind
step (the dyad's ``recorded`` or ``bulk``, :data:`plans.kinematics.dyads.DYADS`); the
order is this loop's alone:

1. the crank's points, from its state (the path set it up: pivot, e^{iφ}, ω1, ε1), and
   a second input's (a mechanism of two degrees of freedom);
2. for each group, its step at the group's sign: the kernel finds its new point, the
   states of its two links and any points of another link it passes (coincident points);
3. the other points of its two links, from their states (rigid-body formulas);
4. the coincident points, after the links' own, each with the kernel's own values.

A path is an object with ``fill(link)``, ``step(dyad, group, setup, sigma)`` returning
the coincident points, and ``coincide(points)``.
"""

from __future__ import annotations

from collections.abc import Callable


def assemble(path, setup, sigma: Callable[[int], object], count: int | None = None):
    """Solve ``setup``'s mechanism on ``path``: every group, or its first ``count``;
    ``sigma(i)`` is the i-th group's sign (a number, or an array of the path's angles).
    Returns ``path``."""
    step, fill, coincide = path.step, path.fill, path.coincide  # read once: one angle's
    for link in setup.inputs:                                     # plan runs this loop
        fill(link)
    for i, (g, dyad, own) in enumerate(setup.steps[:count]):
        found = step(dyad, g, own, sigma(i))
        fill(g.a)
        fill(g.b)
        if found:
            coincide(found)
    return path
