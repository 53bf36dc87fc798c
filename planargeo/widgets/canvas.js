// planargeo's page renderer: draws a picture (planargeo.draw.picture) as SVG, live.
//
// The picture arrives as plain data (trait "picture"); nothing here computes geometry
// beyond mapping data coordinates to pixels.  What happens in the page, at once:
//   * a dragged handle follows the pointer in the same animation frame;
//   * zoom (wheel), pan (drag the background) and reset move the drawing at once;
//   * hover highlights an element and shows its description; a click focuses it.
// What goes to the kernel: {type: "drag" | "view" | "ping", ...} messages, at most one
// in flight; while one is in flight only the latest new request is kept (the older is
// dropped), and it is sent when the kernel's "ack" arrives.
const NS = "http://www.w3.org/2000/svg";

function mk(tag, attrs, parent) {
  const e = document.createElementNS(NS, tag);
  for (const k in attrs) e.setAttribute(k, attrs[k]);
  if (parent) parent.appendChild(e);
  return e;
}

function arcGlyph(r, ccw) {
  // the 270° rotation arrow of planargeo.draw.geometry.arc_glyph (pixels, y up)
  const n = 40, a0 = -Math.PI / 4, span = 1.5 * Math.PI, pts = [];
  for (let i = 0; i < n; i++) {
    const t = ccw ? a0 + (span * i) / (n - 1) : a0 + span - (span * i) / (n - 1);
    pts.push([r * Math.cos(t), r * Math.sin(t)]);
  }
  const te = ccw ? a0 + span : a0, end = pts[n - 1], s = ccw ? 1 : -1;
  const tang = [-Math.sin(te) * s, Math.cos(te) * s], nrm = [Math.cos(te), Math.sin(te)];
  const h = Math.min(Math.max(3, 0.45 * r), 6);
  const head = [[end[0] + tang[0] * h, end[1] + tang[1] * h],
                [end[0] - 0.5 * h * nrm[0], end[1] - 0.5 * h * nrm[1]],
                [end[0] + 0.5 * h * nrm[0], end[1] + 0.5 * h * nrm[1]]];
  return [pts, head];
}

function fmtTick(v) {
  const s = Math.abs(v) < 1e-12 ? "0" : String(+v.toPrecision(6));
  return s.replace("-", "\u2212");
}

