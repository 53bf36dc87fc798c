"""Every explorer drawn by the browser (``display="page"``): real mouse and keyboard, in a real host.

The checks here run on every explorer of the app notebook (``app/planargeo-app.ipynb``,
each explorer forced to ``display="page"`` in the copy under test), one server and one
page per host: JupyterLab here, the web app's Voila in ``test_browser_explorers.py``
(which also makes ``docs/screens``).  For each explorer, headless chromium

* **layout**: samples the plot area on a 12 × 12 grid and finds only the picture on top
  (no control, bar, tooltip or toolbar over the axes), and no clipping container (an
  output area) cuts it; measures every readout cell's box against the readout, the
  explorer and every clipping container it sits in, and its text against the cell's own
  width (no value clipped); measures the SVG text boxes of the picture's labels (no two
  overlap); in the default state and again after the drag and the slider below;
* **drag**: presses its first handle in view, moves it 12 px: the handle follows the
  pointer in the page at once, the kernel answers and a new picture is painted, and the
  readout changes;
* **slider**: moves its first slider with the keyboard: the readout changes and a new
  picture is painted;
* **zoom / pan / reset**: a wheel step zooms about the pointer at once (a handle moves
  away from the pointer), the kernel answers with the new view; a background drag pans;
  "reset view" brings every handle back to its first place (within 1 px);
* **hover**: rests on a described element on top: its description shows;
* **Play** (where it has it): frames are painted while it plays, and stop when paused; the
  page asked for them (tick requests on the wire: frames paced by the page);
* **export**: the SVG button gives an SVG document holding every element and label the
  page shows, by id (matplotlib's drawing of the same picture);

Over the whole run, every message between the page and the kernel is read off the
websocket (both of Jupyter's wire formats): the test fails if a page sends a request
while its previous one is unanswered.  Every network request the page makes is
recorded: the test fails if any leaves 127.0.0.1.
"""
from __future__ import annotations

import html
import json
import re
import time
from pathlib import Path
from urllib.parse import urlparse

import nbformat
import pytest

from .conftest import ARTIFACTS
from .test_browser import _readout, _wait_for

pytestmark = pytest.mark.browser

REPO = Path(__file__).resolve().parents[2]
APP = REPO / "app" / "planargeo-app.ipynb"
CELL = re.compile(r"^pw\.(\w+)\((.*)\)$")

# Installed before any page script: every comm message of the page canvases, read off the
# websocket in either wire format (JSON text, or v1.kernel.websocket.jupyter.org binary).
WIRE_HOOK = """
(() => {
  const log = [];
  window.__pgWire = log;
  const dec = new TextDecoder();
  const REQUESTS = ["drag", "view", "tick", "ping", "sync", "describe"];
  function parse(data) {
    try {
      if (typeof data === "string") {
        const m = JSON.parse(data);
        return [m.header ? m.header.msg_type : m.msg_type, m.content];
      }
      const buf = data instanceof ArrayBuffer ? data : (ArrayBuffer.isView(data) ? data.buffer : null);
      if (!buf) return ["unreadable", null];
      const dv = new DataView(buf);
      const n = Number(dv.getBigUint64(0, true));
      const off = [];
      for (let i = 0; i < n; i++) off.push(Number(dv.getBigUint64(8 * (i + 1), true)));
      const part = (i) => dec.decode(new Uint8Array(buf, off[i], (i + 1 < n ? off[i + 1] : buf.byteLength) - off[i]));
      return [JSON.parse(part(1)).msg_type, JSON.parse(part(4))];
    } catch (e) { return ["unreadable", null]; }
  }
  function note(dir, data) {
    const [kind, c] = parse(data);
    if (kind === "unreadable") { log.push({ dir, unreadable: true }); return; }
    if (kind !== "comm_msg" || !c || !c.data || c.data.method !== "custom" || !c.data.content) return;
    const m = c.data.content;
    if (dir === "out" && REQUESTS.includes(m.type))
      log.push({ dir, comm: c.comm_id, seq: m.seq, type: m.type, t: performance.now() });
    else if (dir === "in" && m.type === "ack")
      log.push({ dir, comm: c.comm_id, seq: m.seq, t: performance.now() });
  }
  const send = WebSocket.prototype.send;
  WebSocket.prototype.send = function (data) { note("out", data); return send.call(this, data); };
  window.WebSocket = new Proxy(window.WebSocket, {
    construct(T, args) {
      const ws = new T(...args);
      ws.addEventListener("message", (ev) => note("in", ev.data));
      return ws;
    },
  });
})();
"""


