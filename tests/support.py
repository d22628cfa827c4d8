"""What several test files share: the command line run in-process, the problems a file
of the malformed-input corpus says it must produce, a four-bar standing upright, and
measurement files of a variant's exact plans (the check's tests)."""

from pathlib import Path

from plans.check import verdict as ck
from plans.cli import main


def run(capsys, *argv):
    """(exit status, stdout, stderr) of ``plans *argv``; paths may be Path objects."""
    code = main([str(a) for a in argv])
    out, err = capsys.readouterr()
    return code, out, err


def expectations(path: Path) -> list[str]:
    """The messages a corpus file names in its leading ``# expect:`` lines."""
    out = []
    for line in path.read_bytes().split(b"\n"):
        if not line.startswith(b"# expect: "):
            break
        out.append(line[len(b"# expect: ") :].decode("utf-8"))
    assert out, f"{path.name}: no '# expect:' header"
    return out


def upright_fourbar(crank: float, coupler: float, rocker: float, height: float, hint: str) -> str:
    """A four-bar file with its rocker's pivot D straight above the crank's O (the line
    OD vertical), the crank at 0°, and the assembly hint ``hint`` for B."""
    return f"""
[frame]
O = [0.0, 0.0]
D = [0.0, {height!r}]
[driver]
link = 1
angle_deg = 0
omega = 10
[links.1]
axis = ["O", "A"]
points = {{ A = {crank!r} }}
[links.2]
axis = ["A", "B"]
points = {{ B = {coupler!r} }}
[links.3]
axis = ["D", "B"]
points = {{ B = {rocker!r} }}
[assembly]
B = "{hint}"
"""


#: a four-bar that cannot make a full turn: its crank rocks through ±99.72° (a str.format
#: template: ``angle`` in degrees from +x)
NON_GRASHOF = """
name = "Non-Grashof four-bar"
output = "C"
[frame]
A = [0.0, 0.0]
D = [0.2, 0.0]
[driver]
link = 1
angle_deg = {angle}
omega = 5
[links.1]
axis = ["A", "B"]
points = {{ B = 0.12 }}
[links.2]
axis = ["B", "C"]
points = {{ C = 0.15 }}
[links.3]
axis = ["D", "C"]
points = {{ C = 0.1 }}
[assembly]
C = "above BD"
"""


def ascii_name(name: str) -> str:
    return name.replace("π", "pi")


def plan_segments(sol) -> list[ck.Item]:
    """Every segment the two plans name, as items to measure."""
    out = []
    for kind, plan in (("velocity", sol.velocity), ("acceleration", sol.acceleration)):
        for name, (a, b) in ck.recorded_segments(plan).items():
            out.append(ck.Item("segments." + name, name, "segment", kind, 0.0, a, b))
    return out


def variant_exact(tmp_path, n: int, mu: dict):
    """Variant ``n``'s exact plans at the scales ``mu``, its plans' segments at them (mm),
    and ``write(segs)``: the measurement file of those segments, to 0.01 mm."""
    head = f"variant = {n}\n[scales]\n" + "".join(f"{k} = {v}\n" for k, v in mu.items())
    path = tmp_path / f"v{n}.toml"
    path.write_text(head + "[segments]\npb = 70\n", encoding="utf-8")
    sol = ck.load(path).solution
    exact = ck.simulate(sol, None)

    def write(segs):
        path.write_text(head + "[segments]\n" + "".join(f"{ascii_name(k)} = {x:.2f}\n"
                                                        for k, x in segs.items()), encoding="utf-8")
        return path

    return exact, {it.name: ck.expected(it, exact, mu) for it in plan_segments(sol)}, write
