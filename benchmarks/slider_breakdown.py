"""Where a slider step's time goes, beside a drag step's: the page's clock at each stage.

Opens the 10-link chain (every overlay) in Voila (the setup of :mod:`page_latency`) and,
in alternating blocks of drag steps and ``angle`` slider steps (the same idle pause before
each), stamps with the page's clock:

* **input**: the key's ``keydown`` (slider) or the pointer's move (drag);
* **sent**: the page's websocket frame to the kernel (the slider's ``update``, the drag request);
* **busy, picture, other, idle**: the kernel's frames as they reach the page's websocket
  handler (status busy, the message carrying the picture: an ``update`` or the drag's
  ``ack``; the other widgets' ``update`` messages; status idle);
* **applied**: the canvas has applied the picture (its own ``applyTimes``);
* **painted**: the animation frame after it (the canvas's ``paintTimes``, as page_latency).

With ``--trace`` each block runs under a Chrome trace (no CPU profiler: it slows the page) and
each step's frame is taken apart: the main thread's tasks from the picture's arrival to the
frame, and the frame's work before and after its animation-frame callbacks (where "painted"
is stamped), with its style, layout, paint and hit test.  With ``--b CODE`` (Python, run in the kernel) the blocks alternate A/B
as well (ABBA), e.g. a change of the explorer switched on and off in the same page.

Run::

    MPLBACKEND=Agg .venv/bin/python benchmarks/slider_breakdown.py [--steps 10] [--rounds 4]
"""
from __future__ import annotations

import argparse
import json
import statistics
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import page_latency as pl  # noqa: E402
from browser_harness import launch_chromium  # noqa: E402

#: Page-side stamps on the kernel's websocket (installed on the next frame the page sends).
PAGE_HOOK = r"""
() => {
  window.__pgWs = [];
  const kind = (d) => {
    let s = typeof d === 'string' ? d : new TextDecoder().decode(new Uint8Array(d).slice(0, 4000));
    const m = s.match(/"msg_type":\s*"([a-z_]+)"/);
    let k = m ? m[1] : '?';
    if (k === 'status') k += ':' + ((s.match(/"execution_state":\s*"([a-z]+)"/) || [])[1]);
    if (k === 'comm_msg') {
      const meth = (s.match(/"method":\s*"([a-z_]+)"/) || [])[1];
      k += ':' + meth;
      if (meth === 'custom') k += ':' + ((s.match(/"content":\s*\{"type":\s*"([a-z]+)"/) || [])[1]);
    }
    return k;
  };
  // the end of each frame's main-thread work (style, layout, paint, commit): a task posted from
  // the frame's animation-frame callbacks runs after them
  window.__pgFrameEnds = [];
  const ch = new MessageChannel();
  let posted = false;
  ch.port1.onmessage = () => { posted = false; window.__pgFrameEnds.push(performance.now());
                               if (window.__pgFrameEnds.length > 2000) window.__pgFrameEnds.shift(); };
  const raf = window.requestAnimationFrame.bind(window);
  window.requestAnimationFrame = (cb) => raf((t) => {
    if (!posted) { posted = true; ch.port2.postMessage(0); }
    return cb(t);
  });
  const send = WebSocket.prototype.send;
  WebSocket.prototype.send = function (d) {
    if (!this.__pgHooked) {
      this.__pgHooked = true;
      const f = this.onmessage;
      this.onmessage = (e) => {
        window.__pgWs.push([performance.now(), 'in', kind(e.data), (e.data.byteLength || e.data.length)]);
        return f.call(this, e);
      };
    }
    window.__pgWs.push([performance.now(), 'out', kind(d), (d.byteLength || d.length)]);
    return send.call(this, d);
  };
}
"""


DUMP = None
CATEGORIES = "devtools.timeline,disabled-by-default-devtools.timeline,blink.user_timing,toplevel,v8.execute"


