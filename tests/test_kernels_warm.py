"""No wait on the compiler in a lesson (issue 24): the install step fills numba's cache with every kernel
signature the package calls (``python -m planargeo.algorithms.compiled --warm``).  Times are measured by
benchmarks, not asserted here; these tests check what is compiled and that the set-up asks for it."""
import subprocess
import sys
from pathlib import Path

import numba
import numpy as np
import pytest

from planargeo.algorithms import compiled
from planargeo.algorithms.aba import forward_dynamics
from planargeo.algorithms.rnea import inverse_dynamics
from planargeo.mechanics.model import chain_model

ROOT = Path(__file__).resolve().parents[1]
#: these read numba's dispatchers and cache, which NUMBA_DISABLE_JIT=1 does not make
COMPILED = pytest.mark.skipif(numba.config.DISABLE_JIT, reason="inspects numba's compiled dispatchers and cache")


@COMPILED
def test_warm_compiles_every_signature_the_package_calls():
    steps = [what for what, _ in compiled.warm()]
    for what in ("forward and inverse dynamics, one state", "forward dynamics, batch", "inverse dynamics, batch"):
        assert what in steps and f"{what}, external wrenches" in steps     # (one kernel for one state, both ways)
    assert "singular-joint check" in steps and "singular-joint check, external wrenches" in steps
    assert compiled.cache_is_warm()
    # every signature the warm-up compiled is one a call through the public functions uses: no new one appears
    from planargeo.algorithms import kernels
    before = {name: len(getattr(kernels, name).signatures) for name in compiled.ENTRY_POINTS}
    m = chain_model(3)
    z, fe = np.zeros(3), np.ones((3, 3))
    zb, feb = np.zeros((5, 3)), np.ones((5, 3, 3))
    for f in (forward_dynamics, inverse_dynamics):
        f(m, z, z, z)
        f(m, z, z, z, fe)
        f(m, zb, zb, zb)
        f(m, zb, zb, zb, feb)
        f(m, [0.1, 0.2, 0.3], [0, 0, 0], [0, 0, 0])         # lists: validated into the same arrays
    with pytest.raises(Exception):
        forward_dynamics(chain_model(1, mass=1.0), z[:1], z[:1], z[:1], np.full((1, 3), np.nan))
    assert {name: len(getattr(kernels, name).signatures) for name in compiled.ENTRY_POINTS} == before


def test_warm_command_and_its_place_in_the_install_step():
    out = subprocess.run([sys.executable, "-m", "planargeo.algorithms.compiled", "--warm"], capture_output=True,
                         text=True, timeout=600, check=True).stdout
    assert out.startswith("planargeo: compiling the dynamics kernels") and "kernels ready in" in out
    assert compiled.main([]) == 2
    dry = subprocess.run(["make", "-n", "-B", "install", f"BIN={Path(sys.executable).parent}"], cwd=ROOT,
                         capture_output=True, text=True, timeout=60).stdout
    lines = dry.splitlines()
    pip = next(i for i, x in enumerate(lines) if "pip install" in x and "-e" in x)
    warm = next(i for i, x in enumerate(lines) if "-m planargeo.algorithms.compiled --warm" in x)
    assert warm > pip                              # after the install, before the stamp
    placer = next(i for i, x in enumerate(lines) if "from planargeo.draw.picture import warm_labels" in x)
    assert placer > pip                            # the label placer's loops too (every picture's labels)


@COMPILED
def test_the_label_placer_is_compiled_once_then_loaded(tmp_path):
    """The placer's loops: compiled on a cold cache (``warm()`` says so), then loaded from it by the next process."""
    import os

    env = dict(os.environ, NUMBA_CACHE_DIR=str(tmp_path), MPLBACKEND="Agg")
    code = "from planargeo.draw.picture import warm_labels; print(warm_labels())"
    runs = [subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True, timeout=600,
                           check=True).stdout.split() for _ in range(2)]
    assert runs == [["False"], ["True"]]


@COMPILED
def test_a_cold_cache_is_seen_without_compiling(tmp_path):
    """With numba's cache in an empty folder the kernels are cold (the first call would compile): ``cache_is_warm``
    says so without compiling anything (warm after ``--warm``: the first test)."""
    import os

    env = dict(os.environ, NUMBA_CACHE_DIR=str(tmp_path))
    code = ("from planargeo.algorithms import compiled, kernels; "
            "w = compiled.cache_is_warm(); print(w, sum(len(getattr(kernels, n).signatures) "
            "for n in compiled.ENTRY_POINTS))")
    out = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, text=True, timeout=300, check=True)
    assert out.stdout.split() == ["False", "0"]
