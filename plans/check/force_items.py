"""The force analysis's items of a measurement file: the ``[forces]`` table (μF, the force
plans' segments, Zhukovsky's lever) and the forces and moments of ``[values]``, by the names
``plans forces`` prints, in the spellings a student types.

    [forces]
    mu_F = 20              # N/mm, every force plan; or by group: mu_F = { "4-5" = 10, "2-3" = 20 }
    "R12^τ" = 28.4         # a segment of a force plan, mm at μF
    pb = 49                # Zhukovsky's lever: the crank pin's image, mm of the velocity plan at μv
    h.G1 = 19              # the arm of G1 on the lever, mm
    [values]
    R12 = 2009             # N;  F_у = 1942 (N);  M_у = "120.3 ccw" (N·m, with its sense)

A name may be typed as the note and the textbooks write it: R12^t, R12t or R^τ_12 for
R12^τ; Фи2, Fи2, Ф2, φ2 or Phi2 for Φ2; Ми3, M_и3 or MΦ3 for M_Φ3 (and Ри3C for the force
of its pair at C, M_Φ3(C)); F_y, Fy or FУ for F_у; FПС for F_пс; a Cyrillic letter for a
Latin one that looks the same (Р for P); with or without "_", "^" and braces, in either case.
A name that two of the analysis's names could be is refused as such.
"""

from __future__ import annotations

import re
import unicodedata
from typing import Any

from plans.check.forces import F_Y, ForceContext, group_key
from plans.check.items import Item
from plans.check.reading import magnitude_sense, number, scale
from plans.model.fileformat import LOOKALIKES, Problems, close_match, key_text, quote

#: the key of the force plans' scale factor, as a file may write it
MU_F = ("mu_F", "μF", "μ_F")
#: the lever's arms: a table of [forces]
ARMS = "h"
_LATIN = {c.lower(): x.lower() for c, x in LOOKALIKES.items()}


def canonical(name: str) -> str:
    """One spelling of a force's name, for matching what a student types to the analysis's
    names: no spaces, "_", "^" or braces, case folded, Φ for its spellings (Фи, Fи, φ, Phi),
    M_Φ for the inertia moment's (Ми, Mи, MФ), a pair's force Ри3C as M_Φ3(C), a Cyrillic
    letter as the Latin one it looks like, τ for t after a reaction's number.

    >>> [canonical(x) for x in ("R12^τ", "R^t_12", "R12t", "Fи2", "Фи2", "M_Φ3", "Ми3", "FПС", "F_пс")]
    ['r12τ', 'r12τ', 'r12τ', 'φ2', 'φ2', 'mφ3', 'mφ3', 'fпc', 'fпc']
    >>> [canonical(x) for x in ("F_у", "FУ", "Fy", "M_y", "Ри3C", "M_Φ3(C)", "Р", "R_{05}")]
    ['fy', 'fy', 'fy', 'my', 'mφ3(c)', 'mφ3(c)', 'p', 'r05']
    """
    s = unicodedata.normalize("NFC", str(name))
    s = re.sub(r"[\s_^{}\\]", "", s).casefold()
    s = re.sub(r"^(?:[mм])(?:фи|φи|ф|φ|phi|и)", "mφ", s)  # M_Φ3, Ми3, MФи3
    s = re.sub(r"^(?:фи|φи|fи|ф|φ|phi)", "φ", s)  # Φ2, Фи2, Fи2
    s = re.sub(r"^[pр]и(?=\d)", "mφ", s)  # Ри3C: the force of M_Φ3's pair at C
    s = "".join(_LATIN.get(c, c) for c in s)
    s = re.sub(r"^mφ(\d+)\(?([a-z]\w*)\)?$", r"mφ\1(\2)", s)
    s = re.sub(r"^([fm])yp?$", r"\1y", s)  # F_у, F_ур (уравновешивающая), M_у
    s = re.sub(r"^r([τtn])(\d[\d,]*)$", r"r\2\1", s)  # R^τ_12
    return re.sub(r"^(r\d[\d,]*)t$", r"\1τ", s)


