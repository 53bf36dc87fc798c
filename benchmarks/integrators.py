"""Integrators: work–precision diagrams, and energy / constraint drift of the loop stabilisations.

Run ``python benchmarks/integrators.py [--quick] [--out DIR]`` (full: a few minutes; ``--quick``:
seconds).  Writes ``integrators.md``, ``integrators.svg/.png`` (work–precision) and
``integrators_drift.svg/.png`` (drift against time) to ``DIR`` (default ``benchmarks/results``).

Work–precision (in the manner of the classic ODE-solver comparisons, Hairer & Wanner)
-------------------------------------------------------------------------------------
Two systems, each integrated with every scipy method (``RK23``, ``RK45``, ``DOP853``, ``Radau``,
``BDF``, ``LSODA``) over a range of ``rtol`` (``atol = 1e-2 rtol``) and with fixed-step classical
``RK4`` over a range of ``dt``, all through :func:`planargeo.simulate.simulate`:

a. a free conservative chain (``chain_model(5)``, gravity, ``τ = 0``) released from a bent,
   moving state, ``t_end = 3 s`` (full mode);
b. the slider-crank of thesis 9.6 (scene ``slider-crank``, free crank, ``g = 9.81``) through
   :func:`planargeo.simulate.loops.simulate_loops` with ``stabilization="none"`` (the plain ODE
   ``q̈ = f(q, q̇)`` of the constrained algorithm, so that the error is the integrator's alone).

For each run: the error at ``t_end``, ``‖y - y_ref‖∞`` over the state ``y = (q, q̇)`` (rad,
rad/s), against a reference run of ``DOP853`` at ``rtol = 1e-13``, ``atol = 1e-14``, with the
cost: dynamics evaluations (``nfev``, including finite-difference Jacobians) and the wall time of
the run (charted; thread CPU time is tabulated as well).  The reference is checked by a second, independent run — the chain:
``Radau`` at ``rtol = 1e-11`` (an implicit collocation method, nothing shared with ``DOP853``
but the dynamics); the slider-crank (full mode): ``DOP853`` tight on the *Lagrange-multiplier*
dynamics in maximal coordinates (``constrained_dynamics_lagrange``, a formulation independent
of the loop algorithm).  Their disagreement is reported as the reference's own error floor.

Drift
-----
The slider-crank over 10 s (full mode; ``DOP853``, ``rtol = 1e-5``) with every stabilisation
:func:`~planargeo.simulate.loops.simulate_loops` offers: ``none``, ``baumgarte`` (default
``α = β = 5``/s and a stiffer ``α = β = 20``/s), ``projection`` (trigger 1e-10) and ``both``:
relative energy drift ``|E(t) - E(0)| / max(|E(0)|, max T)`` (energy is conserved: free crank,
no drive, no friction), position residual ``max |φ(q)|`` and velocity residual
``max |J_c q̇|`` against time.
"""
from __future__ import annotations

import os

for _v in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_v, "1")

import argparse  # noqa: E402
import math  # noqa: E402
import platform  # noqa: E402
import sys  # noqa: E402
import time  # noqa: E402
from pathlib import Path  # noqa: E402

import numpy as np  # noqa: E402

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
if str(ROOT) not in sys.path:
    sys.path.insert(0, str(ROOT))

from planargeo import scenes  # noqa: E402
from planargeo.algorithms.loops import constrained_dynamics_lagrange  # noqa: E402
from planargeo.mechanics.model import chain_model  # noqa: E402
from planargeo.simulate.integrate import simulate  # noqa: E402
from planargeo.simulate.loops import simulate_loops  # noqa: E402

METHODS = ("RK23", "RK45", "DOP853", "Radau", "BDF", "LSODA", "RK4")
COLORS = {"RK45": "C0", "DOP853": "C1", "Radau": "C2", "RK4": "C3", "RK23": "C4", "BDF": "C5", "LSODA": "C6"}
MARKERS = {"RK45": "o", "DOP853": "s", "Radau": "^", "RK4": "D", "RK23": "v", "BDF": "P", "LSODA": "X"}
REF = dict(method="DOP853", rtol=1e-13, atol=1e-14)
ATOL_FACTOR = 1e-2          # atol = ATOL_FACTOR * rtol

