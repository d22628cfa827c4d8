"""The drive (seed 001, steps 8–9): the power on the crank, the motor from a catalogue, and
the gearbox's ratio split into stages with its tooth numbers.

    P = F_у·V_B = M_у·ω1;  P_motor ≥ P / η;  u = n_motor / n1
    one stage for u ≤ 6.3, two for u ≤ 33 with u12 = 1.2·u34 (u = u12·u34)
    z1 = z3 = 20 + Ш;  z2 = u12·z1, z4 = u34·z3 rounded;  n1' = n_motor / (z2/z1 · z4/z3)

The workbook does this arithmetic by hand with every ratio to two decimals; so does
:func:`gearbox` by default (``classroom=True``), which reproduces its worked example
(u = 19.10, u34 = 3.99, u12 = 4.79, z = 22/105 and 22/88, n1 = 149.37 rpm, +0.1 %).
"""

from __future__ import annotations

import math
import tomllib
from importlib import resources
from pathlib import Path
from typing import NamedTuple

from plans.errors import InputError
from plans.model.fileformat import Problems, check_keys, read_number, read_text, read_toml

#: the largest ratio of one stage and of two stages (the workbook's limits)
ONE_STAGE = 6.3
TWO_STAGES = 33.0
#: u12 = SPLIT·u34: the first stage's ratio 20 % above the second's
SPLIT = 1.2
#: the tooth number of a pinion is BASE_TEETH + Ш
BASE_TEETH = 20


class Motor(NamedTuple):
    type: str
    power_kw: float
    rpm: float  # rated (full-load) speed
    synchronous: int


class Gearbox(NamedTuple):
    u: float  # required: n_motor / n1
    stages: int
    u12: float
    u34: float | None
    z1: int
    z2: int
    z3: int | None
    z4: int | None
    u_actual: float
    n1_actual: float  # rpm
    deviation: float  # % of n1


class DriveResult(NamedTuple):
    power: float  # W on the crank
    efficiency: float
    needed: float  # W: power / η
    motor: Motor
    n1: float  # rpm of the crank
    gearbox: Gearbox


def read_catalogue(path: str | Path | None = None) -> tuple[Motor, ...]:
    """The motors of ``path`` (TOML, ``[[motor]] type, power_kw, rpm, synchronous``), or of
    the built-in 4A catalogue."""
    if path is None:
        text = resources.files("plans").joinpath("data/motors_4a.toml").read_text("utf-8")
        data, source = tomllib.loads(text), "motors_4a.toml"
    else:
        data, text = read_toml(path)
        source = str(path)
    pr = Problems(source, text)
    rows = data.get("motor") if isinstance(data, dict) else None
    if not isinstance(rows, list) or not rows:
        raise InputError(
            source,
            "motor: missing: a catalogue lists its motors as [[motor]] type = …, "
            "power_kw = …, rpm = …, synchronous = …",
        )
    out = []
    for i, row in enumerate(rows):
        at = f"motor[{i}]"
        if not isinstance(row, dict):
            pr.add(at, "must be a table: type, power_kw, rpm, synchronous")
            continue
        check_keys(row, {"type", "power_kw", "rpm", "synchronous"}, at, pr)
        kind = read_text(row.get("type"), f"{at}.type", pr, "")
        if not kind:
            pr.add(f"{at}.type", 'missing: the motor\'s type, e.g. "4А80В2У3"')
        kw = read_number(row.get("power_kw"), f"{at}.power_kw", pr, positive=True, unit="kW", high=1e5)
        rpm = read_number(row.get("rpm"), f"{at}.rpm", pr, positive=True, unit="rpm", high=1e5)
        sync = read_number(
            row.get("synchronous"), f"{at}.synchronous", pr, positive=True, unit="rpm", high=1e5
        )
        if kind and kw and rpm and sync:
            out.append(Motor(kind, kw, rpm, int(sync)))
    pr.raise_if_any()
    return tuple(out)


