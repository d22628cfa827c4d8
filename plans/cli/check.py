"""``plans check MEAS.toml``: a hand-drawn plan against the computed one, and the mistake.

Exit status: 0 every item within tolerance, 1 something is not, 2 bad input. Several
files (``plans check students/*.toml``) are checked by :mod:`plans.cli.check_batch`,
one summary table.
"""

from __future__ import annotations

import json
import math

from plans.cli.common import EXIT_DEVIATIONS, EXIT_OK, warn, write_output
from plans.errors import InputError
from plans.fmt import (
    columns,
    from_x,
    json_angle,
    listing,
    notation_in,
    num,
    ru_plural,
    signed,
)


def configure(p) -> None:
    p.add_argument("file", metavar="MEAS.toml", nargs="+",
                   help="the measurement file: mechanism, crank position, the student's scale "
                        "factors and the segments measured on the drawing (mm). Several "
                        "files: one summary table, a row per file (file, title, mechanism, "
                        "verdict, diagnosis); a file that cannot be checked is a row of "
                        "its own. Exit status the worst of theirs: 3 an internal error, "
                        "else 2 bad input, else 1 beyond tolerance, else 0")
    p.add_argument("--tolerance", metavar="TOL",
                   help='allowed deviation, e.g. "5%%", "1mm" or "5%%,1mm" '
                        "(default: the larger of 1 mm and 5 %%)")
    p.dash_values = ("--tolerance",)  # "--tolerance -5%" is a wrong tolerance, said as one
    p.add_argument("--json", action="store_true",
                   help="machine-readable output (several files: a list, one object per file)")
    p.add_argument("--svg", metavar="OUT.svg|DIR",
                   help="also draw the student's plan over the computed one (several files: "
                        "a folder, DIR/STEM.svg for each file checked)")
    p.add_argument("--png", metavar="OUT.png|DIR",
                   help="the same drawing as a PNG (needs cairosvg: pip install "
                        "'vector-plans[export]'; several files: a folder, as --svg)")
    p.add_argument("--lang", choices=("en", "ru"), default="en",
                   help="language of the report (ru: decimal commas)")
    p.add_argument("-o", "--output", metavar="FILE",
                   help="write the report (several files: the table) to FILE instead of stdout")


def command_tolerance(args):
    """The tolerance ``--tolerance`` gives, over every file's own; None without it."""
    from plans.check import verdict as ck

    if args.tolerance is None:
        return None
    try:
        return ck.parse_tolerance(args.tolerance)
    except ValueError as exc:
        raise InputError("command line", f"--tolerance: {exc}") from None


def run(args) -> int:
    if len(args.file) > 1:
        from plans.cli.check_batch import run as run_batch

        return run_batch(args, args.file)
    args.file = args.file[0]
    from plans.check import verdict as ck
    from plans.cli.common import claim_inputs, picture_names

    claim_inputs(args, [args.file])
    picture_names(args, {".svg": ("--svg", "svg"), ".png": ("--png", "png")})
    if args.png:
        from drawing import export

        export.require()  # before anything is computed
    meas = ck.load(args.file)
    claim_inputs(args, meas.inputs[1:])
    result = ck.check(meas, command_tolerance(args))  # None: the file's own, or the default
    files = []  # all built before any is written
    if args.svg or args.png:
        from drawing.overlay import overlay_svg

        svg = overlay_svg(result, lang=args.lang)
        if args.svg:
            files.append((args.svg, svg))
        if args.png:
            from drawing import export

            files.append((args.png, export.png_bytes(svg, scale=PNG_SCALE)))
    if args.json:
        text = json.dumps(to_json(result, args.lang), ensure_ascii=False, indent=2) + "\n"
    else:
        text = to_text(result, args.lang)
    for path, data in [(args.output, text), *files]:
        write_output(path, data)
    for w in result.measurement.solution.warnings:  # as solve and report: on stderr too
        warn("check", w)
    return EXIT_OK if result.ok else EXIT_DEVIATIONS


#: the PNG of the drawing: two pixels for each px of the SVG
PNG_SCALE = 2.0


# ---------------------------------------------------------------------------------------

