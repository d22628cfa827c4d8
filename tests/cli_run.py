"""Run the command line in-process, as the tests of the commands do."""

from plans.cli import main


def run(capsys, *argv):
    """(exit status, stdout, stderr) of ``plans *argv``; paths may be Path objects."""
    code = main([str(a) for a in argv])
    out, err = capsys.readouterr()
    return code, out, err
