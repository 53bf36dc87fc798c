"""SliderCrankExplorer, a student's review: the ψ₀ slider read −180 while the readout said ψ = 180 (one
convention now: (−180°, 180°]); the labels "a₂" and "3" touched at the piston's top; φ's label sat ~70 px
above the wrist pin with nothing to say what it measured.  Now ψ, θ, φ are arcs at their joints, from the
direction each is measured from, their symbols by the arcs.

The arcs are checked against the readout's angles and against the links drawn (their ends), not against
the code that draws them (the picture holds coordinates to 1e-4 m); the labels' boxes with the checks the other picture tests use."""
import math

import numpy as np
import pytest

from _picture_checks import elements, label_boxes, overlapping_labels, to_px
from planargeo.widgets.slider_crank import SliderCrankExplorer

ANGLE = "crank angle (deg)"


@pytest.mark.parametrize("set_to", [-180.0, 180.0])
def test_the_crank_angle_reads_the_same_on_the_slider_in_the_readout_and_on_the_picture(set_to):
    for ex in (SliderCrankExplorer(display="agg", **{ANGLE: set_to}), SliderCrankExplorer(display="agg")):
        ex.set(**{ANGLE: set_to})
        assert ex.message == ""
        assert ex.controls[ANGLE].value == ex.values[ANGLE] == set_to
        assert ex.readout_values["crank angle ψ"] == set_to
        arc = next(np.asarray(p["xy"], float) for e in ex.picture()["elements"] if e["id"] == "angle ψ"
                   for p in e["parts"] if p["p"] == "path")
        assert sum(_turn(p, q) for p, q in zip(arc[:-1], arc[1:])) == pytest.approx(set_to, abs=0.05)
    # once Play has turned the crank, ψ reads in (−180°, 180°]
    ex = SliderCrankExplorer(display="agg", **{ANGLE: -180.0, "crank speed": -20.0})
    ex.advance(2)
    assert -180.0 < ex.readout_values["crank angle ψ"] <= 180.0 and ex.readout_values["crank angle ψ"] > 150.0


def _turn(a, b) -> float:
    """The signed angle (degrees, in (−180, 180]) from direction ``a`` to direction ``b``."""
    t = math.degrees(math.atan2(a[0] * b[1] - a[1] * b[0], a[0] * b[0] + a[1] * b[1]))
    return 180.0 if t == -180.0 else t


@pytest.mark.parametrize("psi0", [23.0, 120.0, -100.0, 179.0])
def test_each_joint_angle_is_an_arc_at_its_joint_spanning_the_readouts_angle(psi0):
    ex = SliderCrankExplorer(display="agg", **{ANGLE: psi0})
    pic, r = ex.picture(), ex.readout_values
    els = elements(pic)

    def path(eid):
        (p,) = [p for p in els[eid]["parts"] if p["p"] == "path"]
        return np.asarray(p["xy"], float)

    pivot, pin = path("crank")
    pin2, wrist = path("rod")
    assert np.allclose(pin, pin2)
    up = np.array([0.0, 1.0])                              # the piston stays upright
    links = {"ψ": (pivot, np.array([1.0, 0.0]), pin - pivot),           # from the x axis to the crank
             "θ": (pin, pin - pivot, wrist - pin),                      # from the crank produced to the rod
             "φ": (wrist, wrist - pin, up)}                             # from the rod produced to the piston
    readout = {"ψ": r["crank angle ψ"], "θ": r["rod joint angle θ"], "φ": r["wrist joint angle φ"]}
    for sym, (centre, a, b) in links.items():
        assert _turn(a, b) == pytest.approx(readout[sym], abs=0.01)      # the readout's angle, from the links
        arc = path(f"angle {sym}")
        radii = np.hypot(*(arc - centre).T)
        assert np.ptp(radii) < 5e-4 and 0.3 < radii[0] < 1.5            # a circle's arc about the joint
        ends = arc[[0, -1]] - centre
        # it turns through the angle the readout says, from one side of the angle to the other (its
        # sides are the links or their productions: either sense of a side, the arc's ends on them)
        steps = [_turn(p, q) for p, q in zip(arc[:-1] - centre, arc[1:] - centre)]
        assert sum(steps) == pytest.approx(readout[sym], abs=0.05)
        for end, side in zip(ends, (a, b)):
            assert abs(_turn(side, end)) < 0.05 or abs(abs(_turn(side, end)) - 180.0) < 0.05
        # the symbol by its arc: the label within 30 px of the arc's middle
        (lab,) = [box for eid, text, box in label_boxes(pic) if eid == f"angle {sym}"]
        mx, my = to_px(pic, *arc[len(arc) // 2])
        cx, cy = (lab[0] + lab[2]) / 2, (lab[1] + lab[3]) / 2
        assert math.hypot(cx - mx, cy - my) < 30.0, (sym, (cx, cy), (mx, my))
    assert overlapping_labels(pic) == []


@pytest.mark.parametrize("values", [{}, {"velocity poles": True, "acceleration poles": True},
                                    {ANGLE: 120.0, "velocity poles": True, "acceleration poles": True}])
def test_the_piston_label_keeps_clear_of_the_labels_about_it(values):
    """The review's case: "a₂" (the rod's acceleration pole, near the piston's top) and "3" touched."""
    pic = SliderCrankExplorer(display="agg", **values).picture()
    boxes = label_boxes(pic)
    (three,) = [b for eid, t, b in boxes if eid == "piston"]
    for eid, text, b in boxes:
        if eid == "piston":
            continue
        gap = max(b[0] - three[2], three[0] - b[2], b[1] - three[3], three[1] - b[3])
        assert gap >= 2.0, (text, gap)
    assert overlapping_labels(pic) == []
