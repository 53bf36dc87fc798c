"""Closed loops and contacts in stacked form (thesis 9.3-9.5).

The tree is cut open at its contacts, solved as an open tree, and the contact forces that close
the loops are added (9.49-9.75).  ``Λ^{-1}`` there is the tree's full stacked mobility, not the
block diagonal of 7.37 (``docs/errata.md``).  :func:`constrained_dynamics_lagrange` is the
independent reference in maximal coordinates.
"""
from __future__ import annotations

import functools
from dataclasses import dataclass

import numpy as np

from planargeo.mechanics.contacts import contact_matrix, stacked_contact_spaces, validate_contacts, world_point
from planargeo.errors import InputError, ShapeError, SingularConfigurationError
from planargeo.mechanics.kinematics import kinematics
from planargeo.mechanics.model import Model
from planargeo.algorithms.articulated_inertia import _one_state, _per_state
from planargeo.algorithms.stacked import _blockdiag, adjacency, blocks, stacked_solve, trunk

__all__ = ["LoopSolution", "Reaction", "loop_solve", "joint_wrenches", "loop_condition", "forward_dynamics_loops", "constrained_dynamics_lagrange",
           "branch_matrix", "SINGULAR_COND"]

#: ``B^T G Λ^{-1} G^T B`` is declared singular above this condition number.
SINGULAR_COND = 1e10


def branch_matrix(G, parents) -> np.ndarray:
    """Branch matrix ``Υ = G Δ^{-1}`` (thesis 9.50, 9.51): each loop's two branches from their common ancestor.

    Parameters
    ----------
    G : array_like (m, N)
        Contact matrix (9.49): ``+1`` on body ``a``, ``-1`` on body ``b`` of each contact.
    parents : sequence of int (N,)
        Parent of each body (-1: the ground).

    Returns
    -------
    ndarray (m, N)

    Examples
    --------
    >>> G = np.zeros((2, 9)); G[0, 3], G[0, 6], G[1, 7], G[1, 8] = 1, -1, 1, -1     # 9.49
    >>> branch_matrix(G, [-1, 0, 1, 2, 0, 4, 5, 5, 0]).astype(int)                  # 9.51
    array([[ 0,  1,  1,  1, -1, -1, -1,  0,  0],
           [ 0,  0,  0,  0,  1,  1,  0,  1, -1]])
    """
    return np.asarray(G, dtype=float) @ trunk(adjacency(parents))


