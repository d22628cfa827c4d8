"""Quantities of the whole cycle: extreme positions, stroke H, θ and K, the N positions,
trajectories, and whether the crank can make a full turn (Grashof for a four-bar).

K = (180° + θ)/(180° − θ): the crank angle of the slower (working) stroke over that of the
faster (return) stroke; θ is the crank angle between the extreme positions' lines.
"""

from __future__ import annotations

import itertools
import math
import numbers
from dataclasses import dataclass

import numpy as np

from plans import tolerances
from plans.cycle.words import change_angles, outside, shown_from, worded
from plans.errors import AssemblyError, InputError, PlansError, PositionError
from plans.fmt import angle, num
from plans.geometry import apart
from plans.kinematics.setup import Setup
from plans.kinematics.solver import Motion, Solver
from plans.model import Mechanism
from plans.model.outputs import Output, find_output
from plans.model.structure import DyadKind

TWO_PI = 2 * math.pi


def table_angle(psi, full_turn: bool):
    """The output's angle ψ (rad, unwrapped over the positions in their order) as a table
    gives it: an output that turns with the crank, a whole turn per turn, modulo 2π as φ1
    is; one that swings, continuous over its swing and moved by whole turns so that the
    middle of its swing lies in [0, 2π). A rocker then reads 170°…190° whichever side of
    ±180° ``np.angle`` started it on, one swinging about +x −10°…10°, and a drag link's
    output 150°…360°, 0°…120° rather than up to 480°.
    NaN (a position where the link is nowhere) stays NaN."""
    psi = np.array(psi, dtype=float)
    known = np.isfinite(psi)
    if psi.ndim == 0 or not known.any():
        return psi
    got = psi[known]
    if full_turn and got.size > 1:
        # the step from the last position back to the first closes the turn: the output
        # turns fully when the steps add up to a whole turn, not to nothing
        back = math.remainder(got[0] - got[-1], TWO_PI)
        if round((got[-1] - got[0] + back) / TWO_PI) != 0:
            psi[known] = np.mod(got, TWO_PI)
            return psi
    psi[known] = got - TWO_PI * math.floor((got.max() + got.min()) / 2 / TWO_PI)
    return psi


@dataclass(frozen=True)
class Cycle:
    output: Output | None
    full_turn: bool
    #: crank angles (rad) of the extreme positions: the output's, the one that starts the
    #: working stroke (position 0) first, or where the crank cannot make a full turn its
    #: limit positions (dead points), ``crank_range``
    extremes: tuple[float, ...]
    stroke: float | None  # H (m) or swing ψ (rad)
    theta: float | None  # rad
    K: float | None
    positions: tuple[float, ...]  # the N crank angles, numbered from an extreme
    grashof: str | None
    notes: tuple[str, ...]
    crank_range: tuple[float, float] | None = None  # rad: where it assembles, if not a full turn
    #: crank angles (rad from +x) of the change points the motion passes smoothly
    #: (:func:`plans.kinematics.branches.change_points`), in the order the crank meets them
    change_points: tuple[float, ...] = ()
    #: what the cycle runs over: "turn", the crank's angle; "range", a slider input's
    #: travel (m) where the mechanism assembles; "time", the instants (s) of the drivers'
    #: laws. ``positions``, ``extremes`` and ``crank_range`` are in its unit.
    kind: str = "turn"
    #: the interval a "range" or "time" cycle runs over (its positions lie within it)
    span: tuple[float, float] | None = None
    #: a "time" cycle: whether its interval is one period of the drivers' laws (the
    #: motion then repeats from its end, as a crank's turn does)
    periodic: bool = False

    @property
    def ccw_range(self) -> tuple[float, float] | None:
        """``crank_range`` counter-clockwise from its first angle to its second, whichever
        way the crank turns (``crank_range`` runs in the crank's sense: numbers falling
        for a clockwise crank)."""
        if self.crank_range is None:
            return None
        lo, hi = self.crank_range
        return (min(lo, hi), max(lo, hi))