def choose_motor(needed: float, catalogue, synchronous: int = 3000, source: str = "") -> Motor:
    """The catalogue's smallest motor of ``synchronous`` rpm whose power is at least
    ``needed`` (W)."""
    fit = sorted((m for m in catalogue if m.synchronous == synchronous), key=lambda m: m.power_kw)
    if not fit:
        speeds = sorted({m.synchronous for m in catalogue})
        raise InputError(
            source,
            f"drive.synchronous: the catalogue has no motor of {synchronous} rpm "
            f"(it has {', '.join(map(str, speeds))})",
        )
    for m in fit:
        if m.power_kw * 1000 >= needed:
            return m
    raise InputError(
        source,
        f"the drive needs {needed / 1000:.3g} kW: the catalogue's largest motor of "
        f"{synchronous} rpm is {fit[-1].type}, {fit[-1].power_kw:g} kW",
    )


def _r2(x: float, classroom: bool) -> float:
    return round(x + 0.0, 2) if classroom else x


def gearbox(n_motor: float, n1: float, digit: int = 0, classroom: bool = True, source: str = "") -> Gearbox:
    """The gearbox from the motor's speed to the crank's (rpm); ``digit``: Ш;
    ``classroom``: every ratio to two decimals, as the workbook writes them."""
    u = _r2(n_motor / n1, classroom)
    z1 = BASE_TEETH + digit
    if u < 1:
        raise InputError(
            source,
            f"the motor turns slower ({n_motor:g} rpm) than the crank ({n1:.6g} rpm): "
            "a gearbox that reduces speed cannot drive it",
        )
    if u <= ONE_STAGE:
        z2 = _teeth(u * z1)
        ua = _r2(z2 / z1, classroom)
        n1a = _r2(n_motor / ua, classroom)
        return Gearbox(u, 1, u, None, z1, z2, None, None, ua, n1a, _dev(n1a, n1, classroom))
    if u > TWO_STAGES:
        raise InputError(
            source,
            f"u = {u:g} is beyond a two-stage gearbox (at most {TWO_STAGES:g}): "
            "choose a slower motor ([drive] synchronous = 1500, 1000 or 750)",
        )
    u34 = _r2(math.sqrt(u / SPLIT), classroom)
    u12 = _r2(SPLIT * u34, classroom)
    z2, z4 = _teeth(u12 * z1), _teeth(u34 * z1)
    u12a, u34a = _r2(z2 / z1, classroom), _r2(z4 / z1, classroom)
    ua = _r2(u12a * u34a, classroom)
    n1a = _r2(n_motor / ua, classroom)
    return Gearbox(u, 2, u12, u34, z1, z2, z1, z4, ua, n1a, _dev(n1a, n1, classroom))


def _teeth(x: float) -> int:
    """The nearest whole number of teeth (a half rounded up, as by hand)."""
    return math.floor(x + 0.5)


def _dev(n1a: float, n1: float, classroom: bool) -> float:
    d = (n1a - n1) / n1 * 100
    return round(d, 1) if classroom else d


def drive(
    power: float,
    n1: float,
    efficiency: float = 0.9,
    digit: int = 0,
    synchronous: int = 3000,
    catalogue=None,
    classroom: bool = True,
    source: str = "",
) -> DriveResult:
    """The motor and the gearbox for ``power`` (W) on a crank turning at ``n1`` rpm."""
    if not power > 0:
        raise InputError(
            source,
            f"the crank takes no power here (P = M_у·ω1 = {power:.4g} W): a motor is "
            "chosen for a position where the drive does work, or for the cycle's mean power",
        )
    catalogue = catalogue if catalogue is not None else read_catalogue()
    needed = power / efficiency
    motor = choose_motor(needed, catalogue, synchronous, source)
    return DriveResult(power, efficiency, needed, motor, n1, gearbox(motor.rpm, n1, digit, classroom, source))
