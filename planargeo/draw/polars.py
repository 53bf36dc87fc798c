"""Pole and polar constructions on a :class:`~planargeo.draw.picture.Picture` (thesis 5.2, 5.4, 5.5).

Polars (Figs 5.2, 5.3), the axis of percussion (Fig. 5.6) and power (Fig. 5.7); each function
returns its elements by name.
"""
from __future__ import annotations

import math

import numpy as np

from planargeo._validate import as_scalar
from planargeo.draw._shared import added, as_picture, bare_line, documented, inertia, line_words, texts
from planargeo.draw.geometry import _mat, _vec, point_xy
from planargeo.draw.picture import PX_PER_PT, Picture, _text_part, plain_text
from planargeo.draw.pictures._words import num, pair, where
from planargeo.draw.pictures.common import label_line, point_along
from planargeo.draw.sketch import dimension, segment
from planargeo.draw.style import COLORS
from planargeo.errors import InputError
from planargeo.geometry.conics import (line_conic_intersections, polar_construction_exterior,
                                       polar_construction_interior)
from planargeo.geometry.projective import from_direction, from_xy, is_ideal, join, meet, to_xy
from planargeo.screws.inertia import centre_of_mass, percussion_axis, radius_of_gyration

__all__ = ["line_conic_points", "interior_construction", "power_values", "polar_exterior",
           "polar_interior", "percussion", "power"]


def _line(pic: Picture, id: str, l, role: str, symbol: str, desc: str, *, anchor=None,
          side: float = 1.0) -> dict:
    """A line without a sense arrow, labelled with its symbol beside it (:func:`label_line`)."""
    el = bare_line(pic, id, l, role=role, symbol=symbol, desc=desc)
    label_line(pic, id, plain_text(symbol), anchor=anchor, side=side)
    return el


def _inertia(pic: Picture, prefix: str, I, more: str) -> dict:
    """The inertia ``I`` (:func:`inertia`), its description ending in ``more``."""
    return inertia(pic, prefix + "I", I, "inertia I (5.64) as its circle of gyration" + more)


def _polar_and_point(pic: Picture, out: dict, prefix: str, K, p, names, *, inside: bool, through: str,
                     anchor, side: float) -> dict:
    """Add the polar ``L`` of a construction ``K`` (labelled) and its point ``P`` to ``out``."""
    P, L = texts(names, 2, "names")
    out["L"] = _line(pic, prefix + "L", K.polar, "wrench", L, anchor=anchor, side=side,
                     desc=f"polar L = C P of P (5.36): the line through {through}")
    out["P"] = added(pic.point, prefix + "P", p, role="twist", glyph=False, symbol=P,
                     desc=f"the point P, {'inside' if inside else 'outside'} C (5.36): {where(p)}")
    return out


def _conic(pic: Picture, id: str, C) -> dict:
    """The conic ``C``, labelled inside an ellipse (upper left), or at another's first point."""
    el = added(pic.conic, id, C, role="conic", symbol="C", label="",
               desc="the conic C (5.35): the points x with xᵀCx = 0")
    e = next((q for q in el["parts"] if q["p"] in ("ellipse", "path")), None)
    if e is None:
        return el
    if e["p"] == "ellipse":      # the unit circle under (x, y) + m: its point farthest up-left, 70 % out
        a, b, c, d = e["m"]
        t = np.linspace(0.0, 2 * math.pi, 72, endpoint=False)
        k = int(np.argmax(-(a * np.cos(t) + b * np.sin(t)) * pic.kx + (c * np.cos(t) + d * np.sin(t)) * pic.ky))
        x = e["x"] + 0.7 * (a * math.cos(t[k]) + b * math.sin(t[k]))
        y = e["y"] + 0.7 * (c * math.cos(t[k]) + d * math.sin(t[k]))
        dx = dy = 0.0
        ha = va = "center"
    else:
        x, y = (float(v) for v in np.asarray(e["xy"], float)[0])
        dx = dy = 4.0
        ha, va = "left", "bottom"
    el["parts"].append(_text_part(x, y, "C", dx, dy, ha, va))
    return el


