"""Reading the inputs of a mechanism file: ``[driver]`` (or ``[[drivers]]``, two inputs),
each driver's law in time (``[driver.law]``) and ``[motion]``, the instant and the
interval of a mechanism moved by laws in time.

A driver is a link hinged to the frame, a crank or a rocker, given by its angle, ω and
ε at the position analysed, or a slider on a fixed guide given by its travel along the
guide, its velocity and acceleration there; or either by a law in time
(:mod:`plans.model.laws`). Every problem is added to the file's
:class:`~plans.model.fileformat.Problems`, located, as the other parts are.
"""

from __future__ import annotations

import math
from dataclasses import replace
from typing import Any

from plans.model.fileformat import MAX_ABS, Problems, check_keys, name_list, quote, read_number
from plans.model.laws import KINDS, Law, Timing, common_period, table_law, uniform_period
from plans.model.mechanism import REFERENCES, SENSES, Driver, phi_of
from plans.model.parts import RPM_MIN, SPEED, link_id, link_ids, not_a_link

#: the keys of a crank's (or rocker's) [driver], and of a slider's
ROTARY_KEYS = {"link", "angle_deg", "from", "measured", "omega", "rpm", "sense", "epsilon",
               "epsilon_sense", "law"}
LINEAR_KEYS = {"link", "position", "velocity", "acceleration", "law"}
#: the keys that place a driver at the position analysed: a law of its own (harmonic, a
#: table) places it instead
PLACING = {"angle_deg", "omega", "rpm", "sense", "epsilon", "epsilon_sense", "position",
           "velocity", "acceleration"}
#: rows of a law's table
MAX_TABLE = 500
#: s: the longest time a file may name
MAX_TIME = 1e6


def read_drivers(data: dict, pr: Problems, links, frame, bad_links, frame_names, sliders,
                 sliding) -> tuple[tuple[Driver, ...], Timing | None]:
    """The mechanism's drivers, ``[driver]`` or ``[[drivers]]`` (one or two), placed at the
    instant of ``[motion]`` where they move by laws in time, and that motion (None: the
    mechanism is placed by its driver's position). No drivers where one cannot be read
    (the problem is said)."""
    if "drivers" in data:
        if "driver" in data:
            pr.add("drivers", "give [driver] or [[drivers]], not both")
            return (), None
        raw = data["drivers"]
        if not isinstance(raw, list) or not 1 <= len(raw) <= 2:
            pr.add("drivers", "must be one or two tables, [[drivers]] link = …: a mechanism here "
                              f"has one or two inputs, got {quote(raw)}")
            return (), None
        where = [f"drivers[{i}]" for i in range(len(raw))]
    else:
        raw, where = [data.get("driver")], ["driver"]
    got = [read_driver(body, pr, links, frame, bad_links, frame_names, sliders, sliding, at)
           for body, at in zip(raw, where, strict=True)]
    if any(d is None for d in got):
        return (), None
    if len(got) == 2 and got[0].link == got[1].link:
        pr.add(f"{where[1]}.link", f"link {got[1].link} is {where[0]} already: two inputs are two links")
        return (), None
    motion = read_motion(data.get("motion"), pr, got)
    if motion is None:
        return tuple(got), None
    timing, laws = motion
    return tuple(place(d, timing.time, law) for d, law in zip(got, laws, strict=True)), timing


