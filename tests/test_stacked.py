"""Stacked form of trees (thesis 9.1-9.2) against independent references.

References (``test_articulated_reference``): Pinocchio's ``aba`` and mobility (revolute and
prismatic joints), the KKT solve in maximal coordinates (every joint kind), the thesis's printed
matrices (9.1, 9.13) and the chain recursion 7.4.1 for the erratum on trees.
"""
import numpy as np
import pytest
from hypothesis import assume, given, strategies as st

from planargeo.algorithms.articulated_mobility import mobility_recursion
from planargeo.algorithms.stacked import adjacency, blocks, direct_accelerations, forward_dynamics_stacked, stacked_solve, trunk
from planargeo.errors import (COND_LIMIT, CyclicTopologyError, InputError, ShapeError, SingularConfigurationError,
                             TopologyError)
from planargeo.mechanics.kinematics import kinematics
from planargeo.mechanics.model import Body, Joint, Model, chain_model, random_model
from test_articulated_reference import mass_matrix_cond, mobility_matrix, reference_qdd

FIG91 = [-1, 0, 1, 2, 0, 4, 5, 5, 0]  # Fig 9.1: parents of bodies 1..9 (0-based)


def _state(m, rng):
    return (rng.normal(size=m.nq), rng.normal(size=m.nq), rng.normal(size=m.nq),
            rng.normal(size=(m.N, 3)))


def _tol(m, q, ref):
    # tolerance scaled by the conditioning of the mass matrix
    return 1e-13 * mass_matrix_cond(m, q) * max(1.0, np.abs(ref).max()) + 1e-12


# --------------------------------------------------------------------------- topology
def test_adjacency_fig_9_1_is_9_1():
    printed = np.zeros((9, 9), int)
    for i, j in [(2, 1), (3, 2), (4, 3), (5, 1), (6, 5), (7, 6), (8, 6), (9, 1)]:
        printed[i - 1, j - 1] = 1
    assert np.array_equal(adjacency(FIG91), printed)


def test_trunk_fig_9_1_is_9_13():
    rows = {1: [1], 2: [1, 2], 3: [1, 2, 3], 4: [1, 2, 3, 4], 5: [1, 5], 6: [1, 5, 6],
            7: [1, 5, 6, 7], 8: [1, 5, 6, 8], 9: [1, 9]}
    printed = np.zeros((9, 9))
    for i, cols in rows.items():
        printed[i - 1, [c - 1 for c in cols]] = 1
    D = trunk(adjacency(FIG91))
    assert np.array_equal(D, printed)
    assert np.allclose(D @ (np.eye(9) - adjacency(FIG91)), np.eye(9))  # (9.12)


def test_chain_adjacency_9_2_and_trunk_lower_triangular():
    C = adjacency(range(-1, 4))
    assert np.array_equal(C, np.eye(5, k=-1))
    assert np.array_equal(trunk(C), np.tril(np.ones((5, 5))))


@pytest.mark.parametrize("C, cycle", [
    (np.array([[0, 1], [1, 0]]), (0, 1)),
    (np.array([[0, 0, 1], [1, 0, 0], [0, 1, 0]]), (0, 2, 1)),
    (np.array([[0, 0, 0, 0], [1, 0, 0, 0], [0, 0, 0, 1], [0, 0, 1, 0]]), (2, 3)),   # a tree plus a 2-cycle
    (np.array([[1]]), (0,)),
])
def test_trunk_cycle_raises_cyclic_topology_error_with_cond(C, cycle):
    """A cycle: C^n ≠ 0 and 1 - C singular (9.12); the error carries cond = inf and names the bodies."""
    with pytest.raises(CyclicTopologyError) as e:
        trunk(C)
    assert isinstance(e.value, TopologyError)
    assert e.value.cond == np.inf and e.value.cycle == cycle
    path = " -> ".join(map(str, cycle + cycle[:1]))
    assert str(e.value) == f"C contains a cycle through bodies {path}: not a tree (condition number of 1 - C: inf)"
    assert np.linalg.cond(np.eye(len(C)) - C) > 1e15            # numerically singular as well


@pytest.mark.parametrize("C, msg", [
    (np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0]]), "more than one parent"),
    (np.array([[0, 2], [0, 0]]), "zeros and ones"),
])
def test_trunk_rejects_non_trees(C, msg):
    with pytest.raises(TopologyError, match=msg):
        trunk(C)


