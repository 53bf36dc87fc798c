"""PercussionExplorer: a dragged handle stays under the pointer (review: the view re-fitted itself during
the drag, so a slow drag of the centre of percussion stopped ~100 px short and a fast one jumped past the
view's edge, where the axis and its handle vanished).

The page is driven as canvas.js drives it: the pointer's pixel is turned into data through the box of the
picture the page holds at that moment (``dataOf``), one ``drag`` message per move, a ``release`` at the end.
"""
import math

import numpy as np
import pytest

from planargeo.widgets.percussion import PercussionExplorer

from _page_drag import page_drag as drag

HANDLE = "axis (point)"        # on the centre of percussion: the foot of c on the axis (5.68)


def page_drag(ex, name, dx_px, steps, dy_px=0.0):
    """The drag (tests/_page_drag.py): the picture's boxes during it (before the release) and the data
    point the pointer was over at the last move (in the box it was drawn in when the drag began)."""
    b0, moves, aimed = drag(ex, name, dx_px, dy_px, steps)
    return [b0] + [box for _xy, _reply, box, _values in moves], aimed


@pytest.mark.parametrize("steps", [1, 3, 30])
def test_the_centre_of_percussion_stays_under_the_pointer_and_the_view_holds(steps):
    """The review's drag: the defaults, the handle 150 px to the right, slowly (30 moves) or fast."""
    ex = PercussionExplorer(display="page")
    boxes, aimed = page_drag(ex, HANDLE, 150.0, steps)
    assert ex.message == ""
    assert set(boxes) == {boxes[0]}                               # the view held during the drag
    x, y = ex.handle_position(HANDLE)
    assert (x, y) == pytest.approx(aimed, abs=1e-9)              # where the pointer is (≈ 1.21 m)
    assert aimed[0] == pytest.approx(1.213, abs=2e-3)
    # the centre of percussion there: c, the pole and it on one line, ρ²/d beyond c (5.68)
    r = ex.readout_values
    c, rho = np.array(r["centre of mass"]), r["radius of gyration ρ"]
    d = r["d = |pole − c|"]
    assert math.dist((x, y), c) == pytest.approx(rho ** 2 / d, rel=1e-9)
    # the release fits the view again, as a fresh explorer of the same values draws it, the handle in it
    fresh = PercussionExplorer(display="page", **ex.values)
    assert ex.canvas.picture == fresh.canvas.picture
    b = ex.canvas.picture["box"]
    assert b[0] < x < b[1] and b[2] < y < b[3]


def test_a_drag_past_the_picture_is_refused_and_the_handle_stays_in_view():
    """The pointer 400 px right of the handle is past 2 m, the pole slider's end, as far as the view
    reaches (it fits the handles within the pole sliders' range): that move is refused with its reason,
    the handle keeps the last place it had, and the view fitted on release shows it."""
    ex = PercussionExplorer(display="page")
    boxes, aimed = page_drag(ex, HANDLE, 400.0, 4)
    b = boxes[0]
    assert aimed[0] > b[1]
    assert set(boxes) == {b}
    assert aimed[0] > ex.controls["pole x"].max
    assert "refused" in ex.message and "out of the picture's reach" in ex.message
    x, y = ex.handle_position(HANDLE)
    assert x <= ex.controls["pole x"].max
    nb = ex.canvas.picture["box"]                                 # and in the view fitted on release
    assert nb[0] < x < nb[1] and nb[2] < y < nb[3]
    assert any(h["id"] == HANDLE for h in ex.canvas.picture["handles"])


def test_a_slider_after_a_drag_fits_the_view_again():
    """The held view is the drag's only: a control changed afterwards shows the view a fresh explorer shows."""
    ex = PercussionExplorer(display="page")
    page_drag(ex, HANDLE, 150.0, 5)
    ex.set(**{"mass (kg)": 2.0})
    assert ex.canvas.picture == PercussionExplorer(display="page", **ex.values).canvas.picture
