"""Axis of percussion (thesis 5.64-5.71), its inverse, and the drawable conic (10.2.3)."""
import numpy as np
import pytest
from hypothesis import assume, given
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays

from planargeo.screws.inertia import (
    Inertia, centre_of_mass, drawable_conic, mobility, percussion_axis, percussion_pole, radius_of_gyration,
)
from planargeo.screws.twists import X_P, crf, inertia_matrix

coord = st.floats(-10, 10, allow_nan=False)
xy = arrays(float, 2, elements=coord)
pos = st.floats(0.1, 10)


def hom(p):
    return np.array([p[1], -p[0], 1.0])


def on_line(L, X, tol):
    return abs(L[2] + X[1] * L[0] - X[0] * L[1]) <= tol * (1 + np.abs(L).max())    # 4.27


def points_on(L):
    """Two Euclidean points of a finite line [fx, fy, tau] (4.28-4.32)."""
    F = np.hypot(L[0], L[1])
    e, n, d = L[:2] / F, np.array([L[1], -L[0]]) / F, L[2] / F
    return n * d, n * d + e


@pytest.mark.parametrize("m,rho,d,alpha", [(1.0, 0.5, 1.0, 1.0), (2.0, 0.3, 2.5, -3.0),
                                           (7.5, 2.0, 0.4, 0.2), (0.3, 1.0, -1.5, 2.0)])
def test_axis_of_percussion_5_64_to_5_68(m, rho, d, alpha):
    I564 = np.array([[m, 0, 0], [0, m, d * m], [0, d * m, m * (rho ** 2 + d ** 2)]])   # 5.64
    np.testing.assert_allclose(Inertia.from_mass(m, [d, 0.0], radius_of_gyration=rho).matrix, I564)
    f = percussion_axis(I564, [0.0, 0.0, alpha])                                        # 5.65
    np.testing.assert_allclose(f, [0.0, m * d * alpha, m * (rho ** 2 + d ** 2) * alpha])  # 5.66
    l = f[2] / f[1]                                  # the vertical line x = l
    assert l == pytest.approx(d + rho ** 2 / d)      # 5.67
    assert l - d == pytest.approx(rho ** 2 / d)      # 5.68
    assert on_line(f, [l, 12.3], 1e-12)


@given(pos, xy, pos, xy)
def test_axis_geometry_general(m, c, rho, P):
    d = np.linalg.norm(P - c)
    assume(d > 0.05)
    I = inertia_matrix(m, c, m * rho * rho)
    L = percussion_axis(I, hom(P))
    u = (P - c) / d
    X1, X2 = points_on(L)
    for X in (X1, X2):
        # perpendicular to P c, on the far side of c at distance rho^2/d: (X - c).u = -rho^2/d
        assert (X - c) @ u == pytest.approx(-rho * rho / d, rel=1e-7, abs=1e-7 * (1 + rho * rho / d))
        # distance from the pole: l = d + rho^2/d (5.67)
        assert (P - X) @ u == pytest.approx(d + rho * rho / d, rel=1e-7, abs=1e-7 * (1 + d + rho * rho / d))


@given(pos, xy, pos)
def test_limits_centre_and_infinity(m, c, rho):
    I = inertia_matrix(m, c, m * rho * rho)
    # pole at the centre of mass: a pure couple (line at infinity), moment J alpha
    np.testing.assert_allclose(percussion_axis(I, hom(c)), [0.0, 0.0, m * rho * rho],
                               atol=1e-9 * m * (1 + c @ c))
    # pole at infinity (a translation with acceleration (ax, ay)): a force m a through the centre
    a = np.array([0.6, -0.8, 0.0])
    L = percussion_axis(I, a)
    np.testing.assert_allclose(L[:2], m * a[:2], rtol=1e-12)
    assert on_line(L, c, 1e-9 * (1 + np.abs(c).max()))
    # and back
    np.testing.assert_allclose(percussion_pole(I, [0.0, 0.0, 1.0]) / percussion_pole(I, [0.0, 0.0, 1.0])[2],
                               hom(c), atol=1e-9 * (1 + np.abs(c).max()))


