"""The table of ``plans cycle``: every point and link over N crank positions of the cycle,
and the conditioning of each position.

The positions are numbered from an extreme position of the output, as the course numbers
them (``plans.cycle.analyse_cycle``): position 0 starts the working (slower) stroke. For a
linkage whose crank cannot make a full turn, the N positions span the crank range where it
assembles.

Each position carries its conditioning: for every group the sine of the angle between the
two lines the plans intersect (``Construction.sine``; 1 = perpendicular, 0 = parallel, a
dead point or toggle), and for a slotted link (RPR) also how far the block is from the
rocker's pivot relative to the loop (|QP| / (|OQ| + |OP|), O the crank's pivot): near 0
the rocker's ω = V / |QP| loses its digits. A figure below ``WARN_SINE`` (≈ 2°) makes a
warning, below ``SINGULAR_SINE`` (or a group that does not close) an error: the values of
that position are then left out (the position is not ``ok``; where the positions stand it
is still ``placed``).

A position on a change point (a parallelogram at 0° and 180°) is no error: the positions
stand there, only its plans are singular. So is one beside a change point whose figure is
under ``CHANGE_SINE`` (1e-3), where the acceleration plan would lose its digits as
1/sin³. Its status gives the positions, leaves the velocities and accelerations out, and
says why (``singular``).

How the table is written (text, CSV, JSON) is the command's: :mod:`plans.cli.cycle`.
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass

import numpy as np

from plans import tolerances
from plans.cycle.analysis import analyse_cycle, table_angle
from plans.cycle.existence import support_conditions
from plans.cycle.transmission import transmission
from plans.cycle.words import shown_from
from plans.kinematics.conditioning import (
    is_pivot,
    near_pivot,
    on_pivot,
    pivot_figure,
    pivot_key,
    sine_figure,
)
from plans.kinematics.solver import Solver
from plans.kinematics.transmission import gamma as angle_of


@dataclass(frozen=True)
class Status:
    """Conditioning and diagnostics of one position."""

    ok: bool  # solved: every group closes and no figure is singular
    placed: bool  # the positions stand: every group closes (or misses it by rounding)
    min_sine: float  # the smallest |sin| between intersected lines (NaN if it does not close)
    figures: dict[str, float]  # per group: "group 2–3 (RPR)" → |sin|; "… pivot" → |QP| ratio
    warnings: tuple[str, ...]
    errors: tuple[str, ...]
    #: why the plans are singular where the position is a change point (positions only)
    singular: tuple[str, ...] = ()

    @property
    def state(self) -> str:
        return ("error" if self.errors else "singular" if self.singular
                else "warning" if self.warnings else "ok")


@dataclass(frozen=True)
class CycleTable:
    """N positions of the cycle (:func:`compute`): the motion over them (arrays, one
    value a position) and each position's :class:`Status`."""

    mechanism: object
    cycle: object
    motion: object
    status: tuple[Status, ...]
    points: tuple[str, ...]
    links: tuple[int, ...]
    output_values: object | None  # array: s (m) or ψ (rad) of the output, or None
    #: per group (by its label) its transmission angle γ at each position (rad, NaN where
    #: the group does not close), and the transmission over the whole cycle
    #: (:func:`plans.cycle.transmission.transmission`)
    gamma: dict | None = None
    transmission: object | None = None
    #: a moving rocker support's crank-existence conditions
    #: (:func:`plans.cycle.existence.support_conditions`), None for other mechanisms
    conditions: object | None = None


def compute(mech, n_positions: int, solver=None) -> CycleTable:
    """The table of ``mech`` over ``n_positions`` positions of its cycle, numbered as
    :func:`plans.cycle.analyse_cycle` numbers them; ``solver``: the mechanism's, if made."""
    solver = solver or Solver(mech)
    cycle = analyse_cycle(mech, n_positions=n_positions, solver=solver)
    phi = np.array(cycle.positions, dtype=float)
    with np.errstate(all="ignore"):
        motion = solver.solve(phi)
        status = conditioning(mech, motion, solver, shown_from(cycle, mech.driver))
        out_values = None
        if cycle.output is not None:
            out_values = cycle.output.value(motion, mech)
            if cycle.output.kind == "angular":
                out_values = table_angle(out_values, cycle.full_turn)
    points = tuple(motion.position)
    links = tuple(sorted(lid for lid in motion.links if lid != 0))
    placed = np.broadcast_to(np.asarray(motion.placed, dtype=bool), phi.shape)
    gamma = {g.group.label: np.where(placed & np.asarray(g.valid, dtype=bool),
                                     np.broadcast_to(angle_of(g), phi.shape), np.nan)
             for g in motion.groups}
    return CycleTable(mech, cycle, motion, status, points, links, out_values, gamma,
                      transmission(solver, cycle), support_conditions(mech, solver, cycle))


