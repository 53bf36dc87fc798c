"""Thin classes over the array functions: :class:`Point`, :class:`Line`, :class:`Conic`.

Each wraps one read-only array in the package's homogeneous coordinates
(``Point.array``: ``[y, -x, w]``; ``Line.array``: a wrench ``[fx, fy, tz]``;
``Conic.matrix``: symmetric 3×3), validated in the constructor.  All the
mathematics lives in :mod:`planargeo.geometry.projective` and :mod:`planargeo.geometry.conics`.

Single values only: each object is *one* point, line or conic (a batch such as
shape ``(n, 3)`` raises :class:`~planargeo.errors.ShapeError`).  For many at
once use the array functions, which broadcast over leading dimensions.

Equality is projective: two points (lines, conics) are equal when their
arrays are proportional (any non-zero factor, either sign), up to a relative
tolerance of 1e-12.  The classes are therefore not hashable.

Operators: ``p ^ q`` is the join (a :class:`Line`), ``l ^ m`` the meet (a
:class:`Point`), ``p @ l`` / ``l @ p`` the incidence form (a float, zero iff
the point lies on the line).
"""
from __future__ import annotations

import inspect
import textwrap

import numpy as np

from planargeo.geometry import conics as _c
from planargeo.geometry import projective as _p
from planargeo.geometry._docs import entries
from planargeo._validate import as_array
from planargeo.errors import DegenerateGeometryError, ShapeError

__all__ = ["Point", "Line", "Conic"]

_EQ_TOL = 1e-12


#: Docstring entries the classes share, said once (a line ``{point}`` in a docstring).
_shared = entries({"point": "point : Point or array_like, shape (3,)\n    A Point or homogeneous point array.",
                   "line": "line : Line or array_like, shape (3,)\n    A Line or homogeneous line array."})


def _fmt(v: float) -> str:
    v = float(v)
    if v == 0:
        return "0"
    return f"{v:.6g}"


def _one(x, name: str, n: int) -> np.ndarray:
    """``x`` as one vector of ``n`` floats (a batch is refused: the classes hold single values)."""
    a = as_array(x, name, (n,))
    if a.shape != (n,):
        raise ShapeError(f"{name} must have shape ({n},), got shape {a.shape}")
    return a


def _vec(x, name: str) -> np.ndarray:
    if isinstance(x, (Point, Line)):
        x = x.array
    a = _one(x, name, 3) + 0.0
    a.setflags(write=False)
    return a


def _proportional(a: np.ndarray, b: np.ndarray) -> bool:
    a = a.ravel() / np.linalg.norm(a)
    b = b.ravel() / np.linalg.norm(b)
    return bool(min(np.linalg.norm(a - b), np.linalg.norm(a + b)) <= _EQ_TOL * 10)


def _as_point_array(p, name: str = "p") -> np.ndarray:
    return p.array if isinstance(p, Point) else _vec(p, name)


def _as_line_array(l, name: str = "l") -> np.ndarray:
    return l.array if isinstance(l, Line) else _vec(l, name)


class _Homogeneous:
    """Common base: one read-only array ``_a``, compared projectively.

    Notebooks draw it with :mod:`planargeo.draw.notebook` (registered by ``import planargeo``).
    """

    __slots__ = ("_a",)
    __hash__ = None

    def __eq__(self, other):
        if not isinstance(other, type(self)):
            return NotImplemented
        return _proportional(self._a, other._a)

    def __array__(self, dtype=None, copy=None):
        return np.array(self._a, dtype=dtype)


