"""Scene ``chain``: a planar chain of uniform links (thesis Chapters 2-3).

Link ``i`` has mass ``mass``, length ``length``, centre of mass at mid-link and
inertia ``mass length²/12`` about it; joint 1 sits at the origin and joint ``i``
at the tip of link ``i-1``; at ``q = 0`` the links lie along +x; ``q`` are
relative joint angles (CCW positive) or slides along the link, ``tau`` the
joint torques / forces; gravity acts along y.

The joint accelerations are solved by every forward dynamics method available
(``aba`` (3.6), ``projective`` (6.108-6.113), ``mobility_split`` (7.54/7.56),
``stacked`` (9.39/9.48), ``crba`` (dense reference)); a method whose module is
not installed is skipped.

Examples
--------
>>> from planargeo import scenes
>>> r = scenes.build("chain", n=1)
>>> r.quantities["qdd"]["aba"]          # a rod released horizontally: -1.5 g
[-14.715]
"""
from __future__ import annotations

import importlib

import numpy as np

from .._validate import as_scalar
from ..errors import InputError, SceneError
from ..model import JOINT_DOFS, chain_model
from . import SceneResult, register

__all__ = ["chain", "METHODS"]

#: method name -> (module, function); missing modules are skipped
METHODS: dict[str, tuple[str, str]] = {
    "aba": ("planargeo.algorithms.aba", "forward_dynamics"),
    "projective": ("planargeo.algorithms.projective", "forward_dynamics_projective"),
    "mobility_split": ("planargeo.algorithms.chain_splitting", "forward_dynamics_mobility_split"),
    "stacked": ("planargeo.algorithms.stacked", "forward_dynamics_stacked"),
    "crba": ("planargeo.algorithms.crba", "forward_dynamics_crba"),
}


def available_methods() -> dict:
    """``{name: function}`` for every forward dynamics method whose module can be imported."""
    out = {}
    for name, (mod, fn) in METHODS.items():
        try:
            out[name] = getattr(importlib.import_module(mod), fn)
        except (ImportError, AttributeError):
            continue
    return out


@register("chain")
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
        If given, ``q``, ``qd``, ``tau`` are drawn from a normal distribution
        with this seed; otherwise they are zero.
    gravity : float
        Gravitational acceleration along y (default -9.81).

    Returns
    -------
    SceneResult
        ``model`` (:class:`planargeo.model.Model`); ``state``: ``q``, ``qd``,
        ``tau``; ``quantities``: ``q``, ``qd``, ``tau``, ``qdd`` (``{method:
        list}``), ``max_disagreement`` (largest difference between methods),
        ``failed`` (``{method: error message}``); ``extra``: ``methods``
        (names run), ``data`` (the ABA workspace: ``A``, ``d``, ``a``, ``f``...).
    """
    try:
        n_int = int(n)
    except (TypeError, ValueError):
        raise SceneError(f"n must be a positive integer, got {n!r}") from None
    if n_int != n or n_int < 1:
        raise SceneError(f"n must be a positive integer, got {n!r}")
    if joint not in ("revolute", "prismatic"):
        raise SceneError(f"joint must be 'revolute' or 'prismatic', got {joint!r}")
    try:
        mass_v, length_v, g = as_scalar(mass, "mass"), as_scalar(length, "length"), as_scalar(gravity, "gravity")
        if not mass_v > 0:
            raise InputError(f"mass must be positive, got {mass_v!r}")
        if not length_v > 0:
            raise InputError(f"length must be positive, got {length_v!r}")
    except InputError as exc:
        raise SceneError(str(exc)) from None
    model = chain_model(n_int, mass_v, length_v, joint, gravity=(0.0, g))
    if seed is None:
        q = qd = tau = np.zeros(n_int)
    else:
        rng = np.random.default_rng(seed)
        q, qd, tau = rng.normal(size=(3, n_int))
    qdd, failed = {}, {}
    for name, fn in available_methods().items():
        try:
            qdd[name] = np.asarray(fn(model, q, qd, tau), dtype=float).tolist()
        except Exception as exc:  # a method may legitimately refuse (e.g. singular): report, don't die
            failed[name] = f"{type(exc).__name__}: {exc}"
    vals = [np.asarray(v) for v in qdd.values()]
    disagreement = max((float(np.abs(v - vals[0]).max()) for v in vals), default=0.0)
    from ..algorithms.aba import articulated_body

    data = articulated_body(model, q, qd, tau)
    params = {"n": n_int, "mass": mass_v, "length": length_v, "joint": joint, "seed": seed, "gravity": g}
    state = {"q": q.tolist(), "qd": qd.tolist(), "tau": tau.tolist()}
    return SceneResult(
        name="chain", params=params, model=model, state=state,
        quantities={**state, "qdd": qdd, "max_disagreement": disagreement, "failed": failed},
        extra={"methods": list(qdd), "data": data, "joint_dofs": JOINT_DOFS[joint]},
    )
