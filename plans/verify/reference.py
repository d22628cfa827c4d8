"""An independent high-precision reference for the kinematics: differentiated loop closure.

The plan construction (``plans.kinematics``) finds each group's new point as the
intersection of two lines. This module reaches the same numbers by a route that shares
nothing with it except the mechanism description: natural link coordinates and the
loop-closure equations, solved in multiple precision (mpmath, 30 significant digits by
default).

Unknowns ``q``: for every moving link i its origin (x_i, y_i) and angle θ_i (the world
pose of the link's own coordinates; a point with own coordinates l is at
``(x_i, y_i) + R(θ_i)·l``; frame points are fixed in world coordinates).
Constraints ``F(q, φ) = 0`` (3 per moving link, W = 3n − 2p5 = 1):

* the driver: its origin at its pivot, θ_driver = φ;
* every revolute (a point named on two links): equal world positions on both links;
* every slider: the sliding point of the sliding link lies on the guide line
  (``(P − G) × u = 0``, G and u the guide's world point and direction), and the sliding
  link's angle equals the guide link's angle plus the guide's own direction angle (a link
  sliding on a guide has its own x axis along the guide, as ``Guide`` documents).

Positions: Newton in mpmath, started from the float engine's positions so that the
assembly branch is inherited (only the start: the result is wherever Newton converges).
Velocities: ``J·q' = −F_φ·ω1``. Accelerations (ω1 constant): differentiating
``J·q' + F_φ·ω1 = 0`` in time gives ``J·q'' = γ`` with
``γ = −[∂(J·q' + F_φ·ω1)/∂q]·q' − [∂(J·q' + F_φ·ω1)/∂φ]·ω1``.
``F``, ``J``, ``F_φ`` and ``γ`` are derived symbolically with sympy once per mechanism
topology (numbers are passed as parameters, so one compiled model serves every mechanism
with the same links, points and pairs) and lambdified to mpmath. No finite differences.

**sympy is required** (a test dependency, ``pip install .[test]``); mpmath is a runtime
dependency. Both are imported lazily.

Coincident points (``"A3"``: the point of link 3 under the pin A) are computed from the
carrying link's motion at the base point's position; ask for them with ``extra`` (the
default derives ``<point><guide link>`` for every slider on a moving guide) or pass the
engine's motion, whose coincident names are then added.

Error measure of :func:`max_rel_error` — per angle, max-norm over the points:
``max_X |engine_X − ref_X| / max_X |ref_X|`` for positions, velocities and accelerations
(the largest magnitude among all points of that quantity at that angle, frame points
included), ``max_i |ω_i − ω_i ref| / max_i |ω_i ref|`` for ω over the moving links and the
same for ε with the scale ``max(max_i |ε_i ref|, ω1²)`` (a mechanism whose links all
translate or turn uniformly has ε ≡ 0); then the maximum over the angles.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from plans.kinematics.solver import Motion, Solver
from plans.model import Mechanism

DEFAULT_DPS = 30
MAX_NEWTON = 40
GUARD_DPS = 10  # extra digits carried inside the solution


class ReferenceError(ArithmeticError):
    """Newton did not converge (a singular position, or a start far from any assembly)."""


# ---------------------------------------------------------------------------------------
# the symbolic model, compiled once per topology
# ---------------------------------------------------------------------------------------


def _topology(mech: Mechanism) -> tuple:
    """Everything the symbolic model depends on, without the numbers."""
    return (
        mech.driver.link,
        mech.driver.pivot,
        tuple(mech.frame),
        tuple((lid, tuple(link.points)) for lid, link in sorted(mech.links.items())),
        tuple((s.link, s.guide.link, s.point) for s in mech.sliders),
    )


@dataclass(frozen=True)
class _Model:
    link_ids: tuple[int, ...]  # q = [x, y, θ] for each, in this order
    F: Any  # (q, φ, params) -> list
    J: Any  # (q, φ, params) -> list of rows
    Fphi: Any  # (q, φ, params) -> list
    gamma: Any  # (q, qd, φ, ω, params) -> list
    param_names: tuple[str, ...]

    def index(self, lid: int) -> int:
        return 3 * self.link_ids.index(lid)


_MODELS: dict[tuple, _Model] = {}


def _param_values(mech: Mechanism, names: tuple[str, ...], mp) -> list:
    """Numeric values of the model's parameters, exact conversions of the file's floats."""
    out = []
    for name in names:
        kind, *rest = name.split(":")
        if kind == "f":  # frame point
            z = mech.frame[rest[0]]
            out.append(mp.mpf(z.real) if rest[1] == "x" else mp.mpf(z.imag))
        elif kind == "l":  # link point in own coordinates
            z = mech.links[int(rest[0])].points[rest[1]]
            out.append(mp.mpf(z.real) if rest[2] == "x" else mp.mpf(z.imag))
        elif kind == "g":  # guide i: point x/y in the carrier's coordinates, angle
            g = mech.sliders[int(rest[0])].guide
            if rest[1] == "x":
                out.append(mp.mpf(g.point.real))
            elif rest[1] == "y":
                out.append(mp.mpf(g.point.imag))
            else:
                out.append(mp.atan2(mp.mpf(g.direction.imag), mp.mpf(g.direction.real)))
        else:  # pragma: no cover
            raise AssertionError(name)
    return out


def _build(mech: Mechanism) -> _Model:
    import sympy as sp

    link_ids = tuple(sorted(mech.links))
    q = []
    pose = {}
    for lid in link_ids:
        x, y, t = sp.symbols(f"x{lid} y{lid} t{lid}", real=True)
        q += [x, y, t]
        pose[lid] = (x, y, t)
    phi, omega = sp.symbols("phi omega", real=True)
    params: dict[str, sp.Symbol] = {}

    def par(name: str) -> sp.Symbol:
        if name not in params:
            params[name] = sp.Symbol(f"p{len(params)}", real=True)
        return params[name]

    def world(lid: int, name: str):
        if lid == 0:
            return par(f"f:{name}:x"), par(f"f:{name}:y")
        lx, ly = par(f"l:{lid}:{name}:x"), par(f"l:{lid}:{name}:y")
        x, y, t = pose[lid]
        return x + sp.cos(t) * lx - sp.sin(t) * ly, y + sp.sin(t) * lx + sp.cos(t) * ly

    def angle(lid: int):
        return 0 if lid == 0 else pose[lid][2]

    drv = mech.driver
    eqs = []
    x, y, t = pose[drv.link]
    px, py = world(0, drv.pivot)
    eqs += [x - px, y - py, t - phi]
    for name, a, b in mech.revolutes():
        if {a, b} == {0, drv.link} and name == drv.pivot:
            continue  # the driver's pivot, already imposed
        (xa, ya), (xb, yb) = world(a, name), world(b, name)
        eqs += [xa - xb, ya - yb]
    for i, s in enumerate(mech.sliders):
        G = s.guide.link
        Px, Py = world(s.link, s.point)
        gx, gy = par(f"g:{i}:x"), par(f"g:{i}:y")
        if G == 0:
            Gx, Gy = gx, gy
        else:
            xg, yg, tg = pose[G]
            Gx = xg + sp.cos(tg) * gx - sp.sin(tg) * gy
            Gy = yg + sp.sin(tg) * gx + sp.cos(tg) * gy
        alpha = par(f"g:{i}:a")
        ux, uy = sp.cos(angle(G) + alpha), sp.sin(angle(G) + alpha)
        eqs += [ux * (Py - Gy) - uy * (Px - Gx), angle(s.link) - angle(G) - alpha]
    if len(eqs) != len(q):
        raise ReferenceError(
            f"{len(eqs)} loop-closure equations for {len(q)} link coordinates: "
            "the reference needs a mechanism with W = 1"
        )
    F = sp.Matrix(eqs)
    qv = sp.Matrix(q)
    J = F.jacobian(qv)
    Fphi = F.diff(phi)
    qd = sp.Matrix(sp.symbols(f"qd0:{len(q)}", real=True))
    Fv = J * qd + Fphi * omega
    gamma = -(Fv.jacobian(qv) * qd + Fv.diff(phi) * omega)
    pnames = tuple(params)
    psyms = [params[n] for n in pnames]

    def lam(args, expr):
        return sp.lambdify(args, expr, modules="mpmath", cse=True)

    base = [q, phi, psyms]
    return _Model(
        link_ids=link_ids,
        F=lam(base, list(F)),
        J=lam(base, J.tolist()),
        Fphi=lam(base, list(Fphi)),
        gamma=lam([q, list(qd), phi, omega, psyms], list(gamma)),
        param_names=pnames,
    )


def model(mech: Mechanism) -> _Model:
    """The compiled model of ``mech`` (cached by topology)."""
    key = _topology(mech)
    m = _MODELS.get(key)
    if m is None:
        m = _MODELS[key] = _build(mech)
    return m


# ---------------------------------------------------------------------------------------
# results
# ---------------------------------------------------------------------------------------


@dataclass(frozen=True)
class ReferenceMotion:
    """High-precision motion over the angles ``phi``.

    ``points[name] = (positions, velocities, accelerations)``, each a list over the angles
    of ``mpmath.mpc`` (x + iy; m, m/s, m/s²); ``links[id] = (omegas, epsilons)`` lists of
    ``mpmath.mpf`` (counter-clockwise positive), the frame 0 included. Angles the start
    motion reports as not assembling hold NaN and ``valid`` is False there.
    """

    phi: np.ndarray
    points: dict[str, tuple[list, list, list]]
    links: dict[int, tuple[list, list]]
    valid: np.ndarray
    dps: int
    omega1: float
    coincident: dict[str, tuple[str, int]]  # name -> (base point, carrying link)
    residual: float  # largest |F| after Newton over the valid angles

    def arrays(self) -> ReferenceArrays:
        return as_arrays(self)


@dataclass(frozen=True)
class ReferenceArrays:
    """The reference rounded to floats, shaped like the engine's ``Motion``."""

    phi: np.ndarray
    position: dict[str, np.ndarray]
    velocity: dict[str, np.ndarray]
    acceleration: dict[str, np.ndarray]
    omega: dict[int, np.ndarray]
    epsilon: dict[int, np.ndarray]
    valid: np.ndarray
    omega1: float


