"""Independent reference for the slider-crank of thesis 9.6 (used by the slider-crank and report tests).

Nothing here calls planargeo.  The mechanism is written out in plain trigonometry:
joint angles ``q = (ψ, θ, φ)`` are relative, the absolute angles are ``α = cumsum(q)``,
and a point ``p = Σ L_k e(α_k)`` with ``e(α) = (cos α, sin α)``:

* crank centre of mass ``c1 = (r/4) e(α1)``, rod ``c2 = r e(α1) + (l/2) e(α2)``,
  piston (and contact point) ``c3 = r e(α1) + l e(α2) + t e(α3)``;
* Jacobians by complex-step differentiation of those positions (exact to rounding);
  the velocity-product terms by hand: ``p̈|_{q̈=0} = -Σ L_k α̇_k² e(α_k)``;
* the joint-space mass matrix ``H = Σ mᵢ Jcᵢᵀ Jcᵢ + Izᵢ Jαᵢᵀ Jαᵢ`` and bias
  ``C = Σ mᵢ Jcᵢᵀ (p̈ᵢ|_{q̈=0} - g)`` (Lagrange; the angular Jacobians are constant),
  or ``H`` and ``C`` from Pinocchio (``pin.crba``, ``pin.rnea``) when asked;
* the loop closure ``φ(q) = (x of the piston point, α3 - π/2) = 0`` with its Jacobian
  ``J_c`` (complex step) and ``J̇_c q̇``, and the multiplier solve::

      [ H  J_cᵀ ] [ q̈ ]   [ τ - C      ]
      [ J_c  0  ] [ ξ  ] = [ -J̇_c q̇   ]

Conventions matched to the thesis (9.59-9.61, 9.81-9.94) — twists ``[vx, vy, ω]`` of the
body point at the global origin, wrenches ``[fx, fy, τ_o]`` at the origin:

* body ``i``'s twist Jacobian ``Jᵢ = [Jp_x + p_y Jα; Jp_y - p_x Jα; Jα]`` for any point ``p``
  of the body, and ``J̇ᵢ q̇ = (p̈_x + ω ṗ_y, p̈_y - ω ṗ_x, 0)`` at ``q̈ = 0``;
* ``Λ₃⁻¹ = J₃ H⁻¹ J₃ᵀ`` (9.81): acceleration of body 3 per unit wrench on it;
* ``u`` (9.82): ``Jᵢ q̈_open + J̇ᵢ q̇`` with ``H q̈_open = τ - C``;
* ``B₃ = [[1, 0], [0, 0], [-h, 1]]`` (9.87: a horizontal unit force through the piston point
  at height ``h``, a unit couple), and ``J_c = B₃ᵀ J₃`` (checked);
* the contact applies ``-F₃ = -B₃ ξ`` to body 3 (9.61 with ``G = [0 0 1]``), so
  ``H q̈ + C = τ - J₃ᵀ B₃ ξ = τ - J_cᵀ ξ``: the multiplier of the solve above *is* ``ξ`` (9.90),
  ``F₃ = B₃ ξ`` (9.92), ``a₃ = J₃ q̈ + J̇₃ q̇`` (9.94);
* a crank driven at constant speed adds the row ``ψ̈ = 0`` with multiplier ``μ``; the drive
  torque is ``-μ`` (``tau_drive[0]``).
"""
from __future__ import annotations

import numpy as np

M = (0.40, 0.15, 0.30)
R, L, T = 2.29, 5.00, 0.5


def _e(a):
    return np.array([np.cos(a), np.sin(a)])


def _segments(r, l, t):
    """Each point as a list of (length, index of the absolute angle)."""
    return {"c1": [(r / 4, 0)], "c2": [(r, 0), (l / 2, 1)], "c3": [(r, 0), (l, 1), (t, 2)]}


def _point(segs, q):
    a = np.cumsum(q)
    return sum(Lk * _e(a[k]) for Lk, k in segs)


