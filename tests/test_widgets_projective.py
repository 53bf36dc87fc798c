"""ProjectiveExplorer: poles, polars and constructions against closed forms for circles.

What is drawn is read off the explorer's picture (``ex.picture()``, the plain data the
page and the exports draw): a line is its clipped segment, a point its marker, a point
at infinity an arrow at the edge of the view.
"""
import math
import re

import numpy as np
import pytest

from planargeo.widgets.projective import CONICS, ProjectiveExplorer

from _picture_checks import elements, problems


def xy(p):
    return np.array([-p[1] / p[2], p[0] / p[2]])


def cross2(a, b) -> float:
    """The z component of the cross product of two plane vectors."""
    return float(a[0] * b[1] - a[1] * b[0])


def segment(el):
    """The two ends of a drawn (clipped) line."""
    return np.array(next(p["xy"] for p in el["parts"] if p["p"] == "path"), float)


def mark(el):
    """Where a drawn point's marker is."""
    m = next(p for p in el["parts"] if p["p"] == "mark")
    return np.array([m["x"], m["y"]])


def construction_ids(pic):
    return {i for i in elements(pic) if i.startswith(("tangent", "chord", "contact"))}


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
    # the polar of P for x² + y² = r² is the line P·X = r²: perpendicular to OP at r²/d (5.36)
    els = elements(ex.picture())
    drawn = [p for p in els["polar"]["parts"] if p["p"] == "path"]
    assert drawn or r2 / d > 4.0                                          # in view unless far out
    for X in (np.asarray(drawn[0]["xy"]) if drawn else []):
        assert np.dot(X, P) == pytest.approx(r2, abs=1e-4)
    assert ex.readout_values["P is"] == ("outside" if d > 1.5 else "inside")


def test_exterior_construction_contacts_are_tangent_points(ex):
    ex.set(**{"P x": 2.0, "P y": 1.5})
    els = elements(ex.picture())
    assert construction_ids(ex.picture()) == {"tangent 1", "tangent 2", "contact 1", "contact 2"}
    for k in (1, 2):
        X = mark(els[f"contact {k}"])
        assert np.hypot(*X) == pytest.approx(1.5, abs=1e-4)                  # on the circle
        assert np.dot(X - [2.0, 1.5], X) == pytest.approx(0.0, abs=1e-4)     # radius ⟂ tangent
        A, B = segment(els[f"tangent {k}"])                                  # the tangent: P and X on it
        for Q in ([2.0, 1.5], X):
            assert cross2(B - A, np.asarray(Q) - A) == pytest.approx(0.0, abs=1e-3)


def test_interior_construction_poles_lie_on_polar(ex):
    ex.set(**{"P x": 0.4, "P y": 0.3})
    pic = ex.picture()
    assert construction_ids(pic) == {"tangent 1", "tangent 2", "tangent 3", "tangent 4", "chord 1",
                                     "chord 2", "chord end 1", "chord end 2", "chord end 3", "chord end 4",
                                     "chord pole 1", "chord pole 2"}
    # the poles of the chords lie on the polar of P: P·K = r² (5.2.2, Fig 5.3); here 4.5 m away,
    # beyond the view: drawn as arrows at its edge, named
    for K in ex.state["interior"].poles:
        assert np.dot(xy(K), [0.4, 0.3]) == pytest.approx(1.5 ** 2)
    for k in (1, 2):
        parts = elements(pic)[f"chord pole {k}"]["parts"]
        assert [p["p"] for p in parts] == ["arrow", "text"] and parts[1]["text"].startswith("pole of chord c")


def test_inertia_polar_is_axis_of_percussion(ex):
    # imaginary circle of radius ρ = radius of gyration: polar of a point at distance d
    # lies on the other side of the centre at distance ρ²/d (thesis 5.68)
    ex.set(conic="inertia (imaginary circle)", a=0.8, **{"P x": 2.0, "P y": 0.0})
    assert ex.readout_values["conic"] == "imaginary circle"
    pic = ex.picture()
    assert segment(elements(pic)["polar"])[:, 0] == pytest.approx([-0.8 ** 2 / 2.0] * 2)   # x = −ρ²/d
    assert construction_ids(pic) == set()
    C = elements(pic)["C"]                # its real stand-in: the circle of radius ρ, dashed, centre marked
    e = next(p for p in C["parts"] if p["p"] == "ellipse")
    assert (e["x"], e["y"]) == (0.0, 0.0) and np.abs(np.linalg.det(np.reshape(e["m"], (2, 2)))) == pytest.approx(0.64)
    assert C["dash"] and any(p["p"] == "mark" for p in C["parts"])


