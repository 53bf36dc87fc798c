"""The page renderer's updates: what a view draws from updates is what a new view draws at once,
and an update writes no attribute with the value it already has.

The page renderer (``canvas.js``) runs alone in headless chromium
(:class:`browser_harness.CanvasHarness`).  The 10-link chain with every overlay (the largest
picture of the explorers, 94 elements) is driven in Python: drags of its last link's end,
two overlays switched off and on again, steps of its angle slider; every update the kernel
sends is handed to one view of the page in turn.  The reference is a new view opened on the
canvas's state after all of them (its whole picture drawn at once, no node kept): both must
hold the same SVG (the clip path's random id and the order of attributes aside).  While the
updates are applied, a MutationObserver sees every attribute written: none may be written
with the value it already had (a write of an unchanged value still makes the browser restyle,
lay out and repaint the node).
"""
from __future__ import annotations

import json

import pytest

pytestmark = pytest.mark.browser

OVERLAYS = ("velocity poles", "acceleration poles", "bias terms", "internal forces", "T/U split",
            "articulated inertias")

#: the figure's SVG as text: the clip path's id replaced, each node's attributes in name order
SVG_TEXT = """() => {
  const svg = document.querySelector(".pg-canvas svg"), clip = svg.querySelector("clipPath");
  const walk = (n) => {
    if (n.nodeType !== 1) return n.nodeType === 3 ? n.textContent : "";
    const at = [...n.attributes].map((a) => a.name).sort()
      .map((k) => ` ${k}="${n.getAttribute(k).split(clip.id).join("CLIP")}"`).join("");
    return `<${n.tagName}${at}>` + [...n.childNodes].map(walk).join("") + `</${n.tagName}>`;
  };
  return walk(svg);
}"""

#: every attribute written under the figure, with the value it had: [tag, name, old, new]
WATCH = """() => {
  window.writes = [];
  const svg = document.querySelector(".pg-canvas svg");
  window.watcher = new MutationObserver((ms) => { for (const m of ms) window.writes.push(
    [m.target.tagName, m.attributeName, m.oldValue, m.target.getAttribute(m.attributeName)]); });
  window.watcher.observe(svg, { subtree: true, attributes: true, attributeOldValue: true });
}"""


def _chain_and_updates():
    from planargeo.widgets import ChainExplorer

    ex = ChainExplorer(display="page", links=10, **{k: True for k in OVERLAYS})
    ex.canvas.defer = False        # each request answered at once (no kernel here to answer it later)
    sent = []
    ex.canvas.send = lambda m, *a, **k: sent.append(m)
    first = json.loads(json.dumps(ex.canvas._snapshot()))
    h = next(h for h in ex.canvas.picture["handles"] if h["id"] == "link 10 end")
    for k in range(1, 9):
        ex.canvas._on_msg(None, {"type": "drag", "id": h["id"], "x": h["x"] - 0.02 * k, "y": h["y"] + 0.01 * k,
                                 "seq": k}, None)
    ex.canvas._on_msg(None, {"type": "release", "id": h["id"], "seq": 9}, None)
    for name in ("bias terms", "internal forces"):
        ex.controls[name].value = False
    for name in ("bias terms", "internal forces"):
        ex.controls[name].value = True
    for k in range(1, 4):
        ex.controls["angle"].value = -30.0 + 5 * k
    updates = [u for u in (m if m.get("type") == "update" else m.get("update") for m in sent) if u]
    last = json.loads(json.dumps(ex.canvas._snapshot()))
    return first, [json.loads(json.dumps({**u, "type": "update"})) for u in updates], last


def test_updates_draw_what_a_new_view_draws_and_write_only_changes(harness_page):
    page = harness_page
    first, updates, last = _chain_and_updates()
    assert len(updates) >= 12, len(updates)
    page.evaluate("(s) => window.openView(s)", {"snapshot": first, "playing": False})
    assert page.locator(".pg-el").count() == len(first["order"])
    page.evaluate(WATCH)
    for u in updates:
        page.evaluate("(m) => window.deliver(m)", u)
    version = page.evaluate("document.querySelector('.pg-canvas').__planargeo.version()")
    assert version == last["version"], "an update was not applied (the view asked for the whole picture)"
    writes = page.evaluate("() => { window.watcher.takeRecords(); window.watcher.disconnect(); return window.writes; }")
    changed = [w for w in writes if w[2] != w[3]]
    same = [w for w in writes if w[2] == w[3]]
    assert len(changed) > 100, f"the updates changed only {len(changed)} attributes"
    assert not same, f"{len(same)} attributes written with the value they had, e.g. {same[:5]}"
    drawn = page.evaluate(SVG_TEXT)
    page.evaluate("(s) => window.openView(s)", {"snapshot": last, "playing": False})
    fresh = page.evaluate(SVG_TEXT)
    assert fresh.count("<g ") > 90
    if drawn != fresh:
        j = next(j for j in range(min(len(drawn), len(fresh))) if drawn[j] != fresh[j])
        pytest.fail(f"drawn by updates …{drawn[max(0, j - 300):j + 200]}\n"
                    f"a new view        …{fresh[max(0, j - 300):j + 200]}")
