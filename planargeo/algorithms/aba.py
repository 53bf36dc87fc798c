"""Recursive articulated-body forward dynamics (thesis 3.6, 3.31-3.42), on arrays or by the compiled kernels."""
from __future__ import annotations

import numpy as np

from planargeo.algorithms.compiled import check_finite, evaluate
from planargeo.mechanics.kinematics import check_state, kinematics
from planargeo.mechanics.model import Data, Model
from planargeo.mechanics.subspaces import _checked_gram

__all__ = ["forward_dynamics", "articulated_body"]


@np.errstate(over="ignore", invalid="ignore")   # out of the float range: check_finite says so by name
def articulated_body(model: Model, q, qd, tau, f_ext=None) -> Data:
    """Run the recursive algorithm (thesis 3.6) and return the full workspace.

    Parameters
    ----------
    model, q, qd, tau, f_ext : Model, array_like
        The mechanism and its states, as for :func:`forward_dynamics`.

    Returns
    -------
    Data
        The kinematics fields plus ``A`` (3.38), ``d`` (3.39), ``a`` (3.42), ``f = A a + d``
        (3.13), ``qdd`` (3.41), ``tau``, and per joint ``D`` (``sᵀAs``), ``U`` (``A s``), ``u``.

    Notes
    -----
    One state of joints with at most one coordinate each (an explorer's update) runs steps 3-4
    on Python floats: the array code's operations in NumPy's order, so the same numbers.

    Raises
    ------
    ShapeError, NonFiniteError, InputError, SingularConfigurationError, NumericOverflowError
        As :func:`forward_dynamics`.

    Examples
    --------
    >>> from planargeo.mechanics.model import Body, Joint, Model
    >>> pendulum = Model([Body(1.0, com=(1.0, 0.0))], [Joint("revolute")], [-1])
    >>> w = articulated_body(pendulum, [0.0], [0.0], [0.0])
    >>> w.qdd, w.f[0]                     # released horizontally: g / L, no pivot load
    (array([-9.81]), array([0., 0., 0.]))
    """
    q, qd, tau, f_ext, _, shape = check_state(model, q, qd, tau, f_ext)
    data = kinematics(model, q, qd, f_ext)
    nq, N = model.nq, model.N
    tau = np.broadcast_to(tau, shape + (nq,))
    if shape == () and data.kappa.flags.c_contiguous and all(data.s(i).shape[-1] <= 1 for i in range(N)):
        _one_state(model, data, tau)
        check_finite(data.qdd, "q̈", q=q, qd=qd, tau=tau, f_ext=f_ext)
        return data
    A, d, parents = data.I.copy(), data.p.copy(), model.parents
    Dl, Ul, Dinvl, ul = [None] * N, [None] * N, [None] * N, [None] * N
    # 3. articulated inertias, tip to base (3.35-3.39)
    for i in range(N - 1, -1, -1):
        s = data.s(i)
        k = s.shape[-1]
        Ai, di = A[..., i, :, :], d[..., i, :]
        c = np.einsum("...ij,...j->...i", Ai, data.kappa[..., i, :]) + di
        par = parents[i]
        if k:                                       # a weld passes on A_i and c whole
            U, D = _checked_gram(Ai, s, f"sᵀAs of joint {i + 1}", data.origin[..., i, :])
            Dinv = 1.0 / D if k == 1 else np.linalg.inv(D)
            u = tau[..., model.q_slice(i)] - np.einsum("...ij,...i->...j", s, c)
            Dl[i], Ul[i], Dinvl[i], ul[i] = D, U, Dinv, u
            if par >= 0:
                UDinv = U @ Dinv
                Ai, c = Ai - UDinv @ np.swapaxes(U, -1, -2), c + np.einsum("...ij,...j->...i", UDinv, u)
        if par >= 0:
            A[..., par, :, :] += Ai
            d[..., par, :] += c
    # 4. joint accelerations, base to tip (3.40-3.42)
    a, qdd = np.zeros(shape + (N, 3)), np.zeros(shape + (nq,))
    for i in range(N):
        par = parents[i]
        ap = a[..., par, :] if par >= 0 else np.zeros(shape + (3,))
        ai = ap + data.kappa[..., i, :]
        if Dl[i] is not None:
            qi = np.einsum("...ij,...j->...i", Dinvl[i], ul[i] - np.einsum("...ij,...i->...j", Ul[i], ap))
            qdd[..., model.q_slice(i)] = qi
            ai = ai + np.einsum("...ij,...j->...i", data.s(i), qi)
        a[..., i, :] = ai
    data.tau, data.A, data.d, data.a, data.qdd = tau, A, d, a, qdd
    data.D, data.U, data.u = Dl, Ul, ul
    data.f = np.einsum("...ij,...j->...i", A, a) + d
    check_finite(qdd, "q̈", q=q, qd=qd, tau=tau, f_ext=f_ext)
    return data


def _dot3(r, x):
    """``einsum("ij,j->i")``'s sum of one row on floats: NumPy's order (elements 0 and 2, then 1) and
    its zero (+0, never -0: its sums start from 0)."""
    return 0.0 + ((r[0] * x[0] + r[2] * x[2]) + r[1] * x[1])


