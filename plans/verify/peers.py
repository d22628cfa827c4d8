"""Peer packages the bench measures beside the engine: pylinkage's model of the scenes it
can take (a crank with one RRR group on a fixed pivot or one RRP group on a fixed guide).
"""

from __future__ import annotations

import numpy as np

from plans.model.structure import DyadKind


def pylinkage_model(pl, mech, solver, phi):
    """A pylinkage linkage for a crank + one RRR group on a fixed pivot, or a crank + one
    RRP group on a fixed guide; returns a function that runs it over ``phi`` (a uniform
    grid) and gives {point: positions}, velocities, accelerations as complex arrays."""
    groups = solver.structure.groups
    drv = mech.driver
    if len(groups) != 1:
        raise NotImplementedError("more than one group")
    g = groups[0]
    if g.P != drv.tip:
        raise NotImplementedError("the group is not hinged to the crank")
    if g.kind == DyadKind.RRR:
        if g.Q not in mech.frame:
            raise NotImplementedError("the rocker is not hinged to the frame")
    elif g.kind == DyadKind.RRP:
        if g.s1.guide.link != 0:
            raise NotImplementedError("a moving guide")
    else:
        raise NotImplementedError(f"no {g.kind.name} group in pylinkage")
    with np.errstate(all="ignore"):
        start = solver.solve(phi[:1])
    C0 = complex(start.position[g.C][0])
    l2 = abs(mech.links[g.a].points[g.C] - mech.links[g.a].points[g.P])
    n = len(phi)
    step = float(phi[1] - phi[0]) if n > 1 else 0.0

    def build():
        pivot = mech.frame[drv.pivot]
        ground = pl.Ground(pivot.real, pivot.imag, name=drv.pivot)
        crank = pl.Crank(
            anchor=ground,
            radius=drv.length,
            angular_velocity=step,
            initial_angle=float(phi[0]) - step,
            name=drv.tip,
        )
        comps = [ground]
        if g.kind == DyadKind.RRR:
            Q = mech.frame[g.Q]
            gq = pl.Ground(Q.real, Q.imag, name=g.Q)
            l3 = abs(mech.links[g.b].points[g.C] - mech.links[g.b].points[g.Q])
            comps.append(gq)
            dyad = pl.RRRDyad(
                anchor1=crank.output,
                anchor2=gq,
                distance1=l2,
                distance2=l3,
                x=C0.real,
                y=C0.imag,
                name=g.C,
            )
        else:
            gd = g.s1.guide
            a, b = gd.point, gd.point + gd.direction
            la = pl.Ground(a.real, a.imag, name="L1")
            lb = pl.Ground(b.real, b.imag, name="L2")
            comps += [la, lb]
            dyad = pl.RRPDyad(
                revolute_anchor=crank.output,
                line_anchor1=la,
                line_anchor2=lb,
                distance=l2,
                x=C0.real,
                y=C0.imag,
                name=g.C,
            )
        comps += [crank, dyad]
        linkage = pl.Linkage(comps, name=mech.name)
        linkage.set_input_velocity(crank, omega=drv.omega)
        which = ((drv.tip, comps.index(crank)), (g.C, comps.index(dyad)))
        P = {k: np.empty(n, complex) for k, _ in which}
        V = {k: np.empty(n, complex) for k, _ in which}
        A = {k: np.empty(n, complex) for k, _ in which}
        for k, (pos, vel, acc) in enumerate(
            linkage.step_with_derivatives(iterations=n)
        ):
            for nm, i in which:
                P[nm][k] = complex(*pos[i])
                V[nm][k] = complex(*vel[i]) if vel[i] is not None else complex("nan")
                A[nm][k] = complex(*acc[i]) if acc[i] is not None else complex("nan")
        return P, V, A

    return build

