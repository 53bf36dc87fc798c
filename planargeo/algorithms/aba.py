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
are all revolute, prismatic or fixed:

* a single state (or each state of a batch of at most ``SMALL_BATCH``) runs a
  *compiled plan*: the recursion generated once per topology as straight-line
  Python on floats (no loops, containers or numpy calls), with every body's
  quantities taken at its own origin (a revolute joint is then ``[0, 0, 1]``),
  classical accelerations (the bias terms are centripetal and Coriolis terms
  of angular velocities only) and gravity as the base acceleration ``-g``; a
  state given as float64
  arrays skips the general validator after a cheap shape and finiteness check
  (see the comment above :func:`_plan_source`);
* a larger batch runs the same plan on rows of numbers (one per state) as
  in-place numpy ufunc calls into preallocated rows, block by block
  (:func:`_batch_source`); models the plan does not cover (or not yet: large
  models compile on reuse) run the recursion component by component
  (:func:`_aba_components`) on one contiguous array per component.
Other joint kinds use the general 3×k array path of :func:`articulated_body`.
:func:`articulated_body` returns the whole workspace (``A``, ``d``, ``a``,
``f``, ``D``, ``U``, ``u``...) for drawings and reports.
"""
from __future__ import annotations

import ast
import math
import re
from fractions import Fraction

import numpy as np

from planargeo.errors import SingularConfigurationError
from planargeo.mechanics.kinematics import check_state, kinematics
from planargeo.mechanics.model import Data, Model
from planargeo.mechanics.subspaces import COND_LIMIT, COND_LIMIT2, _checked_gram, joint_cond, joint_scale, singular_joint_error

__all__ = ["forward_dynamics", "articulated_body"]

# Singular joints: the package's one rule, :data:`planargeo.mechanics.subspaces.COND_LIMIT` (imported, not
# restated): ``cond = ‖A_P‖_F ‖s_P‖² / σ_min(sᵀAs)`` with ``A`` and ``s`` at the joint's point ``P``
# (the joint frame's world origin: the pivot of a revolute joint), invariant under moving the whole
# mechanism, so every
# method accepts or raises for the same states, with the same ``.cond`` and message
# (:func:`planargeo.mechanics.subspaces.singular_joint_error`).
#: batches up to this size are evaluated state by state on Python floats (the batched
#: plan's ~0.5 µs per numpy call per body-step is worth it from about 30 states on)
SMALL_BATCH = 32


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
        joint at its own position), by the rule of :data:`planargeo.mechanics.subspaces.COND_LIMIT`
        (measured at the joint's point).

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


def _singular_components(D, A6, s, X, Y, i):
    """The exact rule for joint ``i`` of :func:`_aba_components`, where its cheap squared test failed.

    ``D = sᵀAs``; ``A6 = (A_00, A_01, A_02, A_11, A_12, A_22)`` and ``s = (s_0, s_1, s_2)`` at the
    origin, ``(X, Y)`` the joint's point (scalars or equally long rows).  The squared test
    ``D² LIMIT² > ‖A_P‖_F²`` also fails when the squares underflow (masses ``1e-170``) or
    overflow: the condition number is computed scale-safely (:func:`planargeo.mechanics.subspaces.joint_scale`)
    and the error raised only for states above :data:`planargeo.mechanics.subspaces.COND_LIMIT`.
    """
    *a, s0, s1, s2, X, Y, D = np.broadcast_arrays(*(np.asarray(x, dtype=float) for x in (*A6, *s, X, Y, D)))
    a00, a01, a02, a11, a12, a22 = a
    A = np.stack([np.stack([a00, a01, a02], -1), np.stack([a01, a11, a12], -1),
                  np.stack([a02, a12, a22], -1)], -2)
    scale = joint_scale(A, np.stack([s0, s1, s2], -1)[..., None], np.stack([X, Y], -1))
    D = np.abs(D)
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        cond = np.where(D > 0, scale / np.where(D > 0, D, 1.0), np.inf)
    bad = ~(cond <= COND_LIMIT)
    if np.any(bad):
        raise singular_joint_error(i, float(np.max(np.where(bad, cond, 0.0))))


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
    O = [None] * N   # the joints' points (joint frame origins), where the singularity rule is measured
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
        O[i] = (ox, oy)
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
        # the rule of subspaces.COND_LIMIT, squared: D² LIMIT² > ‖A_P‖_F² ‖s_P‖⁴ at the joint's point
        # P = (X, Y), where ‖s_P‖ = 1 (s_P = [0, 0, 1] or [cos, sin, 0]); A moved to P (joint_scale)
        X, Y = O[i]
        p02 = a02 + Y * a00 - X * a01
        p12 = a12 + Y * a01 - X * a11
        p22 = a22 + Y * a02 - X * a12 + Y * p02 - X * p12
        F2 = a00 * a00 + a11 * a11 + p22 * p22 + 2.0 * (a01 * a01 + p02 * p02 + p12 * p12)
        ok = D * D * COND_LIMIT2 > F2
        if ok is not True and not np.all(ok):
            _singular_components(D, A[i], S[i], X, Y, i)
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


# -- single state: a compiled plan ---------------------------------------------
#
# One state of a model whose joints are all revolute, prismatic or fixed runs
# the same recursion (3.35-3.42) as straight-line Python on floats, generated
# once per topology ("plan") and compiled: no loops, no containers, no numpy
# calls, only local-variable float arithmetic.  Three reformulations make it
# cheaper without changing the algorithm (the same elimination, 3.35-3.42):
#
# * Every quantity of body i (bias acceleration, articulated inertia and bias
#   force, acceleration) is taken at the body's own origin o_i (world-aligned
#   axes) instead of the world origin: a constant change of reference point,
#   under which the algebra of 3.6 is unchanged (accelerations transform as
#   ``(a + α ẑ × r, α)``, wrenches as ``(F, n + r × F)``, inertias
#   congruently).  A revolute joint is then ``s = [0, 0, 1]``: ``U = A s`` is
#   a column of ``A``, ``D = A_22`` and ``(1 - s s⁺)ᵀ A`` keeps only the 2×2
#   force block, so each step costs a few flops; the articulated bias force
#   passed inwards has moment ``τ_i`` about the joint, and (3.41) reads
#   ``q̈_i = D⁻¹ (u'_i - U_0 ā_0 - U_1 ā_1) - a'_2`` with ``u'_i = τ_i - d_i,2`` and
#   ``ā = a' + κ_i`` (the parent's acceleration at o_i plus the bias term).
#   Singularity follows the package's rule (:data:`planargeo.mechanics.subspaces.COND_LIMIT`,
#   ``A`` and ``s`` at the joint's point ``P``: o_i itself for a revolute joint, o_i
#   less ``q`` along the axis for a prismatic one): the plan tests a cheap sufficient
#   condition ``D² LIMIT² > b²``, ``b ≥ ‖A_P‖_F ‖s_P‖²`` from ``trace A`` at o_i (and
#   ``q²`` for a prismatic joint), and only where that fails the exact rule
#   (:func:`_singular_plan`), so it accepts and raises exactly where the other
#   methods do.
# * Accelerations are *classical*: ``a_i`` is the acceleration of the material
#   point at o_i (and the angular acceleration), not the spatial acceleration.
#   The equations keep their form ``f = I a + d``, ``a_i = a'_λ + s_i q̈_i + κ_i``
#   with other bias terms: the rigid body's ``d`` is the centripetal force
#   ``-ω_i² m_i (c_i - o_i)`` (through the centre of mass: no moment about o_i),
#   and ``κ_i = -ω_λ² r_i`` (the centripetal acceleration of o_i about o_λ, with
#   ``r_i = o_i - o_λ``), plus ``2 ω_λ q̇_i ẑ × e_i`` (Coriolis) for a prismatic
#   joint along ``e_i``.  Only the angular velocities are needed, not the twists
#   (3.32), and the angular component of ``κ`` stays zero.
# * Gravity enters as the base acceleration ``a_ground = -g`` (Featherstone's
#   device): the gravity wrench of 3.34 on body i equals ``I_i (-g)``, so both
#   give the same ``q̈``.
#
# Constants equal to zero (placements along x, coms on the body's x axis, a
# vertical gravity...) are folded out of the generated code; the zero pattern is
# part of the plan's key, the nonzero values are passed in at call time.  So is
# the set of joints whose singularity test cannot fail for any state (proven from
# the constants, see :func:`_checks`; e.g. every joint of ``chain_model``): their
# tests are left out.
_PLAN_KINDS = {"revolute": 1, "prismatic": 2, "fixed": 0}
_PLANS: dict = {}
#: single states of models with more bodies than this use the loop of :func:`_aba_components`
MAX_PLAN_BODIES = 400
#: plans for more bodies than this are compiled only when the model is used again (the float loop meanwhile)
EAGER_PLAN_BODIES = 64
#: plans for more bodies than this keep each body's values in a tuple between passes
PACK_BODIES = 64
#: a joint's singularity test is left out of the plan when proven to pass: ``D`` above this times the bound on
#: ``‖A_P‖_F ‖s_P‖²`` (twice the rule's ``1 / COND_LIMIT``: rounding of ``D`` formed at the joint's point moves
#: ``cond`` by a relative ``ε cond ≤ 1e-4``, far less than the factor 2; see :func:`_checks`) ...
PROVEN_RTOL = 2.0 / COND_LIMIT
#: ... and above this times the bound on ``trace A`` at o_i (rounding errors of ``D``, accumulated at o_i, stay far below)
ROUNDING_RTOL = 1e-8
assert ROUNDING_RTOL >= PROVEN_RTOL   # so the one test of _checks implies both
_cos, _sin = math.cos, math.sin


def _singular_plan(D, a00, a01, a02, a11, a12, a22, q, c, s, i):
    """The exact singularity rule for joint ``i`` of a plan, where its cheap bound failed: raise or return.

    The plan keeps ``A`` at the body origin o_i (world axes); the rule
    (:data:`planargeo.mechanics.subspaces.COND_LIMIT`) takes ``A`` and ``s`` at the joint's point ``P``:
    o_i itself for a revolute joint (``q = 0`` is passed), ``P = o_i - q (c, s)`` for a prismatic
    joint along ``(c, s)`` (its placement point; o_i has slid by ``q``).  ``A_P`` is ``A`` moved by
    ``r = P - o_i`` (moments ``n - r × F``, congruently: :func:`planargeo.mechanics.subspaces.joint_scale`),
    ``s_P = [0, 0, 1]`` or ``[c, s, 0]`` (``‖s_P‖² = 1``); ``D = sᵀAs`` is the same at either point.

    The plan tests first the cheaper sufficient condition ``D² LIMIT² > b²`` with
    ``b ≥ ‖A_P‖_F ‖s_P‖² = ‖A_P‖_F``: for positive semi-definite ``A``, ``‖A_P‖_F ≤ trace A_P``
    (the 2-norm of the eigenvalues is at most their sum), which is ``trace A`` at o_i for a
    revolute joint (``b = A_00 + A_11 + A_22``) and at most ``(1 + 2 q²)(A_00 + A_11) + 2 A_22``
    for a prismatic one (the force block is the same at every point; the moment about ``P`` is
    ``(ẑ + u)ᵀA(ẑ + u) ≤ 2 ẑᵀAẑ + 2 uᵀAu`` with ``|u| = |r| = |q|``); this function runs only
    when that fails.  The test is translation invariant: the plan never uses the world
    position of o_i for it.
    """
    A = np.array([[a00, a01, a02], [a01, a11, a12], [a02, a12, a22]])
    # s = [c, s, 0] at o_i: the prismatic axis, the same at P; for a revolute joint (c, s) = (1, 0), q = 0 and P = o_i:
    # either way ‖s_P‖² = 1, so the scale is ‖A_P‖_F, computed scale-safely (masses 1e-170 or 1e160)
    cond = joint_cond(D, 1.0, joint_scale(A, [c, s, 0.0], (-q * c, -q * s)))
    if not cond <= COND_LIMIT:
        raise singular_joint_error(i, cond)


def _packed(N):
    """Whether the plan for ``N`` bodies keeps per-body values in tuples between passes (fewer locals)."""
    return N > PACK_BODIES


def _plan_source(kinds, parents, zero, with_fext, pack=None, checks=None):
    """Python source of thesis 3.6 for one state of one topology (see the comment above)."""
    return "\n".join(_registers(_plan_lines(kinds, parents, zero, with_fext, pack, checks))) + "\n"


def _plan_lines(kinds, parents, zero, with_fext, pack=None, checks=None):
    """The plan as straight-line statements on uniquely named values, before :func:`_registers`.

    ``kinds``: 1 revolute, 2 prismatic, 0 fixed; ``zero``: which of the
    constants (see :func:`_plan_constants`) vanish.  Values are tracked as
    "signed atoms" ``(negated, name)`` or ``None`` for an exact zero, so zero
    terms disappear and single atoms are aliased rather than copied.
    """
    N = len(kinds)
    nchild = [0] * N
    for p in parents:
        if p >= 0:
            nchild[p] += 1
    lines = []
    emit = lines.append
    ONE, TWO = (False, "1"), (False, "2.0")

    def neg(a):
        return None if a is None else (not a[0], a[1])

    def text(a):
        return "0.0" if a is None else ("-" if a[0] else "") + a[1]

    def expr(terms):
        # sum of products of signed atoms -> (source, None) or (None, single atom or None)
        parts = []
        for factors in terms:
            if any(f is None for f in factors):
                continue
            sign, names = False, []
            for f in factors:
                sign ^= f[0]
                if f[1] != "1":
                    names.append(f[1])
            parts.append((sign, "*".join(names) if names else "1.0"))
        if not parts:
            return None, None
        if len(parts) == 1 and parts[0][1] != "1.0" and "*" not in parts[0][1]:
            return None, parts[0]
        parts.sort(key=lambda t: t[0])
        src = ("-" if parts[0][0] else "") + parts[0][1]
        for sign, part in parts[1:]:
            src += (" - " if sign else " + ") + part
        return src, None

    def let(name, terms):
        src, atom = expr(terms)
        if src is None:
            return atom
        if src.startswith("-") and " + " not in src:   # all terms negative: store the opposite
            src, atom = expr([[(True, "1")] + t for t in terms])
            emit(f"    {name} = {src}")
            return (True, name)
        emit(f"    {name} = {src}")
        return (False, name)

    def let_scaled(name, scale, terms):
        # name = scale * (sum of terms)
        src, atom = expr(terms)
        if src is None or scale is None:
            return let(name, [[scale, atom]])
        emit(f"    {name} = {text(scale)}*({src})")
        return (False, name)

    names, gnames, bnames = [], [], [[] for _ in range(N)]
    if pack is None:
        pack = _packed(N)
    if checks is None:
        checks = (True,) * N

    def const(name, k, group):
        if zero[k]:
            return None
        names.append(name)
        group.append(name)
        return (False, name)

    gx, gy = const("gx", 0, gnames), const("gy", 1, gnames)
    cst = []
    for i in range(N):
        cst.append([const(f"{c}{i}", 2 + 7 * i + k, bnames[i])
                    for k, c in enumerate(("px", "py", "pth", "m", "hx", "hy", "Jo"))])
    emit("def aba_plan(C, q, qd, tau, fe):")
    nq = sum(1 for k in kinds if k)
    if not pack:
        if names:
            emit("    " + ", ".join(names) + ", = C")
        if nq:
            for v in ("q", "qd", "tau"):
                emit("    " + ", ".join(f"{v}{k}" for k in range(nq)) + f", = {v}")
        if with_fext:
            emit("    " + ", ".join(f"F{c}_{i}" for i in range(N) for c in "xyn") + ", = fe")
    else:   # many bodies: read constants and inputs where they are needed
        if gnames:
            emit("    " + ", ".join(gnames) + ", = C[0]")
    stashed = {}

    def stash(name, atoms):
        seen = list(dict.fromkeys(a[1] for a in atoms if a is not None and a[1].isidentifier()))
        stashed[name] = seen
        emit(f"    {name} = ({', '.join(seen)}{',' if len(seen) == 1 else ''})")

    def unstash(name):
        if stashed[name]:
            emit(f"    {', '.join(stashed[name])}, = {name}")

    unpacked = set()

    def need(i):
        if pack and i not in unpacked:
            unpacked.add(i)
            unstash(f"T{i}")
            if "tau" in body[i]:
                emit(f"    {body[i]['tau'][1]} = tau[{body[i]['tau'][1][3:]}]")
    ground = dict(c=ONE, s=None, th=None, w=None, ww=None, o=(None, None))
    body = []
    k = 0
    # 1-2. poses, angular velocities, bias accelerations and bias forces, base to tip (3.32-3.34)
    for i in range(N):
        kind, p = kinds[i], parents[i]
        P = ground if p < 0 else body[p]
        px, py, pth, m, mcbx, mcby, Jo = cst[i]
        cp, sp = P["c"], P["s"]
        emit(f"    # body {i}: {('fixed', 'revolute', 'prismatic')[kind]} joint on {'the ground' if p < 0 else p}")
        if pack:
            emit(f"    {', '.join(bnames[i])}, = C[{i + 1}]")
            if kind:
                emit(f"    q{k} = q[{k}]; qd{k} = qd[{k}]")
            if with_fext:
                emit(f"    Fx_{i} = fe[{3 * i}]; Fy_{i} = fe[{3 * i + 1}]; Fn_{i} = fe[{3 * i + 2}]")
        rx = let(f"rx{i}", [[cp, px], [neg(sp), py]])      # joint frame origin - o_parent
        ry = let(f"ry{i}", [[sp, px], [cp, py]])
        phi = let(f"phi{i}", [[P["th"]], [pth]])
        B = {}
        if kind:
            qi, qdi = (False, f"q{k}"), (False, f"qd{k}")
            B["tau"] = (False, f"tau{k}")
            k += 1
        if kind == 1:
            th = let(f"th{i}", [[phi], [qi]])
        else:
            th = phi
        if th is None:
            c, s = ONE, None
        else:
            emit(f"    c{i} = _cos({text(th)}); s{i} = _sin({text(th)})")
            c, s = (False, f"c{i}"), (False, f"s{i}")
        if kind == 2:   # the body origin slides by q along the joint axis e = (c, s)
            rx = let(f"rx{i}", [[rx], [qi, c]])
            ry = let(f"ry{i}", [[ry], [qi, s]])
        B.update(c=c, s=s, th=th, r=(rx, ry), kind=kind, p=p, q=qi if kind else None)
        # classical accelerations (see the comment above): only angular velocities are needed
        wp = P["w"]
        w = let(f"w{i}", [[wp], [qdi]]) if kind == 1 else wp
        ww = P["ww"] if kind != 1 else let(f"ww{i}", [[w, w]])
        wwp = P["ww"]
        if kind == 2:   # kappa = -w² r + 2 w q̇ ẑ × e, e = (c, s)
            wq = let(f"wq{i}", [[TWO, wp, qdi]])
            kap = (let(f"k0_{i}", [[neg(wwp), rx], [neg(wq), s]]), let(f"k1_{i}", [[neg(wwp), ry], [wq, c]]))
        else:           # kappa = -w² r (centripetal)
            kap = (let(f"k0_{i}", [[neg(wwp), rx]]), let(f"k1_{i}", [[neg(wwp), ry]]))
        B.update(w=w, ww=ww, kap=kap)
        # the body origin in the world (for external wrenches; dropped if unused)
        ox = let(f"ox{i}", [[P["o"][0]], [rx]])
        oy = let(f"oy{i}", [[P["o"][1]], [ry]])
        B["o"] = (ox, oy)
        # rigid inertia at o_i (4.58): m, m (c_i - o_i), J + m |com in body|^2
        mcx = let(f"mcx{i}", [[c, mcbx], [neg(s), mcby]])
        mcy = let(f"mcy{i}", [[s, mcbx], [c, mcby]])
        # bias force: the centripetal force -w² m (c_i - o_i), through the com (no moment about o_i),
        # less the external wrench moved to o_i (3.34; gravity is the base acceleration)
        if with_fext:
            Fx, Fy, Fn = (False, f"Fx_{i}"), (False, f"Fy_{i}"), (False, f"Fn_{i}")
            e = ([neg(Fx)], [neg(Fy)], [neg(Fn)], [ox, Fy], [neg(oy), Fx])
        else:
            e = ([None],) * 5
        B["A"] = [m, None, neg(mcy), m, mcx, Jo]
        B["d"] = [let(f"d0_{i}", [[neg(ww), mcx], e[0]]),
                  let(f"d1_{i}", [[neg(ww), mcy], e[1]]),
                  let(f"d2_{i}", [e[2], e[3], e[4]])]
        body.append(B)
        if pack:   # what the inward pass needs, in one local
            stash(f"T{i}", [*B["r"], *B["kap"], *B["A"], *B["d"],
                            *((B["q"], B["c"], B["s"]) if checks[i] and kind == 2 else ())])
    # 3. articulated inertias and bias forces, tip to base (3.35-3.39)
    IDX = ((0, 0), (0, 1), (0, 2), (1, 1), (1, 2), (2, 2))

    def check(i, D):
        # the rule of subspaces.COND_LIMIT at the joint's point P, cheaply bounded (see _singular_plan):
        # pass if D² LIMIT² > (bound on ‖A_P‖_F ‖s_P‖²)², else the exact rule in _singular_plan
        B = body[i]
        a00, a01, a02, a11, a12, a22 = B["A"]
        t0 = let(f"t0_{i}", [[a00], [a11]])
        if B["kind"] == 1:   # P = o_i: trace A
            bnd = let(f"bd{i}", [[t0], [a22]])
            args = (D, *B["A"], None, ONE, None)
        else:                # P = o_i - q e: (1 + 2 q²)(A_00 + A_11) + 2 A_22
            qq = B["q"]
            bnd = let(f"bd{i}", [[t0], [TWO, qq, qq, t0], [TWO, a22]])
            args = (D, *B["A"], qq, B["c"], B["s"])
        emit(f"    if not {text(D)}*{text(D)}*{COND_LIMIT2!r} > {text(bnd)}*{text(bnd)}:")
        emit(f"        _singular_plan({', '.join(text(x) for x in args)}, {i})")

    def inward(i):
        B = body[i]
        kind, p = B["kind"], B["p"]
        A, d, (k0, k1) = B["A"], B["d"], B["kap"]
        a00, a01, a02, a11, a12, a22 = A
        emit(f"    # body {i}, inwards")
        if kind == 1:   # D = A_22, U = A[:, 2]
            if checks[i]:
                check(i, a22)
            emit(f"    Di{i} = 1.0 / {text(a22)}")
            Di = (False, f"Di{i}")
            W0, W1 = let(f"W0_{i}", [[a02, Di]]), let(f"W1_{i}", [[a12, Di]])
            uu = let(f"u{i}", [[B["tau"]], [neg(d[2])]])
            B["acc"] = (a02, a12, Di, uu)
            if p < 0:
                return
            b = [let(f"b00_{i}", [[a00], [neg(W0), a02]]), let(f"b01_{i}", [[a01], [neg(W0), a12]]), None,
                 let(f"b11_{i}", [[a11], [neg(W1), a12]]), None, None]
            e = [let(f"e0_{i}", [[b[0], k0], [b[1], k1], [d[0]], [W0, uu]]),
                 let(f"e1_{i}", [[b[1], k0], [b[3], k1], [d[1]], [W1, uu]]),
                 B["tau"]]
        else:
            c = [let(f"c{j}_{i}", [[A[IDX.index(tuple(sorted((j, 0))))], k0],
                                   [A[IDX.index(tuple(sorted((j, 1))))], k1], [d[j]]]) for j in range(3)]
            if kind == 2:   # s = [c, s, 0]
                cs, ss = B["c"], B["s"]
                U = [let(f"U{j}_{i}", [[A[IDX.index(tuple(sorted((j, 0))))], cs],
                                       [A[IDX.index(tuple(sorted((j, 1))))], ss]]) for j in range(3)]
                D = let(f"D{i}", [[U[0], cs], [U[1], ss]])
                if checks[i]:
                    check(i, D)
                emit(f"    Di{i} = 1.0 / {text(D)}")
                Di = (False, f"Di{i}")
                uu = let(f"u{i}", [[B["tau"]], [neg(cs), c[0]], [neg(ss), c[1]]])
                B["acc"] = (U, Di, uu)
                if p < 0:
                    return
                W = [let(f"W{j}_{i}", [[U[j], Di]]) for j in range(3)]
                b = [let(f"b{j}{l}_{i}", [[A[n]], [neg(W[j]), U[l]]]) for n, (j, l) in enumerate(IDX)]
                e = [let(f"e{j}_{i}", [[c[j]], [W[j], uu]]) for j in range(3)]
            else:
                if p < 0:
                    return
                b, e = A, c
        # move (b, e) from o_i to o_parent: n' = n + r x F; inertia congruently
        rx, ry = B["r"]
        P02 = let(f"P02_{i}", [[b[2]], [neg(ry), b[0]], [rx, b[1]]])
        P12 = let(f"P12_{i}", [[b[4]], [neg(ry), b[1]], [rx, b[3]]])
        P22 = let(f"P22_{i}", [[b[5]], [neg(ry), b[2]], [neg(ry), P02], [rx, b[4]], [rx, P12]])
        E2 = let(f"E2_{i}", [[e[2]], [rx, e[1]], [neg(ry), e[0]]])
        need(p)
        Q = body[p]
        for n, x in enumerate((b[0], b[1], P02, b[3], P12, P22)):
            Q["A"][n] = let(f"A{IDX[n][0]}{IDX[n][1]}_{p}", [[Q["A"][n]], [x]])
        for j, x in enumerate((e[0], e[1], E2)):
            Q["d"][j] = let(f"d{j}_{p}", [[Q["d"][j]], [x]])
    for i in range(N - 1, -1, -1):
        need(i)
        inward(i)
        if pack:   # what the outward pass needs, in one local
            B = body[i]
            keep = [*B["r"], *B["kap"]]
            if B["kind"] == 1:
                keep += B["acc"]
            elif B["kind"] == 2:
                keep += [*B["acc"][0], *B["acc"][1:], B["c"], B["s"]]
            stash(f"S{i}", keep)

    # 4. accelerations, base to tip (3.40-3.42); a_ground = -g
    out = []
    for i in range(N):
        B = body[i]
        if pack:
            unstash(f"S{i}")
        kind, p = B["kind"], B["p"]
        a0p, a1p, a2p = (neg(gx), neg(gy), None) if p < 0 else body[p]["a"]
        rx, ry = B["r"]
        k0, k1 = B["kap"]
        if kind == 1:   # a0, a1: the parent's acceleration at o_i plus kappa
            a0 = let(f"a0_{i}", [[a0p], [neg(a2p), ry], [k0]])
            a1 = let(f"a1_{i}", [[a1p], [a2p, rx], [k1]])
            a02, a12, Di, uu = B["acc"]
            # the body's angular acceleration a_2 = D⁻¹ (u - U_0 ā_0 - U_1 ā_1), and q̈ = a_2 - a'_2
            a2 = let_scaled(f"a2_{i}", Di, [[uu], [neg(a02), a0], [neg(a12), a1]])
            out.append(let(f"qdd{i}", [[a2], [neg(a2p)]]))
            if nchild[i]:
                B["a"] = (a0, a1, a2)
        elif kind == 2:   # a0, a1: the parent's acceleration at o_i
            a0 = let(f"a0p_{i}", [[a0p], [neg(a2p), ry]])
            a1 = let(f"a1p_{i}", [[a1p], [a2p, rx]])
            U, Di, uu = B["acc"]
            qdd = let_scaled(f"qdd{i}", Di, [[uu], [neg(U[0]), a0], [neg(U[1]), a1], [neg(U[2]), a2p]])
            out.append(qdd)
            if nchild[i]:
                B["a"] = (let(f"a0_{i}", [[a0], [B["c"], qdd], [k0]]),
                          let(f"a1_{i}", [[a1], [B["s"], qdd], [k1]]), a2p)
        elif nchild[i]:   # fixed: the parent's acceleration at o_i plus kappa
            B["a"] = (let(f"a0_{i}", [[a0p], [neg(a2p), ry], [k0]]), let(f"a1_{i}", [[a1p], [a2p, rx], [k1]]), a2p)
    emit("    return [" + ", ".join(text(x) for x in out) + "]")
    return lines


_NAME = re.compile(r"[A-Za-z_][A-Za-z0-9_]*")
_PARAMS = frozenset(("C", "q", "qd", "tau", "fe"))


def _registers(lines):
    """Drop dead assignments and rename the locals of straight-line code onto few reused names.

    CPython slows down past 256 local variables (``EXTENDED_ARG``) and with large
    frames; a linear scan over single assignments (each value lives from its
    assignment to its last read) reuses names as soon as a value is dead.
    """
    head, body = lines[0], []
    for line in lines[1:]:
        st = line.strip()
        if st.startswith("#"):
            continue
        ind = line[:len(line) - len(line.lstrip())]
        body += [(ind, part) for part in st.split("; ")]
    stmts = []   # (indent, targets source or None, targets, rhs source)
    for ind, st in body:
        if " = " in st and not st.startswith(("if ", "return")):
            lhs, rhs = st.split(" = ", 1)
            stmts.append((ind, lhs, [t for t in _NAME.findall(lhs)], rhs))
        else:
            stmts.append((ind, None, [], st))
    local = _PARAMS | {t for s in stmts for t in s[2]}
    while True:   # dead code elimination (pure assignments whose value is never read)
        live, keep = set(), []
        for ind, lhs, tg, rhs in reversed(stmts):
            if lhs is not None and len(tg) == 1 and tg[0] not in live:
                continue
            live.difference_update(tg)
            live.update(n for n in _NAME.findall(rhs) if n in local)
            keep.append((ind, lhs, tg, rhs))
        keep.reverse()
        if len(keep) == len(stmts):
            break
        stmts = keep
    # versions and last reads
    cur, last, reads, writes = {}, {}, [], []
    nver = 0
    for k, (ind, lhs, tg, rhs) in enumerate(stmts):
        r = {n: cur[n] for n in _NAME.findall(rhs) if n in local and n in cur}
        for v in r.values():
            last[v] = k
        w = []
        for t in tg:
            cur[t] = nver
            w.append(nver)
            nver += 1
        reads.append(r)
        writes.append(w)
    free, reg, nreg, out = [], {}, 0, [head]
    for k, (ind, lhs, tg, rhs) in enumerate(stmts):
        r = reads[k]
        src = _NAME.sub(lambda mt: reg[r[mt.group()]] if mt.group() in r else mt.group(), rhs)
        for v in set(r.values()):
            if last[v] == k:
                free.append(reg[v])
        names = []
        for v in writes[k]:
            if free:
                reg[v] = free.pop()
            else:
                reg[v] = f"r{nreg}"
                nreg += 1
            names.append(reg[v])
            if v not in last:   # never read
                free.append(reg[v])
        if lhs is None:
            out.append(ind + src)
        else:
            out.append(ind + (", ".join(names) + ("," if len(names) > 1 or lhs.endswith(",") else "")) + " = " + src)
    return out


def _checks(model: Model, kinds) -> tuple:
    """Which joints keep the singularity test in the plan: those where it is not proven to pass.

    The rule (:data:`planargeo.mechanics.subspaces.COND_LIMIT`) accepts ``D = sᵀAs`` when
    ``D > ‖A_P‖_F ‖s_P‖² / COND_LIMIT`` (``A``, ``s`` at the joint's point ``P``, which
    for a revolute joint is o_i, ``s_P = [0, 0, 1]``).  In exact arithmetic the
    articulated inertia lies between the body's own inertia and the composite inertia
    of its subtree: at o_i, ``D = A_22 ≥ J_i + m_i |c_i - o_i|²`` (revolute; a prismatic
    joint's own ``q`` moves o_i away from ``P`` without bound, so its test is always
    kept), and ``‖A_P‖_F ≤ trace A_P ≤ 2 M + Σ J_k + M ρ²`` with ``M`` the subtree's
    mass and ``ρ`` a bound on the distance from o_i to its centres of mass.  With only
    revolute and fixed joints below body i, ``ρ`` is a constant (a sum of placement
    lengths); where the joint is in the world does not matter.  If the lower bound on
    ``D`` exceeds ``ROUNDING_RTOL`` times that upper bound (so that rounding cannot
    matter; this implies the rule's own margin ``PROVEN_RTOL`` = 2 / LIMIT, far smaller), the test can never fail for any finite
    state and is left out.  Joints whose test can fail (a point mass on its own joint,
    prismatic joints, prismatic joints below...) keep it.
    """
    N = model.N
    mass, jsum, reach, rigid = [0.0] * N, [0.0] * N, [0.0] * N, [True] * N
    for i in range(N - 1, -1, -1):   # children come after their parents
        b = model.bodies[i]
        mass[i] += b.mass
        jsum[i] += b.inertia
        reach[i] = max(reach[i], math.hypot(*b.com))
        p = model.parents[i]
        if p >= 0:
            mass[p] += mass[i]
            jsum[p] += jsum[i]
            reach[p] = max(reach[p], math.hypot(*model.joints[i].placement[:2]) + reach[i])
            rigid[p] = rigid[p] and rigid[i] and kinds[i] != 2
    checks = []
    for i, (b, kind) in enumerate(zip(model.bodies, kinds)):
        low = b.inertia + b.mass * (b.com[0] ** 2 + b.com[1] ** 2)
        high = 2.0 * mass[i] + jsum[i] + mass[i] * reach[i] ** 2
        proven = kind == 1 and rigid[i] and low > ROUNDING_RTOL * high   # implies low > PROVEN_RTOL * high
        checks.append(kind != 0 and not proven)
    return tuple(checks)


def _plan_constants(model: Model):
    """``(key, constants)`` of the compiled single-state plan, or None if a joint kind is unsupported."""
    kinds = []
    for j in model.joints:
        if j.kind not in _PLAN_KINDS:
            return None
        kinds.append(_PLAN_KINDS[j.kind])
    C = [float(g) for g in model.gravity]
    for b, j in zip(model.bodies, model.joints):
        m, (cx, cy), J = float(b.mass), b.com, float(b.inertia)
        C += [float(x) for x in j.placement] + [m, m * cx, m * cy, J + m * (cx * cx + cy * cy)]
    zero = tuple(c == 0.0 for c in C)
    pack = _packed(model.N)
    key = (tuple(kinds), tuple(model.parents), zero, _checks(model, kinds), pack)
    if not pack:
        return key, tuple(c for c in C if c != 0.0)
    groups = [C[:2]] + [C[2 + 7 * i:9 + 7 * i] for i in range(model.N)]
    return key, tuple(tuple(c for c in g if c != 0.0) for g in groups)


def _plan_entry(model: Model):
    """``(key, constants)`` of ``model``'s plan (cached on the model), or None (unsupported joints, too many bodies)."""
    cache = model._arrays
    entry = cache.get("aba_plan")
    if entry is None:
        entry = _plan_constants(model) if model.N <= MAX_PLAN_BODIES else None
        entry = cache["aba_plan"] = entry or False
    return entry or None


def _compile_now(model: Model, counter: str) -> bool:
    """Whether to compile a plan for ``model`` now: at once up to EAGER_PLAN_BODIES bodies, else on the 4th call."""
    if model.N <= EAGER_PLAN_BODIES:   # compiling takes ~5 ms per body: not for a one-off call
        return True
    calls = model._arrays[counter] = model._arrays.get(counter, 0) + 1
    return calls >= 4


def _plan(model: Model, with_fext: bool, force: bool = False):
    """The compiled single-state function and its constants for ``model`` (cached), or None.

    None for unsupported joint kinds or too many bodies (see ``MAX_PLAN_BODIES``), and
    (unless ``force``) for the first calls on a large model (``EAGER_PLAN_BODIES``):
    callers then run the float loop of :func:`_aba_components`.
    """
    entry = _plan_entry(model)
    if entry is None:
        return None
    key, C = entry
    fkey = key + (with_fext,)
    fn = _PLANS.get(fkey)
    if fn is None:
        if not (force or _compile_now(model, "aba_plan_calls")):
            return None
        if len(_PLANS) >= 256:
            _PLANS.clear()
        kinds, parents, zero, checks, pack = key
        src = _plan_source(kinds, parents, zero, with_fext, pack, checks)
        ns: dict = {}
        exec(compile(src, f"<aba plan N={len(key[0])}>", "exec"), globals(), ns)
        fn = _PLANS[fkey] = ns["aba_plan"]
    return fn, C


_ndarray, _F64, _array, _isfinite = np.ndarray, np.dtype(np.float64), np.array, math.isfinite


# -- batches: the plan on rows of numbers ---------------------------------------
#
# A batch of more than SMALL_BATCH states runs the same plan, with each input and
# each intermediate value a row of float64 numbers, one per state.  The plan's
# statements (before :func:`_registers`) are lowered to three-address numpy ufunc
# calls that write into preallocated rows (``out=``), so no temporary array is
# created; values that depend only on the model's constants stay Python floats,
# computed once per block and handed to ufuncs as 0-d arrays (cheaper operands).  A
# linear scan over the ufunc calls assigns each value a row of one work array
# ``W``, reusing a row as soon as its value is dead (an operand's row may be the
# result's: elementwise ufuncs allow that).  The batch is cut into equal blocks of
# at most ``BATCH_CHUNK`` states (fewer if the work rows would take more than
# ``BATCH_BYTES``, but at least 1024): fewer, longer calls cost less overhead per
# state (~0.4 µs a call), shorter rows stay in the cache.  A block's inputs are
# read, and its ``q̈`` written, in place as strided rows (columns of the batch).
#
# ``cos`` and ``sin`` of an angle (libm's take ~10 ns each per state, as much as
# 30 multiplications) come together from a table (:func:`_sincos_table`), when a
# bound on the block's angles (``N max|q|`` plus the placement angles) is within
# ``TRIG_TABLE_RANGE``; otherwise from numpy.
#
# The plan's cheap singularity test ``D² LIMIT² > b²`` (where the plan keeps it, see
# :func:`_checks` and :func:`_singular_plan`) becomes ``D² LIMIT² - b² > 0``, its
# minimum kept in one row and tested once per block.  If it fails, the block is
# evaluated state by state by the single-state plan, which applies the exact rule and
# raises SingularConfigurationError for the first singular state exactly as a single
# state does.  If a result is not finite (finite but huge inputs overflow), the batch is
# run again by the general component path (:func:`_aba_components`), which returns
# its non-finite values with numpy's warnings.
_BATCH_PLANS: dict = {}
#: states per block of a batched plan, and the most bytes of work rows a block may use
BATCH_CHUNK = 16384
BATCH_BYTES = 16 << 20
_UFUNC_NS = {"add": np.add, "sub": np.subtract, "mul": np.multiply, "div": np.divide, "neg": np.negative,
             "minimum": np.minimum, "copyto": np.copyto, "_0d": np.array,
             "_mcos": math.cos, "_msin": math.sin}
_BINOPS = {ast.Add: ("add", "+"), ast.Sub: ("sub", "-"), ast.Mult: ("mul", "*"), ast.Div: ("div", "/")}
_CHECK = re.compile(r"if not (.+) > (.+):$")


#: entries of the sine and cosine tables of :func:`_sincos_table`, and the angles it serves
TRIG_TABLE = 16384
TRIG_TABLE_RANGE = 1e4
_TRIG_H = 2 * Fraction("3.14159265358979323846264338327950288419716939937510582097494459") / TRIG_TABLE
_TRIG_H1 = math.ldexp(round(math.ldexp(_TRIG_H, 38)), -38)   # 27 significant bits: k H1 exact for |k| < 2^26
_TRIG_H2 = float(_TRIG_H - Fraction(_TRIG_H1))               # H1 + H2 = 2π/TRIG_TABLE to ~1e-28
_TRIG_ANGLES = np.arange(TRIG_TABLE, dtype=np.longdouble) * (np.longdouble(_TRIG_H1) + np.longdouble(_TRIG_H2))
_TRIG_COS, _TRIG_SIN = np.cos(_TRIG_ANGLES).astype(float), np.sin(_TRIG_ANGLES).astype(float)
_TRIG_INV_H = float(1 / _TRIG_H)
_TRIG_0D = tuple(np.array(c) for c in (_TRIG_INV_H, _TRIG_H1, _TRIG_H2, TRIG_TABLE - 1, -1.0 / 6.0, 1.0, -0.5))


def _sincos_table(x, c, s, K, R, Z, I):   # noqa: E741
    """``c = cos x``, ``s = sin x`` on rows, for ``|x| < TRIG_TABLE_RANGE``; ``K, R, Z`` float, ``I`` int64 scratch rows.

    ``x = k h + r`` with ``h = 2π/TRIG_TABLE``, ``k`` the nearest integer and
    ``|r| ≤ h/2 ≈ 1.9e-4`` (Cody–Waite: ``k h`` in two parts, the first exact);
    ``cos r = 1 - r²/2`` and ``sin r = r (1 - r²/6)`` (truncation below 6e-17,
    a quarter unit of 1), then ``cos x = C_k cos r - S_k sin r``, ``sin x = S_k cos r
    + C_k sin r`` with the tabulated ``C_k, S_k`` (rounded from extended precision;
    2 × 128 kB).  22 elementwise operations (two table lookups), against ~10 ns per
    value for each of libm's ``cos`` and ``sin``; within 2 units of 1 of them.
    """
    mul, sub, add = np.multiply, np.subtract, np.add
    inv_h, h1, h2, mask, sixth, one, half = _TRIG_0D   # constants as 0-d arrays (cheaper operands than floats)
    mul(x, inv_h, K)
    np.rint(K, K)
    mul(K, h1, R)
    sub(x, R, R)
    mul(K, h2, Z)
    sub(R, Z, R)                                   # r
    np.copyto(I, K, casting="unsafe")
    np.bitwise_and(I, mask, I)                     # k mod TRIG_TABLE
    mul(R, R, Z)                                   # r²
    mul(Z, sixth, K)
    add(K, one, K)
    mul(K, R, R)                                   # sin r
    mul(Z, half, Z)
    add(Z, one, Z)                                 # cos r
    np.take(_TRIG_COS, I, out=c, mode="clip")      # (in range: "clip" skips the bounds check)
    np.take(_TRIG_SIN, I, out=s, mode="clip")
    mul(c, R, K)                                   # C_k sin r
    mul(c, Z, c)
    mul(s, R, R)                                   # S_k sin r
    mul(s, Z, s)
    add(s, K, s)
    sub(c, R, c)


def _sincos_numpy(x, c, s):
    """``c = cos x``, ``s = sin x`` on rows by numpy (libm), for angles beyond the table's range."""
    np.cos(x, c)
    np.sin(x, s)


def _batch_source(lines):
    """Python source of the plan ``lines`` (see :func:`_plan_lines`) on rows: ``(source, number of work rows)``.

    The function ``aba_batch(C, q, qd, tau, fe, W, out, sincos)`` takes the
    constants ``C`` (as for the plan), the inputs as sequences of rows (``fe``:
    ``3 N`` rows, x, y, moment of each body), the work rows ``W``, the ``q̈`` rows
    ``out`` and ``sincos(x, cos_out, sin_out)`` on rows; it returns False if the
    singularity test fails.
    """
    # statements: ("let", target, rhs) / ("unpack", targets, source) / ("check", D, trace) / ("return", atoms)
    stmts = []
    for line in lines[1:]:
        for st in line.strip().split("; "):
            if not st or st.startswith(("#", "_singular_plan")):
                continue
            if st.startswith("if not "):
                stmts.append(("check",) + _CHECK.match(st).groups())
            elif st.startswith("return ["):
                stmts.append(("return", [a.strip() for a in st[8:-1].split(",")]))
            else:
                lhs, rhs = st.split(" = ", 1)
                if lhs.endswith(","):
                    stmts.append(("unpack", [t.strip() for t in lhs.split(",") if t.strip()], rhs))
                else:
                    stmts.append(("let", lhs, rhs))
    live, keep = set(), []
    for s in reversed(stmts):   # drop assignments whose value is never read
        if s[0] == "let" and s[1] not in live:
            continue
        if s[0] == "let":
            live.discard(s[1])
        for src in ((s[2],) if s[0] == "let" else s[1:] if s[0] == "check" else s[1] if s[0] == "return" else ()):
            live.update(_NAME.findall(src))
        keep.append(s)
    stmts = keep[::-1]

    # lower to items ("py", source) and ("op", ufunc, result id, operands); an operand is
    # ("v", id) for a value computed in a row, ("x", source) for an input row or a Python float
    env, items, nval, trig = {}, [], [0], {}
    nscal = [0]

    def op(uf, *args):
        nval[0] += 1
        items.append(("op", uf, nval[0], args))
        return ("v", nval[0])

    def lower(node):   # -> (negated, operand, is_row)
        if isinstance(node, ast.Name):
            return (False,) + env[node.id]
        if isinstance(node, ast.Constant):
            return False, ("x", repr(float(node.value))), False
        if isinstance(node, ast.UnaryOp) and isinstance(node.op, ast.USub):
            n, x, row = lower(node.operand)
            return (n, x, True) if row else (False, ("x", f"(-{x[1]})"), False)
        if isinstance(node, ast.Call):
            n, x, row = lower(node.args[0])
            fn = node.func.id[1:]   # _cos / _sin
            if not row:
                return False, ("x", f"_m{fn}({'-' if n else ''}{x[1]})"), False
            if x not in trig:   # cos and sin together, into two rows
                nval[0] += 2
                items.append(("op", "sincos", (nval[0] - 1, nval[0]), (x,)))
                trig[x] = (("v", nval[0] - 1), ("v", nval[0]))
            return (n and fn == "sin"), trig[x][fn == "sin"], True
        nl, l, rl = lower(node.left)
        nr, r, rr = lower(node.right)
        uf, sym = _BINOPS[type(node.op)]
        if not (rl or rr):
            return False, ("x", f"({l[1]} {sym} {r[1]})"), False
        if uf in ("mul", "div"):
            return nl ^ nr, op(uf, l, r), True
        if uf == "sub":
            nr = not nr
        if nl == nr:
            return nl, op("add", l, r), True
        return False, (op("sub", r, l) if nl else op("sub", l, r)), True

    def value(src):
        n, x, row = lower(ast.parse(src, mode="eval").body)
        return (op("neg", x) if n else x), row

    ok = None
    for s in stmts:
        if s[0] == "unpack":
            for t in s[1]:
                env[t] = (("x", t), s[2] != "C")
            items.append(("py", f"{', '.join(s[1])}, = {s[2]}"))
        elif s[0] == "let":
            x, row = value(s[2])
            if not row and x[1] != s[1]:
                nscal[0] += 1
                items.append(("py", f"s{nscal[0]} = {x[1]}"))
                x = ("x", f"s{nscal[0]}")
            env[s[1]] = (x, row)
        elif s[0] == "check":
            (D, drow), (tr, trow) = value(s[1]), value(s[2])
            if not (drow or trow):
                items.append(("py", f"if not {D[1]} > {tr[1]}: return False"))
                continue
            if not drow:   # a constant D (e.g. 0: a point mass on its joint) is tested before 1/D is taken
                items.append(("py", f"if not {D[1]} > 0.0: return False"))
            margin = op("sub", D, tr)
            ok = margin if ok is None else op("minimum", ok, margin)
        else:
            outs = s[1]
    # the returned values are computed in (or copied into) the rows of ``out``
    pinned, defined = {}, {it[2] for it in items if it[0] == "op"}
    for k, src in enumerate(outs):
        x, row = value(src)
        if x[0] == "v" and x[1] in defined and x[1] not in pinned:
            pinned[x[1]] = f"o{k}"
        else:
            items.append(("op", "copyto", None, (x,), f"o{k}"))

    # rows: last reads, then a linear scan
    last = {}
    for j, it in enumerate(items):
        if it[0] == "op":
            for a in it[3]:
                if a[0] == "v":
                    last[a[1]] = j
    if ok is not None:
        last[ok[1]] = len(items)
    reg, free, nreg, body = dict(pinned), [], 0, []
    rows = {t for s in stmts if s[0] == "unpack" and s[2] != "C" for t in s[1]}
    zeros = {}   # Python floats as ufunc operands: 0-d arrays, made once (a float costs ~0.3 µs more per call)

    def name(a):
        if a[0] == "v":
            return reg[a[1]]
        if a[1] in rows:
            return a[1]
        if a[1] not in zeros:
            zeros[a[1]] = f"z{len(zeros)}"
            body.append(f"{zeros[a[1]]} = _0d({a[1]})")
        return zeros[a[1]]

    for j, it in enumerate(items):
        if it[0] == "py":
            body.append(it[1])
            continue
        uf, dst, args = it[1], it[2], it[3]
        srcs = [name(a) for a in args]
        dead = [reg[a] for a in set(a[1] for a in args if a[0] == "v") if last[a] == j and not reg[a].startswith("o")]
        if uf == "copyto":
            body.append(f"copyto({it[4]}, {srcs[0]})")
            free += dead
            continue
        if uf != "sincos":   # one elementwise ufunc: the result may take an operand's row
            free += dead
        dsts = dst if uf == "sincos" else (dst,)
        for d in dsts:
            if d not in reg:
                if free:
                    reg[d] = free.pop()
                else:
                    reg[d] = f"w{nreg}"
                    nreg += 1
        free += [reg[d] for d in dsts if d not in last and d not in pinned]   # never read (a sine without its cosine)
        if uf == "sincos":
            free += dead
            body.append(f"sincos({srcs[0]}, {reg[dst[0]]}, {reg[dst[1]]})")
        else:
            body.append(f"{uf}({', '.join(srcs)}, {'out=' if uf == 'minimum' else ''}{reg[dst]})")
    head = ["def aba_batch(C, q, qd, tau, fe, W, out, sincos):"]
    if nreg:
        head.append("    " + ", ".join(f"w{r}" for r in range(nreg)) + ", = W")
    head.append("    " + ", ".join(f"o{k}" for k in range(len(outs))) + ", = out")
    tail = f"    return {reg[ok[1]]}.min() > 0.0" if ok is not None else "    return True"
    return "\n".join(head + ["    " + b for b in body] + [tail]) + "\n", nreg


def _batch_plan(model: Model, with_fext: bool):
    """The compiled batch function, its flat constants, number of work rows and placement-angle bound (or None).

    Available for the models the single-state plan covers (see :func:`_plan`).
    """
    entry = _plan_entry(model)
    if entry is None or model.nq == 0:
        return None
    (kinds, parents, zero, checks, pack), C = entry
    if pack:
        C = tuple(c for g in C for c in g)
    fkey = (kinds, parents, zero, checks, with_fext)
    entry = _BATCH_PLANS.get(fkey)
    if entry is None:
        if not _compile_now(model, "aba_batch_calls"):
            return None
        if len(_BATCH_PLANS) >= 256:
            _BATCH_PLANS.clear()
        src, nreg = _batch_source(_plan_lines(kinds, parents, zero, with_fext, False, checks))
        ns: dict = {}
        exec(compile(src, f"<aba batch plan N={len(kinds)}>", "exec"), dict(_UFUNC_NS), ns)
        entry = _BATCH_PLANS[fkey] = (ns["aba_batch"], nreg)
    turn = model._arrays.get("aba_turn")
    if turn is None:   # a bound on the placement angles' part of any body's angle
        turn = model._arrays["aba_turn"] = sum(abs(j.placement[2]) for j in model.joints)
    return entry[0], C, entry[1], turn


def _batch(model: Model, plan, q, qd, tau, f_ext, shape):
    """A validated batch through the batched plan, block by block: ``q̈`` (..., nq), or None (see above)."""
    fn, C, nreg, turn = plan
    nq, N = model.nq, model.N
    B = int(np.prod(shape))
    ins = [np.broadcast_to(x, shape + (nq,)).reshape(B, nq) for x in (q, qd, tau)]
    fe = None if f_ext is None else np.broadcast_to(f_ext, shape + (N, 3)).reshape(B, 3 * N)
    most = max(1024, min(BATCH_CHUNK, BATCH_BYTES // (8 * (nreg + 4))))
    n = -(-B // -(-B // most))   # blocks of equal size, at most ``most``
    W, S, I = np.empty((nreg, n)), np.empty((3, n)), np.empty(n, np.int64)   # noqa: E741
    res = np.empty((B, nq))
    with np.errstate(all="ignore"):
        for lo in range(0, B, n):
            k = min(n, B - lo)
            # a block's inputs and q̈ are read and written in place, as strided rows (no copies)
            rows = [x[lo:lo + k].T for x in ins] + [None if fe is None else fe[lo:lo + k].T]
            w, s, i = (W, S, I) if k == n else (W[:, :k], S[:, :k], I[:k])
            qmax = max(rows[0].max(), -rows[0].min())
            if N * qmax + turn < TRIG_TABLE_RANGE:   # every angle (sums of q and placement angles) in the table's range
                def sincos(x, c, si, s=s, i=i):
                    _sincos_table(x, c, si, s[0], s[1], s[2], i)
            else:
                sincos = _sincos_numpy
            if not fn(C, *rows, w, res[lo:lo + k].T, sincos):
                # some state fails the singularity test: the block state by state, as single states run
                single, Cs = _plan(model, fe is not None, force=True)
                ql, qdl, taul = (x[lo:lo + k].tolist() for x in ins)
                fl = [None] * k if fe is None else fe[lo:lo + k].tolist()
                try:
                    res[lo:lo + k] = [single(Cs, *state) for state in zip(ql, qdl, taul, fl)]
                except SingularConfigurationError:
                    raise
                except (ArithmeticError, ValueError):   # overflow (math.cos(inf)...), not a singular state
                    return None
            if not _isfinite(res[lo:lo + k].sum()):
                return None
    return res.reshape(shape + (nq,))


def _single(model: Model, table, q, qd, tau, f_ext) -> np.ndarray:
    """One validated state (float64 arrays (nq,), f_ext (N, 3) or None): the compiled plan or the float loop."""
    plan = _plan(model, f_ext is not None)
    if plan is None:
        return np.array(_aba_components(model, table, q.tolist(), qd.tolist(), tau.tolist(),
                                        None if f_ext is None else f_ext.tolist()))
    return np.array(plan[0](plan[1], q.tolist(), qd.tolist(), tau.tolist(),
                            None if f_ext is None else f_ext.ravel().tolist()))


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
        If some ``s_i^T A_i s_i`` is singular by the package's one rule
        (:data:`planargeo.mechanics.subspaces.COND_LIMIT`: ``‖A_P‖_F ‖s_P‖² / σ_min(sᵀAs) > 1e12``
        at the joint's point ``P``, invariant under moving the whole mechanism), with
        that ``.cond``, for the same states the other recursive methods refuse.

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
    # float64 arrays of one state (or a few): a cheap check (shapes; finite iff the sum is), then the compiled plan
    if (type(q) is _ndarray and type(qd) is _ndarray and type(tau) is _ndarray
            and q.dtype is qd.dtype is tau.dtype is _F64):
        if q.ndim == qd.ndim == tau.ndim == 1:
            if f_ext is None:
                plan = model._arrays.get("aba_plan0")
                if plan is None:
                    plan = _plan(model, False)
                    if plan is not None:
                        model._arrays["aba_plan0"] = plan
                if plan is not None:
                    ql, qdl, taul = q.tolist(), qd.tolist(), tau.tolist()
                    if len(ql) == len(qdl) == len(taul) == model.nq and _isfinite(sum(ql, sum(qdl, sum(taul)))):
                        return _array(plan[0](plan[1], ql, qdl, taul, None))
            elif type(f_ext) is _ndarray and f_ext.dtype is _F64 and f_ext.shape == (model.N, 3):
                plan = _plan(model, True)
                if plan is not None:
                    ql, qdl, taul, fe = q.tolist(), qd.tolist(), tau.tolist(), f_ext.ravel().tolist()
                    if (len(ql) == len(qdl) == len(taul) == model.nq
                            and _isfinite(sum(ql, sum(qdl, sum(taul, sum(fe)))))):
                        return _array(plan[0](plan[1], ql, qdl, taul, fe))
        elif (f_ext is None and q.ndim == 2 and q.shape == qd.shape == tau.shape and q.shape[0] <= SMALL_BATCH
              and q.shape[1] == model.nq):
            plan = model._arrays.get("aba_plan0") or _plan(model, False)   # (B, nq): state by state
            if plan is not None:
                ql, qdl, taul = q.tolist(), qd.tolist(), tau.tolist()
                if _isfinite(sum(map(sum, ql)) + sum(map(sum, qdl)) + sum(map(sum, taul))):
                    fn, C = model._arrays["aba_plan0"] = plan
                    return _array([fn(C, x, y, z, None) for x, y, z in zip(ql, qdl, taul)]).reshape(q.shape)
    q, qd, tau, f_ext, _, shape = check_state(model, q, qd, tau, f_ext)
    table = _scalar_tables(model)
    if table is None:
        return articulated_body(model, q, qd, tau, f_ext).qdd
    if shape == ():   # one state: Python floats
        return _single(model, table, q, qd, tau, f_ext)
    # a batch: one contiguous array per component, batch along the last axis
    nq, N = model.nq, model.N
    B = int(np.prod(shape))
    if B <= SMALL_BATCH:   # numpy's per-call overhead dominates: state by state on floats
        qb, qdb, taub = ((x if x.shape == shape + (nq,) else np.broadcast_to(x, shape + (nq,))).reshape(B, nq).tolist()
                         for x in (q, qd, tau))
        plan = _plan(model, f_ext is not None)
        if plan is None:
            feb = None if f_ext is None else np.broadcast_to(f_ext, shape + (N, 3)).reshape(B, N, 3).tolist()
            res = [_aba_components(model, table, qb[k], qdb[k], taub[k], None if feb is None else feb[k])
                   for k in range(B)]
        else:
            feb = None if f_ext is None else np.broadcast_to(f_ext, shape + (N, 3)).reshape(B, 3 * N).tolist()
            fn, C = plan
            res = [fn(C, qb[k], qdb[k], taub[k], None if feb is None else feb[k]) for k in range(B)]
        return np.array(res).reshape(shape + (nq,))

    plan = _batch_plan(model, f_ext is not None)
    if plan is not None:
        res = _batch(model, plan, q, qd, tau, f_ext, shape)
        if res is not None:
            return res

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
