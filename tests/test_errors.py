"""Validation of input files: located, one line per problem, all problems at once.

The corpus (``tests/corpus``) holds the malformed files with their expected messages; the
tests here also cover hostile sizes, line location, and the engine's own messages for
scenes that cannot be solved.
"""

from __future__ import annotations

import copy
import math
import time
import tomllib
from pathlib import Path

import pytest
from support import expectations, run, upright_fourbar

from plans import model
from plans.errors import (
    AssemblyError,
    InputError,
    PlansError,
    SingularPlanError,
    StructureError,
)
from plans.kinematics.solver import Solver
from plans.model import fileformat, from_dict, load
from plans.model.variants import load_table, variant, variant_numbers
from plans.plan.solution import solve_position

ROOT = Path(__file__).resolve().parent.parent
CORPUS = ROOT / "tests" / "corpus"
MECHANISMS = sorted(CORPUS.glob("*.toml"))
TABLES = sorted((CORPUS / "tables").glob("*.toml"))
SAMPLES = [ROOT / "samples" / "press.toml", ROOT / "samples" / "fourbar.toml"]



def problems_of(call, path: Path) -> list[str]:
    with pytest.raises(InputError) as info:
        call(path)
    err = info.value
    assert err.source == str(path)
    assert str(err).splitlines() == [f"{path}: {p}" for p in err.problems]
    return err.problems


def assert_matches(problems: list[str], expected: list[str]) -> None:
    assert len(problems) == len(expected), "\n".join(problems)
    for got, want in zip(problems, expected, strict=True):
        assert want in got, f"expected {want!r}\n     got {got!r}"
        assert "\n" not in got and len(got) <= 400


# ---------------------------------------------------------------------------------------
# the corpus
# ---------------------------------------------------------------------------------------


def test_corpus_is_large_enough():
    assert len(MECHANISMS) + len(TABLES) >= 50


@pytest.mark.parametrize("path", MECHANISMS, ids=lambda p: p.stem)
def test_corpus_mechanism(path):
    assert_matches(problems_of(load, path), expectations(path))


@pytest.mark.parametrize("path", TABLES, ids=lambda p: p.stem)
def test_corpus_table(path):
    assert_matches(problems_of(load_table, path), expectations(path))


@pytest.mark.parametrize("path", SAMPLES, ids=lambda p: p.stem)
def test_samples_stay_valid(path):
    load(path)


def test_scenes_and_builtin_variants_stay_valid():
    from plans.model.scenes import SCENES

    for scene in SCENES.values():
        scene.mechanism()
    for n in variant_numbers():
        variant(n)


# ---------------------------------------------------------------------------------------
# located messages
# ---------------------------------------------------------------------------------------

FOURBAR = (ROOT / "samples" / "fourbar.toml").read_text("utf-8")


def _problems_of_text(tmp_path, text: str, name: str = "m.toml") -> list[str]:
    path = tmp_path / name
    path.write_text(text, "utf-8")
    return problems_of(load, path)


def test_several_problems_are_reported_at_once_in_line_order(tmp_path):
    text = (
        FOURBAR.replace("A = [0.0, 0.0]", 'A = [0.0, "zero"]')
        .replace("angle_deg = 40", "angle_deg = 40\nfrom = 'north'")
        .replace("points = { C = 0.1025, S3 = 0.05125 }", "points = { C = -0.1025, S3 = 0.05125 }")
    )
    lines = text.split("\n")
    where = [lines.index(s) + 1 for s in ('A = [0.0, "zero"]', "from = 'north'",
                                          "points = { C = -0.1025, S3 = 0.05125 }")]
    got = _problems_of_text(tmp_path, text)
    assert [p.split(":")[0] for p in got] == [f"line {n}" for n in where]
    assert "frame.A[1]" in got[0] and "driver.from" in got[1] and "negative length" in got[2]


