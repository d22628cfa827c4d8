"""The equilibrium of each kind of class-II group and of the driving link, one function per
kind, on complex numbers: Python numbers at one crank position, numpy arrays over many.
The single position's force plans (:mod:`plans.forces.analysis`) and the cycle's sweep
(:mod:`plans.forces.sweep`) share them, as the kinematics' paths share their kernels.

Loads reach a kernel as the resultant F (N, complex) of each link's loads and their
moment about a named point (N·m, counter-clockwise positive), so that a kernel never
divides by anything but the construction's own sine. A force of link i on link j is
written R_ij; ``a`` and ``b`` are the group's two links as :class:`plans.model.structure.Group`
names them. Each reaction is found as the textbook finds it:

    RRR  R_Pa = R^τ + R^n: R^τ from link a's moments about C (R^τ·l_PC = M_C(a)), the same
         for link b; the polygon R^τ_Pa + F_a + F_b + R^τ_Qb + R^n_Qb + R^n_Pa = 0 closed by
         two lines ∥ PC and ∥ QC; R_ba = −(R_Pa + F_a).
    RRP  R^τ_Pa as above; the polygon R^τ_Pa + F_a + F_b + N + R^n_Pa = 0 closed by a line
         ⊥ the guide (N, the guide's force on the slider) and a line ∥ PC; N acts s from C
         along the guide, s·ν = −M_C(b).
    RPR  the guide's force on the block N ⊥ the guide from the group's moments about Q:
         ν·(QP·u) = M_Q(b) + M_P(a); it acts s from P, s·ν = −M_P(a); R_Pa = −F_a − N and
         R_Qb = N − F_b, the closing vector of the polygon.
    PRP  F_a + F_b + N1 + N2 = 0 closed by two lines ⊥ the two guides; each N acts s from C
         along its guide, s·ν = −M_C(link); R_ba = −(F_a + N1).
    RPP  link b: F_b − N_ba + N_kb = 0 closed by lines ⊥ the inner and ⊥ the outer guide;
         R_Pa = −F_a − N_ba; N_ba acts s1 from P along the inner guide (s1·ν1 = −M_P(a)).

The force a group puts back on a link solved before it is given as a force through a
point and a couple (:attr:`back`), never through a point found by dividing by a normal
force that may be 0.
"""

from __future__ import annotations

from typing import NamedTuple

from plans.geometry import cross, meet


class Back(NamedTuple):
    """A force that a group puts on a link solved before it (the negative of the
    reaction that link gives the group): through ``at`` with an added couple (N·m)."""

    link: int
    name: str  # the reaction on the known link, e.g. "R21"
    other: int  # the group's link that puts it there
    at: object
    force: object
    moment: object


class RRR(NamedTuple):
    e_a: object  # unit vectors P→C, Q→C (the lines of R^n) and i·e (of R^τ)
    e_b: object
    tau_a: object  # R^τ_Pa, R^τ_Qb along i·e_a, i·e_b
    tau_b: object
    n_a: object  # R^n_Pa, R^n_Qb along e_a, e_b
    n_b: object
    R_P: object  # on a at P, on b at Q, of b on a at C
    R_Q: object
    R_C: object
    sine: object  # between the two closing lines


class RRP(NamedTuple):
    e_a: object
    w: object  # i·u: the line of N, ⊥ the guide
    tau_a: object
    n_a: object
    nu: object  # N = ν·w, the guide's force on the slider
    R_P: object
    N: object
    R_C: object
    m_b: object  # M_C(b): the couple N puts about C (s·ν = −m_b)
    sine: object


class RPR(NamedTuple):
    w: object  # i·u, ⊥ the guide of link b
    nu: object  # N = ν·w: link b's force on the block
    N: object
    R_P: object  # on the block at P, on b at Q
    R_Q: object
    m_a: object  # M_P(a): s·ν = −m_a
    sine: object  # QP·u / |QP|


class PRP(NamedTuple):
    w1: object
    w2: object
    nu1: object
    nu2: object
    N1: object  # guide 1 on a, guide 2 on b
    N2: object
    R_C: object  # b on a at C
    m_a: object  # M_C(a), M_C(b): s·ν = −m
    m_b: object
    sine: object


class RPP(NamedTuple):
    ws: object  # ⊥ the inner guide (carried by b), ⊥ the outer guide (carried by k)
    w: object
    nu1: object
    nu2: object
    N_ba: object  # b on the block, k on b
    N_kb: object
    R_P: object
    m_a: object  # M_P(a): s1·ν1 = −m_a
    couple: object  # s2·ν2: N_kb's moment about B0
    sine: object


