"""Where the forward-dynamics methods break down, against an independent extended-precision reference.

This file holds the study's reference (``reference_qdd``): the joint-space
equations of motion ``H q̈ = τ - C`` written from scratch with world-frame
Jacobians, evaluated and solved in ``np.longdouble`` (x87 extended precision,
ε ≈ 1.1e-19) or, for small models, in exact rational arithmetic
(``fractions.Fraction``).  Nothing of :mod:`planargeo` is used for it except
reading the model's numbers.  ``benchmarks/breakdown.py`` imports it from here
(one copy).

Reference formulation (planar, one coordinate per revolute / prismatic joint):

* body poses by composing ``(cos, sin)`` pairs of the placements and joint
  angles (so the exact mode only rounds the sines and cosines, to longdouble);
* centre-of-mass Jacobian columns ``J_c[i][:, k] = ẑ × (c_i - o_k)`` (revolute
  joint ``k`` with axis point ``o_k``) or ``e_k`` (prismatic, world sliding
  direction), angular columns 1 / 0, for every ancestor ``k`` of ``i``;
* ``H = Σ m_i J_cᵀ J_c + J_i J_ωᵀ J_ω``; in the plane ``J_ω`` is constant, so the
  velocity bias is only ``J̇_c q̇ = Σ_k q̇_k (ẑ × (ċ_i - ȯ_k))`` (revolute) or
  ``q̇_k ω_k ẑ × e_k`` (prismatic);
* ``τ - C = τ + Σ m_i J_cᵀ (g - J̇_c q̇) + Σ J_iᵀ f_i`` (``J_i`` the twist
  Jacobian at the origin, ``f_i`` the external wrench);
* solved by Gaussian elimination without pivoting (``H`` is symmetric positive
  definite) in the same arithmetic.

The reference's own error is at most about ``ε_ld cond(H)`` (longdouble) and
only the sine/cosine rounding (exact mode).
"""
from __future__ import annotations

from fractions import Fraction

import numpy as np
import pytest

from planargeo.algorithms.aba import forward_dynamics
from planargeo.algorithms.chain_splitting import forward_dynamics_mobility_split
from planargeo.algorithms.crba import forward_dynamics_crba
from planargeo.algorithms.loops import SINGULAR_COND, constrained_dynamics_lagrange, loop_solve
from planargeo.algorithms.projective import forward_dynamics_projective
from planargeo.algorithms.stacked import forward_dynamics_stacked
from planargeo.errors import SingularConfigurationError
from planargeo.model import Body, Joint, Model, chain_model  # noqa: F401

EPS = float(np.finfo(float).eps)
EPS_LD = float(np.finfo(np.longdouble).eps)

METHODS = {
    "aba": forward_dynamics,
    "projective": forward_dynamics_projective,
    "mobility_split": forward_dynamics_mobility_split,
    "stacked": forward_dynamics_stacked,
    "crba": forward_dynamics_crba,
}
RECURSIVE = ("aba", "projective", "mobility_split", "stacked")


# =========================================================================== reference
def _exact(x):
    """A longdouble (or float) as an exact Fraction."""
    return Fraction(*np.longdouble(x).as_integer_ratio())


def _cs(angle, mode):
    a = np.longdouble(angle)
    c, s = np.cos(a), np.sin(a)
    return (_exact(c), _exact(s)) if mode == "exact" else (c, s)


def _num(x, mode):
    return _exact(x) if mode == "exact" else np.longdouble(x)


def _perp(v):
    return np.array([-v[1], v[0]], dtype=v.dtype)


def _rot(cs, v):
    c, s = cs
    return np.array([c * v[0] - s * v[1], s * v[0] + c * v[1]], dtype=v.dtype)


def _compose(a, b):
    return (a[0] * b[0] - a[1] * b[1], a[1] * b[0] + a[0] * b[1])


def _lu(A):
    """Gaussian elimination without pivoting (A SPD), in A's arithmetic: (multipliers, U) packed in one array."""
    A = A.copy()
    for k in range(len(A) - 1):
        f = A[k + 1:, k] / A[k, k]
        A[k + 1:, k + 1:] -= np.outer(f, A[k, k + 1:])
        A[k + 1:, k] = f
    return A


