"""Geometric constructions of the thesis, drawn from computed quantities.

Every function takes the quantities (arrays in the package's coordinates, or
planargeo objects), computes what the construction needs with the math modules
(:mod:`planargeo.geometry.projective`, conic polarity ``C p`` / ``C⁻¹ l``, twist and
wrench sums) and draws it with the artists of :mod:`planargeo.draw.artists`.
They take ``ax=None`` (current axes) and return a dict of the artists made,
keyed by name, so a caller (a gallery figure) can adjust them.

Thesis figures: twist addition (4.1, 4.3), wrench addition (4.4–4.6), pole and
polar constructions (5.2, 5.3), tangents, the axis of percussion (5.6), power
relations (5.7), velocity / acceleration kinematics along a chain (4.7, 4.8),
Newton–Euler balance of one body (4.9), T/U decompositions (6.1–6.5).
"""
from __future__ import annotations

import numpy as np

from planargeo.geometry.conics import (line_conic_intersections, polar_construction_exterior,
                      polar_construction_interior)
from planargeo.screws.inertia import centre_of_mass, percussion_axis
from planargeo.geometry.projective import from_direction, from_xy, join, meet, to_xy
from planargeo.screws.twists import bias_force, kappa
from planargeo.draw.artists import _mat, _vec, plot_conic, plot_line, plot_point
from planargeo.draw.style import COLORS, LABEL_PT, get_ax, style, sum_style
from planargeo.errors import InputError
from planargeo.mechanics.subspaces import Decomposition

__all__ = [
    "line_conic_points", "label",
    "draw_twist_sum", "draw_wrench_sum", "draw_velocity_step", "draw_acceleration_step",
    "draw_newton_euler", "draw_polar_exterior", "draw_polar_interior",
    "draw_percussion", "draw_power", "draw_segment", "draw_dimension",
    "draw_decomposition", "draw_twist_split", "draw_wrench_split", "draw_projective_step",
]


def _is_axes(x) -> bool:
    """True for a matplotlib axes (the former first argument of :func:`label`, :func:`draw_segment`
    and :func:`draw_dimension`)."""
    return hasattr(x, "transData") and hasattr(x, "annotate")


def _former_order(args: tuple, n: int, name: str, ax):
    """``(ax, args)`` of a call in the former order ``name(ax, *args)``; ``args`` unchanged otherwise.

    The former order put ``ax`` first; every drawing function now takes what
    it draws first and ``ax=None`` as a keyword.  Calls in the former order
    keep working (the gallery's figures use it) and are read as the new one.
    """
    if not args or not _is_axes(args[0]):
        return ax, args
    if ax is not None:
        raise InputError(f"{name}: ax given twice (first argument and ax=)")
    if len(args) < n + 1:
        raise InputError(f"{name} needs {n} arguments besides ax, got {len(args) - 1}")
    return args[0], args[1:]


def label(*args, ax=None, offset=(5, 5), color=None, ha="left", va="bottom", **kw):
    """A text label at data point ``xy`` shifted by ``offset`` points: ``label(xy, text, ax=None)``.

    Parameters
    ----------
    *args
        ``xy, text`` (below); the former order ``ax, xy, text`` is read too.
    xy : array_like (2,)
        Euclidean data point the label refers to.
    text : str
        The label (matplotlib mathtext allowed).
    ax : matplotlib.axes.Axes, optional
        Where to draw (default: the current axes, :func:`~planargeo.draw.style.get_ax`).
        The former call ``label(ax, xy, text)`` is still read correctly.
    offset : (float, float)
        Shift of the text in points.
    color, ha, va, **kw
        Text colour (default the text colour of the style), alignment and
        further :meth:`~matplotlib.axes.Axes.annotate` keywords (``fontsize``
        defaults to :data:`~planargeo.draw.style.LABEL_PT`).

    Returns
    -------
    matplotlib.text.Annotation

    Raises
    ------
    InputError
        Not two arguments ``xy, text`` (besides a leading axes).

    Examples
    --------
    >>> import matplotlib; matplotlib.use("Agg")
    >>> import matplotlib.pyplot as plt
    >>> fig, ax = plt.subplots()
    >>> label((1.0, 2.0), "$P$", ax=ax).get_text()
    '$P$'
    >>> plt.close(fig)
    """
    ax, args = _former_order(args, 2, "label", ax)
    if len(args) != 2:
        raise InputError(f"label takes (xy, text), got {len(args)} positional arguments")
    xy, text = args
    return get_ax(ax).annotate(text, xy=tuple(np.asarray(xy, float)), xytext=offset,
                               textcoords="offset points", color=color or COLORS["text"],
                               ha=ha, va=va, fontsize=kw.pop("fontsize", LABEL_PT), **kw)


def draw_segment(*args, ax=None, role="construct", **kw):
    """A finite segment between two Euclidean points in a role's style: ``draw_segment(p, q, ax=None)``.

    Parameters
    ----------
    *args
        ``p, q`` (below); the former order ``ax, p, q[, role]`` is read too.
    p, q : array_like (2,)
        The end points.
    ax : matplotlib.axes.Axes, optional
        Where to draw (default: the current axes).  The former call
        ``draw_segment(ax, p, q[, role])`` is still read correctly.
    role : str
        Style role (:func:`~planargeo.draw.style.style`), default ``"construct"``.
    **kw
        Line properties overriding the role's.

    Returns
    -------
    matplotlib.lines.Line2D

    Raises
    ------
    InputError
        Not two end points, or an unknown role.
    """
    ax, args = _former_order(args, 2, "draw_segment", ax)
    if len(args) == 3:                      # the former positional role
        args, role = args[:2], args[2]
    if len(args) != 2:
        raise InputError(f"draw_segment takes (p, q), got {len(args)} positional arguments")
    p, q = args
    st = {k: v for k, v in style(role).items() if k in ("color", "linewidth", "linestyle")}
    st.update(kw)
    (ln,) = get_ax(ax).plot([p[0], q[0]], [p[1], q[1]], **st)
    return ln


