"""Planar screws as arrays: twists ``[vx, vy, wz]`` and wrenches ``[fx, fy, tz]``.

All quantities are expressed at a stated reference point, by default the
global origin, with the linear part first (thesis ordering).  Every function
broadcasts over leading dimensions: vectors are ``(..., 3)``, matrices
``(..., 3, 3)``, Euclidean points ``(..., 2)``.

A twist *is* a point in the package's homogeneous coordinates (its pole, the
instant centre; thesis 5.51), a wrench *is* a line (its polar, the line of
action; thesis 5.56).  See :mod:`planargeo.geometry.projective`.

Finite in, finite out: a result beyond double precision's range raises
:class:`~planargeo.errors.NumericOverflowError` naming the arguments; powers,
energies and magnitudes whose plain evaluation overflows only in an
intermediate step are evaluated rescaled (:func:`planargeo._validate.rescaled`).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from planargeo._validate import (as_array, as_mat3, as_vec3, as_xy, batch_shape, check_overflow, check_positive,
                                 check_positive_semidefinite, check_tolerance, overflow_checked, rescaled)
from planargeo.errors import NumericOverflowError
from planargeo.geometry.projective import _fit, normalize_line, normalize_point, to_xy
from planargeo.screws._docs import documented

__all__ = [
    "X_P", "X_P_inv_T", "rot", "X_frame", "X_frame_inv_T", "rotation_about", "crm", "crf",
    "unit_rotation", "unit_translation", "inertia_matrix",
    "power", "kinetic_energy",
    "twist_magnitude", "pole_xy", "wrench_magnitude", "wrench_axis", "reciprocal",
    "inertia_at", "inertia_transform", "inertia_rotated", "momentum", "kappa", "bias_force",
    "Twist", "Wrench", "TwistSum", "WrenchSum", "add_twists", "add_wrenches",
]


@documented
def X_P(point) -> np.ndarray:
    """Twist transform from the origin to ``point`` (thesis 4.8).

    ``X_P(p) @ v`` is the twist ``v`` (given at the origin) expressed at ``p``.

    Parameters
    ----------
    {point}

    Returns
    -------
    ndarray, shape (..., 3, 3)

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
    """Wrench transform from the origin to ``point`` (thesis 4.24).

    ``X_P_inv_T(p) @ f`` is the wrench ``f`` (given at the origin) expressed
    at ``p``; it equals ``inv(X_P(p)).T``.

    Parameters
    ----------
    {point}

    Returns
    -------
    numpy.ndarray, shape (..., 3, 3)
        ``X_P(point)⁻ᵀ``.

    Examples
    --------
    >>> X_P_inv_T([0.0, 1.0]) @ [1.0, 0.0, 0.0]   # force along x through the origin, moment about (0, 1)
    array([1., 0., 1.])
    """
    return np.ascontiguousarray(np.swapaxes(X_P(-as_xy(point, "point")), -1, -2))     # X_P(p)⁻¹ = X_P(-p)


def rot(theta) -> np.ndarray:
    """Rotation of screw coordinates by ``theta`` about the reference point.

    The same matrix rotates twists and wrenches (it is orthogonal).

    Parameters
    ----------
    theta : array_like, shape (...)
        Angle (rad).

    Returns
    -------
    numpy.ndarray, shape (..., 3, 3)
        The rotation matrix.

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
def X_frame(theta, point) -> np.ndarray:
    """General planar twist transform: translation to ``point``, then rotation by ``theta`` (thesis 1.56, 4.7).

    Thesis 1.56 projected on the plane (``X_2D = Dᵀ X_3D D``, 4.7) with
    ``r_AB = point`` and ``E`` the rotation by ``theta`` about z::

        X = rot(θ) X_P(p) = [[ cos θ, -sin θ,  -(p_y cos θ + p_x sin θ)],
                             [ sin θ,  cos θ,    p_x cos θ - p_y sin θ ],
                             [ 0,      0,        1                     ]]

    ``X @ v`` is the twist ``v`` (given at the origin) expressed at ``point``
    and then rotated by ``theta`` (the coordinates in a frame at ``point``
    whose axes are turned by ``-theta``).  ``theta = 0`` gives :func:`X_P`;
    ``point = (0, 0)`` gives :func:`rot`.

    Parameters
    ----------
    theta : array_like (...)
        Angle of the new frame (rad).
    point : array_like (..., 2)
        Origin of the new frame ``(x, y)`` (m).

    Returns
    -------
    ndarray (..., 3, 3)

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

    ``X_frame_inv_T(θ, p) @ f`` is the wrench ``f`` (given at the origin)
    expressed at ``p`` and rotated by ``θ``; power is preserved:
    ``(X v)ᵀ (X⁻ᵀ f) = vᵀ f``.

    Parameters
    ----------
    theta : array_like, shape (...)
        Angle of the new frame (rad).
    {point}

    Returns
    -------
    numpy.ndarray, shape (..., 3, 3)
        ``rot(θ) X_P⁻ᵀ(p)``.

    Examples
    --------
    >>> np.round(X_frame_inv_T(np.pi / 2, [0.0, 1.0]) @ [1.0, 0.0, 0.0], 12) + 0.0   # X_P⁻ᵀ gives [1, 0, 1]
    array([0., 1., 1.])
    """
    _batches(theta=(theta, 0), point=(point, 1))
    return rot(theta) @ X_P_inv_T(point)


@overflow_checked("theta or about")
def rotation_about(theta, about=(0.0, 0.0)) -> np.ndarray:
    """Twist map of a rigid rotation by ``theta`` about the point ``about`` (active; thesis 4.8, 1.56).

    ``M = X_P(-c) rot(θ) X_P(c)``: express at ``c``, turn, express back at the
    origin.  ``M @ v`` is the twist ``v`` carried along when the plane is
    turned by ``theta`` about ``c`` (its pole turns about ``c``); wrenches are
    carried by ``inv(M).T`` (= ``X_P⁻ᵀ(-c) rot(θ) X_P⁻ᵀ(c)``) and inertias by
    :func:`inertia_rotated`.  With ``about = (0, 0)`` this is :func:`rot`.

    Parameters
    ----------
    theta : array_like, shape (...)
        Angle (rad).
    about : array_like, shape (..., 2), optional
        Centre ``c`` of the rotation (m).

    Returns
    -------
    numpy.ndarray, shape (..., 3, 3)
        ``M`` acting on twists.

    Examples
    --------
    >>> v = unit_rotation([2.0, 0.0])                       # spin about (2, 0)
    >>> pole_xy(rotation_about(np.pi / 2, [1.0, 0.0]) @ v).round(12) + 0.0   # (2, 0) turned about (1, 0)
    array([1., 1.])
    """
    c = as_xy(about, "about")
    _batches(theta=(theta, 0), about=(c, 1))
    return X_P(-c) @ rot(theta) @ X_P(c)


def crm(v) -> np.ndarray:
    """Planar motion cross operator ``v×`` (thesis 2.16 projected, 4.63).

    ``crm(v) @ s`` is the rate of change of a twist ``s`` carried by a body
    moving with twist ``v``; for ``v = [vx, vy, w]``::

        [[0, -w,  vy],
         [w,  0, -vx],
         [0,  0,   0]]

    Parameters
    ----------
    v : array_like, shape (..., 3)
        Twist ``[vx, vy, ω]``.

    Returns
    -------
    numpy.ndarray, shape (..., 3, 3)
        The matrix of ``v×``.

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


