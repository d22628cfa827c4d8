"""Built-in mechanisms covering all five dyad kinds, as TOML texts (the file format users
write): the scenes of the tests and of ``plans bench``.

Each scene is a real mechanism that assembles over the crank range given with it; the
comments give the textbook numbers the tests check (θ: crank angle of the extreme
positions' difference, ψ: rocker swing, K = (180° + θ)/(180° − θ), H: stroke).
The two samples (``samples/press.toml``, ``samples/fourbar.toml``) are scenes too.
"""

from __future__ import annotations

import tomllib
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from plans.model.load import from_dict, load
from plans.model.mechanism import Mechanism

#: the samples of a source checkout; an installed package has the other scenes only
SAMPLES = Path(__file__).resolve().parents[2] / "samples"


@dataclass(frozen=True)
class Scene:
    name: str
    kinds: tuple[str, ...]  # the dyad kinds in attachment order, e.g. ("RPR", "RRP")
    lo_deg: float  # crank range (degrees from +x) over which it assembles
    hi_deg: float
    toml: str | None = (
        None  # the mechanism file; None: ``sample`` is a file in samples/
    )
    sample: str | None = None

    @property
    def available(self) -> bool:
        return self.sample is None or (SAMPLES / self.sample).is_file()

    @property
    def full_turn(self) -> bool:
        return self.hi_deg - self.lo_deg >= 360.0

    def mechanism(self) -> Mechanism:
        if self.sample is not None:
            return load(SAMPLES / self.sample)
        return from_dict(tomllib.loads(self.toml), f"<scene {self.name}>")

    def angles(self, n: int = 13) -> np.ndarray:
        """``n`` crank angles (rad) spread over the range, avoiding its ends and 0."""
        if self.full_turn:
            deg = self.lo_deg + 360.0 * (np.arange(n) + 0.37) / n
        else:
            span = self.hi_deg - self.lo_deg
            deg = self.lo_deg + span * (0.03 + 0.94 * (np.arange(n) + 0.37) / n)
        return np.radians(deg)


# --- RRR: Grashof crank-rocker a = 0.05, b = 0.2, c = 0.15, d = 0.2 ----------------------
# extreme positions: AD = b ± a = 0.25 / 0.15 ⇒ θ = 11.320°, ψ = 41.810°, K = 1.1342
CRANK_ROCKER = """
name = { en = "Crank-rocker four-bar", ru = "Кривошипно-коромысловый механизм" }
output = "B"
[frame]
O = [0.0, 0.0]
D = [0.2, 0.0]
[driver]
link = 1
angle_deg = 60
omega = 10
[links.1]
axis = ["O", "A"]
points = { A = 0.05 }
[links.2]
name = "coupler"
axis = ["A", "B"]
points = { B = 0.2, E = [0.1, 0.06], S2 = 0.1 }
[links.3]
name = "rocker"
axis = ["D", "B"]
points = { B = 0.15, F = [0.05, -0.03] }
[assembly]
B = "above OD"
"""

def _without(text: str, *changes: tuple[str, str]) -> str:
    """``text`` with each ``(old, new)`` made, each ``old`` found exactly once."""
    for old, new in changes:
        if text.count(old) != 1:
            raise ValueError(f"scenes: {old!r} is not in the text once")
        text = text.replace(old, new)
    return text


# --- RRR, joints only: the same crank-rocker without E, S2 and F -------------------------
# the workload of the peers' four-bar kernels (their joints' motion), so the bench compares
# like with like; ``crank_rocker`` adds three points found by the similarity theorem
FOURBAR_JOINTS = _without(
    CRANK_ROCKER,
    ('en = "Crank-rocker four-bar"', 'en = "Crank-rocker four-bar, joints only"'),
    ('ru = "Кривошипно-коромысловый механизм"',
     'ru = "Кривошипно-коромысловый механизм (только шарниры)"'),
    ("points = { B = 0.2, E = [0.1, 0.06], S2 = 0.1 }", "points = { B = 0.2 }"),
    ("points = { B = 0.15, F = [0.05, -0.03] }", "points = { B = 0.15 }"),
)

