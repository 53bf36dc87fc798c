"""Forward kinematics in world-frame, at-origin screw coordinates (thesis Chapter 2).

:func:`kinematics` walks the tree from the ground outwards and fills a
:class:`planargeo.model.Data` with, for every body ``i``:

* the world pose and centre of mass,
* the joint motion space ``s_i`` (3×k unit twists at the global origin;
  a revolute joint at ``(x, y)`` is the point ``[y, -x, 1]``, a prismatic
  joint along ``d`` the ideal point ``[dx, dy, 0]``),
* the spatial inertia ``I_i`` at the origin (4.58),
* the twist ``v_i = v_{λ(i)} + s_i q̇_i`` (2.9, 3.32),
* the bias acceleration ``kappa_i`` (2.19, 3.33),
* the applied wrench ``g_i`` (gravity at the centre of mass plus ``f_ext``)
  and the bias force ``p_i = -(v_i×)^T I_i v_i - g_i`` (3.11, 3.34).

All arrays broadcast over leading batch dimensions of ``q``.

Multi-dof joints: the columns of ``s_i`` are sequential screws (2.2); column
``j`` is carried by the frame after the motions ``1..j-1``, so its rate is
``ṡ_j = (v_{λ(i)} + Σ_{k<j} s_k q̇_k) × s_j`` and
``kappa_i = v_{λ(i)} × s_i q̇_i + Σ_{k<j} (s_k q̇_k) × (s_j q̇_j)``.  For one-dof
joints this is the printed ``v_i × s_i q̇_i`` (2.19); for multi-dof joints the
printed form drops the cross terms (see ``docs/errata/dynamics-a.md``).
"""
from __future__ import annotations

import numpy as np

from ._validate import as_array
from .errors import ShapeError
from .model import Data, Model

__all__ = ["kinematics", "check_state", "cross_motion", "cross_force", "joint_axes"]


def cross_motion(v: np.ndarray, u: np.ndarray) -> np.ndarray:
    """``v × u`` for twists (thesis 2.16 projected; same as ``crm(v) @ u``).

    Examples
    --------
    >>> cross_motion(np.array([0.0, 0.0, 1.0]), np.array([1.0, 0.0, 0.0]))
    array([0., 1., 0.])
    """
    w = v[..., 2]
    out = np.empty(np.broadcast_shapes(v.shape, u.shape))
    out[..., 0] = -w * u[..., 1] + v[..., 1] * u[..., 2]
    out[..., 1] = w * u[..., 0] - v[..., 0] * u[..., 2]
    out[..., 2] = 0.0
    return out


def cross_force(v: np.ndarray, f: np.ndarray) -> np.ndarray:
    """``v ×* f = -(v×)^T f`` for a twist ``v`` and a wrench ``f`` (thesis 3.8, 3.11).

    Examples
    --------
    >>> cross_force(np.array([0.0, 0.0, 1.0]), np.array([1.0, 0.0, 0.0]))
    array([0., 1., 0.])
    """
    w = v[..., 2]
    out = np.empty(np.broadcast_shapes(v.shape, f.shape))
    out[..., 0] = -w * f[..., 1]
    out[..., 1] = w * f[..., 0]
    out[..., 2] = v[..., 0] * f[..., 1] - v[..., 1] * f[..., 0]
    return out


def check_state(model: Model, q, qd=None, tau=None, f_ext=None, *, qdd=None):
    """Validate and broadcast a state; returns ``(q, qd, tau, f_ext, qdd, batch_shape)``.

    ``q``, ``qd``, ``tau``, ``qdd`` have shape ``(..., nq)``; ``f_ext`` has
    shape ``(..., N, 3)`` (world wrenches at the origin, one per body) or is
    ``None``.  Missing arguments are returned as ``None``.
    """
    nq, N = model.nq, model.N
    q = as_array(q, "q")
    if q.ndim == 0 or q.shape[-1] != nq:
        raise ShapeError(f"q must have shape (..., {nq}), got shape {q.shape}")
    shape = q.shape[:-1]
    out = []
    for name, x in (("qd", qd), ("tau", tau), ("qdd", qdd)):
        if x is None:
            out.append(None)
            continue
        a = as_array(x, name)
        if a.ndim == 0 or a.shape[-1] != nq:
            raise ShapeError(f"{name} must have shape (..., {nq}), got shape {a.shape}")
        try:
            shape = np.broadcast_shapes(shape, a.shape[:-1])
        except ValueError:
            raise ShapeError(f"{name} of shape {a.shape} does not broadcast with q of shape {q.shape}") from None
        out.append(a)
    if f_ext is not None:
        f_ext = as_array(f_ext, "f_ext", (N, 3))
        try:
            shape = np.broadcast_shapes(shape, f_ext.shape[:-2])
        except ValueError:
            raise ShapeError(f"f_ext of shape {f_ext.shape} does not broadcast with q of shape {q.shape}") from None
    qd, tau, qdd = out
    return q, qd, tau, f_ext, qdd, shape


