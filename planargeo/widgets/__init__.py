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

from planargeo.widgets.base import Explorer, Handle, fmt

__all__ = ["Explorer", "Handle", "fmt", "EXPLORERS", "use_widget_backend"]


def use_widget_backend() -> str:
    """Turn on ``%matplotlib widget`` (ipympl) in a kernel where it works; else stay inline.

    Notebooks call this first: explorers then draw on an interactive canvas
    (drag the handles with the mouse).  Without a kernel, or where ipympl is
    missing or fails, nothing changes and explorers render images.

    Returns
    -------
    str
        ``"ipympl"`` when the widget backend is on, ``"image"`` otherwise.
    """
    try:
        from IPython import get_ipython
    except ImportError:
        return "image"
    ip = get_ipython()
    if ip is None or getattr(ip, "kernel", None) is None:
        return "image"
    try:
        import ipympl  # noqa: F401

        ip.run_line_magic("matplotlib", "widget")
    except Exception:  # noqa: BLE001 - fall back silently to the inline backend
        try:
            ip.run_line_magic("matplotlib", "inline")
        except Exception:  # noqa: BLE001
            pass
        return "image"
    import matplotlib

    return "ipympl" if "ipympl" in matplotlib.get_backend().lower() or \
        "widget" in matplotlib.get_backend().lower() else "image"

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
