"""A/B of a change in one run: the same chain, the change switched on and off between blocks.

The notebook (Voila and JupyterLab) shows one 10-link chain with every overlay and a
checkbox ("B"); ticking it runs ``--b`` (Python, e.g. ``PictureCanvas.defer = False``),
clearing it runs ``--a``.  ``--css`` is CSS the harness adds to the page during the B blocks.
Blocks of ``--block`` floor (ping), drag and slider steps alternate between A and B,
``--rounds`` times (ABBA order), so both see the same machine load and the same page.
Besides the steps as page_latency stamps them ("painted": the painting frame's rAF callback),
each step is also taken to the end of that frame's work ("→ frame end", :data:`FRAME_END_HOOK`).

Run::

    MPLBACKEND=Agg .venv/bin/python benchmarks/page_ab.py --a "PictureCanvas.defer = True" \
        --b "PictureCanvas.defer = False" [--only jupyterlab]
"""
from __future__ import annotations

import argparse
import json
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import page_latency as pl  # noqa: E402
from browser_harness import LabServer, VoilaServer, launch_chromium  # noqa: E402


def _cells(a: str, b: str, every: bool = False) -> list[str]:
    """The A/B notebook: the chain, the A/B checkbox and, with ``every``, the other eleven explorers
    after them (as in :data:`page_latency.CELLS`: JupyterLab's work per step grows with the page)."""
    make = "pw.ChainExplorer(display='page', links=10, **{k: True for k in %r})" % (pl.OVERLAYS,)
    return ["import planargeo.widgets as pw\nimport ipywidgets as W\nfrom planargeo.widgets.canvas import PictureCanvas",
            f"chain = {make}\nchain",
            "ab = W.Checkbox(description='B', value=False)\n"
            f"ab.observe(lambda c: exec({b!r} if c.new else {a!r}, globals()), 'value')\n"
            f"exec({a!r}, globals())\nab"] + (pl.CELLS[2:] if every else [])


#: The end of each frame's main-thread work (style, layout, paint, commit): a task posted from the
#: frame's animation-frame callbacks runs after them.  "painted" (page_latency) is stamped in the
#: frame's rAF callback; what the frame does before its rAF callbacks (a hover hit test after the
#: picture changed under a resting pointer runs style and layout there) counts in a step, what it
#: does after them does not: "→ frame end" counts the whole frame, for drag and slider alike.
FRAME_END_HOOK = """() => {
  if (window.__pgFrameEnds) return;
  window.__pgFrameEnds = [];
  const ch = new MessageChannel();
  let posted = false;
  ch.port1.onmessage = () => { posted = false; window.__pgFrameEnds.push(performance.now());
                               if (window.__pgFrameEnds.length > 5000) window.__pgFrameEnds.shift(); };
  const raf = window.requestAnimationFrame.bind(window);
  window.requestAnimationFrame = (cb) => raf((t) => {
    if (!posted) { posted = true; ch.port2.postMessage(0); }
    return cb(t);
  });
}"""


def _to_frame_end(page, pairs: list) -> list:
    """For each ``(input, painted)`` (page ms): the end of the painting frame's work, from the input."""
    return page.evaluate("(ps) => ps.map(([t0, t1]) => { const e = window.__pgFrameEnds.find(t => t >= t1);"
                         " return e === undefined ? null : e - t0; })", pairs)


def _block(res: dict, page, ex, cv, a) -> None:
    """One block of steps in the page's current set-up: F, F after a pause, drags, slider steps."""
    res["F"] += pl.floor(cv, a.block)
    res["F after the steps' pause"] += pl.floor(cv, a.block, pl.PAUSE)
    n0 = len(pl.STEPS)
    res["drag"] += pl.drag(page, cv, "link 10 end", a.block)[0]
    for st in pl.STEPS[n0:]:
        res["drag: ack → painted"].append(st["tPaint"] - st["tAck"])
        res["drag: sent → ack"].append(st["tAck"] - st["tSent"])
        res["drag: kernel ms"].append(st.get("kernelMs"))
    res["drag → frame end"] += _to_frame_end(page, [[st["tInput"], st["tPaint"]] for st in pl.STEPS[n0:]])
    if not a.no_slider:
        res["slider"] += pl.slider(page, ex, cv, "angle", a.block)[0]
        # the block's key presses (the slider starts its list again; a listener more each block: one
        # press is stamped once per listener, within a millisecond), the steps' first
        pairs = pl._api(cv, "window.__pgKeys.filter((k, i, ks) => i === 0 || k - ks[i - 1] > 1)"
                            f".slice(0, {a.block}).map(k => [k, p.paintTimes.find(t => t > k)])"
                            ".filter(q => q[1] !== undefined)")
        res["slider → frame end"] += _to_frame_end(page, pairs)


