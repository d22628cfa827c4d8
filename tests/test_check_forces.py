"""``plans check`` reads force plans: the segments of each group's force plan, the forces and
moments, the arms of Zhukovsky's lever and the balancing force, against the exact force
analysis at the student's scales, and the common mistakes of the force analysis named.

Measurement files are built from the check's own replay of the force analysis (the exact
one, or one with a mistake made: ``verdict.redraw``), never from hand-written numbers that
could drift; the replay without a mistake is held equal to ``plans.forces`` (the groups,
the lever) here. The workbook of seed 001 gives the one student's file of real numbers.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from support import run

from plans.check import forces as cf
from plans.check import verdict as ck
from plans.check.force_items import canonical
from plans.cycle import analyse_cycle
from plans.errors import InputError
from plans.forces.analysis import analyse_loads
from plans.forces.summary import solve_forces

SAMPLES = Path(__file__).resolve().parents[1] / "samples"
PRESS = SAMPLES / "press.toml"
FOURBAR = SAMPLES / "fourbar.toml"
#: the scales a student of each mechanism draws at: the press as seed 000, the four-bar
#: as seed 001's workbook (kv = 0.02 (m/s)/mm; its force plans are not in the workbook)
SCALES = {PRESS: ({"mu_v": 0.05, "mu_a": 1.0}, 20.0), FOURBAR: ({"mu_v": 0.02, "mu_a": 0.25}, 20.0)}


def _key(name: str) -> str:
    return json.dumps(name, ensure_ascii=False)


def write(path: Path, mech: Path, mu: dict, items: dict[str, float], mu_F=None,
          kinematic: dict[str, float] | None = None, extra: str = "") -> Path:
    """A measurement file: ``items`` by their keys (``forces.R12``, ``forces.h.G1``,
    ``values.F_у``; a value a (number, sense) pair), the kinematic segments ``kinematic``."""
    lines = [f"mechanism = {_key(str(mech))}", extra, "[scales]", *(f"{k} = {v!r}" for k, v in mu.items())]
    if kinematic:
        lines += ["[segments]", *(f"{_key(k)} = {v:.3f}" for k, v in kinematic.items())]
    tables: dict[str, list[str]] = {"forces": [], "forces.h": [], "values": []}
    if mu_F is not None:
        tables["forces"].append(f"mu_F = {mu_F!r}" if not isinstance(mu_F, dict) else
                                "mu_F = { " + ", ".join(f"{_key(k)} = {v!r}" for k, v in mu_F.items()) + " }")
    for key, x in items.items():
        table, name = key.rsplit(".", 1) if not key.startswith("forces.h.") else ("forces.h", key[9:])
        if isinstance(x, tuple):
            mag, sense = x
            text = _key(f"{abs(mag):.6g} {'ccw' if (mag > 0) == (sense > 0) else 'cw'}")
        else:
            text = f"{x:.4f}"
        tables[table].append(f"{_key(name)} = {text}")
    for table, rows in tables.items():
        if rows:
            lines += [f"[{table}]", *rows]
    path.write_text("\n".join(lines) + "\n", encoding="utf-8")
    return path


def every_item(tmp_path: Path, mech: Path, kinematic: bool = False) -> ck.Measurement:
    """A measurement of every item the force analysis of ``mech`` names (and, with
    ``kinematic``, every segment of its velocity and acceleration plans), at the scales
    of :data:`SCALES`: the template the planted files are written from."""
    mu, mu_F = SCALES[mech]
    probe = ck.load(write(tmp_path / "probe.toml", mech, mu, {"values.F_у": 1.0}))
    ctx = probe.forces
    items = {f"forces.{label}": 1.0 for gf in ctx.analysis.groups for label in gf.plan.ends}
    items |= {f"forces.h.{name}": 1.0 for name in ctx.lever[0]}
    items[f"forces.{ctx.pb_name}"] = 1.0
    exact = ctx.drawn()
    items |= {f"values.{name}": (1.0, 1) if isinstance(v, float) else 1.0 for name, v in exact.values.items()}
    items["values.F_у"] = (1.0, 1)
    segs = None
    if kinematic:
        from support import plan_segments

        segs = {it.name: 1.0 for it in plan_segments(probe.solution)}
    return ck.load(write(tmp_path / "all.toml", mech, mu, items, mu_F, segs))


def planted(tmp_path: Path, meas: ck.Measurement, mk: ck.Mistake | None, name: str = "m.toml",
            rng=None, noise: float = 0.0) -> Path:
    """The file of ``meas``'s items as a student who makes the mistake ``mk`` measures
    them (the check's replay), with drawing noise of ± ``noise`` mm (and ± noise % on a
    value)."""
    st = ck.redraw(meas, mk)
    mu = {k: v for k, v in meas.mu.items() if k in meas.given}
    items, segs = {}, {}
    for it in meas.items:
        x = ck.expected(it, st, meas.mu)
        if rng is not None:
            off = rng.uniform(-noise, noise)
            x = x + off if it.unit == "mm" else x * (1 + off / 100)
        if it.plan in ("velocity", "acceleration"):
            segs[it.name] = max(x, 0.0)
        else:
            items[it.key] = (x, 1) if it.sense else max(x, 0.0)
    return write(tmp_path / name, meas.mechanism.source, mu, items, meas.forces.mu_F_given, segs or None)


def named(res: ck.CheckResult) -> list[tuple[str, str]]:
    d = res.diagnosis
    return [(f.mistake.kind, f.mistake.target) for f in (d.best, *d.alternatives) if f is not None]


@pytest.fixture(scope="module", params=[PRESS, FOURBAR], ids=["press", "fourbar"])
def template(request, tmp_path_factory):
    return every_item(tmp_path_factory.mktemp("forces"), request.param)


# ---------------------------------------------------------------------------------------
# the replay without a mistake is the force analysis of plans.forces
# ---------------------------------------------------------------------------------------


def test_the_replay_is_the_force_analysis(template):
    """Every segment, reaction, load, the lever's arms, pb and F_у of the check's exact
    replay are those ``plans forces`` reports; and the motion rebuilt from the exact plans
    as a student reads them (:func:`plans.check.forces.drawn_motion`) gives the same
    analysis to rounding, so a kinematic mistake carries over through the same code."""
    meas = template
    sol = meas.solution
    F = solve_forces(sol, sol.solver, analyse_cycle(sol.mechanism, solver=sol.solver))
    fd = meas.forces.drawn()
    fa = F.analysis
    for gf in fa.groups:
        for label, mm in gf.plan.segments.items():
            assert fd.segments[label] == pytest.approx(mm * gf.plan.mu, rel=1e-12, abs=1e-9)
    for name, r in fa.reactions.items():
        assert fd.values[name] == pytest.approx(r.value, rel=1e-12)
    for ld in fa.loads:
        assert fd.values[ld.name] == pytest.approx(ld.moment if ld.force == 0 else ld.force, rel=1e-12)
    lever = F.lever
    assert fd.pb == pytest.approx(lever.pb, rel=1e-12)
    assert fd.F_y == pytest.approx(lever.F_y, rel=1e-12)
    assert fd.F_y == pytest.approx(fa.F_y, rel=1e-9)
    assert fd.values[cf.M_Y] == pytest.approx(fa.M_y, rel=1e-12)
    for t in lever.terms:
        if t.point:
            assert fd.arms[t.name] == pytest.approx(t.arm, rel=1e-12, abs=1e-12)
    # the plans as drawn, read back into a motion: the same analysis
    st = ck.simulate(sol, None)
    again = cf.drawn_motion(st, sol.scalar)
    external = cf.external(sol.mechanism, meas.forces.loads, again, sol.phi, meas.forces.stroke)
    other = analyse_loads(sol, external, meas.forces.stroke, motion=again)
    assert other.M_y == pytest.approx(fa.M_y, rel=1e-12)
    for name, r in other.reactions.items():
        assert r.value == pytest.approx(fa.reactions[name].value, rel=1e-12, abs=1e-9)


def test_every_exact_item_is_within_tolerance(template, tmp_path, capsys):
    path = planted(tmp_path, template, None)
    res = ck.check(ck.load(path))
    assert res.ok and res.diagnosis.best is None
    code, out, _ = run(capsys, "check", path)
    assert code == 0
    assert "Force plan of group" in out and "Zhukovsky's lever" in out and "Forces and moments" in out


@pytest.mark.parametrize("seed", range(4))
def test_drawing_noise_passes(template, tmp_path, seed):
    """Measured to ±0.4 mm and computed to ±2 %: every item within tolerance."""
    path = planted(tmp_path, template, None, rng=np.random.default_rng(seed), noise=0.4)
    res = ck.check(ck.load(path))
    assert res.ok, [(d.item.name, d.item.measured, d.computed) for d in res.failed]


# ---------------------------------------------------------------------------------------
# seed 001's workbook: its own numbers, within tolerance, no mistake named
# ---------------------------------------------------------------------------------------

WORKBOOK = """mechanism = {mech}
title = "Seed 001, task 1, steps 4-7: the workbook's own numbers"
[scales]
mu_v = 0.02
[forces]
pvb = 49
h.G1 = 19
h.G2 = 3
h.G3 = 5
h."Fи2" = 24
h."Fи3" = 17
h."FПС" = 61
[values]
G1 = 3
G2 = 15.5
G3 = 5
"Fи1" = 2.4
"Fи2" = 20.2
"Fи3" = 3.1
"FПС" = 1550
"FУ" = 1942
"""


def test_the_workbooks_lever_is_within_tolerance(tmp_path, capsys):
    """Seed 001 step 7: F_у = (3·19 + 15,5·3 − 5·5 + 20,2·24 + 3,1·17 + 1550·61) / 49 =
    1942 N, with the arms measured on its lever; the exact F_у is 1925 N (0.9 % off)."""
    path = tmp_path / "workbook.toml"
    path.write_text(WORKBOOK.format(mech=_key(str(FOURBAR))), encoding="utf-8")
    meas = ck.load(path)
    res = ck.check(meas)
    assert res.ok, [(d.item.name, d.item.measured, d.computed) for d in res.failed]
    got = {d.item.name: d for d in res.deviations}
    assert set(got) == {"pb", "h_G1", "h_G2", "h_G3", "h_Φ2", "h_Φ3", "h_F_пс", "G1", "G2", "G3",
                        "Φ1", "Φ2", "Φ3", "F_пс", "F_у"}
    assert got["F_у"].computed == pytest.approx(1925.03, abs=0.01)
    assert abs(got["F_у"].percent) < 1.0
    code, out, _ = run(capsys, "check", path)
    assert code == 0 and "Diagnosis" not in out


def test_the_shipped_sample_is_the_workbook(capsys):
    """samples/check_forces.toml: seed 001's own numbers (its kinematic and force items)
    within tolerance; the Russian report says so in its words."""
    code, out, _ = run(capsys, "check", SAMPLES / "check_forces.toml")
    assert code == 0, out
    assert "Zhukovsky's lever" in out and "F_у, N" in out
    code, out, _ = run(capsys, "check", SAMPLES / "check_forces.toml", "--lang", "ru")
    assert code == 0 and "Рычаг Жуковского" in out and "F_у, Н" in out


# ---------------------------------------------------------------------------------------
# the mistakes, planted through the replay and named
# ---------------------------------------------------------------------------------------

#: (mechanism, kind, target): the mistakes each test plants; "all" the every-link variant
PLANTED = [
    (PRESS, "inertia-along", "Φ4"), (PRESS, "inertia-along", "Φ5"), (PRESS, "inertia-along", "all"),
    (PRESS, "inertia-moment-omitted", "M_Φ4"), (PRESS, "inertia-moment-omitted", "all"),
    (PRESS, "inertia-moment-reversed", "M_Φ4"), (PRESS, "inertia-moment-reversed", "all"),
    (PRESS, "weight-omitted", "G3"), (PRESS, "weight-omitted", "G5"), (PRESS, "weight-omitted", "all"),
    (PRESS, "inertia-omitted", "Φ5"), (PRESS, "force-reversed", "P"), (PRESS, "lever-unturned", "lever"),
    (FOURBAR, "inertia-along", "Φ3"), (FOURBAR, "inertia-along", "all"),
    (FOURBAR, "weight-omitted", "G3"), (FOURBAR, "force-reversed", "F_пс"),
    (FOURBAR, "lever-unturned", "lever"), (FOURBAR, "moment-sense", "M_у"),
]


@pytest.fixture(scope="module")
def templates(tmp_path_factory):
    return {m: every_item(tmp_path_factory.mktemp("t"), m) for m in (PRESS, FOURBAR)}


def find(meas, kind, target, factor=None) -> ck.Mistake:
    for mk in cf.hypotheses(meas.forces, meas.items):
        if mk.kind == kind and mk.target == target and (factor is None or mk.factor == factor):
            return mk
    raise LookupError((kind, target))


@pytest.mark.parametrize(("mech", "kind", "target"), PLANTED,
                         ids=[f"{m.stem}-{k}-{t}" for m, k, t in PLANTED])
def test_a_planted_mistake_is_named(templates, tmp_path, mech, kind, target):
    """Every item as the student who makes the mistake measures it: that mistake is named
    (first, or tied with one that draws the same analysis)."""
    meas = templates[mech]
    mk = find(meas, kind, target)
    res = ck.check(ck.load(planted(tmp_path, meas, mk)))
    assert not res.ok
    assert (kind, target) in named(res), (named(res), res.diagnosis.closest)
    families = ("inertia", "inertia moment", "weight", "force", "lever", "sense")
    assert res.diagnosis.best.mistake.family in families


@pytest.mark.parametrize(("mech", "kind", "target"), [p for p in PLANTED if p[1] != "moment-sense"][::3],
                         ids=lambda x: getattr(x, "stem", x))
def test_a_planted_mistake_is_named_through_drawing_noise(templates, tmp_path, mech, kind, target):
    meas = templates[mech]
    mk = find(meas, kind, target)
    res = ck.check(ck.load(planted(tmp_path, meas, mk, rng=np.random.default_rng(7), noise=0.3)))
    assert (kind, target) in named(res), (named(res), res.diagnosis.closest)


@pytest.mark.parametrize("factor", [10.0, 0.1])
@pytest.mark.parametrize("mech", [PRESS, FOURBAR], ids=["press", "fourbar"])
def test_a_force_plan_ten_times_off_is_named(templates, tmp_path, mech, factor):
    meas = templates[mech]
    key = meas.forces.keys[0]
    mk = find(meas, "force-scale", key, factor)
    res = ck.check(ck.load(planted(tmp_path, meas, mk)))
    assert ("force-scale", key) in named(res)
    assert res.diagnosis.best.mistake.factor == factor


@pytest.mark.parametrize("ratio", [2.0, 0.4, 1.6])
def test_a_force_plan_at_another_mu_F_is_named_with_the_one_it_fits(templates, tmp_path, ratio):
    """The press's plans drawn at μF/ratio with 20 N/mm written down: every plan's segments
    (and the reactions read off them) ratio times the exact ones; the μF they fit is
    named, as the kinematic check fits μv."""
    meas = templates[PRESS]
    mk = ck.Mistake("force-scale", "force", "all", ratio, info=(("factor", ratio),))
    res = ck.check(ck.load(planted(tmp_path, meas, mk)))
    best = res.diagnosis.best
    assert best is not None and best.mistake.kind == "force-scale" and best.mistake.target == "all"
    assert float(best.mistake.get("fits")) == pytest.approx(20.0 / ratio, rel=1e-6)
    assert f"fit μF = {20 / ratio:g} N/mm" in best.mistake.describe("en")


def test_one_group_at_another_mu_F_is_that_groups(templates, tmp_path):
    meas = templates[PRESS]
    key = meas.forces.keys[1]  # group 2–3, drawn second
    mk = ck.Mistake("force-scale", "force", key, 2.5, info=(("factor", 2.5),))
    res = ck.check(ck.load(planted(tmp_path, meas, mk)))
    assert res.diagnosis.best.mistake.target == key
    assert float(res.diagnosis.best.mistake.get("fits")) == pytest.approx(8.0)


def test_a_kinematic_mistake_carries_over_to_the_forces(tmp_path, capsys):
    """The press with its velocity and acceleration plans measured and its force analysis:
    the Coriolis vector reversed changes a_S3, a_S4, ε3 and ε4, so the student's inertia
    loads and every reaction after them; the one mistake explains the plans' and the
    forces' deviations together."""
    meas = every_item(tmp_path, PRESS, kinematic=True)
    mk = next(m for m in ck.hypotheses(meas.solution) if m.kind == "coriolis-reversed")
    res = ck.check(ck.load(planted(tmp_path, meas, mk)))
    failed = {d.item.plan for d in res.failed}
    assert {"acceleration", "force"} <= failed
    assert ("coriolis-reversed", mk.target) in named(res)
    assert not res.diagnosis.best.unexplained
    code, out, _ = run(capsys, "check", tmp_path / "m.toml")
    assert code == 1 and "Coriolis" in out


