"""Thin classes over the array functions: :class:`Point`, :class:`Line`, :class:`Conic` (thesis 5).

Each holds one validated read-only array; equality is projective (proportional arrays), so they
are not hashable.  ``p ^ q`` is the join, ``l ^ m`` the meet, ``p @ l`` the incidence form.
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
_shared = entries({
    "point": "point : Point or array_like, shape (3,)\n    A Point or homogeneous point array.",
    "line": "line : Line or array_like, shape (3,)\n    A Line or homogeneous line array.",
    "other": "other : Point, Line or array_like, shape (3,)\n    The element of the dual kind.",
    **{f"other_{kind.lower()}": f"other : {kind} or array_like, shape (3,)\n    The second {kind.lower()}."
       for kind in ("Point", "Line")},
    "not_pair": "Raises\n------\nShapeError\n    A pair of coordinates not of shape (2,).",
    "not_one": "Raises\n------\nShapeError, DegenerateGeometryError\n"
               "    ``array`` not of shape (3,), or zero.",
}, {f"returns_{kind.lower()}": f"Returns\n-------\n{kind}"
    for kind in ("Point", "Line", "Conic", "float", "bool")})


def _fmt(v: float) -> str:
    return "0" if float(v) == 0 else f"{float(v):.6g}"


def _one(x, name: str, n: int) -> np.ndarray:
    """``x`` as one vector of ``n`` floats (a batch is refused)."""
    a = as_array(x, name, (n,))
    if a.shape != (n,):
        raise ShapeError(f"{name} must have shape ({n},), got shape {a.shape}")
    return a


def _vec(x, name: str) -> np.ndarray:
    a = _one(x, name, 3) + 0.0
    a.setflags(write=False)
    return a


def _proportional(a: np.ndarray, b: np.ndarray) -> bool:
    a = a.ravel() / np.linalg.norm(a)
    b = b.ravel() / np.linalg.norm(b)
    return bool(min(np.linalg.norm(a - b), np.linalg.norm(a + b)) <= _EQ_TOL * 10)


class _Homogeneous:
    """Common base: one read-only array ``_a``, compared projectively."""

    __slots__ = ("_a",)
    __hash__ = None

    def __eq__(self, other):
        if not isinstance(other, type(self)):
            return NotImplemented
        return _proportional(self._a, other._a)

    def __array__(self, dtype=None, copy=None):
        return np.array(self._a, dtype=dtype)


class _PointOrLine(_Homogeneous):
    """What points and lines share by duality (thesis 5.3): ``^`` is ``_wedge``, ``@`` incidence."""

    __slots__ = ()

    def __init__(self, array):
        a = _vec(array, "array")
        if not np.any(a):
            raise DegenerateGeometryError(f"array is the zero vector, which is no {type(self).__name__.lower()}")
        self._a = a

    def normalized(self):
        """The element normalised: a point at ``w = 1``, a line of unit force (thesis 5.49, 5.55).

        Returns
        -------
        Point or Line

        Examples
        --------
        >>> Point([2.0, -4.0, 2.0]).normalized().array     # the point (2, 1)
        array([ 1., -2.,  1.])
        """
        return type(self)(self._normalize(self._a))

    @property
    def array(self) -> np.ndarray:
        """The read-only homogeneous coordinates."""
        return self._a

    @property
    def direction(self) -> np.ndarray:
        """Unit direction of an ideal point, or along a line; else NaN."""
        return self._direction(self._a)

    def _pair(self, other) -> tuple:
        """``(point, line)`` arrays of this element and ``other`` of the dual kind."""
        theirs = _vec(other, self._dual.__name__.lower())
        return (self._a, theirs) if self._dual is Line else (theirs, self._a)

    @_shared
    def incidence(self, other) -> float:
        """The form ``p @ l`` with ``other`` of the dual kind (thesis 5.23): zero iff incident.

        {parameters other returns_float}

        Examples
        --------
        >>> Line.at_infinity() @ Point.at_infinity((3, 4))    # every ideal point is on it
        0.0
        """
        return float(_p.incidence(*self._pair(other)))

    @_shared
    def _signed_distance(self, other) -> float:
        """Signed distance (m) of the point from the line, positive on its left (thesis 5.23).

        {parameters other returns_float}

        Examples
        --------
        >>> Line.from_point_direction((0, 1), (1, 0)).signed_distance(Point.from_xy(3, 4))   # y = 1
        3.0
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


