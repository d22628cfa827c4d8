"""The check's words, one table per language: the names of the plans, the units, the
tolerance, each mistake of the plans and of the force analysis (what it is, and its
correction in the method's words) and each look-alike. A third language is a third table
of the same keys, registered in :data:`WORDS`; the functions that fill them in
(:mod:`plans.check.describe`) stay as they are. Numbers are written in the language's own
convention by :func:`plans.fmt.num`.

A mistake's templates are (description, correction) under its kind, or under its kind
and a variant where the method says it otherwise (``normal-reversed-crank``,
``value-sense-epsilon``, ``similarity-end``…). The fields a template may name are those
:func:`plans.check.describe.mistake_words` fills in.
"""

from __future__ import annotations

from plans.fmt import num, ru_plural


def _times_en(x: float) -> str:
    """"2", "1.25": a ratio, as "… is drawn 2 times too large" takes it."""
    return num(float(x), 3, "en")


def _times_ru(x: float) -> str:
    """"в 2 раза", "в 5 раз", "в 21 раз", "в 1,25 раза": раз agrees with the numeral as
    it is written; a fraction takes the genitive singular.

    >>> [_times_ru(x) for x in (2, 4, 5, 10, 11, 12, 20, 21, 22, 25, 1.25, 2.5)]
    ['в 2 раза', 'в 4 раза', 'в 5 раз', 'в 10 раз', 'в 11 раз', 'в 12 раз', 'в 20 раз',
     'в 21 раз', 'в 22 раза', 'в 25 раз', 'в 1,25 раза', 'в 2,5 раза']
    """
    text = num(float(x), 3, "ru")
    if not text.isdigit():  # a fraction, or an exponent
        return f"в {text} раза"
    return f"в {text} {ru_plural(int(text), 'раз', 'раза', 'раз')}"


