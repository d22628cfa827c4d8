"""The kinematics' words: the warnings of a near-singular position, one table per language,
and the sentences of its errors.

A warning is said in the language of the report that gives it; a third language is one
more table in :data:`WARNINGS`, with the same keys (and its way of writing a number).
An error is a sentence of the engine's (:data:`ERRORS`), said in English where the command
line prints it on stderr as it is; a layer that words a crank angle its own way says it
again (:meth:`plans.errors.PositionError.at_words`), and a report in another language says
it in that one (``solve`` at a change point).
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
        "on_change": " (точка смены сборки: в ней сходятся две сборки группы)",
        "beside_change": " (рядом с точкой смены сборки при {at}, где сходятся две сборки группы)",
    },
}

#: the errors of a position (:mod:`plans.kinematics.conditioning`): each a template of
#: the crank angle's words ``{at}`` and of ``{singular}``, which says "dead point" unless
#: the angle's words already call it a change point (:func:`singular`)
ERRORS = {
    "en": {
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
        "change_mark": "change point",
    },
    "ru": {
        "misses": "{label} не собирается при {at}: нужно {admissible}, недостаёт {gap} м{note}",
        "dead": "{label} при {at}: {why}: {singular}, план не имеет единственного решения{note}",
        "beside": "{label} при {at}: прямые {r0} и {r1} пересекаются под углом {degrees}° "
                  "(sin = {sine}), меньше {below} рядом с точкой смены сборки, где ускорения "
                  "теряют точность как 1/sin³: {singular}, план не строится",
        "parallel": "{label} при {at}: прямые {r0} и {r1} параллельны (угол {degrees}°, "
                    "sin = {sine}): {singular}, план не имеет единственного решения",
        "on_pivot": "{label} при {at}: камень {P} {where} оси кулисы {Q} (отношение |{Q}{P}| "
                    "{figure}): ω кулисы не определена, {singular}",
        "is_on": "находится на",
        "all_but_on": "почти на (меньше {below}, рядом с точкой смены сборки)",
        "singular": "особое положение (мёртвая точка)",
        "singular_at_change": "особое положение",
        "change_mark": "смены сборки",
    },
}


def singular(at: str, lang: str = "en") -> str:
    """'a singular position (dead point)', but not where ``at`` already calls the angle a
    change point (:meth:`plans.kinematics.Solver.at`), through which the motion goes on."""
    words = ERRORS.get(lang, ERRORS["en"])
    return words["singular_at_change" if words["change_mark"] in at else "singular"]


def in_every_language(key: str, **fields) -> dict[str, str]:
    """The words ``key`` of :data:`ERRORS` filled with ``fields``, in every language: a field
    of a :class:`Sentence` that is said as the sentence is."""
    return {lang: words[key].format(**fields) for lang, words in ERRORS.items()}


class Sentence(NamedTuple):
    """An error's sentence as a function of its crank angle's words: ``template`` of
    :data:`ERRORS` filled with ``fields`` (name, text) and the angle."""

    template: str
    #: a field is a text, or a text per language ({"en": …, "ru": …}) said as the sentence is
    fields: tuple[tuple[str, str | dict[str, str]], ...]

    def __call__(self, at: str, lang: str = "en") -> str:
        lang = lang if lang in ERRORS else "en"
        fields = {k: v.get(lang, v["en"]) if isinstance(v, dict) else v for k, v in self.fields}
        return ERRORS[lang][self.template].format(at=at, singular=singular(at, lang), **fields)
