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
    from ..style import setup_axes

    fig, axs = plt.subplots(nrows, ncols, figsize=(w, h), squeeze=False, **kw)
    if geometric:
        fig.subplots_adjust(left=0.02, right=0.98, bottom=0.02, top=0.98, wspace=0.05, hspace=0.05)
    for ax in axs.ravel():
        if geometric:
            setup_axes(ax, limits)
    return fig, (axs[0, 0] if axs.size == 1 else axs.ravel())


def fit_view(ax, points, margin=0.25, *, aspect=None):
    """Set limits to the bounding box of the finite ``points`` (Euclidean, (n, 2)) plus a margin.

    ``margin`` is a fraction of the larger extent; with ``aspect`` (height /
    width of the panel) the box is widened so that equal-aspect drawing fills it.
    """
    import numpy as np

    P = np.asarray(points, float).reshape(-1, 2)
    P = P[np.all(np.isfinite(P), axis=1)]
    if len(P) > 2:  # ignore far outliers (poles of near-translations)
        med = np.median(P, axis=0)
        dist = np.hypot(*(P - med).T)
        P = P[dist <= 20 * max(np.median(dist), 1e-9) + 1e-9] if np.median(dist) > 0 else P
    lo, hi = P.min(axis=0), P.max(axis=0)
    size = max(float(np.max(hi - lo)), 1e-9)
    lo, hi = lo - margin * size, hi + margin * size
    if aspect is None:
        bb = ax.get_position(original=True)
        fw, fh = ax.figure.get_size_inches()
        aspect = (bb.height * fh) / (bb.width * fw)
    w, h = hi - lo
    c = (lo + hi) / 2
    if h / w < aspect:
        h = w * aspect
    else:
        w = h / aspect
    ax.set_xlim(c[0] - w / 2, c[0] + w / 2)
    ax.set_ylim(c[1] - h / 2, c[1] + h / 2)
    return ax
