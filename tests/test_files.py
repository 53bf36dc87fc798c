"""planargeo.files: atomic writes that never leave a truncated or half-replaced set (issue 16.1, 16.2)."""
from __future__ import annotations

import os
import stat
import subprocess
import sys

import pytest

from planargeo.errors import InputError, OutputError
from planargeo.files import atomic_write, atomic_write_many


def _limited(code: str, limit: int) -> subprocess.CompletedProcess:
    """Run ``code`` in a fresh process whose files may not grow past ``limit`` bytes (a full device)."""
    pre = ("import resource, signal; signal.signal(signal.SIGXFSZ, signal.SIG_IGN); "
           f"resource.setrlimit(resource.RLIMIT_FSIZE, ({limit}, {limit}))\n")
    return subprocess.run([sys.executable, "-c", pre + code], capture_output=True, text=True, timeout=60)


def test_failure_midway_leaves_the_old_file_whole(tmp_path):
    """A 66 kB file rewritten under a 10 kB limit: OutputError, the old bytes intact, no temporary left."""
    target = tmp_path / "view.svg"
    old = b"<svg>" + b"x" * 66000 + b"</svg>"
    target.write_bytes(old)
    r = _limited("from planargeo.files import atomic_write\n"
                 "from planargeo.errors import OutputError\n"
                 f"try:\n    atomic_write({str(target)!r}, b'y' * 50000)\n"
                 "except OutputError as e:\n    print('OutputError', e)\n", 10000)
    assert r.returncode == 0, r.stderr
    assert r.stdout.startswith("OutputError cannot write") and "File too large" in r.stdout
    assert target.read_bytes() == old
    assert [p.name for p in tmp_path.iterdir()] == ["view.svg"]


def test_many_is_all_or_nothing(tmp_path):
    """The first file fits the limit, the second does not: neither target changes."""
    a, b = tmp_path / "a.txt", tmp_path / "b.txt"
    a.write_text("old a")
    b.write_text("old b")
    r = _limited("from planargeo.files import atomic_write_many\n"
                 f"atomic_write_many({{{str(a)!r}: 'new a', {str(b)!r}: 'b' * 5000}})\n", 1000)
    assert r.returncode == 1 and "OutputError" in r.stderr
    assert (a.read_text(), b.read_text()) == ("old a", "old b")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a.txt", "b.txt"]


def test_dev_full_is_refused_and_never_replaced():
    """/dev/full is a device: writing it is refused before anything is staged beside it."""
    before = os.stat("/dev/full")
    with pytest.raises(OutputError, match="not a regular file"):
        atomic_write("/dev/full", "x")
    after = os.stat("/dev/full")
    assert stat.S_ISCHR(after.st_mode) and after.st_rdev == before.st_rdev
    assert not any(n.startswith(".full.") for n in os.listdir("/dev"))


def test_folder_target_and_bad_arguments(tmp_path):
    with pytest.raises(OutputError, match="not a regular file"):
        atomic_write(tmp_path, "x")
    with pytest.raises(InputError, match="must be bytes or str"):
        atomic_write(tmp_path / "a", None)
    with pytest.raises(InputError, match="path must"):
        atomic_write(None, "x")
    with pytest.raises(InputError, match="path must name a file"):
        atomic_write(str(tmp_path / "a\0b"), "x")
    assert list(tmp_path.iterdir()) == []


def test_normal_permissions(tmp_path):
    mask = os.umask(0o027)
    try:
        p = atomic_write(tmp_path / "a.txt", "hello")
    finally:
        os.umask(mask)
    assert stat.S_IMODE(p.stat().st_mode) == 0o640
    assert p.read_text() == "hello"
    assert atomic_write_many({tmp_path / "b" / "c.txt": b"\x00\x01"}) == [tmp_path / "b" / "c.txt"]
