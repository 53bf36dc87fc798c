"""Geometric constructions of the thesis, drawn from computed quantities.

Every function takes the quantities (arrays in the package's coordinates, or
planargeo objects), computes what the construction needs with the math modules
(:mod:`planargeo.projective`, conic polarity ``C p`` / ``C⁻¹ l``, twist and
wrench sums) and draws it with the artists of :mod:`planargeo.draw.artists`.
They take ``ax=None`` (current axes) and return a dict of the artists made,
keyed by name, so a caller (a widget) can update them.

Thesis figures: twist addition (4.1, 4.3), wrench addition (4.4–4.6), pole and
polar constructions (5.2, 5.3), tangents, the axis of percussion (5.6), power
relations (5.7), velocity / acceleration kinematics along a chain (4.7, 4.8),
Newton–Euler balance of one body (4.9), T/U decompositions (6.1–6.5).
"""
from __future__ import annotations

import numpy as np

from ..conics import (line_conic_intersections, polar, polar_construction_exterior,
                      polar_construction_interior)
from ..inertia import percussion_axis
from ..projective import from_xy, join, meet, to_xy
from .artists import _mat, _vec, plot_conic, plot_line, plot_point
from .style import COLORS, style

__all__ = [
    "line_conic_points", "tangent_points", "label",
    "draw_twist_sum", "draw_wrench_sum", "draw_polar_exterior", "draw_polar_interior",
    "draw_tangent", "draw_percussion", "draw_power", "draw_segment", "draw_dimension",
]


def _ax(ax):
    if ax is None:
        import matplotlib.pyplot as plt

        ax = plt.gca()
    return ax


def label(ax, xy, text, *, offset=(5, 5), color=None, ha="left", va="bottom", **kw):
    """A text label at data point ``xy`` shifted by ``offset`` points."""
    return ax.annotate(text, xy=tuple(np.asarray(xy, float)), xytext=offset,
                       textcoords="offset points", color=color or COLORS["text"],
                       ha=ha, va=va, fontsize=kw.pop("fontsize", 8), **kw)


def draw_segment(ax, p, q, role="construct", **kw):
    """A finite segment between two Euclidean points in a role's style."""
    st = {k: v for k, v in style(role).items() if k in ("color", "linewidth", "linestyle")}
    st.update(kw)
    (ln,) = ax.plot([p[0], q[0]], [p[1], q[1]], **st)
    return ln


def draw_dimension(ax, p, q, text, *, offset=0.0, color=None, fontsize=7):
    """A dimension arrow ``<->`` between Euclidean points ``p`` and ``q``, labelled ``text``."""
    p, q = np.asarray(p, float), np.asarray(q, float)
    d = q - p
    n = np.array([-d[1], d[0]]) / max(np.hypot(*d), 1e-300)
    p2, q2 = p + offset * n, q + offset * n
    arr = ax.annotate("", xy=tuple(q2), xytext=tuple(p2),
                      arrowprops=dict(arrowstyle="<->", color=color or COLORS["construct"],
                                      lw=0.7, shrinkA=0, shrinkB=0))
    m = (p2 + q2) / 2
    txt = ax.annotate(text, xy=tuple(m), xytext=tuple(4 * n), textcoords="offset points",
                      ha="center", va="center", fontsize=fontsize, color=color or COLORS["text"])
    return arr, txt


# --------------------------------------------------------------------------- conic helpers
def line_conic_points(C, L) -> list[np.ndarray]:
    """Real common points of line ``L`` and conic ``C`` (0 or 2 homogeneous points; GEO's
    :func:`planargeo.conics.line_conic_intersections`)."""
    X, real = line_conic_intersections(_mat(C, "C"), _vec(L, "L"))
    return [X[0], X[1]] if bool(real) else []


def tangent_points(C, p) -> list[np.ndarray]:
    """Points where the tangents from ``p`` touch ``C``: the conic meets the polar ``C p`` (5.36)."""
    C = _mat(C, "C")
    return line_conic_points(C, polar(C, _vec(p, "p")))


