"""Tests of planargeo.geometry.projective against hand-derived references (thesis 5.1-5.34, 5.47-5.60)."""
import warnings

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from planargeo.errors import COND_LIMIT, DegenerateGeometryError, NonFiniteError, ShapeError, InputError
from planargeo.geometry.projective import (
    LINE_AT_INFINITY, T_STD, cross_cond, conic_from_standard, conic_to_standard, direction, foot_point,
    from_direction, from_standard, from_xy, incidence, is_at_infinity, is_ideal, join,
    line_direction, line_through_point_direction, meet, normalize, normalize_line,
    normalize_point, pencil, signed_distance, to_standard, to_xy,
)

coord = st.floats(-10, 10, allow_nan=False, allow_infinity=False).map(lambda x: round(x, 4))
xy = st.tuples(coord, coord).map(np.array)
angle = st.floats(-np.pi, np.pi)
vec3 = st.tuples(coord, coord, coord).map(np.array).filter(lambda v: np.linalg.norm(v) > 1e-2)


def same_up_to_scale(a, b, tol=1e-9):
    a, b = np.asarray(a, float), np.asarray(b, float)
    return np.linalg.norm(np.cross(a, b)) <= tol * max(np.linalg.norm(a) * np.linalg.norm(b), 1e-300)


# ----------------------------------------------------------------------------- coordinates
def test_T_is_proper_rotation_and_involution():
    assert np.allclose(T_STD @ T_STD.T, np.eye(3))
    assert np.isclose(np.linalg.det(T_STD), 1.0)
    assert np.array_equal(T_STD, T_STD.T)


def test_point_coordinates_match_unit_rotation_twist():
    # (5.51): the unit rotation about (x, y) has velocity at the origin w × (-r) = (y, -x)
    x, y = 1.5, -2.0
    r = np.array([x, y])
    v_origin = np.array([-(-r[1]) * 0 + r[1], -r[0]])  # ω ẑ × (0 - r) = (r_y, -r_x)
    assert np.allclose(from_xy([x, y]), [*v_origin, 1.0])
    assert np.allclose(to_standard(from_xy([x, y])), [1.0, x, y])


@given(r=st.floats(0.1, 10), lam=angle, l=st.floats(0.1, 5))
def test_line_standard_vs_alternative(r, lam, l):
    # (5.15): standard line [r l, -l cos, -l sin]; (5.54): alternative [-l sin, l cos, r l]
    std = np.array([r * l, -l * np.cos(lam), -l * np.sin(lam)])
    alt = np.array([-l * np.sin(lam), l * np.cos(lam), r * l])
    assert np.allclose(from_standard(std), alt)
    assert np.allclose(to_standard(alt), std)
    # (5.57): the foot point r n lies on the line; the force is along e = (-sin, cos) (5.58)
    assert np.isclose(incidence(from_xy(r * np.array([np.cos(lam), np.sin(lam)])), alt), 0, atol=1e-9)
    assert np.allclose(line_direction(alt), [-np.sin(lam), np.cos(lam)])
    assert np.allclose(to_xy(foot_point(alt)), r * np.array([np.cos(lam), np.sin(lam)]))


def test_polar_coordinates_of_point_5_52_corrected():
    # (5.48): [p0 r sin λ, -p0 r cos λ, p0] is the point x = r cos λ, y = r sin λ
    r, lam, p0 = 2.0, 0.3, 1.7
    p = np.array([p0 * r * np.sin(lam), -p0 * r * np.cos(lam), p0])
    assert np.allclose(to_xy(p), [r * np.cos(lam), r * np.sin(lam)])   # not (r sin, r cos) as printed


@given(v=vec3)
def test_standard_roundtrip(v):
    assert np.allclose(from_standard(to_standard(v)), v)
    C = np.outer(v, v) + np.diag([1.0, -2.0, 0.5])
    assert np.allclose(conic_from_standard(conic_to_standard(C)), C)


def test_conic_standard_incidence_preserved(rng):
    C = rng.normal(size=(3, 3)); C = C + C.T
    p = rng.normal(size=3)
    assert np.isclose(p @ C @ p, to_standard(p) @ conic_to_standard(C) @ to_standard(p))


