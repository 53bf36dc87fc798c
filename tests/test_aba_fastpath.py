"""The compiled kernels against the general array recursions: the same equations, two codes.

``forward_dynamics`` and ``inverse_dynamics`` run the numba kernels of
:mod:`planargeo.algorithms.kernels` for models of revolute, prismatic and fixed joints
(one state at a time; batches in blocks shared among threads), and the general
recursions :func:`articulated_body` / :func:`newton_euler` (3×k arrays, any joint kind)
otherwise.  Here the two must agree to 1e-12 relative on chains and trees with random
gravity and external wrenches, for single states and batches of every shape and
layout; the physics references (Pinocchio, Lagrange's equations) are in
test_dyn_aba.py and test_pinocchio.py.
"""
import numba
import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from planargeo.algorithms import kernels
from planargeo.algorithms.aba import articulated_body, forward_dynamics
from planargeo.algorithms.rnea import inverse_dynamics, newton_euler
from planargeo.errors import NonFiniteError, SingularConfigurationError
from planargeo.mechanics.model import Body, Joint, Model, chain_model, random_model

KINDS = [("revolute",), ("prismatic",), ("revolute", "prismatic"), ("revolute", "prismatic", "fixed")]


def _state(m, seed, batch=()):
    rng = np.random.default_rng(seed)
    q, qd, tau = rng.normal(size=(3,) + batch + (m.nq,))
    return q, qd, tau, rng.normal(size=batch + (m.N, 3))


def _rel(a, b):
    """Relative difference, with a floor of 1 on the scale (q̈ of O(1) inputs may nearly cancel)."""
    return np.abs(a - b).max(initial=0.0) / max(np.abs(b).max(initial=0.0), 1.0)


def _general(m, q, qd, tau, f_ext=None):
    return articulated_body(m, q, qd, tau, f_ext).qdd


def _same_tau(m, q, qd, qdd, f_ext):
    """The kernel's τ against the array recursion's, relative to the joint forces it sums (τ may cancel them)."""
    ref = newton_euler(m, q, qd, qdd, f_ext)
    err = np.abs(inverse_dynamics(m, q, qd, qdd, f_ext) - ref.tau).max(initial=0.0)
    assert err <= 1e-13 * max(np.abs(ref.f).max(), 1.0)


@pytest.mark.parametrize("kinds", KINDS)
@pytest.mark.parametrize("tree", [False, True])
@pytest.mark.parametrize("N", [1, 2, 7, 30])
def test_kernel_equals_general_path(N, tree, kinds):
    rng = np.random.default_rng(N)
    m = random_model(N, seed=N, kinds=kinds, tree=tree, gravity=tuple(rng.normal(size=2) * 5))
    assert kernels.tables(m) is not None
    for seed in range(3):
        q, qd, tau, f_ext = _state(m, seed)
        ref, ref_f = _general(m, q, qd, tau), _general(m, q, qd, tau, f_ext)
        assert _rel(forward_dynamics(m, q, qd, tau), ref) < 1e-12
        assert _rel(forward_dynamics(m, q, qd, tau, f_ext), ref_f) < 1e-12
        if m.nq:
            assert not np.allclose(ref, ref_f)     # the external wrenches matter
        _same_tau(m, q, qd, ref_f, f_ext)


@given(st.integers(1, 12), st.integers(0, 10_000), st.booleans(), st.sampled_from(KINDS))
def test_property_kernel_equals_general_path(n, seed, tree, kinds):
    rng = np.random.default_rng(seed)
    m = random_model(n, seed=seed, kinds=kinds, tree=tree, gravity=tuple(rng.normal(size=2) * 10))
    q, qd, tau, f_ext = _state(m, seed)
    assert _rel(forward_dynamics(m, q, qd, tau, f_ext), _general(m, q, qd, tau, f_ext)) < 1e-12
    _same_tau(m, q, qd, tau, f_ext)


def test_other_joint_kinds_take_the_general_path():
    m = random_model(5, seed=3, kinds=("plane", "revolute_prismatic", "twin_prismatic", "revolute"), tree=True)
    assert kernels.tables(m) is None
    q, qd, tau, f_ext = _state(m, 3)
    assert np.array_equal(forward_dynamics(m, q, qd, tau, f_ext), _general(m, q, qd, tau, f_ext))


def test_other_inputs_take_the_validated_road():
    """Lists, float32, non-contiguous and read-only arrays give the numbers float64 arrays give."""
    m = random_model(4, seed=7, tree=True)
    q, qd, tau, f_ext = _state(m, 7)
    ref = forward_dynamics(m, q, qd, tau, f_ext)
    assert _rel(ref, _general(m, q, qd, tau, f_ext)) < 1e-12
    assert np.array_equal(forward_dynamics(m, list(q), tuple(qd), tau, f_ext.tolist()), ref)
    wide = np.zeros((2, m.nq))
    wide[0] = q
    ro = tau.copy()
    ro.setflags(write=False)
    assert np.array_equal(forward_dynamics(m, wide[0], np.repeat(qd, 2)[::2], ro, f_ext), ref)
    q32 = q.astype(np.float32)
    assert _rel(forward_dynamics(m, q32, qd, tau, f_ext), _general(m, q32.astype(float), qd, tau, f_ext)) < 1e-12


