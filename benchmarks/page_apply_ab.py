"""A/B of the page renderer (canvas.js) alone: two versions of it on the same updates, in one page.

The 10-link chain with every overlay (as in page_latency.py) is driven in this process: drags of
its last link's end, toggles of its overlays and steps of its angle slider; every update the
kernel would send is kept.  One static page (no kernel, no server but a file server on
127.0.0.1) loads both versions of ``canvas.js`` (A: a file or a git revision's; B: the package's
own) with a stand-in for the anywidget model, and delivers the same updates to a view of each in
turn, in interleaved blocks (ABBA...), so both see the same machine load.  For each update:

* apply: the renderer's own ``applyTimes`` (the update handled, DOM written);
* apply + style/layout: the same, then ``document.body.offsetHeight`` read (style and layout forced);
* → frame end: from before the update to the end of the next frame's main-thread work (a task
  posted from that frame's animation-frame callback: style, layout, paint of the frame).

Sameness: after every update the figure's SVG (its outerHTML, the clip path's random id and
attribute order normalised) of A and B must be the same; the first difference is printed.

With ``--voila``, the same A/B in the page students get: Voila showing two such chains, the first
drawn by A, the second by B (each widget's own ``_esm``), in blocks of F (an empty request's round
trip, after a pause as before a drag step), drag steps (mouse move → painted, page_latency.drag)
and their apply times (the renderer's ``applyTimes``), in ABBA order.

Run::

    MPLBACKEND=Agg .venv/bin/python benchmarks/page_apply_ab.py [--a-rev HEAD | --a-file old.js] [--voila]
"""
from __future__ import annotations

import argparse
import json
import statistics
import subprocess
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from browser_harness import launch_chromium, serve_files as serve  # noqa: E402

ROOT = Path(__file__).resolve().parents[1]
OVERLAYS = ("velocity poles", "acceleration poles", "bias terms", "internal forces", "T/U split",
            "articulated inertias")

PAGE = """<!doctype html><html><head><meta charset="utf-8"><style>body { margin: 0; } %s</style></head>
<body><div id="host"></div><script type="module">
import A from "/a.js";
import B from "/b.js";
const mods = { A: A, B: B };
let handlers = {}, data = {};
const model = {
  get: (k) => data[k], set: (k, v) => { data[k] = v; }, save_changes: () => {},
  on: (ev, cb) => { (handlers[ev] = handlers[ev] || []).push(cb); },
  off: () => {}, send: () => {},
};
// the next frame: [its animation-frame callback's time, the end of its main-thread work]
const frameEnd = () => new Promise((res) => requestAnimationFrame(() => {
  const ch = new MessageChannel(), t = performance.now();
  ch.port1.onmessage = () => res([t, performance.now()]);
  ch.port2.postMessage(0);
}));
window.open_ = async (which, state) => {
  handlers = {}; data = { ...state };
  const host = document.getElementById("host");
  host.textContent = "";
  mods[which].render({ model, el: host });
  await frameEnd();
};
// the figure's SVG, normalised: the clip path's random id, attributes in name order
window.svgText = () => {
  const svg = document.querySelector(".pg-canvas svg").cloneNode(true);
  const clip = svg.querySelector("clipPath");
  const walk = (n) => {
    if (n.nodeType !== 1) return n.nodeType === 3 ? n.textContent : "";
    const names = [...n.attributes].map((a) => a.name).sort();
    const at = names.map((k) => { let v = n.getAttribute(k);
      if (clip) v = v.split(clip.id).join("CLIP"); return ` ${k}="${v}"`; }).join("");
    return `<${n.tagName}${at}>` + [...n.childNodes].map(walk).join("") + `</${n.tagName}>`;
  };
  return walk(svg);
};
window.run = async (msgs, withSvg) => {
  const p = document.querySelector(".pg-canvas").__planargeo, out = [];
  for (const m of msgs) {
    await frameEnd();                    // start from a quiet page
    const n = p.applyTimes.length, t0 = performance.now();
    for (const cb of handlers["msg:custom"] || []) cb(m, []);
    const t1 = performance.now();
    void document.body.offsetHeight;     // style and layout, forced
    const t2 = performance.now();
    const [tr, te] = await frameEnd();
    out.push({ apply: p.applyTimes[n], applyLayout: t2 - t0, frame: te - tr, total: t2 - t0 + te - tr,
               svg: withSvg ? window.svgText() : null });
  }
  return out;
};
window.ready = true;
</script></body></html>"""


