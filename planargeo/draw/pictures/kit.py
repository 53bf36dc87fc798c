"""Steps shared by the mechanism pictures (car, slider-crank, trees): forces to scale, ground, scale bar.

Examples
--------
>>> from planargeo.draw.picture import Picture
>>> pic = Picture((-2, 2, -2, 2), size=(200, 200), ticks=False)
>>> foot = force(pic, "f", [0.0, 10.0, 0.0], scale=0.1, anchor=(0.0, 0.0), symbol="f", desc="a push")
>>> [round(float(v), 6) for v in foot]              # the line x = 0 through the anchor
[0.0, 0.0]
>>> [p["p"] for p in pic.elements[-1]["parts"]]
['path', 'arrow', 'text']
"""
from __future__ import annotations

import math

import numpy as np

from planargeo.draw.geometry import clip_line, point_xy
from planargeo.draw.picture import PX_PER_PT, Picture, _text_part
from planargeo.draw.pictures._words import num as _num, subscript
from planargeo.draw.pictures.common import label_toward as aim_label
from planargeo.draw.style import COLORS

__all__ = ["force", "ground", "scale_bar", "label_at", "aim_label", "side_label", "clearest", "clearest_sides",
           "pin_heads", "seg_distance",
           "foot_on_line", "nice_length", "where", "rate", "pole_overlays", "pole_groups", "POLES_APART_PX"]


def foot_on_line(w, p) -> np.ndarray:
    """The foot of the point ``p`` on the line of action of the wrench ``w = [fx, fy, τ]`` (4.27).

    Parameters
    ----------
    w : array_like (3,)
        A force with ``fx² + fy² > 0``.
    p : (float, float)
        The point.

    Returns
    -------
    numpy.ndarray (2,)

    Examples
    --------
    >>> foot_on_line([1.0, 0.0, 2.0], (3.0, 0.0)).tolist()     # the line y = -2 (τ + y fx = 0)
    [3.0, -2.0]
    """
    fx, fy, tz = (float(v) for v in w)
    p = np.asarray(p, dtype=float)
    F = math.hypot(fx, fy)
    m_p = tz + p[1] * fx - p[0] * fy                 # the moment about p: the line's value there
    return p - (m_p / F) * np.array([-fy, fx]) / F


def label_at(pic: Picture, xy, text: str, *, gap: float = 6.0, dy: float | None = None,
             ha: str = "left", va: str = "bottom") -> None:
    """Add a label (moved by the picture's placer) ``gap`` pixels from ``xy`` to the element added last.

    Parameters
    ----------
    pic, xy, text, gap
    dy, ha, va : optional
        Its offset up in pixels (default: ``gap``) and its alignment.
    """
    x, y = (float(v) for v in xy)
    if text and math.isfinite(x) and math.isfinite(y):
        pic.elements[-1]["parts"].append(_text_part(x, y, text, gap, gap if dy is None else dy, ha, va))


