"""Every explorer drawn by the browser (``display="page"``), in the web app's Voila.

One notebook shows all twelve explorers in page mode.  For each, headless chromium
checks that the picture is drawn as SVG elements, that dragging its first handle in
view moves the handle with the pointer at once and brings a new picture from the
kernel (the request is answered: an acknowledgement, and the page paints again), and
that hovering a labelled element shows its symbol and description.
"""
from __future__ import annotations

import time

import nbformat
import pytest

from .conftest import ARTIFACTS, VoilaServer
from .test_browser import _wait_for

pytestmark = pytest.mark.browser

CODE = """\
import planargeo.widgets as pw
explorers = {name: getattr(pw, name)(display="page") for name in pw.EXPLORERS}
"""
SHOW = "explorers[{name!r}]"


def test_every_explorer_in_the_page(browser, tmp_path):
    import planargeo.widgets as pw

    names = list(pw.EXPLORERS)
    nb = nbformat.v4.new_notebook()
    nb.cells = [nbformat.v4.new_code_cell(CODE)] + [nbformat.v4.new_code_cell(SHOW.format(name=n))
                                                     for n in names]
    nb.metadata["kernelspec"] = {"name": "python3", "display_name": "Python 3", "language": "python"}
    path = tmp_path / "page-explorers.ipynb"
    nbformat.write(nb, path)
    server = VoilaServer(path, tmp_path / "voila")
    page = browser.new_page(viewport={"width": 1400, "height": 1000})
    failures = []
    try:
        page.goto(server.url, wait_until="domcontentloaded", timeout=180_000)
        _wait_for(lambda: page.locator(".pg-canvas").count() == len(names), 300,
                  f"{len(names)} page canvases")
        for k, name in enumerate(names):
            cv = page.locator(".pg-canvas").nth(k)
            try:
                cv.scroll_into_view_if_needed()
                _wait_for(lambda: cv.locator(".pg-el").count() > 0, 60, f"{name}: elements drawn")
                handles = cv.locator("circle.pg-handle")
                svg_box = cv.locator("svg").first.bounding_box()
                moved = False
                for j in range(handles.count()):
                    box = handles.nth(j).bounding_box()
                    if box is None or not (svg_box["x"] + 10 < box["x"] < svg_box["x"] + svg_box["width"] - 40
                                           and svg_box["y"] + 30 < box["y"] < svg_box["y"] + svg_box["height"] - 40):
                        continue
                    h = handles.nth(j)
                    cx0 = float(h.get_attribute("cx"))
                    n0 = cv.evaluate("el => el.__planargeo.stats.length")
                    p0 = cv.evaluate("el => el.__planargeo.painted()")
                    x, y = box["x"] + box["width"] / 2, box["y"] + box["height"] / 2
                    page.mouse.move(x, y)
                    page.mouse.down()
                    page.mouse.move(x + 12, y + 4)
                    assert abs(float(h.get_attribute("cx")) - (cx0 + 12)) < 1.5, "handle did not follow"
                    page.mouse.up()
                    _wait_for(lambda: cv.evaluate(
                        f"el => el.__planargeo.stats.length > {n0} && !el.__planargeo.busy()"), 60,
                        f"{name}: the drag answered")
                    _wait_for(lambda: cv.evaluate(f"el => el.__planargeo.painted() > {p0}"), 30,
                              f"{name}: a new picture painted")
                    moved = True
                    break
                if handles.count() and not moved:
                    failures.append(f"{name}: no handle inside the view to drag")
                described = cv.locator(".pg-el[data-described]")
                tip = cv.locator(".pg-tip")
                reachable = shown = 0
                for j in range(min(described.count(), 12)):
                    box = described.nth(j).bounding_box()
                    if box is None:
                        continue
                    x, y = box["x"] + box["width"] / 2, box["y"] + box["height"] / 2
                    on_top = page.evaluate(
                        "([x, y, id]) => { const e = document.elementFromPoint(x, y);"
                        " const g = e && e.closest('.pg-el'); return !!g && g.dataset.id === id; }",
                        [x, y, described.nth(j).get_attribute("data-id")])
                    if not on_top:            # another element covers its centre: try the next
                        continue
                    reachable += 1
                    page.mouse.move(x, y)
                    time.sleep(0.2)
                    if tip.is_visible() and tip.inner_text().strip():
                        shown += 1
                        break
                if reachable and not shown:
                    failures.append(f"{name}: no hover text on {reachable} described elements under the pointer")
            except Exception as exc:  # collect: one explorer's failure does not hide the others'
                ARTIFACTS.mkdir(exist_ok=True)
                page.screenshot(path=str(ARTIFACTS / f"page-{name}.png"))
                failures.append(f"{name}: {exc}"[:400])
    finally:
        page.close()
        server.stop()
    assert not failures, "\n".join(failures)

