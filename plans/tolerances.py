"""Every threshold the engine judges by, each with its reason: one place to read them.

The engine's numbers are exact to rounding (the bench's largest error against a 30-digit
reference is 2.6e-15); what it must judge (is a plan singular, are two points one, is a
value rounding of 0) it judges by these. Modules read them from here when they judge, as
``tolerances.SINGULAR_SINE``, not as a copy taken at import: a test (or a reader trying
another threshold) sets one here and every judgement follows.

The ground: no project imports.
"""

from __future__ import annotations

# ---------------------------------------------------------------------------------------
# the conditioning of a plan: the sine between the two lines a group's plans intersect
# ---------------------------------------------------------------------------------------

#: below this |sin| of the angle between the two lines a plan is singular (and two guides
#: are parallel: a PRP or RPP group then has no unique position; a slotted link's block
#: this close, relative to the loop, to the rocker's pivot leaves the rocker's ω undefined)
SINGULAR_SINE = 1e-10

#: below this |sin| (about 2°) a position is reported as near-singular
WARN_SINE = 0.035

#: the relative error of a plan's velocities and accelerations where its lines meet at
#: sine s is within about LOSS·ε/s² (κ²·ε, κ = 1/s: the position's error tilts the lines
#: it intersects): 11 on the stiff scenes (README); at a crank's limit position, against
#: the 30-digit reference, 0.7 (1.5e-3 at s = 3.3e-7)
LOSS = 11.0

#: a plan's possible error is said in a warning from this share of its largest value on:
#: half a unit of the fourth digit a report prints
PRINTED = 5e-5

# ---------------------------------------------------------------------------------------
# change points: a group's links in line, its two assemblies meeting
# ---------------------------------------------------------------------------------------

#: beside a change point (within :data:`CHANGE_NEAR` rad of one of the group's) a sine
#: below this makes the position singular: there the acceleration plan's right-hand side
#: carries the velocities' error (κ²·ε, κ = 1/sin), and the nearly parallel lines
#: multiply it by κ again; measured on a parallelogram, ε of the rocker was off by
#: 7·κ³·ε of ω1², 2e-6 at sin = 1e-3 and 1e-3 at sin = 1e-4
CHANGE_SINE = 1e-3
#: the same for a slotted link's pivot figure, whose accelerations lose 0.05–0.4·κ³·ε
#: there (its pivot on the crank circle: 1e-8 at 1.1e-3, 1e-4 at 1.1e-4): about 3e-6 here
CHANGE_PIVOT = 3e-4
#: rad: how near a change point a crank angle is "beside" it
CHANGE_NEAR = 0.05
#: rad: a crank angle this near a change point is on it (the change points are found to
#: about 1e-10 rad)
AT_CHANGE_POINT = 1e-9

#: a group whose margin (a fraction of its size) is within this of 0 has its links in
#: line to rounding: equal lengths typed in decimal meet to about 1e-16, and Grashof's
#: equality is judged to 1e-12 as well
IN_LINE = 1e-12

#: a group that misses closing by no more than this share of its size is at its limit,
#: a dead point (its links in line, parallel guides), not a group whose links do not reach
DEAD_GAP = 1e-9

#: how far past a change point (rad, in the crank's sense) the points that are nowhere on
#: it are placed (:meth:`plans.kinematics.Solver.solve`): the positions are then off by
#: about 1e-9 of the links' lengths, where rounding alone would leave the rocker's
#: direction 0/0
LIMIT_STEP = 1e-9

#: how far past an angle where a group's two assemblies meet its hints are read (rad):
#: there (a change point, a limit of the crank's range) no hint can tell them apart,
#: while 1e-4 rad on they stand some 1e-4 of the group's size apart
PAST_MEETING = 1e-4

#: two assemblies that put a point within this share of the mechanism's size of one
#: another put it in one place (a hint on it chooses neither)
SAME_PLACE = 1e-9

# ---------------------------------------------------------------------------------------
# assembly hints: "above BD", "right of C"
# ---------------------------------------------------------------------------------------

#: a point within this fraction of the distances from a hint's line (or level with its
#: point) lies on it, on neither side
ON_LINE = 1e-9

#: above and below a vertical line (left and right of a horizontal one) are not defined:
#: the hint is refused. Only a line vertical to rounding: one a degree off still has a
#: side that points up, and a table's own hint ("C above BD") passes near vertical as
#: the crank turns
UPRIGHT = 1e-9

# ---------------------------------------------------------------------------------------
# the plans of one position
# ---------------------------------------------------------------------------------------

#: a plan's segment shorter than this share of its longest vector is 0: rounding left by
#: two equal vectors subtracted (a relative acceleration that is 0, a translating link's
#: points) is a few 1e-16 of them, and at an extreme position, after a group's fifty
#: operations, up to 1.2e-14 (variant 3's rocker at rest: pc = 1.6e-12 mm of 137 mm),
#: never a length to draw, measure or print. It is below what the engine can resolve
#: (2.6e-15 at worst against the 30-digit reference, a few ulps per step). A real small
#: value (a^n = V²/l 1e-4° from the press's extreme position, 4.5e-13 of the plan) stays.
NOISE = 1e-13

#: |Im| of a similarity ratio below which the point is in line with its two bases
#: (:attr:`plans.plan.Source.in_line`): its step is then worded as a ratio of lengths
RATIO_IN_LINE = 1e-12

# ---------------------------------------------------------------------------------------
# the cycle
# ---------------------------------------------------------------------------------------

#: below this share of the crank's own (ω1, or its pin's speed for a linear output, to
#: each order) an output's value, rate or acceleration is rounding of 0: at rest
AT_REST = 1e-9

#: rad: the extreme positions and the crank's limit positions are found to this by
#: bisection (the velocities are exact, so the extreme is as exact as the angle)
ANGLE = 1e-13

#: rad: two strokes whose crank angles differ by less are equal (θ = 0, K = 1 exactly)
EQUAL_STROKES = 1e-9

# ---------------------------------------------------------------------------------------
# the mechanism as data
# ---------------------------------------------------------------------------------------

#: m: two points of one link closer than this are the same place
SAME = 1e-12

#: the components of a unit direction below this are 0: a guide along an axis (named
#: x-x or y-y, or by a link's axis), two guides parallel (they may share a name)
AXIAL = 1e-12
