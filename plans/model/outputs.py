"""The output of a mechanism: the point whose stroke or swing the cycle measures.

An output is the point of a slider on a fixed guide (its travel along the guide), or a
moving point of a link hinged to the frame other than the crank (its swing): the
topology of the mechanism decides which points can be one, and the file may name one.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from plans.model.mechanism import Mechanism


@dataclass(frozen=True)
class Output:
    """The output coordinate: a slider's travel along its fixed guide (m) or a rocker's
    angle (rad)."""

    point: str
    kind: str  # "linear" or "angular"
    link: int

    def value(self, m, mech: Mechanism):
        """The output's coordinate over the motion ``m`` (a
        :class:`plans.kinematics.Motion`): its travel (m) or its angle (rad, unwrapped)."""
        if self.kind == "linear":
            g = mech.slider_of(self.link).guide
            return ((m.position[self.point] - g.point) * np.conj(g.direction)).real
        psi = np.angle(m.links[self.link].rotor)
        known = np.isfinite(psi)
        if np.ndim(psi) == 0 or known.all():
            return np.unwrap(psi)
        out = np.full(psi.shape, np.nan)  # one position where the link is nowhere: not the rest
        out[known] = np.unwrap(psi[known])
        return out

    def arm(self, mech: Mechanism) -> tuple[str, str] | None:
        """A rocker's fixed pivot and its point farthest from it, the two the swing ψ is
        measured by (∠C′DC″ between its extreme positions: the sheet's arc and the note's
        angle alike); None for a slider, or a rocker with no fixed point."""
        if self.kind != "angular":
            return None
        link = mech.links[self.link]
        pivot = next((p for p in link.points if p in mech.frame), None)
        others = [p for p in link.points if p != pivot]
        if pivot is None or not others:
            return None
        return pivot, max(others, key=lambda p: abs(link.points[p] - link.points[pivot]))

    def rate(self, m, mech: Mechanism, which: str = "velocity"):
        """The output's velocity (m/s or rad/s), or with ``which`` "acceleration" its
        acceleration, over the motion ``m``."""
        data = m.velocity if which == "velocity" else m.acceleration
        if self.kind == "linear":
            g = mech.slider_of(self.link).guide
            return (data[self.point] * np.conj(g.direction)).real
        st = m.links[self.link]
        return st.omega if which == "velocity" else st.epsilon


def find_output(mech: Mechanism) -> Output | None:
    """The output named in the file, else the last slider on a fixed guide, else the last
    link hinged to the frame (a rocker), named by its moving joint (C of a rocker DC, as
    the textbook's ψ_C), never by its fixed pivot."""
    for name in ([mech.output] if mech.output else []) + outputs(mech):
        if (out := output_of(mech, name)) is not None:
            return out
    return None


def outputs(mech: Mechanism) -> list[str]:
    """Every point that can be the output (:func:`output_of`), in the order
    :func:`find_output` takes them: the sliders' points on fixed guides, the last first,
    then the points of each link from the last, a rocker's by its moving joints first
    (the far end of its axis, then the points it shares with other links)."""
    names = [s.point for s in reversed(mech.sliders)
             if s.guide.link == 0 and output_of(mech, s.point) is not None]
    for lid in sorted(mech.links, reverse=True):
        link = mech.links[lid]
        far = [link.axis[1]] if link.axis else []
        joints = [p for p in link.points if len(mech.links_of(p)) > 1]
        for p in far + joints + list(link.points):
            if (out := output_of(mech, p)) is not None and out.link == lid:
                names.append(p)
    return list(dict.fromkeys(names))


def no_output(mech: Mechanism, name: str) -> str | None:
    """Why point ``name`` cannot be the output, naming the points of ``mech`` that can
    (:func:`outputs`); None if it can. A coupler's point traces a curve, with no stroke
    along a line nor swing about a pivot: it is refused, as a fixed point and the
    crank's are."""
    if output_of(mech, name) is not None:
        return None
    carriers = mech.links_of(name)
    if 0 in carriers:
        what = "it is a fixed point"
    elif mech.driver.link in carriers:
        what = "it is a point of the crank"
    else:
        links = " and ".join(f"link {lid}" for lid in carriers)
        what = (f"it is a point of {links}, which neither "
                f"{'slides' if len(carriers) == 1 else 'slide'} on a fixed guide nor "
                f"{'turns' if len(carriers) == 1 else 'turn'} about a fixed pivot")
    names = [f'"{p}"' for p in outputs(mech)]
    here = ("here " + (names[0] if len(names) == 1 else
                       ", ".join(names[:-1]) + " or " + names[-1])) if names else \
        "this mechanism has none"
    return (f'"{name}" has no stroke or swing: {what}; the output is the point of a slider '
            "on a fixed guide or a moving point of a rocker (a link other than the crank "
            f"hinged to the frame): {here}")


def output_of(mech: Mechanism, name: str) -> Output | None:
    """Point ``name`` as the output: the point of a slider on a fixed guide, or any point
    of a link that only translates along one (its travel), or a moving point of a link
    hinged to the frame other than the crank (its swing); None for any other point (a
    fixed one, the crank's, a coupler's), which has no stroke. A rocker hinged to a
    support that an input slider carries along a fixed guide (seed 003) swings too: its
    angle is its output."""
    if name in mech.frame:  # it stands still: no stroke, no swing of its own
        return None
    still = mech.translating()
    inputs = {d.link for d in mech.drivers}
    for lid in mech.links_of(name):
        if lid == 0 or lid in inputs:
            continue
        s = mech.slider_of(lid)
        if s is not None and s.guide.link == 0 and (s.point == name or lid in still):
            return Output(name, "linear", lid)  # a yoke's every point travels as its slider does
        if any(p in mech.frame for p in mech.links[lid].points):
            return Output(name, "angular", lid)
        if any(p in mech.links[d.link].points for d in mech.drivers if d.linear
               for p in mech.links[lid].points):
            return Output(name, "angular", lid)  # a rocker whose support an input carries
    return None
