"""Dragging handles and Play (issue 13): one update per move, no echo, no snapping, refusals keep state.

Drags are the page's drag messages (``ex.drag`` sends them through the canvas's own
check, ``PictureCanvas.handle_message``); Play's ticks are the page's tick messages; the
browser's slider echo is driven through ``Widget.set_state``, the method ipywidgets calls
for a message from the front end.
"""
from __future__ import annotations

import math

import numpy as np
import pytest

from planargeo.errors import InputError, SceneError
from planargeo.widgets import PercussionExplorer, ProjectiveExplorer
from planargeo.widgets.base import Handle

from _dot import PlayingDot as Dot


# ----------------------------------------------------------------------- drag
def test_drag_is_one_update_per_move_and_not_snapped():
    ex = Dot(display="agg")
    n = ex.n_updates
    ex.drag("dot", (0.0, 0.0), (0.737, -0.4213), steps=7)
    assert ex.n_updates == n + 7 + 1 and ex.message == ""      # 7 moves, and the release's redraw
    assert ex.values["x"] == pytest.approx(0.737) and ex.values["y"] == pytest.approx(-0.4213)
    assert ex.readout_values["x"] == pytest.approx(0.737)          # not on the 0.1 grid
    assert ex.readout_strings["x"] == "0.737 m"


def test_drag_in_the_page_is_one_picture_per_move():
    ex = Dot(display="page")
    version, n = ex.canvas.version, ex.n_updates
    ex.drag("dot", (0.0, 0.0), (0.513, -0.25), steps=5)
    assert ex.n_updates == n + 5 + 1                   # five moves and the release's redraw
    assert ex.canvas.version == version + 5            # the release's picture is the last move's: not sent
    h = ex.canvas.picture["handles"][0]
    assert (h["x"], h["y"]) == pytest.approx((0.513, -0.25))


def test_drag_is_checked_as_the_page_is():
    """A position the page's canvas refuses (beyond its coordinate limit) is refused the same way."""
    ex = Dot(display="agg")
    ex.drag("dot", (0.0, 0.0), (0.4, 0.1), steps=1)
    ex.drag("dot", (0.4, 0.1), (1e300, 0.0), steps=1)
    assert ex.message.startswith("drag of dot refused: x must be within")
    assert ex.values["x"] == pytest.approx(0.4) and ex.readout_values["x"] == pytest.approx(0.4)


def test_slider_echo_of_a_dragged_value_is_ignored():
    ex = Dot(display="agg")
    ex.drag("dot", (0.0, 0.0), (0.737, 0.0), steps=1)
    n = ex.n_updates
    ex.controls["x"].set_state({"value": 0.7})       # the browser's slider rounds to its step
    assert ex.n_updates == n and ex.values["x"] == pytest.approx(0.737)
    assert ex.shown_values["x"] == pytest.approx(0.737)
    ex.controls["x"].set_state({"value": 0.2})       # a real move of the slider
    assert ex.n_updates == n + 1 and ex.values["x"] == pytest.approx(0.2)


def test_python_set_to_a_rounded_value_is_not_an_echo():
    ex = Dot(display="agg")
    ex.drag("dot", (0.0, 0.0), (0.737, 0.0), steps=1)
    ex.controls["x"].value = 0.7
    assert ex.values["x"] == 0.7 and ex.readout_values["x"] == 0.7


def test_refused_drag_step_keeps_the_last_good_state():
    ex = Dot(display="agg")
    ex.drag("dot", (0.0, 0.0), (1.2, 0.0), steps=1)
    ex.drag("dot", (1.2, 0.0), (1.8, 0.0), steps=1)
    assert "x must not exceed 1.5" in ex.message
    assert ex.values["x"] == pytest.approx(1.2) and ex.readout_values["x"] == pytest.approx(1.2)
    assert ex.values == ex.shown_values


def test_drag_past_the_slider_range_stops_at_its_end():
    ex = Dot(display="agg")
    ex.drag("dot", (0.0, 0.0), (0.0, 5.0), steps=2)
    assert ex.values["y"] == 2.0 and ex.message == ""


def test_handle_that_raises_refuses_the_step_by_name():
    class Bad(Dot):
        def handles(self):
            def drag(x, y):
                raise SceneError("no such place")
            return [Handle("bad", lambda: (0.0, 0.0), drag)]

    ex = Bad(display="agg")
    ex.drag("bad", (0, 0), (1, 1), steps=2)
    assert "bad" in ex.message and "no such place" in ex.message and ex.values["x"] == 0.0


