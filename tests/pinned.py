"""The outputs pinned by ``tests/test_pinned.py``: what every command writes for the samples,
the built-in variants and every built-in scene, as SHA-256 digests in
``tests/pinned.json``.

A change that alters an output on purpose says so in its commit and updates the digests:

    python tests/pinned.py --update          # rewrite tests/pinned.json
    python tests/pinned.py --write DIR       # every output as a file, to diff two trees

Each output is produced in-process through the command line (``plans.cli.main``) from a
scratch folder, so that no path of the checkout reaches the text.
"""

from __future__ import annotations

import contextlib
import hashlib
import io
import json
import os
import shutil
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
MANIFEST = Path(__file__).resolve().parent / "pinned.json"
VARIANTS = range(10)


def _run(argv: list[str]) -> tuple[int, bytes, bytes]:
    from plans.cli import main

    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        code = main(argv)
    return code, out.getvalue().encode(), err.getvalue().encode()


def _jobs(scenes: list[str]) -> list[tuple[str, list[str], str | None]]:
    """(name, argv, file the command writes or None for stdout)."""
    sources = [("press", ["samples/press.toml"]), ("fourbar", ["samples/fourbar.toml"])]
    sources += [(f"variant{n}", ["--variant", str(n)]) for n in VARIANTS]
    sources += [(f"scene-{s}", [f"scene-{s}.toml"]) for s in scenes]
    jobs = []
    for name, src in sources:
        jobs += [
            (f"{name}.solve.txt", ["solve", *src], None),
            (f"{name}.solve.json", ["solve", *src, "--json"], None),
            (f"{name}.cycle.json", ["cycle", *src, "--json"], None),
            (f"{name}.cycle.csv", ["cycle", *src, "--csv"], None),
            (f"{name}.cycle.txt", ["cycle", *src], None),
            (f"{name}.report.en.md", ["report", *src, "--lang", "en"], None),
            (f"{name}.report.ru.md", ["report", *src, "--lang", "ru"], None),
        ]
        jobs.append((f"{name}.sheet.svg", ["sheet", *src, "-o", "out.svg"], "out.svg"))
        if not name.startswith("scene-"):  # the samples and the variants carry loads
            jobs += [
                (f"{name}.forces.txt", ["forces", *src], None),
                (f"{name}.forces.ru.txt", ["forces", *src, "--lang", "ru"], None),
                (f"{name}.forces.json", ["forces", *src, "--json"], None),
            ]
    jobs += [
        ("variant3.sheet.A2.ru.plans.svg",
         ["sheet", "--variant", "3", "--format", "A2", "--lang", "ru", "--plans", "2,8",
          "-o", "out.svg"], "out.svg"),
        ("press.sheet.en.plans.svg",
         ["sheet", "samples/press.toml", "--lang", "en", "--plans", "1,5", "-o", "out.svg"],
         "out.svg"),
        ("press.sheet.note.md",
         ["sheet", "samples/press.toml", "-o", "out.svg", "--note", "note.md"], "note.md"),
        # sheet 2, the force analysis: the samples, a crank-slider and a four-bar variant
        ("press.sheet2.A2.svg", ["sheet", "samples/press.toml", "--sheet", "2", "--format", "A2",
                                 "-o", "out.svg"], "out.svg"),
        ("fourbar.sheet2.svg", ["sheet", "samples/fourbar.toml", "--sheet", "2", "-o", "out.svg"],
         "out.svg"),
        ("variant0.sheet2.en.svg", ["sheet", "--variant", "0", "--sheet", "2", "--lang", "en",
                                    "-o", "out.svg"], "out.svg"),
        ("variant1.sheet2.A2.svg", ["sheet", "--variant", "1", "--sheet", "2", "--format", "A2",
                                    "-o", "out.svg"], "out.svg"),
        # both sheets in one run: sheet 2 beside sheet 1, the note with its force section
        ("variant3.sheets.2.svg", ["sheet", "--variant", "3", "--sheet", "1,2", "-o", "out.svg",
                                   "--note", "note.md"], "out-2.svg"),
        ("variant3.sheets.note.md", ["sheet", "--variant", "3", "--sheet", "1,2", "-o", "out.svg",
                                     "--note", "note.md"], "note.md"),
        ("check_press.txt", ["check", "samples/check_press.toml"], None),
        ("check_press.ru.txt", ["check", "samples/check_press.toml", "--lang", "ru"], None),
        ("check_press.json", ["check", "samples/check_press.toml", "--json"], None),
        ("check_forces.txt", ["check", "samples/check_forces.toml"], None),
        ("check_forces.ru.txt", ["check", "samples/check_forces.toml", "--lang", "ru"], None),
        ("check_forces.json", ["check", "samples/check_forces.toml", "--json"], None),
        ("check_press.overlay.svg", ["check", "samples/check_press.toml", "--svg", "over.svg"],
         "over.svg"),
    ]
    for case in sorted((ROOT / "tests" / "overlay_cases").glob("*.toml")):
        jobs.append((f"overlay-{case.stem}.json", ["check", f"tests/overlay_cases/{case.name}", "--json"],
                     None))
        jobs.append((f"overlay-{case.stem}.svg",
                     ["check", f"tests/overlay_cases/{case.name}", "--svg", "over.svg"], "over.svg"))
    jobs.append(("check_batch.txt",
                 ["check", *(f"tests/overlay_cases/{c.name}" for c in
                             sorted((ROOT / "tests" / "overlay_cases").glob("*.toml")))],
                 None))
    for bad in sorted((ROOT / "tests" / "corpus").glob("*.toml")):
        jobs.append((f"corpus-{bad.stem}.err", ["solve", f"corpus/{bad.name}"], None))
    cam = "samples/cam.toml"
    jobs += [
        ("cam.txt", ["cam", cam], None),
        ("cam.ru.txt", ["cam", cam, "--lang", "ru"], None),
        ("cam.json", ["cam", cam, "--json"], None),
        ("cam.csv", ["cam", cam, "--csv"], None),
        ("cam.sheet.ru.svg", ["cam", cam, "--lang", "ru", "-o", "out.svg"], "out.svg"),
        ("cam.sheet.en.A3.svg", ["cam", cam, "--format", "A3", "-o", "out.svg"], "out.svg"),
        ("cam.note.ru.md", ["cam", cam, "--lang", "ru", "--note", "note.md"], "note.md"),
    ]
    for bad in sorted((ROOT / "tests" / "corpus" / "cams").glob("*.toml")):
        jobs.append((f"corpus-cams-{bad.stem}.err", ["cam", f"corpus/cams/{bad.name}"], None))
    return jobs


