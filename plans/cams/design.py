"""A cam designed from its file: the motion, the base circle (the smallest the limits allow
where the file leaves it out), the follower's arrangement, the pressure angles along the
cycle and their maxima, the profile's curvature, and the refusals where no profile can be
made (an undercut roller, a flat face on a concave profile, a cusp).

>>> from plans.cams.camfile import from_dict
>>> cam = from_dict({"follower": {"kind": "knife-edge", "stroke": 0.016},
...                  "cam": {"base_radius": 0.03},
...                  "phases": [{"kind": "rise", "angle_deg": 120, "law": "cosine"},
...                             {"kind": "dwell", "angle_deg": 60},
...                             {"kind": "return", "angle_deg": 120, "law": "cosine"},
...                             {"kind": "dwell", "angle_deg": 60}]}, "exam.toml")
>>> d = design(cam)
>>> round(math.degrees(d.pressure["rise"].value), 4), [i.kind for i in d.impacts]
(17.902, ['soft', 'soft', 'soft', 'soft'])
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import NamedTuple

import numpy as np

from plans.cams.base import Portrait, pieces, portrait
from plans.cams.follower import Arrangement
from plans.cams.motion import DiscMotion, Impact, Motion, impacts
from plans.cams.profile import Curves, cross, curves
from plans.cams.search import edge, extreme
from plans.errors import PlansError
from plans.fmt import num

__all__ = ["Corner", "Design", "Extreme", "ProfileError", "design", "motion_of"]


class ProfileError(PlansError, ValueError):
    """No profile can be made of the cam as given (an undercut, a cusp, a flat face on a
    concave stretch): where, and by how much. ``source``: the cam file."""

    def __init__(self, message: str, *, source: str = ""):
        self.source = source
        super().__init__(message)


class Extreme(NamedTuple):
    """A largest or smallest value, at the cam angle ``phi`` of phase ``phase``."""

    value: float
    phi: float
    phase: int


class Corner(NamedTuple):
    """A joint where the follower's velocity jumps (a rigid impact): the pitch curve turns
    a corner there, ``convex`` towards the cam or not."""

    phi: float
    before: int
    after: int
    convex: bool


def motion_of(cam):
    """The follower's motion: by the phases, or the disc's."""
    if cam.disc is not None:
        f = cam.follower
        return DiscMotion(cam.disc.radius, cam.disc.eccentricity, f.offset, cam.sense, f.roller, f.flat)
    return Motion(cam.phases, cam.follower.stroke)


@dataclass(frozen=True)
class Design:
    """The cam as designed: ``r0`` and ``offset`` as used (given or chosen), ``smallest``
    the smallest base radius the limits allow at that offset, ``best`` (r0, e) the
    smallest at any offset (translating knife-edge and roller followers, by the phase
    portrait ``portrait``), the extremes along the cycle and the ``warnings``."""

    cam: object
    motion: object
    arrangement: Arrangement
    r0: float
    offset: float
    smallest: float | None
    best: tuple[float, float] | None
    portrait: Portrait | None
    impacts: tuple[Impact, ...]
    corners: tuple[Corner, ...]
    pressure: dict[str, Extreme]
    phase_pressure: dict[int, Extreme]
    speeds: dict[int, tuple[Extreme, Extreme]]
    radius: dict[str, Extreme | None]
    face: tuple[float, float] | None
    warnings: tuple[str, ...] = field(default=())

    def curves(self, phi) -> Curves:
        """The construction at the cam angles ``phi`` (a joint: the phase that starts
        there)."""
        phi = np.asarray(phi, dtype=float)
        return curves(self.arrangement, phi, self.motion.at(phi))

    def of_phase(self, i: int, phi, side: str = "right") -> Curves:
        """The construction at ``phi`` by phase ``i``'s own formulas."""
        phi = np.asarray(phi, dtype=float)
        return curves(self.arrangement, phi, self.motion.of_phase(i, phi, side))


