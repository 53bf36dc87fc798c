"""Every explorer in the web app of ``make app`` (Voila), drawn by the page, in a real browser.

The app notebook (``app/planargeo-app.ipynb``, one section per explorer) is copied with
every explorer shown in the page (``display="page"``; the app's own default) and served
by Voila with the app's configuration (seats, the offline page template).  Headless
chromium then runs, on every explorer, the checks of ``test_page_explorers.py``
(layout, drag, slider, zoom / pan / reset, hover, Play, export; one request in flight,
read off the websocket; no request leaves 127.0.0.1).  JupyterLab runs the same checks
in ``test_page_explorers.py``.

With ``PLANARGEO_UPDATE_SCREENS=1`` (``make screens``) the run also writes every
explorer's default state, as the page shows it, to ``docs/screens/<slug>.png``.
"""
from __future__ import annotations

import os
import re
from pathlib import Path

import nbformat
import pytest

from .conftest import VoilaServer
from .test_page_explorers import WIRE_HOOK, finish, page_app, run_all, watch_network

pytestmark = pytest.mark.browser

REPO = Path(__file__).resolve().parents[2]
APP = REPO / "app" / "planargeo-app.ipynb"
SCREENS = REPO / "docs" / "screens"
CELL = re.compile(r"^pw\.(\w+)\(.*\)$")


def test_app_shows_every_registered_explorer():
    """The app has one section per registered explorer, and nothing else."""
    from planargeo.widgets import EXPLORERS

    nb = nbformat.read(APP, as_version=4)
    shown = [CELL.match(c.source.strip()).group(1) for c in nb.cells
             if c.cell_type == "code" and CELL.match(c.source.strip())]
    assert sorted(shown) == sorted(EXPLORERS)
    assert len(set(shown)) == len(shown)


def test_every_explorer_in_the_app(browser, tmp_path):
    """``make app``: Voila serves the app notebook; every explorer works there, in the page."""
    root = tmp_path / "app"
    root.mkdir()
    names = page_app(root / "app.ipynb")
    server = VoilaServer(root / "app.ipynb", tmp_path)
    page = browser.new_page(viewport={"width": 1400, "height": 1000}, accept_downloads=True)
    page.add_init_script(WIRE_HOOK)
    urls = watch_network(page)
    try:
        page.goto(server.url + "/", wait_until="domcontentloaded", timeout=180_000)
        failures = run_all(page, names, tmp_path,
                           screens=SCREENS if os.environ.get("PLANARGEO_UPDATE_SCREENS") else None)
        finish(page, failures, urls, "page-voila")
    finally:
        page.close()
        server.stop()
