"""The trees explorer's time: one update does a bounded amount of work (issue 23, second pass).

Jumping the time to 60 s used to integrate 1,200 checkpoints of the nine links in one update (52 s under
load).  Now an update spends at most ``UPDATE_EVALS`` evaluations of the dynamics (the slider-crank's
:class:`planargeo.widgets._motion.Budget`): a farther time is refused in the package's words, controls,
readout and picture stay on the shown state, and asking again goes on from the checkpoints computed.
The motion reached that way is checked against references outside the integrator: the loops' closure
and the links' lengths read off the picture, the energy of the links coasting without gravity (no
force does work: ``E(t) = E(0)``), and the same state reached by another path (one state per time).
"""
from __future__ import annotations

import math
import re

import pytest

from _limits import REFUSAL, ask, by_steps, picture_texts, play_after_refusal, time_limit
from planargeo.errors import SizeLimitError
from planargeo.widgets import TreeExplorer
from planargeo.widgets.trees import T_END, UPDATE_EVALS

TIME = "t (s)"
#: the picture's coordinates are rounded to 1e-5 m
TOL = 5e-5


def _links(pic) -> dict:
    """Body ``i``: the two ends of its link as drawn (its joint, its tip)."""
    out = {}
    for e in pic["elements"]:
        if e["role"] == "body" and e["id"].startswith("body "):
            path = next(p for p in e["parts"] if p["p"] == "path")
            out[int(e["id"].split()[1])] = [tuple(map(float, xy)) for xy in path["xy"]]
    return out


def _one_state(ex) -> None:
    """Controls, readout and picture tell the same state; in the picture the nine links are 1 m long,
    joined as the tree of Fig 9.1, and the loops of Fig 9.2 are closed (tips 4-7 and 8-9 meet)."""
    ro, pic = ex.readout_values, ex.picture()
    assert ro["t"] == float(ex.values[TIME])
    links = _links(pic)
    assert sorted(links) == list(range(1, 10))
    for (a, b) in links.values():
        assert abs(math.dist(a, b) - 1.0) < TOL                              # rigid links
    assert math.dist(links[1][0], (0.0, 0.0)) < TOL                          # body 1 on the pivot
    # the tree of Fig 9.1: each body's joint is its parent's tip (2, 5, 9 on body 1; 3 on 2; 4 on 3;
    # 6 on 5; 7 and 8 on 6)
    for child, parent in ((2, 1), (5, 1), (9, 1), (3, 2), (4, 3), (6, 5), (7, 6), (8, 6)):
        assert math.dist(links[child][0], links[parent][1]) < TOL, (child, parent)
    assert math.dist(links[4][1], links[7][1]) < TOL                         # loop closed: pin 4-7
    assert math.dist(links[8][1], links[9][1]) < TOL                         # loop closed: pin 8-9
    hs = {h["id"]: (h["x"], h["y"]) for h in pic["handles"]}
    assert math.dist(hs["tip of body 1"], links[1][1]) < TOL                 # handles on the links drawn
    assert math.dist(hs["tip of body 2"], links[2][1]) < TOL


def _ask(ex, t: str) -> re.Match | None:
    return ask(ex, TIME, t)


def test_a_far_time_is_refused_in_words_and_asking_again_goes_on():
    ex = TreeExplorer(display="agg")                 # closed loops, no gravity: the links coast
    assert ex.values["gravity"] == 0.0 and ex.values["loops"].startswith("closed")
    shown = dict(ex.readout_values)
    E0 = shown["energy E"]
    _one_state(ex)
    end = f"{T_END:g}"
    m = _ask(ex, end)
    assert m, ex.message
    assert m["t"] == end and int(m["n"].replace(",", "")) == UPDATE_EVALS
    assert f"t = {end} s" in ex.message and "(refused:" not in ex.message   # the time named once, with its unit
    first = float(m["reached"])
    assert 0.0 < first < T_END
    # the state shown is still t = 0: controls, readout, picture
    assert ex.values[TIME] == "0" and ex.readout_values == shown
    _one_state(ex)
    assert (f"too far for one step: computed up to {m['reached']} s; ask again to go on"
            in picture_texts(ex.picture()))
    # asking again goes on from the checkpoints kept
    m = _ask(ex, end)
    assert m, ex.message
    reached = m["reached"]
    assert float(reached) > first and ex.values[TIME] == "0" and ex.readout_values == shown
    # the time reached is shown at once (its checkpoints are kept)
    assert _ask(ex, reached) is None and ex.message == "", ex.message
    assert ex.values[TIME] == reached
    _one_state(ex)
    ro = ex.readout_values
    assert ro["t"] == float(reached) > 0.0
    # no gravity, no drive: the energy is conserved, E(t) = E(0), to the Play integration's tolerance
    # (rtol 1e-7 per checkpoint; about 1e-7 measured over 15 s)
    assert abs(ro["energy E"] - E0) < 1e-5 * abs(E0)
    assert abs(ro["energy drift ΔE/E₀"]) < 1e-5
    assert ro["closure drift |φ|"] < 1e-6

    # a new explorer given the far time is bounded too: one update's work, then the same words
    with time_limit(300), pytest.raises(SizeLimitError, match=REFUSAL.pattern.replace(r"(?P<t>\S+)", end)):
        TreeExplorer(display="agg", **{**ex.values, TIME: end})

    # the same time reached by another path, in steps each within one update: the same state
    def same_motion(other):
        _one_state(other)
        assert abs(other.readout_values["energy E"] - E0) < 1e-5 * abs(E0)
    steps = [f"{float(reached) * k / 4:.9g}" for k in (1, 2, 3)] + [reached]
    other = by_steps(TreeExplorer(display="agg"), TIME, steps, same_motion)
    assert other.readout_values == ro


def test_play_after_a_refusal_goes_on_from_the_shown_time():
    """A refused jump leaves Play where it was: frames on from the shown t = 0, the loops closed."""
    ex = play_after_refusal(TreeExplorer(display="agg"), TIME, f"{T_END:g}")
    assert 0.0 < ex.readout_values["t"] < 1.0
    _one_state(ex)
