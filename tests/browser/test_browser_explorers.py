"""Every explorer in a real browser: in JupyterLab and in the web app of ``make app`` (Voila).

The app notebook (``app/planargeo-app.ipynb``, one section per explorer) is copied
with two changes: each explorer is kept in a variable, and a last cell prints, for
each explorer, where its first draggable handle sits on the figure (as fractions of
the canvas) and whether it has Play.  Then, for every explorer, the browser

* drags a handle on the ipympl canvas with real mouse events (to a drop point the
  kernel found, on an off-screen twin of the explorer, to change the readout) and
  sees the readout and the figure change;
* moves a slider with the keyboard and sees the readout and the figure change;
* presses Play (where the mechanism moves) and sees frames advance;
* clicks *Export SVG* and receives a file that is an SVG document.

All failures are collected and reported together (one explorer's failure does not
hide the others').  With ``PLANARGEO_UPDATE_SCREENS=1`` (``make screens``) the app
run also writes every explorer's default state to ``docs/screens/<slug>.png``.
"""
from __future__ import annotations

import json
import os
import re
import time
from pathlib import Path

import nbformat
import numpy as np
import pytest

from .conftest import ARTIFACTS, LabServer, VoilaServer
from .test_browser import _pixels, _readout, _wait_for

pytestmark = pytest.mark.browser

REPO = Path(__file__).resolve().parents[2]
APP = REPO / "app" / "planargeo-app.ipynb"
SCREENS = REPO / "docs" / "screens"
CELL = re.compile(r"^pw\.(\w+)\(\)$")

PROBE = """\
import json as _json
from planargeo.widgets import Explorer as _Explorer


def _drag_plan(ex):
    # a handle in view and a drop point that changes the readout and the picture (off-screen twin)
    x0, x1 = sorted(ex.ax.get_xlim()); y0, y1 = sorted(ex.ax.get_ylim())
    inside = lambda p: p is not None and x0 < p[0] < x1 and y0 < p[1] < y1
    twin = type(ex)(display="agg", **ex.values)
    for hd in twin.handles():
        p = hd.where()
        if not inside(p):
            continue
        for fx, fy in ((0.12, 0), (-0.12, 0), (0, 0.12), (0, -0.12), (0.25, 0), (-0.25, 0), (0, 0.25), (0, -0.25)):
            q = (p[0] + fx * (x1 - x0), p[1] + fy * (y1 - y0))
            if not inside(q):
                continue
            fresh = type(ex)(display="agg", **ex.values)
            before = dict(fresh.readout_values)
            fresh.fig.canvas.draw()
            picture = bytes(fresh.fig.canvas.buffer_rgba())
            fresh.drag(hd.name, p, q, steps=8)
            fresh.fig.canvas.draw()
            if (not fresh.message and fresh.readout_values != before
                    and bytes(fresh.fig.canvas.buffer_rgba()) != picture):
                return hd.name, p, q
    return None


_probe = []
for _k, _ex in enumerate(_explorers):
    _W, _H = _ex.fig.canvas.get_width_height()
    _ex.ax.apply_aspect()
    _plan = _drag_plan(_ex)
    _h = None
    if _plan is not None:
        _name, _p, _q = _plan
        _fp = _ex.ax.transData.transform(_p); _fq = _ex.ax.transData.transform(_q)
        _h = {"name": _name, "fx": float(_fp[0] / _W), "fy": float(1 - _fp[1] / _H),
              "tx": float(_fq[0] / _W), "ty": float(1 - _fq[1] / _H)}
    _probe.append({"title": _ex.title, "slug": _ex.slug, "handle": _h,
                   "play": type(_ex).play_step is not _Explorer.play_step})
print("PROBE " + _json.dumps(_probe))
"""


def instrumented_app(dst: Path) -> list[str]:
    """Copy the app notebook to ``dst``, keeping each explorer in ``_explorers``; return their names."""
    nb = nbformat.read(APP, as_version=4)
    names = []
    for cell in nb.cells:
        m = CELL.match(cell.source.strip()) if cell.cell_type == "code" else None
        if m:
            names.append(m.group(1))
            cell.source = f"_explorers.append(pw.{m.group(1)}())\n_explorers[-1]"
    first_code = next(c for c in nb.cells if c.cell_type == "code")
    first_code.source += "\n_explorers = []"
    nb.cells.append(nbformat.v4.new_code_cell(PROBE))
    nbformat.write(nb, dst)
    return names


