"""Views fitted to computed points (and the figure height to their aspect), and a legibility check.

:func:`legibility_problems` is the one test of a drawn figure that explorers and
the gallery share: text at least :data:`~planargeo.draw.style.MIN_TEXT_PX` pixels
high at the displayed size, no two texts on top of each other, and no label of
an axes outside it.
"""
from __future__ import annotations

import itertools

import numpy as np

from planargeo.draw.style import MIN_TEXT_PX, _is_axes, get_ax
from planargeo.errors import InputError

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


def _former_order(name, points, rest, ax, margin):
    """``(ax, points, margin)`` of ``name(points[, margin], ax=...)`` or the former ``name(ax, points[, margin])``."""
    if _is_axes(points):                    # the former order: axes first
        if ax is not None:
            raise InputError(f"{name}: ax given twice (first argument and ax=)")
        if not rest:
            raise InputError(f"{name} needs points besides the axes")
        ax, points, rest = points, rest[0], rest[1:]
    if len(rest) > 1:
        raise InputError(f"{name} takes (points[, margin]), got {1 + len(rest)} positional arguments")
    if rest:
        if margin is not None:
            raise InputError(f"{name}: margin given twice (positionally and margin=)")
        margin = rest[0]
    return get_ax(ax), points, margin


def fit_panel(points, *args, ax=None, margin=None, hmin=1.5, hmax=4.6):
    """Fit a single-panel figure to ``points``: the figure height follows the points' aspect.

    The width stays; the height becomes ``width × (extent_y / extent_x)`` (clamped to
    ``[hmin, hmax]`` inches), so that the drawing fills the panel instead of
    leaving a band empty; then :func:`fit_view`.

    The former call ``fit_panel(ax, points[, margin])`` (axes first) is still read correctly.

    Parameters
    ----------
    points : array_like (n, 2)
        Points to keep in view.
    *args
        ``margin`` positionally (and, in the former order, ``points`` after the axes).
    ax : matplotlib.axes.Axes, optional
        The panel (default: the current axes).
    margin : float, optional
        Margin, a fraction of the larger extent (default 0.08).
    hmin, hmax : float
        Bounds of the figure height (inches).

    Returns
    -------
    matplotlib.axes.Axes
        The panel.

    Raises
    ------
    InputError
        Axes or margin given twice, or too many positional arguments.
    """
    ax, points, margin = _former_order("fit_panel", points, args, ax, margin)
    margin = 0.08 if margin is None else margin
    P = np.asarray(points, float).reshape(-1, 2)
    P = P[np.all(np.isfinite(P), axis=1)]
    ext = P.max(axis=0) - P.min(axis=0) + 2 * margin * np.max(P.max(axis=0) - P.min(axis=0))
    fig = ax.figure
    fw, _ = fig.get_size_inches()
    bb = ax.get_position(original=True)
    h = float(np.clip(fw * bb.width * ext[1] / ext[0] / bb.height, hmin, hmax))
    fig.set_size_inches(fw, h)
    fit_view(P, ax=ax, margin=margin)
    return ax


