"""ProjectiveExplorer: poles, polars and constructions against closed forms for circles."""
import math
import re

import numpy as np
import pytest
from matplotlib.backend_bases import MouseEvent

from planargeo.widgets.projective import CONICS, ProjectiveExplorer


def xy(p):
    return np.array([-p[1] / p[2], p[0] / p[2]])


def line_distance(l):
    """Distance |tz| / |f| of the line from the origin (5.55)."""
    F = math.hypot(l[0], l[1])
    return abs(l[2]) / F


@pytest.fixture
def ex():
    return ProjectiveExplorer(display="agg", conic="circle", a=1.5)


@pytest.mark.parametrize("P", [(2.0, 1.5), (0.3, -0.4), (-3.0, 0.5)])
def test_circle_polar_distance(ex, P):
    ex.set(**{"P x": P[0], "P y": P[1]})
    r2, d = 1.5 ** 2, math.hypot(*P)
    assert ex.readout_values["polar of P: distance to origin"] == pytest.approx(r2 / d)
    pol = ex.polar_art.get_line()
    # the polar is perpendicular to OP and crosses OP at distance r²/d (same side as P)
    foot = r2 / d * np.array(P) / d
    assert np.dot([foot[1], -foot[0], 1.0], pol) == pytest.approx(0.0, abs=1e-12)
    assert np.dot(pol[:2], P) == pytest.approx(0.0, abs=1e-12)
    assert ex.readout_values["P is"] == ("outside" if d > 1.5 else "inside")


def test_exterior_construction_contacts_are_tangent_points(ex):
    ex.set(**{"P x": 2.0, "P y": 1.5})
    shown = [a for a in ex.cpts_art if a.get_visible()]
    assert len(shown) == 2 and sum(a.get_visible() for a in ex.tan_art) == 2
    for a in shown:
        X = a.get_xy()
        assert np.hypot(*X) == pytest.approx(1.5)                      # on the circle
        assert np.dot(X - [2.0, 1.5], X) == pytest.approx(0.0, abs=1e-9)  # radius ⟂ tangent


def test_interior_construction_poles_lie_on_polar(ex):
    ex.set(**{"P x": 0.4, "P y": 0.3})
    assert sum(a.get_visible() for a in ex.tan_art) == 4
    pol = ex.polar_art.get_line()
    for a in ex.cpts_art[4:]:
        assert a.get_visible()
        assert np.dot(a.get_point(), pol) == pytest.approx(0.0, abs=1e-9 * np.abs(a.get_point()).max())


def test_inertia_polar_is_axis_of_percussion(ex):
    # imaginary circle of radius ρ = radius of gyration: polar of a point at distance d
    # lies on the other side of the centre at distance ρ²/d (thesis 5.68)
    ex.set(conic="inertia (imaginary circle)", a=0.8, **{"P x": 2.0, "P y": 0.0})
    assert ex.readout_values["conic"] == "imaginary circle"
    pol = ex.polar_art.get_line()
    x_line = pol[2] / pol[1]             # vertical line: tz - x fy = 0
    assert x_line == pytest.approx(-0.8 ** 2 / 2.0)
    assert not any(a.get_visible() for a in ex.tan_art)


def test_line_pole_and_invariance(ex):
    ex.set(**{"line angle (deg)": 90.0, "line offset": 0.5})   # vertical line x = -0.5
    M = ex.M_art.get_line()
    assert np.dot([0.0, 0.5, 1.0], M) == pytest.approx(0.0)    # (−0.5, 0) lies on it
    # pole of the line x = -0.5 w.r.t. the circle r = 1.5: (-r²/0.5, 0)
    assert ex.readout_values["pole of M"] == pytest.approx((-4.5, 0.0))
    assert ex.readout_values["P·M"] == pytest.approx(ex.readout_values["pole(M)·polar(P)"])


