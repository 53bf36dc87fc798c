"""Named scenes: functions from keyword parameters (each with a default) to a :class:`SceneResult`.

Each scene module registers itself with :func:`register`; drawings, widgets and ``planargeo
report`` all build scenes by name.
"""
from __future__ import annotations

import functools
import importlib
import inspect
import math
import warnings
from dataclasses import dataclass, field
from typing import Any, Callable

import numpy as np

from planargeo.errors import (InputError, NonFiniteError, NumericOverflowError, PlanargeoError, SceneError,
                              ShapeError, SizeLimitError)

__all__ = ["SceneResult", "register", "get", "names", "parameters", "limits", "build", "check_param",
           "plain", "non_finite", "SceneNonFiniteError", "SceneShapeError", "SceneSizeError", "SceneRangeError"]


class SceneNonFiniteError(SceneError, NonFiniteError):
    """A scene parameter is NaN or infinite."""


class SceneShapeError(SceneError, ShapeError):
    """A scalar scene parameter was given as an array."""


class SceneSizeError(SceneError, SizeLimitError):
    """A size parameter past the scene's limit."""


class SceneRangeError(SceneError, NumericOverflowError):
    """Finite parameters the scene cannot evaluate in double precision (overflow, a zero that underflowed)."""

# Scene modules, imported on first use.
_MODULES = [f"planargeo.scenes.{m}" for m in (
    "chain", "car", "two_body", "horizontal_chain", "mobility_example", "slider_crank", "trees", "subspace",
    "impulse", "articulated", "splitting")]

_REGISTRY: dict[str, Callable[..., "SceneResult"]] = {}
_LIMITS: dict[str, dict[str, tuple[int, str]]] = {}
_loaded = False


@dataclass
class SceneResult:
    """What a scene function returns.

    Attributes
    ----------
    name : str
        Registered scene name, e.g. ``"slider-crank"`` (set by :func:`register`).
    params : dict
        Every parameter with the value used (set by :func:`register`).
    model : object or None
        The mechanism (``planargeo.mechanics.model.Model``), if the scene has one.
    state : dict
        The state used, plain numbers and lists (``q``, ``qd``, ``tau``...).
    quantities : dict
        Every solved output, plain, thesis ordering, at the global origin.
    extra : dict
        Anything else a drawing may want (numpy arrays allowed).
    """

    name: str = ""
    params: dict[str, Any] = field(default_factory=dict)
    model: Any = None
    state: dict[str, Any] = field(default_factory=dict)
    quantities: dict[str, Any] = field(default_factory=dict)
    extra: dict[str, Any] = field(default_factory=dict)


def register(name: str, limits: dict[str, tuple[int, str]] | None = None,
             checks: dict | None = None):
    """Decorator registering a scene function under ``name``, its parameters checked up front.

    Parameters
    ----------
    name : str
        The scene's name.
    limits : dict, optional
        ``{size parameter: (largest value, what that costs)}``, e.g. ``{"n": (200, "about 0.5 s")}``:
        :func:`build` refuses larger values unless ``allow_big=True``.
    checks : dict, optional
        ``{parameter: rule}`` for :func:`check_param`: words among ``int``, ``positive``,
        ``nonnegative``, ``nonzero``, ``optional``, a tuple of choices, or None for a drawing
        option left to the function and not in ``params``.  A parameter not named is a float.

    Returns
    -------
    callable
        The decorator; it returns the scene function calling the original with the checked
        values and setting ``name`` and ``params`` of its result.
    """

    def deco(fn):
        sig = inspect.signature(fn)
        rules = {k: (checks or {}).get(k, "") for k in sig.parameters}

        @functools.wraps(fn)
        def scene(*args, **kwargs):
            bound = sig.bind(*args, **kwargs)
            bound.apply_defaults()
            values = {k: v if rules[k] is None else _check(k, v, rules[k])
                      for k, v in bound.arguments.items()}
            res = fn(**values)
            res.name, res.params = name, {k: v for k, v in values.items() if rules[k] is not None}
            return res

        _REGISTRY[name] = scene
        _LIMITS[name] = dict(limits or {})
        return scene

    return deco


def _check(name: str, value: Any, rule: str | tuple) -> Any:
    """:func:`check_param` of one parameter by its rule (see :func:`register`)."""
    if isinstance(rule, tuple):
        return check_param(name, value, "choice", choices=rule)
    words = rule.split()
    kind = "int" if "int" in words else "float"
    return check_param(name, value, kind, **{w: True for w in words if w != "int"})


def _load() -> None:
    global _loaded
    if _loaded:
        return
    for mod in _MODULES:
        importlib.import_module(mod)
    _loaded = True


def names() -> list[str]:
    """Registered scene names, in registration order.

    Returns
    -------
    list of str

    Examples
    --------
    >>> "slider-crank" in names(), "no-such-scene" in names()
    (True, False)
    """
    _load()
    return list(_REGISTRY)


