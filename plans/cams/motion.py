"""The follower's motion over the cam's turn: s(φ) and its derivatives, phase by phase, and
the impacts at the phases' joints.

φ is the cam's angle of rotation from the start of the first phase (rad, growing the way
the cam turns); s is the follower's displacement from its lowest position (m; the swing
angle ψ in rad for an oscillating follower), and s′ = ds/dφ, s″ = d²s/dφ², s‴ = d³s/dφ³.
At a constant ω the follower's velocity, acceleration and jerk are

    v = ω·s′,   a = ω²·s″,   j = ω³·s‴.

:class:`Motion` is a cam designed by its phases (rise, dwells, return, each with its law);
:class:`DiscMotion` the motion an eccentric disc gives a translating follower, in closed
form from the disc's geometry.

>>> from plans.cams.laws import LAWS
>>> m = Motion((Phase("rise", 0.0, math.radians(120), LAWS["cosine"]),
...             Phase("dwell", math.radians(120), math.radians(240), level=0.016)), 0.016)
>>> s, s1, s2, s3 = m.at(np.radians([60.0, 120.0]))
>>> [round(float(x), 6) for x in s]
[0.008, 0.016]
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from plans.cams.laws import Law, unit

__all__ = ["TURN", "DiscMotion", "Impact", "Motion", "Phase", "impacts"]

TURN = 2.0 * math.pi


@dataclass(frozen=True, slots=True)
class Phase:
    """One phase of the cycle: ``kind`` "rise", "return" or "dwell", starting at the cam
    angle ``start`` and lasting ``angle`` (rad); a rise or return moves by ``law`` with its
    acceleration part ``ratio`` times its deceleration part; a dwell holds ``level``."""

    kind: str
    start: float
    angle: float
    law: Law | None = None
    ratio: float = 1.0
    level: float = 0.0

    @property
    def end(self) -> float:
        return self.start + self.angle

    @property
    def k(self) -> float:
        """The share of the phase the follower accelerates over."""
        return self.ratio / (1.0 + self.ratio)

    @property
    def moves(self) -> bool:
        return self.kind != "dwell"


class Motion:
    """s(φ), s′, s″, s‴ of a cam designed by ``phases`` (which fill one turn) with the
    stroke ``stroke`` (m, or rad of swing)."""

    def __init__(self, phases, stroke: float):
        self.phases = tuple(phases)
        self.stroke = float(stroke)
        self._starts = np.array([p.start for p in self.phases])

    def of_phase(self, i: int, phi, side: str = "right"):
        """(s, s′, s″, s‴) by phase ``i``'s own formulas at ``phi`` (rad, within the phase's
        closed interval: its ends give the phase's own limits there). ``side``: at an
        asymmetric law's joint, "left" takes the acceleration part."""
        p = self.phases[i]
        phi = np.asarray(phi)
        if not p.moves:
            zero = np.zeros_like(phi)
            return zero + p.level, zero, zero, zero
        u = (phi - p.start) / p.angle
        u = np.where(np.abs(np.real(u) - p.k) < 1e-12, p.k + 0.0 * u, u)  # the joint itself, exactly
        f, f1, f2, f3 = unit(p.law.key, u, p.k, side)
        h, b = self.stroke, p.angle
        sign = 1.0 if p.kind == "rise" else -1.0
        s = h * f if p.kind == "rise" else h * (1.0 - f)
        return s, sign * h * f1 / b, sign * h * f2 / b**2, sign * h * f3 / b**3

    def index(self, phi) -> np.ndarray:
        """The phase each cam angle lies in (a joint belongs to the phase that starts
        there)."""
        turned = np.mod(np.real(np.asarray(phi)), TURN)
        return np.clip(np.searchsorted(self._starts, turned, side="right") - 1, 0, len(self.phases) - 1)

    def at(self, phi):
        """(s, s′, s″, s‴) at every cam angle of ``phi`` (any shape; taken modulo a turn)."""
        phi = np.asarray(phi)
        turned = phi - TURN * np.floor(np.real(phi) / TURN)
        idx = self.index(turned)
        out = [np.zeros(phi.shape, dtype=np.result_type(phi, float)) for _ in range(4)]
        for i in range(len(self.phases)):
            mask = idx == i
            if mask.any():
                for o, v in zip(out, self.of_phase(i, turned[mask]), strict=True):
                    o[mask] = v
        return tuple(out)

    def joints(self) -> list[tuple[float, int, int]]:
        """(cam angle, phase before, phase after) of every joint of two phases, the turn's
        end and start included."""
        n = len(self.phases)
        return [(self.phases[i].start, (i - 1) % n, i) for i in range(n)]

    def limits(self, i: int, phi: float, side: str):
        """(s, s′, s″) of phase ``i`` at ``phi`` (one of its ends, or an inner joint)."""
        return [float(np.real(x)) for x in self.of_phase(i, np.array(phi), side)[:3]]


@dataclass(frozen=True, slots=True)
class Impact:
    """What happens at a cam angle where the motion may jump: ``kind`` "rigid" (the
    follower's velocity jumps: ``dv`` = Δs′, in m or rad per rad of cam), "soft" (its
    acceleration jumps: ``da`` = Δs″) or "none". ``where``: (phase before, phase after),
    or (i, i) at the joint inside a phase where its law turns from acceleration to
    deceleration."""

    phi: float
    where: tuple[int, int]
    kind: str
    dv: float
    da: float


#: a jump of s′ or s″ smaller than this share of the motion's own scale (h/β, h/β²) is
#: rounding, not a jump
JUMP = 1e-9


