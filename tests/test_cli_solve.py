"""The solve and report commands, run in-process as a user would run them."""

import json
import math
import re
from pathlib import Path

import pytest
from support import NON_GRASHOF, run

from plans.fmt import num
from plans.model.variants import variant

ROOT = Path(__file__).resolve().parent.parent


@pytest.mark.parametrize("n", range(10))
def test_solve_variant_json_shape(capsys, n):
    code, out, err = run(capsys, "solve", "--variant", str(n), "--json")
    assert code == 0, err
    data = json.loads(out)
    assert set(data) >= {"points", "links", "scales", "segments", "structure"}
    names = {"A", "B", "C", "S1", "S2"} | ({"D", "E", "S3"} if n % 2 else {"S3"})
    assert names <= set(data["points"])
    for p in data["points"].values():
        assert set(p) == {"position", "velocity", "acceleration"}
        assert all(len(p[k]) == 2 for k in p)
    assert set(data["links"]) == {"1", "2", "3"}
    assert data["structure"]["W"] == 1
    kind = "RRR" if n % 2 else "RRP"
    assert data["structure"]["groups"] == [{"links": [2, 3], "kind": kind}]
    assert set(data["scales"]) == {"mu_l", "mu_v", "mu_a"}
    # the crank speed is ω1·l_AB, as in the table
    import math

    from plans.model.variants import load_table

    row = load_table()[1][n]
    vb = math.hypot(*data["points"]["B"]["velocity"])
    assert vb == pytest.approx(math.pi * row["rpm"] / 30 * row["AB"], rel=1e-12)


def test_solve_press_json_includes_coincident_point(capsys):
    code, out, _ = run(capsys, "solve", "samples/press.toml", "--json")
    data = json.loads(out)
    assert code == 0
    a3 = data["points"]["A3"]
    assert a3["position"] == data["points"]["A"]["position"]
    assert math_hypot(a3["velocity"]) == pytest.approx(2.7716, rel=1e-4)
    assert data["links"]["3"]["omega"] == pytest.approx(4.8217, rel=1e-4)
    assert data["scales"] == {"mu_l": 0.01, "mu_v": 0.05, "mu_a": 1.0}
    assert data["segments"]["pa"] == pytest.approx(60)


def test_solve_json_keeps_each_plans_segments_apart(capsys, tmp_path):
    """On a Scotch yoke the relative vector aa3 is drawn on both plans: V_A3A on the
    velocity plan, a^r_A3A on the acceleration plan. Each plan's table keeps its own."""
    from plans.model.scenes import SCENES
    from plans.plan.solution import solve_position

    scene = SCENES["scotch_yoke"]
    path = tmp_path / "yoke.toml"
    path.write_text(scene.toml, encoding="utf-8")
    code, out, err = run(capsys, "solve", str(path), "--json")
    assert code == 0, err
    plans = json.loads(out)["plans"]
    sol = solve_position(scene.mechanism())
    v, a = plans["velocity"]["segments"]["aa3"], plans["acceleration"]["segments"]["aa3"]
    assert v == pytest.approx(sol.velocity.mm("a", "a3"), rel=1e-12)
    assert a == pytest.approx(sol.acceleration.mm("a", "a3"), rel=1e-12)
    assert v != pytest.approx(a, rel=1e-3)
    assert (plans["velocity"]["pole"], plans["acceleration"]["pole"]) == ("p", "π")
    assert plans["velocity"]["mu"] == sol.mu_v and plans["acceleration"]["unit"] == "m/s²"


def math_hypot(v):
    import math

    return math.hypot(*v)


def test_solve_angle_option_moves_the_crank(capsys):
    _, out0, _ = run(capsys, "solve", "samples/press.toml", "--json")
    _, out1, _ = run(capsys, "solve", "samples/press.toml", "--json", "--angle", "40")
    a0 = json.loads(out0)["points"]["A"]["position"]
    a1 = json.loads(out1)["points"]["A"]["position"]
    # 40° clockwise from +y is 50° from +x
    import math

    assert a1 == pytest.approx([0.15 * math.cos(math.radians(50)), 0.15 * math.sin(math.radians(50))])
    assert a0 != a1


def test_solve_text_table(capsys):
    code, out, _ = run(capsys, "solve", "samples/fourbar.toml")
    assert code == 0
    assert "II1(2,3)" in out
    assert "double rocker (non-Grashof: 0.2725 > 0.2375)" in out
    assert "cannot make a full turn" in out


def test_unreachable_angle_is_reported_not_nan(capsys):
    code, out, err = run(capsys, "solve", "samples/fourbar.toml", "--angle", "180")
    assert code == 2
    assert out == ""
    assert err.startswith(
        "plans solve: samples/fourbar.toml: --angle 180 is outside the crank's range, φ1 from "
        "−128.8° to 128.8°, where the mechanism assembles: group 2–3 (RRR) cannot be "
        "assembled at φ1 = 180°")
    assert err.count("\n") == 1 and "nan" not in err.lower()