# ----------------------------------------------------------------------------- normalisation
def test_normalize_points_and_lines():
    assert np.allclose(normalize_point([2.0, -4.0, -2.0]), [-1.0, 2.0, 1.0])
    assert np.allclose(normalize_point([3.0, -4.0, 0.0]), [0.6, -0.8, 0.0])
    assert np.allclose(normalize_line([3.0, -4.0, 10.0]), [0.6, -0.8, 2.0])
    assert np.array_equal(normalize_line([0.0, 0.0, -3.0]), [0.0, 0.0, -1.0])
    assert np.array_equal(normalize([0.0, 0.0, 4.0], kind="line"), [0.0, 0.0, 1.0])
    batch = normalize_point(np.array([[2.0, 0.0, 2.0], [0.0, 2.0, 0.0]]))
    assert np.allclose(batch, [[1.0, 0.0, 1.0], [0.0, 1.0, 0.0]])


def test_normalize_zero_vector_raises():
    with pytest.raises(DegenerateGeometryError, match=r"p is the zero vector at index \(1,\)"):
        normalize_point([[1.0, 0, 1], [0.0, 0, 0]])
    with pytest.raises(DegenerateGeometryError, match="l is the zero vector"):
        normalize_line([0.0, 0, 0])
    with pytest.raises(InputError, match="kind must be 'point' or 'line'"):
        normalize([1.0, 0, 0], kind="conic")


def test_normalize_requires_kind():
    # a line passed without kind must not be silently scaled as a point
    with pytest.raises(InputError, match=r"^kind must be given, 'point' or 'line'"):
        normalize([3.0, 4.0, 10.0])
    assert np.allclose(normalize([3.0, 4.0, 10.0], "line"), [0.6, 0.8, 2.0])      # positional still works
    assert np.allclose(normalize([3.0, 4.0, 10.0], "point"), [0.3, 0.4, 1.0])


def test_line_at_infinity_keeps_the_couples_sense_everywhere():
    # one rule for the whole package: a line at infinity is a couple, its sign is the couple's sense
    from planargeo.screws.twists import Wrench, add_wrenches
    assert np.array_equal(normalize_line([0.0, 0.0, -3.0]), [0.0, 0.0, -1.0])
    assert np.array_equal(normalize_line([0.0, 0.0, 2.0]), [0.0, 0.0, 1.0])
    cw = add_wrenches(Wrench.couple(-2.0), Wrench.force([0.0, 0.0], [1.0, 0.0]))
    assert np.array_equal(cw.L1, [0.0, 0.0, -1.0])
    c = add_wrenches(Wrench.couple(-2.0), Wrench.couple(-1.0))
    assert c.case == "couples" and np.array_equal(c.L3, [0.0, 0.0, -1.0])


def test_screws_pole_xy_is_to_xy():
    from planargeo.screws.twists import pole_xy
    P = np.array([[2.0, -1.0, 1.0], [4.0, -2.0, 2.0], [1.0, 0.0, 0.0], [0.0, 3.0, -3.0]])
    expected = np.array([[1.0, 2.0], [1.0, 2.0], [np.nan, np.nan], [1.0, 0.0]])   # (x, y) = (-p1/w, p0/w)
    np.testing.assert_array_equal(pole_xy(P), expected)
    np.testing.assert_array_equal(to_xy(P), expected)


def test_is_ideal_exact():
    assert list(is_ideal([[1, 2, 0], [1, 2, 1e-300]])) == [True, False]
    assert list(is_at_infinity([[0, 0, 1], [1e-300, 0, 1]])) == [True, False]


def test_to_xy_and_direction_of_ideal_points_no_warning():
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert np.all(np.isnan(to_xy([1.0, 2.0, 0.0])))
        assert np.allclose(direction([1.0, 0.0, 0.0]), [0.0, 1.0])
        assert np.all(np.isnan(direction([1.0, 0.0, 1.0])))
        assert np.allclose(direction(from_direction([3.0, 4.0])), [0.6, 0.8])
        assert np.all(np.isnan(line_direction(LINE_AT_INFINITY)))
        assert np.all(np.isnan(foot_point(LINE_AT_INFINITY)))


