"""In a narrow JupyterLab (a window 1000 × 900 with the file browser open: the output ~570 px wide)
an explorer's figure and its sliders are on screen together: figure, then controls, then readout
(review: the controls came below the readout, a screen and more under the figure).  Side by side
the controls stay left of the figure in a wide notebook.
"""
from __future__ import annotations

import time

import pytest

from .conftest import open_in_lab, write_notebook

pytestmark = pytest.mark.browser

CELLS = ["from planargeo.widgets import ChainExplorer",
         "ChainExplorer()"]

BOXES = """e => Object.fromEntries(Object.entries({explorer: ':scope', figure: '.planargeo-figure',
  controls: '.planargeo-body > .widget-vbox:first-child', readout: '.planargeo-readout',
  slider: '.planargeo-body .widget-slider'}).map(([k, s]) => {
    const r = (s === ':scope' ? e : e.querySelector(s)).getBoundingClientRect();
    return [k, {left: r.left, right: r.right, top: r.top, bottom: r.bottom}]; }))"""


def _boxes(lab, browser, width: int, height: int, browser_open: bool) -> dict:
    name = f"order{width}.ipynb"
    write_notebook(lab.root / name, CELLS)
    page = browser.new_page(viewport={"width": width, "height": height})
    try:
        open_in_lab(page, lab, name, file_browser=browser_open)
        ex = page.locator(".planargeo-explorer").first
        ex.locator("svg .pg-frame").first.wait_for(state="attached", timeout=240_000)
        ex.scroll_into_view_if_needed()
        time.sleep(1.0)                                   # the layout settles
        from pathlib import Path
        out = Path(__file__).parent / "artifacts"
        out.mkdir(exist_ok=True)
        ex.screenshot(path=str(out / f"narrow_order_{width}.png"))
        return ex.evaluate(BOXES)
    finally:
        page.close()


def test_narrow_lab_shows_figure_then_controls_then_readout(lab, browser):
    b = _boxes(lab, browser, 1000, 900, browser_open=True)
    width = b["explorer"]["right"] - b["explorer"]["left"]
    assert width < 330 + 620, b                        # too narrow for controls beside the figure
    fig, ctl, ro = b["figure"], b["controls"], b["readout"]
    assert fig["bottom"] <= ctl["top"] + 1, b          # the figure first, the controls under it
    assert ctl["bottom"] <= ro["top"] + 1, b           # the readout last
    assert fig["right"] <= b["explorer"]["right"] + 1, b     # the figure within the column
    # the figure's lower half and the first slider fit in one 900 px window together
    assert b["slider"]["bottom"] - (fig["top"] + fig["bottom"]) / 2 < 900 - 150, b


def test_wide_lab_keeps_the_controls_beside_the_figure(lab, browser):
    b = _boxes(lab, browser, 1400, 1100, browser_open=False)
    fig, ctl, ro = b["figure"], b["controls"], b["readout"]
    assert fig["left"] >= ctl["right"] - 1 and abs(fig["top"] - ctl["top"]) < 60, b
    assert ro["top"] >= fig["bottom"] - 1 and ro["left"] >= ctl["right"] - 1, b   # under the figure
