"""Points and lines of the projective plane as arrays (thesis chapter 5).

A point ``(x, y)`` is ``[y, -x, 1]`` (5.51), a line a wrench ``[fx, fy, tz]`` (5.56).  Ideal
elements are ordinary values, decided by exact zeros.  Functions broadcast; vectors are rescaled
exactly where products could overflow, and a result beyond double precision raises
:class:`~planargeo.errors.NumericOverflowError`.
"""
from __future__ import annotations

import math

import numpy as np

from planargeo._validate import as_array, as_scalar, as_vec3, as_xy, batch_shape, check_overflow
from planargeo.errors import COND_LIMIT, DegenerateGeometryError, InputError
from planargeo.geometry._docs import entries

__all__ = [
    "T_STD", "LINE_AT_INFINITY",
    "normalize", "normalize_point", "normalize_line",
    "is_ideal", "is_at_infinity",
    "from_xy", "from_direction", "to_xy", "direction", "line_direction",
    "join", "meet", "cross_cond", "incidence", "signed_distance", "pencil",
    "line_through_point_direction", "foot_point",
    "to_standard", "from_standard", "conic_to_standard", "conic_from_standard",
]

#: Change of coordinates of thesis (5.47): ``alternative = T_STD @ standard``.
#: It is symmetric, orthogonal and a proper rotation (det = +1), hence its own
#: inverse, and cross products (join, meet) carry over unchanged.
T_STD = np.array([[0.0, 0.0, 1.0], [0.0, -1.0, 0.0], [1.0, 0.0, 0.0]])
T_STD.setflags(write=False)

#: The line at infinity ``[0, 0, 1]`` (a pure couple).
LINE_AT_INFINITY = np.array([0.0, 0.0, 1.0])
LINE_AT_INFINITY.setflags(write=False)


#: Docstring entries many functions here share, each said once (a line ``{p l}`` in a docstring).
_shared = entries({
    "p": "p : array_like, shape (..., 3)\n    Homogeneous points.",
    "l": "l : array_like, shape (..., 3)\n    Homogeneous lines ``[fx, fy, tz]``.",
    "normalized": "Returns\n-------\nndarray, shape (..., 3)\n    The base coordinates.\n\n"
                  "Raises\n------\nDegenerateGeometryError, NumericOverflowError\n"
                  "    Some element is the zero vector, or a finite one lies beyond double precision.",
    "p_q": "p, q : array_like, shape (..., 3)\n    Homogeneous points.",
    "l_m": "l, m : array_like, shape (..., 3)\n    Homogeneous lines.",
    "cond_limit": "cond_limit : float, optional\n"
                  "    Largest accepted condition number ``κ`` (:func:`cross_cond`; default\n"
                  "    :data:`planargeo.errors.COND_LIMIT`, ``1e12``).",
    "cross_raises": "Raises\n------\nDegenerateGeometryError\n"
                    "    The two are the same element or one is zero (``.cond`` is ``inf``),\n"
                    "    or κ > ``cond_limit``.",
    "standard": "Returns\n-------\nnumpy.ndarray, shape (..., 3, 3)",
})


def _first_index(mask: np.ndarray) -> str:
    """Human-readable position of the first True in ``mask`` ('' for a scalar)."""
    if mask.ndim == 0:
        return ""
    idx = tuple(int(i) for i in np.argwhere(mask)[0])
    return f" at index {idx}"


def _cross(a, b):
    """Cross product over the last axis (broadcasting); ~10x faster than ``np.cross``."""
    a, b = np.asarray(a, float), np.asarray(b, float)
    if a.shape == b.shape == (3,):    # one pair: Python floats, one array (a few µs less than the general path)
        a0, a1, a2 = a.tolist()
        b0, b1, b2 = b.tolist()
        return np.array([a1 * b2 - a2 * b1, a2 * b0 - a0 * b2, a0 * b1 - a1 * b0])
    a, b = np.broadcast_arrays(a, b)
    out = np.empty(a.shape)
    out[..., 0] = a[..., 1] * b[..., 2] - a[..., 2] * b[..., 1]
    out[..., 1] = a[..., 2] * b[..., 0] - a[..., 0] * b[..., 2]
    out[..., 2] = a[..., 0] * b[..., 1] - a[..., 1] * b[..., 0]
    return out


