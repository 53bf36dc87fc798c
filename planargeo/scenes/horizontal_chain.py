"""Scene ``horizontal-chain``: articulated inertia of the first body of a straight chain (thesis 7.3).

``n`` identical bodies along +x (joints ``L`` apart) at rest, without gravity.  ``A_1`` (7.1.1) is
diagonal, ``diag(m_x, m_y, A_z)``, at its *effective centre of gravity* ``(d, 0)`` (7.26); the
results depend on ``n`` and ``lambda = L / rho`` only.  For two bodies (by hand from 7.19)::

    d/L = (lambda^2 + 12) / (2 (lambda^2 + 8))   (7.27)     m_x/m = 2
    m_y/m = (lambda^2 + 8) / (lambda^2 + 4)                  A_z/(m rho^2) = 2 (lambda^2 + 4) / (lambda^2 + 8)

and at ``lambda = 2`` further bodies leave ``d``, ``m_y`` and ``A_z`` unchanged (7.3's claim).

Examples
--------
>>> from planargeo import scenes
>>> q = scenes.build("horizontal-chain", n=2, lam=2.0).quantities
>>> round(q["d_over_L"], 12), round(q["my_over_m"], 12), round(q["Az_over_m_rho2"], 12)
(0.666666666667, 1.5, 1.333333333333)
"""
from __future__ import annotations

import numpy as np

from planargeo.mechanics.model import Model
from planargeo.scenes import SceneResult, _at_rest, plain, register
from planargeo.scenes.articulated import bent_chain_model, effective_centre

__all__ = ["horizontal_chain", "horizontal_chain_model", "effective_centre"]


def horizontal_chain_model(n: int, m: float, rho: float, L: float) -> Model:
    """``n`` identical bodies in line along +x on revolute joints ``L`` apart, no gravity.

    Parameters
    ----------
    n : int
        Number of bodies.
    m, rho, L : float
        Mass (kg) and radius of gyration (m) of each body, joint spacing (m).

    Returns
    -------
    Model
    """
    return bent_chain_model(n, rho, L, m)


@register("horizontal-chain", limits={"n": (2000, "n = 2000 takes about 1 s; the cost grows as n²")},
          checks={"n": "int positive", "lam": "positive"})
def horizontal_chain(n: int = 4, lam: float = 2.0) -> SceneResult:
    """Effective centre and inertia of the first body of a horizontal chain (thesis 7.3, 7.25-7.27).

    Parameters
    ----------
    n, lam : int, float
        Number of bodies (>= 1) and size ratio ``lambda = L / rho`` (> 0, 7.21).

    Returns
    -------
    SceneResult
        ``d_over_L``, ``mx_over_m``, ``my_over_m``, ``Az_over_m_rho2`` of body 1 (7.26) and
        ``A1`` at the origin, for ``m = L = 1``.

    Examples
    --------
    >>> horizontal_chain(n=1, lam=3.0).quantities["d_over_L"]
    0.5
    """
    from planargeo.algorithms.articulated_inertia import articulated_inertia

    m, L = 1.0, 1.0
    rho = L / lam
    model, q = horizontal_chain_model(n, m, rho, L), np.zeros(n)
    r = articulated_inertia(model, q)
    d, mx, my, Az = effective_centre(r.A[0])
    quantities = {"d_over_L": d / L, "mx_over_m": mx / m, "my_over_m": my / m,
                  "Az_over_m_rho2": Az / (m * rho * rho), "A1": plain(r.A[0])}
    return SceneResult(model=model, state=_at_rest(q), quantities=quantities,
                       extra={"articulated": r, "effective_centre": np.array([d, 0.0])})