def test_line_pole_and_invariance(ex):
    ex.set(**{"line angle (deg)": 90.0, "line offset": 0.5})   # vertical line x = -0.5
    els = elements(ex.picture())
    assert segment(els["M"])[:, 0] == pytest.approx([-0.5, -0.5])
    # its pole (−4.5, 0) is beyond the view: an arrow at the left edge, pointing left, "off view"
    parts = els["pole of M"]["parts"]
    arrow = next(p for p in parts if p["p"] == "arrow")
    assert arrow["dx"] < 0 and arrow["dy"] == pytest.approx(0.0, abs=1e-9)
    assert next(p for p in parts if p["p"] == "text")["text"] == "pole of M (off view)"
    # pole of the line x = -0.5 w.r.t. the circle r = 1.5: (-r²/0.5, 0)
    assert ex.readout_values["pole of M"] == pytest.approx((-4.5, 0.0))
    assert ex.readout_values["P·M"] == pytest.approx(ex.readout_values["pole(M)·polar(P)"])


@pytest.mark.parametrize("conic", CONICS)
def test_every_conic_draws(ex, conic):
    for P in [(2.0, 1.5), (0.1, 0.1), (0.0, 0.0)]:
        ex.set(conic=conic, **{"P x": P[0], "P y": P[1]})
        assert ex.message == ""
        assert ex.readout_values["P·M"] == pytest.approx(ex.readout_values["pole(M)·polar(P)"])
        assert problems(ex.picture()) == [], (conic, P)


def test_drag_moves_the_point(ex):
    ex.drag("P", (2.0, 1.5), (-1.0, 2.5), steps=3)
    assert ex.values["P x"] == pytest.approx(-1.0) and ex.values["P y"] == pytest.approx(2.5)
    pic = ex.picture()
    assert mark(elements(pic)["P"]) == pytest.approx([-1.0, 2.5])
    assert {h["id"]: (h["x"], h["y"]) for h in pic["handles"]}["P"] == pytest.approx((-1.0, 2.5))
    # its polar moved with it: P·X = r² on the drawn line
    for X in segment(elements(pic)["polar"]):
        assert np.dot(X, [-1.0, 2.5]) == pytest.approx(1.5 ** 2, abs=1e-4)


def test_ideal_point_maps_to_a_diameter_and_line_at_infinity_to_the_centre(ex):
    # thesis 5.2.2: a point at infinity maps to a line through the centre, the line at
    # infinity to the centre (here the circle's centre is the origin)
    ex.set(**{"P at infinity": True, "P x": 1.0, "P y": 1.0, "M at infinity": True})
    assert ex.message == ""
    pic = ex.picture()
    els = elements(pic)
    A, B = segment(els["polar"])                                    # a diameter ⟂ to the direction
    assert cross2(A, B) == pytest.approx(0.0, abs=1e-4) and np.dot(B - A, [1.0, 1.0]) == pytest.approx(0.0, abs=1e-4)
    # P at infinity: an arrow at the edge of the view, pointing along its direction (1, 1)
    parts = els["P"]["parts"]
    arrow = next(p for p in parts if p["p"] == "arrow")
    assert arrow["dx"] == pytest.approx(arrow["dy"]) and arrow["dx"] > 0
    assert next(p for p in parts if p["p"] == "text")["text"] == "P at ∞"
    assert not any(p["p"] == "mark" for p in parts)
    # M, the line at infinity: no stroke in the view, said in words; its pole the centre
    assert not any(p["p"] == "path" for p in els["M"]["parts"])
    assert any(p["p"] == "text" and p["text"] == "M at ∞" for p in els["M"]["parts"])
    assert mark(els["pole of M"]) == pytest.approx([0.0, 0.0])
    assert ex.readout_values["pole of M"] == pytest.approx((0.0, 0.0), abs=1e-12)
    assert ex.readout_values["P"] == "at infinity (direction (0.7071, 0.7071))" and "at infinity" in ex.readout_values["P is"]
    # the two tangents in that direction are parallel and touch the circle at ±r along the normal
    for k in (1, 2):
        X = mark(els[f"contact {k}"])
        assert np.hypot(*X) == pytest.approx(1.5, abs=1e-4)
        assert np.dot(X, [1.0, 1.0]) == pytest.approx(0.0, abs=1e-4)
    ex.set(**{"P x": 0.0, "P y": 0.0})                                # no direction: a message
    assert "P x, P y" in ex.message
    ex.set(**{"P at infinity": False})
    assert ex.message == ""


