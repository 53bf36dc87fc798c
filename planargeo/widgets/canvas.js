// planargeo's page renderer: draws a picture (planargeo.draw.picture) as SVG, live.  canvas.py
// sends it as one module: canvas_parts.js (what is drawn: SVG nodes, glyphs, numbers), then this.
//
// The picture arrives as keyed updates (canvas.py's docstring): each element keeps its SVG group,
// found by id; only the elements whose data changed are redrawn, writing only the attributes whose
// value changed; the handles keep their nodes.  A view starts from the synced "snapshot" and asks
// for the whole picture ("sync") whenever an update does not apply to its version.
// What happens in the page, at once:
//   * the figure fits its container: shrunk (its text drawn larger, never shown below MIN_TEXT_PX)
//     as long as the text grows at most MAX_TEXT_GROW times; narrower, a horizontal scrollbar;
//     pointer positions are read in the shown scale;
//   * a dragged handle follows the pointer in the same animation frame; arrow keys nudge the
//     handle last clicked or marked with Tab / Shift-Tab, and letting go of them ends the
//     nudges as a mouse-up ends a drag;
//   * zoom (wheel), pan (drag the background) and reset move the drawing at once;
//   * hover highlights the element nearest the pointer and shows its description, kept inside
//     the figure (asked of the kernel when the picture changed since it was last asked); a
//     click focuses it, a click on the background (or the element leaving) ends the focus;
//   * a "download" message from the kernel (an export's file) is saved at once.
// What goes to the kernel: {type: "drag" | "release" | "view" | "tick" | "describe" | "sync" |
// "ping", ...}, at most one in flight; while one is in flight only the latest request of each
// type is kept (in the order last asked), and the next is sent when the kernel's "ack" arrives.
// While the synced "playing" is true, a "tick" is sent as soon as the previous reply has arrived
// (the kernel computes the next frame while the page paints this one, and sends one more frame
// alone halfway to the next tick; a "halt" message says that Play was refused in such a frame).
// While Play runs the page shows at most one new picture per animation frame: frames that arrive
// together are shown one after the other (at most two wait), not painted over each other.

// text is never shown smaller than this (CSS pixels): a shrunk figure draws its labels larger
const MIN_TEXT_PX = 11;
// ... but at most this many times their size (the labels were placed for their own size): the
// figure shrinks down to MIN_TEXT_PX / (MAX_TEXT_GROW × its font); narrower, a scrollbar
const MAX_TEXT_GROW = 1.15;
// pointer tolerance for hover / click (CSS pixels): the nearest element within it is hit
const HIT_PX = 6;
// the pointer resting this long on a handle asks for the description of what lies under it (ms)
const HANDLE_DESC_MS = 250;

