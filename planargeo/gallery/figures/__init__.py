"""Registry of gallery figures (one function per thesis figure, :func:`register`) and what they share.

A registered ``figC_K(ax)`` is named like its SVG file and captioned by its docstring;
:func:`load_all` imports every module of :data:`MODULES` (an import error propagates).
"""
from __future__ import annotations

import importlib
import inspect
from dataclasses import dataclass
from typing import Callable

from planargeo.draw.style import COLUMN_WIDTH, LABEL_PT, setup_axes
from planargeo.errors import PlanargeoError
from planargeo.mechanics.kinematics import kinematics
from planargeo.mechanics.model import Body, Joint, Model
from planargeo.scenes import build as build_scene

MODULES = ("ch1", "ch3", "ch4", "ch5", "ch6", "ch7", "ch9", "ch10", "extra", "fields", "notation",
           "subspaces_2dof")


@dataclass(frozen=True)
class FigureSpec:
    """One registered gallery figure.

    Attributes
    ----------
    name : str
        The SVG file's stem (``fig5_6``).
    caption : str
        The drawing function's docstring, lines joined.
    build : callable
        ``build() -> matplotlib.figure.Figure``.
    order : float
        Its place in the gallery (``5.06`` for Fig. 5.6).
    """
    name: str
    caption: str
    build: Callable
    order: float


REGISTRY: dict[str, FigureSpec] = {}


def register(order: float, *, height: float = 2.8, **layout):
    """Decorator: register ``draw(ax)``, drawn on a :func:`new_figure`, as the figure named like it.

    Parameters
    ----------
    order : float
        Place in the gallery (thesis figure number, e.g. ``4.07``).
    height : float, optional
        Figure height (inches).
    **layout :
        Keywords of :func:`new_figure`.

    Returns
    -------
    callable
        The decorator; it returns the drawing function unchanged.

    Raises
    ------
    PlanargeoError
        If ``draw`` has no docstring (its caption; ``python -OO`` drops them).
    """
    def deco(draw):
        if not draw.__doc__:
            raise PlanargeoError(f"figure {draw.__name__} has no caption: captions are the figure "
                                 f"functions' docstrings, which python -OO drops")

        def build():
            fig, ax = new_figure(height, **layout)
            draw(ax)
            legible_text(fig)
            return fig

        caption = " ".join(inspect.cleandoc(draw.__doc__).splitlines())
        REGISTRY[draw.__name__] = FigureSpec(draw.__name__, caption, build, order)
        return draw
    return deco


def legible_text(fig, min_pt: float = LABEL_PT):
    """Raise every text of ``fig`` smaller than ``min_pt`` points to ``min_pt``.

    Parameters
    ----------
    fig, min_pt

    Returns
    -------
    int
        How many texts were enlarged.
    """
    from matplotlib.text import Text

    n = 0
    for t in fig.findobj(Text):
        if t.get_fontsize() < min_pt:
            t.set_fontsize(min_pt)
            n += 1
    return n


def load_all() -> dict[str, FigureSpec]:
    """Import every figure module (errors propagate); return the registry sorted by thesis order.

    Returns
    -------
    dict of str to FigureSpec
    """
    for mod in MODULES:
        importlib.import_module(f"{__name__}.{mod}")
    return dict(sorted(REGISTRY.items(), key=lambda kv: (kv[1].order, kv[0])))


def new_figure(height=2.8, *, nrows=1, ncols=1, margins=None, polar=None, **kw):
    """A figure one column wide and ``height`` inches tall, and its axes (equal-aspect, axis-free panels).

    Parameters
    ----------
    height : float, optional
    nrows, ncols : int, optional
        Panel grid.
    margins : tuple of 4 float, optional
        ``(left, right, bottom, top)`` figure fractions for chart axes.
    polar : sequence of 4 float, optional
        ``[left, bottom, width, height]`` of one polar axes.
    **kw :
        Keywords of :func:`matplotlib.pyplot.subplots`.

    Returns
    -------
    tuple
        ``(fig, ax)`` or ``(fig, axs)``.
    """
    import matplotlib.pyplot as plt

    if polar is not None:
        fig = plt.figure(figsize=(COLUMN_WIDTH, height))
        return fig, fig.add_axes(polar, projection="polar")
    fig, axs = plt.subplots(nrows, ncols, figsize=(COLUMN_WIDTH, height), squeeze=False, **kw)
    if margins is None:
        fig.subplots_adjust(left=0.02, right=0.98, bottom=0.02, top=0.98, wspace=0.05, hspace=0.05)
        for ax in axs.flat:
            setup_axes(ax=ax)
    else:
        left, right, bottom, top = margins
        fig.subplots_adjust(left=left, right=right, bottom=bottom, top=top)
    return fig, (axs[0, 0] if axs.size == 1 else axs.ravel())


def chain(n: int, *, base: str = "revolute", gravity=(0.0, 0.0), tip_com: float = 0.5) -> Model:
    """``n`` unit links (mass 1, centre of mass 0.5 along the link, 1/12 about it) named 1…n.

    Parameters
    ----------
    n : int
    base : str, optional
        Kind of joint 1 (at the origin; the others are revolute).
    gravity : array_like, shape (2,), optional
    tip_com : float, optional
        Centre of mass of the last link along it (m).

    Returns
    -------
    Model
    """
    bodies = [Body(1.0, (0.5 if i < n - 1 else tip_com, 0.0), 1.0 / 12, name=str(i + 1))
              for i in range(n)]
    joints = [Joint(base if i == 0 else "revolute", (0.0 if i == 0 else 1.0, 0.0, 0.0))
              for i in range(n)]
    return Model(bodies, joints, list(range(-1, n - 1)), gravity)


def scene_state(name: str, **params):
    """The scene ``name`` (:func:`planargeo.scenes.build`) and the kinematics at its state.

    Parameters
    ----------
    name : str
    **params
        Scene parameters.

    Returns
    -------
    tuple
        ``(SceneResult, Data)``.
    """
    res = build_scene(name, **params)
    return res, kinematics(res.model, res.state["q"], res.state["qd"])
