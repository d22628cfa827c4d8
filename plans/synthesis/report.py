"""What ``plans synth`` prints: the requirements, θ, every solution in a table with the one
chosen and why, the family a free parameter spans, and the engine's check; or the same as
JSON (SI units, angles in degrees)."""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from plans.fmt import ITEM_SEPARATOR, columns, num
from plans.synthesis.design import Design
from plans.synthesis.mechfile import mechanism_dict, why_words
from plans.synthesis.note import given_line
from plans.synthesis.words import WORDS, grashof_in


def grashof_words(text: str, lang: str) -> str:
    """The engine's Grashof class (in English) as the report's language writes it."""
    return WORDS[lang]["grashof_said"].format(g=grashof_in(text, lang))


def _why(design: Design, lang: str) -> str:
    t = WORDS[lang]["why"]
    if design.problem.solution is not None:
        return t["asked"]
    slider = design.problem.kind == "crank-slider"
    if design.why == "given":
        return t["given_slider" if slider else "given"]
    if design.why in ("best", "size"):
        return t["size"] if design.why == "size" else t["best_slider" if slider else "best"]
    return t["only"]


def _rows(design: Design, lang: str) -> tuple[tuple[str, ...], list[list[str]]]:
    t = WORDS[lang]
    kind = design.problem.kind

    def n(x, d=5):
        return num(x, d, lang)

    def deg(x):
        return f"{num(math.degrees(x), 4, lang)}°"

    rows = []
    for i, s in enumerate(design.solutions):
        mark = f"{i + 1}{'*' if i == design.chosen else ''}"
        L, F = s.lengths, s.figures
        if kind == "crank-slider":
            rows.append([mark, n(L["AB"]), n(L["BC"]), n(L["e"]), n(F["lambda"], 4), n(F["eps"], 4),
                         deg(F["delta_m"]), deg(F["delta_w"])])
        elif kind == "slotted-link":
            rows.append([mark, n(L["AB"]), n(L["AC"]), n(L["CD"]), n(L["h"]), n(L["DE"]),
                         deg(F["alpha_max"])])
        else:
            side = t["sides"][s.branch] if kind == "crank-rocker" else "—"
            rows.append([mark, side, n(L["AB"]), n(L["BC"]), n(L["CD"]), n(L["AD"]),
                         deg(F["gamma_min"])])
    head = t["head_slider"] if kind == "crank-slider" else t["head_slotted"] \
        if kind == "slotted-link" else t["head"]
    return head, rows


def text(design: Design, check, lang: str = "en", written: str | None = None) -> str:
    """The report as ``plans synth`` prints it."""
    t = WORDS[lang]
    p, sol = design.problem, design.solution
    out = [t["title"][p.kind], "", f"{t['given']}: {given_line(design, lang)}"]
    if "theta" in sol.figures:
        K = p.given["K"]
        out.append(f"θ = 180°·(K − 1)/(K + 1) = 180°·({num(K, 4, lang)} − 1)/({num(K, 4, lang)} + 1) = "
                   f"{num(math.degrees(sol.figures['theta']), 6, lang)}°")
    out.append("")
    n = len(design.solutions)
    out.append(f"{t['solutions']} ({t['solutions_n'].format(n=n) if n > 1 else t['solution_1']})")
    head, rows = _rows(design, lang)
    out += columns(rows, head, right=tuple(range(2 if p.kind == "crank-rocker" else 1, len(head))))
    if n > 1:
        out.append(t["chosen"].format(i=design.chosen + 1, why=_why(design, lang)))
    fam = _family(design, lang)
    if fam:
        out += ["", *fam]
    if check is not None:
        out += ["", t["check"]]
        parts = []
        for r in check.rows:
            parts.append(f"{r.name} = {_shown(r, lang)}")
        out.append("  " + ITEM_SEPARATOR[lang].join(parts))
        if check.grashof:
            out.append(f"  {grashof_words(check.grashof, lang)}")
        out.append("  " + t["worst"].format(d=num(check.worst, 2, lang), tol="1e-12"))
    out += ["", t["file"].format(path=written) if written else t["no_file"]]
    return "\n".join(out) + "\n"