WORDS = {
    "en": {
        "head": "Check of a hand-drawn plan",
        "mech": "Mechanism",
        "scales": "Student's scale factors",
        "none_given": "none given",
        "tol": "Tolerance",
        "cols": ("segment", "measured", "computed", "deviation", "%", "verdict"),
        "vcols": ("value", "student", "computed", "deviation", "%", "verdict"),
        "positions": "Plan of positions (μl), mm",
        "velocity": "Velocity plan (pole p, μv), mm",
        "acceleration": "Acceleration plan (pole π, μa), mm",
        "values": "Values the student computed",
        "ok": "ok",
        "bad": "BEYOND",
        "sense": "wrong sense",
        "all_ok": "Overall: {all} within tolerance.",
        "some": "Overall: {k} of {n} {items} beyond tolerance: {names}.",
        "diag": "Diagnosis",
        "none": "no single mistake explains this.",
        "slips": "the plans are right; the items beyond tolerance are slips in measuring or writing down:",
        "less": "or, less closely: {what}",
        "closest": "closest: {what}; it explains {ex} but not {un}",
        "explains": "explains",
        "all_of": "{all} beyond tolerance",
        "like_segment": "{item} = {m} mm is the length of {other} ({exact} mm): measured from the wrong point?",
        "like_swapped": "{item} = {m} mm is the length of {other} ({exact} mm): are {item} and {other} swapped?",
        "like_value": "{item} = {m} is {other} in {unit} ({exact}): a segment is {other}/{mu}, in mm",
        "like_length": "{item} = {m} is the length of {other} in mm ({exact} mm): the value is {other}·{mu}, in {unit}",
        "k_of": "{e} of the {k} items beyond tolerance; not {un}",
        "correction": "correction",
        "also": "equally consistent with",
        "hint": ' (the sense of ω{link} tells them apart: give it in [values], e.g. omega{link} = "4.8 ccw")',
        "warning": "warning",
        "ccw": "ccw",
        "cw": "cw",
    },
    "ru": {
        "head": "Проверка плана, построенного вручную",
        "mech": "Механизм",
        "scales": "Масштабные коэффициенты студента",
        "none_given": "не заданы",
        "tol": "Допуск",
        "cols": ("отрезок", "измерено", "расчёт", "отклонение", "%", "вывод"),
        "vcols": ("величина", "студент", "расчёт", "отклонение", "%", "вывод"),
        "positions": "План положений (μl), мм",
        "velocity": "План скоростей (полюс p, μv), мм",
        "acceleration": "План ускорений (полюс π, μa), мм",
        "values": "Величины, вычисленные студентом",
        "ok": "в допуске",
        "bad": "ВНЕ ДОПУСКА",
        "sense": "не то направление",
        "all_ok": "Итог: {all} в допуске.",
        "some": "Итог: {k} из {n} вне допуска: {names}.",
        "diag": "Диагноз",
        "none": "ни одна отдельная ошибка этого не объясняет.",
        "slips": "планы построены верно; отклонения — ошибки измерения или записи отдельных величин:",
        "less": "или, с меньшей точностью: {what}",
        "closest": "ближе всего: {what}; объясняет {ex}, но не {un}",
        "explains": "объясняет",
        "all_of": "{all} вне допуска",
        "k_of": "{e} из {k} величин вне допуска; не объясняет {un}",
        "correction": "исправление",
        "also": "столь же хорошо объясняет",
        "hint": ' (их различает направление ω{link}: укажите его в [values], например omega{link} = "4,8 против ч.с.")',
        "warning": "предупреждение",
        "like_segment": "{item} = {m} мм — это длина {other} ({exact} мм): отрезок измерен не от той точки?",
        "like_swapped": "{item} = {m} мм — это длина {other} ({exact} мм): {item} и {other} перепутаны?",
        "like_value": "{item} = {m} — это {other} в {unit} ({exact}): отрезок равен {other}/{mu}, в мм",
        "like_length": "{item} = {m} — это длина {other} в мм ({exact} мм): величина равна {other}·{mu}, в {unit}",
        "ccw": "против ч.с.",
        "cw": "по ч.с.",
    },
}


def _items(n: int, lang: str) -> str:
    """The noun after "all n": "items" / "item"; in Russian it agrees with the number
    (все 21 величина, все 2 величины, все 5 величин).

    >>> _items(1, "en"), _items(2, "ru"), _items(5, "ru"), _items(21, "ru"), _items(12, "ru")
    ('item', 'величины', 'величин', 'величина', 'величин')
    """
    if lang != "ru":
        return "item" if n == 1 else "items"
    return ru_plural(n, "величина", "величины", "величин")


def _all(n: int, lang: str) -> str:
    """"All n items", as the number has it: the one item, both items, all 5 items; in
    Russian agreeing with it (обе величины, все 5 величин, все 21 величина).

    >>> [_all(n, "en") for n in (1, 2, 3)]
    ['the one item', 'both items', 'all 3 items']
    >>> [_all(n, "ru") for n in (1, 2, 3, 5, 21)]
    ['единственная величина', 'обе величины', 'все 3 величины', 'все 5 величин', 'все 21 величина']
    """
    if n == 1:
        return "единственная величина" if lang == "ru" else "the one item"
    if n == 2:
        return "обе величины" if lang == "ru" else "both items"
    return f"{'все' if lang == 'ru' else 'all'} {n} {_items(n, lang)}"


def _pct(x: float, lang: str) -> str:
    return signed(x, lang, 1)


def _u(unit: str, lang: str) -> str:
    """A unit written in English, in ``lang``: the note's own words (report.UNITS)."""
    from plans.note.report import UNITS

    if lang == "en":
        return unit
    return next((UNITS[lang][k] for k, v in UNITS["en"].items() if v == unit), unit)


def plan_unit(plan: str | None, lang: str) -> str:
    """The unit of a value of the velocity plan (m/s) or of the acceleration plan
    (m/s²), in ``lang``."""
    return _u("m/s" if plan == "velocity" else "m/s²", lang)


def _sense(x: float, w) -> str:
    return w["ccw"] if x > 0 else w["cw"] if x < 0 else ""


