"""Polygon inertias vs closed forms, composites, and bad input."""
import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays
from shapely.geometry import LineString, MultiPolygon, Point, Polygon, box
from shapely.ops import unary_union

from planargeo.errors import InputError, InvalidPolygonError, NonFiniteError, ShapeError, SingularInertiaError
from planargeo.screws.inertia import Inertia, polygon_moments
from planargeo.screws.twists import inertia_matrix

coord = st.floats(-20, 20, allow_nan=False)


@pytest.mark.parametrize("b,h,x0,y0", [(2.0, 1.0, 0.0, 0.0), (0.3, 5.0, -7.0, 2.0), (1e-2, 1e-2, 100.0, 100.0)])
def test_rectangle_closed_form(b, h, x0, y0):
    A, c, J = polygon_moments(box(x0, y0, x0 + b, y0 + h))
    assert A == pytest.approx(b * h)
    np.testing.assert_allclose(c, [x0 + b / 2, y0 + h / 2])
    # polar moment about the centroid: b h^3/12 + h b^3/12
    assert J == pytest.approx(b * h ** 3 / 12 + h * b ** 3 / 12, rel=1e-9)


@given(arrays(float, (3, 2), elements=coord))
def test_triangle_closed_form(P):
    tri = Polygon(P)
    u, w = P[1] - P[0], P[2] - P[0]
    A_ref = 0.5 * abs(u[0] * w[1] - u[1] * w[0])
    if A_ref < 1e-2 or not tri.is_valid:
        return
    A, c, J = polygon_moments(tri)
    sides2 = sum(np.sum((P[i] - P[(i + 1) % 3]) ** 2) for i in range(3))
    assert A == pytest.approx(A_ref, rel=1e-9)
    np.testing.assert_allclose(c, P.mean(axis=0), atol=1e-9 * 40)
    assert J == pytest.approx(A_ref * sides2 / 36, rel=1e-7)      # J_c = A (a² + b² + c²) / 36


def test_square_with_square_hole_exact():
    a, b = 4.0, 2.0
    g = Polygon(box(-a / 2, -a / 2, a / 2, a / 2).exterior.coords, [box(-b / 2, -b / 2, b / 2, b / 2).exterior.coords])
    A, c, J = polygon_moments(g)
    assert A == pytest.approx(a * a - b * b)
    np.testing.assert_allclose(c, [0.0, 0.0], atol=1e-12)
    assert J == pytest.approx((a ** 4 - b ** 4) / 6)            # square: a^4/6


def test_circular_annulus():
    R, r = 2.0, 1.2
    g = Point(1.0, -1.0).buffer(R, quad_segs=256).difference(Point(1.0, -1.0).buffer(r, quad_segs=256))
    I = Inertia.from_polygon(g, density=2.0)
    m = 2.0 * np.pi * (R * R - r * r)
    assert float(I.mass) == pytest.approx(m, rel=1e-4)
    np.testing.assert_allclose(I.com, [1.0, -1.0], atol=1e-9)
    assert float(I.rotational_inertia) == pytest.approx(2.0 * np.pi * (R ** 4 - r ** 4) / 2, rel=2e-4)
    assert float(I.radius_of_gyration) == pytest.approx(np.sqrt((R * R + r * r) / 2), rel=1e-4)


def test_offset_hole_equals_solid_minus_hole():
    outer = box(0.0, 0.0, 6.0, 3.0)
    hole = box(4.0, 0.5, 5.0, 2.0)
    I = Inertia.from_polygon(outer.difference(hole), density=1.5)
    # independent: rectangles as closed forms, hole as negative mass
    def rect(x0, y0, x1, y1):
        b, h = x1 - x0, y1 - y0
        return inertia_matrix(1.5 * b * h, [(x0 + x1) / 2, (y0 + y1) / 2], 1.5 * b * h * (b * b + h * h) / 12)
    ref = rect(0, 0, 6, 3) - rect(4, 0.5, 5, 2)
    np.testing.assert_allclose(I.matrix, ref, rtol=1e-12, atol=1e-12)


def test_union_of_disjoint_squares_equals_composite():
    s1, s2 = box(0, 0, 1, 1), box(3, 2, 5, 4)
    union = unary_union([s1, s2])
    assert isinstance(union, MultiPolygon)
    I_union = Inertia.from_polygon(union, density=2.0)
    I_comp = Inertia.composite([Inertia.from_polygon(s1, 2.0), Inertia.from_polygon(s2, 2.0)])
    np.testing.assert_allclose(I_union.matrix, I_comp.matrix, rtol=1e-12)
    np.testing.assert_allclose((Inertia.from_polygon(s1, 2.0) + Inertia.from_polygon(s2, 2.0)).matrix, I_comp.matrix)
    # closed form: masses 2 and 8 at (0.5, 0.5) and (4, 3)
    m1, m2 = 2.0, 8.0
    c = (m1 * np.array([0.5, 0.5]) + m2 * np.array([4.0, 3.0])) / (m1 + m2)
    J = m1 / 6 + m2 * 8 / 12 + m1 * np.sum((c - [0.5, 0.5]) ** 2) + m2 * np.sum((c - [4.0, 3.0]) ** 2)
    assert float(I_union.mass) == pytest.approx(10.0)
    np.testing.assert_allclose(I_union.com, c)
    assert float(I_union.rotational_inertia) == pytest.approx(J)


