"""A :class:`~planargeo.draw.picture.Picture` read off an explorer's axes (the migration path).

The explorers still hold their scene in matplotlib artists, updated in place.  To
draw them in the page, this module reads what those artists *hold* — a homogeneous
point, line or conic, a polyline, a polygon, a text — and hands it to the picture
builder, which does the geometry once (clipping, ideal elements, conic classes,
label places).  Nothing is rasterised and matplotlib draws nothing: reading an
artist's data costs microseconds.

Each element's ``id`` is the artist's position among the axes' children (an
explorer creates its artists once, so the position is stable), or its ``gid``
when it has one; its ``symbol`` is its label text, and its description comes from
the explorer's ``explain()`` table.
"""
from __future__ import annotations

import numpy as np
from matplotlib.artist import Artist
from matplotlib.lines import Line2D
from matplotlib.patches import FancyArrowPatch, Patch
from matplotlib.text import Annotation, Text
from matplotlib.ticker import NullLocator

from planargeo.draw.artists import ConicArtist, LineArtist, PointArtist
from planargeo.draw.picture import PX_PER_PT, Picture

__all__ = ["picture_from_axes"]

_DASHES = {"--": [5.0, 3.0], ":": [1.5, 2.5], "-.": [5.0, 2.5, 1.5, 2.5]}


def _dash(a) -> list[float] | None:
    ls = a.get_linestyle()
    if ls in ("-", "solid", "None", "none", "", " "):
        return None
    pat = _DASHES.get(ls)
    return [round(v * PX_PER_PT, 2) for v in (pat or [4.0, 3.0])]


def _hex(c) -> str:
    from matplotlib.colors import to_hex

    try:
        return to_hex(c, keep_alpha=False)
    except (ValueError, TypeError):
        return "#000000"


def _describe(explain: dict, symbol: str) -> str:
    if not symbol:
        return ""
    return explain.get(symbol) or explain.get(symbol.split(" ")[0], "")


def picture_from_axes(axes, *, explain: dict | None = None, title: str = "", view=None,
                      handles=()) -> Picture:
    """The picture of what ``ax`` shows (module docstring).

    Parameters
    ----------
    axes : matplotlib.axes.Axes
        An explorer's axes, its artists up to date (read, never drawn on).
    explain : dict, optional
        ``{symbol: description}`` (the explorer's :meth:`explain`).
    title : str
        Title above the picture.
    view : (x0, x1, y0, y1), optional
        The data box to show (default: the axes' limits).
    handles : iterable of (id, (x, y), description)
        Draggable points.

    Returns
    -------
    Picture
    """
    explain = dict(explain or {})
    ax = axes
    fig = ax.figure
    W, H = (fig.get_size_inches() * fig.dpi).round().astype(int)
    ax.apply_aspect()  # the limits and box matplotlib would draw with
    pos = ax.get_position()
    margin = (pos.x0 * W, (1 - pos.x1) * W, (1 - pos.y1) * H, pos.y0 * H)
    own_view = view is None
    if own_view:
        (x0, x1), (y0, y1) = sorted(ax.get_xlim()), sorted(ax.get_ylim())
        view = (x0, x1, y0, y1)
    ticks = (ax.axison and ax.xaxis.get_visible()
             and ax.xaxis.get_tick_params().get("labelbottom", True)
             and not isinstance(ax.xaxis.get_major_locator(), NullLocator))
    pic = Picture(view, size=(W, H), title=title, equal=not own_view and ax.get_aspect() == 1.0,
                  ticks=bool(ticks), margin=margin)
    children = [(a, f"e{k}") for k, a in enumerate(ax.get_children())]
    children += [(t, f"fig{k}") for k, t in enumerate(fig.texts)]
    skip = {ax.patch, ax.xaxis, ax.yaxis, ax.title, ax._left_title, ax._right_title,
            *ax.spines.values()}
    for a, eid in sorted(children, key=lambda c: c[0].get_zorder()):
        if a not in skip:
            _add_artist(pic, a, a.get_gid() or eid, ax, explain)
    for hid, xy, desc in handles:
        pic.handle(hid, xy, symbol=hid, desc=desc)
    return pic


