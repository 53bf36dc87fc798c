"""Recursive forward dynamics (thesis 3.6) against independent references.

References: Pinocchio's ``aba`` on the same mechanism (``bench.pinocchio_forward``:
composite joints for the multi-dof kinds, external wrenches as ``Jᵀ f``), hand-derived
closed forms (Lagrange's equations for single and double pendulums, a free body, a
slider), and the inverse dynamics round trip.  More Pinocchio checks in test_pinocchio.py.
"""
import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from planargeo.algorithms.aba import articulated_body, forward_dynamics
from planargeo.algorithms.crba import forward_dynamics_crba, mass_matrix
from planargeo.algorithms.rnea import inverse_dynamics, newton_euler
from planargeo.errors import SingularConfigurationError
from planargeo.mechanics.model import JOINT_DOFS, Body, Joint, Model, chain_model, random_model

pytest.importorskip("pinocchio")
from bench import pinocchio_forward  # noqa: E402  (benchmarks/bench.py: the Pinocchio reference)

ALL_KINDS = tuple(JOINT_DOFS)
G = 9.81


def _random_state(m, rng, batch=()):
    q, qd, tau = rng.normal(size=(3,) + batch + (m.nq,))
    f_ext = rng.normal(size=batch + (m.N, 3))
    return q, qd, tau, f_ext


def _assert_close_cond(a, b, H):
    """Relative agreement scaled by cond(H): |a-b| <= 1e-14 cond(H) max|b| (+ a small floor)."""
    cond = np.max(np.linalg.cond(H))
    scale = max(np.abs(b).max(), 1.0)
    err = np.abs(a - b).max() / scale
    assert err <= 1e-14 * cond + 1e-12, f"error {err:.3g} with cond(H) {cond:.3g}"


# -- ABA vs Pinocchio ---------------------------------------------------------
@pytest.mark.parametrize("N", [1, 2, 5, 20, 50, 200])
@pytest.mark.parametrize("tree", [False, True])
def test_aba_matches_pinocchio_revolute_prismatic(N, tree):
    m = random_model(N, seed=N, kinds=("revolute", "prismatic"), tree=tree)
    rng = np.random.default_rng(N)
    q, qd, tau, f_ext = _random_state(m, rng, (3,))
    H = mass_matrix(m, q)
    _assert_close_cond(forward_dynamics(m, q, qd, tau, f_ext), pinocchio_forward(m, q, qd, tau, f_ext), H)
    # without external loads, single states
    for k in range(3):
        _assert_close_cond(forward_dynamics(m, q[k], qd[k], tau[k]), pinocchio_forward(m, q[k], qd[k], tau[k]), H[k])


@pytest.mark.parametrize("N", [1, 3, 12])
@pytest.mark.parametrize("tree", [False, True])
def test_aba_matches_pinocchio_all_joint_kinds(N, tree):
    m = random_model(N, seed=100 + N, kinds=ALL_KINDS, tree=tree)
    if m.nq == 0:
        pytest.skip("all joints fixed")
    rng = np.random.default_rng(N)
    q, qd, tau, f_ext = _random_state(m, rng, (4,))
    _assert_close_cond(forward_dynamics(m, q, qd, tau, f_ext), pinocchio_forward(m, q, qd, tau, f_ext),
                       mass_matrix(m, q))


def test_scalar_path_equals_batch_path():
    m = random_model(9, seed=4, tree=True)
    rng = np.random.default_rng(4)
    q, qd, tau, f_ext = _random_state(m, rng, (5,))
    batch = forward_dynamics(m, q, qd, tau, f_ext)
    for k in range(5):
        np.testing.assert_allclose(forward_dynamics(m, q[k], qd[k], tau[k], f_ext[k]), batch[k], rtol=1e-12, atol=1e-12)
        np.testing.assert_allclose(forward_dynamics(m, list(q[k]), tuple(qd[k]), tau[k], f_ext[k].tolist()),
                                   batch[k], rtol=1e-12, atol=1e-12)