def test_a_force_mistake_leaves_the_plans_measured_alone(tmp_path):
    meas = every_item(tmp_path, PRESS, kinematic=True)
    mk = find(meas, "inertia-along", "Φ4")
    res = ck.check(ck.load(planted(tmp_path, meas, mk)))
    assert res.failed and {d.item.plan for d in res.failed} <= {"force", "lever"}
    assert res.diagnosis.best.mistake.kind == "inertia-along"


def test_a_force_plan_only_file_is_checked_without_the_plans_mistakes(templates, tmp_path, monkeypatch):
    """A file of force items only: the plans' mistakes (and the search of another crank
    angle) are not tried, so nothing of the plans is named from the forces alone."""
    calls = []
    monkeypatch.setattr(ck, "fitted_angle", lambda *a: calls.append(a) or [])
    meas = templates[FOURBAR]
    res = ck.check(ck.load(planted(tmp_path, meas, find(meas, "weight-omitted", "G3"))))
    assert not calls
    assert res.diagnosis.tried == len(cf.hypotheses(meas.forces, meas.items)) + \
        len(cf.fitted_scales(meas.forces, res.deviations))


# ---------------------------------------------------------------------------------------
# names, spellings, the report
# ---------------------------------------------------------------------------------------


@pytest.mark.parametrize(("typed", "meant"), [
    ("R12^τ", "r12τ"), ("R12^t", "r12τ"), ("R12t", "r12τ"), ("R^τ_12", "r12τ"), ("R_{12}^{τ}", "r12τ"),
    ("Фи2", "φ2"), ("Fи2", "φ2"), ("Φ_2", "φ2"), ("phi2", "φ2"), ("Ф2", "φ2"),
    ("Ми3", "mφ3"), ("M_и3", "mφ3"), ("MФи3", "mφ3"), ("M_Φ3", "mφ3"), ("Ри3C", "mφ3(c)"),
    ("F_у", "fy"), ("F_y", "fy"), ("FУ", "fy"), ("Fур", "fy"), ("М_у", "my"), ("My", "my"),
    ("FПС", "fпc"), ("Р", "p"),
])
def test_spellings(typed, meant):
    assert canonical(typed) == meant


