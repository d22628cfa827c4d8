"""``plans cycle``: every point and link over N crank positions of the cycle, as text,
CSV or JSON.

The table and its conditioning are computed by :mod:`plans.cycle.table` (positions
numbered from an extreme position of the output; per position the sines of the lines the
plans intersect). A position whose figure is singular has its values left out (``—`` in
the text, empty in CSV, null in JSON; its coordinates are given where its positions
stand, ``placed``) and the command exits with status 2 after writing everything else. A
position on or beside a change point gives its positions only and says why
("singular"); the command still exits with status 0.
"""

from __future__ import annotations

import csv
import io
import json
import math

import numpy as np

from drawing import chart as charts
from plans.cli.common import (
    EXIT_INPUT,
    EXIT_OK,
    add_source,
    angle_field,
    cycle_json,
    mechanism_from,
    number,
    place_json,
    say,
    warn,
)
from plans.cli.output import picture_format
from plans.cycle import existence, outside, reachable_cycle, shown_from, summary
from plans.cycle.table import CycleTable, compute, figure_labels
from plans.cycle.transmission import lines as transmission_lines
from plans.errors import AssemblyError
from plans.fmt import from_x, in_turn, json_angle, num
from plans.kinematics.conditioning import is_pivot
from plans.tolerances import NOISE

#: a table for reading or a file for a spreadsheet: 10⁵ rows of the press are 270 MB of
#: JSON; for more angles, Solver.sweep works on arrays (README, "Whole cycle")
MAX_POSITIONS = 100_000


def configure(p) -> None:
    add_source(p)
    p.add_argument(
        "--positions",
        type=number(1, MAX_POSITIONS, integer=True),
        default=12,
        metavar="N",
        help="number of crank positions (default 12), numbered from an extreme position",
    )
    fmt = p.add_mutually_exclusive_group()
    fmt.add_argument(
        "--csv", action="store_true", help="one row per position (SI units)"
    )
    fmt.add_argument(
        "--json", action="store_true", help="machine-readable output (SI units)"
    )
    p.add_argument(
        "-o", "--output", metavar="FILE", help="write to FILE instead of stdout"
    )
    p.add_argument(
        "--plot", metavar="FILE",
        help="also plot the output's s, v, a and every link's ω, ε over the cycle "
        "(PNG, SVG or PDF by the name's ending)",
    )


def run(args) -> int:
    n = args.positions
    plot_format = picture_format(args, "plot", "--plot") if args.plot is not None else None
    mech = mechanism_from(args)  # refuses an output that is an input, or two outputs one file
    try:
        table = compute(mech, n)
    except AssemblyError:  # its angle does not assemble: the cycle where it does, if any
        got = reachable_cycle(mech, n)
        if got is None:
            raise
        turned, solver, c = got
        # the hints read where the range is (the file's own angle does not close), or at
        # the file's angle (--angle beyond the range of a file whose angle closes)
        read = (", assembled as the hints ask at " + solver.at(solver.branch_at)
                if solver.branch_at == turned.driver.phi else "")
        warn("cycle", f"{outside(*angle_field(args, mech), c, mech.driver)}: the cycle runs "
                      f"over that range{read}", mech.source)
        table = compute(turned, n, solver)
    if args.json:
        text = json_chunks(table)
    elif args.csv:
        text = csv_chunks(table)
    else:
        text = to_text(table)
    plot = None
    if plot_format is not None:  # drawn before anything is written: all outputs or none
        angle_deg, panels = plot_panels(table)
        kind, d = table.cycle.kind, mech.driver
        x_label = (f"{d.phi_sym}, degrees turned from position 0" if kind == "turn" else "t, s"
                   if kind == "time" else f"{d.phi_sym}, m along {d.guide.label}")
        plot = charts.cycle_chart(angle_deg, panels, title=mech.name, fmt=plot_format, x_label=x_label)
    args.run_files.write(args.output, text)
    if plot is not None:
        args.run_files.write(args.plot, plot)
    warned = [i for i, s in enumerate(table.status) if s.warnings]
    failed = [i for i, s in enumerate(table.status) if s.errors]
    if warned:
        worst = min(warned, key=lambda i: table.status[i].min_sine)
        warn("cycle", f"{len(warned)} of {n} positions are near-singular (smallest figure at "
                      f"position {worst}: {_fig(min(table.status[worst].figures.values()))})")
    for i in failed:
        for e in table.status[i].errors:
            say("cycle", f"error: position {i}: {e}")
    singular = [i for i, s in enumerate(table.status) if s.singular]
    if singular:
        which = ", ".join(str(i) for i in singular)
        warn("cycle", f"position{'s' if len(singular) > 1 else ''} {which} "
                      f"{'are' if len(singular) > 1 else 'is'} on or beside a change point: "
                      "positions only, the plans there are singular")
    return EXIT_INPUT if failed else EXIT_OK


