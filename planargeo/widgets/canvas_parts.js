// What planargeo's page renderer draws with (canvas.py sends this, then canvas.js, as one
// module): SVG nodes and their attributes, the rotation glyph, the unit circle, numbers.
const NS = "http://www.w3.org/2000/svg";
const ANCHOR = { l: "start", c: "middle", r: "end" };
const BASELINE = { b: "text-after-edge", t: "text-before-edge", c: "central" };

function mk(tag, attrs, parent) {
  const e = document.createElementNS(NS, tag);
  for (const k in attrs) e.setAttribute(k, attrs[k]);
  if (parent) parent.appendChild(e);
  return e;
}

// Writes to a drawn node only the attributes whose value changed since its last drawing (the
// values written are kept on the node, as the strings setAttribute stores; null: no attribute):
// a value written again unchanged would still make the browser restyle, lay out and repaint it.
function setChanged(n, attrs) {
  const last = n.__pgAttrs || (n.__pgAttrs = {});
  for (const k in attrs) {
    const v = attrs[k] === null || attrs[k] === undefined ? null : String(attrs[k]);
    if (last[k] === v || (v === null && last[k] === undefined)) continue;
    if (v === null) n.removeAttribute(k); else n.setAttribute(k, v);
    last[k] = v;
  }
  return n;
}

const glyphs = new Map();      // (r, ccw) -> the glyph's paths about its centre (pixels, y down)
function glyphPaths(r, ccw) {
  const key = r + (ccw ? "+" : "-");
  let g = glyphs.get(key);
  if (!g) {
    const [arc, head] = arcGlyph(r, ccw);
    g = [arc.map((p, i) => (i ? "L" : "M") + f2(p[0]) + " " + f2(-p[1])).join(""),
         "M" + head.map((p) => f2(p[0]) + " " + f2(-p[1])).join("L") + "Z"];
    if (glyphs.size > 500) glyphs.clear();
    glyphs.set(key, g);
  }
  return g;
}

// the unit circle, sampled once (an ellipse part is its image under an affine map)
const CIRCLE_N = 96;
const CIRCLE = Array.from({ length: CIRCLE_N }, (_, i) => [Math.cos((2 * Math.PI * i) / CIRCLE_N),
                                                          Math.sin((2 * Math.PI * i) / CIRCLE_N)]);

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

const f2 = (v) => (Math.round(v * 100) / 100).toString();
