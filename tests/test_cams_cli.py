"""``plans cam`` as a user runs it: the text in both languages, the JSON and the CSV of the
profile, the cam sheet (parsed: its views, title block and scale; its letters clear of each
other), the note, the outputs all or none, and hostile cam files."""

from __future__ import annotations

import csv
import io
import json
import math
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from support import run

from drawing.cam_sheet import build
from drawing.obstacles import overlaps
from drawing.scene import Text, flatten
from plans.cams import design, from_dict, load
from plans.cams.design import ProfileError
from plans.errors import InputError

ROOT = Path(__file__).resolve().parent.parent
SAMPLE = ROOT / "samples" / "cam.toml"
SVG = "{http://www.w3.org/2000/svg}"


def _strict(text: str):
    """JSON with no NaN or infinity in it."""
    def bad(name):
        raise AssertionError(f"{name} in the JSON")
    return json.loads(text, parse_constant=bad)


def test_the_sample_as_text(capsys):
    code, out, err = run(capsys, "cam", SAMPLE)
    assert code == 0 and err == ""
    for line in ("Follower: roller, translating; roller r_r = 8 mm; "
                 "offset e = 5 mm (right of the cam's centre)",
                 "  rise           0°  150°   150°  cosine acceleration (simple harmonic)  32 mm",
                 "  φ = 0°    inner dwell → rise    soft: the acceleration jumps by 3.638 m/s²",
                 "  φ = 180°  outer dwell → return  none",
                 "  smallest r0 at e = 5 mm: 18.15 mm (phase portrait)",
                 "  r0 = 18.15 mm (the smallest)",
                 "  rise: max 25° at φ = 57.304° (limit 25°)"):
        assert line in out.splitlines(), line
    assert "nan" not in out.lower() and "inf" not in out.lower()


def test_the_sample_in_russian(capsys):
    code, out, _ = run(capsys, "cam", SAMPLE, "--lang", "ru")
    assert code == 0
    assert "Кулачковый механизм: Кулачковый механизм с роликовым толкателем" in out
    assert "наименьший r0 при e = 5 мм: 18,15 мм (по фазовому портрету)" in out
    assert "ω = 12,57 рад/с, n = 120 об/мин" in out


def test_json_is_si_and_agrees_with_the_design(capsys):
    code, out, _ = run(capsys, "cam", SAMPLE, "--json")
    assert code == 0
    data = _strict(out)
    d = design(load(SAMPLE))
    assert data["cam"]["base_radius"] == d.r0 and data["cam"]["base_radius_given"] is False
    assert data["base"]["best"] == {"base_radius": d.best[0], "offset": d.best[1]}
    assert [p["law"] for p in data["phases"]] == ["cosine", None, "cycloidal", None]
    assert [i["kind"] for i in data["impacts"]] == ["soft", "soft", "none", "none"]
    assert data["pressure"]["rise"]["value"] == pytest.approx(25.0, abs=1e-9)
    rows = data["profile"]
    assert len(rows) == 360 and rows[0]["phi_deg"] == 0.0 and rows[-1]["phi_deg"] == pytest.approx(359.0)
    assert math.hypot(*rows[0]["pitch"]) == pytest.approx(d.r0, rel=1e-14)  # on the base circle
    om = 120 * math.pi / 30
    for r in rows[::37]:  # the follower's velocity, acceleration and jerk at ω
        assert (r["velocity"], r["acceleration"], r["jerk"]) == pytest.approx(
            (r["ds"] * om, r["d2s"] * om**2, r["d3s"] * om**3), rel=1e-15, abs=1e-300)
    assert math.hypot(*[a - b for a, b in zip(rows[0]["pitch"], rows[0]["profile"], strict=True)]) == \
        pytest.approx(0.008, rel=1e-12)


