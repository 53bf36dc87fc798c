"""The page renderer in a real browser, in the web app (Voila) and in JupyterLab.

A small notebook shows a :class:`~planargeo.widgets.canvas.PictureCanvas` whose
kernel side answers a drag by drawing the point ``P`` where it was dropped and the
horizontal line through it, slowly on purpose (0.15 s per request), and refuses
``x > 3``.  In headless chromium the test checks what the issue asks of the page:

* the dragged handle moves in the same event as the mouse (before any reply);
* at most one request is in flight: ten quick moves reach the kernel as two or three
  requests, and the last position wins;
* a refused position snaps the handle back to the last accepted one, with the reason, which
  stays until the next picture;
* the wheel zooms at once and the kernel redraws the new view (a sideways wheel does not zoom);
  *reset view* returns;
* hovering an element shows its symbol and description (asked of the kernel);
* Play: while ``playing`` is on the page asks for frames by itself (``tick``), one at a
  time, and stops when it is off;
* a view opened later (a second display of the same widget, after many updates) shows
  the whole current picture;
* no request of the page leaves 127.0.0.1 (every URL is recorded).
"""
from __future__ import annotations

import json
import re
import time
from pathlib import Path

import nbformat
import pytest

from .conftest import ARTIFACTS, LabServer, VoilaServer
from .test_browser import _wait_for

pytestmark = pytest.mark.browser

CODE = """\
import time
import ipywidgets as W
from IPython.display import display
from planargeo.draw.picture import Picture
from planargeo.errors import PlanargeoError
from planargeo.widgets.canvas import PictureCanvas

state = {"n": 0, "view": (-4.0, 4.0, -4.0, 4.0), "xy": (0.0, 0.0), "ticks": 0}

def make():
    x, y = state["xy"]
    pic = Picture(state["view"], size=(480, 460), title=f"requests {state['n']} ticks {state['ticks']}")
    pic.point("P", [y, -x, 1.0], symbol="P", desc="the dragged point", glyph=False)
    pic.line("l", [1.0, 0.0, -y], symbol="l", desc="the horizontal line through P", arrow=False)
    pic.handle("P", (x, y), symbol="P", desc="drag me")
    return pic.to_dict()

def on_drag(h, x, y):
    state["n"] += 1
    time.sleep(0.15)
    if x > 3.0:
        raise PlanargeoError(f"x must stay at most 3, got {x:.3g}")
    state["xy"] = (x, y)
    c.picture = make()

def on_view(box):
    state["view"] = tuple(box) if box is not None else (-4.0, 4.0, -4.0, 4.0)
    c.picture = make()

def on_tick():
    state["ticks"] += 1
    time.sleep(0.01)
    c.picture = make()

c = PictureCanvas(on_drag=on_drag, on_view=on_view, on_tick=on_tick)
c.picture = make()
play = W.ToggleButton(description="play")
W.link((play, "value"), (c, "playing"))
again = W.Button(description="show again")
out = W.Output()
def show_again(_):
    with out:
        display(c)
again.on_click(show_again)
redraw = W.Button(description="redraw")
def do_redraw(_):
    state["xy"] = (0.5, 0.5)
    c.picture = make()
redraw.on_click(do_redraw)
display(c, W.HBox([play, again, redraw]), out)
"""


def _notebook(path: Path) -> None:
    nb = nbformat.v4.new_notebook()
    nb.cells = [nbformat.v4.new_code_cell(CODE)]
    nb.metadata["kernelspec"] = {"name": "python3", "display_name": "Python 3", "language": "python"}
    nbformat.write(nb, path)


def _local(url: str) -> bool:
    return bool(re.match(r"^(https?|wss?)://127\.0\.0\.1(:\d+)?/", url)) or url.startswith(
        ("data:", "blob:", "about:"))