def force(pic: Picture, id: str, w, *, scale: float, anchor, role: str = "reaction",
          symbol: str = "", desc: str = "", label: str | None = None, reach: float | None = None,
          color: str | None = None, width: float | None = None, dash=None, opacity: float = 1.0,
          start: bool = False, z: int = 5, label_xy=None):
    """A force on its line of action with an arrow ``scale |f|`` long (data units) at the anchor's foot.

    Parameters
    ----------
    pic : Picture
    id, role, symbol, desc : str
        The element's id, style role, thesis symbol and description.
    w : array_like (3,)
        The wrench ``[fx, fy, τ]`` (N, N·m).
    scale : float
        Arrow length per newton (data units).
    anchor : (float, float)
        The arrow sits at this point's foot on the line.
    label : str, optional
        Text at the arrow (default: the symbol; "" for none).
    reach : float, optional
        The line drawn only ``reach`` either side of the foot (default: across the view).
    color, width, dash, opacity, z
        Line colour, width and dash (pixels), the element's opacity and drawing order.
    start : bool
        The arrow starts at the foot (default: it is centred on it).
    label_xy : (float, float), optional
        The label sits at this point's foot on the line (default: the arrow's middle).

    Returns
    -------
    numpy.ndarray or None
        The foot (where the arrow and the label sit), None for a zero force (nothing drawn).
    """
    w = np.asarray(w, dtype=float)
    F = math.hypot(w[0], w[1])
    if not F > 0.0 or not math.isfinite(F):
        return None
    e = w[:2] / F
    foot = foot_on_line(w, anchor)
    if reach is None:
        seg = clip_line(w, pic.box)
        seg = [] if seg is None else [np.asarray(seg, float)]
    else:
        seg = [np.array([foot - reach * e, foot + reach * e])]
    parts = [{"p": "path", "xy": s, "closed": False} for s in seg]
    v = scale * F * e
    tail = foot if start else foot - 0.5 * v
    dx, dy = float(v[0] * pic.kx), float(v[1] * pic.ky)
    if math.hypot(dx, dy) >= 2.0:
        parts.append({"p": "arrow", "x": float(tail[0]), "y": float(tail[1]), "dx": dx, "dy": dy})
    text = symbol if label is None else label
    if text:
        at = tail + 0.5 * v if label_xy is None else foot_on_line(w, label_xy)
        parts.append({"p": "text", "x": float(at[0]), "y": float(at[1]), "dx": 6.0, "dy": 6.0,
                      "text": text, "ha": "left", "va": "bottom"})     # mathtext kept for matplotlib
    pic.path(id, np.zeros((0, 2)), role=role, symbol=symbol, desc=desc, color=color, width=width,
             dash=dash, z=z, opacity=float(opacity))
    pic.elements[-1]["parts"] = parts
    return foot


def ground(pic: Picture, id: str, xy, *, width: float = 0.9, depth: float = 0.12, n: int = 7,
           desc: str = "the ground", opacity: float = 1.0) -> None:
    """A ground line of ``width`` centred on ``xy`` with ``n`` hatch strokes ``depth`` deep below it.

    Parameters
    ----------
    pic, id, desc, xy, width, depth, n, opacity
    """
    x, y = (float(v) for v in xy)
    rows = [[x - width / 2, y], [x + width / 2, y], [np.nan, np.nan]]
    for u in np.linspace(x - width / 2 + depth, x + width / 2, n):
        rows += [[u, y], [u - depth, y - depth], [np.nan, np.nan]]
    pic.path(id, np.array(rows), role="ground", symbol="ground", color=COLORS["ground"], width=1.4, desc=desc,
             z=1, opacity=float(opacity))


def _distances(points, segs, *, each: bool = False) -> np.ndarray:
    """The distance from each of ``points`` ``(k, 2)`` to the nearest of the segments ``segs`` ``(n, 2, 2)``
    (``each``: to every segment, ``(k, n)``)."""
    points = np.asarray(points, dtype=float).reshape(-1, 2)
    segs = np.asarray(segs, dtype=float).reshape(-1, 2, 2)
    if not len(segs):
        return np.full((len(points), 0) if each else len(points), math.inf)
    a, d = segs[:, 0], segs[:, 1] - segs[:, 0]
    L2 = np.einsum("ij,ij->i", d, d)
    t = np.clip(np.einsum("kij,ij->ki", points[:, None] - a, d) / np.where(L2 > 0, L2, 1.0), 0.0, 1.0)
    gap = a + t[..., None] * d - points[:, None]
    gap = np.hypot(gap[..., 0], gap[..., 1])
    return gap if each else np.min(gap, axis=1)


def seg_distance(p, segs) -> float:
    """The distance from the point ``p`` to the nearest of the segments ``segs`` ``(n, 2, 2)``.

    Parameters
    ----------
    p, segs

    Returns
    -------
    float

    Examples
    --------
    >>> seg_distance((0.0, 1.0), [[[-1.0, 0.0], [1.0, 0.0]], [[3.0, 0.0], [3.0, 2.0]]])
    1.0
    """
    return float(_distances(p, segs)[0])