class ForceNames:
    """The names of one force analysis: its force plans' segments (each by its group), its
    forces and moments, the forces on its lever; and the items a file names by them."""

    def __init__(self, ctx: ForceContext):
        self.ctx = ctx
        fa = ctx.analysis
        self.segments: dict[str, str] = {}  # label → the group key of its plan
        self.twice: set[str] = set()  # a label on two plans (a file's own force named R43…)
        for gf in fa.groups:
            for label in gf.plan.ends:
                if label in self.segments:
                    self.twice.add(label)
                self.segments.setdefault(label, group_key(gf))
        exact = ctx.drawn()
        self.kinds = {name: "moment" if isinstance(v, float) else "force" for name, v in exact.values.items()}
        self.kinds[F_Y] = "balancing"
        self.terms = list(ctx.lever[0])
        self.read_off = ctx.read_off

    # ------------------------------------------------------------------------------------

    @staticmethod
    def _match(name: str, pool) -> list[str]:
        if name in pool:
            return [name]
        c = canonical(name)
        return [k for k in pool if canonical(k) == c]

    def _known_segments(self) -> str:
        parts = []
        for key in self.ctx.keys:
            labels = [lb for lb, k in self.segments.items() if k == key]
            parts.append(f"{', '.join(labels)} (group {key})")
        return "; ".join(parts)

    def is_pb(self, key: str) -> bool:
        """The lever's pb as a file may name it: p and the crank pin's letter (pb, pvb)."""
        tip = canonical(self.ctx.tip)
        return canonical(key) in (f"p{tip}", f"pv{tip}")

    def segment(self, key: str, where: str, name: str, mm: float, problems: Problems) -> Item | None:
        hit = self._match(name, self.segments)
        if len(hit) != 1:
            if hit:
                problems.add(where, f'"{name}" can be read as {" or ".join(hit)}: write it as one of them')
            else:
                known = [*self.segments, *MU_F[:1], ARMS, self.ctx.pb_name]
                problems.add(where, f'unknown force-plan segment "{name}"; {close_match(name, known)}'
                             f"known: {self._known_segments()}; and {MU_F[0]}, {ARMS}.<force> (the lever's "
                             f"arms), {self.ctx.pb_name}")
            return None
        label = hit[0]
        if label in self.twice:
            problems.add(where, f'"{label}" is a segment of two force plans: it cannot be told which')
            return None
        gf = self.ctx.analysis.groups[self.ctx.keys.index(self.segments[label])]
        a, b = gf.plan.ends[label]
        return Item(key, label, "segment", "force", mm, a, b, group=self.segments[label])

    def arm(self, key: str, where: str, name: str, mm: float, problems: Problems) -> Item | None:
        if canonical(name) == canonical(F_Y):  # F_у's arm is pb
            return self.pb(key, mm)
        hit = self._match(name, self.terms)
        if len(hit) != 1:
            if hit:
                problems.add(where, f'"{name}" can be read as {" or ".join(hit)}: write it as one of them')
            else:
                problems.add(where, f'unknown force on the lever "{name}"; {close_match(name, self.terms)}'
                             f"known: {', '.join(self.terms)}, {F_Y}")
            return None
        return Item(key, f"h_{hit[0]}", "segment", "lever", mm, hit[0])

    def pb(self, key: str, mm: float) -> Item:
        return Item(key, self.ctx.pb_name, "segment", "lever", mm)

    def value(self, key: str, where: str, name: str, value: Any, problems: Problems,
              mu_F: dict[str, float]) -> Item | bool | None:
        """The item of [values] ``name`` (a force in N, a moment in N·m with its sense, F_у);
        False where it names none of the analysis's forces and moments."""
        hit = self._match(name, self.kinds)
        if not hit:
            return False
        if len(hit) > 1:
            problems.add(where, f'"{name}" can be read as {" or ".join(hit)}: write it as one of them')
            return None
        name = hit[0]
        kind = self.kinds[name]
        mag, sense = magnitude_sense(value, where, problems, allow_sense=kind != "force",
                                     kind="moment" if kind == "moment" else "force")
        if mag is None:
            return None
        # read off a force plan: 1 mm of it is μF (N) of the reaction, as for a value read off
        # a velocity plan; the loads, the moment equations' components, F_у and M_у: 5 %
        per_mm = mu_F.get(self.read_off.get(name, ""), 0.0)
        return Item(key, name, kind, "force", mag, sense=sense, per_mm=per_mm)

    def known_values(self) -> str:
        return ", ".join(self.kinds)


