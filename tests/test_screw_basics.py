"""Screw primitives, frame changes and bias terms (thesis 1.6-1.9, 2.19, 3.11, 4.1-4.8, 5.72).

References are independent: 6x6 spatial operators of chapter 1/2 projected
with D (4.1, 4.7), the closed forms printed in 4.66-4.83 (each re-derived by
hand; all correct as printed except 4.77, which misses the sequential-screw
cross term, see docs/errata.md), and the parallel axis theorem.
"""
import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays

from planargeo.errors import DegenerateGeometryError, NonFiniteError, ShapeError
from planargeo.mechanics.joints import twin_prismatic
from planargeo.screws.twists import (
    X_P, X_P_inv_T, Twist, Wrench, bias_force, crf, crm, inertia_at, inertia_matrix, kappa,
    kinetic_energy, momentum, pole_xy, power, reciprocal, rot, unit_rotation, wrench_axis,
)

fin = st.floats(-10, 10, allow_nan=False, allow_infinity=False)
vec3 = arrays(float, 3, elements=fin)
xy = arrays(float, 2, elements=fin)
pos = st.floats(0.1, 10)
nz = st.floats(0.2, 5) | st.floats(-5, -0.2)

# ---------------------------------------------------------------- 3D references
D = np.zeros((6, 3))
D[0, 0] = D[1, 1] = D[5, 2] = 1.0          # thesis 4.1: [i j 0; 0 0 k]


def skew(r):
    x, y, z = r
    return np.array([[0, -z, y], [z, 0, -x], [-y, x, 0.0]])   # thesis 1.52


def spatial_crm(v6):
    v, w = v6[:3], v6[3:]
    out = np.zeros((6, 6))
    out[:3, :3] = skew(w)
    out[:3, 3:] = skew(v)
    out[3:, 3:] = skew(w)
    return out                                                 # thesis 2.16


def spatial_X(r):
    out = np.eye(6)
    out[:3, 3:] = -skew(r)
    return out                                                 # thesis 1.55


@given(vec3)
def test_crm_is_projection_of_spatial_cross(v):
    # thesis 4.63 == D^T (v3D x) D for the in-plane twist v3D = D v
    ref = D.T @ spatial_crm(D @ v) @ D
    np.testing.assert_allclose(crm(v), ref, atol=1e-12)


@given(vec3)
def test_crf_is_projection_of_spatial_force_cross(v):
    ref = D.T @ (-spatial_crm(D @ v).T) @ D
    np.testing.assert_allclose(crf(v), ref, atol=1e-12)


@given(xy)
def test_X_P_is_projection_of_spatial_transform(p):
    r = np.array([p[0], p[1], 0.0])
    np.testing.assert_allclose(X_P(p), D.T @ spatial_X(r) @ D, atol=1e-12)                    # 4.7/4.8
    np.testing.assert_allclose(X_P_inv_T(p), D.T @ np.linalg.inv(spatial_X(r)).T @ D, atol=1e-12)  # 4.23/4.24


@given(xy)
def test_X_P_inv_T_is_inverse_transpose(p):
    np.testing.assert_allclose(X_P_inv_T(p), np.linalg.inv(X_P(p)).T, atol=1e-12)


@given(vec3, vec3, xy)
def test_power_invariant_under_frame_change(v, f, p):
    vp = X_P(p) @ v
    fp = X_P_inv_T(p) @ f
    assert np.isclose(power(vp, fp), power(v, f), atol=1e-9 * (1 + np.abs(v).sum() * np.abs(f).sum()))
    assert np.isclose(Twist(v).at(p) @ Wrench(f).at(p), v @ f,
                      atol=1e-9 * (1 + np.abs(v).sum() * np.abs(f).sum()))


