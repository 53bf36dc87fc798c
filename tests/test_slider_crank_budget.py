"""The slider-crank explorer's time: one update does a bounded amount of work (issue 23, second pass).

Jumping the time to 10 s used to integrate 500 checkpoints in one update (104 s under load).  Now an
update spends at most ``UPDATE_EVALS`` evaluations of the loop's dynamics (the budget mechanism of the
chain explorer's time slider, :class:`planargeo.widgets._motion.Budget`): a farther time is refused in
the package's words, controls, readout and picture stay on the shown state, and asking again goes on
from the checkpoints already computed.  The motion reached that way is checked against references
outside the integrator: the loop's closure read off the picture (crank pin on its circle, rod length
between crank pin and wrist pin), energy conservation of the free crank, and the same state reached by
another path (one state per time).
"""
from __future__ import annotations

import math
import re

import pytest

from _limits import REFUSAL, ask, by_steps, picture_texts, play_after_refusal, time_limit
from planargeo import scenes
from planargeo.errors import SizeLimitError
from planargeo.widgets import SliderCrankExplorer
from planargeo.widgets.slider_crank import UPDATE_EVALS

TIME = "t (s)"


def _one_state(ex) -> None:
    """Controls, readout and picture tell the same state; the loop is closed in the picture."""
    ro, pic = ex.readout_values, ex.picture()
    assert ro["t"] == float(ex.values[TIME])
    r, l = float(scenes.parameters("slider-crank")["r"]), float(ex.values["rod length"])
    hs = {h["id"]: (h["x"], h["y"]) for h in pic["handles"]}
    pin, wrist = hs["crank pin"], hs["piston"]
    psi = math.radians(ro["crank angle ψ"])
    tol = 2e-4                                            # the picture's coordinates are rounded to 1e-4
    assert math.hypot(pin[0] - r * math.cos(psi), pin[1] - r * math.sin(psi)) < tol   # readout = picture
    assert abs(wrist[0]) < tol                                                        # on the slide
    assert abs(math.hypot(pin[0] - wrist[0], pin[1] - wrist[1]) - l) < tol            # the rod closes the loop


def _ask(ex, t: str) -> re.Match | None:
    return ask(ex, TIME, t)


def test_a_far_time_is_refused_in_words_and_asking_again_goes_on():
    ex = SliderCrankExplorer(display="agg")
    shown = dict(ex.readout_values)
    E0 = shown["energy E"]
    m = _ask(ex, "5")
    assert m, ex.message
    assert m["t"] == "5" and int(m["n"].replace(",", "")) == UPDATE_EVALS
    assert "t = 5 s" in ex.message and "(refused:" not in ex.message   # the time named once, with its unit
    first = float(m["reached"])
    assert 0.0 < first < 5.0
    # the state shown is still t = 0: controls, readout, picture
    assert ex.values[TIME] == "0" and ex.readout_values == shown
    _one_state(ex)
    on_picture = picture_texts(ex.picture())
    assert f"too far for one step: computed up to {m['reached']} s; ask again to go on" in on_picture
    # asking again goes on from the checkpoints kept
    reached = [first]
    for _ in range(10):
        m = _ask(ex, "5")
        if m is None:
            break
        reached.append(float(m["reached"]))
        _one_state(ex)
    assert m is None and ex.message == "" and ex.values[TIME] == "5", ex.message
    assert len(reached) >= 1 and reached == sorted(set(reached))     # each ask went further
    _one_state(ex)
    ro = ex.readout_values
    # the free crank under gravity conserves energy (no drive, no damping): E(5 s) = E(0), to the Play
    # integration's tolerance (rtol 1e-7 per checkpoint; 4e-6 measured over 5 s, most of it at dead centres)
    assert abs(ro["energy E"] - E0) < 2e-5 * abs(E0)
    assert abs(ro["energy drift ΔE/E₀"]) < 2e-5
    assert ro["closure drift"] < 1e-6

    # a new explorer given these values is bounded too: one update's work, then the same words
    with time_limit(300), pytest.raises(SizeLimitError, match=REFUSAL.pattern.replace(r"(?P<t>\S+)", "5")):
        SliderCrankExplorer(display="agg", **ex.values)

    # the same time reached by another path, in steps each within one update: the same state
    def same_motion(other):
        _one_state(other)
        assert abs(other.readout_values["energy E"] - E0) < 2e-5 * abs(E0)
    other = by_steps(SliderCrankExplorer(display="agg"), TIME, ("1.5", "3", "4.5", "5"), same_motion)
    assert other.readout_values == ro


def test_play_after_a_refusal_goes_on_from_the_shown_time():
    """A refused jump leaves Play where it was: one frame on from the shown t = 0."""
    ex = play_after_refusal(SliderCrankExplorer(display="agg"), TIME, "10")
    assert 0.0 < ex.readout_values["t"] < 0.1
    _one_state(ex)
