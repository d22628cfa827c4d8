"""The force analysis drawn on the mechanism (sheet 2): the mechanism in its position with
every load, each Assur group drawn apart with its loads and its unknown reactions, the
driving link with its reactions and the balancing moment M_у, and each group's force plan
(:func:`drawing.views.plans.vector_plan_view`, its vectors named by their forces).

A force on a link is drawn as an arrow of one length (:data:`drawing.views.arrows.ARROW`)
at its point: its line, its sense and where it acts, not its size, which the force plans
give to scale. Where several forces act at one point, each is drawn leaving the point or
arriving at it, chosen together so that it keeps clear of the links' bars and of the other
arrows there (:func:`drawing.views.arrows.rays`): a force along a bar arrives from outside
rather than lies on the bar. A moment is an arc arrow round the link's centre of mass (an
inertia moment written as a pair of forces, ``couples = "pair"``, is drawn as those two
forces).
"""

from __future__ import annotations

import math
import re
from typing import NamedTuple

from drawing.labels import LabelRequest
from drawing.scene import Circle, Group, Item, Segment, shared_label
from drawing.styles import LineType
from drawing.views.arrows import ARROW, arc_arrow, beside, compass, force_arrow, rays
from drawing.views.common import JOINT_R, LETTER, View, finish, shared_points
from drawing.views.plans import vector_plan_view
from drawing.views.positions import (
    centre_of_mass,
    guide_dir,
    guide_slots,
    link_segments,
    slider_block,
    slot_segments,
    support,
    to_sheet,
)
from plans.fmt import num
from plans.forces.lever import couple_pair, joints

__all__ = [
    "FAR",
    "FORCE_WORDS",
    "UNDER",
    "Drawn",
    "body_view",
    "crank_view",
    "force_markup",
    "force_plan_view",
    "group_name",
    "group_view",
    "loads_drawn",
    "mechanism_view",
    "polygon_equation",
]

#: letters of the lines under a view of sheet 2: 3.5 mm, their indices 2.45 mm (GOST
#: 2.304 allows no index under 1.8 mm, which 2.5 mm letters' 1.75 mm ones are)
UNDER = 3.5

FORCE_WORDS = {
    "ru": {
        "mechanism": "Механизм с нагрузками",
        "group": "Группа",
        "force_plan": "План сил группы {g}",
        "crank": "Ведущее звено {i}",
        "N": "Н",
        "Nm": "Н·м",
        "Nmm": "Н·мм",
        "N_per_mm": "Н/мм",
        "m_per_mm": "м/мм",
        "ccw": "против ч.с.",
        "cw": "по ч.с.",
        "link": "звено",
        "moment_eq": "ΣM_{{{about}}} = 0 ({link} {i}): {unknown} = {value} Н",
        "My": "M_у = {value} Н·м, {sense}",
        "Fy": "F_у = M_у / l_{{{crank}}} = {value} Н",
        "title": "Силовой анализ",
        "no_moment_diagram": "Диаграмма M_у(φ) не строится: ",
        "far": "{name}: линия действия пересекает направляющую в {d} м от {block}",
    },
    "en": {
        "mechanism": "Mechanism with its loads",
        "group": "Group",
        "force_plan": "Force plan of group {g}",
        "crank": "Driving link {i}",
        "N": "N",
        "Nm": "N·m",
        "Nmm": "N·mm",
        "N_per_mm": "N/mm",
        "m_per_mm": "m/mm",
        "ccw": "ccw",
        "cw": "cw",
        "link": "link",
        "moment_eq": "ΣM_{{{about}}} = 0 ({link} {i}): {unknown} = {value} N",
        "My": "M_у = {value} N·m, {sense}",
        "Fy": "F_у = M_у / l_{{{crank}}} = {value} N",
        "title": "Force analysis",
        "no_moment_diagram": "No M_у(φ) diagram: ",
        "far": "{name}: its line meets the guide {d} m from {block}",
    },
}


#: a reaction's component as each language's textbooks letter it (the engine's τ is t in English)
COMPONENT = {"en": {"τ": "t"}}