def design(cam) -> Design:
    """Design ``cam``: choose what the file leaves free, check what it fixes; raises
    :class:`ProfileError` where no profile can be made."""
    f = cam.follower
    motion = motion_of(cam)
    lim = cam.limits
    port = None
    best = None
    offset = 0.0 if f.oscillating else f.offset
    if cam.disc is not None:
        smallest = motion.base_radius
        if not f.flat:
            port = portrait(motion, cam.sense, lim.rise_deg, lim.return_deg)
    elif not f.oscillating and not f.flat:
        port = portrait(motion, cam.sense, lim.rise_deg, lim.return_deg)
        best = (port.r0, port.e)
        if offset is None:
            offset = port.e
        smallest = port.at_offset(offset)[0]
    elif f.flat:
        smallest = _smallest_flat(cam, motion)
        offset = offset or 0.0
    else:
        smallest = _smallest_oscillating(cam, motion)
    r0 = cam.base_radius if cam.base_radius is not None else \
        motion.base_radius if cam.disc is not None else smallest
    if r0 is None:
        raise ProfileError(_no_base(cam), source=cam.source)
    arr = Arrangement(f, cam.sense, r0, offset or 0.0)
    d = _figures(cam, motion, arr)
    corners = _corners(motion, arr, d.impacts)
    warnings = _check(cam, motion, arr, d, corners, smallest)
    return Design(cam, motion, arr, r0, offset or 0.0, smallest, best, port, d.impacts, corners,
                  d.pressure, d.phase_pressure, d.speeds, d.radius, d.face, tuple(warnings))


class _Figures(NamedTuple):
    impacts: tuple[Impact, ...]
    pressure: dict[str, Extreme]
    phase_pressure: dict[int, Extreme]
    speeds: dict[int, tuple[Extreme, Extreme]]
    radius: dict[str, Extreme | None]
    face: tuple[float, float] | None


def _over(motion, fn, largest: bool, phases=None, refine: bool = True) -> Extreme | None:
    """The extreme of ``fn(i, phi, side)`` over the phases' smooth pieces (``refine``:
    to rounding, else the best of the samples)."""
    best = None
    for i, _ in enumerate(motion.phases):
        if phases is not None and i not in phases:
            continue
        for lo, hi, side in pieces(motion, i):
            v, x = extreme(lambda phi, i=i, side=side: fn(i, phi, side), lo, hi, largest,
                           samples=2049 if refine else 513, refine=refine)
            if best is None or (v > best.value if largest else v < best.value):
                best = Extreme(v, x, i)
    return best


def _figures(cam, motion, arr: Arrangement) -> _Figures:
    def crv(i, phi, side):
        return curves(arr, phi, motion.of_phase(i, phi, side))

    pressure, per = {}, {}
    for i, p in enumerate(motion.phases):
        if p.moves:
            per[i] = _over(motion, lambda i, phi, side: crv(i, phi, side).pressure, True, {i})
    for kind in ("rise", "return"):
        got = [e for i, e in per.items() if motion.phases[i].kind == kind]
        pressure[kind] = max(got, key=lambda e: e.value)
    speeds = {}
    for i, p in enumerate(motion.phases):
        if p.moves:
            v = _over(motion, lambda i, phi, side: np.abs(motion.of_phase(i, phi, side)[1]), True, {i})
            a = _over(motion, lambda i, phi, side: np.abs(motion.of_phase(i, phi, side)[2]), True, {i})
            speeds[i] = (v, a)
    radius: dict[str, Extreme | None] = {}
    if arr.flat:
        radius["profile"] = _over(motion, lambda i, phi, side: 1.0 / crv(i, phi, side).kappa, False)
    else:
        k = _over(motion, lambda i, phi, side: crv(i, phi, side).kappa, True)
        radius["pitch"] = Extreme(1.0 / k.value, k.phi, k.phase) if k.value > 0 else None
        c = _over(motion, lambda i, phi, side: crv(i, phi, side).kappa, False)
        radius["pitch_concave"] = Extreme(1.0 / c.value, c.phi, c.phase) if c.value < 0 else None
    face = _face(motion, arr) if arr.flat else None
    return _Figures(tuple(impacts(motion)), pressure, per, speeds, radius, face)


def _face(motion, arr: Arrangement) -> tuple[float, float]:
    """Where the face touches the profile, along the face from the follower's axis (or
    its pivot): (nearest, farthest) over the cycle, m."""
    def along(i, phi, side):
        c = curves(arr, phi, motion.of_phase(i, phi, side))
        X = c.profile * np.exp(1j * arr.sigma * phi)  # back in the fixed frame
        if not arr.oscillating:
            return X.real - arr.e
        g = arr.tau * (arr.psi0 + c.s)
        return ((X - arr.A) * np.conj(arr.tau * (np.cos(g) + 1j * np.sin(g)))).real
    lo = _over(motion, along, False)
    hi = _over(motion, along, True)
    return lo.value, hi.value


