"""Viscous joint damping in ``simulate`` (``damping=``, τ = -c q̇) against closed forms.

* a free rotor (no gravity): ``J ω̇ = -c ω``, so ``ω = ω₀ e^{-ct/J}`` and the dissipated energy is
  ``W = ½ J ω₀² (1 - e^{-2ct/J})`` exactly;
* a rod pendulum swinging with a small amplitude about its hanging position: the damped
  oscillator ``J ε̈ + c ε̇ + k ε = 0`` (``J = m L²/3``, ``k = m g L / 2``);
* the energy balance ``T + V + W = E₀`` and ``W`` against an independent quadrature of
  ``Σ c q̇²`` over the recorded motion.
"""
from __future__ import annotations

import numpy as np
import pytest

from planargeo.errors import InputError, NonFiniteError, ShapeError
from planargeo.mechanics.model import chain_model
from planargeo.simulate.integrate import simulate

TIGHT = dict(rtol=1e-11, atol=1e-13)


@pytest.mark.parametrize("c", [0.05, 0.4, 2.0])
def test_free_rotor_speed_and_dissipated_energy_closed_form(c):
    model = chain_model(1, gravity=(0.0, 0.0))
    J, w0 = 1.0 / 3.0, 2.5                               # a unit rod about its end
    r = simulate(model, [0.0], [w0], 1.5, damping=c, dt=0.05, **TIGHT)
    t = r.t
    np.testing.assert_allclose(r.qd[:, 0], w0 * np.exp(-c * t / J), rtol=1e-9)
    np.testing.assert_allclose(r.q[:, 0], w0 * J / c * (1 - np.exp(-c * t / J)), rtol=1e-9, atol=1e-12)
    W = 0.5 * J * w0**2 * (1 - np.exp(-2 * c * t / J))
    np.testing.assert_allclose(r.dissipated, W, rtol=1e-9, atol=1e-13)
    np.testing.assert_allclose(r.energy + r.dissipated, r.energy[0], rtol=1e-10)
    assert r.energy_drift() < 1e-10


@pytest.mark.parametrize("c", [0.1, 0.5])
def test_small_angle_pendulum_decays_as_the_damped_oscillator(c):
    model = chain_model(1)                               # g = 9.81 along -y, rod of mass 1, length 1
    J, k = 1.0 / 3.0, 9.81 / 2.0
    eps0 = 1e-4                                          # nonlinearity ~ eps0² / 6: far below the tolerance
    r = simulate(model, [-np.pi / 2 + eps0], [0.0], 3.0, damping=[c], dt=0.01, **TIGHT)
    t = r.t
    zeta_w = c / (2 * J)
    wd = np.sqrt(k / J - zeta_w**2)
    eps = eps0 * np.exp(-zeta_w * t) * (np.cos(wd * t) + zeta_w / wd * np.sin(wd * t))
    np.testing.assert_allclose(r.q[:, 0] + np.pi / 2, eps, atol=1e-8 * eps0 + 2e-9 * eps0)
    # logarithmic decrement over one damped period
    T = 2 * np.pi / wd
    i = np.argmin(np.abs(t - T))
    assert r.q[i, 0] + np.pi / 2 == pytest.approx(eps0 * np.exp(-zeta_w * t[i]) *
                                                 (np.cos(wd * t[i]) + zeta_w / wd * np.sin(wd * t[i])), rel=1e-6)


@pytest.mark.parametrize("method, kw", [("DOP853", TIGHT), ("RK45", dict(rtol=1e-10, atol=1e-12)),
                                        ("RK4", dict(dt=2e-4))])
def test_energy_balance_and_quadrature_of_the_dissipated_power(method, kw):
    model = chain_model(3)
    c = np.array([0.3, 0.0, 0.8])                        # per joint; the middle one free
    r = simulate(model, [0.2, -0.4, 0.9], [0.0, 1.0, -2.0], 1.0, method=method, damping=c, **kw)
    assert r.status == "ok"
    E0 = r.energy[0]
    assert np.max(np.abs(r.energy + r.dissipated - E0)) < 1e-6 * abs(E0)
    assert np.all(np.diff(r.dissipated) >= -1e-12) and r.dissipated[0] == 0.0
    # independent: trapezoidal quadrature of Σ c q̇² on a fine output grid
    g = simulate(model, [0.2, -0.4, 0.9], [0.0, 1.0, -2.0], 1.0, damping=c, dt=1e-4, **TIGHT)
    power = np.einsum("j,tj,tj->t", c, g.qd, g.qd)
    W = np.concatenate([[0.0], np.cumsum(0.5 * (power[1:] + power[:-1]) * np.diff(g.t))])
    np.testing.assert_allclose(g.dissipated, W, rtol=1e-6, atol=1e-9)


def test_zero_damping_changes_nothing():
    model = chain_model(2)
    a = simulate(model, [0.3, 0.1], [0.0, 0.5], 0.5, dt=0.05, **TIGHT)
    b = simulate(model, [0.3, 0.1], [0.0, 0.5], 0.5, dt=0.05, damping=0.0, **TIGHT)
    np.testing.assert_allclose(a.q, b.q, rtol=1e-9, atol=1e-11)   # the same motion (steps may differ:
    r4a = simulate(model, [0.3, 0.1], [0.0, 0.5], 0.5, method="RK4", dt=0.01)   # W joins the error norm)
    r4b = simulate(model, [0.3, 0.1], [0.0, 0.5], 0.5, method="RK4", dt=0.01, damping=[0.0, 0.0])
    np.testing.assert_array_equal(r4a.q, r4b.q)                   # fixed steps: identical
    np.testing.assert_array_equal(b.dissipated, 0.0)
    assert a.dissipated is None


def test_damping_with_a_torque_and_projection_hook():
    # a driving torque and damping together: steady speed ω = τ / c of a free rotor
    model = chain_model(1, gravity=(0.0, 0.0))
    r = simulate(model, [0.0], [0.0], 20.0, tau=[1.0], damping=2.0, dt=1.0,
                 project=lambda q, qd: (q, qd), **TIGHT)
    assert r.qd[-1, 0] == pytest.approx(0.5, rel=1e-9)
    # the balance with work input: W = ∫ τ ω dt - T (no potential)
    assert r.dissipated[-1] == pytest.approx(r.q[-1, 0] * 1.0 - r.kinetic[-1], rel=1e-8)


@pytest.mark.parametrize("bad, err, match", [
    (-0.1, InputError, "damping coefficients must be non-negative"),
    ([0.1, -1.0], InputError, "non-negative"),
    ([0.1, 0.2, 0.3], ShapeError, r"damping must be a number or one coefficient per joint coordinate, shape \(2,\)"),
    (float("nan"), NonFiniteError, "damping"),
    ("0.1", InputError, "damping must be numeric"),
])
def test_bad_damping_is_named(bad, err, match):
    with pytest.raises(err, match=match):
        simulate(chain_model(2), [0.0, 0.0], [0.0, 0.0], 0.1, damping=bad)
