"""The cam's profile by inversion, exact: the pitch curve, the actual profile as the envelope
of the roller circles or of the face lines, and their radii of curvature.

In the cam's frame (:func:`plans.cams.follower.in_cam_frame`) the pitch point traces the
pitch curve R(φ). Turning as the cam turns the other way (σ = +1: clockwise), its inner
side, the cam's own, is on the right of its tangent; the inner normal is

    n = −σ·i·R′/|R′|,   its curvature towards the cam   κ = −σ·(R′ × R″)/|R′|³

(ρ = 1/κ, positive where the curve is convex). A **roller** of radius r_r on it touches
the envelope of its circles, the pitch curve offset inwards,

    P = R + r_r·n,   ρ_P = ρ − r_r,

which turns back on itself (undercut) where the convex ρ < r_r. A **flat face** is the line
X·n(θ) = p of the cam's frame; the envelope of the lines, and its radius of curvature,

    P = p·n + (dp/dθ)·i·n,   ρ = p + d²p/dθ²   (dp/dθ = p′/θ′, d²p/dθ² = (p″θ′ − p′θ″)/θ′³),

is convex only where ρ > 0: for a translating face, ρ = r0 + s + s″.

Every function works on arrays of cam angles at once: a profile of thousands of points is
one call.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from plans.cams.follower import Arrangement, in_cam_frame

__all__ = ["Curves", "cross", "curves"]


def cross(a, b):
    """z of a × b for complex vectors (positive: b counter-clockwise of a)."""
    return (np.conj(a) * b).imag


class Curves(NamedTuple):
    """The construction at the cam angles ``phi`` (arrays of their shape): s and its
    derivatives; the pitch point in the fixed frame; the pitch curve in the cam's (its
    first derivative, its curvature towards the cam); the profile and its curvature
    (convex positive); the pressure angle (rad). A flat face has no pitch curve of its
    own: ``pitch`` is where its axis meets it (translating) or its point over the pivot's
    foot (oscillating), ``kappa`` the profile's."""

    phi: np.ndarray
    s: np.ndarray
    s1: np.ndarray
    s2: np.ndarray
    s3: np.ndarray
    B: np.ndarray
    pitch: np.ndarray
    pitch1: np.ndarray
    kappa: np.ndarray
    profile: np.ndarray
    kappa_profile: np.ndarray
    pressure: np.ndarray


def curves(arr: Arrangement, phi, values) -> Curves:
    """The construction at the cam angles ``phi`` from ``values`` = (s, s′, s″, s‴)
    there."""
    phi = np.asarray(phi)
    s, s1, s2, s3 = (np.asarray(v) for v in values)
    sig = arr.sigma
    alpha = arr.pressure(s, s1)
    if arr.flat:
        n, p, p1, p2, t1, t2 = arr.face(s, s1, s2, phi)
        P = p * n + (p1 / t1) * 1j * n
        rho = p + (p2 * t1 - p1 * t2) / t1**3
        if arr.oscillating:  # the face's point nearest the cam's centre, its foot
            g = np.pi / 2 + arr.tau * (arr.psi0 + s)
            B = p * (np.cos(g) + 1j * np.sin(g))
            pitch, pitch1 = p * n, np.zeros_like(P)
        else:
            B = arr.e + 1j * (arr.r0 + s)
            pitch, pitch1, _ = in_cam_frame(B, 1j * s1, 1j * s2, phi, sig)
        with np.errstate(divide="ignore"):
            k = 1.0 / rho
        return Curves(phi, s, s1, s2, s3, B, pitch, pitch1, k, P, k, alpha)
    B, B1, B2 = arr.pitch(s, s1, s2)
    R, R1, R2 = in_cam_frame(B, B1, B2, phi, sig)
    speed = np.abs(R1)
    kappa = -sig * cross(R1, R2) / speed**3
    rr = arr.follower.roller
    if rr:
        n = -sig * 1j * R1 / speed
        P = R + rr * n
        with np.errstate(divide="ignore", invalid="ignore"):
            kp = kappa / (1.0 - rr * kappa)
    else:
        P, kp = R, kappa
    return Curves(phi, s, s1, s2, s3, B, R, R1, kappa, P, kp, alpha)
