"""The profile as a table of points, for a CNC or CAD user and for the sheet: every ``step``
of cam angle and every joint of two phases, with the corner a jump of the follower's
velocity makes drawn in full (the roller's arc round a hollow corner of the pitch curve,
or the two ends of the straight stretch a flat face leaves).

>>> from plans.cams.camfile import from_dict
>>> from plans.cams.design import design
>>> cam = from_dict({"follower": {"kind": "roller", "stroke": 0.02, "roller_radius": 0.005},
...                  "cam": {"base_radius": 0.04},
...                  "phases": [{"kind": "rise", "angle_deg": 90, "law": "cycloidal"},
...                             {"kind": "dwell", "angle_deg": 90},
...                             {"kind": "return", "angle_deg": 90, "law": "3-4-5"},
...                             {"kind": "dwell", "angle_deg": 90}]}, "c.toml")
>>> t = profile_table(design(cam), math.radians(10))
>>> len(t.phi), round(float(abs(t.profile[0])) * 1000, 9)
(36, 35.0)
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

from plans.cams.motion import TURN
from plans.cams.profile import curves

__all__ = ["Table", "profile_table"]


class Table(NamedTuple):
    """Rows of the profile: the cam angle, the phase, s, s′, s″, s‴, the pressure angle, the
    pitch point and the profile's point in the cam's frame (complex, m), the profile's
    radius of curvature (m, convex positive; inf where straight) and ``corner``: the row
    is one of the extra points of a corner (its cam angle repeats)."""

    phi: np.ndarray
    phase: np.ndarray
    s: np.ndarray
    s1: np.ndarray
    s2: np.ndarray
    s3: np.ndarray
    pressure: np.ndarray
    pitch: np.ndarray
    profile: np.ndarray
    radius: np.ndarray
    corner: np.ndarray


def profile_table(d, step: float) -> Table:
    """The profile of the design ``d`` every ``step`` (rad) of cam angle and at every
    joint, corners in full."""
    n = max(math.floor(TURN / step + 1e-9), 1)
    grid = np.arange(n) * step
    grid = grid[grid < TURN - 1e-12]
    joints = np.array([p.start for p in d.motion.phases])
    phi = np.unique(np.concatenate([grid, joints[~np.isclose(joints[:, None], grid[None, :],
                                                             rtol=0, atol=1e-12).any(axis=1)]]))
    c = d.curves(phi)
    rows = {k: list(v) for k, v in _columns(c, d.motion.index(phi), np.zeros(len(phi), bool)).items()}
    for corner in sorted(d.corners, key=lambda x: x.phi, reverse=True):
        at = int(np.argmin(np.abs(phi - corner.phi)))
        end = d.motion.phases[corner.before].end
        at_end = np.array([end])
        left = curves(d.arrangement, at_end, d.motion.of_phase(corner.before, at_end, "left"))
        extra = _columns(left, np.array([corner.before]), np.array([True]), phi_value=corner.phi)
        fill = _fill(d, corner, left, c, at)
        for k in rows:
            rows[k][at:at] = list(extra[k]) + list(fill[k]) if fill else list(extra[k])
    return Table(*(np.array(rows[k]) for k in Table._fields))


def _columns(c, phase, corner, phi_value=None) -> dict:
    with np.errstate(divide="ignore"):
        radius = np.where(c.kappa_profile == 0, np.inf, 1.0 / np.where(c.kappa_profile == 0, 1.0,
                                                                         c.kappa_profile))
    phi = c.phi if phi_value is None else np.full(len(c.phi), phi_value)
    return {"phi": phi, "phase": phase, "s": c.s, "s1": c.s1, "s2": c.s2, "s3": c.s3, "pressure": c.pressure,
            "pitch": c.pitch, "profile": c.profile, "radius": radius, "corner": corner}


def _fill(d, corner, left, c, at) -> dict | None:
    """The roller's arc round a hollow corner of the pitch curve: the profile there is the
    roller circle itself, from the normal before the corner to the normal after."""
    rr = d.arrangement.follower.roller
    if not rr or corner.convex:
        return None
    centre = c.pitch[at]
    a0 = np.angle(left.profile[0] - centre)
    a1 = np.angle(c.profile[at] - centre)
    span = (a1 - a0 + np.pi) % (2 * np.pi) - np.pi
    k = max(int(abs(math.degrees(span))), 1)
    ang = a0 + span * np.arange(1, k) / k
    pts = centre + rr * np.exp(1j * ang)
    m = len(pts)
    rep = {f: np.repeat(getattr(left, f)[:1], m) for f in ("s", "s1", "s2", "s3", "pressure")}
    return {"phi": np.full(m, corner.phi), "phase": np.full(m, corner.after), **rep,
            "pitch": np.full(m, centre), "profile": pts, "radius": np.full(m, -rr),
            "corner": np.ones(m, bool)}


#: degrees: the rays of the construction divide each rise and return into parts of about
#: this cam angle, four at least
RAY_STEP = 15.0


def positions(d) -> list[float]:
    """The cam angles of the follower's numbered positions, as the construction draws them
    (numbered 0, 1, 2 … from φ = 0): every joint of two phases, and each rise and return
    divided into equal parts of about :data:`RAY_STEP`.

    >>> from plans.cams.camfile import from_dict
    >>> from plans.cams.design import design
    >>> cam = from_dict({"follower": {"kind": "knife-edge", "stroke": 0.016}, "cam": {"base_radius": 0.03},
    ...                  "phases": [{"kind": "rise", "angle_deg": 120, "law": "cosine"},
    ...                             {"kind": "dwell", "angle_deg": 60},
    ...                             {"kind": "return", "angle_deg": 120, "law": "cosine"},
    ...                             {"kind": "dwell", "angle_deg": 60}]}, "c.toml")
    >>> [round(math.degrees(p)) for p in positions(design(cam))][:10]
    [0, 15, 30, 45, 60, 75, 90, 105, 120, 180]
    """
    out: list[float] = []
    for p in d.motion.phases:
        parts = max(4, round(math.degrees(p.angle) / RAY_STEP)) if p.moves else 1
        out += [p.start + p.angle * k / parts for k in range(parts)]
    return out