@given(pos, xy, pos, xy, vec3)
def test_inertia_at_parallel_axis_and_energy(m, c, J, p, v):
    I = inertia_matrix(m, c, J)
    IP = inertia_at(I, p)
    # parallel axis theorem: the same body with its centre at c - p
    np.testing.assert_allclose(IP, inertia_matrix(m, c - p, J), atol=1e-9 * (1 + np.abs(I).max()))
    # thesis 1.68 form with the chapter-1 matrices: I_B = (A X_B)^T I_A (A X_B), A X_B = inv(B X_A)
    AXB = np.linalg.inv(X_P(p))
    np.testing.assert_allclose(IP, AXB.T @ I @ AXB, atol=1e-9 * (1 + np.abs(I).max()))
    # kinetic energy (1.9) and momentum (1.64) consistent
    vp = X_P(p) @ v
    scale = 1e-9 * (1 + np.abs(I).max() * (1 + np.abs(v).max()) ** 2)
    assert np.isclose(kinetic_energy(IP, vp), kinetic_energy(I, v), atol=scale)
    np.testing.assert_allclose(momentum(IP, vp), X_P_inv_T(p) @ momentum(I, v), atol=scale)


def test_kinetic_energy_closed_form():
    # disc m=2, J=0.5 at (1, 0) rotating at w=3 about the origin: 1/2 (J + m d^2) w^2
    I = inertia_matrix(2.0, [1.0, 0.0], 0.5)
    assert kinetic_energy(I, unit_rotation([0.0, 0.0]) * 3.0) == pytest.approx(0.5 * (0.5 + 2.0) * 9.0)


def test_broadcasting():
    P = np.random.default_rng(0).normal(size=(4, 5, 2))
    assert X_P(P).shape == (4, 5, 3, 3)
    I = inertia_matrix(np.ones((4, 5)), P, 1.0)
    assert inertia_at(I, P).shape == (4, 5, 3, 3)
    np.testing.assert_allclose(inertia_at(I, P)[..., :2, 2], 0.0, atol=1e-12)
    assert kappa(np.ones((4, 5, 3)), np.eye(3)[:, :2], np.ones((4, 5, 2))).shape == (4, 5, 3)
    assert bias_force(I, np.ones((4, 5, 3))).shape == (4, 5, 3)


# ---------------------------------------------------------------- bias examples 4.58-4.83
def I458(m, r, C):
    return np.array([[m, 0, 0], [0, m, m * C], [0, m * C, m * (r ** 2 + C ** 2)]])


PARAMS = [
    dict(m=1.0, r=0.3, C=0.7, vx=0.4, vy=-1.2, w=0.9, th=2.0, u=-0.5, lam=0.3, ux=0.2, uy=-0.8),
    dict(m=3.5, r=1.1, C=-0.4, vx=-2.0, vy=0.5, w=-1.7, th=-0.6, u=1.4, lam=2.2, ux=-1.1, uy=0.9),
    dict(m=0.2, r=0.05, C=2.0, vx=0.0, vy=3.0, w=0.0, th=5.0, u=0.0, lam=-1.0, ux=4.0, uy=0.0),
]


@pytest.mark.parametrize("k", PARAMS)
def test_revolute_bias_4_66_to_4_68(k):
    m, C, vx, vy, w, th = k["m"], k["C"], k["vx"], k["vy"], k["w"], k["th"]
    I = I458(m, k["r"], C)
    v = np.array([vx, vy, w + th])                                     # 4.66
    kap = np.array([vy * th, -vx * th, 0.0])                           # 4.67
    W = w + th
    p = np.array([-m * (vy * W + C * W ** 2), m * vx * W, C * m * vx * W])   # 4.68
    np.testing.assert_allclose(kappa(v, [0.0, 0.0, 1.0], th), kap, atol=1e-12)
    np.testing.assert_allclose(bias_force(I, v), p, atol=1e-12)
    # p is a force through the centre of gravity (C, 0): zero moment there (4.24)
    assert abs((X_P_inv_T([C, 0.0]) @ p)[2]) < 1e-12


@pytest.mark.parametrize("k", PARAMS)
def test_prismatic_bias_4_71_to_4_73(k):
    m, C, vx, vy, w, u, lam = k["m"], k["C"], k["vx"], k["vy"], k["w"], k["u"], k["lam"]
    c, s = np.cos(lam), np.sin(lam)
    v = np.array([vx + u * c, vy + u * s, w])                          # 4.71
    kap = np.array([-w * u * s, w * u * c, 0.0])                       # 4.72
    p = np.array([-m * w * (vy + u * s) - m * C * w ** 2, m * w * (vx + u * c), m * w * C * (vx + u * c)])  # 4.73
    np.testing.assert_allclose(kappa(v, [c, s, 0.0], u), kap, atol=1e-12)
    np.testing.assert_allclose(bias_force(I458(m, k["r"], C), v), p, atol=1e-12)


