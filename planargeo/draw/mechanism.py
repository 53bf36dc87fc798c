"""Mechanism drawing: bodies, pins, sliders, ground, frames, internal forces.

Bodies are drawn from their shapely polygons (world frame) or as a default
rounded link between two points.  Internal and contact forces are drawn as
lines (:class:`~planargeo.draw.artists.LineArtist`), with a joint's force
split into its active part (along the percussion space ``T Q``) and its
reaction part (``R μ``) by :func:`draw_joint_split`.
"""
from __future__ import annotations

import numpy as np
from matplotlib.patches import Circle, Polygon, Rectangle

from planargeo.draw.artists import plot_line
from planargeo.draw.style import COLORS, LABEL_PT, LINEWIDTHS, get_ax

__all__ = ["link_polygon", "draw_body", "draw_link", "draw_pin", "draw_ground", "draw_slider",
           "draw_frame", "draw_com", "draw_joint_split", "transform_shape", "draw_contact",
           "slider_guide", "draw_model"]


def link_polygon(p, q, width=0.25):
    """A rounded link (stadium) between Euclidean points ``p`` and ``q`` as a shapely polygon.

    Parameters
    ----------
    p, q : (float, float)
        The link's end points (a single point gives a disc).
    width : float
        Width of the link (the diameter of its rounded ends).

    Returns
    -------
    shapely.geometry.Polygon
    """
    from shapely.geometry import LineString, Point as SPoint

    p, q = tuple(map(float, p)), tuple(map(float, q))
    geom = SPoint(p) if p == q else LineString([p, q])
    return geom.buffer(width / 2, quad_segs=12)


def transform_shape(shape, pose):
    """A shapely shape given in a body frame, moved to world by ``pose = (x, y, θ)``.

    Parameters
    ----------
    shape : shapely geometry
        The shape in the body frame.
    pose : (float, float, float)
        The body frame's origin and angle (radians) in the world.

    Returns
    -------
    shapely geometry
        The shape in world coordinates.
    """
    from shapely import affinity

    x, y, th = (float(v) for v in pose)
    return affinity.translate(affinity.rotate(shape, th, origin=(0, 0), use_radians=True), x, y)


def draw_body(shape, ax=None, *, color=None, alpha=0.35, edgecolor="#1f3a4d", zorder=1, label=None,
              com=None):
    """Fill a shapely polygon (or multipolygon) in world coordinates; returns the patches.

    With ``com`` (x, y) the centre-of-mass symbol (:func:`draw_com`) marks it.

    Parameters
    ----------
    shape : shapely Polygon or MultiPolygon
        The body in world coordinates (holes drawn white).
    ax : matplotlib.axes.Axes, optional
        Axes to draw on (default: the current axes).
    color, edgecolor : color, optional
        Fill (default: the body colour of :mod:`planargeo.draw.style`) and outline colours.
    alpha : float
        Opacity of the fill.
    zorder : float
        Drawing order.
    label : str, optional
        Text drawn at a point inside the shape.
    com : (float, float), optional
        Centre of mass to mark.

    Returns
    -------
    list of matplotlib.artist.Artist
    """
    ax = get_ax(ax)
    geoms = getattr(shape, "geoms", [shape])
    out = []
    for g in geoms:
        xy = np.asarray(g.exterior.coords)
        patch = Polygon(xy, closed=True, facecolor=color or COLORS["body"], alpha=alpha,
                        edgecolor=edgecolor, linewidth=LINEWIDTHS["body"], zorder=zorder)
        ax.add_patch(patch)
        out.append(patch)
        for hole in g.interiors:
            h = Polygon(np.asarray(hole.coords), closed=True, facecolor="white",
                        edgecolor=edgecolor, linewidth=LINEWIDTHS["body"], zorder=zorder)
            ax.add_patch(h)
            out.append(h)
    if label is not None:
        c = shape.representative_point()
        out.append(ax.text(c.x, c.y, label, ha="center", va="center", fontsize=LABEL_PT,
                           color="#1f3a4d", zorder=zorder + 0.5))
    if com is not None:
        out += draw_com(com, ax)
    return out


def draw_link(p, q, ax=None, *, width=0.25, **kw):
    """A default rounded link between two Euclidean points.

    Parameters
    ----------
    p, q : (float, float)
        The link's end points.
    ax : matplotlib.axes.Axes, optional
        Axes to draw on (default: the current axes).
    width : float
        Width of the link.
    **kw
        Options of :func:`draw_body`.

    Returns
    -------
    list of matplotlib.artist.Artist
    """
    return draw_body(link_polygon(p, q, width), ax, **kw)


