"""``plans cycle``: the N positions of the cycle, run in-process as a user would run it."""

import csv
import io
import json
import math
import re

import numpy as np
import pytest
from support import NON_GRASHOF, run

from plans.cycle import analyse_cycle
from plans.kinematics.solver import Solver
from plans.model import from_dict, load
from plans.plan.solution import solve_position
from plans.tolerances import WARN_SINE

PRESS = "samples/press.toml"
FOURBAR = "samples/fourbar.toml"



def test_press_table_has_every_section_and_row(capsys):
    code, out, err = run(capsys, "cycle", PRESS)
    assert code == 0, err
    assert "numbered from the extreme position that starts the working stroke" in out
    sections = [
        "x of points (m)",
        "y of points (m)",
        "|V| of points (m/s)",
        "|a| of points (m/s²)",
        "ω (rad/s) and ε (rad/s²)",
        "Conditioning",
    ]
    for s in sections:
        assert s in out
    cond = out.split("Conditioning")[1].splitlines()[2:]
    rows = [line.split() for line in cond if line.strip() and not line.strip().startswith("QP:")]
    assert [r[0] for r in rows] == [str(i) for i in range(12)]
    assert "  QP: how far a slotted link's block P is from the rocker's pivot Q" in out
    # position 0 is an extreme: the slider, the rocker and its points stand still, and
    # the rounding left there prints as 0, not as 2.9e-14
    v0 = out.split("|V| of points (m/s)")[1].splitlines()[2].split()
    assert v0[:2] == ["0", "109.93"] and v0[3:] == ["0"] * 5
    assert all(r[-1] == "ok" for r in rows)
    assert "stroke of D: H = 0.5114 m" in out
    assert err == ""


def test_press_json_agrees_with_the_plan_of_each_position(capsys):
    code, out, err = run(capsys, "cycle", PRESS, "--json", "--positions", "8")
    assert code == 0, err
    data = json.loads(out)
    mech = load(PRESS)
    solver = Solver(mech)
    cyc = analyse_cycle(mech, n_positions=8, solver=solver)
    assert data["positions"] == 8 and len(data["rows"]) == 8
    assert data["cycle"]["full_turn"] is True
    assert data["link_ids"] == [1, 2, 3, 4, 5]
    assert {"A", "A3", "C", "D", "S3", "S4"} <= set(data["point_names"])
    for row, phi in zip(data["rows"], cyc.positions, strict=True):
        assert row["phi_deg"] == pytest.approx(math.degrees(phi) % 360, abs=1e-9)
        # the file measures φ1 clockwise from +y
        assert row["angle_deg"] == pytest.approx((90 - row["phi_deg"]) % 360, abs=1e-9)
        assert row["solved"] and row["warnings"] == [] and row["errors"] == []
        sol = solve_position(mech, phi, solver=solver)
        scale_v = max(abs(complex(*p["velocity"])) for p in row["points"].values())
        scale_a = max(abs(complex(*p["acceleration"])) for p in row["points"].values())
        for name, p in row["points"].items():
            assert complex(*p["position"]) == pytest.approx(
                sol.positions[name], abs=1e-14
            )
            v = complex(sol.motion.velocity[name][0])
            a = complex(sol.motion.acceleration[name][0])
            assert abs(complex(*p["velocity"]) - v) <= 1e-13 * scale_v
            assert abs(complex(*p["acceleration"]) - a) <= 1e-13 * scale_a
        for lid, w in row["links"].items():
            assert w["omega"] == pytest.approx(
                sol.omega[int(lid)], rel=1e-12, abs=1e-12
            )
            assert w["epsilon"] == pytest.approx(
                sol.epsilon[int(lid)], rel=1e-12, abs=1e-9
            )
        sines = [abs(float(g.velocity.sine[0])) for g in sol.motion.groups]
        assert row["conditioning"]["min_sine"] == pytest.approx(min(sines), rel=1e-12)
    # numbered from an extreme position: the slider D stands still at position 0
    v0 = complex(*data["rows"][0]["points"]["D"]["velocity"])
    assert abs(v0) < 1e-9
    assert data["rows"][0]["output"] == pytest.approx(
        max(r["output"] for r in data["rows"])
    )


def test_csv_carries_the_same_numbers_as_json(capsys):
    _, out_json, _ = run(capsys, "cycle", PRESS, "--json", "--positions", "5")
    code, out_csv, err = run(capsys, "cycle", PRESS, "--csv", "--positions", "5")
    assert code == 0, err
    rows = list(csv.DictReader(io.StringIO(out_csv)))
    data = json.loads(out_json)
    assert len(rows) == 5
    head = rows[0].keys()
    for col in (
        "index",
        "phi_deg",
        "angle_deg",
        "min_sine",
        "group 2–3 (RPR)",
        "group 2–3 (RPR) pivot",
        "group 4–5 (RRP)",
        "D.vx",
        "A3.ay",
        "omega3",
        "epsilon5",
        "warnings",
        "errors",
    ):
        assert col in head
    for r, j in zip(rows, data["rows"], strict=True):
        assert int(r["index"]) == j["index"]
        assert float(r["D.x"]) == j["points"]["D"]["position"][0]
        assert float(r["C.vy"]) == j["points"]["C"]["velocity"][1]
        assert float(r["A3.ax"]) == j["points"]["A3"]["acceleration"][0]
        assert float(r["omega3"]) == j["links"]["3"]["omega"]
        assert float(r["min_sine"]) == j["conditioning"]["min_sine"]


