"""The fast paths of ``forward_dynamics`` (compiled plan, batched plan) against the general path and CRBA.

The physics reference stays the dense CRBA solve and Pinocchio (test_dyn_aba.py,
test_pinocchio.py); here the compiled straight-line plan (body-origin frame,
gravity as base acceleration, zero constants folded) must reproduce the general
3×k array recursion of :func:`articulated_body` to 1e-12 relative, on chains and
trees of revolute, prismatic and fixed joints, with random gravity and external
wrenches, and every input must still be validated.  Batches above SMALL_BATCH
run the plan lowered to in-place numpy calls on rows, block by block: they must
agree with CRBA (the independent reference) and with the states one by one, at
block boundaries, for strided, broadcast and non-float64 inputs, and raise what
single states raise.
"""
import re

import numpy as np
import pytest
from hypothesis import given
from hypothesis import strategies as st

from planargeo.algorithms import aba
from planargeo.algorithms.aba import articulated_body, forward_dynamics
from planargeo.algorithms.crba import forward_dynamics_crba
from planargeo.errors import NonFiniteError, ShapeError, SingularConfigurationError
from planargeo.mechanics.model import Body, Joint, Model, chain_model, random_model

KINDS = [("revolute",), ("prismatic",), ("revolute", "prismatic"), ("revolute", "prismatic", "fixed")]


def _state(m, seed):
    rng = np.random.default_rng(seed)
    q, qd, tau = rng.normal(size=(3, m.nq))
    return q, qd, tau, rng.normal(size=(m.N, 3))


def _rel(a, b):
    """Relative difference, with a floor of 1 on the scale as in test_dyn_aba (q̈ of O(1) inputs).

    Without the floor a q̈ that nearly cancels (|q̈| ~ 1e-4 from terms ~ 10) compares rounding
    errors of two orderings of the sum: e.g. ``random_model(1, seed=6517)`` differs by 1.1e-15.
    """
    return np.abs(a - b).max() / max(np.abs(b).max(), 1.0)


@pytest.fixture
def no_full_validation(monkeypatch):
    """Fail if forward_dynamics falls back to the general validator (the fast path must not need it)."""
    def boom(*args, **kwargs):
        raise AssertionError("check_state called: the fast path was not taken")

    monkeypatch.setattr(aba, "check_state", boom)


def _general(m, q, qd, tau, f_ext=None):
    return articulated_body(m, q, qd, tau, f_ext).qdd


@pytest.mark.parametrize("kinds", KINDS)
@pytest.mark.parametrize("tree", [False, True])
@pytest.mark.parametrize("N", [1, 2, 7, 30])
def test_fast_path_equals_general_path(N, tree, kinds):
    rng = np.random.default_rng(N)
    g = tuple(rng.normal(size=2) * 5)
    m = random_model(N, seed=N, kinds=kinds, tree=tree, gravity=g)
    if m.nq == 0:
        pytest.skip("all joints fixed")
    for seed in range(3):
        q, qd, tau, f_ext = _state(m, seed)
        ref, ref_f = _general(m, q, qd, tau), _general(m, q, qd, tau, f_ext)
        assert _rel(forward_dynamics(m, q, qd, tau), ref) < 1e-12
        assert _rel(forward_dynamics(m, q, qd, tau, f_ext), ref_f) < 1e-12
        assert not np.allclose(ref, ref_f)     # the external wrenches matter


@given(st.integers(1, 12), st.integers(0, 10_000), st.booleans(), st.sampled_from(KINDS))
def test_property_fast_path_equals_general_path(n, seed, tree, kinds):
    rng = np.random.default_rng(seed)
    m = random_model(n, seed=seed, kinds=kinds, tree=tree, gravity=tuple(rng.normal(size=2) * 10))
    if m.nq == 0:
        return
    q, qd, tau, f_ext = _state(m, seed)
    assert _rel(forward_dynamics(m, q, qd, tau, f_ext), _general(m, q, qd, tau, f_ext)) < 1e-12


