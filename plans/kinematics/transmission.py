"""The transmission angle γ and the pressure angle α = 90° − γ of every group.

A group passes the motion from the links it is attached to on to its own: the force one
link of the group puts on the other acts along a line the group's geometry fixes, and the
point it drives moves along another. The transmission angle is the acute angle between
them, the pressure angle its complement:

* RRR (a coupler PC and a rocker QC): γ between the coupler and the rocker, at C;
* RRP (a rod PC driving a slider along its guide): γ between the rod and the guide's
  normal; α between the rod and the guide, the angle the slider is pushed at;
* RPR (a block sliding in a slotted link about Q): γ between the slot and the normal to
  QP, along which the slot's point moves; α between the slot's normal, along which the
  block pushes, and that motion (90° where the slot runs through Q);
* PRP, RPP (two slides): γ between the two guides.

Each is the acute angle between the two lines the group's velocity plan intersects
(⊥ CP and ⊥ CQ for an RRR group, ⊥ CP and ∥ guide for an RRP one …): the plans are the
method's own record of it, and a dead point, γ = 0, is where those lines are parallel
and the plans singular. γ is found from the lines' directions d1, d2 as
atan2(|d1 × d2|, |d1 · d2|), exact to rounding at every angle (an arcsin of the sine
loses half its digits near 90°, an arccos near 0°).

>>> import math
>>> round(math.degrees(acute(1j, complex(math.cos(1.0), math.sin(1.0)))), 6)
32.70422
"""

from __future__ import annotations

import numpy as np

from plans.model.structure import DyadKind

#: what each kind's γ is measured between, by language
BETWEEN = {
    "en": {
        DyadKind.RRR: "link {a} and link {b} at {C}",
        DyadKind.RRP: "the rod {a} and the normal to the guide {guide}",
        DyadKind.RPR: "the guide {guide} of link {b} and the normal to {Q}{P}",
        DyadKind.PRP: "the guides {guide} and {guide2}",
        DyadKind.RPP: "the guides {guide} and {guide2}",
    },
    "ru": {
        DyadKind.RRR: "между звеньями {a} и {b} в шарнире {C}",
        DyadKind.RRP: "между шатуном {a} и нормалью к направляющей {guide}",
        DyadKind.RPR: "между направляющей {guide} звена {b} и нормалью к {Q}{P}",
        DyadKind.PRP: "между направляющими {guide} и {guide2}",
        DyadKind.RPP: "между направляющими {guide} и {guide2}",
    },
}


def acute(d1, d2):
    """The acute angle (rad, in [0, π/2]) between two lines of directions ``d1``, ``d2``
    (complex numbers or arrays of them)."""
    z = np.conj(d1) * d2
    return np.arctan2(np.abs(z.imag), np.abs(z.real))


def gamma(g):
    """γ (rad) of a group's recorded solution ``g`` (a
    :class:`plans.kinematics.GroupSolution`), at each angle it was solved at."""
    r0, r1 = g.velocity.routes
    out = acute(r0.direction, r1.direction)
    return float(out) if np.ndim(out) == 0 else out


def gammas(motion) -> dict[str, object]:
    """γ of every group of ``motion``, by the group's label (rad)."""
    return {g.group.label: gamma(g) for g in motion.groups}


def between(grp, lang: str = "en") -> str:
    """What the group ``grp``'s γ is measured between, in words: "link 2 and link 3 at C"."""
    s1, s2 = grp.s1, grp.s2
    return BETWEEN[lang][grp.kind].format(a=grp.a, b=grp.b, C=grp.C, P=grp.P, Q=grp.Q,
                                          guide=s1.guide.label if s1 else "",
                                          guide2=s2.guide.label if s2 else "")
