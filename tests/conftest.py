import os
import sys
from pathlib import Path

import matplotlib
import numpy as np
import pytest
from hypothesis import HealthCheck, settings

matplotlib.use("Agg")

# The benchmark suite (benchmarks/) is not part of the installed package; its independent
# reference (benchmarks/reference.py) and harness (benchmarks/bench.py) are imported from there.
sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "benchmarks"))

settings.register_profile(
    "ci", max_examples=60, deadline=None, suppress_health_check=[HealthCheck.too_slow]
)
settings.register_profile("dev", max_examples=200, deadline=None)
settings.load_profile(os.environ.get("HYPOTHESIS_PROFILE", "ci"))


@pytest.fixture
def rng():
    return np.random.default_rng(12345)


@pytest.fixture(autouse=True)
def _no_foreign_event_loop(request, monkeypatch):
    """Outside the browser tests, page requests are answered as they arrive.

    The browser tests' Playwright (a session fixture) leaves its event loop running in this
    thread; a canvas would then defer each answer to that loop (``PictureCanvas.defer``, for a
    kernel's idle message) and a kernel-side test would wait for it in vain.  Tests that want
    deferral make a loop of their own, in a thread of their own, and set ``defer`` on the canvas.
    """
    if "browser" in request.node.nodeid.split("::")[0].split("/"):
        return
    import asyncio

    try:
        asyncio.get_running_loop()
    except RuntimeError:
        return
    from planargeo.widgets.canvas import PictureCanvas

    monkeypatch.setattr(PictureCanvas, "defer", False)
