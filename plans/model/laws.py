"""A driver's law in time: its coordinate q(t) and the derivatives q′(t), q″(t).

A driver is a link hinged to the frame (q the angle φ, rad, counter-clockwise from +x; q′
its ω, q″ its ε) or a slider on a fixed guide (q its travel s along the guide, m; q′ its
velocity, q″ its acceleration). Its law is one of:

* ``uniform``:      q = q0 + q′0·t;
* ``accelerated``:  q = q0 + q′0·t + q″·t²/2 (uniformly accelerated: q″ constant);
* ``harmonic``:     q = q_m + A·sin(Ω·t + α), q′ = A·Ω·cos(Ω·t + α), q″ = −A·Ω²·sin(Ω·t + α);
* ``table``:        q at given instants t_k; q′ and q″ given with it, or from the cubic
  spline through the table (C², its third derivative piecewise constant), periodic where
  the table ends as it begins (to a whole turn of a rotating driver), else not-a-knot.

Every law is evaluated on Python numbers or numpy arrays of instants alike.

>>> law = Law("harmonic", mean=0.135, amplitude=0.01, omega=10.0)
>>> [round(float(x), 6) for x in law.at(0.0)]
[0.135, 0.1, 0.0]
>>> law.period
0.6283185307179586
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from fractions import Fraction

import numpy as np

KINDS = ("uniform", "accelerated", "harmonic", "table")


@dataclass(frozen=True)
class Law:
    """One driver's law in time (module docstring). Values in the engine's units: rad or
    m, rad/s or m/s, rad/s² or m/s², s."""

    kind: str
    q0: float = 0.0  # uniform, accelerated: q at t = 0
    rate: float = 0.0  # q′ at t = 0
    accel: float = 0.0  # q″ (accelerated)
    mean: float = 0.0  # harmonic
    amplitude: float = 0.0
    omega: float = 0.0  # rad/s, the harmonic law's circular frequency Ω
    phase: float = 0.0  # rad
    t: tuple[float, ...] = ()  # table: the instants, ascending
    q: tuple[float, ...] = ()
    dq: tuple[float, ...] | None = None
    ddq: tuple[float, ...] | None = None
    #: a rotating driver's table that ends a whole turn on from where it began runs on
    #: periodically (its q then grows by ``turn`` each period)
    turn: float = 0.0
    periodic: bool = False
    #: the table's spline: per interval (q, q′, q″/2, q‴/6) at its start, worked out once
    coef: tuple = field(default=(), repr=False, compare=False)

    @property
    def period(self) -> float | None:
        """The law's period (s): a uniform rotation's turn 2π/|q′| (``rotary``: see
        :func:`uniform_period`), a harmonic law's 2π/Ω, a periodic table's span; None
        where it has none."""
        if self.kind == "harmonic":
            return 2 * math.pi / abs(self.omega)
        if self.kind == "table" and self.periodic:
            return self.t[-1] - self.t[0]
        return None

    def at(self, t):
        """(q, q′, q″) at the instant(s) ``t`` (s)."""
        if self.kind == "uniform":
            return self.q0 + self.rate * t, self.rate + 0.0 * t, 0.0 * t
        if self.kind == "accelerated":
            return (self.q0 + self.rate * t + 0.5 * self.accel * t * t,
                    self.rate + self.accel * t, self.accel + 0.0 * t)
        if self.kind == "harmonic":
            arg = self.omega * t + self.phase
            s, c = np.sin(arg), np.cos(arg)
            a = self.amplitude
            return self.mean + a * s, a * self.omega * c, -a * self.omega * self.omega * s
        return self._table(t)

    def _table(self, t):
        scalar = np.ndim(t) == 0
        tt = np.asarray(t, dtype=float)
        knots = np.asarray(self.t)
        span = knots[-1] - knots[0]
        shift = np.zeros(tt.shape)
        if self.periodic:  # the table runs on, a turn more (or the same q) each period
            k = np.floor((tt - knots[0]) / span)
            tt = tt - k * span
            shift = k * self.turn
        i = np.clip(np.searchsorted(knots, tt, side="right") - 1, 0, len(knots) - 2)
        h = tt - knots[i]
        c = np.asarray(self.coef)[i]  # (…, 4): q, q′, q″/2, q‴/6 at the interval's start
        if len(self.coef[0]) == 6:  # quintic Hermite: q, q′, q″/2, c3, c4, c5
            c0, c1, c2, c3, c4, c5 = (c[..., j] for j in range(6))
            q = c0 + h * (c1 + h * (c2 + h * (c3 + h * (c4 + h * c5))))
            dq = c1 + h * (2 * c2 + h * (3 * c3 + h * (4 * c4 + h * 5 * c5)))
            ddq = 2 * c2 + h * (6 * c3 + h * (12 * c4 + h * 20 * c5))
        else:
            q = c[..., 0] + h * (c[..., 1] + h * (c[..., 2] + h * c[..., 3]))
            dq = c[..., 1] + h * (2 * c[..., 2] + h * 3 * c[..., 3])
            ddq = 2 * c[..., 2] + h * 6 * c[..., 3]
        q = q + shift
        if scalar:
            return float(q), float(dq), float(ddq)
        return q, dq, ddq


def table_law(t, q, dq=None, ddq=None, turn: float = 0.0) -> Law:
    """The law of a table of instants ``t`` (ascending) and values ``q``, with their
    derivatives where given: a quintic Hermite curve through q, q′, q″; a cubic one
    through q, q′; else the cubic spline through q. Periodic where ``q`` ends as it begins
    (to ``turn``: 2π or −2π for a table of a turning crank, else 0) and the derivatives
    given, if any, do too."""
    t = np.asarray(t, dtype=float)
    q = np.asarray(q, dtype=float)
    h = np.diff(t)
    end = q[-1] - q[0]
    periodic = (abs(end - turn) <= 1e-12 * max(1.0, abs(turn), float(np.ptp(q)))
                and (dq is None or abs(dq[-1] - dq[0]) <= 1e-12 * max(1.0, max(map(abs, dq))))
                and (ddq is None or abs(ddq[-1] - ddq[0]) <= 1e-12 * max(1.0, max(map(abs, ddq)))))
    if dq is not None and ddq is not None:
        coef = _quintic(t, q, np.asarray(dq, float), np.asarray(ddq, float))
    elif dq is not None:
        coef = _cubic(h, q, np.asarray(dq, float))
    else:
        coef = _spline(h, q, periodic)
    return Law("table", t=tuple(map(float, t)), q=tuple(map(float, q)),
               dq=None if dq is None else tuple(map(float, dq)),
               ddq=None if ddq is None else tuple(map(float, ddq)),
               turn=turn if periodic else 0.0, periodic=periodic,
               coef=tuple(tuple(map(float, row)) for row in coef))


def _cubic(h, q, dq):
    """Cubic Hermite pieces through q and q′ at the knots."""
    rows = []
    for i, hi in enumerate(h):
        d = (q[i + 1] - q[i]) / hi
        c2 = (3 * d - 2 * dq[i] - dq[i + 1]) / hi
        c3 = (dq[i] + dq[i + 1] - 2 * d) / (hi * hi)
        rows.append((q[i], dq[i], c2, c3))
    return rows


def _quintic(t, q, dq, ddq):
    """Quintic Hermite pieces through q, q′ and q″ at the knots."""
    rows = []
    for i in range(len(t) - 1):
        h = t[i + 1] - t[i]
        a0, a1, a2 = q[i], dq[i], ddq[i] / 2
        # the rest from the end values: a solve of the 3×3 system in h
        r0 = q[i + 1] - (a0 + a1 * h + a2 * h * h)
        r1 = dq[i + 1] - (a1 + 2 * a2 * h)
        r2 = ddq[i + 1] - 2 * a2
        m = np.array([[h**3, h**4, h**5], [3 * h**2, 4 * h**3, 5 * h**4], [6 * h, 12 * h**2, 20 * h**3]])
        a3, a4, a5 = np.linalg.solve(m, np.array([r0, r1, r2]))
        rows.append((a0, a1, a2, a3, a4, a5))
    return rows


def _spline(h, q, periodic: bool):
    """The cubic spline through q: its second derivatives M at the knots from the
    spline's equations (periodic, or not-a-knot at both ends), then its pieces."""
    n = len(q)
    if n == 2:  # a straight line
        return [(q[0], (q[1] - q[0]) / h[0], 0.0, 0.0)]
    d = np.diff(q) / h
    a = np.zeros((n, n))
    b = np.zeros(n)
    for i in range(1, n - 1):
        a[i, i - 1], a[i, i], a[i, i + 1] = h[i - 1], 2 * (h[i - 1] + h[i]), h[i]
        b[i] = 6 * (d[i] - d[i - 1])
    if periodic:
        # M0 = M(n−1), and the slopes meet at the seam
        a[0, 0], a[0, n - 1] = 1.0, -1.0
        a[n - 1, 0], a[n - 1, 1] = 2 * h[0], h[0]
        a[n - 1, n - 2], a[n - 1, n - 1] = h[-1], 2 * h[-1]
        b[n - 1] = 6 * (d[0] - d[-1])
    elif n == 3:  # not-a-knot with three points: the parabola through them
        a[0, 0], a[0, 1] = 1.0, -1.0
        a[n - 1, n - 2], a[n - 1, n - 1] = 1.0, -1.0
    else:  # not-a-knot: the third derivative continuous at the second and last-but-one knots
        a[0, 0], a[0, 1], a[0, 2] = h[1], -(h[0] + h[1]), h[0]
        a[n - 1, n - 3], a[n - 1, n - 2], a[n - 1, n - 1] = h[-1], -(h[-2] + h[-1]), h[-2]
    m = np.linalg.solve(a, b)
    rows = []
    for i, hi in enumerate(h):
        rows.append((q[i], d[i] - hi * (2 * m[i] + m[i + 1]) / 6, m[i] / 2, (m[i + 1] - m[i]) / (6 * hi)))
    return rows


def common_period(periods: list[float]) -> float | None:
    """The least period all of ``periods`` (s) divide, where their ratios are fractions of
    small whole numbers (to 1e-9); None where there is none.

    >>> round(common_period([0.2, 0.3]), 12)
    0.6
    >>> common_period([1.0, math.sqrt(2)]) is None
    True
    """
    if not periods:
        return None
    base = periods[0]
    lcm = Fraction(1)
    for p in periods[1:]:
        f = Fraction(p / base).limit_denominator(12)
        if abs(float(f) - p / base) > 1e-9 * p / base:
            return None
        lcm = Fraction(math.lcm(lcm.numerator, f.numerator), math.gcd(lcm.denominator, f.denominator))
    return base * float(lcm)


def uniform_period(rate: float) -> float:
    """A uniform rotation's turn: 2π/|ω| (s)."""
    return 2 * math.pi / abs(rate)


@dataclass(frozen=True)
class Timing:
    """A mechanism moved by laws in time: the instant its plans are built for and the
    interval its cycle is swept over (s)."""

    time: float
    span: tuple[float, float]