def test_composite_of_touching_pieces_equals_polygon_of_union():
    a, b = box(0, 0, 2, 1), Polygon([(2, 0), (3, 0), (2, 1)])
    u = unary_union([a, b])
    np.testing.assert_allclose(Inertia.from_polygon(u).matrix,
                               Inertia.composite([Inertia.from_polygon(a), Inertia.from_polygon(b)]).matrix,
                               rtol=1e-12, atol=1e-12)


def test_agrees_with_shapely_area_and_centroid():
    g = Polygon([(0, 0), (4, 0), (5, 3), (2, 5), (-1, 2)], [[(1, 1), (2, 1), (2, 2), (1, 2)]])
    A, c, _ = polygon_moments(g)
    assert A == pytest.approx(g.area)
    np.testing.assert_allclose(c, [g.centroid.x, g.centroid.y])
    # clockwise input orientation gives the same answer
    A2, c2, J2 = polygon_moments(Polygon(list(g.exterior.coords)[::-1], [list(g.interiors[0].coords)[::-1]]))
    assert A2 == pytest.approx(A) and np.allclose(c2, c) and J2 == pytest.approx(_)


# ------------------------------------------------------------------ bad input
def test_bow_tie_invalid():
    with pytest.raises(InvalidPolygonError, match=r"geometry must be a valid polygon: Self-intersection"):
        Inertia.from_polygon(Polygon([(0, 0), (1, 1), (1, 0), (0, 1)]))


def test_non_area_and_empty():
    with pytest.raises(InvalidPolygonError, match="geometry must be a shapely Polygon or MultiPolygon, got LineString"):
        Inertia.from_polygon(LineString([(0, 0), (1, 1)]))
    with pytest.raises(InvalidPolygonError, match="geometry must be a shapely Polygon or MultiPolygon, got list"):
        Inertia.from_polygon([(0, 0), (1, 0), (0, 1)])
    with pytest.raises(InvalidPolygonError, match="geometry must be non-empty"):
        Inertia.from_polygon(Polygon())
    with pytest.raises(InvalidPolygonError, match="geometry must be a valid polygon"):
        Inertia.from_polygon(Polygon([(0, 0), (1, 0), (2, 0)]))          # zero area
    assert issubclass(InvalidPolygonError, InputError)


def test_bad_density():
    with pytest.raises(InputError, match="density must be positive"):
        Inertia.from_polygon(box(0, 0, 1, 1), density=0.0)
    with pytest.raises(NonFiniteError, match="density must be finite"):
        Inertia.from_polygon(box(0, 0, 1, 1), density=np.nan)
    with pytest.raises(ShapeError, match="density must be a scalar"):
        Inertia.from_polygon(box(0, 0, 1, 1), density=[1.0, 2.0])


def test_bad_mass_and_matrices():
    with pytest.raises(InputError, match="mass must be positive, got -1.0"):
        Inertia.from_mass(-1.0, [0, 0], radius_of_gyration=1.0)
    with pytest.raises(InputError, match="mass must be positive, got 0.0"):
        Inertia.from_mass(0.0, [0, 0], inertia=1.0)
    with pytest.raises(InputError, match="radius_of_gyration must be positive"):
        Inertia.from_mass(1.0, [0, 0], radius_of_gyration=0.0)
    with pytest.raises(InputError, match="inertia must be positive"):
        Inertia.from_mass(1.0, [0, 0], inertia=-2.0)
    with pytest.raises(InputError, match="exactly one of radius_of_gyration or inertia"):
        Inertia.from_mass(1.0, [0, 0])
    with pytest.raises(InputError, match="exactly one of radius_of_gyration or inertia"):
        Inertia.from_mass(1.0, [0, 0], radius_of_gyration=1.0, inertia=1.0)
    with pytest.raises(ShapeError, match="com must have shape"):
        Inertia.from_mass(1.0, [0, 0, 0], inertia=1.0)
    with pytest.raises(NonFiniteError, match="com must be finite"):
        Inertia.from_mass(1.0, [0, np.inf], inertia=1.0)
    with pytest.raises(InputError, match="matrix must be symmetric"):
        Inertia([[1.0, 0, 0], [0, 1.0, 0.5], [0, 0, 1.0]])
    with pytest.raises(SingularInertiaError, match="matrix must be positive definite") as exc:
        Inertia([[1.0, 0, 0], [0, 1.0, 2.0], [0, 2.0, 1.0]])          # indefinite
    assert exc.value.cond == np.inf
    with pytest.raises(SingularInertiaError, match="matrix must be positive definite"):
        Inertia(inertia_matrix(1.0, [1.0, 2.0], 0.0))                  # point mass: singular
    with pytest.raises(InputError, match="matrix must have a positive mass"):
        Inertia(-np.eye(3))
    with pytest.raises(ShapeError, match="matrix must have shape"):
        Inertia(np.eye(2))
    with pytest.raises(NonFiniteError, match="matrix must be finite"):
        Inertia(np.full((3, 3), np.nan))
    with pytest.raises(InputError, match="parts must contain at least one inertia"):
        Inertia.composite([])
    with pytest.raises(ShapeError, match=r"parts\[1\] must have shape"):
        Inertia.composite([np.eye(3), np.eye(2)])
