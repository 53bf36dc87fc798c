"""Scene "slider-crank": the constrained example of thesis 9.6 (Fig 9.3).

Crank (body 1) about the origin by ``ψ``, rod (body 2) by ``θ``, piston (body 3) by ``φ``; a
slider keeps the piston on the vertical through the crank pivot (``ψ + θ + φ = π/2``,
``r cos ψ + l cos(ψ + θ) = 0``, branch ``sin(ψ + θ) ≥ 0``).  Defaults are the thesis's; ``g``
(not stated there) is a parameter.  Erratum (``docs/errata.md``): the printed state (9.78, 9.79)
has ``θ = 1.603`` (the loop closes at 1.6063) and the signs of ``θ̇``, ``φ̇`` inverted.

Examples
--------
>>> res = slider_crank()
>>> [round(x, 4) for x in res.state["q"]]
[0.4, 1.6063, -0.4355]
"""
from __future__ import annotations

import numpy as np

from planargeo.errors import COND_LIMIT, PlanargeoError, SceneError, SingularConfigurationError
from planargeo.scenes import SceneResult, check_param, register

__all__ = ["slider_crank", "slider_crank_model", "slider_crank_solve", "slider_crank_state", "slider_crank_advance",
           "slider_crank_reactions",
           "dead_centre_at", "dead_centres_passed", "DEAD_CENTRES", "DEAD_CENTRE_TOL"]

#: The crank angles ``ψ`` (rad) at which crank and rod lie in line with the slide (the y axis through the
#: crank pivot, Fig 9.3): the toggle positions, where a force on the piston cannot turn the crank.
DEAD_CENTRES = {"top dead centre": np.pi / 2, "bottom dead centre": -np.pi / 2}
#: ``|cos ψ|`` below which the crank is said to be at a dead centre.
DEAD_CENTRE_TOL = 0.02


def slider_crank_model(m1=0.40, m2=0.15, m3=0.30, r=2.29, l=5.00, t=0.5, g=9.81):
    """The slider-crank :class:`~planargeo.mechanics.model.Model` (tree + one slider contact) of thesis 9.6.

    Parameters
    ----------
    m1, m2, m3 : float, optional
        Masses of crank, connecting rod and slider (kg).
    r, l, t : float, optional
        Crank and rod lengths; piston joint to its centre of mass and slider contact (m).
    g : float, optional
        Gravity along -y (m/s²).

    Returns
    -------
    Model
    """
    from planargeo.mechanics.contacts import Contact
    from planargeo.mechanics.model import Body, Joint, Model

    m1, m2, m3, r, l, t = (check_param(name, val, positive=True) for name, val in
                           (("m1", m1), ("m2", m2), ("m3", m3), ("r", r), ("l", l), ("t", t)))
    g = check_param("g", g)
    bodies = [
        Body(m1, (r / 4, 0.0), 0.1464 * m1 * r * r, name="crank"),
        Body(m2, (l / 2, 0.0), 0.0866 * m2 * l * l, name="rod"),
        Body(m3, (t, 0.0), 0.666 * m3 * t * t, name="piston"),
    ]
    joints = [Joint("revolute", (0.0, 0.0, 0.0), name="psi"),
              Joint("revolute", (r, 0.0, 0.0), name="theta"),
              Joint("revolute", (l, 0.0, 0.0), name="phi")]
    slider = Contact("slider", 2, -1, point_a=(t, 0.0), point_b=(0.0, 0.0), direction=(0.0, 1.0),
                     angle=np.pi / 2, name="piston slider")
    return Model(bodies, joints, [-1, 0, 1], gravity=(0.0, -float(g)), contacts=(slider,))


