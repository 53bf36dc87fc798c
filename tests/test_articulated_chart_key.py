"""The articulated explorer's chart key covers none of the chart's curves (the student's review).

The key was in the chart's lower right corner, over the error curve's last points (the error is
0 after every step).  Now it goes where the curves leave room: checked on the picture's own data
(the key's box, the curves' points and, sampled every pixel, the lines between them) in states
across the controls, and in a chart whose every corner is taken.
"""
from __future__ import annotations

import numpy as np
import pytest

from _picture_checks import elements, to_px
from planargeo.draw.pictures.articulated import key_corner
from planargeo.widgets import ArticulatedExplorer

STATES = [{}, {"outboard bodies": 1}, {"outboard bodies": 0}, {"bodies n": 2}, {"bodies n": 3},
          {"bodies n": 8}, {"bodies n": 8, "outboard bodies": 2}, {"λ = L/ρ": 0.5}, {"λ = L/ρ": 8.0},
          {"bodies n": 8, "λ = L/ρ": 8.0}, {"bodies n": 8, "λ = L/ρ": 0.5}, {"bend φ (deg)": 0.0},
          {"bend φ (deg)": 90.0}, {"bend φ (deg)": 180.0}, {"bend φ (deg)": -120.0, "base θ₁ (deg)": 45.0},
          ({"bodies n": 6}, {"focus": "body 3"}), ({"bodies n": 8}, {"focus": "body 7"}), {"rigid inertias": False},
          {"bodies n": 5, "bend φ (deg)": 10.0, "λ = L/ρ": 1.0},
          # no corner free: the values' axis raised, the key above the curves
          {"bodies n": 8, "λ = L/ρ": 4.54, "bend φ (deg)": -177.0, "outboard bodies": 1},
          ({"bodies n": 8, "λ = L/ρ": 5.05, "bend φ (deg)": 169.0, "outboard bodies": 4}, {"focus": "body 5"})]


def _key_and_curves(pic):
    els = elements(pic)
    (box,) = [np.asarray(p["xy"], float) for p in els["key box"]["parts"] if p["p"] == "path"]
    box = np.array([to_px(pic, *q) for q in box])
    (frame,) = [np.asarray(p["xy"], float) for p in els["chart frame"]["parts"] if p["p"] == "path"]
    frame = np.array([to_px(pic, *q) for q in frame])
    curves = {}
    for id, el in els.items():
        if id.startswith("chart ") and id not in ("chart frame", "chart now") and not id.startswith(
                ("chart grid", "chart x", "chart y", "chart title")):
            marks = [to_px(pic, p["x"], p["y"]) for p in el["parts"] if p["p"] == "mark"]
            if marks:
                curves[id] = np.array(marks)
    return box, frame, curves


def _id(state) -> str:
    return ", ".join(f"{k}={v}" for d in (state if isinstance(state, tuple) else (state,))
                     for k, v in d.items()) or "default"


@pytest.mark.parametrize("state", STATES, ids=_id)
def test_the_key_covers_no_point_and_no_line_of_the_chart(state):
    ex = ArticulatedExplorer(display="agg")
    for step in state if isinstance(state, tuple) else (state,):
        ex.set(**step)
    assert ex.message == ""
    box, frame, curves = _key_and_curves(ex.picture())
    x0, y0 = box.min(axis=0)
    x1, y1 = box.max(axis=0)
    # the key inside the chart's frame, of its full size (two columns of 50 px, 15 px a row)
    fx0, fy0 = frame.min(axis=0)
    fx1, fy1 = frame.max(axis=0)
    assert fx0 <= x0 and x1 <= fx1 and fy0 <= y0 and y1 <= fy1
    assert x1 - x0 >= 95.0 and y1 - y0 >= 15.0 * ((len(curves) + 1) // 2)
    assert "chart error" in curves and len(curves) >= 2
    for id, pts in curves.items():
        inside = [(x, y) for x, y in pts if x0 - 2 <= x <= x1 + 2 and y0 - 2 <= y <= y1 + 2]
        assert inside == [], (id, inside, (x0, y0, x1, y1))
        # the lines between the points, sampled at least every pixel
        for a, b in zip(pts, pts[1:]):
            t = np.linspace(0.0, 1.0, int(np.hypot(*(b - a))) + 2)[:, None]
            s = a + t * (b - a)
            hit = (s[:, 0] >= x0) & (s[:, 0] <= x1) & (s[:, 1] >= y0) & (s[:, 1] <= y1)
            assert not hit.any(), (id, s[hit][:3])


def test_a_key_with_no_free_corner_goes_above_the_curves():
    # a chart whose every corner and side has a line: no place (None); one free corner: that corner
    cross = [[[0.0, 0.0], [200.0, 100.0]], [[0.0, 100.0], [200.0, 0.0]], [[0.0, 50.0], [200.0, 50.0]]]
    assert key_corner(cross, (200.0, 100.0), (60.0, 30.0)) is None
    assert key_corner(cross[:1], (200.0, 100.0), (60.0, 30.0)) == (2.0, 68.0)          # upper left
    bands = [[[0.0, 80.0], [100.0, 98.0]], [[0.0, 0.0], [100.0, 30.0]]]
    assert key_corner(bands, (100.0, 100.0), (30.0, 20.0)) == (68.0, 40.0)            # middle right
