"""Time integration of a mechanism's equations of motion, with diagnostics (``docs/simulation.md``).

:func:`simulate` integrates ``q̈ = forward(model, q, q̇, τ, f_ext)`` with scipy (:data:`METHODS`) or
fixed-step ``"RK4"``, recording the energy and, through hooks, residuals and a watched condition
number.  ``result.events``, in time order: ``{"kind": "near-singular", "t", "cond", "t_start",
"t_end"}`` per excursion of that number above ``cond_event`` (:func:`near_singular_events`), and
``{"kind": "singular", "t", "cond", "message"}`` when the dynamics raise a
:class:`~planargeo.errors.SingularConfigurationError`, which stops the run cleanly.

Examples
--------
>>> from planargeo.mechanics.model import chain_model
>>> r = simulate(chain_model(1), [0.0], [0.0], 1.0, method="RK4", dt=1e-3)
>>> r.status, float(r.t[-1]), bool(r.energy_drift() < 1e-9)
('ok', 1.0, True)
"""
from __future__ import annotations

import math
import sys
from dataclasses import dataclass, field
from typing import Any, Callable

import numpy as np

from planargeo._validate import as_array, as_scalar
from planargeo.errors import (InputError, NumericOverflowError, PlanargeoError, ShapeError,
                              SingularConfigurationError, SizeLimitError)
from planargeo.mechanics.kinematics import check_state, kinematics
from planargeo.mechanics.model import Model, _positive

__all__ = ["simulate", "SimulationResult", "energy", "progress_enabled", "near_singular_events", "METHODS",
           "MULTISTEP", "MAX_STEPS", "RATE_LIMIT"]

METHODS = ("RK23", "RK45", "DOP853", "Radau", "BDF", "LSODA", "RK4")

#: Default largest number of steps of a run (``max_steps`` of :func:`simulate`).
MAX_STEPS = 1_000_000
#: Accepted steps after which an adaptive run checks its extrapolated step count.
_PROBE = 100


#: The multistep methods: a restart (after a projection that moved the state) begins again at
#: order 1 with a small step, so projecting after every step keeps them there (docs/simulation.md).
MULTISTEP = ("BDF", "LSODA")


def energy(model: Model, q=None, qd=None, *, data=None) -> tuple[np.ndarray, np.ndarray]:
    """Kinetic and potential energy ``T = ½ Σ vᵢᵀ Iᵢ vᵢ`` (thesis 1.9) and ``V = -Σ mᵢ g · cᵢ``.

    Parameters
    ----------
    model : Model
        The mechanism.
    q, qd : array_like (..., nq)
        The state (``qd`` None: at rest); not with ``data``.
    data : Data, optional
        The kinematics of ``model`` already computed for the state, used as they are.

    Returns
    -------
    tuple of numpy.ndarray
        ``(T, V)``, each shape (...) (J).

    Raises
    ------
    InputError
        If both a state and ``data`` are given.

    Examples
    --------
    >>> from planargeo.mechanics.model import chain_model
    >>> T, V = energy(chain_model(1), [np.pi / 2], [3.0])   # rod upright, spinning at 3 rad/s
    >>> float(T), float(V)                                  # ½ (1/3) 9, m g L/2
    (1.5, 4.905)
    >>> d = kinematics(chain_model(1), [np.pi / 2], [3.0])
    >>> [float(x) for x in energy(chain_model(1), data=d)]
    [1.5, 4.905]
    """
    if data is None:
        data = kinematics(model, q, qd)
    elif q is not None or qd is not None or (data.model is not model and data.model != model):
        raise InputError("energy takes q, qd or the data of model's kinematics, not both")
    T = 0.5 * np.einsum("...ni,...nij,...nj->...", data.v, data.I, data.v)
    m = model.arrays()["mass"]
    V = -np.einsum("n,...nk,k->...", m, data.com, np.asarray(model.gravity))
    return T, V


