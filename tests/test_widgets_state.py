"""One consistent state in every explorer (issue 16, item 3).

After any change, from the keyboard, the page's pointer or code, the controls, the
picture and the readout show one state: the last one computed.  A value that
cannot be shown (NaN, out of range, ``None``, an impossible or singular
configuration) is refused by name and the controls return to that state; no
exception escapes a callback.

The reference for "the picture and readout show the state" is the explorer's
own reading of its shown state, done again from scratch: :meth:`readout_of` of
``ex.state`` with the controls as they are must give the same readout, and the
picture the same data.
"""
from __future__ import annotations

import json
import math
import re

import ipywidgets as W
import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

import planargeo.widgets as widgets
from planargeo.errors import InputError
from planargeo.widgets.base import fmt

NAMES = sorted(widgets.EXPLORERS)
HOSTILE = [math.nan, math.inf, -math.inf, 1e300, -1e300, None, "x", "1.5", 1 + 2j, [1.0, 2.0], {}, True,
           np.float64("nan"), np.array([1.0, 2.0])]


def _png(ex) -> bytes:
    """What is drawn: the picture's data."""
    return json.dumps(ex.picture(), sort_keys=True).encode()


def assert_one_state(ex, pixels: bool = False) -> None:
    """Controls, readout (and figure) show ``ex.state``: drawing it again changes nothing."""
    assert ex.values == ex.shown_values
    readout = {k: fmt(v) for k, v in ex.readout_values.items()}
    before = _png(ex) if pixels else None
    assert {k: fmt(v) for k, v in ex.readout_of(ex.state).items()} == readout
    if pixels:
        assert _png(ex) == before


def _sliders(ex):
    return {k: w for k, w in ex.controls.items()
            if isinstance(w, (W.FloatSlider, W.IntSlider)) and not w.disabled}


@pytest.fixture(scope="module")
def explorers():
    return {name: getattr(widgets, name)(display="agg") for name in NAMES}


@pytest.mark.parametrize("name", NAMES)
def test_nan_in_any_slider_is_refused_by_name(name):
    """773 fuzzed cases kept the old numbers beside a NaN slider; display-only sliders took NaN silently."""
    ex = getattr(widgets, name)(display="agg")
    for control, w in _sliders(ex).items():
        shown, readout = w.value, dict(ex.readout_values)
        png = _png(ex)
        for bad in (math.nan, math.inf):
            if isinstance(w, W.IntSlider):                  # its trait takes no float: through set()
                ex.set(**{control: bad})
            else:
                w.value = bad                               # must not raise
            assert ex.message.startswith(f"{control} must be a"), (control, ex.message)
            assert w.value == shown and ex.readout_values == readout, control
            assert_one_state(ex)
            assert ex.figure_text.startswith(control)
        assert _png(ex) != png                              # the figure says so too
        w.value = shown + 0.0


def test_percussion_alpha_nan_gets_a_message_not_a_dash():
    ex = widgets.PercussionExplorer(display="agg")
    key = "force for α: m d α (5.66)"
    good = ex.readout_values[key]
    ex.controls["angular accel. α"].value = math.nan
    assert ex.message == "angular accel. α must be a number between -50 and 50, got nan"
    assert ex.readout_values[key] == good != "—" and ex.values["angular accel. α"] == 10.0
    assert_one_state(ex, pixels=True)


@pytest.mark.parametrize("name", [n for n in NAMES if n != "CarExplorer"])   # the car has no list
def test_none_in_any_list_is_refused_by_name(name):
    """Screw sum raised KeyError out of the callback; the others showed 'internal error (KeyError): None'."""
    ex = getattr(widgets, name)(display="agg")
    lists = {k: w for k, w in ex.controls.items() if isinstance(w, (W.Dropdown, W.ToggleButtons))}
    assert lists
    for control, w in lists.items():
        shown = w.value
        w.value = None                                      # must not raise
        assert ex.message.startswith(f"{control} must be one of"), ex.message
        assert "internal error" not in ex.message and w.value == shown
        assert_one_state(ex)


@pytest.mark.parametrize("name", NAMES)
def test_out_of_range_is_refused_not_clamped(name):
    """``set`` clamped 5 of 35 out-of-range values silently; now every one is refused, set or typed."""
    ex = getattr(widgets, name)(display="agg")
    for control, w in _sliders(ex).items():
        shown, span = w.value, w.max - w.min
        for bad in (w.max + 0.5 * span + 1, w.min - 0.5 * span - 1):
            ex.set(**{control: bad})
            assert ex.message.startswith(f"{control} must be "), ex.message
            assert f"between {w.min:g} and {w.max:g}" in ex.message and w.value == shown
            w.value = bad
            assert f"between {w.min:g} and {w.max:g}" in ex.message and w.value == shown
        assert_one_state(ex)


