"""Cam mechanisms: the follower's motion laws and their impacts, the smallest base circle by
the phase portrait, the profile by inversion for knife-edge, roller and flat-faced
followers (translating, centred or offset, and oscillating), its curvature and undercut.

Only the ground lies below: the cam file is read with :mod:`plans.model.fileformat`'s
located problems, and nothing of the linkages' engine is needed.

    from plans.cams import load, design, profile_table
    d = design(load("samples/cam.toml"))
    d.r0, d.pressure["rise"], profile_table(d, d.cam.step).profile
"""

from plans.cams.base import Portrait, Tangent, portrait
from plans.cams.camfile import Cam, Disc, Follower, Limits, from_dict, load
from plans.cams.design import Corner, Design, Extreme, ProfileError, design, motion_of
from plans.cams.follower import Arrangement, in_cam_frame
from plans.cams.laws import LAWS, Law, law_named, unit
from plans.cams.motion import DiscMotion, Impact, Motion, Phase, impacts
from plans.cams.profile import Curves, curves
from plans.cams.table import Table, profile_table

__all__ = [
    "LAWS",
    "Arrangement",
    "Cam",
    "Corner",
    "Curves",
    "Design",
    "Disc",
    "DiscMotion",
    "Extreme",
    "Follower",
    "Impact",
    "Law",
    "Limits",
    "Motion",
    "Phase",
    "Portrait",
    "ProfileError",
    "Table",
    "Tangent",
    "curves",
    "design",
    "from_dict",
    "impacts",
    "in_cam_frame",
    "law_named",
    "load",
    "motion_of",
    "portrait",
    "profile_table",
    "unit",
]
