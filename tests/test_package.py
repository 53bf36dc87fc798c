"""Package-level contracts: public names, and math never importing matplotlib."""
import ast
import subprocess
import sys
from pathlib import Path

import planargeo

PKG = Path(planargeo.__file__).parent
# Modules allowed to import matplotlib: drawing, widgets (on top of drawing) and the
# benchmark runner (charts).
DRAWING = {"draw", "widgets"}
ALLOWED_FILES = {"bench.py"}


def test_public_names_importable():
    for name in planargeo.__all__:
        assert hasattr(planargeo, name), name
    for name in ["Point", "Line", "Conic", "Twist", "Wrench", "Inertia", "join", "meet",
                 "pole", "polar", "percussion_axis", "revolute", "prismatic",
                 "revolute_prismatic", "plane", "fixed"]:
        assert name in planargeo.__all__


def test_import_does_not_load_matplotlib():
    code = "import sys, planargeo, planargeo.scenes as s; s.names(); print('matplotlib' in sys.modules)"
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "False"


def test_math_modules_never_import_matplotlib_or_widgets():
    offenders = []
    for path in PKG.rglob("*.py"):
        rel = path.relative_to(PKG)
        if rel.parts[0] in DRAWING or rel.name in ALLOWED_FILES:
            continue
        tree = ast.parse(path.read_text())
        for node in ast.walk(tree):
            names = []
            if isinstance(node, ast.Import):
                names = [a.name for a in node.names]
            elif isinstance(node, ast.ImportFrom):
                names = [node.module or ""]
                if node.level and (node.module or "").split(".")[0] in DRAWING:
                    names.append("planargeo.draw")
            for n in names:
                if n.startswith(("matplotlib", "ipywidgets", "planargeo.draw", "planargeo.widgets")):
                    offenders.append(f"{rel}: {n}")
    assert not offenders, offenders


def test_draw_never_imports_widgets():
    offenders = []
    for path in (PKG / "draw").rglob("*.py"):
        src = path.read_text()
        if "planargeo.widgets" in src or "from ..widgets" in src or "from ...widgets" in src:
            offenders.append(str(path.relative_to(PKG)))
    assert not offenders, offenders
