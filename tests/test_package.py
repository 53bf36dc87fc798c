"""Package-level contracts: public names, and math never importing matplotlib."""
import subprocess
import sys
from pathlib import Path

import planargeo

PKG = Path(planargeo.__file__).parent
# (which layers may import matplotlib, and that imports point down: tests/test_layers.py)


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


def test_draw_never_imports_widgets():
    offenders = []
    for path in (PKG / "draw").rglob("*.py"):
        src = path.read_text()
        if "planargeo.widgets" in src or "from ..widgets" in src or "from ...widgets" in src:
            offenders.append(str(path.relative_to(PKG)))
    assert not offenders, offenders