@pytest.mark.parametrize("k", PARAMS)
def test_revolute_prismatic_bias_4_76_to_4_78(k):
    """4.76 and 4.78 as printed; 4.77 corrected (erratum): slide-then-turn adds u θ̇ (sin λ, -cos λ, 0).

    Hand derivation, local frame at the pin (4.58), parent twist (vx, vy, w):
    the slide direction e = (c, s) is carried by the parent, ṡ_1 = w (-s, c, 0);
    the rotation column s_2 = [p_y, -p_x, 1] follows the pin p, which sits at the
    origin and moves at (vx + u c, vy + u s), so ṡ_2 = (vy + u s, -(vx + u c), 0).
    κ = ṡ_1 u + ṡ_2 θ̇.
    """
    m, C, vx, vy, w, u, lam, th = k["m"], k["C"], k["vx"], k["vy"], k["w"], k["u"], k["lam"], k["th"]
    c, s = np.cos(lam), np.sin(lam)
    S = np.array([[c, 0.0], [s, 0.0], [0.0, 1.0]])                    # 4.74
    qd = np.array([u, th])                                             # 4.75
    v_prev = np.array([vx, vy, w])
    v = np.array([vx + u * c, vy + u * s, w + th])                     # 4.76
    np.testing.assert_allclose(v_prev + S @ qd, v, atol=1e-12)
    kap_printed = np.array([-(w * u * s - vy * th), w * u * c - vx * th, 0.0])    # 4.77 as printed
    kap_hand = w * u * np.array([-s, c, 0.0]) + th * np.array([vy + u * s, -(vx + u * c), 0.0])
    np.testing.assert_allclose(kap_hand, kap_printed + u * th * np.array([s, -c, 0.0]), atol=1e-12)
    np.testing.assert_allclose(kappa(v_prev, S, qd), kap_hand, atol=1e-12)
    np.testing.assert_allclose(kappa(v, S, qd), kap_hand, atol=1e-12)   # body velocity: same κ
    if u * th != 0:
        assert np.abs(kappa(v_prev, S, qd) - kap_printed).max() > 0.1 * abs(u * th)
    W = w + th
    p = np.array([-m * (vy + u * s) * W - m * C * W ** 2, m * (vx + u * c) * W, m * C * (vx + u * c) * W])  # 4.78
    np.testing.assert_allclose(bias_force(I458(m, k["r"], C), v), p, atol=1e-12)


@pytest.mark.parametrize("k", PARAMS)
def test_plane_joint_bias_4_81_to_4_83(k):
    m, C, vx, vy, w, ux, uy = k["m"], k["C"], k["vx"], k["vy"], k["w"], k["ux"], k["uy"]
    v = np.array([vx + ux, vy + uy, w])                                # 4.81
    kap = np.array([-uy * w, ux * w, 0.0])                             # 4.82
    p = np.array([-m * w * (uy + vy) - m * C * w ** 2, m * w * (ux + vx), m * C * w * (ux + vx)])  # 4.83
    s = twin_prismatic().s                                             # 4.79
    np.testing.assert_allclose(v, np.array([vx, vy, w]) + s @ [ux, uy], atol=1e-12)   # 4.81 = v_prev + s q̇
    np.testing.assert_allclose(kappa(v, s, [ux, uy]), kap, atol=1e-12)
    np.testing.assert_allclose(bias_force(I458(m, k["r"], C), v), p, atol=1e-12)


@given(pos, xy, pos, xy, nz)
def test_centripetal_force_through_com_towards_pole(m, c, J, q, w):
    # thesis 4.7: p = -(v x)^T I v is a force through the centre of gravity,
    # towards the velocity pole, of magnitude m l w^2
    v = Twist.rotation(q, w).array
    p = bias_force(inertia_matrix(m, c, J), v)
    np.testing.assert_allclose(p[:2], m * w ** 2 * (q - c), atol=1e-9 * (1 + m * w * w * 20))
    assert abs(power(unit_rotation(c), p)) < 1e-8 * (1 + np.abs(p).max() * 20)


