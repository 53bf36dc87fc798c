"""The T/U decompositions of chapter 6 drawn into a :class:`~planargeo.draw.picture.Picture`.

A joint's spaces ``s``, ``R`` and an inertia ``A`` split forces and accelerations (thesis 6.2–6.3,
6.36–6.48, Figs 6.1–6.5); each function returns its elements by name, arrays under ``"values"``.
"""
from __future__ import annotations

import math

import numpy as np

from planargeo._validate import as_vec3
from planargeo.draw._shared import ENTRIES, added, as_picture, line_words, texts, view_centre
from planargeo.draw.picture import Picture, plain_text
from planargeo.draw.pictures.common import label_toward, labelled_line
from planargeo.draw.pictures.kit import force as _force_arrow
from planargeo.draw.pictures._words import num, where
from planargeo.errors import InputError
from planargeo.geometry._docs import entries
from planargeo.mechanics.subspaces import Decomposition

__all__ = ["decomposition", "twist_split", "wrench_split", "projective_step", "twist_parts",
           "wrench_parts"]


# --------------------------------------------------------------------------- words and helpers
def _keys(prefix: str, k: int) -> list[str]:
    """Keys of ``k`` columns: ``prefix`` alone for one column, else ``prefix1``, ``prefix2``..."""
    return [prefix] if k == 1 else [f"{prefix}{j + 1}" for j in range(k)]


def _tex(sym: str, k: int, j: int) -> str:
    """``$sym$`` for one column, ``$sym_{j+1}$`` for column ``j`` of several."""
    return f"${sym}$" if k == 1 else f"${sym}_{{{j + 1}}}$"


#: The shared entries, and the examples' set-up: a rod of mass 1 pinned at the origin, its centre of
#: mass at (1, 0), and a view
_documented = entries(ENTRIES, {
    "sRA": "s, R, A : array_like (3, k), (3, 3-k), (3, 3)\n    Motion and reaction spaces of the "
           "joint (``sᵀR = 0``) and the inertia, positive definite.",
    "aims": "aims : dict, optional\n    Per key: the pixel offset ``(dx, dy)`` (y up) at which the "
            "placer tries the label first.",
    "rod": ">>> from planargeo.mechanics.joints import revolute\n"
           ">>> from planargeo.screws.twists import inertia_matrix, unit_rotation\n"
           ">>> j, A = revolute([0.0, 0.0]), inertia_matrix(1.0, [1.0, 0.0], 0.25)",
    "view": ">>> pic = Picture((-1, 3, -2, 2), size=(300, 300), ticks=False)"})

#: what the axis of percussion of a joint is (the start of its description)
_T_WORDS = "axis of percussion of the joint, T = A s (sᵀAs)⁻¹ (6.36, 6.39): "


def _wrench_words(l, unit: str = "N") -> str:
    """A force in words: its size and line, or a couple."""
    fx, fy, tz = (float(v) for v in l)
    F = math.hypot(fx, fy)
    if F == 0.0:
        return "zero" if tz == 0.0 else f"a couple of {num(tz)} {unit}·m"
    return f"{num(F)} {unit}, {line_words(l)}"


def _accel_words(p) -> str:
    """An acceleration pole in words: where it is and its rate."""
    return f"pole {where(p)}, rate {num(float(p[2]))} rad/s²"


def _aim(el: dict, aims: dict, key: str) -> None:
    """Ask the placer to try the label of ``el`` first at the pixel offset ``aims[key]``."""
    u = aims.get(key)
    if u is not None:
        u = np.asarray(u, dtype=float)
        gap = math.hypot(*u)
        if gap > 0.0:
            label_toward(el, u, gap)


def _line(pic: Picture, id: str, l, text, *, role: str, symbol: str, desc: str, anchor, side: float,
          aims: dict, key: str) -> dict:
    """A line without a sense arrow, labelled beside it near ``anchor`` (a couple: at its glyph)."""
    el = labelled_line(pic, id, l, plain_text(text or ""), anchor=anchor, side=side, end=14.0,
                       role=role, symbol=symbol, desc=desc, arrow=False)
    _aim(el, aims, key)
    return el