def test_csv_names_the_conditioning_figures_as_json_and_the_sweep_do(capsys):
    """One name for one quantity: each figure of a JSON row's ``conditioning.figures``
    (a group's lines' sine by the group's label, a slotted link's pivot figure by the
    label and " pivot", the keys of ``Sweep.sine`` and ``Sweep.pivot``) is the CSV
    column of that name, with the same value. The CSV had called them "sine group 2–3
    (RPR)" and "pivot group 2–3 (RPR)", so that a script reading both had to translate."""
    _, out_json, _ = run(capsys, "cycle", PRESS, "--json", "--positions", "6")
    code, out_csv, err = run(capsys, "cycle", PRESS, "--csv", "--positions", "6")
    assert code == 0, err
    rows = list(csv.DictReader(io.StringIO(out_csv)))
    data = json.loads(out_json)["rows"]
    keys = list(data[0]["conditioning"]["figures"])
    assert keys == ["group 2–3 (RPR)", "group 2–3 (RPR) pivot", "group 4–5 (RRP)"]
    head = list(rows[0])
    assert head[head.index("min_sine") + 1:head.index("min_sine") + 1 + len(keys)] == keys
    for r, j in zip(rows, data, strict=True):
        for key in keys:
            assert float(r[key]) == j["conditioning"]["figures"][key]
    sw = Solver(load(PRESS)).sweep(np.radians([r["phi_deg"] for r in data]))
    assert set(keys) == set(sw.sine) | set(sw.pivot)


def test_variant_to_a_file(capsys, tmp_path):
    target = tmp_path / "cycle.csv"
    code, out, err = run(
        capsys,
        "cycle",
        "--variant",
        "1",
        "--csv",
        "--positions",
        "24",
        "-o",
        str(target),
    )
    assert code == 0, err
    assert out == ""
    rows = list(csv.DictReader(io.StringIO(target.read_text("utf-8"))))
    assert [int(r["index"]) for r in rows] == list(range(24))
    assert not list(tmp_path.glob(".*.tmp"))


def test_a_linkage_that_cannot_turn_fully_has_its_positions_inside_its_exact_limits(capsys):
    """Seed 001's four-bar folds where |BD| = BC − CD: its limits, by the cosine rule,
    are the extreme positions to 1e-9°; the nine positions are the middles of nine equal
    parts of the range, none of them at a dead point, so none is near-singular (they had
    been the last samples of a 0.1° grid, sin = 0.007, with values that hung on the grid)."""
    code, out, err = run(capsys, "cycle", FOURBAR, "--json", "--positions", "9")
    assert code == 0, err
    data = json.loads(out)
    assert data["cycle"]["full_turn"] is False
    assert "cannot make a full turn" in data["numbering"]
    mech = load(FOURBAR)
    a, ad = mech.driver.length, abs(mech.frame["D"] - mech.frame["A"])
    bc = abs(mech.links[2].points["C"] - mech.links[2].points["B"])
    cd = abs(mech.links[3].points["C"] - mech.links[3].points["D"])
    gamma = math.degrees(math.acos((a * a + ad * ad - (bc - cd) ** 2) / (2 * a * ad)))
    lo, hi = data["cycle"]["crank_range_phi_deg"]
    assert (lo % 360, hi) == pytest.approx((180 + gamma, 180 - gamma), abs=1e-9)
    assert data["cycle"]["extremes_phi_deg"] == data["cycle"]["crank_range_phi_deg"]
    rows = data["rows"]
    span = (hi - lo) % 360
    for k, row in enumerate(rows):
        assert (row["phi_deg"] - lo - (k + 0.5) * span / 9 + 180) % 360 - 180 == pytest.approx(
            0, abs=1e-9)
        assert row["solved"] and row["warnings"] == []
        assert row["conditioning"]["min_sine"] > WARN_SINE
    assert "near-singular" not in err


def test_singular_positions_are_errors_with_no_values(capsys, monkeypatch):
    import plans.tolerances

    # make every position with |sin| < 0.7 count as singular, so the error path runs
    monkeypatch.setattr(plans.tolerances, "SINGULAR_SINE", 0.7)
    monkeypatch.setattr(plans.tolerances, "WARN_SINE", 0.9)
    code, out, err = run(capsys, "cycle", FOURBAR, "--json", "--positions", "9")
    assert code == 2
    rows = json.loads(out)["rows"]
    bad = [r for r in rows if r["errors"]]
    assert bad and len(bad) < len(rows)
    for r in bad:
        assert not r["solved"]
        assert "a singular position" in r["errors"][0]
        assert r["points"]["C"]["velocity"] is None
        assert r["links"]["3"]["omega"] is None
        assert f"error: position {r['index']}:" in err
    code, out, err = run(capsys, "cycle", FOURBAR, "--positions", "9")
    assert code == 2
    assert "—" in out and "error" in out