def crf(v) -> np.ndarray:
    """Planar force cross operator ``v×* = -(v×)^T`` (dual of :func:`crm`, thesis 3.8).

    ``crf(v) @ f`` is the rate of change of a wrench ``f`` carried by a body
    moving with twist ``v``; for ``v = [vx, vy, w]``::

        [[ 0,   -w,   0],
         [ w,    0,   0],
         [-vy,  vx,   0]]

    Parameters
    ----------
    v : array_like, shape (..., 3)
        Twist ``[vx, vy, ω]``.

    Returns
    -------
    numpy.ndarray, shape (..., 3, 3)
        The matrix of ``v×*``.

    Examples
    --------
    >>> crf([0.0, 0.0, 1.0]) @ [1.0, 0.0, 0.0]   # a force along x, rotated at unit rate about the origin
    array([0., 1., 0.])
    >>> crf([1.0, 0.0, 0.0]) @ [0.0, 1.0, 0.0]   # a force along y carried along x: moment about the origin grows
    array([0., 0., 1.])
    """
    return -np.swapaxes(crm(v), -1, -2)


def unit_rotation(point) -> np.ndarray:
    """Unit twist of a counter-clockwise rotation about ``point`` (thesis 4.10, 5.51).

    For ``point = (x, y)`` this is ``[y, -x, 1]``: the homogeneous point itself.

    Parameters
    ----------
    point : array_like, shape (..., 2)
        The pole ``(x, y)`` (m).

    Returns
    -------
    numpy.ndarray, shape (..., 3)
        ``[y, -x, 1]``.

    Examples
    --------
    >>> unit_rotation([1.0, 2.0])
    array([ 2., -1.,  1.])
    """
    p = as_xy(point, "point")
    return np.stack([p[..., 1], -p[..., 0], np.ones(p.shape[:-1])], axis=-1)


def unit_translation(direction) -> np.ndarray:
    """Unit twist of a translation along ``direction`` (a point at infinity, thesis 5.62).

    The direction is normalised.

    Parameters
    ----------
    direction : array_like, shape (..., 2)
        Direction of the velocity (non-zero).

    Returns
    -------
    numpy.ndarray, shape (..., 3)
        ``[dx, dy, 0] / |d|``.

    Raises
    ------
    DegenerateGeometryError
        If ``direction`` is the zero vector.

    Examples
    --------
    >>> unit_translation([0.0, 2.0])
    array([0., 1., 0.])
    """
    from planargeo.errors import DegenerateGeometryError

    d = _fit(as_xy(direction, "direction"))       # exact rescaling: |d| cannot overflow
    n = np.hypot(d[..., 0], d[..., 1])
    if np.any(n == 0):
        raise DegenerateGeometryError("direction must be non-zero, got a zero vector")
    return np.stack([d[..., 0] / n, d[..., 1] / n, np.zeros(n.shape)], axis=-1)