def _point(pic: Picture, id: str, p, text, *, role: str, symbol: str, desc: str, glyph: bool,
           aims: dict, key: str) -> dict:
    """A pole (:meth:`Picture.point`) with its label aimed as asked; the element."""
    el = added(pic.point, id, p, role=role, symbol=symbol, desc=desc, label=text or "", glyph=glyph)
    _aim(el, aims, key)
    return el


# --------------------------------------------------------------------------- decomposition
@_documented
def decomposition(pic: Picture, s, R, A, *, reactive: str = "U", labels=None, anchors=None,
                  sides=None, aims=None, prefix: str = "") -> dict:
    """A joint's spaces completed by an inertia (thesis 6.2–6.3, 6.36–6.48, Figs 6.1, 6.2).

    The poles ``s``, the lines ``T = A s (sᵀAs)⁻¹`` (6.36) and ``R``, and the poles
    ``U = A⁻¹R(RᵀA⁻¹R)⁻¹`` (6.45, on ``T``) or, with ``reactive="inverse"``, ``A⁻¹R`` (Fig. 6.1).

    {parameters pic sRA}
    reactive : {"U", "inverse"}
        Which accelerations to mark for the reactions.
    labels : dict, optional
        Label per key (``"s"``, ``"T"``, ``"R1"``, ``"U1"`` or ``"AiR1"``; ``"s1"``, ``"T1"``...
        for several columns); ``""`` for none.
    anchors : dict, optional
        Per line key: the point near which its label sits (default: the view's centre).
    sides : dict, optional
        Per line key: +1 (default) labels above the line (right of a vertical one), -1 below.
    {aims prefix}

    Returns
    -------
    dict
        The elements keyed as above, and ``"values"``: the arrays ``{"T", "U", "AiR"}``
        (``AiR = A⁻¹R``).

    Raises
    ------
    InputError
        ``pic`` not a Picture, or ``reactive`` neither "U" nor "inverse".
    PlanargeoError
        Spaces or an inertia the decomposition refuses (named by
        :class:`~planargeo.mechanics.subspaces.Decomposition`).

    Examples
    --------
    {rod view}
    >>> out = decomposition(pic, j.s, j.R, A)
    >>> sorted(k for k in out if k != "values")
    ['R1', 'R2', 'T', 'U1', 'U2', 's']
    >>> [(p["x"], p["y"]) for p in out["U2"]["parts"] if p["p"] == "mark"]   # U₂ on R₁ and on T
    [(1.25, 0.0)]
    >>> out["T"]["desc"]
    'axis of percussion of the joint, T = A s (sᵀAs)⁻¹ (6.36, 6.39): through (1.25, 0) m, along (0, 1)'
    """
    as_picture(pic)
    if reactive not in ("U", "inverse"):
        raise InputError(f"reactive must be 'U' or 'inverse', got {reactive!r}")
    dec = Decomposition(A, s, R)
    s, R, A, T, U = dec.s, dec.R, dec.A, dec.T, dec.U
    AiR = np.linalg.solve(A, R)
    k, r = s.shape[1], R.shape[1]
    inv = reactive == "inverse"
    pts = AiR if inv else U
    keys = {"s": _keys("s", k), "T": _keys("T", k), "R": _keys("R", r),
            "P": _keys("AiR" if inv else "U", r)}
    tex = {"s": "s", "T": "T", "R": "R", "P": "A^{-1}R" if inv else "U"}
    spaces = (("s", s), ("T", T), ("R", R), ("P", pts))
    default = {n: _tex(tex[key], X.shape[1], j)
               for key, X in spaces for j, n in enumerate(keys[key])}
    labels = {**default, **dict(labels or {})}
    anchors, sides, aims = dict(anchors or {}), dict(sides or {}), dict(aims or {})
    out: dict = {}
    for key, X, role, what in (("T", T, "momentum", _T_WORDS),
                               ("R", R, "reaction", "a unit reaction of the joint, a line through it (6.1): ")):
        for j, n in enumerate(keys[key]):
            out[n] = _line(pic, prefix + n, X[:, j], labels[n], role=role, symbol=default[n],
                           desc=what + line_words(X[:, j]), anchor=anchors.get(n),
                           side=sides.get(n, 1.0), aims=aims, key=n)
    for key, X, role, what, words in (
            ("s", s, "twist", "motion space of the joint, its pole (6.1): ", where),
            ("P", pts, "accel", "acceleration a unit reaction gives the free body, A⁻¹R (6.15): " if inv
             else "reactive acceleration U = A⁻¹R(RᵀA⁻¹R)⁻¹, RᵀU = 1 (6.45, 6.48): ", _accel_words)):
        for j, n in enumerate(keys[key]):
            out[n] = _point(pic, prefix + n, X[:, j], labels[n], role=role, symbol=default[n],
                            desc=what + words(X[:, j]), glyph=False, aims=aims, key=n)
    out["values"] = {"T": T, "U": U, "AiR": AiR}
    return out


