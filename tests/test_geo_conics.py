"""Tests of planargeo.geometry.conics against hand-derived references (thesis 5.35-5.46, 10.2.3)."""
import warnings

import numpy as np
import pytest
from hypothesis import assume, given
from hypothesis import strategies as st

from planargeo.geometry.conics import (
    affine_frame, centre, classify, conic_circle, conic_ellipse, conic_from_affine,
    conic_from_coefficients, conic_hyperbola, conic_parabola, conic_residual, correlation,
    decompose_line, decompose_line_special, decompose_point, decompose_point_special,
    drawable_conic, is_on_conic, line_conic_intersections, polar, polar_construction_exterior,
    polar_construction_interior, pole, special_base, tangents_from_point,
)
from planargeo.errors import DegenerateGeometryError, InputError, NonFiniteError, ShapeError
from planargeo.geometry.projective import (
    LINE_AT_INFINITY, direction, from_direction, from_xy, incidence, is_ideal, join,
    line_direction, meet, to_xy,
)
from planargeo.screws.twists import inertia_matrix

coord = st.floats(-5, 5).map(lambda x: round(x, 4))
xy = st.tuples(coord, coord).map(np.array)
pos = st.floats(0.5, 3.0)
angle = st.floats(-np.pi, np.pi).map(lambda x: round(x, 6))


def unit(a):
    a = np.asarray(a, float)
    a = a / np.abs(a).max(axis=-1, keepdims=True)
    return a / np.linalg.norm(a, axis=-1, keepdims=True)


def same_matrix_up_to_scale(A, B, tol=1e-8):
    a, b = np.ravel(A) / np.linalg.norm(A), np.ravel(B) / np.linalg.norm(B)
    return min(np.linalg.norm(a - b), np.linalg.norm(a + b)) <= tol


def same_up_to_scale(a, b, tol=1e-8):
    a, b = unit(a), unit(b)
    return np.linalg.norm(np.cross(a, b)) <= tol * np.linalg.norm(a) * np.linalg.norm(b)


def ellipse_points(c, a, b, th, phi):
    """Hand parametrisation of the ellipse (x'/a)² + (y'/b)² = 1 turned by th."""
    R = np.array([[np.cos(th), -np.sin(th)], [np.sin(th), np.cos(th)]])
    return np.asarray(c) + (R @ np.array([a * np.cos(phi), b * np.sin(phi)])).T


def ellipse_tangent(a, b, th, phi):
    R = np.array([[np.cos(th), -np.sin(th)], [np.sin(th), np.cos(th)]])
    return (R @ np.array([-a * np.sin(phi), b * np.cos(phi)])).T


@st.composite
def symmetric_conics(draw):
    v = [draw(st.floats(-3, 3)) for _ in range(6)]
    C = np.array([[v[0], v[3], v[4]], [v[3], v[1], v[5]], [v[4], v[5], v[2]]])
    assume(np.linalg.cond(C) < 1e4)
    return C


vec3 = st.tuples(coord, coord, coord).map(np.array).filter(lambda v: np.linalg.norm(v) > 0.1)


# ----------------------------------------------------------------------------- constructors
@given(c=xy, r=pos)
def test_circle_matches_expanded_equation(c, r):
    # (x - cx)² + (y - cy)² - r² expanded by hand into a x² + b xy + c y² + d x + e y + f
    ref = conic_from_coefficients(1.0, 0.0, 1.0, -2 * c[0], -2 * c[1], c @ c - r * r)
    assert np.allclose(conic_circle(c, r), ref)
    for phi in (0.0, 1.0, 2.5):
        P = from_xy(c + r * np.array([np.cos(phi), np.sin(phi)]))
        assert abs(conic_residual(conic_circle(c, r), P)) < 1e-9 * (1 + c @ c)


def test_inertia_is_imaginary_circle():
    m, c, J = 2.0, np.array([1.0, -0.5]), 0.7
    I = inertia_matrix(m, c, J)
    assert np.allclose(I / m, conic_circle(c, np.sqrt(J / m), imaginary=True))
    t = classify(I)
    assert (t.reality, t.kind, t.is_circle) == ("imaginary", "ellipse", True)
    assert np.allclose(to_xy(centre(I)), c)          # 5.2.2: the centre of an inertia is the centre of mass


