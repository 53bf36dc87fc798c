"""The fuzz suite's fast profile (issue 16): every entry point, 20 derandomized calls each, no defect.

It runs ``tests/fuzz/run.py --per-target 20 --derandomize`` in a fresh process (its own 4 GB
address-space limit and alarm-based hang detection, away from the test workers) and reads the
tallies.  Defects of entry points owned by other parts of the code are listed in :data:`KNOWN`
with their owner; the test fails on any defect not listed there, and on a listed entry point
that has become clean (remove it from the list: the fix landed).
"""
from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

RUN = Path(__file__).resolve().parent / "fuzz" / "run.py"
BAD = ("foreign", "non-finite", "hang", "inconsistent")

#: Entry points with defects found by the fast profile that other modules must fix (owner: what).
KNOWN = {
    # mechanics/joints.py, subspaces.py ("names"): overflow warnings, complex and None accepted
    "joints.reaction_space_of": "mechanics: overflow warning in reaction_space_of for 1e200 spaces",
    "subspaces.reactive_acceleration_space": "mechanics: overflow warning for 1e300 inputs",
    "subspaces.active_acceleration": "mechanics: overflow warning in matmul",
    "subspaces.reactive_acceleration": "mechanics: overflow warning in matmul",
    "subspaces.wrench_projectors": "mechanics: invalid-value warning for a zero motion space",
    "subspaces.twist_projectors": "mechanics: invalid-value warning for a zero motion space",
    "subspaces.inertia_decomposition": "mechanics: invalid-value warning for a zero motion space",
    "subspaces.inverse_inertia_decomposition": "mechanics: invalid-value warning for a zero motion space",
    "subspaces.joint_cond": "mechanics: inf for zeros, TypeError for None",
    "subspaces.joint_scale": "mechanics: complex accepted with a ComplexWarning",
    "subspaces.singular_joint_error": "mechanics: TypeError for cond=None",
    # algorithms/crba.py, mechanics/kinematics.py, model.py ("kernels"): issue 16 items 4-7
    "mass_matrix": "kernels: overflow warning and NaN for q near 1e200",
    "bias_forces": "kernels: overflow warning for qd near 1e160",
    "kinematics": "kernels: overflow warning for qd near 1e160",
    "chain_model": "kernels: hangs on n = 10**30, TypeError for bad n",
    "random_model": "kernels: hangs on huge n, TypeError for n = 3.0",
    # widgets ("widgets"): explorer.set with a wrong type lets traitlets' TraitError out (issue 16 item 3)
    **{f"{name}.set": "widgets: TraitError out of set() for None / a dict / a NaN checkbox"
       for name in ("ProjectiveExplorer", "PercussionExplorer", "ScrewSumExplorer", "ChainExplorer",
                    "CarExplorer", "SliderCrankExplorer", "TreeExplorer")},
    "Explorer.export_svg": "widgets: a raw OSError (a folder, /dev/full) instead of OutputError (issue 16 item 8)",
}


@pytest.fixture(scope="module")
def tallies(tmp_path_factory):
    work = tmp_path_factory.mktemp("fuzz")
    out = work / "tallies.json"
    env = dict(os.environ, MPLBACKEND="Agg")
    r = subprocess.run([sys.executable, str(RUN), "--per-target", "20", "--derandomize", "--json", str(out)],
                       capture_output=True, text=True, timeout=900, env=env, cwd=work)
    assert out.exists(), r.stderr[-3000:]
    return json.loads(out.read_text())


@pytest.mark.slow
def test_fast_fuzz_profile_finds_no_new_defect(tallies):
    assert len(tallies) >= 150                                   # every module's public functions, and the rest
    calls = sum(sum(t["counts"].values()) for t in tallies.values())
    assert calls >= 3000
    defects = {name: t for name, t in tallies.items() if any(t["counts"].get(o, 0) for o in BAD)}
    new = {name: t["examples"] for name, t in defects.items() if name not in KNOWN}
    assert not new, "defects: " + json.dumps(new, indent=1)[:4000]
    fixed = sorted(set(KNOWN) - set(defects))
    assert not fixed, f"no longer defective (remove from KNOWN): {fixed}"