def draw_dimension(*args, ax=None, offset=0.0, color=None, fontsize=LABEL_PT, at=0.5):
    """A dimension arrow ``<->`` between ``p`` and ``q``, labelled: ``draw_dimension(p, q, text, ax=None)``.

    The arrow is shifted by ``offset`` (data units) to the left of ``p → q``;
    the label sits at fraction ``at`` along it, on the same side.

    Parameters
    ----------
    *args
        ``p, q, text`` (below); the former order ``ax, p, q, text`` is read too.
    p, q : array_like (2,)
        Distinct Euclidean points.
    text : str
        The dimension's label.
    ax : matplotlib.axes.Axes, optional
        Where to draw (default: the current axes).  The former call
        ``draw_dimension(ax, p, q, text)`` is still read correctly.
    offset, color, fontsize, at
        Placement and look (see above).

    Returns
    -------
    (Annotation, Annotation)
        The arrow and its label.

    Raises
    ------
    InputError
        ``p`` and ``q`` coincide, or not three arguments ``p, q, text``.
    """
    ax, args = _former_order(args, 3, "draw_dimension", ax)
    if len(args) != 3:
        raise InputError(f"draw_dimension takes (p, q, text), got {len(args)} positional arguments")
    p, q, text = args
    ax = get_ax(ax)
    p, q = np.asarray(p, float), np.asarray(q, float)
    d = q - p
    L = np.hypot(*d)
    if L == 0.0:
        raise InputError("draw_dimension: p and q must be distinct points")
    n = np.array([-d[1], d[0]]) / L
    p2, q2 = p + offset * n, q + offset * n
    arr = ax.annotate("", xy=tuple(q2), xytext=tuple(p2),
                      arrowprops=dict(arrowstyle="<->", color=color or COLORS["construct"],
                                      lw=0.7, shrinkA=0, shrinkB=0))
    m = p2 + at * (q2 - p2)
    txt = ax.annotate(text, xy=tuple(m), xytext=tuple(4 * n), textcoords="offset points",
                      ha="center", va="center", fontsize=fontsize, color=color or COLORS["text"])
    return arr, txt


# --------------------------------------------------------------------------- conic helpers
def line_conic_points(C, L) -> list[np.ndarray]:
    """Real common points of line ``L`` and conic ``C`` (0 or 2 homogeneous points; GEO's
    :func:`planargeo.geometry.conics.line_conic_intersections`).

    Parameters
    ----------
    C : array_like (3, 3)
        A conic.
    L : array_like (3,)
        A line.

    Returns
    -------
    list of ndarray (3,)
        The two real common points, or an empty list when the line misses the conic.

    Raises
    ------
    ShapeError, NonFiniteError
        An argument that is not a finite homogeneous vector (or 3×3 matrix), named.
    """
    X, real = line_conic_intersections(_mat(C, "C"), _vec(L, "L"))
    return [X[0], X[1]] if bool(real) else []


# --------------------------------------------------------------------------- twist / wrench sums
def _lever(p, q):
    """``p × q`` without the coincidence check of :func:`join`: zero when the poles coincide
    (then every line through the common pole is a lever; the artist draws nothing)."""
    return np.cross(p, q)


def draw_twist_sum(v1, v2, ax=None, *, labels=("$v_1$", "$v_2$", "$v_3 = v_1 + v_2$"),
                   lever=True, glyph_scale=6.0, role="twist", text_offsets=(None, None, None)):
    """Twist addition (thesis 4.11–4.16, Figs 4.1, 4.3): ``v3 = v1 + v2`` lies on ``join(v1, v2)``.

    The sum is a twist like its terms: same ``role`` colour, marked by
    :func:`~planargeo.draw.style.sum_style` (larger diamond).  Coincident poles
    (``v2`` a multiple of ``v1``) have no lever line: its artist then draws
    nothing.  Returns the artists ``{"v1", "v2", "v3", "lever"}``.

    Parameters
    ----------
    v1, v2 : array_like (3,)
        The twists (points).
    ax : matplotlib.axes.Axes, optional
        Where to draw (default: the current axes, :func:`~planargeo.draw.style.get_ax`).
    labels : (str, str, str)
        Labels of ``v1``, ``v2`` and the sum.
    lever : bool
        Draw the line joining the poles.
    glyph_scale : float
        Rotation glyph size (points per unit rate).
    role : str
        Style role of the three points.
    text_offsets : (offset, offset, offset)
        Label offsets in points (None: automatic).

    Returns
    -------
    dict
        The artists ``{"v1", "v2", "v3", "lever"}``.

    Raises
    ------
    ShapeError, NonFiniteError
        An argument that is not a finite homogeneous vector (or 3×3 matrix), named.

    Examples
    --------
    >>> import matplotlib
    >>> matplotlib.use("Agg")
    >>> import matplotlib.pyplot as plt
    >>> from planargeo.screws.twists import unit_rotation
    >>> out = draw_twist_sum(unit_rotation([0, 0]), 2 * unit_rotation([3, 0]), plt.figure().gca())
    >>> out["v3"].get_xy()          # beta = 2 / 3 of the way from Q1 to Q2 (4.12-4.13)
    array([2., 0.])
    >>> plt.close("all")
    """
    ax = get_ax(ax)
    v1, v2 = _vec(v1, "v1"), _vec(v2, "v2")
    v3 = v1 + v2
    out = {}
    if lever:
        out["lever"] = plot_line(_lever(v1, v2), ax, role="construct", scale=None)
    o1, o2, o3 = text_offsets
    out["v1"] = plot_point(v1, ax, role=role, text=labels[0], glyph_scale=glyph_scale,
                           text_offset=o1)
    out["v2"] = plot_point(v2, ax, role=role, text=labels[1], glyph_scale=glyph_scale,
                           text_offset=o2)
    out["v3"] = plot_point(v3, ax, role=role, text=labels[2], glyph_scale=glyph_scale,
                           text_offset=o3, **sum_style("point"))
    return out