# --------------------------------------------------------------------------- twist / wrench sums
def draw_twist_sum(v1, v2, ax=None, *, labels=("$v_1$", "$v_2$", "$v_3 = v_1 + v_2$"),
                   lever=True, glyph_scale=6.0):
    """Twist addition (thesis 4.11–4.16, Figs 4.1, 4.3): ``v3 = v1 + v2`` lies on ``join(v1, v2)``.

    Returns the artists ``{"v1", "v2", "v3", "lever"}``.
    """
    ax = _ax(ax)
    v1, v2 = _vec(v1, "v1"), _vec(v2, "v2")
    v3 = v1 + v2
    out = {}
    if lever:
        out["lever"] = plot_line(join(v1, v2), ax, role="construct", scale=None)
    out["v1"] = plot_point(v1, ax, text=labels[0], glyph_scale=glyph_scale)
    out["v2"] = plot_point(v2, ax, text=labels[1], glyph_scale=glyph_scale)
    out["v3"] = plot_point(v3, ax, role="accel", text=labels[2], glyph_scale=glyph_scale)
    return out


def draw_wrench_sum(f1, f2, ax=None, *, labels=("$f_1$", "$f_2$", "$f_3 = f_1 + f_2$"),
                    scale=1.0, anchors=(None, None, None), parallelogram=True):
    """Wrench addition (thesis 4.33–4.46, Figs 4.4–4.6): ``f3 = f1 + f2``.

    Two crossing forces: ``f3`` passes through ``meet(f1, f2)`` and the force
    parallelogram is drawn there.  Parallel forces: ``f3`` lies between them by
    the lever rule (4.43); a force and a couple: ``f3`` is parallel to ``f1``
    at ``ρ = τ/F`` (4.46).  Returns ``{"f1", "f2", "f3", "meet", ...}``.
    """
    ax = _ax(ax)
    f1, f2 = _vec(f1, "f1"), _vec(f2, "f2")
    f3 = f1 + f2
    out = {}
    P = np.cross(f1, f2)
    finite_meet = P[2] != 0.0 and np.any(f1[:2]) and np.any(f2[:2])
    anc = list(anchors)
    if finite_meet and parallelogram:
        Pxy = to_xy(P)
        anc = [Pxy + scale * f1[:2] / 2, Pxy + scale * f2[:2] / 2, Pxy + scale * f3[:2] / 2]
    out["f1"] = plot_line(f1, ax, text=labels[0], scale=scale, anchor=anc[0])
    out["f2"] = plot_line(f2, ax, text=labels[1], scale=scale, anchor=anc[1],
                          corner="upper left")
    out["f3"] = plot_line(f3, ax, role="reaction", text=labels[2], scale=scale, anchor=anc[2])
    if finite_meet:
        Pxy = to_xy(P)
        out["meet"] = ax.plot(*Pxy, "o", color=COLORS["construct"], ms=3.5, zorder=5)[0]
        if parallelogram:
            a, b = Pxy + scale * f1[:2], Pxy + scale * f2[:2]
            c = Pxy + scale * f3[:2]
            out["parallelogram"] = [draw_segment(ax, a, c), draw_segment(ax, b, c)]
    return out


# --------------------------------------------------------------------------- pole / polar
def draw_tangent(C, q, ax=None, *, text=None):
    """The tangent ``C q`` at a point ``q`` of the conic (5.38–5.39)."""
    ax = _ax(ax)
    C, q = _mat(C, "C"), _vec(q, "q")
    return {"q": plot_point(q, ax, role="twist", glyph=False, text=text),
            "tangent": plot_line(polar(C, q), ax, role="construct", scale=None)}


def draw_polar_exterior(C, p, ax=None, *, names=("$P$", "$L = CP$")):
    """Polar of an exterior point (thesis 5.36, Fig. 5.2): tangents from ``p``; ``L`` joins their contacts."""
    ax = _ax(ax)
    C, p = _mat(C, "C"), _vec(p, "p")
    K = polar_construction_exterior(C, p)
    out = {"conic": plot_conic(C, ax, text="$C$"),
           "P": plot_point(p, ax, glyph=False, text=names[0]),
           "L": plot_line(K.polar, ax, role="wrench", scale=None, text=names[1])}
    out["construction"] = K
    out["tangents"] = [plot_line(t, ax, role="construct", scale=None) for t in K.tangents]
    out["touch_marks"] = [ax.plot(*to_xy(t), "o", color=COLORS["construct"], ms=3.5, zorder=5)[0]
                          for t in K.contacts]
    return out