def test_unreachable_variant_position_names_the_variant(capsys, tmp_path):
    """A four-bar of a course's table that cannot turn fully (AB + AD = 0.25 > BC + CD
    = 0.22), at the crank angles where it does not close: the message names the variant."""
    table = tmp_path / "table.toml"
    table.write_text(
        "[[variant]]\nn = 1\nAB = 0.12\nBC = 0.11\nCD = 0.11\nAD = 0.13\nphi_deg = 0\nrpm = 60\n",
        encoding="utf-8")
    failed = []
    for angle in range(0, 360, 10):
        code, out, err = run(capsys, "solve", "--variant", "1", "--table", str(table),
                             "--angle", str(angle))
        if code == 2:
            failed.append(angle)
            assert out == "" and err.count("\n") == 1
            assert err.startswith(
                f"plans solve: {table}, variant 1: --angle {angle} is outside the crank's "
                "range, φ1 from ")
            assert ", where the mechanism assembles: group 2–3 (RRR) cannot be assembled" in err
    assert 0 < len(failed) < 36  # it closes over part of the turn only


def test_report_russian_uses_decimal_comma(capsys):
    code, out, _ = run(capsys, "report", "samples/press.toml", "--lang", "ru")
    assert code == 0
    assert "`a^k_A3A = 2·ω3·V_A3A = 2·4,8217·1,1482 = 11,073 м/с²`" in out
    assert "`μv = 0,05 (м/с)/мм`\n- `pa = V_A / μv = 3 / 0,05 = 60 мм`" in out  # μv taken, then pa
    assert "`pc = pa3·BC / BA3 = 55,432·75 / 57,482 = 72,325 мм`" in out
    assert "`πc = πa3·BC / BA3 = 17,888·75 / 57,482 = 23,339 мм`" in out  # b is π: no point b
    assert "bc =" not in out


@pytest.mark.parametrize("path", ["samples/press.toml", "samples/fourbar.toml"])
def test_no_number_in_a_russian_note_has_a_decimal_point(capsys, path):
    """Every number of the Russian note, π in ω1 = π·n1/30 included, has a decimal comma."""
    import re

    code, out, _ = run(capsys, "report", path, "--lang", "ru")
    assert code == 0
    assert re.findall(r"\d\.\d", out) == []
    if "fourbar" in path:  # its file gives n1 in rpm, the press ω1
        assert "`ω1 = π·n1 / 30 = 3,1415927·149,2 / 30 = 15,62419 рад/с`" in out


def test_report_english(capsys):
    code, out, _ = run(capsys, "report", "samples/press.toml")
    assert code == 0
    assert "`a^n_A3B = V_A3B² / l_A3B = 2.7716² / 0.57482 = 13.364 m/s²`" in out
    assert "`ε3 = a^t_A3B / l_A3B = 11.891 / 0.57482 = 20.686 rad/s², counter-clockwise`" in out
    assert "Through point k draw a line ∥ BC and through point n1 a line ⊥ BA3; they meet at point a3." in out


def test_russian_note_says_the_crank_range_in_russian(capsys):
    code, out, _ = run(capsys, "report", "samples/fourbar.toml", "--lang", "ru")
    assert code == 0
    assert ("Начальное звено 1 не может сделать полный оборот (это коромысло, а не кривошип): "
            "механизм собирается только при φ1 от −128,8° до 128,8°, угол качания 257,6°.") in out
    assert "кривошипа" not in out.split("## 4.")[1]  # the input link is not called a crank
    assert "cannot" not in out


@pytest.mark.parametrize(("edit", "words"), [
    ({}, "from −128.8° to 128.8°"),
    ({'sense = "ccw"': 'sense = "cw"'}, "from −128.8° to 128.8°"),
    ({"angle_deg = 40": 'angle_deg = 50\nfrom = "+y"\nmeasured = "cw"'}, "from −38.8° to 218.8°"),
    ({"angle_deg = 40": 'angle_deg = 50\nfrom = "+y"\nmeasured = "cw"',
      'sense = "ccw"': 'sense = "cw"'}, "from −38.8° to 218.8°"),
])
def test_the_crank_range_reads_upwards_in_the_files_convention(capsys, tmp_path, edit, words):
    """Seed 001's four-bar assembles over −128.8°…128.8° from +x. With the crank turning
    clockwise the range had been worded in the crank's order, "from 128.8° to 231.2°":
    read as the convention counts, exactly the angles where it does not assemble."""
    text = Path("samples/fourbar.toml").read_text("utf-8")
    for a, b in edit.items():
        assert a in text
        text = text.replace(a, b)
    path = tmp_path / "f.toml"
    path.write_text(text, "utf-8")
    # the note and solve say the convention they are in, where it is not the usual one
    conv = " (from +y, cw)" if "+y" in text else ""
    code, out, _ = run(capsys, "report", path)
    assert code == 0 and f"assembles only for φ1 {words}{conv}, a swing of 257.6°" in out
    code, out, _ = run(capsys, "solve", path)
    assert f"assembles only for φ1 {words}{conv}, a swing of 257.6°" in out


