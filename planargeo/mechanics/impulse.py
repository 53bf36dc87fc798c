"""A body at rest struck by a short blow: velocity change, reaction impulse, apparent mass (thesis 5.4, 6.3.2).

Only the blow's impulse ``ĵ`` (a wrench, N·s) matters: ``I Δv = ĵ + ĵ_R`` (6.63).  Free,
``Δv = I⁻¹ ĵ``: the body starts turning about the percussion pole of the blow's line (5.64–5.68).
Held by a joint ``s``, ``Δv = s (sᵀIs)⁻¹ sᵀ ĵ`` (6.93, applied-wrench sign) and the support answers
with ``ĵ_R = −R Uᵀ ĵ`` (6.38, 6.61b), zero for a blow on the pivot's axis of percussion, through
the centre of percussion ``l = d + ρ²/d`` (5.67).  The apparent mass along a line (figure 3.3) is
``1 / (uᵀ M u)``, ``u`` the unit force on the line and ``M`` the body's (effective) mobility.
"""
from __future__ import annotations

import math

import numpy as np

from planargeo._validate import as_array, as_scalar
from planargeo.errors import DegenerateGeometryError, NumericOverflowError, ShapeError
from planargeo.geometry._docs import entries
from planargeo.mechanics.model import _finite_tuple
from planargeo.mechanics.subspaces import effective_mobility
from planargeo.screws.inertia import centre_of_mass, mobility, radius_of_gyration

__all__ = ["StruckBody", "impulse_response", "apparent_mass", "centre_of_percussion", "moved_points"]

_documented = entries({
    "I": "I : array_like, shape (3, 3)\n    The body's inertia at the origin (definite for a free body).",
    "s": "s : array_like, shape (3, k) or (3,), optional\n    The support's motion space; None: a free body.",
    "impulse": "impulse : array_like, shape (3,)\n"
               "    The blow's impulse wrench ``ĵ = [Jx, Jy, Jz]`` (N·s).",
    "line": "line : array_like, shape (3,)\n"
            "    The line (any non-zero multiple of a force wrench on it).",
    "dv": "Returns\n-------\ndv, reaction : ndarray, shape (3,)\n    The velocity twist just after "
          "the blow; the support's reaction impulse ``I Δv − ĵ``.",
    "mass": "Returns\n-------\nfloat\n    The impulse per unit velocity change along the line "
            "(kg); ``inf`` through a pivot.\n\nRaises\n------\nDegenerateGeometryError\n"
            "    ``line`` is the line at infinity (a couple).",
})


def _single(x, name: str, n: int = 3) -> np.ndarray:
    """One vector of shape ``(n,)``, or a named error."""
    return np.array(_finite_tuple(x, name, n))


def _unit_force(line) -> np.ndarray:
    """``line`` scaled to a unit force (``fx² + fy² = 1``); the line at infinity is refused."""
    u = _single(line, "line")
    F = math.hypot(float(u[0]), float(u[1]))
    if not F > 0:
        raise DegenerateGeometryError(
            f"line must be a force line, not the line at infinity (a couple has no apparent mass), got {u!r}")
    return u / F