def read_forces(raw: Any, names: ForceNames, problems: Problems) -> tuple[list[Item], dict[str, float], Any]:
    """The items of ``[forces]`` (segments, the lever's arms, pb) and the student's μF: by
    group key, and as the file writes it (one number, or a table by group)."""
    items: list[Item] = []
    mu_at: tuple[str, Any] | None = None
    for key, value in raw.items():
        where = f"forces.{key_text(key)}"
        if key in MU_F:
            if mu_at is not None:
                problems.add(where, f"gives μF again ({mu_at[0]} gives it already): give it once")
                continue
            mu_at = (key, value)
        elif key == ARMS:
            if not isinstance(value, dict):
                problems.add(where, "must be a table of the lever's arms in mm, e.g. h.G1 = 19 or "
                             '[forces.h] G1 = 19, "Fи2" = 24')
                continue
            for k2, v2 in value.items():
                w2 = f"{where}.{key_text(k2)}"
                x = number(v2, w2, problems, nonneg=True)
                if x is not None and (it := names.arm(f"forces.{key}.{k2}", w2, k2, x, problems)):
                    items.append(it)
        elif isinstance(value, dict):
            problems.add(where, f"a sub-table of [forces] is {ARMS} (the lever's arms, mm) or {MU_F[0]} "
                         '(μF by group, e.g. mu_F = { "4-5" = 10, "2-3" = 20 })')
        else:
            x = number(value, where, problems, nonneg=True)
            if x is None:
                continue
            if names.is_pb(key):
                items.append(names.pb(f"forces.{key}", x))
            elif it := names.segment(f"forces.{key}", where, key, x, problems):
                items.append(it)
    mu_F, given = _mu_F(mu_at, names, problems)
    groups = list(dict.fromkeys(it.group for it in items if it.plan == "force"))
    if groups and mu_at is None:
        problems.add(f"forces.{MU_F[0]}", "missing: the scale factor the student used for the force plans "
                     "(N/mm), e.g. mu_F = 20")
    elif groups and given is not None:
        for g in groups:
            if g not in mu_F:
                first = next(it.key for it in items if it.group == g)
                problems.add(f"forces.{mu_at[0]}", f"no μF for the force plan of group {g} ({first} is "
                             f"measured on it): give {mu_at[0]}.\"{g}\"")
    return items, mu_F, given


def _mu_F(mu_at, names: ForceNames, problems: Problems) -> tuple[dict[str, float], Any]:
    if mu_at is None:
        return {}, None
    key, value = mu_at
    where = f"forces.{key_text(key)}"
    keys = names.ctx.keys
    if not isinstance(value, dict):
        x = scale(value, where, problems, "N/mm")
        return (dict.fromkeys(keys, x), x) if x is not None else ({}, None)
    out: dict[str, float] = {}
    by_links = {frozenset(map(int, k.split("–"))): k for k in keys}
    for k2, v2 in value.items():
        w2 = f"{where}.{key_text(k2)}"
        digits = re.findall(r"\d+", str(k2))
        if len(digits) == 1 and len(digits[0]) == 2:  # "45": links 4 and 5
            digits = list(digits[0])
        group = by_links.get(frozenset(map(int, digits))) if len(digits) == 2 else None
        if group is None:
            problems.add(w2, f"{quote(k2)} is not a group of the mechanism: its groups are "
                         f"{', '.join(keys)} (by their links)")
            continue
        x = scale(v2, w2, problems, "N/mm")
        if x is not None:
            if group in out:
                problems.add(w2, f"gives the μF of group {group} again: give it once")
            out[group] = x
    return out, dict(out)
