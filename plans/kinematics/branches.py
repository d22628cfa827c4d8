"""Assembly branches from human-readable hints: "above BD", "right of C".

Each group with two assemblies gets a sign, chosen at the file's crank angle by the hints
and then kept over the whole cycle, so the branch stays continuous; at a change point,
where the two assemblies meet, the sign flips so that the motion stays smooth
(:func:`change_points`).
"""

from __future__ import annotations

import math

import numpy as np

from plans import tolerances
from plans.errors import AssemblyError, InputError, SingularPlanError
from plans.kinematics.dyads import DYADS
from plans.kinematics.records import coincident_name
from plans.model import Mechanism
from plans.model.hints import Ambiguous, hint_holds, parse_hint
from plans.model.structure import DyadKind, Structure

#: samples of the turn searched for change points
CHANGE_SAMPLES = 3600


def change_points(sv) -> tuple[tuple[tuple[float, ...], ...], tuple[tuple[float, ...], ...],
                               float | None]:
    """Per group of ``sv``, the change points of its motion: counter-clockwise turns of
    the crank from ``sv.branch_at`` (rad, in [0, 2π), ascending) where the group's
    links come in line and part again on the same side without ever failing to close;
    per group those where its sign flips; and the seam, a turn from ``sv.branch_at`` where
    the mechanism does not close (None when it makes a full turn), across which the flips
    are not counted (:meth:`plans.kinematics.Solver.sigma`).

    There the group's margin (how far inside its limit it is) touches 0 and rises
    again, and its two assemblies meet: kept, the sign would fold the linkage into the
    other assembly with a kink in its motion (a parallelogram into an antiparallelogram,
    an isosceles crank-slider's slider to rest on the crank's pivot). The smooth motion
    goes on with the other sign. A minimum of the margin on a grid of the turn is refined
    (to about 1e-10 rad) and taken when it lies within :data:`plans.tolerances.IN_LINE` of 0; one below
    that is a dead point of a linkage that cannot turn there.

    Where a group meets an odd number of them a turn, its smooth motion repeats only
    after two turns (a kite's, a crank-slider's with its rod as long as crank and offset
    together): it keeps its sign, and folds back at them, as long as that is a
    continuous motion. A slotted link whose pivot is on the crank circle would turn
    over by 180° at once as the block passes the pivot: it follows its smooth motion,
    half the crank's turn, with the seam of the two turns at ``branch_at``. A crank that
    cannot make a full turn has no turn to repeat: its groups flip at every change point
    within its range.
    """
    n = len(sv.structure.groups)
    if sv.mech.timed or sv.mech.driver.linear:  # no turn to search: a motion in time, a slider
        return ((),) * n, ((),) * n, None
    found: list[tuple[float, ...]] = []
    flips: list[tuple[float, ...]] = []
    grid = sv.branch_at + np.linspace(0.0, 2 * math.pi, CHANGE_SAMPLES, endpoint=False)
    step = 2 * math.pi / CHANGE_SAMPLES
    with np.errstate(all="ignore"):
        kept = sv.with_flips(((),) * n).solve(grid)  # every sign kept: serves until one flips
    gap = ~kept.placed
    seam = None
    if gap.any() and not gap[0]:  # the middle of the first run of angles that do not close
        first = int(np.argmax(gap))
        last = first + int(np.argmin(gap[first:])) - 1 if not gap[first:].all() else len(gap) - 1
        seam = 0.5 * (first + last) * step
    for i, g in enumerate(sv.structure.groups):
        if not DYADS[g.kind].assemblies:  # no assemblies to meet
            found.append(())
            flips.append(())
            continue
        trial = sv.with_flips(tuple(flips) + ((),) * (n - i), seam)
        if any(flips):
            with np.errstate(all="ignore"):
                kept = trial.solve(grid)
        margin = kept.groups[i].margin
        low = (margin <= np.roll(margin, 1)) & (margin < np.roll(margin, -1)) & (margin < 1e-3)
        points = []
        for k in np.flatnonzero(low):
            at, least = _lowest(trial, i, grid[k] - step, grid[k] + step)
            if abs(least) <= tolerances.IN_LINE:
                points.append((at - sv.branch_at) % (2 * math.pi))
        points.sort()
        found.append(tuple(points))
        smooth = len(points) % 2 == 0 or seam is not None or _jumps(trial, i, points)
        flips.append(tuple(points) if smooth else ())
    return tuple(found), tuple(flips), seam


def _jumps(sv, i: int, points: list[float]) -> bool:
    """Whether a link of group ``i`` turns over (by more than a degree) within 1e-6 rad of
    one of its change points when it keeps its sign."""
    g = sv.structure.groups[i]
    near = np.array([[p - 1e-6, p + 1e-6] for p in points]).ravel() + sv.branch_at
    with np.errstate(all="ignore"):
        m = sv.solve(near)
    for lid in (g.a, g.b):
        rot = m.links[lid].rotor
        if np.any(np.abs(rot[1::2] - rot[::2]) > math.radians(1)):
            return True
    return False