# --- RRP: offset crank-slider r = 0.1, l = 0.4, e = 0.05 ---------------------------------
# θ = arcsin(e/(l−r)) − arcsin(e/(l+r)) = 3.855°, H = √((l+r)²−e²) − √((l−r)²−e²) = 0.20169 m
CRANK_SLIDER_OFFSET = """
name = { en = "Offset crank-slider", ru = "Дезаксиальный кривошипно-ползунный механизм" }
output = "B"
[frame]
O = [0.0, 0.0]
[driver]
link = 1
angle_deg = 30
omega = 15
sense = "cw"
[links.1]
axis = ["O", "A"]
points = { A = 0.1 }
[links.2]
name = "connecting rod"
axis = ["A", "B"]
points = { B = 0.4, S2 = [0.15, 0.02] }
[links.3]
name = "slider"
points = { B = 0, M = [0.03, 0.01] }
[[sliders]]
link = 3
guide = { link = 0, through = [0.0, 0.05], angle_deg = 0 }
[assembly]
B = "right of O"
"""

# --- RRP: central crank-slider (closed form x = r cosφ + √(l² − r² sin²φ)) -----------------
CRANK_SLIDER_CENTRAL = """
name = { en = "Central crank-slider", ru = "Центральный кривошипно-ползунный механизм" }
output = "B"
[frame]
O = [0.0, 0.0]
[driver]
link = 1
angle_deg = 45
omega = 12
[links.1]
axis = ["O", "A"]
points = { A = 0.1 }
[links.2]
axis = ["A", "B"]
points = { B = 0.4 }
[links.3]
points = { B = 0 }
[[sliders]]
link = 3
guide = { link = 0, through = "O", angle_deg = 0 }
[assembly]
B = "right of O"
"""

# --- RPR + RRP on a moving guide: the slotted link drives a link hinged at a fixed pivot E
# whose end F carries a block sliding along the rocker (Coriolis term in the RRP group) ----
SLOT_RRP_MOVING = """
name = { en = "Slotted link with a block on the rocker", ru = "Кулисный механизм с камнем на коромысле" }
output = "F"
[frame]
O = [0.0, 0.0]
B = [0.0, -0.44]
E = [0.05, -0.1]
[driver]
link = 1
angle_deg = 60
omega = 20
[links.1]
axis = ["O", "A"]
points = { A = 0.15 }
[links.2]
name = "slide block"
points = { A = 0 }
[links.3]
name = "rocker"
axis = ["B", "C"]
points = { C = 0.75, S3 = [0.3, 0.02] }
[links.4]
name = "link EF"
axis = ["E", "F"]
points = { F = 0.2, S4 = [0.1, -0.02] }
[links.5]
name = "block on the rocker"
points = { F = 0 }
[[sliders]]
link = 2
guide = { link = 3 }
[[sliders]]
link = 5
guide = { link = 3 }
[assembly]
F = "above E"
"""

# --- RPR: oscillating slotted link r = 0.1 < L = 0.3: θ = ψ = 2·arcsin(r/L) = 38.942° -----
SLOTTED_OSCILLATING = """
name = { en = "Oscillating slotted link", ru = "Механизм с качающейся кулисой" }
output = "C"
[frame]
O = [0.0, 0.0]
B = [0.0, -0.3]
[driver]
link = 1
angle_deg = 20
omega = 8
[links.1]
axis = ["O", "A"]
points = { A = 0.1 }
[links.2]
points = { A = 0 }
[links.3]
axis = ["B", "C"]
points = { C = 0.5, S3 = [0.25, 0.015] }
[[sliders]]
link = 2
guide = { link = 3 }
"""

# --- RPR with the guide offset from the rocker pivot by 0.02 m ---------------------------
SLOTTED_OFFSET = """
name = { en = "Slotted link, offset guide", ru = "Кулисный механизм со смещённой направляющей" }
output = "C"
[frame]
O = [0.0, 0.0]
B = [0.0, -0.3]
[driver]
link = 1
angle_deg = 110
omega = 8
sense = "cw"
[links.1]
axis = ["O", "A"]
points = { A = 0.1 }
[links.2]
points = { A = 0, M = [0.02, 0.0] }
[links.3]
axis = ["B", "C"]
points = { C = 0.5 }
[[sliders]]
link = 2
guide = { link = 3, offset = 0.02 }
"""