def analyse_cycle(mech: Mechanism, n_positions: int = 12, solver: Solver | None = None,
                  samples: int = 3600) -> Cycle:
    """The cycle of ``mech`` (see :class:`Cycle`), solved by ``solver`` (one of ``mech``,
    made here where it is not given). Whoever needs the cycle more than once keeps it:
    it is a value, worked out anew at each call.

    Where the mechanism does not close at its own crank angle (and so has no cycle from
    there) this raises the error solving there raises, its angle written as the nearest
    range where it does close writes it (:func:`plans.cycle.words.worded`).

    ``n_positions``: how many crank positions (:attr:`Cycle.positions`), at least 1;
    ``samples``: how many angles a turn is searched at, at least 2."""
    _whole(n_positions, "n_positions", 1)
    _whole(samples, "samples", 2)
    solver = solver or Solver(mech)
    if mech.timed:
        return _timed_cycle(mech, n_positions, solver, samples)
    if mech.driver.linear:
        return _travel_cycle(mech, n_positions, solver, samples)
    return _analyse_cycle(mech, n_positions, solver, samples)


def _whole(value, name: str, least: int) -> None:
    """``value`` is a whole number ≥ ``least``: 0 or −3 positions gave a cycle of none, 1.5
    failed deep in numpy, and a turn searched at one angle indexed past its end."""
    if isinstance(value, bool) or not isinstance(value, int | np.integer) or value < least:
        raise InputError("analyse_cycle", f"{name}: must be a whole number from {least}, "
                         f"got {value!r}")


def reachable(mech: Mechanism, samples: int = 3600) -> Mechanism | None:
    """Where the crank angle of ``mech`` does not assemble on any assembly: ``mech`` with
    its crank turned to the middle of the nearest range of angles where it does, as
    ``--angle`` turns it (:meth:`Mechanism.at_file_angle`: the hints are read at the
    file's own angle where the mechanism closes there, else at the new one). None where
    its angle assembles (on some assembly), or no angle does."""
    setup = Setup.of(mech)
    n = len(setup.structure.groups)
    grid = mech.driver.phi + np.linspace(0.0, TWO_PI, samples, endpoint=False)
    closes = np.zeros(samples, dtype=bool)
    # on every assembly: a later group may close on one of an earlier group's only
    for sigmas in itertools.islice(itertools.product((1, -1), repeat=n), 64):
        with np.errstate(all="ignore"):
            closes |= Solver(mech, None, sigmas, ((),) * n, setup=setup).solve(grid).placed
    if closes[0] or not closes.any():
        return None
    got = np.flatnonzero(closes)
    k = int(got[np.argmin(np.minimum(got, samples - got))])  # the nearest, either way
    i = j = k
    while closes[(i - 1) % samples] and k - i < samples:
        i -= 1
    while closes[(j + 1) % samples] and j - k < samples:
        j += 1
    mid = float(grid[0] + (i + j) / 2 * (grid[1] - grid[0]))
    return mech.at_file_angle(mech.driver.file_angle(mid))


def reachable_cycle(mech: Mechanism, n_positions: int = 12):
    """(mechanism, its solver, its cycle) over the range :func:`reachable` finds, where the
    crank angle of ``mech`` does not assemble; None where that finds none or the range's
    cycle cannot be made."""
    turned = reachable(mech)
    if turned is None:
        return None
    try:
        solver = Solver(turned)
        c = analyse_cycle(turned, n_positions, solver=solver)
    except PlansError:
        return None
    return None if c.full_turn else (turned, solver, c)


def outside_range(mech: Mechanism, exc: PlansError, field: str, given: float) -> PlansError:
    """The error for a crank angle where ``mech`` does not assemble, one line: the field
    that gave it (``driver.angle_deg``, ``--angle``) and its value ``given``, the crank's
    range where it does, in the file's convention, and the group that cannot close;
    ``exc`` itself where there is no such range."""
    if not isinstance(exc, AssemblyError) or (got := reachable_cycle(mech)) is None:
        return exc
    _, solver, c = got
    d = mech.driver
    at = d.at(d.phi, lo=shown_from(c, d))
    why = ""
    with np.errstate(all="ignore"):
        m = solver.solve(np.array([d.phi]))
    for g in m.groups:  # the group that misses, on the assembly the range is drawn in
        if not g.valid[0]:
            why = f": {g.failure(0, at)}"
            break
    return InputError(mech.source, f"{outside(field, given, c, d)}, where the mechanism "
                                   f"assembles{why}")