def outputs() -> dict[str, bytes]:
    """Every pinned output, by name: its exit status, stdout (or the file written) and
    stderr."""
    from plans.model.scenes import SCENES

    scenes = sorted(n for n, s in SCENES.items() if s.toml is not None)
    here = os.getcwd()
    with tempfile.TemporaryDirectory() as tmp:
        work = Path(tmp)
        (work / "samples").mkdir()
        for f in ("press.toml", "fourbar.toml", "check_press.toml", "check_forces.toml", "cam.toml"):
            shutil.copy(ROOT / "samples" / f, work / "samples" / f)
        # the overlay cases name their mechanisms as ../../samples/…
        shutil.copytree(ROOT / "tests" / "overlay_cases", work / "tests" / "overlay_cases")
        shutil.copytree(ROOT / "tests" / "corpus", work / "corpus")
        for s in scenes:
            (work / f"scene-{s}.toml").write_text(SCENES[s].toml, encoding="utf-8")
        os.chdir(work)
        try:
            got = {}
            for name, argv, written in _jobs(scenes):
                code, out, err = _run(argv)
                if written is not None:
                    path = work / written
                    out = path.read_bytes() if path.exists() else b""
                    path.unlink(missing_ok=True)
                got[name] = b"exit %d\n" % code + out + b"\n--- stderr\n" + err
            return got
        finally:
            os.chdir(here)


def digests(got: dict[str, bytes]) -> dict[str, str]:
    return {k: hashlib.sha256(v).hexdigest() for k, v in sorted(got.items())}


def main(argv: list[str]) -> int:
    sys.path.insert(0, str(ROOT))
    got = outputs()
    if "--write" in argv:
        folder = Path(argv[argv.index("--write") + 1])
        folder.mkdir(parents=True, exist_ok=True)
        for name, data in got.items():
            (folder / name).write_bytes(data)
        print(f"{len(got)} outputs written to {folder}")
    if "--update" in argv:
        MANIFEST.write_text(json.dumps(digests(got), indent=1, ensure_ascii=False) + "\n",
                            encoding="utf-8")
        print(f"{len(got)} digests written to {MANIFEST}")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
