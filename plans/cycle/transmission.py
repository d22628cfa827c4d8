"""The transmission angle over the cycle: each group's least γ and where it occurs, and the
dead points, where γ = 0.

γ of a group at one position is :func:`plans.kinematics.transmission.gamma`'s. Over the
cycle it is sampled (the turn, the crank's range, a slider's travel or the laws' interval
in time), its least sample narrowed by golden-section search to 1e-12 of the cycle's
span, where a smooth minimum is found (a crank-rocker's at the crank in line with the
frame, an offset crank-slider's at the crank across the guide): the value is then exact to
rounding, its place to about 1e-8 of the span. A dead point is a position of the cycle
where a group's γ is 0: its links in line (a limit of a crank that cannot turn, a change
point) or its two guides parallel; the plans are singular there.

Driven from its output instead, any mechanism stands at a dead point in the output's
extreme positions, where the output is at rest while the crank turns: those are said too
(:attr:`Transmission.reversed`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from plans.errors import PlansError
from plans.fmt import angle, num, unit
from plans.geometry import golden_min
from plans.kinematics.solver import Solver
from plans.kinematics.transmission import between, gamma
from plans.model.structure import Group

#: samples of the cycle γ is searched over
SAMPLES = 3600
#: γ below this (rad) at a limit of the cycle is 0: a dead point found to rounding
DEAD = 1e-6


@dataclass(frozen=True)
class GroupAngle:
    """One group's transmission over the cycle."""

    group: Group
    #: rad: the least γ over the cycle, and where (the cycle's parameter: a crank angle,
    #: a slider's travel or an instant)
    gamma_min: float
    at: float
    #: where its γ is 0 (dead points: a limit of the cycle's range), in the cycle's order
    dead: tuple[float, ...] = ()
    #: γ is the same at every position (a slotted link whose slot runs through its pivot:
    #: 90°), to 1e-9 rad
    constant: bool = False
    #: the change points where its γ is 0: its links lie in line there and the motion
    #: goes on through them on one branch or the other
    change: tuple[float, ...] = ()

    @property
    def pressure_max(self) -> float:
        """The largest pressure angle α = 90° − γmin (rad)."""
        return math.pi / 2 - self.gamma_min


@dataclass(frozen=True)
class Transmission:
    """Every group's transmission over the cycle, and the dead points the mechanism would
    have if its output drove it (its extreme positions)."""

    groups: tuple[GroupAngle, ...]
    reversed: tuple[float, ...] = ()

    @property
    def least(self) -> GroupAngle | None:
        """The group whose γ falls lowest: the mechanism's γmin."""
        return min(self.groups, key=lambda g: g.gamma_min, default=None)


def _grid(cycle, n: int) -> np.ndarray:
    """The parameters the cycle is sampled at: its turn from position 0 in the crank's
    sense, else its range or interval, ends included."""
    if cycle.kind == "turn" and cycle.full_turn:
        start = cycle.positions[0] if cycle.positions else 0.0
        sense = 1.0 if len(cycle.positions) < 2 or _ahead(cycle) else -1.0
        return start + sense * np.linspace(0.0, 2 * math.pi, n, endpoint=False)
    lo, hi = cycle.span if cycle.span is not None else cycle.crank_range
    return np.linspace(lo, hi, n)


def _ahead(cycle) -> bool:
    """Whether the cycle's positions run counter-clockwise (the crank's sense)."""
    a, b = cycle.positions[0], cycle.positions[1]
    return math.remainder(b - a, 2 * math.pi) > 0


