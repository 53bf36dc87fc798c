"""Articulated mobility algorithm (thesis 7.4.1; trees 9.45) against independent references.

References (``test_articulated_reference``): Pinocchio and the KKT solve in maximal coordinates
for the chain (tree) with body ``i``'s descendants cut off; hand closed forms (7.42).
"""
from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from planargeo.algorithms.articulated_mobility import articulated_mobility, mobility_recursion
from planargeo.errors import SingularConfigurationError
from planargeo.mechanics.joints import R_of
from planargeo.mechanics.kinematics import kinematics
from planargeo.mechanics.subspaces import T_of, U_of
from planargeo.mechanics.model import Body, Joint, Model, random_model
from test_articulated_reference import dense_mobility, mass_matrix_cond, random_state, without_descendants

ALL_KINDS = ("revolute", "prismatic", "revolute_prismatic", "plane", "fixed")


def _matches_reference(model, q, qd, tau, f_ext):
    r = articulated_mobility(model, q, qd, tau, f_ext)
    for i in range(model.N):
        Lam, b = dense_mobility(model, q, qd, tau, f_ext, i)
        np.testing.assert_allclose(r.Lambda_inv[i], Lam, atol=1e-9 * (1 + np.abs(Lam).max()))
        np.testing.assert_allclose(r.b[i], b, atol=1e-8 * (1 + np.abs(b).max()))


@given(n=st.integers(1, 6), seed=st.integers(0, 10_000), loads=st.booleans())
def test_Lambda_and_b_match_dense_truncated_chain(n, seed, loads):
    model = random_model(n, seed=seed)
    q, qd, tau, f_ext = random_state(model, np.random.default_rng(seed), loads=loads)
    _matches_reference(model, q, qd, tau, f_ext)


@pytest.mark.parametrize("seed", range(4))
def test_multi_dof_joints(seed):
    model = random_model(5, seed=200 + seed, kinds=ALL_KINDS)
    q, qd, tau, f_ext = random_state(model, np.random.default_rng(seed))
    _matches_reference(model, q, qd, tau, f_ext)


@given(seed=st.integers(0, 10_000))
def test_mobility_is_symmetric_positive_semidefinite_with_the_jacobian_rank(seed):
    model = random_model(5, seed=seed)
    q, qd, tau, f_ext = random_state(model, np.random.default_rng(seed))
    r = articulated_mobility(model, q, qd, tau, f_ext)
    d = kinematics(model, q)
    for i in range(model.N):
        L = r.Lambda_inv[i]
        np.testing.assert_array_equal(L, L.T)
        w = np.linalg.eigvalsh(L)
        assert w[0] > -1e-10 * w[-1]
        assert np.linalg.matrix_rank(L, tol=1e-9 * w[-1]) == np.linalg.matrix_rank(d.jacobian(i))


def _printed_mobility(I, S, kappa, p, tau):
    """Thesis 7.38a exactly as printed (minus sign before U R^T Lambda^-1)."""
    N = len(I)
    Lam = np.zeros((N, 3, 3))
    for i in range(N):
        s = S[i]
        T = T_of(I[i], s)
        U = U_of(I[i], R_of(s))
        G = s @ T.T @ np.linalg.inv(I[i])
        if i == 0:
            Lam[i] = G
        else:
            P = U @ R_of(s).T
            M = np.eye(3) + P @ Lam[i - 1] @ I[i]
            Lam[i] = np.linalg.solve(M, G - P @ Lam[i - 1])
    return Lam


def test_printed_7_38a_sign_is_wrong():
    # Erratum 7.36/7.38a: "- U R^T Lambda^-1" must be "+ U R^T Lambda^-1".
    model = random_model(4, seed=5)
    q, qd, tau, f_ext = random_state(model, np.random.default_rng(5))
    d = kinematics(model, q, qd, f_ext)
    S = [d.s(i) for i in range(4)]
    printed = _printed_mobility(d.I, S, d.kappa, d.p, [tau[model.q_slice(i)] for i in range(4)])
    for i in (1, 2, 3):
        Lam, _ = dense_mobility(model, q, qd, tau, f_ext, i)
        assert np.abs(printed[i] - Lam).max() > 0.1 * np.abs(Lam).max()
    np.testing.assert_allclose(printed[0], dense_mobility(model, q, qd, tau, f_ext, 0)[0], atol=1e-12)