def test_an_angle_that_rounds_to_360_is_written_0(capsys):
    """At the header's six digits 359.9999999 rounds to 360: it is written 0; 359.99 is
    written as typed."""
    code, out, _ = run(capsys, "solve", "--variant", "1", "--angle", "359.9999999")
    assert code == 0
    assert "φ1 = 0° from +x" in out and "360°" not in out
    code, out, _ = run(capsys, "solve", "--variant", "1", "--angle", "359.99")
    assert code == 0 and "φ1 = 359.99° from +x" in out


def test_the_russian_note_reads_as_a_teacher_wants(capsys):
    """θ is given before K, with degree signs in K's substitution; the stroke is the
    segment between the extreme positions times μl; no step ends in a space inside its
    code span; the Chebyshev line's quantities take a dash."""
    code, out, _ = run(capsys, "report", "samples/press.toml", "--lang", "ru")
    assert code == 0
    assert ("- `θ = (φ_рх − φ_хх) / 2 = (219,865° − 140,135°) / 2 = 39,86°`\n"
            "- `K = (180° + θ) / (180° − θ) = (180° + 39,86°) / (180° − 39,86°) = 1,569`") in out
    assert "- `H = D′D″·μl = 51,136·0,01 = 0,5114 м`" in out
    assert "(n = 5 — число подвижных звеньев, p5 = 7 — число одноподвижных пар" in out
    assert not re.search(r" `$", out, re.M)  # no "= 1,569 `" at a line's end
    code, out, _ = run(capsys, "report", "--variant", "1", "--lang", "ru")
    assert "- `ψ = " in out and "° `" not in out and " °`" not in out


def test_the_english_note_uses_western_textbooks_terms(capsys):
    """A Western course knows the mobility formula as Gruebler's (Kutzbach's), the
    class-II groups as dyads and the similarity step as the velocity (acceleration)
    image; "Chebyshev's formula" and "the similarity theorem" were Russian terms in
    English words. The Russian note keeps its own."""
    code, out, _ = run(capsys, "report", "samples/press.toml", "--lang", "en")
    assert code == 0
    assert "Degrees of freedom (mobility) by the Chebyshev–Grübler–Kutzbach formula:" in out
    assert "- links 2 and 3: kind 3 (RPR dyad)" in out
    assert "By the velocity image (the image of a link is similar to the link):" in out
    assert "By the acceleration image (the image of a link is similar to the link):" in out
    assert "similarity theorem" not in out and "Chebyshev's" not in out
    code, out, _ = run(capsys, "report", "samples/press.toml", "--lang", "ru")
    assert "По теореме подобия:" in out and "формуле П. Л. Чебышева" in out


def test_the_english_note_names_the_plan_points_it_draws_through(capsys):
    """"Through a draw a line ∥ BC" read as the article a: the plan point's letter is
    now called a point, as on the Russian note («через точку a»)."""
    code, out, _ = run(capsys, "report", "samples/press.toml", "--lang", "en")
    assert code == 0 and "Through point a draw a line ∥ BC" in out
    assert not re.search(r"Through [a-zπ]\w* draw", out)


def test_a_point_on_another_point_gets_no_segment_of_zero_length(capsys):
    """The slider's centre of mass S3 is at C: 'CS3 = 0 / 0,002 = 0 мм' said nothing."""
    code, out, _ = run(capsys, "report", "--variant", "0", "--lang", "ru")
    assert code == 0 and "CS3" not in out and "= 0 мм" not in out


def test_the_note_finds_every_point_of_the_input_link_it_uses(capsys, tmp_path):
    """The tangent mechanism's line through c1 and the four-bar's centre of mass S1 were
    used or listed but never found in the note. Now the similarity theorem finds them on
    the input link: V_S1 = ω1·l_AS1 exactly, a_S1 = ω1²·l_AS1 (ω1 constant)."""
    import math

    from plans.model.scenes import SCENES

    _, out, _ = run(capsys, "report", "samples/fourbar.toml", "--lang", "ru")
    w1 = 149.2 * math.pi / 30
    v, a = w1 * 0.03125, w1 * w1 * 0.03125
    assert f"- `V_S1 = ps1·μv = 24,413·0,02 = {v:.4f} м/с`".replace(".", ",") in out
    assert "a_S1 = πs1·μa = " in out and f"= {a:.4f} м/с²`".replace(".", ",") in out
    path = tmp_path / "tangent.toml"
    path.write_text(SCENES["tangent"].toml, "utf-8")
    _code, out, _ = run(capsys, "report", path, "--lang", "ru")
    velocity = out.split("## 4.")[1].split("## 5.")[0]
    assert velocity.index("- `pc1 = pa·OC1 / OA = ") < velocity.index("Через точку c1")
    assert "- `V_C1 = pc1·μv = " in velocity


