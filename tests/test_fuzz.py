"""Property-based hardening tests (hypothesis).

1. Random *valid* mechanisms of each of the five dyad kinds, with geometry drawn freely
   (so that many do not assemble at the given angle, or sit near a dead point): either
   the plans satisfy the rigid-body and guide invariants, or the engine raises a clear
   :class:`~plans.errors.PlansError` (assembly, singularity, ambiguous hint) on one line —
   never another exception, never NaN.
2. Random mutations of valid files (deleted lines and keys, wrong types, swapped names,
   garbage bytes, truncation): the CLI exits 0 with its output, or 2 with one line per
   problem, no traceback and no output file; ``from_dict`` raises only InputError.
3. Hostile generators: long dotted headers with one problem, tiny and huge scale factors
   of a measurement file, control and bidi characters in a title and a file name, and a
   table's designation of any width: one located line and exit 2 or a correct result,
   and no raw control character on the terminal.

The examples are derandomized so CI is reproducible; ``PLANS_FUZZ_EXAMPLES=2000`` runs a
longer exploration locally.
"""

from __future__ import annotations

import copy
import os
import tomllib
import xml.etree.ElementTree as ET
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from plans.cli import main
from plans.errors import InputError, PlansError
from plans.kinematics.solver import Solver
from plans.model import Mechanism, from_dict
from plans.model.structure import DyadKind
from plans.plan.solution import solve_position

ROOT = Path(__file__).resolve().parent.parent
SCALE = float(os.environ.get("PLANS_FUZZ_EXAMPLES", "0")) or None


def fuzz(n: int):
    return settings(
        max_examples=int(SCALE or n),
        deadline=None,
        derandomize=SCALE is None,
        database=None,
        suppress_health_check=list(HealthCheck),
    )


# =======================================================================================
# 1. random valid mechanisms of each dyad kind
# =======================================================================================

length = st.floats(0.01, 1.0)
angle = st.floats(-360.0, 360.0)
speed = st.floats(0.1, 100.0)
coord = st.floats(-1.0, 1.0)
sense = st.sampled_from(["ccw", "cw"])


def _driver(draw) -> str:
    return (
        f"[driver]\nlink = 1\nangle_deg = {draw(angle)!r}\nomega = {draw(speed)!r}\n"
        f'sense = "{draw(sense)}"\n'
        f'from = "{draw(st.sampled_from(["+x", "+y", "-x", "-y"]))}"\n'
        f'measured = "{draw(sense)}"\n'
    )


@st.composite
def rrr(draw):
    """Four-bar: crank OA, coupler AB with a point E off its axis, rocker DB."""
    a, b, c = draw(length), draw(length), draw(length)
    dx, dy = draw(coord), draw(coord)
    rel = draw(st.sampled_from(["above", "below", "left of", "right of"]))
    return f"""
[frame]
O = [0.0, 0.0]
D = [{dx!r}, {dy!r}]
{_driver(draw)}
[links.1]
axis = ["O", "A"]
points = {{ A = {a!r} }}
[links.2]
axis = ["A", "B"]
points = {{ B = {b!r}, E = [{draw(coord)!r}, {draw(coord)!r}] }}
[links.3]
axis = ["D", "B"]
points = {{ B = {c!r}, S3 = {c / 2!r} }}
[assembly]
B = "{rel} AD"
"""


@st.composite
def rrp(draw):
    """Crank-slider on a fixed guide of any angle and offset."""
    r, rod = draw(length), draw(length)
    rel = draw(st.sampled_from(["right of O", "left of O", "above O", "below O"]))
    return f"""
[frame]
O = [0.0, 0.0]
{_driver(draw)}
[links.1]
axis = ["O", "A"]
points = {{ A = {r!r} }}
[links.2]
axis = ["A", "B"]
points = {{ B = {rod!r}, S2 = [{draw(coord)!r}, {draw(coord)!r}] }}
[links.3]
points = {{ B = 0, M = [0.02, 0.01] }}
[[sliders]]
link = 3
guide = {{ link = 0, through = [{draw(coord)!r}, {draw(coord)!r}], angle_deg = {draw(angle)!r} }}
[assembly]
B = "{rel}"
"""


