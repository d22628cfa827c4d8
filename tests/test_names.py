"""Point names as textbooks letter them (issue 24, item 5): P, Q, R, S, K, N, K1… are
points like any other; the plans' own letters (the pole p, the Coriolis point k, the
normal components' ends n1, n2…) stay apart by construction, a point whose letter would be
one of them being written with a prime on the plans. And a negative axis end is refused
with a fix that keeps the link where it was."""

from __future__ import annotations

import tomllib

import pytest

from plans.check import check, load
from plans.errors import InputError
from plans.model import from_dict
from plans.plan import plan_name, solve_position

FOURBAR = """
name = "Four-bar lettered as a textbook letters it"
trace = ["K"]
[frame]
A = [0.0, 0.0]
P = [-0.135, 0.0]
[driver]
link = 1
angle_deg = 40
rpm = 149.2
[links.1]
axis = ["A", "B"]
points = { B = 0.0625 }
[links.2]
axis = ["B", "N1"]
points = { N1 = 0.21, K = 0.315 }
[links.3]
axis = ["P", "N1"]
points = { N1 = 0.1025, Q = 0.05 }
[assembly]
N1 = "above BP"
"""

PLAIN = (FOURBAR.replace('"P"', '"D"').replace("P = [", "D = [").replace("BP", "BD")
         .replace("N1", "C").replace('"K"', '"E"').replace("K = ", "E = ").replace("Q = ", "S3 = "))


def test_plan_letters_of_the_plans_own_are_primed():
    assert [plan_name(n) for n in ("P", "K", "K2", "N1", "N", "Q", "R", "S", "PI", "A3")] == \
        ["p′", "k′", "k2′", "n1′", "n", "q", "r", "s", "pi′", "a3"]


def test_textbook_names_are_points_like_any_other():
    """P, K, N1 and Q solve as D, E, C and S3 do: the same numbers, the plans' letters
    apart from the pole p and the normal points n1, n2."""
    named = solve_position(from_dict(tomllib.loads(FOURBAR)))
    plain = solve_position(from_dict(tomllib.loads(PLAIN)))
    rename = {"p′": "d", "n1′": "c", "k′": "e", "q": "s3"}
    for kind in ("velocity", "acceleration"):
        a, b = getattr(named, kind), getattr(plain, kind)
        assert a.pole in ("p", "π") and a.pole not in rename
        for name, pt in a.points.items():
            assert pt.value == pytest.approx(b.points[rename.get(name, name)].value, abs=1e-15)
    assert set(named.velocity.points) >= {"p′", "n1′", "k′", "q"}
    # the normal components' ends are n1, n2; the point N1's image is n1′
    assert {"n1", "n2", "n1′"} <= set(named.acceleration.points)
    assert named.acceleration.segments["n1n1′"] == pytest.approx(plain.acceleration.segments["n1c"])
    assert named.velocity.segments["pk′"] == pytest.approx(plain.velocity.segments["pe"])


def test_a_primed_letter_reads_in_a_measurement_file(tmp_path):
    """A student types the prime as ' (a key in quotes): "pk'" is pk′."""
    mech = tmp_path / "named.toml"
    mech.write_text(FOURBAR, encoding="utf-8")
    sol = solve_position(from_dict(tomllib.loads(FOURBAR)))
    pk = sol.velocity.segments["pk′"]
    meas = tmp_path / "student.toml"
    meas.write_text(f'mechanism = "named.toml"\n[scales]\nmu_l = {sol.mu_l}\nmu_v = {sol.mu_v}\n'
                    f'mu_a = {sol.mu_a}\n[segments]\n"pk\'" = {pk:.3f}\n"pn1′" = '
                    f'{sol.velocity.segments["pn1′"]:.3f}\n', encoding="utf-8")
    result = check(load(meas))
    assert result.ok
    assert [d.item.name for d in result.deviations] == ["pk′", "pn1′"]


def test_a_negative_axis_end_is_refused_with_a_fix_that_keeps_the_link_in_place():
    """Writing the end positive alone would turn the link to the other side of its pivot,
    its other points being measured along the reversed axis: the message gives them all."""
    text = PLAIN.replace("points = { C = 0.1025, S3 = 0.05 }",
                         "points = { C = -0.1025, S3 = -0.05125, F = [-0.08, 0.02] }")
    with pytest.raises(InputError) as info:
        from_dict(tomllib.loads(text), "m.toml")
    (line,) = info.value.problems
    assert "negative length -0.1025" in line
    assert "write C = 0.1025 and the other points with both signs changed (S3 = 0.05125, " \
           "F = [0.08, -0.02])" in line
    assert "(write C = 0.1025)" not in line
    fixed = PLAIN.replace("points = { C = 0.1025, S3 = 0.05 }",
                          "points = { C = 0.1025, S3 = 0.05125, F = [0.08, -0.02] }")
    # the fix puts S3 where the file meant it: midway between D and C
    sol = solve_position(from_dict(tomllib.loads(fixed)))
    D, C, S3 = (sol.positions[n] for n in ("D", "C", "S3"))
    assert abs(S3 - (D + C) / 2) < 1e-15
