"""Articulated mobility algorithm for a constrained chain or tree (thesis 7.4, 7.4.1).

``a_i = -Λ_i⁻¹ f_{i+1} + b_i`` (7.28), base to tips by 7.31, 7.35, 7.38 (the printed sign of
7.36/7.38a and the loads dropped from ``p_i`` corrected; on a tree the siblings' articulated
inertias load the parent first, 9.45: ``docs/errata.md``).  :func:`mobility_recursion` is the one copy.
"""
from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from planargeo.errors import SingularConfigurationError
from planargeo.mechanics.subspaces import _checked_gram, _effective_mobility, _solve, _T
from planargeo.algorithms.articulated_inertia import (_EYE3, ArticulatedInertias, _arrays, _Reactions,
                                                      _state_arrays, articulated_recursion)

__all__ = ["ArticulatedMobilities", "mobility_recursion", "articulated_mobility", "SOLVE_COND_LIMIT"]


@dataclass(eq=False)
class ArticulatedMobilities(_Reactions):
    """Result of the articulated mobility algorithm (per body ``i``; thesis 7.4.1, 7.31, 7.38).

    Attributes
    ----------
    Lambda_inv, b : (N, 3, 3), (N, 3) articulated mobilities (7.31a, 7.38a) and bias accelerations (7.31b, 7.38b).
    S, T : lists of joint spaces and body-inertia percussion spaces ``I s (sᵀIs)⁻¹`` (6.36).
    points : (N, 2) or None, the points of the reaction bases of prismatic joints.
    R, U : lists, built on first access: reaction spaces (7.16, 5.63) and body-inertia ``U_i`` (6.37).
    """

    Lambda_inv: np.ndarray
    b: np.ndarray
    S: list
    T: list
    points: np.ndarray | None = None


#: Backstop for the method's own 3×3 solves (7.38, 9.45, 7.54): singular only at ``cond ≥ 1/ε``, as
#: they inherit the joints' conditioning (up to ~30×), which the joints' rule already decides.
SOLVE_COND_LIMIT = 1e16


def _cond(M) -> float:
    """Cheap ``‖M‖_F ‖M⁻¹‖_F`` of a 3×3 matrix (cond₂ to 3 cond₂) by its adjugate; ``inf`` if singular."""
    (a, b, c), (d, e, f), (g, h, k) = M.tolist()     # on Python floats
    adj = (e * k - f * h, c * h - b * k, b * f - c * e,
           f * g - d * k, a * k - c * g, c * d - a * f,
           d * h - e * g, b * g - a * h, a * e - b * d)
    det = a * adj[0] + b * adj[3] + c * adj[6]
    if det == 0.0:
        return math.inf
    n2, a2 = sum(x * x for x in (a, b, c, d, e, f, g, h, k)), sum(x * x for x in adj)
    cond = math.sqrt(n2 * a2) / abs(det)
    return cond if cond == cond else math.inf


def _check_solvable(M, what: str) -> None:
    """Raise SingularConfigurationError (``.cond``) for the method's own 3×3 matrices past :data:`SOLVE_COND_LIMIT`."""
    c = _cond(M)
    if not c < SOLVE_COND_LIMIT:
        raise SingularConfigurationError(f"{what} is singular", c)


def _checked_solve(M, B, what: str):
    """``M⁻¹ B`` after :func:`_check_solvable`."""
    _check_solvable(M, what)
    return _solve(M, B, what)


def _siblings_loaded(art: ArticulatedInertias, tau, kappa, children, i, j, Lam_j, b_j):
    """The parent's ``(Λ_j⁻¹, b_j)`` with ``i``'s siblings' articulated inertias attached (thesis 9.45, corrected)."""
    sib = [k for k in children[j] if k != i]
    if not sib:
        return Lam_j, b_j
    E = np.zeros((3, 3))
    e = np.zeros(3)
    for k in sib:
        E += art.P[k] @ art.A[k]                                               # R_k U_k^T A_k (7.7a)
        e += art.T[k] @ tau[k] + art.P[k] @ (art.A[k] @ kappa[k] + art.d[k])   # (7.7b)
    X = _EYE3 + Lam_j @ E
    Mb = _checked_solve(X, np.column_stack([Lam_j, b_j - Lam_j @ e]), f"1 + Lambda^-1 E of body {j}")
    return Mb[:, :3], Mb[:, 3]


