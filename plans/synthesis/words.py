"""The synthesis's words, one table per language: a third language is one more table.

Each entry is a ``str.format`` template; numbers reach it already written in the
language's own way (:func:`plans.fmt.num`: a decimal comma in Russian).
"""

from __future__ import annotations

from plans.fmt import decimal

EN = {
    "title": {
        "crank-rocker": "Synthesis of a crank-rocker mechanism by the time-ratio coefficient K",
        "crank-slider": "Synthesis of an offset crank-slider mechanism by the time-ratio "
                        "coefficient K",
        "slotted-link": "Synthesis of a shaper's slotted-link mechanism by the time-ratio "
                        "coefficient K",
        "function": "Synthesis of a four-bar by given positions of crank and rocker (Freudenstein)",
        "coupler": "Synthesis of a four-bar by given positions of the coupler",
    },
    "given": "Given",
    "theta": "The angle between the crank's positions at the extreme positions:",
    "chord": "The chord between the rocker's extreme positions:",
    "circle": ("The crank pivot A lies on the circle through C1 and C2 that sees the chord under θ "
               "(C1P ⊥ C1C2, ∠C1C2P = 90° − θ, C2P its diameter); at the extreme positions "
               "AC1 = l_BC − l_AB (crank and coupler folded) and AC2 = l_BC + l_AB (stretched)."),
    "circle_slider": ("The crank pivot A lies on the circle through the slider's extreme positions C1 "
                      "and C2 that sees them under θ, at the offset e from the guide; AC1 = l_BC − l_AB, "
                      "AC2 = l_BC + l_AB."),
    "place": ("A's place on the arc: u = ∠AC2C1 + θ/2, by the sine rule in the triangle AC1C2:"),
    "root": "u = {u}° (root {i} of {n} of {eq}, found by bracketing over the whole arc)",
    "best": "u = {u}°: the family's best member ({why})",
    "cosines": "By the cosine rule in the triangle AC1C2 (C1C2² = AC1² + AC2² − 2·AC1·AC2·cos θ):",
    "lengths": "The links:",
    "frame_len": "The frame, from the triangle AC1D:",
    "gamma": "The transmission angle at the crank's two positions along the frame:",
    "grashof": "Grashof's rule (the crank the shortest link):",
    "grashof_check": "Grashof: {g}",
    "grashof_said": "Grashof: {g}",
    # the engine's Grashof class (plans.cycle.grashof_class) is written in English
    "grashof_terms": {},
    "crank_rocker": "crank-rocker",
    "not_crank_rocker": "not a crank-rocker: the input link does not turn fully",
    "pressure": "The pressure angle on the slider:",
    "pressure_p": "Where the working stroke begins (p·H before its end):",
    "shaper_swing": "The rocker swings through ψ = θ (the crank stands across it at the extremes):",
    "shaper_guide": ("The ram's guide through the middle of the sagitta of D's arc (the least offset "
                     "of D from it, f/2):"),
    "alpha_default": ("The rod DE for the pressure angle α_max = {a}° on the ram (taken where neither "
                      "DE nor alpha_max_deg is given):"),
    "freudenstein": ("The loop closes where K1·cos ψ − K2·cos φ + K3 = cos(φ − ψ), "
                     "K1 = l_AD/l_AB, K2 = l_AD/l_CD, K3 = (l_AB² − l_BC² + l_CD² + l_AD²)/(2·l_AB·l_CD); "
                     "one equation per position:"),
    "family2": "Two positions leave one link free: {what}.",
    "centres": ("The fixed pivots are the centres of the circles through the joint's positions "
                "(where the perpendicular bisectors of B1B2, B2B3 and of C1C2, C2C3 meet):"),
    "centres2": ("Two positions leave each fixed pivot anywhere on the perpendicular bisector of "
                 "its joint's two positions: {what}."),
    "check": "Check by analysis (the written mechanism analysed as plans cycle does):",
    "check_row": "{name}: required {want}, by analysis {got}",
    "worst": "the largest relative difference {d} (at most {tol})",
    "solutions": "Solutions",
    "solutions_n": "{n} solutions",
    "solution_1": "one solution",
    "chosen": "Chosen: {i} ({why})",
    "why": {"given": "the largest γmin of those listed", "only": "the only one",
            "best": "the family's best by γmin", "size": "the smallest within the limit",
            "asked": "asked for", "best_slider": "the least largest pressure angle",
            "given_slider": "the least pressure angles of those listed: the largest, then the "
                            "working stroke's"},
    "family": "Family: {what}",
    "family_row": ("  {label}: {figure} from {lo} to {hi} over {p} from {ulo} to {uhi}; "
                   "best {best} at {p} = {u}"),
    "no_member": "  {label}: no member",
    "edge": " (at the end of the range searched)",
    "off": "{d} m from the given place",
    "file": "Mechanism file: {path}",
    "no_file": "Mechanism file: give -o MECH.toml to write it",
    "head": ("#", "A", "l_AB, m", "l_BC, m", "l_CD, m", "l_AD, m", "γmin"),
    "head_slider": ("#", "l_AB, m", "l_BC, m", "e, m", "λ", "ε", "δmax", "δ (working)"),
    "head_slotted": ("#", "l_AB, m", "l_AC, m", "l_CD, m", "h, m", "l_DE, m", "αmax"),
    "sides": {0: "beyond C1C2 from D", 1: "on D's side of C1C2"},
    "gamma_min": "γmin", "delta_max": "δmax",
    "ccw": "ccw", "cw": "cw",
    "positions_given": "position {i}: {what}",
    "engine": "by the engine",
    "m": "m", "mm": "mm",
    "curves": {},
}

