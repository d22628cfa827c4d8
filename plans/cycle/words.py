"""The words of the cycle: its crank range, its change points and its summary, and the
turn the crank angles of a mechanism are written in.

A crank that cannot make a full turn has its range written from the smaller angle to
the larger, through 0° where it runs through it ("from −99.72° to 99.72°"); every other
angle said beside it is then written in the same turn (−99.7°, not 260.3°:
:func:`shown_from`). The kinematics words an angle in [0°, 360°); :func:`worded` says
its errors again in the cycle's turn.

The sentences a report gives in its language are one table per language
(:data:`WORDS`); the summary and the messages of the command line are English.
"""

from __future__ import annotations

import math

from plans.errors import PositionError
from plans.fmt import angle, from_x, num

#: the sentences of the cycle a report gives, by language
WORDS = {
    "en": {
        "change": "At {phi} = {at}°{conv}, {what}, the links of a group lie on one line and "
                  "its two assemblies meet: the plans there are singular.",
        "change1": "a change point",
        "changes": "change points",
        "and": " and ",
        "noturn": "The input link {d} cannot make a full turn (it rocks, it is not a crank): "
                  "the mechanism assembles only for {phi} from {lo}° to {hi}°{conv}, a swing "
                  "of {span}°.",
        "travel": "The input slider {d} is taken over the travel where the mechanism "
                  "assembles: {phi} from {lo} m to {hi} m along {guide}, {span} m.",
        "time": "The cycle runs over t from {lo} s to {hi} s, {what}.",
        "period": "one period of the drivers' laws",
        "given": "the interval [motion] gives",
        "textremes": "extreme positions at t = {at} s",
        "tK": "K = t_work / t_return = {K}, θ = 180°·(K − 1)/(K + 1) = {theta}°",
        "fourbar": "four-bar: {g}",
        "stroke": "stroke of {p}: H = {H} m",
        "swing": "swing of link {i}: ψ = {psi}°",
        "extremes": "extreme positions at {phi} = {at}{conv}; θ = {theta}°, K = {K}",
        # the cycle's notes (plans.cycle.analysis) are written in English
        "notes": True,
    },
    "ru": {
        "change": "При {phi} = {at}°{conv} ({what}) звенья группы лежат на одной прямой и обе "
                  "её сборки совпадают: планы скоростей и ускорений там не строятся.",
        "change1": "точка смены сборки",
        "changes": "точки смены сборки",
        "and": " и ",
        "noturn": "Начальное звено {d} не может сделать полный оборот (это коромысло, а не "
                  "кривошип): механизм собирается только при {phi} от {lo}° до {hi}°{conv}, "
                  "угол качания {span}°.",
        "travel": "Ползун {d} (начальное звено) рассмотрен на ходе, где механизм собирается: "
                  "{phi} от {lo} м до {hi} м вдоль {guide}, {span} м.",
        "time": "Цикл рассмотрен при t от {lo} с до {hi} с ({what}).",
        "period": "один период законов движения начальных звеньев",
        "given": "интервал из [motion]",
        "textremes": "крайние положения при t = {at} с",
        "tK": "K = t_раб / t_хол = {K}, θ = 180°·(K − 1)/(K + 1) = {theta}°",
        "fourbar": "четырёхзвенник: {g}",
        "stroke": "ход точки {p}: H = {H} м",
        "swing": "размах звена {i}: ψ = {psi}°",
        "extremes": "крайние положения при {phi} = {at}{conv}; θ = {theta}°, K = {K}",
        # the cycle's notes are in English only: a Russian summary leaves them out
        "notes": False,
    },
}


def file_range(c, driver=None) -> tuple[float, float]:
    """The crank range of the cycle ``c`` (where it cannot make a full turn) in the
    convention of ``driver`` (degrees; without one, counter-clockwise from +x) as it is
    written: from the smaller angle to the larger, the first one negative where it runs
    through 0° ("from −128.8° to 128.8°"; in the crank's own order, a clockwise crank's
    "from 128.8° to 231.2°" named the very angles where it does not assemble)."""
    lo, hi = c.ccw_range
    deg = driver.file_angle if driver else from_x
    a, b = deg(lo), deg(hi)
    if driver is not None and driver.measured == "cw":  # that convention counts the other way
        a, b = b, a
    b = 0.0 if b > 360.0 - 1e-9 else b  # 359.99999999999 is 0, as angle() writes it
    a = a - 360.0 if a > b else a
    a = 0.0 if abs(a) < 1e-9 else a  # a limit found to 1e-13 rad: −5.7e−14° is 0
    return a, b


def shown_from(c, driver=None) -> float:
    """Where the turn the output writes crank angles in begins (degrees, in the
    convention of ``driver``) for the cycle ``c`` (None: none known): 0, for [0°, 360°),
    unless the crank cannot make a full turn and its range is written through 0°
    (:func:`file_range`, "from −99.72° to 99.72°"); then the turn centred on that range,
    so that an angle compared with it reads −99.7°, not 260.3° (:func:`plans.fmt.angle`)."""
    if c is None or c.full_turn or c.crank_range is None or c.kind != "turn":
        return 0.0
    a, b = file_range(c, driver)
    return 0.0 if a >= 0.0 else (a + b) / 2 - 180.0


