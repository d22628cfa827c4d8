"""The note's first section, the initial data (исходные данные), as a course's note opens:
every length the file gives, the masses and moments of inertia where it gives loads, each
input's speed, and the position studied; and where each input is at an instant of laws in
time. Split from :mod:`plans.note.report`, which writes the sections after it."""

from __future__ import annotations

import itertools
import math
import re

from plans.fmt import md_code, md_text, num
from plans.note.words import UNITS, T
from plans.plan.solution import Solution

__all__ = ["initial_data", "inputs_there", "law_row"]


def initial_data(sol: Solution, lang: str = "en") -> list[str]:
    """The note's first section, as a course's note opens (seed 000, §1.1): every length
    the file gives (each link's points from its first one, the joints of a link of three
    or more from one another: a ternary link's CE; the frame's points from one another;
    a fixed guide's offset e from the crank's pivot), the masses and J_S where the file
    gives loads, ω1 (and n1 where the file gives rpm) and the position, φ1 in the file's
    convention and from +x: an enumeration of steps, each with the words it needs (the
    note's PDF had run a table's cells together)."""
    t, u = T[lang], UNITS[lang]
    mech, d = sol.mechanism, sol.mechanism.driver

    def n(x):
        return num(x, 6, lang)

    rows: list[tuple[str, str, str]] = []  # (quantity, value, the words after it)
    seen: set[frozenset[str]] = set()

    def length(a: str, b: str, value: float) -> None:
        if value > 0 and frozenset((a, b)) not in seen:
            seen.add(frozenset((a, b)))
            rows.append((f"l_{a}{b}", f"{n(value)} {u['m']}", ""))

    frame = list(mech.frame)
    for i, a in enumerate(frame):
        for b in frame[i + 1:]:
            length(a, b, abs(mech.frame[b] - mech.frame[a]))
    centres = {m.centre for m in mech.loads.masses.values()} if mech.loads is not None else set()
    centres |= {p for p in mech.point_names() if re.fullmatch(r"S\d+", p)}
    joints = {p for p in mech.point_names() if len(mech.links_of(p)) >= 2 or p in mech.frame}
    for lid in sorted(mech.links):
        link = mech.links[lid]
        pts = link.points
        if not pts:
            continue
        first = link.axis[0] if link.axis else next(iter(pts))
        for p in pts:
            if p != first:
                length(first, p, abs(pts[p] - pts[first]))
        # a point off the link's axis is given by two lengths: from its second point too
        # (a ternary link BCE: CE); the joints of a link without an axis, from one another
        second = link.axis[1] if link.axis else None
        if second is not None:
            line = pts[second] - pts[first]
            along = []  # the points on the axis, centres of mass aside, in order along it
            for p in pts:
                across = ((pts[p] - pts[first]) * line.conjugate())
                if abs(across.imag) > 0:
                    length(second, p, abs(pts[p] - pts[second]))
                elif p not in centres:
                    along.append((across.real, p))
            along.sort()
            for (_, a), (_, b) in itertools.pairwise(along):  # B, C, E in line: CE too
                length(a, b, abs(pts[b] - pts[a]))
        else:
            others = [p for p in pts if p != first and p in joints]
            for i, a in enumerate(others):
                for b in others[i + 1:]:
                    length(a, b, abs(pts[b] - pts[a]))
    fixed = [s.guide for s in mech.sliders if s.guide.link == 0] if not d.linear else []
    pivot = mech.frame[d.pivot] if fixed else 0j  # a guide's offset e from the crank's pivot
    for g in dict.fromkeys(fixed):
        e = abs(((pivot - g.point) * g.direction.conjugate()).imag)
        name = "e" if len(fixed) == 1 else f"e_{g.label}"
        rows.append((name, f"{n(e)} {u['m']}", ", " + t["offset"].format(p=d.pivot, g=md_text(g.label))))
    loads = mech.loads
    if loads is not None:
        for lid in sorted(loads.masses):
            ms = loads.masses[lid]
            if ms.mass:
                rows.append((f"m{lid}", f"{n(ms.mass)} {u['kg']}", ""))
            if ms.J:
                rows.append((f"J_{ms.centre}", f"{n(ms.J)} {u['kgm2']}", ""))
    # each input's speed (and its acceleration where it has one) at the position studied
    for dd, (_, dq, ddq) in zip(mech.drivers, mech.inputs_at(sol.phi), strict=True):
        dq, ddq = float(dq), float(ddq)
        ddq = 0.0 if abs(ddq) <= 1e-12 * max(abs(dq), abs(ddq)) else ddq  # sin π of a harmonic law
        if dd.linear:
            rows.append((f"V_{dd.tip}", f"{n(abs(dq))} {u['m/s']}", ""))
            if ddq:
                rows.append((f"a_{dd.tip}", f"{n(abs(ddq))} {u['m/s²']}", ""))
            continue
        sense = t["sense"][1 if dq > 0 else -1 if dq < 0 else 0]
        rows.append((dd.omega_sym, f"{n(abs(dq))} {u['rad/s']}", f", {sense}" if sense else ""))
        if dd.rpm:
            rows.append((f"n{dd.link}", f"{n(dd.rpm)} {u['rpm']}", ""))
        if ddq:
            sense = t["sense"][1 if ddq > 0 else -1]
            rows.append((f"ε{dd.link}", f"{n(abs(ddq))} {u['rad/s²']}", f", {sense}"))
    if mech.timing is not None:  # laws in time: each law, then the instant studied
        for dd in mech.drivers:
            if dd.law is not None:
                rows.append(law_row(dd, lang))
        rows.append(("t", f"{n(sol.phi)} {u['s']}", f" ({md_text(inputs_there(sol, lang))})"))
    else:
        at, _, conv = d.both(sol.phi, lang, sol.shown_from).partition(" ")
        rows.append((d.phi_sym, at, f" {conv}" if conv else ""))
    out = [f"## 1. {t['initial']}", "", t["given"], ""]
    # an enumeration, as the seed writes its data: each item ends in ";", the last in "."
    out += [f"- `{md_code(f'{k} = {v}')}`{what}{';' if i < len(rows) - 1 else '.'}"
            for i, (k, v, what) in enumerate(rows)]
    return [*out, ""]