# ---------------------------------------------------------------------------------------
# the plot
# ---------------------------------------------------------------------------------------


def plot_panels(t: CycleTable) -> tuple[list[float], list[tuple[str, list[tuple[str, list[float]]]]]]:
    """What ``--plot`` draws over the crank angle (degrees turned from position 0, in the
    crank's sense): the output's s, v, a (a rocker's ψ, ω, ε), then ω and ε of every
    link, one panel each, as ``drawing.chart.cycle_chart`` takes them. A value a position
    does not give (its plans singular, or the position not placed) is NaN: a gap.

    >>> from plans.model.scenes import SCENES
    >>> from plans.cycle.table import compute
    >>> angle, panels = plot_panels(compute(SCENES["crank_slider_offset"].mechanism(), 4))
    >>> angle
    [0.0, 90.0, 180.0, 270.0]
    >>> [label for label, _ in panels]
    ['s_B, m', 'V_B, m/s', 'a_B, m/s²', 'ω, rad/s', 'ε, rad/s²']
    """
    m, mech, c = t.motion, t.mechanism, t.cycle
    n = len(t.status)
    phi = np.broadcast_to(np.asarray(m.phi, dtype=float), (n,))
    sense = 1.0 if mech.driver.omega >= 0 else -1.0
    turned = np.degrees(np.mod((phi - phi[0]) * sense, 2 * math.pi)) if n else phi
    if c.kind != "turn":  # over an instant or a slider's travel, as it is
        turned = phi
    ok = np.array([st.ok for st in t.status], dtype=bool)
    placed = np.array([st.placed for st in t.status], dtype=bool)

    def shown(values, rows) -> list[float]:
        got = np.broadcast_to(np.asarray(values, dtype=float), (n,))
        return np.where(rows, got, math.nan).tolist()

    panels = []
    o = c.output
    if o is not None and t.output_values is not None:
        if o.kind == "linear":
            heads = (f"s_{o.point}", f"V_{o.point}", f"a_{o.point}")
            units = ("m", "m/s", "m/s²")
            value = t.output_values
        else:
            heads = (f"ψ_{o.point}", f"ω{o.link}", f"ε{o.link}")
            units = ("°", "rad/s", "rad/s²")
            value = np.degrees(t.output_values)
        for head, unit, values, rows in zip(
                heads, units, (value, o.rate(m, mech), o.rate(m, mech, "acceleration")),
                (placed, ok, ok), strict=True):
            panels.append((f"{head}, {unit}", [(head, shown(values, rows))]))
    panels.append(("ω, rad/s", [(f"ω{i}", shown(m.links[i].omega, ok)) for i in t.links]))
    panels.append(("ε, rad/s²", [(f"ε{i}", shown(m.links[i].epsilon, ok)) for i in t.links]))
    return turned.tolist(), panels


def _fig(x: float) -> str:
    return "—" if not math.isfinite(x) else f"{x:.3g}"


def _ok(x) -> float | None:
    x = float(x) + 0.0  # + 0.0: no −0.0
    return x if math.isfinite(x) else None


# ---------------------------------------------------------------------------------------
# output
# ---------------------------------------------------------------------------------------


def _cycle_summary(t: CycleTable) -> dict:
    return cycle_json(t.cycle) | {"transmission": _transmission_head(t)} | (
        {} if t.conditions is None else {"crank_conditions": existence.as_json(t.conditions)})


def _numbering(t: CycleTable) -> str:
    c = t.cycle
    if c.kind == "time":
        return ("over the interval, from the extreme position that starts the working stroke"
                if c.periodic and len(c.extremes) == 2 else "over the interval in time, evenly")
    if c.kind == "range":
        return "over the input slider's travel where the linkage assembles"
    if not c.full_turn:
        return "over the crank range where the linkage assembles (it cannot make a full turn)"
    if len(c.extremes) == 2:
        return "from the extreme position that starts the working stroke"
    return "from the given crank position (the output has no two extreme positions)"