def _corners(motion, arr: Arrangement, imps) -> tuple[Corner, ...]:
    """The pitch curve's corners, at the joints where the velocity jumps."""
    out = []
    for imp in imps:
        if imp.kind != "rigid" or imp.where[0] == imp.where[1]:
            continue
        before, after = imp.where
        end = motion.phases[before].end
        c0 = curves(arr, np.array([end]), motion.of_phase(before, np.array([end]), "left"))
        c1 = curves(arr, np.array([imp.phi]), motion.of_phase(after, np.array([imp.phi]), "right"))
        if arr.flat:  # the face's contact runs back along the face: the profile folds
            t0 = c0.profile[0] - curves(arr, np.array([end - 1e-6]),
                                        motion.of_phase(before, np.array([end - 1e-6]), "left")).profile[0]
            convex = bool((np.conj(t0) * (c1.profile[0] - c0.profile[0])).real < 0)
        else:
            convex = bool(-arr.sigma * cross(c0.pitch1[0], c1.pitch1[0]) > 0)
        out.append(Corner(imp.phi, before, after, convex))
    return tuple(out)


def _mm(x: float) -> str:
    return num(x * 1000.0, 4).replace("-", "−")


def _deg(x: float) -> str:
    return num(math.degrees(x) % 360.0, 4)


def _where(motion, e: Extreme) -> str:
    return f"φ = {_deg(e.phi)}° ({motion.phases[e.phase].kind})"


def _check(cam, motion, arr: Arrangement, d: _Figures, corners, smallest) -> list[str]:
    """Refuse a profile that cannot be made; the warnings of one that can."""
    f, lim = cam.follower, cam.limits
    src = cam.source
    rr, m = f.roller, lim.min_radius
    fix = _remedy(cam, motion, arr)
    if f.kind == "roller":
        if arr.r0 <= rr:
            raise ProfileError(f"the roller (r_r = {_mm(rr)} mm) is not smaller than the base circle "
                               f"(r0 = {_mm(arr.r0)} mm): the profile would pass the cam's centre",
                               source=src)
        for c in corners:
            if c.convex:
                raise ProfileError(
                    f"undercut: the pitch curve turns a corner at φ = {_deg(c.phi)}°, where the "
                    f"{motion.phases[c.after if motion.phases[c.after].moves else c.before].kind}'s "
                    "velocity jumps (a rigid impact): a roller cannot follow it; take a law without "
                    "a velocity jump there, or a knife-edge follower", source=src)
    if f.flat:
        for c in corners:
            if c.convex:
                raise ProfileError(
                    f"the flat face cannot follow the velocity jump at φ = {_deg(c.phi)}° (a rigid "
                    "impact): the profile would fold back there; take a law without a velocity jump",
                    source=src)
        rho = d.radius["profile"]
        if rho.value <= 0 or rho.value < m - 1e-12 * max(m, arr.r0):  # (r0 chosen at the limit: on it)
            need = f"at least {_mm(m)} mm" if m > 0 else "positive"
            raise ProfileError(
                f"the profile is not convex enough for a flat face at {_where(motion, rho)}: its radius of "
                f"curvature is {_mm(rho.value)} mm" + (" (r0 + s + s″)" if not f.oscillating else "") +
                f", it must be {need}, short by {_mm(max(m, 0.0) - rho.value)} mm{fix('flat')}", source=src)
    else:
        k = d.radius["pitch"]
        floor = rr + m
        if k is not None and floor > 0 and (k.value <= rr * (1 + 1e-12) or k.value < floor * (1 - 1e-12)):
            what = (f"the roller's r_r = {_mm(rr)} mm" + (f" and the limit {_mm(m)} mm" if m else "")
                    if rr else f"the limit {_mm(m)} mm")
            raise ProfileError(
                f"{'undercut' if rr else 'too sharp'}: at {_where(motion, k)} the pitch curve's radius of "
                f"curvature is {_mm(k.value)} mm, under {what} by {_mm(floor - k.value)} mm"
                f"{fix('pitch')}", source=src)
    out = []
    for kind, limit in (("rise", lim.rise_deg), ("return", lim.return_deg)):
        e = d.pressure[kind]
        if math.degrees(e.value) > limit + 1e-9:
            where = "the disc is given as it is" if cam.disc is not None else (
                f"r0 ≥ {_mm(smallest)} mm keeps within both limits" if smallest is not None else "")
            out.append(f"the pressure angle reaches {num(math.degrees(e.value), 4)}° on {kind} at "
                       f"φ = {_deg(e.phi)}°, over [α] = {num(limit, 4)}°" + (f": {where}" if where else ""))
    return out


