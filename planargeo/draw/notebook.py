"""One element drawn for a notebook: a point, line, conic, twist, wrench or inertia as a picture.

A value at the end of a cell is a :class:`~planargeo.draw.picture.Picture` around it and the origin,
written as SVG by matplotlib; ``import planargeo`` registers :func:`element_svg` with IPython.
"""
from __future__ import annotations

import io
import math

import numpy as np

from planargeo.draw.geometry import conic_geometry
from planargeo.draw.picture import Picture
from planargeo.draw.pictures._words import num as _num
from planargeo.draw.pictures.kit import foot_on_line
from planargeo.draw.style import rc_context
from planargeo.errors import InputError
from planargeo.geometry.conics import centre, classify
from planargeo.geometry.elements import Conic, Line, Point
from planargeo.geometry.projective import to_xy
from planargeo.screws.inertia import Inertia
from planargeo.screws.twists import Twist, Wrench

__all__ = ["element_picture", "element_svg", "register", "SIZE"]

#: Width and height (pixels) of an element's picture.
SIZE = (280, 300)
#: The classes drawn for notebooks.
DRAWN = (Point, Line, Conic, Twist, Wrench, Inertia, Picture)


def num(x: float) -> str:
    """``x`` to three significant digits, round-off below 1e-12 (and ``-0``) as ``0``."""
    return _num(x, 3, 1e-12)


def _pair(xy) -> str:
    return f"({num(xy[0])}, {num(xy[1])})"


def _frame(points, title: str, size, minimum: float = 1.0) -> Picture:
    """A square view, at least ``2 minimum`` wide, around the finite ``points`` and the origin."""
    P = np.vstack([np.zeros((1, 2)), np.asarray(points, float).reshape(-1, 2)])
    P = P[np.all(np.isfinite(P), axis=1)]
    lo, hi = P.min(axis=0), P.max(axis=0)
    c, half = (lo + hi) / 2, 1.5 * max(float(np.max(hi - lo)) / 2, minimum)
    pic = Picture((c[0] - half, c[0] + half, c[1] - half, c[1] + half), size, title=title,
                  ticks=False, margin=(6, 6, 26, 6))
    r = 6.0 / pic.kx
    pic.path("O", [[-r, 0.0], [r, 0.0], [float("nan"), float("nan")], [0.0, -r], [0.0, r]],
             role="construct", symbol="O", desc="the origin", color="#7F7F7F")
    return pic


def _ring(C) -> np.ndarray:
    """Points of the conic's real curve or real partner (for the view)."""
    g = conic_geometry(C)
    if "affine" not in g:
        return np.zeros((0, 2))
    A = g["affine"]
    u = np.array([[1, 0, 1], [-1, 0, 1], [0, 1, 1], [0, -1, 1]], float)
    return (u @ A.T)[:, :2]


def element_picture(obj, *, size=SIZE) -> Picture:
    """The picture of one element, as a notebook shows it.

    Parameters
    ----------
    obj : Point, Line, Conic, Twist, Wrench or Inertia
        A single element (not a batch).
    size : (int, int)
        Width and height in pixels.

    Returns
    -------
    Picture
        The element in a square view around it and the origin, titled with its numbers.

    Raises
    ------
    InputError
        ``obj`` is none of these, or a batch.

    Examples
    --------
    >>> from planargeo.geometry.elements import Line
    >>> element_picture(Line.at_infinity()).title
    'l = the line at infinity'
    """
    if not isinstance(obj, (Point, Line, Conic, Twist, Wrench, Inertia)):
        raise InputError(f"obj must be a Point, Line, Conic, Twist, Wrench or Inertia, got "
                         f"{type(obj).__name__}")
    conic = isinstance(obj, (Conic, Inertia))
    a = np.asarray(obj.matrix if conic else obj.array, float)
    if a.shape != ((3, 3) if conic else (3,)):
        raise InputError(f"obj must be a single element, got a batch of shape {a.shape}")
    if conic:
        return _conic(a, "C" if isinstance(obj, Conic) else "I", isinstance(obj, Inertia), size)
    if isinstance(obj, (Point, Twist)):
        return _pole(a, "P" if isinstance(obj, Point) else "v", isinstance(obj, Twist), size)
    return _line(a, "l" if isinstance(obj, Line) else "f", isinstance(obj, Wrench), size)


def _pole(p, name: str, twist: bool, size) -> Picture:
    if not np.any(p):
        return _frame([], f"{name} = 0: zero twist, no pole", size)
    if p[2] == 0:
        d = np.array([-p[1], p[0]]) / math.hypot(p[0], p[1])
        title = (f"{name}: translation, velocity {_pair(p[:2])}" if twist
                 else f"{name} at infinity, direction {_pair(d)}")
        pic = _frame([], title, size)
        pic.point(name, p, role="twist", symbol=name, desc=title + " (pole at infinity)")
        return pic
    xy = to_xy(p)
    title = f"{name}: pole {_pair(xy)}, ω = {num(p[2])}" if twist else f"{name} = {_pair(xy)}"
    pic = _frame([xy], title, size)
    pic.point(name, p, role="twist", symbol=name, desc=title, glyph=twist,
              shape=None if twist else "o")
    return pic


