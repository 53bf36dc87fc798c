"""ChainExplorer against the rules of issues 22 and 23: bounded runs, one state per set of controls,
controls that do something (or say why not), options that follow n, symbols explained."""
import _thread
import contextlib
import math
import threading

import numpy as np
import pytest

from _limits import time_limit
from planargeo.errors import InputError, PlanargeoError, SizeLimitError
from planargeo.simulate.integrate import energy
from planargeo.widgets.chain import ChainExplorer


@pytest.fixture
def alarm():
    """Fail (instead of hanging) a test that runs longer than the given seconds (:func:`_limits.time_limit`)."""
    with contextlib.ExitStack() as stack:
        yield lambda seconds: stack.enter_context(time_limit(seconds))


@pytest.mark.parametrize("duration, error, words", [
    (1e6, SizeLimitError, "at most 60 s"), (1e300, SizeLimitError, "allow_long=True"),
    (math.inf, InputError, "positive finite"), (math.nan, InputError, "positive finite"),
    (-1.0, InputError, "positive finite"), (0.0, InputError, "positive finite"),
    (1e-300, InputError, "at least one frame"), ("10", InputError, "positive finite")])
def test_simulate_is_bounded_and_names_the_problem(alarm, duration, error, words):
    alarm(60)
    ex = ChainExplorer(display="agg")
    with pytest.raises(error) as info:
        ex.simulate(duration)
    assert words in str(info.value) and "duration" in str(info.value)
    assert ex.message == ""


def test_simulate_within_the_range_and_ctrl_c_keeps_what_was_computed(alarm):
    alarm(60)
    ex = ChainExplorer(display="agg", links=2)
    assert ex.simulate(2.0) == pytest.approx(2.0)
    timer = threading.Timer(1.0, _thread.interrupt_main)
    timer.start()
    try:
        reached = ex.simulate(1e6, allow_long=True)             # far too long: stopped by Ctrl-C
    finally:
        timer.cancel()
    assert 2.0 < reached < 1e6 and "Ctrl-C" in ex.message
    # what was computed is kept: the time slider reads it without integrating again
    model, q0, qd0, tau = ex.initial_state(ex.values)
    motion = ex.motion_for(model, q0, qd0, tau)
    n_chunks = len(motion.sols)
    t = min(reached, 60.0) - 0.5
    ex.set(**{"time (s)": t})
    assert len(motion.sols) == n_chunks and ex.readout_values["t (s)"] == pytest.approx(t)


def test_bad_duration_and_fps_are_refused_by_name():
    with pytest.raises(InputError, match="duration must be"):
        ChainExplorer(display="agg", duration=1e9)
    with pytest.raises(InputError, match="fps must be"):
        ChainExplorer(display="agg", fps=0)


@pytest.mark.parametrize("field, text, words", [
    ("joint speeds", "1e150, 0", "between -1\u202f000\u202f000 and 1\u202f000\u202f000"),   # digits, not 1e+06
    ("joint speeds", "1e5", "joint speeds: joint 1 takes at most 100 rad/s"),
    ("joint torques", "0, -2e4", "joint torques: joint 2 takes at most 10000 N·m"),
    ("joint values (deg / m)", "1e5", "joint values (deg / m): joint 1 takes at most 3600°")])
def test_extreme_typed_values_are_refused_in_the_package_words(field, text, words):
    ex = ChainExplorer(display="agg")
    shown = dict(ex.readout_values)
    ex.set(**{field: text})
    assert words in ex.message, ex.message
    assert "overflow" not in ex.message and "encountered" not in ex.message
    assert ex.readout_values == shown and ex.values[field] == ""
    # and the explorer keeps working (the joint values: one per joint of the 4 links)
    ex.set(**{field: "1, 2, 3, 4" if field.startswith("joint values") else "1"})
    assert ex.message == ""


def test_focus_options_follow_the_number_of_links():
    ex = ChainExplorer(display="agg")
    expect = [f"link {i}" for i in range(1, 5)] + [f"joint {i}" for i in range(1, 5)]
    assert ex.focus_options() == expect
    ex.set(links=2)
    assert ex.focus_options() == ["link 1", "link 2", "joint 1", "joint 2"]      # words, spaced
    assert list(ex.controls["focus"].options) == ["all", "link 1", "link 2", "joint 1", "joint 2"]


def test_slide_is_disabled_with_revolute_joints_and_changes_nothing_there():
    ex = ChainExplorer(display="agg")
    why = ex.disabled(ex.values)
    assert "revolute" in why["slide"] and "angle" not in why and "bend" not in why
    before = dict(ex.readout_values)
    ex.set(slide=0.7)                                       # it would change nothing: the rule holds
    assert ex.readout_values == before
    ex.set(joints="alternating")
    assert "slide" not in ex.disabled(ex.values)
    before = dict(ex.readout_values)
    ex.set(slide=0.1)
    assert ex.readout_values != before
    ex.set(joints="prismatic")
    assert {"angle", "bend"} <= set(ex.disabled(ex.values))
    ex.set(torque=0.0)
    assert "torque on" in ex.disabled(ex.values)