class Tracer:
    """A Chrome trace of the main thread while the steps run (no CPU profiler: it slows the page)."""

    def __init__(self, page):
        self.page, self.cdp, self.events, self.done = page, page.context.new_cdp_session(page), [], []
        self.cdp.on("Tracing.dataCollected", lambda p: self.events.extend(p["value"]))
        self.cdp.on("Tracing.tracingComplete", lambda p: self.done.append(1))

    def start(self):
        self.events.clear()
        self.done.clear()
        self.cdp.send("Tracing.start", {"categories": CATEGORIES, "transferMode": "ReportEvents"})
        time.sleep(0.2)
        self.t_mark = self.page.evaluate("() => { const t = performance.now(); performance.mark('pg-sync'); return t; }")

    def stop(self) -> list:
        self.cdp.send("Tracing.end")
        for _ in range(600):
            if self.done:
                break
            self.page.wait_for_timeout(50)
        return self.events


def frame_costs(events: list, t_mark: float, steps: list[tuple[float, float]]) -> list[dict]:
    """Per step ``(picture in, rAF time)`` (page clock, ms): the main thread's work from the picture's
    arrival to the end of the frame that painted it, by kind."""
    import bisect

    if DUMP:
        Path(DUMP).write_text(json.dumps({"events": events, "t_mark": t_mark, "steps": steps}))
    mark = next((e for e in events if e.get("name") == "pg-sync"), None)
    if mark is None:
        return [{} for _ in steps]
    off = mark["ts"] / 1e3 - t_mark            # trace ms = page ms + off
    main = (mark["pid"], mark["tid"])
    evs = sorted((e for e in events if (e.get("pid"), e.get("tid")) == main and e.get("ph") == "X"),
                 key=lambda e: (e["ts"], -e.get("dur", 0)))
    tops = [e for e in evs if e["name"] == "ThreadControllerImpl::RunTask"]
    starts = [e["ts"] / 1e3 for e in tops]
    ts_all = [e["ts"] for e in evs]

    def inside(task, name):
        i, out = bisect.bisect_left(ts_all, task["ts"]), 0.0
        while i < len(evs) and evs[i]["ts"] < task["ts"] + task.get("dur", 0):
            if evs[i]["name"] == name:
                out += evs[i].get("dur", 0) / 1e3
            i += 1
        return out

    rows = []
    for t_in, t_raf in steps:
        a, r = t_in + off, t_raf + off
        i = bisect.bisect_left(starts, a - 0.5)
        busy, frame, pre, style, layout, paint, hit = 0.0, None, 0.0, 0.0, 0.0, 0.0, 0.0
        while i < len(tops):
            t = tops[i]
            s, d = t["ts"] / 1e3, t.get("dur", 0) / 1e3
            if s > r + 1.0:
                break
            if s <= r <= s + d + 0.05 and (inside(t, "FireAnimationFrame") > 0 or inside(t, "Paint") > 0):
                frame = t
                break
            busy += d
            i += 1
        if frame is None:
            rows.append({})
            continue
        fs, fd = frame["ts"] / 1e3, frame.get("dur", 0) / 1e3
        rows.append({"picture → frame start": fs - a, "tasks before the frame": busy,
                     "waiting for the frame": (fs - a) - busy,
                     "frame: rAF → end": fs + fd - r, "frame: before rAF": r - fs,
                     "frame: hit test": inside(frame, "HitTest"),
                     "frame: style": inside(frame, "UpdateLayoutTree"),
                     "frame: layout": inside(frame, "Layout"),
                     "frame: paint": inside(frame, "Paint"), "frame total": fd})
    return rows


def _frames(page, t0: float, t1: float) -> list:
    return page.evaluate(f"window.__pgWs.filter(f => f[0] >= {t0} && f[0] <= {t1})")


def _stages(t_input: float, t_paint: float, frames: list, picture_kind: str) -> dict:
    out = {"total": t_paint - t_input}
    sent = next((f[0] for f in frames if f[1] == "out"), None)
    pic = next((f[0] for f in frames if f[1] == "in" and f[2] == picture_kind), None)
    busy = next((f[0] for f in frames if f[1] == "in" and f[2] == "status:busy"), None)
    idle = next((f[0] for f in frames if f[1] == "in" and f[2] == "status:idle"), None)
    others = [f for f in frames if f[1] == "in" and f[2] == "comm_msg:update"]
    out["input → sent"] = None if sent is None else sent - t_input
    out["sent → busy"] = None if sent is None or busy is None else busy - sent
    out["sent → picture"] = None if sent is None or pic is None else pic - sent
    out["picture → painted"] = None if pic is None else t_paint - pic
    out["picture → idle"] = None if pic is None or idle is None else idle - pic
    out["frames in"] = sum(f[1] == "in" for f in frames)
    out["other updates in"] = len(others)
    out["KB in"] = sum(f[3] for f in frames if f[1] == "in") / 1024
    return out