def test_csv_is_the_profile_in_millimetres(capsys):
    code, out, _ = run(capsys, "cam", SAMPLE, "--csv")
    assert code == 0
    rows = list(csv.DictReader(io.StringIO(out)))
    _, js, _ = run(capsys, "cam", SAMPLE, "--json")
    profile = _strict(js)["profile"]
    assert len(rows) == len(profile) == 360
    for row, p in zip(rows, profile, strict=True):
        assert float(row["x_mm"]) == pytest.approx(p["profile"][0] * 1000, rel=1e-15, abs=1e-12)
        assert float(row["y_mm"]) == pytest.approx(p["profile"][1] * 1000, rel=1e-15, abs=1e-12)
        assert float(row["phi_deg"]) == pytest.approx(p["phi_deg"], abs=1e-12)
    assert list(rows[0]) == ["phi_deg", "phase", "s_mm", "ds_dphi_mm", "d2s_dphi2_mm", "pressure_deg",
                             "pitch_x_mm", "pitch_y_mm", "x_mm", "y_mm", "radius_mm", "corner"]


def test_a_corner_is_drawn_in_full_in_the_coordinates(capsys, tmp_path):
    """A knife-edge follower on a constant-velocity rise: the pitch curve's corners at its
    ends are rows of their own, the cam angle repeated (the left limit, then the right)."""
    path = tmp_path / "cv.toml"
    path.write_text('[cam]\nbase_radius = 0.04\n[follower]\nkind = "knife-edge"\nstroke = 0.02\n'
                    '[[phases]]\nkind = "rise"\nangle_deg = 120\nlaw = "constant velocity"\n'
                    '[[phases]]\nkind = "dwell"\nangle_deg = 60\n[[phases]]\nkind = "return"\n'
                    'angle_deg = 120\nlaw = "cycloidal"\n[[phases]]\nkind = "dwell"\nangle_deg = 60\n',
                    encoding="utf-8")
    code, out, err = run(capsys, "cam", path, "--csv")
    assert code == 0 and err == ""
    rows = list(csv.DictReader(io.StringIO(out)))
    corner = [r for r in rows if r["corner"] == "1"]
    assert [float(r["phi_deg"]) for r in corner] == pytest.approx([0.0, 120.0])
    for r in corner:  # the corner's other side follows with the same angle and point
        nxt = rows[rows.index(r) + 1]
        assert nxt["phi_deg"] == r["phi_deg"] and nxt["corner"] == "0"
        assert float(nxt["x_mm"]) == pytest.approx(float(r["x_mm"]), abs=1e-12)
        assert float(nxt["ds_dphi_mm"]) != pytest.approx(float(r["ds_dphi_mm"]))


def test_sheet_png_and_note_together(capsys, tmp_path):
    sheet, png, note = tmp_path / "cam.svg", tmp_path / "cam.png", tmp_path / "cam.md"
    code, out, err = run(capsys, "cam", SAMPLE, "-o", sheet, "--png", png, "--note", note, "--dpi", "20")
    assert code == 0 and err == "" and out.startswith("Cam mechanism:")
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    root = ET.fromstring(sheet.read_text(encoding="utf-8"))
    assert root.get("width") == "841mm" and root.get("height") == "594mm"
    layers = {g.get("id") for g in root.iter(f"{SVG}g") if g.get("id", "").startswith("layer-")}
    assert {"layer-frame", "layer-title-block", "layer-views"} <= layers
    texts = " ".join("".join(t.itertext()) for t in root.iter(f"{SVG}text"))
    for caption in ("Cam profile (inversion)", "Phase portrait s(ds/dφ)", "Follower's motion diagrams",
                    "Profile coordinates", "Phases of the follower's motion"):
        assert caption in texts, caption
    assert "ТММ.КП.00.04" in texts and "2.5:1" in texts
    views = [g.get("class") for g in root.iter(f"{SVG}g") if (g.get("class") or "").startswith("view ")]
    assert views == ["view construction", "view profile-table", "view phases", "view portrait",
                     "view cam-diagrams"]
    text = note.read_text(encoding="utf-8")
    assert text.startswith("## 1. Cam mechanism: Disc cam with an offset roller follower")
    assert "`v_max = C_v·h·ω/β = 1.571·0.032·12.57/2.618 = 0.2413 m/s`" in text
    assert "`tan α = |s′ − σe| / (s0 + s)" in text


