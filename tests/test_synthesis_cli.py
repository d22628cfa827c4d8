"""``plans synth`` as a user runs it: the report, the JSON, the mechanism file that solve,
sheet and forces take unchanged, the note in Russian with decimal commas, the construction
sheet (parsed), and every malformed requirement of ``tests/corpus/synth`` one located line,
exit 2, nothing written."""

from __future__ import annotations

import json
import re
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest
from support import expectations, run

from plans import load
from plans.synthesis import read_file

ROOT = Path(__file__).resolve().parent.parent
CORPUS = ROOT / "tests" / "corpus" / "synth"
SVG = "{http://www.w3.org/2000/svg}"
ROCKER = ["crank-rocker", "K=1.25", "psi_deg=32", "CD=0.29", "BC=0.26"]
SLIDER = ["crank-slider", "K=1.5", "H=0.05", "e=0.02"]

#: loads for each kind's written file: every moving link's mass at its centre, a slider's
#: useful resistance over its working stroke
LOADS = {
    "crank-rocker": {1: "S1", 2: "S2", 3: "S3"},
    "crank-slider": {1: "S1", 2: "S2", 3: "C"},
    "slotted-link": {1: "S1", 3: "S3", 4: "S4", 5: "E"},
}


def loads_of(kind: str) -> str:
    text = "[loads]\ng = 9.81\n"
    for link, centre in LOADS[kind].items():
        text += f'[loads.links.{link}]\nmass = {0.5 * link}\nJ_S = 0.002\ncentre = "{centre}"\n'
    if kind != "crank-rocker":
        text += "[loads.resistance]\nfraction = [0.0, 0.5, 1.0]\nP = [0, 500, 500]\n"
    return text


@pytest.mark.parametrize("path", sorted(CORPUS.glob("*.toml")), ids=lambda p: p.stem)
def test_malformed_requirements(capsys, tmp_path, path):
    out = tmp_path / "mech.toml"
    code, stdout, err = run(capsys, "synth", path, "-o", out, "--svg", tmp_path / "s.svg")
    assert code == 2 and stdout == ""
    lines = err.splitlines()
    want = expectations(path)
    assert "Traceback" not in err and len(lines) == len(want), err
    for line, expected in zip(lines, want, strict=True):
        assert line.startswith(f"plans synth: {path}: ") and line.endswith(expected)
    assert list(tmp_path.iterdir()) == []


@pytest.mark.parametrize(("argv", "says"), [
    (["crank-rocker", "K=abc", "psi_deg=32", "CD=0.29"], 'K: must be a number, got "abc"'),
    (["crank-rocker", "K=1.25", "psi_deg=32", "CD=-1"], "CD: negative length -1 m"),
    (["crank-rock", "K=1.25"], 'kind: unknown kind "crank-rock" — did you mean "crank-rocker"?'),
    (["K=1.25"], "give the kind first"),
    ([], "give the kind"),
    (["crank-slider", "K=1.5", "H=0.05", "e"], 'command line: "e" is not KEY=VALUE'),
    (["crank-rocker", "K=1.25", "psi_deg=32", "CD=0.29", "BC=5"], "BC must lie from 0.07993 m"),
    (["slotted-link", "K=2", "H=0.3", "AB=0.075", "alpha_max_deg=95"],
     "alpha_max_deg: 95° is out of range"),
], ids=["not-a-number", "negative", "kind", "no-kind", "nothing", "not-a-pair", "family", "alpha"])
def test_command_line_mistakes_are_one_line_exit_2(capsys, argv, says):
    code, stdout, err = run(capsys, "synth", *argv)
    assert code == 2 and stdout == ""
    (line,) = err.splitlines()
    assert line.startswith("plans synth: ") and says in line, line


def test_the_report_lists_both_assemblies_and_the_check(capsys):
    code, out, err = run(capsys, "synth", *ROCKER)
    assert code == 0 and err == ""
    assert "θ = 180°·(K − 1)/(K + 1) = 180°·(1.25 − 1)/(1.25 + 1) = 20°" in out
    assert re.search(r"1\*\s+on D's side of C1C2\s+0\.066981\s+0\.26\s+0\.29\s+0\.26101\s+40\.86°", out)
    assert re.search(r"2\s+beyond C1C2 from D\s+0\.066981\s+0\.26\s+0\.29\s+0\.46764\s+27\.2°", out)
    assert "Chosen: 1 (the largest γmin of those listed)" in out
    assert "K = 1.25, θ = 20°, ψ = 32°, γmin = 40.859923°" in out
    assert "Grashof: crank-rocker" in out


