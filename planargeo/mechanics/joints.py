"""Planar joints: motion spaces ``s`` and reaction spaces ``R`` (thesis 4.8, 5.61–5.63, 6.1).

A ``k``-dof joint has ``k`` unit twists ``s`` and ``3-k`` unit wrenches ``R``, ``sᵀR = 0``, world
coordinates at the origin (twists ``[vx, vy, wz]``, wrenches ``[fx, fy, tz]``); ``e⊥`` is ``e``
turned by +90° (5.63), and thesis 4.79's 2-dof "plane joint" is ``twin_prismatic`` here:

============================  ==============================  =============================================
kind (dof)                    ``s`` columns                   ``R`` columns
============================  ==============================  =============================================
``revolute`` (1)              rotation about ``p``            unit forces through ``p`` along x, along y
``prismatic`` (1)             translation along ``e``         unit force through ``p`` along ``e⊥``, couple
``revolute_prismatic`` (2)    translation ``e``,              unit force through ``p`` along ``e⊥``
                              rotation about ``p`` (4.74)
``twin_prismatic`` (2)        translations ``e``, ``e⊥``      unit couple (the line at infinity)
``plane`` (3)                 translations ``e``, ``e⊥``,     (none)
                              rotation about ``p``
``fixed`` (0)                 (none)                          unit forces through ``p`` along x, y, couple
============================  ==============================  =============================================
"""
from __future__ import annotations

import functools

import numpy as np

from planargeo._validate import as_array, as_xy, overflow_checked
from planargeo.errors import InputError, ShapeError
from planargeo.geometry._docs import entries
from planargeo.mechanics.model import JOINT_DOFS, _finite_tuple
from planargeo.screws.twists import unit_rotation, unit_translation

__all__ = ["KINDS", "DOF", "motion_space", "reaction_space", "R_of", "JointSpace",
           "revolute", "prismatic", "revolute_prismatic", "twin_prismatic", "plane", "fixed"]

#: Degrees of freedom of each kind (the model's :data:`planargeo.mechanics.model.JOINT_DOFS`).
DOF = dict(JOINT_DOFS)
#: Joint kinds understood by :func:`motion_space` / :func:`reaction_space`.
KINDS = tuple(DOF)

_USES_DIRECTION = ("prismatic", "revolute_prismatic", "twin_prismatic", "plane")

#: The sections of the joint constructors, written once (:func:`planargeo.geometry._docs.entries`).
_documented = entries({
    "point": "point : array_like, shape (2,), optional\n    A point of the joint (m); default the origin.",
    "direction": "direction : array_like, shape (2,), optional\n    Sliding direction (non-zero); default +x.",
    "joint": "Returns\n-------\nJointSpace\n    The joint (its ``s`` and ``R``: module table).",
})


def _check_kind(kind) -> str:
    if not isinstance(kind, str) or kind not in DOF:
        raise InputError(f"kind must be one of {', '.join(map(repr, KINDS))}, got {kind!r}")
    return kind


def _force_through(point: np.ndarray, direction: np.ndarray) -> np.ndarray:
    """Wrench ``[fx, fy, x fy - y fx]`` of the force ``direction`` acting through ``point`` (thesis 5.56)."""
    fx, fy = direction[..., 0], direction[..., 1]
    x, y = point[..., 0], point[..., 1]
    return np.stack([fx, fy, x * fy - y * fx], axis=-1) + 0.0   # + 0.0: no negative zeros


def _prepare(kind, point, direction):
    kind = _check_kind(kind)
    p = as_xy(point, "point")
    if kind in _USES_DIRECTION:
        e = unit_translation(direction)          # validates; zero -> DegenerateGeometryError naming direction
        shape = np.broadcast_shapes(p.shape[:-1], e.shape[:-1])
        p = np.broadcast_to(p, shape + (2,))
        e = np.broadcast_to(e, shape + (3,))
    else:
        e = None
        shape = p.shape[:-1]
    return kind, p, e, shape