@pytest.mark.parametrize(("fmt", "follower"), [
    ("A1", 'kind = "knife-edge"\nstroke = 0.016'),
    ("A2", 'kind = "flat-faced"\nstroke = 0.02\noffset = 0.005'),
    ("A3", 'kind = "roller"\nmotion = "oscillating"\nswing_deg = 20\narm = 0.08\ncentre_distance = 0.1\n'
           'roller_radius = 0.006'),
])
def test_every_follower_has_its_sheet_with_its_letters_apart(tmp_path, fmt, follower):
    """Each kind of follower on each format: the sheet is made, its views inside the frame
    and clear of the title block, and no two letters of a view overlap."""
    path = tmp_path / "c.toml"
    path.write_text(f'[cam]\nbase_radius = 0.035\n[follower]\n{follower}\n'
                    '[[phases]]\nkind = "rise"\nangle_deg = 150\nlaw = "3-4-5"\n'
                    '[[phases]]\nkind = "dwell"\nangle_deg = 30\n[[phases]]\nkind = "return"\n'
                    'angle_deg = 120\nlaw = "cycloidal"\n[[phases]]\nkind = "dwell"\nangle_deg = 60\n',
                    encoding="utf-8")
    scene, sheet, mu = build(design(load(path)), fmt, "ru")
    frame, block = sheet.frame, sheet.title_block
    for group in scene.layer("views").items:
        texts = [t for t in flatten(group.items) if isinstance(t, Text)]
        assert overlaps(texts) == [], group.name
        x0, y0 = group.offset
        w = max(max(p[0] for p in _points(it)) for it in flatten(group.items) if _points(it))
        assert frame.x <= x0 and x0 + w <= frame.x1 + 1e-6
        assert not (x0 + w > block.x and y0 > block.y - 1e-6)
    assert mu > 0


def _points(item):
    for name in ("p1", "p2", "center", "pos"):
        if hasattr(item, name):
            return [getattr(item, name)]
    return list(getattr(item, "points", ()))


def test_the_disc_warns_of_its_pressure_angle_and_is_drawn(capsys, tmp_path):
    """Seed 004's disc with its follower on the wrong side: the pressure angle over the
    limit is a warning, not a refusal (the disc is given), and the output is whole."""
    path = tmp_path / "disc.toml"
    path.write_text('[cam]\nsense = "ccw"\n[follower]\nkind = "knife-edge"\noffset = -0.010\n'
                    '[disc]\nradius = 0.030\neccentricity = 0.010\n', encoding="utf-8")
    code, out, err = run(capsys, "cam", path, "-o", tmp_path / "disc.svg")
    assert code == 0
    assert err == (f"plans cam: warning: {path}: the pressure angle reaches 41.81° on rise at φ = 60°, "
                   "over [α] = 30°: the disc is given as it is\n")
    assert "r0 = R − OA + r_r = 20 mm (the disc's); stroke h = 21.41 mm" in out
    assert (tmp_path / "disc.svg").exists()


def test_the_exams_laws_and_their_impacts(capsys, tmp_path):
    """Seed 004's exam asks the impacts of the constant-velocity, constant-acceleration and
    cosine laws on the rise: rigid, soft, soft."""
    for law, kind in (("constant velocity", "rigid: the velocity jumps"), ("parabolic", "soft"),
                      ("cosine", "soft")):
        path = tmp_path / "exam.toml"
        path.write_text(f'[cam]\nbase_radius = 0.030\n[follower]\nkind = "knife-edge"\nstroke = 0.016\n'
                        f'[[phases]]\nkind = "rise"\nangle_deg = 120\nlaw = "{law}"\n'
                        '[[phases]]\nkind = "dwell"\nangle_deg = 60\n[[phases]]\nkind = "return"\n'
                        'angle_deg = 120\nlaw = "cycloidal"\n[[phases]]\nkind = "dwell"\nangle_deg = 60\n',
                        encoding="utf-8")
        code, out, _ = run(capsys, "cam", path)
        assert code == 0
        assert f"  φ = 0°    inner dwell → rise    {kind}" in out


