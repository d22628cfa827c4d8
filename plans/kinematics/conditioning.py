"""How well a position's plans are conditioned, and the errors and warnings that say so.

Each group's plans intersect two lines; the sine between them is the conditioning
figure of the construction (0: parallel lines, a singular plan). A slotted link (RPR)
has a second figure: how far its block is from the rocker's pivot, relative to the loop.
Below :data:`plans.tolerances.SINGULAR_SINE` (beside a change point, the larger
:data:`plans.tolerances.CHANGE_SINE`, :data:`plans.tolerances.CHANGE_PIVOT`) a figure
makes the position singular, an error; below :data:`plans.tolerances.WARN_SINE` it is
near-singular, a warning.

The errors keep their numbers (:class:`plans.errors.PositionError`) and word the crank
angle as they are given it (``at``); the warnings are worded in the report's language
(:data:`plans.kinematics.words.WARNINGS`). ``g`` is a group's recorded solution
(:class:`plans.kinematics.records.GroupSolution`).
"""

from __future__ import annotations

import math

import numpy as np

from plans import tolerances
from plans.errors import AssemblyError, SingularPlanError
from plans.kinematics.words import WARNINGS, Sentence, in_every_language
from plans.model.structure import DyadKind


def plan_error(sine: float) -> float | None:
    """How far off, at most and relative to the largest of them, a plan's velocities and
    accelerations may be where its lines' sine is ``sine`` (:data:`plans.tolerances.LOSS`);
    None where it is below what a report prints (:data:`plans.tolerances.PRINTED`).

    >>> plan_error(0.03), f"{plan_error(3.3e-7):.1e}", plan_error(1e-9) > 1
    (None, '2.2e-02', True)
    """
    err = tolerances.LOSS * float(np.finfo(float).eps) / (sine * sine)
    return err if err > tolerances.PRINTED else None


def sine_figure(sine):
    """The conditioning figure of a group's lines from the kernel's signed ``sine`` (a
    number or an array): |sin| within [0, 1], the cross product of two unit vectors as
    rounded reaching 1.0000000000000002, which the kernel divides by as it is; 0 where it
    is not a number (parallel lines). The sweep clips its own in its blocks
    (:func:`plans.kinematics.sweep.sweep`), where it is NaN only where nothing closes."""
    s = np.abs(sine)
    return np.where(np.isfinite(s), np.minimum(s, 1.0), 0.0)


def sine_at(g, k: int | None = None) -> float:
    """|sin| of the angle between the two lines of group ``g``'s plans (``k``: the angle's
    index in an array solution; None for a solution on Python numbers), as
    :func:`sine_figure`."""
    s = g.velocity.sine
    return float(sine_figure(s if k is None else s[k]))


# ---------------------------------------------------------------------------------------
# a slotted link's pivot figure
# ---------------------------------------------------------------------------------------

#: what the pivot figure's key adds to its group's label ("group 2–3 (RPR) pivot"), in a
#: sweep's :attr:`plans.kinematics.sweep.Sweep.pivot` and a cycle row's figures alike
PIVOT = " pivot"


def pivot_key(label: str) -> str:
    """The key of group ``label``'s pivot figure."""
    return label + PIVOT


def is_pivot(key: str) -> bool:
    """Whether a figure's key is a pivot figure's (else it is a group's lines' sine)."""
    return key.endswith(PIVOT)


def pivot_ratio(P, Q, crank):
    """|QP| / (|OQ| + |OP|) of a block P, a rocker's pivot Q and the crank's pivot O
    (``crank``; arrays or Python numbers); 0 where all three coincide."""
    loop = abs(Q - crank) + abs(P - crank)
    if isinstance(loop, float):  # the one-angle path, on Python numbers
        return abs(P - Q) / loop if loop > 0 else 0.0
    with np.errstate(all="ignore"):
        return np.where(loop > 0, np.abs(P - Q) / np.where(loop > 0, loop, 1.0), 0.0)


