"""The words that name a mistake, in English and Russian, with numbers in the language's
own convention (a decimal comma in Russian)."""

from __future__ import annotations

from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from plans.check.replay import Mistake


PLAN_WORDS = {
    "en": {"velocity": "velocity plan", "acceleration": "acceleration plan",
           "positions": "plan of positions", "both": "both plans"},
    "ru": {"velocity": "план скоростей", "acceleration": "план ускорений",
           "positions": "план положений", "both": "оба плана"},
}


#: "on the plan": in Russian the plan's name in the prepositional case; both plans take no
#: article
PLAN_ON = {
    "en": {"velocity": "on the velocity plan", "acceleration": "on the acceleration plan",
           "positions": "on the plan of positions", "both": "on both plans"},
    "ru": {"velocity": "на плане скоростей", "acceleration": "на плане ускорений",
           "positions": "на плане положений", "both": "на обоих планах"},
}


def _fnum(x: float, lang: str) -> str:
    from plans.fmt import num

    return num(float(x), 3, lang)


def _times_ru(x: float) -> str:
    """"в 2 раза", "в 5 раз", "в 21 раз", "в 1,25 раза": раз agrees with the numeral as
    it is written; a fraction takes the genitive singular.

    >>> [_times_ru(x) for x in (2, 4, 5, 10, 11, 12, 20, 21, 22, 25, 1.25, 2.5)]
    ['в 2 раза', 'в 4 раза', 'в 5 раз', 'в 10 раз', 'в 11 раз', 'в 12 раз', 'в 20 раз',
     'в 21 раз', 'в 22 раза', 'в 25 раз', 'в 1,25 раза', 'в 2,5 раза']
    """
    text = _fnum(x, "ru")
    if not text.isdigit():  # a fraction, or an exponent
        return f"в {text} раза"
    from plans.fmt import ru_plural

    return f"в {text} {ru_plural(int(text), 'раз', 'раза', 'раз')}"