def line_conic_points(C, L) -> list[np.ndarray]:
    """Real common points of the line ``L`` and the conic ``C`` (5.38; 0 or 2 homogeneous points).

    Parameters
    ----------
    C : array_like (3, 3)
        A conic.
    L : array_like (3,)
        A line.

    Returns
    -------
    list of ndarray (3,)
        The two real common points, or none when the line misses the conic.

    Raises
    ------
    InputError
        An argument that is not a finite homogeneous vector (or symmetric 3×3 matrix), named.

    Examples
    --------
    >>> from planargeo.geometry.conics import conic_circle
    >>> C = conic_circle([0.0, 0.0], 2.0)
    >>> sorted(to_xy(X).round(6).tolist() for X in line_conic_points(C, [1.0, 0.0, 0.0]))  # y = 0
    [[-2.0, 0.0], [2.0, 0.0]]
    """
    X, real = line_conic_intersections(_mat(C, "C"), _vec(L, "L"))
    return [X[0], X[1]] if bool(real) else []


# --------------------------------------------------------------------------- pole / polar
@documented
def polar_exterior(pic: Picture, C, p, *, names=("$P$", "$L = CP$"), L_anchor=None, L_side: float = 1.0,
                   prefix: str = "") -> dict:
    """Polar of an exterior point (thesis 5.36, Fig. 5.2): tangents from ``p``; ``L`` joins their contacts.

    {parameters pic}
    C : array_like (3, 3)
        A real conic.
    p : array_like (3,)
        An exterior point.
    names : (str, str)
        Symbols (labels) of the point and its polar.
    L_anchor : (x, y), optional
        Near which point of the polar its label sits (default: the middle of the contacts).
    L_side : float
        +1: the polar's label above it (right of a vertical one); -1: below it.
    {prefix}

    Returns
    -------
    dict
        The elements ``{"conic", "P", "L", "tangents", "contacts"}`` and
        ``"construction"`` (:class:`~planargeo.geometry.conics.ExteriorConstruction`).

    Raises
    ------
    InputError
        ``pic`` not a picture, ``C`` or ``p`` not finite (or ``C`` not symmetric), an interior
        point (no real tangents), or ``names`` not two.

    Examples
    --------
    >>> from planargeo.geometry.conics import conic_circle
    >>> pic = Picture((-3, 3, -3, 3), size=(300, 300), ticks=False)
    >>> out = polar_exterior(pic, conic_circle([0.0, 0.0], 1.0), from_xy([2.0, 0.0]))
    >>> sorted((part["x"], round(part["y"], 6)) for part in out["contacts"]["parts"])  # x = 1/2
    [(0.5, -0.866025), (0.5, 0.866025)]
    """
    pic = as_picture(pic)
    C, p = _mat(C, "C"), _vec(p, "p")
    K = polar_construction_exterior(C, p)
    contacts = [to_xy(X) for X in K.contacts]
    both = f"{pair(contacts[0], 3)} and {pair(contacts[1], 3)}"
    out = {"construction": K, "conic": _conic(pic, prefix + "C", C)}
    out["tangents"] = [bare_line(pic, f"{prefix}tangent {k + 1}", t, role="construct",
                                 symbol=f"T{k + 1}", desc=f"tangent {k + 1} from P to C "
                                 f"(5.38–5.39): touches C at {pair(xy, 3)}")
                       for k, (t, xy) in enumerate(zip(K.tangents, contacts))]
    out["contacts"] = added(pic.marks, prefix + "contacts", contacts, role="construct", size=3.5 * PX_PER_PT,
                            color=COLORS["construct"], z=5, symbol="contacts",
                            desc=f"where the tangents from P touch C (5.38): {both}")
    return _polar_and_point(pic, out, prefix, K, p, names, inside=False, through=f"the contacts {both}",
                            anchor=(contacts[0] + contacts[1]) / 2 if L_anchor is None else L_anchor,
                            side=L_side)