@pytest.mark.parametrize("lang", ["ru", "en"])
def test_the_note_explains_translating_links_sliding_links_and_its_own_guide_names(capsys, tmp_path, lang):
    """A Scotch yoke's link 3 translates: one velocity for all its points (the output D
    was never given, and a degenerate 'triangle a3de' stood for it), and no Coriolis term,
    with the reason. A link sliding on a turning one turns with it (ω5 = ω3 was used,
    never said). A guide the tool names x3-x3 is said to be link 3's slot."""
    from plans.model.scenes import SCENES
    from plans.plan.solution import solve_position

    def note_of(name):
        path = tmp_path / f"{name}.toml"
        path.write_text(SCENES[name].toml, "utf-8")
        code, out, _ = run(capsys, "report", path, "--lang", lang)
        assert code == 0
        return out

    out = note_of("scotch_yoke")
    sol = solve_position(SCENES["scotch_yoke"].mechanism())
    v_d = abs(sol.velocity.value("d"))
    assert v_d == pytest.approx(abs(sol.velocity.value("a3")), rel=1e-12)  # one velocity
    assert "△a3de" not in out
    if lang == "ru":
        assert ("Звено 3 движется поступательно (ω3 = 0): скорости всех его точек равны, "
                "V_D = V_E = V_S3 = V_A3:") in out
        assert ("- ускорение Кориолиса равно нулю: звено 3, несущее направляющую, движется "
                "поступательно (ω3 = 0)") in out
        mu_v = sol.velocity.mu
        assert (f"- `V_D = pd·μv = {num(v_d / mu_v, 5, 'ru')}·{num(mu_v, 4, 'ru')} = "
                f"{num(v_d, 4, 'ru')} м/с`") in out
    else:
        assert "Link 3 translates (ω3 = 0): all its points have one velocity, V_D = V_E = V_S3 = V_A3:" in out
        assert "Link 2 translates" not in out  # the block has one point: nothing to equate
        assert "- no Coriolis term: the guide's link 3 translates (ω3 = 0)" in out
    out = note_of("yoke_on_rocker")
    said = ("ω5 = ω3: звено 5 движется по направляющей звена 3" if lang == "ru"
            else "ω5 = ω3: link 5 slides along a guide of link 3")
    assert said in out and out.index(said) < out.index("2·ω5·V_A5A")
    out = note_of("yoke_inclined")
    assert ("x3-x3 — ось направляющей (паза) на звене 3" if lang == "ru"
            else "x3-x3: the axis of the guide (slot) on link 3") in out



def _notes():
    from plans.model.scenes import SCENES

    yield "press", (ROOT / "samples" / "press.toml").read_text("utf-8")
    yield "fourbar", (ROOT / "samples" / "fourbar.toml").read_text("utf-8")
    # inputs other than a uniform crank: two inputs with laws in time, an accelerating crank
    yield "moving_support", (ROOT / "samples" / "moving_support.toml").read_text("utf-8")
    yield "accelerating", (ROOT / "samples" / "fourbar.toml").read_text("utf-8").replace(
        'sense = "ccw"', 'sense = "ccw"\nepsilon = 30')
    for name, sc in SCENES.items():
        if sc.toml:
            yield name, sc.toml


@pytest.mark.parametrize("lang", ["ru", "en"])
def test_every_substitution_in_the_note_gives_its_result_by_hand(capsys, tmp_path, lang):
    """A teacher redoes the arithmetic: 'a_B = 15,62²·0,0625 = 15,26' gives 15,25 by
    hand. Every step whose substitution is plain arithmetic must give its printed result
    to within half a unit of its last digit (values carried with one digit more), the force
    section's steps too; and a number carried from one step into another is the number
    the first printed (carried_otherwise)."""
    checked = forces = 0
    for name, text in _notes():
        path = tmp_path / f"{name}.toml"
        path.write_text(text, "utf-8")
        code, out, _ = run(capsys, "report", path, "--lang", lang)
        assert code == 0
        for line in out.splitlines():
            m = re.fullmatch(r"\s*(?:- )?`(.+) = ([^=`]+) = (-?[\d.,]+)(?:°| [^`]*)?`", line)
            if not m:
                continue
            sub, res = m.group(2).replace("°", ""), m.group(3)
            if lang == "ru":
                sub, res = sub.replace(",", "."), res.replace(",", ".")
            if not re.fullmatch(r"[\d.·/²+−() ]+", sub):
                continue
            expr = sub.replace("·", "*").replace("²", "**2").replace("−", "-")
            got = eval(expr, {"__builtins__": {}})
            decimals = len(res.split(".")[1]) if "." in res else 0
            assert abs(got - float(res)) <= 0.6 * 10 ** -decimals, (name, line, got)
            checked += 1
        assert not carried_otherwise(out), name
        forces += out.count("## 6.") and sum(1 for ln in out.split("## 6.")[1].splitlines() if " = " in ln)
    assert checked > 200
    assert forces > 60  # the force section's steps are redone too


_OPS = r"[·/+−()²°\s]+"


def carried_otherwise(text: str) -> list[tuple[str, str, str, str]]:
    """The steps of a note that carry a number otherwise than an earlier step printed it:
    each step's quantities (its formula's right-hand side) against its substitution, term
    by term, where both have the same terms. 'V_CB = 0,4', then '0,39997 / 0,18' (more
    digits than printed) or 'a_S3 = 7,7798', then '10·7,78' (fewer) is one."""
    printed, bad = {}, []
    for line in text.splitlines():
        m = re.fullmatch(r"\s*(?:- )?`(.+) = ([^=`]+) = (-?[\d.,]+)(?:°| [^`]*)?`", line)
        if not m:
            continue
        formula, sub, res = m.groups()
        names = [x for x in re.split(_OPS, formula.split(" = ")[-1]) if x]
        values = [x for x in re.split(_OPS, sub) if x]
        if len(names) == len(values):
            bad += [(line, k, printed[k], v) for k, v in zip(names, values, strict=True)
                    if k in printed and printed[k] != v]
        printed[formula.split(" = ")[0]] = res
    return bad


