"""Subspace decompositions of wrenches, twists and inertias (thesis chapter 6).

A joint's motion space ``s`` and reaction space ``R`` (``sᵀR = 0``) are completed with an inertia
``A`` into the percussion space ``T = A s (sᵀAs)⁻¹`` (:func:`T_of`) and the reactive-acceleration
space ``U = A⁻¹R (RᵀA⁻¹R)⁻¹`` (:func:`U_of`): ``sᵀT = 1``, ``RᵀU = 1``, ``TᵀU = 0`` (6.22, 6.23,
6.46), ``f = T Q + R μ`` (6.38), ``a = s ψ + U γ`` (6.44).  Arguments: the inertia, then ``s``
before ``R``, then the screw; all broadcast, a ``(3,)`` space is one column, nothing is inverted
explicitly.  The public functions validate and call unchecked kernels (``_T``, ``_U``, ...), which
the chain algorithms call per body, so the package's one singularity rule lives here:
``‖A‖_F ‖s‖_F² / σ_min(sᵀAs)`` (:func:`joint_cond`, at the joint's point: :func:`joint_scale`) past
:data:`planargeo.errors.COND_LIMIT` raises :class:`~planargeo.errors.SingularConfigurationError`
(a singular ``A`` where ``A⁻¹`` is needed, :class:`~planargeo.errors.SingularInertiaError`).
"""
from __future__ import annotations

import math

import numpy as np

from planargeo._validate import (as_array, as_scalar, as_vec3, check_overflow,
                                 check_positive_semidefinite, overflow_checked)
from planargeo.errors import (COND_LIMIT, InputError, ShapeError,
                              SingularConfigurationError, SingularInertiaError)
from planargeo.geometry._docs import entries

__all__ = [
    "T_of", "U_of",
    "active_force", "reaction_force", "active_acceleration", "reactive_acceleration",
    "wrench_projectors", "twist_projectors",
    "joint_space_inertia", "reaction_space_inverse_inertia",
    "inertia_decomposition", "inverse_inertia_decomposition",
    "effective_mobility", "effective_base_inertia",
    "Decomposition", "joint_cond", "joint_scale", "singular_joint_error",
]

#: ``COND_LIMIT²``: the joint rule without a square root, ``σ_min² COND_LIMIT² > ‖A‖_F² ‖s‖⁴``
#: (for code that tests the squared scale; it accepts exactly the states ``cond <= COND_LIMIT``
#: accepts, up to rounding of the last bit at the threshold itself)
COND_LIMIT2 = COND_LIMIT * COND_LIMIT


#: The parameters most functions here take, described once (``{I s R}`` in a docstring: those entries)
_parameters = entries({
    "A": "A : array_like, shape (..., 3, 3)\n    Symmetric positive semi-definite inertia at the origin.",
    "I": "I : array_like, shape (..., 3, 3)\n    Symmetric inertia (rigid or articulated) at the origin.",
    "s": "s : array_like, shape (..., 3, k)\n    Joint motion space (k unit twists as columns).",
    "R": "R : array_like, shape (..., 3, 3-k)\n    Joint reaction space (wrenches reciprocal to ``s``).",
    "f": "f : array_like, shape (..., 3)\n    Wrench.",
    "a": "a : array_like, shape (..., 3)\n    Acceleration twist.",
    "what": "what : str, optional\n    Name of the matrix in the singularity error's message.",
    "U": "U : array_like, shape (..., 3, 3-k)\n"
         "    The joint's reactive-acceleration space (:func:`U_of`).",
    "T": "T : array_like, shape (..., 3, k)\n    The joint's percussion space (:func:`T_of`).",
    # the four projections' results (6.61-6.62), the components of f = T Q + R μ and a = s ψ + U γ
    "Q": "Returns\n-------\nQ : numpy.ndarray, shape (..., k)\n"
         "    The joint force (a torque at a revolute joint): ``f = T Q + R μ`` (6.38).",
    "mu": "Returns\n-------\nmu : numpy.ndarray, shape (..., 3-k)\n"
          "    Reaction components: ``f = T Q + R μ`` (6.38).",
    "psi": "Returns\n-------\npsi : numpy.ndarray, shape (..., k)\n"
           "    Joint accelerations: ``a = s ψ + U γ`` (6.44).",
    "gamma": "Returns\n-------\ngamma : numpy.ndarray, shape (..., 3-k)\n"
             "    Components of ``a`` along ``U``: ``a = s ψ + U γ`` (6.44).",
})


def joint_cond(smin: float, A_norm2: float, s_norm2: float) -> float:
    """A joint's scale-free condition number ``‖A_P‖_F ‖s_P‖_F² / σ_min(sᵀAs)`` (the rule of ``COND_LIMIT``).

    ``A_P``, ``s_P``: at the joint's own point (:func:`joint_scale`); singular when ``cond > COND_LIMIT``.

    Parameters
    ----------
    smin : float
        ``σ_min(sᵀAs)`` (``|sᵀAs|`` for one dof; its sign is ignored).
    A_norm2, s_norm2 : float
        ``‖A_P‖_F²`` and ``‖s_P‖_F²`` (``1`` for a revolute or prismatic joint).

    Returns
    -------
    float
        ``inf`` when ``σ_min = 0``.

    Raises
    ------
    InputError
        If a squared norm is negative.

    Examples
    --------
    >>> round(joint_cond(1e-12, 2.0, 1.0) / 1e12, 6)      # a unit mass 1e-6 from its pivot
    1.414214
    """
    smin, A_norm2, s_norm2 = (as_scalar(x, name) for x, name in
                              ((smin, "smin"), (A_norm2, "A_norm2"), (s_norm2, "s_norm2")))
    if A_norm2 < 0 or s_norm2 < 0:
        raise InputError(f"A_norm2 and s_norm2 are squared norms (>= 0), got {A_norm2!r}, {s_norm2!r}")
    with np.errstate(over="ignore"):
        return math.sqrt(A_norm2) * s_norm2 / abs(smin) if smin != 0 else math.inf


