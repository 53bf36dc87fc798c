"""Screw sums of chapter 4 drawn into a :class:`~planargeo.draw.picture.Picture` (thesis 4.11–4.56).

Figs 4.1–4.9; each function returns its elements by name (and the computed arrays under ``"values"``).
"""
from __future__ import annotations

import math

import numpy as np

from planargeo._validate import as_mat3, as_scalar, as_vec3
from planargeo.draw._shared import ENTRIES, added, as_picture, bare_line, texts, view_centre
from planargeo.draw._shared import inertia as inertia_conic
from planargeo.draw.picture import PX_PER_PT, Picture, _dash, _glyph_radius, plain_text
from planargeo.draw.pictures._words import force as force_words, num, pair
from planargeo.draw.pictures.common import label_toward
from planargeo.draw.pictures.kit import force as force_arrow
from planargeo.draw.sketch import dimension
from planargeo.draw.style import COLORS, LINEWIDTHS, SUM
from planargeo.errors import InputError
from planargeo.geometry._docs import entries
from planargeo.geometry.projective import is_at_infinity, is_ideal
from planargeo.screws.inertia import centre_of_mass, mass
from planargeo.screws.twists import bias_force, kappa

__all__ = ["twist_sum", "wrench_sum", "velocity_step", "acceleration_step", "newton_euler"]

#: marker size (pixels) of a sum's pole, line width (pixels) of a sum's line of action
_SUM_POINT_PX = SUM["point"]["markersize"] * PX_PER_PT
_SUM_LINE_PX = SUM["line"]["linewidth"] * PX_PER_PT
documented = entries(ENTRIES, {
    "toward": "toward : tuple of (float, float) or None\n    Per label, the pixel direction (y up) "
              "in which it is put first (None: automatic).",
    "scale": "scale : float or None\n    Force arrow length per unit force (data units); None: "
             "no arrows."})


# --------------------------------------------------------------------------- checks and words
def _scale(scale) -> float | None:
    """A force arrow's length per unit force: None (no arrows) or a positive number, checked."""
    if scale is None:
        return None
    scale = as_scalar(scale, "scale")
    if not scale > 0.0:
        raise InputError(f"scale must be a positive number (data units per unit force), got {scale!r}")
    return scale


def _symbol(label: str) -> str:
    """The thesis symbol of a label: its plain text before any remark in brackets."""
    return plain_text(label).split(" (")[0].strip()


def _pole_words(p, unit: str = "rad/s", speed: str = "m/s") -> str:
    """A twist (or acceleration) ``[vx, vy, w]`` in words: its rate and where its pole is."""
    p = np.asarray(p, float)
    w = float(p[2])
    if not np.any(p):
        return "zero"
    if bool(is_ideal(p)):
        d = np.array([p[0], p[1]]) / math.hypot(p[0], p[1])
        return (f"a translation of {num(math.hypot(p[0], p[1]))} {speed} along {pair(d)}, "
                f"its pole at infinity")
    return f"ω = {num(w)} {unit}, pole at {pair((-p[1] / w, p[0] / w))} m"


def _pole(pic: Picture, id: str, p, *, role: str, label: str, desc: str, toward=None,
          emphasis: bool = False, glyph_scale: float = 6.0) -> dict:
    """A pole (:meth:`Picture.point`); a sum's as a larger diamond; its label put ``toward`` first."""
    kw = dict(shape="D", size=_SUM_POINT_PX) if emphasis else {}
    el = added(pic.point, id, p, role=role, symbol=_symbol(label), desc=desc, label=plain_text(label),
               glyph_scale=glyph_scale, **kw)
    if toward is not None and not bool(is_ideal(p)):      # clear of the glyph, which grows with |ω|
        gap = 0.75 * _glyph_radius(p[2], glyph_scale) * PX_PER_PT + 5.0
        label_toward(el, toward, gap + (3.0 if emphasis else 0.0))
    return el