def _point_bias(segs, q, qd):
    """p̈ at q̈ = 0: -Σ L_k α̇_k² e(α_k)."""
    a, w = np.cumsum(q), np.cumsum(qd)
    return sum(-Lk * w[k] ** 2 * _e(a[k]) for Lk, k in segs)


def complex_step_jacobian(f, q, h=1e-30):
    """``∂f/∂q`` by complex steps (no subtractive cancellation)."""
    q = np.asarray(q, dtype=float)
    cols = []
    for k in range(len(q)):
        dq = np.zeros(len(q), dtype=complex)
        dq[k] = 1j * h
        cols.append(np.imag(np.asarray(f(q + dq))) / h)
    return np.stack(cols, axis=-1)


def closed_state(psi, psidot, r=R, l=L):
    """Joint coordinates and rates on the loop, piston above the crank pivot (Fig 9.3)."""
    beta = np.arccos(-r * np.cos(psi) / l)                # ψ + θ
    q = np.array([psi, beta - psi, np.pi / 2 - beta])
    wrod = -r * np.sin(psi) * psidot / (l * np.sin(beta))  # ψ̇ + θ̇ from d/dt (r cos ψ + l cos β) = 0
    return q, np.array([psidot, wrod - psidot, -wrod])


def pinocchio_model(m=M, r=R, l=L, t=T, g=9.81):
    """The same chain in Pinocchio (JointModelRZ, inertia about the centre of mass)."""
    import pinocchio as pin

    pm = pin.Model()
    parent = 0
    for x, mi, c, Iz in ((0.0, m[0], r / 4, 0.1464 * m[0] * r ** 2), (r, m[1], l / 2, 0.0866 * m[1] * l ** 2),
                         (l, m[2], t, 0.666 * m[2] * t ** 2)):
        parent = pm.addJoint(parent, pin.JointModelRZ(), pin.SE3(np.eye(3), np.array([x, 0.0, 0.0])), "j")
        pm.appendBodyToJoint(parent, pin.Inertia(mi, np.array([c, 0.0, 0.0]), np.diag([1.0, 1.0, Iz])),
                             pin.SE3.Identity())
    pm.gravity = pin.Motion(np.array([0.0, -g, 0.0, 0.0, 0.0, 0.0]))
    return pm


def mass_matrix_and_bias(q, qd, m=M, r=R, l=L, t=T, g=9.81, method="hand"):
    """``(H, C)`` with ``H q̈ + C = τ``: by hand (Lagrange in plain trigonometry) or from Pinocchio."""
    q, qd = np.asarray(q, dtype=float), np.asarray(qd, dtype=float)
    if method == "pinocchio":
        import pinocchio as pin

        pm = pinocchio_model(m, r, l, t, g)
        H = pin.crba(pm, pm.createData(), q).copy()
        H = np.triu(H) + np.triu(H, 1).T
        C = pin.rnea(pm, pm.createData(), q, qd, np.zeros(3)).copy()
        return H, C
    if method != "hand":
        raise ValueError(method)
    Iz = (0.1464 * m[0] * r ** 2, 0.0866 * m[1] * l ** 2, 0.666 * m[2] * t ** 2)
    segs = _segments(r, l, t)
    H = np.zeros((3, 3))
    C = np.zeros(3)
    gvec = np.array([0.0, -g])
    for i, key in enumerate(("c1", "c2", "c3")):
        Jc = complex_step_jacobian(lambda x: _point(segs[key], x), q)
        Ja = np.array([1.0 if k <= i else 0.0 for k in range(3)])
        H += m[i] * Jc.T @ Jc + Iz[i] * np.outer(Ja, Ja)
        C += m[i] * Jc.T @ (_point_bias(segs[key], q, qd) - gvec)
    return H, C