@overflow_checked("mass, com or inertia_about_com")
def inertia_matrix(mass, com, inertia_about_com) -> np.ndarray:
    """Planar spatial inertia at the origin (thesis 1.68 projected; 4.58, 5.64).

    For mass ``m``, centre of mass ``c = (cx, cy)`` and rotational inertia
    ``J`` about the centre of mass (``J = m ρ²``)::

        [[ m,     0,    -m cy          ],
         [ 0,     m,     m cx          ],
         [-m cy,  m cx,  J + m |c|²    ]]

    Parameters
    ----------
    mass : array_like (...)
        ``m > 0``.
    com : array_like (..., 2)
        Centre of mass ``(cx, cy)`` (m).
    inertia_about_com : array_like (...)
        ``J >= 0`` (``J = 0`` is a point mass: a singular, positive
        semi-definite inertia).

    Returns
    -------
    numpy.ndarray, shape (..., 3, 3)
        The inertia matrix shown above.

    Raises
    ------
    InputError
        ``mass <= 0`` or ``inertia_about_com < 0`` (the message names the
        argument, e.g. ``"mass must be positive, got -1.0"``).

    Examples
    --------
    >>> inertia_matrix(2.0, [1.0, 0.0], 0.5)   # thesis 5.64 with m=2, d=1, ρ²=1/4
    array([[2. , 0. , 0. ],
           [0. , 2. , 2. ],
           [0. , 2. , 2.5]])
    >>> inertia_matrix(-1, [0.0, 0.0], 1.0)
    Traceback (most recent call last):
    ...
    planargeo.errors.InputError: mass must be positive, got -1.0
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
    """Power ``vᵀf`` of a wrench on a twist (thesis 5.73); zero means incidence.

    Parameters
    ----------
    {twist wrench}

    Returns
    -------
    numpy.ndarray, shape (...)
        Power (W).

    Examples
    --------
    >>> power([0.0, 0.0, 1.0], [1.0, 0.0, 0.0])  # force through the pole: no power
    array(0.)
    """
    v = as_vec3(twist, "twist")
    f = as_vec3(wrench, "wrench")
    batch_shape(twist=(v, 1), wrench=(f, 1))
    return np.asarray(rescaled(_dot, (v, f), (1, 1), (1, 1), 0, "power(twist, wrench)", "twist or wrench"))


def _dot(a, b):
    return np.einsum("...i,...i->...", a, b)


@documented
def kinetic_energy(inertia, twist) -> np.ndarray:
    """Kinetic energy ``½ vᵀ I v`` (thesis 1.9), invariant under frame changes.

    Parameters
    ----------
    {inertia twist}

    Returns
    -------
    numpy.ndarray, shape (...)
        Kinetic energy (J).

    Examples
    --------
    A disc (``m = 2``, ``J = 0.5``) centred at ``(1, 0)`` spinning at ``ω = 3``
    about the origin: ``½ (J + m d²) ω² = 11.25``.

    >>> float(kinetic_energy(inertia_matrix(2.0, [1.0, 0.0], 0.5), [0.0, 0.0, 3.0]))
    11.25

    Raises
    ------
    InputError
        ``inertia`` is not symmetric.
    SingularInertiaError
        ``inertia`` has a negative eigenvalue (beyond rounding,
        :data:`planargeo._validate.PSD_RTOL`): no inertia, the energy could be
        negative.  Singular (positive semi-definite) inertias such as point
        masses are accepted.

    >>> kinetic_energy(np.diag([1.0, 1.0, -1.0]), [0.0, 0.0, 1.0])
    Traceback (most recent call last):
    ...
    planargeo.errors.SingularInertiaError: inertia must be positive semi-definite, got smallest eigenvalue -1 (condition number inf)
    """
    I = _inertia_psd(inertia)
    v = as_vec3(twist, "twist")
    batch_shape(inertia=(I, 2), twist=(v, 1))
    return np.asarray(rescaled(lambda I, v: 0.5 * np.einsum("...i,...ij,...j->...", v, I, v), (I, v), (1, 2),
                               (2, 1), 0, "kinetic_energy(inertia, twist)", "inertia or twist"))


def _inertia_psd(inertia, name: str = "inertia") -> np.ndarray:
    """An inertia argument: (..., 3, 3), finite, symmetric, positive semi-definite."""
    return check_positive_semidefinite(as_mat3(inertia, name), name)


# ---------------------------------------------------------------------------
# Scalar features of twists and wrenches (thesis 4.6-4.10, 4.22-4.32)
# ---------------------------------------------------------------------------

@documented
def twist_magnitude(twist) -> np.ndarray:
    """Magnitude ``ω_z`` of a planar twist (thesis 4.6), signed; 0 for a translation.

    Parameters
    ----------
    {twist}

    Returns
    -------
    numpy.ndarray, shape (...)
        ``ω_z`` (rad/s).

    Examples
    --------
    >>> twist_magnitude([1.0, -2.0, 3.0])
    array(3.)
    """
    v = as_vec3(twist, "twist")
    return np.asarray(v[..., 2])


@documented
def pole_xy(twist) -> np.ndarray:
    """Euclidean pole ``(-v_y/ω, v_x/ω)`` of a twist (thesis 4.10).

    The twist *is* its pole (thesis 5.51), so this is
    :func:`planargeo.geometry.projective.to_xy` applied to the twist.  A translation
    (``ω = 0``) has its pole at infinity: NaN is returned (no warning); use
    the homogeneous array itself.

    Parameters
    ----------
    {twist}

    Returns
    -------
    numpy.ndarray, shape (..., 2)
        The pole (m); NaN for translations.

    Examples
    --------
    >>> pole_xy([2.0, -1.0, 1.0])
    array([1., 2.])
    >>> pole_xy([1.0, 0.0, 0.0])
    array([nan, nan])
    """
    return to_xy(as_vec3(twist, "twist"))


@documented
def wrench_magnitude(wrench) -> np.ndarray:
    """Magnitude ``F = sqrt(f_x² + f_y²)`` of a planar wrench (thesis 4.22, 4.29).

    A pure couple has ``F = 0`` (its strength is the moment ``τ_z``).

    Parameters
    ----------
    {wrench}

    Returns
    -------
    numpy.ndarray, shape (...)
        ``F`` (N).

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
    """Direction ``e``, distance ``d`` and normal ``n`` of a wrench's line of action (thesis 4.28-4.32).

    ``e = f/F`` (4.28), ``d = τ_z/F`` (4.31), ``n = (f_y, -f_x)/F`` (4.32);
    the point of the line nearest the origin is ``n d`` (4.30).  For a pure
    couple (line at infinity) ``e`` and ``n`` are NaN and ``d`` is ``±inf``
    (sign of ``τ_z``); for the zero wrench everything is NaN.  No warnings.

    Parameters
    ----------
    {wrench}

    Returns
    -------
    e : ndarray (..., 2)
    d : ndarray (...)
    n : ndarray (..., 2)

    Examples
    --------
    >>> e, d, n = wrench_axis([0.0, 2.0, 4.0])   # vertical force along x = 2
    >>> e, d, n
    (array([0., 1.]), array(2.), array([ 1., -0.]))
    >>> e, d, n = wrench_axis([0.0, 0.0, -1.0])
    >>> d
    array(-inf)
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
    """True where twist and wrench are reciprocal: zero power (thesis 1.9, 5.61, 5.69).

    Geometrically the pole of the twist lies on the line of the wrench.  The
    test is ``|vᵀf| <= rtol * |v| |f|``.

    Parameters
    ----------
    {twist wrench}
    rtol : float, optional
        Relative tolerance of the zero-power test ``|vᵀf| <= rtol |v| |f|``.

    Returns
    -------
    numpy.ndarray of bool, shape (...)
        Whether the pair is reciprocal.

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


# ---------------------------------------------------------------------------
# Inertia frame change, momentum and bias terms (thesis 1.68, 2.19, 3.11, 5.72)
# ---------------------------------------------------------------------------

