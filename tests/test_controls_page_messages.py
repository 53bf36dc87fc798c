"""What the kernel sends the page about a slider: its ``disabled`` in a message without its value.

The page's slider (ipywidgets 8.1) draws ``disabled`` in an update it skips for a change it made
itself; given a value, it writes back its copy rounded to its grid within the same change, so a
``disabled`` sent with the value stayed undrawn (the student's review: "direction of F₁" greyed in
wrench addition after twist addition had disabled it).  Measured here on the messages themselves, as
the page would receive them; the page's own drawing is checked in
tests/browser/test_construction_enabled.py.
"""
from __future__ import annotations

import pytest

from planargeo.widgets import ConstructionExplorer
from planargeo.widgets.controls import Step


class Comm:
    """A comm that keeps what the widget sends (as the page would receive it)."""

    comm_id = "recorder"
    kernel = object()

    def __init__(self):
        self.sent = []

    def send(self, data=None, buffers=None):
        self.sent.append(data)

    def on_msg(self, callback):
        pass

    def close(self, *a, **k):
        pass


def _states(comm):
    return [m["state"] for m in comm.sent if m.get("method") == "update"]


@pytest.fixture
def recorded():
    """``record(widget)``: the widget sends to a :class:`Comm` (let go after the test)."""
    widgets = []

    def record(w):
        w.comm = Comm()
        widgets.append(w)
        return w.comm

    yield record
    for w in widgets:
        w.comm = None          # (a recorder left on a widget is closed at exit, after ipywidgets' tables)


def test_a_sliders_disabled_and_value_go_in_separate_messages_value_first(recorded):
    w = Step(-180, 180, 5, 0.0, "direction (deg)").make("angle")
    w.disabled = True
    comm = recorded(w)
    with w.hold_sync():
        w.value = 60.0
        w.disabled = False
        w.description = "direction of F₁ (deg)"
    states = _states(comm)
    assert not [s for s in states if "value" in s and "disabled" in s], states
    assert states[-1] == {"disabled": False}, states
    assert states[0]["value"] == 60.0 and states[0]["description"] == "direction of F₁ (deg)"


def test_a_disabled_state_alone_is_one_message(recorded):
    w = Step(0, 10, 1, 3, "n", integer=True).make("n")
    comm = recorded(w)
    w.disabled = True
    assert _states(comm) == [{"disabled": True}]


def test_switching_construction_enables_the_direction_slider_in_a_message_of_its_own(recorded):
    ex = ConstructionExplorer()                      # twist addition: u₁ = 0, its direction disabled
    w = ex.controls["angle1"]
    assert w.disabled
    comm = recorded(w)
    ex.set(construction="wrench_sum")
    assert not w.disabled
    states = _states(comm)
    with_disabled = [s for s in states if "disabled" in s]
    assert with_disabled and with_disabled[-1] == {"disabled": False}, states
    assert not [s for s in states if "value" in s and "disabled" in s], states


def test_the_pages_rounded_copy_of_a_value_set_here_is_its_echo_not_a_change():
    """Set to 60, the page's slider (step 5 from −180) writes back 59.99999999999997: an echo, which
    changes neither the values (60 exactly) nor the state (no new computation)."""
    ex = ConstructionExplorer()
    ex.set(construction="wrench_sum")
    w = ex.controls["angle1"]
    assert ex.values["angle1"] == 60.0
    computes = ex.n_computes
    w.set_state({"value": 59.99999999999997})             # as the page sends it
    assert ex.values["angle1"] == 60.0
    assert ex.n_computes == computes and ex.message == ""
    w.set_state({"value": 65.0})                          # a step of the student's: a change
    assert ex.values["angle1"] == 65.0 and ex.n_computes == computes + 1