function render({ model, el }) {
  const root = document.createElement("div");
  root.className = "pg-canvas";
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
  el.appendChild(root);

  let pic = null, W = 0, H = 0, ml = 0, mt = 0, pw = 0, ph = 0, box = null, kx = 1, ky = 1;
  let content = null, handleLayer = null, focusId = null, focusHandle = null;
  const circles = new Map();
  let drag = null, pan = null;
  let inflight = false, pending = null, seq = 0;
  const handlePaints = [];

  const X = (x) => (x - box[0]) * kx;
  const Y = (y) => ph - (y - box[2]) * ky;
  const dataOf = (px, py) => [box[0] + px / kx, box[2] + (ph - py) / ky];

  // timings of each request, for benchmarks: input event, sent, acknowledged, picture painted
  const stats = [];
  let current = null;
  function send(msg, tInput) {
    if (inflight) { pending = msg; pending.tInput = tInput; return; }
    inflight = true;
    seq += 1;
    const { tInput: _t, ...clean } = msg;
    current = { seq, type: msg.type, tInput: tInput ?? msg.tInput ?? performance.now(), tSent: performance.now() };
    stats.push(current);
    if (stats.length > 1000) stats.shift();
    model.send({ ...clean, seq });
  }
  model.on("msg:custom", (m) => {
    if (!m || m.type !== "ack") return;
    if (current) current.tAck = performance.now();
    const done = current;
    requestAnimationFrame(() => { if (done) done.tPaint = performance.now(); });
    inflight = false;
    status.textContent = m.ok === false && m.message ? m.message : "";
    if (pending) { const p = pending; pending = null; send(p); }
    else if (!drag) placeHandles();
  });

  function localPoint(ev) {
    const r = svg.getBoundingClientRect();
    return [ev.clientX - r.left - ml, ev.clientY - r.top - mt];
  }

  function drawPart(g, part, elData) {
    const k = part.p;
    if (k === "path") {
      const d = part.xy.map((q, i) => (i ? "L" : "M") + X(q[0]).toFixed(2) + " " + Y(q[1]).toFixed(2)).join("");
      const fill = elData.fill || "none";
      const a = { d: d + (part.closed ? "Z" : ""), fill, stroke: elData.color, "stroke-width": elData.width };
      if (elData.fill) a["fill-opacity"] = elData.alpha ?? 1;
      if (elData.dash) a["stroke-dasharray"] = elData.dash.join(" ");
      mk("path", a, g);
    } else if (k === "ellipse") {
      // the unit circle under the picture's affine map (data units), sampled here
      const [a, b, c, d] = part.m, n = 96;
      let p = "";
      for (let i = 0; i < n; i++) {
        const t = (2 * Math.PI * i) / n, u = Math.cos(t), v = Math.sin(t);
        p += (i ? "L" : "M") + X(part.x + a * u + b * v).toFixed(2) + " " + Y(part.y + c * u + d * v).toFixed(2);
      }
      const at = { d: p + "Z", fill: "none", stroke: elData.color, "stroke-width": elData.width };
      if (elData.dash) at["stroke-dasharray"] = elData.dash.join(" ");
      mk("path", at, g);
    } else if (k === "mark") {
      const x = X(part.x), y = Y(part.y), s = part.size / 2;
      if (part.shape === "D") {
        mk("path", { d: `M${x} ${y - s * 1.2}L${x + s} ${y}L${x} ${y + s * 1.2}L${x - s} ${y}Z`,
                     fill: elData.color, stroke: "white", "stroke-width": 0.8 }, g);
      } else if (part.shape === "s") {
        mk("rect", { x: x - s, y: y - s, width: 2 * s, height: 2 * s, fill: elData.color,
                     stroke: "white", "stroke-width": 0.8 }, g);
      } else {
        mk("circle", { cx: x, cy: y, r: s, fill: elData.color, stroke: "white", "stroke-width": 0.8 }, g);
      }
    } else if (k === "glyph") {
      const [arc, head] = arcGlyph(part.r, part.ccw), x = X(part.x), y = Y(part.y);
      const d = arc.map((q, i) => (i ? "L" : "M") + (x + q[0]).toFixed(2) + " " + (y - q[1]).toFixed(2)).join("");
      mk("path", { d, fill: "none", stroke: elData.color, "stroke-width": 1.6 }, g);
      mk("path", { d: "M" + head.map((q) => (x + q[0]).toFixed(2) + " " + (y - q[1]).toFixed(2)).join("L") + "Z",
                   fill: elData.color }, g);
    } else if (k === "arrow") {
      const x = X(part.x), y = Y(part.y), x2 = x + part.dx, y2 = y - part.dy;
      const L = Math.hypot(part.dx, part.dy) || 1, ux = part.dx / L, uy = -part.dy / L, h = 8;
      mk("line", { x1: x, y1: y, x2: x2 - ux * h * 0.8, y2: y2 - uy * h * 0.8, stroke: elData.color,
                   "stroke-width": 1.9 }, g);
      mk("path", { d: `M${x2} ${y2}L${x2 - ux * h - uy * h * 0.35} ${y2 - uy * h + ux * h * 0.35}` +
                      `L${x2 - ux * h + uy * h * 0.35} ${y2 - uy * h - ux * h * 0.35}Z`, fill: elData.color }, g);
    } else if (k === "text") {
      if (part.hidden) return;
      const t = mk("text", { x: X(part.x) + part.dx, y: Y(part.y) - part.dy, fill: elData.color,
                             "font-size": pic.font_px,
                             "text-anchor": { left: "start", right: "end", center: "middle" }[part.ha],
                             "dominant-baseline": { bottom: "text-after-edge", top: "text-before-edge",
                                                    center: "central" }[part.va] }, g);
      t.textContent = part.text;
    }
  }

  let nPaint = 0;
  const paintTimes = [];
  function draw() {
    nPaint += 1;
    requestAnimationFrame(() => { paintTimes.push(performance.now()); if (paintTimes.length > 1000) paintTimes.shift(); });
    pic = model.get("picture");
    svg.textContent = "";
    circles.clear();
    if (!pic || !pic.size) return;
    [W, H] = pic.size;
    [ml, , mt] = pic.margin;
    pw = W - pic.margin[0] - pic.margin[1];
    ph = H - pic.margin[2] - pic.margin[3];
    box = pic.box;
    kx = pw / (box[1] - box[0]);
    ky = ph / (box[3] - box[2]);
    svg.setAttribute("width", W);
    svg.setAttribute("height", H);
    svg.setAttribute("viewBox", `0 0 ${W} ${H}`);
    const defs = mk("defs", {}, svg);
    const clipId = "pgclip" + Math.random().toString(36).slice(2);
    mk("rect", { x: 0, y: 0, width: pw, height: ph }, mk("clipPath", { id: clipId }, defs));
    if (pic.title) {
      const t = mk("text", { x: W / 2, y: 16, "text-anchor": "middle", "font-size": pic.font_px + 1,
                             class: "pg-title" }, svg);
      t.textContent = pic.title;
    }
    const plot = mk("g", { transform: `translate(${ml},${mt})` }, svg);
    mk("rect", { x: 0, y: 0, width: pw, height: ph, class: "pg-bg" }, plot);
    if (pic.ticks) {
      const axes = mk("g", { class: "pg-axes" }, plot);
      for (const v of pic.ticks.x) {
        const x = X(v);
        mk("line", { x1: x, y1: ph, x2: x, y2: ph + 4 }, axes);
        const t = mk("text", { x, y: ph + 6, "text-anchor": "middle", "dominant-baseline": "text-before-edge",
                               "font-size": pic.font_px }, axes);
        t.textContent = fmtTick(v);
      }
      for (const v of pic.ticks.y) {
        const y = Y(v);
        mk("line", { x1: -4, y1: y, x2: 0, y2: y }, axes);
        const t = mk("text", { x: -6, y, "text-anchor": "end", "dominant-baseline": "central",
                               "font-size": pic.font_px }, axes);
        t.textContent = fmtTick(v);
      }
    }
    content = mk("g", { "clip-path": `url(#${clipId})` }, plot);
    const inner = mk("g", { class: "pg-content" }, content);
    for (const e of pic.elements) {
      const g = mk("g", { "data-id": e.id, class: "pg-el" + (focusId && focusId !== e.id ? " pg-faded" : "") }, inner);
      if (e.opacity !== undefined && e.opacity !== 1) g.setAttribute("opacity", e.opacity);
      if (e.symbol || e.desc) g.setAttribute("data-described", "");
      for (const part of e.parts) drawPart(g, part, e);
    }
    mk("rect", { x: 0, y: 0, width: pw, height: ph, class: "pg-frame" }, plot);
    handleLayer = mk("g", { class: "pg-handles" }, plot);
    for (const h of pic.handles) {
      const c = mk("circle", { r: 8, "data-handle": h.id, class: "pg-handle", tabindex: "-1" }, handleLayer);
      const t = mk("title", {}, c);
      t.textContent = (h.symbol ? h.symbol + ": " : "") + (h.desc || "drag");
      circles.set(h.id, c);
    }
    placeHandles();
  }

  function setLocalView(b) {
    // show the drawn picture in the box b at once (a transform), until the kernel's redraw arrives
    box = b;
    kx = pw / (b[1] - b[0]);
    ky = ph / (b[3] - b[2]);
    const s = kx / (pw / (pic.box[1] - pic.box[0]));
    const tx = (pic.box[0] - b[0]) * kx, ty = ph * (1 - s) - (pic.box[2] - b[2]) * ky;
    content.firstChild.setAttribute("transform", `translate(${tx},${ty}) scale(${s})`);
    placeHandles();
  }

  function placeHandles() {
    if (!pic) return;
    for (const h of pic.handles) {
      const c = circles.get(h.id);
      if (!c) continue;
      if (drag && drag.id === h.id) {  // the dragged one stays under the pointer, also when redrawn
        if (drag.circle !== c) {
          c.setAttribute("cx", drag.circle.getAttribute("cx"));
          c.setAttribute("cy", drag.circle.getAttribute("cy"));
          c.classList.add("pg-dragging");
          drag.circle = c;
        }
        continue;
      }
      c.setAttribute("cx", X(h.x));
      c.setAttribute("cy", Y(h.y));
    }
  }

  function showTip(ev, e) {
    if (!e.symbol && !e.desc) { tip.style.display = "none"; return; }
    tip.textContent = (e.symbol ? e.symbol + " \u2014 " : "") + (e.desc || "");
    const r = root.getBoundingClientRect();
    tip.style.left = Math.min(ev.clientX - r.left + 12, W - 220) + "px";
    tip.style.top = ev.clientY - r.top + 14 + "px";
    tip.style.display = "block";
  }

  svg.addEventListener("pointermove", (ev) => {
    if (drag) {
      const [px, py] = localPoint(ev);
      drag.circle.setAttribute("cx", px);
      drag.circle.setAttribute("cy", py);
      const t = performance.now();
      requestAnimationFrame(() => handlePaints.push(performance.now() - t));
      const [x, y] = dataOf(px, py);
      send({ type: "drag", id: drag.id, x, y }, t);
      return;
    }
    if (pan) {
      const [px, py] = localPoint(ev);
      const dx = px - pan.start[0], dy = py - pan.start[1];
      setLocalView([pan.box0[0] - dx / kx, pan.box0[1] - dx / kx, pan.box0[2] + dy / ky, pan.box0[3] + dy / ky]);
      send({ type: "view", box: box });
      return;
    }
    const g = ev.target.closest && ev.target.closest(".pg-el");
    for (const n of svg.querySelectorAll(".pg-hover")) if (n !== g) n.classList.remove("pg-hover");
    if (g) {
      g.classList.add("pg-hover");
      const e = pic.elements.find((q) => q.id === g.dataset.id);
      if (e) showTip(ev, e);
    } else tip.style.display = "none";
  });
  svg.addEventListener("pointerdown", (ev) => {
    const hid = ev.target.dataset && ev.target.dataset.handle;
    svg.setPointerCapture(ev.pointerId);
    if (hid) {
      drag = { id: hid, circle: ev.target };
      focusHandle = hid;
      ev.target.classList.add("pg-dragging");
      svg.focus();
      ev.preventDefault();
      return;
    }
    const g = ev.target.closest && ev.target.closest(".pg-el");
    if (g) {
      focusId = focusId === g.dataset.id ? null : g.dataset.id;
      for (const n of svg.querySelectorAll(".pg-el"))
        n.classList.toggle("pg-faded", !!focusId && n.dataset.id !== focusId);
      return;
    }
    pan = { start: localPoint(ev), box0: box.slice() };
  });
  svg.addEventListener("pointerup", (ev) => {
    if (drag) {
      drag.circle.classList.remove("pg-dragging");
      drag = null;
      if (!inflight && !pending) placeHandles();  // a refused position snaps back
    }
    pan = null;
  });
  svg.addEventListener("wheel", (ev) => {
    ev.preventDefault();
    const [px, py] = localPoint(ev);
    const [x, y] = dataOf(px, py);
    const f = Math.exp(Math.sign(ev.deltaY) * 0.15);
    setLocalView([x + (box[0] - x) * f, x + (box[1] - x) * f, y + (box[2] - y) * f, y + (box[3] - y) * f]);
    send({ type: "view", box: box });
  }, { passive: false });
  svg.addEventListener("keydown", (ev) => {
    const dirs = { ArrowLeft: [-1, 0], ArrowRight: [1, 0], ArrowUp: [0, 1], ArrowDown: [0, -1] };
    if (!(ev.key in dirs) || !focusHandle || !pic) return;
    const h = pic.handles.find((q) => q.id === focusHandle);
    if (!h) return;
    ev.preventDefault();
    const step = (ev.shiftKey ? 20 : 2) / kx, [dx, dy] = dirs[ev.key];
    h.x += dx * step;
    h.y += dy * step;
    placeHandles();
    send({ type: "drag", id: h.id, x: h.x, y: h.y });
  });
  reset.addEventListener("click", () => send({ type: "view", box: null }));

  model.on("change:picture", draw);
  draw();
  root.__planargeo = { ping: () => send({ type: "ping" }), busy: () => inflight, stats, handlePaints,
                       paintTimes, painted: () => nPaint };
  return () => model.off("change:picture", draw);
}

export default { render };