def force_markup(name: str, lang: str = "ru") -> str:
    """A force's or moment's engine name as a sheet writes it (markup): the links' numbers
    as an index, a component as a superscript (τ in Russian, t in English).

    >>> [force_markup(n) for n in ("G4", "Φ3", "R34", "R34^τ", "R12,3^n", "M_Φ3", "P", "F_пс")]
    ['G_4', 'Φ_3', 'R_{34}', 'R^τ_{34}', 'R^n_{12,3}', 'M_{Φ3}', 'P', 'F_{пс}']
    >>> force_markup("R34^τ", "en"), force_markup("M_Φ3(B)"), force_markup("M53")
    ('R^t_{34}', 'P_{Φ3}', 'M_{53}')
    """
    if m := re.fullmatch(r"M_(\S+)\((\w+)\)", name):  # a couple's force at a joint (the lever)
        return f"P_{{{m[1]}}}"
    if m := re.fullmatch(r"M(\d+(?:,\d+)?)", name):  # the couple of a slide's reaction
        return f"M_{{{m[1]}}}"
    if m := re.fullmatch(r"R(\d+(?:,\d+)?)(?:\^(τ|n))?", name):
        sup = "" if m[2] is None else "^" + COMPONENT.get(lang, {}).get(m[2], m[2])
        return f"R{sup}_{{{m[1]}}}"
    if m := re.fullmatch(r"([GΦ])(\d+)", name):
        return f"{m[1]}_{m[2]}" if len(m[2]) == 1 else f"{m[1]}_{{{m[2]}}}"
    if "_" in name:
        base, index = name.split("_", 1)
        return f"{base}_{{{index}}}"
    return name


def group_name(group, lang: str) -> str:
    """"4–5 (ВВП)", "4–5 (RRP)": a group by its links and its kind."""
    kind = group.kind.letters(lang)
    return f"{group.links[0]}–{group.links[1]} ({kind})"


class Drawn(NamedTuple):
    """A force or a moment a view draws: ``at`` (m, world) where it acts; ``force`` (N,
    complex) its line and sense, 0 for a moment; ``moment`` (N·m, counter-clockwise
    positive) for a moment, drawn round ``at``; ``kind``: "load" or "reaction", its
    class on the SVG."""

    name: str
    at: complex
    force: complex
    moment: float = 0.0
    kind: str = "load"


def loads_drawn(mech, loads, pos, pairs: bool) -> list[Drawn]:
    """The loads ``loads`` (:class:`plans.forces.loads.Load`) as drawn: each force at its
    point, each couple round its link's centre of mass, or (``pairs``) as the two forces
    ⊥ the link at its joints that replace it (named P_Φ3 where the couple is M_Φ3); the
    reactions the groups solved after put on a link, as reactions."""
    out = []
    for ld in loads:
        kind = "reaction" if ld.kind == "reaction" else "load"
        if ld.force != 0:
            out.append(Drawn(ld.name, complex(ld.at), complex(ld.force), 0.0, kind))
        if ld.moment:
            ends = joints(mech, ld.link) if pairs and ld.kind == "inertia moment" else None
            if ends is None:
                # a slide's reaction carries a couple too: M₅₃ beside the force R₅₃
                name = "M" + ld.name[1:] if kind == "reaction" else ld.name
                out.append(Drawn(name, _centre(mech, ld, pos), 0j, float(ld.moment), kind))
                continue
            for point, at, f in couple_pair(ld.link, float(ld.moment), pos, *ends):
                out.append(Drawn(f"{ld.name}({point})", complex(at), complex(f), 0.0, kind))
    return out


def _centre(mech, ld, pos) -> complex:
    """Where a couple on a link is drawn: round its centre of mass (an inertia moment's
    ``at``), else round the middle of the link's points."""
    if ld.kind == "inertia moment":
        return complex(ld.at)
    own = [pos[n] for n in mech.links[ld.link].points if n in pos]
    return complex(sum(own) / len(own)) if own else complex(ld.at)


def _bars_at(mech, pos, links, name) -> tuple[list[complex], list[complex]]:
    """The directions (unit, sheet) of the bars of ``links`` that leave the point ``name``,
    and of the guide its block slides along (both ways)."""
    out = []
    here = pos[name]
    for lid in links:
        pts = mech.links[lid].points
        if name not in pts:
            continue
        for other in pts:
            if other != name and other in pos and not centre_of_mass(mech, other):
                d = pos[other] - here
                if abs(d) > 1e-12:
                    out.append(complex(d.real, -d.imag) / abs(d))
    guides = []
    for s in mech.sliders:
        if s.point == name and s.link in links:
            g = guide_dir(mech, s, pos)
            guides += [complex(g.real, -g.imag), -complex(g.real, -g.imag)]
    return out, guides