RU = {
    "title": {
        "crank-rocker": "Синтез кривошипно-коромыслового механизма по коэффициенту изменения "
                        "средней скорости K",
        "crank-slider": "Синтез дезаксиального кривошипно-ползунного механизма по коэффициенту изменения "
                        "средней скорости K",
        "slotted-link": "Синтез кулисного механизма поперечно-строгального станка по коэффициенту изменения "
                        "средней скорости K",
        "function": "Синтез шарнирного четырёхзвенника по заданным положениям кривошипа и коромысла "
                    "(уравнение Фрейденштейна)",
        "coupler": "Синтез шарнирного четырёхзвенника по заданным положениям шатуна",
    },
    "given": "Дано",
    "theta": "Угол между положениями кривошипа в крайних положениях механизма (угол перекрытия):",
    "chord": "Хорда между крайними положениями коромысла:",
    "circle": ("Ось A кривошипа лежит на окружности, проходящей через C1 и C2, из точек которой хорда "
               "видна под углом θ (C1P ⊥ C1C2, ∠C1C2P = 90° − θ, C2P — её диаметр); в крайних "
               "положениях AC1 = l_BC − l_AB (кривошип и шатун сложены) и AC2 = l_BC + l_AB "
               "(вытянуты в линию)."),
    "circle_slider": ("Ось A кривошипа лежит на окружности, проходящей через крайние положения ползуна "
                      "C1 и C2, из точек которой они видны под углом θ, на расстоянии e (дезаксиал) от "
                      "направляющей; AC1 = l_BC − l_AB, AC2 = l_BC + l_AB."),
    "place": "Положение A на дуге: u = ∠AC2C1 + θ/2; по теореме синусов в треугольнике AC1C2:",
    "root": "u = {u}° (корень {i} из {n} уравнения {eq}, найденный отделением корней на всей дуге)",
    "best": "u = {u}°: лучший член семейства ({why})",
    "cosines": "По теореме косинусов в треугольнике AC1C2 (C1C2² = AC1² + AC2² − 2·AC1·AC2·cos θ):",
    "lengths": "Длины звеньев:",
    "frame_len": "Стойка, из треугольника AC1D:",
    "gamma": "Угол передачи в двух положениях кривошипа вдоль стойки:",
    "grashof": "Условие Грасгофа (кривошип — кратчайшее звено):",
    "grashof_check": "Условие Грасгофа (кривошип — кратчайшее звено): {g}",
    "grashof_said": "Грасгоф: {g}",
    "grashof_terms": {"crank-rocker": "кривошипно-коромысловый", "Grashof": "Грасгоф"},
    "crank_rocker": "кривошипно-коромысловый механизм",
    "not_crank_rocker": "не кривошипно-коромысловый: входное звено не проворачивается",
    "pressure": "Угол давления на ползун:",
    "pressure_p": "В начале рабочего хода (за p·H до его конца):",
    "shaper_swing": "Угол качания кулисы ψ = θ (в крайних положениях кривошип перпендикулярен кулисе):",
    "shaper_guide": ("Направляющая ползуна через середину стрелы дуги точки D (наименьшее отклонение D "
                     "от неё, f/2):"),
    "alpha_default": ("Шатун DE — по углу давления на ползун α_max = {a}° (принят, так как не заданы "
                      "ни DE, ни alpha_max_deg):"),
    "freudenstein": ("Контур замыкается при K1·cos ψ − K2·cos φ + K3 = cos(φ − ψ), "
                     "K1 = l_AD/l_AB, K2 = l_AD/l_CD, K3 = (l_AB² − l_BC² + l_CD² + l_AD²)/(2·l_AB·l_CD); "
                     "по уравнению на каждое положение:"),
    "family2": "Два положения оставляют одно звено свободным: {what}.",
    "centres": ("Неподвижные шарниры — центры окружностей, проходящих через положения шарниров шатуна "
                "(пересечение серединных перпендикуляров к B1B2, B2B3 и к C1C2, C2C3):"),
    "centres2": ("При двух положениях каждый неподвижный шарнир лежит где угодно на серединном "
                 "перпендикуляре к двум положениям своего шарнира: {what}."),
    "check": "Проверка анализом (записанный механизм исследован так же, как в plans cycle):",
    "check_row": "{name}: требуется {want}, по анализу {got}",
    "worst": "наибольшее относительное расхождение {d} (не более {tol})",
    "solutions": "Решения",
    "solutions_n": "решений: {n}",
    "solution_1": "одно решение",
    "chosen": "Выбрано: {i} ({why})",
    "why": {"given": "наибольший γmin из найденных", "only": "единственное",
            "best": "лучший член семейства по γmin", "size": "наименьший в пределах ограничения",
            "asked": "задано", "best_slider": "наименьший наибольший угол давления",
            "given_slider": "наименьшие углы давления из найденных: наибольший, затем на "
                            "рабочем ходе"},
    "family": "Семейство: {what}",
    "family_row": ("  {label}: {figure} от {lo} до {hi} при {p} от {ulo} до {uhi}; "
                   "лучший {best} при {p} = {u}"),
    "no_member": "  {label}: механизмов нет",
    "edge": " (на границе просмотренного диапазона)",
    "off": "{d} м от заданного положения",
    "file": "Файл механизма: {path}",
    "no_file": "Файл механизма: запишите его ключом -o MECH.toml",
    "head": ("№", "A", "l_AB, м", "l_BC, м", "l_CD, м", "l_AD, м", "γmin"),
    "head_slider": ("№", "l_AB, м", "l_BC, м", "e, м", "λ", "ε", "δmax", "δ (раб.)"),
    "head_slotted": ("№", "l_AB, м", "l_AC, м", "l_CD, м", "h, м", "l_DE, м", "αmax"),
    "sides": {0: "за хордой C1C2 от D", 1: "со стороны D от C1C2"},
    "gamma_min": "γmin", "delta_max": "δmax",
    "ccw": "против ч.с.", "cw": "по ч.с.",
    "positions_given": "положение {i}: {what}",
    "engine": "по анализу",
    "m": "м", "mm": "мм",
    "curves": {"beyond C1C2 from D": "за хордой C1C2 от D", "on D's side of C1C2": "со стороны D от C1C2",
               "offset crank-slider": "дезаксиальный кривошипно-ползунный",
               "A on the bisector of B1B2": "A на серединном перпендикуляре к B1B2"},
}

WORDS = {"en": EN, "ru": RU}


def grashof_in(text: str, lang: str) -> str:
    """The engine's Grashof class, written in English, in ``lang``'s words and decimal mark.

    >>> grashof_in("crank-rocker (Grashof: 0.3 ≤ 0.5)", "ru")
    'кривошипно-коромысловый (Грасгоф: 0,3 ≤ 0,5)'
    """
    for en, said in WORDS[lang]["grashof_terms"].items():
        text = text.replace(en, said)
    return decimal(text, lang)