def test_dotted_quoted_and_inline_keys_are_located(tmp_path):
    text = """
[frame]
"O" = [0.0, 0.0]
[driver]
angle_deg = 10
omega = 5
[links.1]
axis = ["O", "A"]
points.A = 0.1
[links."2"]
axis = ["A", "B"]
points = { B = 0.3,
   C = "far" }
"""
    text = text.replace("points = { B = 0.3,\n   C = \"far\" }", "points = { B = 0.3, C = \"far\" }")
    got = _problems_of_text(tmp_path, text)
    assert got[0].startswith('line 12: links.2.points.C: must be a number, got "far"')


def test_problems_in_arrays_of_tables_point_at_their_element(tmp_path):
    text = (ROOT / "samples" / "press.toml").read_text("utf-8")
    text = text.replace("guide = { link = 0, through = [0.0, 0.35], angle_deg = 0 }",
                        "guide = { link = 0, through = [0.0, 0.35], angle_deg = [0] }")
    (got,) = _problems_of_text(tmp_path, text)
    line = text.split("\n").index("guide = { link = 0, through = [0.0, 0.35], angle_deg = [0] }") + 1
    assert got.startswith(f"line {line}: sliders[1].guide.angle_deg: must be a number")


def test_multiline_strings_and_arrays_do_not_confuse_the_locator(tmp_path):
    text = FOURBAR.replace(
        'name = "Four-bar linkage"',
        'name = """Four-bar\n[links.9]\nlinkage"""',
    ).replace('trace = ["E"]', 'trace = [\n  "E",  # the coupler point\n  "Z",\n]')
    (got,) = _problems_of_text(tmp_path, text)
    line = text.split("\n").index('  "Z",') + 1
    assert got.startswith(f"line {line}: trace[1]: unknown point \"Z\"")


def test_from_dict_without_text_gives_key_paths():
    data = tomllib.loads(FOURBAR)
    data["links"]["3"]["points"]["C"] = 0
    with pytest.raises(InputError) as info:
        from_dict(data, "dict")
    assert info.value.problems == [
        'links.3.points.C: zero-length link: the axis end "C" is at the origin "D"; '
        "give the length DC in metres"
    ]


def test_validation_does_not_change_its_input():
    data = tomllib.loads((ROOT / "samples" / "press.toml").read_text("utf-8"))
    data["links"]["3"]["points"]["Q"] = "x"
    before = copy.deepcopy(data)
    with pytest.raises(InputError):
        from_dict(data)
    assert data == before


def test_toml_errors_carry_their_line(tmp_path):
    text = FOURBAR.replace("rpm = 149.2", "rpm = 149,2")
    (got,) = _problems_of_text(tmp_path, text)
    line = text.split("\n").index("rpm = 149,2") + 1
    assert got.startswith(f"line {line}, column 10: TOML syntax error:")


def test_a_bare_decimal_comma_is_told_to_be_quoted(tmp_path):
    """rpm = 149,2 stops TOML at the comma: the message says what to write (the comma in
    quotes, or a point), not only "one key = value per line"."""
    text = FOURBAR.replace("rpm = 149.2", "rpm = 149,2")
    (got,) = _problems_of_text(tmp_path, text)
    assert got.endswith('(a decimal comma is written in quotes: "149,2", or 149.2)')


def test_duplicate_key_names_both_lines(tmp_path):
    text = FOURBAR.replace("D = [-0.135, 0.0]", "D = [-0.135, 0.0]\nD = [-0.2, 0.0]")
    (got,) = _problems_of_text(tmp_path, text)
    first = text.split("\n").index("D = [-0.135, 0.0]") + 1
    assert got == (
        f"line {first + 1}: TOML syntax error: frame.D is given twice (first at line {first}): "
        "each name once"
    )


def test_a_byte_order_mark_is_accepted(tmp_path):
    path = tmp_path / "bom.toml"
    path.write_bytes(b"\xef\xbb\xbf" + FOURBAR.encode())
    assert load(path).name == "Four-bar linkage"


# ---------------------------------------------------------------------------------------
# hostile sizes: refused with a message, quickly, without exhausting memory
# ---------------------------------------------------------------------------------------


def _quick(fn, limit=10.0):
    t0 = time.perf_counter()
    with pytest.raises(InputError) as info:
        fn()
    assert time.perf_counter() - t0 < limit
    lines = str(info.value).splitlines()
    assert all(len(line) < 600 for line in lines), max(map(len, lines))
    return info.value


