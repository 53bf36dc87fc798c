"""Argument validation shared by the whole package (private): bad shapes and values named uniformly."""
from __future__ import annotations

import functools

import numpy as np

from planargeo.errors import (InputError, NonFiniteError, NumericOverflowError, PlanargeoError, ShapeError,
                              SingularInertiaError)

__all__ = ["as_array", "as_vec3", "as_mat3", "as_xy", "as_scalar", "check_symmetric",
           "check_positive_definite", "check_positive_semidefinite", "check_positive", "PSD_RTOL",
           "batch_shape", "check_overflow", "overflow_checked", "check_tolerance", "rescaled"]

#: Relative tolerance of :func:`check_positive_semidefinite`: an eigenvalue below
#: ``-PSD_RTOL * max|eigenvalue|`` is a genuinely negative direction, not rounding.
PSD_RTOL = 1e-10


def as_array(x, name: str, tail: tuple[int, ...] = (), *, finite: bool = True) -> np.ndarray:
    """Return ``x`` as a float array whose trailing dimensions are ``tail`` (leading batch dimensions free).

    :class:`InputError` for complex values or anything not numbers, :class:`ShapeError` for a
    wrong trailing shape, :class:`NonFiniteError` for NaN or inf (unless ``finite=False``).

    Examples
    --------
    >>> as_array([1, 2], "x")
    array([1., 2.])
    >>> as_array("1.5", "x")
    Traceback (most recent call last):
    ...
    planargeo.errors.InputError: x must be numeric, got '1.5'
    """
    try:
        a = np.asarray(x)
        kind = a.dtype.kind
        if kind in "USV" or (kind == "O" and any(v is None for v in a.flat)):
            raise TypeError            # numpy would read "1.5" as 1.5 and None as NaN
        if kind != "c":
            a = a.astype(float, copy=False)
    except (TypeError, ValueError) as exc:
        raise InputError(f"{name} must be numeric, got {x!r}") from exc
    if kind == "c":
        raise InputError(f"{name} must be real, got complex values")
    nt = len(tail)
    if a.ndim < nt or (nt and a.shape[-nt:] != tuple(tail)):
        want = "(..., " + ", ".join(map(str, tail)) + ")" if nt else "a scalar array"
        raise ShapeError(f"{name} must have shape {want}, got shape {a.shape}")
    if finite and not np.all(np.isfinite(a)):
        raise NonFiniteError(f"{name} must be finite, got non-finite values in {np.asarray(x)!r}")
    return a


def as_vec3(x, name: str) -> np.ndarray:
    """Shorthand for ``as_array(x, name, (3,))``: homogeneous vectors, twists, wrenches."""
    return as_array(x, name, (3,))


def as_mat3(x, name: str) -> np.ndarray:
    """Shorthand for ``as_array(x, name, (3, 3))``: conics, inertias, transforms."""
    return as_array(x, name, (3, 3))


def as_xy(x, name: str) -> np.ndarray:
    """Shorthand for ``as_array(x, name, (2,))``: Euclidean points and directions."""
    return as_array(x, name, (2,))


def as_scalar(x, name: str, *, finite: bool = True) -> float:
    """Return ``x`` as a Python float (finite unless ``finite=False``)."""
    a = as_array(x, name, finite=finite)
    if a.ndim != 0:
        raise ShapeError(f"{name} must be a scalar, got shape {a.shape}")
    return float(a)


def check_tolerance(x, name: str = "rtol") -> float:
    """A tolerance: a finite non-negative float (a negative one would accept nothing, or everything).

    Examples
    --------
    >>> check_tolerance(-1.0)
    Traceback (most recent call last):
    ...
    planargeo.errors.InputError: rtol must be a non-negative number, got -1.0
    """
    v = as_scalar(x, name)
    if v < 0:
        raise InputError(f"{name} must be a non-negative number, got {v!r}")
    return v


def check_positive(x, name: str, *, strict: bool = True) -> np.ndarray:
    """Raise :class:`InputError` unless every value of ``x`` is positive (or >= 0)."""
    a = as_array(x, name)
    bad = a <= 0 if strict else a < 0
    if np.any(bad):
        word = "positive" if strict else "non-negative"
        raise InputError(f"{name} must be {word}, got {float(a[bad].ravel()[0])!r}")
    return a


def check_symmetric(m: np.ndarray, name: str, rtol: float = 1e-10) -> np.ndarray:
    """Raise :class:`InputError` unless the (..., 3, 3) matrices ``m`` are symmetric.

    Scale-relative, matrix by matrix (``max|m - mᵀ| <= rtol * max|m|``): a tiny matrix is judged
    like a large one.  The message gives the largest asymmetry.
    """
    asym = np.abs(m - np.swapaxes(m, -1, -2)).max(axis=(-2, -1), initial=0.0)
    scale = np.abs(m).max(axis=(-2, -1), initial=0.0)
    bad = asym > rtol * scale
    if np.any(bad):
        raise InputError(f"{name} must be symmetric, got asymmetry {float(np.max(asym[bad])):.3g}")
    return m


def check_positive_semidefinite(m: np.ndarray, name: str, rtol: float = PSD_RTOL, *,
                                eig: bool = False):
    """Raise unless ``m`` is symmetric positive *semi*-definite (an inertia, possibly singular).

    Point masses and articulated inertias across a joint are singular but legitimate: zero
    eigenvalues pass, one below ``-rtol * max|eigenvalue|`` raises :class:`SingularInertiaError`
    (``.cond`` inf); asymmetry raises :class:`InputError`.  Returns ``m``, with ``eig=True`` also
    its ascending eigenvalues (so a caller need not solve again).
    """
    check_symmetric(m, name)
    w = np.linalg.eigvalsh(m)
    lo = w[..., 0]
    top = np.maximum(np.abs(w[..., 0]), np.abs(w[..., -1]))
    bad = lo < -rtol * top
    if np.any(bad):
        raise SingularInertiaError(
            f"{name} must be positive semi-definite, got smallest eigenvalue {float(np.min(lo[bad])):.3g}",
            float("inf"))
    return (m, w) if eig else m


