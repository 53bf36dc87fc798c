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
KNOWN: dict[str, str] = {}


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
