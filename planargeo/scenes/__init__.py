"""Named scenes: functions from named parameters (with defaults) to a model and state.

Each scene module registers itself with :func:`register`.  A scene function
takes keyword parameters only (each with a default) and returns a
:class:`SceneResult`; drawings, widgets and ``planargeo report`` all use them.

>>> from planargeo import scenes
>>> sorted(scenes.names())  # doctest: +SKIP
['car', 'chain', ...]
"""
from __future__ import annotations

import importlib
import importlib.util
import inspect
from dataclasses import dataclass, field
from typing import Any, Callable

import numpy as np

from planargeo.errors import InputError, NonFiniteError, SceneError, ShapeError

__all__ = ["SceneResult", "register", "get", "names", "parameters", "build", "check_param",
           "SceneNonFiniteError", "SceneShapeError"]


class SceneNonFiniteError(SceneError, NonFiniteError):
    """A scene parameter is NaN or infinite (both a :class:`SceneError` and a :class:`NonFiniteError`)."""


class SceneShapeError(SceneError, ShapeError):
    """A scalar scene parameter was given as an array (both a :class:`SceneError` and a :class:`ShapeError`)."""

# Scene modules, imported on first use (a module that does not exist yet is skipped).
_MODULES = [
    "planargeo.scenes.chain",
    "planargeo.scenes.car",
    "planargeo.scenes.two_body",
    "planargeo.scenes.horizontal_chain",
    "planargeo.scenes.mobility_example",
    "planargeo.scenes.slider_crank",
    "planargeo.scenes.trees",
]

_REGISTRY: dict[str, Callable[..., "SceneResult"]] = {}
_loaded = False


@dataclass
class SceneResult:
    """What a scene function returns.

    Attributes
    ----------
    name : str
        Registered scene name, e.g. ``"slider-crank"``.
    params : dict
        Every parameter with the value used (defaults filled in).
    model : object or None
        The frozen mechanism description (``planargeo.mechanics.model.Model``), if the scene has one.
    state : dict
        The state used: plain numbers / lists (e.g. ``q``, ``qd``, ``tau``).
    quantities : dict
        Every solved output, as plain numbers / nested lists, thesis ordering,
        expressed at the global origin.
    extra : dict
        Anything else a drawing may want (numpy arrays allowed).
    """

    name: str
    params: dict[str, Any]
    model: Any = None
    state: dict[str, Any] = field(default_factory=dict)
    quantities: dict[str, Any] = field(default_factory=dict)
    extra: dict[str, Any] = field(default_factory=dict)


def register(name: str):
    """Decorator registering a scene function under ``name``."""

    def deco(fn):
        _REGISTRY[name] = fn
        fn.scene_name = name
        return fn

    return deco


def _load() -> None:
    global _loaded
    if _loaded:
        return
    for mod in _MODULES:
        if importlib.util.find_spec(mod) is not None:
            importlib.import_module(mod)
    _loaded = True


def names() -> list[str]:
    """Registered scene names."""
    _load()
    return list(_REGISTRY)


def get(name: str) -> Callable[..., SceneResult]:
    """The scene function registered as ``name``; :class:`SceneError` if unknown."""
    _load()
    try:
        return _REGISTRY[name]
    except KeyError:
        raise SceneError(f"scene must be one of {sorted(_REGISTRY)}, got {name!r}") from None


def parameters(name: str) -> dict[str, Any]:
    """The scene's parameters and their defaults."""
    sig = inspect.signature(get(name))
    return {k: p.default for k, p in sig.parameters.items()}


def build(name: str, **params) -> SceneResult:
    """Build scene ``name`` with ``params``; unknown parameters raise :class:`SceneError`."""
    fn = get(name)
    known = parameters(name)
    unknown = sorted(set(params) - set(known))
    if unknown:
        raise SceneError(f"scene {name!r} has no parameter {unknown[0]!r} (parameters: {', '.join(known)})")
    return fn(**params)


def check_param(name: str, value: Any, kind: str = "float", *, positive: bool = False,
                nonnegative: bool = False, nonzero: bool = False, choices=None, optional: bool = False):
    """Validate one scene parameter up front, naming it in the message.

    Parameters
    ----------
    name : str
        The parameter's name (used in the message).
    value : object
        The value given.
    kind : {"float", "int", "choice"}
        ``"float"``: a finite real number (not a bool, not a string, not an
        array), returned as ``float``.  ``"int"``: an integer (not a bool; a
        float with an integral value is accepted), returned as ``int``.
        ``"choice"``: one of ``choices``, returned unchanged.
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
        Wrong type, out of range or not one of ``choices``;
        :class:`SceneNonFiniteError` for NaN / inf and :class:`SceneShapeError`
        for an array (subclasses of ``SceneError``).
    InputError
        ``kind`` is not one of ``"float"``, ``"int"``, ``"choice"`` (a mistake
        in the scene module, not in the user's parameters).

    Examples
    --------
    >>> check_param("m", 2, positive=True), check_param("n", 3.0, "int", positive=True)
    (2.0, 3)
    >>> check_param("psidot", float("nan"))
    Traceback (most recent call last):
    ...
    planargeo.scenes.SceneNonFiniteError: psidot must be finite, got nan
    >>> check_param("seed", -1, "int", nonnegative=True, optional=True)
    Traceback (most recent call last):
    ...
    planargeo.errors.SceneError: seed must be a non-negative integer, got -1
    >>> check_param("n", True, "int", positive=True)
    Traceback (most recent call last):
    ...
    planargeo.errors.SceneError: n must be a positive integer, got True
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
        if isinstance(value, (bool, np.bool_)):
            raise SceneError(msg)
        if isinstance(value, (int, np.integer)):
            v = int(value)
        elif isinstance(value, (float, np.floating)) and float(value).is_integer():
            v = int(value)
        else:
            raise SceneError(msg)
        if (positive and v <= 0) or (nonnegative and v < 0) or (nonzero and v == 0):
            raise SceneError(msg)
        return v
    if kind != "float":
        raise InputError(f"kind must be 'float', 'int' or 'choice', got {kind!r}")
    if isinstance(value, (bool, np.bool_, str, bytes)) or value is None:
        raise SceneError(f"{name} must be numeric, got {value!r}")
    try:
        a = np.asarray(value, dtype=float)
    except (TypeError, ValueError):
        raise SceneError(f"{name} must be numeric, got {value!r}") from None
    if a.ndim != 0:
        raise SceneShapeError(f"{name} must be a scalar, got shape {a.shape}")
    v = float(a)
    if not np.isfinite(v):
        raise SceneNonFiniteError(f"{name} must be finite, got {v!r}")
    if positive and not v > 0:
        raise SceneError(f"{name} must be positive, got {v!r}")
    if nonnegative and not v >= 0:
        raise SceneError(f"{name} must be non-negative, got {v!r}")
    if nonzero and v == 0:
        raise SceneError(f"{name} must be non-zero, got {v!r}")
    return v
