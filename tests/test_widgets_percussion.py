"""PercussionExplorer: axis of percussion and sweet spot against 5.64-5.68 closed forms.

What is drawn is read off the explorer's picture (``ex.picture()``): the axis of
percussion is its clipped segment, the pole and the centre of percussion their markers.
"""
import math
import re

import numpy as np
import pytest

from planargeo.widgets.percussion import PercussionExplorer, parse_polygon
from planargeo.errors import InvalidPolygonError

from _picture_checks import elements, fill, problems


def axis_line(ex):
    """The drawn axis of percussion as a line ``[fx, fy, tz]`` through its two clipped ends."""
    a, b = np.array(next(p["xy"] for p in elements(ex.picture())["axis of percussion"]["parts"]
                         if p["p"] == "path"), float)
    d = b - a
    return np.array([d[0], d[1], a[0] * d[1] - a[1] * d[0]])     # through a along d (5.56)


def mark(ex, id):
    m = next(p for p in elements(ex.picture())[id]["parts"] if p["p"] == "mark")
    return np.array([m["x"], m["y"]])

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
    f = axis_line(ex)                           # vertical line x = l:  tz - x fy = 0
    assert f[0] == pytest.approx(0.0, abs=1e-12)
    assert f[2] / f[1] == pytest.approx(0.5 + RHO2 / 0.5, abs=1e-5)
    assert mark(ex, "spot") == pytest.approx([0.5 + RHO2 / 0.5, 0.0], abs=1e-5)   # centre of percussion
    assert mark(ex, "a") == pytest.approx([0.0, 0.0])


@pytest.mark.parametrize("pole", [(-0.4, 0.3), (1.2, -0.5), (0.5, 0.9)])
def test_axis_far_side_at_rho2_over_d(ex, pole):
    ex.set(**{"pole x": pole[0], "pole y": pole[1]})
    c = np.array([0.5, 0.0])
    P = np.array(pole)
    d = np.linalg.norm(P - c)
    f = axis_line(ex)
    F = np.hypot(f[0], f[1])
    # signed distance of the centre of mass and of the pole from the axis (5.23)
    dist_c = np.dot([c[1], -c[0], 1.0], f) / F
    dist_P = np.dot([P[1], -P[0], 1.0], f) / F
    assert abs(dist_c) == pytest.approx(RHO2 / d, abs=1e-4)         # (5.68)
    assert abs(dist_P) == pytest.approx(d + RHO2 / d, abs=1e-4)     # (5.67)
    assert np.sign(dist_c) == np.sign(dist_P)                       # both on the same side: c between
    assert np.dot(f[:2], P - c) / F == pytest.approx(0.0, abs=1e-4)  # axis ⟂ (pole - c)
    assert problems(ex.picture()) == []


def test_pole_at_centre_gives_a_couple(ex):
    ex.set(**{"pole x": 0.5, "pole y": 0.0})
    axis = elements(ex.picture())["axis of percussion"]      # the line at infinity: the couple glyph
    assert [p["p"] for p in axis["parts"]] == ["glyph", "text"] and "line at ∞" in axis["parts"][1]["text"]
    assert ex.readout_values["force for α: m d α (5.66)"] == "pure couple"
    assert "spot" not in elements(ex.picture()) and problems(ex.picture()) == []


def test_impact_at_sweet_spot_turns_about_the_grip(ex):
    ex.set(drive="impact")
    spot = 0.5 + RHO2 / 0.5
    assert ex.readout_values["sweet spot of the grip"] == pytest.approx((spot, 0.0), abs=1e-12)
    ex.controls["impact at"].value = spot
    assert ex.readout_values["pole distance from grip"] == pytest.approx(0.0, abs=1e-9)
    # elsewhere the body turns about another point on the axis: x = 0.5 - ρ²/(s - 0.5)
    ex.controls["impact at"].value = 0.9
    assert ex.readout_values["pole"] == pytest.approx((0.5 - RHO2 / 0.4, 0.0), abs=1e-12)
    # drawn: the blow's line x = 0.9, the pole on the other side of c, the grip's sweet spot marked
    assert axis_line(ex)[2] / axis_line(ex)[1] == pytest.approx(0.9, abs=1e-5)
    assert mark(ex, "a") == pytest.approx([0.5 - RHO2 / 0.4, 0.0], abs=1e-5)
    assert mark(ex, "spot") == pytest.approx([spot, 0.0], abs=1e-5)
    assert elements(ex.picture())["spot"]["symbol"] == "sweet spot"


def test_presets_and_custom_polygon(ex):
    for name in ("bat", "disc", "L-shape"):
        ex.controls["shape"].value = name
        assert ex.message == "" and problems(ex.picture()) == [], name
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
    x0, x1, y0, y1 = ex.picture()["box"]
    assert x0 <= 0 and x1 >= 4 and y0 <= 0 and y1 >= 3


