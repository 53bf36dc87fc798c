"""Scene ``subspace``: the subspace decomposition of one body at a joint (thesis 6.1–6.4, 6.63–6.97).

One rigid body at rest, held by one joint (a ``revolute`` pivot, a ``prismatic`` slider, a
``revolute_prismatic`` pin in a slot, or the 2-dof ``twin_prismatic`` plane joint of 4.79) and
loaded by one force ``f``; everything chapter 6 names, computed with
:mod:`planargeo.mechanics.subspaces`.  For a 2-dof joint the columns of ``s`` span a line of poles
(the reaction line) and the ``T`` lines pass through one point, ``U`` (``s_line``, ``T_pencil``).

Examples
--------
>>> from planargeo import scenes
>>> r = scenes.build("subspace", joint="revolute", px=0.0, py=0.0, m=2.0, cx=1.0, cy=0.0, rho=0.5)
>>> r.quantities["T"]                          # the pivot's axis of percussion, x = d + ρ²/d (5.67)
[[0.0], [0.8], [1.0]]
"""
from __future__ import annotations

import math

import numpy as np

from planargeo.errors import DegenerateGeometryError
from planargeo.mechanics.joints import reaction_space, motion_space
from planargeo.mechanics.subspaces import (Decomposition, joint_space_inertia,
                                           reaction_space_inverse_inertia)
from planargeo.scenes import SceneResult, plain, register
from planargeo.screws.twists import inertia_matrix

__all__ = ["subspace", "JOINT_KINDS", "subspace_state", "unit_direction"]

#: The joints the scene offers (the package's kind names; ``twin_prismatic`` is thesis 4.79's plane joint).
JOINT_KINDS = ("revolute", "prismatic", "revolute_prismatic", "twin_prismatic")


def unit_direction(deg: float) -> np.ndarray:
    """The unit vector at ``deg`` degrees from +x, exact at multiples of 90° (no ``6e-17`` for a zero).

    Parameters
    ----------
    deg : float
        The angle in degrees.

    Returns
    -------
    ndarray, shape (2,)

    Examples
    --------
    >>> unit_direction(90.0), unit_direction(-180.0)
    (array([0., 1.]), array([-1.,  0.]))
    """
    q = float(deg) / 90.0
    if q.is_integer():
        return np.array([(1.0, 0.0), (0.0, 1.0), (-1.0, 0.0), (0.0, -1.0)][int(q) % 4])
    a = math.radians(deg)
    return np.array([math.cos(a), math.sin(a)])


def _span_line(X: np.ndarray) -> np.ndarray | None:
    """The normalised line joining the two columns of a (3, 2) space; None if k != 2."""
    if X.shape[-1] != 2:
        return None
    line = np.cross(X[:, 0], X[:, 1])
    n = float(np.linalg.norm(line))
    return line / n if n > 0 else None


