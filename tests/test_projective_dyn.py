"""Projective articulated equations (thesis 6.101-6.113) against independent references.

References (``test_articulated_reference``): Pinocchio's ``aba`` (revolute and prismatic
joints), the KKT solve in maximal coordinates (every joint kind, body accelerations),
Newton-Euler for the joint forces, hand-derived pendulum and slider cases.
"""
from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from planargeo.algorithms.projective import (
    acceleration_propagator, force_propagator, forward_dynamics_projective, joint_accelerations, projective_solve,
    projective_workspace)
from planargeo.errors import SingularConfigurationError
from planargeo.mechanics.joints import R_of
from planargeo.mechanics.kinematics import kinematics
from planargeo.mechanics.model import Body, Joint, Model, random_model
from planargeo.mechanics.subspaces import T_of, U_of
from planargeo.screws.twists import inertia_matrix
from test_articulated_reference import (kkt, newton_euler_forces, random_state, reference_accelerations,
                                       reference_qdd, rtol_for)

ALL_KINDS = ("revolute", "prismatic", "revolute_prismatic", "plane", "fixed")


def _close(x, ref, rtol):
    err = np.linalg.norm(x - ref) / max(np.linalg.norm(ref), 1.0)
    assert err <= rtol, (err, rtol)


@given(n=st.integers(1, 8), seed=st.integers(0, 10_000), tree=st.booleans(), loads=st.booleans())
def test_qdd_matches_reference_random_chains_and_trees(n, seed, tree, loads):
    model = random_model(n, seed=seed, tree=tree)
    q, qd, tau, f_ext = random_state(model, np.random.default_rng(seed), loads=loads)
    ref = reference_qdd(model, q, qd, tau, f_ext)
    _close(forward_dynamics_projective(model, q, qd, tau, f_ext), ref, rtol_for(model, q))


@pytest.mark.parametrize("n", [50, 200])
def test_qdd_matches_reference_long_chains(n):
    model = random_model(n, seed=n)
    q, qd, tau, f_ext = random_state(model, np.random.default_rng(n))
    ref = reference_qdd(model, q, qd, tau, f_ext)
    _close(forward_dynamics_projective(model, q, qd, tau, f_ext), ref, rtol_for(model, q))


def large_tree(n, seed, shape):
    """A random ``n``-body tree of revolute and prismatic joints: ``"uniform"`` parents (shallow,
    depth ~ log n) or ``"deep"`` (each parent among the 4 bodies before: long branches, depth ~ n/2.5)."""
    m = random_model(n, seed=seed, tree=True)
    if shape == "deep":
        rng = np.random.default_rng(seed + 1)
        parents = [-1] + [int(rng.integers(max(-1, i - 4), i)) for i in range(1, n)]
        m = Model(m.bodies, m.joints, parents, m.gravity)
    return m


@pytest.mark.parametrize("n", [50, 200])
@pytest.mark.parametrize("shape", ["uniform", "deep"])
@pytest.mark.parametrize("seed", range(3))
def test_qdd_matches_reference_large_random_trees(n, shape, seed):
    """Random trees of 50 and 200 bodies with external loads: relative error within 100 eps cond(H)
    (measured <= 0.03 eps cond(H); cond(H) up to 1e7 for the deep 200-body trees)."""
    model = large_tree(n, seed, shape)
    assert not model.is_chain and {j.kind for j in model.joints} == {"revolute", "prismatic"}
    q, qd, tau, f_ext = random_state(model, np.random.default_rng(seed))
    ref = reference_qdd(model, q, qd, tau, f_ext)
    _close(forward_dynamics_projective(model, q, qd, tau, f_ext), ref, rtol_for(model, q))


@pytest.mark.parametrize("seed", range(6))
def test_qdd_matches_reference_multi_dof_joints(seed):
    model = random_model(6, seed=seed, kinds=ALL_KINDS, tree=bool(seed % 2))
    q, qd, tau, f_ext = random_state(model, np.random.default_rng(seed))
    ref = reference_qdd(model, q, qd, tau, f_ext)
    _close(forward_dynamics_projective(model, q, qd, tau, f_ext), ref, rtol_for(model, q))


