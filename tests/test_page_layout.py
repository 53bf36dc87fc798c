"""Layout of every explorer's picture (issue 21, "Layout"): the mechanism is big enough to see.

In the default state the mechanism (:meth:`Explorer.mechanism_points`) lies in the
picture's view, and its extent fills at least a third of the view's width or of its
height.  The view is read from the picture the page and the exports draw
(``ex.picture()["box"]``), so the rule holds for what a student sees.

Explorers that do not meet it yet are listed in :data:`NOT_YET` with their numbers;
they are strict xfails, so the test flips (and the entry must go) when they are fixed.
"""
from __future__ import annotations

import numpy as np
import pytest

import planargeo.widgets as pw

#: explorer -> why it fails today (fill = extent of the mechanism / extent of the view)
NOT_YET: dict[str, str] = {
}

FILL = 1.0 / 3.0


def _fill(ex) -> tuple[np.ndarray, list[float], float, float]:
    pic = ex.picture()
    x0, x1, y0, y1 = pic["box"]
    pts = np.asarray(ex.mechanism_points(), dtype=float).reshape(-1, 2)
    fw = float(np.ptp(pts[:, 0]) / (x1 - x0)) if len(pts) else 0.0
    fh = float(np.ptp(pts[:, 1]) / (y1 - y0)) if len(pts) else 0.0
    return pts, [x0, x1, y0, y1], fw, fh


@pytest.mark.parametrize("name", [
    pytest.param(n, marks=pytest.mark.xfail(strict=True, reason=NOT_YET[n])) if n in NOT_YET else n
    for n in pw.EXPLORERS])
def test_mechanism_fills_a_third_of_the_default_view(name):
    ex = getattr(pw, name)(display="agg")
    pts, (x0, x1, y0, y1), fw, fh = _fill(ex)
    assert len(pts) >= 2, f"{name}: mechanism_points gives {len(pts)} point(s): nothing to measure"
    inside = (pts[:, 0] >= x0) & (pts[:, 0] <= x1) & (pts[:, 1] >= y0) & (pts[:, 1] <= y1)
    assert inside.all(), f"{name}: mechanism points outside the view {[x0, x1, y0, y1]}: {pts[~inside].tolist()}"
    assert max(fw, fh) >= FILL, (f"{name}: the mechanism fills {fw:.3f} of the view's width and "
                                 f"{fh:.3f} of its height (at least {FILL:.3f} of one is needed)")


def test_the_fill_measure_against_a_hand_made_case():
    """The measure itself: a square view of side 8 and points spanning 4 x 1 fill 1/2 and 1/8."""

    class Fake:
        def picture(self):
            return {"box": [-4.0, 4.0, -4.0, 4.0]}

        def mechanism_points(self):
            return np.array([[-1.0, 0.0], [3.0, 1.0], [0.0, 0.5]])

    _, box, fw, fh = _fill(Fake())
    assert box == [-4.0, 4.0, -4.0, 4.0]
    assert (fw, fh) == (0.5, 0.125)