class LoopSolution:
    """All quantities of one constrained state (thesis 9.49-9.75; attributes named after the symbols).

    ``xi`` are the contact forces' components in the contact reaction spaces ``B``
    (:func:`planargeo.mechanics.contacts.B_of`, ``F = B ξ``); a slider's normal is turned by -90° as in
    the thesis's 9.87 (a joint's by +90°, 5.63), so ``xi`` compares with 9.90.

    Attributes
    ----------
    tree : StackedSolution (the open tree; ``tree.a`` is ``u``, 9.63)
    G, Upsilon, G3, z, B : contact and branch matrices (``G3`` in 3×3 blocks), contact motion / reaction spaces
    Lambda_inv, Lambda_inv_Gt, contact_mobility : ``Λ^{-1}`` (9.65-9.73), ``Λ^{-1} G^T``, ``G Λ^{-1} G^T``
    J, theta_dot, nu, K, cond : ``Υ I Υ^T`` (9.57), contact rates (9.58), ``ν`` (9.55), ``B^T G Λ^{-1} G^T B``
    Gamma, xi, F : (9.72), reaction magnitudes in ``B`` (9.70), contact forces (9.71)
    u, a, qdd, tau_drive : open and closed-loop accelerations (9.73, 9.75), torques with the drives
    f, Q, mu : joint wrenches from ``Δᵀ f = I a + p + Gᵀ F`` (9.61), ``s_iᵀ f_i`` (6.38), ``U_iᵀ f_i`` (6.61b, 6.104)
    reactions : list of :class:`Reaction`, one per tree joint then one per contact

    Examples
    --------
    >>> from planargeo.mechanics.contacts import Contact
    >>> from planargeo.mechanics.model import Body, Joint, Model
    >>> m = Model([Body(2.0, (0.0, 0.0), 0.5)], [Joint("plane")], [-1])
    >>> pin = Contact("pin", 0, -1, point_a=(0.0, 0.0), point_b=(3.0, 1.0))     # at its centre
    >>> loop_solve(m, [3.0, 1.0, 0.0], [0.0] * 3, [0.0] * 3, contacts=[pin]).xi.round(9) + 0.0
    array([ 0.  , -19.62])
    """

    def __repr__(self):
        return f"LoopSolution(N={self.tree.N}, contacts={self.G.shape[0]}, cond={self.cond:.3g})"

    @functools.cached_property
    def mu(self) -> np.ndarray:
        """Reaction magnitudes ``μ_i = U_iᵀ f_i`` (6.61b) of every joint in its basis ``R_i``, built on first access."""
        return self.tree.U.T @ self.f

    @functools.cached_property
    def reactions(self) -> list:
        """Every pin and bearing force of the loop, a :class:`Reaction` per tree joint then per contact."""
        pose = self.data.pose                           # tree joints (f_i), then contacts (-F_k on body a)
        return _joint_reactions(self._model, pose, self.f) + [
            _reaction(f"F_{k + 1}", c.name, c.kind, c.a, c.b,
                      np.asarray(world_point(pose, c.a, c.point_a), dtype=float), -w)
            for k, (c, w) in enumerate(zip(self.contacts, self.F.reshape(-1, 3)))]

    def reaction(self, name: str) -> "Reaction":
        """The :class:`Reaction` named ``name`` (a joint's or contact's name, or its symbol ``f_1``, ``F_1``).

        Parameters
        ----------
        name : str
            A joint or contact name of the model, or a symbol of :attr:`reactions`.

        Returns
        -------
        Reaction

        Raises
        ------
        InputError
            If no reaction has that name or symbol.
        """
        for r in self.reactions:
            if name in (r.name, r.symbol):
                return r
        raise InputError(f"name must be a joint or contact name or a symbol of the loop's reactions "
                         f"({', '.join(r.symbol for r in self.reactions)}), got {name!r}")

    @property
    def Lambda_inv(self) -> np.ndarray:
        """The tree's full stacked mobility ``Λ^{-1}`` (3N×3N) of 9.65-9.73, built on first access."""
        return self.tree.mobility


@dataclass(frozen=True)
class Reaction:
    """One pin or bearing force of a closed loop (thesis 9.61 for the joints, 9.59/9.71 for the contacts).

    Attributes
    ----------
    symbol, name, kind : str
        ``"f_i"`` (tree joint ``i``, 1-based) or ``"F_k"`` (contact ``k``); its name in the model; its kind.
    body, other : int
        The body the wrench acts on and the body that exerts it (0-based; -1 the ground).
    point, wrench : ndarray (2,), (3,)
        Where it acts (the joint, or the contact point on body ``a``), and ``[fx, fy, τ_o]`` acting **on**
        ``body``, moment about the origin: ``f_i``, or ``-F_k`` (9.61).
    moment : float
        Moment of ``wrench`` about ``point``: a drive torque, zero for a free pin, a slider's couple.
    """

    symbol: str
    name: str
    kind: str
    body: int
    other: int
    point: np.ndarray
    wrench: np.ndarray
    moment: float

    @property
    def force(self) -> float:
        """Magnitude ``|(fx, fy)|`` of the force (N)."""
        return float(np.hypot(self.wrench[0], self.wrench[1]))


def _reaction(symbol, name, kind, body, other, P, w) -> Reaction:
    """The :class:`Reaction` of the wrench ``w`` on ``body`` acting at ``P``, its moment about ``P`` last."""
    return Reaction(symbol, name, kind, body, other, P, w, float(w[2] + P[1] * w[0] - P[0] * w[1]))


def _joint_reactions(model, pose, f) -> list:
    """A :class:`Reaction` per tree joint: ``f_i`` (stacked ``f``) on body ``i`` from its parent (9.61, 9.41)."""
    return [_reaction(f"f_{i + 1}", jt.name, jt.kind, i, model.parents[i], pose[i, :2].astype(float),
                      w.copy()) for i, (jt, w) in enumerate(zip(model.joints, np.reshape(f, (model.N, 3))))]


