"""Scenes "tree" (Fig 9.1) and "constrained-tree" (Fig 9.2)."""
import numpy as np
import pytest

from planargeo import scenes
from planargeo.algorithms.loops import constrained_dynamics_lagrange
from planargeo.errors import SceneError
from planargeo.mechanics.kinematics import kinematics
from planargeo.simulate.loops import closure_jacobian, closure_residual
from test_articulated_reference import dense_mobility, reference_qdd


def test_registered():
    assert {"tree", "constrained-tree"} <= set(scenes.names())


@pytest.mark.parametrize("speed, g", [(1.0, 9.81), (3.0, 0.0)])
def test_tree_matches_pinocchio(speed, g):
    res = scenes.build("tree", speed=speed, g=g)
    q, qd = res.state["q"], res.state["qd"]
    ref = reference_qdd(res.model, q, qd, np.zeros(9))
    assert np.allclose(res.quantities["qdd"], ref, atol=1e-10)
    assert np.allclose(res.quantities["qdd_direct"], ref, atol=1e-10)
    assert np.array(res.quantities["C"]).sum() == 8
    assert np.array(res.quantities["Dinv"])[7].tolist() == [1, 0, 0, 0, 1, 1, 0, 1, 0]   # row 8 of 9.13


def test_tree_pose_closes_fig_9_2_loops():
    res = scenes.build("tree")
    pose = kinematics(res.model, res.state["q"]).pose
    L = 1.0
    tip = lambda i: pose[i, :2] + L * np.array([np.cos(pose[i, 2]), np.sin(pose[i, 2])])
    assert np.allclose(tip(3), tip(6)) and np.allclose(tip(7), tip(8))


@pytest.mark.parametrize("speed, g, mass", [(1.0, 9.81, 1.0), (2.0, 0.0, 0.5)])
def test_constrained_tree_matches_lagrange(speed, g, mass):
    res = scenes.build("constrained-tree", speed=speed, g=g, mass=mass)
    Q, m = res.quantities, res.model
    q, qd = np.array(res.state["q"]), np.array(res.state["qd"])
    assert np.abs(closure_residual(m, q)).max() < 1e-14
    Jc = closure_jacobian(m, q)
    assert np.abs(Jc @ qd).max() < 1e-12 and np.linalg.matrix_rank(Jc) == 4   # 9 - 4 = 5 dof
    ref = constrained_dynamics_lagrange(m, q, qd, np.zeros(9))
    assert np.allclose(Q["qdd"], ref["qdd"], atol=1e-9)
    assert np.allclose(Q["a"], ref["a"], atol=1e-9)
    assert np.allclose(Q["F"], ref["F"], atol=1e-9)
    assert np.array_equal(np.array(Q["G"]), [[0, 0, 0, 1, 0, 0, -1, 0, 0], [0, 0, 0, 0, 0, 0, 0, 1, -1]])  # 9.49
    assert np.array_equal(np.array(Q["Upsilon"]),
                          [[0, 1, 1, 1, -1, -1, -1, 0, 0], [0, 0, 0, 0, 1, 1, 0, 1, -1]])              # 9.51


@pytest.mark.parametrize("name", ["tree", "constrained-tree"])
def test_bad_parameters(name):
    with pytest.raises(SceneError, match="length must be positive"):
        scenes.build(name, length=-1.0)
    with pytest.raises(SceneError, match="has no parameter 'colour'"):
        scenes.build(name, colour="red")


def _fig91_parents():
    # Fig 9.1 read off by hand (0-based): 1 root; 2-3-4 and 5-6-7 from 1's tip; 8 from 6; 9 from 1
    return [-1, 0, 1, 2, 0, 4, 5, 5, 0]


def test_tree_articulation_matrix_is_the_finite_series_on_independent_articulated_inertias():
    """``L = (1 - Cᵀ R Uᵀ)⁻¹`` (9.31) against its finite series (9.34), ``Σ_k (Cᵀ P)^k``, built here.

    ``C`` from the hand-read parents of Fig 9.1, ``P_i = R_i U_iᵀ = 1 - T_i s_iᵀ`` (7.8) with
    ``T_i = A_i s_i / (s_iᵀ A_i s_i)`` from the articulated inertias of the recursive
    articulated-body algorithm (:func:`planargeo.algorithms.aba.articulated_body`, an
    independent code path from the stacked solution's).
    """
    from planargeo.algorithms.aba import articulated_body

    res = scenes.build("tree", speed=2.0)
    L = np.array(res.quantities["L"])
    assert L.shape == (27, 27)
    m, q, qd = res.model, np.array(res.state["q"]), np.array(res.state["qd"])
    w = articulated_body(m, q, qd, np.zeros(9))
    d = kinematics(m, q)
    C = np.zeros((9, 9))
    for i, p in enumerate(_fig91_parents()):
        if p >= 0:
            C[i, p] = 1.0
    C3 = np.kron(C, np.eye(3))
    P = np.zeros((27, 27))
    for i in range(9):
        s = d.S[:, i:i + 1]
        A = w.A[i]
        P[3 * i:3 * i + 3, 3 * i:3 * i + 3] = np.eye(3) - (A @ s) @ s.T / (s.T @ A @ s)[0, 0]
    X = C3.T @ P
    series, term = np.eye(27), np.eye(27)
    for _ in range(4):                     # depth of Fig 9.1 is 4 (1-2-3-4): X⁴ = 0
        term = term @ X
        series = series + term
    assert not (term @ X).any() or np.abs(term @ X).max() < 1e-12
    np.testing.assert_allclose(L, series, atol=1e-12)
    # body 4's articulated load reaches bodies 3, 2, 1 and no other (the block structure of L)
    reach = [bool(np.abs(L[3 * j:3 * j + 3, 9:12]).max() > 0) for j in range(9)]
    assert reach == [True, True, True, True, False, False, False, False, False]


