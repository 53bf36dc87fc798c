"""Bad input at the compiled entry points, the kernels uncompiled, and the defects of issue 16 they fixed.

Every compiled road (forward and inverse dynamics, one state and batches) gets the
package's named errors for wrong shapes, non-finite and complex values and singular
joints, never a numba typing error or a crash; ints, float32 and lists are converted.
References: hand-computed values (the pendulum ``q̈ = -1.5 g``), and the same kernels
run as plain Python under ``NUMBA_DISABLE_JIT=1``.
"""
import json
import os
import subprocess
import sys

import numba
import numpy as np
import pytest

from planargeo.algorithms.aba import forward_dynamics
from planargeo.algorithms.crba import forward_dynamics_crba, mass_matrix
from planargeo.algorithms.rnea import inverse_dynamics
from planargeo.errors import (InputError, NonFiniteError, NumericOverflowError, ShapeError,
                              SingularConfigurationError)
from planargeo.mechanics.model import MAX_BODIES, Body, Joint, Model, chain_model

G = 9.81
M = chain_model(3)
ENTRIES = {
    "forward, one state": lambda q, qd, z, f=None: forward_dynamics(M, q, qd, z, f),
    "forward, batch": lambda q, qd, z, f=None: forward_dynamics(M, np.stack([q, q]), qd, z, f)[1],
    "inverse, one state": lambda q, qd, z, f=None: inverse_dynamics(M, q, qd, z, f),
    "inverse, batch": lambda q, qd, z, f=None: inverse_dynamics(M, np.stack([q, q]), qd, z, f)[1],
}
Z = np.zeros(3)


@pytest.mark.parametrize("entry", list(ENTRIES))
def test_entry_points_convert_ints_float32_and_lists(entry):
    call = ENTRIES[entry]
    q32 = np.array([0.1, 0.2, 0.3], dtype=np.float32)
    ref = call(q32.astype(float), Z, Z)
    assert np.array_equal(call(q32, [0, 0, 0], (0, 0, 0)), ref)
    assert np.array_equal(call(q32.tolist(), np.zeros(3, dtype=int), [0.0] * 3), ref)
    one = Model([Body(1.0, (0.5, 0.0), 1 / 12)], [Joint("revolute")], [-1])
    assert forward_dynamics(one, [0], [0], [0]) == pytest.approx([-1.5 * G])   # ints: -m g L/2 / (m L²/3)


@pytest.mark.parametrize("entry", list(ENTRIES))
@pytest.mark.parametrize("which", [0, 1, 2])
def test_entry_points_refuse_bad_values(entry, which):
    call, names = ENTRIES[entry], ("q", "qd", "qdd" if entry.startswith("inverse") else "tau")

    def with_(x):
        args = [Z, Z, Z]
        args[which] = x
        return args

    with pytest.raises(ShapeError, match=names[which]):
        call(*with_(np.zeros(4)))
    with pytest.raises(ShapeError, match=names[which]):
        call(*with_([0.0, 0.0]))
    for bad in (np.nan, np.inf, -np.inf):
        with pytest.raises(NonFiniteError, match=names[which]):
            call(*with_(np.array([0.0, bad, 0.0])))
    with pytest.raises(InputError, match=f"{names[which]} must be real"):
        call(*with_(np.array([0.0, 1j, 0.0])))
    with pytest.raises(InputError, match=f"{names[which]} must be numeric"):
        call(*with_(["a", "b", "c"]))


@pytest.mark.parametrize("entry", list(ENTRIES))
def test_entry_points_refuse_bad_external_wrenches(entry):
    call = ENTRIES[entry]
    with pytest.raises(ShapeError, match="f_ext"):
        call(Z, Z, Z, np.zeros((2, 3)))
    with pytest.raises(NonFiniteError, match="f_ext"):
        call(Z, Z, Z, np.array([[0.0, np.nan, 0.0]] * 3))
    with pytest.raises(InputError, match="f_ext must be real"):
        call(Z, Z, Z, np.zeros((3, 3)) + 1j)


def test_non_finite_wrench_on_a_welded_body_is_refused():
    """A body welded to the ground passes no load to any joint: its NaN wrench must still be refused."""
    m = Model([Body(1.0, (0.5, 0.0), 0.1), Body(1.0, (0.5, 0.0), 0.1)], [Joint("fixed"), Joint("revolute")], [-1, -1])
    f = np.zeros((2, 3))
    f[0, 1] = np.inf
    with pytest.raises(NonFiniteError, match="f_ext"):
        forward_dynamics(m, np.zeros(1), np.zeros(1), np.zeros(1), f)


@pytest.mark.parametrize("batch", [False, True])
def test_singular_state_at_every_entry_point(batch):
    """A point mass on its own pivot: sᵀAs = 0, refused with cond = inf by the one rule."""
    m = Model([Body(1.0, (0.0, 0.0), 0.0)], [Joint("revolute")], [-1])
    z = np.zeros((4, 1)) if batch else np.zeros(1)
    with pytest.raises(SingularConfigurationError, match="sᵀAs of joint 1 is singular") as e:
        forward_dynamics(m, z, z, z)
    assert e.value.cond == np.inf
    # inverse dynamics needs no inverse: the torque that holds it is zero
    assert np.array_equal(inverse_dynamics(m, z, z, z), z)


