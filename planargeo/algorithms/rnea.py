"""Recursive Newton-Euler inverse dynamics (thesis 3.5, 3.9-3.12, absolute formulation).

Outwards, ``a_i = a_λ + s_i q̈_i + κ_i`` (2.18) with ``a_ground = 0``
(gravity is an applied wrench in ``p_i``, 3.11).  Inwards, each body's joint
force is the force needed to move it plus everything carried by its children,

    ``f_i = I_i a_i + p_i + Σ_{c: λ(c) = i} f_c``       (3.10 for a tree)

and the joint torque is its projection ``τ_i = s_iᵀ f_i`` (3.5).

As for forward dynamics (:mod:`planargeo.algorithms.aba`), the recursion is written
twice: :func:`newton_euler` on arrays (any joint kind, batches, the whole workspace),
and :func:`planargeo.algorithms.kernels.newton_euler_state`, compiled, which
:func:`inverse_dynamics` runs for models of revolute, prismatic and fixed joints.
"""
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
    model, q, qd, f_ext : Model, array_like
        The mechanism and its state, as for :func:`planargeo.algorithms.aba.articulated_body`.
    qdd : array_like (..., nq)
        Joint accelerations.

    Returns
    -------
    Data
        Kinematics fields plus ``qdd``, ``a`` (..., N, 3) accelerations (2.18),
        ``f`` (..., N, 3) joint forces (the load joint ``i`` transmits from the
        parent to body ``i``, 3.10) and ``tau`` (..., nq) (3.5).

    Raises
    ------
    ShapeError, NonFiniteError, InputError
        Arguments of the wrong shape, not finite, or complex.
    NumericOverflowError
        If finite input gives a ``τ`` that is not finite (e.g. ``q̈`` near 1e308).

    Examples
    --------
    Holding a horizontal uniform rod (m = 1, L = 1) still takes ``τ = m g L / 2``:

    >>> from planargeo.mechanics.model import chain_model
    >>> w = newton_euler(chain_model(1), [0.0], [0.0], [0.0])
    >>> w.tau, w.f[0]    # the joint carries the weight and the torque (a couple at the pivot)
    (array([4.905]), array([0.   , 9.81 , 4.905]))
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
    """Joint forces/torques ``τ_i = s_iᵀ f_i`` that produce ``qdd`` (thesis 3.5, 3.10, 2.18; recursive Newton-Euler).

    Accelerations outwards by 2.18, joint forces inwards by 3.10 (3.12 at the
    tips, children summed for a tree), torques by 3.5.

    Parameters
    ----------
    model : Model
        The mechanism (bodies, joints, parents, gravity).
    q, qd, qdd : array_like (..., nq)
        ``qd`` or ``qdd`` None: zeros.
    f_ext : array_like (..., N, 3), optional
        External world wrenches at the origin, one per body (besides gravity).
    return_forces : bool
        Also return the joint forces ``f`` (..., N, 3) (world wrenches at the origin).

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
    A unit rod about its end (``J_pivot = m L²/3 = 1/3``), no gravity:

    >>> from planargeo.mechanics.model import chain_model
    >>> inverse_dynamics(chain_model(1, gravity=(0, 0)), [0.0], [0.0], [3.0])
    array([1.])

    Holding it horizontal against gravity takes ``m g L / 2``; the joint force is the
    pivot's reaction (weight plus couple), and a batch of states is one call:

    >>> tau, f = inverse_dynamics(chain_model(1), [0.0], [0.0], [0.0], return_forces=True)
    >>> tau, f
    (array([4.905]), array([[0.   , 9.81 , 4.905]]))
    >>> inverse_dynamics(chain_model(1), [[0.0], [np.pi / 2]], [[0.0], [0.0]], [[0.0], [0.0]]).round(12)
    array([[4.905],
           [0.   ]])
    """
    if return_forces:
        w = newton_euler(model, q, qd, qdd, f_ext)
        return w.tau, w.f
    return evaluate(model, True, q, qd, qdd, f_ext, _general)


def _general(model, q, qd, qdd, f_ext):
    return newton_euler(model, q, qd, qdd, f_ext).tau