def draw_wrench_sum(f1, f2, ax=None, *, labels=("$f_1$", "$f_2$", "$f_3 = f_1 + f_2$"),
                    scale=1.0, anchors=(None, None, None), parallelogram=True,
                    text_offsets=(None, None, None), role="wrench"):
    """Wrench addition (thesis 4.33–4.46, Figs 4.4–4.6): ``f3 = f1 + f2``.

    Two crossing forces: ``f3`` passes through ``meet(f1, f2)`` and the force
    parallelogram is drawn there.  Parallel forces: ``f3`` lies between them by
    the lever rule (4.43); a force and a couple: ``f3`` is parallel to ``f1``
    at ``ρ = τ/F`` (4.46).  The sum is a wrench like its terms: same ``role``
    colour, heavier line (:func:`~planargeo.draw.style.sum_style`).
    Returns ``{"f1", "f2", "f3", "meet", ...}``.
    

    Parameters
    ----------
    f1, f2 : array_like (3,)
        The wrenches (lines).
    ax : matplotlib.axes.Axes, optional
        Where to draw (default: the current axes, :func:`~planargeo.draw.style.get_ax`).
    labels : (str, str, str)
        Labels of ``f1``, ``f2`` and the sum.
    scale : float
        Force arrow length per unit force (data units).
    anchors : (xy, xy, xy)
        Where each arrow sits (None: automatic; the parallelogram's corners when drawn).
    parallelogram : bool
        Draw the force parallelogram at the meet of crossing lines.
    text_offsets : (offset, offset, offset)
        Label offsets in points.
    role : str
        Style role of the three lines.

    Returns
    -------
    dict
        The artists ``{"f1", "f2", "f3"}`` and, for crossing lines, ``"meet"`` and
        ``"parallelogram"``.

    Raises
    ------
    ShapeError, NonFiniteError
        An argument that is not a finite homogeneous vector (or 3×3 matrix), named.
    """
    ax = get_ax(ax)
    f1, f2 = _vec(f1, "f1"), _vec(f2, "f2")
    f3 = f1 + f2
    out = {}
    P = np.cross(f1, f2)
    finite_meet = P[2] != 0.0 and np.any(f1[:2]) and np.any(f2[:2])
    anc = list(anchors)
    if finite_meet and parallelogram:
        Pxy = to_xy(P)
        anc = [Pxy + scale * f1[:2] / 2, Pxy + scale * f2[:2] / 2, Pxy + scale * f3[:2] / 2]
    off = list(text_offsets)
    out["f1"] = plot_line(f1, ax, role=role, text=labels[0], scale=scale, anchor=anc[0],
                          text_offset=off[0])
    out["f2"] = plot_line(f2, ax, role=role, text=labels[1], scale=scale, anchor=anc[1],
                          corner="upper left", text_offset=off[1])
    out["f3"] = plot_line(f3, ax, role=role, text=labels[2], scale=scale, anchor=anc[2],
                          text_offset=off[2], **sum_style("line"))
    if finite_meet:
        Pxy = to_xy(P)
        out["meet"] = ax.plot(*Pxy, "o", color=COLORS["construct"], ms=3.5, zorder=5)[0]
        if parallelogram:
            a, b = Pxy + scale * f1[:2], Pxy + scale * f2[:2]
            c = Pxy + scale * f3[:2]
            out["parallelogram"] = [draw_segment(a, c, ax=ax), draw_segment(b, c, ax=ax)]
    return out


# --------------------------------------------------------------------------- chains, one body
def draw_velocity_step(v_prev, s, qd, ax=None, *,
                       names=("$v_{i-1}$", r"$s_i\dot q_i$", "$v_i$"),
                       text_offsets=(None, None, None), dims=True, dim_offset=0.25):
    """One step of velocity kinematics along a chain (thesis 4.47–4.49, Fig. 4.7).

    ``v_i = v_{i-1} + s_i q̇_i`` is a twist sum: the pole of ``v_i`` lies on
    the line joining the pole of ``v_{i-1}`` and the joint (the pole of
    ``s_i``), at ``β k`` from the former with ``β = q̇_i/(q̇_i + ω_{i-1})``.
    With ``dims`` the distance ``k`` between the two poles is dimensioned
    (when both are finite), ``dim_offset`` to the left of the lever line.

    Returns the artists of :func:`draw_twist_sum` keyed ``{"v_prev", "joint",
    "v", "lever"}`` (plus ``"k"``) and ``"values"``: the arrays
    ``{"joint": s q̇, "v": v_i}``.
    

    Parameters
    ----------
    v_prev : array_like (3,)
        The previous body's twist ``v_{i-1}``.
    s : array_like (3,)
        The joint's unit twist ``s_i``.
    qd : float
        The joint speed ``q̇_i``.
    ax : matplotlib.axes.Axes, optional
        Where to draw (default: the current axes, :func:`~planargeo.draw.style.get_ax`).
    names : (str, str, str)
        Labels of ``v_{i-1}``, ``s_i q̇_i`` and ``v_i``.
    text_offsets : (offset, offset, offset)
        Label offsets in points.
    dims, dim_offset
        Dimension the distance ``k`` (offset to the left of the lever, data units).

    Returns
    -------
    dict
        See above.

    Raises
    ------
    ShapeError, NonFiniteError
        An argument that is not a finite homogeneous vector (or 3×3 matrix), named.
    """
    ax = get_ax(ax)
    v_prev = _vec(v_prev, "v_prev")
    u = _vec(s, "s") * float(qd)
    art = draw_twist_sum(v_prev, u, ax, labels=names, text_offsets=text_offsets)
    out = {"v_prev": art["v1"], "joint": art["v2"], "v": art["v3"], "lever": art["lever"],
           "values": {"joint": u, "v": v_prev + u}}
    if dims and v_prev[2] != 0.0 and u[2] != 0.0:
        out["k"] = draw_dimension(to_xy(v_prev), to_xy(u), "$k$", ax=ax, offset=dim_offset)
    return out


def draw_acceleration_step(a_prev, v_prev, s, qd, qdd, ax=None, *,
                           names=("$a_{i-1}$", r"$s_i\ddot q_i$", r"$v_i\times s_i\dot q_i$",
                                  r"$s_i\ddot q_i + v_i\times s_i\dot q_i$", "$a_i$"),
                           text_offsets=(None,) * 5):
    """One step of acceleration kinematics along a chain (thesis 4.50–4.54, Fig. 4.8).

    ``a_i = a_{i-1} + s_i q̈_i + κ_i`` with the bias ``κ_i = v_i × s_i q̇_i``
    (:func:`planargeo.screws.kappa`), a translation (an ideal point).  The
    joint's part ``s_i q̈_i + κ_i`` is a rotation on the line through the joint
    in the direction of that ideal point, offset by ``|κ_i| / q̈_i`` (4.54), and
    ``a_i`` lies on its line to ``a_{i-1}``; all five are accelerations
    (vermillion), ``a_i`` marked as the sum.

    Returns the artists ``{"a_prev", "joint", "bias", "joint_total", "a",
    "lever", "joint_lever"}`` and ``"values"`` (the arrays of the same names).
    

    Parameters
    ----------
    a_prev, v_prev : array_like (3,)
        The previous body's acceleration and velocity twists.
    s : array_like (3,)
        The joint's unit twist.
    qd, qdd : float
        Joint speed and acceleration.
    ax : matplotlib.axes.Axes, optional
        Where to draw (default: the current axes, :func:`~planargeo.draw.style.get_ax`).
    names : tuple of 5 str
        Labels of the five points.
    text_offsets : tuple of 5 offsets
        Label offsets in points.

    Returns
    -------
    dict
        See above.

    Raises
    ------
    ShapeError, NonFiniteError
        An argument that is not a finite homogeneous vector (or 3×3 matrix), named.
    """
    ax = get_ax(ax)
    a_prev, v_prev, s = _vec(a_prev, "a_prev"), _vec(v_prev, "v_prev"), _vec(s, "s")
    rel = s * float(qdd)
    bias = kappa(v_prev, s, float(qd))
    combo = rel + bias
    a = a_prev + combo
    o = list(text_offsets)
    out = {"lever": plot_line(_lever(a_prev, combo), ax, role="construct", scale=None),
           "joint_lever": plot_line(_lever(rel, bias), ax, role="construct", scale=None,
                                    linewidth=0.6)}
    out["a_prev"] = plot_point(a_prev, ax, role="accel", text=names[0], text_offset=o[0])
    out["joint"] = plot_point(rel, ax, role="accel", text=names[1], text_offset=o[1])
    out["bias"] = plot_point(bias, ax, role="accel", text=names[2], text_offset=o[2])
    out["joint_total"] = plot_point(combo, ax, role="accel", text=names[3], text_offset=o[3])
    out["a"] = plot_point(a, ax, role="accel", text=names[4], text_offset=o[4],
                          **sum_style("point"))
    out["values"] = {"a_prev": a_prev, "joint": rel, "bias": bias, "joint_total": combo, "a": a}
    return out


