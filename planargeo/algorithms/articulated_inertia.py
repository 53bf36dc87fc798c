"""Articulated inertia algorithm for a free-floating chain or tree (thesis 7.1, 7.1.1).

``f_i = A_i a_i + d_i`` (7.1), tips to base by 7.7a, 7.7b (the listing's ``+ g_i`` is a minus,
``docs/errata.md``).  :func:`articulated_recursion` is the package's one copy of it; the module
also holds the model glue the chapter 6-9 algorithms share.
"""
from __future__ import annotations

import functools
from dataclasses import dataclass

import numpy as np

from planargeo.errors import COND_LIMIT, InputError, ShapeError
from planargeo.mechanics.joints import R_of
from planargeo.mechanics.kinematics import _kinematics_scalar, check_state
from planargeo.mechanics.subspaces import _gram, _T, _U, singular_joint_error

__all__ = ["ArticulatedInertias", "articulated_recursion", "articulated_inertia", "truncation_error"]

_EYE3 = np.eye(3)
_EYE3.setflags(write=False)


class _Reactions:
    """The reaction bases ``R_i`` and spaces ``U_i`` of a recursion's result, built on first access."""

    @functools.cached_property
    def R(self) -> list:
        """Reaction spaces ``R_i`` (forces through the joint, couples; thesis 7.16, 5.63)."""
        pts = np.zeros((len(self.S), 2)) if self.points is None else self.points
        return [R_of(s, pt) for s, pt in zip(self.S, pts)]

    @functools.cached_property
    def U(self) -> list:
        """Reactive acceleration spaces ``U_i = A_i⁻¹ R_i (R_iᵀ A_i⁻¹ R_i)⁻¹ = (1 - s_i T_iᵀ) R_i (R_iᵀR_i)⁻¹`` (6.99, 6.75)."""
        return [_U(None, R, s, T) for R, s, T in zip(self.R, self.S, self.T)]


@dataclass(eq=False)
class ArticulatedInertias(_Reactions):
    """Result of the articulated inertia algorithm (per body ``i``; thesis 7.1.1, 7.7a-7.8).

    Attributes
    ----------
    A, d : (N, 3, 3), (N, 3) articulated inertias (7.7a) and bias forces (7.7b).
    S, T : lists of (3, k_i) joint spaces and percussion spaces ``A s (sᵀAs)⁻¹`` (6.105).
    P : list of (3, 3) projectors ``R_i U_i^T = 1 - T_i s_i^T`` (7.8).
    gram, cond : ``(A s, sᵀAs)`` (None for a fixed joint) and the joints' condition numbers (1 when fixed).
    points : (N, 2) or None, the points of the reaction bases of prismatic joints.
    steps : int or None, the truncation of the recursion (10.2.2; None: full).
    R, U : lists, built on first access: reaction spaces and reactive acceleration spaces (6.99).
    """

    A: np.ndarray
    d: np.ndarray
    S: list
    T: list
    P: list
    gram: list
    cond: np.ndarray
    points: np.ndarray | None = None
    steps: int | None = None


def _arrays(I, S, kappa, p, tau, parents):
    """The arguments of a recursion on arrays as float arrays and lists (``parents`` default: a chain)."""
    I = np.asarray(I, dtype=float)
    S = [np.asarray(x, dtype=float).reshape(3, -1) for x in S]
    tau = [np.asarray(x, dtype=float).reshape(-1) for x in tau]
    parents = list(range(-1, I.shape[0] - 1)) if parents is None else [int(x) for x in parents]
    return I, S, np.asarray(kappa, dtype=float), np.asarray(p, dtype=float), tau, parents