def test_table_marks_warnings(capsys, monkeypatch):
    import plans.tolerances

    # the five positions' sines are 0.54 at the ends and 0.86 or more between: warn below 0.6
    monkeypatch.setattr(plans.tolerances, "WARN_SINE", 0.6)
    code, out, _ = run(capsys, "cycle", FOURBAR, "--positions", "5")
    assert code == 0
    assert "position 0: warning: group 2–3 (RRR)" in out
    assert "position 4: warning: group 2–3 (RRR)" in out


@pytest.mark.parametrize("n", ["0", "-3", "100001", "1000000"])
def test_positions_out_of_range(capsys, n):
    """Up to 10⁵: a million rows of JSON had needed 24 GB and been killed."""
    code, _, err = run(capsys, "cycle", PRESS, "--positions", n)
    assert code == 2
    assert f"argument --positions: '{n}' is not a whole number from 1 to 100000" in err


def test_json_is_written_row_by_row_as_one_object():
    """The head, then one position per line, then the tail: one JSON object whatever the
    number of rows, each row on its own line."""
    from plans.cli.cycle import json_chunks
    from plans.cycle.table import compute

    for n in (1, 2, 7):
        chunks = list(json_chunks(compute(load(PRESS), n)))
        assert len(chunks) == n + 2  # the head, a row each, the tail
        text = "".join(chunks)
        data = json.loads(text)
        assert list(data) == ["mechanism", "positions", "numbering", "crank_link", "omega1", "cycle",
                              "point_names", "link_ids", "rows"]
        assert data["positions"] == n and [r["index"] for r in data["rows"]] == list(range(n))
        rows = [line for line in text.splitlines() if line.startswith('  {"index": ')]
        assert len(rows) == n


def test_one_position_and_json_is_strict(capsys):
    code, out, err = run(capsys, "cycle", PRESS, "--json", "--positions", "1")
    assert code == 0, err
    data = json.loads(
        out, parse_constant=lambda c: pytest.fail(f"non-JSON constant {c}")
    )
    assert len(data["rows"]) == 1
    assert np.isfinite(data["rows"][0]["conditioning"]["min_sine"])


def _modules_after(tmp_path, runs: list[list[str]], names) -> str:
    """Which of ``names`` (modules, or packages by their first part) a fresh process has
    imported after ``plans.cli.main`` ran each argument list of ``runs`` (each must exit
    0), as the printed sorted list."""
    import subprocess
    import sys
    from pathlib import Path

    root = Path(__file__).resolve().parent.parent
    code = "import sys\nfrom plans.cli import main\n" + "".join(
        f"assert main({run!r}) == 0\n" for run in runs) + (
        f"names = {set(names)!r}\n"
        "print(sorted(m for m in names if m in sys.modules or any(\n"
        "    k.split('.')[0] == m for k in sys.modules)))\n")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         cwd=tmp_path, env={"PYTHONPATH": str(root), "PATH": ""}, check=True)
    return out.stdout.strip()


def test_cycle_pays_for_no_heavy_import(tmp_path):
    """Commands that do not draw load neither plotting, geometry nor symbolic packages."""
    from pathlib import Path

    press = str(Path(__file__).resolve().parent.parent / PRESS)
    runs = [["cycle", press, "--json", "-o", str(tmp_path / "c.json")],
            ["solve", press, "--json", "-o", str(tmp_path / "s.json")]]
    heavy = ("matplotlib", "shapely", "svgwrite", "sympy", "mpmath", "cairosvg", "pylinkage")
    assert _modules_after(tmp_path, runs, heavy) == "[]"


def test_solve_imports_neither_the_other_commands_nor_the_drawing(tmp_path):
    """``plans solve`` is end-to-end time (README: ≤ 0.3 s), most of it imports: it
    configures its own command only, and imports neither the drawing nor a package that
    draws, plots or computes symbolically. (The standard library's modules an engine
    module needs are imported at its top, as any other import: difflib, for a misspelt
    key, costs some 2 ms.)"""
    from pathlib import Path

    press = str(Path(__file__).resolve().parent.parent / PRESS)
    runs = [["solve", press, "--json", "-o", str(tmp_path / "s.json")]]
    unpaid = ("plans.cli.report", "plans.cli.check", "plans.cli.bench", "plans.cli.sheet",
              "plans.cli.check_batch", "drawing", "matplotlib", "shapely",
              "svgwrite", "cairosvg", "sympy", "mpmath")
    assert _modules_after(tmp_path, runs, unpaid) == "[]"


def test_cycle_text_gives_every_crank_angle_in_the_files_convention(capsys):
    """The press measures φ1 clockwise from +y: the extreme positions in the summary are
    in that convention, and position 0, which starts the working stroke, is the first."""
    import re

    code, out, _ = run(capsys, "cycle", PRESS)
    assert code == 0
    mech = load(PRESS)
    c = analyse_cycle(mech, 12)
    (line,) = [ln for ln in out.splitlines() if ln.startswith("extreme positions at φ1 = ")]
    shown = [float(x) for x in re.findall(r"([\d.]+)°", line.split(";")[0])]
    want = [mech.driver.file_angle(x) for x in c.extremes]
    assert shown == pytest.approx(want, abs=0.05)
    assert shown == pytest.approx([109.9, 250.1], abs=0.05)  # 340.1° and 199.9° from +x
    row0 = next(ln for ln in out.splitlines() if re.match(r"\s+0\s", ln))
    assert float(row0.split()[1]) == pytest.approx(shown[0], abs=0.05)


