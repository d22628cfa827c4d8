"""Group-by-group solution of positions, velocity plans and acceleration plans.

:class:`Solver` solves a mechanism's groups in their order of attachment, each by its kernel
(``plans/kinematics/kernels.py``), and records every construction (``plans/kinematics/records.py``): over an
array of crank angles at once (:meth:`Solver.solve`), on Python numbers at one angle for
the single-position plan (:meth:`Solver.solve_one`), or without the record, block by
block, for bulk work (:meth:`Solver.sweep`). All three run the one group loop
(``plans/kinematics/assemble.py``) over the mechanism's setup, worked out once
(``plans/kinematics/setup.py``). For each group the velocity and the
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
from plans.kinematics import sweep
from plans.kinematics.assemble import assemble
from plans.kinematics.branches import change_points, choose_branches
from plans.kinematics.conditioning import pivot_figure, pivot_key
from plans.kinematics.groups import Recorded, ScalarFallback
from plans.kinematics.kernels import ARRAY, SCALAR
from plans.kinematics.records import (
    Construction,
    GroupSolution,
    LinkState,
    Motion,
    Route,
    Term,
    coincident_name,
)
from plans.kinematics.setup import Setup
from plans.kinematics.words import WARNINGS
from plans.model import Mechanism
from plans.model.fileformat import one_line
from plans.model.structure import Structure

__all__ = [
    "Construction", "GroupSolution", "LinkState", "Motion", "Route", "Solver", "Term",
    "coincident_name", "crank_angle",
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

    ``setup``: the mechanism's :class:`~plans.kinematics.setup.Setup`, shared with another
    solver of it (made here where it is not given).
    """

    def __init__(self, mech: Mechanism, structure: Structure | None = None,
                 sigmas: tuple[int, ...] | None = None,
                 flips: tuple[tuple[float, ...], ...] | None = None, *,
                 setup: Setup | None = None):
        if not isinstance(mech, Mechanism):  # a file's name was 'str' has no 'revolutes'
            hint = (f": read the file first, with load({str(mech)!r})"
                    if isinstance(mech, str | Path) else "")
            raise TypeError(f"a mechanism (plans.load, plans.from_dict) is needed, "
                            f"not {one_line(repr(mech), 60)}{hint}")
        self.mech = mech
        self.setup = setup if setup is not None else Setup.of(mech, structure)
        self.structure = self.setup.structure
        #: links that never turn: a guide on one carries no Coriolis term
        self.translating = self.setup.translating
        # the turn starts at ``branch_at``; ``sigmas`` hold at ``read_at``, which is
        # ``branch_at`` unless a group's two assemblies meet there (a parallelogram given
        # at 0°): then a little past it (plans.kinematics.branches._read)
        if sigmas is None:
            self.sigmas, self.branch_at, self.read_at = choose_branches(
                mech, self.structure, self._trial)
        else:  # given signs hold at the mechanism's own angle
            self.sigmas, self.branch_at = sigmas, mech.param
            self.read_at = self.branch_at
        #: per group, its change points as counter-clockwise turns from ``branch_at``
        #: (rad, in [0, 2π), ascending), and where its sign flips (at all of them, or at
        #: none); None until the first solve
        self._changes = self._flips = flips
        #: where the counting of flips wraps: a turn from ``branch_at`` (rad) where the
        #: mechanism does not close; None: at ``branch_at`` itself
        self._seam: float | None = None

    @property
    def changes(self) -> tuple[tuple[float, ...], ...]:
        if self._changes is None:
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
        crank = self.mech.driver.origin
        if isinstance(m, Motion):
            figures = [(g.velocity.sine, pivot_figure(g, m.position, crank)) for g in m.groups]
        else:  # a sweep: its figures by the group's label, the pivot's worked out here
            pivots = m.pivot
            figures = [(m.sine[g.label], pivots.get(pivot_key(g.label)))
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

    def at(self, phi: float, lang: str = "en", lo: float = 0.0) -> str:
        """The crank angle ``phi`` in words, as :meth:`plans.model.mechanism.Driver.at`
        gives it in the turn from ``lo`` (the file's degrees: 0 for [0°, 360°)), saying so
        where it is a change point (to :data:`plans.tolerances.AT_CHANGE_POINT`) or beside
        one (:data:`plans.kinematics.words.WARNINGS`). Where the crank cannot
        make a full turn and its range is written through 0° ("from −99.72° to 99.72°")
        the cycle knows ``lo`` (:func:`plans.cycle.shown_from`), and the angle is written as
        the range is: −99.7°, not 260.3°."""
        drv = self.mech.driver
        words = self.mech.at(phi, lang, lo)
        near = self.change_point_near(phi)
        if near is None:
            return words
        said = WARNINGS[lang]
        if apart(phi, near) < tolerances.AT_CHANGE_POINT:
            return words + said["on_change"]
        beside = said["beside_change"]
        return words + (beside.format(at=drv.at(near, lang, lo)) if beside else "")

    def with_flips(self, flips: tuple[tuple[float, ...], ...], seam: float | None = None) -> Solver:
        """This solver with the given flips (and seam) instead of its own."""
        out = Solver(self.mech, self.structure, self.sigmas, flips, setup=self.setup)
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
            m = self._motion(ARRAY, phi, zero, np.exp(1j * phi), self.signs(phi))
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
        later = self._motion(ARRAY, on, np.zeros_like(on), np.exp(1j * on), self.signs(on))

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
        return sweep.sweep(self, phi, **options)

    def solve_one(self, phi: float) -> Motion:
        """The same recorded solution at one crank angle, on Python numbers.

        Every value in the result is a Python ``complex`` or ``float`` instead of an array
        of one; it is about twenty times faster than :meth:`solve` on one angle. Where
        the mechanism does not close or a plan is singular it raises the error that
        :meth:`solve` would report for that angle, its crank angle worded by :meth:`at`
        in [0°, 360°) (:meth:`plans.errors.PositionError.at_words` words it otherwise).
        """
        phi = crank_angle(phi)
        try:
            return self._motion(SCALAR, phi, 0.0, complex(math.cos(phi), math.sin(phi)),
                                self.signs(phi))
        except (ScalarFallback, ArithmeticError, ValueError):
            pass
        m = self.solve(np.array([phi]))
        at = self.at(phi)
        source = self.mech.source
        for g in m.groups:
            if not g.valid[0]:
                raise g.failure(0, at, source=source, phi=phi)
        for i, g in enumerate(m.groups):
            below = self.singular_figures(i, phi)[0]
            if (err := g.parallel(0, at, source, below, phi)) is not None:
                raise err
        raise SingularPlanError(  # pragma: no cover - every fallback above is a failure
            f"at {at}: the plan has no unique solution", source=source, phi=phi, at=at)

    def signs(self, phi):
        """Each group's sign at the angles ``phi``, as a function of the group's index
        (:meth:`sigma`, the same at every angle where the group never flips): what the
        group loop (:func:`plans.kinematics.assemble.assemble`) asks."""
        flips = self.flips
        sigmas = self.sigmas
        if not any(flips):  # the signs chosen, at every angle (read by index, in C)
            return sigmas.__getitem__
        return lambda i: self.sigma(i, phi) if flips[i] else sigmas[i]

    def _motion(self, xp, phi, zero, rotor, sigma, count: int | None = None) -> Motion:
        """The recorded solution at ``phi`` by the group loop, each group at ``sigma(i)``;
        of the first ``count`` groups only where it is given."""
        return assemble(Recorded(self.setup, xp, phi, zero, rotor), self.setup, sigma,
                        count).motion()

    def _trial(self, phi: float, sigmas, count: int) -> Motion:
        """The first ``count`` groups at crank angle ``phi`` on the signs ``sigmas``, none
        flipping: the assemblies the hints choose between
        (:func:`plans.kinematics.branches.choose_branches`)."""
        with np.errstate(all="ignore"):
            at = np.array([phi], dtype=float)
            return self._motion(ARRAY, at, np.zeros_like(at), np.exp(1j * at),
                                lambda i: sigmas[i], count)