def test_fast_path_skips_the_general_validator(no_full_validation):
    m = random_model(6, seed=2, tree=True)
    q, qd, tau, f_ext = _state(m, 2)
    out = forward_dynamics(m, q, qd, tau, f_ext)
    assert out.shape == (m.nq,) and out.dtype == np.float64


def test_zero_constants_folded_and_plans_shared():
    """chain_model has zero placement angles, y offsets and x gravity: folded; same topology shares code."""
    a, b = chain_model(5), chain_model(5, mass=3.0, length=0.5)
    q, qd, tau, f_ext = _state(a, 5)
    for m in (a, b):
        assert _rel(forward_dynamics(m, q, qd, tau, f_ext), _general(m, q, qd, tau, f_ext)) < 1e-12
    fa, Ca = aba._plan(a, True)
    fb, Cb = aba._plan(b, True)
    assert fa is fb and Ca != Cb
    # the zero pattern is part of the plan: a nonzero x gravity is not folded away
    c = chain_model(5, gravity=(2.0, -9.81))
    assert aba._plan(c, True)[0] is not fa
    assert _rel(forward_dynamics(c, q, qd, tau), _general(c, q, qd, tau)) < 1e-12


def test_other_inputs_take_the_validated_route():
    m = random_model(4, seed=7, tree=True)
    q, qd, tau, f_ext = _state(m, 7)
    ref = _general(m, q, qd, tau, f_ext)
    assert _rel(forward_dynamics(m, list(q), tuple(qd), tau, f_ext.tolist()), ref) < 1e-12
    assert _rel(forward_dynamics(m, q.astype(np.float32), qd, tau, f_ext), _general(m, q.astype(np.float32), qd, tau,
                                                                                   f_ext)) < 1e-12
    # a finite state whose sum overflows: the cheap check fails, the full validator accepts it
    two = Model([Body(1.0, (0.5, 0.0), 0.1)] * 2, [Joint("revolute")] * 2, [-1, -1])
    out = forward_dynamics(two, np.full(2, 1e308), np.zeros(2), np.zeros(2))
    assert out.shape == (2,) and np.isfinite(out).all()


@pytest.mark.parametrize("name", ["q", "qd", "tau"])
def test_bad_single_states_raise(name):
    m = chain_model(3)
    args = dict(q=np.zeros(3), qd=np.zeros(3), tau=np.zeros(3))
    args[name] = np.array([0.0, np.nan, 0.0])
    with pytest.raises(NonFiniteError, match=name):
        forward_dynamics(m, **args)
    args[name] = np.zeros(4)
    with pytest.raises(ShapeError, match=name):
        forward_dynamics(m, **args)
    with pytest.raises(NonFiniteError, match="f_ext"):
        forward_dynamics(m, np.zeros(3), np.zeros(3), np.zeros(3), np.array([[0.0, np.inf, 0.0]] * 3))
    with pytest.raises(ShapeError, match="f_ext"):
        forward_dynamics(m, np.zeros(3), np.zeros(3), np.zeros(3), np.zeros((2, 3)))


def test_singular_on_the_fast_path():
    m = Model([Body(1.0, (0.0, 0.0), 0.0)], [Joint("revolute")], [-1])
    with pytest.raises(SingularConfigurationError, match="joint 0") as e:
        forward_dynamics(m, np.zeros(1), np.zeros(1), np.zeros(1))
    assert e.value.cond == np.inf
    # a point mass on its own pivot at the tip of a pendulum
    m = Model([Body(1.0, (0.5, 0.0), 0.1), Body(1.0, (0.0, 0.0), 0.0)],
              [Joint("revolute"), Joint("revolute", (1.0, 0.0, 0.3))], [-1, 0])
    with pytest.raises(SingularConfigurationError, match="joint 1"):
        forward_dynamics(m, np.zeros(2), np.zeros(2), np.zeros(2))


def test_models_beyond_the_plan_limit_use_the_float_loop(monkeypatch):
    monkeypatch.setattr(aba, "MAX_PLAN_BODIES", 3)
    m = random_model(6, seed=11, kinds=("revolute", "prismatic", "fixed"), tree=True)
    q, qd, tau, f_ext = _state(m, 11)
    assert _rel(forward_dynamics(m, q, qd, tau, f_ext), _general(m, q, qd, tau, f_ext)) < 1e-12
    assert m._arrays["aba_plan"] is False


