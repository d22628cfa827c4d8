"""The formulas of the five dyad kinds: one function per kind, shared by every path.

Each kernel takes the known points of its group (world position, velocity and
acceleration as complex numbers) and the motion of any guide it slides on, and returns
the new point's position, velocity and acceleration, the ω and ε of its links, and the
pieces of the construction (line directions, line parameters, normal and Coriolis terms,
the sine between the two lines). Three callers share them, so they cannot drift apart:

* :class:`plans.kinematics.Solver` records every construction over an array of angles;
* its one-angle path runs the same kernels on Python complex numbers (``SCALAR``),
  about twenty times faster than numpy on one-element arrays;
* :func:`plans.kinematics.sweep.sweep` runs them in cache-sized blocks for bulk work, keeping
  only the results.

``xp`` supplies the few non-arithmetic functions (square root, maximum, where, a complex
number from its two parts) for numpy arrays (``ARRAY``) or Python scalars (``SCALAR``);
everything else is operator arithmetic and ``.conjugate()``, ``.real``, ``.imag``, which
both kinds of value share.

A guide's link ``k`` enters as ``G, vG, aG, wk, ek``: a world point of the guide line,
that point's velocity and acceleration, and ω, ε of link k (zeros for the frame).
Unit direction vectors stay unit to rounding, so the cross product of two of them is
already the sine of the angle between them.
"""

from __future__ import annotations

import math
from typing import NamedTuple

import numpy as np

from plans import tolerances
from plans.geometry import cross, heron, meet

#: ``record(Cls, (field, …))``: a NamedTuple built from a tuple of all its fields, in
#: order. The records of a construction are made at every angle of the one-angle path,
#: where the class's own Python-level ``__new__`` takes twice as long.
record = tuple.__new__



class _Array:
    scalar = False
    sqrt = staticmethod(np.sqrt)
    maximum = staticmethod(np.maximum)
    where = staticmethod(np.where)

    @staticmethod
    def cplx(re, im):
        """re + i·im without numpy's two casts of a real array to complex."""
        out = np.empty(np.broadcast(re, im).shape, dtype=complex)
        out.real = re
        out.imag = im
        return out


class _Scalar:
    scalar = True
    sqrt = staticmethod(math.sqrt)
    maximum = staticmethod(max)

    @staticmethod
    def where(cond, a, b):
        return a if cond else b

    cplx = staticmethod(complex)


ARRAY = _Array()
SCALAR = _Scalar()


class RRR(NamedTuple):
    C: object  # the new hinge, its velocity and acceleration
    vC: object
    aC: object
    w2: object  # ω, ε of the link P–C and of the link Q–C
    e2: object
    w3: object
    e3: object
    d1: object  # the two lines' directions, ⊥ CP and ⊥ CQ
    d2: object
    t1: object  # velocity parameters along d1, d2
    t2: object
    s1: object  # acceleration parameters along d1, d2 (the tangential components)
    s2: object
    nP: object  # normal components a^n_CP, a^n_CQ
    nQ: object
    sine: object  # between the two lines
    closes: object  # the links reach: |PQ| within [|l2 − l3|, l2 + l3]
    d: object  # |PQ|


class RRP(NamedTuple):
    C: object
    vC: object
    aC: object
    w2: object
    e2: object
    d1: object  # ⊥ CP; the other line is the guide
    t1: object
    t2: object
    s1: object
    s2: object
    nP: object
    vCk: object  # velocity and acceleration of the guide's point under C
    aCk: object
    cor: object  # a^k of the slide (None on a fixed guide)
    sine: object
    closes: object  # the distance h of P from the guide is at most l2
    h: object


class RPR(NamedTuple):
    rot: object  # the rocker's rotor and the guide's world direction
    u: object
    vP3: object  # the rocker's point under the block
    aP3: object
    w3: object
    e3: object
    d2: object  # ⊥ QP3; the other line is the guide
    t1: object
    t2: object
    s1: object
    s2: object
    cor: object
    nQ: object
    sine: object
    closes: object  # the block is farther from the pivot than the guide's offset
    dist: object


class PRP(NamedTuple):
    C: object
    vC: object
    aC: object
    v1: object  # the guides' points under C
    v2: object
    a1: object
    a2: object
    c1: object  # a^k of each slide (None on a fixed guide)
    c2: object
    t1: object
    t2: object
    s1: object
    s2: object
    sine: object
    closes: object  # the guides are not parallel


