"""The force analysis's words, one table per language: a third language is one more table.

Each entry is a ``str.format`` template; numbers reach it already written in the
language's own way (:func:`plans.fmt.num`: a decimal comma in Russian).
"""

from __future__ import annotations

EN = {
    "title": "{name}: force analysis",
    "position": "Position: {phi}; {omega_sym} = {omega} rad/s {sense}",
    "rads2": "rad/s²",
    "loads": "Loads (g = {g} m/s²)",
    "load_head": ("load", "kind", "link", "point", "value", "direction"),
    "weight": "weight",
    "inertia": "inertia force",
    "inertia moment": "inertia moment",
    "resistance": "useful resistance",
    "force": "force",
    "moment": "moment",
    "reaction": "reaction",
    "stroke": "  {P}: s = {s} m of H = {H} m from the start of the working stroke ({stroke})",
    "working": "working stroke",
    "idle": "idle stroke",
    "group": "{label}, force plan μF = {mu} N/mm",
    "reaction_head": ("reaction", "N", "mm", "direction", "acts at"),
    "crank": "Driving link {link}",
    "R01": "  {name} = {value} N, direction {angle}° (at {pivot})",
    "My": "  M_у = {value} N·m {sense}; F_у = M_у / l_{pivot}{tip} = {F} N at {tip} ⊥ {pivot}{tip}",
    "balance": "Balancing moment M_у",
    "by_groups": "  by the force plans (groups)   {value} N·m",
    "by_lever": "  by Zhukovsky's lever           {value} N·m (discrepancy {d} %; with arms to the "
    "millimetre as on paper {m} %)",
    "by_power": "  by virtual power               {value} N·m",
    "by_global": "  by one linear solve of all links {value} N·m",
    "cycle": "Cycle: mean M_у = {mean} N·m, work of the useful resistance {work} J per cycle, mean power "
             "{power} W",
    "cycle_no_resistance": "Cycle: mean M_у = {mean} N·m, mean power {power} W",
    "no_cycle": "Cycle: the crank makes no full turn: no mean over the cycle",
    "drive": "Drive",
    "power_position": "  P = M_у·{omega_sym} = {P} W at this position",
    "power_mean": "  P = M_у,mean·{omega_sym} = {P} W (the cycle's mean power: the crank takes none at this "
    "position)",
    "power_mean_asked": "  P = M_у,mean·{omega_sym} = {P} W (the cycle's mean power, as [drive] asks)",
    "motor": "  P/η = {P} / {eta} = {need} W: motor {type}, {kw} kW, {rpm} rpm",
    "ratio": "  u = n_motor / n1 = {rpm} / {n1} = {u}: {stages}",
    "one_stage": "one stage (u ≤ 6.3)",
    "two_stages": "two stages (6.3 < u ≤ 33), u12 = 1.2·u34",
    "split": "  u34 = √(u/1.2) = {u34}, u12 = 1.2·u34 = {u12}",
    "teeth2": "  z1 = z3 = 20 + Ш = {z1}; z2 = u12·z1 = {z2}; z4 = u34·z3 = {z4}",
    "teeth1": "  z1 = 20 + Ш = {z1}; z2 = u·z1 = {z2}",
    "actual": "  actual u = {u}; n1 = {rpm} / {u} = {n1} rpm ({dev} % from {n1_given} rpm)",
    "no_drive": "  no drive: {why}",
    "ccw": "ccw",
    "cw": "cw",
    "contact_none": "— (no force)",
}

RU = {
    "title": "{name}: силовой анализ",
    "position": "Положение: {phi}; {omega_sym} = {omega} рад/с {sense}",
    "rads2": "рад/с²",
    "loads": "Нагрузки (g = {g} м/с²)",
    "load_head": ("нагрузка", "вид", "звено", "точка", "величина", "направление"),
    "weight": "сила тяжести",
    "inertia": "сила инерции",
    "inertia moment": "момент сил инерции",
    "resistance": "сила полезного сопротивления",
    "force": "сила",
    "moment": "момент",
    "reaction": "реакция",
    "stroke": "  {P}: s = {s} м из H = {H} м от начала рабочего хода ({stroke})",
    "working": "рабочий ход",
    "idle": "холостой ход",
    "group": "{label}, план сил μF = {mu} Н/мм",
    "reaction_head": ("реакция", "Н", "мм", "направление", "точка приложения"),
    "crank": "Ведущее звено {link}",
    "R01": "  {name} = {value} Н, направление {angle}° (в точке {pivot})",
    "My": "  M_у = {value} Н·м {sense}; F_у = M_у / l_{pivot}{tip} = {F} Н в точке {tip} ⊥ {pivot}{tip}",
    "balance": "Уравновешивающий момент M_у",
    "by_groups": "  по планам сил (группы)          {value} Н·м",
    "by_lever": "  по рычагу Жуковского            {value} Н·м (расхождение {d} %; с плечами, измеренными "
    "до миллиметра, {m} %)",
    "by_power": "  по принципу возможных мощностей {value} Н·м",
    "by_global": "  по решению системы для всех звеньев {value} Н·м",
    "cycle": "Цикл: средний M_у = {mean} Н·м, работа сил полезного сопротивления {work} Дж за цикл, "
    "средняя мощность {power} Вт",
    "cycle_no_resistance": "Цикл: средний M_у = {mean} Н·м, средняя мощность {power} Вт",
    "no_cycle": "Цикл: кривошип не делает полного оборота, среднего за цикл нет",
    "drive": "Привод",
    "power_position": "  P = M_у·{omega_sym} = {P} Вт в этом положении",
    "power_mean": "  P = M_у,ср·{omega_sym} = {P} Вт (средняя мощность за цикл: в этом положении кривошип "
    "мощности не потребляет)",
    "power_mean_asked": "  P = M_у,ср·{omega_sym} = {P} Вт (средняя мощность за цикл, как задано в [drive])",
    "motor": "  P/η = {P} / {eta} = {need} Вт: электродвигатель {type}, {kw} кВт, {rpm} об/мин",
    "ratio": "  u = n_дв / n1 = {rpm} / {n1} = {u}: {stages}",
    "one_stage": "одноступенчатый редуктор (u ≤ 6,3)",
    "two_stages": "двухступенчатый редуктор (6,3 < u ≤ 33), u12 = 1,2·u34",
    "split": "  u34 = √(u/1,2) = {u34}, u12 = 1,2·u34 = {u12}",
    "teeth2": "  z1 = z3 = 20 + Ш = {z1}; z2 = u12·z1 = {z2}; z4 = u34·z3 = {z4}",
    "teeth1": "  z1 = 20 + Ш = {z1}; z2 = u·z1 = {z2}",
    "actual": "  фактическое u = {u}; n1 = {rpm} / {u} = {n1} об/мин ({dev} % от {n1_given} об/мин)",
    "no_drive": "  привод не подобран: {why}",
    "ccw": "против часовой стрелки",
    "cw": "по часовой стрелке",
    "contact_none": "— (силы нет)",
}

WORDS = {"en": EN, "ru": RU}


def words(lang: str) -> dict:
    return WORDS.get(lang, EN)
