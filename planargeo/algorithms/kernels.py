"""The compiled recursions: ABA (thesis 3.31-3.42) and RNEA (2.18, 3.10, 3.5), one state at a time or a block.

Plain loops over the bodies on arrays allocated once per call, compiled by numba
(``NUMBA_DISABLE_JIT=1`` runs them as Python).  Each body is taken at its joint's point ``o_i``:
twists move out and wrenches and inertias move in by ``r_i = o_i - o_λ`` (4.8, 4.24, 1.68), so only
offsets enter.  A state kernel returns :data:`OK`, :data:`NOT_FINITE`, or a joint the rule of
:data:`planargeo.errors.COND_LIMIT` refuses (its condition number left in ``w.D``).
"""
from __future__ import annotations

import math
import threading
from collections import namedtuple
from concurrent.futures import ThreadPoolExecutor

import numpy as np
import numba
from numba import get_num_threads, njit

from planargeo.errors import COND_LIMIT
from planargeo.mechanics.subspaces import COND_LIMIT2

__all__ = ["FIXED", "REVOLUTE", "PRISMATIC", "BLOCK", "OK", "NOT_FINITE", "tables", "workspace",
           "kinematics_state", "articulated_body_state", "columns", "articulated_body_block", "newton_euler_state", "dynamics_one",
           "dynamics_many", "singular_joint"]

FIXED, REVOLUTE, PRISMATIC = 0, 1, 2
_CODES = {"fixed": FIXED, "revolute": REVOLUTE, "prismatic": PRISMATIC}
#: what a state kernel returns when it succeeded, and when an input or the result is not finite
OK, NOT_FINITE = -1, -2
#: states per block of a batch (:func:`articulated_body_block`); large batches are shared among threads in runs of blocks
BLOCK = 256

jit = njit(cache=True, nogil=True, error_model="numpy")
inline = njit(cache=True, nogil=True, error_model="numpy", inline="always")
#: numba checks the types of a one-state call; run as Python (``NUMBA_DISABLE_JIT=1``), nothing does
TYPED = not numba.config.DISABLE_JIT
if not TYPED:                   # as Python, a float error gives inf or nan silently, as compiled
    jit = inline = np.errstate(divide="ignore", invalid="ignore", over="ignore")

#: Parameter entries the kernels' docstrings share (:func:`_doc`).
_PARAMETERS = {"{tables}": """kind, parent : numpy.ndarray of int, shape (N,)
        Joint kind codes and parent indices (:func:`tables`).
    body, gravity : numpy.ndarray, shapes (N, 8), (2,)
        Per body its joint placement ``(x, y, cos φ, sin φ)``, mass, centre of mass, inertia;
        gravity (m/s²).""",
               "{model}": """model : tuple
        The model's :func:`tables`.
    q, qd : numpy.ndarray, shape (nq,)
        Joint positions and velocities (float64).""",
               "{scratch}": """{fext}
    w : Workspace
        Scratch arrays from :func:`workspace`, filled in place.""",
               "{fext}": """fext : numpy.ndarray, shape (N, 3) or None
        External world wrenches at the origin."""}


def _doc(f):
    """``f`` with the shared parameters written into its docstring (:data:`_PARAMETERS`)."""
    for key, text in _PARAMETERS.items():
        f.__doc__ = f.__doc__.replace(key, text)
    return f


#: Per-state arrays, one row per body at its joint point: ``origin`` ``o_i``, ``r = o_i - o_λ``,
#: ``frame`` (origin less ``o_i``, cos θ, sin θ), ``s``, ``v`` (3.32), ``kappa`` (3.33), ``I`` (then
#: ``A``), ``p`` (3.34; then ``d`` or ``f``), ``U = A s``, ``D = sᵀAs``, ``u = τ - sᵀ(Aκ + d)``,
#: ``a`` (3.42, 2.18).
Workspace = namedtuple("Workspace", "origin r frame s v kappa I p U D u a")


def tables(model):
    """The model as the kernels' arrays ``(kind, parent, body, gravity)``, or None if a joint is of another kind.

    Parameters
    ----------
    model : Model
        The mechanism.

    Returns
    -------
    tuple or None
        ``(kind, parent, body, gravity)``; None where a joint is of another kind.

    Examples
    --------
    >>> from planargeo.mechanics.model import chain_model
    >>> tables(chain_model(2))[:2]
    (array([1, 1]), array([-1,  0]))
    """
    if not all(j.kind in _CODES for j in model.joints):
        return None
    kind = np.array([_CODES[j.kind] for j in model.joints], dtype=np.int64)
    parent = np.array(model.parents, dtype=np.int64)
    body = np.array([[j.placement[0], j.placement[1], math.cos(j.placement[2]), math.sin(j.placement[2]),
                      b.mass, b.com[0], b.com[1], b.inertia] for b, j in zip(model.bodies, model.joints)])
    return kind, parent, body, np.array(model.gravity, dtype=float)


