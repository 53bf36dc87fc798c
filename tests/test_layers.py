"""The package's layers point one way, and no module imports another that imports it back.

An AST walk over every module of ``planargeo/`` (imports inside functions included):

    errors, _validate → geometry → screws → mechanics → algorithms → simulate → scenes
        → draw → gallery | widgets → cli, report, run_benchmarks, __main__

A module may import its own layer and the layers below; ``gallery`` and ``widgets`` are
siblings that never import each other; only the drawing layers and above may import
matplotlib or ipywidgets; nothing below the command line imports the ``planargeo`` package
itself (its ``__init__`` is the facade over the lower layers).
"""
from __future__ import annotations

import ast
from pathlib import Path

import pytest

import planargeo

PKG = Path(planargeo.__file__).parent

LAYERS = [
    {"planargeo.errors", "planargeo._validate", "planargeo.files"},
    {"planargeo.geometry"},
    {"planargeo.screws"},
    {"planargeo.mechanics"},
    {"planargeo.algorithms"},
    {"planargeo.simulate"},
    {"planargeo.scenes"},
    {"planargeo.draw"},
    {"planargeo.gallery", "planargeo.widgets"},
    {"planargeo.cli", "planargeo.report", "planargeo.run_benchmarks", "planargeo.__main__", "planargeo"},
]
DRAWING_LEVEL = 7
SIBLINGS = {("planargeo.gallery", "planargeo.widgets"), ("planargeo.widgets", "planargeo.gallery")}


def _modules() -> dict[str, Path]:
    out = {}
    for path in PKG.rglob("*.py"):
        parts = list(path.relative_to(PKG.parent).with_suffix("").parts)
        if parts[-1] == "__init__":
            parts.pop()
        out[".".join(parts)] = path
    return out


MODULES = _modules()


def _imports(name: str, path: Path) -> list[str]:
    """Every module ``name`` imports (absolute names; ``from pkg import submodule`` resolved)."""
    is_pkg = path.name == "__init__.py"
    found = []
    for node in ast.walk(ast.parse(path.read_text(encoding="utf-8"))):
        if isinstance(node, ast.Import):
            found += [a.name for a in node.names]
        elif isinstance(node, ast.ImportFrom):
            base = node.module or ""
            if node.level:
                pkg = name.split(".") if is_pkg else name.split(".")[:-1]
                pkg = pkg[:len(pkg) - node.level + 1]
                base = ".".join(pkg + ([node.module] if node.module else []))
            for a in node.names:
                sub = f"{base}.{a.name}"
                found.append(sub if sub in MODULES else base)
    return found


GRAPH = {name: sorted({m for m in _imports(name, path) if m in MODULES and m != name})
         for name, path in MODULES.items()}
EXTERNAL = {name: {m.split(".")[0] for m in _imports(name, path) if not m.startswith("planargeo")}
            for name, path in MODULES.items()}


def level(name: str) -> tuple[int, str]:
    best = None
    for i, layer in enumerate(LAYERS):
        for top in layer:
            if (name == top or name.startswith(top + ".")) and (best is None or len(top) > len(best[1])):
                best = (i, top)
    assert best is not None, f"{name} is in no layer: add it to LAYERS"
    return best


def test_every_module_has_a_layer():
    for name in MODULES:
        level(name)


@pytest.mark.parametrize("name", sorted(MODULES))
def test_imports_point_down(name):
    lo, top = level(name)
    bad = []
    for m in GRAPH[name]:
        l2, top2 = level(m)
        if l2 > lo or (top, top2) in SIBLINGS or (m == "planargeo" and lo < len(LAYERS) - 1):
            bad.append(m)
    assert not bad, f"{name} (layer {top}) imports the higher layers {bad}"


@pytest.mark.parametrize("name", sorted(MODULES))
def test_only_drawing_layers_import_matplotlib(name):
    if level(name)[0] < DRAWING_LEVEL:
        assert not EXTERNAL[name] & {"matplotlib", "ipywidgets", "ipympl", "IPython"}, name


def test_no_import_cycles():
    """Tarjan's strongly connected components of the import graph: every one a single module."""
    index, low, stack, on, cycles = {}, {}, [], set(), []

    def visit(v):
        index[v] = low[v] = len(index)
        stack.append(v)
        on.add(v)
        for w in GRAPH[v]:
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
                cycles.append(sorted(comp))

    for v in GRAPH:
        if v not in index:
            visit(v)
    assert not cycles, cycles


def test_the_check_sees_a_violation():
    """The walk resolves relative and ``from pkg import module`` imports (a check that cannot fail is none)."""
    assert "planargeo.errors" in GRAPH["planargeo.geometry.projective"]
    assert "planargeo.geometry.projective" in GRAPH["planargeo.geometry.conics"]
    assert level("planargeo.widgets.chain")[0] > level("planargeo.algorithms.aba")[0]


def test_installed_package_imports_nothing_from_tests_or_benchmarks():
    bad = {n: sorted(e & {"tests", "benchmarks", "bench", "reference", "conftest"}) for n, e in EXTERNAL.items()}
    assert not {n: e for n, e in bad.items() if e}


@pytest.mark.parametrize("name", sorted(n for n in MODULES if n.startswith("planargeo.widgets")))
def test_widgets_import_no_matplotlib(name):
    """Issue 21: explorers are drawn by the page from their pictures; only draw/ turns a picture into
    matplotlib (exports, stored images). No widget module imports matplotlib or ipympl, not even lazily."""
    assert not EXTERNAL[name] & {"matplotlib", "ipympl"}, (name, sorted(EXTERNAL[name]))