def test_drag_bad_arguments_are_input_errors():
    ex = Dot(display="agg")
    with pytest.raises(InputError, match="name must name a handle"):
        ex.drag("nope", (0, 0), (1, 1))
    with pytest.raises(InputError, match="steps"):
        ex.drag("dot", (0, 0), (1, 1), steps=0)
    with pytest.raises(InputError, match="finite"):
        ex.drag("dot", (0, 0), (math.nan, 1))


def test_refused_value_from_the_browser_returns_the_control():
    """The crank at -180 while the figure shows 90 must not happen: the refused value reverts."""
    ex = Dot(display="agg")
    ex.controls["x"].set_state({"value": 1.9})
    assert "x must not exceed 1.5" in ex.message
    assert ex.controls["x"].value == 0.0 and ex.readout_values["x"] == 0.0


# ----------------------------------------------------------------------- play
def test_advance_is_one_update_per_frame_and_stops_on_none():
    ex = Dot(display="agg")
    assert ex.has_play and ex.play_control is not None
    n = ex.n_updates
    ex.advance(4)
    assert ex.n_updates == n + 4
    assert ex.values["x"] == pytest.approx(4 * 1.0 / ex.play_fps)
    ex.advance(100)                                   # stops before x > 1
    assert 1.0 - 1.0 / ex.play_fps - 1e-9 <= ex.values["x"] <= 1.0


def test_speed_scales_the_time_step():
    ex = Dot(display="agg")
    ex.play_speed.value = 2.0
    ex.advance(1)
    assert ex.values["x"] == pytest.approx(2.0 / ex.play_fps)


class FakeClock:
    """A wall clock the test moves by hand."""

    def __init__(self):
        self.t = 100.0

    def __call__(self):
        return self.t


def _playing(ex):
    ex.wall_clock = FakeClock()
    ex.play_control.playing = True
    return ex.wall_clock


def test_play_widget_ticks_and_loops():
    ex = Dot(display="agg", x=0.9)
    clock = _playing(ex)
    ex.play_control.value += 1                        # the first tick: one frame (1/play_fps s)
    assert ex.values["x"] == pytest.approx(0.95)
    clock.t += 0.02
    ex.play_control.value += 1                        # 0.97
    assert ex.values["x"] == pytest.approx(0.97)
    clock.t += 0.05
    ex.play_control.value += 1                        # 1.02 > 1: back to the start (loop on)
    assert ex.values["x"] == pytest.approx(0.9) and ex.play_control.playing
    ex.play_loop.value = False
    for _ in range(4):
        clock.t += 0.05
        ex.play_control.value += 1
    assert not ex.play_control.playing


class Counted(Dot):
    """The dot, counting the calls of play_step and their time steps."""

    def play_step(self, values, dt):
        self.steps = getattr(self, "steps", []) + [dt]
        return super().play_step(values, dt)


@pytest.mark.parametrize("speed, scale", [(1.0, 1.0), (2.0, 1.0), (0.5, 0.1)])
def test_play_runs_at_real_time_in_sub_steps(speed, scale):
    """Simulated time = wall time × speed × time_scale, whatever the ticks; steps ≤ 1/play_fps."""
    ex = Counted(display="agg", v=0.1)
    ex.time_scale = scale
    ex.play_speed.value = speed
    clock = _playing(ex)
    ex.play_control.value += 1                        # the first tick: one frame
    x0 = ex.values["x"]
    assert x0 == pytest.approx(0.1 * speed * scale / ex.play_fps)
    ex.steps = []
    n = ex.n_updates
    clock.t += 0.37                                   # a slow frame: 0.37 s of wall time
    ex.play_control.value += 1
    assert ex.n_updates == n + 1                      # one picture
    assert ex.values["x"] == pytest.approx(x0 + 0.1 * 0.37 * speed * scale)
    assert sum(ex.steps) == pytest.approx(0.37 * speed * scale)
    assert max(ex.steps) <= 1.0 / ex.play_fps + 1e-12
    assert len(ex.steps) == math.ceil(0.37 * speed * scale * ex.play_fps - 1e-9)


def test_the_time_scale_is_shown_beside_the_speed_menu():
    class Slow(Dot):
        time_scale = 0.1

    assert "1× = real time" in Dot(display="agg").play_scale.value
    assert "1× plays 0.1 s of motion a second" in Slow(display="agg").play_scale.value
    assert Dot(display="agg").play_speed.description == "play at"     # not a second "speed"


PageDot = Counted


