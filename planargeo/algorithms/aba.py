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
