"""Scene ``articulated``: rigid and articulated inertias along a chain as conics (thesis 7.1-7.3, 10.2.2, 10.2.3).

``n`` bodies (``m = 1``, joints ``L = 1`` apart, ``rho = L / lam``) hang from the origin, each
joint after the first bent by ``phi``, at rest.  Inertias are imaginary conics, drawn through
the real conic with the homogeneous part's sign flipped (10.2.3).

Examples
--------
>>> from planargeo import scenes
>>> q = scenes.build("articulated", n=3, lam=2.0, phi=0.0).quantities
>>> round(q["effective_7_26"]["d_over_L"], 12)          # 7.27 at lambda = 2: 2/3 for any n
0.666666666667
"""
from __future__ import annotations

import numpy as np

from planargeo.mechanics.model import Body, Joint, Model
from planargeo.scenes import SceneResult, _at_rest, plain, register

__all__ = ["articulated", "articulated_state", "percussion_axes", "bent_chain_model", "joint_points", "inertia_at", "conic_centre",
           "effective_centre", "COMPONENTS"]

#: the six independent components of a planar inertia, in the order of the convergence chart
COMPONENTS = ("m_x", "m_y", "A_z", "m_xy", "c_x", "c_y")


def bent_chain_model(n: int, rho: float, L: float = 1.0, m: float = 1.0, g: float = 0.0) -> Model:
    """``n`` identical bodies on revolute joints ``L`` apart along each body's x axis, no gravity.

    Parameters
    ----------
    n : int
        Number of bodies (>= 1).
    rho, L, m : float
        Radius of gyration, length and mass of each body (> 0).
    g : float
        Gravity along -y [m/s²].

    Returns
    -------
    Model

    Examples
    --------
    >>> bent_chain_model(2, 0.5).N
    2
    """
    bodies = [Body(m, (L / 2, 0.0), m * rho * rho, name=f"body {i + 1}") for i in range(n)]
    joints = [Joint("revolute", (0.0 if i == 0 else L, 0.0, 0.0), name=f"CJ{i + 1}") for i in range(n)]
    return Model(bodies, joints, list(range(-1, n - 1)), gravity=(0.0, 0.0 - float(g)))   # g = 0: +0.0


def joint_points(q, L: float = 1.0) -> np.ndarray:
    """Joint positions ``(n + 1, 2)`` of the chain with relative angles ``q`` (the last: the tip's end).

    Parameters
    ----------
    q : array_like (n,)
        Relative joint angles [rad].
    L : float
        Distance between joints.

    Returns
    -------
    ndarray (n + 1, 2)

    Examples
    --------
    >>> joint_points([0.0, np.pi / 2]).round(12)[-1]           # the tip's end
    array([1., 1.])
    """
    th = np.cumsum(np.asarray(q, dtype=float))
    steps = L * np.column_stack([np.cos(th), np.sin(th)])
    return np.vstack([[0.0, 0.0], np.cumsum(steps, axis=0)])


def inertia_at(A, point) -> np.ndarray:
    """An inertia given at the origin, expressed at ``point = (x, y)``: ``X⁻ᵀ A X⁻¹`` (thesis 1.68, 4.58, 4.8).

    Parameters
    ----------
    A : array_like (3, 3)
    point : (float, float)

    Returns
    -------
    ndarray (3, 3)

    Examples
    --------
    >>> from planargeo.screws.twists import inertia_matrix
    >>> np.diag(inertia_at(inertia_matrix(2.0, [1.0, 0.0], 0.5), (1.0, 0.0)))   # at the centre of mass
    array([2. , 2. , 0.5])
    """
    x, y = (float(v) for v in point)
    Xi = np.array([[1.0, 0.0, y], [0.0, 1.0, -x], [0.0, 0.0, 1.0]])     # X⁻¹
    return Xi.T @ np.asarray(A, dtype=float) @ Xi