def _sheet_dir(z: complex) -> complex:
    return complex(z.real, -z.imag) / abs(z)


def body_view(name: str, caption: str, mech, pos, mu_l: float, links, drawn: list[Drawn],
              lang: str = "ru", frame: bool = False, under=(), sizing: bool = False) -> View:
    """The links ``links`` of ``mech`` in the position ``pos`` at ``mu_l``, heavy, with the
    forces and moments ``drawn`` on them: its bars and plates, the slots they carry, their
    blocks, the joints ringed, the centres of mass dotted, the fixed guides of its blocks
    dash-dotted; ``frame``: the fixed pivots on their supports (else the frame is taken
    away, as from a group drawn apart, and its reactions stand for it). Each force is an
    arrow (:data:`ARROW`) in a group of class ``load NAME`` or ``reaction NAME``, each
    moment an arc in one of class ``moment NAME``; ``under``: lines under the view."""
    links = set(links)
    own = {n for lid in links for n in mech.links[lid].points if n in pos}
    if frame:
        own |= {n for n in mech.frame if n in pos}
    sub = {n: pos[n] for n in own}
    items: list[Item] = list(link_segments(mech, sub, mu_l, LineType.MAIN))
    slots = [s for s in guide_slots(mech, [pos]) if s[0].guide.link in links]
    items += slot_segments(mech, slots, pos, mu_l, LineType.MAIN)
    # the fixed guides of the blocks drawn, over the block and the lines of the forces on it
    for s in mech.sliders:
        if s.link not in links or s.guide.link != 0:
            continue
        g = s.guide
        on = [((d.at - g.point) * g.direction.conjugate()).real for d in drawn
              if abs(((d.at - g.point) * g.direction.conjugate()).imag) < 1e-9 * max(1.0, abs(d.at))]
        t = ((pos[s.point] - g.point) * g.direction.conjugate()).real
        reach = (ARROW + 6.0) * mu_l
        a, b = min([t, *on]) - reach, max([t, *on]) + reach
        items.append(Segment(to_sheet(g.point + a * g.direction, mu_l),
                             to_sheet(g.point + b * g.direction, mu_l), LineType.DASH_DOT_THIN))
    for s in mech.sliders:
        if s.link in links and s.point in pos:
            items.append(slider_block(to_sheet(pos[s.point], mu_l), guide_dir(mech, s, pos),
                                      LineType.MAIN))
    for n in sorted(own):
        if centre_of_mass(mech, n):
            items.append(Circle(to_sheet(pos[n], mu_l), 0.6, LineType.MAIN, fill="black"))
    if frame:
        for n in mech.frame:
            if n in pos:
                items += support(to_sheet(pos[n], mu_l))
    joints_here = sorted(n for n in own if len(mech.links_of(n)) > 1)
    items += [Circle(to_sheet(pos[n], mu_l), JOINT_R, LineType.MAIN, fill="white") for n in joints_here]
    labels = [LabelRequest(xy, shared_label(names), LETTER, "nw", blank=True)
              for xy, names in shared_points((to_sheet(pos[n], mu_l), n) for n in mech.point_names()
                                             if n in own)]
    arrows, arrow_labels = _forces(mech, pos, mu_l, links, drawn, lang)
    return finish(name, items + arrows, labels + arrow_labels, caption, list(under), sizing=sizing,
                  under_size=UNDER)


