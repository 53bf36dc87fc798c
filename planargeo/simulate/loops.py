"""Simulation of closed-loop mechanisms (thesis 9.5 integrated in time).

:func:`simulate_loops` integrates the accelerations of the constrained
projective dynamics algorithm (:func:`planargeo.algorithms.loops.loop_solve`)
with :func:`planargeo.simulate.simulate`.  The loop closures hold exactly
only at the acceleration level (``B^T (G a - ν) = 0``, 9.55/9.60), so the
positions and velocities drift; two documented stabilisations are offered:

``"projection"`` (default)
    After every accepted step the state is pulled back onto the constraint
    manifold: positions by Gauss-Newton iterations
    ``q ← q - J_c^+ φ(q)`` until ``|φ| < tol``, then velocities by the
    mass-weighted (kinetic-energy-minimal) projection
    ``q̇ ← q̇ - H^{-1} J_c^T (J_c H^{-1} J_c^T)^{-1} J_c q̇``.
    ``φ`` are the contacts' position residuals (:func:`planargeo.mechanics.contacts.residual`)
    and ``J_c = B^T G J`` the closure Jacobian (``J`` the stacked body
    Jacobians; ``J_c`` is the exact derivative of ``φ`` on the manifold).
``"baumgarte"``
    The accelerations are corrected so that
    ``φ̈ + 2 α φ̇ + β² φ = 0``: ``q̈ ← q̈ - H^{-1} J_c^T (J_c H^{-1} J_c^T)^{-1} (2 α φ̇ + β² φ)``
    (parameters ``alpha``, ``beta`` in 1/s; critically damped for ``alpha = beta``).
``"both"``, ``"none"``
    Both corrections, or neither (to see the drift).

Diagnostics per recorded step (``result.residual`` columns and ``result.extra``):
energy (kinetic + gravitational; conserved for a free mechanism without
drives), the position residuals ``φ`` and the velocity residuals ``J_c q̇``.

Documented tolerances (``docs/simulation.md``, the figures the tests assert):
slider-crank of 9.6, free crank, g = 9.81, 10 s (44 crank turns), DOP853
with ``rtol = 1e-7``, ``atol = 1e-9``, projection triggered above 1e-10:
position and velocity residuals below 1e-9 (measured 8.6e-11 and 1.0e-10,
the trigger), relative energy drift below 2e-5 (measured 4.1e-6; 6.9e-7 at
``rtol = 1e-8``), 18 600 dynamics evaluations.  Without stabilisation the
position residual reaches 4e-6 after 1 s at that tolerance.

Integrators: every method of :func:`planargeo.simulate.simulate`.  The
multistep ``"BDF"`` and ``"LSODA"`` take ``"baumgarte"`` or ``"none"`` only:
each projection restarts them at order 1 with a tiny step (measured on the
crank at ``rtol = 1e-8``: 0.01 s took 10 785 LSODA steps and 19 741 BDF steps,
against about 20 for DOP853), so ``"projection"`` and ``"both"`` raise
:class:`~planargeo.errors.InputError` with them.

Singular configurations (a dead centre where ``BᵀGΛ⁻¹GᵀB`` loses rank) are
watched and recorded as events (``result.cond``, ``result.events``; see
:mod:`planargeo.simulate.integrate`).
"""
from __future__ import annotations

import math
from typing import Callable

import numpy as np

from planargeo.algorithms.loops import loop_condition, loop_solve
from planargeo.algorithms.stacked import blocks
from planargeo.mechanics.contacts import contact_matrix, residual as contact_residual, stacked_contact_spaces, validate_contacts
from planargeo._validate import as_array, as_scalar, check_overflow, check_tolerance, overflow_checked
from planargeo.errors import InputError, ShapeError
from planargeo.mechanics.kinematics import kinematics
from planargeo.mechanics.model import Model
from planargeo.simulate.integrate import MAX_STEPS, MULTISTEP, SimulationResult, simulate

__all__ = ["simulate_loops", "closure_residual", "closure_jacobian", "project_state", "baumgarte",
           "STABILIZATIONS", "LOOP_MAX_EVALS"]

STABILIZATIONS = ("projection", "baumgarte", "both", "none")

#: Default budget of a closed-loop run (``max_evals`` of :func:`simulate_loops`): evaluations of the
#: constrained dynamics, each about 0.5 ms for the slider-crank on a quiet core (with the projection),
#: so about 10 s of work; the 10 s crank run of the module docstring takes 18 600.
LOOP_MAX_EVALS = 20_000


def _cs(model, contacts):
    return validate_contacts(model.contacts if contacts is None else contacts, model.N)


def _state(model, x, name: str) -> np.ndarray:
    """One state vector ``(nq,)`` of ``model`` (a fresh float array), or a named error."""
    a = as_array(x, name, (model.nq,))
    if a.ndim != 1:
        raise ShapeError(f"{name} must have shape ({model.nq},), got shape {a.shape}")
    return np.array(a)


