"""Scenes "tree" (thesis Fig 9.1) and "constrained-tree" (Fig 9.2).

Nine uniform links (``J = m L²/12``) on revolute joints at their parents' tips: body 1 pinned at
the origin, branches 2-3-4 and 5-6-7 and body 9 from its tip, body 8 from body 6.  In the default
pose the tips of bodies 4 and 7 meet, and so do those of 8 and 9; the constrained tree pins them
there (``G`` of 9.49), leaving 9 - 2·2 = 5 degrees of freedom.

Examples
--------
>>> ct = constrained_tree()
>>> np.array(ct.quantities["G"]).astype(int)[0]
array([ 0,  0,  0,  1,  0,  0, -1,  0,  0])
"""
from __future__ import annotations

import math

import numpy as np

from planargeo.errors import PlanargeoError, SceneError
from planargeo.scenes import SceneResult, check_param, plain, register

__all__ = ["tree", "constrained_tree", "tree_model", "tree_solve", "tree_dof", "tree_pose", "tree_advance",
           "tree_reactions", "CROSS_COND", "CROSS_STEP",
           "FIG91_PARENTS", "FIG91_ANGLES"]

#: Parents of Fig 9.1 (0-based; -1 is the ground).
FIG91_PARENTS = (-1, 0, 1, 2, 0, 4, 5, 5, 0)
#: Absolute link angles (degrees) of the default pose, in which both loops of Fig 9.2 close.
FIG91_ANGLES = (90.0, 135.0, 90.0, 45.0, 45.0, 90.0, 135.0, 225.0, 90.0)
_QD_PATTERN = np.array([1.0, -0.5, 0.3, 0.2, -0.4, 0.6, -0.3, 0.5, 0.1])


def tree_model(mass=1.0, length=1.0, g=9.81, contacts=()):
    """The nine-link tree of Fig 9.1 (optionally with contacts).

    Parameters
    ----------
    mass, length : float, optional
        Mass (kg) and length (m) of each link.
    g : float, optional
        Gravity along -y (m/s²).
    contacts : sequence of Contact, optional
        Loop closures to add.

    Returns
    -------
    Model
    """
    from planargeo.mechanics.model import Body, Joint, Model

    mass, length = check_param("mass", mass, positive=True), check_param("length", length, positive=True)
    g = check_param("g", g)
    L = float(length)
    bodies = [Body(mass, (L / 2, 0.0), mass * L * L / 12, name=f"body{i + 1}") for i in range(9)]
    joints = [Joint("revolute", (0.0 if p < 0 else L, 0.0, 0.0), name=f"joint{i + 1}")
              for i, p in enumerate(FIG91_PARENTS)]
    return Model(bodies, joints, FIG91_PARENTS, gravity=(0.0, -float(g)), contacts=contacts)


def tree_solve(model, q, qd, tau=None):
    """One solve of the tree: stacked (9.39-9.43) when open, the constrained algorithm (9.5) with contacts.

    Parameters
    ----------
    model : Model
        A tree, with or without contacts.
    q, qd : array_like, shape (nq,)
        One state.
    tau : array_like, shape (nq,), optional
        Joint torques (zero).

    Returns
    -------
    StackedSolution or LoopSolution
        From :func:`~planargeo.algorithms.stacked.stacked_solve` or ``loops.loop_solve``.

    Examples
    --------
    >>> closed = constrained_tree()
    >>> sol = tree_solve(closed.model, closed.state["q"], closed.state["qd"])
    >>> bool(np.allclose(sol.qdd, closed.quantities["qdd"]))
    True
    """
    from planargeo.algorithms.loops import loop_solve
    from planargeo.algorithms.stacked import stacked_solve

    return (loop_solve if model.contacts else stacked_solve)(model, q, qd, tau)


def tree_dof(model, q) -> int:
    """Degrees of freedom ``nq − rank J_c`` with the closure Jacobian ``J_c`` of the contacts (9.54, 9.60).

    Parameters
    ----------
    model : Model
        A tree, with or without contacts.
    q : array_like, shape (nq,)
        Joint coordinates.

    Returns
    -------
    int

    Examples
    --------
    >>> tree_dof(tree().model, _default_q()), tree_dof(constrained_tree().model, _default_q())
    (9, 5)
    """
    from planargeo.simulate.loops import closure_jacobian

    return model.nq - (int(np.linalg.matrix_rank(closure_jacobian(model, q))) if model.contacts else 0)


