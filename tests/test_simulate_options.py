"""simulate's options, step limits and clean stops (issue 16, items 5-7): each defect failed before.

References: the trajectories cut short (step limit, Ctrl-C) are compared with the same run
uninterrupted (its prefix), and the free rod's energy with its closed form.
"""
from __future__ import annotations

import numpy as np
import pytest

from planargeo.errors import InputError, SizeLimitError
from planargeo.mechanics.model import chain_model
from planargeo.simulate.integrate import MAX_STEPS, simulate

ROD = chain_model(1)


@pytest.mark.parametrize("kw, match", [
    ({"max_step": 0.0}, "max_step must be positive, got 0.0"),           # was scipy's ValueError
    ({"max_step": float("nan")}, "max_step must be positive, got nan"),  # was accepted
    ({"max_step": -1.0}, "max_step must be positive"),
    ({"rtol": -1.0}, "rtol must be at least"),                          # was accepted
    ({"rtol": float("nan")}, "rtol must be finite"),                    # was blamed on q
    ({"rtol": 1e-20}, "rtol must be at least 100 ε"),                   # scipy warned and raised it
    ({"atol": -1e-9}, "atol must be non-negative"),
    ({"atol": "tiny"}, "atol must be numeric"),
    ({"method": ["RK4"]}, "method must be one of"),
    ({"method": "RK4"}, "dt must be given for method 'RK4'"),
    ({"dt": 0.0}, "dt must be positive"),
    ({"max_steps": 2.5}, "max_steps must be a positive integer"),
    ({"max_steps": True}, "max_steps must be a positive integer"),
])
def test_bad_options_are_named(kw, match):
    with pytest.raises(InputError, match=match):
        simulate(ROD, [0.0], [0.0], 0.1, progress=False, **kw)


@pytest.mark.parametrize("t_end, kw, match", [
    (1.0, {"method": "RK4", "dt": 1e-300}, r"t_end / dt = 1e\+300 steps, past max_steps = 1000000"),   # hung
    (1e300, {"method": "RK4", "dt": 1e-300}, r"t_end / dt = inf steps"),                             # OverflowError
    (1e300, {"dt": 1.0}, r"t_end / dt = 1e\+300 steps"),
    (1e300, {"max_step": 1.0}, r"t_end / max_step = 1e\+300 steps"),
    (1e300, {}, r"DOP853 would need about .* steps to reach t_end = 1e\+300 \(extrapolated from the first 100\)"),
])
def test_runs_past_the_step_limit_fail_fast(t_end, kw, match):
    with pytest.raises(SizeLimitError, match=match):
        simulate(ROD, [0.3], [0.0], t_end, progress=False, **kw)
    assert MAX_STEPS == 1_000_000


def test_step_limit_stops_cleanly_keeping_the_trajectory():
    """max_steps = 20: status "limit", and the 21 recorded states are those of the unlimited run (36)."""
    full = simulate(ROD, [0.3], [0.0], 2.0, rtol=1e-10, atol=1e-12, progress=False)
    cut = simulate(ROD, [0.3], [0.0], 2.0, rtol=1e-10, atol=1e-12, progress=False, max_steps=20)
    assert len(full.t) > 21 and full.status == "ok"
    assert cut.status == "limit" and "max_steps = 20 steps taken" in cut.message and len(cut.t) == 21
    np.testing.assert_array_equal(cut.q, full.q[:21])
    # the closed form: energy of the free rod is conserved, T + V = m g (L/2) sin(0.3) throughout
    np.testing.assert_allclose(cut.energy, 9.81 * 0.5 * np.sin(0.3), rtol=1e-9)


def test_ctrl_c_stops_cleanly_keeping_what_was_computed():
    """A KeyboardInterrupt while integrating (here raised by the torque hook past t = 0.5) ends the run
    with status "interrupted" and the steps accepted before it, equal to the uninterrupted run's."""
    def tau(t, q, qd):
        if t > 0.5:
            raise KeyboardInterrupt
        return np.zeros(1)

    for method, kw in (("DOP853", {}), ("RK4", {"dt": 0.01})):
        full = simulate(ROD, [0.3], [0.0], 1.0, method=method, tau=lambda t, q, qd: np.zeros(1), progress=False,
                        **kw)
        r = simulate(ROD, [0.3], [0.0], 1.0, method=method, tau=tau, progress=False, **kw)
        assert r.status == "interrupted" and r.message.startswith("interrupted at t = ")
        n = len(r.t)
        assert 1 < n < len(full.t) and r.t[-1] <= 0.5 + 1e-12
        np.testing.assert_array_equal(r.q, full.q[:n])
        assert len(r.energy) == n == len(r.qd)