def _chain_xy(ex):
    """The links as drawn in the picture (base, then each joint and the link's far end)."""
    return np.asarray(next(e for e in ex.picture()["elements"] if e["id"] == "links")["parts"][0]["xy"])


def test_time_slider_shows_the_motion_without_play_and_play_gives_the_same_state():
    ex = ChainExplorer(display="agg", links=3)
    assert "time (s)" not in ex.disabled(ex.values) and "frame" not in ex.controls
    xy0 = _chain_xy(ex)
    ex.set(**{"time (s)": 0.4})                             # no Play needed
    assert ex.message == "" and not np.allclose(_chain_xy(ex), xy0)
    by_slider = dict(ex.readout_values)
    played = ChainExplorer(display="agg", links=3)
    rng = np.random.default_rng(3)
    vals = dict(played.values)
    while vals["time (s)"] < 0.4 - 1e-12:                    # uneven steps, each at most 1 / fps
        step = played.play_step(vals, min(float(rng.uniform(0.001, 0.04)), 0.4 - vals["time (s)"]))
        vals.update(step)
    played.set(**{"time (s)": vals["time (s)"]})
    assert played.readout_values["t (s)"] == pytest.approx(0.4, abs=1e-12)
    for k, v in by_slider.items():
        assert played.readout_values[k] == pytest.approx(v, rel=1e-9, abs=1e-9), k


def test_sixty_seconds_of_play_from_the_default_state(alarm):
    alarm(120)
    ex = ChainExplorer(display="agg")
    vals, t = dict(ex.values), 0.0
    while t < 60.0:
        vals.update(ex.play_step(vals, 1.0 / ex.play_fps))
        t = vals["time (s)"]
    ex.set(**{"time (s)": t})
    assert ex.message == "" and 60.0 <= ex.readout_values["t (s)"] < 60.0 + 1.0 / ex.play_fps
    ex.advance(3)
    assert ex.message == ""
    # the drift the readout states is the drift: E(t) − E(0) by an independent energy evaluation
    w = ex.state["w"]
    e = sum(energy(ex.state["model"], w.q, w.qd))
    e0 = ChainExplorer(display="agg").readout_values["total energy (J)"]
    assert ex.readout_values["energy drift (J)"] == pytest.approx(e - e0, abs=1e-12)
    assert abs(ex.readout_values["energy drift (J)"]) < 1e-4


def _same_as_fresh(ex):
    fresh = ChainExplorer(display="agg", **ex.values)
    assert fresh.readout_values.keys() == ex.readout_values.keys()
    for k, v in ex.readout_values.items():
        assert fresh.readout_values[k] == pytest.approx(v, rel=1e-12, abs=1e-12), k
    assert fresh.picture()["box"] == pytest.approx(ex.picture()["box"])     # the same view


def test_a_fresh_explorer_shows_the_same_after_drags_play_and_reset():
    ex = ChainExplorer(display="agg")
    ex.drag("base", (0.0, 0.0), (2.5, 1.5), steps=6)          # the mouse's path: press, moves, release
    assert ex.message == ""
    _same_as_fresh(ex)
    x0, x1 = ex.picture()["box"][:2]
    ends = ex._ends(ex.state["w"])
    assert x0 < ends[:, 0].min() and ends[:, 0].max() < x1     # the whole chain in view
    ex.advance(7)
    _same_as_fresh(ex)
    h = [h for h in ex.handles() if h.name == "link 2 end"][0]
    x, y = h.where()
    ex.drag("link 2 end", (x, y), (x, y + 0.6), steps=3)
    _same_as_fresh(ex)
    ex.set(**{"time (s)": 13.5})
    assert ex.values["time (s)"] == 13.5
    _same_as_fresh(ex)
    ex.reset()
    _same_as_fresh(ex)


def test_time_given_with_the_initial_state_is_kept():
    ex = ChainExplorer(display="agg", links=2, **{"time (s)": 1.5})
    assert ex.values["time (s)"] == 1.5 and ex.readout_values["t (s)"] == 1.5


def test_every_symbol_and_readout_row_is_explained_with_a_unit():
    ex = ChainExplorer(display="agg", links=3, torque=1.0,
                       **{k: True for k in ("acceleration poles", "bias terms", "T/U split",
                                            "articulated inertias")})
    ex.advance(2)
    words = ex.explain()
    for name in ex.readout_values:
        assert name in words or name.startswith("q̈") and "q̈ᵢ" in words, name
        unit = ex.units.get(name)
        assert unit, name
    for sym in ("vᵢ", "aᵢ", "κᵢ", "pᵢ", "fᵢ", "TQᵢ", "Rμᵢ", "sψᵢ", "Uγᵢ", "Aᵢ"):
        assert "eq. " in words[sym], sym
    assert not any("qdd" in k or "_" in k for k in ex.readout_values)