def motion_space(kind, point=(0.0, 0.0), direction=(1.0, 0.0)) -> np.ndarray:
    """Motion space ``s`` of a joint, world coordinates at the origin (thesis 4.64, 4.69, 4.74, 5.62).

    Parameters
    ----------
    kind : {"revolute", "prismatic", "revolute_prismatic", "twin_prismatic", "plane", "fixed"}
        Joint kind (:data:`KINDS`).
    point : array_like, shape (..., 2)
        The pivot, a point on the slide, the joint frame's origin or the weld point.
    direction : array_like, shape (..., 2)
        Slide direction or the joint frame's x axis (normalised; ignored by revolute and fixed).

    Returns
    -------
    ndarray, shape (..., 3, k)
        Unit twists as columns, ``k = DOF[kind]``; ``point`` and ``direction`` broadcast.

    Examples
    --------
    >>> motion_space("revolute", (2.0, 1.0))          # the pivot as a homogeneous point [y, -x, 1]
    array([[ 1.],
           [-2.],
           [ 1.]])
    """
    kind, p, e, shape = _prepare(kind, point, direction)
    if kind == "revolute":
        return unit_rotation(p)[..., None] + 0.0
    if kind == "prismatic":
        return np.array(e)[..., None]
    if kind == "revolute_prismatic":
        return np.stack([e, unit_rotation(p)], axis=-1) + 0.0
    if kind in ("twin_prismatic", "plane"):
        perp = np.stack([-e[..., 1], e[..., 0], e[..., 2]], axis=-1) + 0.0
        if kind == "twin_prismatic":
            return np.stack([e, perp], axis=-1)
        return np.stack([e, perp, unit_rotation(p)], axis=-1) + 0.0
    return np.zeros(shape + (3, 0))


def reaction_space(kind, point=(0.0, 0.0), direction=(1.0, 0.0)) -> np.ndarray:
    """Reaction space ``R`` of a joint, with ``sᵀR = 0`` (thesis 5.61, 5.63, 6.1): the module table's wrenches.

    Parameters
    ----------
    kind, point, direction
        As for :func:`motion_space`.

    Returns
    -------
    ndarray, shape (..., 3, 3 - k)

    Examples
    --------
    >>> reaction_space("revolute", (2.0, 1.0))              # forces along x and y through (2, 1)
    array([[ 1.,  0.],
           [ 0.,  1.],
           [-1.,  2.]])
    """
    kind, p, e, shape = _prepare(kind, point, direction)
    ex = np.broadcast_to(np.array([1.0, 0.0]), shape + (2,))
    ey = np.broadcast_to(np.array([0.0, 1.0]), shape + (2,))
    couple = np.broadcast_to(np.array([0.0, 0.0, 1.0]), shape + (3,))
    if kind == "revolute":
        return np.stack([_force_through(p, ex), _force_through(p, ey)], axis=-1)
    if kind == "plane":
        return np.zeros(shape + (3, 0))
    if kind == "twin_prismatic":
        return np.array(couple)[..., None]
    if kind in _USES_DIRECTION:
        normal = np.stack([-e[..., 1], e[..., 0]], axis=-1)
        cols = [_force_through(p, normal)]
        if kind == "prismatic":
            cols.append(couple)
        return np.stack(cols, axis=-1)
    return np.stack([_force_through(p, ex), _force_through(p, ey), couple], axis=-1)


@overflow_checked("s")
def R_of(s, point=(0.0, 0.0)) -> np.ndarray:
    """Reaction space ``R`` (``sᵀR = 0``) of the joint whose motion space is ``s`` (thesis 6.1, 5.63, 7.16).

    The algorithms know a joint only by ``s``: this reads kind, pivot and slide off it (a rotation
    ``[a, b, w]``, ``w ≠ 0`` exactly, is a pivot at ``(-b/w, a/w)``, 7.16) and returns
    :func:`reaction_space`, so every ``μ = Uᵀ f`` in the package is in the module table's basis.

    Parameters
    ----------
    s : array_like, shape (3, k)
        Motion space (unit twists at the origin, as columns).
    point : array_like, shape (2,)
        A point on a prismatic joint's slide (the models use the slider's frame origin), or the weld point.

    Returns
    -------
    ndarray, shape (3, 3 - k)

    Raises
    ------
    ShapeError
        ``s`` is not ``(3, k)`` with ``k <= 3``.

    Examples
    --------
    >>> R_of([[1.0], [0.0], [0.0]], (2.0, 3.0))  # prismatic along x at (2, 3): 5.63
    array([[0., 0.],
           [1., 0.],
           [2., 1.]])
    """
    a = as_array(s, "s")
    point = as_xy(point, "point")
    if a.ndim == 1 and a.shape == (3,):
        a = a[:, None]
    if a.ndim != 2 or a.shape[0] != 3 or a.shape[1] > 3:
        raise ShapeError(f"s must have shape (3, k) with k <= 3, got shape {a.shape}")
    k = a.shape[1]
    if k == 3:
        return reaction_space("plane")
    if k == 0:
        return reaction_space("fixed", point)
    if k == 1:
        x, y, w = a[:, 0]
        if w != 0.0:
            return reaction_space("revolute", (-y / w, x / w))
        return reaction_space("prismatic", point, (x, y))
    w1, w2 = a[2, 0], a[2, 1]
    if w1 == 0.0 and w2 == 0.0:
        return reaction_space("twin_prismatic")             # two translations: only a couple
    e = w2 * a[:2, 0] - w1 * a[:2, 1]                      # the translation in the span
    rot = a[:, 1] if w2 != 0.0 else a[:, 0]
    return reaction_space("revolute_prismatic", (-rot[1] / rot[2], rot[0] / rot[2]), e * np.sign(w2 or -w1))


