"""Time integration: energy conservation, hooks, singular stops, progress bars."""
import io
import sys
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from planargeo.errors import InputError, SingularConfigurationError
from planargeo.mechanics.model import Body, Joint, Model, chain_model, random_model
from planargeo.simulate.integrate import energy, progress_enabled, simulate

Q0, QD0 = [0.3, 0.5, -0.2], [0.0, 1.0, 0.0]

# Documented tolerances (docs/simulation.md, table "The tolerances, once"; measured values there)
TOLERANCES = {"chain-dop853": 1e-9, "chain-rk4": 1e-6, "random-dop853": 1e-8}


def documented_bounds() -> dict:
    """``{id: bound}`` from the table of docs/simulation.md."""
    text = (Path(__file__).resolve().parents[1] / "docs" / "simulation.md").read_text(encoding="utf-8")
    out = {}
    for line in text.splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if len(cells) == 6 and cells[0] not in ("id", "") and not cells[0].startswith("-"):
            out[cells[0]] = float(cells[4])
    return out


def test_documented_tolerances_match_the_tests():
    doc = documented_bounds()
    for key, bound in TOLERANCES.items():
        assert doc[key] == bound, key


def test_energy_by_hand():
    """Double pendulum of unit rods, both horizontal, link 2 spinning: T = ½ ω² (1/12 + 1.5²)... by hand."""
    m = chain_model(2)
    T, V = energy(m, [0.0, 0.0], [1.0, 0.0])
    # rigid rotation about the origin of both links: ½ ω² H11 with H11 = 8/3
    assert float(T) == pytest.approx(0.5 * 8 / 3, rel=1e-14)
    assert float(V) == pytest.approx(0.0, abs=1e-14)
    T, V = energy(m, [np.pi / 2, 0.0], [0.0, 0.0])
    assert float(V) == pytest.approx(9.81 * (0.5 + 1.5), rel=1e-14)


def test_energy_of_given_kinematics_is_not_recomputed():
    """energy(data=...) uses the frame's kinematics as they are: a unit rod spinning at ω has T = ω²/6."""
    from planargeo.mechanics.kinematics import kinematics

    m = chain_model(1)
    d = kinematics(m, [np.pi / 2], [3.0])
    assert [float(x) for x in energy(m, data=d)] == [float(x) for x in energy(m, [np.pi / 2], [3.0])]
    d.v = d.v * 2.0                                   # the caller's numbers, not a fresh computation
    assert float(energy(m, data=d)[0]) == pytest.approx(4 * 9 / 6, rel=1e-14)
    with pytest.raises(InputError, match="not both"):
        energy(m, [0.0], [0.0], data=d)
    with pytest.raises(InputError, match="not both"):
        energy(chain_model(2), data=d)


def test_dop853_conserves_energy_free_chain():
    """Documented tolerance (docs/simulation.md, chain-dop853): DOP853 at rtol 1e-10 keeps the relative
    energy drift of the free 3-link chain below 1e-9 over 5 s (measured 4.2e-11)."""
    r = simulate(chain_model(3), Q0, QD0, 5.0, method="DOP853", rtol=1e-10, atol=1e-12)
    assert r.status == "ok" and r.t[-1] == 5.0
    assert r.energy_drift() < TOLERANCES["chain-dop853"]


def test_rk4_conserves_energy_free_chain():
    """Documented tolerance (chain-rk4): RK4 at dt = 1e-3 keeps the drift below 1e-6 over 2 s (measured 9.1e-8)."""
    r = simulate(chain_model(3), Q0, QD0, 2.0, method="RK4", dt=1e-3)
    assert r.status == "ok" and len(r.t) == 2001 and r.t[-1] == pytest.approx(2.0)
    assert r.energy_drift() < TOLERANCES["chain-rk4"]


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
        ev = r.events[-1]
        assert ev["kind"] == "singular" and ev["cond"] == 1e17 and r.t[-1] <= ev["t"] <= r.t[-1] + 0.1


# --------------------------------------------------------------------------- singular events (real ones)
def _bead_on_a_rod():
    """A unit point mass on the pivot of a rod (no inertia of its own) along which a unit bead slides.

    With the bead at ``x`` on the rod: ``sᵀAs = m x²`` for the pivot and ``‖A‖_F = √(5 + 2x² + x⁴)``
    (inertia at the pivot, rod frame ``[[1, 0, 0], [0, 2, x], [0, x, x²]]``), so the joint's
    condition number is ``√(5 + 2x² + x⁴) / x²``: singular when the bead passes through the pivot.
    Nothing acts on the bead (no gravity, the rod cannot push), so it moves on a straight line.
    """
    return Model([Body(1.0), Body(1.0)], [Joint("revolute"), Joint("prismatic")], [-1, 0], gravity=(0.0, 0.0))


def _bead_cond(x):
    x = np.asarray(x, dtype=float)
    return np.sqrt(5 + 2 * x ** 2 + x ** 4) / x ** 2


