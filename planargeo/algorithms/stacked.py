"""Trees in stacked form (thesis 9.1-9.2): adjacency, trunk, articulation matrix.

Per-body quantities stacked into block vectors and block-diagonal matrices (dense on purpose,
O((3N)³)); the topology enters through ``C`` (9.1) and ``Δ^{-1} = (1 - C)^{-1}`` (9.12).  The articulated
solution (9.39, 9.43) and the direct one (9.48), with printed 9.27, 9.28/9.32, 9.44b and 7.38a
corrected (``docs/errata.md``).
"""
from __future__ import annotations

import functools

import numpy as np

from planargeo._validate import as_array
from planargeo.errors import InputError, ShapeError, TopologyError
from planargeo.mechanics.kinematics import _kinematics_scalar
from planargeo.mechanics.subspaces import _effective_mobility
from planargeo.mechanics.model import Model, _cycle_error, _find_cycle
from planargeo.algorithms.articulated_inertia import (_data_arrays, _one_state, _per_state, _state_arrays,
                                                     articulated_recursion)
from planargeo.algorithms.articulated_mobility import mobility_recursion

__all__ = ["adjacency", "trunk", "blocks", "StackedSolution", "stacked_solve", "joint_conditions",
           "articulation_matrix", "direct_accelerations", "forward_dynamics_stacked"]


# -- topology -------------------------------------------------------------------------------------
def adjacency(parents) -> np.ndarray:
    """Adjacency matrix ``C`` of a tree (thesis Definition 41, 9.1, 9.2): ``C[i, j] = 1`` when ``parents[i] = j``.

    Parameters
    ----------
    parents : sequence of int
        Parent of each body (``-1``: the ground); need not be ordered.

    Returns
    -------
    numpy.ndarray, shape (n, n)

    Raises
    ------
    TopologyError, CyclicTopologyError
        An invalid index, or a body its own parent (longer cycles: :func:`trunk`).

    Examples
    --------
    >>> adjacency([-1, 0, 1]).astype(int)[2]                 # a serial chain (9.2)
    array([0, 1, 0])
    """
    try:
        ps = [int(p) for p in parents]
    except (TypeError, ValueError):
        raise TopologyError(f"parents must be a sequence of integers, got {parents!r}") from None
    n = len(ps)
    C = np.zeros((n, n))
    for i, p in enumerate(ps):
        if p < -1 or p >= n:
            raise TopologyError(f"parents[{i}] must be -1 (ground) or a body index in 0..{n - 1}, got {p}")
        if p == i:
            raise _cycle_error(ps, (i,), f"parents[{i}] must not be {i} itself: a cycle of length one "
                                         "through bodies {path} (parents={parents})")
        if p >= 0:
            C[i, p] = 1.0
    return C


def trunk(C) -> np.ndarray:
    """Trunk matrix ``Δ^{-1} = (1 - C)^{-1} = 1 + C + … + C^{n-1}`` (thesis 9.12, 9.13), exact as ``C`` is nilpotent.

    Parameters
    ----------
    C : array_like, shape (n, n)
        Adjacency matrix of a tree.

    Returns
    -------
    numpy.ndarray, shape (n, n)
        Row ``i`` has ones for the bodies between body ``i`` and the root.

    Raises
    ------
    ShapeError, TopologyError, CyclicTopologyError
        ``C`` not square, not 0/1 or giving a body two parents, or with a cycle (``.cycle``).

    Examples
    --------
    >>> trunk(adjacency([-1, 0, 0]))[2]                   # body 3 hangs from body 1
    array([1., 0., 1.])
    """
    C = as_array(C, "C")
    if C.ndim != 2 or C.shape[0] != C.shape[1]:
        raise ShapeError(f"C must be a square matrix, got shape {C.shape}")
    if not np.all((C == 0) | (C == 1)):
        raise TopologyError("C must contain only zeros and ones")
    if np.any(C.sum(axis=1) > 1):
        i = int(np.argmax(C.sum(axis=1) > 1))
        raise TopologyError(f"C gives body {i} more than one parent: not a tree")
    n = C.shape[0]
    out = np.eye(n)
    P = np.eye(n)
    for _ in range(n):
        P = P @ C
        if not P.any():
            return out
        out = out + P
    # C^n ≠ 0: some body reaches itself through its parents; 1 - C is singular
    ps = [int(np.argmax(row)) if row.any() else -1 for row in C]
    raise _cycle_error(ps, _find_cycle(ps), "C contains a cycle through bodies {path}: not a tree")