@given(vec3, vec3, st.floats(-5, 5))
def test_kappa_is_translation_independent_of_own_axis_rate(v, s, qd):
    k = kappa(v, s, qd)
    assert k[2] == 0.0
    # kappa is a translation, and (v + s qd) x s qd = v x s qd (s x s = 0)
    np.testing.assert_allclose(kappa(v + s * qd, s, qd), k, atol=1e-9 * (1 + np.abs(v).max() * np.abs(s).max() * 10))


def test_bias_force_with_gravity():
    I = inertia_matrix(2.0, [1.0, 0.0], 0.5)
    g = np.array([0.0, -2.0 * 9.81, -2.0 * 9.81 * 1.0])   # weight through (1, 0): tau = x fy
    np.testing.assert_allclose(bias_force(I, np.zeros(3), g), -g)


def test_kappa_bad_shapes():
    with pytest.raises(ShapeError, match="qd must have shape"):
        kappa([0, 0, 1.0], np.eye(3)[:, :2], [1.0, 2.0, 3.0])
    with pytest.raises(ShapeError, match="s must have shape"):
        kappa([0, 0, 1.0], np.zeros((2, 2)), 1.0)


# ---------------------------------------------------------------- classes
def test_twist_features():
    v = Twist.rotation([1.0, 2.0], 3.0)
    np.testing.assert_array_equal(v.array, [6.0, -3.0, 3.0])
    assert float(v.magnitude) == 3.0
    np.testing.assert_allclose(v.pole_xy, [1.0, 2.0])
    np.testing.assert_allclose((X_P([1.0, 2.0]) @ v.array)[:2], 0.0)   # 4.9: zero velocity at the pole
    t = Twist.translation([0.0, 2.0])
    assert bool(t.is_translation) and float(t.magnitude) == 0.0
    assert np.all(np.isnan(t.pole_xy))
    np.testing.assert_allclose(v.at([1.0, 2.0]).array, [0.0, 0.0, 3.0])
    np.testing.assert_allclose((2 * v - v).array, v.array)
    np.testing.assert_allclose((-v + v).array, 0.0)
    np.testing.assert_allclose(v.rotated(np.pi / 2).pole_xy, [-2.0, 1.0], atol=1e-12)
    assert "Twist(" in repr(v)
    with pytest.raises(TypeError):
        v + Wrench.couple(1.0)
    with pytest.raises(ValueError):
        v.array[0] = 1.0


def test_wrench_features_4_26_to_4_32():
    f = Wrench.force([3.0, 4.0], [-4.0, 3.0])     # tangent to the circle r = 5 at (3, 4)
    e, d, n = wrench_axis(f.array)
    assert float(f.magnitude) == pytest.approx(5.0)
    np.testing.assert_allclose(e, [-0.8, 0.6])
    assert float(d) == pytest.approx(5.0)
    np.testing.assert_allclose(n, [0.6, 0.8])
    np.testing.assert_allclose(n * d, [3.0, 4.0])              # 4.30: nearest point
    assert abs(f.at([3.0, 4.0]).moment) < 1e-12               # 4.26/4.27 on the line
    c = Wrench.couple(2.0)
    assert float(c.magnitude) == 0.0 and bool(c.is_couple)
    assert np.all(np.isnan(c.direction)) and float(c.distance) == np.inf
    np.testing.assert_allclose(c.at([5.0, -7.0]).array, [0.0, 0.0, 2.0])   # a couple is free
    assert np.isnan(wrench_axis([0.0, 0.0, 0.0])[1])


def test_reciprocity():
    v = Twist.rotation([1.0, 1.0], 2.0)
    f = Wrench.force([1.0, 1.0], [3.0, -1.0])
    assert float(v @ f) == 0.0 and float(f @ v) == 0.0 and bool(v.reciprocal(f))
    assert not bool(Twist.rotation([0.0, 0.0]).reciprocal(f))
    # a couple is reciprocal to every translation, a translation to every force along it
    assert bool(reciprocal(Twist.translation([1.0, 2.0]).array, Wrench.couple(1.0).array))
    assert bool(Twist.translation([1.0, 2.0]).reciprocal(Wrench.force([7.0, 3.0], [-2.0, 1.0])))