def articulated_recursion(I, S, kappa, p, tau, parents=None, points=None, joint_points=None, *,
                          check: bool = True, steps: int | None = None) -> ArticulatedInertias:
    """Articulated inertias and bias forces on arrays, tips to base (thesis 7.1.1: 7.2, 7.7a, 7.7b, 7.8).

    Parameters
    ----------
    I, S : (N, 3, 3) body inertias at the origin, list of N (3, k_i) joint spaces.
    kappa, p : (N, 3) bias accelerations (2.19) and bias forces (3.11, gravity and loads included).
    tau : list of N (k_i,) joint torques ``Q_i``.
    parents : sequence of N ints (``-1`` the ground, parents before children), default a chain.
    points, joint_points : (N, 2), optional
        Points for the reaction bases of prismatic joints, and where the rule of
        :data:`planargeo.errors.COND_LIMIT` is measured; default the origin.
    check : bool
        Raise for a singular joint (default); ``False`` treats an exactly singular one as locked.
    steps : int, optional
        Keep only the bodies at most ``steps`` joints outboard (10.2.2), by Jacobi sweeps; None: all.

    Returns
    -------
    ArticulatedInertias

    Raises
    ------
    SingularConfigurationError, InputError
        A singular joint (``.cond``; the message names it), or a bad ``steps``.

    Examples
    --------
    >>> from planargeo.screws.twists import inertia_matrix
    >>> I = [inertia_matrix(1.0, [0.5, 0.0], 0.25), inertia_matrix(1.0, [1.5, 0.0], 0.25)]
    >>> S = [np.array([[0.0], [0.0], [1.0]]), np.array([[0.0], [-1.0], [1.0]])]
    >>> r = articulated_recursion(I, S, np.zeros((2, 3)), np.zeros((2, 3)), [np.zeros(1)] * 2)
    >>> float(r.A[0][0, 0])
    2.0
    """
    I, S, kappa, p, tau, parents = _arrays(I, S, kappa, p, tau, parents)
    A, d, N = I.copy(), p.copy(), I.shape[0]       # (7.2): A_N = I_N, d_N = p_N, children added below
    if steps is not None:
        if isinstance(steps, (bool, np.bool_)) or not isinstance(steps, (int, np.integer)) or steps < 0:
            raise InputError(f"steps must be None or a non-negative integer, got {steps!r}")
        steps = int(steps)
        if steps < _depth(parents):
            return _truncated(A, d, S, kappa, tau, parents, points, joint_points, check, steps)
    T, P, gram = [None] * N, [None] * N, [None] * N
    cond = np.ones(N)
    for i in reversed(range(N)):
        Ai = A[i] = 0.5 * (A[i] + A[i].T)          # symmetric by construction; remove round-off
        Si = S[i]
        if Si.shape[1]:
            As, M, cond[i] = _gram(Ai, Si, None if joint_points is None else joint_points[i])
            if check and not cond[i] <= COND_LIMIT:
                raise singular_joint_error(i, cond[i])
            gram[i] = (As, M)
        locked = not np.isfinite(cond[i])          # only without check: sᵀAs exactly singular
        T[i] = Ti = np.zeros((3, Si.shape[1])) if locked else _T(Ai, Si, gram=gram[i])   # (6.105)
        P[i] = Pi = _EYE3 - Ti @ Si.T              # R_i U_i^T (7.8)
        j = parents[i]
        if j >= 0:
            A[j] += Pi @ Ai                        # (7.7a)
            d[j] += Ti @ tau[i] + Pi @ (Ai @ kappa[i] + d[i])   # (7.7b)
    return ArticulatedInertias(A, d, S, T, P, gram, cond, None if points is None else np.asarray(points, float),
                               steps)


def _depth(parents) -> int:
    """Largest number of joints between a body and its deepest descendant."""
    level = [0] * len(parents)
    for i in reversed(range(len(parents))):
        j = parents[i]
        if j >= 0:
            level[j] = max(level[j], level[i] + 1)
    return max(level, default=0)


