"""Where a page step's time goes: a Chrome trace of chain drag and slider steps, per medium.

Opens the 10-link chain (every overlay) in Voila and in JupyterLab, in headless chromium,
and records, over ``--steps`` drag steps and then ``--steps`` slider steps (each after the
same idle pause as :mod:`page_latency`):

* the renderer main thread's time per step, by what it did: script (split by the script's
  source: the canvas module, Jupyter's and ipywidgets' bundles, the rest), style
  recalculation, layout, paint and compositing, ResizeObserver and IntersectionObserver
  callbacks, garbage collection, message parsing, idle;
* the websocket frames per step in each direction, by Jupyter message type (and, for
  ``comm_msg``, by the widget's method: ``update``, ``custom``, ``echo_update``);
* the step latencies themselves (as :mod:`page_latency` measures them);
* each request (drag step, ping) split by what the page did (:func:`request_steps`): until its
  reply's task, that task, the wait for the frame (and the tasks that ran first, e.g. the
  controls' syncs), and the frame's own work.

The script's source comes from a V8 sampling profile taken over the same steps (self time
of each sample's top frame, by its script's URL); the rest from the trace's events
(self time: an event's duration less that of the events nested in it, on the main thread).

Run::

    MPLBACKEND=Agg .venv/bin/python benchmarks/page_trace.py [--only jupyterlab] [--steps 20] [--out /tmp/pt]

Writes ``<out>/page_trace.json`` (and the raw traces with ``--raw``); prints a table.
"""
from __future__ import annotations

import argparse
import collections
import json
import re
import statistics
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import page_latency as pl  # noqa: E402
from browser_harness import launch_chromium  # noqa: E402

CATEGORIES = ",".join(["devtools.timeline", "disabled-by-default-devtools.timeline", "v8", "blink",
                       "blink.user_timing", "toplevel", "loading", "v8.execute"])

#: Trace event names (by a part of the name) → the bucket their self time counts in; first match wins.
BUCKETS = [
    ("CpuProfiler", "profiler (measurement)"),
    ("ResizeObserver", "ResizeObserver callbacks"), ("NotifyResizeObservers", "ResizeObserver callbacks"),
    ("Intersection", "IntersectionObserver"),
    ("GC", "garbage collection"), ("Major concurrent marking", "garbage collection"),
    ("HitTest", "hit testing"),
    ("Style", "style recalc"), ("recalcStyle", "style recalc"), ("rebuildLayoutTree", "style recalc"),
    ("Layout", "layout"), ("Shape", "layout"), ("SvgText", "layout"), ("InlineNode", "layout"),
    ("Paint", "paint / composite"), ("Composit", "paint / composite"), ("Layerize", "paint / composite"),
    ("CullRect", "paint / composite"), ("Raster", "paint / composite"), ("Commit", "paint / composite"),
    ("UpdateLifecycle", "paint / composite"), ("BeginMainFrame", "paint / composite"),
    ("Receive mojo message", "script (harness's CDP calls, websocket, input)"),
    ("v8.callFunction", "script (harness's CDP calls, websocket, input)"),
    ("FunctionCall", "script"), ("RunMicrotasks", "script"), ("Microtask", "script"), ("v8", "script"),
    ("V8", "script"), ("AsyncTask", "script"), ("TimerFire", "script"), ("FireAnimationFrame", "script"),
    ("AnimationFrame", "script"), ("EventDispatch", "script"), ("serviceScriptedAnimations", "script"),
    ("FrameCallbacks", "script"), ("EvaluateScript", "script"), ("Serialized", "script"),
    ("ParseHTML", "parse HTML"), ("Resource", "network / resources"), ("URLLoader", "network / resources"),
    ("Response", "network / resources"), ("Image", "images"),
    ("RunTask", "task overhead"),
]


def _bucket(name: str) -> str:
    for part, b in BUCKETS:
        if part in name:
            return b
    return "other"


def _source(url: str) -> str:
    u = url or ""
    if not u:
        return "script: harness (Playwright's injected code)"
    if u.startswith("blob:") or u.startswith("data:") or "canvas" in u:
        return "script: canvas.js (anywidget module)"
    if "jupyter-widgets" in u or "ipywidgets" in u or "jupyterlab_widgets" in u or "widgets" in u:
        return "script: ipywidgets / widget manager"
    if "voila" in u:
        return "script: voila bundle"
    if "/static/" in u or "lab" in u:
        return "script: jupyterlab bundles"
    return "script: other (" + u.rsplit("/", 1)[-1][:40] + ")"