CHAIN_Q0 = (0.9, -0.5, 0.7, -0.3, 0.6)
CHAIN_QD0 = (0.5, -1.0, 0.8, 0.0, -0.6)


def _decades(a, b):
    return [10.0 ** -k for k in range(a, b + 1)]


CONFIGS = {
    "full": dict(
        chain_n=5, chain_t=3.0,
        chain_grid={"RK23": _decades(3, 8), "RK45": _decades(3, 10), "DOP853": _decades(3, 11),
                    "Radau": _decades(3, 8), "BDF": _decades(3, 8), "LSODA": _decades(3, 10),
                    "RK4": [0.02 / 2 ** k for k in range(7)]},
        chain_check=dict(method="Radau", rtol=1e-11, atol=1e-13),
        crank_t=0.3,
        crank_grid={"RK23": _decades(3, 7), "RK45": _decades(3, 9), "DOP853": _decades(3, 11),
                    "Radau": _decades(3, 7), "BDF": _decades(3, 7), "LSODA": _decades(3, 9),
                    "RK4": [0.005 / 2 ** k for k in range(5)]},
        crank_check=True,
        drift_t=10.0, drift_rtol=1e-5,
        stabilisations=[("none", {}), ("baumgarte", dict(alpha=5.0, beta=5.0)),
                        ("baumgarte", dict(alpha=20.0, beta=20.0)), ("projection", {}), ("both", {})],
        repeat_below=0.05,
    ),
    "quick": dict(
        chain_n=3, chain_t=1.0,
        chain_grid={"RK23": _decades(3, 7)[::2], "RK45": _decades(3, 8)[::1], "DOP853": _decades(3, 11)[::2],
                    "Radau": _decades(3, 7)[::2], "BDF": _decades(3, 7)[::2], "LSODA": _decades(3, 9)[::2],
                    "RK4": [0.02 / 2 ** k for k in range(4)]},
        chain_check=dict(method="Radau", rtol=1e-11, atol=1e-13),
        crank_t=0.1,
        crank_grid={"RK23": _decades(3, 5)[::2], "RK45": _decades(3, 7)[::2], "DOP853": _decades(3, 11)[::2],
                    "Radau": _decades(3, 7)[::2], "BDF": _decades(3, 7)[::2], "LSODA": _decades(3, 9)[::2],
                    "RK4": [0.01 / 2 ** k for k in range(3)]},
        crank_check=False,
        drift_t=1.0, drift_rtol=1e-5,
        stabilisations=[("none", {}), ("baumgarte", dict(alpha=5.0, beta=5.0)),
                        ("baumgarte", dict(alpha=20.0, beta=20.0)), ("projection", {}), ("both", {})],
        repeat_below=0.0,
    ),
}

_T0 = time.perf_counter()


def log(msg: str) -> None:
    print(f"[integrators {time.perf_counter() - _T0:6.1f} s] {msg}", file=sys.stderr, flush=True)


# --------------------------------------------------------------------------- systems
def chain_system(n: int = 5, t_end: float = 3.0) -> dict:
    """The free conservative chain: ``chain_model(n)`` (unit links, gravity), ``τ = 0``."""
    return dict(name="chain", label=f"free chain, N = {n}, t_end = {t_end:g} s", model=chain_model(n),
                q0=np.array(CHAIN_Q0[:n] if n <= len(CHAIN_Q0) else np.resize(CHAIN_Q0, n), dtype=float),
                qd0=np.array(CHAIN_QD0[:n] if n <= len(CHAIN_QD0) else np.resize(CHAIN_QD0, n), dtype=float),
                t_end=float(t_end), loops=False)


def crank_system(t_end: float = 0.5) -> dict:
    """The slider-crank of thesis 9.6 (scene defaults: ψ = 0.4, ψ̇ = 20 rad/s, g = 9.81), free crank."""
    sc = scenes.build("slider-crank")
    return dict(name="slider-crank", label=f"slider-crank (free crank), t_end = {t_end:g} s", model=sc.model,
                q0=np.array(sc.state["q"], dtype=float), qd0=np.array(sc.state["qd"], dtype=float),
                t_end=float(t_end), loops=True)


