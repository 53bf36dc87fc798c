"""Charts (curves over a parameter) in the package style: Figs 7.4, 7.6-7.8, 7.10."""
from __future__ import annotations

from planargeo.draw.style import OKABE_ITO, LINEWIDTHS

__all__ = ["CURVE_COLORS", "plot_curves", "polar_curves"]

#: Colours for families of curves (Okabe-Ito order, skipping yellow for contrast).
CURVE_COLORS = [OKABE_ITO[k] for k in ("blue", "vermillion", "green", "purple", "orange",
                                        "skyblue", "black")]
_DASHES = ["-", "--", "-.", ":", (0, (5, 1, 1, 1)), (0, (1, 1)), (0, (8, 2))]


def plot_curves(ax, x, ys, labels, *, xlabel="", ylabel="", title=None, legend_loc="best",
                logx=False, ylim=None):
    """Several curves ``ys[k]`` over ``x`` with distinct colour and dash (readable in grey)."""
    arts = []
    for k, (y, lab) in enumerate(zip(ys, labels)):
        (ln,) = ax.plot(x, y, color=CURVE_COLORS[k % len(CURVE_COLORS)],
                        linestyle=_DASHES[k % len(_DASHES)], lw=LINEWIDTHS["chart"], label=lab)
        arts.append(ln)
    if logx:
        ax.set_xscale("log")
    ax.set_xlabel(xlabel)
    ax.set_ylabel(ylabel)
    if ylim is not None:
        ax.set_ylim(*ylim)
    if title:
        ax.set_title(title)
    ax.grid(True, lw=0.4, alpha=0.5)
    if any(labels):
        ax.legend(loc=legend_loc, frameon=False)
    return arts


def polar_curves(ax, theta, rs, labels, *, title=None, rlabel=""):
    """Polar curves ``rs[k](theta)`` on a polar axes ``ax``; ``rlabel`` names the radius.

    The radial tick labels run along 100°; ``rlabel`` goes in the axes' upper-left
    corner (outside the circle) so that it never sits on a tick label.
    """
    arts = []
    for k, (r, lab) in enumerate(zip(rs, labels)):
        (ln,) = ax.plot(theta, r, color=CURVE_COLORS[k % len(CURVE_COLORS)],
                        linestyle=_DASHES[k % len(_DASHES)], lw=LINEWIDTHS["chart"], label=lab)
        arts.append(ln)
    if title:
        ax.set_title(title)
    ax.set_rlabel_position(100)
    if rlabel:  # in the empty upper-left corner, clear of the radial tick labels along 100°
        ax.text(-0.08, 1.04, f"radius: {rlabel}", transform=ax.transAxes, fontsize=7,
                ha="left", va="top")
    ax.legend(loc="upper left", bbox_to_anchor=(0.92, 1.12), frameon=False, fontsize=6.5)
    return arts
