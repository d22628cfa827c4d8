"""``plans cam``: a cam mechanism from its file: the motion laws and their impacts, the base
circle (the smallest the pressure-angle limits allow, by the phase portrait), the pressure
angles, the curvature checks and the profile's coordinates; the cam sheet and the note.

    plans cam samples/cam.toml                       # the text
    plans cam samples/cam.toml --csv > profile.csv   # the profile for a CNC or CAD user (mm)
    plans cam samples/cam.toml --json                # everything, SI
    plans cam samples/cam.toml -o cam.svg --png cam.png --note cam.md --lang ru
"""

from __future__ import annotations

import csv
import io
import json
import math

from drawing import export
from drawing.cam_sheet import render
from drawing.sheet.layout import LayoutError
from plans.cams.camfile import load
from plans.cams.design import Design, design
from plans.cams.note import cam_note
from plans.cams.table import profile_table
from plans.cams.words import words
from plans.cli.common import EXIT_OK, number, picture_names, warn
from plans.errors import InputError
from plans.fmt import columns, num

PICTURES = {".svg": ("-o", "output"), ".png": ("--png", "png"), ".pdf": ("--pdf", "pdf")}


def configure(p) -> None:
    p.add_argument("file", help="cam file (TOML)")
    fmt = p.add_mutually_exclusive_group()
    fmt.add_argument("--json", action="store_true", help="everything as JSON (SI units)")
    fmt.add_argument("--csv", action="store_true",
                     help="the profile's points as CSV, in mm, every step_deg of the file (default 1°)")
    p.add_argument("--lang", choices=("ru", "en"), default="en", help="language of the text, sheet and note")
    p.add_argument("-o", "--output", metavar="SHEET.svg", help="also draw the cam sheet (SVG)")
    p.add_argument("--png", metavar="FILE", help="the cam sheet as PNG too (needs cairosvg)")
    p.add_argument("--pdf", metavar="FILE", help="the cam sheet as PDF too (needs cairosvg)")
    p.add_argument("--format", default="A1", choices=["A1", "A2", "A3"],
                   help="the sheet's format (default A1)")
    p.add_argument("--dpi", type=number(10, 600), default=100.0,
                   help="PNG resolution, 10 to 600 (default 100)")
    p.add_argument("--note", metavar="NOTE.md",
                   help="also write the explanatory note's cam section (Markdown)")
    p.add_argument("--title-block", nargs="*", default=[], metavar="KEY=VALUE",
                   help="title-block fields: name, designation, student, group, university, checker, date")


def run(args) -> int:
    picture_names(args, PICTURES)
    if args.output == "-":  # the text (or JSON, CSV) goes there
        raise InputError("command line", "-o -: stdout takes the text; give the sheet a file name")
    args.run_files.claim(args, [args.file])  # an output onto the cam file: refused first
    sheet = args.output is not None or args.png or args.pdf
    if args.png or args.pdf:
        export.require()  # before anything is computed
    cam = load(args.file)
    d = design(cam)
    table = profile_table(d, cam.step)
    if args.json:
        text = json.dumps(to_json(d, table), ensure_ascii=False, indent=1) + "\n"
    elif args.csv:
        text = to_csv(d, table)
    else:
        text = to_text(d, args.lang)
    files: list[tuple[str | None, str | bytes]] = [(None, text)]
    if sheet:
        try:
            svg = render(d, args.format, args.lang, args.title_block)
        except LayoutError as exc:  # the format is too small: which is not, said by the file
            raise InputError(cam.source, str(exc)) from None
        if args.output is not None:
            files.append((args.output, svg))
        if args.png:
            files.append((args.png, export.png_bytes(svg, dpi=args.dpi)))
        if args.pdf:
            files.append((args.pdf, export.pdf_bytes(svg)))
    if args.note:
        files.append((args.note, cam_note(d, args.lang)))
    for path, data in files:  # everything rendered: now written, all or none
        args.run_files.write(path, data)
    for w in d.warnings:
        warn("cam", w, cam.source)
    return EXIT_OK


# ---------------------------------------------------------------------------------------
# text
# ---------------------------------------------------------------------------------------


def phase_name(d: Design, i: int, lang: str = "en") -> str:
    """"rise", "return", "outer dwell" (the follower held at the top), "inner dwell"."""
    w = words(lang)
    p = d.motion.phases[i]
    if p.kind != "dwell":
        return w[p.kind]
    return w["outer dwell" if p.level > d.motion.stroke / 2 else "inner dwell"]


def _deg(x: float) -> float:
    return math.degrees(x)


def _ang(x: float, lang: str) -> str:
    """A cam angle in degrees, in [0, 360)."""
    v = math.degrees(x) % 360.0
    return num(0.0 if v > 360.0 - 5e-10 else v, 5, lang)