@_documented
class StruckBody:
    """A body at rest, free or held by a joint, ready to be struck: its mobility computed once.

    The inertia is checked and inverted here, once (``I⁻¹`` free, ``s (sᵀIs)⁻¹ sᵀ`` held, 6.93);
    :meth:`response` and :meth:`apparent_mass` then only multiply.

    {parameters I s}

    Attributes
    ----------
    I, M : ndarray, shape (3, 3)
        The inertia and the body's (effective) mobility (read-only).
    held : bool
        Whether a joint holds the body.

    Raises
    ------
    InputError, SingularInertiaError, SingularConfigurationError
        A bad argument, ``I`` not symmetric positive semi-definite (definite when free), ``sᵀIs`` singular.

    Examples
    --------
    A uniform rod (m = 3, L = 2) pivoted at the origin: struck across at x = 1 and at its tip.

    >>> from planargeo.screws.twists import inertia_matrix
    >>> rod = StruckBody(inertia_matrix(3.0, [1.0, 0.0], 1.0), [0.0, 0.0, 1.0])
    >>> [float(rod.response([0.0, 1.0, x])[0][2]) for x in (1.0, 2.0)]
    [0.25, 0.5]
    >>> round(rod.apparent_mass([0.0, 1.0, 2.0]), 12)
    1.0
    """

    def __init__(self, I, s=None) -> None:
        M = mobility(I) if s is None else effective_mobility(I, s)     # a fresh array: kept as it is
        self.I = np.array(I, dtype=float, order="K")
        self.M = M
        self.held = s is not None
        for a in (self.I, self.M):
            a.flags.writeable = False

    def __repr__(self) -> str:
        return f"StruckBody({'held' if self.held else 'free'}, I={self.I.tolist()})"

    @_documented
    def response(self, impulse) -> tuple[np.ndarray, np.ndarray]:
        """Velocity change and reaction impulse after the blow ``impulse`` (:func:`impulse_response`).

        {parameters impulse dv}

        Raises
        ------
        InputError
            ``impulse`` not three finite numbers.
        NumericOverflowError
            ``Δv`` or the reaction beyond double precision.
        """
        j = _single(impulse, "impulse")
        # Δv and ĵᵣ are linear in ĵ: computed for ĵ scaled by 2^-e (exact) to a largest entry in [0.5, 1)
        # when it lies outside (2^-500, 2^500), then scaled back; a subnormal or huge blow keeps its digits
        # and no product of the matrices with it under- or overflows on the way.
        m = float(np.max(np.abs(j)))
        e = math.frexp(m)[1] if m > 0 and not 2.0 ** -500 < m < 2.0 ** 500 else 0
        js = np.ldexp(j, -e) if e else j
        dv = self.M @ js
        reaction = self.I @ dv - js if self.held else np.zeros(3)
        if e:
            with np.errstate(over="ignore", under="ignore"):
                dv, reaction = np.ldexp(dv, e), np.ldexp(reaction, e)
        if not (np.isfinite(dv).all() and np.isfinite(reaction).all()):
            raise NumericOverflowError(f"impulse_response: the velocity change or the reaction overflows double "
                                       f"precision (impulse {tuple(map(float, j))} too large for this inertia)")
        return dv + 0.0, reaction + 0.0

    @_documented
    def apparent_mass(self, line) -> float:
        """Apparent mass ``1 / (uᵀ M u)`` along a force line (:func:`apparent_mass`).

        {parameters line mass}
        """
        u = _unit_force(line)
        M = self.M
        w = float(u @ M @ u)
        scale = float(np.max(np.abs(M))) * float(u @ u)
        if w <= 1e-14 * scale:
            return math.inf
        return 1.0 / w


@_documented
def impulse_response(I, impulse, s=None) -> tuple[np.ndarray, np.ndarray]:
    """Velocity change and reaction impulse of a body at rest struck by ``impulse`` (thesis 6.63, 6.93, 6.38).

    {parameters I impulse s dv}

    Raises
    ------
    InputError, SingularInertiaError, SingularConfigurationError
        A bad argument, ``I`` not symmetric positive semi-definite (definite when free), ``sᵀIs`` singular.
    NumericOverflowError
        ``Δv`` or the reaction beyond double precision (a huge blow on a tiny mass).

    See Also
    --------
    StruckBody : many blows on one body, its inertia inverted once.

    Examples
    --------
    A uniform rod (m = 3, L = 2) pivoted at the origin, struck across at x = 1 by a unit impulse:
    ``ω = J d / (m L²/3) = 0.25``, and the pivot pulls back by ``−0.25``.

    >>> from planargeo.screws.twists import inertia_matrix
    >>> dv, jr = impulse_response(inertia_matrix(3.0, [1.0, 0.0], 1.0), [0.0, 1.0, 1.0], [0.0, 0.0, 1.0])
    >>> dv + 0.0, jr + 0.0
    (array([0.  , 0.  , 0.25]), array([ 0.  , -0.25,  0.  ]))
    """
    _single(impulse, "impulse")                  # a bad blow is named before the inertia is inverted
    return StruckBody(I, s).response(impulse)