@functools.lru_cache(maxsize=256)
def _topology(parents: tuple) -> tuple[np.ndarray, np.ndarray]:
    """Cached block adjacency and trunk matrices ``(C ⊗ 1_3, Δ^{-1} ⊗ 1_3)`` of a parent tuple."""
    C = adjacency(parents)
    out = blocks(C), blocks(trunk(C))
    for x in out:
        x.setflags(write=False)
    return out


def blocks(X, k: int = 3) -> np.ndarray:
    """Expand an ``n × m`` topology matrix into ``k n × k m`` blocks, ``X ⊗ 1_k`` (thesis 9.9, 9.14).

    Parameters
    ----------
    X : array_like, shape (n, m)
        Topology matrix.
    k : int, optional
        Block size.

    Returns
    -------
    numpy.ndarray, shape (k n, k m)

    Examples
    --------
    >>> blocks(np.array([[0, 1]])).shape
    (3, 6)
    """
    return np.kron(np.asarray(X, dtype=float), np.eye(k))


def joint_conditions(model: Model, q) -> np.ndarray:
    """Scale-free condition number of every joint's ``sᵀAs`` at ``q`` (thesis 7.7a, 6.105; the singular case of 3.6).

    Parameters
    ----------
    model, q : Model, array_like (nq,)
        The mechanism and its joint coordinates.

    Returns
    -------
    numpy.ndarray, shape (N,)
        ``cond_i`` by the rule of :data:`planargeo.errors.COND_LIMIT`, never raising: ``inf`` when singular.

    Examples
    --------
    >>> from planargeo.mechanics.model import Body, Joint, Model
    >>> m = Model([Body(1.0), Body(1.0)], [Joint("revolute"), Joint("prismatic")], [-1, 0])
    >>> round(float(joint_conditions(m, [0.0, 1e-3])[0]) * 1e-6, 3)        # slid x out: √5 / x²
    2.236
    """
    return articulated_recursion(*_state_arrays(model, q, None, None, None)[1:], check=False).cond


def _blockdiag(mats) -> np.ndarray:
    """The block-diagonal matrix of the 2-d arrays ``mats``."""
    n, shapes = len(mats), {np.shape(m) for m in mats}
    if len(shapes) == 1:                           # equal blocks: one assignment
        (r, c), = shapes
        out = np.zeros((n * r, n * c))
        k = np.arange(n)
        out.reshape(n, r, n, c)[k, :, k, :] = np.asarray(mats, dtype=float).reshape(n, r, c)
        return out
    from scipy.linalg import block_diag

    return block_diag(*mats) if n else np.zeros((0, 0))


def _unit_upper_solve(M, b, trans: bool = False) -> np.ndarray:
    """``M⁻¹ b`` (or ``M⁻ᵀ b``) for the unit upper triangular ``M = 1 - C^T P`` of a tree whose parents come first."""
    from scipy.linalg.lapack import dtrtrs

    # LAPACK on the Fortran-ordered view M^T (lower triangular): M x = b is (M^T)^T x = b
    x, info = dtrtrs(M.T, b, lower=1, trans=0 if trans else 1, unitdiag=1)
    assert info == 0, info                        # unit diagonal: never singular
    return x


