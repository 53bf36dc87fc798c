"""ChainExplorer as an instrument (issue 13): drag link ends and the base, Play, focus, labels.

Every number compared here comes from an independent source: the dragged joint
angle from ``atan2`` of the dragged point by hand, the accelerations of a Play
frame from Pinocchio's ``aba`` (``benchmarks/bench.pinocchio_forward``), the
energy over Play frames from its conservation, the labels from their boxes in
the picture (tests/_picture_checks.py: no two overlap).
"""
import math

import numpy as np
import pytest

from _picture_checks import elements, label_boxes, overlapping_labels
from planargeo.widgets.chain import OVERLAYS, ChainExplorer

ALL = {k: True for k in OVERLAYS}


def _drawn(ex) -> np.ndarray:
    """The links as drawn (base, then each joint and the link's far end), from the picture."""
    return np.asarray(elements(ex.picture())["links"]["parts"][0]["xy"], float)


def _abs_angles(ex):
    """Absolute link directions (rad): from each joint to the link's end (the state's poses)."""
    w = ex.state["w"]
    ends = ex._ends(w)
    return [math.atan2(ends[i, 1] - w.pose[i, 1], ends[i, 0] - w.pose[i, 0]) for i in range(len(ends))]


def _joints(ex):
    """Joint positions (the state's), checked against the drawn links (to the picture's rounding)."""
    joints = np.asarray(ex.state["w"].pose[:, :2], float)
    assert _drawn(ex)[1::2] == pytest.approx(joints, abs=2e-4)
    return joints


def legible(ex) -> list:
    """Pairs of labels of the shown picture that overlap (none, for a legible picture).

    A refusal written over the picture (the base's "figure message") is a deliberate box on
    top of everything, as it was on the figure: it is not a label.
    """
    return [pair for pair in overlapping_labels(ex.picture())
            if "figure message" not in (pair[0][0], pair[1][0])]


def shown_labels(ex) -> list[str]:
    """The label texts shown in the picture."""
    return [t for _, t, _ in label_boxes(ex.picture())]


def _wrap(a):
    return math.atan2(math.sin(a), math.cos(a))


@pytest.mark.parametrize("link", [1, 3, 5])
def test_dragging_a_link_end_sets_its_joint_angle_by_atan2(link):
    ex = ChainExplorer(display="agg", links=5, speed=0.0)
    before = ex.state["w"].q.copy()
    joint = _joints(ex)[link - 1]
    start = ex.handles()[link].where()
    target = joint + 0.7 * np.array([math.cos(2.0), math.sin(2.0)])     # direction 2 rad, any length
    ex.drag(f"link {link} end", start, target, steps=6)
    assert ex.message == ""
    parent = 0.0 if link == 1 else _abs_angles(ex)[link - 2]
    want = _wrap(math.atan2(target[1] - joint[1], target[0] - joint[0]) - parent)
    q = ex.state["w"].q
    # the joint angle as a student types it: to 0.01° (joint 1: the angle slider, exact)
    assert q[link - 1] == pytest.approx(math.radians(round(math.degrees(want), 2)) if link > 1 else want,
                                        abs=1e-12)
    tol = math.radians(0.005)
    assert _abs_angles(ex)[link - 1] == pytest.approx(2.0, abs=tol)     # the link points at the mouse
    keep = [i for i in range(5) if i != link - 1]
    assert q[keep] == pytest.approx(before[keep], abs=1e-9)              # the other joints kept
    # the handle is now at the link's end, on the ray to the mouse
    end = np.array(ex.handles()[link].where())
    assert end == pytest.approx(joint + [math.cos(2.0), math.sin(2.0)], abs=tol)
    assert legible(ex) == []


def test_drag_of_link_1_moves_the_angle_slider_and_sliders_move_dragged_joints():
    ex = ChainExplorer(display="agg", links=3)
    ex.drag("link 1 end", ex.handles()[1].where(), (0.0, 1.0), steps=3)
    assert ex.values["angle"] == pytest.approx(90.0) and ex.values["joint values (deg / m)"] == ""
    ex.drag("link 3 end", ex.handles()[3].where(), (3.0, 3.0), steps=4)
    text = ex.values["joint values (deg / m)"]
    assert text and ex.message == ""
    # as a student would type them: at most two decimals (the dragged joint was 49.13529911)
    assert all(len(t.strip().partition(".")[2]) <= 2 for t in text.split(",")), text
    fresh = ChainExplorer(display="agg", **ex.values)        # the state the field says, exactly
    assert fresh.state["w"].q == pytest.approx(ex.state["w"].q, abs=0.0)
    q3 = ex.state["w"].q[2]
    ex.controls["angle"].value = 45.0              # the slider still moves joint 1; joint 3 is kept
    assert ex.state["w"].q[0] == pytest.approx(math.radians(45.0))
    assert ex.state["w"].q[2] == pytest.approx(q3)
    assert ex.values["joint values (deg / m)"].split(",")[0] == "45"
    ex.controls["bend"].value = 10.0               # the common bend returns every joint to it
    assert ex.values["joint values (deg / m)"] == ""
    assert ex.state["w"].q[1:] == pytest.approx([math.radians(10.0)] * 2)


