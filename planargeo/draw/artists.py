"""Matplotlib artists for homogeneous points, lines and conics.

Each artist holds one homogeneous array in the package's coordinates (a point
``[y, -x, 1]`` is a twist, a line ``[fx, fy, tz]`` is a wrench, a symmetric
``(3, 3)`` matrix is a conic or an inertia).  The geometry (clipping against
the current view, glyph placement) is computed when the figure is drawn, with a
fixed set of child primitives.  The gallery's figures draw with these artists;
the explorers draw pictures (:mod:`planargeo.draw.picture`) instead.

* :class:`PointArtist`: a twist's pole with a rotation glyph (counter-clockwise
  or clockwise arc arrow, radius growing with ``|ω|``); an ideal point (a
  translation) becomes an arrow at the edge of the view, placed in the
  direction in which the point lies and pointing along the translation.
* :class:`LineArtist`: a wrench's line of action, infinite and clipped to the
  view at draw time, with an arrow showing the force's sense and magnitude;
  the line at infinity (a pure couple) is a labelled couple glyph in a corner.
* :class:`ConicArtist`: ellipses, hyperbolas (both branches), parabolas as a
  fixed unit path under an affine transform; degenerate conics as their real
  lines; an imaginary conic (an inertia) by the package convention: the
  sign-flipped real conic (for an inertia the radius-of-gyration circle about
  the centre of mass), dashed, with its centre marked.
"""
from __future__ import annotations

import math

import numpy as np
from matplotlib import artist as martist
from matplotlib import cbook
from matplotlib import colors as mcolors
from matplotlib.backends.backend_agg import RendererAgg
from matplotlib.lines import Line2D
from matplotlib.markers import MarkerStyle
from matplotlib.patches import FancyArrowPatch, Polygon
from matplotlib.path import Path
from matplotlib.text import Text
from matplotlib.transforms import Affine2D, IdentityTransform

from planargeo.errors import InputError
from planargeo.draw.geometry import _mat, _vec, clip_line, conic_geometry, euclidean_conic, point_xy
from planargeo.draw.style import LABEL_PT, get_ax, style as _style

__all__ = [
    "PointArtist", "LineArtist", "ConicArtist",
    "point_xy", "clip_line", "conic_geometry", "euclidean_conic",
    "plot_point", "plot_line", "plot_conic",
]

#: A finite pole farther than FAR view diagonals from the view is drawn like an ideal point
#: (direction arrow at the edge): its weight is zero up to rounding.
FAR = 1e6



# --------------------------------------------------------------------------- helpers
def _pyxy(xy):
    """Plain Python floats (numpy scalars trip a Matplotlib 3.10 mathtext deprecation)."""
    return (float(xy[0]), float(xy[1]))


def _view(ax):
    (x0, y0), (x1, y1) = ax.viewLim.get_points()
    return (min(x0, x1), max(x0, x1), min(y0, y1), max(y0, y1))


def _arc_glyph(center, radius, ccw: bool, npts: int = 40, pts: float = 1.0):
    """Display-space arc (270°) and arrowhead triangle for a rotation glyph.

    ``pts`` is the renderer's pixels per point (the head is 3-6 points long).
    """
    a0, span = np.deg2rad(-45.0), np.deg2rad(270.0)
    t = np.linspace(a0, a0 + span, npts) if ccw else np.linspace(a0 + span, a0, npts)
    arc = center + radius * np.column_stack([np.cos(t), np.sin(t)])
    end, te = arc[-1], t[-1]
    tang = np.array([-np.sin(te), np.cos(te)]) * (1.0 if ccw else -1.0)
    norm = np.array([np.cos(te), np.sin(te)])
    h = min(max(3.0 * pts, 0.45 * radius), 6.0 * pts)
    head = np.array([end + tang * h, end - 0.5 * h * norm, end + 0.5 * h * norm])
    return arc, head


# --------------------------------------------------------------------------- fast drawing
_IDENTITY = IdentityTransform()
_NO_MARKER = {"None", "none", None, " ", ""}
_NO_LINE = {"None", "none", " ", ""}


def _gc(renderer, clip, rgba, linewidth, dashes=(0, None), cap="butt", join="round"):
    gc = renderer.new_gc()
    gc.set_clip_rectangle(clip)
    gc.set_foreground(rgba, isRGBA=True)
    gc.set_linewidth(linewidth)
    gc.set_dashes(*dashes)
    gc.set_capstyle(cap)
    gc.set_joinstyle(join)
    return gc


def _to_display(c, xy):
    """``xy`` (n, 2) in ``c``'s coordinates to display pixels (an affine transform: one product)."""
    tr = c.get_transform()
    if isinstance(tr, IdentityTransform):
        return xy
    if tr.is_affine:
        m = tr.get_matrix()
        return xy @ m[:2, :2].T + m[:2, 2]
    return tr.transform(xy)