def _row(d, lang, w) -> list[str]:
    it = d.item
    meas = num(it.measured, 4, lang)
    comp = num(abs(d.computed), 4, lang)
    if it.kind in ("omega", "epsilon"):
        if it.sense:
            meas += " " + _sense(it.sense, w)
        comp += " " + _sense(d.computed, w)
    verdict = w["ok"] if d.ok else w["bad"]
    if d.sense_ok is False:
        verdict += f" ({w['sense']})"
    name = it.name + ("" if it.kind == "segment" else f", {_u(it.unit, lang)}")
    dev = signed(d.deviation, lang, 2 if it.kind == "segment" else None)
    return [name, meas, comp, dev, _pct(d.percent, lang), verdict]


def to_text(result, lang: str = "en") -> str:
    w = WORDS[lang]
    meas = result.measurement
    sol = meas.solution
    mech = meas.mechanism
    out = [f"{w['head']}: {meas.source}"]
    if meas.title:
        out.append(f"  {meas.title}")
    out.append(f"{w['mech']}: {mech.name_in(lang)} ({mech.source_in(lang)}), "
               f"{mech.driver.phi_sym} = "
               f"{mech.driver.both(sol.phi, lang, lo=sol.shown_from)}")
    mu = meas.mu
    from plans.check.measured import MU_KEY, MU_SYMBOL
    from plans.note.report import UNITS

    given = [f"{MU_SYMBOL[plan]} = {num(mu[key], 4, lang)} {UNITS[lang][key]}"
             for plan, key in MU_KEY.items() if key in meas.given]
    out.append(f"{w['scales']}: {listing(given, lang) if given else w['none_given']}")
    out.append(f"{w['tol']}: {result.tolerance.describe(lang)}")
    groups = [("positions", lambda it: it.kind == "segment" and it.plan == "positions"),
              ("velocity", lambda it: it.kind == "segment" and it.plan == "velocity"),
              ("acceleration", lambda it: it.kind == "segment" and it.plan == "acceleration"),
              ("values", lambda it: it.kind != "segment")]
    for key, pick in groups:
        devs = [d for d in result.deviations if pick(d.item)]
        if not devs:
            continue
        out.append("")
        out.append(w[key])
        out += columns([_row(d, lang, w) for d in devs],
                       w["vcols"] if key == "values" else w["cols"], right=range(1, 5))
    out.append("")
    n = len(result.deviations)
    failed = result.failed
    if not failed:
        out.append(w["all_ok"].format(all=_all(n, lang)))
    else:
        out.append(w["some"].format(k=len(failed), n=n, items=_items(n, lang),
                                    names=", ".join(d.item.name for d in failed)))
        out += diagnosis_lines(result, lang)
    from plans.note.report import warnings

    for line in warnings(sol, lang):
        out.append(f"{w['warning']}: {line}")
    # the items' names in the notation of the language (a^τ_A3B in Russian), as the words
    return notation_in("\n".join(out) + "\n", lang)


def diagnosis_lines(result, lang: str = "en") -> list[str]:
    w = WORDS[lang]
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
        ex = w["all_of"].format(all=_all(k, lang))
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


def lookalike_lines(result, lang: str = "en") -> list[str]:
    """One line per item beyond tolerance that no mistake explains but that matches
    something else (:func:`plans.check.lookalikes`)."""
    from plans.check.measured import MU_SYMBOL

    w = WORDS[lang]
    measured = {d.item.name: d.item for d in result.deviations}
    out = []
    for lk in result.diagnosis.lookalikes:
        it = measured[lk.item]
        if lk.kind in ("value", "length"):
            unit = plan_unit(it.plan, lang)
            exact = num(lk.exact, 4, lang) + (f" {unit}" if lk.kind == "value" else "")
            text = w[f"like_{lk.kind}"].format(
                item=lk.item, m=num(it.measured, 4, lang), other=lk.other, unit=unit,
                exact=exact, mu=MU_SYMBOL[it.plan])
        else:
            text = w[f"like_{lk.kind}"].format(item=lk.item, m=num(it.measured, 4, lang),
                                                other=lk.other, exact=num(lk.exact, 4, lang))
        out.append(f"  {text}")
    return out


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


def to_json(result, lang: str = "en") -> dict:
    """The check as data; the words of a finding (description, correction) and of a
    near-singular position's warning in ``lang``."""
    from plans.note.report import warnings

    meas = result.measurement
    items = []
    for d in result.deviations:
        it = d.item
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
                               if it.kind in ("omega", "epsilon") and d.computed else None),
            "deviation": d.deviation,
            "percent": d.percent if math.isfinite(d.percent) else None,
            "limit": d.limit,
            "ok": d.ok,
        })
    diag = result.diagnosis
    return {
        "file": meas.source,
        "mechanism": meas.mechanism.source,
        "phi_deg": json_angle(from_x(meas.solution.phi)),
        "angle_deg": json_angle(meas.mechanism.driver.file_angle(meas.solution.phi)),
        "scales": {k: v for k, v in meas.mu.items() if k in meas.given},
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
