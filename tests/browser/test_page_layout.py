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