def json_chunks(t: CycleTable):
    """The JSON text of :func:`to_json` in pieces: the head, then one row per line, so
    that 10⁵ rows are written as they are made."""
    def dumps(x) -> str:
        return json.dumps(x, ensure_ascii=False, allow_nan=False)

    head = _json_head(t)
    yield "{\n" + "".join(f" {dumps(k)}: {dumps(v)},\n" for k, v in head.items()) + ' "rows": ['
    sep = "\n  "
    for row in _json_rows(t):
        yield sep + dumps(row)
        sep = ",\n  "
    yield "\n ]\n}\n"


def _json_head(t: CycleTable) -> dict:
    mech = t.mechanism
    return {
        "mechanism": mech.name,
        "positions": len(t.status),
        "numbering": _numbering(t),
        # the crank's ω by its link's number, as the CSV's columns and rows' links name it
        "crank_link": mech.driver.link,
        f"omega{mech.driver.link}": mech.driver.omega,
        "cycle": _cycle_summary(t),
        "point_names": list(t.points),
        "link_ids": list(t.links),
    }


def _transmission_head(t: CycleTable) -> dict:
    """Each group's γmin over the cycle, where, and its dead points (degrees)."""
    mech, tr = t.mechanism, t.transmission
    out = {}
    for g in tr.groups if tr is not None else ():
        fin = math.isfinite(g.gamma_min)
        out[g.group.label] = {
            "gamma_min_deg": math.degrees(g.gamma_min) if fin else None,
            "pressure_max_deg": math.degrees(g.pressure_max) if fin else None,
            "at": place_json(mech, g.at) if fin and not g.constant else None,
            "constant": g.constant,
            "dead_points": [place_json(mech, x) for x in g.dead],
            "change_points": [place_json(mech, x) for x in g.change]}
    return {"groups": out, "reversed_dead_points": [place_json(mech, x) for x in tr.reversed]
            if tr is not None else []}


def _place_cols(t: CycleTable, x: float) -> dict:
    """Where a row is: its crank angle (from +x and in the file's convention, to 1e-9°: 180,
    not 179.99999999999855); a slider input's travel; an instant and each input's coordinate."""
    mech = t.mechanism
    if t.cycle.kind == "turn":
        return {"phi_deg": json_angle(from_x(x)), "angle_deg": json_angle(mech.driver.file_angle(x))}
    if t.cycle.kind == "range":
        return {"s": x}
    out = {"t": x}
    for d, (q, _, _) in zip(mech.drivers, mech.inputs_at(x), strict=True):
        out[f"{d.phi_sym}_m" if d.linear else f"{d.phi_sym}_deg"] = (
            float(q) if d.linear else json_angle(d.file_angle(float(q))))
    return out


def _json_rows(t: CycleTable):
    m = t.motion
    for k, st in enumerate(t.status):
        phi = float(m.phi[k])
        good = st.ok
        row = {
            "index": k,
            **_place_cols(t, phi),
            "solved": good,
            "placed": st.placed,  # the positions stand (where not solved: a change point)
            "conditioning": {
                "min_sine": _ok(st.min_sine),
                "figures": {key: _ok(v) for key, v in st.figures.items()},
            },
            "warnings": list(st.warnings),
            "errors": list(st.errors),
            "singular": list(st.singular),
        }
        if t.output_values is not None:
            row["output"] = _ok(t.output_values[k]) if st.placed else None
        row["points"] = {
            name: {
                key: ([z.real + 0.0, z.imag + 0.0] if shown else None)
                for key, z, shown in (
                    ("position", complex(m.position[name][k]), st.placed),
                    ("velocity", complex(m.velocity[name][k]), good),
                    ("acceleration", complex(m.acceleration[name][k]), good),
                )
            }
            for name in t.points
        }
        row["links"] = {
            str(i): {
                "omega": _ok(m.links[i].omega[k]) if good else None,
                "epsilon": _ok(m.links[i].epsilon[k]) if good else None,
            }
            for i in t.links
        }
        row["transmission_deg"] = {label: _ok(math.degrees(g[k])) for label, g in (t.gamma or {}).items()}
        yield row


