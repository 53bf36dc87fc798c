"""Truncated articulated recursion (thesis 10.2.2: "three iterations are almost as precise as six").

``articulated_recursion(..., steps=k)`` keeps, for every body, only the bodies at most ``k``
joints outboard.  Reference: the dense free-floating Schur complement (``dense_articulated``,
Pinocchio / KKT) of the chain *cut* after body ``i + k``, an independent construction; and the
thesis's 7.3 claim at ``lambda = 2`` (further bodies change ``d``, ``m_y``, ``A_z`` of the first
body not at all).
"""
from __future__ import annotations

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from planargeo.algorithms.articulated_inertia import (articulated_inertia, articulated_recursion,
                                                      truncation_error)
from planargeo.errors import InputError, SingularConfigurationError
from planargeo.mechanics.model import Body, Joint, Model, random_model
from planargeo.scenes.horizontal_chain import effective_centre, horizontal_chain_model
from test_articulated_reference import dense_articulated, random_state


def _cut(model, n):
    """The chain's first ``n`` bodies (a new model: the bodies past ``n`` removed)."""
    return Model(model.bodies[:n], model.joints[:n], list(model.parents[:n]), model.gravity)


@settings(max_examples=25, deadline=None)
@given(n=st.integers(2, 6), k=st.integers(0, 5), seed=st.integers(0, 10_000))
def test_truncated_A_d_match_the_dense_reference_of_the_cut_chain(n, k, seed):
    model = random_model(n, seed=seed, kinds=("revolute", "prismatic"))
    q, qd, tau, f_ext = random_state(model, np.random.default_rng(seed))
    r = articulated_inertia(model, q, qd, tau, f_ext, steps=k)
    assert r.steps == k
    for i in range(n):
        cut = _cut(model, min(n, i + k + 1))
        nq = cut.nq
        A_ref, d_ref = dense_articulated(cut, q[:nq], qd[:nq], tau[:nq], f_ext[:cut.N], i)
        np.testing.assert_allclose(r.A[i], A_ref, atol=1e-9 * np.abs(A_ref).max())
        np.testing.assert_allclose(r.d[i], d_ref, atol=1e-8 * (1 + np.abs(d_ref).max()))


@pytest.mark.parametrize("tree", [False, True])
@pytest.mark.parametrize("seed", range(3))
def test_enough_steps_is_the_full_recursion_multi_dof(tree, seed):
    model = random_model(7, seed=200 + seed, tree=tree,
                         kinds=("revolute", "prismatic", "revolute_prismatic", "plane", "fixed"))
    q, qd, tau, f_ext = random_state(model, np.random.default_rng(seed))
    full = articulated_inertia(model, q, qd, tau, f_ext)
    for k in (6, 7, 50):
        r = articulated_inertia(model, q, qd, tau, f_ext, steps=k)
        np.testing.assert_allclose(r.A, full.A, atol=1e-12 * np.abs(full.A).max())
        np.testing.assert_allclose(r.d, full.d, atol=1e-11 * (1 + np.abs(full.d).max()))
        assert truncation_error(model, q, qd, tau, f_ext, steps=k)["max_A"] < 1e-13
    # every truncated result has consistent subspaces: sᵀT = 1 and R Uᵀ = 1 - T sᵀ (7.8)
    r = articulated_inertia(model, q, qd, tau, f_ext, steps=1)
    for S, T, P in zip(r.S, r.T, r.P):
        np.testing.assert_allclose(S.T @ T, np.eye(S.shape[1]), atol=1e-9)
        np.testing.assert_allclose(P, np.eye(3) - T @ S.T, atol=1e-12)


def test_tree_truncation_counts_joints_outboard():
    # a star: body 0 carries 1 and 2; body 1 carries 3.  steps=1: A_0 sees bodies 1 and 2, not 3
    b = Body(1.0, (0.5, 0.0), 0.1)
    joints = [Joint("revolute", (0.0, 0.0, 0.0)), Joint("revolute", (1.0, 0.0, 0.0)),
              Joint("revolute", (1.0, 0.0, 0.0)), Joint("revolute", (1.0, 0.0, 0.0))]
    model = Model([b] * 4, joints, [-1, 0, 0, 1], gravity=(0.0, 0.0))
    q = np.array([0.1, 0.7, -0.9, 0.4])
    r = articulated_inertia(model, q, steps=1)
    small = Model([b] * 3, joints[:3], [-1, 0, 0], gravity=(0.0, 0.0))
    A_ref, _ = dense_articulated(small, q[:3], np.zeros(3), np.zeros(3), None, 0)
    np.testing.assert_allclose(r.A[0], A_ref, atol=1e-12)