def test_names_as_students_type_them(tmp_path):
    path = write(tmp_path / "n.toml", PRESS, {"mu_v": 0.05}, {
        "forces.R34^t": 0.9, "forces.Ф4": 6.4, "forces.Р": 110.0, "forces.h.Ри3C": 72.3,
        "forces.h.Fи4": 59.6, "forces.pa": 60, "values.Ми3": (8.3, -1), "values.Fи3": 78.0,
        "values.М_у": (226.9, 1), "values.F_ур": 1513, "values.R^n_34": 1277}, mu_F={"4-5": 10, "23": 20})
    text = path.read_text("utf-8").replace('"8.3 cw"', '"8,3 Н·м по часовой стрелке"')
    path.write_text(text, encoding="utf-8")
    meas = ck.load(path)
    assert [it.name for it in meas.items] == ["R34^τ", "Φ4", "P", "pa", "h_M_Φ3(C)", "h_Φ4", "M_Φ3", "Φ3",
                                              "M_у", "F_у", "R34^n"]
    assert meas.forces.mu_F == {"4–5": 10.0, "2–3": 20.0}
    res = ck.check(meas)
    assert res.ok, [(d.item.name, d.item.measured, d.computed) for d in res.failed]


def test_the_report_in_json(templates, tmp_path, capsys):
    meas = templates[PRESS]
    path = planted(tmp_path, meas, find(meas, "weight-omitted", "G5"))
    code, out, _ = run(capsys, "check", path, "--json")
    data = json.loads(out)
    assert code == 1
    assert data["scales"] == {"mu_v": 0.05, "mu_a": 1.0, "mu_F": 20.0}
    seg = next(i for i in data["items"] if i["key"] == "forces.R05")
    assert seg["plan"] == "force" and seg["group"] == "4–5" and seg["unit"] == "mm"
    val = next(i for i in data["items"] if i["key"] == "values.M_у")
    assert val["kind"] == "moment" and val["unit"] == "N·m" and val["computed_sense"] in ("ccw", "cw")
    assert all("group" not in i for i in data["items"] if i["plan"] == "lever")
    best = data["diagnosis"]["best"]
    assert (best["kind"], best["target"], best["family"]) == ("weight-omitted", "G5", "weight")