def integrate(system: dict, method: str, *, rtol=None, atol=None, dt=None, stabilization: str = "none",
              forward=None, **kw):
    """One run of ``system``; returns ``(result, cpu_seconds, wall_seconds)``.

    Through :func:`~planargeo.simulate.simulate` (or ``simulate_loops``), which offers every method
    of the study.
    """
    opts = dict(method=method)
    if method == "RK4":
        opts["dt"] = dt
    else:
        opts.update(rtol=rtol, atol=atol if atol is not None else ATOL_FACTOR * rtol)
    c0, w0 = time.thread_time(), time.perf_counter()
    if system["loops"] and forward is None:
        r = simulate_loops(system["model"], system["q0"], system["qd0"], system["t_end"],
                           stabilization=stabilization, project_initial=stabilization != "none",
                           progress=False, **opts, **kw)
    else:
        r = simulate(system["model"], system["q0"], system["qd0"], system["t_end"], forward=forward,
                     progress=False, **opts, **kw)
    return r, time.thread_time() - c0, time.perf_counter() - w0


def final_state(r) -> np.ndarray:
    return np.concatenate([r.q[-1], r.qd[-1]])


def state_error(y, y_ref) -> float:
    """``‖y - y_ref‖∞`` over the state ``(q, q̇)``."""
    return float(np.max(np.abs(np.asarray(y) - np.asarray(y_ref))))


def lagrange_forward(model, q, qd, tau, f_ext):
    """``q̈`` from the maximal-coordinate Lagrange-multiplier solve (independent of the loop algorithm)."""
    return constrained_dynamics_lagrange(model, q, qd, tau, f_ext)["qdd"]


def reference(system: dict, check=None) -> dict:
    """The tight reference at ``t_end`` and, if ``check`` is given, its disagreement with a second run."""
    r, cpu, wall = integrate(system, REF["method"], rtol=REF["rtol"], atol=REF["atol"])
    if r.status != "ok":
        raise RuntimeError(f"reference run failed: {r.message}")
    out = dict(y=final_state(r), nfev=r.nfev, cpu=cpu, wall=wall, desc="DOP853, rtol 1e-13, atol 1e-14")
    log(f"  reference {out['desc']}: nfev {r.nfev}, {cpu:.1f} s CPU")
    if check is not None:
        if check == "lagrange":
            r2, cpu2, _ = integrate(system, REF["method"], rtol=REF["rtol"], atol=REF["atol"],
                                    forward=lagrange_forward)
            desc = "DOP853 rtol 1e-13 on the Lagrange-multiplier dynamics (maximal coordinates)"
        else:
            r2, cpu2, _ = integrate(system, check["method"], rtol=check["rtol"], atol=check["atol"])
            desc = f"{check['method']}, rtol {check['rtol']:g}, atol {check['atol']:g}"
        out["check"] = dict(desc=desc, nfev=r2.nfev, cpu=cpu2, status=r2.status,
                            disagreement=state_error(final_state(r2), out["y"]))
        log(f"  check {desc}: nfev {r2.nfev}, {cpu2:.1f} s CPU, disagreement {out['check']['disagreement']:.2e}")
    return out


def work_precision(system: dict, grid: dict, y_ref, repeat_below: float = 0.0) -> list:
    """One row per (method, tolerance or step): error at ``t_end``, nfev, CPU and wall time."""
    rows = []
    for method in METHODS:
        for tol in grid.get(method, []):
            kw = dict(dt=tol) if method == "RK4" else dict(rtol=tol)
            r, cpu, wall = integrate(system, method, **kw)
            # cheap runs are repeated (best wall time of up to 3) to tame the noise of a shared machine
            n = 1
            while wall < repeat_below and n < 3:
                _, c2, w2 = integrate(system, method, **kw)
                cpu, wall, n = min(cpu, c2), min(wall, w2), n + 1
            err = state_error(final_state(r), y_ref) if r.status == "ok" else float("nan")
            row = dict(method=method, tol=tol, param="dt" if method == "RK4" else "rtol", nfev=r.nfev,
                       steps=len(r.t) - 1, cpu=cpu, wall=wall, error=err, status=r.status)
            rows.append(row)
            log(f"  {method:6s} {row['param']} {tol:8.2e}: nfev {r.nfev:6d}  {wall:7.3f} s wall  error {err:.2e}"
                + ("" if r.status == "ok" else f"  [{r.status}: {r.message}]"))
    return rows


