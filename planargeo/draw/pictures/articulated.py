"""The articulated-inertia explorer's picture: a chain, its inertias as conics, axes, a chart.

Thesis 7.1–7.3, 10.2.2–10.2.3: rigid inertias ``Iᵢ`` and articulated ones ``Aᵢ`` (7.7a) as
conics, the focused body's bold; the acceleration pole ``a``, its axes of percussion ``Aₖa``,
``Iₖa`` (5.64–5.68) and its polar; on the right a chart of ``Aₖ`` against the recursion steps.

Examples
--------
>>> fit_box([[0.0, 0.0], [2.0, 0.0]], margin=0.0)
(0.0, 2.0, -1.0, 1.0)
"""
from __future__ import annotations

import math

import numpy as np

from planargeo.draw.geometry import clip_line
from planargeo.draw.pictures.common import builder, labelled_line
from planargeo.draw.picture import PX_PER_PT, Picture, nice_ticks
from planargeo.draw.pictures._words import force, num, pair, subscript, where
from planargeo.draw.style import COLORS
from planargeo.geometry.conics import drawable_conic

__all__ = ["fit_box", "chain_view", "key_corner", "articulated_picture", "CHART", "CHAIN_SHARE", "MARGIN"]


def fit_box(mechanism, extra=(), margin: float = 0.15, reach: float = 3.0,
            least: float = 1.0) -> tuple[float, float, float, float]:
    """A square box about every finite point of ``mechanism`` and the ``extra`` points near it.

    Parameters
    ----------
    mechanism : array_like (m, 2)
        Points that must be in view.
    extra : array_like (k, 2)
        Points kept in view when within ``reach`` mechanism sizes of its middle.
    margin : float
        Margin on each side, a fraction of the box's side.
    reach : float
    least : float
        Smallest side of the box (m).

    Returns
    -------
    tuple
        ``(x0, x1, y0, y1)``.
    """
    M = np.asarray(mechanism, dtype=float).reshape(-1, 2)
    M = M[np.all(np.isfinite(M), axis=1)]
    lo, hi = M.min(axis=0), M.max(axis=0)
    size = max(float(np.max(hi - lo)), least)
    E = np.asarray(extra, dtype=float).reshape(-1, 2)
    E = E[np.all(np.isfinite(E), axis=1)]
    if len(E):
        mid = 0.5 * (lo + hi)
        E = E[np.hypot(*(E - mid).T) <= reach * size]
        if len(E):
            lo, hi = np.minimum(lo, E.min(axis=0)), np.maximum(hi, E.max(axis=0))
    c, half = 0.5 * (lo + hi), 0.5 * max(float(np.max(hi - lo)), least)
    half = half * (1.0 + 2.0 * margin)
    return (float(c[0] - half), float(c[0] + half), float(c[1] - half), float(c[1] + half))


_ART = "#CC79A7"        # OKABE_ITO purple: the articulated inertias
_RIGID = "#9a9a9a"
#: chart legend and colour of each component of ``A_k`` at joint ``k``
CHART = (("xx", "#0072B2"), ("yy", "#E69F00"), ("zz", "#009E73"), ("xy", "#D55E00"), ("xz", "#CC79A7"),
         ("yz", "#56B4E9"))
#: the share of the view's width the chain takes (the chart the rest)
CHAIN_SHARE = 0.62


def chain_view(box, size, margin) -> tuple[float, float, float, float]:
    """A view whose left :data:`CHAIN_SHARE` holds the square ``box`` of the chain (the chart on the right).

    Parameters
    ----------
    box : (x0, x1, y0, y1)
        The chain's box (:func:`fit_box`).
    size : (int, int)
    margin : (left, right, top, bottom)
        The picture's margins (pixels).

    Returns
    -------
    tuple
        ``(x0, x1, y0, y1)`` with the plot area's shape.
    """
    x0, x1, y0, y1 = box
    pw, ph = size[0] - margin[0] - margin[1], size[1] - margin[2] - margin[3]
    r = pw / ph
    S = max(x1 - x0, y1 - y0)
    H = max(S, S / (CHAIN_SHARE * r))
    W = r * H
    cx, cy = (x0 + x1) / 2, (y0 + y1) / 2
    left = cx - CHAIN_SHARE * W / 2
    return (left, left + W, cy - H / 2, cy + H / 2)


