"""Browser latency: from a control change or a mouse move to the new picture in the page.

Measured in a real JupyterLab in Debian's headless chromium, on the 10-link chain
explorer with every overlay on (the heaviest explorer state the tests visit):

* **slider → new image** (default image mode, inline backend): the time from a key
  press on the ``angle`` slider to the figure's ``<img>`` receiving its new PNG;
* **slider → new canvas** under ``%matplotlib widget`` (ipympl): the same, until
  ipympl paints the new frame on its ``<canvas>``;
* **drag step** under ipympl: the mouse holds the end of the last link and moves by
  3 px; the time from the move to the next paint of the canvas.

The same three measurements on the projective playground (the lightest explorer), in
the same run, give the floor of the machine: what messaging, the page's work and the
smallest update cost, against which the chain's own cost reads.

Times are taken in the page (``performance.now()``): a ``MutationObserver`` on the
image and a wrapper of the canvas's ``drawImage`` record when a new picture lands.
Each step waits for its picture before the next starts, so the numbers are
end-to-end latencies, not throughput.  Medians and the 10–90 % spread of ``--steps``
steps are written to ``<out>/browser_latency.{json,md}``.

Goals (issue "Every explorer an instrument"): slider → new image ≤ 100 ms median,
drag step ≤ 60 ms median.

Run::

    .venv/bin/python benchmarks/browser_latency.py [--steps 25] [--out benchmarks/results]
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
from browser_harness import CHROMIUM, LabServer, launch_chromium  # noqa: E402

from planargeo.files import atomic_write_many  # noqa: E402

OVERLAYS = ("velocity poles", "acceleration poles", "bias terms", "internal forces", "T/U split",
            "articulated inertias")
EXPLORER = ("from planargeo.widgets import ChainExplorer\n"
            "ex = ChainExplorer(links=10, **{k: True for k in %r if k in ChainExplorer(display='agg').controls})\n"
            "ex" % (OVERLAYS,))
#: the floor of this machine: the lightest explorer (a point, a line, a conic) through the same path
LIGHT = "from planargeo.widgets import ProjectiveExplorer\nex = ProjectiveExplorer()\nex"
#: (name, notebook code, slider to step, handle to drag: the first one that is in view)
CASES = (("10-link chain, all overlays", EXPLORER, "angle", -1),
         ("projective playground (floor)", LIGHT, "P x", 0))
HANDLE = (
    "import json\n"
    "W, H = ex.fig.canvas.get_width_height()\n"
    "ex.ax.apply_aspect()\n"
    "hs = [h for h in ex.handles() if h.where() is not None]\n"
    "if hs:\n"
    "    h = hs[%d]\n"
    "    px, py = ex.ax.transData.transform(h.where())\n"
    "    print('HANDLE ' + json.dumps({'name': h.name, 'fx': float(px / W), 'fy': float(1 - py / H)}))\n"
    "else:\n"
    "    print('HANDLE null')")

# Record when a new picture lands: the figure <img> gets a new src; an ipympl canvas is painted.
INIT = """
window.__pgPaints = [];
const _draw = CanvasRenderingContext2D.prototype.drawImage;
CanvasRenderingContext2D.prototype.drawImage = function (...a) {
  window.__pgPaints.push(performance.now());
  return _draw.apply(this, a);
};
new MutationObserver((ms) => {
  for (const m of ms) {
    const t = m.target;
    if (t.tagName === 'IMG' && m.attributeName === 'src' && t.closest('.planargeo-figure, .planargeo-explorer'))
      window.__pgPaints.push(performance.now());
  }
}).observe(document, {attributes: true, subtree: true, attributeFilter: ['src']});
"""


def _notebook(path: Path, cells: list[str]) -> None:
    nb = nbformat.v4.new_notebook()
    nb.cells = [nbformat.v4.new_code_cell(c) for c in cells]
    nb.metadata["kernelspec"] = {"name": "python3", "display_name": "Python 3", "language": "python"}
    nbformat.write(nb, path)


def _open(page, lab, name: str):
    page.goto(f"{lab.url}/lab/tree/{name}?reset", wait_until="domcontentloaded", timeout=60_000)
    page.wait_for_selector(".jp-Notebook", timeout=60_000)
    page.wait_for_function("window.jupyterapp && window.jupyterapp.shell.currentWidget"
                           " && window.jupyterapp.shell.currentWidget.sessionContext.session"
                           " && window.jupyterapp.shell.currentWidget.sessionContext.session.kernel",
                           timeout=60_000)
    page.evaluate("window.jupyterapp.commands.execute('notebook:run-all-cells')")
    page.wait_for_function(
        "() => { const c = window.jupyterapp.shell.currentWidget.sessionContext;"
        " return c.session.kernel.status === 'idle' &&"
        " ![...document.querySelectorAll('.jp-InputArea-prompt')].some(e => e.textContent.includes('*')); }",
        timeout=180_000, polling=250)
    explorer = page.locator(".planargeo-explorer").first
    explorer.wait_for(state="visible", timeout=60_000)
    return explorer


def _next_paint(page, t0: float, timeout: float = 10.0) -> float | None:
    """Milliseconds from ``t0`` (page clock) to the first paint after it (None: none within ``timeout``)."""
    from playwright.sync_api import TimeoutError as PlaywrightTimeout

    try:
        page.wait_for_function(f"window.__pgPaints.some(t => t > {t0})", timeout=timeout * 1000,
                               polling="raf")
    except PlaywrightTimeout:
        return None
    return page.evaluate(f"window.__pgPaints.find(t => t > {t0})") - t0


def _quiet(page, ms: float = 250.0) -> None:
    """Wait until no paint has landed for ``ms`` milliseconds (the previous step is over)."""
    page.wait_for_function(
        f"(() => {{ const p = window.__pgPaints; return !p.length || performance.now() - p[p.length-1] > {ms}; }})()",
        timeout=20_000, polling=50)


def slider_steps(page, explorer, steps: int, name: str = "angle") -> list[float]:
    slider = explorer.locator(".widget-slider").filter(has_text=name).first
    handle = slider.locator(".noUi-handle").first
    handle.scroll_into_view_if_needed()
    handle.focus()
    out, net = [], 0
    for k in range(steps):
        _quiet(page)
        t0 = page.evaluate("performance.now()")
        right = (k // 5) % 2 == 0
        page.keyboard.press("ArrowRight" if right else "ArrowLeft")
        net += 1 if right else -1
        out.append(_next_paint(page, t0))
    for _ in range(abs(net)):         # back to the start: the drag's handle is where it was measured
        _quiet(page)
        page.keyboard.press("ArrowLeft" if net > 0 else "ArrowRight")
    _quiet(page)
    return out


def drag_steps(page, explorer, handle: dict, steps: int, px: float = 3.0) -> list[float]:
    canvas = explorer.locator(".planargeo-figure canvas").first
    canvas.scroll_into_view_if_needed()
    time.sleep(1.0)
    box = canvas.bounding_box()
    x = box["x"] + handle["fx"] * box["width"]
    y = box["y"] + handle["fy"] * box["height"]
    page.mouse.move(x, y)
    _quiet(page)
    page.mouse.down()
    out = []
    for k in range(steps):
        _quiet(page, 150.0)
        x += px if (k // 8) % 2 == 0 else -px
        t0 = page.evaluate("performance.now()")
        page.mouse.move(x, y)
        out.append(_next_paint(page, t0))
    page.mouse.up()
    return out


def python_share(repeat: int = 25) -> dict:
    """Milliseconds (medians) of the Python side of one update of the same explorer, in this process.

    What the page waits for besides messaging and painting: the update (compute and
    render), drawing the frame (blitted over the kept background, and whole for
    comparison), and the light PNG (whole, and the diff of a drag step as ipympl sends it).
    """
    import numpy as np

    from planargeo.widgets import ChainExplorer
    from planargeo.widgets.frames import live_png

    ex = ChainExplorer(display="agg", links=10, **{k: True for k in OVERLAYS})
    w = ex.controls["angle"]
    values = [w.value + w.step * (k % 10) for k in range(1, repeat + 1)]

    def med(fn):
        out = []
        for k in range(repeat):
            t0 = time.perf_counter()
            fn(k)
            out.append((time.perf_counter() - t0) * 1e3)
        return statistics.median(out)

    res = {"slider update, whole (agg: compute, render, frame)": med(lambda k: ex.set(angle=values[k]))}
    res["render (artists and labels from the state)"] = med(lambda k: ex.render(ex.state))
    res["frame, blitted over the kept background"] = med(lambda k: ex.frames.draw())

    def whole(k):
        ex.frames.invalidate()
        ex.frames.draw()
    res["frame, whole figure"] = med(whole)
    res["Matplotlib's own draw of the figure"] = med(lambda k: ex.fig.canvas.draw())
    ex.frames.draw()
    before = np.asarray(ex.fig.canvas.buffer_rgba()).copy()
    h = [h for h in ex.handles() if h.where() is not None][-1]
    x, y = h.where()
    ex.drag(h.name, (x, y), (x + 0.03, y), steps=1)
    after = np.asarray(ex.fig.canvas.buffer_rgba()).copy()
    changed = (before.view(np.uint32) != after.view(np.uint32)).squeeze(-1)
    res["live PNG, whole frame (image mode)"] = med(lambda k: live_png(after))
    res[f"live PNG, drag-step diff ({100 * changed.mean():.1f} % of pixels, ipympl)"] = med(
        lambda k: live_png(after, changed))

    def full_png(k):
        import io
        buf = io.BytesIO()
        ex.fig.savefig(buf, format="png", dpi=ex.dpi, pil_kwargs={"compress_level": 1})
    res["full-colour PNG by savefig (before: every image-mode update)"] = med(full_png)
    return res


def summary(xs: list) -> dict:
    """Median and 10-90 % spread of the steps that got a picture; ``missed``: those that got none."""
    got = [x for x in xs if x is not None]
    if len(got) < 2:
        raise RuntimeError(f"only {len(got)} of {len(xs)} steps got a new picture within 10 s")
    qs = statistics.quantiles(got, n=10)
    return {"median_ms": statistics.median(got), "p10_ms": qs[0], "p90_ms": qs[-1], "n": len(got),
            "missed": len(xs) - len(got)}


def run(steps: int) -> dict:
    from playwright.sync_api import sync_playwright

    results = {}
    with tempfile.TemporaryDirectory() as tmp, sync_playwright() as p:
        tmp = Path(tmp)
        root = tmp / "nb"
        root.mkdir()
        for k, (_, code, _, pick) in enumerate(CASES):
            _notebook(root / f"image{k}.ipynb", [code])
            _notebook(root / f"ipympl{k}.ipynb", ["%matplotlib widget", code, HANDLE % pick])
        lab = LabServer(root, tmp)
        browser = launch_chromium(p)
        try:
            for k, (case, _, slider, _) in enumerate(CASES):
                print(f"[{case}]", file=sys.stderr, flush=True)
                page = browser.new_page(viewport={"width": 1500, "height": 1100})
                page.add_init_script(INIT)
                explorer = _open(page, lab, f"image{k}.ipynb")
                time.sleep(1.0)
                results[f"{case}: slider → new image (image mode)"] = summary(
                    slider_steps(page, explorer, steps, slider))
                page.close()

                page = browser.new_page(viewport={"width": 1500, "height": 1100})
                page.add_init_script(INIT)
                explorer = _open(page, lab, f"ipympl{k}.ipynb")
                out = page.locator(".jp-OutputArea-output", has_text="HANDLE").first
                out.wait_for(timeout=60_000)
                handle = json.loads(out.inner_text().split("HANDLE", 1)[1].strip())
                page.wait_for_function("document.querySelector('.planargeo-figure canvas') &&"
                                       " document.querySelector('.planargeo-figure canvas').width > 50",
                                       timeout=60_000)
                time.sleep(1.0)
                results[f"{case}: slider → new canvas (ipympl)"] = summary(
                    slider_steps(page, explorer, steps, slider))
                if handle is None:
                    print(f"{case}: no draggable handle in view: drag step not measured")
                else:
                    results[f"{case}: drag step, 3 px, handle {handle['name']!r} (ipympl)"] = summary(
                        drag_steps(page, explorer, handle, steps))
                page.close()
        finally:
            browser.close()
            lab.stop()
    return results


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--steps", type=int, default=25, help="steps per measurement (median of these)")
    ap.add_argument("--out", default=str(Path(__file__).parent / "results"))
    args = ap.parse_args(argv)
    if not Path(CHROMIUM).exists():
        print(f"{CHROMIUM} not found: install Debian's chromium (make browser); skipped")
        return 0
    res = run(args.steps)
    share = python_share()
    meta = {"date": datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC"),
            "python": platform.python_version(), "machine": platform.machine(), "cpus": os.cpu_count(),
            "load": os.getloadavg()[0], "steps": args.steps,
            "explorer": "ChainExplorer(links=10), every overlay on"}
    lines = ["# Browser latency", "",
             "End-to-end, in JupyterLab in headless chromium (page clock), for the 10-link chain explorer",
             "with every overlay on: from a key press on a slider, or a 3-px mouse move dragging the last",
             "link's end, to the new picture in the page. Goals: slider ≤ 100 ms, drag step ≤ 60 ms (medians).",
             "The projective playground (one point, one line, one conic) measured the same way in the same",
             "run is the floor of this machine: messaging, the page's work and the lightest update.",
             "", "| measurement | median (ms) | 10 % | 90 % | steps |", "|---|---:|---:|---:|---:|"]
    for k, r in res.items():
        missed = f" ({r['missed']} without a picture in 10 s)" if r.get("missed") else ""
        lines.append(f"| {k} | {r['median_ms']:.0f} | {r['p10_ms']:.0f} | {r['p90_ms']:.0f} | {r['n']}{missed} |")
        print(f"{k:50s} median {r['median_ms']:6.1f} ms  (10–90 %: {r['p10_ms']:.0f}–{r['p90_ms']:.0f})")
    lines += ["", "The Python side of one update of the same explorer (this process, Agg, medians of 25):",
              "", "| step | ms |", "|---|---:|"]
    for k, v in share.items():
        lines.append(f"| {k} | {v:.1f} |")
        print(f"{k:50s} {v:6.1f} ms")
    lines += ["", "How the frame is made fast: `planargeo.widgets.frames` (blitting over a kept background, "
              "256-colour live PNGs, ipympl frames sent at once) and the artists' direct drawing of their "
              "children (`planargeo.draw.artists`).",
              "", f"Machine: {meta['machine']}, {meta['cpus']} CPUs, load {meta['load']:.2f}, "
              f"Python {meta['python']}, {meta['date']}.", ""]
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    atomic_write_many({out / "browser_latency.json": json.dumps({"meta": meta, "results": res,
                                                                 "python_share_ms": share}, indent=2,
                                                                ensure_ascii=False) + "\n",
                       out / "browser_latency.md": "\n".join(lines)})
    return 0


if __name__ == "__main__":
    sys.exit(main())