@pytest.mark.parametrize("angle", [0, 180])
def test_an_extreme_on_the_given_angle_is_one_turning_point(angle):
    """The central crank-slider drawn at φ1 = 0 (the textbook's first position): the
    slider's velocity is exactly 0 on the first sample of the cycle's grid. That sample
    counted as two changes of sign, so the cycle had "3 turning points" and no H, θ, K."""
    from plans.model.scenes import SCENES

    text = SCENES["crank_slider_central"].toml.replace("angle_deg = 45", f"angle_deg = {angle}")
    mech = from_dict(__import__("tomllib").loads(text), "<central>")
    cyc = analyse_cycle(mech)
    assert not cyc.notes
    assert cyc.stroke == pytest.approx(0.2, abs=1e-12)  # H = 2R
    assert cyc.theta == 0.0 and cyc.K == 1.0
    # at the dead points, 0° and 180° (to the bisection's 1e-13 rad)
    ends = sorted(round(math.degrees(x) / 180) % 2 for x in cyc.extremes)
    assert ends == [0, 1]
    assert all(abs(math.sin(x)) < 1e-12 for x in cyc.extremes)


def test_a_velocity_that_touches_zero_is_no_turning_point():
    from plans.cycle import rate_signs

    assert rate_signs(np.array([1.0, 0.0, 1.0, -1.0, 0.0, 0.0, -1.0, 0.0])).tolist() == [
        1, 1, 1, -1, -1, -1, -1, 1]
    assert rate_signs(np.zeros(4)).tolist() == [0, 0, 0, 0]


def test_a_cycle_from_an_angle_that_does_not_close_says_why(capsys, tmp_path):
    """The tangent mechanism given at φ1 = 90°, its dead point: the cycle had printed
    "assembles only for φ1 from 90° to 90°, a swing of 0°" and N empty positions."""
    from plans.model.scenes import SCENES

    path = tmp_path / "t.toml"
    path.write_text(SCENES["tangent"].toml.replace("angle_deg = 25", "angle_deg = 90", 1), "utf-8")
    code, out, err = run(capsys, "cycle", path, "--positions", "4")
    assert code == 2 and out == ""
    assert err == (f"plans cycle: {path}: group 2–3 (PRP) at φ1 = 90°: the guides OA and y-y "
                   "are parallel: the hinge C is not fixed: a singular position (dead point), "
                   "the plan has no unique solution\n")


@pytest.mark.parametrize("sense", ["ccw", "cw"])
def test_the_json_crank_range_runs_counter_clockwise(capsys, tmp_path, sense):
    """Seed 001's four-bar assembles counter-clockwise from 231.2° to 128.8° (from +x). With
    the crank turning clockwise the JSON had said [128.8, 231.2]: the arc where it does
    not assemble."""
    from pathlib import Path

    path = tmp_path / "f.toml"
    path.write_text(Path(FOURBAR).read_text("utf-8").replace('sense = "ccw"', f'sense = "{sense}"'),
                    "utf-8")
    _code, out, _ = run(capsys, "cycle", path, "--json", "--positions", "3")
    lo, hi = json.loads(out)["cycle"]["crank_range_phi_deg"]
    assert lo == pytest.approx(231.2, abs=0.1) and hi == pytest.approx(128.8, abs=0.1)


def _output_column(out: str) -> list[float]:
    rows = out.split("Conditioning")[1].splitlines()
    head = next(i for i, line in enumerate(rows) if "ψ_B °" in line)
    return [float(r.split()[2]) for r in rows[head + 1:] if r.strip() and r.split()[0].isdigit()]


def test_an_output_that_turns_fully_reads_its_angle_within_one_turn(capsys, tmp_path):
    """A drag link's output turns with the crank: its ψ column reads within [0°, 360°) as
    φ1 does, where the unwrapped angle reached 480° by position 11."""
    from test_stability import fourbar

    f = tmp_path / "drag.toml"
    f.write_text(fourbar(0.2, 0.25, 0.22, 0.05))  # the frame is the shortest link
    code, out, err = run(capsys, "cycle", str(f))
    assert code == 0, err
    assert "ψ_B: degrees of link 3 from +x, measured ccw" in out
    psi = _output_column(out)
    assert len(psi) == 12 and all(0 <= v < 360 for v in psi)
    assert int(np.sum(np.diff(psi) < 0)) == 1  # it passes 360° once
    code, out, err = run(capsys, "cycle", str(f), "--json")
    data = json.loads(out)
    for row, shown in zip(data["rows"], psi, strict=True):
        c, d = row["points"]["B"]["position"], (0.05, 0.0)
        truth = math.degrees(math.atan2(c[1] - d[1], c[0] - d[0])) % 360
        assert math.degrees(row["output"]) == pytest.approx(truth, abs=1e-9)
        assert shown == pytest.approx(truth, abs=0.06)


