"""Planar screws as arrays (thesis 1, 4): twists ``[vx, vy, ω]`` are points, wrenches lines.

Quantities are given at the origin unless said otherwise and broadcast over leading dimensions;
a result beyond double precision raises :class:`~planargeo.errors.NumericOverflowError`.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from planargeo._validate import (as_array, as_mat3, as_vec3, as_xy, batch_shape, check_overflow, check_positive,
                                 check_positive_semidefinite, check_tolerance, overflow_checked, rescaled)
from planargeo.errors import DegenerateGeometryError, NumericOverflowError, ShapeError
from planargeo.geometry.projective import _fit, normalize_line, normalize_point, to_xy
from planargeo.geometry._docs import entries

__all__ = [
    "X_P", "X_P_inv_T", "rot", "X_frame", "X_frame_inv_T", "rotation_about", "crm", "crf",
    "unit_rotation", "unit_translation", "inertia_matrix",
    "power", "kinetic_energy",
    "twist_magnitude", "pole_xy", "wrench_magnitude", "wrench_axis", "reciprocal",
    "inertia_at", "inertia_transform", "inertia_rotated", "momentum", "kappa", "bias_force",
    "Twist", "Wrench", "TwistSum", "WrenchSum", "add_twists", "add_wrenches",
]


#: The docstring entries the screws share (a line ``{inertia twist}``; see geometry/_docs.py).
SCREWS = {
    "twist": "twist : Twist or array_like, shape (..., 3)\n    Twist ``[vx, vy, ω]`` (m/s, rad/s).",
    "v": "v : array_like, shape (..., 3)\n    Twist ``[vx, vy, ω]``.",
    "wrench": "wrench : Wrench or array_like, shape (..., 3)\n"
              "    Wrench ``[fx, fy, τz]`` (N, N·m).",
    "point": "point : array_like, shape (..., 2)\n    Reference point ``(x, y)`` (m).",
    "other": "other : Twist, Wrench or array_like, shape (..., 3)\n    The screw of the dual kind.",
    "rtol": "rtol : float, optional\n    Relative tolerance of the zero-power test.",
    "theta": "theta : array_like, shape (...)\n    Angle (rad), counter-clockwise.",
    "about": "about : array_like, shape (..., 2), optional\n    Centre ``c`` of the rotation (m).",
    "mass_com": "mass : float or array_like, shape (...)\n    Mass ``m > 0`` (kg).\n"
                "com : array_like, shape (..., 2)\n    Centre of mass ``c = (cx, cy)`` (m).",
    "inertia": "inertia : array_like, shape (..., 3, 3)\n"
               "    Symmetric inertia matrix at the origin (kg, kg·m, kg·m²).",
    "returns_twist": "Returns\n-------\nTwist",
    "returns_wrench": "Returns\n-------\nWrench",
    "not_psd": "Raises\n------\nInputError, SingularInertiaError\n"
               "    ``inertia`` not symmetric positive semi-definite.",
    "bad_array": "Raises\n------\nShapeError, NonFiniteError, InputError\n"
                 "    ``array`` without a last axis of 3, not finite, or not real numbers.",
}
documented = entries(SCREWS)


@documented
def X_P(point) -> np.ndarray:
    """Twist transform from the origin to ``point`` (thesis 4.8): ``X_P(p) @ v`` is ``v`` at ``p``.

    {parameters point returns_3x3}

    Examples
    --------
    >>> X_P([2.0, 0.0]) @ [0.0, 0.0, 1.0]   # unit rotation about the origin, seen at (2, 0)
    array([0., 2., 1.])
    """
    p = as_xy(point, "point")
    out = np.zeros(p.shape[:-1] + (3, 3))
    out[..., 0, 0] = out[..., 1, 1] = out[..., 2, 2] = 1.0
    out[..., 0, 2] = -p[..., 1]
    out[..., 1, 2] = p[..., 0]
    return out


@documented
def X_P_inv_T(point) -> np.ndarray:
    """Wrench transform from the origin to ``point`` (thesis 4.24): ``inv(X_P(p)).T``.

    {parameters point returns_3x3}

    Examples
    --------
    >>> X_P_inv_T([0.0, 1.0]) @ [1.0, 0.0, 0.0]   # force along x through the origin, moment about (0, 1)
    array([1., 0., 1.])
    """
    inverse = X_P(-as_xy(point, "point"))           # X_P(p)⁻¹ = X_P(-p)
    return np.ascontiguousarray(np.swapaxes(inverse, -1, -2))


@documented
def rot(theta) -> np.ndarray:
    """Rotation of screw coordinates by ``theta`` about the reference point (twists, wrenches).

    {parameters theta returns_3x3}

    Examples
    --------
    >>> np.round(rot(np.pi / 2) @ [1.0, 0.0, 3.0], 12)
    array([0., 1., 3.])
    """
    t = as_array(theta, "theta")
    c, s = np.cos(t), np.sin(t)
    out = np.zeros(t.shape + (3, 3))
    out[..., 0, 0] = c
    out[..., 0, 1] = -s
    out[..., 1, 0] = s
    out[..., 1, 1] = c
    out[..., 2, 2] = 1.0
    return out


@overflow_checked("theta or point")
@documented
def X_frame(theta, point) -> np.ndarray:
    """Twist transform ``rot(θ) X_P(p)`` to a turned frame at ``point`` (thesis 1.56, 4.7).

    {parameters theta}
    point : array_like (..., 2)
        Origin of the new frame ``(x, y)`` (m).

    {returns_3x3}

    Examples
    --------
    >>> np.round(X_frame(np.pi / 2, [2.0, 0.0]) @ [0.0, 0.0, 1.0], 12) + 0.0   # X_P gives [0, 2, 1], then turned
    array([-2.,  0.,  1.])
    """
    _batches(theta=(theta, 0), point=(point, 1))
    return rot(theta) @ X_P(point)


@overflow_checked("theta or point")
@documented
def X_frame_inv_T(theta, point) -> np.ndarray:
    """Wrench transform matching :func:`X_frame`: ``X⁻ᵀ = rot(θ) X_P⁻ᵀ`` (thesis 1.58, 4.24).

    {parameters theta point returns_3x3}

    Examples
    --------
    >>> np.round(X_frame_inv_T(np.pi / 2, [0.0, 1.0]) @ [1.0, 0.0, 0.0], 12) + 0.0   # X_P⁻ᵀ gives [1, 0, 1]
    array([0., 1., 1.])
    """
    _batches(theta=(theta, 0), point=(point, 1))
    return rot(theta) @ X_P_inv_T(point)


@overflow_checked("theta or about")
@documented
def rotation_about(theta, about=(0.0, 0.0)) -> np.ndarray:
    """Twist map ``X_P(-c) rot(θ) X_P(c)``: a turn by ``theta`` about ``about`` (thesis 4.8, 1.56).

    Wrenches are carried by its inverse transpose, inertias by :func:`inertia_rotated`.

    {parameters theta about returns_3x3}

    Examples
    --------
    >>> v = unit_rotation([2.0, 0.0])                       # spin about (2, 0)
    >>> pole_xy(rotation_about(np.pi / 2, [1.0, 0.0]) @ v).round(12) + 0.0   # (2, 0) turned about (1, 0)
    array([1., 1.])
    """
    c = as_xy(about, "about")
    _batches(theta=(theta, 0), about=(c, 1))
    return _turn(X_P, theta, c)


def _turn(carry, theta, c) -> np.ndarray:
    """``carry(-c) rot(θ) carry(c)``: a turn about ``c`` of twists (``carry = X_P``) or wrenches."""
    return carry(-c) @ rot(theta) @ carry(c)


@documented
def crm(v) -> np.ndarray:
    """Planar motion cross operator ``v×`` (thesis 2.16 projected, 4.63).

    {parameters v returns_3x3}

    Examples
    --------
    >>> crm([0.0, 0.0, 1.0]) @ [1.0, 0.0, 0.0]   # a translation along x, rotated at unit rate
    array([0., 1., 0.])
    """
    v = as_vec3(v, "v")
    out = np.zeros(v.shape[:-1] + (3, 3))
    out[..., 0, 1] = -v[..., 2]
    out[..., 0, 2] = v[..., 1]
    out[..., 1, 0] = v[..., 2]
    out[..., 1, 2] = -v[..., 0]
    return out


@documented
def crf(v) -> np.ndarray:
    """Planar force cross operator ``v×* = -(v×)ᵀ`` (dual of :func:`crm`, thesis 3.8).

    {parameters v returns_3x3}

    Examples
    --------
    >>> crf([1.0, 0.0, 0.0]) @ [0.0, 1.0, 0.0]   # a force along y carried along x: moment about the origin grows
    array([0., 0., 1.])
    """
    return -np.swapaxes(crm(v), -1, -2)


@documented
def unit_rotation(point) -> np.ndarray:
    """Unit twist ``[y, -x, 1]`` of a counter-clockwise turn about ``point`` (thesis 4.10, 5.51).

    {parameters point returns_3}

    Examples
    --------
    >>> unit_rotation([1.0, 2.0])
    array([ 2., -1.,  1.])
    """
    p = as_xy(point, "point")
    return np.stack([p[..., 1], -p[..., 0], np.ones(p.shape[:-1])], axis=-1)


@documented
def unit_translation(direction) -> np.ndarray:
    """Unit twist ``[dx, dy, 0] / |d|`` of a translation along ``direction`` (thesis 5.62).

    Parameters
    ----------
    direction : array_like, shape (..., 2)
        Direction of the velocity (non-zero).

    {returns_3}

    Raises
    ------
    DegenerateGeometryError
        ``direction`` is zero, so there is no velocity to scale.

    Examples
    --------
    >>> unit_translation([0.0, 2.0])
    array([0., 1., 0.])
    """
    d = _fit(as_xy(direction, "direction"))       # exact rescaling: |d| cannot overflow
    n = np.hypot(d[..., 0], d[..., 1])
    if np.any(n == 0):
        raise DegenerateGeometryError("direction must be non-zero, got a zero vector")
    return np.stack([d[..., 0] / n, d[..., 1] / n, np.zeros(n.shape)], axis=-1)


@overflow_checked("mass, com or inertia_about_com")
@documented
def inertia_matrix(mass, com, inertia_about_com) -> np.ndarray:
    """Planar spatial inertia at the origin (thesis 1.68 projected; 4.58, 5.64).

    ``[[m, 0, -m cy], [0, m, m cx], [-m cy, m cx, J + m |c|²]]`` for the centre of mass ``c``.

    {parameters mass_com}
    inertia_about_com : array_like (...)
        ``J >= 0`` (kg·m²; ``J = 0`` is a point mass).

    {returns_3x3}

    Raises
    ------
    InputError
        ``mass <= 0`` or ``inertia_about_com < 0``.

    Examples
    --------
    >>> inertia_matrix(2.0, [1.0, 0.0], 0.5)   # thesis 5.64 with m=2, d=1, ρ²=1/4
    array([[2. , 0. , 0. ],
           [0. , 2. , 2. ],
           [0. , 2. , 2.5]])
    """
    m = check_positive(mass, "mass")
    c = as_xy(com, "com")
    J = check_positive(inertia_about_com, "inertia_about_com", strict=False)
    shape = batch_shape(mass=(m, 0), com=(c, 1), inertia_about_com=(J, 0))
    out = np.zeros(shape + (3, 3))
    cx, cy = c[..., 0], c[..., 1]
    out[..., 0, 0] = m
    out[..., 1, 1] = m
    out[..., 0, 2] = out[..., 2, 0] = 0.0 - m * cy
    out[..., 1, 2] = out[..., 2, 1] = m * cx
    out[..., 2, 2] = J + m * (cx * cx + cy * cy)
    return out


@documented
def power(twist, wrench) -> np.ndarray:
    """Power ``vᵀf`` (W) of a wrench on a twist (thesis 5.73); zero means incidence.

    {parameters twist wrench returns_scalar}

    Examples
    --------
    >>> power([0.0, 0.0, 1.0], [1.0, 0.0, 0.0])  # force through the pole: no power
    array(0.)
    """
    v = as_vec3(twist, "twist")
    f = as_vec3(wrench, "wrench")
    batch_shape(twist=(v, 1), wrench=(f, 1))
    return np.asarray(rescaled(lambda v, f: np.einsum("...i,...i->...", v, f), (v, f), (1, 1),
                               (1, 1), 0, "power(twist, wrench)", "twist or wrench"))


@documented
def kinetic_energy(inertia, twist) -> np.ndarray:
    """Kinetic energy ``½ vᵀ I v`` (J; thesis 1.9), invariant under frame changes.

    {parameters inertia twist returns_scalar not_psd}

    Examples
    --------
    >>> float(kinetic_energy(inertia_matrix(2.0, [1.0, 0.0], 0.5), [0.0, 0.0, 3.0]))  # ½(J+md²)ω²
    11.25
    """
    I = _inertia_psd(inertia)
    v = as_vec3(twist, "twist")
    batch_shape(inertia=(I, 2), twist=(v, 1))
    return np.asarray(rescaled(lambda I, v: 0.5 * np.einsum("...i,...ij,...j->...", v, I, v), (I, v), (1, 2),
                               (2, 1), 0, "kinetic_energy(inertia, twist)", "inertia or twist"))


def _inertia_psd(inertia, name: str = "inertia") -> np.ndarray:
    """An inertia argument: (..., 3, 3), finite, symmetric, positive semi-definite."""
    return check_positive_semidefinite(as_mat3(inertia, name), name)


# ---------- Scalar features of twists and wrenches (thesis 4.6-4.10, 4.22-4.32)
@documented
def twist_magnitude(twist) -> np.ndarray:
    """Signed magnitude ``ω_z`` (rad/s) of a twist (thesis 4.6); 0 for a translation.

    {parameters twist returns_scalar}

    Examples
    --------
    >>> twist_magnitude([1.0, -2.0, 3.0])
    array(3.)
    """
    v = as_vec3(twist, "twist")
    return np.asarray(v[..., 2])


@documented
def pole_xy(twist) -> np.ndarray:
    """Euclidean pole ``(-v_y/ω, v_x/ω)`` of a twist (thesis 4.10, 5.51); NaN for a translation.

    {parameters twist returns_2}

    Examples
    --------
    >>> pole_xy([2.0, -1.0, 1.0])
    array([1., 2.])
    """
    return to_xy(as_vec3(twist, "twist"))


@documented
def wrench_magnitude(wrench) -> np.ndarray:
    """Magnitude ``F = sqrt(f_x² + f_y²)`` (N) of a wrench (thesis 4.22, 4.29); 0 for a couple.

    {parameters wrench returns_scalar}

    Examples
    --------
    >>> wrench_magnitude([3.0, 4.0, 1.0])
    array(5.)
    """
    f = as_vec3(wrench, "wrench")
    return np.asarray(rescaled(lambda f: np.hypot(f[..., 0], f[..., 1]), (f,), (1,), (1,), 0,
                               "wrench_magnitude(wrench)", "wrench"))


@documented
def wrench_axis(wrench):
    """Direction ``e``, distance ``d = τ/F``, normal ``n`` of a line of action (thesis 4.28-4.32).

    The point nearest the origin is ``n d`` (4.30).  A couple gives NaN ``e``, ``n`` and
    ``d = ±inf``; the zero wrench all NaN; no warnings.

    {parameters wrench}

    Returns
    -------
    e : ndarray (..., 2)
    d : ndarray (...)
    n : ndarray (..., 2)

    Examples
    --------
    >>> wrench_axis([0.0, 2.0, 4.0])   # vertical force along x = 2
    (array([0., 1.]), array(2.), array([ 1., -0.]))
    """
    f = as_vec3(wrench, "wrench")
    ok = np.any(f[..., :2] != 0, axis=-1)
    g = _fit(f[..., :2])                       # e and n do not depend on the force's scale
    G = np.hypot(g[..., 0], g[..., 1])
    safe = np.where(ok, G, 1.0)
    e = np.where(ok[..., None], g / safe[..., None], np.nan)
    n = np.where(ok[..., None], np.stack([g[..., 1], -g[..., 0]], axis=-1) / safe[..., None], np.nan)
    tau = f[..., 2]
    far = np.where(tau != 0, np.copysign(np.inf, tau), np.nan)
    with np.errstate(over="ignore"):
        d = np.where(ok, tau / np.where(ok, np.hypot(f[..., 0], f[..., 1]), 1.0), far)
    check_overflow(d, "wrench_axis(wrench)", "the distance tz / F", ok=~ok)
    return e, np.asarray(d), n


@documented
def reciprocal(twist, wrench, rtol: float = 1e-12) -> np.ndarray:
    """Twist and wrench reciprocal, ``|vᵀf| <= rtol |v| |f|`` (thesis 1.9, 5.61, 5.69).

    {parameters twist wrench rtol returns_bool}

    Examples
    --------
    >>> bool(reciprocal(unit_rotation([1.0, 0.0]), [0.0, 1.0, 1.0]))   # the line x = 1
    True
    """
    v = _fit(as_vec3(twist, "twist"))          # the test does not depend on the scales (exact rescaling)
    f = _fit(as_vec3(wrench, "wrench"))
    batch_shape(twist=(v, 1), wrench=(f, 1))
    P = np.einsum("...i,...i->...", v, f)
    scale = np.linalg.norm(v, axis=-1) * np.linalg.norm(f, axis=-1)
    with np.errstate(over="ignore"):
        return np.asarray(np.abs(P) <= check_tolerance(rtol) * scale)


# ---------- Inertia frame change, momentum and bias terms (thesis 1.68, 2.19, 3.11, 5.72)
@overflow_checked("inertia or point")
@documented
def inertia_at(inertia, point) -> np.ndarray:
    """Inertia expressed at ``point``: ``X_P⁻ᵀ I X_P⁻¹`` (thesis 1.68, 4.24).

    {parameters inertia point returns_3x3 not_psd}

    Examples
    --------
    >>> inertia_at(inertia_matrix(2.0, [1.0, 0.0], 0.5), [1.0, 0.0])[2]   # at the centre of mass: J
    array([0. , 0. , 0.5])
    """
    I = _inertia_psd(inertia)
    _batches(inertia=(I, 2), point=(point, 1))
    return _congruence(X_P_inv_T(point), I)


def _congruence(W: np.ndarray, I: np.ndarray) -> np.ndarray:
    """``W I Wᵀ`` (thesis 1.68 with ``W = (_A X_B)ᵀ``), symmetric by construction."""
    return W @ I @ np.swapaxes(W, -1, -2)


@overflow_checked("inertia, theta or point")
@documented
def inertia_transform(inertia, theta=0.0, point=(0.0, 0.0)) -> np.ndarray:
    """Inertia in the frame of :func:`X_frame`: ``I_B = X⁻ᵀ I X⁻¹`` (thesis 1.68; passive).

    {parameters inertia theta point returns_3x3 not_psd}

    Examples
    --------
    >>> np.round(inertia_transform(inertia_matrix(2.0, [1.0, 0.0], 0.5), np.pi / 2), 12) + 0.0
    array([[ 2. ,  0. , -2. ],
           [ 0. ,  2. ,  0. ],
           [-2. ,  0. ,  2.5]])
    """
    I = _inertia_psd(inertia)
    _batches(inertia=(I, 2), theta=(theta, 0), point=(point, 1))
    return _congruence(X_frame_inv_T(theta, point), I)


@overflow_checked("inertia, theta or about")
@documented
def inertia_rotated(inertia, theta, about=(0.0, 0.0)) -> np.ndarray:
    """Inertia ``M⁻ᵀ I M⁻¹`` of the body turned by ``theta`` about ``about`` (thesis 1.68, 4.8).

    {parameters inertia theta about returns_3x3 not_psd}

    Examples
    --------
    >>> I = inertia_rotated(inertia_matrix(2.0, [2.0, 0.0], 0.5), np.pi / 2, about=[1.0, 0.0])
    >>> np.allclose(I, inertia_matrix(2.0, [1.0, 1.0], 0.5))       # centred at (1, 1) now
    True
    """
    I = _inertia_psd(inertia)
    c = as_xy(about, "about")
    _batches(inertia=(I, 2), theta=(theta, 0), about=(c, 1))
    return _congruence(_turn(X_P_inv_T, theta, c), I)


@overflow_checked("inertia or twist")
@documented
def momentum(inertia, twist) -> np.ndarray:
    """Momentum wrench ``p = I v`` (thesis 1.65, 5.72), its line through the centre of mass (1.60).

    {parameters inertia twist returns_3 not_psd}

    Examples
    --------
    >>> momentum(inertia_matrix(1.0, [0.0, 0.0], 1.0), [1.0, 0.0, 0.0])
    array([1., 0., 0.])
    """
    I = _inertia_psd(inertia)
    v = as_vec3(twist, "twist")
    batch_shape(inertia=(I, 2), twist=(v, 1))
    return np.einsum("...ij,...j->...i", I, v)


@overflow_checked("twist, s or qd")
def kappa(twist, s, qd) -> np.ndarray:
    """Bias acceleration ``κ = ṡ q̇`` of a joint with sequential screws (thesis 2.19, 4.61).

    Column ``j`` of ``s`` (sequential screws, thesis 2.2) moves with ``v + Σ_{l<j} s_l q̇_l``,
    so (2.14) ``κ = v × s q̇ + Σ_{l<j} (s_l q̇_l) × (s_j q̇_j)``: the printed 2.19/4.61 for one
    column; for several the printed form drops the cross terms (``docs/errata.md``; thesis 4.77,
    3.33, 4.53).

    Parameters
    ----------
    twist : array_like (..., 3)
        Velocity of the parent body at the origin (the body's own gives the same result).
    s : array_like (..., 3, k) or (..., 3)
        Joint motion space, columns in the order the motions are applied.
    qd : array_like (..., k) or (...)
        Joint speeds, in the order of the columns.

    Returns
    -------
    ndarray (..., 3)
        A translation (zero ``ω``).

    Raises
    ------
    ShapeError
        If ``s`` is not ``(..., 3)`` or ``(..., 3, k)``, or ``qd`` does not match its columns.

    Examples
    --------
    >>> kappa([1.0, 2.0, 0.5], [0.0, 0.0, 1.0], 3.0)   # revolute joint, thesis 4.66-4.67
    array([ 6., -3.,  0.])
    """
    v = as_vec3(twist, "twist")
    S = as_array(s, "s")
    q = as_array(qd, "qd")
    if S.ndim >= 1 and S.shape[-1] == 3 and (S.ndim == 1 or S.shape[-2] != 3):
        U = (S * q[..., None])[..., None]
    elif S.ndim >= 2 and S.shape[-2] == 3:
        if q.ndim == 0 or q.shape[-1] != S.shape[-1]:
            raise ShapeError(f"qd must have shape (..., {S.shape[-1]}) to match s, got shape {q.shape}")
        U = S * q[..., None, :]
    else:
        raise ShapeError(f"s must have shape (..., 3) or (..., 3, k), got shape {S.shape}")
    shape = batch_shape(twist=(v, 1), **{"s q̇": (U, 2)})
    out = np.zeros(shape + (3,))
    carrier = np.broadcast_to(v, shape + (3,))         # v + Σ_{l<j} s_l q̇_l
    for j in range(U.shape[-1]):
        u = U[..., :, j]
        w = carrier[..., 2]
        out[..., 0] += carrier[..., 1] * u[..., 2] - w * u[..., 1]   # crm(carrier) @ u (4.63)
        out[..., 1] += w * u[..., 0] - carrier[..., 0] * u[..., 2]
        carrier = carrier + u
    return out


@overflow_checked("inertia, twist or g")
@documented
def bias_force(inertia, twist, g=None) -> np.ndarray:
    """Bias force ``p = -(v×)ᵀ I v - g = crf(v) I v - g`` (thesis 3.11, 4.56, 4.62, 4.7).

    {parameters inertia twist}
    g : array_like (..., 3), optional
        External wrench (gravity, loads) at the origin; default zero.

    {returns_3}

    {not_psd}

    Examples
    --------
    >>> bias_force(inertia_matrix(1.0, [2.0, 0.0], 1.0), [0.0, 0.0, 1.0])   # m l ω² = 2 towards the origin
    array([-2.,  0.,  0.])
    """
    I = _inertia_psd(inertia)
    v = as_vec3(twist, "twist")
    g = None if g is None else as_vec3(g, "g")
    batch_shape(inertia=(I, 2), twist=(v, 1), g=(np.zeros(3) if g is None else g, 1))
    out = np.einsum("...ij,...jk,...k->...i", crf(v), I, v)
    if g is not None:
        out = out - g
    return out


# ---------- Thin classes
def _batches(**named) -> tuple:
    """:func:`planargeo._validate.batch_shape` of arguments not yet converted."""
    return batch_shape(**{k: (as_array(x, k), nd) for k, (x, nd) in named.items()})


def _derived(function, doc: str) -> property:
    """A read-only property: ``function`` of the held array, documented by ``doc``."""
    def get(self):
        return function(self._array)

    get.__doc__ = doc
    return property(get)


def _xy(a: np.ndarray) -> np.ndarray:
    return a[..., :2].copy()


class _Held:
    """Common base of :class:`Twist`, :class:`Wrench` and ``Inertia``: one read-only array."""

    __slots__ = ("_array",)
    __hash__ = None

    def __array__(self, dtype=None, copy=None):
        return np.asarray(self._array, dtype=dtype)

    def __eq__(self, other):
        if type(other) is not type(self):
            return NotImplemented
        return bool(np.array_equal(self._array, other._array))


class _Screw(_Held):
    """Common base of :class:`Twist` and :class:`Wrench`, written once through the duality.

    A subclass names itself (``_name``), the matrix ``_carry`` that moves it to another point, its
    dual kind ``_dual`` and its projective element ``_element`` (class, property, noun).
    """

    __slots__ = ()
    _name = "screw"

    def __init__(self, array):
        a = np.array(as_vec3(array, self._name), dtype=float)
        a.flags.writeable = False
        self._array = a

    array = _derived(np.asarray, "The screw coordinates (read-only).")
    shape = _derived(lambda a: a.shape[:-1], "Batch shape (leading dimensions).")

    def __repr__(self) -> str:
        body = np.array2string(self._array, separator=", ", precision=6, suppress_small=True)
        return f"{type(self).__name__}({body})"

    def _new(self, op: str, function, *args):
        """A screw of this kind, ``function(*args)``, refused if a coordinate overflows."""
        with np.errstate(over="ignore", invalid="ignore"):
            array = function(*args)
        return type(self)(check_overflow(array, f"{type(self).__name__} {op}", "a coordinate"))

    def __add__(self, other):
        if type(other) is not type(self):
            return NotImplemented
        return self._new("+", np.add, self._array, other._array)

    def __sub__(self, other):
        if type(other) is not type(self):
            return NotImplemented
        return self._new("-", np.subtract, self._array, other._array)

    def __neg__(self):
        return type(self)(-self._array)

    def __mul__(self, k):
        number = isinstance(k, (int, float, np.integer, np.floating)) and not isinstance(k, bool)
        if not number and not (isinstance(k, np.ndarray) and k.ndim == 0):
            return NotImplemented
        return self._new("*", np.multiply, self._array, float(k))

    __rmul__ = __mul__

    def rotated(self, theta, about=None):
        """The screw turned by ``theta`` about ``about`` (the reference point by default).

        Examples
        --------
        >>> Twist.rotation([1.0, 0.0]).rotated(np.pi / 2).pole_xy.round(12)   # the pole turns with it
        array([0., 1.])
        """
        if about is None:
            M = rot(theta)
            _batches(theta=(theta, 0), twist_or_wrench=(self._array, 1))
        else:
            c = as_xy(about, "about")
            _batches(theta=(theta, 0), about=(c, 1), twist_or_wrench=(self._array, 1))
            M = _turn(self._carry, theta, c)
        return self._new("rotated", np.einsum, "...ij,...j->...i", M, self._array)

    @documented
    def at(self, point):
        """The same screw at ``point``: ``X_P v`` (thesis 4.8) or ``X_P⁻ᵀ f`` (4.24, 4.26).

        {parameters point}

        Returns
        -------
        Twist or Wrench

        Examples
        --------
        >>> Twist.rotation([0.0, 0.0], 1.0).at([2.0, 0.0])   # the point (2, 0) moves up at 2
        Twist([0., 2., 1.])
        """
        return self._new("at", np.einsum, "...ij,...j->...i", self._carry(point), self._array)

    def _pair(self, other) -> tuple:
        """``(twist, wrench)`` arrays of this screw and ``other`` of the dual kind."""
        theirs = as_vec3(other, self._dual._name)
        return (self._array, theirs) if self._dual is Wrench else (theirs, self._array)

    @documented
    def power(self, other) -> np.ndarray:
        """Power ``vᵀf`` (W; thesis 5.73) with ``other`` of the dual kind; also ``v @ f``.

        {parameters other returns_scalar}

        Examples
        --------
        >>> float(Twist.translation([2.0, 0.0]).power(Wrench.force([0.0, 5.0], [3.0, 0.0])))   # 2 · 3
        6.0
        """
        return power(*self._pair(other))

    @documented
    def reciprocal(self, other, rtol: float = 1e-12) -> np.ndarray:
        """True where this screw and ``other`` of the dual kind do no power (:func:`reciprocal`).

        {parameters other rtol returns_bool}

        Examples
        --------
        >>> bool(Wrench.couple(1.0).reciprocal(Twist.translation([1.0, 0.0])))   # no work
        True
        """
        return reciprocal(*self._pair(other), rtol)

    def __matmul__(self, other):
        if isinstance(other, self._dual):
            return power(*self._pair(other))
        return NotImplemented

    __rmatmul__ = __matmul__

    def _as_element(self):
        """The projective element this screw is (a twist's pole, a wrench's line; thesis 5.51, 5.56)."""
        cls, attr, noun = self._element
        if self._array.ndim != 1:
            raise ShapeError(f"{self._name} must be a single (3,) {self._name} for .{attr}, got shape {self._array.shape}")
        if not np.any(self._array):
            raise DegenerateGeometryError(f"{self._name} is zero: the zero {self._name} has no {noun}")
        from planargeo.geometry import elements
        return getattr(elements, cls)(self._array)


@documented
class Twist(_Screw):
    """A velocity (or acceleration) twist ``[vx, vy, ω]`` at the origin (thesis 4.6, 5.51).

    It is a point, its pole; ``.at(P)`` is the same motion at ``P``, ``X_P v`` (thesis 4.8).

    Parameters
    ----------
    array : array_like, shape (..., 3), or Twist
        ``[vx, vy, ω]`` (m/s, rad/s); leading dimensions are a batch.  Stored read-only.

    {bad_array}

    Examples
    --------
    >>> v = Twist.rotation([1.0, 2.0], 3.0)
    >>> v, v.pole_xy
    (Twist([ 6., -3.,  3.]), array([1., 2.]))
    >>> (v + Twist.translation([0.0, 3.0])).pole_xy      # thesis 4.16: P = Q + (u/ω) n
    array([0., 2.])
    """

    __slots__ = ()
    _name, _carry = "twist", staticmethod(X_P)
    _element = ("Point", "pole", "pole")

    @classmethod
    @documented
    def rotation(cls, point, omega=1.0) -> "Twist":
        """Rotation ``omega [y, -x, 1]`` about ``point`` (thesis 4.10, 5.51).

        {parameters point}
        omega : float or array_like, optional
            Angular velocity (rad/s), counter-clockwise positive.

        {returns_twist}

        Examples
        --------
        >>> Twist.rotation([1.0, 0.0], 2.0)
        Twist([ 0., -2.,  2.])
        """
        w = as_array(omega, "omega")
        with np.errstate(over="ignore"):
            return cls(check_overflow(unit_rotation(point) * w[..., None], "Twist.rotation", "point or omega"))

    @classmethod
    @documented
    def translation(cls, velocity) -> "Twist":
        """Pure translation ``[vx, vy, 0]`` (a point at infinity).

        Parameters
        ----------
        velocity : array_like, shape (..., 2)
            Linear velocity ``(vx, vy)`` (m/s).

        {returns_twist}

        Examples
        --------
        >>> Twist.translation([0.0, 3.0])
        Twist([0., 3., 0.])
        """
        u = as_xy(velocity, "velocity")
        return cls(np.concatenate([u, np.zeros(u.shape[:-1] + (1,))], axis=-1))

    magnitude = omega = _derived(twist_magnitude, "``ω_z`` (thesis 4.6), signed; 0 for a "
                                                  "translation (whose speed is ``|velocity|``).")
    velocity = _derived(_xy, "Linear velocity ``(vx, vy)`` of the body point at the "
                             "reference point.")
    is_translation = _derived(lambda a: np.asarray(a[..., 2] == 0),
                              "True where ``ω == 0`` (pole at infinity).")
    pole_xy = _derived(pole_xy, "Euclidean pole (thesis 4.10); NaN for translations.")

    @property
    def pole(self):
        """The pole as a :class:`planargeo.geometry.Point` (thesis 5.51); ideal for a translation.

        Raises
        ------
        ShapeError, DegenerateGeometryError
            A batch of twists, or the zero twist.

        Examples
        --------
        >>> Twist.rotation([1.0, 2.0], 3.0).pole
        Point(x=1, y=2)
        """
        return self._as_element()


@documented
class Wrench(_Screw):
    """A force wrench ``[fx, fy, τz]`` at the origin (thesis 4.21), its line of action (5.56).

    It is a line; ``.magnitude`` is ``F = |f|`` (4.22), 0 for a couple, whose strength is
    ``.moment``; ``.at(P)`` is ``X_P⁻ᵀ f`` (thesis 4.24, 4.26).

    Parameters
    ----------
    array : array_like, shape (..., 3), or Wrench
        ``[fx, fy, τz]`` (N, N·m); leading dimensions are a batch.  Stored read-only.

    {bad_array}

    Examples
    --------
    >>> f = Wrench.force([0.0, 1.0], [2.0, 0.0])     # horizontal force along y = 1
    >>> f, float(f.distance)
    (Wrench([ 2.,  0., -2.]), -1.0)
    >>> f + Wrench.couple(2.0)                       # thesis 4.46: shifted by τ/F = 1
    Wrench([2., 0., 0.])
    """

    __slots__ = ()
    _name, _carry = "wrench", staticmethod(X_P_inv_T)
    _element = ("Line", "line", "line of action")

    @classmethod
    @documented
    def force(cls, point, force) -> "Wrench":
        """Pure force ``(fx, fy)`` on the line through ``point``: ``[fx, fy, x fy - y fx]`` (4.27).

        {parameters point}
        force : array_like, shape (..., 2)
            Force ``(fx, fy)`` (N).

        {returns_wrench}

        Examples
        --------
        >>> Wrench.force([2.0, 0.0], [0.0, 1.0])     # upward force along x = 2: moment 2 at the origin
        Wrench([0., 1., 2.])
        """
        p = as_xy(point, "point")
        f = as_xy(force, "force")
        batch_shape(point=(p, 1), force=(f, 1))
        with np.errstate(over="ignore", invalid="ignore"):
            tau = check_overflow(p[..., 0] * f[..., 1] - p[..., 1] * f[..., 0], "Wrench.force", "point or force")
        fx, fy, tau = np.broadcast_arrays(f[..., 0], f[..., 1], tau)
        return cls(np.stack([fx, fy, tau], axis=-1))

    @classmethod
    @documented
    def couple(cls, tau) -> "Wrench":
        """Pure couple ``[0, 0, tau]``: the line at infinity.

        Parameters
        ----------
        tau : float or array_like, shape (...)
            Moment (N·m), counter-clockwise positive.

        {returns_wrench}

        Examples
        --------
        >>> Wrench.couple(-2.0)
        Wrench([ 0.,  0., -2.])
        """
        t = as_array(tau, "tau")
        z = np.zeros(t.shape)
        return cls(np.stack([z, z, t], axis=-1))

    magnitude = _derived(wrench_magnitude,
                         "``F = sqrt(fx² + fy²)`` (thesis 4.22); 0 for a pure couple.")
    force_xy = _derived(_xy, "The force vector ``(fx, fy)``.")
    moment = _derived(lambda a: np.asarray(a[..., 2]), "``τz`` about the reference point.")
    is_couple = _derived(lambda a: np.asarray(np.all(a[..., :2] == 0, axis=-1)),
                         "True where the force part is zero (line at infinity).")
    direction = _derived(lambda a: wrench_axis(a)[0], "Unit direction ``e`` of the line of action "
                                                       "(thesis 4.28); NaN for couples.")
    distance = _derived(lambda a: wrench_axis(a)[1],
                        "Signed distance ``d = τ/F`` of the line from the origin (thesis 4.31).")
    normal = _derived(lambda a: wrench_axis(a)[2], "Unit normal ``n = (fy, -fx)/F`` (thesis 4.32); "
                                                   "the nearest point is ``n d`` (4.30).")

    @property
    def line(self):
        """The line of action as a :class:`planargeo.geometry.Line` (thesis 5.56).

        Raises
        ------
        ShapeError, DegenerateGeometryError
            A batch of wrenches; the zero wrench, which has no line.

        Examples
        --------
        >>> Wrench.force([2.0, 0.0], [0.0, 1.0]).line.array
        array([0., 1., 2.])
        """
        return self._as_element()

    polar = line


Twist._dual, Wrench._dual = Wrench, Twist
for _kind in (Twist, Wrench):            # their own members (for the API pages), one definition
    _kind.at, _kind.power, _kind.reciprocal = _Screw.at, _Screw.power, _Screw.reciprocal
del _kind


# ---------- Twist and wrench addition as constructions (thesis 4.2, 4.4)
def _single(x, name) -> np.ndarray:
    a = as_vec3(x, name)
    if a.ndim != 1:
        raise ShapeError(f"{name} must have shape (3,) for a construction, got shape {a.shape}")
    if not np.any(a):
        raise DegenerateGeometryError(f"{name} must be non-zero, got {a!r}")
    return a


@dataclass(frozen=True)
class TwistSum:
    """Construction of ``v3 = v1 + v2`` (thesis 4.2), for drawing.

    Points and lines are normalised homogeneous arrays (``normalize_point``,
    ``normalize_line``); the pole ``P`` of the sum lies on ``line``, the join of ``Q1`` and ``Q2``.

    Attributes
    ----------
    v1, v2, sum : Twist
        The two twists and their sum.
    case : str
        ``"rotations"`` (4.11-4.13), ``"opposite_rotations"`` (``ω1 = -ω2``),
        ``"rotation_translation"`` (4.16), ``"translations"`` or ``"zero"``.
    Q1, Q2 : ndarray (3,)
        Poles of ``v1`` and ``v2``.
    P : ndarray (3,) or None
        Pole of the sum (None for the zero twist).
    omega1, omega2, omega3 : float
        Magnitudes; ``omega3 = omega1 + omega2`` (4.11).
    beta : float or None
        Lever ratio ``ω2/(ω1+ω2)``, ``P = Q1 + β (Q2 - Q1)`` (4.12-4.13); ``inf`` if opposite.
    rho : float or None
        Offset ``u/ω`` of 4.16: ``P = Q + ρ n``, ``n`` the translation turned by +90°.
    line : ndarray (3,) or None
        Join of ``Q1`` and ``Q2`` (None when they coincide).

    Examples
    --------
    >>> c = add_twists(Twist.rotation([0.0, 0.0], 1.0), Twist.translation([0.0, 2.0]))
    >>> c.case, c.rho, c.sum
    ('rotation_translation', 2.0, Twist([0., 2., 1.]))
    """

    v1: Twist
    v2: Twist
    sum: Twist
    case: str
    Q1: np.ndarray
    Q2: np.ndarray
    P: np.ndarray | None
    omega1: float
    omega2: float
    omega3: float
    beta: float | None
    rho: float | None
    line: np.ndarray | None


def add_twists(v1, v2, rtol: float = 1e-12) -> TwistSum:
    """Add two single twists and describe the construction (thesis 4.11-4.16).

    Parameters
    ----------
    v1, v2 : Twist or array_like (3,)
        Non-zero twists at the origin (a batch raises ShapeError).
    rtol : float
        The poles coincide (``line`` is None) when ``|v1 × v2| <= rtol |v1| |v2|``.

    Returns
    -------
    TwistSum

    Examples
    --------
    >>> c = add_twists(Twist.rotation([0.0, 0.0], 1.0), Twist.rotation([4.0, 0.0], 3.0))
    >>> c.case, c.beta, c.P
    ('rotations', 0.75, array([ 0., -3.,  1.]))
    """
    return _finite_sum(_add_twists, (v1, v2), ("v1", "v2"), rtol)


def _add_twists(a, b, rtol) -> TwistSum:
    s = check_overflow(a + b, "add_twists", "v1 + v2")
    w1, w2, w3 = float(a[2]), float(b[2]), float(s[2])
    beta = rho = None
    if w1 != 0 and w2 != 0:
        if w3 == 0:
            case, beta = "opposite_rotations", float("inf")
        else:
            case, beta = "rotations", w2 / w3
    elif w1 != 0 or w2 != 0:
        case = "rotation_translation"
        w, t = (w1, b) if w1 != 0 else (w2, a)
        rho = float(np.hypot(t[0], t[1])) / w
    else:
        case = "translations" if np.any(s) else "zero"
    line = np.cross(_fit(a), _fit(b))          # the join of the poles: scale-free, rescaled exactly
    if np.linalg.norm(line) <= rtol * np.linalg.norm(_fit(a)) * np.linalg.norm(_fit(b)):
        line = np.zeros(3)
    return TwistSum(
        v1=Twist(a), v2=Twist(b), sum=Twist(s), case=case,
        Q1=normalize_point(a), Q2=normalize_point(b),
        P=normalize_point(s) if np.any(s) else None,
        omega1=w1, omega2=w2, omega3=w3, beta=beta, rho=rho,
        line=normalize_line(line) if np.any(line) else None,
    )


@dataclass(frozen=True)
class WrenchSum:
    """Construction of ``f3 = f1 + f2`` (thesis 4.4), for drawing (arrays as in :class:`TwistSum`).

    The line ``L3`` of the sum passes through ``P``, the meet of ``L1`` and ``L2``.

    Attributes
    ----------
    f1, f2, sum : Wrench
        The two wrenches and their sum.
    case : str
        ``"concurrent"`` (4.4.1), ``"parallel"`` (4.4.2, lever rule), ``"couple"`` (equal opposite
        parallel forces), ``"force_couple"`` (4.4.3), ``"couples"`` or ``"zero"``.
    L1, L2 : ndarray (3,)
        Lines of ``f1`` and ``f2``.
    L3 : ndarray (3,) or None
        Line of the sum (None for the zero wrench).
    P : ndarray (3,) or None
        Meet of ``L1`` and ``L2`` (ideal for parallel lines, None for two couples).
    F1, F2, F3 : float
        Magnitudes ``|f|`` (4.22, 4.39).
    beta : float or None
        Lever ratio ``F2/(F1+F2)`` of 4.44, signed along ``f1`` (parallel case).
    d1, d2, d3 : float or None
        Signed distances ``τ/F`` from the origin along ``f1``'s normal (parallel case, 4.43-4.45).
    rho : float or None
        Shift ``τ/F`` of 4.46 (force + couple), along the force's normal (4.32).

    Examples
    --------
    >>> c = add_wrenches(Wrench.force([0.0, 0.0], [1.0, 0.0]), Wrench.couple(2.0))
    >>> c.case, c.rho, c.L3                  # onto the line y = -2
    ('force_couple', 2.0, array([1., 0., 2.]))
    """

    f1: Wrench
    f2: Wrench
    sum: Wrench
    case: str
    L1: np.ndarray
    L2: np.ndarray
    L3: np.ndarray | None
    P: np.ndarray | None
    F1: float
    F2: float
    F3: float
    beta: float | None
    d1: float | None
    d2: float | None
    d3: float | None
    rho: float | None


def add_wrenches(f1, f2, rtol: float = 1e-12) -> WrenchSum:
    """Add two single wrenches and describe the construction (thesis 4.33-4.46).

    Thesis 4.37 is misprinted (``docs/errata.md``); the meet here is the exact ``L1 × L2``.

    Parameters
    ----------
    f1, f2 : Wrench or array_like, shape (3,)
        Non-zero wrenches at the origin (a batch raises ShapeError).
    rtol : float, optional
        The lines are parallel when ``|f1x f2y - f1y f2x| <= rtol F1 F2``.

    Returns
    -------
    WrenchSum

    Examples
    --------
    >>> c = add_wrenches(Wrench.force([0.0, 0.0], [0.0, 1.0]), Wrench.force([4.0, 0.0], [0.0, 3.0]))
    >>> c.case, c.beta, c.d3                          # lever rule: resultant on x = 3
    ('parallel', 0.75, 3.0)
    """
    return _finite_sum(_add_wrenches, (f1, f2), ("f1", "f2"), rtol)


def _add_wrenches(a, b, rtol) -> WrenchSum:
    s = check_overflow(a + b, "add_wrenches", "f1 + f2")
    F1, F2 = float(np.hypot(a[0], a[1])), float(np.hypot(b[0], b[1]))
    F3 = float(np.hypot(s[0], s[1]))
    beta = d1 = d2 = d3 = rho = None
    meet = np.cross(_fit(a), _fit(b))          # the meet of the lines: scale-free, rescaled exactly
    if F1 > 0 and F2 > 0:
        cr = a[0] * b[1] - a[1] * b[0]
        if abs(cr) <= rtol * F1 * F2:
            e = a[:2] / F1
            meet = np.array([e[1], -e[0], 0.0])    # the common ideal point (direction e)
            s1, s2 = F1, (F2 if e @ b[:2] >= 0 else -F2)
            if s1 + s2 == 0 or F3 == 0:
                case = "couple" if s[2] != 0 else "zero"
                s = np.array([0.0, 0.0, s[2]])
                F3 = 0.0
            else:
                case = "parallel"
                beta = s2 / (s1 + s2)
                d1, d2 = float(a[2]) / s1, float(b[2]) / s2
                d3 = d1 + beta * (d2 - d1)
        else:
            case = "concurrent"
    elif F1 > 0 or F2 > 0:
        case = "force_couple"
        force, cpl = (a, b) if F1 > 0 else (b, a)
        rho = float(cpl[2]) / float(np.hypot(force[0], force[1]))
    else:
        case = "couples" if s[2] != 0 else "zero"
    return WrenchSum(
        f1=Wrench(a), f2=Wrench(b), sum=Wrench(s), case=case,
        L1=normalize_line(a), L2=normalize_line(b),
        L3=normalize_line(s) if np.any(s) else None,
        P=normalize_point(meet) if np.any(meet) else None,
        F1=F1, F2=F2, F3=F3, beta=beta, d1=d1, d2=d2, d3=d3, rho=rho,
    )


def _finite_sum(add, pair, names, rtol):
    """``add(a, b, rtol)`` of two single screws, refused unless finite (β = ∞ of ω1 = -ω2 aside)."""
    a, b = (_single(x, name) for x, name in zip(pair, names))
    with np.errstate(over="ignore", invalid="ignore"):
        c = add(a, b, check_tolerance(rtol))
    for k, v in vars(c).items():
        if v is None or isinstance(v, str) or (k == "beta" and c.case == "opposite_rotations"):
            continue
        if not np.all(np.isfinite(getattr(v, "array", v))):
            raise NumericOverflowError(f"{add.__name__[1:]}: {k} overflows double precision "
                                       f"({' or '.join(names)} too large)")
    return c