def slider_crank_state(psi=0.4, psidot=20.0, r=2.29, l=5.00):
    """Joint coordinates and rates closing the loop (assembly branch ``sin(ψ+θ) ≥ 0``).

    Parameters
    ----------
    psi, psidot : float, optional
        Crank angle ψ (rad) and speed (rad/s).
    r, l : float, optional
        Crank and rod lengths (m).

    Returns
    -------
    q, qd : ndarray, shape (3,)

    Raises
    ------
    SceneError
        The rod cannot reach the piston line (``l < r |cos ψ|``), or a bad parameter.
    SingularConfigurationError
        The rod lies along the horizontal (``l = r |cos ψ|``): ``θ̇`` is undetermined.

    Examples
    --------
    >>> q, qd = slider_crank_state()
    >>> np.round(qd, 4)
    array([ 20.    , -23.9343,   3.9343])
    """
    psi, psidot = check_param("psi", psi), check_param("psidot", psidot)
    r, l = check_param("r", r, positive=True), check_param("l", l, positive=True)
    c = -r * np.cos(psi) / l
    if abs(c) > 1.0:
        raise SceneError(
            f"rod too short: l = {l:g} cannot reach the piston line x = 0 from the crank pin at "
            f"x = r cos ψ = {r * np.cos(psi):.4g} m (need l ≥ r |cos ψ|)")
    beta = float(np.arccos(c))          # psi + theta, in [0, pi]: piston above the crank pin
    theta = beta - psi
    phi = np.pi / 2 - beta
    sb = np.sin(beta)
    Jdep = np.array([[-l * sb, 0.0], [1.0, 1.0]])     # d(closure)/d(theta, phi)
    cond = np.linalg.cond(Jdep)
    if not np.isfinite(cond) or cond > COND_LIMIT:
        raise SingularConfigurationError(
            "slider-crank loop closure is singular (rod along the horizontal): the rod's turning rate θ̇ "
            "is undetermined", cond)
    wrod = -r * np.sin(psi) * psidot / (l * sb)         # psidot + thetadot
    q = np.array([psi, theta, phi])
    qd = np.array([psidot, wrod - psidot, -wrod])
    return q, qd


def slider_crank_solve(model, psi, psidot, r, l, t, drive="free"):
    """Close the loop at crank angle ``psi`` and solve it with the constrained algorithm (9.5).

    Parameters
    ----------
    model : Model
        :func:`slider_crank_model` built with the same ``r``, ``l``, ``t``.
    psi, psidot : float
        Crank angle and speed.
    r, l, t : float
        Crank, rod and piston lengths (thesis 9.6).
    drive : {"free", "constant-speed"}
        ``"constant-speed"`` prescribes ``ψ̈ = 0`` (torque needed: ``sol.tau_drive``).

    Returns
    -------
    q, qd : ndarray
        Joint coordinates and rates closing the loop.
    sol : LoopSolution
        From :func:`~planargeo.algorithms.loops.loop_solve`.
    h : float
        Piston height (9.85).

    Raises
    ------
    SceneError
        The rod cannot reach the piston line.
    SingularConfigurationError
        The loop closure is singular (rod along the horizontal; with the piston pin on the
        crank pivot the message says so, with the contact matrix's condition).

    Examples
    --------
    >>> q, qd, sol, h = slider_crank_solve(slider_crank_model(), 0.4, 20.0, 2.29, 5.0, 0.5)
    >>> round(h, 3)
    5.925
    """
    from planargeo.algorithms.loops import SINGULAR_COND, loop_condition, loop_solve

    try:
        q, qd = slider_crank_state(psi, psidot, r, l)
    except SingularConfigurationError:
        # the rod lies along the horizontal: if the piston pin is then on the crank pivot (l = r at a dead
        # centre, the folded crank), the contact matrix is singular too: report that, with its condition
        beta = 0.0 if -r * np.cos(psi) / l > 0 else np.pi
        cond = loop_condition(model, [psi, beta - psi, np.pi / 2 - beta])
        if not cond <= SINGULAR_COND:
            raise SingularConfigurationError(
                f"singular configuration: slider-crank at a dead centre with the piston pin on the crank pivot "
                f"(l = r = {l:g} m, ψ = {np.degrees(psi):.4g}°): the contact matrix Bᵀ G Λ⁻¹ Gᵀ B of the piston slider "
                f"is singular and the rod's turning rate θ̇ undetermined", cond) from None
        raise
    sol = loop_solve(model, q, qd, np.zeros(3), prescribed={0: 0.0} if drive == "constant-speed" else None)
    h = r * np.sin(q[0]) + l * np.sin(q[0] + q[1]) + t * np.sin(q.sum())     # (9.85)
    return q, qd, sol, float(h)