def test_every_point_of_a_yoke_is_an_output_and_a_slider_link_says_so(capsys, tmp_path):
    """A Scotch yoke's E travels as D does: output = "E" was refused. A crank-slider's
    slider translates: the note says V_M = V_B (it said 'V_M:' alone)."""
    from plans.model.scenes import SCENES

    path = tmp_path / "y.toml"
    path.write_text(SCENES["scotch_yoke"].toml.replace('output = "D"', 'output = "E"'), "utf-8")
    code, out, err = run(capsys, "solve", path)
    assert code == 0, err
    assert "stroke of E: H = 0.2 m" in out
    path = tmp_path / "cs.toml"
    path.write_text(SCENES["crank_slider_offset"].toml, "utf-8")
    code, out, _ = run(capsys, "report", path)
    assert "Link 3 translates (ω3 = 0): all its points have one velocity, V_M = V_B:" in out


def test_a_fixed_point_is_the_pole_everywhere_in_the_note(capsys):
    """B is fixed, so b lies at the pole: the note drew 'through b' and read 'ba3' next to
    'pc = pa3·BC/BA3'. Every step now writes p (π)."""
    _code, out, _ = run(capsys, "report", "samples/press.toml")
    assert "Through point a draw a line ∥ BC and through point p a line ⊥ BA3; they meet at point a3." in out
    assert "- `V_A3B = pa3·μv = 55.432·0.05 = 2.7716 m/s`" in out
    assert "through b " not in out and "ba3·μ" not in out


def test_a_zero_omega_has_no_sense_word(capsys):
    """The press's slider: 'ω5 = 0 rad/s —' printed a dash where a sense would stand."""
    _code, out, _ = run(capsys, "solve", "samples/press.toml")
    assert "  link 5 (slider): ω5 = 0 rad/s, ε5 = 0 rad/s²\n" in out
    assert "  link 1 (crank): ω1 = 20 rad/s ccw, ε1 = 0 rad/s²\n" in out


def test_the_extreme_positions_are_given_as_angle_takes_them(capsys):
    """The press measures φ1 from +y, clockwise. solve printed its extreme positions from
    +x without saying so: --angle 199.9 landed where the slider runs at 6.5 m/s."""
    code, out, _ = run(capsys, "solve", "samples/press.toml")
    assert code == 0
    assert "φ1 = 60° from +x (30° from +y, cw, as the file gives it)" in out
    line = next(x for x in out.splitlines() if "extreme positions" in x)
    assert "(from +y, cw)" in line
    for text in re.findall(r"([\d.]+)°", line.split("θ")[0]):
        _, js, _ = run(capsys, "solve", "samples/press.toml", "--json", "--angle", text)
        vD = json.loads(js)["points"]["D"]["velocity"][0]
        # the printed angle is within 0.05° of the extreme, where a_D is about 20 m/s²:
        # |V_D| under 1e-3 m/s (at 199.9°, read from +y as the file does, 6.5 m/s)
        assert abs(vD) < 1e-2


def test_rounding_at_an_extreme_prints_as_zero(capsys):
    """At the press's extreme position the rocker is at rest: ω3 had printed as
    "3.516e-14 rad/s cw"."""
    code, out, _ = run(capsys, "solve", "samples/press.toml", "--angle", "109.93227047220137")
    assert code == 0 and "ω3 = 0 rad/s, ε3 = 145.1 rad/s² ccw" in out
    # the solution holds the 0, so JSON and the explanatory note say it too
    _, js, _ = run(capsys, "solve", "samples/press.toml", "--angle", "109.93227047220137", "--json")
    assert json.loads(js)["links"]["3"]["omega"] == 0.0
    code, note, _ = run(capsys, "report", "samples/press.toml", "--angle", "109.93227047220137",
                        "--lang", "ru")
    assert "`ω3 = V_A3B / l_A3B = 0 / 0,41364 = 0 рад/с`" in note
    assert not re.search(r"e-\d\d", note)  # no 3,9e-14 anywhere
    code, out, _ = run(capsys, "cycle", "samples/press.toml", "--csv", "--positions", "2")
    assert "output D (m)" in out.splitlines()[0]


def test_the_crank_angle_is_printed_as_typed(capsys):
    """--angle 40.001 printed as 40° (four digits): the header keeps six."""
    from support import run

    code, out, err = run(capsys, "solve", "samples/fourbar.toml", "--angle", "40.001")
    assert code == 0, err
    assert "φ1 = 40.001° from +x," in out
    code, out, err = run(capsys, "solve", "samples/press.toml", "--angle", "270.01")
    assert code == 0, err
    assert "φ1 = 179.99° from +x (270.01° from +y, cw, as the file gives it)" in out