@inline
def workspace(N):
    """Fresh, uninitialised :data:`Workspace` arrays for one state of an ``N``-body model.

    Parameters
    ----------
    N : int
        Number of bodies.

    Returns
    -------
    Workspace
    """
    return Workspace(np.empty((N, 2)), np.empty((N, 2)), np.empty((N, 4)), np.empty((N, 3)), np.empty((N, 3)),
                     np.empty((N, 3)), np.empty((N, 3, 3)), np.empty((N, 3)), np.empty((N, 3)), np.empty(N),
                     np.empty(N), np.empty((N, 3)))


@inline
def _finite(x):
    """Whether every entry of the vector ``x`` is finite."""
    for k in range(x.shape[0]):
        if not math.isfinite(x[k]):
            return False
    return True


@inline
def _finite_inputs(x, y, z, fext):
    """Whether the vectors ``x, y, z`` and the (N, 3) wrenches ``fext`` (or None) are finite."""
    if not (_finite(x) and _finite(y) and _finite(z)):
        return False
    if fext is not None:
        for i in range(fext.shape[0]):
            if not (math.isfinite(fext[i, 0]) and math.isfinite(fext[i, 1]) and math.isfinite(fext[i, 2])):
                return False
    return True


@jit
@_doc
def kinematics_state(model, q, qd, fext, w):
    """Joint points, joint twists, velocities, bias terms and inertias of every body, base to tip (thesis 3.31-3.34).

    Fills ``w.origin, w.r, w.frame, w.s, w.v, w.kappa, w.I, w.p``, each body at its joint's point.

    Parameters
    ----------
    {model}
    {scratch}
    """
    kind, parent, body, gravity = model
    k = 0                                           # the next joint coordinate
    for i in range(len(kind)):
        px, py, cp, sp = body[i, 0], body[i, 1], body[i, 2], body[i, 3]
        m, bx, by, J = body[i, 4], body[i, 5], body[i, 6], body[i, 7]
        lam = parent[i]
        if lam < 0:                                 # v_0 = 0 (3.31): the ground, at the world origin
            rx, ry, c, s = px, py, cp, sp
            ox, oy = px, py
            vx = vy = w_ = 0.0
        else:                                       # the joint's point, placed in the parent's frame
            lx, ly, cl, sl = w.frame[lam, 0], w.frame[lam, 1], w.frame[lam, 2], w.frame[lam, 3]
            rx, ry = lx + cl * px - sl * py, ly + sl * px + cl * py
            c, s = cl * cp - sl * sp, sl * cp + cl * sp
            ox, oy = w.origin[lam, 0] + rx, w.origin[lam, 1] + ry
            w_ = w.v[lam, 2]                        # v_λ moved out to o_i (4.8)
            vx, vy = w.v[lam, 0] - ry * w_, w.v[lam, 1] + rx * w_
        w.origin[i, 0], w.origin[i, 1], w.r[i, 0], w.r[i, 1] = ox, oy, rx, ry
        qdi = ex = ey = 0.0                         # (ex, ey): the body frame's origin less o_i
        if kind[i] == REVOLUTE:                     # s = [0, 0, 1]: a rotation about o_i (4.10)
            qi, qdi = q[k], qd[k]
            w.s[i, 0], w.s[i, 1], w.s[i, 2] = 0.0, 0.0, 1.0
            cq, sq = math.cos(qi), math.sin(qi)
            c, s = c * cq - s * sq, s * cq + c * sq
            k += 1
        elif kind[i] == PRISMATIC:                  # s = [c, s, 0]: the direction of sliding, a point at infinity
            qi, qdi = q[k], qd[k]
            w.s[i, 0], w.s[i, 1], w.s[i, 2] = c, s, 0.0
            ex, ey = qi * c, qi * s
            k += 1
        else:                                       # fixed: no motion
            w.s[i, 0] = w.s[i, 1] = w.s[i, 2] = 0.0
        w.frame[i, 0], w.frame[i, 1], w.frame[i, 2], w.frame[i, 3] = ex, ey, c, s
        # v_i = v_λ + s_i q̇_i (3.32);  κ_i = v_i × s_i q̇_i = v_λ × s_i q̇_i (3.33, 2.16)
        s0, s1, s2 = w.s[i, 0] * qdi, w.s[i, 1] * qdi, w.s[i, 2] * qdi
        w.kappa[i, 0], w.kappa[i, 1], w.kappa[i, 2] = -w_ * s1 + vy * s2, w_ * s0 - vx * s2, 0.0
        vx, vy, w_ = vx + s0, vy + s1, w_ + s2
        w.v[i, 0], w.v[i, 1], w.v[i, 2] = vx, vy, w_
        # I_i from the centre of mass (cx, cy) relative to o_i (4.58)
        cx, cy = ex + c * bx - s * by, ey + s * bx + c * by
        I = w.I
        I[i, 0, 0], I[i, 0, 1], I[i, 0, 2] = m, 0.0, -m * cy
        I[i, 1, 0], I[i, 1, 1], I[i, 1, 2] = 0.0, m, m * cx
        I[i, 2, 0], I[i, 2, 1], I[i, 2, 2] = -m * cy, m * cx, J + m * (cx * cx + cy * cy)
        # p_i = -(v_i×)ᵀ I_i v_i - g_i (3.34): g_i gravity at the centre of mass, plus f_ext moved to o_i (4.24)
        h0, h1 = m * vx - m * cy * w_, m * vy + m * cx * w_          # the momentum I_i v_i (its moment unused)
        gx, gy = m * gravity[0], m * gravity[1]
        w.p[i, 0] = -w_ * h1 - gx
        w.p[i, 1] = w_ * h0 - gy
        w.p[i, 2] = vx * h1 - vy * h0 - (cx * gy - cy * gx)
        if fext is not None:
            w.p[i, 0] -= fext[i, 0]
            w.p[i, 1] -= fext[i, 1]
            w.p[i, 2] -= fext[i, 2] + oy * fext[i, 0] - ox * fext[i, 1]