EN = {
    "plan": {"velocity": "velocity plan", "acceleration": "acceleration plan",
             "positions": "plan of positions", "both": "both plans"},
    #: "on the plan": both plans take no article
    "plan_on": {"velocity": "on the velocity plan", "acceleration": "on the acceleration plan",
                "positions": "on the plan of positions", "both": "on both plans"},
    #: a unit as English writes it → as this language does
    "units": {},
    "tolerance": "the larger of {mm} mm and {percent} %",
    #: a ratio as the templates' {times} take it
    "times": _times_en,
    "group": "group",
    "or_length": " (or l_{link})",
    "mistakes": {
        "coriolis-reversed": (
            "the Coriolis vector {target} points the wrong way",
            "turn the relative velocity {rel} by 90° in the sense of {omega}"),
        "coriolis-omitted": (
            "the Coriolis acceleration {target} is missing",
            "lay off {target} = 2·{omega}·{rel} ({rel} turned by 90° in the sense of {omega}) "
            "before drawing the line of the sliding acceleration"),
        "coriolis-half": (
            "the Coriolis acceleration {target} is half as long as it should be",
            "{target} = 2·{omega}·{rel}: the factor 2 is missing"),
        "coriolis-double": (
            "the Coriolis acceleration {target} is twice as long as it should be",
            "{target} = 2·{omega}·{rel}: the factor 2 is taken twice"),
        "crank-tangential-omitted": (
            "the crank's tangential acceleration {target} is missing",
            "the crank accelerates: a_{X} = a^n_{X}{Y} + a^t_{X}{Y}, lay off a^t_{X}{Y} = ε{driver}·l_{Y}{X} "
            "⊥ {Y}{X} from the end of a^n_{X}{Y}, in the sense of ε{driver}"),
        "crank-tangential-reversed": (
            "the crank's tangential acceleration {target} points the wrong way",
            "a^t_{X}{Y} = ε{driver}·l_{Y}{X} is laid off ⊥ {Y}{X} in the sense of ε{driver}, not against it"),
        "normal-reversed-crank": (
            "the crank's acceleration {target} points from {Y} to {X}",
            "a_{X} = ω{driver}²·l_{Y}{X} is directed from {X} towards the centre {Y}: "
            "draw π{x} ∥ {Y}{X}, from {X} to {Y}"),
        "normal-reversed": (
            "the normal acceleration {target} points the wrong way",
            "{target} = V_{X}{Y}²/l_{X}{Y} is directed from {X} towards the centre {Y} (∥ {X}{Y})"),
        "normal-omitted": (
            "the normal acceleration {target} is missing",
            "lay off {target} = V_{X}{Y}²/l_{X}{Y} (∥ {X}{Y}, from {X} to {Y}) and draw the "
            "line of the tangential acceleration ⊥ {X}{Y} through its end"),
        "normal-swapped": (
            "the normal {target} and the tangential {tan} swapped: {target} laid off "
            "⊥ {X}{Y}, the line of {tan} drawn ∥ {X}{Y}",
            "{target} = V_{X}{Y}²/l_{X}{Y} is laid off ∥ {X}{Y}, from {X} towards the centre "
            "{Y}; the line of the tangential {tan} is drawn ⊥ {X}{Y} through its end"),
        "normal-length": (
            "the normal acceleration {target} computed with l_{wrong}{also} instead of l_{X}{Y}",
            "{target} = V_{X}{Y}²/l_{X}{Y} with l_{X}{Y} = {own} m, the length of "
            "{X}{Y}, not l_{wrong}"),
        "omega-sense": (
            "{target} taken with the wrong sense",
            "the sense of {target} is that of the relative velocity on the velocity plan"
            "{coriolis_too}"),
        "omega-sense-coriolis": "; with it the Coriolis vector {coriolis} turns the wrong way",
        "value-sense-omega": (
            "{target} written with the wrong sense; the plans are right",
            "read the sense of {target} off the velocity plan: it is the sense in which "
            "{vector}, placed at {X}, turns the link about {Y}"),
        "value-sense-epsilon": (
            "{target} written with the wrong sense; the plans are right",
            "read the sense of {target} off the acceleration plan: it is the sense in which "
            "{vector}, placed at {X}, turns the link about {Y}"),
        "crank-sense": (
            "{target} (V_{X}) drawn with the wrong sense",
            "lay off V_{X} ⊥ {Y}{X} in the sense the crank turns ({target} {sense}, as "
            "given); with {target} reversed every velocity and every ω turns the other "
            "way (the velocity plan is reflected through the pole p), while the "
            "accelerations and ε stay as they are"),
        "line-swapped": (
            "{on} the line of {target} is drawn {wrong} instead of {relation}",
            "through {through} draw the line {relation} (the line of {target}), not {wrong}"),
        "branch": (
            "{group} is assembled the other way (the other branch)",
            "draw the plan of positions with the given assembly of the group ({point} "
            "on the other side), then redraw the plans"),
        "crank-omega": (
            "{target} computed wrongly: both plans fit {target} = {fits} rad/s, not {given} "
            "rad/s (velocities ×{velocities}, accelerations ×{accelerations})",
            "{how}; V_{X} = {target}·l_{Y}{X}, a_{X} = {target}²·l_{Y}{X}"),
        "crank-omega-how": "{target} = {given} rad/s",
        "crank-omega-rpm": "{target} = π·n{link}/30 = π·{rpm}/30 = {given} rad/s",
        "crank-angle": (
            "the plans are drawn for the crank at {at}, not at {given}",
            "draw the crank at {given} on the plan of positions and build the plans for "
            "that position"),
        "scale-large": "the {plan} is drawn {times} times too large for the stated {mu}",
        "scale-small": "the {plan} is drawn {times} times too small for the stated {mu}",
        "scale-fits": ": its segments fit {mu} = {fits} {unit}",
        "scale-si": ", that is, the values in SI units are written, not the lengths in mm",
        "scale-swapped": "μv and μa swapped: {what}",
        "scale-fitted": (
            "{what}",
            "draw the plan at the {mu} written down (segment = {value} / {mu}), or "
            "write down the {mu} it was drawn at"),
        "scale-length": "length",
        "scale-value": "value",
        "scale-positions": (
            "{what}",
            "a segment of the plan of positions is the link's length divided by "
            "μl: {example} = l_{example}/μl, in mm; check the power of 10"),
        "scale": (
            "{what}",
            "a segment is the value divided by its own scale factor: pa = V_A/μv, "
            "πa = a_A/μa, in mm; check the power of 10 and which μ belongs to which plan"),
        "term-scale-long": (
            "{target} is drawn {times} times too long",
            "compute {target} in SI units (lengths in m: l = segment·μl), then divide by μa"),
        "term-scale-short": (
            "{target} is drawn {times} times too short",
            "compute {target} in SI units (lengths in m: l = segment·μl), then divide by μa"),
        "similarity-sibling": (
            "{target} {on} found with the ratio meant for {sibling}",
            "by similarity: {equation}"),
        "similarity-inverse": (
            "{target} {on} found with the ratio of the wrong segments (inverted)",
            "by similarity: {equation} (plan segment / link segment is the same for every "
            "point of the link)"),
        "similarity-end": (
            "{target} {on} laid off from the wrong end of {base}{other}: from {other}, "
            "not from {base}",
            "by similarity: {equation}, measured from {base}"),
        "similarity-side": (
            "{target} {on} laid off on the wrong side of {base}",
            "by similarity: {equation}, in the same direction as on the link"),
        "similarity-mirrored": (
            "the figure for {target} {on} is mirrored",
            "by similarity: {equation}, with the letters in the same order round the figure "
            "as on the link, not mirrored"),
        "weight-omitted": (
            "the weight {target} is left out of the force plans and the lever",
            "{target} = m{link}·g acts at {centre}, downwards: {where} and apply it on the lever "
            "at {image}"),
        "weight-omitted-all": (
            "the weights are left out of the force plans and the lever",
            "G = m·g of each link acts at its centre of mass, downwards: lay each off in the force "
            "plan of its group and apply it on the lever at the image of the centre of mass"),
        "inertia-along": (
            "the inertia force {target} is laid along the acceleration a_{centre} instead of "
            "against it",
            "{target} = −m{link}·a_{centre}: through {centre}, against the acceleration of the "
            "centre of mass (π{image} on the acceleration plan, turned round)"),
        "inertia-along-all": (
            "every inertia force is laid along the acceleration of its centre of mass instead "
            "of against it",
            "Φ = −m·a_S: each through its centre of mass S, against the acceleration a_S"),
        "inertia-omitted": (
            "the inertia force {target} is left out",
            "{target} = −m{link}·a_{centre} acts through {centre}: {where} and apply it on the "
            "lever at {image}"),
        "inertia-omitted-all": (
            "the inertia forces are left out",
            "Φ = −m·a_S of each link acts through its centre of mass S: lay each off in the "
            "force plan of its group and apply it on the lever at the image of S"),
        "inertia-moment-omitted": (
            "the inertia moment {target} is left out",
            "{target} = −J_S{link}·ε{link} enters the moment equations of link {link}, and the "
            "lever as two forces {target}/l ⊥ the link at the images of its joints"),
        "inertia-moment-omitted-all": (
            "the inertia moments are left out",
            "M_Φ = −J_S·ε of each link enters the moment equations of its link, and the lever "
            "as two forces M_Φ/l ⊥ the link at the images of its joints"),
        "inertia-moment-reversed": (
            "the inertia moment {target} has the wrong sense",
            "{target} = −J_S{link}·ε{link} turns against ε{link}"),
        "inertia-moment-reversed-all": (
            "every inertia moment has the wrong sense",
            "M_Φ = −J_S·ε turns against the ε of its link"),
        "force-reversed-resistance": (
            "the useful resistance {target} points the wrong way",
            "{target} acts on the output against its motion: on the working stroke against "
            "V_{point}, along the guide"),
        "force-reversed": (
            "the force {target} points the wrong way",
            "{target} acts {rule}"),
        "lever-unturned": (
            "on Zhukovsky's lever the forces are applied to the velocity plan as it is, not "
            "turned by 90° (or turned by 90° with it)",
            "turn the velocity plan by 90° (either way) and apply each force at the image of "
            "its point, keeping its own direction; h is the perpendicular from the pole p to "
            "the line of the force, and F_у·{pb} balances Σ ±F·h"),
        "moment-sense-balancing": (
            "{target} written with the wrong sense; the force analysis is right",
            "M_у balances the moments of the loads on the driving link about its pivot: it "
            "turns the other way than their sum"),
        "moment-sense-force": (
            "{target} written with the wrong sense; the force analysis is right",
            "F_у turns the crank in the sense of M_у: the sense in which Σ ±F·h on the lever "
            "needs it to balance"),
        "moment-sense-inertia": (
            "{target} written with the wrong sense; the force analysis is right",
            "{target} = −J_S·ε turns against the ε of its link"),
        "moment-sense-moment": (
            "{target} written with the wrong sense; the force analysis is right",
            "{target} turns as the mechanism file gives it"),
        "force-scale-large": "the force plan of {group} is drawn {times} times too large for "
                             "the stated μF",
        "force-scale-small": "the force plan of {group} is drawn {times} times too small for "
                             "the stated μF",
        "force-scale-all-large": "the force plans are drawn {times} times too large for the "
                                 "stated μF",
        "force-scale-all-small": "the force plans are drawn {times} times too small for the "
                                 "stated μF",
        "force-scale-fits": ": their segments fit μF = {fits} N/mm",
        "force-scale": (
            "{what}",
            "a segment of a force plan is the force divided by μF, in mm, and a force read "
            "off it is the segment times μF: check the power of 10"),
        "force-scale-fitted": (
            "{what}",
            "draw the force plan at the μF written down (segment = force / μF), or write "
            "down the μF it was drawn at"),
    },
    #: a force's direction as the file's rule gives it (README: Loads)
    "rules": {"against velocity": "against the velocity of {point}",
              "along velocity": "along the velocity of {point}",
              "against guide": "along the guide of its link, against its direction",
              "along guide": "along the guide of its link", "": "at the angle the file gives"},
    #: a group as a force plan's words name it
    "of_group": "group {key}",
    #: where a load left out goes: its group's force plan, or the driving link's equilibrium
    "load_where": {"group": "lay it off in the force plan of its group",
                   "crank": "take it into the driving link's equilibrium"},
    #: an item beyond tolerance that is, within tolerance, something else
    "lookalikes": {
        "segment": "{item} = {m} mm is the length of {other} ({exact} mm): measured from the "
                   "wrong point?",
        "swapped": "{item} = {m} mm is the length of {other} ({exact} mm): are {item} and "
                   "{other} swapped?",
        "value": "{item} = {m} is {other} in {unit} ({exact}): a segment is {other}/{mu}, in mm",
        "length": "{item} = {m} is the length of {other} in mm ({exact} mm): the value is "
                  "{other}·{mu}, in {unit}",
    },
}

