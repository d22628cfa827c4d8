"""The engine's paths agree: the recorded array solve, its one-angle scalar path and the
blocked bulk sweep run the same group kernels (``plans/kinematics/kernels.py``), so at every angle
they must give the same numbers to rounding, and fail in the same words where a group
does not close or a plan is singular."""

from __future__ import annotations

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as hs

from plans.errors import AssemblyError, SingularPlanError
from plans.kinematics.solver import Motion, Solver
from plans.model.scenes import SCENES

ALL = sorted(SCENES)
TOL = 1e-14  # relative to the largest value of the quantity at that angle


def _rel(a, b) -> float:
    scale = max(max(abs(complex(v)) for v in b.values()), 1e-300)
    return max(abs(complex(a[k]) - complex(b[k])) / scale for k in b)


def _angles(scene, n=25):
    return scene.mechanism().driver.phi + np.linspace(0, 2 * np.pi, n, endpoint=False)


@pytest.mark.parametrize("name", ALL)
def test_scalar_path_equals_array_path(name):
    """Every point, link and recorded construction of ``solve_one`` equals ``solve``."""
    mech = SCENES[name].mechanism()
    sv = Solver(mech)
    phi = _angles(SCENES[name])
    arr = sv.solve(phi)
    compared = 0
    for k, x in enumerate(phi):
        if not arr.valid[k]:
            with pytest.raises((AssemblyError, SingularPlanError)):
                sv.solve_one(float(x))
            continue
        one = sv.solve_one(float(x))
        assert type(one.position[mech.driver.tip]) is complex
        for field in ("position", "velocity", "acceleration"):
            got, want = getattr(one, field), getattr(arr, field)
            assert set(got) == set(want)
            assert _rel(got, {n: v[k] for n, v in want.items()}) < TOL, (field, k)
        for lid, st in arr.links.items():
            w = max(abs(mech.driver.omega), 1.0)
            assert abs(one.links[lid].omega - st.omega[k]) <= TOL * w
            assert abs(one.links[lid].epsilon - st.epsilon[k]) <= TOL * w * w * 1e2
        for g1, ga in zip(one.groups, arr.groups, strict=True):
            for c1, ca in ((g1.velocity, ga.velocity), (g1.acceleration, ga.acceleration)):
                assert abs(c1.sine - ca.sine[k]) < 1e-14
                for r1, ra in zip(c1.routes, ca.routes, strict=True):
                    assert (r1.relation, r1.unknown, r1.base) == (ra.relation, ra.unknown, ra.base)
                    assert abs(r1.direction - ra.direction[k]) < 1e-14
                    assert [t.label for t in r1.terms] == [t.label for t in ra.terms]
                    for t1, ta in zip(r1.terms, ra.terms, strict=True):
                        assert abs(t1.value - ta.value[k]) <= TOL * max(abs(ta.value[k]), 1.0)
        compared += 1
    assert compared >= 10


def test_scalar_path_fails_in_the_array_paths_words():
    """A group that misses, and a dead point, raise the same message on both paths."""
    mech = SCENES["fourbar"].mechanism()  # seed 001's four-bar: not a full turn
    sv = Solver(mech)
    phi = np.radians(np.arange(0, 360, 1.0))
    arr = sv.solve(phi)
    bad = np.nonzero(~arr.valid)[0]
    assert bad.size > 0
    k = int(bad[0])
    with pytest.raises(AssemblyError) as one:
        sv.solve_one(float(phi[k]))
    assert str(one.value) == str(arr.groups[0].failure(k, mech.driver.at(float(phi[k]))))
    assert "misses by" in str(one.value)


