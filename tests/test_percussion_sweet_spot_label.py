"""PercussionExplorer, impact drive: the "sweet spot" label sits by its diamond (review: it sat ~45 px
off, on the other side of the axis line, next to c).

Measured from the picture data alone (:mod:`_picture_checks`): the label's box (0.6 font sizes per
character, 1.25 high) is crossed by no stroke and meets no other label, lies wholly on the diamond's
side of the axis of percussion (the blow's line x = impact at, thesis 5.56), and is near the diamond.
"""
import numpy as np
import pytest

from planargeo.widgets.percussion import PercussionExplorer

from _picture_checks import crossed_labels, label_boxes, to_px

STATES = [{}, {"impact at": 0.9}, {"impact at": 0.0}, {"impact at": 1.2}, {"shape": "uniform rod"},
          {"shape": "disc"}, {"shape": "L-shape"}, {"mass (kg)": 3.0, "impact at": 0.3}]


@pytest.mark.parametrize("values", STATES, ids=str)
def test_the_sweet_spot_label_is_by_its_diamond_on_its_side_of_the_axis(values):
    ex = PercussionExplorer(display="agg", drive="impact", **values)
    pic = ex.picture()
    spot = next(e for e in pic["elements"] if e["id"] == "spot")
    mark = next(p for p in spot["parts"] if p["p"] == "mark")
    mx, my = to_px(pic, mark["x"], mark["y"])
    boxes = [b for eid, text, b in label_boxes(pic) if eid == "spot"]
    assert len(boxes) == 1                                    # shown, once
    x0, y0, x1, y1 = boxes[0]
    # the grip's sweet spot (5.67): ρ²/|c| beyond c, along the grip-c line
    r = ex.readout_values
    c, rho = np.array(r["centre of mass"]), r["radius of gyration ρ"]
    assert (mark["x"], mark["y"]) == pytest.approx(tuple(c + c / np.hypot(*c) * rho ** 2 / np.hypot(*c)), abs=1e-4)
    ax, _ = to_px(pic, float(ex.values["impact at"]), 0.0)   # the axis: the vertical x = impact at
    assert x1 < ax if mx < ax else x0 > ax                   # wholly on the diamond's side
    near = np.hypot(np.clip(mx, x0, x1) - mx, np.clip(my, y0, y1) - my)
    assert near <= 40.0                                       # the review's was ~45 px, across the axis
    assert [h for h in crossed_labels(pic) if h[0] == "spot"] == []
