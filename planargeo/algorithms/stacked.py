"""Trees in stacked form (thesis 9.1-9.2): adjacency, trunk, articulation matrix.

Every per-body quantity is stacked into one block vector (``{x_i}``) or one
block-diagonal matrix (``{{X_i}}``) and the tree's topology enters through
the adjacency matrix ``C`` (Definition 41, 9.1) and the trunk matrix
``Δ^{-1} = (1 - C)^{-1}`` (9.12).  Two solutions are provided:

* the articulated solution (9.39): ``a = L^T [S T^T A^{-1} (T Q - d) + U R^T κ]``
  with the articulation matrix ``L = (1 - C^T R U^T)^{-1}`` (9.31) and
  ``q̈ = T^T (Δ a - κ)`` (9.43);
* the direct solution (9.48) from the articulated mobilities ``Λ^{-1}``, ``b``.

Corrections to the printed equations (see ``docs/errata.md``):

* (9.27) ``A = I + C^T R U^T A C`` (printed without the trailing ``C``, which
  makes ``C^T R U^T A`` off-diagonal); hence (9.30) ``A = Σ_k (C^T R U^T)^k I C^k``,
  not ``L I``;
* (9.28)/(9.32) ``d = L (p + C^T T Q + C^T R U^T A κ)``: the term
  ``C^T R U^T A κ`` (7.7b) is missing in print;
* (9.44b) ``f = (1 - C^T)^{-1} (I a + p) = Δ^{-T} (I a + p)`` (printed
  without the inverse), which changes (9.46)-(9.48) accordingly;
* (7.38a) for the mobilities: ``s T^T I^{-1} + U R^T Λ_{λ}^{-1}`` (printed with
  a minus), generalised here to trees (siblings enter through their
  articulated inertias).

Dense block matrices are used on purpose (they *are* the stacked form); the
cost is O((3N)^3), fine up to a few hundred bodies.

Examples
--------
>>> C = adjacency([-1, 0, 1, 2, 0, 4, 5, 5, 0])          # Fig 9.1, thesis 9.1
>>> trunk(C)[7].astype(int)                               # row 8 of 9.13: bodies 1, 5, 6, 8
array([1, 0, 0, 0, 1, 1, 0, 1, 0])
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


# ---------------------------------------------------------------------------
# topology
# ---------------------------------------------------------------------------
def adjacency(parents) -> np.ndarray:
    """Adjacency matrix ``C`` of a tree (thesis Definition 41, 9.1, 9.2).

    ``C[i, j] = 1`` when body ``j`` is the immediate parent of body ``i``
    (``parents[i] = j``; ``-1`` is the ground and gives a zero row).  The
    parents need not be ordered; cycles are detected by :func:`trunk`.

    Parameters
    ----------
    parents : sequence of int
        Parent of each body (``-1``: the ground).

    Returns
    -------
    numpy.ndarray, shape (n, n)
        ``C``.

    Raises
    ------
    TopologyError
        If ``parents`` is not a sequence of valid indices.
    CyclicTopologyError
        If a body is its own parent.

    Examples
    --------
    >>> adjacency([-1, 0, 1]).astype(int)                 # a serial chain (9.2)
    array([[0, 0, 0],
           [1, 0, 0],
           [0, 1, 0]])
    >>> adjacency([-1, 5])
    Traceback (most recent call last):
    ...
    planargeo.errors.TopologyError: parents[1] must be -1 (ground) or a body index in 0..1, got 5
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
    """Trunk matrix ``Δ^{-1} = (1 - C)^{-1}`` (thesis 9.12, 9.13).

    Computed as the finite series ``1 + C + C² + ... + C^{n-1}``, exact because
    a tree's adjacency matrix is nilpotent (``C^n = 0``).  Row ``i`` has ones
    in the columns of the bodies between body ``i`` and the root.

    Parameters
    ----------
    C : array_like, shape (n, n)
        Adjacency matrix of a tree.

    Returns
    -------
    numpy.ndarray, shape (n, n)
        ``(1 - C)⁻¹``.

    Raises
    ------
    TopologyError
        If ``C`` is not 0/1 or gives a body two parents.
    CyclicTopologyError
        If ``C`` contains a cycle (``C^n ≠ 0``): ``1 - C`` is singular
        (``.cond`` is ``inf``, ``.cycle`` the bodies on it).
    ShapeError
        If ``C`` is not square.

    Examples
    --------
    >>> trunk(adjacency([-1, 0, 1])).astype(int)
    array([[1, 0, 0],
           [1, 1, 0],
           [1, 1, 1]])
    >>> trunk(np.array([[0, 1], [1, 0]]))
    Traceback (most recent call last):
    ...
    planargeo.errors.CyclicTopologyError: C contains a cycle through bodies 0 -> 1 -> 0: not a tree (condition number of 1 - C: inf)
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
    C3, D3 = blocks(C), blocks(trunk(C))
    C3.setflags(write=False)
    D3.setflags(write=False)
    return C3, D3


def blocks(X, k: int = 3) -> np.ndarray:
    """Expand an ``n × m`` 0/±1 topology matrix into ``3n × 3m`` blocks (``X ⊗ 1_3``; thesis 9.9, 9.14).

    Parameters
    ----------
    X : array_like, shape (n, m)
        Topology matrix.
    k : int, optional
        Block size.

    Returns
    -------
    numpy.ndarray, shape (k n, k m)
        ``X ⊗ 1_k``.

    Examples
    --------
    >>> blocks(np.array([[0, 1]])).shape
    (3, 6)
    """
    return np.kron(np.asarray(X, dtype=float), np.eye(k))


def joint_conditions(model: Model, q) -> np.ndarray:
    """Scale-free condition number of every joint's ``sᵀAs`` at ``q`` (thesis 7.7a, 6.105; the singular case of 3.6).

    ``cond_i = ‖A_i‖ ‖s_i‖² / σ_min(s_iᵀ A_i s_i)`` (Frobenius norms; ``A_i`` and
    ``s_i`` at the joint's point, :func:`planargeo.mechanics.subspaces.joint_scale`), the
    package's singularity rule (:data:`planargeo.errors.COND_LIMIT` ``= 1e12``;
    invariant under moving the whole mechanism), with ``A_i`` the articulated inertias of the
    tree (``A = I + C^T R U^T A C``, :func:`planargeo.algorithms.articulated_inertia.articulated_recursion`
    with ``check=False``).  Unlike the forward dynamics it never
    raises: a singular joint gets ``inf`` (and is treated as locked for its
    parent).  ``A`` does not depend on ``q̇``.  Joints with no coordinates
    (``"fixed"``) get ``1.0``.  Used to watch a simulation for singular
    configurations (:func:`planargeo.simulate.simulate`, ``condition="joints"``).

    Parameters
    ----------
    model : Model
        The mechanism.
    q : array_like, shape (nq,)
        Joint coordinates.

    Returns
    -------
    numpy.ndarray, shape (N,)
        ``cond_i``; ``inf`` for a singular joint.

    Examples
    --------
    A unit point mass on the pivot of a rod along which a second unit point
    mass slides (at ``x``): ``sᵀAs = m x²`` for the pivot and ``‖A‖ ≈ √5 m`` at it,
    so ``cond ≈ √5 / x²``; the slider (its point: the pivot) has ``sᵀIs = m`` and
    ``‖I‖ = m √(2 + 2x² + x⁴)`` there, so ``cond = √(2 + 2x² + x⁴)``.

    >>> from planargeo.mechanics.model import Body, Joint, Model
    >>> m = Model([Body(1.0), Body(1.0)], [Joint("revolute"), Joint("prismatic")], [-1, 0])
    >>> c = joint_conditions(m, [0.0, 1e-3])
    >>> round(float(c[0]) * 1e-6, 3), round(float(c[1]), 3)
    (2.236, 1.414)
    >>> float(joint_conditions(m, [0.0, 0.0])[0])
    inf
    """
    return articulated_recursion(*_state_arrays(model, q, None, None, None)[1:], check=False).cond


def _blockdiag(mats, rows, cols):
    n = len(mats)
    if n and all(r == rows[0] for r in rows) and all(c == cols[0] for c in cols):   # equal blocks: one assignment
        r, c = rows[0], cols[0]
        out = np.zeros((n * r, n * c))
        k = np.arange(n)
        out.reshape(n, r, n, c)[k, :, k, :] = np.asarray(mats, dtype=float).reshape(n, r, c)
        return out
    out = np.zeros((sum(rows), sum(cols)))
    r = c = 0
    for M, nr, nc in zip(mats, rows, cols):
        out[r:r + nr, c:c + nc] = M
        r += nr
        c += nc
    return out


def _unit_upper_solve(M, b, trans: bool = False) -> np.ndarray:
    """``M⁻¹ b`` (or ``M⁻ᵀ b``) for the unit upper triangular ``M = 1 - C^T P`` of a tree whose parents come first."""
    from scipy.linalg.lapack import dtrtrs

    # LAPACK on the Fortran-ordered view M^T (lower triangular): M x = b is (M^T)^T x = b
    x, info = dtrtrs(M.T, b, lower=1, trans=0 if trans else 1, unitdiag=1)
    assert info == 0, info                        # unit diagonal: never singular
    return x


def articulation_matrix(C3, P) -> np.ndarray:
    """Articulation matrix ``L = (1 - C^T R U^T)^{-1}`` (thesis 9.31, 9.34).

    ``C3`` is the block adjacency (3n×3n) and ``P = {{R_i U_i^T}}`` the
    block-diagonal projector (``R U^T = 1 - T S^T``, 7.8).  ``C^T P`` is
    nilpotent, so the series (9.34) is finite; a direct solve is used.

    Parameters
    ----------
    C3 : numpy.ndarray, shape (3n, 3n)
        Block adjacency.
    P : numpy.ndarray, shape (3n, 3n)
        Block-diagonal ``{R_i U_iᵀ}``.

    Returns
    -------
    numpy.ndarray, shape (3n, 3n)
        ``L``.

    Examples
    --------
    >>> C3 = blocks(adjacency([-1, 0]))
    >>> L = articulation_matrix(C3, np.eye(6))
    >>> L[:3, 3:], L[3:, :3].any()                   # body 2's articulated load reaches body 1
    (array([[1., 0., 0.],
           [0., 1., 0.],
           [0., 0., 1.]]), np.False_)
    """
    n = C3.shape[0]
    return np.linalg.solve(np.eye(n) - C3.T @ P, np.eye(n))


class StackedSolution:
    """All stacked quantities of one state (thesis 9.17-9.43; attributes named after the symbols).

    Reaction basis: ``R`` holds each joint's :func:`planargeo.mechanics.joints.R_of`
    (unit forces through the joint, couples; thesis 7.16, 5.63), the same as
    :mod:`planargeo.algorithms.projective`, so ``U^T f`` gives the same ``μ``.

    Attributes
    ----------
    C, Dinv : (3N, 3N) block adjacency and trunk matrices (9.1, 9.12)
    S, T : (3N, nq) joint axes and percussion spaces (9.9, 9.19)
    P : (3N, 3N) block-diagonal ``R U^T = 1 - T S^T`` (7.8)
    R, U : (3N, 3N-nq) reaction and quake spaces (9.20), computed on demand
    I, A : (3N, 3N) block-diagonal inertias and articulated inertias
    L : (3N, 3N) articulation matrix (9.31)
    kappa, p, d : (3N,) bias accelerations, bias forces, articulated bias forces (9.32)
    articulated : ArticulatedInertias, the per-body quantities
        (:func:`planargeo.algorithms.articulated_inertia.articulated_recursion`, 7.7 = 9.27-9.28 corrected)
    articulated_mobilities : ArticulatedMobilities, built on first access (7.38, 9.45; the input of 9.48)
    a : (3N,) body accelerations (9.39)
    f : (3N,) internal joint forces (9.41 with 9.17)
    qdd : (nq,) joint accelerations (9.43)

    Examples
    --------
    A unit link (m = L = 1) lying along x on a pin at the origin, released
    under gravity with no joint torque: ``μ = Uᵀ f`` (6.61b) is the pin force,
    along x and y through the pin, ``m (a_c + g) = 0.5 q̈ + 9.81`` along y.
    (With a joint torque ``Q``, ``f = T Q + R μ`` sets the percussion-axis
    force ``T Q`` apart first, 6.38.)

    >>> from planargeo.mechanics.model import chain_model
    >>> sol = stacked_solve(chain_model(1), [0.0], [0.0], [0.0])
    >>> sol.R
    array([[1., 0.],
           [0., 1.],
           [0., 0.]])
    >>> (sol.U.T @ sol.f).round(6) + 0.0, round(0.5 * float(sol.qdd[0]) + 9.81, 6)
    (array([0.    , 2.4525]), 2.4525)
    """

    def __repr__(self):
        return f"StackedSolution(N={self.N}, nq={len(self.qdd)})"

    @property
    def articulated_mobilities(self):
        """The tree's articulated mobilities ``Λ_i⁻¹``, ``b_i`` (7.38 with the siblings loaded, 9.45 corrected).

        :func:`planargeo.algorithms.articulated_mobility.mobility_recursion` of this state (an
        ``ArticulatedMobilities``), built on first access; the input of :func:`direct_accelerations`.
        """
        if not hasattr(self, "_mobilities"):
            self._mobilities = mobility_recursion(*self._args, articulated=self.articulated)
        return self._mobilities

    @property
    def L(self) -> np.ndarray:
        """Articulation matrix ``L = (1 - C^T R U^T)^{-1}`` (9.31; :func:`articulation_matrix`, built on first access)."""
        if not hasattr(self, "_L"):
            self._L = articulation_matrix(self.C, self.P)
        return self._L

    def _stack(self, blocks) -> np.ndarray:
        kr = [3 - si.shape[1] for si in self.articulated.S]
        return _blockdiag(blocks, [3] * self.N, kr)

    @property
    def R(self) -> np.ndarray:
        """Block-diagonal reaction spaces ``{{R_i}}`` (``S^T R = 0``, thesis 9.20; :func:`planargeo.mechanics.joints.R_of`: forces through the joints, couples)."""
        return self._stack(self.articulated.R)

    @property
    def U(self) -> np.ndarray:
        """Block-diagonal quake spaces ``{{U_i}}`` (9.20, 6.99), ``U R^T = 1 - S T^T``."""
        return self._stack(self.articulated.U)

    @property
    def mobility(self) -> np.ndarray:
        """The tree's full stacked mobility ``Φ = L^T S T^T A^{-1} L`` (3N×3N).

        ``a = u - Φ w`` when wrenches ``-w`` are applied to the bodies; block
        ``(i, i)`` is body ``i``'s articulated mobility in the whole tree (the
        ``Λ^{-1}`` of 9.65-9.73, see the erratum there).
        """
        if not hasattr(self, "_mob"):
            self._mob = self.L.T @ self.StTAinv @ self.L
            self._mob = 0.5 * (self._mob + self._mob.T)
        return self._mob

    def mobility_times(self, X) -> np.ndarray:
        """``Φ X`` without forming ``Φ`` or ``L``: ``Lᵀ (S Tᵀ A⁻¹ (L X))`` by two unit-triangular solves.

        ``L⁻¹ = 1 - Cᵀ P`` is block upper triangular along the tree, so
        ``Y = L X`` is the inward sweep ``Y_λ(i) += P_i Y_i`` (children first,
        the articulated load of 9.31/9.34) and ``Z = Lᵀ W`` the outward sweep
        ``Z_i = W_i + P_iᵀ Z_λ(i)``: ``O(N k)`` for the ``k`` columns of ``X``
        (3N × k), 3×3 blocks only, instead of the ``3N × 3N`` inverse and
        products of :attr:`mobility`.  This is what the loop solver needs:
        the contact columns ``Λ⁻¹ Gᵀ`` (9.65-9.73).

        Parameters
        ----------
        X : array_like, shape (3N, k) or (3N,)
            Stacked wrenches.

        Returns
        -------
        numpy.ndarray
            ``Φ X``, the shape of ``X``.

        Examples
        --------
        A unit link on a pin at the origin (``ρ² = 1/12``): a unit couple turns it at ``1/(m(ρ² + L²/4)) = 3`` rad/s² (7.42).

        >>> from planargeo.mechanics.model import chain_model
        >>> sol = stacked_solve(chain_model(1), [0.0], [0.0], [0.0])
        >>> sol.mobility_times(np.array([[0.0], [0.0], [1.0]])).ravel().round(12) + 0.0
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

    Parameters
    ----------
    model : Model
        A tree (or chain) without contacts.
    q, qd, tau : array_like (nq,)
        One state: joint coordinates, velocities and forces.
    f_ext : array_like (N, 3), optional
        World wrenches at the origin applied to each body.
    data : Data, optional
        Precomputed kinematics for this state.

    Returns
    -------
    StackedSolution
        ``a = L^T [S T^T A^{-1} (T Q - d) + U R^T κ]`` (9.39),
        ``d = L (p + C^T T Q + C^T R U^T A κ)`` (9.32 corrected),
        ``f = T Q + R U^T (A (C a + κ) + d)`` (9.41/9.17),
        ``q̈ = T^T (Δ a - κ)`` (9.43).

    Raises
    ------
    ShapeError
        If the state is a batch.

    Examples
    --------
    >>> from planargeo.mechanics.model import chain_model
    >>> sol = stacked_solve(chain_model(1), [0.0], [0.0], [0.0])
    >>> round(float(sol.qdd[0]), 6)                      # uniform rod from its end: -3g/(2L)
    -14.715
    """
    q, qd, tau, f_ext = _one_state(model, q, qd, tau, f_ext, "stacked_solve")
    N = model.N
    if data is None:
        data = _kinematics_scalar(model, q, qd, f_ext)   # kinematics(), checked
    args = _data_arrays(model, data, tau)
    art = articulated_recursion(*args[1:])          # 7.7a/7.7b = 9.27/9.28 corrected, 7.8
    ks = [si.shape[1] for si in art.S]
    three = [3] * N
    sol = StackedSolution()
    sol.N = N
    sol.C, sol.Dinv = _topology(tuple(model.parents))
    sol.S = _blockdiag(art.S, three, ks)
    sol.T = _blockdiag(art.T, three, ks)
    sol.P = _blockdiag(art.P, three, three)
    sol.I = _blockdiag(list(data.I), three, three)
    sol.A = _blockdiag(art.A, three, three)
    sol.kappa = data.kappa.reshape(-1)
    sol.p = data.p.reshape(-1)
    Q = np.concatenate(args[5]) if N else np.zeros(0)
    C, T, P, A = sol.C, sol.T, sol.P, sol.A
    # L = (1 - C^T R U^T)^-1 (9.31) is applied by solves with the unit upper triangular
    # 1 - C^T P (parents before children); sol.L itself is built on first access.
    Linv = np.eye(3 * N)                           # 1 - C^T P: block (λ(i), i) is -P_i
    for i, j in enumerate(model.parents):
        if j >= 0:
            Linv[3 * j:3 * j + 3, 3 * i:3 * i + 3] = -art.P[i]
    # (9.32) corrected: d = L (p + C^T T Q + C^T R U^T A κ)
    sol.d = _unit_upper_solve(Linv, sol.p + C.T @ (T @ Q) + C.T @ (P @ (A @ sol.kappa)))
    # (9.39): a = L^T [S T^T A^-1 (T Q - d) + U R^T κ]
    # S T^T A^-1 = S (S^T A S)^-1 S^T: no inverse of A needed
    if N and all(k == 1 for k in ks):              # one-dof joints: all bodies in one call (sᵀAs checked above)
        mobs = _effective_mobility(art.A, np.stack(art.S),
                                   gram=(np.stack([g[0] for g in art.gram]), np.stack([g[1] for g in art.gram])))
    else:
        mobs = [_effective_mobility(Ai, si, gram=g) for si, Ai, g in zip(art.S, art.A, art.gram)]
    sol.StTAinv = _blockdiag(mobs, three, three)
    sol.mobs = np.reshape(mobs, (N, 3, 3))         # its 3×3 blocks (mobility_times)
    sol.parents = tuple(model.parents)
    sol.a = _unit_upper_solve(Linv, sol.StTAinv @ (T @ Q - sol.d) + P.T @ sol.kappa, trans=True)  # U R^T = P^T
    # (9.41) with (9.17): internal forces
    sol.f = T @ Q + P @ (A @ (C @ sol.a + sol.kappa) + sol.d)
    # (9.43): q̈ = T^T (Δ a - κ)
    sol.qdd = T.T @ (sol.a - C @ sol.a - sol.kappa)
    sol.articulated = art
    sol.data = data
    sol._args = args[1:]
    return sol


# ---------------------------------------------------------------------------
# direct solution (9.2)
# ---------------------------------------------------------------------------
def direct_accelerations(sol: StackedSolution, Lambda_inv, b) -> np.ndarray:
    """Direct solution of the body accelerations (thesis 9.48, corrected).

    From ``a = b - Λ^{-1} C^T f`` (9.45) and ``f = Δ^{-T} (I a + p)`` (9.44b
    with the missing inverse restored)::

        a = (1 + Λ^{-1} C^T Δ^{-T} I)^{-1} (b - Λ^{-1} C^T Δ^{-T} p)

    ``Λ^{-1} = {{Λ_i^{-1}}}`` block diagonal and ``b = {b_i}`` the articulated mobilities of
    the tree (:attr:`StackedSolution.articulated_mobilities`, 7.38 with the siblings loaded:
    ``docs/errata.md``, chapter 9, item 5).

    Parameters
    ----------
    sol : StackedSolution
        The state (:func:`stacked_solve`), for ``C``, ``Δ^{-1}``, ``I``, ``p``.
    Lambda_inv, b : (N, 3, 3) and (N, 3)
        E.g. ``sol.articulated_mobilities.Lambda_inv`` and ``.b``.

    Returns
    -------
    a : (3N,) stacked body accelerations, equal to ``sol.a`` (9.39).

    Examples
    --------
    >>> from planargeo.mechanics.model import chain_model
    >>> m = chain_model(2, gravity=(0.0, 0.0))
    >>> sol = stacked_solve(m, [0.0, 0.0], [0.0, 0.0], [1.0, 0.0])
    >>> mob = sol.articulated_mobilities
    >>> a = direct_accelerations(sol, mob.Lambda_inv, mob.b)
    >>> bool(np.allclose(a, sol.a))
    True
    """
    N = sol.N
    Lam = _blockdiag(Lambda_inv, [3] * N, [3] * N)
    bb = np.concatenate(b)
    K = Lam @ sol.C.T @ sol.Dinv.T
    return np.linalg.solve(np.eye(3 * N) + K @ sol.I, bb - K @ sol.p)


def forward_dynamics_stacked(model: Model, q, qd, tau, f_ext=None, *, method: str = "articulation"):
    """Forward dynamics of a tree in stacked form (thesis 9.39 / 9.48, then 9.43).

    Parameters
    ----------
    model : Model
        A tree (or chain) without contacts.
    q, qd, tau : array_like (..., nq)
        Joint coordinates, velocities and forces.
    f_ext : array_like (..., N, 3), optional
        World wrenches at the origin applied to each body (besides gravity).
    method : {"articulation", "direct"}
        ``"articulation"``: accelerations from the articulation matrix (9.39);
        ``"direct"``: from the articulated mobilities (9.48, corrected).

    Returns
    -------
    qdd : ndarray (..., nq)

    Raises
    ------
    InputError
        For an unknown ``method``.

    Examples
    --------
    >>> from planargeo.mechanics.model import chain_model
    >>> m = chain_model(2, gravity=(0.0, 0.0))
    >>> forward_dynamics_stacked(m, [0.0, 0.0], [0.0, 0.0], [1.0, 0.0]).round(6)
    array([ 1.714286, -4.285714])
    >>> forward_dynamics_stacked(m, [0.0, 0.0], [0.0, 0.0], [1.0, 0.0], method="direct").round(6)
    array([ 1.714286, -4.285714])
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
