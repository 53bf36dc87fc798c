"""Small SVG drawings of single elements, for notebooks (``_repr_svg_``), without matplotlib.

A point, a line, a conic, a twist, a wrench or an inertia is drawn in a
240 × 240 pixel panel whose view box is fitted to the element (and the origin
``O``, marked grey, for orientation), with a caption band below naming the
element.  Ideal elements are ordinary values here too (conventions): a point
at infinity is a labelled arrow pointing in its direction, the line at
infinity a dashed frame around the panel with the note "line at infinity",
and an imaginary conic (an inertia) is drawn as its real point-reflection
partner, the sign-flipped conic of thesis 10.2.3 (for an inertia the circle of
gyration), dashed, with a note saying so.

The output is deterministic (coordinates printed with two decimals, no ids
or dates) and is valid XML; every text is 12 px high.  Only numpy and the
geometry functions are used: the math layers never import matplotlib.

Examples
--------
>>> import xml.etree.ElementTree as ET
>>> svg = point_svg([2.0, -1.0, 1.0], label="P")          # the point (1, 2)
>>> ET.fromstring(svg).tag
'{http://www.w3.org/2000/svg}svg'
>>> "P = (1, 2)" in svg
True
>>> "line at infinity" in line_svg([0.0, 0.0, 1.0])
True
"""
from __future__ import annotations

import math
from xml.sax.saxutils import escape

import numpy as np

from planargeo.errors import InputError

__all__ = ["SvgPanel", "point_svg", "line_svg", "conic_svg", "twist_svg", "wrench_svg",
           "inertia_svg", "FONT_PX"]

#: Text height (px) of every label: at least the 11 px the legibility rule asks for.
FONT_PX = 12
_SIZE = 240
_PAD = 22

_BLUE, _VERMILLION, _ORANGE, _GREEN, _GREY, _BLACK = ("#0072B2", "#D55E00", "#E69F00", "#009E73",
                                                       "#7F7F7F", "#000000")


def _num(x: float, digits: int = 3) -> str:
    """A short number for a caption: ``-0`` and round-off relative to 1e-12 print as ``0``."""
    x = float(x)
    if not math.isfinite(x):
        return "∞" if x > 0 else ("−∞" if x < 0 else "nan")
    if abs(x) < 1e-12:
        return "0"
    s = f"{x:.{digits}g}"
    return "0" if s in ("-0", "0") else s


def _pair(xy) -> str:
    return f"({_num(xy[0])}, {_num(xy[1])})"


def _vec3(x, name: str) -> np.ndarray:
    a = np.asarray(getattr(x, "array", x), dtype=float)
    if a.shape != (3,):
        raise InputError(f"{name} must be a single homogeneous (3,) vector, got shape {a.shape}")
    if not np.all(np.isfinite(a)):
        raise InputError(f"{name} must be finite, got {a.tolist()}")
    return a


def _mat3(x, name: str) -> np.ndarray:
    a = np.asarray(getattr(x, "matrix", x), dtype=float)
    if a.shape != (3, 3):
        raise InputError(f"{name} must be a single (3, 3) matrix, got shape {a.shape}")
    if not np.all(np.isfinite(a)):
        raise InputError(f"{name} must be finite")
    return 0.5 * (a + a.T)