def test_trunk_shape_error():
    with pytest.raises(ShapeError, match="C must be a square matrix"):
        trunk(np.zeros((2, 3)))


def test_adjacency_self_parent_is_a_cycle_of_length_one():
    with pytest.raises(CyclicTopologyError) as e:
        adjacency([-1, 1])
    assert e.value.cond == np.inf and e.value.cycle == (1,)
    assert str(e.value) == ("parents[1] must not be 1 itself: a cycle of length one through bodies 1 -> 1 "
                            "(parents=[-1, 1]) (condition number of 1 - C: inf)")


@pytest.mark.parametrize("parents, msg", [([-1, 1], "parents\\[1\\] must not be 1"),
                                          ([-1, 7], "parents\\[1\\] must be -1"),
                                          (["a"], "parents must be a sequence of integers")])
def test_adjacency_rejects_bad_parents(parents, msg):
    with pytest.raises(TopologyError, match=msg):
        adjacency(parents)


def test_raw_cycle_in_unordered_parents_detected():
    # parents given raw (not ordered): 0 -> 2 -> 1 -> 0 is a cycle
    with pytest.raises(CyclicTopologyError, match="cycle through bodies 0 -> 2 -> 1 -> 0") as e:
        trunk(adjacency([2, 0, 1]))
    assert e.value.cond == np.inf and e.value.cycle == (0, 2, 1)
    # a valid but unordered tree passes
    D = trunk(adjacency([1, -1, 1]))
    assert np.array_equal(D, [[1, 1, 0], [0, 1, 0], [0, 1, 1]])


def test_stacked_R_U_blocks_equal_the_projective_ones():
    from planargeo.algorithms.projective import projective_workspace

    model = random_model(5, seed=4, kinds=("revolute", "prismatic", "revolute_prismatic", "plane", "fixed"))
    rng = np.random.default_rng(4)
    q, qd, tau = rng.normal(size=(3, model.nq))
    sol = stacked_solve(model, q, qd, tau)
    ws = projective_workspace(model, q, qd, tau)
    c = 0
    for i in range(model.N):
        k = 3 - ws.R[i].shape[1]
        np.testing.assert_allclose(sol.R[3 * i:3 * i + 3, c:c + 3 - k], ws.R[i], atol=1e-12)
        np.testing.assert_allclose(sol.U[3 * i:3 * i + 3, c:c + 3 - k], ws.U[i], atol=1e-9)
        c += 3 - k


# --------------------------------------------------------------------------- dynamics
@given(st.integers(1, 12), st.booleans(), st.integers(0, 10_000))
def test_stacked_matches_pinocchio_random_trees(n, tree, seed):
    rng = np.random.default_rng(seed)
    m = random_model(n, seed=seed, tree=tree)
    q, qd, tau, fe = _state(m, rng)
    ref = reference_qdd(m, q, qd, tau, fe)
    tol = _tol(m, q, ref)
    assert np.abs(forward_dynamics_stacked(m, q, qd, tau, fe) - ref).max() < tol
    assert np.abs(forward_dynamics_stacked(m, q, qd, tau, fe, method="direct") - ref).max() < tol


@given(st.integers(2, 8), st.integers(0, 10_000))
def test_stacked_all_joint_kinds(n, seed):
    rng = np.random.default_rng(seed)
    m = random_model(n, seed=seed, tree=True,
                     kinds=("revolute", "prismatic", "revolute_prismatic", "plane", "fixed"))
    assume(m.nq > 0)  # (no coordinates, nothing to compare)
    q, qd, tau, fe = _state(m, rng)
    ref = reference_qdd(m, q, qd, tau, fe)
    tol = _tol(m, q, ref)
    assert np.abs(forward_dynamics_stacked(m, q, qd, tau, fe) - ref).max() < tol
    assert np.abs(forward_dynamics_stacked(m, q, qd, tau, fe, method="direct") - ref).max() < tol


@pytest.mark.parametrize("tree", [False, True])
def test_stacked_200_bodies(tree):
    rng = np.random.default_rng(200)
    m = random_model(200, seed=7, tree=tree)
    q, qd, tau, fe = _state(m, rng)
    ref = reference_qdd(m, q, qd, tau, fe)
    tol = _tol(m, q, ref)
    assert np.abs(forward_dynamics_stacked(m, q, qd, tau, fe) - ref).max() < tol
    assert np.abs(forward_dynamics_stacked(m, q, qd, tau, fe, method="direct") - ref).max() < tol