@dataclass
class SimulationResult:
    """A trajectory and its diagnostics.

    Attributes
    ----------
    t : ndarray (T,)
    q, qd : ndarray (T, nq)
    kinetic, potential, energy : ndarray (T,)
    residual : ndarray (T, m) or None
        Constraint residuals (with a ``residual`` hook).
    cond : ndarray (T,) or None
        The watched condition number per recorded step (with ``condition``).
    dissipated : ndarray (T,) or None
        Energy removed by the joints' damping since ``t = 0`` (with ``damping``).
    events : list of dict
        Singular and near-singular events (module docstring).
    status : str
        ``"ok"``, ``"singular"``, ``"failed"``, ``"limit"`` or ``"interrupted"`` (then what was computed).
    message : str
    method : str
    nfev : int
        Number of dynamics evaluations.
    extra : dict
        Method-specific extras (e.g. contact forces of a loop simulation).
    """

    t: np.ndarray
    q: np.ndarray
    qd: np.ndarray
    kinetic: np.ndarray
    potential: np.ndarray
    energy: np.ndarray
    residual: np.ndarray | None = None
    status: str = "ok"
    message: str = ""
    method: str = ""
    nfev: int = 0
    extra: dict[str, Any] = field(default_factory=dict)
    cond: np.ndarray | None = None
    events: list = field(default_factory=list)
    dissipated: np.ndarray | None = None

    @property
    def success(self) -> bool:
        """``True`` when the run reached ``t_end`` (``status == "ok"``)."""
        return self.status == "ok"

    def energy_drift(self) -> float:
        """``max |E(t) + W(t) - E(0)| / max(|E(0)|, max T(t))``: relative drift of the energy balance.

        ``E = T + V``, ``W`` the energy the damping dissipated (:attr:`dissipated`); the kinetic
        energy in the denominator keeps the measure meaningful when ``E`` is near zero.

        Returns
        -------
        float
        """
        scale = max(abs(float(self.energy[0])), float(np.max(self.kinetic)), np.finfo(float).tiny)
        total = self.energy if self.dissipated is None else self.energy + self.dissipated
        return float(np.max(np.abs(total - self.energy[0])) / scale)


def _in_ipython_kernel() -> bool:
    """True inside a Jupyter/IPython kernel (notebook, JupyterLab, Colab), without importing IPython."""
    ipython = sys.modules.get("IPython")
    try:
        shell = None if ipython is None else ipython.get_ipython()
        if shell is None:
            return False
        return (any(cls.__name__ == "ZMQInteractiveShell" for cls in type(shell).__mro__)
                or "IPKernelApp" in shell.config)
    except Exception:  # pragma: no cover - a broken IPython
        return False


def progress_enabled(progress: bool | None = None, stream=None) -> bool:
    """Whether :func:`simulate` shows a progress bar: ``progress``, or on a terminal or in a Jupyter kernel.

    Parameters
    ----------
    progress : bool or None, optional
        ``True``/``False`` to force, None for auto.
    stream : file, optional
        Where the bar goes (default ``sys.stderr``).

    Returns
    -------
    bool

    Examples
    --------
    >>> import io
    >>> progress_enabled(True), progress_enabled(False), progress_enabled(None, io.StringIO())
    (True, False, False)
    """
    if progress is not None:
        return bool(progress)
    stream = sys.stderr if stream is None else stream
    try:
        if stream is not None and stream.isatty():
            return True
    except Exception:  # closed or odd streams
        pass
    return _in_ipython_kernel()


def _progress(enabled, total):
    if not progress_enabled(enabled):
        return None
    try:
        from tqdm.auto import tqdm
    except ImportError:  # pragma: no cover
        return None
    return tqdm(total=total, unit="s", leave=False, bar_format="{l_bar}{bar}| {n:.3g}/{total:.3g} s")