def test_batch_broadcasting():
    m = chain_model(3)
    q = np.zeros((2, 4, 3))
    out = forward_dynamics(m, q, np.zeros(3), np.zeros((4, 3)))
    assert out.shape == (2, 4, 3)
    np.testing.assert_allclose(out, np.broadcast_to(forward_dynamics(m, np.zeros(3), np.zeros(3), np.zeros(3)), out.shape))


def test_mass_matrix_two_ways():
    m = random_model(15, seed=8, kinds=ALL_KINDS, tree=True)
    q = np.random.default_rng(8).normal(size=(2, m.nq))
    np.testing.assert_allclose(mass_matrix(m, q), mass_matrix(m, q, method="jacobian"), atol=1e-12)


@given(n=st.integers(1, 6), seed=st.integers(0, 2**31), tree=st.booleans(), allkinds=st.booleans())
def test_property_aba_equals_pinocchio_and_rnea_roundtrip(n, seed, tree, allkinds):
    m = random_model(n, seed=seed, kinds=ALL_KINDS if allkinds else ("revolute", "prismatic"), tree=tree)
    rng = np.random.default_rng(seed)
    q, qd, tau, f_ext = _random_state(m, rng)
    if m.nq == 0:
        return
    qdd = forward_dynamics(m, q, qd, tau, f_ext)
    H = mass_matrix(m, q)
    _assert_close_cond(qdd, pinocchio_forward(m, q, qd, tau, f_ext), H)
    # RNEA(ABA(tau)) == tau
    back = inverse_dynamics(m, q, qd, qdd, f_ext)
    assert np.abs(back - tau).max() <= 1e-12 * np.linalg.cond(H) * max(1.0, np.abs(tau).max())


def test_rnea_roundtrip_large_tree_batch():
    m = random_model(50, seed=5, tree=True)
    rng = np.random.default_rng(5)
    q, qd, tau, f_ext = _random_state(m, rng, (2,))
    np.testing.assert_allclose(inverse_dynamics(m, q, qd, forward_dynamics(m, q, qd, tau, f_ext), f_ext), tau,
                               atol=1e-9)


def test_rnea_equals_h_qdd_plus_c():
    """τ = H q̈ + C, with H and C from Pinocchio's forward dynamics: q̈ = ABA(τ) is linear in τ."""
    m = random_model(7, seed=6, kinds=ALL_KINDS, tree=True)
    rng = np.random.default_rng(6)
    q, qd, qdd, _ = _random_state(m, rng)
    z = np.zeros(m.nq)
    free = pinocchio_forward(m, q, qd, z)                                          # -H⁻¹ C
    Hinv = np.array([pinocchio_forward(m, q, qd, e) - free for e in np.eye(m.nq)]).T
    tau = inverse_dynamics(m, q, qd, qdd)
    np.testing.assert_allclose(Hinv @ tau + free, qdd, atol=1e-10)


# -- hand-derived closed forms ------------------------------------------------
@pytest.mark.parametrize("q, qd, tau", [(0.0, 0.0, 0.0), (0.7, 2.0, 1.5), (-2.0, -3.0, -0.2)])
@pytest.mark.parametrize("mass, L", [(1.0, 1.0), (2.5, 0.4)])
def test_single_pendulum_closed_form(q, qd, tau, mass, L):
    """Uniform rod on a pivot: (m L²/3) θ̈ = τ - m g (L/2) cos θ (θ from +x, gravity -y)."""
    m = chain_model(1, mass=mass, length=L)
    expected = (tau - mass * G * L / 2 * np.cos(q)) / (mass * L * L / 3)
    for fd in (forward_dynamics, forward_dynamics_crba):        # both methods against the closed form
        np.testing.assert_allclose(fd(m, [q], [qd], [tau]), [expected], rtol=1e-13)


