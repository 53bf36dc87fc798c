"""Chain splitting (thesis 7.6: 7.54, 7.56) against independent references.

References (``test_articulated_reference``): Pinocchio's ``aba`` (revolute and prismatic
joints), the KKT solve in maximal coordinates (every joint kind, body accelerations),
Newton-Euler for the joint forces, a hand-derived two-mass example.
"""
from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from planargeo.algorithms.chain_splitting import (
    chain_split, forward_dynamics_mobility_split, mobility_split, split_acceleration, split_force)
from planargeo.errors import COND_LIMIT, SingularConfigurationError, TopologyError
from planargeo.mechanics.model import Body, Joint, Model, random_model
from planargeo.screws.twists import inertia_matrix
from test_articulated_reference import (newton_euler_forces, random_state, reference_accelerations, reference_qdd,
                                       rtol_for)

ALL_KINDS = ("revolute", "prismatic", "revolute_prismatic", "plane", "fixed")


def _close(x, ref, rtol):
    err = np.linalg.norm(x - ref) / max(np.linalg.norm(ref), 1.0)
    assert err <= rtol, (err, rtol)


@given(n=st.integers(1, 8), seed=st.integers(0, 10_000), loads=st.booleans())
def test_qdd_matches_pinocchio_random_chains(n, seed, loads):
    model = random_model(n, seed=seed)
    q, qd, tau, f_ext = random_state(model, np.random.default_rng(seed), loads=loads)
    ref = reference_qdd(model, q, qd, tau, f_ext)
    _close(forward_dynamics_mobility_split(model, q, qd, tau, f_ext), ref, rtol_for(model, q))


@pytest.mark.parametrize("n", [50, 200])
def test_qdd_matches_pinocchio_long_chains(n):
    model = random_model(n, seed=n + 1)
    q, qd, tau, f_ext = random_state(model, np.random.default_rng(n))
    ref = reference_qdd(model, q, qd, tau, f_ext)
    _close(forward_dynamics_mobility_split(model, q, qd, tau, f_ext), ref, rtol_for(model, q))


@pytest.mark.parametrize("seed", range(4))
def test_multi_dof_joints(seed):
    model = random_model(6, seed=300 + seed, kinds=ALL_KINDS)
    q, qd, tau, f_ext = random_state(model, np.random.default_rng(seed))
    ref = reference_qdd(model, q, qd, tau, f_ext)                 # the KKT solve (multi-dof joints)
    _close(forward_dynamics_mobility_split(model, q, qd, tau, f_ext), ref, rtol_for(model, q))


@given(seed=st.integers(0, 10_000))
def test_direct_accelerations_and_forces_match_newton_euler(seed):
    model = random_model(6, seed=seed)
    q, qd, tau, f_ext = random_state(model, np.random.default_rng(seed))
    a = reference_accelerations(model, q, qd, tau, f_ext)
    f = newton_euler_forces(model, q, qd, a, f_ext)
    r = mobility_split(model, q, qd, tau, f_ext)
    tol = 1e-8 * (1 + np.abs(f).max())
    np.testing.assert_allclose(r.a, a, atol=tol)     # (7.54)
    np.testing.assert_allclose(r.f, f, atol=tol)     # (7.56), f[0] by 6.113b


def test_tip_load_reaches_every_body_in_one_step():
    # "what total effect an externally applied load has on any body": a load on the
    # tip changes a_i as the dense solution does, for every i
    model = random_model(5, seed=4)
    q, qd, tau, _ = random_state(model, np.random.default_rng(4), loads=False)
    load = np.zeros((5, 3))
    load[4] = [3.0, -1.0, 0.5]
    a0 = mobility_split(model, q, qd, tau).a
    a1 = mobility_split(model, q, qd, tau, load).a
    w0 = reference_accelerations(model, q, qd, tau)
    w1 = reference_accelerations(model, q, qd, tau, load)
    np.testing.assert_allclose(a1 - a0, w1 - w0, atol=1e-9)


def test_split_functions_hand_example():
    # two unit point masses: body i at (1, 0) on a pin at the origin, body i+1 on a pin
    # at (1, 0) with its mass at (2, 0); unit torque on joint i+1 only.
    A2 = inertia_matrix(1.0, [2.0, 0.0], 0.0)
    s2 = np.array([[0.0], [-1.0], [1.0]])
    T2 = A2 @ s2 / (s2.T @ A2 @ s2)
    Lam1 = np.diag([0.0, 0.0, 1.0])          # s s^T / (m r^2) for the first mass
    args = (Lam1, np.zeros(3), A2, np.zeros(3), T2, s2, [1.0], np.zeros(3))
    a1 = split_acceleration(*args)
    f2 = split_force(*args)
    # dense: H = [[5, 2], [2, 1]] (point masses at 1 and 2 on a straight double pendulum), tau = [0, 1]
    qdd = np.linalg.solve([[5.0, 2.0], [2.0, 1.0]], [0.0, 1.0])
    np.testing.assert_allclose(a1, [0.0, 0.0, qdd[0]], atol=1e-14)
    # force on body i+1: f2 = I2 a2 with a2 = a1 + s2 qdd2
    np.testing.assert_allclose(f2, A2 @ (a1 + s2[:, 0] * qdd[1]), atol=1e-14)


def test_branched_model_is_rejected():
    model = Model([Body(1.0, (0.5, 0.0), 0.1)] * 3, [Joint("revolute")] * 3, [-1, 0, 0])
    with pytest.raises(TopologyError, match="unbranched chain"):
        forward_dynamics_mobility_split(model, np.zeros(3), np.zeros(3), np.zeros(3))


def test_singular_joint_raises():
    I = np.stack([inertia_matrix(1.0, [0.5, 0.0], 0.1), inertia_matrix(1.0, [1.0, 0.0], 0.0)])
    S = [np.array([[0.0], [0.0], [1.0]]), np.array([[0.0], [-1.0], [1.0]])]
    with pytest.raises(SingularConfigurationError) as e:
        chain_split(I, S, np.zeros((2, 3)), np.zeros((2, 3)), [np.zeros(1)] * 2)
    assert e.value.cond > COND_LIMIT
