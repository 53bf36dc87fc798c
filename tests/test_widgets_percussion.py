"""PercussionExplorer: axis of percussion and sweet spot against 5.64-5.68 closed forms."""
import math

import numpy as np
import pytest

from planargeo.widgets.percussion import PercussionExplorer, parse_polygon
from planargeo.errors import InvalidPolygonError

# uniform rod preset: box 1.0 x 0.08, centre (0.5, 0):  ρ² = (1 + 0.08²) / 12
RHO2 = (1.0 + 0.08 ** 2) / 12.0


@pytest.fixture
def ex():
    return PercussionExplorer(display="agg", shape="uniform rod")


def test_rod_pivot_at_end(ex):
    r = ex.readout_values
    assert r["radius of gyration ρ"] == pytest.approx(math.sqrt(RHO2))
    assert r["centre of mass"] == pytest.approx((0.5, 0.0), abs=1e-12)
    assert r["l = d + ρ²/d (5.67)"] == pytest.approx(0.5 + RHO2 / 0.5)    # ≈ 2/3 of the rod
    assert r["force for α: m d α (5.66)"] == pytest.approx(1.0 * 0.5 * 10.0)
    f = ex.axis_art.get_line()                  # vertical line x = l:  tz - x fy = 0
    assert f[0] == pytest.approx(0.0, abs=1e-12)
    assert f[2] / f[1] == pytest.approx(0.5 + RHO2 / 0.5)


@pytest.mark.parametrize("pole", [(-0.4, 0.3), (1.2, -0.5), (0.5, 0.9)])
def test_axis_far_side_at_rho2_over_d(ex, pole):
    ex.set(**{"pole x": pole[0], "pole y": pole[1]})
    c = np.array([0.5, 0.0])
    P = np.array(pole)
    d = np.linalg.norm(P - c)
    f = ex.axis_art.get_line()
    F = np.hypot(f[0], f[1])
    # signed distance of the centre of mass and of the pole from the axis (5.23)
    dist_c = np.dot([c[1], -c[0], 1.0], f) / F
    dist_P = np.dot([P[1], -P[0], 1.0], f) / F
    assert abs(dist_c) == pytest.approx(RHO2 / d)                   # (5.68)
    assert abs(dist_P) == pytest.approx(d + RHO2 / d)               # (5.67)
    assert np.sign(dist_c) == np.sign(dist_P)                       # both on the same side: c between
    assert np.dot(f[:2], P - c) == pytest.approx(0.0, abs=1e-12)    # axis ⟂ (pole - c)


def test_pole_at_centre_gives_a_couple(ex):
    ex.set(**{"pole x": 0.5, "pole y": 0.0})
    f = ex.axis_art.get_line()
    assert f[:2] == pytest.approx([0.0, 0.0], abs=1e-12) and f[2] != 0     # line at infinity
    assert ex.readout_values["force for α: m d α (5.66)"] == "pure couple"
    ex.fig.canvas.draw()


def test_impact_at_sweet_spot_turns_about_the_grip(ex):
    ex.set(drive="impact")
    spot = 0.5 + RHO2 / 0.5
    assert ex.readout_values["sweet spot of the grip"] == pytest.approx((spot, 0.0), abs=1e-12)
    ex.controls["impact at"].value = spot
    assert ex.readout_values["pole distance from grip"] == pytest.approx(0.0, abs=1e-9)
    # elsewhere the body turns about another point on the axis: x = 0.5 - ρ²/(s - 0.5)
    ex.controls["impact at"].value = 0.9
    assert ex.readout_values["pole"] == pytest.approx((0.5 - RHO2 / 0.4, 0.0), abs=1e-12)
    ex.fig.canvas.draw()


def test_presets_and_custom_polygon(ex):
    for name in ("bat", "disc", "L-shape"):
        ex.controls["shape"].value = name
        assert ex.message == ""
        ex.fig.canvas.draw()
    ex.set(shape="custom polygon", polygon="0,0; 1,0; 0.5,1")   # triangle: centroid (0.5, 1/3)
    assert ex.readout_values["centre of mass"] == pytest.approx((0.5, 1 / 3))
    good = dict(ex.readout_values)
    ex.controls["polygon"].value = "0,0; 1,1; 1,0; 0,1"         # bow tie
    assert "polygon" in ex.message and ex.readout_values == good
    ex.controls["polygon"].value = "nonsense"
    assert "polygon" in ex.message
    ex.controls["polygon"].value = "0,0; 2,0; 2,1; 0,1"
    assert ex.message == "" and ex.readout_values["centre of mass"] == pytest.approx((1.0, 0.5))


def test_parse_polygon_errors():
    with pytest.raises(InvalidPolygonError, match="polygon"):
        parse_polygon("0,0; 1,1")
    assert parse_polygon("0,0; 1,0; 0,1;").area == pytest.approx(0.5)


def test_view_grows_to_show_a_large_custom_body(ex):
    ex.set(shape="custom polygon", polygon="0,0; 4,0; 4,3; 0,3")
    x0, x1 = ex.ax.get_xlim()
    y0, y1 = ex.ax.get_ylim()
    assert x0 <= 0 and x1 >= 4 and y0 <= 0 and y1 >= 3


