"""Rotations and general planar frame changes of twists, wrenches and inertias (thesis 1.56-1.59, 1.68, 4.7).

References are independent of the code under test:
* the 6x6 spatial transforms of chapter 1 (1.55-1.59) built here from a 3D
  rotation matrix about z and a cross-product matrix, and the 6x6 spatial
  inertia 1.66 of a lamina, all projected on the plane with D (4.1, 4.7):
  ``X_2D = Dᵀ X_3D D`` and ``I_2D = Dᵀ I_3D D``;
* rotating the centre of mass by hand with a 2x2 rotation matrix
  (``m`` and ``J`` are unchanged by a rigid motion) for the active rotation;
* invariance of power ``vᵀf`` and kinetic energy ``½ vᵀIv`` (thesis 1.9).
"""
import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays

from planargeo import errors
from planargeo.screws.inertia import Inertia
from planargeo.screws.twists import (
    X_P, X_P_inv_T, X_frame, X_frame_inv_T, Twist, Wrench, bias_force, inertia_at, inertia_matrix,
    inertia_rotated, inertia_transform, kinetic_energy, momentum, power, rot, rotation_about,
)

fin = st.floats(-10, 10, allow_nan=False, allow_infinity=False)
vec3 = arrays(float, 3, elements=fin)
xy = arrays(float, 2, elements=fin)
angle = st.floats(-2 * np.pi, 2 * np.pi, allow_nan=False)
pos = st.floats(0.1, 10)

# ---------------------------------------------------------------- 3D references (chapter 1, projected with D)
D = np.zeros((6, 3))
D[0, 0] = D[1, 1] = D[5, 2] = 1.0          # thesis 4.1: [vx, vy, vz, wx, wy, wz] -> [vx, vy, wz]


def skew(r):
    x, y, z = r
    return np.array([[0, -z, y], [z, 0, -x], [-y, x, 0.0]])        # thesis 1.52


def Rz(theta):
    """3D rotation by theta about z (the E of 1.56)."""
    c, s = np.cos(theta), np.sin(theta)
    return np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])


def X3_BA(E, r):
    """Twist transform 1.56: translation r_AB followed by rotation E."""
    out = np.zeros((6, 6))
    out[:3, :3] = E
    out[:3, 3:] = E @ skew(r).T
    out[3:, 3:] = E
    return out


def X3_AB(E, r):
    """Its inverse, 1.57."""
    out = np.zeros((6, 6))
    out[:3, :3] = E.T
    out[:3, 3:] = skew(r) @ E.T
    out[3:, 3:] = E.T
    return out


def I3(m, c, Ixx, Iyy, J):
    """Spatial inertia 1.66 of a lamina in the plane z = 0 (centre c, principal inertias Ixx, Iyy, J)."""
    r = np.array([c[0], c[1], 0.0])
    Ibar = np.diag([Ixx, Iyy, J])
    out = np.zeros((6, 6))
    out[:3, :3] = m * np.eye(3)
    out[:3, 3:] = m * skew(r).T
    out[3:, :3] = m * skew(r)
    out[3:, 3:] = Ibar + m * skew(r) @ skew(r).T
    return out


def rot2(theta):
    c, s = np.cos(theta), np.sin(theta)
    return np.array([[c, -s], [s, c]])


def _tol(*xs):
    return 1e-10 * (1 + max(float(np.abs(x).max()) for x in xs)) ** 3


# ---------------------------------------------------------------- transforms vs chapter 1 projected
@given(angle, xy)
def test_X_frame_is_projection_of_spatial_transform_1_56(theta, p):
    r = np.array([p[0], p[1], 0.0])
    BXA = X3_BA(Rz(theta), r)
    np.testing.assert_allclose(X3_AB(Rz(theta), r) @ BXA, np.eye(6), atol=1e-9 * (1 + np.abs(p).max()) ** 2)
    np.testing.assert_allclose(X_frame(theta, p), D.T @ BXA @ D, atol=1e-12 * (1 + np.abs(p).max()))
    # wrenches: 1.58 projected
    np.testing.assert_allclose(X_frame_inv_T(theta, p), D.T @ X3_AB(Rz(theta), r).T @ D,
                               atol=1e-12 * (1 + np.abs(p).max()))


@given(angle)
def test_rot_is_projection_of_the_3d_rotation(theta):
    E6 = X3_BA(Rz(theta), np.zeros(3))                  # pure rotation: block-diag(E, E)
    np.testing.assert_allclose(rot(theta), D.T @ E6 @ D, atol=1e-15)
    np.testing.assert_allclose(rot(theta), D.T @ np.linalg.inv(E6).T @ D, atol=1e-15)   # twists and wrenches alike
    np.testing.assert_allclose(X_frame(theta, [0.0, 0.0]), rot(theta), atol=0)


