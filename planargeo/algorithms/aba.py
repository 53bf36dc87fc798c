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

:func:`forward_dynamics` evaluates batches ``(..., nq)`` in one vectorised
call (loop over bodies, vectorised over the batch).  For models whose joints
are all revolute, prismatic or fixed the recursion is written component by
component (:func:`_aba_components`): a single state (or a batch of at most
``SMALL_BATCH``) runs on Python floats, avoiding numpy's per-call overhead, and
a larger batch runs the same code on one contiguous array per component.
Other joint kinds use the general 3×k array path of :func:`articulated_body`.
:func:`articulated_body` returns the whole workspace (``A``, ``d``, ``a``,
``f``, ``D``, ``U``, ``u``...) for drawings and reports.
"""
from __future__ import annotations

import math

import numpy as np

from ..errors import SingularConfigurationError
from ..kinematics import check_state, kinematics
from ..model import Data, Model

__all__ = ["forward_dynamics", "articulated_body"]

#: relative threshold below which ``s^T A s`` is declared singular
SINGULAR_RTOL = 1e-13
#: batches up to this size are evaluated state by state on Python floats
SMALL_BATCH = 8


def _check_D(D, A, s, i):
    """Raise SingularConfigurationError if D = s^T A s (..., k, k) is (numerically) singular."""
    k = D.shape[-1]
    scale = np.trace(A, axis1=-2, axis2=-1) * np.maximum(np.sum(s * s, axis=(-2, -1)), 1e-300)
    if k == 1:
        lo = D[..., 0, 0]
        hi = lo
    else:
        w = np.linalg.eigvalsh(D)
        lo, hi = w[..., 0], w[..., -1]
    bad = ~(lo > SINGULAR_RTOL * scale)
    if np.any(bad):
        with np.errstate(divide="ignore", invalid="ignore"):
            cond = np.where(lo > 0, np.maximum(scale, hi) / np.where(lo > 0, lo, 1.0), np.inf)
        raise SingularConfigurationError(
            f"joint {i}: s^T A s is singular (the articulated inertia does not resist the joint motion)",
            float(np.max(np.where(bad, cond, 0.0))))


def articulated_body(model: Model, q, qd, tau, f_ext=None) -> Data:
    """Run the recursive algorithm (thesis 3.6) and return the full workspace.

    Parameters
    ----------
    model : Model
    q, qd, tau : array_like (..., nq)
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
    SingularConfigurationError
        If some ``s_i^T A_i s_i`` is singular (e.g. a point mass on a revolute
        joint at its own position).

    Examples
    --------
    A unit point mass at distance 1 from its pivot (a simple pendulum), released horizontally:

    >>> from planargeo.model import Body, Joint, Model
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
        U = Ai @ s
        D = np.swapaxes(s, -1, -2) @ U
        _check_D(D, Ai, s, i)
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
    return data


def _scalar_tables(model: Model):
    """Per-model constants of the scalar path (cached on the model), or None if unsupported."""
    cache = model._arrays
    if "aba_scalar" not in cache:
        kinds = {"revolute": 1, "prismatic": 2, "fixed": 0}
        if all(j.kind in kinds for j in model.joints):
            cache["aba_scalar"] = tuple(
                (kinds[j.kind], model.parents[i], model.q_offsets[i], *j.placement,
                 b.mass, b.com[0], b.com[1], b.inertia)
                for i, (b, j) in enumerate(zip(model.bodies, model.joints)))
        else:
            cache["aba_scalar"] = None
    return cache["aba_scalar"]


def _singular_components(D, scale, i):
    D, scale = np.asarray(D, dtype=float), np.asarray(scale, dtype=float)
    with np.errstate(divide="ignore", invalid="ignore"):
        cond = np.where(D > 0, scale / np.where(D > 0, D, 1.0), np.inf)
    raise SingularConfigurationError(
        f"joint {i}: s^T A s is singular (the articulated inertia does not resist the joint motion)",
        float(np.max(cond)))