class _PointOrLine(_Homogeneous):
    """What a point and a line share through the duality (thesis 5.3): the same array seen twice.

    ``a ^ b`` of two of a kind is ``_wedge`` (the join of points, the meet of
    lines); ``a @ b`` with the dual kind ``_dual`` is the incidence form.
    """

    __slots__ = ()

    def __init__(self, array):
        a = _vec(array, "array")
        if not np.any(a):
            raise DegenerateGeometryError(f"array is the zero vector, which is no {type(self).__name__.lower()}")
        self._a = a

    def normalized(self):
        """The same element, normalised: a point with ``w = 1`` (or unit length at infinity), a line with
        unit force (or ``tz = ±1`` at infinity).

        Returns
        -------
        Point or Line
            A new element of the same kind.

        Examples
        --------
        >>> Point([2.0, -4.0, 2.0]).normalized().array     # the point (2, 1)
        array([ 1., -2.,  1.])
        >>> Line([0.0, 3.0, 3.0]).normalized().array
        array([0., 1., 1.])
        """
        return type(self)(self._normalize(self._a))

    @property
    def array(self) -> np.ndarray:
        """The read-only homogeneous coordinates: ``[y, -x, w]`` of a point, ``[fx, fy, tz]`` of a line."""
        return self._a

    @property
    def direction(self) -> np.ndarray:
        """Unit direction of a point at infinity, or along a line (``(fx, fy)/|f|``); ``(nan, nan)`` for a
        finite point and for the line at infinity."""
        return self._direction(self._a)

    def _pair(self, other) -> tuple:
        """``(point, line)`` arrays of this element and ``other``, of the dual kind (an element or its array)."""
        name = self._dual.__name__.lower()
        theirs = other.array if isinstance(other, self._dual) else _vec(other, name)
        return (self._a, theirs) if self._dual is Line else (theirs, self._a)

    def incidence(self, other) -> float:
        """The form ``p @ l`` with ``other``, of the dual kind (thesis 5.23): zero exactly when the point lies on the line.

        For a twist and a wrench it is the power ``v·f``.  Its value depends on
        the scale of both arrays; for a distance use :meth:`Point.distance_to`
        or :meth:`Line.signed_distance`.

        Parameters
        ----------
        other : Line (of a point), Point (of a line), or array_like, shape (3,)
            The element of the dual kind, or its homogeneous array.

        Returns
        -------
        float
            ``p @ l``.

        Examples
        --------
        >>> y1 = Line.from_point_direction((0, 1), (1, 0))            # the line y = 1
        >>> Point.from_xy(3, 1).incidence(y1), Point.from_xy(3, 2).incidence(y1)
        (0.0, 1.0)
        >>> Point.at_infinity((1, 0)) @ y1                            # y = 1 passes through it
        0.0
        >>> Line.at_infinity().incidence(Point.at_infinity((3, 4)))    # every ideal point is on it
        0.0
        >>> Line.at_infinity() @ Point.from_xy(3, 4)                   # no finite point is
        1.0
        """
        return float(_p.incidence(*self._pair(other)))

    def _signed_distance(self, other) -> float:
        """Signed distance of the point from the line, this element and ``other`` of the dual kind (thesis 5.23).

        Positive on the line's left, seen looking along its direction ``(fx, fy)``.
        Ideal elements are infinitely far (documented, no warning): ``±inf``, or NaN
        for an ideal point on the line (:func:`planargeo.geometry.projective.signed_distance`).
        This is ``Point.distance_to(line)`` and ``Line.signed_distance(point)``.

        Parameters
        ----------
        other : Line, Point or array_like, shape (3,)
            As for :meth:`incidence`.

        Returns
        -------
        float
            Signed distance (m); ``±inf`` or NaN for ideal elements.

        Examples
        --------
        >>> y1 = Line.from_point_direction((0, 1), (1, 0))            # y = 1, directed along +x
        >>> y1.signed_distance(Point.from_xy(3, 4)), Point.from_xy(0, -1).distance_to(y1)
        (3.0, -2.0)
        >>> y1.signed_distance(Point.at_infinity((1, 0))), Point.from_xy(1, 1).distance_to(Line.at_infinity())
        (nan, inf)
        """
        return float(_p.signed_distance(*self._pair(other)))

    def __xor__(self, other):
        if isinstance(other, type(self)):
            return self._wedge(other)
        return NotImplemented

    def __matmul__(self, other):
        if isinstance(other, self._dual):
            return self.incidence(other)
        return NotImplemented


