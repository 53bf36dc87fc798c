"""ArticulatedExplorer: the dragged "first body" handle follows the pointer (student review: the view
re-fitted at every step of the drag, so the pointer's place in data drifted with it, a feedback loop:
θ₁ climbed 1 → 4 → 7.5 → … → 156° while the pointer moved 50 px, ~10° about the base; on release the
handle was 124 px from the pointer).

The page is driven as canvas.js drives it: the pointer's pixel turned into data through the box of the
picture the page holds at that moment (``dataOf``), one ``drag`` message per move, a ``release`` at the end.
"""
import math

import pytest

from planargeo.widgets.articulated import ArticulatedExplorer

from _page_drag import page_drag as drag

THETA = "base θ₁ (deg)"


def page_drag(ex, name, dx_px, dy_px, steps):
    """The drag (tests/_page_drag.py): the first box and, per move, the pointer's data point, the box and θ₁."""
    b0, moves, _aimed = drag(ex, name, dx_px, dy_px, steps)
    assert all(reply == (True, "") for _xy, reply, _b, _v in moves)
    return b0, [(xy, box, float(values[THETA])) for xy, _reply, box, values in moves]


@pytest.mark.parametrize("steps", [1, 10, 40])
def test_the_first_body_follows_the_pointer_about_the_base_and_the_view_holds(steps):
    """The review's drag: the far end of body 1, 40 px right and 30 px up, slowly or at once."""
    ex = ArticulatedExplorer(display="page")
    assert ex.handle_position("first body") == pytest.approx((1.0, 0.0), abs=1e-12)   # θ₁ = 0, L = 1
    b0, moves = page_drag(ex, "first body", 40.0, -30.0, steps)
    assert ex.message == ""
    for (x, y), box, theta in moves:
        assert box == b0                                           # the view held during the drag
        # θ₁ is the pointer's angle about the base (the pivot at the origin), step by step
        assert theta == pytest.approx(math.degrees(math.atan2(y, x)), abs=0.5)
    # the pointer ended ≈ 50 px from where it began, ≈ 10° about the base at this scale (not 156°)
    (x, y), _box, theta = moves[-1]
    assert 5.0 < theta < 15.0
    # after the release the handle is the end of body 1 (L = 1 along θ₁), on the ray to the pointer
    hx, hy = ex.handle_position("first body")
    assert (hx, hy) == pytest.approx((math.cos(math.radians(theta)), math.sin(math.radians(theta))), abs=1e-9)
    assert math.atan2(hy, hx) == pytest.approx(math.atan2(y, x), abs=math.radians(0.5))
    # the release fits the view again, as a fresh explorer of the same values draws it, the handle in it
    fresh = ArticulatedExplorer(display="page", **ex.values)
    assert ex.canvas.picture == fresh.canvas.picture
    b = ex.canvas.picture["box"]
    assert b[0] < hx < b[1] and b[2] < hy < b[3]


def test_a_control_after_a_drag_fits_the_view_again():
    """The held view is the drag's only: a control changed afterwards shows the view a fresh explorer shows."""
    ex = ArticulatedExplorer(display="page")
    page_drag(ex, "pole a", 60.0, 20.0, 5)
    ex.set(**{"λ = L/ρ": 2.0})
    assert ex.canvas.picture == ArticulatedExplorer(display="page", **ex.values).canvas.picture