def test_a_table_angle_moves_a_swing_by_whole_turns_and_keeps_it_continuous():
    from plans.cycle import table_angle

    swing = np.radians([-170.0, -178.0, -185.0, -190.0, -181.0])  # across ±180°
    got = np.degrees(table_angle(swing, full_turn=True))
    assert got == pytest.approx([190, 182, 175, 170, 179])
    got = np.degrees(table_angle(np.radians([350.0, 365.0, 370.0, 355.0]), full_turn=True))
    assert got == pytest.approx([-10, 5, 10, -5])  # a swing across 0° stays continuous
    ramp = np.radians([150.0, 250.0, 350.0, 450.0, 475.0, np.nan])
    got = np.degrees(table_angle(ramp, full_turn=True))
    assert got[:5] == pytest.approx([150, 250, 350, 90, 115]) and np.isnan(got[5])
    # a crank that rocks never closes a turn: its output's angle is never taken modulo
    assert np.degrees(table_angle(ramp[:5], full_turn=False)) == pytest.approx(
        [150, 250, 350, 450, 475])


@pytest.mark.parametrize("given", ["25", "25.05", "-37.0137"])
def test_parallel_guides_end_the_cranks_range_wherever_the_samples_fall(given):
    """The tangent mechanism's slider runs off to infinity at φ1 = ±90°, where its two
    guides turn parallel. The range was found only where one of the 3600 samples fell
    exactly there (given at 25°); given at 25.05° the cycle ran through infinity as a full
    turn, with y_C = 2.3 m at 85° and −0.43 m at 115°."""
    from plans.model.scenes import SCENES

    toml = SCENES["tangent"].toml.replace("angle_deg = 25", f"angle_deg = {given}", 1)
    mech = from_dict(__import__("tomllib").loads(toml))
    c = analyse_cycle(mech)
    assert not c.full_turn
    # to within 1e-10 rad: a sine under SINGULAR_SINE (1e-10) is parallel, C at 2e9 m
    assert c.ccw_range == pytest.approx((-math.pi / 2, math.pi / 2), abs=2e-10)
    assert any("guides turn parallel" in n for n in c.notes)
    assert all(abs(p) < math.pi / 2 for p in c.positions)


def test_two_moving_guides_limit_the_crank_where_they_turn_parallel():
    from plans.model.scenes import SCENES

    toml = SCENES["prp_two_moving"].toml
    got = []
    for shift in (0.0, 0.05, 0.0137):
        mech = from_dict(__import__("tomllib").loads(toml))
        mech = from_dict(__import__("tomllib").loads(toml.replace(
            f"angle_deg = {math.degrees(mech.driver.phi):g}",
            f"angle_deg = {math.degrees(mech.driver.phi) + shift:g}", 1)))
        c = analyse_cycle(mech)
        assert not c.full_turn
        lo, hi = c.ccw_range
        m = Solver(mech).solve(np.array([lo, hi]))
        prp = [g for g in m.groups if g.group.kind.name == "PRP"]
        assert len(prp) == 1 and np.all(np.abs(prp[0].velocity.sine) < 1e-9)
        got.append((lo, hi))
    assert got[1] == pytest.approx(got[0], abs=1e-12) and got[2] == pytest.approx(got[0], abs=1e-12)


def test_a_sine_is_never_above_one(capsys, tmp_path):
    """The cross product of two unit vectors as rounded reaches 1 + 4e-16: the CSV's sine
    of the oscillating slotted link read 1.0000000000000004, as did the sweep's."""
    from plans.model.scenes import SCENES

    path = tmp_path / "s.toml"
    path.write_text(SCENES["slotted_oscillating"].toml, "utf-8")
    code, out, err = run(capsys, "cycle", path, "--csv", "--positions", "360")
    assert code == 0, err
    rows = list(csv.reader(io.StringIO(out)))
    cols = [i for i, h in enumerate(rows[0]) if h == "min_sine"
            or (h.startswith("group ") and not h.endswith(" pivot"))]
    assert [rows[0][i] for i in cols] == ["min_sine", "group 2–3 (RPR)"]
    sines = [float(r[i]) for r in rows[1:] for i in cols if r[i]]
    assert max(sines) == 1.0 and min(sines) >= 0.0
    code, out, _ = run(capsys, "cycle", path, "--json", "--positions", "360")
    figures = [v for r in json.loads(out)["rows"] for v in r["conditioning"]["figures"].values()]
    assert max(figures) == 1.0
    mech = from_dict(__import__("tomllib").loads(SCENES["slotted_oscillating"].toml))
    sw = Solver(mech).sweep(np.radians(np.arange(0.0, 360.0, 1.0)))
    assert max(float(s.max()) for s in sw.sine.values()) == 1.0
    assert max(Solver(mech).solve_one(math.radians(a)).groups[0].sine_at() for a in range(360)) == 1.0