def _lever(pic: Picture, id: str, p, q, *, desc: str, width: float | None = None) -> dict | None:
    """The construction line ``p × q`` through two poles; None when it is not a line to draw.

    Coincident poles have no lever line (every line through the pole is one), and two
    ideal poles join in the line at infinity: neither is drawn.
    """
    line = np.cross(p, q)
    if not np.any(line) or bool(is_at_infinity(line)):
        return None
    return bare_line(pic, id, line, role="construct", symbol=id, desc=desc, width=width)


def _wrench(pic: Picture, id: str, f, *, role: str, label: str, desc: str, scale, anchor,
            emphasis: bool = False, toward=None, couples: list | None = None,
            corner: str = "right") -> dict | None:
    """A wrench: its line, a force arrow ``scale |f|`` long (None: none) at ``anchor``'s foot.

    A couple is the glyph in the upper ``corner``, a row lower per couple already there
    (``couples``); a zero wrench draws nothing (None).
    """
    f = np.asarray(f, float)
    width = _SUM_LINE_PX if emphasis else None
    symbol = _symbol(label)
    text = plain_text(label)
    if not np.any(f):
        return None
    if bool(is_at_infinity(f)):
        el = added(pic.line, id, f, role=role, symbol=symbol, desc=desc, label=text, width=width)
        row = 0 if couples is None else couples.count(corner)
        x0 = pic.box[0]
        for part in el["parts"]:
            if part["p"] in ("text", "glyph"):
                part["y"] -= row * 30.0 / pic.ky
            if part["p"] == "text" and text and "couple" in text:
                part["text"] = text
            if corner == "left":          # mirrored: the glyph 26 px from the left edge, its words right of it
                if part["p"] == "glyph":
                    part["x"] = x0 + 26.0 / pic.kx
                elif part["p"] == "text":
                    part["x"], part["dx"], part["ha"] = x0 + 26.0 / pic.kx, 18.0, "left"
        if couples is not None:
            couples.append(corner)
        return el
    if anchor is None:
        anchor = view_centre(pic)
    if scale is None:
        pic.line(id, f, role=role, symbol=symbol, desc=desc, label=text, anchor=anchor, arrow=False,
                 width=width)
    else:
        force_arrow(pic, id, f, scale=float(scale), anchor=anchor, role=role, symbol=symbol, desc=desc,
                    label=text, width=width, color=COLORS.get(role))
    el = pic.elements[-1]
    arrow = next((q for q in el["parts"] if q["p"] == "arrow"), None)
    if arrow is not None:        # the label at the arrow's tip (as the old drawing), the placer's first spot
        tip = (arrow["x"] + arrow["dx"] / pic.kx, arrow["y"] + arrow["dy"] / pic.ky)
        for part in el["parts"]:
            if part["p"] == "text":
                part["x"], part["y"] = tip
        if toward is None:       # beside the tip, left of the force's sense
            toward = (-arrow["dy"], arrow["dx"])
        if emphasis:
            _notch(pic, el, arrow, tip)
    if toward is not None:
        label_toward(el, toward, gap=12.0 if emphasis else 9.0)
    return el


def _notch(pic: Picture, el: dict, arrow: dict, tip) -> None:
    """Cut a heavy line of action where its arrow's head sits, so that the head shows on it."""
    L = math.hypot(arrow["dx"], arrow["dy"])
    if L < 12.0:
        return
    u = np.array([arrow["dx"] / pic.kx, arrow["dy"] / pic.ky]) / L       # data units per pixel along it
    a, b = np.asarray(tip) - 10.0 * u, np.asarray(tip) + 2.0 * u          # the head's stretch, and a little
    parts = []
    for part in el["parts"]:
        if part["p"] != "path":
            parts.append(part)
            continue
        p, q = np.asarray(part["xy"], float)
        d = q - p
        t = sorted(((a - p) @ d / (d @ d), (b - p) @ d / (d @ d)))
        if t[1] <= 0.0 or t[0] >= 1.0:
            parts.append(part)
            continue
        for lo, hi in ((0.0, t[0]), (t[1], 1.0)):
            if hi > lo:
                parts.append({"p": "path", "xy": np.array([p + lo * d, p + hi * d]), "closed": False})
    el["parts"] = parts