@given(pos, xy, pos, arrays(float, 3, elements=coord))
def test_percussion_pole_is_inverse(m, c, rho, p):
    assume(np.linalg.norm(p) > 1e-2)
    I = inertia_matrix(m, c, m * rho * rho)
    scale = np.linalg.cond(I)
    np.testing.assert_allclose(percussion_pole(I, percussion_axis(I, p)), p, atol=1e-12 * scale * np.abs(p).max())
    np.testing.assert_allclose(percussion_axis(I, percussion_pole(I, p)), p, atol=1e-12 * scale * np.abs(p).max())
    np.testing.assert_allclose(mobility(I) @ I, np.eye(3), atol=1e-12 * scale)


@given(pos, xy, pos, arrays(float, 3, elements=coord), arrays(float, 3, elements=coord))
def test_conjugacy_and_power_5_69_to_5_74(m, c, rho, v, a):
    I = inertia_matrix(m, c, m * rho * rho)
    tol = 1e-9 * (1 + np.abs(I).max()) * (1 + np.abs(v).max()) ** 2 * (1 + np.abs(a).max())
    # v lies on the axis of percussion of a  <=>  a lies on the axis of percussion of v (I symmetric)
    assert v @ percussion_axis(I, a) == pytest.approx(a @ percussion_axis(I, v), abs=tol)
    # 5.70-5.71: v^T f = (I v)^T a for f = I a - (v x)^T I v: the bias force is powerless on v
    f = I @ a + crf(v) @ I @ v
    assert v @ f == pytest.approx((I @ v) @ a, abs=tol)


@given(pos, xy, pos, xy)
def test_powerless_force_through_pole(m, c, rho, P):
    # a force through the velocity pole does no power; its acceleration lies on the momentum line (5.71c)
    I = inertia_matrix(m, c, m * rho * rho)
    v = hom(P)
    f = np.array([1.0, 2.0, 0.0])
    f[2] = P[0] * f[1] - P[1] * f[0]               # line through P
    assert abs(v @ f) < 1e-9 * (1 + np.abs(P).max()) * 3
    a = percussion_pole(I, f)                        # from rest: f = I a
    assert abs(a @ (I @ v)) < 1e-8 * (1 + np.abs(P).max()) ** 2 * (1 + m) * 10


# ------------------------------------------------------------------ drawable conic
def reflection_through(c):
    """Point reflection x -> 2c - x in the package's homogeneous coordinates (independent)."""
    Xc = X_P(c)                                    # maps [y, -x, 1] to [y - cy, -(x - cx), 1]
    return np.linalg.inv(Xc) @ np.diag([-1.0, -1.0, 1.0]) @ Xc


@given(pos, xy, pos, xy)
def test_drawable_conic_is_gyration_circle_and_reflects_polars(m, c, rho, P):
    I = inertia_matrix(m, c, m * rho * rho)
    C = drawable_conic(I)
    # real circle of radius rho about c
    for t in np.linspace(0, 2 * np.pi, 7):
        X = c + rho * np.array([np.cos(t), np.sin(t)])
        assert abs(hom(X) @ C @ hom(X)) < 1e-9 * m * (1 + np.abs(c).max() + rho) ** 2
    assert abs(hom(c) @ C @ hom(c) + m * rho * rho) < 1e-9 * m * (1 + c @ c)   # centre inside
    w = np.linalg.eigvalsh(C)
    assert (w > 0).sum() == 2 and (w < 0).sum() == 1
    d = np.linalg.norm(P - c)
    assume(d > 0.05)
    u = (P - c) / d
    # ordinary polar of P: (X - c).(P - c) = rho^2 (same side as P)
    Lp = C @ hom(P)
    for X in points_on(Lp):
        assert (X - c) @ u == pytest.approx(rho * rho / d, rel=1e-7, abs=1e-7 * (1 + rho * rho / d))
    # the axis of percussion is its reflection through c
    R = reflection_through(c)
    Lr = np.linalg.inv(R).T @ Lp
    La = percussion_axis(I, hom(P))
    assert np.linalg.norm(np.cross(Lr, La)) <= 1e-8 * np.linalg.norm(Lr) * np.linalg.norm(La) * (1 + np.abs(c).max())


