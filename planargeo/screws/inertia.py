"""Planar rigid-body inertias as (imaginary) conics (thesis 1.8, 4.58, 5.4, 10.2.3).

Functions broadcast; :class:`Inertia` is a thin validated wrapper.
"""
from __future__ import annotations

import inspect
import re

import numpy as np

from planargeo._validate import (as_mat3, as_scalar, as_vec3, as_xy, batch_shape, check_overflow, check_positive,
                                 check_positive_definite, overflow_checked, rescaled)
from planargeo.errors import InputError, InvalidPolygonError, SingularInertiaError
from planargeo.geometry import conics
from planargeo.geometry._docs import entries
from planargeo.geometry.elements import Conic, Line, Point
from planargeo.screws.twists import (SCREWS, _derived, _Held, _inertia_psd, inertia_at,
                                      inertia_matrix, inertia_rotated, kinetic_energy, momentum)

__all__ = [
    "Inertia", "mass", "centre_of_mass", "rotational_inertia", "radius_of_gyration",
    "percussion_axis", "percussion_pole", "drawable_conic", "mobility", "polygon_moments",
]

#: The docstring entries of this module (:func:`planargeo.geometry._docs.entries`): the screws' and these.
_documented = entries(SCREWS, {
    "pole": "point : array_like, shape (..., 3)\n    Homogeneous acceleration pole (a twist).",
    "impulse": "line : array_like, shape (..., 3)\n    Homogeneous line (an impulse's line of action).",
    **{f"returns_{kind.lower()}": f"Returns\n-------\n{kind}"
       for kind in ("Inertia", "Line", "Point", "Conic")},
    "no_mass": "Raises\n------\nInputError\n    A mass ``inertia[..., 0, 0]`` not positive.",
})


#: Relative tolerance of the rigid-body structure test of :class:`Inertia`.
RIGID_RTOL = 1e-10


def _check_rigid(M: np.ndarray, name: str) -> np.ndarray:
    """``M``, checked for the rigid form ``M[0, 0] == M[1, 1]``, ``M[0, 1] == 0`` (thesis 4.58)."""
    scale = np.abs(M).max(axis=(-2, -1), initial=0.0)
    dev = np.maximum(np.abs(M[..., 0, 0] - M[..., 1, 1]),
                     np.maximum(np.abs(M[..., 0, 1]), np.abs(M[..., 1, 0])))
    bad = dev > RIGID_RTOL * scale
    if np.any(bad):
        i = np.unravel_index(int(np.argmax(np.where(bad, dev, -1.0))), bad.shape) if bad.ndim else ()
        a, b, c = (float(M[i + (0, 0)]), float(M[i + (1, 1)]), float(M[i + (0, 1)]))
        raise InputError(
            f"{name} must be a rigid-body inertia ({name}[0, 0] == {name}[1, 1] == mass and "
            f"{name}[0, 1] == 0, thesis 4.58), got {name}[0, 0] = {a:.6g}, {name}[1, 1] = {b:.6g}, "
            f"{name}[0, 1] = {c:.6g}; articulated inertias are plain arrays")
    return M


def _pd(x, name="inertia") -> np.ndarray:
    """An inertia that must be symmetric positive definite (it is inverted)."""
    return check_positive_definite(as_mat3(x, name), name)


# ---------- Features of a rigid-body inertia (thesis 1.66, 4.58): read from the form 4.58,
# not checked (Inertia checks it); those dividing by the mass reject inertia[0, 0] <= 0.
@_documented
def mass(inertia) -> np.ndarray:
    """Mass ``m = I[0, 0]`` (kg) of a rigid-body inertia (thesis 1.66, 4.58; form not checked).

    {parameters inertia returns_scalar}

    Examples
    --------
    >>> mass(inertia_matrix(2.0, [1.0, 0.0], 0.5))
    array(2.)
    """
    return np.asarray(as_mat3(inertia, "inertia")[..., 0, 0])