def test_app_shows_every_registered_explorer():
    """The app has one section per registered explorer, and nothing else."""
    from planargeo.widgets import EXPLORERS

    nb = nbformat.read(APP, as_version=4)
    shown = [CELL.match(c.source.strip()).group(1) for c in nb.cells
             if c.cell_type == "code" and CELL.match(c.source.strip())]
    assert sorted(shown) == sorted(EXPLORERS)
    assert len(set(shown)) == len(shown)


# --------------------------------------------------------------------------- the browser side
def _readout_changed(explorer, before, timeout):
    return _wait_for(lambda: (lambda r: r if r and r != before else None)(_readout(None, explorer)),
                     timeout, "the readout to change")


def _figure_png(explorer):
    fig = explorer.locator(".planargeo-figure").first
    return _pixels(fig.screenshot())


def _changed(a, b) -> float:
    if a.shape != b.shape:
        return 1.0
    return float(np.mean(np.any(a != b, axis=-1)))


def _try(what: str, failures: list, title: str, fn):
    try:
        fn()
    except Exception as exc:  # noqa: BLE001 - collected, reported together
        failures.append(f"{title}: {what}: {type(exc).__name__}: {str(exc)[:300]}")


def check_slider(page, explorer):
    """Some slider of the explorer moves the readout and the figure."""
    sliders = explorer.locator(".widget-slider")
    problems = []
    for i in range(min(sliders.count(), 4)):
        before, png = _readout(page, explorer), _figure_png(explorer)
        handle = sliders.nth(i).locator(".noUi-handle").first
        if not handle.is_visible():
            continue
        handle.scroll_into_view_if_needed()
        handle.focus()
        for key in ("ArrowRight", "ArrowLeft"):
            for _ in range(3):
                page.keyboard.press(key)
                time.sleep(0.05)
            try:
                _readout_changed(explorer, before, 8)
            except AssertionError:
                continue
            time.sleep(0.8)
            frac = _changed(png, _figure_png(explorer))
            if frac > 0.001:
                return
            problems.append(f"slider {i}: readout changed but only {frac:.3%} of the figure")
    raise AssertionError("no slider changed both the readout and the figure; " + "; ".join(problems))


def check_drag(page, explorer, handle):
    """Drag the handle to the drop point the probe found (on an off-screen twin) to change the readout."""
    canvas = explorer.locator(".planargeo-figure canvas").first
    canvas.scroll_into_view_if_needed()
    time.sleep(0.5)
    box = canvas.bounding_box()
    x0 = box["x"] + handle["fx"] * box["width"]
    y0 = box["y"] + handle["fy"] * box["height"]
    x1 = box["x"] + handle["tx"] * box["width"]
    y1 = box["y"] + handle["ty"] * box["height"]
    before, png = _readout(page, explorer), _figure_png(explorer)
    page.mouse.move(x0, y0)
    page.mouse.down()
    for k in range(1, 9):
        page.mouse.move(x0 + (x1 - x0) * k / 8, y0 + (y1 - y0) * k / 8)
        time.sleep(0.03)
    page.mouse.up()
    _readout_changed(explorer, before, 10)
    time.sleep(0.8)
    assert _changed(png, _figure_png(explorer)) > 0.001, "the readout changed but not the figure"


def check_play(page, explorer):
    # from the default state: the drag and slider checks may have left a state whose motion ends at
    # once by a stated event (the car sliding out once the tyres' friction limit is reached)
    reset = explorer.locator("button").filter(has_text="Reset").first
    if reset.count():
        shown = _readout(page, explorer)
        reset.click()
        _wait_for(lambda: (lambda r: r if r and r != shown else None)(_readout(None, explorer)) or True,
                  5, "Reset")
        time.sleep(1.0)
    play = explorer.locator(".widget-play button, .jupyter-widgets.widget-play button").first
    play.scroll_into_view_if_needed()
    before = _readout(page, explorer)
    play.click()
    first = _readout_changed(explorer, before, 15)
    _readout_changed(explorer, first, 15)  # and again: frames keep coming
    pause = explorer.locator(".widget-play button").nth(1)
    if pause.count():
        pause.click()