class SvgPanel:
    """A square SVG panel showing the data box ``box = (x0, x1, y0, y1)``, with a caption band.

    Drawing methods take data coordinates (y up); :meth:`svg` returns the text.

    Parameters
    ----------
    box : (float, float, float, float)
        The data rectangle shown (widened to a square about its centre).
    title : str
        The accessible title (``<title>``) of the drawing.

    Raises
    ------
    InputError
        A box that is empty or not finite.

    Examples
    --------
    >>> p = SvgPanel((-1, 1, -1, 1), "demo")
    >>> p.dot((0.0, 0.0), _BLACK)
    >>> p.caption("the origin")
    >>> p.svg().count("<circle")
    1
    """

    def __init__(self, box, title: str):
        x0, x1, y0, y1 = (float(v) for v in box)
        if not all(map(math.isfinite, (x0, x1, y0, y1))) or x1 <= x0 or y1 <= y0:
            raise InputError(f"box must be a finite, non-empty (x0, x1, y0, y1), got {box!r}")
        half = max(x1 - x0, y1 - y0) / 2
        self.cx, self.cy, self.half = (x0 + x1) / 2, (y0 + y1) / 2, half
        self.k = (_SIZE - 2 * _PAD) / (2 * half)
        self.title = title
        self._items: list[str] = []
        self._captions: list[str] = []

    # -- coordinates ------------------------------------------------------
    @property
    def box(self) -> tuple[float, float, float, float]:
        """The square data box shown ``(x0, x1, y0, y1)``.

        Returns
        -------
        tuple of float
        """
        h = self.half + _PAD / self.k
        return (self.cx - h, self.cx + h, self.cy - h, self.cy + h)

    def px(self, xy) -> tuple[float, float]:
        """Pixel position of the data point ``xy`` (y down).

        Parameters
        ----------
        xy : array_like (2,)

        Returns
        -------
        (float, float)
        """
        return (_SIZE / 2 + self.k * (float(xy[0]) - self.cx),
                _SIZE / 2 - self.k * (float(xy[1]) - self.cy))

    def clip(self, point, direction):
        """The segment of the line through ``point`` along ``direction`` inside the panel, or None.

        Parameters
        ----------
        point, direction : array_like (2,)

        Returns
        -------
        (ndarray, ndarray) or None
        """
        p, d = np.asarray(point, float), np.asarray(direction, float)
        x0, x1, y0, y1 = self.box
        lo, hi = -np.inf, np.inf
        for k, (a, b) in enumerate(((x0, x1), (y0, y1))):
            if d[k] == 0:
                if not a <= p[k] <= b:
                    return None
                continue
            t1, t2 = sorted(((a - p[k]) / d[k], (b - p[k]) / d[k]))
            lo, hi = max(lo, t1), min(hi, t2)
        if not lo < hi:
            return None
        return p + lo * d, p + hi * d

    # -- drawing ----------------------------------------------------------
    def _add(self, s: str) -> None:
        self._items.append(s)

    def polyline(self, points, color: str, width: float = 1.5, dash: str | None = None) -> None:
        """A polyline through data ``points`` (n, 2).

        Parameters
        ----------
        points : array_like (n, 2)
        color : str
        width : float
        dash : str, optional
            An SVG ``stroke-dasharray``.
        """
        pts = " ".join(f"{x:.2f},{y:.2f}" for x, y in (self.px(p) for p in np.asarray(points, float)))
        d = f' stroke-dasharray="{dash}"' if dash else ""
        self._add(f'<polyline points="{pts}" fill="none" stroke="{color}" '
                  f'stroke-width="{width:g}"{d}/>')

    def arrow(self, p, q, color: str, width: float = 1.8, head: float = 9.0) -> None:
        """An arrow from data point ``p`` to ``q`` with a filled head of ``head`` pixels.

        Parameters
        ----------
        p, q : array_like (2,)
        color : str
        width, head : float
        """
        (x0, y0), (x1, y1) = self.px(p), self.px(q)
        L = math.hypot(x1 - x0, y1 - y0)
        if L == 0:
            return
        ux, uy = (x1 - x0) / L, (y1 - y0) / L
        bx, by = x1 - head * ux, y1 - head * uy
        self._add(f'<line x1="{x0:.2f}" y1="{y0:.2f}" x2="{bx:.2f}" y2="{by:.2f}" '
                  f'stroke="{color}" stroke-width="{width:g}"/>')
        w = head * 0.45
        self._add(f'<polygon points="{x1:.2f},{y1:.2f} {bx - w * uy:.2f},{by + w * ux:.2f} '
                  f'{bx + w * uy:.2f},{by - w * ux:.2f}" fill="{color}"/>')

    def dot(self, p, color: str, r: float = 4.0, hollow: bool = False) -> None:
        """A dot of radius ``r`` pixels at data point ``p``.

        Parameters
        ----------
        p : array_like (2,)
        color : str
        r : float
        hollow : bool
            An open circle instead of a filled one.
        """
        x, y = self.px(p)
        fill = "white" if hollow else color
        self._add(f'<circle cx="{x:.2f}" cy="{y:.2f}" r="{r:g}" fill="{fill}" stroke="{color}" '
                  f'stroke-width="1.2"/>')

    def spin(self, p, ccw: bool, color: str, r: float = 13.0) -> None:
        """A three-quarter arc with an arrow head about data point ``p``: the sense of a rotation.

        Parameters
        ----------
        p : array_like (2,)
        ccw : bool
            Counter-clockwise (positive) on screen.
        color : str
        r : float
            Radius in pixels.
        """
        x, y = self.px(p)
        a0, a1 = (math.radians(200), math.radians(-60)) if ccw else (math.radians(-20), math.radians(240))
        # screen y is down: a counter-clockwise turn on screen decreases the screen angle
        pts = [(x + r * math.cos(a), y - r * math.sin(a)) for a in np.linspace(a0, a1, 24)]
        self._add('<polyline points="' + " ".join(f"{u:.2f},{v:.2f}" for u, v in pts)
                  + f'" fill="none" stroke="{color}" stroke-width="1.4"/>')
        (u0, v0), (u1, v1) = pts[-2], pts[-1]
        L = math.hypot(u1 - u0, v1 - v0)
        ux, uy = (u1 - u0) / L, (v1 - v0) / L
        h, w = 7.0, 3.5
        bx, by = u1 - h * ux, v1 - h * uy
        self._add(f'<polygon points="{u1 + 2 * ux:.2f},{v1 + 2 * uy:.2f} {bx - w * uy:.2f},'
                  f'{by + w * ux:.2f} {bx + w * uy:.2f},{by - w * ux:.2f}" fill="{color}"/>')

    def text(self, p, s: str, color: str = _BLACK, dx: float = 7.0, dy: float = -7.0,
             anchor: str = "start") -> None:
        """Text ``s`` at data point ``p`` shifted by ``(dx, dy)`` pixels, kept inside the panel.

        Parameters
        ----------
        p : array_like (2,)
        s : str
        color : str
        dx, dy : float
        anchor : {"start", "middle", "end"}
        """
        x, y = self.px(p)
        x, y = x + dx, y + dy
        width = 0.6 * FONT_PX * len(s)
        left = {"start": x, "middle": x - width / 2, "end": x - width}[anchor]
        if left < 2:
            x += 2 - left
        elif left + width > _SIZE - 2:
            x -= left + width - (_SIZE - 2)
        y = min(max(y, FONT_PX + 2), _SIZE - 4)
        self._add(f'<text x="{x:.2f}" y="{y:.2f}" font-size="{FONT_PX}" fill="{color}" '
                  f'text-anchor="{anchor}">{escape(s)}</text>')

    def frame(self, color: str, dash: str = "6 4") -> None:
        """A dashed frame just inside the panel's edge (the line at infinity).

        Parameters
        ----------
        color : str
        dash : str
        """
        self._add(f'<rect x="4" y="4" width="{_SIZE - 8}" height="{_SIZE - 8}" fill="none" '
                  f'stroke="{color}" stroke-width="2" stroke-dasharray="{dash}"/>')

    def origin(self) -> None:
        """A small grey cross at the origin labelled ``O`` (when it is inside the panel)."""
        x0, x1, y0, y1 = self.box
        if not (x0 < 0 < x1 and y0 < 0 < y1):
            return
        s = 5.0 / self.k
        self.polyline([(-s, 0), (s, 0)], _GREY, 1.0)
        self.polyline([(0, -s), (0, s)], _GREY, 1.0)
        self.text((0, 0), "O", _GREY, dx=-6, dy=14, anchor="end")

    def caption(self, s: str) -> None:
        """Add a line to the caption band below the drawing.

        Parameters
        ----------
        s : str
        """
        self._captions.append(s)

    def svg(self) -> str:
        """The SVG document (a string, deterministic).

        Returns
        -------
        str
        """
        n = max(1, len(self._captions))
        H = _SIZE + n * (FONT_PX + 4) + 8
        W = max(_SIZE, math.ceil(max((0.62 * FONT_PX * len(c) for c in self._captions), default=0)) + 12)
        shift = (W - _SIZE) / 2
        cap = "".join(f'<text x="{W / 2:.1f}" y="{_SIZE + (k + 1) * (FONT_PX + 4)}" '
                      f'font-size="{FONT_PX}" text-anchor="middle" fill="{_BLACK}">{escape(c)}</text>'
                      for k, c in enumerate(self._captions))
        return (f'<svg xmlns="http://www.w3.org/2000/svg" width="{W}" height="{H}" '
                f'viewBox="0 0 {W} {H}" font-family="DejaVu Sans, sans-serif">'
                f"<title>{escape(self.title)}</title>"
                f'<rect x="0" y="0" width="{W}" height="{H}" fill="white"/>'
                f'<g transform="translate({shift:.1f},0)">' + "".join(self._items) + "</g>"
                + cap + "</svg>")


