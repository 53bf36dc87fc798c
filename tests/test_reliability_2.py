"""Reliability, second pass (issue 23): the findings ``make fuzz`` still reported, each with a test that
failed before its fix, plus the set-up's stamp of the compiled kernels."""
from __future__ import annotations

import os
import shutil
import subprocess
import time
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]


# --------------------------------------------------------------------------- Makefile: the kernels' stamp
def _fake_tree(tmp_path: Path) -> tuple[Path, Path]:
    """A copy of the Makefile with the files its install step depends on, and a fake ``.venv/bin/python``
    that logs its arguments instead of installing or compiling."""
    shutil.copy(ROOT / "Makefile", tmp_path / "Makefile")
    for rel in ("pyproject.toml", "planargeo/algorithms/kernels.py", "planargeo/algorithms/compiled.py",
                "planargeo/errors.py", "planargeo/mechanics/subspaces.py"):
        (tmp_path / rel).parent.mkdir(parents=True, exist_ok=True)
        (tmp_path / rel).write_text("# stand-in\n")
    log = tmp_path / "calls.log"
    py = tmp_path / ".venv" / "bin" / "python"
    py.parent.mkdir(parents=True)
    py.write_text(f'#!/bin/sh\necho "$*" >> "{log}"\n')
    py.chmod(0o755)
    return log, py


def _install(tmp_path: Path, log: Path) -> list[str]:
    """``make install`` in the fake tree: the python calls it made ("pip" / "warm"), in order."""
    if log.exists():
        log.unlink()
    subprocess.run(["make", "--no-print-directory", "install"], cwd=tmp_path, check=True, capture_output=True,
                   text=True, timeout=60)
    calls = log.read_text().splitlines() if log.exists() else []
    return ["pip" if "pip install" in c else "warm" if "compiled --warm" in c else c for c in calls]


def _newer(path: Path) -> None:
    """An edit of ``path``: a modification time after every stamp (make compares times to the nanosecond)."""
    time.sleep(0.05)
    os.utime(path)


@pytest.mark.skipif(shutil.which("make") is None, reason="make is not installed")
def test_the_kernel_cache_is_filled_again_when_a_kernel_source_changes(tmp_path):
    log, _ = _fake_tree(tmp_path)
    assert _install(tmp_path, log) == ["pip", "warm"]          # a fresh clone: install, then fill the cache
    assert _install(tmp_path, log) == []                       # nothing changed: nothing to do
    kernels = tmp_path / "planargeo/algorithms/kernels.py"
    _newer(kernels)
    assert _install(tmp_path, log) == ["warm"]                 # an edited kernel: compiled again, no re-install
    before = kernels.stat().st_mtime
    _newer(tmp_path / "planargeo/errors.py")                   # COND_LIMIT is frozen into the machine code
    assert _install(tmp_path, log) == ["warm"]
    assert kernels.stat().st_mtime > before                    # numba sees a new kernels.py: no stale load
    assert _install(tmp_path, log) == []                       # and that touch asks for nothing more
    _newer(tmp_path / "pyproject.toml")
    assert _install(tmp_path, log) == ["pip", "warm"]          # new dependencies: install, then the cache