def inputs_there(sol: Solution, lang: str) -> str:
    """Where each input is at the instant ``sol.phi`` of laws in time: "φ1 = 40° from +x;
    s4 = 0 m along x-x" (a slider's rounding of 0 to 1e-12 m written as 0)."""
    mech = sol.mechanism
    parts = []
    for dd, (q, _, _) in zip(mech.drivers, mech.inputs_at(sol.phi), strict=True):
        q = float(q)
        q = 0.0 if dd.linear and abs(q) < 1e-12 else q
        parts.append(f"{dd.phi_sym} = {dd.both(q, lang)}")
    return "; ".join(parts)


def law_row(d, lang: str = "en") -> tuple[str, str, str]:
    """An input's law in time as the initial data gives it: ("s4(t)", "0 + 0,01·sin(15,6242·t
    + 180°) м", ", the law of input 4 in time"), in the engine's units (m or rad, s)."""
    t, u = T[lang], UNITS[lang]
    law = d.law

    def n(x):
        return num(float(x), 6, lang).replace("-", "−")

    def terms(*parts: tuple[float, str]) -> str:  # "a + b·t − c·t²", zero terms left out
        out = ""
        for x, tail in parts:
            if x == 0:
                continue
            sign = "−" if x < 0 else "+"
            out += (f" {sign} " if out else ("−" if x < 0 else "")) + n(abs(x)) + tail
        return out or "0"

    unit = u["m"] if d.linear else u["rad"]
    if law.kind == "uniform":
        formula = f"{terms((law.q0, ''), (law.rate, '·t'))} {unit}"
    elif law.kind == "accelerated":
        formula = f"{terms((law.q0, ''), (law.rate, '·t'), (law.accel / 2, '·t²'))} {unit}"
    elif law.kind == "harmonic":
        phase = math.degrees(law.phase)
        arg = f"{n(law.omega)}·t" + (f" {'−' if phase < 0 else '+'} {n(abs(phase))}°" if phase else "")
        formula = f"{terms((law.mean, ''), (law.amplitude, f'·sin({arg})'))} {unit}"
    else:
        return (f"{d.phi_sym}(t)", t["law_table"].format(n=len(law.t)), ", " + t["law"].format(i=d.link))
    return f"{d.phi_sym}(t)", formula, ", " + t["law"].format(i=d.link)