def mobility_recursion(I, S, kappa, p, tau, parents=None, points=None, joint_points=None, *,
                       articulated: ArticulatedInertias | None = None) -> ArticulatedMobilities:
    """Articulated mobilities and bias accelerations on arrays, base to tips (thesis 7.4.1: 7.31, 7.35, 7.38).

    Parameters
    ----------
    I, S, kappa, p, tau, parents, points, joint_points
        One state, as for :func:`planargeo.algorithms.articulated_inertia.articulated_recursion`.
    articulated : ArticulatedInertias, optional
        ``articulated_recursion`` of the same state, for the siblings of a tree (computed if needed).

    Returns
    -------
    ArticulatedMobilities

    Raises
    ------
    SingularConfigurationError
        A singular ``s_i^T I_i s_i`` (the joint rule) or ``1 + U_i R_i^T Λ_{i-1}⁻¹ I_i`` (:data:`SOLVE_COND_LIMIT`).

    Examples
    --------
    >>> from planargeo.screws.twists import inertia_matrix
    >>> r = mobility_recursion([inertia_matrix(1.0, [0.5, 0.0], 0.25)], [np.array([[0.0], [0.0], [1.0]])],
    ...                        np.zeros((1, 3)), np.zeros((1, 3)), [np.zeros(1)])
    >>> float(r.Lambda_inv[0][2, 2])                  # 4 / (m (L² + 4 ρ²)), thesis 7.42
    2.0
    """
    I, S, kappa, p, tau, parents = _arrays(I, S, kappa, p, tau, parents)
    N = I.shape[0]
    children = [[] for _ in range(N)]
    for i, j in enumerate(parents):
        if j >= 0:
            children[j].append(i)
    if articulated is None and any(len(c) > 1 for c in children):
        articulated = articulated_recursion(I, S, kappa, p, tau, parents, points, joint_points)
    Lam, b, T = np.zeros((N, 3, 3)), np.zeros((N, 3)), [None] * N
    for i in range(N):
        Si, Ii = S[i], I[i]
        gram = _checked_gram(Ii, Si, f"sᵀIs of joint {i + 1}",
                             None if joint_points is None else joint_points[i]) if Si.shape[1] else None
        T[i] = Ti = _T(Ii, Si, gram=gram)                   # (6.36)
        G = _effective_mobility(Ii, Si, gram=gram)          # s T^T I^-1 = s (s^T I s)^-1 s^T (6.93)
        eta = G @ (Ti @ tau[i] - p[i])                      # (7.35)
        P = _EYE3 - Si @ Ti.T                               # U R^T (6.75)
        j = parents[i]
        if j < 0:                                           # (7.31a, 7.31b): a_0 = 0
            Lam[i], b[i] = G, eta + P @ kappa[i]
        else:
            M, beta = _siblings_loaded(articulated, tau, kappa, children, i, j, Lam[j], b[j])
            X = _EYE3 + P @ M @ Ii
            Lb = _checked_solve(X, np.column_stack([G + P @ M, eta - P @ (M @ p[i] - beta - kappa[i])]),
                                f"1 + U R^T Lambda^-1 I of body {i}")
            Lam[i], b[i] = Lb[:, :3], Lb[:, 3]              # (7.38a, corrected; 7.38b)
        Lam[i] = 0.5 * (Lam[i] + Lam[i].T)                  # symmetric by construction; remove round-off
    return ArticulatedMobilities(Lam, b, S, T, None if points is None else np.asarray(points, float))


def articulated_mobility(model, q, qd=None, tau=None, f_ext=None) -> ArticulatedMobilities:
    """Articulated mobilities ``Lambda_i^-1`` and bias accelerations ``b_i`` (thesis 7.4.1, 7.38, 7.41; trees 9.45).

    Parameters
    ----------
    model, q, qd, tau, f_ext : Model, array_like
        A chain or tree hanging from the ground and one state, as for
        :func:`planargeo.algorithms.articulated_inertia.articulated_inertia`.

    Returns
    -------
    ArticulatedMobilities

    Examples
    --------
    >>> from planargeo.mechanics.model import chain_model
    >>> float(np.abs(articulated_mobility(chain_model(2, gravity=(0, 0)), [0.0, 0.0]).b).max())
    0.0
    """
    return mobility_recursion(*_state_arrays(model, q, qd, tau, f_ext)[1:])