def _with_mass(inertia, name: str = "inertia") -> np.ndarray:
    """The inertia array, after checking every mass ``inertia[0, 0] > 0`` (InputError naming it)."""
    I = as_mat3(inertia, name)
    m = I[..., 0, 0]
    bad = ~(m > 0)
    if np.any(bad):
        raise InputError(f"{name}: mass {name}[0, 0] must be positive, got {float(m[bad].ravel()[0])!r}")
    return I


@overflow_checked("1 / mass")
@_documented
def centre_of_mass(inertia) -> np.ndarray:
    """Centre of mass ``c = (I[1, 2], -I[0, 2]) / m`` (m; thesis 1.66, 4.58): the conic's centre.

    {parameters inertia returns_2 no_mass}

    Examples
    --------
    >>> centre_of_mass(inertia_matrix(2.0, [1.0, -3.0], 0.5))
    array([ 1., -3.])
    """
    I = _with_mass(inertia)
    m = I[..., 0, 0]
    return np.stack([I[..., 1, 2] / m, (0.0 - I[..., 0, 2]) / m], axis=-1)


@overflow_checked("inertia")
@_documented
def rotational_inertia(inertia) -> np.ndarray:
    """Rotational inertia ``J = m ρ²`` (kg·m²) about the centre of mass (thesis 1.68, 4.58).

    By the parallel axis theorem, ``J = I[2, 2] - m |c|²`` with ``c`` the centre of mass.

    {parameters inertia returns_scalar no_mass}

    Examples
    --------
    >>> rotational_inertia(inertia_matrix(2.0, [1.0, -3.0], 0.5))
    array(0.5)
    """
    I = _with_mass(inertia)
    c = centre_of_mass(I)
    return np.asarray(I[..., 2, 2] - I[..., 0, 0] * np.einsum("...i,...i->...", c, c))


@overflow_checked("inertia")
@_documented
def radius_of_gyration(inertia) -> np.ndarray:
    """Radius of gyration ``ρ = sqrt(J / m)`` (m; thesis 4.58, 5.64).

    {parameters inertia returns_scalar no_mass}

    Examples
    --------
    >>> radius_of_gyration(inertia_matrix(2.0, [1.0, 0.0], 0.5))
    array(0.5)
    """
    I = _with_mass(inertia)
    return np.asarray(np.sqrt(np.maximum(rotational_inertia(I) / I[..., 0, 0], 0.0)))


@overflow_checked("1 / inertia")
@_documented
def mobility(inertia) -> np.ndarray:
    """Mobility ``I⁻¹``, the dual conic (thesis 8.3.5), computed with ``solve``.

    {parameters inertia returns_3x3}

    Raises
    ------
    SingularInertiaError, InputError
        ``inertia`` singular or indefinite (carrying ``.cond``), or not symmetric.

    Examples
    --------
    >>> mobility(inertia_matrix(2.0, [0.0, 0.0], 0.5)).diagonal()
    array([0.5, 0.5, 2. ])
    """
    I = _pd(inertia)
    return _solve(I, np.broadcast_to(np.eye(3), I.shape))


def _solve(I: np.ndarray, b: np.ndarray) -> np.ndarray:
    try:
        return np.linalg.solve(I, b)
    except np.linalg.LinAlgError:
        raise SingularInertiaError("inertia must be invertible", float("inf")) from None


# ---------- Axis of percussion (thesis 5.64-5.68) and the drawable conic (10.2.3)
@_documented
def percussion_axis(inertia, point) -> np.ndarray:
    """Axis of percussion ``f = I a`` of an acceleration pole ``a`` (thesis 5.64-5.68).

    {parameters inertia pole}

    Returns
    -------
    ndarray (..., 3)
        The wrench ``I a`` (not normalised).

    {not_psd}

    Examples
    --------
    >>> percussion_axis(inertia_matrix(2.0, [1.0, 0.0], 0.5), [0.0, 0.0, 1.0])   # 5.66: x = 1.25
    array([0. , 2. , 2.5])
    """
    I = _inertia_psd(inertia)
    a = as_vec3(point, "point")
    batch_shape(inertia=(I, 2), point=(a, 1))
    return rescaled(lambda I, a: np.einsum("...ij,...j->...i", I, a), (I, a), (1, 1), (2, 1), 1,
                    "percussion_axis(inertia, point)", "inertia or point")


