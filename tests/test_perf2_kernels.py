"""The unchecked kernels and qdd-only fast paths behind the teaching algorithms (PERF-2).

References are independent: dense inverses / numpy's own condition numbers,
Pinocchio's ``aba`` (``bench.pinocchio_forward``), and the full workspaces (which
build the reaction bases).
"""
import numpy as np
import pytest
from hypothesis import given, strategies as st

from planargeo import errors
from planargeo.algorithms.articulated_mobility import _cond
from planargeo.algorithms.chain_splitting import forward_dynamics_mobility_split, mobility_split
from planargeo.algorithms.projective import forward_dynamics_projective, projective_workspace
from planargeo.algorithms.stacked import articulation_matrix, forward_dynamics_stacked, stacked_solve
from planargeo.mechanics.model import chain_model, random_model
from planargeo.screws.twists import inertia_matrix
from planargeo.errors import COND_LIMIT
from planargeo.mechanics.subspaces import T_of, _effective_mobility, _T, effective_mobility

pytest.importorskip("pinocchio")
from bench import pinocchio_forward  # noqa: E402

EPS = np.finfo(float).eps

finite = st.floats(-3.0, 3.0, allow_nan=False)


@given(m=st.floats(0.1, 5.0), cx=finite, cy=finite, J=st.floats(0.01, 2.0), x=finite, y=finite)
def test_kernels_match_dense_closed_forms(m, cx, cy, J, x, y):
    I = inertia_matrix(m, [cx, cy], J)
    s = np.array([[y], [-x], [1.0]])                       # revolute at (x, y)
    M = (s.T @ I @ s).item()
    tol = 1e-12 * (1 + np.abs(I).max()) * (1 + np.abs(s).max()) ** 2
    np.testing.assert_allclose(_T(I, s), I @ s / M, atol=tol * (1 + 1 / M))
    np.testing.assert_allclose(_effective_mobility(I, s), s @ s.T / M, atol=tol * (1 + 1 / M))
    # the public functions are the kernels behind validation: the same numbers
    assert np.array_equal(T_of(I, s), _T(I, s))
    assert np.array_equal(effective_mobility(I, s), _effective_mobility(I, s))


def test_kernel_singularity_rule_1x1_and_kxk():
    A = np.diag([1.0, 1.0, 1e-15])
    with pytest.raises(errors.SingularConfigurationError, match="sᵀAs of joint 4 is singular") as e:
        _T(A, np.array([[0.0], [0.0], [1.0]]), "sᵀAs of joint 4")
    assert e.value.cond > COND_LIMIT                     # ‖A‖_F ‖s‖² / |sᵀAs| = √2 · 1e15
    np.testing.assert_allclose(e.value.cond, np.sqrt(2.0) * 1e15, rtol=1e-12)
    s2 = np.array([[1.0, 0.0], [0.0, 0.0], [0.0, 1.0]])   # two columns, no inertia along the 2nd
    with pytest.raises(errors.SingularConfigurationError) as e:
        _T(np.diag([1.0, 1.0, 0.0]), s2)
    assert e.value.cond == np.inf


@given(st.lists(st.floats(-5.0, 5.0, allow_nan=False), min_size=9, max_size=9))
def test_cheap_cond_is_the_frobenius_condition_number(vals):
    M = np.array(vals).reshape(3, 3) + 4.0 * np.eye(3)
    ref = np.linalg.cond(M, "fro") if abs(np.linalg.det(M)) > 1e-8 else None
    if ref is not None:
        np.testing.assert_allclose(_cond(M), ref, rtol=1e-8)
        assert _cond(M) >= np.linalg.cond(M) * (1 - 1e-12)        # never below cond₂


def test_cheap_cond_singular_is_inf():
    assert _cond(np.diag([1.0, 1.0, 0.0])) == np.inf
    assert _cond(np.ones((3, 3))) == np.inf or _cond(np.ones((3, 3))) > 1e15


@pytest.mark.parametrize("model", [chain_model(7), random_model(9, seed=4)], ids=["chain", "random"])
def test_qdd_paths_agree_with_pinocchio_and_workspaces(model):
    rng = np.random.default_rng(11)
    q, qd, tau = rng.standard_normal((3, model.nq))
    ref = pinocchio_forward(model, q, qd, tau)
    tol = 1e-9 * (1 + np.abs(ref).max())
    fast = {"projective": forward_dynamics_projective(model, q, qd, tau),
            "stacked": forward_dynamics_stacked(model, q, qd, tau)}
    full = {"projective": projective_workspace(model, q, qd, tau).qdd,
            "stacked": stacked_solve(model, q, qd, tau).qdd}
    if list(model.parents) == list(range(-1, model.N - 1)):
        fast["mobility_split"] = forward_dynamics_mobility_split(model, q, qd, tau)
        full["mobility_split"] = mobility_split(model, q, qd, tau).qdd
    for name in fast:
        np.testing.assert_allclose(fast[name], ref, atol=tol, err_msg=name)
        np.testing.assert_allclose(fast[name], full[name], atol=tol, err_msg=name)


def test_stacked_articulation_matrix_built_on_access():
    m = random_model(6, seed=2)
    q, qd, tau = np.random.default_rng(3).standard_normal((3, m.nq))
    sol = stacked_solve(m, q, qd, tau)
    assert np.array_equal(sol.L, articulation_matrix(sol.C, sol.P))
    n = 3 * m.N
    np.testing.assert_allclose(sol.L @ (np.eye(n) - sol.C.T @ sol.P), np.eye(n), atol=1e-12)
    # d and a from the triangular solves are L (...) and L^T (...) (9.32, 9.39)
    rhs_d = sol.p + sol.C.T @ (sol.T @ tau) + sol.C.T @ sol.P @ sol.A @ sol.kappa
    np.testing.assert_allclose(sol.d, sol.L @ rhs_d, atol=1e-10 * (1 + np.abs(sol.d).max()))