def draw_pin(xy, ax=None, *, radius=0.06, zorder=6):
    """A revolute joint: white disc with a dark rim.

    Parameters
    ----------
    xy : (float, float)
        The joint.
    ax : matplotlib.axes.Axes, optional
        Axes to draw on (default: the current axes).
    radius : float
        Radius of the disc (data units).
    zorder : float
        Drawing order.

    Returns
    -------
    matplotlib.patches.Circle
    """
    ax = get_ax(ax)
    c = Circle(tuple(map(float, xy)), radius, facecolor="white", edgecolor="#222222",
               linewidth=1.0, zorder=zorder)
    ax.add_patch(c)
    return c


def draw_ground(xy, ax=None, *, width=0.8, angle=0.0, depth=0.12, n=7, zorder=1):
    """A ground line with hatching below it (``angle`` of the line in radians).

    Parameters
    ----------
    xy : (float, float)
        Middle of the ground line.
    ax : matplotlib.axes.Axes, optional
        Axes to draw on (default: the current axes).
    width : float
        Length of the line.
    angle : float
        Direction of the line (radians); the hatching is on its right-hand side.
    depth : float
        Length of the hatching strokes.
    n : int
        Number of hatching strokes.
    zorder : float
        Drawing order.

    Returns
    -------
    list of matplotlib.lines.Line2D
    """
    ax = get_ax(ax)
    xy = np.asarray(xy, float)
    e = np.array([np.cos(angle), np.sin(angle)])
    nrm = np.array([-e[1], e[0]])
    a, b = xy - e * width / 2, xy + e * width / 2
    out = ax.plot(*np.column_stack([a, b]), color=COLORS["ground"], lw=1.2, zorder=zorder)
    for t in np.linspace(0, 1, n):
        s = a + (b - a) * t
        out += ax.plot([s[0], s[0] - (e[0] + nrm[0]) * depth], [s[1], s[1] - (e[1] + nrm[1]) * depth],
                       color=COLORS["ground"], lw=0.7, zorder=zorder)
    return out


def draw_slider(xy, direction, ax=None, *, size=(0.35, 0.2), track=1.6, zorder=3):
    """A prismatic joint: a block on a track along ``direction`` (the track is hatched ground).

    Parameters
    ----------
    xy : (float, float)
        Centre of the block.
    direction : (float, float)
        Direction of sliding.
    ax : matplotlib.axes.Axes, optional
        Axes to draw on (default: the current axes).
    size : (float, float)
        Length and height of the block.
    track : float
        Length of the track.
    zorder : float
        Drawing order of the block.

    Returns
    -------
    list of matplotlib.artist.Artist
    """
    ax = get_ax(ax)
    xy = np.asarray(xy, float)
    d = np.asarray(direction, float)
    ang = np.arctan2(d[1], d[0])
    w, h = size
    out = draw_ground(xy - np.array([-d[1], d[0]]) / np.hypot(*d) * h / 2, ax, width=track,
                      angle=ang)
    rect = Rectangle((-w / 2, -h / 2), w, h, facecolor="#dddddd", edgecolor="#222222", lw=1.0,
                     zorder=zorder)
    from matplotlib.transforms import Affine2D

    rect.set_transform(Affine2D().rotate(ang).translate(*xy) + ax.transData)
    ax.add_patch(rect)
    return out + [rect]


def draw_frame(origin, ax=None, *, angle=0.0, length=0.5, labels=("$x$", "$y$"), color="#222222"):
    """Coordinate axes arrows at ``origin`` rotated by ``angle``.

    Parameters
    ----------
    origin : (float, float)
        Origin of the frame.
    ax : matplotlib.axes.Axes, optional
        Axes to draw on (default: the current axes).
    angle : float
        Direction of the first axis (radians).
    length : float
        Length of the arrows.
    labels : (str, str)
        Labels of the two axes ("" for none).
    color : color
        Colour of the arrows and labels.

    Returns
    -------
    list of matplotlib.artist.Artist
    """
    ax = get_ax(ax)
    o = np.asarray(origin, float)
    out = []
    for k, lab in enumerate(labels):
        a = angle + k * np.pi / 2
        tip = o + length * np.array([np.cos(a), np.sin(a)])
        out.append(ax.annotate("", xy=tuple(tip), xytext=tuple(o),
                               arrowprops=dict(arrowstyle="-|>", color=color, lw=0.9,
                                               shrinkA=0, shrinkB=0, mutation_scale=8)))
        if lab:
            out.append(ax.annotate(lab, xy=tuple(tip), xytext=(3, 3), textcoords="offset points",
                                   fontsize=LABEL_PT, color=color))
    return out