def test_solve_json_gives_the_cycle_the_text_gives(capsys):
    """The README promises the cycle (H, θ, K, Grashof) from solve; its JSON left it out.
    The press: H = 0.5114 m (the text's line), θ and K from the extreme positions; a
    four-bar variant: its Grashof class, as plans cycle --json gives it."""
    code, out, _ = run(capsys, "solve", "samples/press.toml", "--json")
    assert code == 0
    c = json.loads(out)["cycle"]
    code, text, _ = run(capsys, "solve", "samples/press.toml")
    assert f"H = {num(c['stroke'])} m" in text and num(c["stroke"]) == "0.5114"
    a, b = c["extremes_phi_deg"]
    assert c["theta_deg"] == pytest.approx(abs(180 - abs(b - a)), abs=1e-9)
    assert c["K"] == pytest.approx((180 + c["theta_deg"]) / (180 - c["theta_deg"]), rel=1e-12)
    code, out, _ = run(capsys, "solve", "--variant", "3", "--json")
    solved = json.loads(out)["cycle"]
    code, out, _ = run(capsys, "cycle", "--variant", "3", "--json")
    cycled = json.loads(out)["cycle"]
    assert solved["grashof"] is not None and solved["grashof"] == cycled["grashof"]
    assert solved["stroke"] == cycled["stroke"] and solved["K"] == cycled["K"]


CRANK_3 = """
name = "Four-bar, crank numbered 3"
output = "C"
[frame]
A = [0.0, 0.0]
D = [0.30, 0.05]
[driver]
link = 3
angle_deg = 50
omega = 12
[links.3]
axis = ["A", "B"]
points = { B = 0.08 }
[links.1]
axis = ["B", "C"]
points = { C = 0.28, E = [0.12, 0.05] }
[links.2]
axis = ["D", "C"]
points = { C = 0.18 }
[assembly]
C = "above AD"
"""


def test_a_crank_numbered_3_is_named_by_its_number(capsys, tmp_path):
    """The crank's symbols were ω1 and φ1 whatever its number: a crank numbered 3 read
    "ω1 = 12 rad/s" in the crank's line and "link 1: ω1 = 2.897 rad/s" two lines below,
    and the note derived V_B from ω1 = 12 and then found ω1 = 2.897. Its symbols now
    carry its number, and ω1 is link 1's only."""
    path = tmp_path / "crank3.toml"
    path.write_text(CRANK_3, "utf-8")
    code, out, err = run(capsys, "solve", path)
    assert code == 0, err
    assert "Crank: link 3, l_AB = 0.08 m, φ3 = 50° from +x, ω3 = 12 rad/s ccw" in out
    assert "V_B = ω3·l_AB" in out and "a_B = a^n_BA = ω3²·l_AB" in out
    assert "extreme positions at φ3 = " in out
    assert re.findall(r"ω1 = [\d.]+", out) == ["ω1 = 2.897"] and "φ1" not in out
    for lang, sense in (("en", "in the sense of ω3:"), ("ru", "в сторону вращения ω3:")):
        code, note, err = run(capsys, "report", path, "--lang", lang)
        assert code == 0, err
        assert sense in note and "V_B = ω3·l_AB = 12·0" in note and "(ω3 = const)" in note
        assert "φ1" not in note and all(v.startswith(("ω1 = V_", "ω1 = 2")) for v in
                                        re.findall(r"ω1 = \S+", note))
    code, table, err = run(capsys, "cycle", path, "--positions", "3")
    assert code == 0, err
    assert "; ω3 = 12 rad/s ccw" in table and "φ3: degrees from +x" in table
    assert "φ1" not in table and "φ3 °" in table


def test_the_cycle_json_names_the_cranks_omega_by_its_number(capsys, tmp_path):
    """The head of ``plans cycle --json`` gave the crank's ω as "omega1" whatever its
    number: for a crank numbered 3 "omega1" was 12 in the head while every row's
    links["1"].omega, and the CSV's omega1 column, were link 1's 2.897. The head names
    it as the CSV and the text do, omega3, beside the crank's link number."""
    path = tmp_path / "crank3.toml"
    path.write_text(CRANK_3, "utf-8")
    code, out, err = run(capsys, "cycle", path, "--positions", "4", "--json")
    assert code == 0, err
    data = json.loads(out)
    assert "omega1" not in data and data["omega3"] == 12.0 and data["crank_link"] == 3
    assert all(r["links"]["3"]["omega"] == data["omega3"] for r in data["rows"])
    code, out, err = run(capsys, "cycle", "samples/press.toml", "--positions", "2", "--json")
    data = json.loads(out)
    assert data["omega1"] == 20.0 and data["crank_link"] == 1