@_shared
class Point(_PointOrLine):
    """A point of the projective plane (thesis 5.49): a twist's pole.

    Parameters
    ----------
    array : array_like, shape (3,)
        ``[y, -x, w]`` (any non-zero multiple); ``w = 0`` at infinity.

    {not_one}

    Examples
    --------
    >>> Point.from_xy(0, 0) ^ Point.from_xy(1, 1)
    Line(through=(0, 0), direction=(0.707107, 0.707107))
    """

    __slots__ = ()
    _normalize, _direction = staticmethod(_p.normalize_point), staticmethod(_p.direction)

    # constructors
    @classmethod
    @_shared
    def from_xy(cls, x, y=None) -> "Point":
        """The finite point ``(x, y)``: ``from_xy(x, y)`` or ``from_xy((x, y))``.

        Parameters
        ----------
        x : float or array_like, shape (2,)
            ``x`` (m), or the pair ``(x, y)``.
        y : float, optional
            ``y`` (m).

        {returns_point}

        {not_pair}

        Examples
        --------
        >>> Point.from_xy(1, 2)
        Point(x=1, y=2)
        """
        return cls(_p.from_xy(_one(x if y is None else (x, y), "xy", 2)))

    @classmethod
    @_shared
    def at_infinity(cls, direction) -> "Point":
        """The point at infinity in ``direction``.

        Parameters
        ----------
        direction : array_like, shape (2,)
            A non-zero direction.

        {returns_point}

        {not_pair}

        Examples
        --------
        >>> Point.at_infinity((1, 0))
        Point(at infinity, direction=(1, 0))
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
    @_shared
    def join(self, other) -> "Line":
        """The line through this point and ``other`` (thesis 5.32); also ``p ^ q``.

        {parameters other_point returns_line}

        Examples
        --------
        >>> Point.from_xy(0, 2).join(Point.at_infinity((1, 0)))     # the horizontal line y = 2
        Line(through=(0, 2), direction=(1, 0))
        """
        return Line(_p.join(self._a, _vec(other, "other")))

    _wedge = join

    def __repr__(self) -> str:
        if self.is_ideal:
            d = self.direction
            return f"Point(at infinity, direction=({_fmt(d[0])}, {_fmt(d[1])}))"
        x, y = self.xy
        return f"Point(x={_fmt(x)}, y={_fmt(y)})"


@_shared
class Line(_PointOrLine):
    """A line of the projective plane (thesis 5.55): a wrench's line of action.

    Parameters
    ----------
    array : array_like, shape (3,)
        ``[fx, fy, tz]``: the points with ``tz + y fx - x fy = 0``, directed along ``(fx, fy)``.

    {not_one}

    Examples
    --------
    >>> Line([1, 0, 0]) ^ Line([0, 1, -3])
    Point(x=-3, y=0)
    """

    __slots__ = ()
    _normalize, _direction = staticmethod(_p.normalize_line), staticmethod(_p.line_direction)

    @classmethod
    @_shared
    def through(cls, p, q) -> "Line":
        """The line from ``p`` to ``q`` (thesis 5.32).

        Parameters
        ----------
        p, q : Point or array_like, shape (3,)
            Two distinct points.

        {returns_line}

        Examples
        --------
        >>> Line.through(Point.from_xy(0, 1), Point.from_xy(2, 1))
        Line(through=(0, 1), direction=(1, 0))
        """
        return cls(_p.join(_vec(p, "p"), _vec(q, "q")))

    @classmethod
    @_shared
    def at_infinity(cls) -> "Line":
        """The line at infinity ``[0, 0, 1]`` (thesis 5.16).

        {returns_line}

        Examples
        --------
        >>> Line.at_infinity()
        Line(at infinity)
        """
        return cls(_p.LINE_AT_INFINITY)

    @classmethod
    @_shared
    def from_point_direction(cls, point, direction) -> "Line":
        """The line through ``point`` (a Point, or ``(x, y)``) along ``direction``.

        Parameters
        ----------
        point : Point or array_like, shape (2,)
            A Point or Euclidean ``(x, y)`` (m).
        direction : array_like, shape (2,)
            Direction of the line (non-zero).

        {returns_line}

        {not_pair}

        Examples
        --------
        >>> Line.from_point_direction((1, 0), (0, 3)).array    # x = 1: a force of 3 N along +y
        array([0., 3., 3.])
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

    @_shared
    def meet(self, other) -> Point:
        """The common point with ``other`` (thesis 5.34), at infinity if parallel; also ``l ^ m``.

        {parameters other_line returns_point}

        Examples
        --------
        >>> Line([0.0, 1.0, 2.0]).meet(Line.from_point_direction((0, 1), (1, 0)))   # x = 2, y = 1
        Point(x=2, y=1)
        """
        return Point(_p.meet(self._a, _vec(other, "other")))

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
    """A constructor of :class:`Conic`: ``make`` of the conics module, with its docstring."""
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
    matrix : array_like, shape (3, 3)
        Symmetric (one conic; :mod:`planargeo.geometry.conics` broadcasts).

    Raises
    ------
    ShapeError, DegenerateGeometryError
        ``matrix`` not of shape (3, 3), or zero.

    Examples
    --------
    >>> C = Conic.circle((0, 0), 1)
    >>> C, C.pole(Line.at_infinity())
    (Conic(real circle, centre=(0, 0)), Point(x=0, y=0))
    """

    __slots__ = ()

    def __init__(self, matrix):
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
        """The polar line ``C p`` of ``point`` (thesis 5.36, 5.64).

        {parameters point returns_line}

        Examples
        --------
        >>> Conic.circle((0, 0), 1).polar(Point.from_xy(2, 0))                # x = r²/2 = 1/2
        Line(through=(0.5, 0), direction=(0, -1))
        """
        return Line(_c.polar(self._a, _vec(point, "point")))

    @_shared
    def pole(self, line) -> Point:
        """The pole ``C⁻¹ l`` of ``line`` (thesis 5.37), the inverse of :meth:`polar`.

        {parameters line returns_point}

        Examples
        --------
        >>> Conic.circle((0, 0), 1).pole(Line.from_point_direction((0.5, 0), (0, 1)))   # x = 1/2
        Point(x=2, y=0)
        """
        return Point(_c.pole(self._a, _vec(line, "line")))

    def classify(self, rtol: float = 1e-10) -> _c.ConicType:
        """Real / imaginary / degenerate and kind (thesis 5.2.2; :func:`~.conics.classify`).

        Parameters
        ----------
        rtol : float, optional
            Relative tolerance for zero eigenvalues and circles.

        Returns
        -------
        ConicType

        Examples
        --------
        >>> str(Conic(np.diag([2.0, 2.0, 8.0])).classify())    # an inertia: no real points
        'imaginary circle'
        """
        return _c.classify(self._a, rtol=rtol)

    @property
    def centre(self) -> Point:
        """The centre, the pole of the line at infinity (thesis 5.2.2, 4.58); ideal for a parabola.

        Examples
        --------
        >>> Conic.ellipse((1, 2), (2, 1)).centre
        Point(x=1, y=2)
        """
        return Point(_c.centre(self._a))

    @_shared
    def contains(self, point, rtol: float = 1e-9) -> bool:
        """True if ``point`` lies on the conic: ``|p C p| <= rtol |C| |p|²`` (thesis 5.38).

        {parameters point}
        rtol : float, optional
            Relative tolerance of the test.

        {returns_bool}

        Examples
        --------
        >>> Conic.hyperbola((0, 0), (1, 1)).contains(Point.at_infinity((1, 1)))   # asymptote y = x
        True
        """
        return bool(_c.is_on_conic(self._a, _vec(point, "point"), rtol=rtol))

    @_shared
    def tangents_from(self, point):
        """The two tangents from an exterior ``point``, and their contacts (thesis 5.2.2, 5.39).

        {parameters point}

        Returns
        -------
        tuple
            ``((Line, Line), (Point, Point))``: tangent ``i`` touches at contact ``i``.

        Examples
        --------
        >>> (t1, t2), (x1, x2) = Conic.circle((0, 0), 1).tangents_from(Point.from_xy(2, 0))
        >>> x1                                      # on the polar x = 1/2
        Point(x=0.5, y=0.866025)
        """
        L, X = _c.tangents_from_point(self._a, _vec(point, "point"))
        return (Line(L[0]), Line(L[1])), (Point(X[0]), Point(X[1]))

    def affine_frame(self) -> _c.AffineFrame:
        """``x = A u + t`` mapping the unit curve onto this real conic (``conics.affine_frame``).

        Returns
        -------
        AffineFrame

        Examples
        --------
        >>> Conic.ellipse((1, 2), (3, 1)).affine_frame().t
        array([1., 2.])
        """
        return _c.affine_frame(self._a)

    @_shared
    def drawable(self) -> "Conic":
        """The real point-reflection partner of an imaginary conic (thesis 10.2.3); self if real.

        {returns_conic}

        Examples
        --------
        >>> Conic(np.diag([2.0, 2.0, 8.0])).drawable()     # inertia m = 2, J = 8: ρ = 2
        Conic(real circle, centre=(0, 0))
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
