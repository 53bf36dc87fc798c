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
