"""Drive the tour notebook in a real JupyterLab with headless Debian chromium.

Run all cells, move the first explorer's first slider with the keyboard, wait
for the *final* readout value (the browser coalesces slider updates while the
kernel is busy), and check that both the readout text and the figure's pixels
changed.  Screenshots go to ``tests/browser/artifacts/`` (git-ignored); with
``PLANARGEO_UPDATE_SCREENSHOT=1`` the final one also replaces the committed
``benchmarks/results/browser.png``.
"""
from __future__ import annotations

import io
import os
import re
import shutil
import time
from pathlib import Path

import numpy as np
import pytest

from .conftest import ARTIFACTS, copy_notebook

pytestmark = pytest.mark.browser

REPO = Path(__file__).resolve().parents[2]
NOTEBOOK = REPO / "notebooks" / "00-tour.ipynb"
PRESSES = 5


def _readout(page, explorer) -> dict[str, str]:
    rows = explorer.locator(".planargeo-readout tr")
    out = {}
    for i in range(rows.count()):
        cells = rows.nth(i).locator("td")
        out[cells.nth(0).inner_text().strip()] = cells.nth(1).inner_text().strip()
    return out


def _number(text: str) -> float:
    text = text.replace("−", "-").strip()
    m = re.search(r"[-+]?\d*\.?\d+(?:e[-+]?\d+)?", text)
    if not m:
        raise ValueError(f"no number in {text!r}")
    return float(m.group())


def _pixels(png: bytes) -> np.ndarray:
    from PIL import Image

    return np.asarray(Image.open(io.BytesIO(png)).convert("RGB"), dtype=np.int16)


def _wait_for(predicate, timeout: float, what: str, interval: float = 0.25):
    t0 = time.time()
    last = None
    while time.time() - t0 < timeout:
        try:
            last = predicate()
            if last:
                return last
        except Exception as exc:  # element not there yet
            last = exc
        time.sleep(interval)
    raise AssertionError(f"timed out after {timeout} s waiting for {what} (last: {last!r})")


def test_tour_slider_updates_readout_and_figure(lab, browser):
    ARTIFACTS.mkdir(exist_ok=True)
    copy_notebook(NOTEBOOK, lab.root, "tour-under-test.ipynb")
    page = browser.new_page(viewport={"width": 1500, "height": 1000})
    console = []
    page.on("console", lambda m: console.append(f"{m.type}: {m.text}"))
    try:
        page.goto(f"{lab.url}/lab/tree/tour-under-test.ipynb?reset", wait_until="domcontentloaded",
                  timeout=60_000)
        page.wait_for_selector(".jp-Notebook", timeout=60_000)
        # Wait until the app and the notebook's kernel are ready, then run every cell.
        page.wait_for_function("window.jupyterapp && window.jupyterapp.shell.currentWidget"
                               " && window.jupyterapp.shell.currentWidget.sessionContext"
                               " && window.jupyterapp.shell.currentWidget.sessionContext.session"
                               " && window.jupyterapp.shell.currentWidget.sessionContext.session.kernel",
                               timeout=60_000)
        page.evaluate("window.jupyterapp.commands.execute('notebook:run-all-cells')")
        explorer = page.locator(".planargeo-explorer").first
        explorer.wait_for(state="visible", timeout=120_000)
        # every cell has run once the kernel is idle and no cell shows [*]
        page.wait_for_function(
            "() => { const c = window.jupyterapp.shell.currentWidget.sessionContext;"
            " return c.session.kernel.status === 'idle' &&"
            " ![...document.querySelectorAll('.jp-InputArea-prompt')].some(e => e.textContent.includes('*')); }",
            timeout=180_000, polling=500)
        errors = page.locator(".jp-OutputArea-output[data-mime-type='application/vnd.jupyter.stderr'],"
                              " .jp-RenderedText[data-mime-type='application/vnd.jupyter.error']")
        assert errors.count() == 0, "a cell raised: " + errors.first.inner_text()[:2000]

        figure = explorer.locator(".planargeo-figure").first
        figure.scroll_into_view_if_needed()
        _wait_for(lambda: figure.bounding_box() and figure.bounding_box()["height"] > 50, 30,
                  "the figure to render")
        slider = explorer.locator(".widget-slider").first
        label = slider.locator(".widget-label").first.inner_text().strip()
        value_box = slider.locator(".widget-readout").first
        v0 = _number(value_box.inner_text())
        before = _wait_for(lambda: _readout(page, explorer), 30, "the readout")
        assert label in before, f"readout {before} has no row for slider {label!r}"
        assert abs(_number(before[label]) - v0) <= 1e-3 * max(1.0, abs(v0))
        png_before = figure.screenshot()
        page.screenshot(path=str(ARTIFACTS / "before.png"))

        handle = slider.locator(".noUi-handle").first
        handle.focus()
        for _ in range(PRESSES):
            page.keyboard.press("ArrowRight")
            time.sleep(0.05)
        v1 = _wait_for(lambda: (lambda v: v if v != v0 else None)(_number(value_box.inner_text())),
                       10, "the slider to move")
        assert v1 > v0
        # the readout shows the FINAL slider value (intermediate updates may be coalesced)
        after = _wait_for(
            lambda: (lambda r: r if abs(_number(r[label]) - v1) <= 1e-3 * max(1.0, abs(v1)) else None)(
                _readout(page, explorer)), 60, f"readout {label!r} to reach {v1}")
        assert after != before
        time.sleep(1.0)  # let the image widget repaint
        png_after = figure.screenshot()
        a, b = _pixels(png_before), _pixels(png_after)
        assert a.shape == b.shape, (a.shape, b.shape)
        changed = np.mean(np.any(a != b, axis=-1))
        assert changed > 0.001, f"only {changed:.4%} of the figure's pixels changed"
        page.screenshot(path=str(ARTIFACTS / "after.png"))
        # the committed screenshot is refreshed only on request (keeps the work tree clean)
        if os.environ.get("PLANARGEO_UPDATE_SCREENSHOT"):
            shutil.copy(ARTIFACTS / "after.png", REPO / "benchmarks" / "results" / "browser.png")
    except Exception:
        try:
            page.screenshot(path=str(ARTIFACTS / "failure.png"))
        except Exception:
            pass
        (ARTIFACTS / "console.log").write_text("\n".join(console))
        raise
    finally:
        page.close()
