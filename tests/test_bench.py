"""``plans bench`` at tiny sizes: the row shape, small errors, the chart, and the error
measure agreeing with ``plans.verify.reference``."""

import json
import math
import xml.etree.ElementTree as ET

import numpy as np
import pytest

from plans.cli import bench, main
from plans.kinematics.solver import Solver
from plans.model.scenes import SCENES
from plans.verify import bench as measure
from plans.verify import reference

ROW_KEYS = {"scene", "method", "positions", "seconds_per_position", "max_rel_error"}


@pytest.fixture(scope="module")
def quick_rows(tmp_path_factory):
    chart = tmp_path_factory.mktemp("bench") / "chart.svg"
    capture = {}

    def run():
        import contextlib
        import io

        out, err = io.StringIO(), io.StringIO()
        with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
            code = main(
                [
                    "bench",
                    "--json",
                    "--quick",
                    "--max-positions",
                    "100",
                    "--scene",
                    "press",
                    "--scene",
                    "crank_rocker",
                    "--chart",
                    str(chart),
                ]
            )
        capture.update(code=code, out=out.getvalue(), err=err.getvalue())

    run()
    return capture, chart


def test_bench_json_rows(quick_rows):
    cap, _ = quick_rows
    assert cap["code"] == 0, cap["err"]
    rows = json.loads(cap["out"])
    assert rows and all(set(r) == ROW_KEYS for r in rows)
    assert {r["scene"] for r in rows} == {"press", "crank_rocker"}
    assert {r["positions"] for r in rows} == {12, 100}
    methods = {r["method"] for r in rows}
    assert {"vectorized", "plan", "fd h=1e-04"} <= methods
    for r in rows:
        assert isinstance(r["positions"], int)
        assert 0 < r["seconds_per_position"] < 1
        assert r["max_rel_error"] is not None
        if r["method"].startswith("fd"):
            # finite differences lose about half the digits, and no more
            assert 1e-12 < r["max_rel_error"] < 1e-5
        elif r["method"] in ("vectorized", "plan"):
            assert r["max_rel_error"] < 1e-14
        else:  # a peer package
            assert r["max_rel_error"] < 1e-9


def test_bench_chart_is_svg_with_a_marker_per_row(quick_rows):
    cap, chart = quick_rows
    rows = json.loads(cap["out"])
    root = ET.fromstring(chart.read_text("utf-8"))
    assert root.tag.endswith("svg")
    text = chart.read_text("utf-8")
    assert "wall time per position" in text and "max relative error" in text
    for r in rows:
        assert r["method"] in text


def test_bench_table_names_the_targets(capsys, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)  # where a chart would go by default: --chart "" writes none
    code = main(
        [
            "bench",
            "--quick",
            "--max-positions",
            "12",
            "--scene",
            "scotch_yoke",
            "--methods",
            "vectorized,peers",
            "--chart",
            "",
        ]
    )
    out, err = capsys.readouterr()
    assert code == 0, err
    assert "scotch_yoke" in out and "vectorized" in out
    assert "targets" in out
    assert "max rel error ≤ 1e-13" in out
    assert not (tmp_path / "bench.svg").exists()


def test_bench_rejects_an_unknown_scene(capsys):
    assert main(["bench", "--json", "--scene", "nope", "--chart", ""]) == 2
    assert "unknown nope" in capsys.readouterr().err


def test_error_measure_is_the_reference_norm():
    scene = SCENES["slot_rrp_moving"]
    mech = scene.mechanism()
    phi = scene.angles(7)
    motion = Solver(mech).solve(phi)
    ref = reference.reference(mech, phi, motion=motion)
    ours = measure.motion_error(motion, ref.arrays())
    theirs = reference.max_rel_error(motion, ref)["max"]
    assert ours == pytest.approx(theirs, rel=1e-12)
    assert ours < 1e-14


def test_shared_reference_angles():
    scene = SCENES["crank_rocker"]
    sub = {n: measure.grid(scene, n)[measure.subset(n, 100)] for n in (100, 1000, 10_000)}
    assert np.array_equal(sub[100], sub[1000]) and np.array_equal(sub[100], sub[10_000])
    assert len(measure.subset(12, 100)) == 12
    assert len(measure.subset(1234, 100)) == 100


def _chart_spy(monkeypatch) -> list:
    """What the bench hands drawing.chart.bench_chart: (rows, title, fmt) of each call,
    answered with bytes that say their format."""
    from drawing import chart

    calls = []

    def spy(rows, title, fmt):
        calls.append((list(rows), title, fmt))
        return f"<{fmt} chart of {len(calls[-1][0])} rows>".encode()

    monkeypatch.setattr(chart, "bench_chart", spy, raising=False)
    return calls


@pytest.mark.parametrize("fmt", ["png", "svg", "pdf"])
def test_the_chart_is_written_in_the_format_its_name_ends_in(capsys, tmp_path, monkeypatch, fmt):
    """--chart FILE.png|svg|pdf: the rows measured go to the chart (the very rows of the
    JSON), the format is the name's ending, and the chart's bytes are the file."""
    calls = _chart_spy(monkeypatch)
    target = tmp_path / f"bench.{fmt.upper() if fmt == 'pdf' else fmt}"
    code = main(["bench", "--json", "--quick", "--max-positions", "12", "--scene", "scotch_yoke",
                 "--methods", "vectorized", "--chart", str(target)])
    out, err = capsys.readouterr()
    assert code == 0, err
    ((rows, title, got),) = calls
    assert got == fmt
    assert [r.as_json() for r in rows] == json.loads(out)
    assert "cores" in title and "numpy" in title  # the machine it was measured on
    assert target.read_bytes() == f"<{fmt} chart of {len(rows)} rows>".encode()