def test_ideal_point_is_translation_perpendicular():
    # convention: ideal point [a, b, 0] is a translation with velocity (a, b) and lies in direction (-b, a)
    p = np.array([2.0, 0.0, 0.0])                   # translation along +x
    assert np.allclose(direction(p), [0.0, 1.0])
    # it lies on every vertical line: x = c is the line [0, 1, c]
    assert incidence(p, [0.0, 1.0, 5.0]) == 0


# ----------------------------------------------------------------------------- join / meet
def thesis_5_32(p, q):
    """(5.32) in standard coordinates, transcribed by hand."""
    px, py = p
    qx, qy = q
    return np.array([py * qx - px * qy, -(py - qy), px - qx])


def thesis_5_34(r1, l1, r2, l2):
    """(5.34) in standard coordinates, transcribed by hand."""
    return np.array([np.sin(l1 - l2), r2 * np.sin(l1) - r1 * np.sin(l2), r1 * np.cos(l2) - r2 * np.cos(l1)])


@given(p=xy, q=xy)
def test_join_matches_thesis_5_32(p, q):
    if np.linalg.norm(p - q) < 1e-3:
        return
    L = join(from_xy(p), from_xy(q))
    ref = from_standard(thesis_5_32(p, q))
    assert same_up_to_scale(L, ref)
    # conventions: force q - p along the line from p to q, moment about origin p × (q - p)
    d = q - p
    assert np.allclose(L, [d[0], d[1], p[0] * d[1] - p[1] * d[0]])


def test_join_example_by_hand():
    # the line y = 1 through (0, 1) and (1, 1): (5.28-5.31) give λ = π/2, r = 1
    L = join(from_xy([0.0, 1.0]), from_xy([1.0, 1.0]))
    assert np.allclose(normalize_line(L), [1.0, 0.0, -1.0])     # force +x, tz = x fy - y fx = -1
    assert np.allclose(to_standard(normalize_line(L)), [-1.0, 0.0, 1.0])    # = -[r, -cos λ, -sin λ]


@given(r1=st.floats(-5, 5), l1=angle, r2=st.floats(-5, 5), l2=angle)
def test_meet_matches_thesis_5_34(r1, l1, r2, l2):
    if abs(np.sin(l1 - l2)) < 1e-3:
        return
    L1 = from_standard([r1, -np.cos(l1), -np.sin(l1)])
    L2 = from_standard([r2, -np.cos(l2), -np.sin(l2)])
    P = meet(L1, L2)
    assert same_up_to_scale(P, from_standard(thesis_5_34(r1, l1, r2, l2)))


def test_meet_example_by_hand():
    # x = 1 (λ = 0, r = 1) meets y = 2 (λ = π/2, r = 2) at (1, 2)
    L1 = from_standard([1.0, -1.0, 0.0])
    L2 = from_standard([2.0, 0.0, -1.0])
    assert np.allclose(to_xy(meet(L1, L2)), [1.0, 2.0])


@given(p=vec3, q=vec3)
def test_join_incidence(p, q):
    if np.linalg.norm(np.cross(p, q)) < 1e-3 * np.linalg.norm(p) * np.linalg.norm(q):
        return
    L = join(p, q)
    s = np.linalg.norm(L)
    assert abs(incidence(p, L)) <= 1e-9 * s * np.linalg.norm(p)
    assert abs(incidence(q, L)) <= 1e-9 * s * np.linalg.norm(q)


@given(a=vec3, b=vec3, c=vec3, d=vec3)
def test_meet_of_joins(a, b, c, d):
    # the meet of join(a, b) and join(c, d) lies on both lines, and on the pencil between them
    for u, v in ((a, b), (c, d)):
        if np.linalg.norm(np.cross(u, v)) < 1e-2 * np.linalg.norm(u) * np.linalg.norm(v):
            return
    L1, L2 = join(a, b), join(c, d)
    if np.linalg.norm(np.cross(L1, L2)) < 1e-3 * np.linalg.norm(L1) * np.linalg.norm(L2):
        return
    P = meet(L1, L2)
    n = np.linalg.norm(P)
    for L in (L1, L2, pencil(L1, L2, 0.37), pencil(L1, L2, -3.0)):
        assert abs(incidence(P, L)) <= 1e-8 * n * np.linalg.norm(L)
    # P lies on the line through a and b: a, b, P are dependent
    assert abs(np.linalg.det(np.array([a, b, P]))) <= 1e-8 * n * np.linalg.norm(a) * np.linalg.norm(b)