def pivot_figure(g, position: dict, crank_pivot: complex):
    """For a slotted link (RPR): how far the block P is from the rocker's pivot Q, relative
    to the loop, |QP| / (|OQ| + |OP|) with O the crank's pivot (arrays or Python numbers,
    as ``position`` holds them); None for the other kinds. Near 0 the rocker's
    ω = V / |QP| loses its digits, though the two lines of the plans stay perpendicular."""
    if g.group.kind != DyadKind.RPR:
        return None
    return pivot_ratio(position[g.group.P], position[g.group.Q], crank_pivot)


# ---------------------------------------------------------------------------------------
# the errors
# ---------------------------------------------------------------------------------------


def _error(cls, template: str, at: str, fields: dict, **numbers):
    """An error of ``cls`` worded by :data:`plans.kinematics.words.ERRORS`' ``template``
    with ``fields``, its crank angle said ``at``."""
    words = Sentence(template, tuple(fields.items()))
    return cls(words(at), at=at, words=words, **numbers)


def failure(g, k: int, at: str, note: str = "", source: str = "",
            phi: float | None = None):
    """The error for angle index ``k`` where group ``g`` does not close; ``at`` names the
    crank angle ("φ1 = 330°", :meth:`plans.model.mechanism.Driver.at`), ``phi`` is it.

    A group that misses (its links do not reach) is an :class:`AssemblyError` with the
    distance it misses by; one exactly at the limit (links in line, parallel guides,
    a pivot on the pin) is a dead point: a :class:`SingularPlanError`.
    """
    label = g.group.label
    if bool(g.singular[k]):
        return _error(SingularPlanError, "dead", at,
                      {"label": g.group.labels(), "why": g.why_singular, "note": note},
                      source=source, phi=phi, group=label)
    gap = float(g.gap[k])
    return _error(AssemblyError, "misses", at,
                  {"label": label, "admissible": g.admissible, "gap": f"{gap:.6g}", "note": note},
                  source=source, phi=phi, group=label, gap=gap, admissible=g.admissible)


def parallel(g, k: int | None, at: str, source: str = "", below: float | None = None,
             phi: float | None = None) -> SingularPlanError | None:
    """The error where the two lines of group ``g``'s plans are parallel (|sin| below
    :data:`plans.tolerances.SINGULAR_SINE`): a dead point, no unique plan. None elsewhere.
    ``below``: :data:`plans.tolerances.CHANGE_SINE` beside a change point."""
    below = tolerances.SINGULAR_SINE if below is None else below
    s = sine_at(g, k)
    if s >= below:
        return None
    r0, r1 = g.velocity.routes
    fields = {"label": g.group.labels(), "r0": r0.relation, "r1": r1.relation,
              "degrees": f"{_degrees(s):.3g}", "sine": f"{s:.3g}", "below": f"{below:g}"}
    template = "beside" if s >= tolerances.SINGULAR_SINE else "parallel"
    return _error(SingularPlanError, template, at, fields, sine=s, source=source, phi=phi,
                  group=g.group.label)


def on_pivot(g, q: float, at: str, source: str = "", below: float | None = None,
             phi: float | None = None) -> SingularPlanError | None:
    """The error where the block is on the rocker's pivot (``q`` from :func:`pivot_figure`
    below :data:`plans.tolerances.SINGULAR_SINE`, or ``below`` beside a change point): the
    rocker's direction, ω and ε are undefined. None elsewhere."""
    below = tolerances.SINGULAR_SINE if below is None else below
    if not q < below:
        return None
    where = (in_every_language("is_on") if q < tolerances.SINGULAR_SINE else
             in_every_language("all_but_on", below=f"{below:g}"))
    fields = {"label": g.group.labels(), "P": g.group.P, "Q": g.group.Q, "where": where,
              "figure": f"{q:.3g}"}
    return _error(SingularPlanError, "on_pivot", at, fields, sine=q, source=source, phi=phi,
                  group=g.group.label)


