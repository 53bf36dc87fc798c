"""Articulated mobility algorithm for a constrained chain (thesis 7.4, 7.4.1).

The articulated mobility ``Lambda_i^-1`` and bias acceleration ``b_i`` relate
the force of joint ``i+1`` to the acceleration of body ``i`` with the chain
from the ground up to ``i`` attached (7.28)::

    a_i = -Lambda_i^-1 f_{i+1} + b_i

From the base to the tip, with the body-inertia subspaces ``T_i = I_i s_i
(s_i^T I_i s_i)^-1``, ``U_i = I_i^-1 R_i (R_i^T I_i^-1 R_i)^-1`` (6.36, 6.37)::

    eta_i      = s_i T_i^T I_i^-1 (T_i Q_i - p_i)                                (7.35)
    Lambda_1^-1 = s_1 T_1^T I_1^-1,  b_1 = eta_1 + U_1 R_1^T kappa_1              (7.31)
    M_i        = 1 + U_i R_i^T Lambda_{i-1}^-1 I_i
    Lambda_i^-1 = M_i^-1 (s_i T_i^T I_i^-1 + U_i R_i^T Lambda_{i-1}^-1)          (7.38a, corrected)
    b_i        = M_i^-1 (eta_i - U_i R_i^T (Lambda_{i-1}^-1 p_i - b_{i-1} - kappa_i))  (7.38b)

The thesis prints a minus sign before ``U_i R_i^T Lambda_{i-1}^-1`` in 7.36
and 7.38a, and its listing 7.4.1 drops the applied loads ``g_i`` from
``p_i``; both are corrected here (``docs/errata.md``).  The
algorithm needs an unbranched chain whose first body hangs from the ground.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from planargeo.errors import SingularConfigurationError, TopologyError
from planargeo.mechanics.subspaces import _checked_gram, _effective_mobility, _percussion_space, _reactive_from_T, _solve
from planargeo.algorithms.projective import _state_arrays, reaction_space

__all__ = ["ArticulatedMobilities", "mobility_recursion", "articulated_mobility"]


@dataclass
class ArticulatedMobilities:
    """Result of the articulated mobility algorithm (per body ``i``; thesis 7.4.1, 7.31, 7.38).

    Attributes
    ----------
    Lambda_inv : (N, 3, 3) articulated mobilities (7.31a, 7.38a); symmetric, positive semi-definite.
    b : (N, 3) articulated bias accelerations (7.31b, 7.38b).
    T, U, R : lists of body-inertia subspaces (6.36, 6.37) and reaction spaces (the basis of
        :func:`planargeo.mechanics.joints.reaction_space_of`: forces through the joint, couples; 7.16, 5.63).
    """

    Lambda_inv: np.ndarray
    b: np.ndarray
    T: list
    U: list
    R: list


def _check_chain(parents, N):
    if list(parents) != list(range(-1, N - 1)):
        raise TopologyError(
            f"parents must describe an unbranched chain [-1, 0, 1, ...] for the articulated "
            f"mobility (thesis 7.4), got {list(parents)}")


def mobility_recursion(I, S, kappa, p, tau, parents=None, points=None, joint_points=None) -> ArticulatedMobilities:
    """Articulated mobilities and bias accelerations on arrays (thesis 7.4.1).

    Parameters
    ----------
    I : (N, 3, 3) body inertias at the origin (point masses allowed while every ``s_i^T I_i s_i`` is invertible).
    S : list of N (3, k_i) joint spaces.
    kappa, p : (N, 3) bias accelerations (2.19) and bias forces (3.11, gravity and loads included).
    tau : list of N (k_i,) joint torques ``Q_i``.
    parents : sequence of N ints; must be the chain ``[-1, 0, ..., N-2]`` (the default).
    points : (N, 2), optional
        A point of each joint, for the reaction bases ``R`` of prismatic joints
        (:func:`planargeo.mechanics.joints.reaction_space_of`); default the origin.
    joint_points : (N, 2), optional
        Each joint's point (pivot; placement point of a prismatic joint: the joint
        frame's origin), where the singularity rule of :data:`planargeo.mechanics.subspaces.COND_LIMIT`
        is measured; default the origin.  The model-level functions pass the joint frames' origins.

    Returns
    -------
    ArticulatedMobilities

    Raises
    ------
    TopologyError
        When ``parents`` is not an unbranched chain.
    SingularConfigurationError
        When ``s_i^T I_i s_i`` or ``1 + U_i R_i^T Lambda_{i-1}^-1 I_i`` is singular.

    Examples
    --------
    Thesis 7.42 with ``m = L = 1``, ``rho = 1/2``: ``4 / (m (L^2 + 4 rho^2)) = 2``.

    >>> from planargeo.screws.twists import inertia_matrix
    >>> r = mobility_recursion([inertia_matrix(1.0, [0.5, 0.0], 0.25)], [np.array([[0.0], [0.0], [1.0]])],
    ...                        np.zeros((1, 3)), np.zeros((1, 3)), [np.zeros(1)])
    >>> r.Lambda_inv[0].round(12) + 0.0
    array([[0., 0., 0.],
           [0., 0., 0.],
           [0., 0., 2.]])
    """
    I = np.asarray(I, dtype=float)
    N = I.shape[0]
    if parents is not None:
        _check_chain(parents, N)
    S = [np.asarray(x, dtype=float).reshape(3, -1) for x in S]
    tau = [np.asarray(x, dtype=float).reshape(-1) for x in tau]
    kappa = np.asarray(kappa, dtype=float)
    p = np.asarray(p, dtype=float)
    Lam, b, T = _mobility(I, S, kappa, p, tau, joint_points)
    R = [reaction_space(S[i], (0.0, 0.0) if points is None else points[i]) for i in range(N)]
    U = [_reactive_from_T(R[i], S[i], T[i]) for i in range(N)]                     # (6.37), inverse-free
    return ArticulatedMobilities(Lam, b, T, U, R)


_EYE3 = np.eye(3)
_EYE3.setflags(write=False)

#: Backstop for the method's own 3×3 solves (``1 + U Rᵀ Λ⁻¹ I`` of 7.38, ``1 + Λ⁻¹ R Uᵀ A`` of 7.54):
#: raise only when numerically singular (``cond ≥ 1/ε``).  Whether a configuration is singular is
#: decided by the joints' rule (:data:`planargeo.mechanics.subspaces.COND_LIMIT`, checked on every ``sᵀIs``)
#: as for every other method; these matrices inherit their conditioning from the joints' (measured
#: up to ~30 × the joint's ``cond`` near the limit: a point-mass tip), so a tighter limit here
#: would refuse states the other methods accept.
SOLVE_COND_LIMIT = 1e16


def _cond(M) -> float:
    """Cheap condition number ``‖M‖ ‖M⁻¹‖`` (Frobenius norms) of a small square matrix; ``inf`` if singular.

    Between ``cond₂`` and ``k cond₂`` for a ``k×k`` matrix; no singular value decomposition.
    """
    if M.shape == (3, 3):                       # adjugate and determinant on Python floats
        (a, b, c), (d, e, f), (g, h, k) = M.tolist()
        adj = (e * k - f * h, c * h - b * k, b * f - c * e,
               f * g - d * k, a * k - c * g, c * d - a * f,
               d * h - e * g, b * g - a * h, a * e - b * d)
        det = a * adj[0] + b * adj[3] + c * adj[6]
        if det == 0.0:
            return math.inf
        n2 = a * a + b * b + c * c + d * d + e * e + f * f + g * g + h * h + k * k
        m0, m1, m2, m3, m4, m5, m6, m7, m8 = adj
        a2 = m0 * m0 + m1 * m1 + m2 * m2 + m3 * m3 + m4 * m4 + m5 * m5 + m6 * m6 + m7 * m7 + m8 * m8
        cond = math.sqrt(n2 * a2) / abs(det)
        return cond if cond == cond else math.inf
    try:
        Mi = np.linalg.inv(M)
    except np.linalg.LinAlgError:
        return math.inf
    c = math.sqrt(float(np.vdot(M, M)) * float(np.vdot(Mi, Mi)))
    return c if c == c else math.inf


def _mobility(I, S, kappa, p, tau, jpoints=None):
    """The recursion of :func:`mobility_recursion` on checked arrays: ``(Lambda_inv, b, T)`` (7.31, 7.35, 7.38).

    ``U_i R_i^T = 1 - s_i T_i^T`` (the twist projectors of 6.75), so no reaction basis is built.
    ``jpoints`` (N, 2): the joints' points, where the singularity rule is measured (default the origin).
    """
    N = I.shape[0]
    Lam = np.zeros((N, 3, 3))
    b = np.zeros((N, 3))
    T = [None] * N
    eye = _EYE3
    for i in range(N):
        Si, Ii = S[i], I[i]
        what = f"sᵀIs of joint {i}"
        gram = _checked_gram(Ii, Si, what, None if jpoints is None else jpoints[i])   # (I s, s^T I s), checked once
        T[i] = Ti = _percussion_space(Ii, Si, what, gram)                  # (6.36)
        G = _effective_mobility(Ii, Si, what, gram)     # s T^T I^-1 = s (s^T I s)^-1 s^T (6.93)
        eta = G @ (Ti @ tau[i] - p[i])                  # (7.35)
        P = eye - Si @ Ti.T                             # U R^T (6.75)
        if i == 0:                                      # (7.31a, 7.31b): a_0 = 0
            Lam[i] = G
            b[i] = eta + P @ kappa[i]
        else:
            M = eye + P @ Lam[i - 1] @ Ii
            c = _cond(M)
            if not c < SOLVE_COND_LIMIT:
                raise SingularConfigurationError(f"1 + U R^T Lambda^-1 I of body {i} is singular", c)
            Lam[i] = _solve(M, G + P @ Lam[i - 1], f"1 + U R^T Lambda^-1 I of body {i}")  # (7.38a)
            b[i] = _solve(M, eta - P @ (Lam[i - 1] @ p[i] - b[i - 1] - kappa[i]),
                          f"1 + U R^T Lambda^-1 I of body {i}")  # (7.38b)
        Lam[i] = 0.5 * (Lam[i] + Lam[i].T)              # symmetric by construction; remove round-off
    return Lam, b, T


def articulated_mobility(model, q, qd=None, tau=None, f_ext=None) -> ArticulatedMobilities:
    """Articulated mobilities ``Lambda_i^-1`` and bias accelerations ``b_i`` (thesis 7.4.1).

    Parameters
    ----------
    model : planargeo.mechanics.model.Model
        An unbranched chain (``model.is_chain``).
    q, qd, tau : array_like (nq,)
        State and joint torques (zero if omitted).
    f_ext : array_like (N, 3), optional
        World wrenches at the origin applied to each body (besides gravity).

    Examples
    --------
    The tip of a double pendulum of unit links, at rest without gravity:
    ``a_2 = -Lambda_2^-1 f_3 + b_2`` with ``b_2 = 0``.

    >>> from planargeo.mechanics.model import chain_model
    >>> r = articulated_mobility(chain_model(2, gravity=(0, 0)), [0.0, 0.0])
    >>> float(np.abs(r.b).max())
    0.0
    >>> bool(np.allclose(r.Lambda_inv[1], r.Lambda_inv[1].T))
    True
    """
    d, I, S, kappa, p, parents, taus = _state_arrays(model, q, qd, tau, f_ext)
    _check_chain(parents, len(S))
    return mobility_recursion(I, S, kappa, p, taus, points=d.pose[:, :2], joint_points=d.origin)