def key_corner(lines, size, key, *, inset: float = 2.0, pad: float = 4.0):
    """Where a key of size ``key`` goes in a plot area of size ``size`` so that it covers no line.

    Tried in turn: the upper left and upper right corners, the middle of the right and of the left
    side, the lower left and lower right corners.

    Parameters
    ----------
    lines : list of array_like (m, 2)
        The curves drawn (polylines, their points in pixels from the plot area's lower left corner).
    size : (float, float)
        The plot area's width and height (pixels).
    key : (float, float)
        The key's width and height (pixels).
    inset : float
        The key's distance from the plot area's sides (pixels).
    pad : float
        The least distance kept between the key and a line (pixels).

    Returns
    -------
    tuple or None
        The key's lower left corner ``(x, y)`` (pixels), or None when every place covers a line.

    Examples
    --------
    >>> key_corner([[[0.0, 0.0], [100.0, 100.0]]], (100.0, 100.0), (30.0, 20.0))   # the diagonal
    (2.0, 78.0)
    >>> key_corner([[[0.0, 100.0], [100.0, 0.0]]], (100.0, 100.0), (30.0, 20.0))   # the other one
    (68.0, 78.0)
    >>> key_corner([[[0.0, 50.0], [100.0, 50.0]], [[50.0, 0.0], [50.0, 100.0]]], (100.0, 100.0),
    ...            (80.0, 80.0)) is None
    True
    """
    (w, h), (kw, kh) = size, key
    left, right, bottom, top = inset, w - inset - kw, inset, h - inset - kh
    for x, y in ((left, top), (right, top), (right, (h - kh) / 2), (left, (h - kh) / 2), (left, bottom),
                 (right, bottom)):
        box = (x - pad, x + kw + pad, y - pad, y + kh + pad)
        if not any(_crosses(np.asarray(xy, float).reshape(-1, 2), box) for xy in lines):
            return (float(x), float(y))
    return None


def _crosses(xy, box) -> bool:
    """Whether the polyline ``xy`` has a point in the rectangle ``box = (x0, x1, y0, y1)`` (Liang–Barsky)."""
    x0, x1, y0, y1 = box
    for (ax, ay), (bx, by) in zip(xy, xy[1:] if len(xy) > 1 else xy):
        dx, dy = bx - ax, by - ay
        t0, t1 = 0.0, 1.0
        for p, q in ((-dx, ax - x0), (dx, x1 - ax), (-dy, ay - y0), (dy, y1 - ay)):
            if p == 0.0:
                if q < 0.0:
                    break
            else:
                t = q / p
                if p < 0.0:
                    t0 = max(t0, t)
                else:
                    t1 = min(t1, t)
        else:
            if t0 <= t1:
                return True
    return False