def as_arrays(ref: ReferenceMotion) -> ReferenceArrays:
    """Float / complex numpy arrays of the reference (NaN where it did not assemble)."""

    def c(seq):
        return np.array([complex(z) for z in seq], dtype=complex)

    def r(seq):
        return np.array([float(v) for v in seq], dtype=float)

    return ReferenceArrays(
        phi=ref.phi.copy(),
        position={k: c(v[0]) for k, v in ref.points.items()},
        velocity={k: c(v[1]) for k, v in ref.points.items()},
        acceleration={k: c(v[2]) for k, v in ref.points.items()},
        omega={k: r(v[0]) for k, v in ref.links.items()},
        epsilon={k: r(v[1]) for k, v in ref.links.items()},
        valid=ref.valid.copy(),
        omega1=ref.omega1,
    )


def default_coincident(mech: Mechanism) -> dict[str, tuple[str, int]]:
    """``<point><link>`` for every slider on a guide carried by a moving link."""
    out = {}
    for s in mech.sliders:
        if s.guide.link != 0:
            out[f"{s.point}{s.guide.link}"] = (s.point, s.guide.link)
    return out


# ---------------------------------------------------------------------------------------
# solving
# ---------------------------------------------------------------------------------------


def _start(mech: Mechanism, mdl: _Model, motion, k: int, phi: float) -> list[float]:
    """Start vector from the engine's float poses, angles unwrapped to satisfy the
    (linear) angle equations exactly: the driver at φ, sliders at guide + direction."""
    q0 = []
    theta = {0: 0.0}
    for lid in mdl.link_ids:
        st = motion.links[lid]
        o = complex(st.origin[k])
        q0 += [o.real, o.imag, 0.0]
        theta[lid] = float(np.angle(st.rotor[k]))
    theta[mech.driver.link] = phi
    for _ in range(len(mech.sliders) + 1):
        for s in mech.sliders:
            a = math.atan2(s.guide.direction.imag, s.guide.direction.real)
            want = theta[s.guide.link] + a
            d = theta[s.link] - want
            theta[s.link] = want + (d - 2 * math.pi * round(d / (2 * math.pi)))
    for lid in mdl.link_ids:
        q0[mdl.index(lid) + 2] = theta[lid]
    return q0


