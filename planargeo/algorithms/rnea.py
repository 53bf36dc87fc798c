"""Recursive Newton-Euler inverse dynamics (thesis 3.5, 3.9-3.12), on arrays or by the compiled kernels."""
from __future__ import annotations

import numpy as np

from planargeo.algorithms.compiled import check_finite, evaluate
from planargeo.mechanics.kinematics import check_state, kinematics
from planargeo.mechanics.model import Data, Model

__all__ = ["inverse_dynamics", "newton_euler"]


@np.errstate(over="ignore", invalid="ignore")   # out of the float range: check_finite says so by name
def newton_euler(model: Model, q, qd, qdd, f_ext=None) -> Data:
    """Recursive Newton-Euler pass (thesis 2.18, 3.10, 3.5); returns the workspace with ``a``, ``f``, ``tau``.

    Parameters
    ----------
    model, q, qd, qdd, f_ext : Model, array_like
        As for :func:`inverse_dynamics`: the mechanism and its states.

    Returns
    -------
    Data
        Kinematics fields plus ``qdd``, ``a`` (2.18), ``f`` (the load joint ``i`` carries from the
        parent to body ``i``, 3.10) and ``tau`` (3.5).

    Raises
    ------
    ShapeError, NonFiniteError, InputError, NumericOverflowError
        Arguments of the wrong shape, not finite or complex, or a ``τ`` that is not finite.

    Examples
    --------
    >>> from planargeo.mechanics.model import chain_model
    >>> newton_euler(chain_model(1), [0.0], [0.0], [0.0]).f[0]    # a unit rod held: m g, m g L / 2
    array([0.   , 9.81 , 4.905])
    """
    q, qd, _, f_ext, qdd, shape = check_state(model, q, qd, None, f_ext, qdd=qdd)
    data = kinematics(model, q, qd, f_ext)
    nq, N = model.nq, model.N
    qdd = np.broadcast_to(qdd, shape + (nq,))
    a = np.zeros(shape + (N, 3))
    for i, par in enumerate(model.parents):
        ai = data.kappa[..., i, :] + np.einsum("...ij,...j->...i", data.s(i), qdd[..., model.q_slice(i)])
        if par >= 0:
            ai = ai + a[..., par, :]
        a[..., i, :] = ai
    f = np.einsum("...ij,...j->...i", data.I, a) + data.p
    tau = np.zeros(shape + (nq,))
    for i in range(N - 1, -1, -1):
        par = model.parents[i]
        if par >= 0:
            f[..., par, :] += f[..., i, :]
        tau[..., model.q_slice(i)] = np.einsum("...ij,...i->...j", data.s(i), f[..., i, :])
    data.qdd, data.a, data.f, data.tau = qdd, a, f, tau
    check_finite(tau, "τ", q=q, qd=qd, qdd=qdd, f_ext=f_ext)
    return data


def inverse_dynamics(model: Model, q, qd, qdd, f_ext=None, *, return_forces: bool = False):
    """Joint forces/torques ``τ_i = s_iᵀ f_i`` that produce ``qdd`` (thesis 3.5, 3.10, 3.12, 2.18; RNEA).

    Parameters
    ----------
    model, q, qd, qdd, f_ext : Model, array_like
        The mechanism and its states, as for :func:`planargeo.algorithms.aba.forward_dynamics`.
    return_forces : bool
        Also return the joint forces ``f`` (..., N, 3).

    Returns
    -------
    tau : ndarray (..., nq)
    f : ndarray (..., N, 3), only if ``return_forces``

    Raises
    ------
    ShapeError, NonFiniteError, InputError, NumericOverflowError
        As :func:`newton_euler`.

    Examples
    --------
    >>> from planargeo.mechanics.model import chain_model
    >>> inverse_dynamics(chain_model(1, gravity=(0, 0)), [0.0], [0.0], [3.0])     # J_pivot = m L²/3
    array([1.])
    """
    if return_forces:
        w = newton_euler(model, q, qd, qdd, f_ext)
        return w.tau, w.f
    return evaluate(model, True, q, qd, qdd, f_ext, _general)


def _general(model, q, qd, qdd, f_ext):
    return newton_euler(model, q, qd, qdd, f_ext).tau