# --------------------------------------------------------------------------- the notebook
def page_app(dst: Path) -> list[str]:
    """Copy the app notebook to ``dst`` with every explorer shown in the page; return their names."""
    nb = nbformat.read(APP, as_version=4)
    names = []
    for cell in nb.cells:
        m = CELL.match(cell.source.strip()) if cell.cell_type == "code" else None
        if m:
            names.append(m.group(1))
            args = m.group(2).strip()
            if "display=" not in args:
                args = ", ".join(a for a in (args, 'display="page"') if a)
            cell.source = f"pw.{m.group(1)}({args})"
    nb.metadata["kernelspec"] = {"name": "python3", "display_name": "Python 3", "language": "python"}
    nbformat.write(nb, dst)
    return names


# --------------------------------------------------------------------------- what the page shows
def _canvas(ex):
    return ex.locator(".pg-canvas").first


def _stats(cv) -> dict:
    return cv.evaluate("el => ({n: el.__planargeo.stats.length, painted: el.__planargeo.painted(),"
                       " busy: el.__planargeo.busy()})")


def _settled(cv, n0: int, p0: int, what: str, timeout: float = 60):
    """Wait until the canvas answered a request made after ``n0`` and painted after ``p0``."""
    _wait_for(lambda: (lambda s: s["n"] > n0 and not s["busy"])(_stats(cv)), timeout, f"{what}: answered")
    _wait_for(lambda: _stats(cv)["painted"] > p0, 30, f"{what}: a new picture painted")


def _handles(cv) -> dict[str, tuple[float, float]]:
    return {k: tuple(v) for k, v in cv.evaluate(
        "el => Object.fromEntries([...el.querySelectorAll('circle.pg-handle')]"
        ".map(c => [c.dataset.handle, [+c.getAttribute('cx'), +c.getAttribute('cy')]]))").items()}


def _plot_box(cv) -> dict:
    return cv.locator("svg .pg-frame").first.bounding_box()