# --------------------------------------------------------------------------- splits
@_documented
def twist_parts(s, R, A, a) -> dict:
    """The split of an acceleration by a joint: ``a = sψ + Uγ`` and the forces ``f_k = A a_k`` (6.44, 6.76).

    {parameters sRA}
    a : array_like (3,)
        The acceleration to split.

    Returns
    -------
    dict
        ``{"T", "U", "psi", "gamma", "a1", "a2", "f1", "f2"}``: ``ψ = Tᵀa``, ``γ = Rᵀa``,
        ``a₁ = sψ``, ``a₂ = Uγ``, ``f_k = A a_k``.

    Raises
    ------
    ShapeError, NonFiniteError
        ``a`` not a finite 3-vector.

    Examples
    --------
    {rod}
    >>> v = twist_parts(j.s, j.R, A, unit_rotation([2.0, 1.0]))
    >>> bool(np.allclose(v["a1"] + v["a2"], unit_rotation([2.0, 1.0])))    # a = sψ + Uγ (6.44)
    True
    """
    a = as_vec3(a, "a")
    dec = Decomposition(A, s, R)
    psi, gamma = dec.split_twist(a)                       # (Tᵀa, Rᵀa), 6.44
    a1, a2 = dec.s @ psi, dec.U @ gamma
    return {"T": dec.T, "U": dec.U, "psi": psi, "gamma": gamma, "a1": a1, "a2": a2,
            "f1": dec.A @ a1, "f2": dec.A @ a2}


@_documented
def wrench_parts(s, R, A, f) -> dict:
    """The split of a force by a joint: ``f = TQ + Rμ`` and the accelerations ``a_k = A⁻¹f_k`` (6.38, 6.80).

    Parameters
    ----------
    s, R, A, f : array_like
        As :func:`twist_parts`, with the force ``f`` (3,) to split.

    Returns
    -------
    dict
        ``{"T", "U", "Q", "mu", "f1", "f2", "a1", "a2"}``: ``Q = sᵀf``, ``μ = Uᵀf``,
        ``f₁ = TQ``, ``f₂ = Rμ``, ``a_k = A⁻¹f_k``.

    Raises
    ------
    ShapeError, NonFiniteError
        As :func:`twist_parts` (``f`` for ``a``).

    Examples
    --------
    {rod}
    >>> v = wrench_parts(j.s, j.R, A, [0.0, 1.0, 2.0])     # 1 N upwards on the line x = 2
    >>> float(v["Q"][0]), v["f1"] + v["f2"]                 # Q = sᵀf: the moment 2
    (2.0, array([0., 1., 2.]))
    """
    f = as_vec3(f, "f")
    dec = Decomposition(A, s, R)
    Q, mu = dec.split_wrench(f)                           # (sᵀf, Uᵀf), 6.38
    f1, f2 = dec.T @ Q, dec.R @ mu
    return {"T": dec.T, "U": dec.U, "Q": Q, "mu": mu, "f1": f1, "f2": f2,
            "a1": np.linalg.solve(dec.A, f1), "a2": np.linalg.solve(dec.A, f2)}


