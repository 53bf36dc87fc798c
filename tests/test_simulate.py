"""Time integration: energy conservation, hooks, singular stops, progress bars."""
import io
import sys

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from planargeo.errors import InputError, SingularConfigurationError
from planargeo.model import chain_model, random_model
from planargeo.simulate import energy, progress_enabled, simulate

Q0, QD0 = [0.3, 0.5, -0.2], [0.0, 1.0, 0.0]


def test_energy_by_hand():
    """Double pendulum of unit rods, both horizontal, link 2 spinning: T = ½ ω² (1/12 + 1.5²)... by hand."""
    m = chain_model(2)
    T, V = energy(m, [0.0, 0.0], [1.0, 0.0])
    # rigid rotation about the origin of both links: ½ ω² H11 with H11 = 8/3
    assert float(T) == pytest.approx(0.5 * 8 / 3, rel=1e-14)
    assert float(V) == pytest.approx(0.0, abs=1e-14)
    T, V = energy(m, [np.pi / 2, 0.0], [0.0, 0.0])
    assert float(V) == pytest.approx(9.81 * (0.5 + 1.5), rel=1e-14)


def test_dop853_conserves_energy_free_chain():
    """Documented tolerance: DOP853 at rtol 1e-10 keeps the relative drift below 1e-7 over 5 s."""
    r = simulate(chain_model(3), Q0, QD0, 5.0, method="DOP853", rtol=1e-10, atol=1e-12)
    assert r.status == "ok" and r.t[-1] == 5.0
    assert r.energy_drift() < 1e-7


def test_rk4_conserves_energy_free_chain():
    """Documented tolerance: RK4 at dt = 1e-3 keeps the relative drift below 1e-6 over 2 s."""
    r = simulate(chain_model(3), Q0, QD0, 2.0, method="RK4", dt=1e-3)
    assert r.status == "ok" and len(r.t) == 2001 and r.t[-1] == pytest.approx(2.0)
    assert r.energy_drift() < 1e-6


@pytest.mark.parametrize("method", ["RK45", "Radau"])
def test_other_methods_agree_with_dop853(method):
    m = chain_model(2)
    ref = simulate(m, Q0[:2], QD0[:2], 0.5, method="DOP853", rtol=1e-11, atol=1e-12)
    r = simulate(m, Q0[:2], QD0[:2], 0.5, method=method, rtol=1e-9, atol=1e-11)
    assert r.status == "ok"
    np.testing.assert_allclose(r.q[-1], ref.q[-1], atol=1e-5)
    assert r.energy_drift() < 1e-5


def test_dense_output_sampling_and_torque_work():
    """With dt, outputs are sampled on a grid; a constant torque on a horizontal-gravity-free rod
    does work τ θ: T(t) = τ (θ(t) - θ0)."""
    m = chain_model(1, gravity=(0.0, 0.0))
    r = simulate(m, [0.0], [0.0], 1.0, tau=[0.6], dt=0.1, rtol=1e-11, atol=1e-12)
    np.testing.assert_allclose(r.t, np.linspace(0, 1, 11), atol=1e-12)
    np.testing.assert_allclose(r.kinetic, 0.6 * r.q[:, 0], atol=1e-10)
    # closed form θ = ½ (τ/J) t² with J = 1/3
    np.testing.assert_allclose(r.q[:, 0], 0.5 * 0.6 * 3 * r.t**2, atol=1e-10)


def test_callable_tau_and_fext():
    m = chain_model(1, gravity=(0.0, 0.0))
    # a damping torque -c qd dissipates energy monotonically
    r = simulate(m, [0.0], [2.0], 1.0, tau=lambda t, q, qd: -0.5 * qd, method="RK4", dt=1e-2)
    assert np.all(np.diff(r.energy) < 0)
    # an external pure couple of 0.6 at the origin acts like the joint torque
    fe = np.array([[0.0, 0.0, 0.6]])
    a = simulate(m, [0.0], [0.0], 0.5, f_ext=lambda t, q, qd: fe, method="RK4", dt=1e-2)
    b = simulate(m, [0.0], [0.0], 0.5, tau=[0.6], method="RK4", dt=1e-2)
    np.testing.assert_allclose(a.q, b.q, atol=1e-14)


@pytest.mark.parametrize("method", ["RK4", "DOP853"])
def test_hooks_stabilize_project_residual(method):
    """Hooks: a projection holding joint 2 locked, a residual recording it, a stabilize term."""
    m = chain_model(2)
    calls = {"stab": 0}

    def project(q, qd):
        q, qd = q.copy(), qd.copy()
        q[1], qd[1] = 0.0, 0.0
        return q, qd

    def stabilize(t, q, qd, qdd):
        calls["stab"] += 1
        return qdd

    kw = {"dt": 1e-3} if method == "RK4" else {}
    r = simulate(m, [0.2, 0.4], [0.0, 1.0], 0.3, method=method, project=project, stabilize=stabilize,
                 residual=lambda q, qd: [q[1], qd[1]], **kw)
    assert r.status == "ok" and calls["stab"] == r.nfev > 0
    assert r.residual.shape == (len(r.t), 2)
    np.testing.assert_array_equal(r.residual, 0.0)