def _lowest(sv, i: int, lo: float, hi: float) -> tuple[float, float]:
    """Where in [lo, hi] group ``i``'s margin is least, and that margin: 33 samples,
    narrowed eight times round the least (to about 1e-12 rad of the turn).

    A margin that touches 0 as a square (links coming in line) is flat to rounding for
    some 1e-8 rad round its least, where the samples pick any point: the place is then
    the vertex of the parabola through the margins 1e-5 rad either side, which the
    margin's third-order term and rounding leave some 1e-10 rad off."""
    with np.errstate(all="ignore"):
        for _ in range(8):
            xs = np.linspace(lo, hi, 33)
            margin = sv.solve(xs).groups[i].margin
            j = int(np.argmin(margin))
            lo, hi = xs[max(j - 1, 0)], xs[min(j + 1, 32)]
        at, h = float(xs[j]), 1e-5
        left, mid, right = sv.solve(np.array([at - h, at, at + h])).groups[i].margin
    bend = left - 2 * mid + right
    if bend > 0 and abs(left - right) < 2 * bend:  # the vertex lies within h of ``at``
        at += h * (left - right) / (2 * bend)
    return at, float(margin[j])


def choose_branches(mech: Mechanism, structure: Structure,
                    trial) -> tuple[tuple[int, ...], float, float]:
    """Turn the file's hints into a sign per group, evaluated at the file's crank angle
    (``mech.hints_at`` when the crank was turned from it, :meth:`Mechanism.at_file_angle`);
    returns the signs, that angle and the one they were read at (rad from +x): the same,
    unless a group's two assemblies meet there (:func:`_read`).

    The sign (which side of the line of centres, which way along the guide) is then kept
    over the whole cycle, so the branch stays continuous: ``--angle 180`` gives the
    position the cycle passes through at 180°, not whichever assembly the hint's words
    would pick there. Where the mechanism does not close at the file's angle, the hints
    are read at the angle asked for instead.

    ``trial(phi, sigmas, count)``: the motion of the first ``count`` groups at crank angle
    ``phi`` on the signs ``sigmas``, none flipping (an array of one angle): the solver's.
    """
    at = mech.hints_at
    if at is not None and at != mech.param:
        try:
            return _read(mech.with_phi(at), structure, trial)
        except (AssemblyError, SingularPlanError):
            pass
    return _read(mech, structure, trial)


class _Meet(Exception):
    """A group's two assemblies meet at the angle the hints are read at."""


def _read(mech: Mechanism, structure: Structure, trial) -> tuple[tuple[int, ...], float, float]:
    """The signs the hints give, the mechanism's angle, and the angle they were read at:
    the mechanism's own, or, where a group's two assemblies meet there,
    :data:`plans.tolerances.PAST_MEETING` on, the way the crank turns (or back, where the linkage does not
    close on that side or the hints part nothing there). The change point itself is then
    one the motion passes (a parallelogram given at 0°), and the motion's turn still
    starts at the given angle (:meth:`plans.kinematics.Solver.sigma`)."""
    phi = mech.param
    try:
        return _choose(mech, structure, trial), phi, phi
    except _Meet as meet:
        step = math.copysign(tolerances.PAST_MEETING, 1.0 if mech.timed else mech.driver.omega)
        first = None
        for past in (phi + step, phi - step):
            try:
                return _choose(mech.with_phi(past), structure, trial), phi, past
            except (AssemblyError, SingularPlanError, _Meet):
                continue
            except InputError as exc:  # the hints part nothing there: the other side?
                first = first or exc
        if first is not None:
            unit = "s" if mech.timed else "rad"
            why = (f" (read {tolerances.PAST_MEETING:g} {unit} past {mech.at(phi)}, where the two "
                   f"assemblies of {meet} meet)")
            raise InputError(first.source, [p + why for p in first.problems]) from None
        return _choose(mech, structure, trial, meet=False), phi, phi  # its error, or rounding's pick


def _same(positions: dict, name: str) -> bool:
    """Whether the two assemblies (``positions`` by sign) put point ``name`` in one place,
    to rounding of the mechanism's size."""
    a, b = (complex(positions[sigma].position[name][0]) for sigma in (1, -1))
    return abs(a - b) <= tolerances.SAME_PLACE * (1.0 + abs(a) + abs(b))


def _at_both(positions: dict, name: str, joint: str = " and ") -> str:
    """Where the two assemblies put point ``name``, for messages."""
    return joint.join(f"({X.real:.4g}, {X.imag:.4g})" for X in (
        complex(positions[sigma].position[name][0]) for sigma in (1, -1)))


def _parting(g, mech: Mechanism, positions: dict) -> str:
    """The point to name in a hint for group ``g``: its new point, or the first point of
    its links that the two assemblies put in different places (a slotted link's rocker
    end, not its pivot)."""
    names = ([g.C] if g.C else []) + list(mech.links[g.b].points) + list(mech.links[g.a].points)
    for name in names:
        if name in positions[1].position and name in positions[-1].position:
            if not _same(positions, name):
                return name
    return g.C or next(iter(mech.links[g.b].points))


