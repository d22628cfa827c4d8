"""``plans bench`` at tiny sizes: the row shape, small errors, the chart, and the error
measure agreeing with ``plans.reference``."""

import json
import math
import xml.etree.ElementTree as ET

import numpy as np
import pytest

from plans import bench, reference
from plans.cli import main
from plans.kinematics import Solver
from plans.scenes import SCENES

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
    ours = bench.motion_error(motion, ref.arrays())
    theirs = reference.max_rel_error(motion, ref)["max"]
    assert ours == pytest.approx(theirs, rel=1e-12)
    assert ours < 1e-14


def test_shared_reference_angles():
    scene = SCENES["crank_rocker"]
    sub = {n: bench.grid(scene, n)[bench.subset(n, 100)] for n in (100, 1000, 10_000)}
    assert np.array_equal(sub[100], sub[1000]) and np.array_equal(sub[100], sub[10_000])
    assert len(bench.subset(12, 100)) == 12
    assert len(bench.subset(1234, 100)) == 100


def test_svg_chart_handles_zero_and_missing_errors():
    rows = [
        bench.Row("a", "vectorized", 12, 1e-6, 0.0),
        bench.Row("a", "fd h=1e-04", 12, 1e-5, None),
        bench.Row("b", "plan", 12, 1e-3, math.inf),
    ]
    from drawing.bench_chart import svg_chart

    ET.fromstring(svg_chart(rows, "test"))
