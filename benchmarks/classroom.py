"""A classroom's load: k visitors of ``make app`` at once, each dragging and pressing Play.

The app (``app/planargeo-app.ipynb``) is served as ``make app`` serves it (Voila with
``app/config/voila.py``, 127.0.0.1 only, a free port) but with no seat limit, and k
visitors (k = 1, 5, 10, 20) open it, arriving ``ARRIVAL_S`` = 2 s apart, each in its own
browser context (own cookies, own page processes) of one headless Chromium.  Voila starts one kernel
per visitor, which runs the whole app notebook (every explorer).  When every page shows
all its explorers, all visitors at once

1. drag the end of the last link of the chain explorer ("A chain in motion") by 3-px
   mouse moves, each step waiting for its picture (:func:`drag_steps`: the time from the
   mouse move to the paint of the picture that move asked for, page clock, read from the
   canvas's own timings, ``planargeo/widgets/canvas.js``);
2. press Play on the same explorer and count the pictures the page paints in a fixed
   time, then press Pause.

Memory is read with psutil while every page is still open: each kernel's RSS and PSS
(the kernels are the Voila server's child processes), the server's own RSS, the
browser's PSS beyond that of the empty browser (every chromium process), and the drop of the
machine's available memory, per visitor.

The machine is **full** at the smallest k where one of these holds: the 90th
percentile of the drag step exceeds 1 s; a visitor's page is not ready within the
time limit or a tenth of the drag steps get no picture within 10 s; or the kernels'
memory (PSS per visitor times k) would exceed 80 % of the machine's memory.  ``k_max``,
the default seat count of ``make app``, is the largest measured k below full.

Here the browsers run on the same machine as the kernels and take CPU from them; in
a classroom they run on the visitors' own computers, so these latencies are an upper
bound for a server with this CPU.  The kernels' CPU time per phase (opening, a drag
step, a second of Play) gives an estimate for a machine that does nothing else
(:func:`estimate`).  Memory and time are bounded: a k is tried only if it fits in the
available memory, the browser is stopped if available memory falls under 2 GiB, and
each phase has a time limit.

Run::

    .venv/bin/python benchmarks/classroom.py [--ks 1,5,10,20] [--steps 20] [--play 10] [--out benchmarks/results]
    .venv/bin/python benchmarks/classroom.py --quick      # k = 1, 2; a few steps (about two minutes)
"""
from __future__ import annotations

import argparse
import datetime
import json
import math
import os
import platform
import re
import statistics
import subprocess
import sys
import tempfile
import threading
import time
from pathlib import Path

import nbformat

sys.path.insert(0, str(Path(__file__).resolve().parent))
from browser_harness import CHROMIUM, CHROMIUM_ARGS, VoilaServer  # noqa: E402

from planargeo.files import atomic_write_many  # noqa: E402

REPO = Path(__file__).resolve().parents[1]
APP = REPO / "app" / "planargeo-app.ipynb"
APP_CONFIG = REPO / "app" / "config"
CELL = re.compile(r"^pw\.(\w+)\(\)$")
#: the explorer every visitor drags and plays
EXPLORER = "ChainExplorer"
#: "full": the drag step's 90th percentile above this (ms) ...
FULL_P90_MS = 1000.0
#: ... or more than this share of drag steps without a picture within 10 s ...
FULL_MISSED = 0.10
#: ... or the kernels would take more than this share of the machine's memory
FULL_MEMORY = 0.80
VIEWPORT = {"width": 1400, "height": 1000}
#: stop a run when the machine's available memory falls below this (MiB)
MEMORY_FLOOR_MB = 2048
#: a k is tried only if k visitors (kernel and browser, as measured at the previous k) fit in
#: the available memory less this margin (MiB)
MEMORY_MARGIN_MB = 4096
#: seconds between two visitors' arrivals (a class opening the page within a minute)
ARRIVAL_S = 2.0


# --------------------------------------------------------------------------- the server
def serve_app(tmp: Path, seats: int = 0, idle: float | None = None,
              notebook: Path = APP, cull_interval: float | None = None) -> VoilaServer:
    """Voila on ``notebook`` with the app's configuration (``app/config/voila.py``), 127.0.0.1 only.

    Parameters
    ----------
    tmp : Path
        Scratch folder (Voila's configuration folder, runtime files, log).
    seats : int
        ``ClassroomKernelManager.max_kernels`` (0: no limit), as ``make app APP_VISITORS=...``.
    idle : float, optional
        ``MappingKernelManager.cull_idle_timeout`` in seconds (default: the app's).
    notebook : Path
        The notebook served (default: the app).
    cull_interval : float, optional
        ``MappingKernelManager.cull_interval`` in seconds (default: the app's).
    """
    cfg = tmp / "config"
    cfg.mkdir(parents=True, exist_ok=True)
    lines = ["c = get_config()  # noqa: F821",
             f"load_subconfig('voila.py', path={str(APP_CONFIG)!r})  # noqa: F821",
             f"c.ClassroomKernelManager.max_kernels = {int(seats)}"]
    if idle is not None:
        lines.append(f"c.MappingKernelManager.cull_idle_timeout = {float(idle)!r}")
    if cull_interval is not None:
        lines.append(f"c.MappingKernelManager.cull_interval = {float(cull_interval)!r}")
    (cfg / "voila.py").write_text("\n".join(lines) + "\n")
    return VoilaServer(notebook, tmp, app_config=False)   # its own config loads the app's


