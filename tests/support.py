"""What several test files share: the command line run in-process, the problems a file
of the malformed-input corpus says it must produce, and a four-bar standing upright."""

from pathlib import Path

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
