"""The loads at a crank position: weights, inertia forces and moments from the exact
acceleration plan, the useful resistance read off its graph, and the file's own forces and
moments, each with where it acts.

    G_i = m_i·g (down, through S_i);  Φ_i = −m_i·a_Si (through S_i);  M_Φi = −J_Si·ε_i

Every value here works on Python numbers at one position and on numpy arrays over many
(:mod:`plans.forces.sweep`): the same formulas for both.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

from plans.errors import InputError
from plans.model import Mechanism
from plans.model.loads import Loads


class Load(NamedTuple):
    """One load on one link: a force through a point, or a couple (``point`` None).

    ``kind``: "weight", "inertia", "inertia moment", "resistance", "force", "moment"."""

    name: str
    kind: str
    link: int
    point: str | None
    at: object  # m, world
    force: object  # N
    moment: object  # N·m, counter-clockwise positive

    @property
    def term(self) -> tuple:
        return (self.at, self.force, self.moment)


class Stroke(NamedTuple):
    """What the resistance graph needs of the cycle: the output's coordinate at the start
    and the end of the working stroke, the crank angles there (rad from +x) and the sense
    the crank turns (+1 counter-clockwise)."""

    point: str
    link: int
    origin: complex  # a point of the output's fixed guide
    direction: complex  # the guide's unit direction
    start: float  # the output's coordinate (m along the guide) at the start of the working stroke
    end: float
    phi_start: float
    phi_end: float
    sense: int

    @property
    def H(self) -> float:
        return abs(self.end - self.start)

    def working(self, phi):
        """Whether the crank angle(s) ``phi`` lie on the working stroke (its two ends
        included), the crank turning from ``phi_start`` to ``phi_end`` in its sense."""
        span = ((self.phi_end - self.phi_start) * self.sense) % (2 * math.pi)
        turn = ((np.asarray(phi) - self.phi_start) * self.sense) % (2 * math.pi)
        return turn <= span + 1e-12


def stroke_of(mech: Mechanism, cycle, solver) -> Stroke | None:
    """The working stroke of ``cycle`` (:func:`plans.cycle.analyse_cycle`) for a slider
    output on a fixed guide; None where the cycle has no such output or no full turn."""
    out = cycle.output
    if out is None or out.kind != "linear" or not cycle.full_turn or len(cycle.extremes) != 2:
        return None
    guide = mech.slider_of(out.link).guide
    ends = []
    for phi in cycle.extremes:
        m = solver.solve_one(phi)
        ends.append(((m.position[out.point] - guide.point) * guide.direction.conjugate()).real)
    sense = 1 if mech.driver.omega > 0 else -1
    return Stroke(
        out.point,
        out.link,
        guide.point,
        guide.direction,
        ends[0],
        ends[1],
        cycle.extremes[0],
        cycle.extremes[1],
        sense,
    )


def resistance(loads: Loads, stroke: Stroke | None, phi, position, source: str = ""):
    """The useful resistance at crank angle(s) ``phi``: (its magnitude P (N), its force
    (N, complex), s (m from the start of the working stroke)); None where the file gives
    no graph. The force acts along the guide against the output's motion: on the working
    stroke against the way from its start to its end, on the idle stroke the other way."""
    graph = loads.resistance
    if graph is None:
        return None
    if stroke is None:
        raise InputError(
            source,
            "loads.resistance: a P(S) graph needs an output that slides on a fixed "
            "guide and a crank that makes a full turn (output = the slider's point)",
        )
    H = stroke.H
    xs = np.asarray(graph.s) * (H if graph.relative else 1.0)
    if not graph.relative and xs[-1] > H * (1 + 1e-9) + 1e-12:
        raise InputError(
            source,
            f"loads.resistance.s: the graph runs to s = {xs[-1]:g} m, beyond the "
            f"stroke H = {H:.6g} m: s is measured from the start of the working stroke",
        )
    way = 1.0 if stroke.end >= stroke.start else -1.0
    s = ((position[stroke.point] - stroke.origin) * stroke.direction.conjugate()).real
    s = (s - stroke.start) * way
    s = np.clip(s, 0.0, H)  # within rounding of the stroke's two ends
    working = stroke.working(phi)
    P = np.where(working, np.interp(s, xs, np.asarray(graph.P, dtype=float), right=0.0), graph.idle)
    force = np.where(working, -way, way) * P * stroke.direction
    if np.ndim(P) == 0:
        return float(P), complex(force), float(s)
    return P, force, s


def at_position(mech: Mechanism, loads: Loads, motion, phi, stroke: Stroke | None = None) -> list[Load]:
    """Every load at the position(s) of ``motion`` (a :class:`plans.kinematics.Motion`, on
    Python numbers or arrays), in the order the note lists them: per link its weight, its
    inertia force and moment, then the file's forces and moments, then the resistance."""
    out: list[Load] = []
    g = loads.g
    pos, acc = motion.position, motion.acceleration
    for lid in sorted(loads.masses):
        mass = loads.masses[lid]
        S = mass.centre
        if mass.mass:
            out.append(Load(f"G{lid}", "weight", lid, S, pos[S], -1j * (mass.mass * g), 0.0))
            out.append(Load(f"Φ{lid}", "inertia", lid, S, pos[S], -mass.mass * acc[S], 0.0))
        if mass.J and loads.inertia_moments:
            eps = motion.links[lid].epsilon
            out.append(Load(f"M_Φ{lid}", "inertia moment", lid, None, pos[S], 0j, -mass.J * eps))
    for f in loads.forces:
        lid = f.link if f.link is not None else min(i for i in mech.links_of(f.point) if i)
        size = f.magnitude
        if size is None:  # so many times a link's weight (seed 001: 100·G2)
            m = loads.masses.get(f.weight_of)
            size = f.times * (m.mass if m else 0.0) * g
        out.append(
            Load(f.name, "force", lid, f.point, pos[f.point], size * _direction(mech, motion, f, lid), 0.0)
        )
    for mo in loads.moments:
        value = mo.moment
        if mo.rule is not None:
            w = motion.links[mo.link].omega
            value = np.sign(w) * value * (1.0 if mo.rule == "along omega" else -1.0)
            value = float(value) if np.ndim(value) == 0 else value
        out.append(Load(mo.name, "moment", mo.link, None, 0j, 0j, value))
    if loads.resistance is not None:
        _P, force, _ = resistance(loads, stroke, phi, pos, mech.source)
        lid = stroke.link
        out.append(
            Load(loads.resistance.name, "resistance", lid, stroke.point, pos[stroke.point], force, 0.0)
        )
    return out


def _direction(mech: Mechanism, motion, f, lid):
    """The unit direction of the file's force ``f`` on link ``lid``."""
    if f.angle is not None:
        return complex(math.cos(f.angle), math.sin(f.angle))
    if f.rule in ("along velocity", "against velocity"):
        v = motion.velocity[f.point]
        size = abs(v)
        with np.errstate(all="ignore"):
            unit = np.where(size > 0, v / np.where(size > 0, size, 1.0), 0j)
        unit = complex(unit) if np.ndim(unit) == 0 else unit
        return unit if f.rule == "along velocity" else -unit
    slider = mech.slider_of(lid)
    guide = slider.guide
    u = motion.links[guide.link].rotor * guide.direction if guide.link else guide.direction
    return u if f.rule == "along guide" else -u