def _lu(A: list[list]) -> tuple[list[list], list[int]]:
    """LU factors of a square matrix (rows of mpf, copied) with partial pivoting.

    Plain lists: the Jacobian is small and sparse, and mpmath's matrix indexing would
    cost more than the arithmetic.
    """
    n = len(A)
    a = [list(row) for row in A]
    perm = list(range(n))
    for c in range(n):
        p = max(range(c, n), key=lambda r: abs(a[r][c]))
        if not a[p][c]:
            raise ReferenceError(
                "singular loop-closure Jacobian (a dead point or a locked chain)"
            )
        if p != c:
            a[c], a[p] = a[p], a[c]
            perm[c], perm[p] = perm[p], perm[c]
        piv = a[c][c]
        rowc = a[c]
        for r in range(c + 1, n):
            f = a[r][c]
            if not f:
                continue
            f = f / piv
            row = a[r]
            row[c] = f
            for j in range(c + 1, n):
                if rowc[j]:
                    row[j] -= f * rowc[j]
    return a, perm


def _lu_solve(lu: tuple[list[list], list[int]], b: list) -> list:
    a, perm = lu
    n = len(a)
    y = [b[i] for i in perm]
    for i in range(n):
        row = a[i]
        acc = y[i]
        for j in range(i):
            if row[j]:
                acc -= row[j] * y[j]
        y[i] = acc
    for i in range(n - 1, -1, -1):
        row = a[i]
        acc = y[i]
        for j in range(i + 1, n):
            if row[j]:
                acc -= row[j] * y[j]
        y[i] = acc / row[i]
    return y