#: The two splits by a joint: how the parts are computed, their default labels and what they are
_SPLITS = {
    "twist": (twist_parts,
              {"a1": r"$a_1 = s\psi$", "a2": r"$a_2 = U\gamma$", "f1": "$f_1 = Aa_1$", "f2": "$f_2 = Aa_2$"},
              {"a1": "the part of a about the joint, a₁ = sψ, ψ = Tᵀa (6.44): ",
               "a2": "the part of a on the axis T, a₂ = Uγ, γ = Rᵀa (6.44): ",
               "f1": "the force of a₁, f₁ = A a₁ = T sᵀA a, a multiple of T (6.76): ",
               "f2": "the force of a₂, f₂ = A a₂ = R UᵀA a, through the joint (6.76): "}),
    "wrench": (wrench_parts,
               {"a1": "$a_1 = A^{-1}f_1$", "a2": "$a_2 = A^{-1}f_2$", "f1": "$f_1 = TQ$", "f2": r"$f_2 = R\mu$"},
               {"a1": "the acceleration of f₁, a₁ = A⁻¹f₁ = s TᵀA⁻¹f, about the joint (6.80): ",
                "a2": "the acceleration of f₂, a₂ = A⁻¹f₂ = U RᵀA⁻¹f, on the axis T (6.81): ",
                "f1": "the active part of f, f₁ = TQ, Q = sᵀf (6.38): ",
                "f2": "the reaction part of f, f₂ = Rμ, μ = Uᵀf, through the joint (6.38): "})}


def _split(kind, pic, s, R, A, x, *, parts, names, aims, anchors, scale, arrow_length, show_T, prefix):
    """Split ``x`` (:data:`_SPLITS` ``[kind]``); draw the axis ``T`` and the chosen parts ``(a_k, f_k)``."""
    as_picture(pic)
    try:
        show = tuple(int(p) for p in parts)
    except (TypeError, ValueError):
        show = ()
    if not show or any(p not in (1, 2) for p in show):
        raise InputError(f"parts must be a non-empty selection of 1 and 2, got {parts!r}")
    compute, default, descs = _SPLITS[kind]
    vals = compute(s, R, A, x)
    names = {**default, **(names or {})}
    out: dict = {"values": vals}
    T = vals["T"]
    aims, anchors = dict(aims or {}), dict(anchors or {})
    if show_T:
        for j, n in enumerate(_keys("T", T.shape[1])):
            sym = _tex("T", T.shape[1], j)
            out[n] = _line(pic, prefix + n, T[:, j], names.get(n, sym), role="construct", symbol=sym,
                           desc=_T_WORDS + line_words(T[:, j]), anchor=anchors.get(n), side=-1.0,
                           aims=aims, key=n)
    for k in show:
        a, f = vals[f"a{k}"], vals[f"f{k}"]
        ka, kf = f"a{k}", f"f{k}"
        out[ka] = _point(pic, prefix + ka, a, names.get(ka), role="accel", symbol=f"$a_{k}$",
                         desc=descs[ka] + _accel_words(a), glyph=True, aims=aims, key=ka)
        F = math.hypot(float(f[0]), float(f[1]))
        if F > 0.0:                             # data units per newton, or a fixed arrow length
            sc = float(arrow_length) / F if arrow_length is not None else float(scale or 0.0)
            at = anchors.get(kf)
            _force_arrow(pic, prefix + kf, f, scale=sc,
                         anchor=view_centre(pic) if at is None else at, role="wrench",
                         symbol=f"$f_{k}$", label=plain_text(names.get(kf) or ""),
                         desc=descs[kf] + _wrench_words(f))
        else:                                   # a couple (or nothing): the picture's couple glyph
            pic.line(prefix + kf, f, role="wrench", symbol=f"$f_{k}$", label=names.get(kf) or "",
                     desc=descs[kf] + _wrench_words(f))
        out[kf] = pic.elements[-1]
        _aim(out[kf], aims, kf)
    return out


