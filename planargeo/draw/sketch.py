"""Shared basics of the gallery's pictures: a panel fitted to an axes, labels, dimensions, mechanisms.

Examples
--------
>>> import matplotlib; matplotlib.use("Agg")
>>> from matplotlib.figure import Figure
>>> ax = Figure(figsize=(3.4, 2.0)).add_axes((0.0, 0.0, 1.0, 1.0))
>>> pic = panel(ax, [[0.0, 0.0], [2.0, 1.0]], margin=0.1)
>>> el = link(pic, "body 1", (0.0, 0.0), (2.0, 0.0), width=0.2)
>>> _ = pin(pic, "joint 1", (0.0, 0.0))
>>> pic.size, len(show(pic, ax)) > 0
((340, 200), True)
"""
from __future__ import annotations

import math

import numpy as np

from planargeo._validate import as_scalar
from planargeo.draw._shared import ENTRIES, added, as_picture, number, view_centre
from planargeo.draw.layout import fit_box, shape_points
from planargeo.draw.picture import PX_PER_PT, Picture, _align, _text_part, plain_text
from planargeo.draw.picture import _color as _role_color, _dash as _role_dash
from planargeo.draw.pictures.kit import foot_on_line, force as force_arrow, seg_distance
from planargeo.draw.splits import wrench_parts
from planargeo.draw.style import COLORS, LINEWIDTHS
from planargeo.errors import InputError
from planargeo.geometry._docs import entries

__all__ = ["panel", "fit_box", "show", "label", "segment", "dimension", "body_words", "link_polygon",
           "transform_shape", "arrow", "body", "link", "pin", "ground", "slider", "frame", "com", "model",
           "model_shapes", "slider_guide", "contact", "split_arrows", "joint_split"]

#: The shared docstring entries, what the two-point elements raise, and the entries of several
#: mechanism and split functions, written once
_ENTRIES = {
    **ENTRIES,
    "distinct": "Raises\n------\nInputError\n    ``p`` and ``q`` coincide or are not finite.",
    "pq": "p, q : (float, float)\n    End points (finite).",
    "xy": "xy : (float, float)\n    Where it is (finite, data units).",
    "radius": "radius : float\n    Radius of the disc (data units).",
    "model": "model : planargeo.mechanics.model.Model\n    The model.\n"
             "data : planargeo.mechanics.model.Data\n    Its kinematics at the state to draw.",
    "pose": "pose : array_like (N, 3)\n    The bodies' poses.",
    "width": "width : float\n    Width of the default rounded links.",
    "scale": "scale : float\n    Arrow length per unit force (data units).",
    "avoid": "avoid : shapely geometry, optional\n    What the arrows keep clear of (the bodies).\n"
             "clearance : float\n    Free distance around ``avoid`` and earlier arrows."}
documented = entries(_ENTRIES)

#: outline colour of bodies and body labels
BODY_EDGE = "#1f3a4d"
#: outline colour of pins, sliders and frames
DARK = "#222222"
_SQUARE = np.array([[-1.0, -1.0], [1.0, -1.0], [1.0, 1.0], [-1.0, 1.0]])   # side 2, about 0


# --------------------------------------------------------------------------- checks
def _xy(v, name: str) -> np.ndarray:
    """A finite Euclidean point (2,) or an InputError naming ``name``."""
    try:
        a = np.asarray(v, dtype=float).reshape(-1)
    except (TypeError, ValueError):
        raise InputError(f"{name} must be a point (x, y) of two numbers, got {v!r}") from None
    if a.shape != (2,) or not np.all(np.isfinite(a)):
        raise InputError(f"{name} must be a point (x, y) of two finite numbers, got {v!r}")
    return a


def _beside(m, u, text: str, gap: float) -> dict:
    """A text part at ``m``, ``gap`` pixels off in the pixel direction ``u``, aligned away."""
    u = np.asarray(u, float) / math.hypot(*u)
    return _text_part(m[0], m[1], text, gap * u[0], gap * u[1], *_align(u))


def _arc(c, r, t) -> np.ndarray:
    return np.column_stack([c[0] + r * np.cos(t), c[1] + r * np.sin(t)])


def _disc(pic: Picture, id: str, xy, radius, *, color: str, width: float, **kw) -> tuple:
    """A white disc of ``radius`` at ``xy``, its rim ``width`` points: its centre and radius."""
    c = _xy(xy, "xy")
    r = number(radius, "radius", positive=True)
    rim = _arc(c, r, np.linspace(0.0, 2 * np.pi, 36, endpoint=False))
    as_picture(pic).path(id, rim, role="body", closed=True, fill="white", color=color,
                         width=width * PX_PER_PT, **kw)
    return c, r


def body_words(name=None, number=None) -> str:
    """How a description names a body: ``"body 2"``, ``"crank (body 2)"``, never ``"body body 2"``.

    Parameters
    ----------
    name : str, optional
        The body's name or label (``"body 1"``, ``"crank"``, ``"3"``).
    number : int, optional
        The body's number (from 1).

    Returns
    -------
    str

    Examples
    --------
    >>> body_words("body 1", 1), body_words("3"), body_words("crank", 2), body_words(None, 4)
    ('body 1', 'body 3', 'crank (body 2)', 'body 4')
    """
    name = "" if name is None else str(name).strip()
    if not name:
        return f"body {number}" if number is not None else "a body"
    if name.lower().startswith("body"):
        return name
    if len(name) <= 2 or name == str(number):       # a number or a letter: "body 3", "body A"
        return f"body {name}"
    return f"{name} (body {number})" if number is not None else name


