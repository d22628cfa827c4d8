"""The note's words, one table per language: its headings and sentences (:data:`T`) and
its units (:data:`UNITS`). A third language is one more table of each, with the same keys.

Beside the sentences: ``dash``, what stands between a symbol and its meaning ("n = 5 —
число подвижных звеньев" in Russian, "n = 5 moving links" in English); ``dyad``, a group's
kind by the letters of its pairs, ``{latin}`` (RPR) or ``{cyrillic}`` (ВПВ); ``working`` and
``return``, the crank's turn over the working and the return stroke.
"""

from __future__ import annotations

from plans.fmt import SENSE
from plans.fmt import UNITS as SI

T = {
    "en": {
        "title": "Kinematic analysis",
        "initial": "Initial data",
        "given": "The mechanism's dimensions, loads, input speed and the position studied, as the file "
                 "gives them:",
        "offset": "offset of the guide {g} from {p}",
        "law": "the law of input {i} in time",
        "law_table": "by a table of {n} instants, a spline through them",
        "position": "Position of the mechanism: {phi} = {at}.",
        "structure": "Structural analysis",
        "cheb": "Degrees of freedom (mobility) by the Chebyshev–Grübler–Kutzbach formula:",
        "n": "moving links", "p5": "one-DOF pairs (revolute and prismatic)", "p4": "two-DOF pairs",
        "groups": "Detaching the input link {d} and the frame, the chain splits into class-II (Assur) "
                  "groups, dyads:",
        "group": "links {a} and {b}: kind {k} ({name} dyad)",
        "class": "The mechanism is of class {c}; structural formula {f}.",
        "positions": "Plan of positions",
        "mul": "Scale factor of the plan of positions:",
        "seg": "Segments of the links on the drawing:",
        "heavy": "The position of the plans below ({title}) is drawn in heavy lines, the other positions in "
                 "thin lines.",
        "heavy_all": "The positions of the plans below ({title}) are drawn in heavy lines, the other "
                     "positions in thin lines.",
        "seg_first": "Segments of the links on the drawing, in the position of the plans below ({title}):",
        "seg_at": "Segments whose length changes with the position, in the position of the plans below "
                  "({title}):",
        "seg_same": "In the position of the plans below ({title}) the segments are as above.",
        "seg_same_all": "In the positions of the plans below ({title}) the segments are as above.",
        "stroke": "Stroke of the output point {p}:",
        "swing": "Swing of the output link {l}:",
        "kth": "Crank angle between the extreme positions, θ, and the time ratio K, from the crank's turn "
               "over the working stroke φ_w (from the extreme position ′ to ″ in the sense of ω{d}) and "
               "over the return stroke φ_r:",
        "velocities": "Velocity plan",
        "va": "Velocity of point {t} of the input link, ⊥ {p}{t} in the sense of {w}:",
        "muv": "Take a round scale factor of the velocity plan; the vector p{t} of the input link's "
               "point is then:",
        "eqs": "Vector equations for point {x}:",
        "known": "known", "dir": "direction",
        "build": "Through point {l0} draw a line {r0} and through point {l1} a line {r1}; they meet at point "
                 "{x}.",
        "sim": "By the {plan} image (the image of a link is similar to the link):",
        "values": "Velocities read from the plan:",
        "avalues": "Accelerations read from the plan:",
        "omega": "Angular velocity of link {i}:",
        "sense": {**SENSE["en"], 0: ""},
        "dash": "",
        "dyad": "{latin}",
        "working": "φ_w",
        "return": "φ_r",
        "accelerations": "Acceleration plan",
        "aa": "Acceleration of point {t}, directed from {t} to {p} ({w} = const):",
        "transmission": "Transmission angles γ and pressure angles α = 90° − γ of the groups:",
        "aa_eps": "Acceleration of point {t}: the crank turns with {e} = {ev} rad/s², {sense}; its normal "
                  "component is directed from {t} to {p}, its tangential one ⊥ {p}{t} in the sense of {e}:",
        "vs": "Velocity of point {t} of the input slider {i}, along its guide {g}, given:",
        "as": "Acceleration of point {t} of the input slider {i}, along its guide {g}, given:",
        "mua": "Take a round scale factor of the acceleration plan; the vector π{t} of the input link's "
               "point is then:",
        "normal": "Normal component, directed from {x} to {y}:",
        "coriolis": "Coriolis component: V_{x}{y} turned by 90° in the sense of ω{i}:",
        "ontheplan": "on the plan",
        "eps": "Angular acceleration of link {i}:",
        "fixed": "fixed point: at the pole",
        "warn": "Warning",
        "translates": "Link {i} translates (ω{i} = 0): all its points have one {what}, {eq}:",
        "vel": "velocity", "acc": "acceleration",
        "nocor": "no Coriolis term: the guide's link {k} translates (ω{k} = 0)",
        "same_w": "ω{i} = ω{k}: link {i} slides along a guide of link {k}, so it turns with it",
        "xk": "{x}: the axis of the guide (slot) on link {k}",
    },
    "ru": {
        "title": "Кинематический анализ",
        "initial": "Исходные данные",
        "given": "Размеры звеньев, нагрузки, угловая скорость начального звена и исследуемое положение "
                 "механизма:",
        "offset": "смещение направляющей {g} от {p}",
        "law": "закон движения начального звена {i} во времени",
        "law_table": "по таблице из {n} моментов времени, сплайн через них",
        "position": "Положение механизма: {phi} = {at}.",
        "structure": "Структурный анализ механизма",
        "cheb": "Число степеней свободы по формуле П. Л. Чебышева:",
        "n": "число подвижных звеньев", "p5": "число одноподвижных пар", "p4": "число двухподвижных пар",
        "groups": "После отделения начального звена {d} со стойкой цепь разбивается на группы Ассура II "
                  "класса:",
        "group": "звенья {a} и {b}: {k}-й вид ({name})",
        "class": "Механизм относится к {c} классу; структурная формула {f}.",
        "positions": "План положений механизма",
        "mul": "Масштабный коэффициент плана положений:",
        "seg": "Длины отрезков, изображающих звенья на чертеже:",
        "heavy": "Положение, для которого ниже построены планы ({title}), выделено основными линиями, "
                 "остальные положения — тонкими.",
        "heavy_all": "Положения, для которых ниже построены планы ({title}), выделены основными линиями, "
                     "остальные положения — тонкими.",
        "seg_first": "Длины отрезков, изображающих звенья на чертеже, в положении, для которого ниже "
                     "построены планы ({title}):",
        "seg_at": "Отрезки, длина которых меняется с положением, в положении, для которого ниже построены "
                  "планы ({title}):",
        "seg_same": "В положении, для которого ниже построены планы ({title}), длины отрезков те же.",
        "seg_same_all": "В положениях, для которых ниже построены планы ({title}), длины отрезков те же.",
        "stroke": "Ход выходной точки {p}:",
        "swing": "Угол размаха выходного звена {l}:",
        "kth": "Угол между положениями кривошипа в крайних положениях механизма θ и коэффициент изменения "
               "средней скорости K — по углам поворота кривошипа за рабочий ход φ_рх (от крайнего положения "
               "′ до ″ в сторону ω{d}) и за холостой ход φ_хх:",
        "velocities": "План скоростей механизма",
        "va": "Скорость точки {t} начального звена, ⊥ {p}{t} в сторону вращения {w}:",
        "muv": "Примем масштабный коэффициент плана скоростей (круглое значение); тогда длина вектора p{t}, "
               "изображающего скорость точки начального звена:",
        "eqs": "Векторные уравнения для точки {x}:",
        "known": "известна", "dir": "направление",
        "build": "Через точку {l0} проводим прямую {r0}, через точку {l1} — прямую {r1}; их пересечение даёт "
                 "точку {x}.",
        "sim": "По теореме подобия:",
        "values": "Скорости точек по плану:",
        "avalues": "Ускорения точек по плану:",
        "omega": "Угловая скорость звена {i}:",
        "sense": {**SENSE["ru"], 0: ""},
        "dash": " —",
        "dyad": "{cyrillic}",
        "working": "φ_рх",
        "return": "φ_хх",
        "accelerations": "План ускорений механизма",
        "aa": "Ускорение точки {t} направлено от {t} к {p} ({w} = const):",
        "transmission": "Углы передачи движения γ и углы давления α = 90° − γ групп:",
        "aa_eps": "Ускорение точки {t}: кривошип вращается с {e} = {ev} рад/с², {sense}; нормальная "
                  "составляющая направлена от {t} к {p}, касательная ⊥ {p}{t} в сторону {e}:",
        "vs": "Скорость точки {t} ползуна {i} (начальное звено) вдоль направляющей {g}, задана:",
        "as": "Ускорение точки {t} ползуна {i} (начальное звено) вдоль направляющей {g}, задано:",
        "mua": "Примем масштабный коэффициент плана ускорений (круглое значение); тогда длина вектора π{t}, "
               "изображающего ускорение точки начального звена:",
        "normal": "Нормальное ускорение направлено от {x} к {y}:",
        "coriolis": "Ускорение Кориолиса: вектор V_{x}{y}, повёрнутый на 90° в сторону ω{i}:",
        "ontheplan": "на плане",
        "eps": "Угловое ускорение звена {i}:",
        "fixed": "неподвижная точка: в полюсе",
        "warn": "Предупреждение",
        "translates": "Звено {i} движется поступательно (ω{i} = 0): {what} всех его точек равны, {eq}:",
        "vel": "скорости", "acc": "ускорения",
        "nocor": "ускорение Кориолиса равно нулю: звено {k}, несущее направляющую, движется поступательно "
                 "(ω{k} = 0)",
        "same_w": "ω{i} = ω{k}: звено {i} движется по направляющей звена {k} и поворачивается вместе с ним",
        "xk": "{x} — ось направляющей (паза) на звене {k}",
    },
}

#: the note's units: the SI ones of :data:`plans.fmt.UNITS`, with the scale factors' and
#: these few names of the note's own
UNITS = {lang: {**si, "kgm2": si["kg·m²"], "deg": "°", **scales} for lang, si, scales in (
    ("en", SI["en"], {"mu_l": "m/mm", "mu_v": "(m/s)/mm", "mu_a": "(m/s²)/mm"}),
    ("ru", SI["ru"], {"mu_l": "м/мм", "mu_v": "(м/с)/мм", "mu_a": "(м/с²)/мм"}),
)}
