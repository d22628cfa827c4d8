"""The bench's measurement: run time per crank position and error against a high-precision
reference, for ``plans bench`` (:mod:`plans.cli.bench`, the command and its table).

For each bench scene (the two samples, one scene of each dyad kind, and the crank-rocker
with its joints only, the work of the peers' four-bar kernels; the built-in scenes of
``plans/model/scenes.py``) and each number N of crank positions (12 … 10⁶), it measures

* ``vectorized`` — ``Solver.sweep`` over the N angles (positions, velocities and
  accelerations of every point, ω and ε of every link, the conditioning of every group:
  the group kernels in blocks, results only), into new arrays each time;
* ``reused`` — the same sweep writing into the arrays of the previous one (``into=``):
  what a loop that sweeps again and again pays, without the system zeroing fresh pages;
* ``recorded`` — ``Solver.solve`` over the N angles at once, keeping every recorded
  construction (routes, terms, line directions) as arrays as well;
* ``plan`` — ``solve_position`` angle by angle (the single-position plan builder with
  its recorded constructions, scale factors and segments), for N up to ``--plan-max``;
  its error is read from the plan points themselves (the similarity steps included);
* ``fd h=…`` — a finite-difference baseline from positions only: V ≈ ω1·(X(φ+h) −
  X(φ−h))/2h, a ≈ ω1²·(X(φ+h) − 2X(φ) + X(φ−h))/h², ω and ε from the links' turns. Its
  positions come from the same solver, which also computes the plans it throws away,
  so its time is an upper bound of what a positions-only solver would take;
* peer packages when installed (``pip install pylinkage``; pyslvs is looked for too):
  pylinkage on the scenes it can model (a crank with one RRR group on a fixed pivot or
  one RRP group on a fixed guide), its crank stepped by a constant angle as the package
  works; the other scenes and absent packages are skipped with a note.

The error of each is the largest normwise relative error against ``plans.verify.reference``
(mpmath, 30 digits, from the loop-closure equations): per angle, max over the points of
|X − X_ref| / max over the points of |X_ref|, for positions, velocities and
accelerations, and the same over the links for ω and ε (ε scaled by at least ω1²);
then the largest over the quantities and the angles. The reference is evaluated on at
most ``--ref-angles`` of the N angles (evenly spaced; the same angles for every N that
is a multiple of it, so it is computed once per scene).

Each measurement is a :class:`Row`; :class:`Bench` makes them, scene by scene.
"""

from __future__ import annotations

import importlib
import math
import os
import platform
import time
from dataclasses import dataclass, replace

import numpy as np

from plans.kinematics.solver import Solver
from plans.model.scenes import SCENES
from plans.plan.solution import plan_name, solve_position
from plans.verify import reference
from plans.verify.peers import pylinkage_model

SIZES = (12, 100, 1_000, 10_000, 100_000, 1_000_000)
QUICK_SIZES = (12, 100)
FD_STEPS = (1e-2, 1e-4, 1e-6)
QUICK_FD_STEPS = (1e-4,)
#: scene → what it stands for in the table
BENCH_SCENES = {
    "press": "sample: RPR + RRP",
    "fourbar": "sample: RRR, not a full turn",
    "fourbar_joints": "RRR, joints only, as the peers' four-bar kernels",
    "crank_rocker": "RRR with three more points",
    "crank_slider_offset": "RRP",
    "slotted_oscillating": "RPR",
    "tangent": "PRP",
    "scotch_yoke": "RPP",
}
#: "forces": the loaded sweep of the force analysis, benched by the command (plans.forces.bench);
#: "synthesis": γmin over a crank-rocker family in one call (plans.synthesis.bench)
METHODS = ("vectorized", "reused", "recorded", "plan", "fd", "peers", "forces", "synthesis")
PEER_HINTS = {
    "pylinkage": "pip install pylinkage",
    "pyslvs": "it ships no wheel for recent Pythons and its source build fails on 3.11",
}
PEER_MAX = 10_000


@dataclass(frozen=True)
class Row:
    """One measurement: a method on a scene over N crank positions, its best wall time
    per position and its largest relative error (None without a reference)."""

    scene: str
    method: str
    positions: int
    seconds_per_position: float
    max_rel_error: float | None

    def as_json(self) -> dict:
        err = self.max_rel_error
        return {
            "scene": self.scene,
            "method": self.method,
            "positions": self.positions,
            "seconds_per_position": self.seconds_per_position,
            "max_rel_error": err if err is not None and math.isfinite(err) else None,
        }