def _len(d: Design, x: float, lang: str) -> str:
    """A displacement: mm, or degrees of an oscillating follower's swing."""
    if d.cam.follower.oscillating:
        return f"{num(math.degrees(x), 4, lang)}°"
    return f"{num(x * 1000, 4, lang)} {words(lang)['mm']}"


def to_text(d: Design, lang: str = "en") -> str:
    w = words(lang)
    cam, f = d.cam, d.cam.follower

    def n(x, digits=4):
        return num(x, digits, lang)

    def mm(x):
        return n(x * 1000)

    out = [w["title"].format(name=cam.name_in(lang)), ""]
    line = w["follower"].format(kind=w[f.kind], motion=w[f.motion])
    parts = []
    if f.kind == "roller":
        parts.append(w["roller_r"].format(r=mm(f.roller)))
    if f.oscillating:
        parts.append(w["arm"].format(l=mm(f.arm), a=mm(f.centre), how=w["with" if f.with_cam else "against"]))
    elif d.offset:
        parts.append(w["offset"].format(e=mm(abs(d.offset)), side=w["right" if d.offset > 0 else "left"]))
    else:
        parts.append(w["centred"])
    out.append(line + "; " + "; ".join(parts))
    rpm = f", n = {n(cam.rpm)} {w['rpm']}" if cam.rpm else ""
    out.append(w["cam"].format(sense=w["ccw" if cam.sense > 0 else "cw"], omega=n(cam.omega), rpm=rpm))
    if cam.disc is not None:
        out.append(w["disc"].format(R=mm(cam.disc.radius), c=mm(cam.disc.eccentricity)))
    out += ["", w["phases"]]
    rows = []
    for i, p in enumerate(d.motion.phases):
        law = ""
        if p.moves:
            law = p.law.name(lang)
            if p.ratio != 1.0:
                law = w["ratio"].format(law=law, r=n(p.ratio))
        stroke = _len(d, d.motion.stroke, lang) if p.moves else ""
        rows.append([phase_name(d, i, lang), f"{_ang(p.start, lang)}°",
                     f"{num(_deg(p.end), 5, lang)}°", f"{num(_deg(p.angle), 5, lang)}°", law, stroke])
    out += columns(rows, w["phase_head"], right=(1, 2, 3))
    out += ["", w["motion"].format(omega=n(cam.omega))]
    rows = []
    unit_v, unit_a = (w["rad/s"], w["rad/s²"]) if f.oscillating else (w["m/s"], w["m/s²"])
    for i, (v, a) in d.speeds.items():
        rows.append([phase_name(d, i, lang), f"{n(v.value * cam.omega)} {unit_v}", f"{_ang(v.phi, lang)}°",
                     f"{n(a.value * cam.omega**2)} {unit_a}", f"{_ang(a.phi, lang)}°"])
    out += columns(rows, w["motion_head"], right=(1, 2, 3, 4))
    out += ["", w["impacts"]]
    rows = []
    for imp in d.impacts:
        b, a = imp.where
        where = (w["inner"].format(phase=phase_name(d, b, lang)) if a == b
                 else f"{phase_name(d, b, lang)} → {phase_name(d, a, lang)}")
        if imp.kind == "rigid":
            what = w["impact_rigid"].format(v=f"{n(abs(imp.dv) * cam.omega)} {unit_v}")
        elif imp.kind == "soft":
            what = w["impact_soft"].format(a=f"{n(abs(imp.da) * cam.omega**2)} {unit_a}")
        else:
            what = w["impact_none"]
        rows.append([f"φ = {_ang(imp.phi, lang)}°", where, what])
    out += list(columns(rows, ("", "", ""))[1:])
    out += ["", w["base"]]
    lim = cam.limits
    if not f.flat:
        out.append("  " + w["limits"].format(rise=n(lim.rise_deg), ret=n(lim.return_deg)))
    if cam.disc is not None:
        out.append("  " + w["r0_disc"].format(r=mm(d.r0), h=_len(d, d.motion.stroke, lang)))
    else:
        if d.best is not None:
            out.append("  " + w["smallest_at"].format(e=mm(d.offset), r=mm(d.smallest)))
            out.append("  " + w["smallest_best"].format(r=mm(d.best[0]), e=mm(d.best[1])))
        elif f.flat and d.smallest is not None:
            out.append("  " + w["smallest_flat"].format(m=mm(lim.min_radius), r=mm(d.smallest)))
        elif d.smallest is not None:
            out.append("  " + w["smallest_osc"].format(r=mm(d.smallest)))
        out.append("  " + w["r0_given" if cam.base_radius is not None else "r0_chosen"].format(r=mm(d.r0)))
    out += ["", w["pressure"]]
    arr = d.arrangement
    if f.flat:
        out.append("  " + w["p_flat"])
    else:
        if f.oscillating:
            out.append("  " + w["p_osc"].format(psi0=n(math.degrees(arr.psi0)),
                                                st=f"{arr.sigma * arr.tau:+d}"))
        else:
            out.append("  " + w["p_trans"].format(s0=mm(arr.s0), sigma=f"{arr.sigma:+d}"))
        for kind, limit in (("rise", lim.rise_deg), ("return", lim.return_deg)):
            e = d.pressure[kind]
            a = math.degrees(e.value)
            out.append("  " + w["p_max"].format(kind=w[kind], a=n(a), phi=_ang(e.phi, lang), lim=n(limit),
                                                flag=w["over"] if a > limit + 1e-9 else ""))
    out += ["", w["curvature"]]
    out += ["  " + x for x in curvature_lines(d, lang)]
    out += ["", w["profile"].format(step=10, csv=n(math.degrees(cam.step)))]
    out += profile_rows(d, lang)
    return "\n".join(out) + "\n"


