"""Registry of gallery figures (one function per thesis figure).

A figure module registers builders with :func:`register`; a builder takes no
argument and returns a matplotlib Figure drawn from computed quantities.
:func:`load_all` imports every module of :data:`MODULES`; an import error
propagates (a figure never silently drops out of the gallery).
"""
from __future__ import annotations

import importlib
from dataclasses import dataclass
from typing import Callable

MODULES = ("ch1", "ch3", "ch4", "ch5", "ch6", "ch7", "ch9", "extra")


@dataclass(frozen=True)
class FigureSpec:
    name: str
    caption: str
    build: Callable
    order: float


REGISTRY: dict[str, FigureSpec] = {}


def register(name: str, caption: str, order: float):
    """Decorator: register ``build() -> Figure`` under ``name`` (the SVG file stem)."""
    def deco(fn):
        REGISTRY[name] = FigureSpec(name, caption, fn, order)
        return fn
    return deco


def load_all() -> dict[str, FigureSpec]:
    """Import every figure module; return the registry sorted by thesis order.

    Any import error propagates: a broken figure module fails the gallery loudly.
    """
    for mod in MODULES:
        importlib.import_module(f"{__name__}.{mod}")
    return dict(sorted(REGISTRY.items(), key=lambda kv: (kv[1].order, kv[0])))


def new_figure(w=3.4, h=2.8, *, ncols=1, nrows=1, limits=None, geometric=True, **kw):
    """A figure with equal-aspect, axis-free panels (geometric) or plain axes (charts)."""
    import matplotlib.pyplot as plt
    from planargeo.draw.style import setup_axes

    fig, axs = plt.subplots(nrows, ncols, figsize=(w, h), squeeze=False, **kw)
    if geometric:
        fig.subplots_adjust(left=0.02, right=0.98, bottom=0.02, top=0.98, wspace=0.05, hspace=0.05)
    for ax in axs.ravel():
        if geometric:
            setup_axes(ax, limits)
    return fig, (axs[0, 0] if axs.size == 1 else axs.ravel())


