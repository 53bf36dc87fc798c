"""Package-level contracts: public names, and math never importing matplotlib."""
import subprocess
import sys
from pathlib import Path

import planargeo
import pytest

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
    """draw/ builds pictures for widgets/, never the other way up (an import statement, not a mention)."""
    import ast

    offenders = []
    for path in (PKG / "draw").rglob("*.py"):
        for node in ast.walk(ast.parse(path.read_text())):
            names = ([a.name for a in node.names] if isinstance(node, ast.Import) else
                     [("." * node.level) + (node.module or "")] if isinstance(node, ast.ImportFrom) else [])
            if any(n.startswith("planargeo.widgets") or n.lstrip(".").startswith("widgets") and
                   n.startswith("..") for n in names):
                offenders.append(str(path.relative_to(PKG)))
    assert not offenders, offenders


# --------------------------------------------------------------------------- the main jobs, one attribute away
MAIN_JOBS = ["forward_dynamics", "inverse_dynamics", "simulate", "chain_model", "scene", "scenes"]


def test_import_loads_neither_numba_nor_the_algorithms():
    """The main jobs are loaded on first use: ``import planargeo`` imports no compiler and no algorithm."""
    code = ("import sys, planargeo; heavy = ['numba', 'scipy', 'matplotlib', 'planargeo.algorithms.aba', "
            "'planargeo.algorithms.rnea', 'planargeo.simulate.integrate', 'planargeo.scenes']; "
            "print([m for m in heavy if m in sys.modules])")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "[]"


def test_main_jobs_are_one_attribute_away_and_listed():
    from planargeo.algorithms.aba import forward_dynamics
    from planargeo.algorithms.rnea import inverse_dynamics
    from planargeo.mechanics.model import chain_model
    from planargeo.scenes import build

    for name in MAIN_JOBS:
        assert name in planargeo.__all__ and name in dir(planargeo), name
    assert planargeo.forward_dynamics is forward_dynamics
    assert planargeo.inverse_dynamics is inverse_dynamics
    assert planargeo.chain_model is chain_model
    assert planargeo.scene is build
    assert "slider-crank" in planargeo.scenes.names()
    with pytest.raises(AttributeError, match="no attribute 'forward_dynamic'"):
        planargeo.forward_dynamic


def test_main_jobs_compute_a_pendulum():
    """A uniform rod (m, L) pinned at one end: q̈ = -3 g cos q / (2 L) (from I = m L²/3 about the pivot);
    τ = I q̈ + m g (L/2) cos q inverts it; the scene and the simulation agree with the same model."""
    import numpy as np

    pg = planargeo
    model = pg.chain_model(1, mass=2.0, length=0.5)
    q = np.array([0.3])
    qdd = pg.forward_dynamics(model, q, [0.0], [0.0])
    np.testing.assert_allclose(qdd, [-3 * 9.81 * np.cos(0.3) / (2 * 0.5)], rtol=1e-13)
    tau = pg.inverse_dynamics(model, q, [0.0], [1.0])
    np.testing.assert_allclose(tau, [2.0 * 0.25 / 3 + 2.0 * 9.81 * 0.25 * np.cos(0.3)], rtol=1e-13)
    res = pg.simulate(model, [0.0], [0.0], 1e-3, method="RK4", dt=1e-4)
    np.testing.assert_allclose(res.q[-1], [0.5 * -3 * 9.81 / (2 * 0.5) * 1e-6], rtol=1e-6)
    assert pg.scene("two-body").name == "two-body"


def test_simulate_is_also_the_subpackage():
    """``pg.simulate`` is callable and still the subpackage: its modules import as before, in any order."""
    code = ("import planargeo.simulate.loops as L, planargeo as pg, inspect; "
            "from planargeo.simulate import integrate; "
            "print(L.__name__, pg.simulate.integrate is integrate, "
            "list(inspect.signature(pg.simulate).parameters)[:4])")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.strip() == "planargeo.simulate.loops True ['model', 'q0', 'qd0', 't_end']"