def test_small_batches_use_the_plan_state_by_state():
    m = random_model(5, seed=3, tree=True)
    rng = np.random.default_rng(3)
    q, qd, tau = rng.normal(size=(3, 4, m.nq))
    f_ext = rng.normal(size=(4, m.N, 3))
    out = forward_dynamics(m, q, qd, tau, f_ext)
    assert _rel(out, _general(m, q, qd, tau, f_ext)) < 1e-12


@pytest.mark.parametrize("tree", [False, True])
def test_packed_plans_equal_general_path(monkeypatch, tree):
    """Plans for many bodies keep per-body values in tuples between passes: same results."""
    monkeypatch.setattr(aba, "PACK_BODIES", 2)
    for seed, kinds in enumerate(KINDS):
        m = random_model(9, seed=seed, kinds=kinds, tree=tree, gravity=(1.5, -9.81))
        if m.nq == 0:
            continue
        q, qd, tau, f_ext = _state(m, seed)
        assert _rel(forward_dynamics(m, q, qd, tau), _general(m, q, qd, tau)) < 1e-12
        assert _rel(forward_dynamics(m, q, qd, tau, f_ext), _general(m, q, qd, tau, f_ext)) < 1e-12
        assert m._arrays["aba_plan"][0][-1] is True     # the packed layout was used


def test_large_models_compile_on_reuse(monkeypatch):
    """A one-off call on a large model runs the float loop; the plan is compiled once the model is reused."""
    monkeypatch.setattr(aba, "EAGER_PLAN_BODIES", 3)
    m = random_model(7, seed=31, kinds=("revolute", "prismatic", "fixed"), tree=True)
    q, qd, tau, f_ext = _state(m, 31)
    ref = _general(m, q, qd, tau)
    first = forward_dynamics(m, q, qd, tau)
    assert "aba_plan0" not in m._arrays
    assert _rel(first, ref) < 1e-12
    for _ in range(3):
        assert _rel(forward_dynamics(m, q, qd, tau), ref) < 1e-12
    assert "aba_plan0" in m._arrays
    assert _rel(forward_dynamics(m, q, qd, tau, f_ext), _general(m, q, qd, tau, f_ext)) < 1e-12


@pytest.mark.parametrize("B", [1, 3])
def test_few_states_agree_and_validate(B, monkeypatch):
    """A few states as (B, nq) arrays take the cheap check and the plan state by state."""
    m = random_model(5, seed=9, tree=True)
    rng = np.random.default_rng(9)
    q, qd, tau = rng.normal(size=(3, B, m.nq))
    ref = _general(m, q, qd, tau)
    with monkeypatch.context() as mp:
        mp.setattr(aba, "check_state", lambda *a, **k: pytest.fail("check_state called"))
        out = forward_dynamics(m, q, qd, tau)
    assert out.shape == (B, m.nq)
    assert _rel(out, ref) < 1e-12
    qd[0, 1] = np.inf
    with pytest.raises(NonFiniteError, match="qd"):
        forward_dynamics(m, q, qd, tau)


# -- batches: the plan on rows of numbers (one per state), block by block ----------------------------------------

BATCH_MODELS = {
    "chain10": lambda: chain_model(10),
    "prismatic chain": lambda: chain_model(4, joint="prismatic", gravity=(0.5, -9.81)),
    "random": lambda: random_model(10, seed=4, gravity=(1.5, -9.81)),
    "random tree, fixed joints": lambda: random_model(9, seed=5, kinds=("revolute", "prismatic", "fixed"), tree=True,
                                                      gravity=(-2.0, 3.0)),
}


@pytest.fixture
def no_component_path(monkeypatch):
    """Fail if a batch falls back to the component-wise path (the batched plan must cover it)."""
    def boom(*args, **kwargs):
        raise AssertionError("_aba_components called: the batched plan was not taken")

    monkeypatch.setattr(aba, "_aba_components", boom)


