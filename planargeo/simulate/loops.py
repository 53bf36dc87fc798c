"""Simulation of closed-loop mechanisms (thesis 9.5 in time; measured figures in ``docs/simulation.md``).

:func:`simulate_loops` integrates the accelerations of the constrained projective dynamics
(:func:`planargeo.algorithms.loops.loop_solve`) with :func:`planargeo.simulate.simulate`.  The
closures hold only at the acceleration level (``Bᵀ (G a - ν) = 0``, 9.55/9.60), so positions and
velocities drift: ``stabilization`` is ``"projection"`` onto the manifold after each accepted step
(:func:`project_state`, the default), ``"baumgarte"`` (:func:`baumgarte`), ``"both"`` or ``"none"``
(to see the drift).  The multistep ``"BDF"`` and ``"LSODA"`` take ``"baumgarte"`` or ``"none"``
only: each projection restarts them at order 1 with a tiny step (0.01 s of the crank took 10 785
LSODA steps against about 20 for DOP853).  Dead centres (``BᵀGΛ⁻¹GᵀB`` losing rank) are recorded
as events (:mod:`planargeo.simulate.integrate`).
"""
from __future__ import annotations

import math
from typing import Callable

import numpy as np

from planargeo.algorithms.crba import mass_matrix
from planargeo.algorithms.loops import loop_condition, loop_solve
from planargeo.algorithms.stacked import blocks
from planargeo.mechanics.contacts import contact_matrix, residual as contact_residual, stacked_contact_spaces, validate_contacts
from planargeo._validate import check_overflow, check_tolerance, overflow_checked
from planargeo.errors import InputError
from planargeo.geometry._docs import entries
from planargeo.mechanics.kinematics import kinematics
from planargeo.mechanics.model import Model, _finite_tuple, _positive
from planargeo.simulate.integrate import MAX_STEPS, MULTISTEP, SimulationResult, _count, simulate

__all__ = ["simulate_loops", "closure_residual", "closure_jacobian", "close_loops", "project_state", "baumgarte",
           "STABILIZATIONS", "LOOP_MAX_EVALS"]

STABILIZATIONS = ("projection", "baumgarte", "both", "none")

#: Default budget of a closed-loop run (``max_evals`` of :func:`simulate_loops`): evaluations of the
#: constrained dynamics, each about 0.5 ms for the slider-crank on a quiet core (with the projection),
#: so about 10 s of work; the 10 s crank run of ``docs/simulation.md`` takes 18 600.
LOOP_MAX_EVALS = 20_000

#: Docstring entries shared here (:func:`planargeo.geometry._docs.entries`).
_documented = entries({
    "model": "model : Model\n    The mechanism (a spanning tree).",
    "q": "q : array_like (nq,)\n    Joint coordinates.",
    "contacts": "contacts : sequence of Contact, optional\n    The loops' contacts (default ``model.contacts``).",
    "fixed": "fixed : sequence of int\n    Coordinates left unchanged (driven joints).",
    "tol": "tol, max_iter : float, int\n    Position tolerance; Gauss-Newton iterations at most.",
})


def _cs(model, contacts):
    return validate_contacts(model.contacts if contacts is None else contacts, model.N)


def _state(model, x, name: str) -> np.ndarray:
    """One state vector ``(nq,)`` of ``model`` (a fresh float array), or a named error."""
    return np.array(_finite_tuple(x, name, model.nq))


def _free(model, fixed) -> np.ndarray:
    """The coordinates not in ``fixed`` (indices into ``q``, checked)."""
    idx = list(fixed) if isinstance(fixed, (list, tuple, range, np.ndarray)) else None
    if idx is None or not all(isinstance(i, (int, np.integer)) and not isinstance(i, bool) and 0 <= i < model.nq
                              for i in idx):
        raise InputError(f"fixed must be indices into q in 0..{model.nq - 1}, got {fixed!r}")
    return np.setdiff1d(np.arange(model.nq), np.asarray(idx, dtype=int))


def _rates(alpha, beta) -> tuple[float, float]:
    """The Baumgarte rates (1/s), finite and non-negative."""
    return _positive(alpha, "alpha", strict=False), _positive(beta, "beta", strict=False)


@_documented
def closure_residual(model: Model, q, contacts=None) -> np.ndarray:
    """Position residuals ``φ(q)`` of all contacts, concatenated (thesis 9.54 in positions; zero when closed).

    ``φ`` resolves the relative pose of the contact frames along ``B`` (9.59-9.60): ``φ̇ = Bᵀ G v``.

    {parameters model q contacts}

    Returns
    -------
    ndarray
        One residual per constrained contact direction (m, rad).

    Examples
    --------
    >>> from planargeo.scenes.slider_crank import slider_crank_model, slider_crank_state
    >>> m = slider_crank_model(); q, _ = slider_crank_state()
    >>> bool(np.abs(closure_residual(m, q)).max() < 1e-14)
    True
    """
    cs = _cs(model, contacts)
    pose = kinematics(model, q).pose
    if not cs:
        return np.zeros(0)
    return np.concatenate([np.atleast_1d(contact_residual(c, pose)) for c in cs])