@pytest.mark.parametrize("name", ALL)
@pytest.mark.parametrize("block", [7, 8192])
def test_sweep_equals_array_path(name, block):
    """The blocked sweep gives every point, ω, ε, conditioning and validity of ``solve``;
    a block of 7 over 101 angles puts block edges everywhere, the last one ragged."""
    mech = SCENES[name].mechanism()
    sv = Solver(mech)
    phi = mech.driver.phi + np.linspace(0, 2 * np.pi, 101)
    arr = sv.solve(phi)
    sw = sv.sweep(phi, block=block)
    np.testing.assert_array_equal(sw.valid, arr.valid)
    ok = arr.valid
    assert ok.sum() > 50
    for field in ("position", "velocity", "acceleration"):
        got, want = getattr(sw, field), getattr(arr, field)
        assert list(got) == list(want)
        scale = np.max([np.abs(v[ok]) for v in want.values()], axis=0)
        for k in want:
            assert got[k].shape == phi.shape
            assert np.all(np.abs(got[k][ok] - want[k][ok]) <= TOL * scale), (field, k)
    for lid, st in arr.links.items():
        w = abs(mech.driver.omega)
        np.testing.assert_allclose(sw.omega[lid][ok], st.omega[ok], rtol=0, atol=TOL * w)
        np.testing.assert_allclose(sw.epsilon[lid][ok], st.epsilon[ok], rtol=0, atol=1e2 * TOL * w * w)
    assert list(sw.sine) == [g.group.label for g in arr.groups]
    for g in arr.groups:
        np.testing.assert_allclose(sw.sine[g.group.label][ok], np.abs(g.velocity.sine[ok]),
                                   rtol=0, atol=1e-14)
    np.testing.assert_allclose(sw.min_sine[ok], arr.min_sine[ok], rtol=0, atol=1e-14)


def test_sweep_keeps_the_shape_of_its_angles_as_solve_does():
    """A 2-D grid of angles (rows of φ1, a set of runs) gives arrays of that shape, as
    ``solve`` and numpy do; the sweep had flattened it to 1-D, so sw.position[k][i, j]
    failed and a reshape by hand had to know the order. A single angle is an array of
    one, as in ``solve``; ``into`` takes a sweep of the same shape."""
    sv = Solver(SCENES["press"].mechanism())
    phi = np.radians(np.arange(0.0, 360.0, 15.0)).reshape(4, 6)
    sw, m = sv.sweep(phi, block=5), sv.solve(phi)
    assert sw.phi.shape == sw.valid.shape == sw.min_sine.shape == phi.shape
    np.testing.assert_array_equal(sw.phi, phi)
    for field in ("position", "velocity", "acceleration"):
        for k, want in getattr(m, field).items():
            got = getattr(sw, field)[k]
            assert got.shape == phi.shape, (field, k)
            np.testing.assert_allclose(got, want, rtol=0, atol=1e-12)
    for lid, st in m.links.items():
        assert sw.omega[lid].shape == sw.epsilon[lid].shape == phi.shape
        np.testing.assert_allclose(sw.omega[lid], st.omega, rtol=0, atol=1e-12)
    assert all(v.shape == phi.shape for v in (*sw.sine.values(), *sw.pivot.values()))
    assert sv.trusted(sw).shape == phi.shape
    flat = sv.sweep(phi.ravel())
    np.testing.assert_array_equal(sw.velocity["D"].ravel(), flat.velocity["D"])
    assert sv.sweep(0.5).position["D"].shape == sv.solve(0.5).position["D"].shape == (1,)
    keep = sw.position["D"]
    again = sv.sweep(phi + 0.1, into=sw)
    assert again.position["D"] is keep and again.phi.shape == phi.shape
    np.testing.assert_array_equal(again.position["D"], sv.sweep(phi + 0.1).position["D"])
    with pytest.raises(ValueError, match=r"shaped \(4, 6\), not \(24,\)"):
        sv.sweep(phi.ravel(), into=sw)


def test_sweep_fixed_points_cost_no_memory_and_cannot_be_written():
    mech = SCENES["press"].mechanism()
    sw = Solver(mech).sweep(np.linspace(0, 1, 1000))
    for name in mech.frame:
        x = sw.position[name]
        assert x.strides == (0,) and not x.flags.writeable
        assert np.all(x == mech.frame[name]) and np.all(sw.velocity[name] == 0)
    assert sw.omega[mech.driver.link].strides == (0,)
    assert np.all(sw.omega[mech.driver.link] == mech.driver.omega)