def interior_construction(C, p, angles=(0.35, 1.9)):
    """The polar construction of an interior point with its two chords at ``angles`` (5.36, Theorem 12).

    Parameters
    ----------
    C : array_like (3, 3)
        A real conic.
    p : array_like (3,)
        A point inside it (a finite point).
    angles : (float, float)
        Directions of the two chords through ``p`` (radians from the x axis).

    Returns
    -------
    InteriorConstruction
        :class:`~planargeo.geometry.conics.InteriorConstruction`.

    Raises
    ------
    InputError
        ``C`` or ``p`` not finite, ``p`` at infinity, not two angles, or a chord missing the conic.

    Examples
    --------
    >>> from planargeo.geometry.conics import conic_circle
    >>> K = interior_construction(conic_circle([0.0, 0.0], 2.0), from_xy([1.0, 0.0]), (0.7, 2.0))
    >>> [round(float(to_xy(R)[0]), 9) for R in K.poles]       # both on the polar x = r²/d = 4
    [4.0, 4.0]
    """
    C, p = _mat(C, "C"), _vec(p, "p")
    if bool(is_ideal(p)):
        raise InputError("p must be a finite point (inside the conic), got a point at infinity")
    a = np.asarray(angles, dtype=float)
    if a.shape != (2,) or not np.all(np.isfinite(a)):
        raise InputError(f"angles must be two finite directions in radians, got {angles!r}")
    pxy = to_xy(p)
    lines = np.stack([join(p, from_xy(pxy + [np.cos(t), np.sin(t)])) for t in a])
    return polar_construction_interior(C, p, lines=lines)


def polar_interior(pic: Picture, C, p, *, angles=(0.35, 1.9), names=("$P$", "$L = CP$"),
                   L_anchor=None, L_side: float = 1.0, prefix: str = "") -> dict:
    """Polar of an interior point (thesis 5.36, Theorem 12, Fig. 5.3).

    The tangents at the ends of each of two chords through ``p`` meet in the chord's pole
    ``R_k`` (Theorem 12; at infinity for a diameter); ``L`` joins the two.

    Parameters
    ----------
    pic, C, names, L_side, prefix
        As :func:`polar_exterior`.
    p : array_like (3,)
        An interior point.
    angles : (float, float)
        Directions (radians) of the two chords through ``p``.
    L_anchor : (x, y), optional
        Near which point of the polar its label sits (default: the view's centre).

    Returns
    -------
    dict
        The elements ``{"conic", "P", "chords", "tangents", "chord_points", "R1", "R2", "L"}``
        and ``"construction"`` (:class:`~planargeo.geometry.conics.InteriorConstruction`).

    Raises
    ------
    InputError
        ``pic`` not a picture, bad ``C``, ``p``, ``angles`` or ``names``, or a chord that misses
        the conic (``p`` not inside it).

    Examples
    --------
    >>> from planargeo.geometry.conics import conic_circle
    >>> pic = Picture((-5, 5, -5, 5), size=(300, 300), ticks=False)
    >>> out = polar_interior(pic, conic_circle([0.0, 0.0], 2.0), from_xy([1.0, 0.0]), angles=(0.7, 2.0))
    >>> [round(out[k]["parts"][0]["x"], 9) for k in ("R1", "R2")]    # on L: x = r²/d = 4
    [4.0, 4.0]
    """
    pic = as_picture(pic)
    C, p = _mat(C, "C"), _vec(p, "p")
    K = interior_construction(C, p, angles)
    out = {"construction": K, "conic": _conic(pic, prefix + "C", C)}
    ends = [[to_xy(X) for X in K.chord_points[k]] for k in range(2)]
    out["chords"] = [bare_line(pic, f"{prefix}chord {k + 1}", K.lines[k], role="construct",
                               symbol=f"chord {k + 1}",
                               desc=f"chord {k + 1} through P (5.36, step 1): "
                                    f"cuts C at {pair(ends[k][0], 3)} and {pair(ends[k][1], 3)}")
                     for k in range(2)]
    out["tangents"] = [bare_line(pic, f"{prefix}tangent {k + 1}.{j + 1}", K.tangents[k, j],
                                 role="construct", width=0.6 * PX_PER_PT,
                                 symbol=f"tangent {k + 1}.{j + 1}", desc=f"tangent to C at the end "
                                 f"{pair(ends[k][j], 3)} of chord {k + 1} (5.38–5.39)")
                       for k in range(2) for j in range(2)]
    pts = [xy for pair_ in ends for xy in pair_]
    out["chord_points"] = added(pic.marks, prefix + "chord points", pts, role="construct", size=3.0 * PX_PER_PT,
                                color=COLORS["construct"], z=5, symbol="chord ends",
                                desc="where the two chords through P cut C (5.38): "
                                     + ", ".join(pair(xy, 3) for xy in pts))
    for k in range(2):
        point_along(pic, f"{prefix}R{k + 1}", K.poles[k], role="accel", symbol=f"$R_{k + 1}$",
                    desc=f"pole R{'₁₂'[k]} of chord {k + 1} (Theorem 12): where the tangents at its ends "
                         f"meet, {where(K.poles[k])}")
        out[f"R{k + 1}"] = pic.elements[-1]
    return _polar_and_point(pic, out, prefix, K, p, names, inside=True,
                            through=f"R₁ and R₂, {line_words(K.polar, 3)}", anchor=L_anchor, side=L_side)


