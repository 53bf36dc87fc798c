"""Reliability, second pass (issue 23): the findings ``make fuzz`` still reported, each with a test that
failed before its fix, plus the set-up's stamp of the compiled kernels."""
from __future__ import annotations

import os
import re
import shutil
import subprocess
import time
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]


# --------------------------------------------------------------------------- Makefile: the kernels' stamp
def _fake_tree(tmp_path: Path) -> tuple[Path, Path]:
    """A copy of the Makefile with the files its install step depends on, and a fake ``.venv/bin/python``
    that logs its arguments instead of installing or compiling."""
    shutil.copy(ROOT / "Makefile", tmp_path / "Makefile")
    for rel in ("pyproject.toml", "planargeo/algorithms/kernels.py", "planargeo/algorithms/compiled.py",
                "planargeo/errors.py", "planargeo/mechanics/subspaces.py", "planargeo/draw/_labels.py"):
        (tmp_path / rel).parent.mkdir(parents=True, exist_ok=True)
        (tmp_path / rel).write_text("# stand-in\n")
    log = tmp_path / "calls.log"
    py = tmp_path / ".venv" / "bin" / "python"
    py.parent.mkdir(parents=True)
    py.write_text(f'#!/bin/sh\necho "$*" >> "{log}"\n')
    py.chmod(0o755)
    return log, py


def _install(tmp_path: Path, log: Path) -> list[str]:
    """``make install`` in the fake tree: the python calls it made ("pip" / "warm" / "placer"), in order."""
    if log.exists():
        log.unlink()
    subprocess.run(["make", "--no-print-directory", "install"], cwd=tmp_path, check=True, capture_output=True,
                   text=True, timeout=60)
    calls = log.read_text().splitlines() if log.exists() else []
    return ["pip" if "pip install" in c else "warm" if "compiled --warm" in c else
            "placer" if "import warm_labels" in c else c for c in calls]


def _newer(path: Path) -> None:
    """An edit of ``path``: a modification time after every stamp (make compares times to the nanosecond)."""
    time.sleep(0.05)
    os.utime(path)


@pytest.mark.skipif(shutil.which("make") is None, reason="make is not installed")
def test_the_kernel_cache_is_filled_again_when_a_kernel_source_changes(tmp_path):
    log, _ = _fake_tree(tmp_path)
    both = ["warm", "placer"]                                  # the kernels, then the label placer's loops
    assert _install(tmp_path, log) == ["pip", *both]           # a fresh clone: install, then fill the cache
    assert _install(tmp_path, log) == []                       # nothing changed: nothing to do
    kernels = tmp_path / "planargeo/algorithms/kernels.py"
    _newer(kernels)
    assert _install(tmp_path, log) == both                     # an edited kernel: compiled again, no re-install
    before = kernels.stat().st_mtime
    _newer(tmp_path / "planargeo/errors.py")                   # COND_LIMIT is frozen into the machine code
    assert _install(tmp_path, log) == both
    assert kernels.stat().st_mtime > before                    # numba sees a new kernels.py: no stale load
    assert _install(tmp_path, log) == []                       # and that touch asks for nothing more
    _newer(tmp_path / "planargeo/draw/_labels.py")
    assert _install(tmp_path, log) == both                     # an edited placer: its loops compiled again
    _newer(tmp_path / "pyproject.toml")
    assert _install(tmp_path, log) == ["pip", *both]           # new dependencies: install, then the cache
    # a dry run with the set-up taken as done (tests/test_readme.py) runs nothing and leaves the Makefile alone
    _newer(kernels)
    made = (tmp_path / "Makefile").stat().st_mtime_ns
    log.unlink()
    dry = subprocess.run(["make", "-n", "lab", "STAMP=Makefile"], cwd=tmp_path, capture_output=True, text=True,
                         timeout=60)
    assert "scripts/lab.py" in dry.stdout and "--warm" not in dry.stdout and not log.exists()
    assert (tmp_path / "Makefile").stat().st_mtime_ns == made


# --------------------------------------------------------------------------- conics: decompositions at any scale
import warnings  # noqa: E402

import numpy as np  # noqa: E402

from planargeo.errors import DegenerateGeometryError, NumericOverflowError  # noqa: E402
from planargeo.geometry import conics  # noqa: E402


def _strict(fn, *args, **kw):
    """``fn(*args, **kw)`` with every numpy warning an error (underflow to a subnormal is no defect)."""
    with warnings.catch_warnings(), np.errstate(divide="warn", over="warn", invalid="warn", under="ignore"):
        warnings.simplefilter("error")
        return fn(*args, **kw)