@given(seed=st.integers(0, 10_000))
def test_workspace_accelerations_and_forces_match_newton_euler(seed):
    model = random_model(6, seed=seed, tree=True, kinds=ALL_KINDS)
    q, qd, tau, f_ext = random_state(model, np.random.default_rng(seed))
    ws = projective_workspace(model, q, qd, tau, f_ext)
    a = reference_accelerations(model, q, qd, tau, f_ext)                  # the KKT solve (multi-dof joints)
    f = newton_euler_forces(model, q, qd, a, f_ext)
    tol = 1e-8 * (1 + np.abs(f).max())
    np.testing.assert_allclose(ws.a, a, atol=tol)
    np.testing.assert_allclose(ws.f, f, atol=tol)


@given(seed=st.integers(0, 10_000))
def test_components_are_the_projections_6_61_6_62(seed):
    model = random_model(5, seed=seed, tree=True, kinds=ALL_KINDS)
    q, qd, tau, f_ext = random_state(model, np.random.default_rng(seed))
    ws = projective_workspace(model, q, qd, tau, f_ext)
    for i in range(model.N):
        s, R, T, U = ws.s[i], ws.R[i], ws.T[i], ws.U[i]
        tol = 1e-9 * (1 + np.abs(ws.f).max() + np.abs(ws.a).max())
        np.testing.assert_allclose(s.T @ ws.f[i], ws.Q[i], atol=tol)          # Q = s^T f (6.61a)
        np.testing.assert_allclose(U.T @ ws.f[i], ws.mu[i], atol=tol)         # mu = U^T f (6.61b)
        np.testing.assert_allclose(T.T @ ws.a[i], ws.psi[i], atol=tol)        # psi = T^T a (6.62b)
        np.testing.assert_allclose(R.T @ ws.a[i], ws.gamma[i], atol=tol)      # gamma = R^T a (6.62a)
        np.testing.assert_allclose(T @ ws.Q[i] + R @ ws.mu[i], ws.f[i], atol=tol)       # (6.104)
        np.testing.assert_allclose(s @ ws.psi[i] + U @ ws.gamma[i], ws.a[i], atol=tol)  # (6.44)


@given(seed=st.integers(0, 10_000))
def test_propagators_6_113_reproduce_the_solution(seed):
    # with the true neighbour quantities, 6.113a/b give back a_i and f_i
    model = random_model(5, seed=seed, tree=True)
    q, qd, tau, f_ext = random_state(model, np.random.default_rng(seed))
    a = reference_accelerations(model, q, qd, tau, f_ext)                      # Pinocchio
    f = newton_euler_forces(model, q, qd, a, f_ext)
    w = kinematics(model, q, qd, f_ext)
    for i in range(model.N):
        kids = model.children(i)
        f_next = sum((f[c] for c in kids), np.zeros(3))
        par = model.parents[i]
        a_prev = a[par] if par >= 0 else np.zeros(3)
        args = (w.I[i], w.s(i), tau[model.q_slice(i)], w.p[i], f_next, a_prev, w.kappa[i])
        tol = 1e-8 * (1 + np.abs(f).max())
        np.testing.assert_allclose(acceleration_propagator(*args), a[i], atol=tol)
        np.testing.assert_allclose(force_propagator(*args), f[i], atol=tol)


def test_relative_and_absolute_joint_acceleration_6_100():
    # psi_i = qdd_i + T_i^T (a_{i-1} + kappa_i)
    model = random_model(4, seed=11)
    q, qd, tau, f_ext = random_state(model, np.random.default_rng(11))
    ws = projective_workspace(model, q, qd, tau, f_ext)
    for i in range(model.N):
        a_prev = ws.a[i - 1] if i else np.zeros(3)
        kap = kinematics(model, q, qd).kappa[i]
        np.testing.assert_allclose(ws.psi[i], ws.qdd[model.q_slice(i)] + ws.T[i].T @ (a_prev + kap), atol=1e-9)