def test_the_report_in_russian(templates, tmp_path, capsys):
    meas = templates[FOURBAR]
    path = planted(tmp_path, meas, find(meas, "inertia-along", "Φ3"))
    code, out, _ = run(capsys, "check", path, "--lang", "ru")
    assert code == 1
    assert "План сил группы 2–3 (μF = 20 Н/мм), мм" in out
    assert "Диагноз: сила инерции Φ3 направлена по ускорению a_S3, а не против него." in out
    assert "Силы и моменты, вычисленные студентом" in out


def test_a_batch_names_the_force_mistake(templates, tmp_path, capsys):
    meas = templates[FOURBAR]
    a = planted(tmp_path, meas, None, "a.toml")
    b = planted(tmp_path, meas, find(meas, "lever-unturned", "lever"), "b.toml")
    code, out, _ = run(capsys, "check", a, b)
    assert code == 1
    assert "on Zhukovsky's lever the forces are applied to the velocity plan as it is" in out


def test_every_mistake_is_worded_in_every_language(templates):
    from plans.check.words import WORDS

    for meas in templates.values():
        mistakes = [*cf.hypotheses(meas.forces, meas.items),
                    ck.Mistake("force-scale", "force", "all", 2.0, info=(("factor", 2.0), ("fits", 10.0)))]
        for mk in mistakes:
            for lang in WORDS:
                assert mk.describe(lang) and mk.correction(lang)
                assert "{" not in mk.describe(lang) + mk.correction(lang)


