"""Tests of planargeo.draw.polars: the drawn elements of the pole/polar, percussion and power
constructions against hand-computed geometry (circles, closed forms of 5.36, 5.68, 5.71)."""
from __future__ import annotations

import math
import warnings

import matplotlib

matplotlib.use("Agg")
import numpy as np  # noqa: E402
import pytest  # noqa: E402
from hypothesis import given, settings, strategies as st  # noqa: E402

from planargeo.draw.picture import Picture  # noqa: E402
from planargeo.draw.polars import (line_conic_points, percussion, polar_exterior,  # noqa: E402
                                   polar_interior, power, power_values)
from planargeo.draw.render import figure  # noqa: E402
from planargeo.errors import InputError  # noqa: E402
from planargeo.geometry.projective import is_ideal  # noqa: E402
from planargeo.screws.twists import inertia_matrix, unit_rotation  # noqa: E402


def _pic(r=4.0):
    return Picture((-r, r, -r, r), size=(400, 400), ticks=False)


def _circle(c, r):
    """x² + y² − 2 c·x + |c|² − r² = 0 in the package's point coordinates p = [y, −x, 1]."""
    cx, cy = c
    # p = [y, -x, 1]: x = -p1, y = p0
    return np.array([[1.0, 0.0, -cy],
                     [0.0, 1.0, cx],
                     [-cy, cx, cx * cx + cy * cy - r * r]])


def _pt(xy):
    return np.array([xy[1], -xy[0], 1.0])


def _path(el):
    return np.asarray(next(p["xy"] for p in el["parts"] if p["p"] == "path"), float)


def _marks(el):
    return np.array([[p["x"], p["y"]] for p in el["parts"] if p["p"] == "mark"])


def _collinear(a, b, q, tol=1e-9):
    """q lies on the line through a and b."""
    d = b - a
    return abs(d[0] * (q[1] - a[1]) - d[1] * (q[0] - a[0])) <= tol * math.hypot(*d)


def _on_line(l, xy, tol=1e-9):
    """The point xy satisfies the line [fx, fy, τ]: τ + y fx − x fy = 0 (4.27)."""
    return abs(l[2] + xy[1] * l[0] - xy[0] * l[1]) <= tol * math.hypot(l[0], l[1])


def _explained(pic):
    for el in pic.elements:
        assert el["id"] and el["role"] and el["symbol"], el["id"]
        assert el["desc"] and "\n" not in el["desc"] and "(" in el["desc"], (el["id"], el["desc"])


def _renders(pic):
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        fig = figure(pic.to_dict())
        fig.canvas.draw()


def test_the_circle_helper_is_a_circle():
    C = _circle((0.3, -0.2), 1.0)
    assert abs(_pt((1.3, -0.2)) @ C @ _pt((1.3, -0.2))) < 1e-12
    assert abs(_pt((0.3, 0.8)) @ C @ _pt((0.3, 0.8))) < 1e-12


@settings(max_examples=30, deadline=None)
@given(st.floats(1.2, 3.0), st.floats(0, 2 * np.pi))
def test_polar_exterior_construction(d, th):
    c, r = np.array([0.3, -0.2]), 1.0
    u = np.array([np.cos(th), np.sin(th)])
    pxy = c + d * u
    pic = _pic()
    out = polar_exterior(pic, _circle(c, r), _pt(pxy))
    # the polar of a circle: perpendicular to c->p at distance r²/d from c (same side)
    for X in _path(out["L"]):
        assert (X - c) @ u == pytest.approx(r * r / d, abs=1e-9)
    # the tangent contacts, by hand: r²/d along u, ± r √(1 − r²/d²) across
    n = np.array([-u[1], u[0]])
    h = r * math.sqrt(1 - (r / d) ** 2)
    hand = [c + r * r / d * u + s * h * n for s in (1, -1)]
    got = _marks(out["contacts"])
    assert len(got) == 2
    for q in hand:
        assert min(np.hypot(*(got - q).T)) < 1e-9
    # each tangent passes through P and touches the circle at its contact
    for t, q in zip(out["tangents"], got):
        a, b = _path(t)
        assert _collinear(a, b, pxy) and _collinear(a, b, q)
    assert [m["x"] for m in out["P"]["parts"] if m["p"] == "mark"] == pytest.approx([pxy[0]])
    _explained(pic)