def _exercise(page, where: str) -> None:
    svg = page.locator(".pg-canvas svg").first
    svg.wait_for(state="visible", timeout=120_000)
    svg.scroll_into_view_if_needed()
    time.sleep(0.5)
    handle = page.locator("circle.pg-handle").first
    title = page.locator(".pg-title").first
    _wait_for(lambda: title.text_content().startswith("requests"), 30, "the first picture")

    def n_requests() -> int:
        return int(title.text_content().split()[1])

    def n_ticks() -> int:
        return int(title.text_content().split()[3])

    def marker_cx() -> float:
        return float(page.locator("g[data-id='P'] circle").first.get_attribute("cx"))

    box = handle.bounding_box()
    x0, y0 = box["x"] + box["width"] / 2, box["y"] + box["height"] / 2
    cx0 = float(handle.get_attribute("cx"))
    m0 = marker_cx()
    # 1. the handle follows the pointer in the same event
    page.mouse.move(x0, y0)
    page.mouse.down()
    page.mouse.move(x0 + 30, y0)
    assert float(handle.get_attribute("cx")) == pytest.approx(cx0 + 30, abs=1.0), \
        f"{where}: the handle did not move with the pointer"
    # 2. ten quick moves: one in flight, the latest wins
    n_before = n_requests()
    for k in range(1, 11):
        page.mouse.move(x0 + 30 + 6 * k, y0)
    page.mouse.up()
    _wait_for(lambda: abs(marker_cx() - (m0 + 90)) < 1.5, 20, f"{where}: P drawn at the last position")
    time.sleep(0.5)
    sent = n_requests() - n_before
    assert 1 <= sent <= 4, f"{where}: {sent} requests reached the kernel for 10 quick moves"
    # 3. a refused position snaps back, with the reason
    box = handle.bounding_box()
    x1, y1 = box["x"] + box["width"] / 2, box["y"] + box["height"] / 2
    accepted = float(handle.get_attribute("cx"))
    page.mouse.move(x1, y1)
    page.mouse.down()
    page.mouse.move(x1 + 200, y1, steps=2)
    page.mouse.up()
    status = page.locator(".pg-status").first
    _wait_for(lambda: "at most 3" in status.inner_text(), 20, f"{where}: the refusal's reason")
    _wait_for(lambda: abs(float(handle.get_attribute("cx")) - accepted) < 1.5, 10,
              f"{where}: the refused handle to snap back")
    # a new state from the kernel (not an answer to the page): the refusal said is past
    page.get_by_role("button", name="redraw").click()
    _wait_for(lambda: status.inner_text() == "", 20, f"{where}: the refusal cleared by a new picture")
    # 4. zoom at once, then the kernel's picture of the new view; reset view returns
    ticks_before = page.locator(".pg-axes text").all_text_contents()
    svg.hover()
    n_before = n_requests()
    page.mouse.wheel(-400, 0)            # sideways: scrolls the page, never zooms
    time.sleep(0.3)
    assert n_requests() == n_before, f"{where}: a sideways wheel asked for a new view"
    assert page.locator(".pg-axes text").all_text_contents() == ticks_before
    page.mouse.wheel(0, -400)
    _wait_for(lambda: page.locator(".pg-axes text").all_text_contents() != ticks_before, 20,
              f"{where}: the zoomed view redrawn by the kernel")
    page.locator(".pg-bar button").first.click()
    _wait_for(lambda: page.locator(".pg-axes text").all_text_contents() == ticks_before, 20,
              f"{where}: reset view")
    # 5. hover shows the description
    line = page.locator("g[data-id='l'] path").first
    line.hover(force=True)
    tip = page.locator(".pg-tip").first
    _wait_for(lambda: "horizontal line through P" in tip.inner_text(), 10, f"{where}: the hover text")
    # pressing a handle starts a drag: the tip (what the pointer was over) goes, as on leaving
    handle.hover(force=True)
    _wait_for(lambda: tip.is_visible(), 10, f"{where}: the handle's hover text")
    page.mouse.down()
    _wait_for(lambda: not tip.is_visible(), 5, f"{where}: the tip hidden when a drag starts")
    page.mouse.up()
    # 6. Play: the page asks for frames by itself while playing is on, one at a time
    api = page.locator(".pg-canvas").first
    page.get_by_role("button", name="play").click()
    _wait_for(lambda: n_ticks() >= 10, 30, f"{where}: ticks while playing")
    assert api.evaluate("el => el.__planargeo.stats.filter(s => s.type === 'tick' && !s.tAck).length") <= 1
    page.get_by_role("button", name="play").click()
    time.sleep(1.0)
    stopped = n_ticks()
    time.sleep(1.0)
    assert n_ticks() <= stopped + 1, f"{where}: ticks went on after Play stopped"
    # 7. a view opened now shows the whole current picture, as the first view does
    cx_now = marker_cx()
    page.get_by_role("button", name="show again").click()
    second = page.locator(".pg-canvas").nth(1)
    second.wait_for(state="visible", timeout=30_000)
    _wait_for(lambda: second.locator("g[data-id='P'] circle").count() == 1, 20, f"{where}: the second view drawn")
    _wait_for(lambda: abs(float(second.locator("g[data-id='P'] circle").first.get_attribute("cx")) - cx_now) < 0.5,
              20, f"{where}: the second view shows the current picture")
    assert second.locator(".pg-title").first.text_content() == title.text_content()


def _run(page, url: str, where: str, requests: list[str]) -> None:
    page.on("request", lambda r: requests.append(r.url))
    page.on("websocket", lambda ws: requests.append(ws.url))
    try:
        page.goto(url, wait_until="domcontentloaded", timeout=90_000)
        if where == "jupyterlab":
            page.wait_for_selector(".jp-Notebook", timeout=60_000)
            page.wait_for_function("window.jupyterapp && window.jupyterapp.shell.currentWidget"
                                   " && window.jupyterapp.shell.currentWidget.sessionContext"
                                   " && window.jupyterapp.shell.currentWidget.sessionContext.session"
                                   " && window.jupyterapp.shell.currentWidget.sessionContext.session.kernel",
                                   timeout=60_000)
            page.evaluate("window.jupyterapp.commands.execute('notebook:run-all-cells')")
        _exercise(page, where)
    except Exception:
        ARTIFACTS.mkdir(exist_ok=True)
        page.screenshot(path=str(ARTIFACTS / f"page-canvas-{where}.png"))
        raise
    outside = sorted({u for u in requests if not _local(u)})
    assert not outside, f"{where}: requests left localhost: {outside[:5]}"


def test_page_canvas_in_voila(browser, tmp_path):
    nb = tmp_path / "canvas.ipynb"
    _notebook(nb)
    server = VoilaServer(nb, tmp_path / "voila")
    page = browser.new_page(viewport={"width": 900, "height": 800})
    requests: list[str] = []
    try:
        _run(page, server.url, "voila", requests)
    finally:
        page.close()
        server.stop()
    assert requests, "no request was recorded at all"


def test_page_canvas_in_jupyterlab(lab, browser):
    _notebook(lab.root / "canvas.ipynb")
    page = browser.new_page(viewport={"width": 1200, "height": 1400})
    requests: list[str] = []
    try:
        _run(page, f"{lab.url}/lab/tree/canvas.ipynb?reset", "jupyterlab", requests)
    finally:
        page.close()
