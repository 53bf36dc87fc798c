"""Closed-loop simulation with stabilisation (planargeo.simulate_loops) on the slider-crank of 9.6."""
import numpy as np
import pytest

from planargeo.errors import InputError
from planargeo.scenes.slider_crank import slider_crank_model, slider_crank_state
from planargeo.simulate_loops import closure_jacobian, closure_residual, project_state, simulate_loops


@pytest.fixture(scope="module")
def crank():
    m = slider_crank_model()
    q, qd = slider_crank_state()
    return m, q, qd


def test_projection_keeps_loop_closed_and_energy(crank):
    m, q, qd = crank
    r = simulate_loops(m, q, qd, 0.2, rtol=1e-8)
    assert r.status == "ok"
    assert r.extra["position_residual"].max() < 1e-9          # trigger 1e-10 plus one step's drift
    assert r.extra["velocity_residual"].max() < 1e-9
    assert r.energy_drift() < 1e-7                             # measured 3e-9
    # recorded residuals are the contacts' own, recomputed independently here
    k = len(r.t) // 2
    assert np.abs(closure_residual(m, r.q[k])).max() == pytest.approx(r.extra["position_residual"][k], abs=1e-15)


def test_without_stabilization_the_loop_drifts_more(crank):
    m, q, qd = crank
    r0 = simulate_loops(m, q, qd, 0.2, rtol=1e-8, stabilization="none")
    r1 = simulate_loops(m, q, qd, 0.2, rtol=1e-8, stabilization="projection", trigger=1e-12)
    assert r0.extra["velocity_residual"].max() > 10 * r1.extra["velocity_residual"].max()


def test_baumgarte_pulls_a_violated_loop_back(crank):
    m, q, qd = crank
    qp = q + np.array([0.0, 2e-3, -1e-3])
    rb = simulate_loops(m, qp, qd, 0.2, rtol=1e-7, stabilization="baumgarte", alpha=40.0, beta=40.0,
                        project_initial=False)
    pr = rb.extra["position_residual"]
    assert pr[-1] < 0.02 * pr[0]                    # e^{-αt}(1 + αt) ≈ 3e-3 at t = 0.2
    rn = simulate_loops(m, qp, qd, 0.2, rtol=1e-7, stabilization="none", project_initial=False)
    assert rn.extra["position_residual"][-1] > 0.5 * rn.extra["position_residual"][0]


def test_constant_speed_drive(crank):
    m, q, qd = crank
    r = simulate_loops(m, q, qd, 0.2, rtol=1e-8, prescribed={0: 0.0})
    assert np.abs(r.qd[:, 0] - 20.0).max() < 1e-10
    assert np.abs(r.q[:, 0] - (0.4 + 20.0 * r.t)).max() < 1e-10
    assert r.extra["position_residual"].max() < 1e-9


def test_project_state(crank):
    m, q, qd = crank
    q2, qd2 = project_state(m, q + [0.05, -0.02, 0.03], qd + [0.0, 1.0, 2.0], fixed=[0])
    assert q2[0] == q[0] + 0.05
    assert np.abs(closure_residual(m, q2)).max() < 1e-12
    assert np.abs(closure_jacobian(m, q2) @ qd2).max() < 1e-10
    assert qd2[0] == qd[0]


@pytest.mark.parametrize("kw, msg", [(dict(stabilization="magic"), "stabilization must be one of"),
                                     (dict(alpha=-1.0), "alpha must be non-negative"),
                                     (dict(prescribed={7: 0.0}), "prescribed keys must be joint indices")])
def test_bad_arguments(crank, kw, msg):
    m, q, qd = crank
    with pytest.raises(InputError, match=msg):
        simulate_loops(m, q, qd, 0.1, **kw)


@pytest.mark.slow
def test_ten_second_free_crank(crank):
    """10 s of the free slider-crank (about 30 crank turns): projection keeps the loop closed.

    Documented figures (DOP853, rtol 1e-7, projection triggered above 1e-10):
    position and velocity residuals below 1e-9, relative energy drift below 1e-5.
    """
    m, q, qd = crank
    r = simulate_loops(m, q, qd, 10.0, rtol=1e-7, atol=1e-9)
    assert r.status == "ok" and r.t[-1] == pytest.approx(10.0)
    assert r.extra["position_residual"].max() < 1e-8
    assert r.extra["velocity_residual"].max() < 1e-8
    assert r.energy_drift() < 1e-5
    assert r.q[-1, 0] - r.q[0, 0] > 2 * np.pi * 10       # the crank kept turning
