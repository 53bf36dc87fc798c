"""A translation in the screw-sum explorer: its labels by their own elements, its handle with a meaning.

The student's review: with screw 2 a translation, "v₂ at ∞" sat over v₃'s diamond while v₂'s arrow
was at the left edge; with screw 1 a translation, a hollow "v₁ direction" handle floated at
(−0.5, 0) with no label and no hover text.  Now a translation's velocity u is drawn as an arrow from its
point, the direction handle at its tip, labelled u₁ and described; every handle sits on what it moves; the
edge label stands over its own arrow, nearer it than any other pole.  Measured on the picture's numbers.
"""
from __future__ import annotations

import math

import numpy as np
import pytest

from planargeo.widgets import ScrewSumExplorer


def px_frame(pic):
    bx0, bx1, by0, by1 = pic["box"]
    ml, mr, mt, mb = pic["margin"]
    kx = (pic["size"][0] - ml - mr) / (bx1 - bx0)
    ky = (pic["size"][1] - mt - mb) / (by1 - by0)
    return lambda x, y: np.array([(x - bx0) * kx, (y - by0) * ky])


def text_box(pic, p):
    """Estimated pixel box (x0, y0, x1, y1) of a text part, y up (as the placer estimates it)."""
    at = px_frame(pic)(p["x"], p["y"]) + (p["dx"], p["dy"])
    w, h = 0.6 * pic["font_px"] * len(p["text"]), 1.25 * pic["font_px"]
    x0 = at[0] - {"left": 0.0, "center": 0.5, "right": 1.0}[p["ha"]] * w
    y0 = at[1] - {"bottom": 0.0, "center": 0.5, "top": 1.0}[p["va"]] * h
    return x0, y0, x0 + w, y0 + h


def box_distance(box, q) -> float:
    x0, y0, x1, y1 = box
    return math.hypot(q[0] - min(max(q[0], x0), x1), q[1] - min(max(q[1], y0), y1))


def element(pic, id):
    return next(e for e in pic["elements"] if e["id"] == id)


def test_the_edge_label_of_a_translation_stands_by_its_own_arrow():
    ex = ScrewSumExplorer(kind2="translation")
    pic = ex.picture()
    at = px_frame(pic)
    v2 = element(pic, "v2")
    label = next(p for p in v2["parts"] if p["p"] == "text")
    arrow = next(p for p in v2["parts"] if p["p"] == "arrow")
    assert label["text"] == "v₂ at ∞" and not label.get("hidden")
    box = text_box(pic, label)
    foot = at(arrow["x"], arrow["y"])
    ends = [foot, foot + (arrow["dx"], arrow["dy"])]
    own = min(box_distance(box, q) for q in ends)
    others = [at(p["x"], p["y"]) for e in pic["elements"] if e["id"] != "v2"
              for p in e["parts"] if p["p"] in ("mark", "glyph")]
    assert others                                               # v₁ and v₃ are drawn
    nearest_other = min(box_distance(box, q) for q in others)
    # nearer its own arrow than any other pole, and a label height clear of their glyphs' centres
    assert own < nearest_other, (own, nearest_other)
    assert nearest_other > 1.25 * pic["font_px"] + 8.0, nearest_other
    # the box stands over the arrow (their horizontal extents share pixels)
    assert box[0] <= max(e[0] for e in ends) and min(e[0] for e in ends) <= box[2], (box, ends)


@pytest.mark.parametrize("k, size", [(1, 2.0), (2, 2.0), (1, -2.0)])
def test_a_translations_direction_handle_is_the_tip_of_its_drawn_velocity(k, size):
    s = "₁₂"[k - 1]
    ex = ScrewSumExplorer(**{f"kind{k}": "translation", f"angle{k}": 30.0, f"size{k}": size})
    assert not ex.message
    pic = ex.picture()
    v = ex.values
    handle = next(h for h in pic["handles"] if h["id"] == f"v{s} direction")
    u = element(pic, f"u{k}")
    (a, b) = next(p for p in u["parts"] if p["p"] == "path")["xy"]
    # from the screw's point, one unit along u = size (cos angle, sin angle) (a negative size: back)
    sense = math.copysign(1.0, size)
    assert np.allclose(a, (v[f"x{k}"], v[f"y{k}"]))
    assert np.allclose(b, (v[f"x{k}"] + sense * math.cos(math.radians(30)),
                           v[f"y{k}"] + sense * math.sin(math.radians(30))))
    assert np.allclose((handle["x"], handle["y"]), b, atol=1e-4)
    texts = [p["text"] for p in u["parts"] if p["p"] == "text" and not p.get("hidden")]
    assert texts == [f"u{s}"]
    said = "at 30°" if size > 0 else "at -150°"                  # where u points
    assert u["symbol"] == f"u{s}" and "2 m/s" in u["desc"] and said in u["desc"], u["desc"]
    assert any(p["p"] == "arrow" for p in u["parts"])
    assert ex.handle_words(handle["id"]).startswith(f"direction of u{s}")
    assert "drag its tip" in u["desc"]          # the page shows it when the handle is hovered


def seg_distance(q, a, b) -> float:
    d = b - a
    t = 0.0 if not d @ d else min(max((q - a) @ d / (d @ d), 0.0), 1.0)
    return float(np.hypot(*(q - a - t * d)))


@pytest.mark.parametrize("values", [
    {}, {"kind1": "translation"}, {"kind2": "translation"},
    {"add": "wrenches"}, {"add": "wrenches", "kind2": "couple"},
])
def test_every_handle_sits_on_a_drawn_element_of_its_screw_and_has_words(values):
    """A handle is on what it moves: the pole v₁, the line f₁, or the tip of the velocity u₁ drawn; that
    element carries the screw's symbol (a label, and its hover text in the page)."""
    ex = ScrewSumExplorer(**values)
    pic = ex.picture()
    at = px_frame(pic)
    handles = pic["handles"]
    assert handles
    for h in handles:
        name = h["id"].split()[0]                                  # v₁, f₂
        symbol = ("u" + name[1:]) if h["id"].endswith("direction") and name[0] == "v" else name
        q = at(h["x"], h["y"])
        near = []
        for e in pic["elements"]:
            if not str(e.get("symbol", "")).startswith(symbol):
                continue
            for p in e["parts"]:
                if p["p"] in ("mark", "glyph"):
                    near.append(float(np.hypot(*(at(p["x"], p["y"]) - q))))
                elif p["p"] == "path":
                    xy = [at(x, y) for x, y in p["xy"]]
                    near += [seg_distance(q, a, b) for a, b in zip(xy, xy[1:])]
        assert near and min(near) < 2.0, (h, symbol, near)
        words = ex.handle_words(h["id"])
        assert "drag" in words and not words.startswith("drag to change") and symbol[0] in words, words


def test_the_pages_handles_carry_each_explorers_own_words():
    """The picture the page gets gives each handle the explorer's words (its hover text), not a generic one."""
    from planargeo.widgets import ConstructionExplorer

    for ex in (ScrewSumExplorer(display="agg"), ConstructionExplorer("wrench_sum", display="agg")):
        handles = ex.picture()["handles"]
        assert handles and all(h["desc"] == ex.handle_words(h["id"]) for h in handles)
        assert not any(h["desc"].startswith("drag to change") for h in handles), handles
