"""Articulated inertia algorithm for a free-floating chain (thesis 7.1, 7.1.1).

The articulated inertia ``A_i`` and bias force ``d_i`` relate the internal
force of joint ``i`` to the acceleration of body ``i`` with everything beyond
it attached (7.1)::

    f_i = A_i a_i + d_i

From the tip to the base (7.2, 7.7a, 7.7b, 7.8)::

    A_N = I_N,  d_N = p_N
    A_i = I_i + R_{i+1} U_{i+1}^T A_{i+1}
    d_i = p_i + T_{i+1} Q_{i+1} + R_{i+1} U_{i+1}^T (A_{i+1} kappa_{i+1} + d_{i+1})
    R_i U_i^T = 1 - T_i s_i^T

with ``p_i = -(v_i×)^T I_i v_i - g_i`` (3.11).  The algorithm listing of 7.1.1
prints ``+ g_i`` in ``d_N`` and ``d_i``; the applied loads enter with a minus
sign (3.11, 3.34), see ``docs/errata.md``.  On a tree each body
sums the projected contributions of all its children.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from planargeo.mechanics.subspaces import _percussion_space
from planargeo.algorithms.projective import _state_arrays, reaction_space, reactive_subspace

__all__ = ["ArticulatedInertias", "articulated_recursion", "articulated_inertia"]


@dataclass
class ArticulatedInertias:
    """Result of the articulated inertia algorithm (per body ``i``; thesis 7.1.1, 7.7a-7.7b).

    Attributes
    ----------
    A : (N, 3, 3) articulated inertias (7.7a).
    d : (N, 3) articulated bias forces (7.7b).
    T : list of (3, k_i) active force subspaces ``A_i s_i (s_i^T A_i s_i)^-1`` (6.105).
    R : list of (3, 3-k_i) reaction spaces, the basis of :func:`planargeo.mechanics.joints.reaction_space_of`
        (forces through the joint, couples; thesis 7.16, 5.63).
    S : list of (3, k_i) joint spaces.
    """

    A: np.ndarray
    d: np.ndarray
    T: list
    R: list
    S: list

    def U(self, i: int) -> np.ndarray:
        """Reactive acceleration subspace ``U_i = A_i^-1 R_i (R_i^T A_i^-1 R_i)^-1`` (6.99)."""
        return reactive_subspace(self.A[i], self.R[i], s=self.S[i], T=self.T[i])


def articulated_recursion(I, S, kappa, p, tau, parents=None, points=None, joint_points=None) -> ArticulatedInertias:
    """Articulated inertias and bias forces on arrays (thesis 7.1.1: 7.2, 7.7a, 7.7b, 7.8).

    Parameters
    ----------
    I : (N, 3, 3) body inertias at the origin.
    S : list of N (3, k_i) joint spaces.
    kappa, p : (N, 3) bias accelerations (2.19) and bias forces (3.11, gravity and loads included).
    tau : list of N (k_i,) joint torques ``Q_i``.
    parents : sequence of N ints, default a chain.
    points : (N, 2), optional
        A point of each joint, for the reaction bases ``R`` of prismatic joints
        (:func:`planargeo.mechanics.joints.reaction_space_of`); default the origin.
    joint_points : (N, 2), optional
        Each joint's point (pivot; placement point of a prismatic joint: the joint
        frame's origin), where the singularity rule of :data:`planargeo.mechanics.subspaces.COND_LIMIT`
        is measured; default the origin.  The model-level functions pass the joint frames' origins.

    Returns
    -------
    ArticulatedInertias

    Raises
    ------
    SingularConfigurationError
        When some ``s_i^T A_i s_i`` is singular (e.g. a massless tip body).

    Examples
    --------
    Thesis 7.2 with ``m = L = 1``, ``rho = 1/2``, ``phi = 0``: the two bodies in
    line have ``m_x = 2 m`` (7.20).

    >>> from planargeo.screws.twists import inertia_matrix
    >>> I = [inertia_matrix(1.0, [0.5, 0.0], 0.25), inertia_matrix(1.0, [1.5, 0.0], 0.25)]
    >>> S = [np.array([[0.0], [0.0], [1.0]]), np.array([[0.0], [-1.0], [1.0]])]
    >>> r = articulated_recursion(I, S, np.zeros((2, 3)), np.zeros((2, 3)), [np.zeros(1)] * 2)
    >>> r.A[0].round(12) + 0.0
    array([[2. , 0. , 0. ],
           [0. , 1.5, 1. ],
           [0. , 1. , 1. ]])
    """
    I = np.asarray(I, dtype=float)
    N = I.shape[0]
    parents = list(range(-1, N - 1)) if parents is None else [int(x) for x in parents]
    S = [np.asarray(x, dtype=float).reshape(3, -1) for x in S]
    tau = [np.asarray(x, dtype=float).reshape(-1) for x in tau]
    A, d, T = _articulated(I, S, np.asarray(kappa, dtype=float), p, tau, parents, joint_points)
    R = [reaction_space(S[i], (0.0, 0.0) if points is None else points[i]) for i in range(N)]
    return ArticulatedInertias(A, d, T, R, S)


def _articulated(I, S, kappa, p, tau, parents, jpoints=None):
    """The recursion of :func:`articulated_recursion` on checked arrays: ``(A, d, T)`` (7.2, 7.7a, 7.7b, 7.8).

    ``I`` (N, 3, 3), ``S`` / ``tau`` lists of (3, k_i) / (k_i,) float arrays,
    ``kappa`` (N, 3), ``parents`` a list of ints.  The reaction bases are not
    needed (``R U^T = 1 - T s^T``, 7.8) and not built.  ``jpoints`` (N, 2): the joints'
    points, where the singularity rule is measured (default the origin).
    """
    N = I.shape[0]
    A = I.copy()                                   # (7.2): A_N = I_N, children added below
    d = np.asarray(p, dtype=float).copy()          # d_N = p_N
    T = [None] * N
    eye = np.eye(3)
    for i in reversed(range(N)):
        Ai = A[i] = 0.5 * (A[i] + A[i].T)          # symmetric by construction; remove round-off
        Si = S[i]
        T[i] = Ti = _percussion_space(Ai, Si, f"sᵀAs of joint {i}",   # (6.105)
                                      point=None if jpoints is None else jpoints[i])
        j = parents[i]
        if j < 0:
            continue
        P = eye - Ti @ Si.T                        # R_i U_i^T (7.8)
        A[j] += P @ Ai                             # (7.7a)
        d[j] += Ti @ tau[i] + P @ (Ai @ kappa[i] + d[i])   # (7.7b)
    return A, d, T


def articulated_inertia(model, q, qd=None, tau=None, f_ext=None) -> ArticulatedInertias:
    """Articulated inertias ``A_i`` and bias forces ``d_i`` of every body (thesis 7.1.1).

    Parameters
    ----------
    model : planargeo.mechanics.model.Model
    q, qd, tau : array_like (nq,)
        State and joint torques (zero if omitted).
    f_ext : array_like (N, 3), optional
        World wrenches at the origin applied to each body (besides gravity).

    Returns
    -------
    ArticulatedInertias

    Examples
    --------
    Two unit slender links in line on pins: the first body feels twice the
    mass along the chain.

    >>> from planargeo.mechanics.model import chain_model
    >>> float(articulated_inertia(chain_model(2), [0.0, 0.0]).A[0][0, 0])
    2.0
    """
    d, I, S, kappa, p, parents, taus = _state_arrays(model, q, qd, tau, f_ext)
    return articulated_recursion(I, S, kappa, p, taus, parents, d.pose[:, :2], d.origin)
