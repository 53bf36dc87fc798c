"""Under ``%matplotlib widget`` (ipympl) the figure is a live canvas: drag the point with the mouse.

A throw-away notebook shows a ProjectiveExplorer on the ipympl canvas and
prints where the point P sits (as fractions of the figure); the browser drags
it with real mouse events; the readout must follow (P x, P y near the drop
point) and the canvas pixels must change.
"""
from __future__ import annotations

import json
import time

import nbformat
import numpy as np
import pytest

from .conftest import ARTIFACTS
from .test_browser import _number, _pixels, _readout, _wait_for

pytestmark = pytest.mark.browser

CELLS = [
    "%matplotlib widget",
    "from planargeo.widgets import ProjectiveExplorer\nex = ProjectiveExplorer()\nex",
    "import json\n"
    "W, H = ex.fig.canvas.get_width_height()\n"
    "ex.ax.apply_aspect()  # no canvas.draw() here: ipympl must initialise from the browser first\n"
    "def frac(x, y):\n"
    "    px, py = ex.ax.transData.transform([x, y])\n"
    "    return [float(px / W), float(1 - py / H)]\n"
    "print('FRACTIONS ' + json.dumps({'P': frac(ex.values['P x'], ex.values['P y']),"
    " 'target': frac(-1.0, -2.0)}))",
]


def test_drag_point_on_ipympl_canvas(lab, browser):
    ARTIFACTS.mkdir(exist_ok=True)
    nb = nbformat.v4.new_notebook()
    nb.cells = [nbformat.v4.new_code_cell(c) for c in CELLS]
    nb.metadata["kernelspec"] = {"name": "python3", "display_name": "Python 3", "language": "python"}
    nbformat.write(nb, lab.root / "ipympl-under-test.ipynb")
    page = browser.new_page(viewport={"width": 1500, "height": 1000})
    try:
        page.goto(f"{lab.url}/lab/tree/ipympl-under-test.ipynb?reset", wait_until="domcontentloaded",
                  timeout=60_000)
        page.wait_for_selector(".jp-Notebook", timeout=60_000)
        page.wait_for_function("window.jupyterapp && window.jupyterapp.shell.currentWidget"
                               " && window.jupyterapp.shell.currentWidget.sessionContext.session"
                               " && window.jupyterapp.shell.currentWidget.sessionContext.session.kernel",
                               timeout=60_000)
        page.evaluate("window.jupyterapp.commands.execute('notebook:run-all-cells')")
        out = page.locator(".jp-OutputArea-output", has_text="FRACTIONS").first
        out.wait_for(timeout=120_000)
        fr = json.loads(out.inner_text().split("FRACTIONS", 1)[1].strip())
        explorer = page.locator(".planargeo-explorer").first
        canvas = explorer.locator(".planargeo-figure canvas").first
        canvas.wait_for(state="visible", timeout=60_000)
        _wait_for(lambda: page.evaluate("(c) => c.width > 50", canvas.element_handle()), 60,
                  "the ipympl canvas to initialise")
        canvas.scroll_into_view_if_needed()
        time.sleep(1.0)
        box = canvas.bounding_box()
        assert box and box["width"] > 100, box
        before = _readout(page, explorer)
        png_before = canvas.screenshot()
        x0 = box["x"] + fr["P"][0] * box["width"]
        y0 = box["y"] + fr["P"][1] * box["height"]
        x1 = box["x"] + fr["target"][0] * box["width"]
        y1 = box["y"] + fr["target"][1] * box["height"]
        page.mouse.move(x0, y0)
        page.mouse.down()
        for k in range(1, 11):
            page.mouse.move(x0 + (x1 - x0) * k / 10, y0 + (y1 - y0) * k / 10)
            time.sleep(0.05)
        page.mouse.up()
        after = _wait_for(lambda: (lambda r: r if abs(_number(r["P x"]) + 1.0) < 0.15
                                   and abs(_number(r["P y"]) + 2.0) < 0.15 else None)(
            _readout(page, explorer)), 60, "the readout to follow the drag")
        assert after != before
        time.sleep(1.0)
        a, b = _pixels(png_before), _pixels(canvas.screenshot())
        assert a.shape == b.shape and np.mean(np.any(a != b, axis=-1)) > 0.001
        page.screenshot(path=str(ARTIFACTS / "ipympl-after-drag.png"))
    except Exception:
        try:
            page.screenshot(path=str(ARTIFACTS / "ipympl-failure.png"))
        except Exception:
            pass
        raise
    finally:
        page.close()