def _remedy(cam, motion, arr):
    """What makes a refused profile possible: the smallest base radius that does, where a
    larger one would (the file's phases; not a given disc)."""
    def text(which: str) -> str:
        if cam.disc is not None:
            return "; the disc is given as it is: take a smaller roller" if which == "pitch" and \
                cam.follower.roller else ""
        r = _smallest_profile(cam, motion, arr, which)
        if r is None:
            return ""
        more = "" if which == "flat" or not cam.follower.roller else " (or a smaller roller)"
        return f"; a base radius of at least {_mm(r)} mm avoids it{more}"
    return text


def _smallest_profile(cam, motion, arr: Arrangement, which: str) -> float | None:
    """The smallest base radius (at the design's offset) whose profile can be made."""
    f, m = cam.follower, cam.limits.min_radius

    def ok(r0: float, refine: bool = True) -> bool:
        try:
            a = Arrangement(f, cam.sense, r0, arr.e)
        except ValueError:
            return False
        if which == "flat":
            rho = _over(motion, lambda i, phi, side: 1.0 / curves(a, phi, motion.of_phase(i, phi, side))
                        .kappa, False, refine=refine)
            return rho.value > max(m, 0.0)
        k = _over(motion, lambda i, phi, side: curves(a, phi, motion.of_phase(i, phi, side)).kappa, True,
                  refine=refine)
        return k.value <= 0 or 1.0 / k.value > f.roller + m

    lo = abs(arr.e) * (1 + 1e-9) + 1e-9 if not f.oscillating else abs(f.centre - f.arm) + 1e-9
    hi = 20.0 * max(arr.r0, motion.stroke if not f.oscillating else f.arm)
    if f.oscillating:
        hi = min(hi, f.centre + f.arm - 1e-9) if not f.flat else f.centre * (1 - 1e-9)
    return edge(ok, max(lo, arr.r0), hi, samples=60, rough=lambda r0: ok(r0, False))


def _smallest_flat(cam, motion) -> float | None:
    """The smallest base radius of a flat face's profile with ρ ≥ the limit: for a
    translating face ρ = r0 + s + s″, so r0 = limit − min(s + s″)."""
    m = cam.limits.min_radius
    f = cam.follower
    if not f.oscillating:
        low = _over(motion, lambda i, phi, side: sum(motion.of_phase(i, phi, side)[0:3:2]), False)
        return max(m - low.value, 0.0) or None
    a = f.centre

    def ok(r0: float, refine: bool = True) -> bool:
        arr = Arrangement(f, cam.sense, r0)
        if arr.psi0 + f.stroke >= math.pi:
            return False
        rho = _over(motion, lambda i, phi, side: 1.0 / curves(arr, phi, motion.of_phase(i, phi, side)).kappa,
                    False, refine=refine)
        return rho.value >= m and rho.value > 0
    return edge(ok, a * 1e-6, a * (1 - 1e-9), samples=120, rough=lambda r0: ok(r0, False))


def _smallest_oscillating(cam, motion) -> float | None:
    """The smallest base radius of an oscillating follower's pitch curve that keeps the
    pressure angles within the limits, its pivot and arm as given."""
    f, lim = cam.follower, cam.limits
    a, ell = f.centre, f.arm
    limits = {i: math.radians(lim.rise_deg if p.kind == "rise" else lim.return_deg)
              for i, p in enumerate(motion.phases) if p.moves}

    def ok(r0: float, refine: bool = True) -> bool:
        arr = Arrangement(f, cam.sense, r0)
        if arr.psi0 + f.stroke >= math.pi:
            return False
        for i, limit in limits.items():
            e = _over(motion, lambda i, phi, side: arr.pressure(*motion.of_phase(i, phi, side)[:2]), True,
                      {i}, refine=refine)
            if e.value > limit:
                return False
        return True
    return edge(ok, abs(a - ell) + 1e-9 * (a + ell), (a + ell) * (1 - 1e-9), samples=120,
                rough=lambda r0: ok(r0, False))


def _no_base(cam) -> str:
    f, lim = cam.follower, cam.limits
    if f.flat:
        return (f"no base radius gives the flat face's profile a radius of curvature of at least "
                f"{_mm(lim.min_radius)} mm: give base_radius")
    return (f"no base radius keeps the pressure angles within [α] = {num(lim.rise_deg, 4)}° on rise and "
            f"{num(lim.return_deg, 4)}° on return with this arm (l = {_mm(f.arm)} mm) and pivot "
            f"(a = {_mm(f.centre)} mm): allow larger angles, or move the pivot")


