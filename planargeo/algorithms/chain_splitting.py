"""Chain splitting: direct body accelerations and joint forces (thesis 7.6).

Split the chain at joint ``i+1``: the bodies ``1..i`` form a constrained
chain with articulated mobility ``Lambda_i^-1``, ``b_i`` (7.4.1,
:mod:`~planargeo.algorithms.articulated_mobility`), the bodies ``i+1..N`` a
free-floating chain with articulated inertia ``A_{i+1}``, ``d_{i+1}`` (7.1.1,
:mod:`~planargeo.algorithms.articulated_inertia`).  Eliminating the unknown
force or acceleration gives, with ``K = R_{i+1} U_{i+1}^T A_{i+1}`` and
``C = 1 + Lambda_i^-1 K``::

    a_i     = C^-1 [b_i - Lambda_i^-1 (T_{i+1} Q_{i+1} + R_{i+1} U_{i+1}^T (A_{i+1} kappa_{i+1} + d_{i+1}))]   (7.54)
    f_{i+1} = C^-T [T_{i+1} Q_{i+1} + R_{i+1} U_{i+1}^T (A_{i+1} (b_i + kappa_{i+1}) + d_{i+1})]             (7.56)

For the tip ``a_N = b_N``.  7.56 relies on ``C^T = 1 + K Lambda_i^-1`` (7.55),
true because ``K = R (R^T A^-1 R)^-1 R^T`` and ``Lambda_i^-1`` are symmetric;
it holds only with the corrected mobility recursion (7.38a).  Joint
accelerations then follow from 6.110: ``qdd_i = T_i^T (a_i - a_{i-1} - kappa_i)``.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from planargeo.errors import SingularConfigurationError
from planargeo.algorithms.articulated_inertia import _articulated
from planargeo.mechanics.subspaces import _solve
from planargeo.algorithms.articulated_mobility import _EYE3, SOLVE_COND_LIMIT, _check_chain, _cond, _mobility
from planargeo.algorithms.projective import _per_state, _state_arrays, force_propagator

_ZERO3 = np.zeros(3)

__all__ = ["ChainSplit", "split_acceleration", "split_force", "chain_split",
           "mobility_split", "forward_dynamics_mobility_split"]


def _C(Lam_i, K):
    C = _EYE3 + Lam_i @ K
    c = _cond(C)
    if not c < SOLVE_COND_LIMIT:
        raise SingularConfigurationError("1 + Lambda^-1 R U^T A of the split is singular", c)
    return C


def split_acceleration(Lam_i, b_i, A_next, d_next, T_next, s_next, Q_next, kappa_next) -> np.ndarray:
    """Acceleration of body ``i`` split from the rest of the chain at joint ``i+1`` (thesis 7.54).

    Parameters
    ----------
    Lam_i, b_i : (3, 3), (3,)
        Articulated mobility and bias acceleration of body ``i`` (7.38).
    A_next, d_next : (3, 3), (3,)
        Articulated inertia and bias force of body ``i+1`` (7.7).
    T_next, s_next : (3, k)
        Active force subspace (6.105) and joint space of joint ``i+1``.
    Q_next : (k,) torque of joint ``i+1``;  kappa_next : (3,) bias acceleration of body ``i+1``.

    Examples
    --------
    A pinned unit point mass at (1, 0) (body i) carrying a second one on a pin at
    (1, 0), at rest, with a unit upward push on body i (``b_i = [0, 0, 1]``):
    the second mass adds to the first, halving the acceleration.

    >>> from planargeo.screws.twists import inertia_matrix
    >>> A2 = inertia_matrix(1.0, [1.0, 0.0], 1e-3)
    >>> s2 = np.array([[0.0], [-1.0], [1.0]])
    >>> T2 = A2 @ s2 / (s2.T @ A2 @ s2)
    >>> Lam1 = np.diag([0.0, 0.0, 1.0])
    >>> split_acceleration(Lam1, [0, 0, 1.0], A2, np.zeros(3), T2, s2, [0.0], np.zeros(3)).round(12)
    array([0. , 0. , 0.5])
    """
    return _split_acceleration(np.asarray(Lam_i, dtype=float), np.asarray(b_i, dtype=float),
                               np.asarray(A_next, dtype=float), np.asarray(d_next, dtype=float),
                               np.asarray(T_next, dtype=float).reshape(3, -1),
                               np.asarray(s_next, dtype=float).reshape(3, -1),
                               np.asarray(Q_next, dtype=float).reshape(-1), np.asarray(kappa_next, dtype=float))


def _split_acceleration(Lam_i, b_i, A_next, d_next, T_next, s_next, Q_next, kappa_next):
    """7.54 on float arrays of the right shapes (the kernel of :func:`split_acceleration`)."""
    P = _EYE3 - T_next @ s_next.T                         # R U^T (7.8)
    K = P @ A_next
    rhs = b_i - Lam_i @ (T_next @ Q_next + P @ (A_next @ kappa_next + d_next))
    return _solve(_C(Lam_i, K), rhs, "1 + Lambda^-1 R U^T A of the split")


def split_force(Lam_i, b_i, A_next, d_next, T_next, s_next, Q_next, kappa_next) -> np.ndarray:
    """Internal force of joint ``i+1`` from the split chain (thesis 7.56).

    Same parameters as :func:`split_acceleration`.

    Examples
    --------
    The example of :func:`split_acceleration`: the pin between the masses pushes
    the second one up with half the unit push (``f = I_2 a_1`` with ``a_1 = [0, 0, 0.5]``).

    >>> from planargeo.screws.twists import inertia_matrix
    >>> A2 = inertia_matrix(1.0, [1.0, 0.0], 1e-3)
    >>> s2 = np.array([[0.0], [-1.0], [1.0]])
    >>> T2 = A2 @ s2 / (s2.T @ A2 @ s2)
    >>> f = split_force(np.diag([0.0, 0.0, 1.0]), [0, 0, 1.0], A2, np.zeros(3), T2, s2, [0.0], np.zeros(3))
    >>> f.round(12) + 0.0
    array([0. , 0.5, 0.5])
    """
    Lam_i = np.asarray(Lam_i, dtype=float)
    A_next = np.asarray(A_next, dtype=float)
    s_next = np.asarray(s_next, dtype=float).reshape(3, -1)
    T_next = np.asarray(T_next, dtype=float).reshape(3, -1)
    P = np.eye(3) - T_next @ s_next.T                     # R U^T (7.8)
    K = P @ A_next
    rhs = (T_next @ np.asarray(Q_next, dtype=float).reshape(-1)
           + P @ (A_next @ (np.asarray(b_i, dtype=float) + np.asarray(kappa_next, dtype=float))
                  + np.asarray(d_next, dtype=float)))
    return np.linalg.solve(_C(Lam_i, K).T, rhs)


@dataclass
class ChainSplit:
    """Direct solution of a chain by splitting at every joint (thesis 7.6: 7.54, 7.56, 6.110).

    Attributes
    ----------
    a : (N, 3) body accelerations (7.54; ``a_N = b_N``).
    f : (N, 3) internal joint forces: ``f[i]`` for ``i >= 1`` from 7.56
        (split at joint ``i``); ``f[0]`` from the force propagator of body 1
        (6.113b) with ``f[1]``.
    qdd : (nq,) joint accelerations (6.110).
    """

    a: np.ndarray
    f: np.ndarray
    qdd: np.ndarray


def chain_split(I, S, kappa, p, tau, parents=None, joint_points=None) -> ChainSplit:
    """Solve a chain by chain splitting on arrays (thesis 7.6 algorithm).

    Steps: articulated inertias (7.1.1), articulated mobilities (7.4.1),
    then every ``a_i`` directly by 7.54, every ``f_{i+1}`` by 7.56, and the
    joint accelerations by 6.110.  ``joint_points`` (N, 2): each joint's point, where the
    singularity rule of :data:`planargeo.mechanics.subspaces.COND_LIMIT` is measured (default the origin;
    :func:`mobility_split` passes the joint frames' origins).

    Examples
    --------
    >>> from planargeo.screws.twists import inertia_matrix
    >>> I = [inertia_matrix(1.0, [0.5, 0.0], 1 / 12), inertia_matrix(1.0, [1.5, 0.0], 1 / 12)]
    >>> S = [np.array([[0.0], [0.0], [1.0]]), np.array([[0.0], [-1.0], [1.0]])]
    >>> chain_split(I, S, np.zeros((2, 3)), np.zeros((2, 3)), [np.ones(1), np.zeros(1)]).qdd.round(9)
    array([ 1.71428571, -4.28571429])
    """

    I = np.asarray(I, dtype=float)
    N = I.shape[0]
    if parents is not None:
        _check_chain(parents, N)
    S = [np.asarray(x, dtype=float).reshape(3, -1) for x in S]
    tau = [np.asarray(x, dtype=float).reshape(-1) for x in tau]
    kappa = np.asarray(kappa, dtype=float)
    p = np.asarray(p, dtype=float)
    A, d, T = _articulated(I, S, kappa, p, tau, list(range(-1, N - 1)), joint_points)     # (7.1.1)
    Lam, b, Tm = _mobility(I, S, kappa, p, tau, joint_points)                              # (7.4.1)
    a = np.zeros((N, 3))
    f = np.zeros((N, 3))
    for i in range(N - 1):
        j = i + 1
        args = (Lam[i], b[i], A[j], d[j], T[j], S[j], tau[j], kappa[j])
        a[i] = split_acceleration(*args)                # (7.54)
        f[j] = split_force(*args)                       # (7.56)
    a[N - 1] = b[N - 1]                                 # f_{N+1} = 0 in (7.37)
    if N:   # (6.113b) with a_0 = 0; T of sᵀIs from the mobility pass (checked at the joint's point)
        f[0] = force_propagator(I[0], S[0], tau[0], p[0], f[1] if N > 1 else _ZERO3, _ZERO3, kappa[0], T=Tm[0])
    qdd = [T[i].T @ (a[i] - (a[i - 1] if i else 0.0) - kappa[i]) for i in range(N)]  # (6.110)
    qdd = np.concatenate(qdd) if qdd else np.zeros(0)
    return ChainSplit(a, f, qdd)


def mobility_split(model, q, qd=None, tau=None, f_ext=None) -> ChainSplit:
    """Chain-splitting solution of one state of an unbranched chain (thesis 7.6).

    Examples
    --------
    >>> from planargeo.mechanics.model import chain_model
    >>> r = mobility_split(chain_model(2, gravity=(0, 0)), [0.0, 0.0], [0.0, 0.0], [1.0, 0.0])
    >>> r.qdd.round(9)
    array([ 1.71428571, -4.28571429])
    """
    d, I, S, kappa, p, parents, taus = _state_arrays(model, q, qd, tau, f_ext)
    _check_chain(parents, len(S))
    return chain_split(I, S, kappa, p, taus, joint_points=d.origin)


def forward_dynamics_mobility_split(model, q, qd, tau, f_ext=None) -> np.ndarray:
    """Joint accelerations by articulated mobility + chain splitting (thesis 7.4.1, 7.54, 7.56, 6.110).

    Parameters
    ----------
    model : planargeo.mechanics.model.Model
        An unbranched chain whose first body hangs from the ground.
    q, qd, tau : array_like (..., nq)
        Leading batch dimensions are solved state by state.
    f_ext : array_like (..., N, 3), optional
        World wrenches at the origin applied to each body (besides gravity).

    Returns
    -------
    ndarray (..., nq)

    Raises
    ------
    TopologyError
        When the model is not an unbranched chain.
    SingularConfigurationError
        When a joint-space matrix is singular.

    Examples
    --------
    >>> from planargeo.mechanics.model import chain_model
    >>> forward_dynamics_mobility_split(chain_model(1), [0.0], [0.0], [0.0]).round(6)
    array([-14.715])
    """
    return _per_state(_mobility_split_qdd, model, q, qd, tau, f_ext)


def _mobility_split_qdd(model, q, qd, tau, f_ext):
    """``qdd`` of one state by 7.54 and 6.110 (the forces 7.56 of :func:`mobility_split` are not needed)."""
    from planargeo.algorithms.articulated_inertia import _articulated

    data, I, S, kappa, p, parents, taus = _state_arrays(model, q, qd, tau, f_ext, checked=True)
    _check_chain(parents, len(S))
    N = len(S)
    A, d, T = _articulated(I, S, kappa, p, taus, parents, data.origin)
    Lam, b, _ = _mobility(I, S, kappa, p, taus, data.origin)
    a = np.zeros((N, 3))
    for i in range(N - 1):
        j = i + 1
        a[i] = _split_acceleration(Lam[i], b[i], A[j], d[j], T[j], S[j], taus[j], kappa[j])   # (7.54)
    a[N - 1] = b[N - 1]                                 # f_{N+1} = 0 in (7.37)
    qdd = [T[i].T @ (a[i] - (a[i - 1] if i else 0.0) - kappa[i]) for i in range(N)]  # (6.110)
    return np.concatenate(qdd) if qdd else np.zeros(0)