def figure_labels(t: CycleTable) -> list[str]:
    """The conditioning figures' keys, each once, in the order the rows give them: one
    column each in the CSV and the text table, whichever rows lack one."""
    return list(dict.fromkeys(key for st in t.status for key in st.figures))


def conditioning(mech, motion, solver=None, lo: float = 0.0) -> tuple[Status, ...]:
    """Per position: the figures of every group, warnings and errors (see the module doc);
    ``solver``, the motion's, names the change points among the angles; ``lo``: the turn
    the angles are written in (:func:`plans.cycle.shown_from` of the motion's cycle)."""
    n = len(motion.phi)
    crank_pivot = mech.driver.origin
    # read here, not bound at import: a test moves the thresholds to exercise the error path
    warn_sine, singular_sine = tolerances.WARN_SINE, tolerances.SINGULAR_SINE
    per_group = [(g, pivot_figure(g, motion.position, crank_pivot)) for g in motion.groups]
    # each group's figures as Python lists, once; words only where a position is flagged
    cols = []
    for g, pivot in per_group:
        s = np.broadcast_to(sine_figure(np.asarray(g.velocity.sine, dtype=float)), (n,))
        valid = np.broadcast_to(np.asarray(g.valid, dtype=bool), (n,))
        q = None if pivot is None else np.where(np.isfinite(pivot), pivot, 0.0).tolist()
        cols.append((g, g.group.label, valid.tolist(), s.tolist(), (s < warn_sine).tolist(), q))
    phis = np.asarray(motion.phi, dtype=float).tolist()
    at_ = ((lambda phi: solver.at(phi, "en", lo)) if solver is not None else
           (lambda phi: mech.driver.at(phi, "en", lo)))
    at = functools.cache(lambda k: at_(phis[k]))  # words only where flagged, once
    placed = np.broadcast_to(np.asarray(motion.placed, dtype=bool), (n,)).tolist()
    plain = (singular_sine, singular_sine)
    out = []
    for k in range(n):
        figures: dict[str, float] = {}
        warnings: list[str] = []
        errors: list[str] = []
        singular: list[str] = []  # positions stand, plans singular: beside a change point
        for i, (g, label, valid, sine, low, pivot) in enumerate(cols):
            # a group beside one of its change points: its figures must reach CHANGE_SINE
            # (Solver.singular_figures), and its failures are the change point's: positions
            # only, no error. Looked up only where a figure calls for a word
            flagged = not valid[k] or low[k] or (pivot is not None and pivot[k] < warn_sine)
            under, under_q = (solver.singular_figures(i, phis[k])
                              if flagged and solver is not None else plain)
            fails = singular if under > singular_sine and placed[k] else errors
            if not valid[k]:
                fails.append(str(g.failure(k, at(k))))
                figures[label] = sine[k] if placed[k] else math.nan  # in line: about 0
                if pivot is not None:  # every row has every figure: the CSV's columns
                    figures[pivot_key(label)] = pivot[k] if placed[k] else math.nan
                continue
            figures[label] = sine[k]
            if low[k]:
                if (err := g.parallel(k, at(k), below=under)) is not None:
                    fails.append(str(err))
                elif (warning := g.near_parallel(k, at(k), below=under)) is not None:
                    warnings.append(warning)
            if pivot is not None:
                q = pivot[k]
                figures[pivot_key(label)] = q
                if q < warn_sine:  # worded (and the angle with it) only where flagged
                    if (err := on_pivot(g, q, at(k), below=under_q)) is not None:
                        fails.append(str(err))
                    else:
                        warnings.append(near_pivot(g, q, at(k), below=under_q))
        sines = [v for key, v in figures.items() if not is_pivot(key)]
        if not sines:
            min_sine = 1.0
        elif all(math.isfinite(v) for v in sines):
            min_sine = min(sines)
        else:
            min_sine = math.nan
        out.append(Status(not errors and not singular, placed[k], min_sine, figures,
                          tuple(warnings), tuple(errors), tuple(singular)))
    return tuple(out)
