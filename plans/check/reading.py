"""Numbers as a student writes them in a measurement file: a length, a magnitude with its
unit ("2,77 м/с", "1942 Н"), and a sense after it ("4.82 ccw", "120 Н·м против часовой
стрелки"); every problem added, located, to the file's :class:`Problems`.
"""

from __future__ import annotations

import re
from typing import Any

from plans.model import SCALE
from plans.model.fileformat import DECIMAL, MAX_ABS, Problems, decimal, quote, read_number

#: the sense of an ω, an ε or a moment as a student writes it after the magnitude, +1 ccw,
#: −1 cw
SENSE_WORDS = {
    "ccw": 1, "cw": -1, "counterclockwise": 1, "counter-clockwise": 1, "anticlockwise": 1,
    "anti-clockwise": 1, "clockwise": -1,
    "против часовой стрелки": 1, "против часовой": 1, "против ч.с.": 1, "против ч. с.": 1,
    "против чс": 1, "против": 1,
    "по часовой стрелке": -1, "по часовой": -1, "по ч.с.": -1, "по ч. с.": -1, "по чс": -1,
    "по": -1,
}
#: the senses a hint names
SENSE_HINT = "ccw, cw, против часовой стрелки, по часовой стрелке, против ч.с., по ч.с."
#: the units a quoted value may carry, by kind (Item.kind, "value" by its plan)
VALUE_UNITS = {
    "velocity": ("m/s", ("m/s", "м/с")),
    "acceleration": ("m/s²", ("m/s²", "м/с²")),
    "omega": ("rad/s", ("rad/s", "рад/с", "1/s", "1/с", "s⁻¹", "с⁻¹")),
    "epsilon": ("rad/s²", ("rad/s²", "рад/с²", "1/s²", "1/с²", "s⁻²", "с⁻²")),
    # a force in N; seed 000 writes the Cyrillic Н as a Latin H ("80 H")
    "force": ("N", ("N", "Н", "H")),
    "moment": ("N·m", ("N·m", "Н·м", "N*m", "Н*м", "N.m", "Н.м", "Nm", "Нм", "H·м", "H·m", "Hм")),
}
WHAT = {"velocity": "a velocity", "acceleration": "an acceleration",
        "omega": "an angular velocity", "epsilon": "an angular acceleration",
        "force": "a force", "moment": "a moment"}


def number(value: Any, where: str, problems: Problems, *, positive=False, nonneg=False,
           unit: str = "mm", what: str = "a length on the drawing",
           low: float | None = None, high: float = MAX_ABS) -> float | None:
    """A number of the file (``fileformat.read_number``: in quotes too, with a decimal point
    or comma); ``what`` (a length on the drawing, a magnitude) is not negative; ``low``,
    ``high``: the magnitudes admitted (a scale factor's, :func:`scale`)."""
    x = read_number(value, where, problems, positive=positive, unit=unit, low=low, high=high)
    if x is not None and nonneg and x < 0:
        problems.add(where, f"{what} cannot be negative, got {x:g}")
        return None
    return x


def scale(value: Any, where: str, problems: Problems, unit: str) -> float | None:
    """A scale factor the student used (μl, μv, μa, μF): positive and within the range a
    mechanism file admits for its own (``plans.model.mechanism.SCALE``), with the same
    located message. A μ of 1e-160 had overflowed the check's misfit (an internal
    error), one of 5e-324 had made every computed segment infinite and every item "ok"."""
    return number(value, where, problems, positive=True, unit=unit, low=SCALE[0], high=SCALE[1])