def check_export(page, explorer, tmp: Path):
    button = explorer.locator("button", has_text="SVG").first
    button.scroll_into_view_if_needed()
    got = []

    def on_download(d):
        got.append(d)

    page.on("download", on_download)
    try:
        button.click()
        _wait_for(lambda: got, 5, "a download from the button")
    except AssertionError:
        link = explorer.locator("a[download]").last
        link.wait_for(state="visible", timeout=15_000)
        with page.expect_download(timeout=15_000) as info:
            link.click()
        got.append(info.value)
    finally:
        page.remove_listener("download", on_download)
    path = tmp / got[0].suggested_filename
    got[0].save_as(path)
    head = path.read_bytes()[:400].decode("utf-8", "replace")
    assert "<svg" in head or head.startswith("<?xml"), head[:100]


def run_all(page, tmp: Path, screens: bool = False) -> list[str]:
    out = page.locator("pre, .jp-OutputArea-output, .output_area", has_text="PROBE").last
    out.wait_for(timeout=240_000)
    probe = json.loads(out.inner_text().split("PROBE", 1)[1].strip().splitlines()[0])
    explorers = page.locator(".planargeo-explorer")
    _wait_for(lambda: explorers.count() == len(probe), 120, f"{len(probe)} explorers to render")
    failures = []
    for k, info in enumerate(probe):
        ex = explorers.nth(k)
        title = info["title"]
        ex.scroll_into_view_if_needed()
        _wait_for(lambda: ex.locator(".planargeo-figure canvas, .planargeo-figure").first.bounding_box(),
                  30, f"{title}: the figure")
        time.sleep(0.5)
        if screens:
            SCREENS.mkdir(parents=True, exist_ok=True)
            ex.screenshot(path=str(SCREENS / f"{info['slug']}.png"))
        # the drag first: the probe found its handle and drop point in the default state
        if info["handle"] is None:
            failures.append(f"{title}: no handle in view whose drag changes the readout")
        else:
            _try("drag", failures, title, lambda: check_drag(page, ex, info["handle"]))
        _try("slider", failures, title, lambda: check_slider(page, ex))
        if info["play"]:
            _try("play", failures, title, lambda: check_play(page, ex))
        _try("export", failures, title, lambda: check_export(page, ex, tmp))
    return failures


def _finish(page, failures, name):
    if failures:
        page.screenshot(path=str(ARTIFACTS / f"{name}-failure.png"), full_page=True)
    assert not failures, "\n".join(failures)


def test_every_explorer_in_the_app(tmp_path):
    """``make app``: Voila serves the app notebook; every explorer works there."""
    from playwright.sync_api import sync_playwright

    from .conftest import CHROMIUM, CHROMIUM_ARGS

    if not Path(CHROMIUM).exists():
        pytest.skip(f"{CHROMIUM} not found")
    ARTIFACTS.mkdir(exist_ok=True)
    root = tmp_path / "app"
    root.mkdir()
    instrumented_app(root / "app.ipynb")
    server = VoilaServer(root / "app.ipynb", tmp_path)
    try:
        with sync_playwright() as p:
            b = p.chromium.launch(executable_path=CHROMIUM, args=CHROMIUM_ARGS)
            page = b.new_page(viewport={"width": 1400, "height": 1000}, accept_downloads=True)
            try:
                page.goto(server.url + "/", timeout=120_000)
                failures = run_all(page, tmp_path, screens=bool(os.environ.get("PLANARGEO_UPDATE_SCREENS")))
                _finish(page, failures, "app")
            finally:
                b.close()
    finally:
        server.stop()


def test_every_explorer_in_jupyterlab(lab, browser, tmp_path):
    """The same checks in JupyterLab, where the notebook turns on ``%matplotlib widget`` itself."""
    ARTIFACTS.mkdir(exist_ok=True)
    instrumented_app(lab.root / "app-under-test.ipynb")
    page = browser.new_page(viewport={"width": 1500, "height": 1000}, accept_downloads=True)
    try:
        page.goto(f"{lab.url}/lab/tree/app-under-test.ipynb?reset", wait_until="domcontentloaded",
                  timeout=60_000)
        page.wait_for_function("window.jupyterapp && window.jupyterapp.shell.currentWidget"
                               " && window.jupyterapp.shell.currentWidget.sessionContext.session"
                               " && window.jupyterapp.shell.currentWidget.sessionContext.session.kernel",
                               timeout=60_000)
        page.evaluate("window.jupyterapp.commands.execute('notebook:run-all-cells')")
        failures = run_all(page, tmp_path)
        _finish(page, failures, "lab")
    finally:
        page.close()
