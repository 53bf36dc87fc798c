"""The construction explorer as a student opens it (Voila, Chromium): the menu's label whole.

The student's review: at load the menu's label read "constructi…", cut by the page's default
label width.  Measured on what Chromium drew: the label's text needs no more room than it has.
"""
from __future__ import annotations

import time

import pytest

from .conftest import ARTIFACTS, VoilaServer, write_notebook

pytestmark = pytest.mark.browser

LABELS_JS = """(ex) => [...ex.querySelectorAll(".widget-dropdown > label, .widget-slider > label")]
  .filter((l) => l.offsetParent !== null)
  .map((l) => ({text: l.textContent, need: l.scrollWidth, has: l.clientWidth}))"""


def test_the_construction_menus_label_is_shown_whole(browser, tmp_path):
    nb = write_notebook(tmp_path / "construction.ipynb",
                        ["from planargeo.widgets import ConstructionExplorer", "ConstructionExplorer()"])
    server = VoilaServer(nb, tmp_path / "voila")
    page = browser.new_page(viewport={"width": 1200, "height": 1000})
    try:
        page.goto(server.url + "/", wait_until="domcontentloaded", timeout=180_000)
        ex = page.locator(".planargeo-explorer").first
        ex.locator(".widget-dropdown").first.wait_for(state="visible", timeout=240_000)
        time.sleep(1.0)                                    # the layout settles
        ARTIFACTS.mkdir(exist_ok=True)
        ex.screenshot(path=str(ARTIFACTS / "construction-at-load.png"))
        labels = ex.evaluate(LABELS_JS)
    finally:
        page.close()
        server.stop()
    menu = [l for l in labels if l["text"] == "construction"]
    assert len(menu) == 1, labels
    assert menu[0]["need"] <= menu[0]["has"], menu          # not "constructi…"