def _free(model, fixed) -> np.ndarray:
    """The coordinates not in ``fixed`` (indices into ``q``, checked)."""
    idx = list(fixed) if isinstance(fixed, (list, tuple, range, np.ndarray)) else None
    if idx is None or not all(isinstance(i, (int, np.integer)) and not isinstance(i, bool) and 0 <= i < model.nq
                              for i in idx):
        raise InputError(f"fixed must be indices into q in 0..{model.nq - 1}, got {fixed!r}")
    return np.setdiff1d(np.arange(model.nq), np.asarray(idx, dtype=int))


def _rate(x, name: str) -> float:
    """A Baumgarte rate (1/s): finite and non-negative."""
    v = as_scalar(x, name)
    if v < 0:
        raise InputError(f"{name} must be non-negative, got {v!r}")
    return v


def closure_residual(model: Model, q, contacts=None) -> np.ndarray:
    """Position residuals ``φ(q)`` of all contacts, concatenated (thesis 9.54 in positions; zero when closed).

    ``φ`` is the position-level form of the contact kinematics ``G v = z θ̇``
    (9.54): the relative pose of the two contact frames, resolved along the
    reaction space ``B`` (9.59-9.60), so ``φ̇ = Bᵀ G v``.

    Parameters
    ----------
    model : Model
    q : array_like (nq,)
    contacts : sequence of Contact, optional
        Default ``model.contacts``.

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


def closure_jacobian(model: Model, q, contacts=None) -> np.ndarray:
    """Closure Jacobian ``J_c = B^T G J`` (``nc × nq``): ``φ̇ = J_c q̇`` on the manifold (thesis 9.54, 9.60).

    ``J`` stacks the body Jacobians (Remark 8); ``Bᵀ G J q̇ = Bᵀ z θ̇ = 0``
    on the manifold because ``zᵀ B = 0`` (9.60).

    Parameters
    ----------
    model : Model
    q : array_like (nq,)
    contacts : sequence of Contact, optional

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


def _mass_matrix(model, q):
    from planargeo.algorithms.crba import mass_matrix
    return mass_matrix(model, q)


def _weighted_correction(model, q, J, rhs, free):
    """``H^{-1} J^T (J H^{-1} J^T)^{-1} rhs`` restricted to the ``free`` coordinates."""
    H = _mass_matrix(model, q)[np.ix_(free, free)]
    Jf = J[:, free]
    HiJt = np.linalg.solve(H, Jf.T)
    lam = np.linalg.lstsq(Jf @ HiJt, rhs, rcond=None)[0]
    out = np.zeros(model.nq)
    out[free] = HiJt @ lam
    return out


@overflow_checked("q or qd")
def project_state(model: Model, q, qd, contacts=None, *, fixed=(), tol: float = 1e-12, max_iter: int = 25):
    """Project ``(q, q̇)`` onto the constraint manifold, positions then velocities (thesis 9.54, 9.58, 9.60).

    The velocity step removes the part of ``q̇`` that violates ``Bᵀ G v = 0``
    (9.54 with 9.60), with the kinetic-energy metric ``H`` (as 9.56-9.58 project
    the contact velocities with the stacked inertia).

    Positions: Gauss-Newton ``q ← q - J_c^+ φ(q)`` until ``max |φ| < tol``.
    Velocities: mass-weighted projection onto ``J_c q̇ = 0``.  Coordinates in
    ``fixed`` (indices into ``q``, e.g. driven joints) are left unchanged.

    Parameters
    ----------
    model : Model
    q, qd : array_like (nq,)
    contacts : sequence of Contact, optional
    fixed : sequence of int
        Coordinates the projection must not change.
    tol : float
        Position tolerance.
    max_iter : int
        Gauss-Newton iterations at most.

    Returns
    -------
    q, qd : ndarray (nq,)

    Raises
    ------
    InputError
        For a bad ``tol``, ``max_iter`` or ``fixed``.

    Examples
    --------
    >>> from planargeo.scenes.slider_crank import slider_crank_model, slider_crank_state
    >>> m = slider_crank_model(); q, qd = slider_crank_state()
    >>> q2, qd2 = project_state(m, q + [0.0, 0.01, -0.02], qd + 1.0, fixed=[0])
    >>> bool(np.abs(closure_residual(m, q2)).max() < 1e-12), float(q2[0]) == float(q[0])
    (True, True)
    """
    q, qd = _state(model, q, "q"), _state(model, qd, "qd")
    tol = check_tolerance(tol, "tol")
    if isinstance(max_iter, bool) or not isinstance(max_iter, (int, np.integer)) or max_iter < 1:
        raise InputError(f"max_iter must be a positive integer, got {max_iter!r}")
    cs = _cs(model, contacts)
    free = _free(model, fixed)
    if not cs:
        return q, qd
    for _ in range(max_iter):
        phi = closure_residual(model, q, cs)
        if np.abs(phi).max() < tol:
            break
        J = closure_jacobian(model, q, cs)[:, free]
        q[free] -= np.linalg.lstsq(J, phi, rcond=None)[0]
    J = closure_jacobian(model, q, cs)
    qd = qd - _weighted_correction(model, q, J, J @ qd, free)
    return q, qd


