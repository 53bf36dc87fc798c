"""The matplotlib renderer of a :class:`~planargeo.draw.picture.Picture` (exports, stored pictures).

It draws the picture's plain data with no geometry of its own, pixel sizes as points at
100 dpi (:data:`~planargeo.draw.picture.PX_PER_PT`), as the page does.

Examples
--------
>>> from planargeo.draw.picture import Picture
>>> pic = Picture((-1, 1, -1, 1), size=(200, 200))
>>> pic.line("f", [1.0, 0.0, 0.0], symbol="f")
>>> figure(pic.to_dict()).get_size_inches().tolist()
[2.0, 2.0]
"""
from __future__ import annotations

import io

import numpy as np
from matplotlib.figure import Figure
from matplotlib.patches import Polygon
from matplotlib.transforms import offset_copy

from planargeo.draw.geometry import arc_glyph
from planargeo.draw.picture import PX_PER_PT
from planargeo.draw.style import LABEL_PT, TITLE_PT, get_ax, rc_context

__all__ = ["draw_picture", "figure", "picture_bytes"]

_MARKERS = {"o": "o", "D": "D", "s": "s"}
#: Line width of a rotation glyph and of an arrow's shaft, the length of its head (pixels, as the page)
_GLYPH_PX, _ARROW_PX, _HEAD_PX = 1.6, 1.9, 8.0


def draw_picture(pic: dict, ax=None) -> list:
    """Draw the picture ``pic`` (:meth:`Picture.to_dict`) on the axes ``ax``.

    Every artist's ``gid`` is its element's id (``"<id>:label"`` for a label), and fixed pixel
    sizes have the page's geometry (``planargeo/widgets/canvas.js``).  The lines below the
    plot (``pic["below"]``) are texts of the axes' figure, placed in pixels from the axes'
    lower left corner (``gid`` ``"<id>:below"``; not in the list returned).

    Parameters
    ----------
    pic : dict
        A picture's data.
    ax : matplotlib.axes.Axes, optional
        Axes placed on the picture's plot area (default: the current axes).

    Returns
    -------
    list of (str, int, matplotlib.artist.Artist)
        Each drawn artist with its element's id and the index of the part it draws.
    """
    ax = get_ax(ax)
    x0, x1, y0, y1 = pic["box"]
    w, h = pic["size"]
    ml, mr, mt, mb = pic["margin"]
    kx, ky = (w - ml - mr) / (x1 - x0), (h - mt - mb) / (y1 - y0)
    ax.set_xlim(x0, x1)
    ax.set_ylim(y0, y1)
    ax.set_aspect("auto")
    if pic.get("ticks"):
        ax.set_xticks(pic["ticks"]["x"])
        ax.set_yticks(pic["ticks"]["y"])
        ax.tick_params(labelsize=LABEL_PT)
    else:
        ax.set_axis_off()
    if pic.get("title"):
        ax.set_title(pic["title"], fontsize=TITLE_PT)
    drawn = []
    for el in pic["elements"]:
        c, lw, z = el["color"], el["width"] / PX_PER_PT, el["z"]
        op = el.get("opacity", 1.0)
        dashes = None if not el.get("dash") else [v / PX_PER_PT / lw for v in el["dash"]]
        gid = el["id"]

        def head(xy, zorder):
            """A filled triangle (a glyph's or an arrow's head)."""
            return ax.add_patch(Polygon(xy, closed=True, facecolor=c, edgecolor="none",
                                        zorder=zorder, gid=gid, alpha=op))

        for i, part in enumerate(el["parts"]):
            kind = part["p"]
            arts = []
            if kind == "path" and (el.get("fill") or part.get("closed")):
                arts.append(ax.add_patch(Polygon(
                    np.asarray(part["xy"], float).reshape(-1, 2), closed=part.get("closed", False),
                    facecolor=el.get("fill") or "none", edgecolor=c if c != "none" else "none",
                    linewidth=lw, alpha=el.get("alpha", 1.0) * op, zorder=z, gid=gid)))
            elif kind in ("path", "ellipse"):
                if kind == "path":
                    xy = np.asarray(part["xy"], float).reshape(-1, 2)
                    kw = {"solid_capstyle": "butt"}
                else:
                    t = np.linspace(0.0, 2 * np.pi, 97)
                    a, b, cc, d = part["m"]
                    xy = np.column_stack([part["x"] + a * np.cos(t) + b * np.sin(t),
                                          part["y"] + cc * np.cos(t) + d * np.sin(t)])
                    kw = {}
                (ln,) = ax.plot(xy[:, 0], xy[:, 1], color=c, linewidth=lw, zorder=z, gid=gid,
                                alpha=op, **kw)
                arts.append(ln)
                if dashes:
                    ln.set_dashes(dashes)
            elif kind == "mark":
                arts += ax.plot([part["x"]], [part["y"]], linestyle="none",
                                marker=_MARKERS[part["shape"]], markersize=part["size"] / PX_PER_PT,
                                color=c, markeredgecolor="white", markeredgewidth=0.6, zorder=z + 0.5,
                                gid=gid, alpha=op)
            elif kind == "glyph":
                arc, tri = arc_glyph(part["r"], part["ccw"])
                part_xy = np.array([part["x"], part["y"]])
                arts += ax.plot(part["x"] + arc[:, 0] / kx, part["y"] + arc[:, 1] / ky, color=c,
                                linewidth=_GLYPH_PX / PX_PER_PT, zorder=z, gid=gid, alpha=op)
                arts.append(head(part_xy + tri / (kx, ky), z))
            elif kind == "arrow":
                # the page's arrow (pixels, y up): a shaft to 0.8 of the head's length before the
                # tip, and a head max(_HEAD_PX, 4 × the line's width) long and 0.7 of that wide
                dx, dy = float(part["dx"]), float(part["dy"])
                hp = max(_HEAD_PX, 4.0 * el["width"])       # the head grows with its line
                length = float(np.hypot(dx, dy)) or 1.0
                u = np.array([dx, dy]) / length
                nrm = np.array([-u[1], u[0]])
                tip = np.array([dx, dy])
                shaft = np.array([[0.0, 0.0], tip - u * 0.8 * hp])
                tri = np.array([tip, tip - u * hp + nrm * 0.35 * hp,
                                tip - u * hp - nrm * 0.35 * hp])
                to_data = np.array([1.0 / kx, 1.0 / ky])
                arts += ax.plot(part["x"] + shaft[:, 0] * to_data[0],
                                part["y"] + shaft[:, 1] * to_data[1],
                                color=c, linewidth=_ARROW_PX / PX_PER_PT, zorder=z + 0.5, gid=gid,
                                alpha=op, solid_capstyle="butt")
                arts.append(head(np.array([part["x"], part["y"]]) + tri * to_data, z + 0.5))
            elif kind == "text" and not part.get("hidden"):
                arts.append(ax.annotate(
                    part["text"], (part["x"], part["y"]),
                    xytext=(part["dx"] / PX_PER_PT, part["dy"] / PX_PER_PT),
                    textcoords="offset points", ha=part["ha"],
                    va={"center": "center_baseline"}.get(part["va"], part["va"]),
                    fontsize=LABEL_PT, color=c, zorder=z + 1, gid=gid + ":label",
                    annotation_clip=False, alpha=op))
            drawn += [(gid, i, a) for a in arts]
    for b in pic.get("below", ()):      # lines under the plot's tick labels: figure texts, no axes
        at = offset_copy(ax.transAxes, fig=ax.figure, x=b["x"] / PX_PER_PT, y=-b["y"] / PX_PER_PT,
                         units="points")
        ax.figure.text(0.0, 0.0, b["text"], transform=at, ha="left", va="top", fontsize=LABEL_PT,
                       color=b["color"], gid=b["id"] + ":below")
    return drawn


