"""Finite in, finite out, or a named error: the geometry's defects of issue 16 (items 4-6), one test each.

The expected values are worked out by hand (in the comments) for points and lines whose
coordinates are near the ends of double precision's range, where rescaling by powers of two
must not change the answer.
"""
from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

import planargeo as pg
from planargeo.errors import DegenerateGeometryError, InputError, NumericOverflowError, ShapeError
from planargeo.geometry import conics as C
from planargeo.geometry import projective as P

R2 = np.sqrt(0.5)


def test_join_of_huge_points_is_a_finite_line():
    """(1e300, 0) and (0, 1e300): the line x + y = 1e300, directed from the first to the second,
    i.e. unit force (-1, 1)/√2 and moment tz = x fy - y fx = 1e300/√2 at (1e300, 0).  Was [-inf...]."""
    l = P.join(P.from_xy([1e300, 0.0]), P.from_xy([0.0, 1e300]))
    assert np.all(np.isfinite(l))
    np.testing.assert_allclose(P.normalize_line(l), [-R2, R2, 1e300 * R2], rtol=1e-15)
    # batches take the same path: the same line, and a distinct tiny pair does not underflow to "the same point"
    lb = P.join([P.from_xy([1e300, 0.0])] * 2, [P.from_xy([0.0, 1e300])] * 2)
    np.testing.assert_allclose(P.normalize_line(lb), [[-R2, R2, 1e300 * R2]] * 2, rtol=1e-15)
    # (0, 1) and (-1, 0): direction (-1, -1)/√2, tz = x fy - y fx = 1/√2 at (0, 1)
    tiny = P.join([1e-200, 0.0, 1e-200], [0.0, 1e-200, 1e-200])
    np.testing.assert_allclose(P.normalize_line(tiny), [-R2, -R2, R2], rtol=1e-15)


def test_meet_of_huge_lines_is_a_finite_point():
    """1e300 times the x axis [1, 0, 0] and 1e300 times x = -3 ([0, 1, -3]) meet at (-3, 0)."""
    p = P.meet(1e300 * np.array([1.0, 0.0, 0.0]), 1e300 * np.array([0.0, 1.0, -3.0]))
    np.testing.assert_allclose(P.to_xy(p), [-3.0, 0.0], rtol=1e-15)
    # far lines whose 3-vectors are nearly parallel are refused by κ, as near ones are
    with pytest.raises(DegenerateGeometryError, match="condition number 7.07e"):
        P.meet([0.0, 1.0, 1e300], [-1.0, 0.0, 1e300])


def test_zero_vector_is_no_point_and_no_line():
    """to_xy([0, 0, 0]) was [nan, nan]; signed_distance(p, [0, 0, 0]) was nan."""
    with pytest.raises(DegenerateGeometryError, match="p is the zero vector, which is no point"):
        P.to_xy([0.0, 0.0, 0.0])
    with pytest.raises(DegenerateGeometryError, match="l is the zero vector, which is no line"):
        P.signed_distance(P.from_xy([1.0, 2.0]), [0.0, 0.0, 0.0])
    with pytest.raises(DegenerateGeometryError, match=r"p is the zero vector at index \(1,\)"):
        P.to_xy([[0.0, 0.0, 1.0], [0.0, 0.0, 0.0]])
    for f in (P.direction, P.normalize_point):
        with pytest.raises(DegenerateGeometryError):
            f([0.0, 0.0, 0.0])
    for f in (P.line_direction, P.foot_point, P.normalize_line):
        with pytest.raises(DegenerateGeometryError):
            f([0.0, 0.0, 0.0])
    # points and lines at infinity stay ordinary values with their documented NaN / inf
    assert np.all(np.isnan(P.to_xy([1.0, 0.0, 0.0])))
    assert float(P.signed_distance([1.0, 0.0, 0.0], [1.0, 0.0, 0.0])) == np.inf


def test_signed_distance_rescales_instead_of_overflowing():
    """p = [0, 1e300, 1e300] is (-1, 0); l = [1e160, 0, 1e160] is y = -1 directed along +x: distance +1.
    p @ l = 1e460 overflowed before."""
    assert float(P.signed_distance([0.0, 1e300, 1e300], [1e160, 0.0, 1e160])) == 1.0
    # (1e-160, 1e300) from 9.7 x + 1.4e-45 y = 1e160: (1.4e-45 · 1e300 + 9.7e-160 - 1e160) / 9.7 (was inf)
    d = float(P.signed_distance(P.from_xy([1e-160, 1e300]), [1.4e-45, -9.7, -1e160]))
    assert d == pytest.approx((1.4e-45 * 1e300 - 1e160) / 9.7, rel=1e-14)
    # x = 1e310 ([0, -1e300, 1e-10]) from the y axis: a distance past 1e308 is refused by name
    with pytest.raises(NumericOverflowError, match="signed_distance"):
        P.signed_distance([0.0, -1e300, 1e-10], [0.0, 1.0, 0.0])


