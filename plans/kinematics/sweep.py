"""Bulk solution over many crank angles: the group kernels run block by block, results only.

:meth:`plans.kinematics.Solver.solve` records every construction of every group (the
routes, their terms and line directions) as arrays, which the plans, the note and the
check need at a few angles. Over 10⁵–10⁶ angles that record is most of the memory
traffic, so :func:`sweep` runs the same kernels (``plans/kinematics/kernels.py``) and keeps only
what a table or a chart uses: the position, velocity and acceleration of every point,
ω and ε of every link, the conditioning of every group and where the mechanism closes.

It works in blocks of :data:`BLOCK` angles, so that the twenty-odd arrays a group
needs stay in the processor's cache, and writes each block into arrays cut from one
allocation (:func:`_allocate`). The blocks run the one group loop
(:func:`plans.kinematics.assemble.assemble`) with each dyad's bulk step.
Fixed points cost nothing: their entries are read-only broadcast views of one number.
Each link is carried through a block by one of its points (an anchor: position,
velocity, acceleration), its rotor, ω and ε; any other point Y of it follows by the
rigid-body formulas Y = X + r, V_Y = V_X + iω·r, a_Y = a_X + (iε − ω²)·r with
r = rotor·(y − x) in the link's own coordinates.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from plans.kinematics.assemble import assemble
from plans.kinematics.conditioning import pivot_key, pivot_ratio
from plans.kinematics.dyads import rigid
from plans.kinematics.groups import driver_inputs
from plans.model.structure import DyadKind

#: angles per block: 8192 complex numbers are 128 KiB an array, so the few arrays a step
#: works on at a time stay in a core's 2 MiB second-level cache, while numpy's cost per
#: call (about 0.6 µs here, some 200 calls a block) is spread over enough angles.
#: Measured on the press: 1024 → 381, 2048 → 284, 4096 → 242, 8192 → 229,
#: 16384 → 243 ns per angle for the blocks alone.
BLOCK = 8192


@dataclass(frozen=True)
class Sweep:
    """Every point and link over the crank angles ``phi``, without the record: each array
    of the shape of the angles swept (a single angle: an array of one, as in ``solve``).

    ``sine`` holds, per group (by its label), the |sin| between the two lines its plans
    intersect: the conditioning figure. A slotted link (RPR) has a second figure,
    :attr:`pivot`. Where ``valid`` is False a group does not close: every moving point's
    position, velocity and acceleration, every turning link's ω and ε and every figure
    is NaN there. On a change point itself (a parallelogram at φ = 0),
    where a group's links lie in line, rounding may put the group just out of reach
    (within about 1e-9 rad of it): not valid either, though the recorded
    :meth:`plans.kinematics.Solver.solve` and ``plans cycle`` give the positions there.
    """

    phi: np.ndarray
    position: dict[str, np.ndarray]
    velocity: dict[str, np.ndarray]
    acceleration: dict[str, np.ndarray]
    omega: dict[int, np.ndarray]
    epsilon: dict[int, np.ndarray]
    sine: dict[str, np.ndarray]
    valid: np.ndarray
    #: per slotted link (RPR): its key in :attr:`pivot`, its block P and rocker pivot Q,
    #: and the crank's pivot O
    slots: tuple[tuple[str, str, str, complex], ...] = ()

    @property
    def min_sine(self) -> np.ndarray:
        out = np.ones_like(self.phi)
        for s in self.sine.values():
            out = np.minimum(out, s)
        return out

    @property
    def pivot(self) -> dict[str, np.ndarray]:
        """Per slotted link ("group 2–3 (RPR) pivot", as ``plans cycle`` names it): how far
        its block P is from the rocker's pivot Q, |QP| / (|OQ| + |OP|), O the crank's pivot
        (:func:`plans.kinematics.conditioning.pivot_figure`). Near 0 the rocker's ω = V / |QP| loses its
        digits while the lines' sine stays 1. Worked out when asked for."""
        return {key: pivot_ratio(self.position[P], self.position[Q], crank)
                for key, P, Q, crank in self.slots}