def check_positive_definite(m: np.ndarray, name: str, rtol: float = 1e-12) -> np.ndarray:
    """Raise :class:`SingularInertiaError` (with the condition number) unless ``m`` is symmetric positive definite."""
    check_symmetric(m, name)
    w = np.linalg.eigvalsh(m)
    lo, hi = w[..., 0], w[..., -1]
    with np.errstate(divide="ignore", invalid="ignore", over="ignore"):
        cond = np.where(lo > 0, hi / np.where(lo > 0, lo, 1.0), np.inf)
    bad = lo <= rtol * np.maximum(np.abs(hi), np.finfo(float).tiny)
    if np.any(bad):
        c = float(np.max(np.where(bad, cond, 0.0)))
        raise SingularInertiaError(
            f"{name} must be positive definite, got smallest eigenvalue {float(np.min(lo)):.3g}", c)
    return m


def batch_shape(**arrays) -> tuple[int, ...]:
    """The common batch shape of named arrays ``name=(array, core_ndim)``, or a :class:`ShapeError`.

    Examples
    --------
    >>> batch_shape(p=(np.zeros((2, 3)), 1), q=(np.zeros((4, 3)), 1))
    Traceback (most recent call last):
    ...
    planargeo.errors.ShapeError: the batch shapes do not broadcast: p (2,), q (4,)
    """
    shapes = {k: np.shape(a)[:np.ndim(a) - nd] for k, (a, nd) in arrays.items()}
    first = next(iter(shapes.values()))
    if all(s == first for s in shapes.values()):     # the common case: nothing to broadcast
        return first
    try:
        return np.broadcast_shapes(*shapes.values())
    except ValueError:
        given = ", ".join(f"{k} {v}" for k, v in shapes.items())
        raise ShapeError(f"the batch shapes do not broadcast: {given}") from None


def check_overflow(out, what: str, culprits: str, ok=None):
    """Return ``out`` (an array or a tuple of arrays) if finite, else raise :class:`NumericOverflowError`.

    For arguments checked finite a NaN or inf in the result can only be overflow; ``ok`` marks
    entries non-finite by design (the coordinates of a point at infinity).

    Examples
    --------
    >>> check_overflow(np.array(np.inf), "incidence(p, l)", "p or l")
    Traceback (most recent call last):
    ...
    planargeo.errors.NumericOverflowError: incidence(p, l): the result overflows double precision (p or l too large)
    """
    for o in (out if isinstance(out, tuple) else (out,)):
        bad = ~np.isfinite(o)
        if not bad.any():
            continue
        if ok is not None:
            bad &= ~np.asarray(ok, bool)
        if np.any(bad):
            raise NumericOverflowError(f"{what}: the result overflows double precision ({culprits} too large)")
    return out


def overflow_checked(culprits: str):
    """Decorator: run the function with numpy's overflow warnings off, then :func:`check_overflow` its result.

    A LAPACK failure on entries near the float range is reported the same way.  Only for functions
    whose results are finite for finite arguments (validated with :func:`as_array`).
    """
    def deco(fn):
        @functools.wraps(fn)
        def wrapper(*args, **kwargs):
            try:
                with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
                    out = fn(*args, **kwargs)
            except np.linalg.LinAlgError as e:     # LAPACK on finite entries near the float range
                if isinstance(e, PlanargeoError):
                    raise
                raise NumericOverflowError(f"{fn.__name__}: {culprits} too large to decompose ({e})") from None
            return check_overflow(out, f"{fn.__name__}", culprits)
        return wrapper
    return deco


def rescaled(fn, args, degrees, core, out_core: int, what: str, culprits: str):
    """``fn(*args)`` for ``fn`` homogeneous of degree ``degrees[i]`` in ``args[i]``, finite when it can be.

    The plain evaluation when finite (bit for bit).  Otherwise each argument (each ``core[i]``-dim
    element) is scaled by a power of two to a largest entry near 1 and the result scaled back
    exactly by ``2^(Σ degrees[i] e[i])``: a true result beyond double precision raises
    :class:`NumericOverflowError` naming ``culprits``.

    Examples
    --------
    >>> float(rescaled(lambda a: np.sqrt(a @ a), (np.array([1e200, 1e200]),), (1,), (1,), 0,
    ...                "|a|", "a"))       # a @ a overflows, |a| does not
    1.4142135623730951e+200
    """
    with np.errstate(all="ignore"):
        out = fn(*args)
    if np.isfinite(out).all() if not isinstance(out, tuple) else all(np.isfinite(o).all() for o in out):
        return out
    scaled, total = [], 0
    for a, c, d in zip(args, core, degrees):
        e = np.frexp(np.abs(a).max(axis=tuple(range(-c, 0)), keepdims=True) if c else np.abs(a))[1]
        scaled.append(np.ldexp(a, -e))
        total = total + d * (e.reshape(e.shape[:e.ndim - c]) if c else e)
    with np.errstate(all="ignore"):
        out = fn(*scaled)
        total = np.asarray(total).reshape(np.shape(total) + (1,) * out_core)
        out = tuple(np.ldexp(o, total) for o in out) if isinstance(out, tuple) else np.ldexp(out, total)
    return check_overflow(out, what, culprits)
