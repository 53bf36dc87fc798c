"""Planar screws as arrays: twists ``[vx, vy, wz]`` and wrenches ``[fx, fy, tz]``.

All quantities are expressed at a stated reference point, by default the
global origin, with the linear part first (thesis ordering).  Every function
broadcasts over leading dimensions: vectors are ``(..., 3)``, matrices
``(..., 3, 3)``, Euclidean points ``(..., 2)``.

A twist *is* a point in the package's homogeneous coordinates (its pole, the
instant centre; thesis 5.51), a wrench *is* a line (its polar, the line of
action; thesis 5.56).  See :mod:`planargeo.projective`.
"""
from __future__ import annotations

import numpy as np

from ._validate import as_array, as_vec3, as_xy

__all__ = [
    "X_P", "X_P_inv_T", "rot", "crm", "crf",
    "unit_rotation", "unit_translation", "inertia_matrix",
    "power", "kinetic_energy",
]


def X_P(point) -> np.ndarray:
    """Twist transform from the origin to ``point`` (thesis 4.8).

    ``X_P(p) @ v`` is the twist ``v`` (given at the origin) expressed at ``p``.

    Parameters
    ----------
    point : array_like, shape (..., 2)

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


def X_P_inv_T(point) -> np.ndarray:
    """Wrench transform from the origin to ``point`` (thesis 4.24).

    ``X_P_inv_T(p) @ f`` is the wrench ``f`` (given at the origin) expressed
    at ``p``; it equals ``inv(X_P(p)).T``.

    Examples
    --------
    >>> X_P_inv_T([0.0, 1.0]) @ [1.0, 0.0, 0.0]   # force along x through the origin, moment about (0, 1)
    array([1., 0., 1.])
    """
    p = as_xy(point, "point")
    out = np.zeros(p.shape[:-1] + (3, 3))
    out[..., 0, 0] = out[..., 1, 1] = out[..., 2, 2] = 1.0
    out[..., 2, 0] = p[..., 1]
    out[..., 2, 1] = -p[..., 0]
    return out


def rot(theta) -> np.ndarray:
    """Rotation of screw coordinates by ``theta`` about the reference point.

    The same matrix rotates twists and wrenches (it is orthogonal).

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


def crm(v) -> np.ndarray:
    """Planar motion cross operator ``v×`` (thesis 2.16 projected, 4.63).

    ``crm(v) @ s`` is the rate of change of a twist ``s`` carried by a body
    moving with twist ``v``; for ``v = [vx, vy, w]``::

        [[0, -w,  vy],
         [w,  0, -vx],
         [0,  0,   0]]

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
    """Planar force cross operator ``v×* = -(v×)^T`` (dual of :func:`crm`, thesis 3.8)."""
    return -np.swapaxes(crm(v), -1, -2)


def unit_rotation(point) -> np.ndarray:
    """Unit twist of a counter-clockwise rotation about ``point`` (thesis 4.10, 5.51).

    For ``point = (x, y)`` this is ``[y, -x, 1]``: the homogeneous point itself.

    Examples
    --------
    >>> unit_rotation([1.0, 2.0])
    array([ 2., -1.,  1.])
    """
    p = as_xy(point, "point")
    return np.stack([p[..., 1], -p[..., 0], np.ones(p.shape[:-1])], axis=-1)


def unit_translation(direction) -> np.ndarray:
    """Unit twist of a translation along ``direction`` (a point at infinity, thesis 5.62).

    The direction is normalised; a zero direction raises :class:`~planargeo.errors.DegenerateGeometryError`.

    Examples
    --------
    >>> unit_translation([0.0, 2.0])
    array([0., 1., 0.])
    """
    from .errors import DegenerateGeometryError

    d = as_xy(direction, "direction")
    n = np.hypot(d[..., 0], d[..., 1])
    if np.any(n == 0):
        raise DegenerateGeometryError("direction must be non-zero, got a zero vector")
    return np.stack([d[..., 0] / n, d[..., 1] / n, np.zeros(n.shape)], axis=-1)


def inertia_matrix(mass, com, inertia_about_com) -> np.ndarray:
    """Planar spatial inertia at the origin (thesis 1.68 projected; 4.58, 5.64).

    For mass ``m``, centre of mass ``c = (cx, cy)`` and rotational inertia
    ``J`` about the centre of mass (``J = m ρ²``)::

        [[ m,     0,    -m cy          ],
         [ 0,     m,     m cx          ],
         [-m cy,  m cx,  J + m |c|²    ]]

    No validation of positivity here; :class:`planargeo.Inertia` validates.

    Examples
    --------
    >>> inertia_matrix(2.0, [1.0, 0.0], 0.5)   # thesis 5.64 with m=2, d=1, ρ²=1/4
    array([[2. , 0. , 0. ],
           [0. , 2. , 2. ],
           [0. , 2. , 2.5]])
    """
    m = as_array(mass, "mass")
    c = as_xy(com, "com")
    J = as_array(inertia_about_com, "inertia_about_com")
    shape = np.broadcast_shapes(m.shape, c.shape[:-1], J.shape)
    out = np.zeros(shape + (3, 3))
    cx, cy = c[..., 0], c[..., 1]
    out[..., 0, 0] = m
    out[..., 1, 1] = m
    out[..., 0, 2] = out[..., 2, 0] = 0.0 - m * cy
    out[..., 1, 2] = out[..., 2, 1] = m * cx
    out[..., 2, 2] = J + m * (cx * cx + cy * cy)
    return out


def power(twist, wrench) -> np.ndarray:
    """Power ``vᵀf`` of a wrench on a twist (thesis 5.73); zero means incidence.

    Examples
    --------
    >>> power([0.0, 0.0, 1.0], [1.0, 0.0, 0.0])  # force through the pole: no power
    array(0.)
    """
    v = as_vec3(twist, "twist")
    f = as_vec3(wrench, "wrench")
    return np.asarray(np.einsum("...i,...i->...", v, f))


def kinetic_energy(inertia, twist) -> np.ndarray:
    """Kinetic energy ``½ vᵀ I v`` (thesis 1.9), invariant under frame changes."""
    I = as_array(inertia, "inertia", (3, 3))
    v = as_vec3(twist, "twist")
    return np.asarray(0.5 * np.einsum("...i,...ij,...j->...", v, I, v))