def _line(l, name: str, wrench: bool, size) -> Picture:
    if not np.any(l):
        return _frame([], f"{name} = 0: zero wrench, no line", size)
    if l[0] == 0 and l[1] == 0:
        title = f"{name}: pure couple, τ = {num(l[2])}" if wrench else f"{name} = the line at infinity"
        pic = _frame([], title, size)
        if wrench:
            pic.line(name, l, role="wrench", symbol=name, desc=title)
        else:   # the line at infinity: a dashed frame just inside the view
            x0, x1, y0, y1 = pic.box
            ix, iy = 8.0 / pic.kx, 8.0 / pic.ky
            pic.path(name, [[x0 + ix, y0 + iy], [x1 - ix, y0 + iy], [x1 - ix, y1 - iy],
                            [x0 + ix, y1 - iy], [x0 + ix, y0 + iy]], role="wrench", symbol=name,
                     desc=title, dash=[5.0, 4.0])
            pic.text(name + ":label", ((x0 + x1) / 2, y1 - 30.0 / pic.ky), f"{name}: line at ∞",
                     role="wrench", symbol=name, desc=title, ha="center")
        return pic
    foot = foot_on_line(l, (0.0, 0.0))
    F = math.hypot(l[0], l[1])
    title = (f"{name}: F = {num(F)} through {_pair(foot)}" if wrench
             else f"{name} through {_pair(foot)}, direction {_pair(np.asarray(l[:2]) / F)}")
    pic = _frame([foot], title, size)
    pic.line(name, l, role="wrench", symbol=name, desc=title, arrow=wrench, anchor=foot)
    pic.marks(name + ":foot", [foot], role="wrench", symbol="", desc=f"foot of {name} on O",
              size=4.0)
    return pic


def _conic(C, name: str, inertia: bool, size) -> Picture:
    C = 0.5 * (C + C.T)
    t = classify(C)
    if t.reality == "degenerate":
        pic = _frame([], f"{name}: degenerate conic ({t.kind})", size)
        pic.conic(name, C, symbol=name, desc=pic.title)
        return pic
    if inertia and C[0, 0] < 0:
        C = -C
    z = centre(C)
    if inertia and t.reality == "imaginary":
        m = float(C[0, 0])
        c = to_xy(z)
        rigid = (abs(C[0, 0] - C[1, 1]) <= 1e-10 * np.abs(C).max()
                 and abs(C[0, 1]) <= 1e-10 * np.abs(C).max())
        rho = math.sqrt(max(float(C[2, 2]) / m - float(c @ c), 0.0))
        title = (f"{name}: m = {num(m)}, c = {_pair(c)}, ρ = {num(rho)}" if rigid
                 else f"{name}: centre {_pair(c)}")
    else:
        where = f", centre {_pair(to_xy(z))}" if z[2] != 0 else ""
        title = f"{name}: {t}{where}"
    real = t.reality == "real"
    pic = _frame(_ring(C), title, size)
    pic.conic(name, C, role="inertia" if inertia else "conic", symbol=name,
              desc=title + ("" if real else "; dashed: its real partner (10.2.3)"))
    return pic


def element_svg(obj) -> str | None:
    """The SVG of :func:`element_picture` (a Picture drawn as it is); None for a batch.

    Parameters
    ----------
    obj : Point, Line, Conic, Twist, Wrench, Inertia or Picture
        What to draw.

    Returns
    -------
    str or None
        An SVG document.

    Examples
    --------
    >>> from planargeo.geometry.elements import Point
    >>> element_svg(Point.from_xy(1.0, 2.0)).lstrip().startswith("<?xml")
    True
    """
    from planargeo.draw.render import figure   # matplotlib: imported when needed

    if not isinstance(obj, Picture):
        try:
            obj = element_picture(obj)
        except InputError:
            return None
    buf = io.StringIO()
    with rc_context():               # fixed hash salt, no date: the same text every time
        figure(obj.to_dict()).savefig(buf, format="svg", metadata={"Date": None})
    return buf.getvalue()


def register(shell) -> None:
    """Show the elements (and pictures) as SVG drawings in the IPython ``shell``.

    Parameters
    ----------
    shell : IPython.core.interactiveshell.InteractiveShell
        The running shell (``IPython.get_ipython()``).

    Examples
    --------
    >>> from IPython.core.interactiveshell import InteractiveShell
    >>> from planargeo.geometry.elements import Point
    >>> register(shell := InteractiveShell.instance())
    >>> "image/svg+xml" in shell.display_formatter.format(Point.from_xy(1.0, 2.0))[0]
    True
    """
    svg = shell.display_formatter.formatters["image/svg+xml"]
    for cls in DRAWN:
        svg.for_type(cls, element_svg)
