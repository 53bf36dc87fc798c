"""Frozen mechanism descriptions :class:`Body`, :class:`Joint`, :class:`Model`, and the per-state :class:`Data`.

A :class:`Model` is a tree, validated up front: body ``i`` hangs from ``parents[i] < i`` (``-1`` the
ground) through ``joints[i]``, whose frame has the pose ``placement = (x, y, theta)`` in the parent's
frame; the joint moves the body frame relative to it (thesis chapter 2):

============================  ====  =================================================
kind                          dofs  body frame = joint frame ...
============================  ====  =================================================
``"revolute"``                1     rotated by ``q`` about its origin (CCW positive)
``"prismatic"``               1     slid by ``q`` along its x axis
``"revolute_prismatic"``      2     slid by ``q[0]`` along x, then rotated by ``q[1]``
                                    about the slid origin (thesis 2.6-2.8)
``"twin_prismatic"``          2     slid by ``(q[0], q[1])`` along (x, y), not rotated
                                    (thesis 4.79)
``"plane"``                   3     slid by ``(q[0], q[1])`` along (x, y), then
                                    rotated by ``q[2]`` (a free body)
``"fixed"``                   0     unchanged (a weld)
============================  ====  =================================================
"""
from __future__ import annotations

import itertools
import math
import operator
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from planargeo._validate import as_array, as_scalar, check_positive
from planargeo.errors import CyclicTopologyError, InputError, ShapeError, TopologyError
from planargeo.geometry._docs import entries

__all__ = ["Body", "Joint", "Model", "Data", "JOINT_DOFS", "MAX_BODIES", "chain_model", "random_model"]

#: Number of degrees of freedom of each joint kind.
JOINT_DOFS: dict[str, int] = {"revolute": 1, "prismatic": 1, "revolute_prismatic": 2,
                              "twin_prismatic": 2, "plane": 3, "fixed": 0}

#: Docstring entries shared here (:func:`planargeo.geometry._docs.entries`).
_documented = entries({
    "i": "Parameters\n----------\ni : int\n    Body (joint) index.",
    "gravity": "gravity : array_like, shape (2,)\n    Gravitational acceleration ``(gx, gy)`` (m/s²).",
    "allow_large": "allow_large : bool, optional\n    Lift the :data:`MAX_BODIES` limit.",
})


def _finite_tuple(x, name: str, n: int) -> tuple[float, ...]:
    a = as_array(x, name, (n,))
    if a.ndim != 1:
        raise ShapeError(f"{name} must have shape ({n},), got shape {a.shape}")
    return tuple(float(v) for v in a)


def _positive(x, name: str, strict: bool = True) -> float:
    """A scalar argument, positive (non-negative unless ``strict``), as a float."""
    return float(check_positive(as_scalar(x, name), name, strict=strict))


def _check_name(name) -> None:
    if not isinstance(name, str):
        raise InputError(f"name must be a string, got {name!r}")


@dataclass(frozen=True)
class Body:
    """A rigid body (frozen).

    Parameters
    ----------
    mass : float
        Mass, strictly positive.
    com : (float, float)
        Centre of mass in the body frame.
    inertia : float
        Rotational inertia about the centre of mass, ``J = m rho^2 >= 0`` (0: a point mass).
    shape : shapely geometry or None
        Outline in the body frame, for drawings only.
    name : str
        A label for drawings and messages.

    Examples
    --------
    >>> Body(2.0, com=(0.5, 0.0), inertia=1 / 6).spatial_inertia()[2]      # at the frame origin (5.64)
    array([0.        , 1.        , 0.66666667])
    """

    mass: float
    com: tuple[float, float] = (0.0, 0.0)
    inertia: float = 0.0
    shape: Any = None
    name: str = ""

    def __post_init__(self):
        object.__setattr__(self, "mass", _positive(self.mass, "mass"))
        object.__setattr__(self, "inertia", _positive(self.inertia, "inertia", strict=False))
        object.__setattr__(self, "com", _finite_tuple(self.com, "com", 2))
        _check_name(self.name)

    def spatial_inertia(self) -> np.ndarray:
        """The 3×3 inertia at the body-frame origin (thesis 4.58, 5.64).

        Returns
        -------
        numpy.ndarray, shape (3, 3)
            ``inertia_matrix(mass, com, inertia)``.

        Examples
        --------
        >>> Body(2.0, (1.0, 0.0), 0.5).spatial_inertia()      # J + m |c|² = 0.5 + 2
        array([[2. , 0. , 0. ],
               [0. , 2. , 2. ],
               [0. , 2. , 2.5]])
        """
        from planargeo.screws.twists import inertia_matrix

        return inertia_matrix(self.mass, self.com, self.inertia)