@jit
def joint_cond(A, s, D):
    """``‖A‖_F ‖s‖² / |D|``, the rule of ``COND_LIMIT`` at the joint's point, scale-safe.

    ``inf`` when ``D = sᵀAs`` is 0, NaN when ``A`` or ``D`` is not finite.
    """
    big = 0.0
    for j in range(3):
        for k in range(3):
            big = max(big, abs(A[j, k]))
    if not (math.isfinite(big) and math.isfinite(D)):
        return math.nan
    if big == 0.0 or D == 0.0:
        return math.inf
    F2 = 0.0
    for j in range(3):
        for k in range(3):
            F2 += (A[j, k] / big) ** 2
    return big * math.sqrt(F2) * (s[0] * s[0] + s[1] * s[1] + s[2] * s[2]) / abs(D)


@inline
def _parent_acceleration(a, r, lam, i):
    """The parent's acceleration ``a_λ`` moved out to body ``i``'s joint point by ``r_i`` (4.8); ``a_0 = 0`` (3.40)."""
    if lam < 0:
        return 0.0, 0.0, 0.0
    a2 = a[lam, 2]
    return a[lam, 0] - r[i, 1] * a2, a[lam, 1] + r[i, 0] * a2, a2


@jit
@_doc
def articulated_body_state(model, q, qd, tau, fext, w, qdd):
    """The recursive algorithm (thesis 3.6, 3.31-3.42) for one state: writes ``q̈`` into ``qdd``.

    Parameters
    ----------
    {model}
    tau : numpy.ndarray, shape (nq,)
        Joint forces.
    {scratch}
    qdd : numpy.ndarray, shape (nq,)
        Output: joint accelerations.

    Returns
    -------
    int
        :data:`OK`, :data:`NOT_FINITE`, or the first joint (tip to base) the rule refuses.
    """
    if not _finite_inputs(q, qd, tau, fext):
        return NOT_FINITE
    kinematics_state(model, q, qd, fext, w)                       # 2. kinematics (3.31-3.34)
    kind, parent = model[0], model[1]
    r, s, kappa, U, u, a = w.r, w.s, w.kappa, w.U, w.u, w.a
    A, d = w.I, w.p           # A_i, d_i start as I_i, p_i (3.35, 3.36) and collect the children in place
    # 3. articulated inertias and bias forces, tip to base (3.37-3.39)
    k = q.shape[0]
    for i in range(len(kind) - 1, -1, -1):
        c0 = A[i, 0, 0] * kappa[i, 0] + A[i, 0, 1] * kappa[i, 1] + A[i, 0, 2] * kappa[i, 2] + d[i, 0]   # c = A κ + d
        c1 = A[i, 1, 0] * kappa[i, 0] + A[i, 1, 1] * kappa[i, 1] + A[i, 1, 2] * kappa[i, 2] + d[i, 1]
        c2 = A[i, 2, 0] * kappa[i, 0] + A[i, 2, 1] * kappa[i, 1] + A[i, 2, 2] * kappa[i, 2] + d[i, 2]
        B00, B01, B02 = A[i, 0, 0], A[i, 0, 1], A[i, 0, 2]   # B: what the parent receives, at o_i
        B11, B12, B22 = A[i, 1, 1], A[i, 1, 2], A[i, 2, 2]
        if kind[i] != FIXED:                                # a weld passes on A_i and c whole
            k -= 1
            for j in range(3):                              # U = A_i s_i, D = s_iᵀ A_i s_i
                U[i, j] = A[i, j, 0] * s[i, 0] + A[i, j, 1] * s[i, 1] + A[i, j, 2] * s[i, 2]
            D = s[i, 0] * U[i, 0] + s[i, 1] * U[i, 1] + s[i, 2] * U[i, 2]
            # ‖A‖_F² ‖s‖⁴ < D² COND_LIMIT²: the rule squared where in range; else the exact rule
            F2 = A[i, 0, 0] ** 2 + A[i, 1, 1] ** 2 + A[i, 2, 2] ** 2 + 2.0 * (
                A[i, 0, 1] ** 2 + A[i, 0, 2] ** 2 + A[i, 1, 2] ** 2)
            ss = s[i, 0] * s[i, 0] + s[i, 1] * s[i, 1] + s[i, 2] * s[i, 2]
            if not (1e-300 < F2 < 1e300 and F2 * ss * ss < D * D * COND_LIMIT2):
                cond = joint_cond(A[i], s[i], D)
                if math.isnan(cond):                                # the inertia is out of the float range
                    return NOT_FINITE
                if not cond <= COND_LIMIT:
                    w.D[i] = cond
                    return i
            w.D[i] = D
            u[i] = tau[k] - (s[i, 0] * c0 + s[i, 1] * c1 + s[i, 2] * c2)   # u = τ_i - s_iᵀ (A_i κ_i + d_i)
            # s⁺ = D⁻¹ Uᵀ (3.37): (1 - s s⁺)ᵀ A_i = A_i - U Wᵀ (3.38) and
            # (s⁺)ᵀ τ_i + (1 - s s⁺)ᵀ (A_i κ_i + d_i) = c + W u (3.39), with W = U / D; so formed, the
            # part along s is exactly 0 where s is a unit axis (a revolute joint: W_2 = U_2 / D = 1)
            W0, W1, W2 = U[i, 0] / D, U[i, 1] / D, U[i, 2] / D
            B00, B01, B02 = B00 - U[i, 0] * W0, B01 - U[i, 0] * W1, B02 - U[i, 0] * W2
            B11, B12, B22 = B11 - U[i, 1] * W1, B12 - U[i, 1] * W2, B22 - U[i, 2] * W2
            c0, c1, c2 = c0 + W0 * u[i], c1 + W1 * u[i], c2 + W2 * u[i]
        lam = parent[i]
        if lam >= 0:             # moved in by r = o_i - o_λ: wrenches (4.24), inertias X_rᵀ B X_r (1.68)
            rx, ry = r[i, 0], r[i, 1]
            M02, M12 = B02 - ry * B00 + rx * B01, B12 - ry * B01 + rx * B11
            M22 = B22 - ry * B02 + rx * B12 - ry * M02 + rx * M12
            A[lam, 0, 0] += B00
            A[lam, 0, 1] += B01
            A[lam, 1, 0] += B01
            A[lam, 1, 1] += B11
            A[lam, 0, 2] += M02
            A[lam, 2, 0] += M02
            A[lam, 1, 2] += M12
            A[lam, 2, 1] += M12
            A[lam, 2, 2] += M22
            d[lam, 0] += c0
            d[lam, 1] += c1
            d[lam, 2] += c2 - ry * c0 + rx * c1
    # 4. joint accelerations, base to tip (3.40-3.42)
    for i in range(len(kind)):
        a0, a1, a2 = _parent_acceleration(a, r, parent[i], i)
        if kind[i] != FIXED:                                # q̈_i = D⁻¹ (u - Uᵀ a_λ) (3.41)
            qi = (u[i] - (U[i, 0] * a0 + U[i, 1] * a1 + U[i, 2] * a2)) / w.D[i]
            qdd[k] = qi
            k += 1
            a0, a1, a2 = a0 + s[i, 0] * qi, a1 + s[i, 1] * qi, a2 + s[i, 2] * qi
        a[i, 0], a[i, 1], a[i, 2] = a0 + kappa[i, 0], a1 + kappa[i, 1], a2 + kappa[i, 2]   # (3.42)
    return OK if _finite(qdd) else NOT_FINITE


