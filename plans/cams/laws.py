"""The follower's motion laws over one phase, in closed form and normalised.

A phase of cam angle β moves the follower through its stroke h (or its swing ψ_max):
with u = φ/β running from 0 to 1 over the phase,

    s = h·f(u),   ds/dφ = h·f′(u)/β,   d²s/dφ² = h·f″(u)/β²,   d³s/dφ³ = h·f‴(u)/β³

(a return runs f backwards: s = h·(1 − f(u))). Each law gives f on the first half of a
symmetric phase, u ∈ [0, ½], as F(u) with its three derivatives; the whole phase follows
from it. An asymmetric phase accelerates over the share k of the phase and decelerates over
the rest, k = ratio/(1 + ratio) with ``ratio`` the acceleration part's angle to the
deceleration part's:

    f(u) = 2k·F(u/(2k))                     for u ≤ k,
    f(u) = 1 − 2(1 − k)·F((1 − u)/(2(1 − k)))   for u ≥ k,

which keeps s, ds/dφ and d²s/dφ² continuous at u = k wherever the symmetric law does so
at its middle (f″ = 0 there, for every law but the parabolic one), and with k = ½ is the
symmetric law itself (F(½ + t) = 1 − F(½ − t)).

The laws, as Artobolevsky, 孙桓 and Norton name them: constant velocity (rigid impacts at
both ends), constant acceleration and deceleration (parabolic: soft impacts at the ends
and the middle), cosine acceleration (simple harmonic: soft impacts at the ends), sine
acceleration (cycloidal: none), the 3-4-5 and 4-5-6-7 polynomials (none) and the modified
trapezoid (none). Every function takes numpy arrays, complex ones too (the tests
differentiate by complex step).

>>> f, f1, f2, f3 = unit("cosine", np.array([0.0, 0.5, 1.0]))
>>> [round(float(x), 12) for x in f], [round(float(x), 12) for x in f2]
([0.0, 0.5, 1.0], [4.934802200545, 0.0, -4.934802200545])
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

__all__ = ["LAWS", "MT_PEAK", "Law", "law_named", "unit", "unit_half"]

#: the modified trapezoid's peak of f″: its acceleration rises as a quarter sine over
#: the first eighth of the phase, holds for a quarter, falls as a quarter sine over the
#: next eighth (then the same, negative, backwards); f(½) = ½ gives
#: C·(1/(8π) + 1/16) = ½, C = 8π/(2 + π) = 4.888…, and its peak f′ is 2
MT_PEAK = 8.0 * math.pi / (2.0 + math.pi)


@dataclass(frozen=True, slots=True)
class Law:
    """A motion law: its key in a cam file, its names, and the impacts it causes at its
    ends after a dwell, as the textbooks class them ("rigid", "soft", "none")."""

    key: str
    en: str
    ru: str
    impacts: str
    #: the formula of s over a rise, as the note writes it (u = φ/β)
    formula: str

    def name(self, lang: str = "en") -> str:
        return getattr(self, lang, self.en) if lang in ("en", "ru") else self.en


LAWS: dict[str, Law] = {law.key: law for law in (
    Law("constant velocity", "constant velocity", "равномерный (постоянной скорости)", "rigid",
        "s = h·φ/β"),
    Law("parabolic", "constant acceleration and deceleration (parabolic)",
        "равноускоренный и равнозамедленный (параболический)", "soft",
        "s = 2h·(φ/β)² for φ ≤ β/2;  s = h − 2h·(1 − φ/β)² for φ ≥ β/2"),
    Law("cosine", "cosine acceleration (simple harmonic)", "косинусоидальный (гармонический)", "soft",
        "s = h·(1 − cos(π·φ/β))/2"),
    Law("cycloidal", "sine acceleration (cycloidal)", "синусоидальный (циклоидальный)", "none",
        "s = h·(φ/β − sin(2π·φ/β)/(2π))"),
    Law("3-4-5", "3-4-5 polynomial", "полином 3-4-5", "none",
        "s = h·(10u³ − 15u⁴ + 6u⁵), u = φ/β"),
    Law("4-5-6-7", "4-5-6-7 polynomial", "полином 4-5-6-7", "none",
        "s = h·(35u⁴ − 84u⁵ + 70u⁶ − 20u⁷), u = φ/β"),
    Law("modified trapezoid", "modified trapezoid", "модифицированный трапецеидальный", "none",
        "f″ = C·sin 4πu (u ≤ ⅛), C (⅛ ≤ u ≤ ⅜), C·cos 4π(u − ⅜) (⅜ ≤ u ≤ ½), C = 8π/(2 + π)"),
)}

#: other spellings a cam file may use for a law, and the key they stand for
ALIASES = {
    "uniform": "constant velocity", "linear": "constant velocity",
    "constant acceleration": "parabolic",
    "simple harmonic": "cosine", "harmonic": "cosine",
    "sine": "cycloidal",
    "345": "3-4-5", "4567": "4-5-6-7",
    "trapezoid": "modified trapezoid", "modified trapezoidal": "modified trapezoid",
}


def law_named(name: str) -> Law | None:
    """The law a cam file names (its key or another spelling), or None.

    >>> law_named("Simple harmonic").key, law_named("sine").key, law_named("spline")
    ('cosine', 'cycloidal', None)
    """
    key = " ".join(str(name).lower().replace("_", " ").split())
    key = ALIASES.get(key, key)
    return LAWS.get(key)


def _where(mask, a, b):
    return np.where(mask, a, b)


def unit_half(key: str, u):
    """F(u), F′(u), F″(u), F‴(u) of the law ``key`` on the first half of a symmetric
    phase, u ∈ [0, ½] (arrays, real or complex; pieces chosen by the real part).

    >>> [float(x) for x in unit_half("modified trapezoid", np.array(0.5))[:2]]
    [0.5, 2.0]
    """
    u = np.asarray(u)
    one, zero = np.ones_like(u), np.zeros_like(u)
    if key == "constant velocity":
        return u, one, zero, zero
    if key == "parabolic":
        return 2.0 * u * u, 4.0 * u, 4.0 * one, zero
    if key == "cosine":
        a = math.pi * u
        return ((1.0 - np.cos(a)) / 2.0, math.pi / 2.0 * np.sin(a), math.pi**2 / 2.0 * np.cos(a),
                -(math.pi**3) / 2.0 * np.sin(a))
    if key == "cycloidal":
        a = 2.0 * math.pi * u
        return (u - np.sin(a) / (2.0 * math.pi), 1.0 - np.cos(a), 2.0 * math.pi * np.sin(a),
                4.0 * math.pi**2 * np.cos(a))
    if key == "3-4-5":
        return (u**3 * (10.0 - 15.0 * u + 6.0 * u * u), 30.0 * u * u * (1.0 - u) ** 2,
                60.0 * u * (1.0 - 3.0 * u + 2.0 * u * u), 60.0 - 360.0 * u + 360.0 * u * u)
    if key == "4-5-6-7":
        return (u**4 * (35.0 - 84.0 * u + 70.0 * u * u - 20.0 * u**3),
                140.0 * u**3 * (1.0 - u) ** 3,
                420.0 * u * u * (1.0 - u) ** 2 * (1.0 - 2.0 * u),
                840.0 * u * (1.0 - u) * (1.0 - 5.0 * u + 5.0 * u * u))
    if key == "modified trapezoid":
        return _modified_trapezoid(u)
    raise KeyError(key)


def _modified_trapezoid(u):
    """The modified trapezoid on [0, ½]: f″ = C·sin 4πu, then C, then C·cos 4π(u − ⅜),
    each piece integrated in closed form from the values where the last ended."""
    C, w = MT_PEAK, 4.0 * math.pi
    # piece 1, u ≤ ⅛
    a1 = w * u
    f_1 = C / w * (u - np.sin(a1) / w)
    v_1 = C / w * (1.0 - np.cos(a1))
    j1 = C * w * np.cos(a1)
    acc1 = C * np.sin(a1)
    s_a, v_a = C / w * (0.125 - 1.0 / w), C / w  # at u = ⅛
    # piece 2, ⅛ ≤ u ≤ ⅜
    t = u - 0.125
    f_2 = s_a + v_a * t + C * t * t / 2.0
    v_2 = v_a + C * t
    s_b, v_b = s_a + v_a * 0.25 + C / 32.0, v_a + C / 4.0  # at u = ⅜
    # piece 3, ⅜ ≤ u ≤ ½
    t3 = u - 0.375
    a3 = w * t3
    f_3 = s_b + v_b * t3 + C / (w * w) * (1.0 - np.cos(a3))
    v_3 = v_b + C / w * np.sin(a3)
    acc3 = C * np.cos(a3)
    j3 = -C * w * np.sin(a3)
    r = np.real(u)
    first, middle = r <= 0.125, r <= 0.375
    f = _where(first, f_1, _where(middle, f_2, f_3))
    f1 = _where(first, v_1, _where(middle, v_2, v_3))
    f2 = _where(first, acc1, _where(middle, C * np.ones_like(u), acc3))
    f3 = _where(first, j1, _where(middle, np.zeros_like(u), j3))
    return f, f1, f2, f3


def unit(key: str, u, k: float = 0.5, side: str = "right"):
    """f(u), f′(u), f″(u), f‴(u) of a rise by the law ``key`` over u ∈ [0, 1], its
    acceleration over the share ``k`` of the phase (½: symmetric). At u = k itself the
    acceleration part is taken with ``side="left"``, the deceleration part with "right".

    >>> f, f1, f2, f3 = unit("parabolic", np.array([0.25, 0.5, 0.75]), k=0.5)
    >>> [float(x) for x in f], [float(x) for x in f2]
    ([0.125, 0.5, 0.875], [4.0, -4.0, -4.0])
    >>> [float(x) for x in unit("parabolic", np.array(0.5), side="left")[2:3]]
    [4.0]
    """
    u = np.asarray(u)
    r = np.real(u)
    first = r <= k if side == "left" else r < k
    a = u / (2.0 * k)
    b = (1.0 - u) / (2.0 * (1.0 - k))
    A, A1, A2, A3 = unit_half(key, a)
    B, B1, B2, B3 = unit_half(key, b)
    f = _where(first, 2.0 * k * A, 1.0 - 2.0 * (1.0 - k) * B)
    f1 = _where(first, A1, B1)
    f2 = _where(first, A2 / (2.0 * k), -B2 / (2.0 * (1.0 - k)))
    f3 = _where(first, A3 / (4.0 * k * k), B3 / (4.0 * (1.0 - k) ** 2))
    return f, f1, f2, f3