def _aba_components(model: Model, table, q, qd, tau, fe, cos=math.cos, sin=math.sin) -> list:
    """Thesis 3.6 written component by component (revolute / prismatic / fixed joints).

    ``q[k]``, ``qd[k]``, ``tau[k]``, ``fe[i][c]`` are Python floats (one state:
    no numpy overhead) or equally shaped 1-D arrays (a batch: every operation
    is a contiguous elementwise numpy operation); ``cos``/``sin`` match.
    Returns the list of ``q̈_k``.
    """
    gx, gy = model.gravity
    N = len(table)
    # per body: pose+cos/sin, s, v, kappa, A (6 entries), d
    P = [None] * N
    S = [None] * N
    V = [None] * N
    K = [None] * N
    A = [None] * N
    Dd = [None] * N
    for i in range(N):
        kind, par, o, px, py, pth, m, cbx, cby, J = table[i]
        if par < 0:
            ox, oy, phi = px, py, pth
            vx = vy = w = 0.0
        else:
            bx, by, bth, cb, sb = P[par]
            ox = bx + cb * px - sb * py
            oy = by + sb * px + cb * py
            phi = bth + pth
            vx, vy, w = V[par]
        if kind == 1:  # revolute: s = [oy, -ox, 1]
            qi, qdi = q[o], qd[o]
            s0, s1, s2 = oy, -ox, 1.0
            x, y, th = ox, oy, phi + qi
            ct, st = cos(th), sin(th)
        elif kind == 2:  # prismatic: s = [cos phi, sin phi, 0]
            qi, qdi = q[o], qd[o]
            ct, st = cos(phi), sin(phi)
            s0, s1, s2 = ct, st, 0.0
            x, y, th = ox + qi * ct, oy + qi * st, phi
        else:  # fixed
            qdi = 0.0
            s0 = s1 = s2 = 0.0
            x, y, th = ox, oy, phi
            ct, st = cos(th), sin(th)
        P[i] = (x, y, th, ct, st)
        S[i] = (s0, s1, s2)
        u0, u1, u2 = s0 * qdi, s1 * qdi, s2 * qdi
        # kappa = v_parent x (s qd)   (2.19; equal to v_i x s qd for one-dof joints)
        K[i] = (-w * u1 + vy * u2, w * u0 - vx * u2)
        vx, vy, w = vx + u0, vy + u1, w + u2
        V[i] = (vx, vy, w)
        cx = x + ct * cbx - st * cby
        cy = y + st * cbx + ct * cby
        mcx, mcy = m * cx, m * cy
        Io = J + m * (cx * cx + cy * cy)
        # I v, then p = -(v x)^T I v - g   (3.34)
        f0 = m * vx - mcy * w
        f1 = m * vy + mcx * w
        p0 = -w * f1 - m * gx
        p1 = w * f0 - m * gy
        p2 = vx * f1 - vy * f0 - (mcx * gy - mcy * gx)
        if fe is not None:
            e = fe[i]
            p0 -= e[0]
            p1 -= e[1]
            p2 -= e[2]
        A[i] = [m, 0.0, -mcy, m, mcx, Io]
        Dd[i] = [p0, p1, p2]
    # articulated inertias (3.35-3.39), tip to base
    UU = [None] * N
    for i in range(N - 1, -1, -1):
        kind, par, o = table[i][0], table[i][1], table[i][2]
        a00, a01, a02, a11, a12, a22 = A[i]
        d0, d1, d2 = Dd[i]
        k0, k1 = K[i]
        c0 = a00 * k0 + a01 * k1 + d0
        c1 = a01 * k0 + a11 * k1 + d1
        c2 = a02 * k0 + a12 * k1 + d2
        if kind == 0:
            if par >= 0:
                Ap, dp = A[par], Dd[par]
                Ap[0] += a00; Ap[1] += a01; Ap[2] += a02; Ap[3] += a11; Ap[4] += a12; Ap[5] += a22  # noqa: E702
                dp[0] += c0; dp[1] += c1; dp[2] += c2  # noqa: E702
            continue
        s0, s1, s2 = S[i]
        U0 = a00 * s0 + a01 * s1 + a02 * s2
        U1 = a01 * s0 + a11 * s1 + a12 * s2
        U2 = a02 * s0 + a12 * s1 + a22 * s2
        D = s0 * U0 + s1 * U1 + s2 * U2
        scale = (a00 + a11 + a22) * (s0 * s0 + s1 * s1 + s2 * s2)
        ok = D > SINGULAR_RTOL * scale
        if ok is not True and not np.all(ok):
            _singular_components(D, scale, i)
        Di = 1.0 / D
        u = tau[o] - (s0 * c0 + s1 * c1 + s2 * c2)
        UU[i] = (U0, U1, U2, Di, u)
        if par >= 0:
            W0, W1, W2 = U0 * Di, U1 * Di, U2 * Di
            Ap, dp = A[par], Dd[par]
            Ap[0] += a00 - W0 * U0
            Ap[1] += a01 - W0 * U1
            Ap[2] += a02 - W0 * U2
            Ap[3] += a11 - W1 * U1
            Ap[4] += a12 - W1 * U2
            Ap[5] += a22 - W2 * U2
            dp[0] += c0 + W0 * u
            dp[1] += c1 + W1 * u
            dp[2] += c2 + W2 * u
    # joint accelerations (3.40-3.42), base to tip
    qdd = [0.0] * model.nq
    Acc = [None] * N
    for i in range(N):
        kind, par, o = table[i][0], table[i][1], table[i][2]
        if par >= 0:
            b0, b1, b2 = Acc[par]
        else:
            b0 = b1 = b2 = 0.0
        k0, k1 = K[i]
        if kind:
            U0, U1, U2, Di, u = UU[i]
            qi = (u - U0 * b0 - U1 * b1 - U2 * b2) * Di
            qdd[o] = qi
            s0, s1, s2 = S[i]
            Acc[i] = (b0 + s0 * qi + k0, b1 + s1 * qi + k1, b2 + s2 * qi)
        else:
            Acc[i] = (b0 + k0, b1 + k1, b2)
    return qdd


