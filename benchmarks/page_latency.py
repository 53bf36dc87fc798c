"""Page latency: explorers drawn by the browser (``display="page"``), in JupyterLab and in Voila.

Measured in Debian's headless chromium, in the same run and through the same widget
(:class:`planargeo.widgets.canvas.PictureCanvas`):

* **F, the floor**: an empty request from the page to the kernel and back (``ping``),
  doing no work; the machine's and Jupyter's share of every step;
* **drag step**: a 3 px mouse move on a handle → the picture with the new geometry
  painted (the page's own clock: input event to the animation frame after the reply);
* **handle repaint**: the mouse move → the dragged handle painted at the pointer
  (the page alone, no kernel);
* **slider step**: a key press on a slider → the new picture painted;
* the **Python side** of one update and the size of the message (in this process).

Explorers: the 10-link chain with every overlay on, and the projective playground.
The chain builds its picture natively (:mod:`planargeo.draw.chain`); the projective
playground's is still read off its matplotlib artists (:mod:`planargeo.draw.from_axes`),
so its Python side includes that adapter.  Medians and 90th percentiles of
``--steps`` steps go to ``<out>/page_latency.{json,md}``.

Run::

    .venv/bin/python benchmarks/page_latency.py [--steps 25] [--out benchmarks/results]
"""
from __future__ import annotations

import argparse
import datetime
import json
import os
import platform
import statistics
import sys
import tempfile
import time
from pathlib import Path

import nbformat

sys.path.insert(0, str(Path(__file__).resolve().parent))
from browser_harness import LabServer, VoilaServer, launch_chromium  # noqa: E402

from planargeo.files import atomic_write_many  # noqa: E402

OVERLAYS = ("velocity poles", "acceleration poles", "bias terms", "internal forces", "T/U split",
            "articulated inertias")
CELLS = [
    "from planargeo.widgets import ChainExplorer, ProjectiveExplorer",
    "chain = ChainExplorer(display='page', links=10, **{k: True for k in %r})\nchain" % (OVERLAYS,),
    "light = ProjectiveExplorer(display='page')\nlight",
]
#: (case, explorer title fragment, handle, slider)
CASES = (("10-link chain, all overlays", "Chain", "link 10 end", "angle"),
         ("projective playground", "Projective", "P", "P x"))


def _notebook(path: Path) -> None:
    nb = nbformat.v4.new_notebook()
    nb.cells = [nbformat.v4.new_code_cell(c) for c in CELLS]
    nb.metadata["kernelspec"] = {"name": "python3", "display_name": "Python 3", "language": "python"}
    nbformat.write(nb, path)


def _stat(xs: list[float]) -> dict:
    xs = sorted(x for x in xs if x is not None)
    if not xs:
        return {"median": None, "p90": None, "n": 0}
    return {"median": round(statistics.median(xs), 1), "p90": round(xs[int(0.9 * (len(xs) - 1))], 1),
            "n": len(xs)}


def _canvas(page, title: str):
    ex = page.locator(".planargeo-explorer").filter(has_text=title).first
    ex.wait_for(state="visible", timeout=180_000)
    cv = ex.locator(".pg-canvas").first
    cv.wait_for(state="visible", timeout=60_000)
    cv.scroll_into_view_if_needed()
    return ex, cv


def _api(cv, expr: str):
    return cv.evaluate(f"(el) => {{ const p = el.__planargeo; return {expr}; }}")


def _wait_idle(cv) -> None:
    for _ in range(400):
        if not _api(cv, "p.busy()"):
            return
        time.sleep(0.01)


def floor(cv, steps: int) -> list[float]:
    out = []
    for _ in range(steps):
        _wait_idle(cv)
        n = _api(cv, "p.stats.length")
        _api(cv, "p.ping()")
        for _ in range(500):
            s = _api(cv, f"p.stats.length > {n} && p.stats[p.stats.length - 1].tAck ? p.stats[p.stats.length - 1] : null")
            if s:
                out.append(s["tAck"] - s["tSent"])
                break
            time.sleep(0.005)
    return out