def _tolist(x):
    return np.asarray(x, dtype=float).tolist()


@register("slider-crank", checks={**{k: "positive" for k in ("m1", "m2", "m3", "r", "l", "t")},
                                  "drive": ("free", "constant-speed")})
def slider_crank(psi: float = 0.4, psidot: float = 20.0, m1: float = 0.40, m2: float = 0.15,
                 m3: float = 0.30, r: float = 2.29, l: float = 5.00, t: float = 0.5, g: float = 9.81,
                 drive: str = "free") -> SceneResult:
    """Slider-crank of thesis 9.6 solved with the constrained algorithm (9.5).

    Parameters
    ----------
    psi, psidot : float
        Crank angle ψ (rad) and speed ψ̇ (rad/s).
    m1, m2, m3, r, l, t, g : float
        As for :func:`slider_crank_model`.
    drive : {"free", "constant-speed"}
        No crank torque, or the crank driven at ``ψ̈ = 0`` (torque needed: ``tau_drive``).

    Returns
    -------
    SceneResult
        ``q``, ``qd``, ``v`` (9.80), ``u`` (9.82), ``Lambda3_inv`` (9.81), ``h`` (9.86), ``z3``,
        ``B3`` (9.87), ``xi`` (9.90), ``F3`` (9.92), ``a3`` (9.94), ``a``, ``qdd``, ``tau_drive``,
        and every pin and bearing force (9.61): ``f``, ``mu`` (6.61b), ``pin_forces``,
        ``reaction_moments``.
    """
    model = slider_crank_model(m1, m2, m3, r, l, t, g)
    q, qd, sol, h = slider_crank_solve(model, psi, psidot, r, l, t, drive)
    tau = np.zeros(3)
    v = sol.data.v
    quantities = {
        "q": _tolist(q), "qd": _tolist(qd), "v": _tolist(v),
        "u": _tolist(sol.u.reshape(3, 3)),
        "Lambda3_inv": _tolist(sol.Lambda_inv[6:9, 6:9]),
        "h": float(h),
        "z3": _tolist(sol.z[:, 0]), "B3": _tolist(sol.B),
        "xi": _tolist(sol.xi), "F3": _tolist(sol.F),
        "a3": _tolist(sol.a[6:9]), "a": _tolist(sol.a.reshape(3, 3)),
        "qdd": _tolist(sol.qdd), "tau_drive": _tolist(sol.tau_drive),
        "cond": float(sol.cond),
        # every pin and bearing force of the loop (9.61): f_i on body i from its parent, -F_1 on the piston
        "f": _tolist(sol.f.reshape(3, 3)), "mu": _tolist(sol.mu),
        "pin_forces": {r.symbol: _tolist(r.wrench) for r in sol.reactions},
        "reaction_moments": {r.symbol: float(r.moment) for r in sol.reactions},
    }
    return SceneResult(model=model, state={"q": _tolist(q), "qd": _tolist(qd), "tau": _tolist(tau)},
                       quantities=quantities, extra={"solution": sol})


def dead_centre_at(psi, tol: float = DEAD_CENTRE_TOL) -> str:
    """The name of the dead centre the crank is at (``|cos ψ| < tol``), or ``""``.

    Parameters
    ----------
    psi : float
        Crank angle (rad), any turn.
    tol : float
        Threshold on ``|cos ψ|``.

    Returns
    -------
    str

    Examples
    --------
    >>> dead_centre_at(np.pi / 2 + 2 * np.pi), dead_centre_at(-np.pi / 2 + 0.01), dead_centre_at(0.4)
    ('top dead centre', 'bottom dead centre', '')
    """
    psi = float(psi)
    if abs(np.cos(psi)) >= tol:
        return ""
    return "top dead centre" if np.sin(psi) > 0 else "bottom dead centre"


