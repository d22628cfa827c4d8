"""The architecture, held: imports go down the layers only, no module imports another in a
loop, and nothing is imported inside a function to dodge one.

The layers, from the bottom (README, "How the code is laid out"):

    ground        plans.errors, geometry, fmt, scales, tolerances (importing one another)
    model         plans.model
    cams          plans.cams             (the ground and the model's file reading only)
    kinematics    plans.kinematics
    cycle         plans.cycle
    plan          plans.plan
    forces        plans.forces
    peers         plans.note, plans.check, plans.synthesis, plans.verify
    drawing       drawing
    command line  plans.cli              (the package face plans and plans.__main__ above all)

A module imports its own package's modules and any layer below its own; peers do not import
each other. The graph is read with ``ast`` from the source, imports inside functions
included (TYPE_CHECKING ones too: they are loops all the same).
"""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parent.parent

#: layer of each package (by its dotted prefix), from the bottom
LAYERS = (
    ({"ground"}, 0),
    ({"plans.model"}, 1),
    ({"plans.cams"}, 1.5),
    ({"plans.kinematics"}, 2),
    ({"plans.cycle"}, 3),
    ({"plans.plan"}, 4),
    ({"plans.forces"}, 5),
    ({"plans.note", "plans.check", "plans.synthesis", "plans.verify"}, 6),
    ({"drawing"}, 7),
    ({"plans.cli"}, 8),
    ({"plans", "plans.__main__"}, 9),
)
#: third-party packages that may be imported inside a function: optional or heavy, paid only
#: by the command that needs them
LAZY = {"cairosvg", "sympy", "mpmath", "ezdxf", "matplotlib", "docx", "fpdf", "pylinkage", "numba",
        "fontTools"}


def _modules() -> dict[str, Path]:
    out = {}
    for top in ("plans", "drawing"):
        for p in sorted((ROOT / top).rglob("*.py")):
            if "__pycache__" in p.parts or "fonts" in p.parts:
                continue
            parts = list(p.relative_to(ROOT).with_suffix("").parts)
            if parts[-1] == "__init__":
                parts = parts[:-1]
            out[".".join(parts)] = p
    return out


MODULES = _modules()


def _resolve(name: str) -> str | None:
    parts = name.split(".")
    while parts:
        if ".".join(parts) in MODULES:
            return ".".join(parts)
        parts.pop()
    return None


def _imports(mod: str, path: Path):
    """(target module, line, inside a function, the top-level name imported)."""
    tree = ast.parse(path.read_text(encoding="utf-8"))
    base = mod.split(".") if path.name == "__init__.py" else mod.split(".")[:-1]
    funcs = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.FunctionDef | ast.AsyncFunctionDef):
            for inner in ast.walk(node):
                if isinstance(inner, ast.Import | ast.ImportFrom):
                    funcs.add(id(inner))
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            for a in node.names:
                yield _resolve(a.name), node.lineno, id(node) in funcs, a.name.split(".")[0]
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                anchor = base[: len(base) - (node.level - 1)]
                src = ".".join(anchor + ([node.module] if node.module else []))
            else:
                src = node.module or ""
            for a in node.names:
                target = _resolve(f"{src}.{a.name}") or _resolve(src)
                yield target, node.lineno, id(node) in funcs, src.split(".")[0]


GROUND = {"plans.errors", "plans.geometry", "plans.fmt", "plans.scales", "plans.tolerances"}


def _layer(mod: str) -> tuple[str, float]:
    if mod in GROUND:
        return "ground", 0
    best = ("", -1)
    for names, rank in LAYERS:
        for name in names:
            if (mod == name or mod.startswith(name + ".")) and len(name) > len(best[0]):
                best = (name, rank)
    return best


GRAPH = {m: [(t, line, lazy, top) for t, line, lazy, top in _imports(m, p)] for m, p in MODULES.items()}


def test_every_module_is_in_a_layer():
    assert [m for m in MODULES if _layer(m)[1] < 0] == []


def test_imports_go_down_only():
    bad = []
    for mod, imports in GRAPH.items():
        own, rank = _layer(mod)
        for target, line, _, _ in imports:
            if target is None or target == mod:
                continue
            their, their_rank = _layer(target)
            if their == own:
                continue
            if their_rank > rank or (their_rank == rank and their != own):
                bad.append(f"{MODULES[mod].relative_to(ROOT)}:{line}: {mod} imports {target} "
                           f"({their}, layer {their_rank}, above or beside its own {own}, {rank})")
    assert bad == [], "\n".join(bad)


def test_no_import_loops():
    graph = {m: {t for t, *_ in imports if t and t != m} for m, imports in GRAPH.items()}
    index: dict[str, int] = {}
    low: dict[str, int] = {}
    stack: list[str] = []
    on: set[str] = set()
    loops: list[list[str]] = []
    counter = [0]

    def visit(v):
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on.add(v)
        for w in graph[v]:
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on.discard(w)
                comp.append(w)
                if w == v:
                    break
            if len(comp) > 1:
                loops.append(sorted(comp))

    for v in sorted(graph):
        if v not in index:
            visit(v)
    assert loops == []


def test_nothing_is_imported_inside_a_function_but_optional_packages():
    bad = []
    for mod, imports in GRAPH.items():
        for target, line, lazy, top in imports:
            if not lazy or top in LAZY:
                continue
            bad.append(f"{MODULES[mod].relative_to(ROOT)}:{line}: {top} ({target or 'stdlib'})")
    assert bad == [], "\n".join(bad)


@pytest.mark.parametrize("mod", sorted(MODULES))
def test_no_module_is_much_over_600_lines_without_a_reason(mod):
    text = MODULES[mod].read_text(encoding="utf-8")
    lines = text.count("\n")
    if lines <= 650:
        return
    doc = ast.get_docstring(ast.parse(text)) or ""
    assert "lines" in doc and "because" in doc, f"{mod}: {lines} lines, and its docstring gives no reason"


def _forks(tree) -> list[int]:
    """Lines that compare a language with a literal ("if lang == 'ru'"): a fork by language."""
    out = []
    for node in ast.walk(tree):
        if (isinstance(node, ast.Compare) and len(node.ops) == 1
                and isinstance(node.ops[0], ast.Eq | ast.NotEq)):
            sides = (node.left, node.comparators[0])
            named = [s for s in sides if isinstance(s, ast.Name | ast.Attribute)]
            literal = [s for s in sides if isinstance(s, ast.Constant) and isinstance(s.value, str)]
            if named and literal and (getattr(named[0], "id", None) or named[0].attr).endswith("lang"):
                out.append(node.lineno)
    return sorted(out)


def test_words_are_tables_not_forks_by_language():
    """A third language is a table, not an edit of every function (issue 20, item 4): no
    module compares a language with a literal; each reads its package's words by language."""
    bad = [f"{MODULES[mod].relative_to(ROOT)}:{line}" for mod, path in MODULES.items()
           for line in _forks(ast.parse(path.read_text(encoding="utf-8")))]
    assert bad == [], "\n".join(bad)


def test_a_fork_by_language_is_seen():
    assert _forks(ast.parse("x = 'ру' if lang == 'ru' else 'en'\nif self.lang != 'en': pass")) == [1, 2]
    assert _forks(ast.parse("w = WORDS[lang]\nif kind == 'ru': pass")) == []
