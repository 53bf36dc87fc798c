"""How the dynamics functions reach the compiled kernels (:mod:`planargeo.algorithms.kernels`).

numba is imported for the first model the kernels cover (:func:`kernels_for`).  :func:`evaluate`
hands one float64 state straight to the kernel (compiled for that one type), validates anything
else, and turns a state the kernel does not finish into the general recursion's named error.
``make lab`` fills numba's per-machine cache with ``python -m planargeo.algorithms.compiled --warm``.
"""
from __future__ import annotations

import math
import sys
import time
from collections import namedtuple
from functools import partial

import numpy as np

from planargeo.errors import NumericOverflowError
from planargeo.mechanics.kinematics import check_state
from planargeo.mechanics.subspaces import singular_joint_error

__all__ = ["Compiled", "kernels_for", "evaluate", "check_finite", "warm", "cache_is_warm", "main"]

_ARRAY = np.ndarray


#: What :func:`kernels_for` returns: the kernels module, tables, the shapes ``(nq,)``, ``(N, 3)``
Compiled = namedtuple("Compiled", "kernels tables state wrenches")


def kernels_for(model):
    """The :data:`Compiled` kernels of ``model`` if they cover it (joints revolute, prismatic or fixed), else None.

    Parameters
    ----------
    model : Model
        The mechanism (the answer is cached on it).

    Returns
    -------
    Compiled or None
        The kernels with the model's :func:`~planargeo.algorithms.kernels.tables`, or None.

    Examples
    --------
    >>> from planargeo.mechanics.model import chain_model
    >>> kernels_for(chain_model(2)).tables[0]            # joint codes: revolute
    array([1, 1])
    """
    cache = model._arrays
    if "kernels" not in cache:
        from planargeo.algorithms import kernels     # numba: imported on first use

        tables = kernels.tables(model)
        if tables is not None:
            _say_if_cold(kernels)
            if hasattr(kernels.dynamics_one, "_can_compile"):   # (not under NUMBA_DISABLE_JIT=1)
                # numba's disable_compile() before any signature: another type raises TypeError at once
                kernels.dynamics_one._can_compile = False
        cache["kernels"] = None if tables is None else Compiled(kernels, tables, (model.nq,), (model.N, 3))
    return cache["kernels"]


def evaluate(model, inverse: bool, q, qd, z, f_ext, general):
    """Forward (``z = τ``) or inverse (``inverse=True``, ``z = q̈``) dynamics: the kernels, else ``general``.

    A batch raises for its first state a kernel does not finish, as that state would alone.

    Parameters
    ----------
    model, q, qd, z, f_ext : Model, array_like
        The mechanism and its states (``(..., nq)``; ``f_ext`` ``(..., N, 3)`` or None).
    inverse : bool
        Inverse dynamics instead of forward.
    general : callable
        ``general(model, q, qd, z, f_ext)``, the general recursion for models the kernels do not cover.

    Returns
    -------
    ndarray (..., nq)
        ``q̈`` or ``τ``.
    """
    c = model._arrays.get("kernels", False)
    if c is False:
        c = kernels_for(model)
    if c is None:
        return general(model, q, qd, z, f_ext)
    kernels, tables = c.kernels, c.tables
    if (kernels.TYPED and type(q) is _ARRAY and q.ndim == 1 and type(qd) is _ARRAY and type(z) is _ARRAY
            and (f_ext is None or type(f_ext) is _ARRAY)):
        try:                # numba checks the types (float64, C-contiguous, writeable), the kernel the shapes
            out = kernels.dynamics_one(inverse, *tables, q, qd, z, f_ext)
        except TypeError:   # another type (ints, a read-only view, f_ext a list...), or the first call: validated
            out = None
        if out is not None:
            return out
    tau, qdd = (None, z) if inverse else (z, None)      # the kernels test for NaN and infinity themselves
    q, qd, tau, f_ext, qdd, shape = check_state(model, q, qd, tau, f_ext, qdd=qdd, finite=False)
    z = qdd if inverse else tau
    nq, N = model.nq, model.N
    B = math.prod(shape)
    rows = [_rows(a, shape + (nq,), (B, nq)) for a in (q, qd, z)]
    fe = None if f_ext is None else _rows(f_ext, shape + (N, 3), (B, N, 3))
    if shape == ():
        _ready(kernels, fe is not None)
        out = kernels.dynamics_one(inverse, *tables, *(r[0] for r in rows), None if fe is None else fe[0])
        return out if out is not None else _failed(kernels, tables, model, inverse, q, qd, z, f_ext, general)
    out, declined = kernels.dynamics_many(inverse, *tables, *rows, fe)
    if declined < 0:
        return out.reshape(shape + (nq,))
    _failed(kernels, tables, model, inverse, *(r[declined] for r in rows), None if fe is None else fe[declined],
            general)
    return general(model, q, qd, z, f_ext)       # the general recursion answered that state: the batch by it