def test_outputs_onto_the_cam_file_or_each_other_are_refused(capsys, tmp_path):
    cam = tmp_path / "cam.toml"
    cam.write_text(SAMPLE.read_text(encoding="utf-8"), encoding="utf-8")
    before = cam.read_bytes()
    code, out, err = run(capsys, "cam", cam, "--note", cam)
    assert code == 2 and out == "" and "is the input file" in err and cam.read_bytes() == before
    code, _, err = run(capsys, "cam", cam, "-o", tmp_path / "a.svg", "--png", tmp_path / "a.svg")
    assert code == 2 and "-o" in err and list(tmp_path.iterdir()) == [cam]
    code, _, err = run(capsys, "cam", cam, "--json", "--csv")
    assert code == 2 and "not allowed with argument" in err
    code, out, err = run(capsys, "cam", cam, "-o", "-")
    assert (code, out) == (2, "")
    assert err == "plans cam: command line: -o -: stdout takes the text; give the sheet a file name\n"


def test_a_sheet_that_does_not_fit_says_so_and_writes_nothing(capsys, tmp_path, monkeypatch):
    import drawing.cam_sheet as cs

    monkeypatch.setitem(cs.SIZES, "A3", (2000.0, 900.0, 900.0, 200.0))
    monkeypatch.setattr(cs, "STEPS", (1.0,))
    out = tmp_path / "cam.svg"
    code, stdout, err = run(capsys, "cam", SAMPLE, "--format", "A3", "-o", out)
    assert code == 2 and not out.exists() and stdout == ""
    assert err.startswith(f"plans cam: {SAMPLE}: the cam sheet does not fit on A3, whose frame is "
                          "395 × 287 mm")
    assert err.count("\n") == 1


# ---------------------------------------------------------------------------------------
# hostile files
# ---------------------------------------------------------------------------------------

_values = st.one_of(st.none(), st.booleans(), st.integers(-10, 400), st.floats(allow_nan=True),
                    st.text(max_size=12), st.lists(st.integers(), max_size=3))
_phase = st.fixed_dictionaries({}, optional={"kind": st.sampled_from(["rise", "return", "dwell", "up", 3]),
                                             "angle_deg": _values, "law": st.one_of(
                                                 st.sampled_from(["cosine", "3-4-5", "constant velocity",
                                                                  "parabolic", "sine"]), _values),
                                             "ratio": _values})
_cams = st.fixed_dictionaries({}, optional={
    "cam": st.fixed_dictionaries({}, optional={"sense": _values, "omega": _values, "base_radius": st.one_of(
        st.floats(0.001, 0.2), _values), "rpm": _values}),
    "follower": st.fixed_dictionaries({}, optional={
        "kind": st.one_of(st.sampled_from(["knife-edge", "roller", "flat-faced"]), _values),
        "motion": st.one_of(st.sampled_from(["translating", "oscillating"]), _values),
        "stroke": st.one_of(st.floats(0.001, 0.1), _values), "swing_deg": _values,
        "offset": st.one_of(st.floats(-0.05, 0.05), st.just("best"), _values),
        "roller_radius": st.one_of(st.floats(0.001, 0.03), _values),
        "arm": st.one_of(st.floats(0.01, 0.2), _values),
        "centre_distance": st.one_of(st.floats(0.01, 0.3), _values)}),
    "limits": st.fixed_dictionaries({}, optional={"pressure_rise_deg": _values, "min_radius": _values}),
    "phases": st.one_of(st.lists(_phase, max_size=5), _values),
    "disc": st.fixed_dictionaries({}, optional={"radius": _values, "eccentricity": _values}),
})


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(_cams)
def test_hostile_cam_files_are_refused_in_lines_or_designed(data):
    """Any table read from a cam file is either refused with located lines (InputError), or
    designed, or refused as a profile that cannot be made (ProfileError): never another
    exception, never NaN in a design."""
    try:
        cam = from_dict(data, "fuzz.toml")
    except InputError as exc:
        assert exc.problems and all("\n" not in p for p in exc.problems)
        return
    try:
        d = design(cam)
    except ProfileError as exc:
        assert "\n" not in str(exc)
        return
    assert math.isfinite(d.r0) and all(math.isfinite(e.value) for e in d.pressure.values())


def test_the_committed_sample_sheet_is_the_readmes_command(capsys, tmp_path):
    """samples/cam.svg is what README's command writes, byte for byte."""
    out = tmp_path / "cam.svg"
    code, _, err = run(capsys, "cam", SAMPLE, "--lang", "ru", "-o", out)
    assert code == 0 and err == ""
    assert out.read_bytes() == (ROOT / "samples" / "cam.svg").read_bytes()