function render({ model, el }) {
  const client = Math.random().toString(36).slice(2);
  const root = document.createElement("div");
  root.className = "pg-canvas";
  root.style.overscrollBehaviorX = "contain";   // a sideways scroll ends at its edge
  const bar = document.createElement("div");
  bar.className = "pg-bar";
  const reset = document.createElement("button");
  reset.textContent = "reset view";
  reset.title = "Back to the explorer's own view (wheel: zoom, drag the background: pan)";
  const status = document.createElement("span");
  status.className = "pg-status";
  bar.append(reset, status);
  const svg = mk("svg", { tabindex: "0", role: "img" });
  const tip = document.createElement("div");
  tip.className = "pg-tip";
  tip.style.display = "none";
  root.append(bar, svg, tip);
  // the widget's own box is never wider than its container (in a notebook its layout says so:
  // canvas.py); a figure too wide to shrink scrolls inside it (root: overflow-x auto)
  el.appendChild(root);

  // the picture held: its version, view, elements by id (wire format), handles
  const st = { version: null, head: null, order: [], els: new Map(), handles: [], tips: {} };
  let W = 0, H = 0, ml = 0, mt = 0, pw = 0, ph = 0, box = null, kx = 1, ky = 1, localBox = null;
  let frame = null;             // {plot, axes, title, inner, handleLayer, clipRect, bg, border}
  const nodes = new Map();      // element id -> its <g>
  const circles = new Map();    // handle id -> its <circle>
  const descs = new Map();      // element id -> {version, text}
  let focusId = null, focusHandle = null, hoverId = null, lastPointer = null, descTimer = null;
  let drag = null, pan = null;
  let inflight = false, seq = 0, tickHalted = false, syncAsked = false;
  const pending = new Map();    // request type -> the latest request of that type
  const handlePaints = [];
  const arrivals = [];          // when each update sent alone arrived (for benchmarks)

  // the shown scale: CSS pixels per SVG unit (the figure fits its container, see buildFrame)
  let shown = 1;
  function rescale() {
    if (!W) return;
    const w = svg.getBoundingClientRect().width;
    const s = w > 0 ? w / W : 1;
    shown = s;
    const font = st.head && st.head.font_px ? st.head.font_px : 12;
    svg.style.setProperty("--pg-font", `${Math.max(font, MIN_TEXT_PX / s)}px`);
    for (const c of circles.values()) setChanged(c, { r: f2(8 / Math.min(s, 1)) });
  }
  if (typeof ResizeObserver !== "undefined") new ResizeObserver(() => rescale()).observe(svg);

  const X = (x) => (x - box[0]) * kx;
  const Y = (y) => ph - (y - box[2]) * ky;
  const dataOf = (px, py) => [box[0] + px / kx, box[2] + (ph - py) / ky];

  // timings of each request, for benchmarks: input event, sent, acknowledged, picture painted
  const stats = [];
  let current = null;
  function send(msg, tInput) {
    // the latest of each type, kept in the order last asked: a release asked after a drag goes after it
    if (inflight) { pending.delete(msg.type); pending.set(msg.type, { msg, tInput }); return; }
    inflight = true;
    seq += 1;
    current = { seq, type: msg.type, tInput: tInput ?? performance.now(), tSent: performance.now() };
    stats.push(current);
    if (stats.length > 1000) stats.shift();
    model.send({ ...msg, seq, client });
  }
  function sendNext() {
    if (inflight || !pending.size) return false;
    const [type, p] = pending.entries().next().value;
    pending.delete(type);
    send(p.msg, p.tInput);
    return true;
  }
  function maybeTick() {
    if (model.get("playing") && !tickHalted && !inflight && !pending.size && !drag) send({ type: "tick" });
  }
  function say(text) {          // beside "reset view" (whole in its title); written only when it changes
    if (status.textContent !== text) status.title = status.textContent = text;
  }
  function askSync() {
    if (syncAsked) return;
    syncAsked = true;
    send({ type: "sync", version: st.version });
  }

  model.on("msg:custom", (m) => {
    if (!m) return;
    if (m.type === "update") {     // a new state shown: a refusal said beside "reset view" is past
      nPushed += 1;
      if (!tickHalted) say("");
      arrivals.push(performance.now());
      if (arrivals.length > 1000) arrivals.shift();
      applyFrame(m);
      return;
    }
    if (m.type === "download") {    // an export button's file: saved at once (the view last used)
      if (m.client && m.client !== client) return;
      download(m.name, m.mime, m.data);
      return;
    }
    if (m.type === "halt") {        // Play refused in a frame the kernel sent alone
      say(m.message || "");
      tickHalted = true;
      return;
    }
    if (m.type !== "ack") return;
    const mine = m.client === client || m.client === null || m.client === undefined;
    const tAck = performance.now();
    if (!mine) {
      if (m.update && m.update.base !== null) applyFrame(m.update);
      return;
    }
    const done = current;
    inflight = false;
    // Play: the next frame is asked for before this one is drawn, so the kernel computes it
    // while the page applies and paints this one (still one request in flight)
    if (done && done.type === "tick" && m.ok !== false && !pending.size) maybeTick();
    if (m.update) applyFrame(m.update);
    if (done) { done.tAck = tAck; done.tApplied = performance.now(); done.kernelMs = m.ms; }
    requestAnimationFrame(() => {
      if (!done) return;
      done.tPaint = performance.now();
      // the end of that frame's main-thread work (style, layout, paint): a task posted from its rAF
      const ch = new MessageChannel();
      ch.port1.onmessage = () => { done.tFrame = performance.now(); };
      ch.port2.postMessage(0);
    });
    say(m.ok === false && m.message && !m.said ? m.message : "");
    if (done && done.type === "sync") syncAsked = false;
    if (done && done.type === "tick" && m.ok === false) tickHalted = true;
    if (done && done.type === "view" && !m.update?.head && !pending.has("view")) clearLocalView();
    if (m.desc !== undefined && m.id) {
      descs.set(m.id, { version: st.version, text: m.desc });
      if (hoverId === m.id && tip.style.display !== "none") {
        tip.textContent = m.desc;
        if (lastPointer) placeTip(lastPointer[0], lastPointer[1]);    // its new size kept inside
      }
    }
    if (!sendNext() && !drag) placeHandles();
    // Play: the next frame, if not asked for yet (the wall clock sets how far each frame goes)
    maybeTick();
  });
  model.on("change:playing", () => { tickHalted = false; maybeTick(); });

  function download(name, mime, b64) {
    // the bytes as a Blob, saved through a temporary link (no server: works offline)
    const bin = atob(b64), bytes = new Uint8Array(bin.length);
    for (let i = 0; i < bin.length; i++) bytes[i] = bin.charCodeAt(i);
    const url = URL.createObjectURL(new Blob([bytes], { type: mime || "application/octet-stream" }));
    const a = document.createElement("a");
    a.href = url;
    a.download = name;
    a.style.display = "none";
    root.appendChild(a);
    a.click();
    a.remove();
    setTimeout(() => URL.revokeObjectURL(url), 60_000);
  }

  function localPoint(ev) {
    // the pointer in the plot's SVG units (the figure may be shown smaller than its size)
    const r = svg.getBoundingClientRect(), s = r.width > 0 && W ? r.width / W : 1;
    return [(ev.clientX - r.left) / s - ml, (ev.clientY - r.top) / s - mt];
  }

  // ------------------------------------------------------------------ drawing
  function drawPart(put, q, e) {
    const k = q[0];
    if (k === "P") {
      let d = "";
      for (let i = 2; i + 1 < q.length; i += 2) d += (i > 2 ? "L" : "M") + f2(X(q[i])) + " " + f2(Y(q[i + 1]));
      if (q[1]) d += "Z";
      const a = { d, fill: e.fill || "none", stroke: e.color, "stroke-width": e.width ?? 1.8 };
      if (e.fill) a["fill-opacity"] = e.alpha ?? 1;
      if (e.dash) a["stroke-dasharray"] = e.dash.join(" ");
      put("path", a);
    } else if (k === "E") {
      // the unit circle under the picture's affine map (data units), sampled here
      const [, cx, cy, a, b, c, dd] = q;
      let p = "";
      for (let i = 0; i < CIRCLE_N; i++) {
        const [u, v] = CIRCLE[i];
        p += (i ? "L" : "M") + f2(X(cx + a * u + b * v)) + " " + f2(Y(cy + c * u + dd * v));
      }
      const at = { d: p + "Z", fill: "none", stroke: e.color, "stroke-width": e.width ?? 1.8 };
      if (e.dash) at["stroke-dasharray"] = e.dash.join(" ");
      put("path", at);
    } else if (k === "M") {
      const x = X(q[1]), y = Y(q[2]), s = q[4] / 2;
      if (q[3] === "D") {
        put("path", { d: `M${x} ${y - s * 1.2}L${x + s} ${y}L${x} ${y + s * 1.2}L${x - s} ${y}Z`,
                     fill: e.color, stroke: "white", "stroke-width": 0.8 });
      } else if (q[3] === "s") {
        put("rect", { x: x - s, y: y - s, width: 2 * s, height: 2 * s, fill: e.color,
                     stroke: "white", "stroke-width": 0.8 });
      } else {
        put("circle", { cx: x, cy: y, r: s, fill: e.color, stroke: "white", "stroke-width": 0.8 });
      }
    } else if (k === "G") {
      // the glyph drawn once about its centre, moved there
      const [arc, head] = glyphPaths(q[3], !!q[4]), at = `translate(${f2(X(q[1]))},${f2(Y(q[2]))})`;
      put("path", { d: arc, transform: at, fill: "none", stroke: e.color, "stroke-width": 1.6 });
      put("path", { d: head, transform: at, fill: e.color });
    } else if (k === "A") {
      const x = X(q[1]), y = Y(q[2]), x2 = x + q[3], y2 = y - q[4];
      const L = Math.hypot(q[3], q[4]) || 1, ux = q[3] / L, uy = -q[4] / L,
            h = Math.max(8, 4 * (e.width || 0));   // the head grows with the line it marks
      put("line", { x1: x, y1: y, x2: x2 - ux * h * 0.8, y2: y2 - uy * h * 0.8, stroke: e.color,
                   "stroke-width": 1.9 });
      put("path", { d: `M${x2} ${y2}L${x2 - ux * h - uy * h * 0.35} ${y2 - uy * h + ux * h * 0.35}` +
                      `L${x2 - ux * h + uy * h * 0.35} ${y2 - uy * h - ux * h * 0.35}Z`, fill: e.color });
    } else if (k === "T") {
      const t = put("text", { x: X(q[1]) + q[3], y: Y(q[2]) - q[4], fill: e.color,
                             "font-size": st.head.font_px,
                             "text-anchor": ANCHOR[q[6][0]] || "start",
                             "dominant-baseline": BASELINE[q[6][1]] || "text-after-edge" });
      if (t.textContent !== q[5]) t.textContent = q[5];
    }
  }

  function drawElement(id) {
    const e = st.els.get(id);
    let g = nodes.get(id);
    if (!g) {
      g = mk("g", { "data-id": id, class: "pg-el" });
      nodes.set(id, g);
    }
    g.classList.toggle("pg-faded", !!focusId && focusId !== id);
    setChanged(g, { opacity: e.opacity !== undefined && e.opacity !== 1 ? e.opacity : null,
                    "data-described": e.d ? "" : null, "data-role": e.role || null });
    // the same kinds of parts as drawn last: their nodes are kept and only moved
    const parts = e.parts || [];
    let sig = (e.fill ? "f" : "") + (e.dash ? "d" : "") + ":";
    for (const q of parts) sig += q[0] === "M" ? "M" + q[3] : q[0];
    const kids = g.childNodes;
    let i = 0;
    const reuse = g.__sig === sig;
    const put = reuse
      ? (tag, attrs) => setChanged(kids[i++], attrs)
      : (tag, attrs) => setChanged(mk(tag, {}, g), attrs);
    if (!reuse) g.textContent = "";
    for (const q of parts) drawPart(put, q, e);
    g.__sig = sig;
  }

  function buildFrame() {
    // the parts that depend on the view only: size, clip, title, ticks, lines below, background, border
    const h = st.head;
    svg.textContent = "";
    nodes.clear();
    circles.clear();
    frame = null;
    if (!h || !h.size) return false;
    [W, H] = h.size;
    [ml, , mt] = h.margin;
    pw = W - h.margin[0] - h.margin[1];
    ph = H - h.margin[2] - h.margin[3];
    box = h.box;
    localBox = null;
    kx = pw / (box[1] - box[0]);
    ky = ph / (box[3] - box[2]);
    svg.setAttribute("width", W);
    bar.style.maxWidth = `${W}px`;  // the status line is cut at the figure's width (whole: its title)
    svg.setAttribute("height", H);
    svg.setAttribute("viewBox", `0 0 ${W} ${H}`);
    // shown at the container's width when narrower (aspect kept), down to the smallest scale
    // whose text is MIN_TEXT_PX when drawn MAX_TEXT_GROW times larger; narrower still, a
    // horizontal scrollbar.  The labels' shown size stays at least MIN_TEXT_PX.
    const minScale = Math.min(1, MIN_TEXT_PX / (MAX_TEXT_GROW * (h.font_px || MIN_TEXT_PX)));
    svg.style.width = "100%";
    svg.style.maxWidth = `${W}px`;
    svg.style.minWidth = `${Math.ceil(W * minScale)}px`;
    rescale();
    const defs = mk("defs", {}, svg);
    const clipId = "pgclip" + Math.random().toString(36).slice(2);
    mk("rect", { x: 0, y: 0, width: pw, height: ph }, mk("clipPath", { id: clipId }, defs));
    if (h.title) {
      const t = mk("text", { x: W / 2, y: 16, "text-anchor": "middle", "font-size": h.font_px + 1,
                             class: "pg-title" }, svg);
      t.textContent = h.title;
    }
    const plot = mk("g", { transform: `translate(${ml},${mt})` }, svg);
    mk("rect", { x: 0, y: 0, width: pw, height: ph, class: "pg-bg" }, plot);
    if (h.ticks) {
      const axes = mk("g", { class: "pg-axes" }, plot);
      for (const v of h.ticks.x) {
        const x = X(v);
        mk("line", { x1: x, y1: ph, x2: x, y2: ph + 4 }, axes);
        const t = mk("text", { x, y: ph + 6, "text-anchor": "middle", "dominant-baseline": "text-before-edge",
                               "font-size": h.font_px }, axes);
        t.textContent = fmtTick(v);
      }
      for (const v of h.ticks.y) {
        const y = Y(v);
        mk("line", { x1: -4, y1: y, x2: 0, y2: y }, axes);
        const t = mk("text", { x: -6, y, "text-anchor": "end", "dominant-baseline": "central",
                               "font-size": h.font_px }, axes);
        t.textContent = fmtTick(v);
      }
    }
    // lines below the plot, under the x tick labels (a key no corner had room for): y down
    for (const b of h.below || []) {
      const t = mk("text", { x: b.x, y: ph + b.y, fill: b.color, "dominant-baseline": "text-before-edge",
                             "font-size": h.font_px, class: "pg-below", "data-below": b.id }, plot);
      t.textContent = b.text;
      if (b.desc) mk("title", {}, t).textContent = b.desc;
    }
    const content = mk("g", { "clip-path": `url(#${clipId})` }, plot);
    const inner = mk("g", { class: "pg-content" }, content);
    mk("rect", { x: 0, y: 0, width: pw, height: ph, class: "pg-frame" }, plot);
    const handleLayer = mk("g", { class: "pg-handles" }, plot);
    frame = { inner, handleLayer };
    return true;
  }

  let nPaint = 0, nPushed = 0, paintAsked = false;
  const paintTimes = [];
  const applyTimes = [];         // milliseconds each update took to apply (for benchmarks)
  // While Play runs, at most one new picture per animation frame: a frame that arrives when
  // one is already waiting to be painted waits for the next animation frame (at most two wait;
  // beyond that the oldest are applied at once, only display frames dropped).  Frames that
  // arrive together (the page was busy) are so shown one after the other, not in one paint.
  const waiting = [];
  let waitArmed = false;
  function applyFrame(u) {
    if (!model.get("playing") && !waiting.length) { apply(u); return; }
    if (!paintAsked && !waiting.length) { apply(u); return; }
    waiting.push(u);
    while (waiting.length > 2) apply(waiting.shift());
    armWaiting();
  }
  function armWaiting() {
    if (waitArmed) return;
    waitArmed = true;
    // asked after the paint's own callback (same frame, called in order): it has counted the last picture
    requestAnimationFrame(() => {
      waitArmed = false;
      if (!waiting.length) return;
      apply(waiting.shift());
      if (waiting.length) armWaiting();
    });
  }
  function apply(u) {
    if (u.base === null || u.base === undefined) while (waiting.length) applyUpdate(waiting.shift());
    const t0 = performance.now();
    applyUpdate(u);
    applyTimes.push(performance.now() - t0);
    if (applyTimes.length > 1000) applyTimes.shift();
  }
  function applyUpdate(u) {
    const full = u.base === null || u.base === undefined;
    if (!full && u.base !== st.version) { askSync(); return; }
    if (full && u.version === st.version && frame) return;      // already held
    let rebuild = full || !!u.head;
    if (full) { st.els = new Map(); st.order = []; st.handles = []; st.tips = {}; descs.clear(); }
    if (u.head) st.head = u.head;
    const changed = [];
    if (u.set) {
      for (const id in u.set) {
        const d = u.set[id], e = full ? {} : { ...(st.els.get(id) || {}) };
        for (const k in d) { if (d[k] === null) delete e[k]; else e[k] = d[k]; }
        st.els.set(id, e);
        changed.push(id);
      }
    }
    if (u.order) {
      st.order = u.order;
      const keep = new Set(u.order);
      for (const id of [...st.els.keys()]) if (!keep.has(id)) st.els.delete(id);
    }
    if (u.handles) st.handles = u.handles;
    if (u.tips) st.tips = u.tips;
    st.version = u.version;
    nPaint += 1;
    if (!paintAsked) {              // one entry per animation frame that shows a new picture
      paintAsked = true;
      requestAnimationFrame(() => {
        paintAsked = false;
        paintTimes.push(performance.now());
        if (paintTimes.length > 1000) paintTimes.shift();
      });
    }
    if (rebuild) { if (!buildFrame()) return; }
    if (!frame) return;
    // elements: drop the gone, redraw the changed (all after a new view), keep the order
    for (const [id, g] of nodes) if (!st.els.has(id)) { g.remove(); nodes.delete(id); }
    if (focusId !== null && !st.els.has(focusId)) setFocus(null);    // its element is gone: no focus
    for (const id of rebuild ? st.order : changed) if (st.els.has(id)) drawElement(id);
    if (rebuild || u.order || changed.some((id) => nodes.has(id) && !nodes.get(id).parentNode)) {
      const inner = frame.inner;
      let at = inner.firstChild;
      for (const id of st.order) {
        const g = nodes.get(id);
        if (!g) continue;
        if (g === at) at = at.nextSibling;
        else inner.insertBefore(g, at);
      }
    }
    if (localBox) setLocalView(localBox);
    // handles: one circle each, kept while the handle is there
    const seen = new Set();
    for (const [id] of st.handles) {
      seen.add(id);
      let c = circles.get(id);
      if (!c) {
        c = mk("circle", { r: f2(8 / Math.min(shown, 1)), "data-handle": id, class: "pg-handle", tabindex: "-1" },
               frame.handleLayer);
        mk("title", {}, c);
        circles.set(id, c);
      }
      if (u.tips || rebuild || !c.firstChild.textContent) c.firstChild.textContent = st.tips[id] || "drag";
    }
    for (const [id, c] of circles) if (!seen.has(id)) { c.remove(); circles.delete(id); }
    if (focusHandle !== null && !seen.has(focusHandle)) focusHandle = null;
    markHandle();
    placeHandles();
  }

  function setLocalView(b) {
    // show the drawn picture in the box b at once (a transform), until the kernel's redraw arrives
    if (!frame) return;
    const b0 = st.head.box;
    localBox = b;
    box = b;
    kx = pw / (b[1] - b[0]);
    ky = ph / (b[3] - b[2]);
    const s = kx / (pw / (b0[1] - b0[0]));
    const tx = (b0[0] - b[0]) * kx, ty = ph * (1 - s) - (b0[2] - b[2]) * ky;
    frame.inner.setAttribute("transform", `translate(${tx},${ty}) scale(${s})`);
    placeHandles();
  }

  function clearLocalView() {
    if (!localBox || !frame) return;
    localBox = null;
    box = st.head.box;
    kx = pw / (box[1] - box[0]);
    ky = ph / (box[3] - box[2]);
    frame.inner.removeAttribute("transform");
    placeHandles();
  }

  function placeHandles() {
    if (!frame) return;
    for (const [id, x, y] of st.handles) {
      const c = circles.get(id);
      if (!c) continue;
      if (drag && drag.id === id) {  // the dragged one stays under the pointer
        if (drag.circle !== c) {
          setChanged(c, { cx: drag.circle.getAttribute("cx"), cy: drag.circle.getAttribute("cy") });
          c.classList.add("pg-dragging");
          drag.circle = c;
        }
        continue;
      }
      setChanged(c, { cx: X(x), cy: Y(y) });
    }
  }

  // ------------------------------------------------------------------ hit-testing
  // The element under the pointer is the one nearest it among those within HIT_PX (shown
  // pixels), not the first drawn there: a thin line under a larger element can be hovered.
  // Ties (within a pixel) go to the topmost (drawn last).  The inside of a filled shape counts as near, but
  // less near than a line or mark within the tolerance.
  function segDist(px, py, ax, ay, bx, by) {
    const dx = bx - ax, dy = by - ay, L2 = dx * dx + dy * dy;
    let t = L2 > 0 ? ((px - ax) * dx + (py - ay) * dy) / L2 : 0;
    t = Math.max(0, Math.min(1, t));
    return Math.hypot(px - ax - t * dx, py - ay - t * dy);
  }
  function polyDist(pts, closed, filled, px, py, tol) {
    let d = Infinity, inside = false;
    const n = pts.length;
    for (let i = 0; i + 1 < n; i++) d = Math.min(d, segDist(px, py, pts[i][0], pts[i][1], pts[i + 1][0], pts[i + 1][1]));
    if (n === 1) d = Math.hypot(px - pts[0][0], py - pts[0][1]);
    if (closed && n > 2) d = Math.min(d, segDist(px, py, pts[n - 1][0], pts[n - 1][1], pts[0][0], pts[0][1]));
    if (filled && n > 2) {
      for (let i = 0, j = n - 1; i < n; j = i++) {
        const [xi, yi] = pts[i], [xj, yj] = pts[j];
        if ((yi > py) !== (yj > py) && px < ((xj - xi) * (py - yi)) / (yj - yi) + xi) inside = !inside;
      }
      if (inside) d = Math.min(d, 0.9 * tol);
    }
    return d;
  }
  function elementDist(e, g, px, py, tol, r, s) {
    let d = Infinity;
    for (const q of e.parts || []) {
      const k = q[0];
      if (k === "P") {
        const pts = [];
        for (let i = 2; i + 1 < q.length; i += 2) pts.push([X(q[i]), Y(q[i + 1])]);
        d = Math.min(d, polyDist(pts, !!q[1], !!e.fill, px, py, tol));
      } else if (k === "E") {
        const [, cx, cy, a, b, c, dd] = q, pts = CIRCLE.map(([u, v]) => [X(cx + a * u + b * v), Y(cy + c * u + dd * v)]);
        d = Math.min(d, polyDist(pts, true, false, px, py, tol));
      } else if (k === "M") {
        d = Math.min(d, Math.max(0, Math.hypot(px - X(q[1]), py - Y(q[2])) - q[4] / 2));
      } else if (k === "G") {
        d = Math.min(d, Math.abs(Math.hypot(px - X(q[1]), py - Y(q[2])) - q[3]));
      } else if (k === "A") {
        const x = X(q[1]), y = Y(q[2]);
        d = Math.min(d, segDist(px, py, x, y, x + q[3], y - q[4]));
      }
    }
    for (const t of g.querySelectorAll("text")) {     // a label: its box as shown
      const b = t.getBoundingClientRect();
      if (!b.width) continue;
      const x0 = (b.left - r.left) / s - ml, x1 = (b.right - r.left) / s - ml;
      const y0 = (b.top - r.top) / s - mt, y1 = (b.bottom - r.top) / s - mt;
      d = Math.min(d, Math.hypot(Math.max(x0 - px, 0, px - x1), Math.max(y0 - py, 0, py - y1)));
    }
    return d;
  }
  function hitAt(px, py) {
    if (!frame || !box) return null;
    const r = svg.getBoundingClientRect(), s = r.width > 0 && W ? r.width / W : 1;
    const tol = HIT_PX / s;
    if (px < -tol || py < -tol || px > pw + tol || py > ph + tol) return null;
    let best = null, bestD = Infinity;
    for (const id of st.order) {             // drawn first to last: a tie goes to the later
      const e = st.els.get(id), g = nodes.get(id);
      if (!e || !g || !g.parentNode) continue;
      const d = elementDist(e, g, px, py, tol, r, s);
      // within a pixel of the nearest: a tie (lines drawn on each other), the later wins
      if (d <= tol && d <= bestD + 1 / s) { best = id; bestD = Math.min(d, bestD); }
    }
    return best;
  }
  function setFocus(id) {
    focusId = id && st.els.has(id) ? id : null;
    for (const [k, n] of nodes) n.classList.toggle("pg-faded", !!focusId && k !== focusId);
  }

  function showTip(ev, id) {
    const e = st.els.get(id);
    if (!e || !e.d) { tip.style.display = "none"; return; }
    const known = descs.get(id);
    if (known && known.version === st.version) tip.textContent = known.text;
    else {
      tip.textContent = (e.symbol ? e.symbol + " \u2014 " : "") + "\u2026";
      if (hoverId !== id || !known || known.asked !== st.version) {
        const ask = () => {
          descTimer = null;
          if (hoverId !== id || drag) return;
          const k = descs.get(id);
          descs.set(id, { ...(k || {}), asked: st.version });
          send({ type: "describe", id });
        };
        clearTimeout(descTimer);
        // on a handle the pointer may be about to drag: asked once it rests (a drag's first
        // request does not wait behind a description)
        const onHandle = ev.target && ev.target.dataset && ev.target.dataset.handle;
        if (onHandle) {
          if (hoverId !== id || !descTimer) descTimer = setTimeout(ask, HANDLE_DESC_MS);
        } else { hoverId = id; ask(); }
      }
    }
    hoverId = id;
    tip.style.display = "block";
    placeTip(ev.clientX, ev.clientY);
  }
  function placeTip(cx, cy) {
    // beside the pointer, flipped to its other side (and then clamped) so that the whole box
    // stays inside the figure as shown (the part of it in view when the figure scrolls)
    const r = root.getBoundingClientRect(), f = svg.getBoundingClientRect();
    const left = Math.max(f.left, r.left), right = Math.min(f.right, r.right);
    const top = Math.max(f.top, r.top), bottom = Math.min(f.bottom, r.bottom);
    tip.style.maxWidth = `${Math.max(80, Math.min(210, right - left - 4))}px`;
    const tw = tip.offsetWidth, th = tip.offsetHeight;
    let x = cx + 12, y = cy + 14;
    if (x + tw > right) x = cx - 12 - tw;
    if (y + th > bottom) y = cy - 10 - th;
    x = Math.max(left, Math.min(x, right - tw));
    y = Math.max(top, Math.min(y, bottom - th));
    tip.style.left = `${x - r.left + root.scrollLeft}px`;
    tip.style.top = `${y - r.top + root.scrollTop}px`;
  }

  svg.addEventListener("pointermove", (ev) => {
    if (drag) {
      const [px, py] = localPoint(ev);
      setChanged(drag.circle, { cx: px, cy: py });
      const t = performance.now();
      requestAnimationFrame(() => handlePaints.push(performance.now() - t));
      const [x, y] = dataOf(px, py);
      drag.moved = true;
      send({ type: "drag", id: drag.id, x, y }, t);
      return;
    }
    if (pan) {
      const [px, py] = localPoint(ev);
      const dx = px - pan.start[0], dy = py - pan.start[1];
      if (!pan.moved && Math.hypot(dx, dy) < 3) return;     // a click, not yet a pan
      pan.moved = true;
      setLocalView([pan.box0[0] - dx / kx, pan.box0[1] - dx / kx, pan.box0[2] + dy / ky, pan.box0[3] + dy / ky]);
      send({ type: "view", box: box });
      return;
    }
    lastPointer = [ev.clientX, ev.clientY];
    const id = hitAt(...localPoint(ev));      // on a handle too: what it moves is described
    const g = id === null ? null : nodes.get(id);
    for (const n of svg.querySelectorAll(".pg-hover")) if (n !== g) n.classList.remove("pg-hover");
    if (g) {
      g.classList.add("pg-hover");
      showTip(ev, id);
    } else { tip.style.display = "none"; hoverId = null; }
  });
  svg.addEventListener("pointerleave", () => { tip.style.display = "none"; hoverId = null; });
  svg.addEventListener("pointerdown", (ev) => {
    clearTimeout(descTimer);
    descTimer = null;
    const hid = ev.target.dataset && ev.target.dataset.handle;
    svg.setPointerCapture(ev.pointerId);
    if (hid) {
      tip.style.display = "none";     // a drag moves what the tip described: it goes, as on leaving
      hoverId = null;
      drag = { id: hid, circle: ev.target };
      focusHandle = hid;
      markHandle();
      ev.target.classList.add("pg-dragging");
      svg.focus();
      ev.preventDefault();
      return;
    }
    const id = hitAt(...localPoint(ev));
    if (id !== null) {
      setFocus(focusId === id ? null : id);
      return;
    }
    if (box) pan = { start: localPoint(ev), box0: box.slice(), moved: false };
  });
  svg.addEventListener("pointerup", () => {
    if (pan && !pan.moved && focusId !== null) setFocus(null);   // a click on the background: no focus
    if (drag) {
      drag.circle.classList.remove("pg-dragging");
      if (drag.moved) send({ type: "release", id: drag.id });   // after the drag's last request
      drag = null;
      if (!inflight && !pending.size) { placeHandles(); maybeTick(); }  // a refused position snaps back
    }
    pan = null;
  });
  svg.addEventListener("wheel", (ev) => {
    // a sideways wheel (or Shift + wheel) scrolls a figure wider than its column and never
    // zooms; it never reaches the page either (there it would be a "back" gesture)
    const sideways = ev.shiftKey || Math.abs(ev.deltaX) > Math.abs(ev.deltaY);
    if (sideways && root.scrollWidth > root.clientWidth) return;
    ev.preventDefault();
    if (!box || sideways) return;
    const [px, py] = localPoint(ev);
    const [x, y] = dataOf(px, py);
    const f = Math.exp(Math.sign(ev.deltaY) * 0.15);
    setLocalView([x + (box[0] - x) * f, x + (box[1] - x) * f, y + (box[2] - y) * f, y + (box[3] - y) * f]);
    send({ type: "view", box: box });
  }, { passive: false });
  // arrow keys nudge the focused handle (a drag); letting go of the last arrow key held (or the
  // picture losing the keyboard's focus) ends the nudges as a mouse-up ends a drag: a "release"
  const DIRS = { ArrowLeft: [-1, 0], ArrowRight: [1, 0], ArrowUp: [0, 1], ArrowDown: [0, -1] };
  const keysHeld = new Set();
  let nudged = null;              // the handle nudged since the last release
  function endNudge() {
    keysHeld.clear();
    if (nudged === null) return;
    const id = nudged;
    nudged = null;
    send({ type: "release", id });
  }
  // Tab / Shift-Tab move the keyboard's handle through the handles (marked while the figure has
  // the focus); past the last (first) one the focus leaves the figure.  Escape: no handle.
  let pointerFocus = false;
  function markHandle() {
    for (const [id, c] of circles) c.classList.toggle("pg-kbd", id === focusHandle);
  }
  // the focus ring shows when the keyboard is used, not after a click or a drag
  svg.addEventListener("pointerdown", () => { pointerFocus = true; svg.classList.add("pg-pointer"); }, true);
  svg.addEventListener("pointerup", () => { pointerFocus = false; });
  svg.addEventListener("focus", () => {
    if (!pointerFocus && focusHandle === null && st.handles.length) focusHandle = st.handles[0][0];
    pointerFocus = false;
    markHandle();
  });
  svg.addEventListener("keydown", (ev) => {
    svg.classList.remove("pg-pointer");
    if (ev.key === "Tab" && st.handles.length) {
      const ids = st.handles.map((q) => q[0]), i = ids.indexOf(focusHandle);
      const j = i < 0 ? (ev.shiftKey ? ids.length - 1 : 0) : i + (ev.shiftKey ? -1 : 1);
      if (j < 0 || j >= ids.length) { endNudge(); focusHandle = null; markHandle(); return; }  // leave
      ev.preventDefault();
      if (nudged !== null) endNudge();
      focusHandle = ids[j];
      markHandle();
      return;
    }
    if (ev.key === "Escape") { endNudge(); focusHandle = null; markHandle(); return; }
    if (!(ev.key in DIRS) || !focusHandle || !frame) return;
    const h = st.handles.find((q) => q[0] === focusHandle);
    if (!h) return;
    ev.preventDefault();
    if (nudged !== null && nudged !== h[0]) endNudge();
    keysHeld.add(ev.key);
    const step = (ev.shiftKey ? 20 : 2) / kx, [dx, dy] = DIRS[ev.key];
    h[1] += dx * step;
    h[2] += dy * step;
    placeHandles();
    nudged = h[0];
    send({ type: "drag", id: h[0], x: h[1], y: h[2] });
  });
  svg.addEventListener("keyup", (ev) => {
    if (!(ev.key in DIRS)) return;
    keysHeld.delete(ev.key);
    if (!keysHeld.size) endNudge();
  });
  svg.addEventListener("blur", endNudge);
  reset.addEventListener("click", () => send({ type: "view", box: null }));

  const snap = model.get("snapshot");
  if (snap) apply({ ...snap, base: null });
  askSync();        // the snapshot may be older than this view (a second display): the kernel knows
  root.__planargeo = { ping: () => send({ type: "ping" }), busy: () => inflight || pending.size > 0, stats,
                       handlePaints, paintTimes, applyTimes, arrivals, painted: () => nPaint, pushed: () => nPushed, version: () => st.version,
                       elements: () => st.els.size, status: () => status.textContent,
                       text: (id) => { const e = st.els.get(id); const t = e && (e.parts || []).find((q) => q[0] === "T");
                                       return t ? t[5] : null; } };
  return () => {};
}

export default { render };