def test_drawable_conic_in_centre_frame_is_sign_flip():
    m, rho = 3.0, 0.7
    np.testing.assert_allclose(drawable_conic(inertia_matrix(m, [0.0, 0.0], m * rho * rho)),
                               np.diag([m, m, -m * rho * rho]))


# ------------------------------------------------------------------ the class
def test_inertia_class_features():
    I = Inertia.from_mass(2.0, [1.0, -2.0], radius_of_gyration=0.5)
    assert float(I.mass) == 2.0
    np.testing.assert_allclose(I.com, [1.0, -2.0])
    assert float(I.radius_of_gyration) == pytest.approx(0.5)
    assert float(I.rotational_inertia) == pytest.approx(0.5)
    J = Inertia.from_mass(2.0, [1.0, -2.0], inertia=0.5)
    assert I == J
    # kinetic energy: spinning about the origin, 1/2 (J + m d^2) w^2
    assert float(I.kinetic_energy([0.0, 0.0, 2.0])) == pytest.approx(0.5 * (0.5 + 2.0 * 5.0) * 4.0)
    np.testing.assert_allclose(I.momentum([1.0, 0.0, 0.0]), [2.0, 0.0, 4.0])   # m v through the centre
    K = I.at([1.0, -2.0])
    np.testing.assert_allclose(K.matrix, np.diag([2.0, 2.0, 0.5]), atol=1e-12)
    np.testing.assert_allclose(K.com, [0.0, 0.0], atol=1e-12)
    np.testing.assert_allclose(I.mobility @ I.matrix, np.eye(3), atol=1e-12)
    assert "Inertia(mass=2" in repr(I)
    with pytest.raises(ValueError):
        I.matrix[0, 0] = 5.0
    np.testing.assert_allclose(I.percussion_pole_array(I.percussion_axis_array([0.0, 0.0, 1.0])), [0.0, 0.0, 1.0],
                               atol=1e-12)


def test_batched_functions():
    rng = np.random.default_rng(1)
    m = rng.uniform(0.5, 2.0, size=(4, 3))
    c = rng.normal(size=(4, 3, 2))
    rho = rng.uniform(0.1, 1.0, size=(4, 3))
    I = inertia_matrix(m, c, m * rho ** 2)
    np.testing.assert_allclose(centre_of_mass(I), c, atol=1e-12)
    np.testing.assert_allclose(radius_of_gyration(I), rho, atol=1e-12)
    p = rng.normal(size=(4, 3, 3))
    assert percussion_axis(I, p).shape == (4, 3, 3)
    np.testing.assert_allclose(percussion_pole(I, percussion_axis(I, p)), p, atol=1e-9)
    assert drawable_conic(I).shape == (4, 3, 3, 3)
    B = Inertia(I)
    assert B.mass.shape == (4, 3) and "batch" in repr(B)


def test_geometry_classes_when_available():
    geometry = pytest.importorskip("planargeo.geometry.elements")
    I = Inertia.from_mass(2.0, [1.0, 0.0], radius_of_gyration=0.5)
    L = I.percussion_axis([0.0, 0.0, 1.0])
    assert isinstance(L, geometry.Line)
    np.testing.assert_allclose(L.array, [0.0, 2.0, 2.5])
    assert isinstance(I.percussion_pole([0.0, 0.0, 1.0]), geometry.Point)
    assert isinstance(I.drawable_conic(), geometry.Conic)


def test_drawable_conic_matches_geo_circle():
    geometry = pytest.importorskip("planargeo.geometry.elements")
    I = Inertia.from_mass(3.0, [1.5, -0.5], radius_of_gyration=0.8)
    C = I.drawable_conic().matrix
    ref = geometry.Conic.circle((1.5, -0.5), 0.8).matrix
    k = C[0, 0] / ref[0, 0]
    np.testing.assert_allclose(C, k * ref, atol=1e-12)
    assert k > 0
