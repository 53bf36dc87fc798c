"""Scene ``impulse``: a bat or a door at rest struck by a short blow (thesis 5.4, 6.3.2, figure 3.3).

A uniform ``"bat"`` lamina held at its grip, or a ``"door"`` seen from above held by its hinge
(``P``, the origin), struck by ``J`` N·s on a line; held by a revolute joint or free.  Solved with
:mod:`planargeo.mechanics.impulse`: no reaction when the blow passes through the centre of
percussion, ``l = d + ρ²/d`` from the pivot (5.67).

Examples
--------
>>> from planargeo import scenes
>>> r = scenes.build("impulse", body="door")     # 0.9 m by 0.04 m: l = 2L/3 + w²/(6L) from the hinge (5.67)
>>> round(r.quantities["centre_of_percussion"][0], 7)
0.6002963
"""
from __future__ import annotations

import functools
import math

import numpy as np

from planargeo.mechanics.impulse import StruckBody, centre_of_percussion
from planargeo.mechanics.joints import motion_space
from planargeo.scenes import SceneResult, check_param, plain, register
from planargeo.scenes.subspace import unit_direction
from planargeo.screws.inertia import Inertia

__all__ = ["impulse", "BODIES", "body_outline"]

#: The bodies offered: outline vertices (metres, the grip / hinge at the origin).
BODIES = {
    "bat": [(-0.08, -0.016), (0.35, -0.018), (0.6, -0.03), (0.84, -0.034), (0.84, 0.034),
            (0.6, 0.03), (0.35, 0.018), (-0.08, 0.016)],
    "door": [(0.0, -0.02), (0.9, -0.02), (0.9, 0.02), (0.0, 0.02)],
}
SUPPORTS = ("held", "free")


def body_outline(body: str) -> np.ndarray:
    """The outline ``(n, 2)`` of a body of :data:`BODIES` (metres, grip or hinge at the origin).

    Parameters
    ----------
    body : {"bat", "door"}

    Returns
    -------
    ndarray, shape (n, 2)

    Raises
    ------
    SceneError
        ``body`` is not one of :data:`BODIES`.
    """
    body = check_param("body", body, "choice", choices=tuple(BODIES))
    return np.array(BODIES[body], dtype=float)


def _finite_or_none(v: float) -> float | None:
    return v if math.isfinite(v) else None


def _pole(tw, size: float = 1.0) -> list | None:
    """The pole ``(x, y)`` of a twist, None for a translation (or no motion).

    A turn at round-off level (``|ω| size ≤ 1e-12 |v|``, ``size`` the body's length) is a
    translation: a blow through the centre of mass meets a centroid off by an ulp.
    """
    if abs(tw[2]) * size <= 1e-12 * math.hypot(tw[0], tw[1]):
        return None
    return [float(-tw[1] / tw[2]) + 0.0, float(tw[0] / tw[2]) + 0.0]


@functools.lru_cache(maxsize=16)
def _body_inertia(outline: tuple, m: float) -> tuple:
    """``(I, com, ρ, centre of percussion about the origin)`` of a uniform lamina of mass ``m`` (read-only).

    Kept per (outline, mass): a blow moved over the same body reuses it.
    """
    from shapely.geometry import Polygon

    unit = Inertia.from_polygon(Polygon(outline))
    I = unit.matrix * (m / float(unit.mass))
    inertia = Inertia(I)
    c = np.asarray(inertia.com, dtype=float)
    cop = np.asarray(centre_of_percussion(I, (0.0, 0.0)), dtype=float)
    for a in (I, c, cop):
        a.flags.writeable = False
    return I, c, float(inertia.radius_of_gyration), cop


@functools.lru_cache(maxsize=16)
def _struck(outline: tuple, m: float) -> tuple[StruckBody, StruckBody]:
    """The body held at the origin by a revolute joint and free, each inertia checked and inverted
    once per (outline, mass): a blow dragged over the same body only multiplies (thesis 6.93)."""
    I = _body_inertia(outline, m)[0]
    return StruckBody(I, motion_space("revolute", (0.0, 0.0))), StruckBody(I)