def test_thesis_7_41_U2_and_corrected_T2():
    m, rho, L, phi = 1.3, 0.37, 1.1, 0.7
    c, s = np.cos(phi), np.sin(phi)
    D = L**2 + 4 * rho**2
    I2 = inertia_matrix(m, [L + L / 2 * c, L / 2 * s], m * rho**2)
    s2 = np.array([[0.0], [-L], [1.0]])
    U2 = U_of(I2, R_of(s2))
    np.testing.assert_allclose(U2, [[1, 0], [-2 * L**2 * s / D, 1 + 2 * L**2 * c / D],
                                    [2 * L * s / D, -2 * L * c / D]], atol=1e-14)
    T2 = T_of(I2, s2).ravel()
    # as printed in 7.41 the last entry is 1: that is T2 expressed at the joint (L, 0);
    # at the origin (the thesis's stated reference point, and s^T T = 1) it is 1 + 2 L^2 cos(phi) / D.
    np.testing.assert_allclose(T2, [-2 * L * s / D, 2 * L * c / D, 1 + 2 * L**2 * c / D], atol=1e-14)
    assert (s2.ravel() @ [-2 * L * s / D, 2 * L * c / D, 1.0]) != pytest.approx(1.0)


def test_singular_joint_raises_with_cond_array_level():
    I = np.stack([inertia_matrix(1.0, [0.5, 0.0], 0.1), np.zeros((3, 3))])
    S = [np.array([[0.0], [0.0], [1.0]]), np.array([[0.0], [-1.0], [1.0]])]
    with pytest.raises(SingularConfigurationError, match="sᵀAs of joint 2 is singular") as e:
        projective_solve(I, S, np.zeros((2, 3)), np.zeros((2, 3)), [np.zeros(1)] * 2)
    assert e.value.cond == np.inf


def test_singular_joint_raises_model_level():
    model = Model([Body(1.0, (0.5, 0.0), 0.1), Body(1.0, (0.0, 0.0), 0.0)],
                  [Joint("revolute"), Joint("revolute", (1.0, 0.0, 0.0))], [-1, 0])
    with pytest.raises(SingularConfigurationError, match="condition number"):
        forward_dynamics_projective(model, [0.1, 0.2], [0.0, 0.0], [0.0, 0.0])


def test_single_pendulum_hand_value():
    # uniform rod m = 2, L = 3 on a pin, horizontal, torque 1: qdd = (tau - m g L/2) / (m L^2 / 3)
    model = Model([Body(2.0, (1.5, 0.0), 2.0 * 9 / 12)], [Joint("revolute")], [-1])
    qdd = forward_dynamics_projective(model, [0.0], [0.0], [1.0])
    assert qdd[0] == pytest.approx((1.0 - 2.0 * 9.81 * 1.5) / (2.0 * 9 / 3), rel=1e-13)


def test_f_ext_shape_is_validated():
    from planargeo.errors import ShapeError

    model = random_model(3, seed=2)
    with pytest.raises(ShapeError, match="f_ext"):
        forward_dynamics_projective(model, np.zeros(model.nq), np.zeros(model.nq), np.zeros(model.nq),
                                    np.zeros((2, 3)))


def test_batched_states_are_solved_one_by_one():
    from planargeo.algorithms.chain_splitting import forward_dynamics_mobility_split

    model = random_model(4, seed=21)
    rng = np.random.default_rng(21)
    q = rng.normal(size=(2, 3, model.nq))
    qd = rng.normal(size=(3, model.nq))
    tau = rng.normal(size=model.nq)
    f_ext = rng.normal(size=(2, 1, model.N, 3))
    ref = np.array([[reference_qdd(model, q[b, k], qd[k], tau, f_ext[b, 0]) for k in range(3)] for b in range(2)])
    for fn in (forward_dynamics_projective, forward_dynamics_mobility_split):
        out = fn(model, q, qd, tau, f_ext)
        assert out.shape == (2, 3, model.nq)
        np.testing.assert_allclose(out, ref, atol=1e-9 * np.abs(ref).max())


