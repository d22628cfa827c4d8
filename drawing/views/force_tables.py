"""The tables of sheet 2: the loads (name, link, magnitude, direction), the reactions (N, and
mm of their force plans) and Zhukovsky's lever (each force, its arm, its moment)."""

from __future__ import annotations

import cmath
import math

from drawing.views.common import View
from drawing.views.forces import force_markup
from drawing.views.lever import arm_numbers
from drawing.views.tables import table_view
from plans.fmt import num
from plans.forces.lever import couple_pair, joints

__all__ = ["TABLE_WORDS", "lever_table_view", "loads_table_view", "reactions_table_view"]

TABLE_WORDS = {
    "ru": {
        "loads": "Нагрузки", "loads_head": ["Нагрузка", "Звено", "Величина", "Направление", "План сил, мм"],
        "reactions": "Реакции в кинематических парах",
        "reactions_head": ["Реакция", "Н", "мм", "Направление"],
        "lever": "Рычаг Жуковского: силы и плечи",
        "lever_head": ["Плечо", "Сила", "F, Н", "h, мм", "±F·h, Н·мм"],
        "N": "Н", "Nm": "Н·м", "ccw": "против ч.с.", "cw": "по ч.с.",
    },
    "en": {
        "loads": "Loads", "loads_head": ["Load", "Link", "Value", "Direction", "Force plan, mm"],
        "reactions": "Reactions in the pairs",
        "reactions_head": ["Reaction", "N", "mm", "Direction"],
        "lever": "Zhukovsky's lever: forces and arms",
        "lever_head": ["Arm", "Force", "F, N", "h, mm", "±F·h, N·mm"],
        "N": "N", "Nm": "N·m", "ccw": "ccw", "cw": "cw",
    },
}

ROW = 7.0  # mm: rows of 3.5 mm letters
BODY = 3.5  # their indices 2.45 mm: GOST 2.304's 1.8 mm or more


def _deg(z: complex, lang: str) -> str:
    """A direction in degrees counter-clockwise from +x, in [0, 360), rounding of a
    whole angle written as it (0°, not 1,6e-14°).

    >>> _deg(complex(1.0, 2.8e-16), "ru"), _deg(complex(1.0, -2.8e-16), "en"), _deg(-1j, "en")
    ('0°', '0°', '270°')
    """
    a = round(math.degrees(cmath.phase(z)) % 360.0, 9) % 360.0
    return f"{num(a, 4, lang)}°"


def loads_table_view(forces, lang: str = "ru", sizing: bool = False) -> View:
    """Every load of the analysed position: its name, link, magnitude (N, or N·m for a
    couple), direction (degrees from +x, or the couple's sense) and its segment on its
    group's force plan (mm at the plan's μF; "—" for a couple, and for a load on the
    driving link, which no force plan draws); a couple written as
    a pair of forces (``couples = "pair"``) is followed by that pair, each force with its
    joint."""
    w = TABLE_WORDS[lang]
    fa = forces.analysis
    mech = fa.solution.mechanism
    pos = fa.solution.positions
    plans = {lid: gf.plan for gf in fa.groups for lid in gf.group.links}
    rows = []
    for ld in fa.loads:
        if ld.force != 0:
            mm = plans[ld.link].segments.get(ld.name) if ld.link in plans else None
            rows.append([force_markup(ld.name, lang), str(ld.link),
                         f"{num(abs(ld.force), 4, lang)} {w['N']}", _deg(complex(ld.force), lang),
                         "—" if mm is None else num(mm, 4, lang)])
        if ld.moment:
            rows.append([force_markup(ld.name, lang), str(ld.link),
                         f"{num(abs(ld.moment), 4, lang)} {w['Nm']}", w["ccw" if ld.moment > 0 else "cw"],
                         "—"])
            ends = joints(mech, ld.link)
            if mech.loads.couples == "pair" and ld.kind == "inertia moment" and ends is not None:
                for point, _, f in reversed(couple_pair(ld.link, float(ld.moment), pos, *ends)):
                    rows.append([f"{force_markup(f'{ld.name}({point})', lang)} ({point})", str(ld.link),
                                 f"{num(abs(f), 4, lang)} {w['N']}", _deg(complex(f), lang), "—"])
    return table_view("loads", w["loads"], w["loads_head"], rows, [26.0, 16.0, 28.0, 26.0, 24.0], ROW,
                      sizing=sizing, body=BODY)