def simulate(model: Model, q0, qd0, t_end, *, tau=None, f_ext=None, method: str = "DOP853",
             rtol: float = 1e-8, atol: float = 1e-10, dt: float | None = None, max_step: float = math.inf,
             forward: Callable | None = None, stabilize: Callable | None = None,
             project: Callable | None = None, residual: Callable | None = None,
             energy_fn: Callable | None = None, condition: Callable | str | None = None,
             cond_event: float = 1e6, progress: bool | None = None,
             max_steps: int = MAX_STEPS, damping=None, max_evals: int | None = None) -> SimulationResult:
    """Integrate ``q̈ = forward(q, q̇, τ)`` from ``(q0, qd0)`` over ``[0, t_end]`` (thesis 3.41-3.42, 2.9 in time).

    ``ẏ = (q̇, q̈)`` for ``y = (q, q̇)``, ``q̈`` from the forward dynamics (default the
    articulated-body algorithm, 3.31-3.42); the thesis leaves the integration to the reader (section 3.6).

    Parameters
    ----------
    model : Model
        The mechanism.
    q0, qd0 : array_like (nq,)
        The initial state.
    t_end : float
        Final time (> 0).
    tau, f_ext : array_like (nq,) and (N, 3), or callables ``(t, q, qd)``, optional
        Joint forces (default zero) and external world wrenches at the origin.
    method : {"DOP853", "RK23", "RK45", "Radau", "BDF", "LSODA", "RK4"}
        scipy's adaptive solvers (implicit ones' Jacobian evaluations count in ``nfev``) or fixed-step RK4.
    rtol, atol : float
        Tolerances of the adaptive methods: ``rtol`` at least ``100 ε`` (2.2e-14), ``atol >= 0``.
    dt : float, optional
        Step of ``"RK4"`` (required there); the adaptive methods' output is then sampled every ``dt``.
    max_step : float
        Largest step of the adaptive methods (> 0; ``inf`` by default).
    forward : callable ``(model, q, qd, tau, f_ext) -> qdd``, optional
        The forward dynamics (default :func:`planargeo.algorithms.aba.forward_dynamics`).
    stabilize : callable ``(t, q, qd, qdd) -> qdd``, optional
        Corrects the accelerations, e.g. Baumgarte terms ``-2α φ̇ - β² φ``.
    project : callable ``(q, qd) -> (q, qd)``, optional
        Pulls the state back onto a constraint manifold after each accepted step (the integrator
        restarts from it; the multistep :data:`MULTISTEP` then restart at order 1).
    residual, energy_fn : callable ``(q, qd)``, optional
        Constraint residuals recorded at every step; ``(T, V)`` replacing :func:`energy`.
    condition : callable ``(q, qd) -> float``, ``"joints"`` or None
        Condition number watched at every recorded step (``"joints"``: the largest of the joints'
        ``sᵀAs``, :func:`planargeo.algorithms.stacked.joint_conditions`).
    cond_event : float
        A watched condition number above this opens a ``"near-singular"`` event.
    progress : bool or None
        Show a tqdm progress bar; ``None``: :func:`progress_enabled` decides.
    max_steps, max_evals : int
        Largest number of steps (:data:`MAX_STEPS`) and of evaluations of the dynamics (None: no limit).
    damping : float or array_like (nq,), optional
        Viscous coefficients ``c_j >= 0`` per joint coordinate: ``τ_j - c_j q̇_j`` replaces ``τ_j``;
        the dissipated ``W(t) = ∫ Σ c_j q̇_j² dt`` is integrated too (``result.dissipated``).

    Returns
    -------
    SimulationResult
        ``status`` ``"ok"``, ``"singular"``, ``"failed"`` (the state left double precision), ``"limit"``
        (``max_steps`` or ``max_evals`` reached) or ``"interrupted"`` (Ctrl-C).

    Raises
    ------
    InputError
        An unknown ``method``, a bad number or ``damping``, a batch of states, ``"RK4"`` without ``dt``.
    SizeLimitError
        A run that needs more than ``max_steps`` steps or ``max_evals`` evaluations.
    NumericOverflowError
        A start whose speeds or accelerations reach :data:`RATE_LIMIT`.

    Examples
    --------
    A unit rod released horizontally: ``q ≈ -½ (1.5 g) t²`` at first, and energy is kept.

    >>> from planargeo.mechanics.model import chain_model
    >>> r = simulate(chain_model(1), [0.0], [0.0], 0.01, method="DOP853", rtol=1e-12, atol=1e-14)
    >>> r.status, round(float(r.q[-1, 0]) / (-0.5 * 14.715 * 0.01 ** 2), 4), bool(r.energy_drift() < 1e-10)
    ('ok', 1.0, True)
    """
    t_end, dt, rtol, atol, max_step, max_steps = _options(method, t_end, dt, rtol, atol, max_step, max_steps)
    max_evals = _eval_budget(max_evals, method, t_end, dt)
    if qd0 is None:
        raise InputError(f"qd0 must be the initial joint speeds, shape ({model.nq},), got None")
    q0, qd0, _, _, _, shape = check_state(model, q0, qd0)
    if shape != ():
        raise InputError(f"q0 and qd0 must be single states of shape ({model.nq},), got batch shape {shape}")
    if forward is None:
        from planargeo.algorithms.aba import forward_dynamics as forward
    nq = model.nq
    damp = None if damping is None else _damping(damping, nq)
    tau_c = None if callable(tau) else (np.zeros(nq) if tau is None else as_array(tau, "tau", (nq,)))
    fext_c = None if callable(f_ext) else (None if f_ext is None else as_array(f_ext, "f_ext", (model.N, 3)))
    if condition == "joints":
        from planargeo.algorithms.stacked import joint_conditions

        def condition(q, qd):
            return float(np.max(joint_conditions(model, q), initial=1.0))
    elif condition is not None and not callable(condition):
        raise InputError(f"condition must be a callable, 'joints' or None, got {condition!r}")
    cond_event = as_scalar(cond_event, "cond_event")
    nfev = 0

    def qdd_of(t, q, qd):
        nonlocal nfev
        nfev += 1
        ta = tau(t, q, qd) if tau_c is None else tau_c
        if damp is not None:
            ta = ta - damp * qd                  # viscous joint damping, τ = -c q̇
        fe = f_ext(t, q, qd) if callable(f_ext) else fext_c
        try:
            a = forward(model, q, qd, ta, fe)
        except SingularConfigurationError as exc:
            exc.t = float(t)                     # when it happened (a stage may lie past the last step)
            raise
        if stabilize is not None:
            a = stabilize(t, q, qd, a)
        return a

    def rhs(t, y):
        qd = y[nq:2 * nq]
        if damp is None:
            return np.concatenate([qd, qdd_of(t, y[:nq], qd)])
        return np.concatenate([qd, qdd_of(t, y[:nq], qd), [float(np.dot(damp * qd, qd))]])   # Ẇ = Σ c q̇²

    def projected(y):
        """``y`` with ``(q, q̇)`` pulled back by ``project`` (the dissipated energy kept)."""
        qp, qdp = project(y[:nq], y[nq:2 * nq])
        return np.concatenate([qp, qdp, y[2 * nq:]])

    if energy_fn is None:
        def energy_fn(q, qd):
            T, V = energy(model, q, qd)
            return float(T), float(V)

    ts, ys, cs = [], [], []          # times, states (q, q̇, dissipated energy), watched conditions

    def watch(y):
        # at record time: a hook may reuse the value of the dynamics evaluation at this very state
        return float(condition(y[:nq], y[nq:2 * nq])) if condition is not None else math.nan

    def record(t, y):
        y = np.array(y, dtype=float)
        c = watch(y)
        ts.append(float(t))
        ys.append(y)
        cs.append(c)

    y = np.concatenate([q0, qd0] + ([] if damp is None else [[0.0]])).astype(float)
    if project is not None:
        y = projected(y)
    record(0.0, y)
    status, message, singular = "ok", "", None
    bar = _progress(progress, t_end)
    t = 0.0
    try:
        if method == "RK4":
            nsteps = max(1, math.ceil(t_end / dt - 1e-9))      # at most max_steps (_options)
            h = t_end / nsteps
            for k in range(nsteps):
                k1 = rhs(t, y)
                if k == 0:
                    _check_rates(k1, nq)
                k2 = rhs(t + h / 2, y + h / 2 * k1)
                k3 = rhs(t + h / 2, y + h / 2 * k2)
                k4 = rhs(t + h, y + h * k3)
                y = y + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4)
                t = (k + 1) * h
                if project is not None:
                    y = projected(y)
                record(t, y)
                if bar is not None:
                    bar.update(h)
        else:
            from scipy import integrate

            cls = getattr(integrate, method)   # scipy's OdeSolver class of that name ("RK4" is stepped above)

            def make(t0, y0, first_step=None):
                # scipy's step-size norms square the scaled rates: rates near 1e154 overflow there (an
                # infinite norm gives a zero step, which scipy reports as a failure: stopped below)
                with np.errstate(over="ignore", invalid="ignore"):
                    return cls(rhs, t0, y0, t_end, rtol=rtol, atol=atol, max_step=max_step, first_step=first_step)

            if method in MULTISTEP:                 # they keep no rates of the start: one more evaluation
                _check_rates(rhs(0.0, y), nq)
            solver = make(0.0, y)
            if getattr(solver, "f", None) is not None:   # the one-step methods' rates at the start
                _check_rates(solver.f, nq)
            grid = []
            if dt is not None:
                nout = int(math.floor(t_end / dt + 1e-9))
                grid = [k * dt for k in range(1, nout + 1)]
                if not grid or grid[-1] < t_end * (1 - 1e-12):
                    grid.append(t_end)
                grid[-1] = min(grid[-1], t_end)
            gi = steps = 0
            while solver.status == "running":
                stop = (_step_budget(steps, t, t_end, max_steps, method)
                        or _eval_check(nfev, steps, t, t_end, max_evals, method))
                if stop:
                    status, message = "limit", stop
                    break
                try:
                    with np.errstate(over="ignore", invalid="ignore", divide="ignore"):
                        msg = solver.step()
                except (ValueError, ArithmeticError, np.linalg.LinAlgError) as exc:
                    if isinstance(exc, PlanargeoError):
                        raise
                    solver.status, msg = "failed", f"the step could not be computed ({exc})"
                steps += 1
                if solver.status != "failed" and not np.isfinite(solver.y).all():
                    solver.status, msg = "failed", "the state left double precision's range (speeds too large)"
                if solver.status == "failed":
                    status, message = "failed", f"{method} failed at t = {solver.t:.6g}: {msg}"
                    break
                t_new = solver.t
                if dt is not None:
                    dense = solver.dense_output()
                    while gi < len(grid) and (grid[gi] <= t_new or solver.status == "finished"):
                        yo = dense(grid[gi])
                        if project is not None:  # outputs between projections, pulled back too
                            yo = projected(yo)
                        record(grid[gi], yo)
                        gi += 1
                else:
                    record(t_new, solver.y)
                if bar is not None:
                    bar.update(t_new - t)
                t = t_new
                if project is not None:
                    yp = projected(solver.y)
                    if dt is None:
                        if not np.array_equal(yp, ys[-1]):
                            cs[-1] = watch(yp)
                        ys[-1] = yp
                    if solver.status == "running" and not np.array_equal(yp, solver.y):
                        h = min(solver.step_size or (t_end - t), t_end - t)
                        solver = make(t, yp, first_step=h if h > 0 else None)
    except SingularConfigurationError as exc:
        status = "singular"
        message = f"stopped at t = {t:.6g}: singular configuration: {exc}"
        singular = {"kind": "singular", "t": getattr(exc, "t", t), "cond": exc.cond, "message": str(exc)}
    except KeyboardInterrupt:
        status, message = "interrupted", f"interrupted at t = {t:.6g}: the trajectory holds what was computed"
        n = min(len(ts), len(ys), len(cs))  # a step interrupted while being recorded
        del ts[n:], ys[n:], cs[n:]
    finally:
        if bar is not None:
            bar.close()

    Y = np.array(ys)
    qs, qds = Y[:, :nq], Y[:, nq:2 * nq]
    dissipated = None if damp is None else Y[:, 2 * nq].copy()
    Ts, Vs = np.empty(len(ts)), np.empty(len(ts))
    for k in range(len(ts)):
        Ts[k], Vs[k] = energy_fn(qs[k], qds[k])
    res = None
    if residual is not None:
        res = np.array([np.atleast_1d(np.asarray(residual(qs[k], qds[k]), dtype=float)) for k in range(len(ts))])
    tt = np.array(ts)
    conds = None if condition is None else np.array(cs)
    events = [] if conds is None else near_singular_events(tt, conds, cond_event)
    events += [] if singular is None else [singular]
    return SimulationResult(t=tt, q=qs, qd=qds, kinetic=Ts, potential=Vs, energy=Ts + Vs,
                            residual=res, status=status, message=message, method=method, nfev=nfev,
                            cond=conds, events=events, dissipated=dissipated)


