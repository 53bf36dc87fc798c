"""Scene ``mobility-example``: articulated mobility of a pinned two-body chain (thesis 7.5, Figure 7.9).

The bodies of :mod:`~planargeo.scenes.two_body`, pinned at the origin, at rest, no gravity.  A
pure couple ``f_3 = [0, 0, tau]`` (7.44) on body 2 accelerates it by ``a_2 = -Lambda_2^-1 f_3``
(7.45; mobility of 7.38a), a rotation about ``(x, 0)`` with (7.47, by hand, ``eta = L / rho``)
``x / L = 1 + 2 eta^2 cos(phi) / (4 + 5 eta^2)``.

Examples
--------
>>> from planargeo import scenes
>>> q = scenes.build("mobility-example", phi=np.pi / 2).quantities
>>> round(q["x_over_L"], 12)               # at phi = 90 degrees: the joint of body 2
1.0
"""
from __future__ import annotations

import numpy as np

from planargeo.scenes import SceneResult, _at_rest, plain, register
from planargeo.scenes.two_body import two_body_model

__all__ = ["mobility_example"]


@register("mobility-example", checks={"m": "positive", "rho": "positive", "L": "positive",
                                      "tau": "nonzero"})    # a zero couple has no instant centre
def mobility_example(m: float = 1.0, rho: float = 0.5, L: float = 1.0, phi: float = np.pi / 4,
                     tau: float = 1.0) -> SceneResult:
    """A pure couple on the tip of a pinned two-body chain (thesis 7.5, 7.40-7.49).

    Parameters
    ----------
    m, rho, L : float
        Mass, radius of gyration and length of each body (> 0).
    phi : float
        Angle of body 2 relative to body 1 [rad].
    tau : float
        The pure couple ``f_3 = [0, 0, tau]`` (non-zero).

    Returns
    -------
    SceneResult
        ``Lambda1_inv`` (7.42), ``Lambda2_inv`` (7.43), ``f3`` (7.44), ``a2`` (7.46), ``x_over_L``
        (7.48), ``eta`` (7.49), ``T1``, ``U1`` (7.40), ``T2``, ``U2`` (7.41).

    Examples
    --------
    >>> r = mobility_example(phi=0.0)
    >>> round(r.quantities["x_over_L"], 12)    # 1 + 2*4/(4 + 20)
    1.333333333333
    """
    from planargeo.algorithms.articulated_mobility import articulated_mobility
    model = two_body_model(m, rho, L)
    q = np.array([0.0, phi])
    r = articulated_mobility(model, q)
    f3 = np.array([0.0, 0.0, tau])
    a2 = -r.Lambda_inv[1] @ f3 + r.b[1]                                   # (7.37), (7.45)
    quantities = {
        "Lambda1_inv": plain(r.Lambda_inv[0]), "Lambda2_inv": plain(r.Lambda_inv[1]), "f3": plain(f3),
        "a2": plain(a2), "x_over_L": float(-a2[1] / (L * a2[2])), "eta": L / rho,      # x/L: (7.47)
        "T1": plain(r.T[0][:, 0]), "U1": plain(r.U[0]), "T2": plain(r.T[1][:, 0]), "U2": plain(r.U[1]),
    }
    return SceneResult(model=model, state=_at_rest(q), quantities=quantities,
                       extra={"mobility": r, "instant_centre": np.array([-a2[1] / a2[2], 0.0])})