@dataclass(frozen=True)
class Joint:
    """A joint between a body and its parent (frozen).

    Parameters
    ----------
    kind : str
        One of :data:`JOINT_DOFS` (see the module docstring).
    placement : (x, y, theta)
        Pose of the joint frame in the parent body's frame (world frame for the ground).
    name : str
        A label for drawings and messages.

    Examples
    --------
    >>> Joint("revolute", (1.0, 0.0, 0.0)).dofs
    1
    >>> Joint("twin_prismatic").dofs              # thesis 4.79: translations along x and y
    2
    >>> Joint("hinge")
    Traceback (most recent call last):
    ...
    planargeo.errors.InputError: kind must be one of ['revolute', 'prismatic', 'revolute_prismatic', 'twin_prismatic', 'plane', 'fixed'], got 'hinge'
    """

    kind: str
    placement: tuple[float, float, float] = (0.0, 0.0, 0.0)
    name: str = ""

    def __post_init__(self):
        if not isinstance(self.kind, str) or self.kind not in JOINT_DOFS:
            raise InputError(f"kind must be one of {list(JOINT_DOFS)}, got {self.kind!r}")
        object.__setattr__(self, "placement", _finite_tuple(self.placement, "placement", 3))
        _check_name(self.name)

    @property
    def dofs(self) -> int:
        """Number of joint coordinates (columns of ``s``)."""
        return JOINT_DOFS[self.kind]


def _find_cycle(ps) -> tuple[int, ...]:
    """The first cycle of a parent list (bodies in parent order), or ``()`` if there is none."""
    n = len(ps)
    for i in range(n):
        order, j = {}, i
        while 0 <= j < n and j not in order:
            order[j] = len(order)
            j = ps[j]
        if 0 <= j < n:                     # came back to a body already on this path
            path = list(order)
            return tuple(path[order[j]:])
    return ()


def _cycle_error(ps, cycle, message: str | None = None) -> CyclicTopologyError:
    """The :class:`CyclicTopologyError` of parents ``ps`` with a ``cycle`` (or ``message``)."""
    ps = [int(p) for p in ps]
    n = len(ps)
    C = np.zeros((n, n))
    for i, p in enumerate(ps):
        if 0 <= p < n:
            C[i, p] = 1.0
    e = np.zeros(n)
    e[list(cycle)] = 1.0
    singular = not np.any(e @ (np.eye(n) - C))        # eᵀ (1 - C) = 0 (9.12), exact: small integers
    cond = math.inf if singular else float(np.linalg.cond(np.eye(n) - C))
    path = " -> ".join(str(b) for b in (*cycle, cycle[0]))
    if message is None:
        message = f"parents contain a cycle through bodies {path} (parents={ps})"
    return CyclicTopologyError(message.format(path=path, parents=ps), cond, cycle)


def _check_parents(parents, n: int) -> tuple[int, ...]:
    try:
        ps = [int(p) for p in parents]
        if any(int(p) != p for p in parents):
            raise ValueError
    except (TypeError, ValueError):
        raise TopologyError(f"parents must be a sequence of integers, got {parents!r}") from None
    if len(ps) != n:
        raise TopologyError(f"parents must have one entry per body ({n}), got {len(ps)}")
    for i, p in enumerate(ps):
        if p < -1 or p >= n:
            raise TopologyError(
                f"parents[{i}] must be -1 (ground) or a body index in 0..{n - 1}, got {p} (index out of range)")
    for i, p in enumerate(ps):
        if p >= i:
            # Distinguish a genuine cycle from a mere ordering problem.
            seen, j = {i}, p
            while j != -1 and j not in seen:
                seen.add(j)
                j = ps[j]
            if j != -1:
                raise _cycle_error(ps, _find_cycle(ps))
            raise TopologyError(
                f"parents[{i}] must be below {i} (parents before children), got {p}")
    return tuple(ps)


