"""``plans bench``: run time per crank position and error against a high-precision reference.

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

The table goes to stdout (``--json``: a list of rows ``{"scene", "method", "positions",
"seconds_per_position", "max_rel_error"}``), the error-versus-time chart (log-log SVG,
``drawing/chart.py``) to ``--chart`` (default ``bench.svg``).
The bench needs sympy (the ``bench`` extra); the two samples are benched in a source
checkout, where ``samples/`` is.
"""

from __future__ import annotations

import math
import sys
import time
from dataclasses import dataclass

from plans.cli.common import number

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
METHODS = ("vectorized", "reused", "recorded", "plan", "fd", "peers")
PEER_HINTS = {
    "pylinkage": "pip install pylinkage",
    "pyslvs": "it ships no wheel for recent Pythons and its source build fails on 3.11",
}
PEER_MAX = 10_000
#: the issue's rates (positions per second at N ≥ 10⁵): (label, scenes, goal). The
#: four-bar's goal is read on its joints, the work the peers' four-bar kernels do; the
#: four-bars with coupler points and mass centres are held to it too, and reported apart
TARGETS = (
    ("four-bar, joints only", ("fourbar_joints",), 5e6),
    ("four-bar with 3–4 more points", ("crank_rocker", "fourbar"), 5e6),
    ("press", ("press",), 2e6),
)


@dataclass(frozen=True)
class Row:
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


def configure(p) -> None:
    p.add_argument("--json", action="store_true", help="print the rows as JSON")
    p.add_argument(
        "--quick",
        action="store_true",
        help="sizes 12 and 100, one FD step, short timing: seconds, for tests",
    )
    p.add_argument(
        "--max-positions",
        type=number(1, 10_000_000, integer=True),
        default=SIZES[-1],
        metavar="N",
        help=f"largest N of crank positions (default {SIZES[-1]})",
    )
    p.add_argument(
        "--scene",
        action="append",
        metavar="NAME",
        help=f"only these scenes (repeatable; default: {', '.join(BENCH_SCENES)})",
    )
    p.add_argument(
        "--methods",
        metavar="LIST",
        default=",".join(METHODS),
        help=f"comma-separated subset of {','.join(METHODS)} (reused and recorded "
        "are timed only with vectorized)",
    )
    p.add_argument(
        "--ref-angles",
        type=number(1, 100_000, integer=True),
        default=100,
        metavar="M",
        help="angles on which the reference is evaluated (default 100)",
    )
    p.add_argument(
        "--plan-max",
        type=number(1, 10_000_000, integer=True),
        default=1_000,
        metavar="N",
        help="largest N timed for the single-position plan (default 1000)",
    )
    p.add_argument(
        "--budget",
        type=number(0, 600),
        default=0.3,
        metavar="S",
        help="seconds spent repeating a short measurement, best run kept (default 0.3)",
    )
    p.add_argument(
        "--chart",
        metavar="FILE",
        default="bench.svg",
        help="error-versus-time chart (SVG; default bench.svg; '' for none)",
    )
    p.add_argument(
        "-o",
        "--output",
        metavar="FILE",
        help="write the table to FILE instead of stdout",
    )