@jit
@_doc
def newton_euler_state(model, q, qd, qdd, fext, w, tau):
    """Inverse dynamics (thesis 2.18, 3.10, 3.5) for one state: writes ``τ`` into ``tau``.

    Accelerations base to tip (2.18), then forces tip to base (3.10), moved in to ``o_λ`` (4.24).

    Parameters
    ----------
    {model}
    qdd, tau : numpy.ndarray, shape (nq,)
        Joint accelerations; the output, joint forces.
    {scratch}

    Returns
    -------
    int
        :data:`OK` or :data:`NOT_FINITE`.
    """
    if not _finite_inputs(q, qd, qdd, fext):
        return NOT_FINITE
    kinematics_state(model, q, qd, fext, w)
    kind, parent = model[0], model[1]
    r, s, kappa, I, a = w.r, w.s, w.kappa, w.I, w.a
    f = w.p                   # f_i = I_i a_i + p_i + Σ f_children (3.10), collected in place of p_i
    k = 0
    for i in range(len(kind)):                              # a_i = a_λ + s_i q̈_i + κ_i (2.18)
        a0, a1, a2 = _parent_acceleration(a, r, parent[i], i)
        if kind[i] != FIXED:
            a0, a1, a2 = a0 + s[i, 0] * qdd[k], a1 + s[i, 1] * qdd[k], a2 + s[i, 2] * qdd[k]
            k += 1
        a0, a1, a2 = a0 + kappa[i, 0], a1 + kappa[i, 1], a2 + kappa[i, 2]
        a[i, 0], a[i, 1], a[i, 2] = a0, a1, a2
        for j in range(3):
            f[i, j] += I[i, j, 0] * a0 + I[i, j, 1] * a1 + I[i, j, 2] * a2
    for i in range(len(kind) - 1, -1, -1):                  # tip to base: τ_i = s_iᵀ f_i (3.5)
        if kind[i] != FIXED:
            k -= 1
            tau[k] = s[i, 0] * f[i, 0] + s[i, 1] * f[i, 1] + s[i, 2] * f[i, 2]
        lam = parent[i]
        if lam >= 0:                                        # f_i moved in to o_λ (4.24)
            f[lam, 0] += f[i, 0]
            f[lam, 1] += f[i, 1]
            f[lam, 2] += f[i, 2] - r[i, 1] * f[i, 0] + r[i, 0] * f[i, 1]
    return OK if _finite(tau) else NOT_FINITE