@_documented
def twist_split(pic: Picture, s, R, A, a, *, parts=(1, 2), names=None, aims=None, anchors=None,
                scale=1.0, arrow_length=None, show_T: bool = True, prefix: str = "") -> dict:
    """An acceleration split by a joint, and the forces of its parts (thesis 6.44, 6.75–6.76, Fig. 6.3).

    ``a = sψ + Uγ``, ``ψ = Tᵀa``, ``γ = Rᵀa`` (6.44, 6.62); the forces ``f_k = A a_k`` (6.76).

    {parameters pic sRA}
    a : array_like (3,)
        The acceleration to split.
    parts : sequence of {1, 2}
        Which parts to draw (e.g. one per panel); the values hold both.
    names : dict, optional
        Labels keyed ``"a1"``, ``"f1"``, ``"a2"``, ``"f2"``, ``"T"`` (``""``: none).
    {aims}
    anchors : dict, optional
        Per key ``"T"``, ``"f1"``, ``"f2"``: near which point the label or the force's arrow sits.
    scale, arrow_length : float, optional
        Force arrows: data units per newton, or a fixed length; neither: no arrow.
    show_T : bool
        Draw the axis ``T`` (a construction line).
    {prefix}

    Returns
    -------
    dict
        Elements ``{"T", "a1", "f1", "a2", "f2"}`` (those drawn) and ``"values"``:
        ``{"T", "U", "psi", "gamma", "a1", "a2", "f1", "f2"}`` (:func:`twist_parts`).

    Raises
    ------
    InputError
        ``pic`` not a Picture, ``parts`` not a selection of 1 and 2.
    ShapeError, NonFiniteError
        ``a`` not a finite 3-vector.

    Examples
    --------
    {rod view}
    >>> out = twist_split(pic, j.s, j.R, A, unit_rotation([2.0, 1.0]), arrow_length=0.6)
    >>> v = out["values"]
    >>> bool(np.allclose(v["a1"] + v["a2"], unit_rotation([2.0, 1.0])))    # a = sψ + Uγ (6.44)
    True
    >>> [p["p"] for p in out["f1"]["parts"]]          # the line, its arrow, its label
    ['path', 'arrow', 'text']
    """
    return _split("twist", pic, s, R, A, a, parts=parts, names=names, aims=aims, anchors=anchors,
                  scale=scale, arrow_length=arrow_length, show_T=show_T, prefix=prefix)


@_documented
def wrench_split(pic: Picture, s, R, A, f, *, parts=(1, 2), names=None, aims=None, anchors=None,
                 scale=1.0, arrow_length=None, show_T: bool = True, prefix: str = "") -> dict:
    """A force split by a joint, and the accelerations of its parts (thesis 6.38, 6.77–6.81, Fig. 6.4).

    ``f = TQ + Rμ``, ``Q = sᵀf``, ``μ = Uᵀf`` (6.38, 6.61); their accelerations ``A⁻¹f_k`` (6.80).

    Parameters
    ----------
    pic, s, R, A, parts, names, aims, anchors, scale, arrow_length, show_T, prefix
        As :func:`twist_split`.
    f : array_like (3,)
        The force to split.

    Returns
    -------
    dict
        As :func:`twist_split`; ``"values"``: ``{"T", "U", "Q", "mu", "f1", "f2", "a1", "a2"}``
        (:func:`wrench_parts`).

    Raises
    ------
    InputError, ShapeError, NonFiniteError
        As :func:`twist_split` (``f`` for ``a``).

    Examples
    --------
    {rod view}
    >>> f = np.array([0.0, 1.0, 2.0])                 # 1 N upwards on the line x = 2 (4.27)
    >>> out = wrench_split(pic, j.s, j.R, A, f, parts=[1])
    >>> v = out["values"]
    >>> sorted(k for k in out if k != "values"), float(v["Q"][0])   # Q = sᵀf: the moment 2
    (['T', 'a1', 'f1'], 2.0)
    """
    return _split("wrench", pic, s, R, A, f, parts=parts, names=names, aims=aims, anchors=anchors,
                  scale=scale, arrow_length=arrow_length, show_T=show_T, prefix=prefix)