def drag(page, cv, handle: str, steps: int, px: float = 3.0) -> tuple[list[float], list[float]]:
    circle = cv.locator(f"circle[data-handle='{handle}']").first
    box = circle.bounding_box()
    x, y = box["x"] + box["width"] / 2, box["y"] + box["height"] / 2
    page.mouse.move(x, y)
    page.mouse.down()
    lat = []
    n0 = _api(cv, "p.handlePaints.length")
    for k in range(steps):
        _wait_idle(cv)
        time.sleep(0.03)
        n = _api(cv, "p.stats.length")
        x += px if (k // 8) % 2 == 0 else -px
        page.mouse.move(x, y)
        for _ in range(1000):
            s = _api(cv, f"p.stats.length > {n} && p.stats[{n}].tPaint ? p.stats[{n}] : null")
            if s:
                lat.append(s["tPaint"] - s["tInput"])
                break
            time.sleep(0.005)
    page.mouse.up()
    _wait_idle(cv)
    return lat, _api(cv, f"p.handlePaints.slice({n0})")


def slider(page, ex, cv, name: str, steps: int) -> list[float]:
    sl = ex.locator(".widget-slider").filter(has_text=name).first
    knob = sl.locator(".noUi-handle").first
    knob.scroll_into_view_if_needed()
    knob.focus()
    out, net = [], 0
    for k in range(steps):
        _wait_idle(cv)
        time.sleep(0.25)
        t0 = cv.evaluate("() => performance.now()")
        right = (k // 5) % 2 == 0
        page.keyboard.press("ArrowRight" if right else "ArrowLeft")
        net += 1 if right else -1
        for _ in range(1000):
            t = _api(cv, f"p.paintTimes.find(t => t > {t0}) ?? null")
            if t is not None:
                out.append(t - t0)
                break
            time.sleep(0.005)
    for _ in range(abs(net)):
        time.sleep(0.25)
        page.keyboard.press("ArrowLeft" if net > 0 else "ArrowRight")
    return out


def measure(page, steps: int) -> dict:
    res = {}
    for case, title, handle, sl in CASES:
        ex, cv = _canvas(page, title)
        time.sleep(1.0)
        r = {"F (ping round trip)": _stat(floor(cv, steps))}
        lat, hp = drag(page, cv, handle, steps)
        r["drag step"] = _stat(lat)
        r["handle repaint"] = _stat(hp)
        r["slider step"] = _stat(slider(page, ex, cv, sl, steps))
        res[case] = r
    return res


def python_side(repeat: int = 25) -> dict:
    from planargeo.widgets import ChainExplorer, ProjectiveExplorer

    out = {}
    for case, cls, kw, handle in (("10-link chain, all overlays", ChainExplorer,
                                   dict(links=10, **{k: True for k in OVERLAYS}), "link 10 end"),
                                  ("projective playground", ProjectiveExplorer, {}, "P")):
        ex = cls(display="page", **kw)
        h = next(h for h in ex.canvas.picture["handles"] if h["id"] == handle)
        ts = []
        for k in range(repeat):
            t0 = time.perf_counter()
            ex.canvas.handle_message({"type": "drag", "id": handle, "x": h["x"] + 0.01 * (k % 5),
                                      "y": h["y"], "seq": k})
            ts.append((time.perf_counter() - t0) * 1e3)
        t1 = time.perf_counter()
        for _ in range(repeat):
            ex.picture()
        pic_ms = (time.perf_counter() - t1) / repeat * 1e3
        out[case] = {"update, drag step (ms)": round(statistics.median(ts), 1),
                     "of which the picture (ms)": round(pic_ms, 1),
                     "message (KB)": round(len(json.dumps(ex.canvas.picture)) / 1024, 1),
                     "elements": len(ex.canvas.picture["elements"])}
    return out


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--steps", type=int, default=25)
    ap.add_argument("--out", type=Path, default=Path(__file__).parent / "results")
    ap.add_argument("--only", choices=("voila", "jupyterlab"), action="append")
    ap.add_argument("--quick", action="store_true", help="10 steps")
    a = ap.parse_args(argv)
    if a.quick:
        a.steps = min(a.steps, 10)
    if not 1 <= a.steps <= 500:
        ap.error(f"--steps must be between 1 and 500, got {a.steps}")
    from playwright.sync_api import sync_playwright

    results = {"python": python_side()}
    with tempfile.TemporaryDirectory() as tmp, sync_playwright() as p:
        tmp = Path(tmp)
        browser = launch_chromium(p)
        try:
            for medium in a.only or ("voila", "jupyterlab"):
                root = tmp / medium
                root.mkdir()
                _notebook(root / "page.ipynb")
                if medium == "voila":
                    server = VoilaServer(root / "page.ipynb", tmp / f"{medium}-srv")
                    url = server.url
                else:
                    server = LabServer(root, tmp / f"{medium}-srv")
                    url = f"{server.url}/lab/tree/page.ipynb?reset"
                page = browser.new_page(viewport={"width": 1400, "height": 1100})
                try:
                    page.goto(url, wait_until="domcontentloaded", timeout=120_000)
                    if medium == "jupyterlab":
                        page.wait_for_function(
                            "window.jupyterapp && window.jupyterapp.shell.currentWidget"
                            " && window.jupyterapp.shell.currentWidget.sessionContext.session"
                            " && window.jupyterapp.shell.currentWidget.sessionContext.session.kernel",
                            timeout=120_000)
                        page.evaluate("window.jupyterapp.commands.execute('notebook:run-all-cells')")
                    results[medium] = measure(page, a.steps)
                finally:
                    page.close()
                    server.stop()
        finally:
            browser.close()
    results["when"] = datetime.datetime.now().isoformat(timespec="seconds")
    results["machine"] = f"{platform.machine()}, {os.cpu_count()} cores, {platform.python_version()}"
    lines = ["# Page latency: explorers drawn by the browser", "",
             f"{results['when']}, {results['machine']}; medians (90th percentiles) of {a.steps} steps, ms.",
             "F is the round trip of an empty request through the same widget (the floor).", ""]
    for medium in a.only or ("voila", "jupyterlab"):
        lines += [f"## {medium}", "", "| explorer | F | drag step | handle repaint | slider step |",
                  "|---|---|---|---|---|"]
        for case, r in results[medium].items():
            cell = lambda s: f"{s['median']} ({s['p90']})" if s["median"] is not None else "—"  # noqa: E731
            lines.append(f"| {case} | {cell(r['F (ping round trip)'])} | {cell(r['drag step'])} | "
                         f"{cell(r['handle repaint'])} | {cell(r['slider step'])} |")
        lines.append("")
    lines += ["## Python side (this process)", "", "| explorer | update (ms) | picture (ms) | message (KB) | elements |",
              "|---|---|---|---|---|"]
    for case, r in results["python"].items():
        lines.append(f"| {case} | {r['update, drag step (ms)']} | {r['of which the picture (ms)']} | "
                     f"{r['message (KB)']} | {r['elements']} |")
    lines += ["", "The chain's picture is built natively (planargeo/draw/chain.py); the projective "
              "playground's is still read off its matplotlib artists (planargeo/draw/from_axes.py).",
              "Goals (issue 21): drag and slider steps ≤ F + 15 ms; handle repaint ≤ 20 ms; "
              "Python side ≤ 5 ms and message ≤ 20 KB for the chain."]
    a.out.mkdir(parents=True, exist_ok=True)
    atomic_write_many({a.out / "page_latency.json": json.dumps(results, indent=1) + "\n",
                       a.out / "page_latency.md": "\n".join(lines) + "\n"})
    print("\n".join(lines))
    return 0


if __name__ == "__main__":
    sys.exit(main())