def main_thread_buckets(events: list[dict]) -> tuple[dict[str, float], dict[str, float]]:
    """(ms of self time per bucket, ms per top-level task name) on the busiest renderer main thread."""
    mains = {(e["pid"], e["tid"]) for e in events
             if e.get("ph") == "M" and e.get("name") == "thread_name" and e["args"].get("name") == "CrRendererMain"}
    best, busiest = None, -1.0
    for key in mains:
        busy = sum(e.get("dur", 0) for e in events if (e.get("pid"), e.get("tid")) == key and e.get("ph") == "X"
                   and e.get("name") in ("RunTask", "ThreadControllerImpl::RunTask"))
        if busy > busiest:
            best, busiest = key, busy
    evs = [e for e in events if (e.get("pid"), e.get("tid")) == best and e.get("ph") in ("X", "B", "E")]
    # complete events from B/E pairs
    spans, stack = [], []
    for e in sorted(evs, key=lambda e: (e["ts"], 0 if e["ph"] == "E" else 1)):
        if e["ph"] == "X":
            spans.append((e["ts"], e["ts"] + e.get("dur", 0), e["name"], e.get("args", {})))
        elif e["ph"] == "B":
            stack.append(e)
        elif stack:
            b = stack.pop()
            spans.append((b["ts"], e["ts"], b["name"], b.get("args", {})))
    spans.sort(key=lambda s: (s[0], -s[1]))
    self_t: dict[str, float] = collections.defaultdict(float)
    tasks: dict[str, float] = collections.defaultdict(float)
    open_: list[list] = []             # [end, name, child time]
    for t0, t1, name, _args in spans:
        while open_ and open_[-1][0] <= t0:
            end, nm, child, start = open_.pop()
            self_t[nm] += (end - start) - child
        if open_:
            open_[-1][2] += t1 - t0
        else:
            tasks[name] += t1 - t0
        open_.append([t1, name, 0.0, t0])
    while open_:
        end, nm, child, start = open_.pop()
        self_t[nm] += (end - start) - child
    buckets: dict[str, float] = collections.defaultdict(float)
    for name, us in self_t.items():
        buckets[_bucket(name)] += us / 1e3
    return dict(buckets), {k: v / 1e3 for k, v in tasks.items()}


def profile_by_source(profile: dict) -> dict[str, float]:
    """ms of self time per script source in a V8 CPU profile (``Profiler.stop``'s ``profile``)."""
    nodes = {n["id"]: n for n in profile["nodes"]}
    deltas = profile.get("timeDeltas") or []
    out: dict[str, float] = collections.defaultdict(float)
    for sid, dt in zip(profile.get("samples", []), deltas[1:] + [0]):
        n = nodes.get(sid)
        if n is None:
            continue
        cf = n["callFrame"]
        fn = cf.get("functionName", "")
        if fn in ("(idle)", "(program)", "(garbage collector)", "(root)"):
            out[fn] += dt / 1e3
        elif not cf.get("url") and cf.get("lineNumber", -1) < 0:
            out["native calls (DOM, builtins)"] += dt / 1e3
        else:
            out[_source(cf.get("url", ""))] += dt / 1e3
    return dict(out)


def profile_functions(profile: dict, top: int = 25) -> list[tuple[str, float]]:
    """The functions with the most self time: ``(name @ file:line, ms)``."""
    nodes = {n["id"]: n for n in profile["nodes"]}
    deltas = profile.get("timeDeltas") or []
    out: dict[str, float] = collections.defaultdict(float)
    for sid, dt in zip(profile.get("samples", []), deltas[1:] + [0]):
        cf = nodes[sid]["callFrame"]
        if cf.get("functionName") in ("(idle)", "(program)", "(root)"):
            continue
        out[f"{cf.get('functionName') or '(anon)'} @ {cf.get('url', '').rsplit('/', 1)[-1][:50]}:{cf.get('lineNumber')}"] \
            += dt / 1e3
    return sorted(out.items(), key=lambda kv: -kv[1])[:top]


