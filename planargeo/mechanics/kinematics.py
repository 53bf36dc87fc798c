"""Forward kinematics in world-frame, at-origin screw coordinates (thesis chapter 2).

:func:`kinematics` walks the tree from the ground outwards and fills a
:class:`planargeo.mechanics.model.Data` (its fields and equations are listed there), broadcast
over batches of ``q``.  Multi-dof joints' columns are sequential screws (2.2), so
``kappa_i = v_{λ(i)} × s_i q̇_i + Σ_{k<j} (s_k q̇_k) × (s_j q̇_j)``; the printed 2.19 drops the
cross terms (``docs/errata.md``).
"""
from __future__ import annotations

import math

import numpy as np

from planargeo._validate import as_array
from planargeo.errors import NonFiniteError, NumericOverflowError, ShapeError
from planargeo.geometry._docs import entries
from planargeo.mechanics.model import Data, Model

__all__ = ["kinematics", "check_state", "cross_motion", "cross_force", "joint_axes"]

#: Docstring entries shared here (:func:`planargeo.geometry._docs.entries`).
_documented = entries({
    "v": "v : numpy.ndarray, shape (..., 3)\n    Twist.",
    "model": "model : Model\n    The mechanism.",
    "q": "q : array_like, shape (..., nq)\n    Joint coordinates (m or rad each).",
    "qd": "qd : array_like, shape (..., nq), optional\n    Joint velocities; None is zero.",
    "f_ext": "f_ext : array_like, shape (..., N, 3), optional\n    External world wrenches at the origin.",
})


@_documented
def cross_motion(v: np.ndarray, u: np.ndarray) -> np.ndarray:
    """``v × u`` for twists (thesis 2.16 projected; same as ``crm(v) @ u``).

    Parameters
    ----------
    v, u : numpy.ndarray, shape (..., 3)
        Twists: ``u`` is carried by the motion ``v``.

    Returns
    -------
    numpy.ndarray, shape (..., 3)
        The rate of change of the twist ``u`` carried along by the motion ``v``.

    Examples
    --------
    >>> cross_motion(np.array([0.0, 0.0, 1.0]), np.array([1.0, 0.0, 0.0]))
    array([0., 1., 0.])
    """
    out = _turned(v, u)
    out[..., 0] += v[..., 1] * u[..., 2]
    out[..., 1] -= v[..., 0] * u[..., 2]
    return out


@_documented
def cross_force(v: np.ndarray, f: np.ndarray) -> np.ndarray:
    """``v ×* f = -(v×)^T f`` for a twist ``v`` and a wrench ``f`` carried by it (thesis 3.8, 3.11).

    {parameters v}
    f : numpy.ndarray, shape (..., 3)
        Wrench.

    Returns
    -------
    numpy.ndarray, shape (..., 3)
        The rate of change of the wrench ``f`` carried along by ``v``.

    Examples
    --------
    >>> cross_force(np.array([0.0, 0.0, 1.0]), np.array([1.0, 0.0, 0.0]))
    array([0., 1., 0.])
    """
    out = _turned(v, f)
    out[..., 2] = v[..., 0] * f[..., 1] - v[..., 1] * f[..., 0]
    return out


def _turned(v: np.ndarray, x: np.ndarray) -> np.ndarray:
    """``(-ω x₁, ω x₀, 0)`` with ``ω = v₂``: the part both cross products share (a new array)."""
    w = v[..., 2]
    out = np.empty(np.broadcast_shapes(v.shape, x.shape))
    out[..., 0] = -w * x[..., 1]
    out[..., 1] = w * x[..., 0]
    out[..., 2] = 0.0
    return out


def _as_state(x, name: str, nq: int, finite: bool = True) -> np.ndarray:
    a = x
    if not (type(a) is np.ndarray and a.dtype == np.float64):
        a = as_array(x, name, finite=False)            # refuses complex values too
    if a.ndim == 0 or a.shape[-1] != nq:
        raise ShapeError(f"{name} must have shape (..., {nq}), got shape {a.shape}")
    if finite and not np.isfinite(a).all():
        raise NonFiniteError(f"{name} must be finite, got non-finite values in {a!r}")
    return a