def _frame_end(page, st: dict, t_input: float, t_raf: float, t_pic) -> None:
    """The end of the frame that painted the picture (its main-thread work done), from the input and
    from the picture's arrival: "painted" as the step's end, whatever the frame did before its rAF."""
    end = page.evaluate(f"window.__pgFrameEnds.find(t => t >= {t_raf})")
    st["input → frame end"] = None if end is None else end - t_input
    st["picture → frame end"] = None if end is None or t_pic is None else end - t_pic


def slider_steps(page, ex, cv, steps: int, pause: float = pl.PAUSE) -> list[dict]:
    sl = ex.locator(".widget-slider").filter(has_text="angle").first
    knob = sl.locator(".noUi-handle").first
    knob.scroll_into_view_if_needed()
    knob.focus()
    knob.evaluate("(el) => { if (window.__pgKeys) return; window.__pgKeys = []; el.addEventListener('keydown', "
                  "() => window.__pgKeys.push(performance.now()), true); }")
    out, net = [], 0
    for k in range(steps):
        pl._wait_idle(cv)
        time.sleep(pause)
        n_keys = page.evaluate("window.__pgKeys.length")
        n_apply = pl._api(cv, "(p.applyTimes || []).length")
        right = (k // 5) % 2 == 0
        page.keyboard.press("ArrowRight" if right else "ArrowLeft")
        net += 1 if right else -1
        got = pl._until(cv, f"window.__pgKeys.length > {n_keys}"
                            f" && p.paintTimes.find(t => t > window.__pgKeys[{n_keys}])"
                            f" ? [window.__pgKeys[{n_keys}], p.paintTimes.find(t => t > window.__pgKeys[{n_keys}])]"
                            " : null")
        if not got:
            continue
        time.sleep(0.02)                          # the idle and the other updates in
        fr = _frames(page, got[0], got[1] + 15)
        st = _stages(got[0], got[1], [f for f in fr if f[0] <= got[1] or f[2] != "comm_msg:update" or True],
                     "comm_msg:custom:update")
        ap = pl._api(cv, f"(p.applyTimes || []).slice({n_apply})")
        st["page applies"] = ap[0] if ap else None
        pic = next((f[0] for f in fr if f[1] == "in" and f[2] == "comm_msg:custom:update"), None)
        st["_pic"], st["_raf"] = pic, got[1]
        _frame_end(page, st, got[0], got[1], pic)
        out.append(st)
    for _ in range(abs(net)):
        time.sleep(0.25)
        page.keyboard.press("ArrowLeft" if net > 0 else "ArrowRight")
    return out


def drag_steps(page, cv, steps: int) -> list[dict]:
    n0 = len(pl.STEPS)
    pl.drag(page, cv, "link 10 end", steps)
    out = []
    for s in pl.STEPS[n0:]:
        fr = _frames(page, s["tInput"], s["tPaint"] + 15)
        st = _stages(s["tInput"], s["tPaint"], fr, "comm_msg:custom:ack")
        st["page applies"] = s["tApplied"] - s["tAck"]
        st["kernel (ack ms)"] = s.get("kernelMs")
        st["_pic"] = next((f[0] for f in fr if f[1] == "in" and f[2] == "comm_msg:custom:ack"), None)
        st["_raf"] = s["tPaint"]
        _frame_end(page, st, s["tInput"], s["tPaint"], st["_pic"])
        out.append(st)
    return out


def _med(rows: list[dict]) -> dict:
    keys = list(dict.fromkeys(k for r in rows for k in r))
    out = {}
    for k in keys:
        if k.startswith("_"):
            continue
        xs = sorted(r[k] for r in rows if r.get(k) is not None)
        out[k] = round(statistics.median(xs), 2) if xs else None
    return out


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--steps", type=int, default=10)
    ap.add_argument("--rounds", type=int, default=4)
    ap.add_argument("--a", default="pass", help="Python run in the kernel for the A blocks")
    ap.add_argument("--b", default=None, help="Python run in the kernel for the B blocks (none: no A/B)")
    ap.add_argument("--out", type=Path, default=Path("/tmp/slider_breakdown.json"))
    ap.add_argument("--trace", action="store_true", help="trace each block: the frame's costs per step")
    ap.add_argument("--press", action="store_true",
                    help="with --mouse-ab: B also holds the mouse button down there during the slider steps")
    ap.add_argument("--mouse-ab", default=None, metavar="X,Y",
                    help="no kernel A/B: A leaves the mouse where the drag let go (over the picture), "
                         "B moves it to the page point X,Y before the slider steps")
    a = ap.parse_args(argv)
    from playwright.sync_api import sync_playwright

    cells = pl.CELLS[:2]
    if a.mouse_ab is not None:
        a.b = "pass"
    if a.b is not None:
        cells = cells + ["import ipywidgets as W\nab = W.Checkbox(description='B', value=False)\n"
                         f"ab.observe(lambda c: exec({a.b!r} if c.new else {a.a!r}, globals()), 'value')\n"
                         f"exec({a.a!r}, globals())\nab"]
    res = {k: {"slider": [], "drag": []} for k in "AB"}
    with tempfile.TemporaryDirectory() as tmp, sync_playwright() as p:
        browser = launch_chromium(p)
        root = Path(tmp) / "voila"
        root.mkdir()
        pl._notebook(root / "page.ipynb", cells)
        server, url = pl.serve("voila", root, Path(tmp))
        page = browser.new_page(viewport={"width": 1400, "height": 1100})
        try:
            page.goto(url, wait_until="domcontentloaded", timeout=120_000)
            page.evaluate(PAGE_HOOK)
            ex, cv = pl._canvas(page, pl._titles()["ChainExplorer"])
            time.sleep(1.0)
            pl.drag(page, cv, "link 10 end", 3)
            slider_steps(page, ex, cv, 2)
            box = page.locator(".widget-checkbox input").last if a.b is not None else None
            for r in range(a.rounds):
                for k in (("AB" if r % 2 == 0 else "BA") if a.b is not None else "A"):
                    if box is not None and box.is_checked() != (k == "B"):
                        box.scroll_into_view_if_needed()
                        box.click()
                        time.sleep(0.5)
                    cv.scroll_into_view_if_needed()
                    tr = Tracer(page) if a.trace else None
                    if tr:
                        tr.start()
                    d_rows = drag_steps(page, cv, a.steps)
                    if tr:
                        ev = tr.stop()
                        have = [q for q in d_rows if q["_pic"] is not None]
                        for row, fc in zip(have, frame_costs(ev, tr.t_mark, [(q["_pic"], q["_raf"]) for q in have])):
                            row.update(fc)
                    res[k]["drag"] += d_rows
                    if a.mouse_ab is not None and k == "B":
                        x, y = (float(v) for v in a.mouse_ab.split(","))
                        page.mouse.move(x, y)
                        if a.press:
                            page.mouse.down()
                    if tr:
                        tr.start()
                    s_rows = slider_steps(page, ex, cv, a.steps)
                    if a.mouse_ab is not None and a.press and k == "B":
                        page.mouse.up()
                    if tr:
                        ev = tr.stop()
                        have = [q for q in s_rows if q["_pic"] is not None]
                        for row, fc in zip(have, frame_costs(ev, tr.t_mark, [(q["_pic"], q["_raf"]) for q in have])):
                            row.update(fc)
                    res[k]["slider"] += s_rows
        finally:
            page.close()
            server.stop()
            browser.close()
    out = {k: {m: _med(v) for m, v in d.items() if v} for k, d in res.items() if d["slider"]}
    out["n"] = {k: {m: len(v) for m, v in d.items()} for k, d in res.items()}
    out["A code"], out["B code"] = a.a, a.b
    a.out.write_text(json.dumps({"medians": out, "raw": res}, indent=1))
    print(json.dumps(out, indent=1))
    return 0


if __name__ == "__main__":
    sys.exit(main())
