"""Twist addition's controls say and do what is drawn (a student's review in Voila).

1. "direction of u₁" was live while u₁ = 0 and moved nothing; now it is disabled with the reason, and
   so are the centre's sliders of a translation (ω = 0), which move nothing either.
2. With u₂ = −3 the drawn pole of v₂ moved to (3, 0.5) while the sliders named "pole of v₂" read
   (1.5, 0.5) and the handle v₂ stayed there.  The sliders set the centre of the rotation ω₂, before
   u₂ shifts the pole by ρ = u/ω across u (4.16): they are named so, and the handle v₂ sits on the
   pole drawn.  The reference is that closed form, not the scene's code.
(3., the menu's label cut in the page, is measured in tests/browser/test_construction_page.py.)
"""
from __future__ import annotations

import math

import pytest

from planargeo.scenes.construction import construct
from planargeo.widgets import ConstructionExplorer


def pole(x, y, w, u, angle_deg):
    """The pole of ω about (x, y) plus u at ``angle_deg``: the centre shifted by u/ω across u (4.16)."""
    a = math.radians(angle_deg)
    return (x - u * math.sin(a) / w, y + u * math.cos(a) / w)


def drawn(ex, name):
    """The drawn mark of element ``name`` (a finite pole) in the explorer's picture."""
    el = next(e for e in ex.picture()["elements"] if e["id"] == name)
    m = next(p for p in el["parts"] if p["p"] == "mark")
    return m["x"], m["y"]


def test_the_direction_of_a_zero_translation_is_disabled_with_its_reason():
    ex = ConstructionExplorer("twist_sum", display="agg")
    assert ex.values["u1"] == 0.0
    # what the review saw: the direction moves nothing while u₁ = 0
    a, b = (construct("twist_sum", angle1=t).steps[0].elements[0].value for t in (-180.0, 180.0))
    assert a.tolist() == b.tolist()
    w = ex.controls["angle1"]
    assert w.disabled and "u₁ = 0" in w.tooltip and "direction" in w.tooltip, w.tooltip
    # with a translation, the direction is live and turns the pole about the centre (4.16)
    ex.set(u1=1.0)
    assert not ex.controls["angle1"].disabled
    ex.set(angle1=90.0)
    assert drawn(ex, "Q1") == pytest.approx(pole(-1.5, 0.0, 1.0, 1.0, 90.0))
    ex.set(angle1=0.0)
    assert drawn(ex, "Q1") == pytest.approx(pole(-1.5, 0.0, 1.0, 1.0, 0.0))


def test_a_translations_centre_is_disabled_and_has_no_handle():
    ex = ConstructionExplorer("twist_sum", display="agg", w2=0.0, u2=2.0)
    # a translation's pole is at infinity: its centre moves nothing
    a, b = (construct("twist_sum", w2=0.0, u2=2.0, x2=t).steps[0].elements[1].value for t in (-3.0, 3.0))
    assert a.tolist() == b.tolist()
    for k in ("x2", "y2"):
        w = ex.controls[k]
        assert w.disabled and "ω₂ = 0" in w.tooltip and "translation" in w.tooltip, w.tooltip
    assert ex.handle_position("v₂") is None
    assert not ex.controls["x1"].disabled and ex.handle_position("v₁") == pytest.approx((-1.5, 0.0))


def test_the_sliders_name_the_centre_and_the_handle_sits_on_the_pole_drawn():
    ex = ConstructionExplorer("twist_sum", display="agg")
    ex.set(u2=-3.0)
    want = pole(1.5, 0.5, 2.0, -3.0, 90.0)
    assert want == pytest.approx((3.0, 0.5))
    assert drawn(ex, "Q2") == pytest.approx(want)
    assert ex.handle_position("v₂") == pytest.approx(want)            # on the pole drawn
    assert (ex.values["x2"], ex.values["y2"]) == (1.5, 0.5)              # what the sliders set ...
    for k, axis in (("x2", "x"), ("y2", "y")):                           # ... and what they say
        assert ex.controls[k].description == f"centre of ω₂: {axis} (m)"
        assert "pole" not in ex.controls[k].description
    # dragged, the pole lands under the pointer and the centre keeps its offset ρ = u/ω across u
    ex.drag("v₂", ex.handle_position("v₂"), (2.0, 1.0), steps=2)
    assert ex.message == ""
    assert drawn(ex, "Q2") == pytest.approx((2.0, 1.0))
    assert ex.handle_position("v₂") == pytest.approx((2.0, 1.0))
    assert (ex.values["x2"], ex.values["y2"]) == pytest.approx((0.5, 1.0))


def test_a_pole_beyond_the_view_has_no_handle_and_the_sliders_still_move_it():
    ex = ConstructionExplorer("twist_sum", display="agg")
    ex.set(u1=3.0, w1=0.05)                     # ρ = u/ω = 60 m: the pole far above the view
    assert ex.message == "" and ex.handle_position("v₁") is None
    assert "v₁" not in {h["id"] for h in ex.picture()["handles"]}
    ex.set(w1=1.0)                              # back in view: the handle on it again
    assert ex.handle_position("v₁") == pytest.approx(pole(-1.5, 0.0, 1.0, 3.0, 0.0))