def _draw_primitive(c, renderer, clip):
    """Draw one child primitive straight through ``renderer`` (what its ``draw`` would draw).

    The children of this module's artists are plain polylines, markers, filled
    triangles and straight arrows whose style never changes between frames; drawing
    them here skips Matplotlib's per-artist bookkeeping (path caches, transform
    trees, property lookups), which is most of the cost of a frame with a hundred
    artists.  Anything else is drawn by its own ``draw``.
    """
    kind = type(c)
    if kind is Line2D:
        _draw_line2d(c, renderer, clip)
    elif kind is Polygon:
        xy = _to_display(c, np.asarray(c.get_xy(), dtype=float))
        rgba = mcolors.to_rgba(c.get_facecolor(), c.get_alpha())
        gc = _gc(renderer, clip, rgba, 0.0)
        renderer.draw_path(gc, Path(xy), _IDENTITY, rgba)
        gc.restore()
    elif kind is FancyArrowPatch and c._posA_posB is not None:
        _draw_arrow(c, renderer, clip)
    else:
        c.draw(renderer)


def _draw_line2d(c, renderer, clip):
    x, y = c.get_data()
    n = len(x)
    if n == 0:
        return
    xy = np.empty((n, 2))
    xy[:, 0] = x
    xy[:, 1] = y
    xy = _to_display(c, xy)
    alpha = c.get_alpha()
    if c.get_linestyle() not in _NO_LINE:
        dashed = c.is_dashed()
        gc = _gc(renderer, clip, mcolors.to_rgba(c.get_color(), alpha),
                 c.get_linewidth(), c._dash_pattern,
                 c.get_dash_capstyle() if dashed else c.get_solid_capstyle(),
                 c.get_dash_joinstyle() if dashed else c.get_solid_joinstyle())
        renderer.draw_path(gc, Path(xy, _interpolation_steps=1), _IDENTITY)
        gc.restore()
    if c.get_marker() not in _NO_MARKER and c.get_markersize() > 0:
        m = _marker_style(c.get_marker())
        gc = _gc(renderer, clip, mcolors.to_rgba(c.get_markeredgecolor(), alpha),
                 c.get_markeredgewidth(), cap=m.get_capstyle(), join=m.get_joinstyle())
        trans = _marker_transform(m, renderer.points_to_pixels(c.get_markersize()))
        face = c.get_markerfacecolor()
        renderer.draw_markers(gc, m.get_path(), trans, Path(xy), _IDENTITY,
                              None if face in ("none", "None") else mcolors.to_rgba(face, alpha))
        gc.restore()


#: marker styles and their transforms at a size (pixels), made once
_MARKERS: dict = {}
_MARKER_TRANSFORMS: dict = {}


def _marker_style(marker):
    if marker not in _MARKERS:
        _MARKERS[marker] = MarkerStyle(marker)
    return _MARKERS[marker]


def _marker_transform(m, size_px):
    key = (id(m), size_px)            # the styles live in _MARKERS: their ids are stable
    if key not in _MARKER_TRANSFORMS:
        _MARKER_TRANSFORMS[key] = m.get_transform().frozen().scale(size_px)
    return _MARKER_TRANSFORMS[key]


#: (text, font, alignment, dpi) -> baseline start of a one-line label relative to its position
#: (display pixels) and whether it is mathtext: a label's layout is worked out once
_TEXT_LAYOUT: dict = {}


def _draw_text(t, renderer):
    """Draw a label: with Agg, the glyphs at the baseline its layout gives (cached), else ``t.draw``.

    What is drawn is what :meth:`matplotlib.text.Text.draw` draws for a
    one-line, unrotated label without a box; the layout (alignment offsets,
    mathtext or not) is computed once per text, font, alignment and dpi.
    Any other text is drawn by ``t.draw``.
    """
    s = t.get_text()
    if not s:
        return
    if (not isinstance(renderer, RendererAgg) or t.get_rotation() != 0.0 or "\n" in s
            or t.get_wrap() or t.get_usetex() or t.get_bbox_patch() is not None
            or t.get_path_effects()):
        t.draw(renderer)
        return
    prop = t.get_fontproperties()
    key = (s, hash(prop), t.get_horizontalalignment(), t.get_verticalalignment(), renderer.dpi)
    lay = _TEXT_LAYOUT.get(key)
    if lay is None:
        try:
            _, info, _ = t._get_layout(renderer)
            (_line, _wh, dx, dy), = info
        except Exception:  # noqa: BLE001 - any surprise: Matplotlib draws it
            t.draw(renderer)
            return
        lay = _TEXT_LAYOUT[key] = (dx, dy, bool(cbook.is_math_text(s)))
    x, y = t.get_transform().transform(t.get_position())
    gc = renderer.new_gc()
    gc.set_foreground(t.get_color())
    gc.set_alpha(t.get_alpha())
    gc.set_antialiased(t.get_antialiased())
    text = s if lay[2] else s.replace(r"\$", "$")
    renderer.draw_text(gc, x + lay[0], renderer.height - (y + lay[1]), text, prop, 0.0,
                       ismath=lay[2], mtext=t)
    gc.restore()


