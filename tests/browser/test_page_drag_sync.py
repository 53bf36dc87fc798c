"""A drag in JupyterLab: the controls and the readout wait for its release, then agree with the picture.

The chain explorer (``display="page"``, ``drag_sync_s`` set beyond the test's length, so that no
periodic sync comes) is dragged in headless chromium by a real mouse.  Read off the websocket:
while the handle is held, the kernel sends pictures (the canvas's replies) and no control or
readout sync (``comm_msg`` with ``method: update``); after the mouse is let go they come.  Then
what the page shows agrees: its readout and its "joint values" field are those of a fresh
explorer made (in this process) from the joint values the page shows, and the dragged handle is
drawn where that explorer's picture puts it.
"""
from __future__ import annotations

import html
import json
import re
import time

import pytest

from .conftest import open_in_lab, write_notebook

pytestmark = pytest.mark.browser

CELLS = ["import planargeo.widgets as pw",
         "ex = pw.ChainExplorer(links=3)\nex.drag_sync_s = 3600.0\nex"]


def _cells_of(table_html: str) -> dict[str, str]:
    """A readout's rows ``{name: value}`` from its HTML, as the page shows them (tags off, spaces one)."""
    out = {}
    for row in re.findall(r"<tr.*?</tr>", table_html, re.S):
        cells = [" ".join(html.unescape(re.sub(r"<[^>]+>", "", c)).split())
                 for c in re.findall(r"<td.*?</td>", row, re.S)]
        if len(cells) >= 2:
            out[cells[0]] = cells[1]
    return out


def _page_readout(ex) -> dict[str, str]:
    rows = ex.locator(".planargeo-readout tr")
    out = {}
    for i in range(rows.count()):
        cells = rows.nth(i).locator("td")
        if cells.count() >= 2:
            out[" ".join(cells.nth(0).inner_text().split())] = " ".join(cells.nth(1).inner_text().split())
    return out


def _kind(payload) -> str:
    b = payload.encode() if isinstance(payload, str) else bytes(payload)
    if b'"comm_msg"' not in b:
        return "other"
    if re.search(rb'"method"\s*:\s*"update"', b):
        return "sync"
    return "picture" if re.search(rb'"type"\s*:\s*"(ack|update)"', b) else "other"


def test_a_drag_sends_controls_and_readout_at_its_release_and_they_agree_with_the_picture(lab, browser):
    from planargeo.widgets import ChainExplorer

    write_notebook(lab.root / "drag-sync.ipynb", CELLS)
    page = browser.new_page(viewport={"width": 1400, "height": 1100})
    frames = []
    page.on("websocket", lambda ws: ws.on(
        "framereceived", lambda p: frames.append((time.perf_counter(), _kind(p), p))))
    try:
        open_in_lab(page, lab, "drag-sync.ipynb")
        ex = page.locator(".planargeo-explorer").first
        ex.locator("svg .pg-frame").first.wait_for(state="attached", timeout=240_000)
        cv = ex.locator(".pg-canvas").first
        cv.scroll_into_view_if_needed()
        time.sleep(1.0)
        handle = cv.locator("circle[data-handle='link 3 end']")
        h = handle.bounding_box()
        x, y = h["x"] + h["width"] / 2, h["y"] + h["height"] / 2
        before = _page_readout(ex)
        page.mouse.move(x, y)
        page.mouse.down()
        t_down = time.perf_counter()
        n_stats = cv.evaluate("(c) => c.__planargeo.stats.length")
        for k in range(1, 13):                          # a hand's drag, a move every ~30 ms
            page.mouse.move(x + 2.5 * k, y + 1.5 * k)
            page.wait_for_timeout(30)
        for _ in range(300):                            # every step answered, the mouse still down
            if not cv.evaluate("(c) => c.__planargeo.busy()"):
                break
            time.sleep(0.02)
        time.sleep(0.3)
        t_up = time.perf_counter()
        answered = cv.evaluate(f"(c) => c.__planargeo.stats.slice({n_stats}).filter(s => s.type === 'drag'"
                               " && s.tAck).length")
        held = [k for t, k, _p in frames if t_down < t < t_up]
        assert answered >= 2 and held.count("picture") >= answered, (answered, held)
        assert "sync" not in held, held                 # nothing but pictures while held
        assert _page_readout(ex) == before              # the page's readout as before the drag
        page.mouse.up()
        deadline = time.time() + 20
        while time.time() < deadline and not any(k == "sync" for t, k, _p in frames if t > t_up):
            page.wait_for_timeout(50)
        assert any(k == "sync" for t, k, _p in frames if t > t_up), "no sync after the release"
        page.wait_for_timeout(1000)                     # the release's syncs applied
        text = ex.locator(".widget-text").filter(has_text="joint values").locator("input").first.input_value()
        fresh = ChainExplorer(display="page", links=3, **{"joint values (deg / m)": text})
        assert fresh.message == ""
        shown = _page_readout(ex)
        assert shown != before
        assert shown == _cells_of(fresh.readout.value), (shown, _cells_of(fresh.readout.value))
        # the picture: the dragged handle where the fresh explorer's picture has it
        pic = fresh.canvas.picture
        (hx, hy), = [(q["x"], q["y"]) for q in pic["handles"] if q["id"] == "link 3 end"]
        drawn = handle.evaluate("(c) => [parseFloat(c.getAttribute('cx')), parseFloat(c.getAttribute('cy'))]")
        head = json.loads(json.dumps(fresh.canvas._snapshot()["head"]))
        (w, hgt), m, box = head["size"], head["margin"], head["box"]
        pw_, ph_ = w - m[0] - m[1], hgt - m[2] - m[3]
        want = ((hx - box[0]) * pw_ / (box[1] - box[0]), ph_ - (hy - box[2]) * ph_ / (box[3] - box[2]))
        assert drawn == pytest.approx(want, abs=0.05), (drawn, want)
    finally:
        page.close()