@pytest.mark.parametrize("conic", CONICS)
def test_every_conic_draws(ex, conic):
    for P in [(2.0, 1.5), (0.1, 0.1), (0.0, 0.0)]:
        ex.set(conic=conic, **{"P x": P[0], "P y": P[1]})
        assert ex.message == ""
        assert ex.readout_values["P·M"] == pytest.approx(ex.readout_values["pole(M)·polar(P)"])
        ex.fig.canvas.draw()


def test_drag_moves_the_point(ex):
    ex.fig.canvas.draw()
    canvas = ex.fig.canvas
    x0, y0 = ex.ax.transData.transform([2.0, 1.5])
    x1, y1 = ex.ax.transData.transform([-1.0, 2.5])
    canvas.callbacks.process("button_press_event",
                             MouseEvent("button_press_event", canvas, x0 + 2, y0 - 2, button=1))
    canvas.callbacks.process("motion_notify_event", MouseEvent("motion_notify_event", canvas, x1, y1))
    canvas.callbacks.process("button_release_event",
                             MouseEvent("button_release_event", canvas, x1, y1, button=1))
    assert ex.values["P x"] == pytest.approx(-1.0, abs=0.02)
    assert ex.values["P y"] == pytest.approx(2.5, abs=0.02)
    assert xy(ex.P_art.get_point()) == pytest.approx([ex.values["P x"], ex.values["P y"]])
    # a move without a press on the point does nothing
    canvas.callbacks.process("motion_notify_event", MouseEvent("motion_notify_event", canvas, x0, y0))
    assert ex.values["P x"] == pytest.approx(-1.0, abs=0.02)


def test_ideal_point_maps_to_a_diameter_and_line_at_infinity_to_the_centre(ex):
    # thesis 5.2.2: a point at infinity maps to a line through the centre, the line at
    # infinity to the centre (here the circle's centre is the origin)
    ex.set(**{"P at infinity": True, "P x": 1.0, "P y": 1.0, "M at infinity": True})
    assert ex.message == ""
    pol = ex.polar_art.get_line()
    assert pol[2] == pytest.approx(0.0, abs=1e-12)                  # through the origin
    assert np.dot(pol[:2], [1.0, 1.0]) == pytest.approx(0.0, abs=1e-12)  # ⟂ to the direction (circle)
    assert ex.readout_values["pole of M"] == pytest.approx((0.0, 0.0), abs=1e-12)
    assert ex.readout_values["P"] == "at infinity (direction (0.7071, 0.7071))" and "at infinity" in ex.readout_values["P is"]
    # the two tangents in that direction are parallel and touch the circle at ±r along the normal
    shown = [a for a in ex.cpts_art if a.get_visible()]
    assert len(shown) == 2
    for a in shown:
        X = a.get_xy()
        assert np.hypot(*X) == pytest.approx(1.5)
        assert np.dot(X, [1.0, 1.0]) == pytest.approx(0.0, abs=1e-9)
    ex.fig.canvas.draw()
    ex.set(**{"P x": 0.0, "P y": 0.0})                                # no direction: a message
    assert "P x, P y" in ex.message
    ex.set(**{"P at infinity": False})
    assert ex.message == ""


def test_construction_toggle_only_redraws_and_shows_the_current_point(ex):
    ex.set(**{"P x": 2.0, "P y": 1.5})
    n = ex.n_computes
    ex.controls["construction"].value = False
    assert ex.n_computes == n and not any(a.get_visible() for a in ex.tan_art + ex.cpts_art)
    ex.controls["P x"].value = -2.5                      # moved while the construction is hidden
    ex.controls["construction"].value = True
    assert ex.n_computes == n + 1
    shown = [a for a in ex.cpts_art if a.get_visible()]
    assert len(shown) == 2
    for a in shown:                                      # tangent points of the moved P
        X = a.get_xy()
        assert np.hypot(*X) == pytest.approx(1.5)
        assert np.dot(X - [-2.5, 1.5], X) == pytest.approx(0.0, abs=1e-9)
    ex.controls["line and its pole"].value = False
    assert ex.n_computes == n + 1 and not ex.M_art.get_visible() and not ex.Mpole_art.get_visible()


