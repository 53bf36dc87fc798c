"""Physics claims of the integrator study (``benchmarks/integrators.py``), on tiny configurations.

The references come from outside the code under test:

* the compound pendulum (``chain_model(1)``, a uniform unit rod about its end) released from
  rest at an angle ``θ0`` from the hanging position has the closed-form motion
  ``θ(t) = 2 arcsin(k sn(K - ω0 t | k²))``, ``θ̇ = -2 k ω0 cn(K - ω0 t | k²)``,
  ``k = sin(θ0/2)``, ``ω0² = m g (L/2) / (m L²/3)``, period ``4 K(k²) / ω0``
  (``2π/ω0`` for small swings) — Jacobi elliptic functions from scipy;
* energy conservation of free conservative mechanisms (a law), with the energy written here by
  hand from the link geometry (uniform rods; the slider-crank's bodies of thesis 9.6);
* the slider-crank's loop closure written by hand from its geometry:
  ``ψ + θ + φ = π/2`` and ``r cos ψ + l cos(ψ + θ) = 0`` (and their time derivatives).

No timing is asserted.
"""
import importlib.util
import math
import os
from pathlib import Path

import numpy as np
import pytest
from scipy.special import ellipj, ellipk

from planargeo.mechanics.model import chain_model
from planargeo.scenes.slider_crank import slider_crank_model, slider_crank_state
from planargeo.simulate.integrate import energy, simulate
from planargeo.simulate.loops import simulate_loops

ROOT = Path(__file__).resolve().parent.parent
G = 9.81


def _study():
    spec = importlib.util.spec_from_file_location("_integrators_study", ROOT / "benchmarks" / "integrators.py")
    mod = importlib.util.module_from_spec(spec)
    env = dict(os.environ)
    try:
        spec.loader.exec_module(mod)
    finally:                      # the script pins BLAS threads for itself; leave the test session's environment alone
        os.environ.clear()
        os.environ.update(env)
    return mod


@pytest.fixture(scope="module")
def study():
    return _study()


# --------------------------------------------------------------------------- independent references
W0 = math.sqrt(1.0 * G * 0.5 / (1.0 / 3.0))          # unit rod about its end: ω0² = m g (L/2) / (m L²/3)


def pendulum_exact(theta0, t):
    """Angle from the hanging position and its rate, released from rest at ``theta0``."""
    k = math.sin(theta0 / 2)
    K = ellipk(k * k)
    sn, cn, _, _ = ellipj(K - W0 * np.asarray(t, dtype=float), k * k)
    return 2 * np.arcsin(k * sn), -2 * k * W0 * cn


def pendulum_run(theta0, t_end, **kw):
    """``chain_model(1)`` (q measured from +x; hanging is q = -π/2) released at rest ``theta0`` from hanging."""
    r = simulate(chain_model(1), [-math.pi / 2 + theta0], [0.0], t_end, **kw)
    assert r.status == "ok"
    return r


def pendulum_error(theta0, r):
    th, thd = pendulum_exact(theta0, r.t[-1])
    return max(abs(r.q[-1, 0] + math.pi / 2 - th), abs(r.qd[-1, 0] - thd))


def serial_energy(q, qd, placements, coms, masses, inertias, g=G):
    """Kinetic + potential energy of a serial revolute chain whose joints and centres of mass lie
    on each link's x axis: joint i at ``placements[i]`` along link i-1, com at ``coms[i]`` along link i,
    ``inertias`` about the com; gravity ``g`` along -y.  Written from the geometry alone."""
    a = np.cumsum(q)
    ad = np.cumsum(qd)
    o = np.zeros(2)
    vo = np.zeros(2)
    T = V = 0.0
    for i in range(len(q)):
        if i > 0:
            e = np.array([math.cos(a[i - 1]), math.sin(a[i - 1])])
            o = o + placements[i] * e
            vo = vo + placements[i] * ad[i - 1] * np.array([-e[1], e[0]])
        e = np.array([math.cos(a[i]), math.sin(a[i])])
        c = o + coms[i] * e
        vc = vo + coms[i] * ad[i] * np.array([-e[1], e[0]])
        T += 0.5 * masses[i] * vc @ vc + 0.5 * inertias[i] * ad[i] ** 2
        V += masses[i] * g * c[1]
    return T + V, T


