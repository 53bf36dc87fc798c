"""Articulated inertia algorithm (thesis 7.1.1) against independent references and closed forms.

References (``test_articulated_reference``): Pinocchio and the KKT solve in maximal
coordinates for the free-floating subtrees (``A_i``, ``d_i``) and the true motion;
Newton-Euler for the joint forces; the thesis's closed form 7.19 derived by hand.
"""
from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from planargeo.algorithms.articulated_inertia import articulated_inertia, articulated_recursion
from planargeo.errors import COND_LIMIT, SingularConfigurationError, ShapeError
from planargeo.mechanics.kinematics import kinematics
from planargeo.mechanics.model import Body, Joint, Model, random_model
from planargeo.screws.twists import inertia_matrix
from test_articulated_reference import (dense_articulated, mass_matrix_cond, newton_euler_forces, random_state,
                                       reference_accelerations)

KINDS = ("revolute", "prismatic")
ALL_KINDS = ("revolute", "prismatic", "revolute_prismatic", "plane", "fixed")


@given(n=st.integers(1, 6), seed=st.integers(0, 10_000), tree=st.booleans())
def test_A_and_d_match_dense_free_floating_subtree(n, seed, tree):
    model = random_model(n, seed=seed, tree=tree, kinds=KINDS)
    rng = np.random.default_rng(seed)
    q, qd, tau, f_ext = random_state(model, rng)
    r = articulated_inertia(model, q, qd, tau, f_ext)
    for i in range(model.N):
        A_ref, d_ref = dense_articulated(model, q, qd, tau, f_ext, i)
        scale = np.abs(A_ref).max()
        np.testing.assert_allclose(r.A[i], A_ref, atol=1e-9 * scale)
        np.testing.assert_allclose(r.d[i], d_ref, atol=1e-8 * (1 + np.abs(d_ref).max()))


@pytest.mark.parametrize("seed", range(4))
def test_multi_dof_joints_match_dense(seed):
    model = random_model(5, seed=100 + seed, kinds=ALL_KINDS, tree=bool(seed % 2))
    rng = np.random.default_rng(seed)
    q, qd, tau, f_ext = random_state(model, rng)
    r = articulated_inertia(model, q, qd, tau, f_ext)
    for i in range(model.N):
        A_ref, d_ref = dense_articulated(model, q, qd, tau, f_ext, i)
        np.testing.assert_allclose(r.A[i], A_ref, atol=1e-9 * np.abs(A_ref).max())
        np.testing.assert_allclose(r.d[i], d_ref, atol=1e-8 * (1 + np.abs(d_ref).max()))


@given(seed=st.integers(0, 10_000))
def test_articulated_equation_of_motion_holds_along_the_true_motion(seed):
    # f_i = A_i a_i + d_i (7.1) with a_i from Pinocchio and f_i from Newton-Euler (3.9) along that motion
    model = random_model(6, seed=seed, tree=True)
    q, qd, tau, f_ext = random_state(model, np.random.default_rng(seed))
    a = reference_accelerations(model, q, qd, tau, f_ext)
    f = newton_euler_forces(model, q, qd, a, f_ext)
    r = articulated_inertia(model, q, qd, tau, f_ext)
    lhs = np.einsum("nij,nj->ni", r.A, a) + r.d
    np.testing.assert_allclose(lhs, f, atol=1e-8 * (1 + np.abs(f).max()))