def read_driver(body, pr: Problems, links, frame, bad_links, frame_names, sliders=(),
                sliding=frozenset(), where: str = "driver") -> Driver | None:
    """One driver: a crank (or rocker) hinged to the frame, or a slider on a fixed guide;
    ``frame_names``: the names in [frame] (None: no [frame] at all); ``sliders``: the
    file's sliders read, ``sliding``: the links of every [[sliders]] entry."""
    if not isinstance(body, dict):
        got = "missing" if body is None else f"must be a table, got {quote(body)}"
        pr.add(where, f"{got}: [driver] with link, angle_deg, and omega (rad/s) or rpm")
        return None
    raw = body.get("link", 1)
    lid = link_id(raw)
    if lid is None or lid not in links:
        check_keys(body, ROTARY_KEYS, where, pr)
        if lid not in bad_links and (links or lid is None):
            pr.add(where + ".link", not_a_link(raw, "a moving link", f"moving links: {link_ids(links)}"))
        return None
    link = links[lid]
    slider = next((s for s in sliders if s.link == lid), None)
    if slider is not None and slider.guide.link == 0 and not any(n in frame for n in link.points):
        return _linear(body, pr, lid, slider, link, where)
    check_keys(body, ROTARY_KEYS, where, pr)
    if link.axis is None:
        if lid not in bad_links and lid not in sliding:
            pr.add(f"links.{lid}.axis", f'missing: the crank (link {lid}) needs an axis from its fixed pivot '
                                        'to its pin, e.g. ["O", "A"]')
        return None
    pivot, tip = link.axis
    if frame_names is None or (pivot in frame_names and pivot not in frame):
        pass  # [frame] missing, or the pivot's coordinates are wrong: said already
    elif pivot not in frame:
        swapped = (f' (the axis runs from the fixed pivot to the pin: ["{tip}", "{pivot}"]?)'
                   if tip in frame else "")
        moving = (f"; or, to drive it along a fixed guide, a [[sliders]] entry for link {lid}"
                  if link.axis else "")
        pr.add(
            f"links.{lid}.axis[0]",
            f'the crank turns about "{pivot}", which is not a fixed point in [frame] '
            f"(fixed points: {name_list(frame)}): the driver must be attached to the frame{swapped}"
            + ("" if swapped or where == "driver" else moving),
        )
    else:
        also = sorted(n for n in link.points if n in frame and n != pivot)
        if also:
            pr.add(
                f"links.{lid}.points.{also[0]}",
                f'the crank is hinged to the frame at "{pivot}" and at "{also[0]}": it could '
                "not turn; a crank has one fixed pivot",
            )
    ref = body.get("from", "+x")
    if not isinstance(ref, str) or ref not in REFERENCES:
        pr.add(where + ".from", f'{quote(ref, 20)} is not a reference: one of "+x", "+y", "-x", "-y"')
        ref = "+x"
    measured = body.get("measured", "ccw")
    if not isinstance(measured, str) or measured not in SENSES:
        pr.add(where + ".measured", f'{quote(measured, 20)}: must be "ccw" (counter-clockwise) or "cw" '
                                    '(clockwise)')
        measured = "ccw"
    law_body = body.get("law")
    by_law = isinstance(law_body, dict) and law_body.get("kind") in ("harmonic", "table")
    if by_law:  # the law places it: its own angle, ω and ε are the law's
        _placed_twice(body, where, pr)
        law = read_law(law_body, where + ".law", pr, False, ref, measured)
        if law is None or tip not in link.points:
            return None
        q, w, e = law.at(0.0)
        return Driver(lid, pivot, tip, link.points[tip].real, q, w, 0.0, ref, measured, None, e,
                      law=law, origin=frame.get(pivot, 0j))
    angle = read_number(body.get("angle_deg"), where + ".angle_deg", pr, unit="°")
    sense = body.get("sense", "ccw")
    if not isinstance(sense, str) or sense not in SENSES:
        pr.add(where + ".sense", f'{quote(sense, 20)}: must be "ccw" (counter-clockwise) or "cw" (clockwise)')
        sense = "ccw"
    rpm = None
    if "omega" in body and "rpm" in body:
        pr.add(where, "give omega (rad/s) or rpm, not both")
        return None
    if "rpm" in body:
        rpm = read_number(body["rpm"], where + ".rpm", pr, positive=True, unit="rpm",
                          low=RPM_MIN, high=SPEED[1])
        omega = None if rpm is None else math.pi * rpm / 30.0
    elif "omega" in body:
        omega = read_number(body["omega"], where + ".omega", pr, positive=True, unit="rad/s",
                            low=SPEED[0], high=SPEED[1])
    else:
        pr.add(where + ".omega", "missing: the crank speed, omega in rad/s or rpm")
        omega = None
    epsilon = _epsilon(body, where, pr, sense)
    law = None
    if law_body is not None:
        law = read_law(law_body, where + ".law", pr, False, ref, measured)
    if angle is None or omega is None or epsilon is None or tip not in link.points:
        return None
    phi = phi_of(angle, ref, measured)
    w = SENSES[sense] * omega
    if law is not None:
        law = _through(law, phi, w, epsilon, where, pr)
        if law is None:
            return None
    return Driver(
        link=lid,
        pivot=pivot,
        tip=tip,
        length=link.points[tip].real,
        phi=phi,
        omega=w,
        angle_deg=angle,
        reference=ref,
        measured=measured,
        rpm=rpm,
        epsilon=epsilon,
        law=law,
        origin=frame.get(pivot, 0j),
    )