def _safe_div(num, den):
    """``num / den`` where ``den != 0``, NaN elsewhere, without warnings (overflow gives ±inf)."""
    num, den = np.broadcast_arrays(np.asarray(num, float), np.asarray(den, float))
    out = np.full(num.shape, np.nan)
    with np.errstate(over="ignore"):
        np.divide(num, den, out=out, where=den != 0)
    return out


_TINY, _HUGE = 1e-150, 1e150          # squared norms of vectors in this range neither over- nor underflow
_TINY2, _HUGE2 = _TINY * _TINY, _HUGE * _HUGE   # the same bounds on the squared norms


def _fit(a: np.ndarray, core: int = 1, tiny: float = _TINY, huge: float = _HUGE) -> np.ndarray:
    """``a``, each vector (``core=2``: matrix) with largest |entry| outside ``(tiny, huge)`` scaled
    exactly by a power of two to a largest entry in ``[0.5, 1)``."""
    if a.ndim == core == 1:                   # one vector: plain floats are faster
        m = max(map(abs, a.tolist()), default=0.0)
        return a if tiny < m < huge or m == 0 or m != m else np.ldexp(a, -math.frexp(m)[1])
    m = np.abs(a).max(axis=tuple(range(-core, 0)), keepdims=True)
    ok = ((m > tiny) & (m < huge)) | (m == 0)
    if np.all(ok):
        return a
    return np.where(ok, a, np.ldexp(a, -np.frexp(m)[1]))


def _fit_line(l: np.ndarray) -> np.ndarray:
    """Lines scaled exactly by a power of two to a force ``|(fx, fy)|`` (else ``|tz|``) near 1."""
    if l.ndim == 1:                           # one line: plain floats are faster
        fx, fy, tz = l.tolist()
        m = max(abs(fx), abs(fy)) or abs(tz)
        if _TINY < m < _HUGE or m == 0:
            return l
    f = np.maximum(np.abs(l[..., 0]), np.abs(l[..., 1]))
    m = np.where(f != 0, f, np.abs(l[..., 2]))[..., None]
    if np.all(((m > _TINY) & (m < _HUGE)) | (m == 0)):
        return l
    with np.errstate(over="ignore"):
        return np.ldexp(l, -np.frexp(m)[1])


def _refuse_zero(x: np.ndarray, name: str, what: str) -> None:
    if x.ndim == 1 and any(x.tolist()):      # one vector, not zero: the common case, quickly
        return
    zero = np.all(x == 0, axis=-1)
    if np.any(zero):
        raise DegenerateGeometryError(f"{name} is the zero vector{_first_index(zero)}, which is no {what}")


# --------------------------------------------------------------------------- normalisation
@_shared
def normalize_point(p) -> np.ndarray:
    """Base coordinates of points (thesis 5.2, 5.49): weight ``w = 1``, or unit length at infinity.

    A finite point ``(x, y)`` becomes ``[y, -x, 1]`` (5.51).

    {parameters p normalized}

    Examples
    --------
    >>> normalize_point([4.0, -2.0, 2.0])
    array([ 2., -1.,  1.])
    """
    p = as_vec3(p, "p")
    _refuse_zero(p, "p", "point")
    p = _fit(p)
    w = p[..., 2]
    den = np.where(w != 0, w, np.linalg.norm(p, axis=-1))
    with np.errstate(over="ignore"):
        return check_overflow(p / den[..., None], "normalize_point(p)", "p's coordinates")