# -- entry points: the model's tables as separate arrays (cheaper to pass), one state or a batch ---
@jit
@_doc
def dynamics_one(inverse, kind, parent, body, gravity, q, qd, z, fext):
    """``q̈`` (forward, ``z = τ``) or ``τ`` (``inverse``, ``z = q̈``) of one state; None if not :data:`OK`.

    Parameters
    ----------
    inverse : bool
        Inverse dynamics instead of forward.
    {tables}
    q, qd, z : numpy.ndarray, shape (nq,)
        Joint positions, velocities, and forces (forward) or accelerations (inverse).
    {fext}

    Returns
    -------
    numpy.ndarray, shape (nq,) or None
    """
    nq = 0                                          # the one-state shapes: (nq,) and (N, 3) or None
    for i in range(kind.shape[0]):
        if kind[i] != FIXED:
            nq += 1
    if q.shape[0] != nq or qd.shape[0] != nq or z.shape[0] != nq:
        return None
    if fext is not None and not (fext.shape[0] == kind.shape[0] and fext.shape[1] == 3):
        return None
    out = np.empty(q.shape[0])
    model, w = (kind, parent, body, gravity), workspace(kind.shape[0])
    if inverse:
        status = newton_euler_state(model, q, qd, z, fext, w, out)
    else:
        status = articulated_body_state(model, q, qd, z, fext, w, out)
    return out if status == OK else None


@jit
@_doc
def singular_joint(kind, parent, body, gravity, q, qd, tau, fext):
    """``(joint, cond)`` of the first joint of the state the singularity rule refuses, or ``(-1, 0.0)``.

    Parameters
    ----------
    {tables}
    q, qd, tau : numpy.ndarray, shape (nq,)
        Joint positions, velocities and forces.
    {fext}

    Returns
    -------
    tuple
    """
    w = workspace(kind.shape[0])
    status = articulated_body_state((kind, parent, body, gravity), q, qd, tau, fext, w, np.empty(q.shape[0]))
    return (status, w.D[status]) if status >= 0 else (-1, 0.0)


#: Per-block arrays, the block's states innermost (they vectorise); one row more than bodies, the
#: last (parent -1) the ground at rest.  ``x, y, z, out`` (nq, BLOCK); ``A``, ``B`` upper triangles
#: ``A00 A01 A02 A11 A12 A22``; ``c`` (3.39); ``sq = s q̇``; ``ok``: passed the quick singular test
Columns = namedtuple("Columns", "x y z out origin r frame s sq v kappa A d U D u a c B ok")


@inline
def columns(N, nq, L):
    """Fresh :data:`Columns` for blocks of up to ``L`` states, ``N`` bodies, ``nq`` coordinates; the ground row at rest.

    Parameters
    ----------
    N, nq, L : int
        Numbers of bodies, coordinates and states per block.

    Returns
    -------
    Columns
    """
    w = Columns(np.empty((nq, L)), np.empty((nq, L)), np.empty((nq, L)), np.empty((nq, L)),
                np.zeros((N + 1, 2, L)), np.empty((N, 2, L)), np.zeros((N + 1, 4, L)), np.empty((N, 3, L)),
                np.empty((3, L)), np.zeros((N + 1, 3, L)), np.empty((N, 3, L)), np.empty((N + 1, 6, L)),
                np.empty((N + 1, 3, L)), np.empty((N, 3, L)), np.empty((N, L)), np.empty((N, L)),
                np.zeros((N + 1, 3, L)), np.empty((3, L)), np.empty((6, L)), np.empty(L, dtype=np.bool_))
    w.frame[N, 2] = 1.0                             # the ground's frame: cos θ = 1
    return w