@_documented
def check_state(model: Model, q, qd=None, tau=None, f_ext=None, *, qdd=None, finite: bool = True):
    """Validate and broadcast a state (every method of the package validates its state here).

    {parameters model q qd}
    tau, qdd : array_like, shape (..., nq), optional
        Joint forces/torques (N or N·m) and accelerations; None is zero.
    {f_ext}
    finite : bool, optional
        Check for NaN and infinity (default True; the compiled kernels check themselves).

    Returns
    -------
    tuple
        ``(q, qd, tau, f_ext, qdd, batch_shape)``, float64 arrays; ``qd``, ``tau``, ``qdd`` given as
        None are zeros of shape ``(nq,)``, ``f_ext`` None stays None (no external load).

    Raises
    ------
    ShapeError, NonFiniteError, InputError
        A wrong shape or batch shapes that do not broadcast; NaN or infinity; not numeric, or complex.

    Examples
    --------
    >>> from planargeo.mechanics.model import chain_model
    >>> check_state(chain_model(2), [0.0, 0.0], [[1.0, 2.0]] * 4)[-1]
    (4,)
    >>> check_state(chain_model(2), [0.0, 0.0])[1:3]            # qd, tau: None is zeros
    (array([0., 0.]), array([0., 0.]))
    >>> check_state(chain_model(2), [0.0])
    Traceback (most recent call last):
    ...
    planargeo.errors.ShapeError: q must have shape (..., 2), got shape (1,)
    >>> check_state(chain_model(2), [0.0, 1j])
    Traceback (most recent call last):
    ...
    planargeo.errors.InputError: q must be real, got complex values
    """
    nq, N = model.nq, model.N
    q = _as_state(q, "q", nq, finite)
    shape = q.shape[:-1]
    out = []
    for name, x in (("qd", qd), ("tau", tau), ("qdd", qdd)):
        if x is None:
            out.append(np.zeros(nq))
            continue
        a = _as_state(x, name, nq, finite)
        shape = _batch(shape, a, 1, name, q)
        out.append(a)
    if f_ext is not None:
        f_ext = as_array(f_ext, "f_ext", (N, 3), finite=finite)
        shape = _batch(shape, f_ext, 2, "f_ext", q)
    qd, tau, qdd = out
    return q, qd, tau, f_ext, qdd, shape


def _batch(shape: tuple, a: np.ndarray, core: int, name: str, q: np.ndarray) -> tuple:
    """``shape`` broadcast with the batch shape of ``a`` (all but its last ``core`` axes)."""
    if a.ndim > core or shape:
        try:
            return np.broadcast_shapes(shape, a.shape[:-core])
        except ValueError:
            raise ShapeError(
                f"{name} of shape {a.shape} does not broadcast with q of shape {q.shape}") from None
    return shape


def _rot2(c, s, x, y):
    return c * x - s * y, s * x + c * y


def joint_axes(kind: str, ox, oy, phi, qi):
    """World-frame motion space of one joint and the resulting body pose (4.10, 5.51, 5.62, 4.79).

    Parameters
    ----------
    kind : str
        Joint kind (see :data:`planargeo.mechanics.model.JOINT_DOFS`).
    ox, oy, phi : array_like, shape (...)
        World pose of the joint frame (m, rad).
    qi : numpy.ndarray, shape (..., k)
        The joint's coordinates.

    Returns
    -------
    tuple
        ``(cols, (x, y, theta))``: k unit twists at the origin, each (..., 3), and the body's world pose.

    Examples
    --------
    >>> cols, pose = joint_axes("twin_prismatic", 1.0, 2.0, np.pi / 2, np.array([0.5, 0.25]))
    >>> np.round(np.array(cols), 12) + 0.0        # e = y, e⊥ = -x: ideal points
    array([[ 0.,  1.,  0.],
           [-1.,  0.,  0.]])
    """
    cols, pose = _axes(kind, ox, oy, phi, [qi[..., j] for j in range(qi.shape[-1])], np.cos(phi), np.sin(phi))
    return [np.stack(np.broadcast_arrays(*col), -1) for col in cols], pose


def _axes(kind: str, ox, oy, phi, q, c, s):
    """:func:`joint_axes` on floats or arrays, columns as triples; ``c, s``: cos, sin of ``phi``."""
    if kind == "revolute":
        return [(oy, -ox, 1.0)], (ox, oy, phi + q[0])
    if kind == "prismatic":
        return [(c, s, 0.0)], (ox + q[0] * c, oy + q[0] * s, phi)
    if kind == "revolute_prismatic":
        x1, y1 = ox + q[0] * c, oy + q[0] * s
        return [(c, s, 0.0), (y1, -x1, 1.0)], (x1, y1, phi + q[1])
    if kind in ("twin_prismatic", "plane"):       # slide along e and e⊥; a plane joint then turns
        x1 = ox + q[0] * c - q[1] * s
        y1 = oy + q[0] * s + q[1] * c
        cols = [(c, s, 0.0), (-s, c, 0.0)]
        if kind == "twin_prismatic":       # thesis 4.79: s = [e, e⊥], no rotation
            return cols, (x1, y1, phi)
        return cols + [(y1, -x1, 1.0)], (x1, y1, phi + q[2])
    if kind == "fixed":
        return [], (ox, oy, phi)
    raise AssertionError(kind)  # pragma: no cover (Joint validates kinds)