def _double_pendulum_lagrange(q, qd, tau, m1, L1, m2, L2):
    """Lagrange's equations for two uniform rods, q2 relative (derived by hand).

    T = ½(m1L1²/3)q̇1² + ½ m2 |ċ2|² + ½ (m2L2²/12)(q̇1+q̇2)², c2 = L1 e(q1) + (L2/2) e(q1+q2);
    V = m1 g (L1/2) sin q1 + m2 g (L1 sin q1 + (L2/2) sin(q1+q2)).
    """
    c2, s2 = np.cos(q[1]), np.sin(q[1])
    H11 = m1 * L1**2 / 3 + m2 * (L1**2 + L2**2 / 4 + L1 * L2 * c2) + m2 * L2**2 / 12
    H12 = m2 * (L2**2 / 4 + L1 * L2 / 2 * c2) + m2 * L2**2 / 12
    H22 = m2 * L2**2 / 3
    h = m2 * L1 * L2 / 2 * s2
    C = np.array([-h * (2 * qd[0] * qd[1] + qd[1] ** 2), h * qd[0] ** 2])
    Gv = G * np.array([(m1 * L1 / 2 + m2 * L1) * np.cos(q[0]) + m2 * L2 / 2 * np.cos(q[0] + q[1]),
                       m2 * L2 / 2 * np.cos(q[0] + q[1])])
    return np.linalg.solve([[H11, H12], [H12, H22]], np.asarray(tau) - C - Gv)