@_shared
def normalize_line(l) -> np.ndarray:
    """Base coordinates of lines (thesis 5.11, 5.55): unit force, or ``tz = ±1`` at infinity.

    {parameters l normalized}

    Examples
    --------
    >>> normalize_line([0.0, 2.0, 4.0])       # the vertical line x = 2, pointing up
    array([0., 1., 2.])
    """
    l = as_vec3(l, "l")
    _refuse_zero(l, "l", "line")
    l = _fit_line(l)
    f = np.hypot(l[..., 0], l[..., 1])
    den = np.where(f != 0, f, np.abs(l[..., 2]))
    with np.errstate(over="ignore"):
        return check_overflow(l / den[..., None], "normalize_line(l)", "l's distance from the origin")


@_shared
def normalize(x, kind: str | None = None) -> np.ndarray:
    """Base coordinates of points or lines by ``kind`` (thesis 5.49, 5.55; ``normalize_*``).

    Parameters
    ----------
    x : array_like, shape (..., 3)
        Homogeneous points or lines.
    kind : {"point", "line"}
        How to read ``x`` (required: the two are scaled differently).

    {returns_3}

    Raises
    ------
    InputError
        ``kind`` missing or not ``"point"`` / ``"line"``.

    Examples
    --------
    >>> normalize([3.0, 4.0, 10.0], kind="line")
    array([0.6, 0.8, 2. ])
    """
    if kind is None:
        raise InputError("kind must be given, 'point' or 'line' (a point and a line are scaled differently)")
    if kind == "point":
        return normalize_point(x)
    if kind == "line":
        return normalize_line(x)
    raise InputError(f"kind must be 'point' or 'line', got {kind!r}")


@_shared
def is_ideal(p) -> np.ndarray:
    """True for points at infinity: weight ``w = p[..., 2]`` exactly zero (thesis 5.5).

    {parameters p returns_bool}

    Examples
    --------
    >>> is_ideal([[1.0, 0.0, 0.0], [1.0, 0.0, 1.0]])
    array([ True, False])
    """
    p = as_vec3(p, "p")
    return p[..., 2] == 0


@_shared
def is_at_infinity(l) -> np.ndarray:
    """True for the line at infinity: force ``(fx, fy)`` exactly zero (thesis 5.16).

    {parameters l returns_bool}

    Examples
    --------
    >>> bool(is_at_infinity([0.0, 0.0, 2.0]))
    True
    """
    l = as_vec3(l, "l")
    return (l[..., 0] == 0) & (l[..., 1] == 0)


# --------------------------------------------------------------------------- Euclidean <-> homogeneous
@_shared
def from_xy(xy) -> np.ndarray:
    """Homogeneous point ``[y, -x, 1]`` of Euclidean points (thesis 5.49, 5.51).

    Parameters
    ----------
    xy : array_like, shape (..., 2)
        Euclidean points ``(x, y)`` (m).

    {returns_3}

    Examples
    --------
    >>> from_xy([1.0, 2.0])
    array([ 2., -1.,  1.])
    """
    xy = as_xy(xy, "xy")
    out = np.empty(xy.shape[:-1] + (3,))
    out[..., 0] = xy[..., 1]
    out[..., 1] = -xy[..., 0]
    out[..., 2] = 1.0
    return out


@_shared
def from_direction(d) -> np.ndarray:
    """The point at infinity ``[dy, -dx, 0]`` in direction ``d`` (a translation normal to ``d``).

    Parameters
    ----------
    d : array_like, shape (..., 2)
        A non-zero Euclidean direction.

    {returns_3}

    Raises
    ------
    DegenerateGeometryError
        ``d`` is the zero vector: it has no direction.

    Examples
    --------
    >>> from_direction([0.0, 1.0])
    array([1., 0., 0.])
    """
    d = as_xy(d, "d")
    zero = (d[..., 0] == 0) & (d[..., 1] == 0)
    if np.any(zero):
        raise DegenerateGeometryError(f"d is the zero vector{_first_index(zero)}, which has no direction")
    out = np.zeros(d.shape[:-1] + (3,))
    out[..., 0] = d[..., 1]
    out[..., 1] = 0.0 - d[..., 0]
    return out


