"""Scene ``two-body``: articulated inertia of two joined bodies (thesis 7.2, Figure 7.3).

Two identical bodies joined at an angle ``phi``: body 1 along +x from ``CJ_1`` at the origin,
joint 2 at ``(L, 0)``.  At rest without gravity a horizontal force on body 1 meets ``A_1`` (7.10,
7.19), whose ``[1, 1]`` entry is the effective mass (7.12, 7.22)::

    m_x / m = (8 + lambda^2 (1 + cos^2 phi)) / (lambda^2 + 4),   lambda = L / rho

Examples
--------
>>> from planargeo import scenes
>>> scenes.build("two-body", phi=0.0).quantities["m_x"]     # in line: both bodies are pushed (7.20)
2.0
"""
from __future__ import annotations

import numpy as np

from planargeo.mechanics.model import Model
from planargeo.scenes import SceneResult, _at_rest, check_param, plain, register
from planargeo.scenes.articulated import bent_chain_model

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
    """
    return check_param(name, value, positive=True)


def two_body_model(m: float, rho: float, L: float) -> Model:
    """Two identical bodies on revolute joints at the origin and at ``(L, 0)`` of body 1, no gravity."""
    return bent_chain_model(2, rho, L, m)


@register("two-body", checks={"m": "positive", "rho": "positive", "L": "positive"})
def two_body(m: float = 1.0, rho: float = 0.5, L: float = 1.0, phi: float = np.pi / 4) -> SceneResult:
    """Two joined bodies pushed horizontally (thesis 7.2, 7.9-7.24).

    Parameters
    ----------
    m, rho, L : float
        Mass, radius of gyration (0.5: the elliptical disk of thesis 7.3) and length of each body (> 0).
    phi : float
        Angle of body 2 relative to body 1 [rad].

    Returns
    -------
    SceneResult
        ``A1`` (at ``CJ_1``, 7.19), ``m_x`` (7.12), ``mx_over_m`` (7.22), ``lam`` (7.21), ``A2``
        (= ``I_2``, 7.14, 7.17), ``U2`` (7.18), ``T2``, ``s``, ``R`` (7.15, 7.16).

    Examples
    --------
    >>> r = two_body(m=2.0, rho=1.0, L=2.0, phi=np.pi / 2)
    >>> round(r.quantities["mx_over_m"], 12)     # (L^2 + 8 rho^2) / (L^2 + 4 rho^2) = 12/8
    1.5
    """
    from planargeo.algorithms.articulated_inertia import articulated_inertia

    model = two_body_model(m, rho, L)
    q = np.array([0.0, phi])
    r = articulated_inertia(model, q)
    A1 = r.A[0]
    quantities = {
        "A1": plain(A1), "m_x": float(A1[0, 0]), "mx_over_m": float(A1[0, 0] / m), "lam": L / rho,
        "A2": plain(r.A[1]), "U2": plain(r.U[1]), "T2": plain(r.T[1][:, 0]),
        "s": [plain(r.S[0][:, 0]), plain(r.S[1][:, 0])], "R": [plain(r.R[0]), plain(r.R[1])],
    }
    return SceneResult(model=model, state=_at_rest(q), quantities=quantities,
                       extra={"articulated": r, "force_direction": np.array([1.0, 0.0])})
