"""The check in words: what a mistake is and how to correct it, and what a look-alike
measurement is, in any language of :data:`plans.check.words.WORDS`.

The functions here fill in the tables' templates; they hold no words of any language
themselves (a third language is a table, not an edit here). A mistake is read duck-typed
(:class:`plans.check.replay.Mistake`: kind, plan, target, factor, link and its words
``get(key)``).
"""

from __future__ import annotations

from plans.check.items import MU_KEY, MU_SYMBOL
from plans.check.words import WORDS
from plans.fmt import SENSE, notation_in, num
from plans.model import MU_UNIT
from plans.plan.values import plan_name


def unit_in(unit: str, lang: str) -> str:
    """A unit written in English, as ``lang`` writes it.

    >>> unit_in("m/s²", "ru"), unit_in("(m/s)/mm", "ru"), unit_in("m/s", "en")
    ('м/с²', '(м/с)/мм', 'm/s')
    """
    return WORDS[lang]["units"].get(unit, unit)


def plan_unit(plan: str | None, lang: str) -> str:
    """The unit of a value of the velocity plan (m/s) or of the acceleration plan
    (m/s²), in ``lang``."""
    return unit_in("m/s" if plan == "velocity" else "m/s²", lang)


def mistake_words(mk, lang: str = "en") -> tuple[str, str]:
    """(what the mistake is, the correction in the method's words), in ``lang``, before
    the notation is put in the language's own (:func:`plans.fmt.notation_in`)."""
    w = WORDS[lang]
    t = w["mistakes"]
    g = mk.get
    k = mk.kind
    fields = dict(mk.info) | {"target": mk.target, "link": mk.link}
    if k in ("coriolis-reversed", "coriolis-omitted", "coriolis-half", "coriolis-double",
             "normal-omitted", "normal-swapped", "line-swapped"):
        key = k
        fields |= {"tan": g("tangential"), "on": w["plan_on"].get(mk.plan, "")}
    elif k == "normal-reversed":
        key = "normal-reversed-crank" if g("driver") else k
        fields["x"] = plan_name(g("X"))
    elif k in ("crank-tangential-omitted", "crank-tangential-reversed"):
        key = k
        fields["x"] = plan_name(g("X"))
    elif k == "normal-length":
        key = k
        fields["own"] = num(float(g("own")), 4, lang)
        # other lengths of the same ratio: the plans cannot tell which one was taken
        fields["also"] = "".join(w["or_length"].format(link=x) for x in g("also").split())
    elif k == "omega-sense":
        key = k
        fields["coriolis_too"] = (t["omega-sense-coriolis"].format(coriolis=g("coriolis"))
                                  if g("coriolis") else "")
    elif k == "value-sense":
        omega = g("value") == "omega"
        key = "value-sense-omega" if omega else "value-sense-epsilon"
        fields["vector"] = f"V_{g('X')}{g('Y')}" if omega else f"a^t_{g('X')}{g('Y')}"
    elif k == "crank-sense":
        key = k
        fields["sense"] = SENSE[lang][1 if g("sense") == "ccw" else -1]
    elif k == "branch":
        key = k
        fields["group"] = mk.target.replace("group", w["group"])
    elif k == "crank-omega":
        key = k
        fields |= {"fits": num(float(g("omega")), 4, lang),
                   "given": num(float(g("given")), 4, lang),
                   "velocities": num(float(g("velocity")), 3, lang),
                   "accelerations": num(float(g("acceleration")), 3, lang)}
        if g("rpm"):
            fields["rpm"] = num(float(g("rpm")), 4, lang)
        fields["how"] = t["crank-omega-rpm" if g("rpm") else "crank-omega-how"].format(**fields)
    elif k == "crank-angle":
        key = k
        fields |= {"at": g(f"at_{lang}"), "given": g(f"given_{lang}")}
    elif k in ("scale", "scale-swapped"):
        return _scale_words(mk, lang)
    elif k in ("weight-omitted", "inertia-along", "inertia-omitted", "inertia-moment-omitted",
               "inertia-moment-reversed"):
        key = f"{k}-all" if mk.target == "all" else k
        fields["where"] = w["load_where"]["crank" if g("crank") else "group"]
    elif k == "force-reversed":
        key = "force-reversed-resistance" if g("what") == "resistance" else k
        fields["rule"] = w["rules"].get(g("rule"), w["rules"][""]).format(point=g("point"))
    elif k == "lever-unturned":
        key = k
    elif k == "moment-sense":
        key = f"{k}-{g('what')}"
    elif k == "force-scale":
        return _force_scale_words(mk, lang)
    elif k == "term-scale":
        f = float(mk.factor.real)
        key = "term-scale-long" if f > 1 else "term-scale-short"
        fields["times"] = w["times"](max(f, 1 / f))
    elif k.startswith("similarity"):
        how = g("how")
        fields["on"] = w["plan_on"].get(mk.plan, "")
        if how.startswith("sibling:"):
            key, fields["sibling"] = "similarity-sibling", how.split(":", 1)[1]
        elif how in ("inverse", "end", "side"):
            key = f"similarity-{how}"
        else:
            key = "similarity-mirrored"
    else:
        return (k, "")
    description, correction = t[key]
    return description.format(**fields), correction.format(**fields)