# --------------------------------------------------------------------------- twist / wrench sums
@documented
def twist_sum(pic, v1, v2, *, labels=("$v_1$", "$v_2$", "$v_3 = v_1 + v_2$"), lever: bool = True,
              glyph_scale: float = 6.0, role: str = "twist", toward=(None, None, None),
              prefix: str = "") -> dict:
    """Twist addition (thesis 4.11–4.16, Figs 4.1, 4.3): ``v₃ = v₁ + v₂`` lies on the lever line of the poles.

    The sum is a larger diamond, its label across the lever line from the terms'.

    {parameters pic}
    v1, v2 : array_like (3,)
        The twists ``[vx, vy, ω]`` to add.
    labels : (str, str, str)
        Labels of ``v₁``, ``v₂`` and the sum; the symbol is the text before a remark in brackets.
    lever : bool
        Draw the line joining the poles (not for coincident poles or two translations).
    glyph_scale : float
        Rotation glyph radius (points per unit rate).
    {role toward prefix}

    Returns
    -------
    dict
        The elements ``{"v1", "v2", "v3"}`` and ``"lever"`` (when drawn).

    Raises
    ------
    InputError
        ``pic`` not a Picture, a twist not 3 finite numbers, ``labels`` / ``toward`` not three.

    Examples
    --------
    >>> from planargeo.screws.twists import unit_rotation, unit_translation
    >>> pic = Picture((-3, 3, -3, 3), size=(200, 200), ticks=False)
    >>> out = twist_sum(pic, 2 * unit_rotation([1, 0]), unit_translation([0, 1]))
    >>> out["v3"]["parts"][0]["x"], out["v3"]["parts"][0]["y"]     # Q + (u/ω) n, n = (-1, 0) (4.16)
    (0.5, 0.0)
    """
    pic = as_picture(pic)
    v1, v2 = as_vec3(v1, "v1"), as_vec3(v2, "v2")
    labels = texts(labels, 3, "labels")
    toward = list(texts(toward, 3, "toward"))
    v3 = v1 + v2
    out = {}
    if lever:
        beta = (f"β = ω₂/(ω₁ + ω₂) = {num(v2[2] / v3[2])}" if v3[2] != 0.0
                else "β = ∞: the sum is a translation")
        out["lever"] = _lever(pic, prefix + "lever", v1, v2, desc="lever line Q₁Q₂ through both poles "
                              f"(4.11–4.13): the sum's pole lies on it, {beta}")
    auto = _label_sides(pic, v1, v2)
    toward = [t if t is not None else a for t, a in zip(toward, auto)]
    for k, (name, v, what) in enumerate((("v1", v1, "twist {} (4.10)"),
                                         ("v2", v2, "twist {} (4.10)"),
                                         ("v3", v3, "sum {} (4.11–4.13)"))):
        out[name] = _pole(pic, prefix + name, v, role=role, label=labels[k], toward=toward[k],
                          glyph_scale=glyph_scale, emphasis=name == "v3",
                          desc=f"{what.format(_symbol(labels[k]))}: {_pole_words(v)}")
    return {k: v for k, v in out.items() if v is not None}


def _label_sides(pic: Picture, p, q, apart: bool = True):
    """Label directions (pixels): the terms above their lever line, the sum below (or spread)."""
    if not apart or p[2] == 0.0 or q[2] == 0.0 or not np.any(np.cross(p, q)):
        return [(-0.7, 0.7), (0.7, 0.7), (0.0, -1.0)]
    d = np.array([(p[1] / p[2] - q[1] / q[2]) * pic.kx, (q[0] / q[2] - p[0] / p[2]) * pic.ky])
    d = d / math.hypot(*d)
    n = np.array([-d[1], d[0]]) if d[0] >= 0 else np.array([d[1], -d[0]])
    return [tuple(n), tuple(n), tuple(-n)]