def test_parallel_lines_meet_at_infinity_without_warning():
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        L1 = join(from_xy([0.0, 0.0]), from_xy([1.0, 1.0]))
        L2 = join(from_xy([0.0, 3.0]), from_xy([2.0, 5.0]))
        P = meet(L1, L2)
        assert is_ideal(P)
        assert np.allclose(np.abs(direction(P)), [np.sqrt(0.5)] * 2)
        # the meet of any finite line with the line at infinity is its ideal point
        Q = meet(L1, LINE_AT_INFINITY)
        assert is_ideal(Q) and same_up_to_scale(Q, P)
        # two ideal points join in the line at infinity
        assert is_at_infinity(join(from_direction([1, 0]), from_direction([0, 1])))
        assert np.all(np.isnan(to_xy(P)))
        assert np.isinf(signed_distance(P, [1.0, 0.0, 0.0]))
        assert np.isnan(signed_distance(P, L2 + [0, 0, 1.0]))    # P lies on every line parallel to L2


def test_join_coincident_points_raises_naming_arguments():
    with pytest.raises(DegenerateGeometryError, match=r"join\(p, q\): p and q are the same point"):
        join(from_xy([1.0, 2.0]), 3.0 * from_xy([1.0, 2.0]))
    with pytest.raises(DegenerateGeometryError, match=r"at index \(1,\)"):
        join(from_xy([[0.0, 0.0], [1.0, 1.0]]), from_xy([[2.0, 2.0], [1.0, 1.0]]))


def test_meet_identical_lines_raises_naming_arguments():
    with pytest.raises(DegenerateGeometryError, match=r"meet\(l, m\): l and m are the same line"):
        meet([1.0, 2.0, 3.0], [-2.0, -4.0, -6.0])


# ----------------------------------------------------------------------------- the join/meet threshold
# Hand-derived: for a = [0, 0, 1] and b = [s, 0, 1] (the origin and the point (0, s); or, read as lines,
# ...) |a × b| = s and |a| |b| = sqrt(1 + s²), so κ = sqrt(1 + s²) / s: κ = 1e12 at s ≈ 1e-12.
def _kappa(s):
    return np.sqrt(1.0 + s * s) / s


def test_cond_limit_documented_value():
    # the package's one limit (planargeo.errors), the default of join and meet
    assert COND_LIMIT == 1e12
    assert "COND_LIMIT" in join.__doc__ and "COND_LIMIT" in meet.__doc__
    assert join.__defaults__ == (COND_LIMIT,) and meet.__defaults__ == (COND_LIMIT,)


@pytest.mark.parametrize("s", [1e-3, 1e-9, 1.1e-12])
def test_join_just_below_the_limit_returns_the_line(s):
    p, q = from_xy([0.0, 0.0]), from_xy([0.0, s])        # the y axis, points s apart
    assert _kappa(s) < COND_LIMIT
    assert abs(cross_cond(p, q) / _kappa(s) - 1) < 1e-12
    l = join(p, q)
    assert same_up_to_scale(l, [0.0, 1.0, 0.0], tol=1e-15)   # exactly the line x = 0, force +y
    assert l[1] > 0


@pytest.mark.parametrize("s", [0.9e-12, 1e-15, 1e-300])
def test_join_just_above_the_limit_raises_with_cond(s):
    p, q = from_xy([0.0, 0.0]), from_xy([0.0, s])
    with pytest.raises(DegenerateGeometryError, match=r"join\(p, q\): p and q are nearly the same point: "
                                                      r"condition number .* exceeds cond_limit = 1e\+12") as e:
        join(p, q)
    assert abs(e.value.cond / _kappa(s) - 1) < 1e-12
    # the limit is the caller's to move; a larger one accepts the same points
    assert same_up_to_scale(join(p, q, cond_limit=np.inf), [0.0, 1.0, 0.0], tol=1e-15)


