"""The package as installed, not as the source tree: every subpackage and data file of the
source tree must be in what ``pip install .`` put in the environment.

The suite runs from the project's root, where ``plans`` would import from the source tree
whatever was installed; so the installed copy is asked from a child Python started in an
empty folder. In CI (``pip install '.[test]'``, as README says) that is the wheel; a
subpackage that ``packages.find`` misses, or a data file that ``package-data`` leaves out, fails
here instead of on a user's machine.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
PACKAGES = ("plans", "drawing")

PROBE = r"""
import importlib, json, sys
from importlib import resources
names, files = json.loads(sys.argv[1])
out = {"modules": {}, "files": {}}
for name in names:
    out["modules"][name] = getattr(importlib.import_module(name), "__file__", None)
for pkg, rel in files:
    out["files"][pkg + "/" + rel] = resources.files(pkg).joinpath(rel).is_file()
print(json.dumps(out))
"""


def _source_modules() -> list[str]:
    names = []
    for pkg in PACKAGES:
        for path in sorted((ROOT / pkg).rglob("*.py")):
            rel = path.relative_to(ROOT).with_suffix("")
            parts = rel.parts[:-1] if rel.name == "__init__" else rel.parts
            if "__pycache__" not in parts and parts[-1] != "__main__":  # __main__ runs the CLI
                names.append(".".join(parts))
    return names


def _source_data() -> list[tuple[str, str]]:
    """The files beside the modules that the package reads at run time."""
    found = []
    for pkg in PACKAGES:
        for path in sorted((ROOT / pkg).rglob("*")):
            if path.is_file() and path.suffix not in (".py", ".pyc") and "__pycache__" not in path.parts:
                found.append((pkg, path.relative_to(ROOT / pkg).as_posix()))
    return found


def test_every_subpackage_and_data_file_is_installed(tmp_path):
    names, files = _source_modules(), _source_data()
    assert len(names) > 100 and ("plans", "data/table2.toml") in files  # the walk sees the tree
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "PYTHONSTARTUP")}
    run = subprocess.run([sys.executable, "-I", "-c", PROBE, json.dumps([names, files])],
                         cwd=tmp_path, env=env, capture_output=True, text=True, timeout=300)
    assert run.returncode == 0, run.stderr[-2000:]
    got = json.loads(run.stdout)
    missing = [f for f, ok in got["files"].items() if not ok]
    assert not missing, f"data files not installed: {missing}"
    # every module from one installed copy, none from the folder the child ran in
    homes = {Path(f).resolve().parents[len(n.split(".")) - 1 + f.endswith("__init__.py")]
             for n, f in got["modules"].items() if f}
    assert len(homes) == 1, homes
    assert len(got["modules"]) == len(names)