# --------------------------------------------------------------------------- panel
def panel(ax, points, *, margin=None, keep=None, min_span=None, fit_height=False, hmin=1.5,
          hmax=4.6) -> Picture:
    """A Picture the size of the axes ``ax`` (pixels at 100 dpi), its view fitted to ``points``.

    Parameters
    ----------
    ax : matplotlib.axes.Axes
        The panel the picture will be drawn on.
    points, keep, min_span
        As :func:`fit_box`.
    margin : float, optional
        As :func:`fit_box` (default 0.25; with ``fit_height`` 0.08).
    fit_height : bool
        Set the figure's height to the points' aspect first.
    hmin, hmax : float
        Bounds of that height (inches).

    Returns
    -------
    Picture
        Sized to the axes, with neither ticks nor margin.

    Raises
    ------
    InputError
        ``ax`` is not an axes, no finite point, or a bad margin / min_span.

    Examples
    --------
    >>> from matplotlib.figure import Figure
    >>> ax = Figure(figsize=(4, 2)).add_axes((0.0, 0.0, 1.0, 1.0))
    >>> pic = panel(ax, [[0, 0], [1, 1]], margin=0.0)
    >>> pic.size, pic.box
    ((400, 200), (-0.5, 1.5, 0.0, 1.0))
    """
    if not (hasattr(ax, "get_position") and hasattr(ax, "figure")):
        raise InputError(f"ax must be a matplotlib axes, got {type(ax).__name__}")
    fig = ax.figure
    if fit_height:
        margin = 0.08 if margin is None else margin
        P = np.asarray(points, float).reshape(-1, 2)
        P = P[np.all(np.isfinite(P), axis=1)]
        if len(P):
            span = P.max(axis=0) - P.min(axis=0)
            ext = span + 2 * float(margin) * float(np.max(span))
            fw, _ = fig.get_size_inches()
            bb = ax.get_position(original=True)
            if ext[0] > 0:
                fig.set_size_inches(fw, float(np.clip(fw * bb.width * ext[1] / ext[0] / bb.height,
                                                      hmin, hmax)))
    bb = ax.get_position(original=True)
    fw, fh = fig.get_size_inches()
    w, h = fw * bb.width * 100.0, fh * bb.height * 100.0
    box = fit_box(points, h / w, margin=margin, keep=keep, min_span=min_span)
    return Picture(box, size=(w, h), ticks=False, margin=(0, 0, 0, 0))


@documented
def show(pic: Picture, ax=None) -> list:
    """Draw the picture on the axes ``ax`` (:func:`planargeo.draw.render.draw_picture`).

    {parameters pic}
    ax : matplotlib.axes.Axes, optional
        The axes :func:`panel` sized the picture to (default: the current axes).

    Returns
    -------
    list of (str, int, matplotlib.artist.Artist)
        The drawn artists with their element ids and part indices.
    """
    from planargeo.draw.render import draw_picture

    return draw_picture(as_picture(pic).to_dict(), ax)


# --------------------------------------------------------------------------- texts, lines
@documented
def label(pic: Picture, id: str, xy, text: str, *, offset=(5, 5), ha: str = "left",
          va: str = "bottom", role: str = "text", color=None, symbol: str = "", desc: str = "",
          fixed: bool = False) -> dict:
    """A text at the data point ``xy``, moved by ``offset`` points (placed, unless ``fixed``).

    {parameters pic id xy}
    text : str
        The text (``$..$`` mathtext becomes Unicode).
    offset : (float, float)
        Shift of the text in points (y up).
    ha, va : str
        Alignment at the shifted anchor.
    {role color symbol}
    fixed : bool
        Keep the text where asked (others avoid it).

    {element}

    Raises
    ------
    InputError
        ``xy`` not a finite point, or ``offset`` not two numbers.

    Examples
    --------
    >>> pic = Picture((0, 1, 0, 1), size=(100, 100), ticks=False, margin=(0, 0, 0, 0))
    >>> part = label(pic, "P", (0.5, 0.5), "$P_1$", offset=(0, 0))["parts"][0]
    >>> part["text"], part["x"], part["dx"]
    ('P₁', 0.5, 0.0)
    """
    x, y = _xy(xy, "xy")
    try:
        dx, dy = (float(v) * PX_PER_PT for v in offset)
    except (TypeError, ValueError):
        raise InputError(f"offset must be two numbers (points), got {offset!r}") from None
    el = added(as_picture(pic).text, id, (x, y), str(text), role=role, color=_role_color(role, color), ha=ha,
               va=va, dx=dx, dy=dy, symbol=symbol, desc=desc)
    if not fixed:
        el["parts"][0].pop("fixed", None)
    return el


@documented
def segment(pic: Picture, id: str, p, q, *, role: str = "construct", label=None, color=None,
            width=None, dash=None, symbol: str = "", desc: str = "", z: int = 2) -> dict:
    """A finite segment ``p q`` in a role's style (colour, width, dash), optionally labelled.

    {parameters pic id pq}
    role : str
        Style role (default ``"construct"``: thin, grey, dashed).
    label : str, optional
        Text beside the segment's middle.
    {color}
    width : float, optional
        Line width in pixels (default: the role's).
    dash : list of float, optional
        Dash pattern in pixels (default: the role's; ``[]`` for solid).
    {symbol z}

    {element}

    Examples
    --------
    >>> pic = Picture((0, 1, 0, 1), size=(100, 100), ticks=False, margin=(0, 0, 0, 0))
    >>> el = segment(pic, "s", (0, 0), (1, 1))
    >>> el["parts"][0]["xy"].tolist(), el["dash"]
    ([[0.0, 0.0], [1.0, 1.0]], [5.56, 4.17])
    """
    p, q = _xy(p, "p"), _xy(q, "q")
    el = added(as_picture(pic).path, id, np.array([p, q]), role=role, symbol=symbol, desc=desc,
               color=_role_color(role, color),
               width=width if width is not None else LINEWIDTHS.get(role, 1.0) * PX_PER_PT,
               dash=(dash or None) if dash is not None else _role_dash(role), z=z)
    if label:
        d = (q - p) * (pic.kx, pic.ky)
        n = (-d[1], d[0]) if math.hypot(*d) else (0.0, 1.0)
        el["parts"].append(_beside((p + q) / 2, n, label, 5))
    return el