class Point(_PointOrLine):
    """A point of the projective plane (thesis 5.49), i.e. a twist's pole.

    Parameters
    ----------
    array : array_like, shape (3,)
        Homogeneous coordinates ``[y, -x, w]`` (any non-zero multiple);
        ``w = 0`` is a point at infinity.

    Raises
    ------
    ShapeError, DegenerateGeometryError
        If ``array`` does not have shape (3,) (one point: for a batch use the functions
        of :mod:`planargeo.geometry.projective`), or is the zero vector.

    Examples
    --------
    >>> Point.from_xy(1, 2)
    Point(x=1, y=2)
    >>> Point.at_infinity((0, 1))
    Point(at infinity, direction=(0, 1))
    >>> Point.from_xy(0, 0) ^ Point.from_xy(1, 1)
    Line(through=(0, 0), direction=(0.707107, 0.707107))
    """

    __slots__ = ()
    _normalize, _direction = staticmethod(_p.normalize_point), staticmethod(_p.direction)

    # constructors
    @classmethod
    def from_xy(cls, x, y=None) -> "Point":
        """The finite point ``(x, y)``; accepts ``from_xy(x, y)`` or ``from_xy((x, y))``.

        Parameters
        ----------
        x : float or array_like, shape (2,)
            The x coordinate (m), or the pair ``(x, y)`` when ``y`` is omitted.
        y : float, optional
            The y coordinate (m).

        Returns
        -------
        Point
            The point ``[y, -x, 1]``.

        Raises
        ------
        ShapeError
            If the pair given alone does not have shape (2,).

        Examples
        --------
        >>> Point.from_xy(1, 2), Point.from_xy((1, 2))
        (Point(x=1, y=2), Point(x=1, y=2))
        """
        return cls(_p.from_xy(_one(x if y is None else (x, y), "xy", 2)))

    @classmethod
    def at_infinity(cls, direction) -> "Point":
        """The point at infinity in ``direction`` (a translation perpendicular to it).

        Parameters
        ----------
        direction : array_like, shape (2,)
            A non-zero direction.

        Returns
        -------
        Point
            The ideal point ``[dy, -dx, 0]``.

        Raises
        ------
        ShapeError
            If ``direction`` does not have shape (2,).

        Examples
        --------
        >>> P = Point.at_infinity((1, 0))       # the translation along y
        >>> P, P.array
        (Point(at infinity, direction=(1, 0)), array([ 0., -1.,  0.]))
        """
        return cls(_p.from_direction(_one(direction, "direction", 2)))

    # data
    @property
    def xy(self) -> np.ndarray:
        """Euclidean ``(x, y)``; ``(nan, nan)`` at infinity."""
        return _p.to_xy(self._a)

    @property
    def is_ideal(self) -> bool:
        """True for a point at infinity (``w`` exactly zero)."""
        return bool(_p.is_ideal(self._a))

    # geometry
    def join(self, other) -> "Line":
        """The line through this point and ``other`` (thesis 5.32); also ``p ^ q``.

        Joining with a point at infinity gives the line through this point in
        that direction; two coincident points raise
        :class:`~planargeo.errors.DegenerateGeometryError`.

        Parameters
        ----------
        other : Point or array_like, shape (3,)
            The second point.

        Returns
        -------
        Line
            The joining line.

        Examples
        --------
        >>> Point.from_xy(0, 0).join(Point.from_xy(1, 1))
        Line(through=(0, 0), direction=(0.707107, 0.707107))
        >>> Point.from_xy(0, 2).join(Point.at_infinity((1, 0)))     # the horizontal line y = 2
        Line(through=(0, 2), direction=(1, 0))
        """
        return Line(_p.join(self._a, _as_point_array(other, "other")))

    _wedge = join

    def __repr__(self) -> str:
        if self.is_ideal:
            d = self.direction
            return f"Point(at infinity, direction=({_fmt(d[0])}, {_fmt(d[1])}))"
        x, y = self.xy
        return f"Point(x={_fmt(x)}, y={_fmt(y)})"