@_documented
def apparent_mass(I, line, s=None) -> float:
    """Apparent mass ``1 / (uᵀ M u)`` of a body at rest along a force line (thesis figure 3.3, 6.93).

    {parameters I line s mass}

    See Also
    --------
    StruckBody : many lines on one body, its inertia inverted once.

    Examples
    --------
    A uniform rod (m = 3, L = 2) pivoted at one end, struck across at its tip: ``m/3``; free, ``m/4``.

    >>> from planargeo.screws.twists import inertia_matrix
    >>> I = inertia_matrix(3.0, [1.0, 0.0], 1.0)
    >>> round(apparent_mass(I, [0.0, 1.0, 2.0], [0.0, 0.0, 1.0]), 12), round(apparent_mass(I, [0.0, 1.0, 2.0]), 12)
    (1.0, 0.75)
    """
    _unit_force(line)                            # the line at infinity is named before the inertia is inverted
    return StruckBody(I, s).apparent_mass(line)


def centre_of_percussion(I, pivot) -> np.ndarray:
    """The centre of percussion of a pivot, ``l = d + ρ²/d`` from it beyond the centre of mass (5.67).

    Parameters
    ----------
    I : array_like, shape (3, 3)
        A rigid-body inertia (mass > 0) at the origin.
    pivot : array_like, shape (2,)
        The pivot ``(x, y)``.

    Returns
    -------
    ndarray, shape (2,)

    Raises
    ------
    DegenerateGeometryError
        The pivot is at the centre of mass (the axis is the line at infinity).

    Examples
    --------
    >>> from planargeo.screws.twists import inertia_matrix
    >>> centre_of_percussion(inertia_matrix(3.0, [1.0, 0.0], 1.0), (0.0, 0.0))   # 2L/3 for a rod of L = 2
    array([1.33333333, 0.        ])
    """
    P = _single(pivot, "pivot", 2)
    c = np.asarray(centre_of_mass(I), dtype=float)          # raises for a massless "inertia"
    rho = float(radius_of_gyration(I))
    d = c - P
    dd = float(d @ d)
    if not dd > 1e-24 * max(1.0, float(P @ P), float(c @ c)):
        raise DegenerateGeometryError(f"pivot must differ from the centre of mass {tuple(map(float, c))}, "
                                      f"got {tuple(map(float, P))} (its axis of percussion is the line at infinity)")
    return P + d * (1.0 + rho * rho / dd)                   # l = d + ρ²/d along the line P c (5.67)


def moved_points(dv, points, t: float) -> np.ndarray:
    """Where body points are ``t`` seconds after the blow, the body moving with the constant twist ``dv``.

    ``p(t) = R(θ) p₀ + t [[S, −K], [K, S]] v`` with ``θ = ω t``, ``S = sin θ / θ``,
    ``K = (1 − cos θ) / θ``: without the pole, so finite from a turn to a translation.

    Parameters
    ----------
    dv : array_like, shape (3,)
        The twist ``[vx, vy, ω]``.
    points : array_like, shape (n, 2) or (2,)
        Body points at ``t = 0``.
    t : float
        Time after the blow (s).

    Returns
    -------
    ndarray, shape of ``points``

    Raises
    ------
    NumericOverflowError
        A point carried beyond double precision's range.

    Examples
    --------
    >>> moved_points([0.0, -1.0, 1.0], [[2.0, 0.0]], math.pi / 2).round(12) + 0.0   # turned about (1, 0)
    array([[1., 1.]])
    """
    tw = _single(dv, "dv")
    P = as_array(points, "points")
    if P.shape[-1:] != (2,) or P.ndim > 2:
        raise ShapeError(f"points must have shape (n, 2) or (2,), got {P.shape}")
    t = as_scalar(t, "t")
    vx, vy, w = map(float, tw)
    with np.errstate(over="ignore", invalid="ignore"):
        th = w * t
        if abs(th) < 1e-8:                    # the series: S = 1 − θ²/6, K = θ/2 − θ³/24, exact in double here
            S, K = 1.0, 0.5 * th
        else:
            S, K = math.sin(th) / th, math.sin(0.5 * th) * (math.sin(0.5 * th) / (0.5 * th))
        c, s_ = (1.0, th) if abs(th) < 1e-8 else (math.cos(th), math.sin(th))
        shift = np.array([t * (S * vx - K * vy), t * (K * vx + S * vy)])
        out = P @ np.array([[c, s_], [-s_, c]]) + shift
    if not np.isfinite(out).all():
        raise NumericOverflowError(f"moved_points: the points leave double precision's range "
                                   f"(dv {tuple(map(float, tw))}, t = {t!r} too large)")
    return out + 0.0