@documented
def dimension(pic: Picture, id: str, p, q, text: str, *, offset: float = 0.0, at: float = 0.5,
              color=None, tick: float = 8.0, symbol: str | None = None, desc: str = "") -> dict:
    """A dimension line ``p q`` with end ticks, shifted ``offset`` to the left of ``p → q``, labelled.

    {parameters pic id pq}
    text : str
        The dimension.
    offset : float
        Shift of the line to the left of ``p → q`` (data units).
    at : float
        Where the text sits along the line (0: at ``p``, 1: at ``q``), 4 points off it.
    color : str, optional
        Colour of the line, ticks and text (default: the construction grey).
    tick : float
        Length of the end ticks (pixels).
    symbol : str, optional
        Thesis symbol (default: the text before its first ``" = "``, or all of it).
    desc : str
        One-line description (default: the text).

    Returns
    -------
    dict
        The element: parts ``[line, tick at p, tick at q, text]``.

    {distinct}

    Examples
    --------
    >>> pic = Picture((-1, 3, -1, 3), size=(100, 100), ticks=False, margin=(0, 0, 0, 0))   # 25 px per unit
    >>> el = dimension(pic, "d", (0, 0), (2, 0), "2 m", offset=1.0)
    >>> [part["xy"].tolist() for part in el["parts"][:3]]
    [[[0.0, 1.0], [2.0, 1.0]], [[0.0, 0.84], [0.0, 1.16]], [[2.0, 0.84], [2.0, 1.16]]]
    """
    p, q = _xy(p, "p"), _xy(q, "q")
    d = q - p
    L = math.hypot(*d)
    if L == 0.0:
        raise InputError("dimension: p and q must be distinct points")
    offset, at = as_scalar(offset, "offset"), as_scalar(at, "at")
    as_picture(pic)
    n = np.array([-d[1], d[0]]) / L
    p2, q2 = p + offset * n, q + offset * n
    npx = n * (pic.kx, pic.ky)
    npx = npx / math.hypot(*npx)
    half = np.array([npx[0] / pic.kx, npx[1] / pic.ky]) * tick / 2     # half a tick, data units
    parts = [{"p": "path", "xy": np.array([p2, q2]), "closed": False},
             {"p": "path", "xy": np.array([p2 - half, p2 + half]), "closed": False},
             {"p": "path", "xy": np.array([q2 - half, q2 + half]), "closed": False},
             _beside(p2 + at * (q2 - p2), n * (pic.kx, pic.ky), text, 4.0 * PX_PER_PT)]
    if symbol is None:
        symbol = str(text).split(" = ", 1)[0]
    return pic._add(id, "construct", symbol, desc or text, parts,
                    color=color or COLORS["construct"], width=0.7 * PX_PER_PT, z=2)


@documented
def arrow(pic: Picture, id: str, p, q, *, role: str = "wrench", color=None, label=None,
          offset=(5, 5), symbol: str = "", desc: str = "", z: int = 5) -> dict:
    """An arrow from ``p`` to ``q`` (data points): a solid shaft, its head at ``q``.

    {parameters pic id pq role color}
    label : str, optional
        Text at the tip, moved by ``offset`` points (y up).
    offset : (float, float)
        Shift of the label.
    {symbol z}

    {element}

    {distinct}

    Examples
    --------
    >>> pic = Picture((0, 2, 0, 2), size=(100, 100), ticks=False, margin=(0, 0, 0, 0))
    >>> part = arrow(pic, "F", (0.0, 1.0), (1.0, 1.0))["parts"][0]
    >>> part["x"], part["y"], part["dx"], part["dy"]        # 1 unit = 50 px to the right
    (0.0, 1.0, 50.0, 0.0)
    """
    p, q = _xy(p, "p"), _xy(q, "q")
    if np.array_equal(p, q):
        raise InputError("arrow: p and q must be distinct points")
    as_picture(pic)
    d = (q - p) * (pic.kx, pic.ky)
    parts = [{"p": "arrow", "x": float(p[0]), "y": float(p[1]), "dx": float(d[0]), "dy": float(d[1])}]
    if label:
        parts.append(_text_part(q[0], q[1], label, offset[0] * PX_PER_PT, offset[1] * PX_PER_PT))
    return pic._add(id, role, symbol, desc, parts, color=_role_color(role, color), z=z)