@_parameters
def joint_scale(A, s, point):
    """``‖A_P‖_F ‖s_P‖_F²``: the scale of the rule of :func:`joint_cond` at the joint's point ``P``.

    ``s_P = X s`` with ``X = [[1, 0, -y], [0, 1, x], [0, 0, 1]]`` (thesis 4.8), ``A_P = X⁻ᵀ A X⁻¹``
    (1.68, 4.58); where squares would leave the float range the norm is taken scaled (scale invariant).

    {parameters A s}
    point : array_like, shape (..., 2)
        The joint's point ``P`` (m).

    Returns
    -------
    float or ndarray (...)

    Raises
    ------
    ShapeError
        If ``s`` is not ``(..., 3, k)`` with ``k <= 3``.

    Examples
    --------
    A unit point mass at ``(1000.5, 0)`` on a pivot at ``(1000, 0)``: ``‖A_P‖_F² = 2 + 2 · 0.5² + 0.25²``.

    >>> from planargeo.screws.twists import inertia_matrix
    >>> joint_scale(inertia_matrix(1.0, [1000.5, 0.0], 0.0), [0.0, -1000.0, 1.0], [1000.0, 0.0])
    1.6007810593582121
    """
    A, P, s = as_array(A, "A", (3, 3)), as_array(point, "point", (2,)), _space(s, "s")
    if A.ndim == 2 and s.ndim == 2 and P.ndim == 1:      # one joint: the same arithmetic on Python floats
        out = _joint_scale_one(A.tolist(), s.T.tolist(), *P.tolist())
        if out is not None:
            return out
    x, y = P[..., 0], P[..., 1]
    a00, a01, a02 = A[..., 0, 0], A[..., 0, 1], A[..., 0, 2]
    a11, a12, a22 = A[..., 1, 1], A[..., 1, 2], A[..., 2, 2]
    with np.errstate(over="ignore", under="ignore", invalid="ignore"):   # out of range: check_overflow below
        p02, p12, p22, F2 = _moved_inertia(a00, a01, a02, a11, a12, a22, x, y)
    if not np.all((F2 < 1e300) & (F2 > 1e-300)):
        # squares overflowed or underflowed (masses like 1e160 or 1e-170): the norm is homogeneous,
        # so take it of the entries divided by their largest magnitude, then scale back
        e = [np.abs(v) for v in np.broadcast_arrays(a00, a11, p22, a01, p02, p12)]
        mx = np.maximum.reduce(e)
        safe = np.where(mx > 0, mx, 1.0)
        with np.errstate(invalid="ignore", under="ignore"):    # inf / inf: check_overflow below names it
            r = [v / safe for v in e]
            F2 = None
            F = mx * np.sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2] + 2.0 * (r[3] * r[3] + r[4] * r[4] + r[5] * r[5]))
    x, y = x[..., None], y[..., None]
    s0, s1, s2 = s[..., 0, :], s[..., 1, :], s[..., 2, :]
    with np.errstate(over="ignore", invalid="ignore"):
        t0, t1 = s0 - y * s2, s1 + x * s2
        ss = np.sum(t0 * t0 + t1 * t1 + s2 * s2, axis=-1)
        out = check_overflow((np.sqrt(F2) if F2 is not None else F) * ss, "joint_scale", "A or s")
    return float(out) if np.ndim(out) == 0 else out


def _moved_inertia(a00, a01, a02, a11, a12, a22, x, y):
    """The moment entries ``p02, p12, p22`` of ``A_P`` and ``‖A_P‖_F²`` (:func:`joint_scale`), of floats or arrays alike."""
    p02 = a02 + y * a00 - x * a01
    p12 = a12 + y * a01 - x * a11
    p22 = a22 + y * a02 - x * a12 + y * p02 - x * p12
    return p02, p12, p22, a00 * a00 + a11 * a11 + p22 * p22 + 2.0 * (a01 * a01 + p02 * p02 + p12 * p12)


def _joint_scale_one(A, cols, x, y):
    """:func:`joint_scale` of one joint, ``A`` and the columns of ``s`` as lists; None where squares leave range."""
    (a00, a01, a02), (_, a11, a12), (_, _, a22) = A
    F2 = _moved_inertia(a00, a01, a02, a11, a12, a22, x, y)[3]
    if not 1e-300 < F2 < 1e300:
        return None
    ss = 0.0
    for s0, s1, s2 in cols:
        t0, t1 = s0 - y * s2, s1 + x * s2
        ss += t0 * t0 + t1 * t1 + s2 * s2
    out = math.sqrt(F2) * ss
    return out if out < math.inf else None


def singular_joint_error(i: int, cond: float) -> SingularConfigurationError:
    """The error every method raises for a singular joint ``i`` (message and ``.cond`` shared).

    Parameters
    ----------
    i : int
        The model's joint index, counted from 0; the message counts from 1, as the thesis and the
        pictures do (index 3 is joint 4).
    cond : float
        Its condition number.

    Returns
    -------
    SingularConfigurationError
        The error (not raised).

    Raises
    ------
    InputError
        If ``i`` is not an int.

    Examples
    --------

    >>> str(singular_joint_error(3, 2e12))
    'sᵀAs of joint 4 is singular: the inertia has (almost) nothing along s (condition number 2e+12)'
    """
    if isinstance(i, bool) or not isinstance(i, (int, np.integer)):
        raise InputError(f"i must be a joint index (an int), got {i!r}")
    cond = as_scalar(cond, "cond", finite=False)
    return SingularConfigurationError(
        f"sᵀAs of joint {i + 1} is singular: the inertia has (almost) nothing along s", cond)