def draw_newton_euler(I, a, v, ax=None, *, scale=None, names=("$v$", "$a$", "$Ia$", "$p$",
                                                               r"$f^{net} = Ia + p$"),
                      positions=(-1.0, -0.9, 1.0), text_offsets=(None,) * 5, inertia=True):
    """Newton–Euler balance of one body (thesis 4.55–4.56, Fig. 4.9): ``f_net = I a + p``.

    ``I a`` is the axis of percussion of ``a`` (5.64), ``p = v×* I v``
    (:func:`planargeo.screws.bias_force`, no gravity) the centripetal force
    through the centre of mass toward the pole of ``v``, and ``f_net`` their
    sum, drawn as a wrench with the sum's heavier line.  The arrows sit at
    signed distances ``positions`` (for ``Ia``, ``p``, ``f_net``) along each
    line from the foot of the centre of mass.

    Returns the artists ``{"inertia", "v", "a", "Ia", "p", "f_net"}`` and
    ``"values"`` (the arrays ``Ia``, ``p``, ``f_net``).
    

    Parameters
    ----------
    I : array_like (3, 3)
        The body's inertia.
    a, v : array_like (3,)
        Its acceleration and velocity twists.
    ax : matplotlib.axes.Axes, optional
        Where to draw (default: the current axes, :func:`~planargeo.draw.style.get_ax`).
    scale : float, optional
        Force arrow length per unit force (None: no arrows).
    names : tuple of 5 str
        Labels of ``v``, ``a``, ``Ia``, ``p`` and ``f_net``.
    positions : (float, float, float)
        Where the arrows of ``Ia``, ``p`` and ``f_net`` sit (see above).
    text_offsets : tuple of 5 offsets
        Label offsets in points.
    inertia : bool
        Draw the inertia's circle of gyration.

    Returns
    -------
    dict
        See above.

    Raises
    ------
    ShapeError, NonFiniteError
        An argument that is not a finite homogeneous vector (or 3×3 matrix), named.
    """
    ax = get_ax(ax)
    I, a, v = _mat(I, "inertia"), _vec(a, "a"), _vec(v, "v")
    Ia = I @ a
    p = bias_force(I, v)
    fnet = Ia + p
    c = centre_of_mass(I)
    o = list(text_offsets)

    def along(f, t):  # a point at signed distance t along line f from the foot of c
        F = np.hypot(f[0], f[1])
        return None if F == 0.0 else c + f[:2] / F * t

    out = {}
    if inertia:
        out["inertia"] = plot_conic(I, ax, role="inertia")
    out["v"] = plot_point(v, ax, role="twist", text=names[0], text_offset=o[0])
    out["a"] = plot_point(a, ax, role="accel", text=names[1], text_offset=o[1])
    out["Ia"] = plot_line(Ia, ax, role="wrench", scale=scale, text=names[2],
                          anchor=along(Ia, positions[0]), text_offset=o[2])
    out["p"] = plot_line(p, ax, role="momentum", scale=scale, text=names[3],
                         anchor=along(p, positions[1]), text_offset=o[3])
    out["f_net"] = plot_line(fnet, ax, role="wrench", scale=scale, text=names[4],
                             anchor=along(fnet, positions[2]), text_offset=o[4],
                             **sum_style("line"))
    out["values"] = {"Ia": Ia, "p": p, "f_net": fnet}
    return out


# --------------------------------------------------------------------------- pole / polar
def draw_polar_exterior(C, p, ax=None, *, names=("$P$", "$L = CP$"), L_anchor=None):
    """Polar of an exterior point (thesis 5.36, Fig. 5.2): tangents from ``p``; ``L`` joins their contacts.

    Parameters
    ----------
    C : array_like (3, 3)
        A real conic.
    p : array_like (3,)
        An exterior point.
    ax : matplotlib.axes.Axes, optional
        Where to draw (default: the current axes, :func:`~planargeo.draw.style.get_ax`).
    names : (str, str)
        Labels of the point and its polar.
    L_anchor : (x, y), optional
        Where the polar's label sits.

    Returns
    -------
    dict
        The artists ``{"conic", "P", "L", "tangents", "touch_marks"}`` and
        ``"construction"`` (:class:`~planargeo.geometry.conics.ExteriorConstruction`).

    Raises
    ------
    InputError
        An interior point (no real tangents).
    """
    ax = get_ax(ax)
    C, p = _mat(C, "C"), _vec(p, "p")
    K = polar_construction_exterior(C, p)
    out = {"conic": plot_conic(C, ax, text="$C$"),
           "P": plot_point(p, ax, glyph=False, text=names[0]),
           "L": plot_line(K.polar, ax, role="wrench", scale=None, text=names[1],
                          anchor=L_anchor)}
    out["construction"] = K
    out["tangents"] = [plot_line(t, ax, role="construct", scale=None) for t in K.tangents]
    out["touch_marks"] = [ax.plot(*to_xy(t), "o", color=COLORS["construct"], ms=3.5, zorder=5)[0]
                          for t in K.contacts]
    return out