# ---------------------------------------------------------------------------------------
# malformed force items: one located line each, exit 2
# ---------------------------------------------------------------------------------------

BAD = [
    ('[forces]\nmu_F = 20\nR99 = 3\n', ['forces.R99: unknown force-plan segment "R99"; ',
                                        "known: R34^τ, G4, Φ4, G5, Φ5, P, R05, R34^n, R34, R54 (group 4–5)"]),
    ('[forces]\nR34 = 3\n', ["forces.mu_F: missing: the scale factor the student used for the force plans"]),
    ('[forces]\nmu_F = 0\nR34 = 3\n', ["forces.mu_F: must be positive"]),
    ('[forces]\nmu_F = 20\nR34 = -3\n', ["forces.R34: a length on the drawing cannot be negative"]),
    ('[forces]\nmu_F = { "4-5" = 10 }\nR12 = 3\n', ['forces.mu_F: no μF for the force plan of group 2–3']),
    ('[forces]\nmu_F = { "3-4" = 10 }\n',
     ['forces.mu_F.3-4: "3-4" is not a group of the mechanism: its groups are 4–5, 2–3']),
    ('forces = 3\n', ["forces: must be a table"]),
    ('[forces]\nh = 19\n', ["forces.h: must be a table of the lever's arms"]),
    ('[forces]\nh.G9 = 19\n[scales]\nmu_v = 0.05\n', ['forces.h.G9: unknown force on the lever "G9"']),
    ('[forces]\npa = 60\n',
     ["scales.mu_v: missing: the scale factor the student used for the velocity plan"]),
    ('[forces]\nmu_F = 20\nR34 = 3\nR34t = 4\n"R34^τ" = 4\n',
     ["forces.R34^τ: measures what forces.R34t does"]),
    ('[forces.x]\ny = 1\n', ["forces.x: a sub-table of [forces] is h"]),
    ('[scales]\nmu_F = 20\n[forces]\n',
     ["line 3: scales.mu_F: goes in [forces]", "segments: nothing to check"]),
    ('[values]\nG3 = "98 m/s"\n', ['values.G3: "98 m/s" is in m/s, the unit of a velocity: a force is in N']),
    ('[values]\nG3 = "98 ccw"\n', ["(a sense is given for ω, ε, a moment and F_у only)"]),
    ('[values]\n"M_у" = "227 sideways"\n', ['values."M_у": write a magnitude and a sense']),
    ('[forces]\nmu_F = 20\n', ["line 2: forces: nothing to check: give the segments of the force plans"]),
    ('[values]\nQ7 = 1\n', ['values.Q7: unknown value "Q7"; known: ω<link>', "; forces and moments: G1, G3"]),
]