@given(angle, xy, pos, xy, pos, pos, pos)
def test_inertia_transform_is_projection_of_1_68(theta, p, m, c, Ixx, Iyy, J):
    r = np.array([p[0], p[1], 0.0])
    IA = I3(m, c, Ixx, Iyy, J)
    AXB = X3_AB(Rz(theta), r)
    IB = AXB.T @ IA @ AXB                               # thesis 1.68
    I2 = D.T @ IA @ D
    np.testing.assert_allclose(I2, inertia_matrix(m, c, J), atol=_tol(I2))   # the planar inertia of the lamina
    np.testing.assert_allclose(inertia_transform(I2, theta, p), D.T @ IB @ D, atol=_tol(IB, I2))
    if theta == 0.0:
        np.testing.assert_allclose(inertia_transform(I2, 0.0, p), inertia_at(I2, p), atol=_tol(I2, p))


@given(angle, pos, xy, pos)
def test_inertia_rotated_about_origin_is_projection_of_the_3d_rotation(theta, m, c, J):
    IA = I3(m, c, 1.0, 2.0, J)
    E6 = X3_BA(Rz(theta), np.zeros(3))
    ref = D.T @ (E6 @ IA @ E6.T) @ D                   # body turned by E: I E6ᵀ maps turned twists back, E6 turns the momentum
    I2 = D.T @ IA @ D
    np.testing.assert_allclose(inertia_rotated(I2, theta), ref, atol=_tol(I2))
    np.testing.assert_allclose(inertia_rotated(I2, theta), inertia_transform(I2, theta), atol=_tol(I2))


@given(angle, pos, xy, pos, xy)
def test_inertia_rotated_about_a_point_turns_the_centre_of_mass(theta, m, c, J, q):
    ref = inertia_matrix(m, q + rot2(theta) @ (c - q), J)   # hand: centre of mass turned about q
    I = inertia_matrix(m, c, J)
    np.testing.assert_allclose(inertia_rotated(I, theta, about=q), ref, atol=_tol(I, ref))
    B = Inertia(I).rotated(theta, about=q)
    np.testing.assert_allclose(B.com, q + rot2(theta) @ (c - q), atol=_tol(c, q))
    assert B.mass == pytest.approx(m) and B.rotational_inertia == pytest.approx(J, abs=_tol(I))


@given(angle, xy, xy)
def test_rotation_about_turns_the_pole_about_the_centre(theta, P, q):
    v = Twist.rotation(P, 1.5)
    turned = v.rotated(theta, about=q)
    np.testing.assert_allclose(turned.pole_xy, q + rot2(theta) @ (P - q), atol=_tol(P, q))
    np.testing.assert_allclose(turned.array, rotation_about(theta, q) @ v.array, atol=_tol(P, q))
    f = Wrench.force(P, [0.3, -1.0])                        # a force through P turns with it: still through P'
    g = f.rotated(theta, about=q)
    Pq = q + rot2(theta) @ (P - q)
    np.testing.assert_allclose(g.force_xy, rot2(theta) @ [0.3, -1.0], atol=1e-12)
    assert abs(np.array([Pq[1], -Pq[0], 1.0]) @ g.array) <= _tol(P, q)


# ---------------------------------------------------------------- invariance of power and kinetic energy
@given(angle, xy, vec3, vec3)
def test_power_invariant_under_rotation_and_translation(theta, p, v, f):
    tol = 1e-9 * (1 + np.abs(v).sum() * np.abs(f).sum()) * (1 + np.abs(p).max())
    assert np.isclose(power(X_frame(theta, p) @ v, X_frame_inv_T(theta, p) @ f), v @ f, atol=tol)
    assert np.isclose(Twist(v).rotated(theta, about=p) @ Wrench(f).rotated(theta, about=p), v @ f, atol=tol)
    # rotate, then translate: the classes' composition
    assert np.isclose(Twist(v).rotated(theta).at(p) @ Wrench(f).rotated(theta).at(p), v @ f, atol=tol)


@st.composite
def inertias(draw):
    """A rigid body's inertia, or a general symmetric positive semi-definite (articulated) one."""
    if draw(st.booleans()):
        return inertia_matrix(draw(pos), draw(xy), draw(st.floats(0.0, 10)))
    # entries on a 1e-6 grid: products of tiny entries would underflow to subnormals, which the
    # validation rightly refuses as an inertia of no size (asymmetry, eigenvalue -5e-324)
    L = draw(arrays(float, (3, 3), elements=st.floats(-3, 3).map(lambda x: round(x, 6))))
    return L @ L.T