def test_a_drag_onto_the_joint_itself_is_refused_with_the_reason():
    ex = ChainExplorer(display="agg", links=3)
    shown = dict(ex.readout_values)
    joint = tuple(_joints(ex)[1])
    ex.drag("link 2 end", ex.handles()[2].where(), joint, steps=1)
    assert "cannot be dragged onto joint 2" in ex.message
    assert ex.readout_values == shown and ex.values == ex.shown_values
    assert legible(ex) == []


def test_prismatic_drag_sets_the_slide_and_refuses_beyond_its_range():
    ex = ChainExplorer(display="agg", links=2, joints="prismatic", slide=0.2)
    # all joints slide: every link lies along +x; joint 2 slides along link 1
    e = np.array([1.0, 0.0])
    end = np.array(ex.handles()[2].where())
    ex.drag("link 2 end", end, end + 0.5 * e, steps=5)
    assert ex.message == "" and ex.state["w"].q[1] == pytest.approx(0.7, abs=1e-9)
    ex.drag("link 2 end", end + 0.5 * e, end + 2.0 * e, steps=1)
    assert "joint 2 slides between -0.5 and 1 m" in ex.message
    assert ex.state["w"].q[1] == pytest.approx(0.7, abs=1e-9)


def test_dragging_the_base_translates_the_chain_and_not_its_dynamics():
    ex = ChainExplorer(display="agg", links=4, speed=0.7, torque=1.0)
    qdd = ex.state["w"].qdd.copy()
    joints = _joints(ex)
    ex.drag("base", (0.0, 0.0), (1.5, -0.5), steps=5)
    assert ex.message == ""
    assert (ex.values["base x (m)"], ex.values["base y (m)"]) == pytest.approx((1.5, -0.5))
    assert _joints(ex) == pytest.approx(joints + [1.5, -0.5], abs=1e-12)
    assert ex.state["w"].qdd == pytest.approx(qdd, rel=1e-12, abs=1e-12)    # uniform gravity
    ex.drag("base", (1.5, -0.5), (9.0, 0.0), steps=1)                 # beyond the slider: its end
    assert ex.message == "" and ex.values["base x (m)"] == 3.0 and ex.values["base y (m)"] == 0.0


def test_play_conserves_energy_and_matches_pinocchio():
    pytest.importorskip("pinocchio")
    from bench import pinocchio_forward

    ex = ChainExplorer(display="agg", links=4, speed=1.0, torque=0.0, fps=25, **ALL)
    e0 = ex.readout_values["total energy (J)"]
    xy0 = _drawn(ex)
    es = []
    for k in range(1, 13):
        ex.advance(1)
        assert ex.message == "" and ex.values["time (s)"] == pytest.approx(k / 25)
        assert ex.readout_values["t (s)"] == pytest.approx(k / 25)         # 1× speed: 1 / fps a frame
        es.append(ex.readout_values["total energy (J)"])
        assert ex.readout_values["energy drift (J)"] == pytest.approx(es[-1] - e0)  # no joint forces
    assert not np.allclose(_drawn(ex), xy0)                                  # it moved
    assert np.abs(np.array(es) - e0).max() <= 1e-6 * max(1.0, abs(e0))
    w = ex.state["w"]
    ref = pinocchio_forward(ex.state["model"], w.q, w.qd, w.tau)
    assert w.qdd == pytest.approx(ref, rel=1e-9, abs=1e-9)
    assert ex.readout_values["q̈₁"] == pytest.approx(ref[0], rel=1e-9, abs=1e-9)
    # the overlays follow the time: the drawn velocity pole is the shown state's
    v1 = elements(ex.picture())["v1"]
    m = next((p for p in v1["parts"] if p["p"] == "mark"), None)
    if m is not None:
        assert [m["x"], m["y"]] == pytest.approx([-w.v[0][1] / w.v[0][2], w.v[0][0] / w.v[0][2]], abs=2e-4)
    assert f"rate {w.v[0][2]:.3g} rad/s" in v1["desc"]
    assert legible(ex) == []