@_shared
def to_xy(p) -> np.ndarray:
    """Euclidean coordinates ``(-p1/w, p0/w)`` of points (thesis 5.51); NaN at infinity, silently.

    {parameters p returns_2}

    Raises
    ------
    DegenerateGeometryError, NumericOverflowError
        ``p`` is the zero vector, or a finite point beyond double precision.

    Examples
    --------
    >>> to_xy([4.0, -2.0, 2.0])
    array([1., 2.])
    """
    p = as_vec3(p, "p")
    _refuse_zero(p, "p", "point")
    w = p[..., 2]
    xy = np.stack([_safe_div(-p[..., 1], w), _safe_div(p[..., 0], w)], axis=-1)
    return check_overflow(xy, "to_xy(p)", "p's coordinates", ok=(w == 0)[..., None])


@_shared
def direction(p) -> np.ndarray:
    """Unit direction ``(-b, a)/|(a, b)|`` of an ideal point ``[a, b, 0]``; NaN for finite points.

    {parameters p returns_2}

    Examples
    --------
    >>> direction([1.0, 0.0, 0.0])
    array([0., 1.])
    """
    p = as_vec3(p, "p")
    _refuse_zero(p, "p", "point")
    p = _fit(p)
    n = np.hypot(p[..., 0], p[..., 1])
    den = np.where(p[..., 2] == 0, n, 0.0)
    return np.stack([_safe_div(-p[..., 1], den), _safe_div(p[..., 0], den)], axis=-1)


@_shared
def line_direction(l) -> np.ndarray:
    """Unit direction ``(fx, fy)/|f|`` along a line (thesis 5.55); NaN for the line at infinity.

    {parameters l returns_2}

    Examples
    --------
    >>> line_direction([0.0, -3.0, 1.0])
    array([ 0., -1.])
    """
    l = as_vec3(l, "l")
    _refuse_zero(l, "l", "line")
    f = _fit(l[..., :2])
    n = np.hypot(f[..., 0], f[..., 1])
    return np.stack([_safe_div(f[..., 0], n), _safe_div(f[..., 1], n)], axis=-1)


@_shared
def foot_point(l) -> np.ndarray:
    """The point of a line nearest the origin, at weight 1 (NaN for the line at infinity).

    {parameters l returns_3}

    Examples
    --------
    >>> to_xy(foot_point([0.0, 1.0, 2.0]))     # the line x = 2
    array([2., 0.])
    """
    l = as_vec3(l, "l")
    _refuse_zero(l, "l", "line")
    at_infinity = (l[..., 0] == 0) & (l[..., 1] == 0)
    l = _fit_line(l)
    f2 = l[..., 0] ** 2 + l[..., 1] ** 2
    with np.errstate(over="ignore", invalid="ignore"):     # tz = inf: a line beyond range, reported below
        x = _safe_div(l[..., 2] * l[..., 1], f2)
        y = _safe_div(0.0 - l[..., 2] * l[..., 0], f2)
    foot = np.stack([y + 0.0, 0.0 - x, np.where(f2 != 0, 1.0, np.nan)], axis=-1)
    return check_overflow(foot, "foot_point(l)", "l's distance from the origin", ok=at_infinity[..., None])


# --------------------------------------------------------------------------- join / meet
@_shared
def cross_cond(a, b) -> np.ndarray:
    """Condition number ``κ = |a| |b| / |a × b|`` of :func:`join` and :func:`meet`.

    Parameters
    ----------
    a, b : array_like, shape (..., 3)
        Two homogeneous points, or two lines.

    {returns_scalar}

    Examples
    --------
    >>> round(float(cross_cond([0.0, 0.0, 1.0], [1.0, 0.0, 1.0])), 6)   # 45 degrees apart: √2
    1.414214
    """
    a, b = as_vec3(a, "a"), as_vec3(b, "b")
    batch_shape(a=(a, 1), b=(b, 1))
    a, b = np.broadcast_arrays(_fit(a), _fit(b))
    return _cross_cond(a, b, _cross(a, b))