@_documented
@dataclass(frozen=True)
class Model:
    """A tree of rigid bodies (frozen, validated).

    Parameters
    ----------
    bodies : sequence of Body
        The bodies, each parent before its children.
    joints : sequence of Joint
        ``joints[i]`` connects body ``i`` to ``parents[i]``.
    parents : sequence of int
        ``parents[i]`` is ``-1`` (ground) or a body index ``< i``.
    {gravity}
    contacts : tuple
        Contact / loop-closure descriptions (:mod:`planargeo.mechanics.contacts`).

    Attributes
    ----------
    N, nq, q_offsets : int, int, tuple of int
        Bodies, joint coordinates; ``q[q_offsets[i]:q_offsets[i+1]]`` are joint ``i``'s.

    Examples
    --------
    >>> Model([Body(1.0), Body(1.0)], [Joint("revolute")] * 2, [1, 0])
    Traceback (most recent call last):
    ...
    planargeo.errors.CyclicTopologyError: parents contain a cycle through bodies 0 -> 1 -> 0 (parents=[1, 0]) (condition number of 1 - C: inf)
    """

    bodies: tuple[Body, ...]
    joints: tuple[Joint, ...]
    parents: tuple[int, ...]
    gravity: tuple[float, float] = (0.0, -9.81)
    contacts: tuple = ()
    # derived, filled in __post_init__
    N: int = field(init=False, repr=False, compare=False)
    nq: int = field(init=False, repr=False, compare=False)
    q_offsets: tuple[int, ...] = field(init=False, repr=False, compare=False)
    _arrays: dict = field(init=False, repr=False, compare=False, hash=False)

    def __post_init__(self):
        bodies = tuple(self.bodies)
        joints = tuple(self.joints)
        for what, items, cls in (("bodies", bodies, Body), ("joints", joints, Joint)):
            for i, x in enumerate(items):
                if not isinstance(x, cls):
                    raise InputError(f"{what}[{i}] must be a {cls.__name__}, "
                                     f"got {type(x).__name__}")
        if len(bodies) == 0:
            raise InputError("bodies must not be empty")
        if len(joints) != len(bodies):
            raise InputError(f"joints must have one entry per body ({len(bodies)}), got {len(joints)}")
        offs = (0, *itertools.accumulate(j.dofs for j in joints))
        for name, value in (("bodies", bodies), ("joints", joints),
                            ("parents", _check_parents(self.parents, len(bodies))),
                            ("gravity", _finite_tuple(self.gravity, "gravity", 2)),
                            ("contacts", tuple(self.contacts)), ("N", len(bodies)), ("nq", offs[-1]),
                            ("q_offsets", offs), ("_arrays", {})):
            object.__setattr__(self, name, value)

    # -- structure -------------------------------------------------------
    @_documented
    def q_slice(self, i: int) -> slice:
        """Slice of ``q`` holding joint ``i``'s coordinates.

        {i}

        Returns
        -------
        slice

        Raises
        ------
        InputError
            If ``i`` is not a body index.

        Examples
        --------
        >>> chain_model(3).q_slice(1)
        slice(1, 2, None)
        """
        if not -self.N <= i < self.N:
            raise InputError(f"i must be a body index in 0..{self.N - 1}, got {i}")
        i %= self.N
        return slice(self.q_offsets[i], self.q_offsets[i + 1])

    def children(self, i: int) -> tuple[int, ...]:
        """Bodies whose parent is ``i`` (``-1``: bodies on the ground), in order.

        Parameters
        ----------
        i : int
            Body index, or ``-1`` for the ground.

        Returns
        -------
        tuple of int

        Examples
        --------
        >>> m = chain_model(3)
        >>> m.children(-1), m.children(0), m.children(2)
        ((0,), (1,), ())
        """
        return tuple(k for k, p in enumerate(self.parents) if p == i)

    @_documented
    def ancestors(self, i: int) -> tuple[int, ...]:
        """Bodies on the path from the ground to ``i`` (inclusive), root first.

        {i}

        Returns
        -------
        tuple of int

        Examples
        --------
        >>> chain_model(3).ancestors(2)
        (0, 1, 2)
        """
        path = []
        while i != -1:
            path.append(i)
            i = self.parents[i]
        return tuple(reversed(path))

    @property
    def is_chain(self) -> bool:
        """True for an unbranched chain ``parents == (-1, 0, 1, ...)``."""
        return self.parents == tuple(range(-1, self.N - 1))

    @property
    def mass(self) -> float:
        """Total mass."""
        return float(sum(b.mass for b in self.bodies))

    # -- cached numeric arrays (used by the algorithms) -------------------
    def arrays(self) -> dict:
        """Read-only numeric arrays of the model (cached): masses, coms, inertias, placements, parents.

        Returns
        -------
        dict of str to numpy.ndarray
            ``mass``, ``com``, ``J``, ``placement``, ``parents``.

        Examples
        --------
        >>> sorted(chain_model(3).arrays())
        ['J', 'com', 'mass', 'parents', 'placement']
        """
        a = self._arrays
        if "mass" not in a:
            a["mass"] = np.array([b.mass for b in self.bodies])
            a["com"] = np.array([b.com for b in self.bodies]).reshape(self.N, 2)
            a["J"] = np.array([b.inertia for b in self.bodies])
            a["placement"] = np.array([j.placement for j in self.joints]).reshape(self.N, 3)
            a["parents"] = np.array(self.parents, dtype=int)
            for k in ("mass", "com", "J", "placement", "parents"):
                a[k].setflags(write=False)
        return a

    def ancestor_mask(self) -> np.ndarray:
        """``mask[i, c]``: whether coordinate ``c`` moves body ``i`` (its joint is on the path to ``i``); cached, read-only.

        Returns
        -------
        numpy.ndarray of bool, shape (N, nq)

        Examples
        --------
        >>> chain_model(3).ancestor_mask().astype(int)
        array([[1, 0, 0],
               [1, 1, 0],
               [1, 1, 1]])
        """
        a = self._arrays
        if "ancestor_mask" not in a:
            mask = np.zeros((self.N, self.nq), dtype=bool)
            for i, p in enumerate(self.parents):
                if p >= 0:
                    mask[i] = mask[p]
                mask[i, self.q_slice(i)] = True
            mask.setflags(write=False)
            a["ancestor_mask"] = mask
        return a["ancestor_mask"]

    @_documented
    def with_gravity(self, gravity) -> "Model":
        """A copy with another gravity vector.

        {parameters gravity}

        Returns
        -------
        Model

        Examples
        --------
        >>> chain_model(3).with_gravity((0.0, 0.0)).gravity
        (0.0, 0.0)
        """
        return Model(self.bodies, self.joints, self.parents, gravity, self.contacts)