def _shown(r, lang: str) -> str:
    if r.unit == "°":
        return f"{num(math.degrees(r.engine), 8, lang)}°"
    if r.scale is not None and r.synthesis == 0.0:  # a position's distance from the given one
        return WORDS[lang]["off"].format(d=num(r.engine, 2, lang))
    unit = f" {WORDS[lang]['m']}" if r.unit == "m" else ""
    return f"{num(r.engine, 8, lang)}{unit}"


def _family(design: Design, lang: str) -> list[str]:
    """The family's figure over its free parameter, per branch: its range and its best."""
    t = WORDS[lang]
    if design.why not in ("best", "size") or not design.curves:
        return []
    out = []
    for cv in design.curves:
        ok = np.isfinite(cv.y)
        figure = t[cv.figure]
        if not ok.any():
            out.append(t["no_member"].format(label=t["curves"].get(cv.label, cv.label)))
            continue
        best = int(np.nanargmin(cv.y) if cv.figure == "delta_max" else np.nanargmax(cv.y))
        edge = best in (int(np.flatnonzero(ok)[0]), int(np.flatnonzero(ok)[-1]))
        x = cv.shown(cv.x)
        after = {"°": "°", "m": f" {t['m']}"}.get(cv.unit, "")
        out.append(t["family_row"].format(
            label=t["curves"].get(cv.label, cv.label), figure=figure, p=cv.parameter,
            lo=f"{num(math.degrees(np.nanmin(cv.y)), 4, lang)}°",
            hi=f"{num(math.degrees(np.nanmax(cv.y)), 4, lang)}°",
            ulo=f"{num(float(x[ok].min()), 4, lang)}{after}",
            uhi=f"{num(float(x[ok].max()), 4, lang)}{after}",
            best=f"{num(math.degrees(cv.y[best]), 4, lang)}°",
            u=f"{num(float(x[best]), 4, lang)}{after}")
            + (t["edge"] if edge else ""))
    cv = design.curves[0]
    return [t["family"].format(what=f"{t[cv.figure]}({cv.parameter})"), *out]


def as_json(design: Design, check, written: str | None = None) -> dict[str, Any]:
    """The report as data: SI units, angles in degrees."""
    p = design.problem

    def given(v):
        if isinstance(v, complex):
            return [v.real, v.imag]
        if isinstance(v, list):
            return [given(x) for x in v]
        return v

    def figure(k, v):
        return v if k in ("K", "H", "lambda", "eps", "sagitta", "crank_rocker") else math.degrees(v)

    angles = {"psi", "frame", "gamma_min", "delta_m", "delta_p", "delta_max", "alpha_max", "phi"}
    out: dict[str, Any] = {
        "kind": p.kind,
        "given": {(f"{k}_deg" if k in angles else k): (
            [math.degrees(x) for x in v] if k in angles and isinstance(v, list)
            else math.degrees(v) if k in angles else given(v)) for k, v in p.given.items()},
        "criterion": p.criterion,
        "chosen": design.chosen,
        "why": why_words(design),
        "solutions": [{
            "lengths": dict(s.lengths),
            "figures": {f"{k}_deg" if k not in ("K", "H", "lambda", "eps", "sagitta", "crank_rocker")
                        else k: figure(k, v) for k, v in s.figures.items()},
            "points": {k: [z.real, z.imag] for k, z in s.points.items()},
            "branch": s.branch,
        } for s in design.solutions],
        "family": [{"label": cv.label, "figure": cv.figure,
                    "parameter_name": cv.parameter, "parameter_unit": cv.unit,
                    "parameter": [float(x) for x in cv.shown(cv.x)],
                    "value_deg": [None if not math.isfinite(y) else math.degrees(float(y)) for y in cv.y]}
                   for cv in design.curves],
        "check": None if check is None else {
            "rows": [{"name": r.name, "unit": "deg" if r.unit == "°" else r.unit,
                      "synthesis": math.degrees(r.synthesis) if r.unit == "°" else r.synthesis,
                      "engine": math.degrees(r.engine) if r.unit == "°" else r.engine,
                      "error": r.error} for r in check.rows],
            "worst": check.worst, "grashof": check.grashof, "ok": check.ok},
        "mechanism": mechanism_dict(design),
        "file": written,
    }
    return out
