"""Views fitted to computed points (and the figure height to their aspect), and a legibility check.

:func:`legibility_problems` is the one test of a drawn figure that explorers and
the gallery share: text at least :data:`~planargeo.draw.style.MIN_TEXT_PX` pixels
high at the displayed size, no two texts on top of each other, and no label of
an axes outside it.
"""
from __future__ import annotations

import itertools

import numpy as np

from planargeo.draw.style import MIN_TEXT_PX

__all__ = ["shape_points", "fit_panel", "fit_view", "legibility_problems", "drawn_texts"]

#: pixels two text boxes may overlap (in both directions) or stick out before it is a problem
TOL_PX = 1.0


def shape_points(*shapes) -> np.ndarray:
    """Exterior vertices (n, 2) of shapely shapes (polygons or multipolygons), for view fitting.

    Parameters
    ----------
    *shapes : shapely geometries
        Polygons or multipolygons.

    Returns
    -------
    numpy.ndarray
        ``(n, 2)``.
    """
    out = [np.zeros((0, 2))]
    for s in shapes:
        for g in getattr(s, "geoms", [s]):
            out.append(np.asarray(g.exterior.coords)[:, :2])
    return np.vstack(out)


def fit_panel(ax, points, margin=0.08, *, hmin=1.5, hmax=4.6):
    """Fit a single-panel figure to ``points``: the figure height follows the points' aspect.

    The width stays; the height becomes ``width × (extent_y / extent_x)`` (clamped to
    ``[hmin, hmax]`` inches), so that the drawing fills the panel instead of
    leaving a band empty; then :func:`fit_view`.

    Parameters
    ----------
    ax : matplotlib.axes.Axes
        The panel.
    points : array_like (n, 2)
        Points to keep in view.
    margin : float
        Margin, a fraction of the larger extent.
    hmin, hmax : float
        Bounds of the figure height (inches).

    Returns
    -------
    matplotlib.axes.Axes
        ``ax``.
    """
    P = np.asarray(points, float).reshape(-1, 2)
    P = P[np.all(np.isfinite(P), axis=1)]
    ext = P.max(axis=0) - P.min(axis=0) + 2 * margin * np.max(P.max(axis=0) - P.min(axis=0))
    fig = ax.figure
    fw, _ = fig.get_size_inches()
    bb = ax.get_position(original=True)
    h = float(np.clip(fw * bb.width * ext[1] / ext[0] / bb.height, hmin, hmax))
    fig.set_size_inches(fw, h)
    fit_view(ax, P, margin=margin)
    return ax


def fit_view(ax, points, margin=0.25, *, aspect=None):
    """Set limits to the bounding box of the finite ``points`` (Euclidean, (n, 2)) plus a margin.

    ``margin`` is a fraction of the larger extent; with ``aspect`` (height /
    width of the panel) the box is widened so that equal-aspect drawing fills it.

    Parameters
    ----------
    ax : matplotlib.axes.Axes
        The panel.
    points : array_like (n, 2)
        Points to keep in view.
    margin : float
        Margin, a fraction of the larger extent.
    aspect : float, optional
        Height / width of the panel (default: the axes').

    Returns
    -------
    matplotlib.axes.Axes
        ``ax``.
    """
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


def drawn_texts(fig) -> list:
    """The texts actually drawn when ``fig`` is drawn now: ``[(Text, Bbox in pixels), ...]``.

    Drawing goes through an Agg renderer whose ``draw_text`` records the Text
    being drawn, so texts an artist skips (off-view ticks, labels of hidden
    elements, empty texts) are not listed.

    Parameters
    ----------
    fig : matplotlib.figure.Figure

    Returns
    -------
    list of (matplotlib.text.Text, matplotlib.transforms.Bbox)
    """
    from matplotlib.backends.backend_agg import FigureCanvasAgg

    canvas = fig.canvas if hasattr(fig.canvas, "get_renderer") else FigureCanvasAgg(fig)
    renderer = canvas.get_renderer()
    seen: dict[int, object] = {}
    orig = renderer.draw_text

    def record(gc, x, y, s, prop, angle, ismath=False, mtext=None):
        if mtext is not None and str(s).strip():
            seen.setdefault(id(mtext), mtext)
        return orig(gc, x, y, s, prop, angle, ismath=ismath, mtext=mtext)

    renderer.draw_text = record
    try:
        fig.draw(renderer)
    finally:
        del renderer.draw_text
    return [(t, t.get_window_extent(renderer)) for t in seen.values()]