def test_polar_exterior_renders_with_its_label():
    pic = _pic()
    polar_exterior(pic, _circle((0.0, 0.0), 1.0), _pt((2.0, 1.0)), L_anchor=(0.5, 0.0))
    d = pic.to_dict()
    texts = [p["text"] for e in d["elements"] for p in e["parts"] if p["p"] == "text"]
    assert {"C", "P", "L = CP"} <= set(texts)
    _renders(pic)


def test_polar_interior_construction():
    r, pxy, angles = 2.0, np.array([1.0, 0.0]), (0.7, 2.0)
    pic = _pic(6.0)
    out = polar_interior(pic, _circle((0.0, 0.0), r), _pt(pxy), angles=angles)
    for X in _path(out["L"]):
        assert X[0] == pytest.approx(r * r / 1.0, abs=1e-9)          # x = r²/d = 4
    # the pole of the chord through (1, 0) at angle t: r² n / (n·p) with n = (sin t, −cos t)
    for k, t in enumerate(angles):
        R = _marks(out[f"R{k + 1}"])
        np.testing.assert_allclose(R[0], [4.0, -4.0 / math.tan(t)], atol=1e-9)
        a, b = _path(out["chords"][k])
        assert _collinear(a, b, pxy)
    ends = _marks(out["chord_points"])
    assert len(ends) == 4
    np.testing.assert_allclose(np.hypot(*ends.T), r, atol=1e-9)       # on the circle
    for k in range(2):   # the tangents at the ends of chord k meet at R_k
        R = _marks(out[f"R{k + 1}"])[0]
        for j in range(2):
            a, b = _path(out["tangents"][2 * k + j])
            assert _collinear(a, b, R) and _collinear(a, b, ends[2 * k + j])
    assert line_conic_points(_circle((0.0, 0.0), r), [1.0, 0.0, -5.0]) == []   # y = 5 misses
    _explained(pic)
    _renders(pic)


def test_polar_interior_diameter_has_its_pole_at_infinity():
    # the chord along the x axis through (1, 0) is a diameter: its pole is the ideal point of the
    # vertical direction, drawn as an arrow at the edge along it; the polar x = 4 is vertical too
    pic = _pic(6.0)
    out = polar_interior(pic, _circle((0.0, 0.0), 2.0), _pt((1.0, 0.0)), angles=(0.0, 2.0))
    assert bool(is_ideal(out["construction"].poles[0]))
    arrow = next(p for p in out["R1"]["parts"] if p["p"] == "arrow")
    assert arrow["dx"] == pytest.approx(0.0, abs=1e-9) and abs(arrow["dy"]) > 10
    assert not _marks(out["R1"]).size
    assert "infinity" in out["R1"]["desc"]
    for X in _path(out["L"]):
        assert X[0] == pytest.approx(4.0, abs=1e-9)
    _renders(pic)


def test_percussion_distance():
    # thesis 5.67-5.68: the axis at r = ρ²/d beyond the centre of mass
    m, c, rho, d = 2.0, np.array([1.0, 0.5]), 0.6, 1.5
    I = inertia_matrix(m, c, m * rho * rho)
    axy = c - [d, 0.0]
    pic = _pic()
    out = percussion(pic, I, _pt(axy))
    x_axis = c[0] + rho * rho / d
    for X in _path(out["f"]):
        assert X[0] == pytest.approx(x_axis, abs=1e-12)                # a vertical axis at ρ²/d
    np.testing.assert_allclose(_path(out["lever"]), [axy, [x_axis, c[1]]], atol=1e-12)
    dd, dr = out["dims"]
    np.testing.assert_allclose(_path(dd), [axy, c], atol=1e-12)
    np.testing.assert_allclose(_path(dr), [c, [x_axis, c[1]]], atol=1e-12)
    assert "0.24 m" in dr["desc"] and "1.5 m" in dd["desc"]
    _explained(pic)
    _renders(pic)


def test_percussion_pole_at_infinity_has_an_axis_through_the_centre_of_mass():
    m, c = 2.0, np.array([1.0, 0.5])
    I = inertia_matrix(m, c, m * 0.36)
    pic = _pic()
    out = percussion(pic, I, np.array([1.0, 0.0, 0.0]))                # a translation along x
    a, b = _path(out["f"])
    assert _collinear(a, b, c)
    assert "lever" not in out and "dims" not in out
    assert any(p["p"] == "arrow" for p in out["a"]["parts"])           # the pole at the edge


def _momentum_closed_form(m, c, J, Q, w):
    """p = I v by hand: force m v_c (v_c = w × (c − Q)), moment about O = J w + (c × m v_c)_z."""
    vc = w * np.array([-(c[1] - Q[1]), c[0] - Q[0]])
    F = m * vc
    return np.array([F[0], F[1], J * w + c[0] * F[1] - c[1] * F[0]])