def _fitted(points, title: str, minimum: float = 1.0) -> SvgPanel:
    """A panel around the finite Euclidean ``points`` and the origin, at least ``2 minimum`` wide."""
    P = np.vstack([np.zeros((1, 2)), np.asarray(points, float).reshape(-1, 2)])
    P = P[np.all(np.isfinite(P), axis=1)]
    lo, hi = P.min(axis=0), P.max(axis=0)
    c = (lo + hi) / 2
    half = max(float(np.max(hi - lo)) / 2 * 1.25, minimum)
    return SvgPanel((c[0] - half, c[0] + half, c[1] - half, c[1] + half), title)


def _panel(title: str, fit=None, frame: str | None = None) -> SvgPanel:
    """A panel with the origin marked: around the points ``fit`` (:func:`_fitted`), else the square of
    half-width 1.5, first framed (dashed) in the colour ``frame``: the line at infinity."""
    panel = SvgPanel((-1.5, 1.5, -1.5, 1.5), title) if fit is None else _fitted(fit, title)
    if frame is not None:
        panel.frame(frame)
    panel.origin()
    return panel


def _done(panel: SvgPanel, *captions: str) -> str:
    """The SVG document of ``panel`` with the caption lines ``captions``."""
    for c in captions:
        panel.caption(c)
    return panel.svg()