@pytest.mark.parametrize(("text", "expect"), BAD, ids=[b[0][:30] for b in BAD])
def test_bad_force_items(tmp_path, capsys, text, expect):
    path = tmp_path / "bad.toml"
    body = text.replace("[forces]\n", "[forces]\n", 1)
    path.write_text(f"mechanism = {_key(str(PRESS))}\n" + body, encoding="utf-8")
    code, out, err = run(capsys, "check", path)
    assert code == 2 and out == "" and "Traceback" not in err
    lines = err.strip().splitlines()
    assert all(ln.startswith(f"plans check: {path}: ") for ln in lines), err
    for want in expect:
        assert any(want in ln for ln in lines), (want, err)


def test_a_mechanism_without_loads_is_said(tmp_path, capsys):
    mech = tmp_path / "bare.toml"
    mech.write_text(PRESS.read_text("utf-8").split("[loads]")[0], encoding="utf-8")
    path = tmp_path / "m.toml"
    path.write_text('mechanism = "bare.toml"\n[forces]\nmu_F = 20\nR34 = 3\n', encoding="utf-8")
    with pytest.raises(InputError) as info:
        ck.load(path)
    assert info.value.problems == [
        f"line 2: forces: the mechanism ({mech}) gives no loads: the force analysis needs its "
        '[loads], e.g. [loads.links.3] mass = 10, J_S = 0.4, centre = "S3" (README: Loads)']


def test_a_kinematic_file_has_no_force_analysis(capsys):
    """The check of the plans alone reads no loads and draws no force plan (its output is
    pinned byte for byte by test_pinned)."""
    meas = ck.load(SAMPLES / "check_press.toml")
    assert meas.forces is None and all(it.plan in ck.PLANS for it in meas.items)


def test_f_y_and_the_lever_disagree_only_under_the_lever_mistake(templates):
    meas = templates[FOURBAR]
    ctx = meas.forces
    exact = ctx.drawn()
    l_ab = ctx.analysis.crank_length
    assert exact.F_y * l_ab == pytest.approx(exact.values[cf.M_Y], rel=1e-9)
    for mk in cf.hypotheses(ctx, meas.items):
        fd = ctx.drawn(None, mk)
        if mk.kind in ("lever-unturned", "moment-sense"):
            continue
        assert fd.F_y * l_ab == pytest.approx(fd.values[cf.M_Y], rel=1e-9), mk
    fd = ctx.drawn(None, find(meas, "lever-unturned", "lever"))
    assert not math.isclose(fd.F_y * l_ab, fd.values[cf.M_Y], rel_tol=0.05)