class RPP(NamedTuple):
    oB: object  # the yoke's origin and the inner guide's world direction
    us: object
    vP3: object
    aP3: object
    vk: object  # the outer guide's point under the block
    ak: object
    c1: object
    c2: object
    t1: object
    t2: object
    s1: object
    s2: object
    sine: object
    closes: object  # always True: parallel guides are refused with the structure


def rrr(xp, sigma, l2, l3, P, vP, aP, Q, vQ, aQ):
    """C on link 2 (|PC| = l2) and link 3 (|QC| = l3), on the side ``sigma`` of P→Q.

    V_C = V_P + V_CP (⊥ CP) = V_Q + V_CQ (⊥ CQ);
    a_C = a_P + a^n_CP + a^t_CP = a_Q + a^n_CQ + a^t_CQ.
    """
    w = Q - P
    d = abs(w)
    disc = heron(l2, l3, d)
    dd = d * d
    k = 0.5 / dd
    root = xp.sqrt(xp.maximum(disc, 0.0))  # 2·d·h, h the height of C over PQ
    # C = P + (along + i·σ·h)·w/d: along/d and σ·h/d formed as one complex number
    C = P + xp.cplx((l2 * l2 - l3 * l3 + dd) * k, root * (sigma * k)) * w
    rP, rQ = C - P, C - Q
    d1, d2 = rP * (1j / l2), rQ * (1j / l3)
    # the sine as the cross product of the two directions as rounded, not from the
    # triangle (d·h = l2·l3·|sin|): Cramer's rule below then solves for the very lines it
    # intersects, and the bench's largest error stays 2.6e-15, where the triangle's sine,
    # two passes cheaper, made it 4.6e-15
    sine = cross(d1, d2)
    inv = 1.0 / sine
    t1, t2 = meet(vQ - vP, d1, d2, inv)
    vC = vP + t1 * d1
    w2, w3 = t1 * (1 / l2), t2 * (1 / l3)
    nP, nQ = rP * -(w2 * w2), rQ * -(w3 * w3)
    k1 = aP + nP
    s1, s2 = meet((aQ + nQ) - k1, d1, d2, inv)
    aC = k1 + s1 * d1
    return record(RRR, (C, vC, aC, w2, s1 * (1 / l2), w3, s2 * (1 / l3), d1, d2, t1, t2, s1, s2,
               nP, nQ, sine, disc > 0, d))


def _guide_motion(C, G, vG, aG, wk, ek):
    """Velocity and acceleration of the point of the guide's link under C."""
    if wk is None:  # a guide on a link that never turns: all its points move as G does
        return vG, aG
    r = C - G
    return vG + r * (1j * wk), aG + r * (1j * ek - wk * wk)


def rrp(xp, sigma, l2, P, vP, aP, G, u, vG, aG, wk, ek):
    """C on link 2 (|PC| = l2) and on the guide G + t·u, ``sigma`` along u from the
    foot of P. ``wk`` is None for a guide on a link that never turns (the frame, a yoke
    on a fixed guide).

    V_C = V_P + V_CP (⊥ CP) = V_Ck + V_CCk (∥ guide);
    a_C = a_P + a^n_CP + a^t_CP = a_Ck + a^k_CCk + a^r_CCk.
    """
    w = P - G
    cw = w.conjugate() * u  # conj(w)·u: real part along u, imaginary part −(u × w)
    h = abs(cw.imag)
    disc = (l2 - h) * (l2 + h)
    C = G + (cw.real + sigma * xp.sqrt(xp.maximum(disc, 0.0))) * u
    rP = C - P
    d1 = rP * (1j / l2)
    sine = cross(d1, u)
    inv = 1.0 / sine
    vCk, aCk = _guide_motion(C, G, vG, aG, wk, ek)
    t1, t2 = meet(vCk - vP, d1, u, inv)
    vC = vP + t1 * d1
    w2 = t1 * (1 / l2)
    nP = rP * -(w2 * w2)
    cor = None if wk is None else u * (2j * wk * t2)
    known2 = aCk if cor is None else aCk + cor
    k1 = aP + nP
    s1, s2 = meet(known2 - k1, d1, u, inv)
    aC = k1 + s1 * d1
    return record(RRP, (C, vC, aC, w2, s1 * (1 / l2), d1, t1, t2, s1, s2, nP, vCk, aCk, cor, sine,
               disc > 0, h))


