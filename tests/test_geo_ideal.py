"""Ideal points and the line at infinity are ordinary values: every GEO function takes them silently."""
import warnings

import numpy as np
import pytest

from planargeo.geometry import conics as K
from planargeo.geometry import projective as P
from planargeo.geometry.elements import Conic, Line, Point
from planargeo.screws.twists import inertia_matrix

IDEAL = P.from_direction([1.0, 0.0])            # the point at infinity along x
FINITE = P.from_xy([0.5, -0.25])
LINF = P.LINE_AT_INFINITY


@pytest.fixture(autouse=True)
def _all_warnings_are_errors():
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        yield


def test_projective_functions_take_ideal_elements():
    assert np.array_equal(P.normalize_point(3 * IDEAL), [0.0, -1.0, 0.0])
    assert np.array_equal(P.normalize_line(-2 * LINF), [0.0, 0.0, -1.0])
    assert P.is_ideal(IDEAL) and P.is_at_infinity(LINF)
    assert np.all(np.isnan(P.to_xy(IDEAL)))
    assert np.allclose(P.direction(IDEAL), [1.0, 0.0])
    L = P.join(FINITE, IDEAL)                                # the horizontal line through FINITE
    assert np.allclose(P.normalize_line(L) * np.sign(L[0]), [1.0, 0.0, 0.25])
    assert P.is_at_infinity(P.join(IDEAL, P.from_direction([0.0, 1.0])))
    assert P.is_ideal(P.meet(L, LINF))
    assert P.incidence(IDEAL, LINF) == 0 and P.incidence(IDEAL, L) == 0
    assert np.isnan(P.signed_distance(IDEAL, L)) and np.isinf(P.signed_distance(FINITE, LINF))
    assert P.is_at_infinity(P.pencil(LINF, 2 * LINF, 0.3))
    assert np.array_equal(P.to_standard(LINF), [1.0, 0.0, 0.0])     # (5.16)
    assert np.all(np.isnan(P.foot_point(LINF)))
    assert np.all(np.isnan(P.line_direction(LINF)))


def test_conic_functions_take_ideal_elements():
    E = K.conic_ellipse([1.0, 2.0], [2.0, 1.0], 0.0)
    H = K.conic_hyperbola([0.0, 0.0], [1.0, 1.0])
    I = inertia_matrix(2.0, [1.0, 2.0], 0.5)
    for C in (E, H, I):
        D = K.polar(C, IDEAL)                                # a diameter
        assert abs(P.incidence(K.centre(C), D)) < 1e-12
        assert np.allclose(P.normalize_point(K.pole(C, LINF)), K.centre(C))
        assert K.conic_residual(C, IDEAL).shape == ()
    # tangents from the ideal point along x to the ellipse: y = 2 ± 1, touching at (1, 2 ± 1)
    T, X = K.tangents_from_point(E, IDEAL)
    assert np.allclose(sorted(P.to_xy(X)[:, 1]), [1.0, 3.0]) and np.allclose(P.to_xy(X)[:, 0], 1.0)
    ext = K.polar_construction_exterior(E, IDEAL)
    assert np.allclose(P.normalize_line(ext.polar) * np.sign(ext.polar[1]), [0.0, 1.0, 1.0])   # x = 1
    # the ideal point along x is interior to x² - y² = 1: its polar is the conjugate axis x = 0
    inn = K.polar_construction_interior(H, IDEAL)
    assert np.allclose(np.abs(P.normalize_line(inn.polar)), [0.0, 1.0, 0.0])
    Xi, real = K.line_conic_intersections(H, LINF)
    assert real and np.all(P.is_ideal(Xi))
    assert np.all(K.is_on_conic(H, Xi))
    u = K.decompose_point(FINITE, IDEAL, P.from_direction([0.0, 1.0]), P.from_xy([0.0, 0.0]))
    assert np.allclose(u[0] * IDEAL + u[1] * P.from_direction([0.0, 1.0]) + u[2] * np.array([0, 0, 1.0]), FINITE)
    Q1, Q2, Q3 = K.special_base(E, IDEAL)
    v = K.decompose_point_special(E, FINITE, Q1, Q2, Q3)
    assert np.allclose(v[0] * Q1 + v[1] * Q2 + v[2] * Q3, FINITE)
    assert K.classify(K.drawable_conic(I)).reality == "real"


def test_classes_take_ideal_elements():
    p = Point(IDEAL)
    assert repr(p) == "Point(at infinity, direction=(1, 0))"
    assert (p ^ Point.at_infinity((0, 1))) == Line.at_infinity()
    assert (Line.at_infinity() ^ Line.from_point_direction((0, 0), (1, 0))) == p
    assert Conic.circle((0, 0), 1).polar(p) == Line([0.0, 1.0, 0.0])       # the diameter x = 0
    assert Conic.circle((3, 4), 1).pole(Line.at_infinity()) == Point.from_xy(3, 4)
    assert repr(Conic.from_coefficients(1, 0, 0, 0, -1, 0)) == "Conic(real parabola, vertex=(0, 0), axis=(0, 1))"
    assert Conic.from_coefficients(1, 0, 0, 0, -1, 0).centre == Point.at_infinity((0, 1))