@jit
def articulated_body_block(model, q, qd, tau, fext, lo, hi, w, qdd):
    """:func:`articulated_body_state` for the states ``lo:hi`` (at most :data:`BLOCK`) at once (thesis 3.31-3.42).

    Parameters
    ----------
    model : tuple
        The model's :func:`tables`.
    q, qd, tau, qdd : numpy.ndarray, shape (B, nq)
        Joint positions, velocities and forces of B states; the output, joint accelerations.
    fext : numpy.ndarray, shape (B, N, 3) or None
        External world wrenches at the origin.
    lo, hi : int
        The block's states ``lo:hi``.
    w : Columns
        Scratch arrays from :func:`columns`.

    Returns
    -------
    bool
        Whether every state succeeded with the numbers it gets alone; else the caller reruns the block.
    """
    kind, parent, body, gravity = model
    n, N = hi - lo, kind.shape[0]
    x, y, z, origin, r, frame, s, sq, v, kappa = w.x, w.y, w.z, w.origin, w.r, w.frame, w.s, w.sq, w.v, w.kappa
    A, d, U, D, u, a, c, B, ok = w.A, w.d, w.U, w.D, w.u, w.a, w.c, w.B, w.ok
    finite = True
    for b in range(n):                              # the states' coordinates as columns
        for k in range(q.shape[1]):
            x[k, b], y[k, b], z[k, b] = q[lo + b, k], qd[lo + b, k], tau[lo + b, k]
            finite &= math.isfinite(x[k, b]) & math.isfinite(y[k, b]) & math.isfinite(z[k, b])
        if fext is not None:
            for i in range(N):
                finite &= (math.isfinite(fext[lo + b, i, 0]) & math.isfinite(fext[lo + b, i, 1])
                           & math.isfinite(fext[lo + b, i, 2]))
    if not finite:
        return False
    # 2. kinematics, base to tip (3.31-3.34; kinematics_state)
    k = 0
    for i in range(N):
        px, py, cp, sp = body[i, 0], body[i, 1], body[i, 2], body[i, 3]
        m, bx, by, J = body[i, 4], body[i, 5], body[i, 6], body[i, 7]
        lam = parent[i]
        for b in range(n):                          # the joint's point, placed in the parent's frame
            lx, ly, cl, sl = frame[lam, 0, b], frame[lam, 1, b], frame[lam, 2, b], frame[lam, 3, b]
            rx, ry = lx + cl * px - sl * py, ly + sl * px + cl * py
            r[i, 0, b], r[i, 1, b] = rx, ry
            frame[i, 2, b], frame[i, 3, b] = cl * cp - sl * sp, sl * cp + cl * sp
            origin[i, 0, b], origin[i, 1, b] = origin[lam, 0, b] + rx, origin[lam, 1, b] + ry
            w_ = v[lam, 2, b]                       # v_λ moved out to o_i (4.8)
            v[i, 0, b], v[i, 1, b], v[i, 2, b] = v[lam, 0, b] - ry * w_, v[lam, 1, b] + rx * w_, w_
        if kind[i] == REVOLUTE:                     # s = [0, 0, 1]: a rotation about o_i (4.10)
            for b in range(n):
                c_, s_ = frame[i, 2, b], frame[i, 3, b]
                cq, sq_ = math.cos(x[k, b]), math.sin(x[k, b])
                frame[i, 0, b], frame[i, 1, b] = 0.0, 0.0
                frame[i, 2, b], frame[i, 3, b] = c_ * cq - s_ * sq_, s_ * cq + c_ * sq_
                s[i, 0, b], s[i, 1, b], s[i, 2, b] = 0.0, 0.0, 1.0
                sq[0, b], sq[1, b], sq[2, b] = 0.0 * y[k, b], 0.0 * y[k, b], 1.0 * y[k, b]
            k += 1
        elif kind[i] == PRISMATIC:                  # s = [c, s, 0]: the direction of sliding
            for b in range(n):
                c_, s_ = frame[i, 2, b], frame[i, 3, b]
                frame[i, 0, b], frame[i, 1, b] = x[k, b] * c_, x[k, b] * s_
                s[i, 0, b], s[i, 1, b], s[i, 2, b] = c_, s_, 0.0
                sq[0, b], sq[1, b], sq[2, b] = c_ * y[k, b], s_ * y[k, b], 0.0 * y[k, b]
            k += 1
        else:                                       # fixed: no motion
            for b in range(n):
                frame[i, 0, b] = frame[i, 1, b] = 0.0
                s[i, 0, b] = s[i, 1, b] = s[i, 2, b] = 0.0
                sq[0, b] = sq[1, b] = sq[2, b] = 0.0
        for b in range(n):
            vx, vy, w_ = v[i, 0, b], v[i, 1, b], v[i, 2, b]
            s0, s1, s2 = sq[0, b], sq[1, b], sq[2, b]
            # v_i = v_λ + s_i q̇_i (3.32);  κ_i = v_λ × s_i q̇_i (3.33, 2.16)
            kappa[i, 0, b], kappa[i, 1, b], kappa[i, 2, b] = -w_ * s1 + vy * s2, w_ * s0 - vx * s2, 0.0
            vx, vy, w_ = vx + s0, vy + s1, w_ + s2
            v[i, 0, b], v[i, 1, b], v[i, 2, b] = vx, vy, w_
            ex, ey, c_, s_ = frame[i, 0, b], frame[i, 1, b], frame[i, 2, b], frame[i, 3, b]
            cx, cy = ex + c_ * bx - s_ * by, ey + s_ * bx + c_ * by          # I_i (4.58)
            A[i, 0, b], A[i, 1, b], A[i, 2, b] = m, 0.0, -m * cy
            A[i, 3, b], A[i, 4, b], A[i, 5, b] = m, m * cx, J + m * (cx * cx + cy * cy)
            h0, h1 = m * vx - m * cy * w_, m * vy + m * cx * w_              # p_i (3.34)
            gx, gy = m * gravity[0], m * gravity[1]
            d[i, 0, b] = -w_ * h1 - gx
            d[i, 1, b] = w_ * h0 - gy
            d[i, 2, b] = vx * h1 - vy * h0 - (cx * gy - cy * gx)
        if fext is not None:
            for b in range(n):
                f0, f1, f2 = fext[lo + b, i, 0], fext[lo + b, i, 1], fext[lo + b, i, 2]
                d[i, 0, b] -= f0
                d[i, 1, b] -= f1
                d[i, 2, b] -= f2 + origin[i, 1, b] * f0 - origin[i, 0, b] * f1
    # 3. articulated inertias and bias forces, tip to base (3.37-3.39)
    for b in range(n):
        ok[b] = True
    for i in range(N - 1, -1, -1):
        for b in range(n):                          # c = A κ + d
            k0, k1, k2 = kappa[i, 0, b], kappa[i, 1, b], kappa[i, 2, b]
            c[0, b] = A[i, 0, b] * k0 + A[i, 1, b] * k1 + A[i, 2, b] * k2 + d[i, 0, b]
            c[1, b] = A[i, 1, b] * k0 + A[i, 3, b] * k1 + A[i, 4, b] * k2 + d[i, 1, b]
            c[2, b] = A[i, 2, b] * k0 + A[i, 4, b] * k1 + A[i, 5, b] * k2 + d[i, 2, b]
            for j in range(6):
                B[j, b] = A[i, j, b]
        if kind[i] != FIXED:
            k -= 1
            for b in range(n):
                A00, A01, A02, A11, A12, A22 = A[i, 0, b], A[i, 1, b], A[i, 2, b], A[i, 3, b], A[i, 4, b], A[i, 5, b]
                s0, s1, s2 = s[i, 0, b], s[i, 1, b], s[i, 2, b]
                U0 = A00 * s0 + A01 * s1 + A02 * s2                     # U = A_i s_i, D = s_iᵀ A_i s_i
                U1 = A01 * s0 + A11 * s1 + A12 * s2
                U2 = A02 * s0 + A12 * s1 + A22 * s2
                Di = s0 * U0 + s1 * U1 + s2 * U2
                F2 = A00 ** 2 + A11 ** 2 + A22 ** 2 + 2.0 * (A01 ** 2 + A02 ** 2 + A12 ** 2)   # the quick rule
                ss = s0 * s0 + s1 * s1 + s2 * s2
                ok[b] &= (1e-300 < F2) & (F2 < 1e300) & (F2 * ss * ss < Di * Di * COND_LIMIT2)
                ui = z[k, b] - (s0 * c[0, b] + s1 * c[1, b] + s2 * c[2, b])   # u = τ_i - s_iᵀ c
                W0, W1, W2 = U0 / Di, U1 / Di, U2 / Di                       # (3.38), (3.39)
                B[0, b], B[1, b], B[2, b] = A00 - U0 * W0, A01 - U0 * W1, A02 - U0 * W2
                B[3, b], B[4, b], B[5, b] = A11 - U1 * W1, A12 - U1 * W2, A22 - U2 * W2
                c[0, b], c[1, b], c[2, b] = c[0, b] + W0 * ui, c[1, b] + W1 * ui, c[2, b] + W2 * ui
                U[i, 0, b], U[i, 1, b], U[i, 2, b], D[i, b], u[i, b] = U0, U1, U2, Di, ui
        lam = parent[i]
        for b in range(n):                          # moved in by r = o_i - o_λ (4.24, 1.68)
            rx, ry = r[i, 0, b], r[i, 1, b]
            B00, B01, B02, B11, B12, B22 = B[0, b], B[1, b], B[2, b], B[3, b], B[4, b], B[5, b]
            M02, M12 = B02 - ry * B00 + rx * B01, B12 - ry * B01 + rx * B11
            A[lam, 0, b] += B00
            A[lam, 1, b] += B01
            A[lam, 3, b] += B11
            A[lam, 2, b] += M02
            A[lam, 4, b] += M12
            A[lam, 5, b] += B22 - ry * B02 + rx * B12 - ry * M02 + rx * M12
            d[lam, 0, b] += c[0, b]
            d[lam, 1, b] += c[1, b]
            d[lam, 2, b] += c[2, b] - ry * c[0, b] + rx * c[1, b]
    # 4. joint accelerations, base to tip (3.40-3.42)
    for i in range(N):
        lam = parent[i]
        for b in range(n):                          # a_λ moved out to o_i (4.8); a_0 = 0 (3.40)
            a2 = a[lam, 2, b]
            a[i, 0, b], a[i, 1, b], a[i, 2, b] = a[lam, 0, b] - r[i, 1, b] * a2, a[lam, 1, b] + r[i, 0, b] * a2, a2
        if kind[i] != FIXED:
            for b in range(n):                      # q̈_i = D⁻¹ (u - Uᵀ a_λ) (3.41)
                qi = (u[i, b] - (U[i, 0, b] * a[i, 0, b] + U[i, 1, b] * a[i, 1, b] + U[i, 2, b] * a[i, 2, b])) / D[i, b]
                w.out[k, b] = qi
                a[i, 0, b] += s[i, 0, b] * qi
                a[i, 1, b] += s[i, 1, b] * qi
                a[i, 2, b] += s[i, 2, b] * qi
            k += 1
        for b in range(n):                          # (3.42)
            a[i, 0, b] += kappa[i, 0, b]
            a[i, 1, b] += kappa[i, 1, b]
            a[i, 2, b] += kappa[i, 2, b]
    for b in range(n):
        finite &= ok[b]
        for k in range(q.shape[1]):
            qdd[lo + b, k] = w.out[k, b]
            finite &= math.isfinite(w.out[k, b])
    return finite