def articulation_matrix(C3, P) -> np.ndarray:
    """Articulation matrix ``L = (1 - C^T R U^T)^{-1}`` (thesis 9.31, 9.34), by a direct solve.

    Parameters
    ----------
    C3, P : numpy.ndarray, shape (3n, 3n)
        Block adjacency, and block-diagonal ``{R_i U_iᵀ} = 1 - T Sᵀ`` (7.8).

    Returns
    -------
    numpy.ndarray, shape (3n, 3n)

    Examples
    --------
    >>> L = articulation_matrix(blocks(adjacency([-1, 0])), np.eye(6))
    >>> L[:3, 3:].diagonal(), L[3:, :3].any()            # body 2's articulated load reaches body 1
    (array([1., 1., 1.]), np.False_)
    """
    n = C3.shape[0]
    return np.linalg.solve(np.eye(n) - C3.T @ P, np.eye(n))


class StackedSolution:
    """All stacked quantities of one state (thesis 9.17-9.43; attributes named after the symbols).

    Attributes
    ----------
    C, Dinv : (3N, 3N) block adjacency and trunk matrices (9.1, 9.12)
    S, T : (3N, nq) joint axes and percussion spaces (9.9, 9.19)
    P : (3N, 3N) block-diagonal ``R U^T = 1 - T S^T`` (7.8)
    R, U : (3N, 3N-nq) reaction (:func:`planargeo.mechanics.joints.R_of`, thesis 7.16) and quake spaces (9.20)
    I, A, L : (3N, 3N) inertias, articulated inertias, articulation matrix (9.31)
    kappa, p, d : (3N,) bias accelerations, bias forces, articulated bias forces (9.32)
    articulated : the per-body quantities (7.7 = 9.27-9.28 corrected)
    articulated_mobilities : built on first access (7.38, 9.45)
    a, f, qdd : body accelerations (9.39), joint forces (9.41 with 9.17), joint accelerations (9.43)

    Examples
    --------
    >>> from planargeo.mechanics.model import chain_model
    >>> sol = stacked_solve(chain_model(1), [0.0], [0.0], [0.0])
    >>> (sol.U.T @ sol.f).round(6) + 0.0       # a released link's pin force (μ = Uᵀ f)
    array([0.    , 2.4525])
    """

    def __repr__(self):
        return f"StackedSolution(N={self.N}, nq={len(self.qdd)})"

    @functools.cached_property
    def articulated_mobilities(self):
        """The tree's articulated mobilities ``Λ_i⁻¹``, ``b_i`` (7.38 with the siblings, 9.45 corrected)."""
        return mobility_recursion(*self._args, articulated=self.articulated)

    @functools.cached_property
    def L(self) -> np.ndarray:
        """Articulation matrix ``L = (1 - C^T R U^T)^{-1}`` (9.31), built on first access."""
        return articulation_matrix(self.C, self.P)

    @property
    def R(self) -> np.ndarray:
        """Block-diagonal reaction spaces ``{{R_i}}`` (``S^T R = 0``, thesis 9.20)."""
        return _blockdiag(self.articulated.R)

    @property
    def U(self) -> np.ndarray:
        """Block-diagonal quake spaces ``{{U_i}}`` (9.20, 6.99), ``U R^T = 1 - S T^T``."""
        return _blockdiag(self.articulated.U)

    @functools.cached_property
    def mobility(self) -> np.ndarray:
        """The tree's full stacked mobility ``Φ = L^T S T^T A^{-1} L`` (3N×3N): ``a = u - Φ w`` for wrenches ``-w``."""
        M = self.L.T @ self.StTAinv @ self.L
        return 0.5 * (M + M.T)

    def mobility_times(self, X) -> np.ndarray:
        """``Φ X`` without forming ``Φ`` or ``L``: ``Lᵀ (S Tᵀ A⁻¹ (L X))`` by two sweeps (9.31, 9.34).

        Parameters
        ----------
        X : array_like, shape (3N, k) or (3N,)
            Stacked wrenches (the loop solver's contact columns ``Gᵀ`` (9.65-9.73)).

        Returns
        -------
        numpy.ndarray
            ``Φ X``, the shape of ``X``.

        Examples
        --------
        >>> from planargeo.mechanics.model import chain_model
        >>> sol = stacked_solve(chain_model(1), [0.0], [0.0], [0.0])
        >>> sol.mobility_times([0.0, 0.0, 1.0]).round(12) + 0.0     # 1 / (m (ρ² + L²/4)) (7.42)
        array([0., 0., 3.])
        """
        X = np.asarray(X, dtype=float)
        N, P, par = self.N, self.articulated.P, self.parents
        Y = X.reshape(N, 3, -1).copy()
        for i in range(N - 1, 0, -1):                  # Y = L X: children before parents
            j = par[i]
            if j >= 0:
                Y[j] += P[i] @ Y[i]
        Z = np.einsum("nij,njk->nik", self.mobs, Y)   # S Tᵀ A⁻¹, block diagonal
        for i in range(1, N):                          # Z = Lᵀ W: parents before children
            j = par[i]
            if j >= 0:
                Z[i] += P[i].T @ Z[j]
        return Z.reshape(X.shape)