@pytest.mark.skipif(numba.config.DISABLE_JIT, reason="checks the compiled kernels")
def test_one_state_kernels_compile_one_type_and_check_shapes():
    """The one-state kernel is compiled for C-contiguous writeable float64 arrays only (without and with
    external wrenches): other types go the validated road, compiling nothing; float64 arrays of the wrong
    shape are refused by name, as the validated road refuses them."""
    from planargeo.errors import ShapeError

    m = random_model(3, seed=3, kinds=("revolute", "prismatic", "fixed"))
    q, qd, tau, f_ext = _state(m, 3)
    ref = forward_dynamics(m, q, qd, tau, f_ext)
    forward_dynamics(m, q, qd, tau)
    inverse_dynamics(m, q, qd, tau)
    inverse_dynamics(m, q, qd, tau, f_ext)
    before = len(kernels.dynamics_one.signatures)
    ro = q.copy()
    ro.setflags(write=False)
    for args in [(q.astype(np.int64), qd, tau, f_ext), (ro, qd, tau, f_ext), (q, qd, tau, np.asfortranarray(f_ext)),
                 (q, qd, tau.astype(np.float32), f_ext)]:
        assert _rel(forward_dynamics(m, *args), _general(m, *(np.asarray(a, dtype=float) for a in args))) < 1e-12
        inverse_dynamics(m, *args)
    assert np.array_equal(forward_dynamics(m, ro, qd, tau, np.asfortranarray(f_ext)), ref)
    assert len(kernels.dynamics_one.signatures) == before
    assert before == 2                     # forward and inverse alike: without and with external wrenches
    for bad, name in [((q[:-1], qd, tau, None), "q"), ((q, np.append(qd, 0.0), tau, None), "qd"),
                      ((q, qd, tau[:-1], None), "tau"), ((q, qd, tau, f_ext[:-1]), "f_ext"),
                      ((q, qd, tau, np.zeros((m.N, 2))), "f_ext")]:
        with pytest.raises(ShapeError, match=name):
            forward_dynamics(m, *bad)
    with pytest.raises(ShapeError, match="qdd"):
        inverse_dynamics(m, q, qd, tau[:-1])


# -- batches: blocks of kernels.BLOCK states shared among threads -----------------------------------------------------
BATCH_MODELS = {
    "chain10": lambda: chain_model(10),
    "prismatic chain": lambda: chain_model(4, joint="prismatic", gravity=(0.5, -9.81)),
    "random": lambda: random_model(10, seed=4, gravity=(1.5, -9.81)),
    "random tree, fixed joints": lambda: random_model(9, seed=5, kinds=("revolute", "prismatic", "fixed"), tree=True,
                                                      gravity=(-2.0, 3.0)),
}


@pytest.mark.parametrize("name", list(BATCH_MODELS))
@pytest.mark.parametrize("shape", [(40,), (5, 9), (2 * kernels.BLOCK + 3,), (kernels.PARALLEL_STATES + 5,)])
def test_batches_equal_single_states(name, shape):
    """Blocks of states, on one thread and (from PARALLEL_STATES on) on all of numba's threads."""
    m = BATCH_MODELS[name]()
    q, qd, tau, f_ext = _state(m, 1, shape)
    for f in (None, f_ext):
        out = forward_dynamics(m, q, qd, tau, f)
        assert out.shape == shape + (m.nq,) and out.dtype == np.float64
        flat = [forward_dynamics(m, *(x.reshape(-1, *x.shape[len(shape):])[k] for x in (q, qd, tau)),
                                 None if f is None else f.reshape(-1, m.N, 3)[k]) for k in range(int(np.prod(shape)))]
        assert np.array_equal(out.reshape(-1, m.nq), np.array(flat))
        tau_back = inverse_dynamics(m, q, qd, out, f)
        assert tau_back.shape == out.shape and _rel(tau_back, tau) < 1e-10
    assert _rel(forward_dynamics(m, q[:3], qd[:3], tau[:3]), _general(m, q[:3], qd[:3], tau[:3])) < 1e-12


