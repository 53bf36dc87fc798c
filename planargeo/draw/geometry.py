"""What a picture needs from the projective plane, as plain coordinates (no matplotlib here).

Poles (:func:`point_xy`), clipped lines, a conic's class and the affine map carrying a unit curve
onto it (:func:`conic_geometry`), its curves, and the rotation glyph.
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
    return np.array(_sym_rows(x, name))


def _sym_rows(x, name: str) -> list[list[float]]:
    """A symmetric 3×3 matrix (array_like or ``.matrix`` / ``.array``) as rows of floats, ``(m + mᵀ)/2``."""
    rows = None
    if not isinstance(x, np.ndarray):
        for attr in ("matrix", "array"):
            if hasattr(x, attr):
                x = getattr(x, attr)
                break
    if type(x) is np.ndarray and x.dtype == np.float64 and x.shape == (3, 3):
        rows = x.tolist()       # finite when their sum is (else as_array names the problem)
    if not (rows and math.isfinite(sum(rows[0]) + sum(rows[1]) + sum(rows[2]))):
        m = as_array(x, name, (3, 3))
        if m.ndim != 2:
            raise InputError(f"{name} must be a single (3, 3) matrix, got shape {m.shape}")
        rows = m.tolist()
    # np.allclose(m, m.T, rtol=1e-10, atol=…) on plain floats (as_array checked they are
    # finite; the diagonal always passes): the same comparisons, a fraction of the time
    (a, b, c), (d, e, f), (g, h, i) = rows
    atol = 1e-12 * max(1.0, abs(a), abs(b), abs(c), abs(d), abs(e), abs(f), abs(g), abs(h), abs(i))
    for u, v in ((b, d), (c, g), (f, h)):
        if not (abs(u - v) <= atol + 1e-10 * abs(v) and abs(v - u) <= atol + 1e-10 * abs(u)):
            raise InputError(f"{name} must be symmetric")
    # 0.5 * (m + m.T), entry by entry (the same IEEE operations)
    return [[0.5 * (a + a), 0.5 * (b + d), 0.5 * (c + g)],
            [0.5 * (d + b), 0.5 * (e + e), 0.5 * (f + h)],
            [0.5 * (g + c), 0.5 * (h + f), 0.5 * (i + i)]]


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
    x0, x1, y0, y1 = (float(v) for v in box)
    out = _clip(fx, fy, tz, x0, x1, y0, y1)
    return None if out is None else np.array(out)


def _clip(fx: float, fy: float, tz: float, x0: float, x1: float, y0: float, y1: float):
    """:func:`clip_line` on plain floats: ``[[x, y], [x, y]]`` (lists) or None."""
    sc = max(abs(fx), abs(fy))
    if sc == 0.0 or abs(tz) >= sc * 1e300:  # the line at infinity (or beyond any view)
        return None
    fx, fy, tz = fx / sc, fy / sc, tz / sc  # homogeneous rescaling: same line
    F2 = fx * fx + fy * fy
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
    # snap the coordinate that hit the boundary exactly onto it (within 1e-12 of the bound, at least 1)
    ex0, ex1 = 1e-12 * max(1.0, abs(x0)), 1e-12 * max(1.0, abs(x1))
    ey0, ey1 = 1e-12 * max(1.0, abs(y0)), 1e-12 * max(1.0, abs(y1))
    out = []
    for t in (tlo, thi):
        x, y = p0 + t * d0, p1 + t * d1
        if abs(x - x0) <= ex0:
            x = x0
        elif abs(x - x1) <= ex1:
            x = x1
        if abs(y - y0) <= ey0:
            y = y0
        elif abs(y - y1) <= ey1:
            y = y1
        out.append([x, y])
    return out


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


_EPS = 2.0 ** -53                    # LAPACK's dlamch("E")
_SAFMIN = 2.2250738585072014e-308    # dlamch("S")
_RMIN = 1.4916681462400413e-154      # below this LAPACK's syevd rescales first: left to numpy


def _eigh2(a: float, b: float, c: float):
    """Eigenvalues (ascending) and unit eigenvectors of ``[[a, b], [b, c]]`` in plain floats.

    The same values and the same eigenvector signs as :func:`numpy.linalg.eigh` (LAPACK
    ``syevd``: a 2×2 block is split off when ``b`` is negligible, else turned by ``dlaev2``'s
    rotation), without numpy's per-call cost; a matrix so small that LAPACK rescales it goes to
    numpy.  Returns ``((l0, l1), (r0, r1))`` with ``r0``, ``r1`` the eigenvector columns.
    """
    m = max(abs(a), abs(b), abs(c))
    if 0.0 < m < _RMIN or not math.isfinite(m):
        lam, R = np.linalg.eigh(np.array([[a, b], [b, c]]))
        return (float(lam[0]), float(lam[1])), (tuple(R[:, 0].tolist()), tuple(R[:, 1].tolist()))
    if (b == 0.0 or abs(b) <= math.sqrt(abs(a)) * math.sqrt(abs(c)) * _EPS
            or b * b <= (_EPS * _EPS * abs(a)) * abs(c) + _SAFMIN):
        d0, d1, z0, z1 = a, c, (1.0, 0.0), (0.0, 1.0)
    else:   # the rotation of LAPACK's dlaev2, step by step
        sm, df, tb = a + c, a - c, b + b
        adf, ab = abs(df), abs(tb)
        acmx, acmn = (a, c) if abs(a) > abs(c) else (c, a)
        if adf > ab:
            rt = adf * math.sqrt(1.0 + (ab / adf) ** 2)
        elif adf < ab:
            rt = ab * math.sqrt(1.0 + (adf / ab) ** 2)
        else:
            rt = ab * math.sqrt(2.0)
        if sm < 0.0:
            rt1, sgn1 = 0.5 * (sm - rt), -1
            rt2 = (acmx / rt1) * acmn - (b / rt1) * b
        elif sm > 0.0:
            rt1, sgn1 = 0.5 * (sm + rt), 1
            rt2 = (acmx / rt1) * acmn - (b / rt1) * b
        else:
            rt1, rt2, sgn1 = 0.5 * rt, -0.5 * rt, 1
        cs, sgn2 = (df + rt, 1) if df >= 0.0 else (df - rt, -1)
        if abs(cs) > ab:
            ct = -tb / cs
            sn1 = 1.0 / math.sqrt(1.0 + ct * ct)
            cs1 = ct * sn1
        elif ab == 0.0:
            cs1, sn1 = 1.0, 0.0
        else:
            tn = -cs / tb
            cs1 = 1.0 / math.sqrt(1.0 + tn * tn)
            sn1 = tn * cs1
        if sgn1 == sgn2:
            cs1, sn1 = -sn1, cs1
        d0, d1, z0, z1 = rt1, rt2, (cs1, sn1), (-sn1, cs1)
    if d0 > d1:
        d0, d1, z0, z1 = d1, d0, z1, z0
    return (d0, d1), (z0, z1)


def _solve2(a00: float, a01: float, a10: float, a11: float, b0: float, b1: float):
    """``[[a00, a01], [a10, a11]] x = b`` by LU with partial pivoting (as LAPACK ``gesv``)."""
    if abs(a10) > abs(a00):
        a00, a01, a10, a11, b0, b1 = a10, a11, a00, a01, b1, b0
    l = a10 * (1.0 / a00)
    u11 = a11 - l * a01
    y1 = b1 - l * b0
    x1 = y1 / u11
    return (b0 - x1 * a01) / a00, x1


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
    # plain floats (a 2×2 eigen-decomposition and solve in closed form, as LAPACK does them:
    # the numbers numpy.linalg gives, at a fraction of its per-call cost)
    (p00, p01, p02), (_, p11, p12), (_, _, p22) = _sym_rows(C, "conic")
    # the Euclidean matrix Mᵀ C M (euclidean_conic), entry by entry
    e00, e01, e02, e11, e12, e22 = p11, -p01, -p12, p00, p02, p22
    scale = max(abs(e00), abs(e01), abs(e02), abs(e11), abs(e12), abs(e22))
    if scale == 0.0:
        return {"kind": "empty", "imaginary": False}
    e00, e01, e02, e11, e12, e22 = (v / scale for v in (e00, e01, e02, e11, e12, e22))
    b0, b1, c = e02, e12, e22
    (l0, l1), (r0, r1) = _eigh2(e00, e01, e11)
    if abs(l0) < abs(l1):          # the larger |eigenvalue| first
        l0, l1, r0, r1 = l1, l0, r1, r0
    if r0[0] * r1[1] - r0[1] * r1[0] < 0:
        r1 = (-r1[0], -r1[1])
    if abs(l1) > rtol * max(1.0, abs(l0)) and abs(l0) > rtol:
        # central conic
        x, y = _solve2(e00, e01, e01, e11, b0, b1)
        x, y = -x, -y
        k = c + (b0 * x + b1 * y)
        if abs(k) <= rtol * max(abs(l0), 1.0) * max(1.0, x * x + y * y):
            if l0 * l1 > 0:
                return {"kind": "point", "point": np.array([x, y]), "imaginary": False}
            # two lines through x0: sqrt|l0| u = ± sqrt|l1| v in the eigenframe
            s0, s1 = math.sqrt(abs(l0)), math.sqrt(abs(l1))
            lines = []
            for sg in (1.0, -1.0):
                n0, n1 = s0 * r0[0] - sg * s1 * r1[0], s0 * r0[1] - sg * s1 * r1[1]
                lines.append(_line_from_euclid(n0, n1, -(n0 * x + n1 * y)))
            return {"kind": "lines", "lines": lines, "imaginary": False}
        imaginary = False
        if l0 * l1 > 0:
            if l0 * k > 0:  # no real points: flip the sign of k (package convention)
                imaginary = True
                k = -k
            a0, a1 = math.sqrt(-k / l0), math.sqrt(-k / l1)
            kind = "ellipse"
        else:
            # hyperbola: the axis whose eigenvalue has the sign of -k is the real one
            a0, a1 = math.sqrt(abs(k / l0)), math.sqrt(abs(k / l1))
            if l0 * k >= 0:
                a0, a1 = a1, a0
                r0, r1 = r1, (-r0[0], -r0[1])
            kind = "hyperbola"
        aff = np.array([[r0[0] * a0, r1[0] * a1, x], [r0[1] * a0, r1[1] * a1, y], [0.0, 0.0, 1.0]])
        return {"kind": kind, "affine": aff, "imaginary": imaginary, "center": np.array([x, y])}
    if abs(l0) > rtol:
        # A has rank one: parabola or parallel lines
        be, bf = b0 * r0[0] + b1 * r0[1], b0 * r1[0] + b1 * r1[1]
        if abs(bf) > rtol * max(1.0, abs(be), abs(c)):
            # l0 u^2 + 2 be u + 2 bf v + c = 0  ->  v = -(l0 u^2 + 2 be u + c) / (2 bf)
            u0 = -be / l0
            v0 = -(c - be * be / l0) / (2 * bf)
            kcoef = -l0 / (2 * bf)  # v - v0 = kcoef (u - u0)^2
            # unit parabola (s, s^2): u = u0 + s / kcoef, v = v0 + s^2 / kcoef
            aff = np.array([[r0[0] / kcoef, r1[0] / kcoef, u0 * r0[0] + v0 * r1[0]],
                            [r0[1] / kcoef, r1[1] / kcoef, u0 * r0[1] + v0 * r1[1]],
                            [0.0, 0.0, 1.0]])
            return {"kind": "parabola", "affine": aff, "imaginary": False}
        disc = be * be - l0 * c
        if disc < -rtol:
            return {"kind": "empty", "imaginary": True}
        r = math.sqrt(max(disc, 0.0))
        us = sorted({(-be + r) / l0, (-be - r) / l0}) if r > 0 else [-be / l0]
        return {"kind": "lines", "imaginary": False,
                "lines": [_line_from_euclid(r0[0], r0[1], -u) for u in us]}
    # A == 0: the line at infinity times a finite line  2 b.x + c = 0
    if math.hypot(b0, b1) > rtol:
        return {"kind": "lines", "imaginary": False,
                "lines": [_line_from_euclid(2 * b0, 2 * b1, c)], "line_at_infinity": True}
    return {"kind": "lines", "imaginary": False, "lines": [], "line_at_infinity": True}


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
        x0, x1, y0, y1 = box
        out = []
        for c in curves:
            x, y = c[:, 0], c[:, 1]
            keep = np.all(np.isfinite(c), axis=1) & (x >= x0) & (x <= x1) & (y >= y0) & (y <= y1)
            out += _runs(c, keep)
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
