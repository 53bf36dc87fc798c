"""The key and a refusal's words never hide the mechanism (student review in Chromium).

* The key (legend) covered the crank, its ground pivot and the poles of the slider-crank with every
  overlay on, the grip P, the reaction impulse and the velocity pole of the impulse explorer, the
  base and the "a" handle of the articulated explorer after a drag.  Now its panel touches no handle
  (the page's circle, 8 px), no body outline (paths of the body and ground roles) and no pole glyph
  or mark; when no corner of the plot is clear the figure grows a strip below the plot for it, and
  the plot keeps its size, its view and its scale (the mechanism stays where it was).
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


@pytest.mark.parametrize("state", list(STATES))
def test_the_key_covers_no_handle_body_or_pole(state):
    ex = STATES[state]()
    assert ex.controls["key"].value and not ex.message, ex.message
    pic = ex.picture()
    covered = _covered(pic, _panel(pic, "key panel"))
    assert not covered, f"{state}: the key covers {covered}"


@pytest.mark.parametrize("state", list(STATES))
def test_the_key_keeps_the_plot_its_view_and_scale(state):
    ex = STATES[state]()
    on = ex.picture()
    ex.set(key=False)
    off = ex.picture()
    ml, mr, mt, mb = on["margin"]
    w_on, h_on = on["size"][0] - ml - mr, on["size"][1] - mt - mb
    w_off, h_off = off["size"][0] - ml - mr, off["size"][1] - mt - mb
    assert on["margin"] == off["margin"] and w_on == w_off and h_on >= h_off
    assert on["box"][0] == off["box"][0] and on["box"][1] == off["box"][1] and on["box"][3] == off["box"][3]
    assert on["box"][2] <= off["box"][2]
    # one scale: the strip below (if any) is as many pixels as data units times the scale
    ky_on = h_on / (on["box"][3] - on["box"][2])
    ky_off = h_off / (off["box"][3] - off["box"][2])
    assert ky_on == pytest.approx(ky_off, rel=1e-3)
    # every handle at the same pixels from the plot's top left
    top_on = {h["id"]: (_px(on, [h["x"], h["y"]])[0] - (0.0, h_on)) for h in on["handles"]}
    top_off = {h["id"]: (_px(off, [h["x"], h["y"]])[0] - (0.0, h_off)) for h in off["handles"]}
    assert top_on.keys() == top_off.keys()
    for k in top_on:
        assert top_on[k] == pytest.approx(top_off[k], abs=0.5), k


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