# --- RPR: rotating slotted link r = 0.2 > L = 0.1 ----------------------------------------
SLOTTED_ROTATING = """
name = { en = "Rotating slotted link", ru = "Механизм с вращающейся кулисой" }
output = "C"
[frame]
O = [0.0, 0.0]
B = [0.0, -0.1]
[driver]
link = 1
angle_deg = 15
omega = 5
[links.1]
axis = ["O", "A"]
points = { A = 0.2 }
[links.2]
points = { A = 0 }
[links.3]
axis = ["B", "C"]
points = { C = 0.35 }
[[sliders]]
link = 2
guide = { link = 3 }
"""

# --- PRP: tangent mechanism, block on the crank's guide, hinged to a slider on x = 0.2 ----
# closed form: y_C = d·tanφ, v = dω/cos²φ, a = 2dω² tanφ/cos²φ
TANGENT = """
name = { en = "Tangent mechanism", ru = "Тангенсный механизм" }
output = "C"
[frame]
O = [0.0, 0.0]
[driver]
link = 1
angle_deg = 25
omega = 6
[links.1]
axis = ["O", "A"]
points = { A = 0.1 }
[links.2]
name = "block on the crank"
points = { C = 0 }
[links.3]
name = "slider on x = 0.2"
points = { C = 0, M = [0.05, 0.02] }
[[sliders]]
link = 2
guide = { link = 1 }
[[sliders]]
link = 3
guide = { link = 0, through = [0.2, 0.0], angle_deg = 90 }
"""

# --- RPP: Scotch yoke, x_D = r cos φ ------------------------------------------------------
SCOTCH_YOKE = """
name = { en = "Scotch yoke", ru = "Синусный механизм" }
output = "D"
[frame]
O = [0.0, 0.0]
[driver]
link = 1
angle_deg = 35
omega = 10
[links.1]
axis = ["O", "A"]
points = { A = 0.1 }
[links.2]
name = "block"
points = { A = 0 }
[links.3]
name = "yoke"
axis = ["D", "E"]
points = { E = 0.3, S3 = [0.15, 0.05] }
[[sliders]]
link = 2
guide = { link = 3, angle_deg = 90 }
[[sliders]]
link = 3
point = "D"
guide = { link = 0, through = [0.0, 0.0], angle_deg = 0 }
"""

# --- RPP with an inclined slot (60° to the yoke) on a guide inclined at 20° --------------
YOKE_INCLINED = """
name = { en = "Inclined Scotch yoke", ru = "Синусный механизм с наклонной направляющей" }
output = "D"
[frame]
O = [0.0, 0.0]
[driver]
link = 1
angle_deg = 200
omega = 10
[links.1]
axis = ["O", "A"]
points = { A = 0.1 }
[links.2]
points = { A = 0 }
[links.3]
axis = ["D", "E"]
points = { E = 0.3, S3 = [0.1, -0.04] }
[[sliders]]
link = 2
guide = { link = 3, angle_deg = 60, through = [0.05, 0.0] }
[[sliders]]
link = 3
point = "D"
guide = { link = 0, through = [0.0, -0.05], angle_deg = 20 }
"""

# --- RPR + RPP whose outer guide is carried by a moving link: a yoke slides on the
# slotted link (at 15° to it, offset 0.1), the block on the crank pin A moves in the
# yoke's 60° slot; Coriolis terms in both routes of the RPP group ----------------------
YOKE_ON_ROCKER = """
name = { en = "Yoke sliding on a slotted link", ru = "Синусный механизм на кулисе" }
[frame]
O = [0.0, 0.0]
B = [0.0, -0.44]
[driver]
link = 1
angle_deg = 60
omega = 20
[links.1]
axis = ["O", "A"]
points = { A = 0.15 }
[links.2]
points = { A = 0 }
[links.3]
axis = ["B", "C"]
points = { C = 0.75 }
[links.4]
name = "block in the yoke"
points = { A = 0 }
[links.5]
name = "yoke on the rocker"
axis = ["D", "E"]
points = { E = 0.2, S5 = [0.1, 0.03] }
[[sliders]]
link = 2
guide = { link = 3 }
[[sliders]]
link = 4
guide = { link = 5, angle_deg = 60 }
[[sliders]]
link = 5
point = "D"
guide = { link = 3, offset = 0.1, angle_deg = 15 }
"""