def _scale_words(mk, lang: str) -> tuple[str, str]:
    """A plan drawn at another scale than the one written down (or μv and μa swapped):
    by how much, what μ its segments fit, and how to draw a segment."""
    w = WORDS[lang]
    t = w["mistakes"]
    facs = dict(mk.info)
    fits = facs.pop("fits", None)
    example = facs.pop("example", None)
    parts = []
    for plan, f in facs.items():
        f = float(f)
        parts.append(t["scale-large" if f > 1 else "scale-small"].format(
            plan=w["plan"][plan], times=w["times"](f if f > 1 else 1 / f), mu=MU_SYMBOL[plan]))
    what = "; ".join(parts)
    mu = ""
    if fits is not None:
        (plan,) = facs
        mu = MU_SYMBOL[plan]
        what += t["scale-fits"].format(mu=mu, fits=num(float(fits), 3, lang),
                                       unit=unit_in(MU_UNIT[MU_KEY[plan]], lang))
        if float(fits) == 1.0 and plan != "positions":  # values in SI written as lengths
            what += t["scale-si"]
    if mk.kind == "scale-swapped":
        what = t["scale-swapped"].format(what=what)
    positions = set(facs) == {"positions"}
    if fits is not None:
        key = "scale-fitted"
    elif positions:
        key = "scale-positions"
    else:
        key = "scale"
    value = t["scale-length"] if positions else t["scale-value"]
    description, correction = t[key]
    fields = {"what": what, "mu": mu, "value": value, "example": example or "AB"}
    return description.format(**fields), correction.format(**fields)


def _force_scale_words(mk, lang: str) -> tuple[str, str]:
    """A force plan (or every one) drawn at another μF than the one written down."""
    w = WORDS[lang]
    t = w["mistakes"]
    f = float(mk.get("factor"))
    every = "-all" if mk.target == "all" else ""
    what = t[f"force-scale{every}-{'large' if f > 1 else 'small'}"].format(
        group=w["of_group"].format(key=mk.target), times=w["times"](f if f > 1 else 1 / f))
    if mk.get("fits"):
        what += t["force-scale-fits"].format(fits=num(float(mk.get("fits")), 3, lang))
    description, correction = t["force-scale-fitted" if mk.get("fits") else "force-scale"]
    return description.format(what=what), correction


def describe(mk, lang: str = "en") -> str:
    """What the mistake ``mk`` is, in ``lang`` and its notation."""
    return notation_in(mistake_words(mk, lang)[0], lang)


def correction(mk, lang: str = "en") -> str:
    """How to correct the mistake ``mk``, in ``lang`` and its notation."""
    return notation_in(mistake_words(mk, lang)[1], lang)


def lookalike_lines(result, lang: str = "en") -> list[str]:
    """One line per item beyond tolerance that no mistake explains but that matches
    something else (:func:`plans.check.lookalikes`), indented by two spaces."""
    words = WORDS[lang]["lookalikes"]
    measured = {d.item.name: d.item for d in result.deviations}
    out = []
    for lk in result.diagnosis.lookalikes:
        it = measured[lk.item]
        fields = {"item": lk.item, "m": num(it.measured, 4, lang), "other": lk.other,
                  "exact": num(lk.exact, 4, lang)}
        if lk.kind in ("value", "length"):
            unit = plan_unit(it.plan, lang)
            fields |= {"unit": unit, "mu": MU_SYMBOL[it.plan]}
            if lk.kind == "value":
                fields["exact"] += f" {unit}"
        out.append(f"  {words[lk.kind].format(**fields)}")
    return out
