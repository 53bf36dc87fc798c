"""Projective articulated dynamics: subspaces, propagators, forward dynamics (thesis 6.5-6.8).

Each joint splits its body's wrench and acceleration into active and reactive parts,
``f = T Q + R μ``, ``a = s ψ + U γ`` (6.38, 6.44), solved base outwards by 6.101-6.110 with
``R_i`` the package's one basis (:func:`planargeo.mechanics.joints.R_of`); ``q̈`` does not depend on it.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from planargeo.mechanics.subspaces import _effective_mobility, _solve, T_of
from planargeo.algorithms.articulated_inertia import _arrays, _per_state, _state_arrays, articulated_recursion

__all__ = ["acceleration_propagator", "force_propagator", "joint_accelerations",
           "ProjectiveWorkspace", "projective_solve", "projective_workspace", "forward_dynamics_projective"]


# -- Propagators (thesis 6.113) -------------------------------------------------------------------
def _propagator_args(I, s, Q, T, *vectors):
    I = np.asarray(I, dtype=float)
    s = np.asarray(s, dtype=float).reshape(3, -1)
    T = T_of(I, s) if T is None else np.asarray(T, dtype=float).reshape(3, -1)
    return (I, s, np.asarray(Q, dtype=float).reshape(-1), T, *(np.asarray(x, dtype=float) for x in vectors))


def acceleration_propagator(I, s, Q, p, f_next, a_prev, kappa, *, T=None) -> np.ndarray:
    """Acceleration of a body from its neighbours' loads (thesis 6.113a).

    ``a_i = s_i T_i^T I_i^-1 (T_i Q_i - p_i - f_{i+1}) + U_i R_i^T (a_{i-1} + kappa_i)`` with ``T_i``,
    ``U_i`` on the body inertia (6.36, 6.37), ``s T^T I^-1 = s (s^T I s)^-1 s^T`` (6.93) and
    ``U R^T = 1 - s T^T`` (6.75).

    Parameters
    ----------
    I, s, Q : array_like, shapes (3, 3), (3, k), (k,)
        Body inertia at the origin, joint motion space, joint force.
    p, f_next, a_prev, kappa : array_like, shape (3,)
        The body's bias force (3.11), its child joints' summed force, the parent's acceleration,
        the joint's bias acceleration (2.19).
    T : array_like, shape (3, k), optional
        ``I s (sᵀIs)⁻¹`` if already formed and checked; else :func:`planargeo.mechanics.subspaces.T_of`.

    Returns
    -------
    numpy.ndarray, shape (3,)
        ``a_i``, the body's acceleration.

    Examples
    --------
    >>> from planargeo.screws.twists import inertia_matrix
    >>> acceleration_propagator(inertia_matrix(1.0, [1.0, 0.0], 0.0), [[0.0], [0.0], [1.0]], [0.0],
    ...                         [0.0, -1.0, -1.0], np.zeros(3), np.zeros(3), np.zeros(3))  # 1 rad/s²
    array([0., 0., 1.])
    """
    I, s, Q, T, p, f_next, a_prev, kappa = _propagator_args(I, s, Q, T, p, f_next, a_prev, kappa)
    base = a_prev + kappa
    return _effective_mobility(I, s, gram=(I @ s, s.T @ I @ s)) @ (T @ Q - p - f_next) + base - s @ (T.T @ base)


def force_propagator(I, s, Q, p, f_next, a_prev, kappa, *, T=None) -> np.ndarray:
    """Internal force of a body's joint from its neighbours (thesis 6.113b).

    ``f_i = T_i Q_i + R_i U_i^T (I_i (a_{i-1} + kappa_i) + p_i + f_{i+1})`` with ``T_i``, ``U_i`` on the
    body inertia (6.36, 6.37) and ``R U^T = 1 - T s^T`` (7.8).

    Parameters
    ----------
    I, s, Q, p, f_next, a_prev, kappa, T : array_like
        As in :func:`acceleration_propagator`.

    Returns
    -------
    numpy.ndarray, shape (3,)
        ``f_i``, on body ``i`` from its parent through joint ``i``.

    Examples
    --------
    >>> from planargeo.screws.twists import inertia_matrix
    >>> f = force_propagator(inertia_matrix(1.0, [1.0, 0.0], 0.0), [[0.0], [0.0], [1.0]], [0.0],
    ...                      [0.0, -1.0, -1.0], np.zeros(3), np.zeros(3), np.zeros(3))
    >>> np.round(f, 12) + 0.0          # the pin carries none of a push through the mass
    array([0., 0., 0.])
    """
    I, s, Q, T, p, f_next, a_prev, kappa = _propagator_args(I, s, Q, T, p, f_next, a_prev, kappa)
    load = I @ (a_prev + kappa) + p + f_next
    return T @ Q + load - T @ (s.T @ load)


def joint_accelerations(T, a, kappa, parents) -> np.ndarray:
    """Joint accelerations ``qdd_i = T_i^T (a_i - a_{λ(i)} - kappa_i)`` (thesis 6.110), all joints.

    Parameters
    ----------
    T : list of N (3, k_i)
        Percussion spaces (6.105 or 6.36; only ``sᵀT = 1`` is used).
    a, kappa : (N, 3)
        Body accelerations and joint bias accelerations.
    parents : sequence of N ints
        Parent of each body (-1: the ground).

    Returns
    -------
    ndarray (nq,)

    Examples
    --------
    >>> joint_accelerations([np.array([[0.0], [0.0], [1.0]])], np.array([[0.0, 0.0, 2.0]]), np.zeros((1, 3)), [-1])
    array([2.])
    """
    qdd = [Ti.T @ (a[i] - (a[j] if j >= 0 else 0.0) - kappa[i]) for i, (Ti, j) in enumerate(zip(T, parents))]
    return np.concatenate(qdd) if qdd else np.zeros(0)


# -- Projective forward dynamics (thesis 6.101-6.110) ---------------------------------------------
@dataclass
class ProjectiveWorkspace:
    """Everything the projective solution computes, per body ``i`` (thesis 6.99-6.110; lists of arrays).

    Attributes
    ----------
    s, R, T, U : list of (3, k), (3, 3-k), (3, k), (3, 3-k)
        Joint and reaction spaces, active force and reactive acceleration subspaces (6.99, 6.105).
    A, d : (N, 3, 3), (N, 3) articulated inertias and bias forces (7.7a, 7.7b).
    Q, mu, psi, gamma : lists
        Active and reaction components of ``f_i`` (6.104, 6.106a) and of ``a_i`` (6.107, 6.101).
    a, f, qdd : body accelerations (6.108), joint forces (6.109), joint accelerations (6.110).
    """

    s: list
    R: list
    T: list
    U: list
    A: np.ndarray
    d: np.ndarray
    Q: list
    mu: list
    psi: list
    gamma: list
    a: np.ndarray
    f: np.ndarray
    qdd: np.ndarray


def _accelerations(art, kappa, tau, parents):
    """``psi_i = (sᵀAs)⁻¹ (Q - sᵀd)`` (6.107) and ``a_i`` (6.108, ``U Rᵀ = 1 - s Tᵀ``), base to tips."""
    N = len(art.S)
    a, psi = np.zeros((N, 3)), [None] * N
    for i in range(N):
        j = parents[i]
        base = (a[j] if j >= 0 else 0.0) + kappa[i]
        Si, Ti = art.S[i], art.T[i]
        rhs = tau[i] - Si.T @ art.d[i]
        psi[i] = _solve(art.gram[i][1], rhs) if Si.shape[1] else rhs          # (6.107)
        a[i] = Si @ psi[i] + base - Si @ (Ti.T @ base)                         # (6.108)
    return psi, a


def projective_solve(I, S, kappa, p, tau, parents=None, points=None, joint_points=None) -> ProjectiveWorkspace:
    """Projective articulated equations of motion on arrays (thesis 6.101-6.110).

    Parameters
    ----------
    I, S, kappa, p, tau, parents, points, joint_points
        One state (bias accelerations (2.19) and forces (3.11)), as for
        :func:`planargeo.algorithms.articulated_inertia.articulated_recursion`.

    Returns
    -------
    ProjectiveWorkspace
        With ``f[i] = T[i] Q[i] + R[i] mu[i]``.

    Raises
    ------
    SingularConfigurationError
        When some ``s_i^T A_i s_i`` is singular.

    Examples
    --------
    >>> from planargeo.screws.twists import inertia_matrix
    >>> projective_solve([inertia_matrix(1.0, [1.0, 0.0], 0.0)], [np.array([[0.0], [0.0], [1.0]])],
    ...                  np.zeros((1, 3)), np.zeros((1, 3)), [np.array([1.0])]).qdd    # unit torque
    array([1.])
    """
    I, S, kappa, p, tau, parents = _arrays(I, S, kappa, p, tau, parents)
    art = articulated_recursion(I, S, kappa, p, tau, parents, points, joint_points)
    N = len(art.S)
    psi, a = _accelerations(art, kappa, tau, parents)
    A, d, T, R, U = art.A, art.d, art.T, art.R, art.U
    f, mu, gamma = np.zeros((N, 3)), [None] * N, [None] * N
    for i in range(N):
        j = parents[i]
        gamma[i] = R[i].T @ ((a[j] if j >= 0 else 0.0) + kappa[i])     # (6.101)
        mu[i] = U[i].T @ A[i] @ U[i] @ gamma[i] + U[i].T @ d[i]         # (6.106a)
        f[i] = T[i] @ tau[i] + R[i] @ mu[i]                             # (6.109)
    return ProjectiveWorkspace(art.S, R, T, U, A, d, tau, mu, psi, gamma, a, f,
                               joint_accelerations(T, a, kappa, parents))          # (6.110)


def projective_workspace(model, q, qd=None, tau=None, f_ext=None) -> ProjectiveWorkspace:
    """Full projective solution of one state of ``model`` (thesis 6.101-6.110), for drawings.

    Parameters
    ----------
    model, q, qd, tau, f_ext : Model, array_like
        The mechanism and one state (``q``, ``qd``, ``tau`` of shape (nq,)), as for
        :func:`planargeo.algorithms.articulated_inertia.articulated_inertia`.

    Returns
    -------
    ProjectiveWorkspace
        As :func:`projective_solve` returns it.

    Examples
    --------
    >>> from planargeo.mechanics.model import chain_model
    >>> projective_workspace(chain_model(2, gravity=(0, 0)), [0, 0], [0, 0], [1, 0]).qdd.round(9)
    array([ 1.71428571, -4.28571429])
    """
    return projective_solve(*_state_arrays(model, q, qd, tau, f_ext)[1:])


def _projective_qdd(model, q, qd, tau, f_ext):
    """``qdd`` of one checked state by 6.107, 6.108, 6.110, without the reaction components."""
    _, I, S, kappa, p, taus, parents, points, jpoints = _state_arrays(model, q, qd, tau, f_ext, checked=True)
    art = articulated_recursion(I, S, kappa, p, taus, parents, points, jpoints)
    return joint_accelerations(art.T, _accelerations(art, kappa, taus, parents)[1], kappa, parents)


def forward_dynamics_projective(model, q, qd, tau, f_ext=None) -> np.ndarray:
    """Joint accelerations by the projective articulated equations (thesis 6.108-6.110), state by state.

    Parameters
    ----------
    model, q, qd, tau, f_ext : Model, array_like
        The mechanism and its states, as for :func:`planargeo.algorithms.aba.forward_dynamics`.

    Returns
    -------
    numpy.ndarray, shape (..., nq)

    Raises
    ------
    ShapeError, NonFiniteError, InputError, SingularConfigurationError
        Bad arguments, as for :func:`planargeo.algorithms.aba.forward_dynamics`; a singular ``s_i^T A_i s_i``.

    Examples
    --------
    >>> from planargeo.mechanics.model import chain_model
    >>> forward_dynamics_projective(chain_model(1), [0.0], [0.0], [0.0]).round(6)    # -3g / 2L
    array([-14.715])
    """
    return _per_state(_projective_qdd, model, q, qd, tau, f_ext)