def draw_polar_interior(C, p, ax=None, *, angles=(0.35, 1.9), names=("$P$", "$L = CP$"),
                        L_anchor=None, text_offsets=(None,) * 4):
    """Polar of an interior point (thesis 5.36, Fig. 5.3).

    Two chords through ``p`` (at ``angles``); the tangents at each chord's ends
    meet in a point; the two points span ``L``.  Each of them is the pole of
    its chord (Theorem 12), which is why ``L`` passes through both.
    ``L_anchor`` places ``L``'s label; ``text_offsets`` are for ``P``, ``L``,
    ``R_1``, ``R_2`` (points, None: automatic).
    

    Parameters
    ----------
    C : array_like (3, 3)
        A real conic.
    p : array_like (3,)
        An interior point.
    ax : matplotlib.axes.Axes, optional
        Where to draw (default: the current axes, :func:`~planargeo.draw.style.get_ax`).
    angles : (float, float)
        Directions (radians) of the two chords through ``p``.
    names : (str, str)
        Labels of the point and its polar.
    L_anchor : (x, y), optional
        Where the polar's label sits.
    text_offsets : tuple of 4 offsets
        Label offsets of ``P``, ``L``, ``R_1``, ``R_2``.

    Returns
    -------
    dict
        The artists ``{"conic", "P", "chords", "R1", "R2", "L"}`` and
        ``"construction"`` (:class:`~planargeo.geometry.conics.InteriorConstruction`).

    Raises
    ------
    PlanargeoError
        A chord that misses the conic (named by
        :func:`~planargeo.geometry.conics.polar_construction_interior`).
    """
    ax = get_ax(ax)
    C, p = _mat(C, "C"), _vec(p, "p")
    pxy = to_xy(p)
    lines = np.stack([join(p, from_xy(pxy + [np.cos(t), np.sin(t)])) for t in angles])
    K = polar_construction_interior(C, p, lines=lines)
    out = {"conic": plot_conic(C, ax, text="$C$"),
           "P": plot_point(p, ax, glyph=False, text=names[0], text_offset=text_offsets[0]),
           "construction": K}
    out["chords"] = [plot_line(ln, ax, role="construct", scale=None) for ln in K.lines]
    for k in range(2):
        for j in range(2):
            plot_line(K.tangents[k, j], ax, role="construct", scale=None, linewidth=0.6)
            ax.plot(*to_xy(K.chord_points[k, j]), "o", color=COLORS["construct"], ms=3, zorder=5)
        out[f"R{k + 1}"] = plot_point(K.poles[k], ax, glyph=False, role="accel",
                                      text=f"$R_{k + 1}$", text_offset=text_offsets[2 + k])
    out["L"] = plot_line(K.polar, ax, role="wrench", scale=None, text=names[1], anchor=L_anchor,
                         text_offset=text_offsets[1])
    return out


# --------------------------------------------------------------------------- inertia
def draw_percussion(I, a, ax=None, *, names=("$a$", "$f = Ia$"), dims=True, scale=None,
                    f_anchor=None, text_offsets=(None, None)):
    """Axis of percussion ``f = I a`` of an acceleration pole ``a`` (thesis 5.64–5.68, Fig. 5.6).

    Draws the inertia (radius-of-gyration circle, dashed), the pole and the
    axis; with ``dims`` the distances ``d`` (pole to centre of mass) and
    ``ρ²/d`` (centre of mass to the axis) along the line through both.
    ``f_anchor`` places the axis's label (and arrow, with ``scale``) along it.
    

    Parameters
    ----------
    I : array_like (3, 3)
        The inertia.
    a : array_like (3,)
        The acceleration pole.
    ax : matplotlib.axes.Axes, optional
        Where to draw (default: the current axes, :func:`~planargeo.draw.style.get_ax`).
    names : (str, str)
        Labels of the pole and the axis.
    dims : bool
        Dimension ``d`` and ``ρ²/d``.
    scale : float, optional
        Force arrow length per unit force (None: no arrow).
    f_anchor : (x, y), optional
        Where the axis's label (and arrow) sits.
    text_offsets : (offset, offset)
        Label offsets in points.

    Returns
    -------
    dict
        The artists ``{"inertia", "a", "f"}`` and, with ``dims``, ``"dims"`` and ``"lever"``.

    Raises
    ------
    ShapeError, NonFiniteError
        An argument that is not a finite homogeneous vector (or 3×3 matrix), named.
    """
    ax = get_ax(ax)
    I, a = _mat(I, "inertia"), _vec(a, "a")
    f = percussion_axis(I, a)
    c = centre_of_mass(I)
    out = {"inertia": plot_conic(I, ax, role="inertia"),
           "a": plot_point(a, ax, role="accel", text=names[0], text_offset=text_offsets[0]),
           "f": plot_line(f, ax, role="wrench", scale=scale, text=names[1], anchor=f_anchor,
                          text_offset=text_offsets[1])}
    axy = to_xy(a)
    if dims and a[2] != 0.0 and np.any(f[:2]):
        foot = to_xy(meet(f, join(a, from_xy(c))))
        out["dims"] = [draw_dimension(axy, c, "$d$", ax=ax, offset=0.0),
                       draw_dimension(c, foot, r"$\rho^2/d$", ax=ax, offset=0.0)]
        out["lever"] = draw_segment(axy, foot, ax=ax)
    return out


def draw_power(v, I, ax=None, *, f_angle=0.6, a_distance=1.6,
               names=("$v$", "$p = Iv$", "$f$: $v^Tf = 0$", "$a$: $p^Ta = 0$"),
               text_offsets=(None,) * 4, f_label_at=1.6, p_label_at=None):
    """Power relations (thesis 5.69–5.74, Fig. 5.7).

    A powerless force ``f`` passes through the velocity pole ``v``
    (``vᵀ f = 0``); a powerless acceleration ``a`` lies on the momentum line
    ``p = I v`` (``pᵀ a = 0``), which passes through the centre of mass.

    ``f`` is the line through ``v`` whose direction is the momentum's turned by
    ``f_angle`` (for a translation ``v``, an ideal point: the line through the
    centre of mass along ``v``'s direction); ``a`` is the point of ``p`` at
    signed distance ``a_distance`` from the foot of the perpendicular from the
    centre of mass.  Ideal elements are
    ordinary values: ``v`` at the centre of mass makes ``p`` a pure couple (the
    line at infinity), and ``a`` is then an ideal point (a translation) in the
    direction turned by ``f_angle`` from the x axis.  ``f_label_at`` and
    ``p_label_at`` place the labels of ``f`` and ``p`` at signed distances along
    them from ``v`` and from ``a`` (None: the default place).

    Returns the artists ``{"inertia", "v", "p", "f", "a"}`` and ``"values"``
    (the arrays ``p``, ``f``, ``a``).
    

    Parameters
    ----------
    v : array_like (3,)
        The velocity twist.
    I : array_like (3, 3)
        The inertia.
    ax : matplotlib.axes.Axes, optional
        Where to draw (default: the current axes, :func:`~planargeo.draw.style.get_ax`).
    f_angle, a_distance, f_label_at, p_label_at : float
        Placement (see above).
    names : tuple of 4 str
        Labels of ``v``, ``p``, ``f`` and ``a``.
    text_offsets : tuple of 4 offsets
        Label offsets in points.

    Returns
    -------
    dict
        See above.

    Raises
    ------
    ShapeError, NonFiniteError
        An argument that is not a finite homogeneous vector (or 3×3 matrix), named.
    """
    ax = get_ax(ax)
    v, I = _vec(v, "v"), _mat(I, "inertia")
    p = I @ v
    c = centre_of_mass(I)
    F = np.hypot(p[0], p[1])
    ang = np.arctan2(p[1], p[0]) + f_angle          # arctan2(0, 0) = 0: a couple p
    ef = np.array([np.cos(ang), np.sin(ang)])
    if v[2] != 0.0:
        f = np.cross(v, from_direction(ef))          # through v, along ef
    else:
        f = np.cross(v, from_xy(c))                  # through c, parallel to the translation
    if F != 0.0:   # on p, a_distance from the foot of the perpendicular from the centre of mass
        e = p[:2] / F
        foot = np.cross(p, np.cross(from_xy(c), from_direction([-e[1], e[0]])))   # homogeneous
        a = foot + foot[2] * a_distance * from_direction(e)   # no division by the weight: a
        # nearly-couple p (v close to the centre of mass) gives a far, nearly ideal point
    else:
        a = from_direction(ef)                       # p at infinity: an ideal point
    o = list(text_offsets)
    f_anchor = None
    if v[2] != 0.0 and f_label_at is not None:
        f_anchor = to_xy(v) + f_label_at * ef
    p_anchor = None
    if p_label_at is not None and F != 0.0 and a[2] != 0.0:
        p_anchor = to_xy(a) + p_label_at * p[:2] / F
    out = {"inertia": plot_conic(I, ax, role="inertia"),
           "v": plot_point(v, ax, text=names[0], text_offset=o[0]),
           "p": plot_line(p, ax, role="momentum", scale=None, text=names[1], anchor=p_anchor,
                          text_offset=o[1]),
           "f": plot_line(f, ax, role="wrench", scale=None, text=names[2], anchor=f_anchor,
                          text_offset=o[2]),
           "a": plot_point(a, ax, role="accel", text=names[3], glyph=False, text_offset=o[3])}
    out["values"] = {"p": p, "f": f, "a": a}
    return out