@pytest.mark.parametrize("n", [50, 200])
@pytest.mark.parametrize("shape", ["uniform", "deep"])
@pytest.mark.parametrize("seed", range(3))
def test_stacked_matches_pinocchio_large_random_trees(n, shape, seed):
    """Random trees of 50 and 200 bodies (revolute + prismatic, external loads), both stacked solutions
    (9.39 and the direct 9.48) against Pinocchio within 100 eps cond(H) relative."""
    from test_articulated_reference import random_state, rtol_for
    from test_projective_dyn import large_tree

    m = large_tree(n, seed, shape)
    q, qd, tau, fe = random_state(m, np.random.default_rng(seed))
    ref = reference_qdd(m, q, qd, tau, fe)
    rtol = rtol_for(m, q)
    scale = max(np.linalg.norm(ref), 1.0)
    for method in ("articulation", "direct"):
        err = np.linalg.norm(forward_dynamics_stacked(m, q, qd, tau, fe, method=method) - ref) / scale
        assert err <= rtol, (method, err, rtol)


def test_batched_states():
    rng = np.random.default_rng(3)
    m = random_model(4, seed=3, tree=True)
    q, qd, tau = (rng.normal(size=(2, 3, m.nq)) for _ in range(3))
    out = forward_dynamics_stacked(m, q, qd, tau)
    assert out.shape == (2, 3, m.nq)
    ref = [[reference_qdd(m, q[b, k], qd[b, k], tau[b, k]) for k in range(3)] for b in range(2)]
    assert np.allclose(out, ref, atol=1e-10)


def test_closed_form_pendulum():
    # uniform rod hinged at one end, horizontal: qdd = -3 g / (2 L)
    assert forward_dynamics_stacked(chain_model(1), [0.0], [0.0], [0.0])[0] == pytest.approx(-1.5 * 9.81)


def test_mobility_is_jacobian_mass_inverse():
    # Φ = L^T S T^T A^-1 L equals J H^-1 J^T: the accelerations per unit wrench (Pinocchio)
    rng = np.random.default_rng(5)
    m = random_model(6, seed=5, tree=True)
    q, qd, tau, fe = _state(m, rng)
    sol = stacked_solve(m, q, qd, tau, fe)
    assert np.allclose(sol.mobility, mobility_matrix(m, q), atol=1e-10)


def test_internal_forces_and_9_43():
    rng = np.random.default_rng(6)
    m = random_model(7, seed=6, tree=True)
    q, qd, tau, fe = _state(m, rng)
    sol = stacked_solve(m, q, qd, tau, fe)
    # joint torques are the projections of the internal forces (9.21: Q = S^T f)
    assert np.allclose(sol.S.T @ sol.f, tau, atol=1e-10)
    # (9.14): f = C^T f + I a + p
    assert np.allclose(sol.f, sol.C.T @ sol.f + sol.I @ sol.a + sol.p, atol=1e-9)
    # (9.10): a = C a + S qdd + κ
    assert np.allclose(sol.a, sol.C @ sol.a + sol.S @ sol.qdd + sol.kappa, atol=1e-10)


# --------------------------------------------------------------------------- errata pins
def _printed_d(sol, tau):
    # (9.32) as printed: d = L p + L C^T T Q
    return sol.L @ sol.p + sol.L @ sol.C.T @ sol.T @ tau


def test_erratum_9_32_missing_kappa_term():
    rng = np.random.default_rng(11)
    m = random_model(5, seed=11)
    q, qd, tau, _ = _state(m, rng)
    sol = stacked_solve(m, q, qd, tau)
    # the corrected d reproduces the recursive articulated bias forces (7.7b) ...
    assert np.allclose(sol.d, sol.articulated.d.reshape(-1), atol=1e-10)
    # ... the printed one does not when the joints move (κ ≠ 0) ...
    assert np.abs(_printed_d(sol, tau) - sol.d).max() > 1e-3
    # ... and agrees when they are at rest (κ = 0): the missing term is C^T R U^T A κ
    sol0 = stacked_solve(m, q, np.zeros(m.nq), tau)
    assert np.allclose(_printed_d(sol0, tau), sol0.d, atol=1e-10)


