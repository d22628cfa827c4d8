"""The kinematics' words: the warnings of a near-singular position, one table per language,
and the sentences of its errors.

A warning is said in the language of the report that gives it; a third language is one
more table in :data:`WARNINGS`, with the same keys (and its way of writing a number).
An error is a sentence of the engine's, in English (:data:`ERRORS`): the command line
prints it as it is, and a layer that words a crank angle its own way says it again
(:meth:`plans.errors.PositionError.at_words`).
"""

from __future__ import annotations

from typing import NamedTuple

from plans.fmt import num


def _g(x: float, digits: int) -> str:
    """A figure of an English warning: ``digits`` significant digits, as Python writes them."""
    return f"{x:.{digits}g}"


def _ru(x: float, digits: int) -> str:
    """A figure of a Russian warning: :func:`plans.fmt.num`, with its decimal comma."""
    return num(x, digits, "ru")


#: the warnings of a position near a singular one (:mod:`plans.kinematics.conditioning`),
#: and the words of a crank angle on or beside a change point
#: (:meth:`plans.kinematics.Solver.at`)
WARNINGS = {
    "en": {
        "number": _g,
        "group": "{label}",
        "near_parallel": "{group} at {at}: near-singular, the lines {r0} and {r1} meet at "
                         "{degrees}° (sin = {sine}){lost}",
        "lost_all": "; its velocities and accelerations may be wrong altogether",
        "lost_some": "; its velocities and accelerations may be off by up to {percent} % "
                     "(of the largest)",
        "near_pivot": "{group} at {at}: the block {P} passes close to the rocker's pivot {Q} "
                      "(|{Q}{P}| / (|O{Q}| + |O{P}|) = {figure}): the rocker's ω and ε lose digits",
        "on_change": " (a change point: the two assemblies of a group meet there)",
        "beside_change": " (beside the change point at {at}, where the two assemblies of a "
                         "group meet)",
    },
    "ru": {
        "number": _ru,
        "group": "группа {short}",
        "near_parallel": "{group} при {at}: положение, близкое к особому: прямые {r0} и {r1} "
                         "пересекаются под углом {degrees}° (sin = {sine}){lost}",
        "lost_all": "; скорости и ускорения могут быть неверны целиком",
        "lost_some": "; скорости и ускорения могут быть неточны до {percent} % (от наибольшей)",
        "near_pivot": "{group} при {at}: камень {P} проходит близко к оси кулисы {Q} "
                      "(|{Q}{P}| / (|O{Q}| + |O{P}|) = {figure}): ω и ε кулисы теряют точность",
        # the change point is said in English only: a Russian text names the angle alone
        "on_change": "",
        "beside_change": "",
    },
}

#: the errors of a position (:mod:`plans.kinematics.conditioning`): each a template of
#: the crank angle's words ``{at}`` and of ``{singular}``, which says "dead point" unless
#: the angle's words already call it a change point (:func:`singular`)
ERRORS = {
    "misses": "{label} cannot be assembled at {at}: needs {admissible}, misses by {gap} m{note}",
    "dead": "{label} at {at}: {why}: {singular}, the plan has no unique solution{note}",
    "beside": "{label} at {at}: the lines {r0} and {r1} meet at {degrees}° (sin = {sine}), "
              "under {below} beside a change point, where the accelerations lose their "
              "digits as 1/sin³: {singular}, the plan is not built",
    "parallel": "{label} at {at}: the lines {r0} and {r1} are parallel (angle {degrees}°, "
                "sin = {sine}): {singular}, the plan has no unique solution",
    "on_pivot": "{label} at {at}: the block {P} {where} the rocker's pivot {Q} (|{Q}{P}| "
                "ratio {figure}): the rocker's ω is undefined, {singular}",
    "is_on": "is on",
    "all_but_on": "is all but on (under {below}, beside a change point)",
    "singular": "a singular position (dead point)",
    "singular_at_change": "a singular position",
}


def singular(at: str) -> str:
    """'a singular position (dead point)', but not where ``at`` already calls the angle a
    change point (:meth:`plans.kinematics.Solver.at`), through which the motion goes on."""
    return ERRORS["singular_at_change" if "change point" in at else "singular"]


class Sentence(NamedTuple):
    """An error's sentence as a function of its crank angle's words: ``template`` of
    :data:`ERRORS` filled with ``fields`` (name, text) and the angle."""

    template: str
    fields: tuple[tuple[str, str], ...]

    def __call__(self, at: str) -> str:
        return ERRORS[self.template].format(at=at, singular=singular(at), **dict(self.fields))