def _epsilon(body, where: str, pr: Problems, sense: str) -> float | None:
    """ε of a crank (rad/s², counter-clockwise positive): ``epsilon`` in the sense of
    ``epsilon_sense``, by default the sense of ω (so that a positive ε speeds it up)."""
    if "epsilon_sense" in body and "epsilon" not in body:
        pr.add(where + ".epsilon_sense", "goes with epsilon (rad/s²): give both, or neither")
        return None
    esense = body.get("epsilon_sense", sense)
    if not isinstance(esense, str) or esense not in SENSES:
        pr.add(where + ".epsilon_sense", f'{quote(esense, 20)}: must be "ccw" (counter-clockwise) or '
                                         '"cw" (clockwise)')
        return None
    if "epsilon" not in body:
        return 0.0
    eps = read_number(body["epsilon"], where + ".epsilon", pr, unit="rad/s²", high=MAX_ABS)
    return None if eps is None else SENSES[esense] * eps + 0.0


def _linear(body, pr: Problems, lid: int, slider, link, where: str) -> Driver | None:
    """A slider on a fixed guide as the input: its travel along the guide from the
    guide's point (position, m), its velocity and acceleration along it."""
    guide = slider.guide
    for key in sorted(set(body) & (ROTARY_KEYS - LINEAR_KEYS)):
        pr.add(f"{where}.{key}", f"link {lid} slides on the fixed guide {guide.label}: it is driven by "
                                 "its travel along the guide, position (m), velocity (m/s) and "
                                 "acceleration (m/s²), not by an angle or a speed of turning")
    check_keys({k: v for k, v in body.items() if k not in ROTARY_KEYS}, LINEAR_KEYS, where, pr)
    common = {"link": lid, "pivot": "", "tip": slider.point, "length": 1.0, "reference": "+x",
              "measured": "ccw", "kind": "linear", "guide": guide, "origin": guide.point,
              "local": link.points[slider.point]}
    law_body = body.get("law")
    if isinstance(law_body, dict) and law_body.get("kind") in ("harmonic", "table"):
        _placed_twice(body, where, pr)
        law = read_law(law_body, where + ".law", pr, True)
        if law is None:
            return None
        q, v, a = law.at(0.0)
        return Driver(phi=q, omega=v, angle_deg=q, epsilon=a, law=law, **common)
    s = read_number(body.get("position"), where + ".position", pr)
    v = read_number(body.get("velocity"), where + ".velocity", pr, unit="m/s")
    a = read_number(body.get("acceleration", 0.0), where + ".acceleration", pr, unit="m/s²")
    if v is not None and v == 0 and law_body is None:
        pr.add(where + ".velocity", "0: the input slider stands still, and so does every link; give its "
                                    "velocity along the guide (m/s, negative against the guide's "
                                    "direction)")
        v = None
    law = None if law_body is None else read_law(law_body, where + ".law", pr, True)
    if s is None or v is None or a is None or (law_body is not None and law is None):
        return None
    if law is not None:
        law = _through(law, s, v, a, where, pr)
        if law is None:
            return None
    return Driver(phi=s, omega=v, angle_deg=s, epsilon=a, law=law, **common)


def _placed_twice(body, where: str, pr: Problems) -> None:
    for key in sorted(set(body) & PLACING):
        pr.add(f"{where}.{key}", f"the driver's law ({where}.law) gives its position, velocity and "
                                 f"acceleration at every instant: leave out {key}")


