"""Where the follower stands: its displacement s turned into points of the plane, its
pressure angle, and the cam's frame of the inversion.

Points are complex numbers, x + iy, in metres: the cam's centre O at 0, the follower above
it, moving up (translating) or swinging about its pivot A (oscillating). The cam turns
at σω (σ = +1 counter-clockwise); the follower's pitch point B (the knife's edge, the
roller's centre) is fixed by s alone:

    translating, axis at x = e:   B = e + i(s0 + s),  s0 = √(r0² − e²);
    oscillating, pivot A:         B = A + l·w,  w = τ·exp(iτΨ),  Ψ = Ψ0 + ψ,

where Ψ is the angle OAB, Ψ0 its value on the base circle (cos Ψ0 = (a² + l² − r0²)/(2al)),
τ the sense the arm turns on rise (σ where it turns with the cam, −σ against it) and
A = −τa on the x-axis. A flat face stands ⊥ the axis at s0 + s = r0 + s above O, or runs
through the pivot along the arm (its distance from O is a·sin Ψ).

Inversion (обращение движения, 反转法): hold the cam still and turn everything else by −σφ;
a point X of the fixed frame is X·exp(−iσφ) in the cam's. The pitch curve is the path of B
so turned.

>>> from plans.cams.camfile import Follower
>>> arr = Arrangement(Follower("knife-edge", stroke=0.016, offset=0.01), 1, 0.03, 0.01)
>>> round(arr.s0, 6), round(math.degrees(float(arr.pressure(0.0, 0.01))), 6)
(0.028284, 0.0)
"""

from __future__ import annotations

import math

import numpy as np

__all__ = ["Arrangement", "in_cam_frame"]


def in_cam_frame(X, X1, X2, phi, sigma: int):
    """A point X(φ) of the fixed frame and its first two derivatives in φ, seen from the
    cam: R = X·exp(−iσφ), R′ = (X′ − iσX)·exp(−iσφ), R″ = (X″ − 2iσX′ − X)·exp(−iσφ)."""
    turn = np.exp(-1j * sigma * phi) if not np.iscomplexobj(phi) else \
        np.cos(sigma * phi) - 1j * np.sin(sigma * phi)
    return X * turn, (X1 - 1j * sigma * X) * turn, (X2 - 2j * sigma * X1 - X) * turn


class Arrangement:
    """The follower of ``follower`` beside a cam turning ``sense`` (+1 ccw) whose base
    circle is ``r0`` (of the pitch curve; of the profile for a flat face), a translating
    follower's axis at ``offset`` e."""

    def __init__(self, follower, sense: int, r0: float, offset: float = 0.0):
        self.follower, self.sigma, self.r0 = follower, int(sense), float(r0)
        f = follower
        self.flat = f.flat
        self.oscillating = f.oscillating
        self.e = 0.0 if f.oscillating else float(offset)
        if not f.oscillating:
            self.s0 = r0 if f.flat else math.sqrt(r0 * r0 - self.e * self.e)
            self.psi0 = 0.0
            self.tau = 0
            self.A = 0j
        else:
            a, ell = f.centre, f.arm
            self.a, self.l = a, ell
            self.tau = self.sigma if f.with_cam else -self.sigma
            self.A = complex(-self.tau * a, 0.0)
            self.psi0 = (math.asin(r0 / a) if f.flat
                         else math.acos((a * a + ell * ell - r0 * r0) / (2.0 * a * ell)))
            self.s0 = 0.0

    # ---- the pitch point (knife-edge, roller) -------------------------------------
    def pitch(self, s, s1, s2):
        """B, dB/dφ, d²B/dφ² in the fixed frame."""
        if not self.oscillating:
            return self.e + 1j * (self.s0 + s), 1j * s1, 1j * s2
        W = self.arm_vector(s)
        it = 1j * self.tau
        return self.A + W, it * s1 * W, (it * s2 - s1 * s1) * W

    def arm_vector(self, s):
        """W = B − A = l·τ·exp(iτΨ) of an oscillating follower."""
        g = self.tau * (self.psi0 + np.asarray(s))
        return self.l * self.tau * (np.cos(g) + 1j * np.sin(g))

    def direction(self, s):
        """The unit direction the follower's point B moves in as s grows."""
        if not self.oscillating:
            return 1j + 0.0 * np.asarray(s)
        return 1j * self.tau * self.arm_vector(s) / self.l

    def pressure(self, s, s1):
        """The pressure angle α (rad), between the common normal at the contact and the
        velocity of the follower's point there:

            translating:   tan α = |s′ − σe| / (s0 + s);
            oscillating:   tan α = |l·(ψ′ − στ) + στ·a·cos Ψ| / (a·sin Ψ);
            flat face:     α = 0 (the face ⊥ the axis, or through the pivot)."""
        s, s1 = np.asarray(s), np.asarray(s1)
        if self.flat:
            return np.zeros(np.broadcast(s, s1).shape)
        if not self.oscillating:
            return np.arctan2(np.abs(s1 - self.sigma * self.e), self.s0 + s)
        st = self.sigma * self.tau
        psi = self.psi0 + s
        return np.arctan2(np.abs(self.l * (s1 - st) + st * self.a * np.cos(psi)), self.a * np.sin(psi))

    # ---- the flat face ------------------------------------------------------------
    def face(self, s, s1, s2, phi):
        """The flat face in the cam's frame as the line X·n = p, n = exp(iθ), with p, θ
        and their derivatives in φ: (n, p, p′, p″, θ′, θ″)."""
        s, s1, s2 = np.asarray(s), np.asarray(s1), np.asarray(s2)
        sig = self.sigma
        if not self.oscillating:
            theta = math.pi / 2 - sig * phi
            return (np.cos(theta) + 1j * np.sin(theta), self.r0 + s, s1, s2,
                    -sig + 0.0 * s, 0.0 * s)
        psi = self.psi0 + s
        a, tau = self.a, self.tau
        theta = math.pi / 2 + tau * psi - sig * phi
        return (np.cos(theta) + 1j * np.sin(theta), a * np.sin(psi), a * np.cos(psi) * s1,
                a * (np.cos(psi) * s2 - np.sin(psi) * s1 * s1), tau * s1 - sig, tau * s2)
