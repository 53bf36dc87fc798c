"""Views fitted to computed points (:func:`fit_box`, :func:`fit_view`), and the legibility check
that explorers and the gallery share (:func:`legibility_problems`).
"""
from __future__ import annotations

import itertools

import numpy as np

from planargeo.draw._shared import number
from planargeo.draw.style import MIN_TEXT_PX, get_ax
from planargeo.errors import InputError

__all__ = ["shape_points", "fit_box", "fit_view", "legibility_problems", "drawn_texts"]

#: pixels two text boxes may overlap (in both directions) or stick out before it is a problem
TOL_PX = 1.0


def shape_points(*shapes) -> np.ndarray:
    """Exterior vertices (n, 2) of shapely polygons or multipolygons, for view fitting.

    Parameters
    ----------
    *shapes : shapely geometries
        Polygons or multipolygons.

    Returns
    -------
    numpy.ndarray
    """
    out = [np.zeros((0, 2))]
    for s in shapes:
        for g in getattr(s, "geoms", [s]):
            out.append(np.asarray(g.exterior.coords)[:, :2])
    return np.vstack(out)


def fit_box(points, aspect: float, *, margin=None, keep=None, min_span=None) -> tuple:
    """The view ``(x0, x1, y0, y1)`` fitted to the finite ``points``: what :func:`fit_view` sets.

    The bounding box of ``points`` without their far outliers (poles of near-translations:
    farther from the median than 20 times the spread, measured on ``keep`` when given) and of
    ``keep``, at least ``min_span`` wide and high, grown by ``margin`` × its larger extent, then
    widened to the height / width ratio ``aspect``.  Points that all but coincide (a folded
    chain) count as one, so that the view never keeps only them.

    Parameters
    ----------
    points : array_like (n, 2)
        Points to keep in view (far outliers excepted).
    aspect : float
        Height / width of the panel.
    margin : float, optional
        Fraction of the larger extent (default 0.25).
    keep : array_like (m, 2), optional
        Points always in view (the mechanism); never taken for outliers.
    min_span : float, optional
        Smallest width and height before the margin (e.g. the scene's size).

    Returns
    -------
    tuple of float

    Raises
    ------
    InputError
        No finite point, or a bad ``aspect`` (positive), ``margin`` or ``min_span`` (non-negative).

    Examples
    --------
    >>> fit_box([[0, 0], [2, 1]], 1.0, margin=0.1)
    (-0.2, 2.2, -0.7, 1.7)
    >>> folded = [[0, 0], [1e-7, 0], [2e-7, 0], [1e-7, 1e-7], [1.0, 0.0]]   # tip 1 m away
    >>> fit_box(folded, 1.0, margin=0.0)[:2], fit_box([[1e8, 0]], 1.0, margin=0, keep=folded)[:2]
    ((0.0, 1.0), (0.0, 1.0))
    """
    aspect = number(aspect, "aspect", positive=True)
    margin = 0.25 if margin is None else number(margin, "margin")
    min_span = 0.0 if min_span is None else number(min_span, "min_span")
    try:
        P = np.asarray(points, float).reshape(-1, 2)
        K = np.zeros((0, 2)) if keep is None else np.asarray(keep, float).reshape(-1, 2)
    except (TypeError, ValueError):
        raise InputError("points and keep must be arrays of (x, y) points") from None
    P = P[np.all(np.isfinite(P), axis=1)]
    K = K[np.all(np.isfinite(K), axis=1)]
    if not len(P) and not len(K):
        raise InputError("no finite point to fit the view to")
    P = np.vstack([_without_outliers(P, K, min_span), K])
    lo, hi = P.min(axis=0), P.max(axis=0)
    if min_span:                                        # at least min_span wide and high
        c, half = (lo + hi) / 2, np.maximum((hi - lo) / 2, min_span / 2)
        lo, hi = c - half, c + half
    size = max(float(np.max(hi - lo)), 1e-9)
    lo, hi = lo - margin * size, hi + margin * size
    w, h = hi - lo
    c = (lo + hi) / 2
    if h / w < aspect:
        h = w * aspect
    else:
        w = h / aspect
    return tuple(round(float(v), 12) + 0.0 for v in (c[0] - w / 2, c[0] + w / 2, c[1] - h / 2,
                                                      c[1] + h / 2))


def fit_view(points, *, ax=None, margin=None, aspect=None, keep=None, min_span=None):
    """Set the limits of ``ax`` to the view :func:`fit_box` fits to ``points``.

    Parameters
    ----------
    points, margin, keep, min_span
        As :func:`fit_box`.
    ax : matplotlib.axes.Axes, optional
        The panel (default: the current axes).
    aspect : float, optional
        Height / width of the panel (default: the axes').

    Returns
    -------
    matplotlib.axes.Axes
        The panel.

    Raises
    ------
    InputError
        No finite point, or a bad ``margin``, ``aspect`` or ``min_span`` (:func:`fit_box`).

    Examples
    --------
    >>> from matplotlib.figure import Figure
    >>> ax = Figure(figsize=(4, 4)).add_subplot()
    >>> [float(x) for x in fit_view([[0, 0], [1, 0.5]], ax=ax, margin=0.0, aspect=1.0).get_xlim()]
    [0.0, 1.0]
    """
    ax = get_ax(ax)
    if aspect is None:
        bb = ax.get_position(original=True)
        fw, fh = ax.figure.get_size_inches()
        aspect = (bb.height * fh) / (bb.width * fw)
    x0, x1, y0, y1 = fit_box(points, aspect, margin=margin, keep=keep, min_span=min_span)
    ax.set_xlim(x0, x1)
    ax.set_ylim(y0, y1)
    return ax


def _without_outliers(P: np.ndarray, K: np.ndarray, min_span: float) -> np.ndarray:
    """``P`` without its far outliers, measured against the mechanism ``K`` when given (:func:`fit_box`)."""
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

    An Agg renderer records each text it draws, so skipped ones (off-view ticks, hidden or empty
    labels) are not listed.

    Parameters
    ----------
    fig : matplotlib.figure.Figure
        The figure.

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

    Every text drawn must be at least ``min_px`` high at the displayed size, overlap no other
    by more than :data:`TOL_PX` in both directions (``_planargeo_overlay`` texts exempt), and
    lie inside its axes (tick and axis labels, titles excepted) and the figure.

    Parameters
    ----------
    fig : matplotlib.figure.Figure
        The figure.
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
    scale, min_px = number(scale, "scale", positive=True), number(min_px, "min_px", positive=True)
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