def _lu_solve(LU, b):
    b = b.copy()
    n = len(b)
    for k in range(n - 1):
        b[k + 1:] -= LU[k + 1:, k] * b[k]
    x = b.copy()
    for k in range(n - 1, -1, -1):
        x[k] = (b[k] - LU[k, k + 1:] @ x[k + 1:]) / LU[k, k]
    return x


def _gauss_solve(A, b):
    """Solve A x = b by Gaussian elimination without pivoting (A symmetric positive definite)."""
    return _lu_solve(_lu(A), b)


def reference_system(model: Model, q, qd, tau, f_ext=None, mode: str = "longdouble"):
    """``(H, τ - C)`` of the model in longdouble (``mode="longdouble"``) or exact Fractions (``"exact"``).

    Independent of the package's algorithms: world-frame Jacobians, ``H = Σ Jᵀ I J``
    and the bias from the Jacobian derivative (module docstring).
    """
    dt = object if mode == "exact" else np.longdouble
    N = model.N
    kinds = [j.kind for j in model.joints]
    for k in kinds:
        if k not in ("revolute", "prismatic", "fixed"):
            raise NotImplementedError(f"reference handles revolute, prismatic and fixed joints, not {k!r}")
    col = []                                    # joint i -> coordinate index or None
    n = 0
    for k in kinds:
        col.append(n if k != "fixed" else None)
        n += k != "fixed"
    q = np.asarray(q, dtype=float)
    qd = np.asarray(qd, dtype=float)
    zero, one = _num(0.0, mode), _num(1.0, mode)
    R = [None] * N              # (cos, sin) of body i
    o = [None] * N              # body-frame origin (world)
    e = [None] * N              # prismatic sliding direction (world)
    w = [None] * N              # angular velocity of body i
    c = [None] * N              # centre of mass (world)
    anc = [[] for _ in range(N)]
    for i in range(N):
        p = model.parents[i]
        x, y, th = model.joints[i].placement
        if p < 0:
            Rp, op, wp = (one, zero), np.array([zero, zero], dtype=dt), zero
        else:
            Rp, op, wp = R[p], o[p], w[p]
            anc[i] = anc[p] + [p]
        Rj = _compose(Rp, _cs(th, mode))
        oj = op + _rot(Rp, np.array([_num(x, mode), _num(y, mode)], dtype=dt))
        kind = kinds[i]
        if kind == "revolute":
            R[i], o[i], w[i] = _compose(Rj, _cs(q[col[i]], mode)), oj, wp + _num(qd[col[i]], mode)
        elif kind == "prismatic":
            e[i] = np.array([Rj[0], Rj[1]], dtype=dt)
            R[i], o[i], w[i] = Rj, oj + e[i] * _num(q[col[i]], mode), wp
        else:
            R[i], o[i], w[i] = Rj, oj, wp
        b = model.bodies[i]
        c[i] = o[i] + _rot(R[i], np.array([_num(b.com[0], mode), _num(b.com[1], mode)], dtype=dt))
    # Jacobians of body origins and centres of mass; their velocities; bias accelerations
    qdx = np.array([_num(v, mode) for v in qd], dtype=dt)
    Jc = np.zeros((N, 2, n), dtype=dt)
    Jo = np.zeros((N, 2, n), dtype=dt)
    Jw = np.zeros((N, n), dtype=dt)
    Jt = np.zeros((N, 3, n), dtype=dt)            # twist Jacobian at the world origin [vx, vy, w]
    if mode == "exact":
        Jc[...] = zero
        Jo[...] = zero
        Jw[...] = zero
        Jt[...] = zero
    for i in range(N):
        for k in anc[i] + [i]:
            j = col[k]
            if j is None:
                continue
            if kinds[k] == "revolute":
                Jc[i, :, j] = _perp(c[i] - o[k])
                Jo[i, :, j] = _perp(o[i] - o[k])
                Jw[i, j] = one
                Jt[i, :2, j] = _perp(-o[k])
                Jt[i, 2, j] = one
            else:
                Jc[i, :, j] = e[k]
                Jo[i, :, j] = e[k]
                Jt[i, :2, j] = e[k]
    vc = np.array([Jc[i] @ qdx for i in range(N)], dtype=dt)
    vo = np.array([Jo[i] @ qdx for i in range(N)], dtype=dt)
    gvec = np.array([_num(model.gravity[0], mode), _num(model.gravity[1], mode)], dtype=dt)
    H = np.zeros((n, n), dtype=dt)
    if mode == "exact":
        H[...] = zero
    rhs = np.array([_num(t, mode) for t in np.asarray(tau, dtype=float)], dtype=dt)
    fe = None if f_ext is None else np.asarray(f_ext, dtype=float).reshape(N, 3)
    for i in range(N):
        b = model.bodies[i]
        m, Ji = _num(b.mass, mode), _num(b.inertia, mode)
        H += m * (Jc[i].T @ Jc[i]) + Ji * np.outer(Jw[i], Jw[i])
        bias = np.array([zero, zero], dtype=dt)
        for k in anc[i] + [i]:
            j = col[k]
            if j is None:
                continue
            if kinds[k] == "revolute":
                bias = bias + qdx[j] * _perp(vc[i] - vo[k])
            else:
                bias = bias + qdx[j] * w[k] * _perp(e[k])
        rhs = rhs + m * (Jc[i].T @ (gvec - bias))
        if fe is not None:
            rhs = rhs + Jt[i].T @ np.array([_num(v, mode) for v in fe[i]], dtype=dt)
    return H, rhs