def fit_view(points, *args, ax=None, margin=None, aspect=None, keep=None, min_span=None):
    """Set limits to the bounding box of the finite ``points`` (Euclidean, (n, 2)) plus a margin.

    ``margin`` is a fraction of the larger extent; with ``aspect`` (height /
    width of the panel) the box is widened so that equal-aspect drawing fills it.

    Far outliers among ``points`` (poles of near-translations) are left out:
    points farther from the points' median than 20 times their median distance
    from it.  Outliers are only ever taken from ``points``: the ``keep`` points
    (the mechanism) are always in view, and they set the spread the outliers
    are measured by; ``min_span`` is the smallest width and height of the view.
    Without ``keep``, when the points kept would all but coincide (most points
    of a folded chain), they count as one point and the spread is the distance
    to the nearest other point: the view never keeps only the coincident points.

    The former call ``fit_view(ax, points[, margin])`` (axes first) is still read correctly.

    Parameters
    ----------
    points : array_like (n, 2)
        Points to keep in view (far outliers excepted).
    *args
        ``margin`` positionally (and, in the former order, ``points`` after the axes).
    ax : matplotlib.axes.Axes, optional
        The panel (default: the current axes).
    margin : float, optional
        Margin, a fraction of the larger extent (default 0.25).
    aspect : float, optional
        Height / width of the panel (default: the axes').
    keep : array_like (m, 2), optional
        Points always in view (the mechanism); never taken for outliers.
    min_span : float, optional
        The smallest width and height of the view, before the margin (e.g. the scene's size).

    Returns
    -------
    matplotlib.axes.Axes
        The panel.

    Raises
    ------
    InputError
        Axes or margin given twice, too many positional arguments, or a
        ``min_span`` that is not a non-negative finite number.

    Examples
    --------
    A chain folded onto its base: most points coincide (up to round-off), the
    tip is 1 m away.  The view holds the tip (it is no outlier):

    >>> from matplotlib.figure import Figure
    >>> ax = Figure(figsize=(4, 4)).add_subplot()
    >>> folded = [[0, 0], [1e-7, 0], [2e-7, 0], [1e-7, 1e-7], [1.0, 0.0]]
    >>> [float(x) for x in fit_view(folded, ax=ax, margin=0.0, aspect=1.0).get_xlim()]
    [0.0, 1.0]

    With the mechanism as ``keep``, a pole 1e8 m away is left out, the mechanism kept:

    >>> [float(x) for x in fit_view([[1e8, 0.0], [0.5, 0.2]], ax=ax, margin=0.0, aspect=1.0,
    ...                              keep=folded).get_xlim()]
    [0.0, 1.0]
    >>> x0, x1 = fit_view([[0, 0], [1e-7, 0]], ax=ax, margin=0.0, aspect=1.0, min_span=2.0).get_xlim()
    >>> round(float(x1 - x0), 9)
    2.0
    """
    ax, points, margin = _former_order("fit_view", points, args, ax, margin)
    margin = 0.25 if margin is None else margin
    if min_span is not None and not (isinstance(min_span, (int, float, np.floating)) and
                                     np.isfinite(min_span) and min_span >= 0):
        raise InputError(f"min_span must be a non-negative finite number, got {min_span!r}")
    P = np.asarray(points, float).reshape(-1, 2)
    P = P[np.all(np.isfinite(P), axis=1)]
    K = np.zeros((0, 2)) if keep is None else np.asarray(keep, float).reshape(-1, 2)
    K = K[np.all(np.isfinite(K), axis=1)]
    P = _without_outliers(P, K, float(min_span or 0.0))
    P = np.vstack([P, K])
    if not len(P):
        P = np.zeros((1, 2))
    lo, hi = P.min(axis=0), P.max(axis=0)
    if min_span:                                        # at least min_span wide and high
        c, half = (lo + hi) / 2, np.maximum((hi - lo) / 2, min_span / 2)
        lo, hi = c - half, c + half
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


def _without_outliers(P: np.ndarray, K: np.ndarray, min_span: float) -> np.ndarray:
    """``P`` without its far outliers, measured against the mechanism ``K`` when given (fit_view)."""
    ref = K if len(K) else P
    if len(P) <= 2 and not len(K):
        return P
    med = np.median(ref, axis=0)
    spread = float(np.median(np.hypot(*(ref - med).T))) if len(ref) else 0.0
    if len(K):
        spread = max(spread, float(np.max(np.ptp(K, axis=0))) / 2)
    spread = max(spread, min_span / 2)
    if spread <= 0:                                     # no spread to measure outliers by
        return P
    dist = np.hypot(*(P - med).T)
    out = dist > 20 * spread + 1e-9
    if not len(K) and not min_span and np.any(out) and not np.all(out):
        # the points kept all but coincide (most points of a folded chain, up to round-off):
        # they count as one point, and the spread is the distance to the nearest other one
        near = float(np.min(dist[out]))
        if float(np.max(np.ptp(P[~out], axis=0))) < 1e-4 * near:
            out = dist > 20 * near + 1e-9
    return P[~out]


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