def _rot2(c, s, x, y):
    return c * x - s * y, s * x + c * y


def joint_axes(kind: str, ox, oy, phi, qi):
    """World-frame motion space of one joint and the resulting body pose.

    ``(ox, oy, phi)`` is the joint frame's world pose, ``qi`` (..., k) the joint
    coordinates.  Returns ``(cols, (x, y, theta))`` with ``cols`` a list of k
    arrays (..., 3): the unit twists at the origin (4.10, 5.51, 5.62).
    """
    c, s = np.cos(phi), np.sin(phi)
    zero, one = np.zeros_like(ox), np.ones_like(ox)
    if kind == "revolute":
        cols = [np.stack([oy, -ox, one], -1)]
        return cols, (ox, oy, phi + qi[..., 0])
    if kind == "prismatic":
        cols = [np.stack([c, s, zero], -1)]
        return cols, (ox + qi[..., 0] * c, oy + qi[..., 0] * s, phi)
    if kind == "revolute_prismatic":
        x1, y1 = ox + qi[..., 0] * c, oy + qi[..., 0] * s
        cols = [np.stack([c, s, zero], -1), np.stack([y1, -x1, one], -1)]
        return cols, (x1, y1, phi + qi[..., 1])
    if kind == "plane":
        x1 = ox + qi[..., 0] * c - qi[..., 1] * s
        y1 = oy + qi[..., 0] * s + qi[..., 1] * c
        cols = [np.stack([c, s, zero], -1), np.stack([-s, c, zero], -1), np.stack([y1, -x1, one], -1)]
        return cols, (x1, y1, phi + qi[..., 2])
    if kind == "fixed":
        return [], (ox, oy, phi)
    raise AssertionError(kind)  # pragma: no cover (Joint validates kinds)


def kinematics(model: Model, q, qd=None, f_ext=None) -> Data:
    """World-frame kinematics and bias terms of every body (thesis 3.6 step 2).

    Parameters
    ----------
    model : Model
    q : array_like (..., nq)
        Joint coordinates.
    qd : array_like (..., nq), optional
        Joint speeds (zero if omitted).
    f_ext : array_like (..., N, 3), optional
        External wrenches at the origin applied to each body (the thesis's
        ``g_i`` besides gravity).

    Returns
    -------
    Data
        With ``pose, com, origin, S, I, v, kappa, g, p`` (see :class:`~planargeo.model.Data`).

    Examples
    --------
    A unit link turning at 1 rad/s about the origin, at q = 0:

    >>> from planargeo.model import chain_model
    >>> d = kinematics(chain_model(1, gravity=(0, 0)), [0.0], [1.0])
    >>> d.s(0)[:, 0], d.v[0]          # the joint is the point (0, 0) = [0, 0, 1]
    (array([ 0., -0.,  1.]), array([0., 0., 1.]))
    >>> d.p[0]                        # centripetal: the bias force pulls towards the pivot
    array([-0.5,  0. ,  0. ])
    """
    q, qd, _, f_ext, _, shape = check_state(model, q, qd, None, f_ext)
    q = np.broadcast_to(q, shape + (model.nq,))
    qd = np.zeros(shape + (model.nq,)) if qd is None else np.broadcast_to(qd, shape + (model.nq,))
    arr = model.arrays()
    N, nq = model.N, model.nq
    gx, gy = model.gravity

    pose = np.empty(shape + (N, 3))
    com = np.empty(shape + (N, 2))
    origin = np.empty(shape + (N, 2))
    S = np.zeros(shape + (3, nq))
    I = np.zeros(shape + (N, 3, 3))
    v = np.empty(shape + (N, 3))
    kappa = np.empty(shape + (N, 3))
    g = np.empty(shape + (N, 3))
    zeros = np.zeros(shape)

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
        I[..., i, 0, 0] = I[..., i, 1, 1] = m
        I[..., i, 0, 2] = I[..., i, 2, 0] = -m * cy
        I[..., i, 1, 2] = I[..., i, 2, 1] = m * cx
        I[..., i, 2, 2] = J + m * (cx * cx + cy * cy)
        g[..., i, 0] = m * gx
        g[..., i, 1] = m * gy
        g[..., i, 2] = m * (cx * gy - cy * gx)

    if f_ext is not None:
        g = g + f_ext
    Iv = np.einsum("...ij,...j->...i", I, v)
    p = cross_force(v, Iv) - g

    d = Data(model)
    d.q, d.qd = q, qd
    d.pose, d.com, d.origin, d.S = pose, com, origin, S
    d.I, d.v, d.kappa, d.g, d.p = I, v, kappa, g, p
    d.f_ext = f_ext
    return d