def test_the_report_in_russian_has_decimal_commas(capsys):
    code, out, _ = run(capsys, "synth", *ROCKER, "--lang", "ru")
    assert code == 0
    assert "K = 1,25; θ = 20°; ψ = 32°; γmin = 40,859923°" in out
    assert "0,066981" in out and "0.0" not in out


def test_json(capsys, tmp_path):
    code, out, _ = run(capsys, "synth", *SLIDER, "--json", "-o", tmp_path / "m.toml")
    assert code == 0
    got = json.loads(out)
    assert got["kind"] == "crank-slider" and got["given"] == {"K": 1.5, "H": 0.05, "e": 0.02}
    (sol,) = got["solutions"]
    assert sol["lengths"]["AB"] == pytest.approx(0.0215067466596774, rel=1e-12)
    assert sol["figures"]["theta_deg"] == pytest.approx(36.0)
    assert got["check"]["ok"] is True and got["check"]["worst"] <= 1e-12
    rows = {r["name"]: r for r in got["check"]["rows"]}
    assert set(rows) == {"K", "θ", "H", "δmax"}
    assert rows["θ"]["unit"] == "deg" and rows["θ"]["engine"] == pytest.approx(36.0, rel=1e-13)
    assert got["file"] == str(tmp_path / "m.toml")
    assert got["mechanism"]["sliders"][0]["guide"]["through"][1] == pytest.approx(-0.02)


def test_the_family_is_reported_with_its_best(capsys):
    code, out, _ = run(capsys, "synth", "crank-rocker", "K=1.25", "psi_deg=32", "CD=0.29")
    assert code == 0
    assert "Family: γmin(u)" in out
    assert re.search(r"on D's side of C1C2: γmin from [\d.]+° to 44\.02° over u", out)
    code, out, _ = run(capsys, "synth", "crank-rocker", "K=1.25", "psi_deg=32", "CD=0.29", "--json")
    fam = json.loads(out)["family"]
    assert len(fam) == 2 and all(len(f["parameter"]) == len(f["value_deg"]) == 719 for f in fam)


@pytest.mark.parametrize("argv", [ROCKER, SLIDER, ["slotted-link", "K=2", "H=0.3", "AB=0.075"]],
                         ids=["rocker", "slider", "shaper"])
def test_the_written_file_goes_through_solve_sheet_and_forces(capsys, tmp_path, argv):
    spec = tmp_path / "spec.toml"
    lines = [f'kind = "{argv[0]}"', *(w.replace("=", " = ", 1) for w in argv[1:])]
    spec.write_text("\n".join(lines) + "\n" + loads_of(argv[0]), encoding="utf-8")
    mech = tmp_path / "mech.toml"
    code, _, err = run(capsys, "synth", spec, "-o", mech)
    assert code == 0 and err == "", err
    text = mech.read_text("utf-8")
    assert text.startswith("# ") and "# Requirements: " + "; ".join(lines[1:]) in text
    assert "\n[loads.links.1]\n" in text
    m = load(mech)
    assert m.loads is not None
    for command in (["solve", mech], ["sheet", mech, "-o", tmp_path / "s.svg"], ["forces", mech],
                    ["cycle", mech]):
        code, out, err = run(capsys, *command)
        assert code == 0, (command, err)
    code, out, _ = run(capsys, "solve", mech)
    want = argv[1].split("=")[1]
    assert re.search(rf"θ = [\d.]+°, K = {re.escape(want)}\b", out)


def test_without_loads_the_file_says_how_to_add_them(capsys, tmp_path):
    mech = tmp_path / "m.toml"
    assert run(capsys, "synth", *ROCKER, "-o", mech)[0] == 0
    text = mech.read_text("utf-8")
    assert "# For plans forces add [loads] (README: Loads)" in text
    assert not any(line.startswith("[loads") for line in text.splitlines())
    code, _, err = run(capsys, "forces", mech)
    assert code == 2 and "loads: missing" in err


def test_minus_o_prints_the_mechanism_file(capsys):
    code, out, _ = run(capsys, "synth", *SLIDER, "-o", "-")
    assert code == 0 and out.startswith("# Offset crank-slider mechanism: synthesised by")
    assert "[[sliders]]" in out and "Solutions" not in out


