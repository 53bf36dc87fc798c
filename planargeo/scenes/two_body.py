"""Scene ``two-body``: articulated inertia of two joined bodies (thesis 7.2, Figure 7.3).

Two identical bodies (mass ``m``, radius of gyration ``rho``, length ``L``,
centre of mass at mid-length) are joined at an angle ``phi``.  Body 1 lies
along +x from the joint ``CJ_1`` at the global origin (``s_1 = [0, 0, 1]``,
7.15); joint 2 sits at ``(L, 0)`` (``s_2 = [0, -L, 1]``).  At rest and without
gravity a horizontal force on body 1 meets the articulated inertia ``A_1``
(7.10, 7.19, computed by the articulated inertia algorithm 7.1.1), whose
``[1, 1]`` entry is the effective mass ``m_x`` (7.12)::

    m_x / m = (8 + lambda^2 (1 + cos^2 phi)) / (lambda^2 + 4),   lambda = L / rho   (7.22)

Examples
--------
>>> from planargeo import scenes
>>> r = scenes.build("two-body", phi=0.0)
>>> r.quantities["m_x"]                    # in line: both bodies are pushed (7.20)
2.0
"""
from __future__ import annotations

import numpy as np

from planargeo.mechanics.model import Body, Joint, Model
from planargeo.scenes import SceneResult, check_param, plain, register

__all__ = ["two_body", "positive"]


def positive(value, name: str) -> float:
    """``value`` as a float; :class:`SceneError` unless finite and > 0 (:func:`check_param`).

    Parameters
    ----------
    value : object
        The parameter's value.
    name : str
        The parameter's name.

    Returns
    -------
    float
        The value.
    """
    return check_param(name, value, positive=True)


def finite(value, name: str) -> float:
    """``value`` as a finite float, else :class:`SceneError` (:func:`check_param`)."""
    return check_param(name, value)


def two_body_model(m: float, rho: float, L: float) -> Model:
    """Two identical bodies on revolute joints at the origin and at ``(L, 0)`` of body 1, no gravity."""
    body = Body(m, (L / 2, 0.0), m * rho * rho)
    return Model([Body(m, (L / 2, 0.0), m * rho * rho, name="body 1"),
                  Body(body.mass, body.com, body.inertia, name="body 2")],
                 [Joint("revolute", (0.0, 0.0, 0.0), name="CJ1"), Joint("revolute", (L, 0.0, 0.0), name="CJ2")],
                 [-1, 0], gravity=(0.0, 0.0))


@register("two-body")
def two_body(m: float = 1.0, rho: float = 0.5, L: float = 1.0, phi: float = np.pi / 4) -> SceneResult:
    """Two joined bodies pushed horizontally (thesis 7.2, 7.9-7.24).

    Parameters
    ----------
    m : float
        Mass of each body (> 0).  Default 1.
    rho : float
        Radius of gyration of each body about its centre of mass (> 0).
        Default 0.5 = ``L / 2``, the elliptical disk of thesis 7.3 (``lambda = 2``).
    L : float
        Length of each body = distance between the joints (> 0).  Default 1.
    phi : float
        Angle of body 2 relative to body 1 [rad].  Default ``pi / 4``.

    Returns
    -------
    SceneResult
        ``quantities``: ``A1`` (3×3, at the origin = ``CJ_1``, 7.19), ``m_x``
        (7.12), ``mx_over_m`` (7.22), ``lam`` (7.21), ``A2`` (= ``I_2``, 7.14,
        7.17), ``U2`` (3×2, 7.18), ``T2`` (3, at the origin), ``s``, ``R``
        (7.15, 7.16).  ``state``: ``q = [0, phi]``, ``qd = tau = [0, 0]``.

    Examples
    --------
    >>> r = two_body(m=2.0, rho=1.0, L=2.0, phi=np.pi / 2)
    >>> round(r.quantities["mx_over_m"], 12)     # (L^2 + 8 rho^2) / (L^2 + 4 rho^2) = 12/8
    1.5
    """
    from planargeo.algorithms.articulated_inertia import articulated_inertia

    m, rho, L = positive(m, "m"), positive(rho, "rho"), positive(L, "L")
    phi = finite(phi, "phi")
    params = dict(m=m, rho=rho, L=L, phi=phi)
    model = two_body_model(m, rho, L)
    q = np.array([0.0, phi])
    r = articulated_inertia(model, q)
    A1 = r.A[0]
    quantities = {
        "A1": plain(A1),
        "m_x": float(A1[0, 0]),
        "mx_over_m": float(A1[0, 0] / m),
        "lam": L / rho,
        "A2": plain(r.A[1]),
        "U2": plain(r.U[1]),
        "T2": plain(r.T[1][:, 0]),
        "s": [plain(r.S[0][:, 0]), plain(r.S[1][:, 0])],
        "R": [plain(r.R[0]), plain(r.R[1])],
    }
    state = {"q": plain(q), "qd": [0.0, 0.0], "tau": [0.0, 0.0]}
    return SceneResult("two-body", params, model, state, quantities,
                       extra={"articulated": r, "force_direction": np.array([1.0, 0.0])})
