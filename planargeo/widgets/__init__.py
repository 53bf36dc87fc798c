"""Interactive explorers (ipywidgets): controls → state → picture (:mod:`planargeo.draw.picture`)
and readout, drawn by the page (:mod:`planargeo.widgets.canvas`).  Show one by leaving it as the
last expression of a notebook cell, e.g. ``ProjectiveExplorer()``; a saved notebook keeps a PNG.
Explorers are imported lazily: a missing optional module only affects the one that needs it.
"""
from __future__ import annotations

import importlib

from planargeo.widgets.base import Explorer, Handle, fmt

__all__ = ["Explorer", "Handle", "fmt", "EXPLORERS", "use_widget_backend"]


def use_widget_backend() -> str:
    """The front end explorers use: the page draws their pictures (kept for notebooks).

    Returns
    -------
    str
        ``"page"``.
    """
    return "page"


#: public name -> submodule defining it
EXPLORERS = {
    "ProjectiveExplorer": "projective",
    "PercussionExplorer": "percussion",
    "ScrewSumExplorer": "screw_sum",
    "ChainExplorer": "chain",
    "CarExplorer": "car",
    "SliderCrankExplorer": "slider_crank",
    "TreeExplorer": "trees",
    "SubspaceExplorer": "subspace",
    "ImpulseExplorer": "impulse",
    "ConstructionExplorer": "construction",
    "ArticulatedExplorer": "articulated",
    "SplittingExplorer": "splitting",
}
__all__ += list(EXPLORERS)


def __getattr__(name):
    if name in EXPLORERS:
        mod = importlib.import_module(f".{EXPLORERS[name]}", __name__)
        return getattr(mod, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