def sweep(sv, phi, block: int = BLOCK, into: Sweep | None = None) -> Sweep:
    """Solve the mechanism of the solver ``sv`` (:class:`plans.kinematics.Solver`) at
    every angle of ``phi`` (rad from +x, any shape: the results take it), block by block.

    ``into``: a sweep of the same solver over angles of the same shape, whose arrays are
    overwritten instead of allocating new ones. Fresh memory is what a sweep of 10⁶
    angles mostly waits for (the system zeroes every page on first touch), so a loop
    that sweeps again and again, an animation or an optimisation, should pass the
    previous result.
    """
    phi = np.asarray(phi, dtype=float)
    shape = phi.shape if phi.ndim else (1,)  # as solve: one angle is an array of one
    phi = np.ascontiguousarray(phi.ravel())  # worked on flat, block by block
    n = phi.size
    block = max(int(block), 1)
    _raise_malloc_thresholds()
    with np.errstate(all="ignore"):
        if into is not None:
            if into.phi.size != n:
                raise ValueError(f"into: a sweep of {into.phi.size} angles, not {n}")
            if into.phi.shape != shape:
                raise ValueError(f"into: a sweep of angles shaped {into.phi.shape}, not {shape}")
            if [name for name, _ in sv.setup.layout[0]["pos"]] != list(into.position):
                raise ValueError("into: a sweep of another mechanism (its points differ)")
            # flat views of its arrays (cut from one block, or broadcast constants)
            out = {"pos": _flat(into.position), "vel": _flat(into.velocity),
                   "acc": _flat(into.acceleration)}
            omega, epsilon, sine = _flat(into.omega), _flat(into.epsilon), _flat(into.sine)
            valid = into.valid.reshape(-1)
            into.phi.reshape(-1)[...] = phi
            phi = into.phi.reshape(-1)
        else:
            out, omega, epsilon, sine, valid, own = _allocate(sv.setup.layout, n)
            own[...] = phi  # the sweep owns its angles: a later into= overwrites them
            phi = own
        for i in range(0, n, block):
            j = min(i + block, n)
            dest = {kind: {name: o[i:j] for name, o in outs.items() if o.flags.writeable}
                    for kind, outs in out.items()}
            part = assemble(Block(sv.setup, phi[i:j], dest), sv.setup, sv.signs(phi[i:j]))
            for kind, outs in dest.items():
                got = getattr(part, kind)
                for name, o in outs.items():
                    if got[name] is not o:
                        o[...] = got[name]
            for lid, ln in part.links.items():
                for store, k in ((omega, 4), (epsilon, 5)):
                    if store[lid].flags.writeable:
                        store[lid][i:j] = ln[k]
            for label, v in part.sine.items():
                sine[label][i:j] = v
            valid[i:j] = part.valid
        if not valid.all():
            _blank(~valid, out, omega, epsilon, sine)
    mech = sv.mech
    slots = tuple((pivot_key(g.label), g.P, g.Q, mech.driver.origin)
                  for g in sv.structure.groups if g.kind == DyadKind.RPR)
    if into is not None:  # its own arrays, already of the angles' shape
        return Sweep(into.phi, into.position, into.velocity, into.acceleration, into.omega,
                     into.epsilon, into.sine, into.valid, slots)
    if shape != (n,):  # views of the flat arrays, shaped as the angles were
        return Sweep(phi.reshape(shape), *(_shaped(out[k], shape) for k in ("pos", "vel", "acc")),
                     _shaped(omega, shape), _shaped(epsilon, shape), _shaped(sine, shape),
                     valid.reshape(shape), slots)
    return Sweep(phi, out["pos"], out["vel"], out["acc"], omega, epsilon, sine, valid, slots)


def _flat(arrays: dict) -> dict:
    """Flat views of a sweep's arrays, to be written block by block (a view of a
    read-only broadcast constant stays read-only)."""
    return {k: a.reshape(-1) for k, a in arrays.items()}


def _shaped(arrays: dict, shape: tuple[int, ...]) -> dict:
    return {k: a.reshape(shape) for k, a in arrays.items()}


def _blank(bad: np.ndarray, out: dict, *stores: dict) -> None:
    """NaN at the angles ``bad``, where a group does not close, in every array a sweep
    wrote: there the kernels leave finite numbers that mean nothing (a hinge on a clipped
    circle intersection, ω of 1e17), which a max or a ptp over the sweep would take for
    values. The fixed points' constants stay as they are."""
    for arrays in (*out.values(), *stores):
        for a in arrays.values():
            if a.flags.writeable:
                a[bad] = np.nan