def draw_com(xy, ax=None, *, radius=0.07, zorder=6):
    """The centre-of-mass symbol (quartered disc).

    Parameters
    ----------
    xy : (float, float)
        The centre of mass.
    ax : matplotlib.axes.Axes, optional
        Axes to draw on (default: the current axes).
    radius : float
        Radius of the symbol (data units).
    zorder : float
        Drawing order.

    Returns
    -------
    list of matplotlib.patches.Wedge
    """
    from matplotlib.patches import Wedge

    ax = get_ax(ax)
    xy = tuple(map(float, xy))
    out = []
    for k in range(4):
        out.append(Wedge(xy, radius, 90 * k, 90 * (k + 1),
                         facecolor="black" if k % 2 == 0 else "white",
                         edgecolor="black", lw=0.6, zorder=zorder))
        ax.add_patch(out[-1])
    return out


def _seg_dist(c, a, b):
    """Distance from point ``c`` to the segment ``a b`` (Euclidean)."""
    d = b - a
    t = float(np.clip((c - a) @ d / max(d @ d, 1e-300), 0.0, 1.0))
    return float(np.hypot(*(a + t * d - c)))


def _slide_clear(line, L, foot, blocked, clearance):
    """The arrow middle on ``line`` nearest ``foot`` whose arrow (length ``L``) clears ``blocked``."""
    from shapely.geometry import LineString

    e = np.array([line[0], line[1]]) / np.hypot(line[0], line[1])
    if blocked is None or blocked.is_empty:
        return foot
    step = max(L, clearance) / 4
    for k in range(41):                      # 0, +1, -1, +2, -2, ... steps along the line
        t = (k + 1) // 2 * step * (1 if k % 2 else -1)
        m = foot + t * e
        if not LineString([m - e * L / 2, m + e * L / 2]).buffer(clearance).intersects(blocked):
            return m
    return foot