@st.composite
def rpr(draw):
    """Slotted link: the block on the crank pin slides in the rocker BC (offset guide)."""
    r = draw(length)
    bx, by = draw(coord), draw(coord)
    offset = draw(st.one_of(st.just(0.0), st.floats(-0.2, 0.2)))
    hint = draw(st.sampled_from(["", '[assembly]\nA = "above B"\n', '[assembly]\nA = "below B"\n']))
    return f"""
[frame]
O = [0.0, 0.0]
B = [{bx!r}, {by!r}]
{_driver(draw)}
[links.1]
axis = ["O", "A"]
points = {{ A = {r!r} }}
[links.2]
points = {{ A = 0 }}
[links.3]
axis = ["B", "C"]
points = {{ C = {draw(length)!r}, S3 = [{draw(coord)!r}, {draw(coord)!r}] }}
[[sliders]]
link = 2
guide = {{ link = 3, offset = {offset!r} }}
{hint}"""


@st.composite
def prp(draw):
    """Tangent mechanism: a block on the crank's guide hinged to a slider on a fixed guide."""
    return f"""
[frame]
O = [0.0, 0.0]
{_driver(draw)}
[links.1]
axis = ["O", "A"]
points = {{ A = {draw(length)!r} }}
[links.2]
points = {{ C = 0 }}
[links.3]
points = {{ C = 0, M = [{draw(coord)!r}, {draw(coord)!r}] }}
[[sliders]]
link = 2
guide = {{ link = 1, angle_deg = {draw(angle)!r} }}
[[sliders]]
link = 3
guide = {{ link = 0, through = [{draw(coord)!r}, {draw(coord)!r}], angle_deg = {draw(angle)!r} }}
"""


@st.composite
def rpp(draw):
    """Scotch yoke with a slot at any angle to the yoke, on a guide at any angle."""
    return f"""
[frame]
O = [0.0, 0.0]
{_driver(draw)}
[links.1]
axis = ["O", "A"]
points = {{ A = {draw(length)!r} }}
[links.2]
points = {{ A = 0 }}
[links.3]
axis = ["D", "E"]
points = {{ E = {draw(length)!r}, S3 = [{draw(coord)!r}, {draw(coord)!r}] }}
[[sliders]]
link = 2
guide = {{ link = 3, angle_deg = {draw(angle)!r}, through = [{draw(coord)!r}, 0.0] }}
[[sliders]]
link = 3
point = "D"
guide = {{ link = 0, through = [{draw(coord)!r}, {draw(coord)!r}], angle_deg = {draw(angle)!r} }}
"""


KINDS = {"RRR": rrr, "RRP": rrp, "RPR": rpr, "PRP": prp, "RPP": rpp}


def _close(a: complex, b: complex, scale: float, tol: float = 1e-7) -> bool:
    return abs(a - b) <= tol * max(scale, 1e-300)


def check_plans(mech: Mechanism, sol) -> None:
    """Rigid-body and guide invariants of a solved position, and no NaN anywhere."""
    m = sol.motion
    pos = {k: complex(v[0]) for k, v in m.position.items()}
    vel = {k: complex(v[0]) for k, v in m.velocity.items()}
    acc = {k: complex(v[0]) for k, v in m.acceleration.items()}
    for table in (pos, vel, acc, sol.omega, sol.epsilon, sol.segments):
        assert all(np.isfinite(complex(v)) for v in table.values()), table
    size = max(abs(z) for z in pos.values()) + 1.0
    vmax = max(abs(z) for z in vel.values()) + abs(mech.driver.omega) * size
    amax = max(abs(z) for z in acc.values()) + vmax**2 / size
    d = mech.driver
    assert abs(vel[d.tip]) == pytest.approx(abs(d.omega) * d.length, rel=1e-9)
    for lid, link in mech.links.items():
        w, e = sol.omega[lid], sol.epsilon[lid]
        names = list(link.points)
        for i, p in enumerate(names):
            for q in names[i + 1 :]:
                r = pos[q] - pos[p]
                # the link keeps its shape, and moves as a rigid body
                assert abs(abs(r) - abs(link.points[q] - link.points[p])) <= 1e-9 * size
                assert _close(vel[q] - vel[p], 1j * w * r, vmax)
                assert _close(acc[q] - acc[p], (1j * e - w * w) * r, amax)
    for s in mech.sliders:
        g = s.guide
        st_g = m.links[g.link]
        origin, rotor = complex(st_g.origin[0]), complex(st_g.rotor[0])
        u = rotor * g.direction
        X = pos[s.point]
        # the sliding point stays on the guide, and moves along it relative to the guide
        assert abs(((X - (origin + rotor * g.point)) * u.conjugate()).imag) <= 1e-9 * size
        rel = vel[s.point] - (complex(st_g.v[0]) + 1j * float(st_g.omega[0]) * (X - origin))
        assert abs((rel * u.conjugate()).imag) <= 1e-7 * vmax
        # the slider turns with its guide
        assert sol.omega[s.link] == pytest.approx(float(st_g.omega[0]), abs=1e-9 * vmax / size)