def _draw_arrow(c, renderer, clip):
    """A straight ``-|>`` arrow: the shaft and a filled head 0.4 × 0.4 mutation scales."""
    (a, b) = c.get_transform().transform(np.asarray(c._posA_posB, dtype=float))
    d = b - a
    n = float(np.hypot(*d))
    if not n > 0.0:
        return
    u = d / n
    ms = c.get_mutation_scale() * renderer.points_to_pixels(1.0)
    hl, hw = min(0.4 * ms, 0.8 * n), 0.2 * ms
    lw = c.get_linewidth()
    rgba = mcolors.to_rgba(c.get_edgecolor(), c.get_alpha())
    base = b - u * hl
    gc = _gc(renderer, clip, rgba, lw, c._dash_pattern, "butt", "miter")
    renderer.draw_path(gc, Path(np.array([a, base + u * 0.5])), _IDENTITY)
    gc.restore()
    v = np.array([-u[1], u[0]])
    gc = _gc(renderer, clip, rgba, lw, cap="butt", join="miter")
    renderer.draw_path(gc, Path(np.array([b, base + v * hw, base - v * hw, b]), closed=True),
                       _IDENTITY, rgba)
    gc.restore()


class _Base(martist.Artist):
    """Common plumbing: fixed children drawn in data or display space."""

    #: label offset (dx, dy) in points used when ``text_offset`` is None
    default_text_offset = (8.0, 8.0)

    def __init__(self, text=None, text_offset=None, zorder=3):
        super().__init__()
        if text_offset is None:
            text_offset = self.default_text_offset
        self.set_zorder(zorder)
        self.set_in_layout(False)
        self._children = []
        self._text = Text(0, 0, "" if text is None else str(text), fontsize=LABEL_PT, va="bottom")
        self._text.set_transform(IdentityTransform())
        self._text_offset = np.asarray(text_offset, dtype=float)
        self._ha, self._va = "left", "bottom"
        self._add_child(self._text)

    def set(self, **kwargs):
        """Set several properties at once, as :meth:`matplotlib.artist.Artist.set` does.

        Parameters
        ----------
        **kwargs
            ``property=value`` for each ``set_property`` method (e.g. ``visible=False``).

        Returns
        -------
        list
            What each setter returned.
        """
        return martist.Artist.set(self, **kwargs)

    def _add_child(self, child):
        self._children.append(child)
        return child

    def get_children(self):
        return list(self._children)

    def _add_arc_glyph(self, linewidth):
        """Children ``_arc``, ``_head``: a rotation's arc arrow (:func:`_arc_glyph`), display space."""
        self._arc = self._add_child(Line2D([0, 0], [0, 0], color=self._color, linewidth=linewidth))
        self._arc.set_transform(IdentityTransform())
        self._head = self._add_child(Polygon(np.zeros((3, 2)), closed=True, color=self._color,
                                             linewidth=0))
        self._head.set_transform(IdentityTransform())

    def set_text_offset(self, offset):
        """Offset (dx, dy) in points of the label from its reference point (None: the default)."""
        if hasattr(self, "_auto_offset"):
            self._auto_offset = offset is None
            offset = (0.0, 0.0) if offset is None else offset
        elif offset is None:
            offset = self.default_text_offset
        self._text_offset = np.asarray(offset, dtype=float)
        self.stale = True

    def set_text_alignment(self, ha="left", va="bottom"):
        """Alignment of the label at its offset point (e.g. ``ha="right"`` for a label on the left)."""
        self._ha, self._va = ha, va
        self._text.set_horizontalalignment(ha)
        self._text.set_verticalalignment(va)
        self.stale = True

    def set_text_beside(self, u, gap=5.0):
        """The label ``gap`` points from its reference point along the unit vector ``u``.

        It is aligned to extend away from that point along ``u`` (e.g. ``u = (0, -1)``: below,
        top-aligned), so that it stays clear of whatever lies the other way.
        """
        self.set_text_offset(gap * np.asarray(u, dtype=float))
        self.set_text_alignment("left" if u[0] > 0.35 else "right" if u[0] < -0.35 else "center",
                                "bottom" if u[1] > 0.35 else "top" if u[1] < -0.35 else "center")

    def set_figure(self, fig):
        super().set_figure(fig)
        for c in self._children:
            c.set_figure(fig)

    def _prepare_children(self):
        ax = self.axes
        if getattr(self, "_prepared_for", None) is ax:
            return
        for c in self._children:
            if c.axes is None and not isinstance(c, Text):
                c.axes = ax
            if c.get_clip_path() is None and ax is not None and not isinstance(c, Text):
                c.set_clip_path(ax.patch)
            c.set_alpha(self.get_alpha())
        self._on_axes(ax)
        self._prepared_for = ax

    def _on_axes(self, ax):
        """Set data-space transforms once, when the artist meets its axes."""

    def _draw_children(self, renderer, children):
        clip = self.axes.bbox
        for c in children:
            if not c.get_visible():
                continue
            if isinstance(c, Text):
                x, y = c.get_position()
                if abs(x) < 1e7 and abs(y) < 1e7:  # far off the canvas: nothing to show
                    _draw_text(c, renderer)
            else:
                _draw_primitive(c, renderer, clip)

    @martist.allow_rasterization
    def draw(self, renderer):
        if not self.get_visible() or self.axes is None:
            self.stale = False
            return
        self._prepare_children()
        drawn = self._update_geometry(renderer)
        renderer.open_group(type(self).__name__, gid=self.get_gid())
        self._draw_children(renderer, drawn)
        renderer.close_group(type(self).__name__)
        self.stale = False

    def _place_text(self, anchor_disp, renderer):
        if not self._text.get_text():
            return []
        off = self._text_offset * renderer.points_to_pixels(1.0)
        self._text.set_position(_pyxy(np.asarray(anchor_disp) + off))
        return [self._text]