def _forces(mech, pos, mu_l, links, drawn: list[Drawn], lang: str):
    """The arrows and arcs of ``drawn``, with their labels."""
    items: list[Item] = []
    labels: list[LabelRequest] = []
    # the forces by the point they act at (on the sheet, within 1.5 mm: a slide's normal
    # force acts beside its block's centre), with the bars and the guide there
    spots: list[tuple[tuple[float, float], list[int]]] = []
    for i, d in enumerate(drawn):
        xy = to_sheet(d.at, mu_l)
        near = next((idx for where, idx in spots if math.dist(where, xy) < 1.5), None)
        if near is None:
            spots.append((xy, [i]))
        else:
            near.append(i)
    way: dict[int, complex] = {}
    aside: dict[int, float] = {}
    bars: dict[int, list[complex]] = {}
    for _, idx in spots:
        at = drawn[idx[0]].at
        name = min(pos, key=lambda n: abs(pos[n] - at))
        hard, soft = _bars_at(mech, pos, links, name) if abs(pos[name] - at) / mu_l < 1.5 else ([], [])
        forces = [i for i in idx if drawn[i].force != 0]
        got = rays(hard, soft, [_sheet_dir(drawn[i].force) for i in forces])
        seen = list(hard)
        for i, r in zip(forces, got, strict=True):
            way[i], aside[i] = r, beside(seen, r)
            seen.append(r)
        for i in idx:
            bars[i] = hard
    for i, d in enumerate(drawn):
        p = to_sheet(d.at, mu_l)
        markup = force_markup(d.name, lang)
        if d.force == 0:
            arc, anchor, prefer = arc_arrow(p, d.moment, bars[i])
            items.append(Group(tuple(arc), name=f"moment {d.name}"))
            labels.append(LabelRequest(anchor, markup, LETTER, prefer))
            continue
        arrow, far = force_arrow(p, _sheet_dir(d.force), way[i], aside[i], JOINT_R + 0.3)
        items.append(Group((arrow,), name=f"{d.kind} {d.name}"))
        labels.append(LabelRequest(far, markup, LETTER, compass(r)))
    return items, labels


def _mu_l(mu_l: float, lang: str) -> str:
    return f"μ_l = {num(mu_l, 4, lang)} {FORCE_WORDS[lang]['m_per_mm']}"


def mechanism_view(fa, mu_l: float, lang: str = "ru", label: str = "", sizing: bool = False) -> View:
    """The mechanism in the analysed position at ``mu_l`` with every load of the force
    analysis ``fa`` (:class:`plans.forces.analysis.ForceAnalysis`) on it; ``label``: the
    position, in the caption."""
    sol = fa.solution
    mech = sol.mechanism
    w = FORCE_WORDS[lang]
    pairs = mech.loads.couples == "pair"
    drawn = loads_drawn(mech, fa.loads, sol.positions, pairs)
    caption = f"{w['mechanism']}{f' ({label})' if label else ''}, {_mu_l(mu_l, lang)}"
    return body_view("mechanism", caption, mech, sol.positions, mu_l, mech.links, drawn, lang,
                     frame=True, sizing=sizing)


def _unknowns(mech, gf, pos, mu_l: float, lang: str) -> tuple[list[Drawn], list[str]]:
    """The reactions a group's force plan finds on its links from the links outside it:
    a revolute's two components where the textbook finds it so, else the whole, and a
    prismatic pair's normal force where it acts (none where it is 0; at its block where it
    acts far along the guide, said in the lines returned)."""
    links = set(gf.group.links)
    out, notes = [], []
    for r in gf.reactions:
        if r.on not in links or r.by in links or r.at is None:
            continue
        if r.tangential is not None:
            for part, value in (("^τ", r.tangential), ("^n", r.normal)):
                if abs(value) > 1e-12 * max(1.0, abs(r.value)):
                    out.append(Drawn(r.name + part, complex(r.at), complex(value), 0.0, "reaction"))
        elif abs(r.value) > 0:
            d, said = _near_block(mech, pos, r, Drawn(r.name, complex(r.at), complex(r.value), 0.0,
                                                      "reaction"), mu_l, lang)
            out.append(d)
            notes += said
    return out, notes


#: mm: a slide's normal force whose line meets its guide farther than this from the
#: block is drawn at the block, and where its line is is written under the view
FAR = 25.0


def _near_block(mech, pos, r, d: Drawn, mu_l: float, lang: str) -> tuple[Drawn, list[str]]:
    """A slide's normal force ``d`` (of the reaction ``r``) acting far along its guide
    (:data:`FAR`) moved to its block, with the line that says where it acts."""
    s = mech.slider_of(r.on)
    if r.pair != "prismatic" or s is None or s.point not in pos or abs(d.at - pos[s.point]) / mu_l <= FAR:
        return d, []
    note = FORCE_WORDS[lang]["far"].format(name=force_markup(d.name, lang), block=s.point,
                                           d=num(abs(d.at - pos[s.point]), 4, lang))
    return d._replace(at=complex(pos[s.point])), [note]


