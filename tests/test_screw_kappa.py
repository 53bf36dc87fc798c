"""Bias acceleration κ of multi-dof joints with sequential screws (thesis 2.19, 4.61, 4.77; erratum).

References are independent of :func:`planargeo.screws.kappa`:

* central finite differences of the joint's world twist ``v_i(t) = v_par + Σ_j s_j(t) q̇_j``,
  where the columns ``s_j(t)`` are carried by the parent motion and the earlier columns'
  motions, built with ``scipy.linalg.expm`` of the 3×3 SE(2) matrices (no code under test);
* hand derivations (4.77 corrected: ``+ u θ̇ (sin λ, -cos λ, 0)``);
* :func:`planargeo.mechanics.kinematics.kinematics` (DYN-A's own sequential-screw implementation).
"""
import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st
from hypothesis.extra.numpy import arrays
from scipy.linalg import expm

from planargeo.mechanics.joints import plane, revolute_prismatic
from planargeo.mechanics.kinematics import kinematics
from planargeo.mechanics.model import Body, Joint, Model
from planargeo.screws.twists import kappa

fin = st.floats(-3, 3, allow_nan=False, allow_infinity=False)
vec3 = arrays(float, 3, elements=fin)


# ---------------------------------------------------------------- independent SE(2) reference
def hat(t):
    """3x3 SE(2) generator of the twist [vx, vy, w] at the origin (acts on [x, y, 1])."""
    vx, vy, w = t
    return np.array([[0.0, -w, vx], [w, 0.0, vy], [0.0, 0.0, 0.0]])


def Ad(g, t):
    """Twist t carried by the rigid motion g (3x3): [R v + w (p_y, -p_x), w]."""
    R, p = g[:2, :2], g[:2, 2]
    v, w = np.asarray(t[:2]), t[2]
    return np.r_[R @ v + w * np.array([p[1], -p[0]]), w]


def columns_at(t, v_par, S0, q0, qd):
    """Columns of a sequential-screw joint at time t (q = q0 + qd t, parent moving at constant v_par).

    ``S0`` are the columns at q = 0 with the parent at its t = 0 pose; column j is carried by
    the parent's motion and by exp(s_1 q_1) ... exp(s_{j-1} q_{j-1}).
    """
    q = q0 + qd * t
    g = expm(hat(v_par) * t)
    cols = []
    for j in range(S0.shape[1]):
        cols.append(Ad(g, S0[:, j]))
        g = g @ expm(hat(S0[:, j]) * q[j])
    return np.array(cols).T


def kappa_fd(v_par, S0, q0, qd, h=1e-5):
    """d/dt of v_i = v_par + s(t) qd at t = 0 (qdd = 0, a_par = 0): the bias acceleration."""
    vp = columns_at(h, v_par, S0, q0, qd) @ qd
    vm = columns_at(-h, v_par, S0, q0, qd) @ qd
    return (vp - vm) / (2 * h)


# ---------------------------------------------------------------- the reviewer's example
def test_revolute_prismatic_example_cross_term():
    # slide along x by q1 = 0.7 at u = 1.5, then turn (q2 = 0.4) at 2 about the slid pin (0.7, 0)
    s = revolute_prismatic((0.7, 0.0), (1.0, 0.0)).s
    np.testing.assert_allclose(s, [[1.0, 0.0], [0.0, -0.7], [0.0, 1.0]])
    expected = [0.0, -3.0, 0.0]
    # hand derivation: s_2 = [p_y, -p_x, 1] with pin p = (q1, 0) moving at (u, 0):
    # ṡ_2 = [0, -u, 0], ṡ_1 = 0 (parent at rest), κ = ṡ_1 u + ṡ_2 θ̇ = [0, -u θ̇, 0] = [0, -3, 0]
    np.testing.assert_allclose(kappa([0.0, 0.0, 0.0], s, [1.5, 2.0]), expected, atol=1e-15)
    # finite differences of the joint twist
    S0 = np.array([[1.0, 0.0], [0.0, 0.0], [0.0, 1.0]])
    np.testing.assert_allclose(kappa_fd(np.zeros(3), S0, np.array([0.7, 0.4]), np.array([1.5, 2.0])),
                               expected, atol=1e-8)
    # DYN-A's kinematics (a model with this joint at the world origin)
    m = Model([Body(1.0, (0.3, 0.1), 0.2)], [Joint("revolute_prismatic", (0.0, 0.0, 0.0))], [-1], (0.0, 0.0))
    d = kinematics(m, [0.7, 0.4], [1.5, 2.0])
    np.testing.assert_allclose(d.kappa[0], expected, atol=1e-15)
    np.testing.assert_allclose(d.s(0), s, atol=1e-15)


