"""Every answer checked by the engine: the written mechanism file is read back
(:func:`plans.model.mechanism.from_dict`) and analysed by the same code as ``plans cycle``
(:func:`plans.cycle.analysis.analyse_cycle`), which must give back K, θ, the stroke H or
swing ψ and the Grashof class, and by the solver's positions over the turn, which must give
back γmin (or the largest pressure angle), each to 1e-12 relative; a mechanism through
given positions must pass through them.

γmin from the engine: the acute angle between coupler and rocker at every one of 3600
crank angles of its sweep, its least narrowed by golden-section search on the solver's
single-position solve; nothing of the synthesis's own formulas is used.
"""

from __future__ import annotations

import cmath
import math
from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from plans.cycle import Cycle, analyse_cycle
from plans.errors import PlansError
from plans.fmt import num
from plans.geometry import golden_min
from plans.kinematics.solver import Solver
from plans.model import Mechanism, from_dict
from plans.synthesis.design import Design, impossible
from plans.synthesis.mechfile import mechanism_dict

#: the agreement the re-analysis must reach, relative
TOLERANCE = 1e-12
#: crank angles a turn is searched at for an extreme, before it is narrowed
SAMPLES = 3600


@dataclass(frozen=True)
class Row:
    """One figure: the synthesis's value, the engine's, and their relative difference."""

    name: str
    synthesis: float
    engine: float
    unit: str  # "", "m", "°" (the values themselves in rad)
    #: what the difference is relative to (default: the synthesis's value)
    scale: float | None = None

    @property
    def error(self) -> float:
        if self.synthesis == self.engine:
            return 0.0
        scale = abs(self.synthesis) if self.scale is None else self.scale
        return abs(self.engine - self.synthesis) / max(scale, 1e-300)

    @property
    def shown(self) -> str:
        if self.unit == "°":
            return f"{num(math.degrees(self.engine), 6)}°"
        return f"{num(self.engine, 6)}{' ' + self.unit if self.unit else ''}"


@dataclass(frozen=True)
class Check:
    """The engine's re-analysis of the written file."""

    rows: tuple[Row, ...]
    mechanism: Mechanism
    cycle: Cycle
    grashof: str | None

    @property
    def worst(self) -> float:
        return max((r.error for r in self.rows), default=0.0)

    @property
    def ok(self) -> bool:
        return bool(self.worst <= TOLERANCE)


def extreme(sv: Solver, figure: Callable[[dict], np.ndarray], largest: bool,
            lo: float = 0.0, hi: float = 2 * math.pi) -> tuple[float, float]:
    """(value, crank angle) of the least (or ``largest``) of ``figure`` over the crank
    angles [lo, hi]: the solver's sweep at :data:`SAMPLES` angles, then golden-section
    search round the best on its single-position solve. ``figure`` takes the positions
    (dict of arrays or of complex numbers)."""
    phi = np.linspace(lo, hi, SAMPLES, endpoint=False)
    with np.errstate(all="ignore"):
        sw = sv.sweep(phi)
        v = figure(sw.position)
    sign = -1.0 if largest else 1.0
    w = np.where(np.isfinite(v), sign * v, np.inf)
    i = int(np.argmin(w))
    step = phi[1] - phi[0]

    def g(x: float) -> float:
        try:
            return sign * float(figure(sv.solve_one(x).position))
        except PlansError:
            return math.inf

    x = golden_min(g, float(phi[i] - step), float(phi[i] + step))
    best = min((g(x), x), (g(float(phi[i])), float(phi[i])))
    return sign * best[0], best[1]


def _angle_between(p, q):
    """The acute angle between directions ``p`` and ``q`` (arrays or numbers)."""
    c = (p * np.conj(q)).real / (np.abs(p) * np.abs(q))
    return np.arccos(np.clip(np.abs(c), 0.0, 1.0))


def _incline(v):
    """The acute angle of direction ``v`` to the x-axis (a slider's guide)."""
    return np.arcsin(np.clip(np.abs(np.imag(v)) / np.abs(v), 0.0, 1.0))