def test_erratum_9_27_9_30_articulated_inertia():
    m = chain_model(3)
    rng = np.random.default_rng(1)
    q, qd, tau, _ = _state(m, rng)
    sol = stacked_solve(m, q, qd, tau)
    C, R, U, A, I = sol.C, sol.R, sol.U, sol.A, sol.I
    P = R @ U.T
    # corrected (9.27): A = I + C^T R U^T A C (block diagonal)
    assert np.allclose(A, I + C.T @ P @ A @ C, atol=1e-10)
    # printed (9.27) fails: C^T R U^T A + I has off-diagonal blocks
    assert np.abs(C.T @ P @ A + I - A).max() > 1e-2
    # corrected (9.30): A = Σ_k (C^T R U^T)^k I C^k, not L I
    acc, M, Ck = np.zeros_like(A), np.eye(9), np.eye(9)
    for _ in range(3):
        acc += M @ I @ Ck
        M, Ck = M @ C.T @ P, Ck @ C
    assert np.allclose(A, acc, atol=1e-10)
    assert np.abs(sol.L @ I - A).max() > 1e-2


def test_erratum_9_44b_missing_inverse():
    m = chain_model(4)
    rng = np.random.default_rng(2)
    q, qd, tau, _ = _state(m, rng)
    sol = stacked_solve(m, q, qd, tau)
    Dinv = sol.Dinv
    n = Dinv.shape[0]
    assert np.allclose(sol.f, Dinv.T @ (sol.I @ sol.a + sol.p), atol=1e-9)           # corrected
    assert np.abs((np.eye(n) - sol.C.T) @ (sol.I @ sol.a + sol.p) - sol.f).max() > 1e-2  # printed
    # printed (9.48) gives wrong accelerations; corrected (9.48) gives the right ones
    Lam, b = sol.articulated_mobilities.Lambda_inv, sol.articulated_mobilities.b
    assert np.allclose(direct_accelerations(sol, Lam, b), sol.a, atol=1e-9)
    Lb = np.zeros((n, n))
    for i, Li in enumerate(Lam):
        Lb[3 * i:3 * i + 3, 3 * i:3 * i + 3] = Li
    K = Lb @ sol.C.T @ (np.eye(n) - sol.C.T)
    a_printed = np.linalg.solve(np.eye(n) + K @ sol.I, np.concatenate(b) - K @ sol.p)
    assert np.abs(a_printed - sol.a).max() > 1e-2


def test_erratum_7_38a_sign_in_chain_mobility():
    # the corrected chain mobility predicts the response of body 1 (of a 2-chain) to a wrench on it
    m = chain_model(2, gravity=(0, 0))
    q, qd, tau = np.array([0.3, 0.7]), np.zeros(2), np.zeros(2)
    sol = stacked_solve(m, q, qd, tau)
    Lam = sol.articulated_mobilities.Lambda_inv
    # Λ_2^{-1} is the mobility of the tip in the whole chain: block (2, 2) of Φ = J H^-1 J^T (Pinocchio)
    assert np.allclose(Lam[1], mobility_matrix(m, q)[3:, 3:], atol=1e-12)


# --------------------------------------------------------------------------- errors
def test_singular_joint_inertia_raises_with_cond():
    # a point mass on its own revolute axis: s^T A s = 0
    m = Model([Body(1.0, (0.0, 0.0), 0.0)], [Joint("revolute")], [-1])
    with pytest.raises(SingularConfigurationError, match="sᵀAs of joint 1 is singular") as e:
        forward_dynamics_stacked(m, [0.0], [0.0], [0.0])
    assert e.value.cond > COND_LIMIT


def test_bad_method_and_shapes():
    m = chain_model(2)
    with pytest.raises(InputError, match="method must be"):
        forward_dynamics_stacked(m, [0, 0], [0, 0], [0, 0], method="magic")
    with pytest.raises(ShapeError, match="q must have shape"):
        forward_dynamics_stacked(m, [0, 0, 0], [0, 0], [0, 0])
    with pytest.raises(ShapeError, match="stacked_solve takes one state"):
        stacked_solve(m, np.zeros((2, 2)), np.zeros(2), np.zeros(2))


def test_blocks_kron():
    assert np.array_equal(blocks(np.array([[0, 1]])), np.hstack([np.zeros((3, 3)), np.eye(3)]))