@pytest.mark.parametrize("s, ok", [(1.1e-12, True), (0.9e-12, False)])
def test_meet_of_lines_through_the_origin_at_angle_s_threshold(s, ok):
    # y = 0 ([1, 0, 0]) and the line through the origin along (1, s) ([1, s, 0]): κ = sqrt(1 + s²)/s,
    # and they meet at the origin [0, 0, s]
    l, m = [1.0, 0.0, 0.0], [1.0, s, 0.0]
    if ok:
        p = meet(l, m)
        assert np.array_equal(p, [0.0, 0.0, s])
    else:
        with pytest.raises(DegenerateGeometryError, match=r"l and m are nearly the same line") as e:
            meet(l, m)
        assert abs(e.value.cond / _kappa(s) - 1) < 1e-12


def test_condition_number_is_scale_invariant_and_safe_from_overflow():
    a, b = np.array([0.0, 0.0, 1.0]), np.array([1.0, 0.0, 1.0])      # 45 degrees apart: κ = √2
    for sa, sb in ((1.0, 1.0), (1e200, 1e-200), (-3e-300, 7e250)):
        assert abs(cross_cond(sa * a, sb * b) - np.sqrt(2.0)) < 1e-15
        join(sa * a, sb * b)                                          # no error, no warning
    assert cross_cond(a, 0.0 * b) == np.inf


def test_ideal_points_and_parallel_lines_are_well_conditioned():
    # two ideal points 1e-6 rad apart: κ = 1/sin(1e-6); their join is the line at infinity, no error
    t = 1e-6
    P, Q = from_direction([1.0, 0.0]), from_direction([np.cos(t), np.sin(t)])
    l = join(P, Q)
    assert is_at_infinity(l) and l[2] != 0
    assert abs(cross_cond(P, Q) * np.sin(t) - 1) < 1e-9
    # parallel lines one unit apart at any angle: κ = sqrt(1 + (1 + 1)... ) ≤ 3; their meet is the ideal point
    for a in np.linspace(0, np.pi, 7):
        d = np.array([np.cos(a), np.sin(a)])
        L1 = line_through_point_direction(from_xy([0.0, 0.0]), d)
        L2 = line_through_point_direction(from_xy([-d[1], d[0]]), d)
        assert cross_cond(L1, L2) < 3
        assert is_ideal(meet(L1, L2))
    # the line at infinity meets a finite line in its ideal point (κ = 1 for a line through the origin)
    assert is_ideal(meet([1.0, 0.0, 0.0], LINE_AT_INFINITY))


def test_threshold_broadcasts_and_names_the_index():
    P = from_xy([[0.0, 0.0], [0.0, 0.0], [1.0, 1.0]])
    Q = from_xy([[0.0, 1.0], [0.0, 1e-14], [2.0, 1.0]])
    with pytest.raises(DegenerateGeometryError, match=r"at index \(1,\)") as e:
        join(P, Q)
    assert abs(e.value.cond / _kappa(1e-14) - 1) < 1e-12
    with pytest.raises(DegenerateGeometryError, match=r"same point .*at index \(0,\)") as e:
        join(P[:1], P[:1])
    assert e.value.cond == np.inf


def test_bad_input_named():
    with pytest.raises(ShapeError, match=r"q must have shape \(\.\.\., 3\), got shape \(2,\)"):
        join([1.0, 0, 1], [1.0, 0])
    with pytest.raises(NonFiniteError, match="p must be finite"):
        join([np.nan, 0, 1], [1.0, 0, 1])
    with pytest.raises(NonFiniteError, match="m must be finite"):
        meet([1.0, 0, 1], [np.inf, 0, 1])
    with pytest.raises(ShapeError, match="xy must have shape"):
        from_xy([1.0, 2.0, 3.0])
    with pytest.raises(DegenerateGeometryError, match="d is the zero vector"):
        from_direction([0.0, 0.0])
    with pytest.raises(ShapeError, match="l must have shape"):
        signed_distance([0, 0, 1.0], [[1.0, 0.0]])