def rpr(xp, sigma, e, gd, P, vP, aP, Q, vQ, aQ):
    """The block at P slides on the guide of a link turning about Q; the guide runs at
    offset ``e`` from Q with local direction ``gd``. Returns the rocker's rotor too.

    V_P3 = V_P + V_P3P (∥ guide) = V_Q + V_P3Q (⊥ QP3);
    a_P3 = a_P + a^k_P3P + a^r_P3P = a_Q + a^n_P3Q + a^t_P3Q.
    """
    w = P - Q
    dist = abs(w)
    ae = abs(e)
    disc = (dist - ae) * (dist + ae)
    tau = sigma * xp.sqrt(xp.maximum(disc, 0.0))
    safe = xp.where(dist > 0, dist, 1.0)
    rot = w / ((tau + 1j * e) * gd)
    rot = rot / abs(rot)
    u = rot * gd
    d2 = w * (1j / safe)
    sine = cross(u, d2)
    inv = 1.0 / sine
    t1, t2 = meet(vQ - vP, u, d2, inv)
    vP3 = vP + t1 * u
    w3 = t2 / safe
    cor = u * (2j * w3 * t1)
    nQ = w * -(w3 * w3)
    k1 = aP + cor
    s1, s2 = meet((aQ + nQ) - k1, u, d2, inv)
    aP3 = k1 + s1 * u
    return record(RPR, (rot, u, vP3, aP3, w3, s2 / safe, d2, t1, t2, s1, s2, cor, nQ, sine,
               (disc > 0) & (dist > 0), dist))


def prp(xp, G1, u1, vG1, aG1, w1, e1, G2, u2, vG2, aG2, w2, e2):
    """C slides on two guides, each carried by a link (``w`` None where it never turns).

    V_C = V_C1 + V_CC1 (∥ guide 1) = V_C2 + V_CC2 (∥ guide 2).
    """
    sine = cross(u1, u2)
    inv = 1.0 / sine
    t, _ = meet(G2 - G1, u1, u2, inv)
    C = G1 + t * u1
    v1, a1 = _guide_motion(C, G1, vG1, aG1, w1, e1)
    v2, a2 = _guide_motion(C, G2, vG2, aG2, w2, e2)
    vC, aC, (c1, c2, t1, t2, s1, s2) = _two_slides(v1, a1, u1, w1, v2, a2, u2, w2, inv)
    return record(PRP, (C, vC, aC, v1, v2, a1, a2, c1, c2, t1, t2, s1, s2, sine,
                        abs(sine) > tolerances.SINGULAR_SINE))


def rpp(xp, P, vP, aP, G, u, vG, aG, wk, ek, locD, g0, gd):
    """The block at P slides along the inner guide (point g0, direction gd, local to the
    yoke B); the yoke slides along the outer guide G + t·u of link k through its own
    point ``locD``. Returns the yoke's origin too.

    V_P3 = V_P + V_P3P (∥ inner guide) = V_Pk + V_P3Pk (∥ outer guide).

    The two guides keep their angle at every crank angle, so parallel ones (gd.imag = 0)
    are refused with the structure (``plans.model.structure``); ``closes`` is always True.
    """
    z = (P - G) * u.conjugate() + (locD - g0)
    t = z.imag / gd.imag
    sl = z.real - t * gd.real
    oB = G + (sl - locD) * u
    us = u * gd
    sine = cross(us, u)
    inv = 1.0 / sine
    vk, ak = _guide_motion(P, G, vG, aG, wk, ek)
    # the block slides in the yoke, which turns as link k does (ω_k None: not at all)
    vP3, aP3, (c1, c2, t1, t2, s1, s2) = _two_slides(vP, aP, us, wk, vk, ak, u, wk, inv)
    return record(RPP, (oB, us, vP3, aP3, vk, ak, c1, c2, t1, t2, s1, s2, sine, True))


def _two_slides(v1, a1, u1, w1, v2, a2, u2, w2, inv):
    """Two sliding routes: from V1 along u1 and from V2 along u2, each carried by a
    link turning at ω (None: not turning, so no Coriolis term).

    V = V1 + t1·u1 = V2 + t2·u2;  a = a1 + a^k1 + s1·u1 = a2 + a^k2 + s2·u2,
    with a^k = 2ω × V_rel: the sliding velocity t·u turned by 90° in the sense of ω.
    """
    t1, t2 = meet(v2 - v1, u1, u2, inv)
    c1 = None if w1 is None else u1 * (2j * w1 * t1)
    c2 = None if w2 is None else u2 * (2j * w2 * t2)
    k1 = a1 if c1 is None else a1 + c1
    k2 = a2 if c2 is None else a2 + c2
    s1, s2 = meet(k2 - k1, u1, u2, inv)
    return v1 + t1 * u1, k1 + s1 * u1, (c1, c2, t1, t2, s1, s2)