@pytest.mark.parametrize("k", [1e300, 1e-300, 1.0])
def test_decompose_line_of_a_huge_or_tiny_base_is_computed(k):
    """``L = Σ uᵢ C Qᵢ`` (5.43): scaling the first base point by k divides its component by k; the other two stay.
    Reference: the decomposition of ``P = (1, 2, 3)`` on the unit base, by hand ``(-2, -1, 3)`` (the docstring)."""
    C = 1e10 * np.diag([1.0, 2.0, 4.0])                        # C Q1 is 1e310 before scaling: it overflowed
    L = C @ np.array([1.0, 2.0, 3.0])
    u = _strict(conics.decompose_line, C, L, [k, 0.0, 0.0], [0.0, 1.0, 0.0], [1.0, 1.0, 1.0])
    np.testing.assert_allclose(u, [-2.0 / k, -1.0, 3.0], rtol=1e-15)
    C0 = np.diag([1.0, 2.0, 4.0])
    u = _strict(conics.decompose_line, C0 * k, C0 @ [1.0, 2.0, 3.0] * k, [1.0, 0.0, 0.0], [0.0, 1.0, 0.0],
                [1.0, 1.0, 1.0])
    np.testing.assert_allclose(u, [-2.0, -1.0, 3.0], rtol=1e-15)   # degree 0 in (C, L) together
    u = _strict(conics.decompose_point, np.array([1.0, 2.0, 3.0]) * k, [1.0, 0.0, 0.0], [0.0, k, 0.0],
                [1.0, 1.0, 1.0])
    np.testing.assert_allclose(u, [-2.0 * k, -1.0, 3.0 * k], rtol=1e-15)


def test_decompositions_refuse_in_their_own_words():
    """A base with a repeated point at rtol = 0 (LAPACK's 'Singular matrix' before), a nearly dependent one that
    gave ±inf, and components beyond double precision."""
    with pytest.raises(DegenerateGeometryError, match="Q1, Q2, Q3"):
        _strict(conics.decompose_point, [1.0, 2.0, 3.0], [8.0, 0.016, 0.5], [0.1, -0.6, 5.8], [8.0, 0.016, 0.5],
                rtol=0.0)
    C = np.array([[0.0, 1.4197e-300, 5e-306], [1.4197e-300, 1.0, 0.0], [5e-306, 0.0, 1.0]])
    with pytest.raises(DegenerateGeometryError, match="C Q1, C Q2, C Q3"):
        _strict(conics.decompose_line, C, [-2.2251e-308, 2.8395, -9.1357e-137], [0.0, 0.0, 1.0],
                [-2.2251e-308, -9.1357e-137, 1.0], [0.0, 0.0, 1.0], rtol=0.0)
    with pytest.raises(NumericOverflowError, match="decompose_point"):     # u1 = 1e300 / 1e-300
        _strict(conics.decompose_point, [1e300, 0.0, 0.0], [1e-300, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0])


def test_special_decompositions_broadcast_and_scale():
    """A batch of base points against single ones (a ValueError from np.stack before), and a base point of
    1e300 (its component divided by 1e300, the others unchanged); reference: the points rebuilt from their
    components (5.44-5.46: P = Σ uᵢ Qᵢ, L = Σ uᵢ C Qᵢ)."""
    C = conics.conic_circle([0.0, 0.0], 1.0)
    Q1, Q2, Q3 = conics.special_base(C, [0.0, -2.0, 1.0])
    P = np.array([0.3, 0.1, 1.0])
    Q2b = np.stack([Q2, 3.0 * Q2])
    u = _strict(conics.decompose_point_special, C, P, Q1, Q2b, Q3)
    assert u.shape == (2, 3)
    for ui, q2 in zip(u, Q2b):
        np.testing.assert_allclose(ui[0] * Q1 + ui[1] * q2 + ui[2] * Q3, P, atol=1e-14)
    u = _strict(conics.decompose_line_special, C, C @ P, Q1, Q2b, Q3)
    assert u.shape == (2, 3)
    for ui, q2 in zip(u, Q2b):
        np.testing.assert_allclose(ui[0] * (C @ Q1) + ui[1] * (C @ q2) + ui[2] * (C @ Q3), C @ P, atol=1e-14)
    ref = conics.decompose_point_special(C, P, Q1, Q2, Q3)
    for fn, x in ((conics.decompose_point_special, P), (conics.decompose_line_special, C @ P)):
        u = _strict(fn, C, x, Q1 * 1e300, Q2, Q3)
        np.testing.assert_allclose(u, [ref[0] / 1e300, ref[1], ref[2]], rtol=1e-14)