# ----------------------------------------------------------------------------- helpers
def _what(what, default: str) -> str:
    """The name an error message gives the matrix (``what``, a string, or ``default``)."""
    if what is None:
        return default
    if not isinstance(what, str):
        raise InputError(f"what must be a string naming the matrix, got {what!r}")
    return what


def _space(x, name: str) -> np.ndarray:
    """Validate a subspace: (..., 3, k) float array; a (3,) vector is one column."""
    a = as_array(x, name)
    if a.ndim == 1:
        if a.shape != (3,):
            raise ShapeError(f"{name} must have shape (..., 3, k), got shape {a.shape}")
        return a[:, None]
    if a.ndim < 2 or a.shape[-2] != 3 or a.shape[-1] > 3:
        raise ShapeError(f"{name} must have shape (..., 3, k) with k <= 3, got shape {a.shape}")
    return a


def _inertia(A, name: str, eig: bool = False):
    """An inertia argument: (..., 3, 3), finite, symmetric, positive semi-definite (named ``name``);
    with ``eig``, also its ``(largest, smallest)`` |eigenvalue| (for :func:`_solve_A`)."""
    a, w = check_positive_semidefinite(as_array(A, name, (3, 3)), name, eig=True)
    w = np.abs(w)
    return (a, (w.max(axis=-1), w.min(axis=-1))) if eig else a


def _tr(x: np.ndarray) -> np.ndarray:
    return np.swapaxes(x, -1, -2)