class Line(_PointOrLine):
    """A line of the projective plane (thesis 5.55), i.e. a wrench's line of action.

    Parameters
    ----------
    array : array_like, shape (3,)
        ``[fx, fy, tz]``: the points ``(x, y)`` with ``tz + y fx - x fy = 0``,
        directed along ``(fx, fy)``.  ``[0, 0, 1]`` is the line at infinity.

    Raises
    ------
    ShapeError, DegenerateGeometryError
        If ``array`` is not one line, shape (3,) (a batch: the functions of
        :mod:`planargeo.geometry.projective` broadcast), or is zero.

    Examples
    --------
    >>> Line.through(Point.from_xy(0, 1), Point.from_xy(2, 1))
    Line(through=(0, 1), direction=(1, 0))
    >>> Line.at_infinity()
    Line(at infinity)
    >>> Line([1, 0, 0]) ^ Line([0, 1, -3])
    Point(x=-3, y=0)
    """

    __slots__ = ()
    _normalize, _direction = staticmethod(_p.normalize_line), staticmethod(_p.line_direction)

    @classmethod
    def through(cls, p, q) -> "Line":
        """The line from ``p`` to ``q`` (Points or homogeneous arrays; thesis 5.32).

        Parameters
        ----------
        p, q : Point or array_like, shape (3,)
            Two distinct points.

        Returns
        -------
        Line
            The line ``p ^ q``, directed from ``p`` towards ``q``.

        Examples
        --------
        >>> Line.through(Point.from_xy(0, 0), Point.from_xy(2, 2))
        Line(through=(0, 0), direction=(0.707107, 0.707107))
        """
        return cls(_p.join(_as_point_array(p, "p"), _as_point_array(q, "q")))

    @classmethod
    def at_infinity(cls) -> "Line":
        """The line at infinity ``[0, 0, 1]`` (thesis 5.16).

        Returns
        -------
        Line
            ``Line([0, 0, 1])``.

        Examples
        --------
        >>> Line.at_infinity().array
        array([0., 0., 1.])
        """
        return cls(_p.LINE_AT_INFINITY)

    @classmethod
    def from_point_direction(cls, point, direction) -> "Line":
        """The line through ``point`` (a Point, or Euclidean ``(x, y)``) along ``direction``.

        Parameters
        ----------
        point : Point or array_like, shape (2,)
            A Point or Euclidean coordinates ``(x, y)`` (m).
        direction : array_like, shape (2,)
            Direction of the line (non-zero).

        Returns
        -------
        Line
            The line, directed along ``direction``.

        Raises
        ------
        ShapeError
            If ``point`` given as coordinates does not have shape (2,).

        Examples
        --------
        >>> L = Line.from_point_direction((1, 0), (0, 3))    # x = 1: a force of 3 N along +y
        >>> L, L.array
        (Line(through=(1, 0), direction=(0, 1)), array([0., 3., 3.]))
        """
        pa = point.array if isinstance(point, Point) else _p.from_xy(_one(point, "point", 2))
        return cls(_p.line_through_point_direction(pa, direction))

    @property
    def is_at_infinity(self) -> bool:
        """True for the line at infinity (force exactly zero)."""
        return bool(_p.is_at_infinity(self._a))

    @property
    def foot(self) -> Point | None:
        """The point of the line nearest to the origin (``None`` for the line at infinity)."""
        return None if self.is_at_infinity else Point(_p.foot_point(self._a))

    def meet(self, other) -> Point:
        """The common point with ``other`` (thesis 5.34); also ``l ^ m``.

        Parallel lines meet at infinity (no error); the same line twice raises
        :class:`~planargeo.errors.DegenerateGeometryError`.

        Parameters
        ----------
        other : Line or array_like, shape (3,)
            The second line.

        Returns
        -------
        Point
            The common point (ideal for parallel lines).

        Examples
        --------
        >>> y1 = Line.from_point_direction((0, 1), (1, 0))            # y = 1
        >>> y1.meet(Line.from_point_direction((2, 0), (0, 1)))        # x = 2
        Point(x=2, y=1)
        >>> y1.meet(Line.from_point_direction((0, 5), (2, 0))).is_ideal   # y = 5: parallel
        True
        """
        return Point(_p.meet(self._a, _as_line_array(other, "other")))

    _wedge = meet

    def __repr__(self) -> str:
        if self.is_at_infinity:
            return "Line(at infinity)"
        x, y = _p.to_xy(_p.foot_point(self._a))
        d = self.direction
        return (f"Line(through=({_fmt(x)}, {_fmt(y)}), "
                f"direction=({_fmt(d[0])}, {_fmt(d[1])}))")


