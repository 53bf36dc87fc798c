"""The construction's caption stays in its band below the plot, both lines, every step.

The student's review: on Newton–Euler step 6/6 the caption's second line was drawn above the band,
over the plot.  The label placer had moved it (as a label, off a line crossing the band); the caption
is now written at a fixed place.  Checked on the picture's own numbers: each line's box, from its
anchor, offset and alignment, lies inside the band's rectangle, the lines in order.
"""
from __future__ import annotations

import pytest

from planargeo.draw.pictures.construction import caption_lines
from planargeo.scenes.construction import CONSTRUCTIONS
from planargeo.widgets import ConstructionExplorer


def band_and_lines(pic: dict):
    """The band ``(x0, x1, y0, y1)`` in pixels (y up from the plot's bottom) and the caption lines'
    boxes ``(text, x0, y0, y1)``."""
    bx0, bx1, by0, by1 = pic["box"]
    ml, mr, mt, mb = pic["margin"]
    kx = (pic["size"][0] - ml - mr) / (bx1 - bx0)
    ky = (pic["size"][1] - mt - mb) / (by1 - by0)
    el = next(e for e in pic["elements"] if e["id"] == "caption")
    xy = next(p["xy"] for p in el["parts"] if p["p"] == "path")
    xs, ys = [(x - bx0) * kx for x, _ in xy], [(y - by0) * ky for _, y in xy]
    h = 1.25 * pic["font_px"]
    boxes = []
    for p in el["parts"]:
        if p["p"] != "text" or p.get("hidden"):
            continue
        assert (p["ha"], p["va"]) == ("left", "top"), p
        top = (p["y"] - by0) * ky + p["dy"]
        boxes.append((p["text"], (p["x"] - bx0) * kx + p["dx"], top - h, top))
    return (min(xs), max(xs), min(ys), max(ys)), boxes


def assert_in_band(ex):
    pic = ex.picture()
    (x0, x1, y0, y1), boxes = band_and_lines(pic)
    assert [b[0] for b in boxes] == caption_lines(ex.caption), (boxes, ex.caption)
    for text, left, bottom, top in boxes:
        assert x0 < left < x0 + 10, (text, left, x0)
        assert y0 <= bottom and top <= y1, (text, (bottom, top), (y0, y1))
    tops = [b[3] for b in boxes]
    assert tops == sorted(tops, reverse=True), boxes                 # line 1 above line 2


def test_newton_euler_step_6_from_the_menu():
    ex = ConstructionExplorer()
    ex.set(construction="newton_euler")
    assert ex.values["step"] == 6 and len(caption_lines(ex.caption)) == 2
    assert_in_band(ex)


@pytest.mark.parametrize("kind", list(CONSTRUCTIONS))
def test_every_step_of_every_construction_keeps_its_caption_in_the_band(kind):
    ex = ConstructionExplorer(kind)
    for step in range(1, ex.n_steps + 1):
        for earlier in ("faded", "hidden"):
            ex.set(step=step, earlier=earlier)
            assert_in_band(ex)


@pytest.mark.parametrize("kind,values", [
    ("newton_euler", {"step": 4}),            # the second line had been moved above the band
    ("acceleration", {"w": 3.0}),             # the first line had been moved out of its place
    ("through_infinity", {"hy": -3.0}),
    ("wrench_sum", {"y2": -3.0}),
])
def test_states_where_the_placer_had_moved_a_caption_line(kind, values):
    ex = ConstructionExplorer(kind)
    ex.set(**values)
    assert not ex.message
    assert_in_band(ex)
