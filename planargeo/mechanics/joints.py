"""Planar joints: motion spaces ``s`` and reaction spaces ``R`` (thesis 4.8, 5.61–5.63, 6.1).

A joint allowing ``k`` degrees of freedom is described by its *motion space*
``s`` (a ``(3, k)`` matrix whose columns are unit twists) and its *reaction
space* ``R`` (a ``(3, 3 - k)`` matrix whose columns are unit wrenches) with

    sᵀ R = 0          (thesis 5.61, 6.1)

i.e. every reaction wrench is reciprocal to (does no work on) every joint
motion.  In the package's homogeneous coordinates a unit rotation about a
point *is* that point and a unit force *is* its line of action, so ``sᵀR = 0``
says that the reaction lines pass through the joint's pivot (revolute) or
through the joint's ideal point (prismatic: forces perpendicular to the slide,
plus the line at infinity, a couple).

Everything is expressed in world coordinates at the global origin, with
twists ordered ``[vx, vy, wz]`` and wrenches ``[fx, fy, tz]``.

The reaction bases are chosen to be meaningful, as in thesis 4.8 / 5.63:

============================  ==============================  =============================================
kind (dof)                    ``s`` columns                   ``R`` columns
============================  ==============================  =============================================
``revolute`` (1)              rotation about ``p``            unit forces through ``p`` along x, along y
``prismatic`` (1)             translation along ``e``         unit force through ``p`` along ``e⊥``, couple
``revolute_prismatic`` (2)    translation ``e``,              unit force through ``p`` along ``e⊥``
                              rotation about ``p``
``twin_prismatic`` (2)        translations ``e``, ``e⊥``      unit couple (the line at infinity)
``plane`` (3)                 translations ``e``, ``e⊥``,     (none)
                              rotation about ``p``
``fixed`` (0)                 (none)                          unit forces through ``p`` along x, y, couple
============================  ==============================  =============================================

(``e⊥ = (-e_y, e_x)``, the direction ``e`` turned by +90°, as in thesis 5.63.)
The ``revolute_prismatic`` columns follow the thesis's order (4.74):
translation first, then rotation.

:class:`JointSpace` is a small frozen object for one joint (each constructor below,
:func:`revolute` to :func:`fixed`, makes one: ``point`` and ``direction`` of shape
``(2,)``); :func:`motion_space` and :func:`reaction_space` are the vectorised array
functions behind it, which broadcast, and
:func:`R_of` gives ``R`` of a joint known only by its motion space ``s`` (as the
algorithms know it).

Note: thesis 4.8.4 calls its 2-dof "twin prismatic" joint (translations x
and y, 4.79) a *plane joint*; here that joint is ``twin_prismatic``
(:func:`twin_prismatic`; with ``direction = (1, 0)`` its ``s`` is 4.79
exactly, and its reaction space is the unit couple ``[0, 0, 1]``, the line at
infinity, whatever ``point``), while ``plane`` is the 3-dof free planar joint
of the package's model (:class:`planargeo.mechanics.model.Joint` kinds), whose reaction
space is empty.  The column order of every kind the model knows matches
:func:`planargeo.mechanics.kinematics.joint_axes` (``twin_prismatic``'s columns are the
first two of ``plane``).
"""
from __future__ import annotations

import functools

import numpy as np

from planargeo._validate import as_xy, overflow_checked
from planargeo.errors import InputError, ShapeError
from planargeo.geometry._docs import entries
from planargeo.screws.twists import unit_rotation, unit_translation

__all__ = ["KINDS", "DOF", "motion_space", "reaction_space", "R_of", "JointSpace",
           "revolute", "prismatic", "revolute_prismatic", "twin_prismatic", "plane", "fixed"]

#: Joint kinds understood by :func:`motion_space` / :func:`reaction_space`.
KINDS = ("revolute", "prismatic", "revolute_prismatic", "twin_prismatic", "plane", "fixed")

#: Degrees of freedom of each kind.
DOF = {"revolute": 1, "prismatic": 1, "revolute_prismatic": 2, "twin_prismatic": 2, "plane": 3, "fixed": 0}

_USES_DIRECTION = ("prismatic", "revolute_prismatic", "twin_prismatic", "plane")