@pytest.mark.parametrize("n", [3, 6, 9])
def test_thesis_7_3_lambda_2_one_step_is_exact_but_for_m_x(n):
    model = horizontal_chain_model(n, 1.0, 0.5, 1.0)              # lambda = L / rho = 2
    full = effective_centre(articulated_inertia(model, np.zeros(n)).A[0])
    for k in (1, 2, 3):
        d, mx, my, Az = effective_centre(articulated_inertia(model, np.zeros(n), steps=k).A[0])
        assert (d, my, Az) == pytest.approx((2 / 3, 1.5, 0.25 * 4 / 3), rel=1e-12)   # 7.27; A_z = (4/3) m rho^2
        assert (d, my, Az) == pytest.approx(full[:1] + full[2:], rel=1e-12)
        assert mx == pytest.approx(min(k + 1, n))                   # m_x grows by m per step (linear)


def test_three_steps_almost_as_precise_as_six_away_from_lambda_2():
    # 10.2.2 on the chain of 7.3 with lambda = 3 (a rectangle-like body): d, m_y, A_z of the
    # first body after 3 steps within 1 % of 6 steps; m_x grows linearly and is not approximated
    model = horizontal_chain_model(7, 1.0, 1 / 3, 1.0)
    e3 = np.array(effective_centre(articulated_inertia(model, np.zeros(7), steps=3).A[0]))
    e6 = np.array(effective_centre(articulated_inertia(model, np.zeros(7), steps=6).A[0]))
    rel = np.abs(e3 - e6) / np.abs(e6)
    assert rel[0] < 1e-2 and rel[2] < 1e-2 and rel[3] < 1e-2
    assert e3[1] == pytest.approx(4.0) and e6[1] == pytest.approx(7.0)


def test_truncation_error_decreases_to_zero():
    model = random_model(6, seed=5)
    q, qd, tau, f_ext = random_state(model, np.random.default_rng(5))
    errs = [truncation_error(model, q, qd, tau, f_ext, steps=k)["max_A"] for k in range(6)]
    assert errs[-1] < 1e-13 and errs[0] > 1e-3
    e = truncation_error(model, q, qd, tau, f_ext, steps=2)
    assert e["entries"].shape == (6, 3, 3) and e["A"].shape == (6,) and e["d"].shape == (6,)
    assert e["A"][-1] == 0.0                                        # the tip has nothing outboard


@pytest.mark.parametrize("bad", [-1, 1.5, "3", True, None])
def test_bad_steps_are_named(bad):
    model = random_model(3, seed=1)
    if bad is None:
        with pytest.raises(InputError, match="steps"):
            truncation_error(model, np.zeros(3), steps=None)
        return
    with pytest.raises(InputError, match="steps must be None or a non-negative integer"):
        articulated_inertia(model, np.zeros(3), steps=bad)


def test_truncated_singular_joint_raises_with_cond():
    # a massless tip on a pin: singular whatever the truncation
    from planargeo.screws.twists import inertia_matrix
    I = [inertia_matrix(1.0, [0.5, 0.0], 0.1), np.zeros((3, 3))]
    S = [np.array([[0.0], [0.0], [1.0]]), np.array([[0.0], [-1.0], [1.0]])]
    with pytest.raises(SingularConfigurationError, match="joint 2 ") as info:
        articulated_recursion(I, S, np.zeros((2, 3)), np.zeros((2, 3)), [np.zeros(1)] * 2, steps=0)
    assert info.value.cond == np.inf
    r = articulated_recursion(I, S, np.zeros((2, 3)), np.zeros((2, 3)), [np.zeros(1)] * 2, steps=0, check=False)
    assert np.isinf(r.cond[1])