def conic_centre(A) -> np.ndarray:
    """Centre ``(x, y)`` of an inertia conic, ``A⁻¹ [0, 0, 1]``: the centre of mass, or the effective centre (7.26).

    Parameters
    ----------
    A : array_like (3, 3), positive definite

    Returns
    -------
    ndarray (2,)

    Examples
    --------
    >>> from planargeo.screws.twists import inertia_matrix
    >>> conic_centre(inertia_matrix(2.0, [1.0, -0.5], 0.5))
    array([ 1. , -0.5])
    """
    P = np.linalg.solve(np.asarray(A, dtype=float), [0.0, 0.0, 1.0])
    return np.array([-P[1] / P[2], P[0] / P[2]])


def effective_centre(A) -> tuple[float, float, float, float]:
    """``(d, m_x, m_y, A_z)`` of an inertia symmetric about the x axis: where it is diagonal (thesis 7.26).

    Parameters
    ----------
    A : array_like, shape (3, 3)
        An inertia symmetric about the x axis.

    Returns
    -------
    tuple of float
        The centre ``d`` on the x axis (m), the two masses (kg) and the rotational inertia there.

    Examples
    --------
    >>> from planargeo.screws.twists import inertia_matrix
    >>> effective_centre(inertia_matrix(2.0, [0.5, 0.0], 0.3))
    (0.5, 2.0, 2.0, 0.3)
    """
    A = np.asarray(A, dtype=float)
    d = A[1, 2] / A[1, 1]
    return float(d), float(A[0, 0]), float(A[1, 1]), float(A[2, 2] - A[1, 2] ** 2 / A[1, 1])


@register("articulated", limits={"n": (40, "n = 40 takes about 0.1 s; the chart grows as n²")},
          checks={"n": "int positive", "lam": "positive", "outboard": "int nonnegative optional"})
def articulated(n: int = 4, lam: float = 3.0, phi: float = 0.4, outboard: int | None = None,
                pole_x: float = 0.0, pole_y: float = -0.6) -> SceneResult:
    """Rigid and articulated inertias of a bent chain, their axes of percussion and convergence (7.7a, 7.26, 5.64-5.68).

    Parameters
    ----------
    n : int
        Number of bodies (>= 1).
    lam, phi : float
        Size ratio ``lambda = L / rho`` (> 0, 7.21); bend at every joint after the first [rad].
    outboard : int or None
        Bodies beyond each body in its articulated inertia (>= 0; None: all, the full recursion).
    pole_x, pole_y : float
        The acceleration pole ``a`` whose axes of percussion are given [m].

    Returns
    -------
    SceneResult
        The keys of :func:`articulated_state` as lists (without ``result``, ``full``), and
        ``effective_7_26`` of body 1 (7.26; meaningful for ``phi = 0``).

    Raises
    ------
    SceneError
        ``n`` or ``lam`` not positive, ``outboard`` negative (named).

    Examples
    --------
    >>> r = articulated(n=2, lam=2.0, phi=0.0, outboard=0)
    >>> r.quantities["A"][0] == r.quantities["I"][0]       # no outboard body: the rigid inertia
    True
    """
    L, m = 1.0, 1.0
    rho = L / lam
    model = bent_chain_model(n, rho, L, m)
    q = np.array([0.0] + [phi] * (n - 1))
    st = articulated_state(model, q, outboard=outboard, pole=(pole_x, pole_y), L=L)
    d, mx, my, Az = effective_centre(st["A_full"][0])
    quantities = {k: plain(st[k]) for k in ("joints", "I", "A", "A_full", "centre_rigid", "centre", "pole",
                                             "axis_rigid", "axis", "truncation_error")}
    quantities["components"] = [plain(c) for c in st["components"]]
    quantities["error"] = [plain(e) for e in st["error"]]
    quantities["effective_7_26"] = {"d_over_L": d / L, "mx_over_m": mx / m, "my_over_m": my / m,
                                    "Az_over_m_rho2": Az / (m * rho * rho)}
    return SceneResult(model=model, state=_at_rest(q), quantities=quantities,
                       extra={"articulated": st["result"], "full": st["full"], "rho": rho, "L": L})