def run(browser, medium: str, tmp: Path, a) -> dict:
    root = tmp / medium
    root.mkdir()
    pl._notebook(root / "page.ipynb", _cells(a.a, a.b, a.every))
    server, url = pl.serve(medium, root, tmp)
    page = browser.new_page(viewport={"width": 1400, "height": 1100})
    res = {k: {"F": [], "F after the steps' pause": [], "drag": [], "slider": [], "drag: ack → painted": [], "drag: sent → ack": [],
               "drag: kernel ms": [], "drag → frame end": [], "slider → frame end": []} for k in "AB"}
    try:
        page.goto(url, wait_until="domcontentloaded", timeout=120_000)
        if medium == "jupyterlab":
            import page_trace

            page.wait_for_function(pl.KERNEL_READY,
                                   timeout=120_000)
            page_trace.open_lab(page)
        ex, cv = pl._canvas(page, pl._titles()["ChainExplorer"])
        page.evaluate(FRAME_END_HOOK)
        box = page.locator(".widget-checkbox input").first
        box.wait_for(state="attached", timeout=120_000)
        time.sleep(1.0)
        pl.drag(page, cv, "link 10 end", 3)
        for r in range(a.rounds):
            for k in ("AB" if r % 2 == 0 else "BA"):
                box.scroll_into_view_if_needed()
                if a.harness_ab:                     # A: the harness polls; B: the page waits
                    pl.WAIT = "poll" if k == "A" else "page"
                elif box.is_checked() != (k == "B"):
                    box.click()
                time.sleep(0.5)
                if a.css:
                    page.evaluate("([on, css]) => { let s = document.getElementById('pg-ab-css');"
                                  " if (!s) { s = document.createElement('style'); s.id = 'pg-ab-css';"
                                  " document.head.appendChild(s); } s.textContent = on ? css : ''; }",
                                  [k == "B", a.css])
                cv.scroll_into_view_if_needed()
                _block(res[k], page, ex, cv, a)
    finally:
        page.close()
        server.stop()
    return {k: {m: pl._stat(v) for m, v in d.items()} for k, d in res.items()}


def _open_lab(browser, tmp: Path, name: str, server_config: dict | None, a):
    import os

    import page_trace

    root = tmp / name
    root.mkdir()
    nb = pl.nbformat.v4.new_notebook()
    nb.cells = [pl.nbformat.v4.new_code_cell(c) for c in _cells("pass", "pass")[:2]]
    nb.metadata["kernelspec"] = {"name": "python3", "display_name": "Python 3", "language": "python"}
    pl.nbformat.write(nb, root / "page.ipynb")
    old = os.environ.get("JUPYTER_CONFIG_PATH")
    if server_config:
        extra = tmp / f"{name}-extra-config"
        extra.mkdir()
        if "_py" in server_config:          # a Python config file's text (JupyterLab's and Voila's)
            (extra / "jupyter_server_config.py").write_text(server_config["_py"])
            (extra / "voila.py").write_text(server_config["_py"])
        else:
            (extra / "jupyter_server_config.json").write_text(json.dumps(server_config))
        os.environ["JUPYTER_CONFIG_PATH"] = str(extra)
    try:
        if a.only == ["voila"]:
            # without the app's config (its config path would hide B's config file)
            server = VoilaServer(root / "page.ipynb", tmp / f"{name}-srv", app_config=False)
        else:
            server = LabServer(root, tmp / f"{name}-srv")
    finally:
        if server_config:
            if old is None:
                os.environ.pop("JUPYTER_CONFIG_PATH", None)
            else:
                os.environ["JUPYTER_CONFIG_PATH"] = old
    page = browser.new_page(viewport={"width": 1400, "height": 1100})
    if a.only == ["voila"]:
        page.goto(server.url, wait_until="domcontentloaded", timeout=120_000)
        ex, cv = pl._canvas(page, pl._titles()["ChainExplorer"])
        page.evaluate(FRAME_END_HOOK)
        return server, page, ex, cv
    page.goto(f"{server.url}/lab/tree/page.ipynb?reset", wait_until="domcontentloaded", timeout=120_000)
    page.wait_for_function(pl.KERNEL_READY,
                           timeout=120_000)
    page_trace.open_lab(page)
    ex, cv = pl._canvas(page, pl._titles()["ChainExplorer"])
    page.evaluate(FRAME_END_HOOK)
    return server, page, ex, cv