# --------------------------------------------------------------------------- points
class PointArtist(_Base):
    """A homogeneous point (a twist's pole) with a rotation glyph.

    Parameters
    ----------
    point : array_like (3,) or object with ``.array``
        ``[vx, vy, w]``; the pole is ``(-vy/w, vx/w)`` (thesis 4.10).
    role : {"twist", "accel"}
        Style role (colour), see :mod:`planargeo.draw.style`.
    glyph_scale : float
        Radius of the rotation arc in points per unit ``|w|`` (clamped to
        [4, 16] points).  For an ideal point, arrow length in points per unit
        speed (clamped to [12, 40]).
    glyph : bool
        Draw the rotation / translation glyph (the marker alone otherwise).
    text : str, optional
        Label drawn next to the pole.
    text_offset : (dx, dy) points, optional
        Label offset from the pole; default: clear of the glyph, up and right.
    marker, markersize : optional
        Override the role's marker (e.g. :data:`planargeo.draw.style.SUM` for a sum).

    color : color, optional
        Override the role's colour.
    zorder : float
        Drawing order.
    """

    def __init__(self, point, *, role="twist", glyph_scale=6.0, glyph=True, text=None,
                 text_offset=None, color=None, marker=None, markersize=None, zorder=7):
        super().__init__(text, (0.0, 0.0) if text_offset is None else text_offset, zorder)
        self._auto_offset = text_offset is None
        st = _style(role)
        self._color = color or st["color"]
        self._p = _vec(point, "point")
        self._glyph_scale = float(glyph_scale)
        self._glyph = bool(glyph)
        self._marker = self._add_child(Line2D([0], [0], marker=marker or st["marker"], linestyle="none",
                                              markersize=markersize or st["markersize"],
                                              color=self._color, markeredgecolor="white",
                                              markeredgewidth=0.6))
        self._add_arc_glyph(1.0)
        self._arrow = self._add_child(FancyArrowPatch((0, 0), (1, 1), arrowstyle="-|>",
                                                      mutation_scale=9, color=self._color,
                                                      linewidth=1.4, shrinkA=0, shrinkB=0,
                                                      transform=IdentityTransform()))
        self._inf = self._add_child(Text(0, 0, "∞", color=self._color, fontsize=LABEL_PT,
                                         ha="center", va="center"))
        self._inf.set_transform(IdentityTransform())
        self._text.set_color(self._color)

    def _on_axes(self, ax):
        self._marker.set_transform(ax.transData)

    # API
    def get_point(self) -> np.ndarray:
        """The stored homogeneous point.

        Returns
        -------
        numpy.ndarray
        """
        return self._p.copy()

    def get_xy(self):
        """Euclidean pole, or None for an ideal point.

        Returns
        -------
        numpy.ndarray or None
        """
        return point_xy(self._p)

    def _update_geometry(self, renderer):
        ax = self.axes
        p = self._p
        if not np.any(p):
            return []
        pts = renderer.points_to_pixels(1.0)
        out = []
        xy = None
        if p[2] != 0.0:
            # far beyond the view (FAR view diagonals): drawn like an ideal point.  Tested as
            # |w (pole - centre)| > FAR diag |w|, before any division by w (which may overflow).
            box = _view(ax)
            diag = np.hypot(box[1] - box[0], box[3] - box[2])
            c = np.array([(box[0] + box[1]) / 2, (box[2] + box[3]) / 2])
            with np.errstate(over="ignore"):
                off = np.hypot(-p[1] - c[0] * p[2], p[0] - c[1] * p[2])
                near = off <= FAR * diag * abs(p[2])
            if near:
                xy = point_xy(p)
        if xy is not None:
            disp = ax.transData.transform(xy)
            bb = ax.bbox
            if not (bb.x0 - 1 <= disp[0] <= bb.x1 + 1 and bb.y0 - 1 <= disp[1] <= bb.y1 + 1):
                # outside the view: an arrow at the edge pointing to it, labelled inside
                cd = np.array([(bb.x0 + bb.x1) / 2, (bb.y0 + bb.y1) / 2])
                n = disp - cd
                n /= np.hypot(*n)
                return self._edge_arrow(n, n, 16.0 * pts, pts, renderer, infinite=False)
            self._marker.set_data([xy[0]], [xy[1]])
            out.append(self._marker)
            if self._glyph:
                r = float(np.clip(self._glyph_scale * abs(p[2]), 4.0, 16.0)) * pts
                arc, head = _arc_glyph(disp, r, ccw=p[2] > 0, pts=pts)
                self._arc.set_data(arc[:, 0], arc[:, 1])
                self._head.set_xy(head)
                out += [self._arc, self._head]
            self._text.set_horizontalalignment(self._ha)
            self._text.set_verticalalignment(self._va)
            if self._auto_offset:
                rr = float(np.clip(self._glyph_scale * abs(p[2]), 4.0, 16.0)) if self._glyph else 2.0
                self._text_offset = np.array([0.75 * rr + 3.0, 0.75 * rr + 3.0])
            out += self._place_text(disp, renderer)
            return out
        # ideal point: translation velocity (a, b); the point lies in direction (-b, a)
        a, b = float(p[0]), float(p[1])
        lin = ax.transData.get_affine().get_matrix()[:2, :2]
        bb = ax.bbox
        cd = np.array([(bb.x0 + bb.x1) / 2, (bb.y0 + bb.y1) / 2])
        n = lin @ np.array([-b, a])
        if p[2] < 0.0:  # a far finite pole with negative weight lies the other way
            n = -n
        n /= np.hypot(*n)
        t = lin @ np.array([a, b])  # display direction of the velocity (a, b)
        t /= np.hypot(*t)
        L = float(np.clip(self._glyph_scale * np.hypot(a, b), 12.0, 40.0)) * pts
        return self._edge_arrow(n, t, L, pts, renderer, infinite=True)

    def _edge_arrow(self, n, t, L, pts, renderer, *, infinite):
        """An arrow (along ``t``, ``L`` px long) at the view's edge in direction ``n``, labelled.

        ``infinite``: an ideal point (marked ∞); else a finite point outside the view.
        """
        bb = self.axes.bbox
        cd = np.array([(bb.x0 + bb.x1) / 2, (bb.y0 + bb.y1) / 2])
        half = np.array([bb.width, bb.height]) / 2
        s = min(half[k] / abs(n[k]) for k in range(2) if abs(n[k]) > 1e-12)  # a unit vector: one is ≥ 0.7
        base = cd + n * (s - 14 * pts)
        out = []
        self._arrow.set_positions(tuple(base - t * L / 2), tuple(base + t * L / 2))
        out.append(self._arrow)
        if infinite:
            self._inf.set_position(_pyxy(base - t * (L / 2 + 7 * pts)))
            self._inf.set_horizontalalignment("center")
            self._inf.set_verticalalignment("center")
            out.append(self._inf)
        if self._text.get_text() and not self._auto_offset:  # as asked, from the arrow's middle
            self._text.set_position(_pyxy(base + self._text_offset * pts))
            self._text.set_horizontalalignment(self._ha)
            self._text.set_verticalalignment(self._va)
            out.append(self._text)
        elif self._text.get_text():
            # inside the view from the arrow, aligned so that it extends away from the edge
            self._text.set_position(_pyxy(base - n * 16 * pts))
            self._text.set_horizontalalignment(
                "right" if n[0] > 0.5 else "left" if n[0] < -0.5 else "center")
            self._text.set_verticalalignment(
                "top" if n[1] > 0.5 else "bottom" if n[1] < -0.5 else "center")
            out.append(self._text)
        return out