def normal_unit(text: str) -> str:
    """A unit as a student types it, in one spelling: lower case, no spaces, powers as
    superscripts ("m/s^2", "m/s2", "м/с²" → "m/s²", "м/с²"; "s^-1", "с-1" → "s⁻¹", "с⁻¹").

    >>> [normal_unit(u) for u in ("M/S^2", "м/с2", "rad / s", "c^-1", "1/s**2")]
    ['m/s²', 'м/с²', 'rad/s', 'с⁻¹', '1/s²']
    """
    u = "".join(text.lower().split()).replace("**", "^")
    u = re.sub(r"(?<=[sсc])\^?-1$", "⁻¹", u)
    u = re.sub(r"(?<=[sсc])\^?-2$", "⁻²", u)
    u = re.sub(r"(?<=[sсc])\^?2$", "²", u)
    if re.search(r"[а-я]", u):  # "м/c" typed with a Latin c
        u = u.replace("c", "с")
    elif u in ("c⁻¹", "c⁻²"):
        u = "с" + u[1:]
    return u


def _split_sense(rest: str) -> tuple[str, int]:
    """The words after a magnitude as (unit, sense): the sense (SENSE_WORDS) before or
    after the unit, or alone."""
    r = " ".join(rest.lower().split())
    for phrase in sorted(SENSE_WORDS, key=len, reverse=True):
        if r == phrase:
            return "", SENSE_WORDS[phrase]
        if r.endswith(" " + phrase):
            return r[: -len(phrase) - 1], SENSE_WORDS[phrase]
        if r.startswith(phrase + " "):
            return r[len(phrase) + 1:], SENSE_WORDS[phrase]
    return r, 0


def magnitude_sense(value, key, problems, *, allow_sense, kind="velocity"):
    """The magnitude and sense (+1 ccw, −1 cw, 0 not given) of a value of [values]: a
    number, or in quotes a number (decimal point or comma) with its unit and, for ω, ε
    and a moment (``allow_sense``), a sense: "4,82 рад/с против часовой стрелки"."""
    sense = 0
    main, units = VALUE_UNITS[kind]
    if isinstance(value, str):
        if allow_sense:
            example = (f'e.g. "4.82 ccw" or "4,82 {units[1]} против часовой стрелки" '
                       f"(senses: {SENSE_HINT})")
            bad = f"write a magnitude and a sense, {example}, got {quote(value)}"
        else:
            example = f'e.g. 2.77, "2,77" or "2.77 {main}"'
            bad = f"must be a number, got {quote(value)}: write {WHAT[kind]} in {main}, {example}"
        m = re.fullmatch(rf"\s*({DECIMAL})\s*(.*?)\s*", value, re.S)
        if m is None:
            problems.add(key, bad)
            return None, 0
        unit, sense = _split_sense(m.group(2))
        if sense and not allow_sense:
            only = "ω and ε" if kind in ("velocity", "acceleration") else "ω, ε, a moment and F_у"
            problems.add(key, f"{bad} (a sense is given for {only} only)")
            return None, 0
        if unit and normal_unit(unit) not in {normal_unit(u) for u in units}:
            other = next((k for k, (_, us) in VALUE_UNITS.items()
                          if normal_unit(unit) in {normal_unit(u) for u in us}), None)
            if other is not None:
                problems.add(key, f"{quote(value)} is in {unit}, the unit of {WHAT[other]}: "
                                  f"{WHAT[kind]} is in {' or '.join(units[:2])}")
            elif allow_sense:
                problems.add(key, f"{bad}: {quote(unit, 20)} is neither a sense nor a unit of "
                                  f"{WHAT[kind]} ({', '.join(units)})")
            else:
                problems.add(key, f"must be a number, got {quote(value)}: {quote(unit, 20)} is not "
                                  f"a unit of {WHAT[kind]}; write it in {' or '.join(units)}, "
                                  f"{example}")
            return None, 0
        mag = decimal(m.group(1))
        value = mag
        if allow_sense and mag < 0 and not sense:
            sense, value = -1, -mag  # "-4.82": clockwise, as a number would be
    elif allow_sense and isinstance(value, int | float) and not isinstance(value, bool) and value < 0:
        sense, value = -1, -value  # ω3 = -4.82: clockwise, as the engine signs it
    x = number(value, key, problems, nonneg=True, unit=main,
             what="a magnitude with a sense word" if allow_sense else "a magnitude")
    if x is None:
        return None, 0
    return x, sense