@given(seed=st.integers(0, 10_000))
def test_subspace_identities(seed):
    # s^T T = 1 (6.32), R^T U = 1 (6.35), T^T U = 0 (6.46), T s^T + R U^T = 1 (6.75), A symmetric PD
    model = random_model(5, seed=seed, kinds=ALL_KINDS, tree=True)
    q, qd, tau, f_ext = random_state(model, np.random.default_rng(seed))
    r = articulated_inertia(model, q, qd, tau, f_ext)
    for i in range(model.N):
        s, T, R, U = r.S[i], r.T[i], r.R[i], r.U[i]
        k = s.shape[1]
        np.testing.assert_allclose(s.T @ T, np.eye(k), atol=1e-10)
        np.testing.assert_allclose(R.T @ U, np.eye(3 - k), atol=1e-10)
        np.testing.assert_allclose(T.T @ U, 0.0, atol=1e-10)
        np.testing.assert_allclose(s.T @ R, 0.0, atol=1e-12)
        np.testing.assert_allclose(T @ s.T + R @ U.T, np.eye(3), atol=1e-10)
        np.testing.assert_array_equal(r.A[i], r.A[i].T)
        assert np.linalg.eigvalsh(r.A[i])[0] > 0
        # U = A^-1 R (R^T A^-1 R)^-1 (6.99), literally
        AiR = np.linalg.solve(r.A[i], R)
        if k < 3:
            np.testing.assert_allclose(U, AiR @ np.linalg.inv(R.T @ AiR), atol=1e-8 * np.abs(U).max())


def test_thesis_7_19_two_body_articulated_inertia_closed_form():
    m, rho, L = 1.3, 0.37, 1.1
    D = L**2 + 4 * rho**2
    for phi in np.linspace(-3, 3, 7):
        c, s = np.cos(phi), np.sin(phi)
        model = Model([Body(m, (L / 2, 0.0), m * rho**2)] * 2,
                      [Joint("revolute"), Joint("revolute", (L, 0.0, 0.0))], [-1, 0], gravity=(0, 0))
        A1 = articulated_inertia(model, [0.0, phi]).A[0]
        expected = np.array([
            [m + m * (L**2 * c**2 + 4 * rho**2) / D, m * L**2 / D * s * c, m * L**3 / D * s * c],
            [m * L**2 / D * s * c, m + m * (L**2 * s**2 + 4 * rho**2) / D,
             m * L / 2 + (m * L**3 * s**2 + 4 * m * L * rho**2) / D],
            [m * L**3 / D * s * c, m * L / 2 + (m * L**3 * s**2 + 4 * m * L * rho**2) / D,
             m * rho**2 + 1.25 * m * L**2 - m * L**4 * c**2 / D]])
        np.testing.assert_allclose(A1, expected, rtol=1e-13, atol=1e-14)


def test_printed_plus_g_in_listing_7_1_1_is_wrong_under_gravity():
    # Erratum 7.1.1: d_N = -(v_N x)^T I_N v_N + g_N as printed flips the applied loads.
    model = random_model(4, seed=7)
    q, qd, tau, f_ext = random_state(model, np.random.default_rng(7))
    d = kinematics(model, q, qd, f_ext)
    S = [d.s(i) for i in range(4)]
    taus = [tau[model.q_slice(i)] for i in range(4)]
    right = articulated_recursion(d.I, S, d.kappa, d.p, taus)
    printed = articulated_recursion(d.I, S, d.kappa, d.p + 2 * d.g, taus)   # -(v x)^T I v + g
    A_ref, d_ref = dense_articulated(model, q, qd, tau, f_ext, 0)
    np.testing.assert_allclose(right.d[0], d_ref, atol=1e-9 * np.abs(d_ref).max())
    assert np.abs(printed.d[0] - d_ref).max() > 0.5 * np.abs(d_ref).max()


def test_massless_tip_raises_singular_configuration_with_cond():
    # a point mass sitting on its own revolute joint: s^T A s = 0
    I = [inertia_matrix(1.0, [0.5, 0.0], 0.1), inertia_matrix(1.0, [1.0, 0.0], 0.0)]
    S = [np.array([[0.0], [0.0], [1.0]]), np.array([[0.0], [-1.0], [1.0]])]
    with pytest.raises(SingularConfigurationError, match="sᵀAs of joint 2 is singular") as e:
        articulated_recursion(I, S, np.zeros((2, 3)), np.zeros((2, 3)), [np.zeros(1)] * 2)
    assert e.value.cond > COND_LIMIT