def layout(setup):
    """The names a sweep of ``setup``'s mechanism fills, with the value of those that are
    constant (None for the others): (points by kind, ω and ε by link, group labels). A
    block of one angle is solved to find them, every sign +1 (they do not depend on the
    assembly); :attr:`plans.kinematics.setup.Setup.layout` keeps them."""
    with np.errstate(all="ignore"):
        probe = assemble(Block(setup, np.zeros(1)), setup, lambda i: 1.0)
    const = lambda v: v if np.ndim(v) == 0 else None  # noqa: E731
    kinds = {kind: [(name, const(v)) for name, v in getattr(probe, kind).items()]
             for kind in ("pos", "vel", "acc")}
    links = {lid: (const(ln[4]), const(ln[5])) for lid, ln in probe.links.items()}
    return kinds, links, list(probe.sine)


_malloc_ready = False


def _raise_malloc_thresholds() -> None:
    """Free one 16 MiB block so that glibc's malloc keeps the blocks' temporaries.

    Until it has seen a block that large freed, glibc serves each temporary of more
    than 128 KiB with a fresh mmap and gives memory back to the system as soon as
    128 KiB lie free at the top of the heap, so every block of every sweep faulted its
    pages in anew (a third of the run time at 10⁶ angles here). Freeing one block
    raises both thresholds for the rest of the process (mallopt(3), "dynamic mmap
    threshold"); elsewhere it costs one untouched allocation.
    """
    global _malloc_ready
    if not _malloc_ready:
        scratch = np.empty(1 << 21)  # 2²¹ float64 = 16 MiB, never written
        del scratch
        _malloc_ready = True


