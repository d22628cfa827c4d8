"""The recorded path: each group's solution kept as the two routes of its velocity and
acceleration constructions, with the names, equations and conditions of the group.

:class:`Recorded` is the state the group loop (:func:`plans.kinematics.assemble.assemble`)
works on for :meth:`plans.kinematics.Solver.solve` and ``solve_one``; each dyad kind's
recorded step (:mod:`plans.kinematics.dyads`) runs its kernel and records the numbers with
the helpers here. It works on numpy arrays of angles or on Python numbers of one angle
(``xp``); on one angle a group that does not close raises :class:`ScalarFallback`, and
the array path words the error.
"""

from __future__ import annotations

import math

import numpy as np

from plans import tolerances
from plans.kinematics.kernels import record
from plans.kinematics.records import Construction, GroupSolution, LinkState, Motion, frozen
from plans.model import Guide, Mechanism
from plans.model.structure import Group


class ScalarFallback(Exception):
    """The one-angle scalar path met a group that does not close or a division by zero:
    the array path then finds and words the failure."""


#: (valid, gap, singular, margin) of a group that closes at the one angle solved
CLOSED = (True, 0.0, False, None)


def one_closes(xp, closes) -> bool:
    """True on the one-angle path where the group closes; there it leaves as soon as it
    misses (:class:`ScalarFallback`), and the array path words why. False for arrays,
    whose closure :func:`closure` or :func:`never_misses` records angle by angle.

    A group so writes ``CLOSED if one_closes(xp, r.closes) else closure(…)``: the
    arguments of the array's closure are not even evaluated for one angle, and no
    function is made to defer them (a lambda would make the group's locals cells, slower
    to read at every use)."""
    if not xp.scalar:
        return False
    if not closes:
        raise ScalarFallback
    return True


def closure(closes, margin, scale):
    """(valid, gap, singular, margin) of a group over arrays of angles. ``margin``: how
    far inside its limit the group is, in metres, negative where it misses; ``scale``:
    the group's size, which the recorded margin is a fraction of."""
    gap = np.maximum(-margin, 0.0)
    return closes, gap, ~closes & (gap <= tolerances.DEAD_GAP * scale), margin * (1.0 / scale)


def never_misses(closes, shape):
    """(valid, gap, singular, margin) over arrays of angles of a group that cannot miss,
    only fail at a dead point (parallel guides): its gap is 0 and where it does not close
    it is singular; its margin is infinite, and minus infinity where its point is
    nowhere."""
    closes = np.broadcast_to(closes, shape)
    return closes, np.zeros(shape), ~closes, np.where(closes, np.inf, -np.inf)


def solution(g: Group, w: dict, point: str, v, a, vroute, aroute, sine, closed):
    """A group's recorded solution: the velocity and acceleration constructions of its
    new ``point``, where the group closes, and the words of its conditions (``w``)."""
    valid, gap, singular, margin = closed
    return record(GroupSolution, (
        g, record(Construction, (point, v, vroute, sine, w["veq"])),
        record(Construction, (point, a, aroute, sine, w["aeq"])),
        valid, gap, w["admissible"], singular, w["singular"], margin,
    ))


def pose_from_two(P, pl, C, cl):
    """Origin and rotor of a link from two world points and their own coordinates."""
    r = (C - P) / (cl - pl)
    r = r / abs(r)
    return P - r * pl, r


def guide_motion(guide: Guide, states, translating: frozenset[int]):
    """A world point of the guide, its direction, the motion of its link there, and the
    link's ω, ε: None where the link never turns (no Coriolis term, as for the frame)."""
    st = states[guide.link]
    G = st.pos(guide.point)
    u = st.rotor * guide.direction
    if guide.link == 0:
        return G, u, 0j, 0j, None, None
    if guide.link in translating:
        return G, u, st.v, st.a, None, None
    return G, u, st.vel(G), st.acc(G), st.omega, st.epsilon


def driver_inputs(mech: Mechanism, x):
    """Each driver's (q, q′, q″) where the mechanism is at ``x`` (its solver's parameter:
    :meth:`plans.model.Mechanism.inputs_at`)."""
    return mech.inputs_at(x)


def driver_state(d, q, dq, ddq, zc, zero, xp) -> LinkState:
    """The state of the input link ``d`` at its coordinate ``q`` with rates ``dq``,
    ``ddq``: a crank at the angle q (rad), turning at ω = q′, ε = q″; a slider on its
    fixed guide at the travel q (m), moving at V = q′, a = q″ along it."""
    if d.linear:
        u = d.guide.direction
        return record(LinkState, (zc + d.origin + q * u - u * d.local, zc + u, zc + dq * u, zero,
                                  zc + ddq * u, zero))
    rotor = complex(math.cos(q), math.sin(q)) if xp.scalar else np.exp(1j * np.asarray(q))
    return record(LinkState, (zc + d.origin, rotor, zc, zero + dq, zc, zero + ddq))