def rk4_orders(rows) -> list:
    """Observed order ``log2(e(h) / e(h/2))`` for consecutive halvings of the RK4 step."""
    rk = sorted((r for r in rows if r["method"] == "RK4" and r["status"] == "ok"), key=lambda r: -r["tol"])
    out = []
    for a, b in zip(rk, rk[1:]):
        if math.isclose(a["tol"], 2 * b["tol"]) and a["error"] > 0 and b["error"] > 0:
            out.append(dict(dt=b["tol"], ratio=a["error"] / b["error"], order=math.log2(a["error"] / b["error"])))
    return out


def cheapest(rows, target: float, key: str = "wall"):
    """Per method, the cheapest measured run with ``error <= target`` (by ``key``); sorted cheapest first."""
    best = {}
    for r in rows:
        if r["status"] == "ok" and r["error"] <= target:
            if r["method"] not in best or r[key] < best[r["method"]][key]:
                best[r["method"]] = r
    return sorted(best.values(), key=lambda r: r[key])


# --------------------------------------------------------------------------- drift
def drift_one(t_end: float, stab: str, params: dict, rtol: float) -> dict:
    """The slider-crank over ``t_end`` with one stabilisation: drift of energy and residuals per step."""
    label = stab + ("" if not params else " (" + ", ".join(f"{k} = {v:g}" for k, v in params.items()) + ")")
    r, cpu, wall = integrate(crank_system(t_end), "DOP853", rtol=rtol, stabilization=stab, **params)
    scale = max(abs(float(r.energy[0])), float(np.max(r.kinetic)), np.finfo(float).tiny)
    dE = np.abs(r.energy - r.energy[0]) / scale
    pos, vel = r.extra["position_residual"], r.extra["velocity_residual"]
    row = dict(label=label, stabilization=stab, params=params, status=r.status, nfev=r.nfev,
               steps=len(r.t) - 1, cpu=cpu, wall=wall, t=r.t, dE=dE, pos=pos, vel=vel,
               max_dE=float(dE.max()), max_pos=float(pos.max()), max_vel=float(vel.max()),
               end_dE=float(dE[-1]), end_pos=float(pos[-1]), end_vel=float(vel[-1]))
    log(f"  {label:32s}: nfev {r.nfev:6d}  {cpu:6.1f} s CPU  max |ΔE|/E {row['max_dE']:.2e}  "
        f"max |φ| {row['max_pos']:.2e}  max |J q̇| {row['max_vel']:.2e}")
    return row


def drift_study(t_end: float, stabilisations, rtol: float, jobs: int = 1) -> list:
    """:func:`drift_one` for every stabilisation, ``jobs`` runs at a time (separate processes)."""
    tasks = [(t_end, stab, params, rtol) for stab, params in stabilisations]
    if jobs <= 1 or len(tasks) == 1:
        return [drift_one(*a) for a in tasks]
    from concurrent.futures import ProcessPoolExecutor

    # the costliest first (Baumgarte corrects every evaluation) so that the workers finish together
    order = sorted(range(len(tasks)), key=lambda i: -(2 if tasks[i][1] == "both" else
                                                        1 if tasks[i][1] == "baumgarte" else 0))
    with ProcessPoolExecutor(max_workers=jobs) as pool:
        futures = {i: pool.submit(drift_one, *tasks[i]) for i in order}
        return [futures[i].result() for i in range(len(tasks))]


# --------------------------------------------------------------------------- output
def _e(x) -> str:
    if x is None or (isinstance(x, float) and not math.isfinite(x)):
        return "—"
    return f"{x:.2e}"


def _tol(r) -> str:
    return f"dt = {r['tol']:.4g}" if r["param"] == "dt" else f"rtol = {r['tol']:.0e}"