def _analyse_cycle(mech: Mechanism, n_positions: int, solver: Solver, samples: int) -> Cycle:
    w1 = mech.driver.omega
    sense = 1.0 if w1 > 0 else -1.0
    phi0 = mech.driver.phi
    grid = phi0 + sense * np.linspace(0.0, TWO_PI, samples, endpoint=False)
    with np.errstate(all="ignore"):
        m = solver.solve(grid)
    valid = m.valid
    notes: list[str] = []
    grashof = _grashof(mech, solver)
    changes, near = _change_points(solver, grid)
    if changes:
        deg = mech.driver.file_angle
        # groups that meet them an odd number of times a turn: flipped (smooth) or kept;
        # a rocking crank has no turn to repeat
        odd = [bool(f) for c, f in zip(solver.changes, solver.flips, strict=True)
               if len(c) % 2 and solver.seam is None]
        if not odd:
            how = "it could fold into its other assembly; the cycle follows the smooth motion"
        elif any(odd):
            how = ("its two assemblies meet; the cycle follows the smooth motion, which "
                   f"repeats only after two turns: its two turns meet at {mech.driver.phi_sym} = "
                   f"{angle(deg(solver.branch_at))}°")
        else:
            how = ("its two assemblies meet; the cycle keeps the assembly, so the linkage "
                   "folds back there (its smooth motion would repeat only after two turns)")
        # the plans are singular at the change points, not where two turns meet (a seam
        # elsewhere): said beside them, not after the seam's angle at the end
        notes.append(
                f"change points at {mech.driver.phi_sym} = "
            + ", ".join(f"{x}°" for x in change_angles(changes, mech.driver))
            + mech.driver.convention() + f": the links of a group lie in line there and the "
            f"plans are singular; there {how}")
    closes = valid | (near & m.placed)  # a sample on a change point closes to rounding
    # where a PRP group's two guides turn parallel, the point on both runs off to infinity:
    # the crank cannot pass, though both sides close (found by the sine's sign, not by a
    # sample that happens to fall on it)
    sides = _guide_sides(m)
    for label, side in sides.items():
        if (side != side[0]).any():
            notes.append(f"{label}: its two guides turn parallel at a limit of the "
                         "crank's range, where the point on both runs off to infinity")
        closes &= side == side[0]
    # the given angle on a limit of the crank's range ends it; on a change point where a
    # point is nowhere (a kite's crank pin on the rocker's pivot) the motion goes through
    closes[0] |= m.placed[0] or solver.on_change_point(phi0)
    full = bool(closes.all())
    out = find_output(mech)
    if not full:  # the range is worded where it is shown (report.no_full_turn)
        if not closes[0]:  # the given angle itself does not close: say why, as solve does
            try:
                solver.solve_one(phi0)
            except PositionError as err:  # in the turn of the nearest range, if any
                got = reachable_cycle(mech)
                raise worded(err, solver, None if got is None else got[2]) from None
        lo, hi = _limits(solver, *_interval_around(grid, closes), grid[1] - grid[0],
                         {label: side[0] for label, side in sides.items()})
        span = lo + (hi - lo) * (np.arange(n_positions) + 0.5) / n_positions
        return Cycle(out, False, (lo, hi), None, None, None, tuple(span), grashof,
                     tuple(notes), (lo, hi), changes)
    extremes: list[float] = []
    stroke = theta = K = None
    start = phi0
    if out is not None:
        rate = out.rate(m, mech)
        # no sign where it is singular, nor where the rate is rounding of 0 (1e-9 of the
        # crank's ω1, or of its pin's speed): an output at rest does not turn back
        still = at_rest(mech, out.kind == "linear")
        sgn = rate_signs(np.where(near | (np.abs(rate) < still), 0.0, rate))
        if not sgn.any():
            notes.append(f"the output {out.point} does not move")
        idx = np.nonzero(sgn != np.roll(sgn, -1))[0]
        for i in idx:
            a, b = grid[i], grid[(i + 1) % samples] if i + 1 < samples else grid[0] + sense * TWO_PI
            if near[(i + 1) % samples]:  # it turns back at a change point: a fold
                extremes.append(min(changes, key=lambda x: apart(x, b)))
                continue
            extremes.append(_refine(solver, out, mech, a, b, sgn[i] > 0))
        if len(extremes) == 2:
            with np.errstate(all="ignore"):
                me = solver.solve(np.array(extremes))
            val = out.value(me, mech)
            stroke = float(abs(val[1] - val[0]))
            span = (sense * (extremes[1] - extremes[0])) % TWO_PI
            slow, fast = max(span, TWO_PI - span), min(span, TWO_PI - span)
            theta = (slow - fast) / 2
            K = slow / fast
            if abs(theta) < tolerances.EQUAL_STROKES:  # equal strokes, as the tie below: θ = 0, K = 1
                theta, K = 0.0, 1.0
            # position 0 starts the slower (working) stroke; on a tie, the lower output value
            if abs(span - (TWO_PI - span)) < tolerances.EQUAL_STROKES:
                start = extremes[int(np.argmin(val))]
            else:
                start = extremes[0] if span >= TWO_PI - span else extremes[1]
            if start is extremes[1]:  # the working stroke's start first, from any angle
                extremes.reverse()
        elif extremes:
            notes.append(f"the output {out.point} has {len(extremes)} turning points per turn")
    pos = tuple(start + sense * TWO_PI * i / n_positions for i in range(n_positions))
    return Cycle(out, True, tuple(extremes), stroke, theta, K, pos, grashof, tuple(notes),
                 change_points=changes)