@builder
def articulated_picture(st: dict, *, k: int, focus_all: bool, rigid: bool, axes: bool, view,
                        size=(960, 500)) -> Picture:
    """The picture of one state of the articulated explorer (module docstring).

    Parameters
    ----------
    st : dict
        :func:`planargeo.scenes.articulated.articulated_state` with ``n`` and ``outboard``.
    k : int
        The focused body (0-based; body 1 when the focus is "all").
    focus_all, rigid, axes : bool
        Nothing faded; the rigid inertias ``Iᵢ`` drawn; the axes and the polar of ``a`` drawn.
    view : (x0, x1, y0, y1)
        The view (:func:`chain_view`); the chart takes its right part.
    """
    n = int(st["n"])
    kk = subscript(k + 1)
    pts = np.asarray(st["joints"], float)
    pic = Picture(view, size=size, ticks=False, margin=MARGIN)
    pic.path("links", pts, role="body", color=COLORS["body"], width=7.0 * PX_PER_PT, symbol="links",
             desc=f"the chain: {n} bodies of 1 kg, joints L = 1 m apart", z=1, opacity=0.55)
    pic.marks("pins", pts[:-1], role="body", color="#000000", size=6.0, symbol="joints",
              desc=f"the joints: {n} pins (joint 1 on the ground)", z=4)
    pic.marks("ground", [pts[0]], role="ground", color=COLORS["ground"], shape="s", size=10.0, symbol="ground",
              desc="the ground: joint 1 is pinned to it at (0, 0) m", z=3)
    for i in range(n):
        bold = focus_all or i == k
        sub = subscript(i + 1)
        for name, centre, color, faded, what in (
                ("I", "centre_rigid", _RIGID, 0.25, "rigid inertia of body {i}, a conic about its centre of mass "
                                                    "(10.2.3): centre"),
                ("A", "centre", _ART, 0.3, "articulated inertia of body {i} with the bodies outboard of it (7.7a), "
                                          "a conic: effective centre")):
            if name == "A" or rigid:
                pic.conic(f"{name}{i + 1}", st[name][i], role="inertia", color=color, symbol=f"{name}{sub}",
                          label=f"{name}{sub}" if i == k else "",
                          desc=f"{what.format(i=i + 1)} at {pair(np.asarray(st[centre][i], float))} m",
                          opacity=1.0 if bold else faded)
    a = np.asarray(st["pole"], float)
    pic.point("a", a, role="accel", glyph=False, size=8.0, symbol="a",
              desc=f"the acceleration pole a of body {k + 1} (4.6): {where(a)}")
    if axes:
        labelled_line(pic, "Aa", st["axis"][k], f"A{kk} a", role="wrench", arrow=False, symbol=f"A{kk} a",
                      anchor=_at(pic, 0.1),
                      desc=f"axis of percussion of a for body {k + 1} with the outboard bodies attached "
                           f"(5.64–5.68): {force(st['axis'][k])}")
        if rigid:
            labelled_line(pic, "Ia", st["axis_rigid"][k], f"I{kk} a", role="momentum", arrow=False,
                          dash=[8.0, 4.0], symbol=f"I{kk} a", anchor=_at(pic, 0.45), side=-1.0,
                          desc=f"axis of percussion of a for body {k + 1} alone (5.64–5.68): "
                               f"{force(st['axis_rigid'][k])}")
        polar = drawable_conic(st["A"][k]) @ a
        labelled_line(pic, "polar", polar, "polar of a (real conic)", role="construct", arrow=False,
                      symbol="polar of a", anchor=_at(pic, 0.8), side=-1.0,
                      desc=f"polar of a with respect to the drawn real conic of A{kk}: A{kk} a reflected "
                           f"through the centre (10.2.3): {force(polar)}")
    # the lines stay in the chain's part of the view (the chart has the rest)
    X0, X1, Y0, Y1 = pic.box
    part = (X0, X0 + (CHAIN_SHARE + 0.04) * (X1 - X0), Y0, Y1)
    for el in pic.elements:
        if el["id"] in ("Aa", "Ia", "polar"):
            line = {"Aa": st["axis"][k], "Ia": st["axis_rigid"][k], "polar": polar}[el["id"]]
            seg = clip_line(np.asarray(line, float), part)
            el["parts"] = [q for q in el["parts"] if q["p"] != "path" or seg is not None]
            for q in el["parts"]:
                if q["p"] == "path":
                    q["xy"] = seg
    _scale_bar(pic)
    _chart(pic, st, k)
    return pic


#: the picture's margins (pixels): no ticks (a scale bar instead), room for the chart's labels
MARGIN = (6.0, 6.0, 6.0, 6.0)


def _at(pic, f: float):
    """A point of the chain's part of the view, ``f`` of its width from the left, at mid height."""
    x0, x1, y0, y1 = pic.box
    return (x0 + f * CHAIN_SHARE * (x1 - x0), (y0 + y1) / 2)