@register("impulse", checks={"body": tuple(BODIES), "support": SUPPORTS, "m": "positive",
                             "J": "nonzero"})
def impulse(body: str = "bat", support: str = "held", m: float = 0.9, x: float = 0.55, y: float = 0.0,
            angle_deg: float = 90.0, J: float = 1.0) -> SceneResult:
    """A body at rest struck by a blow: velocity pole, reaction impulse, apparent mass (thesis 5.4, 6.93).

    Parameters
    ----------
    body : {"bat", "door"}
        A bat held at its grip, or a door (top view) held by its hinge, at the origin.
    support : {"held", "free"}
        Whether the grip / hinge holds the body (a revolute joint) or nothing does.
    m : float
        Mass [kg] (> 0), spread uniformly over the outline.
    x, y, angle_deg, J : float
        A point of the blow's line [m], its direction [deg] and impulse [N·s] (non-zero).

    Returns
    -------
    SceneResult
        ``I``, ``com``, ``rho``, ``impulse`` (``ĵ``), ``dv``, ``omega``, ``pole`` (None for a
        translation), ``v_com``, ``reaction`` (zero when free) and its ``reaction_force``,
        ``reaction_across``, ``reaction_along`` (the line grip–centre of mass), ``pole_if_free``
        (``I⁻¹ĵ``), ``centre_of_percussion``, ``apparent_mass`` (figure 3.3; also ``_held``,
        ``_free``), ``kinetic_energy``, ``v_grip``.

    Raises
    ------
    SceneError
        ``body`` or ``support`` not one of its choices, ``m`` not positive, ``J`` zero (named).

    Examples
    --------
    A door (L = 0.9, w = 0.04) struck at its edge: ``ω = J L / J_P`` with ``J_P = m (4L² + w²)/12``.

    >>> r = impulse(body="door", support="held", m=3.0, x=0.9, J=1.0)
    >>> round(r.quantities["omega"], 12) == round(0.9 / (3.0 * (4 * 0.81 + 0.0016) / 12), 12)
    True
    """
    key = (tuple(map(tuple, BODIES[body])), float(m))
    I, c, rho, cop = _body_inertia(*key)
    held, free = _struck(*key)
    e = J * unit_direction(angle_deg)
    j = np.array([e[0], e[1], x * e[1] - y * e[0]])              # the blow's impulse wrench (5.56)
    s = motion_space("revolute", (0.0, 0.0))
    dv, reaction = (held if support == "held" else free).response(j)
    dv_free, _ = free.response(j)
    size = float(np.ptp(np.array(BODIES[body]), axis=0).max())
    n = c / float(np.hypot(*c))                                  # along grip -> centre of mass
    t = np.array([-n[1], n[0]])                                  # across
    rf = reaction[:2]
    v_grip = dv[:2]                                              # velocity of the origin (the grip)
    q = {
        "I": plain(I), "com": plain(c), "rho": rho, "impulse": plain(j), "dv": plain(dv),
        "omega": float(dv[2]), "pole": _pole(dv, size), "v_com": plain(dv[:2] + dv[2] * np.array([-c[1], c[0]])),
        "reaction": plain(reaction), "reaction_force": plain(rf),
        "reaction_across": float(rf @ t), "reaction_along": float(rf @ n),
        "pole_if_free": _pole(dv_free, size),
        "centre_of_percussion": plain(cop),
        "apparent_mass_held": _finite_or_none(held.apparent_mass(j)),
        "apparent_mass_free": _finite_or_none(free.apparent_mass(j)),
        "kinetic_energy": float(0.5 * dv @ I @ dv), "v_grip": plain(v_grip),
    }
    q["apparent_mass"] = q["apparent_mass_held"] if support == "held" else q["apparent_mass_free"]
    outline = np.array(BODIES[body], dtype=float)
    return SceneResult(state={"v": [0.0, 0.0, 0.0]}, quantities=q,
                       extra={"outline": outline, "I": I, "impulse": j, "dv": dv, "dv_free": dv_free,
                              "reaction": reaction, "s": s})
