"""The page's layout checks (``test_page_explorers.check_layout``) see what they are meant to see.

The layout rules of issue 21 are checked on every explorer in JupyterLab and in Voila
by ``test_page_explorers.py`` / ``test_browser_explorers.py``; here the check itself is
run on small hand-made pages in headless chromium (no server): one that breaks each
rule (a box over the plot area, a readout value cut by its container and one clipped
in its own cell, two labels on each other) and the same page mended, where it must
find nothing.
"""
from __future__ import annotations

import pytest

from .conftest import open_in_lab, write_notebook
from .test_page_explorers import check_layout

pytestmark = pytest.mark.browser

PAGE = """<!doctype html><html><body style="margin:0; font: 12px 'DejaVu Sans', sans-serif">
<div class="planargeo-explorer" style="position:relative; width:640px; padding:8px">
  <div class="pg-canvas">
    <svg width="300" height="200" viewBox="0 0 300 200">
      <g transform="translate(20,10)">
        <rect class="pg-bg" x="0" y="0" width="260" height="170" fill="white"/>
        <g class="pg-el" data-id="a"><text x="40" y="50" font-size="12">label one</text></g>
        <g class="pg-el" data-id="b"><text x="{bx}" y="54" font-size="12">label two</text></g>
        <rect class="pg-frame" x="0" y="0" width="260" height="170" fill="none" stroke="#444"
              style="pointer-events:none"/>
      </g>
    </svg>
  </div>
  <div class="cover" style="position:absolute; left:{cover}px; top:30px; width:60px; height:50px;
       background:#eee">toolbar</div>
  <div class="planargeo-readout" style="width:{ro}px; overflow:hidden">
    <table style="border-collapse:collapse">
      <tr><td>ω₁</td><td style="white-space:nowrap; font-family:monospace">1.23456789 rad/s</td></tr>
      <tr><td>β</td><td style="white-space:nowrap; display:inline-block; width:{cell}px; overflow:hidden">0.666666666667</td></tr>
    </table>
  </div>
</div></body></html>"""


@pytest.fixture(scope="module")
def page(browser):
    p = browser.new_page(viewport={"width": 900, "height": 600})
    yield p
    p.close()


def test_a_broken_layout_is_seen(page):
    page.set_content(PAGE.format(bx=60, cover=40, ro=120, cell=30))
    problems = check_layout(page, page.locator(".planargeo-explorer"))
    text = "\n".join(problems)
    assert "div.cover covers" in text, text
    assert "readout ω₁: cell '1.23456789 rad/s'" in text and "cut by a div" in text, text
    assert "readout β: cell '0.666666666667' clipped" in text, text
    assert "labels 'label one' (a) and 'label two' (b) overlap" in text, text


def test_a_sound_layout_passes(page):
    page.set_content(PAGE.format(bx=160, cover=400, ro=400, cell=300))
    assert check_layout(page, page.locator(".planargeo-explorer")) == []


LAB_CELLS = ["from planargeo.widgets import ChainExplorer",
             "ChainExplorer()",                              # 620 px: fits beside the controls
             "ChainExplorer(figsize=(9.6, 5.4))"]            # 960 px: wider than the column

BOXES = """e => Object.fromEntries(Object.entries({figure: '.planargeo-figure', explorer: ':scope',
  controls: '.widget-hbox > .widget-vbox:first-child'}).map(([k, s]) => {
    const r = (s === ':scope' ? e : e.querySelector(s)).getBoundingClientRect();
    return [k, {left: r.left, right: r.right, top: r.top, bottom: r.bottom}]; }))"""


def test_the_figure_stays_in_sight_in_jupyterlab_with_its_file_browser(lab, browser):
    """In JupyterLab at 1400 × 1100 with the file browser open (a notebook ~970 px wide) the
    chain's figure is beside its controls; a figure too wide for that comes above them, not
    below a controls column a screen long (review H4: 1287–1787 px down)."""
    import time

    write_notebook(lab.root / "layout.ipynb", LAB_CELLS)
    page = browser.new_page(viewport={"width": 1400, "height": 1100})
    try:
        open_in_lab(page, lab, "layout.ipynb", file_browser=True)
        explorers = page.locator(".planargeo-explorer")
        boxes = []
        for k in range(2):
            ex = explorers.nth(k)
            ex.locator("svg .pg-frame").first.wait_for(state="attached", timeout=240_000)
            ex.scroll_into_view_if_needed()
            time.sleep(0.5)                                   # the layout settles
            boxes.append(ex.evaluate(BOXES))
        width = boxes[0]["explorer"]["right"] - boxes[0]["explorer"]["left"]
        assert 900 < width < 1000, width                      # the notebook's column, file browser open
        fig, ctl = boxes[0]["figure"], boxes[0]["controls"]
        assert fig["left"] >= ctl["right"] - 1 and abs(fig["top"] - ctl["top"]) < 60, boxes[0]
        fig, ctl, whole = boxes[1]["figure"], boxes[1]["controls"], boxes[1]["explorer"]
        assert fig["bottom"] <= ctl["top"] + 1, boxes[1]       # wrapped: the figure first
        assert fig["top"] - whole["top"] < 100, boxes[1]      # at the explorer's top, in sight
    finally:
        page.close()