def test_construction_toggle_only_redraws_and_shows_the_current_point(ex):
    ex.set(**{"P x": 2.0, "P y": 1.5})
    n = ex.n_computes
    ex.controls["construction"].value = False
    assert ex.n_computes == n and construction_ids(ex.picture()) == set()
    ex.controls["P x"].value = -2.5                      # moved while the construction is hidden
    ex.controls["construction"].value = True
    assert ex.n_computes == n + 1
    els = elements(ex.picture())
    for k in (1, 2):                                     # tangent points of the moved P
        X = mark(els[f"contact {k}"])
        assert np.hypot(*X) == pytest.approx(1.5, abs=1e-4)
        assert np.dot(X - [-2.5, 1.5], X) == pytest.approx(0.0, abs=1e-4)
    ex.controls["line and its pole"].value = False
    assert ex.n_computes == n + 1 and not {"M", "pole of M"} & set(elements(ex.picture()))


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
    A, B = segment(elements(ex.picture())["M"])          # the drawn M passes the pivot and the pointer
    for Q in (pivot, (tip[0], tip[1] + 0.5)):
        assert cross2(B - A, np.asarray(Q) - A) == pytest.approx(0.0, abs=1e-3)


@pytest.mark.parametrize("P_inf, M_inf", [(False, False), (False, True), (True, False), (True, True)])
def test_the_linear_form_has_a_unit_only_when_it_is_a_distance(P_inf, M_inf):
    """Issue: P·M read "1 m" with M the line at infinity and "−2.23 m" with P at infinity.  ``t = PᵀM``
    (5.40) is the signed distance of P from M only for a finite P = [y, −x, 1] and a finite M = [e, r]
    with |e| = 1 (5.49, 5.55); otherwise it is a number: P's weight 1 (M at infinity), the cross
    product e × d of the directions (P at infinity), 0 (both).  Values by hand, from the sliders."""
    ex = ProjectiveExplorer(display="agg", **{"P at infinity": P_inf, "M at infinity": M_inf,
                                             "P x": 2.0, "P y": 1.5, "line angle (deg)": 100.0,
                                             "line offset": 0.5})
    assert ex.message == ""
    e = np.array([math.cos(math.radians(100.0)), math.sin(math.radians(100.0))])
    n = np.array([-e[1], e[0]])                                  # M's left normal; M is offset 0.5 along it
    d = np.array([2.0, 1.5])
    if not P_inf and not M_inf:
        ref, unit = float(d @ n) - 0.5, "m"           # signed distance of P from M, positive on M's left
    elif not P_inf:
        ref, unit = 1.0, ""
    elif not M_inf:
        ref, unit = cross2(e, d), ""
    else:
        ref, unit = 0.0, ""
    r = ex.readout_values
    assert r["P·M"] == pytest.approx(ref, abs=1e-12) and r["pole(M)·polar(P)"] == pytest.approx(ref, abs=1e-12)
    for k in ("P·M", "pole(M)·polar(P)"):
        text = ex.readout_strings[k]
        assert text.endswith(" m") == (unit == "m"), text
        assert ex.units[k] in (("m",) if unit else ("—", ""))
    meaning = ex.explain()["P·M"]
    assert ("not a distance" in meaning) == (unit == ""), meaning
    assert ("signed distance" in meaning) == (unit == "m"), meaning


def test_the_line_at_infinity_label_is_clear_of_the_lines():
    """Issue: the label of M = the line at infinity was crossed by a dashed tangent (the default P)."""
    from _picture_checks import crossed_labels

    ex = ProjectiveExplorer(display="agg", **{"M at infinity": True})
    assert [c for c in crossed_labels(ex.picture()) if c[0] == "M"] == []
    (text,) = [p["text"] for p in elements(ex.picture())["M"]["parts"] if p["p"] == "text"]
    assert text == "M at ∞"
    assert "line at infinity" in elements(ex.picture())["M"]["desc"]
