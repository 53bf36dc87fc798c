"""Scene ``splitting``: articulated mobilities and chain splitting (thesis 7.4-7.6: 7.28-7.56).

``n`` bodies (joints ``L`` apart) hang from ``CJ_1`` at the origin, each further joint bent by
``phi``, at rest, gravity ``g`` (0: the thesis's example).  A couple ``f_{n+1} = [0, 0, tau]``
acts on the tip (as ``-f_{n+1}``, 3.1; 7.44: the tip feels ``-tau``, counter-clockwise positive).  Split at joint ``split + 1``: bodies
``1..split`` form the constrained chain (mobility ``Lambda_i⁻¹``, ``b_i``, 7.4.1 corrected
7.38a), the rest the free-floating chain (``A_{i+1}``, ``d_{i+1}``, 7.1.1).  With ``n = 2``
this is example 7.5 (Figure 7.9): ``x / L = 1 + 2 eta² cos(phi) / (4 + 5 eta²)`` (7.47).

Examples
--------
>>> from planargeo import scenes
>>> q = scenes.build("splitting", phi=0.0).quantities
>>> round(q["x_over_L"], 12)                 # 1 + 2*4/(4 + 20)
1.333333333333
"""
from __future__ import annotations

import numpy as np

from planargeo.errors import SceneError
from planargeo.scenes import SceneResult, _at_rest, plain, register
from planargeo.scenes.articulated import bent_chain_model, joint_points

__all__ = ["splitting", "splitting_state", "twist_pole"]


def twist_pole(a) -> np.ndarray | None:
    """The pole ``(x, y)`` of a twist or acceleration ``a = [v_x, v_y, w]`` (None for a translation).

    Parameters
    ----------
    a : array_like (3,)

    Returns
    -------
    ndarray (2,) or None

    Examples
    --------
    >>> twist_pole([0.0, -2.0, 2.0])
    array([1., 0.])
    """
    a = np.asarray(a, dtype=float)
    if abs(a[2]) <= 1e-12 * max(1.0, float(np.abs(a).max())):
        return None
    return np.array([-a[1] / a[2], a[0] / a[2]])


def splitting_state(model, q, split: int, tau: float, *, L: float = 1.0) -> dict:
    """Mobilities, split solution and chain-splitting accelerations of one state at rest (arrays).

    Parameters
    ----------
    model : Model
        An unbranched chain hanging from the ground (:func:`~planargeo.scenes.articulated.bent_chain_model`).
    q : array_like (n,)
        Relative joint angles [rad].
    split : int
        Split at joint ``split + 1`` (1 <= split < n).
    tau : float
        The moment of ``f_{n+1} = [0, 0, tau]`` (7.44): the tip feels ``-f_{n+1}``, a couple ``-tau``
        (counter-clockwise positive); 0: no couple.
    L : float
        Distance between joints.

    Returns
    -------
    dict
        ``joints``; ``Lambda_inv``, ``b`` with the couple (body ``i`` sees loads on ``1..i``), and
        ``Lambda_inv_free``, ``b_free`` without; ``A``, ``d`` with the couple; ``a_split`` (7.54),
        ``f_split`` (7.56); ``a``, ``f``, ``qdd`` by chain splitting (7.6); ``a_tip_7_37``
        (7.37, 7.45); ``f_tip``; ``centres``: poles of ``-Lambda_i⁻¹ [0, 0, 1]`` (NaN: none).

    Raises
    ------
    SceneError
        ``split`` out of range.
    SingularConfigurationError
        A singular joint or split matrix.

    Examples
    --------
    >>> from planargeo.scenes.articulated import bent_chain_model
    >>> st = splitting_state(bent_chain_model(2, 0.5), [0.0, 0.0], 1, 1.0)
    >>> bool(np.allclose(st["a_split"], st["a"][0])), bool(np.allclose(st["a_tip_7_37"], st["a"][1]))
    (True, True)
    """
    from planargeo.algorithms.articulated_inertia import _state_arrays
    from planargeo.algorithms.articulated_mobility import articulated_mobility
    from planargeo.algorithms.chain_splitting import chain_split

    n = model.N
    if not 1 <= split < n:
        raise SceneError(f"split must be between 1 and n - 1 = {n - 1}, got {split!r}")
    q = np.asarray(q, dtype=float)
    z = np.zeros(n)
    f_tip = np.array([0.0, 0.0, float(tau)])
    f_ext = np.zeros((n, 3))
    f_ext[-1] = -f_tip                                   # joint n+1 pushes the tip with -f_{n+1} (3.1)
    # one state split at every joint with the couple (7.6), and the mobilities (7.4.1) without it
    _d, I, S, kappa, p, taus, parents, _points, jp = _state_arrays(model, q, z, z, f_ext)
    cs = chain_split(I, S, kappa, p, taus, parents, jp)
    mob, art, a, f = cs.mobilities, cs.articulated, cs.a, cs.f
    free = articulated_mobility(model, q, z, z)
    centres = []
    for Lam in free.Lambda_inv:
        c = twist_pole(-Lam @ [0.0, 0.0, 1.0])
        centres.append(c if c is not None else np.full(2, np.nan))
    return {
        "joints": joint_points(q, L), "Lambda_inv": mob.Lambda_inv, "b": mob.b,
        "Lambda_inv_free": free.Lambda_inv, "b_free": free.b, "A": art.A, "d": art.d,
        "a_split": a[split - 1], "f_split": f[split],
        "a": a, "f": f, "qdd": cs.qdd,
        "a_tip_7_37": -free.Lambda_inv[-1] @ f_tip + free.b[-1], "f_tip": f_tip,
        "centres": np.array(centres),
    }