def _batch_state(m, shape, seed):
    rng = np.random.default_rng(seed)
    q, qd, tau = rng.normal(size=(3,) + shape + (m.nq,))
    return q, qd, tau, rng.normal(size=shape + (m.N, 3))


@pytest.mark.parametrize("name", list(BATCH_MODELS))
@pytest.mark.parametrize("shape", [(40,), (5, 9)])
def test_batched_plan_equals_crba(name, shape, monkeypatch, no_component_path):
    """Batches above SMALL_BATCH run the batched plan; CRBA (dense solve) is the independent reference."""
    monkeypatch.setattr(aba, "BATCH_CHUNK", 16)     # several blocks and a partial one
    m = BATCH_MODELS[name]()
    q, qd, tau, f_ext = _batch_state(m, shape, 1)
    for f in (None, f_ext):
        out = forward_dynamics(m, q, qd, tau, f)
        assert out.shape == shape + (m.nq,) and out.dtype == np.float64
        assert _rel(out, forward_dynamics_crba(m, q, qd, tau, f)) < 1e-12
    assert not np.allclose(forward_dynamics(m, q, qd, tau), forward_dynamics(m, q, qd, tau, f_ext))


@pytest.mark.parametrize("B", [33, 47, 48, 49, 64, 65])
def test_batched_plan_block_boundaries(B, monkeypatch, no_component_path):
    """Batches just below, at and above multiples of the block size agree with the states one by one."""
    monkeypatch.setattr(aba, "BATCH_CHUNK", 16)
    m = random_model(6, seed=B, tree=True)
    q, qd, tau, f_ext = _batch_state(m, (B,), B)
    out = forward_dynamics(m, q, qd, tau, f_ext)
    assert _rel(out, forward_dynamics_crba(m, q, qd, tau, f_ext)) < 1e-12
    one = np.array([forward_dynamics(m, q[k], qd[k], tau[k], f_ext[k]) for k in range(B)])
    assert _rel(out, one) < 1e-14


@pytest.mark.parametrize("B", [aba.BATCH_CHUNK - 1, aba.BATCH_CHUNK + 1])
def test_batched_plan_default_block_size(B, no_component_path):
    m = chain_model(5)
    q, qd, tau, _ = _batch_state(m, (B,), 7)
    assert _rel(forward_dynamics(m, q, qd, tau), forward_dynamics_crba(m, q, qd, tau)) < 1e-12


def test_batched_plan_strided_broadcast_and_dtypes(monkeypatch, no_component_path):
    """Non-contiguous views, Fortran order, broadcast arguments and non-float64 dtypes take the batched plan."""
    monkeypatch.setattr(aba, "BATCH_CHUNK", 32)
    m = random_model(7, seed=8, kinds=("revolute", "prismatic", "fixed"), tree=True)
    q, qd, tau, f_ext = _batch_state(m, (100,), 8)
    ref = forward_dynamics_crba(m, q[::2], qd[::2], tau[::2], f_ext[::2])
    assert _rel(forward_dynamics(m, q[::2], np.asfortranarray(qd[::2]), tau.T.copy().T[::2], f_ext[::2]), ref) < 1e-12
    # (B1, B2) from a transposed view, qd and f_ext broadcast from one state
    q2 = q.reshape(10, 10, m.nq).transpose(1, 0, 2)
    got = forward_dynamics(m, q2, qd[0], tau.reshape(10, 10, m.nq), f_ext[0])
    ref = forward_dynamics_crba(m, q2, np.broadcast_to(qd[0], q2.shape), tau.reshape(10, 10, m.nq),
                                np.broadcast_to(f_ext[0], (10, 10, m.N, 3)))
    assert got.shape == (10, 10, m.nq) and _rel(got, ref) < 1e-12
    # float32 and integer inputs are converted to float64 like single states
    q32, qi = q.astype(np.float32), np.round(3 * qd).astype(int)
    ref = forward_dynamics_crba(m, q32.astype(float), qi.astype(float), tau)
    assert _rel(forward_dynamics(m, q32, qi, tau), ref) < 1e-12