_READY: set = set()


def _ready(kernels, wrenches: bool) -> None:
    """Compile (or load from the cache) the one type of the one-state kernel, with or without external wrenches."""
    if wrenches in _READY:
        return
    kernel = kernels.dynamics_one
    if hasattr(kernel, "_can_compile"):
        from numba import types

        i1, f1, f2 = (types.Array(types.int64, 1, "C"), types.Array(types.float64, 1, "C"),
                      types.Array(types.float64, 2, "C"))
        kernel._can_compile = True
        try:
            kernel.compile((types.boolean, i1, i1, f2, f1, f1, f1, f1, f2 if wrenches else types.none))
        finally:
            kernel._can_compile = False
    _READY.add(wrenches)


def _rows(a, full, flat):
    """``a`` broadcast to ``full``, as a writeable C-contiguous float64 array of shape ``flat`` (numba's one type)."""
    a = np.ascontiguousarray((a if a.shape == full else np.broadcast_to(a, full)).reshape(flat), dtype=np.float64)
    return a if a.flags.writeable else a.copy()


def _failed(kernels, tables, model, inverse, q, qd, z, f_ext, general):
    """Raise the error of a state the kernel did not finish (validated arrays (nq,), ``f_ext`` (N, 3) or None)."""
    if not inverse:
        joint, cond = kernels.singular_joint(*tables, *(_rows(a, (model.nq,), (model.nq,)) for a in (q, qd, z)),
                                             None if f_ext is None else _rows(f_ext, (model.N, 3), (model.N, 3)))
        if joint >= 0:
            raise singular_joint_error(joint, cond)
    return general(model, q, qd, z, f_ext)    # raises the named error (not finite, overflow)