# ---------------------------------------------------------------------------------------
# scenes and angles
# ---------------------------------------------------------------------------------------


def load_scenes() -> dict:
    """The built-in scenes (plans/model/scenes.py) that this installation has: the two samples
    only in a source checkout."""
    return {name: sc for name, sc in SCENES.items() if sc.available}


def grid(scene, n: int):
    """N crank angles (rad): a full turn from the scene's start, or the middle 94 % of its
    crank range. φ_k = lo + span·(k/N): the same k/N gives the bit-identical angle for
    every N, which lets one reference serve all sizes."""
    if scene.full_turn:
        lo, span = math.radians(scene.lo_deg), 2 * math.pi
    else:
        width = scene.hi_deg - scene.lo_deg
        lo, span = math.radians(scene.lo_deg + 0.03 * width), math.radians(0.94 * width)
    return lo + span * (np.arange(n) / n)


def subset(n: int, m: int):
    """Indices of at most ``m`` evenly spaced angles out of ``n``."""
    if n <= m:
        return np.arange(n)
    if n % m == 0:
        return np.arange(m) * (n // m)
    return np.unique(np.linspace(0, n - 1, m).round().astype(int))


def take(motion, idx):
    """The motion at the angles ``idx`` only (groups dropped)."""
    links = {
        i: st._replace(**{f: getattr(st, f)[idx] for f in st._fields})
        for i, st in motion.links.items()
    }
    return replace(
        motion,
        phi=motion.phi[idx],
        links=links,
        position={k: v[idx] for k, v in motion.position.items()},
        velocity={k: v[idx] for k, v in motion.velocity.items()},
        acceleration={k: v[idx] for k, v in motion.acceleration.items()},
        groups=(),
        valid=motion.valid[idx],
    )


# ---------------------------------------------------------------------------------------
# error measure
# ---------------------------------------------------------------------------------------


def rel_error(
    arr, valid, position, velocity, acceleration, omega=None, epsilon=None
) -> float:
    """Largest normwise relative error against the reference arrays ``arr`` (the norm of
    ``plans.verify.reference.errors``) over the points and links given; inf if a method gives
    a non-finite value where the reference assembles."""
    ok = np.asarray(valid, dtype=bool) & arr.valid
    if not ok.any():
        return math.nan
    worst = 0.0
    quantities = [
        (position, arr.position, 0.0),
        (velocity, arr.velocity, 0.0),
        (acceleration, arr.acceleration, 0.0),
    ]
    if omega:
        quantities.append((omega, arr.omega, 0.0))
    if epsilon:
        quantities.append((epsilon, arr.epsilon, arr.omega1**2))
    for eng, ref, floor in quantities:
        keys = list(eng)
        diff = np.max([np.abs(np.asarray(eng[k]) - ref[k]) for k in keys], axis=0)
        scale = np.maximum(np.max([np.abs(ref[k]) for k in keys], axis=0), floor)
        with np.errstate(all="ignore"):
            r = diff[ok] / np.where(scale[ok] > 0, scale[ok], 1.0)
        if not np.isfinite(r).all():
            return math.inf
        worst = max(worst, float(r.max()))
    return worst


def sweep_error(sw, idx, arr) -> float:
    """The error of a sweep at the reference's angles ``idx``."""
    pick = lambda d: {k: v[idx] for k, v in d.items()}  # noqa: E731
    return rel_error(arr, sw.valid[idx], pick(sw.position), pick(sw.velocity),
                     pick(sw.acceleration),
                     pick({i: w for i, w in sw.omega.items() if i != 0}),
                     pick({i: e for i, e in sw.epsilon.items() if i != 0}))


def motion_error(motion, arr) -> float:
    moving = [i for i in motion.links if i != 0]
    return rel_error(
        arr,
        motion.valid,
        motion.position,
        motion.velocity,
        motion.acceleration,
        {i: motion.links[i].omega for i in moving},
        {i: motion.links[i].epsilon for i in moving},
    )


# ---------------------------------------------------------------------------------------
# the measurements
# ---------------------------------------------------------------------------------------


def best_time(
    fn, budget: float, first: float | None = None, at_least: int = 0
) -> float:
    """Best wall time of ``fn()`` over repeats filling about ``budget`` seconds (and
    ``at_least`` repeats after the first run, on a machine shared with other work).

    The first run may pay what is paid once (a plan's recipe compiled, the cycle solved
    for μl): the repeats are counted from a second run where the first took less than
    the budget, so that a slow first run does not leave a handful of repeats to a noisy
    machine (the press's plan got 6, and its best ranged 84–138 µs from run to run).
    """
    if first is None:
        t0 = time.perf_counter()
        fn()
        first = time.perf_counter() - t0
    best = each = first
    if first < budget:
        t0 = time.perf_counter()
        fn()
        each = time.perf_counter() - t0
        best = min(best, each)
    repeats = max(at_least, min(200, int(budget / max(each, 1e-9))))
    for _ in range(repeats):
        t0 = time.perf_counter()
        fn()
        best = min(best, time.perf_counter() - t0)
    return best


class Bench:
    def __init__(self, *, budget, ref_angles, plan_max, fd_steps, methods, notes, log):
        self.budget = budget
        self.ref_angles = ref_angles
        self.plan_max = plan_max
        self.fd_steps = fd_steps
        self.methods = methods
        self.notes = notes
        self.log = log
        self._refs: dict = {}
        self._peer_state: dict[str, object] = {}

    # reference ------------------------------------------------------------------------
    def reference(self, name, mech, phi):
        key = (name, phi.tobytes())
        if key not in self._refs:
            try:
                self._refs[key] = reference.reference(mech, phi).arrays()
            except reference.ReferenceError as exc:
                self.notes.append(f"{name}: no reference at {len(phi)} angles: {exc}")
                self._refs[key] = None
        return self._refs[key]

    # one scene --------------------------------------------------------------------------
    def scene(self, name, scene, sizes) -> list[Row]:
        mech = scene.mechanism()
        solver = Solver(mech)
        rows: list[Row] = []
        for n in sizes:
            phi = grid(scene, n)
            idx = subset(n, self.ref_angles)
            arr = self.reference(name, mech, phi[idx])
            self.log(f"bench {name}: N = {n}")
            if "vectorized" in self.methods:
                rows += self._vectorized(name, solver, phi, idx, arr)
            if "plan" in self.methods and n <= self.plan_max:
                rows.append(self._plan(name, mech, solver, phi, idx, arr))
            if "fd" in self.methods:
                for h in self.fd_steps:
                    rows.append(self._fd(name, mech, solver, phi, idx, arr, h))
            if "peers" in self.methods:
                rows += self._peers(name, mech, solver, phi, idx, arr)
            del phi
        return rows

    def _vectorized(self, name, solver, phi, idx, arr) -> list[Row]:
        """The sweep into fresh arrays, into reused ones, and the recorded solve."""
        rows = []
        at_least = 0 if self.budget < 0.1 else 2
        with np.errstate(all="ignore"):
            t0 = time.perf_counter()
            sw = solver.sweep(phi)
            first = time.perf_counter() - t0
            err = sweep_error(sw, idx, arr) if arr is not None else None
            best = best_time(lambda: solver.sweep(phi), self.budget, first, at_least)
            rows.append(Row(name, "vectorized", len(phi), best / len(phi), err))
            if "reused" in self.methods:
                best = best_time(lambda: solver.sweep(phi, into=sw), self.budget,
                                  at_least=at_least)
                err = sweep_error(sw, idx, arr) if arr is not None else None
                rows.append(Row(name, "reused", len(phi), best / len(phi), err))
            sw = None  # frees the arrays before the recorded solve
            if "recorded" in self.methods:
                t0 = time.perf_counter()
                motion = solver.solve(phi)
                first = time.perf_counter() - t0
                sub = take(motion, idx)
                del motion
                best = best_time(lambda: solver.solve(phi), self.budget, first, at_least)
                err = motion_error(sub, arr) if arr is not None else None
                rows.append(Row(name, "recorded", len(phi), best / len(phi), err))
        return rows

    def _plan(self, name, mech, solver, phi, idx, arr) -> Row:
        def timed():
            for x in phi:
                solve_position(mech, float(x), solver=solver)

        best = best_time(timed, self.budget)
        err = None
        if arr is not None:
            sols = [solve_position(mech, float(x), solver=solver) for x in phi[idx]]
            names = list(sols[0].motion.position)

            def plan_value(plan, nm, store):
                pt = plan.points.get(plan_name(nm))
                return pt.value if pt is not None else complex(store[nm][0])

            pos = {nm: np.array([s.positions[nm] for s in sols]) for nm in names}
            vel = {
                nm: np.array(
                    [plan_value(s.velocity, nm, s.motion.velocity) for s in sols]
                )
                for nm in names
            }
            acc = {
                nm: np.array(
                    [
                        plan_value(s.acceleration, nm, s.motion.acceleration)
                        for s in sols
                    ]
                )
                for nm in names
            }
            links = [i for i in sols[0].omega if i != 0]
            om = {i: np.array([s.omega[i] for s in sols]) for i in links}
            ep = {i: np.array([s.epsilon[i] for s in sols]) for i in links}
            err = rel_error(arr, np.ones(len(sols), bool), pos, vel, acc, om, ep)
        return Row(name, "plan", len(phi), best / len(phi), err)

    def _fd(self, name, mech, solver, phi, idx, arr, h) -> Row:
        names = mech.point_names()
        links = sorted(mech.links)
        w1 = mech.driver.omega

        def compute():
            with np.errstate(all="ignore"):
                out = []
                for shift in (-h, 0.0, h):
                    m = solver.solve(phi + shift)
                    out.append(
                        (
                            {k: m.position[k] for k in names},
                            {i: m.links[i].rotor for i in links},
                            m.valid,
                        )
                    )
                    del m
            (xm, rm, vm), (x0, r0, v0), (xp, rp, vp) = out
            vel = {k: (xp[k] - xm[k]) * (w1 / (2 * h)) for k in names}
            acc = {k: (xp[k] - 2 * x0[k] + xm[k]) * (w1 * w1 / (h * h)) for k in names}
            om, ep = {}, {}
            for i in links:
                dp = np.angle(rp[i] * np.conj(r0[i]))
                dm = np.angle(r0[i] * np.conj(rm[i]))
                om[i] = (dp + dm) * (w1 / (2 * h))
                ep[i] = (dp - dm) * (w1 * w1 / (h * h))
            return x0, vel, acc, om, ep, vm & v0 & vp

        t0 = time.perf_counter()
        result = compute()
        first = time.perf_counter() - t0
        x0, vel, acc, om, ep, valid = result
        err = None
        if arr is not None:
            pick = lambda d: {k: v[idx] for k, v in d.items()}  # noqa: E731
            err = rel_error(
                arr, valid[idx], pick(x0), pick(vel), pick(acc), pick(om), pick(ep)
            )
        del result, x0, vel, acc, om, ep
        best = best_time(compute, self.budget, first)
        return Row(name, f"fd h={h:.0e}", len(phi), best / len(phi), err)

    # peers --------------------------------------------------------------------------
    def _peer_available(self, peer: str) -> bool:
        if peer not in self._peer_state:
            try:
                self._peer_state[peer] = importlib.import_module(peer)
            except Exception as exc:  # ImportError, or a broken build of the package
                self._peer_state[peer] = None
                self.notes.append(
                    f"peer {peer} is not installed ({type(exc).__name__}): "
                    f"skipped ({PEER_HINTS.get(peer, 'pip install ' + peer)})"
                )
        return self._peer_state[peer] is not None

    def _peers(self, name, mech, solver, phi, idx, arr) -> list[Row]:
        rows = []
        if self._peer_available("pylinkage"):
            n = len(phi)
            if n > PEER_MAX:
                return rows
            try:
                build = pylinkage_model(
                    self._peer_state["pylinkage"], mech, solver, phi
                )
            except NotImplementedError as exc:
                note = f"pylinkage: {name} skipped ({exc})"
                if note not in self.notes:
                    self.notes.append(note)
                return rows
            t0 = time.perf_counter()
            pos, vel, acc = build()
            first = time.perf_counter() - t0
            best = (
                best_time(build, min(self.budget, first), first)
                if n <= 1000
                else first
            )
            err = None
            if arr is not None:
                pick = lambda d: {k: v[idx] for k, v in d.items()}  # noqa: E731

                err = rel_error(
                    arr, np.ones(len(idx), bool), pick(pos), pick(vel), pick(acc)
                )
            rows.append(Row(name, "pylinkage", n, best / n, err))
        self._peer_available("pyslvs")
        return rows


def machine() -> str:
    """The machine measured on, in one line: system, cores, load, Python and numpy."""
    cores = (
        len(os.sched_getaffinity(0))
        if hasattr(os, "sched_getaffinity")
        else os.cpu_count()
    )
    load = ""
    if hasattr(os, "getloadavg"):
        load = f", load {os.getloadavg()[0]:.1f}"
    return (
        f"{platform.system()} {platform.machine()}, {cores} cores{load}, "
        f"Python {platform.python_version()}, numpy {np.__version__}"
    )