@given(c=xy, a=pos, b=pos, th=angle)
def test_ellipse_points_and_tangents(c, a, b, th):
    C = conic_ellipse(c, [a, b], th)
    phi = np.linspace(0, 2 * np.pi, 7)
    X = from_xy(ellipse_points(c, a, b, th, phi))
    assert np.all(is_on_conic(C, X))
    # tangency: the polar of a point on the conic is the tangent there (5.39)
    L = polar(C, X)
    assert np.allclose(incidence(X, L) / np.linalg.norm(L, axis=-1), 0, atol=1e-9)
    d = ellipse_tangent(a, b, th, phi)
    cross = line_direction(L)[:, 0] * d[:, 1] - line_direction(L)[:, 1] * d[:, 0]
    assert np.allclose(cross / np.linalg.norm(d, axis=-1), 0, atol=1e-8)
    # centre is the pole of the line at infinity
    assert np.allclose(to_xy(centre(C)), c)
    assert np.allclose(to_xy(pole(C, LINE_AT_INFINITY)), c)


def test_classify_table():
    cases = {
        "real circle": conic_circle([1.0, 2.0], 1.0),
        "real ellipse": conic_from_coefficients(1, 0, 4, 0, 0, -4),
        "real hyperbola": conic_from_coefficients(1, 0, -1, 0, 0, -1),
        "real parabola": conic_from_coefficients(1, 0, 0, 0, -1, 0),      # y = x²
        "imaginary ellipse": conic_from_coefficients(1, 0, 2, 0, 0, 1),   # x² + 2y² = -1
        "line pair": conic_from_coefficients(1, 0, -1, 0, 0, 0),          # y = ±x
        "point": conic_from_coefficients(1, 0, 1, 0, 0, 0),
        "double line": conic_from_coefficients(1, 0, 0, 0, 0, 0),
    }
    for name, C in cases.items():
        assert str(classify(C)) == name
        assert str(classify(-3.0 * C)) == name                          # scale and sign free
    assert classify(conic_from_coefficients(1, 0, 0, 0, 0, -1)).kind == "line pair"   # x = ±1
    batch = classify(np.stack([cases["real circle"], cases["line pair"]]))
    assert batch.shape == (2,) and batch[1].kind == "line pair"


@given(c=xy, a=pos, b=pos, th=angle)
def test_classify_constructed(c, a, b, th):
    assert classify(conic_ellipse(c, [a, b], th)).kind == "ellipse"
    assert classify(conic_hyperbola(c, [a, b], th)).kind == "hyperbola"
    assert classify(conic_parabola(c, a, th)).kind == "parabola"


# ----------------------------------------------------------------------------- pole / polar
def test_polar_of_circle_by_inversion():
    # classical: the polar of P w.r.t. a circle (O, r) is perpendicular to OP at distance r²/|OP| from O
    O, r, P = np.array([1.0, 1.0]), 2.0, np.array([4.0, 5.0])
    L = polar(conic_circle(O, r), from_xy(P))
    u = (P - O) / np.linalg.norm(P - O)
    foot = O + u * r * r / np.linalg.norm(P - O)
    assert abs(incidence(from_xy(foot), L)) < 1e-12 * np.linalg.norm(L)
    assert abs(line_direction(L) @ u) < 1e-12


def test_percussion_axis_5_64_to_5_68():
    # (5.64)-(5.68): frame at the pole a, com at distance d on x: axis of percussion at l = d + ρ²/d
    m, d, rho = 3.0, 0.5, 0.4
    I = np.array([[m, 0, 0], [0, m, d * m], [0, d * m, m * (rho**2 + d**2)]])
    f = polar(I, [0.0, 0.0, 2.0])
    assert np.allclose(f, [0.0, m * d * 2.0, m * (rho**2 + d**2) * 2.0])          # (5.66)
    assert np.isclose(f[2] / f[1], d + rho**2 / d)                                  # (5.67)
    assert np.allclose(pole(I, f), [0.0, 0.0, 2.0])