# --------------------------------------------------------------------------- inertia
@documented
def percussion(pic: Picture, I, a, *, names=("$a$", "$f = Ia$"), dims: bool = True, f_anchor=None,
               prefix: str = "") -> dict:
    """Axis of percussion ``f = I a`` of an acceleration pole ``a`` (thesis 5.64–5.68, Fig. 5.6).

    With ``dims``: the lever from ``a`` through the centre of mass, the distances ``d``, ``ρ²/d``.

    {parameters pic}
    I : array_like (3, 3)
        The inertia.
    a : array_like (3,)
        The acceleration pole.
    names : (str, str)
        Symbols (labels) of the pole and the axis.
    dims : bool
        Dimension ``d`` and ``ρ²/d`` (when the pole is finite and not at the centre of mass).
    f_anchor : (x, y), optional
        Near which point of the axis its label sits.
    {prefix}

    Returns
    -------
    dict
        The elements ``{"inertia", "a", "f"}`` and, with ``dims``, ``"dims"`` (the two
        dimensions' element dicts) and ``"lever"``; ``"values"``: ``f`` (the axis, ``I a``),
        ``c`` (centre of mass), ``foot`` (where the axis crosses the lever, or None).

    Raises
    ------
    InputError
        ``pic`` not a picture, ``I`` not a finite symmetric 3×3 matrix, ``a`` not finite, or
        ``names`` not two.

    Examples
    --------
    >>> from planargeo.screws.twists import inertia_matrix
    >>> pic = Picture((-2, 3, -2, 2), size=(300, 240), ticks=False)
    >>> I = inertia_matrix(2.0, [0.0, 0.0], 2.0 * 0.6 ** 2)        # ρ = 0.6 about the origin
    >>> out = percussion(pic, I, from_xy([-1.5, 0.0]))              # d = 1.5
    >>> out["values"]["foot"].round(9).tolist()                     # ρ²/d = 0.24 beyond c
    [0.24, 0.0]
    """
    pic = as_picture(pic)
    I, a = _mat(I, "inertia"), _vec(a, "a")
    f = percussion_axis(I, a)
    c = centre_of_mass(I)
    rho = float(radius_of_gyration(I))
    a_name, f_name = texts(names, 2, "names")
    foot = None
    if not bool(is_ideal(a)) and np.any(f[:2]) and not np.allclose(to_xy(a), c, rtol=0, atol=1e-12 * max(1.0, rho)):
        foot = to_xy(meet(f, join(a, from_xy(c))))
    out = {"values": {"f": f, "c": c, "foot": foot}}
    out["inertia"] = _inertia(pic, prefix, I, f": radius ρ = {num(rho)} m about the centre of mass {pair(c, 3)} m")
    if foot is not None:
        r = float(np.hypot(*(foot - c)))
        where_f = f"r = ρ²/d = {num(r)} m beyond the centre of mass"
    elif not np.any(f[:2]):
        where_f = "a pure couple (the pole is at the centre of mass)"
    else:
        where_f = "through the centre of mass (the pole is at infinity)"
    out["f"] = _line(pic, prefix + "f", f, "wrench", f_name, anchor=f_anchor,
                     desc=f"axis of percussion f = I a (5.64–5.68): {where_f}")
    out["a"] = added(pic.point, prefix + "a", a, role="accel", symbol=a_name,
                     desc=f"acceleration pole a (5.64): the point of the body with no acceleration, {where(a)}")
    if dims and foot is not None:
        axy = to_xy(a)
        out["lever"] = segment(pic, prefix + "lever", axy, foot, symbol="lever",
                               desc="the line from the pole a through the centre of mass to the axis (5.68)")
        d = float(np.hypot(*(axy - c)))
        out["dims"] = [dimension(pic, prefix + id_, q0, q1, sym, desc=desc) for id_, (q0, q1), sym, desc in (
            ("d", (axy, c), "d", f"distance d from the pole a to the centre of mass (5.68): {num(d)} m"),
            ("rho2/d", (c, foot), "ρ²/d",
             f"distance ρ²/d from the centre of mass to the axis of percussion (5.68): {num(rho * rho / d)} m"))]
    return out


