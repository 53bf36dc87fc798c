"""Build ``docs/equations.md``: the thesis's equation numbers → the functions that implement them.

Every implementing function cites its equations in its docstring, the way the code cites the
book: ``(thesis 3.31-3.42)``, ``(6.113b)``, ``thesis 7.54/7.56``.  This script finds the public
functions, classes, methods and properties of ``planargeo/`` by parsing, reads each one's
docstring as a reader sees it (imported: with its shared entries filled in), keeps the numbers that
are equation labels of the thesis (``(3.31)`` in ``shared/thesis``; a range ``3.31-3.42`` is
every label between), and writes one table row per equation.  ``planargeo/gallery/`` is left
out: its figure functions' docstrings are captions, citing what a figure illustrates.
``tests/test_equations_index.py`` checks that the committed file is what this script writes.

Run: ``python docs/equations_index.py`` (rewrites ``docs/equations.md``).
"""
from __future__ import annotations

import ast
import importlib
import inspect
import re
import sys
from collections import defaultdict
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
PKG = ROOT / "planargeo"
OUT = ROOT / "docs" / "equations.md"

NUM = r"(?<![\d.])\d{1,2}\.\d{1,3}[a-z]?(?![\d]|\.\d)"   # 7.38a, not the section 7.1.1
#: a citation: "thesis", "eq."/"equation(s)" or an opening parenthesis, then numbers joined by
#: ranges, commas, slashes or "and"
#: (a section number right after the prefix, "thesis 7.1.1: 7.2, 7.7a", is passed over)
CITE = re.compile(rf"(?:thesis|eqs?\.|equations?|\()\s*(?:\d+(?:\.\d+){{2,}}[:,;]?\s*)?"
                  rf"({NUM}(?:\s*(?:[-–,/]|and)\s*{NUM})*)")
PAIR = re.compile(rf"({NUM})\s*[-–]\s*({NUM})|({NUM})")


def _key(label: str) -> tuple:
    ch, rest = label.split(".")
    m = re.fullmatch(r"(\d+)([a-z]?)", rest)
    return int(ch), int(m.group(1)), m.group(2)


def thesis_labels() -> list[str]:
    """Every equation label ``(c.n)`` / ``(c.na)`` of the thesis, in order."""
    text = (ROOT.parent / "shared" / "thesis" / "projective-articulated-dynamics.md")
    if not text.exists():       # CI has no shared/ folder: the labels are committed beside this script
        return (ROOT / "docs" / "thesis_equation_labels.txt").read_text().split()
    return sorted(set(re.findall(rf"\(({NUM})\)", text.read_text(encoding="utf-8"))), key=_key)


def cited(doc: str, labels: list[str]) -> list[str]:
    """The equation labels a docstring cites (ranges expanded over ``labels``)."""
    known = set(labels)
    order = {l: i for i, l in enumerate(labels)}
    lettered = defaultdict(list)                       # "7.38" cites (7.38a) and (7.38b)
    for l in labels:
        if l[-1].isalpha():
            lettered[l[:-1]].append(l)
    known |= set(lettered)
    doc = doc.split("Examples\n--------")[0]           # numbers in examples are data, not citations
    out = []
    for m in CITE.finditer(doc):
        group = m.group(1)
        pairs = PAIR.findall(group)
        nums = [x for p in pairs for x in p if x]
        if m.group(0).startswith("(") and not all(x in known for x in nums):
            continue                                   # "(2.5, 1.25)": a coordinate, not a citation
        for lo, hi, one in pairs:
            if one:
                out += lettered.get(one, [one] if one in known else [])
            elif lo in known and hi in known and lo.split(".")[0] == hi.split(".")[0]:
                first, last = (lettered.get(lo, [lo])[0], lettered.get(hi, [hi])[-1])
                out += labels[order[first]:order[last] + 1]
            else:
                out += [y for x in (lo, hi) if x in known for y in lettered.get(x, [x])]
    return out


def implementations(labels: list[str]) -> dict[str, list[str]]:
    """``{label: ["planargeo.module.function", ...]}`` over the public functions, classes and methods."""
    index = defaultdict(list)
    for path in sorted(PKG.rglob("*.py")):
        if (PKG / "gallery") in path.parents or path.name == "__main__.py":   # captions; the command
            continue
        parts = list(path.relative_to(ROOT).with_suffix("").parts)
        if parts[-1] == "__init__":
            parts.pop()
        module = ".".join(parts)
        tree = ast.parse(path.read_text(encoding="utf-8"))
        mod = importlib.import_module(module)

        def doc(name, fallback):
            obj = mod
            for part in name.split("."):
                obj = getattr(obj, part, None)
            return (inspect.getdoc(obj) if obj is not None else None) or fallback

        def add(name, text):
            for label in dict.fromkeys(cited(text, labels)):
                index[label].append(f"{module}.{name}")

        def walk(nodes, prefix):
            for node in nodes:
                if isinstance(node, (ast.FunctionDef, ast.ClassDef)) and not node.name.startswith("_"):
                    name = f"{prefix}{node.name}"
                    add(name, doc(name, ast.get_docstring(node) or ""))
                    if isinstance(node, ast.ClassDef):
                        walk(node.body, f"{name}.")
                elif prefix and isinstance(node, ast.Assign) and isinstance(node.value, ast.Call):
                    # properties made by a factory (``x = _derived(f, "...")``): their own docstrings
                    for t in node.targets:
                        if isinstance(t, ast.Name) and not t.id.startswith("_"):
                            add(f"{prefix}{t.id}", doc(f"{prefix}{t.id}", ""))

        walk(tree.body, "")
    return index


def render() -> str:
    labels = thesis_labels()
    index = implementations(labels)
    rows = [f"| ({l}) | {', '.join(f'`{f}`' for f in index[l])} |" for l in labels if l in index]
    return "\n".join([
        "# Equations → code",
        "",
        "Each row is an equation of the thesis and the public functions whose docstrings cite it",
        "(so `grep -rn '3.41' planargeo` finds the same places). Generated by",
        "`python docs/equations_index.py` from the docstrings; `tests/test_equations_index.py` checks",
        "that this file is current. Errata to printed equations: [errata.md](errata.md).",
        "",
        f"{len(rows)} of the thesis's {len(labels)} numbered equations have code.",
        "",
        "| equation | implemented by |",
        "|---|---|",
        *rows,
        "",
    ])


def main() -> int:
    sys.path.insert(0, str(ROOT))
    from planargeo.files import atomic_write

    labels = thesis_labels()
    atomic_write(ROOT / "docs" / "thesis_equation_labels.txt", "\n".join(labels) + "\n")
    atomic_write(OUT, render())
    print(f"wrote {OUT}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