Point._dual, Line._dual = Line, Point
Point.normalized = Line.normalized = _PointOrLine.normalized     # their own members (for the API pages)
Point.array, Line.array = _PointOrLine.array, _PointOrLine.array
Point.direction, Line.direction = _PointOrLine.direction, _PointOrLine.direction
Point.incidence = Line.incidence = _PointOrLine.incidence
Point.distance_to = Line.signed_distance = _PointOrLine._signed_distance


def _conic_of(make, examples: str) -> classmethod:
    """A constructor of :class:`Conic`: the conic of ``make``, a function of :mod:`planargeo.geometry.conics`.

    It takes ``make``'s parameters and is documented by ``make``'s summary and Parameters (said once,
    there), then its own Returns and ``examples``.
    """
    def construct(cls, *args, **kwargs):
        return cls(make(*args, **kwargs))

    own = inspect.signature(make)
    cls = inspect.Parameter("cls", inspect.Parameter.POSITIONAL_ONLY)
    construct.__signature__ = own.replace(parameters=[cls, *own.parameters.values()], return_annotation="Conic")
    construct.__name__ = make.__name__.removeprefix("conic_")
    construct.__qualname__ = f"Conic.{construct.__name__}"
    construct.__doc__ = "\n".join([make.__doc__.split("\n    Returns\n")[0], "    Returns", "    -------", "    Conic",
                                   "        One conic (a batch raises ShapeError).", "", "    Examples", "    --------",
                                   textwrap.indent(textwrap.dedent(examples).strip(), "    "), "    "])
    return classmethod(construct)