def _solve_one(mdl: _Model, q0, phi, omega, params, mp, tol):
    q = [mp.mpf(v) for v in q0]
    scale = 1 + max(abs(v) for v in q0)
    for _ in range(MAX_NEWTON):
        Fv = mdl.F(q, phi, params)
        dq = _lu_solve(_lu(mdl.J(q, phi, params)), [-v for v in Fv])
        q = [a + b for a, b in zip(q, dq, strict=True)]
        if max(abs(v) for v in dq) <= tol * scale:
            break
    else:
        raise ReferenceError(f"Newton did not converge at φ = {float(phi)!r} rad")
    res = max(abs(v) for v in mdl.F(q, phi, params))
    lu = _lu(mdl.J(q, phi, params))
    qd = _lu_solve(lu, [-v * omega for v in mdl.Fphi(q, phi, params)])
    qdd = _lu_solve(lu, mdl.gamma(q, qd, phi, omega, params))
    return q, qd, qdd, res


def reference(
    mech: Mechanism,
    phi,
    *,
    motion: Motion | None = None,
    dps: int = DEFAULT_DPS,
    extra: dict[str, tuple[str, int]] | None = None,
) -> ReferenceMotion:
    """Solve ``mech`` at the crank angles ``phi`` (rad from +x, scalar or array).

    ``motion``: the engine's float motion at the same angles, used only as Newton's start
    (so the assembly branch is inherited) and for the names of its coincident points;
    computed with ``plans.kinematics.Solver`` when not given. ``extra``: more coincident
    points, name -> (base point, carrying link). ``dps``: significant decimal digits.
    """
    import mpmath

    phi = np.atleast_1d(np.asarray(phi, dtype=float))
    if motion is None:
        with np.errstate(all="ignore"):
            motion = Solver(mech).solve(phi)
    elif len(motion.phi) != len(phi) or not np.array_equal(motion.phi, phi):
        raise ValueError("the start motion must be solved at the same angles")
    coincident = default_coincident(mech)
    for name, base in getattr(motion, "coincident", {}).items():
        coincident[name] = (base, int(motion.point_link[name]))
    coincident.update(extra or {})
    mdl = model(mech)
    with mpmath.workdps(dps + GUARD_DPS):
        mp = mpmath.mp
        params = _param_values(mech, mdl.param_names, mp)
        omega = mp.mpf(mech.driver.omega)
        tol = mp.mpf(10) ** (-(dps - 3))
        nan = mp.mpc(mp.nan, mp.nan)
        names = mech.point_names()
        points: dict[str, tuple[list, list, list]] = {
            n: ([], [], []) for n in [*names, *coincident]
        }
        links: dict[int, tuple[list, list]] = {
            lid: ([], []) for lid in (0, *mdl.link_ids)
        }
        valid = np.array([bool(v) for v in motion.valid], dtype=bool)
        worst = 0.0
        for k, ph in enumerate(phi):
            if not valid[k]:
                for lists in points.values():
                    for lst in lists:
                        lst.append(nan)
                for lid, (wl, el) in links.items():
                    wl.append(mp.mpf(0) if lid == 0 else mp.nan)
                    el.append(mp.mpf(0) if lid == 0 else mp.nan)
                continue
            phm = mp.mpf(float(ph))
            q0 = _start(mech, mdl, motion, k, float(ph))
            q, qd, qdd, res = _solve_one(mdl, q0, phm, omega, params, mp, tol)
            worst = max(worst, float(res))
            kin = {
                0: (mp.mpc(0), mp.mpc(1), mp.mpc(0), mp.mpc(0), mp.mpf(0), mp.mpf(0))
            }
            for lid in mdl.link_ids:
                i = mdl.index(lid)
                o = mp.mpc(q[i], q[i + 1])
                rot = mp.expj(q[i + 2])
                vo = mp.mpc(qd[i], qd[i + 1])
                ao = mp.mpc(qdd[i], qdd[i + 1])
                kin[lid] = (o, rot, vo, ao, qd[i + 2], qdd[i + 2])
            for lid, (wl, el) in links.items():
                wl.append(kin[lid][4])
                el.append(kin[lid][5])

            def state(lid, X, kin=kin):
                o, _rot, vo, ao, w, e = kin[lid]
                r = X - o
                return vo + mp.j * w * r, ao + (mp.j * e - w * w) * r

            where = {}
            for n in names:
                carriers = mech.links_of(n)
                if carriers[0] == 0:
                    z = mech.frame[n]
                    X, V, A = mp.mpc(z.real, z.imag), mp.mpc(0), mp.mpc(0)
                else:
                    lid = carriers[0]
                    lz = mech.links[lid].points[n]
                    o, rot = kin[lid][0], kin[lid][1]
                    X = o + rot * mp.mpc(lz.real, lz.imag)
                    V, A = state(lid, X)
                where[n] = X
                for lst, val in zip(points[n], (X, V, A), strict=True):
                    lst.append(val)
            for n, (base, lid) in coincident.items():
                X = where[base]
                V, A = state(lid, X)
                for lst, val in zip(points[n], (X, V, A), strict=True):
                    lst.append(val)
    return ReferenceMotion(
        phi=phi.copy(),
        points=points,
        links=links,
        valid=valid,
        dps=dps,
        omega1=float(mech.driver.omega),
        coincident=coincident,
        residual=worst,
    )