def test_point_masses_need_no_inverse_inertia():
    # J = 0 bodies have singular I (and tip A); the stacked form never inverts them
    bodies = [Body(1.0, (1.0, 0.0), 0.0), Body(2.0, (0.5, 0.2), 0.0), Body(0.5, (1.0, 0.0), 0.0)]
    joints = [Joint("revolute"), Joint("prismatic", (1.0, 0.0, 0.3)), Joint("revolute", (0.5, 0.0, 0.0))]
    m = Model(bodies, joints, [-1, 0, 1])
    rng = np.random.default_rng(8)
    q, qd, tau, fe = _state(m, rng)
    ref = reference_qdd(m, q, qd, tau, fe)
    assert np.allclose(forward_dynamics_stacked(m, q, qd, tau, fe), ref, atol=1e-10)
    assert np.allclose(forward_dynamics_stacked(m, q, qd, tau, fe, method="direct"), ref, atol=1e-10)


def test_erratum_tree_mobilities_need_sibling_subtrees():
    # 7.4.1 applied along each root path (siblings ignored) breaks the direct solution on trees
    from planargeo.scenes.trees import tree
    res = tree()
    m, q, qd = res.model, res.state["q"], res.state["qd"]
    tau = np.zeros(9)
    sol = stacked_solve(m, q, qd, tau)
    ref = reference_qdd(m, q, qd, tau)
    d = sol.data
    wrong = ([], [])
    for i in range(9):
        path = list(m.ancestors(i))                    # body i's root path: a chain, its siblings' subtrees ignored
        r = mobility_recursion(d.I[path], [d.s(k) for k in path], d.kappa[path], d.p[path],
                               [tau[m.q_slice(k)] for k in path], joint_points=d.origin[path])
        wrong[0].append(r.Lambda_inv[-1])
        wrong[1].append(r.b[-1])
    right = (sol.articulated_mobilities.Lambda_inv, sol.articulated_mobilities.b)
    for (Lam, b), ok in [(right, True), (wrong, False)]:
        a = direct_accelerations(sol, Lam, b)
        qdd = sol.T.T @ (a - sol.C @ a - sol.kappa)
        assert np.allclose(qdd, ref, atol=1e-9) == ok


@given(st.integers(1, 15), st.integers(0, 10_000))
def test_trunk_rows_are_root_paths(n, seed):
    m = random_model(n, seed=seed, tree=True)
    D = trunk(adjacency(m.parents))
    for i in range(n):
        assert set(np.flatnonzero(D[i])) == set(m.ancestors(i))


def test_articulation_matrix_series_9_34_and_recursion_9_64():
    rng = np.random.default_rng(12)
    m = random_model(7, seed=12, tree=True)
    q, qd, tau, fe = _state(m, rng)
    sol = stacked_solve(m, q, qd, tau, fe)
    X = sol.C.T @ sol.P
    series, Xk = np.eye(21), np.eye(21)
    for _ in range(6):
        Xk = Xk @ X
        series += Xk
    assert np.allclose(series, sol.L, atol=1e-10)                         # (9.34), finite
    assert np.allclose(sol.L.T, np.linalg.inv(np.eye(21) - sol.U @ sol.R.T @ sol.C), atol=1e-10)  # (9.40)
    # (9.64): u_i = s_i T_i^T A_i^-1 (T_i Q_i - d_i) + U_i R_i^T (u_parent + κ_i), root to tips;
    # its first term in the s-only form s_i (s_iᵀ A_i s_i)^-1 (Q_i - s_iᵀ d_i) (s_iᵀ T_i = 1)
    art = sol.articulated
    u = np.zeros((7, 3))
    for i in range(7):
        s, A = art.S[i], art.A[i]
        up = u[m.parents[i]] if m.parents[i] >= 0 else np.zeros(3)
        Qi = tau[m.q_slice(i)]
        R, U = sol.R[3 * i:3 * i + 3], sol.U[3 * i:3 * i + 3]
        act = s @ np.linalg.solve(s.T @ A @ s, Qi - s.T @ art.d[i]) if s.shape[1] else np.zeros(3)
        u[i] = act + U @ (R.T @ (up + sol.kappa[3 * i:3 * i + 3]))
    assert np.allclose(u.reshape(-1), sol.a, atol=1e-9)