def test_a_given_angle_is_written_as_the_crank_range_through_0_is_everywhere(capsys, tmp_path):
    """A four-bar that rocks through ±99.72°: solve echoed --angle 260.3 as −99.7°, while
    check's header, the sheet's plan titles and the note's "in the position given" still
    wrote 260.3° (and -99,7 with a hyphen). (With --plans the note now names the plans'
    positions, which the sheet draws heavy, not the given one.)"""
    text = NON_GRASHOF.format(angle=260.3)
    mech = tmp_path / "ng.toml"
    mech.write_text(text, "utf-8")
    code, out, err = run(capsys, "solve", mech)
    assert code == 0 and "φ1 = −99.7° from +x" in out
    meas = tmp_path / "m.toml"
    meas.write_text(f'mechanism = "{mech}"\nangle_deg = 260.3\n[scales]\nmu_l = 0.002\n'
                    'mu_v = 0.2\n[segments]\npb = 3\n', "utf-8")
    code, out, err = run(capsys, "check", meas)
    assert code == 0, err
    assert "φ1 = −99.7° from +x" in out and "260" not in out
    svg, note = tmp_path / "s.svg", tmp_path / "n.md"
    code, _, err = run(capsys, "sheet", mech, "--format", "A2", "--lang", "ru", "--plans", "1,4",
                       "-o", svg, "--note", note)
    assert code == 0, err
    # the note gives the segments of the positions drawn heavy, those of the plans
    written = note.read_text("utf-8")
    assert "(положение 1, φ1 = −74,79°)" in written and "260" not in written
    svg.unlink()
    code, _, err = run(capsys, "sheet", mech, "--format", "A2", "--lang", "ru", "-o", svg)
    assert code == 0, err
    drawn = svg.read_text("utf-8")
    assert drawn.count(" = −99,7°),") == 2 and "260,3" not in drawn


def test_a_point_off_the_line_is_built_from_two_sides_each_by_formula(capsys, tmp_path):
    """A coupler point E off the line BC is drawn on the plan as a triangle on bc: the
    note said only '△bce ∼ △BCE: be = 17,94 мм', one side, with no formula and no
    substitution. Now both sides be and ce, each formula → substitution → result."""
    from plans.model.scenes import SCENES

    path = tmp_path / "crank_rocker.toml"
    path.write_text(SCENES["crank_rocker"].toml, "utf-8")
    code, out, _ = run(capsys, "report", path, "--lang", "ru")
    assert code == 0
    lines = out.splitlines()
    at = lines.index("- `△abe ∼ △ABE`:")
    assert re.fullmatch(r"  `ae = ab·AE / AB = [\d,]+·[\d,]+ / [\d,]+ = [\d,]+ мм`", lines[at + 1])
    assert re.fullmatch(r"  `be = ab·BE / AB = [\d,]+·[\d,]+ / [\d,]+ = [\d,]+ мм`", lines[at + 2])
    assert "∼ △ABE`: " not in out


def test_the_tangential_component_is_a_tau_in_russian(capsys):
    """Russian textbooks write the tangential acceleration a^τ (a^t in English and Chinese
    ones): the Russian note had written a^t_A3B among its Russian words."""
    code, out, _ = run(capsys, "report", "samples/press.toml", "--lang", "ru")
    assert code == 0
    assert "`ε3 = a^τ_A3B / l_A3B = 11,891 / 0,57482 = 20,686 рад/с², против часовой стрелки`" in out
    assert "a^t" not in out
    code, out, _ = run(capsys, "report", "samples/press.toml")
    assert "a^τ" not in out and "ε3 = a^t_A3B / l_A3B" in out


def test_the_note_works_out_theta_from_the_cranks_turns_and_names_the_swing(capsys):
    """θ and ψ stood as bare values («θ = 54,88°»), with no formula to follow: θ is now
    worked out from the crank's turn over the working and the return stroke, and ψ named
    as the angle between the rocker's extreme positions at its pivot. The turns are the
    cycle's own: φ_рх − 180° = θ."""
    from plans.cycle import analyse_cycle

    c = analyse_cycle(variant(3))
    th = math.degrees(c.theta)
    work, back = 180.0 + th, 180.0 - th
    # the crank's turn from the one extreme to the other, in its sense, measured apart
    sense = math.copysign(1.0, variant(3).driver.omega)
    assert math.degrees((sense * (c.extremes[1] - c.extremes[0])) % (2 * math.pi)) == \
        pytest.approx(work, abs=1e-9)
    code, out, _ = run(capsys, "report", "--variant", "3", "--lang", "ru")
    assert code == 0
    assert "- `ψ = ∠C′DC″ = 79,54°`" in out
    w, r = (f"{x:.6g}".replace(".", ",") for x in (work, back))
    assert f"- `φ_рх = {w}°`" in out
    assert f"- `φ_хх = 360° − φ_рх = 360° − {w}° = {r}°`" in out
    assert f"- `θ = (φ_рх − φ_хх) / 2 = ({w}° − {r}°) / 2 = {th:.4g}°`".replace(".", ",") in out
    code, out, _ = run(capsys, "report", "samples/press.toml")
    assert "- `θ = (φ_w − φ_r) / 2 = (219.865° − 140.135°) / 2 = 39.86°`" in out