# ---------------------------------------------------------------- issue 22: ideal points and units
def test_pole_of_the_line_at_infinity_for_a_parabola_is_at_infinity():
    """Parabola, M = line at infinity: its pole is the centre, the ideal point of the axis (5.37).

    A parabola touches the line at infinity at one point, the direction of its axis:
    the ideal point Q = [dy, −dx, 0] with QᵀCQ = 0 (5.38); the pole C⁻¹[0, 0, 1] is that point.  Computed in floating point
    its weight was 1e-17 and the readout said (3.1e16, −8.5e16) m.
    """
    for tilt in (20.0, 0.0, -37.0):
        ex = ProjectiveExplorer(display="agg", conic="parabola", **{"M at infinity": True,
                                                                    "tilt (deg)": tilt})
        assert ex.message == ""
        text = ex.readout_values["pole of M"]
        assert isinstance(text, str) and text.startswith("at infinity (direction (")
        d = np.array([float(v) for v in re.findall(r"-?[\d.]+(?:e-?\d+)?", text)])
        C = ex.state["C"]
        Q = np.array([d[1], -d[0], 0.0])
        assert abs(Q @ C @ Q) < 1e-3 * np.abs(C).max()                   # on the conic, at infinity
        assert ex.state["poleM"][2] == 0.0                                # an ordinary ideal value
        assert ex.readout_values["centre"] == text
        assert "m" not in ex.readout_strings["pole of M"].split(")")[-1]  # no unit after words


def test_a_far_but_finite_pole_stays_finite():
    """A line one slider step from the centre of a circle has its pole far away, but finite."""
    ex = ProjectiveExplorer(display="agg", conic="circle", a=1.5,
                            **{"line angle (deg)": 90.0, "line offset": 0.05})
    # the line x = -0.05: its pole w.r.t. x² + y² = r² is (-r²/0.05, 0) (5.37)
    assert ex.readout_values["pole of M"] == pytest.approx((-1.5 ** 2 / 0.05, 0.0))


def test_sliders_and_rows_have_units():
    ex = ProjectiveExplorer(display="agg")
    for name in ("P x", "P y", "a", "b", "line offset"):
        assert ex.controls[name].description.endswith("(m)"), name
    for k, v in ex.readout_values.items():
        if isinstance(v, (float, tuple)):
            assert ex.units.get(k, "") not in ("", "—"), k
    for k in ex.readout_values:
        assert k in ex.explain(), k


def test_handles_are_where_they_can_be_grabbed():
    """The fixed view holds P and M's handles (not a far pole of M); M's direction handle turns to
    the side of its pivot that is in view, and dragging it still turns M through the pointer."""
    ex = ProjectiveExplorer(display="agg", conic="circle", a=1.5,
                            **{"line angle (deg)": 90.0, "line offset": 0.1})
    assert ex.readout_values["pole of M"] == pytest.approx((-1.5 ** 2 / 0.1, 0.0))   # 22.5 m away
    handles = {h.name: h for h in ex.handles()}
    assert len(ex.mechanism_points()) == 3                                         # P, M's two
    assert np.all(np.abs(ex.mechanism_points()) <= 4.0)
    ex.set(**{"line angle (deg)": 0.0, "line offset": -3.5})                       # the line y = -3.5
    pivot, tip = (np.array(handles[n].where()) for n in ("M (point)", "M (direction)"))
    assert np.all(np.abs(tip) <= 4.0) and np.all(np.abs(pivot) <= 4.0)
    ex.drag("M (direction)", tuple(tip), (tip[0], tip[1] + 0.5), steps=2)
    M = ex.M_art.get_line()
    on = lambda x, y: M[2] + y * M[0] - x * M[1]
    assert on(*pivot) == pytest.approx(0.0, abs=1e-9)
    assert on(tip[0], tip[1] + 0.5) == pytest.approx(0.0, abs=1e-9)