def inversions(rows) -> list:
    """Pairs where a tighter tolerance (or smaller step) gave a *larger* error at t_end."""
    out = []
    for m in METHODS:
        rr = sorted((r for r in rows if r["method"] == m and r["status"] == "ok"), key=lambda r: -r["tol"])
        for a, b in zip(rr, rr[1:]):
            if b["error"] > a["error"]:
                out.append((a, b))
    return out


def conclusions(res: dict) -> list:
    lines = []
    for key in ("chain", "crank"):
        sysres = res[key]
        rows = sysres["rows"]
        floor = sysres["ref"].get("check", {}).get("disagreement")
        targets = [t for t in (1e-3, 1e-6, 1e-9) if floor is None or t > 10 * floor]
        parts = []
        for tgt in targets:
            c = cheapest(rows, tgt)
            if not c:
                parts.append(f"error ≤ {tgt:.0e}: no run reached it")
                continue
            w = c[0]
            s = f"error ≤ {tgt:.0e}: **{w['method']}** ({_tol(w)}, {w['nfev']} evaluations, {w['wall']:.2g} s)"
            if len(c) > 1:
                s += ", then " + ", ".join(f"{o['method']} ×{o['wall'] / w['wall']:.1f}" for o in c[1:])
                if c[1]["wall"] < 1.3 * w["wall"]:
                    s += (f" (a tie within the timing noise: {w['method']} {w['nfev']} vs {c[1]['method']} "
                          f"{c[1]['nfev']} evaluations)")
            missing = [m for m in METHODS if m not in {o["method"] for o in c}]
            if missing:
                s += " (not reached by " + ", ".join(missing) + ")"
            parts.append(s)
        lines.append(f"* **{sysres['label']}** — cheapest run (wall time) reaching " + "; ".join(parts) + ".")
        orders = sysres["rk4_orders"]
        if orders:
            lines.append("  RK4's error falls by " + ", ".join(f"×{o['ratio']:.1f}" for o in orders)
                         + " on successive halvings of dt (4th order: ×16 once asymptotic; "
                         + f"the last {min(2, len(orders))}: order "
                         + " and ".join(f"{o['order']:.2f}" for o in orders[-2:]) + ").")
        inv = inversions(rows)
        if inv:
            lines.append("  The error at one instant is not monotone in the tolerance: "
                         + "; ".join(f"{a['method']} {_tol(a)} → {_e(a['error'])}, {_tol(b)} → {_e(b['error'])}"
                                     for a, b in inv) + ".")
    drift = res["drift"]
    none = next(r for r in drift if r["stabilization"] == "none")
    T = res["config"]["drift_t"]
    lines.append(f"* **Drift over {T:g} s** (DOP853, rtol = {res['config']['drift_rtol']:.0e}): without "
                 f"stabilisation the loop opens steadily, to |φ| = {none['max_pos']:.1e} and "
                 f"|J_c q̇| = {none['max_vel']:.1e}.")
    for r in drift:
        if r is none:
            continue
        lines.append(f"  {r['label']}: |φ| ≤ {r['max_pos']:.1e} (×{r['max_pos'] / max(none['max_pos'], 1e-300):.0e} "
                     f"of none), |J_c q̇| ≤ {r['max_vel']:.1e}, at ×{r['nfev'] / none['nfev']:.2f} the evaluations "
                     f"and ×{r['cpu'] / none['cpu']:.1f} the CPU time of none.")
    dEs = [r["max_dE"] for r in drift]
    if min(dEs) > 0.1 * none["max_dE"]:
        lines.append(f"  Energy (conserved by the exact motion) drifts by {min(dEs):.0e}–{max(dEs):.0e} (relative) with "
                     "*every* variant, none included: the stabilisations restore the loop closure, not the energy; "
                     "the energy error is the integrator's (set by rtol).")
    else:
        lines.append(f"  Energy (conserved by the exact motion) drifts by {none['max_dE']:.0e} without stabilisation, "
                     + ", ".join(f"{r['max_dE']:.0e} with {r['label']}" for r in drift if r is not none) + ".")
    baum = sorted((r for r in drift if r["stabilization"] == "baumgarte"), key=lambda r: r["params"]["alpha"])
    if len(baum) > 1:
        falls = all(b["max_pos"] < a["max_pos"] for a, b in zip(baum, baum[1:]))
        lines.append("  Baumgarte corrects the accelerations at every evaluation (a mass matrix and a closure Jacobian "
                     "each time, hence its CPU cost) and holds the position residual at a level that "
                     + ("falls" if falls else "does not consistently fall") + " as α = β grows ("
                     + ", ".join(f"{b['params']['alpha']:g}/s: {b['max_pos']:.1e}" for b in baum) + ").")
    proj = [r for r in drift if r["stabilization"] in ("projection", "both")]
    if proj:
        held = all(max(r["max_pos"], r["max_vel"]) < 1e-9 for r in proj)
        lines.append("  Projection acts only when a residual exceeds its trigger (1e-10) and "
                     + ("holds both residuals within a step's drift of it (< 1e-9) for the whole run"
                        if held else "does not hold both residuals below 1e-9 for the whole run") + ".")
    return lines