def articulated_state(model, q, *, outboard: int | None = None, pole=(0.0, 0.0), L: float = 1.0) -> dict:
    """Everything the scene and the explorer show of one configuration of a chain at rest (arrays).

    Parameters
    ----------
    model : Model
        An unbranched chain of revolute joints ``L`` apart (:func:`bent_chain_model`).
    q : array_like (n,)
        Relative joint angles [rad].
    outboard : int or None
        Truncation of the recursion (10.2.2; None: all bodies outboard).
    pole : (float, float)
        The acceleration pole ``a`` whose axes of percussion are wanted.
    L : float
        Distance between joints.

    Returns
    -------
    dict
        ``joints``; ``I``, ``A``, ``A_full`` at the origin (7.7a); conic centres ``centre_rigid``,
        ``centre``; ``pole``; the axes ``axis_rigid`` = ``I_i a``, ``axis`` = ``A_i a``;
        ``truncation_error``; per body ``components`` (:data:`COMPONENTS` of ``A_i`` at its joint
        after ``k = 0, 1, ...`` steps) and their relative ``error``; ``result`` and ``full``.

    Raises
    ------
    SingularConfigurationError
        A singular joint (never for bodies with mass and rotational inertia).

    Examples
    --------
    >>> st = articulated_state(bent_chain_model(2, 0.5), [0.0, 0.0], outboard=0)
    >>> bool(np.allclose(st["A"], st["I"]))
    True
    """
    from planargeo.algorithms.articulated_inertia import articulated_inertia
    from planargeo.mechanics.kinematics import kinematics

    q = np.asarray(q, dtype=float)
    n = model.N
    pts = joint_points(q, L)
    full = articulated_inertia(model, q)
    shown = full if outboard is None else articulated_inertia(model, q, steps=outboard)
    I = np.asarray(kinematics(model, q).I, dtype=float)          # the bodies' inertias at the origin
    comps, errs = [[] for _ in range(n)], [[] for _ in range(n)]
    nA = np.linalg.norm(full.A, axis=(1, 2))
    for k in range(n):                                   # one truncated recursion per k, all bodies at once
        Ak = full.A if k == n - 1 else articulated_inertia(model, q, steps=k).A
        for i in range(n - k):                           # body i has n-1-i bodies outboard
            Ai = inertia_at(Ak[i], pts[i])               # at its joint, as the COMPONENTS
            comps[i].append(Ai[[0, 1, 2, 0, 0, 1], [0, 1, 2, 1, 2, 2]].tolist())
            errs[i].append(float(np.linalg.norm(Ak[i] - full.A[i]) / nA[i]))
    st = {
        "joints": pts, "I": I, "A": shown.A, "A_full": full.A,
        "centre_rigid": np.array([conic_centre(x) for x in I]),
        "centre": np.array([conic_centre(x) for x in shown.A]),
        "truncation_error": np.linalg.norm(shown.A - full.A, axis=(1, 2)) / nA,
        "components": [np.array(c) for c in comps], "error": [np.array(e) for e in errs],
        "result": shown, "full": full,
    }
    return {**st, **percussion_axes(st, pole)}


def percussion_axes(state: dict, pole) -> dict:
    """The axes of percussion of every body for the acceleration pole ``pole`` (thesis 5.64-5.68).

    The part of :func:`articulated_state` that depends on the pole (an explorer dragging the pole
    keeps the rest).

    Parameters
    ----------
    state : dict
        :func:`articulated_state` of the configuration (its ``I`` and ``A``).
    pole : (float, float)
        The acceleration pole ``a``: a unit rotation about it.

    Returns
    -------
    dict
        ``pole`` (the twist ``a``), ``axis_rigid`` = ``I_i a`` and ``axis`` = ``A_i a``.

    Examples
    --------
    >>> st = articulated_state(bent_chain_model(2, 0.5), [0.0, 0.0])
    >>> percussion_axes(st, (1.0, 0.0))["pole"].tolist()
    [0.0, -1.0, 1.0]
    """
    a = np.array([pole[1], -pole[0], 1.0])
    return {"pole": a, "axis_rigid": state["I"] @ a, "axis": state["A"] @ a}