def group_view(fa, gf, mu_l: float, lang: str = "ru", index: str = "1", sizing: bool = False) -> View:
    """The Assur group of ``gf`` (:class:`plans.forces.analysis.GroupForces`, a group of the
    analysis ``fa``) drawn apart at ``mu_l``: its links with their loads (and those the
    groups solved before put on them) and the unknown reactions its force plan finds, its
    moment equations under it."""
    sol_pos = fa.solution.positions
    mech = fa.solution.mechanism
    w = FORCE_WORDS[lang]
    pairs = mech.loads.couples == "pair"
    loads = [ld for lid in gf.group.links for ld in gf.loads[lid]]
    unknowns, notes = _unknowns(mech, gf, sol_pos, mu_l, lang)
    drawn = loads_drawn(mech, loads, sol_pos, pairs) + unknowns
    under = []
    for eq in gf.equations:
        # the slotted link's group solves the slide's force on the block, named as the plan names it
        unknown = eq.unknown if eq.unknown != "N" else next(
            r.name for r in gf.reactions if r.pair == "prismatic" and r.on == gf.group.a)
        under.append(w["moment_eq"].format(about=eq.about, link=w["link"], i=eq.link,
                                           unknown=force_markup(unknown, lang),
                                           value=num(abs(eq.value), 4, lang)))
    caption = f"{w['group']} {group_name(gf.group, lang)}, {_mu_l(mu_l, lang)}"
    return body_view(f"group-{index}", caption, mech, sol_pos, mu_l, gf.group.links, drawn, lang,
                     under=under + notes, sizing=sizing)


def crank_view(fa, mu_l: float, lang: str = "ru", sizing: bool = False) -> View:
    """The driving link at ``mu_l`` with its loads, the reaction of the group on it, the
    frame's reaction R01 at its pivot and the balancing moment M_у."""
    sol = fa.solution
    mech = sol.mechanism
    d = mech.driver
    w = FORCE_WORDS[lang]
    pairs = mech.loads.couples == "pair"
    drawn = loads_drawn(mech, fa.crank_loads, sol.positions, pairs)
    pivot = complex(sol.positions[d.pivot])
    R01 = f"R0{d.link}" if d.link < 10 else f"R0,{d.link}"
    if abs(fa.R01) > 0:
        drawn.append(Drawn(R01, pivot, complex(fa.R01), 0.0, "reaction"))
    if fa.M_y:
        drawn.append(Drawn("M_у", pivot, 0j, fa.M_y, "reaction"))
    under = [w["My"].format(value=num(abs(fa.M_y), 4, lang), sense=w["ccw" if fa.M_y > 0 else "cw"]),
             w["Fy"].format(crank=f"{d.pivot}{d.tip}", value=num(abs(fa.F_y), 4, lang))]
    caption = f"{w['crank'].format(i=d.link)}, {_mu_l(mu_l, lang)}"
    return body_view("crank", caption, mech, sol.positions, mu_l, [d.link], drawn, lang,
                     under=under, sizing=sizing)


def polygon_equation(plan, lang: str = "ru") -> str:
    """The vector equation of a force plan's polygon, as markup: its vectors from the pole
    end to end back to it, "R^τ_{34} + G_4 + … + R^n_{34} = 0"."""
    chain, here = [], plan.pole
    for v in plan.vectors:
        if v.start != here:
            continue
        chain.append(force_markup(v.label, lang))
        here = v.end
        if here == plan.pole:
            break
    return " + ".join(chain) + " = 0"


def force_plan_view(gf, lang: str = "ru", index: str = "1", sizing: bool = False) -> View:
    """The force plan of a group at its μF: the forces laid end to end, the two lines that
    close it thin, the reactions found; its vectors named by their forces, its polygon's
    equation under it."""
    w = FORCE_WORDS[lang]
    plan = gf.plan
    caption = (f"{w['force_plan'].format(g=group_name(gf.group, lang))}, "
               f"μ_F = {num(plan.mu, 4, lang)} {w['N_per_mm']}")
    return vector_plan_view(plan, f"force-{index}", caption, "f", index, lang, sizing=sizing,
                            under=[polygon_equation(plan, lang)], under_size=UNDER,
                            named=lambda label: force_markup(label, lang))
