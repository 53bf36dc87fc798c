"""Page latency: explorers drawn by the browser (``display="page"``), in JupyterLab and in Voila.

Measured in Debian's headless chromium, in the same run and through the same widget
(:class:`planargeo.widgets.canvas.PictureCanvas`), in each medium:

* **F, the floor**: an empty request from the page to the kernel and back (``ping``),
  doing no work; the machine's and Jupyter's share of every step;
* for the **10-link chain with every overlay on**:

  - **drag step**: a 3 px mouse move on the end of link 10 → the picture with the new
    geometry painted (the page's own clock: input event to the animation frame after
    the reply);
  - **handle repaint**: the mouse move → the dragged handle painted at the pointer
    (the page alone, no kernel);
  - **slider step**: a key press on the ``angle`` slider (every element moves; from the
    key's ``keydown`` event in the page) → the new picture painted; and the page's time
    to apply that picture;
  - **Play**: the Play button pressed at 1×; frames painted per second over 10 s (one per
    animation frame that shows a new picture), and the time scale (seconds of motion per
    second of wall clock, read off the picture's ``t = … s``);

* **every explorer's drag step** (its first handle inside the view, 3 px moves), all twelve
  explorers shown in one page (the Voila app; in JupyterLab, one notebook holding all of them);
* in JupyterLab also **each explorer in a notebook of its own**, as a lesson shows one (the
  lessons hold 1-3 explorers each): F and the drag step there (and the chain's slider step),
  each notebook's kernel shut down before the next opens;

  every drag and slider step starts after the page has been idle for the same
  :data:`PAUSE` (0.03 s), and F is also measured after that pause ("F, paused": a ping
  sent as soon as the last reply arrived can wait for the server and kernel, e.g. ~35 ms
  more in Voila on a loaded machine, 2026-11-27; :data:`WAIT`).  Where JupyterLab's extra
  time goes is measured by ``page_trace.py`` and A/B'd by ``page_ab.py``: JupyterLab works
  on every kernel busy/idle pair (favicon swap and fetch, the toolbar's kernel status and a
  forced layout, about 10 ms of main thread per pair), and its kernel websocket holds small
  messages for the browser's delayed ACK (Nagle's algorithm). ``make lab``, ``make app`` and
  the servers measured here switch that off (:mod:`planargeo.widgets.server`); Jupyter's
  default is A/B'd by ``page_ab.py --lab-config-b '{"ServerApp": {"kernel_websocket_connection_class":
  "jupyter_server.services.kernels.connection.channels.ZMQChannelsWebsocketConnection"}}'``;
* **Play** also records the kernel's milliseconds per frame (``ms`` in each tick's
  ack) and the tick's round trip, to tell the kernel's share from the messaging's;
* the **Python side** of one chain update (compute, picture, the update message) and
  the size of the messages, in this process.

Medians and 90th percentiles of ``--steps`` steps go to ``<out>/page_latency.{json,md}``
with the load average of the machine while it ran.

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
CHAIN = "10-link chain, all overlays"
CELLS = [
    "import planargeo.widgets as pw",
    "chain = pw.ChainExplorer(display='page', links=10, **{k: True for k in %r})\nchain" % (OVERLAYS,),
    "others = {n: getattr(pw, n)(display='page') for n in pw.EXPLORERS if n != 'ChainExplorer'}",
] + [f"others[{n!r}]" for n in ("ProjectiveExplorer", "PercussionExplorer", "ScrewSumExplorer", "CarExplorer",
                                "SliderCrankExplorer", "TreeExplorer", "SubspaceExplorer", "ImpulseExplorer",
                                "ConstructionExplorer", "ArticulatedExplorer", "SplittingExplorer")]


#: The floor measured after the same idle pause as the steps (a ping sent as soon as the last
#: reply arrived waits for whatever the kernel still does after a reply).
PAUSED_F = "F after the steps' pause"

#: Every drag step's timings in the page (input, sent, ack, applied, painted; the kernel's ms), in order.
STEPS: list[dict] = []

#: Seconds the page is left idle before each drag or slider step (the same for both).
PAUSE = 0.03


def _titles() -> dict[str, str]:
    """``{explorer class name: its title}`` (how the page's explorers are told apart)."""
    import planargeo.widgets as pw

    return {n: getattr(pw, n).title for n in pw.EXPLORERS}


#: true once JupyterLab's current notebook has a kernel (the page can be driven)
KERNEL_READY = ("window.jupyterapp && window.jupyterapp.shell.currentWidget"
                " && window.jupyterapp.shell.currentWidget.sessionContext.session"
                " && window.jupyterapp.shell.currentWidget.sessionContext.session.kernel")


def _notebook(path: Path, cells=None) -> None:
    nb = nbformat.v4.new_notebook()
    nb.cells = [nbformat.v4.new_code_cell(c) for c in (CELLS if cells is None else cells)]
    nb.metadata["kernelspec"] = {"name": "python3", "display_name": "Python 3", "language": "python"}
    nbformat.write(nb, path)


def serve(medium: str, root: Path, tmp: Path):
    """Serve ``root/page.ipynb`` in ``medium``: the server and the URL of the page."""
    if medium == "voila":
        server = VoilaServer(root / "page.ipynb", tmp / f"{medium}-srv")
        return server, server.url
    server = LabServer(root, tmp / f"{medium}-srv")
    return server, f"{server.url}/lab/tree/page.ipynb?reset"


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
    for _ in range(600):                  # the first picture drawn (synced with the kernel)
        if _api(cv, "p.elements() > 0 && !p.busy()"):
            break
        time.sleep(0.05)
    return ex, cv


#: How the harness waits for the page: ``"poll"`` (it asks every 5 ms through the canvas's
#: locator) or ``"page"`` (one call that the page answers when the step is done, checking on a
#: 2 ms timer).  Each question runs in the page's main thread, but A/B runs (page_ab.py
#: --harness-ab, 2026-11-27) showed no step made slower by polling: with "page" the reply's
#: paint came 2-5 ms later and an F ping sent within a millisecond of the last reply waited
#: ~35 ms more (Voila and JupyterLab), so "poll" stays the default.
WAIT = "poll"


def _api(cv, expr: str):
    return cv.evaluate(f"(el) => {{ const p = el.__planargeo; return {expr}; }}")


def _until(cv, expr: str, timeout_ms: float = 5000.0):
    """The value of ``expr`` (in the page, ``p``: the canvas API) once it is truthy (None: timed out).

    With :data:`WAIT` ``"page"`` the page checks it every 2 ms and answers when it holds (one
    call, no polling from here); with ``"poll"`` the harness asks every 5 ms.
    """
    if WAIT == "poll":
        for _ in range(int(timeout_ms / 5)):
            v = _api(cv, expr)
            if v:
                return v
            time.sleep(0.005)
        return None
    return cv.evaluate(
        "(el, lim) => new Promise((res) => { const p = el.__planargeo, t0 = performance.now();"
        f" const f = () => {{ let v; try {{ v = ({expr}); }} catch (e) {{ v = null; }}"
        " if (v) res(v); else if (performance.now() - t0 > lim) res(null); else setTimeout(f, 2); };"
        " f(); })", timeout_ms)


def _fast(cv):
    """The canvas as the harness addresses it: with :data:`WAIT` ``"page"`` its element, found once
    (a locator is found again, through its text filter, at every question)."""
    return cv.element_handle() if WAIT == "page" and hasattr(cv, "element_handle") else cv


def _wait_idle(cv) -> None:
    _until(cv, "!p.busy()", 4000.0)


def floor(cv, steps: int, pause: float = 0.0) -> list[float]:
    cv, out = _fast(cv), []
    for _ in range(steps):
        _wait_idle(cv)
        time.sleep(pause)
        n = _api(cv, "p.stats.length")
        _api(cv, "p.ping()")
        s = _until(cv, f"p.stats.length > {n} && p.stats[p.stats.length - 1].tAck"
                       " ? p.stats[p.stats.length - 1] : null", 2500.0)
        if s:
            out.append(s["tAck"] - s["tSent"])
    return out


def _handle_inside(cv, handle: str | None):
    """The handle's circle: the named one, or the first well inside the view."""
    if handle is not None:
        return cv.locator(f"circle[data-handle='{handle}']").first
    svg = cv.locator("svg").first.bounding_box()
    circles = cv.locator("circle.pg-handle")
    for j in range(circles.count()):
        b = circles.nth(j).bounding_box()
        if b and svg["x"] + 30 < b["x"] < svg["x"] + svg["width"] - 40 and \
                svg["y"] + 30 < b["y"] < svg["y"] + svg["height"] - 40:
            return circles.nth(j)
    return None


def drag(page, cv, handle: str | None, steps: int, px: float = 3.0, pause: float = PAUSE):
    """(drag step latencies, handle repaints, refused steps, the handle's id)."""
    circle = _handle_inside(cv, handle)
    if circle is None:
        return [], [], 0, None
    hid = circle.get_attribute("data-handle")
    circle.scroll_into_view_if_needed()
    box = circle.bounding_box()
    x, y = box["x"] + box["width"] / 2, box["y"] + box["height"] / 2
    page.mouse.move(x, y)
    page.mouse.down()
    lat, refused = [], 0
    cv = _fast(cv)
    n0 = _api(cv, "p.handlePaints.length")
    for k in range(steps):
        _wait_idle(cv)
        time.sleep(pause)
        n = _api(cv, "p.stats.length")
        x += px if (k // 8) % 2 == 0 else -px
        page.mouse.move(x, y)
        s = _until(cv, f"p.stats.length > {n} && p.stats[{n}].tPaint ? p.stats[{n}] : null")
        if s:
            lat.append(s["tPaint"] - s["tInput"])
            STEPS.append(s)
        refused += bool(_api(cv, "p.status()"))
    page.mouse.up()
    _wait_idle(cv)
    return lat, _api(cv, f"p.handlePaints.slice({n0})"), refused, hid


def slider(page, ex, cv, name: str, steps: int, pause: float = PAUSE) -> tuple[list[float], list[float]]:
    """(slider step latencies, the page's time to apply each new picture), ms.

    A step runs from the key's ``keydown`` event in the page (as a drag step runs from
    the pointer's move event) to the animation frame after the new picture was applied.
    """
    sl = ex.locator(".widget-slider").filter(has_text=name).first
    knob = sl.locator(".noUi-handle").first
    knob.scroll_into_view_if_needed()
    knob.focus()
    knob.evaluate("(el) => { window.__pgKeys = []; el.addEventListener('keydown', "
                  "() => window.__pgKeys.push(performance.now()), true); }")
    out, applied, net = [], [], 0
    cv = _fast(cv)
    for k in range(steps):
        _wait_idle(cv)
        time.sleep(pause)
        n_keys = page.evaluate("window.__pgKeys.length")
        n_apply = _api(cv, "(p.applyTimes || []).length")
        right = (k // 5) % 2 == 0
        page.keyboard.press("ArrowRight" if right else "ArrowLeft")
        net += 1 if right else -1
        got = _until(cv, f"window.__pgKeys.length > {n_keys}"
                         f" && p.paintTimes.find(t => t > window.__pgKeys[{n_keys}])"
                         f" ? [window.__pgKeys[{n_keys}], p.paintTimes.find(t => t > window.__pgKeys[{n_keys}])]"
                         " : null")
        if got:
            out.append(got[1] - got[0])
            applied += _api(cv, f"(p.applyTimes || []).slice({n_apply})")
    for _ in range(abs(net)):
        time.sleep(0.25)
        page.keyboard.press("ArrowLeft" if net > 0 else "ArrowRight")
    return out, applied


def _shown_time(cv) -> float | None:
    text = _api(cv, "p.text('time')")
    try:
        return float(text.split("=")[1].split()[0])
    except (AttributeError, IndexError, ValueError):
        return None


def play(ex, cv, seconds: float = 10.0) -> dict:
    """Play at 1× for ``seconds``: frames painted per second and seconds of motion per second."""
    cv.scroll_into_view_if_needed()
    button = ex.locator(".widget-play button").first
    button.scroll_into_view_if_needed()
    button.click()                                     # play
    for _ in range(600):                               # past the start (a first motion may compile)
        t = _shown_time(cv)
        if t is not None and t > 0.3:
            break
        time.sleep(0.1)
    time.sleep(0.5)
    t0, sim0, pushed0 = cv.evaluate("() => performance.now()"), _shown_time(cv), _api(cv, "p.pushed ? p.pushed() : 0")
    time.sleep(seconds)
    t1, sim1, pushed1 = cv.evaluate("() => performance.now()"), _shown_time(cv), _api(cv, "p.pushed ? p.pushed() : 0")
    frames = _api(cv, f"p.paintTimes.filter(t => t > {t0} && t <= {t1}).length")
    gaps = _api(cv, f"p.paintTimes.filter(t => t > {t0} && t <= {t1})")
    ticks = _api(cv, f"p.stats.filter(s => s.type === 'tick' && s.tSent > {t0} && s.tAck && s.tSent <= {t1})"
                     ".map(s => [s.tAck - s.tSent, s.kernelMs ?? null])")
    button.click()                                     # pause
    _wait_idle(cv)
    wall = (t1 - t0) / 1e3
    d = [b - a for a, b in zip(gaps, gaps[1:])]
    return {"fps": round(frames / wall, 1), "frames": frames, "wall (s)": round(wall, 2),
            "frames sent alone per second": round((pushed1 - pushed0) / wall, 1),
            "time scale": round((sim1 - sim0) / wall, 3) if sim0 is not None and sim1 is not None else None,
            "frame gap median (ms)": round(statistics.median(d), 1) if d else None,
            "frame gap p90 (ms)": round(sorted(d)[int(0.9 * (len(d) - 1))], 1) if d else None,
            "tick round trip (ms)": _stat([a for a, _k in ticks]),
            "kernel per tick (ms)": _stat([k for _a, k in ticks])}


def measure(page, steps: int) -> dict:
    titles = _titles()
    ex, cv = _canvas(page, titles["ChainExplorer"])
    time.sleep(1.0)
    r = {"F (ping round trip)": _stat(floor(cv, steps)), PAUSED_F: _stat(floor(cv, steps, PAUSE))}
    lat, hp, refused, _ = drag(page, cv, "link 10 end", steps)
    r["drag step"], r["handle repaint"] = _stat(lat), _stat(hp)
    lat, applied = slider(page, ex, cv, "angle", steps)
    r["slider step"], r["slider: page applies the picture"] = _stat(lat), _stat(applied)
    r["play"] = play(ex, cv)
    r["F after (ping round trip)"] = _stat(floor(cv, steps))
    res = {CHAIN: r, "every explorer": {}}
    for name, title in titles.items():
        if name == "ChainExplorer":
            continue
        try:
            ex, cv = _canvas(page, title)
            lat, _hp, refused, hid = drag(page, cv, None, steps)
            res["every explorer"][name] = {"drag step": _stat(lat), "handle": hid, "refused": refused}
        except Exception as exc:  # noqa: BLE001 - one explorer's failure is reported, not fatal
            res["every explorer"][name] = {"drag step": _stat([]), "error": f"{type(exc).__name__}: {exc}"[:200]}
    res["every explorer"]["ChainExplorer"] = {"drag step": r["drag step"], "handle": "link 10 end",
                                              "refused": refused}
    return res


def _own_cells(name: str) -> list[str]:
    """A notebook of one explorer (the chain with 10 links and every overlay, as in :data:`CELLS`)."""
    extra = ", links=10, **{k: True for k in %r}" % (OVERLAYS,) if name == "ChainExplorer" else ""
    return ["import planargeo.widgets as pw", f"ex = pw.{name}(display='page'{extra})\nex"]


def _shut_down(page) -> None:
    """Shut the current notebook's kernel down (JupyterLab), so that it takes no part in what follows."""
    try:
        page.evaluate("window.jupyterapp.shell.currentWidget.sessionContext.shutdown()")
    except Exception:  # noqa: BLE001 - a page that is gone has no kernel to stop
        pass


def measure_own(browser, server, root: Path, steps: int) -> dict:
    """Each explorer alone in a notebook of its own (JupyterLab): F, its drag step, the chain's slider step."""
    out = {}
    for name, title in _titles().items():
        chain = name == "ChainExplorer"
        _notebook(root / f"own-{name}.ipynb", _own_cells(name))
        page = browser.new_page(viewport={"width": 1400, "height": 1100})
        try:
            page.goto(f"{server.url}/lab/tree/own-{name}.ipynb?reset", wait_until="domcontentloaded",
                      timeout=120_000)
            page.wait_for_function(KERNEL_READY, timeout=120_000)
            page.evaluate("window.jupyterapp.commands.execute('notebook:run-all-cells')")
            ex, cv = _canvas(page, title)
            time.sleep(1.0)
            r = {"F": _stat(floor(cv, steps, PAUSE))}
            lat, _hp, refused, hid = drag(page, cv, "link 10 end" if chain else None, steps)
            r.update({"drag step": _stat(lat), "handle": hid, "refused": refused})
            if chain:
                r["slider step"] = _stat(slider(page, ex, cv, "angle", steps)[0])
            out[name] = r
        except Exception as exc:  # noqa: BLE001 - one explorer's failure is reported, not fatal
            out[name] = {"drag step": _stat([]), "error": f"{type(exc).__name__}: {exc}"[:200]}
        finally:
            _shut_down(page)
            page.close()
    return out


def python_side(repeat: int = 25) -> dict:
    """One chain update in this process: the drag step and the slider step, and their messages."""
    from planargeo.widgets import ChainExplorer

    ex = ChainExplorer(display="page", links=10, **{k: True for k in OVERLAYS})
    sent = []
    ex.canvas.send = lambda m, *a, **k: sent.append(m)
    h = next(h for h in ex.canvas.picture["handles"] if h["id"] == "link 10 end")
    out = {}
    for label, act in (("drag step", lambda k: ex.canvas._on_msg(
            None, {"type": "drag", "id": "link 10 end", "x": h["x"] + 0.01 * (k % 5), "y": h["y"], "seq": k}, None)),
                       ("slider step", lambda k: setattr(ex.controls["angle"], "value", -30.0 + (k % 7)))):
        for k in range(5):
            act(k)
        ts, wall, sizes = [], [], []
        for k in range(repeat):
            del sent[:]
            t0, c0 = time.perf_counter(), time.process_time()
            act(k)
            wall.append((time.perf_counter() - t0) * 1e3)
            ts.append((time.process_time() - c0) * 1e3)
            sizes.append(sum(len(json.dumps(m, separators=(",", ":"))) for m in sent))
        out[label] = {"update (ms)": round(statistics.median(wall), 2),
                      "update, CPU (ms)": round(statistics.median(ts), 2),
                      "message (KB)": round(statistics.median(sizes) / 1024, 1)}
    t1 = time.perf_counter()
    for _ in range(repeat):
        ex.picture()
    out["picture (ms)"] = round((time.perf_counter() - t1) / repeat * 1e3, 2)
    snapshot = json.dumps(ex.canvas._snapshot(), separators=(",", ":"))
    out["whole picture, first view (KB)"] = round(len(snapshot) / 1024, 1)
    out["picture dict (KB)"] = round(len(json.dumps(ex.canvas.picture)) / 1024, 1)
    out["elements"] = len(ex.canvas.picture["elements"])
    return out


def _cell(s) -> str:
    return f"{s['median']} ({s['p90']})" if s and s.get("median") is not None else "—"


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

    load0 = os.getloadavg()
    results = {"python": python_side()}
    with tempfile.TemporaryDirectory() as tmp, sync_playwright() as p:
        tmp = Path(tmp)
        browser = launch_chromium(p)
        try:
            for medium in a.only or ("voila", "jupyterlab"):
                root = tmp / medium
                root.mkdir()
                _notebook(root / "page.ipynb")
                server, url = serve(medium, root, tmp)
                page = browser.new_page(viewport={"width": 1400, "height": 1100})
                try:
                    page.goto(url, wait_until="domcontentloaded", timeout=120_000)
                    if medium == "jupyterlab":
                        page.wait_for_function(
                            KERNEL_READY,
                            timeout=120_000)
                        page.evaluate("window.jupyterapp.commands.execute('notebook:run-all-cells')")
                    results[medium] = measure(page, a.steps)
                    if medium == "jupyterlab":
                        _shut_down(page)
                        page.close()
                        page = None
                        results[medium]["own notebook"] = measure_own(browser, server, root, a.steps)
                finally:
                    if page is not None:
                        page.close()
                    server.stop()
        finally:
            browser.close()
    load1 = os.getloadavg()
    results["when"] = datetime.datetime.now().isoformat(timespec="seconds")
    results["machine"] = f"{platform.machine()}, {os.cpu_count()} cores, {platform.python_version()}"
    results["load average (1 min) at start, end"] = [round(load0[0], 2), round(load1[0], 2)]
    media = a.only or ("voila", "jupyterlab")
    lines = ["# Page latency: explorers drawn by the browser", "",
             f"{results['when']}, {results['machine']}, load average {load0[0]:.2f} at the start and "
             f"{load1[0]:.2f} at the end; medians (90th percentiles) of {a.steps} steps, ms.",
             "F is the round trip of an empty request through the same widget (the floor), measured "
             "before and after the chain's steps, each request sent as soon as the last reply arrived; "
             f"F, paused: the same after the page was idle for {PAUSE} s, as before each drag and slider step.", "",
             f"## {CHAIN}", "",
             "| medium | F | F, paused | drag step | handle repaint | slider step | (page applies it) | F after |",
             "|---|---|---|---|---|---|---|---|"]
    for m in media:
        r = results[m][CHAIN]
        lines.append(f"| {m} | {_cell(r['F (ping round trip)'])} | {_cell(r.get(PAUSED_F))} | "
                     f"{_cell(r['drag step'])} | "
                     f"{_cell(r['handle repaint'])} | {_cell(r['slider step'])} | "
                     f"{_cell(r.get('slider: page applies the picture'))} | "
                     f"{_cell(r['F after (ping round trip)'])} |")
    own = results.get("jupyterlab", {}).get("own notebook", {})
    if own.get("ChainExplorer", {}).get("F"):
        r = own["ChainExplorer"]
        lines.append(f"| jupyterlab, the chain in a notebook of its own | — | {_cell(r['F'])} | "
                     f"{_cell(r['drag step'])} | — | {_cell(r.get('slider step'))} | — | — |")
    lines += ["", "Play at 1× for 10 s (frames painted per second; seconds of motion per second of wall clock):", "",
              "| medium | fps | frames | time scale | frame gap median (p90), ms | frames sent alone per s "
              "| tick round trip | kernel per tick |",
              "|---|---|---|---|---|---|---|---|"]
    for m in media:
        q = results[m][CHAIN]["play"]
        lines.append(f"| {m} | {q['fps']} | {q['frames']} | {q['time scale']} | "
                     f"{q['frame gap median (ms)']} ({q['frame gap p90 (ms)']}) | "
                     f"{q.get('frames sent alone per second', '—')} | {_cell(q.get('tick round trip (ms)'))} | "
                     f"{_cell(q.get('kernel per tick (ms)'))} |")
    lines += ["", "## Drag step of every explorer", "",
              "All twelve in one page (the Voila app; one JupyterLab notebook)"
              + ("; and in JupyterLab each in a notebook of its own, with that notebook's F (paused)"
                 if own else "") + ".", "",
              "| explorer | handle | " + " | ".join(media) + (" | jupyterlab, own notebook | its F |" if own else " |"),
              "|---|---|" + "---|" * (len(media) + 2 * bool(own))]
    for name in _titles():
        cells = []
        hid = None
        for m in media:
            e = results[m]["every explorer"].get(name, {})
            hid = hid or e.get("handle")
            note = f" ({e['refused']} refused)" if e.get("refused") else ""
            cells.append(_cell(e.get("drag step")) + note if "error" not in e else "error: " + e["error"][:60])
        if own:
            e = own.get(name, {})
            cells += [_cell(e.get("drag step")) if "error" not in e else "error: " + e["error"][:60],
                      _cell(e.get("F"))]
        lines.append(f"| {name} | {hid or '—'} | " + " | ".join(cells) + " |")
    py = results["python"]
    lines += ["", "## Python side of one chain update (this process)", "",
              "| step | update (ms) | CPU (ms) | message (KB) |", "|---|---|---|---|"]
    for k in ("drag step", "slider step"):
        lines.append(f"| {k} | {py[k]['update (ms)']} | {py[k]['update, CPU (ms)']} | {py[k]['message (KB)']} |")
    lines += ["", f"The picture alone: {py['picture (ms)']} ms; {py['elements']} elements; the whole picture a "
              f"newly opened view gets: {py['whole picture, first view (KB)']} KB (the picture's dict, with "
              f"descriptions: {py['picture dict (KB)']} KB).", "",
              "Goals (issue 21): drag and slider steps ≤ F + 15 ms (≤ 40 ms where F ≤ 25 ms); handle repaint "
              "≤ 20 ms; every explorer's drag step ≤ F + 15 ms; Play ≥ 30 fps at 1×; Python side ≤ 5 ms "
              "and message ≤ 20 KB for the chain."]
    a.out.mkdir(parents=True, exist_ok=True)
    atomic_write_many({a.out / "page_latency.json": json.dumps(results, indent=1) + "\n",
                       a.out / "page_latency.md": "\n".join(lines) + "\n"})
    print("\n".join(lines))
    return 0


if __name__ == "__main__":
    sys.exit(main())