def draw_joint_split(s, R, A, f, ax=None, *, name="", scale=1.0, anchor=None, gap=5.0,
                     avoid=None, clearance=0.1):
    """Draw a joint force ``f`` split into active ``T Q`` and reaction ``R μ`` parts (6.38).

    ``s``, ``R``: the joint's motion and reaction spaces, ``A``: the inertia
    (articulated) the decomposition uses.  Each of the three arrows (``f``,
    ``TQ``, ``Rμ``) sits where its line passes closest to ``anchor`` (e.g. the
    joint); each label sits beside the middle of its arrow, ``gap`` points off
    the line, on the side that keeps it farthest from the other two arrows and
    the labels already placed (so the three labels do not stack).  With
    ``avoid`` (a shapely geometry, e.g. the drawn bodies) each arrow slides
    along its line to the nearest place where it stays ``clearance`` (data
    units) away from ``avoid`` and from the arrows placed before it.  The arrow
    ends are ``out[k].get_arrow()`` (to fit a view to them).

    Parameters
    ----------
    s : array_like (3, k)
        The joint's motion space.
    R : array_like (3, 3 - k)
        Its reaction space.
    A : array_like (3, 3)
        The (articulated) inertia of the split.
    f : array_like (3,)
        The joint force.
    ax : matplotlib.axes.Axes, optional
        Axes to draw on (default: the current axes).
    name : str
        Subscript of the labels (``f_name``, ``TQ_name``, ``Rμ_name``).
    scale : float
        Arrow length per unit force (data units).
    anchor : (float, float), optional
        Where the arrows sit along their lines (the foot of this point).
    gap : float
        Distance of a label from its arrow (points).
    avoid : shapely geometry, optional
        What the arrows keep ``clearance`` away from (e.g. the drawn bodies).
    clearance : float
        Free distance around ``avoid`` and earlier arrows (data units).

    Returns
    -------
    tuple
        ``({"f", "active", "reaction"}: LineArtist, (Q, μ, TQ, Rμ))``: the
        artists and the split.

    Examples
    --------
    >>> import matplotlib; matplotlib.use("Agg")
    >>> import matplotlib.pyplot as plt
    >>> fig, ax = plt.subplots()
    >>> from planargeo.mechanics.joints import revolute
    >>> from planargeo.screws.twists import inertia_matrix
    >>> j = revolute([0.0, 0.0])
    >>> A = inertia_matrix(2.0, [1.0, 0.0], 0.3)
    >>> f = np.array([0.0, 1.0, 2.0])                     # 1 N upwards on the line x = 2 (4.27)
    >>> out, (Q, mu, TQ, Rmu) = draw_joint_split(j.s, j.R, A, f, ax, name="1", anchor=[0.0, 0.0])
    >>> bool(np.allclose(TQ + Rmu, f)), sorted(out)
    (True, ['active', 'f', 'reaction'])
    >>> tail, tip = out["f"].get_arrow()                   # centred at the foot of the joint on f
    >>> tail.round(6).tolist(), tip.round(6).tolist()
    ([2.0, -0.5], [2.0, 0.5])
    >>> plt.close(fig)
    """
    from planargeo.mechanics.subspaces import Decomposition

    ax = get_ax(ax)
    dec = Decomposition(A, s, R)
    Q, mu = dec.split_wrench(f)
    active = dec.T @ Q
    react = dec.R @ mu
    parts = {
        "f": (f, dict(role="wrench"), f"$f_{{{name}}}$"),
        "active": (active, dict(role="momentum", linestyle=(0, (6, 2))), f"$TQ_{{{name}}}$"),
        "reaction": (react, dict(role="reaction", linestyle=(0, (2, 2))), f"$R\\mu_{{{name}}}$"),
    }
    out = {k: plot_line(line, ax, scale=scale, anchor=anchor, text=txt, text_at="anchor", **kw)
           for k, (line, kw, txt) in parts.items()}
    if avoid is not None and anchor is not None:
        from shapely.geometry import LineString

        blocked = avoid
        for k, art in out.items():
            seg = art.get_arrow()
            if seg is None:
                continue
            L = float(np.hypot(*(seg[1] - seg[0])))
            mid = _slide_clear(art.get_line(), L, 0.5 * (seg[0] + seg[1]), blocked, clearance)
            art.set_anchor(mid)
            tail, tip = art.get_arrow()
            blocked = blocked.union(LineString([tail, tip]))
    arrows = {k: a.get_arrow() for k, a in out.items()}
    placed = []                                          # label spots chosen so far (data)
    for k, art in out.items():
        seg = arrows[k]
        if seg is None:                                  # no arrow (a zero part): default spot
            continue
        tail, tip = seg
        mid, d = 0.5 * (tail + tip), tip - tail
        L = float(np.hypot(*d))
        if L == 0.0:
            continue
        n = np.array([-d[1], d[0]]) / L
        others = [v for j, v in arrows.items() if j != k and v is not None]

        def label_room(side):
            c = mid + side * n * 0.25 * L
            dist = [_seg_dist(c, *o) for o in others] + [float(np.hypot(*(c - p))) for p in placed]
            if avoid is not None:
                from shapely.geometry import Point as SPoint

                dist.append(float(avoid.distance(SPoint(*c))))
            return min(dist) if dist else 0.0

        side = 1.0 if label_room(1.0) >= label_room(-1.0) else -1.0
        placed.append(mid + side * n * 0.25 * L)
        art.set_text_beside(side * n, gap)
    return out, (Q, mu, active, react)