# ---------------------------------------------------------------------------------------
# comparison
# ---------------------------------------------------------------------------------------


def errors(
    motion: Motion, ref: ReferenceMotion | ReferenceArrays
) -> dict[str, np.ndarray]:
    """Per-angle relative errors of the engine (see the module docstring for the norm).

    Keys: position, velocity, acceleration, omega, epsilon; each an array over the angles
    (NaN where either side does not assemble). Every point and moving link of ``motion``
    must be in the reference.
    """
    arr = ref if isinstance(ref, ReferenceArrays) else as_arrays(ref)
    ok = np.asarray(motion.valid, dtype=bool) & arr.valid
    out = {}
    for key, eng, rr in (
        ("position", motion.position, arr.position),
        ("velocity", motion.velocity, arr.velocity),
        ("acceleration", motion.acceleration, arr.acceleration),
    ):
        missing = set(eng) - set(rr)
        if missing:
            raise KeyError(f"points not in the reference: {sorted(missing)}")
        diff = np.max([np.abs(eng[n] - rr[n]) for n in eng], axis=0)
        scale = np.max([np.abs(rr[n]) for n in eng], axis=0)
        out[key] = _ratio(diff, scale, ok)
    moving = [lid for lid in motion.links if lid != 0]
    missing = set(moving) - set(arr.omega)
    if missing:
        raise KeyError(f"links not in the reference: {sorted(missing)}")
    w1sq = arr.omega1**2
    for key, attr, rr, floor in (
        ("omega", "omega", arr.omega, 0.0),
        ("epsilon", "epsilon", arr.epsilon, w1sq),
    ):
        diff = np.max(
            [np.abs(getattr(motion.links[i], attr) - rr[i]) for i in moving], axis=0
        )
        scale = np.max([np.abs(rr[i]) for i in moving], axis=0)
        out[key] = _ratio(diff, np.maximum(scale, floor), ok)
    return out


def _ratio(diff, scale, ok):
    with np.errstate(all="ignore"):
        r = np.where(ok, diff / np.where(scale > 0, scale, 1.0), np.nan)
    return r


def max_rel_error(
    motion: Motion, ref: ReferenceMotion | ReferenceArrays
) -> dict[str, float]:
    """Largest relative error of the engine's positions, velocities, accelerations, ω and
    ε against the reference over the angles valid in both (norm: module docstring).

    Returns ``{"position": …, "velocity": …, "acceleration": …, "omega": …, "epsilon": …,
    "max": …}``; 0.0 for a quantity when no angle is valid.
    """
    per = errors(motion, ref)
    out = {}
    for k, v in per.items():
        good = v[np.isfinite(v)]
        out[k] = float(good.max()) if good.size else 0.0
    out["max"] = max(out.values())
    return out