@documented
def wrench_sum(pic, f1, f2, *, labels=("$f_1$", "$f_2$", "$f_3 = f_1 + f_2$"), scale=1.0,
               anchors=(None, None, None), parallelogram: bool = True, role: str = "wrench",
               toward=(None, None, None), prefix: str = "") -> dict:
    """Wrench addition (thesis 4.33–4.46, Figs 4.4–4.6): ``f₃ = f₁ + f₂``.

    The force parallelogram sits at the meet ``P = f₁ × f₂``, a couple is the glyph in an upper
    corner, the sum has a heavier line.

    {parameters pic}
    f1, f2 : array_like (3,)
        The wrenches ``[fx, fy, τ]`` (lines).
    labels : (str, str, str)
        Labels of ``f₁``, ``f₂`` and the sum.
    {scale}
    anchors : (xy, xy, xy)
        Where each arrow sits (None: the view centre's foot); not with a parallelogram.
    parallelogram : bool
        Draw the force parallelogram at the meet of crossing lines.
    {role toward prefix}

    Returns
    -------
    dict
        The elements ``{"f1", "f2", "f3"}`` (a zero wrench has none) and, for crossing lines,
        ``"meet"`` and ``"parallelogram"``.

    Raises
    ------
    InputError
        ``pic`` not a Picture, a wrench not 3 finite numbers, a bad scale, or ``labels`` /
        ``anchors`` / ``toward`` not three.

    Examples
    --------
    >>> pic = Picture((-1, 3, -1, 3), size=(200, 200), ticks=False)
    >>> out = wrench_sum(pic, [1.0, 0.0, -1.0], [0.0, 1.0, 2.0], scale=0.5)   # y = 1 and x = 2
    >>> [part["xy"].tolist() for part in out["parallelogram"]["parts"]]   # f1's tip to f3's, f2's to it
    [[[2.5, 1.0], [2.5, 1.5]], [[2.0, 1.5], [2.5, 1.5]]]
    """
    pic = as_picture(pic)
    f1, f2 = as_vec3(f1, "f1"), as_vec3(f2, "f2")
    scale = _scale(scale)
    labels = texts(labels, 3, "labels")
    anchors = list(texts(anchors, 3, "anchors"))
    toward = texts(toward, 3, "toward")
    f3 = f1 + f2
    P = np.cross(f1, f2)
    finite_meet = bool(np.any(P)) and not bool(is_ideal(P)) and not bool(is_at_infinity(f1)) \
        and not bool(is_at_infinity(f2))
    Pxy = np.array([-P[1] / P[2], P[0] / P[2]]) if finite_meet else None
    if finite_meet and parallelogram and scale is not None:
        anchors = [Pxy + scale * f[:2] / 2 for f in (f1, f2, f3)]
        # labels away from the parallelogram: the terms' beyond their corners, the sum's ahead
        # of its tip, on the side of f1
        k = np.array([pic.kx, pic.ky])
        side = (f1[:2] - f2[:2]) * k
        auto = [tuple((f1[:2] - f2[:2]) * k), tuple((f2[:2] - f1[:2]) * k),
                tuple(f3[:2] * k / math.hypot(*(f3[:2] * k)) + side / math.hypot(*side))]
        toward = tuple(t if t is not None else a for t, a in zip(toward, auto))
    syms = [_symbol(x) for x in labels]
    out, couples = {}, []
    for k, (name, f, what, eq) in enumerate((("f1", f1, "wrench", "4.27"), ("f2", f2, "wrench", "4.27"),
                                             ("f3", f3, "sum", "4.33–4.46"))):
        out[name] = _wrench(pic, prefix + name, f, role=role, label=labels[k], scale=scale,
                            anchor=anchors[k], emphasis=name == "f3", toward=toward[k], couples=couples,
                            corner="left" if name == "f2" else "right",
                            desc=f"{what} {syms[k]} on its line of action ({eq}): {force_words(f)}")
    if finite_meet:
        out["meet"] = added(pic.marks, prefix + "meet", [Pxy], role="construct", symbol="P", shape="o",
                            size=3.5 * PX_PER_PT, z=6,
                            desc=f"meet P = f₁ × f₂ of the two lines of action (4.35): at {pair(Pxy)} m; "
                                 f"the sum's line passes through it")
        if parallelogram and scale is not None:
            a, b, c = (Pxy + scale * f[:2] for f in (f1, f2, f3))
            out["parallelogram"] = added(pic.path, prefix + "parallelogram", [a, c, [np.nan, np.nan], b, c],
                                         role="construct", dash=_dash("construct"), z=2, symbol="parallelogram",
                                         width=LINEWIDTHS["construct"] * PX_PER_PT,
                                         desc="force parallelogram (4.33): the sum's arrow is its diagonal from P")
    return {k: v for k, v in out.items() if v is not None}