class Data:
    """Per-state workspace of world-frame, at-origin quantities (mutable).

    Filled by :func:`planargeo.mechanics.kinematics.kinematics`; the recursive algorithms add
    their intermediates (``A``, ``d``, ``a``, ``f``, ``qdd``...).  Batch dimensions ``...`` are ``q``'s.

    Attributes
    ----------
    model : Model
        The mechanism the state belongs to.
    q, qd : ndarray (..., nq)
        Joint coordinates and velocities of the state.
    pose, com, origin : ndarray (..., N, 3), (..., N, 2), (..., N, 2)
        World pose ``(x, y, θ)`` of each body frame, its centre of mass, its joint frame's origin.
    S : ndarray (..., 3, nq)
        All joint axes side by side, ``S[..., :, q_slice(i)] = s_i`` (thesis Remark 8).
    I : ndarray (..., N, 3, 3)
        Spatial inertias at the origin (thesis 4.58).
    v, kappa : ndarray (..., N, 3)
        Body twists (2.9, 3.32) and bias accelerations (2.19, 3.33, with multi-dof cross terms).
    g, p : ndarray (..., N, 3)
        Applied wrenches (gravity plus ``f_ext``) and bias forces ``-(v×)ᵀ I v - g`` (3.11, 3.34).

    Examples
    --------
    >>> from planargeo.mechanics.kinematics import kinematics
    >>> kinematics(chain_model(2), [0.0, 0.0]).com      # two straight unit links along x
    array([[0.5, 0. ],
           [1.5, 0. ]])
    """

    def __init__(self, model: Model):
        self.model = model

    @_documented
    def s(self, i: int) -> np.ndarray:
        """Joint ``i``'s world-frame motion space ``s_i``: its columns of ``S``.

        {i}

        Returns
        -------
        numpy.ndarray, shape (..., 3, k)
            The joint's unit twists at the world origin, one column per coordinate.

        Examples
        --------
        >>> from planargeo.mechanics.kinematics import kinematics
        >>> kinematics(chain_model(3), [0.0, 0.0, 0.0]).s(1)[:, 0]     # a pin at (1, 0): the point [0, -1, 1]
        array([ 0., -1.,  1.])
        """
        return self.S[..., :, self.model.q_slice(i)]

    @_documented
    def jacobian(self, i: int) -> np.ndarray:
        """Body ``i``'s Jacobian (..., 3, nq): ``v_i = J_i qd`` (thesis Remark 8), zero off its path.

        {i}

        Returns
        -------
        J_i : numpy.ndarray, shape (..., 3, nq)
            ``S`` with the columns of the joints not between body ``i`` and the ground set to zero.

        Examples
        --------
        >>> from planargeo.mechanics.kinematics import kinematics
        >>> kinematics(chain_model(3), [0.0, 0.0, 0.0]).jacobian(1) + 0.0    # joint 2 does not move body 1
        array([[ 0.,  0.,  0.],
               [ 0., -1.,  0.],
               [ 1.,  1.,  0.]])
        """
        return self.S * self.model.ancestor_mask()[i]

    @property
    def J(self) -> np.ndarray:
        """All body Jacobians, shape (..., N, 3, nq)."""
        return self.S[..., None, :, :] * self.model.ancestor_mask()[:, None, :]

    def __repr__(self) -> str:
        keys = [k for k in vars(self) if k != "model"]
        return f"Data(N={self.model.N}, nq={self.model.nq}, fields={keys})"