@given(C=symmetric_conics(), p=vec3)
def test_pole_polar_inverse(C, p):
    assert np.allclose(pole(C, polar(C, p)), p, atol=1e-7 * np.linalg.norm(p))
    l = p
    assert np.allclose(polar(C, pole(C, l)), l, atol=1e-7 * np.linalg.norm(l))


@given(C=symmetric_conics(), Q=vec3, L=vec3)
def test_correlation_theorem_12_and_invariance_5_40(C, Q, L):
    P, M = correlation(C, Q, L)
    # linear forms are invariant under the conic mapping: P·M = Q·L (5.40-5.41)
    assert np.isclose(P @ M, Q @ L, atol=1e-7 * np.linalg.norm(Q) * np.linalg.norm(L) * np.linalg.cond(C))
    # Theorem 12: a line through Q maps to a point on the polar of Q
    L0 = np.cross(Q, np.array([0.3, -1.0, 2.0]))
    assume(np.linalg.norm(L0) > 1e-3)
    P0, M0 = correlation(C, Q, L0)
    assert abs(P0 @ M0) < 1e-8 * np.linalg.norm(P0) * np.linalg.norm(M0) * np.linalg.cond(C)


def test_ideal_elements_flow_without_warnings():
    C = conic_hyperbola([0.0, 0.0], [1.0, 1.0])          # x² - y² = 1
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        # the line at infinity meets the hyperbola at the asymptote directions
        X, real = line_conic_intersections(C, LINE_AT_INFINITY)
        assert real and np.all(is_ideal(X))
        dirs = sorted(tuple(np.round(np.abs(direction(x)), 12)) for x in X)
        assert np.allclose(dirs, [[np.sqrt(0.5)] * 2] * 2)
        # tangents there are the asymptotes y = ±x through the centre
        for x in X:
            assert abs(incidence(from_xy([0.0, 0.0]), polar(C, x))) < 1e-12
        # an ideal point maps to a diameter (5.2.2)
        D = polar(conic_ellipse([1.0, 2.0], [2.0, 1.0], 0.4), from_direction([1.0, 0.0]))
        assert abs(incidence(from_xy([1.0, 2.0]), D)) < 1e-12
        # tangents from an ideal point to the unit circle: y = ±1, touching at (0, ±1)
        L, T = tangents_from_point(conic_circle([0.0, 0.0], 1.0), from_direction([1.0, 0.0]))
        assert np.allclose(sorted(to_xy(T)[:, 1]), [-1, 1]) and np.allclose(to_xy(T)[:, 0], 0)
        assert np.all(is_ideal(np.cross(L[0], L[1])))
        # a parabola built exactly has an ideal centre in its axis direction
        z = centre(conic_from_coefficients(1, 0, 0, 0, -1, 0))
        assert is_ideal(z) and np.allclose(np.abs(direction(z)), [0, 1])


# ----------------------------------------------------------------------------- tangents and constructions
def test_tangents_from_point_circle_by_hand():
    # from (2, 0) to the unit circle: contacts at (1/2, ±√3/2), tangents x ± √3 y = 2
    L, X = tangents_from_point(conic_circle([0.0, 0.0], 1.0), from_xy([2.0, 0.0]))
    got = sorted(map(tuple, np.round(to_xy(X), 12)))
    assert np.allclose(got, [(0.5, -np.sqrt(3) / 2), (0.5, np.sqrt(3) / 2)])
    for l in L:
        assert abs(incidence(from_xy([2.0, 0.0]), l)) < 1e-12
        n = np.array([l[1], -l[0]])                # the normal of the line
        assert np.isclose(abs(n[0] / n[1]), 1 / np.sqrt(3))


def local(c, th, x, y):
    R = np.array([[np.cos(th), -np.sin(th)], [np.sin(th), np.cos(th)]])
    return from_xy(np.asarray(c) + R @ np.array([x, y]))


@given(c=xy, a=pos, b=pos, th=angle, s=st.floats(1.1, 4), phi=angle, v=st.floats(-3, 3).map(lambda x: round(x, 6)),
       kind=st.sampled_from(["e", "h", "p"]))
