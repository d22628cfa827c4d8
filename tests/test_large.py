"""A mechanism of the most links a file may have (200): the engine's work grows with its
links, not with their square (issue 22: a 199-link mechanism took 33–58 s a command)."""

from __future__ import annotations

import pytest
from support import run

from plans.kinematics import groups
from plans.kinematics.solver import Solver
from plans.model import from_dict


def chain(groups_: int) -> dict:
    """A crank, then ``groups_`` four-bar dyads in a chain, each hinged to the rocker
    before it and to a fixed pivot of its own: 1 + 2·groups_ links."""
    frame = {"A": [0.0, 0.0]} | {f"D{k}": [0.3 * (k + 1), 0.0] for k in range(groups_)}
    links = {"1": {"axis": ["A", "B0"], "points": {"B0": 0.1}}}
    for k in range(groups_):
        links[str(2 + 2 * k)] = {"axis": [f"B{k}", f"C{k}"], "points": {f"C{k}": 0.3}}
        rocker = {f"C{k}": 0.25} | ({f"B{k + 1}": 0.12} if k + 1 < groups_ else {})
        links[str(3 + 2 * k)] = {"axis": [f"D{k}", f"C{k}"], "points": rocker}
    return {"name": "chain", "frame": frame, "links": links,
            "driver": {"link": 1, "angle_deg": 60, "omega": 10},
            "assembly": {f"C{k}": f"above B{k}D{k}" for k in range(groups_)}}


def test_the_hints_of_a_long_chain_are_read_group_by_group(monkeypatch):
    """Each group's two assemblies were tried by solving every group before it again
    from the crank: 99 groups took 9,900 group solves (4.5 s). Each group is now tried
    from the state of those before it: two solves a group."""
    steps = []
    step = groups.Recorded.step

    def counted(self, *args):
        steps.append(1)
        return step(self, *args)

    monkeypatch.setattr(groups.Recorded, "step", counted)
    mech = from_dict(chain(60), "chain")
    Solver(mech)
    assert len(steps) <= 2 * 60 + 2


@pytest.mark.parametrize("command", ["solve", "report", "cycle"])
def test_a_mechanism_of_199_links_runs(tmp_path, capsys, command):
    import tomllib

    path = tmp_path / "chain.toml"
    path.write_text(_toml(chain(99)), "utf-8")
    assert tomllib.loads(path.read_text("utf-8"))
    code, out, err = run(capsys, command, path)
    assert code == 0, err
    assert out


def _toml(data: dict) -> str:
    """``data`` as TOML: the few shapes :func:`chain` makes."""
    def value(v):
        if isinstance(v, dict):
            return "{ " + ", ".join(f"{k} = {value(x)}" for k, x in v.items()) + " }"
        if isinstance(v, list):
            return "[" + ", ".join(value(x) for x in v) + "]"
        return f'"{v}"' if isinstance(v, str) else repr(v)

    lines = [f"name = {value(data['name'])}", "[frame]"]
    lines += [f"{k} = {value(v)}" for k, v in data["frame"].items()]
    lines += ["[driver]"] + [f"{k} = {value(v)}" for k, v in data["driver"].items()]
    for lid, body in data["links"].items():
        lines += [f"[links.{lid}]"] + [f"{k} = {value(v)}" for k, v in body.items()]
    lines += ["[assembly]"] + [f"{k} = {value(v)}" for k, v in data["assembly"].items()]
    return "\n".join(lines) + "\n"