_UNCOMPILED = """
import json, numpy as np
from planargeo.algorithms import kernels
from planargeo.algorithms.aba import forward_dynamics
from planargeo.algorithms.rnea import inverse_dynamics
from planargeo.mechanics.model import random_model
assert not hasattr(kernels.articulated_body_state, "py_func")      # plain Python
m = random_model(4, seed=2, kinds=("revolute", "prismatic", "fixed"), tree=True)
q, qd, tau = np.random.default_rng(2).normal(size=(3, 5, m.nq))
print(json.dumps([forward_dynamics(m, q[0], qd[0], tau[0]).tolist(), forward_dynamics(m, q, qd, tau).tolist(),
                  inverse_dynamics(m, q, qd, tau).tolist()]))
"""


@pytest.mark.skipif(numba.config.DISABLE_JIT, reason="checks the compiled kernels")
def test_kernels_run_uncompiled_with_the_same_numbers():
    """NUMBA_DISABLE_JIT=1: the kernels are plain Python (to step through), and give the compiled numbers."""
    from planargeo.algorithms import kernels
    from planargeo.mechanics.model import random_model

    env = dict(os.environ, NUMBA_DISABLE_JIT="1")
    out = subprocess.run([sys.executable, "-c", _UNCOMPILED], capture_output=True, text=True, env=env, check=True)
    one, many, inv = (np.array(x) for x in json.loads(out.stdout))
    assert hasattr(kernels.articulated_body_state, "py_func")          # compiled here
    m = random_model(4, seed=2, kinds=("revolute", "prismatic", "fixed"), tree=True)
    q, qd, tau = np.random.default_rng(2).normal(size=(3, 5, m.nq))
    np.testing.assert_allclose(one, forward_dynamics(m, q[0], qd[0], tau[0]), rtol=1e-14, atol=1e-14)
    np.testing.assert_allclose(many, forward_dynamics(m, q, qd, tau), rtol=1e-14, atol=1e-14)
    np.testing.assert_allclose(inv, inverse_dynamics(m, q, qd, tau), rtol=1e-14, atol=1e-13)


# -- issue 16: one test per defect ------------------------------------------------------------------------------------
def test_huge_speeds_raise_overflow_not_nan():
    with pytest.raises(NumericOverflowError, match="qd reaches 1e"):
        forward_dynamics(chain_model(3), np.zeros(3), np.full(3, 1e160), np.zeros(3))


def test_huge_speeds_raise_overflow_in_crba_and_batches():
    with pytest.raises(NumericOverflowError):
        forward_dynamics_crba(chain_model(3), np.zeros(3), np.full(3, 1e160), np.zeros(3))
    qd = np.zeros((50, 3))
    qd[17] = 1e160
    with pytest.raises(NumericOverflowError):
        forward_dynamics(chain_model(3), np.zeros((50, 3)), qd, np.zeros(3))


def test_huge_accelerations_raise_overflow_in_inverse_dynamics():
    with pytest.raises(NumericOverflowError, match="qdd reaches 1.7e"):
        inverse_dynamics(chain_model(3), np.zeros(3), np.zeros(3), np.full(3, 1.7e308))


def test_huge_prismatic_coordinates_raise_overflow_not_a_nan_condition_number():
    with pytest.raises(NumericOverflowError):
        forward_dynamics(chain_model(3, joint="prismatic"), np.full(3, 1e200), np.zeros(3), np.zeros(3))
    with pytest.raises(NumericOverflowError):
        mass_matrix(Model([Body(1.0, (0.1, 0.0), 0.1)], [Joint("plane")], [-1]), [1e200, 1e200, 0.0])


@pytest.mark.parametrize("method", [forward_dynamics, forward_dynamics_crba])
def test_none_is_zero_for_every_method(method):
    """qd or tau None: zeros, as for every other method (was an AttributeError / a TypeError from numpy)."""
    m = chain_model(3)
    ref = method(m, np.zeros(3), np.zeros(3), np.zeros(3))
    assert np.array_equal(method(m, np.zeros(3), None, np.zeros(3)), ref)
    assert np.array_equal(method(m, np.zeros(3), np.zeros(3), None), ref)
    assert np.array_equal(inverse_dynamics(m, np.zeros(3), None, None), inverse_dynamics(m, Z, Z, Z))


def test_complex_state_refused():
    with pytest.raises(InputError, match="q must be real"):
        forward_dynamics(chain_model(3), np.zeros(3) + 0.5j, np.zeros(3), np.zeros(3))


@pytest.mark.parametrize("n", [float("inf"), "x", 1.5, 2.9, True, None])
def test_chain_model_refuses_non_integer_counts(n):
    with pytest.raises(InputError, match="n must be an integer"):
        chain_model(n)


def test_chain_model_refuses_huge_counts_up_front():
    with pytest.raises(InputError, match=f"at most MAX_BODIES = {MAX_BODIES}.*allow_large=True"):
        chain_model(10 ** 7)                      # was: minutes of building, then hours in model.arrays()
    assert chain_model(MAX_BODIES + 1, allow_large=True).N == MAX_BODIES + 1


def test_chain_model_blames_length_for_an_overflowing_inertia():
    with pytest.raises(InputError, match="^length 1e\\+200 is too large"):
        chain_model(2, length=1e200)


def test_import_planargeo_compiles_nothing():
    """numba is imported (and the kernels compiled) on the first dynamics call, not by ``import planargeo``."""
    code = ("import sys, planargeo, planargeo.scenes, planargeo.algorithms.aba, planargeo.algorithms.rnea; "
            "print('numba' in sys.modules, 'planargeo.algorithms.kernels' in sys.modules)")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, check=True)
    assert out.stdout.split() == ["False", "False"]