def _cross_cond(a, b, c) -> np.ndarray:
    """κ of :func:`cross_cond` given ``c = a × b``; rescales only where the norms could over/underflow."""
    na = np.sqrt(np.einsum("...i,...i->...", a, a))
    nb = np.sqrt(np.einsum("...i,...i->...", b, b))
    nc = np.sqrt(np.einsum("...i,...i->...", c, c))
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        out = na * nb / nc
    ok = (na > _TINY) & (na < _HUGE) & (nb > _TINY) & (nb < _HUGE) & (nc > _TINY) & (nc < _HUGE)
    if np.all(ok):
        return out
    # rare: rescale to unit largest component (a zero vector gives NaN there, hence κ = inf)
    a, b = (_safe_div(x, np.abs(x).max(axis=-1, keepdims=True)) for x in (a, b))
    num = np.linalg.norm(a, axis=-1) * np.linalg.norm(b, axis=-1)
    c = _cross(a, b)
    mc = np.abs(c).max(axis=-1)
    den = np.linalg.norm(_safe_div(c, mc[..., None]), axis=-1) * mc
    slow = np.full(den.shape, np.inf)
    with np.errstate(over="ignore"):         # κ past the largest float is infinite for every purpose
        np.divide(num, den, out=slow, where=(den > 0) & ~np.isnan(num))
    return np.where(ok, out, slow)


def _checked_cross(a, b, names: str, what: str, cond_limit: float) -> np.ndarray:
    """``a × b`` for :func:`join` and :func:`meet`, refused when exactly zero or ill-conditioned."""
    if type(cond_limit) is not float or not cond_limit > 0:      # the default passes at no cost
        cond_limit = as_scalar(cond_limit, "cond_limit", finite=False)
        if not cond_limit > 0:
            raise InputError(f"cond_limit must be positive, got {cond_limit!r}")
    if a.shape == b.shape == (3,):
        # one pair (the common scalar call): the squared norms in plain float arithmetic; where they are
        # in range and κ passes (every ordinary case) return, else the array code below decides and reports
        a0, a1, a2 = a.tolist()
        b0, b1, b2 = b.tolist()
        c = _cross(a, b)
        c0, c1, c2 = c.tolist()
        na2 = a0 * a0 + a1 * a1 + a2 * a2
        nb2 = b0 * b0 + b1 * b1 + b2 * b2
        nc2 = c0 * c0 + c1 * c1 + c2 * c2
        if (_TINY2 < na2 < _HUGE2 and _TINY2 < nb2 < _HUGE2 and _TINY2 < nc2 < _HUGE2
                and math.sqrt(na2) * math.sqrt(nb2) / math.sqrt(nc2) <= cond_limit):
            return c
    batch_shape(**{names[0]: (a, 1), names[1]: (b, 1)})
    a, b = _fit(a), _fit(b)
    c = _cross(a, b)
    zero = np.all(c == 0, axis=-1)
    if np.any(zero):
        err = DegenerateGeometryError(
            what.format(kind="the same") + f" (or one is the zero vector){_first_index(zero)}, "
            + ("so the line through them is not unique" if what.startswith("join") else
               "so their common point is not unique"))
        err.cond = float("inf")
        raise err
    cond = _cross_cond(a, b, c)
    bad = ~(cond <= cond_limit)
    if np.any(bad):
        k = float(np.max(np.where(bad, cond, 0.0)))
        err = DegenerateGeometryError(
            what.format(kind="nearly the same") + f"{_first_index(bad)}: condition number {k:.3g} "
            f"exceeds cond_limit = {cond_limit:.3g} (relative error up to about ε κ = "
            f"{np.finfo(float).eps * k:.1g})")
        err.cond = k
        raise err
    return c


