"""Chain splitting: direct body accelerations and joint forces (thesis 7.6).

Split at joint ``i+1`` into a constrained chain (mobility ``Λ_i⁻¹``, ``b_i``, 7.4.1) and a free one
(inertia ``A_{i+1}``, ``d_{i+1}``, 7.1.1): 7.54 gives ``a_i``, 7.56 ``f_{i+1}`` (through 7.55, true
only with the corrected 7.38a), ``a_N = b_N`` and ``q̈`` by 6.110.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from planargeo.errors import TopologyError
from planargeo.geometry._docs import entries
from planargeo.mechanics.subspaces import _solve
from planargeo.algorithms.articulated_inertia import (_EYE3, ArticulatedInertias, _arrays, _per_state,
                                                      _state_arrays, articulated_recursion)
from planargeo.algorithms.articulated_mobility import ArticulatedMobilities, _check_solvable, mobility_recursion
from planargeo.algorithms.projective import force_propagator, joint_accelerations

__all__ = ["ChainSplit", "split_acceleration", "split_force", "chain_split",
           "mobility_split", "forward_dynamics_mobility_split"]


#: The examples' split: body ``i`` turning about the origin, a unit point mass pinned at (1, 0).
_SPLIT = {"two_masses": """>>> from planargeo.screws.twists import inertia_matrix
>>> A2, s2 = inertia_matrix(1.0, [1.0, 0.0], 1e-3), np.array([[0.0], [-1.0], [1.0]])
>>> T2 = A2 @ s2 / (s2.T @ A2 @ s2)
>>> args = (np.diag([0.0, 0.0, 1.0]), [0, 0, 1.0], A2, np.zeros(3), T2, s2, [0.0], np.zeros(3))"""}


def _split(force, Lam_i, b_i, A_next, d_next, T_next, s_next, Q_next, kappa_next):
    """7.54 (``a_i``), or 7.56 (``force``: ``f_{i+1}``), with ``R Uᵀ = 1 - T sᵀ`` (7.8) and ``C = 1 + Λ_i⁻¹ R Uᵀ A``."""
    Lam, b, A, d, kappa = (np.asarray(x, dtype=float) for x in (Lam_i, b_i, A_next, d_next,
                                                                 kappa_next))
    T = np.asarray(T_next, dtype=float).reshape(3, -1)
    TQ = T @ np.asarray(Q_next, dtype=float).reshape(-1)
    P = _EYE3 - T @ np.asarray(s_next, dtype=float).reshape(3, -1).T
    C, what = _EYE3 + Lam @ (P @ A), "1 + Lambda^-1 R U^T A of the split"
    _check_solvable(C, what)
    if force:                                       # through C^T = 1 + R Uᵀ A Λ_i⁻¹ (7.55)
        return _solve(C.T, TQ + P @ (A @ (b + kappa) + d), what)
    return _solve(C, b - Lam @ (TQ + P @ (A @ kappa + d)), what)


@entries(_SPLIT)
def split_acceleration(Lam_i, b_i, A_next, d_next, T_next, s_next, Q_next, kappa_next) -> np.ndarray:
    """Acceleration of body ``i`` split from the rest of the chain at joint ``i+1`` (thesis 7.54).

    Parameters
    ----------
    Lam_i, b_i, A_next, d_next, T_next, s_next, Q_next, kappa_next : array_like
        ``Λ_i⁻¹``, ``b_i`` of body ``i`` (7.38); ``A``, ``d`` of body ``i+1`` (7.7); ``T`` (6.105), ``s``,
        ``Q`` of joint ``i+1``; its ``κ`` (2.19).

    Returns
    -------
    numpy.ndarray, shape (3,)
        ``a_i = C⁻¹ [b_i - Λ_i⁻¹ (T Q + R Uᵀ (A κ + d))]``, ``C = 1 + Λ_i⁻¹ R Uᵀ A``.

    Raises
    ------
    SingularConfigurationError
        When ``C = 1 + Λ_i⁻¹ R Uᵀ A`` is singular.

    Examples
    --------
    {two_masses}
    >>> split_acceleration(*args).round(12)           # a second point mass halves it
    array([0. , 0. , 0.5])
    """
    return _split(False, Lam_i, b_i, A_next, d_next, T_next, s_next, Q_next, kappa_next)


@entries(_SPLIT)
def split_force(Lam_i, b_i, A_next, d_next, T_next, s_next, Q_next, kappa_next) -> np.ndarray:
    """Internal force of joint ``i+1`` from the split chain (thesis 7.56).

    Parameters
    ----------
    Lam_i, b_i, A_next, d_next, T_next, s_next, Q_next, kappa_next : array_like
        The split at joint ``i+1``, as for :func:`split_acceleration`.

    Returns
    -------
    numpy.ndarray, shape (3,)
        ``f_{i+1} = C⁻ᵀ [T Q + R Uᵀ (A (b_i + κ) + d)]``, on body ``i+1``.

    Raises
    ------
    SingularConfigurationError
        As :func:`split_acceleration`.

    Examples
    --------
    {two_masses}
    >>> split_force(*args).round(12) + 0.0             # half the push
    array([0. , 0.5, 0.5])
    """
    return _split(True, Lam_i, b_i, A_next, d_next, T_next, s_next, Q_next, kappa_next)


@dataclass
class ChainSplit:
    """Direct solution of a chain by splitting at every joint (thesis 7.6: 7.54, 7.56, 6.110).

    Attributes
    ----------
    a : (N, 3) body accelerations (7.54; ``a_N = b_N``).
    f : (N, 3) joint forces: ``f[i]``, ``i >= 1``, from 7.56; ``f[0]`` from the force propagator (6.113b).
    qdd : (nq,) joint accelerations (6.110).
    articulated, mobilities : the recursions split at every joint (7.1.1, 7.4.1).
    """

    a: np.ndarray
    f: np.ndarray
    qdd: np.ndarray
    articulated: ArticulatedInertias
    mobilities: ArticulatedMobilities


def _check_chain(parents, N):
    if parents is not None and list(parents) != list(range(-1, N - 1)):
        raise TopologyError(
            f"parents must describe an unbranched chain [-1, 0, 1, ...] for chain splitting "
            f"(thesis 7.6), got {list(parents)}")


def chain_split(I, S, kappa, p, tau, parents=None, joint_points=None) -> ChainSplit:
    """Solve a chain by chain splitting on arrays (thesis 7.6 algorithm: 7.1.1, 7.4.1, 7.54, 7.56, 6.110).

    Parameters
    ----------
    I, S, kappa, p, tau, parents
        One state, as for :func:`planargeo.algorithms.articulated_inertia.articulated_recursion`
        (inertias in the common frame (5.58), bias terms (2.19, 3.11)); ``parents`` only ``[-1, 0, ..., N-2]``.
    joint_points : (N, 2) array, optional
        Where each joint's conditioning is measured (default the origin).

    Returns
    -------
    ChainSplit

    Raises
    ------
    TopologyError, SingularConfigurationError
        ``parents`` not an unbranched chain; a singular joint-space or split matrix.

    Examples
    --------
    >>> from planargeo.screws.twists import inertia_matrix
    >>> I = [inertia_matrix(1.0, [0.5, 0.0], 1 / 12), inertia_matrix(1.0, [1.5, 0.0], 1 / 12)]
    >>> S = [np.array([[0.0], [0.0], [1.0]]), np.array([[0.0], [-1.0], [1.0]])]
    >>> chain_split(I, S, np.zeros((2, 3)), np.zeros((2, 3)), [np.ones(1), np.zeros(1)]).qdd.round(9)
    array([ 1.71428571, -4.28571429])
    """
    N = len(S)
    _check_chain(parents, N)
    I, S, kappa, p, tau, parents = _arrays(I, S, kappa, p, tau, None)
    art = articulated_recursion(I, S, kappa, p, tau, parents, None, joint_points)      # (7.1.1)
    mob = mobility_recursion(I, S, kappa, p, tau, parents, None, joint_points)        # (7.4.1)
    T, A, d, a, f = art.T, art.A, art.d, np.zeros((N, 3)), np.zeros((N, 3))
    for i in range(N - 1):
        j = i + 1
        args = (mob.Lambda_inv[i], mob.b[i], A[j], d[j], T[j], S[j], tau[j], kappa[j])
        a[i] = split_acceleration(*args)                # (7.54)
        f[j] = split_force(*args)                       # (7.56)
    if N:   # a_N = b_N (f_{N+1} = 0 in 7.37); f_1 by (6.113b) with a_0 = 0, T of sᵀIs from the mobility pass
        a[N - 1] = mob.b[N - 1]
        f[0] = force_propagator(I[0], S[0], tau[0], p[0], f[1] if N > 1 else np.zeros(3), np.zeros(3), kappa[0],
                                T=mob.T[0])
    return ChainSplit(a, f, joint_accelerations(T, a, kappa, parents), art, mob)       # (6.110)


def mobility_split(model, q, qd=None, tau=None, f_ext=None) -> ChainSplit:
    """Chain-splitting solution of one state of an unbranched chain (thesis 7.6).

    Parameters
    ----------
    model, q, qd, tau, f_ext : Model, array_like
        An unbranched chain hanging from the ground and one state, as for
        :func:`planargeo.algorithms.articulated_inertia.articulated_inertia`.

    Returns
    -------
    ChainSplit
        Body accelerations, joint forces (7.56) and joint accelerations.

    Raises
    ------
    TopologyError, SingularConfigurationError
        As :func:`chain_split`.

    Examples
    --------
    >>> from planargeo.mechanics.model import chain_model
    >>> mobility_split(chain_model(2, gravity=(0, 0)), [0.0] * 2, [0.0] * 2, [1, 0]).qdd.round(9)
    array([ 1.71428571, -4.28571429])
    """
    return _chain_split(model, q, qd, tau, f_ext)


def _chain_split(model, q, qd, tau, f_ext, checked=False):
    _, I, S, kappa, p, taus, parents, _, joint_points = _state_arrays(model, q, qd, tau, f_ext, checked)
    return chain_split(I, S, kappa, p, taus, parents, joint_points)


def forward_dynamics_mobility_split(model, q, qd, tau, f_ext=None) -> np.ndarray:
    """Joint accelerations by articulated mobility + chain splitting (thesis 7.4.1, 7.54, 7.56, 6.110).

    Parameters
    ----------
    model, q, qd, tau, f_ext : Model, array_like
        An unbranched chain and its states, as for :func:`planargeo.algorithms.aba.forward_dynamics`.

    Returns
    -------
    numpy.ndarray, shape (..., nq)

    Raises
    ------
    ShapeError, NonFiniteError, InputError, TopologyError, SingularConfigurationError
        Bad arguments, as for :func:`planargeo.algorithms.aba.forward_dynamics`; else as :func:`chain_split`.

    Examples
    --------
    >>> from planargeo.mechanics.model import chain_model
    >>> forward_dynamics_mobility_split(chain_model(1), [0.0], [0.0], [0.0]).round(6)
    array([-14.715])
    """
    _check_chain(model.parents, model.N)
    return _per_state(lambda *state: _chain_split(*state, checked=True).qdd, model, q, qd, tau, f_ext)
