"""One visual language for every planargeo drawing.

Colours come from the Okabe-Ito palette (colour-blind safe).  Each kind of
object has one role, used in every figure:

=============  ==============================  ==================================
role           object                          look
=============  ==============================  ==================================
``twist``      a velocity twist (a point)      blue marker + rotation glyph
``accel``      an acceleration (a point)       vermillion marker + glyph
``wrench``     a wrench (a line)               orange line with force arrow
``reaction``   a reaction / internal force     bluish-green line
``momentum``   a momentum wrench               reddish-purple line
``inertia``    an inertia (conic)              black dashed conic + centre dot
``conic``      a real conic                    black solid curve
``construct``  construction lines              grey thin dashed
``body``       a rigid body outline            sky-blue fill, dark outline
``ground``     ground / fixed frame            dark grey hatching
=============  ==============================  ==================================

A sum keeps the role of its terms, told apart by weight (:data:`SUM`).  Gallery output is
reproducible only inside :func:`rc_context` (fixed fonts and sizes).  Functions that draw on
an axes take what they draw first and ``ax=None`` (the current axes, :func:`get_ax`) after it.
"""
from __future__ import annotations

import contextlib

from planargeo.errors import InputError

#: Okabe-Ito colour-blind-safe palette.
OKABE_ITO = {"black": "#000000", "orange": "#E69F00", "skyblue": "#56B4E9", "green": "#009E73",
             "yellow": "#F0E442", "blue": "#0072B2", "vermillion": "#D55E00", "purple": "#CC79A7",
             "grey": "#7F7F7F"}

#: Colour per role (see module docstring).
COLORS = {
    "twist": OKABE_ITO["blue"],
    "accel": OKABE_ITO["vermillion"],
    "wrench": OKABE_ITO["orange"],
    "reaction": OKABE_ITO["green"],
    "momentum": OKABE_ITO["purple"],
    "inertia": OKABE_ITO["black"],
    "conic": OKABE_ITO["black"],
    "construct": OKABE_ITO["grey"],
    "body": OKABE_ITO["skyblue"],
    "ground": "#404040",
    "text": OKABE_ITO["black"],
}

#: Line widths (points) per role.
LINEWIDTHS = {"wrench": 1.8, "reaction": 1.8, "momentum": 1.8, "conic": 1.3, "inertia": 1.2,
              "construct": 0.8, "body": 1.0, "chart": 1.5}

#: Style per role: colour, line width (points), dash (matplotlib ``linestyle``) and marker;
#: a :class:`~planargeo.draw.picture.Picture` turns them into pixels.
STYLES = {
    "twist": dict(color=COLORS["twist"], marker="o", markersize=5.0),
    "accel": dict(color=COLORS["accel"], marker="o", markersize=5.0),
    "wrench": dict(color=COLORS["wrench"], linewidth=LINEWIDTHS["wrench"], linestyle="-"),
    "reaction": dict(color=COLORS["reaction"], linewidth=LINEWIDTHS["reaction"], linestyle="-"),
    "momentum": dict(color=COLORS["momentum"], linewidth=LINEWIDTHS["momentum"], linestyle="-"),
    "construct": dict(color=COLORS["construct"], linewidth=LINEWIDTHS["construct"], linestyle=(0, (4, 3))),
    "conic": dict(color=COLORS["conic"], linewidth=LINEWIDTHS["conic"], linestyle="-"),
    "inertia": dict(color=COLORS["inertia"], linewidth=LINEWIDTHS["inertia"], linestyle=(0, (5, 3))),
}

#: Emphasis of a sum (same colour as its terms, heavier): its line width (points) and pole marker.
SUM = {
    "line": dict(linewidth=3.4),
    "point": dict(marker="D", markersize=6.5),
}

#: Smallest text on screen, in pixels at the displayed size (explorers, gallery, legibility checks).
MIN_TEXT_PX = 11.0
#: The one text size of every planargeo drawing (points): 11.0 px in a gallery SVG at its natural
#: size (96/72 px per point, :data:`MIN_TEXT_PX`), 11.5 px in an explorer's picture (100 dpi).
LABEL_PT = 8.25
#: Titles (points), a little larger than :data:`LABEL_PT`.
TITLE_PT = 8.75
#: Explorers: resolution (pixels per inch, shown at native size), the narrowest figure (pixels)
EXPLORER_DPI = 100
EXPLORER_MIN_WIDTH_PX = 560

#: Fixed rcParams: fonts, sizes (all :data:`LABEL_PT`) and SVG determinism (column width ≈ 3.4 in).
RC = {"font.family": "DejaVu Sans", "font.size": LABEL_PT, "axes.titlesize": TITLE_PT,
      "axes.labelsize": LABEL_PT, "legend.fontsize": LABEL_PT, "xtick.labelsize": LABEL_PT,
      "ytick.labelsize": LABEL_PT,
      "lines.linewidth": 1.3, "legend.frameon": False, "figure.dpi": 100, "savefig.dpi": 100,
      "svg.hashsalt": "planargeo", "svg.fonttype": "path", "svg.id": None, "path.simplify": False,
      "axes.prop_cycle": None}  # the cycle is filled in by _rc

#: Column width (inches).
COLUMN_WIDTH = 3.4


def _rc() -> dict:
    from cycler import cycler

    rc = dict(RC)
    rc["axes.prop_cycle"] = cycler(color=[OKABE_ITO[k] for k in (
        "blue", "vermillion", "green", "orange", "purple", "skyblue", "black", "yellow")])
    return rc


