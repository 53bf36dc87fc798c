"""Twist addition's words agree: the sliders set the centre of ω₁, the handle and the picture show the
pole Q₁; the sliders' hover text says how the two differ (by ρ = u₁/ω₁, 4.16), the handles say what a
drag does (the student's review: "centre of ω₁" on the sliders, "pole" in the tips and readout).
The drawn pole against the closed form of 4.16 is checked in tests/test_construction_twist_controls.py.
"""
from __future__ import annotations

import math

from planargeo.widgets import ConstructionExplorer


def handle_tips(ex) -> dict:
    return {h["id"]: h["desc"] for h in ex.picture()["handles"]}


def test_the_centre_sliders_say_how_the_centre_and_the_drawn_pole_differ():
    ex = ConstructionExplorer(u1=1.0, angle1=0.0)
    for name in ("x1", "y1"):
        w = ex.controls[name]
        assert w.description.startswith("centre of ω₁")
        assert "pole Q₁" in w.tooltip and "ρ = u₁/ω₁" in w.tooltip and "4.16" in w.tooltip, w.tooltip
    assert "pole Q₂" in ex.controls["x2"].tooltip


def test_the_handles_say_they_sit_on_the_pole_and_move_the_centre():
    ex = ConstructionExplorer(u1=1.0, angle1=0.0)
    tips = handle_tips(ex)
    assert tips["v₁"].startswith("pole Q₁ of v₁") and "centre of ω₁" in tips["v₁"], tips
    # the handle sits on the pole: the centre (x₁, y₁) shifted by u₁/ω₁ across u₁ (4.16)
    h = next(h for h in ex.picture()["handles"] if h["id"] == "v₁")
    v = ex.values
    rho = v["u1"] / v["w1"]
    assert math.isclose(h["x"], v["x1"], abs_tol=1e-9)
    assert math.isclose(h["y"], v["y1"] + rho, abs_tol=1e-9)


def test_a_disabled_centre_says_why_and_its_meaning_comes_back():
    ex = ConstructionExplorer(u1=1.0)
    ex.set(w1=0.0)
    assert ex.controls["x1"].disabled and ex.controls["x1"].tooltip.startswith("ω₁ = 0")
    ex.set(w1=1.0)
    assert not ex.controls["x1"].disabled and "pole Q₁" in ex.controls["x1"].tooltip


def test_the_wrench_sliders_take_no_twist_words_and_its_handles_say_their_drag():
    ex = ConstructionExplorer()
    ex.set(construction="wrench_sum")
    assert not ex.controls["x1"].tooltip
    tips = handle_tips(ex)
    assert tips["f₁ direction"].startswith("direction of F₁: drag it to turn"), tips
    assert "line of action" in tips["f₁"], tips