def test_exterior_construction_reproduces_Cp(c, a, b, th, s, phi, v, kind):
    if kind == "e":
        C = conic_ellipse(c, [a, b], th)
        p = local(c, th, s * a * np.cos(phi), s * b * np.sin(phi))       # outside the ellipse
    elif kind == "h":
        C = conic_hyperbola(c, [a, b], th)
        p = local(c, th, a * np.sin(phi) / s, b * v)                     # between the branches
    else:
        C = conic_parabola(c, a, th)
        p = local(c, th, v, v * v / (4 * a) - s + 1.0)                   # below y' = x'²/(4a)
    K = polar_construction_exterior(C, p)
    assert same_up_to_scale(K.polar, polar(C, p), tol=1e-6)
    for i in range(2):
        assert is_on_conic(C, K.contacts[i], rtol=1e-7)
        assert abs(incidence(unit(p), K.tangents[i])) < 1e-7
        assert abs(incidence(unit(K.contacts[i]), K.tangents[i])) < 1e-7


@given(c=xy, a=pos, b=pos, th=angle, s=st.floats(0.05, 0.9), phi=angle, v=st.floats(-3, 3).map(lambda x: round(x, 6)),
       kind=st.sampled_from(["e", "h", "p"]))
def test_interior_construction_reproduces_Cp(c, a, b, th, s, phi, v, kind):
    if kind == "e":
        C = conic_ellipse(c, [a, b], th)
        p = local(c, th, s * a * np.cos(phi), s * b * np.sin(phi))
    elif kind == "h":
        C = conic_hyperbola(c, [a, b], th)
        p = local(c, th, np.sign(phi + 0.1) * a * np.sqrt(1 + v * v) / s, b * v)   # inside a branch
    else:
        C = conic_parabola(c, a, th)
        p = local(c, th, v, v * v / (4 * a) + s)                          # above y' = x'²/(4a)
    K = polar_construction_interior(C, p)
    assert same_up_to_scale(K.polar, polar(C, p), tol=1e-6)
    for i in range(2):
        assert same_up_to_scale(K.poles[i], pole(C, K.lines[i]), tol=1e-6)   # Theorem 12
        for j in range(2):
            assert abs(incidence(unit(K.chord_points[i, j]), K.lines[i])) < 1e-8


def test_interior_construction_with_given_lines_and_errors():
    C = conic_circle([0.0, 0.0], 2.0)
    p = from_xy([1.0, 0.0])
    lines = np.array([join(p, from_xy([1.0, 1.0])), join(p, from_xy([0.0, 1.0]))])
    K = polar_construction_interior(C, p, lines=lines)
    assert same_up_to_scale(K.polar, [0.0, 1.0, 4.0])       # x = 4 = r²/|p|
    with pytest.raises(InputError, match=r"lines\[1\] does not pass through p"):
        polar_construction_interior(C, p, lines=[lines[0], [1.0, 0.0, 5.0]])
    with pytest.raises(InputError, match=r"lines\[0\] does not cut C in two distinct real points"):
        polar_construction_interior(C, from_xy([3.0, 0.0]), lines=[[0.0, 1.0, 3.0], [1.0, 0.0, 0.0]])


def test_interior_construction_incidence_uses_rtol():
    # p = (1, 0) = [0, -1, 1]; the line y = 1e-6 (a force along x through (1, 1e-6): [1, 0, -1e-6], 5.56)
    # misses p by |l·p| = 1e-6, i.e. 1e-6 / sqrt(2) relative to |l| |p|
    C = conic_circle([0.0, 0.0], 2.0)
    p = from_xy([1.0, 0.0])
    near = [1.0, 0.0, -1e-6]
    vertical = [0.0, 1.0, 1.0]                                     # x = 1 through p: force along y through (1, 0)
    with pytest.raises(InputError, match=r"^lines\[0\] does not pass through p: \|lines\[0\] · p\| = 1e-06 > "):
        polar_construction_interior(C, p, lines=[near, vertical])          # default rtol 1e-9
    K = polar_construction_interior(C, p, lines=[near, vertical], rtol=1e-5)   # accepted with a looser rtol
    assert same_up_to_scale(K.polar, [0.0, 1.0, 4.0], tol=1e-5)           # still x = 4 = r²/|p|