def _documented(f):
    """``f`` with the end of its Parameters, its Returns and its Raises heading written in (``{label}``)."""
    f.__doc__ = f.__doc__.replace("{label}", """label : str
        Its name.

    Returns
    -------
    str
        An SVG document.

    Raises
    ------
    InputError""")
    return f


def _xy(p: np.ndarray):
    """Euclidean ``(x, y)`` of a finite homogeneous point ``[y, -x, w]``."""
    return np.array([-p[1] / p[2], p[0] / p[2]])


def _ideal_direction(p: np.ndarray) -> np.ndarray:
    """Unit direction in which the ideal point ``[a, b, 0]`` lies: ``(-b, a)`` (conventions)."""
    d = np.array([-p[1], p[0]])
    return d / np.hypot(*d)


def _ideal_arrow(panel: SvgPanel, d, color: str, text: str) -> None:
    """An arrow from the centre to the panel's edge pointing at the ideal point in direction ``d``."""
    c = np.array([panel.cx, panel.cy])
    q = c + 0.95 * panel.half * np.asarray(d)
    panel.arrow(c - 0.3 * panel.half * np.asarray(d), q, color, width=2.2)
    n = np.array([-d[1], d[0]])                 # beside the arrow, on its left
    panel.text(q - 0.25 * panel.half * np.asarray(d), text, color, dx=14 * n[0] + 4 * (n[0] < 0) * -1,
               dy=-14 * n[1] + 4, anchor="end" if n[0] < -0.3 else ("middle" if abs(n[0]) <= 0.3 else "start"))