def reference_qdd(model: Model, q, qd, tau, f_ext=None, mode: str = "longdouble"):
    """Joint accelerations solved in longdouble or exactly (returned as float64)."""
    H, rhs = reference_system(model, q, qd, tau, f_ext, mode)
    x = _gauss_solve(H, rhs)
    return np.array([float(v) for v in x])


def cond_spd(H) -> float:
    """2-norm condition number of an SPD matrix given in longdouble (or exact).

    ``λ_max`` from float64 ``eigvalsh``; ``λ_min`` by inverse iteration with the
    longdouble elimination, so values beyond 1e16 are still meaningful.
    """
    Hl = np.array(H, dtype=np.longdouble) if H.dtype == object else H
    Hf = np.array(Hl, dtype=float)
    lmax = float(np.linalg.eigvalsh(Hf)[-1])
    LU = _lu(Hl)
    x = np.ones(len(Hf), dtype=np.longdouble) / np.sqrt(np.longdouble(len(Hf)))
    lam = np.longdouble(0)
    for _ in range(100):
        y = _lu_solve(LU, x)
        nrm = np.sqrt(y @ y)
        new = 1 / nrm
        x = y / nrm
        if abs(new - lam) <= 1e-10 * abs(new):
            lam = new
            break
        lam = new
    return lmax / float(lam)


def rel_err(x, ref) -> float:
    return float(np.max(np.abs(np.asarray(x) - ref)) / np.max(np.abs(ref)))


def graded_chain(n: int, ratio: float, *, reverse: bool = False, joint: str = "revolute") -> Model:
    """A uniform-length chain whose link masses fall geometrically from 1 (base) to ``ratio`` (tip).

    ``reverse=True``: from ``ratio`` (base) to 1 (tip).  Inertias ``m L²/12``, unit links.
    """
    k = np.arange(n) / max(n - 1, 1)
    masses = ratio ** (1 - k if reverse else k)
    bodies = [Body(float(m), (0.5, 0.0), float(m) / 12) for m in masses]
    joints = [Joint(joint, (0.0 if i == 0 else 1.0, 0.0, 0.0)) for i in range(n)]
    return Model(bodies, joints, list(range(-1, n - 1)))