# --------------------------------------------------------------------------- lines
class LineArtist(_Base):
    """A homogeneous line (a wrench's line of action), clipped to the view.

    Parameters
    ----------
    line : array_like (3,) or object with ``.array``
        ``[fx, fy, tz]``: the points with ``tz + y fx - x fy = 0`` (4.27).
    role : {"wrench", "reaction", "momentum", "construct"}
        Style role.
    scale : float or None
        Force arrow length in data units per unit force; None draws no arrow.
    anchor : (x, y), optional
        Where along the line to put the arrow (projected onto the line);
        default: the foot of the perpendicular from the view centre.
    corner : str
        Corner for the couple glyph of the line at infinity
        ("upper right", "upper left", "lower right", "lower left").
    couple_scale : float
        Couple glyph radius in points per unit moment (clamped to [5, 18]).
    text_offset : (dx, dy) points, optional
        Label offset; None: :attr:`default_text_offset` ``(6, 6)``.
    text_at : {"tip", "anchor"}
        Where the label's ``text_offset`` (points) starts: the arrow's tip
        (default) or its middle, the anchor (a label beside the arrow, which
        stays in view whenever the arrow's middle does).

    text : str, optional
        Label drawn next to the arrow (or the line).
    color, linewidth, linestyle : optional
        Override the role's style.
    zorder : float
        Drawing order.

    Raises
    ------
    InputError
        An unknown role or ``text_at``, or a line that is not three finite numbers.
    """

    default_text_offset = (6.0, 6.0)

    def __init__(self, line, *, role="wrench", scale=1.0, anchor=None, text=None,
                 text_offset=None, corner="upper right", couple_scale=8.0,
                 color=None, linewidth=None, linestyle=None, zorder=3, text_at="tip"):
        super().__init__(text, text_offset, zorder)
        st = _style(role)
        self._color = color or st["color"]
        self._l = _vec(line, "line")
        self._scale = None if scale is None else float(scale)
        self._anchor = None if anchor is None else np.asarray(anchor, dtype=float)
        self._corner = corner
        if text_at not in ("tip", "anchor"):
            raise InputError(f"text_at must be 'tip' or 'anchor', got {text_at!r}")
        self._text_at = text_at
        self._couple_scale = float(couple_scale)
        self._line = self._add_child(Line2D([0, 0], [0, 0], color=self._color,
                                            linewidth=linewidth or st["linewidth"],
                                            linestyle=linestyle or st["linestyle"]))
        self._arrow = self._add_child(FancyArrowPatch((0, 0), (1, 1), arrowstyle="-|>",
                                                      mutation_scale=10, color=self._color,
                                                      linewidth=2.0, shrinkA=0, shrinkB=0))
        self._add_arc_glyph(1.4)
        self._edge = self._add_child(FancyArrowPatch((0, 0), (1, 1), arrowstyle="-|>",
                                                     mutation_scale=9, color=self._color,
                                                     linewidth=1.4, shrinkA=0, shrinkB=0,
                                                     linestyle="--", transform=IdentityTransform()))
        self._text.set_color(self._color)

    def _on_axes(self, ax):
        self._line.set_transform(ax.transData)
        self._arrow.set_transform(ax.transData)

    def set_anchor(self, anchor):
        """Where along the line the arrow sits (projected onto the line); None: view centre.

        Parameters
        ----------
        anchor : (float, float) or None
        """
        self._anchor = None if anchor is None else np.asarray(anchor, dtype=float)
        self.stale = True

    def get_line(self) -> np.ndarray:
        """The stored homogeneous line.

        Returns
        -------
        numpy.ndarray
        """
        return self._l.copy()

    def get_arrow(self):
        """The force arrow's ``(tail, tip)`` in data coordinates, or None.

        None when no arrow is drawn (``scale`` None, the line at infinity) or
        when it sits at the view centre's foot (no ``anchor``: known only at draw
        time).  With an anchor it needs no axes, so a figure can fit its view to
        the arrow ends before drawing.

        Returns
        -------
        tuple of numpy.ndarray or None
            ``(tail, tip)``.
        """
        fx, fy, _ = self._l
        if self._scale is None or self._anchor is None or (fx == 0.0 and fy == 0.0):
            return None
        _, tail, tip = self._arrow_at(self._anchor)
        return tail, tip

    def _arrow_at(self, near):
        """``(anchor, tail, tip)``: the foot of ``near`` on the (finite) line and the arrow about it.

        The arrow is ``scale |f|`` long along the force ``(fx, fy)``, centred on
        the anchor; without a scale ``tail`` and ``tip`` are the anchor.
        """
        fx, fy, tz = (float(v) for v in self._l)
        s = max(abs(fx), abs(fy))                         # the same line, scaled: no under/overflow
        ux, uy, uz = fx / s, fy / s, tz / s
        G = math.hypot(ux, uy)                            # |f| / s, in [1, √2]
        e = np.array([ux, uy]) / G
        p0 = np.array([uy * uz, -ux * uz]) / (G * G)      # foot of the origin (4.27)
        anchor = p0 + e * ((np.asarray(near, dtype=float) - p0) @ e)
        if self._scale is None:
            return anchor, anchor, anchor
        half = (0.5 * self._scale * s) * G * e            # |f| = s G
        return anchor, anchor - half, anchor + half

    def get_segment(self):
        """The clipped endpoints ``(2, 2)`` in the current view (None if not visible).

        Returns
        -------
        numpy.ndarray or None
        """
        if self.axes is None:
            return None
        return clip_line(self._l, _view(self.axes))

    def _update_geometry(self, renderer):
        ax = self.axes
        fx, fy, tz = self._l
        pts = renderer.points_to_pixels(1.0)
        out = []
        if fx == 0.0 and fy == 0.0:
            if tz == 0.0:
                return []
            # the line at infinity: a pure couple, drawn as a curved arrow in a corner
            bb = ax.bbox
            r = float(np.clip(self._couple_scale * abs(tz), 5.0, 18.0)) * pts
            m = 10 * pts + r
            vert, horiz = self._corner.split()
            cx = bb.x1 - m if horiz == "right" else bb.x0 + m
            cy = bb.y1 - m if vert == "upper" else bb.y0 + m
            arc, head = _arc_glyph(np.array([cx, cy]), r, ccw=tz > 0, pts=pts)
            self._arc.set_data(arc[:, 0], arc[:, 1])
            self._head.set_xy(head)
            out += [self._arc, self._head]
            if self._text.get_text():
                right = horiz == "right"
                self._text.set_position(_pyxy((cx - r - 4 * pts, cy) if right else (cx + r + 4 * pts, cy)))
                self._text.set_horizontalalignment("right" if right else "left")
                self._text.set_verticalalignment("center")
                out.append(self._text)
            return out
        seg = clip_line(self._l, _view(ax))
        if seg is None:
            return self._off_view(renderer, pts)
        self._line.set_data(seg[:, 0], seg[:, 1])
        out.append(self._line)
        near = self._anchor
        if near is None:
            box = _view(ax)
            near = ((box[0] + box[1]) / 2, (box[2] + box[3]) / 2)
        anchor, tail, tip = self._arrow_at(near)
        if self._scale is not None:
            self._arrow.set_positions(tuple(tail), tuple(tip))
            out.append(self._arrow)
        at = anchor if self._text_at == "anchor" else tip
        out += self._place_text(ax.transData.transform(at), renderer)
        return out

    def _off_view(self, renderer, pts):
        """A line that misses the view: a dashed arrow at the edge pointing to it, labelled."""
        ax = self.axes
        fx, fy, tz = self._l
        box = _view(ax)
        c = np.array([(box[0] + box[1]) / 2, (box[2] + box[3]) / 2])
        sc = max(abs(fx), abs(fy))                        # the same line, scaled: no under/overflow
        fx, fy, tz = fx / sc, fy / sc, tz / sc
        F2 = fx * fx + fy * fy                            # in [1, 2]
        # foot of the perpendicular from the view centre on the line tz + y fx - x fy = 0
        dist = (tz + c[1] * fx - c[0] * fy) / F2
        foot = c - dist * np.array([-fy, fx])
        if not np.all(np.isfinite(foot)):
            return []
        bb = ax.bbox
        cd = np.array([(bb.x0 + bb.x1) / 2, (bb.y0 + bb.y1) / 2])
        with np.errstate(over="ignore", invalid="ignore"):
            n = ax.transData.transform(foot) - cd
        if not np.all(np.isfinite(n)) or not np.any(n):
            return []
        n /= np.hypot(*n)
        half = np.array([bb.width, bb.height]) / 2
        s = min(half[k] / abs(n[k]) for k in range(2) if abs(n[k]) > 1e-12)  # a unit vector: one is ≥ 0.7
        base = cd + n * (s - 12 * pts)
        L = 16 * pts
        self._edge.set_positions(tuple(base - n * L / 2), tuple(base + n * L / 2))
        out = [self._edge]
        if self._text.get_text():
            self._text.set_position(_pyxy(base - n * (L / 2 + 3 * pts)))
            self._text.set_horizontalalignment(
                "right" if n[0] > 0.5 else "left" if n[0] < -0.5 else "center")
            self._text.set_verticalalignment(
                "top" if n[1] > 0.5 else "bottom" if n[1] < -0.5 else "center")
            out.append(self._text)
        return out