def _line_parts(l: np.ndarray):
    """``(foot, direction)`` of a finite line ``[fx, fy, tz]`` (points with ``tz + y fx − x fy = 0``)."""
    f = l[:2]
    F2 = float(f @ f)
    foot = np.array([l[2] * f[1], -l[2] * f[0]]) / F2
    return foot, f / math.sqrt(F2)


def _draw_line(panel: SvgPanel, l, color: str, width: float = 2.0, dash=None, name: str = "",
               arrow: bool = True) -> None:
    foot, d = _line_parts(l)
    seg = panel.clip(foot, d)
    if seg is None:
        return
    panel.polyline(seg, color, width, dash)
    if arrow:
        h = 0.22 * panel.half
        panel.arrow(foot - h * d, foot + h * d, color, width=width + 0.6)
    if name:
        n = np.array([-d[1], d[0]])
        panel.text(foot + 0.35 * panel.half * d, name, color, dx=10 * n[0], dy=-10 * n[1] - 4)


def _pole(xy, title: str) -> SvgPanel:
    """A panel around the finite point (or pole) ``xy``, drawn as a blue dot."""
    panel = _panel(title, [xy])
    panel.dot(xy, _BLUE)
    return panel


@_documented
def point_svg(p, *, label: str = "P") -> str:
    """A point as a small SVG drawing: a dot and its coordinates, or an arrow to a point at infinity.

    Parameters
    ----------
    p : array_like (3,)
        Homogeneous point ``[y, -x, w]`` (thesis 5.49); ``w = 0``: at infinity.
    {label}
        Not one finite non-zero (3,) vector.

    Examples
    --------
    >>> "at infinity" in point_svg([0.0, 1.0, 0.0])      # the ideal point in direction (-1, 0)
    True
    """
    p = _vec3(p, "p")
    if not np.any(p):
        raise InputError("p is the zero vector, which is no point")
    if p[2] == 0:
        d = _ideal_direction(p)
        panel = _panel(f"{label}: point at infinity")
        _ideal_arrow(panel, d, _BLUE, f"{label} → ∞")
        return _done(panel, f"{label} at infinity, direction {_pair(d)}")
    xy = _xy(p)
    panel = _pole(xy, f"{label} = {_pair(xy)}")
    panel.text(xy, label, _BLUE)
    return _done(panel, f"{label} = {_pair(xy)}")


@_documented
def line_svg(l, *, label: str = "l") -> str:
    """A line as a small SVG drawing: the directed line through the panel, or the line at infinity.

    Parameters
    ----------
    l : array_like (3,)
        ``[fx, fy, tz]`` (thesis 5.55); ``[0, 0, t]`` is the line at infinity.
    {label}
        Not one finite non-zero (3,) vector.

    Examples
    --------
    >>> "through (0, 1)" in line_svg([1.0, 0.0, -1.0])      # y = 1, along +x
    True
    """
    l = _vec3(l, "l")
    if not np.any(l):
        raise InputError("l is the zero vector, which is no line")
    if l[0] == 0 and l[1] == 0:
        panel = _panel(f"{label}: the line at infinity", frame=_ORANGE)
        panel.text((0, 0.6), f"{label}: line at infinity", _ORANGE, dx=0, dy=0, anchor="middle")
        return _done(panel, f"{label} = line at infinity")
    foot, d = _line_parts(l)
    panel = _panel(f"{label} through {_pair(foot)}", [foot])
    _draw_line(panel, l, _ORANGE, name=label)
    panel.dot(foot, _ORANGE, r=2.5)
    return _done(panel, f"{label} through {_pair(foot)}, direction {_pair(d)}")


def _curve(C: np.ndarray, n: int = 96):
    """Euclidean polylines (a list of (k, 2) arrays) of the real conic ``C``."""
    from planargeo.geometry.conics import affine_frame

    F = affine_frame(C)
    if F.kind == "ellipse":
        s = np.linspace(0.0, 2 * np.pi, n + 1)
        U = [np.stack([np.cos(s), np.sin(s)], -1)]
    elif F.kind == "hyperbola":
        s = np.linspace(-2.0, 2.0, n)
        U = [np.stack([np.cosh(s), np.sinh(s)], -1), np.stack([-np.cosh(s), np.sinh(s)], -1)]
    else:
        s = np.linspace(-2.5, 2.5, n)
        U = [np.stack([s, s * s], -1)]
    return F, [u @ F.A.T + F.t for u in U]