def slender_chain(n: int, rho: float) -> Model:
    """Chain of unit links, unit masses at mid-link, radius of gyration ``rho`` (0: point masses)."""
    bodies = [Body(1.0, (0.5, 0.0), rho * rho) for _ in range(n)]
    joints = [Joint("revolute", (0.0 if i == 0 else 1.0, 0.0, 0.0)) for i in range(n)]
    return Model(bodies, joints, list(range(-1, n - 1)))


def state(n: int, seed: int = 0):
    rng = np.random.default_rng(seed)
    return rng.uniform(-1, 1, n), rng.uniform(-1, 1, n), rng.uniform(-1, 1, n)


# ---------------------------------------------------------------------------- slider-crank reference
def slider_crank_reference(model: Model, q, qd, tau, r: float, l: float, mode: str = "longdouble"):
    """Closed-loop slider-crank accelerations from the reference tree equations (independent of loops.py).

    The closure ``r cos ψ + l cos β = 0``, ``ψ + θ + φ = π/2`` (``β = ψ + θ``) has
    the polynomial null vector ``n = (l sin β, -(r sin ψ + l sin β), r sin ψ)``,
    valid up to the singular fold (where it vanishes).  With ``q̇ = n s``,
    ``q̈ = n s̈ + ṅ s`` and ``(nᵀ H n) s̈ = nᵀ (τ - C - H ṅ s)``.
    """
    H, rhs = reference_system(model, q, qd, tau, mode=mode)
    dt = H.dtype
    num = (lambda v: _num(v, mode))
    r_, l_ = num(r), num(l)
    cpsi, spsi = _cs(q[0], mode)
    cb, sb = _compose((cpsi, spsi), _cs(q[1], mode))
    nvec = np.array([l_ * sb, -(r_ * spsi + l_ * sb), r_ * spsi], dtype=dt)
    qdx = np.array([num(v) for v in qd], dtype=dt)
    s = (nvec @ qdx) / (nvec @ nvec)
    psid, betad = qdx[0], qdx[0] + qdx[1]
    ndot = np.array([l_ * cb * betad, -(r_ * cpsi * psid + l_ * cb * betad), r_ * cpsi * psid], dtype=dt)
    sdd = (nvec @ (rhs - H @ (ndot * s))) / (nvec @ (H @ nvec))
    x = nvec * sdd + ndot * s
    return np.array([float(v) for v in x])


def folded_state(delta: float, path: str = "rod"):
    """Slider-crank near its folded singularity: ``path="rod"``: ψ = 0, l = r(1 + δ); ``"psi"``: l = r, ψ = δ."""
    from planargeo.scenes.slider_crank import slider_crank_model, slider_crank_state

    r = 2.29
    psi, l = (0.0, r * (1 + delta)) if path == "rod" else (delta, r)
    model = slider_crank_model(l=l)
    q, qd = slider_crank_state(psi, 20.0, r, l)
    return model, q, qd, r, l


# =========================================================================== tests
def test_reference_matches_hand_pendulum():
    # single uniform link: J_o = m L²/3, q̈ = (τ - m g L/2 cos q) / J_o
    m = chain_model(1)
    q, tau = 0.3, 0.7
    expect = (tau - 9.81 * 0.5 * np.cos(q)) / (1 / 3)
    for mode in ("longdouble", "exact"):
        assert abs(reference_qdd(m, [q], [2.0], [tau], mode=mode)[0] - expect) < 1e-15


def test_reference_matches_hand_double_prismatic():
    # two sliders along x: H = [[m1+m2, m2], [m2, m2]], no velocity terms, no gravity along x
    m = graded_chain(2, 0.25, joint="prismatic")
    tau = np.array([1.0, 0.5])
    H = np.array([[1.25, 0.25], [0.25, 0.25]])
    assert np.allclose(reference_qdd(m, [0.1, 0.2], [1.0, -2.0], tau, mode="exact"), np.linalg.solve(H, tau),
                       rtol=1e-15, atol=0)


