"""The declarative description of a mechanism: its links, pairs and driver, as values.

A mechanism is the frame (link 0) with its fixed pivots, numbered moving links, each with
its named points in the link's own coordinates, the prismatic pairs (sliders and the
guides they move along), and the driver (the crank). Revolute pairs are implied: a point
named on two links (or on a link and the frame) is a hinge joining them.

A link's own coordinates: the origin at ``axis[0]`` and the x-axis towards ``axis[1]``; a
point is given by its distance along that axis, or ``[along, across]`` (across positive to
the left of the axis). A link without an axis slides on a guide: its origin is its point
on the guide and its x-axis runs along the guide. A link with an axis that slides on a
guide has its axis along the guide too (a Scotch yoke's).

Lengths are metres, angles degrees in the file and radians inside, time seconds. The
file is read by :mod:`plans.model.load`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace

from plans.fmt import angle, num
from plans.model.laws import Law, Timing
from plans.model.loads import Drive, Loads
from plans.model.words import WORDS

#: the unit of each scale factor, as an error message asks for it
MU_UNIT = {"mu_l": "m/mm", "mu_v": "(m/s)/mm", "mu_a": "(m/s²)/mm"}
#: a crank angle's reference (degrees from +x) and sense of measuring, as a file names them
REFERENCES = {"+x": 0.0, "+y": 90.0, "-x": 180.0, "-y": 270.0}
SENSES = {"ccw": 1.0, "cw": -1.0}


@dataclass(frozen=True, slots=True)
class Guide:
    """A straight guide carried by a link: a line through ``point`` along ``direction``.

    Both are in the carrying link's own coordinates (world coordinates for the frame).
    """

    link: int
    point: complex
    direction: complex  # unit
    label: str
    named_by_tool: bool = False  # the file gave no label: x-x, DA, x3-x3 … by notation

    @property
    def along(self) -> str:
        """The guide's direction as a plan's line is described: "∥ x-x", "∥ DE", or
        "⊥ DE" for a slot across the axis of the link that carries it."""
        return self.label if self.label.startswith("⊥") else f"∥ {self.label}"


@dataclass(frozen=True, slots=True)
class Link:
    id: int
    name: str
    points: dict[str, complex]  # own coordinates of every point of the link
    axis: tuple[str, str] | None = None


@dataclass(frozen=True, slots=True)
class Slider:
    """A prismatic pair: ``link`` moves along ``guide``; ``point`` of it lies on the guide."""

    link: int
    guide: Guide
    point: str


@dataclass(frozen=True, slots=True)
class Driver:
    """An input link. The crank (``kind`` "rotary", a link hinged to the frame, a crank or
    a rocker): link ``link`` turning about the fixed ``pivot``; ``tip`` is its pin, ``phi``
    its angle, ``omega`` and ``epsilon`` its ω and ε. A slider on a fixed guide (``kind``
    "linear"): ``tip`` its point on the ``guide``, ``phi`` its travel s along the guide
    from the guide's point (m, positive along the guide's direction), ``omega`` and
    ``epsilon`` its velocity and acceleration along it (m/s, m/s²). ``law``: its law in
    time, where the file gives one (:mod:`plans.model.laws`)."""

    link: int
    pivot: str
    tip: str
    length: float
    phi: float  # rad, counter-clockwise from +x (a slider: m along its guide)
    omega: float  # rad/s, signed: positive counter-clockwise (a slider: m/s)
    angle_deg: float  # as given in the file
    reference: str  # "+x", "+y", ...
    measured: str  # "ccw" or "cw"
    rpm: float | None = None
    #: rad/s², signed: positive counter-clockwise (a slider: m/s² along its guide)
    epsilon: float = 0.0
    kind: str = "rotary"
    guide: Guide | None = None
    law: Law | None = None
    #: where the input is: a crank's pivot, a slider's guide point (world, m)
    origin: complex = 0j
    #: a slider's point on its guide in the slider's own coordinates
    local: complex = 0j

    @property
    def linear(self) -> bool:
        return self.kind == "linear"

    @property
    def phi_sym(self) -> str:
        """"φ1": the crank's angle named by its link's number, as its ω is ("ω1", the
        course's numbering; "φ3" for a crank numbered 3, whose text then never calls
        another link's ω "ω1" beside it); "s4" for a slider's travel."""
        return f"s{self.link}" if self.linear else f"φ{self.link}"

    @property
    def omega_sym(self) -> str:
        """"ω1": the crank's angular velocity, named by its link's number; a slider's
        velocity V_D by its point."""
        return f"V_{self.tip}" if self.linear else f"ω{self.link}"

    @property
    def epsilon_sym(self) -> str:
        """"ε1": the crank's angular acceleration; a slider's acceleration a_D."""
        return f"a_{self.tip}" if self.linear else f"ε{self.link}"

    def phi_of(self, angle_deg: float) -> float:
        """The crank angle (rad, counter-clockwise from +x) of an angle given in the
        file's convention (degrees from ``reference``, ``measured`` ccw or cw); a slider's
        travel as it is."""
        if self.linear:
            return angle_deg
        return phi_of(angle_deg, self.reference, self.measured)

    def file_angle(self, phi: float) -> float:
        """The inverse: the crank angle ``phi`` in the file's convention, in [0, 360); a
        slider's travel as it is."""
        if self.linear:
            return phi
        return (SENSES[self.measured] * (math.degrees(phi) - REFERENCES[self.reference])) % 360.0

    def at(self, phi: float, lang: str = "en", lo: float = 0.0) -> str:
        """"φ1 = 330°" for a message about crank angle ``phi``, in the file's convention as
        ``--angle`` takes it, which it names unless it is the usual one (from +x, ccw);
        ``lo``, the turn it is written in (:func:`plans.fmt.angle`: "−99.7°" beside a crank
        range through 0°).

        >>> d = Driver(1, "O", "A", 0.1, math.radians(-240), 1.0, 330.0, "+y", "cw")
        >>> d.at(math.radians(-240)), d.at(math.radians(-240.5), "ru")
        ('φ1 = 330° (from +y, cw)', 'φ1 = 330,5° (от +y, по часовой стрелке)')
        """
        if self.linear:
            return f"{self.phi_sym} = {num(phi, 6, lang)} {WORDS[lang]['m']}"
        return f"{self.phi_sym} = {angle(self.file_angle(phi), 6, lang, lo)}°{self.convention(lang)}"

    def both(self, phi: float, lang: str = "en", lo: float = 0.0) -> str:
        """"60° from +x (30° from +y, cw, as the file gives it)": the crank angle ``phi``
        from +x, and in the file's own convention where that is another one, to six
        digits (the angle as the user typed it: 270.01° had printed as 270°). ``lo``:
        the turn the file's angles are written in (:func:`plans.cycle.shown_from`, "−99.7°"
        beside a crank range through 0°); the angle from +x takes it too where it is the
        file's own.

        >>> d = Driver(1, "O", "A", 0.1, math.radians(60), 1.0, 30.0, "+y", "cw")
        >>> d.both(math.radians(60))
        '60° from +x (30° from +y, cw, as the file gives it)'
        >>> d.both(math.radians(60), "ru")
        '60° от +x (30° от +y, по часовой стрелке, как задано в файле)'
        >>> replace(d, reference="+x", measured="ccw").both(math.radians(60))
        '60° from +x'
        """
        words = WORDS[lang]
        if self.linear:
            return f"{num(phi, 6, lang)} {words['m']} {words['along']} {self.guide.label}"
        conv = self.convention(lang)[2:-1]  # "from +y, cw" without its brackets
        own = (f" ({angle(self.file_angle(phi), 6, lang, lo)}° {conv}, {words['as_given']})"
               if conv else "")
        at = angle(math.degrees(phi), 6, lang, 0.0 if conv else lo)
        return f"{at}° {words['from']} +x{own}"

    def convention(self, lang: str = "en") -> str:
        """" (from +y, cw)" after an angle in the file's convention; nothing for the usual
        one (from +x, counter-clockwise)."""
        if (self.reference, self.measured) == ("+x", "ccw") or self.linear:
            return ""
        words = WORDS[lang]
        return f" ({words['from']} {self.reference}, {words['measured'][self.measured]})"


def phi_of(angle_deg: float, reference: str, measured: str) -> float:
    """A crank angle in a file's convention (degrees from ``reference``, ``measured`` ccw
    or cw) as the engine's: radians counter-clockwise from +x."""
    return math.radians(REFERENCES[reference] + SENSES[measured] * angle_deg)


@dataclass(frozen=True)
class Mechanism:
    name: str
    frame: dict[str, complex]
    links: dict[int, Link]
    sliders: tuple[Slider, ...]
    driver: Driver
    assembly: dict[str, str] = field(default_factory=dict)
    scales: dict[str, float] = field(default_factory=dict)
    trace: tuple[str, ...] = ()
    output: str | None = None
    title: dict[str, str] = field(default_factory=dict)
    source: str = "<mechanism>"
    #: the name in other languages ("ru": …), from ``name = { en = "…", ru = "…" }``
    names: dict[str, str] = field(default_factory=dict)
    #: ``source`` in other languages, where it has words ("ru": "таблица 2 (встроенная),
    #: вариант 3" for a row of the built-in table); a file's path has none
    sources: dict[str, str] = field(default_factory=dict)
    #: the crank angle (rad from +x) the assembly hints are read at: the file's own, kept
    #: by :meth:`at_file_angle`; None: the driver's
    hints_at: float | None = None
    #: the loads for the force analysis (``[loads]``), None where the file gives none
    loads: Loads | None = None
    #: the drive's data (``[drive]``)
    drive: Drive | None = None
    #: the inputs after the first (``[[drivers]]``): a mechanism of two degrees of freedom
    more_drivers: tuple[Driver, ...] = ()
    #: where the drivers move by laws in time: the instant of the plans and the cycle's
    #: interval (``[motion]``); None where the cycle runs over the crank's angle
    timing: Timing | None = None

    @property
    def drivers(self) -> tuple[Driver, ...]:
        """Every input, the first (``driver``) first."""
        return (self.driver, *self.more_drivers)

    @property
    def timed(self) -> bool:
        """Whether the mechanism is placed by time (its drivers' laws), not by the crank's
        angle: its solver then takes instants (s) where it takes crank angles otherwise."""
        return self.timing is not None

    @property
    def param(self) -> float:
        """Where the file places the mechanism, as its solver takes it: the crank angle
        (rad from +x; a slider's travel, m), or the instant (s) of a timed mechanism."""
        return self.timing.time if self.timing is not None else self.driver.phi

    def inputs_at(self, x):
        """Each driver's (q, q′, q″) where the mechanism is at ``x`` (as :attr:`param` is):
        the crank's angle, ω and ε (a slider's travel, velocity and acceleration) as the
        file gives its rates, or at the instant ``x`` by each driver's law."""
        if self.timing is None:
            d = self.driver
            return ((x, d.omega, d.epsilon),)
        return tuple(d.law.at(x) for d in self.drivers)

    def at(self, x: float, lang: str = "en", lo: float = 0.0) -> str:
        """The place ``x`` (as :attr:`param` is) in words: "φ1 = 330° (from +y, cw)"
        (:meth:`Driver.at`), or "t = 0.05 s" for a timed mechanism."""
        if self.timing is None:
            return self.driver.at(x, lang, lo)
        return f"t = {num(x, 6, lang)} {WORDS[lang]['s']}"

    def name_in(self, lang: str) -> str:
        """The name for a note or sheet in ``lang``: the file's name in that language if
        it gives one, else its name."""
        return self.names.get(lang, self.name)

    def source_in(self, lang: str) -> str:
        """Where the mechanism comes from, for a report in ``lang``: "Table 2 (built in),
        variant 3" is «таблица 2 (встроенная), вариант 3»; a file's path as it is."""
        return self.sources.get(lang, self.source)

    # ---- derived, read-only views -------------------------------------------------
    def links_of(self, point: str) -> list[int]:
        """Links (0 = frame) that carry ``point``."""
        found = [0] if point in self.frame else []
        found += [lid for lid, link in sorted(self.links.items()) if point in link.points]
        return found

    def point_names(self) -> list[str]:
        names = list(self.frame)
        for link in self.links.values():
            names += [p for p in link.points if p not in names]
        return names

    def revolutes(self) -> list[tuple[str, int, int]]:
        """Revolute pairs (point, link, link); a point on k links is k − 1 pairs."""
        pairs = []
        for name in self.point_names():
            carriers = self.links_of(name)
            pairs += [(name, carriers[0], other) for other in carriers[1:]]
        return pairs

    def translating(self) -> frozenset[int]:
        """The links that never turn: the frame, and every link joined to one of them by
        a prismatic pair (a slider on a fixed guide, a block in a translating yoke). A
        guide on such a link carries no Coriolis term."""
        out = {0}
        grew = True
        while grew:
            grew = False
            for s in self.sliders:
                pair = {s.link, s.guide.link}
                if pair & out and not pair <= out:
                    out |= pair
                    grew = True
        return frozenset(out)

    def slider_of(self, link: int) -> Slider | None:
        for s in self.sliders:
            if s.link == link:
                return s
        return None

    def at_file_angle(self, angle_deg: float) -> Mechanism:
        """The same mechanism with the crank at ``angle_deg`` in the file's convention
        (as ``--angle`` and a measurement file's ``angle_deg`` give it), assembled as the
        file's hints ask at the file's own angle: the crank turned there, on the same
        branch, as the cycle and the sheet draw it."""
        d = self.driver
        return replace(self, driver=replace(d, phi=d.phi_of(angle_deg), angle_deg=angle_deg),
                       hints_at=d.phi if self.hints_at is None else self.hints_at)

    def with_phi(self, phi: float) -> Mechanism:
        """The same mechanism with the crank at ``phi`` (rad, from +x); a timed one at the
        instant ``phi`` (s)."""
        if self.timing is not None:
            return replace(self, timing=replace(self.timing, time=phi))
        return replace(self, driver=replace(self.driver, phi=phi))
