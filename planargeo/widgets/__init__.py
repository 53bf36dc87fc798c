"""Interactive explorers (ipywidgets + matplotlib) built on :mod:`planargeo.draw`.

Each explorer builds its figure and artists once and updates them in place when
a control changes.  Display one in a notebook by leaving it as the last
expression of a cell (or calling ``.show()``)::

    from planargeo.widgets import ProjectiveExplorer
    ProjectiveExplorer()

Under ``%matplotlib widget`` (ipympl) the figure is interactive (drag points);
with the default inline backend it is re-rendered as an image on every change.
Explorers are imported lazily so that a missing optional module only affects
the explorer that needs it.
"""
from __future__ import annotations

import importlib

from planargeo.widgets.base import Explorer, fmt

__all__ = ["Explorer", "fmt", "EXPLORERS"]

#: public name -> submodule defining it
EXPLORERS = {
    "ProjectiveExplorer": "projective",
    "PercussionExplorer": "percussion",
    "ScrewSumExplorer": "screw_sum",
    "ChainExplorer": "chain",
    "CarExplorer": "car",
    "SliderCrankExplorer": "slider_crank",
    "TreeExplorer": "trees",
    "ArticulatedExplorer": "articulated",
    "SplittingExplorer": "splitting",
}
__all__ += list(EXPLORERS)


def __getattr__(name):
    if name in EXPLORERS:
        mod = importlib.import_module(f".{EXPLORERS[name]}", __name__)
        return getattr(mod, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