# --------------------------------------------------------------------------- T/U decompositions
def _decomposition(s, R, A):
    """``(s, R, A, T, U)`` of a joint completed by an inertia (thesis 6.36–6.37, 6.45)."""
    dec = Decomposition(A, s, R)
    return dec.s, dec.R, dec.A, dec.T, dec.U


def _names(prefix, k):
    """Artist keys of ``k`` columns: ``prefix`` alone for one column, else ``prefix1``..."""
    return [prefix] if k == 1 else [f"{prefix}{j + 1}" for j in range(k)]


def _tex(sym, k, j):
    """``$sym$`` for one column, ``$sym_{j+1}$`` for column ``j`` of several."""
    return f"${sym}$" if k == 1 else f"${sym}_{{{j + 1}}}$"


def draw_decomposition(s, R, A, ax=None, *, reactive="U", labels=None, anchors=None,
                       text_offsets=None):
    """A joint's spaces completed by an inertia (thesis 6.2–6.3, 6.36–6.48, Figs 6.1, 6.2).

    Draws the motion space ``s`` (joint poles), the percussion space
    ``T = A s (sᵀAs)⁻¹`` (6.36, lines: for a pin, the axis of percussion of the
    joint, ``sᵀT = 1``) and the reaction space ``R`` (lines through the joint),
    and the accelerations the reactions produce: with ``reactive="U"`` the
    decoupled ``U = A⁻¹R(RᵀA⁻¹R)⁻¹`` (6.45, Fig. 6.2: ``RᵀU = 1``, so ``U₁``
    lies on ``R₂`` and ``U₂`` on ``R₁``; ``TᵀU = 0``, all on ``T``), with
    ``reactive="inverse"`` the plain ``A⁻¹R_k`` (Fig. 6.1, the percussion poles
    of the reactions, also on ``T``).

    Parameters
    ----------
    s, R : array_like (3, k), (3, 3-k)
        Motion and reaction spaces of the joint (``sᵀR = 0``).
    A : array_like (3, 3)
        The (rigid or articulated) inertia, positive definite.
    ax : matplotlib.axes.Axes, optional
        Where to draw (default: the current axes).
    reactive : {"U", "inverse"}
        Which accelerations to mark for the reactions (see above).
    labels, anchors, text_offsets : dict, optional
        Per artist key (``"s"``, ``"T"``, ``"R1"``, ``"U1"`` or ``"AiR1"``...):
        the label text (None: no label), where a line's label sits
        (projected onto it) and the label's offset in points.

    Returns
    -------
    dict
        The artists keyed as above (one column: ``"s"``, ``"T"``; several:
        ``"s1"``, ``"T1"``...), and ``"values"``: the arrays ``{"T", "U",
        "AiR"}`` (``AiR = A⁻¹R``).

    Raises
    ------
    InputError
        ``reactive`` is neither "U" nor "inverse".
    PlanargeoError
        Spaces or an inertia the decomposition refuses (named by
        :class:`~planargeo.mechanics.subspaces.Decomposition`).

    Examples
    --------
    A rod of mass 1, centre of mass at (1, 0), pinned at the origin:
    ``T`` is the vertical axis of percussion ``x = (ρ² + 1)/1``.

    >>> import matplotlib; matplotlib.use("Agg")
    >>> import matplotlib.pyplot as plt
    >>> from planargeo.mechanics.joints import revolute
    >>> from planargeo.screws.twists import inertia_matrix
    >>> j, A = revolute([0.0, 0.0]), inertia_matrix(1.0, [1.0, 0.0], 0.25)
    >>> out = draw_decomposition(j.s, j.R, A, plt.figure().gca())
    >>> sorted(k for k in out if k != "values")
    ['R1', 'R2', 'T', 'U1', 'U2', 's']
    >>> T = out["T"].get_line()
    >>> float(T[2] / T[1])                      # x = tz / fy on the axis (4.27): 1 + 0.25
    1.25
    >>> bool(np.allclose(j.R.T @ out["values"]["U"], np.eye(2)))    # RᵀU = 1 (6.48)
    True
    >>> plt.close("all")
    """
    if reactive not in ("U", "inverse"):
        from planargeo.errors import InputError

        raise InputError(f"reactive must be 'U' or 'inverse', got {reactive!r}")
    ax = get_ax(ax)
    s, R, A, T, U = _decomposition(s, R, A)
    AiR = np.linalg.solve(A, R)
    k, r = s.shape[1], R.shape[1]
    pts, psym = (U, "U") if reactive == "U" else (AiR, "A^{-1}R")
    keys = {"s": _names("s", k), "T": _names("T", k), "R": _names("R", r),
            "P": _names("U" if reactive == "U" else "AiR", r)}
    labels, anchors, offs = dict(labels or {}), dict(anchors or {}), dict(text_offsets or {})
    default = {**{n: _tex("s", k, j) for j, n in enumerate(keys["s"])},
               **{n: _tex("T", k, j) for j, n in enumerate(keys["T"])},
               **{n: _tex("R", r, j) for j, n in enumerate(keys["R"])},
               **{n: _tex(psym, r, j) if reactive == "U" or r == 1 else f"$A^{{-1}}R_{j + 1}$"
                  for j, n in enumerate(keys["P"])}}
    for n, t in default.items():
        labels.setdefault(n, t)
    out = {}
    for j, n in enumerate(keys["T"]):
        out[n] = plot_line(T[:, j], ax, role="momentum", scale=None, text=labels[n],
                           anchor=anchors.get(n), text_offset=offs.get(n))
    for j, n in enumerate(keys["R"]):
        out[n] = plot_line(R[:, j], ax, role="reaction", scale=None, text=labels[n],
                           anchor=anchors.get(n), text_offset=offs.get(n))
    for j, n in enumerate(keys["s"]):
        out[n] = plot_point(s[:, j], ax, glyph=False, text=labels[n], text_offset=offs.get(n))
    for j, n in enumerate(keys["P"]):
        out[n] = plot_point(pts[:, j], ax, role="accel", glyph=False, text=labels[n],
                            text_offset=offs.get(n))
    out["values"] = {"T": T, "U": U, "AiR": AiR}
    return out