@given(xy, fin.filter(lambda w: abs(w) > 1e-3), xy)
def test_powerless_force_through_pole(q, w, d):
    # any force whose line passes through the pole of v does no work on v (5.69)
    v = Twist.rotation(q, w)
    f = Wrench.force(q, d)
    assert abs(float(v @ f)) <= 1e-9 * (1 + abs(w) * np.abs(d).max() * 100)


def test_pole_xy_no_warning_for_translations():
    out = pole_xy(np.array([[1.0, 0.0, 0.0], [0.0, 2.0, 1.0]]))
    assert np.all(np.isnan(out[0])) and np.allclose(out[1], [-2.0, 0.0])


def test_rot_preserves_power():
    v, f = np.array([1.0, 2.0, 3.0]), np.array([-1.0, 0.5, 2.0])
    assert power(rot(0.7) @ v, rot(0.7) @ f) == pytest.approx(power(v, f))


def test_bad_inputs():
    with pytest.raises(ShapeError, match="twist must have shape"):
        Twist([1.0, 2.0])
    with pytest.raises(NonFiniteError, match="wrench must be finite"):
        Wrench([1.0, np.nan, 0.0])
    with pytest.raises(NonFiniteError, match="omega must be finite"):
        Twist.rotation([0.0, 0.0], np.inf)
    with pytest.raises(ShapeError, match="point must have shape"):
        Wrench.force([0.0, 0.0, 1.0], [1.0, 0.0])
    with pytest.raises(DegenerateGeometryError, match="twist is zero"):
        Twist([0.0, 0.0, 0.0]).pole
    with pytest.raises(DegenerateGeometryError, match="wrench is zero"):
        Wrench([0.0, 0.0, 0.0]).line
    with pytest.raises(ShapeError, match="inertia must have shape"):
        inertia_at(np.eye(2), [0.0, 0.0])


def test_pole_and_line_as_geometry_objects():
    geometry = pytest.importorskip("planargeo.geometry.elements")
    v = Twist.rotation([1.0, 2.0], 3.0)
    assert isinstance(v.pole, geometry.Point)
    np.testing.assert_allclose(np.asarray(v.pole.array), v.array)
    f = Wrench.force([0.0, 1.0], [2.0, 0.0])
    assert isinstance(f.line, geometry.Line) and isinstance(f.polar, geometry.Line)
    np.testing.assert_allclose(np.asarray(f.line.array), f.array)
    with pytest.raises(ShapeError, match="twist must be a single"):
        Twist(np.ones((2, 3))).pole


@given(xy, xy, nz, nz, nz)
def test_acceleration_kinematics_4_48_to_4_54(V, S, w, qd, qdd):
    # previous body rotating about V at w, revolute joint at S with speed qd, acceleration qdd
    from planargeo.screws.twists import add_twists
    k = np.linalg.norm(S - V)
    if k < 1e-2:
        return
    v_prev = Twist.rotation(V, w).array
    s = unit_rotation(S)
    v_i = v_prev + s * qd
    kap = kappa(v_i, s, qd)
    # 4.53: a translation from the pole of v_{i-1} towards the joint, of size w qd k
    np.testing.assert_allclose(kap, np.r_[w * qd * (S - V), 0.0], atol=1e-9 * 100 * (1 + abs(w * qd)))
    assert np.linalg.norm(kap) == pytest.approx(abs(w * qd) * k)
    # 4.48: the velocity pole of body i divides V S with beta = qd / (qd + w)
    if abs(qd + w) > 1e-3:
        assert add_twists(v_prev, s * qd).beta == pytest.approx(qd / (qd + w))
    # 4.54: s qdd + kappa is a rotation about a point rho = w qd k / qdd from the joint
    c = add_twists(s * qdd, kap)
    assert c.case == "rotation_translation"
    P = c.sum.pole_xy
    assert np.linalg.norm(P - S) == pytest.approx(abs(w * qd * k / qdd), rel=1e-7, abs=1e-9)
    assert abs((P - S) @ (S - V)) < 1e-7 * (1 + k * k) * (1 + abs(w * qd / qdd))   # perpendicular offset (4.16)
