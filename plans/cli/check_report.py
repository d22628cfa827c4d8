"""The report of one checked measurement file, as text and as JSON, and what ``plans check``
of one file and of several share (the ``--tolerance`` option, the pictures' scale).
"""

from __future__ import annotations

import json
import math

from plans.check import verdict as ck
from plans.check.describe import lookalike_lines, unit_in
from plans.check.items import FORCE_PLANS, MU_KEY, MU_SYMBOL, SIGNED
from plans.cli.output import terminal
from plans.cli.words import WORDS
from plans.errors import InputError
from plans.fmt import (
    columns,
    from_x,
    json_angle,
    listing,
    notation_in,
    num,
    signed,
)
from plans.model import MU_UNIT
from plans.note.report import warnings

#: the PNG of the drawing: two pixels for each px of the SVG
PNG_SCALE = 2.0


def command_tolerance(args):
    """The tolerance ``--tolerance`` gives, over every file's own; None without it."""
    if args.tolerance is None:
        return None
    try:
        return ck.parse_tolerance(args.tolerance)
    except ValueError as exc:
        raise InputError("command line", f"--tolerance: {exc}") from None


def all_items(n: int, lang: str) -> str:
    """"All n items", as the number has it: the one item, both items, all 5 items; in
    Russian agreeing with it (обе величины, все 5 величин, все 21 величина).

    >>> [all_items(n, "en") for n in (1, 2, 3)]
    ['the one item', 'both items', 'all 3 items']
    >>> [all_items(n, "ru") for n in (1, 2, 3, 5, 21)]
    ['единственная величина', 'обе величины', 'все 3 величины', 'все 5 величин',
     'все 21 величина']
    """
    w = WORDS[lang]["check"]
    if n == 1:
        return w["one_item"]
    if n == 2:
        return w["two_items"]
    return w["all_items"].format(n=n, items=w["items"](n))


def _pct(x: float, lang: str) -> str:
    return signed(x, lang, 1)


def _sense(x: float, w) -> str:
    return w["ccw"] if x > 0 else w["cw"] if x < 0 else ""


def _row(d, lang, w) -> list[str]:
    it = d.item
    meas = num(it.measured, 4, lang)
    comp = num(abs(d.computed), 4, lang)
    if it.kind in SIGNED:
        if it.sense:
            meas += " " + _sense(it.sense, w)
        comp += " " + _sense(d.computed, w)
    verdict = w["ok"] if d.ok else w["bad"]
    if d.sense_ok is False:
        verdict += f" ({w['sense']})"
    name = it.name + ("" if it.kind == "segment" else f", {unit_in(it.unit, lang)}")
    dev = signed(d.deviation, lang, 2 if it.kind == "segment" else None)
    return [name, meas, comp, dev, _pct(d.percent, lang), verdict]