# ----------------------------------------------------------------------------- distances, pencils
@given(p=xy, q=xy, s=xy)
def test_signed_distance_left_positive(p, q, s):
    if np.linalg.norm(q - p) < 1e-2:
        return
    L = join(from_xy(p), from_xy(q))
    d = q - p
    u = d / np.linalg.norm(d)
    # reference: 2D cross product of the unit direction with (s - p): positive on the left
    ref = u[0] * (s - p)[1] - u[1] * (s - p)[0]
    got = signed_distance(-2.5 * from_xy(s), 3.0 * L)    # invariant to positive line scale and any point scale
    assert np.isclose(got, ref, atol=1e-9)
    assert np.isclose(signed_distance(from_xy(s), -L), -ref, atol=1e-9)


def test_signed_distance_example():
    assert signed_distance(from_xy([0.0, 1.0]), [1.0, 0.0, 0.0]) == 1.0   # left of the +x axis
    assert signed_distance(from_xy([0.0, -1.0]), [1.0, 0.0, 0.0]) == -1.0
    assert signed_distance(from_xy([0.0, 0.0]), LINE_AT_INFINITY) == np.inf


@given(beta=st.floats(-5, 5), p=xy)
def test_pencil_passes_through_meet(beta, p):
    L1 = line_through_point_direction(from_xy(p), [1.0, 0.3])
    L2 = line_through_point_direction(from_xy(p), [-0.2, 1.0])
    L = pencil(L1, L2, beta)
    assert abs(incidence(from_xy(p), L)) < 1e-9 * (1 + np.linalg.norm(L) * (1 + np.linalg.norm(p)))


def test_pencil_broadcasts_and_midpoint():
    P = pencil(from_xy([0.0, 0.0]), from_xy([2.0, 4.0]), np.array([0.0, 0.5, 1.0]))
    assert np.allclose(to_xy(P), [[0, 0], [1, 2], [2, 4]])   # (5.9)


def test_line_through_point_direction():
    L = line_through_point_direction(from_xy([1.0, 1.0]), [0.0, 1.0])
    assert np.allclose(normalize_line(L), [0.0, 1.0, 1.0])   # x = 1: tz = x fy - y fx = 1
    assert is_at_infinity(line_through_point_direction(from_direction([1.0, 0.0]), [0.0, 1.0]))
    with pytest.raises(DegenerateGeometryError, match="p is the point at infinity in direction d"):
        line_through_point_direction(from_direction([1.0, 0.0]), [2.0, 0.0])


def test_broadcasting_shapes():
    P = from_xy(np.zeros((4, 5, 2)) + np.arange(5)[:, None])
    Q = from_xy(np.array([10.0, 3.0]))
    L = join(P, Q)
    assert L.shape == (4, 5, 3)
    assert incidence(P, L).shape == (4, 5)
    assert np.allclose(incidence(P, L), 0)
    assert to_xy(meet(L, LINE_AT_INFINITY)).shape == (4, 5, 2)


@pytest.mark.parametrize("fn", [join, meet])
@pytest.mark.parametrize("scale", [1e-100, 1e-7, 1.0, 1e7, 1e100])   # ±100: squared norms out of range
def test_scalar_fast_check_agrees_with_batch(fn, scale):
    """The one-pair path (plain float norms) accepts and refuses exactly where the array path does.

    ``a = [1, 0, 1]``, ``b = [cos θ, sin θ, 1]`` scaled by ``scale``: by hand ``|a| = |b| = √2``,
    ``|a × b| = √(2 sin²θ + (1 - cos θ)²) ≈ √2 θ``, so ``κ ≈ √2 / θ`` and the default limit 1e12
    refuses exactly ``θ < 1.41e-12``.
    """
    for theta in (1.0, 1e-6, 1e-11, 1.5e-12, 1.3e-12, 3e-14, 1e-16, 0.0):
        a = scale * np.array([1.0, 0.0, 1.0])
        b = scale * np.array([np.cos(theta), np.sin(theta), 1.0])
        try:
            one = fn(a, b)
        except DegenerateGeometryError as e:
            with pytest.raises(DegenerateGeometryError) as eb:
                fn(a[None], b[None])
            assert str(eb.value).replace(" at index (0,)", "") == str(e)
            assert eb.value.cond == e.cond
            assert theta < 1.41e-12
        else:
            np.testing.assert_array_equal(fn(a[None], b[None])[0], one)
            assert theta > 1.42e-12