def write_markdown(res: dict, path: Path) -> None:
    cfg = res["config"]
    L = ["# Integrators: work–precision and loop-closure drift", "",
         f"Generated by `python benchmarks/integrators.py{' --quick' if res['quick'] else ''}` "
         f"({res['date']}, {res['machine']}; total {res['elapsed']:.0f} s wall).  "
         "Charts: [`integrators.svg`](integrators.svg) (work–precision), "
         "[`integrators_drift.svg`](integrators_drift.svg) (drift).", "",
         "## Method", "",
         "Each system is integrated with scipy's `RK23`, `RK45`, `DOP853`, `Radau`, `BDF` and `LSODA` "
         f"over a range of `rtol` (`atol = {ATOL_FACTOR:g} rtol`) and with fixed-step classical `RK4` over a range "
         "of `dt`, all through `planargeo.simulate.simulate` (for the slider-crank, the loop solver as "
         "`simulate_loops(stabilization=\"none\")` uses it).  "
         "**Error** is `‖y(t_end) − y_ref(t_end)‖∞` over the state `y = (q, q̇)` (rad, rad/s) against a "
         "reference run of `DOP853` at `rtol = 1e-13`, `atol = 1e-14`; the reference itself is checked against a "
         "second, independent run and their disagreement is its error floor (errors near it are not resolved).  "
         "**Cost** is the number of dynamics evaluations (`nfev`; for `Radau`, `BDF` and `LSODA` it includes the "
         "finite-difference Jacobians) and the **wall time** of the run (charted, as the issue asks; thread CPU "
         "time is tabulated as well — where the two differ the machine was busy; both vary by some tens of per "
         "cent between runs under load, the `nfev` panels do not)."
         + (f"  Runs cheaper than {cfg['repeat_below']:g} s wall are repeated (best of 3)." if cfg["repeat_below"] else ""),
         "",
         f"* **Free chain**: `chain_model({cfg['chain_n']})` (uniform unit links, g = 9.81, τ = 0), "
         f"q0 = {list(res['chain']['q0'])}, q̇0 = {list(res['chain']['qd0'])}, t_end = {cfg['chain_t']:g} s.",
         f"* **Slider-crank** (scene `slider-crank`, thesis 9.6: ψ = 0.4, ψ̇ = 20 rad/s, free crank, g = 9.81), "
         f"t_end = {cfg['crank_t']:g} s, integrated by `simulate_loops(..., stabilization=\"none\")`: the ODE "
         "`q̈ = f(q, q̇)` of the constrained algorithm itself, so that the error is the integrator's alone.", ""]
    for key in ("chain", "crank"):
        s = res[key]
        ref = s["ref"]
        L += [f"## Work–precision: {s['label']}", "",
              f"Reference: {ref['desc']} ({ref['nfev']} evaluations, {ref['cpu']:.1f} s CPU)."]
        if "check" in ref:
            c = ref["check"]
            L += [f"Check: {c['desc']} ({c['nfev']} evaluations): disagreement **{_e(c['disagreement'])}** "
                  "— the reference's own error floor."]
        L += ["", "| method | tol / dt | nfev | steps | CPU s | wall s | error at t_end |", "|---|---|---:|---:|---:|---:|---:|"]
        for r in s["rows"]:
            err = _e(r["error"]) if r["status"] == "ok" else f"{r['status']}"
            L.append(f"| {r['method']} | {_tol(r)} | {r['nfev']} | {r['steps']} | {r['cpu']:.3f} | {r['wall']:.3f} | {err} |")
        if s["rk4_orders"]:
            L += ["", "RK4 on halving dt: " + ", ".join(f"dt = {o['dt']:.4g}: ×{o['ratio']:.1f} (order {o['order']:.2f})"
                                                        for o in s["rk4_orders"]) + "."]
        L.append("")
    L += [f"## Drift: slider-crank over {cfg['drift_t']:g} s", "",
          f"`simulate_loops` with `DOP853`, `rtol = {cfg['drift_rtol']:.0e}`, `atol = {ATOL_FACTOR * cfg['drift_rtol']:.0e}`, "
          "from the scene's closed state, each stabilisation it offers (projection: default trigger 1e-10, tol 1e-12). "
          "Energy is conserved by the exact motion (free crank, no drive): `|ΔE|/E` is "
          "`max_t |E(t) − E(0)| / max(|E(0)|, max T)`; `|φ|` the largest position residual of the slider "
          "contact, `|J_c q̇|` the largest velocity residual."
          + (f"  The runs went {res['jobs']} at a time (separate processes): their CPU times include some "
             "contention." if res.get("jobs", 1) > 1 else ""), "",
          "| stabilisation | nfev | steps | CPU s | max \\|ΔE\\|/E | max \\|φ\\| | max \\|J_c q̇\\| | \\|φ\\| at end | \\|J_c q̇\\| at end |",
          "|---|---:|---:|---:|---:|---:|---:|---:|---:|"]
    for r in res["drift"]:
        L.append(f"| {r['label']} | {r['nfev']} | {r['steps']} | {r['cpu']:.1f} | {_e(r['max_dE'])} | {_e(r['max_pos'])} | "
                 f"{_e(r['max_vel'])} | {_e(r['end_pos'])} | {_e(r['end_vel'])} |")
    L += ["", "## Conclusions (from the numbers above)", ""] + conclusions(res) + [""]
    L += res.get("notes", [])
    path.write_text("\n".join(L) + "\n")