@register("splitting", limits={"n": (200, "n = 200 takes about 0.2 s")},
          checks={"n": "int positive", "m": "positive", "rho": "positive", "L": "positive",
                  "tau": "nonzero", "split": "int positive", "g": "nonnegative"})
def splitting(n: int = 2, m: float = 1.0, rho: float = 0.5, L: float = 1.0, phi: float = np.pi / 4,
              tau: float = 1.0, split: int = 1, g: float = 0.0) -> SceneResult:
    """A couple on the tip of a pinned chain, solved by articulated mobility and chain splitting (7.38, 7.54, 7.56).

    Parameters
    ----------
    n : int
        Number of bodies (>= 2).
    m, rho, L, phi : float
        Mass, radius of gyration and length of each body (> 0); bend at every later joint [rad].
    tau, split, g : float, int, float
        The moment of ``f_{n+1} = [0, 0, tau]`` [N·m] (non-zero), the thesis's notation (7.44): the tip
        feels ``-f_{n+1}``, a couple ``-tau`` (clockwise for ``tau > 0``; the explorer's slider is the
        couple on the tip itself); split at joint ``split + 1``; gravity along -y (>= 0).

    Returns
    -------
    SceneResult
        :func:`splitting_state` as lists, and for example 7.5 ``Lambda1_inv`` (7.42),
        ``Lambda2_inv`` (7.43), ``a_tip`` (7.46), ``x_over_L`` (7.47-7.48), ``eta`` (7.49).

    Raises
    ------
    SceneError
        ``n < 2``, ``split`` out of range, a size not positive, ``tau`` zero or ``g`` negative.

    Examples
    --------
    >>> r = splitting(phi=np.pi / 2)
    >>> round(r.quantities["x_over_L"], 12)      # at 90 degrees: the joint of body 2
    1.0
    """
    if n < 2:
        raise SceneError(f"n must be at least 2 (a chain to split), got {n}")
    model = bent_chain_model(n, rho, L, m, g)
    q = np.array([0.0] + [phi] * (n - 1))
    st = splitting_state(model, q, split, tau, L=L)
    a_tip = st["a"][-1]
    quantities = {k: plain(st[k]) for k in ("joints", "Lambda_inv", "b", "A", "d", "a_split", "f_split",
                                             "a", "f", "qdd", "a_tip_7_37", "f_tip")}
    quantities.update({
        "Lambda1_inv": plain(st["Lambda_inv_free"][0]),
        "Lambda2_inv": plain(st["Lambda_inv_free"][1]),
        "a_tip": plain(a_tip),
        "x_over_L": float(-a_tip[1] / (L * a_tip[2])),
        "eta": L / rho,
    })
    return SceneResult(model=model, state=_at_rest(q), quantities=quantities, extra={"state": st})