def chain_updates(n_drag: int = 40) -> tuple[dict, list[dict], list[str]]:
    """The chain's first view state and the updates of drags, overlay toggles and slider steps."""
    from planargeo.widgets import ChainExplorer

    ex = ChainExplorer(display="page", links=10, **{k: True for k in OVERLAYS})
    sent = []
    ex.canvas.send = lambda m, *a, **k: sent.append(m)
    state = {"snapshot": json.loads(json.dumps(ex.canvas._snapshot())), "playing": False}
    msgs, kinds = [], []

    def take(kind):
        for m in sent:
            u = m if m.get("type") == "update" else m.get("update")
            if u:
                msgs.append(json.loads(json.dumps({**u, "type": "update"})))
                kinds.append(kind)
        del sent[:]

    h = next(h for h in ex.canvas.picture["handles"] if h["id"] == "link 10 end")
    for k in range(n_drag):
        d = 0.02 * (k % 10 if k % 20 < 10 else 10 - k % 10)
        ex.canvas._on_msg(None, {"type": "drag", "id": "link 10 end", "x": h["x"] + d, "y": h["y"] - d,
                                 "seq": k + 1}, None)
        take("drag")
    ex.canvas._on_msg(None, {"type": "release", "id": "link 10 end", "seq": n_drag + 1}, None)
    take("release")
    for name in OVERLAYS[2:4]:
        for on in (False, True):
            ex.controls[name].value = on
            take("toggle")
    for k in range(8):
        ex.controls["angle"].value = -30.0 + k
        take("slider")
    return state, msgs, kinds