@_shared
def join(p, q, cond_limit: float = COND_LIMIT) -> np.ndarray:
    """The line through two points, ``p × q`` (thesis 5.27-5.32; 5.32 has the opposite orientation).

    {parameters p_q cond_limit returns_3 cross_raises}

    Examples
    --------
    >>> join(from_xy([0.0, 0.0]), from_xy([2.0, 0.0]))   # the x axis, pointing +x
    array([2., 0., 0.])
    >>> join(from_xy([0.0, 0.0]), from_xy([0.0, 1e-14]))     # 1e-14 apart: κ = 1e14
    Traceback (most recent call last):
    ...
    planargeo.errors.DegenerateGeometryError: join(p, q): p and q are nearly the same point: condition number 1e+14 exceeds cond_limit = 1e+12 (relative error up to about ε κ = 0.02)
    """
    p = as_vec3(p, "p")
    q = as_vec3(q, "q")
    return _checked_cross(p, q, "pq", "join(p, q): p and q are {kind} point", cond_limit)


@_shared
def meet(l, m, cond_limit: float = COND_LIMIT) -> np.ndarray:
    """The point common to two lines, ``l × m`` (thesis 5.33-5.34); parallel lines meet at infinity.

    {parameters l_m cond_limit returns_3 cross_raises}

    Examples
    --------
    >>> meet([1.0, 0.0, 0.0], [1.0, 0.0, 1.0])           # parallel: ideal point
    array([ 0., -1.,  0.])
    """
    l = as_vec3(l, "l")
    m = as_vec3(m, "m")
    return _checked_cross(l, m, "lm", "meet(l, m): l and m are {kind} line", cond_limit)


@_shared
def incidence(p, l) -> np.ndarray:
    """The form ``p @ l`` (thesis 5.23): zero iff ``p`` lies on ``l`` (5.24); a power (5.69).

    {parameters p l returns_scalar}

    Examples
    --------
    >>> float(incidence(from_xy([3.0, 0.0]), [1.0, 0.0, 0.0]))
    0.0
    """
    p = as_vec3(p, "p")
    l = as_vec3(l, "l")
    batch_shape(p=(p, 1), l=(l, 1))
    with np.errstate(over="ignore", invalid="ignore"):
        return check_overflow(np.einsum("...i,...i->...", p, l), "incidence(p, l)", "p or l")


@_shared
def signed_distance(p, l) -> np.ndarray:
    """Signed distance from point ``p`` to line ``l`` (thesis 5.23), positive on the line's left.

    Ideal elements give ``±inf``, or NaN for an ideal point on the line; no warning.

    {parameters p l returns_scalar}

    Examples
    --------
    >>> float(signed_distance(from_xy([0.0, 2.0]), [3.0, 0.0, 0.0]))   # left of the +x axis
    2.0
    """
    p = as_vec3(p, "p")
    l = as_vec3(l, "l")
    batch_shape(p=(p, 1), l=(l, 1))
    _refuse_zero(p, "p", "point")
    _refuse_zero(l, "l", "line")
    ideal = (p[..., 2] == 0) | ((l[..., 0] == 0) & (l[..., 1] == 0))
    p, l = _fit(p), _fit_line(l)
    with np.errstate(invalid="ignore"):
        num = np.einsum("...i,...i->...", p, l)
    den = np.where(ideal, 0.0, p[..., 2] * np.hypot(l[..., 0], l[..., 1]))
    out = _safe_div(num, den)
    inf = ideal & (num != 0)
    out = np.where(inf, np.copysign(np.inf, num * np.where(p[..., 2] < 0, -1.0, 1.0)), out)
    return check_overflow(out, "signed_distance(p, l)", "the distance", ok=ideal)