def figure(pic: dict, artists: list | None = None) -> Figure:
    """A new matplotlib figure holding the picture at its pixel size (100 dpi).

    Parameters
    ----------
    pic : dict
        A picture's data (:meth:`Picture.to_dict`).
    artists : list, optional
        If given, the drawn artists are appended to it (as :func:`draw_picture` returns them).

    Returns
    -------
    matplotlib.figure.Figure
    """
    w, h = pic["size"]
    ml, mr, mt, mb = pic["margin"]
    with rc_context():
        fig = Figure(figsize=(w / 100.0, h / 100.0), dpi=100)
        ax = fig.add_axes((ml / w, mb / h, (w - ml - mr) / w, (h - mt - mb) / h))
        drawn = draw_picture(pic, ax)
    if artists is not None:
        artists.extend(drawn)
    return fig


def picture_bytes(pic: dict, format: str = "svg", dpi: float = 100) -> bytes:
    """The picture as SVG or PNG bytes (drawn by matplotlib).

    Parameters
    ----------
    pic : dict
        A picture's data.
    format : {"svg", "png"}
        Output format.
    dpi : float
        Resolution of a PNG (100: the picture's pixel size).

    Returns
    -------
    bytes
    """
    fig = figure(pic)
    buf = io.BytesIO()
    with rc_context():
        fig.savefig(buf, format=format, dpi=dpi)
    return buf.getvalue()