def chain_energy(q, qd):
    n = len(q)
    return serial_energy(q, qd, [0.0] + [1.0] * (n - 1), [0.5] * n, [1.0] * n, [1.0 / 12] * n)


R_, L_, T_ = 2.29, 5.00, 0.5                       # slider-crank geometry (thesis 9.6 defaults)
M_ = (0.40, 0.15, 0.30)
I_ = (0.1464 * M_[0] * R_ ** 2, 0.0866 * M_[1] * L_ ** 2, 0.666 * M_[2] * T_ ** 2)


def crank_energy(q, qd):
    return serial_energy(q, qd, [0.0, R_, L_], [R_ / 4, L_ / 2, T_], M_, I_)


def crank_closure(q, qd):
    """Hand-written loop closure of the slider-crank: position and velocity residuals."""
    psi, theta, phi = q
    b = psi + theta
    pos = [psi + theta + phi - math.pi / 2, R_ * math.cos(psi) + L_ * math.cos(b)]
    vel = [sum(qd), -R_ * math.sin(psi) * qd[0] - L_ * math.sin(b) * (qd[0] + qd[1])]
    return np.abs(pos).max(), np.abs(vel).max()


# --------------------------------------------------------------------------- the references themselves
def test_exact_pendulum_solution_is_consistent():
    # the closed form starts at rest at theta0, and its small-swing period is 2π/ω0
    th, thd = pendulum_exact(1.0, 0.0)
    assert th == pytest.approx(1.0, abs=1e-14) and thd == pytest.approx(0.0, abs=1e-14)
    assert 4 * ellipk(math.sin(0.005) ** 2) / W0 == pytest.approx(2 * math.pi / W0, rel=1e-5)
    # hand-written energies agree with the package's at one state (geometry read correctly)
    q, qd = np.array([0.3, -0.7, 1.1]), np.array([0.4, 2.0, -1.0])
    T, V = energy(chain_model(3), q, qd)
    assert chain_energy(q, qd) == pytest.approx((float(T + V), float(T)), rel=1e-12)
    q, qd = slider_crank_state()
    T, V = energy(slider_crank_model(), q, qd)
    assert crank_energy(q, qd) == pytest.approx((float(T + V), float(T)), rel=1e-12)


# --------------------------------------------------------------------------- integrator claims
def test_rk4_error_falls_like_dt4_against_the_closed_form():
    errs = [pendulum_error(1.0, pendulum_run(1.0, 1.0, method="RK4", dt=dt)) for dt in (0.04, 0.02, 0.01)]
    ratios = [errs[0] / errs[1], errs[1] / errs[2]]
    assert all(8 < x < 32 for x in ratios), (errs, ratios)          # 2^4 = 16 per halving
    assert errs[-1] < 1e-5


def test_rk4_error_falls_like_dt4_on_the_study_chain(study):
    # the study's own error measure on its chain (short horizon): self-convergence of the final state
    sysm = study.chain_system(3, 0.5)
    ys = [study.final_state(study.integrate(sysm, "RK4", dt=dt)[0]) for dt in (0.02, 0.01, 0.005, 0.0025)]
    e = [study.state_error(a, b) for a, b in zip(ys, ys[1:])]           # e_k ≈ (1 - 1/16) C h_k^4
    assert all(8 < x < 32 for x in (e[0] / e[1], e[1] / e[2])), e


def test_period_matches_the_elliptic_closed_form():
    for theta0 in (0.01, 1.0, 2.5):
        T = 4 * ellipk(math.sin(theta0 / 2) ** 2) / W0
        r = pendulum_run(theta0, T, method="DOP853", rtol=1e-11, atol=1e-13)
        assert abs(r.q[-1, 0] - (-math.pi / 2 + theta0)) < 1e-9
        assert abs(r.qd[-1, 0]) < 1e-8
    # small swings: the period is 2π/ω0 (the pendulum is back at rest where it started)
    r = pendulum_run(0.01, 2 * math.pi / W0, method="DOP853", rtol=1e-11, atol=1e-13)
    assert abs(r.q[-1, 0] + math.pi / 2 - 0.01) < 1e-9


