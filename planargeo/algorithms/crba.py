"""Dense reference dynamics: ``H(q) q̈ + C(q, q̇) = τ`` with the mass matrix by composite rigid bodies
and the bias by inverse dynamics, solved densely; the reference the recursive algorithms are tested against.
"""
from __future__ import annotations

import numpy as np

from planargeo.algorithms.compiled import check_finite
from planargeo.errors import InputError, SingularConfigurationError
from planargeo.mechanics.kinematics import check_state, kinematics
from planargeo.mechanics.model import Model
from planargeo.algorithms.rnea import newton_euler

__all__ = ["mass_matrix", "bias_forces", "forward_dynamics_crba", "SINGULAR_RCOND"]

#: H is declared singular when its reciprocal condition number is below this
SINGULAR_RCOND = 1e-13


def mass_matrix(model: Model, q, *, method: str = "crba") -> np.ndarray:
    """Joint-space mass matrix ``H(q) = Σ_i J_iᵀ I_i J_i`` (..., nq, nq) (thesis 3.5, 3.10; Remark 8).

    Parameters
    ----------
    model, q : Model, array_like (..., nq)
        The mechanism and its joint coordinates (leading dimensions: a batch).
    method : {"crba", "jacobian"}
        Composite-rigid-body recursion (``H[r, c] = s_rᵀ Ic_{body(c)} s_c``), or the direct sum.

    Returns
    -------
    ndarray (..., nq, nq)

    Raises
    ------
    InputError, NumericOverflowError
        An unknown ``method`` or a bad ``q``, or an ``H`` that is not finite.

    Examples
    --------
    >>> from planargeo.mechanics.model import chain_model
    >>> (mass_matrix(chain_model(2), [0.0, 0.0]) * 6).round(12)     # 8/3, 5/6, 1/3 by hand
    array([[16.,  5.],
           [ 5.,  2.]])
    """
    if method not in ("crba", "jacobian"):
        raise InputError(f"method must be 'crba' or 'jacobian', got {method!r}")
    q, _, _, _, _, shape = check_state(model, q)
    data = kinematics(model, q)
    with np.errstate(over="ignore", invalid="ignore"):     # out of the float range: check_finite says so
        if method == "jacobian":
            J = data.J
            H = np.einsum("...nki,...nkl,...nlj->...ij", J, data.I, J)
        else:
            Ic = data.I.copy()
            for i in range(model.N - 1, -1, -1):       # composite inertias, tip to base
                if model.parents[i] >= 0:
                    Ic[..., model.parents[i], :, :] += Ic[..., i, :, :]
            body = np.repeat(np.arange(model.N), [j.dofs for j in model.joints])   # the body of each coordinate
            path = model.ancestor_mask()[body].T        # path[r, c]: joint of r on the path to body(c)
            F = np.einsum("...cij,...jc->...ic", Ic[..., body, :, :], data.S)   # Ic_{body(c)} s_c
            SF = np.swapaxes(data.S, -1, -2) @ F                               # s_rᵀ Ic_{body(c)} s_c
            H = np.where(path, SF, np.where(path.T, np.swapaxes(SF, -1, -2), 0.0))
    return check_finite(H, "H", q=q)


def bias_forces(model: Model, q, qd, f_ext=None) -> np.ndarray:
    """Bias forces ``C(q, q̇) = τ(q, q̇, q̈ = 0)``: velocity terms, gravity, loads (thesis 3.5, 3.10, 3.11).

    Parameters
    ----------
    model, q, qd, f_ext : Model, array_like
        The mechanism and its state, as for :func:`planargeo.algorithms.aba.forward_dynamics`.

    Returns
    -------
    ndarray (..., nq)
        ``C``, the joint forces that hold the state with ``q̈ = 0``.

    Examples
    --------
    >>> from planargeo.mechanics.model import chain_model
    >>> bias_forces(chain_model(1), [0.0], [0.0])          # a unit rod at rest: m g L / 2
    array([4.905])
    """
    q, qd, _, f_ext, _, shape = check_state(model, q, qd, None, f_ext)
    return newton_euler(model, q, qd, np.zeros(shape + (model.nq,)), f_ext).tau


def forward_dynamics_crba(model: Model, q, qd, tau, f_ext=None) -> np.ndarray:
    """Joint accelerations by the dense solve ``H q̈ = τ - C`` (thesis 3.5, 3.10 in joint space; independent reference).

    Parameters
    ----------
    model, q, qd, tau, f_ext : Model, array_like
        As for :func:`planargeo.algorithms.aba.forward_dynamics`; leading dimensions are a batch.

    Returns
    -------
    ndarray (..., nq)
        ``q̈ = H⁻¹ (τ - C)``.

    Raises
    ------
    NumericOverflowError, SingularConfigurationError
        A result that is not finite, or ``λ_min(H) ≤ SINGULAR_RCOND λ_max(H)`` (a rule of its own:
        it may answer states the joints' rule refuses, ``docs/simulation.md``).

    Examples
    --------
    >>> from planargeo.mechanics.model import chain_model
    >>> forward_dynamics_crba(chain_model(1), [0.0], [0.0], [0.0])     # -1.5 g / L
    array([-14.715])
    """
    q, qd, tau, f_ext, _, shape = check_state(model, q, qd, tau, f_ext)
    H = np.broadcast_to(mass_matrix(model, q), shape + (model.nq, model.nq))
    C = bias_forces(model, q, qd, f_ext)
    with np.errstate(over="ignore", invalid="ignore"):
        rhs = check_finite(np.broadcast_to(tau, shape + (model.nq,)) - C, "τ - C", tau=tau, C=C)
    if model.nq == 0:                      # nothing to solve (and no condition number to take)
        return np.zeros(shape + (0,))
    w = np.linalg.eigvalsh(H)
    lo, hi = w[..., 0], w[..., -1]
    bad = ~(lo > SINGULAR_RCOND * hi)
    if np.any(bad):
        with np.errstate(divide="ignore", invalid="ignore"):
            cond = np.where(lo > 0, hi / np.where(lo > 0, lo, 1.0), np.inf)
        raise SingularConfigurationError("mass matrix H is singular", float(np.max(np.where(bad, cond, 0))))
    with np.errstate(over="ignore", invalid="ignore"):
        qdd = np.linalg.solve(H, rhs[..., None])[..., 0]
    return check_finite(qdd, "q̈", q=q, qd=qd, tau=tau, f_ext=f_ext)