def test_batches_strided_broadcast_and_dtypes():
    """Non-contiguous views, Fortran order, broadcast arguments and non-float64 dtypes."""
    m = random_model(7, seed=8, kinds=("revolute", "prismatic", "fixed"), tree=True)
    q, qd, tau, f_ext = _state(m, 8, (100,))
    ref = _general(m, q[::2], qd[::2], tau[::2], f_ext[::2])
    assert _rel(forward_dynamics(m, q[::2], np.asfortranarray(qd[::2]), tau.T.copy().T[::2], f_ext[::2]), ref) < 1e-12
    q2 = q.reshape(10, 10, m.nq).transpose(1, 0, 2)
    got = forward_dynamics(m, q2, qd[0], tau.reshape(10, 10, m.nq), f_ext[0])
    assert got.shape == (10, 10, m.nq)
    assert _rel(got, _general(m, q2, qd[0], tau.reshape(10, 10, m.nq), f_ext[0])) < 1e-12
    qi = np.round(3 * qd).astype(int)
    assert _rel(forward_dynamics(m, q.astype(np.float32), qi, tau),
                _general(m, q.astype(np.float32).astype(float), qi.astype(float), tau)) < 1e-12


def test_batch_singular_state_raises_like_a_single_state():
    """A singular state in a batch raises the error the same state raises alone."""
    # a point mass on its own pivot, carrying a pendulum: singular when the pendulum is in line with the link
    m = Model([Body(1.0, (0.0, 0.0), 0.0), Body(1.0, (0.5, 0.0), 0.0)],
              [Joint("revolute"), Joint("revolute", (1.0, 0.0, 0.0))], [-1, 0])
    rng = np.random.default_rng(3)
    q, qd, tau = rng.normal(size=(3, 300, 2))
    q[:, 1] = 0.3 + rng.uniform(size=300)
    assert np.isfinite(forward_dynamics(m, q, qd, tau)).all()
    q[[57, 280], 1] = 0.0
    with pytest.raises(SingularConfigurationError, match="joint 1 ") as batch:
        forward_dynamics(m, q, qd, tau)
    with pytest.raises(SingularConfigurationError) as single:
        forward_dynamics(m, q[57], qd[57], tau[57])
    assert str(batch.value) == str(single.value) and batch.value.cond == single.value.cond


def test_models_without_coordinates():
    m = random_model(3, seed=1, kinds=("fixed",))
    assert forward_dynamics(m, np.zeros(0), np.zeros(0), np.zeros(0)).shape == (0,)
    assert forward_dynamics(m, np.zeros((40, 0)), np.zeros((40, 0)), np.zeros((40, 0))).shape == (40, 0)
    assert inverse_dynamics(m, np.zeros(0), np.zeros(0), np.zeros(0), np.ones((3, 3))).shape == (0,)


def test_empty_batch():
    m = chain_model(3)
    assert forward_dynamics(m, np.zeros((0, 3)), np.zeros(3), np.zeros(3)).shape == (0, 3)


@pytest.mark.parametrize("seed", range(4))
@pytest.mark.parametrize("B", [1, 3, kernels.BLOCK - 1, kernels.BLOCK + 77, kernels.PARALLEL_STATES + 5])
def test_block_kernel_equals_the_state_kernel(seed, B):
    """The batch (states innermost, blocks of BLOCK) gives each state the per-state kernel's q̈, to 1e-13 relative."""
    m = random_model(6 + seed, seed=seed, kinds=("revolute", "prismatic", "fixed") if seed % 2 else
                     ("revolute", "prismatic"), tree=True, gravity=(0.7, -9.81))
    q, qd, tau, f_ext = _state(m, 10 + seed, (B,))
    for f in (None, f_ext):
        out = forward_dynamics(m, q, qd, tau, f)
        for b in range(B):
            one = forward_dynamics(m, q[b], qd[b], tau[b], None if f is None else f[b])
            assert np.abs(out[b] - one).max() <= 1e-13 * max(np.abs(one).max(), 1e-300)


@pytest.mark.parametrize("B", [kernels.BLOCK + 77, kernels.PARALLEL_STATES + 5])
def test_block_with_one_bad_state_raises_that_states_error(B):
    """One singular, or one non-finite, state in the middle of a batch: its own error, as it raises alone."""
    m = Model([Body(1.0, (0.0, 0.0), 0.0), Body(1.0, (0.5, 0.0), 0.0), Body(2.0, (0.0, 0.3), 0.1)],
              [Joint("revolute"), Joint("revolute", (1.0, 0.0, 0.0)), Joint("prismatic", (0.0, 0.0, 0.4))], [-1, 0, -1])
    rng = np.random.default_rng(5)
    q, qd, tau = rng.normal(size=(3, B, 3))
    q[:, 1] = 0.3 + rng.uniform(size=B)              # the pendulum out of line with the link: regular
    mid = B // 2 + 1
    for arrays, error in (((q.copy(), qd, tau), SingularConfigurationError), ((q, qd, tau.copy()), NonFiniteError)):
        if error is SingularConfigurationError:
            arrays[0][mid, 1] = 0.0                  # in line: the first joint's sᵀAs = 0
        else:
            arrays[2][mid, 2] = np.nan
        with pytest.raises(error) as batch:
            forward_dynamics(m, *arrays)
        with pytest.raises(error) as single:
            forward_dynamics(m, *(a[mid] for a in arrays))
        assert str(batch.value) == str(single.value)