def get(name: str) -> Callable[..., SceneResult]:
    """The scene function registered as ``name``.

    Parameters
    ----------
    name : str
        A registered scene name (see :func:`names`).

    Returns
    -------
    callable

    Raises
    ------
    SceneError
        If ``name`` is not registered.

    Examples
    --------
    >>> get("two-body").__name__
    'two_body'
    """
    _load()
    try:
        return _REGISTRY[name]
    except KeyError:
        raise SceneError(f"scene must be one of {sorted(_REGISTRY)}, got {name!r}") from None


def parameters(name: str) -> dict[str, Any]:
    """The scene's parameters and their defaults.

    Parameters
    ----------
    name : str
        A registered scene name (else :class:`SceneError`, as in :func:`get`).

    Returns
    -------
    dict
        ``{parameter: default}``.

    Examples
    --------
    >>> parameters("two-body")
    {'m': 1.0, 'rho': 0.5, 'L': 1.0, 'phi': 0.7853981633974483}
    """
    sig = inspect.signature(get(name))
    return {k: p.default for k, p in sig.parameters.items()}


def limits(name: str) -> dict[str, int]:
    """The scene's size limits ``{parameter: largest value}`` (see :func:`build`).

    Parameters
    ----------
    name : str
        A registered scene name.

    Returns
    -------
    dict of str to int
        Empty for a scene without limits.

    Examples
    --------
    >>> limits("chain")
    {'n': 200}
    """
    get(name)
    return {k: v for k, (v, _) in _LIMITS[name].items()}


def build(name: str, *, allow_big: bool = False, **params) -> SceneResult:
    """Build scene ``name`` with ``params``.

    Parameters
    ----------
    name : str
        A registered scene (:func:`names`).
    allow_big : bool
        Lift the size limits (:func:`limits`), for a deliberate big job.
    **params
        The scene's parameters (:func:`parameters`).

    Returns
    -------
    SceneResult

    Raises
    ------
    SceneError
        An unknown parameter, or a value the scene refuses.
    SceneSizeError
        A size past its limit without ``allow_big`` (the message states the limit and its cost).
    SceneRangeError
        Results beyond double precision (the message names the parameters responsible).

    Examples
    --------
    >>> build("chain", n=10**6)
    Traceback (most recent call last):
    ...
    planargeo.scenes.SceneSizeError: n = 1000000 is past the limit of 200 for scene 'chain' (n = 200 takes about 0.5 s; the cost grows as n³); pass allow_big=True (planargeo report --allow-big) to build it anyway
    """
    fn = get(name)
    known = parameters(name)
    unknown = sorted(set(params) - set(known))
    if unknown:
        raise SceneError(f"scene {name!r} has no parameter {unknown[0]!r} (parameters: {', '.join(known)})")
    for k, (limit, cost) in _LIMITS[name].items():
        if k in params:
            v = check_param(k, params[k], "int", positive=True)
            if v > limit and not allow_big:
                raise SceneSizeError(f"{k} = {v} is past the limit of {limit} for scene {name!r} ({cost}); "
                                     "pass allow_big=True (planargeo report --allow-big) to build it anyway")
    problem = _evaluate(fn, params)
    if isinstance(problem, SceneResult):
        return problem
    culprits = [k for k in params if isinstance(_evaluate(fn, {j: v for j, v in params.items() if j != k}),
                                                    SceneResult)] or list(params)
    given = ", ".join(f"{k}={params[k]:g}" if isinstance(params[k], float) else f"{k}={params[k]}"
                      for k in culprits)
    raise SceneRangeError(f"scene {name!r} {problem} " + (f"with {given} " if params else "with the default "
                          "parameters ") + "(beyond what double precision can evaluate)")


def _evaluate(fn, params) -> SceneResult | str:
    """``fn(**params)`` without numpy's warnings; a string saying what went wrong if not finite."""
    try:
        with warnings.catch_warnings(), np.errstate(all="ignore"):
            warnings.simplefilter("ignore", RuntimeWarning)
            res = fn(**params)
    except PlanargeoError as exc:
        if not isinstance(exc, NumericOverflowError):
            raise
        return f"overflows ({exc})"
    except (ArithmeticError, np.linalg.LinAlgError) as exc:    # beyond double precision
        return f"fails ({type(exc).__name__}: {exc})"
    bad = non_finite(res)
    if bad:
        return ("gives non-finite results (" + ", ".join(b.split(".", 1)[1] for b in bad[:8])
                + (", ...)" if len(bad) > 8 else ")"))
    return res


