"""Assembly branches from human-readable hints: "above BD", "right of C".

Each group with two assemblies gets a sign, chosen at the file's crank angle by the hints
and then kept over the whole cycle, so the branch stays continuous.
"""

from __future__ import annotations

from .errors import AssemblyError, InputError, SingularPlanError
from .geometry import cross
from .mechanism import Mechanism
from .records import coincident_name
from .structure import DyadKind, Structure

RELATIONS = ("above", "below", "left of", "right of")


def parse_hint(hint: str, names: list[str]) -> tuple[str, list[str]]:
    """``"above BD"`` → ("above", ["B", "D"]); ``"right of C"`` → ("right of", ["C"])."""
    text = " ".join(hint.strip().split())
    for rel in RELATIONS:
        if text.startswith(rel + " "):
            rest = text[len(rel) + 1 :].replace("line ", "").replace("-", "").replace(" ", "")
            refs: list[str] = []
            while rest:
                match = max((n for n in names if rest.startswith(n)), key=len, default=None)
                if match is None:
                    raise ValueError(f'"{rest}" is not a point name')
                refs.append(match)
                rest = rest[len(match) :]
            if len(refs) not in (1, 2):
                raise ValueError("name one point or a line through two points")
            return rel, refs
    raise ValueError('a hint reads "above BD", "below BD", "left of C" or "right of C"')


#: above and below a vertical line (left and right of a horizontal one) are not defined:
#: the hint is refused. Only a line vertical to rounding: one a degree off still has a
#: side that points up, and a table's own hint ("C above BD") passes near vertical as
#: the crank turns
UPRIGHT = 1e-9


class Ambiguous(ValueError):
    """A hint whose line stands across the sides it names ("above" a vertical line)."""


def hint_holds(rel: str, X: complex, refs: list[complex]) -> bool:
    if len(refs) == 1:
        Q = refs[0]
        return {"above": X.imag > Q.imag, "below": X.imag < Q.imag,
                "left of": X.real < Q.real, "right of": X.real > Q.real}[rel]
    Q, R = refs
    d = R - Q
    across = d.real if rel in ("above", "below") else d.imag
    if abs(across) < UPRIGHT * abs(d):
        raise Ambiguous("vertical" if rel in ("above", "below") else "horizontal")
    if rel in ("above", "below"):
        if d.real < 0:
            d = -d
        side = cross(d, X - Q) > 0
        return side if rel == "above" else not side
    if d.imag < 0:
        d = -d
    side = cross(d, X - Q) > 0
    return side if rel == "left of" else not side


def choose_branches(mech: Mechanism, structure: Structure) -> tuple[int, ...]:
    """Turn the file's hints into a sign per group, evaluated at the file's crank angle
    (``mech.hints_at`` when the crank was turned from it, :meth:`Mechanism.at_file_angle`).

    The sign (which side of the line of centres, which way along the guide) is then kept
    over the whole cycle, so the branch stays continuous: ``--angle 180`` gives the
    position the cycle passes through at 180°, not whichever assembly the hint's words
    would pick there. Where the mechanism does not close at the file's angle, the hints
    are read at the angle asked for instead.
    """
    at = mech.hints_at
    if at is not None and at != mech.driver.phi:
        try:
            return _choose(mech.with_phi(at), structure)
        except (AssemblyError, SingularPlanError):
            pass
    return _choose(mech, structure)


