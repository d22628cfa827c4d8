"""What solving a mechanism needs of it beyond the assembly signs, worked out once.

A :class:`Setup` is built with a :class:`plans.kinematics.Solver` and shared by the
solvers of the same mechanism and structure (another assembly, other flips): each group's
own setup (its dyad's: lengths, own coordinates, the names and equations of its
constructions), the frame's state on Python numbers, which points each link's fill places,
and, worked out on the first sweep, the sweep's layout. It is a value: nothing writes
into it once it is made.
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import dataclass
from functools import cached_property

from plans.kinematics import sweep
from plans.kinematics.dyads import DYADS, Dyad
from plans.kinematics.groups import frame_points
from plans.model import Mechanism
from plans.model.structure import Group, Structure, analyse


@dataclass(frozen=True, eq=False)
class Setup:
    """The mechanism's setup for solving (module docstring)."""

    mech: Mechanism
    structure: Structure
    #: links that never turn: a guide on one carries no Coriolis term
    translating: frozenset[int]
    #: per group, in the order of attachment: (the group, its dyad, the group's own setup)
    steps: tuple[tuple[Group, Dyad, Mapping], ...]
    #: the frame's state and points on Python numbers: (state, pos, vel, acc, owner)
    scalar_frame: tuple
    #: per link, the points its fill places: those no link solved before it has placed
    #: (a group's new hinge is placed again, from the first of its two links)
    todo: Mapping[int, tuple[tuple[str, complex], ...]]
    #: the input links, the first driver's first: their points are filled before the groups
    inputs: tuple[int, ...] = ()

    @classmethod
    def of(cls, mech: Mechanism, structure: Structure | None = None) -> Setup:
        """The setup of ``mech`` (its structure analysed unless given)."""
        structure = structure or analyse(mech)
        translating = mech.translating()
        steps = tuple((g, DYADS[g.kind], DYADS[g.kind].setup(mech, translating, g))
                      for g in structure.groups)
        return cls(mech, structure, translating, steps, frame_points(mech, 0j, 0.0),
                   _todo(mech, steps), tuple(d.link for d in mech.drivers))

    @cached_property
    def layout(self):
        """The names a sweep fills, with the value of those that are constant
        (:func:`plans.kinematics.sweep.layout`): solved at one angle, on the first sweep."""
        return sweep.layout(self)


def _todo(mech: Mechanism, steps) -> Mapping[int, tuple[tuple[str, complex], ...]]:
    """Which points each link's fill places, following the group loop's order
    (:func:`plans.kinematics.assemble.assemble`): the crank, then each group's two links
    and the coincident points its step adds."""
    placed = set(mech.frame)
    todo: dict[int, tuple[tuple[str, complex], ...]] = {}

    def fill(lid: int) -> None:
        todo[lid] = tuple((name, local) for name, local in mech.links[lid].points.items()
                          if name not in placed)
        placed.update(name for name, _ in todo[lid])

    for d in mech.drivers:
        fill(d.link)
    for g, dyad, own in steps:
        fill(g.a)
        fill(g.b)
        placed.update(own[key] for key in dyad.coincident if own[key])
    return todo