@_shared
def pencil(l1, l2, beta) -> np.ndarray:
    """Member ``l1 + beta (l2 - l1)`` of the pencil of two lines (thesis 5.20-5.22; points: (5.9)).

    Parameters
    ----------
    l1, l2 : array_like, shape (..., 3)
        Two lines (or points) spanning the pencil.
    beta : array_like, shape (...)
        ``0`` gives ``l1``, ``1`` gives ``l2``.

    {returns_3}

    Examples
    --------
    >>> pencil([1.0, 0.0, 0.0], [0.0, 1.0, 0.0], 0.5)   # the diagonal through the origin
    array([0.5, 0.5, 0. ])
    """
    l1 = as_vec3(l1, "l1")
    l2 = as_vec3(l2, "l2")
    beta = as_array(beta, "beta")
    batch_shape(l1=(l1, 1), l2=(l2, 1), beta=(beta, 0))
    with np.errstate(over="ignore", invalid="ignore"):
        return check_overflow(l1 + beta[..., None] * (l2 - l1), "pencil(l1, l2, beta)", "l1, l2 or beta")


@_shared
def line_through_point_direction(p, d) -> np.ndarray:
    """The line through point ``p`` along ``d`` (for ``w = 1``: the wrench of force ``d`` at ``p``).

    {parameters p}
    d : array_like, shape (..., 2)
        Euclidean direction (non-zero).

    {returns_3}

    Raises
    ------
    DegenerateGeometryError
        ``d`` is zero, or ``p`` is the ideal point in direction ``d``.

    Examples
    --------
    >>> line_through_point_direction(from_xy([1.0, 1.0]), [0.0, 2.0])   # x = 1
    array([0., 2., 2.])
    """
    p = as_vec3(p, "p")
    q = from_direction(d)
    try:
        return join(p, q)
    except DegenerateGeometryError as exc:
        raise DegenerateGeometryError(
            "line_through_point_direction: p is the point at infinity in direction d") from exc


# --------------------------------------------------------------------------- standard coordinates
@_shared
def to_standard(x) -> np.ndarray:
    """Standard coordinates ``T @ x`` (thesis 5.1-5.16, 5.47): ``(x, y)`` is ``[1, x, y]``.

    Parameters
    ----------
    x : array_like, shape (..., 3)
        Points or lines in the package's coordinates.

    {returns_3}

    Examples
    --------
    >>> to_standard(from_xy([1.0, 2.0]))
    array([1., 1., 2.])
    """
    x = as_vec3(x, "x")
    return np.einsum("ij,...j->...i", T_STD, x)


@_shared
def from_standard(x) -> np.ndarray:
    """The package's coordinates of standard points or lines (thesis 5.47; ``T`` is self-inverse).

    Parameters
    ----------
    x : array_like, shape (..., 3)
        Points ``[w, x, y]`` or lines in standard coordinates.

    {returns_3}

    Examples
    --------
    >>> from_standard([1.0, 1.0, 2.0])      # the point (1, 2)
    array([ 2., -1.,  1.])
    """
    return to_standard(x)                   # T is its own inverse


@_shared
def conic_to_standard(C) -> np.ndarray:
    """A conic's matrix in standard coordinates, ``T C T`` (thesis 5.35, 5.47).

    Parameters
    ----------
    C : array_like, shape (..., 3, 3)
        Symmetric conic matrix in the package's coordinates.

    {standard}

    Examples
    --------
    >>> conic_to_standard(np.diag([1.0, 1.0, -4.0])).diagonal()   # the circle x² + y² = 4
    array([-4.,  1.,  1.])
    """
    C = as_array(C, "C", (3, 3))
    return T_STD @ C @ T_STD


@_shared
def conic_from_standard(S) -> np.ndarray:
    """A conic's matrix in the package's coordinates, ``T S T`` (thesis 5.47).

    Parameters
    ----------
    S : array_like, shape (..., 3, 3)
        Symmetric conic matrix in standard coordinates.

    {standard}

    Examples
    --------
    >>> conic_from_standard(np.diag([-4.0, 1.0, 1.0])).diagonal()
    array([ 1.,  1., -4.])
    """
    S = as_array(S, "S", (3, 3))
    return T_STD @ S @ T_STD