def plot(res: dict, out_dir: Path) -> None:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    plt.rcParams["svg.hashsalt"] = "planargeo"
    fig, axes = plt.subplots(2, 2, figsize=(11, 8.5))
    for col, key in enumerate(("chain", "crank")):
        s = res[key]
        floor = s["ref"].get("check", {}).get("disagreement")
        for row, xkey, xlabel in ((0, "wall", "wall time of the run (s)"), (1, "nfev", "dynamics evaluations")):
            ax = axes[row, col]
            for m in METHODS:
                pts = [r for r in s["rows"] if r["method"] == m and r["status"] == "ok" and r["error"] > 0]
                if not pts:
                    continue
                ax.loglog([p[xkey] for p in pts], [p["error"] for p in pts], marker=MARKERS[m], color=COLORS[m],
                          label=m + (" (fixed dt)" if m == "RK4" else " (rtol sweep)"))
            if floor:
                ax.axhline(floor, color="0.5", ls="--", lw=1, label="reference error floor")
            ax.set_xlabel(xlabel)
            ax.set_ylabel("error ‖y − y_ref‖∞ at t_end")
            ax.grid(True, which="major", alpha=0.3)
            if row == 0:
                ax.set_title(s["label"], fontsize=10)
            ax.legend(fontsize=8)
    fig.suptitle("Work–precision: error at t_end against cost (wall time, top; dynamics evaluations, bottom)", fontsize=10)
    fig.tight_layout()
    for ext in ("svg", "png"):
        fig.savefig(out_dir / f"integrators.{ext}", dpi=100, metadata={"Date": None} if ext == "svg" else None)
    plt.close(fig)

    fig, axes = plt.subplots(1, 3, figsize=(15, 4.6))
    tiny = 1e-17
    for i, r in enumerate(res["drift"]):
        for ax, key in zip(axes, ("dE", "pos", "vel")):
            ax.semilogy(r["t"], np.maximum(r[key], tiny), color=f"C{i}", lw=1, label=r["label"])
    for ax, title in zip(axes, ("relative energy drift |E(t) − E(0)| / E", "position residual max |φ(q)|",
                                "velocity residual max |J_c q̇|")):
        ax.set_title(title, fontsize=10)
        ax.set_xlabel("t (s)")
        ax.grid(True, which="major", alpha=0.3)
    axes[0].set_ylim(bottom=1e-10)
    axes[0].legend(fontsize=8)
    fig.suptitle(f"Slider-crank, free crank, DOP853 rtol = {res['config']['drift_rtol']:.0e}: drift per stabilisation "
                 f"(residuals below {tiny:g} drawn at {tiny:g})", fontsize=11)
    fig.tight_layout()
    for ext in ("svg", "png"):
        fig.savefig(out_dir / f"integrators_drift.{ext}", dpi=100, metadata={"Date": None} if ext == "svg" else None)
    plt.close(fig)


