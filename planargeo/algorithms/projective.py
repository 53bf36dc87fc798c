"""Projective articulated dynamics: subspaces, propagators, forward dynamics (thesis 6.5-6.8).

Every joint ``i`` splits the wrenches and accelerations of its body into an
*active* part along the joint and a *reactive* part (thesis 6.38, 6.44)::

    f_i = T_i Q_i + R_i mu_i          a_i = s_i psi_i + U_i gamma_i

with the joint space ``s_i`` (3×k), the reaction space ``R_i`` (3×(3-k),
``s_i^T R_i = 0``, 6.1) and the weighted pseudo-inverses (6.105, 6.99)::

    T_i = A_i s_i (s_i^T A_i s_i)^-1      U_i = A_i^-1 R_i (R_i^T A_i^-1 R_i)^-1

built on the articulated inertia ``A_i`` (6.8 uses the body inertia ``I_i``).
The components are projections (6.61, 6.62): ``Q = s^T f``, ``mu = U^T f``,
``psi = T^T a``, ``gamma = R^T a``.

Solving the chain from the base outwards with the articulated inertias of
:mod:`planargeo.algorithms.articulated_inertia` (thesis 6.108-6.110)::

    gamma_i = R_i^T (a_{i-1} + kappa_i)                          (6.101)
    psi_i   = T_i^T A_i^-1 (T_i Q_i - d_i)                        (6.107)
    a_i     = s_i psi_i + U_i gamma_i                             (6.108)
    mu_i    = U_i^T A_i U_i gamma_i + U_i^T d_i                   (6.106a)
    f_i     = T_i Q_i + R_i mu_i                                  (6.109)
    qdd_i   = T_i^T (a_i - a_{i-1} - kappa_i)                     (6.110)

All quantities are world-frame screws at the global origin (twist
``[vx, vy, w]``, wrench ``[fx, fy, tz]``); ``a_{i-1}`` is the acceleration of
body ``i``'s parent (zero for the ground), so trees are handled as well as
chains.

Reaction basis (the meaning of ``mu``): every ``R_i`` is
:func:`planargeo.mechanics.joints.R_of`, the package's one definition
(:func:`planargeo.mechanics.joints.reaction_space`, thesis 4.8, 5.63, 7.16): for a
revolute joint at ``(x, y)`` the unit forces along x and y through the joint;
for a prismatic joint along ``e`` the unit force along ``e⊥`` (``e`` turned by
+90°) through the slider (the body frame's origin) and the unit couple; for a
revolute-prismatic joint the unit force along ``e⊥`` through the pin.  So with
no joint force (``Q = 0``) ``mu`` is the joint's reaction force in those
components; in general ``f = T Q + R mu`` first sets apart the force ``T Q`` on
the axis of percussion (6.38).  ``T`` and ``U`` come from
:func:`planargeo.mechanics.subspaces.T_of` and
:func:`planargeo.mechanics.subspaces.U_of` (one implementation,
one singularity rule); ``qdd`` does not depend on the basis.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from planargeo.mechanics.subspaces import _effective_mobility, _solve, T_of
from planargeo.algorithms.articulated_inertia import _per_state, _state_arrays, articulated_recursion

__all__ = ["acceleration_propagator", "force_propagator", "joint_accelerations",
           "ProjectiveWorkspace", "projective_solve", "projective_workspace", "forward_dynamics_projective"]


# ---------------------------------------------------------------------------
# Propagators (thesis 6.113)
# ---------------------------------------------------------------------------
def _propagator_args(I, s, Q, T):
    I = np.asarray(I, dtype=float)
    s = np.asarray(s, dtype=float).reshape(3, -1)
    T = T_of(I, s) if T is None else np.asarray(T, dtype=float).reshape(3, -1)
    return I, s, np.asarray(Q, dtype=float).reshape(-1), T


def acceleration_propagator(I, s, Q, p, f_next, a_prev, kappa, *, T=None) -> np.ndarray:
    """Acceleration of a body from its neighbours' loads (thesis 6.113a).

    ``a_i = s_i T_i^T I_i^-1 (T_i Q_i - p_i - f_{i+1}) + U_i R_i^T (a_{i-1} + kappa_i)``
    with ``T_i``, ``U_i`` built on the body inertia (6.36, 6.37); ``s T^T I^-1 = s (s^T I s)^-1 s^T``
    (6.93) and ``U R^T = 1 - s T^T`` (6.75), whatever the reaction basis.

    Parameters
    ----------
    I : array_like, shape (3, 3)
        Body inertia at the origin.
    s : array_like, shape (3, k)
        Joint motion space.
    Q : array_like, shape (k,)
        Joint force/torque.
    p : array_like, shape (3,)
        Bias force of the body (3.11), gravity included.
    f_next : array_like, shape (3,)
        Internal force of the child joints (their sum).
    a_prev : array_like, shape (3,)
        Acceleration of the parent body.
    kappa : array_like, shape (3,)
        Bias acceleration of the joint (2.19).
    T : array_like, shape (3, k), optional
        The percussion space ``I s (sᵀIs)⁻¹`` if already formed (and checked, e.g. by
        the singularity rule at the joint's own point); by default it is formed here
        (:func:`planargeo.mechanics.subspaces.T_of`, the rule measured at the origin).

    Returns
    -------
    numpy.ndarray, shape (3,)
        ``a_i``, the body's acceleration at the origin.

    Examples
    --------
    A unit point mass at (1, 0) pinned at the origin, pushed up by a unit force
    through itself (``p = -g``): it turns at 1 rad/s².

    >>> from planargeo.screws.twists import inertia_matrix
    >>> acceleration_propagator(inertia_matrix(1.0, [1.0, 0.0], 0.0), [[0.0], [0.0], [1.0]], [0.0],
    ...                         [0.0, -1.0, -1.0], np.zeros(3), np.zeros(3), np.zeros(3))
    array([0., 0., 1.])
    """
    I, s, Q, T = _propagator_args(I, s, Q, T)
    base = np.asarray(a_prev, dtype=float) + np.asarray(kappa, dtype=float)
    rhs = T @ Q - np.asarray(p, dtype=float) - np.asarray(f_next, dtype=float)
    return _effective_mobility(I, s, gram=(I @ s, s.T @ I @ s)) @ rhs + base - s @ (T.T @ base)


def force_propagator(I, s, Q, p, f_next, a_prev, kappa, *, T=None) -> np.ndarray:
    """Internal force of a body's joint from its neighbours (thesis 6.113b).

    ``f_i = T_i Q_i + R_i U_i^T (I_i (a_{i-1} + kappa_i) + p_i + f_{i+1})``
    with ``T_i``, ``U_i`` built on the body inertia (6.36, 6.37) and ``R U^T = 1 - T s^T``
    (7.8), whatever the reaction basis.  Parameters as :func:`acceleration_propagator`.

    Parameters
    ----------
    I, s, Q, p, f_next, a_prev, kappa, T : array_like
        As in :func:`acceleration_propagator`.

    Returns
    -------
    numpy.ndarray, shape (3,)
        ``f_i``.

    Examples
    --------
    The pinned point mass of :func:`acceleration_propagator`, at rest with the
    base still: the pin carries the whole push (``f = I a + p`` with ``a = [0, 0, 1]``).

    >>> from planargeo.screws.twists import inertia_matrix
    >>> f = force_propagator(inertia_matrix(1.0, [1.0, 0.0], 0.0), [[0.0], [0.0], [1.0]], [0.0],
    ...                      [0.0, -1.0, -1.0], np.zeros(3), np.zeros(3), np.zeros(3))
    >>> np.round(f, 12) + 0.0
    array([0., 0., 0.])
    """
    I, s, Q, T = _propagator_args(I, s, Q, T)
    load = I @ (np.asarray(a_prev, dtype=float) + np.asarray(kappa, dtype=float)) + np.asarray(p, dtype=float) \
        + np.asarray(f_next, dtype=float)
    return T @ Q + load - T @ (s.T @ load)


def joint_accelerations(T, a, kappa, parents) -> np.ndarray:
    """Joint accelerations ``qdd_i = T_i^T (a_i - a_{λ(i)} - kappa_i)`` (thesis 6.110), all joints.

    Parameters
    ----------
    T : list of N (3, k_i) percussion spaces (6.105, or 6.36: ``sᵀT = 1`` is all that is used).
        Each joint's percussion space ``T_i`` (3, k_i).
    a, kappa : (N, 3) body and bias accelerations; ``a_{λ(i)}`` is the parent's (zero for the ground).
        Body accelerations and joint bias accelerations (3,) each.
    parents : sequence of N ints.
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


# ---------------------------------------------------------------------------
# Projective forward dynamics (thesis 6.101-6.110)
# ---------------------------------------------------------------------------
@dataclass
class ProjectiveWorkspace:
    """Everything the projective solution computes, per body ``i`` (thesis 6.99-6.110; lists of arrays).

    ``mu[i]`` are components in ``R[i]``, the basis of
    :func:`planargeo.mechanics.joints.R_of` (unit forces through the joint, couples).

    Attributes
    ----------
    s, R, T, U : list of (3, k), (3, 3-k), (3, k), (3, 3-k)
        Joint space, reaction space, active force and reactive acceleration subspaces (6.99, 6.105).
    A, d : (N, 3, 3), (N, 3)
        Articulated inertias and bias forces (7.7a, 7.7b).
    Q, mu : list of (k,), (3-k,)
        Active (joint torque) and reaction components of ``f_i`` (6.104, 6.106a).
    psi, gamma : list of (k,), (3-k,)
        Active and reactive components of ``a_i`` (6.107, 6.101).
    a, f : (N, 3)
        Body accelerations (6.108) and internal joint forces (6.109).
    qdd : (nq,) joint accelerations (6.110).
        Joint accelerations (6.110).
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
    """``psi_i`` (6.107) and ``a_i`` (6.108), base to tips, from the articulated quantities.

    ``psi = T^T A^-1 (T Q - d) = (s^T A s)^-1 (Q - s^T d)`` and ``U R^T = 1 - s T^T`` (6.75):
    neither ``A^-1`` nor a reaction basis is needed.
    """
    N = len(art.S)
    a = np.zeros((N, 3))
    psi = [None] * N
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
    I : (N, 3, 3) body inertias at the origin.
        Body inertias at the origin (3, 3) each.
    S : list of N arrays (3, k_i): joint spaces.
        Joint motion spaces (3, k_i) each.
    kappa, p : (N, 3) bias accelerations (2.19) and bias forces (3.11).
        Bias accelerations (2.19) and bias forces (3.11, gravity included) of the bodies.
    tau : list of N arrays (k_i,): joint torques ``Q_i``.
        Joint forces, one array (k_i,) per joint.
    parents : sequence of N ints (``-1`` ground, parents before children), default a chain.
        Parent of each body (-1: the ground).
    points : (N, 2), optional
        A point of each joint for the reaction bases (:func:`planargeo.mechanics.joints.R_of`:
        used by prismatic joints, whose reaction force passes through it); default the origin.
        :func:`projective_workspace` passes each body's frame origin.
    joint_points : (N, 2), optional
        Each joint's point (pivot; placement point of a prismatic joint: the joint
        frame's origin), where the singularity rule of :data:`planargeo.errors.COND_LIMIT`
        is measured; default the origin.  The model-level functions pass the joint frames' origins.

    Returns
    -------
    ProjectiveWorkspace
        ``mu[i]`` are the reaction components in the basis ``R[i]`` of
        :func:`planargeo.mechanics.joints.R_of` (forces along x and y through
        a revolute joint; force along ``e⊥`` through the slider and a couple
        for a prismatic joint), so that ``f[i] = T[i] Q[i] + R[i] mu[i]``.

    Raises
    ------
    SingularConfigurationError
        When some ``s_i^T A_i s_i`` is singular (the rule of :data:`planargeo.errors.COND_LIMIT`).

    Examples
    --------
    One unit point mass at (1, 0) on a pin at the origin, a unit torque: ``qdd = 1``.

    >>> from planargeo.screws.twists import inertia_matrix
    >>> ws = projective_solve([inertia_matrix(1.0, [1.0, 0.0], 0.0)], [np.array([[0.0], [0.0], [1.0]])],
    ...                       np.zeros((1, 3)), np.zeros((1, 3)), [np.array([1.0])])
    >>> ws.qdd, ws.a[0]
    (array([1.]), array([0., 0., 1.]))
    """
    art = articulated_recursion(I, S, kappa, p, tau, parents, points, joint_points)
    N = len(art.S)
    parents = list(range(-1, N - 1)) if parents is None else [int(x) for x in parents]
    kappa = np.asarray(kappa, dtype=float)
    tau = [np.asarray(x, dtype=float).reshape(-1) for x in tau]
    psi, a = _accelerations(art, kappa, tau, parents)
    A, d, T, R, U = art.A, art.d, art.T, art.R, art.U
    f = np.zeros((N, 3))
    mu, gamma = [None] * N, [None] * N
    for i in range(N):
        j = parents[i]
        gamma[i] = R[i].T @ ((a[j] if j >= 0 else 0.0) + kappa[i])     # (6.101)
        mu[i] = U[i].T @ A[i] @ U[i] @ gamma[i] + U[i].T @ d[i]         # (6.106a)
        f[i] = T[i] @ tau[i] + R[i] @ mu[i]                             # (6.109)
    return ProjectiveWorkspace(art.S, R, T, U, A, d, tau, mu, psi, gamma, a, f,
                               joint_accelerations(T, a, kappa, parents))          # (6.110)


def projective_workspace(model, q, qd=None, tau=None, f_ext=None) -> ProjectiveWorkspace:
    """Full projective solution of one state of ``model`` (thesis 6.101-6.110).

    Returns the per-joint subspaces ``T, U``, components ``Q, mu, psi,
    gamma``, body accelerations ``a_i`` and internal forces ``f_i`` (for drawings).

    Parameters
    ----------
    model : Model
        The mechanism.
    q, qd, tau, f_ext : array_like
        The state, as for :func:`planargeo.algorithms.articulated_mobility.articulated_mobility`.

    Returns
    -------
    ProjectiveWorkspace
        The per-joint quantities.

    Examples
    --------
    >>> from planargeo.mechanics.model import chain_model
    >>> ws = projective_workspace(chain_model(2, gravity=(0, 0)), [0.0, 0.0], [0.0, 0.0], [1.0, 0.0])
    >>> [round(float(x), 12) for x in ws.qdd]
    [1.714285714286, -4.285714285714]
    """
    return projective_solve(*_state_arrays(model, q, qd, tau, f_ext)[1:])


def _projective_qdd(model, q, qd, tau, f_ext):
    """``qdd`` of one checked state by 6.107, 6.108, 6.110, without the reaction components."""
    _, I, S, kappa, p, taus, parents, points, jpoints = _state_arrays(model, q, qd, tau, f_ext, checked=True)
    art = articulated_recursion(I, S, kappa, p, taus, parents, points, jpoints)
    return joint_accelerations(art.T, _accelerations(art, kappa, taus, parents)[1], kappa, parents)


def forward_dynamics_projective(model, q, qd, tau, f_ext=None) -> np.ndarray:
    """Joint accelerations by the projective articulated equations (thesis 6.108-6.110).

    The forward-dynamics signature of :mod:`planargeo.algorithms`: ``q``, ``qd``, ``tau``
    of shape (..., nq) (leading batch dimensions solved state by state), ``f_ext`` (..., N, 3)
    world wrenches at the origin on the bodies (besides gravity); returns ``q̈`` (..., nq).

    Parameters
    ----------
    model : Model
        The mechanism.
    q : array_like, shape (..., nq)
        Joint coordinates.
    qd : array_like, shape (..., nq)
        Joint velocities.
    tau : array_like, shape (..., nq)
        Joint forces/torques (N, N·m).
    f_ext : array_like, shape (..., N, 3), optional
        External world wrenches at the origin on the bodies (besides gravity).

    Returns
    -------
    numpy.ndarray, shape (..., nq)
        ``q̈``.

    Raises
    ------
    SingularConfigurationError
        When some ``s_i^T A_i s_i`` is singular.

    Examples
    --------
    A unit slender link lying along +x on a pin at the origin, under gravity:
    ``qdd = -g (L/2) / (L^2/3) = -14.715``.

    >>> from planargeo.mechanics.model import chain_model
    >>> forward_dynamics_projective(chain_model(1), [0.0], [0.0], [0.0]).round(6)
    array([-14.715])
    """
    return _per_state(_projective_qdd, model, q, qd, tau, f_ext)