def test_the_note_in_russian(capsys, tmp_path):
    note = tmp_path / "note.md"
    code, _, _ = run(capsys, "synth", *ROCKER, "--lang", "ru", "--note", note)
    assert code == 0
    text = note.read_text("utf-8")
    assert text.startswith("## Синтез кривошипно-коромыслового механизма")
    assert "- `θ = 180°·(K − 1)/(K + 1) = 180°·(1,25 − 1)/(1,25 + 1) = 20°`" in text
    assert "- `C1C2 = 2·l_CD·sin(ψ/2) = 2·0,29·sin 16° = 0,1599 м`" in text
    assert "= 0,06698 м`" in text and "= 0,261 м`" in text
    steps = [ln for ln in text.splitlines() if ln.startswith("- `")]
    assert all(not re.search(r"\d\.\d", ln) for ln in steps), [ln for ln in steps if re.search(r"\d\.\d", ln)]


@pytest.mark.parametrize("argv", [ROCKER, SLIDER, ["slotted-link", "K=2", "H=0.3", "AB=0.075"],
                                  ["crank-rocker", "K=1.25", "psi_deg=32", "CD=0.29"]],
                         ids=["rocker", "slider", "shaper", "family"])
def test_the_construction_sheet(capsys, tmp_path, argv):
    svg = tmp_path / "s.svg"
    code, _, err = run(capsys, "synth", *argv, "--svg", svg, "--lang", "ru")
    assert code == 0, err
    root = ET.parse(svg).getroot()
    assert root.get("width") == "420mm"
    layers = {g.get("id") for g in root.iter(f"{SVG}g") if g.get("id", "").startswith("layer-")}
    assert {"layer-frame", "layer-title-block", "layer-views"} <= layers
    texts = ["".join(t.itertext()) for t in root.iter(f"{SVG}text")]
    assert any(t.startswith("Построение, μl = ") for t in texts)
    assert "Результаты синтеза" in texts
    for letter in ("A", "θ"):
        assert letter in texts
    if argv[0] != "slotted-link":
        for letter in ("C1", "C2", "O", "E"):
            assert letter in texts
    if argv[0] == "crank-rocker":
        assert {"D", "ψ", "P", "90° − θ"} <= set(texts)
    if len(argv) == 4 and argv[0] == "crank-rocker":
        assert "Семейство решений" in texts


def test_png_of_the_sheet(capsys, tmp_path):
    pytest.importorskip("cairosvg")
    png = tmp_path / "s.png"
    code, _, err = run(capsys, "synth", *SLIDER, "--png", png, "--dpi", "30")
    assert code == 0, err
    assert png.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_a_synthesis_file_with_command_line_pairs_over_it(tmp_path):
    spec = tmp_path / "s.toml"
    spec.write_text('kind = "crank-rocker"\nK = 1.25\npsi_deg = 32\nCD = "0,29"\n', encoding="utf-8")
    p = read_file(spec, ["BC=0.26"])
    assert p.given["CD"] == 0.29 and p.given["BC"] == 0.26
    assert p.text == ('K = 1.25', 'psi_deg = 32', 'CD = "0,29"', "BC = 0.26")


def test_the_output_is_never_the_input(capsys, tmp_path):
    spec = tmp_path / "s.toml"
    spec.write_text('kind = "crank-slider"\nK = 1.5\nH = 0.05\ne = 0.02\n', encoding="utf-8")
    before = spec.read_text("utf-8")
    code, _, err = run(capsys, "synth", spec, "-o", spec)
    assert code == 2 and "is the input file" in err
    assert spec.read_text("utf-8") == before


def test_solution_option_takes_the_other_assembly(capsys, tmp_path):
    mech = tmp_path / "m.toml"
    code, out, _ = run(capsys, "synth", *ROCKER, "--solution", "2", "-o", mech)
    assert code == 0 and "Chosen: 2 (asked for)" in out
    assert load(mech).frame["D"].real == pytest.approx(0.46764, abs=1e-5)


def test_the_sample_is_what_the_readme_command_writes(capsys, tmp_path):
    """samples/crusher.toml and samples/crusher_synth.svg, regenerated byte for byte by the
    command in README (the PNG is the export's of that SVG)."""
    mech, svg = tmp_path / "crusher.toml", tmp_path / "crusher_synth.svg"
    code, out, err = run(capsys, "synth", "samples/crusher_synth.toml", "-o", mech, "--lang", "ru",
                         "--svg", svg)
    assert code == 0, err
    assert mech.read_text("utf-8") == (ROOT / "samples" / "crusher.toml").read_text("utf-8")
    assert svg.read_text("utf-8") == (ROOT / "samples" / "crusher_synth.svg").read_text("utf-8")
    assert "44,64°" in out
    code, out, err = run(capsys, "forces", ROOT / "samples" / "crusher.toml")
    assert code == 0, err