def joint_wrenches(parents, I, a, p, GtF=None) -> np.ndarray:
    """Joint wrenches from ``Δᵀ f = I a + p + Gᵀ F`` (thesis 9.61; 9.14 without contacts), by one inward sweep.

    Parameters
    ----------
    parents : sequence of int (N,)
        Parent of each body (-1: the ground), parents before children.
    I, a, p : array_like (3N, 3N), (3N,), (3N,)
        Stacked body inertias, accelerations and bias forces (3.11, 3.34).
    GtF : array_like (3N,), optional
        ``Gᵀ F``, the net contact wrenches of 9.61.

    Returns
    -------
    ndarray (3N,)
        ``f_i``: the wrench (at the origin) the parent exerts on body ``i`` through joint ``i``.

    Raises
    ------
    ShapeError
        If the sizes do not agree with ``parents``.

    Examples
    --------
    >>> joint_wrenches([-1, 0], np.eye(6), np.zeros(6), np.array([0.0, 1.0, 0.0, 0.0, 2.0, 0.0]))
    array([0., 3., 0., 0., 2., 0.])
    """
    N = len(parents)
    I = np.asarray(I, dtype=float)
    a, p = np.asarray(a, dtype=float), np.asarray(p, dtype=float)
    if I.shape != (3 * N, 3 * N) or a.shape != (3 * N,) or p.shape != (3 * N,):
        raise ShapeError(f"I, a and p must have shapes ({3 * N}, {3 * N}), ({3 * N},), ({3 * N},) for "
                         f"{N} bodies, got {I.shape}, {a.shape}, {p.shape}")
    rhs = I @ a + p
    if GtF is not None:
        GtF = np.asarray(GtF, dtype=float)
        if GtF.shape != (3 * N,):
            raise ShapeError(f"GtF must have shape ({3 * N},), got {GtF.shape}")
        rhs = rhs + GtF
    f = rhs.reshape(N, 3).copy()
    for i in range(N - 1, -1, -1):               # children before parents
        j = parents[i]
        if j >= 0:
            f[j] += f[i]
    return f.reshape(-1)


@functools.lru_cache(maxsize=256)
def _contact_topology(parents: tuple, contacts: tuple):
    """Cached ``G``, ``Υ`` and their 3×3 block forms for a tree and its contacts."""
    N = len(parents)
    G = contact_matrix(contacts, N)
    Ups = branch_matrix(G, parents) if len(contacts) else np.zeros((0, N))
    out = (G, Ups, blocks(G), blocks(Ups))
    for x in out:
        x.setflags(write=False)
    return out


