"""Scene ``chain``: a planar chain of uniform links (thesis Chapters 2-3), solved by all five methods.

Link ``i`` (mass ``mass``, length ``length``, ``J = m L²/12`` at mid-link) hangs from joint ``i``
at the tip of link ``i-1`` (joint 1 at the origin), along +x at ``q = 0``; an error from any
method propagates (``planargeo report chain`` then exits non-zero).

Examples
--------
>>> from planargeo import scenes
>>> scenes.build("chain", n=1).quantities["qdd"]["aba"]          # a rod released horizontally: -1.5 g
[-14.715]
"""
from __future__ import annotations

import numpy as np

from planargeo.algorithms.aba import articulated_body, forward_dynamics
from planargeo.algorithms.chain_splitting import forward_dynamics_mobility_split
from planargeo.algorithms.crba import forward_dynamics_crba
from planargeo.algorithms.projective import forward_dynamics_projective
from planargeo.algorithms.stacked import forward_dynamics_stacked
from planargeo.mechanics.model import JOINT_DOFS, chain_model
from planargeo.scenes import SceneResult, register

__all__ = ["chain", "chain_workspace", "chain_accelerations", "METHODS", "available_methods"]

#: method name -> forward dynamics function ``(model, q, qd, tau, f_ext=None) -> qdd``
METHODS = {
    "aba": forward_dynamics,
    "projective": forward_dynamics_projective,
    "mobility_split": forward_dynamics_mobility_split,
    "stacked": forward_dynamics_stacked,
    "crba": forward_dynamics_crba,
}


def available_methods() -> dict:
    """``{name: function}`` for the five forward dynamics methods (a copy of :data:`METHODS`).

    Returns
    -------
    dict
        Method name -> ``forward_dynamics(model, q, qd, tau, f_ext=None)``.

    Examples
    --------
    >>> list(available_methods())
    ['aba', 'projective', 'mobility_split', 'stacked', 'crba']
    """
    return dict(METHODS)


def chain_workspace(model, q, qd, tau):
    """One state of a chain solved by the articulated-body algorithm (thesis 3.6): its workspace.

    What the chain explorer draws: poles ``v``, ``a`` (4.5, 4.6), ``kappa``, ``p``, articulated
    inertias ``A`` (3.38), joint forces ``f`` (3.13), ``qdd`` (3.41).

    Parameters
    ----------
    model : Model
        The chain.
    q, qd, tau : array_like (nq,)
        Joint values, speeds and forces.

    Returns
    -------
    Data
        From :func:`planargeo.algorithms.aba.articulated_body`.

    Examples
    --------
    >>> w = chain_workspace(chain_model(1), [0.0], [0.0], [0.0])
    >>> w.qdd                                   # a rod released horizontally: -1.5 g
    array([-14.715])
    """
    return articulated_body(model, q, qd, tau)


def chain_accelerations(model, q, qd, tau):
    """The joint accelerations ``q̈`` of a chain at one state (articulated-body algorithm, 3.6).

    Parameters
    ----------
    model, q, qd, tau : Model, array_like (nq,)
        As for :func:`chain_workspace`.

    Returns
    -------
    numpy.ndarray
        ``q̈`` (nq,).

    Examples
    --------
    >>> chain_accelerations(chain_model(1), [0.0], [0.0], [0.0])   # a rod released horizontally
    array([-14.715])
    """
    return forward_dynamics(model, q, qd, tau)


@register("chain", limits={"n": (200, "n = 200 takes about 0.5 s; the cost grows as n³")},
          checks={"n": "int positive", "mass": "positive", "length": "positive",
                  "joint": ("revolute", "prismatic"), "seed": "int nonnegative optional"})
def chain(n: int = 3, mass: float = 1.0, length: float = 1.0, joint: str = "revolute", seed=None,
          gravity: float = -9.81) -> SceneResult:
    """A chain of ``n`` uniform links hanging from the origin.

    Parameters
    ----------
    n : int
        Number of links (>= 1).
    mass, length : float
        Mass and length of every link (> 0).
    joint : {"revolute", "prismatic"}
        Kind of every joint (a prismatic joint slides along its link).
    seed : int or None
        If given, ``q``, ``qd``, ``tau`` are normal random numbers with this seed; else zero.
    gravity : float
        Gravitational acceleration along y.

    Returns
    -------
    SceneResult
        ``quantities``: ``q``, ``qd``, ``tau``, ``qdd`` by ``aba`` (3.6), ``projective``
        (6.108-6.113), ``mobility_split`` (7.54/7.56), ``stacked`` (9.39/9.48), ``crba``, and
        ``max_disagreement``; ``extra["data"]``: the ABA workspace.
    """
    model = chain_model(n, mass, length, joint, gravity=(0.0, gravity))
    if seed is None:
        q = qd = tau = np.zeros(n)
    else:
        rng = np.random.default_rng(seed)
        q, qd, tau = rng.normal(size=(3, n))
    qdd = {name: np.asarray(fn(model, q, qd, tau), dtype=float).tolist() for name, fn in METHODS.items()}
    vals = [np.asarray(v) for v in qdd.values()]
    disagreement = max(float(np.abs(v - vals[0]).max(initial=0.0)) for v in vals)
    data = chain_workspace(model, q, qd, tau)
    state = {"q": q.tolist(), "qd": qd.tolist(), "tau": tau.tolist()}
    return SceneResult(model=model, state=state,
                       quantities={**state, "qdd": qdd, "max_disagreement": disagreement},
                       extra={"methods": list(qdd), "data": data, "joint_dofs": JOINT_DOFS[joint]})