# --- RPR + PRP on two moving guides: a block G slides on a guide of the crank (⊥ to it,
# 0.05 from O) and is hinged to a block sliding on the slotted link's offset guide. The
# guides turn parallel at φ = 199.47° and 340.53°: the crank's range between them ------
PRP_TWO_MOVING = """
name = { en = "Cross-slide on the crank and the slotted link", ru = "Крестовый ползун на кривошипе и кулисе" }
[frame]
O = [0.0, 0.0]
B = [0.0, -0.3]
[driver]
link = 1
angle_deg = 20
omega = 8
[links.1]
axis = ["O", "A"]
points = { A = 0.1 }
[links.2]
points = { A = 0 }
[links.3]
axis = ["B", "C"]
points = { C = 0.5 }
[links.4]
points = { G = 0 }
[links.5]
points = { G = 0 }
[[sliders]]
link = 2
guide = { link = 3 }
[[sliders]]
link = 4
point = "G"
guide = { link = 1, angle_deg = 90, through = [0.05, 0.0] }
[[sliders]]
link = 5
point = "G"
guide = { link = 3, offset = 0.03 }
"""

# --- RPR, general: the rocker's pivot B off its axis, the guide through [0.05, −0.02] at
# 75° to the axis, extra points on every link ----------------------------------------------
SLOTTED_GENERAL = """
name = { en = "Slotted link, general guide", ru = "Кулисный механизм с направляющей общего положения" }
[frame]
O = [0.0, 0.0]
B = [0.05, -0.3]
[driver]
link = 1
angle_deg = 20
omega = 8
[links.1]
axis = ["O", "A"]
points = { A = 0.1, S1 = [0.03, 0.02] }
[links.2]
points = { A = 0, M = [0.01, 0.02] }
[links.3]
axis = ["C", "X"]
points = { X = 0.5, B = [0.1, 0.05], S3 = [0.2, -0.01] }
[[sliders]]
link = 2
guide = { link = 3, through = [0.05, -0.02], angle_deg = 75 }
"""


SCENES: dict[str, Scene] = {
    s.name: s
    for s in (
        Scene("crank_rocker", ("RRR",), 0.0, 360.0, CRANK_ROCKER),
        Scene("fourbar_joints", ("RRR",), 0.0, 360.0, FOURBAR_JOINTS),
        Scene("crank_slider_offset", ("RRP",), 0.0, 360.0, CRANK_SLIDER_OFFSET),
        Scene("crank_slider_central", ("RRP",), 0.0, 360.0, CRANK_SLIDER_CENTRAL),
        Scene("slot_rrp_moving", ("RPR", "RRP"), 0.0, 360.0, SLOT_RRP_MOVING),
        Scene("slotted_oscillating", ("RPR",), 0.0, 360.0, SLOTTED_OSCILLATING),
        Scene("slotted_offset", ("RPR",), 0.0, 360.0, SLOTTED_OFFSET),
        Scene("slotted_rotating", ("RPR",), 0.0, 360.0, SLOTTED_ROTATING),
        Scene("tangent", ("PRP",), -75.0, 75.0, TANGENT),
        Scene("scotch_yoke", ("RPP",), 0.0, 360.0, SCOTCH_YOKE),
        Scene("yoke_inclined", ("RPP",), 0.0, 360.0, YOKE_INCLINED),
        Scene("prp_two_moving", ("RPR", "PRP"), 0.0, 180.0, PRP_TWO_MOVING),
        Scene("slotted_general", ("RPR",), 0.0, 360.0, SLOTTED_GENERAL),
        Scene("yoke_on_rocker", ("RPR", "RPP"), 0.0, 360.0, YOKE_ON_ROCKER),
        Scene("press", ("RPR", "RRP"), 0.0, 360.0, sample="press.toml"),
        # not Grashof: BD must stay within [BC − CD, BC + CD] = [0.1075, 0.3125]
        Scene("fourbar", ("RRR",), -125.0, 125.0, sample="fourbar.toml"),
    )
}