def reactions_table_view(forces, lang: str = "ru", sizing: bool = False) -> View:
    """Every reaction on the force plans, group by group (those a group solved before puts
    on its links, then those it finds), and the frame's on the driving link: its size
    (N), its segment on the group's force plan (mm at the plan's μF; "—" where the plan
    draws none) and its direction; a reaction found as two components is followed by
    them."""
    w = TABLE_WORDS[lang]
    fa = forces.analysis
    rows = []
    for gf in fa.groups:
        segments = gf.plan.segments
        # a reaction a group solved before puts on this one's links, as this plan draws it
        known = [ld for lid in gf.group.links for ld in gf.loads[lid]
                 if ld.kind == "reaction" and ld.force != 0]
        for ld in known:
            mm = segments.get(ld.name)
            rows.append([force_markup(ld.name, lang), num(abs(ld.force), 4, lang),
                         "—" if mm is None else num(mm, 4, lang), _deg(complex(ld.force), lang)])
        for r in gf.reactions:
            mm = segments.get(r.name)
            rows.append([force_markup(r.name, lang), num(abs(r.value), 4, lang),
                         "—" if mm is None else num(mm, 4, lang), _deg(r.value, lang)])
            if r.tangential is not None:
                for part, value in (("^τ", r.tangential), ("^n", r.normal)):
                    mm = segments.get(r.name + part)
                    rows.append([force_markup(r.name + part, lang), num(abs(value), 4, lang),
                                 "—" if mm is None else num(mm, 4, lang),
                                 _deg(value, lang) if abs(value) else "—"])
    d = fa.solution.mechanism.driver
    rows.append([force_markup(f"R0{d.link}" if d.link < 10 else f"R0,{d.link}", lang),
                 num(abs(fa.R01), 4, lang), "—", _deg(fa.R01, lang) if abs(fa.R01) else "—"])
    return table_view("reactions", w["reactions"], w["reactions_head"], rows, [24.0, 22.0, 20.0, 26.0],
                      ROW, sizing=sizing, body=BODY)


def lever_table_view(forces, mu_v: float, lang: str = "ru", sizing: bool = False) -> View:
    """The lever's forces with their arms at ``mu_v`` (h1, h2 … as the lever letters them)
    and their moments about the pole (counter-clockwise positive, N·mm of the lever); a
    couple on a link of one point enters as its moment alone; then F_у with its arm pb."""
    w = TABLE_WORDS[lang]
    lv = forces.lever
    k = lv.mu_v / mu_v
    numbers = arm_numbers(forces, mu_v)
    rows = []
    for t in lv.terms:
        if t.force == 0 and t.moment:  # a couple on a block: its moment as it is
            rows.append(["—", force_markup(t.name, lang), "—", "—", num(t.moment * k, 5, lang)])
        elif t.name in numbers:
            rows.append([f"h_{{{numbers[t.name]}}}", force_markup(t.name, lang), num(abs(t.force), 4, lang),
                         num(t.arm * k, 4, lang), num(t.moment * k, 5, lang)])
    d = forces.analysis.solution.mechanism.driver
    sense = 1.0 if d.omega > 0 else -1.0
    rows.append([f"p{d.tip.lower()}", "F_у", num(abs(lv.F_y), 4, lang), num(lv.pb * k, 4, lang),
                 num(-lv.F_y * lv.pb * sense * k, 5, lang)])
    return table_view("lever-table", w["lever"], w["lever_head"], rows, [16.0, 20.0, 22.0, 20.0, 28.0],
                      ROW, sizing=sizing, body=BODY)