def _sweep(A, S, groups, joint_points):
    """``T_i``, ``R_i U_iᵀ`` (7.8), gram and cond of every joint at once, by groups of equal dof count."""
    N = A.shape[0]
    T = np.zeros((N, 3, 3))                        # padded to 3 columns; only k_i used
    P = np.broadcast_to(_EYE3, (N, 3, 3)).copy()
    grams = [None] * N
    cond = np.ones(N)
    for k, idx, Sg in groups:
        pts = None if joint_points is None else np.asarray(joint_points, float)[idx]
        As, M, c = _gram(A[idx], Sg, pts)
        c = np.broadcast_to(np.asarray(c, dtype=float), (len(idx),))
        cond[idx] = c
        ok = np.isfinite(c)
        Tg = np.zeros((len(idx), 3, k))
        if np.any(ok):
            Tg[ok] = np.swapaxes(np.linalg.solve(M[ok], np.swapaxes(As[ok], -1, -2)), -1, -2)   # A s (sᵀAs)⁻¹
        T[idx, :, :k] = Tg
        P[idx] = _EYE3 - Tg @ np.swapaxes(Sg, -1, -2)
        for n, i in enumerate(idx):
            grams[i] = (As[n], M[n])
    return T, P, grams, cond


def _truncated(I, p, S, kappa, tau, parents, points, joint_points, check, steps) -> ArticulatedInertias:
    """7.7a/7.7b truncated after ``steps`` bodies outboard, as Jacobi sweeps (thesis 10.2.2)."""
    N = I.shape[0]
    par = np.asarray(parents, dtype=int)
    kids = np.flatnonzero(par >= 0)
    idxs = {k: np.array([i for i in range(N) if S[i].shape[1] == k], dtype=int)
            for k in {s.shape[1] for s in S} - {0}}
    groups = [(k, idx, np.stack([S[i] for i in idx])) for k, idx in sorted(idxs.items())]
    Tq = np.zeros((N, 3))                          # T_i Q_i comes after T_i is known
    A, d = I.copy(), p.copy()
    for _ in range(steps + 1):
        A = 0.5 * (A + np.swapaxes(A, -1, -2))
        T, P, grams, cond = _sweep(A, S, groups, joint_points)
        if _ == steps:
            break
        for i in range(N):
            Tq[i] = T[i, :, :S[i].shape[1]] @ tau[i]
        PA = P[kids] @ A[kids]
        pd = Tq[kids] + np.einsum("nij,nj->ni", P[kids], np.einsum("nij,nj->ni", A[kids], kappa[kids]) + d[kids])
        A, d = I.copy(), p.copy()
        np.add.at(A, par[kids], PA)                # (7.7a) from the previous sweep's inertias
        np.add.at(d, par[kids], pd)                # (7.7b)
    if check:
        for i in range(N):
            if S[i].shape[1] and not cond[i] <= COND_LIMIT:
                raise singular_joint_error(i, cond[i])
    Ts = [T[i, :, :S[i].shape[1]] for i in range(N)]
    return ArticulatedInertias(A, d, S, Ts, list(P), grams, cond,
                               None if points is None else np.asarray(points, float), steps)


def truncation_error(model, q, qd=None, tau=None, f_ext=None, *, steps: int) -> dict:
    """Error of the truncated articulated recursion against the full one (thesis 10.2.2).

    Parameters
    ----------
    model, q, qd, tau, f_ext : Model, array_like
        One state, as for :func:`articulated_inertia`.
    steps : int
        Bodies outboard kept by the truncated recursion.

    Returns
    -------
    dict
        Per body ``"A"`` ``‖A_i^(k) - A_i‖_F / ‖A_i‖_F`` and ``"d"`` ``max|d_i^(k) - d_i| / max|d|``;
        ``"entries"`` ``|A_i^(k) - A_i| / ‖A_i‖_F``; ``"max_A"``, ``"max_d"``, ``"truncated"``, ``"full"``.

    Raises
    ------
    InputError, SingularConfigurationError
        A bad ``steps``, or a singular joint.

    Examples
    --------
    >>> from planargeo.scenes.horizontal_chain import horizontal_chain_model
    >>> e = truncation_error(horizontal_chain_model(6, 1.0, 0.5, 1.0), np.zeros(6), steps=3)
    >>> round(float(e["A"][0]), 4), float(e["entries"][0][2, 2])     # A_z exact after one step
    (0.3114, 0.0)
    """
    if steps is None:
        raise InputError("steps must be a non-negative integer, got None")
    st = _state_arrays(model, q, qd, tau, f_ext)[1:]
    full = articulated_recursion(*st)
    trunc = articulated_recursion(*st, steps=steps)
    nA = np.sqrt(np.einsum("nij,nij->n", full.A, full.A))
    eA = np.sqrt(np.einsum("nij,nij->n", trunc.A - full.A, trunc.A - full.A)) / nA
    dscale = float(np.abs(full.d).max(initial=0.0))
    ed = np.abs(trunc.d - full.d).max(axis=1) / dscale if dscale > 0 else np.zeros(model.N)
    ent = np.abs(trunc.A - full.A) / nA[:, None, None]
    return {"A": eA, "d": ed, "entries": ent, "max_A": float(eA.max(initial=0.0)), "max_d": float(ed.max(initial=0.0)),
            "truncated": trunc, "full": full}