def test_singular_configuration_stops_cleanly():
    m = chain_model(1)

    def forward(model, q, qd, tau, f_ext):
        if q[0] < -0.5:
            raise SingularConfigurationError("test singularity", 1e17)
        from planargeo.algorithms.aba import forward_dynamics
        return forward_dynamics(model, q, qd, tau, f_ext)

    for method, kw in (("RK4", {"dt": 1e-3}), ("DOP853", {})):
        r = simulate(m, [0.0], [0.0], 3.0, method=method, forward=forward, **kw)
        assert r.status == "singular" and not r.success
        assert "singular configuration" in r.message and "test singularity" in r.message
        assert 0 < r.t[-1] < 3.0 and r.q[-1, 0] >= -0.5 - 1e-9 and len(r.t) == len(r.energy)


def test_input_errors():
    m = chain_model(2)
    with pytest.raises(InputError, match="method must be one of"):
        simulate(m, [0, 0], [0, 0], 1.0, method="Euler")
    with pytest.raises(InputError, match="dt must be given"):
        simulate(m, [0, 0], [0, 0], 1.0, method="RK4")
    with pytest.raises(InputError, match="t_end must be positive"):
        simulate(m, [0, 0], [0, 0], 0.0)
    with pytest.raises(InputError, match="q0 and qd0 must be single states"):
        simulate(m, [[0, 0]], [0, 0], 1.0)


@settings(max_examples=20)
@given(n=st.integers(1, 3), seed=st.integers(0, 2**31), tree=st.booleans())
def test_property_energy_conserved_random_chains(n, seed, tree):
    """Random small mechanisms (revolute/prismatic/plane joints), tau = 0: energy conserved."""
    m = random_model(n, seed=seed, kinds=("revolute", "prismatic", "plane"), tree=tree)
    rng = np.random.default_rng(seed)
    r = simulate(m, rng.normal(size=m.nq), rng.normal(size=m.nq), 0.5, method="DOP853", rtol=1e-10, atol=1e-12)
    assert r.status == "ok"
    assert r.energy_drift() < 1e-6


# --------------------------------------------------------------------------- progress bar decision
class _Stream:
    def __init__(self, tty):
        self.tty = tty

    def isatty(self):
        return self.tty


def _fake_ipython(monkeypatch, shell):
    import types

    mod = types.ModuleType("IPython")
    mod.get_ipython = lambda: shell
    monkeypatch.setitem(sys.modules, "IPython", mod)


def test_progress_explicit_values_win(monkeypatch):
    _fake_ipython(monkeypatch, None)
    assert progress_enabled(True, _Stream(False)) is True
    assert progress_enabled(False, _Stream(True)) is False


def test_progress_auto_terminal(monkeypatch):
    _fake_ipython(monkeypatch, None)
    assert progress_enabled(None, _Stream(True)) is True
    assert progress_enabled(None, _Stream(False)) is False
    assert progress_enabled(None, io.StringIO()) is False


def test_progress_auto_jupyter_kernel(monkeypatch):
    """A Jupyter kernel's stderr is not a terminal, yet the bar is shown there."""
    ZMQInteractiveShell = type("ZMQInteractiveShell", (), {"config": {}})
    Colab = type("Shell", (ZMQInteractiveShell,), {})                      # e.g. Colab subclasses it
    TerminalInteractiveShell = type("TerminalInteractiveShell", (), {"config": {}})
    KernelConfigured = type("SomeShell", (), {"config": {"IPKernelApp": {}}})
    for shell, expected in ((ZMQInteractiveShell(), True), (Colab(), True), (KernelConfigured(), True),
                            (TerminalInteractiveShell(), False), (None, False)):
        _fake_ipython(monkeypatch, shell)
        assert progress_enabled(None, _Stream(False)) is expected, shell
    monkeypatch.delitem(sys.modules, "IPython")                           # IPython not loaded: no kernel
    assert progress_enabled(None, _Stream(False)) is False


def test_progress_bar_is_used_when_enabled(monkeypatch):
    """progress=None under a (fake) kernel drives a tqdm.auto bar to t_end."""
    import tqdm.auto

    _fake_ipython(monkeypatch, type("ZMQInteractiveShell", (), {"config": {}})())
    seen = {}

    class Bar:
        def __init__(self, total, **kw):
            seen["total"], seen["n"] = total, 0.0

        def update(self, dt):
            seen["n"] += dt

        def close(self):
            seen["closed"] = True

    monkeypatch.setattr(tqdm.auto, "tqdm", Bar)
    monkeypatch.setattr(sys, "stderr", _Stream(False))
    r = simulate(chain_model(1), [0.0], [0.0], 0.1, method="RK4", dt=0.01)
    assert r.status == "ok" and seen["total"] == 0.1 and seen["closed"]
    assert seen["n"] == pytest.approx(0.1)