def _default_q():
    th = np.radians(FIG91_ANGLES)
    return np.array([th[i] - (th[p] if p >= 0 else 0.0) for i, p in enumerate(FIG91_PARENTS)])


def _loop_speeds(model, q, speed):
    """``speed`` times the speed pattern, less its part that breaks the loops (least squares)."""
    from planargeo.simulate.loops import closure_jacobian

    qd = speed * _QD_PATTERN
    if not model.contacts:
        return qd
    Jc = closure_jacobian(model, q)
    return qd - np.linalg.pinv(Jc) @ (Jc @ qd)


def _default_state(model, speed):
    """The scenes' state record (the default pose, :func:`_loop_speeds`, no torques) and its solution."""
    q, tau = _default_q(), np.zeros(9)
    qd = _loop_speeds(model, q, speed)
    return {"q": plain(q), "qd": plain(qd), "tau": plain(tau)}, tree_solve(model, q, qd, tau)


@register("tree", checks={"mass": "positive", "length": "positive"})
def tree(mass: float = 1.0, length: float = 1.0, g: float = 9.81, speed: float = 1.0) -> SceneResult:
    """The open tree of Fig 9.1 in the default pose, joint speeds ``speed × pattern``, no torques.

    Parameters
    ----------
    mass, length, g : float, optional
        As for :func:`tree_model`.
    speed : float, optional
        Scale of the joint-speed pattern (rad/s).

    Returns
    -------
    SceneResult
        ``C`` (9.1), ``Dinv`` (9.13), ``L`` (9.31), ``Lambda_inv`` (7.37) and ``b``, the inputs of
        9.48; ``qdd`` (9.39/9.43), ``qdd_direct`` (9.48), ``a``, ``f`` (0-based bodies, origin).
    """
    from planargeo.algorithms.stacked import adjacency, direct_accelerations, trunk

    model = tree_model(mass, length, g)
    state, sol = _default_state(model, speed)
    Lam, b = sol.articulated_mobilities.Lambda_inv, sol.articulated_mobilities.b
    a_direct = direct_accelerations(sol, Lam, b)
    qdd_direct = sol.T.T @ (a_direct - sol.C @ a_direct - sol.kappa)
    C = adjacency(model.parents)
    quantities = {"C": plain(C), "Dinv": plain(trunk(C)), "L": plain(sol.L),
                  "Lambda_inv": plain(np.stack(Lam)), "b": plain(np.stack(b)), "qdd": plain(sol.qdd),
                  "qdd_direct": plain(qdd_direct), "a": plain(sol.a.reshape(9, 3)),
                  "f": plain(sol.f.reshape(9, 3))}
    return SceneResult(model=model, state=state, quantities=quantities, extra={"solution": sol})


@register("constrained-tree", checks={"mass": "positive", "length": "positive"})
def constrained_tree(mass: float = 1.0, length: float = 1.0, g: float = 9.81, speed: float = 1.0) -> SceneResult:
    """The tree of Fig 9.2: pins between the tips of bodies 4 and 7 and of bodies 8 and 9.

    The joint speeds are ``speed × pattern`` less its part that breaks the loops (least squares).

    Parameters
    ----------
    mass, length, g, speed : float, optional
        As for :func:`tree`.

    Returns
    -------
    SceneResult
        ``G`` (9.49), ``Upsilon`` (9.51), ``qdd``, ``a``, ``u``, ``F`` (9.71), ``xi``, ``cond``,
        ``f`` (9.61), ``mu``.
    """
    from planargeo.mechanics.contacts import Contact

    L = length
    contacts = (Contact("pin", 3, 6, (L, 0.0), (L, 0.0), name="4-7"),
                Contact("pin", 7, 8, (L, 0.0), (L, 0.0), name="8-9"))
    model = tree_model(mass, length, g, contacts)
    state, sol = _default_state(model, speed)
    quantities = {"G": plain(sol.G), "Upsilon": plain(sol.Upsilon), "qdd": plain(sol.qdd),
                  "a": plain(sol.a.reshape(9, 3)), "u": plain(sol.u.reshape(9, 3)),
                  "F": plain(sol.F.reshape(-1, 3)), "xi": plain(sol.xi), "cond": float(sol.cond),
                  # every pin force of the closed tree (9.61): f_i on body i from its parent through joint i
                  "f": plain(sol.f.reshape(9, 3)), "mu": plain(sol.mu.reshape(9, 2))}
    return SceneResult(model=model, state=state, quantities=quantities, extra={"solution": sol})