@pytest.mark.parametrize("call, match", [
    (lambda: P.to_xy([1e300, 0.0, 1e-300]), "to_xy"),                       # x = 1e600
    (lambda: P.incidence([1e300, 0.0, 1.0], [1e300, 0.0, 0.0]), "incidence"),
    (lambda: P.normalize_line([1.6e-43, 0.0, 1e300]), "normalize_line"),     # a line 6e342 away
    (lambda: P.foot_point([0.0, 3.7e-289, 1e200]), "foot_point"),            # was [nan, nan, nan]
    (lambda: P.pencil([1e300, 0.0, 0.0], [-1e300, 0.0, 0.0], 1e10), "pencil"),
])
def test_results_beyond_double_precision_are_named(call, match):
    with pytest.raises(NumericOverflowError, match=match):
        call()


def test_line_direction_of_tiny_forces():
    """The force (8e-271, 8e-271) of a line 1e200 away points along (1, 1)/√2 (was NaN after scaling)."""
    np.testing.assert_allclose(P.line_direction([7.98e-271, 7.98e-271, -1e200]), [R2, R2], rtol=1e-15)


@pytest.mark.parametrize("call", [
    lambda: P.meet(np.zeros((2, 3)) + [1.0, 0.0, 0.0], np.zeros((3, 3)) + [0.0, 1.0, 0.0]),
    lambda: P.join(np.zeros((2, 3)) + [0.0, 0.0, 1.0], np.zeros((3, 3)) + [0.0, 1.0, 1.0]),
    lambda: P.pencil(np.zeros((2, 3)), np.zeros((3, 3)), 0.5),
    lambda: P.pencil(np.ones((3, 3)), [0.0, 1.0, 0.0], [0.1, 0.2]),
    lambda: P.incidence(np.zeros((2, 3)), np.zeros((3, 3))),
    lambda: P.cross_cond(np.ones((2, 3)), np.ones((4, 3))),
])
def test_mismatched_batches_are_a_shape_error(call):
    """meet and pencil leaked numpy's broadcasting ValueError."""
    with pytest.raises(ShapeError, match="batch shapes do not broadcast"):
        call()


@pytest.mark.parametrize("make", [
    lambda: pg.Point(np.array([1.0, 2.0, 1.0 + 1e-3j])),
    lambda: pg.Line([1j, 0.0, 1.0]),
    lambda: P.join(np.array([1.0, 0.0, 1.0], complex), [0.0, 1.0, 1.0]),
    lambda: C.polar(np.eye(3) + 0j, [1.0, 0.0, 1.0]),
])
def test_complex_input_is_refused(make):
    """Complex arrays lost their imaginary part with only a numpy warning."""
    with pytest.raises(InputError, match="must be real, got complex values"):
        make()


def test_cond_limit_is_validated():
    with pytest.raises(InputError, match="cond_limit must be numeric"):
        P.meet([1.0, 0.0, 0.0], [0.0, 1.0, 0.0], cond_limit="big")
    with pytest.raises(InputError, match="cond_limit must be positive"):
        P.join([1.0, 0.0, 1.0], [0.0, 1.0, 1.0], cond_limit=-1.0)


exps = st.integers(-300, 300)


@given(st.tuples(st.floats(-1, 1), st.floats(-1, 1), st.floats(0.1, 1)), exps,
       st.tuples(st.floats(-1, 1), st.floats(-1, 1), st.floats(0.1, 1)), exps)
def test_join_is_scale_invariant_over_the_whole_range(p, ep, q, eq):
    """Homogeneous scaling by 10^e (any e in ±300) never changes the normalised join."""
    p, q = np.array(p), np.array(q)
    try:
        ref = P.normalize_line(P.join(p, q))
    except DegenerateGeometryError:
        return
    got = P.normalize_line(P.join(p * 10.0 ** ep, q * 10.0 ** eq))
    np.testing.assert_allclose(got, ref, rtol=1e-12, atol=1e-12 * np.abs(ref).max())