def transmission(solver: Solver, cycle, samples: int = SAMPLES) -> Transmission:
    """γmin of every group over ``cycle`` (:func:`plans.cycle.analyse_cycle`, by
    ``solver``), where each occurs, and the dead points (module docstring)."""
    grid = _grid(cycle, samples)
    with np.errstate(all="ignore"):
        m = solver.solve(grid)
    placed = np.asarray(m.placed, dtype=bool)
    out = []
    for i, g in enumerate(m.groups):
        gam = np.where(placed & np.asarray(g.valid, dtype=bool), gamma(g), np.nan)
        dead, change = _dead(solver, cycle, i)
        if cycle.kind == "time":
            dead += _limits_in_time(solver, grid, placed & np.asarray(g.valid, dtype=bool), i)
        zero = dead + change
        if not np.isfinite(gam).any():
            out.append(GroupAngle(g.group, math.nan, math.nan, dead, change=change))
            continue
        k = int(np.nanargmin(gam))
        if np.nanmax(gam) - gam[k] <= 1e-9:
            out.append(GroupAngle(g.group, float(gam[k]), float(grid[k]), dead, constant=True,
                                  change=change))
            continue
        if zero and (gam[k] < DEAD or not math.isfinite(gam[k])):
            out.append(GroupAngle(g.group, 0.0, zero[0], dead, change=change))
            continue
        lo, hi = grid[max(k - 1, 0)], grid[min(k + 1, len(grid) - 1)]
        at, least = _golden(solver, i, float(lo), float(hi), float(gam[k]), float(grid[k]))
        if zero:
            least, at = (0.0, zero[0]) if least > 0 else (least, at)
        out.append(GroupAngle(g.group, least, at, dead, change=change))
    rev = tuple(cycle.extremes) if cycle.full_turn and cycle.stroke else ()
    return Transmission(tuple(out), rev)


def _dead(solver: Solver, cycle, i: int) -> tuple[tuple[float, ...], tuple[float, ...]]:
    """Where group ``i``'s γ is 0 within the cycle: the limits of a range the group closes
    no farther than (its links in line there, or its guides parallel: dead points), and
    its change points."""
    found, change = [], []
    if not cycle.full_turn and cycle.crank_range is not None and cycle.kind != "time":
        for x in cycle.crank_range:
            with np.errstate(all="ignore"):
                g = solver.solve(np.array([x])).groups[i]
            gam = float(np.ravel(gamma(g))[0])
            if not math.isfinite(gam) or gam < DEAD or abs(float(np.ravel(g.margin)[0])) < DEAD:
                found.append(float(x))
    for x in cycle.change_points:
        if solver.change_point_near(x, i) is not None:
            change.append(float(x))
    return tuple(found), tuple(change)


def _limits_in_time(solver: Solver, grid, ok, i: int) -> tuple[float, ...]:
    """The instants where group ``i`` stops (or starts) closing within the interval
    ``grid`` samples (``ok``: where it closes): each found by bisection to 1e-13 of the
    interval, the last instant it closes. Its links lie in line there: a dead point."""
    span = float(grid[-1] - grid[0]) or 1.0
    found = []
    for k in np.flatnonzero(ok[:-1] != ok[1:]):
        good, bad = (float(grid[k]), float(grid[k + 1])) if ok[k] else (float(grid[k + 1]), float(grid[k]))
        while abs(bad - good) > 1e-13 * span:
            mid = (good + bad) / 2
            with np.errstate(all="ignore"):
                m = solver.solve(np.array([mid]))
            closes = bool(np.ravel(m.placed)[0]) and bool(np.ravel(m.groups[i].valid)[0])
            good, bad = (mid, bad) if closes else (good, mid)
        found.append(good)
    return tuple(found)


def _golden(solver: Solver, i: int, lo: float, hi: float, best: float, at: float
            ) -> tuple[float, float]:
    """Where in [lo, hi] group ``i``'s γ is least, and that γ: golden-section search to
    1e-12 of the interval, each γ on Python numbers (the array path where that one
    refuses: beside a limit)."""
    def f(x: float) -> float:
        try:
            with np.errstate(all="ignore"):
                return gamma(solver.solve_one(x).groups[i])
        except (PlansError, ArithmeticError, ValueError):
            with np.errstate(all="ignore"):
                g = solver.solve(np.array([x])).groups[i]
            v = float(np.ravel(gamma(g))[0])
            return v if bool(np.ravel(g.valid)[0]) and math.isfinite(v) else math.inf

    x = golden_min(f, lo, hi, width=1e-12 * max(abs(hi - lo), 1e-300), iterations=80)
    v = f(x)
    return (x, v) if v <= best else (at, best)