@pytest.mark.parametrize("n", [1, 13, 1000])
def test_sweep_arrays_are_cut_from_one_block_without_overlapping(n):
    """Every writable array of a sweep is its own stretch of one allocation: writing one
    leaves every other unchanged (n = 13 leaves the booleans a ragged last slot)."""
    sw = Solver(SCENES["press"].mechanism()).sweep(np.linspace(0, 1, n))
    arrays = [sw.phi, sw.valid, *sw.sine.values()]
    for store in (sw.position, sw.velocity, sw.acceleration, sw.omega, sw.epsilon):
        arrays += [a for a in store.values() if a.flags.writeable]
    assert len(arrays) == 28 and all(a.shape == (n,) for a in arrays)
    bases = {id(a.base if a.base is not None else a) for a in arrays}
    assert len(bases) <= 2  # the block, and its boolean view
    before = [a.copy() for a in arrays]
    for i, a in enumerate(arrays):
        a[...] = True if a.dtype == bool else 7.0 + i
        for j, b in enumerate(arrays):
            if j != i:
                np.testing.assert_array_equal(b, before[j])
        a[...] = before[i]


def test_sweep_into_reuses_the_arrays_and_keeps_the_callers_angles():
    mech = SCENES["crank_rocker"].mechanism()
    sv = Solver(mech)
    a = np.linspace(0, 2 * np.pi, 300)
    b = a + 0.5
    first = sv.sweep(a, block=64)
    keep = dict(first.position.items())
    again = sv.sweep(b, block=64, into=first)
    fresh = sv.sweep(b, block=64)
    for k in fresh.position:
        assert again.position[k] is keep[k]  # the same arrays, overwritten
        np.testing.assert_array_equal(again.position[k], fresh.position[k])
        np.testing.assert_array_equal(again.acceleration[k], fresh.acceleration[k])
    np.testing.assert_array_equal(again.phi, b)
    np.testing.assert_array_equal(a, np.linspace(0, 2 * np.pi, 300))  # the caller's input
    with pytest.raises(ValueError, match="300 angles, not 299"):
        sv.sweep(b[:-1], into=first)
    press = Solver(SCENES["press"].mechanism())
    with pytest.raises(ValueError, match="another mechanism"):
        press.sweep(b, into=first)


def test_solution_built_in_one_step_equals_the_dataclass_built():
    """solve_position fills a Solution's dict in one step, and solve_one a Motion's; each
    holds every field, equals one built by the frozen dataclass's own __init__, and stays
    frozen."""
    import dataclasses

    from plans.plan.solution import Solution, solve_position

    mech = SCENES["press"].mechanism()
    sol = solve_position(mech, 0.7)
    names = {f.name for f in dataclasses.fields(Solution)}
    assert set(vars(sol)) == names
    again = Solution(**{n: getattr(sol, n) for n in names})
    assert again == sol
    with pytest.raises(dataclasses.FrozenInstanceError):
        sol.phi = 0.0  # type: ignore[misc]
    m = sol.scalar  # the Motion it was built from, made the same way
    fields = {f.name for f in dataclasses.fields(Motion)}
    assert set(vars(m)) == fields
    assert Motion(**{n: getattr(m, n) for n in fields}) == m
    assert sol.motion.velocity["C"][0] == pytest.approx(sol.velocity.value("c"), rel=1e-13)


