"""Drawing geometry without a renderer: poles, clipped lines, conic curves, glyphs.

What a picture needs from the projective plane, as plain coordinates (no matplotlib here):
:func:`point_xy`, :func:`clip_line`, :func:`conic_geometry` (the class of a conic and the
affine map carrying a unit curve onto it), :func:`conic_curves` and :func:`arc_glyph`.
"""
from __future__ import annotations

import math

import numpy as np

from planargeo._validate import as_array, as_vec3
from planargeo.errors import InputError

__all__ = ["point_xy", "clip_line", "euclidean_conic", "conic_geometry", "conic_curves",
           "arc_glyph", "UNIT_CURVES"]

# package point p = M @ [x, y, 1]
_M = np.array([[0.0, 1.0, 0.0], [-1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])


def _vec(x, name: str) -> np.ndarray:
    """A homogeneous 3-vector from an array or a planargeo object (``.array``)."""
    if hasattr(x, "array") and not isinstance(x, np.ndarray):
        x = x.array
    return as_vec3(x, name).copy()


def _mat(x, name: str) -> np.ndarray:
    if not isinstance(x, np.ndarray):
        for attr in ("matrix", "array"):
            if hasattr(x, attr):
                x = getattr(x, attr)
                break
    m = as_array(x, name, (3, 3)).copy()
    if m.ndim != 2:
        raise InputError(f"{name} must be a single (3, 3) matrix, got shape {m.shape}")
    # np.allclose(m, m.T, rtol=1e-10, atol=…) on plain floats (as_array checked they are
    # finite; the diagonal always passes): the same comparisons, a fraction of the time
    (a, b, c), (d, e, f), (g, h, i) = m.tolist()
    atol = 1e-12 * max(1.0, abs(a), abs(b), abs(c), abs(d), abs(e), abs(f), abs(g), abs(h), abs(i))
    for u, v in ((b, d), (c, g), (f, h)):
        if not (abs(u - v) <= atol + 1e-10 * abs(v) and abs(v - u) <= atol + 1e-10 * abs(u)):
            raise InputError(f"{name} must be symmetric")
    return 0.5 * (m + m.T)


def point_xy(p) -> np.ndarray | None:
    """Euclidean ``(x, y)`` of a homogeneous point; None for an ideal one (or beyond the floats).

    Parameters
    ----------
    p : array_like (3,)
        Homogeneous point ``[y, -x, 1]`` (times a weight).

    Returns
    -------
    numpy.ndarray or None

    Examples
    --------
    >>> point_xy([2.0, -1.0, 1.0]), point_xy([1.0, 0.0, 0.0]), point_xy([1e200, 1.0, 1e-200])
    (array([1., 2.]), None, None)
    """
    p = np.asarray(p, dtype=float)
    if p[2] == 0.0:
        return None
    with np.errstate(over="ignore", under="ignore"):
        xy = np.array([-p[1] / p[2], p[0] / p[2]])
    # a weight so small that the pole is beyond the float range: numerically an ideal point
    return xy if np.all(np.isfinite(xy)) else None


def clip_line(line, box) -> np.ndarray | None:
    """Endpoints ``(2, 2)`` of the infinite line ``[fx, fy, tz]`` inside ``box``, on its boundary.

    The points satisfy ``tz + y fx - x fy = 0`` (4.27).

    Parameters
    ----------
    line : array_like (3,)
        ``[fx, fy, tz]``.
    box : (float, float, float, float)
        ``(x0, x1, y0, y1)``.

    Returns
    -------
    numpy.ndarray or None
        None if the line misses the box or is the line at infinity.

    Examples
    --------
    >>> clip_line([1.0, 0.0, -0.5], (-1, 1, -1, 1))   # y = 0.5, force along +x
    array([[-1. ,  0.5],
           [ 1. ,  0.5]])
    """
    fx, fy, tz = (float(v) for v in line)
    sc = max(abs(fx), abs(fy))
    if sc == 0.0 or abs(tz) >= sc * 1e300:  # the line at infinity (or beyond any view)
        return None
    fx, fy, tz = fx / sc, fy / sc, tz / sc  # homogeneous rescaling: same line
    F2 = fx * fx + fy * fy
    x0, x1, y0, y1 = (float(v) for v in box)
    # plain floats (the same IEEE operations as on arrays: a clipped line costs microseconds)
    p0, p1 = fy * tz / F2, -fx * tz / F2  # foot of the perpendicular from the origin
    n = math.sqrt(F2)
    d0, d1 = fx / n, fy / n
    tlo, thi = -math.inf, math.inf
    for pk, dk, lo, hi in ((p0, d0, x0, x1), (p1, d1, y0, y1)):
        if dk == 0.0:
            if pk < lo or pk > hi:
                return None
            continue
        a, b = (lo - pk) / dk, (hi - pk) / dk   # a subnormal component: the slab is unbounded (inf)
        if a > b:
            a, b = b, a
        tlo, thi = max(tlo, a), min(thi, b)
    if not tlo <= thi:
        return None
    out = [[p0 + tlo * d0, p1 + tlo * d1], [p0 + thi * d0, p1 + thi * d1]]
    # snap the coordinate that hit the boundary exactly onto it
    for q in out:
        for k, (lo, hi) in enumerate(((x0, x1), (y0, y1))):
            if abs(q[k] - lo) <= 1e-12 * max(1.0, abs(lo)):
                q[k] = lo
            elif abs(q[k] - hi) <= 1e-12 * max(1.0, abs(hi)):
                q[k] = hi
    return np.array(out)


def _unit_curves() -> dict[str, list[np.ndarray]]:
    t = np.linspace(0.0, 2 * np.pi, 181)
    s = np.linspace(-7.0, 7.0, 481)
    br = np.column_stack([np.cosh(s), np.sinh(s)])
    x = np.sinh(s)
    return {"ellipse": [np.column_stack([np.cos(t), np.sin(t)])],
            "hyperbola": [br, br * [-1.0, 1.0]],
            "parabola": [np.column_stack([x, x * x])]}


#: The unit curves that :func:`conic_geometry`'s affine maps carry onto a conic: the unit
#: circle, both branches of ``x² − y² = 1`` and the parabola ``y = x²``.
UNIT_CURVES = _unit_curves()


def euclidean_conic(C) -> np.ndarray:
    """The conic's matrix acting on Euclidean ``[x, y, 1]`` (``Mᵀ C M``).

    Parameters
    ----------
    C : array_like (3, 3)
        Conic matrix (package coordinates).

    Returns
    -------
    numpy.ndarray

    Examples
    --------
    >>> euclidean_conic(np.diag([1.0, 1.0, -4.0])).tolist()   # x² + y² = 4 either way
    [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, -4.0]]
    """
    return _M.T @ np.asarray(C, dtype=float) @ _M


def _line_from_euclid(a, b, c):
    """Package line of the Euclidean equation ``a x + b y + c = 0``."""
    return np.array([b, -a, c])


def conic_geometry(C, *, rtol: float = 1e-9) -> dict:
    """How to draw the conic ``C`` (package coordinates).

    Parameters
    ----------
    C : array_like (3, 3)
        Symmetric conic matrix.
    rtol : float
        Relative tolerance of the class tests (this is drawing, not arithmetic).

    Returns
    -------
    dict
        ``kind`` ("ellipse", "hyperbola", "parabola", "lines", "point" or "empty"),
        ``imaginary`` (no real points: the sign-flipped conic is described instead, the package
        convention for inertias), and ``affine`` (the 3×3 Euclidean map of the unit curve of
        :data:`UNIT_CURVES` onto the curve), ``lines`` (package lines) or ``point``.

    Examples
    --------
    >>> g = conic_geometry([[1, 0, 0], [0, 1, 0], [0, 0, -4]])   # circle r=2 at origin
    >>> g["kind"], np.round(g["affine"][:2, :2], 12).tolist()
    ('ellipse', [[2.0, 0.0], [0.0, 2.0]])
    """
    E = euclidean_conic(_mat(C, "conic"))
    scale = float(np.abs(E).max())
    if scale == 0.0:
        return {"kind": "empty", "imaginary": False}
    E = E / scale
    A, b, c = E[:2, :2], E[:2, 2], E[2, 2]
    lam, R = np.linalg.eigh(A)
    order = np.argsort(-np.abs(lam))
    lam, R = lam[order], R[:, order]
    if np.linalg.det(R) < 0:
        R[:, 1] = -R[:, 1]
    tol = rtol
    if abs(lam[1]) > tol * max(1.0, abs(lam[0])) and abs(lam[0]) > tol:
        # central conic
        x0 = -np.linalg.solve(A, b)
        k = c + b @ x0
        if abs(k) <= tol * max(abs(lam[0]), 1.0) * max(1.0, x0 @ x0):
            if lam[0] * lam[1] > 0:
                return {"kind": "point", "point": x0, "imaginary": False}
            # two lines through x0: sqrt|l0| u = ± sqrt|l1| v in the eigenframe
            s0, s1 = np.sqrt(abs(lam[0])), np.sqrt(abs(lam[1]))
            lines = []
            for sg in (1.0, -1.0):
                nrm = s0 * R[:, 0] - sg * s1 * R[:, 1]
                lines.append(_line_from_euclid(nrm[0], nrm[1], -nrm @ x0))
            return {"kind": "lines", "lines": lines, "imaginary": False}
        imaginary = False
        if lam[0] * lam[1] > 0:
            if lam[0] * k > 0:  # no real points: flip the sign of k (package convention)
                imaginary = True
                k = -k
            ax_ = np.sqrt(-k / lam)
            kind = "ellipse"
        else:
            # hyperbola: the axis whose eigenvalue has the sign of -k is the real one
            ax_ = np.sqrt(np.abs(k / lam))
            if lam[0] * k >= 0:
                ax_ = ax_[::-1]
                R = np.column_stack([R[:, 1], -R[:, 0]])
            kind = "hyperbola"
        aff = np.eye(3)
        aff[:2, :2] = R @ np.diag(ax_)
        aff[:2, 2] = x0
        return {"kind": kind, "affine": aff, "imaginary": imaginary, "center": x0}
    if abs(lam[0]) > tol:
        # A has rank one: parabola or parallel lines
        e, f = R[:, 0], R[:, 1]
        l0 = lam[0]
        be, bf = b @ e, b @ f
        if abs(bf) > tol * max(1.0, abs(be), abs(c)):
            # l0 u^2 + 2 be u + 2 bf v + c = 0  ->  v = -(l0 u^2 + 2 be u + c) / (2 bf)
            u0 = -be / l0
            v0 = -(c - be * be / l0) / (2 * bf)
            kcoef = -l0 / (2 * bf)  # v - v0 = kcoef (u - u0)^2
            # unit parabola (s, s^2): u = u0 + s / kcoef, v = v0 + s^2 / kcoef
            aff = np.eye(3)
            aff[:2, 0] = e / kcoef
            aff[:2, 1] = f / kcoef
            aff[:2, 2] = u0 * e + v0 * f
            return {"kind": "parabola", "affine": aff, "imaginary": False}
        disc = be * be - l0 * c
        if disc < -tol:
            return {"kind": "empty", "imaginary": True}
        r = np.sqrt(max(disc, 0.0))
        us = sorted({(-be + r) / l0, (-be - r) / l0}) if r > 0 else [-be / l0]
        return {"kind": "lines", "imaginary": False,
                "lines": [_line_from_euclid(e[0], e[1], -u) for u in us]}
    # A == 0: the line at infinity times a finite line  2 b.x + c = 0
    if np.hypot(*b) > tol:
        return {"kind": "lines", "imaginary": False,
                "lines": [_line_from_euclid(2 * b[0], 2 * b[1], c)], "line_at_infinity": True}
    return {"kind": "lines", "imaginary": False, "lines": [], "line_at_infinity": True}


def _inside(xy: np.ndarray, box) -> np.ndarray:
    x0, x1, y0, y1 = box
    return (xy[:, 0] >= x0) & (xy[:, 0] <= x1) & (xy[:, 1] >= y0) & (xy[:, 1] <= y1)


def _runs(xy: np.ndarray, keep: np.ndarray) -> list[np.ndarray]:
    """The maximal runs of consecutive kept points (each with its neighbours, so it leaves the box)."""
    out = []
    idx = np.flatnonzero(keep)
    if idx.size == 0:
        return out
    breaks = np.flatnonzero(np.diff(idx) > 1)
    for a, b in zip(np.r_[0, breaks + 1], np.r_[breaks, idx.size - 1]):
        lo, hi = max(idx[a] - 1, 0), min(idx[b] + 1, len(xy) - 1)
        if hi > lo:
            out.append(xy[lo:hi + 1])
    return out


def conic_curves(C, box, geometry: dict | None = None) -> list[np.ndarray]:
    """The real curve of ``C`` (or of its real stand-in) as polylines ``(n, 2)`` across ``box``.

    An ellipse is one closed polyline; a hyperbola or parabola the runs through the box (each
    one sample beyond it); a degenerate conic its real lines, clipped.

    Parameters
    ----------
    C : array_like (3, 3)
        Symmetric conic matrix (package coordinates).
    box : (float, float, float, float)
        ``(x0, x1, y0, y1)``.
    geometry : dict, optional
        :func:`conic_geometry` of ``C`` when already computed.

    Returns
    -------
    list of numpy.ndarray

    Examples
    --------
    >>> len(conic_curves(np.diag([1.0, -1.0, -1.0]), (-3, 3, -3, 3)))   # two branches
    2
    """
    g = conic_geometry(C) if geometry is None else geometry
    if "affine" in g:
        A = g["affine"]
        curves = [c @ A[:2, :2].T + A[:2, 2] for c in UNIT_CURVES[g["kind"]]]
        if g["kind"] == "ellipse":
            return curves
        out = []
        for c in curves:
            ok = np.all(np.isfinite(c), axis=1)
            out += _runs(c, ok & _inside(c, box))
        return out
    if g["kind"] == "lines":
        segs = (clip_line(ln, box) for ln in g["lines"])
        return [s for s in segs if s is not None]
    return []


def arc_glyph(radius: float, ccw: bool, npts: int = 40) -> tuple[np.ndarray, np.ndarray]:
    """A rotation glyph about the origin: a 270° arc and its head (units of ``radius``, y up).

    Parameters
    ----------
    radius : float
        Arc radius.
    ccw : bool
        Counter-clockwise (a positive rate of rotation).
    npts : int
        Samples of the arc.

    Returns
    -------
    arc : numpy.ndarray
        ``(npts, 2)``.
    head : numpy.ndarray
        ``(3, 2)``, the tip first.

    Examples
    --------
    >>> arc, head = arc_glyph(10.0, True)
    >>> np.allclose(np.hypot(*arc.T), 10.0), head.shape
    (True, (3, 2))
    """
    a0, span = np.deg2rad(-45.0), np.deg2rad(270.0)
    t = np.linspace(a0, a0 + span, npts) if ccw else np.linspace(a0 + span, a0, npts)
    arc = radius * np.column_stack([np.cos(t), np.sin(t)])
    end, te = arc[-1], t[-1]
    tang = np.array([-np.sin(te), np.cos(te)]) * (1.0 if ccw else -1.0)
    norm = np.array([np.cos(te), np.sin(te)])
    h = min(max(3.0, 0.45 * radius), 6.0)
    head = np.array([end + tang * h, end - 0.5 * h * norm, end + 0.5 * h * norm])
    return arc, head
