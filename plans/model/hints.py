"""Assembly hints, as a file writes them: "above BD", "right of C".

A group that closes two ways (a coupler's end above or below the line of its pivots, a
slider on either side) is told by a hint on its new point: the side of a point or of the
line through two points it lies on. This is the hints' grammar and the geometry of a
side; which assembly a hint picks is :mod:`plans.kinematics.branches`'s.
"""

from __future__ import annotations

from plans import tolerances
from plans.geometry import cross

RELATIONS = ("above", "below", "left of", "right of")


def parse_hint(hint: str, names: list[str]) -> tuple[str, list[str]]:
    """``"above BD"`` → ("above", ["B", "D"]); ``"right of C"`` → ("right of", ["C"])."""
    text = " ".join(hint.strip().split())
    for rel in RELATIONS:
        if text.startswith(rel + " "):
            rest = text[len(rel) + 1 :].replace("line ", "").replace("-", "").replace(" ", "")
            refs: list[str] = []
            while rest:
                match = max((n for n in names if rest.startswith(n)), key=len, default=None)
                if match is None:
                    raise ValueError(f'"{rest}" is not a point name')
                refs.append(match)
                rest = rest[len(match) :]
            if len(refs) not in (1, 2):
                raise ValueError("name one point or a line through two points")
            return rel, refs
    raise ValueError('a hint reads "above BD", "below BD", "left of C" or "right of C"')


class Ambiguous(ValueError):
    """A hint whose line stands across the sides it names ("above" a vertical line)."""


def hint_holds(rel: str, X: complex, refs: list[complex]) -> bool:
    """Whether X lies on the side ``rel`` of the point or line ``refs``; a point on the
    line (or level with the point) to rounding, :data:`plans.tolerances.ON_LINE` of the distances, lies
    on neither side: an assembly must not be picked by the sign of rounding."""
    if len(refs) == 1:
        Q = refs[0]
        off = X - Q
        across = off.imag if rel in ("above", "below") else off.real
        if abs(across) <= tolerances.ON_LINE * (abs(X) + abs(Q)):
            return False
        return across > 0 if rel in ("above", "right of") else across < 0
    Q, R = refs
    d = R - Q
    across = d.real if rel in ("above", "below") else d.imag
    if abs(across) < tolerances.UPRIGHT * abs(d):
        raise Ambiguous("vertical" if rel in ("above", "below") else "horizontal")
    if (d.real < 0) if rel in ("above", "below") else (d.imag < 0):
        d = -d
    side = cross(d, X - Q)
    if abs(side) <= tolerances.ON_LINE * abs(d) * (abs(X - Q) + abs(d)):
        return False
    return (side > 0) == (rel in ("above", "left of"))