# ---------------------------------------------------------------- finite differences, general columns
def _screw(kind, a, b, c):
    if kind == 0:                                   # rotation about (a, b): the point [b, -a, 1]
        return np.array([b, -a, 1.0])
    n = np.hypot(a, b)
    return np.array([a / n, b / n, 0.0]) if n > 0.1 else np.array([1.0, 0.0, 0.0])


@given(vec3, st.lists(st.tuples(st.integers(0, 1), fin, fin, fin), min_size=1, max_size=3),
       arrays(float, 3, elements=fin), arrays(float, 3, elements=fin))
def test_kappa_matches_finite_differences_of_sequential_screws(v_par, spec, q0, qd):
    k = len(spec)
    S0 = np.array([_screw(*c) for c in spec]).T
    q0, qd = q0[:k], qd[:k]
    S = columns_at(0.0, v_par, S0, q0, qd)          # the columns at the current configuration
    ref = kappa_fd(v_par, S0, q0, qd)
    scale = 1.0 + np.abs(v_par).max() * np.abs(qd).max() * 20 + (np.abs(qd).max() ** 2) * 20
    got = kappa(v_par, S, qd)
    np.testing.assert_allclose(got, ref, atol=1e-6 * scale)
    # the body's own velocity v_i = v_par + s qd gives the same κ ((s qd) x (s qd) = 0)
    np.testing.assert_allclose(kappa(v_par + S @ qd, S, qd), got, atol=1e-9 * scale)
    assert got[2] == 0.0


@pytest.mark.parametrize("kind", ["revolute_prismatic", "plane"])
def test_kappa_matches_kinematics_on_a_moving_parent(kind):
    rng = np.random.default_rng(3)
    bodies = [Body(1.0, (0.4, 0.2), 0.1), Body(1.5, (0.2, -0.3), 0.2)]
    joints = [Joint("plane", (0.3, -0.2, 0.4)), Joint(kind, (0.8, 0.5, -0.7))]
    m = Model(bodies, joints, [-1, 0], (0.0, 0.0))
    for _ in range(5):
        q, qd = rng.normal(size=(2, m.nq))
        d = kinematics(m, q, qd)
        np.testing.assert_allclose(kappa(d.v[0], d.s(1), qd[m.q_slice(1)]), d.kappa[1], atol=1e-12)
        np.testing.assert_allclose(kappa(d.v[1], d.s(1), qd[m.q_slice(1)]), d.kappa[1], atol=1e-12)


def test_plane_joint_columns_from_joints_module():
    # 3 columns (3, 3): translations e, e⊥, then rotation about the slid point; parent at rest
    e = np.array([np.cos(0.3), np.sin(0.3)])
    s = plane((0.5, -0.2), e).s
    ux, uy, th = 0.7, -1.1, 1.3
    # hand: only the rotation column moves, its pin moving at ux e + uy e⊥:
    # ṡ_3 = [ṗ_y, -ṗ_x, 0], κ = ṡ_3 θ̇
    pdot = ux * e + uy * np.array([-e[1], e[0]])
    np.testing.assert_allclose(kappa(np.zeros(3), s, [ux, uy, th]), [pdot[1] * th, -pdot[0] * th, 0.0],
                               atol=1e-14)


def test_kappa_batch_broadcasts_like_loop():
    rng = np.random.default_rng(0)
    v = rng.normal(size=(4, 3))
    S = rng.normal(size=(4, 3, 2))
    qd = rng.normal(size=(4, 2))
    out = kappa(v, S, qd)
    assert out.shape == (4, 3)
    for i in range(4):
        np.testing.assert_allclose(out[i], kappa(v[i], S[i], qd[i]), atol=1e-14)