def test_interior_point_has_no_tangents():
    C = conic_circle([0.0, 0.0], 1.0)
    with pytest.raises(InputError, match="p has no real tangents to C"):
        tangents_from_point(C, from_xy([0.2, 0.1]))
    with pytest.raises(InputError, match=r"p has no real tangents to C at index \(1,\)"):
        polar_construction_exterior(C, from_xy([[3.0, 0.0], [0.2, 0.1]]))
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        L, X = tangents_from_point(C, from_xy([[3.0, 0.0], [0.2, 0.1]]), on_interior="nan")
        assert np.all(np.isfinite(X[0])) and np.all(np.isnan(X[1])) and np.all(np.isnan(L[1]))
    with pytest.raises(InputError, match="p has no real tangents"):
        tangents_from_point(inertia_matrix(1.0, [0.0, 0.0], 1.0), from_xy([5.0, 0.0]))   # imaginary


def test_point_on_conic_gives_its_tangent_twice():
    C = conic_circle([0.0, 0.0], 1.0)
    L, X = tangents_from_point(C, from_xy([0.0, 1.0]))
    assert np.allclose(to_xy(X), [[0, 1], [0, 1]])
    assert same_up_to_scale(L[0], [1.0, 0.0, -1.0]) and same_up_to_scale(L[1], L[0])
    K = polar_construction_exterior(C, from_xy([0.0, 1.0]))
    assert same_up_to_scale(K.polar, [1.0, 0.0, -1.0])


# ----------------------------------------------------------------------------- decompositions
@given(C=symmetric_conics(), P=vec3, Q1=vec3, Q2=vec3, Q3=vec3)
def test_decomposition_roundtrip_and_duality_5_42_5_43(C, P, Q1, Q2, Q3):
    B = np.column_stack([Q1, Q2, Q3])
    assume(np.linalg.cond(B) < 1e4)
    u = decompose_point(P, Q1, Q2, Q3)
    assert np.allclose(B @ u, P, atol=1e-8 * np.linalg.norm(P))
    v = decompose_line(C, C @ P, Q1, Q2, Q3)        # same ratios for L = C P
    assert np.allclose(v, u, atol=1e-6 * (1 + np.abs(u).max()))


@given(c=xy, a=pos, b=pos, th=angle, s=st.floats(1.2, 4), phi=angle, P=vec3)
def test_special_decomposition_5_44_to_5_46(c, a, b, th, s, phi, P):
    C = conic_ellipse(c, [a, b], th)
    Q1, Q2, Q3 = special_base(C, from_xy(ellipse_points(c, s * a, s * b, th, phi)))
    # the special base's defining relations (Fig. 5.4)
    for x, y in ((Q2, Q2), (Q3, Q3), (Q1, Q2), (Q1, Q3)):
        assert abs(x @ C @ y) < 1e-8 * np.linalg.norm(C)
    u = decompose_point_special(C, P, Q1, Q2, Q3)
    ref = np.linalg.solve(np.column_stack([Q1, Q2, Q3]), P)      # independent: dense solve
    assert np.allclose(u, ref, rtol=1e-6, atol=1e-6 * np.abs(ref).max())
    w = decompose_line_special(C, C @ P, Q1, Q2, Q3)
    assert np.allclose(w, ref, rtol=1e-6, atol=1e-6 * np.abs(ref).max())
    M = C @ np.column_stack([Q1, Q2, Q3])
    assert np.allclose(M @ w, C @ P, atol=1e-6 * np.linalg.norm(C @ P))


def test_collinear_base_raises():
    with pytest.raises(DegenerateGeometryError, match=r"\[Q1, Q2, Q3\] is singular: the three base elements are dependent"):
        decompose_point([1.0, 2, 3], from_xy([0.0, 0]), from_xy([1.0, 1]), from_xy([2.0, 2]))