_MSG_TYPE = re.compile(rb'"msg_type"\s*:\s*"([a-z_]+)"')
_METHOD = re.compile(rb'"method"\s*:\s*"([a-z_]+)"')
_CUSTOM = re.compile(rb'"content"\s*:\s*\{.{0,80}?"type"\s*:\s*"([a-z]+)"', re.S)
_STATE = re.compile(rb'"execution_state"\s*:\s*"([a-z]+)"')


def _classify(payload) -> str:
    b = payload.encode() if isinstance(payload, str) else bytes(payload)
    m = _MSG_TYPE.search(b)
    kind = m.group(1).decode() if m else "?"
    if kind == "comm_msg":
        meth = _METHOD.search(b)
        kind += ":" + (meth.group(1).decode() if meth else "?")
        if meth and meth.group(1) == b"custom":
            c = re.search(rb'"data"\s*:\s*\{"method"\s*:\s*"custom"\s*,\s*"content"\s*:\s*\{"type"\s*:\s*"([a-z]+)"', b) \
                or re.search(rb'"type"\s*:\s*"(ack|update|drag|ping|tick|sync|view|describe|halt)"', b)
            kind += ":" + (c.group(1).decode() if c else "?")
    elif kind == "status":
        s = _STATE.search(b)
        kind += ":" + (s.group(1).decode() if s else "?")
    return kind


def _main_thread(events: list[dict]):
    """(pid, tid) of the busiest renderer main thread."""
    mains = {(e["pid"], e["tid"]) for e in events
             if e.get("ph") == "M" and e.get("name") == "thread_name" and e["args"].get("name") == "CrRendererMain"}
    busy: dict = collections.Counter()
    for e in events:
        if (e.get("pid"), e.get("tid")) in mains and e.get("name") == "ThreadControllerImpl::RunTask":
            busy[(e["pid"], e["tid"])] += e.get("dur", 0)
    return busy.most_common(1)[0][0] if busy else None


LIFECYCLE = ("UpdateLayoutTree", "Layout", "PrePaint", "Paint", "Layerize")


def request_steps(events: list[dict], stats: list[dict], origin_ms: float) -> dict:
    """Each request's time split by what the page did, medians over the requests (ms).

    ``stats`` are the page's own timings of the requests (``p.stats``: input, sent, ack,
    painted = the animation frame after the ack, frame end), ``origin_ms`` the page's clock at
    the trace event ``pg-trace-origin`` (a user-timing mark): so each request's moments are found
    on the trace's clock.  Per request: input → the ack's task starts (kernel, server, websocket
    and whatever ran on the page meanwhile), the ack's task (decoding, the widget's dispatch,
    canvas.js's apply), ack task end → painted (the wait for the frame; ``other tasks before the
    frame``: the main thread's other work in it, ``websocket tasks before the frame``: messages
    that came after the ack and ran first, e.g. the controls' syncs), and the frame's own work
    (style, layout, pre-paint, paint, layerize) from painted to frame end.
    """
    main = _main_thread(events)
    mark = [e["ts"] for e in events if e.get("name") == "pg-trace-origin"]
    if main is None or not mark:
        return {}
    off = mark[0] / 1e3 - origin_ms            # trace ms = page ms + off
    evs = sorted((e for e in events if (e.get("pid"), e.get("tid")) == main and e.get("ph") == "X"),
                 key=lambda e: e["ts"])
    tasks = [(e["ts"] / 1e3, (e["ts"] + e.get("dur", 0)) / 1e3) for e in evs
             if e["name"] == "ThreadControllerImpl::RunTask"]
    ws = [e["ts"] / 1e3 for e in evs if e["name"] == "FunctionCall"
          and "onWSMessage" in str((e.get("args", {}).get("data") or {}).get("functionName", ""))]
    life = [(e["ts"] / 1e3, e.get("dur", 0) / 1e3, e["name"]) for e in evs if e["name"] in LIFECYCLE]

    def task_at(t):
        for a, b in tasks:
            if a <= t <= b:
                return a, b
        return t, t

    rows = collections.defaultdict(list)
    for st in stats:
        if not (st.get("tAck") and st.get("tPaint")):
            continue
        t_in, t_ack, t_paint = st["tInput"] + off, st["tAck"] + off, st["tPaint"] + off
        t_frame = st["tFrame"] + off if st.get("tFrame") else None
        a0, a1 = task_at(t_ack)
        rows["input → ack task"].append(a0 - t_in)
        rows["ack task"].append(a1 - a0)
        rows["ack task end → painted"].append(t_paint - a1)
        rows["other tasks before the frame"].append(sum(min(b, t_paint) - max(a, a1) for a, b in tasks
                                                        if b > a1 and a < t_paint and a >= a1))
        rows["websocket tasks before the frame"].append(sum(1 for t in ws if a1 <= t < t_paint))
        if t_frame is not None:
            rows["painted → frame end"].append(t_frame - t_paint)
            for name in LIFECYCLE:
                rows[f"  of which {name}"].append(sum(d for t, d, n in life if n == name and t_paint <= t < t_frame))
    return {k: round(statistics.median(v), 2) for k, v in rows.items() if v}