#: the transmission's sentences, by language
WORDS = {
    "en": {
        "head": "Transmission angles",
        "at": "{label}: γ = {g}° between {between}; pressure angle α = 90° − γ = {a}°",
        "min": "over the cycle γmin = {g}° (the largest pressure angle {a}°) at {at}",
        "constant": "γ = {g}° at every position of the cycle",
        "dead": "{label}: dead points (γ = 0) at {at}",
        "change": "{label}: γ = 0 at the change points {at}, its links in line",
        "none": "γ > 0 at every position of the cycle: the input drives the mechanism throughout",
        "reversed": "driven from its output {out}, the mechanism would stand at dead points in its "
                    "extreme positions, at {at}",
        "and": ", ",
    },
    "ru": {
        "head": "Углы передачи движения",
        "at": "{label}: γ = {g}° {between}; угол давления α = 90° − γ = {a}°",
        "min": "за цикл γmin = {g}° (наибольший угол давления {a}°) при {at}",
        "constant": "γ = {g}° во всех положениях цикла",
        "dead": "{label}: мёртвые положения (γ = 0) при {at}",
        "change": "{label}: γ = 0 в особых положениях при {at}, звенья группы на одной прямой",
        "none": "γ > 0 во всех положениях цикла: начальное звено ведёт механизм на всём цикле",
        "reversed": "при ведущем выходном звене ({out}) механизм проходил бы мёртвые положения в "
                    "крайних положениях, при {at}",
        "and": ", ",
    },
}


def place(mech, x: float, lang: str = "en", lo: float = 0.0) -> str:
    """Where a γmin or a dead point is, to four digits as the cycle's extreme positions
    are written: "φ1 = 128.8° (from +y, cw)", "s3 = 0.1234 m", "t = 0.3254 s"."""
    d = mech.driver
    if mech.timing is not None:
        return f"t = {num(round(x, 9), 4, lang)} {unit('s', lang)}"
    if d.linear:
        return f"{d.phi_sym} = {num(x, 4, lang)} {unit('m', lang)}"
    return f"{d.phi_sym} = {angle(d.file_angle(x), 4, lang, lo)}°{d.convention(lang)}"


def lines(trans: Transmission | None, mech, groups, at_position: dict[str, float] | None,
          lang: str = "en", lo: float = 0.0, out: str = "") -> list[str]:
    """The transmission in words: each of ``groups`` (the structure's) with its γ and α
    at the position analysed (``at_position``: γ by group label, rad; None: not said),
    its γmin over the cycle and where (``trans``: None, not said), the dead points, and
    those of the mechanism driven from its output ``out``. Places are written by
    :func:`place`, in the turn from ``lo``."""
    w = WORDS[lang]

    def deg(x: float) -> str:
        return num(math.degrees(x), 4, lang)

    def label(grp) -> str:
        return grp.label_in(lang)

    res = []
    over = {g.group.label: g for g in trans.groups} if trans is not None else {}
    any_dead = False
    for grp in groups:
        if at_position is not None and grp.label in at_position:
            g = at_position[grp.label]
            res.append(w["at"].format(label=label(grp), g=deg(g), between=between(grp, lang),
                                      a=deg(math.pi / 2 - g)))
        ga = over.get(grp.label)
        if ga is not None and math.isfinite(ga.gamma_min):
            line = (w["constant"].format(g=deg(ga.gamma_min)) if ga.constant else
                    w["min"].format(g=deg(ga.gamma_min), at=place(mech, ga.at, lang, lo),
                                    a=deg(ga.pressure_max)))
            res.append(("  " + line) if at_position is not None else f"{label(grp)}: {line}")
        if ga is not None and ga.dead:
            any_dead = True
            res.append(w["dead"].format(label=label(grp), at=w["and"].join(
                place(mech, x, lang, lo) for x in ga.dead)))
        if ga is not None and ga.change:
            any_dead = True
            res.append(w["change"].format(label=label(grp), at=w["and"].join(
                place(mech, x, lang, lo) for x in ga.change)))
    if trans is not None and not any_dead:
        res.append(w["none"])
    if trans is not None and trans.reversed and out:
        res.append(w["reversed"].format(out=out, at=w["and"].join(
            place(mech, x, lang, lo) for x in trans.reversed)))
    return res