def _scale_bar(pic) -> None:
    x0, x1, y0, y1 = pic.box
    span = CHAIN_SHARE * (x1 - x0)
    length = 10.0 ** math.floor(math.log10(span / 4))
    for m in (5.0, 2.0):
        if m * length <= span / 4:
            length *= m
            break
    px, py = x0 + 14.0 / pic.kx, y0 + 14.0 / pic.ky
    pic.path("scale", [[px, py], [px + length, py]], role="ground", color="#000000", width=2.0,
             symbol="scale", desc=f"a scale bar: {num(length)} m", z=6)
    pic.text("scale text", (px + length / 2, py), f"{num(length)} m", ha="center", va="bottom", dy=3.0,
             symbol="scale", desc=f"the scale bar's length: {num(length)} m")


class _Calls:
    """Stands for a picture (its view) and records what is drawn on it, to draw it again on another."""

    def __init__(self, pic):
        self.box, self.kx, self.ky, self.calls = pic.box, pic.kx, pic.ky, []
        self.elements = [{}]

    def __getattr__(self, kind):          # path, text: (kind, args, kwargs, the marks added to it)
        def call(*args, **kw):
            for a in args:             # drawn again on other pictures: never changed in place
                if isinstance(a, np.ndarray):
                    a.flags.writeable = False
            self.calls.append((kind, args, kw, []))
            self.elements[-1] = {"parts": self.calls[-1][3]}
        return call


#: the charts drawn lately by what they depend on (a drag of the pole draws the same chart again)
_CHARTS: dict = {}


def _chart(pic, st, k: int) -> None:
    """The convergence chart in the right part of the view (module docstring), drawn as kept for its inputs."""
    comps, errs = np.asarray(st["components"][k], float), np.asarray(st["error"][k], float)
    scale = float(np.linalg.norm(st["A_full"][k]))
    key = (k, int(st["outboard"]), pic.box, pic.kx, pic.ky, scale, comps.shape, comps.tobytes(), errs.tobytes())
    calls = _CHARTS.get(key)
    if calls is None:
        rec = _Calls(pic)
        _draw_chart(rec, comps, errs, scale, int(st["outboard"]), k)
        if len(_CHARTS) > 32:
            _CHARTS.clear()
        calls = _CHARTS[key] = rec.calls
    for kind, args, kw, marks in calls:
        getattr(pic, kind)(*args, **kw)
        if marks:
            pic.elements[-1]["parts"] += [dict(m) for m in marks]