@_documented
def conic_svg(C, *, label: str = "C") -> str:
    """A conic as a small SVG drawing; an imaginary one through its real partner (thesis 10.2.3).

    Real ellipses, hyperbolas (both branches) and parabolas are drawn solid.
    An imaginary conic (no real points, like an inertia) is drawn as the real
    conic with the sign of its homogeneous part flipped in its centred frame
    (:func:`planargeo.geometry.conics.drawable_conic`), dashed: the polars of the
    two are point reflections of each other through the centre.  A degenerate
    conic is named in the caption.

    Parameters
    ----------
    C : array_like (3, 3)
        A symmetric matrix.
    {label}
        Not one finite (3, 3) matrix.

    Examples
    --------
    >>> svg = conic_svg([[2.0, 0, 0], [0, 2.0, 0], [0, 0, 8.0]])   # an inertia: imaginary circle
    >>> "imaginary" in svg and "10.2.3" in svg
    True
    """
    from planargeo.geometry.conics import centre, classify, drawable_conic

    C = _mat3(C, "C")
    t = classify(C)
    if t.reality == "degenerate":
        return _done(_panel(f"{label}: degenerate conic"), f"{label}: degenerate conic ({t.kind})")
    real = t.reality == "real"
    F, curves = _curve(C if real else drawable_conic(C))
    pts = np.vstack(curves) if F.kind == "ellipse" else np.vstack([F.t, F.t + F.A[:, 0],
                                                                    F.t - F.A[:, 0], F.t + F.A[:, 1]])
    panel = _panel(f"{label}: {t}", pts)
    for c in curves:
        panel.polyline(c, _BLACK, 1.6, None if real else "6 4")
    z = centre(C)
    if z[2] != 0:
        zc = _xy(z)
        panel.dot(zc, _BLACK, r=3.0)
        panel.text(zc, label, _BLACK)
        where = f", centre {_pair(zc)}"
    else:
        panel.text(F.t, label, _BLACK)
        where = f", vertex {_pair(F.t)}"
    return _done(panel, f"{label}: {t}{where}", *([] if real else ["dashed: real partner (10.2.3)"]))


@_documented
def twist_svg(v, *, label: str = "v") -> str:
    """A twist as a small SVG drawing: its pole with the sense of rotation, or a translation arrow.

    A rotation ``[vx, vy, ω]`` (``ω ≠ 0``) is its pole (thesis 4.10, 5.51) with
    a curved arrow showing the sense of ``ω``; a translation (``ω = 0``) is a
    point at infinity, drawn as the velocity arrow pointing at it; the zero
    twist is named.

    Parameters
    ----------
    v : array_like (3,)
        ``[vx, vy, ω]`` at the origin.
    {label}
        Not one finite (3,) vector.

    Examples
    --------
    >>> "ω = 3" in twist_svg([6.0, -3.0, 3.0])          # rotation about (1, 2) at 3
    True
    >>> "translation" in twist_svg([0.0, 2.0, 0.0])
    True
    """
    v = _vec3(v, "v")
    if not np.any(v):
        return _done(_panel(f"{label}: zero twist"), f"{label} = 0: zero twist, no pole")
    if v[2] == 0:
        panel = _panel(f"{label}: translation")
        _ideal_arrow(panel, v[:2] / np.hypot(v[0], v[1]), _BLUE, f"{label}")
        return _done(panel, f"{label}: translation, velocity {_pair(v[:2])}", "pole at infinity")
    xy = _xy(v)
    panel = _pole(xy, f"{label}: rotation about {_pair(xy)}")
    panel.spin(xy, bool(v[2] > 0), _BLUE)
    panel.text(xy, label, _BLUE, dx=14, dy=-14)
    return _done(panel, f"{label}: pole {_pair(xy)}, ω = {_num(v[2])}")