# --------------------------------------------------------------------------- driver
def run(out_dir, quick: bool = False, jobs: int | None = None) -> dict:
    """Run the study and write ``integrators.md`` and the charts to ``out_dir``; returns the results.

    ``jobs``: drift runs at a time, in separate processes (default: 2, or 1 on a single CPU); the
    work–precision runs are always timed one at a time.
    """
    jobs = min(2, os.cpu_count() or 1) if jobs is None else max(1, int(jobs))
    out_dir = Path(out_dir)
    out_dir.mkdir(parents=True, exist_ok=True)
    cfg = CONFIGS["quick" if quick else "full"]
    t0 = time.perf_counter()
    res = dict(quick=quick, config=cfg, date=time.strftime("%Y-%m-%d"),
               machine=f"{platform.machine()}, {os.cpu_count()} CPUs, Python {platform.python_version()}")
    # warm up (imports, first-call costs)
    integrate(chain_system(2, 0.01), "DOP853", rtol=1e-6)
    integrate(crank_system(0.002), "DOP853", rtol=1e-6)

    chain = chain_system(cfg["chain_n"], cfg["chain_t"])
    log(f"work-precision: {chain['label']}")
    ref = reference(chain, cfg["chain_check"])
    rows = work_precision(chain, cfg["chain_grid"], ref["y"], cfg["repeat_below"])
    res["chain"] = dict(label=chain["label"], q0=chain["q0"].tolist(), qd0=chain["qd0"].tolist(), ref=ref,
                        rows=rows, rk4_orders=rk4_orders(rows))

    crank = crank_system(cfg["crank_t"])
    log(f"work-precision: {crank['label']}")
    ref = reference(crank, "lagrange" if cfg["crank_check"] else None)
    rows = work_precision(crank, cfg["crank_grid"], ref["y"], cfg["repeat_below"])
    res["crank"] = dict(label=crank["label"], ref=ref, rows=rows, rk4_orders=rk4_orders(rows))

    log(f"drift: slider-crank over {cfg['drift_t']:g} s, DOP853 rtol {cfg['drift_rtol']:g}, {jobs} run(s) at a time")
    res["drift"] = drift_study(cfg["drift_t"], cfg["stabilisations"], cfg["drift_rtol"], jobs)
    res["jobs"] = jobs

    res["elapsed"] = time.perf_counter() - t0
    log("writing tables and charts")
    write_markdown(res, out_dir / "integrators.md")
    plot(res, out_dir)
    return res


def main(argv=None) -> int:
    p = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    p.add_argument("--quick", action="store_true", help="small grids and short horizons (under a minute)")
    p.add_argument("--out", default=str(HERE / "results"), help="output directory (default: %(default)s)")
    p.add_argument("--jobs", type=int, default=None,
                   help="drift runs at a time, in separate processes (default: 2, or 1 on a single CPU)")
    a = p.parse_args(argv)
    run(a.out, quick=a.quick, jobs=a.jobs)
    return 0


if __name__ == "__main__":
    sys.exit(main())