@_documented
def kinematics(model: Model, q, qd=None, f_ext=None) -> Data:
    """World-frame kinematics and bias terms of every body (thesis 3.6 step 2, 3.31-3.34).

    {parameters model q qd f_ext}

    Returns
    -------
    Data
        With ``pose, com, origin, S, I, v, kappa, g, p`` (see :class:`~planargeo.mechanics.model.Data`).

    Raises
    ------
    ShapeError, NonFiniteError, InputError
        As for :func:`check_state`.
    NumericOverflowError
        If finite input gives fields that are not finite (e.g. speeds of 1e160).

    Examples
    --------
    A unit link turning at 1 rad/s about the origin: the bias force pulls towards the pivot.

    >>> from planargeo.mechanics.model import chain_model
    >>> kinematics(chain_model(1, gravity=(0, 0)), [0.0], [1.0]).p[0]
    array([-0.5,  0. ,  0. ])
    """
    q, qd, _, f_ext, _, shape = check_state(model, q, qd, None, f_ext)
    with np.errstate(over="ignore", invalid="ignore"):      # out of the float range: _data says so by name
        if shape == ():
            return _kinematics_scalar(model, q, qd, f_ext)
        return _kinematics_batch(model, np.broadcast_to(q, shape + (model.nq,)),
                                 np.broadcast_to(qd, shape + (model.nq,)), f_ext, shape)


def _kinematics_batch(model: Model, q, qd, f_ext, shape) -> Data:
    """:func:`kinematics` for a batch (``q``, ``qd`` checked and broadcast to ``shape + (nq,)``)."""
    arr = model.arrays()
    N, nq = model.N, model.nq
    gx, gy = model.gravity

    pose, v, kappa, g = (np.empty(shape + (N, 3)) for _ in range(4))
    com, origin = np.empty(shape + (N, 2)), np.empty(shape + (N, 2))
    S, I, zeros = np.zeros(shape + (3, nq)), np.zeros(shape + (N, 3, 3)), np.zeros(shape)

    for i, (joint, par) in enumerate(zip(model.joints, model.parents)):
        px, py, pth = arr["placement"][i]
        if par < 0:
            ox, oy, phi = zeros + px, zeros + py, zeros + pth
            vp = np.zeros(shape + (3,))
        else:
            bx, by, bth = pose[..., par, 0], pose[..., par, 1], pose[..., par, 2]
            dx, dy = _rot2(np.cos(bth), np.sin(bth), px, py)
            ox, oy, phi = bx + dx, by + dy, bth + pth
            vp = v[..., par, :]
        sl = model.q_slice(i)
        cols, (x, y, th) = joint_axes(joint.kind, ox, oy, phi, q[..., sl])
        origin[..., i, 0], origin[..., i, 1] = ox, oy
        pose[..., i, 0], pose[..., i, 1], pose[..., i, 2] = x, y, th
        # twist (2.9) and bias acceleration (2.19 with sequential-screw cross terms)
        vi = vp.copy()
        kap = np.zeros(shape + (3,))
        rel = np.zeros(shape + (3,))  # Σ_{k<j} s_k qd_k
        for j, col in enumerate(cols):
            S[..., :, sl.start + j] = col
            sq = col * qd[..., sl.start + j, None]
            kap += cross_motion(vp + rel, sq)
            rel += sq
        vi += rel
        v[..., i, :] = vi
        kappa[..., i, :] = kap
        # inertia at the origin (4.58) and gravity at the centre of mass
        m, J = arr["mass"][i], arr["J"][i]
        cbx, cby = arr["com"][i]
        ddx, ddy = _rot2(np.cos(th), np.sin(th), cbx, cby)
        cx, cy = x + ddx, y + ddy
        com[..., i, 0], com[..., i, 1] = cx, cy
        inertia, weight = _body_terms(m, J, cx, cy, gx, gy)
        for r, k in np.ndindex(3, 3):
            I[..., i, r, k] = inertia[r][k]
        g[..., i, 0], g[..., i, 1], g[..., i, 2] = weight

    return _data(model, q, qd, f_ext, pose, com, origin, S, I, v, kappa, g)


