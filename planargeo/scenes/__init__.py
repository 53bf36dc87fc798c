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

from ..errors import SceneError

__all__ = ["SceneResult", "register", "get", "names", "parameters", "build"]

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
        The frozen mechanism description (``planargeo.model.Model``), if the scene has one.
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
