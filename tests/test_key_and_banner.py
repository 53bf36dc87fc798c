"""The key and a refusal's words never hide the mechanism (student review in Chromium).

* The key (legend) covered the crank, its ground pivot and the poles of the slider-crank with every
  overlay on, the grip P, the reaction impulse and the velocity pole of the impulse explorer, the
  base and the "a" handle of the articulated explorer after a drag.  Now its panel touches no handle
  (the page's circle, 8 px), no body outline (paths of the body and ground roles) and no pole glyph
  or mark; when no corner of the plot is clear it goes below the plot's x tick labels, outside the
  plot (the figure grows by its height), and the plot, its frame, ticks and view are exactly as
  without the key (the strip the plot once grew below itself put the frame around the key, the
  y tick labels beside it and the x tick labels under it, and cut the lines at its top edge).
* A refusal's words were a white panel in the middle of the figure; now a banner along the top
  edge of the plot area, the plot's full width, under which no handle of the default chain lies.

Geometry here is measured on the picture's plain data (``ex.picture()``), as the page draws it.
"""
from __future__ import annotations

import ipywidgets as W
import numpy as np
import pytest

from planargeo.widgets import ArticulatedExplorer, ChainExplorer, ImpulseExplorer, SliderCrankExplorer

#: radius of a handle's circle in the page (canvas.js), px
HANDLE_PX = 8.0


def _px(pic, xy) -> np.ndarray:
    """Data points -> pixels from the plot area's lower left."""
    x0, x1, y0, y1 = pic["box"]
    w, h = pic["size"]
    ml, mr, mt, mb = pic["margin"]
    kx, ky = (w - ml - mr) / (x1 - x0), (h - mt - mb) / (y1 - y0)
    xy = np.asarray(xy, float).reshape(-1, 2)
    return np.column_stack([(xy[:, 0] - x0) * kx, (xy[:, 1] - y0) * ky])


def _dense(xy: np.ndarray, step: float = 1.0) -> np.ndarray:
    out = [xy[:1]]
    for a, b in zip(xy[:-1], xy[1:]):
        n = int(np.hypot(*(b - a)) / step) + 2
        out.append(a + np.linspace(0, 1, n)[:, None] * (b - a))
    return np.concatenate(out)


def _panel(pic, eid: str) -> tuple[float, float, float, float]:
    (el,) = [e for e in pic["elements"] if e["id"] == eid]
    xy = _px(pic, next(p["xy"] for p in el["parts"] if p["p"] == "path"))
    return (*xy.min(0), *xy.max(0))


def _covered(pic, box) -> list[str]:
    """What the box (px: left, bottom, right, top) covers: handles, body outlines, pole glyphs, marks."""
    left, bottom, right, top = box

    def hits(pts, r=0.0):
        return bool(np.any((pts[:, 0] > left - r) & (pts[:, 0] < right + r)
                           & (pts[:, 1] > bottom - r) & (pts[:, 1] < top + r)))

    out = [f"handle {h['id']}" for h in pic["handles"] if hits(_px(pic, [h["x"], h["y"]]), HANDLE_PX)]
    for el in pic["elements"]:
        if el["id"].startswith("key ") or el["id"] == "figure message":
            continue
        for q in el["parts"]:
            if q["p"] == "path" and el.get("role") in ("body", "ground"):
                if hits(_dense(_px(pic, q["xy"]))):
                    out.append(f"outline of {el['id']}")
            elif q["p"] == "glyph" and hits(_px(pic, [q["x"], q["y"]]), q["r"]):
                out.append(f"pole glyph of {el['id']}")
            elif q["p"] == "mark" and hits(_px(pic, [q["x"], q["y"]]), q["size"] / 2):
                out.append(f"mark of {el['id']}")
    return out


def _every_overlay(ex) -> None:
    ex.set(**{k: True for k, w in ex.controls.items()
              if isinstance(w, (W.Checkbox, W.ToggleButton)) and not w.disabled and k != "loop"})


def _slider_crank():
    ex = SliderCrankExplorer(display="agg")
    _every_overlay(ex)
    return ex


def _impulse():
    ex = ImpulseExplorer(display="agg")
    _every_overlay(ex)
    return ex


def _articulated_dragged():
    # the review's drags: pole a 50 px right and 40 px down, the first body 60 px left and 30 px up
    ex = ArticulatedExplorer(display="agg", key=True)
    pic = ex.picture()
    k = _px(pic, [1.0, 0.0])[0][0] - _px(pic, [0.0, 0.0])[0][0]          # pixels per metre
    for name, (dx, dy) in (("pole a", (50, -40)), ("first body", (-60, 30))):
        at = ex.handle_position(name)
        ex.drag(name, at, (at[0] + dx / k, at[1] + dy / k))
    return ex


STATES = {"slider-crank, every overlay": _slider_crank, "impulse, every overlay": _impulse,
          "articulated after drags": _articulated_dragged,
          "chain, key on": lambda: ChainExplorer(display="agg", key=True)}


STATES["impulse, key on"] = lambda: ImpulseExplorer(display="agg", key=True)
#: the states whose key no corner has room for (the others' key is in a corner)
BELOW = {"slider-crank, every overlay", "impulse, every overlay", "articulated after drags",
         "impulse, key on"}


