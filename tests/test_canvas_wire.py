"""The page's wire format against a reference built part by part (planargeo.widgets.canvas.wire_element).

Every data coordinate is Python's ``round(v, nd)`` of the picture's number, every pixel
offset or size ``round(v, 1)``, whatever the parts share: a pole's marker, glyph and
label sit on one point, and equal numbers held apart, zeros of either sign and
integers keep their own rounding.
"""
from __future__ import annotations

import json

import numpy as np
import pytest
from hypothesis import given, settings, strategies as st

from planargeo.draw.picture import Picture
from planargeo.widgets.canvas import wire_element

_XY = {"text": ("x", "y"), "mark": ("x", "y"), "arrow": ("x", "y"), "glyph": ("x", "y"), "ellipse": ("x", "y")}
_PX = {"text": ("dx", "dy"), "mark": ("size",), "arrow": ("dx", "dy"), "glyph": ("r",)}


def _reference_numbers(el: dict, nd: int) -> list:
    """The numbers of an element's wire parts, each rounded on its own, in wire order."""
    out = []
    for p in el["parts"]:
        k = p["p"]
        if k == "text" and p.get("hidden"):
            continue
        if k == "path":
            xy = p["xy"]
            if len(xy) > 3:         # a long path: numpy's rounding (the documented exception)
                out.append((np.round(np.asarray(xy, float).ravel(), nd) + 0.0).tolist())
            else:
                out.append([round(v, nd) for q in xy for v in q])
            continue
        nums = [round(p[f], nd) for f in _XY[k]] + [round(p[f], 1) for f in _PX.get(k, ())]
        if k == "ellipse":
            nums += [round(v, nd + 1) for v in p["m"]]
        out.append(nums)
    return out


def _wire_numbers(w: dict) -> list:
    out = []
    for part in w["parts"]:
        kind = part[0]
        if kind == "P":
            out.append(part[2:])
        elif kind == "T":
            out.append(part[1:5])
        elif kind == "M":
            out.append([part[1], part[2], part[4]])
        elif kind == "A":
            out.append(part[1:5])
        elif kind == "G":
            out.append(part[1:4])
        elif kind == "E":
            out.append([part[1], part[2]] + part[3:7])
    return out


def _same(a, b) -> bool:
    """Equal as the page reads them: the same JSON text (so 0.0 and -0.0, 1 and 1.0 differ)."""
    return json.dumps(a) == json.dumps(b)


@settings(max_examples=60, deadline=None)
@given(st.lists(st.tuples(st.floats(-3.0, 3.0), st.floats(-3.0, 3.0), st.floats(0.05, 4.0)),
                min_size=1, max_size=8),
       st.integers(0, 6))
def test_a_pictures_wire_is_its_numbers_rounded_one_by_one(poles, nd):
    pic = Picture((-4, 4, -4, 4), size=(300, 300))
    for k, (x, y, w) in enumerate(poles):
        pic.point(f"P{k}", [y * w, -x * w, w], role="twist", symbol=f"v{k}", desc="a pole")
        pic.line(f"f{k}", [x, y, w], role="wrench", symbol=f"f{k}", anchor=(x, y))
    pic.conic("A", np.diag([1.0, 2.0, -0.5]), role="inertia", symbol="A")
    pic.path("links", [[0.0, 0.0], [1.0, 0.5], [1.5, -0.5], [2.0, 0.0]], role="body")
    for el in pic.to_dict()["elements"]:
        assert _same(_wire_numbers(wire_element(el, nd)), _reference_numbers(el, nd)), el["id"]


@pytest.mark.parametrize("x, y", [(0.12345, 0.12345), (-0.0, 0.0), (0.0, -0.0), (1, 1.0), (2.675, 2.675)])
def test_parts_that_share_a_number_or_only_its_value_round_alike(x, y):
    # the marker's point held once and its equal held apart (another object, another type, zero's sign)
    el = {"id": "P", "role": "twist", "parts": [
        {"p": "mark", "x": x, "y": x, "shape": "o", "size": 6.94},
        {"p": "glyph", "x": x, "y": x, "r": 8.33, "ccw": True},
        {"p": "text", "x": y, "y": y, "dx": 4.25, "dy": -4.25, "text": "P", "ha": "left", "va": "bottom"},
        {"p": "arrow", "x": float(str(y)), "y": y, "dx": 1.0, "dy": 0.0}]}
    for nd in (0, 2, 3):
        assert _same(_wire_numbers(wire_element(el, nd)), _reference_numbers(el, nd))
