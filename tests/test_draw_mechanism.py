"""draw_model draws the model's contacts where the contact geometry says (slider-crank, Fig 9.2 tree)."""
from __future__ import annotations

import warnings

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pytest  # noqa: E402

from planargeo.draw.mechanism import draw_model, slider_guide  # noqa: E402
from planargeo.mechanics.kinematics import kinematics  # noqa: E402
from planargeo.scenes import build  # noqa: E402


@pytest.fixture
def ax():
    fig, ax = plt.subplots()
    yield ax
    plt.close(fig)


def test_slider_crank_guide_from_the_contact(ax):
    res = build("slider-crank")                      # r = 2.29, l = 5, t = 0.5, psi = 0.4
    d = kinematics(res.model, res.state["q"])
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        arts = draw_model(res.model, d, ax, width=0.3)
    # hand: the piston slides on x = 0; its joint is at height r sin psi + sqrt(l² - r² cos² psi)
    h = 2.29 * np.sin(0.4) + np.sqrt(25.0 - (2.29 * np.cos(0.4)) ** 2)
    p0, e, n, hw, (s0, s1) = slider_guide(res.model.contacts[0], d.pose, arts["shapes"][2])
    np.testing.assert_allclose(e, [0.0, 1.0], atol=1e-12)
    assert hw == pytest.approx(0.15 + 0.04)          # half the drawn width plus the clearance
    # the piston link runs from its joint (h) to 2t above it, buffered by the half-width 0.15
    assert s0 == pytest.approx(h - 0.15 - 0.3) and s1 == pytest.approx(h + 1.0 + 0.15 + 0.3)
    walls = [ln for ln in arts["contacts"] if hasattr(ln, "get_xydata")
             and np.ptp(ln.get_xydata()[:, 1]) > 1.0]
    xs = sorted(float(np.mean(w.get_xydata()[:, 0])) for w in walls)
    np.testing.assert_allclose(xs, [-0.19, 0.19], atol=1e-12)   # two walls, symmetric about x = 0
    for w in walls:
        np.testing.assert_allclose(np.ptp(w.get_xydata()[:, 0]), 0.0, atol=1e-12)   # vertical


def test_pin_contacts_drawn_at_the_tips(ax):
    res = build("constrained-tree")
    d = kinematics(res.model, res.state["q"])
    arts = draw_model(res.model, d, ax)
    squares = arts["contacts"]
    assert len(squares) == 2
    for sq, c in zip(squares, res.model.contacts):
        x, y, th = d.pose[c.a]
        tip = np.array([x + np.cos(th), y + np.sin(th)])          # point_a = (L, 0), L = 1
        centre = np.array(sq.get_xy()) + [sq.get_width() / 2, sq.get_height() / 2]
        np.testing.assert_allclose(centre, tip, atol=1e-12)


def test_prismatic_slider_follows_the_joint_axis_not_the_body_angle(ax):
    from planargeo.mechanics.model import Body, Joint, Model

    m = Model([Body(1.0, (0.3, 0.0), 0.1)], [Joint("revolute_prismatic", (0.0, 0.0, 0.5))], [-1])
    d = kinematics(m, [0.4, 1.2])                    # slide 0.4 along 0.5 rad, then turn by 1.2
    arts = draw_model(m, d, ax, ground=False)
    rects = [a for a in arts["joints"] if type(a).__name__ == "Rectangle"]
    (rect,) = rects
    M = (rect.get_transform() - ax.transData).get_matrix()   # the block's own rotation
    ang = np.arctan2(M[1, 0], M[0, 0])
    assert ang == pytest.approx(0.5)


def test_draw_body_marks_the_centre_of_mass(ax):
    """``com=`` adds the quartered disc centred there (radius 0.07), after the body's patches."""
    from matplotlib.patches import Wedge

    from planargeo.draw.mechanism import draw_body, link_polygon

    shape = link_polygon([0.0, 0.0], [2.0, 0.0], 0.4)
    plain = draw_body(shape, ax)
    assert not any(isinstance(p, Wedge) for p in plain)
    marked = draw_body(shape, ax, com=(1.0, 0.0))
    wedges = [p for p in marked if isinstance(p, Wedge)]
    assert len(marked) == len(plain) + 4 and marked[-4:] == wedges
    assert all(w.center == (1.0, 0.0) and w.r == 0.07 for w in wedges)
    assert sorted((w.theta1, w.theta2) for w in wedges) == [(0, 90), (90, 180), (180, 270), (270, 360)]


def test_draw_frame_axes_turned_by_angle(ax):
    """The x arrow points along ``angle``, the y arrow 90° further; ``angle`` is keyword-only."""
    from planargeo.draw.mechanism import draw_frame

    x_arrow, _, y_arrow, _ = draw_frame([1.0, 2.0], ax, angle=np.pi / 6, length=2.0)
    c, s = np.cos(np.pi / 6), np.sin(np.pi / 6)
    np.testing.assert_allclose(x_arrow.xy, [1.0 + 2.0 * c, 2.0 + 2.0 * s], atol=1e-12)
    np.testing.assert_allclose(y_arrow.xy, [1.0 - 2.0 * s, 2.0 + 2.0 * c], atol=1e-12)
    np.testing.assert_allclose(x_arrow.xyann, [1.0, 2.0])
    with pytest.raises(TypeError):
        draw_frame([0.0, 0.0], 0.3, ax)                 # the old positional angle