@_documented
def closure_jacobian(model: Model, q, contacts=None) -> np.ndarray:
    """Closure Jacobian ``J_c = B^T G J`` (``nc × nq``): ``φ̇ = J_c q̇`` on the manifold (thesis 9.54, 9.60).

    {parameters model q contacts}

    Returns
    -------
    ndarray (nc, nq)

    Examples
    --------
    >>> from planargeo.scenes.slider_crank import slider_crank_model, slider_crank_state
    >>> m = slider_crank_model(); q, qd = slider_crank_state()
    >>> bool(np.abs(closure_jacobian(m, q) @ qd).max() < 1e-12)
    True
    """
    cs = _cs(model, contacts)
    d = kinematics(model, q)
    if not cs:
        return np.zeros((0, model.nq))
    _, B = stacked_contact_spaces(cs, d.pose)
    Jb = np.concatenate([d.jacobian(i) for i in range(model.N)], 0)
    return B.T @ blocks(contact_matrix(cs, model.N)) @ Jb


def _weighted_correction(model, q, J, rhs, free):
    """``H^{-1} J^T (J H^{-1} J^T)^{-1} rhs`` restricted to the ``free`` coordinates."""
    H = mass_matrix(model, q)[np.ix_(free, free)]
    Jf = J[:, free]
    HiJt = np.linalg.solve(H, Jf.T)
    lam = np.linalg.lstsq(Jf @ HiJt, rhs, rcond=None)[0]
    out = np.zeros(model.nq)
    out[free] = HiJt @ lam
    return out


@overflow_checked("q")
@_documented
def close_loops(model: Model, q, contacts=None, *, fixed=(), tol: float = 1e-12, max_iter: int = 25):
    """Close the loops: Gauss-Newton ``q ← q - J_c^+ φ(q)`` until ``max |φ| < tol`` (thesis 9.54).

    The positions half of :func:`project_state`.

    {parameters model q contacts fixed tol}

    Returns
    -------
    q : ndarray (nq,)
        The closed configuration (``max |φ| < tol`` unless ``max_iter`` ran out).

    Raises
    ------
    InputError
        For a bad ``tol``, ``max_iter`` or ``fixed``.

    Examples
    --------
    >>> from planargeo.scenes.slider_crank import slider_crank_model, slider_crank_state
    >>> m = slider_crank_model(); q, _ = slider_crank_state()
    >>> q2 = close_loops(m, q + [0.0, 0.01, -0.02], fixed=[0])
    >>> bool(np.abs(closure_residual(m, q2)).max() < 1e-12), float(q2[0]) == float(q[0])
    (True, True)
    """
    q = _state(model, q, "q")
    tol = check_tolerance(tol, "tol")
    max_iter = _count(max_iter, "max_iter")
    cs = _cs(model, contacts)
    free = _free(model, fixed)
    if cs:
        for _ in range(max_iter):
            phi = closure_residual(model, q, cs)
            if np.abs(phi).max() < tol:
                break
            J = closure_jacobian(model, q, cs)[:, free]
            q[free] -= np.linalg.lstsq(J, phi, rcond=None)[0]
    return q


@overflow_checked("q or qd")
@_documented
def project_state(model: Model, q, qd, contacts=None, *, fixed=(), tol: float = 1e-12, max_iter: int = 25):
    """Project ``(q, q̇)`` onto the constraint manifold, positions then velocities (thesis 9.54, 9.58, 9.60).

    Positions by Gauss-Newton ``q ← q - J_c^+ φ(q)`` until ``max |φ| < tol``; velocities onto
    ``J_c q̇ = 0`` with the kinetic-energy metric ``H`` (as 9.56-9.58 project contact velocities).

    {parameters model q}
    qd : array_like (nq,)
        Joint velocities.
    {contacts fixed tol}

    Returns
    -------
    q, qd : ndarray (nq,)

    Raises
    ------
    InputError
        As :func:`close_loops`.

    Examples
    --------
    >>> from planargeo.scenes.slider_crank import slider_crank_model, slider_crank_state
    >>> m = slider_crank_model(); q, qd = slider_crank_state()
    >>> q2, qd2 = project_state(m, q + [0.0, 0.01, -0.02], qd + 1.0, fixed=[0])
    >>> bool(np.abs(closure_residual(m, q2)).max() < 1e-12), float(q2[0]) == float(q[0])
    (True, True)
    """
    q, qd = _state(model, q, "q"), _state(model, qd, "qd")
    q = close_loops(model, q, contacts, fixed=fixed, tol=tol, max_iter=max_iter)
    cs = _cs(model, contacts)
    if not cs:
        return q, qd
    free = _free(model, fixed)
    J = closure_jacobian(model, q, cs)
    qd = qd - _weighted_correction(model, q, J, J @ qd, free)
    return q, qd


