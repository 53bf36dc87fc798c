"""Drive the tour notebook in a real JupyterLab with headless Debian chromium.

Run all cells, move the projective playground's first slider (``P x``) with
the keyboard, wait for the *final* readout value (the browser coalesces slider
updates while the kernel is busy), and check that both the readout text and the
figure's pixels changed.  The ``P x`` row only echoes the slider, so a computed
row must follow too: the distance of the polar of ``P`` from the origin, checked
against the hand formula ``1 / |M P|`` for the ellipse ``xᵀ M x = 1`` whose
semi-axes and tilt the explorer's own sliders show.  Screenshots go to ``tests/browser/artifacts/`` (git-ignored); with
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


def _slider_values(explorer) -> dict[str, float]:
    """Label -> number shown by every slider of an explorer."""
    sliders = explorer.locator(".widget-slider")
    out = {}
    for i in range(sliders.count()):
        sl = sliders.nth(i)
        label = sl.locator(".widget-label").first.inner_text().strip()
        out[label.split(" (")[0]] = _number(sl.locator(".widget-readout").first.inner_text())  # no unit
    return out


def _polar_distance(v: dict[str, float], conic: str) -> float:
    """Distance from the centre to the polar of P w.r.t. the ellipse xᵀ M x = 1 (by hand).

    ``M = R(tilt) diag(1/a², 1/b²) R(tilt)ᵀ`` (a circle: ``b = a``); the polar of
    ``P`` is ``{x : xᵀ M P = 1}``, at distance ``1 / |M P|`` from the centre.
    """
    a = v["semi-axis a"]
    b = a if conic == "circle" else v["semi-axis b"]
    t = np.radians(v["tilt"])
    R = np.array([[np.cos(t), -np.sin(t)], [np.sin(t), np.cos(t)]])
    M = R @ np.diag([1 / a ** 2, 1 / b ** 2]) @ R.T
    return float(1.0 / np.linalg.norm(M @ np.array([v["P x"], v["P y"]])))


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
        explorer = page.locator(".planargeo-explorer").filter(has_text="Projective playground").first
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
        _wait_for(lambda: figure.bounding_box() and figure.bounding_box()["height"] > 50
                  and figure.locator("svg path").count() > 5, 30,
                  "the figure to render")       # its picture drawn, not only its box laid out
        slider = explorer.locator(".widget-slider").first
        label = slider.locator(".widget-label").first.inner_text().strip().split(" (")[0]  # "P x (m)": row "P x"
        value_box = slider.locator(".widget-readout").first
        v0 = _number(value_box.inner_text())
        before = _wait_for(lambda: _readout(page, explorer), 30, "the readout")
        assert label in before, f"readout {before} has no row for slider {label!r}"
        assert label == "P x", f"the first slider is {label!r}"
        assert abs(_number(before[label]) - v0) <= 1e-3 * max(1.0, abs(v0))
        conic = explorer.locator(".widget-dropdown select").first.input_value()
        assert conic in ("ellipse", "circle"), conic
        DIST = "polar of P: distance to origin"
        d0 = _polar_distance(_slider_values(explorer), conic)
        assert _number(before[DIST]) == pytest.approx(d0, rel=2e-3)
        png_before = figure.screenshot()
        page.screenshot(path=str(ARTIFACTS / "before.png"))

        handle = slider.locator(".noUi-handle").first
        handle.focus()
        for _ in range(PRESSES):
            page.keyboard.press("ArrowRight")
            time.sleep(0.05)
        _wait_for(lambda: _number(value_box.inner_text()) != v0, 10, "the slider to move")

        def settled():
            a = _number(value_box.inner_text())
            time.sleep(0.5)
            return a if _number(value_box.inner_text()) == a else None

        v1 = _wait_for(settled, 10, "the slider to settle")
        assert v1 > v0
        # the readout shows the FINAL slider value (intermediate updates may be coalesced)
        after = _wait_for(
            lambda: (lambda r: r if abs(_number(r[label]) - v1) <= 1e-3 * max(1.0, abs(v1)) else None)(
                _readout(page, explorer)), 60, f"readout {label!r} to reach {v1}")
        assert after != before
        # a computed row follows: the polar's distance for the final P, by hand
        v_after = _slider_values(explorer)
        assert v_after["P x"] == pytest.approx(v1)
        d1 = _polar_distance(v_after, conic)
        assert abs(d1 - d0) > 0.01 * d0, "the step did not move the polar enough to tell"
        after = _wait_for(
            lambda: (lambda r: r if abs(_number(r[DIST]) - d1) <= 2e-3 * d1 else None)(
                _readout(page, explorer)), 30, f"readout {DIST!r} to reach {d1:.4g}")
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