def test_listing_7_4_1_without_applied_loads_is_wrong_under_gravity():
    # Erratum 7.4.1: p_i = -(v_i x)^T I_i v_i drops -g_i; b_i must include the loads.
    model = random_model(3, seed=9)
    q, qd, tau, _ = random_state(model, np.random.default_rng(9), loads=False)
    d = kinematics(model, q, qd)
    S = [d.s(i) for i in range(3)]
    taus = [tau[model.q_slice(i)] for i in range(3)]
    printed = mobility_recursion(d.I, S, d.kappa, d.p + d.g, taus)     # p without -g
    right = mobility_recursion(d.I, S, d.kappa, d.p, taus)
    _, b_ref = dense_mobility(model, q, qd, tau, None, 2)
    np.testing.assert_allclose(right.b[2], b_ref, atol=1e-9 * np.abs(b_ref).max())
    assert np.abs(printed.b[2] - b_ref).max() > 0.1 * np.abs(b_ref).max()


def test_thesis_7_42_first_body_mobility():
    m, rho, L = 1.7, 0.3, 1.2
    model = Model([Body(m, (L / 2, 0.0), m * rho**2)] * 2,
                  [Joint("revolute"), Joint("revolute", (L, 0.0, 0.0))], [-1, 0], gravity=(0, 0))
    r = articulated_mobility(model, [0.0, 0.5])
    expected = np.zeros((3, 3))
    expected[2, 2] = 4 / (m * (L**2 + 4 * rho**2))
    np.testing.assert_allclose(r.Lambda_inv[0], expected, atol=1e-14)


@given(n=st.integers(2, 7), seed=st.integers(0, 10_000))
def test_trees_match_the_tree_with_descendants_cut_off(n, seed):
    # 9.45: body i's mobility with its descendants cut off, siblings' subtrees loaded on the parents
    model = random_model(n, seed=seed, tree=True)
    q, qd, tau, f_ext = random_state(model, np.random.default_rng(seed))
    _matches_reference(model, q, qd, tau, f_ext)


def test_singular_joint_of_a_tree_raises_with_cond():
    # 7.38 has one singularity check, for chains and trees alike: a point mass on its own pin (sᵀIs = 0)
    model = Model([Body(1.0, (0.5, 0.0), 0.1), Body(1.0, (0.5, 0.0), 0.1), Body(1.0, (0.0, 0.0), 0.0)],
                  [Joint("revolute"), Joint("revolute", (1.0, 0.0, 0.0)), Joint("revolute", (1.0, 0.0, 0.0))],
                  [-1, 0, 0])
    with pytest.raises(SingularConfigurationError, match="of joint 3 is singular") as e:
        articulated_mobility(model, np.zeros(3))
    assert e.value.cond == np.inf


@pytest.mark.parametrize("n, seed", [(50, 0), (50, 1), (200, 2)])
def test_long_chains_match_dense_reference(n, seed):
    # issue 3: agreement with the independent dense reference up to N = 200, with a relative
    # tolerance scaled by the conditioning of the truncated chain's mass matrix
    from test_articulated_reference import EPS

    model = random_model(n, seed=seed)
    q, qd, tau, f_ext = random_state(model, np.random.default_rng(seed))
    r = articulated_mobility(model, q, qd, tau, f_ext)
    for i in (0, 1, n // 2, n - 2, n - 1):
        Lam, b = dense_mobility(model, q, qd, tau, f_ext, i)
        sub = without_descendants(model, i)[0]
        rtol = max(1e-12, 100 * EPS * mass_matrix_cond(sub, q[:sub.nq]))
        assert np.linalg.norm(r.Lambda_inv[i] - Lam) <= rtol * max(np.linalg.norm(Lam), 1.0)
        assert np.linalg.norm(r.b[i] - b) <= rtol * max(np.linalg.norm(b), 1.0)
