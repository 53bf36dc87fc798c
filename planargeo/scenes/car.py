"""Scene ``car``: a car cornering and accelerating, solved by projective dynamics (thesis 6.9).

With its steering fixed the car turns about the instant centre of rotation (ICR), where the
rear- and front-axle lines meet: a revolute joint ``s`` at the ICR (6.114) whose reactions are
the two lateral tyre forces.  World frame: ICR at the origin, rear contact ``(d, 0)``, front
contact ``(d, L)``, heading +y (``d > 0``: a left turn), centre of gravity ``ε L`` behind the
front axle.  Solved through :mod:`planargeo.mechanics.subspaces` as in the thesis: ``T``
(6.124), ``U`` (6.126), ``γ = Rᵀκ`` (6.128), ``ω̇ = Tᵀ I⁻¹ (T Q − d)`` (6.107, 6.130),
``μ = Uᵀ I U γ + Uᵀ d`` (6.106a, 6.132); negative ``μ`` push the car towards the ICR.
"""
from __future__ import annotations

import numpy as np

from planargeo.mechanics.joints import _force_through, revolute
from planargeo.mechanics.model import Body, Joint, Model
from planargeo.screws.twists import crf, crm, inertia_matrix
from planargeo.mechanics.subspaces import Decomposition
from planargeo.errors import SceneError
from planargeo.scenes import SceneResult, register

__all__ = ["car"]


@register("car", checks={"m": "positive", "rho": "positive", "L": "positive", "outlines": None})
def car(m: float = 1200.0, rho: float = 1.2, L: float = 2.6, d: float = 8.0, eps: float = 0.45,
        omega: float = 0.5, F_A: float = 2000.0, outlines: bool = True) -> SceneResult:
    """Car cornering and accelerating at the same time (thesis 6.9, 6.114–6.133).

    Parameters
    ----------
    m, rho, L : float
        Mass [kg], radius of gyration about the centre of gravity [m] and wheelbase [m] (> 0).
    d, eps : float
        Radius of the turn at the rear axle [m]; centre of gravity behind the front axle, per ``L``.
    omega, F_A : float
        Yaw rate about the ICR [rad/s]; drive force at the front tyres, along their rolling [N].
    outlines : bool
        Build the shapely outlines (body ``shape``, ``extra["tyres"]``; only Fig 6.6 draws them).
        A drawing option, not in ``params``; every other output is the same without.

    Returns
    -------
    SceneResult
        ``quantities`` at the ICR: ``omega_dot`` (6.131), ``mu`` = [rear, front] (6.133), ``T``
        (6.125), ``U`` (6.127), ``s``, ``R`` (6.114), ``I`` (6.117), ``v`` (6.115), ``kappa``
        (6.116), ``p`` (6.119), ``f_A`` (6.120), ``gamma`` (6.129), ``a``, ``f`` (6.122), ``V``.
        ``extra``: the geometry for drawing.  ``state`` has ``f_ext = [f_A]``, so any
        forward-dynamics function on ``model`` reproduces ``omega_dot``.

    Raises
    ------
    SceneError
        A parameter not a finite number (``m``, ``rho``, ``L`` not positive), or ``outlines`` not a bool.

    Examples
    --------
    >>> res = car()
    >>> round(res.quantities["omega_dot"], 4), [round(x, 1) for x in res.quantities["mu"]]
    (0.2077, [-1102.4, -1089.3])
    """
    if not isinstance(outlines, (bool, np.bool_)):
        raise SceneError(f"outlines must be True or False, got {outlines!r}")

    # --- model-less geometry
    icr = np.zeros(2)
    rear = np.array([d, 0.0])
    front = np.array([d, L])
    cg = np.array([d, (1.0 - eps) * L])
    hyp = np.hypot(d, L)
    rear_axle = np.array([1.0, 0.0])
    front_axle = np.array([d, L]) / hyp
    front_rolling = np.array([-L, d]) / hyp

    joint = revolute(icr)                                                     # (6.114)
    s = joint.s
    R = np.stack([_force_through(rear, rear_axle), _force_through(front, front_axle)], axis=-1)  # (6.114)

    # --- dynamics quantities at the ICR
    I = inertia_matrix(m, cg, m * rho ** 2)                                   # (6.117)
    qd = np.array([omega])
    v = s @ qd                                                                # (6.115)
    kappa = crm(v) @ (s @ qd)                                                 # (6.116)
    p = crf(v) @ (I @ v)                                                      # (6.118)-(6.119)
    f_A = F_A * _force_through(front, front_rolling)                         # (6.120)

    dec = Decomposition(I, s, R, name="I")                                    # T (6.124), U (6.126)
    T, U = dec.T, dec.U
    gamma = R.T @ kappa                                                       # (6.128)
    Q = np.zeros(1)                                                           # unpowered joint
    bias = p - f_A                                                            # f = I a + bias (6.122)
    psi = T.T @ np.linalg.solve(I, T @ Q - bias)                              # (6.107), (6.130)
    mu = U.T @ I @ U @ gamma + U.T @ bias                                     # (6.106a), (6.132)
    a = dec.join_twist(psi, gamma)                                            # (6.44)
    f = dec.join_wrench(Q, mu)                                                # (6.38), (6.123)

    quantities = {
        "omega_dot": float(psi[0]), "mu": mu.tolist(), "T": T[:, 0].tolist(), "U": U.tolist(),
        "s": s[:, 0].tolist(), "R": R.tolist(), "I": I.tolist(), "v": v.tolist(), "kappa": kappa.tolist(),
        "p": p.tolist(), "f_A": f_A.tolist(), "gamma": gamma.tolist(), "a": a.tolist(), "f": f.tolist(),
        "V": omega * d,
    }
    extra = {
        "icr": icr, "rear_contact": rear, "front_contact": front, "cg": cg,
        "heading": np.array([0.0, 1.0]), "rear_axle": rear_axle, "front_axle": front_axle,
        "front_rolling": front_rolling, "steer": float(np.arctan2(L, d)),
        "joint": joint, "s": s, "R": R, "T": T, "U": U,
        "tyre_wrenches": R * mu, "decomposition": dec,
    }
    body_shape = None
    if outlines:      # body (its frame = world frame at q = 0) and tyres: only Fig 6.6 reads them
        from shapely import affinity
        from shapely.geometry import box

        w, over = 0.7 * L, 0.3 * L
        body_shape = box(d - w / 2, -over, d + w / 2, L + over)
        tyre = box(-0.06 * L, -0.13 * L, 0.06 * L, 0.13 * L)
        steered = affinity.rotate(tyre, extra["steer"], origin=(0, 0), use_radians=True)
        extra["tyres"] = [affinity.translate(tyre, d, 0.0), affinity.translate(steered, d, L)]
    model = Model([Body(m, com=tuple(cg), inertia=m * rho ** 2, shape=body_shape, name="car")],
                  [Joint("revolute", (0.0, 0.0, 0.0), name="icr")], [-1], gravity=(0.0, 0.0))
    state = {"q": [0.0], "qd": [omega], "tau": [0.0], "f_ext": [f_A.tolist()], "omega": omega}
    return SceneResult(model=model, state=state, quantities=quantities, extra=extra)