def curvature_lines(d: Design, lang: str) -> list[str]:
    w = words(lang)
    f = d.cam.follower

    def mm(x):
        return num(x * 1000, 4, lang)

    out = []
    if f.flat:
        r = d.radius["profile"]
        out.append(w["flat_rho"].format(r=mm(r.value), phi=_ang(r.phi, lang)))
        lo, hi = d.face
        if f.oscillating:
            out.append(w["face"].format(lo=mm(lo), hi=mm(hi), along=w["along_pivot"], w=mm(hi - lo), half=""))
        else:
            half = max(abs(lo), abs(hi))
            out.append(w["face"].format(lo=mm(lo), hi=mm(hi), along=w["along_axis"], w=mm(hi - lo),
                                        half=w["half"].format(h=mm(half))))
    else:
        r, c = d.radius["pitch"], d.radius["pitch_concave"]
        text = (w["pitch_rho"].format(r=mm(r.value), phi=_ang(r.phi, lang)) if r is not None
                else w["pitch_straight"])
        if c is not None:
            text += w["concave"].format(r=mm(abs(c.value)), phi=_ang(c.phi, lang))
        out.append(text)
        if f.kind == "roller":
            if r is not None:
                out.append(w["undercut_no"].format(r=mm(f.roller), a=mm(r.value - f.roller)))
        else:
            out.append(w["knife_ok"])
    for c in d.corners:
        what = w["corner_flat"] if f.flat else w["corner_roller"] if f.kind == "roller" else w["corner_knife"]
        how = w["corner_sharp" if c.convex else "corner_hollow"]
        out.append(w["corner"].format(phi=_ang(c.phi, lang), how=how, what=what))
    return out


def profile_rows(d: Design, lang: str, every_deg: float = 10.0) -> list[str]:
    """The profile's table every ``every_deg`` (and at every joint) for the text."""
    w = words(lang)
    t = profile_table(d, math.radians(every_deg))
    head = w["profile_head_osc" if d.cam.follower.oscillating else "profile_head"]

    def mm(x):  # rounding's noise of a zero is a zero
        return num(0.0 if abs(x) < 1e-12 else x * 1000, 5, lang)

    rows = []
    for k in range(len(t.phi)):
        s = (num(math.degrees(t.s[k]), 5, lang) if d.cam.follower.oscillating else mm(t.s[k]))
        rho = t.radius[k]
        rows.append([_ang(t.phi[k], lang), s, mm(t.pitch[k].real), mm(t.pitch[k].imag), mm(t.profile[k].real),
                     mm(t.profile[k].imag), w["straight"] if not math.isfinite(rho) else mm(rho),
                     num(math.degrees(t.pressure[k]), 4, lang)])
    return columns(rows, head, right=tuple(range(8)))


# ---------------------------------------------------------------------------------------
# JSON and CSV
# ---------------------------------------------------------------------------------------


def _f(x) -> float | None:
    x = float(x)
    return x + 0.0 if math.isfinite(x) else None


def _xy(z) -> list[float]:
    return [float(z.real) + 0.0, float(z.imag) + 0.0]


def _ext(e, scale: float = 1.0, deg: bool = False) -> dict | None:
    if e is None:
        return None
    return {"value": math.degrees(e.value) if deg else _f(e.value * scale),
            "phi_deg": math.degrees(e.phi) % 360.0, "phase": e.phase}


