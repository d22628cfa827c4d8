"""The student's plans rebuilt from the measured lengths, for the overlay
(:mod:`drawing.overlay`): each point placed from the segments measured to it.
"""

from __future__ import annotations

from plans.check.items import MU_KEY
from plans.check.replay import Replayer
from plans.geometry import circle_circle, cross


def rebuild(result) -> dict[str, dict[str, complex]]:
    """Points of each plan (mm at the student's scale, pole at 0) placed from the measured
    segments: a point measured from two placed points by the intersection of two circles
    (the one nearer the reference), from one placed point along the reference direction.
    The reference is the plan of the diagnosed mistake if there is one, else the exact
    plan. Points that no measurement reaches are left out."""
    meas = result.measurement
    diag = result.diagnosis
    st = diag.best.state if diag.best and diag.best.state is not None else Replayer(meas.solution).exact()
    out: dict[str, dict[str, complex]] = {}
    for kind in ("velocity", "acceleration"):
        plan = meas.solution.velocity if kind == "velocity" else meas.solution.acceleration
        mu = meas.mu[MU_KEY[kind]] / st.factor[kind]
        ref = {n: z / mu for n, z in st.values(kind).items()}
        segs = [(it.start, it.end, it.measured) for it in meas.items
                if it.kind == "segment" and it.plan == kind]
        placed = {plan.pole: 0j}
        for n, p in plan.points.items():
            if p.source.kind == "pole":
                placed[n] = 0j
        order = list(plan.points)
        changed = True
        while changed:
            changed = False
            for n in order:
                if n in placed:
                    continue
                anchors = []
                for a, b, L in segs:
                    if a == n and b in placed:
                        anchors.append((b, L))
                    elif b == n and a in placed:
                        anchors.append((a, L))
                if not anchors:
                    continue
                z = _place(n, anchors, placed, ref)
                if z is not None:
                    placed[n] = z
                    changed = True
        out[kind] = {n: z for n, z in placed.items()
                     if any(n in (a, b) for a, b, _ in segs) or n == plan.pole}
    return out


def _place(n, anchors, placed, ref):
    uniq = {}
    for a, L in anchors:
        uniq.setdefault(placed[a], (a, L))
    anchors = list(uniq.values())
    if len(anchors) >= 2:
        best = None
        for i, (a, La) in enumerate(anchors):
            for b, Lb in anchors[i + 1:]:
                ua, ub = ref[n] - ref[a], ref[n] - ref[b]
                s = abs(cross(ua, ub)) / max(abs(ua) * abs(ub), 1e-300)
                if best is None or s > best[0]:
                    best = (s, a, La, b, Lb)
        s, a, La, b, Lb = best
        if s > 0.05:
            guess = placed[a] + (ref[n] - ref[a])
            d = abs(placed[b] - placed[a])
            if d > 1e-9:
                cands = []
                for sign in (1, -1):
                    z, disc = circle_circle(placed[a], La, placed[b], Lb, sign)
                    if disc < 0:  # the circles miss: the nearest point between them
                        u = (placed[b] - placed[a]) / d
                        z = placed[a] + u * (La + (d - La - Lb) / 2 if d > La + Lb else
                                             (La if La > Lb else d - Lb))
                    cands.append(complex(z))
                return min(cands, key=lambda z: abs(z - guess))
    a, L = anchors[0]
    u = ref[n] - ref[a]
    if abs(u) < 1e-12:
        return None
    return placed[a] + L * u / abs(u)