def _csv_header(t: CycleTable) -> list[str]:
    # the figures by their keys in a JSON row's conditioning.figures and in Sweep.sine
    # and Sweep.pivot: "group 2–3 (RPR)" (the lines' sine), "group 2–3 (RPR) pivot"
    head = ["index", *_place_cols(t, 0.0), "solved", "placed", "min_sine", *figure_labels(t)]
    if t.output_values is not None:  # s in m along the guide, or ψ in rad
        o = t.cycle.output
        head.append(f"output {o.point} ({'m' if o.kind == 'linear' else 'rad'})")
    for name in t.points:
        head += [f"{name}.{q}" for q in ("x", "y", "vx", "vy", "ax", "ay")]
    for i in t.links:
        head += [f"omega{i}", f"epsilon{i}"]
    head += ["warnings", "errors", "singular"]
    head += [f"gamma_deg {label}" for label in (t.gamma or {})]
    return head


def csv_chunks(t: CycleTable, rows: int = 1000):
    """The CSV text, ``rows`` rows at a time: each stretch of rows is converted to Python
    numbers as it is written, so that 10⁵ rows never stand in memory as some six million
    Python floats (about 200 MB for the press)."""
    m = t.motion
    n = len(t.status)
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(_csv_header(t))

    def f(x) -> str:
        x = float(x) + 0.0  # + 0.0: no −0.0
        return repr(x) if math.isfinite(x) else ""

    def column(arr):
        return np.broadcast_to(np.asarray(arr), (n,))

    # the columns as arrays (views, not copies), each with whether it is a coordinate,
    # given where the position stands but the plans do not
    arrays = []
    coordinate: list[bool] = []
    for name in t.points:
        for arr, shown in ((m.position[name], True), (m.velocity[name], False),
                           (m.acceleration[name], False)):
            z = column(arr)
            arrays += [z.real, z.imag]
            coordinate += [shown, shown]
    for i in t.links:
        arrays += [column(m.links[i].omega), column(m.links[i].epsilon)]
    coordinate += [False] * (len(arrays) - len(coordinate))  # ω and ε
    phi_all = column(m.phi)
    out_all = None if t.output_values is None else column(t.output_values)
    gam_all = [np.degrees(column(g)) for g in (t.gamma or {}).values()]
    blank = [""] * len(arrays)
    labels = figure_labels(t)
    for lo in range(0, n, rows):
        hi = min(lo + rows, n)
        # converted once a stretch (not cell by cell from numpy)
        cols = [a[lo:hi].tolist() for a in arrays]
        phis = phi_all[lo:hi].tolist()
        out = None if out_all is None else out_all[lo:hi].tolist()
        gams = [g[lo:hi].tolist() for g in gam_all]
        for j, st in enumerate(t.status[lo:hi]):
            good = st.ok
            row = [lo + j, *(f(x) for x in _place_cols(t, phis[j]).values()), int(good),
                   int(st.placed), f(st.min_sine)]
            row += [f(st.figures.get(x, math.nan)) for x in labels]
            if out is not None:
                row.append(f(out[j]) if st.placed else "")
            if good:
                row += [f(c[j]) for c in cols]
            elif st.placed:
                row += [f(c[j]) if shown else "" for c, shown in zip(cols, coordinate, strict=True)]
            else:
                row += blank
            row += ["; ".join(st.warnings), "; ".join(st.errors), "; ".join(st.singular)]
            row += [f(g[j]) for g in gams]
            w.writerow(row)
        yield buf.getvalue()
        buf.seek(0)
        buf.truncate()
    if not n:
        yield buf.getvalue()


def _table(title: str, head: list[str], rows: list[list[str]]) -> list[str]:
    widths = [max(len(h), *(len(r[i]) for r in rows)) for i, h in enumerate(head)]
    out = ["", title]
    out.append(
        "  " + "  ".join(h.rjust(wd) for h, wd in zip(head, widths, strict=True))
    )
    for r in rows:
        out.append(
            "  " + "  ".join(c.rjust(wd) for c, wd in zip(r, widths, strict=True))
        )
    return out