def test_dop853_tight_beats_rk45_loose_and_error_follows_rtol():
    e_rk45 = pendulum_error(2.0, pendulum_run(2.0, 2.0, method="RK45", rtol=1e-6, atol=1e-8))
    e_dop = {rt: pendulum_error(2.0, pendulum_run(2.0, 2.0, method="DOP853", rtol=rt, atol=1e-2 * rt))
             for rt in (1e-4, 1e-7, 1e-10)}
    assert e_dop[1e-10] < 1e-8
    assert e_rk45 > 100 * e_dop[1e-10]
    assert e_dop[1e-4] > e_dop[1e-7] > e_dop[1e-10]
    # Radau, an implicit method, agrees with the closed form too
    assert pendulum_error(2.0, pendulum_run(2.0, 2.0, method="Radau", rtol=1e-8, atol=1e-10)) < 1e-5


def test_free_chain_conserves_energy_and_tight_reference_agrees_with_radau(study):
    sysm = study.chain_system(3, 1.0)
    r, _, _ = study.integrate(sysm, "DOP853", rtol=1e-11, atol=1e-13)
    E = np.array([chain_energy(q, qd)[0] for q, qd in zip(r.q, r.qd)])
    Tmax = max(chain_energy(q, qd)[1] for q, qd in zip(r.q, r.qd))
    assert np.abs(E - E[0]).max() < 1e-9 * max(abs(E[0]), Tmax)
    # coarse RK4 breaks the law visibly, and less with a smaller step (≈ dt^4)
    drift = []
    for dt in (0.02, 0.01):
        rr, _, _ = study.integrate(sysm, "RK4", dt=dt)
        EE = np.array([chain_energy(q, qd)[0] for q, qd in zip(rr.q, rr.qd)])
        drift.append(np.abs(EE - EE[0]).max())
    assert drift[0] > 4 * drift[1] > 0
    # the study's reference check: an implicit method agrees with DOP853 to far below the errors studied
    ref = study.reference(sysm, dict(method="Radau", rtol=1e-10, atol=1e-12))
    assert ref["check"]["disagreement"] < 1e-9


# --------------------------------------------------------------------------- loop stabilisation claims
@pytest.fixture(scope="module")
def crank_runs():
    m = slider_crank_model()
    q, qd = slider_crank_state()
    runs = {}
    for name, kw in (("none", {}), ("baumgarte", dict(alpha=20.0, beta=20.0)), ("projection", {})):
        r = simulate_loops(m, q, qd, 0.3, method="DOP853", rtol=1e-5, atol=1e-7, stabilization=name,
                           progress=False, **kw)
        assert r.status == "ok"
        pos, vel = np.array([crank_closure(a, b) for a, b in zip(r.q, r.qd)]).T
        E = np.array([crank_energy(a, b)[0] for a, b in zip(r.q, r.qd)])
        scale = max(abs(E[0]), max(crank_energy(a, b)[1] for a, b in zip(r.q, r.qd)))
        runs[name] = dict(pos=pos.max(), vel=vel.max(), dE=np.abs(E - E[0]).max() / scale)
    return runs


def test_projection_keeps_the_closure_while_none_drifts(crank_runs):
    p, n = crank_runs["projection"], crank_runs["none"]
    assert p["pos"] < 1e-9 and p["vel"] < 1e-8           # trigger 1e-10 (plus a step's drift, re-measured here)
    assert n["pos"] > 1e4 * p["pos"] and n["vel"] > 1e4 * p["vel"]


def test_baumgarte_reduces_the_drift(crank_runs):
    b, n = crank_runs["baumgarte"], crank_runs["none"]
    assert b["pos"] < 0.2 * n["pos"]


def test_slider_crank_energy_is_conserved_to_the_tolerance(crank_runs):
    # a free crank conserves energy; at rtol 1e-5 every variant keeps it to ~1e-5 over 0.3 s
    for name, r in crank_runs.items():
        assert r["dE"] < 1e-4, (name, r)


