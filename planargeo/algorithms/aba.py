"""Recursive articulated-body forward dynamics (thesis 3.6, 3.31-3.42).

Absolute (global-origin) formulation: every twist, wrench and inertia is
expressed at the world origin, so no coordinate transforms appear between
bodies.  Trees are handled by summing the articulated contributions of all
children into the parent (the chain recursion 3.38/3.39 with ``i+1`` replaced
by "each child of ``i``").

For body ``i`` with joint space ``s_i`` (3×k), articulated inertia ``A_i`` and
articulated bias force ``d_i`` (after its children have been added):

* ``D_i = s_iᵀ A_i s_i``, ``U_i = A_i s_i``, ``c_i = A_i κ_i + d_i``,
  ``u_i = τ_i - s_iᵀ c_i``;
* the parent ``λ`` receives (3.37-3.39, with ``(s⁺)ᵀ = U D⁻¹``)
  ``A_λ += A_i - U_i D_i⁻¹ U_iᵀ = (1 - s_i s_i⁺)ᵀ A_i`` and
  ``d_λ += c_i + U_i D_i⁻¹ u_i = (s_i⁺)ᵀ τ_i + (1 - s_i s_i⁺)ᵀ (A_i κ_i + d_i)``;
* outwards, ``q̈_i = D_i⁻¹ (u_i - U_iᵀ a_λ)`` (3.41) and
  ``a_i = a_λ + s_i q̈_i + κ_i`` (3.42), with ``a_ground = 0`` (3.40);
  gravity enters as applied wrenches in ``p_i`` (3.34), not as a base
  acceleration;
* the joint force is ``f_i = A_i a_i + d_i`` (3.13).

The recursion is written twice, once per audience, and the tests hold the two
to each other and to independent references (Pinocchio, Lagrange's equations):

* :func:`articulated_body` on arrays, as above: any joint kind (3×k joint spaces),
  batches broadcast over leading dimensions, and the whole workspace (``A``, ``d``,
  ``a``, ``f``, ``D``, ``U``, ``u``...) returned for drawings and reports;
* :func:`planargeo.algorithms.kernels.articulated_body_state`: one state of a model of
  revolute, prismatic and fixed joints as plain loops over the bodies, each body at
  its joint's point, compiled by numba.  :func:`forward_dynamics` runs it for such
  models (a batch in blocks of states shared among threads) and
  :func:`articulated_body` for the others (see :mod:`planargeo.algorithms.compiled`).
"""
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
    model : Model
        The mechanism (bodies, joints, parents, gravity).
    q, qd, tau : array_like (..., nq)
        One state: joint coordinates, velocities and forces.
    f_ext : array_like (..., N, 3), optional
        External wrenches at the origin on each body.

    Returns
    -------
    Data
        The kinematics fields plus ``A`` (..., N, 3, 3) articulated inertias
        (3.38), ``d`` (..., N, 3) articulated bias forces (3.39), ``a``
        (..., N, 3) accelerations (3.42), ``f`` (..., N, 3) joint forces
        ``A a + d`` (3.13), ``qdd`` (..., nq) (3.41), ``tau``, and per joint
        lists ``D`` (``s^T A s``), ``U`` (``A s``), ``u`` (``tau - s^T (A kappa + d)``).

    Raises
    ------
    ShapeError, NonFiniteError, InputError
        Arguments of the wrong shape, not finite, or complex (:func:`~planargeo.mechanics.kinematics.check_state`).
    SingularConfigurationError
        If some ``s_i^T A_i s_i`` is singular (e.g. a point mass on a revolute
        joint at its own position), by the rule of :data:`planargeo.errors.COND_LIMIT`
        (measured at the joint's point).
    NumericOverflowError
        If finite input gives a ``q̈`` that is not finite (e.g. speeds of 1e160).

    Examples
    --------
    A unit point mass at distance 1 from its pivot (a simple pendulum), released horizontally:

    >>> from planargeo.mechanics.model import Body, Joint, Model
    >>> m = Model([Body(1.0, com=(1.0, 0.0))], [Joint("revolute")], [-1])
    >>> w = articulated_body(m, [0.0], [0.0], [0.0])
    >>> w.qdd, w.f[0]                  # g/L, and the pivot carries no load in free fall
    (array([-9.81]), array([0., 0., 0.]))
    """
    q, qd, tau, f_ext, _, shape = check_state(model, q, qd, tau, f_ext)
    data = kinematics(model, q, qd, f_ext)
    nq, N = model.nq, model.N
    tau = np.broadcast_to(tau, shape + (nq,))
    A = data.I.copy()
    d = data.p.copy()
    Dl, Ul, Dinvl, ul = [None] * N, [None] * N, [None] * N, [None] * N
    parents = model.parents

    # 3. articulated inertias, tip to base (3.35-3.39)
    for i in range(N - 1, -1, -1):
        s = data.s(i)
        k = s.shape[-1]
        Ai, di = A[..., i, :, :], d[..., i, :]
        c = np.einsum("...ij,...j->...i", Ai, data.kappa[..., i, :]) + di
        par = parents[i]
        if k == 0:
            if par >= 0:
                A[..., par, :, :] += Ai
                d[..., par, :] += c
            continue
        U, D = _checked_gram(Ai, s, f"sᵀAs of joint {i}", data.origin[..., i, :])
        Dinv = 1.0 / D if k == 1 else np.linalg.inv(D)
        u = tau[..., model.q_slice(i)] - np.einsum("...ij,...i->...j", s, c)
        Dl[i], Ul[i], Dinvl[i], ul[i] = D, U, Dinv, u
        if par >= 0:
            UDinv = U @ Dinv
            A[..., par, :, :] += Ai - UDinv @ np.swapaxes(U, -1, -2)
            d[..., par, :] += c + np.einsum("...ij,...j->...i", UDinv, u)

    # 4. joint accelerations, base to tip (3.40-3.42)
    a = np.zeros(shape + (N, 3))
    qdd = np.zeros(shape + (nq,))
    for i in range(N):
        par = parents[i]
        ap = a[..., par, :] if par >= 0 else np.zeros(shape + (3,))
        ai = ap + data.kappa[..., i, :]
        if Dl[i] is not None:
            qi = np.einsum("...ij,...j->...i", Dinvl[i], ul[i] - np.einsum("...ij,...i->...j", Ul[i], ap))
            qdd[..., model.q_slice(i)] = qi
            ai = ai + np.einsum("...ij,...j->...i", data.s(i), qi)
        a[..., i, :] = ai
    data.tau = tau
    data.A, data.d, data.a, data.qdd = A, d, a, qdd
    data.f = np.einsum("...ij,...j->...i", A, a) + d
    data.D, data.U, data.u = Dl, Ul, ul
    check_finite(qdd, "q̈", q=q, qd=qd, tau=tau, f_ext=f_ext)
    return data


def forward_dynamics(model: Model, q, qd, tau, f_ext=None) -> np.ndarray:
    """Joint accelerations by the recursive articulated-body algorithm (thesis 3.6, 3.31-3.42).

    Parameters
    ----------
    model : Model
        The mechanism (bodies, joints, parents, gravity).
    q, qd, tau : array_like (..., nq)
        Joint coordinates, speeds and forces/torques; leading dimensions are a
        batch evaluated in one call.  ``qd`` or ``tau`` None: zeros.
    f_ext : array_like (..., N, 3), optional
        External world wrenches at the origin applied to each body (besides gravity).

    Returns
    -------
    ndarray (..., nq)
        ``q̈`` (3.41).

    Raises
    ------
    ShapeError, NonFiniteError, InputError
        Arguments of the wrong shape, not finite, or complex.
    SingularConfigurationError
        If some ``s_i^T A_i s_i`` is singular by the package's one rule
        (:data:`planargeo.errors.COND_LIMIT`: ``‖A_P‖_F ‖s_P‖² / σ_min(sᵀAs) > 1e12``
        at the joint's point ``P``, invariant under moving the whole mechanism), with
        that ``.cond``, for the same states the other recursive methods refuse.
    NumericOverflowError
        If finite input gives a ``q̈`` that is not finite (e.g. speeds of 1e160).

    Examples
    --------
    A uniform rod (mass 1, length 1) pinned at one end, released horizontally:
    ``q̈ = -(m g L/2) / (m L²/3) = -1.5 g``.

    >>> from planargeo.mechanics.model import chain_model
    >>> forward_dynamics(chain_model(1), [0.0], [0.0], [0.0])
    array([-14.715])
    >>> forward_dynamics(chain_model(1), [[0.0], [np.pi / 2]], [[0.0], [0.0]], [[0.0], [0.0]]).round(12)
    array([[-14.715],
           [  0.   ]])
    """
    return evaluate(model, False, q, qd, tau, f_ext, _general)


def _general(model, q, qd, tau, f_ext):
    return articulated_body(model, q, qd, tau, f_ext).qdd