@_documented
def percussion_pole(inertia, line) -> np.ndarray:
    """Acceleration pole ``a = I⁻¹ f`` of the axis of percussion ``line`` (:func:`percussion_axis`).

    {parameters inertia impulse}

    Returns
    -------
    numpy.ndarray, shape (..., 3)
        The acceleration ``I⁻¹ f`` (not normalised).

    Raises
    ------
    InputError, SingularInertiaError
        ``inertia`` not symmetric, or not positive definite (carrying ``.cond``).

    Examples
    --------
    >>> percussion_pole(inertia_matrix(2.0, [1.0, 0.0], 0.5), [0.0, 0.0, 1.0])   # a couple: centre
    array([ 0., -1.,  1.])
    """
    I = _pd(inertia)
    f = as_vec3(line, "line")
    batch_shape(inertia=(I, 2), line=(f, 1))
    return rescaled(lambda I, f: _solve(I, f[..., None])[..., 0], (I, f), (-1, 1), (2, 1), 1,
                    "percussion_pole(inertia, line)", "line, or the inverse inertia,")


@_documented
def drawable_conic(inertia) -> np.ndarray:
    """The real conic drawn for an inertia: the radius-of-gyration circle (thesis 10.2.3).

    ``I`` with ``2 m ρ²`` taken from ``I[2, 2]`` (:func:`planargeo.geometry.conics.drawable_conic`).

    {parameters inertia returns_3x3 not_psd}

    Examples
    --------
    >>> drawable_conic(inertia_matrix(2.0, [0.0, 0.0], 0.5)).diagonal()   # -m ρ² last
    array([ 2. ,  2. , -0.5])
    """
    return conics.drawable_conic(_inertia_psd(inertia))


# ---------- Polygon moments
def polygon_moments(geometry, name: str = "geometry"):
    """Area, centroid and polar second moment about the centroid of a shapely area.

    Green's theorem on each ring (holes and ``MultiPolygon`` parts work), in coordinates
    shifted to the centre of the bounding box for accuracy.

    Parameters
    ----------
    geometry : shapely.geometry.Polygon or MultiPolygon
        The area (m).
    name : str, optional
        Name used in error messages.

    Returns
    -------
    area : float
    centroid : ndarray (2,)
    polar_moment : float
        ``∫ |x - c|² dA`` (per unit density).

    Raises
    ------
    InvalidPolygonError
        Not a (Multi)Polygon, empty, invalid or of zero area.

    Examples
    --------
    >>> from shapely.geometry import box
    >>> A, c, J = polygon_moments(box(0.0, 0.0, 2.0, 1.0))     # b h (b² + h²) / 12
    >>> float(A), c, float(J)
    (2.0, array([1. , 0.5]), 0.833333)
    """
    from shapely.geometry import MultiPolygon, Polygon
    from shapely.geometry.polygon import orient
    from shapely.validation import explain_validity
    if not isinstance(geometry, (Polygon, MultiPolygon)):
        raise InvalidPolygonError(
            f"{name} must be a shapely Polygon or MultiPolygon, got {type(geometry).__name__}")
    if geometry.is_empty:
        raise InvalidPolygonError(f"{name} must be non-empty, got an empty {type(geometry).__name__}")
    if not geometry.is_valid:
        raise InvalidPolygonError(f"{name} must be a valid polygon: {explain_validity(geometry)}")
    parts = list(geometry.geoms) if isinstance(geometry, MultiPolygon) else [geometry]
    x0, y0, x1, y1 = geometry.bounds
    o = np.array([0.5 * (x0 + x1), 0.5 * (y0 + y1)])
    if not np.all(np.isfinite([x0, y0, x1, y1])):
        raise InvalidPolygonError(f"{name} must have finite coordinates")
    A = Sx = Sy = Ixx = Iyy = 0.0
    for part in parts:
        part = orient(part, 1.0)
        for ring in [part.exterior, *part.interiors]:
            xy = np.asarray(ring.coords, dtype=float)[:, :2] - o
            x, y = xy[:-1, 0], xy[:-1, 1]
            xn, yn = xy[1:, 0], xy[1:, 1]
            cr = x * yn - xn * y
            A += cr.sum() / 2.0
            Sx += ((x + xn) * cr).sum() / 6.0
            Sy += ((y + yn) * cr).sum() / 6.0
            Iyy += ((x * x + x * xn + xn * xn) * cr).sum() / 12.0
            Ixx += ((y * y + y * yn + yn * yn) * cr).sum() / 12.0
    if not A > 0:
        raise InvalidPolygonError(f"{name} must have positive area, got {A!r}")
    cl = np.array([Sx / A, Sy / A])
    J = Ixx + Iyy - A * float(cl @ cl)
    return float(A), cl + o, float(J)