def _draw_chart(pic, comps, errs, scale: float, outboard: int, k: int) -> None:
    steps = np.arange(len(comps))
    full = comps[-1]
    kk = subscript(k + 1)
    # the entries that are not zero, over their full values, and the error
    curves = [(name, color, comps[:, j] / full[j]) for j, (name, color) in enumerate(CHART)
              if abs(full[j]) > 1e-9 * scale] + [("error", "#000000", errs)]
    vis = np.concatenate([c[2] for c in curves])
    lo = min(0.0, float(np.min(vis))) - 0.05
    hi = max(1.05, float(np.max(vis))) + 0.1
    s0, s1 = -0.3, max(len(comps) - 1, 1) + 0.3
    X0, X1, Y0, Y1 = pic.box
    fx, fy = 1.0 / pic.kx, 1.0 / pic.ky        # data units per pixel
    cx0, cx1 = X0 + (CHAIN_SHARE + 0.08) * (X1 - X0), X1 - 14.0 * fx
    cy0, cy1 = Y0 + 44.0 * fy, Y1 - 30.0 * fy
    # the legend (two columns) in a corner of the chart the curves leave free, else above them all
    rows = (len(curves) + 1) // 2
    key_w, key_h = 2 * 50.0 - 2.0, rows * 15.0 + 2.0        # pixels
    width, height = (cx1 - cx0) * pic.kx, (cy1 - cy0) * pic.ky
    lines = [np.column_stack([(steps - s0) / (s1 - s0) * width, (y - lo) / (hi - lo) * height])
             for _, _, y in curves]
    corner = key_corner(lines, (width, height), (key_w, key_h))
    if corner is None:                          # no corner free: the values' axis raised above the curves
        r = (key_h + 2.0 + 6.0) / height
        hi = max(hi, (float(np.max(vis)) + 0.02 - r * lo) / (1.0 - r))
        corner = (2.0, height - 2.0 - key_h)
    sx, sy = (cx1 - cx0) / (s1 - s0), (cy1 - cy0) / (hi - lo)

    def at(s, v):
        """Chart values (steps ``s``, values ``v``) to data points of the view."""
        return np.array([[cx0 + (float(a) - s0) * sx, cy0 + (float(b) - lo) * sy] for a, b in zip(s, v)])

    what = f"entries of A{kk} at joint {k + 1} over their full values against the recursion steps (10.2.2)"
    pic.path("chart frame", [[cx0, cy0], [cx1, cy0], [cx1, cy1], [cx0, cy1]], role="chart", closed=True,
             color="#000000", width=0.8, symbol="chart", desc=f"the chart: {what}", z=1)
    for t in nice_ticks(lo, hi, 5):
        pic.path(f"chart grid {t:g}", at([s0, s1], [t, t]), role="chart", color="#dddddd", width=0.6,
                 symbol="chart", desc=f"the chart's grid line: {num(t)} of the full value", z=0)
        pic.text(f"chart y {t:g}", at([s0], [t])[0], num(t), ha="right", va="center", dx=-3.0,
                 symbol="chart", desc=f"the chart's value axis: {num(t)} of the full value")
    for s in steps:
        pic.text(f"chart x {s}", at([s], [lo])[0], str(s), ha="center", va="top", dy=-3.0,
                 symbol="steps", desc=f"the chart's step axis: {s} outboard bodies in the recursion")
    pic.text("chart xlabel", ((cx0 + cx1) / 2, cy0), "recursion steps (outboard bodies)", ha="center", va="top",
             dy=-17.0, symbol="steps", desc="the chart's axis: how many outboard bodies the recursion includes "
                                            "(10.2.2): 0 to " + str(len(comps) - 1))
    pic.text("chart title", ((cx0 + cx1) / 2, cy1), f"entries of A{kk} at joint {k + 1} / full value",
             ha="center", va="bottom", dy=4.0, symbol=f"A{kk}", desc=f"the chart: {what}")
    shown_k = min(outboard, len(comps) - 1)
    pic.path("chart now", at([shown_k, shown_k], [lo, hi]), role="chart", color=_ART, width=1.2,
             symbol="outboard bodies", desc=f"the recursion steps shown in the chain: {shown_k}", z=2,
             opacity=0.7)
    for name, color, y in curves:
        err = name == "error"
        xy = at(steps, y)
        meaning = (f"‖A{kk} after so many steps − A{kk}‖ / ‖A{kk}‖" if err else
                   f"entry {name} of A{kk} at joint {k + 1} over its full value")
        pic.path(f"chart {name}", xy, role="chart", color=color, width=1.2 if err else 1.5,
                 dash=[1.5, 2.5] if err else None, symbol=name,
                 desc=f"{meaning} (10.2.2): " + ", ".join(num(v, 3) for v in y), z=3)
        pic.elements[-1]["parts"] += [{"p": "mark", "x": float(x), "y": float(v), "shape": "s" if err else "o",
                                       "size": 4.0} for x, v in xy]
    kx0, ky0 = cx0 + corner[0] * fx, cy0 + corner[1] * fy
    kx1, ky1 = kx0 + key_w * fx, ky0 + key_h * fy
    pic.path("key box", [[kx0, ky0], [kx1, ky0], [kx1, ky1], [kx0, ky1]], role="chart", closed=True,
             fill="#ffffff", alpha=0.85, color="#cccccc", width=0.6, symbol="key",
             desc=f"the chart's key: {len(curves)} curves", z=5)
    for m, (name, color, _) in enumerate(curves):
        col, row = divmod(m, rows)
        x = kx0 + (col * 50.0 + 4.0) * fx
        y = ky1 - (row * 15.0 + 8.0) * fy
        pic.text(f"key {name}", (x, y), ("— " if name != "error" else "··· ") + name, color=color,
                 ha="left", va="center", symbol=name,
                 desc=f"the chart's key: {name}" + ("" if name == "error" else f", entry {name} of A{kk}"))