def check_layout(page, ex) -> list[str]:
    """Nothing over the plot area; every readout cell fully shown; no two labels overlap."""
    cv = _canvas(ex)
    page.mouse.move(1, 1)            # no hover tip
    cv.scroll_into_view_if_needed()
    time.sleep(0.2)
    out = page.evaluate(
        """([root, cv]) => {
          const problems = [];
          const svg = cv.querySelector('svg');
          const r = cv.querySelector('svg .pg-frame').getBoundingClientRect();
          const over = new Map();
          for (let i = 0; i < 12; i++) for (let j = 0; j < 12; j++) {
            const x = r.left + (i + 0.5) * r.width / 12, y = r.top + (j + 0.5) * r.height / 12;
            if (x < 0 || y < 0 || x >= innerWidth || y >= innerHeight) continue;
            const e = document.elementFromPoint(x, y);
            if (!e || e === svg || svg.contains(e)) continue;
            const name = e.tagName.toLowerCase() + (e.className && e.className.baseVal === undefined
                         ? '.' + String(e.className).trim().split(/\\s+/).join('.') : '');
            over.set(name, (over.get(name) || 0) + 1);
          }
          for (const [name, n] of over) problems.push(`${name} covers ${n} of 144 points of the plot area`);
          for (let a = svg.parentElement; a && a !== document.body; a = a.parentElement) {
            const s = getComputedStyle(a), c = a.getBoundingClientRect();
            if (s.overflowX !== 'visible' && (r.right > c.right + 0.5 || r.left < c.left - 0.5)) {
              problems.push(`the plot area [${r.left.toFixed(0)}, ${r.right.toFixed(0)}] is cut by a `
                            + `${a.tagName.toLowerCase()} (overflow ${s.overflowX}) [${c.left.toFixed(0)}, ${c.right.toFixed(0)}]`);
              break;
            }
          }
          // readout: each cell inside its table's container and the explorer, its text not clipped
          const ro = root.querySelector('.planargeo-readout');
          if (ro) {
            const boxOf = (e) => e.getBoundingClientRect();
            const cont = boxOf(ro), whole = boxOf(root);
            for (const td of ro.querySelectorAll('td')) {
              const b = boxOf(td), t = td.textContent.trim();
              const row = td.parentElement.firstElementChild.textContent.trim();
              for (const [c, cname] of [[cont, 'the readout'], [whole, 'the explorer']]) {
                if (b.left < c.left - 0.5 || b.right > c.right + 0.5 || b.top < c.top - 0.5 || b.bottom > c.bottom + 0.5)
                  problems.push(`readout ${row}: cell '${t}' [${b.left.toFixed(0)}, ${b.right.toFixed(0)}] `
                                + `reaches out of ${cname} [${c.left.toFixed(0)}, ${c.right.toFixed(0)}]`);
              }
              if (td.scrollWidth > td.clientWidth + 1 && td !== td.parentElement.firstElementChild)
                problems.push(`readout ${row}: cell '${t}' clipped (${td.scrollWidth} px of text in ${td.clientWidth} px)`);
              // every clipping ancestor, up to the page (an output area, the notebook), holds the cell
              for (let a = td.parentElement; a && a !== document.body; a = a.parentElement) {
                const s = getComputedStyle(a);
                if (s.overflowX !== 'visible' && a.tagName !== 'TD') {
                  const c = boxOf(a);
                  if (b.right > c.right + 0.5 || b.left < c.left - 0.5) {
                    problems.push(`readout ${row}: cell '${t}' cut by a ${a.tagName.toLowerCase()} `
                                  + `(overflow ${s.overflowX}) at x = ${c.right.toFixed(0)}`);
                    break;
                  }
                }
              }
            }
          } else problems.push('no readout table');
          // labels: the SVG text boxes of the picture's elements
          const boxes = [...svg.querySelectorAll('.pg-el text')].filter((t) => t.textContent)
            .map((t) => [t.textContent, t.closest('.pg-el').dataset.id, t.getBoundingClientRect()]);
          for (let a = 0; a < boxes.length; a++) for (let b = a + 1; b < boxes.length; b++) {
            const p = boxes[a][2], q = boxes[b][2];
            const ox = Math.min(p.right, q.right) - Math.max(p.left, q.left);
            const oy = Math.min(p.bottom, q.bottom) - Math.max(p.top, q.top);
            if (ox > 1 && oy > 1) problems.push(`labels '${boxes[a][0]}' (${boxes[a][1]}) and '${boxes[b][0]}' `
                                                + `(${boxes[b][1]}) overlap by ${ox.toFixed(1)} x ${oy.toFixed(1)} px`);
          }
          return problems;
        }""", [ex.element_handle(), cv.element_handle()])
    return out


def _handle_in_view(cv):
    """The index of the first handle well inside the plot area, and its centre on the screen."""
    plot = _plot_box(cv)
    handles = cv.locator("circle.pg-handle")
    for j in range(handles.count()):
        box = handles.nth(j).bounding_box()
        if box is None:
            continue
        x, y = box["x"] + box["width"] / 2, box["y"] + box["height"] / 2
        if plot["x"] + 20 < x < plot["x"] + plot["width"] - 30 and plot["y"] + 20 < y < plot["y"] + plot["height"] - 30:
            return j, x, y
    return None