def worded(err, solver, c):
    """``err`` with its crank angle written in the turn of the cycle ``c``
    (:func:`shown_from`) by ``solver`` (:meth:`plans.kinematics.Solver.at`): an error of the
    kinematics at one crank angle (:class:`plans.errors.PositionError`), which words it in
    [0°, 360°). Any other error, or one the turn does not change, as it is."""
    if not isinstance(err, PositionError) or err.phi is None:
        return err
    lo = shown_from(c, solver.mech.driver)
    return err.at_words(solver.at(err.phi, "en", lo)) if lo else err


def change_angles(changes, driver, lang: str = "en") -> list[str]:
    """Change points (rad from +x) as the file's angles, written to 1e-6°: they are found to
    about 1e-10 rad, and 0° is not to read 5.7e-09°."""
    return [angle(round(driver.file_angle(x), 6), 4, lang) for x in changes]


def change_points(c, lang: str, driver) -> str:
    """The sentence naming the change points of the cycle ``c``, in the file's convention."""
    words = WORDS[lang]
    at = words["and"].join(change_angles(c.change_points, driver, lang))
    what = words["change1"] if len(c.change_points) == 1 else words["changes"]
    return words["change"].format(at=at, conv=driver.convention(lang), what=what,
                                  phi=driver.phi_sym)


def no_full_turn(c, lang: str = "en", driver=None) -> str:
    """The sentence for a crank that cannot make a full turn (the cycle ``c``), with its
    range in the convention of ``driver`` (:class:`plans.model.mechanism.Driver`), which it
    names; without one, counter-clockwise from +x, and the input link is link 1.

    The range reads as the convention counts, from the smaller angle to the larger, the
    first one negative where it runs through 0°: "from −128.8° to 128.8°" (in the crank's
    own order, a clockwise crank's "from 128.8° to 231.2°" named the very angles where it
    does not assemble).
    """
    if c.kind != "turn":
        return _span_words(c, lang, driver)
    lo, hi = c.ccw_range
    a, b = file_range(c, driver)
    return WORDS[lang]["noturn"].format(
        d=driver.link if driver else 1, phi=driver.phi_sym if driver else "φ1",
        lo=num(a, 4, lang).replace("-", "−"), hi=angle(b, 4, lang),
        conv=driver.convention(lang) if driver else "",
        span=num(math.degrees(abs(hi - lo)), 4, lang),
    )


def _span_words(c, lang: str, driver) -> str:
    """A slider input's travel, or the interval in time, that a cycle runs over."""
    words = WORDS[lang]
    lo, hi = c.span
    if c.kind == "time":
        return words["time"].format(lo=num(lo, 4, lang), hi=num(hi, 4, lang),
                                    what=words["period" if c.periodic else "given"])
    return words["travel"].format(d=driver.link, phi=driver.phi_sym, lo=num(lo, 4, lang),
                                  hi=num(hi, 4, lang), guide=driver.guide.label,
                                  span=num(hi - lo, 4, lang))


def time_lines(c, lang: str = "en") -> list[str]:
    """A cycle in time's extreme positions and its time-ratio K, where it has them."""
    words = WORDS[lang]
    out = []
    if c.extremes:
        out.append(words["textremes"].format(at=", ".join(num(x, 4, lang) for x in c.extremes)))
    if c.K is not None:
        out.append(words["tK"].format(K=num(c.K, 4, lang), theta=num(math.degrees(c.theta), 4, lang)))
    return out


def outside(field: str, given: float, c, driver) -> str:
    """"driver.angle_deg = 150 is outside the crank's range, φ1 from −99.72° to 99.72°":
    the field that gave a crank angle, its value as given, and the range of the cycle
    ``c``, in the convention of ``driver``; ``field`` "" for "150° is outside …", the field
    named before it (a measurement file's located problem)."""
    lo = shown_from(c, driver)
    a, b = file_range(c, driver)
    head = (f"{given:g}°" if not field else
            f"{field}{' ' if field.startswith('--') else ' = '}{given:g}")
    return (f"{head} is outside the crank's range, {driver.phi_sym} from "
            f"{angle(a, 4, 'en', lo)}° to {angle(b, 4, 'en', lo)}°"
            f"{driver.convention()}")


def summary(c, driver=None, lang: str = "en") -> list[str]:
    """The cycle ``c`` in a few lines, as ``plans solve`` and ``plans cycle`` print it: the
    four-bar's Grashof class, the crank range where it cannot make a full turn, the notes,
    the stroke H or swing ψ, the extreme positions, θ and K.

    Angles are in the convention of ``driver`` (the file's), which they name (" (from +y,
    cw)"); without one, counter-clockwise from +x."""
    w = WORDS[lang]
    deg = driver.file_angle if driver else from_x
    convention = driver.convention(lang) if driver else ""
    lines = [w["fourbar"].format(g=c.grashof)] if c.grashof else []
    if not c.full_turn:
        lines.append(no_full_turn(c, lang, driver))
    if w["notes"]:
        lines += c.notes
    elif c.change_points:
        lines.append(change_points(c, lang, driver))
    if c.stroke is not None and c.output is not None:
        if c.output.kind == "linear":
            lines.append(w["stroke"].format(p=c.output.point, H=num(c.stroke, 4, lang)))
        else:
            lines.append(w["swing"].format(i=c.output.link, psi=num(math.degrees(c.stroke), 4, lang)))
        if c.kind == "time":
            return lines + time_lines(c, lang)
        lines.append(w["extremes"].format(
            phi=driver.phi_sym if driver else "φ1", conv=convention,
            at=", ".join(f"{angle(deg(x), 4, lang)}°" for x in c.extremes),
            theta=num(math.degrees(c.theta), 4, lang), K=num(c.K, 4, lang)))
    return lines