def test_reference_longdouble_agrees_with_exact_and_external_loads():
    m = graded_chain(6, 1e-3)
    q, qd, tau = state(6, 3)
    f = np.random.default_rng(4).uniform(-1, 1, (6, 3))
    a = reference_qdd(m, q, qd, tau, f, mode="longdouble")
    b = reference_qdd(m, q, qd, tau, f, mode="exact")
    assert rel_err(a, b) < 1e-17
    # and the package's ABA agrees with it to float64 accuracy (the reference is the right system)
    assert rel_err(forward_dynamics(m, q, qd, tau, f), b) < 1e-13


def test_long_chain_every_method_within_eps_cond():
    # N = 200 uniform chain, state(200): measured cond(H) = 6.6e8; errors aba 3e-12, projective 3.4e-11,
    # mobility_split 9e-10, crba 6.6e-9 (ε·cond = 1.5e-7); the reference resolves ~2e-12 (reverse-order solve)
    N = 200
    m = chain_model(N)
    q, qd, tau = state(N)
    H, rhs = reference_system(m, q, qd, tau)
    ref = np.array([float(v) for v in _gauss_solve(H, rhs)])
    cond = cond_spd(H)
    assert 1e8 < cond < 1e10
    for name in ("aba", "projective", "mobility_split", "crba"):      # stacked: 2 s at N = 200, checked at N = 50
        err = rel_err(METHODS[name](m, q, qd, tau), ref)
        assert err <= 100 * EPS * cond, (name, err, cond)
    # the recursive methods stay well below the bound; the dense solve is the least accurate
    assert rel_err(forward_dynamics(m, q, qd, tau), ref) < 2e-11
    assert rel_err(forward_dynamics_projective(m, q, qd, tau), ref) < 3e-10
    assert rel_err(forward_dynamics_crba(m, q, qd, tau), ref) > rel_err(forward_dynamics(m, q, qd, tau), ref)


def test_chain_50_stacked_within_eps_cond():
    m = chain_model(50)
    q, qd, tau = state(50)
    H, rhs = reference_system(m, q, qd, tau)
    ref = np.array([float(v) for v in _gauss_solve(H, rhs)])
    assert rel_err(forward_dynamics_stacked(m, q, qd, tau), ref) <= 100 * EPS * cond_spd(H)


def _graded(k, reverse, joint="revolute", seed=1):
    ratio = 10.0 ** -k
    q, qd, tau = state(8, seed)
    grade = np.geomspace(1, ratio, 8)
    return graded_chain(8, ratio, reverse=reverse, joint=joint), q, qd, tau * (grade[::-1] if reverse else grade)


@pytest.mark.parametrize("name", list(METHODS))
def test_light_tip_1e10_every_method_stays_accurate(name):
    # tip links 1e-10 of the base (geometric grading, N = 8, torques scaled like the masses): cond(H) = 1.5e10
    # but every method, the dense solve included, measured <= 3e-14: the light links come last in elimination
    m, q, qd, tau = _graded(10, False)
    ref = reference_qdd(m, q, qd, tau, mode="exact")
    assert rel_err(METHODS[name](m, q, qd, tau), ref) < 1e-12


@pytest.mark.parametrize("name, bound", [("aba", 1e-11), ("projective", 4e-9), ("mobility_split", 4e-9),
                                         ("stacked", 4e-8)])
def test_light_base_1e10_recursive_methods_bounded(name, bound):
    # base links 1e-10 of the tip: measured aba 4.7e-13, projective 1.9e-10, mobility_split 1.8e-10,
    # stacked 1.7e-9 (bounds: 20x margin)
    m, q, qd, tau = _graded(10, True)
    ref = reference_qdd(m, q, qd, tau, mode="exact")
    assert rel_err(METHODS[name](m, q, qd, tau), ref) < bound


