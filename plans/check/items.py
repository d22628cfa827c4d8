"""What the check speaks of: the three plans and their scale factors, the force plans and
Zhukovsky's lever, the tolerance, and one measured item (:class:`Item`), the words the rest
of the check is built on.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass

from plans.check.words import WORDS
from plans.fmt import num

PLANS = ("positions", "velocity", "acceleration")
MU_KEY = {"positions": "mu_l", "velocity": "mu_v", "acceleration": "mu_a"}
#: the scale factor of each plan as the note writes it
MU_SYMBOL = {"positions": "μl", "velocity": "μv", "acceleration": "μa"}
#: what the force analysis's items are on: the groups' force plans (mm at μF, and the
#: forces and moments in N, N·m) and Zhukovsky's lever (mm of the velocity plan at μv)
FORCE_PLANS = ("force", "lever")
#: the kinds of item whose value has a sense (counter-clockwise positive): ω, ε, a moment
#: and the balancing force F_у (positive where it turns the crank counter-clockwise)
SIGNED = ("omega", "epsilon", "moment", "balancing")


@dataclass(frozen=True, slots=True)
class Tolerance:
    """A deviation is within tolerance when it is at most the larger of ``mm`` (on the
    drawing) and ``percent`` of the computed length."""

    percent: float = 5.0
    mm: float = 1.0

    def limit(self, computed: float, per_mm: float = 1.0) -> float:
        """The allowed deviation of an item whose 1 mm of drawing is ``per_mm`` units."""
        return max(self.mm * per_mm, self.percent / 100.0 * abs(computed))

    def describe(self, lang: str = "en") -> str:
        """In words, e.g. "the larger of 1 mm and 5 %"."""
        return WORDS[lang]["tolerance"].format(mm=num(self.mm, 3, lang),
                                               percent=num(self.percent, 3, lang))


def parse_tolerance(text: str, base: Tolerance | None = None) -> Tolerance:
    """``"5%"``, ``"1.5mm"``, ``"3%,0.5mm"`` → :class:`Tolerance` (unnamed parts stay).

    >>> parse_tolerance("3%")
    Tolerance(percent=3.0, mm=1.0)
    >>> parse_tolerance("0.5 mm, 2 %")
    Tolerance(percent=2.0, mm=0.5)
    >>> parse_tolerance("5%,1mm,2mm")
    Traceback (most recent call last):
    ValueError: "5%,1mm,2mm" gives the mm part twice: give a percentage and a length at most
    once each, e.g. "5%,1mm"

    A number without its unit is refused, not read as a percentage (``5`` had silently
    been 5 %, where 5 mm may have been meant):

    >>> parse_tolerance("5")
    Traceback (most recent call last):
    ValueError: "5" has no unit: write "5%" for a percentage of the computed value or "5mm"
    for a length on the drawing
    """
    base = base or Tolerance()
    pct, mm = base.percent, base.mm
    token = r"(\d+(?:[.,]\d+)?)\s*(%|mm|мм)?"
    text = str(text).strip()
    if not re.fullmatch(rf"{token}(?:\s*[,;]?\s*{token})*", text):
        raise ValueError(f'"{text[:40]}" is not a tolerance (e.g. "5%", "1mm" or "5%,1mm")')
    seen: set[str] = set()
    for number, unit in re.findall(token, text):
        if not unit:
            raise ValueError(f'"{number[:20]}" has no unit: write "{number[:20]}%" for a percentage of '
                             f'the computed value or "{number[:20]}mm" for a length on the drawing')
        x = float(number.replace(",", "."))
        if not math.isfinite(x) or x > 1000:
            raise ValueError(f'"{number}" is out of range')
        part = "mm" if unit in ("mm", "мм") else "%"
        if part in seen:  # "5%,1mm,2mm": which one was meant?
            raise ValueError(f'"{text[:40]}" gives the {part} part twice: give a percentage and '
                             'a length at most once each, e.g. "5%,1mm"')
        seen.add(part)
        if part == "mm":
            mm = x
        else:
            pct = x
    return Tolerance(pct, mm)


@dataclass(frozen=True, slots=True)
class Item:
    """One measured segment or one value the student wrote down.

    kind: "segment" (mm on a plan), "value" (m/s, m/s²), "omega", "epsilon" (rad/s,
    rad/s²), "force" (N), "moment" (N·m), "balancing" (F_у, N). ``plan``: one of
    :data:`PLANS`, or of :data:`FORCE_PLANS` for the force analysis's items.
    ``start``/``end``: plan point names (mechanism names on the plan of positions);
    ``per_mm``: how much of the item 1 mm of drawing is (for the tolerance); ``group``:
    the group whose force plan a force-plan segment is on ("4–5").
    """

    key: str  # where in the file, e.g. "segments.pia3"
    name: str  # as shown, e.g. "πa3", "ω3", "V_A3"
    kind: str
    plan: str  # positions, velocity, acceleration
    measured: float
    start: str = ""
    end: str = ""
    link: int = 0
    sense: int = 0  # ω, ε: +1 ccw, −1 cw, 0 not given
    per_mm: float = 1.0
    group: str = ""

    @property
    def unit(self) -> str:
        return {"segment": "mm", "omega": "rad/s", "epsilon": "rad/s²", "force": "N",
                "balancing": "N", "moment": "N·m"}.get(
            self.kind, "m/s" if self.plan == "velocity" else "m/s²")
