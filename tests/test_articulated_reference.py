"""Independent dense references for the articulated quantities of thesis Chapter 7.

Nothing here uses the recursions under test: every reference is a dense
joint-space computation (mass matrix by CRBA / ``Σ J^T I J``, bias by inverse
dynamics, solved densely).

* ``dense_articulated(model, q, qd, tau, f_ext, i)``: ``A_i`` and ``d_i`` of the
  subtree rooted at body ``i``, made free-floating by replacing joint ``i`` with a
  ``plane`` joint at the same world pose: with ``f_i = 0`` the body accelerates
  by ``a_free``, and ``A_i = (S H^-1 S^T)^-1`` restricted to the free joint,
  ``d_i = -A_i a_free`` (thesis 7.1).
* ``dense_mobility(model, q, qd, tau, f_ext, i)``: ``Lambda_i^-1 = J_i H^-1 J_i^T``
  of the chain truncated after body ``i``, and ``b_i`` its acceleration with no
  load from joint ``i+1`` (thesis 7.28).

The helpers are imported by the other ``test_articulated*`` / chain splitting
test files; the tests below check the references themselves on hand-derived cases.
"""
from __future__ import annotations

import numpy as np
import pytest

from planargeo.algorithms.crba import forward_dynamics_crba, mass_matrix
from planargeo.algorithms.rnea import newton_euler
from planargeo.mechanics.kinematics import kinematics
from planargeo.mechanics.model import Body, Joint, Model, random_model
from planargeo.screws.twists import inertia_matrix

EPS = np.finfo(float).eps


def subtree(model: Model, i: int) -> list[int]:
    """Body ``i`` and all its descendants, in model order."""
    out = [i]
    for k in range(i + 1, model.N):
        if model.parents[k] in out:
            out.append(k)
    return out


def floating_subtree(model: Model, q, qd, f_ext, i: int):
    """The subtree rooted at ``i`` with joint ``i`` replaced by a free ``plane`` joint.

    Returns ``(sub_model, q_sub, qd_sub, f_sub, keep)``: the same world
    configuration and velocities, ``keep`` the original body indices.
    """
    d = kinematics(model, q, qd)
    keep = subtree(model, i)
    idx = {k: n for n, k in enumerate(keep)}
    bodies = [model.bodies[k] for k in keep]
    joints = [Joint("plane", (0.0, 0.0, 0.0))] + [model.joints[k] for k in keep[1:]]
    parents = [-1] + [idx[model.parents[k]] for k in keep[1:]]
    sub = Model(bodies, joints, parents, model.gravity)
    x, y, th = d.pose[i]
    qs = [np.array([x, y, th])] + [np.asarray(q)[model.q_slice(k)] for k in keep[1:]]
    q_sub = np.concatenate(qs)
    # plane-joint speeds reproducing v_i: solve S_plane qd = v_i
    S_plane = kinematics(sub, q_sub).s(0)
    qds = [np.linalg.solve(S_plane, d.v[i])] + [np.asarray(qd)[model.q_slice(k)] for k in keep[1:]]
    qd_sub = np.concatenate(qds)
    f_sub = None if f_ext is None else np.asarray(f_ext)[keep]
    return sub, q_sub, qd_sub, f_sub, keep


def dense_articulated(model: Model, q, qd, tau, f_ext, i: int):
    """Reference ``(A_i, d_i)`` by a dense solve of the free-floating subtree (thesis 7.1)."""
    sub, q_sub, qd_sub, f_sub, keep = floating_subtree(model, q, qd, f_ext, i)
    H = mass_matrix(sub, q_sub)
    S = kinematics(sub, q_sub).s(0)                     # 3×3, the free joint
    Hinv = np.linalg.inv(H)
    A = np.linalg.inv(S @ Hinv[:3, :3] @ S.T)
    tau_sub = np.concatenate([np.zeros(3)] + [np.asarray(tau)[model.q_slice(k)] for k in keep[1:]])
    qdd = forward_dynamics_crba(sub, q_sub, qd_sub, tau_sub, f_sub)
    a_free = newton_euler(sub, q_sub, qd_sub, qdd, f_sub).a[0]
    return A, -A @ a_free


