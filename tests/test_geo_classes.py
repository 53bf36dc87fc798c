"""Tests of the thin classes Point, Line, Conic (planargeo.geometry.elements)."""
import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from planargeo.errors import DegenerateGeometryError, InputError, NonFiniteError, ShapeError
from planargeo.geometry.elements import Conic, Line, Point
from planargeo.screws.twists import inertia_matrix

coord = st.floats(-10, 10).map(lambda x: round(x, 3))


def test_point_basics_and_repr():
    p = Point.from_xy(1, 2)
    assert repr(p) == "Point(x=1, y=2)"
    assert np.array_equal(p.array, [2.0, -1.0, 1.0])
    assert np.array_equal(Point.from_xy((1, 2)).array, p.array)
    assert np.allclose(p.xy, [1, 2]) and not p.is_ideal
    q = Point.at_infinity((0, 1))
    assert repr(q) == "Point(at infinity, direction=(0, 1))"
    assert q.is_ideal and np.all(np.isnan(q.xy))
    assert repr(Point([0.0, 0.0, -2.0])) == "Point(x=0, y=0)"
    assert Point([4.0, -2.0, 2.0]).normalized().array.tolist() == [2.0, -1.0, 1.0]


def test_point_is_read_only_and_copied():
    a = np.array([1.0, 2.0, 1.0])
    p = Point(a)
    a[0] = 99
    assert p.array[0] == 1.0
    with pytest.raises(ValueError):
        p.array[0] = 5.0


def test_equality_up_to_scale():
    assert Point([2.0, -1.0, 1.0]) == Point([-4.0, 2.0, -2.0])
    assert Point([2.0, -1.0, 1.0]) != Point([2.0, -1.0, 1.1])
    assert Line([1.0, 0.0, 2.0]) == Line([-3.0, 0.0, -6.0])
    assert Conic.circle((0, 0), 1) == Conic(-2 * Conic.circle((0, 0), 1).matrix)
    assert Point([1.0, 0, 0]) != Line([1.0, 0, 0])
    with pytest.raises(TypeError):
        hash(Point([1.0, 0, 0]))


def test_line_constructors_and_repr():
    L = Line.through(Point.from_xy(0, 1), Point.from_xy(2, 1))
    assert repr(L) == "Line(through=(0, 1), direction=(1, 0))"
    assert np.array_equal(L.array, [2.0, 0.0, -2.0])
    assert repr(Line.at_infinity()) == "Line(at infinity)" and Line.at_infinity().is_at_infinity
    assert Line.at_infinity().foot is None
    M = Line.from_point_direction((1, 1), (0, 2))
    assert M == Line([0.0, 1.0, 1.0])                                   # x = 1
    assert Line.from_point_direction(Point.from_xy(1, 1), (0, 2)) == M
    assert np.allclose(M.direction, [0, 1]) and M.foot == Point.from_xy(1, 0)


@given(x1=coord, y1=coord, x2=coord, y2=coord, x3=coord, y3=coord)
def test_join_meet_operators(x1, y1, x2, y2, x3, y3):
    p, q, r = Point.from_xy(x1, y1), Point.from_xy(x2, y2), Point.from_xy(x3, y3)
    if np.hypot(x1 - x2, y1 - y2) < 1e-2 or np.hypot(x1 - x3, y1 - y3) < 1e-2:
        return
    L, M = p ^ q, p.join(r)
    assert abs(p @ L) < 1e-9 and abs(L @ q) < 1e-9
    if abs((x2 - x1) * (y3 - y1) - (y2 - y1) * (x3 - x1)) < 1e-3:
        return
    assert (L ^ M) == p and L.meet(M) == p


def test_distance_and_incidence_sign():
    L = Line([1.0, 0.0, 0.0])          # +x axis
    assert Point.from_xy(3, 2).distance_to(L) == 2.0
    assert L.signed_distance(Point.from_xy(3, -2)) == -2.0
    assert Point.from_xy(5, 0) @ L == 0.0