def _arrow_scale(f, scale, arrow_length):
    """Data units per unit force: ``arrow_length / |F|`` when an arrow length is asked for."""
    if arrow_length is None:
        return scale
    F = float(np.hypot(f[0], f[1]))
    return None if F == 0.0 else float(arrow_length) / F


def _draw_split(parts, show, T, ax, names, text_offsets, scale, arrow_length, show_T, T_anchor):
    """Draw the axis ``T`` and the chosen parts ``(a_k, f_k)``; return the artists and ``"values"``."""
    show, ax = _parts_arg(show), get_ax(ax)
    out = {"values": parts}
    offs = dict(text_offsets or {})
    if show_T:
        for j in range(T.shape[1]):
            n = "T" if T.shape[1] == 1 else f"T{j + 1}"
            out[n] = plot_line(T[:, j], ax, role="construct", scale=None,
                               text=names.get(n, _tex("T", T.shape[1], j)), anchor=T_anchor,
                               text_offset=offs.get(n, (5.0, -2.0)))
    for k in show:
        a, f = parts[f"a{k}"], parts[f"f{k}"]
        out[f"a{k}"] = plot_point(a, ax, role="accel", text=names.get(f"a{k}"),
                                  text_offset=offs.get(f"a{k}"))
        out[f"f{k}"] = plot_line(f, ax, role="wrench", scale=_arrow_scale(f, scale, arrow_length),
                                 text=names.get(f"f{k}"), text_at="anchor",
                                 text_offset=offs.get(f"f{k}"))
    return out


def _parts_arg(parts):
    show = tuple(int(p) for p in parts)
    if not show or any(p not in (1, 2) for p in show):
        from planargeo.errors import InputError

        raise InputError(f"parts must be a non-empty selection of 1 and 2, got {parts!r}")
    return show


def draw_twist_split(s, R, A, a, ax=None, *, parts=(1, 2),
                     names=None, text_offsets=None, scale=1.0, arrow_length=None, show_T=True,
                     T_anchor=None):
    """An acceleration split by a joint, and the forces of its parts (thesis 6.44, 6.75–6.76, Fig. 6.3).

    ``a = s ψ + U γ`` with ``ψ = Tᵀa``, ``γ = Rᵀa`` (6.44, 6.62): ``a₁ = sψ``
    turns the body about the joint, ``a₂ = Uγ`` lies on the axis ``T``.  Their
    forces ``f_k = A a_k`` add up to ``A a`` (the inertia decomposition
    ``A = T sᵀA + R UᵀA``, 6.76): ``f₁ = T sᵀA a`` is a multiple of ``T``,
    ``f₂ = R UᵀA a`` passes through the joint.

    Parameters
    ----------
    s, R, A : array_like
        As in :func:`draw_decomposition`.
    a : array_like (3,)
        The acceleration to split.
    ax : matplotlib.axes.Axes, optional
        Where to draw (default: the current axes).
    parts : sequence of {1, 2}
        Which parts to draw (e.g. one per panel); the values hold both.
    names, text_offsets : dict, optional
        Labels and label offsets keyed ``"a1"``, ``"f1"``, ``"a2"``, ``"f2"``, ``"T"``.
    scale, arrow_length : float, optional
        Force arrows: data units per unit force, or (``arrow_length``) a fixed
        length in data units whatever the magnitude.  A force's label sits
        beside its arrow's middle (``text_at="anchor"``); place the arrow with
        ``out["f1"].set_anchor(xy)``.
    show_T, T_anchor :
        Draw the axis ``T`` (construction line) and where its label sits.

    Returns
    -------
    dict
        Artists ``{"T", "a1", "f1", "a2", "f2"}`` (those drawn) and ``"values"``:
        ``{"T", "U", "psi", "gamma", "a1", "a2", "f1", "f2"}``.

    Examples
    --------
    >>> import matplotlib; matplotlib.use("Agg")
    >>> import matplotlib.pyplot as plt
    >>> from planargeo.mechanics.joints import revolute
    >>> from planargeo.screws.twists import inertia_matrix, unit_rotation
    >>> j, A = revolute([0.0, 0.0]), inertia_matrix(1.0, [1.0, 0.0], 0.25)
    >>> out = draw_twist_split(j.s, j.R, A, unit_rotation([2.0, 1.0]), plt.figure().gca())
    >>> v = out["values"]
    >>> bool(np.allclose(v["a1"] + v["a2"], unit_rotation([2.0, 1.0])))    # a = sψ + Uγ (6.44)
    True
    >>> bool(np.allclose(out["f1"].get_line(), A @ v["a1"]))
    True
    >>> plt.close("all")
    """
    dec = Decomposition(A, s, R)
    T, U, A = dec.T, dec.U, dec.A
    psi, gamma = dec.split_twist(_vec(a, "a"))          # (Tᵀa, Rᵀa), 6.44
    a1, a2 = dec.s @ psi, U @ gamma
    vals = {"T": T, "U": U, "psi": psi, "gamma": gamma, "a1": a1, "a2": a2,
            "f1": A @ a1, "f2": A @ a2}
    nm = {"a1": r"$a_1 = s\psi$", "a2": r"$a_2 = U\gamma$", "f1": "$f_1 = Aa_1$",
          "f2": "$f_2 = Aa_2$", **(names or {})}
    return _draw_split(vals, parts, T, ax, nm, text_offsets, scale, arrow_length, show_T, T_anchor)