def to_text(result, lang: str = "en") -> str:
    w = WORDS[lang]["check"]
    meas = result.measurement
    sol = meas.solution
    mech = meas.mechanism
    # the user's texts one line each, no escape sequence or bidi control among them
    out = [f"{w['head']}: {terminal(meas.source)}"]
    if meas.title:
        out.append(f"  {terminal(meas.title)}")
    out.append(f"{w['mech']}: {terminal(mech.name_in(lang))} ({terminal(mech.source_in(lang))}), "
               f"{mech.driver.phi_sym} = "
               f"{mech.driver.both(sol.phi, lang, lo=sol.shown_from)}")
    mu = meas.mu

    given = [f"{MU_SYMBOL[plan]} = {num(mu[key], 4, lang)} {unit_in(MU_UNIT[key], lang)}"
             for plan, key in MU_KEY.items() if key in meas.given]
    given += _mu_F(meas, lang, w)
    out.append(f"{w['scales']}: {listing(given, lang) if given else w['none_given']}")
    out.append(f"{w['tol']}: {result.tolerance.describe(lang)}")
    # (the section's title, its items, whether they are values)
    groups = [(w["positions"], lambda it: it.kind == "segment" and it.plan == "positions", False),
              (w["velocity"], lambda it: it.kind == "segment" and it.plan == "velocity", False),
              (w["acceleration"], lambda it: it.kind == "segment" and it.plan == "acceleration", False),
              (w["values"], lambda it: it.kind != "segment" and it.plan not in FORCE_PLANS, True)]
    # the force analysis's items: each group's force plan, the lever, the forces computed
    forces = meas.forces
    for key in forces.keys if forces is not None else ():
        head = w["force_plan"].format(group=key, mu=num(forces.mu_F.get(key, 0.0), 4, lang))
        groups.append((head, lambda it, key=key: it.kind == "segment" and it.group == key, False))
    groups += [(w["lever"], lambda it: it.plan == "lever", False),
               (w["forces"], lambda it: it.plan == "force" and it.kind != "segment", True)]
    for head, pick, values in groups:
        devs = [d for d in result.deviations if pick(d.item)]
        if not devs:
            continue
        out.append("")
        out.append(head)
        out += columns([_row(d, lang, w) for d in devs], w["vcols"] if values else w["cols"],
                       right=range(1, 5))
    out.append("")
    n = len(result.deviations)
    failed = result.failed
    if not failed:
        out.append(w["all_ok"].format(all=all_items(n, lang)))
    else:
        out.append(w["some"].format(k=len(failed), n=n, items=w["items"](n),
                                    names=", ".join(d.item.name for d in failed)))
        out += diagnosis_lines(result, lang)

    for line in warnings(sol, lang):
        out.append(f"{w['warning']}: {line}")
    # the items' names in the notation of the language (a^τ_A3B in Russian), as the words
    return notation_in("\n".join(out) + "\n", lang)


def _mu_F(meas, lang: str, w) -> list[str]:
    """μF as the file gives it: one for every force plan, or one for each."""
    given = meas.forces.mu_F_given if meas.forces is not None else None
    if given is None:
        return []
    unit = unit_in("N/mm", lang)
    if not isinstance(given, dict):
        return [f"μF = {num(given, 4, lang)} {unit}"]
    return ["μF = " + w["mu_F_group"].format(mu=num(mu, 4, lang), group=g) for g, mu in given.items()]


def diagnosis_lines(result, lang: str = "en") -> list[str]:
    w = WORDS[lang]["check"]
    diag = result.diagnosis
    k = len(result.failed)
    if result.slips_only:
        # the look-alikes explain every item beyond tolerance: no "no single mistake"
        # above them, nor a mistake that explains only some of them
        c = diag.closest
        more = ([f"  {w['less'].format(what=c.mistake.describe(lang))}"]
                if c is not None and not c.unexplained else [])
        return [f"{w['diag']}: {w['slips']}", *lookalike_lines(result, lang), *more]
    if diag.best is None:
        lines = [f"{w['diag']}: {w['none']}"]
        c = diag.closest
        if c is not None:
            lines.append("  " + w["closest"].format(what=c.mistake.describe(lang),
                                                     ex=", ".join(c.explained),
                                                     un=", ".join(c.unexplained)))
        return lines + lookalike_lines(result, lang)
    b = diag.best
    lines = [f"{w['diag']}: {b.mistake.describe(lang)}."]
    if b.unexplained:
        ex = w["k_of"].format(e=len(b.explained), k=k, un=", ".join(b.unexplained))
    else:
        ex = w["all_of"].format(all=all_items(k, lang))
    lines.append(f"  {w['explains']}: {', '.join(b.explained)} ({ex})")
    lines.append(f"  {w['correction']}: {b.mistake.correction(lang)}")
    reported = {it.link for it in result.measurement.items if it.kind == "omega" and it.sense}
    for alt in diag.alternatives:
        line = f"  {w['also']}: {alt.mistake.describe(lang)}"
        ids = {m.link for m in (alt.mistake, b.mistake) if m.kind == "omega-sense"}
        if ids and not ids & reported:
            line += w["hint"].format(link=min(ids))
        lines.append(line)
    return lines + lookalike_lines(result, lang)