def test_light_base_1e10_dense_solve_bounded_by_eps_cond_and_worst():
    # measured: cond(H) = 2.2e10, crba error 6.8e-8 (ε·cond = 4.8e-6), 100x ABA's
    m, q, qd, tau = _graded(10, True)
    H, _ = reference_system(m, q, qd, tau)
    cond = cond_spd(H)
    assert 1e10 < cond < 1e11
    ref = reference_qdd(m, q, qd, tau, mode="exact")
    err = rel_err(forward_dynamics_crba(m, q, qd, tau), ref)
    assert 1e-9 < err <= EPS * cond, (err, cond)
    assert err > 10 * rel_err(forward_dynamics(m, q, qd, tau), ref)
    # the long-double reference is not enough here: it is off by ~1e-10
    assert rel_err(reference_qdd(m, q, qd, tau), ref) > 1e-12


def test_light_base_slider_dense_solve_loses_recursive_exact():
    # parallel sliders, base 1e-8 of the tip: crba 1.2e-8 (cond 1.7e9), recursive methods ~1e-15
    m, q, qd, tau = _graded(8, True, "prismatic", seed=5)
    ref = reference_qdd(m, q, qd, tau, mode="exact")
    for name in RECURSIVE:
        assert rel_err(METHODS[name](m, q, qd, tau), ref) < 1e-14, name
    assert rel_err(forward_dynamics_crba(m, q, qd, tau), ref) > 1e-10


def test_light_base_slider_1e12_every_method_refuses():
    m, q, qd, tau = _graded(12, True, "prismatic", seed=5)
    for name, f in METHODS.items():
        with pytest.raises(SingularConfigurationError) as e:
            f(m, q, qd, tau)
        assert e.value.cond > 1e12, name


def test_folded_slider_crank_raises_beyond_threshold():
    # rod path: ψ = 0, l = r(1 + δ): cond(BᵀGΛ⁻¹GᵀB) ≈ 5.4/δ; δ = 1e-11 is past the 1e10 threshold
    model, q, qd, r, l = folded_state(1e-11, "rod")
    with pytest.raises(SingularConfigurationError) as e:
        loop_solve(model, q, qd, np.zeros(3))
    assert SINGULAR_COND < e.value.cond < 1e12
    # ... while the Lagrange solver still gets the exact answer to ~1e-16 there
    ref = slider_crank_reference(model, q, qd, np.zeros(3), r, l, mode="exact")
    assert rel_err(constrained_dynamics_lagrange(model, q, qd, np.zeros(3))["qdd"], ref) < 1e-14


def test_near_folded_slider_crank_loop_solver_agrees_with_lagrange():
    # δ = 1e-10, just before the threshold: cond 5.4e9, loop solver vs Lagrange (and vs the exact reference)
    # measured 1.9e-8 = 16 ε·cond
    model, q, qd, r, l = folded_state(1e-10, "rod")
    tau = np.zeros(3)
    sol = loop_solve(model, q, qd, tau)
    assert 1e9 < sol.cond < SINGULAR_COND
    lag = constrained_dynamics_lagrange(model, q, qd, tau)["qdd"]
    ref = slider_crank_reference(model, q, qd, tau, r, l, mode="exact")
    assert rel_err(sol.qdd, lag) <= 100 * EPS * sol.cond
    assert rel_err(sol.qdd, ref) <= 100 * EPS * sol.cond
    assert rel_err(lag, ref) < 1e-14


def test_psi_path_is_ill_posed_for_float_states():
    # l = r, ψ = 1e-4: both solvers deviate ~1e-6 from the exact answer, but so does the exact answer itself
    # when θ moves by one ulp: the float64 state cannot determine q̈ better
    model, q, qd, r, l = folded_state(1e-4, "psi")
    tau = np.zeros(3)
    ref = slider_crank_reference(model, q, qd, tau, r, l, mode="exact")
    q2 = q.copy()
    q2[1] = np.nextafter(q2[1], np.inf)
    sens = rel_err(slider_crank_reference(model, q2, qd, tau, r, l, mode="exact"), ref)
    sol = loop_solve(model, q, qd, tau)
    lag = constrained_dynamics_lagrange(model, q, qd, tau)["qdd"]
    assert rel_err(sol.qdd, ref) < 2 * sens and rel_err(lag, ref) < 2 * sens
    assert rel_err(sol.qdd, lag) < 1e-3 * sens