# --------------------------------------------------------------------------- a blow of any magnitude
from planargeo.mechanics.impulse import impulse_response, moved_points  # noqa: E402
from planargeo.screws.twists import inertia_matrix  # noqa: E402

ROD = inertia_matrix(3.0, [1.0, 0.0], 1.0)          # the docstring's rod: m = 3, L = 2, pivot at the origin


@pytest.mark.parametrize("support", [None, [0.0, 0.0, 1.0]])
@pytest.mark.parametrize("j0, k", [([0.3, -0.7, 0.45], -1070), ([0.3, -0.7, 0.45], -1040),
                                   ([0.0, 0.75, 0.75], 1024), ([0.3, -0.7, 0.45], 0)])
def test_a_blow_is_linear_down_to_subnormals_and_up_to_the_largest_float(j0, k, support):
    """Δv and ĵᵣ are linear in ĵ (thesis 6.63, 6.93): the blow 2^k ĵ₀ gives 2^k times the answer for ĵ₀, rounded
    once.  Before, a subnormal blow lost digits in every product (2^-1070: 3 significant bits), and
    ĵ = 2^1024 (0, 0.75, 0.75) gave Δv = inf through 1.33 · 1.35e308 (the true ω̇ component is 4.5e307)."""
    with np.errstate(under="ignore"):
        j = np.ldexp(np.array(j0), k)                  # the blow as given (a subnormal keeps fewer digits)
        ref_dv, ref_r = impulse_response(ROD, np.ldexp(j, -k), support)   # the same blow, scaled exactly to ~1
        want_dv, want_r = np.ldexp(ref_dv, k), np.ldexp(ref_r, k)
        dv, r = _strict(impulse_response, ROD, j, support)
    assert np.array_equal(dv, want_dv) and np.array_equal(r, want_r)


def test_a_blow_beyond_double_precision_is_refused_in_words():
    tiny = inertia_matrix(1e-300, [1.0, 0.0], 1e-300)
    with pytest.raises(NumericOverflowError, match="impulse"):
        _strict(impulse_response, tiny, [0.0, 1e300, 0.0])


def test_moved_points_turn_about_the_pole_and_shift_in_a_translation():
    """p(t) = P + R(ωt)(p₀ − P) with the pole P = (−v_y, v_x)/ω (the explorer's old formula) for an ordinary
    turn; p₀ + v t for a translation; and a subnormal ω (the pole beyond 1e308) is the translation's limit."""
    pts = np.array([[0.0, 0.0], [0.9, 0.0], [0.9, 0.04], [-0.2, 0.3]])
    dv, t = np.array([0.4, -1.1, 2.3]), 0.7
    P = np.array([-dv[1], dv[0]]) / dv[2]
    c, s = np.cos(dv[2] * t), np.sin(dv[2] * t)
    np.testing.assert_allclose(moved_points(dv, pts, t), (pts - P) @ np.array([[c, s], [-s, c]]) + P, atol=1e-14)
    np.testing.assert_array_equal(moved_points([1.5, -2.0, 0.0], pts, t), pts + t * np.array([1.5, -2.0]))
    for w in (5e-324, -1e-310, 1e-9):
        got = _strict(moved_points, [1.5, -2.0, w], pts, 3.0)
        np.testing.assert_allclose(got, pts + 3.0 * np.array([1.5, -2.0]), atol=1e-7)
    with pytest.raises(NumericOverflowError):
        _strict(moved_points, [1e308, 0.0, 0.0], pts, 1e10)


# --------------------------------------------------------------------------- closed loops: a budget of evaluations
import math  # noqa: E402

from _limits import time_limit  # noqa: E402
from planargeo.errors import InputError, SizeLimitError  # noqa: E402
from planargeo.scenes.slider_crank import slider_crank_model, slider_crank_state  # noqa: E402
from planargeo.simulate.loops import LOOP_MAX_EVALS, simulate_loops  # noqa: E402


@pytest.fixture(scope="module")
def crank():
    m = slider_crank_model()
    q, qd = slider_crank_state()
    return m, q, qd


