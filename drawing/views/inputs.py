"""The inputs and the transmission angle on the plan of positions.

Each input is drawn as such at its heavy position: a crank's ω as an arc arrow about its
pivot in the sense it turns (and ε, where it accelerates, as a second arc in the sense of
ε); a slider input's velocity as an arrow beside its guide from its point. The group whose
transmission angle falls lowest over the cycle has γ marked at its middle joint (an RRR
group: the arc between the coupler and the rocker; a slider on a fixed guide: between the
rod and the guide's normal), valued with its γmin over the cycle (where it occurs the
note and solve say).
"""

from __future__ import annotations

import math

from drawing.labels import LabelRequest
from drawing.scene import Arrow, Item, Polyline
from drawing.styles import LineType
from drawing.views.common import LETTER
from plans.cycle.transmission import transmission
from plans.fmt import num
from plans.model.structure import DyadKind

#: mm on the sheet: the least radius of ω's arc about the crank's pivot (0.3 of the
#: crank, to 2.5 times this; ε's is 1.5 times ω's), the length of a slider input's arrow
ARC_MM = 6.0
ARROW_MM = 12.0
#: the arc's sweep (rad), and where it starts ahead of the crank
SWEEP = math.radians(70.0)
AHEAD = math.radians(25.0)

def _arc(to_sheet, centre: complex, r_world: float, start: float, sweep: float, mu_l: float):
    pts = [to_sheet(centre + r_world * complex(math.cos(start + sweep * k / 24),
                                                 math.sin(start + sweep * k / 24)), mu_l)
           for k in range(25)]
    items: list[Item] = [Polyline(pts[:-2], LineType.THIN)]
    items.append(Arrow(pts[-3], pts[-1], LineType.THIN, 2.5, 1.0))
    return items, pts


def input_marks(sol, pos: dict[str, complex], to_sheet, lang: str) -> tuple[list[Item], list[LabelRequest]]:
    """The inputs' arrows at the position ``pos`` (world coordinates; ``to_sheet`` maps
    them to the sheet at the solution's μl) and their letters."""
    mech, mu_l = sol.mechanism, sol.mu_l
    items: list[Item] = []
    labels: list[LabelRequest] = []
    for d, (_, dq, ddq) in zip(mech.drivers, mech.inputs_at(sol.phi), strict=True):
        if d.tip not in pos:
            continue
        if d.linear:
            if not dq:
                continue
            # beside the guide (4 mm off it, to its left), not on its dash-dot axis
            z = pos[d.tip] + 1j * d.guide.direction * 4.0 * mu_l
            u = d.guide.direction * (1 if dq > 0 else -1)
            end = z + u * ARROW_MM * mu_l
            items.append(Arrow(to_sheet(z, mu_l), to_sheet(end, mu_l), LineType.THIN, 2.5, 1.0))
            labels.append(LabelRequest(to_sheet(end, mu_l), f"V_{{{d.tip}}}", LETTER, "n"))
            continue
        if d.pivot not in pos:
            continue
        o, a = pos[d.pivot], pos[d.tip]
        phi = math.atan2((a - o).imag, (a - o).real)
        radius = min(max(ARC_MM, 0.3 * abs(a - o) / mu_l), 2.5 * ARC_MM)  # mm: about the pivot
        for rate, name, scale in ((dq, f"ω_{{{d.link}}}", 1.0), (ddq, f"ε_{{{d.link}}}", 1.5)):
            if not rate:
                continue
            s = 1.0 if rate > 0 else -1.0
            part, pts = _arc(to_sheet, o, radius * scale * mu_l, phi + s * AHEAD, s * SWEEP, mu_l)
            items += part
            labels.append(LabelRequest(pts[12], name, LETTER, "ne"))
    return items, labels


def gamma_marks(sol, cycle, pos: dict[str, complex], to_sheet, lang: str
                ) -> tuple[list[Item], list[LabelRequest]]:
    """γ at the position drawn of the group whose γ falls lowest over ``cycle`` (an RRR
    group's arc at its middle joint), valued with that γmin."""
    least = None if cycle is None else transmission(sol.solver, cycle).least
    if least is None or not math.isfinite(least.gamma_min):
        return [], []
    mu_l, g = sol.mu_l, least.group
    deg = math.degrees(least.gamma_min)
    items: list[Item] = []
    labels: list[LabelRequest] = []
    u2 = None
    if g.kind is DyadKind.RRR and all(p in pos for p in (g.P, g.C, g.Q)):
        u2 = pos[g.Q] - pos[g.C]
    elif g.kind is DyadKind.RRP and g.s1 is not None and g.s1.guide.link == 0 and g.P in pos and g.C in pos:
        u2 = 1j * g.s1.guide.direction  # a slider on a fixed guide: γ between the rod and its normal
    if u2 is not None:
        c = pos[g.C]
        u1 = pos[g.P] - c
        a1, a2 = math.atan2(u1.imag, u1.real), math.atan2(u2.imag, u2.real)
        sweep = math.remainder(a2 - a1, 2 * math.pi)
        if abs(sweep) > math.pi / 2:  # γ is the acute angle: between CP and QC produced
            a2 = a2 + math.pi
            sweep = math.remainder(a2 - a1, 2 * math.pi)
        r = 8.0 * mu_l
        pts = [to_sheet(c + r * complex(math.cos(a1 + sweep * k / 24), math.sin(a1 + sweep * k / 24)),
                        mu_l) for k in range(25)]
        items.append(Polyline(pts, LineType.THIN))
        here = math.degrees(abs(sweep))  # the position drawn: γ from its own geometry
        # two short labels, not one long one: each finds room of its own in a crowded plan
        labels.append(LabelRequest(pts[12], f"γ = {num(here, 4, lang)}°", 3.5, "ne", markup=False,
                                   blank=True))
        labels.append(LabelRequest(pts[12], f"γ_{{min}} = {num(deg, 4, lang)}°", 3.5, "se", markup=True,
                                   blank=True))
    return items, labels