# -- builders (used by scenes and tests) ----------------------------------------------------
#: The builders (:func:`chain_model`, :func:`random_model`) make at most this many bodies unless
#: ``allow_large=True``: a request for millions of bodies is refused at once, not after minutes
#: (10 000 links take about 0.4 s to build and 0.2 s per batch-free ``kinematics`` call).
MAX_BODIES = 10_000


def _body_count(n, allow_large: bool) -> int:
    """``n`` as a number of bodies: an integer (not a bool) from 1 to :data:`MAX_BODIES` (any with ``allow_large``)."""
    if isinstance(n, bool):
        raise InputError(f"n must be an integer, got the bool {n!r}")
    try:
        n = operator.index(n)
    except TypeError:
        raise InputError(f"n must be an integer, got {n!r}") from None
    if n < 1:
        raise InputError(f"n must be a positive integer, got {n}")
    if n > MAX_BODIES and not allow_large:
        raise InputError(f"n must be at most MAX_BODIES = {MAX_BODIES} bodies, got {n} "
                         "(pass allow_large=True for a bigger model, if memory and time allow)")
    return n


@_documented
def chain_model(n: int = 3, mass: float = 1.0, length: float = 1.0, joint: str = "revolute",
                gravity=(0.0, -9.81), *, allow_large: bool = False) -> Model:
    """An unbranched chain of ``n`` uniform slender links along +x at ``q = 0``, joint 1 at the origin.

    Parameters
    ----------
    n : int
        Number of links, 1 to :data:`MAX_BODIES` (more with ``allow_large=True``).
    mass, length : float
        Of each link, positive; the inertia ``mass length² / 12`` about its middle must be finite.
    joint : str
        The kind of every joint (see :class:`Joint`).
    {gravity allow_large}

    Returns
    -------
    Model
        The chain: bodies ``link1`` to ``linkn``, each jointed to the one before.

    Raises
    ------
    InputError
        ``n`` not an integer or out of range; ``mass`` or ``length`` not positive or too large.

    Examples
    --------
    >>> m = chain_model(3, joint="prismatic")
    >>> [j.kind for j in m.joints], m.joints[1].placement
    (['prismatic', 'prismatic', 'prismatic'], (1.0, 0.0, 0.0))
    >>> chain_model(1.5)
    Traceback (most recent call last):
    ...
    planargeo.errors.InputError: n must be an integer, got 1.5
    """
    n = _body_count(n, allow_large)
    L = _positive(length, "length")
    m = _positive(mass, "mass")
    J = m * L * L / 12
    if not math.isfinite(J):
        raise InputError(f"length {L!r} is too large for mass {m!r}: the link inertia mass length² / 12 overflows")
    bodies = [Body(m, (L / 2, 0.0), J, name=f"link{i + 1}") for i in range(n)]
    joints = [Joint(joint, (0.0 if i == 0 else L, 0.0, 0.0), name=f"joint{i + 1}") for i in range(n)]
    return Model(bodies, joints, list(range(-1, n - 1)), gravity)