def test_a_file_larger_than_a_megabyte_is_not_read(tmp_path):
    path = tmp_path / "big.toml"
    path.write_bytes(b"# " + b"x" * 10_000_000 + b"\n")
    err = _quick(lambda: load(path))
    assert err.problems == ["the file is larger than 1 MB; a mechanism file is a few KB"]


@pytest.mark.skipif(not Path("/dev/zero").exists(), reason="no /dev/zero")
def test_an_endless_input_is_not_read_to_its_end():
    err = _quick(lambda: load("/dev/zero"))
    assert "larger than 1 MB" in err.problems[0]


def test_a_folder_or_a_missing_file(tmp_path):
    assert _quick(lambda: load(tmp_path)).problems == ["is a folder, not a file"]
    err = _quick(lambda: load(tmp_path / "nope.toml"))
    assert err.problems == ["cannot read the file: No such file or directory"]


def test_a_ten_megabyte_string_is_not_echoed():
    data = tomllib.loads(FOURBAR)
    big = "x" * 10_000_000
    data["name"] = big
    data["assembly"]["C"] = big
    data["links"]["2"]["name"] = big
    data[big] = 1
    data["frame"]["O" + big] = [0, 0]
    err = _quick(lambda: from_dict(data, "big"))
    assert len(err.problems) == 5