def truncated_chain(model: Model, i: int) -> Model:
    """Bodies ``0..i`` of a chain (a constrained chain ending at body ``i``)."""
    return Model(model.bodies[: i + 1], model.joints[: i + 1], model.parents[: i + 1], model.gravity)


def dense_mobility(model: Model, q, qd, tau, f_ext, i: int):
    """Reference ``(Lambda_i^-1, b_i)`` by a dense solve of the chain truncated after body ``i``."""
    sub = truncated_chain(model, i)
    n = sub.nq
    qs, qds, taus = (np.asarray(x)[:n] for x in (q, qd, tau))
    f_sub = None if f_ext is None else np.asarray(f_ext)[: i + 1]
    H = mass_matrix(sub, qs)
    J = kinematics(sub, qs).jacobian(i)
    Lam = J @ np.linalg.solve(H, J.T)
    qdd = forward_dynamics_crba(sub, qs, qds, taus, f_sub)
    b = newton_euler(sub, qs, qds, qdd, f_sub).a[i]
    return Lam, b


def random_state(model: Model, rng, *, loads: bool = True):
    q = rng.uniform(-np.pi, np.pi, model.nq)
    qd = rng.normal(size=model.nq)
    tau = rng.normal(size=model.nq)
    f_ext = rng.normal(size=(model.N, 3)) if loads else None
    return q, qd, tau, f_ext


def rtol_for(model: Model, q) -> float:
    """Relative tolerance scaled by the conditioning of the problem."""
    H = mass_matrix(model, q)
    return max(1e-12, 100 * EPS * np.linalg.cond(H))


# ---------------------------------------------------------------------------
# The references themselves, on hand-derived cases
# ---------------------------------------------------------------------------
def test_lone_free_body_articulated_inertia_is_its_inertia():
    m = Model([Body(2.0, (0.3, -0.2), 0.4)], [Joint("revolute", (1.0, 0.5, 0.3))], [-1], gravity=(0, 0))
    A, d = dense_articulated(m, [0.7], [0.0], [0.0], None, 0)
    x, y, th = kinematics(m, [0.7]).pose[0]
    c, s = np.cos(th), np.sin(th)
    com = np.array([x + c * 0.3 + s * 0.2, y + s * 0.3 - c * 0.2])
    np.testing.assert_allclose(A, inertia_matrix(2.0, com, 0.4), atol=1e-12)
    np.testing.assert_allclose(d, 0.0, atol=1e-12)


def test_pinned_body_mobility_is_rank_one_hand_form():
    # unit point mass at (1, 0) on a pin at the origin, J = 0.5: Lambda^-1 = s s^T / (J + m)
    m = Model([Body(1.0, (1.0, 0.0), 0.5)], [Joint("revolute")], [-1], gravity=(0, 0))
    Lam, b = dense_mobility(m, [0.0], [0.0], [0.0], None, 0)
    s = np.array([0.0, 0.0, 1.0])
    np.testing.assert_allclose(Lam, np.outer(s, s) / 1.5, atol=1e-14)
    np.testing.assert_allclose(b, 0.0, atol=1e-14)


def test_two_body_articulated_reference_matches_thesis_7_20():
    # thesis 7.20 checked by hand at phi = 90 degrees: m_x = m (L^2 + 8 rho^2) / (L^2 + 4 rho^2)
    mass, L, rho = 1.5, 2.0, 0.4
    bodies = [Body(mass, (L / 2, 0.0), mass * rho**2)] * 2
    model = Model(bodies, [Joint("revolute"), Joint("revolute", (L, 0.0, 0.0))], [-1, 0], gravity=(0, 0))
    A, _ = dense_articulated(model, [0.0, np.pi / 2], [0.0, 0.0], [0.0, 0.0], None, 0)
    assert A[0, 0] == pytest.approx(mass * (L**2 + 8 * rho**2) / (L**2 + 4 * rho**2), rel=1e-12)


def test_subtree_of_a_tree():
    m = Model([Body(1.0)] * 5, [Joint("revolute")] * 5, [-1, 0, 0, 1, -1])
    assert subtree(m, 0) == [0, 1, 2, 3]
    assert subtree(m, 1) == [1, 3]
    assert subtree(m, 4) == [4]


def test_random_model_helper_is_deterministic():
    a, b = random_model(4, seed=3), random_model(4, seed=3)
    assert a == b