RU = {
    "plan": {"velocity": "план скоростей", "acceleration": "план ускорений",
             "positions": "план положений", "both": "оба плана"},
    #: the plan's name in the prepositional case
    "plan_on": {"velocity": "на плане скоростей", "acceleration": "на плане ускорений",
                "positions": "на плане положений", "both": "на обоих планах"},
    "units": {"m": "м", "mm": "мм", "m/s": "м/с", "m/s²": "м/с²", "rad/s": "рад/с",
              "rad/s²": "рад/с²", "m/mm": "м/мм", "(m/s)/mm": "(м/с)/мм",
              "(m/s²)/mm": "(м/с²)/мм", "N": "Н", "N·m": "Н·м", "N/mm": "Н/мм"},
    "tolerance": "большее из {mm} мм и {percent} %",
    "times": _times_ru,
    "group": "группа",
    "or_length": " (или l_{link})",
    "mistakes": {
        "coriolis-reversed": (
            "вектор ускорения Кориолиса {target} направлен в обратную сторону",
            "поверните вектор относительной скорости {rel} на 90° в сторону "
            "переносной угловой скорости {omega}"),
        "coriolis-omitted": (
            "ускорение Кориолиса {target} не учтено",
            "отложите {target} = 2·{omega}·{rel} (вектор {rel}, повёрнутый на 90° в сторону "
            "{omega}) перед линией относительного ускорения"),
        "coriolis-half": (
            "ускорение Кориолиса {target} вдвое меньше",
            "{target} = 2·{omega}·{rel}: не забудьте множитель 2"),
        "coriolis-double": (
            "ускорение Кориолиса {target} вдвое больше",
            "{target} = 2·{omega}·{rel}: множитель 2 учтён дважды"),
        "crank-tangential-omitted": (
            "касательное ускорение {target} кривошипа не учтено",
            "кривошип вращается с ускорением: a_{X} = a^n_{X}{Y} + a^t_{X}{Y}, отложите a^t_{X}{Y} = "
            "ε{driver}·l_{Y}{X} ⊥ {Y}{X} от конца a^n_{X}{Y}, в сторону ε{driver}"),
        "crank-tangential-reversed": (
            "касательное ускорение {target} кривошипа направлено в обратную сторону",
            "a^t_{X}{Y} = ε{driver}·l_{Y}{X} откладывается ⊥ {Y}{X} в сторону ε{driver}, а не против неё"),
        "normal-reversed-crank": (
            "ускорение {target} кривошипа направлено от {Y} к {X}",
            "a_{X} = ω{driver}²·l_{Y}{X} направлено от {X} к центру {Y}: "
            "π{x} ∥ {Y}{X}, от {X} к {Y}"),
        "normal-reversed": (
            "нормальное ускорение {target} направлено в обратную сторону",
            "{target} = V²_{X}{Y}/l_{X}{Y} направлено от точки {X} к центру {Y} (∥ {X}{Y})"),
        "normal-omitted": (
            "нормальное ускорение {target} не учтено",
            "отложите {target} = V²_{X}{Y}/l_{X}{Y} (∥ {X}{Y}, от {X} к {Y}) и проведите "
            "линию касательного ускорения ⊥ {X}{Y} через его конец"),
        "normal-swapped": (
            "нормальное ускорение {target} и касательное {tan} перепутаны: "
            "{target} отложено ⊥ {X}{Y}, линия {tan} проведена ∥ {X}{Y}",
            "{target} = V²_{X}{Y}/l_{X}{Y} откладывается ∥ {X}{Y}, от {X} к центру {Y}; "
            "линия касательного ускорения {tan} проводится ⊥ {X}{Y} через его конец"),
        "normal-length": (
            "нормальное ускорение {target} вычислено по длине l_{wrong}{also} вместо l_{X}{Y}",
            "{target} = V²_{X}{Y}/l_{X}{Y}, где l_{X}{Y} = {own} м: длина звена "
            "{X}{Y}, а не l_{wrong}"),
        "omega-sense": (
            "угловая скорость {target} взята с обратным направлением",
            "направление {target} определяется направлением относительной скорости "
            "на плане скоростей{coriolis_too}"),
        "omega-sense-coriolis": "; вектор Кориолиса {coriolis} тогда поворачивается не в ту сторону",
        "value-sense-omega": (
            "угловая скорость {target} записана с обратным направлением; планы построены верно",
            "направление {target} определяется по плану скоростей: это направление, "
            "в котором вектор {vector}, перенесённый в точку {X}, поворачивает звено "
            "вокруг точки {Y}"),
        "value-sense-epsilon": (
            "угловое ускорение {target} записано с обратным направлением; планы построены верно",
            "направление {target} определяется по плану ускорений: это направление, "
            "в котором вектор {vector}, перенесённый в точку {X}, поворачивает звено "
            "вокруг точки {Y}"),
        "crank-sense": (
            "{target} (V_{X}) взята с обратным направлением",
            "отложите V_{X} ⊥ {Y}{X} в сторону вращения кривошипа ({target} "
            "{sense}, как задано); с обратной {target} все скорости и все ω "
            "меняют направление (план скоростей отражён относительно полюса p), "
            "ускорения и ε остаются прежними"),
        "line-swapped": (
            "{on} линия {target} проведена {wrong} вместо {relation}",
            "через точку {through} проведите линию {relation} (линия вектора {target}), "
            "а не {wrong}"),
        "branch": (
            "{group} собрана в другом положении (другая сборка)",
            "постройте план положений с заданной сборкой группы: точка {point} "
            "на другой стороне; затем перестройте планы"),
        "crank-omega": (
            "угловая скорость {target} вычислена неверно: оба плана соответствуют {target} = "
            "{fits} рад/с, а не {given} рад/с (скорости ×{velocities}, ускорения ×{accelerations})",
            "{how}; V_{X} = {target}·l_{Y}{X}, a_{X} = {target}²·l_{Y}{X}"),
        "crank-omega-how": "{target} = {given} рад/с",
        "crank-omega-rpm": "{target} = π·n{link}/30 = π·{rpm}/30 = {given} рад/с",
        "crank-angle": (
            "планы построены для положения кривошипа {at}, а не {given}",
            "изобразите кривошип на плане положений под углом {given} и постройте "
            "планы для этого положения"),
        "scale-large": "{plan} {times} крупнее (при указанном {mu})",
        "scale-small": "{plan} {times} мельче (при указанном {mu})",
        "scale-fits": ": его отрезки соответствуют {mu} = {fits} {unit}",
        "scale-si": ", то есть записаны величины в единицах СИ, а не отрезки в мм",
        "scale-swapped": "μv и μa перепутаны: {what}",
        "scale-fitted": (
            "{what}",
            "постройте план при записанном {mu} (отрезок = {value} / {mu}) "
            "или запишите тот {mu}, при котором он построен"),
        "scale-length": "длина",
        "scale-value": "величина",
        "scale-positions": (
            "{what}",
            "отрезок плана положений = длина звена / μl: {example} = l_{example}/μl, "
            "в мм; проверьте степень 10"),
        "scale": (
            "{what}",
            "длина отрезка = величина / масштабный коэффициент: pa = V_A/μv, "
            "πa = a_A/μa, в мм; проверьте степень 10 и какой μ к какому плану"),
        "term-scale-long": (
            "{target} отложено {times} длиннее",
            "вычислите {target} в единицах СИ (длины в м: l = отрезок·μl) и разделите на μa"),
        "term-scale-short": (
            "{target} отложено {times} короче",
            "вычислите {target} в единицах СИ (длины в м: l = отрезок·μl) и разделите на μa"),
        "similarity-sibling": (
            "точка {target} {on} найдена по отношению для точки {sibling}",
            "по теореме подобия: {equation}"),
        "similarity-inverse": (
            "точка {target} {on} найдена по обратному отношению отрезков",
            "по теореме подобия: {equation} (отрезок плана / отрезок звена одинаковы для "
            "всех точек звена)"),
        "similarity-end": (
            "точка {target} {on} отложена от другого конца отрезка {base}{other}: "
            "от {other}, а не от {base}",
            "по теореме подобия: {equation}, отсчитывая от {base}"),
        "similarity-side": (
            "точка {target} {on} отложена по другую сторону от {base}",
            "по теореме подобия: {equation}, в ту же сторону, что и на звене"),
        "similarity-mirrored": (
            "фигура для точки {target} {on} построена зеркально",
            "по теореме подобия: {equation}; обход букв на плане тот же, что на звене, "
            "фигура не зеркальная"),
        "weight-omitted": (
            "сила тяжести {target} не учтена в планах сил и на рычаге",
            "{target} = m{link}·g приложена в точке {centre} и направлена вниз: {where} и "
            "приложите к рычагу в точке {image}"),
        "weight-omitted-all": (
            "силы тяжести не учтены в планах сил и на рычаге",
            "G = m·g каждого звена приложена в его центре масс и направлена вниз: отложите "
            "каждую на плане сил своей группы и приложите к рычагу в образе центра масс"),
        "inertia-along": (
            "сила инерции {target} направлена по ускорению a_{centre}, а не против него",
            "{target} = −m{link}·a_{centre}: через точку {centre}, против ускорения центра масс "
            "(вектор π{image} плана ускорений, повёрнутый на 180°)"),
        "inertia-along-all": (
            "все силы инерции направлены по ускорениям центров масс, а не против них",
            "Φ = −m·a_S: каждая через свой центр масс S, против ускорения a_S"),
        "inertia-omitted": (
            "сила инерции {target} не учтена",
            "{target} = −m{link}·a_{centre} приложена в точке {centre}: {where} и приложите к "
            "рычагу в точке {image}"),
        "inertia-omitted-all": (
            "силы инерции не учтены",
            "Φ = −m·a_S каждого звена приложена в его центре масс S: отложите каждую на плане "
            "сил своей группы и приложите к рычагу в образе точки S"),
        "inertia-moment-omitted": (
            "момент сил инерции {target} не учтён",
            "{target} = −J_S{link}·ε{link} входит в уравнения моментов звена {link}, а на "
            "рычаг — парой сил {target}/l ⊥ звену в образах его шарниров"),
        "inertia-moment-omitted-all": (
            "моменты сил инерции не учтены",
            "M_Φ = −J_S·ε каждого звена входит в уравнения моментов звена, а на рычаг — парой "
            "сил M_Φ/l ⊥ звену в образах его шарниров"),
        "inertia-moment-reversed": (
            "момент сил инерции {target} направлен в обратную сторону",
            "{target} = −J_S{link}·ε{link} направлен против ε{link}"),
        "inertia-moment-reversed-all": (
            "все моменты сил инерции направлены в обратную сторону",
            "M_Φ = −J_S·ε направлен против ε своего звена"),
        "force-reversed-resistance": (
            "сила полезного сопротивления {target} направлена в обратную сторону",
            "{target} действует на выходное звено против его движения: на рабочем ходе "
            "против V_{point}, вдоль направляющей"),
        "force-reversed": (
            "сила {target} направлена в обратную сторону",
            "{target} направлена {rule}"),
        "lever-unturned": (
            "на рычаге Жуковского силы приложены к плану скоростей, не повёрнутому на 90° "
            "(или повёрнуты вместе с ним)",
            "поверните план скоростей на 90° (в любую сторону) и приложите каждую силу в "
            "образе её точки, сохранив её направление; плечо h — перпендикуляр из полюса p "
            "на линию действия силы, и F_у·{pb} уравновешивает Σ ±F·h"),
        "moment-sense-balancing": (
            "{target} записан с обратным направлением; силовой расчёт выполнен верно",
            "M_у уравновешивает моменты нагрузок ведущего звена относительно его оси: он "
            "направлен противоположно их сумме"),
        "moment-sense-force": (
            "{target} записана с обратным направлением; силовой расчёт выполнен верно",
            "F_у поворачивает кривошип в сторону M_у: в ту, в которую её требует равновесие "
            "рычага Σ ±F·h"),
        "moment-sense-inertia": (
            "{target} записан с обратным направлением; силовой расчёт выполнен верно",
            "{target} = −J_S·ε направлен против ε своего звена"),
        "moment-sense-moment": (
            "{target} записан с обратным направлением; силовой расчёт выполнен верно",
            "{target} направлен так, как задано в файле механизма"),
        "force-scale-large": "план сил {group} {times} крупнее (при указанном μF)",
        "force-scale-small": "план сил {group} {times} мельче (при указанном μF)",
        "force-scale-all-large": "планы сил {times} крупнее (при указанном μF)",
        "force-scale-all-small": "планы сил {times} мельче (при указанном μF)",
        "force-scale-fits": ": их отрезки соответствуют μF = {fits} Н/мм",
        "force-scale": (
            "{what}",
            "отрезок плана сил = сила / μF, в мм, а сила, снятая с плана, = отрезок · μF: "
            "проверьте степень 10"),
        "force-scale-fitted": (
            "{what}",
            "постройте план сил при записанном μF (отрезок = сила / μF) или запишите тот μF, "
            "при котором он построен"),
    },
    "rules": {"against velocity": "против скорости точки {point}",
              "along velocity": "по скорости точки {point}",
              "against guide": "вдоль направляющей звена, против её направления",
              "along guide": "вдоль направляющей звена", "": "под углом, заданным в файле"},
    "of_group": "группы {key}",
    "load_where": {"group": "отложите её на плане сил своей группы",
                   "crank": "учтите её в равновесии ведущего звена"},
    "lookalikes": {
        "segment": "{item} = {m} мм — это длина {other} ({exact} мм): отрезок измерен не от "
                   "той точки?",
        "swapped": "{item} = {m} мм — это длина {other} ({exact} мм): {item} и {other} "
                   "перепутаны?",
        "value": "{item} = {m} — это {other} в {unit} ({exact}): отрезок равен {other}/{mu}, в мм",
        "length": "{item} = {m} — это длина {other} в мм ({exact} мм): величина равна "
                  "{other}·{mu}, в {unit}",
    },
}

#: language → its table
WORDS = {"en": EN, "ru": RU}