# --------------------------------------------------------------------------- shapes
@documented
def link_polygon(p, q, width: float = 0.25):
    """A rounded link (stadium) from ``p`` to ``q`` (a disc if they coincide) as a shapely polygon.

    {parameters pq}
    width : float
        Width of the link (the diameter of its rounded ends).

    Returns
    -------
    shapely.geometry.Polygon

    Examples
    --------
    >>> [round(v, 6) for v in link_polygon((0, 0), (2, 0), 0.5).bounds]
    [-0.25, -0.25, 2.25, 0.25]
    """
    from shapely.geometry import LineString, Point as SPoint

    p, q = tuple(map(float, _xy(p, "p"))), tuple(map(float, _xy(q, "q")))
    width = number(width, "width", positive=True)
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

    Examples
    --------
    >>> from shapely.geometry import Point as SPoint
    >>> g = transform_shape(SPoint(1.0, 0.0), (2.0, 0.0, np.pi / 2))
    >>> round(g.x, 9), round(g.y, 9)
    (2.0, 1.0)
    """
    from shapely import affinity

    x, y, th = (float(v) for v in pose)
    return affinity.translate(affinity.rotate(shape, th, origin=(0, 0), use_radians=True), x, y)


def _polygons(shape):
    """Exterior and hole rings (arrays) of a shapely (multi)polygon or of an (n, 2) array."""
    if hasattr(shape, "geom_type"):
        geoms = getattr(shape, "geoms", [shape])
        if not all(hasattr(g, "exterior") for g in geoms):
            raise InputError(f"shape must be a polygon or multipolygon, got {shape.geom_type}")
        return ([np.asarray(g.exterior.coords)[:, :2] for g in geoms],
                [np.asarray(h.coords)[:, :2] for g in geoms for h in g.interiors])
    try:
        xy = np.asarray(shape, dtype=float).reshape(-1, 2)
    except (TypeError, ValueError):
        raise InputError("shape must be a shapely polygon or an (n, 2) array of vertices") from None
    if len(xy) < 3 or not np.all(np.isfinite(xy)):
        raise InputError("shape must have at least 3 finite vertices")
    return [xy], []


# --------------------------------------------------------------------------- mechanism
@documented
def body(pic: Picture, id: str, shape, pose=None, *, label=None, color=None, alpha: float = 0.35,
         edgecolor: str = BODY_EDGE, z: int = 1, com=None, symbol: str = "", desc: str = "") -> dict:
    """A body: a filled polygon, holes white (``id + ":holes"``), centre of mass (``id + ":com"``).

    {parameters pic id}
    shape : shapely Polygon or MultiPolygon, or array_like (n, 2)
        The body; in world coordinates, or in its body frame when ``pose`` is given.
    pose : (float, float, float), optional
        The body frame's origin and angle (radians).
    label : str, optional
        Text at a point inside the body.
    color : str, optional
        Fill colour (default: the body colour).
    alpha : float
        Opacity of the fill.
    edgecolor : str
        Outline colour.
    {z}
    com : (float, float), optional
        Centre of mass to mark.
    {symbol}

    {element}

    Examples
    --------
    >>> pic = Picture((-1, 2, -1, 2), size=(100, 100), ticks=False, margin=(0, 0, 0, 0))
    >>> el = body(pic, "b", [[0, 0], [1, 0], [0, 1]], pose=(1.0, 0.0, np.pi / 2))
    >>> np.round(el["parts"][0]["xy"], 9).tolist()        # turned a quarter, moved by 1 along x
    [[1.0, 0.0], [1.0, 1.0], [0.0, 0.0], [1.0, 0.0]]
    """
    as_picture(pic)
    if pose is not None:
        if not hasattr(shape, "geom_type"):
            from shapely.geometry import Polygon as SPolygon

            shape = SPolygon(np.asarray(shape, float).reshape(-1, 2))
        shape = transform_shape(shape, pose)
    outer, holes = _polygons(shape)
    parts = [{"p": "path", "xy": r, "closed": True} for r in outer]
    edge = _role_color("body", edgecolor)
    el = pic._add(id, "body", symbol, desc or body_words(label), parts, color=edge,
                  fill=color or COLORS["body"], alpha=float(alpha), z=z)
    if label is not None and str(label):
        inside = hasattr(shape, "representative_point")
        cx, cy = shape.representative_point().coords[0] if inside else outer[0].mean(axis=0)
        el["parts"].append(_text_part(cx, cy, str(label), 0.0, 0.0, "center", "center"))
    if holes:
        holes = [{"p": "path", "xy": h, "closed": True} for h in holes]
        pic._add(f"{id}:holes", "body", "", "", holes, color=edge, fill="white", z=z)
    if com is not None:
        _com(pic, f"{id}:com", com, desc=f"centre of mass of {desc or body_words(label)}")
    return el


@documented
def link(pic: Picture, id: str, p, q, *, width: float = 0.25, **kw) -> dict:
    """A default rounded link between two points (:func:`link_polygon`, drawn by :func:`body`).

    {parameters pic id pq}
    width : float
        Width of the link (data units).
    **kw
        Options of :func:`body`.

    {element}

    Examples
    --------
    >>> pic = Picture((-1, 3, -1, 3), size=(100, 100), ticks=False, margin=(0, 0, 0, 0))
    >>> xy = link(pic, "l", (0, 0), (2, 0), width=0.5)["parts"][0]["xy"]
    >>> [round(float(v), 6) for v in (xy[:, 0].min(), xy[:, 0].max(), xy[:, 1].min(), xy[:, 1].max())]
    [-0.25, 2.25, -0.25, 0.25]
    """
    return body(pic, id, link_polygon(p, q, width), **kw)


@documented
def pin(pic: Picture, id: str, xy, *, radius: float = 0.06, z: int = 6, symbol: str = "joint",
        desc: str = "a revolute joint") -> dict:
    """A revolute joint at ``xy``: a white disc with a dark rim, ``radius`` data units.

    {parameters pic id xy radius z symbol}

    {element}

    Examples
    --------
    >>> pic = Picture((-1, 1, -1, 1), size=(100, 100), ticks=False, margin=(0, 0, 0, 0))
    >>> xy = pin(pic, "j", (0.5, 0.0), radius=0.1)["parts"][0]["xy"]
    >>> bool(np.allclose(np.hypot(xy[:, 0] - 0.5, xy[:, 1]), 0.1))
    True
    """
    _disc(pic, id, xy, radius, color=DARK, width=1.0, symbol=symbol, desc=desc, z=z)
    return pic.elements[-1]


@documented
def ground(pic: Picture, id: str, xy, *, width: float = 0.8, angle: float = 0.0, depth: float = 0.12,
           n: int = 7, z: int = 1, desc: str = "the ground") -> dict:
    """A ground line ``width`` long centred on ``xy``, at ``angle``, hatched on its right-hand side.

    {parameters pic id xy}
    width : float
        Length of the line.
    angle : float
        Direction of the line (radians).
    depth : float
        Length (along the line and across it) of the hatch strokes.
    n : int
        Number of hatch strokes (at least 2).
    {z desc}

    {element}

    Raises
    ------
    InputError
        ``xy`` not a finite point, ``width`` not positive or ``n`` below 2.

    Examples
    --------
    >>> pic = Picture((-1, 1, -1, 1), size=(100, 100), ticks=False, margin=(0, 0, 0, 0))
    >>> parts = ground(pic, "g", (0.0, 0.0), width=1.0, depth=0.1, n=2)["parts"]
    >>> [np.round(p["xy"], 9).tolist() for p in parts]
    [[[-0.5, 0.0], [0.5, 0.0]], [[-0.5, 0.0], [-0.6, -0.1]], [[0.5, 0.0], [0.4, -0.1]]]
    """
    c = _xy(xy, "xy")
    width = number(width, "width", positive=True)
    if int(n) != n or n < 2:
        raise InputError(f"n must be an integer of at least 2, got {n!r}")
    angle = float(angle)
    e = np.array([math.cos(angle), math.sin(angle)])
    nrm = np.array([-e[1], e[0]])
    a, b = c - e * width / 2, c + e * width / 2
    parts = [{"p": "path", "xy": np.array([a, b]), "closed": False}]
    for t in np.linspace(0, 1, int(n)):
        s = a + (b - a) * t
        parts.append({"p": "path", "xy": np.array([s, s - (e + nrm) * depth]), "closed": False})
    return as_picture(pic)._add(id, "ground", "ground", desc, parts, color=COLORS["ground"],
                                width=PX_PER_PT, z=z)


@documented
def slider(pic: Picture, id: str, xy, direction, *, size=(0.35, 0.2), track: float = 1.6,
           z: int = 3, desc: str = "a prismatic joint") -> dict:
    """Prismatic joint: a block at ``xy`` on a hatched track ``id + ":track"`` along ``direction``.

    {parameters pic id xy}
    direction : (float, float)
        Direction of sliding (not zero).
    size : (float, float)
        Length and height of the block.
    track : float
        Length of the track.
    {z desc}

    Returns
    -------
    dict
        The block's element.

    Raises
    ------
    InputError
        A zero or non-finite direction, or a bad point or size.

    Examples
    --------
    >>> pic = Picture((-2, 2, -2, 2), size=(100, 100), ticks=False, margin=(0, 0, 0, 0))
    >>> xy = slider(pic, "s", (1.0, 0.0), (0.0, 2.0), size=(0.4, 0.2))["parts"][0]["xy"]
    >>> np.round(xy, 9).tolist()            # the block stands along y
    [[1.1, -0.2], [1.1, 0.2], [0.9, 0.2], [0.9, -0.2]]
    """
    c = _xy(xy, "xy")
    d = _xy(direction, "direction")
    L = math.hypot(*d)
    if L == 0.0:
        raise InputError("slider: direction must not be zero")
    w, h = (number(v, "size", positive=True) for v in size)
    e = d / L
    nrm = np.array([-e[1], e[0]])
    ang = math.atan2(e[1], e[0])
    ground(pic, f"{id}:track", c - nrm * h / 2, width=number(track, "track", positive=True),
           angle=ang)
    corners = _SQUARE * (w / 2, h / 2)
    xy_ = c + corners[:, :1] * e + corners[:, 1:] * nrm
    return added(pic.path, id, xy_, role="body", desc=desc, closed=True, fill="#dddddd", color=DARK,
                 width=1.0 * PX_PER_PT, z=z)


def _arrow_parts(pic: Picture, p, q, head: float = 9.0) -> list:
    """Parts of an arrow from ``p`` to ``q`` (data): a shaft and a head ``head`` pixels long at ``q``."""
    d = (q - p) * (pic.kx, pic.ky)
    Lpx = math.hypot(*d)
    u = d / Lpx
    hd = min(head, Lpx)
    base = q - np.array([u[0] / pic.kx, u[1] / pic.ky]) * hd
    return [{"p": "path", "xy": np.array([p, base]), "closed": False},
            {"p": "arrow", "x": float(base[0]), "y": float(base[1]), "dx": float(u[0] * hd),
             "dy": float(u[1] * hd)}]


@documented
def frame(pic: Picture, id: str, origin, *, angle: float = 0.0, length: float = 0.5,
          labels=("x", "y"), color: str = DARK, desc: str = "a body frame") -> dict:
    """Coordinate axes arrows at ``origin``, the first at ``angle``, ``length`` data units long.

    {parameters pic id}
    origin : (float, float)
        Where the axes start.
    angle : float
        Direction of the first axis (radians).
    length : float
        Length of the arrows.
    labels : (str, str)
        Labels of the two axes at their tips ("" for none).
    color : str
        Colour of the arrows.
    {desc}

    Returns
    -------
    dict
        The element: shaft, head (and label) of the first axis, then of the second.

    Examples
    --------
    >>> pic = Picture((-1, 1, -1, 1), size=(100, 100), ticks=False, margin=(0, 0, 0, 0))
    >>> tip = frame(pic, "F", (0.0, 0.0), angle=np.pi / 2, length=0.5)["parts"][1]   # 1st head
    >>> round(tip["x"], 9), round(tip["y"] + tip["dy"] / 50, 9), round(tip["dx"], 9)
    (0.0, 0.5, 0.0)
    """
    o = _xy(origin, "origin")
    length = number(length, "length", positive=True)
    parts = []
    as_picture(pic)
    for k, lab in enumerate(labels):
        a = float(angle) + k * np.pi / 2
        tip = o + length * np.array([math.cos(a), math.sin(a)])
        parts += _arrow_parts(pic, o, tip, head=8.0)
        if lab:
            parts.append(_text_part(tip[0], tip[1], lab, 3 * PX_PER_PT, 3 * PX_PER_PT))
    return pic._add(id, "construct", "", desc, parts, color=_role_color("construct", color),
                    width=0.9 * PX_PER_PT, z=4)


@documented
def com(pic: Picture, id: str, xy, *, radius: float = 0.07, z: int = 6, symbol: str = "c",
        desc: str = "centre of mass") -> dict:
    """Centre-of-mass mark at ``xy``: a white disc (``id + ":disc"``), black quarters 1, 3 (``id``).

    {parameters pic id xy radius z}
    symbol : str
        Thesis symbol of the centre of mass (default ``"c"``; ``"$c_2$"`` reads c₂).
    {desc}

    Returns
    -------
    dict
        The black quarters' element.

    Examples
    --------
    >>> pic = Picture((-1, 1, -1, 1), size=(100, 100), ticks=False, margin=(0, 0, 0, 0))
    >>> q1 = com(pic, "c", (0.0, 0.0), radius=0.1)["parts"][0]["xy"]
    >>> bool(q1[:, 0].min() >= 0 and q1[:, 1].min() >= 0), round(float(np.hypot(*q1[1])), 9)
    (True, 0.1)
    """
    c, r = _disc(pic, f"{id}:disc", xy, radius, color="black", width=0.6, symbol=symbol, desc=desc,
                 z=z)
    quarters = (np.linspace(k * np.pi / 2, (k + 1) * np.pi / 2, 10) for k in (0, 2))
    parts = [{"p": "path", "xy": np.vstack([c, _arc(c, r, t)]), "closed": True} for t in quarters]
    return pic._add(id, "body", symbol, desc, parts, color="black", width=0.6 * PX_PER_PT,
                    fill="black", z=z)


_com, _ground = com, ground      # for the functions with keywords of these names


@documented
def model(pic: Picture, model, data, *, prefix: str = "", width: float = 0.18, labels: bool = True,
          ground: bool = True, pin_radius: float = 0.05, show_com: bool = True, alpha: float = 0.35,
          names=None, contacts: bool = True) -> dict:
    """A model's bodies (:func:`model_shapes`), joints and contacts at the state in ``data``.

    Element ids (``prefix`` first): ``body i``, ``com i``, ``joint i``, ``ground i``,
    ``slider i``, ``contact k`` (numbers from 1).

    {parameters pic}
    {model prefix width}
    labels : bool
        Label the bodies (their names, or their numbers), below their centroids.
    ground : bool
        Hatch the ground under joints on the ground.
    pin_radius : float
        Radius of the pins (sets the size of the other joint marks).
    show_com : bool
        Mark each body's centre of mass.
    alpha : float
        Opacity of the bodies' fill.
    names : list of str, optional
        Body labels instead of the model's names.
    contacts : bool
        Draw the model's contacts (:func:`contact`).

    Returns
    -------
    dict
        Elements under ``"bodies"``, ``"joints"``, ``"com"``, ``"contacts"``, and the
        bodies' world shapes (shapely) under ``"shapes"``.

    Raises
    ------
    InputError
        ``names`` without one label per body.

    Examples
    --------
    >>> from planargeo.gallery.figures import chain
    >>> from planargeo.mechanics.kinematics import kinematics
    >>> m = chain(2)
    >>> d = kinematics(m, np.array([np.pi / 2, -np.pi / 2]), np.zeros(2))
    >>> pic = Picture((-1, 2, -1, 2), size=(200, 200), ticks=False, margin=(0, 0, 0, 0))
    >>> [round(v, 6) for v in model(pic, m, d)["shapes"][1].centroid.coords[0]]   # (0, 1) to (1, 1)
    [0.5, 1.0]
    """
    as_picture(pic)
    pose, cm, origin = (np.asarray(v, float) for v in (data.pose, data.com, data.origin))
    if names is not None and len(names) != model.N:
        raise InputError(f"names must hold one label per body ({model.N}), got {len(names)}")
    out = {"bodies": [], "joints": [], "com": [], "contacts": [],
           "shapes": model_shapes(model, data, width=width)}
    for i, (b, shape) in enumerate(zip(model.bodies, out["shapes"])):
        name = names[i] if names is not None else (b.name or str(i + 1)) if labels else None
        words = body_words(name, i + 1)
        el = body(pic, f"{prefix}body {i + 1}", shape, alpha=alpha, symbol=str(name or i + 1),
                  desc=words)
        if (labels or names is not None) and name:
            c = shape.centroid
            part = _text_part(c.x, c.y, str(name), 0.0, -9 * PX_PER_PT, "center", "center")
            part["fixed"] = True         # a body's number stays on its body: the placer moves others off it
            el["parts"].append(part)
        out["bodies"].append(el)
        if show_com:
            out["com"].append(com(pic, f"{prefix}com {i + 1}", cm[i], radius=0.9 * pin_radius,
                                  symbol=f"$c_{{{i + 1}}}$", desc=f"centre of mass of {words}"))
    for i, joint in enumerate(model.joints):
        o = origin[i]
        if model.parents[i] == -1 and ground and joint.kind != "plane":
            out["joints"].append(_ground(
                pic, f"{prefix}ground {i + 1}", o - [0, pin_radius * 1.6], width=10 * pin_radius,
                depth=1.6 * pin_radius))
        if joint.kind in ("revolute", "revolute_prismatic"):
            out["joints"].append(pin(pic, f"{prefix}joint {i + 1}",
                                     pose[i, :2] if joint.kind == "revolute" else o, radius=pin_radius,
                                     symbol=f"joint {i + 1}", desc=f"joint {i + 1}, revolute"))
        if joint.kind in ("prismatic", "revolute_prismatic"):
            axis = np.asarray(data.s(i))[:2, 0]        # the translation column of s_i (world)
            out["joints"].append(slider(pic, f"{prefix}slider {i + 1}", pose[i, :2], axis,
                                        size=(0.25, 0.14), track=0.9, desc=f"joint {i + 1}, prismatic"))
    if contacts:
        for k, c in enumerate(model.contacts):
            out["contacts"].append(contact(pic, f"{prefix}contact {k + 1}", c, pose,
                                           body_shape=out["shapes"][c.a], size=1.6 * pin_radius))
    return out


@documented
def slider_guide(contact, pose, body_shape=None, *, clearance: float = 0.04, margin=None):
    """The guide of a slider contact: the world line through ``point_b`` along ``direction`` (9.83).

    Its walls sit ``clearance`` outside the drawn body a and span its extent along the guide.

    Parameters
    ----------
    contact : planargeo.mechanics.contacts.Contact
        A slider contact.
    {pose}
    body_shape : shapely geometry, optional
        Body a as drawn, in world coordinates.
    clearance : float
        Gap between the body and each wall.
    margin : float, optional
        Wall length beyond the body at each end (default: the body's width).

    Returns
    -------
    tuple
        ``(p0, e, n, half_width, (s0, s1))``: a point of the guide line, its unit direction, the
        unit normal, the half distance between the walls and the wall span ``p0 + e s``.

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


@documented
def contact(pic: Picture, id: str, contact, pose, *, body_shape=None, size: float = 0.08,
            clearance: float = 0.04, z: int = 7) -> list:
    """One contact of a model (thesis 9.3, 9.49) at the poses ``pose`` (N, 3).

    A pin is a white square, a weld a dark one; a slider is the two guide walls of
    :func:`slider_guide` (``id + ":wall 1"``, ``":wall 2"``) and a dot on body a (``id``).

    {parameters pic id}
    contact : planargeo.mechanics.contacts.Contact
        The contact.
    {pose}
    body_shape : shapely geometry, optional
        Body a as drawn (sets a slider's guide walls).
    size : float
        Size of the contact's mark (data units).
    clearance : float
        Gap between body a and a slider's walls.
    {z}

    Returns
    -------
    list of dict
        The elements added: a slider's two walls, then the mark.

    Examples
    --------
    >>> from planargeo.mechanics.contacts import Contact
    >>> pic = Picture((-1, 1, -1, 1), size=(100, 100), ticks=False, margin=(0, 0, 0, 0))
    >>> c = Contact("pin", 0, -1, point_a=(0.5, 0.0))
    >>> el = contact(pic, "c", c, np.array([[0.0, 0.0, 0.0]]), size=0.2)[0]
    >>> np.round(el["parts"][0]["xy"], 9).tolist()
    [[0.4, -0.1], [0.6, -0.1], [0.6, 0.1], [0.4, 0.1]]
    """
    from planargeo.mechanics.contacts import world_point

    as_picture(pic)
    size = number(size, "size", positive=True)
    pose = np.asarray(pose, float)
    pa = np.asarray(world_point(pose, contact.a, contact.point_a), float)
    name = getattr(contact, "name", "") or id
    out = []
    if contact.kind == "slider":
        p0, e, n, hw, (s0, s1) = slider_guide(contact, pose, body_shape, clearance=clearance)
        ang = float(np.arctan2(e[1], e[0]))
        length = s1 - s0
        mid = p0 + e * (s0 + s1) / 2
        for k, side in enumerate((1.0, -1.0)):
            wall = mid + side * hw * n
            wid = f"{id}:wall {k + 1}"
            if contact.b < 0:   # hatching on the outside of each wall
                out.append(ground(pic, wid, wall, width=length, angle=ang if side < 0 else ang + np.pi,
                                  depth=0.6 * size, n=max(int(round(length / (1.5 * size))), 2),
                                  z=z - 5, desc=f"guide wall of slider contact {name}"))
            else:
                out.append(added(pic.path, wid, np.array([wall - e * length / 2, wall + e * length / 2]),
                                 role="ground", color=COLORS["ground"], width=1.2 * PX_PER_PT, z=z - 5,
                                 desc=f"guide wall of slider contact {name} (on body {contact.b + 1})"))
        out.append(added(pic.marks, id, [pa], role="body", color=DARK, size=2.5 * PX_PER_PT, z=z,
                         desc=f"slider contact {name} (9.83): its point on body {contact.a + 1}"))
        return out
    filled = contact.kind == "weld"
    out.append(added(pic.path, id, pa + _SQUARE * size / 2, role="body", closed=True, color=DARK,
                     fill=DARK if filled else "white", width=1.0 * PX_PER_PT, z=z,
                     desc=f"{contact.kind} contact {name} (9.49)"))
    return out


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


@documented
def model_shapes(model, data, *, width: float = 0.18) -> list:
    """The bodies of ``model`` at the state ``data`` as :func:`model` draws them (world shapely shapes).

    A body's ``shape`` moved by its pose, else a rounded link from its joint to each child's
    (a tip body: through its centre of mass to twice as far).

    {parameters model width}

    Returns
    -------
    list of shapely geometry

    Examples
    --------
    >>> from planargeo.gallery.figures import chain
    >>> from planargeo.mechanics.kinematics import kinematics
    >>> m = chain(2)
    >>> d = kinematics(m, np.zeros(2), np.zeros(2))
    >>> [round(v, 6) for v in model_shapes(m, d, width=0.2)[1].bounds]    # link 2 from (1, 0) to (2, 0)
    [0.9, -0.1, 2.1, 0.1]
    """
    from shapely.ops import unary_union

    pose, cm, origin = (np.asarray(v, float) for v in (data.pose, data.com, data.origin))
    out = []
    for i, b in enumerate(model.bodies):
        if b.shape is not None:
            out.append(transform_shape(b.shape, pose[i]))
        else:
            ends = [origin[k] for k in model.children(i)] or [pose[i, :2] + 2 * (cm[i] - pose[i, :2])]
            out.append(unary_union([link_polygon(pose[i, :2], e, width) for e in ends]))
    return out


@documented
def split_arrows(s, R, A, f, *, scale: float = 1.0, anchor, avoid=None, clearance: float = 0.1):
    """The split ``f = T Q + R μ`` of a joint force (6.38) and the arrows :func:`joint_split` draws.

    Each arrow is ``scale |part|`` long on its line, centred on ``anchor``'s foot, slid along
    its line to ``clearance`` from ``avoid`` and from the arrows before it.

    Parameters
    ----------
    s, R, A : array_like (3, k), (3, 3 - k), (3, 3)
        The joint's motion and reaction spaces, and the (articulated) inertia of the split.
    f : array_like (3,)
        The joint force.
    {scale}
    anchor : (float, float)
        Where the arrows sit along their lines.
    {avoid}

    Returns
    -------
    tuple
        ``({"f", "active", "reaction"}: (tail, tip) or None, (Q, μ, TQ, Rμ))``; None for a
        part with no arrow (zero, or the line at infinity).

    Raises
    ------
    InputError
        ``anchor`` not a finite point.

    Examples
    --------
    >>> from planargeo.mechanics.joints import revolute
    >>> from planargeo.screws.twists import inertia_matrix
    >>> j = revolute([0.0, 0.0])
    >>> A = inertia_matrix(2.0, [1.0, 0.0], 0.3)
    >>> arrows, (Q, mu, TQ, Rmu) = split_arrows(j.s, j.R, A, [0.0, 1.0, 2.0], anchor=(0.0, 0.0))
    >>> [v.round(6).tolist() for v in arrows["f"]]          # on the line x = 2, centred at (2, 0)
    [[2.0, -0.5], [2.0, 0.5]]
    """
    from shapely.geometry import LineString

    anchor = _xy(anchor, "anchor")
    f = np.asarray(f, float).reshape(3)
    v = wrench_parts(s, R, A, f)
    Q, mu, active, react = v["Q"], v["mu"], v["f1"], v["f2"]
    arrows = {}
    blocked = avoid
    for k, w in (("f", f), ("active", active), ("reaction", react)):
        F = math.hypot(w[0], w[1])
        if not (F > 1e-12 * max(1.0, float(np.max(np.abs(f))))):
            arrows[k] = None
            continue
        e = w[:2] / F
        half = 0.5 * scale * F * e
        mid = foot_on_line(w, anchor)
        if avoid is not None:
            mid = _slide_clear(w, 2 * float(np.hypot(*half)), mid, blocked, clearance)
        tail, tip = mid - half, mid + half
        arrows[k] = (tail, tip)
        if avoid is not None:
            blocked = blocked.union(LineString([tail, tip]))
    return arrows, (Q, mu, active, react)


@documented
def joint_split(pic: Picture, id: str, s, R, A, f, *, name: str = "", scale: float = 1.0, anchor=None,
                gap: float = 5.0, avoid=None, clearance: float = 0.1):
    """A joint force ``f`` split into its active part ``T Q`` and its reaction ``R μ`` (6.38).

    Three lines with arrows (:func:`split_arrows`): ``id + ":f"``, ``":active"`` (dashed) and
    ``":reaction"`` (dotted), each labelled on the side of its arrow with the most room.

    {parameters pic}
    id : str
        Stem of the three elements' ids.
    s, R, A, f
        Motion space, reaction space, inertia of the split and the joint force.
    name : str
        Subscript of the labels (``f_name``, ``TQ_name``, ``Rμ_name``).
    {scale}
    anchor : (float, float), optional
        Where the arrows sit along their lines (default: the view's centre).
    gap : float
        Distance of a label from its arrow (points).
    {avoid}

    Returns
    -------
    tuple
        ``({"f", "active", "reaction"}: element or None, (Q, μ, TQ, Rμ))``.

    Examples
    --------
    >>> from planargeo.mechanics.joints import revolute
    >>> from planargeo.screws.twists import inertia_matrix
    >>> pic = Picture((-1, 3, -2, 2), size=(200, 200), ticks=False, margin=(0, 0, 0, 0))
    >>> j = revolute([0.0, 0.0])
    >>> A = inertia_matrix(2.0, [1.0, 0.0], 0.3)
    >>> out, (Q, mu, TQ, Rmu) = joint_split(pic, "j1", j.s, j.R, A, [0.0, 1.0, 2.0], name="1",
    ...                                     anchor=[0.0, 0.0])
    >>> bool(np.allclose(TQ + Rmu, [0.0, 1.0, 2.0])), sorted(out)
    (True, ['active', 'f', 'reaction'])
    """
    from shapely.geometry import Point as SPoint

    as_picture(pic)
    if anchor is None:
        anchor = view_centre(pic)
    arrows, split = split_arrows(s, R, A, f, scale=scale, anchor=anchor, avoid=avoid,
                                 clearance=clearance)
    Q, mu, active, react = split
    lines = {"f": (np.asarray(f, float).reshape(3), "wrench", None, f"$f_{{{name}}}$",
                   "joint force (6.38)"),
             "active": (active, "momentum", [6.0 * PX_PER_PT, 2.0 * PX_PER_PT], f"$TQ_{{{name}}}$",
                        "active part T Q of the joint force (6.38)"),
             "reaction": (react, "reaction", [2.0 * PX_PER_PT, 2.0 * PX_PER_PT], f"$R\\mu_{{{name}}}$",
                          "reaction part R μ of the joint force (6.38)")}
    out, placed = {}, []
    segs = {k: v for k, v in arrows.items() if v is not None}
    for k, (w, role, dash, text, meaning) in lines.items():
        text = plain_text(text)
        F = math.hypot(w[0], w[1])
        eid = f"{id}:{k}"
        if arrows[k] is None:
            couple = abs(w[2]) > 1e-12 * max(1.0, float(np.max(np.abs(f)))) and F == 0.0
            out[k] = added(pic.line, eid, w, role=role, symbol=text, dash=dash,
                           desc=f"{meaning}: a couple of {w[2]:.3g} N·m") if couple else None
            continue
        tail, tip = arrows[k]
        mid = 0.5 * (tail + tip)
        force_arrow(pic, eid, w, scale=scale, anchor=mid, role=role, symbol=text, label="",
                    dash=dash, desc=f"{meaning}: |{text}| = {F:.3g} N",
                    width=LINEWIDTHS[role] * PX_PER_PT)
        out[k] = pic.elements[-1]
        d = tip - tail
        L = float(np.hypot(*d))
        n = np.array([-d[1], d[0]]) / L
        others = [v for j, v in segs.items() if j != k]

        def label_room(side):
            c = mid + side * n * 0.25 * L
            dist = [seg_distance(c, [o]) for o in others] + [float(np.hypot(*(c - p))) for p in placed]
            if avoid is not None:
                dist.append(float(avoid.distance(SPoint(*c))))
            return min(dist) if dist else 0.0

        side = 1.0 if label_room(1.0) >= label_room(-1.0) else -1.0
        placed.append(mid + side * n * 0.25 * L)
        out[k]["parts"].append(_beside(mid, side * n * (pic.kx, pic.ky), text, gap * PX_PER_PT))
    return out, split