@pytest.mark.parametrize("name", ALL)
def test_plan_recipe_made_once_gives_the_plans_made_afresh(name):
    """solve_position follows a recipe worked out at the first angle a solver sees; at
    every other angle its plans equal those of a solver that works the recipe out there."""
    from plans.plan.solution import solve_position

    mech = SCENES[name].mechanism()
    shared = Solver(mech)
    done = 0
    for x in _angles(SCENES[name], 13):
        try:
            a = solve_position(mech, float(x), solver=shared)
        except (AssemblyError, SingularPlanError):
            continue
        b = solve_position(mech, float(x), solver=Solver(mech))
        for pa, pb in ((a.velocity, b.velocity), (a.acceleration, b.acceleration)):
            assert pa.points == pb.points
            assert pa.vectors == pb.vectors
            assert pa.mu == pb.mu
        assert a.segments == b.segments
        # the one table holds both plans; a name drawn on both keeps the acceleration's
        assert a.segments.items() >= a.acceleration.segments.items()
        assert a.segments.items() >= {k: v for k, v in a.velocity.segments.items()
                                      if k not in a.acceleration.segments}.items()
        for plan in (a.velocity, a.acceleration):  # every drawn segment, found afresh
            for name, pt in plan.points.items():
                if pt.source.kind not in ("pole", "component"):
                    assert plan.segments[plan.pole + name] == pytest.approx(
                        plan.mm(plan.pole, name), rel=1e-15, abs=1e-300)
            for v in plan.vectors:
                assert plan.segments[v.start + v.end] == pytest.approx(
                    plan.mm(v.start, v.end), rel=1e-15, abs=1e-300)
        done += 1
    assert done >= 6


def test_plan_recipe_is_worked_out_again_where_a_similarity_base_degenerates():
    """A recipe whose similarity step divides by two points that have met is not
    followed blindly: the plan is worked out again there (and the result is finite)."""
    from plans.plan import recipes, solve_position
    from plans.plan.recipe import SIMILAR, compile_steps

    mech = SCENES["press"].mechanism()
    sv = Solver(mech)
    good = solve_position(mech, 0.3, solver=sv)
    (recipe,) = recipes(sv, "velocity")
    steps = list(recipe.steps)
    k = next(i for i, st in enumerate(steps) if st[0] == SIMILAR)
    st = steps[k]
    steps[k] = (st[0], st[1], st[2], st[3], st[3], *st[5:])  # base b1 := b0: divides by 0
    broken = compile_steps(recipe.kind, recipe.pole, recipe.tip, steps, recipe.ends)
    recipes(sv, "velocity")[:] = [recipe._replace(steps=tuple(steps), follow=broken)]
    again = solve_position(mech, 0.3, solver=sv)
    assert again.velocity.points == good.velocity.points
    # worked out afresh and kept first; the broken one stays behind it
    fresh, kept = recipes(sv, "velocity")
    assert fresh.steps == recipe.steps and kept.steps == tuple(steps)


def test_a_compiled_recipe_shows_its_generated_line_in_a_traceback():
    """The compiled recipe is ordinary Python: a failure inside it points at the
    generated line, and two solvers of one mechanism share its linecache entry."""
    import linecache
    import traceback

    from plans.plan import recipes, solve_position

    mech = SCENES["press"].mechanism()
    one, two = Solver(mech), Solver(mech)
    solve_position(mech, 0.3, solver=one)
    solve_position(mech, 0.3, solver=two)
    (r1,), (r2,) = (recipes(sv, "velocity") for sv in (one, two))
    assert r1.follow is not r2.follow and r1.follow.source == r2.follow.source
    with pytest.raises(KeyError) as info:
        r1.follow({}, [], {}, None)  # no solved vectors at all
    frame = traceback.extract_tb(info.tb)[-1]
    assert frame.filename.startswith("<plan recipe velocity ")
    assert frame.filename == r2.follow.__code__.co_filename
    assert linecache.getline(frame.filename, frame.lineno).strip() == "v2 = store['A']"


def test_a_mechanism_whose_points_meet_at_some_angles_keeps_one_recipe_for_each_case():
    """The Scotch yoke's recipe changes where two of its points meet (at φ1 = 0); over
    angles that go back and forth between the two cases each recipe is worked out (and
    compiled) once."""
    from plans.plan import recipes, solve_position

    mech = SCENES["scotch_yoke"].mechanism()
    sv = Solver(mech)
    angles = [0.0, *_angles(SCENES["scotch_yoke"], 24)]  # at 0 the pin A3 is on D
    for _ in range(3):
        for x in angles:
            a = solve_position(mech, float(x), solver=sv)
            b = solve_position(mech, float(x), solver=Solver(mech))
            assert a.velocity == b.velocity and a.acceleration == b.acceleration
            assert a.segments == b.segments and a.warnings == b.warnings
    # every recipe worked out is kept, so their number is the number of work-outs
    kept = {kind: len(recipes(sv, kind)) for kind in ("velocity", "acceleration")}
    assert max(kept.values()) == 2  # the two cases, and no more


