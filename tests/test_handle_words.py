"""Refusals of a handle drag and of the time field said in words, with the symbols shown on screen
(review: "f1 direction must be non-zero: the arrow's tip is on its foot", "t (s) must be a time in
seconds, got ''"), and the construction explorer's handles named as the picture labels them."""
from __future__ import annotations

import pytest

from planargeo.widgets import ConstructionExplorer, ImpulseExplorer, SliderCrankExplorer

#: each construction's handles, named as its picture labels the screws (thesis chapter 4)
NAMES = {"twist_sum": {"v₁", "v₂"}, "wrench_sum": {"f₁", "f₂", "f₁ direction", "f₂ direction"},
         "velocity": {"vᵢ₋₁", "joint"}, "acceleration": {"vᵢ₋₁", "aᵢ₋₁", "joint"},
         "through_infinity": {"v₁", "h"}}


@pytest.mark.parametrize("kind", list(NAMES))
def test_construction_handles_are_named_as_drawn(kind):
    ex = ConstructionExplorer(kind, display="agg")
    names = {h.name for h in ex.all_handles()}
    assert NAMES[kind] <= names, names
    drawn = {h["symbol"] for h in ex.picture()["handles"]}
    assert NAMES[kind] <= drawn and not {"v1", "v2", "f1", "f2", "v_prev", "a_prev"} & drawn


def test_a_direction_dragged_onto_its_foot_is_refused_in_words():
    ex = ConstructionExplorer("wrench_sum", display="agg")
    shown = dict(ex.values)
    ex.drag("f₁ direction", ex.handle_position("f₁ direction"), ex.handle_position("f₁"))
    m = ex.message
    assert "f₁ direction cannot be on the arrow's foot" in m and "no direction" in m, m
    assert "must be non-zero" not in m and "f1" not in m
    assert ex.values["angle1"] == pytest.approx(shown["angle1"])       # the force keeps its direction


def test_an_impulse_dragged_to_zero_names_its_slider_symbol():
    ex = ImpulseExplorer(display="agg")
    ex.drag("blow tip", ex.handle_position("blow tip"), ex.handle_position("blow point"))
    label = ex.controls["J"].description.split(" (")[0]            # as the slider shows it
    assert f"{label} would be 0" in ex.message, ex.message
    assert "J must be non-zero" not in ex.message


@pytest.mark.parametrize("text, said", [("", "the time t is empty: type a time in seconds, from 0 to 10 s"),
                                        ("  ", "the time t is empty"),
                                        ("soon", "the time t must be a number of seconds, from 0 to 10 s, got “soon”"),
                                        ("11", "the time t must lie between 0 and 10 s, got 11 s")])
def test_the_time_field_refuses_in_words(text, said):
    ex = SliderCrankExplorer(display="agg")
    ex.set(**{"t (s)": text})
    assert ex.message.startswith(said), ex.message
    assert "t (s) must" not in ex.message and "''" not in ex.message