def subspace_state(joint: str, point, direction, I, force) -> dict:
    """Every quantity of the single-body decomposition, as numpy arrays (thesis 6.1–6.4, 6.63–6.97).

    Parameters
    ----------
    joint : {"revolute", "prismatic", "revolute_prismatic", "twin_prismatic"}
        The joint kind.
    point, direction : array_like, shape (2,)
        The joint's point and direction (slide; the plane joint's x axis).
    I : array_like, shape (3, 3)
        The body's inertia at the origin (positive definite).
    force : array_like, shape (3,)
        The applied wrench ``f``.

    Returns
    -------
    dict
        ``s``, ``R`` (``sᵀR = 0``, 6.1); ``T = I s (sᵀIs)⁻¹`` (6.36), ``U = I⁻¹R (RᵀI⁻¹R)⁻¹``
        (6.37, 6.33 corrected); ``I``, ``f``; ``Q = sᵀf``, ``mu = Uᵀf``, ``TQ``, ``Rmu`` (6.38,
        6.61); ``psi = Tᵀ I⁻¹ f``, ``gamma = Rᵀ I⁻¹ f`` (6.44, 6.62, 6.80–6.81), ``a_free``,
        ``s_psi`` (the held body's acceleration, 6.93 with the applied-wrench sign,
        ``docs/errata.md``), ``U_gamma``; ``reaction = −Rμ``; ``sIs`` (6.67), ``RIR`` (6.71);
        ``s_line``, ``T_pencil``; ``residuals`` of the power relations, each must vanish.

    Raises
    ------
    InputError
        An unknown joint kind, or non-finite input.
    DegenerateGeometryError
        A zero joint direction, or the zero wrench (a pure couple, on the line at infinity, is taken).
    SingularInertiaError, SingularConfigurationError
        ``I`` not positive definite, or ``sᵀIs`` / ``RᵀI⁻¹R`` singular.
    """
    f = np.asarray(force, dtype=float)
    if not np.any(f):        # a pure couple is the line at infinity, an ordinary wrench; zero is none
        raise DegenerateGeometryError("the applied force must be non-zero, or the wrench a pure couple; "
                                      "got no force and no couple")
    s = motion_space(joint, point, direction)
    R = reaction_space(joint, point, direction)
    dec = Decomposition(I, s, R, name="I")
    T, U = dec.T, dec.U
    Q, mu = dec.split_wrench(f)
    a_free = np.linalg.solve(dec.A, f)
    psi, gamma = dec.split_twist(a_free)
    TQ, Rmu = T @ Q, R @ mu
    s_psi, U_gamma = s @ psi, U @ gamma
    k = s.shape[1]
    eye_k, eye_r = np.eye(k), np.eye(3 - k)
    residuals = {
        "sᵀT − 1": float(np.max(np.abs(s.T @ T - eye_k))),
        "RᵀU − 1": float(np.max(np.abs(R.T @ U - eye_r))),
        "TᵀU": float(np.max(np.abs(T.T @ U), initial=0.0)),
        "T sᵀ + R Uᵀ − 1": float(np.max(np.abs(T @ s.T + R @ U.T - np.eye(3)))),
        "sᵀR": float(np.max(np.abs(s.T @ R), initial=0.0)),
        "(sψ)ᵀ(Rμ)": float(s_psi @ Rmu),
        "(Uγ)ᵀ(TQ)": float(U_gamma @ TQ),
        "Rᵀ(sψ)": float(np.max(np.abs(R.T @ s_psi), initial=0.0)),
    }
    return {"joint": joint, "s": s, "R": R, "T": T, "U": U, "I": dec.A, "f": f, "Q": Q, "mu": mu,
            "TQ": TQ, "Rmu": Rmu, "psi": psi, "gamma": gamma, "a_free": a_free, "s_psi": s_psi,
            "U_gamma": U_gamma, "reaction": -Rmu, "sIs": joint_space_inertia(dec.A, s),
            "RIR": reaction_space_inverse_inertia(dec.A, R), "s_line": _span_line(s),
            "T_pencil": _span_line(T), "residuals": residuals}


@register("subspace", checks={"joint": JOINT_KINDS, "m": "positive", "rho": "positive",
                              "F": "nonzero"})
def subspace(joint: str = "revolute", px: float = 0.0, py: float = 0.0, joint_angle_deg: float = 0.0,
             m: float = 2.0, cx: float = 1.0, cy: float = 0.0, rho: float = 0.5,
             ax: float = 1.6, ay: float = 0.0, force_angle_deg: float = 90.0, F: float = 1.0) -> SceneResult:
    """One body at a joint, loaded by one force: ``s, R, T, U`` and every split of chapter 6.

    Parameters
    ----------
    joint : {"revolute", "prismatic", "revolute_prismatic", "twin_prismatic"}
        The joint (``twin_prismatic``: the plane joint of thesis 4.79).
    px, py, joint_angle_deg : float
        The joint's point [m] and direction [deg].
    m, cx, cy, rho : float
        Mass [kg] (> 0), centre of mass [m], radius of gyration about it [m] (> 0).
    ax, ay, force_angle_deg, F : float
        A point of the applied force's line [m], its direction [deg] and magnitude [N] (non-zero).

    Returns
    -------
    SceneResult
        ``quantities``: :func:`subspace_state` as lists (``s_line``, ``T_pencil``: None for 1 dof).

    Raises
    ------
    SceneError
        A parameter out of range (named).
    DegenerateGeometryError
        ``F = 0`` (no line of action).

    Examples
    --------
    >>> r = subspace(joint="twin_prismatic")       # thesis 4.79: T are forces through the centre of mass
    >>> r.quantities["T"]
    [[1.0, 0.0], [0.0, 1.0], [0.0, 1.0]]
    """
    I = inertia_matrix(m, (cx, cy), m * rho * rho)
    e = F * unit_direction(force_angle_deg)
    f = np.array([e[0], e[1], ax * e[1] - ay * e[0]])           # the force e through (ax, ay) (5.56)
    st = subspace_state(joint, (px, py), unit_direction(joint_angle_deg), I, f)
    q = {k: dict(v) if isinstance(v, dict) else plain(v) for k, v in st.items() if k != "joint"}
    return SceneResult(state={"v": [0.0, 0.0, 0.0]}, quantities=q, extra={"state": st})