def frame_points(mech: Mechanism, zc, zero):
    """The frame's state and its points: fixed, at rest. ``zc``, ``zero``: a complex and
    a real 0 of the path's kind (Python numbers, or arrays of the angles' shape)."""
    pos = {name: zc + xy for name, xy in mech.frame.items()}
    rest = dict.fromkeys(pos, zc)
    return (LinkState(zc, zc + 1, zc, zero, zc, zero), pos, rest, rest,
            dict.fromkeys(pos, 0))


class Recorded:
    """The recorded path's state over one solve (:func:`plans.kinematics.assemble.assemble`):
    every point's position, velocity and acceleration, every link's state, the link each
    point belongs to, each group's recorded solution and where the mechanism closes.

    ``xp``: :data:`plans.kinematics.kernels.SCALAR` for one angle on Python numbers (the
    frame's part is then the setup's, copied), :data:`plans.kinematics.kernels.ARRAY` for
    arrays; ``rotor``: the crank's, e^{iφ}.
    """

    __slots__ = ("acc", "coincident", "owner", "phi", "pos", "scalar", "solutions", "states",
                 "todo", "translating", "valid", "vel", "xp")

    def __init__(self, setup, xp, phi, zero, rotor):
        self.xp, self.phi, self.scalar = xp, phi, xp.scalar
        self.todo, self.translating = setup.todo, setup.translating
        if xp.scalar:  # the frame's part is the same at every angle: copied, not rebuilt
            frame_state, pos, vel, acc, owner = setup.scalar_frame
        else:
            frame_state, pos, vel, acc, owner = frame_points(setup.mech, zero * 0j, zero)
        self.states: dict[int, LinkState] = {0: frame_state}
        self.pos, self.vel, self.acc, self.owner = dict(pos), dict(vel), dict(acc), dict(owner)
        self.solutions: list[GroupSolution] = []
        self.valid = True if xp.scalar else np.ones(phi.shape, dtype=bool)
        self.coincident: dict[str, str] = {}
        mech = setup.mech
        drv = mech.driver
        zc = frame_state.v
        if mech.timing is None and not drv.linear:  # the crank at φ, at its ω and ε
            self.states[drv.link] = record(LinkState, (
                zc + drv.origin, rotor, zc, zero + drv.omega, zc,
                zero if drv.epsilon == 0 else zero + drv.epsilon))
        else:
            for d, (q, dq, ddq) in zip(mech.drivers, driver_inputs(mech, phi), strict=True):
                self.states[d.link] = driver_state(d, q, dq, ddq, zc, zero, xp)

    def step(self, dyad, g: Group, own: dict, sigma):
        """Group ``g`` by its dyad's recorded step; the points it found on another link
        (coincident points), as (name, link, base point, velocity, acceleration)."""
        sol, extra = dyad.recorded(self.xp, g, own, sigma, self.states, self.pos, self.vel,
                                   self.acc, self.translating)
        self.solutions.append(sol)
        if not self.scalar:
            self.valid &= sol.valid
        return extra

    def fill(self, lid: int) -> None:
        """The points of link ``lid`` that no link solved before it has placed (a group's
        new hinge is placed again here, from the first of its two links): which those are
        follows from the order of the groups alone (:attr:`plans.kinematics.setup.Setup.todo`)."""
        todo = self.todo[lid]
        if not todo:
            return
        origin, rotor, v, w, a, e = self.states[lid]
        jw, kk = 1j * w, 1j * e - w * w
        pos, vel, acc, owner = self.pos, self.vel, self.acc, self.owner
        for name, local in todo:
            r = rotor * local
            pos[name] = origin + r
            vel[name] = v + jw * r
            acc[name] = a + kk * r
            owner[name] = lid

    def coincide(self, extra) -> None:
        """The coincident points a step found, with the kernel's own values."""
        for name, link, base, v, a in extra:
            self.pos[name], self.vel[name], self.acc[name] = self.pos[base], v, a
            self.owner[name] = link
            self.coincident[name] = base

    def motion(self) -> Motion:
        return frozen(Motion, phi=self.phi, links=self.states, position=self.pos,
                      velocity=self.vel, acceleration=self.acc, point_link=self.owner,
                      groups=tuple(self.solutions), valid=self.valid,
                      coincident=self.coincident)