def test_a_chart_of_another_format_is_refused_before_anything_is_timed(capsys, tmp_path,
                                                                        monkeypatch):
    calls = _chart_spy(monkeypatch)

    def never(*_):
        raise AssertionError("timed before the chart's name was checked")

    monkeypatch.setattr(measure.Bench, "scene", never)
    code = main(["bench", "--quick", "--scene", "scotch_yoke", "--chart", str(tmp_path / "b.jpg")])
    _, err = capsys.readouterr()
    assert code == 2 and not calls and not (tmp_path / "b.jpg").exists()
    assert err == (f"plans bench: command line: --chart {tmp_path / 'b.jpg'}: the name must end "
                   "in .png, .svg or .pdf (--chart writes PNG, SVG or PDF, as the name ends)\n")


def test_svg_chart_handles_zero_and_missing_errors():
    rows = [
        bench.Row("a", "vectorized", 12, 1e-6, 0.0),
        bench.Row("a", "fd h=1e-04", 12, 1e-5, None),
        bench.Row("b", "plan", 12, 1e-3, math.inf),
    ]
    from drawing.chart import bench_chart

    ET.fromstring(bench_chart(rows, "test", "svg"))
    assert bench_chart(rows, "test", "png")[:8] == b"\x89PNG\r\n\x1a\n"
    assert bench_chart(rows, "test", "pdf")[:5] == b"%PDF-"


def test_joints_only_four_bar_is_the_crank_rocker_without_its_extra_points():
    """The bench reads the four-bar target on ``fourbar_joints``: it must be the very
    crank-rocker of ``crank_rocker``, with only the points found by similarity dropped."""
    from plans.kinematics.sweep import sweep

    full, bare = (Solver(SCENES[n].mechanism()) for n in ("crank_rocker", "fourbar_joints"))
    phi = SCENES["crank_rocker"].angles(29)
    a, b = sweep(full, phi), sweep(bare, phi)
    assert set(a.position) - set(b.position) == {"E", "S2", "F"}
    assert set(b.position) == {"O", "D", "A", "B"}
    for kind in ("position", "velocity", "acceleration"):
        for name in b.position:
            np.testing.assert_array_equal(getattr(b, kind)[name], getattr(a, kind)[name])
    for lid in (1, 2, 3):
        np.testing.assert_array_equal(b.omega[lid], a.omega[lid])
        np.testing.assert_array_equal(b.epsilon[lid], a.epsilon[lid])
    assert "fourbar_joints" in bench.BENCH_SCENES


def test_targets_read_each_rate_on_its_own_scenes():
    rate = lambda per_s: 1 / per_s  # noqa: E731
    rows = [
        bench.Row("fourbar_joints", "vectorized", 100_000, rate(7e6), 5e-16),
        bench.Row("fourbar_joints", "vectorized", 1_000_000, rate(5.5e6), 5e-16),
        bench.Row("crank_rocker", "vectorized", 100_000, rate(5.2e6), 5e-16),
        bench.Row("crank_rocker", "vectorized", 1_000_000, rate(3.6e6), 5e-16),
        bench.Row("crank_rocker", "vectorized", 10_000, rate(9e6), 5e-16),  # N < 1e5
        bench.Row("press", "vectorized", 1_000_000, rate(1.9e6), 9e-16),
    ]
    lines = bench.targets(rows)
    joints = [ln for ln in lines if "joints only" in ln and "new arrays" in ln]
    more = [ln for ln in lines if "more points" in ln and "new arrays" in ln]
    press = [ln for ln in lines if "press ≥" in ln]
    assert len(joints) == len(more) == len(press) == 1
    assert joints[0].endswith("— met") and "5.5e+06 at N = 1e+06" in joints[0]
    assert more[0].endswith("met at some N only") and "9e+06" not in more[0]
    assert press[0].endswith("NOT met")
    # no reused rows were given: their lines are left out, not reported as unmeasured
    assert not any("reused" in ln for ln in lines)


def test_best_time_counts_its_repeats_after_a_slow_first_run():
    """A plan's first run compiles its recipe: that once-only cost must not leave the
    measurement a handful of repeats."""
    import time

    calls = []

    def fn():
        calls.append(None)
        if len(calls) == 1:
            time.sleep(0.05)

    best = measure.best_time(fn, budget=0.1)
    assert len(calls) > 50
    assert best < 0.01


def test_every_default_scene_has_its_own_marker_on_the_chart():
    """With the joints-only four-bar the bench has eight scenes; the chart had seven shapes
    and drew the press and the Scotch yoke both as filled circles."""
    from drawing import chart as bench_chart

    drawn = set(bench_chart.SHAPES)
    assert len(drawn) == len(bench_chart.SHAPES) >= len(bench.BENCH_SCENES)
    rows = [bench.Row(name, "vectorized", 12, 1e-6 * (i + 1), 1e-15)
            for i, name in enumerate(bench.BENCH_SCENES)]
    fig = bench_chart.bench_figure(rows, "test")
    (legend,) = [lg for lg in fig.legends if lg.get_title().get_text() == "scene"]
    shown = {t.get_text(): (h.get_marker(), h.get_markerfacecolor() != "none")
             for t, h in zip(legend.get_texts(), legend.legend_handles, strict=True)}
    for i, name in enumerate(bench.BENCH_SCENES):  # the legend draws each scene's own shape
        assert shown[name] == bench_chart.SHAPES[i]
    assert len(set(shown.values())) == len(bench.BENCH_SCENES)