@jit
def _block(inverse, model, x, y, z, fext, out, lo, hi):
    """One state kernel on the rows ``lo:hi`` into ``out``; the first state that failed, or ``hi``."""
    w = workspace(model[0].shape[0])
    for b in range(lo, hi):
        f = fext[b] if fext is not None else None
        if inverse:
            status = newton_euler_state(model, x[b], y[b], z[b], f, w, out[b])
        else:
            status = articulated_body_state(model, x[b], y[b], z[b], f, w, out[b])
        if status != OK:
            return b
    return hi


@jit
def _range(inverse, model, x, y, z, fext, out, lo, hi):
    """The states ``lo:hi`` (forward: a :data:`BLOCK` at a time); the first failure, or ``hi``."""
    if inverse or hi - lo == 1:                     # (one state: its columns would cost more than the kernel)
        return _block(inverse, model, x, y, z, fext, out, lo, hi)
    w = columns(model[0].shape[0], x.shape[1], min(BLOCK, hi - lo))
    for start in range(lo, hi, BLOCK):
        stop = min(hi, start + BLOCK)
        if not articulated_body_block(model, x, y, z, fext, start, stop, w, out):
            b = _block(inverse, model, x, y, z, fext, out, start, stop)
            if b < stop:
                return b
    return hi