def baumgarte(model: Model, contacts=None, alpha: float = 5.0, beta: float = 5.0, *, fixed=()) -> Callable:
    """A ``stabilize(t, q, qd, qdd)`` hook enforcing ``φ̈ + 2αφ̇ + β²φ = 0`` (Baumgarte; thesis 9.69 stabilised).

    The accelerations from the loop algorithm satisfy ``φ̈ = 0`` (the contact
    acceleration condition 9.68-9.69); the hook adds the mass-weighted
    correction ``-H^{-1} J_c^T (J_c H^{-1} J_c^T)^{-1} (2α J_c q̇ + β² φ)``.

    Parameters
    ----------
    model : Model
    contacts : sequence of Contact, optional
    alpha, beta : float
        Damping and stiffness rates (1/s), non-negative.
    fixed : sequence of int
        Coordinates left unchanged (driven joints).

    Returns
    -------
    callable
        ``stabilize(t, q, qd, qdd) -> qdd`` for :func:`planargeo.simulate.simulate`.

    Examples
    --------
    On the manifold the hook changes nothing; off it, the corrected
    accelerations satisfy ``J_c Δq̈ = -(2α φ̇ + β² φ)``:

    >>> from planargeo.scenes.slider_crank import slider_crank_model, slider_crank_state
    >>> m = slider_crank_model(); q, qd = slider_crank_state()
    >>> hook = baumgarte(m, alpha=5.0, beta=5.0)
    >>> bool(np.abs(hook(0.0, q, qd, np.zeros(3))).max() < 1e-9)
    True
    >>> q2 = q + [0.0, 1e-3, 0.0]
    >>> dqdd = hook(0.0, q2, 0 * qd, np.zeros(3))
    >>> bool(np.allclose(closure_jacobian(m, q2) @ dqdd, -25.0 * closure_residual(m, q2)))
    True
    """
    cs = _cs(model, contacts)
    free = _free(model, fixed)
    alpha, beta = _rate(alpha, "alpha"), _rate(beta, "beta")

    def stabilize(t, q, qd, qdd):
        if not cs:
            return qdd
        phi = closure_residual(model, q, cs)
        J = closure_jacobian(model, q, cs)
        with np.errstate(over="ignore", invalid="ignore"):
            out = qdd - _weighted_correction(model, q, J, 2 * alpha * (J @ qd) + beta * beta * phi, free)
        return check_overflow(out, "baumgarte", "alpha or beta")

    return stabilize