def app_explorers(notebook: Path = APP) -> list[str]:
    """The explorers the app shows, in page order."""
    nb = nbformat.read(notebook, as_version=4)
    return [m.group(1) for c in nb.cells if c.cell_type == "code"
            for m in [CELL.match(c.source.strip())] if m]


def chain_handle() -> dict:
    """The last handle inside the default chain explorer's view, and where it sits.

    Read from the explorer's picture (``ex.picture()``): its id (the page's handle circle
    carries it as ``data-handle``) and its place as fractions of the picture's width and
    height, from the picture's box, size and margins (the page's canvas draws the same
    picture at that size, below its button bar).
    """
    from planargeo.widgets import ChainExplorer

    pic = ChainExplorer(display="agg").picture()
    x0, x1, y0, y1 = pic["box"]
    (w, h), (ml, mr, mt, mb) = pic["size"], pic["margin"]
    inside = [hd for hd in pic["handles"] if x0 < hd["x"] < x1 and y0 < hd["y"] < y1]
    hd = inside[-1]
    px = ml + (hd["x"] - x0) * (w - ml - mr) / (x1 - x0)
    py = mt + (y1 - hd["y"]) * (h - mt - mb) / (y1 - y0)
    return {"name": hd["id"], "fx": float(px / w), "fy": float(py / h)}


def _api(cv, expr: str):
    """Evaluate ``expr`` with ``p`` the page canvas's own interface (``canvas.js``)."""
    return cv.evaluate(f"(el) => {{ const p = el.__planargeo; return {expr}; }}")


def _wait_for(cv, expr: str, timeout: float) -> bool:
    from playwright.sync_api import TimeoutError as PlaywrightTimeout

    try:
        cv.page.wait_for_function(f"(el) => {{ const p = el.__planargeo; return !!({expr}); }}",
                                  arg=cv.element_handle(), timeout=timeout * 1000, polling=20)
        return True
    except PlaywrightTimeout:
        return False