def test_json_and_csv_never_write_a_negative_zero(capsys, tmp_path):
    """A crank-slider whose rod is as long as its crank, at 0°: ε of the rod worked out
    as −0.0, and solve --json, cycle --json and --csv wrote "epsilon": -0.0 (and -0.0 in
    its column), where the text writes 0."""
    from plans.model.scenes import SCENES

    path = tmp_path / "s.toml"
    path.write_text(SCENES["crank_slider_central"].toml.replace("B = 0.4", "B = 0.1"), "utf-8")
    negative_zero = re.compile(r"(?<![\w.])-0\.0(?![\d.eE])")
    for argv in (("solve", "--json"), ("cycle", "--json"), ("cycle", "--csv")):
        code, out, err = run(capsys, argv[0], path, "--angle", "0", *argv[1:])
        assert code == 0, err
        assert not negative_zero.findall(out), argv


def test_an_extreme_position_a_rounding_short_of_a_full_turn_reads_zero(capsys, tmp_path):
    """The crank-slider whose rod is as long as its crank has its extreme at 0°, found at
    359.99999999999855°: the table printed 360.00."""
    from plans.model.scenes import SCENES

    path = tmp_path / "eq.toml"
    text = SCENES["crank_slider_central"].toml
    equal = (text.replace("angle_deg = 45", "angle_deg = 30").replace("omega = 12", "omega = 10")
             .replace("points = { B = 0.4 }", "points = { B = 0.1 }")
             .replace('B = "right of O"', 'B = "right of A"'))
    assert equal.count("0.1") == 2 and '"right of A"' in equal
    path.write_text(equal, "utf-8")
    code, out, _ = run(capsys, "cycle", path)
    assert code == 0 and "extreme positions at φ1 = 180°, 0°" in out
    rows = out.split("x of points (m)")[1].splitlines()[2:14]
    assert [r.split()[1] for r in rows] == [f"{a:.2f}" for a in (
        180, 210, 240, 270, 300, 330, 0, 30, 60, 90, 120, 150)]
    assert "360.00" not in out




def _non_grashof(tmp_path, angle, name="ng.toml"):
    path = tmp_path / name
    path.write_text(NON_GRASHOF.format(angle=angle), "utf-8")
    return path


def test_an_angle_beside_a_range_through_zero_is_written_as_the_range(capsys, tmp_path):
    """--angle -99.7, inside −99.72°…99.72°, was echoed as φ1 = 260.3° beside that range,
    and the cycle's positions read 268.59 … 351.69, 8.31 … 91.41."""
    path = _non_grashof(tmp_path, 90)
    code, out, err = run(capsys, "solve", path, "--angle", "-99.7")
    assert code == 0
    assert ", φ1 = −99.7° from +x, ω1 = 5 rad/s ccw" in out
    assert "from −99.72° to 99.72°" in out
    assert err.startswith("plans solve: warning: group 2–3 (RRR) at φ1 = −99.7°: near-singular")
    code, out, err = run(capsys, "report", path, "--angle", "-99.7", "--lang", "ru")
    assert "группа 2–3 (RRR) при φ1 = −99,7°" in out
    code, out, err = run(capsys, "solve", path, "--angle", "-99.8")
    assert code == 2 and "cannot be assembled at φ1 = −99.8°:" in err
    code, out, _ = run(capsys, "cycle", path)
    rows = out.split("x of points (m)")[1].splitlines()[2:14]
    assert [r.split()[1] for r in rows] == [
        "-91.41", "-74.79", "-58.17", "-41.55", "-24.93", "-8.31",
        "8.31", "24.93", "41.55", "58.17", "74.79", "91.41"]


def test_a_cycle_given_outside_the_cranks_range_runs_over_the_range(capsys, tmp_path):
    """A four-bar that assembles for φ1 from −99.72° to 99.72° only, given at 150°: the
    cycle had refused to run although it found that range itself. It runs over it, as the
    same file given at 90° does, and says once on stderr why."""
    path = _non_grashof(tmp_path, 150)
    code, out, err = run(capsys, "cycle", path)
    assert code == 0
    assert err == (f"plans cycle: warning: {path}: driver.angle_deg = 150 is outside the "
                   "crank's range, φ1 from −99.72° to 99.72°: the cycle runs over that range, "
                   "assembled as the hints ask at φ1 = 0°\n")
    code, same, err = run(capsys, "cycle", _non_grashof(tmp_path, 90, "ng90.toml"))
    assert code == 0 and err == "" and out == same
    code, out, err = run(capsys, "cycle", path, "--json", "--positions", "3")
    assert code == 0 and err.count("\n") == 1
    lo, hi = json.loads(out)["cycle"]["crank_range_phi_deg"]
    assert lo == pytest.approx(260.28, abs=0.01) and hi == pytest.approx(99.72, abs=0.01)
    # --angle beyond the range of a file whose own angle closes: its hints hold there
    code, out, err = run(capsys, "cycle", _non_grashof(tmp_path, 90, "ng90.toml"), "--angle", "-99.8")
    assert code == 0 and out == same
    assert err.endswith(": --angle -99.8 is outside the crank's range, φ1 from −99.72° to "
                        "99.72°: the cycle runs over that range\n")