@_documented
def baumgarte(model: Model, contacts=None, alpha: float = 5.0, beta: float = 5.0, *, fixed=()) -> Callable:
    """A ``stabilize(t, q, qd, qdd)`` hook enforcing ``φ̈ + 2αφ̇ + β²φ = 0`` (Baumgarte; thesis 9.69 stabilised).

    The loop algorithm's accelerations give ``φ̈ = 0`` (contact condition 9.68-9.69); the hook adds
    ``-H^{-1} J_c^T (J_c H^{-1} J_c^T)^{-1} (2α J_c q̇ + β² φ)``.

    {parameters model contacts}
    alpha, beta : float
        Damping and stiffness rates (1/s), non-negative.
    {fixed}

    Returns
    -------
    callable
        ``stabilize(t, q, qd, qdd) -> qdd`` for :func:`planargeo.simulate.simulate`.

    Examples
    --------
    Off the manifold the correction satisfies ``J_c Δq̈ = -(2α φ̇ + β² φ)``:

    >>> from planargeo.scenes.slider_crank import slider_crank_model, slider_crank_state
    >>> m = slider_crank_model(); q, qd = slider_crank_state()
    >>> q2 = q + [0.0, 1e-3, 0.0]
    >>> dqdd = baumgarte(m, alpha=5.0, beta=5.0)(0.0, q2, 0 * qd, np.zeros(3))
    >>> bool(np.allclose(closure_jacobian(m, q2) @ dqdd, -25.0 * closure_residual(m, q2)))
    True
    """
    cs = _cs(model, contacts)
    free = _free(model, fixed)
    alpha, beta = _rates(alpha, beta)

    def stabilize(t, q, qd, qdd):
        if not cs:
            return qdd
        phi = closure_residual(model, q, cs)
        J = closure_jacobian(model, q, cs)
        with np.errstate(over="ignore", invalid="ignore"):
            out = qdd - _weighted_correction(model, q, J, 2 * alpha * (J @ qd) + beta * beta * phi, free)
        return check_overflow(out, "baumgarte", "alpha or beta")

    return stabilize