def check_drag(page, ex):
    cv = _canvas(ex)
    cv.scroll_into_view_if_needed()
    found = _handle_in_view(cv)
    assert found is not None, "no handle inside the view to drag"
    j, x, y = found
    h = cv.locator("circle.pg-handle").nth(j)
    before = _readout(page, ex)
    s0 = _stats(cv)
    cx0 = float(h.get_attribute("cx"))
    page.mouse.move(x, y)
    page.mouse.down()
    for k in range(1, 7):            # quick moves: the page keeps one request in flight
        page.mouse.move(x + 2 * k, y + 0.7 * k)
    assert abs(float(h.get_attribute("cx")) - (cx0 + 12)) < 1.5, "the handle did not follow the pointer at once"
    page.mouse.up()
    _settled(cv, s0["n"], s0["painted"], "the drag")
    _wait_for(lambda: _readout(page, ex) != before, 10, "the readout to change after the drag")


def check_slider(page, ex):
    """Some slider, moved with the keyboard, changes the readout and brings a new picture."""
    cv = _canvas(ex)
    sliders = ex.locator(".widget-slider .noUi-handle")
    tried = []
    for i in range(sliders.count()):
        handle = sliders.nth(i)
        if not handle.is_visible():
            continue
        handle.scroll_into_view_if_needed()
        before, s0 = _readout(page, ex), _stats(cv)
        handle.focus()
        for key in ("ArrowRight", "ArrowLeft"):
            for _ in range(3):
                page.keyboard.press(key)
                time.sleep(0.05)
            try:
                _wait_for(lambda: _readout(page, ex) != before, 5, "the readout to change")
            except AssertionError:
                continue
            try:
                _wait_for(lambda: _stats(cv)["painted"] > s0["painted"], 5, "a new picture")
                return
            except AssertionError:
                tried.append(f"slider {i}: the readout changed, the picture did not")
                break
    raise AssertionError("no slider changed both the readout and the picture; " + "; ".join(tried))


