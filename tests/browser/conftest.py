"""Fixtures for the real-browser tests: a throw-away JupyterLab server and headless chromium.

Both are shared by the whole session (one server, one browser: the suite runs on two
cores); each test opens its own page.  Everything the server writes (config, settings,
workspaces, runtime files, the notebook copies) lives in a temporary directory; news
fetching, update checks and the extension manager's network calls are switched off.
"""
from __future__ import annotations

import json
import os
import shutil
import socket
import subprocess
import sys
import time
import urllib.request
from pathlib import Path

import pytest

from browser_harness import CHROMIUM, CHROMIUM_ARGS, LabServer, VoilaServer  # noqa: F401

ARTIFACTS = Path(__file__).parent / "artifacts"


def _need_chromium():
    if not Path(CHROMIUM).exists():
        pytest.skip(f"{CHROMIUM} not found: install Debian's chromium (apt-get install -y chromium)")
    pytest.importorskip("playwright.sync_api", reason="playwright is not installed")


@pytest.fixture(scope="session")
def lab(tmp_path_factory):
    _need_chromium()
    tmp = tmp_path_factory.mktemp("lab")
    root = tmp / "nb"
    root.mkdir()
    server = LabServer(root, tmp)
    try:
        yield server
    finally:
        server.stop()


@pytest.fixture(scope="session")
def browser():
    _need_chromium()
    from playwright.sync_api import sync_playwright

    with sync_playwright() as p:
        b = p.chromium.launch(executable_path=CHROMIUM, args=CHROMIUM_ARGS)
        try:
            yield b
        finally:
            b.close()


def copy_notebook(src: Path, root: Path, name: str = "under-test.ipynb") -> Path:
    """Copy ``src`` into the server root (the original is never touched)."""
    dst = root / name
    shutil.copy(src, dst)
    return dst


@pytest.fixture(scope="module")
def harness_page(browser):
    """The page renderer alone on a static page (:class:`browser_harness.CanvasHarness`)."""
    from browser_harness import CanvasHarness

    with CanvasHarness() as h:
        page = h.open(browser)
        try:
            yield page
        finally:
            page.close()


def write_notebook(path: Path, cells) -> Path:
    """A notebook of code ``cells`` on the Python 3 kernel, written to ``path``."""
    import nbformat

    nb = nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell(c) for c in cells])
    nb.metadata["kernelspec"] = {"name": "python3", "display_name": "Python 3", "language": "python"}
    nbformat.write(nb, path)
    return path


def open_in_lab(page, lab, name: str, file_browser: bool | None = None) -> None:
    """Open notebook ``name`` of ``lab`` in ``page``, wait for its kernel, open (True) or close (False)
    the file browser, and run all cells."""
    page.goto(f"{lab.url}/lab/tree/{name}?reset", wait_until="domcontentloaded", timeout=120_000)
    page.wait_for_function("window.jupyterapp && window.jupyterapp.shell.currentWidget"
                           " && window.jupyterapp.shell.currentWidget.sessionContext.session"
                           " && window.jupyterapp.shell.currentWidget.sessionContext.session.kernel",
                           timeout=120_000)
    collapsed = page.evaluate("window.jupyterapp.shell.leftCollapsed")
    if file_browser is True and collapsed:
        page.evaluate("window.jupyterapp.commands.execute('filebrowser:activate')")
    elif file_browser is False and not collapsed:
        page.evaluate("window.jupyterapp.commands.execute('application:toggle-left-area')")
    if file_browser is not None:
        page.wait_for_function(f"{'!' if file_browser else ''}window.jupyterapp.shell.leftCollapsed",
                               timeout=30_000)
    page.evaluate("window.jupyterapp.commands.execute('notebook:run-all-cells')")


def one_handle_picture() -> dict:
    """A 300 px picture of one point ``P`` with its handle, 75 px a unit (the page harness's tests)."""
    from planargeo.draw.picture import Picture

    pic = Picture((-2, 2, -2, 2), size=(300, 300), ticks=False, margin=(0, 0, 0, 0))
    pic.marks("P", [[0.0, 0.0]], role="twist", symbol="P", desc="a point")
    pic.handle("P", (0.0, 0.0), symbol="P", desc="drag P")
    return pic.to_dict()


def requests_sent(page) -> list:
    """The requests the harness page sent (syncs and descriptions left out)."""
    return page.evaluate("window.sent.filter((m) => m.type !== 'sync' && m.type !== 'describe')")


def ack(page, m) -> None:
    """Acknowledge request ``m`` in the harness page, as the kernel does."""
    page.evaluate("(m) => window.deliver(m)",
                  {"type": "ack", "seq": m["seq"], "client": m.get("client"), "ok": True, "message": ""})


def open_harness_view(page, pic: dict) -> tuple[float, float]:
    """Open a view of ``pic`` in the harness page, answer its first request (a sync), forget what was
    sent, and give the pixel centre of its first handle."""
    from planargeo.widgets.canvas import PictureCanvas

    c = PictureCanvas()
    c.picture = pic
    page.evaluate("(s) => window.openView(s)",
                  {k: v for k, v in c.get_state().items() if k in ("snapshot", "playing")})
    for m in page.evaluate("window.sent"):
        ack(page, m)
    page.evaluate("window.sent.length = 0")
    box = page.locator("circle.pg-handle").first.bounding_box()
    return box["x"] + box["width"] / 2, box["y"] + box["height"] / 2