def test_tree_mobilities_are_those_of_the_tree_with_descendants_cut_off():
    """``Λ_i⁻¹`` and ``b_i`` of the direct solution 9.48, against the reference.

    Cut off body ``i``'s descendants: in the remaining tree a wrench ``w`` on body ``i``
    accelerates it by ``b_i + Λ_i⁻¹ w`` (7.28, 9.45), read off by Pinocchio
    (``test_articulated_reference.dense_mobility``).
    """
    res = scenes.build("tree", speed=1.5, g=9.81)
    Lam, b = np.array(res.quantities["Lambda_inv"]), np.array(res.quantities["b"])
    m, q, qd = res.model, np.array(res.state["q"]), np.array(res.state["qd"])
    for i in range(9):
        Lam_ref, b_ref = dense_mobility(m, q, qd, np.zeros(9), None, i)
        np.testing.assert_allclose(Lam[i], Lam_ref, atol=1e-12, err_msg=f"Lambda_inv {i}")
        np.testing.assert_allclose(b[i], b_ref, atol=1e-11, err_msg=f"b {i}")


# --------------------------------------------------------------------------- Play helpers (#14 item 4)
def test_tree_pose_closes_the_loops_and_keeps_the_fixed_angles():
    from planargeo.scenes.trees import constrained_tree, tree_pose
    from planargeo.simulate.loops import closure_jacobian, closure_residual

    m = constrained_tree().model
    q, qd = tree_pose(m, np.radians(80.0), 0.5, angle2=np.radians(150.0))
    assert q[0] == pytest.approx(np.radians(80.0)) and q[0] + q[1] == pytest.approx(np.radians(150.0))
    assert np.abs(closure_residual(m, q)).max() < 1e-12
    assert np.abs(closure_jacobian(m, q) @ qd).max() < 1e-12


@pytest.mark.parametrize("a1, a2", [(80.0, 150.0), (95.0, 135.0), (-30.0, 200.0), (120.0, 60.0)])
def test_tree_pose_is_project_states_closure_step_by_step(a1, a2):
    """tree_pose closes the loops by positions alone: the same pose as project_state on the same path."""
    from planargeo.scenes.trees import FIG91_ANGLES, FIG91_PARENTS, constrained_tree, tree_pose
    from planargeo.simulate.loops import project_state

    m = constrained_tree().model
    q, _qd = tree_pose(m, np.radians(a1), 1.0, angle2=np.radians(a2))
    th = np.radians(FIG91_ANGLES)                   # the Fig 9.2 pose, relative angles
    ref = np.array([th[i] - (th[p] if p >= 0 else 0.0) for i, p in enumerate(FIG91_PARENTS)])
    ref[0] = np.radians(a1)
    rel = np.radians(a2) - np.radians(a1)
    turn = float(np.remainder(rel - ref[1] + np.pi, 2 * np.pi) - np.pi)
    n = int(np.ceil(abs(turn) / np.radians(10.0)))
    for a in [ref[1] + turn * (k + 1) / n for k in range(n)] + [rel]:
        ref[1] = a
        ref, _ = project_state(m, ref, np.zeros(9), fixed=[0, 1], tol=1e-13, max_iter=50)
    np.testing.assert_array_equal(q, ref)


def test_tree_advance_keeps_energy_and_loops():
    from planargeo.errors import SceneError
    from planargeo.scenes.trees import constrained_tree, tree_advance
    from planargeo.simulate.integrate import energy
    from planargeo.simulate.loops import closure_residual

    ct = constrained_tree()
    m, q, qd = ct.model, np.array(ct.state["q"]), np.array(ct.state["qd"])
    out = tree_advance(m, q, qd, 0.1)
    E0, E1 = sum(energy(m, q, qd)), sum(energy(m, out["q"], out["qd"]))
    assert abs(E1 - E0) < 1e-8 * abs(E0)
    assert np.abs(closure_residual(m, out["q"])).max() < 1e-9
    with pytest.raises(SceneError, match="dt must be positive"):
        tree_advance(m, q, qd, -1.0)