def run_two_labs(browser, tmp: Path, a) -> dict:
    """A: a JupyterLab as configured by the harness; B: the same with ``--lab-config-b`` added."""
    res = {k: {"F": [], "F after the steps' pause": [], "drag": [], "slider": [], "drag: ack → painted": [],
               "drag: sent → ack": [], "drag: kernel ms": [], "drag → frame end": [], "slider → frame end": []}
           for k in "AB"}
    opened = {}
    try:
        for k in ("BA" if a.swap else "AB"):      # --swap: B's server and page opened first
            opened[k] = _open_lab(browser, tmp, f"lab{k}", json.loads(a.lab_config_b) if k == "B" else None, a)
        time.sleep(1.0)
        for k in "AB":
            pl.drag(opened[k][1], opened[k][3], "link 10 end", 3)
        for r in range(a.rounds):
            for k in ("AB" if r % 2 == 0 else "BA"):
                _server, page, ex, cv = opened[k]
                page.bring_to_front()
                cv.scroll_into_view_if_needed()
                time.sleep(0.3)
                _block(res[k], page, ex, cv, a)
    finally:
        for server, page, _ex, _cv in opened.values():
            page.close()
            server.stop()
    return {k: {m: pl._stat(v) for m, v in d.items()} for k, d in res.items()}


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--a", default="PictureCanvas.defer = True", help="Python run for the A blocks")
    ap.add_argument("--b", default="PictureCanvas.defer = False", help="Python run for the B blocks")
    ap.add_argument("--css", default=None, help="CSS added to the page in the B blocks")
    ap.add_argument("--only", choices=("voila", "jupyterlab"), action="append")
    ap.add_argument("--rounds", type=int, default=4)
    ap.add_argument("--block", type=int, default=8)
    ap.add_argument("--no-slider", action="store_true")
    ap.add_argument("--every", action="store_true", help="the other eleven explorers in the page too")
    ap.add_argument("--lab-config-b", default=None,
                    help="JSON server config (or a .py config file) added for B: two JupyterLab servers, A and B"
                         " (--a/--b unused)")
    ap.add_argument("--harness-ab", action="store_true",
                    help="A: the harness polls every 5 ms (page_latency.WAIT = 'poll'); B: the page waits ('page')")
    ap.add_argument("--swap", action="store_true", help="with --lab-config-b: open B's server first")
    ap.add_argument("--wait", choices=("page", "poll"), default="poll", help="page_latency.WAIT")
    a = ap.parse_args(argv)
    pl.WAIT = a.wait
    from playwright.sync_api import sync_playwright

    out = {"A": a.a, "B": a.b, "css (B)": a.css}
    with tempfile.TemporaryDirectory() as tmp, sync_playwright() as p:
        browser = launch_chromium(p)
        try:
            for medium in ([] if a.lab_config_b else a.only or ("voila", "jupyterlab")):
                out[medium] = run(browser, medium, Path(tmp), a)
                print(medium, json.dumps(out[medium]), flush=True)
            if a.lab_config_b:
                if Path(a.lab_config_b).suffix == ".py":
                    a.lab_config_b = json.dumps({"_py": Path(a.lab_config_b).read_text()})
                out["lab config (B)"] = json.loads(a.lab_config_b)
                m = "voila" if a.only == ["voila"] else "jupyterlab"
                out[m] = run_two_labs(browser, Path(tmp), a)
                print(m, json.dumps(out[m]), flush=True)
        finally:
            browser.close()
    print(json.dumps(out, indent=1))
    return 0


if __name__ == "__main__":
    sys.exit(main())