#: The parameters of the joint constructors, described once (:func:`planargeo.geometry._docs.entries`).
_documented = entries({
    "point": "point : array_like, shape (2,), optional\n    A point of the joint (m); default the origin.",
    "direction": "direction : array_like, shape (2,), optional\n    Sliding direction (non-zero); default +x.",
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
        The joint's pivot (revolute), a point on the slide (prismatic), the
        joint frame's origin (plane, twin prismatic: its ``s`` and ``R`` do
        not depend on it), the weld point (fixed).
    direction : array_like, shape (..., 2)
        Slide direction (prismatic kinds), the joint frame's x axis (plane,
        twin prismatic); normalised; ignored by ``revolute`` and ``fixed``.
        A zero direction raises :class:`~planargeo.errors.DegenerateGeometryError`.

    Returns
    -------
    ndarray, shape (..., 3, k)
        Unit twists as columns, ``k = DOF[kind]``; leading dimensions broadcast
        ``point`` and ``direction``.

    Examples
    --------
    >>> motion_space("revolute", (2.0, 1.0))          # the pivot as a homogeneous point [y, -x, 1]
    array([[ 1.],
           [-2.],
           [ 1.]])
    >>> motion_space("prismatic", direction=(0.0, 3.0))
    array([[0.],
           [1.],
           [0.]])
    >>> motion_space("twin_prismatic")                # thesis 4.79
    array([[1., 0.],
           [0., 1.],
           [0., 0.]])
    >>> motion_space("fixed", (1.0, 1.0)).shape
    (3, 0)
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
    """Reaction space ``R`` of a joint, with ``sᵀR = 0`` (thesis 5.61, 5.63, 6.1).

    The columns are unit wrenches chosen to be meaningful (see the module
    table): unit forces whose lines of action pass through the joint, and the
    unit couple ``[0, 0, 1]`` (the line at infinity) when rotation is blocked.

    Parameters
    ----------
    kind, point, direction
        As for :func:`motion_space`.

    Returns
    -------
    ndarray, shape (..., 3, 3 - k)

    Examples
    --------
    >>> reaction_space("prismatic", direction=(1.0, 0.0))   # thesis 5.63 with λ = 0
    array([[0., 0.],
           [1., 0.],
           [0., 1.]])
    >>> reaction_space("revolute", (2.0, 1.0))              # forces along x and y through (2, 1)
    array([[ 1.,  0.],
           [ 0.,  1.],
           [-1.,  2.]])
    >>> reaction_space("twin_prismatic", (2.0, 1.0))        # the couple: line at infinity
    array([[0.],
           [0.],
           [1.]])
    """
    kind, p, e, shape = _prepare(kind, point, direction)
    if shape == ():
        ex, ey, couple = np.array([1.0, 0.0]), np.array([0.0, 1.0]), np.array([0.0, 0.0, 1.0])
    else:
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

    The algorithms (:mod:`planargeo.algorithms.projective`, ``stacked``,
    ``articulated_*``) know a joint only by its motion space ``s`` at the
    current state; this reads the kind, pivot and slide direction off ``s``
    and returns :func:`reaction_space` ``(kind, point, direction)``, so that every
    reaction component ``μ = Uᵀ f`` in the package is measured in the same,
    thesis-meaningful basis (module table):

    * ``k = 1``, rotation ``[a, b, w]`` with ``w ≠ 0``: revolute about the
      point ``(-b/w, a/w)``; ``R`` = unit forces along x and y through it (7.16);
    * ``k = 1``, translation ``[a, b, 0]``: prismatic along ``(a, b)``;
      ``R`` = unit force along ``e⊥`` through ``point``, then the unit couple (5.63);
    * ``k = 2``: the span holds one translation ``e`` and rotations about the
      points of one line; ``R`` = the unit force along ``e⊥`` through the
      rotation point (kind ``revolute_prismatic``); two translations (the
      twin prismatic joint of 4.79, kind ``twin_prismatic``) give the unit couple;
    * ``k = 3``: empty; ``k = 0``: weld at ``point``.

    The kind test ``w ≠ 0`` is exact (a translation is an ordinary ideal
    point with ``w = 0``), not a tolerance.

    Parameters
    ----------
    s : array_like, shape (3, k)
        Motion space (unit twists at the origin, as columns).
    point : array_like, shape (2,)
        A point of the joint, used where ``s`` does not fix the reaction
        lines: on the slide of a prismatic joint (the models use the body's
        frame origin, i.e. the slider's current position) and the weld point.

    Returns
    -------
    ndarray, shape (3, 3 - k)

    Raises
    ------
    ShapeError
        ``s`` is not ``(3, k)`` with ``k <= 3``.

    Examples
    --------
    >>> R_of([[3.0], [-2.0], [1.0]])             # revolute at (2, 3): thesis 7.16
    array([[ 1.,  0.],
           [ 0.,  1.],
           [-3.,  2.]])
    >>> R_of([[1.0], [0.0], [0.0]], (2.0, 3.0))  # prismatic along x at (2, 3): 5.63
    array([[0., 0.],
           [1., 0.],
           [2., 1.]])
    """
    from planargeo._validate import as_array

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
    """One planar joint's motion space ``s`` and reaction space ``R`` (thesis 4.8, 5.61–5.63).

    Frozen: the arrays are read-only.  Build with the named constructors
    :func:`revolute`, :func:`prismatic`, :func:`revolute_prismatic`,
    :func:`twin_prismatic`, :func:`plane`, :func:`fixed` (or
    ``JointSpace(kind, point, direction)``).

    Single joints only: ``point`` and ``direction`` must have shape ``(2,)``
    (a batch raises :class:`~planargeo.errors.ShapeError`).  For many joints
    at once use :func:`motion_space` / :func:`reaction_space`, which broadcast.

    Parameters
    ----------
    kind : str
        One of :data:`KINDS`.
    point : array_like, shape (2,), optional
        The joint's point (m): pivot, point on the slide, joint-frame origin or weld point;
        default the origin.
    direction : array_like, shape (2,), optional
        Slide direction (non-zero; prismatic kinds, twin prismatic, plane), default +x;
        ignored by the revolute and fixed joints.

    Attributes
    ----------
    kind : str
        Joint kind: revolute, prismatic, revolute_prismatic, twin_prismatic, plane or fixed.
    point : ndarray, shape (2,)
        Pivot / point on the slide / joint-frame origin / weld point.
    direction : ndarray, shape (2,) or None
        Unit slide direction (prismatic kinds, twin prismatic, plane), else ``None``.
    s : ndarray, shape (3, k)
        Motion space, unit twists at the origin.
    R : ndarray, shape (3, 3 - k)
        Reaction space, unit wrenches at the origin, ``s.T @ R == 0``.
    dof : int
        ``k``.

    Raises
    ------
    InputError
        For an unknown ``kind``.
    ShapeError
        If ``point`` or ``direction`` does not have shape (2,).

    Examples
    --------
    >>> j = prismatic(point=(1.0, 0.0), direction=(0.0, 1.0))
    >>> j
    JointSpace('prismatic', point=(1.0, 0.0), direction=(0.0, 1.0))
    >>> j.s.T @ j.R
    array([[0., 0.]])
    """

    __slots__ = ("_kind", "_point", "_direction", "_s", "_R")

    def __init__(self, kind: str, point=(0.0, 0.0), direction=(1.0, 0.0)):
        kind = _check_kind(kind)
        p = as_xy(point, "point")
        if p.shape != (2,):
            raise ShapeError(f"point must have shape (2,), got shape {p.shape}")
        if kind in _USES_DIRECTION:
            d = as_xy(direction, "direction")
            if d.shape != (2,):
                raise ShapeError(f"direction must have shape (2,), got shape {d.shape}")
            e = unit_translation(d)[:2]
        else:
            e = None
        object.__setattr__(self, "_kind", kind)
        object.__setattr__(self, "_point", _frozen(p))
        object.__setattr__(self, "_direction", None if e is None else _frozen(e))
        dirn = (1.0, 0.0) if e is None else e
        object.__setattr__(self, "_s", _frozen(motion_space(kind, p, dirn)))
        object.__setattr__(self, "_R", _frozen(reaction_space(kind, p, dirn)))

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
        """The joint's point, shape (2,), read-only: pivot / point on the slide / joint-frame origin / weld point.

        Examples
        --------
        >>> prismatic(point=(3.0, 0.0), direction=(0.0, 1.0)).point
        array([3., 0.])
        """
        return self._point

    @property
    def direction(self) -> np.ndarray | None:
        """Unit slide direction, shape (2,), read-only (prismatic kinds, twin prismatic, plane), else ``None``.

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
        """Motion space ``s``, shape (3, k), read-only: unit twists at the origin as columns (thesis 4.64-4.79).

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
        """Reaction space ``R``, shape (3, 3 - k), read-only: unit wrenches at the origin, ``sᵀR = 0`` (thesis 5.63, 6.1).

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
        p = tuple(float(x) for x in self._point)
        if self._direction is None:
            return f"JointSpace({self._kind!r}, point={p})"
        d = tuple(float(x) for x in self._direction)
        return f"JointSpace({self._kind!r}, point={p}, direction={d})"

    def __eq__(self, other) -> bool:
        if not isinstance(other, JointSpace):
            return NotImplemented
        same_dir = (self._direction is None and other._direction is None) or (
            self._direction is not None and other._direction is not None
            and np.array_equal(self._direction, other._direction))
        return self._kind == other._kind and np.array_equal(self._point, other._point) and same_dir

    def __hash__(self) -> int:
        d = None if self._direction is None else tuple(self._direction)
        return hash((self._kind, tuple(self._point), d))


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

    Parameters
    ----------
    {point}

    Returns
    -------
    JointSpace
        ``s = [y, -x, 1]``, ``R`` = unit forces along x and y through the point.

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

    ``point`` and ``direction`` are given by name (the point first, as
    for every joint; a positional call raises :class:`~planargeo.errors.InputError`, since the
    order was once ``(direction, point)``).

    Parameters
    ----------
    {point direction}

    Returns
    -------
    JointSpace
        ``s = [dx, dy, 0]`` (unit), ``R`` = the normal force through the point and a couple.

    Examples
    --------
    >>> np.round(prismatic(direction=(1.0, 1.0)).s.ravel(), 4)
    array([0.7071, 0.7071, 0.    ])
    >>> prismatic((1.0, 1.0))
    Traceback (most recent call last):
    ...
    planargeo.errors.InputError: prismatic takes point= and direction= by name, e.g. prismatic(point=(0, 0), direction=(1, 0)); got 1 positional argument
    """
    return JointSpace("prismatic", point, direction)


@_documented
def revolute_prismatic(point=(0.0, 0.0), direction=(1.0, 0.0)) -> JointSpace:
    """Two-dof pin-in-slot joint: slide along ``direction``, turn about ``point`` (thesis 4.74).

    Parameters
    ----------
    {point direction}

    Returns
    -------
    JointSpace
        Two columns of ``s`` (slide, turn), one of ``R`` (the normal force through the point).

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

    ``s = [e, e⊥]`` (two unit translations, ``e⊥`` the direction turned by
    +90°); with the default ``direction = (1, 0)`` this is 4.79,
    ``s = [[1, 0], [0, 1], [0, 0]]``.  Rotation is blocked by a couple only:
    ``R = [0, 0, 1]``, the line at infinity, reciprocal to every translation
    (the ideal points lie on the line at infinity).  ``point`` (the joint
    frame's origin) does not change ``s`` or ``R``; it is kept for drawing.
    Like :func:`prismatic`, it takes ``point`` and ``direction`` by name.

    In a model it is the joint kind ``"twin_prismatic"`` of :class:`planargeo.mechanics.model.Joint`
    (two dofs, slid by ``(q[0], q[1])`` along ``e`` and ``e⊥``, not rotated; the same
    columns as :func:`planargeo.mechanics.kinematics.joint_axes`).

    Parameters
    ----------
    {point direction}

    Returns
    -------
    JointSpace
        ``s = [e, e⊥]``, ``R = [0, 0, 1]``.

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

    The columns follow the package's ``Model`` joint ``"plane"`` (translations
    along the joint frame's x and y axes, then rotation about its origin); with
    the defaults ``s`` is the identity.  ``R`` is empty.  Thesis 4.8.4's 2-dof "plane joint"
    (4.79, no rotation) is :func:`twin_prismatic`.

    Parameters
    ----------
    {point direction}

    Returns
    -------
    JointSpace
        Three columns of ``s``, empty ``R``.

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

    Parameters
    ----------
    {point}

    Returns
    -------
    JointSpace
        Empty ``s``, three columns of ``R``.

    Examples
    --------
    >>> fixed((0.0, 0.0)).R
    array([[1., 0., 0.],
           [0., 1., 0.],
           [0., 0., 1.]])
    """
    return JointSpace("fixed", point)