# --------------------------------------------------------------------------- power
def power_values(v, I, *, f_angle: float = 0.6, a_distance: float = 1.6) -> dict:
    """The momentum ``p = I v``, a powerless force ``f`` and a powerless acceleration ``a`` (5.69–5.74).

    ``f`` passes through ``v`` (a translation: through the centre of mass, across it) along the
    momentum's direction turned by ``f_angle``; ``a`` lies on ``p`` (``p`` a couple: ``a`` ideal).

    Parameters
    ----------
    v : array_like (3,)
        The velocity twist.
    I : array_like (3, 3)
        The inertia.
    f_angle, a_distance : float
        Turn of ``f`` from ``p`` (radians); distance of ``a`` along ``p`` from the foot of ``c``.

    Returns
    -------
    dict
        ``p``, ``f``, ``a`` (homogeneous), ``ef`` (``f``'s unit direction), ``c`` (centre of mass).

    Raises
    ------
    InputError
        ``v`` or ``I`` not finite (or ``I`` not symmetric), or a placement not a finite number.

    Examples
    --------
    >>> from planargeo.screws.twists import inertia_matrix, unit_rotation
    >>> I = inertia_matrix(1.0, [0.0, 0.0], 0.5)
    >>> val = power_values(unit_rotation([1.0, 0.0]), I)
    >>> float(unit_rotation([1.0, 0.0]) @ val["f"]), float(val["p"] @ val["a"])   # vᵀf = 0, pᵀa = 0
    (0.0, 0.0)
    """
    v, I = _vec(v, "v"), _mat(I, "inertia")
    f_angle, a_distance = as_scalar(f_angle, "f_angle"), as_scalar(a_distance, "a_distance")
    p = I @ v
    c = centre_of_mass(I)
    F = math.hypot(p[0], p[1])
    ang = math.atan2(p[1], p[0]) + float(f_angle)        # atan2(0, 0) = 0: a couple p
    ef = np.array([math.cos(ang), math.sin(ang)])
    if v[2] != 0.0:
        f = np.cross(v, from_direction(ef))              # through v, along ef
    else:
        f = np.cross(v, from_xy(c))                      # through c, across the translation
    if F != 0.0:   # on p, a_distance from the foot of the perpendicular from the centre of mass
        e = p[:2] / F
        foot = np.cross(p, np.cross(from_xy(c), from_direction([-e[1], e[0]])))   # homogeneous
        a = foot + foot[2] * float(a_distance) * from_direction(e)   # no division by the weight: a
        # nearly-couple p (v close to the centre of mass) gives a far, nearly ideal point
    else:
        a = from_direction(ef)                           # p at infinity: an ideal point
    return {"p": p, "f": f, "a": a, "ef": ef, "c": c}