# --------------------------------------------------------------------------- chains, one body
@documented
def velocity_step(pic, v_prev, s, qd, *, labels=("$v_{i-1}$", r"$s_i\dot{q}_i$", "$v_i$"),
                  toward=(None, None, None), dims: bool = True, dim_offset: float = 0.25,
                  prefix: str = "") -> dict:
    """Velocity kinematics across a joint, ``vᵢ = vᵢ₋₁ + sᵢq̇ᵢ`` (thesis 4.47–4.49, Fig. 4.7).

    A twist sum (:func:`twist_sum`), the distance ``k`` of 4.48 dimensioned.

    {parameters pic}
    v_prev : array_like (3,)
        The previous body's twist ``vᵢ₋₁``.
    s : array_like (3,)
        The joint's unit twist ``sᵢ``.
    qd : float
        The joint speed ``q̇ᵢ``.
    labels : (str, str, str)
        Labels of ``vᵢ₋₁``, ``sᵢq̇ᵢ`` and ``vᵢ``.
    {toward}
    dims, dim_offset
        Dimension the distance ``k`` of finite poles (offset to the left of the lever line).
    {prefix}

    Returns
    -------
    dict
        The elements ``{"v_prev", "joint", "v"}``, ``"lever"`` and ``"k"`` when drawn, and
        ``"values"``: the arrays ``{"joint": sᵢq̇ᵢ, "v": vᵢ}``.

    Raises
    ------
    InputError
        ``pic`` not a Picture, a twist not 3 finite numbers or ``qd`` not a finite number.

    Examples
    --------
    >>> from planargeo.screws.twists import unit_rotation
    >>> pic = Picture((-1, 4, -2, 2), size=(300, 200), ticks=False)
    >>> out = velocity_step(pic, 1.0 * unit_rotation([0, 0]), unit_rotation([3, 0]), 2.0)
    >>> out["values"]["v"].tolist()             # pole at beta k = 2/3 * 3 from the first (4.48)
    [0.0, -6.0, 3.0]
    """
    pic = as_picture(pic)
    v_prev = as_vec3(v_prev, "v_prev")
    u = as_vec3(s, "s") * as_scalar(qd, "qd")
    art = twist_sum(pic, v_prev, u, labels=labels, toward=toward, prefix=prefix)
    out = {"v_prev": art["v1"], "joint": art["v2"], "v": art["v3"], "lever": art.get("lever")}
    out["values"] = {"joint": u, "v": v_prev + u}
    if dims and v_prev[2] != 0.0 and u[2] != 0.0 and np.any(np.cross(v_prev, u)):
        a = np.array([-v_prev[1] / v_prev[2], v_prev[0] / v_prev[2]])
        b = np.array([-u[1] / u[2], u[0] / u[2]])
        out["k"] = dimension(pic, prefix + "k", a, b, "k", offset=as_scalar(dim_offset, "dim_offset"),
                             desc=f"distance k between the poles of {_symbol(labels[0])} and the joint "
                                  f"(4.48): {num(math.hypot(*(b - a)))} m")
        out["k"]["symbol"] = "k"
    return {k: v for k, v in out.items() if v is not None}