def stacked_solve(model: Model, q, qd, tau, f_ext=None, *, data=None) -> StackedSolution:
    """Solve one state of a tree in stacked form (thesis 9.17-9.43, 9.39).

    ``a = L^T [S T^T A^{-1} (T Q - d) + U R^T κ]`` (9.39), ``d = L (p + C^T T Q + C^T R U^T A κ)``
    (9.32 corrected), ``f = T Q + R U^T (A (C a + κ) + d)`` (9.41/9.17), ``q̈ = T^T (Δ a - κ)`` (9.43).

    Parameters
    ----------
    model, q, qd, tau, f_ext : Model, array_like
        A tree (or chain) without contacts and one state.
    data : Data, optional
        Precomputed kinematics for this state.

    Returns
    -------
    StackedSolution

    Raises
    ------
    ShapeError
        If the state is a batch.

    Examples
    --------
    >>> from planargeo.mechanics.model import chain_model
    >>> stacked_solve(chain_model(1), [0.0], [0.0], [0.0]).qdd.round(6)      # -3g / 2L
    array([-14.715])
    """
    q, qd, tau, f_ext = _one_state(model, q, qd, tau, f_ext, "stacked_solve")
    N = model.N
    if data is None:
        data = _kinematics_scalar(model, q, qd, f_ext)   # kinematics(), checked
    args = _data_arrays(model, data, tau)
    art = articulated_recursion(*args[1:])          # 7.7a/7.7b = 9.27/9.28 corrected, 7.8
    sol = StackedSolution()
    sol.N, sol.parents, sol.articulated, sol.data = N, tuple(model.parents), art, data
    sol._args = args[1:]
    sol.C, sol.Dinv = _topology(tuple(model.parents))
    sol.S, sol.T, sol.P, sol.I, sol.A = (_blockdiag(x) for x in (art.S, art.T, art.P, data.I, art.A))
    sol.kappa, sol.p = data.kappa.reshape(-1), data.p.reshape(-1)
    Q = np.concatenate(args[5]) if N else np.zeros(0)
    C, T, P, A = sol.C, sol.T, sol.P, sol.A
    # L = (1 - C^T R U^T)^-1 (9.31) is applied by solves with the unit upper triangular
    # 1 - C^T P (parents before children); sol.L itself is built on first access.
    Linv = np.eye(3 * N)                           # 1 - C^T P: block (λ(i), i) is -P_i
    for i, j in enumerate(model.parents):
        if j >= 0:
            Linv[3 * j:3 * j + 3, 3 * i:3 * i + 3] = -art.P[i]
    sol.d = _unit_upper_solve(Linv, sol.p + C.T @ (T @ Q) + C.T @ (P @ (A @ sol.kappa)))   # (9.32) corrected
    # (9.39) with S T^T A^-1 = S (S^T A S)^-1 S^T: no inverse of A needed
    if N and all(si.shape[1] == 1 for si in art.S):    # one-dof joints: all bodies in one call (sᵀAs checked)
        mobs = _effective_mobility(art.A, np.stack(art.S),
                                   gram=(np.stack([g[0] for g in art.gram]), np.stack([g[1] for g in art.gram])))
    else:
        mobs = [_effective_mobility(Ai, si, gram=g) for si, Ai, g in zip(art.S, art.A, art.gram)]
    sol.StTAinv = _blockdiag(mobs)
    sol.mobs = np.reshape(mobs, (N, 3, 3))         # its 3×3 blocks (mobility_times)
    sol.a = _unit_upper_solve(Linv, sol.StTAinv @ (T @ Q - sol.d) + P.T @ sol.kappa, trans=True)  # U R^T = P^T
    sol.f = T @ Q + P @ (A @ (C @ sol.a + sol.kappa) + sol.d)           # (9.41) with (9.17)
    sol.qdd = T.T @ (sol.a - C @ sol.a - sol.kappa)                     # (9.43)
    return sol