def test_the_readmes_python_example_runs_and_its_comments_are_true(monkeypatch):
    """The README's sweep example, run as written; the figures in its comments hold."""
    import re
    from pathlib import Path

    root = Path(__file__).resolve().parent.parent
    readme = (root / "README.md").read_text("utf-8")
    blocks = re.findall(r"```python\n(.*?)```", readme, re.S)
    assert blocks, "the README lost its Python example"
    monkeypatch.chdir(root)
    for code in blocks:
        scope: dict = {}
        exec(compile(code, "README.md", "exec"), scope)
        for name, value, unit in re.findall(r"^(\w+) = .*# ([\d.]+) (m/s|m)\b", code, re.M):
            digits = len(value.partition(".")[2])
            assert round(float(scope[name]), digits) == float(value), (name, unit)


@settings(max_examples=300, deadline=None)
@given(hs.floats(1e-9, 1e9), hs.floats(0.0, 10.0))
def test_choose_mu_is_the_first_standard_value_that_fits(value, ratio):
    """The plan's scale: the smallest k·10ⁿ (k in 1, 2, 2.5, 4, 5) at which the crank's
    vector is ≤ 80 mm and every vector ≤ 150 mm, found by walking the series."""
    from plans.scales import choose_mu, series

    largest = value * ratio
    need = max(value / 80.0, largest / 150.0)
    got = choose_mu(value, largest)
    assert got == next(series(need, need * 20))
    assert value / got <= 80.0 * (1 + 1e-12) and largest / got <= 150.0 * (1 + 1e-12)


@pytest.mark.parametrize("phi", [math.nan, math.inf, -math.inf])
def test_one_angle_that_is_no_number_is_a_value_error(phi):
    """solve_one(nan) had raised "cannot be assembled at φ1 = —°, misses by nan m"."""
    sv = Solver(SCENES["press"].mechanism())
    with pytest.raises(ValueError, match="the crank angle must be a finite number"):
        sv.solve_one(phi)


@pytest.mark.parametrize("name", ["press", "slotted_oscillating", "crank_rocker"])
def test_the_sweep_gives_each_slotted_links_pivot_figure_as_the_cycle_does(name):
    """|QP| / (|OQ| + |OP|): the figure under which ``plans cycle`` refuses a block on the
    rocker's pivot, where the lines' sine stays 1; the sweep had only the sine."""
    from plans.cycle.table import conditioning

    mech = SCENES[name].mechanism()
    sv = Solver(mech)
    phi = mech.driver.phi + np.linspace(0, 2 * np.pi, 37)
    sw = sv.sweep(phi)
    m = sv.solve(phi)
    rows = conditioning(mech, m, sv)
    want = {k for k in rows[0].figures if k.endswith(" pivot")}
    assert set(sw.pivot) == want and (name == "crank_rocker") == (not want)
    for key in want:
        np.testing.assert_allclose(sw.pivot[key], [r.figures[key] for r in rows], rtol=1e-14)
        g = next(g for g in sv.structure.groups if f"{g.label} pivot" == key)
        P, Q = sw.position[g.P], sw.position[g.Q]
        crank = mech.frame[mech.driver.pivot]
        by_hand = np.abs(P - Q) / (np.abs(Q - crank) + np.abs(P - crank))
        np.testing.assert_allclose(sw.pivot[key], by_hand, rtol=1e-15)
        assert 0 < sw.pivot[key].min() < sw.pivot[key].max() <= 1 + 1e-15  # the triangle OPQ