def _damping(damping, nq: int) -> np.ndarray:
    """The damping coefficients as an (nq,) array of finite non-negative numbers (InputError naming ``damping``)."""
    c = np.asarray(as_array(damping, "damping"), dtype=float)
    if c.ndim == 0:
        c = np.full(nq, float(c))
    if c.shape != (nq,):
        raise ShapeError(f"damping must be a number or one coefficient per joint coordinate, shape ({nq},), "
                         f"got shape {c.shape}")
    if not np.all(c >= 0):
        raise InputError(f"damping coefficients must be non-negative, got {c.tolist()}")
    return c


def _options(method, t_end, dt, rtol, atol, max_step, max_steps):
    """The validated integrator options ``(t_end, dt, rtol, atol, max_step, max_steps)`` of :func:`simulate`."""
    if not isinstance(method, str) or method not in METHODS:
        raise InputError(f"method must be one of {list(METHODS)}, got {method!r}")
    max_steps = _count(max_steps, "max_steps")
    t_end = _positive(t_end, "t_end")
    if dt is not None:
        dt = _positive(dt, "dt")
    elif method == "RK4":
        raise InputError("dt must be given for method 'RK4'")
    rtol = as_scalar(rtol, "rtol")
    if not rtol >= 100 * np.finfo(float).eps:
        raise InputError(f"rtol must be at least 100 ε = 2.2e-14 (scipy's floor), got {rtol!r}")
    atol = as_scalar(atol, "atol")
    if not atol >= 0:
        raise InputError(f"atol must be non-negative, got {atol!r}")
    max_step = as_scalar(max_step, "max_step", finite=False)
    if not max_step > 0:                # NaN too
        raise InputError(f"max_step must be positive, got {max_step!r}")
    with np.errstate(over="ignore"):
        needs = {"t_end / dt": t_end / dt if dt is not None else 0.0,
                 "t_end / max_step": t_end / max_step if method != "RK4" else 0.0}
    for what, n in needs.items():
        if n > max_steps:
            raise SizeLimitError(f"t_end = {t_end:g} needs {what} = {n:.3g} steps, past max_steps = {max_steps}; "
                                 "pass a larger max_steps for a deliberate long run")
    return t_end, dt, rtol, atol, max_step, max_steps