# ---------- The class
def _of_matrix(function, name: str | None = None):
    """A method of :class:`Inertia`: ``function`` of its matrix, documented by it."""
    def method(self, *args, **kwargs):
        return function(self._array, *args, **kwargs)

    own = inspect.signature(function)
    first, *rest = own.parameters.values()
    method.__signature__ = own.replace(parameters=[first.replace(name="self"), *rest])
    method.__name__ = name or function.__name__
    method.__qualname__ = f"Inertia.{method.__name__}"
    doc = re.sub(r"\n    inertia : [^\n]*\n        [^\n]*", "", function.__doc__)
    raises = r"    Raises\n    ------\n(    \S[^\n]*\n        [^\n]*``inertia``[^\n]*\n)+\n"
    doc = re.sub(raises, "", doc)
    method.__doc__ = doc.replace("    Parameters\n    ----------\n\n", "")
    if "inertia :" in method.__doc__:     # the function's docstring changed shape: say so at import
        raise RuntimeError(f"Inertia.{method.__name__}: the inertia entry of {function.__name__}'s "
                           "docstring was not taken out")
    return method


class Inertia(_Held):
    """A planar rigid-body inertia at the origin (thesis 1.66, 4.58, 5.64): an imaginary conic.

    One read-only ``(..., 3, 3)`` matrix of the rigid-body form 4.58 (:func:`inertia_matrix`).
    Articulated inertias (chapters 6-7) have no mass or centre: they stay plain arrays, which
    every function accepts.

    Parameters
    ----------
    matrix : array_like, shape (..., 3, 3)
        Symmetric positive definite matrix of the rigid-body form (4.58).

    Raises
    ------
    InputError, SingularInertiaError
        Not symmetric, a non-positive mass, not of the rigid-body form; not positive definite.

    Examples
    --------
    >>> I = Inertia.from_mass(2.0, [1.0, 0.0], radius_of_gyration=0.5)
    >>> I
    Inertia(mass=2, com=(1, 0), radius_of_gyration=0.5)
    >>> float(I.kinetic_energy([0.0, 0.0, 2.0]))      # ½ (J + m d²) ω²
    5.0
    """

    __slots__ = ()

    def __init__(self, matrix):
        M = np.array(as_mat3(matrix, "matrix"), dtype=float)
        if np.any(M[..., 0, 0] <= 0):
            bad = M[..., 0, 0][M[..., 0, 0] <= 0].ravel()[0]
            raise InputError(f"matrix must have a positive mass matrix[0, 0], got {float(bad)!r}")
        check_positive_definite(M, "matrix")
        _check_rigid(M, "matrix")
        M.flags.writeable = False
        self._array = M

    # -- constructors ---------------------------------------------------
    @classmethod
    @_documented
    def from_mass(cls, mass, com, radius_of_gyration=None, inertia=None) -> "Inertia":
        """Inertia of mass ``mass`` at ``com``, given ``ρ`` or ``J = m ρ²`` (thesis 4.58, 5.64).

        {parameters mass_com}
        radius_of_gyration, inertia : float or array_like, optional
            Exactly one: ``ρ > 0`` (m) or ``J > 0`` about the centre of mass (kg·m²).

        {returns_inertia}

        Raises
        ------
        InputError
            Not exactly one of ``radius_of_gyration`` and ``inertia``, or a value not positive.

        Examples
        --------
        >>> Inertia.from_mass(2.0, [0.0, 0.0], inertia=0.5).matrix.diagonal()
        array([2. , 2. , 0.5])
        """
        m = check_positive(mass, "mass")
        c = as_xy(com, "com")
        if (radius_of_gyration is None) == (inertia is None):
            raise InputError("give exactly one of radius_of_gyration or inertia")
        if inertia is None:
            rho = check_positive(radius_of_gyration, "radius_of_gyration")
            with np.errstate(over="ignore"):
                J = check_overflow(m * rho * rho, "Inertia.from_mass", "mass or radius_of_gyration")
        else:
            J = check_positive(inertia, "inertia")
        return cls(inertia_matrix(m, c, J))

    @classmethod
    @_documented
    def from_polygon(cls, geometry, density=1.0) -> "Inertia":
        """Inertia of a uniform lamina, a shapely (Multi)Polygon (see :func:`polygon_moments`).

        Parameters
        ----------
        geometry : shapely.geometry.Polygon or MultiPolygon
            The lamina's shape (m).
        density : float, optional
            Mass per unit area (kg/m²), positive.

        {returns_inertia}

        Raises
        ------
        InputError, InvalidPolygonError
            ``density`` not positive; not a valid polygon of positive area and polar moment.

        Examples
        --------
        >>> from shapely.geometry import box
        >>> I = Inertia.from_polygon(box(-1.0, -0.5, 1.0, 0.5), density=3.0)
        >>> float(I.mass), float(I.rotational_inertia)        # m (b² + h²)/12 = 6 · 5/48
        (6.0, 2.5)
        """
        rho_d = float(check_positive(as_scalar(density, "density"), "density"))
        A, c, J = polygon_moments(geometry, "geometry")
        if not J > 0:
            raise InvalidPolygonError(f"geometry must have a positive polar moment, got {J!r}")
        return cls(inertia_matrix(rho_d * A, c, rho_d * J))

    @classmethod
    @_documented
    def composite(cls, parts) -> "Inertia":
        """Inertia of rigidly joined parts: the sum of their matrices (thesis 1.65 is linear).

        Parameters
        ----------
        parts : iterable of Inertia
            The bodies (at least one).

        {returns_inertia}

        Raises
        ------
        InputError
            If ``parts`` is empty.

        Examples
        --------
        >>> a = Inertia.from_mass(1.0, [-1.0, 0.0], inertia=0.1)
        >>> float(Inertia.composite([a, a.at([2.0, 0.0])]).rotational_inertia)   # 0.2 + 2 · 1²
        2.2
        """
        parts = list(parts)
        if not parts:
            raise InputError("parts must contain at least one inertia")
        total = sum(as_mat3(p, f"parts[{i}]") for i, p in enumerate(parts))
        return cls(total)

    # -- data ------------------------------------------------------------
    # the matrix and the body's quantities: the module's functions of it
    matrix = _derived(np.asarray, """The ``(..., 3, 3)`` matrix at the origin (read-only).""")
    mass = _derived(mass, """Mass ``m = matrix[0, 0]`` (kg), of the batch shape.""")
    com = _derived(centre_of_mass, """Centre of mass ``(x, y)`` (m).""")
    rotational_inertia = _derived(rotational_inertia, """``J`` about the centre of mass (kg·m²).""")
    radius_of_gyration = _derived(radius_of_gyration, """Radius of gyration ``sqrt(J / m)`` (m).""")
    mobility = _derived(mobility, """Inverse inertia ``I⁻¹`` (via ``solve``).""")

    def __repr__(self) -> str:
        if self._array.ndim == 2:
            c = self.com
            return (f"Inertia(mass={float(self.mass):.6g}, com=({c[0]:.6g}, {c[1]:.6g}), "
                    f"radius_of_gyration={float(self.radius_of_gyration):.6g})")
        return f"Inertia(batch of shape {self._array.shape[:-2]})"

    def __add__(self, other):
        if not isinstance(other, Inertia):
            return NotImplemented
        return Inertia(self._array + other._array)

    # -- operations ------------------------------------------------------
    @_documented
    def at(self, point) -> "Inertia":
        """The same body expressed at ``point`` (thesis 1.68: ``X_P⁻ᵀ I X_P⁻¹``).

        {parameters point returns_inertia}

        Examples
        --------
        >>> Inertia.from_mass(2.0, [1.0, 0.0], inertia=0.5).at([1.0, 0.0])
        Inertia(mass=2, com=(0, 0), radius_of_gyration=0.5)
        """
        return Inertia(inertia_at(self._array, point))

    @_documented
    def rotated(self, theta, about=(0.0, 0.0)) -> "Inertia":
        """The body turned by ``theta`` about ``about`` (thesis 1.68; :func:`planargeo.screws.inertia_rotated`).

        {parameters theta about returns_inertia}

        Examples
        --------
        >>> Inertia.from_mass(2.0, [2.0, 0.0], inertia=0.5).rotated(np.pi / 2, about=[1.0, 0.0])
        Inertia(mass=2, com=(1, 1), radius_of_gyration=0.5)
        """
        return Inertia(inertia_rotated(self._array, theta, about))

    # the module's functions of the matrix, documented there
    kinetic_energy = _of_matrix(kinetic_energy)
    momentum = _of_matrix(momentum)
    percussion_axis_array = _of_matrix(percussion_axis, "percussion_axis_array")
    percussion_pole_array = _of_matrix(percussion_pole, "percussion_pole_array")
    drawable_conic_matrix = _of_matrix(drawable_conic, "drawable_conic_matrix")

    @_documented
    def percussion_axis(self, point):
        """Axis of percussion of ``point`` as a :class:`planargeo.geometry.Line` (thesis 5.67).

        {parameters pole returns_line}

        Examples
        --------
        >>> Inertia.from_mass(2.0, [1.0, 0.0], inertia=0.5).percussion_axis([0.0, 0.0, 1.0])
        Line(through=(1.25, 0), direction=(0, 1))
        """
        return Line(self.percussion_axis_array(point))

    @_documented
    def percussion_pole(self, line):
        """Pole whose axis of percussion is ``line``, as a :class:`planargeo.geometry.Point`.

        {parameters impulse returns_point}

        Examples
        --------
        >>> Inertia.from_mass(2.0, [1.0, 0.0], inertia=0.5).percussion_pole([0.0, 0.0, 1.0])   # a couple: the centre
        Point(x=1, y=0)
        """
        return Point(self.percussion_pole_array(line))

    @_documented
    def drawable_conic(self):
        """The radius-of-gyration circle (thesis 10.2.3) as a :class:`planargeo.geometry.Conic`.

        {returns_conic}

        Examples
        --------
        >>> Inertia.from_mass(2.0, [0.0, 0.0], inertia=0.5).drawable_conic()
        Conic(real circle, centre=(0, 0))
        """
        return Conic(self.drawable_conic_matrix())

    def conic(self):
        """The inertia itself as an (imaginary) :class:`planargeo.geometry.Conic` (thesis 5.4).

        Returns
        -------
        Conic
            Imaginary, with no real points, for a body of positive rotational inertia.

        Examples
        --------
        >>> Inertia.from_mass(2.0, [0.0, 0.0], inertia=0.5).conic()
        Conic(imaginary circle, centre=(0, 0))
        """
        return Conic(self._array)