def tree_pose(model, root_angle, speed=1.0, q_start=None, angle2=None):
    """A state of the (constrained) tree with body 1 at ``root_angle``: the loops closed, the speed pattern projected.

    Without ``q_start``: the pose of Fig 9.2 turned as a whole to ``root_angle``, then body 2 turned
    the shorter way to ``angle2`` in steps of at most 10°, the loops closed after each step by
    Gauss-Newton (:func:`planargeo.simulate.loops.close_loops`, 9.54).  With
    ``q_start``: closed from there in one go.  Velocities: the scene's pattern less its part that
    breaks the loops, so ``root_angle = 90°`` gives the scene's state.

    Parameters
    ----------
    model : Model
        :func:`tree_model`, with or without the pins of Fig 9.2.
    root_angle : float
        Absolute angle of body 1 (rad).
    speed : float
        Scale of the joint-speed pattern (rad/s).
    q_start : array_like (9,), optional
        Where to start the closure.
    angle2 : float, optional
        Absolute angle of body 2 (rad); None: it keeps its angle relative to body 1.

    Returns
    -------
    q, qd : ndarray (9,)

    Raises
    ------
    SceneError
        The loops cannot be closed with body 1 at that angle.

    Examples
    --------
    >>> closed = constrained_tree()
    >>> q, qd = tree_pose(closed.model, np.pi / 2)
    >>> bool(np.allclose(q, closed.state["q"])), bool(np.allclose(qd, closed.state["qd"]))
    (True, True)
    """
    from planargeo.simulate.loops import close_loops, closure_residual

    root_angle, speed = check_param("root_angle", root_angle), check_param("speed", speed)
    q = _default_q() if q_start is None else np.array(q_start, dtype=float)
    q[0] = root_angle
    if angle2 is None:
        fixed, path = [0], [q[1]]
    else:
        fixed, path = [0, 1], [check_param("angle2", angle2) - root_angle]
    if angle2 is not None and q_start is None:
        # the Fig 9.2 pose turned as a whole (its loops stay closed), then body 2 turned the shorter
        # way to angle2 in steps of at most 10° with the loops closed again after each step
        rel = path[0]
        turn = float(np.remainder(rel - q[1] + np.pi, 2 * np.pi) - np.pi)
        n = int(np.ceil(abs(turn) / np.radians(10.0)))
        path = [q[1] + turn * (k + 1) / n for k in range(n)] + [rel] if n else [rel]
    if model.contacts:
        for a in path:
            q[1] = a
            q = close_loops(model, q, fixed=fixed, tol=1e-13, max_iter=50)
        if not np.abs(closure_residual(model, q)).max() < 1e-9:
            where = f"body 1 at {np.degrees(root_angle):.4g}°" + (
                "" if angle2 is None else f", body 2 at {np.degrees(angle2):.4g}°")
            raise SceneError(f"the loops cannot close with {where}: the pins are out of reach")
    else:
        q[1] = path[-1]
    return q, _loop_speeds(model, q, speed)


#: condition number of ``BᵀGΛ⁻¹GᵀB`` below which :func:`tree_advance` integrates adaptively again
#: after crossing a singular configuration
CROSS_COND = 1e3
#: fixed step (s) of the RK4 steps that cross a singular configuration
CROSS_STEP = 1e-3
_CROSS_FACTORS = (1.0, 0.77, 1.3, 0.5, 2.0, 0.31, 3.0, 0.2, 5.0)