# --------------------------------------------------------------------------- conics
def _unit_paths():
    t = np.linspace(0.0, 2 * np.pi, 181)
    circle = Path(np.column_stack([np.cos(t), np.sin(t)]))
    s = np.linspace(-7.0, 7.0, 481)
    br = np.column_stack([np.cosh(s), np.sinh(s)])
    verts = np.vstack([br, br * [-1.0, 1.0]])
    codes = np.full(len(verts), Path.LINETO, dtype=np.uint8)
    codes[0] = codes[len(br)] = Path.MOVETO
    hyperbola = Path(verts, codes)
    x = np.sinh(s)
    parabola = Path(np.column_stack([x, x * x]))
    return {"ellipse": circle, "hyperbola": hyperbola, "parabola": parabola}


UNIT_PATHS = _unit_paths()


class ConicArtist(_Base):
    """A conic drawn as a fixed unit path under an affine transform.

    An update recomputes only the affine matrix (or, for degenerate conics,
    the lines, which are clipped at draw time).  A conic without real points
    (positive definite, e.g. an inertia) is drawn by the package convention:
    the sign-flipped real conic, dashed, with its centre marked; for an
    inertia ``inertia_matrix(m, c, J)`` this is the radius-of-gyration circle
    about the centre of mass.

    Parameters
    ----------
    conic : array_like (3, 3) or object with ``.matrix`` / ``.array``
    role : {"conic", "inertia", "construct"}
    mark_center : bool
        Mark the centre (always for imaginary conics).

    text : str, optional
        Label drawn at the curve.
    text_offset : (dx, dy) points, optional
        Label offset (default ``(6, -10)``).
    color, linewidth : optional
        Override the role's style.
    zorder : float
        Drawing order.
    """

    default_text_offset = (6.0, -10.0)

    def __init__(self, conic, *, role="conic", mark_center=None, text=None,
                 text_offset=None, color=None, linewidth=None, zorder=2):
        super().__init__(text, text_offset, zorder)
        st = _style(role)
        self._color = color or st["color"]
        self._role = role
        self._mark_center = mark_center
        self._affine = Affine2D()
        self._curve = self._add_child(Line2D([], [], color=self._color,
                                             linewidth=linewidth or st["linewidth"],
                                             linestyle=st["linestyle"]))
        self._lines = [self._add_child(Line2D([0, 0], [0, 0], color=self._color,
                                              linewidth=linewidth or st["linewidth"],
                                              linestyle=st["linestyle"])) for _ in range(2)]
        self._center = self._add_child(Line2D([0], [0], marker="+", markersize=7,
                                              color=self._color, linestyle="none"))
        self._text.set_color(self._color)
        self._geom = None
        self._path_kind = None
        self.set_conic(conic)

    def set_conic(self, conic):
        """Store a new conic and mark the artist stale (the geometry is computed at draw time).

        Only the affine transform (or, for a degenerate conic, the lines) changes;
        the unit path is set once per conic class.

        Parameters
        ----------
        conic : array_like (3, 3) or object with ``.matrix`` / ``.array``
        """
        self._C = _mat(conic, "conic")
        self._geom = None
        self.stale = True

    def _geometry(self) -> dict:
        """Classify the stored conic (cached until the next ``set_conic``)."""
        if self._geom is not None:
            return self._geom
        g = self._geom = conic_geometry(self._C)
        if "affine" in g:
            self._affine.set_matrix(g["affine"])
            if self._path_kind != g["kind"]:  # the fixed unit path of this class
                v = UNIT_PATHS[g["kind"]].vertices
                if g["kind"] == "hyperbola":  # keep the two branches apart: NaN between them
                    n = len(v) // 2
                    v = np.vstack([v[:n], [[np.nan, np.nan]], v[n:]])
                self._curve.set_data(v[:, 0], v[:, 1])
                self._path_kind = g["kind"]
        dashed = self._role == "inertia" or g.get("imaginary")
        self._curve.set_linestyle(_style("inertia" if dashed else self._role)["linestyle"])
        return g

    def _on_axes(self, ax):
        self._curve.set_transform(self._affine + ax.transData)
        self._center.set_transform(ax.transData)
        for art in self._lines:
            art.set_transform(ax.transData)

    @property
    def kind(self) -> str:
        """Conic class drawn: ellipse, hyperbola, parabola, lines, point or empty."""
        return self._geometry()["kind"]

    @property
    def imaginary(self) -> bool:
        """True when the conic has no real points and its sign-flipped partner is drawn."""
        return bool(self._geometry().get("imaginary"))

    def get_xy(self) -> np.ndarray:
        """Euclidean points of the drawn curve (data coordinates, NaN between branches).

        Returns
        -------
        numpy.ndarray
            ``(n, 2)``.
        """
        g = self._geometry()
        if "affine" not in g:
            return np.zeros((0, 2))
        x, y = self._curve.get_data()
        return self._affine.transform(np.column_stack([x, y]))

    def _update_geometry(self, renderer):
        ax = self.axes
        g = self._geometry()
        out = []
        if "affine" in g:
            out.append(self._curve)
            anchor = g["affine"][:2, 2]
            mark = self._mark_center if self._mark_center is not None else (
                g.get("imaginary") or self._role == "inertia")
            if mark and g["kind"] != "parabola":
                self._center.set_data([anchor[0]], [anchor[1]])
                out.append(self._center)
            top = g["affine"] @ [0.7071, 0.7071, 1.0]
            out += self._place_text(ax.transData.transform(top[:2]), renderer)
        elif g["kind"] == "lines":
            box = _view(ax)
            for ln, art in zip(g["lines"], self._lines):
                seg = clip_line(ln, box)
                if seg is not None:
                    art.set_data(seg[:, 0], seg[:, 1])
                    out.append(art)
        elif g["kind"] == "point":
            self._center.set_data([g["point"][0]], [g["point"][1]])
            out.append(self._center)
        return out