@pytest.mark.parametrize("where", ["frame", "link", "links", "trace"])
def test_a_million_of_anything_is_refused(where):
    data = tomllib.loads(FOURBAR)
    n = 1_000_000
    if where == "frame":
        data["frame"] = {f"F{i}": [0.0, float(i)] for i in range(n)}
    elif where == "link":
        data["links"]["2"]["points"] = {f"S{i}": 0.1 for i in range(n)}
    elif where == "links":
        link = {"axis": ["A", "B"], "points": {"B": 0.1}}
        data["links"] = {str(i): link for i in range(1, n // 10)}
    else:
        data["trace"] = ["E"] * n
    err = _quick(lambda: from_dict(data, "million"))
    assert any("at most" in p for p in err.problems), err.problems


@pytest.mark.parametrize(
    ("value", "message"),
    [
        (10**300, "an integer of 301 digits is out of range: at most 1e+06 m"),
        (10**5000, "an integer of thousands of digits is out of range"),
        (1e300, "1e+300 is out of range: at most 1e+06 m"),
        (-math.inf, "-inf is out of range"),
        (math.nan, "nan is not a number"),
        (True, "must be a number, got true"),  # as TOML spells it
    ],
    ids=["int-301-digits", "int-5001-digits", "1e300", "-inf", "nan", "bool"],
)
def test_absurd_numbers(value, message):
    data = tomllib.loads(FOURBAR)
    data["frame"]["D"] = [value, 0.0]
    err = _quick(lambda: from_dict(data, "n"))
    assert message in err.problems[0]


def test_tiny_coordinates_are_zero_but_tiny_links_are_refused():
    data = tomllib.loads(FOURBAR)
    data["frame"]["A"] = [1e-300, -5e-324]  # harmless: a computed 0
    from_dict(data)
    data["links"]["1"]["points"]["B"] = 1e-300
    err = _quick(lambda: from_dict(data, "n"))
    assert "link length 1e-300 m: zero or too short" in err.problems[0]


def test_the_number_of_reported_problems_is_capped():
    data = tomllib.loads(FOURBAR)
    for i in range(10_000):
        data[f"junk{i}"] = i
    err = _quick(lambda: from_dict(data, "junk"))
    assert len(err.problems) == fileformat.MAX_PROBLEMS + 1
    assert err.problems[-1] == "… and 9950 more problems"


def test_control_characters_never_break_a_message_into_lines():
    data = tomllib.loads(FOURBAR)
    data["frame"]["O\nX"] = [0, 0]
    data["trace"] = ["E\r\nplans solve: fake"]
    data["driver"]["from"] = "\x1b[31mred"
    err = _quick(lambda: from_dict(data, "ctl"))
    assert len(str(err).splitlines()) == len(err.problems) == 3
    assert all("\x1b" not in p for p in err.problems)


def test_a_link_numbered_with_thousands_of_digits():
    data = tomllib.loads(FOURBAR)
    data.pop("loads")  # whose link 3 would be missing too
    data["links"]["9" * 5000] = data["links"].pop("3")
    err = _quick(lambda: from_dict(data, "x"))
    assert err.problems == [
        "links.\"99999999999999999999999999999…\": links are numbered 1, 2, 3… up to 999, "
        "without leading zeros (0 is the frame)"
    ]


def test_sections_of_the_wrong_type_are_not_called_missing():
    data = tomllib.loads(FOURBAR)
    data["frame"], data["links"] = [1, 2], "x"
    err = _quick(lambda: from_dict(data, "x"))
    assert err.problems[:2] == [
        "frame: must be a table of fixed points, got a list of 2: the fixed pivots, e.g. [frame] O = [0.0, "
        "0.0]",
        'links: must be a table of numbered links, got "x": the moving links, e.g. [links.1] axis = ["O", '
        '"A"]',
    ]


def test_unhashable_values_where_a_word_is_expected():
    data = tomllib.loads(FOURBAR)
    data["driver"].update({"sense": [], "from": {}, "measured": [1]})
    err = _quick(lambda: from_dict(data, "x"))
    assert [p.split(":")[0] for p in err.problems] == ["driver.from", "driver.measured", "driver.sense"]


def test_deep_nesting_in_a_dict_is_reported_not_a_crash():
    deep: list = []
    for _ in range(100_000):
        deep = [deep]
    data = tomllib.loads(FOURBAR)
    data["trace"] = deep
    err = _quick(lambda: from_dict(data, "deep"))
    assert err.problems == ['trace[0]: must be a point name, e.g. "C", got a list of 1']


def test_variant_table_limits(tmp_path):
    row = '[[variant]]\nn = {}\nkind = "crank-slider"\nAB = 0.05\nBC = 0.15\nphi_deg = 15\nrpm = 100\n'
    rows = "".join(row.format(i) for i in range(10_001))
    path = tmp_path / "t.toml"
    path.write_text(rows)
    err = _quick(lambda: load_table(path))
    assert err.problems == ["line 1: variant: 10001 rows: at most 10000"]
    path.write_text(rows.split(row.format(100))[0])
    with pytest.raises(InputError) as info:
        variant(5000, path)
    assert info.value.problems == ["variant 5000 is not in the table (it has 0…99, 100 rows)"]


def test_a_tables_designation_pattern_names_each_variants_sheet(tmp_path, capsys):
    row = '[[variant]]\nn = {}\nAB = 0.05\nBC = 0.15\nCD = 0.1\nAD = 0.1\nphi_deg = 15\nrpm = 100\n'
    path = tmp_path / "t.toml"
    path.write_text('designation = "ТММ.КП.{n:03d}.00"\n' + row.format(6) + row.format(7))
    assert variant(7, path).title["designation"] == "ТММ.КП.007.00"
    assert variant(6, path).title["designation"] == "ТММ.КП.006.00"
    assert variant(7).title["designation"] == "ПМ.01.07"  # the built-in table's
    for bad, why in (('"ТММ.КП"', "(as"), ('"ТММ.{n"', "no other field"),
                     ('"ТММ.{v}"', "no other field"), ('"ТММ.{n:q}"', "no other field"),
                     ("7", "must be text")):
        path.write_text(f"designation = {bad}\n" + row.format(7))
        code, out, err = run(capsys, "solve", "--variant", "7", "--table", str(path))
        assert code == 2 and out == ""
        assert err.count("\n") == 1 and f"{path}: line 1: designation: " in err, err
        assert why in err


def test_public_api_is_unchanged():
    for name in ("load", "from_dict", "Mechanism", "Link", "Guide", "Slider", "Driver"):
        assert hasattr(model, name)
    assert model.REFERENCES == {"+x": 0.0, "+y": 90.0, "-x": 180.0, "-y": 270.0}
    assert model.SENSES == {"ccw": 1.0, "cw": -1.0}
    m = from_dict(tomllib.loads(FOURBAR), "f")
    assert m.assembly == {"C": "above BD"} and m.output == "C" and m.trace == ("E",)


def test_guide_direction_as_a_vector_equals_its_angle():
    text = (ROOT / "samples" / "press.toml").read_text("utf-8")
    a = from_dict(tomllib.loads(text))
    b = from_dict(tomllib.loads(text.replace("angle_deg = 0 }", "direction = [2.0, 0.0] }")))
    assert a.sliders == b.sliders


# ---------------------------------------------------------------------------------------
# the engine's messages for scenes that cannot be solved
# ---------------------------------------------------------------------------------------

PRESS = (ROOT / "samples" / "press.toml").read_text("utf-8")


def engine_error(text: str) -> PlansError:
    mech = from_dict(tomllib.loads(text), "scene")
    with pytest.raises(PlansError) as info:
        solve_position(mech, solver=Solver(mech))
    msg = str(info.value)
    assert "\n" not in msg and "nan" not in msg.lower()
    return info.value


def test_unreachable_angle_names_group_range_and_gap():
    err = engine_error(FOURBAR.replace("angle_deg = 40", "angle_deg = 180"))
    assert isinstance(err, AssemblyError)
    assert str(err).startswith(
        "group 2–3 (RRR) cannot be assembled at φ1 = 180°: needs BD within [0.1075, 0.3125] m, misses by "
    )


def test_hints_that_fit_neither_branch_are_input_errors():
    err = engine_error(PRESS.replace('D = "right of C"', 'D = "below C"'))
    assert isinstance(err, InputError)
    assert "the hint D = 'below C' fits neither assembly of group 4–5 (RRP)" in str(err)


def test_a_hint_that_fits_both_assemblies_says_where_they_are(capsys, tmp_path):
    """A crank-slider row whose rod is shorter than the crank: both places of C are right
    of A. The message had read "fit both assembly", and said no more."""
    table = tmp_path / "t.toml"
    table.write_text('[[variant]]\nn = 2\nAB = 0.05\nBC = 0.03\nCD = 0.1\nAD = 0.1\n'
                     'phi_deg = 15\nrpm = 100\n', "utf-8")
    code, _, err = run(capsys, "solve", "--variant", "2", "--table", table)
    assert code == 2
    assert (f"plans solve: {table}, variant 2: assembly: the hint C = 'right of A' fits both "
            "assemblies of group 2–3 (RRP) at φ1 = 15°, with C at (0.07536, ") in err
    assert "and (0.02123, 0): name a point or line that parts them" in err


def test_near_dead_point_is_a_warning():
    # crank-slider with the rod as long as the crank: at φ1 = 90° the rod stands on the
    # guide, the plan's two lines (⊥ BA, ∥ x-x) are parallel; at 89° they meet at 1°.
    # 90° is a change point (the slider could stay on the crank's pivot): named beside it
    text = """
[frame]
O = [0.0, 0.0]
[driver]
angle_deg = 89
omega = 12
[links.1]
axis = ["O", "A"]
points = { A = 0.1 }
[links.2]
axis = ["A", "B"]
points = { B = 0.1 }
[links.3]
points = { B = 0 }
[[sliders]]
link = 3
guide = { link = 0, through = [0.0, 0.0], angle_deg = 0 }
[assembly]
B = "right of A"
"""
    sol = solve_position(from_dict(tomllib.loads(text), "dead"))
    (warning,) = sol.warnings
    assert warning.startswith(
        "group 2–3 (RRP) at φ1 = 89° (beside the change point at φ1 = 90°, where the two "
        "assemblies of a group meet): near-singular, the lines ⊥ BA and ∥ x-x meet at 1°")


PARALLEL_PRP = """
[frame]
O = [0.0, 0.0]
[driver]
angle_deg = 0
omega = 6
[links.1]
axis = ["O", "A"]
points = { A = 0.1 }
[links.2]
points = { C = 0 }
[links.3]
points = { C = 0 }
[[sliders]]
link = 2
guide = { link = 1 }
[[sliders]]
link = 3
guide = { link = 0, through = [0.0, 0.2], angle_deg = 0 }
"""

PARALLEL_RPP = """
[frame]
O = [0.0, 0.0]
[driver]
angle_deg = 35
omega = 10
[links.1]
axis = ["O", "A"]
points = { A = 0.1 }
[links.2]
points = { A = 0 }
[links.3]
axis = ["D", "E"]
points = { E = 0.3 }
[[sliders]]
link = 2
guide = { link = 3, angle_deg = 0 }
[[sliders]]
link = 3
point = "D"
guide = { link = 0, through = [0.0, 0.0], angle_deg = 0 }
"""

TANGENT_RRR = """
[frame]
O = [0.0, 0.0]
D = [0.3, 0.0]
[driver]
angle_deg = 0
omega = 10
[links.1]
axis = ["O", "A"]
points = { A = 0.05 }
[links.2]
axis = ["A", "B"]
points = { B = 0.1 }
[links.3]
axis = ["D", "B"]
points = { B = 0.15 }
[assembly]
B = "above OD"
"""

RPR_PIVOT_ON_PIN = """
[frame]
O = [0.0, 0.0]
B = [0.1, 0.0]
[driver]
angle_deg = 0
omega = 8
[links.1]
axis = ["O", "A"]
points = { A = 0.1 }
[links.2]
points = { A = 0 }
[links.3]
axis = ["B", "C"]
points = { C = 0.5 }
[[sliders]]
link = 2
guide = { link = 3 }
"""


def test_parallel_guides_are_named_without_a_made_up_gap():
    """Guides parallel at one crank angle (PRP, one guide on the crank) make that angle a
    dead point; guides parallel at every angle (RPP: both fixed to the yoke's axis) are
    refused with the structure, not reported as a dead point of one angle."""
    err = engine_error(PARALLEL_PRP)
    msg = str(err)
    assert isinstance(err, SingularPlanError)
    assert "parallel" in msg and "φ1 = 0°" in msg and "misses by" not in msg
    err = engine_error(PARALLEL_RPP)
    msg = str(err)
    assert isinstance(err, StructureError)
    assert msg == ("group 2–3 (RPP): the guide DE of link 3 is parallel to the guide x-x it "
                   "moves along (a sliding link's x-axis runs along its guide), so the "
                   "yoke's position is not fixed at any crank angle: turn one of them, e.g. "
                   "angle_deg = 90 for a slot across link 3")
    # as the message says: the same yoke with its slot across DE solves
    across = PARALLEL_RPP.replace("guide = { link = 3, angle_deg = 0 }",
                                  "guide = { link = 3, angle_deg = 90 }")
    assert across != PARALLEL_RPP
    sol = solve_position(from_dict(tomllib.loads(across), "yoke"))
    (a3,) = [p for p in sol.velocity.points.values() if p.source.kind == "intersection"]
    assert [ln.relation for ln in a3.source.lines] == ["⊥ DE", "∥ x-x"]
    slanted = across.replace("angle_deg = 90 }", "angle_deg = 60 }")
    sol = solve_position(from_dict(tomllib.loads(slanted), "yoke"))
    (a3,) = [p for p in sol.velocity.points.values() if p.source.kind == "intersection"]
    # a slanted slot is the line through D and the block's A, both on it
    assert [ln.relation for ln in a3.source.lines] == ["∥ DA", "∥ x-x"]
    assert abs(cmath_phase_between(sol, "D", "A") - math.radians(60)) < 1e-12
    off = slanted.replace("angle_deg = 60 }", "angle_deg = 60, offset = 0.02 }")
    sol = solve_position(from_dict(tomllib.loads(off), "yoke"))
    (a3,) = [p for p in sol.velocity.points.values() if p.source.kind == "intersection"]
    assert [ln.relation for ln in a3.source.lines] == ["∥ x3-x3", "∥ x-x"]  # no named point on it


def cmath_phase_between(sol, a, b):
    """The angle of the line from point a to point b, measured from the yoke's guide DE."""
    import cmath

    pos = sol.positions
    return cmath.phase((pos[b] - pos[a]) / (pos["E"] - pos["D"]))


def test_exact_reach_limit_is_a_dead_point_not_a_zero_miss():
    msg = str(engine_error(TANGENT_RRR))
    assert "misses by 0 m" not in msg and ("singular" in msg or "dead point" in msg)


def test_rpr_pivot_on_the_pin_is_explained():
    msg = str(engine_error(RPR_PIVOT_ON_PIN))
    assert "misses by 0 m" not in msg
    assert "the pivot B is on the block's pin A" in msg


def test_a_hint_that_makes_a_later_group_fail_is_named():
    msg = str(engine_error(PRESS.replace('D = "right of C"', 'D = "right of C"\nS3 = "right of C"')))
    assert "S3" in msg


@pytest.mark.parametrize("hint", ["above S4", "above OS4"])
def test_a_hint_naming_a_point_of_a_later_group_is_an_input_error(hint):
    """The press's A3 (group 2–3) placed relative to S4, which group 4–5 finds later: the
    hint had crashed the engine (exit 3), or with a second point "above OS4" been read
    as "above O" without a word."""
    text = PRESS.replace('D = "right of C"', f'D = "right of C"\nC = "{hint}"')
    err = engine_error(text)
    assert isinstance(err, InputError)
    assert f"assembly.C: '{hint}' names S4, a point found after group 2–3 (RPR)" in str(err)


def test_above_a_vertical_line_is_refused_and_left_of_it_does_not_depend_on_the_order():
    """A four-bar standing upright (D above O): "above OD" and "above DO" had picked the
    two different assemblies, neither of them above anything."""
    text = upright_fourbar(0.05, 0.2, 0.15, 0.2, "HINT")
    for hint in ("above OD", "below DO"):
        err = engine_error(text.replace("HINT", hint))
        assert isinstance(err, InputError)
        assert (f"assembly.B: '{hint}': the line {hint[-2:]} is vertical at "
                f"φ1 = 0°, so {hint.split()[0]} it names no side: write \"left of") in str(err)
    spots = {h: Solver(from_dict(tomllib.loads(text.replace("HINT", h)), "<t>"))
             .solve_one(0.0).position["B"] for h in ("left of OD", "left of DO", "right of OD")}
    assert spots["left of OD"] == spots["left of DO"] and spots["left of OD"].real < 0
    assert spots["right of OD"].real > 0


@pytest.mark.parametrize("hint", ['A = "right of B"', 'A = "left of B"'])
def test_a_hint_on_a_point_both_assemblies_share_names_one_that_parts_them(capsys, tmp_path, hint):
    """A slotted link with an offset guide: its block's pin A and the rocker's pivot B
    stand in one place in both assemblies. The hint on A was "fits both … with B at
    (0, -0.3) and (0, -0.3)" or "fits neither (new point A3)": neither says what to
    write. It now names the rocker's end C and where each assembly puts it."""
    from plans.model.scenes import SLOTTED_OFFSET

    path = tmp_path / "slot.toml"
    path.write_text(SLOTTED_OFFSET + f"[assembly]\n{hint}\n", "utf-8")
    code, out, err = run(capsys, "solve", path)
    assert code == 2 and out == ""
    assert err.strip().splitlines() == [
        f"plans solve: {path}: assembly.A: A stands at the same place in both assemblies of "
        "group 2–3 (RPR) at φ1 = 110°, so a hint on it chooses neither: write one on C, which "
        "stands at (-0.018, 0.1997) and (0.06838, -0.7953)"]
    path.write_text(SLOTTED_OFFSET + '[assembly]\nC = "left of OB"\n', "utf-8")
    code, out, err = run(capsys, "solve", path, "--json")
    assert code == 0, err
    C = __import__("json").loads(out)["points"]["C"]["position"]
    assert C == pytest.approx([-0.018, 0.1997], abs=1e-4)


@pytest.mark.parametrize(("value", "unit", "hint"), [
    ("0,15 м", "m", ': write "0,15" or 0.15, without the unit'),
    ("40°", "°", ": write 40 without the unit"),
    ("12 см", "m", ": write the number in m, without the unit"),  # not 12: 0.12 m
    ("3 rad/s", "rpm", ": write the number in rpm, without the unit"),
    ("1 000,5", "m", ""),  # a thousands' space, not a unit
    ("0,12,3", "m", ""),
])
def test_a_number_with_a_unit_is_told_what_to_write_only_when_it_is_sure(value, unit, hint):
    """"12 см" in a field of metres was told "write 12 without the unit", and "1 000,5"
    "write 1": the number alone is suggested only after the field's own unit."""
    from plans.model.fileformat import Problems, read_number

    pr = Problems("f.toml")
    assert read_number(value, "k", pr, unit=unit) is None
    assert pr.items == [("k", f'must be a number, got "{value}"{hint}')]


@pytest.mark.parametrize(("mu", "message"), [
    ({"mu_v": -1}, "mu.mu_v: must be positive, got -1"),  # made every segment 0
    ({"mu_a": 0}, "mu.mu_a: must be positive, got 0"),  # was taken for one not given
    ({"mu_v": "x"}, 'mu.mu_v: must be a number, got "x"'),  # failed inside a plan's recipe
    ({"mu_l": float("nan")}, "mu.mu_l: nan is not a number"),
    ({"muv": 0.05}, 'mu.muv: unknown key — did you mean "mu_v"?'),  # was ignored
])
def test_solve_position_refuses_scale_factors_a_file_could_not_hold(mu, message):
    """``solve_position(mech, mu=…)`` reads its scale factors as a file's [scales] is."""
    mech = load("samples/press.toml")
    with pytest.raises(InputError) as exc:
        solve_position(mech, mu=mu)
    assert str(exc.value).startswith(f"solve_position: {message}")
    sol = solve_position(mech, mu={"mu_v": 0.1, "mu_a": None})  # None: chosen, as absent
    assert sol.mu_v == 0.1 and sol.segments["pa"] == pytest.approx(30)


@pytest.mark.parametrize(("options", "message"), [
    ({"n_positions": 0}, "n_positions: must be a whole number from 1, got 0"),  # no positions
    ({"n_positions": -3}, "n_positions: must be a whole number from 1, got -3"),
    ({"n_positions": 1.5}, "n_positions: must be a whole number from 1, got 1.5"),
    ({"samples": 1}, "samples: must be a whole number from 2, got 1"),  # an IndexError
])
def test_analyse_cycle_refuses_a_count_that_is_not_one(options, message):
    """``analyse_cycle(mech, 0)`` gave a cycle without positions, as ``plans cycle
    --positions 0`` does not; a count of 1.5 or a one-angle search failed inside numpy."""
    from plans.cycle import analyse_cycle

    mech = load("samples/press.toml")
    with pytest.raises(InputError) as exc:
        analyse_cycle(mech, **options)
    assert str(exc.value) == f"analyse_cycle: {message}"
    assert len(analyse_cycle(mech, 1).positions) == 1


@pytest.mark.parametrize("n", ["3", 2.5, None])
def test_a_variant_that_is_not_a_row_number_is_told_so(n):
    """variant("3") said "variant 3 is not in the table (it has 0, 1, 2, 3, …)"."""
    with pytest.raises(InputError) as info:
        variant(n)
    assert info.value.problems == [f"variant {n!r}: a variant is the whole number of a row, e.g. 3"]
    assert variant(3.0).name == variant(3).name  # a whole number all the same


def test_solve_position_takes_any_positive_scale_factor():
    """The bounds of a typed [scales] are not the API's: a sheet 0.03° short of seed 001's
    dead point chooses μa = 5e8 (m/s²)/mm for its plans."""
    mech = load("samples/fourbar.toml")
    sol = solve_position(mech, mech.driver.phi, mu={"mu_v": 1e-12, "mu_a": 5e8})
    assert (sol.mu_v, sol.mu_a) == (1e-12, 5e8)
    with pytest.raises(InputError, match=r"mu\.mu_a: inf is out of range"):
        solve_position(mech, mu={"mu_a": float("inf")})