def loop_solve(model: Model, q, qd, tau, f_ext=None, contacts=None, *, prescribed=None,
               mobility: str = "columns") -> LoopSolution:
    """Constrained projective dynamics algorithm, one state (thesis 9.5).

    Parameters
    ----------
    model, q, qd, tau, f_ext : Model, array_like
        The spanning tree and one state satisfying the loop closures (velocities included).
    contacts : sequence of Contact, optional
        The loop closures (default ``model.contacts``).
    prescribed : dict {joint index: qdd value(s)}, optional
        Drives (e.g. a crank at constant speed, ``{0: 0.0}``), each one more contact with
        ``B = s (s^T s)^{-1}``, ``ν = κ_i + s q̈``; their torques in ``tau_drive``, their ``qdd`` exact.
    mobility : {"columns", "full"}
        Form only the columns ``Λ^{-1} G^T`` by two triangular solves, or the full ``Λ^{-1}`` (a check).

    Returns
    -------
    LoopSolution

    Raises
    ------
    InputError, SingularConfigurationError
        A bad ``mobility`` or ``prescribed``; a singular ``B^T G Λ^{-1} G^T B`` (redundant or locked loops, ``.cond``).

    Examples
    --------
    >>> from planargeo.mechanics.contacts import Contact
    >>> from planargeo.mechanics.model import chain_model
    >>> pin = Contact("pin", 2, -1, point_a=(1.0, 0.0), point_b=(1.0, 0.0))    # φ̈ = -6/5 g cos φ
    >>> sol = loop_solve(chain_model(3), [1.2, -1.2, 1.2 - np.pi], [1.0, -1.0, 1.0], [0.0] * 3, contacts=[pin])
    >>> bool(abs(sol.qdd[0] - (-6 / 5 * 9.81 * np.cos(1.2))) < 1e-12)
    True
    """
    if mobility not in ("columns", "full"):
        raise InputError(f"mobility must be 'columns' or 'full', got {mobility!r}")
    q, qd, tau, f_ext = _one_state(model, q, qd, tau, f_ext, "loop_solve")
    cs = validate_contacts(model.contacts if contacts is None else contacts, model.N)
    data = kinematics(model, q, qd, f_ext)
    tree = stacked_solve(model, q, qd, tau, f_ext, data=data)
    N = model.N
    sol = LoopSolution()
    sol.tree, sol.contacts, sol.data, sol._model = tree, cs, data, model
    # 1. preparatory work; 2. the open-loop accelerations u = tree.a (9.63)
    G, sol.Upsilon, G3, U3 = _contact_topology(tuple(model.parents), tuple(cs))
    z, B = stacked_contact_spaces(cs, data.pose)
    sol.G, sol.G3, sol.z, sol.B, sol.u = G, G3, z, B, tree.a
    # 3. kinematics of the contacts (9.57, 9.58, 9.55)
    sol.J = J = U3 @ tree.I @ U3.T
    Gv = G3 @ data.v.reshape(-1)
    theta_dot = np.zeros(0)
    if z.shape[1]:
        try:
            theta_dot = np.linalg.solve(z.T @ J @ z, z.T @ J @ Gv)
        except np.linalg.LinAlgError:
            theta_dot = np.linalg.lstsq(z, Gv, rcond=None)[0]
    sol.theta_dot = theta_dot
    zt = z @ theta_dot
    sol.nu = nu = np.zeros(3 * len(cs))
    for k, c in enumerate(cs):
        va, w = data.v[c.a], zt[3 * k:3 * k + 3]
        nu[3 * k:3 * k + 3] = [-va[2] * w[1] + va[1] * w[2], va[2] * w[0] - va[0] * w[2], 0.0]
    # drives: one more contact each, between the body and its parent
    G_rows, B_blocks, nu_rows, drive_cols = [G3], [B], [nu], []
    for i, val in dict(prescribed or {}).items():
        if not (isinstance(i, (int, np.integer)) and 0 <= i < N):
            raise InputError(f"prescribed keys must be joint indices in 0..{N - 1}, got {i!r}")
        si = data.s(i)
        k = si.shape[1]
        if k == 0:
            raise InputError(f"prescribed joint {i} is fixed (no coordinate to drive)")
        val = np.broadcast_to(np.asarray(val, dtype=float), (k,))
        row = np.zeros((3, 3 * N))
        row[:, 3 * i:3 * i + 3] = np.eye(3)
        j = model.parents[i]
        if j >= 0:
            row[:, 3 * j:3 * j + 3] = -np.eye(3)
        G_rows.append(row)
        B_blocks.append(si @ np.linalg.inv(si.T @ si))
        nu_rows.append(data.kappa[i] + si @ val)
        drive_cols.append((i, k, val))
    Gall = np.vstack(G_rows)
    Ball = _blockdiag(B_blocks)
    # 4. contact forces (9.70-9.72): Λ^{-1} is read only as Λ^{-1} G^T
    LamGt = tree.mobility @ Gall.T if mobility == "full" else tree.mobility_times(Gall.T)
    ncr = G3.shape[0]
    sol.Lambda_inv_Gt = LamGt[:, :ncr]
    GLG = Gall @ LamGt
    GLG = 0.5 * (GLG + GLG.T)                      # symmetric in exact arithmetic
    sol.contact_mobility = GLG[:ncr, :ncr]
    sol.K = K = Ball.T @ GLG @ Ball
    sol.cond, Kinv = 1.0, K
    if K.size:
        sol.cond = cond = float(np.linalg.cond(K))
        if not np.isfinite(cond) or cond > SINGULAR_COND:
            raise SingularConfigurationError(
                "B^T G Λ^-1 G^T B is singular: the loop closures are redundant or locked "
                "(e.g. a slider-crank with its piston pin on the crank pivot)", cond)
        Kinv = np.linalg.inv(K)
    sol.Gamma = Gamma = Ball @ Kinv @ Ball.T
    rhs = Gall @ tree.a - np.concatenate(nu_rows)
    xi_all = Kinv @ Ball.T @ rhs
    Fall = Gamma @ rhs
    off = B.shape[1]
    sol.xi, sol.F = xi_all[:off], Fall[:3 * len(cs)]
    # 5. closed-loop accelerations (9.73, 9.75)
    sol.a = a = tree.a - LamGt @ Fall
    sol.qdd = tree.T.T @ (a - tree.C @ a - tree.kappa)
    sol.tau_drive = np.array(tau, dtype=float)
    for i, k, val in drive_cols:
        sol.tau_drive[model.q_slice(i)] -= xi_all[off:off + k]
        # a driven coordinate's acceleration is the drive's exactly (the solve gives it to rounding)
        sol.qdd[model.q_slice(i)] = val
        off += k
    # 6. every pin and bearing force of the loop (9.61): Δᵀ f = I a + p + Gᵀ F, solved for f
    sol.f = joint_wrenches(model.parents, tree.I, a, tree.p, G3.T @ sol.F)
    sol.Q = tree.S.T @ sol.f
    return sol