@pytest.mark.parametrize("q, qd, tau", [
    ((0.0, 0.0), (0.0, 0.0), (0.0, 0.0)),         # at rest, horizontal
    ((-1.2, 0.5), (0.0, 0.0), (3.0, -1.0)),       # at rest, torques applied
    ((0.3, -2.0), (1.5, -0.7), (0.0, 0.4)),       # moving
])
def test_double_pendulum_lagrange(q, qd, tau):
    m1, L1, m2, L2 = 1.3, 0.8, 0.6, 1.1
    m = Model([Body(m1, (L1 / 2, 0), m1 * L1**2 / 12), Body(m2, (L2 / 2, 0), m2 * L2**2 / 12)],
              [Joint("revolute"), Joint("revolute", (L1, 0, 0))], [-1, 0])
    expected = _double_pendulum_lagrange(np.array(q), np.array(qd), tau, m1, L1, m2, L2)
    np.testing.assert_allclose(forward_dynamics(m, q, qd, tau), expected, rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(forward_dynamics(m, [q], [qd], [tau])[0], expected, rtol=1e-12, atol=1e-12)


def test_slider_on_incline():
    """Prismatic joint along direction phi: m ẍ = τ - m g sin phi."""
    phi = 0.4
    m = Model([Body(2.0, (0.3, 0.1), 0.2)], [Joint("prismatic", (1.0, 2.0, phi))], [-1])
    np.testing.assert_allclose(forward_dynamics(m, [0.5], [3.0], [1.0]), [1.0 / 2.0 - G * np.sin(phi)], rtol=1e-13)


def test_free_body_plane_joint():
    """A free body (plane joint) with its com offset c from the body origin, spinning at ω without forces:
    the com moves uniformly, so the origin o = c_w - R c accelerates by ω² R(θ) c (the kappa cross terms)."""
    c = np.array([0.3, -0.2])
    m = Model([Body(1.5, c, 0.4)], [Joint("plane", (0.5, 0.0, 0.3))], [-1], gravity=(0.0, 0.0))
    th, w = 0.9, 2.0
    qdd = forward_dynamics(m, [0.1, -0.4, th], [0.7, 0.2, w], [0.0, 0.0, 0.0])
    R = np.array([[np.cos(th), -np.sin(th)], [np.sin(th), np.cos(th)]])
    # q[0:2] are measured in the joint frame (rotated by 0.3): express the acceleration there
    R0 = np.array([[np.cos(0.3), -np.sin(0.3)], [np.sin(0.3), np.cos(0.3)]])
    np.testing.assert_allclose(qdd[:2], R0.T @ (w * w * R0 @ R @ c), rtol=1e-12)
    assert abs(qdd[2]) < 1e-12
    # and under gravity and a pure couple: com falls with g, θ̈ = τ/J
    m2 = m.with_gravity((0.0, -G))
    qdd2 = forward_dynamics(m2, [0.0, 0.0, 0.0], [0.0, 0.0, 0.0], [0.0, 0.0, 0.8])
    assert abs(qdd2[2] - 0.8 / 0.4) < 1e-12


def test_articulated_inertia_example_3_14():
    """Thesis 3.14 (planar): a body sliding along x inside another: apparent mass m along x, 2m along y."""
    mass = 1.7
    m = Model([Body(mass, (0, 0), 0.3), Body(mass, (0, 0), 0.1)], [Joint("plane"), Joint("prismatic")], [-1, 0])
    w = articulated_body(m, np.zeros(4), np.zeros(4), np.zeros(4))
    np.testing.assert_allclose(w.A[0], np.diag([mass, 2 * mass, 0.4]), atol=1e-14)


def test_workspace_identities():
    """f_i = A_i a_i + d_i (3.13) are the joint forces of inverse dynamics, and τ_i = s_iᵀ f_i (3.5)."""
    m = random_model(10, seed=9, kinds=ALL_KINDS, tree=True)
    rng = np.random.default_rng(9)
    q, qd, tau, f_ext = _random_state(m, rng)
    w = articulated_body(m, q, qd, tau, f_ext)
    ne = newton_euler(m, q, qd, w.qdd, f_ext)
    np.testing.assert_allclose(w.f, ne.f, atol=1e-10)
    np.testing.assert_allclose(w.a, ne.a, atol=1e-10)
    for i in range(m.N):
        np.testing.assert_allclose(w.s(i).T @ w.f[i], tau[m.q_slice(i)], atol=1e-10)
        # articulated inertias are symmetric positive semi-definite
        np.testing.assert_allclose(w.A[i], w.A[i].T, atol=1e-12)
        assert np.linalg.eigvalsh(w.A[i]).min() > -1e-10


def test_fixed_joint_is_a_weld():
    """A body welded to another adds its inertia: same qdd as one merged body."""
    L = 1.0
    welded = Model([Body(1.0, (L / 2, 0), 1 / 12), Body(1.0, (L / 2, 0), 1 / 12)],
                   [Joint("revolute"), Joint("fixed", (L, 0, 0))], [-1, 0])
    merged = chain_model(1, mass=2.0, length=2 * L)
    np.testing.assert_allclose(forward_dynamics(welded, [0.3], [1.0], [0.5]),
                               forward_dynamics(merged, [0.3], [1.0], [0.5]), rtol=1e-13)


# -- singular configurations ----------------------------------------------------
def test_singular_point_mass_on_its_pivot():
    m = Model([Body(1.0, (0.0, 0.0), 0.0)], [Joint("revolute")], [-1])
    with pytest.raises(SingularConfigurationError, match="joint 1 ") as e:
        forward_dynamics(m, [0.0], [0.0], [0.0])
    assert e.value.cond == np.inf
    with pytest.raises(SingularConfigurationError, match="joint 1 "):
        forward_dynamics(m, [[0.0], [1.0]], [[0.0], [0.0]], [[0.0], [0.0]])
    with pytest.raises(SingularConfigurationError, match="mass matrix H is singular"):
        forward_dynamics_crba(m, [0.0], [0.0], [0.0])


@pytest.mark.parametrize("tree", [False, True])
def test_batches_with_loads_and_broadcasting(tree):
    """A (3, 4) batch of states, with f_ext, and qd / f_ext broadcast from one state."""
    m = random_model(12, seed=21, kinds=("revolute", "prismatic", "fixed"), tree=tree)
    rng = np.random.default_rng(21)
    q, qd, tau, f_ext = _random_state(m, rng, (3, 4))
    got = forward_dynamics(m, q, qd, tau, f_ext)
    assert got.shape == (3, 4, m.nq)
    _assert_close_cond(got, pinocchio_forward(m, q, qd, tau, f_ext), mass_matrix(m, q))
    # broadcasting a single qd / f_ext against the batch
    got2 = forward_dynamics(m, q, qd[0, 0], tau, f_ext[0, 0])
    ref2 = pinocchio_forward(m, q, np.broadcast_to(qd[0, 0], q.shape), tau, np.broadcast_to(f_ext[0, 0], (3, 4, m.N, 3)))
    _assert_close_cond(got2, ref2, mass_matrix(m, q))


def test_singular_large_batch():
    m = Model([Body(1.0, (0.0, 0.0), 0.0)], [Joint("revolute")], [-1])
    with pytest.raises(SingularConfigurationError, match="joint 1 "):
        forward_dynamics(m, np.zeros((20, 1)), np.zeros((20, 1)), np.zeros((20, 1)))