def _text(mk: Mistake, lang: str) -> tuple[str, str]:
    """(what the mistake is, the correction in the method's words)."""
    ru = lang == "ru"
    g = mk.get
    k = mk.kind
    if k == "coriolis-reversed":
        if ru:
            return (f"вектор ускорения Кориолиса {mk.target} направлен в обратную сторону",
                    f"поверните вектор относительной скорости {g('rel')} на 90° в сторону "
                    f"переносной угловой скорости {g('omega')}")
        return (f"the Coriolis vector {mk.target} points the wrong way",
                f"turn the relative velocity {g('rel')} by 90° in the sense of {g('omega')}")
    if k == "coriolis-omitted":
        if ru:
            return (f"ускорение Кориолиса {mk.target} не учтено",
                    f"отложите {mk.target} = 2·{g('omega')}·{g('rel')} (вектор {g('rel')}, "
                    f"повёрнутый на 90° в сторону {g('omega')}) перед линией относительного ускорения")
        return (f"the Coriolis acceleration {mk.target} is missing",
                f"lay off {mk.target} = 2·{g('omega')}·{g('rel')} ({g('rel')} turned by 90° in "
                f"the sense of {g('omega')}) before drawing the line of the sliding acceleration")
    if k in ("coriolis-half", "coriolis-double"):  # the 2 of 2·ω·V left out, or taken twice
        half = k == "coriolis-half"
        formula = f"{mk.target} = 2·{g('omega')}·{g('rel')}"
        if ru:
            return (f"ускорение Кориолиса {mk.target} вдвое {'меньше' if half else 'больше'}",
                    f"{formula}: {'не забудьте множитель 2' if half else 'множитель 2 учтён дважды'}")
        return (f"the Coriolis acceleration {mk.target} is {'half' if half else 'twice'} as long "
                "as it should be",
                f"{formula}: the factor 2 is {'missing' if half else 'taken twice'}")
    if k == "normal-reversed":
        X, Y = g("X"), g("Y")
        if g("driver"):
            if ru:
                return (f"ускорение {mk.target} кривошипа направлено от {Y} к {X}",
                        f"a_{X} = ω{g('driver')}²·l_{Y}{X} направлено от {X} к центру {Y}: "
                        f"π{X.lower()} ∥ {Y}{X}, от {X} к {Y}")
            return (f"the crank's acceleration {mk.target} points from {Y} to {X}",
                    f"a_{X} = ω{g('driver')}²·l_{Y}{X} is directed from {X} towards the centre {Y}: "
                    f"draw π{X.lower()} ∥ {Y}{X}, from {X} to {Y}")
        if ru:
            return (f"нормальное ускорение {mk.target} направлено в обратную сторону",
                    f"{mk.target} = V²_{X}{Y}/l_{X}{Y} направлено от точки {X} к центру {Y} (∥ {X}{Y})")
        return (f"the normal acceleration {mk.target} points the wrong way",
                f"{mk.target} = V_{X}{Y}²/l_{X}{Y} is directed from {X} towards the centre {Y} (∥ {X}{Y})")
    if k == "normal-omitted":
        X, Y = g("X"), g("Y")
        if ru:
            return (f"нормальное ускорение {mk.target} не учтено",
                    f"отложите {mk.target} = V²_{X}{Y}/l_{X}{Y} (∥ {X}{Y}, от {X} к {Y}) и проведите "
                    f"линию касательного ускорения ⊥ {X}{Y} через его конец")
        return (f"the normal acceleration {mk.target} is missing",
                f"lay off {mk.target} = V_{X}{Y}²/l_{X}{Y} (∥ {X}{Y}, from {X} to {Y}) and draw the "
                f"line of the tangential acceleration ⊥ {X}{Y} through its end")
    if k == "normal-swapped":
        X, Y = g("X"), g("Y")
        tan = g("tangential")
        if ru:
            return (f"нормальное ускорение {mk.target} и касательное {tan} перепутаны: "
                    f"{mk.target} отложено ⊥ {X}{Y}, линия {tan} проведена ∥ {X}{Y}",
                    f"{mk.target} = V²_{X}{Y}/l_{X}{Y} откладывается ∥ {X}{Y}, от {X} к центру {Y}; "
                    f"линия касательного ускорения {tan} проводится ⊥ {X}{Y} через его конец")
        return (f"the normal {mk.target} and the tangential {tan} swapped: {mk.target} laid off "
                f"⊥ {X}{Y}, the line of {tan} drawn ∥ {X}{Y}",
                f"{mk.target} = V_{X}{Y}²/l_{X}{Y} is laid off ∥ {X}{Y}, from {X} towards the centre "
                f"{Y}; the line of the tangential {tan} is drawn ⊥ {X}{Y} through its end")
    if k == "normal-length":
        from plans.fmt import num

        X, Y = g("X"), g("Y")
        own = num(float(g("own")), 4, lang)
        unit = "м" if ru else "m"
        # other lengths of the same ratio: the plans cannot tell which one was taken
        also = "".join(f" ({'или' if ru else 'or'} l_{w})" for w in g("also").split())
        if ru:
            return (f"нормальное ускорение {mk.target} вычислено по длине l_{g('wrong')}{also} "
                    f"вместо l_{X}{Y}",
                    f"{mk.target} = V²_{X}{Y}/l_{X}{Y}, где l_{X}{Y} = {own} {unit}: длина звена "
                    f"{X}{Y}, а не l_{g('wrong')}")
        return (f"the normal acceleration {mk.target} computed with l_{g('wrong')}{also} "
                f"instead of l_{X}{Y}",
                f"{mk.target} = V_{X}{Y}²/l_{X}{Y} with l_{X}{Y} = {own} {unit}, the length of "
                f"{X}{Y}, not l_{g('wrong')}")
    if k == "omega-sense":
        if ru:
            extra = (f"; вектор Кориолиса {g('coriolis')} тогда поворачивается не в ту сторону"
                     if g("coriolis") else "")
            return (f"угловая скорость {mk.target} взята с обратным направлением",
                    f"направление {mk.target} определяется направлением относительной скорости "
                    f"на плане скоростей{extra}")
        extra = (f"; with it the Coriolis vector {g('coriolis')} turns the wrong way"
                 if g("coriolis") else "")
        return (f"{mk.target} taken with the wrong sense",
                f"the sense of {mk.target} is that of the relative velocity on the velocity plan"
                f"{extra}")
    if k == "value-sense":
        X, Y = g("X"), g("Y")
        omega = g("value") == "omega"
        vec = f"V_{X}{Y}" if omega else f"a^t_{X}{Y}"
        if ru:
            what = (f"угловая скорость {mk.target} записана" if omega
                    else f"угловое ускорение {mk.target} записано")
            plan = "скоростей" if omega else "ускорений"
            return (f"{what} с обратным направлением; планы построены верно",
                    f"направление {mk.target} определяется по плану {plan}: это направление, "
                    f"в котором вектор {vec}, перенесённый в точку {X}, поворачивает звено "
                    f"вокруг точки {Y}")
        plan = "velocity" if omega else "acceleration"
        return (f"{mk.target} written with the wrong sense; the plans are right",
                f"read the sense of {mk.target} off the {plan} plan: it is the sense in which "
                f"{vec}, placed at {X}, turns the link about {Y}")
    if k == "crank-sense":
        from plans.fmt import SENSE

        X, Y = g("X"), g("Y")
        sense = SENSE[lang][1 if g("sense") == "ccw" else -1]
        if ru:
            return (f"{mk.target} (V_{X}) взята с обратным направлением",
                    f"отложите V_{X} ⊥ {Y}{X} в сторону вращения кривошипа ({mk.target} "
                    f"{sense}, как задано); с обратной {mk.target} все скорости и все ω "
                    "меняют направление (план скоростей отражён относительно полюса p), "
                    "ускорения и ε остаются прежними")
        return (f"{mk.target} (V_{X}) drawn with the wrong sense",
                f"lay off V_{X} ⊥ {Y}{X} in the sense the crank turns ({mk.target} {sense}, as "
                f"given); with {mk.target} reversed every velocity and every ω turns the other "
                "way (the velocity plan is reflected through the pole p), while the "
                "accelerations and ε stay as they are")
    if k == "line-swapped":
        on = PLAN_ON[lang][mk.plan]
        if ru:
            return (f"{on} линия {mk.target} проведена {g('wrong')} вместо {g('relation')}",
                    f"через точку {g('through')} проведите линию {g('relation')} "
                    f"(линия вектора {mk.target}), а не {g('wrong')}")
        return (f"{on} the line of {mk.target} is drawn {g('wrong')} instead of {g('relation')}",
                f"through {g('through')} draw the line {g('relation')} (the line of {mk.target}), "
                f"not {g('wrong')}")
    if k == "branch":
        if ru:
            return (f"{mk.target.replace('group', 'группа')} собрана в другом положении (другая сборка)",
                    f"постройте план положений с заданной сборкой группы: точка {g('point')} "
                    "на другой стороне; затем перестройте планы")
        return (f"{mk.target} is assembled the other way (the other branch)",
                f"draw the plan of positions with the given assembly of the group ({g('point')} "
                "on the other side), then redraw the plans")
    if k == "crank-omega":
        from plans.fmt import num

        X, Y, sym = g("X"), g("Y"), mk.target
        w, given = num(float(g("omega")), 4, lang), num(float(g("given")), 4, lang)
        fv, fa = _fnum(float(g("velocity")), lang), _fnum(float(g("acceleration")), lang)
        unit = "рад/с" if ru else "rad/s"
        how = (f"{sym} = π·n{mk.link}/30 = π·{num(float(g('rpm')), 4, lang)}/30 = {given} {unit}"
               if g("rpm") else f"{sym} = {given} {unit}")
        if ru:
            return (f"угловая скорость {sym} вычислена неверно: оба плана соответствуют {sym} = "
                    f"{w} {unit}, а не {given} {unit} (скорости ×{fv}, ускорения ×{fa})",
                    f"{how}; V_{X} = {sym}·l_{Y}{X}, a_{X} = {sym}²·l_{Y}{X}")
        return (f"{sym} computed wrongly: both plans fit {sym} = {w} {unit}, not {given} {unit} "
                f"(velocities ×{fv}, accelerations ×{fa})",
                f"{how}; V_{X} = {sym}·l_{Y}{X}, a_{X} = {sym}²·l_{Y}{X}")
    if k == "crank-angle":
        at, given = (g("at_ru"), g("given_ru")) if ru else (g("at"), g("given"))
        if ru:
            return (f"планы построены для положения кривошипа {at}, а не {given}",
                    f"изобразите кривошип на плане положений под углом {given} и постройте "
                    "планы для этого положения")
        return (f"the plans are drawn for the crank at {at}, not at {given}",
                f"draw the crank at {given} on the plan of positions and build the plans for "
                "that position")
    if k in ("scale", "scale-swapped"):
        from plans.check.measured import MU_KEY, MU_SYMBOL
        from plans.note.report import UNITS

        facs = dict(mk.info)
        fits = facs.pop("fits", None)
        example = facs.pop("example", None)
        parts = []
        for plan, f in facs.items():
            f = float(f)
            mu = MU_SYMBOL[plan]
            if ru:
                parts.append(f"{PLAN_WORDS[lang][plan]} {_times_ru(f)} крупнее "
                             f"(при указанном {mu})" if f > 1 else
                             f"{PLAN_WORDS[lang][plan]} {_times_ru(1 / f)} мельче "
                             f"(при указанном {mu})")
            else:
                parts.append(f"the {PLAN_WORDS[lang][plan]} is drawn {_fnum(f, lang)} times too large "
                             f"for the stated {mu}" if f > 1 else
                             f"the {PLAN_WORDS[lang][plan]} is drawn {_fnum(1 / f, lang)} times too "
                             f"small for the stated {mu}")
        what = "; ".join(parts)
        if fits is not None:
            (plan,) = facs
            mu, unit = MU_SYMBOL[plan], UNITS[lang][MU_KEY[plan]]
            what += (f": его отрезки соответствуют {mu} = {_fnum(float(fits), lang)} {unit}" if ru
                     else f": its segments fit {mu} = {_fnum(float(fits), lang)} {unit}")
            if float(fits) == 1.0 and plan != "positions":  # values in SI written as lengths
                what += (", то есть записаны величины в единицах СИ, а не отрезки в мм" if ru
                         else ", that is, the values in SI units are written, not the lengths in mm")
        if k == "scale-swapped":
            what = ("μv и μa перепутаны: " if ru else "μv and μa swapped: ") + what
        positions = set(facs) == {"positions"}
        if fits is not None:
            value = ("длина" if ru else "length") if positions else ("величина" if ru else "value")
            if ru:
                return (what, f"постройте план при записанном {mu} (отрезок = {value} / {mu}) "
                              f"или запишите тот {mu}, при котором он построен")
            return (what, f"draw the plan at the {mu} written down (segment = {value} / {mu}), or "
                          f"write down the {mu} it was drawn at")
        if positions:
            ex = example or "AB"
            if ru:
                return (what, f"отрезок плана положений = длина звена / μl: {ex} = l_{ex}/μl, "
                              "в мм; проверьте степень 10")
            return (what, f"a segment of the plan of positions is the link's length divided by "
                          f"μl: {ex} = l_{ex}/μl, in mm; check the power of 10")
        if ru:
            return (what, "длина отрезка = величина / масштабный коэффициент: pa = V_A/μv, "
                          "πa = a_A/μa, в мм; проверьте степень 10 и какой μ к какому плану")
        return (what, "a segment is the value divided by its own scale factor: pa = V_A/μv, "
                      "πa = a_A/μa, in mm; check the power of 10 and which μ belongs to which plan")
    if k == "term-scale":
        f = float(mk.factor.real)
        if ru:
            return (f"{mk.target} отложено {_times_ru(max(f, 1 / f))} "
                    + ("длиннее" if f > 1 else "короче"),
                    f"вычислите {mk.target} в единицах СИ (длины в м: l = отрезок·μl) и разделите на μa")
        return (f"{mk.target} is drawn {_fnum(max(f, 1 / f), lang)} times too "
                + ("long" if f > 1 else "short"),
                f"compute {mk.target} in SI units (lengths in m: l = segment·μl), then divide by μa")
    if k.startswith("similarity"):
        how = g("how")
        eq = g("equation")
        on = PLAN_ON[lang][mk.plan]
        if how.startswith("sibling:"):
            other = how.split(":", 1)[1]
            if ru:
                return (f"точка {mk.target} {on} найдена по отношению для точки {other}",
                        f"по теореме подобия: {eq}")
            return (f"{mk.target} {on} found with the ratio meant for {other}",
                    f"by similarity: {eq}")
        if how == "inverse":
            if ru:
                return (f"точка {mk.target} {on} найдена по обратному отношению отрезков",
                        f"по теореме подобия: {eq} (отрезок плана / отрезок звена одинаковы для всех точек звена)")
            return (f"{mk.target} {on} found with the ratio of the wrong segments (inverted)",
                    f"by similarity: {eq} (plan segment / link segment is the same for every point of the link)")
        if how == "end":
            if ru:
                return (f"точка {mk.target} {on} отложена от другого конца отрезка "
                        f"{g('base')}{g('other')}: от {g('other')}, а не от {g('base')}",
                        f"по теореме подобия: {eq}, отсчитывая от {g('base')}")
            return (f"{mk.target} {on} laid off from the wrong end of "
                    f"{g('base')}{g('other')}: from {g('other')}, not from {g('base')}",
                    f"by similarity: {eq}, measured from {g('base')}")
        if how == "side":
            if ru:
                return (f"точка {mk.target} {on} отложена по другую сторону от {g('base')}",
                        f"по теореме подобия: {eq}, в ту же сторону, что и на звене")
            return (f"{mk.target} {on} laid off on the wrong side of {g('base')}",
                    f"by similarity: {eq}, in the same direction as on the link")
        if ru:
            return (f"фигура для точки {mk.target} {on} построена зеркально",
                    f"по теореме подобия: {eq}; обход букв на плане тот же, что на звене, "
                    "фигура не зеркальная")
        return (f"the figure for {mk.target} {on} is mirrored",
                f"by similarity: {eq}, with the letters in the same order round the figure as "
                "on the link, not mirrored")
    return (k, "")