def solve_or_clear_error(text: str, kind: str):
    try:
        mech = from_dict(tomllib.loads(text), "<fuzz>")  # e.g. two pivots drawn at one place
        solver = Solver(mech)
        sol = solve_position(mech, solver=solver)
    except PlansError as exc:
        msg = str(exc)
        assert msg and "\n" not in msg.strip(), msg
        assert "nan" not in msg.lower().replace("nan ", "").split("(")[0], msg
        return None
    assert [g.kind for g in solver.structure.groups] == [DyadKind[kind]]
    check_plans(mech, sol)
    return sol


@pytest.mark.parametrize("kind", sorted(KINDS))
def test_random_mechanisms_solve_or_fail_clearly(kind):
    solved = []

    @fuzz(60)
    @given(KINDS[kind]())
    def run(text):
        solved.append(solve_or_clear_error(text, kind) is not None)

    run()
    assert any(solved), f"no random {kind} mechanism assembled: the generator is too wild"


# =======================================================================================
# 2. mutations of valid files
# =======================================================================================

SEEDS = {
    "press": (ROOT / "samples" / "press.toml").read_text("utf-8"),
    "fourbar": (ROOT / "samples" / "fourbar.toml").read_text("utf-8"),
}

GARBAGE_VALUES = [
    '"text"', "true", "-1", "0", "1e300", "-1e-300", "nan", "inf", "[]", "[1, 2, 3]",
    "{}", '{ x = 1 }', "9" * 30, '"O"', "[[1]]", "1979-05-27", '"A\\nB"',
]


TABLE = (ROOT / "plans" / "data" / "table2.toml").read_text("utf-8")


SEED_TEXTS = tuple(sorted(SEEDS.values()))


@st.composite
def mutated(draw, seeds=SEED_TEXTS):
    """A valid file with one to three random mutations, as bytes."""
    text = draw(st.sampled_from(seeds))
    names = ["A", "AB", "AD", "B", "C", "D", "O", "Q", "S3", "n", "rpm"]
    for _ in range(draw(st.integers(1, 3))):
        lines = text.split("\n")
        op = draw(st.sampled_from(["delete", "value", "swap", "garbage", "truncate", "duplicate", "retype"]))
        i = draw(st.integers(0, len(lines) - 1))
        if op == "delete":
            del lines[i]
        elif op == "duplicate":
            lines.insert(i, lines[i])
        elif op == "value" and "=" in lines[i]:
            key = lines[i].split("=", 1)[0]
            lines[i] = f"{key}= {draw(st.sampled_from(GARBAGE_VALUES))}"
        elif op == "retype":  # numbers become texts, texts numbers
            line = lines[i]
            if '"' in line:
                lines[i] = line.replace('"', "", 2)
            elif "=" in line:
                k, v = line.split("=", 1)
                lines[i] = f'{k}= "{v.strip()}"'
        elif op == "swap":
            a, b = draw(st.sampled_from(names)), draw(st.sampled_from(names))
            lines[i] = (lines[i].replace(f'"{a}"', '"\0"').replace(f'"{b}"', f'"{a}"')
                        .replace('"\0"', f'"{b}"'))
            lines[i] = lines[i].replace(f"{a} =", "\0").replace(f"{b} =", f"{a} =").replace("\0", f"{b} =")
        text = "\n".join(lines)
        if op == "truncate":
            text = text[: draw(st.integers(0, len(text)))]
    data = text.encode("utf-8")
    if draw(st.booleans()) and draw(st.booleans()):  # garbage bytes somewhere
        at = draw(st.integers(0, len(data)))
        data = data[:at] + draw(st.binary(min_size=1, max_size=8)) + data[at:]
    return data


