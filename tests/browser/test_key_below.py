"""A key no corner of the plot has room for is drawn below the axes, in the page (Voila, Chromium).

The student's review: the impulse explorer with its key on grew a strip below the plot for the
key, so that the plot's frame enclosed the key, the y tick labels ran down beside it, the x tick
labels sat under it and the lines stopped at its top edge.  Now the key's lines are under the
x tick labels, outside the frame; the frame, the ticks and the plot are as without the key.
Measured on what Chromium drew (boxes in CSS pixels), against the picture's own data.
"""
from __future__ import annotations

import time

import pytest

from .conftest import ARTIFACTS, VoilaServer, write_notebook

pytestmark = pytest.mark.browser

#: the smallest text size shown (canvas.js MIN_TEXT_PX)
MIN_TEXT_PX = 11.0

MEASURE_JS = """(ex) => {
  const svg = ex.querySelector(".pg-canvas svg");
  const box = (n) => { const r = n.getBoundingClientRect(); return [r.left, r.top, r.right, r.bottom]; };
  const scale = svg.getBoundingClientRect().width / svg.viewBox.baseVal.width;
  return {
    svg: box(svg), frame: box(svg.querySelector(".pg-frame")),
    ticks: [...svg.querySelectorAll(".pg-axes text")].map((t) => ({ text: t.textContent, box: box(t) })),
    key: [...svg.querySelectorAll("text.pg-below")].map((t) => ({
      text: t.firstChild.textContent, box: box(t), fill: t.getAttribute("fill"),
      shown_px: parseFloat(getComputedStyle(t).fontSize) * scale })),
  };
}"""


def _shown(server_url: str, browser, shot: str) -> dict:
    page = browser.new_page(viewport={"width": 1200, "height": 1000})
    try:
        page.goto(server_url + "/", wait_until="domcontentloaded", timeout=180_000)
        ex = page.locator(".planargeo-explorer").first
        ex.locator("svg text.pg-below").first.wait_for(state="attached", timeout=240_000)
        ex.locator(".pg-canvas svg").first.scroll_into_view_if_needed()
        time.sleep(1.0)                                    # the layout settles
        ARTIFACTS.mkdir(exist_ok=True)
        ex.screenshot(path=str(ARTIFACTS / shot))
        return ex.evaluate(MEASURE_JS)
    finally:
        page.close()


def test_the_impulse_explorers_key_is_below_the_axes_in_the_page(browser, tmp_path):
    from planargeo.widgets import ImpulseExplorer

    want = ImpulseExplorer(display="agg", key=True).picture()
    assert "below" in want                  # no corner of the plot has room for this key
    nb = write_notebook(tmp_path / "key.ipynb", ["from planargeo.widgets import ImpulseExplorer",
                                                 "ImpulseExplorer(key=True)"])
    server = VoilaServer(nb, tmp_path / "voila")
    try:
        got = _shown(server.url, browser, "key-below-impulse.png")
    finally:
        server.stop()
    left, top, right, bottom = got["frame"]
    # the frame: the plot area as without the key (its size in the picture's pixels, as shown)
    s = (got["svg"][2] - got["svg"][0]) / want["size"][0]
    ml, mr, mt, mb = want["margin"]
    assert right - left == pytest.approx(s * (want["size"][0] - ml - mr), abs=1.5)
    assert bottom - top == pytest.approx(s * (want["size"][1] - mt - mb), abs=1.5)
    # the x tick labels just under the frame, the y tick labels beside it, none beside the key
    xt = [t for t in got["ticks"] if t["box"][1] >= bottom - 0.5]
    yt = [t for t in got["ticks"] if t["box"][1] < bottom - 0.5]
    assert len(xt) == len(want["ticks"]["x"]) and len(yt) == len(want["ticks"]["y"])
    assert all(t["box"][2] <= left + 0.5 and top - 8 <= t["box"][1] and t["box"][3] <= bottom + 8 for t in yt)
    under_ticks = max(t["box"][3] for t in xt)
    # the key: every line of it, in its colour, under the x tick labels, outside the frame,
    # inside the figure, one under the other, its text at least MIN_TEXT_PX as shown
    assert [k["text"] for k in got["key"]] == [b["text"] for b in want["below"]]
    assert [k["fill"] for k in got["key"]] == [b["color"] for b in want["below"]]
    for k in got["key"]:
        x0, y0, x1, y1 = k["box"]
        assert y0 >= under_ticks - 0.5 and y0 > bottom, (k, under_ticks, bottom)
        assert x0 >= got["svg"][0] - 0.5 and x1 <= got["svg"][2] + 0.5 and y1 <= got["svg"][3] + 0.5, k
        assert k["shown_px"] >= MIN_TEXT_PX - 0.01, k
    tops = [k["box"][1] for k in got["key"]]
    assert all(b - a >= 0.9 * s * 14.0 for a, b in zip(tops, tops[1:])), tops