def slider_guide(contact, pose, body_shape=None, *, clearance=0.04, margin=None):
    """The guide of a slider contact in world coordinates, from the contact and the state.

    The guide is the line through ``point_b`` (body b's frame, or the world for
    the ground) along ``direction``, turned by body b's pose (9.83).  Its walls
    sit ``clearance`` outside the drawn body a (``body_shape``, a shapely shape
    in world coordinates: its half-width across the guide), and span body a's
    extent along the guide plus ``margin`` (default: the body's width) at each end.

    Parameters
    ----------
    contact : planargeo.mechanics.contacts.Contact
        A slider contact.
    pose : array_like (N, 3)
        The bodies' poses.
    body_shape : shapely geometry, optional
        Body a as drawn, in world coordinates.
    clearance : float
        Gap between the body and each wall.
    margin : float, optional
        Wall length beyond the body at each end (default: the body's width).

    Returns
    -------
    tuple
        ``(p0, e, n, half_width, (s0, s1))``: a point on the guide line, its
        unit direction, the unit normal (``e`` turned by +90°), the half distance
        between the walls and the wall span ``p0 + e s`` for ``s`` in ``[s0, s1]``.

    Examples
    --------
    >>> from planargeo.mechanics.contacts import Contact
    >>> c = Contact("slider", 0, -1, point_a=(0.5, 0.0), direction=(0.0, 1.0), angle=np.pi / 2)
    >>> pose = np.array([[0.0, 2.0, np.pi / 2]])            # body a upright on the line x = 0
    >>> p0, e, n, hw, (s0, s1) = slider_guide(c, pose, link_polygon([0, 2], [0, 3], 0.3))
    >>> e.round(12), n.round(12), round(hw, 6), (round(s0, 6), round(s1, 6))
    (array([0., 1.]), array([-1.,  0.]), 0.19, (1.55, 3.45))
    """
    from planargeo.mechanics.contacts import world_point, z_of
    from planargeo.draw.layout import shape_points

    pose = np.asarray(pose, float)
    e = np.asarray(z_of(contact, pose)[:2, 0], float)    # the world sliding direction (9.83)
    n = np.array([-e[1], e[0]])
    p0 = np.asarray(world_point(pose, contact.b, contact.point_b), float)
    pa = np.asarray(world_point(pose, contact.a, contact.point_a), float)
    if body_shape is not None:
        xy = shape_points(body_shape)
        across = (xy - p0) @ n
        along = (xy - p0) @ e
        half = float(np.max(np.abs(across)))
        width = float(np.max(across) - np.min(across))
        lo, hi = float(np.min(along)), float(np.max(along))
    else:
        half, width = 0.1, 0.2
        lo = hi = float((pa - p0) @ e)
    m = width if margin is None else float(margin)
    return p0, e, n, half + clearance, (lo - m, hi + m)


def draw_contact(contact, pose, ax=None, *, body_shape=None, size=0.08, clearance=0.04,
                 zorder=7):
    """Draw one contact of a model (thesis 9.3, 9.49) at the poses ``pose`` (N, 3).

    * ``"pin"``: a white square with a dark rim at the contact point (a loop
      closure, distinct from the tree's round pins);
    * ``"slider"``: the two guide walls of :func:`slider_guide` (hatched outside
      when the guide is the ground) and a dot at the contact point on body a;
    * ``"weld"``: a filled dark square at the contact point.

    Parameters
    ----------
    contact : planargeo.mechanics.contacts.Contact
        The contact.
    pose : array_like (N, 3)
        The bodies' poses.
    ax : matplotlib.axes.Axes, optional
        Axes to draw on (default: the current axes).
    body_shape : shapely geometry, optional
        Body a as drawn (sets a slider's guide walls).
    size : float
        Size of the contact's mark (data units).
    clearance : float
        Gap between body a and a slider's walls.
    zorder : float
        Drawing order of the mark.

    Returns
    -------
    list of matplotlib.artist.Artist
    """
    from planargeo.mechanics.contacts import world_point

    ax = get_ax(ax)
    pose = np.asarray(pose, float)
    pa = np.asarray(world_point(pose, contact.a, contact.point_a), float)
    out = []
    if contact.kind == "slider":
        p0, e, n, hw, (s0, s1) = slider_guide(contact, pose, body_shape, clearance=clearance)
        ang = float(np.arctan2(e[1], e[0]))
        length = s1 - s0
        mid = p0 + e * (s0 + s1) / 2
        for side in (1.0, -1.0):
            wall = mid + side * hw * n
            if contact.b < 0:   # hatching on the outside of each wall
                out += draw_ground(wall, ax, width=length, angle=ang if side < 0 else ang + np.pi,
                                   depth=0.6 * size, n=max(int(round(length / (1.5 * size))), 2),
                                   zorder=zorder - 5)
            else:
                out += ax.plot(*np.column_stack([wall - e * length / 2, wall + e * length / 2]),
                               color=COLORS["ground"], lw=1.2, zorder=zorder - 5)
        out += ax.plot([pa[0]], [pa[1]], "o", ms=2.5, color="#222222", zorder=zorder)
        return out
    filled = contact.kind == "weld"
    sq = Rectangle((pa[0] - size / 2, pa[1] - size / 2), size, size,
                   facecolor="#222222" if filled else "white", edgecolor="#222222", lw=1.0,
                   zorder=zorder)
    ax.add_patch(sq)
    return [sq]