def run(args) -> int:
    import json

    from plans.errors import InputError

    methods = {m.strip() for m in args.methods.split(",") if m.strip()}
    unknown = methods - set(METHODS)
    if unknown or not methods:
        raise InputError(
            "command line", f"--methods: unknown {', '.join(sorted(unknown))}" if unknown
            else f"--methods: give at least one of {','.join(METHODS)}"
        )
    args.run_files.check(args)  # a bad --chart is found now, not after minutes of timing
    scenes = load_scenes()
    names = args.scene or [n for n in BENCH_SCENES if n in scenes]
    skipped = [n for n in BENCH_SCENES if n not in scenes]
    missing = [n for n in names if n not in scenes]
    if missing:
        raise InputError(
            "command line",
            f"--scene: unknown {', '.join(missing)} "
            f"(known: {', '.join(sorted(scenes))})",
        )
    sizes = [
        n for n in (QUICK_SIZES if args.quick else SIZES) if n <= args.max_positions
    ]
    if not sizes:
        sizes = [args.max_positions]
    notes: list[str] = []
    log = (
        (lambda msg: print(msg, file=sys.stderr))
        if not args.json
        else (lambda msg: None)
    )
    bench = Bench(
        budget=0.02 if args.quick else args.budget,
        ref_angles=min(args.ref_angles, 12) if args.quick else args.ref_angles,
        plan_max=min(args.plan_max, 100) if args.quick else args.plan_max,
        fd_steps=QUICK_FD_STEPS if args.quick else FD_STEPS,
        methods=methods,
        notes=notes,
        log=log,
    )
    if skipped and not args.scene:
        notes.append(f"{', '.join(skipped)}: the samples are benched in a source checkout")
    rows: list[Row] = []
    for name in names:
        rows += bench.scene(name, scenes[name], sizes)
    if args.json:
        text = json.dumps([r.as_json() for r in rows], indent=1) + "\n"
        for n in notes:
            print(f"plans bench: note: {n}", file=sys.stderr)
    else:
        text = to_text(rows, notes)
    chart = None
    if args.chart:  # built before the table is written: both or neither
        from drawing.chart import svg_chart  # drawing alone writes SVG

        chart = svg_chart(rows, machine())
    args.run_files.write(args.output, text)
    if chart is not None:
        args.run_files.write(args.chart, chart)
        if not args.json:
            print(f"plans bench: chart written to {args.chart}", file=sys.stderr)
    return 0


# ---------------------------------------------------------------------------------------
# scenes and angles
# ---------------------------------------------------------------------------------------


def load_scenes() -> dict:
    """The built-in scenes (plans/model/scenes.py) that this installation has: the two samples
    only in a source checkout."""
    from plans.model.scenes import SCENES

    return {name: sc for name, sc in SCENES.items() if sc.available}


def grid(scene, n: int):
    """N crank angles (rad): a full turn from the scene's start, or the middle 94 % of its
    crank range. φ_k = lo + span·(k/N): the same k/N gives the bit-identical angle for
    every N, which lets one reference serve all sizes."""
    import numpy as np

    if scene.full_turn:
        lo, span = math.radians(scene.lo_deg), 2 * math.pi
    else:
        width = scene.hi_deg - scene.lo_deg
        lo, span = math.radians(scene.lo_deg + 0.03 * width), math.radians(0.94 * width)
    return lo + span * (np.arange(n) / n)