def draw_wrench_split(s, R, A, f, ax=None, *, parts=(1, 2),
                      names=None, text_offsets=None, scale=1.0, arrow_length=None, show_T=True,
                      T_anchor=None):
    """A force split by a joint, and the accelerations of its parts (thesis 6.38, 6.77–6.81, Fig. 6.4).

    ``f = T Q + R μ`` with ``Q = sᵀf``, ``μ = Uᵀf`` (6.38, 6.61): the active
    part ``f₁ = TQ`` (a multiple of the axis ``T``) turns the body about the
    joint, ``a₁ = A⁻¹f₁ = s TᵀA⁻¹f``; the reaction ``f₂ = Rμ`` passes through
    the joint and produces ``a₂ = A⁻¹f₂ = U RᵀA⁻¹f`` on ``T`` (6.80–6.81).

    Parameters
    ----------
    s, R, A, parts, names, text_offsets, scale, arrow_length, show_T, T_anchor
        As :func:`draw_twist_split`.
    f : array_like (3,)
        The force to split.
    ax : matplotlib.axes.Axes, optional
        Where to draw (default: the current axes).

    Returns
    -------
    dict
        As :func:`draw_twist_split`; ``"values"``: ``{"T", "U", "Q", "mu", "f1", "f2", "a1", "a2"}``.

    Examples
    --------
    >>> import matplotlib; matplotlib.use("Agg")
    >>> import matplotlib.pyplot as plt
    >>> from planargeo.mechanics.joints import revolute
    >>> from planargeo.screws.twists import inertia_matrix
    >>> j, A = revolute([0.0, 0.0]), inertia_matrix(1.0, [1.0, 0.0], 0.25)
    >>> f = np.array([0.0, 1.0, 2.0])                 # 1 N upwards on the line x = 2 (4.27)
    >>> out = draw_wrench_split(j.s, j.R, A, f, plt.figure().gca(), parts=[1])
    >>> v = out["values"]
    >>> bool(np.allclose(v["f1"] + v["f2"], f)), float(v["Q"][0])   # Q = sᵀf: the moment 2
    (True, 2.0)
    >>> plt.close("all")
    """
    dec = Decomposition(A, s, R)
    T, U, A = dec.T, dec.U, dec.A
    Q, mu = dec.split_wrench(_vec(f, "f"))              # (sᵀf, Uᵀf), 6.38
    f1, f2 = T @ Q, dec.R @ mu
    vals = {"T": T, "U": U, "Q": Q, "mu": mu, "f1": f1, "f2": f2,
            "a1": np.linalg.solve(A, f1), "a2": np.linalg.solve(A, f2)}
    nm = {"a1": "$a_1 = A^{-1}f_1$", "a2": "$a_2 = A^{-1}f_2$", "f1": "$f_1 = TQ$",
          "f2": r"$f_2 = R\mu$", **(names or {})}
    return _draw_split(vals, parts, T, ax, nm, text_offsets, scale, arrow_length, show_T, T_anchor)


def draw_projective_step(s, R, A, a_prev, a, kappa, ax=None, *,
                         names=("$T_i$", "$s_i$", "$a_{i-1}$", "$a_i$"),
                         text_offsets=(None,) * 4, T_anchor=None):
    """Projective kinematics across one joint (thesis 6.98–6.101, Fig. 6.5).

    With ``T_i`` the percussion space of joint ``i`` for the body inertia
    ``A`` (6.36), ``ψ_i = T_iᵀa_i`` and ``ψ_{i-1} = T_iᵀa_{i-1}`` are the
    absolute accelerations along the joint (``T_i`` picks the ``s_i`` component
    of an acceleration, 6.44), and the joint acceleration is
    ``q̈_i = ψ_i − T_iᵀ(a_{i-1} + κ_i)`` (6.101).

    Returns the artists ``{"T", "s", "a_prev", "a"}`` (first columns for a
    multi-dof joint) and ``"values"``: ``{"T", "psi", "psi_prev", "qdd"}``.

    Parameters
    ----------
    s, R : array_like (3, k), (3, 3-k)
        Motion and reaction spaces of joint ``i``.
    A : array_like (3, 3)
        The body inertia.
    a_prev, a : array_like (3,)
        Accelerations of the parent and of the body.
    kappa : array_like (3,)
        The joint's bias acceleration ``κ_i``.
    ax : matplotlib.axes.Axes, optional
        Where to draw (default: the current axes, :func:`~planargeo.draw.style.get_ax`).
    names : tuple of 4 str
        Labels of ``T_i``, ``s_i``, ``a_{i-1}``, ``a_i``.
    text_offsets : tuple of 4 offsets
        Label offsets in points.
    T_anchor : (x, y), optional
        Where ``T_i``'s label sits.

    Returns
    -------
    dict
        See above.

    Raises
    ------
    ShapeError, NonFiniteError
        An argument that is not a finite homogeneous vector (or 3×3 matrix), named.

    Examples
    --------
    >>> import matplotlib; matplotlib.use("Agg")
    >>> import matplotlib.pyplot as plt
    >>> from planargeo.mechanics.joints import revolute
    >>> from planargeo.screws.twists import inertia_matrix, unit_rotation
    >>> j, A = revolute([0.0, 0.0]), inertia_matrix(1.0, [1.0, 0.0], 0.25)
    >>> a = 2.0 * j.s[:, 0]                            # turning about the joint at 2 rad/s²
    >>> out = draw_projective_step(j.s, j.R, A, np.zeros(3), a, np.zeros(3), plt.figure().gca())
    >>> out["values"]["qdd"].round(12).tolist()
    [2.0]
    >>> plt.close("all")
    """
    ax = get_ax(ax)
    s, R, A, T, _ = _decomposition(s, R, A)
    a_prev, a, kap = _vec(a_prev, "a_prev"), _vec(a, "a"), _vec(kappa, "kappa")
    psi, psi_prev = T.T @ a, T.T @ a_prev
    qdd = psi - T.T @ (a_prev + kap)
    o = list(text_offsets)
    out = {"T": plot_line(T[:, 0], ax, role="momentum", scale=None, text=names[0],
                          anchor=T_anchor, text_offset=o[0]),
           "s": plot_point(s[:, 0], ax, glyph=False, text=names[1], text_offset=o[1]),
           "a_prev": plot_point(a_prev, ax, role="accel", text=names[2], text_offset=o[2]),
           "a": plot_point(a, ax, role="accel", text=names[3], text_offset=o[3])}
    out["values"] = {"T": T, "psi": psi, "psi_prev": psi_prev, "qdd": qdd}
    return out
