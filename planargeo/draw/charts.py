"""Charts (curves over a parameter) in the package style: Figs 7.4, 7.6-7.8, 7.10."""
from __future__ import annotations

from planargeo.draw.style import LABEL_PT, OKABE_ITO, LINEWIDTHS, get_ax
from planargeo.errors import InputError

__all__ = ["CURVE_COLORS", "plot_curves", "polar_curves"]

#: Colours for families of curves (Okabe-Ito order, skipping yellow for contrast).
CURVE_COLORS = [OKABE_ITO[k] for k in ("blue", "vermillion", "green", "purple", "orange",
                                        "skyblue", "black")]
_DASHES = ["-", "--", "-.", ":", (0, (5, 1, 1, 1)), (0, (1, 1)), (0, (8, 2))]


def _curves(ax, x, ys, labels, title):
    """One line per ``ys[k]`` over ``x``, the k-th colour and dash (readable in grey); the title."""
    arts = [ax.plot(x, y, color=CURVE_COLORS[k % len(CURVE_COLORS)],
                    linestyle=_DASHES[k % len(_DASHES)], lw=LINEWIDTHS["chart"], label=lab)[0]
            for k, (y, lab) in enumerate(zip(ys, labels))]
    if title:
        ax.set_title(title)
    return arts


def plot_curves(x, ys, labels, ax=None, *, xlabel="", ylabel="", title=None, logx=False, ylim=None,
                legend=None):
    """Several curves ``ys[k]`` over ``x`` with distinct colour and dash (readable in grey).

    Parameters
    ----------
    x : array_like (n,)
        The parameter.
    ys : sequence of array_like (n,)
        One curve per entry.
    labels : sequence of str
        The curves' names (a legend when any is non-empty).
    ax : matplotlib.axes.Axes, optional
        Where to draw (default: the current axes).
    xlabel, ylabel, title : str
        Axis labels and title.
    logx : bool
        Logarithmic x axis.
    ylim : (float, float), optional
        The y limits.
    legend : dict, optional
        Keyword arguments of the legend (default: best place, no frame).

    Returns
    -------
    list of matplotlib.lines.Line2D

    Examples
    --------
    >>> import matplotlib; matplotlib.use("Agg")
    >>> from matplotlib.figure import Figure
    >>> arts = plot_curves([0, 1], [[0, 1], [1, 0]], ["up", "down"], Figure().add_subplot())
    >>> [a.get_label() for a in arts], arts[1].get_linestyle()
    (['up', 'down'], '--')
    """
    ax = get_ax(ax)
    arts = _curves(ax, x, ys, labels, title)
    if logx:
        ax.set_xscale("log")
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    if ylim is not None:
        ax.set_ylim(*ylim)
    ax.grid(True, lw=0.4, alpha=0.5)
    if any(labels):
        ax.legend(**{"loc": "best", "frameon": False, **(legend or {})})
    return arts


def polar_curves(theta, rs, labels, ax=None, *, title=None, rlabel=""):
    """Polar curves ``rs[k](theta)`` on the polar axes ``ax``; ``rlabel`` names the radius.

    The radial tick labels run along 100°; ``rlabel`` and the key are the figure's texts,
    upper left and right of the round panel.

    Parameters
    ----------
    theta : array_like (n,)
        Angles (radians).
    rs : sequence of array_like (n,)
        One radius curve per entry.
    labels : sequence of str
        The curves' names.
    ax : matplotlib.axes.Axes, optional
        A polar axes (default: the current axes).
    title : str, optional
        The title.
    rlabel : str
        What the radius measures.

    Returns
    -------
    list of matplotlib.lines.Line2D

    Raises
    ------
    InputError
        If ``ax`` is not a polar axes.
    """
    ax = get_ax(ax)
    if ax.name != "polar":
        raise InputError(f"ax must be a polar axes (projection='polar'), got a {ax.name!r} axes")
    arts = _curves(ax, theta, rs, labels, title)
    ax.set_rlabel_position(100)
    # the note and the key belong to the figure, around the round panel (not inside the axes)
    if rlabel:  # in the empty upper-left corner, clear of the radial tick labels along 100°
        ax.figure.text(-0.08, 1.04, f"radius: {rlabel}", transform=ax.transAxes, fontsize=LABEL_PT,
                       ha="left", va="top")
    ax.figure.legend(handles=arts, loc="upper left", bbox_to_anchor=(0.92, 1.12),
                     bbox_transform=ax.transAxes, frameon=False, fontsize=LABEL_PT)
    return arts
