"""How the dynamics functions reach the compiled kernels (:mod:`planargeo.algorithms.kernels`).

``import planargeo`` imports neither numba nor the kernels: :func:`kernels_for` imports
them on the first call for a model the kernels cover (joints all revolute, prismatic or
fixed), and numba compiles each kernel on its first use (then loads it from its cache).

A call (:func:`evaluate`) takes one of three roads, all giving the same numbers:

* one state given as float64 arrays of the right shapes goes straight to the kernel,
  which checks that it is finite (:func:`is_plain_state`);
* anything else (lists, other dtypes, batches, broadcasting) is validated by
  :func:`planargeo.mechanics.kinematics.check_state` and handed over as C-contiguous
  float64 rows;
* where a kernel declines (non-finite input or result, a singular joint), the general
  array recursion runs instead, and raises the package's named error (or answers,
  where the kernel's quick test was only cautious).

:func:`check_finite` is the last step of every general path: finite input that gives a
non-finite result raises :class:`~planargeo.errors.NumericOverflowError`.
"""
from __future__ import annotations

import math

import numpy as np

from planargeo.errors import NumericOverflowError
from planargeo.mechanics.kinematics import check_state

__all__ = ["kernels_for", "is_plain_state", "evaluate", "check_finite"]

_F64 = np.dtype(np.float64)


def kernels_for(model):
    """``(kernels module, model tables)`` if the compiled kernels cover ``model``, else None (cached on the model).

    Examples
    --------
    >>> from planargeo.mechanics.model import Body, Joint, Model, chain_model
    >>> kernels_for(chain_model(2))[1][0]             # joint codes: revolute
    array([1, 1])
    >>> kernels_for(Model([Body(1.0)], [Joint("plane")], [-1])) is None
    True
    """
    cache = model._arrays
    if "kernels" not in cache:
        from planargeo.algorithms import kernels     # numba: imported on first use

        tables = kernels.tables(model)
        cache["kernels"] = None if tables is None else (kernels, tables)
    return cache["kernels"]


def is_plain_state(model, x, y, z, f_ext) -> bool:
    """Whether ``x, y, z`` are float64 arrays (nq,) and ``f_ext`` None or one (N, 3).

    Such a state needs no conversion: the kernel itself checks that it is finite (a
    non-contiguous or read-only array is passed as it is: numba compiles for its layout).
    """
    return (type(x) is type(y) is type(z) is np.ndarray and x.dtype is y.dtype is z.dtype is _F64
            and x.shape == y.shape == z.shape == (model.nq,)
            and (f_ext is None or (type(f_ext) is np.ndarray and f_ext.dtype is _F64 and f_ext.shape == (model.N, 3))))


def evaluate(model, inverse: bool, q, qd, z, f_ext, general):
    """Forward (``z = τ``) or inverse (``inverse=True``, ``z = q̈``) dynamics: the kernels, else ``general``.

    ``general(model, q, qd, z, f_ext)`` is the caller's general recursion, run for a model
    the kernels do not cover, or where they decline a state: on a declined state of a
    batch alone first, so that the batch raises that state's error, as it would alone.
    Arguments that :func:`is_plain_state` does not accept are validated by
    :func:`~planargeo.mechanics.kinematics.check_state` and handed over as C-contiguous
    float64 rows.

    Returns
    -------
    ndarray (..., nq)
        ``q̈`` or ``τ``.
    """
    compiled = kernels_for(model)
    if compiled is None:
        return general(model, q, qd, z, f_ext)
    kernels, tables = compiled
    one = kernels.inverse_dynamics_one if inverse else kernels.forward_dynamics_one
    if is_plain_state(model, q, qd, z, f_ext):
        out = one(*tables, q, qd, z, f_ext)
        return out if out is not None else general(model, q, qd, z, f_ext)
    if inverse:
        q, qd, _, f_ext, z, shape = check_state(model, q, qd, None, f_ext, qdd=z)
    else:
        q, qd, z, f_ext, _, shape = check_state(model, q, qd, z, f_ext)
    nq, N = model.nq, model.N
    if shape == ():
        out = one(*tables, *(np.ascontiguousarray(a) for a in (q, qd, z)),
                  None if f_ext is None else np.ascontiguousarray(f_ext))
        return out if out is not None else general(model, q, qd, z, f_ext)
    B = math.prod(shape)
    rows = [np.ascontiguousarray(np.broadcast_to(a, shape + (nq,)).reshape(B, nq)) for a in (q, qd, z)]
    fe = None if f_ext is None else np.ascontiguousarray(np.broadcast_to(f_ext, shape + (N, 3)).reshape(B, N, 3))
    out, declined = (kernels.inverse_dynamics_many if inverse else kernels.forward_dynamics_many)(*tables, *rows, fe)
    if declined < 0:
        return out.reshape(shape + (nq,))
    general(model, *(r[declined] for r in rows), None if fe is None else fe[declined])   # raises, as it would alone
    return general(model, q, qd, z, f_ext)       # or the kernel was only cautious: the batch by the general path


def check_finite(result, what: str, **inputs):
    """Return ``result``, or raise :class:`~planargeo.errors.NumericOverflowError` if it is not finite.

    ``inputs`` are the (finite, validated) arguments it came from; the message names the
    largest of them.

    Examples
    --------
    >>> check_finite(np.array([np.inf]), "q̈", q=np.zeros(1), qd=np.full(1, 1e160))
    Traceback (most recent call last):
    ...
    planargeo.errors.NumericOverflowError: q̈ overflows for these finite inputs: qd reaches 1e+160 (q 0); the result does not fit in a float
    """
    if np.isfinite(result).all():
        return result
    size = {name: float(np.max(np.abs(a), initial=0.0)) for name, a in inputs.items() if a is not None}
    big = max(size, key=size.get)
    rest = ", ".join(f"{n} {v:.3g}" for n, v in size.items() if n != big)
    raise NumericOverflowError(f"{what} overflows for these finite inputs: {big} reaches {size[big]:.3g}"
                               + (f" ({rest})" if rest else "") + "; the result does not fit in a float")