def test_a_loop_run_past_its_budget_is_refused_at_once(crank):
    """RK23 at rtol 1e-10 needs about 60 000 evaluations of the constrained dynamics per second of the crank
    (order 3); half a second of it ran for minutes (150 s measured under load).  Now its first 100 steps
    extrapolate past LOOP_MAX_EVALS and it is refused, naming the limit and the opt-in."""
    m, q, qd = crank
    with time_limit(90), pytest.raises(SizeLimitError, match=f"max_evals = {LOOP_MAX_EVALS}"):
        simulate_loops(m, q, qd, 0.5, method="RK23", rtol=1e-10, atol=1e-12, progress=False)


@pytest.mark.parametrize("t_end, error", [(1e6, SizeLimitError), (1e300, SizeLimitError), (math.inf, InputError),
                                          (math.nan, InputError), (-1.0, InputError), (0.0, InputError)])
def test_loop_durations_are_bounded_or_named(crank, t_end, error):
    m, q, qd = crank
    with time_limit(90), pytest.raises(error, match="t_end|max_evals|max_steps"):
        simulate_loops(m, q, qd, t_end, progress=False)


def test_a_loop_run_that_reaches_its_budget_keeps_what_it_computed(crank):
    """The same run with and without a budget: the limited one stops with status 'limit' and a message naming
    max_evals, and holds the first steps of the full one, bit for bit; RK4's known count is checked up front."""
    m, q, qd = crank
    full = simulate_loops(m, q, qd, 0.05, rtol=1e-8, progress=False)
    part = simulate_loops(m, q, qd, 0.05, rtol=1e-8, progress=False, max_evals=100)
    assert full.status == "ok" and part.status == "limit" and "max_evals = 100" in part.message
    assert 1 < len(part.t) < len(full.t) and part.nfev >= 100
    np.testing.assert_array_equal(part.t, full.t[:len(part.t)])
    np.testing.assert_array_equal(part.q, full.q[:len(part.t)])
    with pytest.raises(SizeLimitError, match="max_evals = 10"):
        simulate_loops(m, q, qd, 0.05, method="RK4", dt=0.01, progress=False, max_evals=10)   # 20 needed
    with pytest.raises(InputError, match="max_evals"):
        simulate_loops(m, q, qd, 0.05, progress=False, max_evals=0)


@pytest.mark.parametrize("method", ["DOP853", "RK45", "RK23", "Radau", "BDF", "LSODA"])
def test_a_start_too_fast_to_integrate_is_refused_in_words(method):
    """q̇ = 1e150 (q̈ ≈ 1e300): scipy's error norms square the scaled rates, so every method failed in numpy's
    words (overflow in dot, 'array must not contain infs', divide by zero) or stalled at t = 0 for a million
    steps (LSODA: 205 s).  Now the start is refused naming the limit and the arguments."""
    from planargeo.mechanics.model import chain_model
    from planargeo.simulate.integrate import RATE_LIMIT, simulate

    with time_limit(60), pytest.raises(NumericOverflowError, match=re.escape(f"below {RATE_LIMIT:g} (qd0")):
        _strict(simulate, chain_model(2), [0.1, 0.2], [1e150, -3e150], 0.01, method=method, progress=False)


def test_the_slider_crank_started_too_fast_is_refused_in_words(crank):
    m, q, _ = crank
    with time_limit(60), pytest.raises(NumericOverflowError, match="qd0"):
        _strict(simulate_loops, m, q, [1e150, -10.0, 1e-300], 0.2763, method="RK23", rtol=1e-6, atol=1e-8,
                dt=0.01, max_step=0.1, stabilization="baumgarte", progress=False)


def test_a_motion_refuses_a_time_beyond_one_calls_work_and_keeps_what_it_did():
    """The chain explorer's time slider: a far time costs a bounded step, refused by name; asking again goes on."""
    import math

    from planargeo.errors import SizeLimitError
    from planargeo.widgets._motion import Motion

    w = 40.0                                   # a fast oscillator: many steps per second
    m = Motion(lambda t, y: [y[1], -w * w * y[0]], [1.0, 0.0], chunk=0.5, max_evals=3000)
    with pytest.raises(SizeLimitError, match=r"t = 30 s .*computed up to t = \d"):
        m.at(30.0)
    first = m.reached
    assert 0.0 < first < 30.0
    with pytest.raises(SizeLimitError):
        m.at(30.0)
    assert m.reached > first                   # the second call went on from where the first stopped
    while True:
        try:
            y = m.at(30.0)
            break
        except SizeLimitError:
            pass
    assert abs(y[0] - math.cos(w * 30.0)) < 1e-5   # the closed form x = cos ωt