#: how far a slider input's travel is searched each way for where the mechanism assembles,
#: in multiples of the given position's size
TRAVEL_REACH = 4.0


def _travel_cycle(mech: Mechanism, n_positions: int, solver: Solver, samples: int) -> Cycle:
    """The cycle of a slider input placed at the position analysed: its travel over the
    range where the mechanism assembles on its branch, searched each way from the given
    position up to :data:`TRAVEL_REACH` times that position's size; the N positions the
    middles of N equal parts of it, as a rocking crank's."""
    s0 = mech.driver.phi
    try:
        given = solver.solve_one(s0)
    except PositionError as err:
        raise worded(err, solver, None) from None
    pts = np.array(list(given.position.values()))
    reach = TRAVEL_REACH * max(float(np.ptp(pts.real)), float(np.ptp(pts.imag)), 1e-6)
    half = max(samples // 2, 2)
    ends, notes = [], []
    for way in (-1.0, 1.0):
        grid = s0 + way * np.linspace(0.0, reach, half + 1)
        with np.errstate(all="ignore"):
            ok = solver.solve(grid).placed
        j = int(np.argmin(ok)) - 1 if not ok.all() else half
        if j < half:
            lo, hi = _limits(solver, *sorted((float(grid[j]), float(grid[j]))), reach / half)
            ends.append(lo if way < 0 else hi)
        else:
            ends.append(float(grid[-1]))
            notes.append(f"the mechanism assembles up to the end of the travel searched, "
                         f"{mech.driver.phi_sym} = {num(float(grid[-1]), 6)} m")
    lo, hi = ends
    span = lo + (hi - lo) * (np.arange(n_positions) + 0.5) / n_positions
    return Cycle(find_output(mech), False, (lo, hi), None, None, None, tuple(span), None,
                 tuple(notes), (lo, hi), kind="range", span=(lo, hi))


def _timed_cycle(mech: Mechanism, n_positions: int, solver: Solver, samples: int) -> Cycle:
    """The cycle of a mechanism moved by its drivers' laws in time: the interval of
    ``[motion]`` (by default one common period of the laws) sampled at ``samples``
    instants; the output's extreme positions where its velocity changes sign (found to
    1e-13 of the interval), its stroke or swing, and where the interval is a period with
    two extremes the time-ratio K = t_work / t_return (the slower stroke's time over the
    faster's) and θ = 180°·(K − 1)/(K + 1). The N positions are instants a period's Nth
    apart, from the extreme position that starts the working stroke where it has one."""
    t0, t1 = mech.timing.span
    T = t1 - t0
    periodic = _periodic(mech, T)
    grid = t0 + T * np.arange(samples) / samples if periodic else np.linspace(t0, t1, samples)
    with np.errstate(all="ignore"):
        m = solver.solve(grid)
    notes: list[str] = []
    placed = m.placed
    if not placed.all():
        bad = grid[~placed]
        notes.append(f"the mechanism does not assemble over all of the interval: from t = "
                     f"{num(float(bad.min()), 6)} s to {num(float(bad.max()), 6)} s it does "
                     "not close at some instants")
    out = find_output(mech)
    extremes: list[float] = []
    stroke = theta = K = None
    start = t0
    if out is not None and placed.all():
        rate = out.rate(m, mech)
        still = np.abs(rate) < tolerances.AT_REST * max(float(np.max(np.abs(rate))), 1e-300)
        sgn = rate_signs(np.where(still, 0.0, rate))
        if not sgn.any():
            notes.append(f"the output {out.point} does not move")
        n = len(grid)
        idx = np.nonzero(sgn != np.roll(sgn, -1))[0] if periodic else np.nonzero(sgn[:-1] != sgn[1:])[0]
        for i in idx:
            a = float(grid[i])
            b = float(grid[i + 1]) if i + 1 < n else t1
            extremes.append(_refine(solver, out, mech, a, b, sgn[i] > 0, step=T * 1e-13))
        if len(extremes) == 2:
            with np.errstate(all="ignore"):
                val = out.value(solver.solve(np.array(extremes)), mech)
            stroke = float(abs(val[1] - val[0]))
            if periodic:
                span = (extremes[1] - extremes[0]) % T
                slow, fast = max(span, T - span), min(span, T - span)
                K = slow / fast
                theta = math.pi * (K - 1) / (K + 1)
                start = extremes[0] if span >= T - span else extremes[1]
                if start is extremes[1]:
                    extremes.reverse()
        elif len(extremes) > 2:
            notes.append(f"the output {out.point} has {len(extremes)} turning points over the interval")
    if periodic:
        pos = tuple(t0 + (start - t0 + T * i / n_positions) % T for i in range(n_positions))
    else:
        pos = tuple(t0 + T * i / max(n_positions - 1, 1) for i in range(n_positions))
    return Cycle(out, False, tuple(extremes), stroke, theta, K, pos, None, tuple(notes),
                 (t0, t1), kind="time", span=(t0, t1), periodic=periodic)


def _periodic(mech: Mechanism, T: float) -> bool:
    """Whether the interval ``T`` (s) is a period of every driver's law: each is where it
    began, at the same speed, after it (a crank by whole turns)."""
    t0 = mech.timing.span[0]
    for d in mech.drivers:
        (q0, w0, _), (q1, w1, _) = d.law.at(t0), d.law.at(t0 + T)
        diff = q1 - q0 if d.linear else math.remainder(q1 - q0, TWO_PI)
        size = max(abs(q0), abs(q1), 1e-3) if d.linear else 1.0
        if abs(diff) > 1e-9 * size or abs(w1 - w0) > 1e-9 * max(abs(w0), abs(w1), 1e-3):
            return False
    return True


def at_rest(mech: Mechanism, linear: bool, order: int = 1) -> float:
    """Below this an output's value (``order`` 0), rate (1) or acceleration (2) is rounding
    of 0: 1e-9 of the crank's own (its pin's for a linear output) to that order."""
    return tolerances.AT_REST * (mech.driver.length if linear else 1.0) * abs(mech.driver.omega) ** order


def _change_points(solver: Solver, grid: np.ndarray) -> tuple[tuple[float, ...], np.ndarray]:
    """The change points of the solver's motion as crank angles (rad from +x) in the order
    the crank meets them from ``grid[0]``, and the samples of ``grid`` within a step of
    one (where a group may fail to close by rounding, and the plans are singular)."""
    step = abs(grid[1] - grid[0])
    turn = (grid - solver.branch_at) % TWO_PI
    near = np.zeros(grid.shape, dtype=bool)
    offsets = sorted({f for points in solver.changes for f in points})
    for f in offsets:
        near |= apart(turn, f) <= step
    angles = [solver.branch_at + f for f in offsets]
    sense = 1.0 if solver.mech.driver.omega > 0 else -1.0
    angles.sort(key=lambda x: (sense * (x - grid[0])) % TWO_PI)
    return tuple(angles), near


def rate_signs(rate: np.ndarray) -> np.ndarray:
    """The sign of the output's velocity at each sample, a sample where it is exactly 0
    taking the sign of the next one that is not (round the turn): an extreme that falls on
    a sample (the central crank-slider at φ1 = 0) is then one change of sign, between the
    sample before and the zero, and a velocity that touches 0 without turning back is
    none."""
    sgn = np.sign(rate)
    nz = np.flatnonzero(sgn)
    if 0 < nz.size < sgn.size:
        after = np.searchsorted(nz, np.arange(sgn.size)) % nz.size
        sgn = sgn[nz[after]]
    return sgn


def _refine(solver: Solver, out: Output, mech: Mechanism, a: float, b: float,
            rising: bool, step: float = tolerances.ANGLE) -> float:
    """The crank angle in [a, b] where the output's velocity changes sign, from ``rising``
    (positive) at a to the other sign (bisection to 1e-13 rad: the velocity is exact, so
    the extreme is as exact as the angle). The sign at a is the grid's: an extreme on a
    sample has there a velocity of rounding, whose sign one path and the other differ on."""
    def v(phi):
        try:  # one angle on Python numbers: a sixth of the array path's time
            return float(out.rate(solver.solve_one(phi), mech))
        except PlansError:  # where it does not close the array path still gives a sign
            with np.errstate(all="ignore"):
                return float(out.rate(solver.solve(np.array([phi])), mech)[0])

    for _ in range(60):
        mid = 0.5 * (a + b)
        if (v(mid) > 0) == rising:
            a = mid
        else:
            b = mid
        if abs(b - a) < step:
            break
    return 0.5 * (a + b)


def _guide_sides(m: Motion) -> dict[str, np.ndarray]:
    """Per PRP group (by label), the sign of the sine between its two guides at each angle
    of ``m``: it changes where they turn parallel and their common point passes through
    infinity, a limit the crank cannot pass."""
    return {g.group.label: np.sign(np.asarray(g.velocity.sine, dtype=float))
            for g in m.groups if g.group.kind == DyadKind.PRP}


def _limits(solver: Solver, lo: float, hi: float, step: float,
            sides: dict | None = None) -> tuple[float, float]:
    """The crank's limit positions, refined from the last samples ``lo`` and ``hi`` that
    close (``step`` before ``lo`` and after ``hi`` it does not) to 1e-13 rad by bisection,
    both at once; each on the side where the mechanism closes. ``sides``: the sign of each
    PRP group's sine where it closes (:func:`_guide_sides`), which the limits keep."""
    inside = np.array([lo, hi])
    outside = inside + np.array([-step, step])
    for _ in range(60):
        mid = 0.5 * (inside + outside)
        with np.errstate(all="ignore"):
            got = solver.solve(mid)
            ok = got.valid
            for label, side in _guide_sides(got).items() if sides else ():
                ok = ok & (side == sides[label])
        inside, outside = np.where(ok, mid, inside), np.where(ok, outside, mid)
        if np.all(np.abs(outside - inside) < tolerances.ANGLE):
            break
    return float(inside[0]), float(inside[1])


def _interval_around(grid, valid):
    """The assembling interval that contains the given angle (grid[0]), widened by wrap."""
    n = len(grid)
    if not valid[0]:
        return float(grid[0]), float(grid[0])
    j = 0
    while j + 1 < n and valid[j + 1]:
        j += 1
    i = 0
    while -i - 1 > -n and valid[(-i - 1) % n]:
        i += 1
    step = grid[1] - grid[0]
    return float(grid[0] - i * step), float(grid[j])


def _grashof(mech: Mechanism, solver: Solver) -> str | None:
    """Grashof class when the mechanism is a hinged four-bar (crank + one RRR group).

    The group's outer joints are read by what they join, not by their letters P and Q
    nor by the links' numbers: the one on the frame is the rocker's pivot, the one on
    the crank is the coupler's pin (a file may number the rocker before the coupler)."""
    groups = solver.structure.groups
    if len(groups) != 1 or groups[0].kind != DyadKind.RRR:
        return None
    g = groups[0]
    drv = mech.driver
    crank = mech.links[drv.link].points
    ends = {g.P: g.a, g.Q: g.b}  # each outer joint and the link of the group hinged there
    pivots = [p for p in ends if p in mech.frame]
    pins = [p for p in ends if p not in mech.frame and p in crank]
    if len(pivots) != 1 or len(pins) != 1:  # not a four-bar (a dyad carried by the crank)
        return None
    (pivot,), (pin,) = pivots, pins
    coupler, rocker = mech.links[ends[pin]].points, mech.links[ends[pivot]].points
    a = abs(crank[pin] - crank[drv.pivot])
    b = abs(coupler[g.C] - coupler[pin])
    c = abs(rocker[g.C] - rocker[pivot])
    d = abs(mech.frame[pivot] - mech.frame[drv.pivot])
    return grashof_class(a, b, c, d)


def grashof_class(a: float, b: float, c: float, d: float) -> str:
    """Grashof's rule for crank a, coupler b, rocker c, frame d.

    >>> grashof_class(0.05, 0.2, 0.15, 0.2)
    'crank-rocker (Grashof: 0.25 ≤ 0.35)'
    >>> grashof_class(0.3, 0.35, 0.15, 0.4)
    'rocker-crank (Grashof, the shortest link is the rocker, which turns fully: 0.55 ≤ 0.65)'
    >>> grashof_class(0.3, 0.15, 0.35, 0.4)
    'double rocker (Grashof, the shortest link is the coupler: 0.55 ≤ 0.65)'

    Each length must be a positive finite number (a length of −0.03 or 0 was classed
    as if it were a link):

    >>> grashof_class(-0.05, 0.2, 0.15, 0.2)
    Traceback (most recent call last):
    ...
    ValueError: grashof_class: the crank a must be a positive length (m), got -0.05
    """
    for name, x in (("the crank a", a), ("the coupler b", b), ("the rocker c", c),
                    ("the frame d", d)):
        if isinstance(x, bool) or not isinstance(x, numbers.Real) or not 0 < x < math.inf:
            raise ValueError(f"grashof_class: {name} must be a positive length (m), got {x!r}")
    lengths = sorted((a, b, c, d))
    s, longest, p, q = lengths[0], lengths[3], lengths[1], lengths[2]
    lhs, rhs = s + longest, p + q
    tag = f"{lhs:.6g} {'≤' if lhs <= rhs else '>'} {rhs:.6g}"
    if math.isclose(lhs, rhs, rel_tol=1e-12):
        return f"change-point linkage (Grashof equality: {tag}): its links come in line at change points"
    if lhs > rhs:
        return f"double rocker (non-Grashof: {tag})"
    if s == a:
        return f"crank-rocker (Grashof: {tag})"
    if s == d:
        return f"double crank (Grashof: {tag})"
    if s == c:  # the driven link turns fully, the driving one rocks
        return f"rocker-crank (Grashof, the shortest link is the rocker, which turns fully: {tag})"
    return f"double rocker (Grashof, the shortest link is the coupler: {tag})"