def _abs_eig(A: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Largest and smallest |eigenvalue| of symmetric matrices (= their singular values)."""
    w = np.abs(np.linalg.eigvalsh(A))
    return w.max(axis=-1), w.min(axis=-1)


def _fro2(x: np.ndarray) -> np.ndarray:
    """Squared Frobenius norm of each matrix in a stack (an upper bound of the squared 2-norm)."""
    return np.einsum("...ij,...ij->...", x, x)


def _norm(A: np.ndarray):
    """Cheap norm ``‖A‖`` of each matrix in a stack: the Frobenius norm (a float for one matrix)."""
    if A.ndim == 2:
        return math.sqrt(float(np.vdot(A, A)))
    return np.sqrt(_fro2(A))


def _check(cond, error, message: str) -> None:
    """Raise ``error(message, cond)`` where ``cond`` exceeds :data:`planargeo.errors.COND_LIMIT` (NaN too)."""
    if isinstance(cond, float):
        if not cond <= COND_LIMIT:
            raise error(message, cond)
        return
    bad = ~(cond <= COND_LIMIT)
    if np.any(bad):
        raise error(message, float(np.max(np.where(bad, cond, 0.0))))


def _weighted_gram(X: np.ndarray, AX: np.ndarray, A_norm, scale=None):
    """``M = Xᵀ (A X)`` (symmetrised) and its condition ``scale / σ_min(M)``, default scale ``‖A‖ ‖X‖²``."""
    if X.shape == (3, 1) and AX.ndim == 2:
        M = X.T @ AX
        smin = abs(float(M[0, 0]))     # the rule of joint_cond, without squaring the scale (no overflow)
        scale = A_norm * float(np.vdot(X, X)) if scale is None else float(scale)
        return M, (scale / smin if smin > 0 else math.inf)
    M = _tr(X) @ AX
    k = M.shape[-1]
    M = 0.5 * (M + _tr(M))
    smin = np.abs(M[..., 0, 0]) if k == 1 else _abs_eig(M)[1]
    smin, scale = np.broadcast_arrays(np.asarray(smin, dtype=float),
                                      np.asarray(A_norm * _fro2(X) if scale is None else scale, dtype=float))
    cond = np.full(smin.shape, np.inf)
    np.divide(scale, smin, out=cond, where=smin > 0)
    return M, cond


def _solve_A(A: np.ndarray, B: np.ndarray, name: str, eig=None) -> np.ndarray:
    """``A⁻¹ B`` by a solve, raising SingularInertiaError (with cond ``|λ|max / |λ|min``) for a singular ``A``."""
    hi, lo = _abs_eig(A) if eig is None else eig
    cond = np.full(np.shape(lo), np.inf)
    np.divide(hi, lo, out=cond, where=lo > 0)
    _check(cond, SingularInertiaError, f"{name} must be invertible")
    shape = np.broadcast_shapes(A.shape[:-2], B.shape[:-2])
    return np.linalg.solve(np.broadcast_to(A, shape + A.shape[-2:]), np.broadcast_to(B, shape + B.shape[-2:]))


def _solve(M: np.ndarray, b: np.ndarray, what: str = "a recursion matrix") -> np.ndarray:
    """``M⁻¹ b`` for one small ``M`` checked non-singular (LAPACK may still find it singular)."""
    if M.shape == (1, 1):
        return b / M[0, 0]                  # the LU solve's numbers, without its overhead
    try:
        return np.linalg.solve(M, b)
    except np.linalg.LinAlgError:        # round-off, e.g. masses over 14 decades in 7.38
        raise SingularConfigurationError(f"{what} is singular to working precision", math.inf) from None


def _right_solve(X: np.ndarray, M: np.ndarray) -> np.ndarray:
    """``X M⁻¹`` for symmetric ``M`` (..., k, k); a single 1×1 ``M`` multiplies by ``1 / M``."""
    if M.shape == (1, 1):
        return X * (1.0 / M[0, 0])
    Xt = _tr(X)
    if M.shape[:-2] == Xt.shape[:-2]:
        return _tr(np.linalg.solve(M, Xt))
    shape = np.broadcast_shapes(M.shape[:-2], Xt.shape[:-2])
    return _tr(np.linalg.solve(np.broadcast_to(M, shape + M.shape[-2:]),
                               np.broadcast_to(Xt, shape + Xt.shape[-2:])))


def _check_complementary(s: np.ndarray, R: np.ndarray) -> None:
    k, r = s.shape[-1], R.shape[-1]
    if k + r != 3:
        raise ShapeError(f"s and R must have 3 columns together, got s with {k} and R with {r}")
    sR = _tr(s) @ R
    if sR.size:
        tol = 1e-9 * max(1.0, float(np.max(np.abs(s), initial=0.0)) * float(np.max(np.abs(R), initial=0.0)))
        worst = float(np.max(np.abs(sR)))
        if worst > tol:
            raise InputError(f"R must be reciprocal to s (sᵀR = 0, thesis 6.1), got max |sᵀR| = {worst:.3g}")


def _tmul(X: np.ndarray, v: np.ndarray) -> np.ndarray:
    """``Xᵀ v`` for stacks: X (..., 3, k), v (..., 3) -> (..., k)."""
    return (_tr(X) @ v[..., None])[..., 0]


def _components(X, v, names: str) -> np.ndarray:
    """``Xᵀ v`` of a space and a screw given by the caller, validated under their ``names`` (6.61-6.62)."""
    return _tmul(_space(X, names[0]), as_vec3(v, names[1]))


def _combine(X, x, Y, y, names: tuple) -> np.ndarray:
    """``X x + Y y``: a screw from its components ``x, y`` (validated, named ``names``) along two spaces (6.38, 6.44)."""
    x = as_array(x, names[0], (X.shape[-1],))
    y = as_array(y, names[1], (Y.shape[-1],))
    return (X @ x[..., None])[..., 0] + (Y @ y[..., None])[..., 0]


# ----------------------------------------------------------------------------- kernels (unchecked arguments)
def _gram(A: np.ndarray, s: np.ndarray, point=None):
    """``(A s, sᵀ A s, cond)`` (6.67, :func:`joint_cond`), measured at ``point`` (or the origin); never raises."""
    As = A @ s
    scale = None
    if point is not None:
        scale = _joint_scale_fast(A, s, point)
        if scale is None:
            scale = joint_scale(A, s, point)
    M, cond = _weighted_gram(s, As, _norm(A), scale)
    return As, M, cond


def _joint_scale_fast(A, s, point):
    """:func:`joint_scale` of one joint given as finite float arrays, without its checks (None: ask it)."""
    if not (type(A) is np.ndarray and type(s) is np.ndarray and type(point) is np.ndarray
            and A.shape == (3, 3) and s.ndim == 2 and s.shape[0] == 3 and s.shape[1] <= 3
            and point.shape == (2,) and A.dtype == s.dtype == point.dtype == np.float64):
        return None
    rows = A.tolist()
    if not math.isfinite(sum(rows[0]) + sum(rows[1]) + sum(rows[2])):   # (or too big to add): checked there
        return None
    return _joint_scale_one(rows, s.T.tolist(), *point.tolist())


def _checked_gram(A: np.ndarray, s: np.ndarray, what: str, point=None) -> tuple[np.ndarray, np.ndarray]:
    """``(A s, sᵀ A s)`` of :func:`_gram`, raising past the limit (``what`` names ``sᵀAs`` in the message)."""
    As, M, cond = _gram(A, s, point)
    _check(cond, SingularConfigurationError, f"{what} is singular: the inertia has (almost) nothing along s")
    return As, M


def _T(A: np.ndarray, s: np.ndarray, what: str = "sᵀAs", gram=None, point=None) -> np.ndarray:
    """``T = A s (sᵀ A s)⁻¹`` (6.30, 6.36, 6.39, 6.105), the kernel of :func:`T_of` (``gram`` if formed)."""
    if s.shape[-1] == 0:
        return np.zeros(np.broadcast_shapes(s.shape[:-2], A.shape[:-2]) + (3, 0))
    As, M = _checked_gram(A, s, what, point) if gram is None else gram
    return _right_solve(As, M)


def _effective_mobility(A: np.ndarray, s: np.ndarray, what: str = "sᵀIs", gram=None, point=None) -> np.ndarray:
    """``s Tᵀ A⁻¹ = s (sᵀ A s)⁻¹ sᵀ`` (6.93, 7.31a), the kernel of :func:`effective_mobility`."""
    if s.shape[-1] == 0:
        return np.zeros(np.broadcast_shapes(s.shape[:-2], A.shape[:-2]) + (3, 3))
    _, M = _checked_gram(A, s, what, point) if gram is None else gram
    return _right_solve(s, M) @ _tr(s)


def _reaction_gram(A, R: np.ndarray, name: str, eig=None, what=None):
    """``(A⁻¹R, RᵀA⁻¹R)``, raising where ``A`` or ``RᵀA⁻¹R`` is singular (``eig``: ``A``'s |eigenvalues|)."""
    eig = _abs_eig(A) if eig is None else eig
    AiR = _solve_A(A, R, name, eig)
    with np.errstate(divide="ignore"):
        Ainv_norm = 1.0 / eig[1]          # ‖A⁻¹‖ = 1 / σ_min(A); finite here (A checked invertible)
    M, cond = _weighted_gram(R, AiR, Ainv_norm)
    _check(cond, SingularConfigurationError,
           f"{what or f'Rᵀ{name}⁻¹R'} is singular: the inertia has (almost) nothing along R")
    return AiR, M


def _U(A, R: np.ndarray, s=None, T=None, *, name: str = "A", eig=None, what=None) -> np.ndarray:
    """``U = A⁻¹ R (Rᵀ A⁻¹ R)⁻¹`` (6.37, 6.45, 6.99), the kernel of :func:`U_of`; with ``s`` and
    ``T = T(A, s)`` the inverse-free ``U = (1 - s Tᵀ) R (RᵀR)⁻¹`` (6.75), ``A`` unused."""
    if R.shape[-1] == 0:
        return np.zeros(np.broadcast_shapes(R.shape[:-2], (T if s is not None else A).shape[:-2]) + (3, 0))
    if s is not None:
        return _right_solve((np.eye(3) - s @ _tr(T)) @ R, _tr(R) @ R)
    return _right_solve(*_reaction_gram(A, R, name, eig, what))


# ----------------------------------------------------------------------------- T and U
@overflow_checked("A or s")
@_parameters
def T_of(A, s, *, what: str | None = None) -> np.ndarray:
    """Percussion (active-force) space ``T = A s (sᵀ A s)⁻¹`` (thesis 6.30, 6.36, 6.39, 6.105).

    The weighted pseudo-inverse of ``s`` (6.26): ``sᵀT = 1`` (6.32), ``TᵀU = 0`` (6.46); for a
    revolute joint its column is the pivot's axis of percussion (5.67).

    Parameters
    ----------
    A : array_like, shape (..., 3, 3)
        Symmetric positive semi-definite inertia (singular is fine if ``sᵀAs`` is not).
    {s what}

    Returns
    -------
    ndarray, shape (..., 3, k)

    Raises
    ------
    InputError, SingularInertiaError
        ``A`` is not symmetric, or has a negative eigenvalue.
    SingularConfigurationError
        ``sᵀAs`` is singular by the rule of :data:`planargeo.errors.COND_LIMIT` (at the origin).

    Examples
    --------
    >>> from planargeo.screws.twists import inertia_matrix
    >>> T_of(inertia_matrix(2.0, [1.0, 0.0], 0.5), [0.0, 0.0, 1.0]).ravel()   # at x = d + ρ²/d (5.64, 5.67)
    array([0. , 0.8, 1. ])
    """
    return _T(_inertia(A, "A"), _space(s, "s"), _what(what, "sᵀAs"))


@overflow_checked("A or R")
@_parameters
def U_of(A, R, s=None, *, what: str | None = None) -> np.ndarray:
    """Reactive-acceleration space ``U = A⁻¹ R (Rᵀ A⁻¹ R)⁻¹`` (thesis 6.37, 6.45, 6.99; 6.33 corrected).

    ``RᵀU = 1`` (6.35), ``TᵀU = 0`` (6.46); the printed 6.33 omits the inverse (``docs/errata.md``).

    Parameters
    ----------
    A : array_like, shape (..., 3, 3)
        Symmetric positive semi-definite inertia; definite unless ``s`` is given.
    {R}
    s : array_like, shape (..., 3, 3 - r), optional
        The joint's motion space: then ``U = (1 - s Tᵀ) R (RᵀR)⁻¹`` (6.75), no ``A⁻¹`` needed.
    {what}

    Returns
    -------
    ndarray, shape (..., 3, r)

    Raises
    ------
    InputError, SingularInertiaError
        ``A`` not symmetric or ``sᵀR ≠ 0``; ``A`` with a negative eigenvalue, or singular without ``s``.
    SingularConfigurationError
        If ``RᵀA⁻¹R`` (or, with ``s``, ``sᵀAs``) is singular.

    Examples
    --------
    A unit point mass at (1, 0) pinned at the origin (``A`` singular; thesis 7.40 with ``ρ = 0``):

    >>> from planargeo.screws.twists import inertia_matrix
    >>> U_of(inertia_matrix(1.0, [1.0, 0.0], 0.0), [[1.0, 0.0], [0.0, 1.0], [0.0, 0.0]], [0.0, 0.0, 1.0])[2]
    array([ 0., -1.])
    """
    R = _space(R, "R")
    if s is None:
        A, eig = _inertia(A, "A", eig=True)
        return _U(A, R, eig=eig, what=_what(what, None))
    s = _space(s, "s")
    _check_complementary(s, R)
    A = _inertia(A, "A")
    return _U(A, R, s, _T(A, s, _what(what, "sᵀAs")))


# ----------------------------------------------------------------------------- projections
@overflow_checked("s or f")
@_parameters
def active_force(s, f) -> np.ndarray:
    """Active (joint) force ``Q = sᵀ f`` (thesis 6.61a, 6.51): ``Qᵀq̇`` is the power of ``f``.

    {parameters s f Q}

    Examples
    --------
    >>> active_force([0.0, 0.0, 1.0], [1.0, 2.0, 3.0])   # the moment about the pivot
    array([3.])
    """
    return _components(s, f, "sf")


@overflow_checked("U or f")
@_parameters
def reaction_force(U, f) -> np.ndarray:
    """Reaction-force components ``μ = Uᵀ f`` (thesis 6.61b, 6.54): ``R μ``: what the joint carries.

    {parameters U f mu}

    Examples
    --------
    >>> reaction_force(np.eye(3)[:, :2], [1.0, 2.0, 3.0])
    array([1., 2.])
    """
    return _components(U, f, "Uf")


@overflow_checked("T or a")
@_parameters
def active_acceleration(T, a) -> np.ndarray:
    """Active (absolute joint) acceleration ``ψ = Tᵀ a`` (thesis 6.62b, 6.57).

    {parameters T a psi}

    Examples
    --------
    >>> active_acceleration([0.0, 0.8, 1.0], [0.0, 0.0, 2.0])
    array([2.])
    """
    return _components(T, a, "Ta")


@overflow_checked("R or a")
@_parameters
def reactive_acceleration(R, a) -> np.ndarray:
    """Reactive-acceleration components ``γ = Rᵀ a`` (thesis 6.62a, 6.60); zero along ``s``.

    {parameters R a gamma}

    Examples
    --------
    >>> reactive_acceleration([[1.0, 0.0], [0.0, 1.0], [0.0, 0.0]], [0.0, 0.0, 2.0])  # pin at origin
    array([0., 0.])
    """
    return _components(R, a, "Ra")


# ----------------------------------------------------------------------------- projectors
@overflow_checked("A or s or R")
@_parameters
def wrench_projectors(A, s, R) -> tuple[np.ndarray, np.ndarray]:
    """The complementary wrench projectors ``(T sᵀ, R Uᵀ)``, summing to 1 (thesis 6.75, 6.38, 6.61).

    {parameters A s R}

    Returns
    -------
    tuple of numpy.ndarray, each shape (..., 3, 3)
        The active projector ``T sᵀ`` and the reaction projector ``R Uᵀ``.

    Examples
    --------
    >>> P_act, P_rea = wrench_projectors(np.eye(3), [0.0, 0.0, 1.0], [[1.0, 0.0], [0.0, 1.0], [0.0, 0.0]])
    >>> P_act + P_rea
    array([[1., 0., 0.],
           [0., 1., 0.],
           [0., 0., 1.]])
    """
    d = Decomposition(A, s, R)
    return d.T @ _tr(d.s), d.R @ _tr(d.U)


@overflow_checked("A or s or R")
@_parameters
def twist_projectors(A, s, R) -> tuple[np.ndarray, np.ndarray]:
    """The twist projectors ``(s Tᵀ, U Rᵀ)``: the transposes of :func:`wrench_projectors` (dual of thesis 6.75).

    {parameters A s R}

    Returns
    -------
    joint, reactive : numpy.ndarray, each shape (..., 3, 3)
        ``s Tᵀ a = s ψ`` is the joint part of an acceleration, ``U Rᵀ a = U γ`` its reactive part (6.44, 6.62).

    Examples
    --------
    A pin at the origin: the joint part of an acceleration is its rotation about the pin.

    >>> A, s, R = np.eye(3), [0.0, 0.0, 1.0], [[1.0, 0.0], [0.0, 1.0], [0.0, 0.0]]
    >>> P_joint, P_react = twist_projectors(A, s, R)
    >>> P_joint
    array([[0., 0., 0.],
           [0., 0., 0.],
           [0., 0., 1.]])
    >>> all(np.array_equal(P.T, W) for P, W in zip(twist_projectors(A, s, R), wrench_projectors(A, s, R)))
    True
    """
    return tuple(_tr(P) for P in wrench_projectors(A, s, R))     # (T sᵀ)ᵀ, (R Uᵀ)ᵀ: the duality


# ----------------------------------------------------------------------------- inertias
@overflow_checked("I or s")
@_parameters
def joint_space_inertia(I, s) -> np.ndarray:
    """Joint-space inertia ``sᵀ I s`` (thesis 6.67, 6.74c): ``Q = (sᵀIs) ψ``; ``I`` may be singular.

    {parameters I s}

    Returns
    -------
    numpy.ndarray, shape (..., k, k)

    Examples
    --------
    >>> from planargeo.screws.twists import inertia_matrix
    >>> joint_space_inertia(inertia_matrix(2.0, [1.0, 0.0], 0.5), [0.0, 0.0, 1.0])   # m (ρ² + d²)
    array([[2.5]])
    """
    I = _inertia(I, "I")
    s = _space(s, "s")
    return _tr(s) @ I @ s


@overflow_checked("I or R")
@_parameters
def reaction_space_inverse_inertia(I, R) -> np.ndarray:
    """Reaction-space inverse inertia ``Rᵀ I⁻¹ R`` (thesis 6.71): ``γ = (RᵀI⁻¹R) μ``; ``I`` definite.

    {parameters I R}

    Returns
    -------
    numpy.ndarray, shape (..., 3-k, 3-k)

    Examples
    --------
    >>> reaction_space_inverse_inertia(np.diag([2.0, 2.0, 1.0]), [[1.0], [0.0], [0.0]])
    array([[0.5]])
    """
    I, eig = _inertia(I, "I", eig=True)
    R = _space(R, "R")
    return _tr(R) @ _solve_A(I, R, "I", eig)


@overflow_checked("I or s or R")
@_parameters
def inertia_decomposition(I, s, R) -> tuple[np.ndarray, np.ndarray]:
    """Split an inertia as ``I = T sᵀ I + R Uᵀ I`` (thesis 6.76, 6.97); errors as for :class:`Decomposition`.

    {parameters I s R}

    Returns
    -------
    (ndarray, ndarray), each shape (..., 3, 3)

    Examples
    --------
    >>> from planargeo.screws.twists import inertia_matrix
    >>> I = inertia_matrix(2.0, [1.0, 0.0], 0.5)
    >>> Ia, Ib = inertia_decomposition(I, [0.0, 0.0, 1.0], [[1.0, 0.0], [0.0, 1.0], [0.0, 0.0]])
    >>> np.allclose(Ia + Ib, I)
    True
    """
    d = Decomposition(I, s, R, name="I")
    return d.T @ _tr(d.s) @ d.A, d.R @ _tr(d.U) @ d.A


@overflow_checked("I or s or R")
@_parameters
def inverse_inertia_decomposition(I, s, R) -> tuple[np.ndarray, np.ndarray]:
    """Split an inverse inertia as ``I⁻¹ = s Tᵀ I⁻¹ + U Rᵀ I⁻¹`` (thesis 6.79–6.81, 6.93).

    {parameters I s R}

    Returns
    -------
    mobility : numpy.ndarray, shape (..., 3, 3)
        ``s Tᵀ I⁻¹``.
    reactive : numpy.ndarray, shape (..., 3, 3)
        ``U Rᵀ I⁻¹``.

    Examples
    --------
    >>> Ma, Mb = inverse_inertia_decomposition(np.diag([2.0, 2.0, 4.0]), [0.0, 0.0, 1.0],
    ...                                        [[1.0, 0.0], [0.0, 1.0], [0.0, 0.0]])
    >>> Ma + Mb
    array([[0.5 , 0.  , 0.  ],
           [0.  , 0.5 , 0.  ],
           [0.  , 0.  , 0.25]])
    """
    d = Decomposition(I, s, R, name="I")
    IiR = _solve_A(d.A, d.R, "I")
    return _effective_mobility(d.A, d.s, "sᵀIs"), d.U @ _tr(IiR)


@overflow_checked("I or s")
@_parameters
def effective_mobility(I, s, *, what: str | None = None) -> np.ndarray:
    """Effective inverse inertia of a joint-constrained body ``s Tᵀ I⁻¹ = s (sᵀIs)⁻¹ sᵀ`` (thesis 6.93).

    A body at rest loaded by the wrench ``f`` accelerates by ``a = s Tᵀ I⁻¹ f``
    (``f`` applied to the body: the thesis's minus sign, ``docs/errata.md``).

    {parameters I s what returns_3x3}

    Examples
    --------
    >>> from planargeo.screws.twists import inertia_matrix
    >>> effective_mobility(inertia_matrix(2.0, [1.0, 0.0], 0.5), [0.0, 0.0, 1.0])
    array([[0. , 0. , 0. ],
           [0. , 0. , 0. ],
           [0. , 0. , 0.4]])
    """
    return _effective_mobility(_inertia(I, "I"), _space(s, "s"), _what(what, "sᵀIs"))


@overflow_checked("I or R")
@_parameters
def effective_base_inertia(I, R) -> np.ndarray:
    """Effective inertia of the joint base ``R Uᵀ I = R (RᵀI⁻¹R)⁻¹ Rᵀ`` (6.97, 6.76); ``I`` definite.

    {parameters I R}

    Returns
    -------
    numpy.ndarray, shape (..., 3, 3)
        Zero for an empty ``R``.

    Examples
    --------
    >>> effective_base_inertia(np.diag([2.0, 2.0, 4.0]), [[0.0], [0.0], [1.0]])   # only a couple: J
    array([[0., 0., 0.],
           [0., 0., 0.],
           [0., 0., 4.]])
    """
    I, eig = _inertia(I, "I", eig=True)
    R = _space(R, "R")
    if R.shape[-1] == 0:                                # no reaction (a plane joint): nothing is transmitted
        return np.zeros(np.broadcast_shapes(I.shape, R.shape[:-2] + (3, 3)))
    _, M = _reaction_gram(I, R, "I", eig)
    return _right_solve(R, M) @ _tr(R)


# ----------------------------------------------------------------------------- class
#: The two sides of a :class:`Decomposition`, duals: a wrench ``f = T Q + R μ`` is split by ``(s, U)``
#: (6.38, 6.61), a twist ``a = s ψ + U γ`` by ``(T, R)`` (6.44, 6.62).  One split and one join serve
#: both sides; :data:`_SPLIT` and :data:`_JOIN` are their Parameters and Returns, filled per side.
_WRENCH = dict(x="f", screw="Wrench", spaces=("s", "U"), bases=("T", "R"), names=("Q", "mu"), parts=("Q", "μ"),
               words="Active force and reaction components")
_TWIST = dict(x="a", screw="Acceleration twist", spaces=("T", "R"), bases=("s", "U"), names=("psi", "gamma"),
              parts=("ψ", "γ"), words="Joint accelerations and reactive components")
_SPLIT = """
Parameters
----------
{x} : array_like, shape (..., 3)
    {screw}.

Returns
-------
tuple of numpy.ndarray
    ``{parts[0]}`` (..., k) and ``{parts[1]}`` (..., 3-k).
"""
_JOIN = """
Parameters
----------
{names[0]}, {names[1]} : numpy.ndarray, shapes (..., k) and (..., 3-k)
    {words}.

Returns
-------
numpy.ndarray, shape (..., 3)
"""


def _dual_doc(sections: str, dual: dict):
    """A decorator ending a :class:`Decomposition` method's one-line docstring with ``sections`` filled for ``dual``."""
    def document(method):
        method.__doc__ += "\n" + sections.format(**dual)
        return method
    return document


class Decomposition:
    """Decompose wrenches and twists about a joint with an inertia (thesis 6.2–6.3).

    Parameters
    ----------
    A : array_like, shape (..., 3, 3)
        Body or articulated inertia: symmetric positive semi-definite; definite when ``k < 3``.
    s : array_like, shape (..., 3, k) or (3,)
        Motion space.
    R : array_like, shape (..., 3, 3 - k)
        Reaction space, ``sᵀR = 0`` (checked).
    name : str
        Name used for ``A`` in error messages.

    Raises
    ------
    InputError, SingularInertiaError, SingularConfigurationError
        As for :func:`T_of` and :func:`U_of`, and if ``sᵀR ≠ 0``.

    Attributes
    ----------
    A, s, R, T, U : ndarray
        The inertia and the spaces at the origin, ``T`` (6.39, :func:`T_of`), ``U`` (6.45, :func:`U_of`).

    Examples
    --------
    A pendulum (m = 2, centre of mass at (1, 0), J = 0.5) pinned at the origin:
    ``T = [0, 0.8, 1]`` is the wrench of unit joint torque, its line the axis of percussion.

    >>> from planargeo.mechanics.joints import revolute
    >>> from planargeo.screws.twists import inertia_matrix
    >>> dec = Decomposition.from_joint(inertia_matrix(2.0, [1.0, 0.0], 0.5), revolute((0.0, 0.0)))
    >>> dec.T.ravel(), dec.U[:, 1]
    (array([0. , 0.8, 1. ]), array([ 0. ,  1. , -0.8]))
    >>> Q, mu = dec.split_wrench([0.0, 1.0, 2.0])
    >>> Q, mu, dec.join_wrench(Q, mu)
    (array([2.]), array([ 0. , -0.6]), array([0., 1., 2.]))
    """

    __slots__ = ("A", "s", "R", "T", "U")

    def __init__(self, A, s, R, *, name: str = "A"):
        A, eig = _inertia(A, name, eig=True)
        s = _space(s, "s")
        R = _space(R, "R")
        _check_complementary(s, R)
        self.A, self.s, self.R = A, s, R
        self.T = _T(A, s, f"sᵀ{name}s")
        self.U = _U(A, R, name=name, eig=eig)

    @classmethod
    @_parameters
    def from_joint(cls, A, joint, *, name: str = "A") -> "Decomposition":
        """``Decomposition(A, joint.s, joint.R)`` of a :class:`~planargeo.mechanics.joints.JointSpace` (thesis 6.1).

        {parameters A}
        joint : JointSpace
            The joint.
        name : str, optional
            Name of ``A`` in error messages.

        Returns
        -------
        Decomposition

        Examples
        --------
        >>> from planargeo.mechanics.joints import revolute
        >>> Decomposition.from_joint(np.eye(3), revolute((0.0, 0.0))).T.ravel()   # a unit disc: T = s
        array([0., 0., 1.])
        """
        return cls(A, joint.s, joint.R, name=name)

    def _split(self, x, dual: dict) -> tuple[np.ndarray, np.ndarray]:
        """A screw's components along the dual's two spaces (``Xᵀ x``, ``Yᵀ x``)."""
        x = as_vec3(x, dual["x"])
        return tuple(_tmul(getattr(self, name), x) for name in dual["spaces"])

    def _join(self, x, y, dual: dict) -> np.ndarray:
        """The screw ``X x + Y y`` along the dual's two bases."""
        X, Y = (getattr(self, name) for name in dual["bases"])
        return _combine(X, x, Y, y, dual["names"])

    @_dual_doc(_SPLIT, _WRENCH)
    def split_wrench(self, f) -> tuple[np.ndarray, np.ndarray]:
        """``(Q, μ) = (sᵀf, Uᵀf)`` so that ``f = T Q + R μ`` (thesis 6.38, 6.61).

        Examples
        --------
        The class's pendulum loaded by a unit couple: joint torque ``Q = 1``; ``T Q = [0, 0.8, 1]``
        turns it at ``α = 0.4`` and the pivot supplies the rest, ``μ = (0, -0.8)``.

        >>> from planargeo.mechanics.joints import revolute
        >>> from planargeo.screws.twists import inertia_matrix
        >>> dec = Decomposition.from_joint(inertia_matrix(2.0, [1.0, 0.0], 0.5), revolute((0.0, 0.0)))
        >>> dec.split_wrench([0.0, 0.0, 1.0])
        (array([1.]), array([ 0. , -0.8]))
        """
        return self._split(f, _WRENCH)

    @_dual_doc(_SPLIT, _TWIST)
    def split_twist(self, a) -> tuple[np.ndarray, np.ndarray]:
        """``(ψ, γ) = (Tᵀa, Rᵀa)`` so that ``a = s ψ + U γ`` (thesis 6.44, 6.62).

        Examples
        --------
        The class's pendulum translated upwards at unit acceleration: the pivot's ``γ = (0, 1)``
        alone would turn it at ``-0.8`` (``U γ``); ``ψ = 0.8`` cancels that turn.

        >>> from planargeo.mechanics.joints import revolute
        >>> from planargeo.screws.twists import inertia_matrix
        >>> dec = Decomposition.from_joint(inertia_matrix(2.0, [1.0, 0.0], 0.5), revolute((0.0, 0.0)))
        >>> dec.split_twist([0.0, 1.0, 0.0])
        (array([0.8]), array([0., 1.]))
        """
        return self._split(a, _TWIST)

    @_dual_doc(_JOIN, _WRENCH)
    def join_wrench(self, Q, mu) -> np.ndarray:
        """``f = T Q + R μ`` (thesis 6.38).

        Examples
        --------
        The class's pendulum: ``T`` plus the pivot's force (0, -0.8) is the unit couple again.

        >>> from planargeo.mechanics.joints import revolute
        >>> from planargeo.screws.twists import inertia_matrix
        >>> dec = Decomposition.from_joint(inertia_matrix(2.0, [1.0, 0.0], 0.5), revolute((0.0, 0.0)))
        >>> dec.T.ravel()
        array([0. , 0.8, 1. ])
        >>> dec.join_wrench([1.0], [0.0, -0.8]) + 0.0
        array([0., 0., 1.])
        """
        return self._join(Q, mu, _WRENCH)

    @_dual_doc(_JOIN, _TWIST)
    def join_twist(self, psi, gamma) -> np.ndarray:
        """``a = s ψ + U γ`` (thesis 6.44).

        Examples
        --------
        The class's pendulum: ``U[:, 1]`` plus ``s ψ = [0, 0, 0.8]`` is the pure translation;
        a joint acceleration alone is a rotation about the pivot.

        >>> from planargeo.mechanics.joints import revolute
        >>> from planargeo.screws.twists import inertia_matrix
        >>> dec = Decomposition.from_joint(inertia_matrix(2.0, [1.0, 0.0], 0.5), revolute((0.0, 0.0)))
        >>> dec.U[:, 1]
        array([ 0. ,  1. , -0.8])
        >>> dec.join_twist([0.8], [0.0, 1.0]) + 0.0
        array([0., 1., 0.])
        >>> dec.join_twist([1.0], [0.0, 0.0])
        array([0., 0., 1.])
        """
        return self._join(psi, gamma, _TWIST)

    def __repr__(self) -> str:
        return (f"Decomposition(k={self.s.shape[-1]}, batch={self.A.shape[:-2]}, "
                f"T={np.array2string(self.T, precision=4)}, U={np.array2string(self.U, precision=4)})")