#: batches of fewer states run on the calling thread alone: handing them to threads costs more than it saves
PARALLEL_STATES = 4 * BLOCK
#: the threads that share a large batch (``NUMBA_NUM_THREADS`` of them), started on first use
_POOL = []
_POOL_LOCK = threading.Lock()


@_doc
def dynamics_many(inverse, kind, parent, body, gravity, x, y, z, fext):
    """``(out, declined)`` of B states, :func:`dynamics_one` of each; ``declined`` is -1 or the first failed state.

    Large batches run on Python's threads, which sleep while they wait (numba's OpenMP ones spin:
    3× slower on a busy 2-core machine).

    Parameters
    ----------
    inverse : bool
        Inverse dynamics instead of forward.
    {tables}
    x, y, z : numpy.ndarray, shape (B, nq)
        Joint positions, velocities, and forces (forward) or accelerations (inverse).
    fext : numpy.ndarray, shape (B, N, 3) or None
        External world wrenches at the origin.

    Returns
    -------
    tuple
    """
    out = np.empty(x.shape)
    B, model = x.shape[0], (kind, parent, body, gravity)
    if B < PARALLEL_STATES:
        first = _range(inverse, model, x, y, z, fext, out, 0, B)
        return out, (first if first < B else -1)
    nblocks = (B + BLOCK - 1) // BLOCK
    n = min(get_num_threads(), nblocks)
    runs = [(r * nblocks // n * BLOCK, min(B, (r + 1) * nblocks // n * BLOCK)) for r in range(n)]
    with _POOL_LOCK:
        if not _POOL:
            _POOL.append(ThreadPoolExecutor(get_num_threads(), thread_name_prefix="planargeo-kernels"))
    firsts = list(_POOL[0].map(lambda run: _range(inverse, model, x, y, z, fext, out, *run), runs))
    return out, next((b for b, (lo, hi) in zip(firsts, runs) if b < hi), -1)
