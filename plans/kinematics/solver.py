"""Group-by-group solution of positions, velocity plans and acceleration plans.

:class:`Solver` solves a mechanism's groups in their order of attachment, each by its kernel
(``plans/kinematics/kernels.py``), and records every construction (``plans/kinematics/records.py``): over an
array of crank angles at once (:meth:`Solver.solve`), on Python numbers at one angle for
the single-position plan (:meth:`Solver.solve_one`), or without the record, block by
block, for bulk work (:meth:`Solver.sweep`). For each group the velocity and the
acceleration of its new point come from the intersection of two lines, exactly as on paper:

    RRR  V_C  = V_P + V_CP (⊥ CP)          = V_Q + V_CQ (⊥ CQ)
    RRP  V_C  = V_P + V_CP (⊥ CP)          = V_Ck + V_CCk (∥ guide)
    RPR  V_P3 = V_P + V_P3P (∥ guide)      = V_Q + V_P3Q (⊥ QP)
    PRP  V_C  = V_Ck + V_CCk (∥ guide 1)   = V_Cm + V_CCm (∥ guide 2)
    RPP  V_P3 = V_P + V_P3P (∥ guide 1)    = V_Pk + V_P3Pk (∥ guide 2)

and for accelerations the same lines, shifted by the known normal components
a^n = −ω²·r (towards the centre) and the Coriolis components a^k = 2ω × V_rel (the
relative velocity turned by 90° in the sense of the guide's ω).
"""

from __future__ import annotations

import math
from dataclasses import replace
from pathlib import Path

import numpy as np

from plans import tolerances
from plans.errors import SingularPlanError
from plans.geometry import apart
from plans.kinematics import kernels, records
from plans.kinematics.branches import choose_branches
from plans.kinematics.groups import SOLVERS, ScalarFallback
from plans.kinematics.kernels import record
from plans.kinematics.records import (
    Construction,
    GroupSolution,
    LinkState,
    Motion,
    Route,
    Term,
    coincident_name,
    frozen,
    pivot_figure,
)
from plans.model.fileformat import one_line
from plans.model.mechanism import Mechanism
from plans.model.structure import Structure, analyse

__all__ = [
    "Construction", "GroupSolution", "LinkState", "Motion",
    "Route", "Solver", "Term", "coincident_name",
]

def crank_angle(phi) -> float:
    """One crank angle (rad) as a Python float: an array of angles, a complex number or
    nan is one clear error here, not numpy's "only 0-dimensional arrays can be converted
    to Python scalars" or float()'s own words."""
    try:
        out = float(phi)
    except (TypeError, ValueError) as exc:
        many = " (for many angles at once: Solver.sweep or Solver.solve)" if np.ndim(phi) else ""
        raise type(exc)(f"the crank angle must be one number of radians{many}, "
                        f"not {one_line(repr(phi), 60)}") from None
    if not math.isfinite(out):
        raise ValueError(f"the crank angle must be a finite number of radians, not {out}")
    return out