def test_play_in_the_page_ticks_from_the_canvas_in_sub_steps():
    """Page Play: the button's playing is the canvas's; each tick covers the wall time since the last,
    in sub-steps of at most 1/play_fps s (none skipped), and sets one picture; Play ends by the page."""
    ex = PageDot(display="page", v=0.5)
    clock = _playing(ex)
    assert ex.canvas.playing                           # the button started the page's ticks
    ex.steps, version = [], ex.canvas.version
    clock.t += 0.37
    assert ex.canvas.handle_message({"type": "tick", "seq": 1}) == (True, "")
    assert ex.canvas.version == version + 1            # one picture
    due = 0.37 + 1.0 / ex.play_fps                     # the first tick also shows one frame's motion
    assert sum(ex.steps) == pytest.approx(due) and max(ex.steps) <= 1.0 / ex.play_fps + 1e-12
    assert len(ex.steps) == math.ceil(due * ex.play_fps - 1e-9)
    assert ex.values["x"] == pytest.approx(0.5 * due)
    x = ex.values["x"]
    ex.play_control.value += 1                         # the Play widget's own timer does nothing here
    assert ex.values["x"] == x
    ex.play_loop.value = False
    for k in range(2, 60):                             # to x > 1: the run ends, the page stops ticking
        clock.t += 0.2
        ex.canvas.handle_message({"type": "tick", "seq": k})
        if not ex.play_control.playing:
            break
    assert not ex.play_control.playing and not ex.canvas.playing
    assert ex.values["x"] <= 1.0 and ex.message == ""


def test_a_refused_play_step_in_the_page_is_a_refused_tick():
    """A play step the scene refuses stops Play; the page gets the message with the tick's answer."""
    ex = PageDot(display="page", v=2.0, x=1.4)
    ex.play_loop.value = False
    ex.play_step = lambda values, dt: {"x": values["x"] + 0.2}      # past 1.5: refused by compute
    clock = _playing(ex)
    clock.t += 0.05
    ok, why = ex.canvas.handle_message({"type": "tick", "seq": 1})
    assert not ok and "x must not exceed 1.5" in why and not ex.canvas.playing
    assert ex.values["x"] == pytest.approx(1.4) and ex.figure_text


def test_ticks_queued_behind_a_slow_frame_are_dropped():
    import time

    class SlowStep(Dot):
        def play_step(self, values, dt):
            time.sleep(0.003)
            return super().play_step(values, dt)

    ex = SlowStep(display="agg")
    ex.play_control.interval = 1                      # every frame (3 ms of physics) is slower than 1 ms
    ex.play_control.playing = True
    ex.play_control.value += 1
    x = ex.values["x"]
    ex.play_control.value += 1                        # arrives at once: a backlog tick, dropped
    assert ex.values["x"] == x and x == pytest.approx(1.0 / ex.play_fps, rel=0.2)


def test_advance_bounds():
    """Long or meaningless runs are refused by name, with the limit and the opt-in (issue 23)."""
    ex = Dot(display="agg")
    for bad in (0, -1, 1.5, math.nan, math.inf, True):
        with pytest.raises(InputError, match="n_frames must be a positive integer"):
            ex.advance(bad)
    with pytest.raises(InputError, match=r"at most 10000 \(pass allow_long=True"):
        ex.advance(10 ** 6)
    for bad in (0.0, -1.0, math.nan, math.inf):
        with pytest.raises(InputError, match="seconds must be a positive finite number"):
            ex.advance(1, seconds=bad)
    with pytest.raises(InputError, match=r"at most 3600 s \(pass allow_long=True"):
        ex.advance(1, seconds=1e300)
    assert ex.values["x"] == 0.0 and ex.message == ""


def test_advance_seconds_is_sub_stepped_and_stop_keeps_what_was_computed():
    ex = Counted(display="agg", v=0.1)
    ex.advance(2, seconds=1.0)                        # two pictures, 20 steps of 0.05 s
    assert ex.values["x"] == pytest.approx(0.1) and len(ex.steps) == 20
    ex2 = Dot(display="agg", v=1.0)
    ex2.advance(1, seconds=3.0)                       # stops at x ≤ 1: the last good state is shown
    assert 0.95 - 1e-9 <= ex2.values["x"] <= 1.0 and ex2.readout_values["x"] == ex2.values["x"]


def test_drag_release_draws_the_shown_state_as_a_fresh_explorer():
    """The release of a drag draws the state as a fresh explorer with the same values draws it."""
    ex = Dot(display="agg")
    ex.drag("dot", (0.0, 0.0), (1.2, 0.3), steps=3)
    fresh = Dot(display="agg", **ex.values)
    assert ex.picture() == fresh.picture()


def test_no_play_without_play_step():
    ex = ProjectiveExplorer(display="agg")
    assert not ex.has_play and ex.play_control is None
    with pytest.raises(InputError, match="has no Play"):
        ex.advance(1)


# ----------------------------------------------------------------------- the two owned explorers
def _h(ex, name):
    return {h.name: h for h in ex.handles()}[name]