def test_the_body_fills_its_default_view():
    """Issue 21: the bat (0.86 m) fills at least a third of the view (it filled 0.17).  The view
    holds the grip, the body and the pole's handles, 0.25 m around them, as tall as wide (so the
    whole mechanism fits either way round), in steps of 0.25 m: x from -0.25 to 1.25 at least."""
    ex = PercussionExplorer(display="agg")
    pic = ex.picture()
    x0, x1, y0, y1 = pic["box"]
    pts = ex.mechanism_points()
    assert x0 <= -0.25 and x1 >= 1.25 and x1 - x0 < 2.5
    assert min(x1 - x0, y1 - y0) >= float(np.max(np.ptp(pts, axis=0)))
    assert fill(pic, pts) > 0.38
    body = np.array(elements(pic)["body"]["parts"][0]["xy"])
    assert body[:, 0].min() == pytest.approx(0.0) and body[:, 0].max() == pytest.approx(0.86)


def test_dragging_the_pole_moves_it_and_the_axis_follows(ex):
    ex.drag("a", (0.0, 0.0), (-0.4, 0.3), steps=3)
    assert ex.values["pole x"] == pytest.approx(-0.4) and ex.values["pole y"] == pytest.approx(0.3)
    P = np.array([-0.4, 0.3])
    assert mark(ex, "a") == pytest.approx(P)
    # the axis of percussion of the dropped pole: ⟂ (P - c) at ρ²/d beyond c (5.67, 5.68)
    c = np.array([0.5, 0.0])
    d = np.linalg.norm(P - c)
    f = axis_line(ex)
    F = np.hypot(f[0], f[1])
    assert np.dot(f[:2], P - c) / F == pytest.approx(0.0, abs=1e-4)
    assert abs(np.dot([c[1], -c[0], 1.0], f)) / F == pytest.approx(RHO2 / d, abs=1e-4)
    assert mark(ex, "spot") == pytest.approx(c + (c - P) / d * RHO2 / d, abs=1e-4)
    assert ex.readout_values["d = |pole − c|"] == pytest.approx(d)
    # beyond the slider range the pole stops at the range's end
    ex.drag("a", tuple(P), (2.07, 0.2), steps=2)
    assert ex.values["pole x"] == ex.controls["pole x"].max
    x0, x1, y0, y1 = ex.picture()["box"]
    assert x0 < ex.values["pole x"] < x1 and y0 < ex.values["pole y"] < y1       # still in view


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


def test_kept_inertia_follows_mass_and_shape_while_the_pole_is_dragged(ex):
    """The scaled inertia is kept per shape and mass: after changes of either, and drags of the pole, the
    rod still meets ρ² = (L² + w²)/12 and m d α (5.66), and each preset its own ρ (as a fresh explorer's)."""
    for shape, m in (("uniform rod", 2.0), ("disc", 2.0), ("uniform rod", 0.5), ("uniform rod", 2.0)):
        ex.set(shape=shape, **{"mass (kg)": m})
        ex.drag("a", (0.0, 0.0), (-0.3, 0.2), steps=3)
        r = ex.readout_values
        assert r["mass m"] == pytest.approx(m, rel=1e-12)
        if shape == "uniform rod":
            assert r["radius of gyration ρ"] == pytest.approx(math.sqrt(RHO2), rel=1e-12)
            d = math.hypot(-0.3 - 0.5, 0.2)
            assert r["force for α: m d α (5.66)"] == pytest.approx(m * d * 10.0, rel=1e-9)
        fresh = PercussionExplorer(display="agg", **ex.values)
        assert fresh.readout_strings == ex.readout_strings


@pytest.mark.parametrize("s", [0.9, 0.52])
def test_greyed_pole_sliders_show_no_number_and_say_where_the_impact_put_the_pole(ex, s):
    # struck across the rod at x = s, the pole is on the axis at c − ρ²/(s − c) (5.68): the greyed
    # pole sliders must not read 0.00 against it; their tooltip says where it is
    ex.set(drive="impact", **{"impact at": s})
    x = 0.5 - RHO2 / (s - 0.5)
    for name in ("pole x", "pole y"):
        w = ex.controls[name]
        assert w.disabled and not w.readout, name
        got = [float(v) for v in re.findall(r"\((-?[\d.]+), (-?[\d.]+)\) m", w.tooltip)[0]]
        assert got == pytest.approx([x, 0.0], rel=1e-3, abs=1e-9) and "not used" in w.tooltip
    assert ex.readout_values["pole"] == pytest.approx((x, 0.0), rel=1e-9, abs=1e-12)
    ex.set(drive="acceleration pole")                  # in use again: its number is back
    assert all(ex.controls[n].readout and not ex.controls[n].disabled for n in ("pole x", "pole y"))


def test_a_flat_polygon_is_refused_as_flat_and_its_value_said_once():
    ex = PercussionExplorer(display="agg", shape="custom polygon")
    shown = dict(ex.readout_values)
    ex.set(polygon="0,0; 1,0; 1,0")                  # three vertices, no area
    assert "vertices lie on one line" in ex.message and "self-intersecting" not in ex.message
    assert ex.message.count("0,0; 1,0; 1,0") == 1 and ex.readout_values == shown
    ex.set(polygon="0,0; 1,1; 1,0; 0,1")             # a bow tie: its two halves cancel to no area
    assert "self-intersecting" in ex.message and ex.message.count("0,0; 1,1; 1,0; 0,1") == 1