# --------------------------------------------------------------------------- conics
def test_tangents_from_a_point_to_a_degenerate_conic_are_refused():
    """diag(1, 0, 0) is the double line y = 0 ([y, -x, w]: y² = 0); from the ideal point in direction x its
    polar is that line itself, which lies on the conic: the tangents were NaN points, now a named error."""
    with pytest.raises(DegenerateGeometryError, match="lies on the degenerate conic"):
        C.tangents_from_point(np.diag([1.0, 0.0, 0.0]), [7.8, 0.7, 0.0])
    # the point conic x² + y² = 0 (the origin): from an ideal point the only contact is the vertex
    with pytest.raises(DegenerateGeometryError, match="vertex of the degenerate conic"):
        C.tangents_from_point(np.diag([1.0, 1.0, 0.0]), [0.58, 1.0, 0.0])
    # a line on a line pair has every point in common with it
    with pytest.raises(DegenerateGeometryError, match="lies on the degenerate conic"):
        C.line_conic_intersections(np.diag([1.0, -1.0, 0.0]), [1.0, 1.0, 0.0])
    with pytest.raises(DegenerateGeometryError, match="l is the zero vector"):
        C.line_conic_intersections(C.conic_circle([0.0, 0.0], 1.0), [0.0, 0.0, 0.0])


def test_polar_and_pole_of_an_inertia_keep_their_scale_near_the_range_limits():
    """polar(I, a) = I a is a wrench and pole(I, f) = I⁻¹ f an acceleration: the scale matters, so a
    rescaled evaluation must scale back exactly.  For I = diag(1e200, 1e200, 1e200) and a = [1e100, 0, 1e100]
    the plain I a is fine; I = 1e300 I₃ and a = 1e-200 [1, 2, 3] multiply to 1e100 [1, 2, 3]."""
    I = 1e300 * np.eye(3)
    np.testing.assert_allclose(C.polar(I, 1e-200 * np.array([1.0, 2.0, 3.0])), 1e100 * np.array([1.0, 2.0, 3.0]),
                               rtol=1e-15)
    np.testing.assert_allclose(C.pole(I, 1e100 * np.array([1.0, 2.0, 3.0])), 1e-200 * np.array([1.0, 2.0, 3.0]),
                               rtol=1e-15)
    # p C p for the unit circle and the ideal point [1e300, 0, 0]: 1e600, beyond double precision
    with pytest.raises(NumericOverflowError, match="conic_residual"):
        C.conic_residual(np.diag([1.0, 1.0, -1.0]), [1e300, 0.0, 0.0])


def test_centre_of_a_huge_conic():
    """The circle of radius 1e150 about (1e150, 0) scaled by 1e-300 (entries from 1e-300 to 1e0) has its
    centre at (1e150, 0); the same circle's matrix times 1e300 too (C[0] × C[1] overflowed to NaN)."""
    K = C.conic_circle([1e100, 2e100], 1e100)
    for scale in (1.0, 1e-200, 1e100):
        np.testing.assert_allclose(P.to_xy(C.centre(K * scale)), [1e100, 2e100], rtol=1e-15)


def test_conic_constructors_beyond_range_are_named():
    with pytest.raises(NumericOverflowError, match="conic_circle"):
        C.conic_circle([0.0, 0.0], 1e200)                 # r² = 1e400
    with pytest.raises(NumericOverflowError, match="conic_parabola"):
        C.conic_parabola([0.0, 0.0], 5e-324)              # 1/(4f) overflows
    with pytest.raises(InputError, match="imaginary must be True or False"):
        C.conic_circle([0.0, 0.0], 1.0, imaginary=[])


@pytest.mark.parametrize("call", [
    lambda: C.pole(np.eye(3), [1.0, 0.0, 0.0], rtol=-1.0),
    lambda: C.classify(np.eye(3), rtol={"a": 1}),
    lambda: C.affine_frame(C.conic_parabola([0.0, 0.0], 1.0), rtol=-np.inf),
    lambda: C.decompose_point([1.0, 2.0, 3.0], [1.0, 0, 0], [0, 1.0, 0], [1.0, 1.0, 1.0], rtol="x"),
])
def test_tolerances_are_validated(call):
    """A negative, infinite or non-numeric rtol leaked TypeError / LinAlgError."""
    with pytest.raises(InputError, match="rtol must be"):
        call()


def test_a_base_that_is_not_special_is_refused():
    """Q1 on the conic: Q1 C Q1 = 0 divided by zero (inf and a numpy warning)."""
    K = C.conic_circle([0.0, 0.0], 1.0)
    on = P.from_xy([1.0, 0.0])
    with pytest.raises(DegenerateGeometryError, match="Q1 C Q1 = 0"):
        C.decompose_point_special(K, [0.0, 0.0, 1.0], on, P.from_xy([0.0, 1.0]), P.from_xy([0.0, -1.0]))