def test_projective_drag_P_moves_the_polar():
    ex = ProjectiveExplorer(display="agg")
    ex.drag("P", _h(ex, "P").where(), (0.613, -1.237), steps=4)
    P = np.array([-1.237, -0.613, 1.0])                 # [y, -x, 1]
    C = ex.state["C"]
    pol = np.asarray(ex.state["polar"], float)          # the polar line drawn
    assert np.allclose(np.cross(pol, C @ P), 0.0, atol=1e-12)
    assert ex.values["P x"] == pytest.approx(0.613)


def test_projective_drag_M_by_direction_turns_it_through_the_drag_point():
    ex = ProjectiveExplorer(display="agg")
    foot = np.array(_h(ex, "M (point)").where())
    ex.drag("M (direction)", _h(ex, "M (direction)").where(), (2.0, 3.0), steps=3)
    M = np.asarray(ex.state["M"], float)              # the line M drawn
    on = lambda x, y: M[2] + y * M[0] - x * M[1]      # 4.27
    assert on(2.0, 3.0) == pytest.approx(0.0, abs=1e-9)
    assert on(*foot) == pytest.approx(0.0, abs=1e-9)


def test_projective_drag_pole_of_M_makes_M_its_polar():
    ex = ProjectiveExplorer(display="agg")
    ex.drag("pole of M", _h(ex, "pole of M").where(), (0.5, 0.7), steps=3)
    assert ex.readout_values["pole of M"] == pytest.approx((0.5, 0.7))
    # independent: the polar of (0.5, 0.7) is C p, and it is M
    C = ex.state["C"]
    assert np.allclose(np.cross(C @ np.array([0.7, -0.5, 1.0]), np.asarray(ex.state["M"], float)), 0.0,
                       atol=1e-12)


def test_projective_pole_of_M_at_the_centre_is_refused():
    ex = ProjectiveExplorer(display="agg")
    before = dict(ex.values)
    ex.drag("pole of M", _h(ex, "pole of M").where(), (0.0, 0.0), steps=1)
    assert "line at infinity" in ex.message and ex.values == before


def test_percussion_drag_axis_through_a_point_gives_its_pole():
    ex = PercussionExplorer(display="agg", shape="uniform rod")
    ex.drag("axis (point)", _h(ex, "axis (point)").where(), (0.8, 0.0), steps=2)
    # uniform rod: c = (0.5, 0), ρ² = (1 + 0.08²)/12; an axis x = 0.8 has its pole on the axis
    # of the rod at d = ρ²/0.3 on the other side of c (5.68)
    rho2 = (1.0 + 0.08 ** 2) / 12.0
    assert ex.values["pole x"] == pytest.approx(0.5 - rho2 / 0.3, abs=1e-9)
    assert ex.values["pole y"] == pytest.approx(0.0, abs=1e-9)


def test_percussion_axis_through_the_centre_is_refused():
    ex = PercussionExplorer(display="agg", shape="uniform rod")
    before = dict(ex.values)
    ex.drag("axis (point)", _h(ex, "axis (point)").where(), (0.5, 0.0), steps=1)
    assert "infinity" in ex.message and ex.values == before


def test_percussion_impact_handle_only_in_impact_drive():
    ex = PercussionExplorer(display="agg")
    assert _h(ex, "impact").where() is None
    ex.set(drive="impact")
    assert _h(ex, "a").where() is None
    ex.drag("impact", (0.5, 0.0), (0.62, 0.3), steps=2)
    assert ex.values["impact at"] == pytest.approx(0.62)


def test_ctrl_c_during_advance_keeps_what_was_computed():
    class Interrupted(Dot):
        def play_step(self, values, dt):
            if values["x"] >= 0.3 - 1e-9:
                raise KeyboardInterrupt
            return super().play_step(values, dt)

    ex = Interrupted(display="agg")
    with pytest.raises(KeyboardInterrupt):
        ex.advance(1, seconds=1.0)                    # one picture of 20 steps, stopped at the 7th
    assert ex.values["x"] == pytest.approx(0.3) and ex.readout_values["x"] == ex.values["x"]


def test_reset_returns_plays_speed_and_loop_to_their_defaults():
    """Reset returns every control to its default (the app's words), Play's speed and loop included."""
    from planargeo.widgets import ChainExplorer

    ex = ChainExplorer(display="agg", links=2)
    ex.play_speed.value, ex.play_loop.value = 4.0, False
    ex.set(angle=-20.0)
    ex.reset_button.click()
    assert (ex.play_speed.value, ex.play_loop.value) == (1.0, True)
    assert ex.values == ex.defaults and ex.message == ""