@documented
def acceleration_step(pic, a_prev, v_prev, s, qd, qdd, *,
                      labels=("$a_{i-1}$", r"$s_i\ddot{q}_i$", r"$v_i \times s_i\dot{q}_i$",
                              r"$s_i\ddot{q}_i + v_i \times s_i\dot{q}_i$", "$a_i$"),
                      toward=(None,) * 5, prefix: str = "") -> dict:
    """Acceleration across a joint, ``aᵢ = aᵢ₋₁ + sᵢq̈ᵢ + vᵢ × sᵢq̇ᵢ`` (thesis 4.50–4.54, Fig. 4.8).

    {parameters pic}
    a_prev, v_prev : array_like (3,)
        The previous body's acceleration and velocity twists (``vᵢ × sᵢ = vᵢ₋₁ × sᵢ``).
    s : array_like (3,)
        The joint's unit twist.
    qd, qdd : float
        Joint speed and acceleration.
    labels : tuple of 5 str
        Labels of ``aᵢ₋₁``, ``sᵢq̈ᵢ``, ``κᵢ``, ``sᵢq̈ᵢ + κᵢ`` and ``aᵢ``.
    {toward prefix}

    Returns
    -------
    dict
        The elements ``{"a_prev", "joint", "bias", "joint_total", "a"}``, the lever lines
        ``"lever"`` and ``"joint_lever"`` (``sᵢq̈ᵢ`` to ``κᵢ``) when drawn, and ``"values"``.

    Raises
    ------
    InputError
        ``pic`` not a Picture, a twist not 3 finite numbers, ``qd`` / ``qdd`` not finite
        numbers, or ``labels`` / ``toward`` not five.

    Examples
    --------
    >>> from planargeo.screws.twists import unit_rotation
    >>> pic = Picture((-1, 4, -2, 3), size=(300, 300), ticks=False)
    >>> out = acceleration_step(pic, [0, 0, 0], unit_rotation([0, 0]), unit_rotation([2, 0]), 1.0, 1.0)
    >>> out["values"]["bias"].tolist()          # kappa = w qd (S - V): a translation along x (4.53)
    [2.0, 0.0, 0.0]
    """
    pic = as_picture(pic)
    a_prev, v_prev, s = as_vec3(a_prev, "a_prev"), as_vec3(v_prev, "v_prev"), as_vec3(s, "s")
    qd, qdd = as_scalar(qd, "qd"), as_scalar(qdd, "qdd")
    labels = texts(labels, 5, "labels")
    toward = texts(toward, 5, "toward")
    rel = s * qdd
    bias = kappa(v_prev, s, qd)
    combo = rel + bias
    a = a_prev + combo
    syms = [_symbol(x) for x in labels]
    out = {}
    out["lever"] = _lever(pic, prefix + "lever", a_prev, combo,
                          desc=f"lever line of {syms[0]} and {syms[3]} (4.52): {syms[4]} lies on it")
    reach = num(math.hypot(bias[0], bias[1]) / abs(qdd)) if qdd else "∞"
    out["joint_lever"] = _lever(pic, prefix + "joint_lever", rel, bias, width=0.6 * PX_PER_PT,
                                desc=f"line of {syms[1]} and {syms[2]} (4.54): {syms[3]} lies on it, "
                                     f"|κ|/q̈ = {reach} m from the joint")
    words = (("a_prev", a_prev, "acceleration of the previous body", "4.50"),
             ("joint", rel, "joint acceleration", "4.52"),
             ("bias", bias, "bias acceleration κ = v × s q̇", "4.53"),
             ("joint_total", combo, "joint's part", "4.54"),
             ("a", a, "sum", "4.52"))
    for k, (name, p, what, eq) in enumerate(words):
        out[name] = _pole(pic, prefix + name, p, role="accel", label=labels[k], toward=toward[k],
                          emphasis=name == "a",
                          desc=f"{what} {syms[k]} ({eq}): {_pole_words(p, 'rad/s²', 'm/s²')}")
    out["values"] = {"a_prev": a_prev, "joint": rel, "bias": bias, "joint_total": combo, "a": a}
    return {k: v for k, v in out.items() if v is not None}


