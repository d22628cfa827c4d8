"""Zhukovsky's lever (рычаг Жуковского): the velocity plan turned by 90°, every load
applied at the image of its point, the balancing force from the moments about the pole.

    Σ M_p(F_i) + M_p(F_у) = 0:  Σ ±F_i·h_i ± F_у·pb = 0,  h_i the arm of F_i (mm of the plan)

It is the principle of virtual power drawn (M_у·ω1 + Σ F·V + Σ M·ω = 0), so exact arms
give the groups' M_у to rounding; arms measured on paper to the millimetre, as a student
measures them, give it within a few per cent (:attr:`Lever.measured`).

A couple M on a link enters as two forces M/l ⊥ the link at the images of its two
joints (:func:`couple_pair`), as the textbook applies it.
"""

from __future__ import annotations

from typing import NamedTuple

from plans.forces.loads import Load
from plans.geometry import cross


class LeverTerm(NamedTuple):
    """One force on the lever: ``image`` where it acts (mm from the pole, on the plan turned
    by +90°), its arm about the pole (mm, ≥ 0) and its moment (N·mm, counter-clockwise
    positive)."""

    name: str
    point: str
    image: complex
    force: complex
    arm: float
    moment: float


class Lever(NamedTuple):
    terms: tuple[LeverTerm, ...]
    tip: str  # the crank pin, where F_у acts
    pb: float  # mm: the crank pin's image, the arm of F_у
    F_y: float  # N, positive where it turns the crank counter-clockwise
    M_y: float  # N·m: F_у·l_OA
    measured: float  # F_у with every arm rounded to the whole millimetre, as on paper
    mu_v: float

    @property
    def discrepancy(self) -> float:
        """How far the arms read to the millimetre put F_у off the exact lever (relative)."""
        return abs(self.measured - self.F_y) / abs(self.F_y) if self.F_y else 0.0


def couple_pair(link, moment: float, pos, a: str, b: str) -> list[tuple[str, complex, complex]]:
    """A couple ``moment`` (N·m) on a link as two forces ⊥ the line ab at its points a and
    b: (point, at, force), each of size |M|/|ab|, their moment M."""
    A, B = pos[a], pos[b]
    e = B - A
    length = abs(e)
    f = (moment / length) * 1j * (e / length)  # at b: (B − A) × f = M
    return [(b, B, f), (a, A, -f)]


def joints(mech, link: int) -> tuple[str, str] | None:
    """The two points of ``link`` a couple on it is applied at, as two forces: the ends of
    its axis, else its first two points; None for a link of one point (a block), whose
    couple enters the lever as its moment −M·ω/μv."""
    ln = mech.links[link]
    if ln.axis:
        return ln.axis
    names = list(ln.points)
    return (names[0], names[1]) if len(names) >= 2 else None


def lever(solution, loads: list[Load]) -> Lever:
    """The lever at the position of ``solution``, under ``loads``."""
    m = solution.scalar
    mu = solution.velocity.mu
    mech = solution.mechanism
    d = mech.driver
    terms: list[LeverTerm] = []

    def put(name, point, force):
        image = 1j * m.velocity[point] / mu
        size = abs(force)
        mo = cross(image, force)
        terms.append(LeverTerm(name, point, image, complex(force), abs(mo) / size if size else 0.0, mo))

    for ld in loads:
        if ld.point is not None and ld.force != 0:
            put(ld.name, ld.point, ld.force)
        if ld.moment:
            ends = joints(mech, ld.link)
            if ends is None:
                mo = -ld.moment * m.links[ld.link].omega / mu
                terms.append(LeverTerm(ld.name, "", 0j, 0j, 0.0, mo))
                continue
            for point, _, force in couple_pair(ld.link, ld.moment, m.position, *ends):
                put(f"{ld.name}({point})", point, force)
    total = sum(t.moment for t in terms)
    tip = m.velocity[d.tip]
    pb = abs(tip) / mu
    l_crank = abs(m.position[d.tip] - m.position[d.pivot])
    # F_у ⊥ the crank at its pin, positive counter-clockwise: its moment about the pole is
    # −F_у·pb·sign(ω1) (see the module's docstring), and the lever's sum vanishes
    sense = 1.0 if d.omega > 0 else -1.0
    F_y = total / (pb * sense)
    rounded = sum(
        round(t.arm) * (1 if t.moment > 0 else -1) * abs(t.force) if t.force else t.moment for t in terms
    )
    measured = rounded / (round(pb) * sense) if round(pb) else F_y
    return Lever(tuple(terms), d.tip, pb, F_y, F_y * l_crank, measured, mu)
