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
:func:`planargeo.mechanics.joints.reaction_space_of`, the package's one definition
(:func:`planargeo.mechanics.joints.reaction_space`, thesis 4.8, 5.63, 7.16): for a
revolute joint at ``(x, y)`` the unit forces along x and y through the joint;
for a prismatic joint along ``e`` the unit force along ``e⊥`` (``e`` turned by
+90°) through the slider (the body frame's origin) and the unit couple; for a
revolute-prismatic joint the unit force along ``e⊥`` through the pin.  So with
no joint force (``Q = 0``) ``mu`` is the joint's reaction force in those
components; in general ``f = T Q + R mu`` first sets apart the force ``T Q`` on
the axis of percussion (6.38).  ``T`` and ``U`` come from
:func:`planargeo.mechanics.subspaces.percussion_space` and
:func:`planargeo.mechanics.subspaces.reactive_acceleration_space` (one implementation,
one singularity rule); ``qdd`` does not depend on the basis.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from planargeo.mechanics.joints import reaction_space_of
from planargeo.mechanics.subspaces import _reactive_from_T, _solve, effective_mobility, percussion_space, reactive_acceleration_space

__all__ = [
    "reaction_space", "percussion_subspace", "reactive_subspace",
    "acceleration_propagator", "force_propagator",
    "ProjectiveWorkspace", "projective_solve", "projective_workspace",
    "forward_dynamics_projective",
]


# ---------------------------------------------------------------------------
# Subspaces (thesis 6.1, 6.30/6.105, 6.33/6.99): thin wrappers of the one
# implementation each, in planargeo.mechanics.joints and planargeo.mechanics.subspaces
# ---------------------------------------------------------------------------
def reaction_space(s, point=(0.0, 0.0)) -> np.ndarray:
    """Reaction space ``R`` of the joint with motion space ``s`` (thesis 6.1, 7.16, 5.63).

    The same basis everywhere: this is :func:`planargeo.mechanics.joints.reaction_space_of`
    (which reads kind, pivot and direction off ``s`` and calls
    :func:`planargeo.mechanics.joints.reaction_space`).  Revolute: unit forces along x
    and y through the pivot; prismatic: the unit force along ``e⊥`` through
    ``point`` (on the slide) and the unit couple; revolute-prismatic: the unit
    force along ``e⊥`` through the pivot.

    Examples
    --------
    >>> reaction_space([[0.0], [-2.0], [1.0]])          # revolute at (2, 0), thesis 7.16
    array([[1., 0.],
           [0., 1.],
           [0., 2.]])
    >>> reaction_space([[1.0], [0.0], [0.0]], (2.0, 3.0))   # prismatic along x through (2, 3)
    array([[0., 0.],
           [1., 0.],
           [2., 1.]])
    """
    return reaction_space_of(s, point)


def percussion_subspace(A, s, *, what: str = "sᵀAs") -> np.ndarray:
    """Active force subspace ``T = A s (sᵀAs)⁻¹`` (thesis 6.30, 6.105; 6.36 with ``I``).

    Alias of :func:`planargeo.mechanics.subspaces.percussion_space` with the arguments
    in the order ``(A, s)``; the singularity rule and message are that
    function's (:class:`~planargeo.errors.SingularConfigurationError` with ``.cond``).

    Examples
    --------
    Thesis 7.40 (m = 1, L = 1, rho = 1/2: ``2L/(L^2 + 4 rho^2) = 1``):

    >>> from planargeo.screws.twists import inertia_matrix
    >>> percussion_subspace(inertia_matrix(1.0, [0.5, 0.0], 0.25), [[0.0], [0.0], [1.0]]).ravel()
    array([0., 1., 1.])
    """
    return percussion_space(np.asarray(s, dtype=float).reshape(3, -1), A, what=what)


def reactive_subspace(A, R, *, s=None, T=None, what: str | None = None) -> np.ndarray:
    """Reactive acceleration subspace ``U = A⁻¹ R (Rᵀ A⁻¹ R)⁻¹`` (thesis 6.45, 6.99, 6.37).

    Alias of :func:`planargeo.mechanics.subspaces.reactive_acceleration_space` with the
    arguments in the order ``(A, R)``.  With ``s`` (and optionally ``T``) the
    inverse-free form ``U = (1 - s Tᵀ) R (RᵀR)⁻¹`` is used (point masses have
    a singular ``A``).  Thesis 6.33 misprints the inverse; see
    ``docs/errata.md``.

    Examples
    --------
    Thesis 7.40 (m = 1, L = 1, rho = 1/2):

    >>> from planargeo.screws.twists import inertia_matrix
    >>> U = reactive_subspace(inertia_matrix(1.0, [0.5, 0.0], 0.25), reaction_space([[0.0], [0.0], [1.0]]))
    >>> np.round(U, 12) + 0.0
    array([[ 1.,  0.],
           [ 0.,  1.],
           [ 0., -1.]])
    """
    R = np.asarray(R, dtype=float).reshape(3, -1)
    if s is not None:
        s = np.asarray(s, dtype=float).reshape(3, -1)
    if T is not None:
        T = np.asarray(T, dtype=float).reshape(3, -1)
    return reactive_acceleration_space(R, A, s=s, T=T, what=what)


def _active_mobility(A, s, what):
    """``s (sᵀAs)⁻¹ sᵀ`` = ``s Tᵀ A⁻¹`` (thesis 6.93, 7.31a): :func:`planargeo.mechanics.subspaces.effective_mobility`."""
    return effective_mobility(s, A, what=what)


def _joint_solve(A, s, rhs):
    """``(sᵀAs)⁻¹ rhs``; call after ``T`` was built, so singularity has been checked (one rule)."""
    k = s.shape[1]
    if k == 0:
        return np.zeros(0)
    return _solve(s.T @ A @ s, rhs)


# ---------------------------------------------------------------------------
# Propagators (thesis 6.113)
# ---------------------------------------------------------------------------
def acceleration_propagator(I, s, Q, p, f_next, a_prev, kappa, R=None) -> np.ndarray:
    """Acceleration of a body from its neighbours' loads (thesis 6.113a).

    ``a_i = s_i T_i^T I_i^-1 (T_i Q_i - p_i - f_{i+1}) + U_i R_i^T (a_{i-1} + kappa_i)``
    with ``T_i``, ``U_i`` built on the body inertia (6.36, 6.37).

    Parameters
    ----------
    I : (3, 3) body inertia; s : (3, k) joint space; Q : (k,) joint torque;
    p : (3,) bias force (3.11); f_next : (3,) internal force of the child
    joints (sum); a_prev : (3,) parent acceleration; kappa : (3,) bias
    acceleration (2.19); R : (3, 3-k) reaction space (default :func:`reaction_space`).

    Examples
    --------
    A unit point mass at (1, 0) pinned at the origin, pushed up by a unit force
    through itself (``p = -g``): it turns at 1 rad/s².

    >>> from planargeo.screws.twists import inertia_matrix
    >>> acceleration_propagator(inertia_matrix(1.0, [1.0, 0.0], 0.0), [[0.0], [0.0], [1.0]], [0.0],
    ...                         [0.0, -1.0, -1.0], np.zeros(3), np.zeros(3), np.zeros(3))
    array([0., 0., 1.])
    """
    I = np.asarray(I, dtype=float)
    s = np.asarray(s, dtype=float).reshape(3, -1)
    R = reaction_space(s) if R is None else np.asarray(R, dtype=float).reshape(3, -1)
    T = percussion_subspace(I, s)
    U = reactive_subspace(I, R, s=s, T=T)
    Q = np.asarray(Q, dtype=float).reshape(-1)
    rhs = T @ Q - np.asarray(p, dtype=float) - np.asarray(f_next, dtype=float)
    return _active_mobility(I, s, "sᵀIs") @ rhs + U @ (R.T @ (np.asarray(a_prev, dtype=float) + np.asarray(kappa, dtype=float)))


def force_propagator(I, s, Q, p, f_next, a_prev, kappa, R=None, *, T=None) -> np.ndarray:
    """Internal force of a body's joint from its neighbours (thesis 6.113b).

    ``f_i = T_i Q_i + R_i U_i^T (I_i (a_{i-1} + kappa_i) + p_i + f_{i+1})``
    with ``T_i``, ``U_i`` built on the body inertia (6.36, 6.37).

    ``T``: the percussion subspace ``I s (sᵀIs)⁻¹`` if already formed (and checked, e.g. by
    the singularity rule at the joint's own point, as :func:`reactive_subspace` takes it);
    by default it is formed here, with the rule measured at the origin of the coordinates.

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
    I = np.asarray(I, dtype=float)
    s = np.asarray(s, dtype=float).reshape(3, -1)
    R = reaction_space(s) if R is None else np.asarray(R, dtype=float).reshape(3, -1)
    T = percussion_subspace(I, s) if T is None else np.asarray(T, dtype=float).reshape(3, -1)
    U = reactive_subspace(I, R, s=s, T=T)
    Q = np.asarray(Q, dtype=float).reshape(-1)
    base = I @ (np.asarray(a_prev, dtype=float) + np.asarray(kappa, dtype=float))
    return T @ Q + R @ (U.T @ (base + np.asarray(p, dtype=float) + np.asarray(f_next, dtype=float)))


# ---------------------------------------------------------------------------
# Model glue
# ---------------------------------------------------------------------------
def _state_arrays(model, q, qd, tau, f_ext, checked=False):
    """Kinematics of one state: (data, I, S list, kappa, p, parents, tau list).

    ``checked``: the arguments come out of :func:`planargeo.mechanics.kinematics.check_state`
    for one state already (as in :func:`_per_state`), so they are not validated again.
    """
    from planargeo.mechanics.kinematics import _kinematics_scalar, check_state

    if not checked:
        q, qd, tau, f_ext, _, shape = check_state(model, q, qd, tau, f_ext)
        if shape != ():
            raise _batch_error(shape)
    if tau is None:
        tau = np.zeros(model.nq)
    d = _kinematics_scalar(model, q, np.zeros(model.nq) if qd is None else qd, f_ext)   # kinematics()
    offs, N = model.q_offsets, model.N
    S = [d.S[:, offs[i]:offs[i + 1]] for i in range(N)]            # d.s(i)
    taus = [tau[offs[i]:offs[i + 1]] for i in range(N)]
    return d, d.I, S, d.kappa, d.p, list(model.parents), taus


def _batch_error(shape):
    from planargeo.errors import ShapeError

    return ShapeError(f"q must describe one state (shape (nq,)), got batch shape {shape}; "
                      "loop over states or use planargeo.algorithms.aba for batches")


def _per_state(fn, model, q, qd, tau, f_ext):
    """Apply the single-state solver ``fn(model, q, qd, tau, f_ext) -> (nq,)`` over batch dimensions."""
    from planargeo.mechanics.kinematics import check_state

    q, qd, tau, f_ext, _, shape = check_state(model, q, qd, tau, f_ext)
    if shape == ():
        return fn(model, q, qd, tau, f_ext)
    nq, N = model.nq, model.N
    q = np.broadcast_to(q, shape + (nq,))
    qd = np.zeros(shape + (nq,)) if qd is None else np.broadcast_to(qd, shape + (nq,))
    tau = np.zeros(shape + (nq,)) if tau is None else np.broadcast_to(tau, shape + (nq,))
    fx = None if f_ext is None else np.broadcast_to(f_ext, shape + (N, 3))
    out = np.empty(shape + (nq,))
    for idx in np.ndindex(*shape):
        out[idx] = fn(model, q[idx], qd[idx], tau[idx], None if fx is None else fx[idx])
    return out


# ---------------------------------------------------------------------------
# Projective forward dynamics (thesis 6.101-6.110)
# ---------------------------------------------------------------------------
@dataclass
class ProjectiveWorkspace:
    """Everything the projective solution computes, per body ``i`` (thesis 6.99-6.110; lists of arrays).

    ``mu[i]`` are components in ``R[i]``, the basis of
    :func:`planargeo.mechanics.joints.reaction_space_of` (unit forces through the joint, couples).

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


def projective_solve(I, S, kappa, p, tau, parents=None, points=None, joint_points=None) -> ProjectiveWorkspace:
    """Projective articulated equations of motion on arrays (thesis 6.101-6.110).

    Parameters
    ----------
    I : (N, 3, 3) body inertias at the origin.
    S : list of N arrays (3, k_i): joint spaces.
    kappa, p : (N, 3) bias accelerations (2.19) and bias forces (3.11).
    tau : list of N arrays (k_i,): joint torques ``Q_i``.
    parents : sequence of N ints (``-1`` ground), default a chain.
    points : (N, 2), optional
        A point of each joint for the reaction bases (:func:`planargeo.mechanics.joints.reaction_space_of`:
        used by prismatic joints, whose reaction force passes through it); default the origin.
        :func:`projective_workspace` passes each body's frame origin.
    joint_points : (N, 2), optional
        Each joint's point (pivot; placement point of a prismatic joint: the joint
        frame's origin), where the singularity rule of :data:`planargeo.mechanics.subspaces.COND_LIMIT`
        is measured; default the origin.  The model-level functions pass the joint frames' origins.

    Returns
    -------
    ProjectiveWorkspace
        ``mu[i]`` are the reaction components in the basis ``R[i]`` of
        :func:`planargeo.mechanics.joints.reaction_space_of` (forces along x and y through
        a revolute joint; force along ``e⊥`` through the slider and a couple
        for a prismatic joint), so that ``f[i] = T[i] Q[i] + R[i] mu[i]``.

    Examples
    --------
    One unit point mass at (1, 0) on a pin at the origin, a unit torque: ``qdd = 1``.

    >>> from planargeo.screws.twists import inertia_matrix
    >>> ws = projective_solve([inertia_matrix(1.0, [1.0, 0.0], 0.0)], [np.array([[0.0], [0.0], [1.0]])],
    ...                       np.zeros((1, 3)), np.zeros((1, 3)), [np.array([1.0])])
    >>> ws.qdd, ws.a[0]
    (array([1.]), array([0., 0., 1.]))
    """
    from planargeo.algorithms.articulated_inertia import articulated_recursion

    I = np.asarray(I, dtype=float)
    N = I.shape[0]
    parents = list(range(-1, N - 1)) if parents is None else [int(x) for x in parents]
    S = [np.asarray(x, dtype=float).reshape(3, -1) for x in S]
    tau = [np.asarray(x, dtype=float).reshape(-1) for x in tau]
    kappa = np.asarray(kappa, dtype=float)
    p = np.asarray(p, dtype=float)
    rec = articulated_recursion(I, S, kappa, p, tau, parents, points, joint_points)
    A, d, T, R = rec.A, rec.d, rec.T, rec.R
    U = [_reactive_from_T(R[i], S[i], T[i]) for i in range(N)]   # (6.99), inverse-free (6.75)
    a = np.zeros((N, 3))
    f = np.zeros((N, 3))
    mu, psi, gamma, qdd = [None] * N, [None] * N, [None] * N, []
    for i in range(N):
        j = parents[i]
        a_prev = a[j] if j >= 0 else np.zeros(3)
        base = a_prev + kappa[i]
        gamma[i] = R[i].T @ base                                     # (6.101)
        # (6.107) with T^T A^-1 = (s^T A s)^-1 s^T: psi = (s^T A s)^-1 (Q - s^T d)
        psi[i] = _joint_solve(A[i], S[i], tau[i] - S[i].T @ d[i])
        a[i] = S[i] @ psi[i] + U[i] @ gamma[i]                       # (6.108)
        mu[i] = U[i].T @ A[i] @ U[i] @ gamma[i] + U[i].T @ d[i]       # (6.106a)
        f[i] = T[i] @ tau[i] + R[i] @ mu[i]                          # (6.109)
        qdd.append(T[i].T @ (a[i] - base))                           # (6.110)
    qdd = np.concatenate(qdd) if qdd else np.zeros(0)
    return ProjectiveWorkspace(S, R, T, U, A, d, list(tau), mu, psi, gamma, a, f, qdd)


def projective_workspace(model, q, qd=None, tau=None, f_ext=None) -> ProjectiveWorkspace:
    """Full projective solution of one state of ``model`` (thesis 6.101-6.110).

    Returns the per-joint subspaces ``T, U``, components ``Q, mu, psi,
    gamma``, body accelerations ``a_i`` and internal forces ``f_i`` (for drawings).

    Examples
    --------
    >>> from planargeo.mechanics.model import chain_model
    >>> ws = projective_workspace(chain_model(2, gravity=(0, 0)), [0.0, 0.0], [0.0, 0.0], [1.0, 0.0])
    >>> [round(float(x), 12) for x in ws.qdd]
    [1.714285714286, -4.285714285714]
    """
    d, I, S, kappa, p, parents, taus = _state_arrays(model, q, qd, tau, f_ext)
    return projective_solve(I, S, kappa, p, taus, parents, d.pose[:, :2], d.origin)


def _projective_qdd(model, q, qd, tau, f_ext):
    """``qdd`` of one state by 6.107, 6.108, 6.110, without the reaction bases.

    The reactive part of 6.108 needs only the projector ``U_i R_i^T = 1 - s_i T_i^T``
    (the twist projectors of 6.75), which is the same for every reaction basis,
    so ``R_i``, ``U_i``, ``gamma_i``, ``mu_i`` and ``f_i`` (the drawing workspace
    of :func:`projective_workspace`) are not built.
    """
    from planargeo.algorithms.articulated_inertia import _articulated

    data, I, S, kappa, p, parents, taus = _state_arrays(model, q, qd, tau, f_ext, checked=True)
    A, d, T = _articulated(I, S, kappa, p, taus, parents, data.origin)
    N = len(S)
    a = np.zeros((N, 3))
    qdd = []
    zero = np.zeros(3)
    for i in range(N):
        j = parents[i]
        base = (a[j] if j >= 0 else zero) + kappa[i]
        Si, Ti = S[i], T[i]
        psi = _joint_solve(A[i], Si, taus[i] - Si.T @ d[i])             # (6.107)
        a[i] = Si @ psi + (base - Si @ (Ti.T @ base))                   # (6.108), U R^T = 1 - s T^T
        qdd.append(Ti.T @ (a[i] - base))                                # (6.110)
    return np.concatenate(qdd) if qdd else np.zeros(0)


def forward_dynamics_projective(model, q, qd, tau, f_ext=None) -> np.ndarray:
    """Joint accelerations by the projective articulated equations (thesis 6.108-6.110).

    Parameters
    ----------
    model : planargeo.mechanics.model.Model
    q, qd, tau : array_like (..., nq)
        Leading batch dimensions are solved state by state.
    f_ext : array_like (..., N, 3), optional
        World wrenches at the origin applied to each body (besides gravity).

    Returns
    -------
    ndarray (..., nq)

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