def articulated_inertia(model, q, qd=None, tau=None, f_ext=None, *, steps: int | None = None) -> ArticulatedInertias:
    """Articulated inertias ``A_i`` and bias forces ``d_i`` of every body (thesis 7.1.1).

    Parameters
    ----------
    model, q, qd, tau, f_ext : Model, array_like
        One state (``qd``, ``tau`` zero if omitted; ``f_ext`` (N, 3) world wrenches besides gravity).
    steps : int, optional
        Truncate the recursion after ``steps`` outboard bodies (:func:`articulated_recursion`).

    Returns
    -------
    ArticulatedInertias

    Raises
    ------
    InputError, SingularConfigurationError
        A bad state or ``steps``, or a singular joint.

    Examples
    --------
    >>> from planargeo.mechanics.model import chain_model
    >>> articulated_inertia(chain_model(2), [0.0, 0.0]).A[0][0, 0]      # twice the mass
    np.float64(2.0)
    """
    return articulated_recursion(*_state_arrays(model, q, qd, tau, f_ext)[1:], steps=steps)


# -- Model glue shared by the chapter 6-9 algorithms ----------------------------------------------
def _state_arrays(model, q, qd, tau, f_ext, checked=False):
    """``(data, I, S, kappa, p, tau, parents, points, joint_points)`` of one state (``checked``: validated)."""
    if not checked:
        q, qd, tau, f_ext = _one_state(model, q, qd, tau, f_ext, None)
    return _data_arrays(model, _kinematics_scalar(model, q, np.zeros(model.nq) if qd is None else qd, f_ext), tau)


def _one_state(model, q, qd, tau, f_ext, who: str | None):
    """``(q, qd, tau, f_ext)`` checked as one state; a batch: ShapeError naming ``who`` (or ``q``)."""
    q, qd, tau, f_ext, _, shape = check_state(model, q, qd, tau, f_ext)
    if shape != ():
        raise ShapeError(f"{who} takes one state, got batch shape {shape}" if who else
                         f"q must describe one state (shape (nq,)), got batch shape {shape}; "
                         "loop over states or use planargeo.algorithms.aba for batches")
    return q, qd, tau, f_ext


def _data_arrays(model, d, tau):
    """:func:`_state_arrays` of the kinematics ``d`` of one state (``tau`` zero if None)."""
    tau = np.zeros(model.nq) if tau is None else tau
    offs = model.q_offsets
    S = [d.S[:, offs[i]:offs[i + 1]] for i in range(model.N)]                  # d.s(i)
    taus = [tau[offs[i]:offs[i + 1]] for i in range(model.N)]
    return d, d.I, S, d.kappa, d.p, taus, list(model.parents), d.pose[:, :2], d.origin


def _per_state(fn, model, q, qd, tau, f_ext):
    """The one-state solver ``fn(model, q, qd, tau, f_ext) -> (nq,)`` over batch dimensions, validated once."""
    q, qd, tau, f_ext, _, shape = check_state(model, q, qd, tau, f_ext)
    full = shape + (model.nq,)
    q, qd, tau = (np.zeros(full) if x is None else np.broadcast_to(x, full) for x in (q, qd, tau))
    fx = None if f_ext is None else np.broadcast_to(f_ext, shape + (model.N, 3))
    out = np.empty(full)
    for idx in np.ndindex(*shape):
        out[idx] = fn(model, q[idx], qd[idx], tau[idx], None if fx is None else fx[idx])
    return out