def _through(law: Law, q: float, rate: float, accel: float, where: str, pr: Problems) -> Law | None:
    """A uniform or uniformly accelerated law through the driver's values at t = 0."""
    if law.kind == "uniform":
        if accel != 0:
            pr.add(where + ".law.kind", '"uniform" with an acceleration: a uniform law has none; '
                                        'write kind = "accelerated"')
            return None
        return replace(law, q0=q, rate=rate)
    return replace(law, q0=q, rate=rate, accel=accel)


def read_law(body: Any, where: str, pr: Problems, linear: bool, ref: str = "+x",
             measured: str = "ccw") -> Law | None:
    """A driver's law in time (:mod:`plans.model.laws`); a rotating driver's angles in the
    file's convention (degrees from ``ref``, ``measured`` ccw or cw)."""
    if not isinstance(body, dict):
        pr.add(where, f'must be a table, e.g. {{ kind = "harmonic", … }}, got {quote(body)}')
        return None
    kind = body.get("kind")
    if kind not in KINDS:
        pr.add(where + ".kind", f'{quote(kind, 20)}: one of "uniform", "accelerated", "harmonic", "table"')
        return None
    sign = SENSES[measured]
    deg = "" if linear else "_deg"
    unit, rate_unit, acc_unit = ("m", "m/s", "m/s²") if linear else ("°", "rad/s", "rad/s²")
    if kind in ("uniform", "accelerated"):
        check_keys(body, {"kind"}, where, pr)
        return Law(kind)
    if kind == "harmonic":
        keys = {"kind", f"mean{deg}", f"amplitude{deg}", "omega", "period", "phase_deg"}
        check_keys(body, keys, where, pr)
        mean = read_number(body.get(f"mean{deg}"), f"{where}.mean{deg}", pr, unit=unit)
        amp = read_number(body.get(f"amplitude{deg}"), f"{where}.amplitude{deg}", pr, unit=unit)
        phase = read_number(body.get("phase_deg", 0.0), f"{where}.phase_deg", pr, unit="°")
        if "omega" in body and "period" in body:
            pr.add(where, "give omega (rad/s) or period (s), not both")
            return None
        if "period" in body:
            period = read_number(body["period"], where + ".period", pr, positive=True, unit="s",
                                 low=1e-9, high=MAX_TIME)
            omega = None if period is None else 2 * math.pi / period
        else:
            omega = read_number(body.get("omega"), where + ".omega", pr, positive=True, unit="rad/s",
                                low=SPEED[0], high=SPEED[1])
        if None in (mean, amp, phase, omega):
            return None
        if linear:
            return Law("harmonic", mean=mean, amplitude=amp, omega=omega, phase=math.radians(phase))
        return Law("harmonic", mean=phi_of(mean, ref, measured), amplitude=sign * math.radians(amp),
                   omega=omega, phase=math.radians(phase))
    # a table
    qkey, dkey, ddkey = ("position", "velocity", "acceleration") if linear else ("angle_deg", "omega",
                                                                               "epsilon")
    check_keys(body, {"kind", "t", qkey, dkey, ddkey}, where, pr)
    if ddkey in body and dkey not in body:
        pr.add(f"{where}.{ddkey}", f"goes with {dkey}: the table's second derivatives need its first")
        return None
    cols = {}
    for key, u in (("t", "s"), (qkey, unit), (dkey, rate_unit), (ddkey, acc_unit)):
        if key not in body and key in (dkey, ddkey):
            continue
        col = body.get(key)
        if not isinstance(col, list) or not 2 <= len(col) <= MAX_TABLE:
            got = ("missing" if col is None else
                   f"must be a list of 2 to {MAX_TABLE} numbers, got {quote(col)}")
            pr.add(f"{where}.{key}", f"{got}: the table's {'instants (s)' if key == 't' else key}"
                   if col is None else got)
            return None
        vals = [read_number(x, f"{where}.{key}[{i}]", pr, unit=u,
                            high=MAX_TIME if key == "t" else MAX_ABS) for i, x in enumerate(col)]
        if None in vals:
            return None
        cols[key] = vals
    n = len(cols["t"])
    for key, col in cols.items():
        if len(col) != n:
            pr.add(f"{where}.{key}", f"{len(col)} values for {n} instants t: one a row")
            return None
    t = cols["t"]
    for i in range(1, n):
        if not t[i] > t[i - 1]:
            pr.add(f"{where}.t[{i}]", f"{t[i]:g} s after {t[i - 1]:g} s: the instants must rise")
            return None
    if linear:
        return table_law(t, cols[qkey], cols.get(dkey), cols.get(ddkey))
    q = [phi_of(a, ref, measured) for a in cols[qkey]]
    dq = None if dkey not in cols else [sign * w for w in cols[dkey]]
    ddq = None if ddkey not in cols else [sign * e for e in cols[ddkey]]
    ends = (q[-1] - q[0]) / (2 * math.pi)
    turn = 2 * math.pi * round(ends) if abs(ends - round(ends)) < 1e-9 and round(ends) else 0.0
    return table_law(t, q, dq, ddq, turn)