README_FILE = """mechanism = {mech}
[scales]
mu_v = 0.05
[forces]
mu_F = 20
"R34^τ" = 1
G4 = 1.5
"Φ4" = 3.2
P = 55
R05 = 13.5
"R34^n" = 58
R12 = 75
pa = 60
h."Φ4" = 59.5
h.P = 70
[values]
R34 = 1160
"F_у" = 1386
"M_у" = "208 ccw"
"M_Φ4" = "4,15 Н·м по часовой стрелке"
"""


def test_the_readme_example(tmp_path, capsys):
    """README's file of the press with Φ4 laid along a_S4, and what it says of it."""
    path = tmp_path / "student.toml"
    path.write_text(README_FILE.format(mech=_key(str(PRESS))), encoding="utf-8")
    code, out, _ = run(capsys, "check", path)
    assert code == 1
    assert out.splitlines()[-4:] == [
        "Overall: 5 of 14 items beyond tolerance: R34^n, R12, R34, F_у, M_у.",
        "Diagnosis: the inertia force Φ4 is laid along the acceleration a_S4 instead of against it.",
        "  explains: R34^n, R12, R34, F_у, M_у (all 5 items beyond tolerance)",
        "  correction: Φ4 = −m4·a_S4: through S4, against the acceleration of the centre of mass (πs4 on the "
        "acceleration plan, turned round)"]
    text = (SAMPLES.parent / "README.md").read_text("utf-8")
    readme = {line.split("#")[0].strip() for line in text.splitlines()}
    assert all(line in readme for line in README_FILE.splitlines()[1:] if line)  # the file README shows


# ---------------------------------------------------------------------------------------
# hostile force items: exit 0, 1 or 2, never a traceback
# ---------------------------------------------------------------------------------------

_NAMES = st.sampled_from(["R34^τ", "R34t", "R05", "G4", "Фи4", "Ми3", "P", "Р", "pa", "pvb", "h", "mu_F",
                          "μF", "F_у", "FУ", "M_у", "R12", "R99", "", " ", "π", "h.G4", "Σ", "R34^n",
                          "M_Φ3(C)", "\u200b"])
_VALUES = st.one_of(
    st.floats(allow_nan=True, allow_infinity=True), st.integers(-10**20, 10**20), st.booleans(),
    st.sampled_from(["12", "12,5", "-3", "1e999", "4 ccw", "4 Н·м по ч.с.", "98 H", "7 kN", "nan", "",
                     "ccw"]),
    st.just([1, 2]), st.just({"G4": 3}), st.just({"4-5": 10, "9": 1}), st.just({"Q": "x"}))