def check_view(page, ex):
    """Wheel zoom about the pointer, pan by dragging the background, reset view."""
    cv = _canvas(ex)
    cv.scroll_into_view_if_needed()
    s_ = _stats(cv)                  # the explorer's own view first (a drag may have held another)
    cv.locator(".pg-bar button", has_text="reset view").click()
    _settled(cv, s_["n"], s_["painted"] - 1, "reset view")
    time.sleep(0.3)
    first = _handles(cv)
    # a point of the background: no element, no handle on top
    spot = page.evaluate("""(cv) => {
        const r = cv.querySelector('svg .pg-frame').getBoundingClientRect();
        for (let i = 1; i < 10; i++) for (let j = 1; j < 10; j++) {
          const x = r.left + i * r.width / 10, y = r.top + j * r.height / 10;
          const e = document.elementFromPoint(x, y);
          if (e && e.classList.contains('pg-bg')) return [x, y];
        }
        return null; }""", cv.element_handle())
    assert spot is not None, "no background point in the plot area"
    x, y = spot
    s0 = _stats(cv)
    page.mouse.move(x, y)
    page.mouse.wheel(0, -200)        # zoom in about (x, y)
    time.sleep(0.05)
    zoomed = _handles(cv)
    moved = [k for k in first if k in zoomed and abs(zoomed[k][0] - first[k][0]) + abs(zoomed[k][1] - first[k][1]) > 1]
    assert moved or not first, "a wheel step moved no handle"
    _settled(cv, s0["n"], s0["painted"], "the zoom")
    # pan: drag the background by (30, 20) px; the handles follow by that
    s1, before = _stats(cv), _handles(cv)
    page.mouse.move(x, y)
    page.mouse.down()
    for k in range(1, 6):
        page.mouse.move(x + 6 * k, y + 4 * k)
    page.mouse.up()
    _settled(cv, s1["n"], s1["painted"], "the pan")
    after = _handles(cv)
    shifts = sorted((after[k][0] - before[k][0], after[k][1] - before[k][1]) for k in before if k in after)
    if shifts:                       # most handles move with the background (one may sit at the view's edge)
        mx, my = shifts[len(shifts) // 2]
        assert abs(mx - 30) < 1.5 and abs(my - 20) < 1.5, f"the handles moved by {shifts} px, not (30, 20)"
    # reset
    s2 = _stats(cv)
    cv.locator(".pg-bar button", has_text="reset view").click()
    _settled(cv, s2["n"], s2["painted"], "reset view")
    _wait_for(lambda: all(abs(_handles(cv)[k][0] - first[k][0]) < 1 and abs(_handles(cv)[k][1] - first[k][1]) < 1
                          for k in first if k in _handles(cv)), 10, "the handles back after reset view")


def check_hover(page, ex):
    """Rest the pointer on described elements that are on top: a description shows."""
    cv = _canvas(ex)
    spots = page.evaluate("""(cv) => {
        const out = [];
        for (const g of cv.querySelectorAll('.pg-el[data-described]')) {
          for (const n of g.children) {
            let x, y;
            if (n.tagName === 'path' && n.getTotalLength && n.getTotalLength() > 0) {
              const p = n.getPointAtLength(n.getTotalLength() / 2).matrixTransform(n.getScreenCTM());
              [x, y] = [p.x, p.y];
            } else {
              const b = n.getBoundingClientRect();
              [x, y] = [b.left + b.width / 2, b.top + b.height / 2];
            }
            const e = document.elementFromPoint(x, y), hit = e && e.closest('.pg-el');
            if (hit === g) { out.push([g.dataset.id, x, y]); break; }
          }
          if (out.length >= 12) break;
        }
        return out; }""", cv.element_handle())
    tip = cv.locator(".pg-tip")
    for _id, x, y in spots:
        page.mouse.move(x, y)
        try:
            _wait_for(lambda: tip.is_visible() and len(tip.inner_text().strip()) > 3, 5, "a description")
            page.mouse.move(1, 1)
            return
        except AssertionError:
            continue
    page.mouse.move(1, 1)
    raise AssertionError(f"no description shown on hover ({len(spots)} described elements on top tried)")


#: tick requests the page sent during the last Play check (filled by check_play)
PLAY_TICKS = [0]


def _ticks(page) -> int:
    return page.evaluate("(window.__pgWire || []).filter((m) => m.type === 'tick').length")


def check_play_paced(page, ex):
    """Play's frames were asked for by the page (tick requests), not pushed by a timer in the kernel."""
    assert PLAY_TICKS[0] > 0, ("Play painted frames but the page sent no tick: its frames are not paced "
                               "by the page (PictureCanvas.playing / on_tick not linked to the Play button)")


def check_play(page, ex):
    cv = _canvas(ex)
    reset = ex.locator("button").filter(has_text="Reset").first
    if reset.count():                 # from the default state (a drag may leave a motion that ends at once)
        reset.click()
        time.sleep(1.0)
    play = ex.locator(".widget-play button").first
    play.scroll_into_view_if_needed()
    p0 = _stats(cv)["painted"]
    t0 = _ticks(page)
    play.click()
    _wait_for(lambda: _stats(cv)["painted"] >= p0 + 5, 20, "five frames painted while playing")
    PLAY_TICKS[0] = _ticks(page) - t0
    pause = ex.locator(".widget-play button").nth(1)
    if pause.count():
        pause.click()
    time.sleep(1.0)
    p1 = _stats(cv)["painted"]
    time.sleep(1.0)
    assert _stats(cv)["painted"] <= p1 + 1, "frames still painted a second after pause"


def check_export(page, ex, tmp: Path):
    button = ex.locator("button", has_text="SVG").first
    button.scroll_into_view_if_needed()
    got = []

    def on_download(d):
        got.append(d)

    page.on("download", on_download)
    try:
        button.click()
        _wait_for(lambda: got, 5, "a download from the button")
    except AssertionError:
        link = ex.locator("a[download]").last
        link.wait_for(state="visible", timeout=15_000)
        with page.expect_download(timeout=15_000) as info:
            link.click()
        got.append(info.value)
    finally:
        page.remove_listener("download", on_download)
    path = tmp / (got[0].suggested_filename or "export.svg")
    got[0].save_as(path)
    text = path.read_bytes().decode("utf-8", "replace")
    assert "<svg" in text[:400] or text.startswith("<?xml"), text[:100]
    # the export draws the picture the page shows: each element and label the page draws is in it, by id
    ids = {html.unescape(i) for i in re.findall(r'<g id="([^"]+)"', text)}
    shown = page.evaluate("""(cv) => [...cv.querySelectorAll('.pg-el')].filter((g) => g.childElementCount)
        .map((g) => [g.dataset.id, [...g.querySelectorAll('text')].some((t) => t.textContent)])""",
                          _canvas(ex).element_handle())
    missing = ([i for i, _ in shown if i not in ids and f"{i}:label" not in ids]      # a text alone: its label
               + [f"{i}:label" for i, lab in shown if lab and f"{i}:label" not in ids])
    assert not missing, f"the exported SVG lacks what the page shows: {missing[:8]}"


def in_flight_violations(wire: list[dict]) -> list[str]:
    """Requests a page sent while its previous request was unanswered (per canvas), from the wire log."""
    out, open_ = [], {}
    for m in wire:
        if m.get("unreadable"):
            continue
        comm = m["comm"]
        if m["dir"] == "out":
            if open_.get(comm):
                out.append(f"canvas {comm[:8]}: {m['type']} #{m['seq']} sent while #{open_[comm]} was unanswered")
            open_[comm] = m["seq"]
        elif open_.get(comm) == m["seq"]:
            open_[comm] = None
    return out


#: per explorer, per check: "ok" or the failure (written to the artifacts for the report)
RESULTS: dict[str, dict[str, str]] = {}

#: (explorer, check) -> why it fails today.  Strict: the run fails on any other failure, and
#: also when one of these passes (then its entry must go); with only these, it is an xfail.
KNOWN: dict[tuple[str, str], str] = {
}


def _try(what, failures, name, fn):
    try:
        out = fn()
        if isinstance(out, list) and out:
            failures += [f"{name}: {what}: {p}" for p in out]
            RESULTS.setdefault(name, {})[what] = "; ".join(out)[:300]
        else:
            RESULTS.setdefault(name, {})[what] = "ok"
    except Exception as exc:  # noqa: BLE001 - collected: one explorer's failure does not hide the others'
        failures.append(f"{name}: {what}: {type(exc).__name__}: {str(exc)[:300]}")
        RESULTS.setdefault(name, {})[what] = f"{type(exc).__name__}: {str(exc)[:200]}"


def run_all(page, names: list[str], tmp: Path, screens: Path | None = None) -> list[str]:
    """Every check on every explorer of the page; the failures, collected."""
    import planargeo.widgets as pw

    explorers = page.locator(".planargeo-explorer")
    _wait_for(lambda: explorers.count() == len(names), 300, f"{len(names)} explorers")
    failures = []
    for k, name in enumerate(names):
        ex = explorers.nth(k)
        cv = _canvas(ex)
        try:
            ex.scroll_into_view_if_needed()
            _wait_for(lambda: cv.locator(".pg-el").count() > 0, 90, f"{name}: the picture drawn")
        except AssertionError as exc:
            failures.append(f"{name}: {exc}")
            continue
        time.sleep(0.3)
        if screens is not None:
            screens.mkdir(parents=True, exist_ok=True)
            ex.screenshot(path=str(screens / f"{getattr(pw, name).slug}.png"))
        _try("layout", failures, name, lambda: check_layout(page, ex))
        _try("drag", failures, name, lambda: check_drag(page, ex))
        _try("slider", failures, name, lambda: check_slider(page, ex))
        _try("layout after the drag and slider", failures, name, lambda: check_layout(page, ex))
        _try("zoom/pan/reset", failures, name, lambda: check_view(page, ex))
        _try("hover", failures, name, lambda: check_hover(page, ex))
        if ex.locator(".widget-play").count():
            PLAY_TICKS[0] = 0
            _try("play", failures, name, lambda: check_play(page, ex))
            _try("play paced by the page", failures, name, lambda: check_play_paced(page, ex))
        _try("export", failures, name, lambda: check_export(page, ex, tmp))
    wire = page.evaluate("window.__pgWire || []")
    RESULTS["_wire"] = {"requests": str(sum(m.get("dir") == "out" for m in wire)),
                        "acks": str(sum(m.get("dir") == "in" for m in wire))}
    if not any(m.get("dir") == "in" for m in wire):
        failures.append(f"no acknowledgement read off the websocket ({len(wire)} messages): cannot check one in flight")
    failures += in_flight_violations(wire)
    return failures


def watch_network(page) -> list[str]:
    """Record every URL the page requests (the list fills as the page runs)."""
    urls: list[str] = []
    page.on("request", lambda r: urls.append(r.url))
    return urls


def off_localhost(urls: list[str]) -> list[str]:
    out = []
    for u in urls:
        p = urlparse(u)
        if p.scheme in ("data", "blob", "about", "chrome-extension"):
            continue
        if p.hostname not in ("127.0.0.1", "localhost"):
            out.append(u)
    return sorted(set(out))


def finish(page, failures: list[str], urls: list[str], name: str) -> None:
    """Fail on any failure not in :data:`KNOWN`, or on a known one that passes; xfail on known ones."""
    failures = failures + [f"request off localhost: {u}" for u in off_localhost(urls)]
    ARTIFACTS.mkdir(exist_ok=True)
    results = dict(RESULTS)
    RESULTS.clear()
    (ARTIFACTS / f"{name}-results.json").write_text(json.dumps(
        {"results": results, "requests": len(urls), "off_localhost": off_localhost(urls)},
        indent=1, ensure_ascii=False))
    known = [f for f in failures if any(f.startswith(f"{n}: {c}:") for n, c in KNOWN)]
    fixed = [f"{n}: {c} passes now: remove it from KNOWN" for n, c in KNOWN
             if results.get(n, {}).get(c) == "ok"]
    other = [f for f in failures if f not in known] + fixed
    if other:
        page.screenshot(path=str(ARTIFACTS / f"{name}-failure.png"), full_page=True)
        (ARTIFACTS / f"{name}-failures.json").write_text(json.dumps(other, indent=1, ensure_ascii=False))
    assert not other, f"{len(other)} failures:\n" + "\n".join(other)
    if known:
        pytest.xfail("known: " + "; ".join(known))


def test_the_in_flight_rule_reads_the_wire():
    """The in-flight check itself: a second request before the first's ack is seen; after it, not."""
    ok = [{"dir": "out", "comm": "c1", "seq": 1, "type": "drag"}, {"dir": "in", "comm": "c1", "seq": 1},
          {"dir": "out", "comm": "c1", "seq": 2, "type": "drag"}, {"dir": "out", "comm": "c2", "seq": 1, "type": "view"}]
    assert in_flight_violations(ok) == []
    bad = ok + [{"dir": "out", "comm": "c1", "seq": 3, "type": "drag"}]
    assert in_flight_violations(bad) == ["canvas c1: drag #3 sent while #2 was unanswered"]
    assert off_localhost(["http://127.0.0.1:8888/x", "data:image/png;base64,", "https://cdn.jsdelivr.net/a.js"]) \
        == ["https://cdn.jsdelivr.net/a.js"]


def test_every_explorer_in_jupyterlab(lab, browser, tmp_path):
    """The app's explorers in the page, in JupyterLab (one server, one page)."""
    names = page_app(lab.root / "page-under-test.ipynb")
    page = browser.new_page(viewport={"width": 1500, "height": 1000}, accept_downloads=True)
    page.add_init_script(WIRE_HOOK)
    urls = watch_network(page)
    try:
        page.goto(f"{lab.url}/lab/tree/page-under-test.ipynb?reset", wait_until="domcontentloaded",
                  timeout=60_000)
        page.wait_for_function("window.jupyterapp && window.jupyterapp.shell.currentWidget"
                               " && window.jupyterapp.shell.currentWidget.sessionContext.session"
                               " && window.jupyterapp.shell.currentWidget.sessionContext.session.kernel",
                               timeout=60_000)
        page.evaluate("window.jupyterapp.commands.execute('notebook:run-all-cells')")
        failures = run_all(page, names, tmp_path)
        finish(page, failures, urls, "page-lab")
    finally:
        page.close()