class Frames:
    """Websocket frames seen by the page, by direction and message type."""

    def __init__(self, page):
        self.log: list[tuple[float, str, str, int]] = []
        page.on("websocket", self._ws)

    def _ws(self, ws):
        ws.on("framesent", lambda p: self.log.append((time.perf_counter(), "page→kernel", _classify(p), len(p))))
        ws.on("framereceived", lambda p: self.log.append((time.perf_counter(), "kernel→page", _classify(p), len(p))))

    def count(self, t0: float, t1: float, steps: int) -> dict[str, float]:
        c = collections.Counter(f"{d} {k}" for t, d, k, _n in self.log if t0 <= t <= t1)
        return {k: round(v / steps, 2) for k, v in sorted(c.items())}

    def sizes(self, t0: float, t1: float, steps: int) -> dict[str, float]:
        c = collections.Counter()
        for t, d, _k, n in self.log:
            if t0 <= t <= t1:
                c[d] += n
        return {k: round(v / steps / 1024, 1) for k, v in c.items()}


def traced(page, cv, what, steps: int) -> dict:
    """Run ``what()`` under a trace and a CPU profile; per-step breakdowns."""
    cdp = page.context.new_cdp_session(page)
    chunks: list[dict] = []
    done = []
    cdp.on("Tracing.dataCollected", lambda p: chunks.extend(p["value"]))
    cdp.on("Tracing.tracingComplete", lambda p: done.append(1))
    cdp.send("Profiler.enable")
    cdp.send("Profiler.setSamplingInterval", {"interval": 100})
    cdp.send("Tracing.start", {"categories": CATEGORIES, "transferMode": "ReportEvents"})
    cdp.send("Profiler.start")
    t0 = time.perf_counter()
    pw0 = page.evaluate("performance.mark('pg-trace-origin').startTime")   # the two clocks met
    n_stats = pl._api(cv, "p.stats.length")
    lat = what()
    stats = pl._api(cv, f"p.stats.slice({n_stats})")
    pw1 = page.evaluate("performance.now()")
    t1 = time.perf_counter()
    prof = cdp.send("Profiler.stop")["profile"]
    cdp.send("Tracing.end")
    for _ in range(600):
        if done:
            break
        page.wait_for_timeout(50)
    cdp.detach()
    buckets, tasks = main_thread_buckets(chunks)
    src = profile_by_source(prof)
    wall = pw1 - pw0
    return {"latency": pl._stat(lat), "wall per step (ms)": round(wall / steps, 1),
            "main thread self time per step (ms)": {k: round(v / steps, 2) for k, v in
                                                     sorted(buckets.items(), key=lambda kv: -kv[1]) if v / steps >= 0.05},
            "top-level tasks per step (ms)": {k: round(v / steps, 2) for k, v in
                                              sorted(tasks.items(), key=lambda kv: -kv[1]) if v / steps >= 0.05},
            "script by source per step (ms, sampled)": {k: round(v / steps, 2) for k, v in
                                                        sorted(src.items(), key=lambda kv: -kv[1])},
            "top functions (ms per step)": [(k, round(v / steps, 2)) for k, v in profile_functions(prof)],
            "each request, by what the page did (ms, median)": request_steps(chunks, stats, pw0),
            "_t": (t0, t1), "_raw": {"trace": chunks, "profile": prof}}