def _frozen(a: np.ndarray) -> np.ndarray:
    a = np.array(a, dtype=float)
    a.setflags(write=False)
    return a


class JointSpace:
    """One planar joint's motion space ``s`` and reaction space ``R`` (thesis 4.8, 5.61–5.63), frozen.

    Build with :func:`revolute` ... :func:`fixed`; one joint only (for many, :func:`motion_space`).

    Parameters
    ----------
    kind : str
        One of :data:`KINDS`.
    point : array_like, shape (2,), optional
        Pivot, point on the slide, joint-frame origin or weld point (m); default the origin.
    direction : array_like, shape (2,), optional
        Slide direction (non-zero), default +x; ignored by the revolute and fixed joints.

    Raises
    ------
    InputError, ShapeError
        For an unknown ``kind``, or ``point`` or ``direction`` not of shape (2,).

    Examples
    --------
    >>> j = prismatic(point=(1.0, 0.0), direction=(0.0, 1.0))
    >>> j, j.s.T @ j.R
    (JointSpace('prismatic', point=(1.0, 0.0), direction=(0.0, 1.0)), array([[0., 0.]]))
    """

    __slots__ = ("_kind", "_point", "_direction", "_s", "_R")

    def __init__(self, kind: str, point=(0.0, 0.0), direction=(1.0, 0.0)):
        kind = _check_kind(kind)
        p = _frozen(_finite_tuple(point, "point", 2))
        e = None
        if kind in _USES_DIRECTION:
            e = _frozen(unit_translation(_finite_tuple(direction, "direction", 2))[:2])
        dirn = (1.0, 0.0) if e is None else e
        for name, value in (("_kind", kind), ("_point", p), ("_direction", e),
                            ("_s", _frozen(motion_space(kind, p, dirn))),
                            ("_R", _frozen(reaction_space(kind, p, dirn)))):
            object.__setattr__(self, name, value)

    def __setattr__(self, name, value):
        raise AttributeError(f"JointSpace is frozen; cannot set {name!r}")

    @property
    def kind(self) -> str:
        """Joint kind, one of :data:`KINDS`.

        Examples
        --------
        >>> revolute((1.0, 2.0)).kind
        'revolute'
        """
        return self._kind

    @property
    def point(self) -> np.ndarray:
        """The joint's point, shape (2,), read-only: pivot, point on the slide, frame origin or weld point.

        Examples
        --------
        >>> prismatic(point=(3.0, 0.0), direction=(0.0, 1.0)).point
        array([3., 0.])
        """
        return self._point

    @property
    def direction(self) -> np.ndarray | None:
        """Unit slide direction, shape (2,), read-only (kinds with a slide), else ``None``.

        Examples
        --------
        >>> prismatic(direction=(3.0, 4.0)).direction
        array([0.6, 0.8])
        >>> revolute().direction is None
        True
        """
        return self._direction

    @property
    def s(self) -> np.ndarray:
        """Motion space ``s``, shape (3, k), read-only: unit twists at the origin (thesis 4.64-4.79).

        Examples
        --------
        >>> revolute((2.0, 0.0)).s                 # rotation about (2, 0): the point [y, -x, 1]
        array([[ 0.],
               [-2.],
               [ 1.]])
        """
        return self._s

    @property
    def R(self) -> np.ndarray:
        """Reaction space ``R``, shape (3, 3 - k), read-only: unit wrenches, ``sᵀR = 0`` (thesis 5.63, 6.1).

        Examples
        --------
        >>> revolute((2.0, 0.0)).R                 # unit forces along x and y through (2, 0)
        array([[1., 0.],
               [0., 1.],
               [0., 2.]])
        """
        return self._R

    @property
    def dof(self) -> int:
        """Degrees of freedom ``k``."""
        return DOF[self._kind]

    def __repr__(self) -> str:
        kind, p, d = self._key()
        direction = "" if d is None else f", direction={d}"
        return f"JointSpace({kind!r}, point={p}{direction})"

    def _key(self):
        d = None if self._direction is None else tuple(map(float, self._direction))
        return self._kind, tuple(map(float, self._point)), d

    def __eq__(self, other) -> bool:
        if not isinstance(other, JointSpace):
            return NotImplemented
        return self._key() == other._key()

    def __hash__(self) -> int:
        return hash(self._key())


