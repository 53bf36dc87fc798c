"""Scene ``horizontal-chain``: articulated inertia of the first body of a straight chain (thesis 7.3).

``n`` identical bodies (mass ``m``, radius of gyration ``rho``, joints ``L``
apart, centre of mass half-way) lie along +x, joint 1 at the origin, at rest,
without gravity.  The articulated inertia ``A_1`` of the first body (7.1.1) is
diagonal when expressed at its *effective centre of gravity*, the point
``(d, 0)`` (7.26)::

    A_1 at (d, 0) = diag(m_x, m_y, A_z)

With ``A_1 = [[a, 0, 0], [0, b, c], [0, c, e]]`` at the origin (the chain is
symmetric about the x axis) moving the reference point to ``(d, 0)`` gives
``d = c / b``, ``m_x = a``, ``m_y = b``, ``A_z = e - c^2 / b``.  The results
depend on ``n`` and ``lambda = L / rho`` only.  For two bodies (derived by hand
from 7.19 at ``phi = 0``)::

    d/L = (lambda^2 + 12) / (2 (lambda^2 + 8))   (7.27)     m_x/m = 2
    m_y/m = (lambda^2 + 8) / (lambda^2 + 4)                  A_z/(m rho^2) = 2 (lambda^2 + 4) / (lambda^2 + 8)

and for ``lambda = 2`` every further body leaves ``d``, ``m_y`` and ``A_z``
unchanged (7.3's claim; ``m_x = n m`` always).

Examples
--------
>>> from planargeo import scenes
>>> q = scenes.build("horizontal-chain", n=2, lam=2.0).quantities
>>> round(q["d_over_L"], 12), round(q["my_over_m"], 12), round(q["Az_over_m_rho2"], 12)
(0.666666666667, 1.5, 1.333333333333)
"""
from __future__ import annotations

import numpy as np

from planargeo.mechanics.model import Body, Joint, Model
from planargeo.scenes import SceneResult, check_param, plain, register

__all__ = ["horizontal_chain", "horizontal_chain_model", "effective_centre"]


def horizontal_chain_model(n: int, m: float, rho: float, L: float) -> Model:
    """``n`` identical bodies in line along +x on revolute joints ``L`` apart, no gravity.

    Parameters
    ----------
    n : int
        Number of bodies.
    m : float
        Mass of each body (kg).
    rho : float
        Radius of gyration of each body (m).
    L : float
        Joint spacing (m).

    Returns
    -------
    Model
        The chain, without gravity.
    """
    bodies = [Body(m, (L / 2, 0.0), m * rho * rho, name=f"body {i + 1}") for i in range(n)]
    joints = [Joint("revolute", (0.0 if i == 0 else L, 0.0, 0.0), name=f"CJ{i + 1}") for i in range(n)]
    return Model(bodies, joints, list(range(-1, n - 1)), gravity=(0.0, 0.0))


def effective_centre(A) -> tuple[float, float, float, float]:
    """``(d, m_x, m_y, A_z)`` of an inertia symmetric about the x axis (thesis 7.26).

    ``d`` is where the inertia becomes diagonal on the x axis.

    Parameters
    ----------
    A : array_like, shape (3, 3)
        An inertia symmetric about the x axis.

    Returns
    -------
    tuple of float
        ``(d, m_x, m_y, A_z)``: the centre on the x axis (m), the two masses (kg) and the rotational inertia there (kg·m²).

    Examples
    --------
    >>> from planargeo.screws.twists import inertia_matrix
    >>> effective_centre(inertia_matrix(2.0, [0.5, 0.0], 0.3))
    (0.5, 2.0, 2.0, 0.3)
    """
    A = np.asarray(A, dtype=float)
    d = A[1, 2] / A[1, 1]
    return float(d), float(A[0, 0]), float(A[1, 1]), float(A[2, 2] - A[1, 2] ** 2 / A[1, 1])


@register("horizontal-chain", limits={"n": (2000, "n = 2000 takes about 1 s; the cost grows as n²")})
def horizontal_chain(n: int = 4, lam: float = 2.0) -> SceneResult:
    """Effective centre and inertia of the first body of a horizontal chain (thesis 7.3, 7.25-7.27).

    Parameters
    ----------
    n : int
        Number of bodies (>= 1).  Default 4 (the thesis tabulates 1..4).
    lam : float
        Size ratio ``lambda = L / rho`` (> 0, 7.21).  Default 2.0, the
        elliptical disk of the thesis.

    Returns
    -------
    SceneResult
        ``quantities``: ``d_over_L``, ``mx_over_m``, ``my_over_m``,
        ``Az_over_m_rho2`` of the first body (7.26), and ``A1`` (3×3, at the
        origin) for ``m = L = 1``.  ``state``: ``q = 0``.

    Examples
    --------
    >>> horizontal_chain(n=1, lam=3.0).quantities["d_over_L"]
    0.5
    """
    from planargeo.algorithms.articulated_inertia import articulated_inertia

    n = check_param("n", n, "int", positive=True)
    lam = check_param("lam", lam, positive=True)
    params = dict(n=n, lam=lam)
    m, L = 1.0, 1.0
    rho = L / lam
    model = horizontal_chain_model(n, m, rho, L)
    r = articulated_inertia(model, np.zeros(n))
    d, mx, my, Az = effective_centre(r.A[0])
    quantities = {
        "d_over_L": d / L,
        "mx_over_m": mx / m,
        "my_over_m": my / m,
        "Az_over_m_rho2": Az / (m * rho * rho),
        "A1": plain(r.A[0]),
    }
    state = {"q": [0.0] * n, "qd": [0.0] * n, "tau": [0.0] * n}
    return SceneResult("horizontal-chain", params, model, state, quantities,
                       extra={"articulated": r, "effective_centre": np.array([d, 0.0])})