def clearest(points, segs):
    """The point of ``points`` farthest from every segment of ``segs`` (a label's place off the links).

    Parameters
    ----------
    points, segs

    Returns
    -------
    numpy.ndarray (2,)

    Examples
    --------
    >>> clearest([(0.0, 0.1), (0.0, 2.0)], [[[-1.0, 0.0], [1.0, 0.0]]]).tolist()
    [0.0, 2.0]
    """
    points = np.asarray(points, dtype=float).reshape(-1, 2)
    return points[int(np.argmax(_distances(points, segs)))]


def _sides(a, b):
    """The middle ``m`` of the segment ``a``–``b``, its unit normal ``n`` and the spots ``m ± span n`` beside it."""
    a, b = np.asarray(a, float), np.asarray(b, float)
    m = 0.5 * (a + b)
    d = b - a
    L = math.hypot(*d)
    n = np.array([-d[1], d[0]]) / L if L > 0 else np.array([0.0, 1.0])
    span = 0.25 * max(L, 1e-9)
    return m, n, [m + span * n, m - span * n]


def clearest_sides(segs) -> np.ndarray:
    """For each of the segments ``segs`` ``(n, 2, 2)``, the spot beside it clearer of the others (as
    :func:`side_label` picks it, in one measure).

    Parameters
    ----------
    segs

    Returns
    -------
    numpy.ndarray (n, 2)

    Examples
    --------
    >>> clearest_sides([[[0.0, 0.0], [2.0, 0.0]], [[0.0, 1.0], [2.0, 1.0]]]).tolist()     # two rails
    [[1.0, -0.5], [1.0, 1.5]]
    """
    segs = np.asarray(segs, dtype=float).reshape(-1, 2, 2)
    spots = np.array([_sides(a, b)[2] for a, b in segs]).reshape(-1, 2)           # (2n, 2)
    gap = _distances(spots, segs, each=True)
    gap[np.arange(len(spots)), np.arange(len(spots)) // 2] = math.inf              # not its own segment
    far = np.argmax(np.min(gap, axis=1, initial=math.inf).reshape(-1, 2), axis=1)
    return spots.reshape(-1, 2, 2)[np.arange(len(segs)), far]


def side_label(pic: Picture, a, b, text: str, segs, *, gap: float = 5.0, side=None) -> None:
    """Label the segment ``a``–``b`` (the element added last) at its middle, on its side clearer of ``segs``.

    Parameters
    ----------
    pic, a, b, text, segs
    gap : float
        Pixels from the segment.
    side : (float, float), optional
        The spot beside it already picked (:func:`clearest_sides`; then ``segs`` is not used).
    """
    m, n, spots = _sides(a, b)
    side = clearest(spots, segs) if side is None else side
    label_at(pic, m, text, gap=gap)
    aim_label(pic.elements[-1], n if float((side - m) @ n) > 0 else -n, gap + 4.0)


def pin_heads(forces, spots, obstacles) -> np.ndarray:
    """For each pin force (``point``, ``wrench``) of ``forces``, the point ``spots`` along its line from
    the pin clearest of the segments ``obstacles`` (one measure for all).

    Parameters
    ----------
    forces, spots, obstacles

    Returns
    -------
    numpy.ndarray (len(forces), 2)

    Examples
    --------
    >>> from types import SimpleNamespace
    >>> up = SimpleNamespace(point=(0.0, 0.0), wrench=(0.0, 2.0, 0.0))
    >>> pin_heads([up], (0.5, -0.5), [[[-1.0, 0.4], [1.0, 0.4]]]).tolist()       # below, clear of the bar
    [[0.0, -0.5]]
    """
    pts = []
    for x in forces:
        f = np.asarray(x.wrench, float)
        F = math.hypot(f[0], f[1])
        e = f[:2] / F if F else np.zeros(2)
        pts += [np.asarray(x.point, float) + k * e for k in spots]
    pts = np.asarray(pts, dtype=float).reshape(len(forces), len(spots), 2)
    far = np.argmax(_distances(pts, obstacles).reshape(len(forces), len(spots)), axis=1)
    return pts[np.arange(len(forces)), far]


def pin_force(pic: Picture, sym: str, x, w, *, words: str, about: str, tiny: float, head, **kw):
    """A mechanism's pin force ``x`` (``point``, ``wrench``, ``moment``) drawn as ``w`` with :func:`force`,
    described as ``words, |sym| = … N`` with its moment about its ``about`` (above ``tiny``),
    labelled at ``head`` (:func:`pin_heads`)."""
    f = np.asarray(x.wrench, float)
    F = math.hypot(f[0], f[1])
    moment = f", moment {num(x.moment, 3, tiny)} N·m about its {about}" if abs(x.moment) > tiny else ""
    return force(pic, sym, w, anchor=x.point, symbol=sym, dash=[4.0, 3.0], label_xy=head,
                 desc=f"{words}, |{sym}| = {num(F, 4, tiny)} N{moment}", **kw)


def num(x: float, digits: int = 3, tiny: float = 1e-9) -> str:
    """:func:`planargeo.draw.pictures._words.num`, three digits by default."""
    return _num(x, digits, tiny)


def where(p, *, far: float = 1e6) -> str:
    """Where the pole ``p = [vx, vy, w]`` lies: ``"at (x, y) m"``, or at infinity beyond ``far`` m.

    Parameters
    ----------
    p, far

    Returns
    -------
    str

    Examples
    --------
    >>> where([0.0, -2.0, 1.0]), where([1.0, 0.0, 8.88e-16])
    ('at (2, 0) m', 'at infinity (a translation)')
    """
    xy = point_xy(p)
    if xy is None or not np.all(np.isfinite(xy)) or math.hypot(*xy) > far:
        return "at infinity (a translation)"
    return f"at ({num(xy[0])}, {num(xy[1])}) m"


def rate(p, unit: str, *, far: float = 1e6) -> str:
    """The rate (weight) of the pole ``p``, 0 when the pole is at infinity (:func:`where`).

    Parameters
    ----------
    p, unit, far

    Returns
    -------
    str

    Examples
    --------
    >>> rate([0.0, -2.0, 1.0], "rad/s"), rate([1.0, 0.0, 8.88e-16], "rad/s")
    ('rate 1 rad/s', 'rate 0 rad/s')
    """
    w = 0.0 if where(p, far=far).startswith("at infinity") else float(p[2])
    return f"rate {num(w)} {unit}"


def nice_length(span: float) -> float:
    """A round length (1, 2 or 5 × 10ᵏ) near a fifth of ``span``.

    Parameters
    ----------
    span : float
        Width of the view (m).

    Returns
    -------
    float
        The length of the scale bar (m).

    Examples
    --------
    >>> nice_length(12.0), nice_length(8.6), nice_length(30.0)
    (2.0, 2.0, 5.0)
    """
    raw = span / 5.0
    mag = 10.0 ** math.floor(math.log10(raw))
    return max((m * mag for m in (1.0, 2.0, 5.0) if m * mag <= raw * 1.5), default=mag)


#: poles closer than this on the picture (px) share one label naming them all (their glyphs pile up)
POLES_APART_PX = 20.0


def pole_groups(pic: Picture, pts) -> list[list[int]]:
    """The poles ``pts`` drawn within :data:`POLES_APART_PX` of one another, chained, as groups.

    Parameters
    ----------
    pic : Picture
        The picture they are drawn in (its view and scale).
    pts : array_like (n, 3)
        The poles, rows ``[vx, vy, w]``.

    Returns
    -------
    list of list of int
        Groups of indices, in order; a pole at infinity or out of view is a group of its own.

    Examples
    --------
    >>> pic = Picture((-2, 2, -2, 2), size=(200, 200), ticks=False)       # 50 px a metre
    >>> pole_groups(pic, [[0, 0, 1], [0.0, 0.2, 1], [0, 0, 0], [0.0, 0.4, 1.0], [0, 0, 2]])
    [[0, 1, 3, 4], [2]]
    """
    pts = np.asarray(pts, float).reshape(-1, 3)
    x0, x1, y0, y1 = pic.box
    at = {}
    for i, (p0, p1, p2) in enumerate(pts):
        if p2 != 0.0:
            x, y = -p1 / p2, p0 / p2                     # point_xy of a finite pole
            if math.isfinite(x) and math.isfinite(y) and x0 <= x <= x1 and y0 <= y <= y1:
                at[i] = (x * pic.kx, y * pic.ky)
    group = list(range(len(pts)))                        # each pole's group: the least index joined to it
    for i in at:
        for j in at:
            if j < i and math.hypot(at[i][0] - at[j][0], at[i][1] - at[j][1]) < POLES_APART_PX:
                gi, gj = group[i], group[j]
                group = [min(gi, gj) if g in (gi, gj) else g for g in group]
    out: dict[int, list[int]] = {}
    for i, g in enumerate(group):
        out.setdefault(g, []).append(i)
    return list(out.values())


def pole_overlays(pic: Picture, v, a, overlays: dict, bodies, scales=(3.0, 0.3)) -> None:
    """The velocity poles (4.5) and acceleration poles (4.6) of the bodies, as ``overlays`` asks.

    Poles drawn closer than :data:`POLES_APART_PX` share one label naming them all (``v₁, v₅, v₆``),
    at the first of them; each keeps its glyph and description.

    Parameters
    ----------
    pic : Picture
    v, a : array_like (n, 3)
        Velocity and acceleration twists of the bodies.
    overlays : dict
        ``{"velocity poles": shown, "acceleration poles": shown}``.
    bodies : sequence of str
        Each body's name in the descriptions (``"body 1"``, ``"of the crank"``).
    scales : (float, float)
        Glyph scales of the velocity and the acceleration poles.

    Examples
    --------
    >>> pic = Picture((-2, 2, -2, 2), size=(200, 200), ticks=False)
    >>> pole_overlays(pic, [[0, 0, 1], [0.0, 0.1, 2]], None, {"velocity poles": True}, ["body 1", "body 2"])
    >>> [[q["text"] for q in e["parts"] if q["p"] == "text"] for e in pic.elements]
    [['v₁, v₂'], []]
    """
    for key, pts, flag, role, gs, meaning, eq, unit in (
            ("v", v, "velocity poles", "twist", scales[0], "velocity pole", "4.5", "rad/s"),
            ("a", a, "acceleration poles", "accel", scales[1], "acceleration pole", "4.6", "rad/s²")):
        if overlays.get(flag):
            pts = np.asarray(pts, float)
            label, said = {}, {}                   # a shared label, and what each description adds
            for g in pole_groups(pic, pts[:len(bodies)]):
                if len(g) > 1:
                    names = ", ".join(f"{key}{subscript(i + 1)}" for i in g)
                    first = f"{key}{subscript(g[0] + 1)}"
                    label.update({i: "" for i in g})
                    label[g[0]] = names
                    said.update({i: f"; drawn close together, {names}, named in one label at {first}" for i in g})
            for i, body in enumerate(bodies):
                sym = f"{key}{subscript(i + 1)}"
                pic.point(sym, pts[i], role=role, symbol=sym, glyph_scale=gs, label=label.get(i),
                          desc=f"{meaning} ({eq}): {body}, {rate(pts[i], unit)}, {where(pts[i])}{said.get(i, '')}")


def scale_bar(pic: Picture, unit: str = "m") -> float:
    """A bar of a round length in the lower left corner of the view, labelled with it.

    Parameters
    ----------
    pic, unit

    Returns
    -------
    float
        The bar's length.
    """
    x0, x1, y0, y1 = pic.box
    L = nice_length(x1 - x0)
    pad_x, pad_y = 10.0 / pic.kx, 12.0 / pic.ky
    xy = np.array([[x0 + pad_x, y0 + pad_y], [x0 + pad_x + L, y0 + pad_y]])
    pic.path("scale bar", xy, role="construct", symbol="scale", color=COLORS["text"], width=2.0 * PX_PER_PT,
             desc=f"scale bar: {L:g} {unit}", z=1)
    label_at(pic, xy[1], f"{L:g} {unit}", gap=4.0, dy=0.0, va="center")
    return L