@overflow_checked("inertia or point")
@documented
def inertia_at(inertia, point) -> np.ndarray:
    """Inertia expressed at ``point`` (thesis 1.68, parallel axis theorem).

    With ``_A X_B = X_P⁻¹`` (origin ``A``, point ``B = P``), 1.68 reads
    ``I_P = X_P⁻ᵀ I X_P⁻¹``: twists at ``P`` are taken back to the origin
    (``X_P⁻¹``), mapped to momenta, and the momenta carried to ``P`` with
    ``X_P⁻ᵀ`` (4.24).  Consequently ``inertia_at(inertia_matrix(m, c, J), P)
    == inertia_matrix(m, c - P, J)``.  For a rotation as well see
    :func:`inertia_transform` (passive) and :func:`inertia_rotated` (active).

    Parameters
    ----------
    {inertia point}

    Returns
    -------
    numpy.ndarray, shape (..., 3, 3)
        ``X_P⁻ᵀ I X_P⁻¹``.

    Raises
    ------
    {not_psd}

    Examples
    --------
    >>> inertia_at(inertia_matrix(2.0, [1.0, 0.0], 0.5), [1.0, 0.0])   # at the centre of mass
    array([[2. , 0. , 0. ],
           [0. , 2. , 0. ],
           [0. , 0. , 0.5]])
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
    """Inertia in the frame of :func:`X_frame`: ``I_B = X⁻ᵀ I X⁻¹`` (thesis 1.68).

    With ``_B X_A = X_frame(θ, p)`` (translation to ``p`` then rotation by
    ``θ``, 1.56 projected), 1.68 reads ``I_B = (_A X_B)ᵀ I_A (_A X_B)`` with
    ``_A X_B = X⁻¹``, i.e. ``I_B = W I Wᵀ`` with ``W = X_frame_inv_T(θ, p)
    = rot(θ) X_P⁻ᵀ(p)``.  Twists and wrenches transformed by ``X`` and ``X⁻ᵀ``
    then give the same momenta and kinetic energy.  ``theta = 0`` is
    :func:`inertia_at`; for a rigid body ``I_B = inertia_matrix(m, rot₂(θ) (c - p), J)``.

    Parameters
    ----------
    inertia : array_like (..., 3, 3)
        Symmetric positive semi-definite (rigid-body or articulated) inertia.
    theta : array_like (...)
        Angle of the new frame (rad).
    point : array_like (..., 2)
        Origin of the new frame (m).

    Returns
    -------
    numpy.ndarray, shape (..., 3, 3)
        ``I_B``.

    Raises
    ------
    {not_psd}

    Examples
    --------
    A body centred at ``(1, 0)`` seen from a frame at the origin turned by
    -90° (``θ = 90°``): its centre is at ``(0, 1)`` there.

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
    """Inertia of the body turned by ``theta`` about ``about`` (thesis 1.68 with :func:`rotation_about`).

    The active counterpart of :func:`inertia_transform`, matching
    :meth:`Twist.rotated`: with ``M = rotation_about(θ, c)`` carrying twists,
    ``I' = M⁻ᵀ I M⁻¹`` so that ``I' (M v) = M⁻ᵀ (I v)`` (the momentum is
    carried along) and ``½ (M v)ᵀ I' (M v) = ½ vᵀ I v``.  For a rigid body the
    centre of mass turns about ``c`` and ``m``, ``J`` are unchanged.  About the
    origin this is ``rot(θ) I rot(θ)ᵀ``, also 1.68 for the pure rotation
    ``X = rot(θ)`` (:func:`inertia_transform` with ``point = (0, 0)``).

    Parameters
    ----------
    inertia : array_like (..., 3, 3)
        Symmetric positive semi-definite (rigid-body or articulated) inertia.
    theta : array_like (...)
        Angle of the rotation (rad), counter-clockwise.
    about : array_like (..., 2), optional
        Centre of the rotation (default the origin).

    Returns
    -------
    numpy.ndarray, shape (..., 3, 3)
        ``I'``.

    Raises
    ------
    {not_psd}

    Examples
    --------
    A body centred at ``(2, 0)`` turned by 90° about ``(1, 0)``: centred at ``(1, 1)``.

    >>> I = inertia_rotated(inertia_matrix(2.0, [2.0, 0.0], 0.5), np.pi / 2, about=[1.0, 0.0])
    >>> np.allclose(I, inertia_matrix(2.0, [1.0, 1.0], 0.5))
    True
    """
    I = _inertia_psd(inertia)
    c = as_xy(about, "about")
    _batches(inertia=(I, 2), theta=(theta, 0), about=(c, 1))
    return _congruence(X_P_inv_T(-c) @ rot(theta) @ X_P_inv_T(c), I)


@overflow_checked("inertia or twist")
@documented
def momentum(inertia, twist) -> np.ndarray:
    """Momentum wrench ``p = I v`` (thesis 1.65, 5.72).

    Its line passes through the centre of mass (thesis 1.60) and ``pᵀa`` is the
    power of the inertial force on ``a`` (5.74).

    Parameters
    ----------
    {inertia twist}

    Returns
    -------
    numpy.ndarray, shape (..., 3)
        Momentum wrench (kg·m/s, kg·m²/s).

    Examples
    --------
    >>> momentum(inertia_matrix(1.0, [0.0, 0.0], 1.0), [1.0, 0.0, 0.0])
    array([1., 0., 0.])

    Raises
    ------
    {not_psd}
    """
    I = _inertia_psd(inertia)
    v = as_vec3(twist, "twist")
    batch_shape(inertia=(I, 2), twist=(v, 1))
    return np.einsum("...ij,...j->...i", I, v)


@overflow_checked("twist, s or qd")
def kappa(twist, s, qd) -> np.ndarray:
    """Bias (convective) acceleration ``κ = ṡ q̇`` of a joint with sequential screws (thesis 2.19, 4.61).

    The columns ``s_1 … s_k`` of ``s`` are *sequential screws* (thesis 2.2):
    column ``j`` is carried by the parent body and by the motions of the
    columns ``1 … j-1`` before it, so it moves with the twist
    ``v + Σ_{l<j} s_l q̇_l`` and (2.14) gives ``ṡ_j = (v + Σ_{l<j} s_l q̇_l) × s_j``.
    Hence::

        κ = Σ_j (v + Σ_{l<j} s_l q̇_l) × s_j q̇_j
          = v × s q̇ + Σ_{l<j} (s_l q̇_l) × (s_j q̇_j)

    For one column (and for columns that commute, e.g. two translations) this
    is the printed ``v × s q̇`` of 2.19/4.61; for a multi-dof joint the printed
    form drops the cross terms (see ``docs/errata.md``: 4.77, and
    Kinematics §1, (2.19)/(3.33)).  Agrees with
    :func:`planargeo.mechanics.kinematics.kinematics` (``Data.kappa``).

    Parameters
    ----------
    twist : array_like (..., 3)
        Velocity ``v_{λ(i)}`` of the parent body (the one that carries the
        joint), at the origin.  Passing the body's own velocity
        ``v_i = v_{λ(i)} + s q̇`` gives the same result, because
        ``(s q̇) × (s q̇) = 0``.
    s : array_like (..., 3, k) or (..., 3)
        Joint motion space at the current configuration, columns **in the
        order the motions are applied** (e.g. slide then turn for
        :func:`planargeo.mechanics.joints.revolute_prismatic`).  A single axis may be
        given as a vector; an array whose last two dimensions are ``(3, 3)``
        is a 3-column motion space.
    qd : array_like (..., k) or (...)
        Joint speeds, in the order of the columns.

    Returns
    -------
    ndarray (..., 3)
        A translation (zero ``ω``).  For one revolute column it lies along the
        line joining the poles of ``v`` and ``s`` (thesis 4.53):
        ``ω q̇ (S - V)`` for normalised poles ``V`` of ``v`` and ``S`` of ``s``.

    Raises
    ------
    ShapeError
        If ``s`` is not ``(..., 3)`` or ``(..., 3, k)``, or ``qd`` does not match its columns.

    Examples
    --------
    Revolute joint, thesis 4.66-4.67 (``v_{i-1} = (1, 2, 0.5)``, ``θ̇ = 3``):

    >>> kappa([1.0, 2.0, 0.5], [0.0, 0.0, 1.0], 3.0)
    array([ 6., -3.,  0.])

    Slide along x by ``u = 1.5`` then turn at ``θ̇ = 2`` about the slid pin at
    ``(0.7, 0)``, parent at rest: the pin's velocity ``u`` turns at ``θ̇``,
    ``κ = u θ̇ (0, -1)`` (the printed 4.77 gives zero):

    >>> kappa([0.0, 0.0, 0.0], [[1.0, 0.0], [0.0, -0.7], [0.0, 1.0]], [1.5, 2.0])
    array([ 0., -3.,  0.])
    """
    v = as_vec3(twist, "twist")
    S = as_array(s, "s")
    q = as_array(qd, "qd")
    if S.ndim >= 1 and S.shape[-1] == 3 and (S.ndim == 1 or S.shape[-2] != 3):
        U = (S * q[..., None])[..., None]
    elif S.ndim >= 2 and S.shape[-2] == 3:
        if q.ndim == 0 or q.shape[-1] != S.shape[-1]:
            from planargeo.errors import ShapeError
            raise ShapeError(f"qd must have shape (..., {S.shape[-1]}) to match s, got shape {q.shape}")
        U = S * q[..., None, :]
    else:
        from planargeo.errors import ShapeError
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
    """Bias force ``p = -(v×)ᵀ I v - g`` (thesis 3.11, 4.56, 4.62).

    ``-(v×)ᵀ = v×*`` (:func:`crf`), so this is ``crf(v) @ I @ v - g``.  For a
    rigid body the velocity part is the centripetal force: a force through the
    centre of mass pointing towards the pole of ``v`` of magnitude ``m l ω²``
    (thesis 4.7).

    Parameters
    ----------
    inertia : array_like (..., 3, 3)
        Inertia at the origin.
    twist : array_like (..., 3)
        Velocity twist of the body.
    g : array_like (..., 3), optional
        External wrench (gravity, loads) at the origin; default zero.

    Returns
    -------
    numpy.ndarray, shape (..., 3)
        The bias wrench (N, N·m).

    Examples
    --------
    Body of mass 1 with its centre at (2, 0) spinning about the origin:

    >>> bias_force(inertia_matrix(1.0, [2.0, 0.0], 1.0), [0.0, 0.0, 1.0])   # m l ω² = 2 towards the origin
    array([-2.,  0.,  0.])

    Raises
    ------
    {not_psd}
    """
    I = _inertia_psd(inertia)
    v = as_vec3(twist, "twist")
    g = None if g is None else as_vec3(g, "g")
    batch_shape(inertia=(I, 2), twist=(v, 1), g=(np.zeros(3) if g is None else g, 1))
    out = np.einsum("...ij,...jk,...k->...i", crf(v), I, v)
    if g is not None:
        out = out - g
    return out