@given(inertias(), angle, xy, xy, vec3)
def test_kinetic_energy_and_momentum_invariant_under_frame_changes(I, theta, p, q, v):
    scale = 1e-9 * (1 + np.abs(I).max()) * (1 + np.abs(v).max()) ** 2 * (1 + np.abs(p).max() + np.abs(q).max()) ** 2
    # passive (1.68): the same motion seen from a translated and rotated frame
    X = X_frame(theta, p)
    IB = inertia_transform(I, theta, p)
    assert np.isclose(kinetic_energy(IB, X @ v), kinetic_energy(I, v), atol=scale)
    np.testing.assert_allclose(momentum(IB, X @ v), X_frame_inv_T(theta, p) @ momentum(I, v), atol=scale)
    # active: the body and its motion turned about q, then expressed at p
    M = rotation_about(theta, q)
    Ir = inertia_at(inertia_rotated(I, theta, about=q), p)
    vr = X_P(p) @ M @ v
    assert np.isclose(kinetic_energy(Ir, vr), kinetic_energy(I, v), atol=scale)
    np.testing.assert_allclose(momentum(Ir, vr), X_P_inv_T(p) @ np.linalg.inv(M).T @ momentum(I, v), atol=scale)


def test_inertia_rotated_closed_form():
    # hand: body (m = 2, J = 0.5) at (2, 0), turned by 90° about (1, 0): centre (1, 1)
    I = inertia_rotated(inertia_matrix(2.0, [2.0, 0.0], 0.5), np.pi / 2, about=[1.0, 0.0])
    np.testing.assert_allclose(I, [[2.0, 0.0, -2.0], [0.0, 2.0, 2.0], [-2.0, 2.0, 0.5 + 2.0 * 2.0]], atol=1e-14)
    # batches broadcast over theta
    Ib = inertia_rotated(inertia_matrix(1.0, [1.0, 0.0], 0.1), np.array([0.0, np.pi]))
    np.testing.assert_allclose(Ib[1], inertia_matrix(1.0, [-1.0, 0.0], 0.1), atol=1e-14)


# ---------------------------------------------------------------- bad inertias: type and message
INDEF = np.diag([1.0, 1.0, -1.0])
NONSYM = np.array([[1.0, 0.5, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]])
V = [0.0, 0.0, 1.0]

CALLS = {
    "kinetic_energy": lambda I: kinetic_energy(I, V),
    "momentum": lambda I: momentum(I, V),
    "inertia_at": lambda I: inertia_at(I, [1.0, 2.0]),
    "bias_force": lambda I: bias_force(I, V),
    "inertia_transform": lambda I: inertia_transform(I, 0.3, [1.0, 2.0]),
    "inertia_rotated": lambda I: inertia_rotated(I, 0.3, about=[1.0, 2.0]),
}


@pytest.mark.parametrize("fn", sorted(CALLS))
@pytest.mark.parametrize("bad", [INDEF, -np.eye(3), np.stack([np.eye(3), INDEF])], ids=["indef", "negdef", "batch"])
def test_indefinite_inertia_rejected(fn, bad):
    with pytest.raises(errors.SingularInertiaError,
                       match=r"^inertia must be positive semi-definite, got smallest eigenvalue -1 ") as info:
        CALLS[fn](bad)
    assert isinstance(info.value, ValueError)


@pytest.mark.parametrize("fn", sorted(CALLS))
def test_non_symmetric_inertia_rejected(fn):
    with pytest.raises(errors.InputError, match=r"^inertia must be symmetric, got asymmetry 0\.5$"):
        CALLS[fn](NONSYM)


@pytest.mark.parametrize("fn", sorted(CALLS))
def test_point_mass_accepted(fn):
    out = CALLS[fn](inertia_matrix(2.0, [1.0, -0.5], 0.0))      # singular, positive semi-definite
    assert np.all(np.isfinite(out))


def test_kinetic_energy_of_the_audit_example_is_an_error_not_negative():
    # the audit found kinetic_energy(diag(1, 1, -1), [0, 0, 1]) == -0.5
    with pytest.raises(errors.SingularInertiaError, match="inertia must be positive semi-definite"):
        kinetic_energy(np.diag([1.0, 1.0, -1.0]), [0.0, 0.0, 1.0])
    # a point mass at (1, 0) spinning about the origin: ½ m d² ω² = 1 (hand)
    assert float(kinetic_energy(inertia_matrix(2.0, [1.0, 0.0], 0.0), [0.0, 0.0, 1.0])) == pytest.approx(1.0)