def _label_of(a) -> str:
    label = a.get_label() or ""
    return "" if label.startswith("_") else label


def _add_artist(pic: Picture, a, eid: str, ax, explain: dict) -> None:
    """Add what the artist ``a`` holds to ``pic`` (a composite: its children, in order)."""
    if not a.get_visible() or getattr(a, "_planargeo_overlay", False):
        return
    data = ax.transData
    z = int(round(a.get_zorder()))
    if isinstance(a, (PointArtist, LineArtist, ConicArtist)):
        sym = a._text.get_text()
        common = dict(symbol=sym, desc=_describe(explain, sym), color=a._color)
        if isinstance(a, PointArtist):
            marker = a._marker.get_marker()
            pic.point(eid, a.get_point(), glyph=a._glyph, glyph_scale=a._glyph_scale,
                      size=a._marker.get_markersize() * PX_PER_PT,
                      shape=marker if marker in ("o", "D", "s") else "o", **common)
        elif isinstance(a, LineArtist):
            pic.line(eid, a.get_line(), anchor=a._anchor, role="wrench",
                     width=a._line.get_linewidth() * PX_PER_PT, dash=_dash(a._line), **common)
        else:
            pic.conic(eid, a.get_conic(), role=a._role, mark_center=a._mark_center, **common)
        return
    if isinstance(a, Line2D):
        xy = np.asarray(a.get_xydata(), float)
        if xy.size == 0:
            return
        if a.get_transform() != data:
            xy = data.inverted().transform(a.get_transform().transform(xy))
        sym = _label_of(a)
        if a.get_linestyle() not in ("None", "none", "", " ") and len(xy) > 1:
            pic.path(eid, xy, role="line", symbol=sym, desc=_describe(explain, sym),
                     color=_hex(a.get_color()), width=a.get_linewidth() * PX_PER_PT, dash=_dash(a), z=z)
        marker = a.get_marker()
        if marker not in (None, "None", "none", "", " "):
            pic.marks(eid + "m", xy, shape=marker if marker in ("o", "D", "s") else "o",
                      size=a.get_markersize() * PX_PER_PT, color=_hex(a.get_markerfacecolor()),
                      symbol=sym, desc=_describe(explain, sym), z=z)
        return
    if isinstance(a, FancyArrowPatch):
        path = a.get_path()  # display coordinates, head included
        if len(path.vertices):
            xy = data.inverted().transform(path.vertices)
            pic.path(eid, xy, role="line", color=_hex(a.get_edgecolor()), fill=_hex(a.get_facecolor()),
                     closed=False, width=a.get_linewidth() * PX_PER_PT, z=z)
        return
    if isinstance(a, Patch):
        verts = a.get_verts()
        if len(verts) == 0:
            return
        xy = data.inverted().transform(verts)
        fc, ec, lw = a.get_facecolor(), a.get_edgecolor(), a.get_linewidth()
        fill = None if not a.get_fill() or fc[3] == 0 else _hex(fc)
        sym = _label_of(a)
        pic.path(eid, xy, role="body", symbol=sym, desc=_describe(explain, sym), closed=True,
                 fill=fill, alpha=float(fc[3]) if fill else 1.0,
                 color=_hex(ec) if ec[3] > 0 and lw > 0 else "none", width=lw * PX_PER_PT, z=z)
        return
    if isinstance(a, Text):
        if not a.get_text():
            return
        if isinstance(a, Annotation):
            if a.xycoords != "data":
                return
            xy = np.asarray(a.xy, float)
            off = np.asarray(a.get_position(), float) if a.anncoords == "offset points" else None
            dx, dy = (off * PX_PER_PT) if off is not None else (0.0, 0.0)
        else:
            xy = data.inverted().transform(a.get_transform().transform(a.get_position()))
            dx = dy = 0.0
        pic.text(eid, xy, a.get_text(), color=_hex(a.get_color()), ha=a.get_horizontalalignment(),
                 va=a.get_verticalalignment(), dx=float(dx), dy=float(dy), z=z)
        return
    if type(a).get_children is not Artist.get_children:
        for j, c in enumerate(a.get_children()):
            _add_artist(pic, c, f"{eid}.{j}", ax, explain)