def loop_condition(model: Model, q, contacts=None, *, prescribed=None) -> float:
    """Condition number of ``B^T G Λ^{-1} G^T B`` at ``q`` (thesis 9.70-9.72), without raising (``inf``: singular).

    Parameters
    ----------
    model, q : Model, array_like (nq,)
        The spanning tree and its joint coordinates.
    contacts, prescribed : optional
        As in :func:`loop_solve`.

    Returns
    -------
    float

    Examples
    --------
    >>> from planargeo.scenes.slider_crank import slider_crank_model, slider_crank_state
    >>> round(loop_condition(slider_crank_model(), slider_crank_state()[0]), 3)
    5.905
    """
    nq = model.nq
    try:
        return float(loop_solve(model, q, np.zeros(nq), np.zeros(nq), None, contacts, prescribed=prescribed).cond)
    except SingularConfigurationError as exc:
        return exc.cond


def forward_dynamics_loops(model: Model, q, qd, tau, f_ext=None, contacts=None, *, prescribed=None):
    """Joint accelerations ``q̈`` of a closed-loop mechanism (thesis 9.5, 9.75), batches over leading dimensions.

    Parameters
    ----------
    model, q, qd, tau, f_ext : Model, array_like
        The spanning tree and its states, as for :func:`planargeo.algorithms.aba.forward_dynamics`.
    contacts, prescribed : optional
        As in :func:`loop_solve`.

    Returns
    -------
    ndarray (..., nq)

    Examples
    --------
    >>> from planargeo.mechanics.model import chain_model
    >>> forward_dynamics_loops(chain_model(1), [0.0], [0.0], [0.0]).round(3)    # no contacts: a tree
    array([-14.715])
    """
    return _per_state(lambda m, *state: loop_solve(m, *state, contacts, prescribed=prescribed).qdd,
                      model, q, qd, tau, f_ext)


# -- independent reference: maximal coordinates + Lagrange multipliers ----------------------------
#: Each joint kind's constraints in the reference: its point on the parent's (``"on"``) or on a line
#: through it (``"line"``), and whether the angle is kept.
_JOINT_CONSTRAINTS = {"revolute": ("on", False), "prismatic": ("line", True),
                      "revolute_prismatic": ("line", False), "twin_prismatic": (None, True),
                      "fixed": ("on", True), "plane": (None, False)}


def _perp(v):
    return np.array([-v[1], v[0]])


def _rot(th):
    c, s = np.cos(th), np.sin(th)
    return np.array([[c, -s], [s, c]])