def forward_dynamics(model: Model, q, qd, tau, f_ext=None) -> np.ndarray:
    """Joint accelerations by the recursive articulated-body algorithm (thesis 3.6).

    Parameters
    ----------
    model : Model
    q, qd, tau : array_like (..., nq)
        Joint coordinates, speeds and forces/torques; leading dimensions are a
        batch evaluated in one vectorised call.
    f_ext : array_like (..., N, 3), optional
        External world wrenches at the origin applied to each body (besides gravity).

    Returns
    -------
    ndarray (..., nq)
        ``q̈`` (3.41).

    Raises
    ------
    SingularConfigurationError
        If some ``s_i^T A_i s_i`` is singular.

    Examples
    --------
    A uniform rod (mass 1, length 1) pinned at one end, released horizontally:
    ``q̈ = -(m g L/2) / (m L²/3) = -1.5 g``.

    >>> from planargeo.model import chain_model
    >>> forward_dynamics(chain_model(1), [0.0], [0.0], [0.0])
    array([-14.715])
    >>> forward_dynamics(chain_model(1), [[0.0], [np.pi / 2]], [[0.0], [0.0]], [[0.0], [0.0]]).round(12)
    array([[-14.715],
           [  0.   ]])
    """
    q, qd, tau, f_ext, _, shape = check_state(model, q, qd, tau, f_ext)
    table = _scalar_tables(model)
    if table is None:
        return articulated_body(model, q, qd, tau, f_ext).qdd
    if shape == ():   # one state: Python floats
        return np.array(_aba_components(model, table, q.tolist(), qd.tolist(), tau.tolist(),
                                        None if f_ext is None else f_ext.tolist()))
    # a batch: one contiguous array per component, batch along the last axis
    nq, N = model.nq, model.N
    B = int(np.prod(shape))
    if B <= SMALL_BATCH:   # numpy's per-call overhead dominates: state by state on floats
        qb, qdb, taub = (np.broadcast_to(x, shape + (nq,)).reshape(B, nq) for x in (q, qd, tau))
        feb = None if f_ext is None else np.broadcast_to(f_ext, shape + (N, 3)).reshape(B, N, 3)
        res = np.array([_aba_components(model, table, qb[k].tolist(), qdb[k].tolist(), taub[k].tolist(),
                                        None if feb is None else feb[k].tolist()) for k in range(B)])
        return res.reshape(shape + (nq,))

    def rows(x):
        return np.ascontiguousarray(np.broadcast_to(x, shape + (nq,)).reshape(B, nq).T)

    fe = None
    if f_ext is not None:
        fe = np.ascontiguousarray(np.broadcast_to(f_ext, shape + (N, 3)).reshape(B, N, 3).transpose(1, 2, 0))
    out = _aba_components(model, table, rows(q), rows(qd), rows(tau), fe, np.cos, np.sin)
    res = np.empty((B, nq))
    for k, x in enumerate(out):
        res[:, k] = x
    return res.reshape(shape + (nq,))