def _count(x, name: str, alternative: str = "") -> int:
    if isinstance(x, (bool, np.bool_)) or not isinstance(x, (int, np.integer)) or x < 1:
        raise InputError(f"{name} must be a positive integer{alternative}, got {x!r}")
    return int(x)


def _eval_budget(max_evals, method: str, t_end: float, dt) -> int | None:
    """The validated ``max_evals`` of :func:`simulate`; RK4's known count (4 per step) past it raises at once."""
    if max_evals is None:
        return None
    max_evals = _count(max_evals, "max_evals", " or None")
    if method == "RK4":
        n = 4 * math.ceil(t_end / dt - 1e-9)
        if n > max_evals:
            raise SizeLimitError(f"t_end = {t_end:g} needs {n} evaluations of the dynamics with RK4 at dt = {dt:g}, "
                                 f"past max_evals = {max_evals}; pass a larger max_evals for a deliberate long run")
    return max_evals


def _eval_check(nfev: int, k: int, t: float, t_end: float, max_evals: int | None, method: str) -> str:
    """The message of a run stopped by ``max_evals`` ("" to go on); raises on bad extrapolation."""
    if max_evals is None:
        return ""
    if nfev >= max_evals:
        return (f"stopped at t = {t:.6g}: max_evals = {max_evals} evaluations of the dynamics done; pass a "
                "larger max_evals for a deliberate long run")
    factor = 10 if k == 10 else 1 if k == _PROBE else 0     # fail fast: first steps are smallest
    if factor and t > 0 and t_end / (factor * max_evals) > t / nfev:       # overflow-free
        raise SizeLimitError(f"{method} would need {_about(t_end, t, nfev)} evaluations of the dynamics to "
                             f"reach t_end = {t_end:g} (extrapolated from the first {k} steps, {nfev} evaluations), "
                             f"past max_evals = {max_evals}; pass a larger max_evals for a deliberate long run, or a "
                             "looser rtol or a higher-order method (DOP853)")
    return ""