def simulate_loops(model: Model, q0, qd0, t_end, *, contacts=None, tau=None, f_ext=None,
                   method: str = "DOP853", rtol: float = 1e-8, atol: float = 1e-10, dt: float | None = None,
                   max_step: float = math.inf, stabilization: str = "projection", alpha: float = 5.0,
                   beta: float = 5.0, prescribed=None, tol: float = 1e-12, trigger: float = 1e-10,
                   project_initial: bool = True, watch: bool = True, cond_event: float = 1e6,
                   progress: bool | None = None, max_steps: int = MAX_STEPS,
                   max_evals: int | None = LOOP_MAX_EVALS) -> SimulationResult:
    """Integrate a closed-loop mechanism with stabilised loop closures (thesis 9.5, 9.65-9.75 in time).

    The accelerations come from the constrained algorithm (open-loop ``u``
    9.63, contact forces ``F = Γ(Gu - ν)`` 9.71, closed-loop ``a`` 9.73 and
    ``q̈`` 9.75); positions and velocities are kept on the manifold by the
    chosen ``stabilization`` (module docstring).

    Parameters
    ----------
    model : Model
        Spanning tree; ``model.contacts`` closes the loops unless ``contacts`` is given.
    contacts : sequence of Contact, optional
        The contacts closing the loops (default ``model.contacts``).
    q0, qd0 : array_like (nq,)
        Initial state (projected onto the constraint manifold first when
        ``project_initial``; with ``stabilization="none"`` it is used as given).
    t_end : float
    tau, f_ext : as in :func:`planargeo.simulate.simulate`
    method, rtol, atol, dt, max_step : integrator settings (see :func:`planargeo.simulate.simulate`)
    stabilization : {"projection", "baumgarte", "both", "none"}
        ``"BDF"`` and ``"LSODA"`` take ``"baumgarte"`` or ``"none"`` (module docstring).
    alpha, beta : float
        Baumgarte parameters (1/s).
    prescribed : dict {joint: qdd}, optional
        Driven joints (e.g. ``{0: 0.0}`` for a crank at constant speed); their
        coordinates are not changed by the projection.  Energy is not conserved
        then (the drive does work).
    tol : float
        Position tolerance of the projection.
    trigger : float
        The projection runs only when a position or velocity residual exceeds
        ``trigger`` (each projection restarts the integrator); residuals stay
        below ``trigger`` plus one step's drift.
    project_initial : bool
        Project ``(q0, qd0)`` onto the manifold before starting.
    watch : bool
        Record ``cond(BᵀGΛ⁻¹GᵀB)`` (9.70-9.72) at every recorded step
        (``result.cond``) and its excursions above ``cond_event`` as
        ``"near-singular"`` events (``result.events``; see
        :mod:`planargeo.simulate.integrate`).  Nearly free: the value of the dynamics
        evaluation at the accepted state is reused when there is one
        (the first-same-as-last DOP853, RK45 and RK23), also after a
        projection that moved ``q`` by ``|Δq|``
        with ``cond |Δq| < 1e-8``; otherwise
        :func:`planargeo.algorithms.loops.loop_condition`.
        A configuration the solver refuses (condition number above
        :data:`planargeo.algorithms.loops.SINGULAR_COND`, e.g. a folded dead
        centre) stops the run with a ``"singular"`` event whatever ``watch``.
    cond_event : float
        Threshold of the near-singular events.
    progress : bool or None
        Progress bar (:func:`planargeo.simulate.progress_enabled`).
    max_steps : int
        Step limit of :func:`planargeo.simulate.simulate` (raise it for a deliberate long run).
    max_evals : int or None
        Budget of evaluations of the constrained dynamics (default :data:`LOOP_MAX_EVALS`, about
        10 s of work): a run whose first steps extrapolate past it raises
        :class:`~planargeo.errors.SizeLimitError` at once (e.g. ``RK23`` at ``rtol = 1e-10``, whose
        order 3 takes about 60 000 evaluations per second of the crank); one that reaches it stops
        with ``status == "limit"``, keeping what was computed.  Raise it (or None) for a
        deliberate long run.

    Returns
    -------
    SimulationResult
        ``residual`` holds ``[φ(q), J_c q̇]`` per recorded step;
        ``extra["position_residual"]`` and ``extra["velocity_residual"]`` their
        maxima per step, ``extra["n_position"]`` the number of position residuals;
        ``cond`` and ``events`` the watched condition number and the singular events.

    Raises
    ------
    InputError
        An unknown ``stabilization``, a projection with a multistep method, negative
        ``alpha``/``beta``, bad tolerances, or ``prescribed`` not a dict of joint indices.
    SizeLimitError
        A run predicted past ``max_steps`` or ``max_evals``.

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
    alpha, beta = _rate(alpha, "alpha"), _rate(beta, "beta")
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

    use_proj = stabilization in ("projection", "both")
    use_baum = stabilization in ("baumgarte", "both")

    def project(q, qd):
        # on demand: leave the state untouched (no integrator restart) while the
        # residuals are below ``trigger``; otherwise project to ``tol``
        r = np.concatenate([closure_residual(model, q, cs), closure_jacobian(model, q, cs) @ qd])
        if r.size == 0 or np.abs(r).max() <= trigger:
            return q, qd
        return project_state(model, q, qd, cs, fixed=fixed, tol=tol)

    def resid(q, qd):
        return np.concatenate([closure_residual(model, q, cs), closure_jacobian(model, q, cs) @ qd])

    if project_initial and stabilization != "none":
        q0, qd0 = project_state(model, q0, qd0, cs, fixed=fixed, tol=tol)
    res = simulate(model, q0, qd0, t_end, tau=tau, f_ext=f_ext, method=method, rtol=rtol, atol=atol, dt=dt,
                   max_step=max_step, forward=forward,
                   stabilize=baumgarte(model, cs, alpha, beta, fixed=fixed) if use_baum else None,
                   project=project if use_proj else None, residual=resid,
                   condition=condition if watch else None, cond_event=cond_event, progress=progress,
                   max_steps=max_steps, max_evals=max_evals)
    npos = sum(c.nc for c in cs)
    R = res.residual if res.residual is not None else np.zeros((len(res.t), 0))
    res.extra["n_position"] = npos
    res.extra["position_residual"] = np.abs(R[:, :npos]).max(axis=1) if npos else np.zeros(len(res.t))
    res.extra["velocity_residual"] = np.abs(R[:, npos:]).max(axis=1) if npos else np.zeros(len(res.t))
    res.extra["stabilization"] = stabilization
    return res