def drag_on(page, cv, handle: str, moves: int, gap: float = 1 / 60, px: float = 2.0) -> dict:
    """A drag as a hand makes it: a mouse move every ``gap`` s (not waiting for the pictures).

    Returns the lag of each picture shown (its move → painted, ms: the page keeps only the latest
    drag request while one is in flight), pictures shown per second, and each picture's frame's
    main-thread work after its animation-frame callback (style, layout, paint: frame end − paint).
    """
    import time

    import page_latency as pl

    circle = cv.locator(f"circle[data-handle='{handle}']").first
    box = circle.bounding_box()
    x, y = box["x"] + box["width"] / 2, box["y"] + box["height"] / 2
    page.mouse.move(x, y)
    page.mouse.down()
    n0 = pl._api(cv, "p.stats.length")
    t0 = time.perf_counter()
    for k in range(moves):
        x += px if (k // 15) % 2 == 0 else -px
        page.mouse.move(x, y)
        time.sleep(max(0.0, t0 + (k + 1) * gap - time.perf_counter()))
    page.mouse.up()
    pl._wait_idle(cv)
    time.sleep(0.1)
    st = [s for s in pl._api(cv, f"p.stats.slice({n0})") if s["type"] == "drag" and s.get("tPaint")]
    if len(st) < 2:
        return {}
    span = (st[-1]["tPaint"] - st[0]["tPaint"]) / 1e3
    return {"lag": [s["tPaint"] - s["tInput"] for s in st],
            "pictures/s": [(len(st) - 1) / span] if span > 0 else [],
            "frame end − paint": [s["tFrame"] - s["tPaint"] for s in st if s.get("tFrame")]}


def voila(old: str, new: str, rounds: int, block: int, sync_s: dict | None = None,
          continuous: int = 0) -> dict:
    """Drag steps, F and apply times in Voila: two chains in one page, one drawn by A, one by B
    (``sync_s``: each chain's ``drag_sync_s``, where given)."""
    import tempfile
    import time

    import page_latency as pl
    from playwright.sync_api import sync_playwright

    res = {k: {"F": [], "drag": [], "apply": [], "move → ack": [], "ack → painted": [], "kernel ms": [],
               "paint → frame end": [], "continuous: lag": [], "continuous: pictures/s": [],
               "continuous: frame end − paint": []} for k in "AB"}
    make = "pw.ChainExplorer(display='page', links=10, **{k: True for k in %r})" % (OVERLAYS,)
    with tempfile.TemporaryDirectory() as tmp, sync_playwright() as p:
        tmp = Path(tmp)
        root = tmp / "voila"
        root.mkdir()
        cells = ["import planargeo.widgets as pw"]
        for k, js in (("A", old), ("B", new)):
            # each module marks the views it draws (its widget's element: data-pg-module)
            tag = f"export default {{ render: (o) => {{ o.el.dataset.pgModule = {k!r}; return render(o); }} }};"
            (tmp / f"{k}.js").write_text(js.replace("export default { render };", tag))
            own = f"\nchain{k}.drag_sync_s = {sync_s[k]!r}" if (sync_s or {}).get(k) is not None else ""
            cells.append(f"chain{k} = {make}\nchain{k}.canvas._esm = open({str(tmp / f'{k}.js')!r}).read()"
                         f"{own}\nchain{k}")
        pl._notebook(root / "page.ipynb", cells)
        server, url = pl.serve("voila", root, tmp)
        browser = launch_chromium(p)
        try:
            page = browser.new_page(viewport={"width": 1400, "height": 1100})
            page.goto(url, wait_until="domcontentloaded", timeout=120_000)
            pl._canvas(page, pl._titles()["ChainExplorer"])
            views = {}
            for i, k in enumerate("AB"):
                ex = page.locator(".planargeo-explorer").filter(has_text=pl._titles()["ChainExplorer"]).nth(i)
                cv = ex.locator(".pg-canvas").first
                cv.wait_for(state="visible", timeout=60_000)
                pl._until(cv, "p.elements() > 0 && !p.busy()", 60_000)
                marked = cv.evaluate("(el) => el.closest('[data-pg-module]')?.dataset.pgModule")
                if marked != k:
                    raise RuntimeError(f"the view {k} does not run module {k}")
                views[k] = cv
            for r in range(rounds + 1):
                for k in ("AB" if r % 2 == 0 else "BA"):
                    cv = views[k]
                    cv.scroll_into_view_if_needed()
                    time.sleep(0.3)
                    pl.drag(page, cv, "link 10 end", 2)          # warm
                    if r == 0:
                        continue
                    res[k]["F"] += pl.floor(cv, block, pl.PAUSE)
                    n0, a0 = len(pl.STEPS), pl._api(cv, "p.applyTimes.length")
                    res[k]["drag"] += pl.drag(page, cv, "link 10 end", block)[0]
                    res[k]["apply"] += pl._api(cv, f"p.applyTimes.slice({a0})")
                    res[k]["ack → painted"] += [st["tPaint"] - st["tAck"] for st in pl.STEPS[n0:]]
                    res[k]["move → ack"] += [st["tAck"] - st["tInput"] for st in pl.STEPS[n0:]]
                    res[k]["kernel ms"] += [st.get("kernelMs") for st in pl.STEPS[n0:]]
                    res[k]["paint → frame end"] += [st["tFrame"] - st["tPaint"] for st in pl.STEPS[n0:]
                                                    if st.get("tFrame")]
                    if continuous:
                        c = drag_on(page, cv, "link 10 end", continuous)
                        for m, v in c.items():
                            res[k]["continuous: " + m] += v
        finally:
            browser.close()
            server.stop()
    return res


def _med(xs):
    xs = sorted(x for x in xs if x is not None)
    return (round(statistics.median(xs), 2), round(xs[int(0.9 * (len(xs) - 1))], 2)) if xs else None


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--a-rev", default="HEAD", help="git revision whose canvas.js is A")
    ap.add_argument("--a-file", default=None, help="a file that is A (instead of --a-rev)")
    ap.add_argument("--rounds", type=int, default=6)
    ap.add_argument("--voila", action="store_true", help="the A/B in Voila (module docstring)")
    ap.add_argument("--block", type=int, default=8, help="--voila: steps per block")
    ap.add_argument("--continuous", type=int, default=0,
                    help="--voila: also a drag of this many mouse moves, one every 1/60 s, per block")
    ap.add_argument("--same-js", action="store_true", help="--voila: A runs the package's canvas.js too")
    ap.add_argument("--a-drag-sync-s", type=float, default=None,
                    help="--voila: chain A's drag_sync_s (0: controls and readout synced with every step)")
    ap.add_argument("--b-drag-sync-s", type=float, default=None, help="--voila: chain B's drag_sync_s")
    a = ap.parse_args(argv)
    from playwright.sync_api import sync_playwright

    from planargeo.widgets.canvas import PictureCanvas

    def at_rev(name):       # a file of the renderer at a git revision ("" where it did not exist)
        out = subprocess.run(["git", "show", f"{a.a_rev}:planargeo/widgets/{name}"], cwd=ROOT,
                             capture_output=True, text=True)
        return out.stdout if out.returncode == 0 else ""

    # the page renderer is canvas_parts.js then canvas.js, one module (canvas.py's _ESM)
    old = Path(a.a_file).read_text() if a.a_file else at_rev("canvas_parts.js") + at_rev("canvas.js")
    new = str(PictureCanvas._esm)
    if a.same_js:
        old = new
    if a.voila:
        res = voila(old, new, a.rounds, a.block, {"A": a.a_drag_sync_s, "B": a.b_drag_sync_s}, a.continuous)
        print("Voila, the chain: ms, median (p90)")
        for m in res["A"]:
            print(f"  {m:30s} A {_med(res['A'][m])}   B {_med(res['B'][m])}   (n {len(res['A'][m])}, {len(res['B'][m])})")
        return 0
    state, msgs, kinds = chain_updates()
    print(f"{len(msgs)} updates: " + ", ".join(f"{k} {kinds.count(k)}" for k in dict.fromkeys(kinds)))
    srv = serve({"/": ((PAGE % str(PictureCanvas._css)).encode(), "text/html"),
                 "/a.js": (old.encode(), "text/javascript"), "/b.js": (new.encode(), "text/javascript")})
    res = {k: {m: [] for m in ("apply", "applyLayout", "frame", "total")} for k in "AB"}
    same = True
    with sync_playwright() as p:
        browser = launch_chromium(p)
        try:
            page = browser.new_page(viewport={"width": 1200, "height": 900})
            page.goto(f"http://127.0.0.1:{srv.server_address[1]}/")
            page.wait_for_function("window.ready === true")
            svgs = {}
            for r in range(a.rounds + 1):
                for k in ("AB" if r % 2 == 0 else "BA"):
                    page.evaluate("([k, s]) => window.open_(k, s)", [k, state])
                    out = page.evaluate("([m, s]) => window.run(m, s)", [msgs, r == 0])
                    if r == 0:                  # a warm-up round: the SVGs compared
                        svgs[k] = [o["svg"] for o in out]
                        continue
                    for o, kind in zip(out, kinds):
                        if kind == "drag":
                            for m in res[k]:
                                res[k][m].append(o[m])
            for i, (sa, sb) in enumerate(zip(svgs["A"], svgs["B"])):
                if sa != sb:
                    same = False
                    j = next(j for j in range(min(len(sa), len(sb))) if sa[j] != sb[j])
                    print(f"update {i} ({kinds[i]}): SVGs differ at {j}:\n A …{sa[max(0, j - 200):j + 200]}\n"
                          f" B …{sb[max(0, j - 200):j + 200]}")
                    break
        finally:
            browser.close()
            srv.shutdown()
    print("same SVG after every update:", same)
    print("drag updates, ms: median (p90)")
    for m in ("apply", "applyLayout", "frame", "total"):
        print(f"  {m:12s} A {_med(res['A'][m])}   B {_med(res['B'][m])}")
    return 0 if same else 1


if __name__ == "__main__":
    sys.exit(main())
