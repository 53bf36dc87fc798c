"""Conics as symmetric 3×3 matrices: polarity, classification, constructions (thesis 5.2).

Functions broadcast; tolerances are relative ``rtol`` arguments; arguments are rescaled exactly
where a product could overflow.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from planargeo._validate import (as_array, as_mat3, as_vec3, as_xy, batch_shape, check_overflow, check_positive,
                                 check_symmetric, check_tolerance, overflow_checked, rescaled)
from planargeo.errors import DegenerateGeometryError, InputError, ShapeError
from planargeo.geometry._docs import entries
from planargeo.geometry.projective import T_STD, _cross, _first_index, _fit, _refuse_zero, _safe_div

__all__ = [
    "polar", "pole", "conic_residual", "is_on_conic", "ConicType", "classify", "centre",
    "line_conic_intersections", "tangents_from_point",
    "ExteriorConstruction", "InteriorConstruction",
    "polar_construction_exterior", "polar_construction_interior",
    "correlation", "decompose_point", "decompose_line", "special_base",
    "decompose_point_special", "decompose_line_special",
    "drawable_conic", "AffineFrame", "affine_frame", "conic_from_affine",
    "conic_circle", "conic_ellipse", "conic_hyperbola", "conic_parabola", "conic_from_coefficients",
]

#: Docstring entries many functions here share, each said once (a line ``{C p}`` in a docstring).
_shared = entries({
    "C": "C : array_like, shape (..., 3, 3)\n    Symmetric conic matrix (for an inertia: the 3x3 inertia matrix).",
    "p": "p : array_like, shape (..., 3)\n    Homogeneous points.",
    "l": "l : array_like, shape (..., 3)\n    Homogeneous lines.",
    "rtol_on": "rtol : float, optional\n"
               "    Tolerance for \"on the conic\" (:func:`line_conic_intersections`).",
    "rtol_base": "rtol : float, optional\n"
                 "    The base counts as singular when its condition number exceeds ``1/rtol``.",
    "decomposed_P": "P : array_like, shape (..., 3)\n    The point to decompose.",
    "decomposed_L": "L : array_like, shape (..., 3)\n    The line to decompose.",
    "components": "Returns\n-------\nnumpy.ndarray, shape (..., 3)\n    The components ``(u1, u2, u3)``.",
    "special_base": "Q1, Q2, Q3 : array_like, shape (..., 3)\n    A special base of ``C`` (from :func:`special_base`).",
    "not_special": "Raises\n------\nDegenerateGeometryError\n"
                   "    If a denominator is zero (the points are not a special base of ``C``).",
    "centre": "centre : array_like, shape (2,)\n    Centre (m).",
    "ellipse_axes": "axes : array_like, shape (2,)\n    Semi-axes ``(a, b)`` (m).\n"
                    "angle : float, optional\n    Angle of the first semi-axis from +x (rad).",
    "hyperbola_axes": "axes : array_like, shape (2,)\n    Transverse and conjugate semi-axes ``(a, b)`` (m).\n"
                      "angle : float, optional\n    Angle of the transverse axis from +x (rad).",
    "parabola": "vertex : array_like, shape (2,)\n    Vertex (m).\n"
                "focal_length : float\n    Distance ``f`` from the vertex to the focus (m).\n"
                "angle : float, optional\n    Rotation of the parabola's frame from the axes (rad).",
    "conic_matrix": "Returns\n-------\nnumpy.ndarray, shape (3, 3)\n    The conic matrix.",
})


# --------------------------------------------------------------------------- helpers
def _conic(C, name: str = "C") -> np.ndarray:
    C = as_mat3(C, name)
    check_symmetric(C, name)
    return C


def _mv(M, v):
    return np.einsum("...ij,...j->...i", M, v)


def _quad(u, M, v):
    return np.einsum("...i,...ij,...j->...", u, M, v)


def _fitq(x, core: int = 1) -> np.ndarray:
    """:func:`~planargeo.geometry.projective._fit` for quadratic forms: entries within ``(1e-90, 1e90)``."""
    return _fit(x, core, 1e-90, 1e90)


def _check_invertible(M, name: str, what: str, rtol: float) -> None:
    s = np.linalg.svd(_fitq(M, 2), compute_uv=False)
    cond = np.full(s.shape[:-1], np.inf)
    np.divide(s[..., 0], s[..., -1], out=cond, where=s[..., -1] > 0)
    with np.errstate(invalid="ignore"):        # inf · 0: singular whatever the tolerance
        bad = ~(cond * check_tolerance(rtol) < 1.0)
    if np.any(bad):
        c = float(np.max(np.where(bad, cond, 0.0)))
        err = DegenerateGeometryError(f"{name} is {what}{_first_index(bad)} "
                                      f"(condition number {c:.3g})")
        err.cond = c
        raise err


def _unit(v):
    """Scale homogeneous vectors to unit length (zero and NaN rows pass through silently)."""
    with np.errstate(invalid="ignore"):
        v = _fit(v, tiny=0.5, huge=1.0)            # exact: largest component in [0.5, 1), so |v| cannot overflow
    n = np.linalg.norm(v, axis=-1)
    out = np.full(v.shape, np.nan)
    np.divide(v, n[..., None], out=out, where=(n != 0)[..., None])
    return np.where(np.isnan(n)[..., None] | (n != 0)[..., None], out, v)


def _npoint(p):
    """Normalise points (w = 1, or unit length if ideal), letting NaN and zero through silently."""
    p = _unit(p)
    w = np.where(p[..., 2] != 0, p[..., 2], np.linalg.norm(p, axis=-1))
    return _safe_div(p, w[..., None]) + 0.0


def _nline(l):
    """Normalise lines (|f| = 1, or tz = ±1 for the line at infinity), letting NaN through."""
    f = np.hypot(l[..., 0], l[..., 1])
    return _safe_div(l, np.where(f != 0, f, np.abs(l[..., 2]))[..., None]) + 0.0


# --------------------------------------------------------------------------- polarity
@_shared
def polar(C, p) -> np.ndarray:
    """Polar line ``C p`` of point ``p`` (thesis 5.36): an inertia's percussion axis (5.64-5.68).

    {parameters C p}

    Returns
    -------
    numpy.ndarray, shape (..., 3)
        ``C p``, not normalised.

    Examples
    --------
    >>> polar(conic_circle([0.0, 0.0], 1.0), [0.0, -2.0, 1.0])          # the point (2, 0): x = 1/2
    array([ 0., -2., -1.])
    """
    C = _conic(C)
    p = as_vec3(p, "p")
    batch_shape(C=(C, 2), p=(p, 1))
    return rescaled(_mv, (C, p), (1, 1), (2, 1), 1, "polar(C, p)", "C or p")


@_shared
def pole(C, l, rtol: float = 1e-13) -> np.ndarray:
    """Pole ``C⁻¹ l`` of line ``l`` (thesis 5.37), solved: of an inertia, the acceleration.

    {parameters C l}
    rtol : float, optional
        ``C`` counts as singular when its condition number exceeds ``1/rtol``.

    Returns
    -------
    numpy.ndarray, shape (..., 3)
        ``C⁻¹ l``, not normalised.

    Raises
    ------
    DegenerateGeometryError
        ``C`` singular (poles not unique); carries ``.cond``.

    Examples
    --------
    >>> pole(conic_circle([0.0, 0.0], 1.0), [0.0, -2.0, -1.0])   # the line x = 1/2
    array([ 0., -2.,  1.])
    """
    C = _conic(C)
    l = as_vec3(l, "l")
    batch_shape(C=(C, 2), l=(l, 1))
    _check_invertible(C, "C", "singular (a degenerate conic), so poles are not unique", rtol)

    def solve(C, l):
        C, l = np.broadcast_arrays(C, l[..., None, :])
        return np.linalg.solve(C, l[..., 0, :][..., None])[..., 0]

    return rescaled(solve, (C, l), (-1, 1), (2, 1), 1, "pole(C, l)", "l, or C⁻¹,")


@_shared
def conic_residual(C, p) -> np.ndarray:
    """The quadratic form ``p @ C @ p`` (thesis 5.38); zero on the conic.

    {parameters C p returns_scalar}

    Examples
    --------
    >>> float(conic_residual(conic_circle([0.0, 0.0], 2.0), [0.0, -2.0, 1.0]))  # (2, 0)
    0.0
    """
    C = _conic(C)
    p = as_vec3(p, "p")
    batch_shape(C=(C, 2), p=(p, 1))
    return rescaled(lambda C, p: _quad(p, C, p), (C, p), (1, 2), (2, 1), 0, "conic_residual(C, p)", "C or p")


@_shared
def is_on_conic(C, p, rtol: float = 1e-9) -> np.ndarray:
    """True where ``|p C p| <= rtol |C| |p|²`` (relative form of thesis 5.38).

    {parameters C p}
    rtol : float, optional
        Relative tolerance of the test.

    {returns_bool}

    Examples
    --------
    >>> bool(is_on_conic(conic_circle([1.0, 1.0], 1.0), [1.0, -2.0, 1.0]))   # (2, 1)
    True
    """
    C = _fitq(_conic(C), 2)                  # the test does not depend on C's scale
    p = _unit(as_vec3(p, "p"))
    batch_shape(C=(C, 2), p=(p, 1))
    r = np.abs(_quad(p, C, p))
    with np.errstate(over="ignore"):        # a tolerance near 1.8e308 accepts everything
        return r <= check_tolerance(rtol) * np.linalg.norm(C, axis=(-2, -1))


# --------------------------------------------------------------------------- classification
@dataclass(frozen=True)
class ConicType:
    """Result of :func:`classify`; ``str`` gives e.g. ``'real ellipse'``.

    Attributes
    ----------
    reality : str
        ``"real"``, ``"imaginary"`` (definite, like an inertia) or ``"degenerate"``.
    kind : str
        ``"ellipse"``, ``"parabola"``, ``"hyperbola"``; degenerate: ``"line pair"``, ``"point"``,
        ``"double line"`` or ``"zero"``.
    is_circle : bool
        An ellipse whose quadratic part is isotropic.
    rank : int
        Rank of the matrix.

    Examples
    --------
    >>> classify(conic_ellipse([0.0, 0.0], [2.0, 1.0]))
    ConicType(reality='real', kind='ellipse', is_circle=False, rank=3)
    """

    reality: str
    kind: str
    is_circle: bool
    rank: int

    def __str__(self) -> str:
        name = "circle" if self.is_circle else self.kind
        return name if self.reality == "degenerate" else f"{self.reality} {name}"


def _classify1(S: np.ndarray, rtol: float) -> ConicType:
    ev = np.linalg.eigvalsh(S)
    top = np.max(np.abs(ev))
    if top == 0:
        return ConicType("degenerate", "zero", False, 0)
    nz = np.abs(ev) > rtol * top
    rank = int(nz.sum())
    pos, neg = int((ev[nz] > 0).sum()), int((ev[nz] < 0).sum())
    if rank == 3:
        a = np.linalg.eigvalsh(S[1:, 1:])
        amax = np.max(np.abs(a))
        circle = False
        if np.min(np.abs(a)) <= rtol * amax or amax <= rtol * top:
            kind = "parabola"
        elif a[0] * a[1] > 0:
            kind = "ellipse"
            circle = bool(a[1] - a[0] <= rtol * amax)
        else:
            kind = "hyperbola"
        reality = "imaginary" if (pos == 3 or neg == 3) else "real"
        return ConicType(reality, kind, circle, 3)
    if rank == 2:
        return ConicType("degenerate", "line pair" if pos == neg else "point", False, 2)
    return ConicType("degenerate", "double line", False, 1)


@_shared
def classify(C, rtol: float = 1e-10):
    """Classify a conic (thesis 5.2.2): real / imaginary / degenerate, and its kind.

    In standard coordinates ``S = T C T`` (5.47), with ``A = S[1:, 1:]``: ``det S = 0`` is
    degenerate, ``S`` definite imaginary, else ``det A`` > 0, < 0, = 0 an ellipse, hyperbola,
    parabola (eigenvalues below ``rtol`` relative count as zero).

    {parameters C}
    rtol : float
        Relative tolerance below which an eigenvalue counts as zero.

    Returns
    -------
    ConicType, or an object ndarray of them for a batch.

    Examples
    --------
    >>> str(classify(np.diag([2.0, 1.0, 5.0])))       # an inertia-like matrix
    'imaginary ellipse'
    """
    C = _fitq(_conic(C), 2)                  # the kind does not depend on C's scale
    rtol = check_tolerance(rtol)
    S = T_STD @ C @ T_STD
    if S.ndim == 2:
        return _classify1(S, rtol)
    flat = S.reshape(-1, 3, 3)
    out = np.empty(len(flat), dtype=object)
    for i, s in enumerate(flat):
        out[i] = _classify1(s, rtol)
    return out.reshape(S.shape[:-2])


@_shared
def centre(C) -> np.ndarray:
    """Centre of a conic, normalised: the pole of the line at infinity (thesis 5.2.2).

    ``C[0] × C[1]``: ideal for a parabola, the vertex of a line pair, an inertia's centre of mass.

    {parameters C returns_3}

    Raises
    ------
    DegenerateGeometryError
        The centre is not unique (a double line, two parallel lines).

    Examples
    --------
    >>> centre(conic_circle([1.0, 2.0], 3.0))      # the point (1, 2)
    array([ 2., -1.,  1.])
    """
    C = _fitq(_conic(C), 2)                  # the centre does not depend on C's scale
    z = _cross(_fitq(C[..., 0, :]), _fitq(C[..., 1, :]))
    bad = np.all(z == 0, axis=-1)
    if np.any(bad):
        raise DegenerateGeometryError(f"C has no unique centre{_first_index(bad)} "
                                      "(a double line or a pair of parallel lines)")
    return check_overflow(_npoint(z), "centre(C)", "the centre's coordinates")


# --------------------------------------------------------------------------- intersections, tangents
def _intersections(C, l, rtol):
    """Raw intersections (unit length rows) of validated lines with validated conics."""
    C, l = np.broadcast_arrays(C, l[..., None, :])
    l = l[..., 0, :]
    k = np.argmax(np.abs(l), axis=-1)
    eye = np.eye(3)
    a = _unit(_cross(l, eye[(k + 1) % 3]))
    b = _unit(_cross(l, eye[(k + 2) % 3]))
    A, B, G = _quad(a, C, a), _quad(a, C, b), _quad(b, C, b)
    on = np.maximum(np.maximum(np.abs(A), np.abs(B)), np.abs(G)) <= rtol * np.linalg.norm(C, axis=(-2, -1))
    if np.any(on):
        raise DegenerateGeometryError(f"the line lies on the degenerate conic C{_first_index(on)}: "
                                      "every one of its points is an intersection")
    D = B * B - A * G
    scale = B * B + np.abs(A * G)
    D = np.where((D < 0) & (D >= -rtol * scale), 0.0, D)
    real = D >= 0
    sq = np.sqrt(np.where(real, D, 0.0))
    q = -(B + np.where(B < 0, -1.0, 1.0) * sq)
    X1 = q[..., None] * a + A[..., None] * b
    X2 = G[..., None] * a + q[..., None] * b
    z1 = np.all(X1 == 0, axis=-1, keepdims=True)
    z2 = np.all(X2 == 0, axis=-1, keepdims=True)
    X1, X2 = np.where(z1, X2, X1), np.where(z2, X1, X2)
    X = np.stack([X1, X2], axis=-2)
    X = np.where(real[..., None, None], X, np.nan)
    return _unit(X), real


@_shared
def line_conic_intersections(C, l, rtol: float = 1e-9):
    """The two points where line ``l`` meets conic ``C`` (thesis 5.38 on a line).

    {parameters C l}
    rtol : float, optional
        A discriminant negative by less than ``rtol`` of its scale counts as zero (a tangent).

    Returns
    -------
    points : ndarray, shape (..., 2, 3)
        Normalised points; NaN where not real; a tangent gives the contact point twice.
    real : ndarray of bool, shape (...)

    Examples
    --------
    >>> X, real = line_conic_intersections(conic_circle([0.0, 0.0], 1.0), [1.0, 0.0, 0.0])
    >>> bool(real), sorted(X[:, 1].round(12).tolist())    # x axis meets the unit circle at x = ±1
    (True, [-1.0, 1.0])
    """
    C = _fitq(_conic(C), 2)
    l = as_vec3(l, "l")
    batch_shape(C=(C, 2), l=(l, 1))
    _refuse_zero(l, "l", "line")
    X, real = _intersections(C, _unit(l), check_tolerance(rtol))
    return check_overflow(_npoint(X), "line_conic_intersections(C, l)", "the points'", ok=~real[..., None, None]), real


@_shared
def tangents_from_point(C, p, on_interior: str = "raise", rtol: float = 1e-9):
    """The two tangents from a point to a conic and their contact points (thesis 5.2.2, 5.39).

    {parameters C p}
    on_interior : {"raise", "nan"}
        For a point with no real tangents: raise :class:`InputError`, or give NaN rows.
    {rtol_on}

    Returns
    -------
    lines : ndarray, shape (..., 2, 3)
        Normalised tangents.
    points : ndarray, shape (..., 2, 3)
        Normalised contact points (row ``i`` on ``lines[i]``).

    Raises
    ------
    InputError, DegenerateGeometryError
        Bad ``on_interior``, or (``"raise"``) no real tangents; ``p`` a degenerate conic's vertex.

    Examples
    --------
    >>> L, X = tangents_from_point(conic_circle([0.0, 0.0], 1.0), [0.0, -2.0, 1.0])   # from (2, 0)
    >>> np.round(X[:, :2] * [1, -1], 6)[:, ::-1]      # contacts at (1/2, ±√3/2)
    array([[ 0.5     ,  0.866025],
           [ 0.5     , -0.866025]])
    """
    if on_interior not in ("raise", "nan"):
        raise InputError(f"on_interior must be 'raise' or 'nan', got {on_interior!r}")
    C = _fitq(_conic(C), 2)                  # tangents and contacts do not depend on the scales
    p = _fitq(as_vec3(p, "p"))
    batch_shape(C=(C, 2), p=(p, 1))
    _refuse_zero(p, "p", "point")
    L = _mv(C, p)
    bad = np.all(L == 0, axis=-1)
    if np.any(bad):
        raise DegenerateGeometryError(f"p is the vertex of the degenerate conic C{_first_index(bad)}: "
                                      "its polar is undefined")
    X, real = _intersections(C, _unit(L), check_tolerance(rtol))
    if on_interior == "raise" and not np.all(real):
        raise InputError(f"p has no real tangents to C{_first_index(~real)}: it lies inside the conic "
                         "(or C is imaginary); use on_interior='nan' to get NaN instead")
    T = _tangents_at(C[..., None, :, :], X, real, "contact point", -1)
    nan = ~real[..., None, None]
    return (check_overflow(_nline(T), "tangents_from_point(C, p)", "the tangents' distance", ok=nan),
            check_overflow(_npoint(X), "tangents_from_point(C, p)", "the contact points'", ok=nan))


@dataclass(frozen=True)
class ExteriorConstruction:
    """The steps of the polar construction of an exterior point (thesis 5.2.2, Fig. 5.2).

    Attributes
    ----------
    point : ndarray, shape (..., 3)
        The point ``p``.
    tangents : ndarray, shape (..., 2, 3)
        Step 1: the two tangents from ``p``.
    contacts : ndarray, shape (..., 2, 3)
        Step 2: their contact points.
    polar : ndarray, shape (..., 3)
        Step 3: the join of the contacts, ``C p`` (5.36).

    Examples
    --------
    >>> K = polar_construction_exterior(conic_circle([0.0, 0.0], 1.0), [0.0, -2.0, 1.0])  # p = (2, 0)
    >>> K.contacts[:, 1]                                 # at x = 1/2
    array([-0.5, -0.5])
    """

    point: np.ndarray
    tangents: np.ndarray
    contacts: np.ndarray
    polar: np.ndarray


@dataclass(frozen=True)
class InteriorConstruction:
    """The steps of the polar construction of an interior point (thesis 5.2.2, Fig. 5.3).

    Attributes
    ----------
    point : ndarray, shape (..., 3)
        The point ``p``, inside the conic.
    lines : ndarray, shape (..., 2, 3)
        Step 1: two lines through ``p``.
    chord_points : ndarray, shape (..., 2, 2, 3)
        Step 1: where line ``i`` cuts the conic.
    tangents : ndarray, shape (..., 2, 2, 3)
        Step 2: the tangents there.
    poles : ndarray, shape (..., 2, 3)
        Steps 3-4: where each pair meets, the pole of line ``i`` (Theorem 12).
    polar : ndarray, shape (..., 3)
        Step 5: the join of the two poles, ``C p`` (5.36).

    Examples
    --------
    >>> K = polar_construction_interior(conic_circle([0.0, 0.0], 2.0), [0.0, -1.0, 1.0])  # p = (1, 0)
    >>> K.poles[1]                                       # x = 1 has its pole at (4, 0)
    array([ 0., -4.,  1.])
    """

    point: np.ndarray
    lines: np.ndarray
    chord_points: np.ndarray
    tangents: np.ndarray
    poles: np.ndarray
    polar: np.ndarray


@_shared
def polar_construction_exterior(C, p, on_interior: str = "raise", rtol: float = 1e-9) -> ExteriorConstruction:
    """The polar of an exterior point constructed (thesis 5.2.2, Fig. 5.2): its tangents' contacts.

    {parameters C p}
    on_interior : {"raise", "nan"}, optional
        For a point with no real tangents (:func:`tangents_from_point`).
    {rtol_on}

    Returns
    -------
    ExteriorConstruction

    Examples
    --------
    >>> K = polar_construction_exterior(conic_circle([0.0, 0.0], 1.0), [0.0, -2.0, 1.0])
    >>> K.polar                                  # x = 1/2, as C p
    array([ 0. , -1. , -0.5])
    """
    C = _fitq(_conic(C), 2)
    p = _fitq(as_vec3(p, "p"))
    T, X = tangents_from_point(C, p, on_interior=on_interior, rtol=rtol)
    Xu = _unit(X)
    Lj = _cross(Xu[..., 0, :], Xu[..., 1, :])
    same = np.all(Lj == 0, axis=-1, keepdims=True)
    Lj = np.where(same, T[..., 0, :], Lj)
    Lj, P = _like_polar(Lj, C, p)
    return _checked(ExteriorConstruction(_npoint(P), T, X, _nline(Lj)), "polar_construction_exterior",
                    on_interior == "nan")


@_shared
def polar_construction_interior(C, p, lines=None, on_miss: str = "raise", rtol: float = 1e-9) -> InteriorConstruction:
    """The polar of an interior point constructed (thesis 5.2.2, Fig. 5.3): two chords' poles.

    {parameters C p}
    lines : array_like, shape (..., 2, 3), optional
        Two distinct lines through ``p`` (default: two of ``p × e_i``).
    on_miss : {"raise", "nan"}
        A line that does not cut the conic in two real points raises, or gives NaN.
    rtol : float
        Relative tolerance of "through ``p``" and of a tangent.

    Returns
    -------
    InteriorConstruction

    Raises
    ------
    InputError, DegenerateGeometryError
        Bad ``on_miss``, a line not through ``p`` or (with ``"raise"``) missing ``C``; ``p`` zero,
        the two lines the same, or a chord point a vertex of a degenerate conic.

    Examples
    --------
    >>> K = polar_construction_interior(conic_circle([0.0, 0.0], 2.0), [0.0, -1.0, 1.0])  # (1, 0)
    >>> K.polar                                  # x = 4, as C p
    array([ 0., -1., -4.])
    """
    if on_miss not in ("raise", "nan"):
        raise InputError(f"on_miss must be 'raise' or 'nan', got {on_miss!r}")
    C = _fitq(_conic(C), 2)
    p = _fitq(as_vec3(p, "p"))
    rtol = check_tolerance(rtol)
    batch_shape(C=(C, 2), p=(p, 1))
    if lines is None:
        k = np.argmax(np.abs(p), axis=-1)
        eye = np.eye(3)
        lines = np.stack([_cross(p, eye[(k + 1) % 3]), _cross(p, eye[(k + 2) % 3])], axis=-2)
        if np.any(np.all(p == 0, axis=-1)):
            raise DegenerateGeometryError("p is the zero vector, which is no point")
    else:
        lines = _fitq(as_array(lines, "lines", (2, 3)))
        batch_shape(p=(p, 1), lines=(lines, 2))
        inc = np.abs(np.einsum("...i,...ki->...k", p, lines))
        scale = np.linalg.norm(lines, axis=-1) * np.linalg.norm(p, axis=-1)[..., None]
        off = inc > rtol * scale
        if np.any(off):
            j = tuple(np.argwhere(off)[0])
            raise InputError(f"lines[{j[-1]}] does not pass through p: |lines[{j[-1]}] · p| = "
                             f"{float(inc[j]):.3g} > rtol |lines[{j[-1]}]| |p| = {float(rtol * scale[j]):.3g}")
    X, real = _intersections(C[..., None, :, :], _unit(lines), rtol)
    distinct = real & ~np.all(_cross(X[..., 0, :], X[..., 1, :]) == 0, axis=-1)
    if on_miss == "raise" and not np.all(distinct):
        i = int(np.argwhere(~distinct)[0][-1])
        raise InputError(f"lines[{i}] does not cut C in two distinct real points "
                         "(p is not interior, or the line is tangent)")
    T = _nline(_tangents_at(C[..., None, None, :, :], X, distinct, "chord point", (-2, -1)))
    poles = _unit(_cross(_unit(T[..., 0, :]), _unit(T[..., 1, :])))
    polar_ = _cross(poles[..., 0, :], poles[..., 1, :])
    bad = np.all(polar_ == 0, axis=-1) & np.all(distinct, axis=-1)
    if np.any(bad):
        raise DegenerateGeometryError(f"lines[0] and lines[1] are the same line{_first_index(bad)}")
    polar_, P = _like_polar(polar_, C, p)
    return _checked(InteriorConstruction(_npoint(P), _nline(lines), _npoint(X), T, _npoint(poles), _nline(polar_)),
                    "polar_construction_interior", on_miss == "nan")


def _tangents_at(C, X, real, what: str, axes) -> np.ndarray:
    """The tangents ``C X`` at points ``X`` of the conic (a degenerate conic's vertex refused)."""
    T = _mv(C, X)
    vertex = real[..., None] & np.all(T == 0, axis=-1)
    if np.any(vertex):
        raise DegenerateGeometryError(f"a {what} is the vertex of the degenerate conic C"
                                      f"{_first_index(np.any(vertex, axis=axes))}, where the tangent is undefined")
    return T


def _like_polar(L, C, p):
    """``L`` oriented like the polar ``C p``, and ``p`` broadcast to it."""
    s = np.einsum("...i,...i->...", L, _mv(C, p))
    L = np.where((s < 0)[..., None], -L, L)
    return L, np.broadcast_to(p, L.shape)


def _checked(construction, what: str, nan_asked: bool):
    """The construction, unless an element is not finite (NaN only where ``"nan"`` was asked for)."""
    for x in vars(construction).values():
        check_overflow(x, what, "an element's coordinates", ok=np.isnan(x) if nan_asked else None)
    return construction


# --------------------------------------------------------------------------- duality
@_shared
def correlation(C, Q, L, rtol: float = 1e-13):
    """Theorem 12's correlation ``(pole(C, L), polar(C, Q))``, with ``P @ M == Q @ L`` (5.40-5.41).

    Theorem 12 (corrected to the direction of 5.36-5.37): if ``L`` passes through ``Q``, the pole
    ``P`` lies on the polar ``M``.

    {parameters C}
    Q : array_like, shape (..., 3)
        A point.
    L : array_like, shape (..., 3)
        A line.
    rtol : float, optional
        Singularity tolerance of the pole (:func:`pole`).

    Returns
    -------
    P : ndarray, shape (..., 3)
    M : ndarray, shape (..., 3)

    Examples
    --------
    >>> P, M = correlation(np.diag([2.0, 1.0, 3.0]), [1.0, 2.0, 3.0], [4.0, 5.0, 6.0])
    >>> float(P @ M), 1 * 4 + 2 * 5 + 3 * 6
    (32.0, 32)
    """
    return pole(C, L, rtol=rtol), polar(C, Q)


def _scaled_base(Q1, Q2, Q3) -> tuple[list, np.ndarray]:
    """The three base points, validated and scaled by :func:`_pow2`, and their exponents ``(..., 3)``."""
    (Q1, e1), (Q2, e2), (Q3, e3) = (_pow2(as_vec3(x, n)) for x, n in ((Q1, "Q1"), (Q2, "Q2"), (Q3, "Q3")))
    return [Q1, Q2, Q3], np.stack(np.broadcast_arrays(e1, e2, e3), axis=-1)


def _base(Q) -> np.ndarray:
    """The matrix ``[Q1, Q2, Q3]`` (columns) of three points, broadcast over their batches."""
    batch_shape(Q1=(Q[0], 1), Q2=(Q[1], 1), Q3=(Q[2], 1))
    return np.stack(np.broadcast_arrays(*Q), axis=-1)


def _pow2(a: np.ndarray, core: int = 1) -> tuple[np.ndarray, np.ndarray]:
    """``a``, each vector (``core=2``: matrix) beyond ``(1e-90, 1e90)`` times ``2^-e``; ``e``."""
    with np.errstate(invalid="ignore"):
        m = np.abs(a).max(axis=tuple(range(-core, 0)))
        keep = ((m > 1e-90) & (m < 1e90)) | (m == 0) | ~np.isfinite(m)
    e = np.where(keep, 0, np.frexp(m)[1])
    if not e.any():
        return a, e
    return np.ldexp(a, -e.reshape(e.shape + (1,) * core)), e


def _back(u: np.ndarray, e: np.ndarray, what: str, culprits: str) -> np.ndarray:
    """Components ``u`` of scaled arguments times ``2^e`` (exact), or a NumericOverflowError."""
    if np.any(e):
        with np.errstate(over="ignore", under="ignore"):
            u = np.ldexp(u, np.broadcast_to(e, u.shape))
    return check_overflow(u, what, culprits)


def _solve_basis(Mcols, v, name: str, rtol: float):
    """The solution ``u`` of ``Mcols u = v``, refusing a numerically singular base."""
    batch_shape(**{name: (Mcols, 2), "the decomposed element": (v, 1)})
    _check_invertible(Mcols, name, "singular: the three base elements are dependent (no basis)", rtol)
    Mcols, v = np.broadcast_arrays(Mcols, v[..., None, :])
    try:
        with np.errstate(all="ignore"):
            u = np.linalg.solve(Mcols, v[..., 0, :][..., None])[..., 0]
    except np.linalg.LinAlgError:
        u = np.full(v.shape[:-2] + (3,), np.nan)
    if not np.isfinite(u).all():
        raise DegenerateGeometryError(f"{name} is singular: the three base elements are dependent (no basis)"
                                      f"{_first_index(~np.isfinite(u).all(axis=-1))} (it cannot be solved "
                                      "in double precision)")
    return u


@_shared
def decompose_point(P, Q1, Q2, Q3, rtol: float = 1e-13) -> np.ndarray:
    """Components ``u`` of ``P = u1 Q1 + u2 Q2 + u3 Q3`` (thesis 5.42).

    {parameters decomposed_P}
    Q1, Q2, Q3 : array_like, shape (..., 3)
        Three non-collinear base points.
    {rtol_base}

    {components}

    Raises
    ------
    DegenerateGeometryError
        If ``Q1, Q2, Q3`` are collinear.

    Examples
    --------
    >>> decompose_point([1.0, 2.0, 3.0], [1.0, 0, 0], [0, 1.0, 0], [1.0, 1.0, 1.0])
    array([-2., -1.,  3.])
    """
    P, eP = _pow2(as_vec3(P, "P"))
    Q, e = _scaled_base(Q1, Q2, Q3)
    u = _solve_basis(_base(Q), P, "[Q1, Q2, Q3]", rtol)   # u_i = 2^(eP - ei) times that of the scaled ones
    return _back(u, eP[..., None] - e, "decompose_point", "P or the base too large or too small")


@_shared
def decompose_line(C, L, Q1, Q2, Q3, rtol: float = 1e-13) -> np.ndarray:
    """Components ``u`` of ``L = u1 C Q1 + u2 C Q2 + u3 C Q3`` (thesis 5.43).

    {parameters C decomposed_L}
    Q1, Q2, Q3 : array_like, shape (..., 3)
        Three non-collinear base points (base lines: their polars).
    {rtol_base}

    {components}

    Raises
    ------
    DegenerateGeometryError
        If the base lines ``C Qi`` are concurrent.

    Examples
    --------
    >>> C = np.diag([1.0, 2.0, 4.0])
    >>> decompose_line(C, C @ [1.0, 2.0, 3.0], [1.0, 0, 0], [0, 1.0, 0], [1.0, 1.0, 1.0])
    array([-2., -1.,  3.])
    """
    C, eC = _pow2(_conic(C), 2)
    L, eL = _pow2(as_vec3(L, "L"))
    Q, e = _scaled_base(Q1, Q2, Q3)
    Q = _base(Q)
    batch_shape(C=(C, 2), L=(L, 1), Q=(Q, 2))
    with np.errstate(under="ignore"):
        CQ = C @ Q                                        # entries below 1 times entries below 1: no overflow
    u = _solve_basis(CQ, L, "[C Q1, C Q2, C Q3]", rtol)   # u_i = 2^(eL - eC - ei) times the scaled one's
    return _back(u, (eL - eC)[..., None] - e, "decompose_line", "L, C or the base too large or too small")


@overflow_checked("C or Q1")
@_shared
def special_base(C, Q1, rtol: float = 1e-9):
    """The special base of Fig. 5.4: ``Q1`` exterior, ``Q2, Q3`` its tangents' contact points.

    {parameters C}
    Q1 : array_like, shape (..., 3)
        A point exterior to the real conic ``C``.
    {rtol_on}

    Returns
    -------
    Q1, Q2, Q3 : ndarray, shape (..., 3)

    Raises
    ------
    InputError
        ``Q1`` is not exterior to ``C``: it has no real tangents.

    Examples
    --------
    >>> Q1, Q2, Q3 = special_base(conic_circle([0.0, 0.0], 1.0), [0.0, -2.0, 1.0])
    >>> float(Q2 @ conic_circle([0.0, 0.0], 1.0) @ Q1)
    0.0
    """
    Q1 = as_vec3(Q1, "Q1")
    try:
        _, X = tangents_from_point(C, Q1, rtol=rtol)
    except InputError as exc:
        raise InputError("Q1 must be exterior to the real conic C for the special base "
                         "(it has no real tangents)") from exc
    Q1b = np.broadcast_to(Q1, X[..., 0, :].shape)
    return Q1b, X[..., 0, :], X[..., 1, :]


@_shared
def decompose_point_special(C, P, Q1, Q2, Q3) -> np.ndarray:
    """Components of ``P`` on a special base by projections (thesis 5.44-5.45).

    ``u1 = Q1 C P / Q1 C Q1``, ``u2 = Q3 C P / Q3 C Q2``, ``u3 = Q2 C P / Q2 C Q3``.

    {parameters C decomposed_P special_base components not_special}

    Examples
    --------
    >>> C = conic_circle([0.0, 0.0], 1.0)
    >>> B = special_base(C, [0.0, -2.0, 1.0])
    >>> u = decompose_point_special(C, [0.3, 0.1, 1.0], *B)
    >>> np.allclose(u[0] * B[0] + u[1] * B[1] + u[2] * B[2], [0.3, 0.1, 1.0])
    True
    """
    return _special(C, P, "P", (Q1, Q2, Q3), "decompose_point_special")


@_shared
def decompose_line_special(C, L, Q1, Q2, Q3) -> np.ndarray:
    """Components of ``L`` on the lines ``C Qi`` of a special base (thesis 5.46), with no inverse.

    ``u1 = Q1·L / Q1 C Q1``, ``u2 = Q3·L / Q3 C Q2``, ``u3 = Q2·L / Q2 C Q3``.

    {parameters C decomposed_L special_base components not_special}

    Examples
    --------
    >>> C = conic_circle([0.0, 0.0], 1.0)
    >>> B = special_base(C, [0.0, -2.0, 1.0])
    >>> P = np.array([0.3, 0.1, 1.0])
    >>> np.allclose(decompose_line_special(C, C @ P, *B), decompose_point_special(C, P, *B))
    True
    """
    return _special(C, L, "L", (Q1, Q2, Q3), "decompose_line_special")


def _special(C, x, name: str, Q, what: str) -> np.ndarray:
    """``[Q1·y/Q1CQ1, Q3·y/Q3CQ2, Q2·y/Q2CQ3]`` (5.44-5.46); ``y``: ``C x`` (a point) or ``x``."""
    C, x = _conic(C), as_vec3(x, name)
    (Q1, Q2, Q3), e = _scaled_base(*Q)
    batch_shape(C=(C, 2), **{name: (x, 1)}, Q1=(Q1, 1), Q2=(Q2, 1), Q3=(Q3, 1))
    (C, eC), (x, ex) = _pow2(C, 2), _pow2(x)   # u: degree 1 in x, -1 in its Qi, 0 (P) or -1 (L) in C
    if name == "P":
        with np.errstate(under="ignore"):
            x = _mv(C, x)
    e = (ex if name == "P" else ex - eC)[..., None] - e
    with np.errstate(under="ignore"):
        n1, n2, n3 = (np.einsum("...i,...i->...", q, x) for q in (Q1, Q3, Q2))
    with np.errstate(all="ignore"):
        den = [_quad(Q1, C, Q1), _quad(Q3, C, Q2), _quad(Q2, C, Q3)]
        zero = [np.any(d == 0) for d in den]
        if any(zero):
            name = ("Q1 C Q1", "Q3 C Q2", "Q2 C Q3")[zero.index(True)]
            raise DegenerateGeometryError(f"{what}: {name} = 0, so Q1, Q2, Q3 are not a special base of C "
                                          "(see special_base)")
        u = np.stack(np.broadcast_arrays(n1 / den[0], n2 / den[1], n3 / den[2]), axis=-1)
    return _back(u, e, what, "the components")


# --------------------------------------------------------------------------- drawing support
@_shared
def drawable_conic(C) -> np.ndarray:
    """A real conic showing an imaginary one: ``C - 2 k e eᵀ`` (thesis 10.2.3).

    ``k = 1 / (C⁻¹)[2, 2]``, ``e = [0, 0, 1]``: for an inertia, the circle of gyration; its polars
    are those of ``C`` reflected through the centre.

    {parameters C returns_3x3}

    Examples
    --------
    >>> drawable_conic(np.diag([2.0, 2.0, 8.0])).diagonal()   # inertia m = 2, J = 8: radius 2
    array([ 2.,  2., -8.])
    """
    C = _conic(C)
    return rescaled(_drawable, (C,), (1,), (2,), 2, "drawable_conic(C)", "C")


def _drawable(C):
    ev = np.linalg.eigvalsh(C)
    pos = np.all(ev > 0, axis=-1)
    neg = np.all(ev < 0, axis=-1)
    imag = pos | neg
    Cs = np.where(neg[..., None, None], -C, C)
    cof = Cs[..., 0, 0] * Cs[..., 1, 1] - Cs[..., 0, 1] ** 2
    det = np.linalg.det(Cs)
    k = np.zeros(cof.shape)
    np.divide(det, cof, out=k, where=imag & (cof != 0))
    out = Cs.copy()
    out[..., 2, 2] = Cs[..., 2, 2] - 2.0 * k
    return np.where(imag[..., None, None], out, C)


@dataclass(frozen=True)
class AffineFrame:
    """``x = A u + t`` maps the unit curve of ``kind`` onto a real conic (see :func:`affine_frame`).

    Unit curves: ellipse ``u1² + u2² = 1``, hyperbola ``u1² - u2² = 1``, parabola ``u2 = u1²``.

    Attributes
    ----------
    kind : str
        ``"ellipse"``, ``"hyperbola"`` or ``"parabola"``.
    A : ndarray (2, 2)
        Linear part: images of the unit curve's axes (m).
    t : ndarray (2,)
        Centre (ellipse, hyperbola) or vertex (parabola) (m).

    Examples
    --------
    >>> affine_frame(conic_hyperbola([0.0, 1.0], [2.0, 1.0])).kind
    'hyperbola'
    """

    kind: str
    A: np.ndarray
    t: np.ndarray


_UNIT_STD = {
    "ellipse": np.diag([-1.0, 1.0, 1.0]),
    "hyperbola": np.diag([-1.0, 1.0, -1.0]),
    "parabola": np.array([[0.0, 0.0, -0.5], [0.0, 1.0, 0.0], [-0.5, 0.0, 0.0]]),
}


def affine_frame(C, rtol: float = 1e-10) -> AffineFrame:
    """Affine frame of a real conic: ``x = A u + t`` maps the unit curve onto it.

    For an ellipse or hyperbola ``t`` is the centre and ``A``'s columns the semi-axes (transverse
    first); for a parabola ``t`` is the vertex, ``A[:, 0]`` along the tangent there and ``A[:, 1]``
    along the axis, into the parabola.

    Parameters
    ----------
    C : array_like, shape (3, 3)
        A single conic.
    rtol : float
        Classification tolerance (:func:`classify`).

    Returns
    -------
    AffineFrame

    Raises
    ------
    InputError, DegenerateGeometryError
        An imaginary conic (draw :func:`drawable_conic`), or a degenerate one.

    Examples
    --------
    >>> F = affine_frame(conic_ellipse([1.0, 2.0], [3.0, 1.0]))
    >>> F.kind, F.t
    ('ellipse', array([1., 2.]))
    """
    C = _fitq(_conic(C), 2)                  # the frame does not depend on C's scale
    if C.shape != (3, 3):
        raise ShapeError(f"C must have shape (3, 3) for affine_frame, got shape {C.shape}")
    with np.errstate(all="ignore"):
        frame = _affine_frame(C, check_tolerance(rtol))
    check_overflow((frame.A, frame.t), "affine_frame(C)", "the conic's size or distance")
    return frame


def _affine_frame(C, rtol):
    ct = _classify1(T_STD @ C @ T_STD, rtol)
    if ct.reality == "degenerate":
        raise DegenerateGeometryError(f"C is a degenerate conic ({ct.kind}): it has no affine frame")
    if ct.reality == "imaginary":
        raise InputError("C is an imaginary conic (no real points); draw drawable_conic(C) instead")
    S = T_STD @ C @ T_STD
    c, b, A2 = S[0, 0], S[1:, 0], S[1:, 1:]
    lam, V = np.linalg.eigh(A2)
    if ct.kind == "parabola":
        i = int(np.argmax(np.abs(lam)))
        n, d, lm = V[:, i], V[:, 1 - i], lam[i]
        bn, bd = b @ n, b @ d
        s0 = -bn / lm
        tau0 = -(c - bn * bn / lm) / (2.0 * bd)
        t = s0 * n + tau0 * d
        A = np.column_stack([n, (-lm / (2.0 * bd)) * d])
        return AffineFrame("parabola", A, t)
    t = -np.linalg.solve(A2, b)
    k = t @ A2 @ t - c         # (u - t)^T A2 (u - t) = k
    if ct.kind == "ellipse":
        return AffineFrame("ellipse", V * np.sqrt(k / lam), t)
    # hyperbola: the transverse axis has the eigenvalue of the same sign as k
    order = [0, 1] if lam[0] * k > 0 else [1, 0]
    lam, V = lam[order], V[:, order]
    return AffineFrame("hyperbola", V * np.sqrt(np.abs(k / lam)), t)


@overflow_checked("A or t")
@_shared
def conic_from_affine(kind: str, A, t) -> np.ndarray:
    """The unit curve ``kind`` mapped by ``x = A u + t`` (thesis 5.47; see :func:`affine_frame`).

    Parameters
    ----------
    kind : {"ellipse", "hyperbola", "parabola"}
        The unit curve: ``u² + v² = 1``, ``u² - v² = 1`` or ``v = u²``.
    A : array_like, shape (..., 2, 2)
        Linear part (columns: images of the unit axes).
    t : array_like, shape (..., 2)
        Translation (centre or vertex, m).

    {returns_3x3}

    Raises
    ------
    InputError
        If ``kind`` is not one of the three names.

    Examples
    --------
    >>> conic_from_affine("ellipse", np.eye(2), [0.0, 0.0]).diagonal()    # the unit circle
    array([ 1.,  1., -1.])
    """
    if not isinstance(kind, str) or kind not in _UNIT_STD:
        raise InputError(f"kind must be 'ellipse', 'hyperbola' or 'parabola', got {kind!r}")
    A = as_array(A, "A", (2, 2))
    t = as_xy(t, "t")
    _check_invertible(A, "A", "singular", 1e-13)
    Ainv = np.linalg.inv(A)
    Minv = np.zeros(batch_shape(A=(A, 2), t=(t, 1)) + (3, 3))     # [[1, 0], [t, A]]⁻¹ = [[1, 0], [-A⁻¹t, A⁻¹]]
    Minv[..., 0, 0] = 1.0
    Minv[..., 1:, 0] = -np.einsum("...ij,...j->...i", Ainv, t)
    Minv[..., 1:, 1:] = Ainv
    S = np.swapaxes(Minv, -1, -2) @ _UNIT_STD[kind] @ Minv
    C = T_STD @ S @ T_STD
    return 0.5 * (C + np.swapaxes(C, -1, -2))


def _rot(angle):
    c, s = np.cos(angle), np.sin(angle)
    return np.stack([np.stack([c, -s], -1), np.stack([s, c], -1)], -2)


def _turned(kind: str, centre, axes, angle) -> np.ndarray:
    """The ellipse or hyperbola of semi-axes ``axes`` in the turned frame at ``centre``."""
    axes = check_positive(as_xy(axes, "axes"), "axes")
    A = _rot(as_array(angle, "angle")) * axes[..., None, :]
    return conic_from_affine(kind, A, centre)


@overflow_checked("centre or radius")
@_shared
def conic_circle(centre, radius, imaginary: bool = False) -> np.ndarray:
    """Circle ``|x - c|² = r²`` (or the imaginary ``|x - c|² = -r²``, an inertia over its mass).

    {parameters centre}
    radius : array_like, shape (...)
        Radius ``r`` (m).
    imaginary : bool, optional
        Build the imaginary circle instead.

    {conic_matrix}

    Raises
    ------
    InputError
        If ``imaginary`` is not True or False.

    Examples
    --------
    >>> conic_circle([1.0, 2.0], 3.0)
    array([[ 1.,  0., -2.],
           [ 0.,  1.,  1.],
           [-2.,  1., -4.]])
    """
    c = as_xy(centre, "centre")
    r = check_positive(radius, "radius")
    if not isinstance(imaginary, (bool, np.bool_)):
        raise InputError(f"imaginary must be True or False, got {imaginary!r}")
    r2 = np.where(imaginary, -1.0, 1.0) * r * r
    shape = batch_shape(centre=(c, 1), radius=(r, 0))
    C = np.zeros(shape + (3, 3))
    C[..., 0, 0] = C[..., 1, 1] = 1.0
    C[..., 0, 2] = C[..., 2, 0] = -c[..., 1]
    C[..., 1, 2] = C[..., 2, 1] = c[..., 0]
    C[..., 2, 2] = c[..., 0] ** 2 + c[..., 1] ** 2 - r2
    return C


@overflow_checked("centre or axes")
@_shared
def conic_ellipse(centre, axes, angle=0.0) -> np.ndarray:
    """Ellipse ``x'²/a² + y'²/b² = 1`` in the frame at ``centre`` turned by ``angle``.

    {parameters centre ellipse_axes conic_matrix}

    Examples
    --------
    >>> str(classify(conic_ellipse([0.0, 0.0], [2.0, 1.0], 0.3)))
    'real ellipse'
    """
    return _turned("ellipse", centre, axes, angle)


@overflow_checked("centre or axes")
@_shared
def conic_hyperbola(centre, axes, angle=0.0) -> np.ndarray:
    """Hyperbola ``x'²/a² - y'²/b² = 1`` in the frame at ``centre`` turned by ``angle``.

    {parameters centre hyperbola_axes conic_matrix}

    Examples
    --------
    >>> float(conic_residual(conic_hyperbola([0.0, 0.0], [2.0, 1.0]), [0.0, -2.0, 1.0]))  # (2, 0)
    0.0
    """
    return _turned("hyperbola", centre, axes, angle)


@overflow_checked("vertex or focal_length")
@_shared
def conic_parabola(vertex, focal_length, angle=0.0) -> np.ndarray:
    """Parabola ``y' = x'² / (4 f)`` (focus ``(0, f)``) in the turned frame at ``vertex``.

    {parameters parabola conic_matrix}

    Examples
    --------
    >>> conic_parabola([0.0, 0.0], 0.25)      # y = x²
    array([[ 0. ,  0. , -0.5],
           [ 0. ,  1. ,  0. ],
           [-0.5,  0. ,  0. ]])
    """
    f = check_positive(focal_length, "focal_length")
    angle = as_array(angle, "angle")
    with np.errstate(over="ignore"):
        scale = check_overflow(np.stack([np.ones_like(f), 1.0 / (4.0 * f)], axis=-1), "conic_parabola",
                               "1 / focal_length")
    A = _rot(angle) * scale[..., None, :]
    return conic_from_affine("parabola", A, vertex)


@overflow_checked("a coefficient")
@_shared
def conic_from_coefficients(a, b, c, d, e, f) -> np.ndarray:
    """Conic ``a x² + b xy + c y² + d x + e y + f = 0`` (thesis 5.35 in standard coordinates).

    Parameters
    ----------
    a, b, c, d, e, f : array_like
        Coefficients of the implicit equation (broadcast together).

    {conic_matrix}

    Examples
    --------
    >>> conic_from_coefficients(1, 0, 1, 0, 0, -1).diagonal()    # the unit circle
    array([ 1.,  1., -1.])
    """
    a, b, c, d, e, f = np.broadcast_arrays(*(as_array(v, n) for v, n in
                                             zip((a, b, c, d, e, f), "abcdef")))
    S = np.stack([np.stack([f, d / 2, e / 2], -1), np.stack([d / 2, a, b / 2], -1),
                  np.stack([e / 2, b / 2, c], -1)], -2)
    return T_STD @ S @ T_STD + 0.0