def subset(n: int, m: int):
    """Indices of at most ``m`` evenly spaced angles out of ``n``."""
    import numpy as np

    if n <= m:
        return np.arange(n)
    if n % m == 0:
        return np.arange(m) * (n // m)
    return np.unique(np.linspace(0, n - 1, m).round().astype(int))


def take(motion, idx):
    """The motion at the angles ``idx`` only (groups dropped)."""
    from dataclasses import replace

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
    import numpy as np

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


def _best_time(
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
            from plans.verify import reference

            try:
                self._refs[key] = reference.reference(mech, phi).arrays()
            except reference.ReferenceError as exc:
                self.notes.append(f"{name}: no reference at {len(phi)} angles: {exc}")
                self._refs[key] = None
        return self._refs[key]

    # one scene --------------------------------------------------------------------------
    def scene(self, name, scene, sizes) -> list[Row]:
        from plans.kinematics.solver import Solver

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
        import numpy as np

        rows = []
        at_least = 0 if self.budget < 0.1 else 2
        with np.errstate(all="ignore"):
            t0 = time.perf_counter()
            sw = solver.sweep(phi)
            first = time.perf_counter() - t0
            err = sweep_error(sw, idx, arr) if arr is not None else None
            best = _best_time(lambda: solver.sweep(phi), self.budget, first, at_least)
            rows.append(Row(name, "vectorized", len(phi), best / len(phi), err))
            if "reused" in self.methods:
                best = _best_time(lambda: solver.sweep(phi, into=sw), self.budget,
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
                best = _best_time(lambda: solver.solve(phi), self.budget, first, at_least)
                err = motion_error(sub, arr) if arr is not None else None
                rows.append(Row(name, "recorded", len(phi), best / len(phi), err))
        return rows

    def _plan(self, name, mech, solver, phi, idx, arr) -> Row:
        import numpy as np

        from plans.plan.solution import plan_name, solve_position

        def timed():
            for x in phi:
                solve_position(mech, float(x), solver=solver)

        best = _best_time(timed, self.budget)
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
        import numpy as np

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
        best = _best_time(compute, self.budget, first)
        return Row(name, f"fd h={h:.0e}", len(phi), best / len(phi), err)

    # peers --------------------------------------------------------------------------
    def _peer_available(self, peer: str) -> bool:
        if peer not in self._peer_state:
            import importlib

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
                build = _pylinkage_model(
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
                _best_time(build, min(self.budget, first), first)
                if n <= 1000
                else first
            )
            err = None
            if arr is not None:
                pick = lambda d: {k: v[idx] for k, v in d.items()}  # noqa: E731
                import numpy as np

                err = rel_error(
                    arr, np.ones(len(idx), bool), pick(pos), pick(vel), pick(acc)
                )
            rows.append(Row(name, "pylinkage", n, best / n, err))
        self._peer_available("pyslvs")
        return rows


def _pylinkage_model(pl, mech, solver, phi):
    """A pylinkage linkage for a crank + one RRR group on a fixed pivot, or a crank + one
    RRP group on a fixed guide; returns a function that runs it over ``phi`` (a uniform
    grid) and gives {point: positions}, velocities, accelerations as complex arrays."""
    import numpy as np

    from plans.model.structure import DyadKind

    groups = solver.structure.groups
    drv = mech.driver
    if len(groups) != 1:
        raise NotImplementedError("more than one group")
    g = groups[0]
    if g.P != drv.tip:
        raise NotImplementedError("the group is not hinged to the crank")
    if g.kind == DyadKind.RRR:
        if g.Q not in mech.frame:
            raise NotImplementedError("the rocker is not hinged to the frame")
    elif g.kind == DyadKind.RRP:
        if g.s1.guide.link != 0:
            raise NotImplementedError("a moving guide")
    else:
        raise NotImplementedError(f"no {g.kind.name} group in pylinkage")
    with np.errstate(all="ignore"):
        start = solver.solve(phi[:1])
    C0 = complex(start.position[g.C][0])
    l2 = abs(mech.links[g.a].points[g.C] - mech.links[g.a].points[g.P])
    n = len(phi)
    step = float(phi[1] - phi[0]) if n > 1 else 0.0

    def build():
        pivot = mech.frame[drv.pivot]
        ground = pl.Ground(pivot.real, pivot.imag, name=drv.pivot)
        crank = pl.Crank(
            anchor=ground,
            radius=drv.length,
            angular_velocity=step,
            initial_angle=float(phi[0]) - step,
            name=drv.tip,
        )
        comps = [ground]
        if g.kind == DyadKind.RRR:
            Q = mech.frame[g.Q]
            gq = pl.Ground(Q.real, Q.imag, name=g.Q)
            l3 = abs(mech.links[g.b].points[g.C] - mech.links[g.b].points[g.Q])
            comps.append(gq)
            dyad = pl.RRRDyad(
                anchor1=crank.output,
                anchor2=gq,
                distance1=l2,
                distance2=l3,
                x=C0.real,
                y=C0.imag,
                name=g.C,
            )
        else:
            gd = g.s1.guide
            a, b = gd.point, gd.point + gd.direction
            la = pl.Ground(a.real, a.imag, name="L1")
            lb = pl.Ground(b.real, b.imag, name="L2")
            comps += [la, lb]
            dyad = pl.RRPDyad(
                revolute_anchor=crank.output,
                line_anchor1=la,
                line_anchor2=lb,
                distance=l2,
                x=C0.real,
                y=C0.imag,
                name=g.C,
            )
        comps += [crank, dyad]
        linkage = pl.Linkage(comps, name=mech.name)
        linkage.set_input_velocity(crank, omega=drv.omega)
        which = ((drv.tip, comps.index(crank)), (g.C, comps.index(dyad)))
        P = {k: np.empty(n, complex) for k, _ in which}
        V = {k: np.empty(n, complex) for k, _ in which}
        A = {k: np.empty(n, complex) for k, _ in which}
        for k, (pos, vel, acc) in enumerate(
            linkage.step_with_derivatives(iterations=n)
        ):
            for nm, i in which:
                P[nm][k] = complex(*pos[i])
                V[nm][k] = complex(*vel[i]) if vel[i] is not None else complex("nan")
                A[nm][k] = complex(*acc[i]) if acc[i] is not None else complex("nan")
        return P, V, A

    return build


# ---------------------------------------------------------------------------------------
# output
# ---------------------------------------------------------------------------------------


def machine() -> str:
    import os
    import platform

    import numpy as np

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


def _err(x: float | None) -> str:
    if x is None:
        return "—"
    if not math.isfinite(x):
        return "inf" if x == math.inf else "—"
    return f"{x:.2e}"


def _time(sec: float) -> str:
    if sec >= 1e-3:
        return f"{sec * 1e3:.3g} ms"
    if sec >= 1e-6:
        return f"{sec * 1e6:.3g} µs"
    return f"{sec * 1e9:.3g} ns"


def to_text(rows: list[Row], notes: list[str]) -> str:
    out = [f"plans bench — {machine()}; one process, numpy on one core", ""]
    head = ("scene", "method", "N", "time/position", "positions/s", "max rel error")
    body = [
        (
            r.scene,
            r.method,
            str(r.positions),
            _time(r.seconds_per_position),
            f"{1 / r.seconds_per_position:.3g}" if r.seconds_per_position > 0 else "—",
            _err(r.max_rel_error),
        )
        for r in rows
    ]
    widths = [
        max(len(h), *(len(b[i]) for b in body)) if body else len(h)
        for i, h in enumerate(head)
    ]
    fmt = lambda cells: "  ".join(  # noqa: E731
        c.ljust(w) if i < 2 else c.rjust(w)
        for i, (c, w) in enumerate(zip(cells, widths, strict=True))
    )
    out.append(fmt(head))
    last = None
    for r, b in zip(rows, body, strict=True):
        if last is not None and r.scene != last:
            out.append("")
        last = r.scene
        out.append(fmt(b))
    out += ["", *targets(rows)]
    if notes:
        out.append("")
        out += [f"note: {n}" for n in notes]
    return "\n".join(out) + "\n"


def targets(rows: list[Row]) -> list[str]:
    """The issue's targets, checked against what was measured."""
    out = ["targets"]

    for label, scenes, goal in TARGETS:
        for method, how in (("vectorized", "new arrays"), ("reused", "reused arrays")):
            got = {}
            for r in rows:
                if r.method == method and r.scene in scenes and r.positions >= 100_000:
                    rate = 1 / r.seconds_per_position
                    got[r.positions] = max(got.get(r.positions, 0.0), rate)
            head = f"  {label} ≥ {goal:.0e} positions/s, N ≥ 1e5, {how}:"
            if not got:
                if method == "vectorized":
                    out.append(f"{head} not measured")
                continue
            figures = ", ".join(f"{v:.3g} at N = {n:.0e}" for n, v in sorted(got.items()))
            worst = min(got.values())
            verdict = ("met" if worst >= goal
                       else "met at some N only" if max(got.values()) >= goal else "NOT met")
            out.append(f"{head} {figures} — {verdict}")
    plan = [
        r.seconds_per_position
        for r in rows
        if r.method == "plan" and r.scene == "press"
    ]
    if plan:
        best = min(plan)
        out.append(
            f"  plan of the press ≤ 100 µs: {_time(best)} — {'met' if best <= 1e-4 else 'NOT met'}"
        )
    errs = [
        r.max_rel_error
        for r in rows
        if r.method == "vectorized" and r.max_rel_error is not None
    ]
    if errs:
        worst = max(errs)
        out.append(
            f"  vectorized max rel error ≤ 1e-13 (well-conditioned scenes): {_err(worst)} — "
            f"{'met' if worst <= 1e-13 else 'NOT met'}"
        )
    return out