@documented
def newton_euler(pic, I, a, v, *, scale=None,
                 labels=("$v$", "$a$", "$Ia$", "$p$", "fⁿᵉᵗ = Ia + p"),
                 positions=(-1.0, -0.9, 1.0), toward=(None,) * 5, inertia: bool = True,
                 prefix: str = "") -> dict:
    """A body's Newton–Euler balance ``f_net = I a + v ×* I v`` (thesis 4.55–4.56, 5.64, Fig. 4.9).

    {parameters pic}
    I : array_like (3, 3)
        The body's inertia.
    a, v : array_like (3,)
        Its acceleration and velocity twists.
    {scale}
    labels : tuple of 5 str
        Labels of ``v``, ``a``, ``Ia``, ``p`` and ``f_net``.
    positions : (float, float, float)
        Signed distances of the arrows of ``Ia``, ``p``, ``f_net`` along their lines from the
        foot of the centre of mass.
    {toward}
    inertia : bool
        Draw the inertia's circle of gyration.
    {prefix}

    Returns
    -------
    dict
        The elements ``{"inertia", "v", "a", "Ia", "p", "f_net"}`` (those drawn) and
        ``"values"`` (the arrays ``Ia``, ``p``, ``f_net``).

    Raises
    ------
    InputError
        ``pic`` not a Picture, ``I`` not a finite 3×3 matrix, a twist not 3 finite numbers,
        a bad scale, or ``labels`` / ``toward`` / ``positions`` of the wrong length.

    Examples
    --------
    >>> from planargeo.screws.twists import inertia_matrix, unit_rotation
    >>> pic = Picture((-2, 3, -2, 2), size=(300, 240), ticks=False)
    >>> I = inertia_matrix(2.0, [1.0, 0.0], 0.18)
    >>> out = newton_euler(pic, I, 2 * unit_rotation([1, -1]), 1.5 * unit_rotation([-1, 0]), scale=0.1)
    >>> out["values"]["p"].round(12).tolist()   # m l w^2 = 9 toward the pole, along -x through y = 0
    [-9.0, 0.0, 0.0]
    """
    pic = as_picture(pic)
    I, a, v = as_mat3(I, "I"), as_vec3(a, "a"), as_vec3(v, "v")
    scale = _scale(scale)
    labels = texts(labels, 5, "labels")
    toward = texts(toward, 5, "toward")
    positions = [as_scalar(t, "positions") for t in texts(positions, 3, "positions")]
    Ia = I @ a
    p = bias_force(I, v)
    fnet = Ia + p
    c = centre_of_mass(I)
    syms = [_symbol(x) for x in labels]

    def along(f, t):  # a point at signed distance t along line f from the foot of c
        F = math.hypot(f[0], f[1])
        return None if F == 0.0 else c + f[:2] / F * t

    out = {}
    if inertia:
        out["inertia"] = inertia_conic(pic, prefix + "inertia", I,
                                       f"inertia I (4.58) as its circle of gyration: "
                                       f"m = {num(mass(I))} kg, centre of mass at {pair(c)} m")
    out["v"] = _pole(pic, prefix + "v", v, role="twist", label=labels[0], toward=toward[0],
                     desc=f"velocity {syms[0]} (4.10): {_pole_words(v)}")
    out["a"] = _pole(pic, prefix + "a", a, role="accel", label=labels[1], toward=toward[1],
                     desc=f"acceleration {syms[1]} (4.50): {_pole_words(a, 'rad/s²', 'm/s²')}")
    forces = (("Ia", Ia, "wrench", "inertial force I a, the axis of percussion of a", "4.55, 5.64"),
              ("p", p, "momentum", "centripetal force p = v ×* I v through the centre of mass", "4.56"),
              ("f_net", fnet, "wrench", "net force f = I a + p", "4.55"))
    for k, (name, f, role, what, eq) in enumerate(forces):
        out[name] = _wrench(pic, prefix + name, f, role=role, label=labels[k + 2], scale=scale,
                            anchor=along(f, positions[k]), emphasis=name == "f_net",
                            toward=toward[k + 2], desc=f"{what} ({eq}): {force_words(f)}")
    out["values"] = {"Ia": Ia, "p": p, "f_net": fnet}
    return {k: v for k, v in out.items() if v is not None}