def test_play_stops_at_the_end_and_restarts_on_a_new_state():
    ex = ChainExplorer(display="agg", links=2, duration=0.2, fps=20)
    ex.advance(10)                                    # 4 frames, then play_step says None
    assert ex.values["time (s)"] == pytest.approx(0.2) and ex.n_updates == 5
    ex.controls["time (s)"].value = 0.05              # scrub back: the same state as Play's frame 1
    q1 = ex.state["w"].q.copy()
    ex.advance(1)
    ex.controls["time (s)"].value = 0.05
    assert ex.state["w"].q == pytest.approx(q1, abs=0.0)
    ex.play_speed.value = 0.25                        # slow motion: steps a quarter as long
    ex.controls["time (s)"].value = 0.2
    ex.controls["speed"].value = 0.5                  # a new initial state: t = 0 again
    assert ex.values["time (s)"] == 0.0
    ex.advance(2)
    assert ex.readout_values["t (s)"] == pytest.approx(2 * 0.25 / 20)


def test_focus_options_fade_and_label():
    ex = ChainExplorer(display="agg", links=10, torque=2.0, **ALL)
    assert ex.focus_options()[:2] == ["link 1", "link 2"] and "joint 10" in ex.focus_options()
    full = ex.picture()["box"]
    assert legible(ex) == []
    ex.set(focus="joint 4")
    assert ex.message == ""
    shown = shown_labels(ex)
    for sym in ("f₄", "TQ₄", "Rμ₄"):
        assert sym in shown
    assert not any(s.endswith("₃") or s.endswith("₅") for s in shown)         # others unlabelled
    e = elements(ex.picture())
    assert e["f4"].get("opacity", 1.0) == 1.0 and e["f3"]["opacity"] < 0.5    # the rest faded
    assert ex.picture()["box"] == pytest.approx(full)              # no zoom: the whole chain stays in view
    assert legible(ex) == []
    ex.set(focus="link 7")
    assert "v₇" in shown_labels(ex) and "A₇" in shown_labels(ex)
    assert legible(ex) == []
    ex.set(focus="all")
    assert elements(ex.picture())["f3"].get("opacity", 1.0) == 1.0
    assert ex.picture()["box"] == pytest.approx(full)


@pytest.mark.parametrize("links", [1, 4, 10, 20])
def test_labels_legible_with_all_overlays(links):
    """Every label placed clear of the others and inside the axes, at >= 11 px."""
    ex = ChainExplorer(display="agg", links=links, torque=1.0, **ALL)
    assert legible(ex) == []
    assert len(shown_labels(ex)) >= min(links, 10)
    for k in (5, -45.0):
        ex.controls["angle"].value = float(k)
        assert legible(ex) == []


def test_units_and_round_off():
    ex = ChainExplorer(display="agg", links=1, speed=0.0, angle=-90.0, gravity=False)
    assert ex.units["kinetic energy (J)"] == "J" and ex.units["|base force| (N)"] == "N"
    assert ex.readout_strings["kinetic energy (J)"] == "0 J"
    assert ex.readout_strings["q̈₁"] == "0 rad/s²"
    ex.set(joints="alternating", links=2)
    assert ex.readout_strings["q̈₂"].endswith(" m/s²") and ex.readout_strings["q̈₁"].endswith(" rad/s²")


@pytest.mark.parametrize("links", [1, 2, 4, 10, 20])
def test_bias_terms_are_labelled_and_legible(links):
    ex = ChainExplorer(display="agg", links=links, speed=1.5, **{"bias terms": True})
    assert any(s[:1] == "p" and s[1:2] in tuple("₀₁₂₃₄₅₆₇₈₉") for s in shown_labels(ex))
    assert legible(ex) == []


def test_play_energy_drift_counts_the_work_of_the_joint_forces():
    """With constant joint torques the energy changes by their work τ·(q - q₀); the drift stays ~0."""
    ex = ChainExplorer(display="agg", links=3, speed=0.5, torque=2.0, fps=25)
    e0 = ex.readout_values["total energy (J)"]
    q0 = ex.state["w"].q.copy()
    ex.advance(25)
    r = ex.readout_values
    work = 2.0 * float(np.sum(ex.state["w"].q - q0))                 # by hand: τ = 2 on every joint
    assert abs(work) > 1.0                                           # the torques did work
    assert r["work of the joint forces (J)"] == pytest.approx(work, rel=1e-12)
    assert r["total energy (J)"] - e0 == pytest.approx(work, abs=1e-6 * max(1.0, abs(e0)))
    assert abs(r["energy drift (J)"]) <= 1e-6 * max(1.0, abs(e0))