def test_power_relations():
    # thesis 5.69-5.74: f through the pole of v (vᵀf = 0), a on the momentum line (pᵀa = 0)
    m, c, J, Q, w = 1.5, np.array([0.5, 0.2]), 0.4, np.array([1.0, -0.3]), 1.2
    pic = _pic()
    out = power(pic, w * unit_rotation(Q), inertia_matrix(m, c, J))
    p = _momentum_closed_form(m, c, J, Q, w)
    np.testing.assert_allclose(out["values"]["p"], p, rtol=1e-12)
    for X in _path(out["p"]):                                           # the drawn momentum line
        assert _on_line(p, X)
    a, b = _path(out["f"])
    assert _collinear(a, b, Q)                                          # f passes through v's pole
    (axy,) = _marks(out["a"])
    assert _on_line(p, axy)                                             # a lies on p
    np.testing.assert_allclose(_marks(out["v"])[0], Q, atol=1e-12)
    _explained(pic)
    _renders(pic)


def test_power_velocity_at_centre_of_mass_is_a_couple():
    # v at the centre of mass: p = I v = [0, 0, J w], the line at infinity (a pure couple);
    # a powerless acceleration is then a translation (an ideal point)
    m, J, w = 2.0, 0.5, 1.5
    I = inertia_matrix(m, [0.0, 0.0], J)
    pic = _pic()
    out = power(pic, w * unit_rotation([0.0, 0.0]), I)
    np.testing.assert_allclose(out["values"]["p"], [0.0, 0.0, J * w], atol=1e-12)
    assert bool(is_ideal(out["values"]["a"]))
    assert [q["p"] for q in out["p"]["parts"]][:1] == ["glyph"]         # the couple glyph
    assert any(q["p"] == "arrow" for q in out["a"]["parts"]) and not _marks(out["a"]).size
    a, b = _path(out["f"])
    assert _collinear(a, b, np.zeros(2))                                # f through v's pole
    _renders(pic)


def test_power_translation_velocity():
    # v a translation (ideal point): p = m u through the centre of mass; f is the line through
    # the centre of mass across u (a force across the velocity has no power, vᵀf = 0)
    m, c, J, u = 2.0, np.array([0.3, -0.4]), 0.5, np.array([1.0, 2.0])
    v = np.array([u[0], u[1], 0.0])
    pic = _pic()
    out = power(pic, v, inertia_matrix(m, c, J))
    p = np.array([m * u[0], m * u[1], m * (c[0] * u[1] - c[1] * u[0])])
    np.testing.assert_allclose(out["values"]["p"], p)
    for X in _path(out["p"]):
        assert _on_line(p, X)
    a, b = _path(out["f"])
    assert _collinear(a, b, c) and abs((b - a) @ u) < 1e-9 * math.hypot(*(b - a))
    (axy,) = _marks(out["a"])
    assert _on_line(p, axy)
    assert "translation" in out["v"]["desc"]
    _renders(pic)


def test_bad_input_is_refused_by_name():
    C = _circle((0.0, 0.0), 1.0)
    with pytest.raises(InputError, match="inside the conic"):
        polar_exterior(_pic(), C, _pt((0.2, 0.0)))
    with pytest.raises(InputError, match="pic"):
        polar_exterior(None, C, _pt((2.0, 0.0)))
    with pytest.raises(InputError, match="p"):
        polar_exterior(_pic(), C, [np.nan, 0.0, 1.0])
    with pytest.raises(InputError, match="lines\\[0\\]"):            # p outside: a chord misses
        polar_interior(_pic(), C, _pt((3.0, 0.0)), angles=(1.5, 2.0))
    with pytest.raises(InputError, match="angles"):
        polar_interior(_pic(), C, _pt((0.2, 0.0)), angles=(0.3,))
    with pytest.raises(InputError, match="infinity"):
        polar_interior(_pic(), C, [1.0, 0.0, 0.0])
    with pytest.raises(InputError, match="inertia"):
        percussion(_pic(), np.ones((2, 2)), _pt((0.0, 0.0)))
    with pytest.raises(InputError, match="f_angle"):
        power_values(unit_rotation([1.0, 0.0]), inertia_matrix(1.0, [0.0, 0.0], 0.5), f_angle=np.nan)
    # nothing was added by a refused call
    pic = _pic()
    with pytest.raises(InputError):
        polar_exterior(pic, C, _pt((0.2, 0.0)))
    assert pic.elements == []
