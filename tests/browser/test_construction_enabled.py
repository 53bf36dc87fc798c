"""The construction explorer in the page (Voila, Chromium): a slider disabled in one construction is
enabled in the page when the next construction uses it.

The student's review: at load (twist addition, u₁ = 0) "direction of F₁" is greyed out, rightly; after
"Wrench addition (4.4)" is chosen it stayed greyed in the page and ignored the arrow keys, while the
kernel held it enabled.  Checked on what Chromium drew: the slider's ``disabled`` attribute, and an
ArrowRight that moves its value.
"""
from __future__ import annotations

import time

import pytest

from .conftest import ARTIFACTS, VoilaServer, write_notebook

pytestmark = pytest.mark.browser

SLIDER_JS = """(ex, label) => {
  const s = [...ex.querySelectorAll(".widget-slider")].find((e) => e.textContent.includes(label));
  if (!s) return null;
  return {disabled: s.querySelector(".slider").hasAttribute("disabled"),
          value: s.querySelector(".widget-readout").textContent.trim(),
          shown: s.offsetParent !== null};
}"""


def _slider(ex, label):
    return ex.evaluate(SLIDER_JS, label)


def _wait_for(ex, label, want, timeout=60.0):
    end = time.monotonic() + timeout
    s = _slider(ex, label)
    while time.monotonic() < end:
        s = _slider(ex, label)
        if s is not None and all(s[k] == v for k, v in want.items()):
            return s
        time.sleep(0.25)
    return s


def test_a_slider_disabled_in_twist_addition_is_enabled_in_wrench_addition(browser, tmp_path):
    nb = write_notebook(tmp_path / "construction.ipynb",
                        ["from planargeo.widgets import ConstructionExplorer", "ConstructionExplorer()"])
    server = VoilaServer(nb, tmp_path / "voila")
    page = browser.new_page(viewport={"width": 1200, "height": 1000})
    label = "direction of F₁"
    try:
        page.goto(server.url + "/", wait_until="domcontentloaded", timeout=180_000)
        ex = page.locator(".planargeo-explorer").first
        menu = ex.locator(".widget-dropdown select").first
        menu.wait_for(state="visible", timeout=240_000)
        time.sleep(1.0)
        # at load: twist addition, u₁ = 0: its direction slider (hidden) is disabled
        menu.select_option(label="Wrench addition (4.4)")
        after = _wait_for(ex, label, {"shown": True, "disabled": False})
        slider = ex.locator(".widget-slider").filter(has_text=label).first
        ARTIFACTS.mkdir(exist_ok=True)
        ex.screenshot(path=str(ARTIFACTS / "construction-wrench-after-twist.png"))
        assert after is not None and after["shown"], after
        assert not after["disabled"], after             # greyed in the page: the review's fault
        before = after["value"]
        slider.locator(".noUi-handle").first.focus()
        page.keyboard.press("ArrowRight")
        moved = _wait_for(ex, label, {"value": None}, timeout=3.0)   # (never equal: waits 3 s)
        assert moved["value"] != before, (before, moved)
        # away and back: still enabled
        menu.select_option(index=2)
        time.sleep(2.0)
        menu.select_option(label="Wrench addition (4.4)")
        back = _wait_for(ex, label, {"shown": True, "disabled": False})
        assert not back["disabled"], back
    finally:
        page.close()
        server.stop()
