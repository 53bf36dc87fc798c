"""Registry of gallery figures (one function per thesis figure) and what they share.

A figure module registers a drawing function ``figC_K(ax)`` with
:func:`register`: its name is the SVG file stem, its docstring the caption; the
registered builder makes the figure (:func:`new_figure`), draws on its axes from
computed quantities and returns it.  :func:`load_all` imports every module
of :data:`MODULES`; an import error propagates (a figure never silently drops
out of the gallery).  :func:`chain` and :func:`scene_state` are the models and
states several figures draw.
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
        The figure's name, also its SVG file's stem (``fig5_6``).
    caption : str
        The caption: the drawing function's docstring, lines joined.
    build : callable
        ``build() -> matplotlib.figure.Figure``, a new figure drawn.
    order : float
        Its place in the gallery (the thesis figure number, ``5.06`` for Fig. 5.6).
    """
    name: str
    caption: str
    build: Callable
    order: float


REGISTRY: dict[str, FigureSpec] = {}


def register(order: float, *, height: float = 2.8, **layout):
    """Decorator: register ``draw(ax)`` as a figure, ``order`` its place in the gallery.

    The function's name is the figure's name (the SVG file stem) and its
    docstring, its lines joined by spaces, the caption.  The figure's
    ``build() -> Figure`` makes a one-column figure ``height`` inches tall with
    :func:`new_figure` (``layout``: its keywords), calls ``draw`` with its axes
    (an array of axes for several panels) and returns it.

    Parameters
    ----------
    order : float
        Place in the gallery (thesis figure number, e.g. ``4.07``).
    height : float, optional
        Figure height (inches).
    **layout : 
        Keywords of :func:`new_figure` (``nrows``, ``ncols``, ``margins``, ``polar``).

    Returns
    -------
    callable
        The decorator; it returns the drawing function unchanged.

    Raises
    ------
    PlanargeoError
        If ``draw`` has no docstring (``python -OO`` drops them): no caption.
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
    """Raise every text of ``fig`` smaller than ``min_pt`` points to ``min_pt`` (one text size).

    The gallery's figures draw with :mod:`planargeo.draw`, whose texts are
    :data:`~planargeo.draw.style.LABEL_PT`; this catches a text drawn smaller
    (a helper's own default), so that no text of the gallery is below
    :data:`~planargeo.draw.style.MIN_TEXT_PX` at the SVG's natural size.

    Parameters
    ----------
    fig : matplotlib.figure.Figure
        A drawn figure.
    min_pt : float, optional
        Smallest font size (points).

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
    """Import every figure module; return the registry sorted by thesis order.

    Any import error propagates: a broken figure module fails the gallery loudly.

    Returns
    -------
    dict of str to FigureSpec
        Every figure, in gallery order.
    """
    for mod in MODULES:
        importlib.import_module(f"{__name__}.{mod}")
    return dict(sorted(REGISTRY.items(), key=lambda kv: (kv[1].order, kv[0])))


def new_figure(height=2.8, *, nrows=1, ncols=1, margins=None, polar=None, **kw):
    """A figure one column wide and ``height`` inches tall, and its axes.

    By default ``nrows × ncols`` equal-aspect, axis-free panels filling the
    figure; with ``margins = (left, right, bottom, top)`` chart axes inside
    those figure fractions; with ``polar = [left, bottom, width, height]`` one
    polar axes there.  ``kw`` go to :func:`matplotlib.pyplot.subplots`.
    Returns ``(fig, ax)``, or ``(fig, axs)`` (flat) for several panels.

    Parameters
    ----------
    height : float, optional
        Height (inches); the width is one column.
    nrows, ncols : int, optional
        Panel grid.
    margins : tuple of 4 float, optional
        ``(left, right, bottom, top)`` figure fractions for chart axes.
    polar : sequence of 4 float, optional
        ``[left, bottom, width, height]`` of one polar axes.
    **kw : 
        More keywords for :func:`matplotlib.pyplot.subplots`.

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

    Joint 1 (kind ``base``) sits at the origin, joint ``i`` (revolute) 1 along
    link ``i − 1``; the last link's centre of mass is at ``tip_com`` (it is
    drawn ``2 tip_com`` long).

    Parameters
    ----------
    n : int
        Number of links.
    base : str, optional
        Kind of joint 1.
    gravity : array_like, shape (2,), optional
        Gravity (m/s²).
    tip_com : float, optional
        Centre of mass of the last link along it (m).

    Returns
    -------
    Model
        The chain.
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
        Scene name.
    **params : 
        Scene parameters.

    Returns
    -------
    tuple
        ``(SceneResult, Data)``.
    """
    res = build_scene(name, **params)
    return res, kinematics(res.model, res.state["q"], res.state["qd"])