def draw_polar_interior(C, p, ax=None, *, angles=(0.35, 1.9), names=("$P$", "$L = CP$")):
    """Polar of an interior point (thesis 5.36, Fig. 5.3).

    Two chords through ``p`` (at ``angles``); the tangents at each chord's ends
    meet in a point; the two points span ``L``.  Each of them is the pole of
    its chord (Theorem 12), which is why ``L`` passes through both.
    """
    ax = _ax(ax)
    C, p = _mat(C, "C"), _vec(p, "p")
    pxy = to_xy(p)
    lines = np.stack([join(p, from_xy(pxy + [np.cos(t), np.sin(t)])) for t in angles])
    K = polar_construction_interior(C, p, lines=lines)
    out = {"conic": plot_conic(C, ax, text="$C$"),
           "P": plot_point(p, ax, glyph=False, text=names[0]), "construction": K}
    out["chords"] = [plot_line(ln, ax, role="construct", scale=None) for ln in K.lines]
    for k in range(2):
        for j in range(2):
            plot_line(K.tangents[k, j], ax, role="construct", scale=None, linewidth=0.6)
            ax.plot(*to_xy(K.chord_points[k, j]), "o", color=COLORS["construct"], ms=3, zorder=5)
        plot_point(K.poles[k], ax, glyph=False, role="accel", text=f"$R_{k + 1}$")
    out["L"] = plot_line(K.polar, ax, role="wrench", scale=None, text=names[1])
    return out


# --------------------------------------------------------------------------- inertia
def draw_percussion(I, a, ax=None, *, names=("$a$", "$f = Ia$"), dims=True, scale=None):
    """Axis of percussion ``f = I a`` of an acceleration pole ``a`` (thesis 5.64–5.68, Fig. 5.6).

    Draws the inertia (radius-of-gyration circle, dashed), the pole and the
    axis; with ``dims`` the distances ``d`` (pole to centre of mass) and
    ``ρ²/d`` (centre of mass to the axis) along the line through both.
    """
    ax = _ax(ax)
    I, a = _mat(I, "inertia"), _vec(a, "a")
    f = percussion_axis(I, a)
    m = I[0, 0]
    c = np.array([I[1, 2], -I[0, 2]]) / m
    out = {"inertia": plot_conic(I, ax, role="inertia"),
           "a": plot_point(a, ax, role="accel", text=names[0]),
           "f": plot_line(f, ax, role="wrench", scale=scale, text=names[1])}
    axy = to_xy(a)
    if dims and a[2] != 0.0 and np.any(f[:2]):
        foot = to_xy(meet(f, join(a, from_xy(c))))
        out["dims"] = [draw_dimension(ax, axy, c, "$d$", offset=0.0),
                       draw_dimension(ax, c, foot, r"$\rho^2/d$", offset=0.0)]
        out["lever"] = draw_segment(ax, axy, foot)
    return out


def draw_power(v, I, ax=None, *, f_offset=0.6, a_offset=0.8):
    """Power relations (thesis 5.69–5.74, Fig. 5.7).

    A powerless force ``f`` passes through the velocity pole ``v``
    (``vᵀ f = 0``); a powerless acceleration ``a`` lies on the momentum line
    ``p = I v`` (``pᵀ a = 0``).  ``f`` and ``a`` are picked on those
    incidences at the given offsets.
    """
    ax = _ax(ax)
    v, I = _vec(v, "v"), _mat(I, "inertia")
    p = I @ v
    vxy = to_xy(v)
    ang = np.arctan2(p[1], p[0]) + f_offset
    f = join(v, from_xy(vxy + [np.cos(ang), np.sin(ang)]))  # a line through v
    fp = p[:2] / np.hypot(*p[:2])
    foot = to_xy(np.array([-p[0] * p[2], -p[1] * p[2], p[0] ** 2 + p[1] ** 2]))
    a = from_xy(foot + a_offset * 2 * fp)
    out = {"inertia": plot_conic(I, ax, role="inertia"),
           "v": plot_point(v, ax, text="$v$"),
           "p": plot_line(p, ax, role="momentum", scale=None, text="$p = Iv$"),
           "f": plot_line(f, ax, role="wrench", scale=None, text="$f$: $v^Tf = 0$",
                          anchor=vxy + 1.6 * np.array([np.cos(ang), np.sin(ang)])),
           "a": plot_point(a, ax, role="accel", text="$a$: $p^Ta = 0$", glyph=False)}
    out["checks"] = (float(v @ f), float(p @ a))
    return out