def _allocate(layout, n: int):
    """The arrays of a sweep over ``n`` angles, all cut from one allocation.

    One large block instead of some forty: the system gives it 2 MiB pages (numpy asks
    for them above 4 MiB), so fresh memory costs one page fault where 4 KiB pages cost
    512, and glibc does not hand the sweep's memory back between two sweeps of 10⁵ angles
    only to fault it in again. Measured on seed 001's four-bar: 10⁵ angles 350 → 235 ns
    a position, 10⁶ angles 260 → 240 ns. The memory goes back to the system when every
    array of the sweep is gone.
    Returns (position/velocity/acceleration dicts by kind, ω, ε, sine, valid, angles).
    """
    kinds, links, labels = layout
    n_complex = sum(v is None for names in kinds.values() for _, v in names)
    n_float = sum((w is None) + (e is None) for w, e in links.values()) + len(labels) + 1
    n_bool = -(-n // 8)  # float64 slots that hold n booleans
    buf = np.empty((2 * n_complex + n_float) * n + n_bool)
    at = 0

    def cut(count):
        nonlocal at
        at += count
        return buf[at - count:at]

    def complex_(v):
        if v is not None:
            return np.broadcast_to(np.asarray(v, dtype=complex), (n,))
        return cut(2 * n).view(complex)  # offsets stay multiples of 16 bytes

    def float_(v):
        return np.broadcast_to(np.asarray(v, dtype=float), (n,)) if v is not None else cut(n)

    out = {kind: {name: complex_(v) for name, v in names} for kind, names in kinds.items()}
    omega = {lid: float_(w) for lid, (w, _) in links.items()}
    epsilon = {lid: float_(e) for lid, (_, e) in links.items()}
    sine = {label: cut(n) for label in labels}
    phi = cut(n)
    valid = cut(n_bool).view(bool)[:n]
    return out, omega, epsilon, sine, valid, phi


class Block:
    """One block of angles (:func:`sweep`), the bulk path's state in the group loop
    (:func:`plans.kinematics.assemble.assemble`): every point's position, velocity and
    acceleration, each link carried by one of its points, each group's figure and where
    the block closes. ``dest``: the sweep's arrays for this block, written straight into
    where it has one."""

    def __init__(self, setup, phi: np.ndarray, dest: dict | None = None):
        self.setup = setup
        self.dest = dest or {"pos": {}, "vel": {}, "acc": {}}
        mech = setup.mech
        self.pos: dict = {}
        self.vel: dict = {}
        self.acc: dict = {}
        # link id -> (anchor X, V_X, a_X, rotor, ω, ε, anchor's own coordinate)
        self.links: dict[int, tuple] = {0: (0j, 0j, 0j, 1 + 0j, 0.0, 0.0, 0j)}
        self.sine: dict[str, np.ndarray] = {}
        self.valid = np.ones(phi.shape, dtype=bool)
        for name, xy in mech.frame.items():
            self.pos[name], self.vel[name], self.acc[name] = xy, 0j, 0j
        drv = mech.driver
        if mech.timing is None and not drv.linear:  # the crank at φ, at its ω and ε
            rotor = np.empty(phi.shape, dtype=complex)
            np.cos(phi, out=rotor.real)
            np.sin(phi, out=rotor.imag)
            self.links[drv.link] = (drv.origin, 0j, 0j, rotor, drv.omega, drv.epsilon, 0j)
            return
        for d, (q, dq, ddq) in zip(mech.drivers, driver_inputs(mech, phi), strict=True):
            if d.linear:  # carried by its point on the guide
                u = d.guide.direction
                self.links[d.link] = (d.origin + q * u, dq * u, ddq * u, u, 0.0, 0.0, d.local)
            else:
                self.links[d.link] = (d.origin, 0j, 0j, np.exp(1j * q), dq, ddq, 0j)

    # the group loop's three moves ------------------------------------------------------
    def step(self, dyad, g, own: dict, sigma):
        """Group ``g`` by its dyad's bulk step; the coincident points it found."""
        return dyad.bulk(self, g, own, sigma)

    def fill(self, lid: int) -> None:
        """Every point of link ``lid`` not known yet, from the link's anchor; written
        straight into the sweep's output where it has one."""
        X, vX, aX, rot, w, e, xl = self.links[lid]
        jw = kk = None
        for name, yl in self.setup.mech.links[lid].points.items():
            if name in self.pos:
                continue
            if jw is None:
                jw, kk = 1j * w, 1j * e - w * w
            r = rot * (yl - xl)
            self.pos[name] = self._sum("pos", name, X, r)
            self.vel[name] = self._sum("vel", name, vX, r, jw)
            self.acc[name] = self._sum("acc", name, aX, r, kk)

    def coincide(self, found) -> None:
        """The coincident points a step found, after the links' own points, as the
        recorded solve orders them, with the kernel's own values."""
        for name, _lid, at, v, a in found:
            self.pos[name], self.vel[name], self.acc[name] = self.pos[at], v, a

    # what the steps use ------------------------------------------------------------------
    def guide(self, guide):
        """A world point of the guide, its direction, the motion of its link there, and
        the link's ω, ε: None where the link never turns
        (:func:`plans.kinematics.groups.guide_motion`)."""
        if guide.link == 0:
            return guide.point, guide.direction, 0j, 0j, None, None
        _X, _vX, _aX, rot, w, e, _xl = self.links[guide.link]
        G, vG, aG = self._at(guide.link, guide.point)
        if guide.link in self.setup.translating:
            return G, rot * guide.direction, vG, aG, None, None
        return G, rot * guide.direction, vG, aG, w, e

    def close(self, label, sine, valid):
        """Group ``label``'s figure and where it closes."""
        # a figure, |sin| within [0, 1]: the cross product of two unit vectors as rounded
        # reaches 1.0000000000000002, which the kernel divides by as it is
        self.sine[label] = np.minimum(abs(sine), 1.0)
        self.valid &= valid

    def _sum(self, kind, name, a, r, k=None):
        """a + r·k (k omitted: a + r), into the output ``dest[kind][name]`` if there is one."""
        o = self.dest[kind].get(name)
        if o is None:
            rk = r if k is None else r * k
            return rk if isinstance(a, complex) and a == 0 else a + rk
        if k is None:
            np.add(a, r, out=o)
            return o
        np.multiply(r, k, out=o)
        if not (isinstance(a, complex) and a == 0):
            o += a
        return o

    def _at(self, lid: int, local):
        """World position, velocity and acceleration of the point ``local`` of link lid."""
        X, vX, aX, rot, w, e, xl = self.links[lid]
        r = rot * (local - xl)
        return (X + r, *rigid(vX, aX, r, w, e))