def test_batched_plan_singular_state_raises_like_a_single_state():
    """A singular state in a batch raises the error the single-state plan raises for it (first such state)."""
    # a point mass on its own pivot, carrying a pendulum: singular when the pendulum is in line with the link
    m = Model([Body(1.0, (0.0, 0.0), 0.0), Body(1.0, (0.5, 0.0), 0.0)],
              [Joint("revolute"), Joint("revolute", (1.0, 0.0, 0.0))], [-1, 0])
    rng = np.random.default_rng(3)
    q, qd, tau = rng.normal(size=(3, 100, 2))
    q[:, 1] = 0.3 + rng.uniform(size=100)
    assert np.isfinite(forward_dynamics(m, q, qd, tau)).all()
    q[[57, 80], 1] = 0.0
    with pytest.raises(SingularConfigurationError, match="joint 0") as batch:
        forward_dynamics(m, q, qd, tau)
    with pytest.raises(SingularConfigurationError) as single:
        forward_dynamics(m, q[57], qd[57], tau[57])
    assert str(batch.value) == str(single.value) and batch.value.cond == single.value.cond


def test_batched_plan_overflow_falls_back_to_the_component_path(monkeypatch):
    """Finite inputs whose results overflow give the component path's values (non-finite), not a crash."""
    m = chain_model(3)
    q, qd, tau, _ = _batch_state(m, (40,), 9)
    qd[5] = 1e200
    with np.errstate(all="ignore"):
        got = forward_dynamics(m, q, qd, tau)
        monkeypatch.setattr(aba, "_batch_plan", lambda *a: None)
        ref = forward_dynamics(m, q, qd, tau)
    assert not np.isfinite(got[5]).all()
    np.testing.assert_array_equal(got, ref)


def test_batched_plan_bad_input_raises():
    m = chain_model(3)
    q, qd, tau, f_ext = _batch_state(m, (50,), 10)
    qd[31, 2] = np.nan
    with pytest.raises(NonFiniteError, match="qd"):
        forward_dynamics(m, q, qd, tau)
    with pytest.raises(ShapeError, match="tau"):
        forward_dynamics(m, q, q, tau[:, :2])
    with pytest.raises(ShapeError, match="f_ext"):
        forward_dynamics(m, q, q, tau, f_ext[:, :2])


def test_batched_plan_large_and_packed_models(monkeypatch):
    """Large models compile the batched plan on reuse; packed constants (many bodies) are flattened for it."""
    monkeypatch.setattr(aba, "EAGER_PLAN_BODIES", 3)
    monkeypatch.setattr(aba, "PACK_BODIES", 2)
    m = random_model(7, seed=12, kinds=("revolute", "prismatic", "fixed"), tree=True)
    q, qd, tau, f_ext = _batch_state(m, (40,), 12)
    ref = forward_dynamics_crba(m, q, qd, tau, f_ext)
    for _ in range(4):
        assert _rel(forward_dynamics(m, q, qd, tau, f_ext), ref) < 1e-12
    assert m._arrays["aba_batch_calls"] == 4 and m._arrays["aba_plan"][0][-1] is True
    with monkeypatch.context() as mp:
        mp.setattr(aba, "_aba_components", lambda *a, **k: pytest.fail("component path after compilation"))
        assert _rel(forward_dynamics(m, q, qd, tau, f_ext), ref) < 1e-12


def test_batched_plan_without_coordinates():
    m = random_model(3, seed=1, kinds=("fixed",))
    assert forward_dynamics(m, np.zeros((40, 0)), np.zeros((40, 0)), np.zeros((40, 0))).shape == (40, 0)