def dead_centres_passed(psi0, psi1) -> list:
    """The dead centres the crank passes turning from ``psi0`` to ``psi1`` (unwrapped angles), in the order passed.

    One exactly at ``psi1`` counts, one at ``psi0`` does not (consecutive frames never repeat one).

    Parameters
    ----------
    psi0, psi1 : float
        Crank angles (rad) before and after, not wrapped (``psi1 - psi0`` is the turn).

    Returns
    -------
    list of (str, float)
        Name (:data:`DEAD_CENTRES`) and the unwrapped angle at which it was passed.

    Examples
    --------
    >>> dead_centres_passed(2.0, 1.0)
    [('top dead centre', 1.5707963267948966)]
    """
    a, b = float(psi0), float(psi1)
    lo, hi = min(a, b), max(a, b)
    found = []
    for name, c in DEAD_CENTRES.items():
        k = np.ceil((lo - c) / (2 * np.pi))
        while c + 2 * np.pi * k <= hi:
            x = c + 2 * np.pi * k
            if (b > a and a < x <= b) or (b < a and b <= x < a):
                found.append((name, float(x)))
            k += 1
    return sorted(found, key=lambda nx: nx[1], reverse=b < a)


def slider_crank_advance(model, psi, psidot, dt, r=2.29, l=5.00, drive="free", *, rtol=1e-8, atol=1e-10):
    """Integrate the slider-crank over ``dt`` seconds from crank state ``(ψ, ψ̇)`` with :func:`simulate_loops`.

    The constrained algorithm (9.5) with the closures projected; the explorer's Play step.

    Parameters
    ----------
    model : Model
        :func:`slider_crank_model` with the same ``r``, ``l``.
    psi, psidot, dt : float
        Crank angle (rad) and speed (rad/s) at the start; duration (s, > 0).
    r, l, drive : float, float, str
        Crank and rod lengths; the drive, as for :func:`slider_crank`.
    rtol, atol : float
        Integrator tolerances (DOP853).

    Returns
    -------
    dict
        ``psi`` (unwrapped), ``psidot``, ``position_residual``, ``velocity_residual`` (largest
        closure drift), ``dead_centres``, ``events``, ``nfev``, ``status``.

    Raises
    ------
    SceneError
        ``dt`` not positive, or the rod cannot reach the piston line.
    SingularConfigurationError
        The start is singular.
    PlanargeoError
        The integration stops at a singular configuration.

    Examples
    --------
    >>> m = slider_crank_model()
    >>> out = slider_crank_advance(m, 0.4, 20.0, 0.01)
    >>> out["status"], bool(out["position_residual"] < 1e-9), bool(0.5 < out["psi"] < 0.7)
    ('ok', True, True)
    """
    from planargeo.simulate.loops import simulate_loops

    dt = check_param("dt", dt, positive=True)
    drive = check_param("drive", drive, "choice", choices=("free", "constant-speed"))
    q, qd = slider_crank_state(psi, psidot, r, l)
    res = simulate_loops(model, q, qd, dt, rtol=rtol, atol=atol, progress=False,
                         prescribed={0: 0.0} if drive == "constant-speed" else None)
    if res.status != "ok":
        raise PlanargeoError(f"the simulation stopped at t = {res.t[-1]:.4g} s: {res.message}")
    psi1, psidot1 = float(res.q[-1][0]), float(res.qd[-1][0])
    return {"psi": psi1, "psidot": psidot1,
            "position_residual": float(np.max(res.extra["position_residual"], initial=0.0)),
            "velocity_residual": float(np.max(res.extra["velocity_residual"], initial=0.0)),
            "dead_centres": dead_centres_passed(psi, psi1), "events": list(res.events), "nfev": int(res.nfev),
            "status": res.status}


def slider_crank_reactions(sol) -> dict:
    """Every pin and bearing force of a solved slider-crank, by symbol (thesis 9.61, 9.71).

    Parameters
    ----------
    sol : LoopSolution
        From :func:`slider_crank_solve`.

    Returns
    -------
    dict
        ``{"f_1": Reaction, ..., "F_1": Reaction}`` (:class:`planargeo.algorithms.loops.Reaction`).

    Examples
    --------
    >>> _q, _qd, sol, _h = slider_crank_solve(slider_crank_model(), 0.4, 20.0, 2.29, 5.0, 0.5)
    >>> sorted(slider_crank_reactions(sol)), round(slider_crank_reactions(sol)["F_1"].moment, 3)
    (['F_1', 'f_1', 'f_2', 'f_3'], -11.961)
    """
    return {r.symbol: r for r in sol.reactions}