# -- direct solution (9.2) ------------------------------------------------------------------------
def direct_accelerations(sol: StackedSolution, Lambda_inv, b) -> np.ndarray:
    """Direct solution of the body accelerations (thesis 9.48, corrected).

    ``a = (1 + Λ^{-1} C^T Δ^{-T} I)^{-1} (b - Λ^{-1} C^T Δ^{-T} p)`` from ``a = b - Λ^{-1} C^T f`` (9.45)
    and ``f = Δ^{-T} (I a + p)`` (9.44b with the missing inverse restored).

    Parameters
    ----------
    sol : StackedSolution
        The state (:func:`stacked_solve`).
    Lambda_inv, b : (N, 3, 3) and (N, 3)
        The tree's articulated mobilities (``sol.articulated_mobilities``).

    Returns
    -------
    a : (3N,) stacked body accelerations, equal to ``sol.a`` (9.39).

    Examples
    --------
    >>> from planargeo.mechanics.model import chain_model
    >>> sol = stacked_solve(chain_model(2), [0.0, 0.0], [0.0, 0.0], [1.0, 0.0])
    >>> bool(np.allclose(direct_accelerations(sol, sol.articulated_mobilities.Lambda_inv,
    ...                                       sol.articulated_mobilities.b), sol.a))
    True
    """
    N = sol.N
    K = _blockdiag(Lambda_inv) @ sol.C.T @ sol.Dinv.T
    return np.linalg.solve(np.eye(3 * N) + K @ sol.I, np.concatenate(b) - K @ sol.p)


def forward_dynamics_stacked(model: Model, q, qd, tau, f_ext=None, *, method: str = "articulation"):
    """Forward dynamics of a tree in stacked form (thesis 9.39 / 9.48, then 9.43).

    Parameters
    ----------
    model, q, qd, tau, f_ext : Model, array_like
        A tree (or chain) without contacts and its states, as for :func:`planargeo.algorithms.aba.forward_dynamics`.
    method : {"articulation", "direct"}
        The articulation matrix (9.39) or the articulated mobilities (9.48, corrected).

    Returns
    -------
    ndarray (..., nq)

    Raises
    ------
    InputError
        For an unknown ``method``.

    Examples
    --------
    >>> from planargeo.mechanics.model import chain_model
    >>> forward_dynamics_stacked(chain_model(1), [0.0], [0.0], [0.0], method="direct").round(6)
    array([-14.715])
    """
    if method not in ("articulation", "direct"):
        raise InputError(f"method must be 'articulation' or 'direct', got {method!r}")
    return _per_state(functools.partial(_stacked_qdd, direct=method == "direct"), model, q, qd, tau, f_ext)


def _stacked_qdd(model, q, qd, tau, f_ext, *, direct):
    sol = stacked_solve(model, q, qd, tau, f_ext)
    if not direct:
        return sol.qdd
    mob = sol.articulated_mobilities
    a = direct_accelerations(sol, mob.Lambda_inv, mob.b)
    return sol.T.T @ (a - sol.C @ a - sol.kappa)                   # (9.43)
