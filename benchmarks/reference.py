"""The breakdown study's independent reference (private; not part of the public API).

``reference_qdd``: the joint-space
equations of motion ``H q̈ = τ - C`` written from scratch with world-frame
Jacobians, evaluated and solved in ``np.longdouble`` (x87 extended precision,
ε ≈ 1.1e-19) or, for small models, in exact rational arithmetic
(``fractions.Fraction``).  Nothing of :mod:`planargeo` is used for it except
reading the model's numbers.  One copy, imported by ``tests/test_breakdown.py``,
``benchmarks/breakdown.py`` and :mod:`planargeo.bench` (the accuracy columns of
the benchmark tables); it lives in the package so that ``planargeo bench`` works
from an installed package without the test files.  Also the exact-arithmetic
reference of the geometry layer (``cross_exact``, ``matvec_exact``,
``solve_exact``) and the inputs of the study's sweeps.

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

from decimal import Decimal, localcontext
from fractions import Fraction

import numpy as np

from planargeo.mechanics.model import Body, Joint, Model
from planargeo.geometry.projective import from_xy, line_through_point_direction, to_xy
from planargeo.screws.twists import inertia_matrix

EPS = float(np.finfo(float).eps)
EPS_LD = float(np.finfo(np.longdouble).eps)


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


def reference_with_info(model: Model, q, qd, tau, f_ext=None, mode: str = "longdouble"):
    """``(q̈, spread, cond)``: the reference accelerations with an estimate of their own error and ``cond(H)``.

    ``q̈`` as :func:`reference_qdd` (float64); ``spread``: in longdouble the
    relative change when the elimination order is reversed (validated against
    the exact reference at N = 20: 1.0e-15 estimated, 1.3e-15 actual), exact:
    ``0.0``; ``cond``: :func:`cond_spd` of ``H``.

    Examples
    --------
    A single free pendulum (unit link, centre of mass at 1/2, ``I = 1/12``) at
    rest hanging sideways: ``q̈ = -m g (L/2) / (I + m L²/4) = -3 g / (2 L)``.

    >>> from planargeo.mechanics.model import chain_model
    >>> qdd, spread, cond = reference_with_info(chain_model(1), [0.0], [0.0], [0.0], mode="exact")
    >>> round(float(qdd[0]), 6), spread, cond
    (-14.715, 0.0, 1.0)
    """
    H, rhs = reference_system(model, q, qd, tau, f_ext, mode)
    qdd = np.array([float(v) for v in _gauss_solve(H, rhs)])
    spread = 0.0
    if mode == "longdouble":
        xr = _gauss_solve(H[::-1, ::-1].copy(), rhs[::-1].copy())[::-1]
        spread = rel_err(np.array([float(v) for v in xr]), qdd)
    return qdd, spread, cond_spd(H)


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


def alternating_chain(n: int, k: float, *, joint: str = "revolute") -> Model:
    """A uniform-length chain whose link masses alternate between ``10^(k/2)`` and ``10^(-k/2)``.

    Tiny and huge masses mixed along a long chain (mass ratio ``10^k``), inertias ``m L²/12``,
    unit links, heavy first.
    """
    masses = [10.0 ** (k / 2) if i % 2 == 0 else 10.0 ** (-k / 2) for i in range(n)]
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


# ---------------------------------------------------------------------------- geometry reference
# The geometry layer (planargeo.geometry.projective, conics, inertia) against exact rational arithmetic.
# Every input is a float64 array; the reference takes it as the exact number it is (``Fraction``)
# and forms the cross product (join / meet), the matrix-vector product (polar, axis of percussion)
# or the solve (pole, percussion pole) without rounding.  Errors are normwise and relative:
# ``|x - x_ref| / |x_ref|`` for a homogeneous result (the package returns the unnormalised
# ``p × q``, ``C p`` or ``C⁻¹ l``, the scale of the reference), and for its Euclidean reading
# (a point's ``(x, y)``; a line's distance from a given point).

def fr(v) -> list:
    """A float64 vector as exact Fractions."""
    return [Fraction(float(x)) for x in np.asarray(v, dtype=float).ravel()]


def cross_exact(a, b) -> list:
    """``a × b`` in exact arithmetic (join of two points, meet of two lines)."""
    a, b = fr(a), fr(b)
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def matvec_exact(M, v) -> list:
    """``M v`` in exact arithmetic (polar of a point, axis of percussion ``I a``)."""
    v = fr(v)
    return [sum(x * y for x, y in zip(fr(row), v)) for row in np.asarray(M, dtype=float)]


def solve_exact(M, b) -> list:
    """``M⁻¹ b`` in exact arithmetic (pole of a line, percussion pole ``I⁻¹ f``): Gauss-Jordan."""
    A = [fr(row) + [x] for row, x in zip(np.asarray(M, dtype=float), fr(b))]
    n = len(A)
    for k in range(n):
        piv = next(i for i in range(k, n) if A[i][k] != 0)
        A[k], A[piv] = A[piv], A[k]
        for i in range(n):
            if i != k and A[i][k] != 0:
                f = A[i][k] / A[k][k]
                A[i] = [x - f * y for x, y in zip(A[i], A[k])]
    return [A[i][n] / A[i][i] for i in range(n)]


def norm_exact(v) -> float:
    """Euclidean norm of exact (or float) numbers, rounded once at the end."""
    return float(np.sqrt(float(sum(Fraction(x) ** 2 for x in v))))


def hom_err(x, ref) -> float:
    """Normwise relative error of a homogeneous result against the exact one (same scale)."""
    return norm_exact([Fraction(float(a)) - b for a, b in zip(np.asarray(x).ravel(), ref)]) / norm_exact(ref)


def cross_cond(a, b, ref) -> float:
    """Condition number ``|a| |b| / |a × b|`` of a cross product: 1 / sine of the angle of the 3-vectors.

    Each component of ``a × b`` is a difference of two rounded products, so the
    rounding error is at most about ``ε |a| |b|`` and the relative error about ``ε``
    times this number.
    """
    return norm_exact(fr(a)) * norm_exact(fr(b)) / norm_exact(ref)


def matvec_cond(M, v, ref) -> float:
    """Condition number ``| |M| |v| | / |M v|`` of a matrix-vector product (componentwise magnitudes)."""
    return norm_exact(matvec_exact(np.abs(M), np.abs(np.asarray(v, dtype=float)))) / norm_exact(ref)


def euclid_err(p, ref) -> float:
    """Relative error of ``to_xy(p)`` against the exact ``(-p1/w, p0/w)`` (``inf``: the point was lost to infinity)."""
    x = to_xy(p)
    if not np.all(np.isfinite(x)):
        return float("inf")
    X = [-ref[1] / ref[2], ref[0] / ref[2]]
    return norm_exact([Fraction(float(a)) - b for a, b in zip(x, X)]) / norm_exact(X)


def euclid_cond(kappa: float, ref, weight) -> float:
    """Condition number of a Euclidean reading: ``κ |x| / |weight|``.

    Reading Euclidean positions off a homogeneous result divides by its weight
    (``w`` of a point; the force ``|(fx, fy)|`` of a line), which turns the absolute
    error ``ε κ |x|`` into a relative error of up to ``ε κ |x| / |weight|``: large for
    elements near infinity however accurate the homogeneous result is.
    """
    weight = abs(float(weight))
    return kappa * norm_exact(ref) / weight if weight else float("inf")


def distance_cond(kappa: float, f, c) -> float:
    """Condition number of the distance ``r = c·f / |(fx, fy)|`` of the point ``c`` from a line ``f``.

    ``κ (|c| |f| / |c·f| + |f| / |(fx, fy)|)`` (``c`` homogeneous, weight 1): the dot
    product loses accuracy when the line passes close to ``c`` (r → 0), the division
    when the line is near the line at infinity (r → ∞).
    """
    ch = fr(from_xy(c))
    dot = abs(float(sum(x * y for x, y in zip(ch, f))))
    force = norm_exact(f[:2])
    nf = norm_exact(f)
    if dot == 0 or force == 0:
        return float("inf")
    return kappa * (norm_exact(ch) * nf / dot + nf / force)


def _dec(x) -> Decimal:
    x = Fraction(x)
    return Decimal(x.numerator) / Decimal(x.denominator)


def distance_exact(f, c) -> Decimal:
    """Signed distance (thesis 5.23) of the Euclidean point ``c`` from the exact line ``f``, to 40 digits."""
    num = sum(x * y for x, y in zip(fr(from_xy(c)), f))
    with localcontext() as ctx:
        ctx.prec = 40
        return _dec(num) / (_dec(f[0]) ** 2 + _dec(f[1]) ** 2).sqrt()


def decimal_err(x: float, ref: Decimal) -> float:
    """Relative error of a float against a 40-digit reference."""
    with localcontext() as ctx:
        ctx.prec = 40
        return float(abs(Decimal(float(x)) - ref) / abs(ref))


def pencil_pair(theta: float, rng):
    """Two lines through one random point of ``[-1, 1]²`` at random angles ``a`` and ``a + θ`` (near-coincident)."""
    P = from_xy(rng.uniform(-1, 1, 2))
    a = rng.uniform(0, np.pi)
    return (line_through_point_direction(P, (np.cos(a), np.sin(a))),
            line_through_point_direction(P, (np.cos(a + theta), np.sin(a + theta))))


def strip_pair(theta: float, rng, h: float = 1.0):
    """Two lines ``h`` apart (the first through a random point of ``[-3, 3]²``) at angles ``a``, ``a + θ``.

    Near-parallel but not near-coincident: they meet about ``h / θ`` away.  ``θ = 0``
    gives exactly parallel lines (the same direction floats).
    """
    P = rng.uniform(-3, 3, 2)
    a = rng.uniform(0, np.pi)
    n = np.array([-np.sin(a), np.cos(a)])
    return (line_through_point_direction(from_xy(P), (np.cos(a), np.sin(a))),
            line_through_point_direction(from_xy(P + h * n), (np.cos(a + theta), np.sin(a + theta))))


def near_points(delta: float, R: float, rng):
    """Two homogeneous points ``δ`` apart, the first at a random distance in ``[R/2, R]`` from the origin."""
    u, v = rng.normal(size=(2, 2))
    P = R * rng.uniform(0.5, 1.0) * u / np.linalg.norm(u)
    return from_xy(P), from_xy(P + delta * v / np.linalg.norm(v))


#: body of the percussion sweeps: m = 1.3, centre of mass (0.7, -0.4), ρ = 0.5 (no power-of-two products)
GEO_MASS, GEO_COM, GEO_RHO = 1.3, np.array([0.7, -0.4]), 0.5


def geo_inertia(rho: float = GEO_RHO):
    return inertia_matrix(GEO_MASS, GEO_COM, GEO_MASS * rho * rho)


def pole_near_com(d: float, rng):
    """A homogeneous acceleration pole at distance ``d`` from the centre of mass (random direction)."""
    u = rng.normal(size=2)
    return from_xy(GEO_COM + d * u / np.linalg.norm(u))


def pole_far(R: float, rng):
    """A homogeneous acceleration pole ``R`` away from the centre of mass, scaled by ``1/R`` (weight ``1/R``)."""
    u = rng.normal(size=2)
    return from_xy(GEO_COM + R * u / np.linalg.norm(u)) / R


def line_near_infinity(e: float, rng):
    """A line ``[e fx, e fy, 1]``: as ``e → 0`` the line at infinity (its percussion pole → the centre of mass)."""
    u = rng.normal(size=3)
    return np.array([e * u[0], e * u[1], 1.0])


def line_near_com(e: float, rng):
    """A line passing ``e`` from the centre of mass (its percussion pole goes to infinity as ``e → 0``)."""
    u = rng.normal(size=2)
    u /= np.linalg.norm(u)
    return line_through_point_direction(from_xy(GEO_COM + e * np.array([-u[1], u[0]])), u)
