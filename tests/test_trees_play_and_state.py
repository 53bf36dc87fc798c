"""Trees explorer and scene (issues 22 and 23): Play runs a minute from the default, singular poses of the
equal-link loops are stepped over with energy and loops kept, one state per set of controls, Reset after a
drag, Home/End of the angle sliders, every symbol explained."""
import math

import numpy as np
import pytest

from planargeo.scenes.trees import constrained_tree, tree_advance
from planargeo.simulate.integrate import energy
from planargeo.simulate.loops import closure_jacobian, closure_residual
from planargeo.widgets.trees import TreeExplorer


def test_the_fig_9_2_state_under_gravity_passes_the_flat_rhombus():
    """From the Fig 9.2 state (g = 9.81) the loop 5-6-8-9 lies flat at t ≈ 0.88 s, where the solver refuses
    the pose; the motion is carried through it with energy and loops kept."""
    ct = constrained_tree()
    m, q0, qd0 = ct.model, np.array(ct.state["q"]), np.array(ct.state["qd"])
    out = tree_advance(m, q0, qd0, 1.0)
    assert out["crossings"] >= 1
    assert any(e["kind"] == "singular pose passed" and 0.8 < e["t"] < 0.95 for e in out["events"])
    E0, E1 = sum(energy(m, q0, qd0)), sum(energy(m, out["q"], out["qd"]))
    assert abs(E1 - E0) / abs(E0) < 1e-5
    assert np.abs(closure_residual(m, out["q"])).max() < 1e-9
    assert np.abs(closure_jacobian(m, out["q"]) @ out["qd"]).max() < 1e-8
    with pytest.raises(Exception, match="singular"):
        tree_advance(m, q0, qd0, 1.0, cross=False)


@pytest.mark.slow
def test_play_runs_a_minute_from_the_default_with_the_drifts_it_states():
    ex = TreeExplorer(display="agg")
    E0 = sum(energy(ex.state["model"], ex.state["q"], ex.state["qd"]))
    ex.advance(60, seconds=60.0)
    r = ex.readout_values
    assert ex.message == "" and float(ex.values["t (s)"]) == pytest.approx(60.0)
    m, q, qd = ex.state["model"], ex.state["q"], ex.state["qd"]
    E = sum(energy(m, q, qd))
    assert r["energy drift ΔE/E₀"] == pytest.approx((E - E0) / E0, rel=1e-9, abs=1e-15)
    assert abs(r["energy drift ΔE/E₀"]) < 1e-4
    assert np.abs(closure_residual(m, q)).max() <= max(r["closure drift |φ|"], 1e-10)
    assert r["closure drift |φ|"] < 1e-9
    assert not r["singular poses"].startswith("none")         # the default motion passes flat loops


def test_one_state_per_set_of_controls_issue_23_item_6():
    t = TreeExplorer(display="agg")
    t.set(loops="open (Fig 9.1)")
    t.set(**{"body 2 angle (deg)": -9.2})
    t.set(loops="closed (Fig 9.2)")
    t.set(**{"body 2 angle (deg)": 360.0})
    fresh = TreeExplorer(display="agg", **t.values)
    assert t.message == "" and fresh.message == ""
    assert fresh.readout_values == t.readout_values
    np.testing.assert_array_equal(fresh.state["q"], t.state["q"])


def test_reset_after_a_drag_returns_to_the_default_state():
    ex = TreeExplorer(display="agg")
    default = dict(ex.readout_values)
    base = ex.state["tips"][0]
    ex.drag("tip of body 2", tuple(ex.state["tips"][1]), (base[0] + 0.9, base[1] - 0.2), steps=6)
    assert ex.message == "" and ex.readout_values != default
    ex.reset()
    assert ex.message == ""
    assert ex.values == ex.defaults and ex.readout_values == default


@pytest.mark.parametrize("name", ["body 1 angle (deg)", "body 2 angle (deg)"])
def test_home_and_end_of_the_angle_sliders_give_a_state(name):
    ex = TreeExplorer(display="agg")
    for value in (ex.controls[name].min, ex.controls[name].max):
        ex.set(**{name: value})
        assert ex.message == "", (name, value, ex.message)
        assert ex.values[name] == value
        assert np.abs(closure_residual(ex.state["model"], ex.state["q"])).max() < 1e-9


def test_every_readout_row_and_label_is_explained_without_code_names():
    ex = TreeExplorer(display="agg", focus="F₂")
    ex.advance(2)
    meaning = ex.explain()
    for k in ex.readout_values:
        assert k in meaning, k
        assert "_" not in k and "[" not in k and "qdd" not in k
    for sym in ex.focus_options():
        assert sym in meaning
    ex.set(loops="open (Fig 9.1)")
    assert "F₁" not in ex.focus_options() and ex.values["focus"] == "all"
    assert set(ex.disabled(ex.values)) == {"t (s)"}


def test_the_time_field_is_read_only_bounded_and_exact():
    from planargeo.widgets.slider_crank import SliderCrankExplorer

    for ex in (TreeExplorer(display="agg"), SliderCrankExplorer(display="agg")):
        assert ex.controls["t (s)"].disabled and "Play" in ex.disabled(ex.values)["t (s)"]
        ex.advance(3)
        t = 3 * ex.play_dt
        assert float(ex.values["t (s)"]) == pytest.approx(t, abs=1e-9) and ex.readout_values["t"] == float(
            ex.values["t (s)"])
        shown = dict(ex.values)
        ex.set(**{"t (s)": "1e6"})                                  # beyond the end: refused by name
        assert "time t" in ex.message and ex.values == shown
        ex.set(**{"t (s)": "soon"})
        assert "time t" in ex.message and ex.values == shown


@pytest.mark.parametrize("frames", [1, 7])
def test_the_page_shows_play_time_to_the_millisecond_the_state_keeps_the_exact_time(frames):
    from planargeo.widgets.slider_crank import SliderCrankExplorer

    for cls in (TreeExplorer, SliderCrankExplorer):
        ex = cls(display="agg")
        ex.advance(frames)
        exact = frames * ex.play_dt
        on_page = ex.controls["t (s)"].get_state("value")["value"]     # what the browser is sent
        assert on_page == f"{exact:.3f}", (cls.__name__, on_page)
        assert float(ex.values["t (s)"]) == pytest.approx(exact, abs=1e-9) == ex.readout_values["t"]
        fresh = cls(display="agg", **ex.values)                       # the same state from the same values
        assert fresh.message == "" and fresh.readout_values == ex.readout_values
        np.testing.assert_array_equal(fresh.state["q"], ex.state["q"])


@pytest.mark.parametrize("seconds", [None, 0.033])
def test_play_ahead_between_frames_leaves_every_frame_bit_identical(seconds):
    # Play's work between frames (the checkpoints the next frames start from) changes no state: the
    # state at a time depends on the time alone, whoever integrated the checkpoints before it
    plain, ahead = TreeExplorer(display="agg"), TreeExplorer(display="agg")
    for _ in range(6):
        while ahead.play_ahead(ahead.shown_values, 1.0):
            pass
        assert ahead.play_ahead(ahead.shown_values, 1.0) is False          # nothing left to do
        for ex in (plain, ahead):
            ex.advance(1, seconds=seconds)             # a frame of Play's step, or of a page's tick
        assert ahead.values == plain.values and ahead.readout_values == plain.readout_values
        np.testing.assert_array_equal(ahead.state["q"], plain.state["q"])
        np.testing.assert_array_equal(ahead.state["qd"], plain.state["qd"])
