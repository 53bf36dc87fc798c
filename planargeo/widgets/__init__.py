"""Interactive explorers (ipywidgets, drawn by the page) built on :mod:`planargeo.draw`.

Each explorer turns its controls into a state, the state into a picture
(:mod:`planargeo.draw.picture`) and a readout; the page draws the picture
(:mod:`planargeo.widgets.canvas`), moves dragged handles at once, zooms and pans.
Display one in a notebook by leaving it as the last expression of a cell (or
calling ``.show()``)::

    from planargeo.widgets import ProjectiveExplorer
    ProjectiveExplorer()

Where no widget can be shown (a saved notebook, the docs), the output holds a static
PNG of the picture.  Explorers are imported lazily so that a missing optional module
only affects the explorer that needs it.
"""
from __future__ import annotations

import importlib

from planargeo.widgets.base import Explorer, Handle, fmt

__all__ = ["Explorer", "Handle", "fmt", "EXPLORERS", "use_widget_backend"]


def use_widget_backend() -> str:
    """The front end explorers use: the page draws their pictures (kept for notebooks that call it).

    Explorers need no matplotlib backend (``%matplotlib widget`` is not needed): each draws
    its picture in the page, in JupyterLab, Notebook and Voila alike.  Calling this changes
    nothing.

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
