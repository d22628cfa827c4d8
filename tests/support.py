"""What several test files share: the command line run in-process, and the problems a
file of the malformed-input corpus says it must produce."""

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
