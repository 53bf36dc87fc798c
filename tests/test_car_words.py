"""The car explorer's sliders say which speed and where the heading starts (a student's review).

"speed V" is the speed of the rear axle's middle (G moved at 4.07 m/s when V read 4); the heading's
0° points up the page while blow and force angles elsewhere start from +x.  The words are checked
against the explorer's own geometry: its handles (G, the ICR, the drive arrow's tip).
"""
from __future__ import annotations

import math

import numpy as np
import pytest

from planargeo.widgets import CarExplorer

SPEED, HEADING, RADIUS = "speed (m/s)", "heading (deg)", "turn radius (m)"


def where(ex, name):
    return np.array(next(h for h in ex.handles() if h.name == name).where(), dtype=float)


def test_the_speed_slider_names_the_rear_axle_and_g_moves_faster():
    ex = CarExplorer()
    w = ex.controls[SPEED]
    assert "rear-axle" in w.description and "V" in w.description, w.description
    assert "rear axle" in w.tooltip and "faster" in w.tooltip, w.tooltip
    # the car turns about the ICR at ω = V / d; G is farther from it than the rear axle's middle (d)
    V, d = ex.values[SPEED], ex.values[RADIUS]
    g_speed = V / d * float(np.hypot(*(where(ex, "centre of gravity") - where(ex, "ICR"))))
    assert g_speed == pytest.approx(4.07, abs=0.01) and g_speed > V


@pytest.mark.parametrize("heading, forward", [(0.0, (0.0, 1.0)), (90.0, (-1.0, 0.0)), (180.0, (0.0, -1.0))])
def test_the_heading_tip_says_where_zero_points_and_it_does(heading, forward):
    ex = CarExplorer(**{HEADING: heading})
    tip = ex.controls[HEADING].tooltip
    assert "0° the car points up" in tip and "counter-clockwise" in tip and "90° to the left" in tip, tip
    ahead = where(ex, "drive") - where(ex, "centre of gravity")      # the drive arrow points forward
    assert np.allclose(ahead / np.hypot(*ahead), forward, atol=1e-9)