# --------------------------------------------------------------------------- projective step
@_documented
def projective_step(pic: Picture, s, R, A, a_prev, a, kappa, *,
                    names=("$T_i$", "$s_i$", "$a_{i-1}$", "$a_i$"), aims=None, T_anchor=None,
                    T_side: float = 1.0, prefix: str = "") -> dict:
    """Projective kinematics across one joint (thesis 6.98–6.101, Fig. 6.5).

    ``Tᵢ`` (6.36) picks the joint's part of an acceleration, as 6.44: ``ψᵢ = Tᵢᵀaᵢ``,
    ``ψᵢ₋₁ = Tᵢᵀaᵢ₋₁``, and ``q̈ᵢ = ψᵢ − Tᵢᵀ(aᵢ₋₁ + κᵢ)`` (6.100, 6.110).

    {parameters pic sRA}
    a_prev, a : array_like (3,)
        Accelerations of the parent and of the body.
    kappa : array_like (3,)
        The joint's bias acceleration ``κᵢ``.
    names : tuple of 4 str
        Labels (and symbols) of ``Tᵢ``, ``sᵢ``, ``aᵢ₋₁``, ``aᵢ``.
    {aims}
    T_anchor : (x, y), optional
        Near which point of ``Tᵢ`` its label sits.
    T_side : float
        +1: ``Tᵢ``'s label above the line, -1: below.
    {prefix}

    Returns
    -------
    dict
        The elements ``{"T", "s", "a_prev", "a"}`` (first columns) and ``"values"``:
        ``{"T", "psi", "psi_prev", "qdd"}``.

    Raises
    ------
    InputError
        ``pic`` not a Picture, or ``names`` not four labels.
    ShapeError, NonFiniteError
        An argument that is not a finite homogeneous vector, named.

    Examples
    --------
    {rod}
    >>> a = 2.0 * j.s[:, 0]                            # turning about the joint at 2 rad/s²
    >>> pic = Picture((-1, 3, -2, 2), size=(300, 300), ticks=False)
    >>> out = projective_step(pic, j.s, j.R, A, np.zeros(3), a, np.zeros(3))
    >>> out["values"]["qdd"].round(12).tolist()
    [2.0]
    """
    as_picture(pic)
    names = texts(names, 4, "names")                    # Tᵢ, sᵢ, aᵢ₋₁, aᵢ
    a_prev, a, kap = as_vec3(a_prev, "a_prev"), as_vec3(a, "a"), as_vec3(kappa, "kappa")
    dec = Decomposition(A, s, R)
    T = dec.T
    psi, psi_prev = T.T @ a, T.T @ a_prev
    qdd = psi - T.T @ (a_prev + kap)
    aims = dict(aims or {})
    out = {"T": _line(pic, prefix + "T", T[:, 0], names[0], role="momentum", symbol=names[0],
                      desc="axis of percussion of the joint, T = A s (sᵀAs)⁻¹ (6.39), picks the "
                           f"joint's part of an acceleration: {line_words(T[:, 0])}",
                      anchor=T_anchor, side=T_side, aims=aims, key="T")}
    for k, (key, p, role, desc) in enumerate((
            ("s", dec.s[:, 0], "twist", f"the joint, its unit twist (6.1): {where(dec.s[:, 0])}"),
            ("a_prev", a_prev, "accel", f"acceleration of the parent, ψ = Tᵀa = {num(psi_prev[0])} "
                                        f"rad/s² along the joint (6.100): {_accel_words(a_prev)}"),
            ("a", a, "accel", f"acceleration of the body, ψ = Tᵀa = {num(psi[0])} rad/s² along "
                              f"the joint, q̈ = ψᵢ − Tᵀ(aᵢ₋₁ + κ) = {num(qdd[0])} rad/s² "
                              f"(6.100, 6.110): {_accel_words(a)}"))):
        out[key] = _point(pic, prefix + key, p, names[k + 1], role=role, symbol=names[k + 1],
                          desc=desc, glyph=key != "s", aims=aims, key=key)
    out["values"] = {"T": T, "psi": psi, "psi_prev": psi_prev, "qdd": qdd}
    return out