@pytest.mark.parametrize("command", ["solve", "report", "sheet"])
def test_a_position_outside_the_cranks_range_names_the_field_and_the_range(
        capsys, tmp_path, command):
    """solve, report and sheet need the file's own angle: each refuses it in one line that
    names driver.angle_deg and the range where the mechanism assembles."""
    path = _non_grashof(tmp_path, 150)
    svg = tmp_path / "s.svg"
    code, out, err = run(capsys, command, path, *(["-o", svg] if command == "sheet" else []))
    assert code == 2 and out == "" and not svg.exists()
    assert err == (f"plans {command}: {path}: driver.angle_deg = 150 is outside the crank's "
                   "range, φ1 from −99.72° to 99.72°, where the mechanism assembles: group 2–3 "
                   "(RRR) cannot be assembled at φ1 = 150°: needs BD within [0.05, 0.25] m, "
                   "misses by 0.059789 m\n")


def test_the_range_and_the_angle_are_in_the_files_convention(capsys, tmp_path):
    path = tmp_path / "y.toml"
    path.write_text(NON_GRASHOF.format(angle=250).replace(
        "omega = 5", 'omega = 5\nfrom = "+y"\nmeasured = "cw"'), "utf-8")
    code, _, err = run(capsys, "solve", path)
    assert code == 2
    assert err.startswith(f"plans solve: {path}: driver.angle_deg = 250 is outside the crank's "
                          "range, φ1 from −9.715° to 189.7° (from +y, cw), where the mechanism "
                          "assembles: group 2–3 (RRR) cannot be assembled at φ1 = 250° (from +y, "
                          "cw): needs BD")


@pytest.mark.parametrize("angle", ["20", "100", "200", "300"])
def test_the_extreme_that_starts_the_working_stroke_comes_first(capsys, angle):
    """The two extremes were listed in the order the crank met them from the angle asked
    for: the press gave [199.93, 340.07] at 20° and [340.07, 199.93] at 200°, so a program
    reading item 0 as the working stroke's start was right at one angle and wrong at the
    other. Item 0 is now position 0's angle, the working stroke's start, at any angle."""
    code, out, _ = run(capsys, "cycle", PRESS, "--positions", "4", "--angle", angle, "--json")
    data = json.loads(out)
    first, second = data["cycle"]["extremes_phi_deg"]
    assert code == 0 and data["rows"][0]["phi_deg"] == pytest.approx(first, abs=1e-9)
    assert (first, second) == pytest.approx((340.0677295277987, 199.93227047220137), abs=1e-9)


def test_csv_converts_its_rows_a_stretch_at_a_time():
    """The CSV of 10⁵ rows took some 430 MB where the JSON took 200: it turned every
    column into Python floats before writing the first row (65 columns of the press,
    about 2 kB a row). It converts each stretch of rows as it writes it now; the CSV is
    the same, row for row."""
    import tracemalloc

    from plans.cli.cycle import csv_chunks
    from plans.cycle.table import compute

    t = compute(load(PRESS), 6000)
    whole = "".join(csv_chunks(t, rows=6000))
    tracemalloc.start()
    try:
        text = []
        for chunk in csv_chunks(t, rows=100):
            text.append(len(chunk))
        _, peak = tracemalloc.get_traced_memory()
    finally:
        tracemalloc.stop()
    assert peak < 3e6  # the whole table's floats alone were 12 MB; a stretch's text 0.4
    assert sum(text) == len(whole)
    assert "".join(csv_chunks(t, rows=7)) == whole
    rows = list(csv.reader(io.StringIO(whole)))
    assert len(rows) == 6001 and rows[1][0] == "0" and rows[-1][0] == "5999"


# ---------------------------------------------------------------------------------------
# --plot: the curves over the cycle, drawn by drawing.chart.cycle_chart
# ---------------------------------------------------------------------------------------


def _plot_spy(monkeypatch, fail: bool = False) -> list:
    """What plans cycle hands drawing.chart.cycle_chart, one dict a call; answered with
    bytes that name the format (or an error, with ``fail``)."""
    from drawing import chart

    calls = []

    def spy(angle_deg, panels, *, title, x_label, fmt):
        calls.append({"angle": list(angle_deg), "panels": panels, "title": title,
                      "x_label": x_label, "fmt": fmt})
        if fail:
            raise RuntimeError("the plot could not be drawn")
        return f"<{fmt} plot>".encode()

    monkeypatch.setattr(chart, "cycle_chart", spy, raising=False)
    return calls