# --------------------------------------------------------------------------- study helpers
def test_study_helpers(study):
    rows = [dict(method="RK4", tol=0.02, error=1.6e-3, status="ok", wall=1.0, nfev=10),
            dict(method="RK4", tol=0.01, error=1e-4, status="ok", wall=2.0, nfev=20),
            dict(method="DOP853", tol=1e-6, error=1e-5, status="ok", wall=0.5, nfev=30),
            dict(method="RK45", tol=1e-6, error=float("nan"), status="failed", wall=0.1, nfev=5)]
    (o,) = study.rk4_orders(rows)
    assert o["ratio"] == pytest.approx(16.0) and o["order"] == pytest.approx(4.0)
    assert [r["method"] for r in study.cheapest(rows, 1e-3)] == ["DOP853", "RK4"]
    assert study.cheapest(rows, 1e-6) == []
    assert study.state_error([1.0, 2.0], [1.0, 2.5]) == 0.5


# --------------------------------------------------------------------------- RK23, BDF, LSODA as the study runs them
def test_study_covers_every_scipy_method(study):
    assert set(study.METHODS) == {"RK23", "RK45", "DOP853", "Radau", "BDF", "LSODA", "RK4"}
    for cfg in study.CONFIGS.values():
        for key in ("chain_grid", "crank_grid"):
            assert set(cfg[key]) == set(study.METHODS)


@pytest.mark.parametrize("method, rtol, bound", [("RK23", 1e-7, 2e-5), ("BDF", 1e-8, 1e-6), ("LSODA", 1e-9, 3e-7)])
def test_study_runs_of_rk23_bdf_lsoda_match_the_elliptic_pendulum(study, method, rtol, bound):
    # The study's integrate (simulate, with the study's atol = 1e-2 rtol) for the methods added to simulate;
    # tests/test_simulate_methods.py checks simulate itself at atol 1e-11, this checks the study's wrapper
    # and that its rtol reaches the solver.  Against the closed form (Jacobi elliptic functions), released at 2 rad from hanging, 2 s
    # (measured: RK23 3.6e-6, BDF 9.8e-8, LSODA 2.6e-8).
    theta0, t_end = 2.0, 2.0
    sysm = dict(name="pendulum", label="", model=chain_model(1), q0=np.array([-math.pi / 2 + theta0]),
                qd0=np.array([0.0]), t_end=t_end, loops=False)
    r, cpu, wall = study.integrate(sysm, method, rtol=rtol)
    assert r.status == "ok" and r.nfev > 0 and wall > 0
    assert abs(r.t[-1] - t_end) < 1e-12
    err = pendulum_error(theta0, r)
    assert err < bound, err
    # a looser tolerance is visibly worse: the tolerance reaches the solver
    r2, _, _ = study.integrate(sysm, method, rtol=1e-3)
    assert pendulum_error(theta0, r2) > 10 * err


@pytest.mark.parametrize("method", ["BDF", "LSODA"])
def test_study_runs_of_bdf_lsoda_on_the_slider_crank_conserve_energy(study, method):
    # the loop solver's ODE through the study's integrate (simulate_loops(stabilization="none")): energy,
    # written here from the mechanism's geometry (test_simulate_methods compares against DOP853 instead), is conserved to about the tolerance over 0.1 s
    sysm = study.crank_system(0.1)
    r, _, _ = study.integrate(sysm, method, rtol=1e-7)
    assert r.status == "ok"
    E = np.array([crank_energy(a, b)[0] for a, b in zip(r.q, r.qd)])
    scale = max(abs(E[0]), max(crank_energy(a, b)[1] for a, b in zip(r.q, r.qd)))
    assert np.abs(E - E[0]).max() / scale < 2e-5              # measured: BDF 2.1e-6, LSODA 7.4e-7
    pos, vel = np.array([crank_closure(a, b) for a, b in zip(r.q, r.qd)]).T
    assert pos.max() < 1e-5 and vel.max() < 1e-4               # no stabilisation: only the integrator's drift