def to_json(d: Design, t) -> dict:
    cam, f = d.cam, d.cam.follower
    arr = d.arrangement
    out = {
        "name": cam.name,
        "follower": {"kind": f.kind, "motion": f.motion, "roller_radius": f.roller or None,
                     "offset": None if f.oscillating else d.offset,
                     "arm": f.arm or None, "centre_distance": f.centre or None,
                     "rise": ("with" if f.with_cam else "against") if f.oscillating else None,
                     "stroke": d.motion.stroke, "stroke_unit": "rad" if f.oscillating else "m"},
        "cam": {"sense": "ccw" if cam.sense > 0 else "cw", "omega": cam.omega, "base_radius": d.r0,
                "base_radius_given": cam.base_radius is not None, "s0": None if f.oscillating else arr.s0,
                "psi0_deg": math.degrees(arr.psi0) if f.oscillating else None,
                "disc": None if cam.disc is None else {"radius": cam.disc.radius,
                                                       "eccentricity": cam.disc.eccentricity}},
        "phases": [],
        "impacts": [{"phi_deg": math.degrees(i.phi), "before": i.where[0], "after": i.where[1],
                     "kind": i.kind, "velocity_jump": i.dv * cam.omega,
                     "acceleration_jump": i.da * cam.omega**2}
                    for i in d.impacts],
        "base": {"limits_deg": {"rise": cam.limits.rise_deg, "return": cam.limits.return_deg},
                 "min_radius": cam.limits.min_radius, "smallest": d.smallest,
                 "best": None if d.best is None else {"base_radius": d.best[0], "offset": d.best[1]},
                 "portrait": None if d.portrait is None else {
                     "centre": list(d.portrait.centre),
                     "tangents": [{"phase": tg.phase, "slope": tg.m, "intercept": tg.b,
                                   "phi_deg": math.degrees(tg.phi), "point": [tg.x, tg.y],
                                   "limit_deg": tg.limit_deg} for tg in d.portrait.tangents]}},
        "pressure": {k: _ext(e, deg=True) for k, e in d.pressure.items()},
        "curvature": {k: _ext(e) for k, e in d.radius.items()},
        "corners": [{"phi_deg": math.degrees(c.phi), "convex": c.convex} for c in d.corners],
        "face": None if d.face is None else {"from": d.face[0], "to": d.face[1]},
        "warnings": list(d.warnings),
    }
    for i, p in enumerate(d.motion.phases):
        item = {"kind": p.kind, "name": phase_name(d, i), "start_deg": math.degrees(p.start),
                "angle_deg": math.degrees(p.angle), "law": p.law.key if p.moves else None,
                "ratio": p.ratio if p.moves else None}
        if i in d.speeds:
            v, a = d.speeds[i]
            item |= {"max_velocity": v.value * cam.omega, "max_velocity_phi_deg": math.degrees(v.phi),
                     "max_acceleration": a.value * cam.omega**2,
                     "max_acceleration_phi_deg": math.degrees(a.phi),
                     "max_pressure_deg": math.degrees(d.phase_pressure[i].value)}
        out["phases"].append(item)
    om = cam.omega
    out["profile"] = [{"phi_deg": math.degrees(t.phi[k]), "phase": int(t.phase[k]), "s": _f(t.s[k]),
                       "ds": _f(t.s1[k]), "d2s": _f(t.s2[k]), "d3s": _f(t.s3[k]),
                       "velocity": _f(t.s1[k] * om), "acceleration": _f(t.s2[k] * om**2),
                       "jerk": _f(t.s3[k] * om**3),
                       "pressure_deg": math.degrees(float(t.pressure[k])),
                       "pitch": _xy(t.pitch[k]), "profile": _xy(t.profile[k]), "radius": _f(t.radius[k]),
                       "corner": bool(t.corner[k])} for k in range(len(t.phi))]
    return out


def to_csv(d: Design, t) -> str:
    """The profile's points, mm (the swing in degrees): one row a point."""
    osc = d.cam.follower.oscillating
    buf = io.StringIO()
    wr = csv.writer(buf, lineterminator="\n")
    wr.writerow(["phi_deg", "phase", "psi_deg" if osc else "s_mm", "dpsi_dphi" if osc else "ds_dphi_mm",
                 "d2psi_dphi2" if osc else "d2s_dphi2_mm", "pressure_deg", "pitch_x_mm", "pitch_y_mm",
                 "x_mm", "y_mm", "radius_mm", "corner"])

    def r(x) -> str:
        x = float(x) + 0.0
        return repr(x) if math.isfinite(x) else ""

    k_s = (180.0 / math.pi, 1.0, 1.0) if osc else (1000.0, 1000.0, 1000.0)
    for k in range(len(t.phi)):
        wr.writerow([r(math.degrees(t.phi[k])), int(t.phase[k]), r(t.s[k] * k_s[0]), r(t.s1[k] * k_s[1]),
                     r(t.s2[k] * k_s[2]), r(math.degrees(float(t.pressure[k]))), r(t.pitch[k].real * 1000),
                     r(t.pitch[k].imag * 1000), r(t.profile[k].real * 1000), r(t.profile[k].imag * 1000),
                     r(t.radius[k] * 1000), int(bool(t.corner[k]))])
    return buf.getvalue()