def _finding(f, lang: str):
    if f is None:
        return None
    m = f.mistake
    return {
        "kind": m.kind,
        "family": m.family,
        "plan": m.plan,
        "target": m.target,
        "description": m.describe(lang),
        "correction": m.correction(lang),
        "explains": list(f.explained),
        "unexplained": list(f.unexplained),
        "breaks": list(f.broken),
        "score": f.score,
    }


def _json_mu_F(meas) -> dict:
    """μF as the file gives it (N/mm): a number, or an object by group ("4–5")."""
    given = meas.forces.mu_F_given if meas.forces is not None else None
    return {} if given is None else {"mu_F": given}


def json_text(data) -> str:
    """``data`` as the JSON a check prints: never NaN or Infinity (a value that is not
    finite is null) and no −0.0 (it is 0.0).

    >>> json_text({"a": -0.0, "b": [float("inf"), 1.5]}).split()
    ['{', '"a":', '0.0,', '"b":', '[', 'null,', '1.5', ']', '}']
    """
    return json.dumps(_plain(data), ensure_ascii=False, indent=2, allow_nan=False) + "\n"


def _plain(x):
    if isinstance(x, float):
        return x + 0.0 if math.isfinite(x) else None  # + 0.0: no −0.0
    if isinstance(x, dict):
        return {k: _plain(v) for k, v in x.items()}
    if isinstance(x, list | tuple):
        return [_plain(v) for v in x]
    return x


def to_json(result, lang: str = "en") -> dict:
    """The check as data; the words of a finding (description, correction) and of a
    near-singular position's warning in ``lang``."""
    meas = result.measurement
    items = []
    for d in result.deviations:
        it = d.item
        extra = {"group": it.group} if it.group else {}  # a force plan's segment: its plan
        items.append({
            "key": it.key,
            "name": it.name,
            "kind": it.kind,
            "plan": it.plan,
            "from": it.start,
            "to": it.end,
            "link": it.link or None,
            "unit": it.unit,
            "measured": it.measured,
            "sense": {1: "ccw", -1: "cw"}.get(it.sense),
            "computed": abs(d.computed),
            "computed_sense": ({1: "ccw", -1: "cw"}.get(int(math.copysign(1, d.computed)))
                               if it.kind in SIGNED and d.computed else None),
            "deviation": d.deviation,
            "percent": d.percent if math.isfinite(d.percent) else None,
            "limit": d.limit,
            "ok": d.ok,
            **extra,
        })
    diag = result.diagnosis
    return {
        "file": meas.source,
        "mechanism": meas.mechanism.source,
        "phi_deg": json_angle(from_x(meas.solution.phi)),
        "angle_deg": json_angle(meas.mechanism.driver.file_angle(meas.solution.phi)),
        "scales": {k: v for k, v in meas.mu.items() if k in meas.given} | _json_mu_F(meas),
        "tolerance": {"percent": result.tolerance.percent, "mm": result.tolerance.mm},
        "items": items,
        "ok": result.ok,
        "failed": [d.item.name for d in result.failed],
        "warnings": warnings(meas.solution, lang),  # near-singular, as the text's last lines
        "diagnosis": None if result.ok else {
            "explained": diag.best is not None,
            "slips_only": result.slips_only,
            "best": _finding(diag.best, lang),
            "alternatives": [_finding(f, lang) for f in diag.alternatives],
            "closest": _finding(diag.closest, lang),
            "lookalikes": [{"item": lk.item, "kind": lk.kind, "other": lk.other,
                            "exact": lk.exact} for lk in diag.lookalikes],
            "tried": diag.tried,
        },
    }