def _by_name(constructor):
    """``constructor`` (keyword-only arguments) refusing positional ones with a clear :class:`InputError`."""
    @functools.wraps(constructor)
    def named_only(*args, **kwargs):
        if args:
            n = len(args)
            raise InputError(f"{constructor.__name__} takes point= and direction= by name, e.g. "
                             f"{constructor.__name__}(point=(0, 0), direction=(1, 0)); got {n} positional "
                             f"argument{'s' if n > 1 else ''}")
        return constructor(**kwargs)
    return named_only


@_documented
def revolute(point=(0.0, 0.0)) -> JointSpace:
    """Revolute (pin) joint about ``point`` (thesis 4.64): ``s`` = the point ``[y, -x, 1]``.

    {parameters point joint}

    Examples
    --------
    >>> revolute((0.0, 0.0)).s.ravel()          # thesis 4.64
    array([0., 0., 1.])
    """
    return JointSpace("revolute", point)


@_by_name
@_documented
def prismatic(*, point=(0.0, 0.0), direction=(1.0, 0.0)) -> JointSpace:
    """Prismatic (slider) joint through ``point`` along ``direction`` (thesis 4.69, 5.62, 5.63).

    ``point`` and ``direction`` are given by name (a positional call raises
    :class:`~planargeo.errors.InputError`: the order was once ``(direction, point)``).

    {parameters point direction joint}

    Examples
    --------
    >>> prismatic((1.0, 1.0))
    Traceback (most recent call last):
    ...
    planargeo.errors.InputError: prismatic takes point= and direction= by name, e.g. prismatic(point=(0, 0), direction=(1, 0)); got 1 positional argument
    """
    return JointSpace("prismatic", point, direction)


@_documented
def revolute_prismatic(point=(0.0, 0.0), direction=(1.0, 0.0)) -> JointSpace:
    """Two-dof pin-in-slot joint: slide along ``direction``, turn about ``point`` (thesis 4.74).

    {parameters point direction joint}

    Examples
    --------
    >>> revolute_prismatic((0.0, 0.0), (1.0, 0.0)).s     # thesis 4.74 with λ = 0
    array([[1., 0.],
           [0., 0.],
           [0., 1.]])
    """
    return JointSpace("revolute_prismatic", point, direction)


@_by_name
@_documented
def twin_prismatic(*, point=(0.0, 0.0), direction=(1.0, 0.0)) -> JointSpace:
    """Two-dof twin prismatic joint, thesis 4.8.4's "plane joint" (4.79): slides along ``direction`` and its normal.

    ``s = [e, e⊥]``, ``R = [0, 0, 1]`` (the line at infinity, whatever ``point``, which is kept
    for drawing).  Like :func:`prismatic`, it takes ``point`` and ``direction`` by name.

    {parameters point direction joint}

    Examples
    --------
    >>> j = twin_prismatic()
    >>> j.s                                      # thesis 4.79
    array([[1., 0.],
           [0., 1.],
           [0., 0.]])
    >>> j.R                                      # the unit couple
    array([[0.],
           [0.],
           [1.]])
    >>> twin_prismatic(direction=(0.0, 2.0)).s    # e = y, e⊥ = -x
    array([[ 0., -1.],
           [ 1.,  0.],
           [ 0.,  0.]])
    """
    return JointSpace("twin_prismatic", point, direction)


@_documented
def plane(point=(0.0, 0.0), direction=(1.0, 0.0)) -> JointSpace:
    """Free planar (3-dof) joint: slides along ``direction`` and its normal, turns about ``point`` (thesis 4.79 + 4.64, 5.62).

    ``s`` spans every twist and ``R`` is empty: the joint transmits no force.

    {parameters point direction joint}

    Examples
    --------
    >>> plane().s
    array([[1., 0., 0.],
           [0., 1., 0.],
           [0., 0., 1.]])
    >>> plane().R.shape
    (3, 0)
    """
    return JointSpace("plane", point, direction)


@_documented
def fixed(point=(0.0, 0.0)) -> JointSpace:
    """Weld (0-dof) at ``point``: ``s`` is empty, ``R`` = forces through ``point`` along x, y and a couple (thesis 6.10).

    {parameters point joint}

    Examples
    --------
    >>> fixed((0.0, 0.0)).R
    array([[1., 0., 0.],
           [0., 1., 0.],
           [0., 0., 1.]])
    """
    return JointSpace("fixed", point)