@_documented
def wrench_svg(f, *, label: str = "f") -> str:
    """A wrench as a small SVG drawing: its line of action with the force arrow, or a couple.

    A force ``[fx, fy, τ]`` with ``(fx, fy) ≠ 0`` is its line of action (thesis
    4.27, 5.56) with an arrow in the force's sense; a pure couple is the line at
    infinity (dashed frame) with a curved arrow showing the sense of ``τ``; the
    zero wrench is named.

    Parameters
    ----------
    f : array_like (3,)
        ``[fx, fy, τz]`` at the origin.
    {label}
        Not one finite (3,) vector.

    Examples
    --------
    >>> "couple" in wrench_svg([0.0, 0.0, -2.0])
    True
    >>> "F = 2" in wrench_svg([0.0, 2.0, 4.0])           # 2 N upwards along x = 2
    True
    """
    f = _vec3(f, "f")
    if not np.any(f):
        return _done(_panel(f"{label}: zero wrench"), f"{label} = 0: zero wrench, no line")
    if f[0] == 0 and f[1] == 0:
        panel = _panel(f"{label}: pure couple", frame=_ORANGE)
        panel.spin((0.0, -0.6), bool(f[2] > 0), _ORANGE, r=20)
        panel.text((0, 0.75), f"{label}: line at infinity", _ORANGE, dx=0, dy=0, anchor="middle")
        return _done(panel, f"{label}: pure couple, τ = {_num(f[2])}")
    foot, d = _line_parts(f)
    panel = _panel(f"{label}: force on a line", [foot])
    _draw_line(panel, f, _ORANGE, name=label)
    return _done(panel, f"{label}: F = {_num(float(np.hypot(f[0], f[1])))} through {_pair(foot)}",
                 f"direction {_pair(d)}")


@_documented
def inertia_svg(I, *, label: str = "I") -> str:
    """An inertia as a small SVG drawing: its circle of gyration about the centre of mass (10.2.3).

    The inertia is an imaginary conic (thesis 5.4); it is drawn as its real
    partner with the homogeneous part's sign flipped (thesis 10.2.3), the
    circle (ellipse, for an articulated inertia) of radius ``ρ`` about the centre
    of mass, dashed, whose polars are the axes of percussion reflected through
    the centre.

    Parameters
    ----------
    I : array_like (3, 3)
        A symmetric positive definite inertia.
    {label}
        Not one finite (3, 3) matrix.

    Examples
    --------
    >>> svg = inertia_svg([[2.0, 0, 0], [0, 2.0, 2.0], [0, 2.0, 2.5]])   # m 2, c (1, 0), ρ 0.5
    >>> "m = 2" in svg and "ρ = 0.5" in svg
    True
    """
    from planargeo.geometry.conics import centre, classify, drawable_conic

    I = _mat3(I, "I")
    t = classify(I)
    if t.reality != "imaginary":
        return conic_svg(I, label=label)
    if I[0, 0] < 0:
        I = -I
    D = drawable_conic(I)
    F, curves = _curve(D)
    c = _xy(centre(I))
    panel = _panel(f"{label}: inertia", np.vstack(curves))
    for cv in curves:
        panel.polyline(cv, _BLACK, 1.5, "6 4")
    panel.dot(c, _BLACK, r=3.0)
    panel.text(c, label, _BLACK)
    m = I[0, 0]
    rigid = abs(I[0, 0] - I[1, 1]) <= 1e-10 * np.abs(I).max() and abs(I[0, 1]) <= 1e-10 * np.abs(I).max()
    if rigid:
        rho = math.sqrt(max(float(I[2, 2]) / m - float(c @ c), 0.0))
        panel.caption(f"{label}: m = {_num(m)}, c = {_pair(c)}, ρ = {_num(rho)}")
    else:
        panel.caption(f"{label}: centre {_pair(c)}")
    return _done(panel, "dashed: gyration conic (10.2.3)")