@documented
def power(pic: Picture, v, I, *, f_angle: float = 0.6, a_distance: float = 1.6,
          names=("$v$", "$p = Iv$", "$f$: $v^Tf = 0$", "$a$: $p^Ta = 0$"), f_label_at=1.6,
          p_label_at=None, f_side: float = 1.0, p_side: float = 1.0, prefix: str = "") -> dict:
    """Power (thesis 5.69–5.74, Fig. 5.7): ``f`` through ``v`` (``vᵀf = 0``), ``a`` on ``p = I v``.

    {parameters pic}
    v : array_like (3,)
        The velocity twist.
    I : array_like (3, 3)
        The inertia.
    f_angle, a_distance : float
        Placement of ``f`` and ``a`` (:func:`power_values`).
    names : tuple of 4 str
        Symbols (labels) of ``v``, ``p``, ``f`` and ``a``.
    f_label_at, p_label_at : float, optional
        Labels of ``f`` and ``p`` near the points this far from ``v`` and ``a`` (None: the centre).
    f_side, p_side : float
        +1: the label of ``f`` (``p``) above its line (right of a vertical one); -1: below it.
    {prefix}

    Returns
    -------
    dict
        The elements ``{"inertia", "v", "p", "f", "a"}`` and ``"values"`` (:func:`power_values`).

    Raises
    ------
    InputError
        ``pic`` not a picture, ``v`` or ``I`` not finite, a placement not a finite number, or
        ``names`` not four.

    Examples
    --------
    >>> from planargeo.screws.twists import inertia_matrix, unit_rotation
    >>> pic = Picture((-3, 3, -3, 3), size=(300, 300), ticks=False)
    >>> out = power(pic, unit_rotation([1.0, 0.0]), inertia_matrix(1.0, [0.0, 0.0], 0.5))
    >>> sorted(out["p"]["parts"][0]["xy"].round(9).tolist())   # p = I v: x = −ρ²/d = −0.5 (5.71)
    [[-0.5, -3.0], [-0.5, 3.0]]
    """
    pic = as_picture(pic)
    v, I = _vec(v, "v"), _mat(I, "inertia")
    val = power_values(v, I, f_angle=f_angle, a_distance=a_distance)
    p, f, a, ef = val["p"], val["f"], val["a"], val["ef"]
    F = math.hypot(p[0], p[1])
    f_anchor = to_xy(v) + float(f_label_at) * ef if (v[2] != 0.0 and f_label_at is not None) else None
    p_anchor = (to_xy(a) + float(p_label_at) * p[:2] / F
                if (p_label_at is not None and F != 0.0 and a[2] != 0.0) else None)
    nv, np_, nf, na = texts(names, 4, "names")
    out = {"values": val}
    out["inertia"] = _inertia(pic, prefix, I, f" about the centre of mass {pair(val['c'], 3)} m")
    rate = f", rate {num(v[2])} rad/s" if point_xy(v) is not None else " (a translation)"
    out["v"] = added(pic.point, prefix + "v", v, role="twist", symbol=nv,
                     desc=f"velocity pole v (5.69): {where(v)}{rate}")
    if F != 0.0:
        out["p"] = _line(pic, prefix + "p", p, "momentum", np_, anchor=p_anchor, side=p_side,
                         desc=f"momentum p = I v (5.71): {num(F)} kg·m/s, {line_words(p, 3)}")
    else:
        out["p"] = added(pic.line, prefix + "p", p, role="momentum", arrow=False, symbol=np_,
                         desc=f"momentum p = I v (5.71): a pure angular momentum {num(p[2])} kg·m²/s "
                              f"(the line at infinity)")
    out["f"] = _line(pic, prefix + "f", f, "wrench", nf, anchor=f_anchor, side=f_side,
                     desc=f"a powerless force f, vᵀf = 0 (5.69): a line through the pole v, {line_words(f, 3)}")
    out["a"] = added(pic.point, prefix + "a", a, role="accel", glyph=False, symbol=na,
                     desc=f"a powerless acceleration a, pᵀa = 0 (5.72): a point of the momentum line, {where(a)}")
    return out