def test_a_courses_table_gives_an_offset_omega_and_a_clockwise_crank(tmp_path, capsys):
    """A course's table could not hold a crank-slider's offset, a speed in rad/s nor a
    clockwise crank: its rows went through the tool only as Table 2's. With e, omega and
    sense, the offset crank-slider r = 0.1, l = 0.4, e = 0.05 m has the closed forms'
    stroke H = √((l+r)² − e²) − √((l−r)² − e²) and θ = asin(e/(l−r)) − asin(e/(l+r)),
    and its crank turns clockwise at ω1 = 10.5 rad/s."""
    from plans.cycle import analyse_cycle

    table = tmp_path / "course.toml"
    table.write_text('designation = "ТММ.КП.{n:02d}"\n[[variant]]\nn = 4\nkind = "crank-slider"\n'
                     'AB = 0.1\nBC = 0.4\ne = "0,05"\nphi_deg = 30\nomega = 10.5\nsense = "cw"\n',
                     encoding="utf-8")
    mech = variant(4, table)
    r, rod, e = 0.1, 0.4, 0.05
    assert mech.driver.omega == -10.5
    c = analyse_cycle(mech)
    assert c.stroke == pytest.approx(
        math.sqrt((rod + r) ** 2 - e * e) - math.sqrt((rod - r) ** 2 - e * e), rel=1e-12)
    assert c.theta == pytest.approx(math.asin(e / (rod - r)) - math.asin(e / (rod + r)), rel=1e-9)
    code, out, _ = run(capsys, "solve", "--variant", "4", "--table", str(table))
    assert code == 0 and "ω1 = 10.5 rad/s cw" in out, out


def test_the_note_opens_with_the_initial_data_and_names_the_position_in_every_plan(capsys):
    """Seed 000 §1.1 opens with the initial data; the note began with the structure and
    never said at which crank position its plans stand. Now every length the file gives
    (the frame's OB, a fixed guide's offset e, a four-bar coupler's CE), the masses and
    J_S, ω1 (n1 where the file gives rpm) and φ1 as the file gives it and from +x; and
    each plan section names its position."""
    code, out, _ = run(capsys, "report", "samples/press.toml", "--lang", "ru")
    assert code == 0
    first = out.split("## 1. Исходные данные")[1].split("## 2. Структурный анализ механизма")[0]
    for row in ("- `l_OA = 0,15 м`;", "- `l_OB = 0,44 м`;", "- `l_BC = 0,75 м`;", "- `l_CS4 = 0,1 м`;",
                "- `e = 0,35 м`, смещение направляющей x-x от O;", "- `m3 = 10 кг`;",
                "- `J_S3 = 0,4 кг·м²`;", "- `ω1 = 20 рад/с`, против часовой стрелки;",
                "- `φ1 = 60°` от +x (30° от +y, по часовой стрелке, как задано в файле)."):
        assert row in first, row
    said = "Положение механизма: φ1 = 60° от +x (30° от +y, по часовой стрелке, как задано в файле)."
    for head in ("## 4. План скоростей механизма", "## 5. План ускорений механизма"):
        assert out.split(head)[1].lstrip().startswith(said)
    code, out, _ = run(capsys, "report", "--variant", "1", "--angle", "70")
    first = out.split("## 1. Initial data")[1].split("## 2.")[0]
    for row in ("- `l_CE = 0.08 m`;", "- `l_BE = 0.24 m`;", "- `l_AD = 0.11 m`;", "- `n1 = 115 rpm`;",
                "- `φ1 = 70°` from +x."):
        assert row in first, row
    assert out.count("Position of the mechanism: φ1 = 70° from +x.") == 2
    code, out, _ = run(capsys, "report", "--variant", "0")
    assert "- `e = 0 m`, offset of the guide x-x from A;" in out


def test_user_text_is_no_markup_in_the_note_and_no_bidi_on_the_sheet(capsys, tmp_path):
    """A name with HTML, Markdown and a line break became markup and a forged section in
    the note; a guide's label with a backtick broke the step's code span; a bidi control
    (U+202E) turned the sheet's text around it. Now the note escapes what it writes of the
    file's text, and the sheet drops the bidi controls."""
    text = (ROOT / "samples" / "press.toml").read_text("utf-8")
    name = '<script>x</script> **Press**\\n## 9. Forged\\u202e'
    text = text.replace('name = { en = "Slotted-link press for briquetting", ru = '
                        '"Кулисный механизм пресса для брикетирования" }', f'name = "{name}"')
    text = text.replace("angle_deg = 0 }", 'angle_deg = 0, label = "x`|<i>" }')
    path = tmp_path / "hostile.toml"
    path.write_text(text, "utf-8")
    for lang in ("ru", "en"):
        code, out, err = run(capsys, "report", path, "--lang", lang)
        assert code == 0, err
        lines = out.splitlines()
        prose = re.sub(r"(?<!\\)`[^`]*`", "", out)  # a code span's text is literal: markup only outside one
        assert lines[0].startswith("# ") and "<script>" not in out and "<i>" not in prose
        assert "\\<script\\>x\\</script\\> \\*\\*Press\\*\\* \\#\\# 9. Forged" in lines[0]
        assert not any(ln.startswith("## 9.") for ln in lines) and "\u202e" not in out
        assert all(ln.count("`") % 2 == ln.count("\\`") % 2 for ln in lines)  # every code span closed
        assert "∥ xˋ|<i>`" in out  # in a step's code span
    svg = tmp_path / "s.svg"
    code, _, err = run(capsys, "sheet", path, "-o", svg)
    assert code == 0, err
    assert "\u202e" not in svg.read_text("utf-8")