def plain(x) -> list | float | None:
    """``x`` as nested lists of plain floats without ``-0.0`` (None stays None): how scenes keep arrays.

    Parameters
    ----------
    x : array_like or None
        Numbers.

    Returns
    -------
    list, float or None

    Examples
    --------
    >>> plain([[-0.0, 1], [2.5, 3]]), plain(None)
    ([[0.0, 1.0], [2.5, 3.0]], None)
    """
    return None if x is None else (np.asarray(x, dtype=float) + 0.0).tolist()


def _at_rest(q) -> dict:
    """The state record of a mechanism at rest at ``q``: ``q`` :func:`plain`, ``qd`` and ``tau`` zero."""
    return {"q": plain(q), "qd": [0.0] * len(q), "tau": [0.0] * len(q)}


def non_finite(result: SceneResult) -> list[str]:
    """Names (``section.key``) of the parameters, state and quantities of ``result`` holding NaN or infinity.

    Parameters
    ----------
    result : SceneResult
        A built scene.

    Returns
    -------
    list of str
        Empty when all is finite.

    Examples
    --------
    >>> non_finite(SceneResult("x", {"a": 1.0}, state={"q": [0.0, float("inf")]},
    ...                        quantities={"M": [[1.0, float("nan")]], "h": 2.0}))
    ['state.q', 'quantities.M']
    """
    def bad(v) -> bool:
        if isinstance(v, dict):
            return any(bad(w) for w in v.values())
        if isinstance(v, (list, tuple, np.ndarray)):
            return any(bad(w) for w in v)
        return isinstance(v, (float, np.floating)) and not math.isfinite(v)

    return [f"{section}.{k}" for section in ("params", "state", "quantities")
            for k, v in (getattr(result, section) or {}).items() if bad(v)]


def check_param(name: str, value: Any, kind: str = "float", *, positive: bool = False,
                nonnegative: bool = False, nonzero: bool = False, choices=None, optional: bool = False):
    """Validate one scene parameter up front, naming it in the message.

    Parameters
    ----------
    name : str
        The parameter's name.
    value : object
        The value given.
    kind : {"float", "int", "choice"}
        A finite real number (not a bool, str or array), returned as float; an integer (a float
        with an integral value is accepted), returned as int; or one of ``choices``, unchanged.
    positive, nonnegative, nonzero : bool
        Further conditions on a number.
    choices : sequence of str
        The allowed values of a ``"choice"`` parameter.
    optional : bool
        ``None`` is allowed (and returned unchanged).

    Returns
    -------
    float, int, str or None

    Raises
    ------
    SceneError
        Wrong type, out of range or not one of ``choices``; :class:`SceneNonFiniteError` for NaN or
        inf and :class:`SceneShapeError` for an array.
    InputError
        ``kind`` is not one of the three (a mistake in the scene module).

    Examples
    --------
    >>> check_param("m", 2, positive=True), check_param("n", 3.0, "int", positive=True)
    (2.0, 3)
    """
    if optional and value is None:
        return None
    if kind == "choice":
        if value not in tuple(choices):
            opts = " or ".join(repr(c) for c in choices) if len(choices) == 2 else f"one of {list(choices)}"
            raise SceneError(f"{name} must be {opts}, got {value!r}")
        return value
    if kind == "int":
        word = "positive " if positive else "non-negative " if nonnegative else "non-zero " if nonzero else ""
        msg = f"{name} must be a {word}integer, got {value!r}"
        integral = isinstance(value, (int, np.integer)) or (
            isinstance(value, (float, np.floating)) and float(value).is_integer())
        if isinstance(value, (bool, np.bool_)) or not integral:
            raise SceneError(msg)
        v = int(value)
        if (positive and v <= 0) or (nonnegative and v < 0) or (nonzero and v == 0):
            raise SceneError(msg)
        return v
    if kind != "float":
        raise InputError(f"kind must be 'float', 'int' or 'choice', got {kind!r}")
    if isinstance(value, (bool, np.bool_, str, bytes)) or value is None:
        raise SceneError(f"{name} must be numeric, got {value!r}")
    if isinstance(value, (complex, np.complexfloating)) or getattr(value, "dtype", None) == complex:
        raise SceneError(f"{name} must be real, got {value!r}")
    try:
        a = np.asarray(value, dtype=float)
    except OverflowError:
        raise SceneNonFiniteError(f"{name} must be finite, got an integer beyond double precision's range") from None
    except (TypeError, ValueError):
        raise SceneError(f"{name} must be numeric, got {value!r}") from None
    if a.ndim != 0:
        raise SceneShapeError(f"{name} must be a scalar, got shape {a.shape}")
    v = float(a)
    if not np.isfinite(v):
        raise SceneNonFiniteError(f"{name} must be finite, got {v!r}")
    for bad, word in ((positive and not v > 0, "positive"), (nonnegative and not v >= 0, "non-negative"),
                      (nonzero and v == 0, "non-zero")):
        if bad:
            raise SceneError(f"{name} must be {word}, got {v!r}")
    return v