def to_text(t: CycleTable) -> str:
    m, mech, c = t.motion, t.mechanism, t.cycle
    d = mech.driver
    n = len(t.status)
    sense = "ccw" if d.omega > 0 else "cw"
    lines = [mech.name, ""]
    if c.kind == "turn":
        lines.append(
            f"{n} crank position{'s' if n != 1 else ''}, numbered {_numbering(t)}; "
            f"{d.omega_sym} = {num(abs(d.omega))} rad/s {sense}"
            + (f", ε{d.link} = {num(abs(d.epsilon))} rad/s² {'ccw' if d.epsilon > 0 else 'cw'} "
               "at every position (no law in time)" if d.epsilon else "")
        )
        lines.append(
            f"{d.phi_sym}: degrees from {d.reference}, measured {d.measured} (the file's convention)"
        )
    elif c.kind == "range":
        lines.append(f"{n} position{'s' if n != 1 else ''} of the input slider {d.link}, numbered "
                     f"{_numbering(t)}; {d.omega_sym} = {num(d.omega)} m/s, {d.epsilon_sym} = "
                     f"{num(d.epsilon)} m/s² at every position")
        lines.append(f"{d.phi_sym}: m along the guide {d.guide.label} from its point")
    else:
        lines.append(f"{n} instant{'s' if n != 1 else ''}, numbered {_numbering(t)}")
        lines.append("t: s; " + "; ".join(
            f"{dd.phi_sym}: m along {dd.guide.label}" if dd.linear else
            f"{dd.phi_sym}: degrees from {dd.reference}, measured {dd.measured}" for dd in mech.drivers))
    if c.output is not None and c.output.kind == "angular":
        lines.append(
            f"ψ_{c.output.point}: degrees of link {c.output.link} from +x, measured ccw"
        )

    lines += summary(c, d)
    lines += existence.lines(t.conditions)
    lines += transmission_lines(t.transmission, mech, [g.group for g in t.motion.groups], None, "en",
                                shown_from(c, d), c.output.point if c.output is not None else "")
    moving = [p for p in t.points if p not in mech.frame]
    fixed = [p for p in t.points if p in mech.frame]
    if fixed:
        lines.append(
            "fixed points: "
            + ", ".join(
                f"{p} ({num(mech.frame[p].real)}, {num(mech.frame[p].imag)}) m"
                for p in fixed
            )
        )

    lo = shown_from(c, d)  # a range through 0° writes its angles from −…°, as the range

    def lead(k: int) -> list[str]:
        x = float(m.phi[k])
        if c.kind == "time":
            return [str(k), num(x, 6), *(num(float(q), 6) if dd.linear else
                                         table_degrees(dd.file_angle(float(q)))
                                         for dd, (q, _, _) in zip(mech.drivers, mech.inputs_at(x),
                                                                  strict=True))]
        if c.kind == "range":
            return [str(k), num(x, 6)]
        return [str(k), table_degrees(d.file_angle(x), lo)]

    def cell(k: int, value, big: float = 0.0, position: bool = False) -> str:
        """A value of position k; rounding (below NOISE of its column's largest) is 0.
        ``position``: it stands where the position does, even if the plans are singular."""
        if not (t.status[k].placed if position else t.status[k].ok):
            return "—"
        value = float(value)
        return num(0.0 if abs(value) <= NOISE * big else value)

    ok = np.array([st.ok for st in t.status], dtype=bool)
    placed = np.array([st.placed for st in t.status], dtype=bool)

    def largest(values, rows=ok) -> float:
        """|value| largest over the positions solved (numpy: 10⁵ rows in Python took 3 s)."""
        got = np.abs(np.broadcast_to(np.asarray(values), rows.shape)[rows])
        return float(got.max()) if got.size else 0.0

    base = (["№", f"{mech.driver.phi_sym} °"] if c.kind == "turn" else
            ["№", f"{d.phi_sym} m"] if c.kind == "range" else
            ["№", "t s", *(f"{dd.phi_sym} {'m' if dd.linear else '°'}" for dd in mech.drivers)])
    # a coordinate is rounding against the largest distance from the origin: x of a crank
    # pin at 90° is R·cos(π/2) = 3e-18 m
    size = max((largest(m.position[p], placed) for p in moving), default=0.0)
    for title, key in (("x of points (m)", "x"), ("y of points (m)", "y")):
        rows = [
            lead(k)
            + [
                cell(
                    k,
                    getattr(
                        complex(m.position[p][k]), "real" if key == "x" else "imag"
                    ),
                    size,
                    position=True,
                )
                for p in moving
            ]
            for k in range(n)
        ]
        lines += _table(title, base + moving, rows)
    for title, store in (
        ("|V| of points (m/s)", m.velocity),
        ("|a| of points (m/s²)", m.acceleration),
    ):
        big = max((largest(store[p]) for p in moving), default=0.0)
        rows = [
            lead(k) + [cell(k, abs(complex(store[p][k])), big) for p in moving]
            for k in range(n)
        ]
        lines += _table(title, base + moving, rows)
    head = base + [f"ω{i}" for i in t.links] + [f"ε{i}" for i in t.links]
    big_w = max((largest(m.links[i].omega) for i in t.links), default=0.0)
    # ε against ω1² as well, as solve rounds it (plan._rates): a rod that only
    # translates has ε of 1e-13 at every position, the largest of its own column
    big_e = max((largest(m.links[i].epsilon) for i in t.links), default=0.0)
    big_e = max(big_e, d.omega * d.omega)
    rows = [
        lead(k)
        + [cell(k, m.links[i].omega[k], big_w) for i in t.links]
        + [cell(k, m.links[i].epsilon[k], big_e) for i in t.links]
        for k in range(n)
    ]
    lines += _table(
        "ω (rad/s) and ε (rad/s²) of links, counter-clockwise positive", head, rows
    )
    if t.gamma:
        rows = [lead(k) + [num(math.degrees(g[k])) if t.status[k].placed and math.isfinite(g[k])
                           else "—" for g in t.gamma.values()] for k in range(n)]
        lines += _table("Transmission angles γ (°) of the groups; the pressure angle α = 90° − γ",
                        base + [f"γ {label.split()[1]}" for label in t.gamma], rows)
    out_head = []
    if t.output_values is not None:
        unit = "m" if c.output.kind == "linear" else "°"
        out_head = [
            f"{'s' if c.output.kind == 'linear' else 'ψ'}_{c.output.point} {unit}"
        ]
    labels = figure_labels(t)
    head = base + out_head + ["min sin"] + [_short(x) for x in labels] + ["status"]
    rows = []
    big_out = 0.0 if not out_head else largest(t.output_values, placed)
    for k, st in enumerate(t.status):
        r = lead(k)
        if out_head:
            v = float(t.output_values[k])
            v = 0.0 if abs(v) <= NOISE * big_out else v  # s of 4.7e-15 m is rounding
            if c.output.kind != "linear":
                v = math.degrees(v)
            r.append(num(v) if st.placed else "—")
        r.append(_fig(st.min_sine))
        r += [_fig(st.figures.get(x, math.nan)) for x in labels]
        r.append(st.state)
        rows.append(r)
    lines += _table(
        "Conditioning (sine of the angle between the intersected lines)", head, rows
    )
    if any(is_pivot(x) for x in labels):
        lines.append("  QP: how far a slotted link's block P is from the rocker's pivot Q, "
                     "|QP| / (|OQ| + |OP|), O the crank's pivot")
    order = ("error", "singular", "warning")
    notes = [(k, kind, text) for k, st in enumerate(t.status)
             for kind, texts in zip(order, (st.errors, st.singular, st.warnings), strict=True)
             for text in texts]
    if notes:
        lines.append("")
        for k, kind, text in sorted(notes, key=lambda x: (x[0], order.index(x[1]))):
            lines.append(f"position {k}: {kind}: {text}")
        if any(st.singular for st in t.status):
            lines.append("singular: on or beside a change point, where a group's two "
                         "assemblies meet: the positions stand, the plans cannot be built")
    return "\n".join(lines) + "\n"


def table_degrees(deg: float, lo: float = 0.0) -> str:
    """A crank angle (degrees) for the table's φ1 column: two decimals, within the turn
    [lo, lo + 360) the rest of the output writes angles in (:func:`plans.fmt.angle`): an
    extreme position found 1.4e-12° short of a full turn is 0.00, not 360.00.

    >>> table_degrees(359.99999999999855), table_degrees(268.59, -180.0), table_degrees(-1e-9)
    ('0.00', '-91.41', '0.00')
    """
    x = in_turn(deg, lo) if lo else deg % 360.0
    s = f"{x:.2f}"
    if s == f"{lo + 360.0:.2f}":  # rounds up to the end of the turn: its start
        s = f"{lo:.2f}"
    return "0.00" if s == "-0.00" else s


def _short(label: str) -> str:
    """'group 2–3 (RPR)' → 'sin 2–3'; 'group 2–3 (RPR) pivot' → 'QP 2–3'."""
    parts = label.split()
    links = parts[1] if len(parts) > 1 else label
    return f"QP {links}" if is_pivot(label) else f"sin {links}"