# --------------------------------------------------------------------------- legend
# --------------------------------------------------------------------------- plot functions
def plot_point(point, ax=None, **kw) -> PointArtist:
    """Add a :class:`PointArtist` to ``ax`` (default: current axes) and return it.

    Parameters
    ----------
    point : array_like or planargeo object
        What to draw.
    ax : matplotlib.axes.Axes, optional
        Default: the current axes.
    **kw
        Keyword arguments of :class:`PointArtist`.

    Returns
    -------
    PointArtist
    """
    return get_ax(ax).add_artist(PointArtist(point, **kw))


def plot_line(line, ax=None, **kw) -> LineArtist:
    """Add a :class:`LineArtist` to ``ax`` (default: current axes) and return it.

    Parameters
    ----------
    line : array_like or planargeo object
        What to draw.
    ax : matplotlib.axes.Axes, optional
        Default: the current axes.
    **kw
        Keyword arguments of :class:`LineArtist`.

    Returns
    -------
    LineArtist
    """
    return get_ax(ax).add_artist(LineArtist(line, **kw))


def plot_conic(conic, ax=None, **kw) -> ConicArtist:
    """Add a :class:`ConicArtist` to ``ax`` (default: current axes) and return it.

    Parameters
    ----------
    conic : array_like or planargeo object
        What to draw.
    ax : matplotlib.axes.Axes, optional
        Default: the current axes.
    **kw
        Keyword arguments of :class:`ConicArtist`.

    Returns
    -------
    ConicArtist
    """
    return get_ax(ax).add_artist(ConicArtist(conic, **kw))