def open_lab(page) -> None:
    """Run the notebook's cells once the kernel is idle (again if nothing shows within a minute)."""
    for _attempt in range(3):
        for _ in range(1200):
            if page.evaluate("window.jupyterapp.shell.currentWidget.sessionContext.session.kernel.status") == "idle":
                break
            page.wait_for_timeout(100)
        page.evaluate("window.jupyterapp.commands.execute('notebook:run-all-cells')")
        try:
            page.locator(".pg-canvas").first.wait_for(state="attached", timeout=60_000)
            return
        except Exception:  # noqa: BLE001 - a run that did not start: once more
            page.screenshot(path="/tmp/page_trace_lab.png")


def run_medium(browser, medium: str, steps: int, tmp: Path, raw: Path | None,
               drag_sync_s: float | None = None) -> dict:
    root = tmp / medium
    root.mkdir()
    cells = list(pl.CELLS[:2])
    if drag_sync_s is not None:     # the chain's drag_sync_s (0: controls and readout with every step)
        cells[1] = cells[1].replace("\nchain", f"\nchain.drag_sync_s = {drag_sync_s!r}\nchain")
    pl._notebook(root / "page.ipynb", cells)
    server, url = pl.serve(medium, root, tmp)
    page = browser.new_page(viewport={"width": 1400, "height": 1100})
    frames = Frames(page)
    out = {}
    try:
        page.goto(url, wait_until="domcontentloaded", timeout=120_000)
        if medium == "jupyterlab":
            page.wait_for_function(
                pl.KERNEL_READY, timeout=120_000)
            open_lab(page)
        ex, cv = pl._canvas(page, pl._titles()["ChainExplorer"])
        time.sleep(1.5)
        pl.drag(page, cv, "link 10 end", 4)          # warm up both paths
        pl.slider(page, ex, cv, "angle", 2)
        f = pl.floor(cv, steps)
        out["F"] = pl._stat(f)
        for label, what in (("drag", lambda: pl.drag(page, cv, "link 10 end", steps)[0]),
                            ("slider", lambda: pl.slider(page, ex, cv, "angle", steps)[0]),
                            ("ping", lambda: pl.floor(cv, steps))):
            r = traced(page, cv, what, steps)
            t0, t1 = r.pop("_t")
            rawd = r.pop("_raw")
            r["websocket frames per step"] = frames.count(t0, t1, steps)
            r["websocket KB per step"] = frames.sizes(t0, t1, steps)
            out[label] = r
            if raw is not None:
                raw.mkdir(parents=True, exist_ok=True)
                (raw / f"{medium}-{label}.trace.json").write_text(json.dumps({"traceEvents": rawd["trace"]}))
                (raw / f"{medium}-{label}.cpuprofile").write_text(json.dumps(rawd["profile"]))
    finally:
        page.close()
        server.stop()
    return out


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--steps", type=int, default=20)
    ap.add_argument("--only", choices=("voila", "jupyterlab"), action="append")
    ap.add_argument("--out", type=Path, default=Path("/tmp/page_trace"))
    ap.add_argument("--raw", action="store_true", help="also write the raw traces and CPU profiles")
    ap.add_argument("--drag-sync-s", type=float, default=None,
                    help="the chain's drag_sync_s (default: the explorer's; 0: syncs with every drag step)")
    ap.add_argument("--wait", choices=("page", "poll"), default="page",
                    help="page_latency.WAIT (page: the harness's polling stays out of the trace)")
    a = ap.parse_args(argv)
    pl.WAIT = a.wait
    from playwright.sync_api import sync_playwright

    res = {}
    with tempfile.TemporaryDirectory() as tmp, sync_playwright() as p:
        browser = launch_chromium(p)
        try:
            for medium in a.only or ("voila", "jupyterlab"):
                res[medium] = run_medium(browser, medium, a.steps, Path(tmp), a.out / "raw" if a.raw else None,
                                         a.drag_sync_s)
        finally:
            browser.close()
    a.out.mkdir(parents=True, exist_ok=True)
    (a.out / "page_trace.json").write_text(json.dumps(res, indent=1) + "\n")
    print(json.dumps(res, indent=1))
    return 0


if __name__ == "__main__":
    sys.exit(main())