# ----------------------------------------------------------------------------- drawing support
def test_drawable_conic_of_inertia_is_gyration_circle():
    m, c, J = 2.0, np.array([1.0, -2.0]), 0.5
    I = inertia_matrix(m, c, J)
    D = drawable_conic(I)
    assert np.allclose(D / m, conic_circle(c, np.sqrt(J / m)))           # radius of gyration
    assert np.allclose(drawable_conic(-I), D)                           # sign of the imaginary conic irrelevant
    R = conic_hyperbola([0.0, 0.0], [1.0, 2.0])
    assert np.array_equal(drawable_conic(R), R)                         # real conics unchanged


@given(c=xy, a=pos, b=pos, th=angle, m=pos, p=xy, ideal=st.booleans())
def test_drawable_conic_polars_are_point_reflections(c, a, b, th, m, p, ideal):
    # an imaginary ellipse: the real ellipse's matrix with its centred homogeneous part sign-flipped
    E = conic_ellipse(c, [a, b], th)
    z = from_xy(c)
    k = z @ E @ z                                                       # < 0 inside the real ellipse
    I = E - 2 * k * np.outer([0, 0, 1.0], [0, 0, 1.0])
    assert classify(I).reality == "imaginary"
    D = drawable_conic(m * I)
    assert same_matrix_up_to_scale(D, E, tol=1e-8)                           # 10.2.3: back to the real ellipse
    P = from_direction(p + [0.1, 0.0]) if ideal else from_xy(p)
    Lc, Ld = polar(I, P), polar(D, P)
    # reflect two points of the polar w.r.t. I through the centre: they lie on the polar w.r.t. D
    X1 = meet(Lc, [1.0, 0.3, 0.7]) if not np.allclose(np.cross(Lc, [1.0, 0.3, 0.7]), 0) else None
    for X in (meet(Lc, [0.2, 1.0, -0.4]), X1):
        if X is None or X[2] == 0 or abs(X[2]) < 1e-9 * np.linalg.norm(X):
            continue
        Xr = from_xy(2 * c - to_xy(X))
        assert abs(incidence(Xr, Ld)) < 1e-7 * np.linalg.norm(Ld) * (1 + np.linalg.norm(Xr))


@given(c=xy, a=pos, b=pos, th=angle, kind=st.sampled_from(["ellipse", "hyperbola", "parabola"]))
def test_affine_frame_maps_unit_curve_onto_conic(c, a, b, th, kind):
    C = {"ellipse": lambda: conic_ellipse(c, [a, b], th),
         "hyperbola": lambda: conic_hyperbola(c, [a, b], th),
         "parabola": lambda: conic_parabola(c, a, th)}[kind]()
    F = affine_frame(C)
    assert F.kind == kind
    s = np.linspace(-1.5, 1.5, 9)
    U = {"ellipse": np.stack([np.cos(2 * s), np.sin(2 * s)], -1),
         "hyperbola": np.concatenate([np.stack([np.cosh(s), np.sinh(s)], -1),
                                      np.stack([-np.cosh(s), np.sinh(s)], -1)]),
         "parabola": np.stack([s, s * s], -1)}[kind]
    X = U @ F.A.T + F.t
    assert np.all(is_on_conic(C, from_xy(X), rtol=1e-8))
    # tangency for every kind: the polar of a point on the conic is along the curve's derivative
    dU = {"ellipse": np.stack([-np.sin(2 * s), np.cos(2 * s)], -1),
          "hyperbola": np.concatenate([np.stack([np.sinh(s), np.cosh(s)], -1),
                                       np.stack([-np.sinh(s), np.cosh(s)], -1)]),
          "parabola": np.stack([np.ones_like(s), 2 * s], -1)}[kind]
    dX = dU @ F.A.T
    e = line_direction(polar(C, from_xy(X)))
    assert np.allclose((e[:, 0] * dX[:, 1] - e[:, 1] * dX[:, 0]) / np.linalg.norm(dX, axis=-1), 0, atol=1e-8)
    assert np.allclose(incidence(from_xy(X), polar(C, from_xy(X))) / np.linalg.norm(polar(C, from_xy(X)), axis=-1),
                       0, atol=1e-8 * (1 + np.abs(X).max()))
    assert same_matrix_up_to_scale(conic_from_affine(kind, F.A, F.t), C, tol=1e-7)
    if kind == "hyperbola":
        assert np.allclose(F.t, c)
        assert np.allclose(np.linalg.norm(F.A, axis=0), [a, b])        # semi-axes (transverse first)
    elif kind == "ellipse":
        assert np.allclose(F.t, c)
        assert np.allclose(sorted(np.linalg.norm(F.A, axis=0)), sorted([a, b]))
    else:
        assert np.allclose(F.t, c)                                      # vertex
        assert abs(abs(np.linalg.det(F.A)) - 1 / (4 * a)) < 1e-9


