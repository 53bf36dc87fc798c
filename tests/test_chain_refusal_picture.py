"""The chain explorer's picture says what to do when a time is too far for one update (issue 23).

The full refusal ("t = … s is more motion than one step computes (… evaluations of the dynamics); it
is computed up to t = … s now: ask again to go on from there, or press Play") is too long for the
picture: cut at the picture's length it lost "ask again".  The picture now carries the short form,
with the time reached, and the shown state stays (controls and readout).
"""
from __future__ import annotations

from _limits import ask
from planargeo.widgets import ChainExplorer

TIME = "time (s)"


def _message_on_picture(ex) -> str:
    el = [e for e in ex.picture()["elements"] if e["id"] == "figure message"]
    assert len(el) == 1
    texts = [p["text"] for p in el[0]["parts"] if p["p"] == "text"]
    return " ".join(" ".join(texts).split())


def test_a_far_time_says_ask_again_on_the_picture():
    ex = ChainExplorer(display="agg", duration=3600.0, links=20)
    shown, values = dict(ex.readout_values), dict(ex.values)
    reached = []
    for _ in range(2):
        m = ask(ex, TIME, 3600.0)
        assert m, ex.message
        assert "(refused: time t = 3600 s" in ex.message                   # the control named
        # the shown state stays: controls and readout of t = 0
        assert ex.values == values and ex.readout_values == shown
        on_picture = _message_on_picture(ex)
        assert on_picture == f"too far for one step: computed up to {m['reached']} s; ask again to go on"
        reached.append(float(m["reached"]))
    assert 0.0 < reached[0] < reached[1] < 3600.0                           # asking again went on
    # another refusal is drawn as before: the base's text, wrapped
    ex.set(**{"joint speeds": "fast"})
    assert "joint speeds" in ex.message and "ask again" not in _message_on_picture(ex)
    assert ex.values == values and ex.readout_values == shown