def _toml(value) -> str:
    """A value as TOML writes it (inline), for the hostile files."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float):
        if math.isnan(value):
            return "nan"
        return ("inf" if value > 0 else "-inf") if math.isinf(value) else repr(value)
    if isinstance(value, int):
        return str(value)
    if isinstance(value, str):
        return json.dumps(value)
    if isinstance(value, list):
        return "[" + ", ".join(map(_toml, value)) + "]"
    return "{ " + ", ".join(f"{json.dumps(k)} = {_toml(v)}" for k, v in value.items()) + " }"


@st.composite
def hostile(draw) -> str:
    """A measurement file of the press whose [forces] and [values] hold names and values
    a file should not: near misses, junk, tables and lists where numbers go."""
    forces = {draw(_NAMES): draw(_VALUES) for _ in range(draw(st.integers(0, 5)))}
    values = {draw(_NAMES): draw(_VALUES) for _ in range(draw(st.integers(0, 3)))}
    lines = [f"mechanism = {json.dumps(str(PRESS))}", "[scales]",
             f"mu_v = {_toml(draw(st.sampled_from([0.05, 0, 'x', -1])))}"]
    if forces or draw(st.booleans()):
        lines += ["[forces]", *(f"{json.dumps(k)} = {_toml(v)}" for k, v in forces.items())]
    if values:
        lines += ["[values]", *(f"{json.dumps(k)} = {_toml(v)}" for k, v in values.items())]
    return "\n".join(lines) + "\n"


def test_hostile_force_items_exit_0_1_or_2(tmp_path, capsys):
    codes = []

    @settings(max_examples=80, deadline=None, derandomize=True, database=None,
              suppress_health_check=list(HealthCheck))
    @given(hostile())
    def check(text):
        path = tmp_path / "h.toml"
        path.write_text(text, encoding="utf-8")
        code, _, err = run(capsys, "check", path)
        assert code in (0, 1, 2), err
        assert "Traceback" not in err and "internal error" not in err
        codes.append(code)

    check()
    assert 2 in codes


def test_an_acceleration_plan_drawn_ten_times_too_large_gives_ten_times_the_inertia_loads(tmp_path):
    """The carry-over checked by its meaning: a student who reads a_S and ε off an
    acceleration plan drawn 10 times too large computes every inertia force and moment 10
    times too large, and the weights as they are."""
    meas = every_item(tmp_path, PRESS, kinematic=True)
    mk = next(m for m in ck.hypotheses(meas.solution, {"acceleration"})
              if m.kind == "scale" and m.plan == "acceleration" and m.factor == 10)
    drawn, exact = ck.redraw(meas, mk).forces, meas.forces.drawn()
    kinds = {ld.name: ld.kind for ld in meas.forces.analysis.loads}
    assert {"inertia", "inertia moment", "weight"} <= set(kinds.values())
    for name, kind in kinds.items():
        times = {"inertia": 10, "inertia moment": 10}.get(kind, 1)
        assert drawn.values[name] == pytest.approx(times * exact.values[name], rel=1e-12), name


def test_the_lever_not_turned_by_its_definition(templates):
    """The four-bar's lever drawn on the velocity plan as it is: each arm the distance from
    the pole to the force's line through the image v/μv of its point, F_у = Σ (v/μv × F) /
    (pb·sign ω1), worked out here from the solution's velocities."""
    meas = templates[FOURBAR]
    sol = meas.solution
    mu = sol.velocity.mu
    fd = meas.forces.drawn(None, find(meas, "lever-unturned", "lever"))
    total = 0.0
    for ld in meas.forces.analysis.loads:
        v = complex(sol.scalar.velocity[ld.point]) / mu
        F = complex(ld.force)
        moment = v.real * F.imag - v.imag * F.real
        total += moment
        assert fd.arms[ld.name] == pytest.approx(abs(moment) / abs(F), rel=1e-12, abs=1e-12)
    pb = abs(complex(sol.scalar.velocity["B"])) / mu
    assert fd.pb == pytest.approx(pb) and fd.F_y == pytest.approx(total / pb, rel=1e-12)
    assert abs(fd.F_y - meas.forces.drawn().F_y) > 0.05 * abs(meas.forces.drawn().F_y)


def test_a_reaction_read_off_a_force_plan_is_judged_at_that_plans_mu_F(templates):
    """The larger of 1 mm of μF and 5 % for a force read off a plan (one that closes it,
    a reaction drawn whole, the inner one, and the same force the other way round); 5 %
    for a load and for what a moment equation gives (R^τ, the slotted link's R12)."""
    per_mm = {it.name: it.per_mm for it in templates[PRESS].items if it.kind == "force"}
    read = {"R05": 20.0, "R34": 20.0, "R34^n": 20.0, "R54": 20.0, "R45": 20.0, "R43": 20.0, "R03": 20.0,
            "R32": 20.0, "R23": 20.0}
    computed = {"R34^τ": 0.0, "R12": 0.0, "R21": 0.0, "G4": 0.0, "Φ4": 0.0, "P": 0.0, "R01": 0.0}
    assert {k: per_mm[k] for k in read} == read
    assert {k: per_mm[k] for k in computed} == computed


@pytest.mark.parametrize("variant", [2, 5])
def test_a_variant_is_checked_with_its_tables_loads(tmp_path, capsys, variant):
    """A file of ``variant = N``: Table 2's loads (5 kg per metre, the resistance 100·G)
    give the force analysis; its exact F_у and M_у pass, F_у ten times off does not."""
    path = tmp_path / "v.toml"
    path.write_text(f'variant = {variant}\n[values]\n"F_у" = 1\n', encoding="utf-8")
    ctx = ck.load(path).forces
    exact = ctx.drawn()
    M = exact.values[cf.M_Y]
    path.write_text(f'variant = {variant}\n[values]\n"F_у" = {abs(exact.F_y):.6g}\n'
                    f'"M_у" = "{abs(M):.6g} {"ccw" if M > 0 else "cw"}"\n', encoding="utf-8")
    code, out, _ = run(capsys, "check", path)
    assert code == 0, out
    path.write_text(f'variant = {variant}\n[values]\n"F_у" = {10 * abs(exact.F_y):.6g}\n', encoding="utf-8")
    code, out, _ = run(capsys, "check", path)
    assert code == 1 and "F_у" in out