# ---------------------------------------------------------------------------
# Thin classes
# ---------------------------------------------------------------------------

def _batches(**named) -> tuple:
    """:func:`planargeo._validate.batch_shape` of arguments not yet converted (as real arrays, named)."""
    return batch_shape(**{k: (as_array(x, k), nd) for k, (x, nd) in named.items()})


def _is_number(x) -> bool:
    return isinstance(x, (int, float, np.integer, np.floating)) and not isinstance(x, bool)


class _Held:
    """Common base of :class:`Twist`, :class:`Wrench` and :class:`planargeo.screws.Inertia`: one read-only array.

    Equal when the arrays are equal.  Notebooks draw a single value with
    :mod:`planargeo.draw.notebook` (registered by ``import planargeo``); a batch shows its text.
    """

    __slots__ = ("_array",)
    __hash__ = None

    def __array__(self, dtype=None, copy=None):
        return np.asarray(self._array, dtype=dtype)

    def __eq__(self, other):
        if type(other) is not type(self):
            return NotImplemented
        return bool(np.array_equal(self._array, other._array))


class _Screw(_Held):
    """Common base of :class:`Twist` and :class:`Wrench` (one read-only ``(..., 3)`` array), written once through the duality.

    A subclass names itself (``_name``), the matrix ``_carry`` that moves it to another
    reference point (:func:`X_P` for twists, :func:`X_P_inv_T` for wrenches), its dual
    kind ``_dual`` and its projective element ``_element`` (class, property, noun).
    """

    __slots__ = ()
    _name = "screw"

    def __init__(self, array):
        if isinstance(array, _Screw):
            array = array.array
        a = np.array(as_vec3(array, self._name), dtype=float)
        a.flags.writeable = False
        self._array = a

    @property
    def array(self) -> np.ndarray:
        """The screw coordinates (read-only)."""
        return self._array

    @property
    def shape(self) -> tuple:
        """Batch shape (leading dimensions)."""
        return self._array.shape[:-1]

    def __repr__(self) -> str:
        body = np.array2string(self._array, separator=", ", precision=6, suppress_small=True)
        return f"{type(self).__name__}({body})"

    def _new(self, array, op: str):
        return type(self)(check_overflow(array, f"{type(self).__name__} {op}", "a coordinate"))

    def __add__(self, other):
        if type(other) is not type(self):
            return NotImplemented
        with np.errstate(over="ignore", invalid="ignore"):
            return self._new(self._array + other._array, "+")

    def __sub__(self, other):
        if type(other) is not type(self):
            return NotImplemented
        with np.errstate(over="ignore", invalid="ignore"):
            return self._new(self._array - other._array, "-")

    def __neg__(self):
        return type(self)(-self._array)

    def __mul__(self, k):
        if not _is_number(k) and not (isinstance(k, np.ndarray) and k.ndim == 0):
            return NotImplemented
        with np.errstate(over="ignore", invalid="ignore"):
            return self._new(self._array * float(k), "*")

    __rmul__ = __mul__

    def rotated(self, theta, about=None):
        """The screw turned by ``theta`` about ``about`` (default the reference point, matrix :func:`rot`).

        Twists are carried by :func:`rotation_about` ``M``, wrenches by
        ``M⁻ᵀ``, so power is unchanged; about the reference point both are
        :func:`rot`.  Inertias turn with :meth:`planargeo.screws.inertia.Inertia.rotated`.

        Examples
        --------
        >>> Twist.rotation([1.0, 0.0]).rotated(np.pi / 2).pole_xy.round(12)   # the pole turns with it
        array([0., 1.])
        >>> Wrench.force([2.0, 0.0], [0.0, 1.0]).rotated(np.pi, about=[1.0, 0.0]).line.array.round(12) + 0.0
        array([ 0., -1.,  0.])
        """
        if about is None:
            M = rot(theta)
            _batches(theta=(theta, 0), twist_or_wrench=(self._array, 1))
        else:
            c = as_xy(about, "about")
            _batches(theta=(theta, 0), about=(c, 1), twist_or_wrench=(self._array, 1))
            M = self._carry(-c) @ rot(theta) @ self._carry(c)
        with np.errstate(over="ignore", invalid="ignore"):
            return self._new(np.einsum("...ij,...j->...i", M, self._array), "rotated")

    def at(self, point):
        """The same screw expressed at ``point``: a twist ``X_P v`` (thesis 4.8), a wrench ``X_P⁻ᵀ f`` (4.24, 4.26).

        Parameters
        ----------
        point : array_like, shape (..., 2)
            New reference point (m).

        Returns
        -------
        Twist or Wrench
            The same kind, at ``point``.

        Examples
        --------
        >>> Twist.rotation([0.0, 0.0], 1.0).at([2.0, 0.0])   # the point (2, 0) moves up at 2
        Twist([0., 2., 1.])
        >>> Wrench.force([2.0, 0.0], [0.0, 1.0]).at([2.0, 0.0])   # no moment about a point of the line
        Wrench([0., 1., 0.])
        """
        with np.errstate(over="ignore", invalid="ignore"):
            return self._new(np.einsum("...ij,...j->...i", self._carry(point), self._array), "at")

    @classmethod
    def _coords(cls, x) -> np.ndarray:
        """The coordinates of ``x``, a screw of this kind or its array (validated, named by the kind)."""
        return as_vec3(x.array if isinstance(x, cls) else x, cls._name)

    def _pair(self, other) -> tuple:
        """``(twist, wrench)`` arrays of this screw and ``other``, of the dual kind (a screw or its array)."""
        theirs = self._dual._coords(other)
        return (self._array, theirs) if self._dual is Wrench else (theirs, self._array)

    def power(self, other) -> np.ndarray:
        """Power ``vᵀf`` (thesis 5.73) with ``other``, a screw of the dual kind; also ``v @ f`` (either order).

        Parameters
        ----------
        other : Wrench (of a twist), Twist (of a wrench), or array_like, shape (..., 3)
            Wrench ``[fx, fy, τz]`` (N, N·m), or twist ``[vx, vy, ω]`` (m/s, rad/s).

        Returns
        -------
        numpy.ndarray, shape (...)
            Power (W): :func:`power` of the twist and the wrench, whichever is this screw.

        Examples
        --------
        >>> float(Twist.translation([2.0, 0.0]).power(Wrench.force([0.0, 5.0], [3.0, 0.0])))   # 2 · 3
        6.0
        >>> float(Wrench.couple(2.0).power(Twist.rotation([5.0, 5.0], 3.0)))   # τ ω
        6.0
        """
        return power(*self._pair(other))

    def reciprocal(self, other, rtol: float = 1e-12) -> np.ndarray:
        """True where the wrench does no power on the twist (the pole on the line), of this screw and ``other``.

        Parameters
        ----------
        other : Wrench (of a twist), Twist (of a wrench), or array_like, shape (..., 3)
            The screw of the dual kind.
        rtol : float, optional
            Relative tolerance of the zero-power test ``|vᵀf| <= rtol |v| |f|``.

        Returns
        -------
        numpy.ndarray of bool, shape (...)
            Whether the power is zero within ``rtol``.

        Examples
        --------
        >>> bool(Twist.rotation([1.0, 1.0]).reciprocal(Wrench.force([1.0, 0.0], [0.0, 1.0])))  # line x = 1
        True
        >>> bool(Wrench.couple(1.0).reciprocal(Twist.translation([1.0, 0.0])))   # a couple does no work on a translation
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
            from planargeo.errors import ShapeError
            raise ShapeError(f"{self._name} must be a single (3,) {self._name} for .{attr}, got shape {self._array.shape}")
        if not np.any(self._array):
            from planargeo.errors import DegenerateGeometryError
            raise DegenerateGeometryError(f"{self._name} is zero: the zero {self._name} has no {noun}")
        from planargeo.geometry import elements
        return getattr(elements, cls)(self._array)


@documented
class Twist(_Screw):
    """A planar velocity (or acceleration) twist ``[vx, vy, ω]`` at the origin (thesis 4.6).

    A twist *is* its pole in homogeneous coordinates (thesis 5.51): ``.pole``
    returns that point.  The zero twist (no motion) is a legal value but has
    no pole.  Build one from its coordinates, or by name with :meth:`rotation`
    and :meth:`translation`; ``.at(P)`` is the same motion at the point ``P``,
    ``X_P v`` (thesis 4.8).

    Parameters
    ----------
    array : array_like, shape (..., 3), or Twist
        The coordinates ``[vx, vy, ω]`` at the origin: the velocity of the point at the
        origin (m/s) and the angular velocity (rad/s, counter-clockwise positive); leading
        dimensions are a batch of twists.  Stored as a read-only copy.

    Raises
    ------
    {bad_array}

    Examples
    --------
    >>> v = Twist.rotation([1.0, 2.0], 3.0)
    >>> v
    Twist([ 6., -3.,  3.])
    >>> v.pole_xy
    array([1., 2.])
    >>> (v + Twist.translation([0.0, 3.0])).pole_xy      # thesis 4.16: P = Q + (u/ω) n
    array([0., 2.])
    >>> float(v @ Wrench.force([1.0, 2.0], [1.0, 1.0]))  # a force through the pole: no power
    0.0
    """

    __slots__ = ()
    _name = "twist"
    _carry = staticmethod(X_P)
    _element = ("Point", "pole", "pole")

    @classmethod
    def rotation(cls, point, omega=1.0) -> "Twist":
        """Rotation at rate ``omega`` (counter-clockwise positive) about ``point`` (thesis 4.10, 5.51).

        Parameters
        ----------
        point : array_like, shape (..., 2)
            The pole (m).
        omega : float or array_like, optional
            Angular velocity (rad/s), counter-clockwise positive.

        Returns
        -------
        Twist
            ``omega * [y, -x, 1]``.

        Examples
        --------
        >>> Twist.rotation([1.0, 0.0], 2.0)      # ω [y, -x, 1]
        Twist([ 0., -2.,  2.])
        """
        w = as_array(omega, "omega")
        with np.errstate(over="ignore"):
            return cls(check_overflow(unit_rotation(point) * w[..., None], "Twist.rotation", "point or omega"))

    @classmethod
    def translation(cls, velocity) -> "Twist":
        """Pure translation with linear velocity ``velocity = (vx, vy)`` (a point at infinity).

        Parameters
        ----------
        velocity : array_like, shape (..., 2)
            Linear velocity ``(vx, vy)`` (m/s).

        Returns
        -------
        Twist
            ``[vx, vy, 0]``.

        Examples
        --------
        >>> t = Twist.translation([0.0, 3.0])
        >>> t, bool(t.is_translation)
        (Twist([0., 3., 0.]), True)
        """
        u = as_xy(velocity, "velocity")
        return cls(np.concatenate([u, np.zeros(u.shape[:-1] + (1,))], axis=-1))

    @property
    def magnitude(self) -> np.ndarray:
        """``ω_z`` (thesis 4.6), signed; 0 for a translation (whose speed is ``|velocity|``)."""
        return twist_magnitude(self._array)

    omega = magnitude

    @property
    def velocity(self) -> np.ndarray:
        """Linear velocity ``(vx, vy)`` of the body point at the reference point."""
        return self._array[..., :2].copy()

    @property
    def is_translation(self) -> np.ndarray:
        """True where ``ω == 0`` (pole at infinity)."""
        return np.asarray(self._array[..., 2] == 0)

    @property
    def pole_xy(self) -> np.ndarray:
        """Euclidean pole (thesis 4.10); NaN for translations."""
        return pole_xy(self._array)

    @property
    def pole(self):
        """The pole as a :class:`planargeo.geometry.Point` (the array itself, thesis 5.51).

        Raises
        ------
        ShapeError
            If this is a batch of twists.
        DegenerateGeometryError
            If the twist is zero.

        Examples
        --------
        >>> Twist.rotation([1.0, 2.0], 3.0).pole
        Point(x=1, y=2)
        """
        return self._as_element()


@documented
class Wrench(_Screw):
    """A planar force wrench ``[fx, fy, τz]`` at the origin (thesis 4.21).

    A wrench *is* its line of action (polar) in homogeneous coordinates
    (thesis 5.56): ``.line`` returns that line.

    Magnitude choice: ``.magnitude`` is ``F = |f|`` (thesis 4.22) also for a
    pure couple, where it is 0; a couple's strength is its moment ``.moment``
    (``τz``, the same at every point).  ``.distance`` of a couple is ``±inf``.
    Build one from its coordinates, or by name with :meth:`force` and :meth:`couple`;
    ``.at(P)`` is the same load at the point ``P``, ``X_P⁻ᵀ f`` (thesis 4.24, 4.26).

    Parameters
    ----------
    array : array_like, shape (..., 3), or Wrench
        The coordinates ``[fx, fy, τz]`` at the origin: the force (N) and its moment about
        the origin (N m, counter-clockwise positive); leading dimensions are a batch of
        wrenches.  Stored as a read-only copy.

    Raises
    ------
    {bad_array}

    Examples
    --------
    >>> f = Wrench.force([0.0, 1.0], [2.0, 0.0])     # horizontal force along y = 1
    >>> f
    Wrench([ 2.,  0., -2.])
    >>> float(f.magnitude), float(f.distance), f.normal
    (2.0, -1.0, array([ 0., -1.]))
    >>> f + Wrench.couple(2.0)                       # thesis 4.46: shifted by τ/F = 1
    Wrench([2., 0., 0.])
    """

    __slots__ = ()
    _name = "wrench"
    _carry = staticmethod(X_P_inv_T)
    _element = ("Line", "line", "line of action")

    @classmethod
    def force(cls, point, force) -> "Wrench":
        """Pure force ``force = (fx, fy)`` acting along the line through ``point``.

        The moment at the origin is ``x fy - y fx`` (so that 4.27 holds at ``point``).

        Parameters
        ----------
        point : array_like, shape (..., 2)
            A point of the line of action (m).
        force : array_like, shape (..., 2)
            Force ``(fx, fy)`` (N).

        Returns
        -------
        Wrench
            ``[fx, fy, x fy - y fx]``.

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
    def couple(cls, tau) -> "Wrench":
        """Pure couple of moment ``tau`` (counter-clockwise positive): the line at infinity.

        Parameters
        ----------
        tau : float or array_like, shape (...)
            Moment (N·m), counter-clockwise positive.

        Returns
        -------
        Wrench
            ``[0, 0, tau]``.

        Examples
        --------
        >>> c = Wrench.couple(-2.0)
        >>> c, bool(c.is_couple), float(c.magnitude), float(c.moment)
        (Wrench([ 0.,  0., -2.]), True, 0.0, -2.0)
        """
        t = as_array(tau, "tau")
        z = np.zeros(t.shape)
        return cls(np.stack([z, z, t], axis=-1))

    @property
    def magnitude(self) -> np.ndarray:
        """``F = sqrt(fx² + fy²)`` (thesis 4.22); 0 for a pure couple."""
        return wrench_magnitude(self._array)

    @property
    def force_xy(self) -> np.ndarray:
        """The force vector ``(fx, fy)``."""
        return self._array[..., :2].copy()

    @property
    def moment(self) -> np.ndarray:
        """``τz`` about the reference point."""
        return np.asarray(self._array[..., 2])

    @property
    def is_couple(self) -> np.ndarray:
        """True where the force part is zero (line at infinity)."""
        return np.asarray(np.all(self._array[..., :2] == 0, axis=-1))

    @property
    def direction(self) -> np.ndarray:
        """Unit direction ``e`` of the line of action (thesis 4.28); NaN for couples."""
        return wrench_axis(self._array)[0]

    @property
    def distance(self) -> np.ndarray:
        """Signed distance ``d = τ/F`` of the line from the origin (thesis 4.31)."""
        return wrench_axis(self._array)[1]

    @property
    def normal(self) -> np.ndarray:
        """Unit normal ``n = (fy, -fx)/F`` (thesis 4.32); the nearest point is ``n d`` (4.30)."""
        return wrench_axis(self._array)[2]

    @property
    def line(self):
        """The line of action (polar) as a :class:`planargeo.geometry.Line` (thesis 5.56).

        Raises
        ------
        ShapeError
            If this is a batch of wrenches.
        DegenerateGeometryError
            If the wrench is zero.

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


# ---------------------------------------------------------------------------
# Twist and wrench addition as constructions (thesis 4.2, 4.4)
# ---------------------------------------------------------------------------


def _single(x, cls, name) -> np.ndarray:
    a = as_vec3(x.array if isinstance(x, cls) else x, name)
    if a.ndim != 1:
        from planargeo.errors import ShapeError
        raise ShapeError(f"{name} must have shape (3,) for a construction, got shape {a.shape}")
    if not np.any(a):
        from planargeo.errors import DegenerateGeometryError
        raise DegenerateGeometryError(f"{name} must be non-zero, got {a!r}")
    return a


@dataclass(frozen=True)
class TwistSum:
    """Construction of ``v3 = v1 + v2`` (thesis 4.2), for drawing.

    Points and lines are normalised homogeneous arrays in the package's
    coordinates (:func:`planargeo.geometry.projective.normalize_point` /
    :func:`~planargeo.geometry.projective.normalize_line`: finite points with ``w = 1``,
    ideal points and finite lines with unit length, the line at infinity
    ``[0, 0, ±1]`` keeping the sign of the couple); wrap them with ``Point(...)`` / ``Line(...)`` to draw.  The pole
    ``P`` of the sum always lies on ``line`` (the join of ``Q1`` and ``Q2``).

    Attributes
    ----------
    v1, v2, sum : Twist
        The two twists and their sum.
    case : str
        ``"rotations"`` (4.11-4.13), ``"opposite_rotations"`` (``ω1 = -ω2``:
        a translation perpendicular to ``Q1Q2``, ``beta = inf``),
        ``"rotation_translation"`` (4.16, always a rotation),
        ``"translations"`` (sum of the velocities; ``"zero"`` when they cancel).
    Q1, Q2 : ndarray (3,)
        Poles of ``v1`` and ``v2`` (ideal for translations).
    P : ndarray (3,) or None
        Pole of the sum (None for the zero twist).
    omega1, omega2, omega3 : float
        Magnitudes; ``omega3 = omega1 + omega2`` (4.11).
    beta : float or None
        Lever ratio ``ω2/(ω1+ω2)`` with ``P = Q1 + β (Q2 - Q1)`` (4.12-4.13);
        ``inf`` for opposite rotations, None when a translation is involved.
    rho : float or None
        Offset ``u/ω`` of 4.16 (rotation + translation), with ``P = Q + ρ n``,
        ``n`` the translation direction turned by +90°.
    line : ndarray (3,) or None
        Join of ``Q1`` and ``Q2`` (None when they coincide).

    Examples
    --------
    A unit rotation about the origin plus a translation along y at 2
    (thesis 4.16): a rotation about the pole shifted by ``ρ = u/ω = 2``
    along ``n = (-1, 0)``, i.e. about ``(-2, 0)``.

    >>> c = add_twists(Twist.rotation([0.0, 0.0], 1.0), Twist.translation([0.0, 2.0]))
    >>> c.case, c.rho, c.sum
    ('rotation_translation', 2.0, Twist([0., 2., 1.]))
    >>> from planargeo.geometry.projective import to_xy
    >>> to_xy(c.P)
    array([-2.,  0.])
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
    """Add two twists and describe the construction (thesis 4.11-4.16).

    Single twists only (a construction is one drawing): a batch raises
    :class:`~planargeo.errors.ShapeError`; for many sums add the arrays (or
    ``Twist`` batches) directly.

    Parameters
    ----------
    v1, v2 : Twist or array_like (3,)
        Non-zero twists at the origin.
    rtol : float
        The poles count as coincident (``line`` is None) when
        ``|v1 × v2| <= rtol |v1| |v2|``.

    Returns
    -------
    TwistSum

    Examples
    --------
    >>> c = add_twists(Twist.rotation([0.0, 0.0], 1.0), Twist.rotation([4.0, 0.0], 3.0))
    >>> c.case, c.beta, c.P
    ('rotations', 0.75, array([ 0., -3.,  1.]))
    >>> add_twists(Twist.rotation([0.0, 0.0], 1.0), Twist.rotation([4.0, 0.0], -1.0)).sum
    Twist([0., 4., 0.])
    """
    a = _single(v1, Twist, "v1")
    b = _single(v2, Twist, "v2")
    with np.errstate(over="ignore", invalid="ignore"):
        return _finite_sum(_add_twists(a, b, check_tolerance(rtol)), "add_twists", "v1 or v2")


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
    """Construction of ``f3 = f1 + f2`` (thesis 4.4), for drawing.

    Lines and points are normalised homogeneous arrays (see :class:`TwistSum`).
    The line ``L3`` of the sum always passes through ``P``, the meet of ``L1``
    and ``L2``.

    Attributes
    ----------
    f1, f2, sum : Wrench
        The two wrenches and their sum.
    case : str
        ``"concurrent"`` (4.4.1: two forces meeting at ``P``),
        ``"parallel"`` (4.4.2: lever rule, ``P`` ideal),
        ``"couple"`` (opposite parallel forces of equal size: a pure couple),
        ``"force_couple"`` (4.4.3: the force shifted by ``rho = τ/F``),
        ``"couples"`` (two couples), ``"zero"`` (the sum vanishes).
    L1, L2 : ndarray (3,)
        Lines of ``f1`` and ``f2``.
    L3 : ndarray (3,) or None
        Line of the sum (None for the zero wrench).
    P : ndarray (3,) or None
        Meet of ``L1`` and ``L2`` (ideal for parallel lines, None for two couples).
    F1, F2, F3 : float
        Magnitudes ``|f|`` (4.22, 4.39).
    beta : float or None
        Lever ratio ``F2/(F1+F2)`` of 4.44 with signed magnitudes along the
        direction of ``f1`` (parallel case only).
    d1, d2, d3 : float or None
        Signed distances ``τ/F`` from the origin along the normal
        ``n = (sin λ, -cos λ)`` of ``f1``'s direction ``λ`` (parallel case, 4.43-4.45).
    rho : float or None
        Shift ``τ/F`` of 4.46 (force + couple), along the force's normal ``n`` (4.32).

    Examples
    --------
    A unit force along the x axis plus a couple of 2 (thesis 4.46): the force
    shifted by ``ρ = τ/F = 2`` along ``n = (0, -1)``, onto the line ``y = -2``.

    >>> c = add_wrenches(Wrench.force([0.0, 0.0], [1.0, 0.0]), Wrench.couple(2.0))
    >>> c.case, c.rho, c.L3
    ('force_couple', 2.0, array([1., 0., 2.]))
    >>> c.sum.line.foot
    Point(x=0, y=-2)
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
    """Add two wrenches and describe the construction (thesis 4.33-4.46).

    Two force lines are treated as parallel when
    ``|f1x f2y - f1y f2x| <= rtol F1 F2``.

    Single wrenches only (a construction is one drawing): ``f1`` and ``f2``
    must have shape ``(3,)`` (a batch raises :class:`~planargeo.errors.ShapeError`);
    for many sums add the arrays (or ``Wrench`` batches) directly.

    Note: thesis 4.37 is misprinted (see ``docs/errata.md``); the meet
    point here is the exact ``L1 × L2``.

    Parameters
    ----------
    f1, f2 : Wrench or array_like, shape (3,)
        Non-zero wrenches at the origin.
    rtol : float, optional
        Tolerance of the parallel test.

    Returns
    -------
    WrenchSum
        The sum and the construction that draws it (case, meet point, lines).

    Examples
    --------
    >>> c = add_wrenches(Wrench.force([0.0, 0.0], [1.0, 0.0]), Wrench.force([0.0, 2.0], [0.0, 1.0]))
    >>> c.case, c.P                                   # x-axis meets the y-axis at the origin
    ('concurrent', array([0., 0., 1.]))
    >>> c = add_wrenches(Wrench.force([0.0, 0.0], [0.0, 1.0]), Wrench.force([4.0, 0.0], [0.0, 3.0]))
    >>> c.case, c.beta, c.d3                          # lever rule: resultant on x = 3
    ('parallel', 0.75, 3.0)
    """
    a = _single(f1, Wrench, "f1")
    b = _single(f2, Wrench, "f2")
    with np.errstate(over="ignore", invalid="ignore"):
        return _finite_sum(_add_wrenches(a, b, check_tolerance(rtol)), "add_wrenches", "f1 or f2")


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


def _finite_sum(c, what: str, culprits: str):
    """The construction ``c`` if every number in it is finite (``beta = inf`` of opposite rotations aside)."""
    for k, v in vars(c).items():
        if v is None or isinstance(v, str) or (k == "beta" and c.case == "opposite_rotations"):
            continue
        if not np.all(np.isfinite(getattr(v, "array", v))):
            raise NumericOverflowError(f"{what}: {k} overflows double precision ({culprits} too large)")
    return c