def test_parallel_lines_meet_at_infinity():
    P = Line([1.0, 0.0, 0.0]) ^ Line([2.0, 0.0, 3.0])
    assert P.is_ideal and P == Point.at_infinity((1, 0))
    assert (Point.at_infinity((1, 0)) ^ Point.at_infinity((0, 1))).is_at_infinity


def test_conic_methods():
    C = Conic.circle((0, 0), 1)
    assert repr(C) == "Conic(real circle, centre=(0, 0))"
    assert C.polar(Point.from_xy(2, 0)) == Line([0.0, 1.0, 0.5])         # x = 1/2
    assert C.pole(Line([0.0, 1.0, 0.5])) == Point.from_xy(2, 0)
    assert C.centre == Point.from_xy(0, 0)
    assert C.contains(Point.from_xy(0.6, 0.8)) and not C.contains(Point.from_xy(0.6, 0.9))
    (t1, t2), (x1, x2) = C.tangents_from(Point.from_xy(2, 0))
    assert abs(t1 @ Point.from_xy(2, 0)) < 1e-12 and abs(x1 @ t1) < 1e-12
    assert sorted([x1.xy[1], x2.xy[1]]) == pytest.approx([-np.sqrt(3) / 2, np.sqrt(3) / 2])
    assert str(Conic.ellipse((1, 2), (3, 1), 0.5).classify()) == "real ellipse"
    assert repr(Conic.hyperbola((1, 2), (1, 1))) == "Conic(real hyperbola, centre=(1, 2))"
    assert repr(Conic.parabola((1, 2), 0.25)) == "Conic(real parabola, vertex=(1, 2), axis=(0, 1))"
    assert repr(Conic.from_coefficients(1, 0, -1, 0, 0, 0)).startswith("Conic(degenerate line pair")
    I = Conic(inertia_matrix(2.0, [1.0, 0.0], 0.5))
    assert repr(I) == "Conic(imaginary circle, centre=(1, 0))"
    assert I.drawable() == Conic.circle((1, 0), 0.5)                       # radius of gyration √(J/m)
    assert Conic.ellipse((0, 0), (2, 1)).affine_frame().kind == "ellipse"


def test_class_bad_input():
    with pytest.raises(ShapeError, match=r"array must have shape \(3,\), got shape \(2, 3\)"):
        Point(np.zeros((2, 3)))
    with pytest.raises(ShapeError, match=r"^array must have shape \(3,\), got shape \(4, 3\)$"):
        Line(np.ones((4, 3)))                                      # single values only (documented)
    with pytest.raises(NonFiniteError, match="array must be finite"):
        Line([np.nan, 0, 1])
    with pytest.raises(DegenerateGeometryError, match="array is the zero vector, which is no point"):
        Point([0, 0, 0])
    with pytest.raises(DegenerateGeometryError, match="array is the zero vector, which is no line"):
        Line([0, 0, 0])
    with pytest.raises(InputError, match="matrix must be symmetric"):
        Conic([[1, 2, 0], [0, 1, 0], [0, 0, 1]])
    with pytest.raises(ShapeError, match=r"matrix must have shape \(3, 3\)"):
        Conic(np.stack([np.eye(3)] * 2))
    with pytest.raises(DegenerateGeometryError, match=r"join\(p, q\): p and q are the same point"):
        Point.from_xy(1, 1) ^ Point([2.0, -2.0, 2.0])
    with pytest.raises(DegenerateGeometryError, match=r"meet\(l, m\): l and m are the same line"):
        Line([1.0, 0, 0]).meet(Line([2.0, 0, 0]))
    with pytest.raises(ShapeError, match="xy must have shape"):
        Point.from_xy((1, 2, 3))
    with pytest.raises(DegenerateGeometryError, match="C is singular"):
        Conic.from_coefficients(1, 0, -1, 0, 0, 0).pole(Line.at_infinity())
    with pytest.raises(InputError, match="p has no real tangents"):
        Conic.circle((0, 0), 1).tangents_from(Point.from_xy(0, 0))