@_documented
def random_model(n: int, seed=None, *, kinds=("revolute", "prismatic"), tree: bool = False,
                 gravity=(0.0, -9.81), allow_large: bool = False) -> Model:
    """A random model for tests: ``n`` bodies (as for :func:`chain_model`), joint kinds from ``kinds``.

    Parameters
    ----------
    n : int
        Number of bodies.
    seed : int or numpy.random.Generator, optional
        Random seed (non-negative) or generator.
    kinds : sequence of str, optional
        Joint kinds to draw from.
    tree : bool, optional
        Each parent drawn among the earlier bodies and the ground; else a chain.
    {gravity allow_large}

    Returns
    -------
    Model
        Bodies of mass 0.5-2 kg with random centres, inertias and joint placements.

    Raises
    ------
    InputError
        For a bad ``n``, ``tree``, ``kinds`` or ``seed``.

    Examples
    --------
    >>> m = random_model(5, seed=1, tree=True)
    >>> m.N, all(p < i for i, p in enumerate(m.parents))
    (5, True)
    """
    n = _body_count(n, allow_large)
    if not isinstance(tree, bool):
        raise InputError(f"tree must be True or False, got {tree!r}")
    if (not isinstance(kinds, (list, tuple)) or not kinds
            or not all(isinstance(k, str) and k in JOINT_DOFS for k in kinds)):
        raise InputError(f"kinds must be a non-empty sequence of joint kinds ({', '.join(JOINT_DOFS)}), got {kinds!r}")
    if not (seed is None or isinstance(seed, np.random.Generator)
            or (isinstance(seed, (int, np.integer)) and not isinstance(seed, bool) and seed >= 0)):
        raise InputError(f"seed must be None, a non-negative int or a numpy Generator, got {seed!r}")
    rng = np.random.default_rng(seed)
    bodies, joints, parents = [], [], []
    for i in range(n):
        bodies.append(Body(rng.uniform(0.5, 2.0), tuple(rng.uniform(-0.5, 1.0, 2)), rng.uniform(0.05, 0.5)))
        kind = str(kinds[rng.integers(len(kinds))])
        pl = (rng.uniform(-0.5, 1.5), rng.uniform(-0.5, 0.5), rng.uniform(-np.pi, np.pi))
        joints.append(Joint(kind, pl))
        parents.append(int(rng.integers(-1, i)) if tree and i > 0 else i - 1)
    return Model(bodies, joints, parents, gravity)