# --------------------------------------------------------------------------- reaction components mu
def test_mu_of_a_pendulum_is_the_pin_force_through_the_joint_by_hand():
    # uniform rod m, L hanging from a pin at (2, 3); no joint torque.  By hand (Newton on the rod):
    # F = m a_c - m g, with a_c the centre-of-mass acceleration.  In the basis of thesis 7.16
    # (unit forces along x and y through the pin) mu is exactly (Fx, Fy).
    m, L, g = 2.0, 3.0, 9.81
    model = Model([Body(m, (L / 2, 0.0), m * L**2 / 12)], [Joint("revolute", (2.0, 3.0, 0.4))], [-1])
    q, qd = 0.3, 1.1
    th = 0.4 + q
    thdd = -m * g * (L / 2) * np.cos(th) / (m * L**2 / 3)
    ac = (L / 2) * np.array([-np.sin(th) * thdd - np.cos(th) * qd**2, np.cos(th) * thdd - np.sin(th) * qd**2])
    F = m * ac - m * np.array([0.0, -g])
    ws = projective_workspace(model, [q], [qd], [0.0])
    assert ws.qdd[0] == pytest.approx(thdd, rel=1e-12)
    np.testing.assert_allclose(ws.R[0], [[1.0, 0.0], [0.0, 1.0], [-3.0, 2.0]])
    np.testing.assert_allclose(ws.mu[0], F, rtol=1e-12)
    # the reaction wrench R mu is a line through the pin (incidence, 5.69)
    assert np.array([3.0, -2.0, 1.0]) @ (ws.R[0] @ ws.mu[0]) == pytest.approx(0.0, abs=1e-12)


def test_mu_of_a_slider_is_the_normal_force_through_the_slider_and_a_couple_by_hand():
    # a block (m, com offset c in its frame) sliding along x on a slide through (2, 3), gravity down,
    # pushed by Q: the slide holds it with N = m g along +y and a couple balancing the offset weight.
    # Basis 5.63 at the slider's position (2 + q, 3): [unit force along +y through it, unit couple].
    m, cx, Q, q = 1.5, 0.4, 0.7, 0.25
    model = Model([Body(m, (cx, 0.0), 0.2)], [Joint("prismatic", (2.0, 3.0, 0.0))], [-1])
    ws = projective_workspace(model, [q], [0.0], [Q])
    x0 = 2.0 + q
    np.testing.assert_allclose(ws.R[0], [[0.0, 0.0], [1.0, 0.0], [x0, 1.0]])
    # moments about the slider point: couple C + (weight at x0 + cx) = 0 -> C = m g cx; the thrust Q
    # acts along the slide (through the com line y = 3, no moment about (x0, 3)).
    assert ws.qdd[0] == pytest.approx(Q / m, rel=1e-12)
    f_hand = np.array([Q, m * 9.81, 0.0])
    f_hand[2] = x0 * f_hand[1] - 3.0 * f_hand[0] + m * 9.81 * cx      # moment at the origin
    np.testing.assert_allclose(ws.f[0], f_hand, rtol=1e-12, atol=1e-12)
    np.testing.assert_allclose(ws.mu[0], ws.U[0].T @ f_hand, rtol=1e-12)
    # with no active part along the normal/couple (T Q is a pure push along x through the com):
    # f - T Q = R mu is the normal force m g through the slider plus the couple m g cx
    np.testing.assert_allclose(ws.R[0] @ ws.mu[0], f_hand - ws.T[0] @ [Q], atol=1e-12)