def _body_terms(m, J, cx, cy, gx, gy):
    """A body's inertia at the origin (4.58) as rows, and its weight at the centre of mass, of floats or arrays alike."""
    inertia = ((m, 0.0, -m * cy), (0.0, m, m * cx), (-m * cy, m * cx, J + m * (cx * cx + cy * cy)))
    return inertia, (m * gx, m * gy, m * (cx * gy - cy * gx))


def _data(model: Model, q, qd, f_ext, pose, com, origin, S, I, v, kappa, g) -> Data:
    """:func:`kinematics`'s :class:`Data`: ``g + f_ext``, ``p = -(v×)ᵀ I v - g`` (3.11, 3.34)."""
    if f_ext is not None:
        g = g + f_ext
    with np.errstate(over="ignore", invalid="ignore"):
        p = cross_force(v, np.einsum("...ij,...j->...i", I, v)) - g
    for name, x in (("pose", pose), ("I", I), ("v", v), ("kappa", kappa), ("p", p)):
        if not np.isfinite(x).all():
            big = max(("q", q), ("qd", qd), ("f_ext", f_ext if f_ext is not None else q),
                      key=lambda a: np.max(np.abs(a[1]), initial=0.0))
            raise NumericOverflowError(f"kinematics overflow: {name} is not finite for these finite inputs "
                                       f"({big[0]} reaches {np.max(np.abs(big[1])):.3g})")
    d = Data(model)
    d.q, d.qd = q, qd
    d.pose, d.com, d.origin, d.S = pose, com, origin, S
    d.I, d.v, d.kappa, d.g, d.p = I, v, kappa, g, p
    d.f_ext = f_ext
    return d


def _kinematics_scalar(model: Model, q: np.ndarray, qd: np.ndarray, f_ext) -> Data:
    """:func:`kinematics` for one state, on Python floats (same results, less overhead)."""
    cos, sin = math.cos, math.sin
    arr = model.arrays()
    nq = model.nq
    gx, gy = model.gravity
    ql, qdl = q.tolist(), qd.tolist()
    pose, com, origin, v, kappa, g, Il = [], [], [], [], [], [], []
    S = [[0.0] * nq for _ in range(3)]
    for i, (joint, par) in enumerate(zip(model.joints, model.parents)):
        px, py, pth = joint.placement
        if par < 0:
            ox, oy, phi = px, py, pth
            vx = vy = w = 0.0
        else:
            bx, by, bth = pose[par]
            cb, sb = cos(bth), sin(bth)
            ox, oy, phi = bx + cb * px - sb * py, by + sb * px + cb * py, bth + pth
            vx, vy, w = v[par]
        o = model.q_offsets[i]
        cols, (x, y, th) = _axes(joint.kind, ox, oy, phi, ql[o:o + joint.dofs], cos(phi), sin(phi))
        origin.append((ox, oy))
        pose.append((x, y, th))
        # twist (2.9) and bias acceleration (2.19 with sequential-screw cross terms)
        k0 = k1 = 0.0
        rx, ry, rw = vx, vy, w  # v_parent + sum_{k<j} s_k qd_k
        for j, (s0, s1, s2) in enumerate(cols):
            S[0][o + j], S[1][o + j], S[2][o + j] = s0, s1, s2
            qj = qdl[o + j]
            u0, u1, u2 = s0 * qj, s1 * qj, s2 * qj
            k0 += -rw * u1 + ry * u2
            k1 += rw * u0 - rx * u2
            rx, ry, rw = rx + u0, ry + u1, rw + u2
        v.append((rx, ry, rw))
        kappa.append((k0, k1, 0.0))
        m, J = float(arr["mass"][i]), float(arr["J"][i])
        cbx, cby = model.bodies[i].com
        if not math.isfinite(th):                          # the joint angles sum past the float range
            raise NumericOverflowError(f"kinematics: body {i}'s angle overflows double precision (q too large)")
        ct, st = cos(th), sin(th)
        cx, cy = x + ct * cbx - st * cby, y + st * cbx + ct * cby
        com.append((cx, cy))
        inertia, weight = _body_terms(m, J, cx, cy, gx, gy)
        Il.append(inertia)
        g.append(weight)
    return _data(model, q, qd, f_ext, np.array(pose), np.array(com), np.array(origin), np.array(S).reshape(3, nq),
                 np.array(Il), np.array(v), np.array(kappa), np.array(g))