def impacts(motion) -> list[Impact]:
    """Every phase joint (and every law's inner joint where it accelerates and
    decelerates), with its impact classed by the jumps of s′ and s″ across it.

    >>> from plans.cams.laws import LAWS
    >>> b = math.radians(90)
    >>> m = Motion([Phase("rise", 0, b, LAWS["constant velocity"]), Phase("dwell", b, b, level=1.0),
    ...             Phase("return", 2 * b, b, LAWS["cosine"]), Phase("dwell", 3 * b, b)], 1.0)
    >>> [i.kind for i in impacts(m)]
    ['rigid', 'rigid', 'soft', 'soft']
    """
    moving = [p for p in motion.phases if p.moves]
    beta = min(p.angle for p in moving)
    scale1, scale2 = motion.stroke / beta, motion.stroke / beta**2
    out = []
    for phi, before, after in motion.joints():
        end = motion.phases[before].end
        _, v0, a0 = motion.limits(before, end, "left")
        _, v1, a1 = motion.limits(after, phi, "right")
        out.append(_impact(phi, (before, after), v1 - v0, a1 - a0, scale1, scale2))
    for i, p in enumerate(motion.phases):
        if not p.moves or p.law is None or p.law.key in ("constant velocity", DISC.key):
            continue
        at = p.start + p.k * p.angle
        _, v0, a0 = motion.limits(i, at, "left")
        _, v1, a1 = motion.limits(i, at, "right")
        inner = _impact(at, (i, i), v1 - v0, a1 - a0, scale1, scale2)
        if inner.kind != "none":
            out.append(inner)
    return sorted(out, key=lambda x: (x.phi % TURN, x.where[0] != x.where[1]))


def _impact(phi, where, dv, da, scale1, scale2) -> Impact:
    kind = "rigid" if abs(dv) > JUMP * scale1 else "soft" if abs(da) > JUMP * scale2 else "none"
    return Impact(float(phi % TURN), where, kind, float(dv), float(da))


#: the pseudo-law of a disc cam's phases: the motion its circle gives
DISC = Law("eccentric disc", "eccentric disc", "эксцентриковый диск", "none",
           "s = y_B − y_B,min, y_B = OA·sin(…) + √(R² − (e − OA·cos(…))²)")


class DiscMotion:
    """The motion an eccentric disc (radius ``radius``, its centre A at ``eccentricity`` =
    OA from the shaft O) gives a translating follower whose axis runs at ``offset`` e from
    O (positive to the right, the follower above the cam), the cam turning ``sense`` (+1
    counter-clockwise). ``roller``: the roller's radius (0: knife-edge); ``flat``: a flat
    face ⊥ the axis. φ = 0 where the follower is lowest.

    The pitch point B runs on the circle of radius R_p = R + r_r about A: with A at
    OA·exp(i(θ0 + σφ)),

        y_B = y_A + √(R_p² − (e − x_A)²),   s = y_B − √(r0² − e²),   r0 = R_p − OA;

    a flat face touches the disc at y = y_A + R, s = y_A + OA.

    >>> m = DiscMotion(0.030, 0.010, -0.010, 1)   # seed 004: R 30, OA 10, e 10 on the left
    >>> round(m.base_radius, 6), round(float(m.at(math.radians(60))[0]) * 1000, 2)
    (0.02, 5.04)
    """

    law = DISC

    def __init__(self, radius: float, eccentricity: float, offset: float, sense: int,
                 roller: float = 0.0, flat: bool = False):
        self.radius, self.c, self.e, self.sigma = radius, eccentricity, offset, sense
        self.roller, self.flat = roller, flat
        self.rp = radius + roller
        c = eccentricity
        if flat:
            self.base_radius = radius - c
            self.theta0 = -math.pi / 2.0
            top = math.pi / 2.0
            self.stroke = 2.0 * c
        else:
            r0 = self.rp - c
            self.base_radius = r0
            y0 = math.sqrt(r0 * r0 - offset * offset)
            self.y_min = y0
            self.theta0 = math.atan2(-y0, -offset)
            y1 = math.sqrt((self.rp + c) ** 2 - offset * offset)
            top = math.atan2(y1, offset)
            self.stroke = y1 - y0
        rise = (sense * (top - self.theta0)) % TURN
        self.phases = (Phase("rise", 0.0, rise, DISC), Phase("return", rise, TURN - rise, DISC))

    def index(self, phi) -> np.ndarray:
        return (np.mod(np.real(np.asarray(phi)), TURN) >= self.phases[1].start).astype(int)

    def at(self, phi):
        """(s, s′, s″, s‴) in closed form at every cam angle of ``phi``."""
        g = self.theta0 + self.sigma * np.asarray(phi)
        x, y = self.c * np.cos(g), self.c * np.sin(g)  # A; A′ = iσA, A″ = −A, A‴ = −iσA
        x1, y1 = -self.sigma * y, self.sigma * x
        x2, y2, x3, y3 = -x, -y, -x1, -y1
        if self.flat:
            return y + self.c, y1, y2, y3
        D, D1, D2, D3 = self.e - x, -x1, -x2, -x3
        q = np.sqrt(self.rp**2 - D * D)
        q1 = -D * D1 / q
        q2 = (-D1 * D1 - D * D2 - q1 * q1) / q
        q3 = (-3.0 * D1 * D2 - D * D3 - 3.0 * q1 * q2) / q
        return y + q - self.y_min, y1 + q1, y2 + q2, y3 + q3

    def of_phase(self, i: int, phi, side: str = "right"):
        return self.at(phi)

    def joints(self) -> list[tuple[float, int, int]]:
        return [(0.0, 1, 0), (self.phases[1].start, 0, 1)]

    def limits(self, i: int, phi: float, side: str):
        return [float(np.real(x)) for x in self.at(np.array(phi))[:3]]