@pytest.mark.parametrize("seed", range(4))
def test_mu_is_U_transpose_of_the_newton_euler_joint_force_in_the_joints_basis(seed):
    from planargeo.mechanics.joints import reaction_space as joint_R

    model = random_model(6, seed=seed, kinds=ALL_KINDS, tree=bool(seed % 2))
    q, qd, tau, f_ext = random_state(model, np.random.default_rng(seed))
    f_rnea = newton_euler_forces(model, q, qd, kkt(model, q, qd, tau, f_ext)["a"], f_ext)   # independent f_i
    ws = projective_workspace(model, q, qd, tau, f_ext)
    d = kinematics(model, q, qd)
    for i, joint in enumerate(model.joints):
        # the joint's frame: origin d.origin[i], x axis at the parent's angle + placement angle
        j = model.parents[i]
        phi = (d.pose[j, 2] if j >= 0 else 0.0) + joint.placement[2]
        point = d.pose[i, :2]
        R_ref = joint_R(joint.kind, point, (np.cos(phi), np.sin(phi)))
        np.testing.assert_allclose(ws.R[i], R_ref, atol=1e-12 * (1 + np.abs(R_ref).max(initial=0.0)))
        scale = 1 + np.abs(f_rnea[i]).max()
        np.testing.assert_allclose(ws.f[i], f_rnea[i], atol=1e-8 * scale)
        np.testing.assert_allclose(ws.mu[i], ws.U[i].T @ f_rnea[i], atol=1e-8 * scale * (1 + np.abs(ws.U[i]).max(initial=0.0)))


def test_force_propagator_takes_T_checked_at_the_joint():
    """6.113b with ``T=`` given: a pendulum pinned far from the origin, torque ``τ`` at rest.

    Hand values: unit point mass at ``c = (X + 1, 0)``, pin at ``(X, 0)``, ``s = [0, -X, 1]``:
    ``I s = [0, 1, X + 1]``, ``sᵀIs = 1`` so ``T = [0, 1, X + 1]``; gravity ``p = [0, g, g (X + 1)]``.
    ``q̈ = τ - g``, the mass accelerates by ``(0, τ - g)``, so the pin pushes ``(0, τ)`` through
    ``(X, 0)``, and the joint adds its torque ``τ``: ``f = [0, τ, X τ + τ]`` (``sᵀf = τ``).  Measured at the origin the rule refuses this joint
    (``cond_O ≈ X⁴ = 1e16``), at the pin it is a plain pendulum: ``T=`` carries the checked one.
    """
    from planargeo.screws.twists import inertia_matrix
    X, g, tau = 1e4, 9.81, 2.0
    I = inertia_matrix(1.0, [X + 1.0, 0.0], 0.0)
    s = [[0.0], [-X], [1.0]]
    p = [0.0, g, g * (X + 1.0)]
    z = np.zeros(3)
    f = force_propagator(I, s, [tau], p, z, z, z, T=[0.0, 1.0, X + 1.0])
    np.testing.assert_allclose(f, [0.0, tau, X * tau + tau], rtol=1e-9, atol=1e-7)
    with pytest.raises(SingularConfigurationError):
        force_propagator(I, s, [tau], p, z, z, z)


@pytest.mark.parametrize("seed", range(3))
def test_joint_accelerations_6_110_of_the_reference_motion(seed):
    # q̈_i = T_iᵀ (a_i - a_λ(i) - κ_i) reads the reference's joint accelerations back from its body accelerations
    model = random_model(6, seed=seed, tree=True, kinds=ALL_KINDS)
    q, qd, tau, f_ext = random_state(model, np.random.default_rng(seed))
    ref = kkt(model, q, qd, tau, f_ext)
    T = projective_workspace(model, q, qd, tau, f_ext).T
    qdd = joint_accelerations(T, ref["a"], kinematics(model, q, qd).kappa, model.parents)
    np.testing.assert_allclose(qdd, ref["qdd"], atol=1e-9 * (1 + np.abs(ref["qdd"]).max()))