@pytest.mark.parametrize("fmt", ["png", "svg", "pdf"])
def test_plot_draws_the_outputs_s_v_a_and_every_links_omega_epsilon(capsys, monkeypatch,
                                                                    tmp_path, fmt):
    """The press's slider D: s, V and a along its guide, then ω and ε of every link, over
    the crank angle turned from position 0, the very values of the JSON table."""
    calls = _plot_spy(monkeypatch)
    plot, table = tmp_path / f"press.{fmt}", tmp_path / "press.json"
    code, _, err = run(capsys, "cycle", PRESS, "--positions", "24", "--json", "-o", table,
                       "--plot", plot)
    assert code == 0, err
    assert plot.read_bytes() == f"<{fmt} plot>".encode()
    ((call,),) = [calls]
    assert call["fmt"] == fmt and call["title"] == load(PRESS).name
    assert call["x_label"] == "φ1, degrees turned from position 0"
    assert call["angle"] == pytest.approx([15.0 * k for k in range(24)])
    data = json.loads(table.read_text("utf-8"))
    labels = [label for label, _ in call["panels"]]
    links = data["link_ids"]
    assert labels == ["s_D, m", "V_D, m/s", "a_D, m/s²", "ω, rad/s", "ε, rad/s²"]
    series = {name: values for _, lines in call["panels"] for name, values in lines}
    assert list(series) == ["s_D", "V_D", "a_D", *(f"ω{i}" for i in links),
                            *(f"ε{i}" for i in links)]
    rows = data["rows"]
    assert series["s_D"] == pytest.approx([r["output"] for r in rows], abs=1e-15)
    # the slider moves along its guide: its speed is the size of its velocity
    assert np.abs(series["V_D"]) == pytest.approx(
        [math.hypot(*r["points"]["D"]["velocity"]) for r in rows], rel=1e-12, abs=1e-12)
    assert np.abs(series["a_D"]) == pytest.approx(
        [math.hypot(*r["points"]["D"]["acceleration"]) for r in rows], rel=1e-12, abs=1e-12)
    for i in links:
        assert series[f"ω{i}"] == pytest.approx([r["links"][str(i)]["omega"] for r in rows])
        assert series[f"ε{i}"] == pytest.approx([r["links"][str(i)]["epsilon"] for r in rows])


def test_plot_of_a_rocker_draws_its_angle_in_degrees(capsys, monkeypatch, tmp_path):
    calls = _plot_spy(monkeypatch)
    code, out, err = run(capsys, "cycle", FOURBAR, "--json", "--plot", tmp_path / "f.svg")
    assert code == 0, err
    data = json.loads(out)
    o = data["cycle"]["output"]
    assert o["kind"] == "angular"
    (call,) = calls
    labels = [label for label, _ in call["panels"]]
    assert labels[:3] == [f"ψ_{o['point']}, °", f"ω{o['link']}, rad/s", f"ε{o['link']}, rad/s²"]
    psi = call["panels"][0][1][0][1]
    assert psi == pytest.approx([math.degrees(r["output"]) for r in data["rows"]])
    # a crank that cannot make a full turn: its positions span its range, from 0 upwards
    assert call["angle"][0] == 0.0 and np.all(np.diff(call["angle"]) > 0)
    assert call["angle"][-1] < 360.0


def test_plot_leaves_the_values_of_a_singular_position_out(capsys, monkeypatch, tmp_path):
    import plans.tolerances

    monkeypatch.setattr(plans.tolerances, "SINGULAR_SINE", 0.7)
    monkeypatch.setattr(plans.tolerances, "WARN_SINE", 0.9)
    calls = _plot_spy(monkeypatch)
    code, out, _ = run(capsys, "cycle", FOURBAR, "--json", "--positions", "9",
                       "--plot", tmp_path / "f.png")
    assert code == 2 and (tmp_path / "f.png").exists()  # everything else is written
    rows = json.loads(out)["rows"]
    omega = {name: values for _, lines in calls[0]["panels"] for name, values in lines}["ω2"]
    assert any(not r["solved"] for r in rows)
    for r, w in zip(rows, omega, strict=True):
        assert math.isnan(w) if not r["solved"] else w == pytest.approx(r["links"]["2"]["omega"])


@pytest.mark.parametrize(("name", "says"), [
    ("curves.jpg", "--plot {p}: the name must end in .png, .svg or .pdf (--plot writes PNG, "
                   "SVG or PDF, as the name ends)"),
    ("link.png", "--plot '{p}' is the input file"),  # a link to the mechanism file
])
def test_plot_names_are_refused_before_anything_is_computed(capsys, monkeypatch, tmp_path,
                                                             name, says):
    import shutil

    import plans.cli.cycle

    calls = _plot_spy(monkeypatch)

    def never(*_):
        raise AssertionError("computed before the plot's name was checked")

    monkeypatch.setattr(plans.cli.cycle, "compute", never)
    press = tmp_path / "press.toml"
    shutil.copy(PRESS, press)
    before = press.read_bytes()
    plot = tmp_path / name
    if name == "link.png":
        plot.symlink_to(press)
    code, out, err = run(capsys, "cycle", press, "--plot", plot)
    assert code == 2 and out == "" and not calls
    assert err.startswith("plans cycle: command line: " + says.format(p=plot))
    assert press.read_bytes() == before and not (tmp_path / "curves.jpg").exists()


def test_plot_and_table_are_written_both_or_neither(capsys, monkeypatch, tmp_path):
    """A plot that cannot be drawn leaves the table's file as it was: all outputs or none."""
    _plot_spy(monkeypatch, fail=True)
    table = tmp_path / "t.csv"
    table.write_text("KEEP")
    code, _, err = run(capsys, "cycle", PRESS, "--csv", "-o", table, "--plot", tmp_path / "p.png")
    assert code == 3 and "the plot could not be drawn" in err
    assert table.read_text() == "KEEP" and not (tmp_path / "p.png").exists()
    code, _, err = run(capsys, "cycle", PRESS, "-o", tmp_path / "same.png", "--plot",
                       tmp_path / "same.png")
    assert code == 2 and "-o and --plot are both" in err