def test_set_refuses_the_whole_call_and_names_every_bad_value():
    ex = widgets.ChainExplorer(display="agg")
    shown = dict(ex.values)
    ex.set(angle=10.0, links=2.5, joints=None, gravity="yes", nope=1)
    assert ex.values == shown
    for part in ("links must be an integer between 1 and 20, got 2.5", "joints must be one of",
                 "gravity must be True or False, got 'yes'", "unknown control 'nope'"):
        assert part in ex.message
    ex.set(angle=10.0)
    assert ex.message == "" and ex.readout_values["links"] == 4


def test_slider_crank_slider_returns_to_the_shown_crank_angle():
    """By hand, the crank slider stayed at -180 while the figure and readout showed 90."""
    ex = widgets.SliderCrankExplorer(display="agg")
    ex.set(**{"rod length": 2.29, "crank angle (deg)": 90.0})
    assert "dead centre" in ex.message                     # shown, with a warning
    ex.controls["crank angle (deg)"].value = -180.0         # folded: the piston pin on the pivot
    assert "singular" in ex.message and "(refused: ψ₀ = -180°)" in ex.message
    assert ex.values["crank angle (deg)"] == 90.0 == ex.readout_values["crank angle ψ"]
    crank = next(e for e in ex.picture()["elements"] if e["id"] == "crank")
    xy = next(p["xy"] for p in crank["parts"] if p["p"] == "path")
    x, y = xy[-1] if isinstance(xy[0], list) else xy[-2:]   # the crank drawn at 90°: pin at (0, r)
    assert (x, y) == pytest.approx((0.0, 2.29), abs=1e-4)
    assert_one_state(ex, pixels=True)


@pytest.mark.parametrize("name", NAMES)
def test_initial_values_are_checked_by_name(name):
    cls = getattr(widgets, name)
    control, w = next(iter(_sliders(cls(display="agg")).items()))
    with pytest.raises(InputError, match=f"^{re.escape(control)} must be an? (number|integer) between"):
        cls(display="agg", **{control: math.nan})


def _hostile_changes(ex):
    """Sequences of good and hostile values; the good ones listed now (options follow the values, and
    a strategy must not read the explorer's changing state while it draws)."""
    names = sorted(ex.controls)
    sliders = _sliders(ex)
    good = {k: [ex.defaults[k], ex.controls[k].value] + (
        [o[1] if isinstance(o, tuple) else o for o in ex.controls[k].options]
        if isinstance(ex.controls[k], (W.Dropdown, W.ToggleButtons))
        else [ex.controls[k].min, ex.controls[k].max] if k in sliders else []) for k in names}
    valid = st.sampled_from(names).flatmap(lambda k: st.tuples(st.just(k), st.sampled_from(good[k])))
    hostile = st.tuples(st.sampled_from(names), st.sampled_from(HOSTILE))
    return st.lists(st.tuples(st.booleans(), st.one_of(valid, hostile)), min_size=1, max_size=6)


@pytest.mark.parametrize("name", NAMES)
def test_hostile_sequences_leave_one_state(name, explorers):
    """Any sequence of good and hostile values, through ``set`` or typed: never raises, always one state."""
    ex = explorers[name]

    @settings(max_examples=25, deadline=None)
    @given(changes=_hostile_changes(ex))
    def run(changes):
        for by_set, (control, value) in changes:
            if by_set:
                ex.set(**{control: value})
            else:
                try:
                    ex.controls[control].value = value
                except Exception as exc:  # the widget's own type check, before any callback
                    assert type(exc).__name__ == "TraitError", exc
            assert "internal error" not in ex.message, ex.message
            assert_one_state(ex)

    run()
    ex.reset()
    assert ex.values == ex.defaults and ex.message == ""


def test_dragging_off_the_map_never_raises():
    """A drag far off the view (as the page would send it) is refused by name; the state stays."""
    ex = widgets.ProjectiveExplorer(display="agg")
    start = (ex.values["P x"], ex.values["P y"])
    ex.drag("P", start, (1.0, -0.5), steps=1)
    assert ex.values["P x"] == pytest.approx(1.0) and ex.values["P y"] == pytest.approx(-0.5)
    for x, y in ((1e300, -1e300), (-1e300, 1e300)):        # far off the axes
        ex.drag("P", (1.0, -0.5), (x, y), steps=1)
        assert "internal error" not in ex.message
        assert ex.values["P x"] == pytest.approx(1.0) and ex.values["P y"] == pytest.approx(-0.5)
        assert_one_state(ex)


def test_initial_values_that_cannot_be_assembled_raise_the_scene_error():
    """There is no shown state to fall back to: the constructor says why, by the scene's error."""
    from planargeo.errors import SceneError

    with pytest.raises(SceneError, match="rod too short"):
        widgets.SliderCrankExplorer(display="agg", **{"rod length": 2.0, "crank angle (deg)": 0.0})