def drag_steps(page, cv, handle: dict, steps: int, px: float = 3.0, timeout: float = 10.0) -> list[float | None]:
    """Drag ``handle`` by ``px``-pixel mouse moves (8 right, 8 left, ...), one step at a time.

    Per step, milliseconds from the mouse move to the paint of the picture it asked for
    (the canvas's ``stats``: input time and paint time of each request), or None when no
    picture came within ``timeout`` seconds.  The handle is found by its circle
    (``data-handle``), else by its place in the picture (:func:`chain_handle`) within the
    canvas's SVG.
    """
    cv.scroll_into_view_if_needed()
    circle = cv.locator(f"circle[data-handle='{handle['name']}']").first
    box = circle.bounding_box() if circle.count() else None
    if box is not None:
        x, y = box["x"] + box["width"] / 2, box["y"] + box["height"] / 2
    else:
        svg = cv.locator("svg").first.bounding_box()
        x, y = svg["x"] + handle["fx"] * svg["width"], svg["y"] + handle["fy"] * svg["height"]
    page.mouse.move(x, y)
    page.mouse.down()
    out: list[float | None] = []
    for k in range(steps):
        _wait_for(cv, "!p.busy()", 20.0)
        time.sleep(0.03)
        n = _api(cv, "p.stats.length")
        x += px if (k // 8) % 2 == 0 else -px
        page.mouse.move(x, y)
        if _wait_for(cv, f"p.stats.length > {n} && p.stats[{n}].tPaint", timeout):
            s = _api(cv, f"p.stats[{n}]")
            out.append(s["tPaint"] - s["tInput"])
        else:
            out.append(None)
    page.mouse.up()
    return out


# --------------------------------------------------------------------------- the browser
class SharedChromium:
    """One headless Chromium (the harness's flags) that every visitor's thread drives over CDP.

    Each visitor gets its own browser context (own cookies, own renderer processes) in
    this one browser: a browser per visitor would cost this machine about twice the memory
    (its own browser, GPU and utility processes) for nothing the server sees.
    """

    def __init__(self, tmp: Path):
        (tmp / "chromium").mkdir(parents=True, exist_ok=True)
        self.proc = subprocess.Popen([CHROMIUM, *CHROMIUM_ARGS, "--remote-debugging-port=0",
                                      "--remote-debugging-address=127.0.0.1",
                                      f"--user-data-dir={tmp / 'chromium'}", "about:blank"],
                                     stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, text=True)
        t0 = time.monotonic()
        for line in self.proc.stderr:
            if "DevTools listening on " in line:
                self.endpoint = line.split("DevTools listening on ", 1)[1].strip()
                break
            if time.monotonic() - t0 > 60:
                break
        else:
            self.endpoint = None
        if not getattr(self, "endpoint", None):
            self.stop()
            raise RuntimeError("chromium did not start its DevTools endpoint")
        threading.Thread(target=lambda: [None for _ in self.proc.stderr], daemon=True).start()

    def stop(self) -> None:
        self.proc.terminate()
        try:
            self.proc.wait(timeout=15)
        except subprocess.TimeoutExpired:
            self.proc.kill()
            self.proc.wait()


# --------------------------------------------------------------------------- memory
def _mb(n: float) -> float:
    return n / 2**20


def kernel_processes(server: VoilaServer) -> list:
    import psutil

    return [p for p in psutil.Process(server.proc.pid).children(recursive=True)
            if "ipykernel" in " ".join(_cmdline(p))]


def _cmdline(p) -> list[str]:
    try:
        return p.cmdline()
    except Exception:
        return []


def browser_processes() -> list:
    """Every chromium process started by this run (Playwright's drivers launched them)."""
    import psutil

    return [p for p in psutil.Process().children(recursive=True)
            if "chrom" in (p.name() or "").lower()]


def _cpu(procs) -> float:
    """Summed user and system CPU seconds of ``procs``."""
    out = 0.0
    for p in procs:
        try:
            t = p.cpu_times()
        except Exception:
            continue
        out += t.user + t.system
    return out


def _memory(procs) -> tuple[float, float]:
    """Summed RSS and PSS (MiB) of ``procs`` (those that vanished are skipped)."""
    rss = pss = 0.0
    for p in procs:
        try:
            m = p.memory_full_info()
        except Exception:
            continue
        rss += m.rss
        pss += getattr(m, "pss", m.rss)
    return _mb(rss), _mb(pss)


class Sampler(threading.Thread):
    """Peak summed kernel RSS and lowest available memory, sampled every second.

    If the machine's available memory falls below :data:`MEMORY_FLOOR_MB` (there is no
    swap: the next step is the OOM killer), the browser is stopped, which ends the run
    of this k, and ``aborted`` says so.
    """

    def __init__(self, server, chromium):
        super().__init__(daemon=True)
        self.server, self.chromium = server, chromium
        self.stop, self.peak_kernel_rss, self.min_available = threading.Event(), 0.0, math.inf
        self.aborted = False

    def run(self):
        import psutil

        while not self.stop.wait(1.0):
            try:
                rss = sum(p.memory_info().rss for p in kernel_processes(self.server))
            except Exception:
                continue
            self.peak_kernel_rss = max(self.peak_kernel_rss, _mb(rss))
            self.min_available = min(self.min_available, _mb(psutil.virtual_memory().available))
            if self.min_available < MEMORY_FLOOR_MB and not self.aborted:
                self.aborted = True
                print(f"[classroom] available memory {self.min_available:.0f} MiB: stopping the browser",
                      file=sys.stderr, flush=True)
                self.chromium.stop()


# --------------------------------------------------------------------------- one visitor
def _wait(what: str, fn, timeout: float, every: float = 0.5):
    t0 = time.monotonic()
    while time.monotonic() - t0 < timeout:
        got = fn()
        if got:
            return got
        time.sleep(every)
    raise TimeoutError(f"{what} within {timeout:.0f} s")


def visitor(i: int, url: str, cdp: str, plan: dict, barrier: threading.Barrier, rec: dict) -> None:
    """One visitor: open the app, then (in step with the others) drag, play, and stay until released."""
    from playwright.sync_api import sync_playwright

    state: dict = {}

    def load():
        time.sleep(i * plan["arrival"])       # visitors arrive one after the other
        t0 = time.monotonic()
        page = state["page"]
        page.goto(url, wait_until="domcontentloaded", timeout=plan["load_timeout"] * 1000)
        explorers = page.locator(".planargeo-explorer")
        left = plan["load_timeout"] - (time.monotonic() - t0)
        _wait(f"{plan['n_explorers']} explorers", lambda: explorers.count() >= plan["n_explorers"], left)
        ex = explorers.nth(plan["index"])
        ex.scroll_into_view_if_needed()
        cv = ex.locator(".pg-canvas").first
        left = plan["load_timeout"] - (time.monotonic() - t0)
        _wait("the chain's picture", lambda: cv.count() > 0 and _api(cv, "!!p && p.elements() > 0"), max(left, 5))
        state["ex"], state["cv"] = ex, cv
        rec["ready_s"] = time.monotonic() - t0

    def drag():
        rec["drag_ms"] = drag_steps(state["page"], state["cv"], plan["handle"], plan["steps"])

    def play():
        ex, cv = state["ex"], state["cv"]
        buttons = ex.locator(".widget-play button")
        buttons.first.scroll_into_view_if_needed()
        n0 = _api(cv, "p.painted()")
        buttons.first.click()
        time.sleep(plan["play"])
        n1 = _api(cv, "p.painted()")
        if buttons.count() > 1:
            buttons.nth(1).click()          # pause
        rec["play_fps"] = (n1 - n0) / plan["play"]   # pictures that reached the page per second

    def stay():
        pass                                 # every page open while the memory is read

    try:
        with sync_playwright() as p:
            browser = p.chromium.connect_over_cdp(cdp, timeout=60_000)
            context = browser.new_context(viewport=VIEWPORT)
            try:
                state["page"] = context.new_page()
                for phase in (load, drag, play, stay):
                    if "error" not in rec:
                        try:
                            phase()
                        except Exception as exc:       # noqa: BLE001 - recorded, the run goes on
                            rec["error"] = f"{phase.__name__}: {type(exc).__name__}: {str(exc)[:200]}"
                    try:
                        barrier.wait(timeout=3600)     # the main thread ends a phase that takes too long
                    except threading.BrokenBarrierError:
                        pass
            finally:
                context.close()
    except Exception as exc:                  # noqa: BLE001 - e.g. chromium failed to start
        rec.setdefault("error", f"browser: {type(exc).__name__}: {str(exc)[:200]}")


# --------------------------------------------------------------------------- one k
def run_k(k: int, steps: int, play: float, handle: dict, tmp: Path) -> dict:
    import psutil

    names = app_explorers()
    avail0 = _mb(psutil.virtual_memory().available)
    server = serve_app(tmp)
    chromium = SharedChromium(tmp)
    time.sleep(2.0)
    b_base = _memory(browser_processes())[1]
    sampler = Sampler(server, chromium)
    sampler.start()
    load_timeout = 180 + 40 * k
    plan = {"handle": handle, "steps": steps, "play": play, "n_explorers": len(names), "arrival": ARRIVAL_S,
            "index": names.index(EXPLORER), "load_timeout": load_timeout,
            "phase_timeout": {"load": load_timeout + ARRIVAL_S * k + 30, "drag": 60 + 15 * steps,
                              "play": play + 120, "stay": 60}}
    barrier = threading.Barrier(k + 1)
    recs = [{} for _ in range(k)]
    threads = [threading.Thread(target=visitor, args=(i, server.url + "/", chromium.endpoint, plan, barrier, recs[i]),
                                daemon=True)
               for i in range(k)]
    t0 = time.monotonic()
    load0 = os.getloadavg()[0]
    try:
        for t in threads:
            t.start()
        phases, cpu = {}, {}
        for name in ("load", "drag", "play"):
            try:
                barrier.wait(timeout=plan["phase_timeout"][name])
            except threading.BrokenBarrierError:
                pass
            phases[name] = time.monotonic() - t0
            cpu[name] = _cpu(kernel_processes(server))
            print(f"  k={k}: {name} done at {phases[name]:.0f} s", file=sys.stderr, flush=True)
        kernels = kernel_processes(server)
        k_rss, k_pss = _memory(kernels)
        s_rss, _ = _memory([psutil.Process(server.proc.pid)])
        b_rss, b_pss = _memory(browser_processes())
        avail1 = _mb(psutil.virtual_memory().available)
        load1 = os.getloadavg()[0]
        try:
            barrier.wait(timeout=plan["phase_timeout"]["stay"])
        except threading.BrokenBarrierError:
            pass
        end = time.monotonic() + 30
        for t in threads:
            t.join(timeout=max(end - time.monotonic(), 0.1))
    finally:
        sampler.stop.set()
        chromium.stop()
        server.stop()
    drags = [x for r in recs for x in r.get("drag_ms", [])]
    got = sorted(x for x in drags if x is not None)
    res = {"k": k, "served": sum("ready_s" in r for r in recs), "errors": [r["error"] for r in recs if "error" in r],
           "kernels": len(kernels), "ready_s_median": _med([r.get("ready_s") for r in recs]),
           "ready_s_max": max((r["ready_s"] for r in recs if "ready_s" in r), default=None),
           "drag_steps": len(drags), "drag_missed": len(drags) - len(got),
           "drag_median_ms": statistics.median(got) if got else None,
           "drag_p90_ms": _quantile(got, 0.9), "play_fps_median": _med([r.get("play_fps") for r in recs]),
           "play_answered": sum("play_fps" in r for r in recs),
           "kernel_rss_mb": k_rss / max(len(kernels), 1), "kernel_pss_mb": k_pss / max(len(kernels), 1),
           "kernel_peak_rss_total_mb": sampler.peak_kernel_rss, "server_rss_mb": s_rss,
           "browser_rss_mb": b_rss / k, "browser_pss_mb": (b_pss - b_base) / k, "browser_empty_pss_mb": b_base,
           "available_drop_mb": (avail0 - avail1) / k, "available_min_mb": sampler.min_available,
           "load_before": load0, "load_during": load1, "wall_s": time.monotonic() - t0, "phases_s": phases,
           "aborted_for_memory": sampler.aborted,
           # kernel CPU seconds per visitor: opening the app, one drag step, one second of Play
           "cpu_open_s": cpu["load"] / max(len(kernels), 1),
           "cpu_drag_step_ms": 1e3 * (cpu["drag"] - cpu["load"]) / max(len(drags), 1),
           "cpu_play_per_s": (cpu["play"] - cpu["drag"]) / max(len(kernels), 1) / play}
    return res


def _med(xs):
    xs = [x for x in xs if x is not None]
    return statistics.median(xs) if xs else None


def _quantile(xs: list[float], q: float) -> float | None:
    """The ``q`` quantile of sorted ``xs`` (linear between order statistics)."""
    if not xs:
        return None
    if len(xs) == 1:
        return xs[0]
    pos = q * (len(xs) - 1)
    lo = int(pos)
    hi = min(lo + 1, len(xs) - 1)
    return xs[lo] + (xs[hi] - xs[lo]) * (pos - lo)


def full_reason(r: dict, total_mb: float) -> str | None:
    """Why the machine is full with ``r['k']`` visitors, or None if it is not."""
    if r["served"] < r["k"]:
        return f"{r['k'] - r['served']} of {r['k']} pages not ready"
    if r["drag_steps"] and r["drag_missed"] > FULL_MISSED * r["drag_steps"]:
        return f"{r['drag_missed']} of {r['drag_steps']} drag steps without a picture in 10 s"
    if r["drag_p90_ms"] is None or r["drag_p90_ms"] > FULL_P90_MS:
        return f"drag step p90 {r['drag_p90_ms'] or math.inf:.0f} ms > {FULL_P90_MS:.0f} ms"
    if r["kernel_pss_mb"] * r["k"] > FULL_MEMORY * total_mb:
        return f"kernels {r['kernel_pss_mb'] * r['k']:.0f} MiB > {FULL_MEMORY:.0%} of memory"
    return None


def verdict(results: list[dict], total_mb: float) -> dict:
    """k_max (largest measured k below full), the first full k and why, and the memory bound."""
    k_max, full = 0, None
    for r in sorted(results, key=lambda r: r["k"]):
        why = full_reason(r, total_mb)
        if why is None and full is None:
            k_max = r["k"]
        elif why is not None and full is None:
            full = {"k": r["k"], "why": why}
    pss = [r["kernel_pss_mb"] for r in results if r["kernels"]]
    k_memory = int(FULL_MEMORY * total_mb // max(pss)) if pss else None
    return {"k_max": k_max, "full": full, "k_memory": k_memory,
            "kernel_pss_mb": max(pss) if pss else None}


# --------------------------------------------------------------------------- report
def _f(x, fmt="{:.0f}"):
    return "–" if x is None else fmt.format(x)


def makefile_seats() -> str:
    """``APP_VISITORS``'s default in the Makefile (the seat limit of ``make app``)."""
    m = re.search(r"^APP_VISITORS\s*\?=\s*(\d+)", (REPO / "Makefile").read_text(encoding="utf-8"), re.M)
    return m.group(1) if m else "?"


def _answered(r: dict) -> str:
    n = r.get("play_answered", r["served"])
    return "" if n >= r["served"] else f" ({r['served'] - n} pages did not answer)"


def estimate(results: list[dict], cpus: int) -> dict:
    """Visitors a machine with ``cpus`` cores and nothing else to do holds, from the kernels' CPU cost.

    Processor sharing: k visitors dragging at once each need ``cpu_drag_step_ms`` of a core per
    step, so a step waits about ``k * cpu_drag_step_ms / cpus``; it reaches 1 s at ``k_drag``.
    Play keeps every visitor's frames coming in real time while ``k * cpu_play_per_s <= cpus``
    (``k_play``; beyond it frames are dropped, the motion stays in real time). Opening the
    app costs ``cpu_open_s`` each: k visitors arriving at once wait ``k * cpu_open_s / cpus``.
    """
    ok = [r for r in results if r.get("kernels") and r.get("cpu_drag_step_ms")]
    if not ok:
        return {}
    drag = statistics.median(r["cpu_drag_step_ms"] for r in ok)
    play = statistics.median(r["cpu_play_per_s"] for r in ok)
    open_s = statistics.median(r["cpu_open_s"] for r in ok)
    return {"cpu_drag_step_ms": drag, "cpu_play_per_s": play, "cpu_open_s": open_s,
            "k_drag": int(cpus * FULL_P90_MS / drag) if drag > 0 else None,
            "k_play": int(cpus / play) if play > 0 else None}


def report(results: list[dict], meta: dict, v: dict, skipped: list[dict] = ()) -> str:
    est = estimate(results, meta["cpus"])
    lines = ["# A classroom's load", "",
             "`make app` served with no seat limit (app/config/voila.py), k visitors arriving "
             f"{meta.get('arrival', ARRIVAL_S):.0f} s apart, each in its own browser",
             f"context of one headless Chromium on this machine ({meta['cpus']} CPUs, {meta['memory_gib']:.0f} GiB,"
             " no swap);",
             f"once every page shows every explorer, all visitors at once drag the end of the chain explorer's last "
             f"link ({meta['steps']} steps of 3 px,",
             f"each waiting for its picture), then press Play for {meta['play']:.0f} s. One kernel per visitor,",
             "running the whole app (every explorer). Memory is read with every page still open; the kernels' CPU "
             "time is read after each phase.", "",
             "| visitors k | pages ready | ready after (median / max, s) | drag step median (ms) | drag step p90 (ms) "
             "| steps without picture | Play frames/s (median) | kernel RSS / PSS per visitor (MiB) "
             "| browser PSS per visitor (MiB) | kernel CPU per visitor: opening (s) / drag step (ms) / Play (cores) "
             "| machine load (1 min) |",
             "|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for r in results:
        cpu = (f"{_f(r.get('cpu_open_s'), '{:.1f}')} / {_f(r.get('cpu_drag_step_ms'))} / "
               f"{_f(r.get('cpu_play_per_s'), '{:.2f}')}")
        lines.append(
            f"| {r['k']} | {r['served']}/{r['k']} | {_f(r['ready_s_median'], '{:.0f}')} / {_f(r['ready_s_max'], '{:.0f}')} "
            f"| {_f(r['drag_median_ms'])} | {_f(r['drag_p90_ms'])} | {r['drag_missed']}/{r['drag_steps']} "
            f"| {_f(r['play_fps_median'], '{:.1f}')}{_answered(r)} | {_f(r['kernel_rss_mb'])} / {_f(r['kernel_pss_mb'])} "
            f"| {_f(r['browser_pss_mb'])} | {cpu} | {r['load_before']:.1f} → {r['load_during']:.1f} |")
    for sk in skipped:
        why = sk.get("why") or (f"about {sk['needed_mb'] / 1024:.1f} GiB needed, "
                                f"{sk['available_mb'] / 1024:.1f} GiB available")
        lines.append(f"| {sk['k']} | not tried: {why} | | | | | | | | | |")
    full = v["full"]
    lines += ["", "![drag step and memory against k](classroom.png)", "", "## Reading", "",
              f"* **Memory per visitor:** each kernel holds about {_f(v['kernel_pss_mb'])} MiB (PSS: its own pages "
              "plus its share of the libraries it shares with the other kernels; RSS, which counts the shared pages "
              f"in full, is about {_f(results[0]['kernel_rss_mb'])} MiB). The Voila server itself took "
              f"{_f(results[-1]['server_rss_mb'])} MiB. Memory alone would allow about {v['k_memory']} visitors "
              f"({FULL_MEMORY:.0%} of {meta['memory_gib']:.0f} GiB); the processor runs out long before.",
              "* **Full:** " + (f"at k = {full['k']} ({full['why']})." if full else
                                "not reached at the largest k measured.")
              + f" Full means: drag step p90 > {FULL_P90_MS / 1000:.0f} s, a page not ready within "
              f"3 min + 40 s per visitor, more than {FULL_MISSED:.0%} of drag steps without a picture within 10 s, "
              f"or kernels above {FULL_MEMORY:.0%} of memory. Measured largest k below full: **{v['k_max']}**.",
              f"* **The machine was shared:** the last column is the 1-minute load average before and during each "
              f"run; other work kept {meta['cpus']} cores busy several times over, and the browsers (which in a "
              "classroom run on the visitors' own computers) ran here too. The latencies and page times above are "
              "therefore worse than a server that does nothing else would show."]
    if est:
        lines += [
            f"* **What the kernels' own CPU time says** (independent of the other work): opening the app costs "
            f"{est['cpu_open_s']:.1f} s of a core per visitor, a drag step {est['cpu_drag_step_ms']:.0f} ms, a "
            f"second of Play {est['cpu_play_per_s']:.2f} core-seconds. On {meta['cpus']} cores with nothing else to "
            f"do, k visitors dragging at once wait about k × {est['cpu_drag_step_ms']:.0f} ms / {meta['cpus']} per "
            f"step, which reaches 1 s at k ≈ {est['k_drag']} (an upper bound: the Voila server's own work, one "
            f"process for all visitors, is left out); everyone's Play keeps every frame up to "
            f"k ≈ {est['k_play']} (beyond, frames are dropped and the motion stays in real time); "
            f"k visitors arriving at once wait about k × {est['cpu_open_s'] / meta['cpus']:.1f} s for their page."]
    seats = makefile_seats()
    lines += [f"* **The seat limit:** `make app` admits `APP_VISITORS` visitors (the Makefile's default: {seats}, "
              f"below k = {full['k'] if full else '–'}, where this shared machine was full, and below the "
              f"k ≈ {est.get('k_play', '–')} at which 2 cores doing nothing else start dropping Play frames); "
              "visitor `APP_VISITORS` + 1 gets the page “The class is full” (HTTP 503) instead of slowing everyone "
              "down (`app/config/planargeo_classroom.py`). How to choose it for another computer: "
              "docs/serving.md.",
              "", f"Machine: {meta['machine']}, {meta['cpus']} CPUs, {meta['memory_gib']:.1f} GiB, "
              f"Python {meta['python']}, {meta['date']}{' (quick run)' if meta['quick'] else ''}. "
              "Raw numbers: `classroom.json`; chart: `classroom.png`. "
              "Re-run: `python benchmarks/classroom.py` (or `make bench`, group `classroom`); "
              "`--from-json` rewrites this page from `classroom.json` without measuring.", ""]
    return "\n".join(lines)


def chart(results: list[dict], v: dict) -> bytes:
    import io

    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    ks = [r["k"] for r in results]
    fig, (a, b) = plt.subplots(1, 2, figsize=(9, 3.6), dpi=100)
    a.plot(ks, [r["drag_median_ms"] or math.nan for r in results], "o-", label="median")
    a.plot(ks, [r["drag_p90_ms"] or math.nan for r in results], "s--", label="90th percentile")
    a.axhline(FULL_P90_MS, color="0.5", lw=0.8)
    a.text(ks[0], FULL_P90_MS * 1.08, "full: p90 > 1 s", fontsize=8, color="0.35")
    a.set_yscale("log")
    top = max([FULL_P90_MS] + [r["drag_p90_ms"] or 0 for r in results])
    a.set_ylim(top=top * 2)
    a.set_xlabel("visitors k")
    a.set_ylabel("drag step (ms)")
    a.set_title("Drag step: mouse move to new picture", fontsize=10)
    a.legend(fontsize=8)
    b.plot(ks, [r["kernel_pss_mb"] * r["k"] / 1024 for r in results], "o-", label="kernels (PSS)")
    b.plot(ks, [r["browser_pss_mb"] * r["k"] / 1024 for r in results], "s--", label="browsers (PSS)")
    b.set_xlabel("visitors k")
    b.set_ylabel("memory (GiB)")
    b.set_title("Memory, all visitors", fontsize=10)
    b.legend(fontsize=8)
    for ax in (a, b):
        ax.axvline(v["k_max"], color="tab:green", lw=0.8)
        ax.text(v["k_max"], 0.02, " measured k_max", color="tab:green", fontsize=8,
                transform=ax.get_xaxis_transform())
        ax.set_xticks(ks)
    fig.tight_layout()
    buf = io.BytesIO()
    fig.savefig(buf, format="png")
    plt.close(fig)
    return buf.getvalue()


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--ks", default=None, help="visitor counts, comma-separated (default 1,5,10,20; quick: 1,2)")
    ap.add_argument("--steps", type=int, default=None, help="drag steps per visitor (default 20; quick: 8)")
    ap.add_argument("--play", type=float, default=None, help="seconds of Play per visitor (default 10; quick: 3)")
    ap.add_argument("--quick", action="store_true", help="k = 1, 2 and a few steps")
    ap.add_argument("--out", default=str(Path(__file__).parent / "results"))
    ap.add_argument("--merge", action="store_true",
                    help="keep the other k of <out>/classroom.json (this run's k replace theirs)")
    ap.add_argument("--margin", type=float, default=MEMORY_MARGIN_MB / 1024,
                    help="GiB of available memory a k must leave free to be tried (default %(default)s)")
    ap.add_argument("--from-json", action="store_true",
                    help="rewrite classroom.md and classroom.png from <out>/classroom.json (no measurement)")
    args = ap.parse_args(argv)
    out = Path(args.out)
    if args.from_json:
        data = json.loads((out / "classroom.json").read_text(encoding="utf-8"))
        md = report(data["results"], data["meta"], data["verdict"], data.get("not_tried", []))
        atomic_write_many({out / "classroom.md": md, out / "classroom.png": chart(data["results"], data["verdict"])})
        print(md)
        return 0
    if not Path(CHROMIUM).exists():
        print(f"{CHROMIUM} not found: install Debian's chromium (make browser); skipped")
        return 0
    import psutil

    ks = [int(x) for x in (args.ks or ("1,2" if args.quick else "1,5,10,20")).split(",") if x.strip()]
    if not ks or min(ks) < 1 or max(ks) > 40:
        ap.error("--ks: visitor counts between 1 and 40")
    steps = args.steps or (8 if args.quick else 20)
    play = args.play or (3.0 if args.quick else 10.0)
    total_mb = _mb(psutil.virtual_memory().total)
    handle = chain_handle()
    results, skipped = [], []
    with tempfile.TemporaryDirectory() as tmp:
        per_visitor = 800.0          # MiB, kernel and browser, until measured
        if args.merge and (out / "classroom.json").exists():
            earlier = [r for r in json.loads((out / "classroom.json").read_text(encoding="utf-8"))["results"]
                       if r.get("kernels")]
            if earlier:
                per_visitor = 1.1 * (earlier[-1]["kernel_pss_mb"] + earlier[-1]["browser_pss_mb"])
        for k in ks:
            avail = _mb(psutil.virtual_memory().available)
            if k * per_visitor > avail - args.margin * 1024:
                print(f"[classroom] k = {k} not tried: about {k * per_visitor:.0f} MiB needed, "
                      f"{avail:.0f} MiB available", file=sys.stderr, flush=True)
                skipped.append({"k": k, "needed_mb": k * per_visitor, "available_mb": avail})
                continue
            print(f"[classroom] k = {k} ...", file=sys.stderr, flush=True)
            r = run_k(k, steps, play, handle, Path(tmp) / f"k{k}")
            results.append(r)
            if r["kernels"]:
                per_visitor = 1.1 * (r["kernel_pss_mb"] + r["browser_pss_mb"])
            print(f"[classroom] k = {k}: ready {r['served']}/{k}, drag median {_f(r['drag_median_ms'])} ms, "
                  f"p90 {_f(r['drag_p90_ms'])} ms, kernel PSS {_f(r['kernel_pss_mb'])} MiB, "
                  f"browser PSS {_f(r['browser_pss_mb'])} MiB, errors {len(r['errors'])}", file=sys.stderr,
                  flush=True)
            if full_reason(r, total_mb) and r["served"] < r["k"] / 2:
                print("[classroom] fewer than half the pages ready: larger k not tried", file=sys.stderr)
                break
    if args.merge and (out / "classroom.json").exists():
        old = json.loads((out / "classroom.json").read_text(encoding="utf-8"))
        mine = {r["k"] for r in results}
        results = sorted([r for r in old["results"] if r["k"] not in mine] + results, key=lambda r: r["k"])
        done = {r["k"] for r in results}
        skipped = [sk for sk in old.get("not_tried", []) + skipped if sk["k"] not in done]
    v = verdict(results, total_mb)
    meta = {"date": datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC"),
            "python": platform.python_version(), "machine": platform.machine(), "cpus": os.cpu_count(),
            "memory_gib": total_mb / 1024, "steps": steps, "play": play, "quick": bool(args.quick),
            "explorer": EXPLORER, "handle": handle, "arrival": ARRIVAL_S}
    out.mkdir(parents=True, exist_ok=True)
    md = report(results, meta, v, skipped)
    atomic_write_many({out / "classroom.json": json.dumps({"meta": meta, "verdict": v, "results": results, "not_tried": skipped},
                                                          indent=1, ensure_ascii=False) + "\n",
                       out / "classroom.md": md,
                       out / "classroom.png": chart(results, v)})
    print(md)
    return 0


if __name__ == "__main__":
    sys.exit(main())