def test_affine_frame_errors():
    with pytest.raises(InputError, match="imaginary conic.*drawable_conic"):
        affine_frame(inertia_matrix(1.0, [0.0, 0.0], 1.0))
    with pytest.raises(DegenerateGeometryError, match="degenerate conic \\(line pair\\)"):
        affine_frame(conic_from_coefficients(1, 0, -1, 0, 0, 0))
    with pytest.raises(ShapeError, match="C must have shape \\(3, 3\\) for affine_frame"):
        affine_frame(np.stack([np.eye(3), np.eye(3)]))


# ----------------------------------------------------------------------------- bad input
def test_bad_input_named():
    with pytest.raises(InputError, match="C must be symmetric"):
        polar([[1.0, 2, 0], [0, 1, 0], [0, 0, 1]], [0, 0, 1.0])
    with pytest.raises(ShapeError, match=r"C must have shape \(\.\.\., 3, 3\)"):
        polar(np.eye(2), [0, 0, 1.0])
    with pytest.raises(NonFiniteError, match="p must be finite"):
        polar(np.eye(3), [np.nan, 0, 1.0])
    with pytest.raises(DegenerateGeometryError, match="C is singular") as ei:
        pole(conic_from_coefficients(1, 0, -1, 0, 0, 0), [0, 0, 1.0])
    assert ei.value.cond == np.inf or ei.value.cond > 1e12
    with pytest.raises(InputError, match="radius must be positive"):
        conic_circle([0.0, 0.0], -1.0)
    with pytest.raises(DegenerateGeometryError, match="C has no unique centre"):
        centre(conic_from_coefficients(1, 0, 0, 0, 0, 0))
    with pytest.raises(InputError, match="kind must be 'ellipse', 'hyperbola' or 'parabola'"):
        conic_from_affine("circle", np.eye(2), [0, 0])
    with pytest.raises(DegenerateGeometryError, match="A is singular"):
        conic_from_affine("ellipse", np.zeros((2, 2)), [0, 0])
    with pytest.raises(InputError, match="on_interior must be"):
        tangents_from_point(np.eye(3), [0, 0, 1.0], on_interior="skip")


def test_broadcasting():
    C = conic_circle(np.zeros((4, 2)), np.arange(1.0, 5.0))
    assert C.shape == (4, 3, 3)
    p = from_xy([10.0, 0.0])
    assert polar(C, p).shape == (4, 3)
    assert pole(C, polar(C, p)).shape == (4, 3)
    L, X = tangents_from_point(C, p)
    assert L.shape == X.shape == (4, 2, 3)
    assert np.allclose(to_xy(X)[:, 0, 0], np.arange(1.0, 5.0) ** 2 / 10)
    K = polar_construction_interior(C, from_xy([0.5, 0.2]))
    assert K.chord_points.shape == (4, 2, 2, 3) and K.polar.shape == (4, 3)


def test_centre_is_stationary_not_minimum_for_hyperbola():
    # erratum 5.2.2: the centre is the stationary point of Q C Q (w = 1); for a hyperbola a saddle
    C = conic_hyperbola([1.0, 2.0], [1.0, 2.0], 0.3)
    z = to_xy(centre(C))
    q = lambda x: conic_residual(C, from_xy(x))      # noqa: E731
    h = 1e-3
    for d in np.eye(2):
        assert abs(q(z + h * d) - q(z - h * d)) < 1e-9          # zero gradient (central difference)
    F = affine_frame(C)
    along = [q(z + h * F.A[:, i] / np.linalg.norm(F.A[:, i])) - q(z) for i in range(2)]
    assert along[0] * along[1] < 0                               # a saddle: no minimum