def draw_model(model, data, ax=None, *, width=0.18, labels=True, ground=True, pin_radius=0.05,
               show_com=True, alpha=0.35, names=None, contacts=True):
    """Draw a model's bodies, joints and contacts at the state in ``data``.

    ``data`` is a :class:`planargeo.mechanics.model.Data` (from
    :func:`planargeo.mechanics.kinematics.kinematics` or the RNEA): poses, centres of
    mass, joint origins and joint axes ``data.s(i)``.
    A body with a shapely ``shape`` is drawn from it (moved by its pose);
    otherwise as a rounded link from its joint to each child's joint (or, for
    a tip body, through its centre of mass).  Revolute joints are pins,
    prismatic joints sliders along the joint's translation axis (the first
    column of ``s_i``); joints on the ground get hatching.  With ``contacts``
    every contact of ``model.contacts`` is drawn by :func:`draw_contact`
    (slider guides from the contact and the state).

    Parameters
    ----------
    model : planargeo.mechanics.model.Model
        The mechanism.
    data : planargeo.mechanics.model.Data
        Its kinematics at the state to draw.
    ax : matplotlib.axes.Axes, optional
        Axes to draw on (default: the current axes).
    width : float
        Width of the default rounded links.
    labels : bool
        Label the bodies (their names, or their numbers).
    ground : bool
        Hatch the ground under joints on the ground.
    pin_radius : float
        Radius of the pins (sets the size of the other joint marks).
    show_com : bool
        Mark each body's centre of mass.
    alpha : float
        Opacity of the bodies' fill.
    names : list of str, optional
        Body labels (instead of the model's names).
    contacts : bool
        Draw the model's contacts.

    Returns
    -------
    dict
        Lists of artists under ``"bodies"``, ``"joints"``, ``"com"``,
        ``"contacts"``, and the bodies' world shapes under ``"shapes"``.
    """
    from shapely.ops import unary_union

    ax = get_ax(ax)
    pose = np.asarray(data.pose)
    com = np.asarray(data.com)
    origin = np.asarray(data.origin)
    out = {"bodies": [], "joints": [], "com": [], "contacts": [], "shapes": []}
    for i, body in enumerate(model.bodies):
        if body.shape is not None:
            shape = transform_shape(body.shape, pose[i])
        else:
            kids = model.children(i)
            ends = [origin[k] for k in kids] or [pose[i, :2] + 2 * (com[i] - pose[i, :2])]
            shape = unary_union([link_polygon(pose[i, :2], e, width) for e in ends])
        out["shapes"].append(shape)
        if names is not None:
            name = names[i]
        else:
            name = body.name if labels and body.name else (str(i + 1) if labels else None)
        out["bodies"] += draw_body(shape, ax, alpha=alpha, label=None)
        if labels:
            c = shape.centroid
            out["bodies"].append(ax.annotate(name, xy=(c.x, c.y), xytext=(0, -9),
                                             textcoords="offset points", ha="center",
                                             fontsize=LABEL_PT, color="#1f3a4d"))
        if show_com:
            out["com"] += draw_com(com[i], ax, radius=0.9 * pin_radius)
    for i, joint in enumerate(model.joints):
        o = origin[i]
        if model.parents[i] == -1 and ground and joint.kind != "plane":
            out["joints"] += draw_ground(o - [0, pin_radius * 1.6], ax, width=10 * pin_radius,
                                         depth=1.6 * pin_radius)
        if joint.kind in ("revolute", "revolute_prismatic"):
            out["joints"].append(draw_pin(pose[i, :2] if joint.kind == "revolute" else o, ax,
                                          radius=pin_radius))
        if joint.kind in ("prismatic", "revolute_prismatic"):
            axis = np.asarray(data.s(i))[:2, 0]        # the translation column of s_i (world)
            out["joints"] += draw_slider(pose[i, :2], axis, ax, size=(0.25, 0.14), track=0.9)
    if contacts:
        for c in model.contacts:
            out["contacts"] += draw_contact(c, pose, ax, body_shape=out["shapes"][c.a],
                                            size=1.6 * pin_radius)
    return out
