"""The explanatory note (пояснительная записка): each step as formula, substitution, result.

Everything is read from one :class:`~plans.plan.Solution`: the recorded constructions give
the vector equations and the lines, the plan points give the measured segments, so the
note cannot disagree with the sheet. Formatting only; no kinematics is computed here
beyond products and quotients of values the plans already hold.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

from plans.cycle.transmission import lines as transmission_lines
from plans.cycle.transmission import transmission
from plans.cycle.words import change_points, no_full_turn
from plans.fmt import md_code, md_text, notation_in, num
from plans.kinematics.conditioning import flag_words
from plans.kinematics.transmission import gammas
from plans.note.initial import initial_data, inputs_there
from plans.note.words import UNITS, T
from plans.plan.solution import Solution, plan_name


@dataclass(frozen=True, slots=True)
class Step:
    """One line of the note: formula = substitution = result unit."""

    formula: str
    substitution: str
    result: str
    unit: str

    def markdown(self) -> str:
        mid = f" = {self.substitution}" if self.substitution else ""
        unit = "" if not self.unit else self.unit if self.unit == "°" else f" {self.unit}"
        return f"- `{md_code(f'{self.formula}{mid} = {self.result}{unit}')}`"


def note(sol: Solution, lang: str = "en", cycle=None,
         plans: Sequence[tuple[str, Solution]] = (), numbers: dict | None = None) -> str:
    """The whole explanatory note, in Markdown: the structure and the plan of positions,
    then the velocity and acceleration plans of ``sol``'s crank position, or of each of
    ``plans`` instead ((title, solution): the positions a sheet draws plans for, at the
    sheet's scale factors), each titled. With ``plans``, the plan of positions is said to
    draw theirs heavy (as the sheet does) and its segments are theirs; ``sol`` gives the
    structure and μl. ``numbers``: where given, the numbers each position's plan sections
    printed (segments, values, ω and ε, by name) are left there, by (φ, μa), for the force
    section to carry on as printed (:func:`plans.forces.note.force_note`)."""
    t, u = T[lang], UNITS[lang]

    def n(x, d=4):
        return num(x, d, lang)

    mech, st = sol.mechanism, sol.structure
    d = mech.driver
    out = [f"# {t['title']}: {md_text(mech.name_in(lang))}", ""]
    out += initial_data(sol, lang)
    # structure ----------------------------------------------------------------------
    out += [f"## 2. {t['structure']}", "", t["cheb"], ""]
    out.append(f"- `{st.chebyshev()}`")
    dash = t["dash"]  # «n = 5 — число подвижных звеньев»
    out.append(f"  (n = {st.n}{dash} {t['n']}, p5 = {st.p5}{dash} {t['p5']}, p4 = 0{dash} {t['p4']})")
    out += ["", t["groups"].format(d=d.link), ""]
    for g in st.groups:
        out.append("- " + t["group"].format(a=g.links[0], b=g.links[1], k=g.kind.value,
                                            name=t["dyad"].format(latin=g.kind.name,
                                                                  cyrillic=g.kind.ru)))
    out += ["", t["class"].format(c="II" if st.groups else "I", f=f"`{st.formula()}`"), ""]
    # positions ----------------------------------------------------------------------
    mu_l = sol.mu_l
    crank_mm = d.length / mu_l
    out += [f"## 3. {t['positions']}", "", t["mul"], ""]
    if d.linear:  # a slider input has no crank: μl from the first link's segment
        k, v = next(((k, v) for k, v in sol.lengths.items() if v > 0), ("", 0.0))
        out.append(Step(f"μl = l_{k} / {k}", f"{n(v)} / {n(v / mu_l)}", n(mu_l), u["mu_l"]).markdown())
    else:
        out.append(Step(f"μl = l_{d.pivot}{d.tip} / {d.pivot}{d.tip}", f"{n(d.length)} / {n(crank_mm)}",
                        n(mu_l), u["mu_l"]).markdown())
    # with plans of other positions, the plan of positions draws theirs heavy (not the
    # given one): the segments are given at the first, and those that change (BA3 of a
    # slotted link) at each of the others, as their plans' similarity steps use them
    base, rest = (plans[0][1], plans[1:]) if plans else (sol, ())
    if plans:
        titles = "; ".join(title for title, _ in plans)
        out += ["", t["heavy" if len(plans) == 1 else "heavy_all"].format(title=titles)]
    out += ["", t["seg_first"].format(title=plans[0][0]) if plans else t["seg"], ""]

    def segment(k, v):  # five digits: the similarity steps carry them
        return Step(f"{k} = l_{k} / μl", f"{n(v, 5)} / {n(mu_l)}", _drawn(v, mu_l, lang), u["mm"]).markdown()

    for k, v in base.lengths.items():
        if k == d.pivot + d.tip or v == 0:  # the crank is above; a point on another: no segment
            continue
        out.append(segment(k, v))
    same = []  # the positions whose segments are those above: said once, all together
    for title, s in rest:
        changed = [(k, v) for k, v in s.lengths.items() if k != d.pivot + d.tip and v != 0
                   and not math.isclose(v, base.lengths.get(k, math.nan), rel_tol=1e-9)]
        if not changed:
            same.append(title)
            continue
        out += ["", t["seg_at"].format(title=title), ""]
        out += [segment(k, v) for k, v in changed]
    if same:
        out += ["", t["seg_same" if len(same) == 1 else "seg_same_all"].format(title="; ".join(same))]
    if cycle is not None:
        out.append("")
        if cycle.change_points:
            out += [change_points(cycle, lang, d), ""]
        if not cycle.full_turn:
            out.append(no_full_turn(cycle, lang, d))
        elif cycle.stroke is not None:
            if cycle.output.kind == "linear":
                out.append(t["stroke"].format(p=cycle.output.point))
                out.append("")
                p = cycle.output.point  # H on the drawing: from one extreme position to the other
                out.append(Step(f"H = {p}′{p}″·μl", f"{n(cycle.stroke / mu_l, 5)}·{n(mu_l)}", n(cycle.stroke),
                                u["m"]).markdown())
            else:
                out.append(t["swing"].format(l=cycle.output.link))
                out.append("")
                # the angle between the rocker's extreme positions, as the sheet's arc spans it
                arm = cycle.output.arm(mech)
                psi = f"ψ = ∠{arm[1]}′{arm[0]}{arm[1]}″" if arm else "ψ"
                out.append(Step(psi, "", n(math.degrees(cycle.stroke)), u["deg"]).markdown())
            out += ["", t["kth"].format(d=d.link), ""]
            th = math.degrees(cycle.theta)
            # the crank's turn over the working stroke, from the first extreme to the
            # second: 180° + θ, as the cycle found θ from the two turns
            work = 180.0 + th
            w, r = t["working"], t["return"]
            # the turns carried to one decimal more than θ is given to, so that their
            # difference gives θ as printed (3,855° from 183,855° and 176,145°)
            shown = n(th)
            carry = len(shown.replace(",", ".").partition(".")[2]) + 1

            def turn(x: float) -> str:
                return n(x, math.floor(math.log10(max(x, 1.0))) + 1 + carry)

            out.append(Step(w, "", turn(work), u["deg"]).markdown())
            out.append(Step(f"{r} = 360° − {w}", f"360° − {turn(work)}°", turn(360.0 - work),
                            u["deg"]).markdown())
            out.append(Step(f"θ = ({w} − {r}) / 2", f"({turn(work)}° − {turn(360.0 - work)}°) / 2",
                            shown, u["deg"]).markdown())
            out.append(Step("K = (180° + θ) / (180° − θ)", f"(180° + {n(th)}°) / (180° − {n(th)}°)",
                            n(cycle.K), "").markdown())
        trans = transmission(sol.solver, cycle)  # γ at the position, γmin over the cycle
        out += ["", t["transmission"], ""]
        # the lines name the file's guides: its text, escaped as the note's prose is
        out += [f"  - {md_text(line.strip())}" if line.startswith(" ") else f"- {md_text(line)}"
                for line in transmission_lines(trans, mech, st.groups, gammas(sol.scalar), lang,
                                               sol.shown_from,
                                               cycle.output.point if cycle.output is not None else "")]
    out.append("")
    number = 4
    for title, s in plans or [("", sol)]:
        said: dict[str, str] = {}  # the numbers printed for this position, carried on as printed
        if numbers is not None:
            numbers[(s.phi, s.acceleration.mu)] = said
        for plan in (s.velocity, s.acceleration):
            out += _plan_section(s, plan, lang, number, title, said)
            number += 1
        for w in warnings(s, lang):
            out += [f"> {t['warn']}: {w}", ""]
    return notation_in("\n".join(out).rstrip() + "\n", lang)


def _letter(plan, name: str) -> str:
    """The plan point's letter as the note writes it: the pole's for a fixed point, which
    lies at the pole (the acceleration plan has no point b apart from π)."""
    p = plan.points.get(name)
    return plan.pole if p is not None and p.source.kind == "pole" else name


def warnings(sol: Solution, lang: str = "en") -> list[str]:
    """The solution's near-singular groups in ``lang``: its figures (``sol.flags``)
    worded in that language (in English, ``sol.warnings``), the crank angle written as
    the solution writes it (:attr:`plans.plan.Solution.shown_from`)."""
    at = sol.solver.at(sol.phi, lang, sol.shown_from)
    return [flag_words(f, at, lang) for f in sol.flags]


def _inputs_said(sol: Solution, acc: bool) -> bool:
    """Whether the plan's known vectors are other than a uniform crank's (ω1 = const)."""
    mech = sol.mechanism
    rates = mech.inputs_at(sol.phi)
    return (len(mech.drivers) > 1 or mech.driver.linear
            or (acc and any(float(ddq) != 0 for _, _, ddq in rates)))


def _inputs(sol: Solution, plan, lang: str, said: dict[str, str]) -> tuple[list[str], str]:
    """The known vectors every input lays off from the pole, and the value of the first
    (its own velocity or acceleration), from which the plan's scale is taken: a crank's
    ω·l and ω²·l with ε·l ⊥ it where it accelerates; a slider's velocity and acceleration
    along its guide, as given. As the uniform crank's lines do, ω is carried with seven
    digits, each result is worked out from the numbers its line shows and printed with six,
    and the first value is the one the scale's line carries (``said``: the numbers printed
    so far for this position)."""
    t, u = T[lang], UNITS[lang]

    def n(x, digits=4):
        return num(float(x), digits, lang)

    acc = plan.kind == "acceleration"
    unit = u["m/s²"] if acc else u["m/s"]
    out: list[str] = []
    first = ""
    for d, (_, dq, ddq) in zip(sol.mechanism.drivers, sol.mechanism.inputs_at(sol.phi), strict=True):
        if d.linear:
            x = abs(ddq if acc else dq)
            x = 0.0 if x <= 1e-12 * max(abs(dq), abs(ddq)) else x  # sin π of a harmonic law
            out += [t["as" if acc else "vs"].format(t=d.tip, i=d.link, g=d.guide.label), ""]
            shown = n(x, 6)
            out.append(Step(f"{'a' if acc else 'V'}_{d.tip}", "", shown, unit).markdown())
        else:
            ws, ls = said.setdefault(d.omega_sym, n(abs(dq), 7)), n(d.length, 5)
            if not acc:
                out += [t["va"].format(t=d.tip, p=d.pivot, w=d.omega_sym), ""]
                shown = n(_shown(ws) * _shown(ls), 6)
                out.append(Step(f"V_{d.tip} = {d.omega_sym}·l_{d.pivot}{d.tip}", f"{ws}·{ls}", shown,
                                unit).markdown())
            elif ddq == 0:
                out += [t["aa"].format(t=d.tip, p=d.pivot, w=d.omega_sym), ""]
                shown = n(_shown(ws) ** 2 * _shown(ls), 6)
                out.append(Step(f"a_{d.tip} = {d.omega_sym}²·l_{d.pivot}{d.tip}", f"{ws}²·{ls}", shown,
                                unit).markdown())
            else:
                e = f"ε{d.link}"
                es = n(abs(ddq), 7)
                an = n(_shown(ws) ** 2 * _shown(ls), 6)
                at = n(_shown(es) * _shown(ls), 6)
                shown = n(math.hypot(_shown(an), _shown(at)), 6)
                out += [t["aa_eps"].format(t=d.tip, p=d.pivot, e=e, ev=es,
                                           sense=t["sense"][1 if ddq > 0 else -1]), ""]
                out.append(Step(f"a^n_{d.tip}{d.pivot} = {d.omega_sym}²·l_{d.pivot}{d.tip}",
                                f"{ws}²·{ls}", an, unit).markdown())
                out.append(Step(f"a^τ_{d.tip}{d.pivot} = {e}·l_{d.pivot}{d.tip}", f"{es}·{ls}", at,
                                unit).markdown())
                out.append(Step(f"a_{d.tip} = √((a^n_{d.tip}{d.pivot})² + (a^τ_{d.tip}{d.pivot})²)",
                                f"√({an}² + {at}²)", shown, unit).markdown())
        first = first or shown
        out.append("")
    return out, first


def _drawn(length: float, mu_l: float, lang: str) -> str:
    """A link's segment on the drawing (mm) as the plan of positions prints it, from its
    length and μl as printed: ``l / μl`` to five digits."""
    return num(_shown(num(length, 5, lang)) / _shown(num(mu_l, 4, lang)), 5, lang)


def _shown(text: str) -> float:
    """The number a step printed (a decimal comma, a true minus), as a reader takes it."""
    try:
        return float(text.replace(",", ".").replace("−", "-"))
    except ValueError:
        return math.nan


def _plan_section(sol: Solution, plan, lang: str, number: int, title: str = "",
                  said: dict[str, str] | None = None) -> list[str]:
    """One plan's section. ``said``: the numbers printed so far for this position (a
    plan's segments by their ends, a relative velocity, a link's ω, a component by its
    label), shared by its two plans: a later step carries a number as it was printed,
    and computes its result from the numbers it shows (a teacher redoing a line gets
    its result; "V_CB = 0,4" had been followed by "0,39997 / 0,18"). A number carried on
    is printed with five digits, one more than a result."""
    t, u = T[lang], UNITS[lang]
    said = {} if said is None else said

    def n(x, d=4):
        return num(x, d, lang)

    def carry(key: str, value: float) -> str:
        return said.setdefault(key, n(value, 5))

    acc = plan.kind == "acceleration"
    mech, d = sol.mechanism, sol.mechanism.driver
    m = sol.scalar  # the record the plans were built from, on Python numbers
    unit = u["m/s²"] if acc else u["m/s"]
    mu = plan.mu
    sym = "a" if acc else "V"
    mus = "μa" if acc else "μv"
    pole = plan.pole
    head = t["accelerations"] if acc else t["velocities"]
    out = [f"## {number}. {head}" + (f" ({title})" if title else ""), ""]
    if mech.timing is None:
        out += [t["position"].format(phi=d.phi_sym, at=d.both(sol.phi, lang, sol.shown_from)), ""]
    else:  # laws in time: the instant, and where each input is then
        there = md_text(inputs_there(sol, lang))
        out += [t["position"].format(phi="t", at=f"{n(sol.phi, 6)} {u['s']} ({there})"), ""]
    tip = plan_name(d.tip)
    w1 = abs(d.omega)
    val = abs(plan.value(tip))
    # the first vector is drawn from ω1: ω1, V_A (a_A) and pa (πa) are carried with a digit
    # more than a segment (seven, six, six), so that what the plans find from pa keeps its
    # five digits right (a_S1 of a four-bar had drifted to 7,6284 from 7,6286)
    w1s = said.setdefault(d.omega_sym, n(w1, 7))
    ls = n(d.length, 5)
    if _inputs_said(sol, acc):  # a crank with ε, a slider input, two inputs: their own vectors
        lines, vs = _inputs(sol, plan, lang, said)
        out += lines
        out += [t["mua" if acc else "muv"].format(t=tip), ""]
    elif acc:
        out += [t["aa"].format(t=d.tip, p=d.pivot, w=d.omega_sym), ""]
        vs = n(_shown(w1s) ** 2 * _shown(ls), 6)
        out.append(Step(f"a_{d.tip} = {d.omega_sym}²·l_{d.pivot}{d.tip}", f"{w1s}²·{ls}", vs,
                        unit).markdown())
        # the classroom's order: a round μa taken, then the vector's length from it
        out += ["", t["mua"].format(t=tip), ""]
    else:
        out += [t["va"].format(t=d.tip, p=d.pivot, w=d.omega_sym), ""]
        if d.rpm:
            pis = n(math.pi, 8)
            w1s = said[d.omega_sym] = n(_shown(pis) * d.rpm / 30, 7)
            out.append(Step(f"{d.omega_sym} = π·n{d.link} / 30", f"{pis}·{n(d.rpm)} / 30",
                            w1s, u["rad/s"]).markdown())
        vs = n(_shown(w1s) * _shown(ls), 6)
        out.append(Step(f"V_{d.tip} = {d.omega_sym}·l_{d.pivot}{d.tip}", f"{w1s}·{ls}", vs, unit).markdown())
        out += ["", t["muv"].format(t=tip), ""]
    said[f"{sym}_{d.tip}"] = vs
    out.append(Step(mus, "", n(mu), u["mu_a" if acc else "mu_v"]).markdown())
    ps = said[_seg_key(plan, pole, tip)] = n(_shown(vs) / _shown(n(mu)), 6)
    out.append(Step(f"{pole}{tip} = {sym}_{d.tip} / {mus}", f"{vs} / {n(mu)}", ps, u["mm"]).markdown())
    out.append("")
    # the input link's other points (its centre of mass, a point a guide slides past)
    sims = [p for p in plan.points.values() if p.source.kind == "similarity"
            and _belongs(m, p.name, (d.link,))]
    if sims:  # headed as a group's points are
        out += _similar(sol, plan, sims, lang, said)
        out += [t["avalues" if acc else "values"], ""]
        out += [*_values(sol, plan, [p.name for p in sims], lang, said), ""]
    vplan = sol.velocity
    for g in m.groups:
        cons = g.acceleration if acc else g.velocity
        x = cons.point
        px = plan_name(x)
        pt = plan.points[px]
        out += [t["eqs"].format(x=x), "", f"- `{md_code(cons.equation)}`"]
        for sl in (g.group.s1, g.group.s2):  # a slot the tool named x3-x3: say what it is
            if (sl is not None and sl.guide.named_by_tool and sl.guide.link
                    and sl.guide.label.startswith(f"x{sl.guide.link}")):
                out.append(f"- {t['xk'].format(x=md_text(sl.guide.label), k=sl.guide.link)}")
        if acc:  # a block on a guide whose link translates: no Coriolis term, and why
            for sl in (g.group.s1, g.group.s2):
                if sl is not None and sl.guide.link and sl.guide.link in sol.solver.translating:
                    out.append(f"- {t['nocor'].format(k=sl.guide.link)}")
        for r in cons.routes:
            parts = []
            if r.base is not None and r.base in mech.frame:
                parts.append(f"{sym}_{r.base} = 0")
            for term in r.terms:
                a_, b_ = term.about
                rel = vplan.mm(plan_name(b_), plan_name(a_)) * vplan.mu  # 0 where it is rounding
                rels = said.get(f"V_{a_}{b_}") or n(rel, 5)  # as the velocity plan's section gave it
                if term.kind == "normal":
                    spans = n(abs(sol.positions[a_] - sol.positions[b_]), 5)
                    said[term.label] = n(_shown(rels) ** 2 / _shown(spans), 5)
                    out.append(f"- {t['normal'].format(x=a_, y=b_)}")
                    out.append("  " + Step(f"{term.label} = V_{a_}{b_}² / l_{a_}{b_}",
                                           f"{rels}² / {spans}", said[term.label], unit).markdown()[2:])
                else:
                    owner = m.point_link.get(a_) if a_ in m.coincident else m.point_link.get(b_)
                    w = abs(sol.omega[owner])
                    out.append(f"- {t['coriolis'].format(x=a_, y=b_, i=owner)}")
                    s = mech.slider_of(owner)
                    if s is not None and s.guide.link not in (0, owner):  # slides on a turning link
                        out.append(f"  {t['same_w'].format(i=owner, k=s.guide.link)}")
                    ws = said.get(f"ω{owner}") or n(w, 5)
                    said[term.label] = n(2 * _shown(ws) * _shown(rels), 5)
                    out.append("  " + Step(f"{term.label} = 2·ω{owner}·V_{a_}{b_}",
                                           f"2·{ws}·{rels}", said[term.label], unit).markdown()[2:])
                seg = _component_segment(plan, term.label)
                if seg:
                    s0, s1 = seg
                    ts = said.get(term.label) or n(plan.mm(s0, s1) * mu, 5)
                    ss = said[_seg_key(plan, s0, s1)] = n(_shown(ts) / _shown(n(mu)), 5)
                    out.append("  " + Step(f"{s0}{s1} = {term.label} / {mus}", f"{ts} / {n(mu)}",
                                           ss, u["mm"]).markdown()[2:])
            out.append(f"- {r.unknown}: {t['dir']} {md_text(r.relation)}"
                       + (f"; {', '.join(parts)}" if parts else ""))
        lines = pt.source.lines
        out += ["", t["build"].format(l0=_letter(plan, lines[0].through), r0=md_text(lines[0].relation),
                                      l1=_letter(plan, lines[1].through), r1=md_text(lines[1].relation),
                                      x=px), ""]
        # similarity points of the group's links, then values; a link that translates
        # has one velocity and one acceleration for all its points
        moving = tuple(k for k in (g.group.a, g.group.b) if k not in sol.solver.translating)
        sims = [p for p in plan.points.values() if p.source.kind == "similarity"
                and _belongs(m, p.name, moving)]
        out += _similar(sol, plan, sims, lang, said)
        out += [t["avalues" if acc else "values"], ""]
        out += _values(sol, plan, [px] + [p.name for p in sims], lang, said)
        for r in cons.routes:
            # the unknown read off the plan: from where its line was drawn to the point found
            if r.unknown_kind in ("relative", "tangential") or (
                    r.unknown_kind == "sliding" and r.base is not None):
                start = next((ln.through for ln in pt.source.lines if ln.unknown == r.unknown),
                             r.base and plan_name(r.base))
                mms = carry(_seg_key(plan, start, px), plan.mm(start, px))
                said[r.unknown] = n(_shown(mms) * _shown(n(mu)), 5)  # carried on: ω, a^n, a^k
                out.append(Step(f"{r.unknown} = {_letter(plan, start)}{px}·{mus}",
                                f"{mms}·{n(mu)}", said[r.unknown], unit).markdown())
        for k in (g.group.a, g.group.b):  # after the values above, as a list of its own
            if k in moving:
                continue
            own = list(dict.fromkeys([*mech.links[k].points,
                                      *(q for q, o in m.point_link.items() if o == k)]))
            same = [nm for nm in dict.fromkeys(plan_name(q) for q in own)
                    if nm in plan.points and nm != px and plan.points[nm].source.kind != "pole"]
            names = [_mech_name(sol, nm) for nm in same] + ([x] if x in own else [])
            if len(names) >= 2:  # a block with one point has nothing to equate
                eq = " = ".join(f"{sym}_{q}" for q in names)
                out += ["", t["translates"].format(i=k, eq=eq, what=t["acc" if acc else "vel"]), ""]
                out += _values(sol, plan, same, lang, said)
        out.append("")
        # ω or ε of the group's links that turn
        for r in cons.routes:
            if r.unknown_kind not in ("relative", "tangential"):
                continue
            A, B = _split(sol, r.unknown.split("_", 1)[1])  # "V_A3B" → A3, B
            if not A:
                continue
            link = m.point_link.get(A) if A in m.coincident else _common_link(mech, A, B)
            if link is None:
                continue
            spans = n(abs(sol.positions[A] - sol.positions[B]), 5)
            mag = abs(r.param)
            mag = mag if mag > plan.tiny else 0.0  # rounding, as the plan's segments
            mags = said.get(r.unknown) or n(mag, 5)
            val = (sol.epsilon if acc else sol.omega)[link]
            sense = t["sense"][int(math.copysign(1, val)) if val else 0]
            key = "eps" if acc else "omega"
            out += [t[key].format(i=link), ""]
            w = "ε" if acc else "ω"
            # ω is carried on into the Coriolis terms, ε into the inertia moments
            said[f"{w}{link}"] = n(_shown(mags) / _shown(spans), 5)
            out.append(Step(f"{w}{link} = {r.unknown} / l_{A}{B}", f"{mags} / {spans}", said[f"{w}{link}"],
                            (u["rad/s²"] if acc else u["rad/s"]) + (f", {sense}" if sense else ""))
                       .markdown())
            out.append("")
    return out


def _component_segment(plan, label):
    for v in plan.vectors:
        if v.label == label:
            return v.start, v.end
    return None


def _belongs(m, plan_point: str, links) -> bool:
    for name, owner in m.point_link.items():
        if plan_name(name) == plan_point:
            return owner in links
    return False


def _similar(sol: Solution, plan, sims, lang: str, said: dict[str, str]) -> list[str]:
    """The similarity theorem's steps for the plan points ``sims``: a point on the line
    of two known ones by the ratio of lengths, any other by its similar triangle."""
    if not sims:
        return []
    # English texts name the step by its figure (Norton's "velocity image"); Russian by
    # the theorem, «по теореме подобия», on either plan
    out = [T[lang]["sim"].format(plan=plan.kind), ""]
    for p in sims:
        s = p.source
        if s.in_line:
            out.append(_side(sol, plan, p.name, s.base, s.other, s.base, lang, said).markdown())
        else:  # the triangle is built on b0b1 from its two other sides, as on paper
            out.append(f"- `{s.equation}`:")
            out += ["  " + _side(sol, plan, p.name, s.base, s.other, end, lang, said).markdown()[2:]
                    for end in (s.base, s.other)]
    return [*out, ""]


def _side(sol: Solution, plan, x: str, b0: str, b1: str, end: str, lang: str,
          said: dict[str, str]) -> Step:
    """The similarity theorem's side ``end``–``x`` of a figure on the plan segment b0b1:
    end·x = b0b1·(END X) / (B0 B1), the link's segments as drawn at μl; b0b1 as printed
    before, and the side as it computes from the numbers shown, kept for the lines after."""
    X, B0, B1, END = (_mech_name(sol, n) for n in (x, b0, b1, end))
    w0, w1, e = (_letter(plan, n) for n in (b0, b1, end))  # a fixed point is the pole
    l_ex, l_bb = (_drawn(abs(sol.positions[q] - sol.positions[r]), sol.mu_l, lang)
                  for q, r in ((X, END), (B1, B0)))
    bb = said.setdefault(_seg_key(plan, b0, b1), num(plan.mm(b0, b1), 5, lang))
    side = said.setdefault(_seg_key(plan, end, x),
                           num(_shown(bb) * _shown(l_ex) / _shown(l_bb), 5, lang))
    return Step(f"{e}{x} = {w0}{w1}·{END}{X} / {B0}{B1}", f"{bb}·{l_ex} / {l_bb}", side,
                UNITS[lang]["mm"])


def _seg_key(plan, a: str, b: str) -> str:
    """The key of plan segment ab in a section's record of the numbers it printed, its
    ends as the note writes them (a fixed point's is the pole's)."""
    return f"{plan.kind}:{_letter(plan, a)}{_letter(plan, b)}"


def _values(sol: Solution, plan, names, lang: str, said: dict[str, str]) -> list[str]:
    """V_X = pX·μv (a_X = πX·μa) for the plan points ``names``, each segment as printed
    before where it was."""
    u = UNITS[lang]
    acc = plan.kind == "acceleration"
    sym, mus, pole = ("a" if acc else "V"), ("μa" if acc else "μv"), plan.pole
    loads = sol.mechanism.loads
    centres = {ms.centre for ms in loads.masses.values()} if loads is not None else set()
    unit = u["m/s²"] if acc else u["m/s"]
    out = []
    for name in names:
        mms = said.setdefault(_seg_key(plan, pole, name), num(plan.mm(pole, name), 5, lang))
        mus_ = num(plan.mu, 4, lang)
        X = _mech_name(sol, name)
        # a centre of mass's acceleration is carried on into its inertia force: five digits
        digits = 5 if acc and X in centres else 4
        said[f"{sym}_{X}"] = num(_shown(mms) * _shown(mus_), digits, lang)
        out.append(Step(f"{sym}_{X} = {pole}{name}·{mus}", f"{mms}·{mus_}", said[f"{sym}_{X}"],
                        unit).markdown())
    return out


def _mech_name(sol: Solution, plan_point: str) -> str:
    for name in sol.positions:
        if plan_name(name) == plan_point:
            return name
    return plan_point.upper()


def _split(sol: Solution, text: str) -> tuple[str | None, str | None]:
    """'A3B' → ('A3', 'B') using the known point names (longest first)."""
    names = sorted(sol.positions, key=len, reverse=True)
    for a in names:
        if text.startswith(a) and text[len(a):] in sol.positions:
            return a, text[len(a):]
    return None, None


def _common_link(mech, A: str, B: str) -> int | None:
    la, lb = set(mech.links_of(A)), set(mech.links_of(B))
    common = sorted((la & lb) - {0})
    return common[0] if common else None