def test_batched_plan_source_reuses_rows():
    """The lowered plan writes every value into a preallocated row; rows are reused once their value is dead."""
    m = chain_model(10)
    (kinds, parents, zero, checks, _), _ = aba._plan_entry(m)
    src, nreg = aba._batch_source(aba._plan_lines(kinds, parents, zero, False, False, checks))
    calls = [line.strip() for line in src.splitlines()[3:] if line.strip().startswith(("mul(", "add(", "sub("))]
    assert len(calls) > 5 * nreg        # far fewer rows than values
    assert all(" = " not in c for c in calls)   # no temporaries: every call writes into a row
    assert src.count("sincos(") == 10 and "tan(" not in src   # cos and sin of each angle in one call


def test_table_sine_and_cosine():
    """The batched plan's cos/sin (table + short polynomials) agree with libm to about one unit in the last place."""
    rng = np.random.default_rng(0)
    h = 2 * np.pi / aba.TRIG_TABLE
    x = np.concatenate([rng.uniform(-aba.TRIG_TABLE_RANGE, aba.TRIG_TABLE_RANGE, 20_000), rng.normal(size=20_000) * 3,
                        np.arange(-3000, 3000) * h, (np.arange(-3000, 3000) + 0.5) * h,   # table points, midpoints
                        [0.0, -0.0, np.pi, -np.pi, np.pi / 2, 1e-300, 0.999 * aba.TRIG_TABLE_RANGE]])
    n = len(x)
    c, s, K, R, Z = np.empty((5, n))
    aba._sincos_table(x, c, s, K, R, Z, np.empty(n, np.int64))
    assert np.abs(c - np.cos(x)).max() <= 2 * np.spacing(1.0)
    assert np.abs(s - np.sin(x)).max() <= 2 * np.spacing(1.0)


def test_batched_plan_large_angles_use_libm(monkeypatch):
    """Angles beyond the table's range (here q ~ 1e5) take numpy's cos and sin; results as for single states."""
    calls = []
    monkeypatch.setattr(aba, "_sincos_numpy", lambda x, c, s: (calls.append(1), np.cos(x, c), np.sin(x, s)))
    m = chain_model(4)
    q, qd, tau, _ = _batch_state(m, (40,), 13)
    q[7] *= 1e5
    out = forward_dynamics(m, q, qd, tau)
    assert calls
    one = np.array([forward_dynamics(m, q[k], qd[k], tau[k]) for k in range(40)])
    assert _rel(out, one) < 1e-13


@given(st.integers(1, 8), st.integers(0, 10_000), st.booleans())
def test_property_left_out_singularity_tests_cannot_fail(n, seed, tree):
    """Where the plan leaves a joint's singularity test out, the test provably passes: try hard to make it fail.

    Extreme masses, inertias down to zero, coms on and off the joints, any angles: the plan with every
    test kept never raises for a joint whose test was left out.
    """
    rng = np.random.default_rng(seed)
    bodies, joints, parents = [], [], []
    for i in range(n):
        mass = 10.0 ** rng.uniform(-6, 6)
        com = tuple(rng.uniform(-1, 1, 2) * rng.choice([0.0, 1e-6, 1.0, 10.0]))
        bodies.append(Body(mass, com, mass * rng.choice([0.0, 1e-9, 1.0]) * rng.uniform(0, 1)))
        joints.append(Joint(str(rng.choice(["revolute", "revolute", "fixed", "prismatic"])),
                            tuple(rng.uniform(-1, 1, 3) * [rng.choice([0.0, 1e-6, 1.0, 100.0])] * 2 + [3.0])))
        parents.append(int(rng.integers(-1, i)) if tree and i > 0 else i - 1)
    m = Model(bodies, joints, parents)
    if m.nq == 0:
        return
    (kinds, par, zero, checks, pack), C = aba._plan_entry(m)
    ns = {}
    exec(aba._plan_source(kinds, par, zero, False, pack, None), vars(aba), ns)   # every test kept
    for k in range(20):
        q = rng.normal(size=m.nq) * rng.choice([1.0, 100.0])
        try:
            ns["aba_plan"](C, q.tolist(), rng.normal(size=m.nq).tolist(), rng.normal(size=m.nq).tolist(), None)
        except SingularConfigurationError as e:
            joint = int(re.search(r"joint (\d+)", str(e)).group(1))
            assert checks[joint], f"joint {joint}'s test was left out but fails"