class Conic(_Homogeneous):
    """A conic (thesis 5.35): a symmetric 3×3 matrix mapping points to lines.

    Parameters
    ----------
    matrix : array_like, shape (3, 3), symmetric
        Single values only: a batch ``(..., 3, 3)`` raises
        :class:`~planargeo.errors.ShapeError`; the functions of
        :mod:`planargeo.geometry.conics` broadcast.

    Raises
    ------
    ShapeError
        If ``matrix`` does not have shape (3, 3).
    DegenerateGeometryError
        If ``matrix`` is zero.

    Examples
    --------
    >>> C = Conic.circle((0, 0), 1)
    >>> C
    Conic(real circle, centre=(0, 0))
    >>> C.polar(Point.from_xy(2, 0))
    Line(through=(0.5, 0), direction=(0, -1))
    >>> C.pole(Line.at_infinity())
    Point(x=0, y=0)
    """

    __slots__ = ()

    def __init__(self, matrix):
        if isinstance(matrix, Conic):
            matrix = matrix.matrix
        m = _c._conic(matrix, "matrix")
        if m.shape != (3, 3):
            raise ShapeError(f"matrix must have shape (3, 3), got shape {m.shape}")
        if not np.any(m):
            raise DegenerateGeometryError("matrix is zero, which is no conic")
        m = 0.5 * (m + m.T)
        m.setflags(write=False)
        self._a = m

    circle = _conic_of(_c.conic_circle, """
        >>> Conic.circle((1, 2), 3), Conic.circle((0, 0), 1, imaginary=True)
        (Conic(real circle, centre=(1, 2)), Conic(imaginary circle, centre=(0, 0)))""")
    ellipse = _conic_of(_c.conic_ellipse, """
        >>> Conic.ellipse((1, 2), (3, 1)).affine_frame().t
        array([1., 2.])""")
    hyperbola = _conic_of(_c.conic_hyperbola, """
        >>> Conic.hyperbola((0, 0), (1, 2))
        Conic(real hyperbola, centre=(0, 0))""")
    parabola = _conic_of(_c.conic_parabola, """
        >>> P = Conic.parabola((0, 0), 0.25)                  # y = x²
        >>> P, P.contains(Point.from_xy(2, 4))
        (Conic(real parabola, vertex=(0, 0), axis=(0, 1)), True)""")
    from_coefficients = _conic_of(_c.conic_from_coefficients, """
        >>> Conic.from_coefficients(1, 0, 1, 0, 0, -4)      # x² + y² = 4
        Conic(real circle, centre=(0, 0))""")

    @property
    def matrix(self) -> np.ndarray:
        """The read-only symmetric matrix."""
        return self._a

    @_shared
    def polar(self, point) -> Line:
        """The polar line ``C p`` of ``point`` (thesis 5.36).

        For an inertia conic this is the axis of percussion of an acceleration
        pole (5.64).  A point at infinity maps to a diameter (a line through
        the centre).

        Parameters
        ----------
        {point}

        Returns
        -------
        Line
            The polar ``C p``.

        Examples
        --------
        >>> C = Conic.circle((0, 0), 1)
        >>> C.polar(Point.from_xy(2, 0))                # x = r²/2 = 1/2
        Line(through=(0.5, 0), direction=(0, -1))
        >>> C.polar(Point.at_infinity((1, 0)))          # the diameter perpendicular to x
        Line(through=(0, 0), direction=(0, -1))
        """
        return Line(_c.polar(self._a, _as_point_array(point, "point")))

    @_shared
    def pole(self, line) -> Point:
        """The pole ``C⁻¹ l`` of ``line`` (thesis 5.37), the inverse of :meth:`polar`.

        The line at infinity maps to the centre; a line through the centre to
        a point at infinity.  A degenerate (singular) conic raises
        :class:`~planargeo.errors.DegenerateGeometryError`.

        Parameters
        ----------
        {line}

        Returns
        -------
        Point
            The pole ``C⁻¹ l``.

        Examples
        --------
        >>> C = Conic.circle((0, 0), 1)
        >>> C.pole(Line.from_point_direction((0.5, 0), (0, 1)))   # x = 1/2
        Point(x=2, y=0)
        >>> C.pole(Line.at_infinity())
        Point(x=0, y=0)
        """
        return Point(_c.pole(self._a, _as_line_array(line, "line")))

    def classify(self, rtol: float = 1e-10) -> _c.ConicType:
        """Real / imaginary / degenerate and kind (thesis 5.2.2; see :func:`planargeo.geometry.conics.classify`).

        Parameters
        ----------
        rtol : float, optional
            Relative tolerance for zero eigenvalues and circles.

        Returns
        -------
        ConicType
            Reality, kind, whether a circle, and rank.

        Examples
        --------
        >>> Conic.circle((0, 0), 1).classify()
        ConicType(reality='real', kind='ellipse', is_circle=True, rank=3)
        >>> str(Conic(np.diag([2.0, 2.0, 8.0])).classify())    # an inertia: no real points
        'imaginary circle'
        >>> str(Conic.parabola((0, 0), 1).classify())
        'real parabola'
        """
        return _c.classify(self._a, rtol=rtol)

    @property
    def centre(self) -> Point:
        """The centre: the pole ``C⁻¹ [0, 0, 1]`` of the line at infinity (thesis 5.37 with 5.16; 5.2.2).

        A point at infinity (the axis direction) for a parabola; the centre of
        mass for an inertia (4.58).  See :func:`planargeo.geometry.conics.centre`.

        Examples
        --------
        >>> Conic.ellipse((1, 2), (2, 1)).centre
        Point(x=1, y=2)
        >>> Conic.parabola((0, 0), 1).centre            # y = x²/4: ideal point along the axis
        Point(at infinity, direction=(0, 1))
        """
        return Point(_c.centre(self._a))

    @_shared
    def contains(self, point, rtol: float = 1e-9) -> bool:
        """True if ``point`` lies on the conic: ``|p C p| <= rtol |C| |p|²`` (thesis 5.38).

        Points at infinity are ordinary: a hyperbola contains the ideal points
        of its asymptotes.

        Parameters
        ----------
        {point}
        rtol : float, optional
            Relative tolerance of the test.

        Returns
        -------
        bool
            Whether the point lies on the conic.

        Examples
        --------
        >>> C = Conic.circle((0, 0), 1)
        >>> C.contains(Point.from_xy(0.6, 0.8)), C.contains(Point.from_xy(1, 1))
        (True, False)
        >>> Conic.hyperbola((0, 0), (1, 1)).contains(Point.at_infinity((1, 1)))   # asymptote y = x
        True
        """
        return bool(_c.is_on_conic(self._a, _as_point_array(point, "point"), rtol=rtol))

    @_shared
    def tangents_from(self, point):
        """The two tangents from an exterior ``point`` and their contact points.

        Returns ``((Line, Line), (Point, Point))``: the tangent ``i`` touches
        at contact point ``i``, which lies on the polar of ``point`` (thesis
        5.2.2, 5.39).  Raises :class:`~planargeo.errors.InputError` for an
        interior point (see :func:`planargeo.geometry.conics.tangents_from_point`).

        Parameters
        ----------
        {point}

        Returns
        -------
        tuple
            ``((Line, Line), (Point, Point))``: the tangents and their contact points.

        Examples
        --------
        >>> (t1, t2), (x1, x2) = Conic.circle((0, 0), 1).tangents_from(Point.from_xy(2, 0))
        >>> x1, x2                                      # (1/2, ±√3/2), on the polar x = 1/2
        (Point(x=0.5, y=0.866025), Point(x=0.5, y=-0.866025))
        >>> abs(t1 @ Point.from_xy(2, 0)) < 1e-12       # the tangent passes through the point
        True
        """
        L, X = _c.tangents_from_point(self._a, _as_point_array(point, "point"))
        return (Line(L[0]), Line(L[1])), (Point(X[0]), Point(X[1]))

    def affine_frame(self) -> _c.AffineFrame:
        """``x = A u + t`` mapping the unit curve onto this real conic.

        Returns
        -------
        AffineFrame
            See :func:`planargeo.geometry.conics.affine_frame`.

        Examples
        --------
        >>> F = Conic.ellipse((1, 2), (3, 1)).affine_frame()
        >>> F.kind, F.t, np.abs(F.A).round(12)
        ('ellipse', array([1., 2.]), array([[3., 0.],
               [0., 1.]]))
        """
        return _c.affine_frame(self._a)

    def drawable(self) -> "Conic":
        """The real point-reflection partner of an imaginary conic (thesis 10.2.3); self if real.

        For an inertia it is the circle (or ellipse) of gyration about the
        centre of mass: the polar of a point with respect to it is the point
        reflection, through the centre, of the polar with respect to the
        inertia.  See :func:`planargeo.geometry.conics.drawable_conic`.

        Returns
        -------
        Conic
            The real partner, or ``self`` for a real conic.

        Examples
        --------
        >>> I = Conic(np.diag([2.0, 2.0, 8.0]))    # inertia m = 2, J = 8 at the origin
        >>> I, I.drawable()                                 # ρ = sqrt(J/m) = 2
        (Conic(imaginary circle, centre=(0, 0)), Conic(real circle, centre=(0, 0)))
        >>> I.drawable().contains(Point.from_xy(2, 0))
        True
        """
        return Conic(_c.drawable_conic(self._a))

    def __repr__(self) -> str:
        t = self.classify()
        name = str(t)
        if t.reality == "degenerate":
            return f"Conic(degenerate {name}, matrix={np.round(self._a, 6).tolist()})"
        if t.kind == "parabola" and t.reality == "real":
            F = _c.affine_frame(self._a)
            d = F.A[:, 1] / np.linalg.norm(F.A[:, 1])
            return (f"Conic({name}, vertex=({_fmt(F.t[0])}, {_fmt(F.t[1])}), "
                    f"axis=({_fmt(d[0])}, {_fmt(d[1])}))")
        z = _c.centre(self._a)
        x, y = _p.to_xy(z)
        return f"Conic({name}, centre=({_fmt(x)}, {_fmt(y)}))"