def _drag(ex, start, end):
    from matplotlib.backend_bases import MouseEvent

    ex.fig.canvas.draw()
    canvas = ex.fig.canvas
    x0, y0 = ex.ax.transData.transform(start)
    x1, y1 = ex.ax.transData.transform(end)
    canvas.callbacks.process("button_press_event",
                             MouseEvent("button_press_event", canvas, x0 + 2, y0 - 2, button=1))
    canvas.callbacks.process("motion_notify_event", MouseEvent("motion_notify_event", canvas, x1, y1))
    canvas.callbacks.process("button_release_event",
                             MouseEvent("button_release_event", canvas, x1, y1, button=1))
    return (x0, y0)


def test_mouse_drag_moves_the_pole_and_the_axis_follows(ex):
    start = _drag(ex, (0.0, 0.0), (-0.4, 0.3))          # grab the pole at the grip, drop it
    assert ex.values["pole x"] == pytest.approx(-0.4, abs=0.01)
    assert ex.values["pole y"] == pytest.approx(0.3, abs=0.01)
    P = np.array([ex.values["pole x"], ex.values["pole y"]])
    a = ex.pole_art.get_point()
    assert [-a[1] / a[2], a[0] / a[2]] == pytest.approx(P)
    # the axis of percussion of the dropped pole: ⟂ (P - c) at ρ²/d beyond c (5.67, 5.68)
    c = np.array([0.5, 0.0])
    d = np.linalg.norm(P - c)
    f = ex.axis_art.get_line()
    assert np.dot(f[:2], P - c) == pytest.approx(0.0, abs=1e-12)
    assert abs(np.dot([c[1], -c[0], 1.0], f)) / np.hypot(f[0], f[1]) == pytest.approx(RHO2 / d)
    assert ex.readout_values["d = |pole − c|"] == pytest.approx(d)
    # a drag that does not start on the pole moves nothing
    from matplotlib.backend_bases import MouseEvent

    canvas = ex.fig.canvas
    far = ex.ax.transData.transform((1.5, -0.8))
    canvas.callbacks.process("button_press_event",
                             MouseEvent("button_press_event", canvas, *far, button=1))
    canvas.callbacks.process("motion_notify_event", MouseEvent("motion_notify_event", canvas, *start))
    assert ex.values["pole x"] == pytest.approx(-0.4, abs=0.01)
    # beyond the slider range the pole stops at the range's end
    assert ex.ax.get_xlim()[1] > 2.07 > ex.controls["pole x"].max
    _drag(ex, tuple(P), (2.07, 0.2))
    assert ex.values["pole x"] == ex.controls["pole x"].max


def test_angular_acceleration_only_redraws(ex, monkeypatch):
    import planargeo.widgets.percussion as mod

    calls = []
    real = mod.Inertia.from_polygon
    monkeypatch.setattr(mod.Inertia, "from_polygon",
                        staticmethod(lambda *a, **k: calls.append(1) or real(*a, **k)))
    n = ex.n_computes
    ex.controls["angular accel. α"].value = -4.0
    assert ex.n_computes == n                                        # no recompute
    assert ex.readout_values["force for α: m d α (5.66)"] == pytest.approx(1.0 * 0.5 * -4.0)
    # mass, pole, drive: recompute, but the polygon is not integrated again
    ex.set(**{"mass (kg)": 2.0, "pole x": 0.1})
    ex.controls["drive"].value = "impact"
    ex.controls["drive"].value = "acceleration pole"
    assert calls == [] and ex.n_computes == n + 3
    assert ex.readout_values["mass m"] == pytest.approx(2.0)
    assert ex.readout_values["radius of gyration ρ"] == pytest.approx(math.sqrt(RHO2))
    # a new shape is integrated once, and again only when it changes
    ex.controls["shape"].value = "disc"
    ex.controls["pole x"].value = -0.3
    assert len(calls) == 1
    assert ex.readout_values["mass m"] == pytest.approx(2.0)


# ---------------------------------------------------------------- issue 22: controls, units, symbols
def test_controls_that_do_nothing_in_a_drive_are_disabled_with_the_reason(ex):
    off = ex.disabled(ex.values)
    assert "impact" in off["impact at"] and "pole x" not in off
    before = dict(ex.readout_values)
    ex.controls["impact at"].value = 0.9                 # indeed it changes nothing here
    assert ex.readout_values == before
    ex.set(drive="impact")
    off = ex.disabled(ex.values)
    assert "impact at" not in off and "pole x" in off and "pole y" in off
    before = dict(ex.readout_values)
    ex.set(**{"pole x": 1.0, "pole y": 0.5})             # the impact sets the pole here
    assert ex.readout_values == before
    assert "polygon" in off                              # a preset shape: the text is not read


def test_sliders_and_rows_have_units_and_meanings(ex):
    for name, unit in (("pole x", "(m)"), ("pole y", "(m)"), ("impact at", "(m)"),
                       ("angular accel. α", "(rad/s²)")):
        assert ex.controls[name].description.endswith(unit), name
    for drive in ("acceleration pole", "impact"):
        ex.set(drive=drive)
        for k, v in ex.readout_values.items():
            assert k in ex.explain(), k
            if isinstance(v, (float, tuple)):
                assert ex.units.get(k) not in (None, "", "—"), k


def test_a_fresh_explorer_from_the_values_shows_the_same(ex):
    ex.set(drive="impact")
    ex.drag("impact", (0.5, 0.0), (0.7, 0.0), steps=2)
    ex.set(**{"angular accel. α": -4.0})
    fresh = PercussionExplorer(display="agg", **ex.values)
    assert fresh.readout_strings == ex.readout_strings