def read_motion(body, pr: Problems, drivers: list[Driver]) -> tuple[Timing, list[Law]] | None:
    """``[motion]``: the instant the plans are built for (``time``, s, default 0) and the
    interval the cycle is swept over (``span``, default one common period of the drivers'
    laws from t = 0), with each driver's law (a driver given at the position has the
    uniform or uniformly accelerated law through it at t = 0). Where there is one driver,
    placed at the position analysed, there is no motion in time: None (``[motion]`` is
    refused then), as where a problem is said."""
    timed = len(drivers) > 1 or any(d.law is not None for d in drivers)
    if not timed:
        if body is not None:
            pr.add("motion", "is for drivers moved by laws in time (a [driver.law], or two drivers); "
                             "this driver is placed at the position analysed")
        return None
    body = {} if body is None else body
    if not isinstance(body, dict):
        pr.add("motion", f"must be a table: [motion] time = 0.05, span = [0, 0.6], got {quote(body)}")
        return None
    check_keys(body, {"time", "span"}, "motion", pr)
    time = read_number(body.get("time", 0.0), "motion.time", pr, unit="s", high=MAX_TIME)
    laws = [d.law or Law("uniform" if d.epsilon == 0 else "accelerated", d.phi, d.omega, d.epsilon)
            for d in drivers]
    if "span" in body:
        span = body["span"]
        if not (isinstance(span, list) and len(span) == 2):
            pr.add("motion.span", f"must be [t0, t1] in s, got {quote(span)}")
            return None
        a = read_number(span[0], "motion.span[0]", pr, unit="s", high=MAX_TIME)
        b = read_number(span[1], "motion.span[1]", pr, unit="s", high=MAX_TIME)
        if a is None or b is None:
            return None
        if not b > a:
            pr.add("motion.span", f"[{a:g}, {b:g}]: the interval's end must come after its start")
            return None
        span = (a, b)
    else:
        periods = []
        for d, law in zip(drivers, laws, strict=True):
            p = law.period
            if p is None and law.kind == "uniform" and not d.linear:
                p = uniform_period(law.rate)
            periods.append(p)
        if None in periods:
            which = ", ".join(f"link {d.link}" for d, p in zip(drivers, periods, strict=True) if p is None)
            pr.add("motion.span", f"missing: the law of {which} repeats at no period, so the cycle's "
                                  "interval is to be given: span = [t0, t1] in s")
            return None
        period = common_period(periods)
        if period is None:
            pr.add("motion.span", "missing: the drivers' periods ("
                   + ", ".join(f"{p:.6g} s" for p in periods)
                   + ") have no common period; give the cycle's interval: span = [t0, t1] in s")
            return None
        span = (0.0, period)
    if time is None:
        return None
    return Timing(time, span), laws


def place(driver: Driver, time: float, law: Law | None = None) -> Driver:
    """``driver`` at the instant ``time`` of its law (``law``: its own, else ``driver.law``)."""
    law = law or driver.law
    q, w, e = (float(x) for x in law.at(time))
    angle = driver.file_angle(q)
    return replace(driver, phi=q, omega=w, epsilon=e + 0.0, angle_deg=angle, law=law)