def test_joint_conditions_watched_every_step_and_singular_stop():
    """Bead aimed at the pivot (no angular momentum): x = -1 + t; an RK4 stage lands on x = 0 at t = 1,
    where sᵀAs = 0: the run stops cleanly with a singular event at t = 1 carrying the error's cond."""
    r = simulate(_bead_on_a_rod(), [0.3, -1.0], [0.0, 1.0], 2.0, method="RK4", dt=0.1, condition="joints")
    assert r.status == "singular" and "singular configuration" in r.message
    np.testing.assert_allclose(r.t, np.arange(10) * 0.1, atol=1e-12)          # up to the last good step
    np.testing.assert_allclose(r.q[:, 1], -1.0 + r.t, atol=1e-14)
    np.testing.assert_allclose(r.cond, _bead_cond(r.q[:, 1]), rtol=1e-12)     # watched at every step
    assert r.cond.max() < 1e6                                                  # x = -0.1 at t = 0.9: 2.2e2
    (sing,) = r.events
    assert sing["kind"] == "singular" and sing["t"] == pytest.approx(1.0, abs=1e-12) and sing["cond"] > 1e12
    assert f"{sing['cond']:.3g}" in sing["message"]
    # with a lower threshold the approach is an event too (the largest recorded cond, at t = 0.9)
    r = simulate(_bead_on_a_rod(), [0.3, -1.0], [0.0, 1.0], 2.0, method="RK4", dt=0.1, condition="joints",
                 cond_event=10.0)
    assert [e["kind"] for e in r.events] == ["near-singular", "singular"]
    near = r.events[0]
    assert near["t"] == pytest.approx(0.9) and near["cond"] == pytest.approx(_bead_cond(-0.1), rel=1e-12)
    assert near["t_start"] == pytest.approx(0.6) and near["t_end"] == pytest.approx(0.9)   # cond(-0.5) = 9.4, cond(-0.4) = 14


def test_near_singular_event_of_a_bead_passing_the_pivot():
    """Bead with a little angular momentum L = 1e-4: it passes the pivot at b = L / (m v) ≈ 1e-4
    (straight line), at t* = 1/(1 + 1e-8); the joint's condition number peaks at √5 / b² ≈ 2.24e8.
    The run goes on ("ok") and records one near-singular event there."""
    b_imp = 1e-4 / np.sqrt(1 + 1e-8)
    t_star = 1 / (1 + 1e-8)
    r = simulate(_bead_on_a_rod(), [0.3, -1.0], [1e-4, 1.0], 2.0, method="DOP853", rtol=1e-10, atol=1e-12,
                 condition="joints")
    assert r.status == "ok" and r.t[-1] == 2.0
    np.testing.assert_allclose(r.cond, _bead_cond(r.q[:, 1]), rtol=1e-12)
    (ev,) = r.events
    assert ev["kind"] == "near-singular"
    assert ev["cond"] == pytest.approx(_bead_cond(b_imp), rel=0.02)          # measured 0.14 % below the peak
    assert ev["t"] == pytest.approx(t_star, abs=1e-4)                        # measured 4e-6
    # above 1e6 while |x| < 1.5e-3, i.e. |t - t*| < 1.5e-3 (|x| ≈ |t - t*| there)
    assert t_star - 1.5e-3 < ev["t_start"] < ev["t"] < ev["t_end"] < t_star + 1.5e-3
    # and the integration went through the near-singularity accurately: the bead is on its line
    th, x = r.q[-1]
    e0, n0 = np.array([np.cos(0.3), np.sin(0.3)]), np.array([-np.sin(0.3), np.cos(0.3)])
    expected = -e0 + 2.0 * (e0 - 1e-4 * n0)
    np.testing.assert_allclose(x * np.array([np.cos(th), np.sin(th)]), expected, atol=1e-9)   # measured 6e-12


def test_joint_conditions_agree_with_the_algorithms_singularity_rule():
    """joint_conditions is the rule the algorithms apply: below 1e12 they solve, above they raise that cond."""
    from planargeo.algorithms.stacked import joint_conditions, stacked_solve

    m = _bead_on_a_rod()
    for x in (1e-3, 1e-5, 1e-7):
        assert joint_conditions(m, [0.2, x])[0] == pytest.approx(_bead_cond(x), rel=1e-9)
    for x in (1e-3, 1e-5):                                                     # cond 2.2e6, 2.2e10
        stacked_solve(m, [0.2, x], [0.0, 0.0], [0.0, 0.0])
    with pytest.raises(SingularConfigurationError) as e:
        stacked_solve(m, [0.2, 1e-7], [0.0, 0.0], [0.0, 0.0])
    assert e.value.cond == pytest.approx(joint_conditions(m, [0.2, 1e-7])[0], rel=1e-12)


def test_condition_argument_errors():
    with pytest.raises(InputError, match="condition must be a callable, 'joints' or None"):
        simulate(chain_model(1), [0.0], [0.0], 0.1, condition="loops")


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
    """Random small mechanisms (revolute/prismatic/plane joints), tau = 0: energy conserved
    (random-dop853: bound 1e-8, worst measured 1.5e-10 over 1200 cases)."""
    m = random_model(n, seed=seed, kinds=("revolute", "prismatic", "plane"), tree=tree)
    rng = np.random.default_rng(seed)
    r = simulate(m, rng.normal(size=m.nq), rng.normal(size=m.nq), 0.5, method="DOP853", rtol=1e-10, atol=1e-12)
    assert r.status == "ok"
    assert r.energy_drift() < TOLERANCES["random-dop853"]


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