@contextlib.contextmanager
def rc_context():
    """Context with the package's fixed fonts, sizes and SVG settings (:data:`RC`).

    Yields
    ------
    None
    """
    import matplotlib as mpl

    with mpl.rc_context(_rc()):
        yield


def _entry(table: dict, key: str, what: str, overrides: dict) -> dict:
    """``table[key]`` updated by ``overrides`` (a copy); an unknown key: InputError naming ``what``."""
    if key not in table:
        raise InputError(f"{what} must be one of {sorted(table)}, got {key!r}")
    return {**table[key], **overrides}


def style(role: str, **overrides) -> dict:
    """Keyword arguments for ``role`` (see :data:`STYLES`), updated by ``overrides``.

    Parameters
    ----------
    role : str
        A key of :data:`STYLES`.
    **overrides
        Keyword arguments replacing the role's.

    Returns
    -------
    dict
        Matplotlib's keyword arguments for an element in that role.

    Raises
    ------
    InputError
        An unknown role.

    Examples
    --------
    >>> style("wrench", linewidth=3)["linewidth"], style("twist")["color"]
    (3, '#0072B2')
    """
    return _entry(STYLES, role, "role", overrides)


def sum_style(kind: str, **overrides) -> dict:
    """Keyword arguments that mark a sum (``kind`` "line" or "point"), see :data:`SUM`.

    Parameters
    ----------
    kind : {"line", "point"}
        What the sum is drawn as.
    **overrides
        Keyword arguments replacing the defaults.

    Returns
    -------
    dict
        Matplotlib's keyword arguments that mark a sum: a wider line, or a diamond marker.

    Raises
    ------
    InputError
        A ``kind`` other than "line" and "point".

    Examples
    --------
    >>> sum_style("point")["marker"]
    'D'
    """
    return _entry(SUM, kind, "kind", overrides)


def legend(items, ax=None, *, loc="lower right", **kw):
    """A key of roles for one panel: ``items`` are ``(role, kind, text)``.

    Parameters
    ----------
    items : iterable of (str, str, str)
        ``(role, kind, text)``, ``kind`` one of "point", "line", "sum-point", "sum-line".
    ax : matplotlib.axes.Axes, optional
        Default: the current axes.
    loc : str
        Legend location.
    **kw
        Keyword arguments of :meth:`matplotlib.axes.Axes.legend`.

    Returns
    -------
    matplotlib.legend.Legend

    Raises
    ------
    InputError
        An unknown kind or role.

    Examples
    --------
    >>> import matplotlib; matplotlib.use("Agg")
    >>> from matplotlib.figure import Figure
    >>> leg = legend([("twist", "point", "twist"), ("wrench", "sum-line", "sum")], Figure().gca())
    >>> [t.get_text() for t in leg.get_texts()]
    ['twist', 'sum']
    """
    from matplotlib.lines import Line2D

    handles = []
    for role, kind, text in items:
        emph = kind.startswith("sum-")
        base = kind.removeprefix("sum-")
        if base == "point":
            st = STYLES.get(role, {})
            pt = sum_style("point") if emph else {}
            handles.append(Line2D([], [], color=COLORS[role], linestyle="none",
                                  marker=pt.get("marker", st.get("marker", "o")),
                                  markersize=pt.get("markersize", st.get("markersize", 5.0)),
                                  markeredgecolor="white", markeredgewidth=0.6, label=text))
        elif base == "line":
            st = STYLES.get(role, dict(color=COLORS[role], linewidth=1.3, linestyle="-"))
            lw = sum_style("line")["linewidth"] if emph else st["linewidth"]
            handles.append(Line2D([], [], color=COLORS[role], linewidth=lw,
                                  linestyle=st["linestyle"], label=text))
        else:
            raise InputError(f"legend item kind must be point, line, sum-point or sum-line, "
                             f"got {kind!r}")
    opts = dict(loc=loc, fontsize=LABEL_PT, handlelength=1.8, borderaxespad=0.2, labelspacing=0.3)
    opts.update(kw)
    return get_ax(ax).legend(handles=handles, **opts)


def setup_axes(limits=None, ax=None, *, grid=False, axis_off=True):
    """Equal-aspect geometric axes with optional ``limits = (x0, x1, y0, y1)``.

    Parameters
    ----------
    limits : (float, float, float, float), optional
        ``(x0, x1, y0, y1)``.
    ax : matplotlib.axes.Axes, optional
        The axes (default: the current axes).
    grid : bool
        Draw a grid.
    axis_off : bool
        Hide ticks and spines.

    Returns
    -------
    matplotlib.axes.Axes
    """
    ax = get_ax(ax)
    ax.set_aspect("equal", adjustable="box")
    if limits is not None:
        ax.set_xlim(limits[0], limits[1])
        ax.set_ylim(limits[2], limits[3])
    if axis_off:
        ax.set_xticks([])
        ax.set_yticks([])
        for s in ax.spines.values():
            s.set_visible(False)
    ax.grid(grid)
    return ax


def get_ax(ax=None):
    """``ax``, or the current axes when None: how every drawing function treats its ``ax=None``.

    Parameters
    ----------
    ax : matplotlib.axes.Axes, optional
        The axes.

    Returns
    -------
    matplotlib.axes.Axes
    """
    if ax is None:
        import matplotlib.pyplot as plt

        ax = plt.gca()
    return ax
