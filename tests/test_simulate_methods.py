"""scipy's RK23, BDF and LSODA through simulate/simulate_loops: accuracy against references from
outside the code (the exact elliptic-function pendulum, a DOP853 run at rtol 1e-12), energy drift to
the documented tolerances, and the same per-step diagnostics as the other methods."""
import numpy as np
import pytest
from scipy.special import ellipj, ellipk

from planargeo.errors import InputError, SingularConfigurationError
from planargeo.mechanics.model import chain_model
from planargeo.scenes.slider_crank import slider_crank_model, slider_crank_state
from planargeo.simulate.integrate import METHODS, MULTISTEP, simulate
from planargeo.simulate.loops import closure_residual, simulate_loops

NEW = ("RK23", "BDF", "LSODA")

# Documented tolerances (docs/simulation.md, table "The tolerances, once"; measured values there)
TOLERANCES = {"pendulum-exact": 1e-7, "pendulum-energy": 2e-7, "chain-new-energy": 2e-7,
              "chain-new-reference": 3e-5}

# The uniform unit rod of chain_model(1) as a physical pendulum: J = 1/3 about the pivot, centre of
# mass at d = 1/2, m = 1, g = 9.81 (q = 0 horizontal, hanging at q = -π/2).
G, J, D = 9.81, 1.0 / 3.0, 0.5
W0 = np.sqrt(G * D / J)
THETA0 = 1.0                                   # released from rest 1 rad from the bottom


def exact_pendulum(t):
    """θ(t) = 2 arcsin(k sn(K − ω₀t | k²)), k = sin(θ₀/2): released from rest at θ₀ (period 4K/ω₀)."""
    k = np.sin(THETA0 / 2)
    sn, _, _, _ = ellipj(ellipk(k * k) - W0 * np.asarray(t), k * k)
    return 2 * np.arcsin(k * sn)


def period():
    k = np.sin(THETA0 / 2)
    return 4 * ellipk(k * k) / W0


def test_documented_tolerances_match_the_tests():
    from test_simulate import documented_bounds

    doc = documented_bounds()
    for key, bound in TOLERANCES.items():
        assert doc[key] == bound, key


def test_methods_offered():
    assert set(NEW) <= set(METHODS) and set(MULTISTEP) == {"BDF", "LSODA"}


@pytest.mark.parametrize("method", NEW)
def test_pendulum_against_the_exact_elliptic_solution(method):
    """Documented (pendulum-exact, pendulum-energy): one full period of the large-amplitude (1 rad)
    pendulum at rtol 1e-9, atol 1e-11; every recorded angle within 1e-7 of the closed form
    (measured RK23 1.0e-8, BDF 1.4e-8, LSODA 4.0e-9), energy drift below 2e-7, back at the start."""
    T = period()
    # the period against its amplitude series 1 + θ²/16 + 11θ⁴/3072 + 173θ⁶/737280 + O(θ⁸)
    series = 1 + THETA0 ** 2 / 16 + 11 * THETA0 ** 4 / 3072 + 173 * THETA0 ** 6 / 737280
    assert T == pytest.approx(2 * np.pi / W0 * series, rel=2e-5)
    r = simulate(chain_model(1), [-np.pi / 2 + THETA0], [0.0], T, method=method, rtol=1e-9, atol=1e-11)
    assert r.status == "ok" and r.method == method and r.t[-1] == pytest.approx(T, rel=1e-14)
    assert len(r.t) > 20 and np.all(np.diff(r.t) > 0)
    err = np.abs(r.q[:, 0] + np.pi / 2 - exact_pendulum(r.t))
    assert err.max() < TOLERANCES["pendulum-exact"]
    assert r.energy_drift() < TOLERANCES["pendulum-energy"]
    # per-step energy: T + V by hand from the angle (V = m g d sin q, T = ½ J q̇²)
    np.testing.assert_allclose(r.potential, G * D * np.sin(r.q[:, 0]), atol=1e-12)
    np.testing.assert_allclose(r.kinetic, 0.5 * J * r.qd[:, 0] ** 2, atol=1e-12)
    assert abs(r.q[-1, 0] - (-np.pi / 2 + THETA0)) < 1e-7 and abs(r.qd[-1, 0]) < 1e-6


@pytest.fixture(scope="module")
def chain_reference():
    """The free 3-link chain over 2 s by DOP853 at rtol 1e-12 (an independent integrator)."""
    return simulate(chain_model(3), [0.3, 0.5, -0.2], [0.0, 1.0, 0.0], 2.0, method="DOP853", rtol=1e-12,
                    atol=1e-14)


@pytest.mark.parametrize("method", NEW)
def test_free_chain_energy_and_reference(method, chain_reference):
    """Documented (chain-new-energy, chain-new-reference): free 3-link chain, 2 s, rtol 1e-9,
    atol 1e-11: energy drift below 2e-7 (measured RK23 2.5e-9, BDF 1.7e-8, LSODA 4.8e-9); final
    (q, q̇) within 3e-5 of DOP853 at rtol 1e-12 (measured 2.8e-7, 3.7e-6, 1.9e-6)."""
    r = simulate(chain_model(3), [0.3, 0.5, -0.2], [0.0, 1.0, 0.0], 2.0, method=method, rtol=1e-9, atol=1e-11)
    assert r.status == "ok" and r.t[-1] == 2.0
    assert r.energy_drift() < TOLERANCES["chain-new-energy"]
    err = np.abs(np.r_[r.q[-1] - chain_reference.q[-1], r.qd[-1] - chain_reference.qd[-1]]).max()
    assert err < TOLERANCES["chain-new-reference"]
    # a looser tolerance is measurably worse: the tolerance is obeyed, not ignored
    loose = simulate(chain_model(3), [0.3, 0.5, -0.2], [0.0, 1.0, 0.0], 2.0, method=method, rtol=1e-5,
                     atol=1e-7)
    err_loose = np.abs(np.r_[loose.q[-1] - chain_reference.q[-1], loose.qd[-1] - chain_reference.qd[-1]]).max()
    assert err_loose > 10 * err and loose.nfev < r.nfev