# ---------------------------------------------------------------------------------------
# the warnings
# ---------------------------------------------------------------------------------------


def _group(words: dict, g) -> str:
    label = g.group.label
    return words["group"].format(label=label, short=label.removeprefix("group "))


def near_parallel(g, k: int | None, at: str, lang: str = "en",
                  below: float | None = None) -> str | None:
    """The warning where the two lines of group ``g``'s plans meet at under about 2°
    (|sin| below :data:`plans.tolerances.WARN_SINE`), when they are not parallel
    (``below``, as for :func:`parallel`); in ``lang``. None elsewhere."""
    below = tolerances.SINGULAR_SINE if below is None else below
    s = sine_at(g, k)
    if not below <= s < tolerances.WARN_SINE:
        return None
    words = WARNINGS[lang]
    fig = words["number"]
    r0, r1 = g.velocity.routes
    err = plan_error(s)  # said where the four digits printed are not all right
    lost = ("" if err is None else words["lost_all"] if err >= 1 else
            words["lost_some"].format(percent=fig(100 * err, 2)))
    return words["near_parallel"].format(group=_group(words, g), at=at, r0=r0.relation,
                                         r1=r1.relation, degrees=fig(_degrees(s), 3),
                                         sine=fig(s, 3), lost=lost)


def near_pivot(g, q: float, at: str, lang: str = "en", below: float | None = None) -> str | None:
    """The warning where the block passes close to the rocker's pivot (``q`` under
    :data:`plans.tolerances.WARN_SINE`, not on it: ``below`` as for :func:`on_pivot`); in
    ``lang``. None elsewhere."""
    below = tolerances.SINGULAR_SINE if below is None else below
    if not below <= q < tolerances.WARN_SINE:
        return None
    words = WARNINGS[lang]
    return words["near_pivot"].format(group=_group(words, g), at=at, P=g.group.P, Q=g.group.Q,
                                      figure=words["number"](q, 3))


def flagged(groups, position: dict, crank_pivot: complex, at, source: str = "",
            below=None, phi: float | None = None) -> tuple:
    """The conditioning figures of one position (groups and positions on Python numbers)
    that call for a word: (group, "lines" or "pivot", figure) for each under
    :data:`plans.tolerances.WARN_SINE`, the sine between a group's two lines or a slotted
    link's pivot figure. One that is singular raises its error. ``at()`` names the crank
    angle (``phi``), asked only then; ``below(i)``, the singular figures (lines, pivot) of
    the i-th group (:meth:`plans.kinematics.Solver.singular_figures`). The words, in
    either language, are :func:`flag_words`."""
    out = []
    warn = tolerances.WARN_SINE
    for i, g in enumerate(groups):
        lines = abs(g.velocity.sine)
        q = pivot_figure(g, position, crank_pivot)
        if warn <= lines < math.inf and (q is None or q >= warn):
            continue
        plain = tolerances.SINGULAR_SINE
        under, under_q = (plain, plain) if below is None else below(i)
        if not warn <= lines < math.inf:  # NaN, inf: parallel() refuses them
            if (err := parallel(g, None, at(), source, under, phi)) is not None:
                raise err
            out.append((g, "lines", sine_at(g, None)))
        if q is not None and q < warn:
            if (err := on_pivot(g, q, at(), source, under_q, phi)) is not None:
                raise err
            out.append((g, "pivot", q))
    return tuple(out)


def flag_words(flag: tuple, at: str, lang: str = "en") -> str:
    """The warning for one of :func:`flagged`'s figures, in ``lang``."""
    g, kind, figure = flag
    return near_parallel(g, None, at, lang) if kind == "lines" else near_pivot(g, figure, at, lang)


def _degrees(sine: float) -> float:
    return math.degrees(math.asin(min(sine, 1.0)))
