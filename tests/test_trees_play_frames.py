"""TreeExplorer's Play at 1× (student review: 1.25 frames/s in Voila, t = 2.23 s after 6 s of wall time).

Each frame integrated afresh from the last checkpoint to its time (DOP853 restarted, ~40 evaluations of
the constrained dynamics: ~90 ms a frame on the loaded machine, against ~4 ms for the solve and the
picture).  Now the checkpoints' steps keep the states on Play's grid of 1/60 s (the integrator's dense
output projected onto the loops), Play's times fall on that grid with the clock's remainder carried, and a
frame integrates nothing once the work ahead is done.  Checked: no integration in such frames, the
time scale true, the states those of an independent integration and of a fresh explorer at that time.
"""
import math

import numpy as np
import pytest

import planargeo.widgets.trees as trees_widget
from planargeo.scenes.trees import tree_advance
from planargeo.simulate.loops import closure_residual
from planargeo.widgets.trees import TreeExplorer


def playing(**values):
    ex = TreeExplorer(display="agg", **values)
    ex.play_control.playing = True          # as while the page plays (its ticks call the same frames)
    return ex


@pytest.mark.parametrize("dt", [1 / 30, 0.021])
def test_play_frames_integrate_nothing_once_the_work_ahead_is_done_and_keep_the_time_scale(dt, monkeypatch):
    ex = playing()
    calls = []

    def counted(*a, **k):
        calls.append(a[3])
        return tree_advance(*a, **k)

    monkeypatch.setattr(trees_widget, "tree_advance", counted)
    n = 40
    for k in range(n):
        while ex.play_ahead(ex.shown_values, 1.0):        # the page's idle time between frames
            pass
        before = len(calls)
        ex.advance(1, seconds=dt)                         # a tick: the clock's seconds since the last
        assert ex.message == ""
        assert len(calls) == before, f"frame {k} integrated {calls[before:]}"
        t = float(ex.values["t (s)"])
        assert t * 60 == pytest.approx(round(t * 60), abs=1e-6)         # on Play's grid
        assert (k + 1) * dt - 1 / 60 - 1e-9 <= t <= (k + 1) * dt + 1e-9  # 1× (the rest is carried)
    assert calls                                         # the work ahead did integrate (whole steps)
    assert all(h == pytest.approx(trees_widget.CHECKPOINT) for h in calls)


def test_a_play_frame_shows_the_motion_at_its_time():
    """The frame's state against an independent integration from t = 0 (tighter tolerances, one run)
    and against a fresh explorer given that time (the state at a time depends on the time alone)."""
    ex = playing()
    for _ in range(37):
        ex.advance(1, seconds=1 / 30 + 0.003)
    t = float(ex.values["t (s)"])
    assert 1.2 < t < 1.35 and abs(t * 60 - round(t * 60)) < 1e-6 and abs(t / trees_widget.CHECKPOINT % 1) > 1e-3
    m = ex.state["model"]
    start = TreeExplorer(display="agg", **{**ex.values, "t (s)": "0"}).state
    ref = tree_advance(m, start["q"], start["qd"], round(t * 60) / 60, rtol=1e-11, atol=1e-13)
    np.testing.assert_allclose(ex.state["q"], ref["q"], atol=1e-7)
    np.testing.assert_allclose(ex.state["qd"], ref["qd"], atol=1e-7)
    assert np.abs(closure_residual(m, ex.state["q"])).max() < 1e-10                 # on the loops
    assert ex.readout_values["closure drift |φ|"] >= np.abs(closure_residual(m, ex.state["q"])).max()
    fresh = TreeExplorer(display="agg", **ex.values)
    np.testing.assert_array_equal(fresh.state["q"], ex.state["q"])
    assert fresh.readout_values == ex.readout_values


def test_without_play_running_the_time_is_the_step_asked_for():
    ex = TreeExplorer(display="agg")
    ex.advance(3, seconds=0.03)
    assert float(ex.values["t (s)"]) == pytest.approx(0.03, abs=1e-12)
    assert math.isclose(ex.readout_values["t"], 0.03, abs_tol=1e-12)