def _choose(mech: Mechanism, structure: Structure, trial, meet: bool = True) -> tuple[int, ...]:
    """The sign of each group by the hints at the mechanism's angle; ``meet``: raise
    :class:`_Meet` where a group's two assemblies meet there (to rounding)."""
    names = mech.point_names()
    hints = {}
    for key, text in mech.assembly.items():
        try:
            hints[key] = parse_hint(text, names)
        except ValueError as exc:
            raise InputError(mech.source, f"assembly.{key}: {exc}") from None
    used = set()
    sigmas: list[int] = []
    for i, g in enumerate(structure.groups):
        if not DYADS[g.kind].assemblies:
            sigmas.append(1)
            continue
        group_points = set(mech.links[g.a].points) | set(mech.links[g.b].points)
        mine = {k: h for k, h in hints.items() if k in group_points}
        ok = []
        positions = {}
        for sigma in (1, -1):
            motion = trial(mech.param, (*sigmas, sigma), i + 1)
            positions[sigma] = motion
            for k, (_, refs) in mine.items():
                if later := [r for r in refs if r not in motion.position]:
                    raise InputError(
                        mech.source,
                        f"assembly.{k}: {mech.assembly[k]!r} names {later[0]}, a point found "
                        f"after {g.label}, the group of {k}: name fixed points or points found "
                        "before it")
            if not motion.valid[0]:
                continue
            holds = True
            for k, (rel, refs) in mine.items():
                try:
                    holds &= hint_holds(rel, complex(motion.position[k][0]),
                                        [complex(motion.position[r][0]) for r in refs])
                except Ambiguous as exc:
                    line = "".join(refs)
                    other = ('"left of {0}" or "right of {0}"' if str(exc) == "vertical"
                             else '"above {0}" or "below {0}"').format(line)
                    raise InputError(
                        mech.source,
                        f"assembly.{k}: {mech.assembly[k]!r}: the line {line} is {exc} at "
                        f"{mech.at(mech.param)}, so {rel} it names no side: "
                        f"write {other}") from None
            if holds:
                ok.append(sigma)
        margin = positions[1].groups[i].margin
        # on a meeting point to rounding the hints are read past it, unless they part the
        # two assemblies here (a parallelogram given 1e-6 rad short of its change point,
        # its coupler 1e-7 below OD and the other assembly's above: the file's own angle)
        if (meet and margin is not None and abs(float(np.ravel(margin)[0])) <= tolerances.IN_LINE
                and not (mine and len(ok) == 1)):
            raise _Meet(g.label)
        used |= set(mine)
        if len(ok) == 1:
            sigmas.append(ok[0])
            continue
        if g.kind == DyadKind.RPR and not mine:
            sigmas.append(1)  # the guide's axis points from its pivot towards the block
            continue
        if not positions[1].valid[0]:
            earlier = sorted(used - set(mine))
            note = ""
            if earlier:
                asked = ", ".join(f"{k} = {mech.assembly[k]!r}" for k in earlier)
                note = (f" (the groups before it are assembled as the hints {asked} ask: is one of "
                        "them wrong?)")
            raise positions[1].groups[i].failure(0, mech.at(mech.param), note,
                                                 source=mech.source, phi=mech.param)
        new = g.C or coincident_name(g.P, g.b)
        key = _parting(g, mech, positions)
        if mine and key not in mine and all(
                _same(positions, k) for k in mine if k in positions[1].position):
            # a hint on a point both assemblies put in one place (a slotted link's block
            # on the crank pin, the rocker's pivot) can choose neither
            k = next(iter(mine))
            raise InputError(
                mech.source,
                f"assembly.{k}: {k} stands at the same place in both assemblies of "
                f"{g.label} at {mech.at(mech.param)}, so a hint on it chooses "
                f"neither: write one on {key}, which stands at {_at_both(positions, key)}")
        if not mine:
            raise InputError(
                mech.source,
                f"assembly: {g.label} closes two ways at {mech.at(mech.param)}, with {key} at "
                f"{_at_both(positions, key, ' or ')}: add a hint such as [assembly] {key} = "
                f'"above {g.P or ""}{g.Q or ""}"',
            )
        hints_ = ", ".join(f"{k} = {mech.assembly[k]!r}" for k in mine)
        if ok:  # both: say where the two are, so that the hint can be chosen between them
            raise InputError(
                mech.source,
                f"assembly: the {'hint' if len(mine) == 1 else 'hints'} {hints_} "
                f"{'fits' if len(mine) == 1 else 'fit'} both "
                f"assemblies of {g.label} at {mech.at(mech.param)}, with {key} at "
                f"{_at_both(positions, key)}: name a point or line that parts them")
        raise InputError(
            mech.source,
            f"assembly: the {'hint' if len(mine) == 1 else 'hints'} {hints_} "
            f"{'fits' if len(mine) == 1 else 'fit'} neither "
            f"assembly of {g.label} at {mech.at(mech.param)} (new point {new})",
        )
    unused = set(hints) - used
    if unused:
        k = sorted(unused)[0]
        raise InputError(mech.source, f"assembly.{k}: {k} is not a point of a group with two assemblies")
    return tuple(sigmas)