def test_compute_raises_only_package_errors_for_hard_input():
    ex = ChainExplorer(display="agg")
    for text in ("100, -100, 100, -100", "1e6"):
        ex.set(**{"joint speeds": text})
        assert "cannot compute" not in ex.message and "internal error" not in ex.message
    with pytest.raises(PlanargeoError):
        ex.initial_state(dict(ex.values, **{"joint speeds": "1e6"}))


LIST_Q = "joint values (deg / m)"


def _dragged_to_big_angles() -> ChainExplorer:
    """The review's state: link 4's end dragged, the joint values box holds four angles in degrees."""
    ex = ChainExplorer(display="agg")
    ex.drag("link 4 end", ex.handle_position("link 4 end"), (3.0, -1.0))
    typed = [float(t) for t in ex.values[LIST_Q].split(",")]
    assert len(typed) == 4 and typed[0] == -30.0 and abs(typed[3]) > 1.0       # degrees, beyond a slide
    return ex


@pytest.mark.parametrize("joints", ["prismatic", "alternating"])
def test_a_new_joint_type_starts_from_its_own_state_with_a_note(joints):
    ex = _dragged_to_big_angles()
    ex.set(**{"joint speeds": "1, -2", "joint torques": "0, 5"})
    ex.set(joints=joints)
    assert ex.values["joints"] == joints                                 # taken, not snapped back
    assert ex.values[LIST_Q] == ex.values["joint speeds"] == ex.values["joint torques"] == ""
    assert "refused" not in ex.message and "cleared" in ex.message and joints in ex.message
    assert "⚠" not in ex.message_box.value and "b00020" not in ex.message_box.value   # a note, not an error
    # the state is the type's default one: a fresh explorer with that joint type shows the same
    fresh = ChainExplorer(display="agg", joints=joints)
    assert ex.readout_values == pytest.approx(fresh.readout_values)
    ex.set(**{"time (s)": 0.25})                                         # the note was for that change
    assert ex.message == ""


def test_the_same_joint_type_keeps_the_typed_values():
    ex = _dragged_to_big_angles()
    typed = ex.values[LIST_Q]
    ex.set(joints="revolute", gravity=False)
    assert ex.values[LIST_Q] == typed and ex.message == ""


@pytest.mark.parametrize("text, got", [("10, 20, 30, 40, 50", "got 5 values"), ("10, 20", "got 2 values"),
                                       ("10", "got 1 value")])
def test_joint_values_of_the_wrong_count_are_refused_saying_how_many(text, got):
    ex = ChainExplorer(display="agg")                                    # 4 links
    shown = dict(ex.readout_values)
    ex.set(**{LIST_Q: text})
    assert "needs 4 values, one per joint" in ex.message and got in ex.message, ex.message
    assert ex.values[LIST_Q] == "" and ex.readout_values == shown
    ex.set(**{LIST_Q: "10, 20, 30, 40"})
    assert ex.message == "" and ex.values[LIST_Q] == "10, 20, 30, 40"


def test_more_speeds_than_joints_are_refused():
    ex = ChainExplorer(display="agg", links=3)
    ex.set(**{"joint speeds": "1, 2, 3, 4"})
    assert "at most 3 values" in ex.message and ex.values["joint speeds"] == ""


def test_a_links_change_keeps_one_joint_value_per_joint():
    ex = ChainExplorer(display="agg")
    ex.set(**{LIST_Q: "10, 20, 30, 40", "joint speeds": "1, 2, 3, 4"})
    ex.set(links=6)                      # the new joints take the bend slider's angle (20°)
    assert ex.message == "" and ex.values[LIST_Q] == "10, 20, 30, 40, 20, 20"
    assert ex.values["joint speeds"] == "1, 2, 3, 4"     # speeds: the joints not typed take the slider's
    ex.set(links=2)
    assert ex.message == "" and ex.values[LIST_Q] == "10, 20" and ex.values["joint speeds"] == "1, 2"
    # the state is the one the boxes say: a fresh explorer so set shows the same
    fresh = ChainExplorer(display="agg", links=2, **{LIST_Q: "10, 20", "joint speeds": "1, 2"})
    assert ex.readout_values == pytest.approx(fresh.readout_values)


def test_a_pole_at_the_base_is_described_at_0_0_not_minus_0():
    """v₁'s pole is the base joint (0, 0): its x is −v_y/ω = −0.0 in floating point, which read "(-0, 0) m"."""
    ex = ChainExplorer(display="agg", **{"velocity poles": True})
    v1 = next(e for e in ex.picture()["elements"] if e["id"] == "v1")
    assert "at (0, 0) m" in v1["desc"] and "-0" not in v1["desc"], v1["desc"]