def constrained_dynamics_lagrange(model: Model, q, qd, tau, f_ext=None, contacts=None, *, prescribed=None):
    """Independent reference: Lagrange multipliers in maximal coordinates, solved densely (reference for 9.73, 9.75).

    Each body has coordinates ``(c_x, c_y, θ)`` and mass ``diag(m, m, J)``; joints and contacts are
    position constraints with analytic Jacobians ``Φ`` and ``γ = Φ̇ ẋ``, and
    ``[[M, -Φ^T], [Φ, 0]] [ẍ, λ] = [F_applied, -γ]`` is solved densely.  Only the poses and velocities
    of :func:`planargeo.mechanics.kinematics.kinematics` are shared with the stacked code.

    Parameters
    ----------
    model, q, qd, tau, f_ext : Model, array_like
        The spanning tree and one state.
    contacts, prescribed : optional
        As in :func:`loop_solve` (drives of revolute joints only).

    Returns
    -------
    dict
        ``a`` (N, 3), ``qdd`` (least squares from ``Δ a - κ = S q̈``), ``F`` (m, 3) (``-F`` acts on body
        ``a``), ``tau_drive``, ``lambda``, ``Phi`` and ``n_tree_constraints`` (its first rows).

    Raises
    ------
    ShapeError, InputError
        For a batch of states, or a prescribed joint that is not revolute.

    Examples
    --------
    >>> from planargeo.mechanics.contacts import Contact
    >>> from planargeo.mechanics.model import chain_model
    >>> pin = Contact("pin", 2, -1, point_a=(1.0, 0.0), point_b=(1.0, 0.0))    # loop_solve's four-bar
    >>> ref = constrained_dynamics_lagrange(chain_model(3), [1.2, -1.2, 1.2 - np.pi], [1.0, -1.0, 1.0],
    ...                                     [0.0] * 3, contacts=[pin])
    >>> bool(abs(ref["qdd"][0] - (-6 / 5 * 9.81 * np.cos(1.2))) < 1e-10)
    True
    """
    q, qd, tau, f_ext = _one_state(model, q, qd, tau, f_ext, "constrained_dynamics_lagrange")
    N = model.N
    cs = validate_contacts(model.contacts if contacts is None else contacts, N)
    data = kinematics(model, q, qd, None)
    arr = model.arrays()
    m_, J_, com_b = arr["mass"], arr["J"], arr["com"]
    c, th, w = data.com.copy(), data.pose[:, 2], data.v[:, 2]     # centres of mass, angles, spins
    cd = np.stack([data.v[:, 0] - w * c[:, 1], data.v[:, 1] + w * c[:, 0]], -1)
    n = 3 * N
    Mdiag = np.concatenate([[m_[i], m_[i], J_[i]] for i in range(N)])
    Fapp = np.zeros(n)
    gx, gy = model.gravity

    def add_wrench(i, wr):            # wrench at the origin applied to body i
        if i < 0:
            return
        fx, fy, tz = wr
        Fapp[3 * i] += fx
        Fapp[3 * i + 1] += fy
        Fapp[3 * i + 2] += tz - (c[i, 0] * fy - c[i, 1] * fx)

    for i in range(N):
        add_wrench(i, (m_[i] * gx, m_[i] * gy, m_[i] * (c[i, 0] * gy - c[i, 1] * gx)))
        if f_ext is not None:
            add_wrench(i, f_ext[i])
        si = data.s(i)
        if si.shape[1]:
            wr = si @ np.linalg.solve(si.T @ si, tau[model.q_slice(i)])
            add_wrench(i, wr)
            add_wrench(model.parents[i], -wr)

    rows, gam = [], []

    def point_terms(i, r_body):
        """Jacobian (2, n), position, velocity, and quadratic acceleration term of a point."""
        Jp = np.zeros((2, n))
        if i < 0:
            return Jp, np.asarray(r_body, dtype=float), np.zeros(2), np.zeros(2)
        rho = _rot(th[i]) @ (np.asarray(r_body, dtype=float) - com_b[i])    # from the com
        Jp[:, 3 * i:3 * i + 2] = np.eye(2)
        Jp[:, 3 * i + 2] = _perp(rho)
        return Jp, c[i] + rho, cd[i] + w[i] * _perp(rho), -w[i] ** 2 * rho

    def coincide(i, ri, j, rj):
        Ji, Pi, Vi, Qi = point_terms(i, ri)
        Jj, Pj, Vj, Qj = point_terms(j, rj)
        rows.append(Ji - Jj)
        gam.extend(Qi - Qj)

    def on_line(i, ri, j, rj, nj):
        """n·(P_i - P_j) = 0 with n = R(θ_j) nj turning with body j."""
        Ji, Pi, Vi, Qi = point_terms(i, ri)
        Jj, Pj, Vj, Qj = point_terms(j, rj)
        nw = nj if j < 0 else _rot(th[j]) @ nj
        e, ed = Pi - Pj, Vi - Vj
        row = nw @ (Ji - Jj)
        wj = 0.0 if j < 0 else w[j]
        if j >= 0:
            row[3 * j + 2] += _perp(nw) @ e
        rows.append(row)
        gam.append(nw @ (Qi - Qj) - wj ** 2 * (nw @ e) + 2 * wj * (_perp(nw) @ ed))

    def same_angle(i, j, g=0.0):      # θ_i - θ_j = const (g: a drive's -q̈)
        row = np.zeros(n)
        row[3 * i + 2] = 1.0
        if j >= 0:
            row[3 * j + 2] = -1.0
        rows.append(row)
        gam.append(g)

    for i, (jt, par) in enumerate(zip(model.joints, model.parents)):
        px, py, ph = jt.placement
        point, angle = _JOINT_CONSTRAINTS[jt.kind]
        if point == "on":
            coincide(i, (0.0, 0.0), par, (px, py))
        elif point == "line":                           # along the joint frame's x axis
            on_line(i, (0.0, 0.0), par, (px, py), np.array([-np.sin(ph), np.cos(ph)]))
        if angle:
            same_angle(i, par)
    ncons_tree = len(gam)
    contact_rows = []
    for ct in cs:
        start = len(gam)
        if ct.kind in ("pin", "weld"):
            coincide(ct.a, ct.point_a, ct.b, ct.point_b)
        if ct.kind == "slider":
            d = np.asarray(ct.direction)
            on_line(ct.a, ct.point_a, ct.b, ct.point_b, np.array([d[1], -d[0]]))
        if ct.kind in ("slider", "weld"):
            same_angle(ct.a, ct.b)
        contact_rows.append((start, len(gam)))
    drive_rows = []
    for i, val in dict(prescribed or {}).items():      # a_i - a_λ - κ_i along s_i prescribed
        val = np.broadcast_to(np.asarray(val, dtype=float), (data.s(i).shape[1],))
        if model.joints[i].kind != "revolute":
            raise InputError("the reference supports prescribed revolute joints only")
        drive_rows.append((i, len(gam)))
        same_angle(i, model.parents[i], -val[0])
    Phi = np.vstack(rows) if rows else np.zeros((0, n))
    KKT = np.block([[np.diag(Mdiag), -Phi.T], [Phi, np.zeros((len(gam), len(gam)))]])
    rhs = np.concatenate([Fapp, -np.array(gam, dtype=float)])
    sol = np.linalg.lstsq(KKT, rhs, rcond=None)[0] if np.linalg.cond(KKT) > 1e14 else np.linalg.solve(KKT, rhs)
    cdd, lam = sol[:n].reshape(N, 3), sol[n:]
    wd = cdd[:, 2]
    a = np.stack([cdd[:, 0] + wd * c[:, 1] + w * cd[:, 1],
                  cdd[:, 1] - wd * c[:, 0] - w * cd[:, 0], wd], -1)
    # contact wrenches: Φ_c^T λ_c restricted to body a, as a wrench at the origin; thesis F = -that
    F = np.zeros((len(cs), 3))
    for k, (ct, (s0, s1)) in enumerate(zip(cs, contact_rows)):
        fx, fy, mc = (Phi[s0:s1].T @ lam[s0:s1])[3 * ct.a:3 * ct.a + 3]
        F[k] = -np.array([fx, fy, mc + c[ct.a, 0] * fy - c[ct.a, 1] * fx])
    # joint accelerations from Δ a - κ = S q̈
    C3 = blocks(adjacency(model.parents))
    rel = a.reshape(-1) - C3 @ a.reshape(-1) - data.kappa.reshape(-1)
    qdd = np.linalg.lstsq(_blockdiag([data.s(i) for i in range(N)]), rel, rcond=None)[0]
    tau_drive = np.array(tau, dtype=float)
    for i, s0 in drive_rows:
        tau_drive[model.q_slice(i)] += lam[s0]
    return {"a": a, "qdd": qdd, "F": F, "tau_drive": tau_drive, "lambda": lam, "Phi": Phi,
            "n_tree_constraints": ncons_tree}