class Solver:
    """Solves one mechanism on one continuous motion: each group's assembly is chosen at
    the crank angle the hints are read at (``branch_at``) and carried over the turn.

    The sign of a group (which side of its line of centres, which way along its guide)
    is kept, except at a change point, where the group's links lie in line and its two
    assemblies meet without parting (a parallelogram at 0° and 180°): there the smooth
    motion goes on in the other sign, as a parallelogram stays one
    (:func:`plans.kinematics.branches.change_points`, found over the turn at the first solve). A
    group that meets an odd number of change points a turn keeps its sign, and folds
    back there, since its smooth motion would take two turns to repeat; unless keeping
    it would make a link jump (a slotted link's pivot on the crank circle). Where the
    crank cannot make a full turn the signs are counted from ``branch_at`` within its
    range, the way the crank goes, not through the angles where it does not close.
    """

    def __init__(self, mech: Mechanism, structure: Structure | None = None,
                 sigmas: tuple[int, ...] | None = None,
                 flips: tuple[tuple[float, ...], ...] | None = None):
        if not isinstance(mech, Mechanism):  # a file's name was 'str' has no 'revolutes'
            hint = (f": read the file first, with load({str(mech)!r})"
                    if isinstance(mech, str | Path) else "")
            raise TypeError(f"a mechanism (plans.load, plans.from_dict) is needed, "
                            f"not {one_line(repr(mech), 60)}{hint}")
        self.mech = mech
        self.structure = structure or analyse(mech)
        # the turn starts at ``branch_at``; ``sigmas`` hold at ``read_at``, which is
        # ``branch_at`` unless a group's two assemblies meet there (a parallelogram given
        # at 0°): then a little past it (plans.kinematics.branches._read)
        if sigmas is None:
            self.sigmas, self.branch_at, self.read_at = choose_branches(mech, self.structure)
        else:  # given signs hold at the mechanism's own angle
            self.sigmas, self.branch_at = sigmas, mech.driver.phi
            self.read_at = self.branch_at
        #: per group, its change points as counter-clockwise turns from ``branch_at``
        #: (rad, in [0, 2π), ascending), and where its sign flips (at all of them, or at
        #: none); None until the first solve
        self._changes = self._flips = flips
        #: where the counting of flips wraps: a turn from ``branch_at`` (rad) where the
        #: mechanism does not close; None: at ``branch_at`` itself
        self._seam: float | None = None
        #: what follows from the mechanism alone, worked out once: the groups' words,
        #: the plans' recipes, the extent of the cycle (``plans.plan``)
        self.cache: dict = {}
        self._todo: dict[int, tuple] = {}  # link → its points that _fill places
        #: links that never turn: a guide on one carries no Coriolis term
        self.translating = mech.translating()
        self.steps = tuple((SOLVERS[g.kind], g, sigma)
                           for g, sigma in zip(self.structure.groups, self.sigmas, strict=True))

    @property
    def changes(self) -> tuple[tuple[float, ...], ...]:
        if self._changes is None:
            from plans.kinematics.branches import change_points

            self._changes, self._flips, self._seam = change_points(self)
        return self._changes

    @property
    def seam(self) -> float | None:
        self.changes  # noqa: B018 - found with them
        return self._seam

    @property
    def flips(self) -> tuple[tuple[float, ...], ...]:
        if self._flips is None:
            self.changes  # noqa: B018 - finds both
        return self._flips

    def sigma(self, i: int, phi):
        """Group ``i``'s sign at crank angle(s) ``phi`` (rad from +x): its sign at
        ``branch_at``, flipped at each change point passed on the way there. The turn
        starts at ``branch_at``: a motion that repeats only after two turns has its seam
        there."""
        flips = self.flips[i]
        if not flips:
            return self.sigmas[i]
        seam = 2 * math.pi if self._seam is None else self._seam
        start = self.sigmas[i]
        if self.read_at != self.branch_at:  # the sign read past a change point at branch_at
            if self._passed(flips, (self.read_at - self.branch_at) % (2 * math.pi), seam) % 2:
                start = -start
        turn = (phi - self.branch_at) % (2 * math.pi)
        if isinstance(turn, float):
            return -start if self._passed(flips, turn, seam) % 2 else start
        f = np.asarray(flips)
        passed = np.where(turn < seam, np.searchsorted(f, turn),
                          len(f) - np.searchsorted(f, turn, side="right"))
        return np.where(passed % 2 == 1, -start, start).astype(float)

    @staticmethod
    def _passed(flips, turn: float, seam: float) -> int:
        """Flips passed from ``branch_at`` to ``turn``: ahead of it up to the seam,
        behind it past the seam."""
        return sum(f < turn for f in flips) if turn < seam else sum(f > turn for f in flips)

    def change_point_near(self, phi: float, group: int | None = None) -> float | None:
        """The change point (crank angle, rad from +x) of group ``group`` (of any: None)
        nearest to ``phi``, if one is within :data:`plans.tolerances.CHANGE_NEAR`."""
        turn = (phi - self.branch_at) % (2 * math.pi)
        best = None
        for i, points in enumerate(self.changes):
            if group is None or i == group:
                for f in points:
                    if (d := apart(turn, f)) < tolerances.CHANGE_NEAR and (best is None or d < best[0]):
                        best = (d, f)
        return None if best is None else self.branch_at + best[1]

    def on_change_point(self, phi: float) -> bool:
        """Whether the crank angle ``phi`` (rad from +x) is a change point, to 1e-9 rad:
        the positions stand there, the plans are singular."""
        near = self.change_point_near(phi)
        return near is not None and apart(phi, near) < tolerances.AT_CHANGE_POINT

    def singular_figures(self, group: int, phi: float) -> tuple[float, float]:
        """Below which figures (the lines' sine, a slotted link's pivot figure) group
        ``group``'s plans are singular at ``phi``: :data:`plans.tolerances.SINGULAR_SINE`, or
        beside one of its change points :data:`plans.tolerances.CHANGE_SINE` and
        :data:`plans.tolerances.CHANGE_PIVOT`."""
        if self.change_point_near(phi, group) is None:
            return tolerances.SINGULAR_SINE, tolerances.SINGULAR_SINE
        return tolerances.CHANGE_SINE, tolerances.CHANGE_PIVOT

    def trusted(self, m) -> np.ndarray:
        """Where the plans of ``m`` can be built: every group closes and its figures, the
        lines' sine and a slotted link's pivot figure, reach :meth:`singular_figures`
        there; over the whole array at once. ``m``: this solver's :class:`Motion` over an
        array of angles, or its :class:`plans.kinematics.sweep.Sweep`, whose ``valid`` alone does not
        see the accelerations that lose their digits beside a change point."""
        phi = np.asarray(m.phi, dtype=float)
        turn = (phi - self.branch_at) % (2 * math.pi)
        ok = np.broadcast_to(np.asarray(m.valid, dtype=bool), phi.shape).copy()
        crank = self.mech.frame[self.mech.driver.pivot]
        if isinstance(m, Motion):
            figures = [(g.velocity.sine, pivot_figure(g, m.position, crank)) for g in m.groups]
        else:  # a sweep: its figures by the group's label, the pivot's worked out here
            pivots = m.pivot
            figures = [(m.sine[g.label], pivots.get(records.pivot_key(g.label)))
                       for g in self.structure.groups]
        for i, (sine, q) in enumerate(figures):
            beside = np.zeros(phi.shape, dtype=bool)
            for f in self.changes[i]:
                beside |= apart(turn, f) < tolerances.CHANGE_NEAR
            with np.errstate(invalid="ignore"):
                sine = np.abs(np.asarray(sine, dtype=float))
                ok &= np.where(np.isfinite(sine), sine, 0.0) >= np.where(
                    beside, tolerances.CHANGE_SINE, tolerances.SINGULAR_SINE)
                if q is not None:
                    ok &= q >= np.where(beside, tolerances.CHANGE_PIVOT, tolerances.SINGULAR_SINE)
        return ok

    def at(self, phi: float, lang: str = "en") -> str:
        """The crank angle ``phi`` in words, as :meth:`plans.model.mechanism.Driver.at` gives it,
        saying so where it is a change point (to 1e-9 rad) or beside one (in English).
        Where the crank cannot make a full turn and its range is written through 0°
        ("from −99.72° to 99.72°"), the angle is written as the range is: −99.7°, not
        260.3° (:func:`plans.cycle.shown_from`)."""
        words = self._at(phi, lang)
        near = self.change_point_near(phi)
        if near is None or lang != "en":
            return words
        if apart(phi, near) < tolerances.AT_CHANGE_POINT:
            return words + " (a change point: the two assemblies of a group meet there)"
        return (words + f" (beside the change point at {self._at(near, lang)}, where the "
                "two assemblies of a group meet)")

    def _at(self, phi: float, lang: str) -> str:
        return self.mech.driver.at(phi, lang, self.shown_from())

    def shown_from(self) -> float:
        """Where the turn that crank angles are written in begins, in the file's
        convention (:func:`plans.cycle.shown_from`): worked out once, from the cycle, or
        where the mechanism's own angle does not assemble, from the nearest range where
        it does (:func:`plans.cycle.reachable_cycle`)."""
        from plans.cycle.analysis import SHOWN_FROM, analyse_cycle, reachable_cycle, shown_from
        from plans.errors import PlansError

        got = self.cache.get(SHOWN_FROM)
        if got is None:
            try:
                analyse_cycle(self.mech, solver=self)  # it keeps the value
                got = self.cache[SHOWN_FROM]
            except PlansError:
                self.cache[SHOWN_FROM] = 0.0  # meanwhile: a message worded as it is found
                other = reachable_cycle(self.mech)
                got = self.cache[SHOWN_FROM] = (
                    0.0 if other is None else shown_from(other[2], self.mech.driver))
        return got

    def with_flips(self, flips: tuple[tuple[float, ...], ...], seam: float | None = None) -> Solver:
        """This solver with the given flips (and seam) instead of its own."""
        out = Solver(self.mech, self.structure, self.sigmas, flips)
        out.branch_at, out.read_at, out._seam = self.branch_at, self.read_at, seam
        return out

    # -------------------------------------------------------------------------------
    def solve(self, phi) -> Motion:
        """Every point and link at the crank angles ``phi`` (rad from +x, any shape).

        Where a group does not close, ``valid`` is False and the values there are
        meaningless (never shown): numpy's warnings for them are silenced here.
        """
        with np.errstate(all="ignore"):
            phi = np.atleast_1d(np.asarray(phi, dtype=float))
            zero = np.zeros_like(phi)
            m = self._solve(kernels.ARRAY, phi, zero, np.exp(1j * phi))
            return self._placed_on_change_points(m) if any(self.changes) else m

    def _placed_on_change_points(self, m: Motion) -> Motion:
        """``m`` with the points that are nowhere on a change point placed where the
        motion puts them: a slotted link's rocker when the block is exactly on its pivot,
        whose direction 0/0 leaves undetermined, is where it stands an instant later
        (:data:`plans.tolerances.LIMIT_STEP` on, in the crank's sense), as the turn from there goes on.
        The plans there stay singular; only positions and the links' poses are filled."""
        placed = m.placed
        if placed.all():
            return m
        flat = m.phi.reshape(-1)
        idx = np.array([k for k in np.flatnonzero(~placed.reshape(-1))
                        if self.on_change_point(float(flat[k]))], dtype=int)
        if not idx.size:
            return m
        on = flat[idx] + math.copysign(tolerances.LIMIT_STEP, self.mech.driver.omega)
        later = self._solve(kernels.ARRAY, on, np.zeros_like(on), np.exp(1j * on))

        def filled(now, then):
            out = np.array(now, copy=True)
            got = out.reshape(-1)[idx]
            out.reshape(-1)[idx] = np.where(np.isfinite(got), got, then)
            return out

        position = {name: filled(z, later.position[name]) for name, z in m.position.items()}
        links = {lid: st._replace(origin=filled(st.origin, later.links[lid].origin),
                                  rotor=filled(st.rotor, later.links[lid].rotor))
                 for lid, st in m.links.items()}
        return replace(m, position=position, links=links)

    def sweep(self, phi, **options):
        """Every point and link at many angles, without the recorded constructions:
        the same kernels block by block (:func:`plans.kinematics.sweep.sweep`), for bulk work."""
        from plans.kinematics import sweep

        return sweep.sweep(self, phi, **options)

    def solve_one(self, phi: float) -> Motion:
        """The same recorded solution at one crank angle, on Python numbers.

        Every value in the result is a Python ``complex`` or ``float`` instead of an array
        of one; it is about twenty times faster than :meth:`solve` on one angle. Where
        the mechanism does not close or a plan is singular it raises the error that
        :meth:`solve` would report for that angle.
        """
        phi = crank_angle(phi)
        try:
            return self._solve(kernels.SCALAR, phi, 0.0, complex(math.cos(phi), math.sin(phi)))
        except (ScalarFallback, ArithmeticError, ValueError):
            pass
        m = self.solve(np.array([phi]))
        at = self.at(phi)
        source = self.mech.source
        for g in m.groups:
            if not g.valid[0]:
                raise g.failure(0, at, source=source)
        for i, g in enumerate(m.groups):
            if (err := g.parallel(0, at, source, self.singular_figures(i, phi)[0])) is not None:
                raise err
        raise SingularPlanError(  # pragma: no cover - every fallback above is a failure
            f"at {at}: the plan has no unique solution", source=source)

    def _solve(self, xp, phi, zero, rotor) -> Motion:
        mech = self.mech
        drv = mech.driver
        if xp.scalar:  # the frame's part is the same at every angle: copied, not rebuilt
            frame = self.cache.get("scalar frame")
            if frame is None:
                frame = self.cache["scalar frame"] = self._frame(0j, 0.0)
        else:
            frame = self._frame(zero * 0j, zero)
        frame_state, pos, vel, acc, owner = frame
        states: dict[int, LinkState] = {0: frame_state}
        pos, vel, acc, owner = dict(pos), dict(vel), dict(acc), dict(owner)
        zc = frame_state.v
        states[drv.link] = record(LinkState, (zc + mech.frame[drv.pivot], rotor, zc, zero + drv.omega, zc, zero))
        self._fill(drv.link, states, pos, vel, acc, owner)
        solutions = []
        valid = True if xp.scalar else np.ones(phi.shape, dtype=bool)
        coincident: dict[str, str] = {}
        flips = self.flips
        for i, (solve_group, g, sigma) in enumerate(self.steps):
            if flips[i]:
                sigma = self.sigma(i, phi)
            sol, extra = solve_group(self, xp, g, sigma, states, pos, vel, acc)
            solutions.append(sol)
            if not xp.scalar:
                valid &= sol.valid
            for a in (g.a, g.b):
                self._fill(a, states, pos, vel, acc, owner)
            for name, (link, base, v, a) in extra.items():  # the kernel's own values
                pos[name], vel[name], acc[name] = pos[base], v, a
                owner[name] = link
                coincident[name] = base
        return frozen(Motion, phi=phi, links=states, position=pos, velocity=vel,
                      acceleration=acc, point_link=owner, groups=tuple(solutions), valid=valid,
                      coincident=coincident)

    def _frame(self, zc, zero):
        """The frame's state and its points: fixed, at rest."""
        pos = {name: zc + xy for name, xy in self.mech.frame.items()}
        rest = dict.fromkeys(pos, zc)
        return (LinkState(zc, zc + 1, zc, zero, zc, zero), pos, rest, rest,
                dict.fromkeys(pos, 0))

    def _solve_upto(self, count: int) -> Motion:
        """Solve only the first ``count`` groups at the given crank angle (branch choice)."""
        part = Solver(self.mech, replace(self.structure, groups=self.structure.groups[:count]),
                      self.sigmas[:count], ((),) * count)  # at branch_at: no flip counts
        return part.solve(np.array([self.mech.driver.phi]))

    def _fill(self, lid, states, pos, vel, acc, owner):
        """The points of link ``lid`` that no link solved before it has placed (a group's
        new hinge is placed again here, from the first of its two links).

        Which points those are follows from the order of the groups alone, so it is
        worked out at the first solve and kept."""
        todo = self._todo.get(lid)
        if todo is None:
            todo = self._todo[lid] = tuple(
                (name, local) for name, local in self.mech.links[lid].points.items()
                if name not in owner)
        if not todo:
            return
        origin, rotor, v, w, a, e = states[lid]
        jw, kk = 1j * w, 1j * e - w * w
        for name, local in todo:
            r = rotor * local
            pos[name] = origin + r
            vel[name] = v + jw * r
            acc[name] = a + kk * r
            owner[name] = lid

    # helpers used by the group solvers ------------------------------------------------
    def local(self, lid: int, point: str) -> complex:
        return self.mech.links[lid].points[point]