def _check_cli(tmp: Path, data: bytes, capsys, *, table: bool = False) -> int:
    src = tmp / "in.toml"
    out = tmp / "out.txt"
    out.unlink(missing_ok=True)
    src.write_bytes(data)
    source = ["--variant", "3", "--table", str(src)] if table else [str(src)]
    code = main(["solve", *source, "-o", str(out)])
    _stdout, stderr = capsys.readouterr()
    assert code in (0, 2), stderr
    assert "Traceback" not in stderr and "internal error" not in stderr
    assert src.read_bytes() == data  # the input is never written
    if code == 0:
        assert out.is_file() and out.stat().st_size > 0
        return 0
    assert not out.exists()
    assert [p.name for p in tmp.iterdir()] == ["in.toml"]  # no temporary left either
    lines = stderr.splitlines()
    assert lines and all(line.startswith("plans solve: ") for line in lines), stderr
    assert all(len(line) < 700 for line in lines), stderr
    return 2


def test_mutated_files_exit_0_or_2_without_traceback(tmp_path, capsys):
    codes = []

    @fuzz(250)
    @given(mutated())
    def run(data):
        codes.append(_check_cli(tmp_path, data, capsys))

    run()
    assert 2 in codes


def _paths(node, prefix=()):
    """Every key path of a parsed file: ("driver", "sense"), ("sliders", 1, "guide"), …"""
    out = [prefix] if prefix else []
    items = node.items() if isinstance(node, dict) else enumerate(node) if isinstance(node, list) else ()
    for key, value in items:
        out += _paths(value, (*prefix, key))
    return out


def test_mutated_variant_tables_exit_0_or_2_without_traceback(tmp_path, capsys):
    codes = []

    @fuzz(100)
    @given(mutated(seeds=(TABLE,)))
    def run(data):
        codes.append(_check_cli(tmp_path, data, capsys, table=True))

    run()
    assert 2 in codes


PATHS_TO_BREAK = st.sampled_from(
    sorted({p for text in SEEDS.values() for p in _paths(tomllib.loads(text))}, key=repr)
)


SCALAR = (
    st.none() | st.booleans() | st.integers() | st.floats() | st.text(max_size=20)
    | st.sampled_from(["O", "A", "B", "C", "D", "+y", "cw", "above BD", "1"])
)
NESTED = st.lists(SCALAR, max_size=3) | st.dictionaries(st.text(max_size=5), SCALAR, max_size=3)
ANY_VALUE = SCALAR | NESTED | st.lists(NESTED, max_size=2)


@st.composite
def broken_dicts(draw):
    data = tomllib.loads(draw(st.sampled_from(sorted(SEEDS.values()))))
    for _ in range(draw(st.integers(1, 4))):
        path = draw(PATHS_TO_BREAK)
        node = data
        for key in path[:-1]:
            try:
                node = node[key]
            except (KeyError, IndexError, TypeError):
                break
        else:
            value = draw(ANY_VALUE)
            try:
                if value is None:
                    del node[path[-1]]
                else:
                    node[path[-1]] = value
            except (KeyError, IndexError, TypeError):
                pass
    return data


@fuzz(300)
@given(broken_dicts())
def test_broken_dicts_raise_only_input_errors(data):
    before = copy.deepcopy(data)
    try:
        mech = from_dict(data, "<fuzz>")
    except InputError as exc:
        assert exc.problems
        assert all(p and "\n" not in p for p in exc.problems), exc.problems
        return
    finally:
        assert repr(data) == repr(before)  # validation never changes its input
    try:
        solve_position(mech)
    except PlansError as exc:
        assert "\n" not in str(exc).strip()


def test_all_five_kinds_are_generated():
    # the generators above are what the random tests claim to cover
    assert set(KINDS) == {k.name for k in DyadKind}


# =======================================================================================
# 3. hostile generators: dotted headers, tiny scales, control characters, designation
#    widths (issue 22): one located line and exit 2, or a correct result
# =======================================================================================

PRESS = (ROOT / "samples" / "press.toml").read_text("utf-8")
CHECK_PRESS = (ROOT / "samples" / "check_press.toml").read_text("utf-8")
#: characters no terminal may receive raw: C0, DEL, C1, the bidi controls
HOSTILE_CHARS = st.sampled_from([*map(chr, range(0, 32)), "\x7f", "\x85", "\x9b", "\u061c", "\u200e",
                                 "\u200f", "\u2028", "\u202a", "\u202e", "\u2066", "\u2069", "\ufeff"])