def check_finite(result, what: str, **inputs):
    """Return ``result``, or raise :class:`~planargeo.errors.NumericOverflowError` naming the largest input.

    Parameters
    ----------
    result : numpy.ndarray
        The computed result, named ``what`` in the message.
    what : str
        Its name.
    **inputs : numpy.ndarray
        The (finite) arguments it came from, by name.

    Returns
    -------
    numpy.ndarray

    Raises
    ------
    NumericOverflowError
        If ``result`` holds NaN or infinity although the inputs are finite.

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


#: The kernels the package calls from Python (the others are compiled into them).
ENTRY_POINTS = ("dynamics_one", "singular_joint", "_range")
_told = []


def cache_is_warm(kernels=None) -> bool:
    """Whether numba's cache holds the kernels' entry points for the current source (compiles nothing).

    Parameters
    ----------
    kernels : module, optional
        The kernels' module (default :mod:`planargeo.algorithms.kernels`).

    Returns
    -------
    bool

    Examples
    --------
    >>> isinstance(cache_is_warm(), bool)
    True
    """
    if kernels is None:
        from planargeo.algorithms import kernels
    try:
        # numba's index of each entry point: empty when there is none or it is for another source
        return all(getattr(kernels, name)._cache._cache_file._load_index() for name in ENTRY_POINTS)
    except Exception:                                      # (unreadable or foreign files: not warm)
        return False


def _say_if_cold(kernels) -> None:
    """Tell a person at a terminal or in a notebook, once, that the first call compiles (numba's cache is cold)."""
    if _told:
        return
    _told.append(True)
    interactive = "ipykernel" in sys.modules or getattr(sys.stderr, "isatty", lambda: False)()
    if interactive and not cache_is_warm(kernels):
        print("planargeo: compiling the dynamics kernels for this machine (once; about 10-30 s). "
              "`python -m planargeo.algorithms.compiled --warm` (part of `make lab`) does it ahead of time.",
              file=sys.stderr, flush=True)


def warm(progress=None) -> list[tuple[str, float]]:
    """Compile (or load from numba's cache) every kernel signature :func:`evaluate` calls.

    Parameters
    ----------
    progress : callable, optional
        Called with one line of text before and after each step (e.g. ``print``).

    Returns
    -------
    list of (str, float)
        Each step and the seconds it took.

    Examples
    --------
    >>> warm()[0][0]
    'forward and inverse dynamics, one state'
    """
    from planargeo.mechanics.model import Body, Joint, Model

    model = Model([Body(1.0, (0.5, 0.0), 0.1), Body(1.0, (0.5, 0.0), 0.1), Body(0.5, (0.2, 0.0), 0.05)],
                  [Joint("revolute"), Joint("prismatic", (1.0, 0.0, 0.0)), Joint("fixed", (1.0, 0.0, 0.0))],
                  [-1, 0, 1])
    k, tables = kernels_for(model)[:2]
    steps = []
    nq, N, B = model.nq, model.N, 3
    one, fe1 = np.zeros(nq), np.zeros((N, 3))
    rows, feB = np.zeros((B, nq)), np.zeros((B, N, 3))
    runs = [("forward and inverse dynamics, one state", lambda: _ready(k, False)),
            ("forward and inverse dynamics, one state, external wrenches", lambda: _ready(k, True)),
            ("singular-joint check", lambda: k.singular_joint(*tables, one, one, one, None)),
            ("singular-joint check, external wrenches", lambda: k.singular_joint(*tables, one, one, one, fe1))]
    for inverse, kind in ((False, "forward"), (True, "inverse")):
        for extra, fe in (("", None), (", external wrenches", feB)):
            runs.append((f"{kind} dynamics, batch{extra}", partial(k.dynamics_many, inverse, *tables, rows, rows, rows, fe)))
    progress = progress or (lambda line: None)
    for what, run in runs:
        progress(f"  {what} ...")
        t = time.perf_counter()
        run()
        steps.append((what, time.perf_counter() - t))
        progress(f"  {what}: {steps[-1][1]:.2f} s")
    return steps


def main(argv=None) -> int:
    """``python -m planargeo.algorithms.compiled --warm``: fill numba's cache with every kernel (:func:`warm`).

    Parameters
    ----------
    argv : list of str, optional
        The arguments (default ``sys.argv[1:]``).

    Returns
    -------
    int
        The exit status: 0, or 2 for arguments other than ``--warm``.
    """
    if (sys.argv[1:] if argv is None else list(argv)) != ["--warm"]:
        print("usage: python -m planargeo.algorithms.compiled --warm\n"
              "Compile (or load) every dynamics kernel into numba's cache ahead of time.",
              file=sys.stderr)
        return 2
    print("planargeo: compiling the dynamics kernels into numba's cache (once per install) ...", flush=True)
    t = time.perf_counter()
    warm(progress=lambda line: print(line, flush=True) if line.endswith(" s") else None)
    print(f"planargeo: kernels ready in {time.perf_counter() - t:.1f} s", flush=True)
    return 0


if __name__ == "__main__":
    sys.exit(main())