@pytest.mark.parametrize("method", NEW)
def test_diagnostics_hooks_and_dense_output(method):
    """The same per-step recording as the other methods: residual and condition hooks at every
    recorded step, an output grid with dt, nfev counting every evaluation (Jacobians included)."""
    m = chain_model(2)
    calls = {"n": 0}

    def forward(model, q, qd, tau, f_ext):
        calls["n"] += 1
        from planargeo.algorithms.aba import forward_dynamics
        return forward_dynamics(model, q, qd, tau, f_ext)

    r = simulate(m, [0.2, 0.4], [0.0, 1.0], 0.5, method=method, dt=0.05, rtol=1e-10, atol=1e-12, forward=forward,
                 residual=lambda q, qd: [q[1], qd[0]], condition=lambda q, qd: 1.0 + q[0] ** 2)
    np.testing.assert_allclose(r.t, np.linspace(0, 0.5, 11), atol=1e-12)
    assert r.residual.shape == (11, 2) and r.energy.shape == r.kinetic.shape == (11,)
    np.testing.assert_array_equal(r.residual[:, 0], r.q[:, 1])
    np.testing.assert_array_equal(r.cond, 1.0 + r.q[:, 0] ** 2)
    assert r.nfev == calls["n"] > 11
    # the sampled states are the integrator's: the same run recorded at every accepted step ends equal
    r2 = simulate(m, [0.2, 0.4], [0.0, 1.0], 0.5, method=method, rtol=1e-10, atol=1e-12)
    np.testing.assert_allclose(r.q[-1], r2.q[-1], atol=1e-12)


@pytest.mark.parametrize("method", NEW)
def test_singular_configuration_stops_cleanly(method):
    def forward(model, q, qd, tau, f_ext):
        if q[0] < -0.5:
            raise SingularConfigurationError("test singularity", 1e17)
        from planargeo.algorithms.aba import forward_dynamics
        return forward_dynamics(model, q, qd, tau, f_ext)

    r = simulate(chain_model(1), [0.0], [0.0], 3.0, method=method, forward=forward)
    assert r.status == "singular" and "test singularity" in r.message
    assert 0 < r.t[-1] < 3.0 and r.q[-1, 0] >= -0.5 - 1e-9 and len(r.t) == len(r.energy)
    assert r.events[-1]["kind"] == "singular" and r.events[-1]["cond"] == 1e17


# --------------------------------------------------------------------------- closed loops
@pytest.fixture(scope="module")
def crank():
    m = slider_crank_model()
    q, qd = slider_crank_state()
    ref = simulate_loops(m, q, qd, 0.1, method="DOP853", rtol=1e-12, atol=1e-14)
    return m, q, qd, ref


@pytest.mark.parametrize("method,stabilization,bound", [("RK23", "projection", 1e-6), ("BDF", "baumgarte", 2e-6),
                                                        ("LSODA", "baumgarte", 1e-6), ("LSODA", "none", 1e-6)])
def test_loops_with_the_new_methods(crank, method, stabilization, bound):
    """Slider-crank of 9.6, free, 0.1 s at rtol 1e-8: final q within ``bound`` of DOP853 at rtol 1e-12
    (measured RK23 1.8e-8, BDF 1.6e-7, LSODA 3.5e-8); residuals recorded at every step and equal to
    the contacts' own."""
    m, q, qd, ref = crank
    r = simulate_loops(m, q, qd, 0.1, method=method, rtol=1e-8, atol=1e-10, stabilization=stabilization)
    assert r.status == "ok" and r.method == method and r.t[-1] == pytest.approx(0.1)
    assert np.abs(r.q[-1] - ref.q[-1]).max() < bound
    k = len(r.t) // 2
    assert np.abs(closure_residual(m, r.q[k])).max() == pytest.approx(r.extra["position_residual"][k], abs=1e-15)
    assert r.cond is not None and len(r.cond) == len(r.t) and np.all(r.cond < 10)   # regular crank: cond ≤ 5.91
    if stabilization == "projection":
        assert r.extra["position_residual"].max() < 1e-9 and r.extra["velocity_residual"].max() < 1e-9
    else:
        assert r.extra["position_residual"].max() < 1e-6      # measured 7.7e-8 (BDF), 7.9e-9 (LSODA)


@pytest.mark.parametrize("method", MULTISTEP)
@pytest.mark.parametrize("stabilization", ["projection", "both"])
def test_projection_refused_for_multistep_methods(crank, method, stabilization):
    m, q, qd, _ = crank
    with pytest.raises(InputError, match=f"stabilization='{stabilization}'.*{method}.*baumgarte"):
        simulate_loops(m, q, qd, 0.1, method=method, stabilization=stabilization)