#: Largest |q̇| and |q̈| an integration starts from: the adaptive methods square the scaled rates in their
#: error norms (1e150² is near the float range), so beyond it they stall or fail in numpy's words.
RATE_LIMIT = 1e150


def _check_rates(f0, nq: int) -> None:
    """Refuse a start whose rates ``f0 = (q̇, q̈, …)`` reach :data:`RATE_LIMIT` (in the package's words)."""
    f0 = np.asarray(f0, dtype=float)
    qd, qdd = np.abs(f0[:nq]), np.abs(f0[nq:2 * nq])
    if not (np.all(qd < RATE_LIMIT) and np.all(qdd < RATE_LIMIT)):
        raise NumericOverflowError(
            f"the starting state moves too fast to integrate in double precision: largest |q̇| = "
            f"{float(np.max(qd, initial=0.0)):.3g}, |q̈| = {float(np.max(qdd, initial=0.0)):.3g}; both must stay "
            f"below {RATE_LIMIT:g} (qd0, tau or f_ext too large)")


def _about(t_end: float, t: float, n: int) -> str:
    """``"about N"`` for the count ``n t_end / t`` extrapolated from ``n`` at ``t`` (overflow-free words)."""
    with np.errstate(over="ignore"):
        x = n * (t_end / t)
    return f"about {x:.3g}" if math.isfinite(x) else "more than 1e308"