RAW = set(map(chr, range(0, 9))) | set(map(chr, range(11, 32))) | {"\x7f", "\x85", "\x9b", "\u202e", "\u2066"}


def _clean_run(capsys, argv, codes=(0, 2)) -> tuple[int, str, str]:
    code = main([str(a) for a in argv])
    out, err = capsys.readouterr()
    assert code in codes, err
    assert "Traceback" not in err and "internal error" not in err
    assert not RAW & set(err), repr(err)
    return code, out, err


@fuzz(25)
@given(depth=st.integers(1, 400), problem=st.sampled_from(["omega = -20", "sense = \"sideways\"",
                                                           "angle_deg = \"x\""]))
def test_a_dotted_header_and_one_problem_is_one_located_line(tmp_path_factory, depth, problem):
    """A long dotted table header ([a.a.a…]) and one problem: one located line, exit 2.
    (Deep headers of 10,000 levels are the benchmark's: benchmarks/hostile.py.)"""
    d = tmp_path_factory.mktemp("dotted")
    key = problem.split(" = ")[0]
    text = PRESS.replace(f"\n{key} = ", f"\n{problem}\n# {key} = ", 1)
    text += "\n[" + ".".join(["a"] * depth) + "]\nx = 1\n"
    path = d / "m.toml"
    path.write_text(text, "utf-8")
    code = main(["solve", str(path), "-o", str(d / "out.txt")])
    assert code == 2 and not (d / "out.txt").exists()


@fuzz(40)
@given(mu=st.one_of(st.floats(min_value=5e-324, max_value=1e-9, exclude_max=True),
                    st.floats(min_value=1e6, max_value=1e308, exclude_min=True)),
       key=st.sampled_from(["mu_l", "mu_v", "mu_a"]))
def test_tiny_and_huge_scales_of_a_measurement_file_are_located(tmp_path_factory, capsys, mu, key):
    d = tmp_path_factory.mktemp("scales")
    (d / "press.toml").write_text(PRESS, "utf-8")
    text = CHECK_PRESS.replace(f"\n{key} = ", f"\n{key} = {mu!r}\n# ", 1)
    (d / "m.toml").write_text(text, "utf-8")
    _, out, err = _clean_run(capsys, ["check", d / "m.toml", "--json"], codes=(2,))
    assert out == "" and f"scales.{key}:" in err and ("too small" in err or "out of range" in err)


@fuzz(30)
@given(junk=st.lists(HOSTILE_CHARS, min_size=1, max_size=6), where=st.sampled_from(["title", "name"]))
def test_control_characters_reach_no_terminal(tmp_path_factory, capsys, junk, where):
    d = tmp_path_factory.mktemp("ctl")
    (d / "press.toml").write_text(PRESS, "utf-8")
    esc = "".join(f"\\u{ord(c):04x}" for c in junk)
    if where == "title":
        path = d / "m.toml"
        path.write_text(CHECK_PRESS.replace('title = "', f'title = "{esc}', 1), "utf-8")
        _, out, _ = _clean_run(capsys, ["check", path, "--svg", d / "o.svg"], codes=(0, 1, 2))
        if (d / "o.svg").exists():
            ET.parse(d / "o.svg")
    else:
        name = "m" + "".join(c for c in junk if c not in "\0/") + ".toml"
        try:
            path = d / name
            path.write_text(CHECK_PRESS, "utf-8")
        except (OSError, ValueError):
            return
        _, out, _ = _clean_run(capsys, ["check", path, path.with_name("none.toml")], codes=(0, 1, 2))
    assert not RAW & set(out), repr(out)


@fuzz(6)
@given(width=st.integers(1, 300), align=st.sampled_from([">", "<", "^", "0>"]))
def test_designation_widths_are_said_not_drawn_past(tmp_path_factory, capsys, width, align):
    """A table's designation of any width: its sheet, or "does not fit" in one line."""
    d = tmp_path_factory.mktemp("designation")
    table = d / "t.toml"
    table.write_text(TABLE.replace('designation = "ПМ.01.{n:02d}"',
                                   f'designation = "ПМ.{{n:{align}{width}}}"'), "utf-8")
    _clean_run(capsys, ["sheet", "--variant", "3", "--table", table, "-o", d / "s.svg"])