@pytest.mark.parametrize("state", list(STATES))
def test_the_key_covers_no_handle_body_or_pole(state):
    ex = STATES[state]()
    assert ex.controls["key"].value and not ex.message, ex.message
    pic = ex.picture()
    ids = {e["id"] for e in pic["elements"]}
    if state in BELOW:      # under the plot: nothing of the key inside it
        entries = {f"key {k}" for k in range(1, 13)} | {"key panel"}
        assert "below" in pic and not ids & entries, sorted(ids & entries)
        return
    assert "below" not in pic
    covered = _covered(pic, _panel(pic, "key panel"))
    assert not covered, f"{state}: the key covers {covered}"


def _without_key(ex) -> dict:
    ex.set(key=False)
    off = ex.picture()
    ex.set(key=True)
    return off


@pytest.mark.parametrize("state", list(STATES))
def test_the_key_keeps_the_plot_its_frame_ticks_and_view(state):
    ex = STATES[state]()
    on = ex.picture()
    off = _without_key(ex)
    assert on == ex.picture()                       # the key back on: the same picture again
    # the plot area: the same pixels from the figure's top left, the same view and ticks
    assert on["margin"][:3] == off["margin"][:3] and on["size"][0] == off["size"][0]
    assert on["box"] == off["box"] and on["ticks"] == off["ticks"]
    ph_on = on["size"][1] - on["margin"][2] - on["margin"][3]
    ph_off = off["size"][1] - off["margin"][2] - off["margin"][3]
    assert ph_on == ph_off and on["handles"] == off["handles"]
    if state not in BELOW:
        assert on["size"] == off["size"] and on["margin"] == off["margin"]
        return
    # below: the figure grows by the key's lines (14 px each and 4 to spare), nothing else changes
    lines = on["below"]
    grow = on["size"][1] - off["size"][1]
    assert grow == on["margin"][3] - off["margin"][3] == 14 * len(lines) + 4
    assert on["elements"] == off["elements"]        # every line drawn to the view's edge, as without


@pytest.mark.parametrize("state", sorted(BELOW))
def test_the_key_below_is_under_the_tick_labels_inside_the_figure(state):
    ex = STATES[state]()
    on = ex.picture()
    off = _without_key(ex)
    ml, mr, mt, mb = on["margin"]
    w, h = on["size"]
    tops = [b["y"] for b in on["below"]]
    # the first line where the figure without the key ended (under the x tick labels), then
    # one line under the other, the last inside the figure
    assert tops[0] == off["margin"][3] and np.all(np.diff(tops) == 14.0)
    assert h - mt - (h - mt - mb) - tops[-1] >= 14.0 + 4.0 - 1e-9
    for b in on["below"]:
        assert b["x"] == 0.0 and ml + len(b["text"]) * 0.6 * on["font_px"] <= w
    # the entries of the key, their colours and wording, as drawn in a corner: each entry's
    # lines say its description, in the colour of what it names
    colors = {e["id"]: e["color"] for e in off["elements"]}
    by_id: dict[str, list] = {}
    for b in on["below"]:
        by_id.setdefault(b["id"], []).append(b)
    assert list(by_id) == [f"key {k}" for k in range(1, len(by_id) + 1)]
    for bs in by_id.values():
        desc = bs[0]["desc"]
        assert desc.startswith("key: ") and all(b["desc"] == desc for b in bs)
        assert " ".join(b["text"] for b in bs).split() == desc[5:].split()
        assert bs[0]["color"] in colors.values()


def test_a_refusal_is_a_banner_along_the_top_of_the_plot():
    ex = ChainExplorer(display="agg")
    before = ex.picture()
    ex.set(**{"joint speeds": "fast, then faster, and then as fast as the chain can go without flying apart"})
    assert ex.message.startswith("joint speeds must be numbers") and ex.figure_text
    pic = ex.picture()
    assert pic["size"] == before["size"] and pic["box"] == before["box"]
    left, bottom, right, top = _panel(pic, "figure message")
    ml, mr, mt, mb = pic["margin"]
    pw, ph = pic["size"][0] - ml - mr, pic["size"][1] - mt - mb
    assert left <= 1.0 and right >= pw - 1.0                    # the plot's full width
    assert top >= ph - 1.0                                      # along its top edge
    (el,) = [e for e in pic["elements"] if e["id"] == "figure message"]
    lines = [p for p in el["parts"] if p["p"] == "text"]
    assert len(lines) >= 2 and top - bottom <= 20.0 * len(lines) + 12.0   # as tall as its lines
    assert top - bottom < 0.25 * ph
    assert el["desc"] == f"message: {ex.figure_text}" and el["fill"] == "white"
    # the mechanism stays in sight: no handle, body or pole under the banner
    covered = _covered(pic, (left, bottom, right, top))
    assert not covered, covered
    # the words, each line inside the banner (centred, estimated at 0.6 font sizes a character)
    for p in lines:
        y = _px(pic, [p["x"], p["y"]])[0][1] + p["dy"]
        assert bottom <= y <= top and p["ha"] == "center"
        assert len(p["text"]) * 0.6 * pic["font_px"] <= right - left