def rrr(P, C, Q, F_a, MC_a, F_b, MC_b) -> RRR:
    """Link a = PC, link b = QC; loads F, moments about C."""
    e_a, e_b = C - P, C - Q
    l_a, l_b = abs(e_a), abs(e_b)
    e_a, e_b = e_a / l_a, e_b / l_b
    tau_a, tau_b = MC_a / l_a, MC_b / l_b
    known = F_a + F_b + 1j * (tau_a * e_a + tau_b * e_b)
    sine = cross(e_a, e_b)
    t1, t2 = meet(-known, e_a, e_b, 1.0 / sine)
    n_a, n_b = t1, -t2
    R_P = (n_a + 1j * tau_a) * e_a
    R_Q = (n_b + 1j * tau_b) * e_b
    return RRR(e_a, e_b, tau_a, tau_b, n_a, n_b, R_P, R_Q, -(R_P + F_a), sine)


def rrp(P, C, u, F_a, MC_a, F_b, MC_b) -> RRP:
    """Link a = PC; slider b at C on a guide of direction u."""
    e_a = C - P
    l_a = abs(e_a)
    e_a = e_a / l_a
    tau_a = MC_a / l_a
    w = 1j * u
    known = F_a + F_b + 1j * tau_a * e_a
    sine = cross(e_a, w)
    t1, t2 = meet(-known, e_a, w, 1.0 / sine)
    n_a, nu = t1, -t2
    R_P = (n_a + 1j * tau_a) * e_a
    N = nu * w
    return RRP(e_a, w, tau_a, n_a, nu, R_P, N, -(R_P + F_a), MC_b, sine)


def rpr(P, Q, u, F_a, MP_a, F_b, MQ_b) -> RPR:
    """Block a hinged at P slides along the guide (direction u) of link b hinged at Q;
    block's moments about P, link b's about Q."""
    w = 1j * u
    QP = P - Q
    d = cross(QP, w)  # = QP·u: the arm of N about Q
    nu = (MQ_b + MP_a) / d
    N = nu * w
    return RPR(w, nu, N, -F_a - N, N - F_b, MP_a, d / abs(QP))


def prp(C, u1, u2, F_a, MC_a, F_b, MC_b) -> PRP:
    """Link a on guide 1 (u1), link b on guide 2 (u2), hinged together at C."""
    w1, w2 = 1j * u1, 1j * u2
    sine = cross(w1, w2)
    t1, t2 = meet(-(F_a + F_b), w1, w2, 1.0 / sine)
    nu1, nu2 = t1, -t2
    N1, N2 = nu1 * w1, nu2 * w2
    return PRP(w1, w2, nu1, nu2, N1, N2, -(F_a + N1), MC_a, MC_b, sine)


def rpp(P, B0, us, u, F_a, MP_a, F_b, MB0_b) -> RPP:
    """Block a hinged at P slides along the inner guide (us) carried by b; b slides along
    the outer guide (u, through B0)."""
    ws, w = 1j * us, 1j * u
    sine = cross(ws, w)
    t1, t2 = meet(-F_b, ws, w, 1.0 / sine)
    nu1, nu2 = -t1, -t2
    N_ba, N_kb = nu1 * ws, nu2 * w
    # b about B0: (P + s1·us − B0) × (−N_ba) + s2·ν2 + M_B0(b) = 0, with s1·ν1 = −M_P(a)
    couple = cross(P - B0, N_ba) - MP_a - MB0_b
    return RPP(ws, w, nu1, nu2, N_ba, N_kb, -F_a - N_ba, MP_a, couple, sine)


def crank(pivot, F, MO):
    """The driving link: its loads' resultant F and their moment about its pivot (the
    groups' forces on it included). Returns (M_у, R_01): the balancing moment that holds it
    and the frame's force on it at the pivot."""
    return -MO, -F


def resultant(terms):
    """Σ F of a link's loads: ``terms`` are (at, force, couple) triples."""
    out = 0j
    for _, f, _ in terms:
        out = out + f
    return out


def moment(terms, X):
    """Σ M_X of a link's loads: Σ (at − X) × F + Σ couples (N·m, counter-clockwise)."""
    out = 0.0
    for at, f, m in terms:
        out = out + cross(at - X, f) + m
    return out