def tree_advance(model, q, qd, dt, *, rtol=1e-8, atol=1e-10, cross=True, every=None):
    """Integrate the tree (loops closed by its contacts, if any) over ``dt`` seconds (9.5 with :func:`simulate_loops`).

    The closed tree's loop 5-6-8-9 is a rhombus that folds flat in most motions: ``BᵀGΛ⁻¹GᵀB``
    (9.70) loses rank for an instant and the adaptive steps shrink until the solver stops.  With
    ``cross`` that pose is stepped over by fixed RK4 steps of :data:`CROSS_STEP` from the last state
    with condition below :data:`CROSS_COND` until it is below again (an event
    ``{"kind": "singular pose passed", "t", "cond"}``).

    Parameters
    ----------
    model : Model
        :func:`tree_model`.
    q, qd, dt : array_like (9,), array_like (9,), float
        The state at the start (on the loops) and the duration (s, > 0).
    rtol, atol, cross : float, float, bool
        Integrator tolerances (DOP853); step over singular configurations, or stop there.
    every : float, optional
        Also give the states every ``every`` seconds from the start (DOP853's dense output between
        its steps, projected onto the loops as each step's end is; the steps taken are the same).
        The states at ``every``, ``2·every``, … before ``dt``; where a crossing has moved the steps off
        that grid, each from the last step's end before it by a shorter step of the same method.

    Returns
    -------
    dict
        ``q``, ``qd`` at the end, ``position_residual``, ``velocity_residual`` (largest closure
        drift), ``events`` (``t`` from the start of the step), ``crossings``, ``nfev``, ``status``;
        with ``every``, ``samples``: ``(t, q, qd, position_residual)`` per state (the largest closure
        drift up to it).

    Raises
    ------
    SceneError
        ``dt`` not positive.
    PlanargeoError
        The integration stops at a singular configuration that could not be crossed.

    Examples
    --------
    >>> closed = constrained_tree()
    >>> out = tree_advance(closed.model, closed.state["q"], closed.state["qd"], 0.01)
    >>> out["status"], bool(out["position_residual"] < 1e-9)
    ('ok', True)
    >>> out = tree_advance(closed.model, closed.state["q"], closed.state["qd"], 0.01, every=0.0025)
    >>> [round(t, 4) for t, *_ in out["samples"]]
    [0.0025, 0.005, 0.0075]
    """
    from planargeo.simulate.loops import simulate_loops

    dt = check_param("dt", dt, positive=True)
    q, qd = np.array(q, dtype=float), np.array(qd, dtype=float)
    t0, pos, vel, events, nfev, crossings = 0.0, 0.0, 0.0, [], 0, 0
    samples = []
    if every is not None:
        every = check_param("every", every, positive=True)

    def take(res, upto, start):
        nonlocal pos, vel, nfev
        k = slice(0, upto + 1)
        pos = max(pos, float(np.max(res.extra["position_residual"][k], initial=0.0)))
        vel = max(vel, float(np.max(res.extra["velocity_residual"][k], initial=0.0)))
        nfev += int(res.nfev)
        for e in res.events:
            if e.get("kind") != "singular" and float(e.get("t", 0.0)) <= float(res.t[upto]):
                events.append(dict(e, t=start + float(e.get("t", 0.0))))

    def stopped(res, start):
        return PlanargeoError(f"the simulation stopped at t = {start + float(res.t[-1]):.4g} s from the start of "
                              f"the step: {res.message}")

    def on_grid(t):
        return every is not None and abs(t / every - round(t / every)) < 1e-9

    def keep(t, q, qd, drift):            # a state on the grid, inside the step
        if on_grid(t) and 1e-9 < t / every and t < dt * (1 - 1e-9):
            samples.append((round(t / every) * every, np.array(q, dtype=float), np.array(qd, dtype=float),
                            float(drift)))

    def fill(res, start, upto, before, **rk):
        """The grid's states in ``(start, start + upto]`` on the run ``res`` from ``start``: each from the
        last state it recorded before, by the same method (a shorter last step); the run is not changed."""
        if every is None:
            return
        drift = np.maximum.accumulate(np.asarray(res.extra["position_residual"], dtype=float))
        ts = start + np.asarray(res.t, dtype=float)
        for g in range(math.floor(start / every + 1e-9) + 1, math.floor((start + upto) / every + 1e-9) + 1):
            tg = g * every
            i = int(np.searchsorted(ts, tg + 1e-9 * every, side="right")) - 1
            if abs(ts[i] - tg) <= 1e-9 * every:
                keep(tg, res.q[i], res.qd[i], max(before, float(drift[i])))
                continue
            h = tg - ts[i]
            short = simulate_loops(model, res.q[i], res.qd[i], h, progress=False,
                                   **(dict(method="RK4", dt=h) if rk else dict(rtol=rtol, atol=atol)))
            if short.status == "ok":       # else no state there (that frame integrates it itself)
                keep(tg, short.q[-1], short.qd[-1],
                     max(before, float(drift[i]), float(np.max(short.extra["position_residual"]))))

    while dt - t0 > 1e-12 * max(1.0, dt):
        # with ``every``: a run from a time on the grid gives the grid's states (the same steps)
        sample = every is not None and on_grid(t0) and every < (dt - t0) * (1 - 1e-9)
        res = simulate_loops(model, q, qd, dt - t0, rtol=rtol, atol=atol, progress=False,
                             dt=every if sample else None)
        grid, before = None, pos
        if sample:
            grid = res
            if res.status != "ok":         # the crossing starts at the last good step's end, as without
                res = simulate_loops(model, q, qd, dt - t0, rtol=rtol, atol=atol, progress=False)
        if res.status == "ok":
            take(res, len(res.t) - 1, t0)
            if grid is not None:
                drift = np.maximum.accumulate(np.asarray(grid.extra["position_residual"], dtype=float))
                for i in range(1, len(grid.t) - 1):
                    keep(t0 + float(grid.t[i]), grid.q[i], grid.qd[i], max(before, float(drift[i])))
            else:
                fill(res, t0, float(res.t[-1]), before)
            q, qd, t0 = np.array(res.q[-1], dtype=float), np.array(res.qd[-1], dtype=float), dt
            break
        if res.status != "singular" or not cross:
            raise stopped(res, t0)
        cond = np.asarray(res.cond, dtype=float)
        good = np.flatnonzero(cond < CROSS_COND)
        k = int(good[-1]) if good.size else 0
        take(res, k, t0)
        if grid is not None:
            drift = np.maximum.accumulate(np.asarray(grid.extra["position_residual"], dtype=float))
            for i in range(1, len(grid.t)):
                if float(grid.t[i]) <= float(res.t[k]):
                    keep(t0 + float(grid.t[i]), grid.q[i], grid.qd[i], max(before, float(drift[i])))
        else:
            fill(res, t0, float(res.t[k]), before)
        t0 += float(res.t[k])
        q, qd = np.array(res.q[k], dtype=float), np.array(res.qd[k], dtype=float)
        # cross with fixed RK4 steps until the condition number is low again (0.25 s at most)
        h, spent = CROSS_STEP, 0.0
        while spent < 0.25 and dt - t0 > 1e-12 * max(1.0, dt):
            for f in _CROSS_FACTORS:         # an evaluation landed on the flat pose itself: other steps
                span = min(10 * h * f, dt - t0)
                rk = simulate_loops(model, q, qd, span, method="RK4", dt=min(h * f, span), progress=False)
                if rk.status == "ok":
                    break
            else:
                raise stopped(rk, t0)
            before = pos
            take(rk, len(rk.t) - 1, t0)
            fill(rk, t0, float(rk.t[-1]), before, rk=True)
            q, qd = np.array(rk.q[-1], dtype=float), np.array(rk.qd[-1], dtype=float)
            t0 += float(rk.t[-1])
            spent += float(rk.t[-1])
            c = np.asarray(rk.cond, dtype=float)
            if c.size and c[-1] < CROSS_COND:
                break
        crossings += 1
        events.append({"kind": "singular pose passed", "t": t0, "cond": float(cond.max())})
    return {"q": q, "qd": qd, "position_residual": pos, "velocity_residual": vel,
            "events": sorted(events, key=lambda e: e["t"]), "crossings": crossings, "nfev": nfev, "status": "ok",
            **({"samples": samples} if every is not None else {})}


def tree_reactions(model, sol) -> list:
    """Every pin force of the tree: a :class:`~planargeo.algorithms.loops.Reaction` per joint, then per contact.

    The joints' ``f`` on each body from its parent (9.61 closed, 9.41 open) and the contacts' ``-F``
    on body ``a`` (9.71).

    Parameters
    ----------
    model : Model
    sol : LoopSolution or StackedSolution
        From :func:`tree_solve` on ``model``.

    Returns
    -------
    list of Reaction

    Examples
    --------
    >>> closed = constrained_tree()
    >>> [r.symbol for r in tree_reactions(closed.model, closed.extra["solution"])][-3:]
    ['f_9', 'F_1', 'F_2']
    """
    from planargeo.algorithms.loops import _joint_reactions

    return list(sol.reactions) if hasattr(sol, "reactions") else _joint_reactions(model, sol.data.pose, sol.f)