def _step_budget(k: int, t: float, t_end: float, max_steps: int, method: str) -> str:
    """The message of a run stopped by ``max_steps`` ("" to go on); raises on bad extrapolation."""
    if k >= max_steps:
        return (f"stopped at t = {t:.6g}: max_steps = {max_steps} steps taken; pass a larger max_steps "
                "for a deliberate long run")
    if k == _PROBE and t <= 0:
        raise SizeLimitError(f"{method} made no progress in its first {k} steps (t = 0): it would never reach "
                             f"t_end = {t_end:g}")
    if k == _PROBE and t > 0 and t_end / (10 * max_steps) > t / k:      # t_end / t · k > 10 max_steps, overflow-free
        raise SizeLimitError(f"{method} would need {_about(t_end, t, k)} steps to reach t_end = {t_end:g} "
                             f"(extrapolated from the first {k}), past max_steps = {max_steps}; pass a larger "
                             "max_steps for a deliberate long run")
    return ""


def near_singular_events(t, cond, threshold: float) -> list[dict]:
    """``"near-singular"`` events of a condition-number series, one per excursion above ``threshold``.

    Each is ``{"kind", "t", "cond", "t_start", "t_end"}``: the peak and the first/last times
    above (``nan`` counts as above: a condition number that could not be computed).

    Parameters
    ----------
    t, cond : array_like, shape (T,)
        Times (s) and condition numbers.
    threshold : float
        The level above which a step is near-singular.

    Returns
    -------
    list of dict
        The events, in time order.

    Examples
    --------
    >>> ev = near_singular_events([0, 1, 2, 3, 4, 5], [1, 1e7, 1e9, 1e8, 1, 1e7], 1e6)
    >>> [(e["t"], e["t_start"], e["t_end"]) for e in ev]
    [(2.0, 1.0, 3.0), (5.0, 5.0, 5.0)]
    """
    t = np.asarray(t, dtype=float)
    c = np.asarray(cond, dtype=float)
    above = ~(c <= threshold)
    out = []
    k, n = 0, len(c)
    while k < n:
        if not above[k]:
            k += 1
            continue
        e = k
        while e + 1 < n and above[e + 1]:
            e += 1
        seg = np.where(np.isnan(c[k:e + 1]), np.inf, c[k:e + 1])
        p = k + int(np.argmax(seg))
        out.append({"kind": "near-singular", "t": float(t[p]), "cond": float(c[p]),
                    "t_start": float(t[k]), "t_end": float(t[e])})
        k = e + 1
    return out