@_documented
def simulate_loops(model: Model, q0, qd0, t_end, *, contacts=None, tau=None, f_ext=None,
                   method: str = "DOP853", rtol: float = 1e-8, atol: float = 1e-10, dt: float | None = None,
                   max_step: float = math.inf, stabilization: str = "projection", alpha: float = 5.0,
                   beta: float = 5.0, prescribed=None, tol: float = 1e-12, trigger: float = 1e-10,
                   project_initial: bool = True, watch: bool = True, cond_event: float = 1e6,
                   progress: bool | None = None, max_steps: int = MAX_STEPS,
                   max_evals: int | None = LOOP_MAX_EVALS) -> SimulationResult:
    """Integrate a closed-loop mechanism with stabilised loop closures (thesis 9.5, 9.65-9.75 in time).

    The accelerations come from the constrained algorithm (open-loop ``u`` 9.63, contact forces
    ``F = Γ(Gu - ν)`` 9.71, closed-loop ``a`` 9.73 and ``q̈`` 9.75); the chosen ``stabilization``
    keeps positions and velocities on the manifold (module docstring).

    Parameters
    ----------
    model : Model
        Spanning tree; ``model.contacts`` closes the loops unless ``contacts`` is given.
    q0, qd0 : array_like (nq,)
        Initial state (projected onto the manifold first when ``project_initial``, unless ``"none"``).
    t_end : float
        Final time (s).
    {contacts}
    tau, f_ext, method, rtol, atol, dt, max_step, cond_event, progress, max_steps
        As for :func:`planargeo.simulate.simulate`.
    stabilization : {"projection", "baumgarte", "both", "none"}
        ``"BDF"`` and ``"LSODA"`` take ``"baumgarte"`` or ``"none"`` (module docstring).
    alpha, beta : float
        Baumgarte parameters (1/s).
    prescribed : dict {joint: qdd}, optional
        Driven joints (e.g. ``{0: 0.0}``: a crank at constant speed), left alone by the projection.
    tol, trigger : float
        Position tolerance of the projection; it runs only when a residual exceeds ``trigger``.
    project_initial : bool
        Project ``(q0, qd0)`` onto the manifold before starting.
    watch : bool
        Record ``cond(BᵀGΛ⁻¹GᵀB)`` (9.70-9.72) per step and its near-singular events.
    max_evals : int or None
        Budget of evaluations of the constrained dynamics (default :data:`LOOP_MAX_EVALS`).

    Returns
    -------
    SimulationResult
        ``residual`` holds ``[φ(q), J_c q̇]`` per recorded step; ``extra["position_residual"]``,
        ``extra["velocity_residual"]`` their maxima, ``extra["n_position"]`` the count of ``φ``.

    Raises
    ------
    InputError
        An unknown ``stabilization``, a projection with a multistep method, negative
        ``alpha``/``beta``, bad tolerances, or ``prescribed`` not a dict of joint indices.

    Examples
    --------
    >>> from planargeo.scenes.slider_crank import slider_crank_model, slider_crank_state
    >>> m = slider_crank_model(); q, qd = slider_crank_state()
    >>> r = simulate_loops(m, q, qd, 0.02, rtol=1e-8)
    >>> r.status, bool(r.extra["position_residual"].max() < 1e-10)
    ('ok', True)
    """
    if stabilization not in STABILIZATIONS:
        raise InputError(f"stabilization must be one of {list(STABILIZATIONS)}, got {stabilization!r}")
    if method in MULTISTEP and stabilization in ("projection", "both"):
        raise InputError(f"stabilization={stabilization!r} cannot be used with method {method!r}: each projection "
                         "restarts a multistep method at order 1 with a tiny step; use stabilization='baumgarte' "
                         "(or 'none') with it, or a one-step method (DOP853, RK45, RK23, Radau, RK4)")
    alpha, beta = _rates(alpha, beta)
    tol, trigger = check_tolerance(tol, "tol"), check_tolerance(trigger, "trigger")
    q0, qd0 = _state(model, q0, "q0"), _state(model, qd0, "qd0")
    cs = _cs(model, contacts)
    fixed = []
    if prescribed is not None and not isinstance(prescribed, dict):
        raise InputError(f"prescribed must be a dict {{joint: qdd}} or None, got {prescribed!r}")
    if prescribed:
        for i in prescribed:
            if not (isinstance(i, (int, np.integer)) and 0 <= i < model.N):
                raise InputError(f"prescribed keys must be joint indices in 0..{model.N - 1}, got {i!r}")
            fixed.extend(range(model.q_slice(i).start, model.q_slice(i).stop))

    last = {}                                  # cond(BᵀGΛ⁻¹GᵀB) of the last state solved

    def forward(m, q, qd, ta, fe):
        sol = loop_solve(m, q, qd, ta, fe, cs, prescribed=prescribed)
        last["q"], last["cond"] = np.array(q, dtype=float), sol.cond
        return sol.qdd

    def condition(q, qd):
        # The adaptive methods evaluate the dynamics at the accepted state last (FSAL): reuse its
        # cond, also after a projection that moved q by |Δq| with cond |Δq| < 1e-8 (K depends on q
        # only and smoothly: the relative change of cond is about cond |Δq| per unit length).
        if "q" in last and np.abs(last["q"] - q).max() * last["cond"] < 1e-8:
            return last["cond"]
        c = loop_condition(model, q, cs, prescribed=prescribed)
        last["q"], last["cond"] = np.array(q, dtype=float), c
        return c

    def resid(q, qd):
        return np.concatenate([closure_residual(model, q, cs), closure_jacobian(model, q, cs) @ qd])

    def project(q, qd):
        # on demand: leave the state untouched (no integrator restart) while the
        # residuals are below ``trigger``; otherwise project to ``tol``
        r = resid(q, qd)
        if r.size == 0 or np.abs(r).max() <= trigger:
            return q, qd
        return project_state(model, q, qd, cs, fixed=fixed, tol=tol)

    if project_initial and stabilization != "none":
        q0, qd0 = project_state(model, q0, qd0, cs, fixed=fixed, tol=tol)
    res = simulate(model, q0, qd0, t_end, tau=tau, f_ext=f_ext, method=method, rtol=rtol, atol=atol, dt=dt,
                   max_step=max_step, forward=forward,
                   stabilize=(baumgarte(model, cs, alpha, beta, fixed=fixed)
                              if stabilization in ("baumgarte", "both") else None),
                   project=project if stabilization in ("projection", "both") else None, residual=resid,
                   condition=condition if watch else None, cond_event=cond_event, progress=progress,
                   max_steps=max_steps, max_evals=max_evals)
    npos = sum(c.nc for c in cs)
    R = res.residual if res.residual is not None else np.zeros((len(res.t), 0))
    res.extra["n_position"] = npos
    res.extra["position_residual"] = np.abs(R[:, :npos]).max(axis=1) if npos else np.zeros(len(res.t))
    res.extra["velocity_residual"] = np.abs(R[:, npos:]).max(axis=1) if npos else np.zeros(len(res.t))
    res.extra["stabilization"] = stabilization
    return res