def body_twist_jacobian(i, q, qd, r=R, l=L, t=T):
    """``(J_i, J̇_i q̇)`` of body ``i`` (0, 1, 2): twist ``[vx, vy, ω]`` of its point at the origin."""
    segs = _segments(r, l, t)[("c1", "c2", "c3")[i]]
    p = _point(segs, q)
    Jp = complex_step_jacobian(lambda x: _point(segs, x), q)
    Ja = np.array([1.0 if k <= i else 0.0 for k in range(3)])
    J = np.vstack([Jp[0] + p[1] * Ja, Jp[1] - p[0] * Ja, Ja])
    pd, w, b = Jp @ qd, Ja @ qd, _point_bias(segs, q, qd)
    return J, np.array([b[0] + w * pd[1], b[1] - w * pd[0], 0.0])


def closure(q, r=R, l=L, t=T):
    """Loop-closure position residual: x of the piston point, piston angle - π/2 (zero on the loop)."""
    c3 = _point(_segments(r, l, t)["c3"], q)
    return np.array([c3[0], np.sum(q) - np.pi / 2])


def reference(psi, psidot, *, m=M, r=R, l=L, t=T, g=9.81, drive="free", method="hand"):
    """All the 9.6 quantities of the scene, from the multiplier solve (module docstring)."""
    q, qd = closed_state(psi, psidot, r, l)
    H, C = mass_matrix_and_bias(q, qd, m, r, l, t, g, method)
    tau = np.zeros(3)
    Js = [body_twist_jacobian(i, q, qd, r, l, t) for i in range(3)]
    J3, J3dqd = Js[2]
    h = _point(_segments(r, l, t)["c3"], q)[1]
    B3 = np.array([[1.0, 0.0], [0.0, 0.0], [-h, 1.0]])
    Jc = complex_step_jacobian(lambda x: closure(x, r, l, t), q)
    Jcdqd = np.array([_point_bias(_segments(r, l, t)["c3"], q, qd)[0], 0.0])
    rows = [Jc]
    rhs_c = [-Jcdqd]
    if drive == "constant-speed":
        rows.append(np.array([[1.0, 0.0, 0.0]]))
        rhs_c.append([0.0])
    A = np.vstack(rows)
    k = A.shape[0]
    K = np.block([[H, A.T], [A, np.zeros((k, k))]])
    sol = np.linalg.solve(K, np.concatenate([tau - C, *rhs_c]))
    qdd, lam = sol[:3], sol[3:]
    xi = lam[:2]
    tau_drive = tau.copy()
    if drive == "constant-speed":
        tau_drive[0] -= lam[2]
    qdd_open = np.linalg.solve(H, tau - C)
    u = np.array([J @ qdd_open + Jdqd for J, Jdqd in Js])
    a = np.array([J @ qdd + Jdqd for J, Jdqd in Js])
    return dict(q=q, qd=qd, v=np.array([J @ qd for J, _ in Js]), H=H, C=C, J3=J3, Jc=Jc, B3=B3, h=h,
                Lambda3_inv=J3 @ np.linalg.solve(H, J3.T), u=u, xi=xi, F3=B3 @ xi, a=a, a3=a[2], qdd=qdd,
                qdd_open=qdd_open, tau_drive=tau_drive)


def contact_matrix_cond(q, m=M, r=R, l=L, t=T, drive="free"):
    """``cond(J_c H⁻¹ J_cᵀ)`` at any ``q``: the reference's ``B₃ᵀ Λ₃⁻¹ B₃`` (9.70), singular at the folded
    dead centre.  A constant-speed crank adds its drive row ``ψ̇`` (the drive's ``B = s (sᵀs)⁻¹``, ``s = [0, 0, 1]``)."""
    H, _ = mass_matrix_and_bias(q, np.zeros(3), m, r, l, t, 0.0)
    Jc = complex_step_jacobian(lambda x: closure(x, r, l, t), q)
    if drive == "constant-speed":
        Jc = np.vstack([Jc, [1.0, 0.0, 0.0]])
    return float(np.linalg.cond(Jc @ np.linalg.solve(H, Jc.T)))