def _choose(mech: Mechanism, structure: Structure) -> tuple[int, ...]:
    from .kinematics import Solver  # it calls back here: imported when first needed

    names = mech.point_names()
    hints = {}
    for key, text in mech.assembly.items():
        try:
            hints[key] = parse_hint(text, names)
        except ValueError as exc:
            raise InputError(mech.source, f"assembly.{key}: {exc}") from None
    used = set()
    sigmas: list[int] = []
    for i, g in enumerate(structure.groups):
        if g.kind in (DyadKind.PRP, DyadKind.RPP):
            sigmas.append(1)
            continue
        group_points = set(mech.links[g.a].points) | set(mech.links[g.b].points)
        mine = {k: h for k, h in hints.items() if k in group_points}
        ok = []
        positions = {}
        for sigma in (1, -1):
            trial = Solver(mech, structure, tuple(sigmas) + (sigma,) + (1,) * (len(structure.groups) - i - 1))
            motion = trial._solve_upto(i + 1)
            positions[sigma] = motion
            for k, (_, refs) in mine.items():
                if later := [r for r in refs if r not in motion.position]:
                    raise InputError(
                        mech.source,
                        f"assembly.{k}: {mech.assembly[k]!r} names {later[0]}, a point found "
                        f"after {g.label}, the group of {k}: name fixed points or points found "
                        "before it")
            if not motion.valid[0]:
                continue
            holds = True
            for k, (rel, refs) in mine.items():
                try:
                    holds &= hint_holds(rel, complex(motion.position[k][0]),
                                        [complex(motion.position[r][0]) for r in refs])
                except Ambiguous as exc:
                    line = "".join(refs)
                    other = ('"left of {0}" or "right of {0}"' if str(exc) == "vertical"
                             else '"above {0}" or "below {0}"').format(line)
                    raise InputError(
                        mech.source,
                        f"assembly.{k}: {mech.assembly[k]!r}: the line {line} is {exc} at "
                        f"{mech.driver.at(mech.driver.phi)}, so {rel} it names no side: "
                        f"write {other}") from None
            if holds:
                ok.append(sigma)
        used |= set(mine)
        if len(ok) == 1:
            sigmas.append(ok[0])
            continue
        if g.kind == DyadKind.RPR and not mine:
            sigmas.append(1)  # the guide's axis points from its pivot towards the block
            continue
        if not positions[1].valid[0]:
            earlier = sorted(used - set(mine))
            note = ""
            if earlier:
                asked = ", ".join(f"{k} = {mech.assembly[k]!r}" for k in earlier)
                note = f" (the groups before it are assembled as the hints {asked} ask: is one of them wrong?)"
            raise positions[1].groups[i].failure(0, mech.driver.at(mech.driver.phi), note,
                                                 source=mech.source)
        new = g.C or coincident_name(g.P, g.b)
        key = g.C or next(iter(mech.links[g.b].points))
        if not mine:
            cands = []
            for sigma in (1, -1):
                X = complex(positions[sigma].position[key][0])
                cands.append(f"({X.real:.4g}, {X.imag:.4g})")
            raise InputError(
                mech.source,
                f"assembly: {g.label} closes two ways at {mech.driver.at(mech.driver.phi)}, with {key} at "
                f"{cands[0]} or {cands[1]}: add a hint such as [assembly] {key} = "
                f'"above {g.P or ""}{g.Q or ""}"',
            )
        hints_ = ", ".join(f"{k} = {mech.assembly[k]!r}" for k in mine)
        if ok:  # both: say where the two are, so that the hint can be chosen between them
            spots = " and ".join(f"({X.real:.4g}, {X.imag:.4g})" for X in (
                complex(positions[sigma].position[key][0]) for sigma in (1, -1)))
            raise InputError(
                mech.source,
                f"assembly: the {'hint' if len(mine) == 1 else 'hints'} {hints_} "
                f"{'fits' if len(mine) == 1 else 'fit'} both "
                f"assemblies of {g.label} at {mech.driver.at(mech.driver.phi)}, with {key} at "
                f"{spots}: name a point or line that parts them")
        raise InputError(
            mech.source,
            f"assembly: the {'hint' if len(mine) == 1 else 'hints'} {hints_} "
            f"{'fits' if len(mine) == 1 else 'fit'} neither "
            f"assembly of {g.label} at {mech.driver.at(mech.driver.phi)} (new point {new})",
        )
    unused = set(hints) - used
    if unused:
        k = sorted(unused)[0]
        raise InputError(mech.source, f"assembly.{k}: {k} is not a point of a group with two assemblies")
    return tuple(sigmas)
