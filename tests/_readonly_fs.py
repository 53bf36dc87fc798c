"""Run a command with a folder made read-only at the file-system level (not by permissions, which
root ignores): a private mount namespace (``unshare --mount``) in which ``folder`` is a read-only
bind mount of itself (or an empty read-only tmpfs).  The rest of the machine sees no change."""
from __future__ import annotations

import shlex
import shutil
import subprocess

import pytest


def _unshare_works() -> bool:
    if shutil.which("unshare") is None:
        return False
    r = subprocess.run(["unshare", "--mount", "true"], capture_output=True, timeout=30)
    return r.returncode == 0


def run_readonly(folder, argv, *, empty: bool = False, timeout: float = 300) -> subprocess.CompletedProcess:
    """``argv`` run where ``folder`` is on a read-only file system (its files kept, or ``empty``).

    Skips the calling test when mount namespaces are not available here.
    """
    if not _unshare_works():
        pytest.skip("unshare --mount is not available (needs root or user namespaces)")
    f = shlex.quote(str(folder))
    mount = (f"mount -t tmpfs -o ro none {f}" if empty
             else f"mount --bind {f} {f} && mount -o remount,bind,ro {f}")
    script = f"{mount} && exec {' '.join(shlex.quote(str(a)) for a in argv)}"
    return subprocess.run(["unshare", "--mount", "--propagation", "private", "sh", "-c", script],
                          capture_output=True, text=True, timeout=timeout)