def _one_state(model: Model, data: Data, tau: np.ndarray) -> None:
    """Steps 3 and 4 of :func:`articulated_body` for one state whose joints have at most one
    coordinate each, on Python floats: the same operations in the same order as the array code
    (the einsum sums as :func:`_dot3`; a product summed alone, ``0.0 + x y``), without numpy's
    per-call cost on 3-vectors."""
    N, parents = model.N, model.parents
    A, d, kappa = data.I.tolist(), data.p.tolist(), data.kappa.tolist()
    origin = data.origin
    tau_l = tau.tolist()
    cols = [data.s(i) for i in range(N)]
    qi_of = [model.q_slice(i).start for i in range(N)]
    Dl, Ul, ul, uf, dinv = [None] * N, [None] * N, [None] * N, [None] * N, [None] * N
    # 3. articulated inertias, tip to base (3.35-3.39)
    for i in range(N - 1, -1, -1):
        Ai, di, ki = A[i], d[i], kappa[i]
        c = [_dot3(Ai[0], ki) + di[0], _dot3(Ai[1], ki) + di[1], _dot3(Ai[2], ki) + di[2]]
        par = parents[i]
        if cols[i].shape[-1]:
            U, D = _checked_gram(np.array(Ai), cols[i], f"sᵀAs of joint {i + 1}", origin[i])
            Dinv = 1.0 / float(D[0, 0])          # D is not 0 (the check above)
            s0, s1, s2 = cols[i][:, 0].tolist()
            if cols[i].strides[0] == 8:    # einsum's order on a contiguous column; on a strided one, in turn
                sc = (s0 * c[0] + s2 * c[2]) + s1 * c[1]
            else:
                sc = (s0 * c[0] + s1 * c[1]) + s2 * c[2]
            u = tau_l[qi_of[i]] - (0.0 + sc)
            Dl[i], Ul[i], ul[i], uf[i], dinv[i] = D, U, np.array([u]), u, Dinv
            if par >= 0:
                U0, U1, U2 = U[:, 0].tolist()
                W = (0.0 + U0 * Dinv, 0.0 + U1 * Dinv, 0.0 + U2 * Dinv)       # U @ Dinv
                Ai = [[Ai[r][0] - (0.0 + W[r] * U0), Ai[r][1] - (0.0 + W[r] * U1),
                       Ai[r][2] - (0.0 + W[r] * U2)] for r in range(3)]
                c = [c[0] + (0.0 + W[0] * u), c[1] + (0.0 + W[1] * u), c[2] + (0.0 + W[2] * u)]
        if par >= 0:
            Ap, dp = A[par], d[par]
            for r in range(3):
                row, new = Ap[r], Ai[r]
                row[0] += new[0]
                row[1] += new[1]
                row[2] += new[2]
                dp[r] += c[r]
    # 4. joint accelerations, base to tip (3.40-3.42)
    a, qdd = [None] * N, [0.0] * model.nq
    for i in range(N):
        par = parents[i]
        ap = a[par] if par >= 0 else [0.0, 0.0, 0.0]
        ki = kappa[i]
        ai = [ap[0] + ki[0], ap[1] + ki[1], ap[2] + ki[2]]
        if Dl[i] is not None:
            U0, U1, U2 = Ul[i][:, 0].tolist()
            Uap = 0.0 + ((U0 * ap[0] + U2 * ap[2]) + U1 * ap[1])
            qi = 0.0 + dinv[i] * (uf[i] - Uap)
            qdd[qi_of[i]] = qi
            s0, s1, s2 = cols[i][:, 0].tolist()
            ai = [ai[0] + (0.0 + s0 * qi), ai[1] + (0.0 + s1 * qi), ai[2] + (0.0 + s2 * qi)]
        a[i] = ai
    data.tau, data.A, data.d = tau, np.array(A).reshape(N, 3, 3), np.array(d).reshape(N, 3)
    data.a, data.qdd = np.array(a).reshape(N, 3), np.array(qdd)
    data.D, data.U, data.u = Dl, Ul, ul
    f = [[_dot3(Ar[0], x) + di[0], _dot3(Ar[1], x) + di[1], _dot3(Ar[2], x) + di[2]]
         for Ar, x, di in zip(A, a, d)]
    data.f = np.array(f).reshape(N, 3)


def forward_dynamics(model: Model, q, qd, tau, f_ext=None) -> np.ndarray:
    """Joint accelerations by the recursive articulated-body algorithm (thesis 3.6, 3.31-3.42).

    Parameters
    ----------
    model : Model
        The mechanism.
    q, qd, tau : array_like (..., nq)
        Joint coordinates, speeds and forces; leading dimensions are a batch.  ``qd`` or ``tau`` None: zeros.
    f_ext : array_like (..., N, 3), optional
        External world wrenches at the origin on each body (besides gravity).

    Returns
    -------
    ndarray (..., nq)
        ``q̈`` (3.41).

    Raises
    ------
    ShapeError, NonFiniteError, InputError, SingularConfigurationError, NumericOverflowError
        Bad arguments; a joint singular by the rule of :data:`planargeo.errors.COND_LIMIT` (``.cond``);
        a ``q̈`` that is not finite for finite input.

    Examples
    --------
    >>> from planargeo.mechanics.model import chain_model
    >>> forward_dynamics(chain_model(1), [0.0], [0.0], [0.0])     # a unit rod released: -1.5 g
    array([-14.715])
    """
    return evaluate(model, False, q, qd, tau, f_ext, _general)


def _general(model, q, qd, tau, f_ext):
    return articulated_body(model, q, qd, tau, f_ext).qdd