def _axis_texts(ax) -> set:
    out = set()
    for axis in (ax.xaxis, ax.yaxis):
        for t in axis.get_ticklabels(which="both"):
            out.add(id(t))
        out.add(id(axis.label))
        out.add(id(axis.get_offset_text()))
    for t in (ax.title, getattr(ax, "_left_title", None), getattr(ax, "_right_title", None)):
        if t is not None:
            out.add(id(t))
    return out


def legibility_problems(fig, *, scale: float = 1.0, min_px: float = MIN_TEXT_PX) -> list[str]:
    """What makes ``fig`` hard to read as displayed: small text, overlapping or stray labels.

    The figure is drawn (Agg) and every text actually drawn is checked:

    * its font is at least ``min_px`` pixels at the displayed size
      (``fontsize [pt] × dpi / 72 × scale``; ``scale`` = displayed / native width);
    * no two texts overlap by more than :data:`TOL_PX` pixels in both directions
      (a text marked ``_planargeo_overlay``, e.g. a message box, is exempt);
    * a text belonging to an axes, other than its tick and axis labels and titles,
      lies inside that axes; every text lies inside the figure.

    Parameters
    ----------
    fig : matplotlib.figure.Figure
    scale : float
        Displayed size / native size of the figure (1: shown at ``fig.dpi``).
    min_px : float
        Smallest legible text height in pixels.

    Returns
    -------
    list of str
        One sentence per problem; empty when the figure is legible.

    Raises
    ------
    InputError
        ``scale`` or ``min_px`` not a positive finite number.
    """
    from planargeo.errors import InputError

    for name, v in (("scale", scale), ("min_px", min_px)):
        if not (isinstance(v, (int, float)) and np.isfinite(v) and v > 0):
            raise InputError(f"{name} must be a positive finite number, got {v!r}")
    texts = drawn_texts(fig)
    px_per_pt = fig.dpi / 72.0 * scale
    problems = []
    for t, bb in texts:
        size = t.get_fontsize() * px_per_pt
        if size < min_px - 1e-6:
            problems.append(f"text {t.get_text()!r} is {size:.1f} px high (< {min_px:g} px)")
    W, H = fig.bbox.width, fig.bbox.height
    for t, bb in texts:
        if bb.x0 < -TOL_PX or bb.y0 < -TOL_PX or bb.x1 > W + TOL_PX or bb.y1 > H + TOL_PX:
            problems.append(f"text {t.get_text()!r} leaves the figure")
    owned = {}
    for ax in fig.axes:
        skip = _axis_texts(ax)
        for t in ax.findobj(lambda a: hasattr(a, "get_text") and hasattr(a, "get_fontsize")):
            if id(t) not in skip:
                owned.setdefault(id(t), ax)
    for t, bb in texts:
        ax = owned.get(id(t))
        if ax is None:
            continue
        box = ax.bbox
        if bb.x0 < box.x0 - TOL_PX or bb.y0 < box.y0 - TOL_PX or bb.x1 > box.x1 + TOL_PX \
                or bb.y1 > box.y1 + TOL_PX:
            problems.append(f"label {t.get_text()!r} leaves the axes")
    plain = [(t, bb) for t, bb in texts if not getattr(t, "_planargeo_overlay", False)]
    for (ta, ba), (tb, bb) in itertools.combinations(plain, 2):
        dx = min(ba.x1, bb.x1) - max(ba.x0, bb.x0)
        dy = min(ba.y1, bb.y1) - max(ba.y0, bb.y0)
        if dx > TOL_PX and dy > TOL_PX:
            problems.append(f"labels {ta.get_text()!r} and {tb.get_text()!r} overlap "
                            f"({dx:.0f}×{dy:.0f} px)")
    return problems