def test_model_level_point_mass_on_its_joint_raises():
    model = Model([Body(1.0, (0.5, 0.0), 0.1), Body(1.0, (0.0, 0.0), 0.0)],
                  [Joint("revolute"), Joint("revolute", (1.0, 0.0, 0.0))], [-1, 0])
    with pytest.raises(SingularConfigurationError) as e:
        articulated_inertia(model, [0.3, 0.2])
    assert e.value.cond > COND_LIMIT


def test_point_mass_bodies_off_their_joints_are_fine():
    model = Model([Body(1.0, (0.5, 0.0), 0.0), Body(2.0, (1.0, 0.0), 0.0)],
                  [Joint("revolute"), Joint("revolute", (1.0, 0.0, 0.0))], [-1, 0])
    q, qd, tau = [0.3, -0.4], [0.5, 1.0], [0.2, -0.1]
    r = articulated_inertia(model, q, qd, tau)
    A_ref, d_ref = dense_articulated(model, q, qd, tau, None, 0)
    np.testing.assert_allclose(r.A[0], A_ref, atol=1e-10)
    np.testing.assert_allclose(r.d[0], d_ref, atol=1e-10)


def test_batched_state_is_rejected_with_shape_error():
    model = random_model(2, seed=1)
    with pytest.raises(ShapeError, match="q must describe one state"):
        articulated_inertia(model, np.zeros((2, model.nq)))


def test_bad_tau_shape_names_tau():
    model = random_model(2, seed=1)
    with pytest.raises(ShapeError, match="tau"):
        articulated_inertia(model, np.zeros(model.nq), None, np.zeros(model.nq + 1))


@pytest.mark.parametrize("n, seed, tree", [(50, 0, False), (50, 1, True), (200, 2, False), (200, 3, True)])
def test_long_chains_and_trees_match_dense_reference(n, seed, tree):
    # issue 3: agreement with the independent dense reference up to N = 200, with a relative
    # tolerance scaled by the conditioning of the (sub)tree's mass matrix
    from test_articulated_reference import EPS, floating_subtree

    model = random_model(n, seed=seed, tree=tree)
    q, qd, tau, f_ext = random_state(model, np.random.default_rng(seed))
    r = articulated_inertia(model, q, qd, tau, f_ext)
    for i in (0, 1, n // 2, n - 2, n - 1):
        A_ref, d_ref = dense_articulated(model, q, qd, tau, f_ext, i)
        sub, q_sub, *_ = floating_subtree(model, q, qd, f_ext, i)
        rtol = max(1e-12, 100 * EPS * mass_matrix_cond(sub, q_sub))
        assert np.linalg.norm(r.A[i] - A_ref) <= rtol * np.linalg.norm(A_ref)
        assert np.linalg.norm(r.d[i] - d_ref) <= rtol * max(np.linalg.norm(d_ref), 1.0)


@pytest.mark.parametrize("phi", [0.0, np.pi])
def test_figure_7_4_effective_mass_is_flat_in_lambda_when_in_line(phi):
    # Figure 7.4 / 7.22: "the effective mass ratio decreases as the size ratio λ increases" holds only
    # for cos²φ < 1; in line (φ = 0 or π) m_x = 2m for every λ (docs/errata.md, chapter 7 explorers, 1)
    from planargeo import scenes

    values = [scenes.build("two-body", rho=1.0 / lam, L=1.0, phi=phi).quantities["mx_over_m"]
              for lam in (0.1, 1.0, 2.0, 5.0, 50.0)]
    np.testing.assert_allclose(values, 2.0, rtol=1e-12)
    bent = [scenes.build("two-body", rho=1.0 / lam, L=1.0, phi=0.7).quantities["mx_over_m"]
            for lam in (0.1, 1.0, 2.0, 5.0, 50.0)]
    assert np.all(np.diff(bent) < 0)                               # strictly decreasing once bent