def check(design: Design) -> Check:
    """Analyse the mechanism file of ``design`` with the engine and compare; an answer
    the engine does not give back is an internal error (a bug), except for positions a
    linkage reaches only in its other assembly, which is said as the design's failure."""
    p, sol = design.problem, design.solution
    # a problem of the tables carried over ([loads], [drive], [title]) is located to its line
    # of the synthesis file, where the same keys are
    mech = from_dict(mechanism_dict(design), p.source, text=p.file_text)
    sv = Solver(mech)
    cycle = analyse_cycle(mech, solver=sv)
    rows: list[Row] = []
    f = sol.figures
    if p.kind in ("crank-rocker", "crank-slider", "slotted-link"):
        if cycle.theta is None or cycle.K is None or cycle.stroke is None:
            raise RuntimeError(f"the engine finds no extreme positions in the synthesised "
                               f"{p.kind}: {cycle.notes}")
        rows += [Row("K", f["K"], cycle.K, ""), Row("θ", f["theta"], cycle.theta, "°")]
        if p.kind == "crank-rocker":
            rows.append(Row("ψ", f["psi"], cycle.stroke, "°"))
        else:
            rows.append(Row("H", f["H"], cycle.stroke, "m"))
    if p.kind in ("crank-rocker", "function", "coupler"):
        def gamma(pos):
            return _angle_between(pos["C"] - pos["B"], pos["C"] - pos["D"])

        if cycle.full_turn:
            value, _ = extreme(sv, gamma, largest=False)
            rows.append(Row("γmin", f["gamma_min"], value, "°"))
    elif p.kind == "crank-slider":
        def delta(pos):
            return _incline(pos["C"] - pos["B"])

        value, _ = extreme(sv, delta, largest=True)
        rows.append(Row("δmax", f["delta_m"], value, "°"))
        if "delta_p" in f:
            rows.append(Row("δp", f["delta_p"], _start_angle(sv, mech, cycle, p.given["p"]), "°"))
    else:
        def alpha(pos):
            return _incline(pos["E"] - pos["D"])

        value, _ = extreme(sv, alpha, largest=True)
        rows.append(Row("αmax", f["alpha_max"], value, "°"))

        def rocker(pos):
            return np.angle((pos["D"] - pos["C"]) * 1j ** -1)  # from +y: within ±ψ/2

        lo, _ = extreme(sv, rocker, largest=False)
        hi, _ = extreme(sv, rocker, largest=True)
        rows.append(Row("ψ", f["psi"], hi - lo, "°"))
    if p.kind in ("function", "coupler"):
        rows += _through(design, sv)
    crank = cycle.full_turn and (cycle.grashof or "").startswith("crank-rocker")
    if p.kind == "crank-rocker" and not crank:
        raise RuntimeError(f"the engine does not find a crank-rocker in the synthesised linkage: "
                           f"{cycle.grashof}")
    return Check(tuple(rows), mech, cycle, cycle.grashof)


def _start_angle(sv: Solver, mech: Mechanism, cycle: Cycle, share: float) -> float:
    """The rod's pressure angle where the working stroke begins, p·H before its end: the
    crank angle found on the engine's output by bisection over the working stroke."""
    out = cycle.output
    start, end = cycle.extremes
    sense = 1.0 if mech.driver.omega > 0 else -1.0
    span = (sense * (end - start)) % (2 * math.pi)

    def s(phi: float) -> float:
        return float(out.value(sv.solve_one(phi), mech))

    s0, s1 = s(start), s(start + sense * span)
    target = s1 - share * (s1 - s0)
    lo, hi = 0.0, span
    for _ in range(200):
        mid = 0.5 * (lo + hi)
        if (s(start + sense * mid) - target) * (s1 - s0) < 0:
            lo = mid
        else:
            hi = mid
        if hi - lo < 1e-15:
            break
    pos = sv.solve_one(start + sense * 0.5 * (lo + hi)).position
    return float(_incline(pos["C"] - pos["B"]))


def _through(design: Design, sv: Solver) -> list[Row]:
    """The linkage at each given position's crank angle: the rocker's angle (function) or
    C (coupler) as given, on the assembly the file's hint picks."""
    p, sol = design.problem, design.solution
    A = sol.points["A"]
    rows = []
    n = len(p.given["phi"] if p.kind == "function" else p.given["B"])
    for i in range(n):
        B, C = sol.points[f"B{i + 1}"], sol.points[f"C{i + 1}"]
        phi = cmath.phase(B - A)
        try:
            pos = sv.solve_one(phi).position
        except PlansError as exc:
            raise impossible(p, "", f"the linkage found ({_links(sol)}) does not assemble at "
                             f"position {i + 1}: {exc}") from None
        if abs(pos["C"] - C) > 1e-9 * sol.lengths["BC"]:
            raise impossible(p, "", f"the linkage found ({_links(sol)}) reaches position {i + 1} "
                             "only in its other assembly (a branch defect): no one linkage "
                             "moves through the positions; change a position")
        if p.kind == "function":
            got = cmath.phase(pos["C"] - sol.points["D"])
            want = p.given["psi"][i]
            rows.append(Row(f"ψ{i + 1}", want, want + math.remainder(got - want, 2 * math.pi), "°",
                            max(abs(want), 1.0)))
        else:  # how far C is from where it is to be, over the coupler's length
            rows.append(Row(f"C{i + 1}", 0.0, abs(pos["C"] - C), "m", sol.lengths["BC"]))
    return rows


def _links(sol) -> str:
    return ", ".join(f"{k} = {num(v)} m" for k, v in sol.lengths.items())
